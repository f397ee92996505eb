/*
 * harness.h: the host side of FRIC for the C harnesses (header-only).
 *
 * An fh_fric holds every FRIC argument the way a Fortran FE code keeps them, with arrays sized
 * for NFDIR <= 3 plus guard slots, and fh_call() passes them to fric_ exactly as gfortran does:
 * everything by reference, the three names as blank-padded CHARACTER buffers with their hidden
 * lengths (80 for CHARACTER*80) after the 39 explicit arguments.
 *
 * Every fh_call() also checks two invariants of the contract (docs/calling-conventions.md,
 * docs/fric.md): nothing is written past NFDIR / NFDIR^2 / 2*NFDIR / NSTATV (guard slots keep
 * FH_GUARD), and no input argument is written.
 *
 * Checks count passes and failures; fh_finish() prints the last line "N passed, N failed" and
 * returns the exit status (non-zero on any failure, or when nothing was checked at all).
 */
#ifndef FRIC_HARNESS_H
#define FRIC_HARNESS_H

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "interfacial.h"
#include "props_index.h"

#if defined(__GNUC__)
#define FH_PRINTF(fmt_index, first_arg) __attribute__((format(printf, fmt_index, first_arg)))
#else
#define FH_PRINTF(fmt_index, first_arg)
#endif

enum {
    FH_MAXDIR = 3,                               /* a bad NFDIR = 3 still stays inside */
    FH_VEC = FH_MAXDIR + 1,                      /* TAU(NFDIR) + at least one guard */
    FH_MAT = FH_MAXDIR * FH_MAXDIR + 1,          /* DDTDDG(NFDIR,NFDIR) + guard */
    FH_DDT = 2 * FH_MAXDIR + 1,                  /* DDTDDT(NFDIR,2) + guard */
    FH_MAXSTATV = 12,                            /* STATEV(NSTATV) + guards after NSTATV */
    FH_MAXPROPS = 20,                            /* PROPS(1..20): the extended Coulomb layout */
    FH_NAMEBUF = 96                              /* room for bytes past a short hidden length */
};

/* Written into every slot past the sizes the host declared; fric_ must never touch them. */
#define FH_GUARD (-7.77e77)
/* PNEWDT as Abaqus passes it on every call: large, so only a cut-back lowers it. */
#define FH_PNEWDT_IN 1e36
/* What a failed call must leave in PNEWDT (the library's cut-back ratio, docs/fric.md). */
#define FH_CUTBACK 0.25
#define FH_PI 3.14159265358979323846
/* All FRIC arguments of one contact point, in Fortran (column-major) layout. */
typedef struct {
    int lm;                      /* LM */
    double tau[FH_VEC];          /* TAU(NFDIR) */
    double ddtddg[FH_MAT];       /* DDTDDG(NFDIR,NFDIR): (a,b) at [(a-1) + (b-1)*NFDIR] */
    double ddtddp[FH_VEC];       /* DDTDDP(NFDIR) */
    double dslip[FH_VEC];        /* DSLIP(NFDIR) */
    double sed, sfd;             /* SED, SFD */
    double ddtddt[FH_DDT];       /* DDTDDT(NFDIR,2) */
    double pnewdt;               /* PNEWDT */
    double statev[FH_MAXSTATV];  /* STATEV(NSTATV) */
    double dgam[FH_VEC];         /* DGAM(NFDIR) */
    double taulm[FH_VEC];        /* TAULM(NFDIR) */
    double press, dpress, ddpddh;
    double slip[FH_VEC];         /* SLIP(NFDIR) */
    int kstep, kinc;
    double time[2], dtime;
    int noel;
    char ciname[FH_NAMEBUF], slname[FH_NAMEBUF], msname[FH_NAMEBUF];
    size_t ciname_len, slname_len, msname_len; /* hidden lengths */
    int npt, node, npatch;
    double coords[3], rcoord[3];
    double drot[4];              /* DROT(2,2) */
    double temp[2];
    double predef[2];            /* PREDEF(2,NPRED), NPRED = 1 */
    int nfdir, mcrd, npred, nstatv;
    double chrlngth;
    double props[FH_MAXPROPS];
    int nprops;
} fh_fric;

/* ---------------------------------------------------------------------------------------- */
/* Pass/fail bookkeeping                                                                     */

static int fh_passed;
static int fh_failed;
static char fh_where[256]; /* what the driver is doing, printed with each failure */

enum { FH_MAX_PRINTED_FAILURES = 60 };

