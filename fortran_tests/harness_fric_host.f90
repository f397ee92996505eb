! harness_fric_host.f90 -- the host side of one FRIC contact point, shared by the free-form FRIC
! harnesses (test_fric_scenes.f90, test_fric_table.f90, test_fric_steady.f90,
! test_fric_weakening.f90, test_fric_rate_state.f90): every one of the 39 Abaqus arguments in
! one derived type, output arrays longer than NFDIR and STATEV longer than NSTATV with their
! tails at a sentinel, and the call made as a user's Fortran 90 host makes it (a plain
! `call fric(...)`, no interface block). The twin of the host struct of c_tests/harness.h. Each
! harness keeps its own scenes and checks of the law; it sets the host values it pins (names,
! element, node, coordinates, DTIME) after new_point.

module harness_fric_host
  use harness_tally, only: dp, check
  implicit none
  private
  public :: fric_args, new_point, at_c_twin_point, fric_call, check_tails, sentinel, big, mg, msv
  public :: each_nfdir_and_switches, switch_scene

  real(dp), parameter :: sentinel = -999.25_dp, big = 1.0e36_dp
  integer, parameter :: mg = 8, msv = 8

  type :: fric_args
    integer :: lm = 0
    real(dp) :: tau(mg) = sentinel, ddtddg(mg) = sentinel, ddtddp(mg) = sentinel
    real(dp) :: dslip(mg) = sentinel, sed = sentinel, sfd = sentinel, ddtddt(mg) = sentinel
    real(dp) :: pnewdt = big, statev(msv) = sentinel
    real(dp) :: dgam(mg) = sentinel, taulm(mg) = 0
    real(dp) :: press = 0, dpress = 0, ddpddh = 1.0e6_dp, slip(mg) = 0
    integer :: kstep = 1, kinc = 1
    real(dp) :: time(2) = 0, dtime = 0.1_dp
    integer :: noel = 0
    character(len=80) :: ciname = ' ', slname = 'SLAVE', msname = 'MASTER'
    integer :: npt = 1, node = 7, npatch = 1
    real(dp) :: coords(3) = 0, rcoord(3) = 0
    real(dp) :: drot(2, 2) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
    real(dp) :: temp(2) = 20.0_dp, predef(2, 1) = 0
    integer :: nfdir = 2, mcrd = 3, npred = 1, nstatv = 3
    ! PROPS past NPROPS hold the sentinel: a law that read past NPROPS would be refused.
    real(dp) :: chrlngth = 1.0_dp, props(20) = sentinel
    integer :: nprops = 0
  end type fric_args

  ! A scene crossed by each_nfdir_and_switches: NFDIR and two switches a, b (0 off, 1 on).
  abstract interface
    subroutine switch_scene(nfdir, a, b)
      integer, intent(in) :: nfdir, a, b
    end subroutine switch_scene
  end interface

contains

  ! A point at first contact: TAU, DGAM and STATEV(1..3) = 0 (NSTATV = 3), PROPS(1..size) given
  ! (NPROPS = its size), CHRLNGTH 1 unless given.
  function new_point(nfdir, props, name, chrlngth) result(a)
    integer, intent(in) :: nfdir
    real(dp), intent(in) :: props(:)
    character(len=*), intent(in) :: name
    real(dp), intent(in), optional :: chrlngth
    type(fric_args) :: a
    a%nfdir = nfdir
    a%props(1:size(props)) = props
    a%nprops = size(props)
    if (present(chrlngth)) a%chrlngth = chrlngth
    a%tau(1:nfdir) = 0
    a%dgam(1:nfdir) = 0
    a%statev(1:3) = 0
    a%nstatv = 3
    a%ciname = name
  end function new_point

  ! The host values the C twins pin (fh_init of c_tests/harness.h): element 17, node 42, point 3,
  ! patch 5, surfaces SLAVE_SURF and MASTER_SURF.
  subroutine at_c_twin_point(a)
    type(fric_args), intent(inout) :: a
    a%noel = 17
    a%node = 42
    a%npt = 3
    a%npatch = 5
    a%slname = 'SLAVE_SURF'
    a%msname = 'MASTER_SURF'
  end subroutine at_c_twin_point

  ! One FRIC call as the host makes it: the outputs that are not also inputs preset to the
  ! sentinel (so an entry that should have been written cannot pass by accident), PNEWDT = 1e36
  ! as Abaqus passes it. With keep_outputs, those outputs go in as the caller left them (a call
  ! that writes nothing leaves them so), PNEWDT still 1e36.
  subroutine fric_call(a, keep_outputs)
    type(fric_args), intent(inout) :: a
    logical, intent(in), optional :: keep_outputs
    logical :: preset
    preset = .true.
    if (present(keep_outputs)) preset = .not. keep_outputs
    if (preset) then
      a%ddtddg = sentinel
      a%ddtddp = sentinel
      a%dslip = sentinel
      a%ddtddt = sentinel
      a%sed = sentinel
      a%sfd = sentinel
    end if
    a%pnewdt = big
    call fric(a%lm, a%tau, a%ddtddg, a%ddtddp, a%dslip, a%sed, a%sfd, &
              a%ddtddt, a%pnewdt, a%statev, a%dgam, a%taulm, a%press, a%dpress, a%ddpddh, a%slip, &
              a%kstep, a%kinc, a%time, a%dtime, a%noel, a%ciname, a%slname, a%msname, a%npt, &
              a%node, a%npatch, a%coords, a%rcoord, a%drot, a%temp, a%predef, a%nfdir, a%mcrd, &
              a%npred, a%nstatv, a%chrlngth, a%props, a%nprops)
  end subroutine fric_call

  ! Every output array untouched past NFDIR (NFDIR**2 for DDTDDG, 2 NFDIR for DDTDDT) and STATEV
  ! past NSTATV.
  subroutine check_tails(a)
    type(fric_args), intent(in) :: a
    integer :: n
    n = a%nfdir
    call check(all(a%tau(n + 1:) == sentinel), 'TAU past NFDIR untouched')
    call check(all(a%ddtddg(n*n + 1:) == sentinel), 'DDTDDG past NFDIR**2 untouched')
    call check(all(a%ddtddp(n + 1:) == sentinel), 'DDTDDP past NFDIR untouched')
    call check(all(a%dslip(n + 1:) == sentinel), 'DSLIP past NFDIR untouched')
    call check(all(a%ddtddt(2*n + 1:) == sentinel), 'DDTDDT past 2 NFDIR untouched')
    call check(all(a%statev(a%nstatv + 1:) == sentinel), 'STATEV past NSTATV untouched')
  end subroutine check_tails

  ! scene(nfdir, a, b) for NFDIR = 1 and 2 and each setting of two on/off switches a and b (the
  ! variants a harness crosses, e.g. exact stick and frozen rate), NFDIR outermost, then a: the
  ! twin of fh_each_nfdir_and_switches (c_tests/harness.h).
  subroutine each_nfdir_and_switches(scene)
    procedure(switch_scene) :: scene
    integer :: nfdir, a, b
    do nfdir = 1, 2
      do a = 0, 1
        do b = 0, 1
          call scene(nfdir, a, b)
        end do
      end do
    end do
  end subroutine each_nfdir_and_switches
end module harness_fric_host
