! bench_gapcon.f90 -- per-call cost of the library's GAPCON (gapcon_, from libinterfacial.a)
! against GAPREF, a hand-written Fortran 77 GAPCON of the same laws (bench/gapcon_ref.f), and
! GAPNOP, an empty routine with the same argument list (bench/gapcon_nop.f) that measures the
! harness itself.
!
! The library reads its laws from the file named by INTERFACIAL_CONFIG, once per process, so the
! configuration is chosen per run by MODE:
!   laws      INTERFACIAL_CONFIG=bench/gapcon_bench.toml: GAP-CONST (k = 4500), GAP-PTAB (100-row
!             pressure table) and GAP-TTAB (the 100 pressures at two temperatures), each timed
!             against GAPREF and GAPNOP. Prints a Markdown table with its header.
!   lookup1   INTERFACIAL_CONFIG=bench/gapcon_lookup_1.toml: one interaction, INT-01.
!   lookup20  INTERFACIAL_CONFIG=bench/gapcon_lookup_20.toml: INT-01 .. INT-20 and "*"; CINAME is
!             the first entry, the last entry, and a name that is not listed.
!             The lookup modes time GAPCON and GAPNOP with the constant law and print table rows
!             only (scripts/bench.sh writes the header), to be read across the two processes.
!
! Each case has NPOINTS distinct points: contact pressure D(2) spread over -10..215 MPa (the
! table spans 0..196.02, so about 13% of the points are outside it), every 16th point exactly
! on a table row; mean surface temperature 0..340 degC (table temperatures 20 and 320), every
! 16th point exactly on 20 or 320.
!
! Before any timing, every point goes once through GAPCON and through GAPREF (laws) or is
! compared with the configured constant (lookup); AK(1) must agree to 1e-12 relative, and
! AK(2..5) must be left as they were. The run stops on the first failed case.
!
! Timing: one loop body calls the routine chosen by an integer (a perfectly predicted branch,
! the same for every routine), as a host calls GAPCON: plain CALL, implicit interface
! (15 arguments + 3 hidden lengths, CHARACTER*80 names), D and TEMP copied into the host's
! work arrays before each call. Each routine lives in its own compilation unit, so nothing is
! inlined. Each round times the routines in a rotating order; the table reports the best round
! (and the ratio of the medians).
!
! Usage: bench_gapcon MODE [NREP [NRUN [CASE]]]   (defaults 200, 15, 0: 200 sweeps over the
! points per timed run, 15 rounds, every case; CASE = 1.. times only that row, e.g. under a
! profiler). Exits non-zero on a disagreement.
module gapcon_bench_data
  use, intrinsic :: iso_fortran_env, only: int64, real64
  implicit none
  integer, parameter :: dp = real64, npoints = 4096
  integer, parameter :: use_ours = 1, use_ref = 2, use_nop = 3
  ! The table of bench/gapcon_bench.toml: p(i) = (i-1)^2/50 (an exact quotient, so these are
  ! the same doubles as the decimals of the file), 100 rows, 0 .. 196.02.
  integer, parameter :: nrows = 100
  real(dp), parameter :: akcon = 4500.0_dp, theta_lo = 20.0_dp, theta_hi = 320.0_dp

  ! The prepared points: D(1), D(2), TEMP(1), TEMP(2).
  real(dp) :: clearance(npoints), press(npoints), theta_a(npoints), theta_b(npoints)

  ! Host arguments that do not change from point to point.
  integer :: noel = 12, node = 7, npred = 1, kstep = 1, kinc = 3
  real(dp) :: flowm(2) = 0.0_dp, predef(2, 1) = 0.0_dp, time(2) = [0.3_dp, 1.3_dp]
  real(dp) :: coords(3) = [1.0_dp, 2.0_dp, 0.5_dp]
  character(len=80) :: ciname = ' ', slname = 'SLAVE', msname = 'MASTER'

  integer(int64) :: rng_state = 1

