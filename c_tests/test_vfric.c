/*
 * vfric_ (Abaqus/Explicit VFRIC, double precision) driven as Abaqus/Explicit calls it: 42
 * arguments by reference + 3 hidden CHARACTER lengths, arrays in Fortran layout.
 *
 * - Closed form (docs/vfric.md): fTangential(1,k) = -min(mu*fNormal(k), tau_max*areaSlv(node),
 *   fStickForce(k)), 0 for fNormal < 0, -fStickForce with rough friction (PROPS(7) = 2);
 *   fTangential(2,k) = 0 for nFricDir = 2. Points of every kind in one block: slip, stick,
 *   tension, capped by tau_max*area (slave nodes reached through a permuted jConSlvid), zero
 *   stick force. Compared exactly: the closed form is one product and two minima.
 * - Nothing is written past fTangential(nFricDir,nContact), statev is not written.
 * - A bad point (NaN fNormal, negative fStickForce, jConSlvid out of range with tau_max) gets 0
 *   and a message naming VFRIC, the interaction and the point; the others are computed.
 * - A bad call (adhesive or extended PROPS, mu < 0) gives 0 everywhere and a message;
 *   nFricDir = 3 writes nothing.
 */
#include <math.h>
#include <stddef.h>

#include "harness.h"

/* MAXDIR: nDir of the refused nFricDir = 3 case, so its setup stays inside the arrays. */
enum { NC = 9, NSLV = 12, MAXDIR = 4, NSV = 2 };
#define GUARD (-7.77e77)

typedef struct {
    double ftan[MAXDIR * NC + 4];
    double statev[NSV * NSLV];
    int nc, nfacnod, nslv, nmst, nfricdir, ndir, nsv, nprops, ntemp, npred, numdef;
    int kstep, kinc, lconttype;
    int jslvuid[NSLV], jmstuid[4], jconslvid[NC], jconmstid[4 * NC];
    double timstep, timglb, dtimcur;
    char surfint[80], surfslv[80], surfmst[80];
    double dslip[MAXDIR * NC], fstick[NC], ftangprev[MAXDIR * NC], fnormal[NC], work[NC];
    double shape[4 * NC], coordslv[MAXDIR * NSLV], coordmst[MAXDIR * 4];
    double dircossl[MAXDIR * NC], dircosn[MAXDIR * NC], props[20], area[NSLV];
    double tempslv[NC], predefslv[NC], tempmst[4], predefmst[4];
} host_t;

static void set_name(char *buf, const char *text)
{
    size_t n = strlen(text);
    memset(buf, ' ', 80);
    memcpy(buf, text, n < 80 ? n : 80);
}

/* One block: points of every kind; props = {1, mu, mu, tau_max, gc, 0, stick mode}. */
static void setup(host_t *h, int nfricdir, double mu, double tau_max, double stick_mode)
{
    int k, i;
    memset(h, 0, sizeof *h);
    for (i = 0; i < (int)(sizeof h->ftan / sizeof h->ftan[0]); i++) {
        h->ftan[i] = GUARD;
    }
    for (i = 0; i < NSV * NSLV; i++) {
        h->statev[i] = 100.0 + i;
    }
    h->nc = NC;
    h->nfacnod = 4;
    h->nslv = NSLV;
    h->nmst = 4;
    h->nfricdir = nfricdir;
    h->ndir = nfricdir + 1;
    h->nsv = NSV;
    h->nprops = 7;
    h->kstep = h->kinc = h->lconttype = 1;
    h->dtimcur = 1e-6;
    set_name(h->surfint, "CP-1");
    set_name(h->surfslv, "SLAVE");
    set_name(h->surfmst, "MASTER");
    h->props[0] = 1.0;
    h->props[1] = mu;
    h->props[2] = mu;
    h->props[3] = tau_max;
    h->props[4] = 1e-3; /* gamma_crit: ignored in kinematic contact */
    h->props[6] = stick_mode;
    for (i = 0; i < NSLV; i++) {
        h->jslvuid[i] = 1000 + i;
        h->area[i] = 0.25 + 0.5 * i;
    }
    /* Points of every kind: slip, stick, tension, zero stick force, big loads. */
    static const double fn[NC] = {10.0, 10.0, -3.0, 40.0, 0.0, 7.5, 1e5, 2.0, 33.0};
    static const double fs[NC] = {5.0, 2.0, 4.0, 1e3, 6.0, 0.0, 1e9, 0.3, 9.0};
    for (k = 0; k < NC; k++) {
        h->fnormal[k] = fn[k];
        h->fstick[k] = fs[k];
        h->jconslvid[k] = NSLV - 1 - k; /* a permutation: node NSLV-1-k (1-based) */
        h->dslip[k * h->ndir] = 1e-4 * (k + 1);
    }
}

