!     interfacial: set when *FRICTION, USER was read by ifl_ccx_friction
      integer iflusr
