! test_uinter_heat.f90 -- the heat flux of UINTER (adhesive law, PROPS(11) = 1: the
! conductance of interaction PTAB from configs/uinter_heat.toml, named by INTERFACIAL_CONFIG in
! CMake), called with a plain `call uinter(...)`: the Fortran twin of the T1 and frictional-heat
! parts of c_tests/test_uinter_heat.c.
!   T1: bar A (far end 400, resistance 2e-4) against bar B (far end 20, resistance 1e-3), the
!       interface closed at p = K_n h = 40, k(40) = 1300 (by hand from the table). Newton on
!       (TEMP(1), TEMP(2)) with the Jacobian -1/R - DDFDDT converges in one iteration (the
!       problem is linear) to q = 380/(2e-4 + 1/1300 + 1e-3).
!   Frictional heat while sliding at p = 50 (eta = 0.8, f = 0.25): FLUX(1) + FLUX(2) =
!       eta SFD/DTIME, SFD = mu p (|dgam| - gamma_crit), FLUX(1) = k(50)(T2 - T1) + f eta SFD/DTIME.
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.
program test_uinter_heat
  use harness_tally, only: dp, finish, check, check_abs
  use harness_uinter_host
  implicit none
  real(dp), parameter :: th = 400.0_dp, tc = 20.0_dp, ra = 2.0e-4_dp, rb = 1.0e-3_dp
  real(dp), parameter :: kn = 1.0e4_dp, dt = 0.5_dp, big = 1.0e36_dp
  integer :: it
  ! The UINTER arguments of the point (module harness_uinter_host).
  type(uinter_args) :: u
  real(dp) :: r1, r2, j11, j12, j21, j22, det, q, qin(2)

  ! T1
  call init(0.0_dp)
  u%rdisp(1) = 40.0_dp/kn
  u%temp = [th, tc]
  do it = 1, 5
    call call_uinter()
    r1 = (th - u%temp(1))/ra + u%flux(1)
    r2 = (tc - u%temp(2))/rb + u%flux(2)
    if (abs(r1) + abs(r2) < 1.0e-9_dp*(th - tc)/ra .and. it > 1) exit
    j11 = -1.0_dp/ra - u%ddfddt(1, 1); j12 = -u%ddfddt(1, 2)
    j21 = -u%ddfddt(2, 1); j22 = -1.0_dp/rb - u%ddfddt(2, 2)
    det = j11*j22 - j12*j21
    u%temp(1) = u%temp(1) - (r1*j22 - r2*j12)/det
    u%temp(2) = u%temp(2) - (j11*r2 - j21*r1)/det
  end do
  q = (th - u%temp(1))/ra
  call check_abs(q, (th - tc)/(ra + 1.0_dp/1300.0_dp + rb), 1.0e-10_dp*q, 'T1 flux, closed form')
  call check_abs(q, 1300.0_dp*(u%temp(1) - u%temp(2)), 1.0e-10_dp*q, 'T1 flux = k (T1 - T2)')
  call check(it == 2, 'one Newton iteration (then the converged check)')

  ! Frictional heat
  call init(0.8_dp)
  u%rdisp(1) = 50.0_dp/kn
  u%drdisp(2) = 0.05_dp
  u%temp = [60.0_dp, 40.0_dp]
  call call_uinter()
  qin = u%flux
  call check_abs(u%sfd, 0.4_dp*50.0_dp*(0.05_dp - 1.0e-3_dp), 1.0e-12_dp*u%sfd, 'SFD = mu p slip')
  call check_abs(qin(1) + qin(2), 0.8_dp*u%sfd/dt, 1.0e-12_dp*u%sfd/dt, 'heat balance')
  ! k(50) = 1000 + 600 (50 - 20)/40 = 1450.
  call check_abs(qin(1) - 1450.0_dp*(40.0_dp - 60.0_dp), 0.25_dp*0.8_dp*u%sfd/dt, &
                 1.0e-9_dp*u%sfd/dt, 'slave share f')

  call finish()

contains

  subroutine init(eta)
    real(dp), intent(in) :: eta
    ! mu = 0.4, gamma_crit = 1e-3, K_n, conductance from the file, eta, f = 0.25.
    u = new_uinter(2, [2.0_dp, 0.4_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0e-3_dp, &
                       0.0_dp, kn, 1.0_dp, eta, 0.25_dp], 'PTAB')
    u%dtime = dt
    u%node = 1
  end subroutine init

  subroutine call_uinter()
    call uinter_call(u)
    call check(u%pnewdt == big, 'PNEWDT not lowered')
    call check_uinter_tails(u)
  end subroutine call_uinter
end program test_uinter_heat
