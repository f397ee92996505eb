! test_message_hook.f90 -- the Fortran twin of c_tests/test_message_hook.c: a bind(C) procedure
! passed with c_funloc to ifl_set_message_handler (the `interfacial` module) receives every
! message instead of stderr or INTERFACIAL_LOG, with its length and the user pointer given (here
! c_loc of a counter); each is the calling thread's own last error; c_null_funptr sends
! messages back, and the handler hears nothing more.
module hook_record
  use, intrinsic :: iso_c_binding, only: c_char, c_f_pointer, c_int, c_ptr, c_size_t
  implicit none
  character(len=512) :: last = ''
  integer :: bad_len = 0
contains
  subroutine on_message(msg, msg_len, user) bind(C)
    type(c_ptr), value :: msg
    integer(c_size_t), value :: msg_len
    type(c_ptr), value :: user
    character(kind=c_char), pointer :: chars(:)
    integer(c_int), pointer :: counter
    integer :: i, n
    call c_f_pointer(user, counter)
    counter = counter + 1
    n = int(msg_len)
    call c_f_pointer(msg, chars, [n + 1])
    if (chars(n + 1) /= char(0)) bad_len = bad_len + 1
    last = ' '
    do i = 1, min(n, len(last))
      last(i:i) = chars(i)
    end do
  end subroutine on_message
end module hook_record

program test_message_hook
  use, intrinsic :: iso_c_binding, only: c_funloc, c_int, c_loc, c_null_funptr, c_null_ptr
  use interfacial, only: ifl_set_message_handler
  use harness_tally
  use harness_fric_host
  use hook_record
  implicit none

  integer(c_int), target :: counter = 0
  type(fric_args) :: p
  integer :: k
  character(len=2048) :: own

  scene = 'a bind(C) handler'
  call ifl_set_message_handler(c_funloc(on_message), c_loc(counter))
  do k = 1, 3
    p = new_point(2, [1.0_dp, -real(k, dp)], 'F_HOOK')
    p%press = 10
    call fric_call(p)
    own = last_error()
    call check_at(counter == k, 'one message per refused call', k)
    call check_at(trim(last) == trim(own), 'the message is the call''s own last error', k)
    call check_contains(last, 'F_HOOK')
  end do
  call check(bad_len == 0, 'len is the length before the NUL')

  scene = 'c_null_funptr: messages go back to stderr or the file'
  call ifl_set_message_handler(c_null_funptr, c_null_ptr)
  p = new_point(2, [1.0_dp, -9.0_dp], 'F_HOOK')
  p%press = 10
  call fric_call(p)
  call check(counter == 3, 'the handler hears nothing more')
  call check_contains(last_error(), 'μ = -9')
  call finish()
end program test_message_hook
