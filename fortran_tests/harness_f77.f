C=======================================================================
C     harness_f77.f -- the routines the fixed-form harnesses share
C     (test_fric_f1.f, test_fric_bad_input.f, test_fric_rate.f,
C     test_gapcon_t1.f, test_gapcon_bad_input.f, test_vfric.f): the
C     tally TALLY0 / CHECK / CHKNR / TALLYE, the sentinel guard GUARD1,
C     the FRIC arguments preset to the sentinel before a call (SENTAL,
C     SENTOU), the host arguments a Coulomb call does not use (HOSTIN;
C     HOSTAT, where and when the point is, also serves GAPIN), the
C     Coulomb point of scene F1 (F1PT), the host point of
C     fric_host.inc with its one CALL FRIC (HOSTPT, F1HOST, FRICH), a
C     NaN and an Inf made at run time (NANINF), the thread's last
C     library message (GETMSG) and one checked GAPCON call (GAPONE,
C     with SAMEB).
C     Fixed-form Fortran 77 like its callers, which share with it
C       COMMON /TALLY/ NPASS,NFAIL   (zeroed by TALLY0)
C       COMMON /CTX/ CASE            (CHARACTER*48, the current case)
C       COMMON /FHOST/, /FHOSTN/     (the host point, fric_host.inc).
C     Built once (object library fortran_harness_f77) and linked into
C     every fixed-form harness (fortran_tests/CMakeLists.txt).
C=======================================================================

C-----------------------------------------------------------------------
C     The tally opened (TALLY0: counts zero, no case) and closed (TALLYE:
C     the harness's last line "<n> passed, <m> failed", STOP 1 on a
C     failure) by each program.
C-----------------------------------------------------------------------
      SUBROUTINE TALLY0
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      COMMON /TALLY/ NPASS,NFAIL
      NPASS = 0
      NFAIL = 0
      CASE = ' '
      END

      SUBROUTINE TALLYE
      COMMON /TALLY/ NPASS,NFAIL
      WRITE (*,'(I0,A,I0,A)') NPASS, ' passed, ', NFAIL, ' failed'
      IF (NFAIL .GT. 0) STOP 1
      END

C-----------------------------------------------------------------------
C     Tally.  A failure prints the case, K (the check or increment
C     number the caller passes) and the check; the first 40 only, to
C     keep a broken build readable.
C-----------------------------------------------------------------------
      SUBROUTINE CHECK(OK, WHAT, K)
      LOGICAL OK
      CHARACTER*(*) WHAT
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      COMMON /TALLY/ NPASS,NFAIL
      IF (OK) THEN
        NPASS = NPASS + 1
      ELSE
        NFAIL = NFAIL + 1
        IF (NFAIL .LE. 40) WRITE (*,'(A,A,A,I0,A,A)') 'FAIL [',
     1   TRIM(CASE), '] check ', K, ': ', WHAT
      END IF
      END

C     |A - B| <= TOL; a failure also prints got, expected and TOL.
      SUBROUTINE CHKNR(A, B, TOL, WHAT, K)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*(*) WHAT
      COMMON /TALLY/ NPASS,NFAIL
      CALL CHECK(ABS(A - B) .LE. TOL, WHAT, K)
      IF (.NOT. (ABS(A - B) .LE. TOL) .AND. NFAIL .LE. 40)
     1 WRITE (*,'(A,1P,3E24.15)') '   got, expected, tol:', A, B, TOL
      END

C-----------------------------------------------------------------------
C     A(IFROM..ITO) all still hold the sentinel -999.25 (one check); an
C     empty range (ITO < IFROM) is no check at all.
C-----------------------------------------------------------------------
      SUBROUTINE GUARD1(A, IFROM, ITO, WHAT, K)
      INCLUDE 'ABA_PARAM.INC'
      PARAMETER (SENT=-999.25D0)
      DIMENSION A(*)
      CHARACTER*(*) WHAT
      LOGICAL OK
      IF (ITO .LT. IFROM) RETURN
      OK = .TRUE.
      DO 10 I = IFROM, ITO
        IF (A(I) .NE. SENT) OK = .FALSE.
   10 CONTINUE
      CALL CHECK(OK, WHAT, K)
      END

