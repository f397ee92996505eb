!     interfacial: CalculiX's example fricheat is kept, but as a module
!     procedure, not as the external fricheat_: the link then takes the
!     library's fricheat_ (src/abi/fricheat.rs) for *GAP HEAT
!     GENERATION, USER (the stock archive holds fricheat.o, which would
!     otherwise come first)
      module ifl_ccx_stock_fricheat
      contains
