C=======================================================================
C     gapcon_ref.f -- the reference for the per-call benchmark of
C     GAPCON: a gap conductance routine written by hand the way an
C     analyst writes one, fixed-form Fortran 77 with the full
C     Abaqus/Standard argument list, named GAPREF so that it links next
C     to the library's GAPCON (gapcon_).
C
C     The interaction is chosen by comparing CINAME with the names of
C     the model (Abaqus passes them upper-cased, left-justified); the
C     laws are those of bench/gapcon_bench.toml:
C       GAP-CONST  AK = 4500
C       GAP-PTAB   AK(p), p = D(2): 100 rows, linear between rows,
C                  constant outside the table
C       GAP-TTAB   the same pressures at theta = 20 and theta = 320
C                  (mean surface temperature), linear in theta between
C                  them, constant outside
C     The table sits in one DATA statement, a row a line.  The row is
C     found by bisection (PTAB(ILO) <= p < PTAB(ILO+1)), once per call:
C     both temperatures share the pressure column.  Only AK(1) is
C     written.
C=======================================================================
      SUBROUTINE GAPREF(AK,D,FLOWM,TEMP,PREDEF,TIME,CINAME,SLNAME,
     1 MSNAME,COORDS,NOEL,NODE,NPRED,KSTEP,KINC)
C
      INCLUDE 'ABA_PARAM.INC'
      INCLUDE 'gapcon_args.inc'
C
      PARAMETER (NTAB=100, AKCON=4500.0D0, TLO=20.0D0, THI=320.0D0)
      PARAMETER (ZERO=0.0D0, HALF=0.5D0)
      DIMENSION PTAB(NTAB), AKTAB(NTAB,2)
      SAVE PTAB, AKTAB
C
C     The table, a row a line: contact pressure (MPa), then the
C     conductance (W/m^2/K) at theta = 20 and at theta = 320.
      DATA (PTAB(I), AKTAB(I,1), AKTAB(I,2), I = 1, NTAB) /
     1    0.00D0,   1500.0D0,   2200.0D0,
     2    0.02D0,   1519.0D0,   2222.8D0,
     3    0.08D0,   1575.9D0,   2291.1D0,
     4    0.18D0,   1670.5D0,   2404.6D0,
     5    0.32D0,   1802.4D0,   2562.9D0,
     6    0.50D0,   1971.1D0,   2765.3D0,
     7    0.72D0,   2175.9D0,   3011.1D0,
     8    0.98D0,   2416.0D0,   3299.2D0,
     9    1.28D0,   2690.4D0,   3628.5D0,
     1    1.62D0,   2998.2D0,   3997.8D0,
     2    2.00D0,   3338.1D0,   4405.7D0,
     3    2.42D0,   3708.7D0,   4850.4D0,
     4    2.88D0,   4108.8D0,   5330.6D0,
     5    3.38D0,   4536.7D0,   5844.0D0,
     6    3.92D0,   4991.0D0,   6389.2D0,
     7    4.50D0,   5469.8D0,   6963.8D0,
     8    5.12D0,   5971.6D0,   7565.9D0,
     9    5.78D0,   6494.4D0,   8193.3D0,
     1    6.48D0,   7036.5D0,   8843.8D0,
     2    7.22D0,   7596.0D0,   9515.2D0,
     3    8.00D0,   8171.0D0,  10205.2D0,
     4    8.82D0,   8759.6D0,  10911.5D0,
     5    9.68D0,   9359.9D0,  11631.9D0,
     6   10.58D0,   9969.9D0,  12363.9D0,
     7   11.52D0,  10587.8D0,  13105.4D0,
     8   12.50D0,  11211.6D0,  13853.9D0,
     9   13.52D0,  11839.7D0,  14607.6D0,
     1   14.58D0,  12470.2D0,  15364.2D0,
     2   15.68D0,  13101.3D0,  16121.6D0,
     3   16.82D0,  13731.4D0,  16877.7D0,
     4   18.00D0,  14358.9D0,  17630.7D0,
     5   19.22D0,  14982.2D0,  18378.6D0,
     6   20.48D0,  15599.9D0,  19119.9D0,
     7   21.78D0,  16210.5D0,  19852.6D0,
     8   23.12D0,  16812.9D0,  20575.5D0,
     9   24.50D0,  17405.8D0,  21287.0D0,
     1   25.92D0,  17988.0D0,  21985.6D0,
     2   27.38D0,  18558.6D0,  22670.3D0,
     3   28.88D0,  19116.6D0,  23339.9D0,
     4   30.42D0,  19661.2D0,  23993.4D0,
     5   32.00D0,  20191.6D0,  24629.9D0,
     6   33.62D0,  20707.2D0,  25248.6D0,
     7   35.28D0,  21207.5D0,  25849.0D0,
     8   36.98D0,  21691.8D0,  26430.2D0,
     9   38.72D0,  22160.0D0,  26992.0D0,
     1   40.50D0,  22611.7D0,  27534.0D0,
     2   42.32D0,  23046.6D0,  28055.9D0,
     3   44.18D0,  23464.6D0,  28557.5D0,
     4   46.08D0,  23865.7D0,  29038.8D0,
     5   48.02D0,  24249.8D0,  29499.8D0,
     6   50.00D0,  24617.0D0,  29940.4D0,
     7   52.02D0,  24967.6D0,  30361.1D0,
     8   54.08D0,  25301.5D0,  30761.8D0,
     9   56.18D0,  25619.2D0,  31143.0D0,
     1   58.32D0,  25920.8D0,  31505.0D0,
     2   60.50D0,  26206.7D0,  31848.0D0,
     3   62.72D0,  26477.3D0,  32172.8D0,
     4   64.98D0,  26732.9D0,  32479.5D0,
     5   67.28D0,  26974.0D0,  32768.8D0,
     6   69.62D0,  27201.1D0,  33041.3D0,
     7   72.00D0,  27414.5D0,  33297.4D0,
     8   74.42D0,  27614.9D0,  33537.9D0,
     9   76.88D0,  27802.7D0,  33763.2D0,
     1   79.38D0,  27978.4D0,  33974.1D0,
     2   81.92D0,  28142.5D0,  34171.0D0,
     3   84.50D0,  28295.6D0,  34354.7D0,
     4   87.12D0,  28438.1D0,  34525.7D0,
     5   89.78D0,  28570.6D0,  34684.7D0,
     6   92.48D0,  28693.6D0,  34832.3D0,
     7   95.22D0,  28807.7D0,  34969.2D0,
     8   98.00D0,  28913.2D0,  35095.8D0,
     9  100.82D0,  29010.7D0,  35212.8D0,
     1  103.68D0,  29100.7D0,  35320.8D0,
     2  106.58D0,  29183.5D0,  35420.2D0,
     3  109.52D0,  29259.7D0,  35511.6D0,
     4  112.50D0,  29329.7D0,  35595.6D0,
     5  115.52D0,  29393.9D0,  35672.7D0,
     6  118.58D0,  29452.7D0,  35743.2D0,
     7  121.68D0,  29506.4D0,  35807.7D0,
     8  124.82D0,  29555.5D0,  35866.6D0,
     9  128.00D0,  29600.2D0,  35920.2D0,
     1  131.22D0,  29640.9D0,  35969.1D0,
     2  134.48D0,  29677.9D0,  36013.5D0,
     3  137.78D0,  29711.4D0,  36053.7D0,
     4  141.12D0,  29741.8D0,  36090.2D0,
     5  144.50D0,  29769.3D0,  36123.2D0,
     6  147.92D0,  29794.2D0,  36153.0D0,
     7  151.38D0,  29816.6D0,  36179.9D0,
     8  154.88D0,  29836.8D0,  36204.2D0,
     9  158.42D0,  29855.0D0,  36226.0D0,
     1  162.00D0,  29871.3D0,  36245.6D0,
     2  165.62D0,  29885.9D0,  36263.1D0,
     3  169.28D0,  29899.0D0,  36278.8D0,
     4  172.98D0,  29910.7D0,  36292.8D0,
     5  176.72D0,  29921.2D0,  36305.4D0,
     6  180.50D0,  29930.5D0,  36316.6D0,
     7  184.32D0,  29938.8D0,  36326.6D0,
     8  188.18D0,  29946.2D0,  36335.4D0,
     9  192.08D0,  29952.8D0,  36343.4D0,
     1  196.02D0,  29958.6D0,  36350.3D0 /
