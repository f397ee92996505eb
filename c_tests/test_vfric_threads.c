/*
 * vfric_ (Abaqus/Explicit VFRIC, double-precision build: the friction force of a block of
 * contact points) from 8 threads at once, compared bit for bit with a serial run of the same
 * blocks (docs/threads-and-sanitizers.md, docs/vfric.md).
 *
 * 16 384 blocks of 1..127 contact points (nContact = 1 + b mod 127): 1 048 513 point
 * evaluations per run. Every block has its own interaction (name "VF<b>"), nFricDir (1 or 2)
 * and law-1 PROPS drawn from a Lehmer generator (x <- 48271 x mod 2^31 - 1) seeded by the
 * block's index, so a block's call does not depend on which thread makes it or when. Seven
 * kinds of block:
 *   0 plain Coulomb (no shear limit), 1 with τ_max (the cap τ_max·areaSlv(jConSlvid(k))),
 *   2 rough friction (PROPS(7) = 2, τ_max set but not used), 3 exact stick (PROPS(7) = 1) with
 *   τ_max, 4 τ_max and one to three bad points (fNormal NaN, fStickForce < 0, jConSlvid outside
 *   1..nSlvNod), 5 a refused call (μ < 0, the adhesive law, or the extended law 1),
 *   6 nFricDir = 3 (refused, nothing written).
 * Normal forces in [-20, 300] (some in tension), stick forces in [0, 100], areas in [0.1, 2]
 * on 1..64 slave nodes. Every array is its own heap block of exactly the declared size
 * (fTangential(nFricDir,nContact), statev(2,nContact), ...), so an out-of-bounds access is an
 * AddressSanitizer report in scripts/test-sanitizers.sh.
 *
 * Compared with the serial run: every fTangential entry of every block byte by byte and the
 * block's message (ifl_last_error of the calling thread, empty when none), folded into a 64-bit
 * FNV-1a digest per block; the 16 384 digests compared with memcmp; the counts of each kind.
 * Checked on every block of both runs, against docs/vfric.md rather than the library:
 *   fTangential(1,k) = -min(μ·F_N, τ_max·A, F_stick) exactly (0 for F_N < 0, -F_stick when
 *   rough), fTangential(2,k) = +0; a bad point 0 and the message naming VFRIC, the block's
 *   interaction and the last bad point; a refused call 0 everywhere (nothing written for
 *   nFricDir = 3) and a message naming VFRIC and the interaction; statev untouched; no message
 *   for a good block.
 *
 * INTERFACIAL_TEST_SHRINK=n divides the number of blocks by n (valgrind, ASan runs).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "interfacial.h"
#include "thread_harness.h"

enum { FULL_BLOCKS = 16384, MAX_NCONTACT = 127, MIN_BLOCKS = 512, NPROPS = 7 };
enum { MAX_SLAVES = 64, NSTATEV = 2, UNREAD = 3 * 3 * MAX_NCONTACT };
enum { N_KINDS = 7, KIND_BAD_POINTS = 4, KIND_REFUSED = 5, KIND_NFRICDIR = 6 };
static const char *const KIND_NAMES[N_KINDS] = {
    "plain", "tau_max", "rough", "exact stick", "bad points", "refused", "nFricDir 3"};

static void violation(th_tally *t, int block, const char *what, double got, double want)
{
    th_violation(t, "block %d: %s: got %.17g, expected %.17g", block, what, got, want);
}

/* One block's law and inputs, all drawn from the block's own generator. */
typedef struct {
    int kind, n, nf, nslv, last_bad;
    double props[NPROPS];
    double *normal, *stick, *area;
    int *slave;
    char *bad; /* bad[k]: point k is bad (kind 4) */
} block_in;

