/*
 * gapcon_ from 8 threads at once (docs/gapcon.md: "Thread-safe: the file is read once;
 * evaluation touches no shared mutable state"), compared bit for bit with a serial run.
 *
 * 8 threads x 131072 points = 1 048 576 gapcon_ calls (and every fourth point also through
 * ifl_gap_conductance), over six interactions: a constant, a pressure table, a pressure table
 * in temperature [p, k, theta], radiation in Celsius, gas-gap plus radiation, and cmy. Point i
 * goes to thread i mod 8, so every interaction is evaluated by all threads at the same time.
 * The threads start together behind a barrier and make the process's first call into the
 * library concurrently, so they also race for the one-time read of the configuration.
 *
 * Checked: AK(1) and the IflConductance of every point identical to the serial run's (memcmp);
 * AK(2..5) never written; a failing call on each thread (an interaction that is not
 * configured, named after the thread) leaves AK(1) = 0 and that thread's own message in
 * ifl_last_error() while the other threads fail with theirs (the last error is per thread);
 * the log (INTERFACIAL_LOG, set by CTest) holds those 8 messages as 8 whole lines; and, in the
 * serial run, AK(1) against the laws worked out by hand.
 *
 * The configuration is written at run time to argv[1] (default ./gapcon_threads.toml).
 * INTERFACIAL_TEST_SHRINK=n divides the number of points by n (valgrind, ASan runs); every
 * array is a heap block of exactly the size used.
 */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gapcon_harness.h"
#include "thread_harness.h"

enum { N_THREADS = TH_THREADS, PER_THREAD = 131072, FULL_POINTS = N_THREADS * PER_THREAD };
enum { MIN_POINTS = 8192 };

enum { LAW_CONST, LAW_PTAB, LAW_TTAB, LAW_RAD, LAW_GAS_RAD, LAW_CMY, N_LAWS };
static const char *const NAMES[N_LAWS] = {"TH_CONST", "TH_PTAB", "TH_TTAB",
                                          "TH_RAD",   "TH_GAS_RAD", "TH_CMY"};

#define K_CONST 1234.5
static const double PTAB[] = {-1.0, 50.0, 0.0, 200.0, 40.0, 900.0, 90.0, 1500.0};
#define PTAB_ROWS 4
static const double TTAB[] = {
    0.0, 300.0, 20.0,  60.0, 1200.0, 20.0,
    0.0, 800.0, 150.0, 60.0, 2500.0, 150.0,
};
#define TTAB_ROWS 4
#define VIEW_F 0.7
#define ZERO_C (-273.15)
#define K_GAS 0.025
#define G0 1e-5

typedef struct {
    int law;
    double d, p, ta, tb;
} point;

/* n_points points; nat_* and status_* hold every fourth point (index i / 4). */
static int n_points;
static point *points;
static double *ak_par, *ak_ser;
static IflConductance *nat_par, *nat_ser;
static int *status_par, *status_ser;

static pthread_barrier_t start_line, failed_line;

typedef struct {
    int id;
    long guard_violations;   /* AK(2..5) written */
    int unknown_ak_zero;     /* the failing call left AK(1) = 0 */
    int own_message;         /* ... and this thread's last error names this thread's name */
    char message[512];
} worker;

static void write_config(const char *path)
{
    gh_config_open(path, "test_gapcon_threads.c");
    gh_config_constant("TH_CONST", K_CONST);
    gh_config_tabulated("TH_PTAB", "pressure-table", PTAB, PTAB_ROWS, 2);
    gh_config_tabulated("TH_TTAB", "pressure-table", TTAB, TTAB_ROWS, 3);
    gh_config_radiation("TH_RAD", VIEW_F, GH_SIGMA_SI, ZERO_C);
    gh_config_gas_gap("TH_GAS_RAD", K_GAS, G0);
    gh_config_radiation("TH_GAS_RAD", VIEW_F, GH_SIGMA_SI, 0.0);
    gh_config_cmy("TH_CMY", 30.0, 0.12, 3e-6, 2e9);
    gh_config_close(path);
}

