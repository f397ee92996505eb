! test_fric_steady.f90 -- viscous stick for steady-state transport (PROPS(7) = 3,
! docs/props.md) through FRIC, called as a user's Fortran 90 host calls it: a plain
! `call fric(...)` with the 39 Abaqus arguments, no interface block. The Fortran twin of
! c_tests/test_fric_steady.c, with the same scenes and closed forms.
!
! A disc spins at omega about the z axis; the point sits at COORDS = (0.3, 0.4, 2), R = 0.5.
! gamma_dot_crit = 2 F_f omega R (seed 000, PROPS(16) = 0) or F_f omega R (seed 003,
! PROPS(16) = 1). With v = |DGAM|/DTIME held constant along d, increment by increment:
!   stick (v <= gamma_dot_crit): TAU = kappa_s v d, kappa_s = mu p/gamma_dot_crit,
!     DDTDDG = kappa_s/DTIME I, DDTDDP = (mu v/gamma_dot_crit) d, DSLIP = 0, SFD = 0,
!     STATEV(2) = STATEV(3) = 0;
!   slip: TAU = mu(r) p d with r = v - gamma_dot_crit, DSLIP = r DTIME d, SFD = |TAU| r DTIME,
!     STATEV(1) grows by r DTIME, STATEV(2) = r, STATEV(3) = 1,
!     DDTDDG = (mu p/(v DTIME)) (I - d d) + d d mu'(r) p/DTIME, DDTDDP = mu(r) d;
! SED = 0; TAU on entry not read. NFDIR 1 and 2, both variants, constant mu and the
! exponential decay law. Bad input: PROPS(16) = 2, omega = 0 (PNEWDT < 1, a message naming
! the entry, TAU and STATEV unchanged).
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

program test_fric_steady
  use harness_tally
  use harness_fric_host
  implicit none
  real(dp), parameter :: mu = 0.4_dp, mu_k = 0.2_dp, dc = 3.0_dp, p = 50.0_dp, ff = 0.01_dp
  real(dp), parameter :: omega = 20.0_dp, radius = 0.5_dp, dt = 0.1_dp

  ! PROPS entries by name (generated from the schema).
  include 'props_index.inc'

  ! The FRIC arguments of one contact point (module harness_fric_host).
  type(fric_args) :: h

  ! NFDIR, PROPS(16) = 0 / 1 (seed 000's / seed 003's rate_crit), constant / decaying mu.
  call each_nfdir_and_switches(run_scene)
  call bad_input()
  call finish()

