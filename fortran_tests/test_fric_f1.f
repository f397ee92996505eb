C=======================================================================
C     test_fric_f1.f -- scene F1 "pull to plateau" through FRIC, called
C     the way a legacy Abaqus/Standard host calls a user subroutine:
C     fixed-form Fortran 77, INCLUDE 'ABA_PARAM.INC', CHARACTER*80
C     names and a plain CALL FRIC(...) with the 39 Abaqus arguments
C     (FRICH in harness_f77.f, on the host point of fric_host.inc);
C     no interface block, no ISO_C_BINDING.  The library's fric_ has
C     to link and answer unchanged.
C
C     Expected values are closed forms of the Coulomb law with elastic
C     stick (docs/scene-definitions.md, F1; docs/source-model.md):
C       tau_crit = min(mu p, tau_max),  k_s = tau_crit/gamma_crit,
C       stick: tau = k_s gamma_el,  slip: |tau| = tau_crit.
C     Output arrays are declared longer than NFDIR (STATEV longer than
C     NSTATV); their tails hold a sentinel that must survive each call.
C
C     TALLY0, CHECK, CHKNR, TALLYE (the tally and its last line), GUARD1,
C     SENTAL, SENTOU, HOSTPT, F1HOST, FRICH and EACHSW come from
C     harness_f77.f,
C     the host point (COMMON) from fric_host.inc.
C
C=======================================================================
      PROGRAM TFRIC1
      INCLUDE 'ABA_PARAM.INC'
      COMMON /TALLY/ NPASS,NFAIL
      EXTERNAL PULL
      CALL TALLY0
C     NDIR: NFDIR = 1 (2-D) and 2 (3-D).  IGSRC = 0: gamma_crit from
C     PROPS(5); IGSRC = 1: the default 0.005*CHRLNGTH.  ICAP = 0: no
C     shear limit; ICAP = 1: tau_max = 20 < mu p = 30.  (EACHSW.)
C     IGSRC = 2, gamma_crit = PROPS(6) x CHRLNGTH, the C twin's third
C     source, for both NFDIR and both ICAP.
      CALL EACHSW(PULL)
      DO 10 NDIR = 1, 2
        CALL PULL(NDIR, 2, 0)
        CALL PULL(NDIR, 2, 1)
   10 CONTINUE
      CALL LMTWO
      CALL ROUGH
      CALL TALLYE
      END

C-----------------------------------------------------------------------
C     Scene F1: constant p; imposed slip gamma(t) = g(t) E along a fixed
C     unit direction E (E = 1 for NFDIR = 1; 30 degrees from the first
C     tangent direction for NFDIR = 2); g: 0 -> 20 gc -> -20 gc in
C     steps of 20 gc/75, so no increment ends exactly on a stick/slip
C     switch (gc/h = 3.75, 2 gc/h = 7.5).
C     Closed form along E (elastic stick, scenes.md F1):
C       loading    tau = k_s g while g <= gc, then tau = tau_crit;
C       unloading  tau = tau_crit - k_s (20 gc - g) while
C                  g >= 18 gc, then tau = -tau_crit.
C     Plastic slip: 19 gc on loading, 38 gc on unloading, so
C     sum(SFD) = tau_crit gc (19 + 38) (the uncapped case is mu p gc 57;
C     with the cap k_s = tau_max/gc keeps the elastic range at gc, so
C     the capped sum is tau_max gc 57).
C-----------------------------------------------------------------------
      SUBROUTINE PULL(NDIR, IGSRC, ICAP)
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
      PARAMETER (NUP=75)
      DIMENSION E(2),DGIN(MG)
      LOGICAL SLIPS
C
      NFDIR = NDIR
      WRITE (CASE,'(A,I1,A,I1,A,I1)') 'F1 pull NFDIR=', NFDIR,
     1 ' gcsrc=', IGSRC, ' cap=', ICAP
      CALL HOSTPT('F1-PULL')
C
      XMU = 0.3D0
      P = 100.0D0
      GC = 1.0D-3
      TMAX = 0.0D0
      IF (ICAP .EQ. 1) TMAX = 20.0D0
      PROPS(1) = 1.0D0
      PROPS(2) = XMU
      PROPS(3) = 0.0D0
      PROPS(4) = TMAX
      IF (IGSRC .EQ. 0) THEN
