/*
 * ifl_fric_batch against fric_ called once per point (the host of harness.h): on random points
 * (stick, slip, exact stick, LM = 0/1/2, NFDIR 1 and 2, a padded leading dimension) every
 * output must be bit for bit what fric_ writes (memcmp), and nothing is written in the padding.
 * A point with a NaN input gets fric_'s failure outputs while the others are still computed;
 * NFDIR = 3 is refused as a whole (nothing written but PNEWDT). Mirrored by
 * fortran_tests/test_fric_batch.f90 (same generator, seed and sizes).
 */
#define _POSIX_C_SOURCE 200809L /* thread_harness.h declares pthread barriers */
#include <stdint.h>
#include <stdlib.h>

#include "harness.h"
#include "thread_harness.h" /* for its generator only: th_uniform */

enum { NP = 500, LD = 512, NSTATV = 3 };

/* The points, from the harnesses' MINSTD generator (one stream, a fixed seed). */
static uint32_t rng_state = 20240601u;

static double uniform(double a, double b)
{
    return th_uniform(&rng_state, a, b);
}

#define UNSET 12345.678

typedef struct {
    int lm[LD];
    double tau[2 * LD], ddtddg[4 * LD], ddtddp[2 * LD], dslip[2 * LD], sed[LD], sfd[LD];
    double statev[NSTATV * LD], dgam[2 * LD], taulm[2 * LD], press[LD], dpress[LD], chr[LD];
} batch_t;

static void fill(double *x, size_t n, double v)
{
    size_t i;
    for (i = 0; i < n; i++) {
        x[i] = v;
    }
}

static void random_batch(batch_t *b, int nfdir, double gamma_crit)
{
    int i, a;
    memset(b, 0, sizeof *b);
    fill(b->tau, 2 * LD, UNSET);
    fill(b->ddtddg, 4 * LD, UNSET);
    fill(b->ddtddp, 2 * LD, UNSET);
    fill(b->dslip, 2 * LD, UNSET);
    fill(b->sed, LD, UNSET);
    fill(b->sfd, LD, UNSET);
    fill(b->statev, NSTATV * LD, UNSET);
    for (i = 0; i < NP; i++) {
        double scale = gamma_crit * (uniform(0, 1) < 0.5 ? 0.4 : 4.0);
        double r = uniform(0, 1);
        b->lm[i] = r < 0.7 ? 0 : (r < 0.9 ? 1 : 2);
        b->press[i] = uniform(-5.0, 150.0);
        b->dpress[i] = uniform(-20.0, 20.0);
        b->chr[i] = uniform(0.05, 2.0);
        for (a = 0; a < nfdir; a++) {
            b->tau[i + a * LD] = uniform(-30.0, 30.0);
            b->dgam[i + a * LD] = uniform(-1.0, 1.0) * scale;
            b->taulm[i + a * LD] = uniform(-60.0, 60.0);
        }
        b->statev[i] = uniform(0.0, 1.0);
        b->statev[i + LD] = uniform(0.0, 1.0);
        b->statev[i + 2 * LD] = (double)(int)uniform(0.0, 2.999);
    }
}

