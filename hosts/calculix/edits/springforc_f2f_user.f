!     interfacial: *FRICTION, USER: the friction force from FRIC
            if(ifl_ccx_user(elcon(0,1,imat),ncmat_)) then
               call ifl_ccx_force(elcon(0,1,imat),ncmat_,xn,t,
     &              fnl(1,nopep),springarea,
     &              xstateini(1,1,ne0+igauss),
     &              xstate(1,1,ne0+igauss),nstate_,cstr,
     &              igauss,nener,senergy,venergy)
            else
