C=======================================================================
C     test_gapcon_bad_input.f -- fixed-form twin of the C GAPCON
C     bad-input harness: every documented failure reaches GAPCON from
C     legacy Fortran 77 (INCLUDE 'ABA_PARAM.INC', plain CALL GAPCON,
C     no interface block) and must give the documented failure output
C     (docs/gapcon.md):
C       AK(1) = 0 (no conductance), AK(2..5) untouched, inputs never
C       written; message "interfacial: GAPCON: interaction 'NAME'
C       (element E, node N): cause", read back through the native
C       ifl_last_error_copy; for a configuration error the cause is
C       "file:line: key: ..." (or the file and why it cannot be read).
C     The configuration is read once per process, so CTest runs this
C     program once per configuration, the first argument saying which:
C       good      configs/gapcon_good.toml (no "*" entry): unlisted and
C                 prefix-only names, NaN/Inf D and TEMP (made at run
C                 time), temperatures below absolute zero, overflow;
C                 good calls around them, also ignoring case;
C       unsorted  configs/gapcon_unsorted.toml: a table out of order
C                 at the line marked "expected-error-line" (found by
C                 reading the file, not written here);
C       missing   INTERFACIAL_CONFIG names a file that does not exist;
C       unset     INTERFACIAL_CONFIG is empty.
C     In every mode a CHARACTER*8 caller (old user code) follows: its
C     8-character name must match (good) or be reported (bad) without
C     a byte read past the hidden length.  Each call has its own
C     element number, so a stale message cannot pass.
C
C     GAPONE (one checked GAPCON call), the tally, NANINF and GETMSG
C     come from harness_f77.f; the run's COMMON /CFGC/ from
C     gapcon_cfg.inc.
C
C=======================================================================
      PROGRAM TGBAD
      INCLUDE 'ABA_PARAM.INC'
      COMMON /TALLY/ NPASS,NFAIL
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      INCLUDE 'gapcon_cfg.inc'
      CALL TALLY0
      MODE = 'good'
      IF (COMMAND_ARGUMENT_COUNT() .GE. 1)
     1 CALL GET_COMMAND_ARGUMENT(1, MODE)
      CFG = ' '
      CALL GET_ENVIRONMENT_VARIABLE('INTERFACIAL_CONFIG', CFG)
      WRITE (*,'(4A)') '  mode ', TRIM(MODE), ', INTERFACIAL_CONFIG=',
     1 TRIM(CFG)
C     NaN and Inf made at run time (NANINF, harness_f77.f).
      CALL NANINF(XNAN, XINF)
C
      IF (MODE .EQ. 'good') THEN
        CALL GOOD(XNAN, XINF)
      ELSE
        CALL BADCFG
      END IF
      CALL OLDUSR(XNAN)
      CALL TALLYE
      END

C-----------------------------------------------------------------------
C     Good configuration: a good call, then each bad input (one per
C     element number NOEL), then good calls again (no sticky state).
C     h of T1CONST = 2000 and of T1PTAB at p = 40 is 1500 (by hand).
C-----------------------------------------------------------------------
      SUBROUTINE GOOD(XNAN, XINF)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      INCLUDE 'gapcon_cfg.inc'
      PARAMETER (SENT=-999.25D0)
C
      CASE = 'good call T1CONST'
      CALL GAPONE('T1CONST', 0.0D0, 40.0D0, 400.0D0, 380.0D0, 1, AK1)
      CALL CHECK(AK1 .EQ. 2000.0D0, 'AK(1) = k = 2000', 1)
