! test_fric_weakening.f90 -- velocity-weakening friction (issue 16, scene F7) through FRIC and
! UINTER, called as a user's Fortran 90 host calls them: plain `call fric(...)` and
! `call uinter(...)`, no interface block. The Fortran twin of c_tests/test_fric_weakening.c,
! with the same scenes and closed forms:
!   steady sliding at v with increments r*gamma_crit (r = 0.01 .. 5, d_c v = 0.3 .. 10), NFDIR 1
!     and 2: tau = mu(v) p (decay law, PROPS(8) = 1) or S_slide(v) (adhesive law, seed 004),
!     never above the static strength before the first slip;
!   stop: increments without motion keep the sliding stress (stick);
!   reversal: stick through zero stress, then sliding at -mu(v) p;
!   fresh gap (UINTER): free (zero stress, STATEV(3) = 4, LOPENCLOSE = 0) until first contact,
!     bonded (STATEV(3) = 3, tension K_n |h|) at the same gap afterwards.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

program test_fric_weakening
  use harness_tally
  use harness_fric_host
  use harness_uinter_host
  implicit none
  real(dp), parameter :: gcrit = 1.0e-3_dp, p = 100.0_dp, mu_s = 0.5_dp, mu_k = 0.2_dp
  real(dp), parameter :: dc = 200.0_dp, sa = 3.0_dp, kmu = 0.5_dp, vhalf = 1.0e-3_dp

  ! The FRIC arguments of one contact point (module harness_fric_host) and the slip direction.
  type(fric_args) :: h
  real(dp) :: d(2)
  integer :: law, nd

  do law = 1, 2
    do nd = 1, 2
      call steady(law, nd)
      call stop_and_reversal(law, nd)
    end do
  end do
  call fresh_gap(2)
  call fresh_gap(3)
  call finish()

