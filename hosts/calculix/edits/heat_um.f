!     interfacial: *FRICTION, USER: the heat from the friction stress
!     |tau| of FRIC at this point (stx(5:6), written by ifl_ccx_force),
!     not from elcon(6), which is only the friction flag there: um
!     becomes |tau|/p, so that um*pressure below is |tau|
         if(ifl_ccx_user(elcon(0,1,imat),ncmat_)) then
            um=0.d0
            if(pressure.gt.0.d0) um=shear/pressure
         endif
