!     interfacial: *FRICTION, USER: the friction force from FRIC
            if(ifl_ccx_user(elcon(0,1,imat),ncmat_)) then
               call ifl_ccx_force(elcon(0,1,imat),ncmat_,xn,t,
     &              fnl(1,nope),springarea,
     &              xstateini(1,1,ne0+konl(nope+1)),
     &              xstate(1,1,ne0+konl(nope+1)),nstate_,cstr,
     &              konl(nope+1),nener,senergy,venergy)
            else
