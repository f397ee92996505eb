!     interfacial: step, time, interaction and temperatures for FRIC
              call ifl_ccx_ctx(istep,iinc,time,ttime,dtime,
     &             matname(imat),i,ithermal,t1,vold,mi,konl,nope)
