! test_fric_scenes.f90 -- scenes F2 (circle), F3 (friction ellipse), F5 (pressure ramp while
! sliding; also with a pressure-dependent mu), tangential damping and F1 with exact stick (a
! spring host) through FRIC, from free-form Fortran. FRIC is called the way a user's own Fortran
! 90 host would: a plain `call fric(...)` with the 39 Abaqus arguments, no interface block, no
! ISO_C_BINDING.
!
! Every assertion is a closed form (docs/scene-definitions.md; the law: docs/source-model.md), a
! central finite difference of TAU from repeated FRIC calls, or an invariant (SFD >= 0, guard
! entries untouched, PNEWDT never lowered). Symbols: p pressure, mu friction coefficient,
! gc = gamma_crit, k_s = tau_crit/gc, tau_crit = min(mu p, tau_max).
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

! The host side of one contact point (module harness_fric_host) with the checks these scenes make
! after every call and their central finite differences.
module fric_host
  use harness_fric_host
  ! The tally: check and check_near here take the increment or point number K.
  use harness_tally, only: dp, finish, scene, check => check_at, check_near => check_abs_at
  implicit none
  real(dp), parameter :: pi = 3.14159265358979323846_dp

contains

  ! After every call: PNEWDT never lowered, tails past NFDIR / NFDIR**2 / 2 NFDIR / NSTATV
  ! untouched, SFD never negative when LM = 0.
  subroutine check_call(a, k)
    type(fric_args), intent(in) :: a
    integer, intent(in) :: k
    integer :: n
    n = a%nfdir
    call check(a%pnewdt == big, 'PNEWDT never lowered', k)
    call check_tails(a)
    if (a%lm == 0) then
      call check(a%sfd >= 0, 'SFD >= 0', k)
      call check(all(a%ddtddt(1:2*n) == 0), 'DDTDDT = 0 (mu independent of temperature)', k)
    end if
  end subroutine check_call

  ! Central finite differences of TAU from repeated FRIC calls from the same start (a0: the
  ! arguments of the call being checked) against the tangents a1 that call returned.
  ! DGAM(b) is perturbed for DDTDDG(:,b); PRESS and DPRESS together for DDTDDP, so the start of
  ! the increment, p - dp, stays put (the tangent is taken with the start held fixed).
  subroutine check_tangents_fd(a0, a1, gscale, kscale, pscale, k)
    type(fric_args), intent(in) :: a0, a1
    real(dp), intent(in) :: gscale, kscale, pscale
    integer, intent(in) :: k
    type(fric_args) :: b
    real(dp) :: tp(mg), tm(mg), hp, hm
    integer :: n, ia, ib
    n = a0%nfdir
    do ib = 1, n
      b = a0
      b%dgam(ib) = a0%dgam(ib) + 1.0e-6_dp*gscale
      hp = b%dgam(ib) - a0%dgam(ib)
      call fric_call(b)
      call check(b%lm == 0, 'FD call: LM = 0', k)
      tp = b%tau
      b = a0
      b%dgam(ib) = a0%dgam(ib) - 1.0e-6_dp*gscale
      hm = a0%dgam(ib) - b%dgam(ib)
      call fric_call(b)
      call check(b%lm == 0, 'FD call: LM = 0', k)
      tm = b%tau
      do ia = 1, n
        call check_near(a1%ddtddg(ia + (ib - 1)*n), (tp(ia) - tm(ia))/(hp + hm), &
                        1.0e-7_dp*kscale, 'DDTDDG = central FD of TAU in DGAM', k)
      end do
    end do
    b = a0
    b%press = a0%press + 1.0e-6_dp*a0%press
    b%dpress = a0%dpress + (b%press - a0%press)
    hp = b%press - a0%press
    call fric_call(b)
    call check(b%lm == 0, 'FD call: LM = 0', k)
    tp = b%tau
    b = a0
    b%press = a0%press - 1.0e-6_dp*a0%press
    b%dpress = a0%dpress - (a0%press - b%press)
    hm = a0%press - b%press
    call fric_call(b)
    call check(b%lm == 0, 'FD call: LM = 0', k)
    tm = b%tau
    do ia = 1, n
      call check_near(a1%ddtddp(ia), (tp(ia) - tm(ia))/(hp + hm), 1.0e-7_dp*pscale, &
                      'DDTDDP = central FD of TAU in PRESS (with DPRESS)', k)
    end do
  end subroutine check_tangents_fd

  ! Unit direction: 1 for NFDIR = 1, angle theta (radians) for NFDIR = 2.
  function direction(nfdir, theta) result(e)
    integer, intent(in) :: nfdir
    real(dp), intent(in) :: theta
    real(dp) :: e(2)
    if (nfdir == 1) then
      e = [1.0_dp, 0.0_dp]
    else
      e = [cos(theta), sin(theta)]
    end if
  end function direction
