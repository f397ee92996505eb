      end subroutine fricheat
      end module ifl_ccx_stock_fricheat
!     interfacial: CalculiX's own last line ends this empty routine
      subroutine ifl_ccx_stock_fricheat_end