static int draw_block(int b, block_in *in)
{
    uint32_t x = th_block_seed(b);
    int k, kind, nbad;
    kind = (int)(th_lehmer(&x) % N_KINDS);
    in->kind = kind;
    in->n = 1 + b % MAX_NCONTACT;
    in->nf = kind == KIND_NFRICDIR ? 3 : 1 + (int)(th_lehmer(&x) % 2);
    in->nslv = 1 + (int)(th_lehmer(&x) % MAX_SLAVES);
    in->last_bad = -1;
    memset(in->props, 0, sizeof in->props);
    in->props[0] = 1.0;
    in->props[1] = th_uniform(&x, 0.05, 0.9);
    if (kind != 0) {
        in->props[3] = th_uniform(&x, 1.0, 50.0);
    }
    if (kind == 2) {
        in->props[6] = 2.0;
    } else if (kind == 3) {
        in->props[6] = 1.0;
    }
    in->normal = malloc(sizeof(double) * (size_t)in->n);
    in->stick = malloc(sizeof(double) * (size_t)in->n);
    in->slave = malloc(sizeof(int) * (size_t)in->n);
    in->bad = calloc((size_t)in->n, 1);
    in->area = malloc(sizeof(double) * (size_t)in->nslv);
    if (in->normal == NULL || in->stick == NULL || in->slave == NULL || in->bad == NULL ||
        in->area == NULL) {
        return 0;
    }
    for (k = 0; k < in->nslv; k++) {
        in->area[k] = th_uniform(&x, 0.1, 2.0);
    }
    for (k = 0; k < in->n; k++) {
        in->normal[k] = th_uniform(&x, -20.0, 300.0);
        in->stick[k] = th_uniform(&x, 0.0, 100.0);
        in->slave[k] = 1 + (int)(th_lehmer(&x) % (uint32_t)in->nslv);
    }
    if (kind == KIND_BAD_POINTS) {
        for (nbad = 1 + (int)(th_lehmer(&x) % 3); nbad > 0; nbad--) {
            k = (int)(th_lehmer(&x) % (uint32_t)in->n);
            switch (th_lehmer(&x) % 3) {
            case 0:
                in->normal[k] = NAN;
                break;
            case 1:
                in->stick[k] = -th_uniform(&x, 0.1, 1.0);
                break;
            default:
                in->slave[k] = in->nslv + 1;
                break;
            }
            in->bad[k] = 1;
            if (k > in->last_bad) {
                in->last_bad = k;
            }
        }
    }
    if (kind == KIND_REFUSED) {
        switch (th_lehmer(&x) % 3) {
        case 0:
            in->props[1] = -in->props[1]; /* μ < 0 */
            break;
        case 1:
            in->props[0] = 2.0; /* adhesive */
            break;
        default:
            in->props[2] = in->props[1] * 2.0; /* μ₂ ≠ μ: the extended law 1 */
            break;
        }
    }
    return 1;
}

static void free_block(block_in *in)
{
    free(in->normal);
    free(in->stick);
    free(in->slave);
    free(in->bad);
    free(in->area);
}

