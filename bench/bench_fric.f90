! bench_fric.f90 -- per-call cost of the library's FRIC (fric_, from libinterfacial.a) against
! FRICREF, a hand-written Fortran 77 FRIC of the same law (bench/fric_ref.f), and FRICNOP, an
! empty routine with the same argument list (bench/fric_nop.f) that measures the harness itself.
!
! Cases: NFDIR = 1 and 2, each with every point sticking or every point slipping (elastic stick,
! mu = 0.3, gamma_crit = 1e-3, no shear limit). Each case has NPOINTS distinct contact points
! whose PRESS, DPRESS, TAU and DGAM are drawn so that the case holds with a margin.
!
! Before any timing, every prepared point is run once through FRIC and FRICREF and all outputs
! are compared (they are independent implementations of the same formulas); the run stops on
! the first disagreement. Extra check-only variants cover the shear-limit cap, gamma_crit from
! CHRLNGTH and non-positive pressures.
!
! Timing: one loop body calls the routine chosen by an integer (a perfectly predicted branch,
! the same for all three routines), exactly as a host calls FRIC: plain CALL, implicit
! interface, inputs copied into the host's work arrays before each call. Each routine lives in
! its own compilation unit, so nothing is inlined. Each round times the three routines in a
! rotating order; the table reports the best round (and the ratio of the medians).
!
! Usage: bench_fric [NREP [NRUN [CASE]]]   (defaults 200, 15, 0: 200 sweeps over the points per
! timed run, 15 rounds, every case; CASE = 1..4 times only that row, e.g. under a profiler).
! Prints a Markdown table; exits non-zero on a disagreement.
module bench_data
  use, intrinsic :: iso_fortran_env, only: int64, real64
  implicit none
  integer, parameter :: dp = real64, npoints = 4096
  integer, parameter :: use_ours = 1, use_ref = 2, use_nop = 3
  real(dp), parameter :: mu = 0.3_dp, gc = 1.0e-3_dp

  ! The prepared contact points of the current case.
  real(dp) :: tau0(2, npoints), dgam(2, npoints), press(npoints), dpress(npoints)
  real(dp) :: sv0(3, npoints)
  ! |gamma_pr| / gamma_crit of each point, computed here from the formulas of the law.
  real(dp) :: gratio(npoints)

  ! Host arguments that do not change from point to point.
  integer :: kstep = 1, kinc = 3, noel = 0, ipt = 1, node = 17, npatch = 5
  integer :: mcrd = 3, npred = 1, nstatv = 3, nprops = 7
  real(dp) :: time(2) = [0.3_dp, 1.3_dp], dtime = 0.1_dp, ddpddh = 1.0e6_dp
  real(dp) :: slip(2) = 0.0_dp, taulm(2) = 0.0_dp
  real(dp) :: coords(3) = [1.0_dp, 2.0_dp, 0.5_dp], rcoord(3) = [1.0_dp, 2.0_dp, 0.5_dp]
  real(dp) :: drot(2, 2) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
  real(dp) :: temp(2) = 20.0_dp, predef(2, 1) = 0.0_dp
  real(dp) :: chrlngth = 0.2_dp
  real(dp) :: props(7)
  character(len=80) :: ciname = 'BENCH-PAIR', slname = 'SLAVE', msname = 'MASTER'

  integer(int64) :: rng_state = 1

