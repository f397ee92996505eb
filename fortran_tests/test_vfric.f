C=======================================================================
C     test_vfric.f -- VFRIC (Abaqus/Explicit, double precision) called
C     the way a legacy Explicit host calls a user subroutine: fixed-form
C     Fortran 77, INCLUDE 'ABA_PARAM.INC' (the double-precision
C     vaba_param.inc is the same IMPLICIT REAL*8), CHARACTER*80 names
C     and a plain CALL VFRIC(...) with the 42 arguments; no interface
C     block, no ISO_C_BINDING.  The library's vfric_ has to link and
C     answer unchanged.
C
C     Closed form (docs/vfric.md), Coulomb law 1 in force form:
C       fTangential(1,k) = -min(mu fNormal(k), tau_max areaSlv(node),
C                               fStickForce(k)),
C       0 for fNormal(k) < 0, fTangential(2,k) = 0 (nFricDir = 2).
C     A point with a negative stick force gets 0, the others are
C     computed; an adhesive PROPS(1) = 2 gives 0 everywhere.  Columns
C     past nContact hold a sentinel that must survive; STATEV is not
C     written.
C
C     The tally (TALLY0, CHECK with the case in CASE, TALLYE) comes from
C     harness_f77.f.
C=======================================================================
      PROGRAM TVFRIC
      INCLUDE 'ABA_PARAM.INC'