/* The same points through fric_, one call each, results stored in the batch layout. */
static double per_point(batch_t *b, int nfdir, const double *props, int nprops, double dtime)
{
    double pnewdt = FH_PNEWDT_IN;
    int i, a, c;
    for (i = 0; i < NP; i++) {
        fh_fric h;
        fh_init(&h, nfdir, props, nprops);
        h.lm = b->lm[i];
        h.press = b->press[i];
        h.dpress = b->dpress[i];
        h.dtime = dtime;
        h.chrlngth = b->chr[i];
        h.sed = b->sed[i];
        h.sfd = b->sfd[i];
        for (a = 0; a < nfdir; a++) {
            h.tau[a] = b->tau[i + a * LD];
            h.dgam[a] = b->dgam[i + a * LD];
            h.taulm[a] = b->taulm[i + a * LD];
            h.ddtddp[a] = b->ddtddp[i + a * LD];
            h.dslip[a] = b->dslip[i + a * LD];
            for (c = 0; c < nfdir; c++) {
                h.ddtddg[a + c * nfdir] = b->ddtddg[i + (a + c * nfdir) * LD];
            }
        }
        for (a = 0; a < NSTATV; a++) {
            h.statev[a] = b->statev[i + a * LD];
        }
        fh_call(&h); /* guard slots and inputs checked unchanged */
        if (h.pnewdt < pnewdt) {
            pnewdt = h.pnewdt;
        }
        b->lm[i] = h.lm;
        b->sed[i] = h.sed;
        b->sfd[i] = h.sfd;
        for (a = 0; a < nfdir; a++) {
            b->tau[i + a * LD] = h.tau[a];
            b->ddtddp[i + a * LD] = h.ddtddp[a];
            b->dslip[i + a * LD] = h.dslip[a];
            for (c = 0; c < nfdir; c++) {
                b->ddtddg[i + (a + c * nfdir) * LD] = h.ddtddg[a + c * nfdir];
            }
        }
        for (a = 0; a < NSTATV; a++) {
            b->statev[i + a * LD] = h.statev[a];
        }
    }
    return pnewdt;
}

static enum IflStatus batch_call(batch_t *b, int nfdir, const double *props, int nprops,
                                 double dtime, double *pnewdt)
{
    return ifl_fric_batch(NP, LD, nfdir, props, nprops, NSTATV, dtime, b->lm, b->tau, b->ddtddg,
                          b->ddtddp, b->dslip, b->sed, b->sfd, b->statev, b->dgam, b->taulm,
                          b->press, b->dpress, b->chr, pnewdt);
}

static batch_t in, want, got;

