! test_fric_batch.f90 -- the batch entry ifl_fric_batch called from Fortran through
! ISO_C_BINDING, the Fortran twin of c_tests/test_fric_batch.c. The structure-of-arrays layout is
! a Fortran array X(LD, components): component a of point i is X(i, a), DDTDDG(a,c) of point i is
! DDTDDG(i, a + (c-1)*NFDIR).
!
! - On pseudo-random points (stick, slip, exact stick, LM = 0/1/2, NFDIR 1 and 2, three PROPS
!   variants, a padded leading dimension) every output equals what FRIC gives the same point
!   called once per point (== on every entry: the batch is bit-identical), and the padding
!   rows past NPOINTS are never written.
! - Closed forms at first contact: stick tau = (mu p/gc) dgam, DDTDDG = mu p/gc on the diagonal;
!   slip |tau| = mu p.
! - A point with a NaN DGAM and one with an infinite PRESS get FRIC's failure outputs (DDTDDG,
!   DDTDDP, DSLIP, SFD zero; LM, TAU, STATEV unchanged; the same as FRIC per point), the others
!   are still computed, the status is IFL_STATUS_BAD_INPUT, PNEWDT is lowered to 0.25 and the
!   message names ifl_fric_batch and the point (0-based, as C counts); NFDIR = 3 is refused as a
!   whole (IFL_STATUS_BAD_PARAMETER, nothing written but PNEWDT).
! The points come from the harnesses' MINSTD generator (harness_threads: uniform) with the C
! twin's seed and sizes, so both draw the same batches.
!
! Last line printed: "<n> passed, <m> failed"; ERROR STOP on a failure.

module batch_api
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t
  implicit none
  integer(c_int), parameter :: ifl_status_ok = 0, ifl_status_bad_parameter = 1, &
                               ifl_status_bad_input = 2
  interface
    ! include/interfacial.h: enum IflStatus ifl_fric_batch(size_t npoints, size_t ld, ...)
    function ifl_fric_batch(npoints, ld, nfdir, props, nprops, nstatv, dtime, lm, tau, &
                            ddtddg, ddtddp, dslip, sed, sfd, statev, dgam, taulm, press, &
                            dpress, chrlngth, pnewdt) result(status) bind(c, name='ifl_fric_batch')
      import :: c_int, c_double, c_size_t
      integer(c_size_t), value :: npoints, ld
      integer(c_int), value :: nfdir, nprops, nstatv
      real(c_double), value :: dtime
      real(c_double), intent(in) :: props(*), dgam(*), taulm(*), press(*), dpress(*), chrlngth(*)
      integer(c_int), intent(inout) :: lm(*)
      real(c_double), intent(inout) :: tau(*), statev(*), pnewdt
      real(c_double), intent(inout) :: ddtddg(*), ddtddp(*), dslip(*), sed(*), sfd(*)
      integer(c_int) :: status
    end function ifl_fric_batch
  end interface
end module batch_api

module batch_points
  use, intrinsic :: iso_fortran_env, only: int64
  use harness_tally, only: dp, finish, scene, check
  use harness_threads, only: lehmer_uniform => uniform
  use harness_fric_host, only: fric_args, new_point, fric_call, check_tails
  implicit none
  integer, parameter :: np = 500, ld = 512, nsv = 3
  real(dp), parameter :: unset = 12345.678_dp, big = 1.0e36_dp
  ! The generator's state: one stream from a fixed seed, the C twin's.
  integer(int64) :: rng_state = 20240601_int64

  ! One batch: every array LD rows, the rows past NP are padding.
  type :: batch
    integer :: lm(ld) = 0
    real(dp) :: tau(ld, 2) = unset, ddtddg(ld, 4) = unset, ddtddp(ld, 2) = unset
    real(dp) :: dslip(ld, 2) = unset, sed(ld) = unset, sfd(ld) = unset
    real(dp) :: statev(ld, nsv) = unset, dgam(ld, 2) = 0, taulm(ld, 2) = 0
    real(dp) :: press(ld) = 0, dpress(ld) = 0, chr(ld) = 1
  end type batch

