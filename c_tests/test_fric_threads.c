/*
 * fric_ from 8 threads at once (docs/fric.md, "Threads": reentrant, no shared mutable state on
 * the success path), compared bit for bit with a serial run of the same points.
 *
 * 4096 contact points x 256 increments = 1 048 576 fric_ calls per run. Each point is driven
 * increment by increment the way a host drives it: TAU, STATEV and LM carried from one
 * increment to the next, PRESS and DPRESS consistent, and a spring-like host that hands the
 * Lagrange stress TAULM to exact-stick points. Every point has its own Coulomb interaction drawn
 * from a Lehmer generator (x <- 48271 x mod 2^31 - 1) seeded by the point's index, so its calls
 * do not depend on which thread makes them or when:
 *   NFDIR 1 or 2; elastic stick (stick and slip), exact stick (LM = 1 held, released, entered by
 *   a reversal) or rough; tau_max cap or none; gamma_crit from PROPS(5) or PROPS(6) x CHRLNGTH;
 *   NSTATV 3 or 5; now and then a negative pressure (no friction, a safe value) and a NaN in
 *   DGAM (a refused call: PNEWDT = 0.25, state unchanged, this thread's last error names the
 *   point; rough points do not read DGAM and answer LM = 1 as always).
 * Every array fric_ may touch is its own heap block of exactly the size the host declares
 * (NFDIR, NFDIR^2, 2 NFDIR, NSTATV), so an out-of-bounds write is an AddressSanitizer report
 * in the sanitizer build (scripts/test-sanitizers.sh) rather than a silent overwrite.
 *
 * The 8 threads start together behind a barrier and take contiguous blocks of 512 points.
 * Compared with the serial run (on the main thread, afterwards):
 *   - every call: all outputs (LM, TAU, DDTDDG, DDTDDP, DSLIP, SED, SFD, DDTDDT, PNEWDT,
 *     STATEV(1..NSTATV)), byte by byte, folded into a 64-bit FNV-1a digest of that call; the
 *     1 048 576 digests of each run compared with memcmp;
 *   - every point: the final contents of all those arrays, with memcmp;
 *   - the counts of each kind of call.
 * Checked on every call of both runs, against the law rather than against the library: the
 * kind of call the host expects (refused exactly when the host put a NaN in), |tau| <= tau_crit
 * = min(mu p, tau_max) and |tau| = tau_crit when slipping, SED, SFD >= 0, exact-stick outputs
 * (DSLIP = SED = SFD = 0), rough points always LM = 1, STATEV(1) never decreasing, STATEV past
 * 3 untouched, PNEWDT untouched by a successful call. Each kind of call must occur often.
 *
 * INTERFACIAL_TEST_SHRINK=n divides the number of points by n (valgrind, ASan runs).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "thread_harness.h"

enum { FULL_POINTS = 4096, INCS = 256, MIN_POINTS = 64 };
#define PNEWDT_IN 1e36
#define STATEV_TAIL (-5.5e55) /* in STATEV(4..NSTATV): fric_ must leave it */

/* Kinds of call, counted per run. */
enum {
    K_STICK,     /* LM = 0 out, STATEV(3) = 0 */
    K_SLIP,      /* LM = 0 out, STATEV(3) = 1 */
    K_CAPPED,    /* ... slipping on the tau_max cap */
    K_EXACT,     /* LM = 1 out, exact-stick point */
    K_HELD,      /* LM = 1 in and out */
    K_RELEASED,  /* LM = 1 in, 0 out */
    K_REVERSAL,  /* LM = 0 in, 1 out */
    K_ROUGH,     /* rough point, LM = 1 */
    K_NO_PRESS,  /* negative pressure */
    K_REFUSED,   /* NaN in DGAM: refused */
    K_NFDIR1,
    K_NFDIR2,
    N_KINDS
};
static const char *const KIND_NAMES[N_KINDS] = {
    "stick", "slip", "slip on tau_max", "exact stick", "exact stick held", "released",
    "reversal to exact stick", "rough", "negative pressure", "refused (NaN)", "NFDIR 1",
    "NFDIR 2"};

/* ---- one contact point ---------------------------------------------------------------- */
typedef struct {
    uint32_t rng;
    int nfdir, mode, nstatv, nprops;
    double props[7];
    double chrlngth, p_ref, tau_max, gamma_crit;
    /* The host's arrays, each malloc'ed at exactly its declared size. */
    int lm;
    double *tau, *ddtddg, *ddtddp, *dslip, *ddtddt, *statev, *dgam, *taulm, *slip;
    double sed, sfd, pnewdt, press;
} contact;