C       Absolute gamma_crit, PROPS(6..7) omitted (NPROPS = 5).  They
C       hold an invalid sentinel: reading past NPROPS would fail.
C       CHRLNGTH = 1 would give 0.005 /= gc if it were used.
        PROPS(5) = GC
        PROPS(6) = SENT
        PROPS(7) = SENT
        NPROPS = 5
        CHRLNGTH = 1.0D0
      ELSE IF (IGSRC .EQ. 1) THEN
C       gamma_crit = 0.005 * CHRLNGTH = 0.005 * 0.2 = gc.
        PROPS(5) = 0.0D0
        PROPS(6) = 0.0D0
        PROPS(7) = 0.0D0
        NPROPS = 7
        CHRLNGTH = 0.2D0
      ELSE
C       gamma_crit = PROPS(6) * CHRLNGTH = 0.01 * 0.1 = gc (the
C       default tolerance would give 0.005 * 0.1 /= gc).
        PROPS(5) = 0.0D0
        PROPS(6) = 0.01D0
        PROPS(7) = 0.0D0
        NPROPS = 7
        CHRLNGTH = 0.1D0
      END IF
C     tau_crit = min(mu p, tau_max) and d tau_crit/dp (0 on the cap).
      TAUC = XMU*P
      DTCDP = XMU
      IF (TMAX .GT. 0.0D0 .AND. TMAX .LT. TAUC) THEN
        TAUC = TMAX
        DTCDP = 0.0D0
      END IF
      RKS = TAUC/GC
C     Tolerances: stress, stiffness, slip, energy, d tau/dp.
      TOLS = 1.0D-12*TAUC
      TOLK = 1.0D-12*RKS
      TOLG = 1.0D-12*GC
      TOLE = 1.0D-12*TAUC*GC
      TOLP = 1.0D-12*XMU
C
      IF (NFDIR .EQ. 1) THEN
        E(1) = 1.0D0
        E(2) = 0.0D0
      ELSE
        E(1) = COS(ATAN(1.0D0)*4.0D0/6.0D0)
        E(2) = SIN(ATAN(1.0D0)*4.0D0/6.0D0)
      END IF
      CALL SENTAL(TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1 STATEV,DGAM,TAULM,MG,MSV)
      DO 6 I = 1, NFDIR
        TAU(I) = 0.0D0
    6 CONTINUE
C     NSTATV = 4: STATEV(4) is the user's own and must be left alone;
C     STATEV(5..8) lie past NSTATV.
      NSTATV = 4
      STATEV(1) = 0.0D0
      STATEV(2) = 0.0D0
      STATEV(3) = 0.0D0
      STATEV(4) = 42.0D0
      PRESS = P
      DPRESS = 0.0D0
      LM = 0
C
      GOLD = 0.0D0
      TPREV = 0.0D0
      SP = 0.0D0
      SACC = 0.0D0
      SUMSFD = 0.0D0
      SUMTDS = 0.0D0
      GMAX = 20.0D0*GC
      DO 100 K = 1, 3*NUP
        KINC = K
        TIME(1) = DBLE(K)*DTIME
        TIME(2) = TIME(1)
C       SPN: closed-form plastic slip at the end of the increment.
        SPN = SP
        IF (K .LE. NUP) THEN
          G = GMAX*(DBLE(K)/DBLE(NUP))
          SLIPS = G .GT. GC
          IF (SLIPS) SPN = G - GC
        ELSE
          G = GMAX*(DBLE(2*NUP-K)/DBLE(NUP))
          SLIPS = G .LT. GMAX - 2.0D0*GC
          IF (SLIPS) SPN = G + GC
        END IF
        DSP = SPN - SP
        GEL = G - SPN
        IF (SLIPS) THEN
          TEXP = SIGN(TAUC, GEL)
          DPEXP = SIGN(DTCDP, GEL)
        ELSE
          TEXP = RKS*GEL
C         Stick: d tau/dp = gamma_pr mu/gc (0 on the cap).
          DPEXP = GEL*DTCDP/GC
        END IF
        SACC = SACC + ABS(DSP)
