! test_fric_rate_state.f90 -- rate-and-state friction (PROPS(1) = 3, docs/props.md "Law 3")
! through FRIC, called as a user's Fortran 90 host calls it: a plain `call fric(...)` with the 39
! Abaqus arguments, no interface block, NSTATV = 4 (DEPVAR=4). The Fortran twin of
! c_tests/test_fric_rate_state.c, with the same scenes and closed forms:
!   steady sliding at V, NFDIR 1 and 2, aging and slip laws, at two increment sizes (2 L and
!     L/20 of slip): |TAU| = mu_ss(V) p, mu_ss = mu0 + (a - b) ln(V/V0) (logarithmic form) or
!     a asinh(V/(2 V0) exp((mu0 + b ln(V0/V))/a)) (regularised form, on a parameter set where
!     the two differ); both sizes give the same stress; STATEV = (slip path, V, 1, L/V),
!     DSLIP = V DTIME d, SFD = |TAU| V DTIME, SED = |TAU| gamma_crit/2, DDTDDP = mu d, LM = 0;
!     the slip tangent along d against a central difference of TAU;
!   a velocity step V1 -> V2 (up and down) from steady state: TAU/p = mu(V2, theta(t)) at the
!     end of each increment with the evolution law's analytic theta(t) at constant V2 (aging:
!     L/V2 + (theta1 - L/V2) e^(-V2 t/L); slip: (L/V2) exp(ln(V2 theta1/L) e^(-V2 t/L))),
!     STATEV(4) = theta(t), the first increment's jump a ln(V2/V1) + b ln(theta(dt)/theta1);
!   bad input refused (PNEWDT < 1, the message names FRIC, the interaction and the cause; TAU
!     and STATEV unchanged): NSTATV = 3, a = -0.01 (PROPS(3)), V0 = 0 (PROPS(5)), L = 0
!     (PROPS(6)), theta < 0 in STATEV(4), DTIME = 0.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

program test_fric_rate_state
  use harness_tally
  use harness_fric_host
  implicit none
  real(dp), parameter :: v0 = 1.0e-6_dp, l_slip = 1.0e-5_dp, gcrit = 1.0e-7_dp, p = 50.0_dp
  ! Two parameter sets (mu0, a, b): rock-like (a = 0.01: the regularised form is the
  ! logarithmic one to round-off) and mu0/a = 1, where the regularisation changes mu by 10 % or
  ! more. On the second the logarithmic mu goes below 0 for V below V0 at theta = L/V0, so its
  ! scenes slide at V0 and above.
  real(dp), parameter :: sets(3, 2) = reshape([0.6_dp, 0.01_dp, 0.015_dp, &
                                                0.1_dp, 0.1_dp, 0.12_dp], [3, 2])
  real(dp), parameter :: rates(3, 2) = reshape([3.0e-7_dp, 1.0e-6_dp, 1.0e-5_dp, &
                                                1.0e-6_dp, 3.0e-6_dp, 1.0e-5_dp], [3, 2])

  ! PROPS entries by name (generated from the schema).
  include 'props_index.inc'

  ! The FRIC arguments of one contact point (module harness_fric_host) and the slip direction.
  type(fric_args) :: h
  real(dp) :: d(2)
  integer :: set, slip_law, reg, n

  do set = 1, 2
    do slip_law = 0, 1
      do reg = 0, 1
        do n = 1, 2
          call steady(set, slip_law, reg, n)
        end do
        call velocity_step(set, slip_law, reg, 1.0e-6_dp, 1.0e-5_dp, 2.0_dp)
        call velocity_step(set, slip_law, reg, 1.0e-6_dp, 1.0e-5_dp, 200.0_dp)
        ! Down: on the second set the logarithmic mu(V0, L/(10 V0)) < 0.
        if (set == 1 .or. reg == 1) then
          call velocity_step(set, slip_law, reg, 1.0e-5_dp, 1.0e-6_dp, 20.0_dp)
        end if
      end do
    end do
  end do
  do n = 1, 2
    call bad_input(n)
  end do
  call finish()

