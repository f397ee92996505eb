! bench_adhesive.f90 -- per-call cost of the adhesive friction law (PROPS(1) = 2) against plain
! Coulomb (PROPS(1) = 1), through the library's FRIC (fric_) and UINTER (uinter_), with FRICNOP
! (bench/fric_nop.f, the FRIC argument list and nothing else) as the call floor.
!
! Laws (NFDIR = 2, gamma_crit = 1e-3, DTIME = 0.1):
!   coulomb   PROPS = 1, 0.3, 0, 0, 1e-3                         (the plain law)
!   special   PROPS = 2, 0.3, -1, 0, 0, 0, 0, 1e-3               (S_a = N_a = k_mu = v_half = 0:
!                                                                  runs the Coulomb code)
!   adhesive  PROPS = 2, 0.3, 0.5, 4, 10, 0.2, 0.1, 1e-3         (every option on: quadratic
!                                                                  return map)
!   uinter    the adhesive PROPS with K_n = 1e4, through uinter_ (NDIR = 3), closed points.
! Cases: every point sticking, or every point sliding (|gamma_pr|/gamma_crit in 0.05-0.9 or
! 1.1-5, with each law's own static strength mu_s p0 + S_a for the start stress), NPOINTS
! distinct points, PRESS 50-150, DPRESS +-10.
! Timing: NREP sweeps over the points per timed run, NRUN rounds, routines in a rotating order;
! the best round is reported, in ns per call, and net of the empty call.
! Before timing, special and coulomb must give bit-identical TAU (else exit 2).
!
! Usage: bench_adhesive [NREP [NRUN [LAW]]]   (defaults 200, 15, all; LAW = 1..5 times only
! that row, e.g. under a profiler). Prints a Markdown table.
module adh_data
  use, intrinsic :: iso_fortran_env, only: int64, real64
  implicit none
  integer, parameter :: dp = real64, npoints = 4096, nlaw = 5
  real(dp), parameter :: gc = 1.0e-3_dp, dt = 0.1_dp, kn = 1.0e4_dp
  character(len=8), parameter :: names(nlaw) = [character(len=8) :: 'empty', 'coulomb', &
    'special', 'adhesive', 'uinter']
  real(dp) :: props(nlaw, 10)
  integer :: nprops(nlaw) = [7, 7, 8, 8, 10]
  real(dp) :: tau0(2, npoints, nlaw), dgam(2, npoints, nlaw), press(npoints), dpress(npoints)
  integer(int64) :: rng_state = 7
contains
  ! urand (the generator), median and int_arg.
  include 'bench_common.inc'

  subroutine setup()
    props = 0
    props(1, 1:7) = [1.0_dp, 0.3_dp, 0.0_dp, 0.0_dp, gc, 0.0_dp, 0.0_dp]
    props(2, 1:7) = [1.0_dp, 0.3_dp, 0.0_dp, 0.0_dp, gc, 0.0_dp, 0.0_dp]
    props(3, 1:8) = [2.0_dp, 0.3_dp, -1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, gc]
    props(4, 1:8) = [2.0_dp, 0.3_dp, 0.5_dp, 4.0_dp, 10.0_dp, 0.2_dp, 0.1_dp, gc]
    props(5, :) = [2.0_dp, 0.3_dp, 0.5_dp, 4.0_dp, 10.0_dp, 0.2_dp, 0.1_dp, gc, 0.0_dp, kn]
  end subroutine setup

  ! Static strength of law l at pressure p.
  real(dp) function strength(l, p)
    integer, intent(in) :: l
    real(dp), intent(in) :: p
    if (props(l, 1) == 1.0_dp .or. props(l, 3) <= 0.0_dp) then
      strength = props(l, 2) * p + props(l, 4)
    else
      strength = props(l, 3) * p + props(l, 4)
    end if
  end function strength

  subroutine prepare(slipping)
    logical, intent(in) :: slipping
    integer :: i, l
    real(dp) :: p0, a1, a2, g, f, dir(2), tdir(2)
    rng_state = 7
    do i = 1, npoints
      press(i) = 50.0_dp + 100.0_dp * urand()
      dpress(i) = -10.0_dp + 20.0_dp * urand()
      p0 = press(i) - dpress(i)
      a1 = 8.0_dp * atan(1.0_dp) * urand()
      a2 = 8.0_dp * atan(1.0_dp) * urand()
      dir = [cos(a1), sin(a1)]
      tdir = [cos(a2), sin(a2)]
      if (slipping) then
        g = gc * (1.1_dp + 3.9_dp * urand())
        f = 0.5_dp + 0.5_dp * urand()
      else
        g = gc * (0.05_dp + 0.85_dp * urand())
        f = 0.9_dp * urand()
      end if
      do l = 1, nlaw
        tau0(:, i, l) = f * strength(l, p0) * tdir
        dgam(:, i, l) = g * dir - f * gc * tdir
      end do
    end do
  end subroutine prepare
end module adh_data

program bench_adhesive
  use adh_data
  implicit none
  integer :: nrep, nrun, c, l, r, k, i, only
  real(dp) :: best(nlaw, 2), t, chk
  logical :: slipping

  nrep = int_arg(1, 200)
  nrun = int_arg(2, 15)
  only = int_arg(3, 0)
  call setup()
  best = huge(1.0_dp)
  do c = 1, 2
    slipping = c == 2
    call prepare(slipping)
    call same_answers()
    do r = 1, nrun
      do k = 0, nlaw - 1
        l = 1 + mod(r + k, nlaw)
        if (only /= 0 .and. l /= only) cycle
        call sweep(l, nrep, t, chk)
        best(l, c) = min(best(l, c), t)
      end do
    end do
  end do
  write (*, '(a)') '| law | PROPS | stick ns/call | stick net of empty | slip ns/call | &
    &slip net of empty | net / coulomb (stick, slip) |'
  write (*, '(a)') '|---|---|---:|---:|---:|---:|---:|'
  do l = 1, nlaw
    write (*, '(a,a,a,a,a,4(f8.1,a),f6.2,a,f6.2,a)') '| ', trim(names(l)), ' | ', &
      trim(props_text(l)), ' | ', best(l, 1), ' | ', best(l, 1) - best(1, 1), ' | ', &
      best(l, 2), ' | ', best(l, 2) - best(1, 2), ' | ', &
      ratio(l, 1), ', ', ratio(l, 2), ' |'
  end do
  i = 0
contains
  real(dp) function ratio(l, c)
    integer, intent(in) :: l, c
    ratio = (best(l, c) - best(1, c)) / (best(2, c) - best(1, c))
  end function ratio

  function props_text(l) result(s)
    integer, intent(in) :: l
    character(len=80) :: s
    integer :: j
    s = ''
    do j = 1, nprops(l)
      write (s(len_trim(s) + 1:), '(g0.3)') props(l, j)
      if (j < nprops(l)) s = trim(s) // ','
    end do
    if (l == 1) s = '(FRICNOP)'
  end function props_text

  ! Special case and plain Coulomb must agree bit for bit on every point.
  subroutine same_answers()
    real(dp) :: a(2), b(2), dd(6)
    integer :: i2
    do i2 = 1, npoints
      a = tau0(:, i2, 2)
      b = tau0(:, i2, 3)
      call one_fric(2, i2, a, dd(1))
      call one_fric(3, i2, b, dd(2))
      if (any(transfer(a, 1_int64, 2) /= transfer(b, 1_int64, 2))) then
        write (*, '(a,i0)') 'bench_adhesive: special case differs from Coulomb at point ', i2
        error stop 2
      end if
    end do
  end subroutine same_answers

  subroutine one_fric(l, i2, tau, sfd)
    integer, intent(in) :: l, i2
    real(dp), intent(inout) :: tau(2)
    real(dp), intent(out) :: sfd
    real(dp) :: ddtddg(4), ddtddp(2), dslip(2), sed, ddtddt(4), pnewdt, sv(3), taulm(2)
    real(dp) :: slip(2), time(2), coords(3), drot(4), temp(2), predef(2), chr, ddpddh
    real(dp) :: pr(10)
    integer :: lm, nf, mc, np, ns, npr, one, zero
    character(len=80) :: ci, sl, ms
    lm = 0; sv = 0; taulm = 0; slip = 0; time = 0; coords = 0; drot = [1, 0, 0, 1]
    temp = 20; predef = 0; chr = 1; ddpddh = 1.0e6_dp; pnewdt = 1.0e36_dp
    nf = 2; mc = 3; np = 1; ns = 3; npr = nprops(l); one = 1; zero = 0; pr = props(l, :)
    ci = 'BENCH'; sl = 'SLAVE'; ms = 'MASTER'
    if (l == 1) then
      call fricnop(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, sv, &
        dgam(:, i2, l), taulm, press(i2), dpress(i2), ddpddh, slip, one, one, time, dt, zero, &
        ci, sl, ms, one, one, one, coords, coords, drot, temp, predef, nf, mc, np, ns, chr, pr, &
        npr)
    else
      call fric(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, sv, &
        dgam(:, i2, l), taulm, press(i2), dpress(i2), ddpddh, slip, one, one, time, dt, zero, &
        ci, sl, ms, one, one, one, coords, coords, drot, temp, predef, nf, mc, np, ns, chr, pr, &
        npr)
    end if
  end subroutine one_fric

  subroutine sweep(l, n, t, chk)
    integer, intent(in) :: l, n
    real(dp), intent(out) :: t, chk
    integer(int64) :: t0, t1, rate
    integer :: rep, i2
    real(dp) :: tau(2), sfd, st(3), ddsddr(9), z9(9), flux(2), ddfddt(4), ddsddt(6)
    real(dp) :: ddfddr(6), sv(3), sed, spd, svd, scd, pnewdt, rdisp(3), drdisp(3), temp(2)
    real(dp) :: dtemp(2), predef(2), dpred(2), time(2), freqr, coords(3), aloc(9), drot(4)
    real(dp) :: area, chr, pr(10)
    integer :: node, ndir, ns, npred, npr, mcrd, kstep, kinc, kit, linper, lopen, lstate, lsdi
    integer :: lprint
    character(len=80) :: ci, sl, ms
    chk = 0
    ci = 'BENCH'; sl = 'SLAVE'; ms = 'MASTER'
    temp = 20; dtemp = 0; predef = 0; dpred = 0; time = 0; freqr = 0; coords = 0; aloc = 0
    drot = 0; area = 1; chr = 1; node = 1; ndir = 3; ns = 3; npred = 1; npr = nprops(l)
    mcrd = 3; kstep = 1; kinc = 1; kit = 1; linper = 0; lprint = 0; pr = props(l, :)
    call system_clock(t0, rate)
    do rep = 1, n
      do i2 = 1, npoints
        if (l == nlaw) then
          st = [press(i2) - dpress(i2), tau0(1, i2, l), tau0(2, i2, l)]
          rdisp = [press(i2) / kn, 0.0_dp, 0.0_dp]
          drdisp = [dpress(i2) / kn, dgam(1, i2, l), dgam(2, i2, l)]
          sv = 0; pnewdt = 1.0e36_dp
          call uinter(st, ddsddr, z9, z9, flux, ddfddt, ddsddt, ddfddr, sv, sed, sfd, spd, &
            svd, scd, pnewdt, rdisp, drdisp, temp, dtemp, predef, dpred, time, dt, freqr, ci, &
            sl, ms, pr, coords, aloc, drot, area, chr, node, ndir, ns, npred, npr, mcrd, kstep, &
            kinc, kit, linper, lopen, lstate, lsdi, lprint)
          chk = chk + st(2)
        else
          tau = tau0(:, i2, l)
          call one_fric(l, i2, tau, sfd)
          chk = chk + tau(1)
        end if
      end do
    end do
    call system_clock(t1)
    t = real(t1 - t0, dp) / real(rate, dp) * 1.0e9_dp / (real(n, dp) * npoints)
  end subroutine sweep
end program bench_adhesive
