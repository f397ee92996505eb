C     A Fortran 77 host linked through pkg-config (Makefile): plain CALL FRIC and CALL GAPCON,
C     no module, no interface block. Closed forms as in ../common/checks.h: stick tau = 15,
C     slip tau = mu p = 30, GAPCON of SI1: AK(1) = 2. In mode own-fric, own.f supplies
C     its own FRIC (the keep-your-own recipe), then FRIC must give its marker -7.
      PROGRAM F77HOST
      IMPLICIT REAL*8 (A-H,O-Z)
      CHARACTER*80 CINAME
      CHARACTER*16 MODE
      DIMENSION AK(5),D(2),FLOWM(2),TEMP(2),PREDEF(2),TIME(2),COORDS(3)
      NPASS = 0
      NFAIL = 0
      CALL GETARG(1, MODE)
      IF (MODE .EQ. 'own-fric') THEN
        CALL CHECK(ABS(STEP(5.0D-4) + 7.0D0) .LT. 1D-12, 'own FRIC',
     1    NPASS, NFAIL)
      ELSE
        CALL CHECK(ABS(STEP(5.0D-4) - 15.0D0) .LT. 1D-12, 'stick',
     1    NPASS, NFAIL)
        CALL CHECK(ABS(STEP(5.0D-3) - 30.0D0) .LT. 1D-12, 'slip',
     1    NPASS, NFAIL)
      END IF
      CINAME = 'SI1'
      D(1) = 0.0D0
      D(2) = 1.0D0
      TEMP(1) = 300.0D0
      TEMP(2) = 290.0D0
      AK(1) = -1.0D0
      CALL GAPCON(AK,D,FLOWM,TEMP,PREDEF,TIME,CINAME,CINAME,CINAME,
     1  COORDS,1,1,0,1,1)
      CALL CHECK(AK(1) .EQ. 2.0D0, 'GAPCON SI1', NPASS, NFAIL)
      WRITE (*,'(I0,A,I0,A)') NPASS, ' passed, ', NFAIL, ' failed'
      IF (NFAIL .GT. 0) CALL EXIT(1)
      END

      DOUBLE PRECISION FUNCTION STEP(DG)
      IMPLICIT REAL*8 (A-H,O-Z)
      CHARACTER*80 CINAME
      DIMENSION TAU(1),DDTDDG(1),DDTDDP(1),DSLIP(1),DDTDDT(2),
     1  STATEV(3),DGAM(1),TAULM(1),SLIP(1),TIME(2),COORDS(2),
     2  DROT(2,2),TEMP(2),PREDEF(2),PROPS(5)
      DATA PROPS /1.0D0, 0.3D0, 0.0D0, 0.0D0, 1.0D-3/
      LM = 0
      TAU(1) = 0.0D0
      STATEV(1) = 0.0D0
      STATEV(2) = 0.0D0
      STATEV(3) = 0.0D0
      DGAM(1) = DG
      TAULM(1) = 0.0D0
      SLIP(1) = 0.0D0
      DROT(1,1) = 1.0D0
      DROT(2,1) = 0.0D0
      DROT(1,2) = 0.0D0
      DROT(2,2) = 1.0D0
      TEMP(1) = 20.0D0
      TEMP(2) = 20.0D0
      PNEWDT = 1.0D36
      CINAME = 'SI1'
      CALL FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1  STATEV,DGAM,TAULM,100.0D0,0.0D0,0.0D0,SLIP,1,1,TIME,1.0D0,0,
     2  CINAME,CINAME,CINAME,1,1,1,COORDS,COORDS,DROT,TEMP,PREDEF,
     3  1,2,0,3,1.0D0,PROPS,5)
      STEP = TAU(1)
      END

      SUBROUTINE CHECK(OK, WHAT, NPASS, NFAIL)
      LOGICAL OK
      CHARACTER*(*) WHAT
      IF (OK) THEN
        NPASS = NPASS + 1
      ELSE
        NFAIL = NFAIL + 1
        WRITE (*,'(A,A)') 'FAIL ', WHAT
      END IF
      END
