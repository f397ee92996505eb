! harness_omp.f90 -- the two runs of an OpenMP harness, shared by test_fric_omp.f90,
! test_uinter_omp.f90 (point harnesses: a history of increments per point) and
! test_fric_coef_omp.f90, test_vfric_omp.f90 (block harnesses: one call per block of points):
! the same work once from an OpenMP parallel loop (contiguous ranges per thread, at least 8
! threads must have done work) and once serially, each run judged against the law by the
! harness's own run_point / run_block (which report what breaks the law through
! point_violation / block_violation), then compared bit for bit (harness_threads).
! The Fortran side of th_point_runs / th_block_runs in c_tests/thread_harness.h.
!
! The size of a run is the same for every harness of a kind, about 1M calls: 4096 points of
! incs = 256 increments, or 16 384 blocks, block ib of block_points(ib) = 1..127 points
! (1 048 513 point evaluations). INTERFACIAL_TEST_SHRINK=n (valgrind runs) divides the number of
! points or blocks by n, down to 64 points or 512 blocks.
!
! Unlike harness_threads this module holds the parallel loop, so it is compiled with OpenMP:
! each OpenMP harness compiles it as an extra source (fortran_tests/CMakeLists.txt).

module harness_omp
  use, intrinsic :: iso_fortran_env, only: int64
  use harness_threads
  use omp_lib, only: omp_get_thread_num, omp_get_max_threads
  implicit none
  private
  public :: point_run, block_run, omp_point_runs, omp_block_runs, incs, block_points, &
    max_block_points, point_violation, block_violation

  integer, parameter :: full_points = 4096, incs = 256, min_points = 64
  integer, parameter :: full_blocks = 16384, max_block_points = 127, min_blocks = 512

  ! The violations of the law in the current run and the first one's text, shared by the
  ! threads (updated in one critical section, see violation).
  integer :: bad = 0
  character(len=256) :: first_bad = ' '

  abstract interface
    ! One point's history: the digest of each increment's outputs (dig), the point's final
    ! record (fin), the counts of each kind of call (kinds).
    subroutine point_run(ip, dig, fin, kinds)
      import :: int64, dp
      integer, intent(in) :: ip
      integer(int64), intent(out) :: dig(:)
      real(dp), intent(out) :: fin(:)
      integer(int64), intent(inout) :: kinds(:)
    end subroutine point_run

    ! One block: its digest (dig), kind, number of points and number of bad points in it.
    subroutine block_run(ib, dig, kind, npts, nbad_pts)
      import :: int64
      integer, intent(in) :: ib
      integer(int64), intent(out) :: dig(2)
      integer, intent(out) :: kind, npts, nbad_pts
    end subroutine block_run
  end interface