static inline void fh_context(const char *fmt, ...) FH_PRINTF(1, 2);
static inline void fh_context(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(fh_where, sizeof fh_where, fmt, ap);
    va_end(ap);
}

static inline void fh_fail_header(const char *file, int line)
{
    if (fh_failed == FH_MAX_PRINTED_FAILURES) {
        fprintf(stderr, "(further failures are counted but not printed)\n");
    }
    if (fh_failed < FH_MAX_PRINTED_FAILURES) {
        fprintf(stderr, "FAIL %s:%d [%s]: ", file, line, fh_where);
    }
}

static inline int fh_check_(int ok, const char *file, int line, const char *expr)
{
    if (ok) {
        fh_passed++;
        return 1;
    }
    fh_fail_header(file, line);
    if (fh_failed < FH_MAX_PRINTED_FAILURES) {
        fprintf(stderr, "%s\n", expr);
    }
    fh_failed++;
    return 0;
}

/* |got - want| <= atol + rtol*|want|; NaN never passes. */
static inline int fh_near_(double got, double want, double rtol, double atol, const char *file,
                           int line, const char *got_expr, const char *want_expr)
{
    double err = fabs(got - want);
    if (err <= atol + rtol * fabs(want)) {
        fh_passed++;
        return 1;
    }
    fh_fail_header(file, line);
    if (fh_failed < FH_MAX_PRINTED_FAILURES) {
        fprintf(stderr, "%s = %.17g, expected %s = %.17g (error %.3g, rtol %.1g, atol %.1g)\n",
                got_expr, got, want_expr, want, err, rtol, atol);
    }
    fh_failed++;
    return 0;
}

static inline int fh_contains_(const char *hay, const char *needle, const char *file, int line)
{
    if (hay != NULL && strstr(hay, needle) != NULL) {
        fh_passed++;
        return 1;
    }
    fh_fail_header(file, line);
    if (fh_failed < FH_MAX_PRINTED_FAILURES) {
        fprintf(stderr, "\"%s\" does not contain \"%s\"\n", hay ? hay : "(null)", needle);
    }
    fh_failed++;
    return 0;
}