/* A reproducible stream of numbers in [0, 1): the harnesses' MINSTD generator, one stream
 * drawn on the main thread before the runs. */
static uint32_t point_rng = 20240601u;
static double uniform(void)
{
    return th_uniform(&point_rng, 0.0, 1.0);
}

static void make_points(void)
{
    int i;
    for (i = 0; i < n_points; i++) {
        point *x = &points[i];
        x->law = (int)(uniform() * N_LAWS) % N_LAWS;
        x->d = -1e-5 + 2e-3 * uniform();
        x->p = -5.0 + 120.0 * uniform();
        /* Celsius-like temperatures; theta_mean spans TTAB's temperatures and beyond. */
        x->ta = -50.0 + 400.0 * uniform();
        x->tb = -50.0 + 400.0 * uniform();
        if (x->law == LAW_GAS_RAD) { /* in kelvin */
            x->ta += 273.15;
            x->tb += 273.15;
        }
        if (x->law == LAW_CMY) {
            x->p = 1e5 + 1e8 * uniform();
        }
    }
}

/* The raw Fortran-style call; returns 1 when AK(2..5) and the slot after are untouched. */
static int call_point(const point *x, double *ak_out)
{
    double ak[GH_AK];
    double d[2], temp[2], flowm[2] = {0.0, 0.0}, predef[2] = {0.0, 0.0}, time[2] = {0.0, 1.0};
    double coords[3] = {0.0, 0.0, 0.0};
    char ciname[80], slname[80], msname[80];
    int noel = 17, node = 42, npred = 1, kstep = 1, kinc = 1, i, ok = 1;
    size_t n = strlen(NAMES[x->law]);
    memset(ciname, ' ', sizeof ciname);
    memcpy(ciname, NAMES[x->law], n);
    memset(slname, ' ', sizeof slname);
    memset(msname, ' ', sizeof msname);
    for (i = 0; i < GH_AK; i++) {
        ak[i] = GH_GUARD;
    }
    d[0] = x->d;
    d[1] = x->p;
    temp[0] = x->ta;
    temp[1] = x->tb;
    gapcon_(ak, d, flowm, temp, predef, time, ciname, slname, msname, coords, &noel, &node,
            &npred, &kstep, &kinc, 80, 80, 80);
    for (i = 1; i < GH_AK; i++) {
        ok &= ak[i] == GH_GUARD;
    }
    *ak_out = ak[0];
    return ok;
}

static void *work(void *arg)
{
    worker *w = arg;
    char unknown[32], mine[48];
    int i;
    pthread_barrier_wait(&start_line);
    for (i = w->id; i < n_points; i += N_THREADS) {
        if (!call_point(&points[i], &ak_par[i])) {
            w->guard_violations++;
        }
        if (i % 4 == 0) {
            const point *x = &points[i];
            status_par[i / 4] = (int)ifl_gap_conductance(NAMES[x->law], x->d, x->p, x->ta,
                                                         x->tb, &nat_par[i / 4]);
        }
    }
    /* Every thread fails with its own interaction, then all check their own last error. */
    snprintf(unknown, sizeof unknown, "UNKNOWN_%d", w->id);
    snprintf(mine, sizeof mine, "interaction '%s'", unknown);
    {
        gh_gapcon g;
        gh_init(&g, unknown, 1e-4, 10.0, 300.0, 290.0);
        gh_set_guards(&g);
        gh_call_raw(&g);
        w->unknown_ak_zero = g.ak[0] == 0.0 && gh_guards_intact(&g);
    }
    pthread_barrier_wait(&failed_line);
    snprintf(w->message, sizeof w->message, "%s", ifl_last_error());
    w->own_message = strstr(w->message, mine) != NULL;
    return NULL;
}