contains

  ! urand (the generator) and median.
  include 'bench_common.inc'

  ! Standard PROPS of the timed cases: Coulomb, mu, isotropic, no cap, gamma_crit absolute,
  ! default tolerance, elastic stick.
  subroutine standard_props()
    props = [1.0_dp, mu, 0.0_dp, 0.0_dp, gc, 0.0_dp, 0.0_dp]
    chrlngth = 0.2_dp
  end subroutine standard_props

  ! Draws the points of a case. The start-of-increment pressure p0 = PRESS - DPRESS is always
  ! positive and uncapped here, so gamma_el = TAU gamma_crit / (mu p0); the predictor is
  ! chosen first and DGAM = gamma_pr - gamma_el.
  subroutine prepare(nfdir, slipping, seed)
    integer, intent(in) :: nfdir, seed
    logical, intent(in) :: slipping
    integer :: i
    real(dp) :: p, p0, tc0, amp, ang, gpr(2), gel(2), dir(2), tdir(2), g

    rng_state = seed
    do i = 1, npoints
      p = 50.0_dp + 100.0_dp * urand()
      dpress(i) = -10.0_dp + 20.0_dp * urand()
      press(i) = p
      p0 = press(i) - dpress(i)
      tc0 = mu * p0
      if (nfdir == 1) then
        dir = [sign(1.0_dp, urand() - 0.5_dp), 0.0_dp]
        tdir = [sign(1.0_dp, urand() - 0.5_dp), 0.0_dp]
      else
        ang = 8.0_dp * atan(1.0_dp) * urand()
        dir = [cos(ang), sin(ang)]
        ang = 8.0_dp * atan(1.0_dp) * urand()
        tdir = [cos(ang), sin(ang)]
      end if
      if (slipping) then
        amp = tc0 * (0.5_dp + 0.5_dp * urand())
        g = gc * (1.1_dp + 3.9_dp * urand())
      else
        amp = tc0 * 0.9_dp * urand()
        g = gc * (0.05_dp + 0.85_dp * urand())
      end if
      tau0(:, i) = amp * tdir
      gel = tau0(:, i) * (gc / tc0)
      gpr = g * dir
      dgam(:, i) = gpr - gel
      ! The predictor the law will see, recomputed from the stored inputs.
      gpr = tau0(:, i) * (gc / tc0) + dgam(:, i)
      gratio(i) = sqrt(gpr(1)**2 + gpr(2)**2) / gc
      sv0(:, i) = [10.0_dp * urand(), 0.0_dp, merge(1.0_dp, 0.0_dp, urand() > 0.5_dp)]
      if (slipping .and. gratio(i) < 1.01_dp .or. .not. slipping .and. gratio(i) > 0.99_dp) then
        write (*, '(a,i0,a,es12.5)') 'bench_fric: point ', i, ' misses its case: |g_pr|/g_c = ', &
          gratio(i)
        error stop 2
      end if
    end do
  end subroutine prepare

  ! |a - b| <= 1e-12 max|a,b| entry-wise, scaled by the largest entry of either array.
  logical function agree(n, a, b)
    integer, intent(in) :: n
    real(dp), intent(in) :: a(n), b(n)
    real(dp) :: scale
    scale = max(maxval(abs(a)), maxval(abs(b)))
    agree = all(abs(a - b) <= 1.0e-12_dp * scale)
  end function agree

  ! Runs every prepared point once through FRIC and FRICREF and compares every output.
  ! expect_status: 0 (all stick) or 1 (all slip) is checked against STATEV(3); -1 skips it.
  subroutine check_points(nfdir, label, expect_status)
    integer, intent(in) :: nfdir, expect_status
    character(len=*), intent(in) :: label
    integer :: i, lmo, lmr, nbad
    real(dp) :: tauo(2), ddtddgo(4), ddtddpo(2), dslipo(2), sedo, sfdo, ddtddto(4), pnewdto
    real(dp) :: svo(3)
    real(dp) :: taur(2), ddtddgr(4), ddtddpr(2), dslipr(2), sedr, sfdr, ddtddtr(4), pnewdtr
    real(dp) :: svr(3)
    real(dp), parameter :: sentinel = -777.25_dp
    character(len=200) :: what

    mcrd = nfdir + 1
    nbad = 0
    do i = 1, npoints
      lmo = 0
      tauo = tau0(:, i)
      svo = sv0(:, i)
      ddtddgo = sentinel; ddtddpo = sentinel; dslipo = sentinel; ddtddto = sentinel
      sedo = sentinel; sfdo = sentinel; pnewdto = 1.0e36_dp
      lmr = 0
      taur = tau0(:, i)
      svr = sv0(:, i)
      ddtddgr = sentinel; ddtddpr = sentinel; dslipr = sentinel; ddtddtr = sentinel
      sedr = sentinel; sfdr = sentinel; pnewdtr = 1.0e36_dp

      call FRIC(lmo, tauo, ddtddgo, ddtddpo, dslipo, sedo, sfdo, ddtddto, pnewdto, svo, &
                dgam(1, i), taulm, press(i), dpress(i), ddpddh, slip, kstep, kinc, time, dtime, &
                noel, ciname, slname, msname, ipt, node, npatch, coords, rcoord, drot, temp, &
                predef, nfdir, mcrd, npred, nstatv, chrlngth, props, nprops)
      call FRICREF(lmr, taur, ddtddgr, ddtddpr, dslipr, sedr, sfdr, ddtddtr, pnewdtr, svr, &
                   dgam(1, i), taulm, press(i), dpress(i), ddpddh, slip, kstep, kinc, time, dtime, &
                   noel, ciname, slname, msname, ipt, node, npatch, coords, rcoord, drot, temp, &
                   predef, nfdir, mcrd, npred, nstatv, chrlngth, props, nprops)

      what = ''
      if (lmo /= 0 .or. lmr /= 0) what = trim(what) // ' LM'
      if (pnewdto /= 1.0e36_dp .or. pnewdtr /= 1.0e36_dp) what = trim(what) // ' PNEWDT'
      if (.not. agree(nfdir, tauo, taur)) what = trim(what) // ' TAU'
      if (.not. agree(nfdir**2, ddtddgo, ddtddgr)) what = trim(what) // ' DDTDDG'
      if (.not. agree(nfdir, ddtddpo, ddtddpr)) what = trim(what) // ' DDTDDP'
      if (.not. agree(nfdir, dslipo, dslipr)) what = trim(what) // ' DSLIP'
      if (.not. agree(1, [sedo], [sedr])) what = trim(what) // ' SED'
      if (.not. agree(1, [sfdo], [sfdr])) what = trim(what) // ' SFD'
      if (any(ddtddto(1:2*nfdir) /= 0.0_dp) .or. any(ddtddtr(1:2*nfdir) /= 0.0_dp)) &
        what = trim(what) // ' DDTDDT'
      if (.not. agree(3, svo, svr)) what = trim(what) // ' STATEV'
      if (expect_status >= 0) then
        if (svo(3) /= real(expect_status, dp) .or. svr(3) /= real(expect_status, dp)) &
          what = trim(what) // ' STATEV(3)-vs-case'
      end if
      if (disagrees('bench_fric', label, i, what, nbad)) then
        write (*, '(a,4es24.16)') '  ours TAU, SED, SFD: ', tauo(1:nfdir), sedo, sfdo
        write (*, '(a,4es24.16)') '  ref  TAU, SED, SFD: ', taur(1:nfdir), sedr, sfdr
      end if
    end do
    call stop_if_disagreed('bench_fric', label, nbad, npoints, '')
  end subroutine check_points

  ! One timed run: NREP sweeps over the points through routine WHICH. The loop body is the same
  ! for every routine; only the CALL chosen by the (perfectly predicted) branch differs.
  subroutine run_loop(which, nfdir, nrep, checksum, seconds)
    integer, intent(in) :: which, nfdir, nrep
    real(dp), intent(inout) :: checksum
    real(dp), intent(out) :: seconds
    integer :: lm, rep, i
    real(dp) :: tau(2), ddtddg(4), ddtddp(2), dslip(2), sed, sfd, ddtddt(4), pnewdt, statev(3)
    real(dp) :: s
    integer(int64) :: t0, t1, rate

    tau = 0.0_dp; ddtddg = 0.0_dp; ddtddp = 0.0_dp; dslip = 0.0_dp; ddtddt = 0.0_dp
    sed = 0.0_dp; sfd = 0.0_dp; statev = 0.0_dp
    pnewdt = 1.0e36_dp
    mcrd = nfdir + 1
    call system_clock(t0, rate)
    do rep = 1, nrep
      do i = 1, npoints
        tau(1) = tau0(1, i)
        tau(2) = tau0(2, i)
        statev(1) = sv0(1, i)
        statev(2) = sv0(2, i)
        statev(3) = sv0(3, i)
        lm = 0
        select case (which)
        case (use_ours)
          call FRIC(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, &
                    dgam(1, i), taulm, press(i), dpress(i), ddpddh, slip, kstep, kinc, time, &
                    dtime, noel, ciname, slname, msname, ipt, node, npatch, coords, rcoord, &
                    drot, temp, predef, nfdir, mcrd, npred, nstatv, chrlngth, props, nprops)
        case (use_ref)
          call FRICREF(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, &
                       dgam(1, i), taulm, press(i), dpress(i), ddpddh, slip, kstep, kinc, time, &
                       dtime, noel, ciname, slname, msname, ipt, node, npatch, coords, rcoord, &
                       drot, temp, predef, nfdir, mcrd, npred, nstatv, chrlngth, props, nprops)
        case default
          call FRICNOP(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, &
                       dgam(1, i), taulm, press(i), dpress(i), ddpddh, slip, kstep, kinc, time, &
                       dtime, noel, ciname, slname, msname, ipt, node, npatch, coords, rcoord, &
                       drot, temp, predef, nfdir, mcrd, npred, nstatv, chrlngth, props, nprops)
        end select
        ! One add on the loop-carried chain, so the checksum does not serialise the calls.
        s = tau(1) + ddtddg(1) + ddtddp(1) + sed + sfd + statev(1)
        checksum = checksum + s
      end do
    end do
    call system_clock(t1)
    seconds = real(t1 - t0, dp) / real(rate, dp)
    if (pnewdt /= 1.0e36_dp .or. lm /= 0) then
      write (*, '(a,i0)') 'bench_fric: a timed call failed (PNEWDT lowered), routine ', which
      error stop 3
    end if
  end subroutine run_loop