C-----------------------------------------------------------------------
C     The FRIC arguments in the order of the call, preset as the host
C     does before one: every entry of TAU, DDTDDG, DDTDDP, DSLIP,
C     DDTDDT, DGAM, TAULM (MG) and STATEV (MSV) and SED, SFD to the
C     sentinel -999.25, PNEWDT to 1e36 as Abaqus passes it.  The
C     caller then sets the entries it means (up to NFDIR, NSTATV).
C-----------------------------------------------------------------------
      SUBROUTINE SENTAL(TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1 STATEV,DGAM,TAULM,MG,MSV)
      INCLUDE 'ABA_PARAM.INC'
      PARAMETER (SENT=-999.25D0)
      DIMENSION TAU(MG),DDTDDG(MG),DDTDDP(MG),DSLIP(MG),DDTDDT(MG),
     1 STATEV(MSV),DGAM(MG),TAULM(MG)
      CALL SENTOU(DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,MG)
      DO 10 I = 1, MG
        TAU(I) = SENT
        DGAM(I) = SENT
        TAULM(I) = SENT
   10 CONTINUE
      DO 20 I = 1, MSV
        STATEV(I) = SENT
   20 CONTINUE
      END

C     Only the outputs that are not also inputs (before each increment
C     of a history: TAU and STATEV carry the state).
      SUBROUTINE SENTOU(DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,MG)
      INCLUDE 'ABA_PARAM.INC'
      PARAMETER (SENT=-999.25D0, BIG=1.0D36)
      DIMENSION DDTDDG(MG),DDTDDP(MG),DSLIP(MG),DDTDDT(MG)
      DO 10 I = 1, MG
        DDTDDG(I) = SENT
        DDTDDP(I) = SENT
        DSLIP(I) = SENT
        DDTDDT(I) = SENT
   10 CONTINUE
      SED = SENT
      SFD = SENT
      PNEWDT = BIG
      END

C-----------------------------------------------------------------------
C     The host arguments the Coulomb law does not use, filled as a host
C     would (HOSTAT at time 0 and 20 degrees, Delta t = 0.1, identity
C     DROT, point 1, element 0, SLIP(1..MG) = 0), and the names:
C     interaction NAME between surfaces 'SLAVE' and 'MASTER'.
C-----------------------------------------------------------------------
      SUBROUTINE HOSTIN(KSTEP,KINC,TIME,DTIME,NOEL,NPT,NODE,NPATCH,
     1 COORDS,RCOORD,DROT,TEMP,PREDEF,MCRD,NPRED,DDPDDH,SLIP,MG,
     2 CINAME,SLNAME,MSNAME,NAME)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*(*) CINAME,SLNAME,MSNAME,NAME
      DIMENSION TIME(2),COORDS(3),RCOORD(3),DROT(2,2),TEMP(2),
     1 PREDEF(2,1),SLIP(MG)
      CINAME = NAME
      SLNAME = 'SLAVE'
      MSNAME = 'MASTER'
      CALL HOSTAT(0.0D0, 20.0D0, 20.0D0, TIME, TEMP, PREDEF, COORDS,
     1 KSTEP, KINC, NODE, NPRED)
      DTIME = 0.1D0
      NOEL = 0
      NPT = 1
      NPATCH = 1
      MCRD = 3
      DDPDDH = 1.0D6
      DO 10 I = 1, 3
        RCOORD(I) = 0.0D0
   10 CONTINUE
C     DROT the identity: the local directions are not rotated.
      DO 30 J = 1, 2
        DO 20 I = 1, 2
          DROT(I,J) = 0.0D0
   20   CONTINUE
        DROT(J,J) = 1.0D0
   30 CONTINUE
      DO 40 I = 1, MG
        SLIP(I) = 0.0D0
   40 CONTINUE
      END

