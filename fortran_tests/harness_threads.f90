! harness_threads.f90 -- what the OpenMP harnesses (test_*_omp.f90) share, next to the tally of
! harness_tally.f90 (which it passes on: a harness that uses this module has check, npass,
! nfail, dp, last_error and ifl_clear_error too). The Fortran side of c_tests/thread_harness.h.
!
! Each OpenMP harness runs the same work twice, once in an OpenMP parallel loop and once
! serially, and compares the two bit for bit. Shared here:
!   - lehmer / uniform: the MINSTD generator x <- 48271 x mod (2**31 - 1), seeded per point or
!     per block by the harness, so a draw never depends on the thread that makes it;
!   - digest: two multiplicative hashes mod 2**31 - 1 over the 32-bit halves of each value's bit
!     pattern (h(1), h(2)), for a real, an array of reals or a 64-bit pattern; digest_of(h)
!     folds them into one 62-bit number; same_bits compares two reals bit for bit;
!   - shrink_factor: INTERFACIAL_TEST_SHRINK=n (valgrind runs), clamped;
!   - report_kinds / report_violations: a run's counts and its first violation, printed;
!     judge_run: both, and the check that the run had no violation;
!   - compare_point_runs: the end of a harness of points carried over increments (FRIC, UINTER):
!     every kind of call well represented, the same counts, every call's digest and every
!     point's final record bit for bit; compare_block_runs: the same for a harness of blocks
!     (FRIC_COEF, VFRIC); finish: the last line and the exit status.
! No OpenMP directive lives here (this module is built without -fopenmp): the parallel loop is
! in harness_omp.f90 (compiled with OpenMP into each OpenMP harness), the critical section around
! a harness's first violation stays in the harness. The procedures
! the threads call are RECURSIVE, so their locals live on each thread's stack even without
! -fopenmp (and -fcheck=recursion does not take two threads in one for a recursion).
module harness_threads
  use, intrinsic :: iso_fortran_env, only: int64
  use harness_tally
  implicit none
  ! OMP_NUM_THREADS set by CTest; at least this many threads must have done work.
  integer, parameter :: nthreads_min = 8
  integer(int64), parameter :: lehmer_m = 2147483647_int64

  interface digest
    module procedure digest_bits, digest_real, digest_reals
  end interface digest