end module bench_data

program bench_fric
  use bench_data
  implicit none
  integer :: nrep, nrun, only, icase, nfdir, r, k, j, nmissed
  integer :: order(3, 6)
  logical :: slipping
  character(len=32) :: label
  real(dp), allocatable :: t(:, :)
  real(dp) :: chk(3), ns(3), nsmed(3), sec, percall, ratio, net
  character(len=12) :: verdict

  nrep = int_arg(1, 200)
  nrun = int_arg(2, 15)
  only = int_arg(3, 0)
  allocate (t(nrun, 3))
  ! The six orders of (ours, reference, empty), used in turn: each routine runs first, second
  ! and third equally often, so drift in machine load hits all three alike.
  order = reshape([1, 2, 3, 2, 3, 1, 3, 1, 2, 1, 3, 2, 3, 2, 1, 2, 1, 3], [3, 6])

  ! Check-only variants first: disagreement anywhere means the timings would compare
  ! different things.
  do icase = 1, 4
    nfdir = 1 + (icase - 1) / 2
    slipping = mod(icase, 2) == 0
    ! Shear limit tau_max = 30: mu p spans 15..45, so about half the points are capped, at the
    ! start, at the end of the increment, or both.
    call prepare(nfdir, slipping, 1000 + icase)
    call standard_props()
    props(4) = 30.0_dp
    call check_points(nfdir, 'check tau_max cap', -1)
    ! gamma_crit = PROPS(6) * CHRLNGTH = 0.004 * 0.25 (1e-3 up to rounding, inside the margins).
    call standard_props()
    props(5) = 0.0_dp
    props(6) = 0.004_dp
    chrlngth = 0.25_dp
    call check_points(nfdir, 'check gamma_crit from CHRLNGTH', merge(1, 0, slipping))
    ! gamma_crit = 0.005 (default) * CHRLNGTH; non-positive pressures: PRESS < 0 (no friction),
    ! PRESS - DPRESS < 0 (first contact), PRESS = 0.
    call standard_props()
    props(5) = 0.0_dp
    chrlngth = 0.2_dp
    press(1:npoints:7) = -press(1:npoints:7)
    dpress(2:npoints:7) = press(2:npoints:7) + 5.0_dp
    press(3:npoints:7) = 0.0_dp
    call check_points(nfdir, 'check non-positive pressure', -1)
  end do

  call timing_table_head(npoints, nrep, nrun, 'FRIC', 'FRICREF', ' within 1.10 |')
  nmissed = 0
  do icase = 1, 4
    if (only /= 0 .and. icase /= only) cycle
    nfdir = 1 + (icase - 1) / 2
    slipping = mod(icase, 2) == 0
    write (label, '(a,i0,a)') 'NFDIR=', nfdir, merge(', slip ', ', stick', slipping)
    call prepare(nfdir, slipping, 1 + icase)
    call standard_props()
    call check_points(nfdir, trim(label), merge(1, 0, slipping))

    chk = 0.0_dp
    ! Warm-up: caches, branch predictors, page faults, CPU clock.
    do k = 1, 3
      call run_loop(k, nfdir, max(1, nrep / 4), chk(k), sec)
    end do
    chk = 0.0_dp
    do r = 1, nrun
      do j = 1, 3
        k = order(j, 1 + mod(r - 1, 6))
        call run_loop(k, nfdir, nrep, chk(k), sec)
        t(r, k) = sec
      end do
    end do
    percall = 1.0e9_dp / (real(nrep, dp) * real(npoints, dp))
    do k = 1, 3
      ns(k) = minval(t(:, k)) * percall
      nsmed(k) = median(t(:, k)) * percall
    end do
    ! Same inputs, same outputs: the sums of the timed outputs must agree too.
    if (abs(chk(use_ours) - chk(use_ref)) > 1.0e-9_dp * abs(chk(use_ref))) then
      write (*, '(a,a,2es24.16)') 'bench_fric: checksums differ in ', trim(label), &
        chk(use_ours), chk(use_ref)
      error stop 4
    end if
    ratio = ns(use_ours) / ns(use_ref)
    net = (ns(use_ours) - ns(use_nop)) / (ns(use_ref) - ns(use_nop))
    verdict = merge('yes', 'NO ', ratio <= 1.10_dp)
    if (ratio > 1.10_dp) nmissed = nmissed + 1
    write (*, '(a,a,a,f7.2,a,f7.2,a,f6.3,a,f6.3,a,f6.2,a,f6.3,a,a,a)') '| ', trim(label), ' | ', &
      ns(use_ours), ' | ', ns(use_ref), ' | ', ratio, ' | ', nsmed(use_ours) / nsmed(use_ref), &
      ' | ', ns(use_nop), ' | ', net, ' | ', trim(verdict), ' |'
  end do
  write (*, '(a)') ''
  write (*, '(a,i0,a)') 'Checksums of the timed outputs agree (ours vs reference); ', &
    nmissed, ' case(s) above the 1.10 target.'
  write (*, '(a,3es22.14)') 'Last case checksums (ours, reference, empty): ', chk
end program bench_fric