C-----------------------------------------------------------------------
C     The host point of fric_host.inc (COMMON /FHOST/, /FHOSTN/): HOSTIN
C     for interaction NAME (HOSTPT); that and the Coulomb point of scene
C     F1 (F1HOST); FRIC called there as Abaqus calls it, a plain CALL
C     with the 39 arguments (FRICH).
C-----------------------------------------------------------------------
      SUBROUTINE HOSTPT(NAME)
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
      CHARACTER*(*) NAME
      CALL HOSTIN(KSTEP,KINC,TIME,DTIME,NOEL,NPT,NODE,NPATCH,COORDS,
     1 RCOORD,DROT,TEMP,PREDEF,MCRD,NPRED,DDPDDH,SLIP,MG,CINAME,SLNAME,
     2 MSNAME,NAME)
      END

      SUBROUTINE F1HOST(NAME)
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
      CHARACTER*(*) NAME
      CALL HOSTPT(NAME)
      CALL F1PT(PROPS, NPROPS, CHRLNGTH, NSTATV, PRESS, DPRESS)
      END

      SUBROUTINE FRICH
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
      CALL FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,
     1 STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,KSTEP,KINC,TIME,
     2 DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,NPATCH,COORDS,RCOORD,
     3 DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,NSTATV,CHRLNGTH,PROPS,NPROPS)
      END

C-----------------------------------------------------------------------
C     Where and when a host point is, for FRIC (HOSTIN) and GAPCON
C     (GAPIN) alike: step 1, increment 1 at time T (TIME(1) = TIME(2) =
C     T), surface temperatures TEMP = (TA, TB), one predefined field at
C     0 on both surfaces, node 7 at the origin.
C-----------------------------------------------------------------------
      SUBROUTINE HOSTAT(T, TA, TB, TIME, TEMP, PREDEF, COORDS, KSTEP,
     1 KINC, NODE, NPRED)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION TIME(2),TEMP(2),PREDEF(2,1),COORDS(3)
      KSTEP = 1
      KINC = 1
      TIME(1) = T
      TIME(2) = T
      TEMP(1) = TA
      TEMP(2) = TB
      NPRED = 1
      PREDEF(1,1) = 0.0D0
      PREDEF(2,1) = 0.0D0
      NODE = 7
      DO 10 I = 1, 3
        COORDS(I) = 0.0D0
   10 CONTINUE
      END

C-----------------------------------------------------------------------
C     The Coulomb point the fixed-form FRIC harnesses start from (scene
C     F1): PROPS(1..5) = (1, mu = 0.3, 0, tau_max = 0, gc = 1e-3),
C     NPROPS = 5, CHRLNGTH = 0.2, NSTATV = 3, p = 100, DPRESS = 0.
C-----------------------------------------------------------------------
      SUBROUTINE F1PT(PROPS, NPROPS, CHRLNGTH, NSTATV, PRESS, DPRESS)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION PROPS(5)
      PROPS(1) = 1.0D0
      PROPS(2) = 0.3D0
      PROPS(3) = 0.0D0
      PROPS(4) = 0.0D0
      PROPS(5) = 1.0D-3
      NPROPS = 5
      CHRLNGTH = 0.2D0
      NSTATV = 3
      PRESS = 100.0D0
      DPRESS = 0.0D0
      END

C-----------------------------------------------------------------------
C     A quiet NaN and +Inf made at run time from text, so that neither
C     constant folding nor -fcheck sees them; checked to be what they
C     claim (case 'run-time NaN and Inf', check 0).
C-----------------------------------------------------------------------
      SUBROUTINE NANINF(XNAN, XINF)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*48 CASE
      COMMON /CTX/ CASE
      CHARACTER*8 SNAN,SINF
      CASE = 'run-time NaN and Inf'
      SNAN = 'NaN'
      SINF = 'Inf'
      READ (SNAN,*) XNAN
      READ (SINF,*) XINF
      CALL CHECK(XNAN .NE. XNAN, 'NaN from text is a NaN', 0)
      CALL CHECK(XINF .GT. HUGE(XINF), 'Inf from text is +Inf', 0)
      END

