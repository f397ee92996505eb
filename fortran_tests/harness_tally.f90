! harness_tally.f90 -- the pass/fail tally shared by the free-form Fortran harnesses that use it
! (the Fortran side of c_tests/harness.h): finish (the last line), check, check_near (|got - want| <= rtol |want| + atol),
! check_abs (|got - want| <= tol), check_at / check_abs_at (the same for a numbered step),
! the calling thread's last library message (ifl_last_error_copy), check_contains and a quiet
! NaN made at run time (quiet_nan). The
! current scene's name goes in `scene`; the first 40 failures are printed with it.
! Also the native C functions the harnesses call besides the Abaqus entries, as declared in
! include/interfacial.h: ifl_last_error_copy, ifl_clear_error, ifl_gap_conductance (names the
! library's own module `interfacial` also has: a harness that uses both takes them with only:).
module harness_tally
  use, intrinsic :: iso_c_binding, only: c_char, c_double, c_int, c_size_t
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  implicit none
  integer, parameter :: dp = kind(1.0d0)
  integer :: npass = 0, nfail = 0
  character(len=96) :: scene = ''

  type, bind(c) :: ifl_conductance
    real(c_double) :: k, dk_dd, dk_dp, dk_dtheta_mean, dq_dtheta_a, dq_dtheta_b
  end type ifl_conductance

  interface
    function ifl_gap_conductance(interaction, d, p, theta_a, theta_b, out) &
      bind(c, name='ifl_gap_conductance') result(status)
      import :: c_char, c_double, c_int, ifl_conductance
      character(kind=c_char), dimension(*), intent(in) :: interaction
      real(c_double), value :: d, p, theta_a, theta_b
      type(ifl_conductance), intent(out) :: out
      integer(c_int) :: status
    end function ifl_gap_conductance
    function ifl_last_error_copy(buf, len) bind(c, name='ifl_last_error_copy') result(n)
      import :: c_char, c_size_t
      character(kind=c_char), dimension(*), intent(out) :: buf
      integer(c_size_t), value :: len
      integer(c_size_t) :: n
    end function ifl_last_error_copy
    subroutine ifl_clear_error() bind(c, name='ifl_clear_error')
    end subroutine ifl_clear_error
  end interface

contains

  ! The harness's last line, "<n> passed, <m> failed", and ERROR STOP on a failure or when
  ! nothing was checked.
  subroutine finish()
    write (*, '(i0,a,i0,a)') npass, ' passed, ', nfail, ' failed'
    if (nfail > 0 .or. npass == 0) error stop 1
  end subroutine finish

  ! One check counted; a failure (the first 40 only) is printed with the scene and, when given,
  ! a line of numbers: "   <label>: v(1) v(2) ...".
  subroutine check(ok, what, label, values)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    character(len=*), intent(in), optional :: label
    real(dp), intent(in), optional :: values(:)
    if (ok) then
      npass = npass + 1
      return
    end if
    nfail = nfail + 1
    if (nfail > 40) return
    write (*, '(a,a,a,a)') 'FAIL [', trim(scene), '] ', what
    if (present(label) .and. present(values)) write (*, '(a,a,a,1p,3e25.16)') '   ', label, ':', &
      values
  end subroutine check

  ! |got - want| <= rtol |want| + atol.
  subroutine check_near(got, want, rtol, atol, what)
    real(dp), intent(in) :: got, want, rtol, atol
    character(len=*), intent(in) :: what
    call check(abs(got - want) <= rtol*abs(want) + atol, what, 'got, expected', [got, want])
  end subroutine check_near

  ! |got - want| <= tol (an absolute tolerance).
  subroutine check_abs(got, want, tol, what)
    real(dp), intent(in) :: got, want, tol
    character(len=*), intent(in) :: what
    call check(abs(got - want) <= tol, what, 'got, expected, tol', [got, want, tol])
  end subroutine check_abs

  ! check and check_abs for a numbered step (an increment, a point): a failure prints K too.
  subroutine check_at(ok, what, k)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    integer, intent(in) :: k
    character(len=24) :: at
    write (at, '(a,i0,a)') ' (at ', k, ')'
    call check(ok, what//trim(at))
  end subroutine check_at

  subroutine check_abs_at(got, want, tol, what, k)
    real(dp), intent(in) :: got, want, tol
    character(len=*), intent(in) :: what
    integer, intent(in) :: k
    character(len=24) :: at
    write (at, '(a,i0,a)') ' (at ', k, ')'
    call check(abs(got - want) <= tol, what//trim(at), 'got, expected, tol', [got, want, tol])
  end subroutine check_abs_at

  ! The calling thread's last message (ifl_last_error_copy), '' when there is none. RECURSIVE:
  ! the OpenMP harnesses call it from their threads (its buffer lives on each thread's stack).
  recursive function last_error() result(msg)
    character(len=2048) :: msg
    character(kind=c_char) :: buf(2048)
    integer(c_size_t) :: n
    integer :: i
    buf = ' '
    n = ifl_last_error_copy(buf, int(size(buf), c_size_t))
    msg = ' '
    do i = 1, int(min(n, int(size(buf) - 1, c_size_t)))
      msg(i:i) = buf(i)
    end do
  end function last_error

  ! A quiet NaN made at run time (a host's bad input). RECURSIVE like last_error.
  recursive real(dp) function quiet_nan()
    quiet_nan = ieee_value(1.0_dp, ieee_quiet_nan)
  end function quiet_nan

  subroutine check_contains(msg, needle)
    character(len=*), intent(in) :: msg, needle
    call check(index(msg, needle) > 0, 'message contains "'//needle//'"')
    if (index(msg, needle) == 0 .and. nfail <= 40) write (*, '(a,a)') '   message: ', trim(msg)
  end subroutine check_contains
end module harness_tally