contains

  real(dp) function mu_of(dec, rate)
    integer, intent(in) :: dec
    real(dp), intent(in) :: rate
    mu_of = mu
    if (dec == 1) mu_of = mu_k + (mu - mu_k)*exp(-dc*rate)
  end function mu_of

  real(dp) function dmu_of(dec, rate)
    integer, intent(in) :: dec
    real(dp), intent(in) :: rate
    dmu_of = 0
    if (dec == 1) dmu_of = -dc*(mu - mu_k)*exp(-dc*rate)
  end function dmu_of

  subroutine point(n, var, dec)
    integer, intent(in) :: n, var, dec
    real(dp) :: props(kpc_n)
    props = 0
    props(kpc_code) = law_coulomb
    props(kpc_mu) = mu
    props(kpc_slip_tolerance) = ff
    props(kpc_stick) = 3 ! viscous stick, steady-state transport
    if (dec == 1) then
      props(kpc_mu_law) = 1 ! exponential decay
      props(kpc_mu_k) = mu_k
      props(kpc_decay) = dc
    end if
    props(kpc_omega) = omega
    props(kpc_axis) = 3 ! z axis
    props(kpc_viscous_reference) = real(var, dp)
    h = new_point(n, props, 'DISC_PAD')
    h%press = p
    h%dtime = dt
    call at_c_twin_point(h)
    h%slname = 'PAD'
    h%msname = 'DISC'
    h%coords = [0.3_dp, 0.4_dp, 2.0_dp]
    h%rcoord = h%coords
  end subroutine point

  subroutine call_fric()
    call fric_call(h)
    call check_tails(h)
  end subroutine call_fric

  subroutine run_scene(n, var, dec)
    integer, intent(in) :: n, var, dec
    real(dp) :: d(2), rate_crit, kappa, speeds(5), v, r, t, want, delta, proj, path
    integer :: s, k, ia, ib
    logical :: sticks
    d = [1.0_dp, 0.0_dp]
    if (n == 2) d = [0.6_dp, -0.8_dp]
    rate_crit = ff*omega*radius
    if (var == 0) rate_crit = 2*rate_crit
    kappa = mu*p/rate_crit
    ! Two speeds in stick (one just below the limit), two in slip, then stick again.
    speeds = [0.4_dp, 0.999_dp, 1.5_dp, 4.0_dp, 0.7_dp]*rate_crit
    path = 0
    call point(n, var, dec)
    do s = 1, 5
      v = speeds(s)
      sticks = v <= rate_crit
      write (scene, '(a,i0,a,i0,a,i0,a,g0.4)') 'steady NFDIR=', n, ' PROPS(16)=', var, &
        ' decay=', dec, ' v=', v
      do k = 1, 3
        ! TAU on entry is never read: a different one each increment.
        h%tau(1) = 17.0_dp*k
        if (n == 2) h%tau(2) = -17.0_dp*k
        h%dgam(1:n) = v*dt*d(1:n)
        call call_fric()
        call check(h%pnewdt == big, 'PNEWDT not lowered')
        call check(h%lm == 0, 'LM = 0')
        call check(h%sed == 0, 'SED = 0')
        if (sticks) then
          do ia = 1, n
            call check_near(h%tau(ia), kappa*v*d(ia), 1.0e-13_dp, 1.0e-13_dp*mu*p, &
                            'stick TAU = kappa_s v d')
            call check(h%dslip(ia) == 0, 'stick DSLIP = 0')
            call check_near(h%ddtddp(ia), mu*v/rate_crit*d(ia), 1.0e-13_dp, 1.0e-15_dp, &
                            'stick DDTDDP')
            do ib = 1, n
              want = 0
              if (ia == ib) want = kappa/dt
              call check_near(h%ddtddg(ia + (ib - 1)*n), want, 1.0e-13_dp, &
                              1.0e-13_dp*kappa/dt, 'stick DDTDDG = kappa_s/DTIME I')
            end do
          end do
          call check(h%sfd == 0, 'stick SFD = 0')
          call check(h%statev(2) == 0 .and. h%statev(3) == 0, 'stick STATEV(2:3) = 0')
        else
          r = v - rate_crit
          t = mu_of(dec, r)*p
          do ia = 1, n
            call check_near(h%tau(ia), t*d(ia), 1.0e-13_dp, 1.0e-13_dp*mu*p, &
                            'slip TAU = mu(v - crit) p d')
            call check_near(h%dslip(ia), r*dt*d(ia), 1.0e-13_dp, 1.0e-16_dp, 'slip DSLIP')
            call check_near(h%ddtddp(ia), mu_of(dec, r)*d(ia), 1.0e-13_dp, 1.0e-15_dp, &
                            'slip DDTDDP = mu d')
            do ib = 1, n
              delta = 0
              if (ia == ib) delta = 1
              proj = 0
              if (n == 2) proj = delta - d(ia)*d(ib)
              want = (t/v*proj + d(ia)*d(ib)*dmu_of(dec, r)*p)/dt
              call check_near(h%ddtddg(ia + (ib - 1)*n), want, 1.0e-12_dp, &
                              1.0e-12_dp*kappa/dt, 'slip DDTDDG')
            end do
          end do
          path = path + r*dt
          call check_near(h%sfd, t*r*dt, 1.0e-13_dp, 0.0_dp, 'slip SFD = |TAU| |DSLIP|')
          call check(h%statev(3) == 1, 'slip STATEV(3) = 1')
          call check_near(h%statev(2), r, 1.0e-13_dp, 0.0_dp, 'slip STATEV(2) = v - crit')
        end if
        call check_near(h%statev(1), path, 1.0e-13_dp, 0.0_dp, 'STATEV(1) = slip path')
      end do
    end do
  end subroutine run_scene

  subroutine refused(needle)
    character(len=*), intent(in) :: needle
    real(dp) :: tau0(2), statev0(3)
    character(len=2048) :: msg
    h%statev(1:3) = [0.5_dp, 0.1_dp, 1.0_dp]
    h%tau(1:2) = [3.0_dp, -2.0_dp]
    h%dgam(1) = 1.0e-3_dp
    tau0 = h%tau(1:2)
    statev0 = h%statev(1:3)
    call ifl_clear_error()
    call call_fric()
    call check(h%pnewdt < 1, 'PNEWDT < 1')
    msg = last_error()
    call check_contains(msg, 'FRIC')
    call check_contains(msg, needle)
    call check(all(h%tau(1:2) == tau0), 'TAU unchanged')
    call check(all(h%statev(1:3) == statev0), 'STATEV unchanged')
  end subroutine refused

  subroutine bad_input()
    scene = 'steady transport: PROPS(16) = 2'
    call point(2, 2, 0)
    call refused('PROPS(16) = 2 must select')
    scene = 'steady transport: PROPS(16) = 0.5'
    call point(2, 0, 0)
    h%props(kpc_viscous_reference) = 0.5_dp
    call refused('PROPS(16) = 0.5 must select')
    scene = 'steady transport: omega = 0'
    call point(2, 1, 0)
    h%props(kpc_omega) = 0
    call refused('PROPS(14)')
    ! On the axis R = 0, so seed 003's rate_crit F_f omega R is 0.
    scene = 'steady transport: a point on the axis, seed 003'
    call point(2, 1, 0)
    h%coords(1:2) = 0
    call refused('F_f·ω·R must be > 0')
  end subroutine bad_input
end program test_fric_steady
