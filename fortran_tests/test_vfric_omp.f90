! test_vfric_omp.f90 -- VFRIC (Abaqus/Explicit, double precision: the friction force of a block
! of contact points) from an OpenMP parallel loop (OMP_NUM_THREADS = 8, set by CTest), compared
! bit for bit with a serial run of the same blocks. The Fortran twin of
! c_tests/test_vfric_threads.c; VFRIC is called as Abaqus/Explicit user code calls it: a plain
! `call vfric(...)` with the 42 arguments, no interface block.
!
! 16 384 blocks of 1..127 contact points (nContact = 1 + mod(b-1, 127)): 1 048 513 point
! evaluations per run (1/n of the blocks under INTERFACIAL_TEST_SHRINK=n, for valgrind; sizes
! in harness_omp.f90). Each block has its own interaction ("VF<b>"), nFricDir (1 or 2), 1..64
! slave nodes with areas in [0.1, 2] and law-1 PROPS drawn from a Lehmer generator
! x <- 48271 x mod (2**31 - 1) seeded by the block's index, one of seven kinds: plain Coulomb,
! tau_max, rough (PROPS(7) = 2), exact stick with tau_max, tau_max with one to three bad points
! (fNormal NaN, fStickForce < 0, jConSlvid past nSlvNod), a refused call (mu < 0, the adhesive
! law, mu2 /= mu) and nFricDir = 3. Every array is allocated at exactly its declared size, so
! valgrind sees any access past it.
!
! Compared with the serial run: every fTangential entry of every block and the block's message
! (ifl_last_error_copy of the calling thread), folded into a 62-bit digest per block (two
! multiplicative hashes mod 2**31 - 1), and the counts of each kind. Checked on every block of
! both runs against docs/vfric.md, not against the library: fTangential(1,k) =
! 0 - min(mu F_N, tau_max A, F_stick) bit for bit (0 for F_N < 0, 0 - F_stick when rough),
! fTangential(2,k) = +0; a bad point +0 and a message naming VFRIC, the interaction and the
! last bad point; a refused call +0 everywhere (nothing written for nFricDir = 3) and a message
! naming VFRIC, the interaction and "(block)"; statev untouched; no message for a good block.
! At least 8 OpenMP threads must have done work.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

module vfric_omp_support
  use harness_threads
  use harness_omp, only: block_points, block_violation, max_block_points
  implicit none
  integer, parameter :: nprops = 7, n_kinds = 7, max_slaves = 64
  integer, parameter :: kind_bad_points = 5, kind_refused = 6, kind_nfricdir = 7
  integer, parameter :: n_unread = 3*3*max_block_points
  real(dp), parameter :: guard = -7.77e77_dp
  character(len=16), parameter :: kind_names(n_kinds) = [character(len=16) :: 'plain', &
    'tau_max', 'rough', 'exact stick', 'bad points', 'refused', 'nFricDir 3']

