/*
 * test_fric_point.c: ifl_fric_point (one FRIC point with named inputs and outputs,
 * docs/c-api.md) against fric_ called as a host calls it, bit for bit: a point slid over
 * increments in 2-D and 3-D with law 1 (plain, the decay law) and law 2, exact stick, and a bad
 * PROPS (refusal, PNEWDT, the message); and a NULL struct refused by name.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"

/* The same point as ifl_fric_point's input. */
static IflFricInput input_of(const fh_fric *h, double *statev)
{
    IflFricInput in;
    memset(&in, 0, sizeof in);
    in.lm = h->lm;
    in.nfdir = h->nfdir;
    for (int a = 0; a < 2; a++) {
        in.tau[a] = a < h->nfdir ? h->tau[a] : 0.0;
        in.dgam[a] = a < h->nfdir ? h->dgam[a] : 0.0;
        in.taulm[a] = a < h->nfdir ? h->taulm[a] : 0.0;
        in.temp[a] = h->temp[a];
    }
    in.press = h->press;
    in.dpress = h->dpress;
    in.dtime = h->dtime;
    in.chrlngth = h->chrlngth;
    memcpy(in.drot, h->drot, sizeof in.drot);
    memcpy(in.coords, h->coords, sizeof in.coords);
    in.mcrd = h->mcrd;
    in.noel = h->noel;
    in.npt = h->npt;
    in.node = h->node;
    in.interaction = "SI_PAD";
    in.props = h->props;
    in.nprops = h->nprops;
    memcpy(statev, h->statev, sizeof(double) * (size_t)h->nstatv);
    in.statev = statev;
    in.nstatv = h->nstatv;
    in.pnewdt = FH_PNEWDT_IN;
    return in;
}

#define SAME(a, b, n) (memcmp((a), (b), sizeof(double) * (size_t)(n)) == 0)

/* One increment both ways; the fric_ point moves on, the output checked bit for bit. */
static void step_both(fh_fric *h)
{
    double statev[FH_MAXSTATV];
    IflFricInput in = input_of(h, statev);
    IflFricOutput out;
    int n = h->nfdir;
    ifl_clear_error();
    IflStatus st = ifl_fric_point(&in, &out);
    char msg[1024];
    snprintf(msg, sizeof msg, "%s", ifl_last_error());
    /* fric_'s outputs that it may leave alone start as ifl_fric_point's do. */
    memset(h->ddtddg, 0, sizeof(double) * (size_t)(n * n));
    memset(h->ddtddp, 0, sizeof(double) * (size_t)n);
    memset(h->dslip, 0, sizeof(double) * (size_t)n);
    memset(h->ddtddt, 0, sizeof(double) * (size_t)(2 * n));
    h->sed = h->sfd = 0.0;
    ifl_clear_error();
    fh_call(h);
    FH_CHECK(out.lm == h->lm);
    FH_CHECK(SAME(out.tau, h->tau, n));
    FH_CHECK(SAME(out.ddtddg, h->ddtddg, n * n));
    FH_CHECK(SAME(out.ddtddp, h->ddtddp, n));
    FH_CHECK(SAME(out.dslip, h->dslip, n));
    FH_CHECK(SAME(&out.sed, &h->sed, 1) && SAME(&out.sfd, &h->sfd, 1));
    FH_CHECK(SAME(out.ddtddt, h->ddtddt, 2 * n));
    FH_CHECK(SAME(&out.pnewdt, &h->pnewdt, 1));
    FH_CHECK(SAME(statev, h->statev, h->nstatv));
    FH_CHECK(strcmp(msg, ifl_last_error()) == 0);
    FH_CHECK((st == IFL_STATUS_OK) == (msg[0] == '\0'));
}

/* n increments of slip along d from first contact at pressure p. */
static void slide(const char *what, const double *props, int nprops, int nfdir, int lm)
{
    static const double d[2] = {0.6, -0.8};
    fh_fric h;
    fh_init(&h, nfdir, props, nprops);
    fh_set_name(h.ciname, &h.ciname_len, 80, "SI_PAD");
    h.press = h.dpress = 10.0;
    h.dtime = 0.1;
    for (int k = 0; k < 8; k++) {
        fh_context("%s, NFDIR %d, increment %d", what, nfdir, k);
        for (int a = 0; a < nfdir; a++) {
            h.dgam[a] = 2e-3 * d[a] * (k < 5 ? 1.0 : -0.5);
            h.taulm[a] = 0.5 * d[a] * (k % 3);
        }
        h.lm = lm;
        step_both(&h);
        h.dpress = 0.0;
    }
}

int main(void)
{
    double plain[IFLP_COULOMB_NPROPS], decay[IFLP_COULOMB_NPROPS];
    fh_props_coulomb(plain, 0.3);
    plain[4] = 1e-3; /* gamma_crit */
    fh_props_coulomb(decay, 0.5);
    decay[7] = 1.0; /* decay law: mu_k = 0.2, d_c = 2 */
    decay[8] = 0.2;
    decay[9] = 2.0;
    double exact[IFLP_COULOMB_NPROPS];
    fh_props_coulomb(exact, 0.3);
    exact[6] = 1.0; /* exact stick */
    const double adhesive[7] = {2.0, 0.3, 0.5, 1.0, 0.0, 0.1, 0.01};
    double bad[IFLP_COULOMB_NPROPS];
    fh_props_coulomb(bad, -0.3);
    for (int nfdir = 1; nfdir <= 2; nfdir++) {
        slide("plain", plain, 5, nfdir, 0);
        slide("decay law", decay, IFLP_COULOMB_NPROPS, nfdir, 0);
        slide("exact stick", exact, 7, nfdir, 1);
        slide("adhesive", adhesive, 7, nfdir, 0);
        slide("bad PROPS", bad, 5, nfdir, 0);
    }

    fh_context("refusals");
    double statev[3] = {0.0, 0.0, 0.0};
    fh_fric h;
    fh_init(&h, 2, bad, 5);
    IflFricInput in = input_of(&h, statev);
    IflFricOutput out;
    FH_CHECK(ifl_fric_point(&in, &out) == IFL_STATUS_BAD_PARAMETER);
    FH_EXACT(out.pnewdt, FH_CUTBACK);
    FH_CONTAINS(ifl_last_error(), "PROPS(2)");
    FH_CONTAINS(ifl_last_error(), "FRIC");
    FH_CHECK(ifl_fric_point(NULL, &out) == IFL_STATUS_BAD_INPUT);
    FH_CONTAINS(ifl_last_error(), "input is a NULL pointer");
    return fh_finish();
}
