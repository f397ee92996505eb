/*
 * gapcon_harness.h: the host side of GAPCON for the C harnesses (header-only).
 *
 * A gh_gapcon holds every GAPCON argument the way a Fortran FE code keeps them (AK(5) plus
 * guard slots, D(2), FLOWM(2), TEMP(2), PREDEF(2,1), TIME(2), CHARACTER*80 names, COORDS(3),
 * NOEL, NODE, NPRED, KSTEP, KINC and, for the CalculiX variant, AREA), and gh_call() passes
 * them to gapcon_ exactly as gfortran does: everything by reference, the three names as
 * blank-padded buffers with their hidden size_t lengths after the explicit arguments.
 *
 * Every gh_call() checks the write contract of docs/gapcon.md: AK(1) is written (it holds a
 * mark before the call), AK(2..5) and the slot past them keep GH_GUARD, and no input argument
 * changes.
 *
 * Configuration files: the T1, T2, threads and CalculiX harnesses write their TOML at run time
 * (gh_config_*), from the same C constants their closed forms use, to the path given as argv[1]
 * (CTest passes one in the build tree), and setenv INTERFACIAL_CONFIG before the first call.
 * The bad-input harness instead reads fixed files in c_tests/configs/, whose line numbers its
 * expected messages name.
 *
 * Pass/fail bookkeeping (FH_CHECK, FH_NEAR, fh_finish, ...) comes from harness.h.
 */
#ifndef GAPCON_HARNESS_H
#define GAPCON_HARNESS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"

/* In AK(2..5) and the slot after AK(5) before every call: gapcon_ writes AK(1) only. */
#define GH_GUARD (-3.33e33)
/* In AK(1) before every call: shows that AK(1) was written. */
#define GH_AK_MARK 8.125e88
/* Stefan-Boltzmann constant in SI units, W/(m^2 K^4) (CODATA 2018, exact by definition). */
#define GH_SIGMA_SI 5.670374419e-8

/* Names are set with harness.h's fh_set_name, so their buffers have its size. */
enum { GH_AK = 6, GH_NAME = FH_NAMEBUF };

typedef struct {
    double ak[GH_AK];      /* AK(5) + one guard */
    double d[2];           /* D(1) clearance, D(2) contact pressure */
    double flowm[2];       /* FLOWM(2) */
    double temp[2];        /* TEMP(1) = theta_A, TEMP(2) = theta_B */
    double predef[2];      /* PREDEF(2,NPRED), NPRED = 1 */
    double time[2];        /* TIME(2) */
    char ciname[GH_NAME], slname[GH_NAME], msname[GH_NAME];
    size_t ciname_len, slname_len, msname_len; /* hidden lengths */
    double coords[3];
    int noel, node, npred, kstep, kinc;
    double area;           /* CalculiX only */
} gh_gapcon;

/*
 * A point of interaction `name` (CHARACTER*80), element 17, node 42, clearance d, pressure p,
 * surface temperatures theta_a, theta_b; the unread arguments hold plausible host values.
 */
static inline void gh_init(gh_gapcon *g, const char *name, double d, double p, double theta_a,
                           double theta_b)
{
    const gh_gapcon point = {
        .d = {d, p},
        .temp = {theta_a, theta_b},
        .time = {0.5, 1.5},
        .coords = {1.0, 2.0, 3.0},
        .noel = 17,
        .node = 42,
        .npred = 1,
        .kstep = 1,
        .kinc = 3,
        .area = 0.25,
    }; /* everything not named zero: AK, FLOWM, PREDEF */
    *g = point;
    fh_set_name(g->ciname, &g->ciname_len, 80, name);
    fh_set_name(g->slname, &g->slname_len, 80, "SLAVE_SURF");
    fh_set_name(g->msname, &g->msname_len, 80, "MASTER_SURF");
}

/* The raw call, as gfortran makes CALL GAPCON(...) (CalculiX: with AREA after KINC). */
static inline void gh_call_raw(gh_gapcon *g)
{
#if defined(INTERFACIAL_CALCULIX)
    gapcon_(g->ak, g->d, g->flowm, g->temp, g->predef, g->time, g->ciname, g->slname,
            g->msname, g->coords, &g->noel, &g->node, &g->npred, &g->kstep, &g->kinc, &g->area,
            g->ciname_len, g->slname_len, g->msname_len);
#else
    gapcon_(g->ak, g->d, g->flowm, g->temp, g->predef, g->time, g->ciname, g->slname,
            g->msname, g->coords, &g->noel, &g->node, &g->npred, &g->kstep, &g->kinc,
            g->ciname_len, g->slname_len, g->msname_len);
#endif
}

static inline void gh_set_guards(gh_gapcon *g)
{
    int i;
    g->ak[0] = GH_AK_MARK;
    for (i = 1; i < GH_AK; i++) {
        g->ak[i] = GH_GUARD;
    }
}

