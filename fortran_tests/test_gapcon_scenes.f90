! test_gapcon_scenes.f90 -- scenes T1 (two bars, temperature-dependent gap conductance) and T2
! (radiating gap) from free-form Fortran. GAPCON is called the way a user's own Fortran 90 host
! would: a plain `call gapcon(...)` with the 15 Abaqus arguments and no interface block. The
! native C function ifl_gap_conductance (derivatives GAPCON cannot return) and the last error
! are called through the ISO_C_BINDING interfaces of harness_tally.
!
! Scenario (docs/scene-definitions.md, T1/T2; laws from configs/gapcon_good.toml, named by CTest's
! INTERFACIAL_CONFIG): bar A (L_A = 0.1, k_A = 50) held at theta_H = 400, bar B (L_B = 0.2,
! k_B = 15) at theta_C = 300, gap between the interface temperatures theta_A and theta_B.
!
! Every assertion is a closed form (scenes.md; the formulas of docs/config.md), an independent
! computation (central finite differences of the library's own k; a bisection that never calls
! the library), or an invariant (AK(2..5) untouched; GAPCON and ifl_gap_conductance agree).
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

! The host side: scene constants, one GAPCON call as Abaqus makes it, one native call.
module gapcon_host
  ! The tally: check and check_near here take the increment or point number K.
  use harness_tally, only: dp, finish, scene, check => check_at, check_near => check_abs_at, &
    last_error, ifl_conductance, ifl_gap_conductance
  use, intrinsic :: iso_c_binding, only: c_int, c_null_char
  implicit none
  integer(c_int), parameter :: ifl_status_ok = 0 ! IFL_STATUS_OK of include/interfacial.h
  real(dp), parameter :: l_a = 0.1_dp, k_a = 50.0_dp, l_b = 0.2_dp, k_b = 15.0_dp
  real(dp), parameter :: theta_h = 400.0_dp, theta_c = 300.0_dp
  ! Bar conductances k/L and the series resistance of both bars.
  real(dp), parameter :: g_a = k_a/l_a, g_b = k_b/l_b, r_bars = l_a/k_a + l_b/k_b
  ! Radiation of RADK, RADC, GASRAD; gas gap of GASRAD.
  real(dp), parameter :: f_view = 0.8_dp, sigma_sb = 5.670374419e-8_dp
  real(dp), parameter :: k_gas = 0.026_dp, g0 = 1.0e-5_dp, min_gap = 1.0e-6_dp
  ! T1GAS (gas gap) and T1CMY, T1CMY_C1 (cmy with c = 1.25 and 1), as c_gapcon_t1's.
  real(dp), parameter :: t1_k_gas = 0.03_dp, t1_g0 = 2.0e-5_dp, t1_min_gap = 1.0e-5_dp
  real(dp), parameter :: cmy_ks = 2*k_a*k_b/(k_a + k_b), cmy_m = 0.1_dp, cmy_sigma = 2.0e-6_dp
  real(dp), parameter :: cmy_hc = 1.5e9_dp
  real(dp), parameter :: kelvin_zero = 0.0_dp, celsius_zero = -273.15_dp
  real(dp), parameter :: sentinel = -999.25_dp
  integer :: npoint = 0
