/*
 * ns per call of ifl_pore_pressure (closed contact, transient, small sliding, (h, pbar, phat,
 * qhat) basis) against the hand-written C version of the same form (pore_pressure_ref.c), in
 * the same run. NP distinct points, NREP sweeps per timed run, best of NRUN runs reported; the
 * two must agree bit for bit first. A benchmark, not a test: figures go to docs/pore-pressure.md.
 *
 * Usage: bench_pore_pressure [NREP [NRUN]]   (defaults 2000, 15)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "interfacial.h"

int ref_pore_pressure_closed_small(double p1, double p2, double q_hat, double h, double dh,
                                   double dt, double residual[4], double tangent[16],
                                   double geometric[4]);

enum { NP = 1024 };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double p1[NP], p2[NP], qh[NP], hh[NP], dh[NP];
static double res[4], tng[16], geo[4];

static double run_library(int nrep, double dt, double *sink)
{
    IflPorePressureVariant v = {0, 0, 0, 0};
    double acc = 0.0, t0 = now();
    for (int r = 0; r < nrep; r++) {
        for (int i = 0; i < NP; i++) {
            ifl_pore_pressure(NULL, v, p1[i], p2[i], qh[i], hh[i], dh[i], dt, res, tng, geo);
            acc += res[0] + res[3];
        }
    }
    *sink += acc;
    return (now() - t0) / ((double)nrep * NP) * 1e9;
}

static double run_reference(int nrep, double dt, double *sink)
{
    double acc = 0.0, t0 = now();
    for (int r = 0; r < nrep; r++) {
        for (int i = 0; i < NP; i++) {
            ref_pore_pressure_closed_small(p1[i], p2[i], qh[i], hh[i], dh[i], dt, res, tng, geo);
            acc += res[0] + res[3];
        }
    }
    *sink += acc;
    return (now() - t0) / ((double)nrep * NP) * 1e9;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    int nrep = argc > 1 ? atoi(argv[1]) : 2000;
    int nrun = argc > 2 ? atoi(argv[2]) : 15;
    if (nrep < 1 || nrun < 1 || nrun > 1000) {
        fprintf(stderr, "usage: bench_pore_pressure [NREP [NRUN]]\n");
        return 2;
    }
    srand(12345);
    for (int i = 0; i < NP; i++) {
        p1[i] = 100.0 * rand() / RAND_MAX;
        p2[i] = 100.0 * rand() / RAND_MAX;
        qh[i] = 1e-3 * (rand() / (double)RAND_MAX - 0.5);
        hh[i] = 0.0;
        dh[i] = 0.0;
    }
    double dt = 0.01;
    /* Bit-for-bit agreement before timing. */
    IflPorePressureVariant v = {0, 0, 0, 0};
    for (int i = 0; i < NP; i++) {
        double r1[4], t1[16], g1[4], r2[4], t2[16], g2[4];
        int a = ifl_pore_pressure(NULL, v, p1[i], p2[i], qh[i], hh[i], dh[i], dt, r1, t1, g1);
        int b = ref_pore_pressure_closed_small(p1[i], p2[i], qh[i], hh[i], dh[i], dt, r2, t2, g2);
        if (a != b || memcmp(r1, r2, sizeof r1) || memcmp(t1, t2, sizeof t1) ||
            memcmp(g1, g2, sizeof g1)) {
            fprintf(stderr, "bench_pore_pressure: library and reference differ at point %d\n", i);
            return 1;
        }
    }
    double lib[1000], ref[1000], ratio[1000], sink = 0.0;
    for (int k = 0; k < nrun; k++) {
        /* Alternate the order so that neither side always runs warm. */
        if (k % 2 == 0) {
            lib[k] = run_library(nrep, dt, &sink);
            ref[k] = run_reference(nrep, dt, &sink);
        } else {
            ref[k] = run_reference(nrep, dt, &sink);
            lib[k] = run_library(nrep, dt, &sink);
        }
        ratio[k] = lib[k] / ref[k];
    }
    qsort(lib, (size_t)nrun, sizeof lib[0], cmp);
    qsort(ref, (size_t)nrun, sizeof ref[0], cmp);
    qsort(ratio, (size_t)nrun, sizeof ratio[0], cmp);
    printf("points %d, sweeps %d, runs %d (checksum %.6e)\n", NP, nrep, nrun, sink);
    printf("ifl_pore_pressure      best %6.2f ns/call, median %6.2f\n", lib[0], lib[nrun / 2]);
    printf("hand-written C         best %6.2f ns/call, median %6.2f\n", ref[0], ref[nrun / 2]);
    printf("ratio library / C      best-to-best %.3f, median of per-run ratios %.3f\n",
           lib[0] / ref[0], ratio[nrun / 2]);
    return 0;
}