C-----------------------------------------------------------------------
C     The calling thread's last error message, through the library's
C     native C API (size_t ifl_last_error_copy(char *buf, size_t len):
C     copies at most len-1 bytes and a NUL, returns the full length).
C     L: the length of the message in MSG.
C-----------------------------------------------------------------------
      SUBROUTINE GETMSG(MSG, L)
      USE, INTRINSIC :: ISO_C_BINDING, ONLY: C_SIZE_T
      CHARACTER*(*) MSG
      INTERFACE
        FUNCTION IFLCPY(BUF, NBUF) BIND(C, NAME='ifl_last_error_copy')
          USE, INTRINSIC :: ISO_C_BINDING, ONLY: C_CHAR, C_SIZE_T
          INTEGER(C_SIZE_T) :: IFLCPY
          CHARACTER(KIND=C_CHAR), DIMENSION(*) :: BUF
          INTEGER(C_SIZE_T), VALUE :: NBUF
        END FUNCTION IFLCPY
      END INTERFACE
      INTEGER(C_SIZE_T) :: NFULL
      MSG = ' '
      NFULL = IFLCPY(MSG, INT(LEN(MSG), C_SIZE_T))
      L = INT(MIN(NFULL, INT(LEN(MSG) - 1, C_SIZE_T)))
      END

C-----------------------------------------------------------------------
C     One GAPCON call as Abaqus makes it, CHARACTER*80 names: AK(1..5)
C     preset to a sentinel, D = (CLR, P), TEMP = (TA, TB), element
C     NOEL, node 7; the arguments GAPCON does not read hold harmless
C     values.  Checks AK(1) written (a failure writes 0), AK(2..5)
C     untouched and the inputs unchanged bit for bit (a NaN input must
C     still be that NaN).  Returns AK(1).
C-----------------------------------------------------------------------
      SUBROUTINE GAPONE(NAME, CLR, P, TA, TB, NOEL, AK1)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*(*) NAME
      CHARACTER*80 CINAME,SLNAME,MSNAME
      PARAMETER (SENT=-999.25D0)
      DIMENSION AK(5),D(2),FLOWM(2),TEMP(2),PREDEF(2,1),TIME(2),
     1 COORDS(3)
      LOGICAL SAMEB
      CINAME = NAME
      SLNAME = 'SLAVE'
      MSNAME = 'MASTER'
      CALL GAPIN(AK,D,FLOWM,TEMP,PREDEF,TIME,COORDS,NODE,NPRED,KSTEP,
     1 KINC,CLR,P,TA,TB)
      NOELIN = NOEL
      CALL GAPCON(AK,D,FLOWM,TEMP,PREDEF,TIME,CINAME,SLNAME,MSNAME,
     1 COORDS,NOELIN,NODE,NPRED,KSTEP,KINC)
      AK1 = AK(1)
      CALL GUARD1(AK, 2, 5, 'AK(2..5) untouched', NOEL)
      CALL CHECK(SAMEB(D(1), CLR) .AND. SAMEB(D(2), P) .AND.
     1 SAMEB(TEMP(1), TA) .AND. SAMEB(TEMP(2), TB) .AND.
     2 CINAME .EQ. NAME .AND. NOELIN .EQ. NOEL .AND. NODE .EQ. 7,
     3 'inputs not written', NOEL)
      CALL CHECK(AK1 .NE. SENT, 'AK(1) written', NOEL)
      END

C     The GAPCON arguments before a call: AK(1..5) the sentinel, D =
C     (CLR, P), HOSTAT at time 1 with TEMP = (TA, TB), and harmless
C     zeros in what GAPCON does not read.
      SUBROUTINE GAPIN(AK,D,FLOWM,TEMP,PREDEF,TIME,COORDS,NODE,NPRED,
     1 KSTEP,KINC,CLR,P,TA,TB)
      INCLUDE 'ABA_PARAM.INC'
      PARAMETER (SENT=-999.25D0)
      DIMENSION AK(5),D(2),FLOWM(2),TEMP(2),PREDEF(2,1),TIME(2),
     1 COORDS(3)
      DO 10 I = 1, 5
        AK(I) = SENT
   10 CONTINUE
      D(1) = CLR
      D(2) = P
      FLOWM(1) = 0.0D0
      FLOWM(2) = 0.0D0
      CALL HOSTAT(1.0D0, TA, TB, TIME, TEMP, PREDEF, COORDS, KSTEP,
     1 KINC, NODE, NPRED)
      END