C
        DO 10 I = 1, NFDIR
          DGAM(I) = (G - GOLD)*E(I)
          DGIN(I) = DGAM(I)
   10   CONTINUE
        CALL SENTOU(DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,MG)
C
        CALL FRICH
C
        CALL CHECK(LM .EQ. 0, 'LM = 0 in elastic stick', K)
        CALL CHECK(PNEWDT .EQ. BIG, 'PNEWDT never lowered', K)
        DO 20 I = 1, NFDIR
          CALL CHKNR(TAU(I), TEXP*E(I), TOLS,
     1     'TAU = k_s gamma_el (stick) / tau_crit E (slip)', K)
          CALL CHKNR(DSLIP(I), DSP*E(I), TOLG,
     1     'DSLIP = closed-form plastic slip increment', K)
          CALL CHKNR(DDTDDP(I), DPEXP*E(I), TOLP,
     1     'DDTDDP (gamma_pr mu/gc stick, mu n slip, 0 cap)', K)
          CALL CHECK(DGAM(I) .EQ. DGIN(I), 'DGAM not written', K)
   20   CONTINUE
        IF (SLIPS .AND. NFDIR .EQ. 1) THEN
          CALL CHECK(TAU(1) .EQ. SIGN(TAUC, GEL),
     1     'plateau exactly min(mu p, tau_max)', K)
        ELSE IF (SLIPS) THEN
          CALL CHKNR(SQRT(TAU(1)**2 + TAU(2)**2), TAUC,
     1     1.0D-14*TAUC, 'plateau |tau| = min(mu p, tau_max)', K)
        END IF
C       Stress along E as returned; on unloading (every increment
C       after the reversal that does not slip) its slope is k_s.
        TNOW = 0.0D0
        DO 21 I = 1, NFDIR
          TNOW = TNOW + TAU(I)*E(I)
   21   CONTINUE
        IF (K .GT. NUP .AND. .NOT. SLIPS) THEN
          CALL CHKNR((TNOW - TPREV)/(G - GOLD), RKS, 1.0D-9*RKS,
     1     'unloading slope k_s', K)
        END IF
C       DDTDDG(a,b) is element a + (b-1)*NFDIR of the flat array.
        IF (.NOT. SLIPS) THEN
          DO 31 JB = 1, NFDIR
            DO 30 IA = 1, NFDIR
              DKR = 0.0D0
              IF (IA .EQ. JB) DKR = RKS
              CALL CHKNR(DDTDDG(IA+(JB-1)*NFDIR), DKR, TOLK,
     1         'DDTDDG = k_s I in stick', K)
   30       CONTINUE
   31     CONTINUE
        ELSE IF (NFDIR .EQ. 1) THEN
          CALL CHECK(DDTDDG(1) .EQ. 0.0D0,
     1     'DDTDDG = 0 in NFDIR=1 slip', K)
        ELSE
