! test_gapcon_omp.f90 -- GAPCON from an OpenMP parallel loop (OMP_NUM_THREADS = 8, set by CTest),
! compared bit for bit with a serial run of the same points. The Fortran twin of
! c_tests/test_gapcon_threads.c; GAPCON is called as Abaqus user code calls it: a plain
! `call gapcon(...)` with the 15 arguments and no interface block.
!
! 1 048 576 points (8 x 131 072), one GAPCON call each per run, spread over six interactions of
! configs/gapcon_good.toml (INTERFACIAL_CONFIG, set by CTest): T1CONST (constant), T1PTAB
! (pressure table), T1TEMP (pressure table in the mean temperature), RADK and RADC (radiation in
! kelvin and in Celsius) and GASRAD (gas gap plus radiation). Each point's inputs come from a
! Lehmer generator x <- 48271 x mod (2**31 - 1) seeded by the point's index, so they do not
! depend on which thread evaluates it. The threads take contiguous blocks of points and make
! the process's first call together, so they also race for the one-time read of the file.
! AK is allocated per point at exactly AK(5), so valgrind sees any write past it.
!
! Checked: AK(1) of every point bit for bit equal to the serial run's; AK(2..5) never written;
! AK(1) > 0; every fourth point, AK(1) bit for bit equal to k of ifl_gap_conductance (the native
! entry) on the same inputs; and AK(1) against the laws worked out by hand (scenes.md, T1/T2)
! for the constant, the pressure table and the temperature table inside their rows, and for
! radiation in kelvin and in Celsius. At least 8 OpenMP threads must have done work.
!
! INTERFACIAL_TEST_SHRINK=n divides the number of points by n (valgrind runs).
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

module gapcon_omp_support
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: iso_c_binding, only: c_int, c_null_char
  use harness_threads
  implicit none
  integer, parameter :: full_points = 8*131072, min_points = 8192
  real(dp), parameter :: guard = -3.33e33_dp, sigma = 5.670374419e-8_dp, view = 0.8_dp

  integer, parameter :: n_laws = 6
  character(len=8), parameter :: names(n_laws) = [character(len=8) :: 'T1CONST', 'T1PTAB', &
    'T1TEMP', 'RADK', 'RADC', 'GASRAD']