C     A and B the same bit for bit (a NaN equals that same NaN).
      LOGICAL FUNCTION SAMEB(A, B)
      INCLUDE 'ABA_PARAM.INC'
      INTEGER*8 IA, IB
      IA = TRANSFER(A, IA)
      IB = TRANSFER(B, IB)
      SAMEB = IA .EQ. IB
      END

C-----------------------------------------------------------------------
C     SCENE(NDIR, IA, IB) for NDIR = 1 and 2 and each setting of two
C     on/off switches IA and IB (0 or 1: the variants a harness
C     crosses, e.g. exact stick and frozen rate), NDIR outermost, then
C     IA: the twin of fh_each_nfdir_and_switches (c_tests/harness.h).
C-----------------------------------------------------------------------
      SUBROUTINE EACHSW(SCENE)
      EXTERNAL SCENE
      DO 30 NDIR = 1, 2
        DO 20 IA = 0, 1
          DO 10 IB = 0, 1
            CALL SCENE(NDIR, IA, IB)
   10     CONTINUE
   20   CONTINUE
   30 CONTINUE
      END

C-----------------------------------------------------------------------
C     The slip tangent of the host point (fric_host.inc) along the unit
C     direction E (NFDIR entries) against a central difference of
C     FRIC's own TAU: E . DDTDDG . E at the current increment against
C     E . (TAU(DGAM + HG E) - TAU(DGAM - HG E))/(2 HG), HG = 1e-9, to
C     the absolute tolerance ATOL (K: the tally's number); the twin of
C     fh_check_tangent_along (c_tests/harness.h).  Three calls that
C     must succeed, each from the state on entry (LM, TAU, STATEV),
C     which is put back afterwards with DGAM, so the host's history
C     goes on as if they had not been made.
C-----------------------------------------------------------------------
      SUBROUTINE TANGNT(E, ATOL, K)
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_host.inc'
      DIMENSION E(*),TAU0(MG),SV0(MSV),DG0(MG),TPLUS(MG),SGN(3)
      DATA SGN /0.0D0, 1.0D0, -1.0D0/
      HG = 1.0D-9
      LM0 = LM
      CALL COPYV(TAU, TAU0, MG)
      CALL COPYV(DGAM, DG0, MG)
      CALL COPYV(STATEV, SV0, MSV)
      AN = 0.0D0
      FD = 0.0D0
C     Call 1 at DGAM (the tangent), 2 at DGAM + HG E, 3 at DGAM - HG E,
C     each from the state on entry; IC = 4 only puts that state back.
      DO 50 IC = 1, 4
        LM = LM0
        CALL COPYV(TAU0, TAU, MG)
        CALL COPYV(DG0, DGAM, MG)
        CALL COPYV(SV0, STATEV, MSV)
        IF (IC .EQ. 4) GO TO 50
        DO 30 I = 1, NFDIR
          DGAM(I) = DG0(I) + SGN(IC)*HG*E(I)
   30   CONTINUE
        PNEWDT = BIG
        CALL FRICH
        CALL CHECK(PNEWDT .EQ. BIG, 'tangent: PNEWDT not lowered', K)
        DO 40 I = 1, NFDIR
          IF (IC .EQ. 1) THEN
            DO 35 J = 1, NFDIR
              AN = AN + E(I)*DDTDDG(I + (J-1)*NFDIR)*E(J)
   35       CONTINUE
          ELSE IF (IC .EQ. 2) THEN
            TPLUS(I) = TAU(I)
          ELSE
            FD = FD + E(I)*(TPLUS(I) - TAU(I))/(2.0D0*HG)
          END IF
   40   CONTINUE
   50 CONTINUE
      CALL CHKNR(AN, FD, ATOL, 'tangent along the slip = central FD',
     1 K)
      END

C     TO(1..N) = FROM(1..N).
      SUBROUTINE COPYV(FROM, TO, N)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION FROM(N), TO(N)
      DO 10 I = 1, N
        TO(I) = FROM(I)
   10 CONTINUE
      END
