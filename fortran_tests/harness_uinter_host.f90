! harness_uinter_host.f90 -- the host side of one UINTER contact point, shared by the free-form
! UINTER harnesses (test_uinter_adhesive.f90, test_uinter_heat.f90, test_fric_weakening.f90):
! every one of the 47 Abaqus arguments in one derived type (NDIR <= 3, STRESS and STATEV longer
! than NDIR / NSTATV with their tails at a guard) and the call made as a user's Fortran 90 host
! makes it (a plain `call uinter(...)`, no interface block). The twin of c_tests/uinter_harness.h.
! Each harness keeps its own scenes and checks of the law; it sets the host values it pins
! (DTIME, node, RDISP, DRDISP, TEMP ...) after new_uinter.

module harness_uinter_host
  use harness_tally, only: dp, check
  implicit none
  private
  public :: uinter_args, new_uinter, uinter_call, check_uinter_tails

  real(dp), parameter :: guard = -999.25_dp, big = 1.0e36_dp

  ! DDSDDR(NDIR,NDIR), DDSDDT(NDIR,2) and DDFDDR(2,NDIR) are read by the law at their NDIR
  ! leading dimension: index them flat, (i, j) -> i + (j - 1) NDIR.
  type :: uinter_args
    real(dp) :: stress(4) = 0, ddsddr(10) = 0, dvisc(9) = 0, dstruct(9) = 0, flux(2) = 0
    real(dp) :: ddfddt(2, 2) = 0, ddsddt(6) = 0, ddfddr(6) = 0, statev(6) = guard
    real(dp) :: sed = 0, sfd = 0, spd = 0, svd = 0, scd = 0, pnewdt = big
    real(dp) :: rdisp(3) = 0, drdisp(3) = 0, temp(2) = 20, dtemp(2) = 0, predef(2, 1) = 0
    real(dp) :: dpred(2, 1) = 0, time(2) = 0, dtime = 1, freqr = 0
    character(len=80) :: ciname = ' ', slname = 'SLAVE', msname = 'MASTER'
    real(dp) :: props(13) = 0, coords(3) = 0, alocaldir(3, 3) = 0, drot(2, 2) = 0, area = 1
    real(dp) :: chrlngth = 1
    integer :: node = 7, ndir = 2, nstatv = 3, npred = 1, nprops = 0, mcrd = 3, kstep = 1
    integer :: kinc = 1, kit = 1, linper = 0, lopenclose = -1, lstate = -1, lsdi = 0, lprint = 0
  end type uinter_args

contains

  ! A fresh point: no stress, STATEV(1..3) = 0 (NSTATV = 3), PROPS(1..size) given (NPROPS =
  ! its size), LOPENCLOSE = LSTATE = -1 (first call).
  function new_uinter(ndir, props, name) result(u)
    integer, intent(in) :: ndir
    real(dp), intent(in) :: props(:)
    character(len=*), intent(in) :: name
    type(uinter_args) :: u
    u%ndir = ndir
    u%props(1:size(props)) = props
    u%nprops = size(props)
    u%statev(1:3) = 0
    u%ciname = name
  end function new_uinter

  ! One UINTER call as the host makes it: STRESS past NDIR preset to the guard, PNEWDT = 1e36
  ! as Abaqus passes it.
  subroutine uinter_call(u)
    type(uinter_args), intent(inout) :: u
    u%stress(u%ndir + 1:) = guard
    u%pnewdt = big
    call uinter(u%stress, u%ddsddr, u%dvisc, u%dstruct, u%flux, u%ddfddt, u%ddsddt, u%ddfddr, &
                u%statev, u%sed, u%sfd, u%spd, u%svd, u%scd, u%pnewdt, u%rdisp, u%drdisp, &
                u%temp, u%dtemp, u%predef, u%dpred, u%time, u%dtime, u%freqr, u%ciname, &
                u%slname, u%msname, u%props, u%coords, u%alocaldir, u%drot, u%area, &
                u%chrlngth, u%node, u%ndir, u%nstatv, u%npred, u%nprops, u%mcrd, u%kstep, &
                u%kinc, u%kit, u%linper, u%lopenclose, u%lstate, u%lsdi, u%lprint)
  end subroutine uinter_call

  ! STRESS past NDIR and STATEV past NSTATV untouched.
  subroutine check_uinter_tails(u)
    type(uinter_args), intent(in) :: u
    call check(all(u%stress(u%ndir + 1:) == guard), 'STRESS past NDIR untouched')
    call check(all(u%statev(u%nstatv + 1:) == guard), 'STATEV past NSTATV untouched')
  end subroutine check_uinter_tails
end module harness_uinter_host
