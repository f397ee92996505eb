! bench_rate: the cost of rate-dependent friction through fric_, against constant mu.
!
! Same host loop as bench_fric (plain CALL FRIC, implicit interface, TAU and STATEV copied in
! before each call), NFDIR = 2, every point slipping (|gamma_pr|/gamma_crit in 1.5-5), three
! PROPS on the same points:
!   constant  PROPS = 1, 0.6, 0, 0, 1e-3                         (the plain Coulomb path)
!   decay     + PROPS(8..10) = 1, 0.3, 4                         (end-of-increment rate: local
!                                                                  Halley solve per call, through
!                                                                  fric_'s rate fast path)
!   frozen    + PROPS(20) = 1                                    (mu at the start rate, explicit)
! and the decay law again with a warm start: STATEV(2) (the previous increment's slip rate,
! the local solve's first guess) within +-20% of this increment's rate, as in a smooth analysis;
! the other rows have STATEV(2) drawn in 0-1, unrelated to the increment (a cold start).
! Two more rows show what the cheap paths save ("model no more than a scene needs"):
!   general   constant mu with HHT (PROPS(14..16) = 0, 0.25, 0.5): the same stress as
!             `constant` (mu does not depend on the rate), through the extended law's general
!             path; its checksum must agree with `constant` to round-off
!   aniso     constant mu, mu2 = PROPS(3) = 0.3: the friction ellipse (scaled variables)
! Target (issue 4): decay under 3x constant. Usage: bench_rate [NREP [NRUN [ROW]]] (default 200,
! 15, all rows); ROW (1-6, in the order above) runs that row alone, for counting instructions
! (scripts/bench-rate-count.sh): no ratios, no checksum comparison.
module bench_rate_data
  use, intrinsic :: iso_fortran_env, only: dp => real64, int64
  implicit none
  integer, parameter :: npoints = 4096
  real(dp) :: press(npoints), tau0(2, npoints), dgam(2, npoints), rate0(npoints), warm0(npoints)
  integer, parameter :: nrow = 6
  real(dp) :: props(20, 5)
  integer :: nprops(5)
  ! The PROPS set of each row: constant, decay (cold), frozen, decay (warm), general, aniso.
  integer, parameter :: pset(nrow) = [1, 2, 3, 2, 4, 5]
  ! The state of bench_common.inc's urand (this program draws with uniform(state) instead).
  integer(int64) :: rng_state = 1
contains
  ! int_arg (the command line); also urand and median.
  include 'bench_common.inc'

  real(dp) function uniform(state)
    integer(int64), intent(inout) :: state
    ! Park-Miller: the product stays below 2**46, no overflow.
    state = mod(state * 16807_int64, 2147483647_int64)
    uniform = real(state, dp) / 2147483647.0_dp
  end function uniform

  subroutine prepare()
    integer(int64) :: s
    integer :: i
    real(dp) :: a, b, m, g
    s = 12345_int64
    do i = 1, npoints
      press(i) = 50.0_dp + 100.0_dp * uniform(s)
      a = 6.283185307179586_dp * uniform(s)
      m = 0.9_dp * 0.3_dp * press(i) * uniform(s)
      tau0(1, i) = m * cos(a)
      tau0(2, i) = m * sin(a)
      b = 6.283185307179586_dp * uniform(s)
      g = (1.5_dp + 3.5_dp * uniform(s)) * 1.0e-3_dp
      dgam(1, i) = g * cos(b) - tau0(1, i) / (0.6_dp * press(i)) * 1.0e-3_dp
      dgam(2, i) = g * sin(b) - tau0(2, i) / (0.6_dp * press(i)) * 1.0e-3_dp
      rate0(i) = uniform(s)
      ! The slip of a slipping point is |gamma_pr| - gamma_crit (to first order in the rate).
      warm0(i) = (sqrt((dgam(1, i) + tau0(1, i) / (0.6_dp * press(i)) * 1.0e-3_dp)**2 + &
                       (dgam(2, i) + tau0(2, i) / (0.6_dp * press(i)) * 1.0e-3_dp)**2) - &
                  1.0e-3_dp) / 1.0e-2_dp * (0.8_dp + 0.4_dp * uniform(s))
    end do
    props = 0.0_dp
    props(1:5, 1) = [1.0_dp, 0.6_dp, 0.0_dp, 0.0_dp, 1.0e-3_dp]
    props(:, 2) = props(:, 1)
    props(8:10, 2) = [1.0_dp, 0.3_dp, 4.0_dp]
    props(:, 3) = props(:, 2)
    props(20, 3) = 1.0_dp
    props(:, 4) = props(:, 1)
    props(14:16, 4) = [0.0_dp, 0.25_dp, 0.5_dp]
    props(:, 5) = props(:, 1)
    props(3, 5) = 0.3_dp
    nprops = [5, 20, 20, 20, 20]
  end subroutine prepare

  subroutine run_loop(which, nrep, checksum, seconds)
    integer, intent(in) :: which, nrep
    real(dp), intent(inout) :: checksum
    real(dp), intent(out) :: seconds
    integer :: lm, rep, i, kstep, kinc, noel, ipt, node, npatch, nfdir, mcrd, npred, nstatv
    real(dp) :: tau(2), ddtddg(4), ddtddp(2), dslip(2), sed, sfd, ddtddt(4), pnewdt, statev(3)
    real(dp) :: taulm(2), dpress, ddpddh, slip(2), time(2), dtime, coords(3), rcoord(3)
    real(dp) :: drot(2, 2), temp(2), predef(2, 1), chrlngth
    character(len=80) :: ciname, slname, msname
    integer(int64) :: t0, t1, clock_rate
    taulm = 0; dpress = 0; ddpddh = 1.0e6_dp; slip = 0; time = 0; dtime = 1.0e-2_dp
    coords = 0; rcoord = 0; drot = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
    temp = 20; predef = 0; chrlngth = 1; kstep = 1; kinc = 1; noel = 1; ipt = 1; node = 1
    npatch = 1; nfdir = 2; mcrd = 3; npred = 1; nstatv = 3
    ciname = 'BENCH-RATE'; slname = 'SLAVE'; msname = 'MASTER'
    pnewdt = 1.0e36_dp
    call system_clock(t0, clock_rate)
    do rep = 1, nrep
      do i = 1, npoints
        tau = tau0(:, i)
        statev = [0.0_dp, rate0(i), 1.0_dp]
        if (which == 4) statev(2) = warm0(i)
        lm = 0
        call FRIC(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, &
                  dgam(1, i), taulm, press(i), dpress, ddpddh, slip, kstep, kinc, time, &
                  dtime, noel, ciname, slname, msname, ipt, node, npatch, coords, rcoord, &
                  drot, temp, predef, nfdir, mcrd, npred, nstatv, chrlngth, &
                  props(1, pset(which)), nprops(pset(which)))
        checksum = checksum + (tau(1) + ddtddg(1) + sfd + statev(3))
      end do
    end do
    call system_clock(t1)
    seconds = real(t1 - t0, dp) / real(clock_rate, dp)
    if (pnewdt /= 1.0e36_dp) then
      write (*, '(a,i0)') 'bench_rate: a timed call failed (PNEWDT lowered), PROPS set ', which
      error stop 3
    end if
  end subroutine run_loop
end module bench_rate_data

program bench_rate
  use bench_rate_data
  implicit none
  integer :: nrep, nrun, r, w, only
  real(dp) :: best(nrow), t, chk(nrow)
  character(len=*), parameter :: names(nrow) = [character(len=34) :: 'constant', &
    'decay (cold start)', 'frozen', 'decay (warm start)', 'constant, general path (HHT on)', &
    'constant, anisotropic']
  nrep = int_arg(1, 200)
  nrun = int_arg(2, 15)
  only = int_arg(3, 0)
  if (command_argument_count() >= 3) then
    if (only < 1 .or. only > nrow) then
      write (*, '(a,i0)') 'bench_rate: ROW must be 1 to ', nrow
      error stop 2
    end if
  end if
  call prepare()
  if (only /= 0) then
    chk = 0
    best = huge(1.0_dp)
    do r = 1, nrun
      call run_loop(only, nrep, chk(only), t)
      best(only) = min(best(only), t)
    end do
    write (*, '(a,a,a,f8.1,a,es22.14)') '| ', trim(names(only)), ' | ', &
      1.0e9_dp * best(only) / (real(nrep, dp) * npoints), ' ns/call | checksum ', chk(only)
    stop
  end if
  best = huge(1.0_dp)
  chk = 0
  do r = 1, nrun
    do w = 1, nrow
      ! Rotate the order each round.
      call run_loop(1 + mod(w + r, nrow), nrep, chk(1 + mod(w + r, nrow)), t)
      best(1 + mod(w + r, nrow)) = min(best(1 + mod(w + r, nrow)), t)
    end do
  end do
  write (*, '(a,i0,a,i0,a,i0,a)') 'Points: ', npoints, ' (NFDIR = 2, all slipping); timed run: ', &
    nrep, ' sweeps; best of ', nrun, ' rounds.'
  write (*, '(a)') ''
  write (*, '(a)') '| PROPS | FRIC ns/call | ratio to constant |'
  write (*, '(a)') '|---|---:|---:|'
  do w = 1, nrow
    write (*, '(a,a,a,f8.1,a,f6.2,a)') '| ', trim(names(w)), ' | ', &
      1.0e9_dp * best(w) / (real(nrep, dp) * npoints), ' | ', best(w) / best(1), ' |'
  end do
  write (*, '(a,4es22.14)') 'Checksums (constant, decay, frozen, decay warm): ', chk(1:4)
  write (*, '(a,es10.2)') 'General path against the plain path, relative checksum difference: ', &
    abs(chk(5) - chk(1)) / abs(chk(1))
  if (abs(chk(5) - chk(1)) > 1.0e-12_dp * abs(chk(1))) then
    write (*, '(a)') 'bench_rate: the general path does not reproduce the plain path'
    error stop 4
  end if
  if (best(2) / best(1) >= 3.0_dp) write (*, '(a)') 'decay path (cold start) above the 3x target'
  if (best(4) / best(1) >= 3.0_dp) write (*, '(a)') 'decay path (warm start) above the 3x target'
  if (best(3) / best(1) >= 3.0_dp) write (*, '(a)') 'frozen path above the 3x target'
end program bench_rate
