/*
 * thread_harness.h: what the C thread harnesses (test_*_threads.c) share (header-only).
 *
 * Each of them runs the same work twice, once split over TH_THREADS pthreads released together
 * by a barrier and once serially on the main thread, and compares the two bit for bit. This
 * header holds the parts that are the same in all of them:
 *   - th_lehmer / th_uniform: the MINSTD generator (x <- 48271 x mod 2^31 - 1) a harness seeds
 *     per point or per block, so a draw never depends on which thread makes it (the serial
 *     harnesses that draw random points, test_fric_batch.c, include this header for it);
 *   - th_fnv: 64-bit FNV-1a over bytes, from TH_FNV_OFFSET, to digest a call's outputs;
 *   - th_shrink_factor: INTERFACIAL_TEST_SHRINK=n (valgrind, ASan runs), clamped;
 *   - th_tally: the counts a run keeps (kinds of call, points, violations, the first violation
 *     in words), th_violation to record one, th_report to print a run's counts;
 *   - th_run_threads: split [0, n) into TH_THREADS contiguous ranges, run a harness's range
 *     function on each from the start barrier, join, and add up the threads' tallies;
 *   - th_count_differences: how many digests differ between the runs, the first few printed;
 *   - th_block_runs / th_point_runs: both runs of a harness whose item writes one digest (a
 *     block of points) or a digest per increment and a final record (a point carried over
 *     increments), each run reported and checked, then compared bit for bit.
 * What a harness checks (the law, the messages, which outputs are digested) stays in it.
 */
#ifndef THREAD_HARNESS_H
#define THREAD_HARNESS_H

#include <pthread.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"

#if defined(__GNUC__)
#define TH_PRINTF(fmt_index, first_arg) __attribute__((format(printf, fmt_index, first_arg)))
#else
#define TH_PRINTF(fmt_index, first_arg)
#endif

enum { TH_THREADS = 8, TH_MAX_KINDS = 16 };

/* ---- Lehmer generator (MINSTD): x <- 48271 x mod (2^31 - 1) ---------------------------- */
#define TH_LEHMER_M 2147483647u
static inline uint32_t th_lehmer(uint32_t *x)
{
    *x = (uint32_t)(((uint64_t)*x * 48271u) % TH_LEHMER_M);
    return *x;
}
/* The generator's state for block b of a block harness: b scattered by Knuth's multiplicative
 * hash (mod 2^32) into [1, m - 1], then advanced once. */
static inline uint32_t th_block_seed(int b)
{
    uint32_t x = (uint32_t)b * 2654435761u % (TH_LEHMER_M - 1u) + 1u;
    th_lehmer(&x);
    return x;
}
/* A draw in [lo, hi) from the generator's next value. */
static inline double th_uniform(uint32_t *x, double lo, double hi)
{
    return lo + (hi - lo) * ((double)(th_lehmer(x) - 1u) / (double)(TH_LEHMER_M - 1u));
}

/* ---- 64-bit FNV-1a over bytes ----------------------------------------------------------- */
#define TH_FNV_OFFSET 14695981039346656037u
static inline uint64_t th_fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    size_t i;
    for (i = 0; i < n; i++) {
        h = (h ^ b[i]) * 1099511628211u;
    }
    return h;
}

/* ---- A block harness's buffers ---------------------------------------------------------- */
/* n doubles from malloc, each v (a guard or a start value); NULL when out of memory. */
static inline double *th_filled(size_t n, double v)
{
    double *a = malloc(sizeof(double) * n);
    size_t i;
    for (i = 0; a != NULL && i < n; i++) {
        a[i] = v;
    }
    return a;
}
/* The interaction name of block b as a Fortran host passes it: prefix and b, blank-padded to
 * 80 characters (no NUL); blank the blank name of the other two CHARACTER*80 arguments. */
static inline void th_block_names(char name[80], char blank[80], const char *prefix, int b)
{
    char text[32];
    int len = snprintf(text, sizeof text, "%s%d", prefix, b);
    memset(name, ' ', 80);
    memset(blank, ' ', 80);
    memcpy(name, text, (size_t)(len < 32 ? len : 31));
}

