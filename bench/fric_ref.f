C=======================================================================
C     fric_ref.f -- the reference for the per-call benchmark: a FRIC
C     written by hand the way an analyst writes one, fixed-form
C     Fortran 77 with the full Abaqus/Standard argument list, named
C     FRICREF so that it links next to the library's FRIC (fric_).
C
C     Law: Coulomb friction with elastic stick (penalty) and an
C     optional shear limit, the same formulas as the library's
C     PROPS(1) = 1, PROPS(7) = 0 path.  PROPS are read on every call:
C       PROPS(1) law code (1, not checked)   PROPS(2) mu
C       PROPS(3) mu2 (ignored: isotropic)    PROPS(4) tau_max (0: none)
C       PROPS(5) gamma_crit (0: PROPS(6)*CHRLNGTH)
C       PROPS(6) slip tolerance (0: 0.005)   PROPS(7) 0 = elastic stick
C     STATEV(1) accumulated equivalent slip, STATEV(2) slip rate of the
C     increment, STATEV(3) 0 stick / 1 slip.
C
C     Per increment (PRESS at the end, DPRESS its increment, TAU the
C     stress at the start):
C       tau_crit(p) = min(mu max(p,0), tau_max)
C       gamma_el    = TAU gamma_crit / tau_crit(PRESS-DPRESS)
C       gamma_pr    = gamma_el + DGAM
C       stick (|gamma_pr| <= gamma_crit): k_s = tau_crit/gamma_crit,
C         TAU = k_s gamma_pr, DDTDDG = k_s I,
C         DDTDDP = gamma_pr dtau_crit/dp / gamma_crit
C       slip: n = gamma_pr/|gamma_pr|, TAU = tau_crit n,
C         DDTDDG = tau_crit/|gamma_pr| (I - n n^T)  (0 when NFDIR = 1),
C         DDTDDP = n dtau_crit/dp, DSLIP = n (|gamma_pr| - gamma_crit)
C
C     Checks: only what keeps the arithmetic defined (NFDIR, NSTATV,
C     gamma_crit > 0, elastic stick).  A failure asks for a smaller
C     increment through PNEWDT, as hand-written routines usually do.
C=======================================================================
      SUBROUTINE FRICREF(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,
     1 DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,
     2 KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,
     3 NPATCH,COORDS,RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,
     4 NSTATV,CHRLNGTH,PROPS,NPROPS)
C
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_args.inc'
      DIMENSION GPR(2)
      PARAMETER (ZERO=0.0D0, HALF=0.5D0, ONE=1.0D0, TOLDEF=0.005D0)
C
C     LM = 2: frictionless in this iteration, nothing to compute.
      IF (LM .EQ. 2) RETURN
C
      IF (NFDIR .LT. 1 .OR. NFDIR .GT. 2 .OR. NSTATV .LT. 3 .OR.
     1    NPROPS .LT. 2) THEN
        WRITE (6,*) '*** FRICREF: NFDIR, NSTATV or NPROPS wrong:',
     1    NFDIR, NSTATV, NPROPS
        PNEWDT = 0.25D0
        RETURN
      END IF
C
      XMU = PROPS(2)
      TMAX = ZERO
      GCRIT = ZERO
      TOL = ZERO
      STMODE = ZERO
      IF (NPROPS .GE. 4) TMAX = PROPS(4)
      IF (NPROPS .GE. 5) GCRIT = PROPS(5)
      IF (NPROPS .GE. 6) TOL = PROPS(6)
      IF (NPROPS .GE. 7) STMODE = PROPS(7)
      IF (TOL .EQ. ZERO) TOL = TOLDEF
      IF (GCRIT .EQ. ZERO) GCRIT = TOL*CHRLNGTH
      IF (GCRIT .LE. ZERO .OR. STMODE .NE. ZERO) THEN
        WRITE (6,*) '*** FRICREF: need gamma_crit > 0 and PROPS(7)=0',
     1    GCRIT, STMODE
        PNEWDT = 0.25D0
        RETURN
      END IF
C
C     Critical stress at the start of the increment (recovers the
C     elastic slip) and at the end, with its pressure derivative.
      P0 = PRESS - DPRESS
      TCRIT0 = XMU*MAX(P0, ZERO)
      IF (TMAX .GT. ZERO .AND. TCRIT0 .GT. TMAX) TCRIT0 = TMAX
      IF (PRESS .LT. ZERO) THEN
        TCRIT = ZERO
        DTCDP = ZERO
      ELSE
        TCRIT = XMU*PRESS
        DTCDP = XMU
        IF (TMAX .GT. ZERO .AND. TCRIT .GE. TMAX) THEN
          TCRIT = TMAX
          DTCDP = ZERO
        END IF
      END IF
C
C     Elastic predictor.
      IF (TCRIT0 .GT. ZERO) THEN
        SCAL = GCRIT/TCRIT0
      ELSE
        SCAL = ZERO
      END IF
      DO 10 K = 1, NFDIR
        GPR(K) = TAU(K)*SCAL + DGAM(K)
   10 CONTINUE
      IF (NFDIR .EQ. 1) THEN
        GEQ = ABS(GPR(1))
      ELSE
        GEQ = SQRT(GPR(1)*GPR(1) + GPR(2)*GPR(2))
      END IF
C
      IF (GEQ .LE. GCRIT) THEN
C       Stick.
        AKS = TCRIT/GCRIT
        DO 30 K = 1, NFDIR
          TAU(K) = AKS*GPR(K)
          DDTDDP(K) = GPR(K)*DTCDP/GCRIT
          DSLIP(K) = ZERO
          DO 20 J = 1, NFDIR
            DDTDDG(K,J) = ZERO
   20     CONTINUE
          DDTDDG(K,K) = AKS
   30   CONTINUE
        SED = HALF*AKS*GEQ*GEQ
        SFD = ZERO
        SLEQ = ZERO
      ELSE
C       Slip: return to the cone along the predictor.
        SLEQ = GEQ - GCRIT
        RATIO = TCRIT/GEQ
        DO 40 K = 1, NFDIR
          GPR(K) = GPR(K)/GEQ
          TAU(K) = TCRIT*GPR(K)
          DDTDDP(K) = DTCDP*GPR(K)
          DSLIP(K) = SLEQ*GPR(K)
   40   CONTINUE
        IF (NFDIR .EQ. 1) THEN
          DDTDDG(1,1) = ZERO
        ELSE
          DDTDDG(1,1) = RATIO*(ONE - GPR(1)*GPR(1))
          DDTDDG(2,2) = RATIO*(ONE - GPR(2)*GPR(2))
          DDTDDG(1,2) = -RATIO*GPR(1)*GPR(2)
          DDTDDG(2,1) = DDTDDG(1,2)
        END IF
        SED = HALF*TCRIT*GCRIT
        SFD = TCRIT*SLEQ
      END IF
C
      DO 50 K = 1, NFDIR
        DDTDDT(K,1) = ZERO
        DDTDDT(K,2) = ZERO
   50 CONTINUE
C
      STATEV(1) = STATEV(1) + SLEQ
      IF (DTIME .GT. ZERO) THEN
        STATEV(2) = SLEQ/DTIME
      ELSE
        STATEV(2) = ZERO
      END IF
      IF (SLEQ .GT. ZERO) THEN
        STATEV(3) = ONE
      ELSE
        STATEV(3) = ZERO
      END IF
      LM = 0
C
      RETURN
      END
