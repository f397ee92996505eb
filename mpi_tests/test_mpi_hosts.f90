! test_mpi_hosts.f90 -- interfacial inside an MPI-parallel host.
!
! An FE code run with MPI gives each rank its share of the contact points and calls FRIC and
! GAPCON for them, increment by increment. This harness does the same with NPTS points, each
! with its own deterministic history drawn from a Lehmer generator seeded by the point's global
! number (so a point's inputs do not depend on which rank owns it), and checks:
!
!  1. every call against the law's closed form (stick: tau = k_s (tau0/k_s(p0) + dgam); slip:
!     |tau| = tau_crit; exact stick: LM = 1 and STATEV(3) = 2; each GAPCON conductance
!     recomputed by hand from mpi_tests/gapcon_mpi.toml), and the invariants of every call
!     (PNEWDT untouched, nothing written past NFDIR, SFD >= 0, AK(2..5) untouched);
!  2. the points spread over the ranks by blocks and cyclically, the results gathered on rank 0
!     (MPI_Gatherv) and compared bit for bit with a serial run of all points on rank 0; a
!     flipped bit in one gathered value must be caught (the comparison can fail);
!  3. bad input on the last rank (a negative friction coefficient in interaction BADMU, an
!     unconfigured GAPCON interaction NOSUCH, every increment): the last rank gets PNEWDT =
!     0.25 / AK(1) = 0 and its message (read back through ifl_last_error_copy), the other ranks
!     get no message, and the digests of every rank's good points still equal the serial ones.
!     With INTERFACIAL_LOG set, rank 0 reads the shared log afterwards: exactly one line per
!     cause, both from the last rank. Without it the messages go to that rank's stderr, which
!     mpi_tests/run_mpi.cmake checks in mpirun's tagged output.
!
! Rank 0 prints "<n> passed, <m> failed" (summed over the ranks) last; exit code 1 on a failure.

module mpi_host_points
  use, intrinsic :: iso_fortran_env, only: int64
  ! The calling thread's last library message, as the serial Fortran harnesses read it.
  use harness_tally, only: last_error
  implicit none
  integer, parameter :: dp = kind(1.0d0)
  integer, parameter :: npts = 5200, ninc = 24, ncat = 13, reclen = 8
  integer, parameter :: mg = 4, msv = 5
  real(dp), parameter :: sentinel = -999.25_dp, big = 1.0e36_dp
  integer(int64), parameter :: lehmer_m = 2147483647_int64
  integer :: npass = 0, nfail = 0
  ! FRIC calls by what happened (rows) and NFDIR (columns), for the coverage check.
  integer :: visits(0:4, 2) = 0
  character(len=24), parameter :: state_names(0:4) = [character(len=24) :: 'elastic stick', &
    'slip', 'exact stick (LM = 1)', 'released (LM 1 -> 0)', 'reversal (LM 0 -> 1)']
  ! Interaction names of categories 6..12 (GAPCON points), as in gapcon_mpi.toml.
  character(len=8), parameter :: gap_names(6:12) = [character(len=8) :: 'MPICONST', &
    'MPIPTAB', 'MPICTAB', 'MPIGAS', 'MPICMY', 'MPIRADC', 'MPITTAB']

  ! One contact point and its history so far. Categories: 0..5 FRIC (0 elastic NFDIR 1, 1
  ! elastic NFDIR 2 with gamma_crit from the tolerance, 2 elastic NFDIR 2 with tau_max, 3 exact
  ! stick NFDIR 1, 4 exact stick NFDIR 2 with the default tolerance, 5 rough), 6..12 GAPCON.
  type :: point
    integer :: id = 0, cat = 0
    integer(int64) :: rng = 1
    ! FRIC: law and state carried from increment to increment.
    integer :: nfdir = 1, nprops = 7, lm = 0
    real(dp) :: props(7) = 0, chrlngth = 0.1_dp, gc = 0, amplitude = 1
    real(dp) :: tau(2) = 0, statev(3) = 0, p_prev = 0, sfd_sum = 0
    ! Digest of every output of every increment (two Lehmer-style sums, 31 bits each).
    integer(int64) :: h(2) = [1_int64, 1_int64]
    real(dp) :: rec(reclen) = 0
  end type point

