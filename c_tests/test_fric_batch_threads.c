/*
 * ifl_fric_batch from 8 threads at once, compared bit for bit with a serial run.
 *
 * The same 4096 points (NFDIR 2, ld = 4096 + 8 padding) are updated by every thread: each
 * thread owns a copy of the in/out arrays (LM, TAU, STATEV and the outputs) and runs 32
 * increments of one batch call each, carrying the state, with inputs (DGAM, PRESS, DPRESS,
 * CHRLNGTH) that depend only on the point and the increment (Lehmer generator seeded by both).
 * 8 threads x 32 increments x 4096 points = 1 048 576 point updates; then the main thread runs
 * the same 32 batches serially. Compared with memcmp: every output array of every increment
 * (folded into one 64-bit FNV-1a digest per thread and increment: LM, TAU, DDTDDG, DDTDDP,
 * DSLIP, SED, SFD, STATEV, PNEWDT, status), and the final arrays, padding included (the padding
 * must keep its fill value). Points with a NaN in DGAM (1 in 509) fail; the others still run
 * (status IFL_STATUS_BAD_INPUT, PNEWDT = 0.25). Checked against the law on the serial run:
 * |tau| <= mu p (1 + 1e-12), SED, SFD >= 0.
 *
 * INTERFACIAL_TEST_SHRINK=n divides the number of points by n.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "thread_harness.h"

enum { FULL_POINTS = 4096, PAD = 8, INCS = 32, NF = 2, NSTATV = 3 };
#define FILL (-3.25e33)
#define MU 0.3

static const double PROPS[5] = {1.0, MU, 0.0, 0.0, 1e-3};

static int points, ld;
/* Inputs, shared read-only by every thread: [inc][component][ld]. */
static double *dgam_all, *press_all, *dpress_all, *chrl_all;

typedef struct {
    int *lm;
    double *tau, *ddtddg, *ddtddp, *dslip, *sed, *sfd, *statev;
    uint64_t digest[INCS];
    int failed_alloc;
    int check_law; /* serial run: check every point of every increment against the law */
    long bad_law, checked;
} run;

static double *filled(size_t n)
{
    double *p = malloc(n * sizeof(double));
    size_t i;
    for (i = 0; p != NULL && i < n; i++) {
        p[i] = FILL;
    }
    return p;
}

static void run_init(run *r)
{
    size_t l1 = (size_t)ld, ln = (size_t)ld * NF, lnn = (size_t)ld * NF * NF;
    int i;
    memset(r, 0, sizeof *r);
    r->lm = calloc(l1, sizeof(int));
    r->tau = filled(ln);
    r->ddtddg = filled(lnn);
    r->ddtddp = filled(ln);
    r->dslip = filled(ln);
    r->sed = filled(l1);
    r->sfd = filled(l1);
    r->statev = filled((size_t)ld * NSTATV);
    r->failed_alloc = !r->lm || !r->tau || !r->ddtddg || !r->ddtddp || !r->dslip || !r->sed ||
                      !r->sfd || !r->statev;
    for (i = 0; !r->failed_alloc && i < points; i++) {
        r->tau[i] = r->tau[i + ld] = 0.0;
        r->statev[i] = r->statev[i + ld] = r->statev[i + 2 * ld] = 0.0;
    }
}

static void run_free(run *r)
{
    free(r->lm), free(r->tau), free(r->ddtddg), free(r->ddtddp), free(r->dslip);
    free(r->sed), free(r->sfd), free(r->statev);
}

/* Whether increment inc has a NaN in DGAM at some point. */
static int nan_in(int inc)
{
    int i;
    for (i = 0; i < points; i++) {
        if (isnan(dgam_all[(size_t)inc * ld * NF + (size_t)i])) {
            return 1;
        }
    }
    return 0;
}

static void run_all(run *r)
{
    int inc;
    for (inc = 0; inc < INCS && !r->failed_alloc; inc++) {
        size_t off = (size_t)inc * ld;
        double pnewdt = 1e36;
        int status = ifl_fric_batch((size_t)points, (size_t)ld, NF, PROPS, 5, NSTATV, 0.01,
                                    r->lm, r->tau, r->ddtddg, r->ddtddp, r->dslip, r->sed,
                                    r->sfd, r->statev, dgam_all + off * NF, NULL,
                                    press_all + off, dpress_all + off, chrl_all + off, &pnewdt);
        uint64_t h = TH_FNV_OFFSET;
        h = th_fnv(h, r->lm, (size_t)ld * sizeof(int));
        h = th_fnv(h, r->tau, (size_t)ld * NF * sizeof(double));
        h = th_fnv(h, r->ddtddg, (size_t)ld * NF * NF * sizeof(double));
        h = th_fnv(h, r->ddtddp, (size_t)ld * NF * sizeof(double));
        h = th_fnv(h, r->dslip, (size_t)ld * NF * sizeof(double));
        h = th_fnv(h, r->sed, (size_t)ld * sizeof(double));
        h = th_fnv(h, r->sfd, (size_t)ld * sizeof(double));
        h = th_fnv(h, r->statev, (size_t)ld * NSTATV * sizeof(double));
        h = th_fnv(h, &pnewdt, sizeof pnewdt);
        r->digest[inc] = th_fnv(h, &status, sizeof status);
        if (r->check_law) {
            int i;
            for (i = 0; i < points; i++) {
                double tau = hypot(r->tau[i], r->tau[i + ld]), p = press_all[off + (size_t)i];
                if (isnan(dgam_all[off * NF + (size_t)i])) {
                    continue; /* refused: state kept */
                }
                r->checked++;
                if (tau > MU * p * (1.0 + 1e-12) || r->sed[i] < 0.0 || r->sfd[i] < 0.0) {
                    r->bad_law++;
                }
            }
            if (status != (nan_in(inc) ? IFL_STATUS_BAD_INPUT : IFL_STATUS_OK) ||
                pnewdt != (nan_in(inc) ? 0.25 : 1e36)) {
                r->bad_law++;
            }
        }
    }
}