C
      CASE = 'unlisted interaction, no "*" entry'
      CALL GAPONE('NOSUCH', 0.0D0, 40.0D0, 400.0D0, 380.0D0, 2, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', 2)
      CAUSE = 'interaction not found in '//TRIM(CFG)//
     1 ' (and no "*" entry)'
      CALL EXPMSG('GAPCON', 'NOSUCH', 2, 'bad parameter', 1)
C
      CASE = 'prefix of a listed name'
      CALL GAPONE('T1CONSTX', 0.0D0, 40.0D0, 400.0D0, 380.0D0, 3, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0 (never matched by prefix)',
     1 3)
      CALL EXPMSG('GAPCON', 'T1CONSTX', 3, 'bad parameter', 1)
C
      CASE = 'lower-case name'
      CALL GAPONE('t1const', 0.0D0, 40.0D0, 400.0D0, 380.0D0, 4, AK1)
      CALL CHECK(AK1 .EQ. 2000.0D0, 'AK(1) = 2000 (case ignored)', 4)
C
      CASE = 'TEMP(1) = NaN'
      CALL GAPONE('T1CONST', 0.0D0, 40.0D0, XNAN, 380.0D0, 5, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', 5)
      CAUSE = 'TEMP(1) is NaN or infinite'
      CALL EXPMSG('GAPCON', 'T1CONST', 5, 'bad input', 1)
C
      CASE = 'TEMP(2) = NaN with radiation'
      CALL GAPONE('RADK', 1.0D-3, 0.0D0, 400.0D0, XNAN, 6, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', 6)
      CAUSE = 'TEMP(2) is NaN or infinite'
      CALL EXPMSG('GAPCON', 'RADK', 6, 'bad input', 1)
C
      CASE = 'D(1) = +Inf, gas gap'
      CALL GAPONE('GASRAD', XINF, 0.0D0, 400.0D0, 380.0D0, 7, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', 7)
      CAUSE = 'D(1) is NaN or infinite'
      CALL EXPMSG('GAPCON', 'GASRAD', 7, 'bad input', 1)
C
      CASE = 'D(2) = NaN, pressure table'
      CALL GAPONE('T1PTAB', 0.0D0, XNAN, 400.0D0, 380.0D0, 8, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', 8)
      CAUSE = 'D(2) is NaN or infinite'
      CALL EXPMSG('GAPCON', 'T1PTAB', 8, 'bad input', 1)
C
C     -300 degC and -1 K: below absolute zero on the model's scale.
      CASE = 'below absolute zero, Celsius'
      CALL GAPONE('RADC', 1.0D-3, 0.0D0, -300.0D0, 20.0D0, 9, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', 9)
      CAUSE = 'below absolute zero'
      CALL EXPMSG('GAPCON', 'RADC', 9, 'bad input', 0)
      CASE = 'below absolute zero, kelvin'
      CALL GAPONE('RADK', 1.0D-3, 0.0D0, 300.0D0, -1.0D0, 10, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', 10)
      CALL EXPMSG('GAPCON', 'RADK', 10, 'bad input', 0)
C
C     F sigma (a + b)(a^2 + b^2) at a = b = 1e110 overflows a double.
      CASE = 'radiation overflow'
      CALL GAPONE('RADK', 1.0D-3, 0.0D0, 1.0D110, 1.0D110, 11, AK1)
      CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', 11)
      CAUSE = 'overflow'
      CALL EXPMSG('GAPCON', 'RADK', 11, 'numerical failure',
     1 0)
C
      CASE = 'good calls after the failures'
      CALL GAPONE('T1CONST', 0.0D0, 40.0D0, 400.0D0, 380.0D0, 12, AK1)
      CALL CHECK(AK1 .EQ. 2000.0D0, 'AK(1) = 2000 again', 12)
      CALL GAPONE('T1PTAB', 0.0D0, 40.0D0, 400.0D0, 380.0D0, 13, AK1)
      CALL CHKNR(AK1, 500.0D0 + (3000.0D0 - 500.0D0)*0.4D0,
     1 1.0D-13*1500.0D0, 'T1PTAB at p = 40: AK(1) = 1500', 13)
C
C     The native entry point gives the same failure for a name that
C     is not configured, and succeeds for a listed one.
      CASE = 'ifl_gap_conductance, unlisted name'
      CAUSE = 'interaction not found in '//TRIM(CFG)//
     1 ' (and no "*" entry)'
      CALL NATIVE('NOSUCH', 1, 0.0D0)
      CASE = 'ifl_gap_conductance, T1CONST'
      CALL NATIVE('T1CONST', 0, 2000.0D0)
      END

C-----------------------------------------------------------------------
C     Bad configuration (modes unsorted, missing, unset): every call,
C     for every name, fails with the configuration's cause.
C-----------------------------------------------------------------------
      SUBROUTINE BADCFG
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      INCLUDE 'gapcon_cfg.inc'
      CHARACTER*12 NUM
      LOGICAL THERE
      CHARACTER*8 NAMES(3)
      DATA NAMES /'T1CONST', 'BADTAB', 'NOSUCH'/
C
      CASE = 'expected cause of mode '//MODE
      IF (MODE .EQ. 'unsorted') THEN
        CALL MARKLN(CFG, LINENO)
        CALL CHECK(LINENO .GT. 0,
     1   'the config marks its bad line (expected-error-line)', 0)
        WRITE (NUM,'(I0)') LINENO
        CAUSE = TRIM(CFG)//':'//TRIM(NUM)//
     1   ': interactions.BADTAB.conductance.table: rows 1 and 2 are'//
     2   ' not in strictly increasing order'
      ELSE IF (MODE .EQ. 'missing') THEN
        INQUIRE (FILE=CFG, EXIST=THERE)
        CALL CHECK(CFG .NE. ' ' .AND. .NOT. THERE,
     1   'INTERFACIAL_CONFIG names a file that does not exist', 0)
        CAUSE = TRIM(CFG)//': cannot read the configuration file'
      ELSE IF (MODE .EQ. 'unset') THEN
        CALL CHECK(CFG .EQ. ' ', 'INTERFACIAL_CONFIG is empty', 0)
        CAUSE = 'INTERFACIAL_CONFIG is not set'
      ELSE
        CALL CHECK(.FALSE., 'unknown mode (good, unsorted, missing,'//
     1   ' unset)', 0)
        RETURN
      END IF
C
C     Two calls per name, different elements: the message follows.
      DO 20 I = 1, 3
        DO 10 J = 1, 2
          NOEL = 100 + 10*I + J
          WRITE (CASE,'(A,A,A,I0)') 'bad config ', TRIM(MODE),
     1     ' element ', NOEL
          CALL GAPONE(NAMES(I), 0.0D0, 40.0D0, 400.0D0, 380.0D0, NOEL,
     1     AK1)
          CALL CHECK(AK1 .EQ. 0.0D0, 'AK(1) = 0', NOEL)
          CALL EXPMSG('GAPCON', NAMES(I), NOEL, 'bad parameter',
     1     1)
   10   CONTINUE
   20 CONTINUE
      CASE = 'bad config '//TRIM(MODE)//', ifl_gap_conductance'
      CALL NATIVE('T1CONST', 1, 0.0D0)
      END

C-----------------------------------------------------------------------
C     Old user code: CHARACTER*8 names, so the hidden lengths are 8.
C     The interaction name is followed in memory (COMMON /OLDNAM/) by
C     other text: reading past 8 characters would change the name.
C     Good config: 'OLDGAP08' (k = 123.5) and 'T1CONST ' (k = 2000) must
C     match; with TEMP(1) = NaN the message holds the 8 characters and
C     nothing after them.  Bad config: the call fails with its cause.
C-----------------------------------------------------------------------
      SUBROUTINE OLDUSR(XNAN)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*8 CINAME,SLNAME,MSNAME,CTAIL
      COMMON /OLDNAM/ CINAME,CTAIL
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      INCLUDE 'gapcon_cfg.inc'
      DIMENSION AK(5),D(2),FLOWM(2),TEMP(2),PREDEF(2,1),TIME(2),
     1 COORDS(3)
      CHARACTER*512 MSG
      CHARACTER*8 NAMES(3), TAILS(3)
      DATA NAMES /'OLDGAP08', 'T1CONST', 'OLDGAP08'/
      DATA TAILS /'T1CONST', 'XX', 'NOTNAME!'/
C
      SLNAME = 'SLV'
      MSNAME = 'MST'
      DO 30 ICASE = 1, 3
        WRITE (CASE,'(A,I0)') 'CHARACTER*8 caller, case ', ICASE
        CINAME = NAMES(ICASE)
        CTAIL = TAILS(ICASE)
        CALL GAPIN(AK,D,FLOWM,TEMP,PREDEF,TIME,COORDS,NODE,NPRED,
     1   KSTEP,KINC,0.0D0,40.0D0,400.0D0,380.0D0)
        IF (ICASE .EQ. 3) TEMP(1) = XNAN
        NOEL = 200 + ICASE
        CALL GAPCON(AK,D,FLOWM,TEMP,PREDEF,TIME,CINAME,SLNAME,MSNAME,
     1   COORDS,NOEL,NODE,NPRED,KSTEP,KINC)
        CALL GUARD1(AK, 2, 5, 'AK(2..5) untouched', NOEL)
        CALL CHECK(CINAME .EQ. NAMES(ICASE) .AND.
     1   CTAIL .EQ. TAILS(ICASE), 'names not written', NOEL)
        IF (MODE .EQ. 'good' .AND. ICASE .EQ. 1) THEN
          CALL CHECK(AK(1) .EQ. 123.5D0,
     1     'OLDGAP08 matched: AK(1) = 123.5', NOEL)
        ELSE IF (MODE .EQ. 'good' .AND. ICASE .EQ. 2) THEN
          CALL CHECK(AK(1) .EQ. 2000.0D0,
     1     'T1CONST (blank-padded to 8) matched: AK(1) = 2000', NOEL)
        ELSE
          CALL CHECK(AK(1) .EQ. 0.0D0, 'AK(1) = 0', NOEL)
          IF (MODE .EQ. 'good') THEN
            CAUSE = 'TEMP(1) is NaN or infinite'
            CALL EXPMSG('GAPCON', CINAME, NOEL, 'bad input', 1)
          ELSE
            CALL EXPMSG('GAPCON', CINAME, NOEL, 'bad parameter', 1)
          END IF
          CALL GETMSG(MSG, L)
          CALL CHECK(INDEX(MSG(1:L), TRIM(CINAME)//TRIM(CTAIL)) .EQ. 0,
     1     'nothing read past the hidden length', NOEL)
        END IF
   30 CONTINUE
      END

C-----------------------------------------------------------------------
C     The last message must be "interfacial: ROUT: interaction 'NAME'
C     (element NOEL, node 7): KIND: " (NOEL < 0: "(native call)") then
C     CAUSE (IAT = 1: right after; IAT = 0: somewhere after).  KIND is
C     the class of failure, as the native status names it: 'bad
C     parameter' (configuration), 'bad input', 'numerical failure'.
C-----------------------------------------------------------------------
      SUBROUTINE EXPMSG(ROUT, NAME, NOEL, KIND, IAT)
      CHARACTER*(*) ROUT, NAME, KIND
      INCLUDE 'gapcon_cfg.inc'
      COMMON /TALLY/ NPASS,NFAIL
      CHARACTER*600 EXPECT
      CHARACTER*512 MSG
      CHARACTER*12 NUM
      IF (NOEL .GE. 0) THEN
        WRITE (NUM,'(I0)') NOEL
        EXPECT = 'interfacial: '//ROUT//': interaction '''//
     1   TRIM(NAME)//''' (element '//TRIM(NUM)//', node 7): '//
     2   KIND//':'
      ELSE
        EXPECT = 'interfacial: '//ROUT//': interaction '''//
     1   TRIM(NAME)//''' (native call): '//KIND//':'
      END IF
      CALL GETMSG(MSG, L)
      NF0 = NFAIL
      LE = LEN_TRIM(EXPECT) + 1
      CALL CHECK(L .GT. LE .AND. L .LT. LEN(MSG),
     1 'message length sensible', NOEL)
      CALL CHECK(INDEX(MSG(1:L), EXPECT(1:LE)) .EQ. 1,
     1 'message names '//ROUT//', the interaction, the point and '//
     2 KIND, NOEL)
      IF (IAT .EQ. 1) THEN
        CALL CHECK(INDEX(MSG(1:L), EXPECT(1:LE)//TRIM(CAUSE)) .EQ. 1,
     1   'the cause follows: '//TRIM(CAUSE), NOEL)
      ELSE
        CALL CHECK(INDEX(MSG(LE+1:L), TRIM(CAUSE)) .GT. 0,
     1   'the message gives the cause: '//TRIM(CAUSE), NOEL)
      END IF
      IF (NFAIL .GT. NF0 .AND. NFAIL .LE. 40) WRITE (*,'(2A)')
     1 '   message: ', MSG(1:MIN(L,300))
      END
C-----------------------------------------------------------------------
C     ifl_gap_conductance(NAME, d = 0, p = 40, 400, 380): status ISTEXP
C     expected; on success k = AKEXP; on failure all six outputs zero
C     (preset to a sentinel) and the message names the native routine
C     and the cause in CAUSE (IFL_STATUS_BAD_PARAMETER = 1 for a bad
C     configuration or an unlisted name).
C-----------------------------------------------------------------------
      SUBROUTINE NATIVE(NAME, ISTEXP, AKEXP)
      USE, INTRINSIC :: ISO_C_BINDING, ONLY: C_CHAR, C_DOUBLE, C_INT,
     1 C_NULL_CHAR
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*(*) NAME
      INCLUDE 'gapcon_cfg.inc'
      COMMON /TALLY/ NPASS,NFAIL
      TYPE, BIND(C) :: IFLCND
        REAL(C_DOUBLE) :: V(6)
      END TYPE IFLCND
      INTERFACE
        FUNCTION IFLGAP(CNAME, D, P, TA, TB, OUT)
     1   BIND(C, NAME='ifl_gap_conductance')
          IMPORT :: C_CHAR, C_DOUBLE, C_INT, IFLCND
          INTEGER(C_INT) :: IFLGAP
          CHARACTER(KIND=C_CHAR), DIMENSION(*) :: CNAME
          REAL(C_DOUBLE), VALUE :: D, P, TA, TB
          TYPE(IFLCND) :: OUT
        END FUNCTION IFLGAP
      END INTERFACE
      TYPE(IFLCND) :: C
      INTEGER(C_INT) :: IST
      LOGICAL OK
      DO 10 I = 1, 6
        C%V(I) = -999.25D0
   10 CONTINUE
      IST = IFLGAP(TRIM(NAME)//C_NULL_CHAR, 0.0D0, 40.0D0, 400.0D0,
     1 380.0D0, C)
      CALL CHECK(IST .EQ. ISTEXP, 'status as expected', INT(IST))
      IF (ISTEXP .EQ. 0) THEN
        CALL CHECK(C%V(1) .EQ. AKEXP, 'k as expected', 0)
        RETURN
      END IF
      OK = .TRUE.
      DO 20 I = 1, 6
        IF (C%V(I) .NE. 0.0D0) OK = .FALSE.
   20 CONTINUE
      CALL CHECK(OK, 'all six outputs zero on failure', 0)
      CALL EXPMSG('ifl_gap_conductance', NAME, -1, 'bad parameter',
     1 1)
      END

C-----------------------------------------------------------------------
C     Line number of the line of file CFG holding the marker
C     "expected-error-line" (0 if none).
C-----------------------------------------------------------------------
      SUBROUTINE MARKLN(CFG, LINENO)
      CHARACTER*(*) CFG
      CHARACTER*256 LINE
      LINENO = 0
      OPEN (UNIT=11, FILE=CFG, STATUS='OLD', ACTION='READ', IOSTAT=IOS)
      IF (IOS .NE. 0) RETURN
      N = 0
   10 READ (11,'(A)',IOSTAT=IOS) LINE
      IF (IOS .NE. 0) GO TO 20
      N = N + 1
      IF (INDEX(LINE, 'expected-error-line') .GT. 0) THEN
        LINENO = N
        GO TO 20
      END IF
      GO TO 10
   20 CLOSE (11)
      END

