! test_pore_pressure.f90 -- the Fortran twin of c_tests/test_pore_pressure.c: steady seepage
! through two porous layers joined by the interface pore-pressure kernel (ifl_pore_pressure,
! seed 000), called step by step through its own bind(C) interface while the top pressure
! ramps up. Closed form: q = (p_top - p_base)/(L1/k1 + L2/k2), linear pressure per layer,
! p1 = p2 at the interface, flux across q_hat/2 = q.
program test_pore_pressure
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_null_char
  use harness_tally
  implicit none

  type, bind(c) :: ifl_pore_pressure_variant
    integer(c_int) :: open, steady, finite_sliding, per_side
  end type ifl_pore_pressure_variant

  interface
    ! IflStatus ifl_pore_pressure(const char *interaction, IflPorePressureVariant variant,
    !   double p1, double p2, double q_hat, double h, double dh, double dt,
    !   double residual[4], double tangent[16], double geometric[4]);
    function ifl_pore_pressure(interaction, variant, p1, p2, q_hat, h, dh, dt, residual, &
                               tangent, geometric) bind(c, name='ifl_pore_pressure') result(status)
      import :: c_int, c_double, c_char, ifl_pore_pressure_variant
      character(kind=c_char), dimension(*), intent(in) :: interaction
      type(ifl_pore_pressure_variant), value :: variant
      real(c_double), value :: p1, p2, q_hat, h, dh, dt
      real(c_double), intent(out) :: residual(4), tangent(4, 4), geometric(4)
      integer(c_int) :: status
    end function ifl_pore_pressure
  end interface

  integer, parameter :: ne = 4, np = 2*(ne + 1), n = np + 1, qhat = n
  real(dp), parameter :: l1 = 1.0_dp, l2 = 2.0_dp, k1 = 1.0e-3_dp, k2 = 1.0e-4_dp, p_base = 0.0_dp
  real(dp) :: x(n), r(n), k(n, n), p_top, q, p_i, worst, res(4), tng(4, 4), geo(4)
  integer :: step, layer, node, status
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

  scene = 'refused: transient with dt = 0'
  status = ifl_pore_pressure('seepage'//c_null_char, ifl_pore_pressure_variant(1, 0, 1, 0), &
                             130.0_dp, 70.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, res, tng, geo)
  call check(status == 2, 'status IFL_STATUS_BAD_INPUT (2)')
  call check_contains(last_error(), 'ifl_pore_pressure')
  call check_contains(last_error(), 'dt = 0')
  call check(all(res == 0.0_dp) .and. all(tng == 0.0_dp), 'outputs zeroed')

  write (*, '(i0,a,i0,a)') npass, ' passed, ', nfail, ' failed'
  if (nfail > 0 .or. npass == 0) stop 1

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
    status = ifl_pore_pressure('seepage'//c_null_char, ifl_pore_pressure_variant(0, 1, 0, 1), &
                               x(ne + 1), x(ne + 2), x(qhat), 0.0_dp, 0.0_dp, 0.0_dp, kr, kt, kg)
    ok = status == 0
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