/* Runs [first, last) of the array ctx, each all INCS batches (one run per thread). */
static void run_range(int first, int last, void *ctx, th_tally *t)
{
    run *runs = ctx;
    int i;
    (void)t;
    for (i = first; i < last; i++) {
        run_all(&runs[i]);
    }
}

static int same(const run *a, const run *b)
{
    size_t l1 = (size_t)ld, ln = l1 * NF;
    return memcmp(a->digest, b->digest, sizeof a->digest) == 0 &&
           memcmp(a->lm, b->lm, l1 * sizeof(int)) == 0 &&
           memcmp(a->tau, b->tau, ln * sizeof(double)) == 0 &&
           memcmp(a->ddtddg, b->ddtddg, ln * NF * sizeof(double)) == 0 &&
           memcmp(a->ddtddp, b->ddtddp, ln * sizeof(double)) == 0 &&
           memcmp(a->dslip, b->dslip, ln * sizeof(double)) == 0 &&
           memcmp(a->sed, b->sed, l1 * sizeof(double)) == 0 &&
           memcmp(a->sfd, b->sfd, l1 * sizeof(double)) == 0 &&
           memcmp(a->statev, b->statev, l1 * NSTATV * sizeof(double)) == 0;
}

int main(void)
{
    run par[TH_THREADS], ser;
    th_tally unused;
    int i, inc, nan_points = 0, slipping = 0, bad_law = 0, padding_ok = 1;

    points = FULL_POINTS / th_shrink_factor(64);
    ld = points + PAD;
    fh_context("inputs");
    dgam_all = filled((size_t)INCS * ld * NF);
    press_all = filled((size_t)INCS * ld);
    dpress_all = filled((size_t)INCS * ld);
    chrl_all = filled((size_t)INCS * ld);
    if (!FH_CHECK(dgam_all && press_all && dpress_all && chrl_all)) {
        return fh_finish();
    }
    for (inc = 0; inc < INCS; inc++) {
        for (i = 0; i < points; i++) {
            uint32_t x = 1u + (uint32_t)(i * INCS + inc);
            size_t k = (size_t)inc * ld + (size_t)i;
            double amp = i % 4 == 0 ? 5e-4 : 5e-3; /* a quarter of the points mostly stick */
            th_lehmer(&x);
            dgam_all[(size_t)inc * ld * NF + (size_t)i] = th_uniform(&x, -amp, amp);
            dgam_all[(size_t)inc * ld * NF + (size_t)ld + (size_t)i] = th_uniform(&x, -amp, amp);
            if (th_lehmer(&x) % 509u == 0) {
                dgam_all[(size_t)inc * ld * NF + (size_t)i] = NAN;
                nan_points++;
            }
            press_all[k] = th_uniform(&x, 10.0, 100.0);
            dpress_all[k] = th_uniform(&x, -1.0, 1.0);
            chrl_all[k] = 1.0;
        }
    }

    fh_context("%d threads x %d batches of %d points", TH_THREADS, INCS, points);
    for (i = 0; i < TH_THREADS; i++) {
        run_init(&par[i]);
        FH_CHECK(!par[i].failed_alloc);
    }
    memset(&unused, 0, sizeof unused);
    if (!FH_CHECK(th_run_threads(TH_THREADS, run_range, par, &unused))) {
        return fh_finish();
    }

    fh_context("serial run");
    run_init(&ser);
    ser.check_law = 1;
    FH_CHECK(!ser.failed_alloc);
    run_all(&ser);
    for (i = 0; i < points; i++) {
        slipping += ser.statev[i + 2 * ld] == 1.0;
    }
    bad_law = (int)ser.bad_law;
    for (i = points; i < ld; i++) {
        padding_ok = padding_ok && ser.tau[i] == FILL && ser.statev[i] == FILL &&
                     ser.ddtddg[i + 3 * ld] == FILL && ser.sed[i] == FILL;
    }
    printf("%d threads x %d batches x %d points = %ld point updates; %d NaN inputs; %d points "
           "slipping at the end\n",
           TH_THREADS, INCS, points, (long)TH_THREADS * INCS * points, nan_points, slipping);
    FH_CHECK(bad_law == 0);
    FH_CHECK(ser.checked > (long)INCS * points * 9 / 10);
    FH_CHECK(padding_ok);
    FH_CHECK(nan_points > 0);
    FH_CHECK(slipping > 0 && slipping < points);

    fh_context("bit for bit against the serial run");
    for (i = 0; i < TH_THREADS; i++) {
        FH_CHECK(same(&par[i], &ser));
        run_free(&par[i]);
    }
    run_free(&ser);
    free(dgam_all), free(press_all), free(dpress_all), free(chrl_all);
    return fh_finish();
}