C
      IF (CINAME .EQ. 'GAP-CONST') THEN
        AK(1) = AKCON
        RETURN
      ELSE IF (CINAME .EQ. 'GAP-PTAB') THEN
        NT = 1
      ELSE IF (CINAME .EQ. 'GAP-TTAB') THEN
        NT = 2
      ELSE
        WRITE (6,*) '*** GAPREF: no conductance for ', CINAME(1:20)
        AK(1) = ZERO
        RETURN
      END IF
C
C     Segment ILO..IHI of the pressure and the weight F of row IHI;
C     outside the table ILO = IHI (first or last row).
      P = D(2)
      IF (P .LT. PTAB(1)) THEN
        ILO = 1
        IHI = 1
        F = ZERO
      ELSE IF (P .GE. PTAB(NTAB)) THEN
        ILO = NTAB
        IHI = NTAB
        F = ZERO
      ELSE
        ILO = 1
        IHI = NTAB
   10   IF (IHI - ILO .GT. 1) THEN
          MID = (ILO + IHI)/2
          IF (PTAB(MID) .LE. P) THEN
            ILO = MID
          ELSE
            IHI = MID
          END IF
          GO TO 10
        END IF
        F = (P - PTAB(ILO))/(PTAB(IHI) - PTAB(ILO))
      END IF
      AK1 = AKTAB(ILO,1) + F*(AKTAB(IHI,1) - AKTAB(ILO,1))
      IF (NT .EQ. 1) THEN
        AK(1) = AK1
        RETURN
      END IF
C
      AK2 = AKTAB(ILO,2) + F*(AKTAB(IHI,2) - AKTAB(ILO,2))
      TBAR = HALF*(TEMP(1) + TEMP(2))
      IF (TBAR .LE. TLO) THEN
        AK(1) = AK1
      ELSE IF (TBAR .GE. THI) THEN
        AK(1) = AK2
      ELSE
        AK(1) = AK1 + (TBAR - TLO)/(THI - TLO)*(AK2 - AK1)
      END IF
      RETURN
      END