/* The final outputs of a point, zero-padded to the largest sizes, for memcmp. */
typedef struct {
    double tau[2], ddtddg[4], ddtddp[2], dslip[2], ddtddt[4], statev[5];
    double sed, sfd, pnewdt, press;
    int64_t lm;
} final_rec;

/* One of the host's arrays of a contact and its declared size. */
typedef struct {
    double **array;
    size_t len;
} host_array;

enum { N_HOST_ARRAYS = 9 };

/* The host's arrays of c: NFDIR, NFDIR^2, 2 NFDIR or NSTATV doubles. */
static void host_arrays(contact *c, host_array a[N_HOST_ARRAYS])
{
    const size_t n = (size_t)c->nfdir;
    const host_array all[N_HOST_ARRAYS] = {
        {&c->tau, n},   {&c->ddtddg, n * n}, {&c->ddtddp, n},
        {&c->dslip, n}, {&c->ddtddt, 2 * n}, {&c->statev, (size_t)c->nstatv},
        {&c->dgam, n},  {&c->taulm, n},      {&c->slip, n}};
    memcpy(a, all, sizeof all);
}

static int contact_init(contact *c, int index, th_tally *t)
{
    uint32_t *r = &c->rng;
    host_array arrays[N_HOST_ARRAYS];
    int i, allocated = 1;
    memset(c, 0, sizeof *c);
    c->rng = (uint32_t)(index % (int)(TH_LEHMER_M - 1u)) + 1u;
    for (i = 0; i < 4; i++) { /* decorrelate neighbouring seeds */
        th_lehmer(r);
    }
    c->nfdir = th_uniform(r, 0.0, 1.0) < 0.5 ? 1 : 2;
    {
        double m = th_uniform(r, 0.0, 1.0);
        c->mode = m < 0.6 ? 0 : m < 0.9 ? 1 : 2;
    }
    c->nstatv = th_uniform(r, 0.0, 1.0) < 0.75 ? 3 : 5;
    c->p_ref = th_uniform(r, 10.0, 100.0);
    c->props[0] = 1.0;                        /* Coulomb */
    c->props[1] = th_uniform(r, 0.1, 0.6);       /* mu */
    c->tau_max = th_uniform(r, 0.0, 1.0) < 0.3 ? c->props[1] * c->p_ref * th_uniform(r, 0.6, 1.0)
                                            : INFINITY;
    c->props[3] = isinf(c->tau_max) ? 0.0 : c->tau_max;
    c->chrlngth = th_uniform(r, 0.05, 0.2);
    if (th_uniform(r, 0.0, 1.0) < 0.5) {
        c->props[4] = c->gamma_crit = th_uniform(r, 1e-4, 1e-3);
    } else {
        c->props[5] = th_uniform(r, 0.002, 0.01);
        c->gamma_crit = c->props[5] * c->chrlngth;
    }
    c->props[6] = (double)c->mode;
    c->nprops = 7;
    c->lm = 0;
    host_arrays(c, arrays);
    for (i = 0; i < N_HOST_ARRAYS; i++) {
        *arrays[i].array = calloc(arrays[i].len, sizeof(double));
        if (*arrays[i].array == NULL) {
            t->alloc_fail++;
            allocated = 0;
        }
    }
    if (!allocated) {
        return 0;
    }
    for (i = 3; i < c->nstatv; i++) {
        c->statev[i] = STATEV_TAIL;
    }
    return 1;
}

static void contact_free(contact *c)
{
    host_array arrays[N_HOST_ARRAYS];
    int i;
    host_arrays(c, arrays);
    for (i = 0; i < N_HOST_ARRAYS; i++) {
        free(*arrays[i].array);
    }
}

/* Every output of the last call, byte by byte. */
static uint64_t digest(const contact *c)
{
    size_t n = (size_t)c->nfdir;
    uint64_t h = TH_FNV_OFFSET;
    h = th_fnv(h, &c->lm, sizeof c->lm);
    h = th_fnv(h, c->tau, n * sizeof(double));
    h = th_fnv(h, c->ddtddg, n * n * sizeof(double));
    h = th_fnv(h, c->ddtddp, n * sizeof(double));
    h = th_fnv(h, c->dslip, n * sizeof(double));
    h = th_fnv(h, &c->sed, sizeof c->sed);
    h = th_fnv(h, &c->sfd, sizeof c->sfd);
    h = th_fnv(h, c->ddtddt, 2 * n * sizeof(double));
    h = th_fnv(h, &c->pnewdt, sizeof c->pnewdt);
    return th_fnv(h, c->statev, (size_t)c->nstatv * sizeof(double));
}