contains

  ! Calls VFRIC for block ib, checks it, returns its digest, kind and size.
  subroutine run_block(ib, dig, kind, npts, nbad_pts)
    integer, intent(in) :: ib
    integer(int64), intent(out) :: dig(2)
    integer, intent(out) :: kind, npts, nbad_pts
    integer(int64) :: x
    integer :: n, nf, nslv, k, j, nbad, last_bad, ndir, npr, one, two, four, ints(4)
    real(dp) :: props(nprops), f, want, unread(n_unread)
    real(dp), allocatable :: ftan(:, :), statev(:, :), normal(:), stick(:), area(:)
    integer, allocatable :: slave(:)
    logical, allocatable :: isbad(:)
    character(len=80) :: name, blank
    character(len=2048) :: text
    character(len=64) :: head, point
    character(len=200) :: what

    x = block_seed(ib)
    kind = int(mod(lehmer(x), int(n_kinds, int64))) + 1
    n = block_points(ib)
    npts = n
    if (kind == kind_nfricdir) then
      nf = 3
    else
      nf = 1 + int(mod(lehmer(x), 2_int64))
    end if
    nslv = 1 + int(mod(lehmer(x), int(max_slaves, int64)))
    props = 0
    props(1) = 1
    props(2) = uniform(x, 0.05_dp, 0.9_dp)
    if (kind /= 1) props(4) = uniform(x, 1.0_dp, 50.0_dp)
    if (kind == 3) props(7) = 2
    if (kind == 4) props(7) = 1
    allocate (ftan(nf, n), statev(2, n), normal(n), stick(n), area(nslv), slave(n), isbad(n))
    do k = 1, nslv
      area(k) = uniform(x, 0.1_dp, 2.0_dp)
    end do
    do k = 1, n
      normal(k) = uniform(x, -20.0_dp, 300.0_dp)
      stick(k) = uniform(x, 0.0_dp, 100.0_dp)
      slave(k) = 1 + int(mod(lehmer(x), int(nslv, int64)))
    end do
    isbad = .false.
    last_bad = 0
    if (kind == kind_bad_points) then
      do nbad = 1 + int(mod(lehmer(x), 3_int64)), 1, -1
        k = 1 + int(mod(lehmer(x), int(n, int64)))
        select case (mod(lehmer(x), 3_int64))
        case (0)
          normal(k) = quiet_nan()
        case (1)
          stick(k) = -uniform(x, 0.1_dp, 1.0_dp)
        case default
          slave(k) = nslv + 1
        end select
        isbad(k) = .true.
        last_bad = max(last_bad, k)
      end do
    end if
    if (kind == kind_refused) then
      select case (mod(lehmer(x), 3_int64))
      case (0)
        props(2) = -props(2)
      case (1)
        props(1) = 2
      case default
        props(3) = 2*props(2)
      end select
    end if
    nbad_pts = count(isbad)
    ftan = guard
    do k = 1, n
      statev(:, k) = [0.5_dp*k, -0.25_dp*k]
    end do
    unread = 1
    ints = 1
    one = 1
    two = 2
    four = 4
    ndir = nf + 1
    npr = nprops
    write (name, '(a,i0)') 'VF', ib
    blank = ' '
    call ifl_clear_error()
    call vfric(ftan, statev, one, one, n, four, nslv, four, nf, ndir, two, npr, one, one, one, &
               ints, ints, slave, ints, unread, unread, unread, name, blank, blank, ints, unread, &
               stick, unread, normal, unread, unread, unread, unread, unread, unread, props, area, &
               unread, unread, unread, unread)
    text = last_error()
    dig = 0
    do k = 1, n
      do j = 1, nf
        call digest(dig, transfer(ftan(j, k), 0_int64))
      end do
    end do
    do j = 1, len_trim(text)
      call digest(dig, int(ichar(text(j:j)), int64))
    end do

    what = ' '
    do k = 1, n
      if (.not. (same_bits(statev(1, k), 0.5_dp*k) .and. same_bits(statev(2, k), -0.25_dp*k))) &
        what = 'statev written'
    end do
    write (head, '(a,i0,a)') 'interfacial: VFRIC: interaction ''VF', ib, ''''
    if (kind == kind_refused .or. kind == kind_nfricdir) then
      if (index(text, trim(head)) /= 1 .or. index(text, '(block)') == 0) &
        what = 'refusal message lacks VFRIC, the interaction or (block)'
      do k = 1, n
        do j = 1, nf
          if (kind == kind_refused) then
            want = 0
          else
            want = guard
          end if
          if (.not. same_bits(ftan(j, k), want)) write (what, '(a,i0,a,i0,2es25.17)') &
            'refused call: fTangential(', j, ',', k, ftan(j, k), want
        end do
      end do
    else
      do k = 1, n
        if (isbad(k)) then
          want = 0
        else
          if (props(7) == 2) then
            f = stick(k)
          else if (normal(k) < 0) then
            f = 0
          else
            f = props(2)*normal(k)
            if (props(4) > 0) f = min(f, props(4)*area(slave(k)))
            f = min(f, stick(k))
          end if
          want = 0.0_dp - f
          if (.not. (ftan(1, k) >= -stick(k) .and. ftan(1, k) <= 0)) &
            what = 'fTangential(1,k) outside [-fStickForce, 0]'
        end if
        if (.not. same_bits(ftan(1, k), want)) write (what, '(a,i0,a,2es25.17)') &
          'fTangential(1,', k, ')', ftan(1, k), want
        if (nf == 2) then
          if (.not. same_bits(ftan(2, k), 0.0_dp)) what = 'fTangential(2,k) not +0'
        end if
      end do
      if (kind == kind_bad_points) then
        write (point, '(a,i0,a)') '(contact point ', last_bad, ')'
        if (index(text, trim(head)) /= 1 .or. index(text, trim(point)) == 0) &
          what = 'bad-point message lacks VFRIC, the interaction or the last bad point'
      else if (text /= ' ') then
        what = 'a good block left a message'
      end if
    end if
    if (what /= ' ') call block_violation(ib, trim(what))
    deallocate (ftan, statev, normal, stick, area, slave, isbad)
  end subroutine run_block

end module vfric_omp_support

program test_vfric_omp
  use vfric_omp_support
  use harness_omp
  implicit none

  call omp_block_runs('VFRIC', 'docs/vfric.md', kind_names, run_block, .true.)
  call finish()
end program test_vfric_omp
