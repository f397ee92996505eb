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
!   gamma_crit = 2 exactly read as gamma_crit, as 2.0000001 (FRIC, NFDIR 1 and 2);
!   bad input: negative S_a, coeffStatic < coeff, NaN -> PNEWDT = 0.25, STRESS unchanged.
! Parameters: mu_d = 0.3, mu_s = 0.5, S_a = 4, N_a = 10, k_mu = 0.2, v_half = 0.1,
! gamma_crit = 1e-3, K_n = 1e4, p = 100, DTIME = 0.1.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.
program test_uinter_adhesive
  use harness_tally, only: dp, finish, scene, check, check_abs
  use harness_fric_host, only: fric_args, new_point, fric_call, check_tails
  use harness_uinter_host
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  implicit none
  real(dp), parameter :: mud = 0.3_dp, mus = 0.5_dp, sa = 4.0_dp, na = 10.0_dp
  real(dp), parameter :: kmu = 0.2_dp, vhalf = 0.1_dp, gc = 1.0e-3_dp, kn = 1.0e4_dp
  real(dp), parameter :: p = 100.0_dp, dt = 0.1_dp, big = 1.0e36_dp
  real(dp), parameter :: rates(4) = [0.01_dp, 0.1_dp, 1.0_dp, 0.3_dp]

  ! One UINTER point (module harness_uinter_host).
  type(uinter_args) :: u

  call f4_uinter()
  call f4_fric()
  call onset()
  call gamma_crit_two()
  call pull_off()
  call bad_input()

  call finish()