/* INTERFACIAL_TEST_SHRINK=n divides a harness's size by n; at most max_shrink, at least 1. */
static inline int th_shrink_factor(int max_shrink)
{
    const char *s = getenv("INTERFACIAL_TEST_SHRINK");
    long v = s != NULL ? strtol(s, NULL, 10) : 1;
    if (v < 1) {
        return 1;
    }
    return v > max_shrink ? max_shrink : (int)v;
}

/* ---- What one run (or one thread of it) counts ------------------------------------------ */
typedef struct {
    long kinds[TH_MAX_KINDS]; /* calls or blocks of each kind the harness names */
    long points;              /* point evaluations: a block's points, or a point's calls */
    long bad_points;          /* points drawn bad on purpose */
    long msg_bad;             /* refused calls whose last error does not name the point */
    long alloc_fail;
    long violations;          /* calls that broke a check of the law */
    char first_violation[256];
} th_tally;

/* Counts one violation; the first one is kept in words. */
static inline void th_violation(th_tally *t, const char *fmt, ...) TH_PRINTF(2, 3);
static inline void th_violation(th_tally *t, const char *fmt, ...)
{
    if (t->violations++ == 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(t->first_violation, sizeof t->first_violation, fmt, ap);
        va_end(ap);
    }
}

/* sum += t, keeping the first violation of the first thread that had one. */
static inline void th_tally_add(th_tally *sum, const th_tally *t)
{
    int k;
    for (k = 0; k < TH_MAX_KINDS; k++) {
        sum->kinds[k] += t->kinds[k];
    }
    sum->points += t->points;
    sum->bad_points += t->bad_points;
    sum->msg_bad += t->msg_bad;
    sum->alloc_fail += t->alloc_fail;
    sum->violations += t->violations;
    if (sum->first_violation[0] == '\0') {
        memcpy(sum->first_violation, t->first_violation, sizeof sum->first_violation);
    }
}

/* "<run>: <head>; <name> <count>, ... <unit>", the head printed from head_fmt and what
 * follows it; then the first violation on stderr. */
static inline void th_report(const char *run, const th_tally *t, const char *const *names,
                             int n_kinds, const char *unit, const char *head_fmt, ...)
    TH_PRINTF(6, 7);
static inline void th_report(const char *run, const th_tally *t, const char *const *names,
                             int n_kinds, const char *unit, const char *head_fmt, ...)
{
    va_list ap;
    int k;
    printf("%s: ", run);
    va_start(ap, head_fmt);
    vprintf(head_fmt, ap);
    va_end(ap);
    printf(";");
    for (k = 0; k < n_kinds; k++) {
        printf(" %s %ld%s", names[k], t->kinds[k], k + 1 < n_kinds ? "," : "");
    }
    printf("%s\n", unit);
    if (t->violations > 0) {
        fprintf(stderr, "  %s: %ld violations, first: %s\n", run, t->violations,
                t->first_violation);
    }
}

/* ---- The parallel run ------------------------------------------------------------------ */
/* A harness's work on items [first, last), counting into t; ctx is the harness's own. */
typedef void (*th_range_fn)(int first, int last, void *ctx, th_tally *t);

typedef struct {
    int first, last;
    th_range_fn fn;
    void *ctx;
    pthread_barrier_t *start_line;
    th_tally t;
} th_worker;

static inline void *th_work(void *arg)
{
    th_worker *w = arg;
    pthread_barrier_wait(w->start_line);
    w->fn(w->first, w->last, w->ctx, &w->t);
    return NULL;
}

/*
 * Items [0, n) on TH_THREADS threads, thread i taking [n i / T, n (i + 1) / T), all started
 * together; their tallies added into *sum. Returns 0 when a thread could not be created: the
 * others then wait at the barrier forever, so the caller must end the program, not join.
 */