contains

  ! urand (the generator) and median.
  include 'bench_common.inc'

  real(dp) function table_pressure(i)
    integer, intent(in) :: i
    table_pressure = real((i - 1)**2, dp) / 50.0_dp
  end function table_pressure

  subroutine prepare(seed)
    integer, intent(in) :: seed
    integer :: i
    real(dp) :: tbar, jump

    rng_state = seed
    do i = 1, npoints
      if (mod(i, 16) == 0) then
        press(i) = table_pressure(1 + mod(i / 16, nrows))
      else
        press(i) = -10.0_dp + 225.0_dp * urand()
      end if
      ! An open gap (p <= 0) has a clearance; a closed one has none.
      clearance(i) = merge(1.0e-5_dp * urand(), 0.0_dp, press(i) <= 0.0_dp)
      if (mod(i, 16) == 8) then
        tbar = merge(theta_lo, theta_hi, mod(i / 16, 2) == 0)
        jump = 0.0_dp
      else
        tbar = 340.0_dp * urand()
        jump = -30.0_dp + 60.0_dp * urand()
      end if
      theta_a(i) = tbar + 0.5_dp * jump
      theta_b(i) = tbar - 0.5_dp * jump
    end do
  end subroutine prepare

  ! Runs every point once through GAPCON and, when expected < 0, through GAPREF; else compares
  ! with the constant EXPECTED. Stops the program on any disagreement. ak_out: ours, per point.
  subroutine check_points(label, expected, ak_out)
    character(len=*), intent(in) :: label
    real(dp), intent(in) :: expected
    real(dp), intent(out) :: ak_out(npoints)
    real(dp), parameter :: sentinel = -777.25_dp
    real(dp) :: ako(5), akr(5), d(2), temp(2), want
    integer :: i, nbad
    character(len=120) :: what

    nbad = 0
    do i = 1, npoints
      d = [clearance(i), press(i)]
      temp = [theta_a(i), theta_b(i)]
      ako = sentinel
      call GAPCON(ako, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, &
                  node, npred, kstep, kinc)
      if (expected < 0.0_dp) then
        akr = sentinel
        call GAPREF(akr, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, &
                    node, npred, kstep, kinc)
        want = akr(1)
      else
        want = expected
      end if
      ak_out(i) = ako(1)
      what = ''
      if (.not. (abs(ako(1) - want) <= 1.0e-12_dp * max(abs(ako(1)), abs(want)))) &
        what = trim(what) // ' AK(1)'
      if (.not. (want > 0.0_dp)) what = trim(what) // ' AK(1)-of-reference-not-positive'
      if (any(ako(2:5) /= sentinel)) what = trim(what) // ' AK(2..5)-written'
      if (disagrees('bench_gapcon', label, i, what, nbad)) then
        write (*, '(a,4es24.16)') '  D(1), D(2), TEMP: ', d, temp
        write (*, '(a,2es24.16)') '  ours AK(1), expected: ', ako(1), want
      end if
    end do
    call stop_if_disagreed('bench_gapcon', label, nbad, npoints, &
                           ' (is INTERFACIAL_CONFIG the file of this mode?)')
  end subroutine check_points

  ! One timed run: NREP sweeps over the points through routine WHICH.
  subroutine run_loop(which, nrep, checksum, seconds)
    integer, intent(in) :: which, nrep
    real(dp), intent(inout) :: checksum
    real(dp), intent(out) :: seconds
    integer :: rep, i
    real(dp) :: ak(5), d(2), temp(2)
    integer(int64) :: t0, t1, rate

    ak = 0.0_dp
    call system_clock(t0, rate)
    do rep = 1, nrep
      do i = 1, npoints
        d(1) = clearance(i)
        d(2) = press(i)
        temp(1) = theta_a(i)
        temp(2) = theta_b(i)
        select case (which)
        case (use_ours)
          call GAPCON(ak, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, &
                      node, npred, kstep, kinc)
        case (use_ref)
          call GAPREF(ak, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, &
                      node, npred, kstep, kinc)
        case default
          call GAPNOP(ak, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, &
                      node, npred, kstep, kinc)
        end select
        checksum = checksum + ak(1)
      end do
    end do
    call system_clock(t1)
    seconds = real(t1 - t0, dp) / real(rate, dp)
  end subroutine run_loop

  ! Times the routines in ROUTINES (best and median ns per call, indexed by routine) and
  ! returns the checksums of the timed outputs.
  subroutine time_case(routines, nrep, nrun, ns, nsmed, chk)
    integer, intent(in) :: routines(:), nrep, nrun
    real(dp), intent(out) :: ns(3), nsmed(3), chk(3)
    real(dp) :: t(nrun, 3), sec, percall
    integer :: r, j, k, m

    m = size(routines)
    chk = 0.0_dp
    ! Warm-up: caches, branch predictors, page faults, CPU clock.
    do j = 1, m
      call run_loop(routines(j), max(1, nrep / 4), chk(routines(j)), sec)
    end do
    chk = 0.0_dp
    t = 0.0_dp
    ! Rotating order: each routine runs first, second, ... equally often, so drift in machine
    ! load hits all alike.
    do r = 1, nrun
      do j = 1, m
        k = routines(1 + mod(j - 1 + r - 1, m))
        call run_loop(k, nrep, chk(k), sec)
        t(r, k) = sec
      end do
    end do
    percall = 1.0e9_dp / (real(nrep, dp) * real(npoints, dp))
    ns = 0.0_dp
    nsmed = 0.0_dp
    do j = 1, m
      k = routines(j)
      ns(k) = minval(t(:, k)) * percall
      nsmed(k) = median(t(:, k)) * percall
    end do
  end subroutine time_case

