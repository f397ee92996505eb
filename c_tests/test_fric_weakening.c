/*
 * Velocity-weakening friction driven as a host drives it (issue 16, scene F7):
 *
 *   Steady sliding: a point driven at a constant slip velocity v with increments r*gamma_crit,
 *       r = 0.01 .. 5, d_c*v = 0.3 .. 10, slides at tau = mu(v) p once past the onset (decay law,
 *       PROPS(8) = 1: mu(v) = mu_k + (mu_s - mu_k) exp(-d_c v)) or at the seed-004 strength
 *       S_slide(v) = ((mu_s v_half + mu_d v)/(v_half + v) + k_mu v) p + S_a (adhesive law),
 *       NFDIR = 1 and 2 (an oblique direction). From rest the stress first reaches mu_s p
 *       (adhesive: mu_s p + S_a) and never goes above it before the first slip.
 *   Stop: increments without motion keep the sliding stress (stick, no jump to mu_s p).
 *   Reversal: driving back first sticks, the stress changes sign, then it slides at -mu(v) p.
 *   Fresh gap (uinter_): a never-touched point with a small gap is free (zero stress,
 *       STATEV(3) = 4, LOPENCLOSE = 0); after contact, the same gap is bonded (status 3).
 *
 * Every expected value is the law's closed form. Mirrored by
 * fortran_tests/test_fric_weakening.f90.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"

#define GAMMA_CRIT 1e-3
#define P 100.0
#define MU_S 0.5
#define MU_K 0.2
#define DC 200.0
#define SA 3.0
#define KMU 0.5
#define VHALF 1e-3

enum { LAW_DECAY, LAW_ADHESIVE };

static int set_props(double *props, int law)
{
    if (law == LAW_DECAY) {
        const double p[10] = {1.0, MU_S, 0.0, 0.0, GAMMA_CRIT, 0.0, 0.0, 1.0, MU_K, DC};
        memcpy(props, p, sizeof p);
        return 10;
    } else {
        const double p[8] = {2.0, MU_K, MU_S, SA, 0.0, KMU, VHALF, GAMMA_CRIT};
        memcpy(props, p, sizeof p);
        return 8;
    }
}

static double sliding(int law, double v)
{
    if (law == LAW_DECAY) {
        return (MU_K + (MU_S - MU_K) * exp(-DC * v)) * P;
    }
    return ((MU_S * VHALF + MU_K * v) / (VHALF + v) + KMU * v) * P + SA;
}

static double static_strength(int law)
{
    return law == LAW_DECAY ? MU_S * P : MU_S * P + SA;
}

/* The driving direction in the plane. */
static void direction(int nfdir, double d[2])
{
    d[0] = nfdir == 1 ? 1.0 : 0.6;
    d[1] = nfdir == 1 ? 0.0 : -0.8;
}

/* One increment of slip dg along the direction in time |dg|/v; returns tau along it. */
static double step(fh_fric *h, double dg, double v)
{
    double d[2];
    int a;
    direction(h->nfdir, d);
    for (a = 0; a < h->nfdir; a++) {
        h->dgam[a] = dg * d[a];
    }
    h->dtime = dg != 0.0 ? fabs(dg) / v : 0.1; /* a stop still takes time */
    h->dpress = 0.0;
    fh_call_ok(h);
    return h->nfdir == 1 ? h->tau[0] : h->tau[0] * d[0] + h->tau[1] * d[1];
}

/* Drives n increments; returns the number of the first sliding increment (or -1) and checks
 * that no increment before it goes above the static strength. */
static int drive(fh_fric *h, int law, double r, double v, int n, double *last)
{
    int k, first = -1;
    for (k = 0; k < n; k++) {
        double t = step(h, r * GAMMA_CRIT, v);
        if (first < 0 && h->statev[2] == 1.0) {
            first = k;
        }
        if (first < 0) {
            FH_CHECK(t <= static_strength(law) * (1.0 + 1e-12));
        }
        *last = t;
    }
    return first;
}

static void steady(int law, int nfdir)
{
    static const double ratios[6] = {0.01, 0.1, 0.25, 0.5, 1.0, 5.0};
    static const double xs[4] = {0.3, 1.0, 3.0, 10.0};
    double props[FH_MAXPROPS];
    int nprops = set_props(props, law), i, j, k;
    for (i = 0; i < 6; i++) {
        for (j = 0; j < 4; j++) {
            double r = ratios[i], v = xs[j] / DC, t = 0.0, want = sliding(law, v);
            int n = (int)ceil(1.5 / r) + 20, first;
            fh_fric h;
            fh_init(&h, nfdir, props, nprops);
            h.press = P;
            fh_context("steady law %d NFDIR %d r %g d_c v %g", law, nfdir, r, xs[j]);
            first = drive(&h, law, r, v, n, &t);
            FH_CHECK(first >= 0);
            /* Twenty more increments, each at the closed form. */
            for (k = 0; k < 20; k++) {
                t = step(&h, r * GAMMA_CRIT, v);
                FH_EXACT(h.statev[2], 1.0);
                FH_NEAR(t, want, 1e-9, 0.0);
                FH_NEAR(h.statev[1], v, 1e-9, 0.0);
            }
        }
    }
}

