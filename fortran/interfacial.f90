! The Fortran 2008 module of libinterfacial: `use interfacial`.
!
! - bind(C) interfaces for every ifl_* function of include/interfacial.h, with iso_c_binding
!   kinds (tests/fortran_module.rs fails when the header has a function this file lacks);
! - explicit interfaces for the Abaqus entry points FRIC, GAPCON (Abaqus's argument list),
!   FRIC_COEF, UINTER and VFRIC (double precision), so the compiler checks a caller's argument
!   types: INTEGER is integer(c_int), so a caller built with -fdefault-integer-8 that uses this
!   module gets a compile-time type mismatch instead of corrupted integers;
! - Fortran wrappers that take character(*) names (no NUL needed) and return text as
!   character(:), allocatable: ifl_gap_conductance(name, ...), ifl_pore_pressure(name, ...),
!   ifl_last_error_message(), ifl_version_string(), ifl_props_check_text(props, nprops, name,
!   message), and ifl_c_string(p) for the C texts of an ifl_props_entry.
!
! Installed as interfacial.mod (for the gfortran that built it) next to interfacial.h, and as
! this source in share/interfacial/fortran/ for other compilers: compile it with yours and link
! the object with libinterfacial. docs/install.md has the details.
module interfacial
  use, intrinsic :: iso_c_binding, only: c_char, c_double, c_int, c_null_ptr, &
    c_ptr, c_size_t, c_associated, c_f_pointer, c_loc, c_null_char, c_funptr
  implicit none
  private

  ! enum IflStatus (stable numbers)
  integer(c_int), parameter, public :: IFL_STATUS_OK = 0
  integer(c_int), parameter, public :: IFL_STATUS_BAD_PARAMETER = 1
  integer(c_int), parameter, public :: IFL_STATUS_BAD_INPUT = 2
  integer(c_int), parameter, public :: IFL_STATUS_NUMERICAL_FAILURE = 3
  integer(c_int), parameter, public :: IFL_STATUS_INTERNAL_ERROR = 4

  ! struct IflConductance: gap conductance k and its derivatives; q = k*(theta_a - theta_b).
  type, bind(C), public :: ifl_conductance
    real(c_double) :: k = 0
    real(c_double) :: dk_dd = 0
    real(c_double) :: dk_dp = 0
    real(c_double) :: dk_dtheta_mean = 0
    real(c_double) :: dq_dtheta_a = 0
    real(c_double) :: dq_dtheta_b = 0
  end type ifl_conductance

  ! struct IflPorePressureVariant: one flag per choice, each 0 or 1 (docs/pore-pressure.md).
  ! The default, all zeros, is closed contact, transient, small sliding, unknowns
  ! (h, p_mean, p_jump, q_hat); e.g. ifl_pore_pressure_variant(steady=1, per_side=1).
  type, bind(C), public :: ifl_pore_pressure_variant
    integer(c_int) :: open = 0
    integer(c_int) :: steady = 0
    integer(c_int) :: finite_sliding = 0
    integer(c_int) :: per_side = 0
  end type ifl_pore_pressure_variant

  ! struct IflPropsEntry: one row of a law's PROPS table (docs/props.md); the texts are C
  ! pointers to static NUL-terminated UTF-8 (ifl_c_string(p) gives them as Fortran text).
  type, bind(C), public :: ifl_props_entry
    integer(c_int) :: index = 0
    type(c_ptr) :: key = c_null_ptr
    integer(c_int) :: seed_name = 0
    type(c_ptr) :: symbol = c_null_ptr
    type(c_ptr) :: unit = c_null_ptr
    type(c_ptr) :: meaning = c_null_ptr
    type(c_ptr) :: default_text = c_null_ptr
    real(c_double) :: default_value = 0
    integer(c_int) :: required = 0
    type(c_ptr) :: valid = c_null_ptr
    type(c_ptr) :: when = c_null_ptr
  end type ifl_props_entry

  public :: ifl_props_law_count, ifl_props_law_code, ifl_props_entry_count, ifl_props_entry_c, &
    ifl_props_check
  public :: ifl_props_check_text, ifl_c_string

  ! struct IflFricInput / IflFricOutput: one FRIC point by FRIC's argument names (docs/c-api.md).
  ! Arrays sized for NFDIR = 2, column-major; interaction is c_loc of a NUL-terminated name or
  ! c_null_ptr, props and statev c_loc of the arrays (statev written on success).
  type, bind(C), public :: ifl_fric_input
    integer(c_int) :: lm = 0
    integer(c_int) :: nfdir = 2
    real(c_double) :: tau(2) = 0
    real(c_double) :: dgam(2) = 0
    real(c_double) :: taulm(2) = 0
    real(c_double) :: press = 0
    real(c_double) :: dpress = 0
    real(c_double) :: dtime = 1
    real(c_double) :: chrlngth = 1
    real(c_double) :: temp(2) = 0
    real(c_double) :: drot(4) = [1.0_c_double, 0.0_c_double, 0.0_c_double, 1.0_c_double]
    real(c_double) :: coords(3) = 0
    integer(c_int) :: mcrd = 3
    integer(c_int) :: noel = 0
    integer(c_int) :: npt = 0
    integer(c_int) :: node = 0
    type(c_ptr) :: interaction = c_null_ptr
    type(c_ptr) :: props = c_null_ptr
    integer(c_int) :: nprops = 0
    type(c_ptr) :: statev = c_null_ptr
    integer(c_int) :: nstatv = 0
    real(c_double) :: pnewdt = 1.0e36_c_double
  end type ifl_fric_input

  type, bind(C), public :: ifl_fric_output
    integer(c_int) :: lm = 0
    real(c_double) :: tau(2) = 0
    real(c_double) :: ddtddg(4) = 0
    real(c_double) :: ddtddp(2) = 0
    real(c_double) :: dslip(2) = 0
    real(c_double) :: sed = 0
    real(c_double) :: sfd = 0
    real(c_double) :: ddtddt(4) = 0
    real(c_double) :: pnewdt = 0
  end type ifl_fric_output

  public :: ifl_fric_point, ifl_set_message_handler
  public :: ifl_fric_batch, ifl_forced_sliding, ifl_version, ifl_last_error, &
    ifl_last_error_copy, ifl_clear_error, ifl_gap_conductance_c, ifl_gap_conductance_n, &
    ifl_pore_pressure_c, ifl_pore_pressure_n
  public :: ifl_gap_conductance, ifl_pore_pressure, ifl_last_error_message, ifl_version_string
  public :: fric, gapcon, fric_coef, uinter, vfric

  ! ---- the native C API (include/interfacial.h) --------------------------------------------
  interface
    function ifl_fric_batch(npoints, ld, nfdir, props, nprops, nstatv, dtime, lm, tau, &
        ddtddg, ddtddp, dslip, sed, sfd, statev, dgam, taulm, press, dpress, chrlngth, &
        pnewdt) result(status) bind(C, name='ifl_fric_batch')
      import :: c_int, c_double, c_size_t
      integer(c_size_t), value :: npoints, ld
      integer(c_int), value :: nfdir, nprops, nstatv
      real(c_double), value :: dtime
      real(c_double), intent(in) :: props(*), dgam(*), taulm(*), press(*), dpress(*), &
        chrlngth(*)
      integer(c_int), intent(inout) :: lm(*)
      real(c_double), intent(inout) :: tau(*), ddtddg(*), ddtddp(*), dslip(*), sed(*), &
        sfd(*), statev(*), pnewdt
      integer(c_int) :: status
    end function ifl_fric_batch

    function ifl_forced_sliding(props, nprops, nfdir, velocity, pressure, temperature, tau, &
        damping, stiffness) result(status) bind(C, name='ifl_forced_sliding')
      import :: c_int, c_double
      real(c_double), intent(in) :: props(*), velocity(*)
      integer(c_int), value :: nprops, nfdir
      real(c_double), value :: pressure, temperature
      real(c_double), intent(out) :: tau(*), damping(*), stiffness(*)
      integer(c_int) :: status
    end function ifl_forced_sliding

    ! NUL-terminated, static storage; ifl_version_string() gives it as Fortran text.
    function ifl_version() result(p) bind(C, name='ifl_version')
      import :: c_ptr
      type(c_ptr) :: p
    end function ifl_version

    ! NUL-terminated, valid until the next call on this thread; ifl_last_error_message() copies.
    function ifl_last_error() result(p) bind(C, name='ifl_last_error')
      import :: c_ptr
      type(c_ptr) :: p
    end function ifl_last_error

    ! buf: c_loc of len writable characters, or c_null_ptr to ask for the length only.
    function ifl_last_error_copy(buf, len) result(n) bind(C, name='ifl_last_error_copy')
      import :: c_ptr, c_size_t
      type(c_ptr), value :: buf
      integer(c_size_t), value :: len
      integer(c_size_t) :: n
    end function ifl_last_error_copy

    subroutine ifl_clear_error() bind(C, name='ifl_clear_error')
    end subroutine ifl_clear_error

    ! The C function with a NUL-terminated name ('SI1'//c_null_char); Fortran callers use the
    ! generic ifl_gap_conductance(name, ...) below instead.
    function ifl_gap_conductance_c(interaction, d, p, theta_a, theta_b, out) result(status) &
        bind(C, name='ifl_gap_conductance')
      import :: c_char, c_double, c_int, ifl_conductance
      character(kind=c_char), intent(in) :: interaction(*)
      real(c_double), value :: d, p, theta_a, theta_b
      type(ifl_conductance), intent(out) :: out
      integer(c_int) :: status
    end function ifl_gap_conductance_c

    function ifl_gap_conductance_n(interaction, interaction_len, d, p, theta_a, theta_b, out) &
        result(status) bind(C, name='ifl_gap_conductance_n')
      import :: c_char, c_double, c_int, c_size_t, ifl_conductance
      character(kind=c_char), intent(in) :: interaction(*)
      integer(c_size_t), value :: interaction_len
      real(c_double), value :: d, p, theta_a, theta_b
      type(ifl_conductance), intent(out) :: out
      integer(c_int) :: status
    end function ifl_gap_conductance_n

    ! The interface pore-pressure kernel (seed 000) with a NUL-terminated name; Fortran callers
    ! use the generic ifl_pore_pressure(name, ...) below instead. tangent is TANGENT(4,4).
    function ifl_pore_pressure_c(interaction, variant, p1, p2, q_hat, h, dh, dt, residual, &
        tangent, geometric) result(status) bind(C, name='ifl_pore_pressure')
      import :: c_char, c_double, c_int, ifl_pore_pressure_variant
      character(kind=c_char), intent(in) :: interaction(*)
      type(ifl_pore_pressure_variant), value :: variant
      real(c_double), value :: p1, p2, q_hat, h, dh, dt
      real(c_double), intent(out) :: residual(4), tangent(4, 4), geometric(4)
      integer(c_int) :: status
    end function ifl_pore_pressure_c

    function ifl_pore_pressure_n(interaction, interaction_len, variant, p1, p2, q_hat, h, dh, &
        dt, residual, tangent, geometric) result(status) bind(C, name='ifl_pore_pressure_n')
      import :: c_char, c_double, c_int, c_size_t, ifl_pore_pressure_variant
      character(kind=c_char), intent(in) :: interaction(*)
      integer(c_size_t), value :: interaction_len
      type(ifl_pore_pressure_variant), value :: variant
      real(c_double), value :: p1, p2, q_hat, h, dh, dt
      real(c_double), intent(out) :: residual(4), tangent(4, 4), geometric(4)
      integer(c_int) :: status
    end function ifl_pore_pressure_n

    ! The PROPS layouts (docs/c-api.md): laws, rows of a law's table, a check without an
    ! increment. law is the code PROPS(1); i counts from 0.
    function ifl_props_law_count() result(n) bind(C, name='ifl_props_law_count')
      import :: c_int
      integer(c_int) :: n
    end function ifl_props_law_count

    function ifl_props_law_code(i) result(code) bind(C, name='ifl_props_law_code')
      import :: c_int
      integer(c_int), value :: i
      integer(c_int) :: code
    end function ifl_props_law_code

    function ifl_props_entry_count(law) result(n) bind(C, name='ifl_props_entry_count')
      import :: c_int
      integer(c_int), value :: law
      integer(c_int) :: n
    end function ifl_props_entry_count

    ! ifl_props_entry in C (a Fortran name would clash with the type ifl_props_entry).
    function ifl_props_entry_c(law, i, out) result(status) bind(C, name='ifl_props_entry')
      import :: c_int, ifl_props_entry
      integer(c_int), value :: law, i
      type(ifl_props_entry), intent(inout) :: out
      integer(c_int) :: status
    end function ifl_props_entry_c

    ! interaction: c_loc of a NUL-terminated name or c_null_ptr; message: c_loc of capacity
    ! writable characters or c_null_ptr. ifl_props_check_text below does all of that.
    function ifl_props_check(props, nprops, interaction, message, capacity, message_len) &
        result(status) bind(C, name='ifl_props_check')
      import :: c_double, c_int, c_ptr, c_size_t
      real(c_double), intent(in) :: props(*)
      integer(c_int), value :: nprops
      type(c_ptr), value :: interaction, message
      integer(c_size_t), value :: capacity
      integer(c_size_t), intent(out) :: message_len
      integer(c_int) :: status
    end function ifl_props_check

    ! One FRIC point with named inputs and outputs: fric_ itself, bit for bit.
    function ifl_fric_point(input, output) result(status) bind(C, name='ifl_fric_point')
      import :: c_int, ifl_fric_input, ifl_fric_output
      ! No intent(in): the callee writes STATEV through input%statev (with intent(in) gfortran may
      ! take what the struct points to as unchanged by the call).
      type(ifl_fric_input) :: input
      type(ifl_fric_output), intent(out) :: output
      integer(c_int) :: status
    end function ifl_fric_point

    ! handler: c_funloc of a bind(C) subroutine (msg, len, user) with msg type(c_ptr), value
    ! (NUL-terminated), len integer(c_size_t), value, user type(c_ptr), value; or c_null_funptr
    ! to send messages to stderr (or INTERFACIAL_LOG) again.
    subroutine ifl_set_message_handler(handler, user) bind(C, name='ifl_set_message_handler')
      import :: c_funptr, c_ptr
      type(c_funptr), value :: handler
      type(c_ptr), value :: user
    end subroutine ifl_set_message_handler
  end interface

  ! The thermal law of an interaction by its Fortran name (blank-padded, no NUL).
  interface ifl_gap_conductance
    module procedure ifl_gap_conductance_chars
  end interface ifl_gap_conductance

  ! The interface pore-pressure kernel with a Fortran name (blank-padded, no NUL).
  interface ifl_pore_pressure
    module procedure ifl_pore_pressure_chars
  end interface ifl_pore_pressure

  interface
    function c_strlen(s) result(n) bind(C, name='strlen')
      import :: c_ptr, c_size_t
      type(c_ptr), value :: s
      integer(c_size_t) :: n
    end function c_strlen
  end interface

  ! ---- the Abaqus entry points (external procedures of libinterfacial) -----------------------
  ! Argument lists as Abaqus declares them (docs/fric.md, docs/gapcon.md, docs/uinter.md,
  ! docs/vfric.md); arrays assumed-size, so any rank and shape a host uses is accepted.
  interface
    subroutine fric(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, &
        taulm, press, dpress, ddpddh, slip, kstep, kinc, time, dtime, noel, ciname, slname, &
        msname, npt, node, npatch, coords, rcoord, drot, temp, predef, nfdir, mcrd, npred, &
        nstatv, chrlngth, props, nprops)
      import :: c_int, c_double
      integer(c_int) :: lm, kstep, kinc, noel, npt, node, npatch, nfdir, mcrd, npred, nstatv, &
        nprops
      real(c_double) :: tau(*), ddtddg(*), ddtddp(*), dslip(*), ddtddt(*), statev(*), &
        dgam(*), taulm(*), slip(*), time(*), coords(*), rcoord(*), drot(*), temp(*), &
        predef(*), props(*)
      real(c_double) :: sed, sfd, pnewdt, press, dpress, ddpddh, dtime, chrlngth
      character(len=*) :: ciname, slname, msname
    end subroutine fric

    ! Abaqus's GAPCON. CalculiX's has one more argument (AREA after KINC) and lives in
    ! libinterfacial_calculix: call it through your own interface block.
    subroutine gapcon(ak, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, &
        node, npred, kstep, kinc)
      import :: c_int, c_double
      real(c_double) :: ak(*), d(*), flowm(*), temp(*), predef(*), time(*), coords(*)
      character(len=*) :: ciname, slname, msname
      integer(c_int) :: noel, node, npred, kstep, kinc
    end subroutine gapcon

    subroutine fric_coef(fcoef, fcoefderiv, nblock, nprops, ntemp, nfields, idata, rdata, &
        surfint, surfsec, surfmain, props, slipdata, pressure, tempavg, fieldavg)
      import :: c_int, c_double
      real(c_double) :: fcoef(*), fcoefderiv(*), rdata(*), props(*), slipdata(*), &
        pressure(*), tempavg(*), fieldavg(*)
      integer(c_int) :: nblock, nprops, ntemp, nfields, idata(*)
      character(len=*) :: surfint, surfsec, surfmain
    end subroutine fric_coef

    subroutine uinter(stress, ddsddr, dviscous, dstructural, flux, ddfddt, ddsddt, ddfddr, &
        statev, sed, sfd, spd, svd, scd, pnewdt, rdisp, drdisp, temp, dtemp, predef, dpred, &
        time, dtime, freqr, ciname, slname, msname, props, coords, alocaldir, drot, area, &
        chrlngth, node, ndir, nstatv, npred, nprops, mcrd, kstep, kinc, kit, linper, &
        lopenclose, lstate, lsdi, lprint)
      import :: c_int, c_double
      real(c_double) :: stress(*), ddsddr(*), dviscous(*), dstructural(*), flux(*), &
        ddfddt(*), ddsddt(*), ddfddr(*), statev(*), rdisp(*), drdisp(*), temp(*), dtemp(*), &
        predef(*), dpred(*), time(*), props(*), coords(*), alocaldir(*), drot(*)
      real(c_double) :: sed, sfd, spd, svd, scd, pnewdt, dtime, freqr, area, chrlngth
      character(len=*) :: ciname, slname, msname
      integer(c_int) :: node, ndir, nstatv, npred, nprops, mcrd, kstep, kinc, kit, linper, &
        lopenclose, lstate, lsdi, lprint
    end subroutine uinter

    ! Double precision (the default build; the explicit-single build takes real(c_float)).
    subroutine vfric(ftangential, statev, kstep, kinc, ncontact, nfacnod, nslvnod, nmstnod, &
        nfricdir, ndir, nstatevar, nprops, ntemp, npred, numdeftfv, jslvuid, jmstuid, &
        jconslvid, jconmstid, timstep, timglb, dtimcur, surfint, surfslv, surfmst, lconttype, &
        dslipfric, fstickforce, ftangprev, fnormal, frictionwork, shape, coordslv, coordmst, &
        dircossl, dircosn, props, areaslv, tempslv, predefslv, tempmst, predefmst)
      import :: c_int, c_double
      real(c_double) :: ftangential(*), statev(*), dslipfric(*), fstickforce(*), &
        ftangprev(*), fnormal(*), frictionwork(*), shape(*), coordslv(*), coordmst(*), &
        dircossl(*), dircosn(*), props(*), areaslv(*), tempslv(*), predefslv(*), tempmst(*), &
        predefmst(*)
      real(c_double) :: timstep, timglb, dtimcur
      integer(c_int) :: kstep, kinc, ncontact, nfacnod, nslvnod, nmstnod, nfricdir, ndir, &
        nstatevar, nprops, ntemp, npred, numdeftfv, lconttype
      integer(c_int) :: jslvuid(*), jmstuid(*), jconslvid(*), jconmstid(*)
      character(len=*) :: surfint, surfslv, surfmst
    end subroutine vfric
  end interface

contains

  !> ifl_gap_conductance(name, d, p, theta_a, theta_b, out): the thermal law of interaction
  !> `name` (trailing blanks ignored, no NUL needed) at clearance d, pressure p and surface
  !> temperatures theta_a, theta_b. Returns an IFL_STATUS_* value; out is all zeros on failure.
  function ifl_gap_conductance_chars(interaction, d, p, theta_a, theta_b, out) result(status)
    character(len=*), intent(in) :: interaction
    real(c_double), intent(in) :: d, p, theta_a, theta_b
    type(ifl_conductance), intent(out) :: out
    integer(c_int) :: status
    character(kind=c_char, len=max(1, len(interaction))) :: name
    name = interaction
    status = ifl_gap_conductance_n(name, int(len(interaction), c_size_t), d, p, theta_a, &
      theta_b, out)
  end function ifl_gap_conductance_chars

  !> ifl_pore_pressure(name, variant, p1, p2, q_hat, h, dh, dt, residual, tangent, geometric):
  !> the interface pore-pressure terms of one point (docs/pore-pressure.md); `name` (trailing
  !> blanks ignored, no NUL needed) only labels error messages. Returns an IFL_STATUS_* value;
  !> the outputs are all zeros on failure.
  function ifl_pore_pressure_chars(interaction, variant, p1, p2, q_hat, h, dh, dt, residual, &
      tangent, geometric) result(status)
    character(len=*), intent(in) :: interaction
    type(ifl_pore_pressure_variant), intent(in) :: variant
    real(c_double), intent(in) :: p1, p2, q_hat, h, dh, dt
    real(c_double), intent(out) :: residual(4), tangent(4, 4), geometric(4)
    integer(c_int) :: status
    character(kind=c_char, len=max(1, len(interaction))) :: name
    name = interaction
    status = ifl_pore_pressure_n(name, int(len(interaction), c_size_t), variant, p1, p2, q_hat, &
      h, dh, dt, residual, tangent, geometric)
  end function ifl_pore_pressure_chars

  !> The calling thread's last error message, '' when there is none (or since ifl_clear_error).
  function ifl_last_error_message() result(text)
    character(len=:), allocatable :: text
    character(kind=c_char), allocatable, target :: buf(:)
    integer(c_size_t) :: n, got
    integer :: i
    n = ifl_last_error_copy(c_null_ptr, 0_c_size_t)
    allocate (buf(n + 1))
    got = ifl_last_error_copy(c_loc(buf), n + 1)
    n = min(n, got)
    allocate (character(len=n) :: text)
    do i = 1, int(n)
      text(i:i) = buf(i)
    end do
  end function ifl_last_error_message

  !> ifl_props_check_text(props, nprops, name, message): checks PROPS(1:nprops) as FRIC reads
  !> it for interaction `name` (trailing blanks ignored); returns an IFL_STATUS_* value and, in
  !> message, '' or the cause FRIC would report, word for word.
  function ifl_props_check_text(props, nprops, interaction, message) result(status)
    real(c_double), intent(in) :: props(*)
    integer(c_int), intent(in) :: nprops
    character(len=*), intent(in) :: interaction
    character(len=:), allocatable, intent(out) :: message
    integer(c_int) :: status
    character(kind=c_char), target :: name(len_trim(interaction) + 1)
    character(kind=c_char), allocatable, target :: buf(:)
    integer(c_size_t) :: n, got
    integer :: i
    n = 0
    do i = 1, len_trim(interaction)
      name(i) = interaction(i:i)
    end do
    name(size(name)) = c_null_char
    status = ifl_props_check(props, nprops, c_loc(name), c_null_ptr, 0_c_size_t, n)
    allocate (buf(n + 1))
    status = ifl_props_check(props, nprops, c_loc(name), c_loc(buf), n + 1, got)
    allocate (character(len=n) :: message)
    do i = 1, int(n)
      message(i:i) = buf(i)
    end do
  end function ifl_props_check_text

  !> A NUL-terminated C text (an ifl_props_entry's fields) as Fortran text; '' for NULL.
  function ifl_c_string(p) result(text)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: text
    text = from_c(p)
  end function ifl_c_string

  !> The library version, e.g. '0.1.0' ('0.1.0+calculix' for the CalculiX variant).
  function ifl_version_string() result(text)
    character(len=:), allocatable :: text
    text = from_c(ifl_version())
  end function ifl_version_string

  function from_c(p) result(text)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: text
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n
    if (.not. c_associated(p)) then
      text = ''
      return
    end if
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    allocate (character(len=n) :: text)
    do i = 1, n
      text(i:i) = chars(i)
    end do
  end function from_c
end module interfacial