contains

  ! A draw in [a, b) from the stream.
  real(dp) function uniform(a, b)
    real(dp), intent(in) :: a, b
    uniform = lehmer_uniform(rng_state, a, b)
  end function uniform

  subroutine random_batch(b, nfdir, gc)
    type(batch), intent(out) :: b
    integer, intent(in) :: nfdir
    real(dp), intent(in) :: gc
    integer :: i, a
    real(dp) :: r, scale
    do i = 1, np
      scale = gc*merge(0.4_dp, 4.0_dp, uniform(0.0_dp, 1.0_dp) < 0.5_dp)
      r = uniform(0.0_dp, 1.0_dp)
      b%lm(i) = merge(0, merge(1, 2, r < 0.9_dp), r < 0.7_dp)
      b%press(i) = uniform(-5.0_dp, 150.0_dp)
      b%dpress(i) = uniform(-20.0_dp, 20.0_dp)
      b%chr(i) = uniform(0.05_dp, 2.0_dp)
      do a = 1, nfdir
        b%tau(i, a) = uniform(-30.0_dp, 30.0_dp)
        b%dgam(i, a) = uniform(-1.0_dp, 1.0_dp)*scale
        b%taulm(i, a) = uniform(-60.0_dp, 60.0_dp)
      end do
      b%statev(i, 1) = uniform(0.0_dp, 1.0_dp)
      b%statev(i, 2) = uniform(0.0_dp, 1.0_dp)
      b%statev(i, 3) = real(int(uniform(0.0_dp, 2.999_dp)), dp)
    end do
  end subroutine random_batch

  ! The same points through FRIC, one call each (the host point of harness_fric_host.f90), the
  ! results stored back in the batch layout. The outputs go in as the batch holds them, so that a
  ! point FRIC does not write keeps them as the batch entry does. Returns the smallest PNEWDT
  ! FRIC asked for.
  function per_point(b, nfdir, props, dtime) result(pnewdt)
    type(batch), intent(inout) :: b
    integer, intent(in) :: nfdir
    real(dp), intent(in) :: props(:), dtime
    real(dp) :: pnewdt
    type(fric_args) :: a
    integer :: i, n, n2
    pnewdt = big
    n = nfdir
    n2 = nfdir*nfdir
    a = new_point(nfdir, props, 'SI1')
    a%dtime = dtime
    a%nstatv = nsv
    do i = 1, np
      a%lm = b%lm(i)
      a%sed = b%sed(i)
      a%sfd = b%sfd(i)
      a%tau(1:n) = b%tau(i, 1:n)
      a%dgam(1:n) = b%dgam(i, 1:n)
      a%taulm(1:n) = b%taulm(i, 1:n)
      a%ddtddp(1:n) = b%ddtddp(i, 1:n)
      a%dslip(1:n) = b%dslip(i, 1:n)
      a%ddtddg(1:n2) = b%ddtddg(i, 1:n2)
      a%statev(1:nsv) = b%statev(i, :)
      a%ddtddt(1:2*n) = 0
      a%press = b%press(i)
      a%dpress = b%dpress(i)
      a%chrlngth = b%chr(i)
      call fric_call(a, keep_outputs=.true.)
      call check_tails(a)
      pnewdt = min(pnewdt, a%pnewdt)
      b%lm(i) = a%lm
      b%sed(i) = a%sed
      b%sfd(i) = a%sfd
      b%tau(i, 1:n) = a%tau(1:n)
      b%ddtddp(i, 1:n) = a%ddtddp(1:n)
      b%dslip(i, 1:n) = a%dslip(1:n)
      b%ddtddg(i, 1:n2) = a%ddtddg(1:n2)
      b%statev(i, :) = a%statev(1:nsv)
    end do
  end function per_point

  function batch_call(b, nfdir, props, dtime, pnewdt) result(status)
    use batch_api
    type(batch), intent(inout) :: b
    integer, intent(in) :: nfdir
    real(dp), intent(in) :: props(:), dtime
    real(dp), intent(inout) :: pnewdt
    integer(c_int) :: status
    status = ifl_fric_batch(int(np, c_size_t), int(ld, c_size_t), int(nfdir, c_int), props, &
                            int(size(props), c_int), int(nsv, c_int), dtime, b%lm, b%tau, &
                            b%ddtddg, b%ddtddp, b%dslip, b%sed, b%sfd, b%statev, b%dgam, &
                            b%taulm, b%press, b%dpress, b%chr, pnewdt)
  end function batch_call

  ! Every array entry by entry, padding included.
  logical function same(x, y)
    type(batch), intent(in) :: x, y
    same = all(x%lm == y%lm) .and. all(x%tau == y%tau) .and. all(x%ddtddg == y%ddtddg) &
           .and. all(x%ddtddp == y%ddtddp) .and. all(x%dslip == y%dslip) &
           .and. all(x%sed == y%sed) .and. all(x%sfd == y%sfd) .and. all(x%statev == y%statev)
  end function same

  logical function padding_untouched(b)
    type(batch), intent(in) :: b
    padding_untouched = all(b%tau(np + 1:, :) == unset) .and. all(b%ddtddg(np + 1:, :) == unset) &
                        .and. all(b%ddtddp(np + 1:, :) == unset) &
                        .and. all(b%dslip(np + 1:, :) == unset) .and. all(b%sed(np + 1:) == unset) &
                        .and. all(b%sfd(np + 1:) == unset) .and. all(b%statev(np + 1:, :) == unset)
  end function padding_untouched