static void violation(th_tally *t, int point, int inc, const char *what)
{
    th_violation(t, "point %d, increment %d: %s", point, inc, what);
}

static double norm(const double *v, int n)
{
    return n == 1 ? fabs(v[0]) : hypot(v[0], v[1]);
}

/* One increment of point `point`: the host's inputs, the call, the checks; returns the digest. */
static uint64_t increment(contact *c, int point, int inc, th_tally *t)
{
    char names[3][80];
    uint32_t *r = &c->rng;
    int n = c->nfdir, i, lm_in = c->lm, npt = 1, node = point + 1, noel = point + 1, npatch = 0;
    int kstep = 1, kinc = inc + 1, mcrd = n + 1, npred = 1, nfdir = n, nstatv = c->nstatv;
    int nprops = c->nprops, nan_call;
    double time[2] = {0.01 * inc, 0.01 * inc}, dtime = 0.01, ddpddh = 1e6;
    double coords[3] = {0.0, 0.0, 0.0}, rcoord[3] = {0.0, 0.0, 0.0};
    double drot[4] = {1.0, 0.0, 0.0, 1.0}, temp[2] = {20.0, 0.0}, predef[2] = {0.0, 0.0};
    double p_old = c->press, press, dpress, tau_crit, tau_old[2], statev_old[3], s1_old;
    double gc = c->gamma_crit;

    /* The host's inputs for this increment (names blank-padded CHARACTER*80). */
    memset(names, ' ', sizeof names);
    memcpy(names[0], "FRICTION_THREADS", 16);
    memcpy(names[1], "SLAVE", 5);
    memcpy(names[2], "MASTER", 6);
    press = c->p_ref * th_uniform(r, 0.7, 1.3);
    if (th_uniform(r, 0.0, 1.0) < 1.0 / 64.0) {
        press = -0.05 * c->p_ref; /* barely closed: no friction */
    }
    dpress = press - p_old;
    for (i = 0; i < n; i++) {
        c->dgam[i] = th_uniform(r, -2.0, 2.0) * gc;
    }
    tau_crit = press > 0.0 ? fmin(c->props[1] * press, c->tau_max) : 0.0;
    for (i = 0; i < n; i++) {
        c->taulm[i] = th_uniform(r, -1.2, 1.2) * (press > 0.0 ? tau_crit : c->p_ref) / sqrt(n);
    }
    nan_call = (point % 8 == 3) && (inc % 97 == 50);
    if (nan_call) {
        c->dgam[0] = NAN;
    } else {
        for (i = 0; i < n; i++) {
            c->slip[i] += c->dgam[i];
        }
    }
    c->pnewdt = PNEWDT_IN;
    tau_old[0] = c->tau[0];
    tau_old[1] = c->tau[n - 1];
    memcpy(statev_old, c->statev, sizeof statev_old);
    s1_old = c->statev[0];

    fric_(&c->lm, c->tau, c->ddtddg, c->ddtddp, c->dslip, &c->sed, &c->sfd, c->ddtddt,
          &c->pnewdt, c->statev, c->dgam, c->taulm, &press, &dpress, &ddpddh, c->slip, &kstep,
          &kinc, time, &dtime, &noel, names[0], names[1], names[2], &npt, &node, &npatch, coords,
          rcoord, drot, temp, predef, &nfdir, &mcrd, &npred, &nstatv, &c->chrlngth, c->props,
          &nprops, 80, 80, 80);

    t->kinds[n == 1 ? K_NFDIR1 : K_NFDIR2]++;
    for (i = 3; i < c->nstatv; i++) {
        if (memcmp(&c->statev[i], &(double){STATEV_TAIL}, sizeof(double)) != 0) {
            violation(t, point, inc, "STATEV past 3 written");
        }
    }
    if (nan_call && c->mode != 2) { /* rough points do not read DGAM */
        char want[48];
        t->kinds[K_REFUSED]++;
        if (c->pnewdt != FH_CUTBACK || c->lm != lm_in ||
            memcmp(&tau_old[0], &c->tau[0], sizeof(double)) != 0 ||
            memcmp(&tau_old[1], &c->tau[n - 1], sizeof(double)) != 0 ||
            memcmp(statev_old, c->statev, sizeof statev_old) != 0) {
            violation(t, point, inc, "refused call: PNEWDT not 0.25 or state changed");
        }
        snprintf(want, sizeof want, "element %d,", noel);
        if (strstr(ifl_last_error(), want) == NULL || strstr(ifl_last_error(), "DGAM") == NULL) {
            t->msg_bad++;
        }
        c->dgam[0] = 0.0;
        c->press = p_old; /* the increment did not happen */
        return digest(c);
    }
    c->press = press;
    if (c->pnewdt != PNEWDT_IN) {
        violation(t, point, inc, "PNEWDT changed by a successful call");
    }
    if (!(c->statev[0] >= s1_old)) {
        violation(t, point, inc, "STATEV(1) decreased");
    }
    if (press <= 0.0) {
        t->kinds[K_NO_PRESS]++;
    }
    if (c->mode == 2) {
        t->kinds[K_ROUGH]++;
        if (c->lm != 1) {
            violation(t, point, inc, "rough point not LM = 1");
        }
        return digest(c);
    }
    if (c->lm == 1) {
        if (c->mode != 1) {
            violation(t, point, inc, "LM = 1 out of an elastic-stick point");
        }
        t->kinds[K_EXACT]++;
        t->kinds[lm_in == 1 ? K_HELD : K_REVERSAL]++;
        if (lm_in == 1 && !(norm(c->taulm, n) <= tau_crit)) {
            violation(t, point, inc, "held exact stick with |TAULM| > tau_crit");
        }
        if (c->statev[2] != 2.0 || c->sed != 0.0 || c->sfd != 0.0 || c->dslip[0] != 0.0 ||
            c->dslip[n - 1] != 0.0) {
            violation(t, point, inc, "exact stick: STATEV(3) = 2, DSLIP = SED = SFD = 0");
        }
        /* The host's stress at exact stick is the Lagrange stress. */
        memcpy(c->tau, c->taulm, (size_t)n * sizeof(double));
        return digest(c);
    }
    if (c->lm != 0) {
        violation(t, point, inc, "LM not 0, 1");
        return digest(c);
    }
    if (lm_in == 1) {
        t->kinds[K_RELEASED]++;
        if (!(norm(c->taulm, n) > tau_crit)) {
            violation(t, point, inc, "released with |TAULM| <= tau_crit");
        }
    }
    {
        double tn = norm(c->tau, n);
        int slipping = c->statev[2] == 1.0;
        if (!(tn <= tau_crit * (1.0 + 1e-12))) {
            violation(t, point, inc, "|tau| > tau_crit");
        }
        if (slipping && !(fabs(tn - tau_crit) <= 1e-12 * tau_crit)) {
            violation(t, point, inc, "slipping with |tau| != tau_crit");
        }
        if (!(c->sed >= 0.0 && c->sfd >= 0.0)) {
            violation(t, point, inc, "SED or SFD negative");
        }
        if (c->statev[2] != 0.0 && !slipping) {
            violation(t, point, inc, "STATEV(3) not 0 or 1 with LM = 0");
        }
        if (slipping) {
            t->kinds[K_SLIP]++;
            t->kinds[K_CAPPED] += c->props[1] * press > c->tau_max;
        } else {
            t->kinds[K_STICK]++;
        }
    }
    return digest(c);
}

