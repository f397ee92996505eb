C=======================================================================
C     test_gapcon_t1.f -- scene T1 "two bars in contact" through GAPCON,
C     called the way a legacy Abaqus/Standard host calls it: fixed-form
C     Fortran 77, INCLUDE 'ABA_PARAM.INC', CHARACTER*80 names and a
C     plain CALL GAPCON(...) with the 15 Abaqus arguments; no interface
C     block, no ISO_C_BINDING.
C
C     Scene T1 (docs/scene-definitions.md): bar A (L_A = 0.1, k_A = 50)
C     held at theta_H = 400 on its far end, bar B (L_B = 0.2, k_B = 15)
C     at theta_C = 300, gap conductance h between the interface
C     temperatures theta_A, theta_B.  The host solves the steady state
C     by Newton on (theta_A, theta_B) with the only tangent GAPCON
C     gives, dq/dtheta_A = AK(1) = -dq/dtheta_B.  Exact flux
C       q = (theta_H - theta_C)/(L_A/k_A + 1/h + L_B/k_B).
C     h is worked out by hand from the configuration file
C     (configs/gapcon_good.toml; docs/config.md): linear between table
C     rows, constant outside the table.  For T1TEMP, h depends on the
C     mean interface temperature, and the converged state must satisfy
C     the same formula with h* = the bilinear table value at the
C     converged mean temperature; the flux is also the root of the
C     quadratic that follows from h linear in the mean temperature.
C
C     The configuration file comes from CTest (INTERFACIAL_CONFIG).
C     GAPONE (one checked GAPCON call) and the tally (CHECK, CHKNR,
C     TALLYE's last line "<n> passed, <m> failed") come from harness_f77.f.
C
C=======================================================================
      PROGRAM TGAPT1
      INCLUDE 'ABA_PARAM.INC'
      COMMON /TALLY/ NPASS,NFAIL
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      CALL TALLY0
C
C     Constant k = 2000: h = 2000 at any pressure.
      CALL T1LIN('T1CONST', 40.0D0, 2000.0D0, 1)
C     Pressure table [[0, 500], [100, 3000]]: inside, on the rows and
C     outside on both sides (constant there, also for p < 0).
      CALL T1LIN('T1PTAB', 40.0D0,
     1 500.0D0 + (3000.0D0 - 500.0D0)*(40.0D0 - 0.0D0)/100.0D0, 2)
      CALL T1LIN('T1PTAB', -5.0D0, 500.0D0, 3)
      CALL T1LIN('T1PTAB', 250.0D0, 3000.0D0, 4)
      CALL T1LIN('T1PTAB', 0.0D0, 500.0D0, 5)
      CALL T1LIN('T1PTAB', 100.0D0, 3000.0D0, 6)
C     Pressure and temperature table at p = 50.
      CALL T1TMP
C
      CALL TALLYE
      END

C-----------------------------------------------------------------------
C     Bars and boundary temperatures of scene T1.
C-----------------------------------------------------------------------
      SUBROUTINE BARS(TH, TC, GA, GB, R0)
      INCLUDE 'ABA_PARAM.INC'
      PARAMETER (XLA=0.1D0, XKA=50.0D0, XLB=0.2D0, XKB=15.0D0)
      TH = 400.0D0
      TC = 300.0D0
C     Bar conductances k/L and the series resistance of both bars.
      GA = XKA/XLA
      GB = XKB/XLB
      R0 = XLA/XKA + XLB/XKB
      END

C-----------------------------------------------------------------------
C     The host's Newton on the interface temperatures, with the tangent
C     a GAPCON host has: dq/dtheta_A = AK(1), dq/dtheta_B = -AK(1).
C       R1 = G_A (theta_H - theta_A) - q,
C       R2 = q - G_B (theta_B - theta_C),
C       q = AK(1) (theta_A - theta_B).
C     Starts from theta_A = theta_H, theta_B = theta_C.  NIT: Newton
C     updates made until one is <= TOL (0 if none within MAXIT).
C     Returns the final temperatures and AK(1) there.
C-----------------------------------------------------------------------
      SUBROUTINE T1SOLV(NAME, P, MAXIT, TOL, TA, TB, AK1, NIT)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*(*) NAME
      CALL BARS(TH, TC, GA, GB, R0)
      TA = TH
      TB = TC
      NIT = 0
      DO 10 IT = 1, MAXIT
        CALL GAPONE(NAME, 0.0D0, P, TA, TB, 1000 + IT, AK1)
        Q = AK1*(TA - TB)
        R1 = GA*(TH - TA) - Q
        R2 = Q - GB*(TB - TC)
        A11 = -GA - AK1
        A12 = AK1
        A21 = AK1
        A22 = -AK1 - GB
        DET = A11*A22 - A12*A21
        DA = (-R1*A22 + A12*R2)/DET
        DB = (-A11*R2 + A21*R1)/DET
        TA = TA + DA
        TB = TB + DB
        IF (MAX(ABS(DA), ABS(DB)) .LE. TOL) THEN
          NIT = IT
          GO TO 20
        END IF
   10 CONTINUE
   20 CALL GAPONE(NAME, 0.0D0, P, TA, TB, 2000, AK1)
      END

C-----------------------------------------------------------------------
C     h independent of temperature (constant or pressure table), h by
C     hand = HEXP.  q is linear in the temperatures, the tangent AK(1)
C     is exact: Newton's first update solves the problem, the second
C     is round-off.  Checks q, both bar fluxes and the interface
C     temperatures against the closed form.
C-----------------------------------------------------------------------
      SUBROUTINE T1LIN(NAME, P, HEXP, ID)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*(*) NAME
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      COMMON /TALLY/ NPASS,NFAIL
      WRITE (CASE,'(A,A,A,F7.1)') 'T1 ', NAME, ' p=', P
      CALL BARS(TH, TC, GA, GB, R0)
      CALL T1SOLV(NAME, P, 10, 1.0D-9, TA, TB, AK1, NIT)
      CALL CHECK(NIT .GE. 1 .AND. NIT .LE. 2,
     1 'exact tangent: Newton done after one update (+1 to confirm)',
     2 ID)
      CALL CHKNR(AK1, HEXP, 1.0D-13*HEXP,
     1 'AK(1) = h from the table by hand', ID)
C     Closed form.
      QEX = (TH - TC)/(R0 + 1.0D0/HEXP)
      TOL = 1.0D-11*QEX
      CALL CHKNR(AK1*(TA - TB), QEX, TOL,
     1 'gap flux AK(1)(theta_A - theta_B) = closed-form q', ID)
      CALL CHKNR(GA*(TH - TA), QEX, TOL, 'bar A flux = q', ID)
      CALL CHKNR(GB*(TB - TC), QEX, TOL, 'bar B flux = q', ID)
      CALL CHKNR(TA, TH - QEX/GA, 1.0D-12*TH,
     1 'theta_A = theta_H - q L_A/k_A', ID)
      CALL CHKNR(TB, TC + QEX/GB, 1.0D-12*TH,
     1 'theta_B = theta_C + q L_B/k_B', ID)
      WRITE (*,'(A,A,A,F7.1,A,F8.1,A,I0,A,1P,E22.15)') '  T1 ',
     1 NAME, ' p =', P, ': h =', HEXP, ', Newton updates ', NIT,
     2 ', q =', AK1*(TA - TB)
      END

C-----------------------------------------------------------------------
C     T1TEMP at p = 50: table rows [p, k, theta_mean]
C       [0, 500, 300], [100, 1500, 300], [0, 900, 400], [100, 2500, 400]
C     so at p = 50, by hand: h(300) = 1000, h(400) = 1700, and between
C     h(tm) = H3 + S (tm - 300), S = (H4 - H3)/100 (constant outside).
C     GAPCON gives no dh/dtm, so the host's Newton is a fixed-point
C     iteration here, converging linearly; run it to round-off.
C     Checks:
C      - the converged mean temperature lies inside (300, 400);
C      - AK(1) there is h* = H3 + S (tm - 300), by hand;
C      - q = (theta_H - theta_C)/(L_A/k_A + 1/h* + L_B/k_B);
C      - q is the positive root of the closed form: with
C        tm = (theta_H + theta_C)/2 + q (L_B/k_B - L_A/k_A)/2,
C        h = a + b q and q (R0 + 1/h) = dT:
C        R0 b q^2 + (R0 a + 1 - dT b) q - dT a = 0.
C-----------------------------------------------------------------------
      SUBROUTINE T1TMP
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      PARAMETER (P=50.0D0)
      CASE = 'T1 T1TEMP p=50'
      CALL BARS(TH, TC, GA, GB, R0)
      H3 = 500.0D0 + (1500.0D0 - 500.0D0)*(P - 0.0D0)/100.0D0
      H4 = 900.0D0 + (2500.0D0 - 900.0D0)*(P - 0.0D0)/100.0D0
      S = (H4 - H3)/(400.0D0 - 300.0D0)
      CALL T1SOLV('T1TEMP', P, 200, 1.0D-11, TA, TB, AK1, NIT)
      CALL CHECK(NIT .GT. 0, 'host iteration converges', 1)
      TM = 0.5D0*(TA + TB)
      CALL CHECK(TM .GT. 300.0D0 .AND. TM .LT. 400.0D0,
     1 'converged mean temperature inside the table (300, 400)', 1)
      HSTAR = H3 + S*(TM - 300.0D0)
      CALL CHKNR(AK1, HSTAR, 1.0D-12*HSTAR,
     1 'AK(1) = bilinear table value at the converged mean', 1)
      Q = AK1*(TA - TB)
      QEX = (TH - TC)/(R0 + 1.0D0/HSTAR)
      TOL = 1.0D-10*QEX
      CALL CHKNR(Q, QEX, TOL, 'q = dT/(L_A/k_A + 1/h* + L_B/k_B)', 1)
      CALL CHKNR(GA*(TH - TA), Q, TOL, 'bar A flux = gap flux', 1)
      CALL CHKNR(GB*(TB - TC), Q, TOL, 'bar B flux = gap flux', 1)
C     The quadratic for q (independent of the iteration).
      DT = TH - TC
      A = H3 + S*(0.5D0*(TH + TC) - 300.0D0)
      B = S*0.5D0*(0.2D0/15.0D0 - 0.1D0/50.0D0)
      QA = R0*B
      QB = R0*A + 1.0D0 - DT*B
      QC = DT*A
      QROOT = 2.0D0*QC/(QB + SQRT(QB*QB + 4.0D0*QA*QC))
      CALL CHKNR(Q, QROOT, TOL,
     1 'q = root of R0 b q^2 + (R0 a + 1 - dT b) q - dT a', 1)
      WRITE (*,'(A,I0,A,F11.6,A,F10.4,A,1P,E22.15)')
     1 '  T1 T1TEMP p = 50: fixed-point updates ', NIT,
     2 ', mean temperature', TM, ', h* =', HSTAR, ', q =', Q
      END
