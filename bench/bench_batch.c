/*
 * Per-point throughput of ifl_fric_batch against fric_ called once per point, from C.
 *
 * NP distinct contact points (Coulomb, mu = 0.3, elastic stick, gamma_crit = 1e-3), all sticking
 * or all slipping, NFDIR 1 and 2. The fric_ side is a host loop over points kept the way an FE
 * code keeps them (one record per point) that copies TAU and STATEV into work arrays and makes
 * one CALL FRIC per point; the batch side copies TAU and STATEV into structure-of-arrays work
 * arrays and makes one ifl_fric_batch call for all points. NREP sweeps per timed run; the best
 * of NRUN runs is reported (ns per point), with the median ratio as a noise check. Before timing,
 * both paths must agree bit for bit.
 *
 * Usage: bench_batch [NREP [NRUN [CASE]]]   (defaults 200, 15, all cases)
 * CASE 1..4 runs one case only (NFDIR 1 stick, 1 slip, 2 stick, 2 slip), for callgrind:
 *   valgrind --tool=callgrind ./bench_batch 4 1 4
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "interfacial.h"

/* The leading dimension is padded: rows a power-of-two number of bytes apart (ld = 4096 doubles =
 * 32 KiB) fall into the same L1 sets and evict each other, which costs the structure-of-arrays
 * layout more than all the call overhead it saves. */
enum { NP = 4096, LD = NP + 24 };

typedef struct {
    int lm;
    double tau[2], ddtddg[4], ddtddp[2], dslip[2], sed, sfd, ddtddt[4], statev[3];
    double dgam[2], taulm[2], press, dpress;
} point_t;

static point_t pts[NP], work[NP];
static double tau0[2 * LD], statev0[3 * LD], tau[2 * LD], statev[3 * LD];
static double ddtddg[4 * LD], ddtddp[2 * LD], dslip[2 * LD], sed[LD], sfd[LD];
static double dgam[2 * LD], taulm[2 * LD], press[LD], dpress[LD], chr[LD];
static int lm0[LD], lm[LD];

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double uniform(double a, double b)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return a + (b - a) * (double)((rng * 0x2545F4914F6CDD1Dull) >> 11) / 9007199254740992.0;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static const double props[7] = {1.0, 0.3, 0.0, 0.0, 1e-3, 0.0, 0.0};
static const int nprops = 7, nstatv = 3, kstep = 1, kinc = 1, noel = 1, npt = 1, node = 1;
static const int npatch = 1, mcrd = 3, npred = 1;
static const double ddpddh = 1e6, dtime = 0.1, chrlngth = 1.0;
static const double zeros[4] = {0, 0, 0, 0}, time2[2] = {0, 0}, drot[4] = {1, 0, 0, 1};
static const double temp[2] = {20, 20};
static char names[3][80];

static void setup(int nfdir, int slip)
{
    int i, a;
    for (i = 0; i < NP; i++) {
        point_t *p = &pts[i];
        double ratio = slip ? uniform(1.1, 5.0) : uniform(0.05, 0.9);
        double p_end = uniform(50.0, 150.0), dp = uniform(-10.0, 10.0);
        double gc = 1e-3, ks_start = 0.3 * (p_end - dp) / gc;
        double angle = uniform(0.0, 6.283185307179586);
        double g_el[2], g_pr[2];
        memset(p, 0, sizeof *p);
        p->press = p_end;
        p->dpress = dp;
        /* Elastic slip at the start and an increment with |γ_pr| = ratio·γ_crit. */
        g_pr[0] = ratio * gc * cos(angle);
        g_pr[1] = nfdir == 2 ? ratio * gc * sin(angle) : 0.0;
        if (nfdir == 1) {
            g_pr[0] = ratio * gc * (angle < 3.14 ? 1.0 : -1.0);
        }
        for (a = 0; a < nfdir; a++) {
            g_el[a] = uniform(-0.3, 0.3) * gc;
            p->tau[a] = ks_start * g_el[a];
            p->dgam[a] = g_pr[a] - g_el[a];
            tau0[i + a * LD] = p->tau[a];
            dgam[i + a * LD] = p->dgam[a];
            taulm[i + a * LD] = 0.0;
        }
        p->statev[0] = uniform(0, 1);
        statev0[i] = p->statev[0];
        statev0[i + LD] = 0.0;
        statev0[i + 2 * LD] = 0.0;
        press[i] = p_end;
        dpress[i] = dp;
        chr[i] = chrlngth;
        lm0[i] = 0;
    }
    memcpy(work, pts, sizeof work);
}