static inline int th_run_threads(int n, th_range_fn fn, void *ctx, th_tally *sum)
{
    /* Static: on a failed creation the threads already started keep waiting on them. */
    static th_worker w[TH_THREADS];
    static pthread_barrier_t start_line;
    pthread_t tid[TH_THREADS];
    int i, created = 0;

    memset(w, 0, sizeof w);
    pthread_barrier_init(&start_line, NULL, TH_THREADS);
    for (i = 0; i < TH_THREADS; i++) {
        w[i].first = (int)((long)n * i / TH_THREADS);
        w[i].last = (int)((long)n * (i + 1) / TH_THREADS);
        w[i].fn = fn;
        w[i].ctx = ctx;
        w[i].start_line = &start_line;
        if (pthread_create(&tid[i], NULL, th_work, &w[i]) != 0) {
            return 0;
        }
        created++;
    }
    for (i = 0; i < created; i++) {
        pthread_join(tid[i], NULL);
        th_tally_add(sum, &w[i].t);
    }
    pthread_barrier_destroy(&start_line);
    return 1;
}

/* How many of n digests differ; the first five printed as "<item> <i / per>, <sub> <i % per>". */
static inline long th_count_differences(const uint64_t *par, const uint64_t *ser, size_t n,
                                        size_t per, const char *item, const char *sub)
{
    long diff = 0;
    size_t j;
    for (j = 0; j < n; j++) {
        if (par[j] != ser[j] && diff++ < 5) {
            if (per > 1) {
                fprintf(stderr, "  %s %zu, %s %zu: outputs differ\n", item, j / per, sub, j % per);
            } else {
                fprintf(stderr, "  %s %zu: outputs differ\n", item, j);
            }
        }
    }
    return diff;
}

/* A run's report: "<run>: <counts> ..." (th_report with the harness's own head). */
typedef void (*th_report_fn)(const char *run, const th_tally *t);

/* The checks every run makes of its own tally. */
static inline void th_check_run(const th_tally *t)
{
    FH_CHECK(t->alloc_fail == 0);
    FH_CHECK(t->violations == 0);
    FH_CHECK(t->msg_bad == 0);
}

/* One block b of a run: calls the entry point, checks it, returns the digest of its outputs. */
typedef uint64_t (*th_block_fn)(int b, th_tally *t);

typedef struct {
    th_block_fn block;
    uint64_t *digests; /* [b] */
} th_block_run;

/* Blocks [first, last) of a run, each with this thread's last error cleared first. */
static inline void th_blocks(int first, int last, void *ctx, th_tally *t)
{
    th_block_run *r = ctx;
    int b;
    for (b = first; b < last; b++) {
        ifl_clear_error();
        r->digests[b] = r->block(b, t);
    }
}

/*
 * Both runs of a harness of n blocks (full size divided by shrink): on TH_THREADS threads, then
 * serially on this thread; each reported and checked (no allocation failure, no violation, no
 * bad message); then the same digests, the same counts of each kind, of points and of bad
 * points; at least 1M point evaluations at full size and every kind (names[0..n_kinds)) in at
 * least one block in 2 n_kinds. par and ser receive the runs' tallies. Returns 0 when the harness
 * must stop at once (no memory, or a thread not created).
 */
static inline int th_block_runs(int n, int shrink, th_block_fn block, th_report_fn report,
                                const char *const *names, int n_kinds, th_tally *par,
                                th_tally *ser)
{
    th_block_run par_run = {block, calloc((size_t)n, sizeof(uint64_t))};
    th_block_run ser_run = {block, calloc((size_t)n, sizeof(uint64_t))};
    long diff;
    int k;

    memset(par, 0, sizeof *par);
    memset(ser, 0, sizeof *ser);
    fh_context("allocation");
    if (!FH_CHECK(par_run.digests != NULL && ser_run.digests != NULL)) {
        return 0;
    }
    fh_context("%d threads, %d blocks", TH_THREADS, n);
    if (!FH_CHECK(th_run_threads(n, th_blocks, &par_run, par))) {
        return 0; /* the barrier would never open */
    }
    report("8 threads", par);
    th_check_run(par);

    fh_context("serial run");
    th_blocks(0, n, &ser_run, ser);
    report("serial", ser);
    th_check_run(ser);

    fh_context("8 threads against the serial run");
    FH_CHECK(memcmp(par_run.digests, ser_run.digests, sizeof(uint64_t) * (size_t)n) == 0);
    FH_CHECK(memcmp(par->kinds, ser->kinds, sizeof par->kinds) == 0);
    FH_CHECK(par->points == ser->points);
    FH_CHECK(par->bad_points == ser->bad_points);
    /* At least 1M point evaluations at full size; every kind well represented. */
    FH_CHECK(par->points >= 1000000L / shrink);
    for (k = 0; k < n_kinds; k++) {
        fh_context("blocks of kind %s", names[k]);
        FH_CHECK(par->kinds[k] >= n / (2 * n_kinds));
    }
    diff = th_count_differences(par_run.digests, ser_run.digests, (size_t)n, 1, "block", "");
    printf("blocks whose outputs differ between the runs: %ld of %d\n", diff, n);
    free(par_run.digests);
    free(ser_run.digests);
    return 1;
}

