C     A stand-in for a stock CalculiX build: the main program, and heat.f's call to GAPCON with
C     CalculiX's argument list (AREA after KINC). Prints AK(1) for interaction SI1.
      PROGRAM CCX
      IMPLICIT REAL*8 (A-H,O-Z)
      CALL HEAT(AK1)
      WRITE (*,'(A,F8.3)') 'AK(1) =', AK1
      END
