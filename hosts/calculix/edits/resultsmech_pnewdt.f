!     interfacial: a PNEWDT < 1 of FRIC cuts the increment back
              call ifl_ccx_pnewdt(qa(3))