/* A point carried over incs increments: digests[inc] for each call, its final record in *fin
 * (th_points counts the calls in the tally's points). */
typedef void (*th_point_fn)(int point, uint64_t *digests, void *fin, th_tally *t);

typedef struct {
    th_point_fn point;
    int incs;
    size_t fin_size;
    uint64_t *digests; /* [point * incs + inc] */
    unsigned char *finals; /* [point * fin_size] */
} th_point_run;

static inline void th_points(int first, int last, void *ctx, th_tally *t)
{
    th_point_run *r = ctx;
    int p;
    for (p = first; p < last; p++) {
        r->point(p, r->digests + (size_t)p * (size_t)r->incs, r->finals + (size_t)p * r->fin_size,
                 t);
        t->points += r->incs; /* calls */
    }
}

/*
 * Both runs of a harness of n points over incs increments (the entry point is named in the
 * summary line): on TH_THREADS threads, then serially; each reported and checked; every kind of
 * call (names[0..n_kinds)) at least once and in at least 1 in 2000 calls of the serial run; then
 * the same counts, every call's digest and every point's final record (fin_size bytes, zero-padded
 * by the harness) bit for bit. Returns 0 when the harness must stop at once.
 */
static inline int th_point_runs(const char *entry, int n, int incs, th_point_fn point,
                                size_t fin_size, th_report_fn report, const char *const *names,
                                int n_kinds)
{
    size_t calls = (size_t)n * (size_t)incs;
    th_point_run par_run = {point, incs, fin_size, calloc(calls, sizeof(uint64_t)),
                            calloc((size_t)n, fin_size)};
    th_point_run ser_run = {point, incs, fin_size, calloc(calls, sizeof(uint64_t)),
                            calloc((size_t)n, fin_size)};
    th_tally par, ser;
    long diff, fdiff = 0;
    int p, k;

    memset(&par, 0, sizeof par);
    memset(&ser, 0, sizeof ser);
    fh_context("allocation");
    if (!FH_CHECK(par_run.digests != NULL && par_run.finals != NULL && ser_run.digests != NULL &&
                  ser_run.finals != NULL)) {
        return 0;
    }
    fh_context("%d threads, %d points x %d increments", TH_THREADS, n, incs);
    if (!FH_CHECK(th_run_threads(n, th_points, &par_run, &par))) {
        return 0; /* the barrier would never open */
    }
    report("8 threads", &par);
    th_check_run(&par);

    fh_context("serial run");
    th_points(0, n, &ser_run, &ser);
    report("serial", &ser);
    th_check_run(&ser);
    for (k = 0; k < n_kinds; k++) {
        fh_context("serial run: %s calls", names[k]);
        FH_CHECK(ser.kinds[k] > 0 && ser.kinds[k] >= (long)(calls / 2000));
    }

    fh_context("8 threads against serial, bit for bit");
    FH_CHECK(par.points == (long)calls && ser.points == (long)calls);
    FH_CHECK(memcmp(par.kinds, ser.kinds, sizeof par.kinds) == 0);
    diff = th_count_differences(par_run.digests, ser_run.digests, calls, (size_t)incs, "point",
                                "increment");
    for (p = 0; p < n; p++) {
        fdiff += memcmp(par_run.finals + (size_t)p * fin_size,
                        ser_run.finals + (size_t)p * fin_size, fin_size) != 0;
    }
    FH_CHECK(diff == 0);
    FH_CHECK(fdiff == 0);
    printf("%zu %s calls on %d threads and %zu serial: %ld calls and %ld final states differ\n",
           calls, entry, TH_THREADS, calls, diff, fdiff);
    free(par_run.digests);
    free(par_run.finals);
    free(ser_run.digests);
    free(ser_run.finals);
    return 1;
}

#endif
