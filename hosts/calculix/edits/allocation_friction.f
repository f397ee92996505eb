!     interfacial: room in elcon for the PROPS of *FRICTION, USER
        call ifl_ccx_allocfric(textpart,n,ncmat_)
