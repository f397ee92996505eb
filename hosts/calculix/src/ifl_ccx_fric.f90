! interfacial's CalculiX host: *FRICTION, USER served by the library's FRIC (fric_).
!
! Our code, under the library's licence. CalculiX calls these routines from the lines that
! hosts/calculix/edit.sh inserts into its files (hosts/calculix/edits/); see docs/calculix.md.
!
! Storage in CalculiX's arrays, for an interaction with *FRICTION, USER:
!   elcon(6)  = 1   friction on (CalculiX's friction branches and its unsymmetric solver)
!   elcon(7)  = 1   stick slope, unused by the user law
!   elcon(12) = NPROPS, elcon(13) = DEPVAR, elcon(14 .. 13+NPROPS) = PROPS
! Per contact point, xstate(1..nstate_) (start of the increment in xstateini):
!   1-3   accumulated inelastic slip, global x, y, z (the sum of FRIC's DSLIP)
!   4-9   CalculiX's own: relative displacement, accumulated tangential relative displacement
!   10-12 friction stress TAU at the end of the increment as a global vector
!   13    contact pressure at the end of the increment
!   14 .. 13+DEPVAR  the law's STATEV
! so nstate_ >= 13 + DEPVAR.

!> Input phase (allocation.f): PROPERTIES=n of a *FRICTION line needs elcon(0:13+n).
subroutine ifl_ccx_allocfric(textpart, n, ncmat_)
  implicit none
  character(len=132), intent(in) :: textpart(16)
  integer, intent(in) :: n
  integer, intent(inout) :: ncmat_
  integer :: i, np, ios
  do i = 2, min(n, 16)
    if (textpart(i)(1:11) == 'PROPERTIES=') then
      read (textpart(i)(12:31), '(i20)', iostat=ios) np
      if (ios == 0 .and. np > 0) ncmat_ = max(ncmat_, 13 + np)
    end if
  end do
end subroutine ifl_ccx_allocfric

!> Input phase (calinput.f, before *FRICTION): the name of the current *SURFACE INTERACTION.
subroutine ifl_ccx_name(name)
  implicit none
  character(len=80), intent(in) :: name
  character(len=80) :: cname
  common /iflnam/ cname
  cname = name
end subroutine ifl_ccx_name

!> Input phase (frictions.f): reads the parameters of *FRICTION. Without USER nothing is
!> done (iuser = 0) and CalculiX reads its own law. With USER: PROPERTIES=n (required),
!> DEPVAR=m (default 0) and n PROPS values, 8 per line; the PROPS are checked by one call of
!> fric_ at a closed point at rest, and the library's refusal stops the input.
subroutine ifl_ccx_friction(inpc, textpart, elcon, ncmat_, ntmat_, imat, nstate_, istat, n, &
                            iline, ipol, inl, ipoinp, inp, ipoinpc, ier, iuser)
  implicit none
  character(len=1), intent(in) :: inpc(*)
  character(len=132), intent(inout) :: textpart(16)
  integer, intent(in) :: ncmat_, ntmat_, imat
  integer, intent(inout) :: nstate_, istat, n, iline, ipol, inl, ier, iuser
  integer :: ipoinp(2, *), inp(3, *), ipoinpc(0:*)
  real(8), intent(inout) :: elcon(0:ncmat_, ntmat_, *)
  character(len=80) :: cname
  common /iflnam/ cname
  logical :: user, bad
  integer :: i, k, key, np, nd, ios
  real(8) :: val
  character(len=512) :: msg

  iuser = 0
  user = .false.
  bad = .false.
  np = -1
  nd = 0
  do i = 2, min(n, 16)
    if (textpart(i) == 'USER') then
      user = .true.
    else if (textpart(i)(1:11) == 'PROPERTIES=') then
      call read_count(textpart(i)(12:31), 'PROPERTIES=', np)
    else if (textpart(i)(1:7) == 'DEPVAR=') then
      call read_count(textpart(i)(8:27), 'DEPVAR=', nd)
    else if (user) then
      call refuse(': unknown parameter '//trim(textpart(i)))
    end if
  end do
  if (.not. user) then
    if (np /= -1 .or. nd /= 0) then
      write (*, *) '*ERROR reading *FRICTION of interaction ', trim(cname), &
        ': PROPERTIES= and DEPVAR= need the parameter USER'
      ier = 1
    end if
    return
  end if
  iuser = 1
  if (np == -1) then
    call refuse(': PROPERTIES=n is required')
  else if (np < 1) then
    call refuse(': PROPERTIES must be at least 1')
  else if (13 + np > ncmat_) then
    write (*, *) '*ERROR reading *FRICTION, USER of interaction ', trim(cname), &
      ': no room for PROPERTIES=', np
    bad = .true.
  end if
  if (nd < 0) call refuse(': DEPVAR must be 0 or more')
  ! The data lines: up to 8 values each, until the next keyword.
  k = 0
  do
    call getnewline(inpc, textpart, istat, n, key, iline, ipol, inl, ipoinp, inp, ipoinpc)
    if ((istat < 0) .or. (key == 1)) exit
    do i = 1, min(n, 8)
      read (textpart(i)(1:20), '(f20.0)', iostat=ios) val
      if (ios /= 0) then
        call refuse(': PROPS value is not a number: '//trim(textpart(i)))
        cycle
      end if
      k = k + 1
      if (.not. bad .and. k <= np) elcon(13 + k, 1, imat) = val
    end do
  end do
  if (.not. bad .and. k /= np) then
    write (*, '(a,i0,a,i0,a)') ' *ERROR reading *FRICTION, USER of interaction '// &
      trim(cname)//': PROPERTIES=', np, ' but ', k, ' values given'
    bad = .true.
  end if
  if (bad) then
    ier = 1
    return
  end if
  elcon(0, 1, imat) = 0.d0
  elcon(6, 1, imat) = 1.d0
  elcon(7, 1, imat) = 1.d0
  elcon(12, 1, imat) = dble(np)
  elcon(13, 1, imat) = dble(nd)
  nstate_ = max(nstate_, 13 + nd)
  call ifl_ccx_check(elcon(14, 1, imat), np, nd, cname, msg)
  if (len_trim(msg) > 0) then
    write (*, *) '*ERROR reading *FRICTION, USER of interaction ', trim(cname), &
      ': the library refused it:'
    write (*, *) '       ', trim(msg)
    ier = 1
  end if

contains

  !> One refusal of the *FRICTION line: the message (after the interaction's name), and bad set.
  subroutine refuse(what)
    character(len=*), intent(in) :: what
    write (*, *) '*ERROR reading *FRICTION, USER of interaction ', trim(cname), what
    bad = .true.
  end subroutine refuse

  !> The integer n of KEY=n (text: what follows the '='); refused when it is not one. Read
  !> before USER is known, so the message names *FRICTION alone.
  subroutine read_count(text, key, count)
    character(len=*), intent(in) :: text, key
    integer, intent(inout) :: count
    integer :: ios
    read (text, '(i20)', iostat=ios) count
    if (ios /= 0) then
      write (*, *) '*ERROR reading *FRICTION of interaction ', trim(cname), ': ', key, &
        ' is not an integer'
      bad = .true.
    end if
  end subroutine read_count
end subroutine ifl_ccx_friction

!> One call of fric_ at a closed point at rest (p = 1, no motion, STATEV zero); msg is the
!> library's message when it refused the call, blank otherwise.
subroutine ifl_ccx_check(props, np, nd, cname, msg)
  use, intrinsic :: iso_c_binding, only: c_char, c_size_t
  implicit none
  integer, intent(in) :: np, nd
  real(8), intent(in) :: props(np)
  character(len=80), intent(in) :: cname
  character(len=512), intent(out) :: msg
  interface
    subroutine ifl_clear_error() bind(c, name='ifl_clear_error')
    end subroutine ifl_clear_error
    function ifl_last_error_copy(buf, length) bind(c, name='ifl_last_error_copy')
      import :: c_char, c_size_t
      character(kind=c_char), intent(out) :: buf(*)
      integer(c_size_t), value :: length
      integer(c_size_t) :: ifl_last_error_copy
    end function ifl_last_error_copy
  end interface
  real(8), allocatable :: statev(:)
  real(8) :: tau(2), ddtddg(2, 2), ddtddp(2), dslip(2), sed, sfd, ddtddt(2, 2), pnewdt
  real(8) :: dgam(2), taulm(2), slip(2), time(2), coords(3), rcoord(3), drot(2, 2)
  real(8) :: temp(2), predef(2, 1)
  integer :: lm, i
  character(kind=c_char) :: buf(512)
  integer(c_size_t) :: length
  character(len=80) :: blank

  allocate (statev(max(nd, 1)))
  statev = 0.d0
  tau = 0.d0
  dgam = 0.d0
  taulm = 0.d0
  slip = 0.d0
  time = 0.d0
  temp = 0.d0
  call ifl_ccx_unread(coords, rcoord, drot, predef, pnewdt, lm, blank)
  call ifl_clear_error()
  call fric(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, taulm, &
            1.d0, 0.d0, 1.d0, slip, 1, 1, time, 1.d0, 0, cname, blank, blank, 1, 0, 0, &
            coords, rcoord, drot, temp, predef, 2, 3, 1, nd, 1.d0, props, np)
  msg = ' '
  buf = ' '
  length = ifl_last_error_copy(buf, int(size(buf), c_size_t))
  do i = 1, int(min(length, int(len(msg), c_size_t)))
    msg(i:i) = buf(i)
  end do
  if (length == 0 .and. pnewdt < 1.d0) msg = 'FRIC asked for a smaller increment at rest'
  deallocate (statev)
end subroutine ifl_ccx_check

!> FRIC's arguments that CalculiX gives no value for, as both calls of fric pass them: no
!> coordinates, DROT the identity (TAU is already in the point's own basis), no predefined
!> fields, PNEWDT = 1, LM = 0 (no exact stick), blank surface names.
subroutine ifl_ccx_unread(coords, rcoord, drot, predef, pnewdt, lm, blank)
  implicit none
  real(8), intent(out) :: coords(3), rcoord(3), drot(2, 2), predef(2, 1), pnewdt
  integer, intent(out) :: lm
  character(len=80), intent(out) :: blank
  coords = 0.d0
  rcoord = 0.d0
  drot = 0.d0
  drot(1, 1) = 1.d0
  drot(2, 2) = 1.d0
  predef = 0.d0
  pnewdt = 1.d0
  lm = 0
  blank = ' '
end subroutine ifl_ccx_unread

!> What FRIC needs and CalculiX's contact spring routines are not given (step, increment,
!> times, the element, node and interaction, the temperatures), set by ifl_ccx_ctx before them,
!> and the smallest PNEWDT since ifl_ccx_pnewdt last passed it on. Kept per thread (CalculiX
!> runs elements in threads).
module ifl_ccx_context
  implicit none
  real(8) :: ctime(2), cdtime, ctemp(2), cpnewdt
  integer :: cstep, cinc, cnoel, cnode
  character(len=80) :: ciname
  !$omp threadprivate(ctime, cdtime, ctemp, cpnewdt, cstep, cinc, cnoel, cnode, ciname)
end module ifl_ccx_context

!> Before CalculiX's contact spring routines (resultsmech.f, e_c3d.f): what FRIC needs and
!> those routines are not given. Kept per thread (CalculiX runs elements in threads).
subroutine ifl_ccx_ctx(istep, iinc, time, ttime, dtime, name, nelem, ithermal, t1, vold, mi, &
                       konl, nope)
  use ifl_ccx_context, only: ctime, cdtime, ctemp, cpnewdt, cstep, cinc, cnoel, cnode, ciname
  implicit none
  integer, intent(in) :: istep, iinc, nelem, ithermal(*), mi(*), konl(*), nope
  real(8), intent(in) :: time, ttime, dtime, t1(*), vold(0:mi(2), *)
  character(len=80), intent(in) :: name
  integer :: j
  real(8) :: tm

  ctime(1) = time
  ctime(2) = ttime + time
  cdtime = dtime
  cstep = istep
  cinc = iinc
  cnoel = nelem
  ciname = name
  if (cpnewdt <= 0.d0) cpnewdt = 1.d0
  ! The slave node is the contact element's last node, the master face's nodes the others.
  cnode = konl(nope)
  ctemp = 0.d0
  if (ithermal(1) == 1 .or. ithermal(1) >= 2) then
    tm = 0.d0
    do j = 1, nope - 1
      if (ithermal(1) == 1) then
        tm = tm + t1(konl(j))
      else
        tm = tm + vold(0, konl(j))
      end if
    end do
    if (ithermal(1) == 1) then
      ctemp(1) = t1(konl(nope))
    else
      ctemp(1) = vold(0, konl(nope))
    end if
    if (nope > 1) ctemp(2) = tm/dble(nope - 1)
  end if
end subroutine ifl_ccx_ctx

!> After springforc_n2f (resultsmech.f): the smallest PNEWDT < 1 that FRIC returned since the
!> last call goes to CalculiX's qa(3), which cuts the increment back by that factor.
subroutine ifl_ccx_pnewdt(qa3)
  use ifl_ccx_context, only: cpnewdt
  implicit none
  real(8), intent(inout) :: qa3
  real(8) :: r
  if (cpnewdt > 0.d0 .and. cpnewdt < 1.d0) then
    r = max(cpnewdt, 0.05d0)
    if (qa3 <= 0.d0) then
      qa3 = r
    else
      qa3 = min(qa3, r)
    end if
  end if
  cpnewdt = 1.d0
end subroutine ifl_ccx_pnewdt

!> True for an interaction with *FRICTION, USER.
logical function ifl_ccx_user(elc, ncmat_)
  implicit none
  integer, intent(in) :: ncmat_
  real(8), intent(in) :: elc(0:ncmat_)
  ifl_ccx_user = .false.
  if (ncmat_ >= 13) ifl_ccx_user = elc(12) > 0.d0
end function ifl_ccx_user

!> The local tangent basis: t1 is global x projected on the contact plane (global z when the
!> normal is within 1.5231e-6 of x, the threshold CalculiX uses for its own t1), t2 = n x t1.
subroutine ifl_ccx_basis(xn, t1, t2)
  implicit none
  real(8), intent(in) :: xn(3)
  real(8), intent(out) :: t1(3), t2(3)
  real(8) :: e(3), d
  e = 0.d0
  if (1.d0 - abs(xn(1)) < 1.5231d-6) then
    e(3) = 1.d0
  else
    e(1) = 1.d0
  end if
  t1 = e - (e(1)*xn(1) + e(2)*xn(2) + e(3)*xn(3))*xn
  d = sqrt(t1(1)**2 + t1(2)**2 + t1(3)**2)
  t1 = t1/d
  t2(1) = xn(2)*t1(3) - xn(3)*t1(2)
  t2(2) = xn(3)*t1(1) - xn(1)*t1(3)
  t2(3) = xn(1)*t1(2) - xn(2)*t1(1)
end subroutine ifl_ccx_basis

!> One contact point: FRIC with the Abaqus argument list. xn the unit normal, t the
!> accumulated tangential relative displacement (global), fnorm the normal force, area the
!> point's area, sini/s its xstate at the start / end of the increment. Returns the friction
!> stress as a global vector (taug), the tangents in (t1, t2), the energies and writes s.
subroutine ifl_ccx_point(elc, ncmat_, xn, t, fnorm, area, sini, s, nstate_, npt, t1, t2, &
                         taug, ddtddg, ddtddp, sed, sfd, closed)
  use ifl_ccx_context, only: ctime, cdtime, ctemp, cpnewdt, cstep, cinc, cnoel, cnode, ciname
  implicit none
  integer, intent(in) :: ncmat_, nstate_, npt
  real(8), intent(in) :: elc(0:ncmat_), xn(3), t(3), fnorm, area, sini(nstate_)
  real(8), intent(inout) :: s(nstate_)
  real(8), intent(out) :: t1(3), t2(3), taug(3), ddtddg(2, 2), ddtddp(2), sed, sfd
  logical, intent(out) :: closed
  real(8) :: tau(2), dslip(2), ddtddt(2, 2), pnewdt, dgam(2), taulm(2), slip(2)
  real(8) :: press, dpress, ddpddh, chrlngth, coords(3), rcoord(3), drot(2, 2)
  real(8) :: predef(2, 1), temp(2), dummy(1), dt(3)
  integer :: np, nd, lm, i
  character(len=80) :: blank

  np = nint(elc(12))
  nd = nint(elc(13))
  call ifl_ccx_basis(xn, t1, t2)
  taug = 0.d0
  ddtddg = 0.d0
  ddtddp = 0.d0
  sed = 0.d0
  sfd = 0.d0
  s(1:3) = sini(1:3)
  do i = 14, 13 + nd
    s(i) = sini(i)
  end do
  press = fnorm/area
  closed = press > 0.d0
  if (.not. closed) then
    ! An open point: no friction, and it starts afresh when it closes.
    s(10:13) = 0.d0
    return
  end if
  dt = t - sini(7:9)
  tau(1) = sini(10)*t1(1) + sini(11)*t1(2) + sini(12)*t1(3)
  tau(2) = sini(10)*t2(1) + sini(11)*t2(2) + sini(12)*t2(3)
  dgam(1) = dt(1)*t1(1) + dt(2)*t1(2) + dt(3)*t1(3)
  dgam(2) = dt(1)*t2(1) + dt(2)*t2(2) + dt(3)*t2(3)
  slip(1) = t(1)*t1(1) + t(2)*t1(2) + t(3)*t1(3)
  slip(2) = t(1)*t2(1) + t(2)*t2(2) + t(3)*t2(3)
  dpress = press - sini(13)
  ! dp/dh of CalculiX's linear pressure-overclosure law (elcon(2)); 0 for the other laws.
  ddpddh = 0.d0
  if (nint(elc(3)) == 2) ddpddh = elc(2)
  chrlngth = sqrt(area)
  taulm = 0.d0
  dslip = 0.d0
  ddtddt = 0.d0
  temp = ctemp
  call ifl_ccx_unread(coords, rcoord, drot, predef, pnewdt, lm, blank)
  if (nd > 0) then
    call fric(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, s(14), dgam, taulm, &
              press, dpress, ddpddh, slip, cstep, cinc, ctime, cdtime, cnoel, ciname, blank, &
              blank, npt, cnode, 0, coords, rcoord, drot, temp, predef, 2, 3, 1, nd, &
              chrlngth, elc(14), np)
  else
    call fric(lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, dummy, dgam, taulm, &
              press, dpress, ddpddh, slip, cstep, cinc, ctime, cdtime, cnoel, ciname, blank, &
              blank, npt, cnode, 0, coords, rcoord, drot, temp, predef, 2, 3, 1, nd, &
              chrlngth, elc(14), np)
  end if
  if (pnewdt < cpnewdt) cpnewdt = pnewdt
  taug = tau(1)*t1 + tau(2)*t2
  s(1:3) = sini(1:3) + dslip(1)*t1 + dslip(2)*t2
  s(10:12) = taug
  s(13) = press
end subroutine ifl_ccx_point

!> springforc_n2f and springforc_f2f: the friction force of a contact point from FRIC.
!> fnl is the slave node's force (normal part in, friction added), cstr(5:6) the shear stress.
subroutine ifl_ccx_force(elc, ncmat_, xn, t, fnl, springarea, sini, s, nstate_, cstr, &
                             npt, nener, senergy, venergy)
  implicit none
  integer, intent(in) :: ncmat_, nstate_, npt, nener
  real(8), intent(in) :: elc(0:ncmat_), xn(3), t(3), springarea(2), sini(nstate_)
  real(8), intent(inout) :: fnl(3), s(nstate_), cstr(6), senergy, venergy
  real(8) :: t1(3), t2(3), taug(3), ddtddg(2, 2), ddtddp(2), sed, sfd, fnorm, area
  logical :: closed
  area = springarea(1)
  fnorm = sqrt(fnl(1)**2 + fnl(2)**2 + fnl(3)**2)
  call ifl_ccx_point(elc, ncmat_, xn, t, fnorm, area, sini, s, nstate_, npt, t1, t2, taug, &
                     ddtddg, ddtddp, sed, sfd, closed)
  fnl = fnl + area*taug
  cstr(5) = taug(1)*t1(1) + taug(2)*t1(2) + taug(3)*t1(3)
  cstr(6) = taug(1)*t2(1) + taug(2)*t2(2) + taug(3)*t2(3)
  if (nener == 1) then
    senergy = senergy + sed*area
    venergy = sfd*area
  end if
end subroutine ifl_ccx_force

!> springstiff_n2f and springstiff_f2f: the same point's friction force, added to fnl, and its tangent, added to
!> fpu(i,j,k) = d fnl(i) / d u(j, node k): area * t_a DDTDDG_ab t_b . tu (tu = d t / d u), and
!> t_a DDTDDP_a times the derivative of the normal force (as CalculiX does for its slip term,
!> not in linear dynamics).
subroutine ifl_ccx_stiff(elc, ncmat_, xn, t, fnl, fpu, tu, nope, springarea, sini, s, &
                             nstate_, npt, nmethod, iperturb)
  use ifl_ccx_context, only: cpnewdt
  implicit none
  integer, intent(in) :: ncmat_, nope, nstate_, npt, nmethod, iperturb(*)
  real(8), intent(in) :: elc(0:ncmat_), xn(3), t(3), tu(3, 3, *), springarea(2)
  real(8), intent(in) :: sini(nstate_)
  real(8), intent(inout) :: fnl(3), fpu(3, 3, *), s(nstate_)
  real(8) :: t1(3), t2(3), taug(3), ddtddg(2, 2), ddtddp(2), sed, sfd, fnorm, area
  real(8) :: dfn(3, 10), tb(3, 2), g(3, 2), gt(2), w(3)
  logical :: closed
  integer :: i, j, k, a
  real(8) :: keep
  area = springarea(1)
  fnorm = sqrt(fnl(1)**2 + fnl(2)**2 + fnl(3)**2)
  ! the step ratio is CalculiX's to act on after the force (resultsmech), not here
  keep = cpnewdt
  call ifl_ccx_point(elc, ncmat_, xn, t, fnorm, area, sini, s, nstate_, npt, t1, t2, taug, &
                     ddtddg, ddtddp, sed, sfd, closed)
  cpnewdt = keep
  if (.not. closed) return
  ! d |normal force| / d u, before fpu takes the friction terms
  do k = 1, nope
    do j = 1, 3
      dfn(j, k) = -(xn(1)*fpu(1, j, k) + xn(2)*fpu(2, j, k) + xn(3)*fpu(3, j, k))
    end do
  end do
  fnl = fnl + area*taug
  tb(:, 1) = t1
  tb(:, 2) = t2
  ! g(:, a) = sum_b DDTDDG(a, b) t_b, the rows of the tangent in global terms
  do a = 1, 2
    g(:, a) = ddtddg(a, 1)*t1 + ddtddg(a, 2)*t2
  end do
  do k = 1, nope
    do j = 1, 3
      ! d dgam_b / d u(j,k) = t_b . tu(:, j, k)
      do a = 1, 2
        gt(a) = g(1, a)*tu(1, j, k) + g(2, a)*tu(2, j, k) + g(3, a)*tu(3, j, k)
      end do
      do i = 1, 3
        w(i) = area*(tb(i, 1)*gt(1) + tb(i, 2)*gt(2))
      end do
      if ((nmethod /= 4) .or. (iperturb(1) > 1)) then
        do i = 1, 3
          w(i) = w(i) + (tb(i, 1)*ddtddp(1) + tb(i, 2)*ddtddp(2))*dfn(j, k)
        end do
      end if
      do i = 1, 3
        fpu(i, j, k) = fpu(i, j, k) + w(i)
      end do
    end do
  end do
end subroutine ifl_ccx_stiff

!> interpolateinface (face-to-face contact, when CalculiX regenerates its integration points):
!> CalculiX interpolates its own 9 friction entries of xstate over a triangle of old points;
!> this does the same, by CalculiX's plane_eq, for the friction stress and the pressure (10 ..
!> 13: fields, linear over the triangle). The law's STATEV (14 .. nstate_) is a state, not a
!> field (a status code, a slip rate that must stay >= 0, a state variable of its own law): a
!> plane through three states can be none of them (a status of 0.4, a negative rate), so the
!> new point takes the STATEV of the nearest old point of the three.
subroutine ifl_ccx_interpolate(c1, c2, c3, n1, n2, n3, p, xstateini, xstate, nstate_, mi, iout)
  implicit none
  integer, intent(in) :: n1, n2, n3, nstate_, mi(*), iout
  real(8), intent(in) :: c1(2), c2(2), c3(2), p(3), xstateini(nstate_, mi(1), *)
  real(8), intent(inout) :: xstate(nstate_, mi(1), *)
  integer :: i, nearest
  real(8) :: d1, d2, d3
  do i = 10, min(13, nstate_)
    call plane_eq(c1(1), c1(2), xstateini(i, 1, n1), c2(1), c2(2), xstateini(i, 1, n2), &
                  c3(1), c3(2), xstateini(i, 1, n3), p(1), p(2), xstate(i, 1, iout))
  end do
  d1 = (p(1) - c1(1))**2 + (p(2) - c1(2))**2
  d2 = (p(1) - c2(1))**2 + (p(2) - c2(2))**2
  d3 = (p(1) - c3(1))**2 + (p(2) - c3(2))**2
  nearest = n1
  if (d2 < d1 .and. d2 <= d3) nearest = n2
  if (d3 < d1 .and. d3 < d2) nearest = n3
  do i = 14, nstate_
    xstate(i, 1, iout) = xstateini(i, 1, nearest)
  end do
end subroutine ifl_ccx_interpolate