C         (I - n n^T) tau_crit/|gamma_pr|, n = E, |gamma_pr| = gc+|dsp|
          DE1 = DDTDDG(1)*E(1) + DDTDDG(3)*E(2)
          DE2 = DDTDDG(2)*E(1) + DDTDDG(4)*E(2)
          CALL CHKNR(DE1, 0.0D0, TOLK, 'DDTDDG n = 0 in slip', K)
          CALL CHKNR(DE2, 0.0D0, TOLK, 'DDTDDG n = 0 in slip', K)
          TDT = E(2)*(DDTDDG(1)*E(2) - DDTDDG(3)*E(1))
     1        - E(1)*(DDTDDG(2)*E(2) - DDTDDG(4)*E(1))
          CALL CHKNR(TDT, TAUC/(GC + ABS(DSP)), TOLK,
     1     't.DDTDDG.t = tau_crit/|gamma_pr| in slip', K)
          CALL CHKNR(DDTDDG(2), DDTDDG(3), TOLK,
     1     'DDTDDG symmetric', K)
        END IF
        DO 32 I = 1, 2*NFDIR
          CALL CHECK(DDTDDT(I) .EQ. 0.0D0, 'DDTDDT = 0', K)
   32   CONTINUE
        CALL CHKNR(SED, TEXP**2/(2.0D0*RKS), TOLE,
     1   'SED = tau^2/(2 k_s)', K)
        CALL CHECK(SFD .GE. 0.0D0, 'SFD >= 0', K)
        CALL CHKNR(SFD, TAUC*ABS(DSP), TOLE,
     1   'SFD = tau_crit |dgamma_slip|', K)
        SUMSFD = SUMSFD + SFD
        DO 33 I = 1, NFDIR
          SUMTDS = SUMTDS + TAU(I)*DSLIP(I)
   33   CONTINUE
        CALL CHKNR(STATEV(1), SACC, TOLG,
     1   'STATEV(1) = accumulated slip', K)
        CALL CHKNR(STATEV(2), ABS(DSP)/DTIME, TOLG/DTIME,
     1   'STATEV(2) = slip rate', K)
        STAT = 0.0D0
        IF (SLIPS) STAT = 1.0D0
        CALL CHECK(STATEV(3) .EQ. STAT, 'STATEV(3) stick 0 / slip 1',
     1   K)
        CALL CHECK(STATEV(4) .EQ. 42.0D0,
     1   'STATEV(4) (user entry within NSTATV) untouched', K)
        CALL GUARDS(TAU, DDTDDG, DDTDDP, DSLIP, DDTDDT, STATEV,
     1   NFDIR, NSTATV, MG, MSV, K)
        CALL GUARD1(DGAM, NFDIR+1, MG, 'DGAM tail', K)
        CALL GUARD1(TAULM, 1, MG, 'TAULM (input, LM=0) untouched', K)
        CALL CHECK(PRESS .EQ. P .AND. DPRESS .EQ. 0.0D0,
     1   'PRESS, DPRESS not written', K)
        CALL CHECK(PROPS(2) .EQ. XMU .AND. PROPS(4) .EQ. TMAX,
     1   'PROPS not written', K)
C
        SP = SPN
        GOLD = G
        TPREV = TNOW
  100 CONTINUE
C
C     Dissipation over the whole path: closed form and the independent
C     sum of tau . dslip.
      CALL CHKNR(SUMSFD, TAUC*GC*(19.0D0 + 38.0D0), 57.0D0*TOLE,
     1 'sum SFD = tau_crit gc (19+38)', 3*NUP)
      CALL CHKNR(SUMTDS, SUMSFD, 57.0D0*TOLE,
     1 'sum SFD = sum tau . DSLIP', 3*NUP)
      CALL CHKNR(STATEV(1), GC*(19.0D0 + 38.0D0), 57.0D0*TOLG,
     1 'STATEV(1) = 57 gc at the end', 3*NUP)
      END

C-----------------------------------------------------------------------
C     LM = 2 on entry (frictionless this iteration): FRIC returns at once
C     and writes nothing, not even PNEWDT.
C-----------------------------------------------------------------------
      SUBROUTINE LMTWO
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
C
      CALL F1HOST('F1-LM2')
      DO 50 NFDIR = 1, 2
        WRITE (CASE,'(A,I1)') 'F1 LM=2 on entry NFDIR=', NFDIR
        CALL SENTAL(TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1   STATEV,DGAM,TAULM,MG,MSV)
        DO 10 I = 1, MG
          DGAM(I) = 5.0D-3
          TAULM(I) = 50.0D0
   10   CONTINUE
        LM = 2
        CALL FRICH
        CALL CHECK(LM .EQ. 2, 'LM = 2 stays 2', 1)
        CALL CHECK(PNEWDT .EQ. BIG, 'PNEWDT untouched', 1)
        CALL CHECK(SED .EQ. SENT .AND. SFD .EQ. SENT,
     1   'SED, SFD untouched', 1)
        CALL GUARD1(TAU, 1, MG, 'TAU untouched', 1)
        CALL GUARD1(DDTDDG, 1, MG, 'DDTDDG untouched', 1)
        CALL GUARD1(DDTDDP, 1, MG, 'DDTDDP untouched', 1)
        CALL GUARD1(DSLIP, 1, MG, 'DSLIP untouched', 1)
        CALL GUARD1(DDTDDT, 1, MG, 'DDTDDT untouched', 1)
        CALL GUARD1(STATEV, 1, MSV, 'STATEV untouched', 1)
   50 CONTINUE
      END