contains

  subroutine check(ok, what, id, k)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    integer, intent(in) :: id, k
    if (ok) then
      npass = npass + 1
    else
      nfail = nfail + 1
      if (nfail <= 40) write (*, '(a,i0,a,i0,a,a)') 'FAIL point ', id, ' increment ', k, ': ', what
    end if
  end subroutine check

  ! Lehmer (Park-Miller) generator x <- 48271 x mod (2^31 - 1): u in (0, 1).
  function uniform(x) result(u)
    integer(int64), intent(inout) :: x
    real(dp) :: u
    x = mod(48271_int64*x, lehmer_m)
    u = real(x, dp)/real(lehmer_m, dp)
  end function uniform

  ! Folds the 64 bits of x into the digest h: two sums modulo 2^31 - 1 with different
  ! multipliers, 32 bits at a time (no integer overflow anywhere).
  subroutine mix(h, x)
    integer(int64), intent(inout) :: h(2)
    real(dp), intent(in) :: x
    integer(int64) :: w, half(2)
    integer :: i
    w = transfer(x, w)
    half = [ibits(w, 0, 32), ibits(w, 32, 32)]
    do i = 1, 2
      h(1) = mod(h(1)*48271_int64 + half(i), lehmer_m)
      h(2) = mod(h(2)*69621_int64 + half(i), lehmer_m)
    end do
  end subroutine mix

  integer(int64) function digest_of(h)
    integer(int64), intent(in) :: h(2)
    digest_of = ior(ishft(h(1), 31), h(2))
  end function digest_of

  ! The point's law and the start of its history, from its global number alone. The FRIC
  ! categories 0..5: 0 mostly elastic stick; 1 stick and slip, gamma_crit = PROPS(6) * CHRLNGTH,
  ! PROPS(3) = mu (isotropic); 2 mostly slip, tau_max in [5, 20] caps mu p on the higher
  ! pressures; 3 exact stick; 4 exact stick with gamma_crit from the default tolerance
  ! 0.005 * CHRLNGTH; 5 rough. Each with its NFDIR, PROPS(7) (elastic, exact stick, rough) and
  ! the amplitude of its imposed slip (in gamma_crit).
  function new_point(id) result(s)
    integer, intent(in) :: id
    type(point) :: s
    integer, parameter :: nfdirs(0:5) = [1, 2, 2, 1, 2, 2], stick(0:5) = [0, 0, 0, 1, 1, 2]
    real(dp), parameter :: amplitudes(0:5) = [0.4_dp, 1.5_dp, 3.0_dp, 2.0_dp, 2.0_dp, 1.0_dp]
    real(dp) :: mu
    integer :: i
    s%id = id
    s%cat = mod(id - 1, ncat)
    s%rng = mod(int(id, int64)*7919_int64 + 12345_int64, lehmer_m - 1) + 1
    do i = 1, 3
      mu = uniform(s%rng)
    end do
    if (s%cat > 5) return
    mu = 0.1_dp + 0.5_dp*uniform(s%rng)
    s%chrlngth = 0.05_dp + 0.45_dp*uniform(s%rng)
    s%props = 0
    s%props(1) = 1
    s%props(2) = mu
    s%gc = 1.0e-4_dp + 9.0e-4_dp*uniform(s%rng)
    s%nfdir = nfdirs(s%cat)
    s%props(7) = stick(s%cat)
    s%amplitude = amplitudes(s%cat)
    select case (s%cat)
    case (1)
      s%props(3) = mu
      s%props(6) = 0.002_dp + 0.008_dp*uniform(s%rng)
      s%gc = s%props(6)*s%chrlngth
      s%nprops = 6
    case (2)
      s%props(4) = 5 + 15*uniform(s%rng)
      s%props(5) = s%gc
    case (4)
      s%gc = 0.005_dp*s%chrlngth
    case default
      s%props(5) = s%gc
    end select
  end function new_point

  ! tau_crit = min(mu p, tau_max), 0 for p <= 0 (seed 000, 5.2.3).
  real(dp) function critical_stress(s, p)
    type(point), intent(in) :: s
    real(dp), intent(in) :: p
    critical_stress = 0
    if (p <= 0) return
    critical_stress = s%props(2)*p
    if (s%props(4) > 0) critical_stress = min(critical_stress, s%props(4))
  end function critical_stress

  ! One increment of one point: draw its inputs, call the routine as a host does, check the
  ! answer, fold the outputs into the digest and carry the state on.
  subroutine advance(s, k)
    type(point), intent(inout) :: s
    integer, intent(in) :: k
    if (s%cat <= 5) then
      call advance_fric(s, k)
    else
      call advance_gapcon(s, k)
    end if
  end subroutine advance

  subroutine advance_fric(s, k)
    type(point), intent(inout) :: s
    integer, intent(in) :: k
    real(dp) :: press, dpress, dgam(mg), taulm(mg), tau(mg), statev(msv)
    real(dp) :: ddtddg(mg*mg), ddtddp(mg), dslip(mg), ddtddt(2*mg), sed, sfd, pnewdt
    real(dp) :: tc, tc0, ks, ks0, expect(2), tol, drawn
    integer :: lm, n, j
    n = s%nfdir
    ! Pressure walks in [1, 120]; the first increment starts from first contact (p0 = 0).
    if (k == 1) then
      press = 1 + 119*uniform(s%rng)
    else
      press = min(120.0_dp, max(1.0_dp, s%p_prev + 20*(uniform(s%rng) - 0.5_dp)))
    end if
    dpress = press - s%p_prev
    dgam = sentinel
    drawn = uniform(s%rng)
    do j = 1, n
      dgam(j) = s%amplitude*s%gc*(2*uniform(s%rng) - 1)
    end do
    ! Some elastic increments with no relative motion at all.
    if (s%cat <= 2 .and. drawn < 0.1_dp) dgam(1:n) = 0
    tc = critical_stress(s, press)
    tau = sentinel
    tau(1:n) = s%tau(1:n)
    taulm = sentinel
    if (s%lm == 1) then
      ! Stuck: the host's Lagrange stress, inside or outside the cone (|TAULM| up to 1.6 tau_crit),
      ! also carried as the stress at the start of the increment.
      do j = 1, n
        taulm(j) = 1.6_dp*tc*(2*uniform(s%rng) - 1)/sqrt(real(n, dp))
      end do
      tau(1:n) = taulm(1:n)
    end if
    statev = sentinel
    statev(1:3) = s%statev
    lm = s%lm
    call fric_call(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, taulm, &
                   press, dpress, s, k)

    call check(pnewdt == big, 'PNEWDT never lowered', s%id, k)
    call check(all(tau(n + 1:) == sentinel) .and. all(ddtddg(n*n + 1:) == sentinel) .and. &
               all(ddtddp(n + 1:) == sentinel) .and. all(dslip(n + 1:) == sentinel) .and. &
               all(ddtddt(2*n + 1:) == sentinel) .and. all(statev(4:) == sentinel), &
               'nothing written past NFDIR, NFDIR**2, 2 NFDIR, NSTATV', s%id, k)
    tol = 1.0e-11_dp*max(tc, 1.0e-300_dp)
    if (lm == 0) then
      call check(s%props(7) /= 2, 'rough friction always answers LM = 1', s%id, k)
      call check(sfd >= 0, 'SFD >= 0', s%id, k)
      call check(norm2(tau(1:n)) <= tc + tol, '|tau| <= tau_crit', s%id, k)
      if (statev(3) == 0) then
        ! Elastic stick, Eq. 5.2.3-1, with the start-of-increment elastic slip recovered with
        ! the start-of-increment stiffness k_s(p0) (docs/fric.md).
        call check(s%props(7) == 0, 'elastic stick only in penalty mode', s%id, k)
        ks = tc/s%gc
        tc0 = critical_stress(s, press - dpress)
        ks0 = tc0/s%gc
        if (tc0 > 0) then
          expect(1:n) = ks*(s%tau(1:n)/ks0 + dgam(1:n))
        else
          expect(1:n) = ks*dgam(1:n)
        end if
        call check(all(abs(tau(1:n) - expect(1:n)) <= 1.0e-9_dp*tc + 1.0e-300_dp), &
                   'stick: tau = k_s (tau0/k_s(p0) + dgam)', s%id, k)
        call check(sfd == 0, 'stick: no dissipation', s%id, k)
      else
        ! Slip (Eq. 5.2.3-2) or, in exact-stick mode, the released or sliding point (5.2.3-7).
        call check(statev(3) == 1, 'STATEV(3) = 1 when sliding', s%id, k)
        call check(abs(norm2(tau(1:n)) - tc) <= tol, 'slip: |tau| = tau_crit', s%id, k)
      end if
      s%tau(1:n) = tau(1:n)
    else
      call check(lm == 1, 'LM is 0 or 1', s%id, k)
      call check(s%props(7) >= 1, 'LM = 1 only for exact stick or rough', s%id, k)
      call check(statev(3) == 2, 'STATEV(3) = 2 for exact stick', s%id, k)
      call check(sfd == 0 .and. sed == 0, 'exact stick: SFD = SED = 0', s%id, k)
      if (s%props(7) == 1 .and. s%lm == 1) &
        call check(norm2(taulm(1:n)) <= tc*(1 + 1.0e-12_dp), 'kept stuck only inside the cone', &
                   s%id, k)
    end if
    if (lm == 0) then
      j = nint(statev(3))
      if (s%lm == 1) j = 3
    else
      j = 2
      if (s%lm == 0 .and. s%props(7) == 1) j = 4
    end if
    if (j >= 0 .and. j <= 4) visits(j, n) = visits(j, n) + 1
    s%lm = lm
    s%statev = statev(1:3)
    s%p_prev = press
    s%sfd_sum = s%sfd_sum + max(sfd, 0.0_dp)

    call mix(s%h, real(lm, dp))
    call mix(s%h, sed)
    call mix(s%h, sfd)
    do j = 1, n
      call mix(s%h, tau(j))
      call mix(s%h, ddtddp(j))
      call mix(s%h, dslip(j))
    end do
    do j = 1, n*n
      call mix(s%h, ddtddg(j))
    end do
    do j = 1, 2*n
      call mix(s%h, ddtddt(j))
    end do
    do j = 1, 3
      call mix(s%h, statev(j))
    end do
    s%rec = [real(lm, dp), s%tau(1), s%tau(2), s%statev(1), s%statev(2), s%statev(3), &
             s%sfd_sum, press]
  end subroutine advance_fric

  ! The only place FRIC is called: the 39 Abaqus arguments, outputs preset to the sentinel.
  subroutine fric_call(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, &
                       taulm, press, dpress, s, k)
    integer, intent(inout) :: lm
    real(dp), intent(inout) :: tau(mg), statev(msv)
    real(dp), intent(out) :: ddtddg(mg*mg), ddtddp(mg), dslip(mg), ddtddt(2*mg), sed, sfd, pnewdt
    real(dp), intent(in) :: dgam(mg), taulm(mg), press, dpress
    type(point), intent(in) :: s
    integer, intent(in) :: k
    real(dp) :: ddpddh, slip(mg), time(2), dtime, coords(3), rcoord(3), drot(2, 2), temp(2)
    real(dp) :: predef(2, 1), props(7)
    integer :: noel, npt, node, npatch, nstatv, nprops, kstep, kinc
    character(len=80) :: ciname, slname, msname
    ddtddg = sentinel
    ddtddp = sentinel
    dslip = sentinel
    ddtddt = sentinel
    sed = sentinel
    sfd = sentinel
    pnewdt = big
    ddpddh = 1.0e6_dp
    slip = 0
    kstep = 1
    kinc = k
    dtime = 0.1_dp
    time = [0.1_dp*(k - 1), 0.1_dp*(k - 1)]
    noel = s%id
    write (ciname, '(a,i0)') 'CAT', s%cat
    if (s%cat == 99) ciname = 'BADMU'
    slname = 'SLAVE'
    msname = 'MASTER'
    npt = 1
    node = s%id
    npatch = 1
    coords = 0
    rcoord = 0
    drot = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
    temp = 20
    predef = 0
    nstatv = 3
    nprops = s%nprops
    props = s%props
    call fric(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, taulm, &
              press, dpress, ddpddh, slip, kstep, kinc, time, dtime, noel, ciname, slname, &
              msname, npt, node, npatch, coords, rcoord, drot, temp, predef, s%nfdir, 3, 1, &
              nstatv, s%chrlngth, props, nprops)
  end subroutine fric_call

  ! Linear in x through the rows (xs, ys), constant outside (docs/config.md, tables).
  real(dp) function table(x, xs, ys)
    real(dp), intent(in) :: x, xs(:), ys(:)
    integer :: i
    if (x <= xs(1)) then
      table = ys(1)
      return
    end if
    do i = 2, size(xs)
      if (x <= xs(i)) then
        table = ys(i - 1) + (ys(i) - ys(i - 1))*(x - xs(i - 1))/(xs(i) - xs(i - 1))
        return
      end if
    end do
    table = ys(size(ys))
  end function table

  ! F sigma ((thA - thZ)^4 - (thB - thZ)^4)/(thA - thB) = F sigma (a + b)(a^2 + b^2).
  real(dp) function radiation(f, thz, tha, thb)
    real(dp), intent(in) :: f, thz, tha, thb
    real(dp) :: a, b
    a = tha - thz
    b = thb - thz
    radiation = f*5.670374419e-8_dp*(a + b)*(a*a + b*b)
  end function radiation

  ! Each interaction of gapcon_mpi.toml, by hand.
  real(dp) function expected_conductance(cat, d, p, tha, thb) result(k)
    integer, intent(in) :: cat
    real(dp), intent(in) :: d, p, tha, thb
    real(dp) :: k300, k400
    select case (cat)
    case (6)
      k = 1750
    case (7)
      k = table(p, [0.0_dp, 50.0_dp, 100.0_dp], [500.0_dp, 1200.0_dp, 3000.0_dp])
    case (8)
      k = table(d, [0.0_dp, 2.0e-5_dp, 1.0e-4_dp], [4000.0_dp, 1500.0_dp, 100.0_dp])
    case (9)
      k = 0.026_dp/(max(d, 1.0e-6_dp) + 1.0e-5_dp) + radiation(0.8_dp, 0.0_dp, tha, thb)
    case (10)
      ! Cooper-Mikic-Yovanovich: c (k_s m / sigma) (p / H_c)^0.95 for p > 0.
      k = 0
      if (p > 0) k = 1.25_dp*(20.0_dp*0.1_dp/2.0e-6_dp)*(p/300.0_dp)**0.95_dp
    case (11)
      k = radiation(0.5_dp, -273.15_dp, tha, thb)
    case default
      k300 = table(p, [0.0_dp, 100.0_dp], [500.0_dp, 1500.0_dp])
      k400 = table(p, [0.0_dp, 100.0_dp], [900.0_dp, 2500.0_dp])
      k = table(0.5_dp*(tha + thb), [300.0_dp, 400.0_dp], [k300, k400])
    end select
  end function expected_conductance

  subroutine advance_gapcon(s, k)
    type(point), intent(inout) :: s
    integer, intent(in) :: k
    real(dp) :: d(2), tha, thb, ak(5), expect
    ! Clearance in [0, 1e-4] (exactly 0 now and then), pressure in [-10, 150] (outside the
    ! tables on both sides), surface temperatures in [280, 420] K, or [20, 150] degC.
    d(1) = 1.0e-4_dp*uniform(s%rng)
    if (d(1) < 1.5e-5_dp) d(1) = 0
    d(2) = -10 + 160*uniform(s%rng)
    if (s%cat == 11) then
      tha = 20 + 130*uniform(s%rng)
      thb = 20 + 130*uniform(s%rng)
    else
      tha = 280 + 140*uniform(s%rng)
      thb = 280 + 140*uniform(s%rng)
    end if
    call gapcon_call(gap_names(s%cat), d, tha, thb, s%id, k, ak)
    call check(all(ak(2:5) == sentinel), 'AK(2..5) untouched', s%id, k)
    expect = expected_conductance(s%cat, d(1), d(2), tha, thb)
    call check(abs(ak(1) - expect) <= 1.0e-12_dp*abs(expect), &
               trim(gap_names(s%cat))//': AK(1) is the conductance of gapcon_mpi.toml', s%id, k)
    call mix(s%h, ak(1))
    s%rec = [ak(1), d(1), d(2), tha, thb, 0.0_dp, 0.0_dp, real(k, dp)]
  end subroutine advance_gapcon

  ! The only place GAPCON is called: the 15 Abaqus arguments, AK preset to the sentinel.
  subroutine gapcon_call(name, d, tha, thb, noel, k, ak)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: d(2), tha, thb
    integer, intent(in) :: noel, k
    real(dp), intent(out) :: ak(5)
    real(dp) :: flowm(2), temp(2), predef(2, 1), time(2), coords(3)
    character(len=80) :: ciname, slname, msname
    ak = sentinel
    flowm = 0
    temp = [tha, thb]
    predef = 0
    time = [0.1_dp*k, 0.1_dp*k]
    ciname = name
    slname = 'SLAVE'
    msname = 'MASTER'
    coords = 0
    call gapcon(ak, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, noel, 1, &
                1, k)
  end subroutine gapcon_call

  ! Bad input on this rank, once per increment (phase 3): FRIC with mu < 0 in interaction BADMU
  ! and GAPCON for the unconfigured interaction NOSUCH, element 90000 + rank.
  subroutine bad_calls(rank, k)
    integer, intent(in) :: rank, k
    type(point) :: b
    real(dp) :: tau(mg), statev(msv), ddtddg(mg*mg), ddtddp(mg), dslip(mg), ddtddt(2*mg)
    real(dp) :: sed, sfd, pnewdt, dgam(mg), taulm(mg), d(2), ak(5)
    integer :: lm
    character(len=2048) :: msg
    character(len=16) :: elem
    b = new_point(1)
    b%cat = 99
    b%id = 90000 + rank
    b%props(2) = -0.3_dp
    b%nfdir = 1
    write (elem, '(a,i0)') 'element ', b%id
    lm = 0
    tau = [4.0_dp, sentinel, sentinel, sentinel]
    statev = [0.5_dp, 0.25_dp, 1.0_dp, sentinel, sentinel]
    dgam = [1.0e-3_dp, sentinel, sentinel, sentinel]
    taulm = sentinel
    call fric_call(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, taulm, &
                   10.0_dp, 1.0_dp, b, k)
    msg = last_error()
    call check(pnewdt == 0.25_dp, 'bad FRIC: PNEWDT = 0.25', b%id, k)
    call check(lm == 0 .and. tau(1) == 4 .and. all(statev(1:3) == [0.5_dp, 0.25_dp, 1.0_dp]), &
               'bad FRIC: LM, TAU, STATEV unchanged', b%id, k)
    call check(index(msg, 'FRIC') > 0 .and. index(msg, "'BADMU'") > 0 .and. &
               index(msg, 'PROPS(2)') > 0 .and. index(msg, trim(elem)) > 0, &
               'bad FRIC: message names FRIC, BADMU, PROPS(2), the element: '//trim(msg), b%id, k)
    d = [1.0e-5_dp, 40.0_dp]
    call gapcon_call('NOSUCH', d, 300.0_dp, 310.0_dp, b%id, k, ak)
    msg = last_error()
    call check(ak(1) == 0 .and. all(ak(2:5) == sentinel), 'bad GAPCON: AK(1) = 0, AK(2..5) kept', &
               b%id, k)
    call check(index(msg, 'GAPCON') > 0 .and. index(msg, "'NOSUCH'") > 0 .and. &
               index(msg, trim(elem)) > 0, &
               'bad GAPCON: message names GAPCON, NOSUCH, the element: '//trim(msg), b%id, k)
  end subroutine bad_calls

  ! Drives the points ids(:) through every increment, all points of an increment before the
  ! next increment (as an FE code does), and returns their records and digests. With bad set,
  ! the bad calls come after the points of each increment.
  subroutine run_points(ids, bad, rank, rec, dig)
    integer, intent(in) :: ids(:), rank
    logical, intent(in) :: bad
    real(dp), intent(out) :: rec(reclen, size(ids))
    integer(int64), intent(out) :: dig(size(ids))
    type(point), allocatable :: pts(:)
    integer :: i, k
    allocate (pts(size(ids)))
    do i = 1, size(ids)
      pts(i) = new_point(ids(i))
    end do
    do k = 1, ninc
      do i = 1, size(pts)
        call advance(pts(i), k)
      end do
      if (bad) call bad_calls(rank, k)
    end do
    do i = 1, size(pts)
      rec(:, i) = pts(i)%rec
      dig(i) = digest_of(pts(i)%h)
    end do
  end subroutine run_points

  ! Global numbers of the points rank r owns out of n on np ranks: contiguous blocks
  ! (the first mod(n, np) ranks one more) or cyclic (point i on rank mod(i - 1, np)).
  subroutine owned_points(cyclic, r, np, n, ids)
    logical, intent(in) :: cyclic
    integer, intent(in) :: r, np, n
    integer, allocatable, intent(out) :: ids(:)
    integer :: cnt, first, j
    if (cyclic) then
      cnt = 0
      if (r < n) cnt = (n - r - 1)/np + 1
      ids = [(r + 1 + (j - 1)*np, j=1, cnt)]
    else
      cnt = n/np
      first = r*cnt + min(r, mod(n, np)) + 1
      if (r < mod(n, np)) cnt = cnt + 1
      ids = [(first + j - 1, j=1, cnt)]
    end if
  end subroutine owned_points

  ! Bitwise comparison of gathered against reference records and digests (NaN-safe, -0 /= +0).
  integer function mismatches(a, b, da, db)
    real(dp), intent(in) :: a(:, :), b(:, :)
    integer(int64), intent(in) :: da(:), db(:)
    integer :: i, j
    integer(int64) :: wa, wb
    mismatches = count(da /= db)
    do i = 1, size(a, 2)
      do j = 1, size(a, 1)
        wa = transfer(a(j, i), wa)
        wb = transfer(b(j, i), wb)
        if (wa /= wb) mismatches = mismatches + 1
      end do
    end do
  end function mismatches
end module mpi_host_points

program test_mpi_hosts
  use mpi
  use mpi_host_points
  implicit none
  integer :: ierr, rank, np, nbad_rank, totals(2), sums(2), i
  real(dp), allocatable :: ref(:, :)
  integer(int64), allocatable :: refdig(:)
  integer, allocatable :: all_ids(:)
  character(len=1024) :: log_path
  integer :: log_len, lstat

  call mpi_init(ierr)
  call mpi_comm_rank(MPI_COMM_WORLD, rank, ierr)
  call mpi_comm_size(MPI_COMM_WORLD, np, ierr)
  nbad_rank = np - 1
  call get_environment_variable('INTERFACIAL_LOG', log_path, log_len, lstat)
  if (lstat /= 0) log_len = 0

  ! The serial reference: every point on rank 0 alone.
  if (rank == 0) then
    all_ids = [(i, i=1, npts)]
    allocate (ref(reclen, npts), refdig(npts))
    call run_points(all_ids, .false., rank, ref, refdig)
    call coverage_of_reference()
  end if

  call distributed(.false., .false.)
  call distributed(.true., .false.)

  ! Bad input on the last rank. A fresh log: rank 0 removes it before anyone can write to it.
  if (rank == 0 .and. log_len > 0) call remove_file(log_path(1:log_len))
  call mpi_barrier(MPI_COMM_WORLD, ierr)
  call distributed(.true., .true.)
  call mpi_barrier(MPI_COMM_WORLD, ierr)
  if (rank /= nbad_rank) call check(len_trim(last_error()) == 0, 'no message on a good rank', &
                                    rank, 0)
  if (rank == 0 .and. log_len > 0) call check_log(log_path(1:log_len))

  totals = [npass, nfail]
  call mpi_reduce(totals, sums, 2, MPI_INTEGER, MPI_SUM, 0, MPI_COMM_WORLD, ierr)
  if (rank == 0) write (*, '(a,i0,a,i0,a,i0,a)') 'ranks ', np, ': ', sums(1), ' passed, ', &
    sums(2), ' failed'
  call mpi_bcast(sums, 2, MPI_INTEGER, 0, MPI_COMM_WORLD, ierr)
  call mpi_finalize(ierr)
  if (sums(2) > 0) stop 1

contains

  ! The histories must really reach every state the harness claims to cover (counted over
  ! every call of the serial run): elastic stick, slip, exact stick, release from exact stick,
  ! each with NFDIR 1 and 2, and reversal into exact stick.
  subroutine coverage_of_reference()
    integer :: st, n
    character(len=64) :: what
    write (*, '(a)') '  calls of the serial run by state (NFDIR 1, NFDIR 2):'
    do st = lbound(visits, 1), ubound(visits, 1)
      write (*, '(4x,a,2(1x,i8))') state_names(st), visits(st, :)
      do n = 1, 2
        write (what, '(a,a,i0)') trim(state_names(st)), ' reached with NFDIR ', n
        call check(visits(st, n) > 0, what, 0, 0)
      end do
    end do
  end subroutine coverage_of_reference

  ! Spreads the points over the ranks, runs them, gathers records and digests on rank 0 and
  ! compares them bit for bit with the serial reference. In the bad-input phase only the
  ! digests are compared: one per rank, over its good points, against the same digest of the
  ! serial run.
  subroutine distributed(cyclic, bad)
    logical, intent(in) :: cyclic, bad
    integer, allocatable :: ids(:), counts(:), displs(:), rcounts(:), rdispls(:), gids(:)
    real(dp), allocatable :: rec(:, :), grec(:, :), tmp(:, :)
    integer(int64), allocatable :: dig(:), gdig(:), tmpd(:)
    integer(int64) :: mine(2), rank_digests(2, 0:np - 1), h(2)
    integer :: nloc, r, j, nmis
    integer, allocatable :: owner_ids(:), hits(:)
    character(len=40) :: label

    label = merge('cyclic', 'block ', cyclic)
    if (bad) label = trim(label)//', bad input on the last rank'
    call owned_points(cyclic, rank, np, npts, ids)
    nloc = size(ids)
    allocate (rec(reclen, max(nloc, 1)), dig(max(nloc, 1)))
    call run_points(ids, bad .and. rank == nbad_rank, rank, rec(:, 1:nloc), dig(1:nloc))

    if (bad) then
      ! Digest of this rank's good points, in its own order.
      h = [1_int64, 1_int64]
      do j = 1, nloc
        call mix(h, transfer(dig(j), 1.0_dp))
      end do
      mine = h
      call mpi_gather(mine, 2, MPI_INTEGER8, rank_digests, 2, MPI_INTEGER8, 0, MPI_COMM_WORLD, &
                      ierr)
      if (rank == 0) then
        do r = 0, np - 1
          call owned_points(cyclic, r, np, npts, owner_ids)
          h = [1_int64, 1_int64]
          do j = 1, size(owner_ids)
            call mix(h, transfer(refdig(owner_ids(j)), 1.0_dp))
          end do
          call check(all(h == rank_digests(:, r)), 'digest of rank''s good points = serial ('// &
                     trim(label)//')', r, 0)
        end do
      end if
      return
    end if

    allocate (counts(0:np - 1), displs(0:np - 1), rcounts(0:np - 1), rdispls(0:np - 1))
    call mpi_gather(nloc, 1, MPI_INTEGER, counts, 1, MPI_INTEGER, 0, MPI_COMM_WORLD, ierr)
    if (rank == 0) then
      displs(0) = 0
      do r = 1, np - 1
        displs(r) = displs(r - 1) + counts(r - 1)
      end do
      rcounts = reclen*counts
      rdispls = reclen*displs
      allocate (grec(reclen, sum(counts)), gdig(sum(counts)), gids(sum(counts)))
    else
      allocate (grec(reclen, 1), gdig(1), gids(1))
    end if
    call mpi_gatherv(rec, reclen*nloc, MPI_DOUBLE_PRECISION, grec, rcounts, rdispls, &
                     MPI_DOUBLE_PRECISION, 0, MPI_COMM_WORLD, ierr)
    call mpi_gatherv(dig, nloc, MPI_INTEGER8, gdig, counts, displs, MPI_INTEGER8, 0, &
                     MPI_COMM_WORLD, ierr)
    call mpi_gatherv(ids, nloc, MPI_INTEGER, gids, counts, displs, MPI_INTEGER, 0, &
                     MPI_COMM_WORLD, ierr)
    if (rank /= 0) return

    ! Every point gathered exactly once, and it is the point the distribution gives that rank.
    call check(sum(counts) == npts, 'gathered '//trim(label)//': NPTS points in all', 0, 0)
    if (sum(counts) /= npts) return
    allocate (hits(npts))
    hits = 0
    do j = 1, npts
      if (gids(j) >= 1 .and. gids(j) <= npts) hits(gids(j)) = hits(gids(j)) + 1
    end do
    call check(all(hits == 1), 'gathered '//trim(label)//': each point exactly once', 0, 0)
    do r = 0, np - 1
      call owned_points(cyclic, r, np, npts, owner_ids)
      call check(size(owner_ids) == counts(r), 'gathered '//trim(label)//': count per rank', r, 0)
      if (size(owner_ids) == counts(r)) call check(all(gids(displs(r) + 1:displs(r) + counts(r)) &
                                                   == owner_ids), 'gathered ids', r, 0)
    end do
    if (any(hits /= 1)) return

    nmis = mismatches(grec, ref(:, gids), gdig, refdig(gids))
    call check(nmis == 0, 'gathered '//trim(label)//' = serial, bit for bit', 0, 0)
    if (nmis /= 0) write (*, '(a,i0,a)') '   ', nmis, ' values differ'
    write (*, '(a,a,a,i0,a,i0,a)') '  ', trim(label), ': ', npts, ' points x ', ninc, &
      ' increments gathered from every rank, bit-identical to the serial run'

    ! The comparison can fail: one flipped low bit in one gathered value, and one digest.
    tmp = grec
    tmp(2, npts/2) = transfer(ieor(transfer(tmp(2, npts/2), 1_int64), 1_int64), 1.0_dp)
    tmpd = gdig
    call check(mismatches(tmp, ref(:, gids), tmpd, refdig(gids)) == 1, &
               'a flipped bit in one record is caught', 0, 0)
    tmpd(1) = tmpd(1) + 1
    call check(mismatches(grec, ref(:, gids), tmpd, refdig(gids)) == 1, &
               'a changed digest is caught', 0, 0)
  end subroutine distributed

  subroutine remove_file(path)
    character(len=*), intent(in) :: path
    integer :: u, ios
    open (newunit=u, file=path, status='old', iostat=ios)
    if (ios == 0) close (u, status='delete')
  end subroutine remove_file

  ! The shared INTERFACIAL_LOG after the bad-input phase: one line per cause (FRIC mu < 0,
  ! GAPCON unlisted interaction), both naming the last rank's element, nothing else.
  subroutine check_log(path)
    character(len=*), intent(in) :: path
    integer :: u, ios, nlines, nfric, ngap
    character(len=1024) :: line
    character(len=16) :: elem
    write (elem, '(a,i0)') 'element ', 90000 + nbad_rank
    nlines = 0
    nfric = 0
    ngap = 0
    open (newunit=u, file=path, status='old', action='read', iostat=ios)
    call check(ios == 0, 'INTERFACIAL_LOG exists: '//path, 0, 0)
    if (ios /= 0) return
    do
      read (u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      nlines = nlines + 1
      write (*, '(a,a)') '  log: ', trim(line)
      if (index(line, 'interfacial: FRIC:') == 1 .and. index(line, "'BADMU'") > 0 .and. &
          index(line, 'PROPS(2)') > 0 .and. index(line, trim(elem)) > 0) nfric = nfric + 1
      if (index(line, 'interfacial: GAPCON:') == 1 .and. index(line, "'NOSUCH'") > 0 .and. &
          index(line, trim(elem)) > 0) ngap = ngap + 1
    end do
    close (u)
    call check(nlines == 2 .and. nfric == 1 .and. ngap == 1, &
               'log: one FRIC and one GAPCON line, both from the last rank', 0, 0)
  end subroutine check_log
end program test_mpi_hosts
