!     interfacial: the interaction's name, for *FRICTION, USER
        call ifl_ccx_name(matname(imat))