contains

  ! Point ip: its law, clearance d, pressure p and surface temperatures ta, tb.
  subroutine point_inputs(ip, law, d, p, ta, tb)
    integer, intent(in) :: ip
    integer, intent(out) :: law
    real(dp), intent(out) :: d, p, ta, tb
    integer(int64) :: rng
    integer :: i
    rng = int(mod(ip, int(lehmer_m) - 1), int64) + 1_int64
    do i = 1, 3
      d = uniform(rng, 0.0_dp, 1.0_dp)
    end do
    law = min(int(uniform(rng, 0.0_dp, real(n_laws, dp))) + 1, n_laws)
    d = uniform(rng, -1.0e-5_dp, 2.0e-3_dp)
    p = uniform(rng, -5.0_dp, 115.0_dp)
    ! Kelvin for the laws whose file says absolute_zero = 0 (and T1TEMP's 300..400 rows).
    ta = uniform(rng, 250.0_dp, 450.0_dp)
    tb = uniform(rng, 250.0_dp, 450.0_dp)
    if (law == 5) then ! RADC: Celsius
      ta = ta - 273.15_dp
      tb = tb - 273.15_dp
    end if
  end subroutine point_inputs

  ! GAPCON at point ip: AK(1) into k; intact = AK(2..5) still hold the guard.
  subroutine eval_point(ip, k, intact)
    integer, intent(in) :: ip
    real(dp), intent(out) :: k
    logical, intent(out) :: intact
    real(dp), allocatable :: ak(:)
    real(dp) :: d(2), flowm(2), temp(2), predef(2, 1), time(2), coords(3)
    character(len=80) :: ciname, slname, msname
    integer :: law, noel, node, npred, kstep, kinc
    allocate (ak(5))
    ak = guard
    call point_inputs(ip, law, d(1), d(2), temp(1), temp(2))
    flowm = 0.0_dp
    predef = 0.0_dp
    time = [0.0_dp, 1.0_dp]
    coords = 0.0_dp
    ciname = names(law)
    slname = 'SLAVE_SURF'
    msname = 'MASTER_SURF'
    noel = ip
    node = ip
    npred = 1
    kstep = 1
    kinc = 1
    call gapcon(ak, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, node, &
                npred, kstep, kinc)
    k = ak(1)
    intact = all(transfer(ak(2:5), 0_int64, 4) == transfer(guard, 0_int64))
    deallocate (ak)
  end subroutine eval_point

  ! AK(1) by hand where the law is simple enough; known = .false. elsewhere.
  subroutine by_hand(ip, k, known)
    integer, intent(in) :: ip
    real(dp), intent(out) :: k
    logical, intent(out) :: known
    integer :: law
    real(dp) :: d, p, ta, tb, a, b, w
    call point_inputs(ip, law, d, p, ta, tb)
    known = .true.
    select case (law)
    case (1)
      k = 2000.0_dp
    case (2) ! [[0, 500], [100, 3000]]
      k = 500.0_dp + 25.0_dp*p
      known = p >= 0.0_dp .and. p <= 100.0_dp
    case (3) ! k(p) = 500 + 10 p at 300, 900 + 16 p at 400, linear in the mean temperature
      w = (0.5_dp*(ta + tb) - 300.0_dp)/100.0_dp
      k = (1.0_dp - w)*(500.0_dp + 10.0_dp*p) + w*(900.0_dp + 16.0_dp*p)
      known = p >= 0.0_dp .and. p <= 100.0_dp .and. w >= 0.0_dp .and. w <= 1.0_dp
    case (4, 5)
      a = ta
      b = tb
      if (law == 5) then
        a = ta + 273.15_dp
        b = tb + 273.15_dp
      end if
      k = view*sigma*(a + b)*(a*a + b*b)
    case default
      k = 0.0_dp
      known = .false.
    end select
  end subroutine by_hand

end module gapcon_omp_support

program test_gapcon_omp
  use gapcon_omp_support
  use omp_lib, only: omp_get_thread_num, omp_get_max_threads
  implicit none
  integer :: npoints, ip, law, nworkers, ndiff, nguard, npos, nnat, nhand, nchecked, i
  integer :: per_law(n_laws)
  real(dp), allocatable :: ak_par(:), ak_ser(:)
  logical, allocatable :: ok_par(:), ok_ser(:), worked(:)
  real(dp) :: k, d, p, ta, tb
  logical :: known
  type(ifl_conductance) :: nat
  integer(c_int) :: status

  npoints = full_points/shrink_factor(full_points/min_points)
  allocate (ak_par(npoints), ak_ser(npoints), ok_par(npoints), ok_ser(npoints), &
            worked(0:max(omp_get_max_threads(), 1) - 1))
  worked = .false.
  call check(omp_get_max_threads() >= nthreads_min, 'OpenMP offers at least 8 threads '// &
             '(OMP_NUM_THREADS)')

  ! Contiguous blocks of points per thread; the first GAPCON call of the process is in here.
  !$omp parallel do schedule(static) default(shared) private(ip)
  do ip = 1, npoints
    worked(omp_get_thread_num()) = .true.
    call eval_point(ip, ak_par(ip), ok_par(ip))
  end do
  !$omp end parallel do
  nworkers = count(worked)
  call check(nworkers >= nthreads_min, 'at least 8 OpenMP threads did work')

  do ip = 1, npoints
    call eval_point(ip, ak_ser(ip), ok_ser(ip))
  end do

  ndiff = count(transfer(ak_par, 0_int64, npoints) /= transfer(ak_ser, 0_int64, npoints))
  nguard = count(.not. ok_par) + count(.not. ok_ser)
  npos = count(.not. ak_ser > 0.0_dp)
  call check(ndiff == 0, 'AK(1) bit for bit equal to the serial run at every point')
  call check(nguard == 0, 'AK(2..5) never written')
  call check(npos == 0, 'AK(1) > 0 at every point')

  ! The native entry agrees; the simple laws agree with the hand formulas.
  nnat = 0
  nhand = 0
  nchecked = 0
  per_law = 0
  do ip = 1, npoints
    call point_inputs(ip, law, d, p, ta, tb)
    per_law(law) = per_law(law) + 1
    if (mod(ip, 4) == 0) then
      status = ifl_gap_conductance(trim(names(law))//c_null_char, d, p, ta, tb, nat)
      if (status /= 0 .or. transfer(nat%k, 0_int64) /= transfer(ak_ser(ip), 0_int64)) &
        nnat = nnat + 1
    end if
    call by_hand(ip, k, known)
    if (known) then
      nchecked = nchecked + 1
      if (.not. abs(ak_ser(ip) - k) <= 1.0e-13_dp*abs(k)) then
        nhand = nhand + 1
        if (nhand <= 5) write (*, '(a,i0,1x,a,a,1p,2e24.16)') '  point ', ip, trim(names(law)), &
          ': AK(1), by hand ', ak_ser(ip), k
      end if
    end if
  end do
  call check(nnat == 0, 'ifl_gap_conductance k bit for bit equal to AK(1)')
  call check(nhand == 0, 'AK(1) equal to the hand formulas')
  call check(nchecked > npoints/2, 'more than half the points checked by hand')
  do i = 1, n_laws
    call check(per_law(i) > npoints/(2*n_laws), 'each law well represented: '//trim(names(i)))
  end do
  write (*, '(i0,a,i0,a,i0,a,i0,a,i0,a)') npoints, ' GAPCON calls on ', nworkers, &
    ' OpenMP threads and ', npoints, ' serial: ', ndiff, ' AK(1) differences; ', nchecked, &
    ' checked by hand'

  deallocate (ak_par, ak_ser, ok_par, ok_ser, worked)
  call finish()
end program test_gapcon_omp
