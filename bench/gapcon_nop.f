C=======================================================================
C     gapcon_nop.f -- the call floor of the GAPCON benchmark: the GAPCON
C     argument list and nothing but AK(1) = 0.  Timed through the same
C     loop as GAPCON and GAPREF, it shows what the harness itself costs
C     (copying the inputs, 18 arguments, the checksum).
C=======================================================================
      SUBROUTINE GAPNOP(AK,D,FLOWM,TEMP,PREDEF,TIME,CINAME,SLNAME,
     1 MSNAME,COORDS,NOEL,NODE,NPRED,KSTEP,KINC)
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'gapcon_args.inc'
      AK(1) = 0.0D0
      RETURN
      END
