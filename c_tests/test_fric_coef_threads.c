/*
 * fric_coef_ (Abaqus FRIC_COEF: the friction coefficient of a block of points and its
 * derivatives) from 8 threads at once, compared bit for bit with a serial run of the same
 * blocks (docs/threads-and-sanitizers.md).
 *
 * 16 384 blocks of 1..127 points (nBlock = 1 + b mod 127): 1 048 513 point evaluations per run.
 * Every block has its own interaction (name "CF<b>") and its own law-1 PROPS drawn from a
 * Lehmer generator (x <- 48271 x mod 2^31 - 1) seeded by the block's index, so a block's call
 * does not depend on which thread makes it or when. Eight μ laws (docs/props.md):
 *   0 constant isotropic, 1 constant anisotropic (PROPS(3)), 2 exponential decay (PROPS(8..10),
 *   μ_k below or above μ_s), 3 decay + pressure (PROPS(11)), 4 decay + temperature
 *   (PROPS(12..13), nTemp = 1), 5 pressure + temperature, anisotropic, 6 all of them,
 *   7 a block with one bad point (NaN pressure or a negative slip rate): refused.
 * Slip rates in [0, 5] (one in eight exactly 0), pressures in [-20, 300] (some negative),
 * temperatures in [0, 200]. Every array is its own heap block of exactly the declared size
 * (fCoef(nBlock,2), fCoefDeriv(nBlock,20,2), slipData(nBlock,6), ...), so an out-of-bounds
 * access is an AddressSanitizer report in scripts/test-sanitizers.sh.
 *
 * Compared with the serial run: every output of every block (2 nBlock + 40 nBlock doubles),
 * byte by byte, folded into a 64-bit FNV-1a digest per block; the 16 384 digests compared with
 * memcmp; the counts of each kind of block. Checked on every block of both runs, against the
 * closed form rather than the library:
 *   μ_d = (μ_s,d e + μ_k,d (1 - e)) / (1 + p+/p_ref) · exp(-b (θ - θ_ref)), e = exp(-d_c γ̇),
 *   μ_k,2 = μ_k μ₂/μ₁, to 1e-13 relative; ∂μ/∂γ̇ = -d_c (μ_s - μ_k) e π Θ for the decay law
 *   (to 1e-12 of d_c μ_s); ∂μ/∂p = 0 for p < 0 and without p_ref; fCoefDeriv(k,4..20,d) = 0;
 *   refused blocks: μ = 0 and every derivative 0, and this thread's ifl_last_error names
 *   FRIC_COEF and the block's interaction.
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

enum { FULL_BLOCKS = 16384, MAX_NBLOCK = 127, MIN_BLOCKS = 512, NPROPS = 13 };
enum { N_LAWS = 8, LAW_BAD = 7 };
static const char *const LAW_NAMES[N_LAWS] = {
    "constant", "anisotropic", "decay", "decay+pressure", "decay+temperature",
    "pressure+temperature anisotropic", "all", "refused"};

static void violation(th_tally *t, int block, const char *what, double got, double want)
{
    th_violation(t, "block %d: %s: got %.17g, expected %.17g", block, what, got, want);
}

/* One block's law and inputs, all drawn from the block's own generator. */
typedef struct {
    int law, n, ntemp;
    double props[NPROPS];
    double *slip, *pressure, *temp;
} block_in;