contains

  ! The number of points in block ib: 1, 2, ..., 127, 1, 2, ...
  recursive integer function block_points(ib)
    integer, intent(in) :: ib
    block_points = 1 + mod(ib - 1, max_block_points)
  end function block_points

  ! A violation of the law found by a harness's run_point (at increment inc of point ip) or
  ! run_block (in block ib): counted, and its text kept when it is the run's first.
  recursive subroutine point_violation(ip, inc, what)
    integer, intent(in) :: ip, inc
    character(len=*), intent(in) :: what
    character(len=48) :: where
    write (where, '(a,i0,a,i0)') 'point ', ip, ', increment ', inc
    call violation(trim(where)//': '//what)
  end subroutine point_violation

  recursive subroutine block_violation(ib, what)
    integer, intent(in) :: ib
    character(len=*), intent(in) :: what
    character(len=24) :: where
    write (where, '(a,i0)') 'block ', ib
    call violation(trim(where)//': '//what)
  end subroutine block_violation

  recursive subroutine violation(text)
    character(len=*), intent(in) :: text
    !$omp critical (harness_omp_violation)
    bad = bad + 1
    if (first_bad == ' ') first_bad = text
    !$omp end critical (harness_omp_violation)
  end subroutine violation

  ! The start of the two runs: a flag per OpenMP thread (set by the threads that do work);
  ! OpenMP must offer at least 8 threads.
  subroutine start_runs(worked)
    logical, allocatable, intent(out) :: worked(:)
    allocate (worked(0:max(omp_get_max_threads(), 1) - 1))
    worked = .false.
    call check(omp_get_max_threads() >= nthreads_min, 'OpenMP offers at least 8 threads '// &
               '(OMP_NUM_THREADS)')
    call start_run()
  end subroutine start_runs

  ! No violation yet in the run about to start.
  subroutine start_run()
    bad = 0
    first_bad = ' '
  end subroutine start_run

  ! The threads that did work in the parallel run; at least 8 must have.
  integer function workers(worked)
    logical, intent(in) :: worked(:)
    workers = count(worked)
    call check(workers >= nthreads_min, 'at least 8 OpenMP threads did work')
  end function workers

  ! The points of incs increments each (nrec entries in a point's final record), kinds of call
  ! named by names; entry names the routine in the report.
  subroutine omp_point_runs(entry, names, nrec, run_point)
    character(len=*), intent(in) :: entry, names(:)
    integer, intent(in) :: nrec
    procedure(point_run) :: run_point
    integer :: ip, npoints, nworkers
    integer(int64), allocatable :: dig_par(:, :), dig_ser(:, :)
    real(dp), allocatable :: fin_par(:, :), fin_ser(:, :)
    integer(int64) :: kinds_par(size(names)), kinds_ser(size(names)), calls
    logical, allocatable :: worked(:)

    npoints = full_points/shrink_factor(full_points/min_points)
    calls = int(npoints, int64)*incs
    allocate (dig_par(incs, npoints), dig_ser(incs, npoints), fin_par(nrec, npoints), &
              fin_ser(nrec, npoints))
    kinds_par = 0
    kinds_ser = 0
    call start_runs(worked)

    ! Contiguous blocks of points per thread.
    !$omp parallel do schedule(static) default(shared) private(ip) reduction(+:kinds_par)
    do ip = 1, npoints
      worked(omp_get_thread_num()) = .true.
      call run_point(ip, dig_par(:, ip), fin_par(:, ip), kinds_par)
    end do
    !$omp end parallel do
    nworkers = workers(worked)
    call judge_run('OpenMP', names, kinds_par, calls, bad, first_bad)

    call start_run()
    do ip = 1, npoints
      call run_point(ip, dig_ser(:, ip), fin_ser(:, ip), kinds_ser)
    end do
    call judge_run('serial', names, kinds_ser, calls, bad, first_bad)
    call compare_point_runs(entry, nworkers, names, kinds_par, kinds_ser, dig_par, dig_ser, &
                            fin_par, fin_ser)
    deallocate (dig_par, dig_ser, fin_par, fin_ser)
  end subroutine omp_point_runs

  ! The blocks, kinds of block named by names; law names what every block is checked against in
  ! the report. With_bad_points: the blocks together must hold at least one bad point per
  ! 2 size(names) blocks, the same ones in both runs.
  subroutine omp_block_runs(entry, law, names, run_block, with_bad_points)
    character(len=*), intent(in) :: entry, law, names(:)
    procedure(block_run) :: run_block
    logical, intent(in) :: with_bad_points
    integer :: ib, nblocks, shrink, nworkers
    integer(int64), allocatable :: dig_par(:, :), dig_ser(:, :)
    integer, allocatable :: kind_par(:), kind_ser(:), n_par(:), n_ser(:), b_par(:), b_ser(:)
    logical, allocatable :: worked(:)

    shrink = shrink_factor(full_blocks/min_blocks)
    nblocks = full_blocks/shrink
    allocate (dig_par(2, nblocks), dig_ser(2, nblocks), kind_par(nblocks), kind_ser(nblocks), &
              n_par(nblocks), n_ser(nblocks), b_par(nblocks), b_ser(nblocks))
    call start_runs(worked)

    !$omp parallel do schedule(static) default(shared) private(ib)
    do ib = 1, nblocks
      worked(omp_get_thread_num()) = .true.
      call run_block(ib, dig_par(:, ib), kind_par(ib), n_par(ib), b_par(ib))
    end do
    !$omp end parallel do
    nworkers = workers(worked)
    call report_violations('OpenMP', bad, first_bad)
    call check(bad == 0, 'every OpenMP block matches '//law)

    call start_run()
    do ib = 1, nblocks
      call run_block(ib, dig_ser(:, ib), kind_ser(ib), n_ser(ib), b_ser(ib))
    end do
    call report_violations('serial', bad, first_bad)
    call check(bad == 0, 'every serial block matches '//law)

    if (with_bad_points) then
      write (*, '(a,i0)') 'bad points: ', sum(b_par)
      call check(sum(b_par) >= nblocks/(2*size(names)), 'enough bad points')
      call check(all(b_par == b_ser), 'the same bad points in both runs')
    end if
    call compare_block_runs(entry, nworkers, shrink, names, kind_par, kind_ser, n_par, n_ser, &
                            dig_par, dig_ser)
    deallocate (dig_par, dig_ser, kind_par, kind_ser, n_par, n_ser, b_par, b_ser)
  end subroutine omp_block_runs
end module harness_omp