contains

  recursive integer(int64) function lehmer(x)
    integer(int64), intent(inout) :: x
    x = mod(48271_int64*x, lehmer_m)
    lehmer = x
  end function lehmer

  ! The generator's state for block ib of a block harness: ib scattered by Knuth's
  ! multiplicative hash into [1, m - 1], then advanced once.
  recursive function block_seed(ib) result(x)
    integer, intent(in) :: ib
    integer(int64) :: x
    x = mod(int(ib, int64)*2654435761_int64, lehmer_m - 1) + 1
    x = mod(48271_int64*x, lehmer_m)
  end function block_seed

  ! Uniform in [lo, hi) from the generator's next value.
  recursive real(dp) function uniform(x, lo, hi)
    integer(int64), intent(inout) :: x
    real(dp), intent(in) :: lo, hi
    uniform = lo + (hi - lo)*(real(lehmer(x) - 1_int64, dp)/real(lehmer_m - 1_int64, dp))
  end function uniform

  ! Folds a 64-bit pattern into the two hashes (no product exceeds 2**48).
  recursive subroutine digest_bits(h, bits)
    integer(int64), intent(inout) :: h(2)
    integer(int64), intent(in) :: bits
    integer(int64) :: lo, hi
    lo = iand(bits, 4294967295_int64)
    hi = iand(ishft(bits, -32), 4294967295_int64)
    h(1) = mod(mod(h(1)*48271_int64 + lo, lehmer_m)*48271_int64 + hi, lehmer_m)
    h(2) = mod(mod(h(2)*16807_int64 + hi, lehmer_m)*16807_int64 + lo, lehmer_m)
  end subroutine digest_bits

  recursive subroutine digest_real(h, v)
    integer(int64), intent(inout) :: h(2)
    real(dp), intent(in) :: v
    call digest_bits(h, transfer(v, 0_int64))
  end subroutine digest_real

  recursive subroutine digest_reals(h, v)
    integer(int64), intent(inout) :: h(2)
    real(dp), intent(in) :: v(:)
    integer :: i
    do i = 1, size(v)
      call digest_bits(h, transfer(v(i), 0_int64))
    end do
  end subroutine digest_reals

  ! The two hashes as one number below 2**62.
  recursive integer(int64) function digest_of(h)
    integer(int64), intent(in) :: h(2)
    digest_of = h(1)*lehmer_m + h(2)
  end function digest_of

  recursive logical function same_bits(a, b)
    real(dp), intent(in) :: a, b
    same_bits = transfer(a, 0_int64) == transfer(b, 0_int64)
  end function same_bits

  ! INTERFACIAL_TEST_SHRINK=n divides a harness's size by n; at most max_shrink, at least 1.
  integer function shrink_factor(max_shrink)
    integer, intent(in) :: max_shrink
    character(len=32) :: v
    integer :: stat, n
    shrink_factor = 1
    call get_environment_variable('INTERFACIAL_TEST_SHRINK', v, status=stat)
    if (stat /= 0) return
    read (v, *, iostat=stat) n
    if (stat /= 0 .or. n < 1) return
    shrink_factor = min(n, max_shrink)
  end function shrink_factor

  ! "<run>: <head>; <name> <count> ..." on one line.
  subroutine report_kinds(run, head, names, kinds)
    character(len=*), intent(in) :: run, head, names(:)
    integer(int64), intent(in) :: kinds(:)
    integer :: k
    write (*, '(a,a,a,a)', advance='no') run, ': ', head, ';'
    do k = 1, size(kinds)
      write (*, '(1x,a,1x,i0)', advance='no') trim(names(k)), kinds(k)
    end do
    write (*, '()')
  end subroutine report_kinds

  ! "  <run>: <bad> violations, first: <first>" when there was one.
  subroutine report_violations(run, bad, first)
    character(len=*), intent(in) :: run, first
    integer, intent(in) :: bad
    if (bad > 0) write (*, '(a,a,a,i0,a,a)') '  ', run, ': ', bad, ' violations, first: ', &
      trim(first)
  end subroutine report_violations

  ! A run's counts ("<calls> calls; <kind> <count> ...") and its first violation printed, and
  ! checked that it had none.
  subroutine judge_run(run, names, kinds, calls, bad, first)
    character(len=*), intent(in) :: run, names(:), first
    integer(int64), intent(in) :: kinds(:), calls
    integer, intent(in) :: bad
    character(len=32) :: head
    write (head, '(i0,a)') calls, ' calls'
    call report_kinds(run, trim(head), names, kinds)
    call report_violations(run, bad, first)
    call check(bad == 0, 'every '//run//' call obeys the law')
  end subroutine judge_run

  ! The two runs of a point harness against each other: enough calls of each kind in the serial
  ! run (at least one and 1 in 2000), the same counts of each kind, the digest of every call
  ! (dig(increment, point)) and the final record of every point (fin(:, point)) bit for bit.
  subroutine compare_point_runs(entry, nworkers, names, kinds_par, kinds_ser, dig_par, dig_ser, &
                                fin_par, fin_ser)
    character(len=*), intent(in) :: entry, names(:)
    integer, intent(in) :: nworkers
    integer(int64), intent(in) :: kinds_par(:), kinds_ser(:), dig_par(:, :), dig_ser(:, :)
    real(dp), intent(in) :: fin_par(:, :), fin_ser(:, :)
    integer(int64) :: calls
    integer :: k, ip, ndiff, nfin, nrec
    calls = int(size(dig_ser), int64)
    do k = 1, size(kinds_ser)
      call check(kinds_ser(k) > 0 .and. kinds_ser(k) >= calls/2000, &
                 'serial run: enough calls of kind '//trim(names(k)))
    end do
    ndiff = count(dig_par /= dig_ser)
    nrec = size(fin_ser, 1)
    nfin = 0
    do ip = 1, size(fin_ser, 2)
      if (any(transfer(fin_par(:, ip), 0_int64, nrec) /= transfer(fin_ser(:, ip), 0_int64, nrec))) &
        nfin = nfin + 1
    end do
    call check(all(kinds_par == kinds_ser), 'same counts of each kind in both runs')
    call check(ndiff == 0, 'every call: outputs bit for bit equal to the serial run')
    call check(nfin == 0, 'every point: final state bit for bit equal to the serial run')
    write (*, '(i0,a,a,a,i0,a,i0,a,i0,a,i0,a)') calls, ' ', entry, ' calls on ', nworkers, &
      ' OpenMP threads and ', calls, ' serial: ', ndiff, ' calls and ', nfin, &
      ' final states differ'
  end subroutine compare_point_runs

  ! The two runs of a block harness against each other: every kind of block (names) in at
  ! least 1 in 2 n_kinds blocks, at least 1M point evaluations at full size (divided by
  ! shrink), the same kind and size of every block, and every block's digest bit for bit.
  subroutine compare_block_runs(entry, nworkers, shrink, names, kind_par, kind_ser, n_par, &
                                n_ser, dig_par, dig_ser)
    character(len=*), intent(in) :: entry, names(:)
    integer, intent(in) :: nworkers, shrink, kind_par(:), kind_ser(:), n_par(:), n_ser(:)
    integer(int64), intent(in) :: dig_par(:, :), dig_ser(:, :)
    integer(int64) :: points
    integer :: k, nblocks, ndiff
    nblocks = size(kind_par)
    points = sum(int(n_par, int64))
    write (*, '(a,i0,a,i0,a)', advance='no') 'blocks ', nblocks, ', point evaluations ', &
      points, ', per kind:'
    do k = 1, size(names)
      write (*, '(1x,a,1x,i0)', advance='no') trim(names(k)), count(kind_par == k)
      call check(count(kind_par == k) >= nblocks/(2*size(names)), 'enough blocks of kind '// &
                 trim(names(k)))
    end do
    write (*, '()')
    call check(points >= 1000000_int64/shrink, 'at least 1M point evaluations (full size)')
    call check(all(kind_par == kind_ser) .and. all(n_par == n_ser), 'same blocks in both runs')
    ndiff = count(dig_par(1, :) /= dig_ser(1, :) .or. dig_par(2, :) /= dig_ser(2, :))
    call check(ndiff == 0, 'every block: outputs bit for bit equal to the serial run')
    write (*, '(i0,a,a,a,i0,a,i0,a)') nblocks, ' ', entry, ' blocks on ', nworkers, &
      ' OpenMP threads and serially: ', ndiff, ' blocks differ'
  end subroutine compare_block_runs
end module harness_threads