end module gapcon_bench_data

program bench_gapcon
  use gapcon_bench_data
  implicit none
  integer, parameter :: nlaws = 3, nlook = 4
  character(len=48), parameter :: law_label(nlaws) = [character(len=48) :: &
    'constant', 'pressure table, 100 rows', 'pressure table, 100 rows x 2 temperatures']
  character(len=9), parameter :: law_name(nlaws) = [character(len=9) :: &
    'GAP-CONST', 'GAP-PTAB', 'GAP-TTAB']
  ! Lookup rows: configuration, CINAME, and the configured k it must find.
  character(len=40), parameter :: look_label(nlook) = [character(len=40) :: &
    '1 interaction', '20 interactions + "*"', '20 interactions + "*"', '20 interactions + "*"']
  character(len=36), parameter :: look_what(nlook) = [character(len=36) :: &
    'INT-01 (the only entry)', 'INT-01 (1st of 20)', 'INT-20 (20th of 20)', &
    'INT-99 (not listed: "*")']
  real(dp), parameter :: look_k(nlook) = [101.0_dp, 101.0_dp, 120.0_dp, 99.0_dp]
  integer :: nrep, nrun, only, icase, first, last
  character(len=32) :: mode
  real(dp) :: ns(3), nsmed(3), chk(3), ak_ptab(npoints), ak_case(npoints)
  real(dp) :: ratio, net
  integer :: i, nbad

  if (command_argument_count() < 1) then
    write (*, '(a)') 'usage: bench_gapcon laws|lookup1|lookup20 [NREP [NRUN [CASE]]]'
    error stop 2
  end if
  call get_command_argument(1, mode)
  nrep = int_arg(2, 200)
  nrun = int_arg(3, 15)
  only = int_arg(4, 0)
  call prepare(7)

  select case (trim(mode))
  case ('laws')
    ! Agreement first, for every case: a disagreement means the timings compare different
    ! things.
    do icase = 1, nlaws
      ciname = law_name(icase)
      call check_points(trim(law_label(icase)), -1.0_dp, ak_case)
      if (icase == 1 .and. any(ak_case /= akcon)) then
        write (*, '(a)') 'bench_gapcon: GAP-CONST does not give k = 4500 everywhere'
        error stop 1
      end if
      if (icase == 2) ak_ptab = ak_case
      if (icase == 3) then
        ! At a mean temperature at or below the first one, the temperature table is the plain
        ! pressure table (same column of k), independently of GAPREF.
        nbad = 0
        do i = 1, npoints
          if (0.5_dp * (theta_a(i) + theta_b(i)) <= theta_lo .and. &
              ak_case(i) /= ak_ptab(i)) nbad = nbad + 1
        end do
        if (nbad > 0 .or. count(0.5_dp * (theta_a + theta_b) <= theta_lo) < 50) then
          write (*, '(a,i0,a)') 'bench_gapcon: GAP-TTAB differs from GAP-PTAB below theta = 20 at ', &
            nbad, ' points (or too few such points)'
          error stop 1
        end if
      end if
    end do

    call timing_table_head(npoints, nrep, nrun, 'GAPCON', 'GAPREF', '')
    do icase = 1, nlaws
      if (only /= 0 .and. icase /= only) cycle
      ciname = law_name(icase)
      call time_case([use_ours, use_ref, use_nop], nrep, nrun, ns, nsmed, chk)
      if (abs(chk(use_ours) - chk(use_ref)) > 1.0e-9_dp * abs(chk(use_ref))) then
        write (*, '(a,a,2es24.16)') 'bench_gapcon: checksums differ in ', &
          trim(law_label(icase)), chk(use_ours), chk(use_ref)
        error stop 4
      end if
      ratio = ns(use_ours) / ns(use_ref)
      net = (ns(use_ours) - ns(use_nop)) / (ns(use_ref) - ns(use_nop))
      write (*, '(a,a,a,f7.2,a,f7.2,a,f6.3,a,f6.3,a,f6.2,a,f6.3,a)') '| ', &
        trim(law_label(icase)), ' | ', ns(use_ours), ' | ', ns(use_ref), ' | ', ratio, ' | ', &
        nsmed(use_ours) / nsmed(use_ref), ' | ', ns(use_nop), ' | ', net, ' |'
    end do
    write (*, '(a)') ''
    write (*, '(a)') 'Checksums of the timed outputs agree (ours vs reference).'

  case ('lookup1', 'lookup20')
    if (trim(mode) == 'lookup1') then
      first = 1
      last = 1
    else
      first = 2
      last = nlook
    end if
    do icase = first, last
      ciname = look_what(icase)(1:6)
      call check_points(trim(look_what(icase)), look_k(icase), ak_case)
    end do
    do icase = first, last
      if (only /= 0 .and. icase /= only) cycle
      ciname = look_what(icase)(1:6)
      call time_case([use_ours, use_nop], nrep, nrun, ns, nsmed, chk)
      ! Every timed call (NRUN rounds of NREP sweeps) returned the configured k.
      if (chk(use_ours) /= look_k(icase) * real(nrun, dp) * real(nrep, dp) * real(npoints, dp)) &
        then
        write (*, '(a,a)') 'bench_gapcon: wrong checksum in ', trim(look_what(icase))
        error stop 4
      end if
      write (*, '(a,a,a,a,a,f7.2,a,f7.2,a,f6.2,a,f6.2,a)') '| ', trim(look_label(icase)), ' | ', &
        trim(look_what(icase)), ' | ', ns(use_ours), ' | ', nsmed(use_ours), ' | ', &
        ns(use_nop), ' | ', ns(use_ours) - ns(use_nop), ' |'
    end do

  case default
    write (*, '(a,a)') 'bench_gapcon: unknown mode ', trim(mode)
    error stop 2
  end select
end program bench_gapcon