contains

  ! mu(V, theta) of each form, from the law's definition.
  real(dp) function mu_of(st, rg, v, theta)
    integer, intent(in) :: st, rg
    real(dp), intent(in) :: v, theta
    real(dp) :: psi
    psi = sets(1, st) + sets(3, st)*log(v0*theta/l_slip)
    if (rg == 1) then
      mu_of = sets(2, st)*asinh(v/(2*v0)*exp(psi/sets(2, st)))
    else
      mu_of = psi + sets(2, st)*log(v/v0)
    end if
  end function mu_of

  ! The steady-state coefficient at V (theta = L/V).
  real(dp) function mu_ss(st, rg, v)
    integer, intent(in) :: st, rg
    real(dp), intent(in) :: v
    real(dp) :: mu0, a, b
    mu0 = sets(1, st)
    a = sets(2, st)
    b = sets(3, st)
    if (rg == 1) then
      mu_ss = a*asinh(v/(2*v0)*exp((mu0 + b*log(v0/v))/a))
    else
      mu_ss = mu0 + (a - b)*log(v/v0)
    end if
  end function mu_ss

  ! theta after sliding at constant V for a time t from theta1: each law's analytic solution.
  real(dp) function theta_at(theta1, v, t, sl)
    real(dp), intent(in) :: theta1, v, t
    integer, intent(in) :: sl
    real(dp) :: decay
    decay = exp(-v*t/l_slip)
    if (sl == 1) then
      theta_at = l_slip/v*exp(log(v*theta1/l_slip)*decay)
    else
      theta_at = l_slip/v + (theta1 - l_slip/v)*decay
    end if
  end function theta_at

  ! A point of interaction SI_PAD at first contact (PRESS = DPRESS = p), NSTATV = 4 with STATEV
  ! 0 (theta not yet started: L/V0), the whole law-3 layout.
  subroutine point(st, sl, rg, nd)
    integer, intent(in) :: st, sl, rg, nd
    real(dp) :: props(kpr_n)
    props = 0
    props(kpr_code) = law_rate_state
    props(kpr_mu0) = sets(1, st)
    props(kpr_a) = sets(2, st)
    props(kpr_b) = sets(3, st)
    props(kpr_v0) = v0
    props(kpr_l) = l_slip
    props(kpr_evolution) = sl
    props(kpr_form) = rg
    props(kpr_gamma_crit) = gcrit
    h = new_point(nd, props, 'SI_PAD')
    call at_c_twin_point(h)
    h%nstatv = 4
    h%statev(4) = 0
    h%press = p
    h%dpress = p
    d = [1.0_dp, 0.0_dp]
    if (nd == 2) d = [0.6_dp, -0.8_dp]
  end subroutine point

  ! One increment of slip dg along d in time dg/v, a call that must succeed; returns |TAU|.
  real(dp) function step(dg, v)
    real(dp), intent(in) :: dg, v
    h%dgam(1:h%nfdir) = dg*d(1:h%nfdir)
    h%dtime = dg/v
    call fric_call(h)
    call check(h%pnewdt == big, 'no cut-back')
    call check(h%lm == 0, 'LM = 0')
    call check_tails(h)
    h%dpress = 0
    step = norm2(h%tau(1:h%nfdir))
  end function step

  ! The slip tangent along d, d.DDTDDG.d, against a central difference of FRIC's own TAU
  ! (DGAM +- 1e-9 d), to the absolute tolerance atol: the twin of fh_check_tangent_along.
  subroutine check_tangent_along(atol)
    real(dp), intent(in) :: atol
    type(fric_args) :: base, plus, minus
    real(dp), parameter :: hg = 1.0e-9_dp
    real(dp) :: an, fd
    integer :: nd, ia, ib
    nd = h%nfdir
    base = h
    plus = h
    minus = h
    plus%dgam(1:nd) = plus%dgam(1:nd) + hg*d(1:nd)
    minus%dgam(1:nd) = minus%dgam(1:nd) - hg*d(1:nd)
    call fric_call(base)
    call fric_call(plus)
    call fric_call(minus)
    call check(base%pnewdt == big .and. plus%pnewdt == big .and. minus%pnewdt == big, &
               'tangent calls not cut back')
    fd = dot_product(d(1:nd), plus%tau(1:nd) - minus%tau(1:nd))/(2*hg)
    an = 0
    do ia = 1, nd
      do ib = 1, nd
        an = an + d(ia)*base%ddtddg(ia + (ib - 1)*nd)*d(ib)
      end do
    end do
    call check_abs(an, fd, atol, 'slip tangent against a central difference')
  end subroutine check_tangent_along

  subroutine steady(st, sl, rg, nd)
    integer, intent(in) :: st, sl, rg, nd
    real(dp), parameter :: per_l(2) = [0.5_dp, 20.0_dp] ! increments per slip L
    real(dp) :: v, want, dg, t, tau(2), a, b
    integer :: i, j, k, ninc, ia
    a = sets(2, st)
    b = sets(3, st)
    do i = 1, 3
      v = rates(i, st)
      want = mu_ss(st, rg, v)*p
      do j = 1, 2
        dg = l_slip/per_l(j)
        ninc = int(60*per_l(j)) ! 60 L of slip: e^(-60) of the way left
        write (scene, '(a,i0,a,i0,a,i0,a,i0,a,g0.3,a,g0.3)') 'steady set ', st, ' evolution ', &
          sl, ' form ', rg, ' NFDIR ', nd, ' V ', v, ' per L ', per_l(j)
        call point(st, sl, rg, nd)
        do k = 1, ninc
          t = step(dg, v)
        end do
        tau(j) = t
        call check_near(t, want, 1.0e-13_dp, 0.0_dp, '|TAU| = mu_ss(V) p')
        do ia = 1, nd
          call check_near(h%tau(ia), want*d(ia), 1.0e-12_dp, 1.0e-15_dp*want, 'TAU along d')
          call check_near(h%dslip(ia), dg*d(ia), 1.0e-12_dp, 1.0e-15_dp*dg, 'DSLIP = V DTIME d')
          call check_near(h%ddtddp(ia), want/p*d(ia), 1.0e-12_dp, 1.0e-15_dp, 'DDTDDP = mu d')
        end do
        call check_near(h%sfd, t*dg, 1.0e-12_dp, 0.0_dp, 'SFD = |TAU| V DTIME')
        call check_near(h%sed, 0.5_dp*t*gcrit, 1.0e-12_dp, 0.0_dp, 'SED = |TAU| gamma_crit/2')
        call check(h%statev(3) == 1, 'STATEV(3) = 1 (slip)')
        call check_near(h%statev(2), v, 1.0e-12_dp, 0.0_dp, 'STATEV(2) = V')
        call check_near(h%statev(4), l_slip/v, 1.0e-11_dp, 0.0_dp, 'STATEV(4) = theta_ss = L/V')
        ! The path: the first increment slides dg - gamma_crit, every later one dg.
        call check_near(h%statev(1), ninc*dg - gcrit, 1.0e-12_dp, 0.0_dp, 'STATEV(1) = path')
        ! Its scale is p max(a, |b|)/(V DTIME).
        call check_tangent_along(1.0e-5_dp*p*max(a, abs(b))/(v*h%dtime))
      end do
      write (scene, '(a,i0,a,i0,a,i0,a,i0,a,g0.3)') 'steady set ', st, ' evolution ', sl, &
        ' form ', rg, ' NFDIR ', nd, ' V ', v
      call check_near(tau(1), tau(2), 1.0e-13_dp, 0.0_dp, 'the same stress at both sizes')
      ! On the second set the regularised steady state is not the logarithmic one.
      if (st == 2) call check(abs(mu_ss(st, 1, v) - mu_ss(st, 0, v)) > 1.0e-3_dp, &
                              'the two forms differ on the second set')
    end do
  end subroutine steady

  ! Steady sliding at v1 (60 L at 20 increments per L), then increments of L/per_l at v2.
  subroutine velocity_step(st, sl, rg, v1, v2, per_l)
    integer, intent(in) :: st, sl, rg
    real(dp), intent(in) :: v1, v2, per_l
    real(dp) :: dg1, dg, dt, theta1, theta, t, to_ss, decayed, a, b
    integer :: k, ninc
    a = sets(2, st)
    b = sets(3, st)
    dg1 = l_slip/20
    dg = l_slip/per_l
    dt = dg/v2
    ninc = int(10*per_l)
    write (scene, '(a,i0,a,i0,a,i0,a,g0.3,a,g0.3,a,g0.3)') 'step set ', st, ' evolution ', sl, &
      ' form ', rg, ' V ', v1, ' -> ', v2, ' per L ', per_l
    call point(st, sl, rg, 1)
    do k = 1, 1200
      t = step(dg1, v1)
    end do
    call check_near(t, mu_ss(st, rg, v1)*p, 1.0e-12_dp, 0.0_dp, 'steady at V1')
    theta1 = h%statev(4)
    call check_near(theta1, l_slip/v1, 1.0e-11_dp, 0.0_dp, 'theta1 = L/V1')
    do k = 1, ninc
      theta = theta_at(theta1, v2, k*dt, sl)
      t = step(dg, v2)
      call check_abs_at(t/p, mu_of(st, rg, v2, theta), 1.0e-12_dp, 'TAU/p = mu(V2, theta(t))', k)
      call check_abs_at(h%statev(4), theta, 1.0e-10_dp*theta, 'STATEV(4) = theta(t)', k)
      if (k == 1 .and. rg == 0) then
        call check_abs(t/p - mu_ss(st, 0, v1), a*log(v2/v1) + b*log(theta/theta1), 1.0e-12_dp, &
                       'the jump: a ln(V2/V1) + b ln(theta(dt)/theta1)')
      end if
    end do
    ! After 10 L of slip: within b |ln(theta/theta_ss)| of the new steady state, with
    ! ln(V2 theta/L) = ln(V2/V1) e^(-10) (slip law) or V2 theta/L - 1 = (V2/V1 - 1) e^(-10)
    ! (aging law), |ln(1 + x)| <= |x|/(1 - |x|).
    to_ss = abs(t/p - mu_ss(st, rg, v2))
    if (sl == 1) then
      decayed = abs(log(v2/v1))*exp(-10.0_dp)
    else
      decayed = abs(v2/v1 - 1)*exp(-10.0_dp)
    end if
    call check(to_ss <= b*decayed/(1 - decayed)*(1 + 1.0e-9_dp) + 1.0e-12_dp, &
               'within the decayed distance of the new steady state after 10 L')
  end subroutine velocity_step

  ! A point of the rock-like set after one sliding increment, about to slide another.
  subroutine slid_point(nd)
    integer, intent(in) :: nd
    real(dp) :: t
    call point(1, 0, 0, nd)
    t = step(1.0e-6_dp, 1.0e-6_dp)
    h%dgam(1) = 1.0e-6_dp
    h%dtime = 1
  end subroutine slid_point

  ! The spoiled point must be refused: PNEWDT < 1, the message names FRIC, the interaction and
  ! needle; TAU and STATEV(1..min(NSTATV, 4)) unchanged.
  subroutine refused(needle)
    character(len=*), intent(in) :: needle
    real(dp) :: tau0(2), statev0(4)
    character(len=2048) :: msg
    integer :: ns
    ns = min(h%nstatv, 4)
    tau0 = h%tau(1:2)
    statev0 = h%statev(1:4)
    call ifl_clear_error()
    call fric_call(h)
    call check_tails(h)
    call check(h%pnewdt < 1, 'PNEWDT < 1')
    msg = last_error()
    call check_contains(msg, 'FRIC')
    call check_contains(msg, 'SI_PAD')
    call check_contains(msg, needle)
    call check(all(h%tau(1:h%nfdir) == tau0(1:h%nfdir)), 'TAU unchanged')
    call check(all(h%statev(1:ns) == statev0(1:ns)), 'STATEV unchanged')
  end subroutine refused

  subroutine bad_input(nd)
    integer, intent(in) :: nd
    write (scene, '(a,i0,a)') 'bad input NFDIR ', nd, ': NSTATV = 3'
    call slid_point(nd)
    h%nstatv = 3
    h%statev(4) = sentinel ! a host with DEPVAR=3 has no STATEV(4)
    call refused('NSTATV = 3')
    write (scene, '(a,i0,a)') 'bad input NFDIR ', nd, ': a = -0.01'
    call slid_point(nd)
    h%props(kpr_a) = -0.01_dp
    call refused('PROPS(3)')
    write (scene, '(a,i0,a)') 'bad input NFDIR ', nd, ': V0 = 0'
    call slid_point(nd)
    h%props(kpr_v0) = 0
    call refused('PROPS(5)')
    write (scene, '(a,i0,a)') 'bad input NFDIR ', nd, ': L = 0'
    call slid_point(nd)
    h%props(kpr_l) = 0
    call refused('PROPS(6)')
    write (scene, '(a,i0,a)') 'bad input NFDIR ', nd, ': theta < 0'
    call slid_point(nd)
    h%statev(4) = -1
    call refused('STATEV(4)')
    write (scene, '(a,i0,a)') 'bad input NFDIR ', nd, ': DTIME = 0'
    call slid_point(nd)
    h%dtime = 0
    call refused('DTIME')
  end subroutine bad_input
end program test_fric_rate_state
