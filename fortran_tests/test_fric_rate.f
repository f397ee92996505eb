C=======================================================================
C     test_fric_rate.f -- scene F4 "velocity steps" for the exponential
C     decay law through FRIC and FRIC_COEF, called as a legacy
C     Abaqus/Standard host calls user subroutines: fixed-form Fortran
C     77, INCLUDE 'ABA_PARAM.INC', CHARACTER*80 names, plain CALLs.
C     The Fortran twin of c_tests/test_fric_f4.c (rate-law part).
C
C     Law (docs/props.md): PROPS(8) = 1, mu_s = PROPS(2),
C     mu_k = PROPS(9), d_c = PROPS(10):
C       mu(v) = mu_k + (mu_s - mu_k) exp(-d_c v).
C     Slip at v = 0.05, 0.5, 0.2, 1.5 with DGAM = v DTIME E; once
C     steady |tau| = mu(v) p and STATEV(2) = v; FRIC_COEF returns
C     fCoef(1,1) = mu(v), fCoefDeriv(1,1,1) = -d_c (mu_s-mu_k)
C     exp(-d_c v); the slip tangent along the slip against a central
C     difference (TANGNT).  NFDIR = 1 and 2, elastic and exact stick,
C     mu at the end-of-increment rate and frozen (PROPS(20) = 1),
C     crossed by EACHSW as the C twin crosses them.  A rate law with
C     DTIME = 0 refused (BADDT).
C
C     The tally (CHECK with K = the velocity step), HOSTPT, FRICH (the
C     plain CALL FRIC of the host point), TANGNT and EACHSW come from
C     harness_f77.f, the host point (COMMON) from fric_host.inc.
C
C=======================================================================
      PROGRAM TFRATE
      INCLUDE 'ABA_PARAM.INC'
      COMMON /TALLY/ NPASS,NFAIL
      EXTERNAL STEPS
      CALL TALLY0
      CALL EACHSW(STEPS)
      CALL BADDT
      CALL TALLYE
      END

C     LMODE = PROPS(7): 0 elastic, 1 exact stick; IFROZ = PROPS(20).
C     The host point is fric_host.inc's, called through FRICH.
      SUBROUTINE STEPS(NDIR, LMODE, IFROZ)
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
      INCLUDE 'props_index.inc'
      DIMENSION E(2),V(4),FCOEF(1,2),FDERIV(1,20,2),SDATA(1,6),PRS(1),
     1 TAVG(1),FAVG(1,1),IDATA(6),RDATA(8)
      DATA V /0.05D0, 0.5D0, 0.2D0, 1.5D0/
C
      WRITE (CASE,'(A,I1,A,I1,A,I1)') 'F4 rate NFDIR=', NDIR,
     1 ' exact stick=', LMODE, ' frozen=', IFROZ
      XMUS = 0.6D0
      XMUK = 0.3D0
      DC = 4.0D0
      P = 50.0D0
      GC = 1.0D-3
      DO 5 I = 1, KPC_N
        PROPS(I) = 0.0D0
    5 CONTINUE
      PROPS(KPC_CODE) = DBLE(LAW_COULOMB)
      PROPS(KPC_MU) = XMUS
      PROPS(KPC_GAMMA_CRIT) = GC
      PROPS(KPC_STICK) = DBLE(LMODE)
C     Exponential decay from mu_s = PROPS(2) to mu_k.
      PROPS(KPC_MU_LAW) = 1.0D0
      PROPS(KPC_MU_K) = XMUK
      PROPS(KPC_DECAY) = DC
      PROPS(KPC_FROZEN) = DBLE(IFROZ)
      NPROPS = KPC_N
      NFDIR = NDIR
      NSTATV = 3
      E(1) = 1.0D0
      E(2) = 0.0D0
      IF (NFDIR .EQ. 2) THEN
        E(1) = 0.6D0
        E(2) = 0.8D0
      END IF
      DO 6 I = 1, MG
        TAU(I) = 0.0D0
        TAULM(I) = 0.0D0
        SLIP(I) = 0.0D0
    6 CONTINUE
      DO 7 I = 1, MSV
        STATEV(I) = SENT
    7 CONTINUE
      STATEV(1) = 0.0D0
      STATEV(2) = 0.0D0
      STATEV(3) = 0.0D0
      CALL HOSTPT('F4-RATE')
      DTIME = 0.01D0
      PRESS = P
      DPRESS = P
      CHRLNGTH = 1.0D0
      NODE = 1
      LM = 0