/* F of docs/vfric.md: min(μ F_N, τ_max A, F_stick), 0 for F_N < 0, F_stick when rough. */
static double closed_form(const block_in *in, int k)
{
    const double *p = in->props;
    double f;
    if (p[6] == 2.0) {
        return in->stick[k];
    }
    if (in->normal[k] < 0.0) {
        return 0.0;
    }
    f = p[1] * in->normal[k];
    if (p[3] > 0.0) {
        f = fmin(f, p[3] * in->area[in->slave[k] - 1]);
    }
    return fmin(f, in->stick[k]);
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Calls vfric_ for block b and checks it; returns the digest of its outputs and message. */
static uint64_t run_block(int b, th_tally *t)
{
    block_in in;
    int n, nf, k, one = 1, two = NSTATEV, four = 4, nprops = NPROPS, ndir, ints[4] = {1, 1, 1, 1};
    double *ftan, *statev, *unread;
    char name[80], blank[80], want[48];
    const char *msg;
    uint64_t h = TH_FNV_OFFSET;

    memset(&in, 0, sizeof in);
    k = draw_block(b, &in);
    n = in.n;
    nf = in.nf;
    ndir = nf + 1;
    ftan = k ? th_filled((size_t)(nf * n), FH_GUARD) : NULL;
    statev = k ? th_filled(NSTATEV * (size_t)n, 0.0) : NULL;
    unread = k ? th_filled(UNREAD, 1.0) : NULL;
    if (ftan == NULL || statev == NULL || unread == NULL) {
        t->alloc_fail++;
        free(ftan);
        free(statev);
        free(unread);
        free_block(&in);
        return 0;
    }
    for (k = 0; k < NSTATEV * n; k++) {
        statev[k] = 0.5 * k;
    }
    th_block_names(name, blank, "VF", b);
    vfric_(ftan, statev, &one, &one, &n, &four, &in.nslv, &four, &nf, &ndir, &two, &nprops, &one,
           &one, &one, ints, ints, in.slave, ints, unread, unread, unread, name, blank, blank,
           ints, unread, in.stick, unread, in.normal, unread, unread, unread, unread, unread,
           unread, in.props, in.area, unread, unread, unread, unread, sizeof name, sizeof blank,
           sizeof blank);
    msg = ifl_last_error();
    t->kinds[in.kind]++;
    t->points += n;
    h = th_fnv(h, ftan, sizeof(double) * (size_t)(nf * n));
    h = th_fnv(h, msg, strlen(msg) + 1);

    for (k = 0; k < NSTATEV * n; k++) {
        if (statev[k] != 0.5 * k) {
            violation(t, b, "statev written", statev[k], 0.5 * k);
        }
    }
    snprintf(want, sizeof want, "interfacial: VFRIC: interaction 'VF%d'", b);
    if (in.kind == KIND_REFUSED || in.kind == KIND_NFRICDIR) {
        if (strstr(msg, want) != msg || strstr(msg, "(block)") == NULL) {
            violation(t, b, "refusal message lacks VFRIC, the interaction or (block)", 0.0, 0.0);
        }
        for (k = 0; k < nf * n; k++) {
            double w = in.kind == KIND_NFRICDIR ? FH_GUARD : 0.0;
            if (!same_bits(ftan[k], w)) {
                violation(t, b, "refused call: fTangential", ftan[k], w);
            }
        }
    } else {
        for (k = 0; k < n; k++) {
            double w = in.bad[k] ? 0.0 : 0.0 - closed_form(&in, k);
            if (!same_bits(ftan[k * nf], w)) {
                violation(t, b, "fTangential(1,k)", ftan[k * nf], w);
            }
            if (!in.bad[k] && !(ftan[k * nf] >= -in.stick[k] && ftan[k * nf] <= 0.0)) {
                violation(t, b, "fTangential(1,k) outside [-fStickForce, 0]", ftan[k * nf],
                          -in.stick[k]);
            }
            if (nf == 2 && !same_bits(ftan[k * nf + 1], 0.0)) {
                violation(t, b, "fTangential(2,k) not +0", ftan[k * nf + 1], 0.0);
            }
            t->bad_points += in.bad[k];
        }
        if (in.kind == KIND_BAD_POINTS) {
            char point[32];
            snprintf(point, sizeof point, "(contact point %d)", in.last_bad + 1);
            if (strstr(msg, want) != msg || strstr(msg, point) == NULL) {
                violation(t, b, "bad-point message lacks VFRIC, the interaction or the point",
                          in.last_bad + 1, 0.0);
            }
        } else if (msg[0] != '\0') {
            violation(t, b, "a good block left a message", 0.0, 0.0);
        }
    }
    free(ftan);
    free(statev);
    free(unread);
    free_block(&in);
    return h;
}

static void report_tally(const char *run, const th_tally *t)
{
    th_report(run, t, KIND_NAMES, N_KINDS, " blocks", "%ld point evaluations (%ld bad points)",
              t->points, t->bad_points);
}

int main(void)
{
    int shrink = th_shrink_factor(FULL_BLOCKS / MIN_BLOCKS), blocks = FULL_BLOCKS / shrink;
    th_tally par, ser;

    if (th_block_runs(blocks, shrink, run_block, report_tally, KIND_NAMES, N_KINDS, &par, &ser)) {
        fh_context("bad points");
        FH_CHECK(par.bad_points >= blocks / (2 * N_KINDS));
    }
    return fh_finish();
}