static void final_of(const contact *c, final_rec *f)
{
    size_t n = (size_t)c->nfdir;
    memset(f, 0, sizeof *f);
    memcpy(f->tau, c->tau, n * sizeof(double));
    memcpy(f->ddtddg, c->ddtddg, n * n * sizeof(double));
    memcpy(f->ddtddp, c->ddtddp, n * sizeof(double));
    memcpy(f->dslip, c->dslip, n * sizeof(double));
    memcpy(f->ddtddt, c->ddtddt, 2 * n * sizeof(double));
    memcpy(f->statev, c->statev, (size_t)c->nstatv * sizeof(double));
    f->sed = c->sed;
    f->sfd = c->sfd;
    f->pnewdt = c->pnewdt;
    f->press = c->press;
    f->lm = c->lm;
}

/* One point of one run: INCS increments into digests[inc], the final outputs into *fin. */
static void run_point(int p, uint64_t *digests, void *fin, th_tally *t)
{
    contact c;
    int k;
    if (!contact_init(&c, p, t)) {
        contact_free(&c);
        return;
    }
    for (k = 0; k < INCS; k++) {
        digests[k] = increment(&c, p, k, t);
    }
    final_of(&c, fin);
    contact_free(&c);
}

static void report_tally(const char *run, const th_tally *t)
{
    th_report(run, t, KIND_NAMES, N_KINDS, "", "%ld calls", (long)t->points);
}

int main(void)
{
    int points = FULL_POINTS / th_shrink_factor(FULL_POINTS / MIN_POINTS);
    th_point_runs("fric_", points, INCS, run_point, sizeof(final_rec), report_tally, KIND_NAMES,
                  N_KINDS);
    return fh_finish();
}
