C=======================================================================
C     test_fric_bad_input.f -- fixed-form twin of the C bad-input
C     harness: every documented bad input reaches FRIC from legacy
C     Fortran 77 (INCLUDE 'ABA_PARAM.INC', plain CALL FRIC, no
C     interface block), and each one must give the documented failure
C     output (docs/fric.md, "Bad input"):
C       PNEWDT = 0.25 (only ever lowered); LM, TAU, STATEV unchanged;
C       DDTDDG, DDTDDP, DSLIP, DDTDDT zeroed and SFD = 0 when NFDIR is
C       1 or 2, no array written otherwise; entries past NFDIR / NSTATV
C       untouched; inputs never written;
C       message "interfacial: FRIC: interaction 'NAME' (element E,
C       node N, point P): cause", read back through the native
C       ifl_last_error_copy (the only routine given an interface block).
C     Each case gets its own interaction name, so a stale message from
C     an earlier case cannot pass.  A caller that declares CHARACTER*8
C     names (old user code) checks that the hidden length is trusted.
C
C     The tally (TALLY0, CHECK, CHKNR, TALLYE: last line "<n> passed,
C     <m> failed"), GUARD1, SENTAL, F1HOST, FRICH (the plain CALL FRIC
C     of the host point), HOSTIN, F1PT, NANINF, GETMSG and COPYV come
C     from harness_f77.f, the host point (COMMON) from fric_host.inc.
C
C=======================================================================
      PROGRAM TFBAD
      INCLUDE 'ABA_PARAM.INC'
      COMMON /TALLY/ NPASS,NFAIL
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      CALL TALLY0
C     NaN and Inf made at run time (NANINF, harness_f77.f).
      CALL NANINF(XNAN, XINF)
C
C     Case 0 is the untouched baseline (it must succeed, so that every
C     failure below comes from its one bad argument).  NFDIR = 0 and 3
C     (cases 1, 2) are bad for either host dimension: run them once.
C     Case 6 is the table of inputs that must be finite (INPUT 1..4:
C     PRESS, DPRESS, DGAM(NFDIR), TAU(NFDIR)), each with NaN, +Inf and
C     -Inf in turn (IVAL 1..3), as non_finite_inputs of the C twin.
      DO 30 ICASE = 0, 19
        DO 20 NDIR = 1, 2
          IF ((ICASE .EQ. 1 .OR. ICASE .EQ. 2) .AND. NDIR .EQ. 1)
     1     GO TO 20
          IF (ICASE .NE. 6) CALL BADONE(ICASE, NDIR, 0, 0, XNAN, XINF)
          IF (ICASE .NE. 6) GO TO 20
          DO 15 INPUT = 1, 4
            DO 10 IVAL = 1, 3
              CALL BADONE(ICASE, NDIR, INPUT, IVAL, XNAN, XINF)
   10       CONTINUE
   15     CONTINUE
   20   CONTINUE
   30 CONTINUE
      CALL OLDUSR
      CALL TALLYE
      END