static inline int gh_guards_intact(const gh_gapcon *g)
{
    int i, ok = 1;
    for (i = 1; i < GH_AK; i++) {
        ok &= g->ak[i] == GH_GUARD;
    }
    return ok;
}

/* True when no input argument differs between a and b (bitwise, so NaN inputs compare too). */
#define GH_SAME(field) (memcmp(&a->field, &b->field, sizeof a->field) == 0)
static inline int gh_inputs_same(const gh_gapcon *a, const gh_gapcon *b)
{
    return GH_SAME(d) && GH_SAME(flowm) && GH_SAME(temp) && GH_SAME(predef) && GH_SAME(time) &&
           GH_SAME(ciname) && GH_SAME(slname) && GH_SAME(msname) && GH_SAME(ciname_len) &&
           GH_SAME(slname_len) && GH_SAME(msname_len) && GH_SAME(coords) && GH_SAME(noel) &&
           GH_SAME(node) && GH_SAME(npred) && GH_SAME(kstep) && GH_SAME(kinc) && GH_SAME(area);
}
#undef GH_SAME

/*
 * One call from the host; returns AK(1). Checks that AK(1) was written, AK(2..5) and the guard
 * slot were not, and no input changed.
 */
static inline double gh_call(gh_gapcon *g)
{
    gh_gapcon before;
    gh_set_guards(g);
    before = *g;
    gh_call_raw(g);
    FH_CHECK(g->ak[0] != GH_AK_MARK);
    FH_CHECK(gh_guards_intact(g));
    FH_CHECK(gh_inputs_same(g, &before));
    return g->ak[0];
}

/* A call that must succeed: as gh_call, and no error reported on this thread. */
static inline double gh_call_ok(gh_gapcon *g)
{
    double ak;
    ifl_clear_error();
    ak = gh_call(g);
    if (!FH_CHECK(ifl_last_error()[0] == '\0')) {
        fprintf(stderr, "  unexpected error: %s\n", ifl_last_error());
    }
    FH_CHECK(isfinite(ak) && ak >= 0.0);
    return ak;
}

/* AK(1) of interaction `name` (CHARACTER*80) at (d, p, theta_a, theta_b): a successful call. */
static inline double gh_ak(const char *name, double d, double p, double theta_a, double theta_b)
{
    gh_gapcon g;
    gh_init(&g, name, d, p, theta_a, theta_b);
    return gh_call_ok(&g);
}

/* ifl_gap_conductance that must succeed. */
static inline IflConductance gh_native_ok(const char *name, double d, double p, double theta_a,
                                          double theta_b)
{
    IflConductance c;
    IflStatus s;
    ifl_clear_error();
    s = ifl_gap_conductance(name, d, p, theta_a, theta_b, &c);
    if (!FH_CHECK(s == IFL_STATUS_OK)) {
        fprintf(stderr, "  status %d: %s\n", (int)s, ifl_last_error());
    }
    return c;
}

/* ---------------------------------------------------------------------------------------- */
/* Configuration files written at run time                                                   */

static FILE *gh_cfg;

static inline void gh_config_text(const char *fmt, ...) FH_PRINTF(1, 2);

static inline void gh_config_text(const char *fmt, ...)
{
    va_list ap;
    if (gh_cfg == NULL) {
        return;
    }
    va_start(ap, fmt);
    vfprintf(gh_cfg, fmt, ap);
    va_end(ap);
}

/* Opens the file and writes its first line, "# Written by WRITER.". When it cannot, it says so,
 * the gh_config_ writers below write nothing and gh_config_close counts the failure. */
static inline void gh_config_open(const char *path, const char *writer)
{
    gh_cfg = fopen(path, "w");
    if (gh_cfg == NULL) {
        fprintf(stderr, "cannot write the configuration file %s\n", path);
        return;
    }
    gh_config_text("# Written by %s.\n", writer);
}

/* A TOML float that reads back as exactly v (%.17g, with ".0" when it would read as integer). */
static inline void gh_toml_float(char *buf, size_t len, double v)
{
    snprintf(buf, len, "%.17g", v);
    if (strpbrk(buf, ".eEni") == NULL) {
        strncat(buf, ".0", len - strlen(buf) - 1);
    }
}

/* key = v, exactly. */
static inline void gh_config_real(const char *key, double v)
{
    char num[40];
    gh_toml_float(num, sizeof num, v);
    gh_config_text("%s = %s\n", key, num);
}

/* The conductance section of interaction `name` with its law (keys follow). */
static inline void gh_config_law(const char *name, const char *law)
{
    gh_config_text("\n[interactions.%s.conductance]\nlaw = \"%s\"\n", name, law);
}