C
      DO 40 IS = 1, 4
        DO 30 K = 1, 40
          DO 25 I = 1, NFDIR
            DGAM(I) = V(IS) * DTIME * E(I)
   25     CONTINUE
          PNEWDT = BIG
          CALL FRICH
          CALL CHECK(PNEWDT .EQ. BIG, 'PNEWDT not lowered', IS)
          CALL CHECK(LM .EQ. 0, 'LM = 0 while sliding', IS)
          DPRESS = 0.0D0
   30   CONTINUE
        TEQ = 0.0D0
        DO 35 I = 1, NFDIR
          TEQ = TEQ + TAU(I)**2
   35   CONTINUE
        TEQ = SQRT(TEQ)
        XMU = XMUK + (XMUS - XMUK) * EXP(-DC * V(IS))
        CALL CHECK(ABS(TEQ - XMU*P) .LE. 1.0D-12*XMU*P,
     1   'steady |tau| = mu(v) p', IS)
        CALL CHECK(ABS(STATEV(2) - V(IS)) .LE. 1.0D-12*V(IS),
     1   'STATEV(2) = v', IS)
        CALL CHECK(STATEV(4) .EQ. SENT, 'STATEV(4) untouched', IS)
C       FRIC_COEF for the same rate and pressure.
        NBLOCK = 1
        NTEMP = 1
        NFIELD = 0
        SDATA(1,1) = V(IS)
        PRS(1) = P
        TAVG(1) = 20.0D0
        CALL FRIC_COEF(FCOEF,FDERIV,NBLOCK,NPROPS,NTEMP,NFIELD,
     1   IDATA,RDATA,CINAME,SLNAME,MSNAME,PROPS,SDATA,PRS,TAVG,FAVG)
        CALL CHECK(ABS(FCOEF(1,1) - XMU) .LE. 1.0D-15,
     1   'FRIC_COEF mu(v)', IS)
        CALL CHECK(ABS(FCOEF(1,2) - XMU) .LE. 1.0D-15,
     1   'FRIC_COEF mu2 = mu1 (isotropic)', IS)
        DMU = -DC * (XMUS - XMUK) * EXP(-DC * V(IS))
        CALL CHECK(ABS(FDERIV(1,1,1) - DMU) .LE. 1.0D-14,
     1   'FRIC_COEF d mu/d rate', IS)
        CALL CHECK(FDERIV(1,2,1) .EQ. 0.0D0, 'd mu/d p = 0', IS)
C       d tau/d DGAM along E against a central difference.
        CALL TANGNT(E, 1.0D-5*XMUS*P/GC, IS)
   40 CONTINUE
      END

C-----------------------------------------------------------------------
C     The rate law with DTIME = 0 (no slip rate) is refused, as in the
C     C twin's bad_dtime: PNEWDT < 1, the message names DTIME, TAU and
C     STATEV unchanged.
C-----------------------------------------------------------------------
      SUBROUTINE BADDT
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
      INCLUDE 'props_index.inc'
      CHARACTER*512 MSG
      CALL HOSTPT('F4-RATE-DT0')
      CASE = 'rate law with DTIME = 0'
      DO 5 I = 1, KPC_N
        PROPS(I) = 0.0D0
    5 CONTINUE
      PROPS(KPC_CODE) = DBLE(LAW_COULOMB)
      PROPS(KPC_MU) = 0.6D0
      PROPS(KPC_GAMMA_CRIT) = 1.0D-3
      PROPS(KPC_MU_LAW) = 1.0D0
      PROPS(KPC_MU_K) = 0.3D0
      PROPS(KPC_DECAY) = 4.0D0
      NPROPS = KPC_N
      NFDIR = 2
      NSTATV = 3
      CALL SENTAL(TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1 STATEV,DGAM,TAULM,MG,MSV)
      PRESS = 50.0D0
      DPRESS = 0.0D0
      DTIME = 0.0D0
      CHRLNGTH = 1.0D0
      LM = 0
      STATEV(1) = 0.5D0
      STATEV(2) = 0.25D0
      STATEV(3) = 1.0D0
      TAU(1) = 3.0D0
      TAU(2) = 0.0D0
      DGAM(1) = 1.0D-3
      DGAM(2) = 0.0D0
      TAULM(1) = 0.0D0
      TAULM(2) = 0.0D0
      CALL FRICH
      CALL CHECK(PNEWDT .LT. 1.0D0, 'PNEWDT < 1', 0)
      CALL GETMSG(MSG, L)
      CALL CHECK(INDEX(MSG(1:L), 'DTIME') .GT. 0,
     1 'message names DTIME', 0)
      CALL CHECK(TAU(1) .EQ. 3.0D0 .AND. TAU(2) .EQ. 0.0D0,
     1 'TAU unchanged', 0)
      CALL CHECK(STATEV(1) .EQ. 0.5D0 .AND. STATEV(2) .EQ. 0.25D0
     1 .AND. STATEV(3) .EQ. 1.0D0, 'STATEV unchanged', 0)
      END