#define FH_CHECK(cond) fh_check_(!!(cond), __FILE__, __LINE__, #cond)
#define FH_NEAR(got, want, rtol, atol) \
    fh_near_((got), (want), (rtol), (atol), __FILE__, __LINE__, #got, #want)
#define FH_EXACT(got, want) FH_NEAR((got), (want), 0.0, 0.0)
#define FH_CONTAINS(hay, needle) fh_contains_((hay), (needle), __FILE__, __LINE__)

/* The last line of every harness; returns the process exit status. */
static inline int fh_finish(void)
{
    printf("%d passed, %d failed\n", fh_passed, fh_failed);
    fflush(stdout);
    /* A harness that checked nothing proves nothing. */
    return (fh_failed == 0 && fh_passed > 0) ? 0 : 1;
}

/*
 * The library's log file (INTERFACIAL_LOG, which must name `path`) holds exactly the n distinct
 * messages seen (rows of `stride` bytes, each NUL-terminated), once each, in order of first
 * appearance. A line past the n-th is printed to stderr.
 */
static inline void fh_check_log(const char *path, const char *seen, size_t stride, int n)
{
    char line[2048];
    int lines = 0, in_order = 1;
    FILE *f = fopen(path, "r");
    const char *env = getenv("INTERFACIAL_LOG");
    fh_context("INTERFACIAL_LOG %s", path);
    FH_CHECK(env != NULL && strcmp(env, path) == 0);
    if (!FH_CHECK(f != NULL)) {
        return;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        line[strcspn(line, "\n")] = '\0';
        if (lines < n) {
            in_order &= strcmp(line, seen + (size_t)lines * stride) == 0;
        } else {
            fprintf(stderr, "  extra log line: %s\n", line);
        }
        lines++;
    }
    fclose(f);
    FH_CHECK(in_order);
    FH_CHECK(lines == n);
    printf("%d distinct messages, %d lines in the log\n", n, lines);
}

/* ---------------------------------------------------------------------------------------- */
/* The host                                                                                  */

/* A Fortran CHARACTER*len actual argument: `text` blank-padded to `len` bytes, no NUL. */
static inline void fh_set_name(char *buf, size_t *buf_len, size_t len, const char *text)
{
    size_t n = strlen(text);
    if (len > FH_NAMEBUF) {
        len = FH_NAMEBUF;
    }
    memset(buf, ' ', FH_NAMEBUF);
    memcpy(buf, text, n < len ? n : len);
    *buf_len = len;
}

/* A whole Coulomb PROPS layout (IFLP_COULOMB_NPROPS entries): law 1 with μ, every other entry
 * 0 (its default); the caller sets the entries its scene means. */
static inline void fh_props_coulomb(double *props, double mu)
{
    int i;
    for (i = 0; i < IFLP_COULOMB_NPROPS; i++) {
        props[i] = 0.0;
    }
    props[IFLP_COULOMB_CODE] = IFLP_LAW_COULOMB;
    props[IFLP_COULOMB_MU] = mu;
}

static inline int fh_clamp(int v, int lo, int hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* Fills every output slot past NFDIR, NFDIR^2, 2*NFDIR and NSTATV with FH_GUARD. */
static inline void fh_set_guards(fh_fric *h)
{
    int n = fh_clamp(h->nfdir, 0, FH_MAXDIR);
    int ns = fh_clamp(h->nstatv, 0, FH_MAXSTATV);
    int i;
    for (i = n; i < FH_VEC; i++) {
        h->tau[i] = FH_GUARD;
        h->ddtddp[i] = FH_GUARD;
        h->dslip[i] = FH_GUARD;
    }
    for (i = n * n; i < FH_MAT; i++) {
        h->ddtddg[i] = FH_GUARD;
    }
    for (i = 2 * n; i < FH_DDT; i++) {
        h->ddtddt[i] = FH_GUARD;
    }
    for (i = ns; i < FH_MAXSTATV; i++) {
        h->statev[i] = FH_GUARD;
    }
}

/* True when every guard slot still holds FH_GUARD. */
static inline int fh_guards_intact(const fh_fric *h)
{
    int n = fh_clamp(h->nfdir, 0, FH_MAXDIR);
    int ns = fh_clamp(h->nstatv, 0, FH_MAXSTATV);
    int ok = 1;
    int i;
    for (i = n; i < FH_VEC; i++) {
        ok &= h->tau[i] == FH_GUARD && h->ddtddp[i] == FH_GUARD && h->dslip[i] == FH_GUARD;
    }
    for (i = n * n; i < FH_MAT; i++) {
        ok &= h->ddtddg[i] == FH_GUARD;
    }
    for (i = 2 * n; i < FH_DDT; i++) {
        ok &= h->ddtddt[i] == FH_GUARD;
    }
    for (i = ns; i < FH_MAXSTATV; i++) {
        ok &= h->statev[i] == FH_GUARD;
    }
    return ok;
}

#define FH_SAME(field) (memcmp(&a->field, &b->field, sizeof a->field) == 0)
/* True when no input argument differs between a and b (bitwise, so NaN inputs compare too). */
static inline int fh_inputs_same(const fh_fric *a, const fh_fric *b)
{
    return FH_SAME(dgam) && FH_SAME(taulm) && FH_SAME(press) && FH_SAME(dpress) &&
           FH_SAME(ddpddh) && FH_SAME(slip) && FH_SAME(kstep) && FH_SAME(kinc) &&
           FH_SAME(time) && FH_SAME(dtime) && FH_SAME(noel) && FH_SAME(ciname) &&
           FH_SAME(slname) && FH_SAME(msname) && FH_SAME(npt) && FH_SAME(node) &&
           FH_SAME(npatch) && FH_SAME(coords) && FH_SAME(rcoord) && FH_SAME(drot) &&
           FH_SAME(temp) && FH_SAME(predef) && FH_SAME(nfdir) && FH_SAME(mcrd) &&
           FH_SAME(npred) && FH_SAME(nstatv) && FH_SAME(chrlngth) && FH_SAME(props) &&
           FH_SAME(nprops);
}
#undef FH_SAME

/*
 * A closed contact point of interaction "SI_PAD" (element 17, node 42, point 3) with NFDIR
 * friction directions and the given PROPS; NSTATV = 3, state and stress zero, identity DROT,
 * DTIME = 1, every output slot past its size a guard.
 */
static inline void fh_init(fh_fric *h, int nfdir, const double *props, int nprops)
{
    int i;
    memset(h, 0, sizeof *h);
    h->lm = 0;
    h->pnewdt = FH_PNEWDT_IN;
    h->ddpddh = 1e6;
    h->kstep = 1;
    h->kinc = 1;
    h->dtime = 1.0;
    h->noel = 17;
    h->node = 42;
    h->npt = 3;
    h->npatch = 5;
    fh_set_name(h->ciname, &h->ciname_len, 80, "SI_PAD");
    fh_set_name(h->slname, &h->slname_len, 80, "SLAVE_SURF");
    fh_set_name(h->msname, &h->msname_len, 80, "MASTER_SURF");
    h->drot[0] = 1.0;
    h->drot[3] = 1.0;
    h->temp[0] = h->temp[1] = 20.0;
    h->nfdir = nfdir;
    h->mcrd = 3;
    h->npred = 1;
    h->nstatv = 3;
    h->chrlngth = 1.0;
    for (i = 0; i < nprops && i < FH_MAXPROPS; i++) {
        h->props[i] = props[i];
    }
    h->nprops = nprops;
    fh_set_guards(h);
}

/* The point of fh_init at first contact (PRESS = DPRESS = p) with time increment dtime and the
 * whole Coulomb layout, for a scene that slides it increment by increment. */
static inline void fh_init_contact(fh_fric *h, int nfdir, const double *props, double p,
                                   double dtime)
{
    fh_init(h, nfdir, props, IFLP_COULOMB_NPROPS);
    h->press = p;
    h->dpress = p;
    h->dtime = dtime;
}

/* The raw call, as gfortran makes it for CALL FRIC(...) with CHARACTER*(*) names. */
static inline void fh_call_raw(fh_fric *h)
{
    fric_(&h->lm, h->tau, h->ddtddg, h->ddtddp, h->dslip, &h->sed, &h->sfd, h->ddtddt,
          &h->pnewdt, h->statev, h->dgam, h->taulm, &h->press, &h->dpress, &h->ddpddh, h->slip,
          &h->kstep, &h->kinc, h->time, &h->dtime, &h->noel, h->ciname, h->slname, h->msname,
          &h->npt, &h->node, &h->npatch, h->coords, h->rcoord, h->drot, h->temp, h->predef,
          &h->nfdir, &h->mcrd, &h->npred, &h->nstatv, &h->chrlngth, h->props, &h->nprops,
          h->ciname_len, h->slname_len, h->msname_len);
}

/*
 * One call from a host that passes PNEWDT = pnewdt_in (FH_PNEWDT_IN, or less when another routine
 * of the increment already asked for a smaller one), guards refreshed, then after the call the
 * guard slots and every input argument are checked unchanged.
 */
static inline void fh_call_from(fh_fric *h, double pnewdt_in)
{
    fh_fric before;
    h->pnewdt = pnewdt_in;
    fh_set_guards(h);
    before = *h;
    fh_call_raw(h);
    FH_CHECK(fh_guards_intact(h));
    FH_CHECK(fh_inputs_same(h, &before));
}

/* One call from the host: PNEWDT set large as Abaqus does (fh_call_from). */
static inline void fh_call(fh_fric *h)
{
    fh_call_from(h, FH_PNEWDT_IN);
}

/*
 * A call that must succeed: as fh_call, and also PNEWDT not lowered and no error reported
 * (the thread's last error is cleared before the call).
 */
static inline void fh_call_ok(fh_fric *h)
{
    ifl_clear_error();
    fh_call(h);
    FH_CHECK(h->pnewdt == FH_PNEWDT_IN);
    FH_CHECK(ifl_last_error()[0] == '\0');
}

/* DDTDDG(a,b), 1-based as in Fortran. */
static inline double fh_ddtddg(const fh_fric *h, int a, int b)
{
    return h->ddtddg[(a - 1) + (b - 1) * h->nfdir];
}

/*
 * Steady sliding: n increments at the slip rate v along the unit direction d (DGAM = v DTIME d),
 * each a call that must succeed with LM = 0; DPRESS is set to 0 after the first. Returns the
 * magnitude of TAU after the last.
 */
static inline double fh_slide(fh_fric *h, const double *d, double v, int n)
{
    double tau_eq = 0.0;
    int k, a;
    for (k = 0; k < n; k++) {
        for (a = 0; a < h->nfdir; a++) {
            h->dgam[a] = v * h->dtime * d[a];
        }
        fh_call_ok(h);
        FH_CHECK(h->lm == 0);
        h->dpress = 0.0;
    }
    for (a = 0; a < h->nfdir; a++) {
        tau_eq += h->tau[a] * h->tau[a];
    }
    return sqrt(tau_eq);
}

/*
 * Scene F4's velocity steps (docs/scene-definitions.md) for a rate law with these PROPS (the
 * Coulomb layout), from first contact at pressure p with DTIME dt: slip at each of the n rates
 * in turn, 40 increments each, along d (NFDIR 1: t1; NFDIR 2: (0.6, 0.8)); once steady
 * |TAU| = mu(v) p and STATEV(2) = v, to the relative tolerance rtol. then(h, d, v), unless NULL,
 * checks what else the harness wants at each steady rate. Failures name the scene, NFDIR, the
 * stick mode and frozen switch (PROPS(7), PROPS(20)) and v.
 */
static inline void fh_velocity_steps(const char *scene, int nfdir, const double *props, double p,
                                     double dt, const double *rates, int n, double (*mu)(double),
                                     double rtol,
                                     void (*then)(const fh_fric *h, const double *d, double v))
{
    const double d[2] = {nfdir == 1 ? 1.0 : 0.6, nfdir == 1 ? 0.0 : 0.8};
    fh_fric h;
    int s;
    fh_init_contact(&h, nfdir, props, p, dt);
    for (s = 0; s < n; s++) {
        const double v = rates[s];
        fh_context("%s NFDIR=%d exact=%g frozen=%g v=%g", scene, nfdir,
                   props[IFLP_COULOMB_STICK], props[IFLP_COULOMB_FROZEN], v);
        FH_NEAR(fh_slide(&h, d, v, 40), mu(v) * p, rtol, 0.0);
        FH_NEAR(h.statev[1], v, rtol, 0.0);
        if (then != NULL) {
            then(&h, d, v);
        }
    }
}

/*
 * scene(nfdir, a, b) for NFDIR = 1 and 2 and each setting of two on/off switches a and b (the
 * variants a harness crosses, e.g. exact stick and frozen rate), NFDIR outermost, then a.
 */
static inline void fh_each_nfdir_and_switches(void (*scene)(int nfdir, int a, int b))
{
    int nfdir, a, b;
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        for (a = 0; a <= 1; a++) {
            for (b = 0; b <= 1; b++) {
                scene(nfdir, a, b);
            }
        }
    }
}

/*
 * The slip tangent along the unit direction d (NFDIR entries) against a central difference of
 * fric_'s own TAU: d . DDTDDG . d at the increment h against
 * d . (TAU(DGAM + hg d) - TAU(DGAM - hg d)) / (2 hg), hg = 1e-9, to the absolute tolerance atol.
 * Three calls that must succeed, on copies of h.
 */
static inline void fh_check_tangent_along(const fh_fric *h, const double *d, double atol)
{
    fh_fric base = *h, plus = *h, minus = *h;
    const double hg = 1e-9;
    double an = 0.0, fd = 0.0;
    int a, b;
    fh_call_ok(&base);
    for (a = 0; a < h->nfdir; a++) {
        plus.dgam[a] += hg * d[a];
        minus.dgam[a] -= hg * d[a];
    }
    fh_call_ok(&plus);
    fh_call_ok(&minus);
    for (a = 0; a < h->nfdir; a++) {
        fd += d[a] * (plus.tau[a] - minus.tau[a]) / (2.0 * hg);
        for (b = 0; b < h->nfdir; b++) {
            an += d[a] * fh_ddtddg(&base, a + 1, b + 1) * d[b];
        }
    }
    FH_NEAR(an, fd, 0.0, atol);
}

/*
 * The thread's last message copied into msg (len bytes): not empty, naming the routine, the
 * quoted interaction and the place of the call (where); the caller checks the cause.
 */
static inline void fh_check_last_message(char *msg, size_t len, const char *routine,
                                         const char *quoted, const char *where)
{
    snprintf(msg, len, "%s", ifl_last_error());
    FH_CHECK(msg[0] != '\0');
    FH_CONTAINS(msg, routine);
    FH_CONTAINS(msg, quoted);
    FH_CONTAINS(msg, where);
}

/*
 * A call that must be refused: PNEWDT < 1, the message names FRIC and contains n1 and (unless
 * NULL) n2, TAU(1..NFDIR) and STATEV(1..3) unchanged. The caller sets the state first.
 */
static inline void fh_check_refused(fh_fric *h, const char *n1, const char *n2)
{
    fh_fric before = *h;
    int i;
    ifl_clear_error();
    fh_call(h);
    FH_CHECK(h->pnewdt < 1.0);
    FH_CONTAINS(ifl_last_error(), "FRIC");
    FH_CONTAINS(ifl_last_error(), n1);
    if (n2 != NULL) {
        FH_CONTAINS(ifl_last_error(), n2);
    }
    for (i = 0; i < h->nfdir; i++) {
        FH_EXACT(h->tau[i], before.tau[i]);
    }
    for (i = 0; i < 3; i++) {
        FH_EXACT(h->statev[i], before.statev[i]);
    }
}

#endif /* FRIC_HARNESS_H */
