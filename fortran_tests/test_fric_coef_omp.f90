! test_fric_coef_omp.f90 -- FRIC_COEF (the friction coefficient of a block of points) from an
! OpenMP parallel loop (OMP_NUM_THREADS = 8, set by CTest), compared bit for bit with a serial
! run of the same blocks. The Fortran twin of c_tests/test_fric_coef_threads.c; FRIC_COEF is
! called as Abaqus user code calls it: a plain `call fric_coef(...)`, no interface block.
!
! 16 384 blocks of 1..127 points (nBlock = 1 + mod(b-1, 127)): 1 048 513 point evaluations per
! run. Each block has its own law-1 PROPS drawn from a Lehmer generator x <- 48271 x mod
! (2**31 - 1) seeded by the block's index, one of eight mu laws (docs/props.md): constant,
! anisotropic, exponential decay, decay + pressure, decay + temperature, pressure + temperature
! anisotropic, all of them, and a block with one bad point (NaN pressure or a negative slip
! rate: refused). Every array is allocated at exactly its declared size, so valgrind sees any
! access past it; a valgrind run sets INTERFACIAL_TEST_SHRINK=n for 1/n of the blocks (sizes in
! harness_omp.f90).
!
! Compared with the serial run: every output of every block (fCoef(nBlock,2) and
! fCoefDeriv(nBlock,20,2)), bit patterns folded into a 62-bit digest per block (two
! multiplicative hashes mod 2**31 - 1 over the 32-bit halves), and the counts of each law.
! Checked on every block of both runs against the closed form, not against the library:
! mu_d = (mu_s,d e + mu_k,d (1 - e)) / (1 + p+/p_ref) exp(-b (theta - theta_ref)),
! e = exp(-d_c rate), to 1e-13 relative; d mu/d rate = -d_c (mu_s - mu_k) e pi Theta;
! fCoefDeriv(k,4:20,d) = 0; a refused block has mu = 0, every derivative 0 and a message
! naming FRIC_COEF. At least 8 OpenMP threads must have done work.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

module fric_coef_omp_support
  use harness_threads
  use harness_omp, only: block_points, block_violation
  implicit none
  integer, parameter :: nprops = 13, n_laws = 8, law_bad = 8
  character(len=32), parameter :: law_names(n_laws) = [character(len=32) :: 'constant', &
    'anisotropic', 'decay', 'decay+pressure', 'decay+temperature', &
    'pressure+temperature aniso', 'all', 'refused']