static void call(host_t *h)
{
    vfric_(h->ftan, h->statev, &h->kstep, &h->kinc, &h->nc, &h->nfacnod, &h->nslv, &h->nmst,
           &h->nfricdir, &h->ndir, &h->nsv, &h->nprops, &h->ntemp, &h->npred, &h->numdef,
           h->jslvuid, h->jmstuid, h->jconslvid, h->jconmstid, &h->timstep, &h->timglb,
           &h->dtimcur, h->surfint, h->surfslv, h->surfmst, &h->lconttype, h->dslip, h->fstick,
           h->ftangprev, h->fnormal, h->work, h->shape, h->coordslv, h->coordmst, h->dircossl,
           h->dircosn, h->props, h->area, h->tempslv, h->predefslv, h->tempmst, h->predefmst,
           80, 80, 80);
}

/* The closed form of point k (docs/vfric.md). */
static double expected(const host_t *h, int k)
{
    double mu = h->props[1], tau_max = h->props[3], fs = h->fstick[k], critical;
    if (h->props[6] == 2.0) {
        return -fs;
    }
    if (h->fnormal[k] < 0.0) {
        return 0.0; /* tension: no friction */
    }
    critical = mu * h->fnormal[k];
    if (tau_max > 0.0) {
        critical = fmin(critical, tau_max * h->area[h->jconslvid[k] - 1]);
    }
    return -fmin(critical, fs);
}

static void check_block(const host_t *h, int bad_point)
{
    int k, i;
    int nf = h->nfricdir;
    for (k = 0; k < NC; k++) {
        double want = k == bad_point ? 0.0 : expected(h, k);
        fh_context("nFricDir %d, tau_max %g, mode %g, point %d", nf, h->props[3], h->props[6],
                   k + 1);
        FH_EXACT(h->ftan[k * nf], want);
        /* Between 0 and -fStickForce (the VFRIC contract). */
        FH_CHECK(k == bad_point || (h->ftan[k * nf] <= 0.0 && h->ftan[k * nf] >= -h->fstick[k]));
        if (nf == 2) {
            FH_EXACT(h->ftan[k * nf + 1], 0.0);
        }
    }
    fh_context("nFricDir %d: guards and state", nf);
    for (i = nf * NC; i < (int)(sizeof h->ftan / sizeof h->ftan[0]); i++) {
        FH_CHECK(h->ftan[i] == GUARD);
    }
    for (i = 0; i < NSV * NSLV; i++) {
        FH_CHECK(h->statev[i] == 100.0 + i);
    }
}

