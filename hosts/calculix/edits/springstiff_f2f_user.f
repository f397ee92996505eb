!     interfacial: *FRICTION, USER: force and tangent from FRIC
            if(ifl_ccx_user(elcon(0,1,imat),ncmat_)) then
               call ifl_ccx_stiff(elcon(0,1,imat),ncmat_,xn,t,
     &              fnl,fpu,tu,1,springarea,
     &              xstateini(1,1,ne0+igauss),
     &              xstate(1,1,ne0+igauss),nstate_,
     &              igauss,nmethod,iperturb)
            else
