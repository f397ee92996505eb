! test_pore_pressure.f90 -- the Fortran twin of c_tests/test_pore_pressure.c: steady seepage
! through two porous layers joined by the interface pore-pressure kernel (seed 000), called step
! by step through the `interfacial` module (ifl_pore_pressure with a character(*) name, which
! calls ifl_pore_pressure_n: no NUL) while the top pressure ramps up. Closed form:
! q = (p_top - p_base)/(L1/k1 + L2/k2), linear pressure per layer, p1 = p2 at the interface,
! flux across q_hat/2 = q.
program test_pore_pressure
  use, intrinsic :: iso_c_binding, only: c_null_char
  use interfacial, only: ifl_pore_pressure, ifl_pore_pressure_c, ifl_pore_pressure_variant, &
    ifl_last_error_message, IFL_STATUS_OK, IFL_STATUS_BAD_INPUT
  use harness_tally
  implicit none

  integer, parameter :: ne = 4, np = 2*(ne + 1), n = np + 1, qhat = n
  real(dp), parameter :: l1 = 1.0_dp, l2 = 2.0_dp, k1 = 1.0e-3_dp, k2 = 1.0e-4_dp, p_base = 0.0_dp
  real(dp) :: x(n), r(n), k(n, n), p_top, q, p_i, worst, res(4), tng(4, 4), geo(4)
  integer :: step, layer, node, status
  ! A blank-padded name as an Abaqus-style host keeps it: no NUL anywhere.
  character(len=80) :: ciname = 'seepage'
  logical :: ok

  x = 0.0_dp
  do step = 1, 5
    p_top = 20.0_dp*step
    write (scene, '(a,i0)') 'steady seepage, step ', step
    call assemble(x, p_top, r, k, ok)
    if (.not. ok) exit
    call solve(k, r, ok)
    call check(ok, 'non-singular host matrix')
    if (.not. ok) exit
    x = x - r
    q = (p_top - p_base)/(l1/k1 + l2/k2)
    p_i = p_top - q*l1/k1
    call check_near(0.5_dp*x(qhat), q, 1.0e-12_dp, 0.0_dp, 'flux q_hat/2')
    call check_near(x(ne + 1), p_i, 1.0e-12_dp, 1.0e-12_dp*p_top, 'p1 at the interface')
    call check_near(x(ne + 2), p_i, 1.0e-12_dp, 1.0e-12_dp*p_top, 'p2 at the interface')
    do layer = 0, 1
      do node = 0, ne
        if (layer == 0) then
          call check_near(x(node + 1), p_top - q*node*(l1/ne)/k1, 0.0_dp, 1.0e-12_dp*p_top, &
                          'linear pressure, layer 1')
        else
          call check_near(x(ne + 2 + node), p_i - q*node*(l2/ne)/k2, 0.0_dp, &
                          1.0e-12_dp*p_top, 'linear pressure, layer 2')
        end if
      end do
    end do
    call assemble(x, p_top, r, k, ok)
    worst = maxval(abs(r))
    call check_near(worst, 0.0_dp, 0.0_dp, 1.0e-14_dp*p_top, 'residual after one Newton step')
  end do

  scene = 'refused: transient with dt = 0 (character(*) name)'
  status = ifl_pore_pressure(ciname, ifl_pore_pressure_variant(1, 0, 1, 0), &
                             130.0_dp, 70.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, res, tng, geo)
  call check(status == IFL_STATUS_BAD_INPUT, 'status IFL_STATUS_BAD_INPUT')
  call check_contains(ifl_last_error_message(), 'ifl_pore_pressure_n')
  ! The name without its 73 trailing blanks, closed by the quote.
  call check_contains(ifl_last_error_message(), "interaction 'seepage'")
  call check_contains(ifl_last_error_message(), 'dt = 0')
  call check(all(res == 0.0_dp) .and. all(tng == 0.0_dp) .and. all(geo == 0.0_dp), &
             'outputs zeroed')

  scene = 'refused: transient with dt = 0 (NUL-terminated name, the C function)'
  status = ifl_pore_pressure_c('seepage'//c_null_char, ifl_pore_pressure_variant(open=1), &
                               130.0_dp, 70.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, res, tng, geo)
  call check(status == IFL_STATUS_BAD_INPUT, 'status IFL_STATUS_BAD_INPUT')
  call check_contains(ifl_last_error_message(), "ifl_pore_pressure: interaction 'seepage'")

  scene = 'closed, transient, small sliding (the default variant): seed 000 coefficients'
  ! p_mean = 100, p_jump = 30: residual -(p_mean, 0, dt*q_hat, dt*p_jump).
  status = ifl_pore_pressure(ciname, ifl_pore_pressure_variant(), 130.0_dp, 70.0_dp, 0.5_dp, &
                             0.0_dp, 0.0_dp, 0.25_dp, res, tng, geo)
  call check(status == IFL_STATUS_OK, 'status IFL_STATUS_OK')
  call check(all(res == [-100.0_dp, 0.0_dp, -0.125_dp, -7.5_dp]), 'residual -(p_mean, 0, dt q, dt p_jump)')
  call check(tng(1, 2) == -1.0_dp .and. tng(3, 4) == -0.25_dp .and. tng(4, 3) == -0.25_dp, &
             'tangent entries -1, -dt, -dt')
  call check(count(tng /= 0.0_dp) == 3, 'no other tangent entry')
  call check(all(geo == 0.0_dp), 'small sliding: no geometric terms')

  call finish()