contains

  ! AK(1) from a plain CALL GAPCON: AK preset to a sentinel (AK(1) must be written, AK(2..5)
  ! must survive), the arguments GAPCON does not read hold harmless values.
  function gapcon_ak1(name, d, p, theta_a, theta_b) result(ak1)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: d, p, theta_a, theta_b
    real(dp) :: ak1
    real(dp) :: ak(5), dd(2), flowm(2), temp(2), predef(2, 1), time(2), coords(3)
    character(len=80) :: ciname, slname, msname
    integer :: noel, node, npred, kstep, kinc
    npoint = npoint + 1
    ak = sentinel
    dd = [d, p]
    flowm = 0
    temp = [theta_a, theta_b]
    predef = 0
    time = 1
    coords = 0
    ciname = name
    slname = 'BAR-A-END'
    msname = 'BAR-B-END'
    noel = npoint
    node = 7
    npred = 1
    kstep = 1
    kinc = 1
    call gapcon(ak, dd, flowm, temp, predef, time, ciname, slname, msname, coords, noel, node, &
                npred, kstep, kinc)
    call check(ak(1) /= sentinel, 'AK(1) written', npoint)
    call check(all(ak(2:5) == sentinel), 'AK(2..5) untouched', npoint)
    ak1 = ak(1)
  end function gapcon_ak1

  ! k and its derivatives from ifl_gap_conductance, which must succeed.
  function native(name, d, p, theta_a, theta_b) result(c)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: d, p, theta_a, theta_b
    type(ifl_conductance) :: c
    integer(c_int) :: status
    status = ifl_gap_conductance(trim(name)//c_null_char, d, p, theta_a, theta_b, c)
    call check(status == ifl_status_ok, 'ifl_gap_conductance returns IFL_STATUS_OK', npoint)
    if (status /= ifl_status_ok) call print_last_error()
  end function native

  ! Both entry points at one point: they must give the same k (one law behind both).
  function both(name, d, p, theta_a, theta_b) result(c)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: d, p, theta_a, theta_b
    type(ifl_conductance) :: c
    real(dp) :: ak1
    ak1 = gapcon_ak1(name, d, p, theta_a, theta_b)
    c = native(name, d, p, theta_a, theta_b)
    call check(ak1 == c%k, 'GAPCON AK(1) = ifl_gap_conductance k', npoint)
  end function both

  subroutine print_last_error()
    write (*, '(2a)') '   last error: ', trim(last_error())
  end subroutine print_last_error

  ! The host's Newton on the two-bar residual
  !   R1 = G_A (theta_H - theta_A) - q,  R2 = q - G_B (theta_B - theta_C),
  ! q = k (theta_A - theta_B), from theta_A = th, theta_B = tc (the bars' far-end temperatures,
  ! shifted for a Celsius model). With `exact` the flux derivatives of ifl_gap_conductance are
  ! used; without, the tangent a GAPCON-only host has: dq/dtheta_A = k = -dq/dtheta_B.
  ! err(0:nit): max-norm error against (ta_ref, tb_ref); nit: updates until err <= tol (0 if
  ! never within size(err) - 1).
  subroutine newton(name, d, p, th, tc, exact, ta_ref, tb_ref, tol, ta, tb, err, nit)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: d, p, th, tc, ta_ref, tb_ref, tol
    logical, intent(in) :: exact
    real(dp), intent(out) :: ta, tb, err(0:)
    integer, intent(out) :: nit
    type(ifl_conductance) :: c
    real(dp) :: q, r1, r2, dqa, dqb, a11, a12, a21, a22, det, da, db
    integer :: it
    ta = th
    tb = tc
    err = -1
    err(0) = max(abs(ta - ta_ref), abs(tb - tb_ref))
    nit = 0
    do it = 1, ubound(err, 1)
      c = both(name, d, p, ta, tb)
      q = c%k*(ta - tb)
      r1 = g_a*(th - ta) - q
      r2 = q - g_b*(tb - tc)
      if (exact) then
        dqa = c%dq_dtheta_a
        dqb = c%dq_dtheta_b
      else
        dqa = c%k
        dqb = -c%k
      end if
      a11 = -g_a - dqa
      a12 = -dqb
      a21 = dqa
      a22 = dqb - g_b
      det = a11*a22 - a12*a21
      da = (-r1*a22 + a12*r2)/det
      db = (-a11*r2 + a21*r1)/det
      ta = ta + da
      tb = tb + db
      err(it) = max(abs(ta - ta_ref), abs(tb - tb_ref))
      if (err(it) <= tol) then
        nit = it
        exit
      end if
    end do
  end subroutine newton
end module gapcon_host

module gapcon_scenes
  use gapcon_host
  implicit none
contains

  ! Scene T1 with T1TEMP at p = 50. Table rows [p, k, theta_mean]:
  !   [0, 500, 300], [100, 1500, 300], [0, 900, 400], [100, 2500, 400]
  ! so by hand at p = 50: h(300) = 1000, h(400) = 1700, h(tm) = h3 + s (tm - 300) between,
  ! dh/dtm = s = 7, dh/dp = (1 - w) 10 + w 16 with w = (tm - 300)/100.
  ! The exact steady state: with tm = (theta_H + theta_C)/2 + q (L_B/k_B - L_A/k_A)/2, h is
  ! linear in q, h = a + b q, and q (R0 + 1/h) = dT gives R0 b q^2 + (R0 a + 1 - dT b) q - dT a = 0.
  ! q is quadratic in (theta_A, theta_B) on this table segment, so Newton with the seed's
  ! derivatives (seed 000, 5.2.4) converges quadratically: e_{k+1} <= M e_k^2; without dh/dtm
  ! it converges only linearly, and e_{k+1}/e_k^2 grows without bound.
  subroutine scene_t1temp()
    real(dp), parameter :: p = 50.0_dp, tol = 1.0e-10_dp
    ! Bound on e_{k+1}/e_k^2 (1/K). For quadratic q, Newton's error is exactly J^-1 Q(e, e) with
    ! |Q(e, e)| <= 2 s e^2 and |J^-1| of order 1/G_B, so M of order 2 s/G_B ~ 0.2; 1 leaves
    ! room and still fails a linear method as soon as e_k < its rate.
    real(dp), parameter :: m_bound = 1.0_dp
    integer, parameter :: maxit = 60
    real(dp) :: h3, h4, s, a, b, qa, qb, qc, qs, tas, tbs, ta, tb, tm, w, hstar
    real(dp) :: en(0:maxit), eq(0:maxit), ratio, worst_newton, worst_quasi
    real(dp) :: delta, hx, jq11, jq12, jq21, jq22, det, u1, u2, lambda
    type(ifl_conductance) :: c
    integer :: nn, nq, k, nratio
    scene = 'T1 T1TEMP p=50'
    h3 = 500 + (1500.0_dp - 500)*(p - 0)/100
    h4 = 900 + (2500.0_dp - 900)*(p - 0)/100
    s = (h4 - h3)/(400.0_dp - 300)
    a = h3 + s*((theta_h + theta_c)/2 - 300)
    b = s*(l_b/k_b - l_a/k_a)/2
    qa = r_bars*b
    qb = r_bars*a + 1 - (theta_h - theta_c)*b
    qc = (theta_h - theta_c)*a
    qs = 2*qc/(qb + sqrt(qb*qb + 4*qa*qc))
    tas = theta_h - qs/g_a
    tbs = theta_c + qs/g_b
    tm = (tas + tbs)/2
    call check(tm > 300 .and. tm < 400, 'exact mean temperature inside the table (300, 400)', 0)

    call newton('T1TEMP', 0.0_dp, p, theta_h, theta_c, .true., tas, tbs, tol, ta, tb, en, nn)
    call check(nn > 0 .and. nn <= 6, 'Newton with dh/dtm converges within 6 updates', nn)
    hstar = h3 + s*((ta + tb)/2 - 300)
    call check_near(gapcon_ak1('T1TEMP', 0.0_dp, p, ta, tb)*(ta - tb), &
                    (theta_h - theta_c)/(r_bars + 1/hstar), 1.0e-10_dp*qs, &
                    'q = dT/(L_A/k_A + 1/h* + L_B/k_B), h* at the converged mean', nn)
    call check_near(g_a*(theta_h - ta), qs, 1.0e-10_dp*qs, 'bar A flux = exact q', nn)
    call check_near(g_b*(tb - theta_c), qs, 1.0e-10_dp*qs, 'bar B flux = exact q', nn)

    call newton('T1TEMP', 0.0_dp, p, theta_h, theta_c, .false., tas, tbs, tol, ta, tb, eq, nq)
    call check(nq > 0, 'Newton without dh/dtm still converges (linearly)', nq)
    call check(nq > nn, 'without dh/dtm: more updates', nq)

    write (*, '(a)') '  T1 T1TEMP p = 50, max-norm error of (theta_A, theta_B) in K'
    write (*, '(a)') '    k   with dh/dtm (Newton)   e_k/e_{k-1}^2    without dh/dtm    e_k/e_{k-1}'
    do k = 0, max(nn, nq)
      write (*, '(i5)', advance='no') k
      if (k <= nn) then
        if (k == 0) then
          write (*, '(1p,e22.6,a16)', advance='no') en(k), ''
        else
          write (*, '(1p,e22.6,e16.3)', advance='no') en(k), en(k)/en(k - 1)**2
        end if
      else
        write (*, '(a38)', advance='no') ''
      end if
      if (k <= nq) then
        if (k == 0) then
          write (*, '(1p,e18.6)') eq(k)
        else
          write (*, '(1p,e18.6,e14.3)') eq(k), eq(k)/eq(k - 1)
        end if
      else
        write (*, '(a)') ''
      end if
    end do

    ! Quadratic: e_k/e_{k-1}^2 bounded while e_k is above round-off (1e-11 K).
    worst_newton = 0
    nratio = 0
    do k = 1, nn
      if (en(k) > 1.0e-11_dp) then
        ratio = en(k)/en(k - 1)**2
        worst_newton = max(worst_newton, ratio)
        nratio = nratio + 1
        call check(ratio <= m_bound, 'with dh/dtm: e_{k+1}/e_k^2 <= M (quadratic)', k)
      end if
    end do
    call check(nratio >= 2, 'at least two error ratios above round-off', nratio)
    ! The same measure on the linear method has to exceed the bound: the check has teeth.
    worst_quasi = 0
    do k = 1, nq
      if (eq(k) > 1.0e-11_dp) worst_quasi = max(worst_quasi, eq(k)/eq(k - 1)**2)
    end do
    call check(worst_quasi > m_bound, 'without dh/dtm: e_{k+1}/e_k^2 exceeds M (linear only)', nq)
    ! Without dh/dtm the error contracts by a fixed factor, known in closed form: the error map
    ! is I - Jq^-1 Je = Jq^-1 (Jq - Je), where Jq - Je = delta [1 1; -1 -1], delta =
    ! s (theta_A - theta_B)/2, is rank one; its non-zero eigenvalue is
    ! lambda = delta (1, 1) . Jq^-1 (1, -1), Jq = [-G_A - h, h; h, -h - G_B] at the solution.
    delta = s*(tas - tbs)/2
    hx = h3 + s*(tm - 300)
    jq11 = -g_a - hx
    jq12 = hx
    jq21 = hx
    jq22 = -hx - g_b
    det = jq11*jq22 - jq12*jq21
    u1 = (jq22 + jq12)/det
    u2 = (-jq11 - jq21)/det
    lambda = abs(delta*(u1 + u2))
    nratio = 0
    do k = 2, nq
      if (eq(k) > 1.0e-9_dp) then
        nratio = nratio + 1
        call check_near(eq(k)/eq(k - 1), lambda, 0.01_dp*lambda, &
                        'without dh/dtm: e_{k+1}/e_k = closed-form linear rate lambda', k)
      end if
    end do
    call check(nratio >= 2, 'at least two linear-rate ratios above round-off', nratio)
    write (*, '(a,i0,a,i0,a,1p,e10.3,a,e10.3,a,e9.2,a,e11.4)') '    updates: ', nn, ' vs ', nq, &
      '; max e_{k+1}/e_k^2: ', worst_newton, ' vs ', worst_quasi, '; M = ', m_bound, &
      '; predicted linear rate ', lambda

    ! The seed's derivatives by hand along the way (any point inside the segment).
    ta = 395.0_dp
    tb = 371.0_dp
    tm = (ta + tb)/2
    w = (tm - 300)/100
    c = both('T1TEMP', 0.0_dp, p, ta, tb)
    call check_near(c%k, h3 + s*(tm - 300), 1.0e-13_dp*c%k, 'k = bilinear table value', 1)
    call check_near(c%dk_dtheta_mean, s, 1.0e-13_dp*s, 'dk/dtm = (h(400) - h(300))/100', 1)
    call check_near(c%dk_dp, (1 - w)*(1500.0_dp - 500)/100 + w*(2500.0_dp - 900)/100, 1.0e-13_dp, &
                    'dk/dp = table slope at tm', 1)
    call check(c%dk_dd == 0, 'dk/dd = 0 (pressure table)', 1)
    call check_near(c%dq_dtheta_a, c%k + s*(ta - tb)/2, 1.0e-13_dp*c%k, &
                    'dq/dtheta_A = h + (dh/dtm)(theta_A - theta_B)/2', 1)
    call check_near(c%dq_dtheta_b, -c%k + s*(ta - tb)/2, 1.0e-13_dp*c%k, &
                    'dq/dtheta_B = -h + (dh/dtm)(theta_A - theta_B)/2', 1)
    call fd_derivatives('T1TEMP', 0.0_dp, p, ta, tb, 0.0_dp, 1.0e-3_dp, 1.0e-3_dp, 1)
  end subroutine scene_t1temp

  ! Central finite differences of ifl_gap_conductance's k (q = k (theta_A - theta_B)) against
  ! its derivatives. Steps hd (clearance), hp (pressure), ht (temperatures); 0 skips one.
  ! The derivative must match to 1e-7 of its own size or of scale, whichever is larger.
  subroutine fd_derivatives(name, d, p, ta, tb, hd, hp, ht, k)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: d, p, ta, tb, hd, hp, ht
    integer, intent(in) :: k
    type(ifl_conductance) :: c, cp, cm
    real(dp) :: fd, qp, qm
    c = native(name, d, p, ta, tb)
    cp = native(name, d, p, ta + ht, tb)
    cm = native(name, d, p, ta - ht, tb)
    qp = cp%k*(ta + ht - tb)
    qm = cm%k*(ta - ht - tb)
    fd = (qp - qm)/(2*ht)
    call check_near(c%dq_dtheta_a, fd, 1.0e-7_dp*max(abs(fd), c%k), &
                    'dq/dtheta_A = central FD of k (theta_A - theta_B)', k)
    cp = native(name, d, p, ta, tb + ht)
    cm = native(name, d, p, ta, tb - ht)
    qp = cp%k*(ta - tb - ht)
    qm = cm%k*(ta - tb + ht)
    fd = (qp - qm)/(2*ht)
    call check_near(c%dq_dtheta_b, fd, 1.0e-7_dp*max(abs(fd), c%k), &
                    'dq/dtheta_B = central FD of k (theta_A - theta_B)', k)
    cp = native(name, d, p, ta + ht, tb + ht)
    cm = native(name, d, p, ta - ht, tb - ht)
    fd = (cp%k - cm%k)/(2*ht)
    call check_near(c%dk_dtheta_mean, fd, 1.0e-7_dp*max(abs(fd), c%k/abs(ta)), &
                    'dk/dtm = central FD of k at fixed theta_A - theta_B', k)
    if (hp > 0) then
      cp = native(name, d, p + hp, ta, tb)
      cm = native(name, d, p - hp, ta, tb)
      fd = (cp%k - cm%k)/(2*hp)
      call check_near(c%dk_dp, fd, 1.0e-7_dp*max(abs(fd), c%k/max(abs(p), 1.0_dp)), &
                      'dk/dp = central FD of k', k)
    end if
    if (hd > 0) then
      cp = native(name, d + hd, p, ta, tb)
      cm = native(name, d - hd, p, ta, tb)
      fd = (cp%k - cm%k)/(2*hd)
      call check_near(c%dk_dd, fd, 1.0e-7_dp*max(abs(fd), c%k/d), 'dk/dd = central FD of k', k)
    end if
  end subroutine fd_derivatives

  ! Scene T1's gas-gap and cmy regimes, the twin of gas_gap_and_cmy in c_tests/test_gapcon_t1.c.
  ! Gas gap: k = k_gas/(max(d, min_gap) + g0), dk/dd = -k_gas/(d + g0)^2 above min_gap and 0
  ! below (the gap taken as min_gap: k exactly constant in d there), dk/dp = dk/dtm = 0. cmy:
  ! k = c (k_s m/sigma)(p/H_c)^0.95 with c = 1.25 (T1CMY) or 1 (T1CMY_C1), dk/dp = 0.95 k/p,
  ! dk/dd = dk/dtm = 0; k = dk/dp = 0 for p <= 0. Derivatives also against central differences.
  subroutine scene_t1_gas_cmy()
    real(dp), parameter :: gaps(4) = [1.0e-4_dp, 3.0e-5_dp, 2.0e-3_dp, 1.5e-5_dp]
    real(dp), parameter :: closed(3) = [5.0e-6_dp, 0.0_dp, -1.0e-4_dp]
    real(dp), parameter :: pressures(4) = [1.0e6_dp, 3.0e5_dp, 2.0e8_dp, 1.0_dp]
    real(dp), parameter :: nonpositive(2) = [0.0_dp, -5.0e5_dp]
    type(ifl_conductance) :: c, cp, cm
    real(dp) :: d, p, h, hd
    integer :: i
    do i = 1, size(gaps)
      d = gaps(i)
      write (scene, '(a,es10.3)') 'T1 gas gap at d =', d
      call gas_gap_point(d, t1_k_gas/(d + t1_g0), -t1_k_gas/(d + t1_g0)**2, 1.0e-4_dp*d, i)
    end do
    do i = 1, size(closed)
      d = closed(i)
      write (scene, '(a,es10.3,a)') 'T1 gas gap at d =', d, ' (below min_gap)'
      call gas_gap_point(d, t1_k_gas/(t1_min_gap + t1_g0), 0.0_dp, 0.0_dp, i)
      hd = 1.0e-3_dp*(t1_min_gap - 5.0e-6_dp)
      c = native('T1GAS', d, 40.0_dp, 300.0_dp, 280.0_dp)
      cp = native('T1GAS', d + hd, 40.0_dp, 300.0_dp, 280.0_dp)
      cm = native('T1GAS', d - hd, 40.0_dp, 300.0_dp, 280.0_dp)
      call check(cp%k == c%k .and. cm%k == c%k, 'T1GAS: k exactly constant in d below min_gap', i)
    end do
    do i = 1, size(pressures)
      p = pressures(i)
      write (scene, '(a,es10.3)') 'T1 cmy at p =', p
      h = 1.25_dp*(cmy_ks*cmy_m/cmy_sigma)*(p/cmy_hc)**0.95_dp
      c = both('T1CMY', 1.0e-4_dp, p, 300.0_dp, 280.0_dp)
      call check_near(c%k, h, 1.0e-14_dp*h, 'T1CMY: k = 1.25 (k_s m/sigma)(p/H_c)^0.95', i)
      call check_near(c%dk_dp, 0.95_dp*h/p, 1.0e-14_dp*0.95_dp*h/p, 'T1CMY: dk/dp = 0.95 k/p', i)
      call check(c%dk_dd == 0, 'T1CMY: dk/dd = 0', i)
      call check(c%dk_dtheta_mean == 0, 'T1CMY: dk/dtm = 0', i)
      call fd_derivatives('T1CMY', 1.0e-4_dp, p, 300.0_dp, 280.0_dp, 1.0e-6_dp, 1.0e-5_dp*p, &
                          0.5_dp, i)
      c = both('T1CMY_C1', 1.0e-4_dp, p, 300.0_dp, 280.0_dp)
      call check_near(c%k, h/1.25_dp, 1.0e-14_dp*h, 'T1CMY_C1: c = 1 gives k/1.25', i)
    end do
    do i = 1, size(nonpositive)
      p = nonpositive(i)
      write (scene, '(a,es10.3)') 'T1 cmy at p =', p
      c = both('T1CMY', 1.0e-4_dp, p, 300.0_dp, 280.0_dp)
      call check(c%k == 0 .and. c%dk_dp == 0, 'T1CMY: k = dk/dp = 0 for p <= 0', i)
    end do
  contains
    ! T1GAS at gap d against its closed form: k and dk/dd as given, dk/dp = dk/dtm = 0, and the
    ! derivatives against central differences (of d only where hd > 0).
    subroutine gas_gap_point(d, k, dkdd, hd, n)
      real(dp), intent(in) :: d, k, dkdd, hd
      integer, intent(in) :: n
      type(ifl_conductance) :: c
      c = both('T1GAS', d, 40.0_dp, 300.0_dp, 280.0_dp)
      call check_near(c%k, k, 1.0e-15_dp*k, 'T1GAS: k = k_gas/(max(d, min_gap) + g0)', n)
      call check_near(c%dk_dd, dkdd, 1.0e-14_dp*abs(dkdd), &
                      'T1GAS: dk/dd = -k_gas/(d + g0)^2 above min_gap, else 0', n)
      call check(c%dk_dp == 0, 'T1GAS: dk/dp = 0', n)
      call check(c%dk_dtheta_mean == 0, 'T1GAS: dk/dtm = 0', n)
      call fd_derivatives('T1GAS', d, 40.0_dp, 300.0_dp, 280.0_dp, hd, 1.0_dp, 0.5_dp, n)
    end subroutine gas_gap_point
  end subroutine scene_t1_gas_cmy

  ! Scene T2 at imposed surface temperatures: AK(1) (theta_A - theta_B) must be the radiated
  ! flux F sigma ((theta_A - theta_Z)^4 - (theta_B - theta_Z)^4), plus gas conduction
  ! k_gas/(max(d, min_gap) + g0) (theta_A - theta_B) for GASRAD; AK(1) itself is
  ! F sigma (a + b)(a^2 + b^2) + k_gas/(...), with no 0/0 at theta_A = theta_B (4 F sigma a^3).
  ! Temperatures are given in kelvin; RADC gets them in Celsius and must give the same k.
  subroutine scene_t2_points()
    real(dp), parameter :: pts(2, 7) = reshape([600.0_dp, 300.0_dp, 300.0_dp, 600.0_dp, &
                                                450.0_dp, 450.0_dp, 1000.0_dp, 20.0_dp, &
                                                300.0_dp, 0.0_dp, 2000.0_dp, 1999.999_dp, &
                                                0.0_dp, 0.0_dp], [2, 7])
    real(dp), parameter :: gaps(3) = [1.0e-4_dp, 5.0e-7_dp, 0.0_dp]
    real(dp) :: tk(2), a, b, fs, krad, kgas, qhand, ak_k, ak_c, ak_g, tol
    integer :: i, j
    fs = f_view*sigma_sb
    do i = 1, size(pts, 2)
      write (scene, '(a,f8.3,a,f8.3)') 'T2 theta_A=', pts(1, i), ' theta_B=', pts(2, i)
      tk = pts(:, i)
      a = tk(1) - kelvin_zero
      b = tk(2) - kelvin_zero
      krad = fs*(a + b)*(a*a + b*b)
      qhand = fs*(a**4 - b**4)
      ak_k = gapcon_ak1('RADK', 1.0e-3_dp, 0.0_dp, tk(1), tk(2))
      call check_near(ak_k, krad, 1.0e-14_dp*krad, 'RADK: AK(1) = F sigma (a + b)(a^2 + b^2)', i)
      tol = 1.0e-13_dp*fs*(a**4 + b**4)
      call check_near(ak_k*(tk(1) - tk(2)), qhand, tol, &
                      'RADK: AK(1)(theta_A - theta_B) = F sigma (a^4 - b^4)', i)
      if (a == b) call check_near(ak_k, 4*fs*a**3, 1.0e-14_dp*krad, &
                                  'RADK: theta_A = theta_B gives 4 F sigma a^3', i)
      ! The same physical temperatures in degrees Celsius.
      ak_c = gapcon_ak1('RADC', 1.0e-3_dp, 0.0_dp, tk(1) + celsius_zero, tk(2) + celsius_zero)
      a = (tk(1) + celsius_zero) - celsius_zero
      b = (tk(2) + celsius_zero) - celsius_zero
      call check_near(ak_c, fs*(a + b)*(a*a + b*b), 1.0e-14_dp*krad, &
                      'RADC: AK(1) = F sigma (a + b)(a^2 + b^2), a = theta_A + 273.15', i)
      call check_near(ak_c*(tk(1) - tk(2)), qhand, tol + 1.0e-12_dp*fs*(a**4 + b**4), &
                      'RADC (Celsius) radiates the same flux as RADK (kelvin)', i)
      ! Gas gap plus radiation: open (k_gas/(d + g0)), below min_gap and closed (min_gap).
      do j = 1, size(gaps)
        kgas = k_gas/(max(gaps(j), min_gap) + g0)
        ak_g = gapcon_ak1('GASRAD', gaps(j), 0.0_dp, tk(1), tk(2))
        call check_near(ak_g, kgas + krad, 1.0e-14_dp*(kgas + krad), &
                        'GASRAD: AK(1) = k_gas/(max(d, min_gap) + g0) + radiation', 10*i + j)
        call check_near(ak_g*(tk(1) - tk(2)), kgas*(tk(1) - tk(2)) + qhand, &
                        tol + 1.0e-14_dp*kgas*abs(tk(1) - tk(2)), &
                        'GASRAD: flux = gas conduction + F sigma (a^4 - b^4)', 10*i + j)
      end do
    end do

    ! Derivatives: closed forms and central finite differences.
    scene = 'T2 derivatives'
    do i = 1, 4
      tk = pts(:, i)
      a = tk(1)
      b = tk(2)
      call check_derivatives('RADK', 1.0e-3_dp, tk(1), tk(2), a, b, 0.0_dp, i)
      call check_derivatives('RADC', 1.0e-3_dp, tk(1) + celsius_zero, tk(2) + celsius_zero, a, b, &
                             0.0_dp, i)
      call check_derivatives('GASRAD', 1.0e-4_dp, tk(1), tk(2), a, b, &
                             -k_gas/(1.0e-4_dp + g0)**2, i)
      ! Closed gaps (below min_gap, touching, overlapping) as the C twin's: the gap is taken as
      ! min_gap, so dk/dd = 0, and dk/dp = 0, dk/dtm the radiation's alone.
      call check_derivatives('GASRAD', 5.0e-7_dp, tk(1), tk(2), a, b, 0.0_dp, i)
      call check_derivatives('GASRAD', 0.0_dp, tk(1), tk(2), a, b, 0.0_dp, i)
      call check_derivatives('GASRAD', -1.0e-4_dp, tk(1), tk(2), a, b, 0.0_dp, i)
    end do
  contains
    ! Radiation: dq/dtheta_A = 4 F sigma a^3, dq/dtheta_B = -4 F sigma b^3 (exact), and with
    ! a = m + D/2, b = m - D/2: k = F sigma (4 m^3 + m D^2), dk/dm = F sigma (12 m^2 + D^2).
    ! The gas part adds k_gas/(d + g0) (no temperature dependence) and dk/dd = dkdd.
    subroutine check_derivatives(name, d, ta, tb, aa, bb, dkdd, k)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: d, ta, tb, aa, bb, dkdd
      integer, intent(in) :: k
      type(ifl_conductance) :: c
      real(dp) :: kg, m, dl, sc
      kg = 0
      if (name == 'GASRAD') kg = k_gas/(max(d, min_gap) + g0)
      m = (aa + bb)/2
      dl = aa - bb
      c = both(name, d, 0.0_dp, ta, tb)
      sc = 4*fs*max(aa, bb)**3 + kg
      call check_near(c%dq_dtheta_a, 4*fs*aa**3 + kg, 1.0e-12_dp*sc, &
                      trim(name)//': dq/dtheta_A = 4 F sigma a^3 (+ k_gas/(d + g0))', k)
      call check_near(c%dq_dtheta_b, -4*fs*bb**3 - kg, 1.0e-12_dp*sc, &
                      trim(name)//': dq/dtheta_B = -4 F sigma b^3 (- k_gas/(d + g0))', k)
      call check_near(c%dk_dtheta_mean, fs*(12*m*m + dl*dl), 1.0e-12_dp*fs*(12*m*m + dl*dl), &
                      trim(name)//': dk/dtm = F sigma (12 m^2 + (a - b)^2)', k)
      call check_near(c%dk_dd, dkdd, 1.0e-12_dp*abs(dkdd), &
                      trim(name)//': dk/dd = -k_gas/(d + g0)^2 above min_gap, else 0', k)
      call check(c%dk_dp == 0, trim(name)//': dk/dp = 0', k)
      if (name == 'GASRAD') then
        call fd_derivatives(name, d, 0.0_dp, ta, tb, 1.0e-5_dp*d, 0.0_dp, 1.0e-3_dp, k)
      else
        call fd_derivatives(name, d, 0.0_dp, ta, tb, 0.0_dp, 0.0_dp, 1.0e-3_dp, k)
      end if
    end subroutine check_derivatives
  end subroutine scene_t2_points

  ! Scene T2 steady: the two bars of T1 with a radiating (and for GASRAD gas-filled, d = 1e-4)
  ! gap. The host's Newton uses ifl_gap_conductance's exact flux derivatives. Reference: the
  ! flux q solves f(q) = q_gap(theta_H - q/G_A, theta_C + q/G_B) - q = 0, f decreasing, with
  ! q_gap by hand (F sigma (a^4 - b^4) + k_gas/(d + g0)(theta_A - theta_B)), found by bisection
  ! on [0, dT/R0] without calling the library. RADC (Celsius) must give RADK's answer.
  subroutine scene_t2_steady(name, d, theta_z, q)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: d, theta_z
    real(dp), intent(out) :: q
    integer, parameter :: maxit = 30
    real(dp) :: th, tc, lo, hi, mid, qref, taref, tbref, ta, tb, err(0:maxit), kgas
    integer :: it, nit
    write (scene, '(3a)') 'T2 steady ', name
    ! The bars' far ends at 400 K and 300 K on the model's scale.
    th = theta_h + theta_z
    tc = theta_c + theta_z
    kgas = 0
    if (name == 'GASRAD') kgas = k_gas/(max(d, min_gap) + g0)
    lo = 0
    hi = (th - tc)/r_bars
    do it = 1, 200
      mid = (lo + hi)/2
      if (mid <= lo .or. mid >= hi) exit
      if (f(mid) > 0) then
        lo = mid
      else
        hi = mid
      end if
    end do
    qref = (lo + hi)/2
    taref = th - qref/g_a
    tbref = tc + qref/g_b
    call newton(name, d, 0.0_dp, th, tc, .true., taref, tbref, 1.0e-10_dp, ta, tb, err, nit)
    call check(nit > 0 .and. nit <= 8, 'Newton with exact derivatives converges within 8', nit)
    q = gapcon_ak1(name, d, 0.0_dp, ta, tb)*(ta - tb)
    call check_near(q, qref, 1.0e-10_dp*qref, 'steady q = bisection of the hand-written balance', &
                    nit)
    call check_near(g_a*(th - ta), q, 1.0e-10_dp*qref, 'bar A flux = gap flux', nit)
    call check_near(g_b*(tb - tc), q, 1.0e-10_dp*qref, 'bar B flux = gap flux', nit)
    write (*, '(3a,i0,a,1p,e22.15,a,0p,2f12.6)') '  T2 steady ', name, ': Newton updates ', nit, &
      ', q =', q, ', theta_A, theta_B (K) =', ta - theta_z, tb - theta_z
  contains
    function f(qq) result(r)
      real(dp), intent(in) :: qq
      real(dp) :: r, aa, bb
      aa = th - qq/g_a - theta_z
      bb = tc + qq/g_b - theta_z
      r = f_view*sigma_sb*(aa**4 - bb**4) + kgas*(aa - bb) - qq
    end function f
  end subroutine scene_t2_steady
end module gapcon_scenes

program test_gapcon_scenes
  use gapcon_scenes
  implicit none
  real(dp) :: qk, qc, qg
  call scene_t1temp()
  call scene_t1_gas_cmy()
  call scene_t2_points()
  call scene_t2_steady('RADK', 1.0e-3_dp, kelvin_zero, qk)
  call scene_t2_steady('RADC', 1.0e-3_dp, celsius_zero, qc)
  scene = 'T2 steady RADK vs RADC'
  call check_near(qc, qk, 1.0e-10_dp*qk, 'Celsius model gives the kelvin model''s flux', 0)
  call scene_t2_steady('GASRAD', 1.0e-4_dp, kelvin_zero, qg)
  scene = 'T2 steady GASRAD vs RADK'
  call check(qg > qk, 'adding gas conduction raises the flux', 0)
  call finish()
end program test_gapcon_scenes