/* AK(1) by hand for the serial run's spot checks. */
static double hand_k(const point *x)
{
    switch (x->law) {
    case LAW_CONST:
        return K_CONST;
    case LAW_PTAB:
        return gh_lerp_table(PTAB, PTAB_ROWS, 2, x->p);
    case LAW_TTAB:
        return gh_table_k(TTAB, TTAB_ROWS, 3, x->p, 0.5 * (x->ta + x->tb));
    case LAW_RAD: {
        double a = x->ta - ZERO_C, b = x->tb - ZERO_C;
        return VIEW_F * GH_SIGMA_SI * (a + b) * (a * a + b * b);
    }
    case LAW_GAS_RAD: {
        double a = x->ta, b = x->tb;
        return K_GAS / (fmax(x->d, 0.0) + G0) + VIEW_F * GH_SIGMA_SI * (a + b) * (a * a + b * b);
    }
    default:
        return 1.25 * (30.0 * 0.12 / 3e-6) * pow(x->p / 2e9, 0.95);
    }
}

/* The log (INTERFACIAL_LOG) holds the 8 failures, one whole line each, none repeated. */
static void check_log(const char *path)
{
    char line[1024];
    int lines = 0, seen[N_THREADS] = {0}, whole = 1, i;
    FILE *f = fopen(path, "r");
    fh_context("INTERFACIAL_LOG %s", path);
    if (!FH_CHECK(f != NULL)) {
        return;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        int id = -1;
        lines++;
        whole &= strncmp(line, "interfacial: GAPCON: interaction 'UNKNOWN_", 42) == 0 &&
                 strchr(line, '\n') != NULL && sscanf(line + 42, "%d", &id) == 1 && id >= 0 &&
                 id < N_THREADS;
        if (id >= 0 && id < N_THREADS) {
            seen[id]++;
        }
    }
    fclose(f);
    FH_CHECK(whole);
    FH_CHECK(lines == N_THREADS);
    for (i = 0; i < N_THREADS; i++) {
        FH_CHECK(seen[i] == 1);
    }
}