static void sweep_fric(int nfdir)
{
    int i;
    for (i = 0; i < NP; i++) {
        point_t *w = &work[i];
        double pnewdt = 1e36;
        /* The host's work copies of the converged TAU, STATEV and LM. */
        w->lm = pts[i].lm;
        w->tau[0] = pts[i].tau[0];
        w->tau[1] = pts[i].tau[1];
        w->statev[0] = pts[i].statev[0];
        w->statev[1] = pts[i].statev[1];
        w->statev[2] = pts[i].statev[2];
        fric_(&w->lm, w->tau, w->ddtddg, w->ddtddp, w->dslip, &w->sed, &w->sfd, w->ddtddt,
              &pnewdt, w->statev, w->dgam, w->taulm, &w->press, &w->dpress, &ddpddh, zeros,
              &kstep, &kinc, time2, &dtime, &noel, names[0], names[1], names[2], &npt, &node,
              &npatch, zeros, zeros, drot, temp, zeros, &nfdir, &mcrd, &npred, &nstatv,
              &chrlngth, props, &nprops, 80, 80, 80);
    }
}

static void sweep_batch(int nfdir)
{
    double pnewdt = 1e36;
    memcpy(tau, tau0, sizeof tau);
    memcpy(statev, statev0, sizeof statev);
    memcpy(lm, lm0, sizeof lm);
    ifl_fric_batch(NP, LD, nfdir, props, nprops, nstatv, dtime, lm, tau, ddtddg, ddtddp, dslip,
                   sed, sfd, statev, dgam, taulm, press, dpress, chr, &pnewdt);
}

static int check(int nfdir)
{
    int i, a, bad = 0;
    sweep_fric(nfdir);
    sweep_batch(nfdir);
    for (i = 0; i < NP; i++) {
        for (a = 0; a < nfdir; a++) {
            bad += memcmp(&work[i].tau[a], &tau[i + a * LD], sizeof(double)) != 0;
        }
        bad += memcmp(&work[i].sfd, &sfd[i], sizeof(double)) != 0;
        bad += memcmp(&work[i].statev[2], &statev[i + 2 * LD], sizeof(double)) != 0;
    }
    return bad;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    int nrep = argc > 1 ? atoi(argv[1]) : 200, nrun = argc > 2 ? atoi(argv[2]) : 15;
    int only = argc > 3 ? atoi(argv[3]) : 0;
    int nfdir, slip, r, k, i;
    double *tf = malloc(sizeof(double) * (size_t)nrun), *tb = malloc(sizeof(double) * (size_t)nrun);
    double *ratio = malloc(sizeof(double) * (size_t)nrun);
    if (nrep < 1 || nrun < 1 || !tf || !tb || !ratio) {
        fprintf(stderr, "usage: bench_batch [NREP [NRUN [CASE]]]\n");
        return 2;
    }
    for (i = 0; i < 3; i++) {
        memset(names[i], ' ', 80);
    }
    memcpy(names[0], "SI1", 3);
    printf("| NFDIR | points | fric_ per point (ns) | ifl_fric_batch (ns/point) | speed-up (best) | "
           "speed-up (median) |\n|---|---|---|---|---|---|\n");
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        for (slip = 0; slip <= 1; slip++) {
            if (only != 0 && only != 2 * (nfdir - 1) + slip + 1) {
                continue;
            }
            setup(nfdir, slip);
            if (check(nfdir) != 0) {
                fprintf(stderr, "batch and fric_ disagree (NFDIR %d)\n", nfdir);
                return 1;
            }
            for (r = 0; r < nrun; r++) {
                double t0 = now();
                for (k = 0; k < nrep; k++) {
                    sweep_fric(nfdir);
                }
                double t1 = now();
                for (k = 0; k < nrep; k++) {
                    sweep_batch(nfdir);
                }
                double t2 = now();
                tf[r] = (t1 - t0) / ((double)nrep * NP) * 1e9;
                tb[r] = (t2 - t1) / ((double)nrep * NP) * 1e9;
                ratio[r] = tf[r] / tb[r];
            }
            qsort(tf, (size_t)nrun, sizeof(double), cmp);
            qsort(tb, (size_t)nrun, sizeof(double), cmp);
            qsort(ratio, (size_t)nrun, sizeof(double), cmp);
            printf("| %d | all %s | %.1f | %.1f | %.2fx | %.2fx |\n", nfdir,
                   slip ? "slipping" : "sticking", tf[0], tb[0], tf[0] / tb[0],
                   ratio[nrun / 2]);
        }
    }
    free(tf);
    free(tb);
    free(ratio);
    return 0;
}
