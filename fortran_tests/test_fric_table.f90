! test_fric_table.f90 -- mu from a table in the configuration file (PROPS(8) = 2, docs/config.md
! "Friction tables") through FRIC and FRIC_COEF, called as a user's Fortran 90 host calls them:
! plain `call fric(...)` / `call fric_coef(...)` with the Abaqus arguments, no interface block.
! The Fortran twin of c_tests/test_fric_table.c, with the same scenes and closed forms. CTest
! points INTERFACIAL_CONFIG at c_tests/configs/fric_table.toml (no argument) or at
! c_tests/configs/fric_table_bad_unsorted.toml (argument "bad"); the numbers below are those
! files' (edit them together).
!
! good: scene F4 velocity steps with the table of SI_PAD, mu_tab(v) = 0.6 - 0.5 v up to 0.3,
! then linear to 0.3 at v = 1, constant beyond: once steady |tau| = mu_tab(v) p and
! STATEV(2) = v, for NFDIR 1 and 2, elastic and exact stick, implicit and frozen mu, at rates
! inside the table, on its kink and beyond its last row; in elastic stick the slip tangent
! along the slip direction against a central difference of TAU; FRIC_COEF of BRAKE
! (mu(rate, p), bilinear) against the hand interpolation with its derivatives; an interaction
! without a table refused (PNEWDT < 1, message names the interaction and the missing
! [interactions.NAME.friction], TAU and STATEV unchanged).
! bad: the call is refused, the message names the file, line 7, the key and the cause.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

! The host side of one contact point: module harness_fric_host, with this scene's names and sizes.
module table_host
  use harness_tally
  use harness_fric_host
  implicit none
  real(dp), parameter :: p = 50.0_dp, gamma_crit = 1.0e-3_dp, dt = 0.01_dp