/* table = [[x, k], ...] (ncol = 2) or [[x, k, theta], ...] (ncol = 3), rows flat. */
static inline void gh_config_table(const double *rows, int nrows, int ncol)
{
    char num[40];
    int r, c;
    gh_config_text("table = [");
    for (r = 0; r < nrows; r++) {
        gh_config_text("%s[", r ? ", " : "");
        for (c = 0; c < ncol; c++) {
            gh_toml_float(num, sizeof num, rows[r * ncol + c]);
            gh_config_text("%s%s", c ? ", " : "", num);
        }
        gh_config_text("]");
    }
    gh_config_text("]\n");
}

/* Interaction `name` with the constant law k. */
static inline void gh_config_constant(const char *name, double k)
{
    gh_config_law(name, "constant");
    gh_config_real("k", k);
}

/* Interaction `name` with a tabulated law ("pressure-table" or "clearance-table") and its rows. */
static inline void gh_config_tabulated(const char *name, const char *law, const double *rows,
                                       int nrows, int ncol)
{
    gh_config_law(name, law);
    gh_config_table(rows, nrows, ncol);
}

/* Interaction `name` with the gas-gap law k_gas/(d + g0) (min_gap, when wanted, follows). */
static inline void gh_config_gas_gap(const char *name, double k_gas, double g0)
{
    gh_config_law(name, "gas-gap");
    gh_config_real("k_gas", k_gas);
    gh_config_real("g0", g0);
}

/* Interaction `name` with the cmy law of k_s, m, sigma and H_c (c, when wanted, follows). */
static inline void gh_config_cmy(const char *name, double k_s, double m, double sigma,
                                 double h_c)
{
    gh_config_law(name, "cmy");
    gh_config_real("k_s", k_s);
    gh_config_real("m", m);
    gh_config_real("sigma", sigma);
    gh_config_real("H_c", h_c);
}

/* The radiation section of interaction `name`: view factor F, Stefan-Boltzmann constant sigma
 * and absolute zero theta_z on the model's temperature scale. */
static inline void gh_config_radiation(const char *name, double view, double sigma,
                                       double theta_z)
{
    gh_config_text("\n[interactions.%s.radiation]\n", name);
    gh_config_real("view_factor", view);
    gh_config_real("stefan_boltzmann", sigma);
    gh_config_real("absolute_zero", theta_z);
}

/* Closes the file and points INTERFACIAL_CONFIG to it (before the library's first call). */
static inline int gh_config_close(const char *path)
{
    int ok = gh_cfg != NULL && fclose(gh_cfg) == 0;
    gh_cfg = NULL;
    return FH_CHECK(ok) && FH_CHECK(setenv("INTERFACIAL_CONFIG", path, 1) == 0);
}

/* ---------------------------------------------------------------------------------------- */
/* Hand-computed laws (docs/config.md), independent of the library                           */

/* Piecewise-linear y(x), constant outside; rows (x, y) flat with stride `stride`. */
static inline double gh_lerp_table(const double *rows, int nrows, int stride, double x)
{
    int i;
    if (x <= rows[0]) {
        return rows[1];
    }
    if (x >= rows[(nrows - 1) * stride]) {
        return rows[(nrows - 1) * stride + 1];
    }
    for (i = 0; i + 1 < nrows; i++) {
        double x0 = rows[i * stride], x1 = rows[(i + 1) * stride];
        if (x >= x0 && x < x1) {
            double y0 = rows[i * stride + 1], y1 = rows[(i + 1) * stride + 1];
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
        }
    }
    return NAN; /* unreachable for a sorted table */
}

/*
 * k(x, theta_mean) of a table given as docs/config.md writes it: rows [x, k] (ncol = 2) or
 * [x, k, theta] grouped by increasing theta (ncol = 3); linear in x within a temperature,
 * linear in theta between temperatures, constant outside both.
 */
static inline double gh_table_k(const double *rows, int nrows, int ncol, double x, double theta)
{
    int start = 0, lo_start = -1, lo_n = 0;
    double lo_t = 0.0;
    if (ncol == 2) {
        return gh_lerp_table(rows, nrows, 2, x);
    }
    while (start < nrows) {
        double t = rows[start * 3 + 2];
        int n = 0;
        while (start + n < nrows && rows[(start + n) * 3 + 2] == t) {
            n++;
        }
        if (theta <= t) {
            double k_here = gh_lerp_table(rows + start * 3, n, 3, x);
            double k_lo;
            if (lo_start < 0) {
                return k_here; /* at or below the first temperature */
            }
            k_lo = gh_lerp_table(rows + lo_start * 3, lo_n, 3, x);
            return k_lo + (k_here - k_lo) * (theta - lo_t) / (t - lo_t);
        }
        lo_start = start;
        lo_n = n;
        lo_t = t;
        start += n;
    }
    return gh_lerp_table(rows + lo_start * 3, lo_n, 3, x); /* above the last temperature */
}

#endif /* GAPCON_HARNESS_H */
