! harness_omp.f90 -- the two runs of an OpenMP harness, shared by test_fric_omp.f90,
! test_uinter_omp.f90 (point harnesses: a history of increments per point) and
! test_fric_coef_omp.f90, test_vfric_omp.f90 (block harnesses: one call per block of points):
! the same work once from an OpenMP parallel loop (contiguous ranges per thread, at least 8
! threads must have done work) and once serially, each run judged against the law by the
! harness's own run_point / run_block, then compared bit for bit (harness_threads).
! The Fortran side of th_point_runs / th_block_runs in c_tests/thread_harness.h.
!
! Unlike harness_threads this module holds the parallel loop, so it is compiled with OpenMP:
! each OpenMP harness compiles it as an extra source (fortran_tests/CMakeLists.txt).

module harness_omp
  use, intrinsic :: iso_fortran_env, only: int64
  use harness_threads
  use omp_lib, only: omp_get_thread_num, omp_get_max_threads
  implicit none
  private
  public :: point_run, block_run, omp_point_runs, omp_block_runs

  abstract interface
    ! One point's history: the digest of each increment's outputs (dig), the point's final
    ! record (fin), the counts of each kind of call (kinds), the violations of the law (bad,
    ! and the first one's text).
    subroutine point_run(ip, dig, fin, kinds, bad, first_bad)
      import :: int64, dp
      integer, intent(in) :: ip
      integer(int64), intent(out) :: dig(:)
      real(dp), intent(out) :: fin(:)
      integer(int64), intent(inout) :: kinds(:)
      integer, intent(inout) :: bad
      character(len=*), intent(inout) :: first_bad
    end subroutine point_run

    ! One block: its digest (dig), kind, number of points, number of bad points in it, the
    ! violations of the law (bad, and the first one's text).
    subroutine block_run(ib, dig, kind, npts, nbad_pts, bad, first_bad)
      import :: int64
      integer, intent(in) :: ib
      integer(int64), intent(out) :: dig(2)
      integer, intent(out) :: kind, npts, nbad_pts
      integer, intent(inout) :: bad
      character(len=256), intent(inout) :: first_bad
    end subroutine block_run
  end interface

contains

  ! The start of the two runs: a flag per OpenMP thread (set by the threads that do work), the
  ! violation counts and first texts cleared; OpenMP must offer at least 8 threads.
  subroutine start_runs(worked, bad_par, bad_ser, first_par, first_ser)
    logical, allocatable, intent(out) :: worked(:)
    integer, intent(out) :: bad_par, bad_ser
    character(len=*), intent(out) :: first_par, first_ser
    allocate (worked(0:max(omp_get_max_threads(), 1) - 1))
    worked = .false.
    bad_par = 0
    bad_ser = 0
    first_par = ' '
    first_ser = ' '
    call check(omp_get_max_threads() >= nthreads_min, 'OpenMP offers at least 8 threads '// &
               '(OMP_NUM_THREADS)')
  end subroutine start_runs

  ! The threads that did work in the parallel run; at least 8 must have.
  integer function workers(worked)
    logical, intent(in) :: worked(:)
    workers = count(worked)
    call check(workers >= nthreads_min, 'at least 8 OpenMP threads did work')
  end function workers

  ! npoints points of incs increments each (nrec entries in a point's final record), kinds of
  ! call named by names; entry names the routine in the report.
  subroutine omp_point_runs(entry, names, npoints, incs, nrec, run_point)
    character(len=*), intent(in) :: entry, names(:)
    integer, intent(in) :: npoints, incs, nrec
    procedure(point_run) :: run_point
    integer :: ip, bad_par, bad_ser, nworkers
    integer(int64), allocatable :: dig_par(:, :), dig_ser(:, :)
    real(dp), allocatable :: fin_par(:, :), fin_ser(:, :)
    integer(int64) :: kinds_par(size(names)), kinds_ser(size(names)), calls
    logical, allocatable :: worked(:)
    character(len=256) :: first_par, first_ser

    calls = int(npoints, int64)*incs
    allocate (dig_par(incs, npoints), dig_ser(incs, npoints), fin_par(nrec, npoints), &
              fin_ser(nrec, npoints))
    kinds_par = 0
    kinds_ser = 0
    call start_runs(worked, bad_par, bad_ser, first_par, first_ser)

    ! Contiguous blocks of points per thread.
    !$omp parallel do schedule(static) default(shared) private(ip) &
    !$omp reduction(+:kinds_par, bad_par)
    do ip = 1, npoints
      worked(omp_get_thread_num()) = .true.
      call run_point(ip, dig_par(:, ip), fin_par(:, ip), kinds_par, bad_par, first_par)
    end do
    !$omp end parallel do
    nworkers = workers(worked)
    call judge_run('OpenMP', names, kinds_par, calls, bad_par, first_par)

    do ip = 1, npoints
      call run_point(ip, dig_ser(:, ip), fin_ser(:, ip), kinds_ser, bad_ser, first_ser)
    end do
    call judge_run('serial', names, kinds_ser, calls, bad_ser, first_ser)
    call compare_point_runs(entry, nworkers, names, kinds_par, kinds_ser, dig_par, dig_ser, &
                            fin_par, fin_ser)
    deallocate (dig_par, dig_ser, fin_par, fin_ser)
  end subroutine omp_point_runs

  ! nblocks blocks (full size divided by shrink), kinds of block named by names; law names what
  ! every block is checked against in the report. With min_bad_points, the blocks together
  ! must hold at least that many bad points, the same ones in both runs.
  subroutine omp_block_runs(entry, law, names, nblocks, shrink, run_block, min_bad_points)
    character(len=*), intent(in) :: entry, law, names(:)
    integer, intent(in) :: nblocks, shrink
    procedure(block_run) :: run_block
    integer, intent(in), optional :: min_bad_points
    integer :: ib, bad_par, bad_ser, nworkers
    integer(int64), allocatable :: dig_par(:, :), dig_ser(:, :)
    integer, allocatable :: kind_par(:), kind_ser(:), n_par(:), n_ser(:), b_par(:), b_ser(:)
    logical, allocatable :: worked(:)
    character(len=256) :: first_par, first_ser

    allocate (dig_par(2, nblocks), dig_ser(2, nblocks), kind_par(nblocks), kind_ser(nblocks), &
              n_par(nblocks), n_ser(nblocks), b_par(nblocks), b_ser(nblocks))
    call start_runs(worked, bad_par, bad_ser, first_par, first_ser)

    !$omp parallel do schedule(static) default(shared) private(ib)
    do ib = 1, nblocks
      worked(omp_get_thread_num()) = .true.
      call run_block(ib, dig_par(:, ib), kind_par(ib), n_par(ib), b_par(ib), bad_par, first_par)
    end do
    !$omp end parallel do
    nworkers = workers(worked)
    call report_violations('OpenMP', bad_par, first_par)
    call check(bad_par == 0, 'every OpenMP block matches '//law)

    do ib = 1, nblocks
      call run_block(ib, dig_ser(:, ib), kind_ser(ib), n_ser(ib), b_ser(ib), bad_ser, first_ser)
    end do
    call report_violations('serial', bad_ser, first_ser)
    call check(bad_ser == 0, 'every serial block matches '//law)

    if (present(min_bad_points)) then
      write (*, '(a,i0)') 'bad points: ', sum(b_par)
      call check(sum(b_par) >= min_bad_points, 'enough bad points')
      call check(all(b_par == b_ser), 'the same bad points in both runs')
    end if
    call compare_block_runs(entry, nworkers, shrink, names, kind_par, kind_ser, n_par, n_ser, &
                            dig_par, dig_ser)
    deallocate (dig_par, dig_ser, kind_par, kind_ser, n_par, n_ser, b_par, b_ser)
  end subroutine omp_block_runs
end module harness_omp
