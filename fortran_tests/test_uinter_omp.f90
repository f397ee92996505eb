! test_uinter_omp.f90 -- UINTER from an OpenMP parallel loop (OMP_NUM_THREADS = 8, set by CTest),
! compared bit for bit with a serial run of the same points. The Fortran twin of
! c_tests/test_uinter_threads.c; UINTER is called as Abaqus user code calls it: a plain
! `call uinter(...)` with the 47 arguments and no interface block.
!
! 4096 interface points x 256 increments = 1 048 576 calls per run. Each point carries STRESS
! and STATEV from one increment to the next; the overclosure RDISP(1) follows a wave that
! closes, pulls apart (bonded under a small tension, open under a larger one) and re-closes
! the interface; DRDISP(2..NDIR) is random (stick and slip). Every point has its own adhesive
! interaction from a Lehmer generator x <- 48271 x mod (2**31 - 1) seeded by its index: NDIR 2
! or 3, mu_s = mu_d or above, separation adhesion or none, rate dependence or none, heat
! conduction (the PTAB law of configs/uinter_heat.toml, INTERFACIAL_CONFIG set by CTest) with
! frictional heat or none, NSTATV 3 or 5; now and then a NaN in DRDISP (refused: PNEWDT = 0.25,
! STRESS and STATEV unchanged). Arrays are allocated at exactly their declared sizes; under
! valgrind, INTERFACIAL_TEST_SHRINK=n runs 1/n of the points (sizes in harness_omp.f90).
!
! Compared with the serial run: every output of every call (STRESS, DDSDDR, FLUX, DDFDDT,
! DDFDDR, STATEV, SED, SFD, PNEWDT, LOPENCLOSE, LSTATE), bit patterns folded into a 62-bit
! digest per call; the final STRESS and STATEV of every point bit for bit; the counts of each
! kind of call. Checked on every call: outputs finite, |tau| <= (mu_s + k_mu rate) p+ + S_a,
! status 0/1/3/4 with LSTATE and LOPENCLOSE agreeing, open => zero stress, SED, SFD >= 0,
! STATEV past 3 untouched. At least 8 OpenMP threads must have done work.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

module uinter_omp_support
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use harness_threads
  use harness_omp, only: incs, point_violation
  implicit none
  real(dp), parameter :: pnewdt_in = 1.0e36_dp, statev_tail = -5.5e55_dp, kn = 1.0e4_dp
  integer, parameter :: nrec = 8 ! final record: STRESS(3), STATEV(5)
  integer, parameter :: k_stick = 1, k_slip = 2, k_bonded = 3, k_open = 4, k_recontact = 5, &
    k_heat = 6, k_refused = 7, k_ndir2 = 8, k_ndir3 = 9, n_kinds = 9
  character(len=16), parameter :: kind_names(n_kinds) = [character(len=16) :: 'stick', &
    'slip', 'bonded', 'open', 're-contact', 'heat', 'refused (NaN)', 'NDIR 2', 'NDIR 3']

