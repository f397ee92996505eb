! test_uinter_adhesive.f90 -- the adhesive friction law (seed 004, PROPS(1) = 2) through UINTER
! and FRIC from free-form Fortran: a plain `call uinter(...)` with the 47 Abaqus arguments and
! a plain `call fric(...)`, no interface block, no ISO_C_BINDING. The Fortran twin of
! c_tests/test_uinter_adhesive.c:
!   F4  velocity steps v = 0.01, 0.1 (= v_half), 1, 0.3 with k_mu and v_half both non-zero:
!       steady tau = ((mu_s v_half + mu_d v)/(v_half + v) + k_mu v) p + S_a (UINTER and FRIC);
!   onset of sliding at mu_s p + S_a (FRIC, slip ramped at constant p, v_half = 0);
!   A1  pull-off at N = N_a sqrt(1 - (S0/S_a)^2), re-bond on re-contact (UINTER, NDIR = 3),
!       with its energy balance: the work done on the interface (from STRESS and RDISP only)
!       equals SED + sum SPD after every increment; SPD = 1/2 S0^2/k_s + 1/2 N_last^2/K_n at
!       the break, 1/2 (0.99 N_a)^2/K_n at the second break, 0 otherwise;
!   bad input: negative S_a, coeffStatic < coeff, NaN -> PNEWDT = 0.25, STRESS unchanged.
! Parameters: mu_d = 0.3, mu_s = 0.5, S_a = 4, N_a = 10, k_mu = 0.2, v_half = 0.1,
! gamma_crit = 1e-3, K_n = 1e4, p = 100, DTIME = 0.1.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.
program test_uinter_adhesive
  use harness_tally, only: dp, npass, nfail, scene, check, check_abs
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  implicit none
  real(dp), parameter :: mud = 0.3_dp, mus = 0.5_dp, sa = 4.0_dp, na = 10.0_dp
  real(dp), parameter :: kmu = 0.2_dp, vhalf = 0.1_dp, gc = 1.0e-3_dp, kn = 1.0e4_dp
  real(dp), parameter :: p = 100.0_dp, dt = 0.1_dp, big = 1.0e36_dp, guard = -999.25_dp
  real(dp), parameter :: rates(4) = [0.01_dp, 0.1_dp, 1.0_dp, 0.3_dp]

  ! One UINTER point (NDIR <= 3), guard slots past NDIR / NSTATV.
  real(dp) :: stress(4), ddsddr(10), dvisc(9), dstruct(9), flux(2), ddfddt(2, 2), ddsddt(3, 2)
  real(dp) :: ddfddr(2, 3), statev(6), sed, sfd, spd, svd, scd, pnewdt
  real(dp) :: rdisp(3), drdisp(3), temp(2), dtemp(2), predef(2, 1), dpred(2, 1), time(2), freqr
  real(dp) :: props(13), coords(3), alocaldir(3, 3), drot(2, 2), area, chrlngth
  integer :: node, ndir, nstatv, npred, nprops, mcrd, kstep, kinc, kit, linper
  integer :: lopenclose, lstate, lsdi, lprint
  character(len=80) :: ciname, slname, msname

  call f4_uinter()
  call f4_fric()
  call onset()
  call pull_off()
  call bad_input()

  write (*, '(i0,a,i0,a)') npass, ' passed, ', nfail, ' failed'
  if (nfail > 0) error stop 1

