! test_props_query.f90 -- the Fortran twin of c_tests/test_props_query.c: law 1's PROPS rows
! listed through the `interfacial` module (ifl_props_entry_c, ifl_c_string), every index 1..20
! once, PROPS(14..16) twice (steady transport) and PROPS(5) twice (the constant stick stiffness of
! PROPS(7) = 4), and one good and one bad PROPS checked without
! an increment (ifl_props_check_text): the bad one's message is the cause FRIC reports.
program test_props_query
  use interfacial, only: ifl_props_entry, ifl_props_entry_c, ifl_props_entry_count, &
    ifl_props_law_count, ifl_props_law_code, ifl_props_check_text, ifl_c_string, &
    IFL_STATUS_OK, IFL_STATUS_BAD_PARAMETER
  use harness_tally
  use harness_fric_host
  implicit none

  type(ifl_props_entry) :: e
  integer :: i, n, seen(20), status
  real(dp) :: good(20), bad(20)
  character(len=:), allocatable :: msg
  character(len=2048) :: fric_msg
  type(fric_args) :: p

  scene = 'law 1''s rows'
  call check(ifl_props_law_count() == 3, 'three laws')
  call check(ifl_props_law_code(0) == 1 .and. ifl_props_law_code(1) == 2 .and. &
             ifl_props_law_code(2) == 3, 'codes 1, 2 and 3')
  n = ifl_props_entry_count(1)
  seen = 0
  do i = 0, n - 1
    status = ifl_props_entry_c(1, i, e)
    call check(status == IFL_STATUS_OK, 'ifl_props_entry')
    write (*, '(a,i0,a,a,a,a,a,a)') 'PROPS(', e%index, ') ', ifl_c_string(e%key), ' [', &
      ifl_c_string(e%unit), '] default ', ifl_c_string(e%default_text)
    if (e%index >= 1 .and. e%index <= 20) seen(e%index) = seen(e%index) + 1
    if (e%index == 6) call check(e%default_value == 0.005_dp, 'slip tolerance default 0.005')
    if (e%index == 2) call check(e%required == 1, 'mu required')
  end do
  do i = 1, 20
    if (i == 5 .or. (i >= 14 .and. i <= 16)) then
      call check_at(seen(i) == 2, 'listed twice', i)
    else
      call check_at(seen(i) == 1, 'listed once', i)
    end if
  end do

  scene = 'a good and a bad PROPS'
  good = 0
  good(1) = 1
  good(2) = 0.3_dp
  bad = good
  bad(2) = -0.3_dp
  status = ifl_props_check_text(good, 5, 'SI_PAD', msg)
  call check(status == IFL_STATUS_OK .and. len(msg) == 0, 'good PROPS: ok, no message')
  status = ifl_props_check_text(bad, 5, 'SI_PAD', msg)
  call check(status == IFL_STATUS_BAD_PARAMETER, 'bad PROPS: IFL_STATUS_BAD_PARAMETER')
  call check_contains(msg, 'PROPS(2)')
  ! FRIC with the same PROPS: its line ends with the check's message.
  p = new_point(2, bad(1:5), 'SI_PAD')
  p%press = 10
  call ifl_clear_error()
  call fric_call(p)
  fric_msg = last_error()
  call check_contains(fric_msg, 'FRIC')
  call check(index(fric_msg, '): '//msg) > 0 .and. &
    len_trim(fric_msg) == index(fric_msg, '): '//msg) + 2 + len(msg), &
    'FRIC''s message ends with the check''s')
  ! A main program's allocatable is not freed at its end (valgrind would call it lost).
  deallocate (msg)
  call finish()
end program test_props_query