contains

  real(dp) function sliding(lw, v)
    integer, intent(in) :: lw
    real(dp), intent(in) :: v
    if (lw == 1) then
      sliding = (mu_k + (mu_s - mu_k)*exp(-dc*v))*p
    else
      sliding = ((mu_s*vhalf + mu_k*v)/(vhalf + v) + kmu*v)*p + sa
    end if
  end function sliding

  real(dp) function static_strength(lw)
    integer, intent(in) :: lw
    static_strength = mu_s*p
    if (lw == 2) static_strength = mu_s*p + sa
  end function static_strength

  subroutine point(lw, n)
    integer, intent(in) :: lw, n
    if (lw == 1) then
      h = new_point(n, [1.0_dp, mu_s, 0.0_dp, 0.0_dp, gcrit, 0.0_dp, 0.0_dp, 1.0_dp, mu_k, dc], &
                    'WEAKENING')
    else
      h = new_point(n, [2.0_dp, mu_k, mu_s, sa, 0.0_dp, kmu, vhalf, gcrit], 'WEAKENING')
    end if
    h%press = p
    h%dtime = 1
    h%noel = 17
    h%node = 42
    d = [1.0_dp, 0.0_dp]
    if (n == 2) d = [0.6_dp, -0.8_dp]
  end subroutine point

  ! One increment of slip dg along d in time |dg|/v; returns tau along d.
  real(dp) function step(dg, v)
    real(dp), intent(in) :: dg, v
    h%dgam(1:h%nfdir) = dg*d(1:h%nfdir)
    h%dtime = abs(dg)/v
    if (dg == 0) h%dtime = 0.1_dp ! a stop still takes time
    h%dpress = 0
    call fric_call(h)
    call check(h%pnewdt == big, 'no cut-back')
    call check_tails(h)
    step = dot_product(h%tau(1:h%nfdir), d(1:h%nfdir))
  end function step

  subroutine steady(lw, n)
    integer, intent(in) :: lw, n
    real(dp), parameter :: ratios(6) = [0.01_dp, 0.1_dp, 0.25_dp, 0.5_dp, 1.0_dp, 5.0_dp]
    real(dp), parameter :: xs(4) = [0.3_dp, 1.0_dp, 3.0_dp, 10.0_dp]
    real(dp) :: r, v, t, want
    integer :: i, j, k, ninc
    logical :: slid
    do i = 1, 6
      do j = 1, 4
        r = ratios(i)
        v = xs(j)/dc
        want = sliding(lw, v)
        write (scene, '(a,i0,a,i0,a,g0.3,a,g0.3)') 'steady law ', lw, ' NFDIR ', n, ' r ', r, &
          ' d_c v ', xs(j)
        call point(lw, n)
        ninc = ceiling(1.5_dp/r) + 20
        slid = .false.
        do k = 1, ninc
          t = step(r*gcrit, v)
          if (h%statev(3) == 1) slid = .true.
          if (.not. slid) call check(t <= static_strength(lw)*(1 + 1.0e-12_dp), &
                                     'below the static strength before the first slip')
        end do
        call check(slid, 'slides')
        do k = 1, 20
          t = step(r*gcrit, v)
          call check(h%statev(3) == 1, 'sliding')
          call check_near(t, want, 1.0e-9_dp, 0.0_dp, 'tau = mu(v) p')
          call check_near(h%statev(2), v, 1.0e-9_dp, 0.0_dp, 'STATEV(2) = v')
        end do
      end do
    end do
  end subroutine steady

  subroutine stop_and_reversal(lw, n)
    integer, intent(in) :: lw, n
    real(dp) :: v, want, t, r
    integer :: k, crossed, first_slip
    v = 3.0_dp/dc
    r = 0.1_dp
    want = sliding(lw, v)
    call point(lw, n)
    write (scene, '(a,i0,a,i0)') 'stop law ', lw, ' NFDIR ', n
    do k = 1, 40
      t = step(r*gcrit, v)
    end do
    call check_near(t, want, 1.0e-9_dp, 0.0_dp, 'sliding before the stop')
    do k = 1, 4
      t = step(0.0_dp, v)
      call check(h%statev(3) == 0, 'a stop is stick')
      call check_near(t, want, 1.0e-9_dp, 0.0_dp, 'a stop keeps the stress')
    end do
    write (scene, '(a,i0,a,i0)') 'reversal law ', lw, ' NFDIR ', n
    crossed = -1
    first_slip = -1
    do k = 1, 80
      t = step(-r*gcrit, v)
      if (crossed < 0 .and. t < 0) crossed = k
      if (first_slip < 0 .and. h%statev(3) == 1) first_slip = k
    end do
    call check(crossed > 1, 'the first reversed increment still pushes forward')
    call check(first_slip > crossed, 'stick through zero stress')
    call check_near(t, -want, 1.0e-9_dp, 0.0_dp, 'sliding the other way')
  end subroutine stop_and_reversal

  subroutine fresh_gap(ndir)
    integer, intent(in) :: ndir
    type(uinter_args) :: u
    integer :: pass
    u = new_uinter(ndir, [2.0_dp, mu_k, mu_s, sa, 5.0_dp, 0.0_dp, 0.0_dp, gcrit, 0.0_dp, &
                          1.0e6_dp], 'FRESH')
    u%drdisp = [-1.0e-6_dp, 1.0e-5_dp, 0.0_dp]
    u%drot = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
    u%node = 1
    do pass = 0, 2
      write (scene, '(a,i0,a,i0)') 'fresh gap NDIR ', ndir, ' pass ', pass
      u%rdisp(1) = -1.0e-6_dp
      if (pass == 1) u%rdisp(1) = 1.0e-6_dp
      call uinter_call(u)
      call check(u%pnewdt == big, 'no cut-back')
      call check_uinter_tails(u)
      u%drdisp(2) = 0
      select case (pass)
      case (0)
        call check(all(u%stress(1:ndir) == 0), 'a fresh point with a gap carries nothing')
        call check(u%statev(3) == 4, 'status open')
        call check(u%lopenclose == 0, 'LOPENCLOSE = 0')
      case (1)
        call check_near(u%stress(1), 1.0_dp, 1.0e-12_dp, 0.0_dp, 'closed: p = K_n h')
        call check(u%statev(3) == 0, 'status stick')
      case default
        call check_near(u%stress(1), -1.0_dp, 1.0e-12_dp, 0.0_dp, 'bonded: tension K_n |h|')
        call check(u%statev(3) == 3, 'status bonded')
        call check(u%lopenclose == 1, 'LOPENCLOSE = 1')
      end select
    end do
  end subroutine fresh_gap
end program test_fric_weakening