contains

  ! One interface point of one run: 256 digests into dig(:), the final state into fin(:).
  subroutine run_point(ip, dig, fin, kinds)
    integer, intent(in) :: ip
    integer(int64), intent(out) :: dig(:) ! (incs)
    real(dp), intent(out) :: fin(:) ! (nrec)
    integer(int64), intent(inout) :: kinds(:) ! (n_kinds)
    integer(int64) :: rng, h(2)
    integer :: ndir, nstatv, node, npred, nprops, mcrd, kstep, kinc, kit, linper
    integer :: lopenclose, lstate, lsdi, lprint, inc, a
    logical :: adhesion, rate, heat, refuse, finite
    real(dp), allocatable :: stress(:), ddsddr(:), dvisc(:), dstruct(:), ddsddt(:), ddfddr(:)
    real(dp), allocatable :: statev(:), rdisp(:), drdisp(:), stress0(:), statev0(:)
    real(dp) :: flux(2), ddfddt(4), temp(2), dtemp(2), predef(2), dpred(2), time(2)
    real(dp) :: coords(3), alocaldir(9), drot(4), props(13)
    real(dp) :: sed, sfd, spd, svd, scd, pnewdt, dtime, freqr, area, chrlngth
    real(dp) :: amp, offset, omega, slide_amp, tau, p, bound, mu, status0
    character(len=80) :: ciname, slname, msname

    rng = 1_int64 + int(ip - 1, int64)*7919_int64
    ndir = merge(3, 2, iand(lehmer(rng), 1_int64) == 1)
    nstatv = merge(5, 3, iand(lehmer(rng), 1_int64) == 1)
    adhesion = mod(lehmer(rng), 3_int64) /= 0
    rate = mod(lehmer(rng), 4_int64) == 0
    heat = mod(lehmer(rng), 2_int64) == 0
    allocate (stress(ndir), ddsddr(ndir*ndir), dvisc(ndir*ndir), dstruct(ndir*ndir), &
              ddsddt(2*ndir), ddfddr(2*ndir), statev(nstatv), rdisp(ndir), drdisp(ndir), &
              stress0(ndir), statev0(nstatv))
    props = 0.0_dp
    props(1) = 2.0_dp
    props(2) = uniform(rng, 0.1_dp, 0.5_dp)
    if (iand(lehmer(rng), 1_int64) == 1) props(3) = props(2) + uniform(rng, 0.0_dp, 0.2_dp)
    if (adhesion) then
      props(4) = uniform(rng, 1.0_dp, 20.0_dp)
      props(5) = uniform(rng, 5.0_dp, 50.0_dp)
    end if
    if (rate) then
      props(6) = uniform(rng, 0.0_dp, 0.5_dp)
      props(7) = uniform(rng, 0.01_dp, 1.0_dp)
    end if
    props(8) = uniform(rng, 1.0e-4_dp, 1.0e-3_dp)
    props(10) = kn
    if (heat) then
      props(11) = 1.0_dp
      props(12) = 0.5_dp
    end if
    props(13) = 0.5_dp
    ciname = 'PTAB'; slname = ' '; msname = ' '
    stress = 0.0_dp; statev = statev_tail; statev(1:3) = 0.0_dp
    rdisp = 0.0_dp; drdisp = 0.0_dp
    flux = -1.0_dp; ddfddt = -1.0_dp; ddsddt = -1.0_dp; ddfddr = -1.0_dp
    sed = -1.0_dp; sfd = -1.0_dp; spd = -1.0_dp; svd = -1.0_dp; scd = -1.0_dp
    temp(1) = uniform(rng, 300.0_dp, 400.0_dp)
    temp(2) = uniform(rng, 20.0_dp, 100.0_dp)
    dtemp = 0.0_dp; predef = 0.0_dp; dpred = 0.0_dp; time = 0.0_dp
    coords = 0.0_dp; alocaldir = 0.0_dp; drot = 0.0_dp
    dtime = 0.01_dp; freqr = 0.0_dp; area = 1.0_dp; chrlngth = 1.0_dp
    node = ip; npred = 1; nprops = 13; mcrd = 3; kstep = 1; kit = 1; linper = 0
    lopenclose = -1; lstate = -1; lsdi = 0; lprint = 0
    amp = uniform(rng, 1.0e-4_dp, 2.0e-3_dp)
    offset = uniform(rng, -0.5_dp, 0.6_dp)*amp
    omega = uniform(rng, 0.05_dp, 0.3_dp)
    slide_amp = uniform(rng, 0.2_dp, 3.0_dp)*props(8)
    if (ndir == 2) then
      kinds(k_ndir2) = kinds(k_ndir2) + incs
    else
      kinds(k_ndir3) = kinds(k_ndir3) + incs
    end if

    do inc = 1, incs
      stress0 = stress
      statev0 = statev
      status0 = statev(3)
      refuse = mod(lehmer(rng), 997_int64) == 0
      rdisp(1) = offset + amp*sin(omega*(inc - 1))
      drdisp(1) = 0.0_dp
      do a = 2, ndir
        drdisp(a) = uniform(rng, -slide_amp, slide_amp)
        rdisp(a) = rdisp(a) + drdisp(a)
      end do
      if (refuse) drdisp(2) = quiet_nan()
      ddsddr = -1.0_dp; dvisc = -1.0_dp; dstruct = -1.0_dp
      pnewdt = pnewdt_in
      kinc = inc
      call uinter(stress, ddsddr, dvisc, dstruct, flux, ddfddt, ddsddt, ddfddr, statev, sed, &
                  sfd, spd, svd, scd, pnewdt, rdisp, drdisp, temp, dtemp, predef, dpred, time, &
                  dtime, freqr, ciname, slname, msname, props, coords, alocaldir, drot, area, &
                  chrlngth, node, ndir, nstatv, npred, nprops, mcrd, kstep, kinc, kit, linper, &
                  lopenclose, lstate, lsdi, lprint)
      h = [1_int64, 2_int64]
      call digest(h, stress)
      call digest(h, ddsddr)
      call digest(h, flux)
      call digest(h, ddfddt)
      call digest(h, ddfddr)
      call digest(h, statev)
      call digest(h, [sed, sfd, spd, pnewdt, real(lopenclose, dp), real(lstate, dp)])
      dig(inc) = digest_of(h)
      if (nstatv > 3) then
        if (any(transfer(statev(4:), 0_int64, nstatv - 3) /= &
                transfer(statev_tail, 0_int64))) call fault('STATEV past 3 written')
      end if
      if (refuse) then
        kinds(k_refused) = kinds(k_refused) + 1
        if (pnewdt /= 0.25_dp .or. any(transfer(stress, 0_int64, ndir) /= &
            transfer(stress0, 0_int64, ndir)) .or. any(transfer(statev, 0_int64, nstatv) /= &
            transfer(statev0, 0_int64, nstatv))) call fault('NaN in DRDISP not refused cleanly')
        drdisp(2) = 0.0_dp
        cycle
      end if
      if (pnewdt /= pnewdt_in) then
        call fault('a good call lowered PNEWDT')
        cycle
      end if
      finite = all(ieee_is_finite(stress)) .and. all(ieee_is_finite(ddsddr)) .and. &
               all(ieee_is_finite(ddfddr)) .and. all(ieee_is_finite(flux)) .and. &
               ieee_is_finite(sed) .and. ieee_is_finite(sfd) .and. ieee_is_finite(spd) .and. &
               all(ieee_is_finite(statev(1:2)))
      if (.not. finite) call fault('non-finite output')
      tau = 0.0_dp
      do a = 2, ndir
        tau = hypot(tau, stress(a))
      end do
      p = stress(1)
      mu = max(props(2), props(3))
      ! After a slip a stick increment keeps the start rate's strength (docs/props.md).
      bound = statev(2)
      if (statev0(3) == 1.0_dp) bound = max(bound, statev0(2))
      bound = (mu + props(6)*bound)*max(p, 0.0_dp) + props(4)
      if (tau > bound*(1.0_dp + 1.0e-12_dp)) call fault('|tau| above the strength')
      if (sed < 0.0_dp .or. sfd < 0.0_dp .or. spd < 0.0_dp .or. statev(1) < statev0(1) .or. &
          statev(2) < 0.0_dp) &
        call fault('negative energy or decreasing slip')
      if (lstate /= nint(statev(3)) .or. lopenclose /= merge(0, 1, statev(3) == 4.0_dp)) &
        call fault('LSTATE/LOPENCLOSE disagree with STATEV(3)')
      if (statev(3) == 0.0_dp) then
        kinds(k_stick) = kinds(k_stick) + 1
      else if (statev(3) == 1.0_dp) then
        kinds(k_slip) = kinds(k_slip) + 1
      else if (statev(3) == 3.0_dp) then
        kinds(k_bonded) = kinds(k_bonded) + 1
        if (tau >= props(4) .or. p > 0.0_dp) call fault('bonded beyond S_a or in compression')
      else if (statev(3) == 4.0_dp) then
        kinds(k_open) = kinds(k_open) + 1
        if (p /= 0.0_dp .or. tau /= 0.0_dp) call fault('open with a stress')
      else
        call fault('unknown status')
      end if
      if (status0 == 4.0_dp .and. (statev(3) == 0.0_dp .or. statev(3) == 1.0_dp)) &
        kinds(k_recontact) = kinds(k_recontact) + 1
      if (flux(1) /= 0.0_dp .or. flux(2) /= 0.0_dp) kinds(k_heat) = kinds(k_heat) + 1
    end do
    fin = 0.0_dp
    fin(1:ndir) = stress
    fin(4:3 + nstatv) = statev
    deallocate (stress, ddsddr, dvisc, dstruct, ddsddt, ddfddr, statev, rdisp, drdisp, &
                stress0, statev0)

  contains

    subroutine fault(what)
      character(len=*), intent(in) :: what
      call point_violation(ip, inc, what)
    end subroutine fault
  end subroutine run_point
end module uinter_omp_support

program test_uinter_omp
  use uinter_omp_support
  use harness_omp
  implicit none

  call omp_point_runs('UINTER', kind_names, nrec, run_point)
  call finish()
end program test_uinter_omp