int main(void)
{
    static const double elastic[7] = {1.0, 0.3, 0.0, 0.0, 1e-3, 0.0, 0.0};
    static const double exact[7] = {1.0, 0.3, 0.0, 0.0, 1e-3, 0.0, 1.0};
    static const double capped[7] = {1.0, 0.4, 0.0, 25.0, 0.0, 0.01, 0.0};
    const double *variants[3] = {elastic, exact, capped};
    int v, nfdir, i;
    for (v = 0; v < 3; v++) {
        for (nfdir = 1; nfdir <= 2; nfdir++) {
            double pw, pb = FH_PNEWDT_IN;
            fh_context("PROPS variant %d, NFDIR = %d", v, nfdir);
            random_batch(&in, nfdir, 2e-3);
            want = in;
            got = in;
            pw = per_point(&want, nfdir, variants[v], 7, 0.1);
            FH_CHECK(batch_call(&got, nfdir, variants[v], 7, 0.1, &pb) == IFL_STATUS_OK);
            FH_CHECK(pw == FH_PNEWDT_IN && pb == FH_PNEWDT_IN);
            /* Bit for bit, padding included (never written by either). */
            FH_CHECK(memcmp(&want, &got, sizeof want) == 0);
        }
    }

    /* Bad input at two points: fric_'s failure outputs there, the rest computed. */
    fh_context("NaN DGAM at point 3, infinite PRESS at point 99");
    random_batch(&in, 2, 1e-3);
    in.lm[3] = 0;
    in.dgam[3] = NAN;
    in.lm[99] = 0;
    in.press[99] = INFINITY;
    want = in;
    got = in;
    {
        double pw = per_point(&want, 2, elastic, 7, 0.1), pb = FH_PNEWDT_IN;
        ifl_clear_error();
        FH_CHECK(batch_call(&got, 2, elastic, 7, 0.1, &pb) == IFL_STATUS_BAD_INPUT);
        FH_EXACT(pw, FH_CUTBACK);
        FH_EXACT(pb, FH_CUTBACK);
        /* memcmp would also compare the NaN input bit patterns: equal, both untouched. */
        FH_CHECK(memcmp(&want, &got, sizeof want) == 0);
        FH_CONTAINS(ifl_last_error(), "ifl_fric_batch");
        FH_CONTAINS(ifl_last_error(), "batch point 99");
    }
    /* A fault of the whole batch: refused, nothing written but PNEWDT. */
    fh_context("NFDIR = 3");
    random_batch(&in, 2, 2e-3);
    got = in;
    {
        double pb = FH_PNEWDT_IN;
        FH_CHECK(batch_call(&got, 3, elastic, 7, 0.1, &pb) == IFL_STATUS_BAD_PARAMETER);
        FH_EXACT(pb, FH_CUTBACK);
        FH_CHECK(memcmp(&in, &got, sizeof in) == 0);
    }
    /* A stick point and a slip point keep their closed forms: τ = k_s·Δγ, |τ| = μp. */
    fh_context("closed forms through the batch");
    random_batch(&in, 1, 1e-3);
    for (i = 0; i < 2; i++) {
        in.lm[i] = 0;
        in.press[i] = 100.0;
        in.dpress[i] = 0.0;
        in.tau[i] = 0.0;
        in.statev[i + 2 * LD] = 0.0;
    }
    in.dgam[0] = 5e-4; /* k_s = 30/1e-3: τ = 15 */
    in.dgam[1] = 5e-3; /* slip: τ = μp = 30 */
    {
        double pb = FH_PNEWDT_IN;
        FH_CHECK(batch_call(&in, 1, elastic, 7, 0.1, &pb) == IFL_STATUS_OK);
        FH_NEAR(in.tau[0], 15.0, 1e-14, 0.0);
        FH_NEAR(in.ddtddg[0], 3e4, 1e-14, 0.0);
        FH_EXACT(in.tau[1], 30.0);
        FH_NEAR(in.sfd[1], 30.0 * 4e-3, 1e-14, 0.0);
    }
    /* Every point at first contact, NFDIR = 2 (as the Fortran twin): odd points (1-based)
     * stick with |dgam| = 0.5 gc, tau = k_s dgam and DDTDDG = k_s I; even points slip with
     * |dgam| = 3 gc, |tau| = mu p along dgam, SFD = mu p (3 gc - gc). */
    fh_context("closed forms at every point, NFDIR = 2");
    random_batch(&in, 2, 1e-3);
    for (i = 0; i < NP; i++) {
        const int sticks = i % 2 == 0;
        in.lm[i] = 0;
        in.press[i] = 100.0;
        in.dpress[i] = 0.0;
        in.tau[i] = in.tau[i + LD] = 0.0;
        in.statev[i] = in.statev[i + LD] = in.statev[i + 2 * LD] = 0.0;
        in.dgam[i] = (sticks ? 0.3 : 1.8) * 1e-3;
        in.dgam[i + LD] = (sticks ? -0.4 : 2.4) * 1e-3;
    }
    {
        const double ks = 0.3 * 100.0 / 1e-3;
        double pb = FH_PNEWDT_IN;
        FH_CHECK(batch_call(&in, 2, elastic, 7, 0.1, &pb) == IFL_STATUS_OK);
        for (i = 0; i < NP; i++) {
            const double t1 = in.tau[i], t2 = in.tau[i + LD];
            const double g1 = in.dgam[i], g2 = in.dgam[i + LD];
            if (i % 2 == 0) {
                FH_NEAR(t1, ks * g1, 1e-12, 0.0);
                FH_NEAR(t2, ks * g2, 1e-12, 0.0);
                FH_NEAR(in.ddtddg[i], ks, 1e-12, 0.0);
                FH_EXACT(in.ddtddg[i + LD], 0.0);
                FH_EXACT(in.ddtddg[i + 2 * LD], 0.0);
                FH_NEAR(in.ddtddg[i + 3 * LD], ks, 1e-12, 0.0);
            } else {
                FH_NEAR(hypot(t1, t2), 30.0, 1e-12, 0.0);
                FH_NEAR(t1 * g2 - t2 * g1, 0.0, 0.0, 1e-12 * 30.0 * 1e-3);
                FH_NEAR(in.sfd[i], 30.0 * 2e-3, 1e-12, 0.0);
            }
        }
    }
    return fh_finish();
}