int main(int argc, char **argv)
{
    const char *log = getenv("INTERFACIAL_LOG");
    pthread_t tid[N_THREADS];
    worker w[N_THREADS];
    long guard_violations = 0, ak_diff = 0, nat_diff = 0, status_diff = 0, hand_bad = 0;
    int i, created = 0, per_law[N_LAWS] = {0};

    if (log != NULL && log[0] != '\0') {
        remove(log); /* the library appends */
    }
    n_points = FULL_POINTS / th_shrink_factor(FULL_POINTS / MIN_POINTS);
    points = calloc((size_t)n_points, sizeof *points);
    ak_par = calloc((size_t)n_points, sizeof *ak_par);
    ak_ser = calloc((size_t)n_points, sizeof *ak_ser);
    nat_par = calloc(((size_t)n_points + 3) / 4, sizeof *nat_par);
    nat_ser = calloc(((size_t)n_points + 3) / 4, sizeof *nat_ser);
    status_par = calloc(((size_t)n_points + 3) / 4, sizeof *status_par);
    status_ser = calloc(((size_t)n_points + 3) / 4, sizeof *status_ser);
    fh_context("allocation");
    if (!FH_CHECK(points != NULL && ak_par != NULL && ak_ser != NULL && nat_par != NULL &&
                  nat_ser != NULL && status_par != NULL && status_ser != NULL)) {
        return fh_finish();
    }
    write_config(argc > 1 ? argv[1] : "gapcon_threads.toml");
    make_points();
    memset(w, 0, sizeof w);
    pthread_barrier_init(&start_line, NULL, N_THREADS);
    pthread_barrier_init(&failed_line, NULL, N_THREADS);
    fh_context("8 threads");
    for (i = 0; i < N_THREADS; i++) {
        w[i].id = i;
        if (pthread_create(&tid[i], NULL, work, &w[i]) != 0) {
            break;
        }
        created++;
    }
    if (!FH_CHECK(created == N_THREADS)) {
        /* The barrier would never open: give up before joining. */
        return fh_finish();
    }
    for (i = 0; i < N_THREADS; i++) {
        pthread_join(tid[i], NULL);
    }
    for (i = 0; i < N_THREADS; i++) {
        guard_violations += w[i].guard_violations;
        FH_CHECK(w[i].unknown_ak_zero);
        if (!FH_CHECK(w[i].own_message)) {
            fprintf(stderr, "  thread %d's last error: %s\n", i, w[i].message);
        }
        FH_CONTAINS(w[i].message, "GAPCON");
        FH_CONTAINS(w[i].message, "interaction not found");
    }
    FH_CHECK(guard_violations == 0);

    /* The serial run, on the main thread. */
    fh_context("serial run");
    for (i = 0; i < n_points; i++) {
        const point *x = &points[i];
        if (!call_point(x, &ak_ser[i])) {
            guard_violations++;
        }
        if (i % 4 == 0) {
            status_ser[i / 4] = (int)ifl_gap_conductance(NAMES[x->law], x->d, x->p, x->ta,
                                                         x->tb, &nat_ser[i / 4]);
        }
        per_law[x->law]++;
        {
            double k = hand_k(x);
            /* Round-off of the hand formulas: tables and constants to 1e-14; radiation's and
             * cmy's powers to a few ulps more. */
            if (!(fabs(ak_ser[i] - k) <= 1e-13 * fabs(k)) ||
                (i % 4 == 0 && status_ser[i / 4] != 0)) {
                if (hand_bad++ < 5) {
                    fprintf(stderr, "  point %d (%s): AK(1) = %.17g, by hand %.17g\n", i,
                            NAMES[x->law], ak_ser[i], k);
                }
            }
        }
    }
    FH_CHECK(guard_violations == 0);
    FH_CHECK(hand_bad == 0);
    for (i = 0; i < N_LAWS; i++) {
        /* Each law is well represented. */
        FH_CHECK(per_law[i] > n_points / (2 * N_LAWS));
    }

    fh_context("parallel against serial, bit for bit");
    for (i = 0; i < n_points; i++) {
        if (memcmp(&ak_par[i], &ak_ser[i], sizeof ak_par[i]) != 0) {
            if (ak_diff++ < 5) {
                fprintf(stderr, "  point %d: AK(1) %.17g in parallel, %.17g serial\n", i,
                        ak_par[i], ak_ser[i]);
            }
        }
        if (i % 4 == 0) {
            nat_diff += memcmp(&nat_par[i / 4], &nat_ser[i / 4], sizeof nat_par[0]) != 0;
            status_diff += status_par[i / 4] != status_ser[i / 4] || status_ser[i / 4] != 0;
        }
    }
    FH_CHECK(ak_diff == 0);
    FH_CHECK(nat_diff == 0);
    FH_CHECK(status_diff == 0);
    /* Every point conducts: no call silently failed to 0 in both runs. */
    {
        long zero = 0;
        for (i = 0; i < n_points; i++) {
            zero += !(ak_ser[i] > 0.0);
        }
        FH_CHECK(zero == 0);
    }
    printf("%d gapcon_ calls on %d threads and %d serial, %d ifl_gap_conductance calls each; "
           "%ld AK(1) differences\n", n_points, N_THREADS, n_points, n_points / 4, ak_diff);
    if (log != NULL && log[0] != '\0') {
        check_log(log);
    }
    pthread_barrier_destroy(&start_line);
    pthread_barrier_destroy(&failed_line);
    free(points);
    free(ak_par);
    free(ak_ser);
    free(nat_par);
    free(nat_ser);
    free(status_par);
    free(status_ser);
    return fh_finish();
}