C     The blocks run for each nFricDir (BLOCK's ICAP, IBAD): no cap, the
C     tau_max cap, the cap with a negative stick force at point 2, the
C     adhesive law (refused).
      DIMENSION ICAPS(4), IBADS(4)
      DATA ICAPS /0, 1, 1, 0/
      DATA IBADS /0, 0, 1, 2/
      CALL TALLY0
      DO 20 NFD = 1, 2
        DO 10 K = 1, 4
          CALL BLOCK(NFD, ICAPS(K), IBADS(K))
   10   CONTINUE
   20 CONTINUE
      CALL TALLYE
      END

C-----------------------------------------------------------------------
C     One block of NC contact points: slip, stick, tension, capped by
C     tau_max*area (ICAP = 1), a big load.  IBAD = 1: point 2 has a
C     negative stick force; IBAD = 2: the adhesive law (refused).
C-----------------------------------------------------------------------
      SUBROUTINE BLOCK(NFD, ICAP, IBAD)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      PARAMETER (NC=5, MC=7, NSLV=6, NSV=2, SENT=-999.25D0)
      CHARACTER*80 SURFI, SURFS, SURFM
      DIMENSION FTAN(2,MC), STATEV(NSV,NSLV), JSLVU(NSLV), JMSTU(4),
     1 JCONS(NC), JCONM(4,NC), DSLIP(3,NC), FSTICK(NC), FTPREV(3,NC),
     2 FNORM(NC), FWORK(NC), SHAPE(4,NC), CSLV(3,NSLV), CMST(3,4),
     3 DCSL(3,NC), DCN(3,NC), PROPS(8), AREA(NSLV), TSLV(NC),
     4 PDSLV(NC), TMST(1), PDMST(1)
      DIMENSION FNIN(NC), FSIN(NC)
      DATA FNIN /10.0D0, 10.0D0, -3.0D0, 40.0D0, 1.0D5/
      DATA FSIN / 5.0D0,  2.0D0,  4.0D0, 1.0D3, 1.0D9/
C
      WRITE (CASE,'(A,I0,A,I0,A,I0)') 'VFRIC nFricDir=', NFD,
     1 ' cap=', ICAP, ' bad=', IBAD
      NCON = NC
      NFACN = 4
      NSLVN = NSLV
      NMSTN = 4
      NDIR = NFD + 1
      NSTV = NSV
      NPROPS = 7
      NTEMP = 0
      NPRED = 0
      NDTFV = 1
      KSTEP = 1
      KINC = 1
      LCT = 1
      TSTEP = 0.0D0
      TGLB = 0.0D0
      DTIM = 1.0D-6
      SURFI = 'CP-1'
      SURFS = 'SLAVE'
      SURFM = 'MASTER'
      XMU = 0.3D0
      TMAX = 0.0D0
      IF (ICAP .EQ. 1) TMAX = 2.0D0
      DO 5 I = 1, 8
        PROPS(I) = 0.0D0
    5 CONTINUE
      PROPS(1) = 1.0D0
      PROPS(2) = XMU
      PROPS(3) = XMU
      PROPS(4) = TMAX
      PROPS(5) = 1.0D-3
      IF (IBAD .EQ. 2) THEN
        PROPS(1) = 2.0D0
        PROPS(3) = -1.0D0
        PROPS(4) = 1.0D0
        PROPS(5) = 0.0D0
        PROPS(8) = 1.0D-3
        NPROPS = 8
      END IF
      DO 6 I = 1, NSLV
        JSLVU(I) = 100 + I
        AREA(I) = 0.25D0 + 0.5D0*(I-1)
        STATEV(1,I) = 7.0D0
        STATEV(2,I) = 8.0D0
    6 CONTINUE
      DO 7 K = 1, MC
        FTAN(1,K) = SENT
        FTAN(2,K) = SENT
    7 CONTINUE
      DO 8 K = 1, NC
        FNORM(K) = FNIN(K)
        FSTICK(K) = FSIN(K)
C       A permutation of the slave nodes.
        JCONS(K) = NSLV + 1 - K
        DSLIP(1,K) = 1.0D-4*K
    8 CONTINUE
      IF (IBAD .EQ. 1) FSTICK(2) = -1.0D0
C
      CALL VFRIC(FTAN, STATEV, KSTEP, KINC, NCON, NFACN, NSLVN, NMSTN,
     1 NFD, NDIR, NSTV, NPROPS, NTEMP, NPRED, NDTFV, JSLVU, JMSTU,
     2 JCONS, JCONM, TSTEP, TGLB, DTIM, SURFI, SURFS, SURFM, LCT,
     3 DSLIP, FSTICK, FTPREV, FNORM, FWORK, SHAPE, CSLV, CMST, DCSL,
     4 DCN, PROPS, AREA, TSLV, PDSLV, TMST, PDMST)
C
C     fTangential(nFricDir,nContact): with nFricDir = 1 the column
C     stride is 1, so point K is entry K of the flat array.
      DO 30 K = 1, NC
        IF (IBAD .EQ. 2 .OR. (IBAD .EQ. 1 .AND. K .EQ. 2)) THEN
          WANT = 0.0D0
        ELSE IF (FNORM(K) .LT. 0.0D0) THEN
          WANT = 0.0D0
        ELSE
          CRIT = XMU*FNORM(K)
          IF (TMAX .GT. 0.0D0) CRIT = MIN(CRIT, TMAX*AREA(JCONS(K)))
          WANT = -MIN(CRIT, FSTICK(K))
        END IF
        CALL CHECK(FLAT(FTAN, NFD, K, 1) .EQ. WANT,
     1   'fTangential(1,point) = closed form', K)
        IF (NFD .EQ. 2) THEN
          CALL CHECK(FTAN(2,K) .EQ. 0.0D0, 'fTangential(2,point) = 0',
     1     K)
        END IF
   30 CONTINUE
C     Nothing past fTangential(nFricDir,nContact), STATEV untouched.
      DO 40 K = NC*NFD + 1, 2*MC
        CALL CHECK(FLAT(FTAN, 1, K, 1) .EQ. SENT,
     1   'nothing past fTangential(nFricDir,nContact)', -K)
   40 CONTINUE
      DO 50 I = 1, NSLV
        CALL CHECK(STATEV(1,I) .EQ. 7.0D0 .AND. STATEV(2,I) .EQ. 8.0D0,
     1   'STATEV untouched', 100 + I)
   50 CONTINUE
C     The kinds are present: slip, stick, tension (uncapped block).
      IF (IBAD .EQ. 0 .AND. ICAP .EQ. 0) THEN
        CALL CHECK(FLAT(FTAN, NFD, 1, 1) .EQ. -3.0D0, 'slip', 201)
        CALL CHECK(FLAT(FTAN, NFD, 2, 1) .EQ. -2.0D0, 'stick', 202)
        CALL CHECK(FLAT(FTAN, NFD, 3, 1) .EQ. 0.0D0, 'tension', 203)
      END IF
C     Point 4 capped: tau_max*area(node 3) = 2*1.25 < mu*40 = 12.
      IF (IBAD .EQ. 0 .AND. ICAP .EQ. 1) THEN
        CALL CHECK(FLAT(FTAN, NFD, 4, 1) .EQ. -2.5D0,
     1   'point 4 capped at tau_max area', 204)
      END IF
      END

C     Entry (I,K) of an array declared (LDA,*) but viewed flat.
      DOUBLE PRECISION FUNCTION FLAT(A, LDA, K, I)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION A(*)
      FLAT = A(I + (K-1)*LDA)
      END