contains

  ! Calls FRIC_COEF for block ib, checks it, returns its digest and law.
  ! nbad_pts: always 0 (FRIC_COEF refuses a block as a whole, law_bad).
  subroutine run_block(ib, dig, law, npts, nbad_pts)
    integer, intent(in) :: ib
    integer(int64), intent(out) :: dig(2)
    integer, intent(out) :: law, npts, nbad_pts
    integer(int64) :: x
    integer :: n, k, d, j, ntemp, nfields, idata(3), npr
    real(dp) :: props(nprops), rdata(3), field(1), pp, e, ome, mk(2), ms(2), pi, th, mu, dr
    real(dp), allocatable :: coef(:, :), deriv(:, :, :), slip(:, :), press(:), temp(:)
    character(len=80) :: name, blank
    character(len=2048) :: msg
    logical :: decay, pref, tlaw
    character(len=200) :: what

    x = block_seed(ib)
    law = int(mod(lehmer(x), int(n_laws, int64))) + 1
    n = block_points(ib)
    npts = n
    nbad_pts = 0
    props = 0
    props(1) = 1
    props(2) = uniform(x, 0.05_dp, 0.9_dp)
    if (law == 2 .or. law == 6 .or. law == 7) props(3) = uniform(x, 0.05_dp, 0.9_dp)
    decay = law == 3 .or. law == 4 .or. law == 5 .or. law == 7 .or. law == law_bad
    pref = law == 4 .or. law == 6 .or. law == 7
    tlaw = law == 5 .or. law == 6 .or. law == 7
    if (decay) then
      props(8) = 1
      if (mod(lehmer(x), 4_int64) == 0) then
        props(9) = props(2)*uniform(x, 0.0_dp, 3.0_dp)
      else
        props(9) = props(2)*uniform(x, 0.0_dp, 1.0_dp)
      end if
      props(10) = uniform(x, 0.1_dp, 10.0_dp)
    end if
    if (pref) props(11) = uniform(x, 10.0_dp, 500.0_dp)
    if (tlaw) then
      props(12) = uniform(x, -0.01_dp, 0.01_dp)
      props(13) = uniform(x, 0.0_dp, 100.0_dp)
      ntemp = 1
    else
      ntemp = int(mod(lehmer(x), 2_int64))
    end if
    allocate (coef(n, 2), deriv(n, 20, 2), slip(n, 6), press(n), temp(n))
    do j = 1, 6
      do k = 1, n
        slip(k, j) = uniform(x, 0.0_dp, 5.0_dp)
      end do
    end do
    do k = 1, n
      if (mod(lehmer(x), 8_int64) == 0) slip(k, 1) = 0
      press(k) = uniform(x, -20.0_dp, 300.0_dp)
      temp(k) = uniform(x, 0.0_dp, 200.0_dp)
    end do
    if (law == law_bad) then
      k = 1 + int(mod(lehmer(x), int(n, int64)))
      if (mod(lehmer(x), 2_int64) == 0) then
        press(k) = quiet_nan()
      else
        slip(k, 1) = -uniform(x, 0.1_dp, 1.0_dp)
      end if
    end if
    coef = -7.77e77_dp
    deriv = -7.77e77_dp
    write (name, '(a,i0)') 'CF', ib
    blank = ' '
    nfields = 0
    idata = 1
    rdata = 0
    field = 0
    npr = nprops
    call ifl_clear_error()
    call fric_coef(coef, deriv, n, npr, ntemp, nfields, idata, rdata, name, blank, blank, &
                   props, slip, press, temp, field)
    dig = 0
    call digest(dig, reshape(coef, [2*n]))
    call digest(dig, reshape(deriv, [40*n]))

    what = ' '
    msg = last_error()
    if (law == law_bad) then
      if (any(coef /= 0) .or. any(deriv /= 0)) what = 'refused block not zeroed'
      if (len_trim(msg) < 40 .or. index(msg, 'interfacial: FRIC_COEF: interaction') /= 1) what = 'refusal message lacks FRIC_COEF'
    else
      if (msg /= ' ') what = 'a good block left a message'
      ms = [props(2), merge(props(3), props(2), props(3) /= 0)]
      do k = 1, n
        pp = max(press(k), 0.0_dp)
        e = 1
        ome = 0
        mk = 0
        if (decay) then
          e = exp(-props(10)*slip(k, 1))
          ome = -(exp(-props(10)*slip(k, 1)) - 1)
          if (props(10)*slip(k, 1) < 0.5_dp) ome = -expm1_series(-props(10)*slip(k, 1))
          mk = [props(9), props(9)*ms(2)/ms(1)]
        end if
        pi = 1
        if (pref) pi = 1/(1 + pp/props(11))
        th = 1
        if (tlaw) th = exp(-props(12)*(temp(k) - props(13)))
        do d = 1, 2
          mu = (ms(d)*e + mk(d)*ome)*pi*th
          dr = -props(10)*(ms(d) - mk(d))*e*pi*th
          if (.not. (abs(coef(k, d) - mu) <= 1e-13_dp*mu)) write (what, '(a,i0,a,i0,a,2es25.17)') &
            'mu(', k, ',', d, ')', coef(k, d), mu
          if (.not. (abs(deriv(k, 1, d) - dr) <= 4e-12_dp*props(10)*props(2))) &
            write (what, '(a,i0,2es25.17)') 'd mu/d rate at ', k, deriv(k, 1, d), dr
          if ((press(k) < 0 .or. .not. pref) .and. deriv(k, 2, d) /= 0) what = 'd mu/d p not 0'
          if (.not. tlaw .and. deriv(k, 3, d) /= 0) what = 'd mu/d theta not 0'
          if (any(deriv(k, 4:20, d) /= 0)) what = 'fCoefDeriv(k,4:20,d) not 0'
        end do
      end do
    end if
    if (what /= ' ') call block_violation(ib, trim(what))
    deallocate (coef, deriv, slip, press, temp)
  end subroutine run_block

  ! -expm1 is not in Fortran 2008: 1 - e**y for |y| < 0.5 by its series (to round-off).
  real(dp) function expm1_series(y)
    real(dp), intent(in) :: y
    real(dp) :: term
    integer :: i
    term = y
    expm1_series = y
    do i = 2, 30
      term = term*y/i
      expm1_series = expm1_series + term
    end do
  end function expm1_series

end module fric_coef_omp_support

program test_fric_coef_omp
  use fric_coef_omp_support
  use harness_omp
  implicit none

  call omp_block_runs('FRIC_COEF', 'the closed form', law_names, run_block, .false.)
  call finish()
end program test_fric_coef_omp