end module fric_host

module scenes
  use fric_host
  implicit none
  real(dp), parameter :: mu = 0.3_dp, gc = 1.0e-3_dp
contains

  ! Scene F2, circle: constant p = 100, NFDIR = 2, the imposed slip runs on a circle of radius
  ! R = 0.01 (gc/R = 0.1), gamma(theta) = R (cos theta - 1, sin theta), n increments per turn.
  ! The rate problem's steady state: |tau| = mu p and tau lags behind the slip tangent
  ! t = (-sin theta, cos theta) by phi, sin phi = gc/R.
  ! The backward-Euler return map has its own steady state, in closed form: with the increment
  ! chord c = 2 R sin(dth/2) along theta_k - dth/2 + pi/2 and the elastic slip gc n_k rotating
  ! by dth per increment, the predictor gc n_{k-1} + c u is parallel to n_k iff
  !   sin(phi_d - dth/2) = (gc/R) cos(dth/2),  so  phi_d = dth/2 + asin((gc/R) cos(dth/2)),
  ! |gamma_pr| = gc cos(dth) + c cos(phi_d - dth/2) and SFD = mu p (|gamma_pr| - gc).
  ! phi_d - phi = dth/2 + O(dth^2): first order in the step, and <= 2 pi/n.
  subroutine scene_f2(n, nturns, lag_err)
    integer, intent(in) :: n, nturns
    real(dp), intent(out) :: lag_err
    real(dp), parameter :: p = 100.0_dp, r = 0.01_dp
    type(fric_args) :: a, a0
    real(dp) :: dth, th0, th1, phi, phid, chord, gpr, tauc, t(2), lag, tnorm, sumsfd, sumtds
    integer :: k
    write (scene, '(a,i0)') 'F2 circle N=', n
    a = new_point(2, [1.0_dp, mu, 0.0_dp, 0.0_dp, gc], 'F2-CIRCLE', 0.2_dp)
    a%press = p
    a%dpress = 0
    tauc = mu*p
    dth = 2*pi/n
    phi = asin(gc/r)
    phid = dth/2 + asin((gc/r)*cos(dth/2))
    chord = 2*r*sin(dth/2)
    gpr = gc*cos(dth) + chord*cos(phid - dth/2)
    lag_err = 0
    sumsfd = 0
    sumtds = 0
    do k = 1, n*nturns
      th0 = dth*(k - 1)
      th1 = dth*k
      a%kinc = k
      a%dgam(1) = r*(cos(th1) - cos(th0))
      a%dgam(2) = r*(sin(th1) - sin(th0))
      a0 = a
      call fric_call(a)
      call check(a%lm == 0, 'LM = 0', k)
      call check_call(a, k)
      tnorm = hypot(a%tau(1), a%tau(2))
      call check(tnorm <= tauc*(1 + 1.0e-14_dp), '|tau| <= mu p', k)
      sumsfd = sumsfd + a%sfd
      sumtds = sumtds + dot_product(a%tau(1:2), a%dslip(1:2))
      if (k > n*(nturns - 1)) then
        ! Last turn: the steady state of the return map has been reached.
        call check_near(tnorm, tauc, 1.0e-13_dp*tauc, '|tau| = mu p in slip', k)
        call check(a%statev(3) == 1, 'STATEV(3) = 1 (slip)', k)
        t = [-sin(th1), cos(th1)]
        lag = atan2(a%tau(1)*t(2) - a%tau(2)*t(1), dot_product(a%tau(1:2), t))
        call check_near(lag, phid, 1.0e-9_dp, 'lag = discrete steady state phi_d', k)
        call check(abs(lag - phi) <= dth, 'lag error vs asin(gc/R) <= 2 pi/N', k)
        lag_err = max(lag_err, abs(lag - phi))
        call check_near(a%sfd, tauc*(gpr - gc), 1.0e-9_dp*tauc*(gpr - gc), &
                        'SFD = mu p (|gamma_pr| - gc)', k)
        call check_near(a%sed, tauc*gc/2, 1.0e-12_dp*tauc*gc, 'SED = tau_crit gc/2 in slip', k)
        if (mod(k, n/8) == 0) call check_tangents_fd(a0, a, gc, tauc/gc, mu, k)
      end if
    end do
    call check_near(sumtds, sumsfd, 1.0e-10_dp*sumsfd, 'sum SFD = sum tau . DSLIP', n*nturns)
    call check_near(a%statev(1), sumsfd/tauc, 1.0e-10_dp*a%statev(1), &
                    'STATEV(1) = sum SFD / (mu p) (every slip at |tau| = mu p)', n*nturns)
  end subroutine scene_f2

  ! Scene F3, the friction ellipse, the twin of c_tests/test_fric_f3.c: NFDIR = 2, mu1 = 0.5
  ! (PROPS(2)), mu2 = 0.2 (PROPS(3)), p = 100, gc = 1e-3, steady slip DGAM = 0.3 gc d per
  ! increment along d at twelve angles. Once sliding the stress is on the ellipse
  ! (tau1/mu1)^2 + (tau2/mu2)^2 = p^2 and parallel to (mu1^2 d1, mu2^2 d2), same sense; the
  ! tangents against central differences. In stick k_i = (mu_i/mubar)^2 kbar_s with
  ! mubar = sqrt((mu1^2 + mu2^2)/2), kbar_s = mubar p/gc, and SED = sum tau_i^2/(2 k_i).
  subroutine scene_f3()
    real(dp), parameter :: mu1 = 0.5_dp, mu2 = 0.2_dp, p = 100.0_dp
    real(dp), parameter :: mbar2 = (mu1**2 + mu2**2)/2
    type(fric_args) :: a, a0
    real(dp) :: angle, d(2), w(2), kbar, k1, k2
    integer :: j, inc
    kbar = sqrt(mbar2)*p/gc
    do j = 0, 11
      angle = j*pi/6 + 0.1_dp
      d = [cos(angle), sin(angle)]
      w = [mu1**2*d(1), mu2**2*d(2)]
      write (scene, '(a,f6.3)') 'F3 ellipse, angle ', angle
      a = new_point(2, [1.0_dp, mu1, mu2, 0.0_dp, gc], 'F3-ELLIPSE')
      a%press = p
      a%dpress = p
      do inc = 1, 60
        a%dgam(1:2) = 0.3_dp*gc*d
        a0 = a
        call fric_call(a)
        call check(a%lm == 0, 'LM = 0', inc)
        call check_call(a, inc)
        a%dpress = 0
      end do
      call check_near(hypot(a%tau(1)/mu1, a%tau(2)/mu2), p, 1.0e-13_dp*p, &
                      'on the ellipse (tau1/mu1)^2 + (tau2/mu2)^2 = p^2', j)
      call check_near(a%tau(1)*w(2) - a%tau(2)*w(1), 0.0_dp, 1.0e-11_dp*p*mu1**2, &
                      'tau parallel to (mu1^2 d1, mu2^2 d2)', j)
      call check(a%tau(1)*w(1) + a%tau(2)*w(2) > 0, 'tau in the sense of (mu1^2 d1, mu2^2 d2)', j)
      call check(a%statev(3) == 1, 'STATEV(3) = 1 (slip)', j)
      call check(a%sfd > 0, 'SFD > 0 in slip', j)
      call check_tangents_fd(a0, a, gc, kbar, mu1, j)
    end do

    scene = 'F3 stick stiffnesses'
    k1 = mu1**2/mbar2*kbar
    k2 = mu2**2/mbar2*kbar
    a = new_point(2, [1.0_dp, mu1, mu2, 0.0_dp, gc], 'F3-ELLIPSE')
    a%press = p
    a%dpress = p
    a%dgam(1:2) = [1.0e-5_dp, -2.0e-5_dp]
    call fric_call(a)
    call check(a%lm == 0, 'LM = 0', 0)
    call check_call(a, 0)
    call check_near(a%ddtddg(1), k1, 1.0e-13_dp*k1, 'stick k1 = (mu1/mubar)^2 kbar_s', 0)
    call check_near(a%ddtddg(4), k2, 1.0e-13_dp*k2, 'stick k2 = (mu2/mubar)^2 kbar_s', 0)
    call check(a%ddtddg(2) == 0 .and. a%ddtddg(3) == 0, 'stick DDTDDG diagonal', 0)
    call check_near(a%tau(1), k1*1.0e-5_dp, 1.0e-13_dp*k1*1.0e-5_dp, 'stick tau1 = k1 DGAM(1)', 0)
    call check_near(a%tau(2), -k2*2.0e-5_dp, 1.0e-13_dp*k2*2.0e-5_dp, 'stick tau2 = k2 DGAM(2)', 0)
    call check_near(a%sed, a%tau(1)**2/(2*k1) + a%tau(2)**2/(2*k2), &
                    1.0e-13_dp*(a%tau(1)**2/(2*k1) + a%tau(2)**2/(2*k2)), &
                    'SED = sum tau_i^2/(2 k_i)', 0)
  end subroutine scene_f3

  ! Law 1 with mu_c and gc in the first n entries of PROPS, every other one 0 (props_coulomb of
  ! c_tests/test_fric_f4.c).
  function props_coulomb(mu_c, n) result(props)
    real(dp), intent(in) :: mu_c
    integer, intent(in) :: n
    real(dp) :: props(n)
    include 'props_index.inc'
    props = 0
    props(kpc_code) = law_coulomb
    props(kpc_mu) = mu_c
    props(kpc_gamma_crit) = gc
  end function props_coulomb

  ! Tangential damping, the twin of damping in c_tests/test_fric_f4.c: mu = 0.6, gc = 1e-3,
  ! p = 50, DTIME = 0.01, c0 = PROPS(17) = 2, NSTATV = 3 + NFDIR (the damping stress kept in
  ! STATEV(4..)). First stick increment DGAM(1) = 1e-5: tau = (k_s + c0/DTIME) DGAM, the same
  ! tangent, STATEV(4) = c0/DTIME DGAM; steady sliding at v = 0.4 along d:
  ! |tau| = mu p + c0 v and SFD = (mu p + c0 v) v DTIME.
  subroutine scene_damping(nfdir)
    integer, intent(in) :: nfdir
    include 'props_index.inc'
    real(dp), parameter :: mu_s = 0.6_dp, p = 50.0_dp, dt = 0.01_dp, c0 = 2.0_dp, v = 0.4_dp
    real(dp) :: props(kpc_n), d(2), ks, teq
    type(fric_args) :: a
    integer :: k
    write (scene, '(a,i0)') 'damping, first stick increment, NFDIR=', nfdir
    props = props_coulomb(mu_s, kpc_n)
    props(kpc_damping) = c0
    ks = mu_s*p/gc
    d = [1.0_dp, 0.0_dp]
    if (nfdir == 2) d = [0.6_dp, 0.8_dp]
    a = new_point(nfdir, props, 'F4-DAMPING')
    a%nstatv = 3 + nfdir
    a%statev(4:3 + nfdir) = 0
    a%press = p
    a%dpress = p
    a%dtime = dt
    a%dgam(1:nfdir) = 0
    a%dgam(1) = 1.0e-5_dp
    call fric_call(a)
    call check_call(a, 1)
    call check_near(a%tau(1), (ks + c0/dt)*1.0e-5_dp, 1.0e-13_dp*(ks + c0/dt)*1.0e-5_dp, &
                    'stick tau = (k_s + c0/DTIME) DGAM', 1)
    call check_near(a%ddtddg(1), ks + c0/dt, 1.0e-13_dp*(ks + c0/dt), &
                    'stick DDTDDG(1,1) = k_s + c0/DTIME', 1)
    call check_near(a%statev(4), c0/dt*1.0e-5_dp, 1.0e-13_dp*c0/dt*1.0e-5_dp, &
                    'STATEV(4) = damping stress c0/DTIME DGAM', 1)
    write (scene, '(a,i0)') 'damping, steady sliding at v = 0.4, NFDIR=', nfdir
    a%dpress = 0
    do k = 1, 50
      a%dgam(1:nfdir) = v*dt*d(1:nfdir)
      call fric_call(a)
      call check_call(a, k)
    end do
    teq = sqrt(sum(a%tau(1:nfdir)**2))
    call check_near(teq, mu_s*p + c0*v, 1.0e-12_dp*(mu_s*p + c0*v), '|tau| = mu p + c0 v', 50)
    call check_near(a%sfd, (mu_s*p + c0*v)*v*dt, 1.0e-10_dp*(mu_s*p + c0*v)*v*dt, &
                    'SFD = (mu p + c0 v) v DTIME', 50)
  end subroutine scene_damping

  ! F5 with a pressure-dependent mu, the twin of f5_pressure_mu in c_tests/test_fric_f4.c:
  ! mu(p) = mu0/(1 + p/p_ref) (mu0 = 0.5, p_ref = PROPS(11) = 100), tau_max = 30, gc = 1e-3,
  ! p = 2.5, 4.5, ..., 400.5 while sliding 0.5 gc per increment along d: after five increments
  ! tau = min(mu(p) p, tau_max) d and DDTDDP = d(mu p)/dp d = mu0/(1 + p/p_ref)^2 d, 0 on the cap.
  subroutine scene_f5_pressure_mu(nfdir)
    integer, intent(in) :: nfdir
    include 'props_index.inc'
    real(dp), parameter :: mu0 = 0.5_dp, p_ref = 100.0_dp, tau_max = 30.0_dp
    real(dp) :: props(kpc_p_ref), d(2), p, p_before, mu_p, tc, slope
    type(fric_args) :: a
    integer :: k, ia
    write (scene, '(a,i0)') 'F5 pressure-dependent mu, NFDIR=', nfdir
    props = props_coulomb(mu0, kpc_p_ref)
    props(kpc_tau_max) = tau_max
    props(kpc_p_ref) = p_ref
    d = [1.0_dp, 0.0_dp]
    if (nfdir == 2) d = [0.8_dp, -0.6_dp]
    a = new_point(nfdir, props, 'F5-MU-OF-P')
    p_before = 0
    do k = 1, 200
      ! Never exactly on the cap mu(p) p = 30 (p = 150).
      p = 2.0_dp*k + 0.5_dp
      mu_p = mu0*p/(1 + p/p_ref)
      a%press = p
      a%dpress = p - p_before
      p_before = p
      a%dgam(1:nfdir) = 0.5_dp*gc*d(1:nfdir)
      call fric_call(a)
      call check_call(a, k)
      if (k > 5) then
        tc = min(mu_p, tau_max)
        slope = 0
        if (mu_p < tau_max) slope = mu0/(1 + p/p_ref)**2
        do ia = 1, nfdir
          call check_near(a%tau(ia), tc*d(ia), 1.0e-12_dp*tc + 1.0e-13_dp, &
                          'tau = min(mu(p) p, tau_max) d', k)
          call check_near(a%ddtddp(ia), slope*d(ia), 1.0e-14_dp, &
                          'DDTDDP = d(mu(p) p)/dp d, 0 on the cap', k)
        end do
      end if
    end do
  end subroutine scene_f5_pressure_mu

  ! Scene F5, pressure ramp while sliding, along a fixed direction e (NFDIR = 1; NFDIR = 2 at
  ! -40 degrees). Phase 1: first contact at p = 40 (DPRESS = 40 on the first increment, so the
  ! increment starts at p = 0), 7 increments of 0.3 gc: stick while g <= gc, then slip.
  ! Phase 2: slip 0.25 gc per increment while p ramps 40 -> 120 -> 40 in 64 + 64 increments.
  ! Closed form in slip: tau = tau_crit(p) e, DDTDDP = mu e (0 on the cap), DSLIP = h e,
  ! SFD = tau_crit(p) h, DDTDDG = (I - e e^T) tau_crit/(gc + h).
  ! With tau_max = 20 the cap mu p = tau_max is crossed at p = 66.7, never on the grid.
  subroutine scene_f5(nfdir, tmax)
    integer, intent(in) :: nfdir
    real(dp), intent(in) :: tmax
    integer, parameter :: m = 64
    real(dp), parameter :: pa = 40.0_dp, pb = 120.0_dp, h1 = 0.3_dp*gc, h2 = 0.25_dp*gc
    type(fric_args) :: a, a0
    real(dp) :: e(2), tn(2), p, pold, tauc, dtcdp, g, sp, dsp, sumsfd, sumexp, ks, ddg, tol
    integer :: k, j, ia, ib
    logical :: slips
    write (scene, '(a,i0,a,f4.1)') 'F5 ramp NFDIR=', nfdir, ' tau_max=', tmax
    a = new_point(nfdir, [1.0_dp, mu, 0.0_dp, tmax, gc], 'F5-RAMP', 0.2_dp)
    e = direction(nfdir, -40.0_dp*pi/180)
    tn = [-e(2), e(1)]
    pold = 0
    g = 0
    sp = 0
    sumsfd = 0
    sumexp = 0
    do k = 1, 7 + 2*m
      if (k <= 7) then
        p = pa
        g = g + h1
      else
        j = k - 7
        if (j <= m) then
          p = pa + (pb - pa)*(real(j, dp)/m)
        else
          p = pb - (pb - pa)*(real(j - m, dp)/m)
        end if
        g = g + h2
      end if
      call crit(p, tauc, dtcdp)
      ks = tauc/gc
      ! Closed-form slip: the elastic slip g - sp reaches gc and stays there.
      slips = g - sp > gc
      dsp = 0
      if (slips) dsp = (g - sp) - gc
      sp = sp + dsp
      a%kinc = k
      a%press = p
      a%dpress = p - pold
      a%dgam(1:nfdir) = merge(h1, h2, k <= 7)*e(1:nfdir)
      a0 = a
      call fric_call(a)
      call check(a%lm == 0, 'LM = 0', k)
      call check_call(a, k)
      tol = 1.0e-12_dp*tauc
      if (slips) then
        do ia = 1, nfdir
          call check_near(a%tau(ia), tauc*e(ia), tol, 'tau = min(mu p, tau_max) e', k)
          call check_near(a%dslip(ia), dsp*e(ia), 1.0e-12_dp*gc, 'DSLIP = slip e', k)
        end do
        if (dtcdp == 0) then
          call check(all(a%ddtddp(1:nfdir) == 0), 'DDTDDP = 0 on the cap', k)
        else
          do ia = 1, nfdir
            call check_near(a%ddtddp(ia), mu*e(ia), 1.0e-12_dp*mu, 'DDTDDP = mu n', k)
          end do
        end if
        do ib = 1, nfdir
          do ia = 1, nfdir
            ddg = 0
            if (nfdir == 2) ddg = tn(ia)*tn(ib)*tauc/(gc + dsp)
            call check_near(a%ddtddg(ia + (ib - 1)*nfdir), ddg, 1.0e-12_dp*ks, &
                            'DDTDDG = (I - n n^T) tau_crit/|gamma_pr|', k)
          end do
        end do
        call check_near(a%sfd, tauc*dsp, 1.0e-12_dp*tauc*gc, 'SFD = tau_crit dslip', k)
        call check(a%statev(3) == 1, 'STATEV(3) = 1 (slip)', k)
      else
        ! Stick branch of the law: tau = k_s(p) gamma_pr, DDTDDP = gamma_pr mu/gc.
        do ia = 1, nfdir
          call check_near(a%tau(ia), ks*(g - sp)*e(ia), tol, 'stick: tau = k_s gamma', k)
          call check_near(a%ddtddp(ia), dtcdp*(g - sp)/gc*e(ia), 1.0e-12_dp*mu, &
                          'stick: DDTDDP = gamma mu/gc', k)
          call check(a%dslip(ia) == 0, 'stick: DSLIP = 0', k)
        end do
        call check(a%sfd == 0, 'stick: SFD = 0', k)
        call check(a%statev(3) == 0, 'STATEV(3) = 0 (stick)', k)
      end if
      sumsfd = sumsfd + a%sfd
      sumexp = sumexp + tauc*dsp
      call check_tangents_fd(a0, a, gc, ks, mu, k)
      pold = p
    end do
    ! Phase 1 slips 1.1 gc at tau_crit(40); phase 2 slips h2 per increment at tau_crit(p_j).
    call check_near(sumsfd, sumexp, 1.0e-12_dp*sumexp, 'sum SFD = sum tau_crit(p_j) dslip_j', k)
    call check_near(sp, 1.1_dp*gc + 2*m*h2, 1.0e-12_dp*sp, 'closed-form slip total', k)
    call check_near(a%statev(1), sp, 1.0e-12_dp*sp, 'STATEV(1) = total slip', k)
  contains
    subroutine crit(pp, tc, dtc)
      real(dp), intent(in) :: pp
      real(dp), intent(out) :: tc, dtc
      tc = mu*pp
      dtc = mu
      if (tmax > 0 .and. tc >= tmax) then
        tc = tmax
        dtc = 0
      end if
    end subroutine crit
  end subroutine scene_f5

  ! Scene F1 with exact stick (PROPS(7) = 1) and a spring host: a spring of stiffness K pulls the
  ! slider (position gamma = g e), its other end is driven to u(t) e; u: 0 -> umax -> -umax.
  ! The host, each increment: while the point is stuck (LM = 1) it passes TAULM = K(u e - gamma);
  ! when FRIC answers LM = 0 it solves K(u e - gamma) = tau for gamma and calls again with
  ! DGAM = gamma - gamma_start until gamma and LM repeat.
  ! Closed form (mu p = 30, mu p/K = 2e-3): no motion until K u = mu p, then g = u - mu p/K;
  ! on reversal stuck at gmax = umax - mu p/K until K(u - gmax) = -mu p, then g = u + mu p/K.
  ! Total slip 3 (umax - mu p/K); dissipation mu p times that.
  subroutine scene_spring(nfdir)
    integer, intent(in) :: nfdir
    integer, parameter :: n1 = 48
    real(dp), parameter :: p = 100.0_dp, spring = 1.5e4_dp, umax = 1.0e-2_dp
    type(fric_args) :: a, a0, afin
    real(dp) :: e(2), u, uold, gvec(2), gstart(2), gtrial(2), gnew(2), taustart(2), tauc
    real(dp) :: g, gprev, gmax, sumsfd, force
    integer :: k, it, lmflag, ncalls
    logical :: stuck, converged
    write (scene, '(a,i0)') 'F1 exact stick, spring host NFDIR=', nfdir
    a = new_point(nfdir, [1.0_dp, mu, 0.0_dp, 0.0_dp, gc, 0.0_dp, 1.0_dp], 'F1-SPRING', 0.2_dp)
    a%press = p
    a%dpress = 0
    tauc = mu*p
    e = direction(nfdir, 30.0_dp*pi/180)
    gmax = umax - tauc/spring
    gvec = 0
    uold = 0
    gprev = 0
    sumsfd = 0
    lmflag = 1
    do k = 1, 3*n1
      if (k <= n1) then
        u = umax*(real(k, dp)/n1)
        stuck = spring*u <= tauc
        g = max(0.0_dp, u - tauc/spring)
      else
        u = umax*(real(2*n1 - k, dp)/n1)
        stuck = spring*(u - gmax) >= -tauc
        g = min(gmax, u + tauc/spring)
      end if
      a%kinc = k
      gstart = gvec
      ! The start-of-increment stress: the spring force of the converged previous increment.
      taustart = spring*(uold*e - gstart)
      gtrial = u*e - taustart/spring
      converged = .false.
      ncalls = 0
      do it = 1, 6
        a%tau(1:nfdir) = taustart(1:nfdir)
        a%lm = lmflag
        if (lmflag == 1) then
          a%taulm(1:nfdir) = spring*(u*e(1:nfdir) - gstart(1:nfdir))
          a%dgam(1:nfdir) = 0
        else
          a%taulm = sentinel
          a%dgam(1:nfdir) = gtrial(1:nfdir) - gstart(1:nfdir)
        end if
        a0 = a
        call fric_call(a)
        ncalls = ncalls + 1
        call check_call(a, k)
        if (a%lm == 1) then
          ! Exact stick: TAU, DDTDDG, DDTDDP not written; DSLIP = SED = SFD = 0.
          call check(all(a%tau(1:nfdir) == taustart(1:nfdir)), 'LM = 1: TAU not written', k)
          call check(all(a%ddtddg == sentinel) .and. all(a%ddtddp == sentinel), &
                     'LM = 1: DDTDDG, DDTDDP not written', k)
          call check(all(a%dslip(1:nfdir) == 0) .and. a%sed == 0 .and. a%sfd == 0, &
                     'LM = 1: DSLIP = SED = SFD = 0', k)
          call check(a%statev(3) == 2, 'LM = 1: STATEV(3) = 2', k)
          if (lmflag == 1) then
            gvec = gstart
            converged = .true.
            afin = a
            exit
          end if
          lmflag = 1
        else
          call check(a%lm == 0, 'LM out is 0 or 1', k)
          gnew = u*e - a%tau(1:2)/spring
          if (nfdir == 1) gnew(2) = 0
          if (lmflag == 0 .and. all(abs(gnew - gtrial) <= 1.0e-14_dp*umax)) then
            gvec = gtrial
            converged = .true.
            afin = a
            ! Slip tangents against finite differences of this converged call.
            call check_tangents_fd(a0, a, gc, tauc/maxval(abs(a%dgam(1:nfdir))), mu, k)
            exit
          end if
          lmflag = 0
          gtrial = gnew
        end if
      end do
      call check(converged .and. ncalls <= 3, 'host converges within 3 FRIC calls', k)
      if (.not. converged) exit
      call check(afin%lm == merge(1, 0, stuck), 'LM = 1 exactly while stuck', k)
      call check_near(dot_product(gvec, e), g, 1.0e-12_dp*umax, 'slider position g(u)', k)
      call check_near(gvec(1)*e(2) - gvec(2)*e(1), 0.0_dp, 1.0e-12_dp*umax, &
                      'slider moves along the pull', k)
      force = dot_product(spring*(u*e - gvec), e)
      if (stuck) then
        call check(all(gvec == gstart), 'stuck: no motion at all', k)
        call check(abs(force) <= tauc, 'stuck: |K(u - g)| <= mu p', k)
      else
        call check_near(abs(force), tauc, 1.0e-12_dp*tauc, 'slipping: spring force = mu p', k)
        ! To round-off, not bit for bit: the library forms n = DGAM*(1/|DGAM|), which is
        ! 1 ulp short of +-1 for some DGAM even when NFDIR = 1.
        call check_near(dot_product(afin%tau(1:nfdir), e(1:nfdir)), sign(tauc, g - gprev), &
                        1.0e-13_dp*tauc, 'slipping: tau = mu p along the motion', k)
        call check(all(afin%dslip(1:nfdir) == afin%dgam(1:nfdir)), 'slipping: DSLIP = DGAM', k)
        call check_near(afin%sfd, tauc*abs(g - gprev), 1.0e-12_dp*tauc*umax, &
                        'slipping: SFD = mu p |dg|', k)
        call check(afin%sed == 0, 'exact stick: SED = 0', k)
        call check(afin%statev(3) == 1, 'slipping: STATEV(3) = 1', k)
      end if
      sumsfd = sumsfd + afin%sfd
      uold = u
      gprev = g
    end do
    call check_near(sumsfd, tauc*3*(umax - tauc/spring), 1.0e-12_dp*tauc*umax, &
                    'sum SFD = mu p 3 (umax - mu p/K)', 3*n1)
    call check_near(a%statev(1), 3*(umax - tauc/spring), 1.0e-12_dp*umax, &
                    'STATEV(1) = 3 (umax - mu p/K)', 3*n1)
  end subroutine scene_spring
end module scenes

program test_fric_scenes
  use scenes
  implicit none
  real(dp) :: err1000, err5000
  integer :: nfdir
  call scene_f2(1000, 3, err1000)
  call scene_f2(5000, 3, err5000)
  ! First order: the lag error falls by the step ratio 5 (phi_d - phi = dth/2 + O(dth^2)).
  scene = 'F2 convergence'
  call check(err1000/err5000 > 4.5_dp .and. err1000/err5000 < 5.5_dp, &
             'lag error first order in the step: err(1000)/err(5000) ~ 5', 0)
  call scene_f3()
  do nfdir = 1, 2
    call scene_f5(nfdir, 0.0_dp)
    call scene_f5(nfdir, 20.0_dp)
    call scene_spring(nfdir)
    call scene_damping(nfdir)
    call scene_f5_pressure_mu(nfdir)
  end do
  call finish()
end program test_fric_scenes