static void stop_and_reversal(int law, int nfdir)
{
    double props[FH_MAXPROPS], t = 0.0, v = 3.0 / DC, want = sliding(law, v), r = 0.1;
    int nprops = set_props(props, law), k, crossed = -1, first_slip = -1;
    fh_fric h;
    fh_init(&h, nfdir, props, nprops);
    h.press = P;
    drive(&h, law, r, v, 40, &t);
    fh_context("stop law %d NFDIR %d", law, nfdir);
    FH_NEAR(t, want, 1e-9, 0.0);
    for (k = 0; k < 4; k++) {
        t = step(&h, 0.0, v);
        FH_EXACT(h.statev[2], 0.0);
        FH_NEAR(t, want, 1e-9, 0.0);
    }
    fh_context("reversal law %d NFDIR %d", law, nfdir);
    for (k = 0; k < 80; k++) {
        t = step(&h, -r * GAMMA_CRIT, v);
        if (crossed < 0 && t < 0.0) {
            crossed = k;
        }
        if (first_slip < 0 && h.statev[2] == 1.0) {
            first_slip = k;
        }
    }
    FH_CHECK(crossed > 0);              /* the first reversed increment still pushes forward */
    FH_CHECK(first_slip > crossed);     /* stick through zero stress */
    FH_NEAR(t, -want, 1e-9, 0.0);       /* sliding the other way */
    FH_EXACT(h.statev[2], 1.0);
}

static void fresh_gap(int ndir)
{
    const double props[10] = {2.0, MU_K, MU_S, SA, 5.0, 0.0, 0.0, GAMMA_CRIT, 0.0, 1e6};
    double stress[4] = {0, 0, 0, FH_GUARD}, ddsddr[10], dvisc[10], dstruct[10], flux[3];
    double ddfddt[5], ddsddt[7], ddfddr[7], statev[4] = {0, 0, 0, FH_GUARD};
    double sed = 0, sfd = 0, spd = 0, svd = 0, scd = 0, pnewdt;
    double rdisp[3] = {-1e-6, 0, 0}, drdisp[3] = {-1e-6, 1e-5, 0}, temp[2] = {20, 20};
    double dtemp[2] = {0, 0}, predef[2] = {0, 0}, dpred[2] = {0, 0}, time[2] = {0, 0};
    double dtime = 1.0, freqr = 0, coords[3] = {0, 0, 0}, alocaldir[9] = {0};
    double drot[4] = {1, 0, 0, 1}, area = 1.0, chrlngth = 1.0;
    char ciname[80], slname[80], msname[80];
    int node = 1, nstatv = 3, npred = 1, nprops = 10, mcrd = 3, kstep = 1, kinc = 1, kit = 1;
    int linper = 0, lopenclose = -1, lstate = -1, lsdi = 0, lprint = 0, pass;
    memset(ciname, ' ', 80);
    memset(slname, ' ', 80);
    memset(msname, ' ', 80);
    memcpy(ciname, "FRESH", 5);
    /* Never touched with a gap; then closed (h = +1e-6, p = 1); then the same gap again. */
    for (pass = 0; pass < 3; pass++) {
        fh_context("fresh gap NDIR %d pass %d", ndir, pass);
        rdisp[0] = pass == 1 ? 1e-6 : -1e-6;
        pnewdt = FH_PNEWDT_IN;
        uinter_(stress, ddsddr, dvisc, dstruct, flux, ddfddt, ddsddt, ddfddr, statev, &sed, &sfd,
                &spd, &svd, &scd, &pnewdt, rdisp, drdisp, temp, dtemp, predef, dpred, time,
                &dtime, &freqr, ciname, slname, msname, props, coords, alocaldir, drot, &area,
                &chrlngth, &node, &ndir, &nstatv, &npred, &nprops, &mcrd, &kstep, &kinc, &kit,
                &linper, &lopenclose, &lstate, &lsdi, &lprint, 80, 80, 80);
        FH_EXACT(pnewdt, FH_PNEWDT_IN);
        FH_CHECK(statev[3] == FH_GUARD && stress[3] == FH_GUARD);
        drdisp[1] = 0.0;
        if (pass == 0) {
            FH_EXACT(stress[0], 0.0);
            FH_EXACT(stress[1], 0.0);
            FH_EXACT(statev[2], 4.0);
            FH_EXACT(lopenclose, 0);
        } else if (pass == 1) {
            FH_NEAR(stress[0], 1.0, 1e-12, 0.0);
            FH_EXACT(statev[2], 0.0);
        } else {
            FH_NEAR(stress[0], -1.0, 1e-12, 0.0); /* bonded: tension K_n |h| */
            FH_EXACT(statev[2], 3.0);
            FH_EXACT(lopenclose, 1);
        }
    }
}

int main(void)
{
    int law, nfdir;
    for (law = LAW_DECAY; law <= LAW_ADHESIVE; law++) {
        for (nfdir = 1; nfdir <= 2; nfdir++) {
            steady(law, nfdir);
            stop_and_reversal(law, nfdir);
        }
    }
    fresh_gap(2);
    fresh_gap(3);
    return fh_finish();
}