contains

  ! Residual and tangent of the steady host (pressure unknowns, then q_hat); p_top held at node 1.
  subroutine assemble(x, p_top, r, k, ok)
    real(dp), intent(in) :: x(n), p_top
    real(dp), intent(out) :: r(n), k(n, n)
    logical, intent(out) :: ok
    integer :: lay, e, a, b, i, j, dof(4)
    real(dp) :: c, f, kr(4), kt(4, 4), kg(4)
    r = 0.0_dp
    k = 0.0_dp
    do lay = 0, 1
      do e = 0, ne - 1
        a = lay*(ne + 1) + e + 1
        b = a + 1
        if (lay == 0) then
          c = k1/(l1/ne)
        else
          c = k2/(l2/ne)
        end if
        f = -c*(x(a) - x(b))
        r(a) = r(a) + f
        r(b) = r(b) - f
        k(a, a) = k(a, a) - c
        k(a, b) = k(a, b) + c
        k(b, a) = k(b, a) + c
        k(b, b) = k(b, b) - c
      end do
    end do
    ! Steady, closed, small sliding, per-side unknowns (h, p1, p2, q_hat).
    status = ifl_pore_pressure(ciname, ifl_pore_pressure_variant(steady=1, per_side=1), &
                               x(ne + 1), x(ne + 2), x(qhat), 0.0_dp, 0.0_dp, 0.0_dp, kr, kt, kg)
    ok = status == IFL_STATUS_OK
    call check(ok, 'kernel status IFL_STATUS_OK')
    if (.not. ok) return
    call check(all(kg == 0.0_dp), 'small sliding: no geometric terms')
    dof = [0, ne + 1, ne + 2, qhat]
    do i = 2, 4
      r(dof(i)) = r(dof(i)) + kr(i)
      do j = 2, 4
        k(dof(i), dof(j)) = k(dof(i), dof(j)) + kt(i, j)
      end do
    end do
    k(1, :) = 0.0_dp
    k(1, 1) = 1.0_dp
    r(1) = x(1) - p_top
    k(np, :) = 0.0_dp
    k(np, np) = 1.0_dp
    r(np) = x(np) - p_base
  end subroutine assemble

  ! Gaussian elimination with partial pivoting; b is replaced by the solution.
  subroutine solve(a, b, ok)
    real(dp), intent(inout) :: a(n, n), b(n)
    logical, intent(out) :: ok
    integer :: kk, p, i
    real(dp) :: row(n), t, l
    ok = .false.
    do kk = 1, n
      p = kk - 1 + maxloc(abs(a(kk:n, kk)), 1)
      if (a(p, kk) == 0.0_dp) return
      row = a(kk, :)
      a(kk, :) = a(p, :)
      a(p, :) = row
      t = b(kk)
      b(kk) = b(p)
      b(p) = t
      do i = kk + 1, n
        l = a(i, kk)/a(kk, kk)
        a(i, kk:n) = a(i, kk:n) - l*a(kk, kk:n)
        b(i) = b(i) - l*b(kk)
      end do
    end do
    do kk = n, 1, -1
      b(kk) = (b(kk) - dot_product(a(kk, kk + 1:n), b(kk + 1:n)))/a(kk, kk)
    end do
    ok = .true.
  end subroutine solve
end program test_pore_pressure