contains

  ! SI_PAD's table, by hand.
  real(dp) function mu_tab(v)
    real(dp), intent(in) :: v
    if (v <= 0.3_dp) then
      mu_tab = 0.6_dp - 0.5_dp*v
    else if (v <= 1.0_dp) then
      mu_tab = 0.45_dp - (0.15_dp/0.7_dp)*(v - 0.3_dp)
    else
      mu_tab = 0.3_dp
    end if
  end function mu_tab

  ! Law 1 with the mu table: PROPS(2) = 1 is only the reference of the anisotropy ratio.
  function props_table(exact, frozen) result(props)
    logical, intent(in) :: exact, frozen
    real(dp) :: props(20)
    props = 0
    props(1) = 1
    props(2) = 1
    props(5) = gamma_crit
    if (exact) props(7) = 1
    props(8) = 2
    if (frozen) props(20) = 1
  end function props_table

  ! A point of SI_PAD at first contact, as the C twin's host fills it.
  function table_point(nfdir, props) result(a)
    integer, intent(in) :: nfdir
    real(dp), intent(in) :: props(20)
    type(fric_args) :: a
    a = new_point(nfdir, props, 'SI_PAD')
    a%dtime = dt
    call at_c_twin_point(a)
  end function table_point

  ! One FRIC call, then the tails past NFDIR / NFDIR**2 / NSTATV checked untouched.
  subroutine fric_call_tails(a)
    type(fric_args), intent(inout) :: a
    call fric_call(a)
    call check_tails(a)
  end subroutine fric_call_tails

  subroutine fric_call_ok(a)
    type(fric_args), intent(inout) :: a
    call fric_call_tails(a)
    call check(a%pnewdt == big, 'PNEWDT not lowered')
    if (a%pnewdt /= big .and. nfail <= 40) write (*, '(a,a)') '   message: ', trim(last_error())
  end subroutine fric_call_ok

  ! Scene F4: velocity steps, 40 increments at each rate, then the closed forms.
  subroutine steps(nfdir, exact, frozen)
    integer, intent(in) :: nfdir, exact, frozen
    real(dp), parameter :: rates(5) = [0.05_dp, 0.5_dp, 0.2_dp, 1.5_dp, 0.8_dp]
    real(dp), parameter :: hg = 1.0e-9_dp
    type(fric_args) :: h, base, plus, minus
    real(dp) :: d(2), v, an, fd
    integer :: s, k, ia, ib
    d = [1.0_dp, 0.0_dp]
    if (nfdir == 2) d = [0.6_dp, 0.8_dp]
    h = table_point(nfdir, props_table(exact == 1, frozen == 1))
    h%press = p
    h%dpress = p
    do s = 1, size(rates)
      v = rates(s)
      write (scene, '(a,i0,a,i0,a,i0,a,g0.3)') 'F4 table NFDIR=', nfdir, ' exact=', exact, &
        ' frozen=', frozen, ' v=', v
      do k = 1, 40
        h%dgam(1:nfdir) = v*dt*d(1:nfdir)
        call fric_call_ok(h)
        call check(h%lm == 0, 'LM = 0 while sliding')
        h%dpress = 0
      end do
      call check_near(sqrt(sum(h%tau(1:nfdir)**2)), mu_tab(v)*p, 1.0e-11_dp, 0.0_dp, &
                      'steady |tau| = mu_tab(v) p')
      call check_near(h%statev(2), v, 1.0e-11_dp, 0.0_dp, 'STATEV(2) = v')
      if (exact == 0) then
        ! d tau/d DGAM along the slip direction against a central difference of TAU, all three
        ! calls from the same steady start.
        base = h
        plus = h
        minus = h
        call fric_call_ok(base)
        plus%dgam(1:nfdir) = plus%dgam(1:nfdir) + hg*d(1:nfdir)
        minus%dgam(1:nfdir) = minus%dgam(1:nfdir) - hg*d(1:nfdir)
        call fric_call_ok(plus)
        call fric_call_ok(minus)
        an = 0
        fd = 0
        do ia = 1, nfdir
          fd = fd + d(ia)*(plus%tau(ia) - minus%tau(ia))/(2*hg)
          do ib = 1, nfdir
            ! DDTDDG(a,b), column-major.
            an = an + d(ia)*base%ddtddg(ia + (ib - 1)*nfdir)*d(ib)
          end do
        end do
        call check_near(an, fd, 0.0_dp, 1.0e-5_dp*0.6_dp*p/gamma_crit, &
                        'slip tangent along the slip against a central difference')
      end if
    end do
  end subroutine steps

  ! BRAKE at (rate, p) = (0.25, 30): 0.5 - 0.025 = 0.475 at p = 0, 0.375 at p = 100, so
  ! mu = 0.475 - 0.3 * 0.1 = 0.445; d mu/d rate = -0.1; d mu/d p = -0.001; mu2/mu1 = 0.5.
  subroutine coef_brake()
    real(dp) :: props(20), fcoef(1, 2), deriv(1, 20, 2), sdata(1, 6), press(1), tavg(1)
    real(dp) :: favg(1, 1), rdata(8)
    integer :: nblock, nprops, ntemp, nfields, idata(6)
    character(len=80) :: name, blank
    scene = 'FRIC_COEF with the table of BRAKE'
    name = 'brake' ! names match ignoring case
    blank = ' '
    props = props_table(.false., .false.)
    props(3) = 0.5_dp
    sdata = 0
    sdata(1, 1) = 0.25_dp
    press = 30.0_dp
    tavg = 20.0_dp
    favg = 0
    rdata = 0
    idata = 0
    nblock = 1
    nprops = 20
    ntemp = 1
    nfields = 0
    fcoef = -1
    deriv = -1
    call ifl_clear_error()
    call fric_coef(fcoef, deriv, nblock, nprops, ntemp, nfields, idata, rdata, name, blank, &
                   blank, props, sdata, press, tavg, favg)
    call check(len_trim(last_error()) == 0, 'no message')
    call check_near(fcoef(1, 1), 0.445_dp, 1.0e-14_dp, 0.0_dp, 'mu1 = 0.445')
    call check_near(fcoef(1, 2), 0.5_dp*0.445_dp, 1.0e-14_dp, 0.0_dp, 'mu2 = 0.5 mu1')
    call check_near(deriv(1, 1, 1), -0.1_dp, 1.0e-13_dp, 0.0_dp, 'd mu1/d rate = -0.1')
    call check_near(deriv(1, 2, 1), -0.001_dp, 1.0e-12_dp, 0.0_dp, 'd mu1/d p = -0.001')
    call check(deriv(1, 3, 1) == 0, 'd mu1/d theta = 0')
    call check_near(deriv(1, 1, 2), -0.05_dp, 1.0e-13_dp, 0.0_dp, 'd mu2/d rate = -0.05')
  end subroutine coef_brake

  ! A call that must be refused: PNEWDT < 1, every needle in the message, TAU and STATEV
  ! unchanged.
  subroutine refused(h, needles)
    type(fric_args), intent(inout) :: h
    character(len=*), intent(in) :: needles(:)
    type(fric_args) :: before
    character(len=2048) :: msg
    integer :: i
    h%statev(1:3) = [0.5_dp, 0.1_dp, 1.0_dp]
    h%tau(1) = 3.0_dp
    h%press = 100.0_dp
    h%dgam(1) = 1.0e-2_dp
    before = h
    call ifl_clear_error()
    call fric_call_tails(h)
    call check(h%pnewdt < 1, 'PNEWDT < 1')
    msg = last_error()
    call check_contains(msg, 'FRIC')
    do i = 1, size(needles)
      call check_contains(msg, trim(needles(i)))
    end do
    call check(all(h%tau(1:h%nfdir) == before%tau(1:h%nfdir)), 'TAU unchanged')
    call check(all(h%statev(1:3) == before%statev(1:3)), 'STATEV unchanged')
  end subroutine refused
end module table_host

program test_fric_table
  use table_host
  implicit none
  type(fric_args) :: h
  character(len=16) :: mode
  character(len=1024) :: config
  character(len=1200) :: where
  integer :: clen

  mode = 'good'
  if (command_argument_count() >= 1) call get_command_argument(1, mode)
  call get_environment_variable('INTERFACIAL_CONFIG', config, clen)
  if (clen == 0) config = '?'

  if (trim(mode) == 'bad') then
    ! Rows 2 and 3 of SI_PAD's table go backwards, on line 7 of the file.
    scene = 'bad table'
    write (where, '(a,a)') trim(config), ':7: interactions.SI_PAD.friction.table'
    h = table_point(2, props_table(.false., .false.))
    call refused(h, [character(len=1200) :: where, 'slip rates must be strictly increasing'])
  else
    call each_nfdir_and_switches(steps)
    call coef_brake()
    scene = 'interaction without a table'
    h = table_point(2, props_table(.false., .false.))
    h%ciname = 'NO_TABLE'
    call refused(h, [character(len=40) :: "'NO_TABLE'", '[interactions.NO_TABLE.friction]'])
  end if

  call finish()
end program test_fric_table