static int draw_block(int b, block_in *in)
{
    uint32_t x = th_block_seed(b);
    int k, law, decay, pref, temp;
    law = (int)(th_lehmer(&x) % N_LAWS);
    in->law = law;
    in->n = 1 + b % MAX_NBLOCK;
    memset(in->props, 0, sizeof in->props);
    in->props[0] = 1.0;
    in->props[1] = th_uniform(&x, 0.05, 0.9);
    if (law == 1 || law == 5 || law == 6) {
        in->props[2] = th_uniform(&x, 0.05, 0.9);
    }
    decay = law == 2 || law == 3 || law == 4 || law == 6 || law == LAW_BAD;
    pref = law == 3 || law == 5 || law == 6;
    temp = law == 4 || law == 5 || law == 6;
    if (decay) {
        in->props[7] = 1.0;
        /* μ_k below μ_s mostly (decay), above it now and then (strengthening). */
        in->props[8] = in->props[1] * th_uniform(&x, 0.0, th_lehmer(&x) % 4 == 0 ? 3.0 : 1.0);
        in->props[9] = th_uniform(&x, 0.1, 10.0);
    }
    if (pref) {
        in->props[10] = th_uniform(&x, 10.0, 500.0);
    }
    if (temp) {
        in->props[11] = th_uniform(&x, -0.01, 0.01);
        in->props[12] = th_uniform(&x, 0.0, 100.0);
    }
    in->ntemp = temp ? 1 : (int)(th_lehmer(&x) % 2);
    in->slip = malloc(sizeof(double) * 6 * (size_t)in->n);
    in->pressure = malloc(sizeof(double) * (size_t)in->n);
    in->temp = malloc(sizeof(double) * (size_t)in->n);
    if (in->slip == NULL || in->pressure == NULL || in->temp == NULL) {
        return 0;
    }
    for (k = 0; k < 6 * in->n; k++) {
        in->slip[k] = th_uniform(&x, 0.0, 5.0);
    }
    for (k = 0; k < in->n; k++) {
        if (th_lehmer(&x) % 8 == 0) {
            in->slip[k] = 0.0;
        }
        in->pressure[k] = th_uniform(&x, -20.0, 300.0);
        in->temp[k] = th_uniform(&x, 0.0, 200.0);
    }
    if (law == LAW_BAD) {
        k = (int)(th_lehmer(&x) % (uint32_t)in->n);
        if (th_lehmer(&x) % 2 == 0) {
            in->pressure[k] = NAN;
        } else {
            in->slip[k] = -th_uniform(&x, 0.1, 1.0);
        }
    }
    return 1;
}

static void free_block(block_in *in)
{
    free(in->slip);
    free(in->pressure);
    free(in->temp);
}

/* The closed form of docs/props.md, written without the library's factorisation. */
static void closed_form(const block_in *in, int k, double mu[2], double dmu_rate[2])
{
    const double *p = in->props;
    double mu1 = p[1], mu2 = p[2] != 0.0 ? p[2] : p[1], pp = fmax(in->pressure[k], 0.0);
    double e = 1.0, ome = 0.0, mk1 = 0.0, d = 0.0, pi = 1.0, th = 1.0, mk2;
    if (p[7] == 1.0) {
        d = p[9];
        e = exp(-d * in->slip[k]);
        ome = -expm1(-d * in->slip[k]);
        mk1 = p[8];
    }
    mk2 = mk1 * mu2 / mu1;
    if (p[10] > 0.0) {
        pi = 1.0 / (1.0 + pp / p[10]);
    }
    if (p[11] != 0.0) {
        th = exp(-p[11] * (in->temp[k] - p[12]));
    }
    mu[0] = (mu1 * e + mk1 * ome) * pi * th;
    mu[1] = (mu2 * e + mk2 * ome) * pi * th;
    dmu_rate[0] = -d * (mu1 - mk1) * e * pi * th;
    dmu_rate[1] = -d * (mu2 - mk2) * e * pi * th;
}

static const char *const FIELD_NAMES[3] = {"mu1", "mu2", "?"};