int main(void)
{
    host_t h;
    int nf, variant, i;
    /* mu, tau_max, stick mode (0 elastic, 1 exact: the same in kinematic contact; 2 rough). */
    static const double variants[][3] = {
        {0.3, 0.0, 0.0}, {0.3, 2.0, 0.0}, {0.45, 0.0, 1.0}, {0.3, 2.0, 2.0}, {0.0, 0.0, 0.0}};
    for (nf = 1; nf <= 2; nf++) {
        for (variant = 0; variant < 5; variant++) {
            setup(&h, nf, variants[variant][0], variants[variant][1], variants[variant][2]);
            call(&h);
            check_block(&h, -1);
        }
        /* The kinds are really there: slip at mu*fN, stick at fStickForce, capped at tau_max*A. */
        setup(&h, nf, 0.3, 0.0, 0.0);
        call(&h);
        fh_context("nFricDir %d: kinds", nf);
        FH_EXACT(h.ftan[0 * nf], -3.0);       /* slip: 0.3*10 < 5 */
        FH_EXACT(h.ftan[1 * nf], -2.0);       /* stick: 0.3*10 > 2 */
        FH_EXACT(h.ftan[2 * nf], 0.0);        /* tension */
        FH_EXACT(h.ftan[5 * nf], 0.0);        /* zero stick force */
        setup(&h, nf, 0.3, 2.0, 0.0);
        call(&h);
        /* Point 4: mu*fN = 12, area of node NSLV-4 (1-based) = 0.25 + 0.5*(NSLV-5) = 3.75. */
        FH_EXACT(h.ftan[3 * nf], -2.0 * 3.75);

        /* Bad points: each alone in a block, the others computed. */
        for (i = 0; i < 3; i++) {
            int bad = 2 + 3 * i;
            setup(&h, nf, 0.3, 2.0, 0.0);
            if (i == 0) {
                h.fnormal[bad] = NAN;
            } else if (i == 1) {
                h.fstick[bad] = -1.0;
            } else {
                h.jconslvid[bad] = NSLV + 1;
            }
            ifl_clear_error();
            call(&h);
            check_block(&h, bad);
            fh_context("nFricDir %d: bad point %d", nf, bad + 1);
            FH_CONTAINS(ifl_last_error(), "VFRIC");
            FH_CONTAINS(ifl_last_error(), "'CP-1'");
            FH_CONTAINS(ifl_last_error(), i == 0 ? "fNormal" : (i == 1 ? "fStickForce" : "jConSlvid"));
            {
                char place[32];
                snprintf(place, sizeof place, "contact point %d", bad + 1);
                FH_CONTAINS(ifl_last_error(), place);
            }
        }

        /* Bad calls: no friction anywhere, one message. */
        for (i = 0; i < 3; i++) {
            int k;
            setup(&h, nf, 0.3, 0.0, 0.0);
            if (i == 0) {
                h.props[0] = 2.0; /* adhesive */
                h.props[2] = -1.0;
                h.props[3] = 1.0;
                h.props[4] = 0.0;
                h.props[7] = 1e-3;
                h.nprops = 8;
            } else if (i == 1) {
                h.props[2] = 0.1; /* anisotropic: the extended law */
            } else {
                h.props[1] = -0.3;
                h.props[2] = -0.3;
            }
            ifl_clear_error();
            call(&h);
            fh_context("nFricDir %d: bad call %d", nf, i);
            for (k = 0; k < nf * NC; k++) {
                FH_EXACT(h.ftan[k], 0.0);
            }
            FH_CHECK(h.ftan[nf * NC] == GUARD);
            FH_CONTAINS(ifl_last_error(), "VFRIC");
            FH_CONTAINS(ifl_last_error(), i == 0 ? "adhesive" : (i == 1 ? "plain Coulomb" : "PROPS(2)"));
        }
    }
    /* nFricDir = 3: refused before anything is written. */
    setup(&h, 3, 0.3, 0.0, 0.0);
    ifl_clear_error();
    call(&h);
    fh_context("nFricDir 3");
    for (i = 0; i < (int)(sizeof h.ftan / sizeof h.ftan[0]); i++) {
        FH_CHECK(h.ftan[i] == GUARD);
    }
    FH_CONTAINS(ifl_last_error(), "nFricDir = 3");
    return fh_finish();
}
