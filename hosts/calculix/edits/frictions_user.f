!     interfacial: *FRICTION, USER, PROPERTIES=n, DEPVAR=m
      call ifl_ccx_friction(inpc,textpart,elcon,ncmat_,ntmat_,imat,
     &     nstate_,istat,n,iline,ipol,inl,ipoinp,inp,ipoinpc,ier,
     &     iflusr)
      if(iflusr.ne.0) return