C-----------------------------------------------------------------------
C     One FRIC call from a good baseline (mu = 0.3, p = 100, gc = 1e-3,
C     mid-slip state) with the bad argument of case ICASE:
C        0 none (baseline)        6 input INPUT of the table below
C        1 NFDIR = 0                 = value IVAL of the table below
C        2 NFDIR = 3              7 NSTATV = 2
C        3 NPROPS = 1             8 CHRLNGTH = 0 with PROPS(5) = 0
C        4 PROPS(1) = 4 (no law)  9 LM = 5 on entry
C        5 PROPS(2) = mu < 0     10 PROPS(2) = mu < 0 from a host that
C                                   had already asked for a smaller
C                                   increment (PNEWDT = 0.1 on entry):
C                                   PNEWDT is only ever lowered, so it
C                                   stays 0.1
C       11 NPROPS = 0            16 CHRLNGTH < 0 with PROPS(5) = 0
C       12 PROPS(1) = 1.5 (the   17 DTIME = NaN
C          law code an integer)  18 STATEV(1) = NaN
C       13 PROPS(3) = mu2 < 0    19 TAULM(1) = NaN with exact stick
C       14 PROPS(7) = 5             held (PROPS(7) = 1, LM = 1 on
C       15 PROPS(8) = 1e-3 with     entry: TAULM is read)
C          NPROPS = 8
C     (the C twin's catalogue).
C     The inputs of case 6, each of which must be finite: PRESS, DPRESS,
C     DGAM(NFDIR), TAU(NFDIR) (an array gets the value in its last
C     component, so that a check of the first one only would miss it);
C     the values: NaN, +Inf, -Inf.  The cause names the input (' PRESS'
C     with its blank, so that DPRESS does not count) and says NaN for
C     all three values.
C-----------------------------------------------------------------------
      SUBROUTINE BADONE(ICASE, NDIR, INPUT, IVAL, XNAN, XINF)
      INCLUDE 'ABA_PARAM.INC'
      COMMON /TALLY/ NPASS,NFAIL
      INCLUDE 'fric_host.inc'
      DIMENSION TAUIN(MG),SVIN(MSV),DGIN(MG),PRIN(8),XNONF(3)
      CHARACTER*16 KEY(0:19)
      CHARACTER*12 NFKEY(4)
      CHARACTER*4 NFVAL(3)
      CHARACTER*200 EXPECT
      CHARACTER*512 MSG
      LOGICAL VALID,SAMEX
      DATA KEY /' ', 'NFDIR = 0', 'NFDIR = 3', 'NPROPS = 1',
     1 'PROPS(1) = 4', 'PROPS(2)', ' ', 'NSTATV = 2',
     2 'CHRLNGTH', 'LM = 5', 'PROPS(2)', 'NPROPS = 0',
     3 'PROPS(1) = 1.5', 'PROPS(3)', 'PROPS(7)', 'PROPS(8)',
     4 'CHRLNGTH', 'DTIME', 'STATEV', 'TAULM'/
      DATA NFKEY /' PRESS', 'DPRESS', 'DGAM', 'TAU'/
      DATA NFVAL /'NaN', '+Inf', '-Inf'/
      XNONF(1) = XNAN
      XNONF(2) = XINF
      XNONF(3) = -XINF
C
      IF (INPUT .EQ. 0) THEN
        WRITE (CASE,'(A,I0,A,I0)') 'bad input case ', ICASE,
     1   ' host NFDIR=', NDIR
      ELSE
        WRITE (CASE,'(4A,I0)') TRIM(ADJUSTL(NFKEY(INPUT))), ' = ',
     1   TRIM(NFVAL(IVAL)), ', host NFDIR=', NDIR
      END IF
      CALL F1HOST(' ')
      WRITE (CINAME,'(A,I2.2,A,2I1,A,I1)') 'CP-BAD', ICASE, '-',
     1 INPUT, IVAL, '-', NDIR
      NFDIR = NDIR
      PROPS(6) = SENT
      PROPS(7) = SENT
      LM = 0
      CALL SENTAL(TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1 STATEV,DGAM,TAULM,MG,MSV)
      TAU(1) = 30.0D0
      DGAM(1) = 2.0D-4
      IF (NDIR .EQ. 2) THEN
        TAU(1) = 18.0D0
        TAU(2) = -24.0D0
        DGAM(2) = 1.0D-4
      END IF
      STATEV(1) = 0.5D0
      STATEV(2) = 0.1D0
      STATEV(3) = 1.0D0
C
      IF (ICASE .EQ. 1) NFDIR = 0
      IF (ICASE .EQ. 2) NFDIR = 3
      IF (ICASE .EQ. 3) NPROPS = 1
      IF (ICASE .EQ. 4) PROPS(1) = 4.0D0
      IF (ICASE .EQ. 5 .OR. ICASE .EQ. 10) PROPS(2) = -0.3D0
      IF (INPUT .EQ. 1) PRESS = XNONF(IVAL)
      IF (INPUT .EQ. 2) DPRESS = XNONF(IVAL)
      IF (INPUT .EQ. 3) DGAM(NDIR) = XNONF(IVAL)
      IF (INPUT .EQ. 4) TAU(NDIR) = XNONF(IVAL)
      IF (ICASE .EQ. 7) NSTATV = 2
      IF (ICASE .EQ. 8) THEN
        CHRLNGTH = 0.0D0
        PROPS(5) = 0.0D0
      END IF
      IF (ICASE .EQ. 9) LM = 5
      IF (ICASE .EQ. 11) NPROPS = 0
      IF (ICASE .EQ. 12) PROPS(1) = 1.5D0
      IF (ICASE .EQ. 13) PROPS(3) = -0.4D0
C     Cases 14, 15 and 19 give PROPS(6..7) (and 8) a meaning.
      IF (ICASE .EQ. 14 .OR. ICASE .EQ. 15 .OR. ICASE .EQ. 19) THEN
        PROPS(6) = 0.0D0
        PROPS(7) = 0.0D0
        NPROPS = 7
      END IF
      IF (ICASE .EQ. 14) PROPS(7) = 5.0D0
      IF (ICASE .EQ. 15) THEN
        PROPS(8) = 1.0D-3
        NPROPS = 8
      END IF
      IF (ICASE .EQ. 16) THEN
        CHRLNGTH = -0.2D0
        PROPS(5) = 0.0D0
      END IF
      IF (ICASE .EQ. 17) DTIME = XNAN
      IF (ICASE .EQ. 18) STATEV(1) = XNAN
      IF (ICASE .EQ. 19) THEN
        PROPS(7) = 1.0D0
        LM = 1
        TAULM(1) = XNAN
      END IF
      PNWANT = 0.25D0
      IF (ICASE .EQ. 10) THEN
        PNEWDT = 0.1D0
        PNWANT = 0.1D0
      END IF
      LMIN = LM
      PRSIN = PRESS
      DPRIN = DPRESS
      CALL COPYV(TAU, TAUIN, MG)
      CALL COPYV(DGAM, DGIN, MG)
      CALL COPYV(STATEV, SVIN, MSV)
      CALL COPYV(PROPS, PRIN, 8)
C
      CALL FRICH
C
      IF (ICASE .EQ. 0) THEN
C       Baseline, mid-slip at the plateau: gamma_pr = gc n + DGAM
C       points along TAU + k_s DGAM, |.| > gc, so tau = mu p n.
        CALL CHECK(LM .EQ. 0 .AND. PNEWDT .EQ. BIG,
     1   'baseline succeeds: LM = 0, PNEWDT untouched', 0)
        TX = TAUIN(1) + 3.0D4*DGIN(1)
        TY = 0.0D0
        IF (NDIR .EQ. 2) TY = TAUIN(2) + 3.0D4*DGIN(2)
        TN = SQRT(TX**2 + TY**2)
        CALL CHKNR(TAU(1), 30.0D0*TX/TN, 1.0D-12*30.0D0,
     1   'baseline tau = mu p n', 0)
        IF (NDIR .EQ. 2) CALL CHKNR(TAU(2), 30.0D0*TY/TN,
     1   1.0D-12*30.0D0, 'baseline tau = mu p n', 0)
        RETURN
      END IF
C
      CALL CHECK(PNEWDT .EQ. PNWANT,
     1 'PNEWDT = 0.25 (0.1 when 0.1 on entry)', 0)
      CALL CHECK(LM .EQ. LMIN, 'LM unchanged', 0)
      CALL SAME(TAU, TAUIN, MG, 'TAU unchanged (all entries)')
      CALL SAME(STATEV, SVIN, MSV, 'STATEV unchanged (all entries)')
      CALL SAME(PROPS, PRIN, 8, 'PROPS not written')
      CALL SAME(DGAM, DGIN, MG, 'DGAM not written')
      IF (ICASE .EQ. 19) THEN
        CALL CHECK(TAULM(1) .NE. TAULM(1), 'TAULM (NaN) not written', 0)
        CALL GUARD1(TAULM, 2, MG, 'TAULM not written', 0)
      ELSE
        CALL GUARD1(TAULM, 1, MG, 'TAULM not written', 0)
      END IF
      CALL CHECK(SED .EQ. SENT, 'SED not written', 0)
      CALL ZEROS(SLIP, MG, 'SLIP not written')
      CALL CHECK(SAMEX(PRESS, PRSIN), 'PRESS not written', 0)
      CALL CHECK(SAMEX(DPRESS, DPRIN), 'DPRESS not written', 0)
      VALID = NFDIR .EQ. 1 .OR. NFDIR .EQ. 2
      IF (VALID) THEN
        CALL ZEROS(DDTDDG, NFDIR*NFDIR, 'DDTDDG zeroed')
        CALL ZEROS(DDTDDP, NFDIR, 'DDTDDP zeroed')
        CALL ZEROS(DSLIP, NFDIR, 'DSLIP zeroed')
        CALL ZEROS(DDTDDT, 2*NFDIR, 'DDTDDT zeroed')
        CALL CHECK(SFD .EQ. 0.0D0, 'SFD = 0', 0)
        CALL GUARD1(DDTDDG, NFDIR*NFDIR+1, MG, 'DDTDDG past NFDIR**2',
     1   0)
        CALL GUARD1(DDTDDP, NFDIR+1, MG, 'DDTDDP past NFDIR', 0)
        CALL GUARD1(DSLIP, NFDIR+1, MG, 'DSLIP past NFDIR', 0)
        CALL GUARD1(DDTDDT, 2*NFDIR+1, MG, 'DDTDDT past 2*NFDIR', 0)
      ELSE
        CALL GUARD1(DDTDDG, 1, MG, 'bad NFDIR: DDTDDG not written', 0)
        CALL GUARD1(DDTDDP, 1, MG, 'bad NFDIR: DDTDDP not written', 0)
        CALL GUARD1(DSLIP, 1, MG, 'bad NFDIR: DSLIP not written', 0)
        CALL GUARD1(DDTDDT, 1, MG, 'bad NFDIR: DDTDDT not written', 0)
      END IF
C
      CALL GETMSG(MSG, L)
      NF0 = NFAIL
      EXPECT = 'interfacial: FRIC: interaction '''//TRIM(CINAME)//
     1 ''' (element 0, node 7, point 1): '
      LE = LEN_TRIM(EXPECT) + 1
      CALL CHECK(L .GT. LE .AND. L .LT. LEN(MSG),
     1 'message length sensible', 0)
      CALL CHECK(INDEX(MSG(1:L), EXPECT(1:LE)) .EQ. 1,
     1 'message names FRIC, the interaction and the point', 0)
      IF (INPUT .EQ. 0) THEN
        CALL CHECK(INDEX(MSG(LE+1:L), TRIM(KEY(ICASE))) .GT. 0,
     1   'message names the bad argument', 0)
      ELSE
C       From LE, the blank before the cause: ' PRESS' may open it.
        CALL CHECK(INDEX(MSG(LE:L), TRIM(NFKEY(INPUT))) .GT. 0,
     1   'message names the non-finite input', 0)
        CALL CHECK(INDEX(MSG(LE:L), 'NaN') .GT. 0,
     1   'message says NaN (for NaN and both Infs)', 0)
      END IF
      IF (NFAIL .GT. NF0 .AND. NFAIL .LE. 40) WRITE (*,'(2A)')
     1 '   message: ', MSG(1:MIN(L,200))
      END

C-----------------------------------------------------------------------
C     Old user code: CHARACTER*8 names, so the hidden lengths are 8.  The
C     interaction name fills all 8 characters and is followed in memory
C     (COMMON /OLDNAM/) by other text: the message must stop at 8.
C     A good call must also work unchanged from this caller.
C-----------------------------------------------------------------------
      SUBROUTINE OLDUSR
      INCLUDE 'ABA_PARAM.INC'
      COMMON /TALLY/ NPASS,NFAIL
      CHARACTER*8 CINAME,SLNAME,MSNAME,CTAIL
      COMMON /OLDNAM/ CINAME,CTAIL
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      PARAMETER (MG=8, MSV=8, SENT=-999.25D0, BIG=1.0D36)
      DIMENSION TAU(MG),DDTDDG(MG),DDTDDP(MG),DSLIP(MG),DDTDDT(MG),
     1 STATEV(MSV),DGAM(MG),TAULM(MG),SLIP(MG),TIME(2),COORDS(3),
     2 RCOORD(3),DROT(2,2),TEMP(2),PREDEF(2,1),PROPS(5)
      CHARACTER*512 MSG
C
      CALL HOSTIN(KSTEP,KINC,TIME,DTIME,NOEL,NPT,NODE,NPATCH,COORDS,
     1 RCOORD,DROT,TEMP,PREDEF,MCRD,NPRED,DDPDDH,SLIP,MG,CINAME,SLNAME,
     2 MSNAME,'OLDCP-08')
      CTAIL = 'NOTNAME!'
      SLNAME = 'SLV'
      MSNAME = 'MST'
      NFDIR = 2
      CALL F1PT(PROPS, NPROPS, CHRLNGTH, NSTATV, PRESS, DPRESS)
      DPRESS = 100.0D0
      DO 40 IBAD = 0, 1
        IF (IBAD .EQ. 0) THEN
          CASE = 'CHARACTER*8 caller, good call'
        ELSE
          CASE = 'CHARACTER*8 caller, mu < 0'
        END IF
        IF (IBAD .EQ. 1) PROPS(2) = -0.3D0
        CALL SENTAL(TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1   STATEV,DGAM,TAULM,MG,MSV)
        STATEV(1) = 0.0D0
        STATEV(2) = 0.0D0
        STATEV(3) = 0.0D0
C       First contact (p - DPRESS = 0), DGAM = (4e-4, -3e-4), inside
C       gc = 1e-3: tau = k_s DGAM with k_s = mu p/gc = 3e4.
        TAU(1) = 0.0D0
        TAU(2) = 0.0D0
        DGAM(1) = 4.0D-4
        DGAM(2) = -3.0D-4
        LM = 0
        CALL FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,
     1   DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,
     2   KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,
     3   NPATCH,COORDS,RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,
     4   NSTATV,CHRLNGTH,PROPS,NPROPS)
        IF (IBAD .EQ. 0) THEN
          CALL CHECK(LM .EQ. 0 .AND. PNEWDT .EQ. BIG,
     1     'good call: LM = 0, PNEWDT untouched', 0)
          CALL CHKNR(TAU(1), 3.0D4*4.0D-4, 1.0D-12*30.0D0,
     1     'good call: tau = k_s DGAM', 0)
          CALL CHKNR(TAU(2), -3.0D4*3.0D-4, 1.0D-12*30.0D0,
     1     'good call: tau = k_s DGAM', 0)
          CALL GUARD1(TAU, 3, MG, 'good call: TAU past NFDIR', 0)
        ELSE
          CALL CHECK(PNEWDT .EQ. 0.25D0, 'PNEWDT = 0.25', 0)
          CALL CHECK(TAU(1) .EQ. 0.0D0 .AND. TAU(2) .EQ. 0.0D0,
     1     'TAU unchanged', 0)
          CALL CHECK(STATEV(3) .EQ. 0.0D0, 'STATEV unchanged', 0)
          CALL GETMSG(MSG, L)
          NF0 = NFAIL
          CALL CHECK(INDEX(MSG(1:L),
     1     'interfacial: FRIC: interaction ''OLDCP-08'' (') .EQ. 1,
     2     'message has the 8-character name, nothing past it', 0)
          CALL CHECK(INDEX(MSG(1:L), 'NOTNAME') .EQ. 0,
     1     'nothing read past the hidden length', 0)
          IF (NFAIL .GT. NF0 .AND. NFAIL .LE. 40) WRITE (*,'(2A)')
     1     '   message: ', MSG(1:MIN(L,200))
        END IF
        CALL CHECK(CINAME .EQ. 'OLDCP-08' .AND. CTAIL .EQ. 'NOTNAME!',
     1   'names not written', 0)
   40 CONTINUE
      END

C     A(1..N) the same as B(1..N), a NaN the same as a NaN.
      SUBROUTINE SAME(A, B, N, WHAT)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION A(N), B(N)
      CHARACTER*(*) WHAT
      LOGICAL OK,SAMEX
      OK = .TRUE.
      DO 10 I = 1, N
        IF (.NOT. SAMEX(A(I), B(I))) OK = .FALSE.
   10 CONTINUE
      CALL CHECK(OK, WHAT, 0)
      END

C     A and B equal, or both NaN (an input left as the host set it).
      LOGICAL FUNCTION SAMEX(A, B)
      INCLUDE 'ABA_PARAM.INC'
      SAMEX = A .EQ. B .OR. (A .NE. A .AND. B .NE. B)
      END

      SUBROUTINE ZEROS(A, N, WHAT)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION A(N)
      CHARACTER*(*) WHAT
      LOGICAL OK
      OK = .TRUE.
      DO 10 I = 1, N
        IF (A(I) .NE. 0.0D0) OK = .FALSE.
   10 CONTINUE
      CALL CHECK(OK, WHAT, 0)
      END