contains

  real(dp) function g(v, mu_s, vh)
    real(dp), intent(in) :: v, mu_s, vh
    g = ((mu_s*vh + mud*v)/(vh + v) + kmu*v)*p + sa
  end function g

  subroutine init(n, pr)
    integer, intent(in) :: n
    real(dp), intent(in) :: pr(:)
    stress = 0; ddsddr = 0; dvisc = 0; dstruct = 0; flux = 0; ddfddt = 0; ddsddt = 0
    ddfddr = 0; statev = guard; statev(1:3) = 0; sed = 0; sfd = 0; spd = 0; svd = 0; scd = 0
    rdisp = 0; drdisp = 0; temp = 20; dtemp = 0; predef = 0; dpred = 0; time = 0; freqr = 0
    props = 0; props(1:size(pr)) = pr; nprops = size(pr)
    coords = 0; alocaldir = 0; drot = 0; area = 1; chrlngth = 1
    node = 7; ndir = n; nstatv = 3; npred = 1; mcrd = 3; kstep = 1; kinc = 1; kit = 1
    linper = 0; lopenclose = -1; lstate = -1; lsdi = 0; lprint = 0
    ciname = 'ADHESIVE'; slname = 'SLAVE'; msname = 'MASTER'
  end subroutine init

  ! The one call site of UINTER (implicit interface, as a user's host makes it).
  subroutine call_uinter()
    stress(ndir + 1:) = guard
    pnewdt = big
    call uinter(stress, ddsddr, dvisc, dstruct, flux, ddfddt, ddsddt, ddfddr, statev, sed, &
                sfd, spd, svd, scd, pnewdt, rdisp, drdisp, temp, dtemp, predef, dpred, time, &
                dt, freqr, ciname, slname, msname, props, coords, alocaldir, drot, area, &
                chrlngth, node, ndir, nstatv, npred, nprops, mcrd, kstep, kinc, kit, linper, &
                lopenclose, lstate, lsdi, lprint)
    call check(all(stress(ndir + 1:) == guard), 'STRESS past NDIR untouched')
    call check(all(statev(4:) == guard), 'STATEV past NSTATV untouched')
  end subroutine call_uinter

  subroutine f4_uinter()
    integer :: r, k
    scene = 'F4 UINTER'
    call init(2, [2.0_dp, mud, mus, sa, na, kmu, vhalf, gc, 0.0_dp, kn])
    rdisp(1) = p/kn
    do r = 1, 4
      do k = 1, 40
        drdisp(2) = rates(r)*dt
        call call_uinter()
        call check(pnewdt == big, 'PNEWDT not lowered')
      end do
      call check_abs(stress(1), p, 1.0e-12_dp*p, 'normal stress K_n h')
      call check_abs(stress(2), g(rates(r), mus, vhalf), 1.0e-12_dp*stress(2), 'steady tau = g(v)')
      call check_abs(statev(2), rates(r), 1.0e-10_dp, 'slip rate')
      call check(lopenclose == 1 .and. lstate == 1, 'closed and sliding')
    end do
  end subroutine f4_uinter

  ! FRIC with its own arguments (NFDIR = 1).
  subroutine fric_step(lm, tau, st, dgam, press, dpress, pr, pn)
    integer, intent(inout) :: lm
    real(dp), intent(inout) :: tau(1), st(3)
    real(dp), intent(in) :: dgam(1), press, dpress, pr(:)
    real(dp), intent(out) :: pn
    real(dp) :: ddtddg(1), ddtddp(1), dslip(1), sedf, sfdf, ddtddt(2), taulm(1), slip(1)
    real(dp) :: tm(2), crd(3), rcrd(3), drt(2, 2), tmp(2), prd(2, 1), chr, prp(8)
    integer :: nf, mc, np, ns, npr
    character(len=80) :: ci, sl, ms
    taulm = 0; slip = 0; tm = 0; crd = 0; rcrd = 0; drt = 0; tmp = 20; prd = 0; chr = 1
    nf = 1; mc = 3; np = 1; ns = 3; npr = size(pr); prp = 0; prp(1:npr) = pr
    ci = 'ADHESIVE'; sl = 'SLAVE'; ms = 'MASTER'
    pn = big
    call fric(lm, tau, ddtddg, ddtddp, dslip, sedf, sfdf, ddtddt, pn, st, dgam, taulm, &
              press, dpress, 1.0e6_dp, slip, 1, 1, tm, dt, 0, ci, sl, ms, 1, 7, 1, crd, rcrd, &
              drt, tmp, prd, nf, mc, np, ns, chr, prp, npr)
  end subroutine fric_step

  subroutine f4_fric()
    integer :: r, k, lm
    real(dp) :: tau(1), st(3), pn, dpress
    scene = 'F4 FRIC'
    lm = 0; tau = 0; st = 0; dpress = p
    do r = 1, 4
      do k = 1, 40
        call fric_step(lm, tau, st, [rates(r)*dt], p, dpress, &
                       [2.0_dp, mud, mus, sa, na, kmu, vhalf, gc], pn)
        dpress = 0
        call check(pn == big, 'PNEWDT not lowered')
      end do
      call check_abs(tau(1), g(rates(r), mus, vhalf), 1.0e-12_dp*tau(1), 'steady tau = g(v)')
      call check(lm == 0 .and. st(3) == 1.0_dp, 'LM = 0, sliding')
    end do
  end subroutine f4_fric

  subroutine onset()
    integer :: k, lm
    real(dp) :: tau(1), st(3), pn, dpress, ks, step, last
    logical :: slipped
    scene = 'onset FRIC'
    ks = (mus*p + sa)/gc; step = 1.0e-2_dp*gc
    lm = 0; tau = 0; st = 0; dpress = p; last = 0; slipped = .false.
    do k = 1, 200
      call fric_step(lm, tau, st, [step], p, dpress, &
                     [2.0_dp, mud, mus, sa, na, kmu, 0.0_dp, gc], pn)
      dpress = 0
      if (st(3) == 0.0_dp) then
        call check_abs(tau(1), ks*step*k, 1.0e-9_dp*tau(1), 'stick: tau = k_s gamma')
        call check(tau(1) <= mus*p + sa, 'stick below mu_s p + S_a')
        last = tau(1)
      else
        slipped = .true.
        call check(last + ks*step > mus*p + sa, 'slides once the trial exceeds mu_s p + S_a')
        call check_abs(tau(1), (mud + kmu*st(2))*p + sa, 1.0e-12_dp*tau(1), 'drop to dynamic')
        exit
      end if
    end do
    call check(slipped, 'slid')
    call check_abs(last, mus*p + sa, ks*step, 'onset stress')
  end subroutine onset

  ! One A1 increment (NDIR = 3) to the overclosure h with the tangential motion dg along
  ! direction 2. The work of the increment is the trapezoid 1/2 (sigma_start + sigma_end) du
  ! per component while the point carries stress at the end (exact for the law's linear
  ! springs), sigma_end du = 0 for an increment that ends open (backward Euler: the break point
  ! inside the increment is unknown). Checks W = SED + sum SPD and SPD >= 0.
  subroutine a1_step(h, dg, work, spdsum)
    real(dp), intent(in) :: h, dg
    real(dp), intent(inout) :: work, spdsum
    real(dp) :: s_start(3), du(3)
    s_start = stress(1:3)
    du = [h - rdisp(1), 0.0_dp, dg]
    rdisp(1) = h
    drdisp(3) = dg
    spd = -1
    call call_uinter()
    call check(pnewdt == big, 'PNEWDT not lowered')
    if (lopenclose == 1) work = work + sum(0.5_dp*(s_start + stress(1:3))*du)
    call check(spd >= 0, 'SPD >= 0')
    spdsum = spdsum + spd
    call check_abs(work, sed + spdsum, 1.0e-12_dp*abs(sed + spdsum), 'W = SED + sum SPD')
  end subroutine a1_step

  subroutine pull_off()
    integer :: k
    real(dp) :: s0, ks, nbreak, n, lastn, work, spdsum
    logical :: broke
    scene = 'A1 UINTER'
    s0 = 3.0_dp; ks = sa/gc; work = 0; spdsum = 0
    call init(3, [2.0_dp, mud, mus, sa, na, 0.0_dp, 0.0_dp, gc, 0.0_dp, kn])
    call a1_step(0.0_dp, s0/ks, work, spdsum)
    call check_abs(stress(3), s0, 1.0e-12_dp, 'bonded shear S0')
    call check(spd == 0, 'SPD = 0 while bonding')
    call check_abs(work, 0.5_dp*s0**2/ks, 1.0e-12_dp*work, 'work of the shear ramp')
    nbreak = na*sqrt(1.0_dp - (s0/sa)**2)
    broke = .false.; lastn = 0
    do k = 1, 1000
      n = 1.0e-2_dp*k
      call a1_step(-n/kn, 0.0_dp, work, spdsum)
      if (lopenclose == 1) then
        call check(n < nbreak, 'holds below the ellipse')
        call check_abs(stress(1), -n, 1.0e-9_dp, 'tension -N')
        call check_abs(stress(3), s0, 1.0e-12_dp, 'shear held')
        call check(spd == 0, 'SPD = 0 while bonded')
        lastn = n
      else
        broke = .true.
        call check(n >= nbreak .and. lastn < nbreak, 'breaks at N_a sqrt(1 - (S0/S_a)^2)')
        call check(stress(1) == 0 .and. stress(3) == 0 .and. lstate == 4, 'free after break')
        call check(sed == 0, 'SED = 0 once broken')
        ! The energy held at the last bonded increment, from K_n, k_s and the imposed stresses.
        call check_abs(spd, 0.5_dp*s0**2/ks + 0.5_dp*lastn**2/kn, 1.0e-12_dp*spd, 'SPD at the break')
        exit
      end if
    end do
    call check(broke, 'broke')
    ! Closer again but apart, then touching: free, no work, no SPD.
    call a1_step(-1.0e-9_dp, 0.0_dp, work, spdsum)
    call check(lopenclose == 0 .and. spd == 0, 'apart: free, SPD = 0')
    call a1_step(0.0_dp, 0.0_dp, work, spdsum)
    call check(lopenclose == 0 .and. spd == 0, 'touching: free, SPD = 0')
    call a1_step(1.0e-4_dp, 0.0_dp, work, spdsum)
    call check(lopenclose == 1 .and. spd == 0, 're-contact closes')
    call a1_step(-0.99_dp*na/kn, 0.0_dp, work, spdsum)
    call check(lopenclose == 1 .and. lstate == 3 .and. spd == 0, &
               're-bonded with the full strength')
    call a1_step(-1.01_dp*na/kn, 0.0_dp, work, spdsum)
    call check(lopenclose == 0, 'breaks past N_a')
    call check_abs(spd, 0.5_dp*(0.99_dp*na)**2/kn, 1.0e-12_dp*spd, 'SPD at the second break')
  end subroutine pull_off

  subroutine bad_input()
    real(dp) :: nan
    nan = ieee_value(nan, ieee_quiet_nan)
    scene = 'bad input'
    call bad([2.0_dp, mud, mus, -1.0_dp, na, 0.0_dp, 0.0_dp, gc, 0.0_dp, kn], 0.0_dp, 'Sa < 0')
    call bad([2.0_dp, mud, mus, sa, -1.0_dp, 0.0_dp, 0.0_dp, gc, 0.0_dp, kn], 0.0_dp, 'Na < 0')
    call bad([2.0_dp, mud, 0.2_dp, sa, na, 0.0_dp, 0.0_dp, gc, 0.0_dp, kn], 0.0_dp, &
             'coeffStatic < coeff')
    call bad([2.0_dp, mud, mus, sa, na, 0.0_dp, 0.0_dp, gc, 0.0_dp, kn], nan, 'NaN DRDISP')
  end subroutine bad_input

  subroutine bad(pr, dg, what)
    real(dp), intent(in) :: pr(:), dg
    character(len=*), intent(in) :: what
    call init(2, pr)
    stress(1:2) = [5.0_dp, 1.0_dp]
    rdisp(1) = 1.0e-3_dp
    drdisp(2) = dg
    call call_uinter()
    call check(pnewdt == 0.25_dp, what//': PNEWDT = 0.25')
    call check(stress(1) == 5.0_dp .and. stress(2) == 1.0_dp, what//': STRESS unchanged')
    call check(lopenclose == -1, what//': LOPENCLOSE unchanged')
  end subroutine bad
end program test_uinter_adhesive
