/*
 * uinter_harness.h: the host side of UINTER for the C harnesses (header-only), shared by
 * test_uinter_adhesive.c and test_uinter_heat.c. A ui_point holds every UINTER argument of one
 * point for NDIR <= 3, arrays sized with one guard slot or more past the largest NDIR;
 * ui_set fills what both harnesses fill alike, ui_call_raw passes the arguments to uinter_ as
 * gfortran does (by reference, the three CHARACTER*80 names with their hidden lengths last).
 * What each harness checks around a call stays in the harness.
 *
 * Pass/fail bookkeeping comes from harness.h.
 */
#ifndef UINTER_HARNESS_H
#define UINTER_HARNESS_H

#include <string.h>

#include "harness.h"

typedef struct {
    double stress[4], ddsddr[10], dvisc[10], dstruct[10], flux[3], ddfddt[5], ddsddt[7];
    double ddfddr[7], statev[6], sed, sfd, spd, svd, scd, pnewdt;
    double rdisp[3], drdisp[3], temp[2], dtemp[2], predef[2], dpred[2], time[2], dtime, freqr;
    char ciname[80], slname[80], msname[80];
    double props[13], coords[3], alocaldir[9], drot[4], area, chrlngth;
    int node, ndir, nstatv, npred, nprops, mcrd, kstep, kinc, kit, linper;
    int lopenclose, lstate, lsdi, lprint;
} ui_point;

/*
 * Everything zero, then: interaction `name` (blank-padded; the surfaces blank), PROPS(1..nprops)
 * (nprops <= 13), NDIR, DTIME, NSTATV = 3, NPRED = 1, MCRD = 3, KSTEP = KINC = KIT = 1,
 * CHRLNGTH = AREA = 1, LOPENCLOSE = LSTATE = -1 (the host does not track the contact state).
 */
static inline void ui_set(ui_point *u, const char *name, int ndir, const double *props,
                          int nprops, double dtime)
{
    int i;
    size_t n = strlen(name);
    memset(u, 0, sizeof *u);
    memset(u->ciname, ' ', 80);
    memset(u->slname, ' ', 80);
    memset(u->msname, ' ', 80);
    memcpy(u->ciname, name, n < 80 ? n : 80);
    for (i = 0; i < nprops && i < 13; i++) {
        u->props[i] = props[i];
    }
    u->nprops = nprops;
    u->ndir = ndir;
    u->nstatv = 3;
    u->npred = 1;
    u->mcrd = 3;
    u->kstep = u->kinc = u->kit = 1;
    u->dtime = dtime;
    u->chrlngth = 1.0;
    u->area = 1.0;
    u->lopenclose = u->lstate = -1;
}

/* The raw call, as gfortran makes CALL UINTER(...). */
static inline void ui_call_raw(ui_point *u)
{
    uinter_(u->stress, u->ddsddr, u->dvisc, u->dstruct, u->flux, u->ddfddt, u->ddsddt, u->ddfddr,
            u->statev, &u->sed, &u->sfd, &u->spd, &u->svd, &u->scd, &u->pnewdt, u->rdisp,
            u->drdisp, u->temp, u->dtemp, u->predef, u->dpred, u->time, &u->dtime, &u->freqr,
            u->ciname, u->slname, u->msname, u->props, u->coords, u->alocaldir, u->drot,
            &u->area, &u->chrlngth, &u->node, &u->ndir, &u->nstatv, &u->npred, &u->nprops,
            &u->mcrd, &u->kstep, &u->kinc, &u->kit, &u->linper, &u->lopenclose, &u->lstate,
            &u->lsdi, &u->lprint, 80, 80, 80);
}

#endif /* UINTER_HARNESS_H */
