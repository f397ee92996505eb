! A Fortran 2008 host of the installed package: `use interfacial`, nothing hand-declared.
! Closed forms as in ../common/checks.h: friction mu = 0.3, gamma_crit = 1e-3, p = 100 ->
! stick tau = 3e4 * 5e-4 = 15, slip tau = mu p = 30; interaction SI1 has k = 2.
! The expected version is the first command-line argument.
program fortran2008_host
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  use interfacial
  implicit none
  integer :: npass = 0, nfail = 0
  type(ifl_conductance) :: out
  integer(c_int) :: status
  character(len=32) :: expected
  character(len=80) :: name

  call get_command_argument(1, expected)
  call check(ifl_version_string() == trim(expected), 'ifl_version_string() = '//trim(expected))
  call check(abs(increment(5.0e-4_c_double) - 15) < 1e-12_c_double, 'stick: tau = 15')
  call check(abs(increment(5.0e-3_c_double) - 30) < 1e-12_c_double, 'slip: tau = mu p = 30')

  ! A CHARACTER*80 name, blank-padded, no NUL: the generic ifl_gap_conductance takes it as is.
  name = 'SI1'
  status = ifl_gap_conductance(name, 0.0_c_double, 1.0_c_double, 300.0_c_double, &
    290.0_c_double, out)
  call check(status == IFL_STATUS_OK .and. out%k == 2, 'ifl_gap_conductance(name): k = 2')
  status = ifl_gap_conductance('NOPE', 0.0_c_double, 1.0_c_double, 300.0_c_double, &
    290.0_c_double, out)
  call check(status == IFL_STATUS_BAD_PARAMETER .and. out%k == 0, 'NOPE is refused')
  call check(index(ifl_last_error_message(), "interaction 'NOPE'") > 0, &
    'ifl_last_error_message() names it: '//ifl_last_error_message())
  call ifl_clear_error()
  call check(len(ifl_last_error_message()) == 0, 'ifl_clear_error empties it')

  write (*, '(i0,a,i0,a)') npass, ' passed, ', nfail, ' failed'
  if (nfail > 0) error stop 1

contains

  ! One FRIC increment from tau = 0 at p = 100 (held), through the module's explicit interface.
  function increment(dgam_in) result(tau_out)
    real(c_double), intent(in) :: dgam_in
    real(c_double) :: tau_out
    integer(c_int) :: lm, nfdir, nstatv, nprops, one, zero, two
    real(c_double) :: tau(1), ddtddg(1), ddtddp(1), dslip(1), ddtddt(2), statev(3), dgam(1)
    real(c_double) :: taulm(1), slip(1), time(2), coords(2), drot(4), temp(2), predef(2)
    real(c_double) :: props(5), sed, sfd, pnewdt, press, dpress, ddpddh, dtime, chrlngth
    lm = 0; nfdir = 1; nstatv = 3; nprops = 5; one = 1; zero = 0; two = 2
    tau = 0; statev = 0; dgam = dgam_in; taulm = 0; slip = 0; time = 0; coords = 0
    drot = [1, 0, 0, 1]; temp = 20; predef = 0; props = [1.0_c_double, 0.3_c_double, 0.0_c_double, &
      0.0_c_double, 1.0e-3_c_double]
    pnewdt = 1e36_c_double; press = 100; dpress = 0; ddpddh = 0; dtime = 1; chrlngth = 1
    call fric(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, taulm, &
      press, dpress, ddpddh, slip, one, one, time, dtime, zero, 'SI1', 'SLAVE', 'MASTER', one, &
      one, one, coords, coords, drot, temp, predef, nfdir, two, zero, nstatv, chrlngth, props, &
      nprops)
    call check(pnewdt == 1e36_c_double, 'FRIC accepted the increment')
    tau_out = tau(1)
  end function increment

  subroutine check(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    if (ok) then
      npass = npass + 1
    else
      nfail = nfail + 1
      write (*, '(a,a)') 'FAIL ', what
    end if
  end subroutine check
end program fortran2008_host
