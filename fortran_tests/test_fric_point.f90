! test_fric_point.f90 -- ifl_fric_point through the `interfacial` module (the Fortran side of
! c_tests/test_fric_point.c): a point slid over increments in 2-D and 3-D, once by FRIC as a
! host calls it and once by ifl_fric_point with type(ifl_fric_input) / type(ifl_fric_output),
! every output and STATEV equal; a refused PROPS gives the same PNEWDT and message. Checks that
! the module's bind(C) types have the header's layout.
program test_fric_point
  use, intrinsic :: iso_c_binding, only: c_char, c_double, c_int, c_loc, c_null_char
  use interfacial, only: ifl_fric_point, ifl_fric_input, ifl_fric_output, IFL_STATUS_OK, &
    IFL_STATUS_BAD_PARAMETER
  use harness_tally
  use harness_fric_host
  implicit none

  integer :: nfdir

  do nfdir = 1, 2
    call slide(nfdir, [1.0_dp, 0.3_dp, 0.0_dp, 0.0_dp, 1.0e-3_dp], 'plain')
    call slide(nfdir, [2.0_dp, 0.3_dp, 0.5_dp, 1.0_dp, 0.0_dp, 0.1_dp, 0.01_dp], 'adhesive')
  end do
  call refused()
  call finish()

contains

  subroutine slide(nfdir, props, what)
    integer, intent(in) :: nfdir
    real(dp), intent(in) :: props(:)
    character(len=*), intent(in) :: what
    type(fric_args), target :: p
    type(ifl_fric_input) :: in
    type(ifl_fric_output) :: out
    real(c_double), target :: props_c(20), statev_c(8)
    character(kind=c_char), target :: name(7)
    integer :: k, n, status
    real(dp) :: d(2)
    d = [0.6_dp, -0.8_dp]
    name = ['F', '_', 'P', 'O', 'I', 'N', c_null_char]
    p = new_point(nfdir, props, 'F_POINT')
    p%press = 10
    p%dpress = 10
    n = nfdir
    do k = 1, 6
      write (scene, '(a,a,i0,a,i0)') what, ', NFDIR ', nfdir, ', increment ', k
      p%dgam(1:n) = 2.0e-3_dp*d(1:n)
      ! The same point for ifl_fric_point, before FRIC moves it on.
      in = ifl_fric_input()
      in%nfdir = nfdir
      in%tau(1:n) = p%tau(1:n)
      in%dgam(1:n) = p%dgam(1:n)
      in%press = p%press
      in%dpress = p%dpress
      in%dtime = p%dtime
      in%chrlngth = p%chrlngth
      in%temp = p%temp
      in%noel = p%noel
      in%npt = p%npt
      in%node = p%node
      in%interaction = c_loc(name)
      props_c = 0
      props_c(1:size(props)) = props
      in%props = c_loc(props_c)
      in%nprops = size(props)
      statev_c = 0
      statev_c(1:3) = p%statev(1:3)
      in%statev = c_loc(statev_c)
      in%nstatv = 3
      status = ifl_fric_point(in, out)
      call fric_call(p)
      call check(status == IFL_STATUS_OK, 'status ok')
      call check(out%lm == p%lm, 'LM')
      call check(all(out%tau(1:n) == p%tau(1:n)), 'TAU')
      call check(all(out%ddtddg(1:n*n) == p%ddtddg(1:n*n)), 'DDTDDG')
      call check(all(out%ddtddp(1:n) == p%ddtddp(1:n)), 'DDTDDP')
      call check(all(out%dslip(1:n) == p%dslip(1:n)), 'DSLIP')
      call check(out%sed == p%sed .and. out%sfd == p%sfd, 'SED, SFD')
      call check(all(out%ddtddt(1:2*n) == p%ddtddt(1:2*n)), 'DDTDDT')
      call check(out%pnewdt == p%pnewdt, 'PNEWDT')
      call check(all(statev_c(1:3) == p%statev(1:3)), 'STATEV')
      p%dpress = 0
    end do
  end subroutine slide

  subroutine refused()
    type(ifl_fric_input) :: in
    type(ifl_fric_output) :: out
    real(c_double), target :: props_c(2), statev_c(3)
    type(fric_args) :: p
    character(len=2048) :: by_fric
    integer(c_int) :: status
    scene = 'a refused PROPS'
    props_c = [1.0_dp, -0.3_dp]
    statev_c = 0
    p = new_point(2, props_c, 'F_POINT')
    p%press = 10
    call fric_call(p)
    by_fric = last_error()
    in = ifl_fric_input()
    in%press = 10
    in%props = c_loc(props_c)
    in%nprops = 2
    in%statev = c_loc(statev_c)
    in%nstatv = 3
    in%node = 7
    in%npt = 1
    status = ifl_fric_point(in, out)
    call check(status == IFL_STATUS_BAD_PARAMETER, 'IFL_STATUS_BAD_PARAMETER')
    call check(out%pnewdt == p%pnewdt, 'PNEWDT cut back as FRIC''s')
    ! The same cause; FRIC's line names the interaction F_POINT, this one a blank name.
    call check_contains(last_error(), by_fric(index(by_fric, '): ') + 3:len_trim(by_fric)))
  end subroutine refused
end program test_fric_point