C-----------------------------------------------------------------------
C     Rough friction (PROPS(7) = 2): the point never slips, FRIC always
C     answers LM = 1, whatever the motion or the Lagrange stress.  With
C     LM = 1 out: TAU, DDTDDG, DDTDDP not written; DSLIP = 0, SED = 0,
C     SFD = 0; STATEV(1) kept, STATEV(2) = 0, STATEV(3) = 2.
C-----------------------------------------------------------------------
      SUBROUTINE ROUGH
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
C
      CALL F1HOST('F1-ROUGH')
      PROPS(6) = 0.0D0
      PROPS(7) = 2.0D0
      NPROPS = 7
      DO 50 NFDIR = 1, 2
C       LMIN = 0: first call of an increment with a large motion;
C       LMIN = 1: next iteration with a Lagrange stress 1e3 mu p.
        DO 40 LMIN = 0, 1
          WRITE (CASE,'(A,I1,A,I1)') 'F1 rough NFDIR=', NFDIR,
     1     ' LM in=', LMIN
          CALL SENTAL(TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1     STATEV,DGAM,TAULM,MG,MSV)
          DO 11 I = 1, NFDIR
            TAU(I) = 7.0D0
            DGAM(I) = 1.0D-1
            TAULM(I) = 3.0D4
   11     CONTINUE
          STATEV(1) = 0.5D0
          STATEV(2) = 0.1D0
          STATEV(3) = 1.0D0
          LM = LMIN
          CALL FRICH
          CALL CHECK(LM .EQ. 1, 'rough returns LM = 1', 1)
          CALL CHECK(PNEWDT .EQ. BIG, 'PNEWDT untouched', 1)
          DO 20 I = 1, NFDIR
            CALL CHECK(TAU(I) .EQ. 7.0D0, 'TAU not written', 1)
            CALL CHECK(DSLIP(I) .EQ. 0.0D0, 'DSLIP = 0', 1)
   20     CONTINUE
          CALL GUARD1(DDTDDG, 1, MG, 'DDTDDG not written (LM=1)', 1)
          CALL GUARD1(DDTDDP, 1, MG, 'DDTDDP not written (LM=1)', 1)
          CALL GUARD1(TAU, NFDIR+1, MG, 'TAU tail', 1)
          CALL GUARD1(DSLIP, NFDIR+1, MG, 'DSLIP tail', 1)
          CALL CHECK(SED .EQ. 0.0D0 .AND. SFD .EQ. 0.0D0,
     1     'SED = SFD = 0', 1)
          CALL CHECK(STATEV(1) .EQ. 0.5D0, 'STATEV(1) kept', 1)
          CALL CHECK(STATEV(2) .EQ. 0.0D0, 'STATEV(2) = 0', 1)
          CALL CHECK(STATEV(3) .EQ. 2.0D0,
     1     'STATEV(3) = 2 exact stick', 1)
          CALL GUARD1(STATEV, NSTATV+1, MSV, 'STATEV past NSTATV', 1)
   40   CONTINUE
   50 CONTINUE
      END

C-----------------------------------------------------------------------
C     Output arrays past NFDIR (NFDIR**2 for DDTDDG, 2*NFDIR for DDTDDT)
C     and STATEV past NSTATV still hold the sentinel.
C-----------------------------------------------------------------------
      SUBROUTINE GUARDS(TAU, DDTDDG, DDTDDP, DSLIP, DDTDDT, STATEV,
     1 NFDIR, NSTATV, MG, MSV, K)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION TAU(MG),DDTDDG(MG),DDTDDP(MG),DSLIP(MG),DDTDDT(MG),
     1 STATEV(MSV)
      CALL GUARD1(TAU, NFDIR+1, MG, 'TAU past NFDIR', K)
      CALL GUARD1(DDTDDG, NFDIR*NFDIR+1, MG, 'DDTDDG past NFDIR**2', K)
      CALL GUARD1(DDTDDP, NFDIR+1, MG, 'DDTDDP past NFDIR', K)
      CALL GUARD1(DSLIP, NFDIR+1, MG, 'DSLIP past NFDIR', K)
      CALL GUARD1(DDTDDT, 2*NFDIR+1, MG, 'DDTDDT past 2*NFDIR', K)
      CALL GUARD1(STATEV, NSTATV+1, MSV, 'STATEV past NSTATV', K)
      END
