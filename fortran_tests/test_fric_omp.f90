! test_fric_omp.f90 -- FRIC from an OpenMP parallel loop (OMP_NUM_THREADS = 8, set by CTest),
! compared bit for bit with a serial run of the same points. The Fortran twin of
! c_tests/test_fric_threads.c; FRIC is called as Abaqus user code calls it: a plain
! `call fric(...)` with the 39 arguments and no interface block.
!
! 4096 contact points x 256 increments = 1 048 576 calls per run. Each point is driven
! increment by increment (TAU, STATEV and LM carried, PRESS and DPRESS consistent, the host's
! Lagrange stress TAULM handed to exact-stick points) with its own Coulomb interaction drawn
! from a Lehmer generator x <- 48271 x mod (2**31 - 1) seeded by the point's index: NFDIR 1 or 2;
! elastic stick (stick and slip), exact stick (LM = 1 held, released, entered by a reversal) or
! rough; a tau_max cap or none; gamma_crit from PROPS(5) or PROPS(6) x CHRLNGTH; NSTATV 3 or 5;
! now and then a negative pressure (no friction) and a NaN in DGAM (refused: PNEWDT = 0.25, the
! state unchanged, the thread's last error names the element). Every array FRIC may touch is
! allocated at exactly its declared size, so valgrind sees any write past it (a valgrind run
! sets INTERFACIAL_TEST_SHRINK=n: 1/n of the points; sizes in harness_omp.f90).
!
! Compared with the serial run: every output of every call (LM, TAU, DDTDDG, DDTDDP, DSLIP, SED,
! SFD, DDTDDT, PNEWDT, STATEV), bit patterns folded into a 62-bit digest per call; the final
! contents of all those arrays per point, bit for bit; the counts of each kind of call.
! Checked on every call against the law: refused exactly when the host put a NaN in a read
! input, |tau| <= tau_crit = min(mu p, tau_max) and = tau_crit when slipping, SED, SFD >= 0,
! exact-stick outputs, rough points LM = 1, STATEV(1) never decreasing, STATEV past 3 untouched,
! PNEWDT untouched by a successful call. Each kind of call must occur often, and at least 8
! OpenMP threads must have done work.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

module fric_omp_support
  use harness_threads
  use harness_omp, only: incs, point_violation
  implicit none
  real(dp), parameter :: pnewdt_in = 1.0e36_dp, statev_tail = -5.5e55_dp, cutback = 0.25_dp
  integer, parameter :: nrec = 24 ! final record: see final_record

  ! Kinds of call, counted per run.
  integer, parameter :: k_stick = 1, k_slip = 2, k_capped = 3, k_exact = 4, k_held = 5, &
    k_released = 6, k_reversal = 7, k_rough = 8, k_no_press = 9, k_refused = 10, &
    k_nfdir1 = 11, k_nfdir2 = 12, n_kinds = 12
  character(len=24), parameter :: kind_names(n_kinds) = [character(len=24) :: 'stick', &
    'slip', 'slip on tau_max', 'exact stick', 'exact stick held', 'released', &
    'reversal to exact stick', 'rough', 'negative pressure', 'refused (NaN)', 'NFDIR 1', &
    'NFDIR 2']

contains

  real(dp) function norm(v)
    real(dp), intent(in) :: v(:)
    norm = sqrt(sum(v*v))
    if (size(v) == 1) norm = abs(v(1))
  end function norm

  ! One contact point of one run: 256 increments into dig(:), the final outputs into fin(:),
  ! counts into kinds(:), broken checks to point_violation.
  subroutine run_point(ip, dig, fin, kinds)
    integer, intent(in) :: ip
    integer(int64), intent(out) :: dig(:) ! (incs)
    real(dp), intent(out) :: fin(:) ! (nrec)
    integer(int64), intent(inout) :: kinds(:) ! (n_kinds)
    ! FRIC's arguments; the arrays at exactly their declared sizes.
    real(dp), allocatable :: tau(:), ddtddg(:, :), ddtddp(:), dslip(:), ddtddt(:, :), &
      statev(:), dgam(:), taulm(:), slip(:)
    integer :: lm, nfdir, nstatv, nprops, mode, noel, node, npt, npatch, kstep, kinc, mcrd, &
      npred, lm_in, inc, i
    real(dp) :: props(7), sed, sfd, pnewdt, press, dpress, ddpddh, time(2), dtime, chrlngth, &
      coords(3), rcoord(3), drot(2, 2), temp(2), predef(2, 1)
    character(len=80) :: ciname, slname, msname
    ! The host's bookkeeping.
    integer(int64) :: rng, h(2)
    real(dp) :: p_ref, tau_max, gc, p_old, tau_crit, tau_old(2), statev_old(3), s1_old, tn, m
    logical :: nan_call, slipping
    character(len=2048) :: msg
    character(len=32) :: want

    rng = int(mod(ip, int(lehmer_m) - 1), int64) + 1_int64
    do i = 1, 4 ! decorrelate neighbouring seeds
      h(1) = lehmer(rng)
    end do
    nfdir = merge(1, 2, uniform(rng, 0.0_dp, 1.0_dp) < 0.5_dp)
    m = uniform(rng, 0.0_dp, 1.0_dp)
    mode = merge(0, merge(1, 2, m < 0.9_dp), m < 0.6_dp)
    nstatv = merge(3, 5, uniform(rng, 0.0_dp, 1.0_dp) < 0.75_dp)
    p_ref = uniform(rng, 10.0_dp, 100.0_dp)
    props = 0.0_dp
    props(1) = 1.0_dp
    props(2) = uniform(rng, 0.1_dp, 0.6_dp)
    tau_max = huge(1.0_dp)
    if (uniform(rng, 0.0_dp, 1.0_dp) < 0.3_dp) then
      tau_max = props(2)*p_ref*uniform(rng, 0.6_dp, 1.0_dp)
      props(4) = tau_max
    end if
    chrlngth = uniform(rng, 0.05_dp, 0.2_dp)
    if (uniform(rng, 0.0_dp, 1.0_dp) < 0.5_dp) then
      props(5) = uniform(rng, 1.0e-4_dp, 1.0e-3_dp)
      gc = props(5)
    else
      props(6) = uniform(rng, 0.002_dp, 0.01_dp)
      gc = props(6)*chrlngth
    end if
    props(7) = real(mode, dp)
    nprops = 7
    allocate (tau(nfdir), ddtddg(nfdir, nfdir), ddtddp(nfdir), dslip(nfdir), &
              ddtddt(nfdir, 2), statev(nstatv), dgam(nfdir), taulm(nfdir), slip(nfdir))
    tau = 0.0_dp
    ddtddg = 0.0_dp
    ddtddp = 0.0_dp
    dslip = 0.0_dp
    ddtddt = 0.0_dp
    statev = statev_tail
    statev(1:3) = 0.0_dp
    slip = 0.0_dp
    sed = 0.0_dp
    sfd = 0.0_dp
    lm = 0
    press = 0.0_dp
    ciname = 'FRICTION_OMP'
    slname = 'SLAVE'
    msname = 'MASTER'
    noel = ip
    node = ip
    npt = 1
    npatch = 0
    kstep = 1
    mcrd = nfdir + 1
    npred = 1
    dtime = 0.01_dp
    ddpddh = 1.0e6_dp
    coords = 0.0_dp
    rcoord = 0.0_dp
    drot = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
    temp = [20.0_dp, 0.0_dp]
    predef = 0.0_dp

    do inc = 1, incs
      kinc = inc
      time = 0.01_dp*(inc - 1)
      p_old = press
      press = p_ref*uniform(rng, 0.7_dp, 1.3_dp)
      if (uniform(rng, 0.0_dp, 1.0_dp) < 1.0_dp/64.0_dp) press = -0.05_dp*p_ref
      dpress = press - p_old
      do i = 1, nfdir
        dgam(i) = uniform(rng, -2.0_dp, 2.0_dp)*gc
      end do
      tau_crit = 0.0_dp
      if (press > 0.0_dp) tau_crit = min(props(2)*press, tau_max)
      do i = 1, nfdir
        taulm(i) = uniform(rng, -1.2_dp, 1.2_dp)*merge(tau_crit, p_ref, press > 0.0_dp) &
                   /sqrt(real(nfdir, dp))
      end do
      nan_call = mod(ip - 1, 8) == 3 .and. mod(inc - 1, 97) == 50
      if (nan_call) then
        dgam(1) = quiet_nan()
      else
        slip = slip + dgam
      end if
      pnewdt = pnewdt_in
      tau_old = [tau(1), tau(nfdir)]
      statev_old = statev(1:3)
      s1_old = statev(1)
      lm_in = lm

      call fric(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, &
                taulm, press, dpress, ddpddh, slip, kstep, kinc, time, dtime, noel, ciname, &
                slname, msname, npt, node, npatch, coords, rcoord, drot, temp, predef, nfdir, &
                mcrd, npred, nstatv, chrlngth, props, nprops)

      i = merge(k_nfdir1, k_nfdir2, nfdir == 1)
      kinds(i) = kinds(i) + 1
      do i = 4, nstatv
        if (.not. same_bits(statev(i), statev_tail)) call fault('STATEV past 3 written')
      end do
      if (nan_call .and. mode /= 2) then ! rough points do not read DGAM
        kinds(k_refused) = kinds(k_refused) + 1
        if (pnewdt /= cutback .or. lm /= lm_in .or. .not. same_bits(tau(1), tau_old(1)) .or. &
            .not. same_bits(tau(nfdir), tau_old(2)) .or. &
            any(transfer(statev(1:3), 0_int64, 3) /= transfer(statev_old, 0_int64, 3))) &
          call fault('refused call: PNEWDT not 0.25 or state changed')
        msg = last_error()
        write (want, '(a,i0,a)') 'element ', noel, ','
        if (index(msg, trim(want)) == 0 .or. index(msg, 'DGAM') == 0) &
          call fault('last error does not name the element and DGAM: '//trim(msg))
        dgam(1) = 0.0_dp
        press = p_old ! the increment did not happen
      else
        call judge()
      end if
      h = 1_int64
      call digest(h, real(lm, dp))
      do i = 1, nfdir
        call digest(h, tau(i))
        call digest(h, ddtddp(i))
        call digest(h, dslip(i))
        call digest(h, ddtddt(i, 1))
        call digest(h, ddtddt(i, 2))
      end do
      do i = 1, nfdir*nfdir
        call digest(h, ddtddg(mod(i - 1, nfdir) + 1, (i - 1)/nfdir + 1))
      end do
      call digest(h, sed)
      call digest(h, sfd)
      call digest(h, pnewdt)
      do i = 1, nstatv
        call digest(h, statev(i))
      end do
      dig(inc) = digest_of(h)
    end do

    fin = 0.0_dp
    fin(1:nfdir) = tau
    fin(3:2 + nfdir*nfdir) = reshape(ddtddg, [nfdir*nfdir])
    fin(7:6 + nfdir) = ddtddp
    fin(9:8 + nfdir) = dslip
    fin(11:10 + 2*nfdir) = reshape(ddtddt, [2*nfdir])
    fin(15:14 + nstatv) = statev
    fin(20:24) = [sed, sfd, pnewdt, press, real(lm, dp)]
    deallocate (tau, ddtddg, ddtddp, dslip, ddtddt, statev, dgam, taulm, slip)

  contains

    subroutine fault(what)
      character(len=*), intent(in) :: what
      call point_violation(ip, inc, what)
    end subroutine fault

    ! A successful call against the law.
    subroutine judge()
      if (pnewdt /= pnewdt_in) call fault('PNEWDT changed by a successful call')
      if (.not. statev(1) >= s1_old) call fault('STATEV(1) decreased')
      if (press <= 0.0_dp) kinds(k_no_press) = kinds(k_no_press) + 1
      if (mode == 2) then
        kinds(k_rough) = kinds(k_rough) + 1
        if (lm /= 1) call fault('rough point not LM = 1')
        return
      end if
      if (lm == 1) then
        if (mode /= 1) call fault('LM = 1 out of an elastic-stick point')
        kinds(k_exact) = kinds(k_exact) + 1
        if (lm_in == 1) then
          kinds(k_held) = kinds(k_held) + 1
          if (.not. norm(taulm) <= tau_crit) call fault('held exact stick with |TAULM| > tau_crit')
        else
          kinds(k_reversal) = kinds(k_reversal) + 1
        end if
        if (statev(3) /= 2.0_dp .or. sed /= 0.0_dp .or. sfd /= 0.0_dp .or. any(dslip /= 0.0_dp)) &
          call fault('exact stick: STATEV(3) = 2, DSLIP = SED = SFD = 0')
        tau = taulm ! the host's stress at exact stick is the Lagrange stress
        return
      end if
      if (lm /= 0) then
        call fault('LM not 0 or 1')
        return
      end if
      if (lm_in == 1) then
        kinds(k_released) = kinds(k_released) + 1
        if (.not. norm(taulm) > tau_crit) call fault('released with |TAULM| <= tau_crit')
      end if
      tn = norm(tau)
      slipping = statev(3) == 1.0_dp
      if (.not. tn <= tau_crit*(1.0_dp + 1.0e-12_dp)) call fault('|tau| > tau_crit')
      if (slipping .and. .not. abs(tn - tau_crit) <= 1.0e-12_dp*tau_crit) &
        call fault('slipping with |tau| /= tau_crit')
      if (.not. (sed >= 0.0_dp .and. sfd >= 0.0_dp)) call fault('SED or SFD negative')
      if (statev(3) /= 0.0_dp .and. .not. slipping) call fault('STATEV(3) not 0 or 1 with LM = 0')
      if (slipping) then
        kinds(k_slip) = kinds(k_slip) + 1
        if (props(2)*press > tau_max) kinds(k_capped) = kinds(k_capped) + 1
      else
        kinds(k_stick) = kinds(k_stick) + 1
      end if
    end subroutine judge
  end subroutine run_point
end module fric_omp_support

program test_fric_omp
  use fric_omp_support
  use harness_omp
  implicit none

  call omp_point_runs('FRIC', kind_names, nrec, run_point)
  call finish()
end program test_fric_omp
