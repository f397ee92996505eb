!     interfacial: the same interpolation for the state after CalculiX's
!     9 friction entries (the friction stress, pressure and STATEV of
!     *FRICTION, USER)
        call ifl_ccx_interpolate(coi(1,koncont(1,itri)),
     &       coi(1,koncont(2,itri)),coi(1,koncont(3,itri)),
     &       ip(koncont(1,itri)),ip(koncont(2,itri)),
     &       ip(koncont(3,itri)),p,xstateini,xstate,nstate_,mi,
     &       ne0+igauss)