end module batch_points

program test_fric_batch
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use batch_api
  use batch_points
  use harness_tally, only: quiet_nan, last_error, check_contains, ifl_clear_error
  implicit none
  real(dp), parameter :: mu = 0.3_dp, gc = 1.0e-3_dp
  real(dp) :: variants(7, 3), pw, pb, ks
  type(batch) :: in, want, got
  integer :: v, nfdir, i
  integer(c_int) :: status

  variants(:, 1) = [1.0_dp, mu, 0.0_dp, 0.0_dp, gc, 0.0_dp, 0.0_dp]        ! elastic stick
  variants(:, 2) = [1.0_dp, mu, 0.0_dp, 0.0_dp, gc, 0.0_dp, 1.0_dp]        ! exact stick
  variants(:, 3) = [1.0_dp, 0.4_dp, 0.0_dp, 25.0_dp, 0.0_dp, 0.01_dp, 0.0_dp] ! tau_max, CHRLNGTH

  ! Bit for bit against FRIC per point.
  do v = 1, 3
    do nfdir = 1, 2
      write (scene, '(a,i0,a,i0)') 'PROPS variant ', v, ', NFDIR = ', nfdir
      call random_batch(in, nfdir, 2.0e-3_dp)
      want = in
      got = in
      pb = big
      pw = per_point(want, nfdir, variants(:, v), 0.1_dp)
      status = batch_call(got, nfdir, variants(:, v), 0.1_dp, pb)
      call check(status == ifl_status_ok, 'status OK')
      call check(pw == big .and. pb == big, 'PNEWDT untouched')
      call check(same(want, got), 'every output equals FRIC per point')
      call check(padding_untouched(got), 'padding rows never written')
    end do
  end do

  ! Closed forms at first contact (tau = 0, STATEV = 0), NFDIR = 2, p = 100, mu p = 30.
  scene = 'closed forms'
  call random_batch(got, 2, gc)
  got%lm = 0
  got%tau = 0
  got%statev = 0
  got%press = 100
  got%dpress = 0
  ks = mu*100/gc
  do i = 1, np
    ! Odd points stick (|dgam| = 0.5 gc), even points slip (|dgam| = 3 gc).
    got%dgam(i, 1) = merge(0.3_dp, 1.8_dp, mod(i, 2) == 1)*gc
    got%dgam(i, 2) = merge(-0.4_dp, 2.4_dp, mod(i, 2) == 1)*gc
  end do
  pb = big
  status = batch_call(got, 2, variants(:, 1), 0.1_dp, pb)
  call check(status == ifl_status_ok, 'status OK')
  do i = 1, np, 2
    call check(abs(got%tau(i, 1) - ks*got%dgam(i, 1)) <= 1.0e-12_dp*30 .and. &
               abs(got%tau(i, 2) - ks*got%dgam(i, 2)) <= 1.0e-12_dp*30, 'stick: tau = k_s dgam')
    call check(abs(got%ddtddg(i, 1) - ks) <= 1.0e-12_dp*ks .and. got%ddtddg(i, 2) == 0 &
               .and. got%ddtddg(i, 3) == 0 .and. abs(got%ddtddg(i, 4) - ks) <= 1.0e-12_dp*ks, &
               'stick: DDTDDG = k_s I')
  end do
  do i = 2, np, 2
    call check(abs(hypot(got%tau(i, 1), got%tau(i, 2)) - mu*100) <= 1.0e-12_dp*30, &
               'slip: |tau| = mu p')
    call check(abs(got%tau(i, 1)*got%dgam(i, 2) - got%tau(i, 2)*got%dgam(i, 1)) &
               <= 1.0e-12_dp*30*gc, 'slip: tau along dgam')
    ! From tau = 0 the first gc of |dgam| = 3 gc is elastic: SFD = mu p (3 gc - gc).
    call check(abs(got%sfd(i) - mu*100*2*gc) <= 1.0e-12_dp*mu*100*2*gc, 'slip: SFD = mu p 2 gc')
  end do

  ! Bad input at two points (C's points 3 and 99, 0-based): FRIC's failure outputs there, the
  ! others computed.
  scene = 'NaN DGAM at point 4, infinite PRESS at point 100'
  call random_batch(in, 2, gc)
  in%lm(4) = 0
  in%dgam(4, 1) = quiet_nan()
  in%lm(100) = 0
  in%press(100) = ieee_value(1.0_dp, ieee_positive_inf)
  want = in
  got = in
  pw = per_point(want, 2, variants(:, 1), 0.1_dp)
  pb = big
  call ifl_clear_error()
  status = batch_call(got, 2, variants(:, 1), 0.1_dp, pb)
  call check(status == ifl_status_bad_input, 'status BAD_INPUT')
  call check(pw == 0.25_dp, 'FRIC per point: PNEWDT lowered to 0.25')
  call check(pb == 0.25_dp, 'PNEWDT lowered to 0.25')
  call check(same(want, got), 'every output equals FRIC per point, the failed points too')
  do i = 4, 100, 96
    call check(all(got%ddtddg(i, :) == 0) .and. all(got%ddtddp(i, 1:2) == 0) &
               .and. all(got%dslip(i, 1:2) == 0) .and. got%sfd(i) == 0, &
               'failed point: tangents, DSLIP, SFD zero')
    call check(all(got%tau(i, :) == in%tau(i, :)) .and. all(got%statev(i, :) == in%statev(i, :)) &
               .and. got%lm(i) == in%lm(i), 'failed point: TAU, STATEV, LM unchanged')
  end do
  call check_contains(last_error(), 'ifl_fric_batch')
  call check_contains(last_error(), 'batch point 99')

  ! A fault of the whole batch: nothing written but PNEWDT.
  scene = 'NFDIR = 3'
  call random_batch(in, 2, 2.0e-3_dp)
  got = in
  pb = big
  status = batch_call(got, 3, variants(:, 1), 0.1_dp, pb)
  call check(status == ifl_status_bad_parameter, 'status BAD_PARAMETER')
  call check(pb == 0.25_dp, 'PNEWDT lowered to 0.25')
  call check(same(in, got), 'nothing written')

  call finish()

end program test_fric_batch
