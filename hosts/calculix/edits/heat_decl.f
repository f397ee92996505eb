!     interfacial: true for an interaction with *FRICTION, USER
      logical ifl_ccx_user
