C=======================================================================
C     fric_nop.f -- the call floor of the per-call benchmark: the FRIC
C     argument list and nothing but LM = 0.  Timing it through the same
C     loop as FRIC and FRICREF shows what the harness itself costs
C     (copying the inputs, 42 arguments, the checksum), so that the
C     lead can read the ratios with and without it.
C=======================================================================
      SUBROUTINE FRICNOP(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,
     1 DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,
     2 KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,
     3 NPATCH,COORDS,RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,
     4 NSTATV,CHRLNGTH,PROPS,NPROPS)
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'fric_args.inc'
      LM = 0
      RETURN
      END