contains

  real(dp) function g(v, mu_s, vh)
    real(dp), intent(in) :: v, mu_s, vh
    g = ((mu_s*vh + mud*v)/(vh + v) + kmu*v)*p + sa
  end function g

  subroutine init(n, pr)
    integer, intent(in) :: n
    real(dp), intent(in) :: pr(:)
    u = new_uinter(n, pr, 'ADHESIVE')
    u%dtime = dt
  end subroutine init

  ! The one call site of UINTER (implicit interface, as a user's host makes it).
  subroutine call_uinter()
    call uinter_call(u)
    call check_uinter_tails(u)
  end subroutine call_uinter

  subroutine f4_uinter()
    integer :: r, k
    scene = 'F4 UINTER'
    call init(2, [2.0_dp, mud, mus, sa, na, kmu, vhalf, gc, 0.0_dp, kn])
    u%rdisp(1) = p/kn
    do r = 1, 4
      do k = 1, 40
        u%drdisp(2) = rates(r)*dt
        call call_uinter()
        call check(u%pnewdt == big, 'PNEWDT not lowered')
      end do
      call check_abs(u%stress(1), p, 1.0e-12_dp*p, 'normal stress K_n h')
      call check_abs(u%stress(2), g(rates(r), mus, vhalf), 1.0e-12_dp*u%stress(2), &
                     'steady tau = g(v)')
      call check_abs(u%statev(2), rates(r), 1.0e-10_dp, 'slip rate')
      call check(u%lopenclose == 1 .and. u%lstate == 1, 'closed and sliding')
    end do
  end subroutine f4_uinter

  ! The same law through FRIC (module harness_fric_host), NFDIR = 1, at first contact under p.
  function fric_point(pr) result(a)
    real(dp), intent(in) :: pr(:)
    type(fric_args) :: a
    a = new_point(1, pr, 'ADHESIVE')
    a%press = p
    a%dpress = p
    a%dtime = dt
  end function fric_point

  ! gamma_crit = 2 exactly (PROPS(8) = 2, law 1's mu-table switch in the other layout) is read as
  ! gamma_crit: fric_ sticks with tau = k_s dgam, k_s = (mu_s p + S_a)/2, like 2.0000001.
  subroutine gamma_crit_two()
    real(dp), parameter :: gs(2) = [2.0_dp, 2.0000001_dp]
    real(dp) :: taus(2)
    integer :: i, nfdir
    type(fric_args) :: a
    scene = 'gamma_crit = 2 FRIC'
    do nfdir = 1, 2
      do i = 1, 2
        a = new_point(nfdir, [2.0_dp, mud, mus, sa, na, 0.0_dp, 0.0_dp, gs(i)], 'ADHESIVE')
        a%press = p
        a%dpress = p
        a%dtime = dt
        a%dgam(1) = 0.5_dp
        call fric_call(a)
        call check_tails(a)
        call check(a%pnewdt == big, 'PNEWDT not lowered')
        call check_abs(a%tau(1), (mus*p + sa)/gs(i)*0.5_dp, 1.0e-12_dp*a%tau(1), &
                       'stick: tau = k_s dgam')
        taus(i) = a%tau(1)
      end do
      call check_abs(taus(1), taus(2), 1.0e-6_dp*taus(1), 'continuous in gamma_crit')
    end do
  end subroutine gamma_crit_two

  subroutine f4_fric()
    integer :: r, k
    type(fric_args) :: a
    scene = 'F4 FRIC'
    a = fric_point([2.0_dp, mud, mus, sa, na, kmu, vhalf, gc])
    do r = 1, 4
      do k = 1, 40
        a%dgam(1) = rates(r)*dt
        call fric_call(a)
        call check_tails(a)
        a%dpress = 0
        call check(a%pnewdt == big, 'PNEWDT not lowered')
      end do
      call check_abs(a%tau(1), g(rates(r), mus, vhalf), 1.0e-12_dp*a%tau(1), 'steady tau = g(v)')
      call check(a%lm == 0 .and. a%statev(3) == 1.0_dp, 'LM = 0, sliding')
    end do
  end subroutine f4_fric

  subroutine onset()
    integer :: k
    type(fric_args) :: a
    real(dp) :: ks, step, last
    logical :: slipped
    scene = 'onset FRIC'
    ks = (mus*p + sa)/gc; step = 1.0e-2_dp*gc
    a = fric_point([2.0_dp, mud, mus, sa, na, kmu, 0.0_dp, gc])
    last = 0; slipped = .false.
    do k = 1, 200
      a%dgam(1) = step
      call fric_call(a)
      a%dpress = 0
      if (a%statev(3) == 0.0_dp) then
        call check_abs(a%tau(1), ks*step*k, 1.0e-9_dp*a%tau(1), 'stick: tau = k_s gamma')
        call check(a%tau(1) <= mus*p + sa, 'stick below mu_s p + S_a')
        last = a%tau(1)
      else
        slipped = .true.
        call check(last + ks*step > mus*p + sa, 'slides once the trial exceeds mu_s p + S_a')
        call check_abs(a%tau(1), (mud + kmu*a%statev(2))*p + sa, 1.0e-12_dp*a%tau(1), &
                       'drop to dynamic')
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
    s_start = u%stress(1:3)
    du = [h - u%rdisp(1), 0.0_dp, dg]
    u%rdisp(1) = h
    u%drdisp(3) = dg
    u%spd = -1
    call call_uinter()
    call check(u%pnewdt == big, 'PNEWDT not lowered')
    if (u%lopenclose == 1) work = work + sum(0.5_dp*(s_start + u%stress(1:3))*du)
    call check(u%spd >= 0, 'SPD >= 0')
    spdsum = spdsum + u%spd
    call check_abs(work, u%sed + spdsum, 1.0e-12_dp*abs(u%sed + spdsum), 'W = SED + sum SPD')
  end subroutine a1_step

  subroutine pull_off()
    integer :: k
    real(dp) :: s0, ks, nbreak, n, lastn, work, spdsum
    logical :: broke
    scene = 'A1 UINTER'
    s0 = 3.0_dp; ks = sa/gc; work = 0; spdsum = 0
    call init(3, [2.0_dp, mud, mus, sa, na, 0.0_dp, 0.0_dp, gc, 0.0_dp, kn])
    call a1_step(0.0_dp, s0/ks, work, spdsum)
    call check_abs(u%stress(3), s0, 1.0e-12_dp, 'bonded shear S0')
    call check(u%spd == 0, 'SPD = 0 while bonding')
    call check_abs(work, 0.5_dp*s0**2/ks, 1.0e-12_dp*work, 'work of the shear ramp')
    nbreak = na*sqrt(1.0_dp - (s0/sa)**2)
    broke = .false.; lastn = 0
    do k = 1, 1000
      n = 1.0e-2_dp*k
      call a1_step(-n/kn, 0.0_dp, work, spdsum)
      if (u%lopenclose == 1) then
        call check(n < nbreak, 'holds below the ellipse')
        call check_abs(u%stress(1), -n, 1.0e-9_dp, 'tension -N')
        call check_abs(u%stress(3), s0, 1.0e-12_dp, 'shear held')
        call check(u%spd == 0, 'SPD = 0 while bonded')
        lastn = n
      else
        broke = .true.
        call check(n >= nbreak .and. lastn < nbreak, 'breaks at N_a sqrt(1 - (S0/S_a)^2)')
        call check(u%stress(1) == 0 .and. u%stress(3) == 0 .and. u%lstate == 4, 'free after break')
        call check(u%sed == 0, 'SED = 0 once broken')
        ! The energy held at the last bonded increment, from K_n, k_s and the imposed stresses.
        call check_abs(u%spd, 0.5_dp*s0**2/ks + 0.5_dp*lastn**2/kn, 1.0e-12_dp*u%spd, &
                       'SPD at the break')
        exit
      end if
    end do
    call check(broke, 'broke')
    ! Closer again but apart, then touching: free, no work, no SPD.
    call a1_step(-1.0e-9_dp, 0.0_dp, work, spdsum)
    call check(u%lopenclose == 0 .and. u%spd == 0, 'apart: free, SPD = 0')
    call a1_step(0.0_dp, 0.0_dp, work, spdsum)
    call check(u%lopenclose == 0 .and. u%spd == 0, 'touching: free, SPD = 0')
    call a1_step(1.0e-4_dp, 0.0_dp, work, spdsum)
    call check(u%lopenclose == 1 .and. u%spd == 0, 're-contact closes')
    call a1_step(-0.99_dp*na/kn, 0.0_dp, work, spdsum)
    call check(u%lopenclose == 1 .and. u%lstate == 3 .and. u%spd == 0, &
               're-bonded with the full strength')
    call a1_step(-1.01_dp*na/kn, 0.0_dp, work, spdsum)
    call check(u%lopenclose == 0, 'breaks past N_a')
    call check_abs(u%spd, 0.5_dp*(0.99_dp*na)**2/kn, 1.0e-12_dp*u%spd, 'SPD at the second break')
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
    u%stress(1:2) = [5.0_dp, 1.0_dp]
    u%rdisp(1) = 1.0e-3_dp
    u%drdisp(2) = dg
    call call_uinter()
    call check(u%pnewdt == 0.25_dp, what//': PNEWDT = 0.25')
    call check(u%stress(1) == 5.0_dp .and. u%stress(2) == 1.0_dp, what//': STRESS unchanged')
    call check(u%lopenclose == -1, what//': LOPENCLOSE unchanged')
  end subroutine bad
end program test_uinter_adhesive