/* Calls fric_coef_ for block b and checks it; returns the digest of its outputs. */
static uint64_t run_block(int b, th_tally *t)
{
    block_in in;
    int n, nprops = NPROPS, nfields = 0, idata[3] = {1, 1, 1}, k, j, d;
    double rdata[3] = {0.0, 0.0, 0.0}, field[1] = {0.0};
    double *coef, *deriv;
    char name[80], blank[80];
    uint64_t h = TH_FNV_OFFSET;

    memset(&in, 0, sizeof in);
    k = draw_block(b, &in);
    n = in.n;
    coef = k ? th_filled(2 * (size_t)n, FH_GUARD) : NULL;
    deriv = k ? th_filled(40 * (size_t)n, FH_GUARD) : NULL;
    if (coef == NULL || deriv == NULL) {
        t->alloc_fail++;
        free(coef);
        free(deriv);
        free_block(&in);
        return 0;
    }
    th_block_names(name, blank, "CF", b);
    fric_coef_(coef, deriv, &n, &nprops, &in.ntemp, &nfields, idata, rdata, name, blank, blank,
               in.props, in.slip, in.pressure, in.temp, field, sizeof name, sizeof blank,
               sizeof blank);
    t->kinds[in.law]++;
    t->points += n;
    h = th_fnv(h, coef, sizeof(double) * 2 * (size_t)n);
    h = th_fnv(h, deriv, sizeof(double) * 40 * (size_t)n);

    if (in.law == LAW_BAD) {
        char want[32];
        const char *msg = ifl_last_error();
        snprintf(want, sizeof want, "'CF%d'", b);
        if (strstr(msg, "interfacial: FRIC_COEF: interaction") != msg || strstr(msg, want) == NULL) {
            violation(t, b, "refusal message lacks FRIC_COEF or the interaction", 0.0, 0.0);
        }
        for (k = 0; k < 2 * n; k++) {
            if (coef[k] != 0.0) {
                violation(t, b, "refused block: mu not 0", coef[k], 0.0);
            }
        }
        for (k = 0; k < 40 * n; k++) {
            if (deriv[k] != 0.0) {
                violation(t, b, "refused block: derivative not 0", deriv[k], 0.0);
            }
        }
    } else {
        for (k = 0; k < n; k++) {
            double mu[2], dr[2];
            closed_form(&in, k, mu, dr);
            for (d = 0; d < 2; d++) {
                double got = coef[k + n * d];
                double drate = deriv[k + n * (0 + 20 * d)];
                double dp = deriv[k + n * (1 + 20 * d)];
                double dt = deriv[k + n * (2 + 20 * d)];
                if (!(fabs(got - mu[d]) <= 1e-13 * mu[d])) {
                    violation(t, b, FIELD_NAMES[d], got, mu[d]);
                }
                if (!(fabs(drate - dr[d]) <= 1e-12 * in.props[9] * in.props[1] * 4.0)) {
                    violation(t, b, "d mu / d rate", drate, dr[d]);
                }
                if ((in.pressure[k] < 0.0 || in.props[10] == 0.0) && dp != 0.0) {
                    violation(t, b, "d mu / d p without a pressure law or for p < 0", dp, 0.0);
                }
                if (in.props[11] == 0.0 && dt != 0.0) {
                    violation(t, b, "d mu / d theta without a temperature law", dt, 0.0);
                }
                for (j = 3; j < 20; j++) {
                    if (deriv[k + n * (j + 20 * d)] != 0.0) {
                        violation(t, b, "fCoefDeriv(k,4..20,d) not 0", deriv[k + n * (j + 20 * d)],
                                  0.0);
                    }
                }
            }
        }
        if (ifl_last_error()[0] != '\0') {
            violation(t, b, "a good block left a message", 0.0, 0.0);
        }
    }
    free(coef);
    free(deriv);
    free_block(&in);
    return h;
}

static void report_tally(const char *run, const th_tally *t)
{
    th_report(run, t, LAW_NAMES, N_LAWS, " blocks", "%ld point evaluations", t->points);
}

int main(void)
{
    int shrink = th_shrink_factor(FULL_BLOCKS / MIN_BLOCKS), blocks = FULL_BLOCKS / shrink;
    th_tally par, ser;

    th_block_runs(blocks, shrink, run_block, report_tally, LAW_NAMES, N_LAWS, &par, &ser);
    return fh_finish();
}
