/*
 * Scene T1, two bars in contact, steady (docs/scene-definitions.md), solved the way a host FE
 * code solves it: Newton on the two interface temperatures (theta_A, theta_B), with the gap
 * conductance AK(1) from gapcon_ (Abaqus signature, CHARACTER*80 names, hidden lengths 80) and
 * the flux derivatives from ifl_gap_conductance.
 *
 * Bar A: length L_A, conductivity k_A, far end held at theta_H; bar B: L_B, k_B, far end at
 * theta_C. With q = AK(1)*(theta_A - theta_B) the residuals are
 *   R_A = (theta_H - theta_A)/(L_A/k_A) - q,   R_B = q - (theta_B - theta_C)/(L_B/k_B),
 * and for h independent of temperature the exact flux is
 *   q = (theta_H - theta_C)/(L_A/k_A + 1/h + L_B/k_B)         (q = 0 for h = 0).
 *
 * Cases: (a) constant h; (b) pressure table, pressures inside every segment, on a row, below
 * the first row (negative pressures included) and above the last; (c) clearance table, the
 * last conductance 0 (an insulating open gap: q = 0); (d) a table [p, k, theta_mean]: the
 * converged flux satisfies the formula with h* = the bilinear table value at the converged
 * theta_mean worked out by hand, and agrees with an independent bisection on q that uses
 * only the hand-computed table; Newton with the seed's flux derivatives converges
 * quadratically, with dq/dtheta = +-h only linearly at the rate predicted from the
 * derivative left out. Both iteration histories are printed.
 *
 * Then ifl_gap_conductance's derivatives against central finite differences of its own k in
 * every segment of every table (and one-sided ones on the rows), outside the tables, and for
 * the gas-gap and cmy laws; k itself against the hand-computed laws of docs/config.md.
 *
 * The configuration is written at run time from the constants below to argv[1] (default
 * ./gapcon_t1.toml) and INTERFACIAL_CONFIG is set before the first call.
 */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gapcon_harness.h"

/* The bars (any consistent units; think W, m, K). */
#define THETA_H 400.0
#define THETA_C 20.0
#define K_A 400.0
#define L_A 0.08
#define K_B 50.0
#define L_B 0.05
#define R_A (L_A / K_A) /* 2e-4 */
#define R_B (L_B / K_B) /* 1e-3 */
#define DELTA_T (THETA_H - THETA_C)

/* (a) */
#define H_CONST 1200.0

/* (b) [p, k]: the first pressure negative (a slightly open gap). */
static const double PTAB[] = {-2.0, 150.0, 0.0, 400.0, 20.0, 1000.0, 60.0, 1600.0, 100.0, 1700.0};
#define PTAB_ROWS 5

/* (c) [d, k]: k falls with the clearance, to 0 at d = 1e-3. */
static const double CTAB[] = {0.0, 2000.0, 1e-4, 800.0, 5e-4, 100.0, 1e-3, 0.0};
#define CTAB_ROWS 4

/* (d) [p, k, theta_mean] at theta_mean = 100, 400, 600; solved at p = P_T. */
static const double TTAB[] = {
    0.0, 200.0,  100.0, 50.0, 600.0,  100.0,
    0.0, 1500.0, 400.0, 50.0, 4500.0, 400.0,
    0.0, 2000.0, 600.0, 50.0, 5000.0, 600.0,
};
#define TTAB_ROWS 6
#define P_T 30.0

/* A clearance table in temperature with a different set of clearances per temperature. */
static const double CTTAB[] = {
    0.0, 3000.0, 0.0,   2e-4, 500.0,  0.0,
    0.0, 2500.0, 200.0, 1e-4, 1200.0, 200.0, 3e-4, 300.0, 200.0,
};
#define CTTAB_ROWS 5

/* gas-gap */
#define K_GAS 0.03
#define G0 2e-5
#define MIN_GAP 1e-5

/* cmy: k_s the harmonic mean of the bars' conductivities */
#define CMY_KS (2.0 * K_A * K_B / (K_A + K_B))
#define CMY_M 0.1
#define CMY_SIGMA 2e-6
#define CMY_HC 1.5e9

static void write_config(const char *path)
{
    gh_config_open(path, "test_gapcon_t1.c: scene T1");
    gh_config_constant("T1_CONST", H_CONST);
    gh_config_tabulated("T1_PTAB", "pressure-table", PTAB, PTAB_ROWS, 2);
    gh_config_tabulated("T1_CTAB", "clearance-table", CTAB, CTAB_ROWS, 2);
    gh_config_tabulated("T1_TTAB", "pressure-table", TTAB, TTAB_ROWS, 3);
    gh_config_tabulated("T1_CTTAB", "clearance-table", CTTAB, CTTAB_ROWS, 3);
    gh_config_gas_gap("T1_GAS", K_GAS, G0);
    gh_config_real("min_gap", MIN_GAP);
    gh_config_cmy("T1_CMY", CMY_KS, CMY_M, CMY_SIGMA, CMY_HC);
    gh_config_cmy("T1_CMY_C1", CMY_KS, CMY_M, CMY_SIGMA, CMY_HC);
    gh_config_real("c", 1.0);
    gh_config_close(path);
}

/* ---------------------------------------------------------------------------------------- */
/* The host's Newton solve                                                                   */

enum { MAX_IT = 60 };

typedef struct {
    int n;                    /* iterations done */
    double ta[MAX_IT + 1];    /* theta_A after iteration k (k = 0: the start) */
    double tb[MAX_IT + 1];
    double q;                 /* gap flux AK(1)*(theta_A - theta_B) at the last iterate */
} solve_history;

/*
 * Newton (exact_tangent = 1: dq/dtheta from ifl_gap_conductance) or the host that ignores the
 * temperature dependence of h (exact_tangent = 0: dq/dtheta_A = AK(1), dq/dtheta_B = -AK(1)),
 * from theta_A = theta_H, theta_B = theta_C until the update is at round-off.
 */
static void solve_two_bars(const char *name, double d, double p, int exact_tangent,
                           solve_history *s)
{
    double ta = THETA_H, tb = THETA_C;
    int it;
    s->ta[0] = ta;
    s->tb[0] = tb;
    s->n = 0;
    for (it = 1; it <= MAX_IT; it++) {
        gh_gapcon g;
        double ak, q, ra, rb, qa, qb, j11, j12, j21, j22, det, dta, dtb;
        gh_init(&g, name, d, p, ta, tb);
        ak = gh_call_ok(&g);
        q = ak * (ta - tb);
        ra = (THETA_H - ta) / R_A - q;
        rb = q - (tb - THETA_C) / R_B;
        if (exact_tangent) {
            IflConductance c = gh_native_ok(name, d, p, ta, tb);
            /* One law behind both entry points: the same k, bit for bit. */
            FH_CHECK(memcmp(&c.k, &ak, sizeof ak) == 0);
            qa = c.dq_dtheta_a;
            qb = c.dq_dtheta_b;
        } else {
            qa = ak;
            qb = -ak;
        }
        j11 = -1.0 / R_A - qa;
        j12 = -qb;
        j21 = qa;
        j22 = qb - 1.0 / R_B;
        det = j11 * j22 - j12 * j21;
        dta = (-ra * j22 + rb * j12) / det;
        dtb = (-rb * j11 + ra * j21) / det;
        ta += dta;
        tb += dtb;
        s->ta[it] = ta;
        s->tb[it] = tb;
        s->n = it;
        if (fmax(fabs(dta), fabs(dtb)) <= 1e-14 * DELTA_T) {
            break;
        }
    }
    s->q = gh_ak(name, d, p, ta, tb) * (ta - tb);
}

/* Closed form of T1 for an h that does not depend on temperature. */
static double t1_flux(double h)
{
    return h > 0.0 ? DELTA_T / (R_A + 1.0 / h + R_B) : 0.0;
}

/* Solves T1 through the library for a temperature-independent h and checks the closed form. */
static void check_closed_form(const char *name, double d, double p, double h)
{
    solve_history s;
    double q = t1_flux(h);
    IflConductance c;
    fh_context("%s at d = %g, p = %g: h = %g by hand", name, d, p, h);
    /* The library's h first, at a temperature away from the solution (h must not care). */
    FH_NEAR(gh_ak(name, d, p, 350.0, 50.0), h, 1e-14, 0.0);
    c = gh_native_ok(name, d, p, 350.0, 50.0);
    FH_NEAR(c.k, h, 1e-14, 0.0);
    FH_EXACT(c.dk_dtheta_mean, 0.0);
    FH_EXACT(c.dq_dtheta_a, c.k);
    FH_EXACT(c.dq_dtheta_b, -c.k);

    solve_two_bars(name, d, p, 1, &s);
    /* A linear problem: one Newton step solves it, the second only confirms. */
    FH_CHECK(s.n <= 3);
    FH_NEAR(s.q, q, 1e-12, 1e-9);
    FH_NEAR((THETA_H - s.ta[s.n]) / R_A, q, 1e-11, 1e-7);
    FH_NEAR((s.tb[s.n] - THETA_C) / R_B, q, 1e-11, 1e-7);
    FH_NEAR(s.ta[s.n], THETA_H - q * R_A, 0.0, 1e-11);
    FH_NEAR(s.tb[s.n], THETA_C + q * R_B, 0.0, 1e-11);
}

/* (a), (b), (c) */
static void closed_form_cases(void)
{
    /* (b) pressures: h by linear interpolation written out from PTAB. */
    static const double pcases[][2] = {
        {-1.0, 150.0 + (400.0 - 150.0) * (-1.0 + 2.0) / 2.0},   /* negative, inside */
        {-2.0, 150.0},                                          /* first row */
        {10.0, 400.0 + (1000.0 - 400.0) * 10.0 / 20.0},
        {20.0, 1000.0},                                         /* on a row */
        {45.0, 1000.0 + (1600.0 - 1000.0) * 25.0 / 40.0},
        {95.0, 1600.0 + (1700.0 - 1600.0) * 35.0 / 40.0},
        {100.0, 1700.0},                                        /* last row */
        {-5.0, 150.0},                                          /* below, negative */
        {-1e6, 150.0},
        {250.0, 1700.0},                                        /* above */
        {1e12, 1700.0},
    };
    /* (c) clearances: h from CTAB. */
    static const double dcases[][2] = {
        {-1e-5, 2000.0},                                        /* overclosed: below */
        {0.0, 2000.0},
        {5e-5, 2000.0 + (800.0 - 2000.0) * 0.5},
        {3e-4, 800.0 + (100.0 - 800.0) * 0.5},
        {7.5e-4, 100.0 + (0.0 - 100.0) * 0.5},
        {1e-3, 0.0},                                            /* insulating */
        {0.1, 0.0},
    };
    size_t i;

    check_closed_form("T1_CONST", 1e-4, 55.0, H_CONST);
    /* Neither the clearance nor the pressure matters to a constant law. */
    check_closed_form("T1_CONST", -3.0, -1e9, H_CONST);

    for (i = 0; i < sizeof pcases / sizeof pcases[0]; i++) {
        /* The harness's own table reader agrees with the hand-written values. */
        fh_context("gh_lerp_table at p = %g", pcases[i][0]);
        FH_NEAR(gh_lerp_table(PTAB, PTAB_ROWS, 2, pcases[i][0]), pcases[i][1], 1e-15, 0.0);
        /* D(1) is not read by a pressure table: any clearance. */
        check_closed_form("T1_PTAB", 0.37, pcases[i][0], pcases[i][1]);
    }
    for (i = 0; i < sizeof dcases / sizeof dcases[0]; i++) {
        fh_context("gh_lerp_table at d = %g", dcases[i][0]);
        FH_NEAR(gh_lerp_table(CTAB, CTAB_ROWS, 2, dcases[i][0]), dcases[i][1], 1e-15, 0.0);
        check_closed_form("T1_CTAB", dcases[i][0], 55.0, dcases[i][1]);
    }
}

/* ---------------------------------------------------------------------------------------- */
/* (d) temperature-dependent h: quadratic against linear convergence                         */

/* h(P_T, theta_mean) from the table, by hand. */
static double hand_h(double theta_mean)
{
    return gh_table_k(TTAB, TTAB_ROWS, 3, P_T, theta_mean);
}

/* The gap flux minus the flux through the bars when both carry q: zero at the solution. */
static double t1_mismatch(double q)
{
    double ta = THETA_H - q * R_A, tb = THETA_C + q * R_B;
    return hand_h(0.5 * (ta + tb)) * (ta - tb) - q;
}

/* The exact steady flux of (d) without the library: bisection on q in [0, dT/(R_A + R_B)]. */
static double bisect_flux(void)
{
    double lo = 0.0, hi = DELTA_T / (R_A + R_B);
    int i;
    FH_CHECK(t1_mismatch(lo) > 0.0 && t1_mismatch(hi) < 0.0);
    for (i = 0; i < 400; i++) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) {
            break;
        }
        if (t1_mismatch(mid) > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

/* Max-norm error of iterate k against the reference. */
static double iterate_error(const solve_history *s, int k, double ta, double tb)
{
    return fmax(fabs(s->ta[k] - ta), fabs(s->tb[k] - tb));
}

static int iterations_to(const solve_history *s, double ta, double tb, double tol)
{
    int k;
    for (k = 0; k <= s->n; k++) {
        if (iterate_error(s, k, ta, tb) <= tol) {
            return k;
        }
    }
    return MAX_IT + 1;
}

static void print_history(const char *title, const solve_history *s, double ta, double tb)
{
    int k;
    printf("%s\n  %3s %22s %22s %10s %12s %12s\n", title, "k", "theta_A", "theta_B", "error",
           "e_k/e_k-1^2", "e_k/e_k-1");
    for (k = 0; k <= s->n; k++) {
        double e = iterate_error(s, k, ta, tb);
        if (k == 0) {
            printf("  %3d %22.15f %22.15f %10.3e\n", k, s->ta[k], s->tb[k], e);
        } else {
            double ep = iterate_error(s, k - 1, ta, tb);
            printf("  %3d %22.15f %22.15f %10.3e %12.4e %12.4e\n", k, s->ta[k], s->tb[k], e,
                   e / (ep * ep), e / ep);
        }
    }
}

static void temperature_dependent_case(void)
{
    solve_history newton, fixed;
    const double q_ref = bisect_flux();
    const double ta_ref = THETA_H - q_ref * R_A, tb_ref = THETA_C + q_ref * R_B;
    const double tol = 1e-12 * DELTA_T;
    /* Noise floor of the errors: theta ~ 400 carries ~1e-13 of round-off. */
    const double floor_e = 1e-10;
    double tm, h_star, s_theta, jump, c, m_quad, lambda, det, ja[2][2], jx[2][2], v[2];
    double worst_quad = 0.0;
    int n_newton, n_fixed, k, tail = 0;

    fh_context("T1 (d): reference by bisection");
    tm = 0.5 * (ta_ref + tb_ref);
    /* Inside the table in pressure and in temperature: bilinear, not clamped. */
    FH_CHECK(tm > 100.0 && tm < 400.0);
    h_star = hand_h(tm);
    FH_NEAR(q_ref, DELTA_T / (R_A + 1.0 / h_star + R_B), 1e-13, 0.0);

    solve_two_bars("T1_TTAB", 1e-4, P_T, 1, &newton);
    solve_two_bars("T1_TTAB", 1e-4, P_T, 0, &fixed);
    print_history("T1 (d), Newton with dq/dtheta from ifl_gap_conductance:", &newton, ta_ref,
                  tb_ref);
    print_history("T1 (d), dq/dtheta_A = h, dq/dtheta_B = -h (dh/dtheta_mean ignored):", &fixed,
                  ta_ref, tb_ref);

    /* Both converge to the same state, the exact one. */
    fh_context("T1 (d): converged state, Newton");
    {
        double ta = newton.ta[newton.n], tb = newton.tb[newton.n];
        double h_conv = hand_h(0.5 * (ta + tb));
        FH_NEAR(newton.q, DELTA_T / (R_A + 1.0 / h_conv + R_B), 1e-12, 0.0);
        FH_NEAR(newton.q, q_ref, 1e-12, 0.0);
        FH_NEAR(ta, ta_ref, 0.0, 1e-10);
        FH_NEAR(tb, tb_ref, 0.0, 1e-10);
        /* The library's h at the converged state is the hand-computed bilinear value. */
        FH_NEAR(gh_ak("T1_TTAB", 1e-4, P_T, ta, tb), h_conv, 1e-14, 0.0);
    }
    fh_context("T1 (d): converged state, fixed tangent");
    FH_NEAR(fixed.q, q_ref, 1e-12, 0.0);

    /*
     * Theory, from the hand-computed table at the solution. h = h* + s (theta_mean - tm) in
     * the segment, so q is quadratic in (theta_A, theta_B) with Hessian diag(s, -s) and
     * Newton's error obeys e_{k+1} = J_k^{-1} (-1, 1) (s/2)(e_A^2 - e_B^2) exactly:
     * e_{k+1}/e_k^2 <= M = |s|/2 |J*^{-1} (-1, 1)|_inf near the solution.
     * The fixed tangent A differs from J by c (-1, 1)^T (1, 1), c = s (theta_A - theta_B)/2:
     * its error map I - A^{-1} J has the single non-zero eigenvalue
     * lambda = -c (1, 1) A^{-1} (-1, 1)^T, the linear rate.
     */
    s_theta = (gh_table_k(TTAB, TTAB_ROWS, 3, P_T, 400.0) -
               gh_table_k(TTAB, TTAB_ROWS, 3, P_T, 100.0)) / (400.0 - 100.0);
    jump = ta_ref - tb_ref;
    c = 0.5 * s_theta * jump;
    jx[0][0] = -1.0 / R_A - (h_star + c);
    jx[0][1] = -(-h_star + c);
    jx[1][0] = h_star + c;
    jx[1][1] = (-h_star + c) - 1.0 / R_B;
    det = jx[0][0] * jx[1][1] - jx[0][1] * jx[1][0];
    v[0] = (-1.0 * jx[1][1] - 1.0 * jx[0][1]) / det; /* J*^{-1} (-1, 1) */
    v[1] = (1.0 * jx[0][0] + 1.0 * jx[1][0]) / det;
    m_quad = 0.5 * fabs(s_theta) * fmax(fabs(v[0]), fabs(v[1]));
    ja[0][0] = -1.0 / R_A - h_star;
    ja[0][1] = h_star;
    ja[1][0] = h_star;
    ja[1][1] = -h_star - 1.0 / R_B;
    det = ja[0][0] * ja[1][1] - ja[0][1] * ja[1][0];
    v[0] = (-1.0 * ja[1][1] - 1.0 * ja[0][1]) / det; /* A*^{-1} (-1, 1) */
    v[1] = (1.0 * ja[0][0] + 1.0 * ja[1][0]) / det;
    lambda = -c * (v[0] + v[1]);
    printf("T1 (d): h* = %.6f, dh/dtheta_mean = %.6f, theta_A - theta_B = %.6f\n", h_star,
           s_theta, jump);
    printf("        quadratic constant M = %.4e, linear rate |lambda| = %.6f\n", m_quad,
           fabs(lambda));

    fh_context("T1 (d): Newton converges quadratically");
    for (k = 1; k <= newton.n; k++) {
        double e = iterate_error(&newton, k, ta_ref, tb_ref);
        double ep = iterate_error(&newton, k - 1, ta_ref, tb_ref);
        if (e > floor_e) {
            double ratio = e / (ep * ep);
            worst_quad = fmax(worst_quad, ratio);
            /* Close to the solution J_k ~ J*: the bound with a factor 2 for the difference. */
            if (ep < 1.0) {
                FH_CHECK(ratio <= 2.0 * m_quad);
            }
        }
    }
    /* Bounded along the whole path, far from the solution too. */
    FH_CHECK(worst_quad <= 10.0 * m_quad);
    n_newton = iterations_to(&newton, ta_ref, tb_ref, tol);
    n_fixed = iterations_to(&fixed, ta_ref, tb_ref, tol);
    printf("T1 (d): iterations to |error| <= 1e-12 (theta_H - theta_C): Newton %d, fixed "
           "tangent %d\n", n_newton, n_fixed);
    FH_CHECK(n_newton <= 6);

    fh_context("T1 (d): without dh/dtheta_mean the rate is linear, |lambda| = %.4f",
               fabs(lambda));
    /* The rate left out must be visible for this comparison to mean anything. */
    FH_CHECK(fabs(lambda) > 0.05 && fabs(lambda) < 0.5);
    for (k = 1; k <= fixed.n; k++) {
        double e = iterate_error(&fixed, k, ta_ref, tb_ref);
        double ep = iterate_error(&fixed, k - 1, ta_ref, tb_ref);
        /* Tail: the error is along the eigenvector, far above round-off. */
        if (ep < 1e-2 && e > 1e3 * floor_e) {
            FH_NEAR(e / ep, fabs(lambda), 0.01, 0.0);
            tail++;
        }
    }
    FH_CHECK(tail >= 3);
    FH_CHECK(n_fixed <= MAX_IT && n_fixed >= 2 * n_newton && n_fixed >= n_newton + 5);
}

/* ---------------------------------------------------------------------------------------- */
/* Derivatives against finite differences                                                    */

/* The library's k (ifl_gap_conductance, must succeed). */
static double lib_k(const char *name, double d, double p, double ta, double tb)
{
    return gh_native_ok(name, d, p, ta, tb).k;
}

/* What a derivative is compared with: central differences, or (rows) one-sided to the right,
 * second order so that a quadratic q is differentiated exactly. */
static double diff(double (*f)(const void *, double), const void *ctx, double h, int right)
{
    if (right) {
        return (-3.0 * f(ctx, 0.0) + 4.0 * f(ctx, h) - f(ctx, 2.0 * h)) / (2.0 * h);
    }
    return (f(ctx, h) - f(ctx, -h)) / (2.0 * h);
}

typedef struct {
    const char *name;
    double d, p, ta, tb;
    int which; /* 0: k(d), 1: k(p), 2: k(theta_mean), 3: q(theta_A), 4: q(theta_B) */
} fd_point;

static double fd_eval(const void *ctx, double e)
{
    const fd_point *x = ctx;
    double ta = x->ta, tb = x->tb;
    switch (x->which) {
    case 0:
        return lib_k(x->name, x->d + e, x->p, ta, tb);
    case 1:
        return lib_k(x->name, x->d, x->p + e, ta, tb);
    case 2:
        return lib_k(x->name, x->d, x->p, ta + e, tb + e);
    case 3:
        return lib_k(x->name, x->d, x->p, ta + e, tb) * (ta + e - tb);
    default:
        return lib_k(x->name, x->d, x->p, ta, tb + e) * (ta - tb - e);
    }
}

/*
 * Every derivative of ifl_gap_conductance at (d, p, ta, tb) against differences of its own k
 * with steps hd, hp, ht. `rtol` covers truncation (0 for piecewise-linear laws, which finite
 * differences differentiate exactly); round-off is allowed for from the step sizes.
 */
static void check_fd(const char *name, double d, double p, double ta, double tb, double hd,
                     double hp, double ht, int right, double rtol)
{
    IflConductance c = gh_native_ok(name, d, p, ta, tb);
    double want[5], got[5], step[5], scale;
    int i;
    fd_point x;
    got[0] = c.dk_dd;
    got[1] = c.dk_dp;
    got[2] = c.dk_dtheta_mean;
    got[3] = c.dq_dtheta_a;
    got[4] = c.dq_dtheta_b;
    step[0] = hd;
    step[1] = hp;
    step[2] = step[3] = step[4] = ht;
    x.name = name;
    x.d = d;
    x.p = p;
    x.ta = ta;
    x.tb = tb;
    /* The same k through gapcon_, bit for bit. */
    {
        double ak = gh_ak(name, d, p, ta, tb);
        FH_CHECK(memcmp(&ak, &c.k, sizeof ak) == 0);
    }
    FH_NEAR(c.dq_dtheta_a, c.k + 0.5 * c.dk_dtheta_mean * (ta - tb), 1e-15, 1e-300);
    FH_NEAR(c.dq_dtheta_b, -c.k + 0.5 * c.dk_dtheta_mean * (ta - tb), 1e-15, 1e-300);
    for (i = 0; i < 5; i++) {
        x.which = i;
        want[i] = diff(fd_eval, &x, step[i], right);
        /* f ~ |k| (|q| for 3, 4), differences of it carry ~ 8 eps |f| / step. */
        scale = (i < 3 ? fabs(c.k) : fabs(c.k * (ta - tb))) + fabs(c.k);
        if (!FH_NEAR(got[i], want[i], rtol, 16.0 * DBL_EPSILON * scale / step[i])) {
            fprintf(stderr, "  derivative %d at d = %g, p = %g, theta = (%g, %g)\n", i, d, p,
                    ta, tb);
        }
    }
}

/* The table's k and its slopes by hand: differences of gh_table_k (exact for a linear piece). */
static void check_table_point(const char *name, const double *rows, int nrows, int ncol,
                              int in_pressure, double x, double theta_mean, double hx,
                              double ht, int right)
{
    const double half_jump = 7.0;
    double ta = theta_mean + half_jump, tb = theta_mean - half_jump;
    double d = in_pressure ? 3e-4 : x, p = in_pressure ? x : 25.0;
    IflConductance c = gh_native_ok(name, d, p, ta, tb);
    double kx0 = gh_table_k(rows, nrows, ncol, x, theta_mean);
    double slope_x, slope_t;
    if (right) {
        slope_x = (gh_table_k(rows, nrows, ncol, x + hx, theta_mean) - kx0) / hx;
        slope_t = (gh_table_k(rows, nrows, ncol, x, theta_mean + ht) - kx0) / ht;
    } else {
        slope_x = (gh_table_k(rows, nrows, ncol, x + hx, theta_mean) -
                   gh_table_k(rows, nrows, ncol, x - hx, theta_mean)) / (2.0 * hx);
        slope_t = (gh_table_k(rows, nrows, ncol, x, theta_mean + ht) -
                   gh_table_k(rows, nrows, ncol, x, theta_mean - ht)) / (2.0 * ht);
    }
    FH_NEAR(c.k, kx0, 1e-14, 1e-12);
    FH_NEAR(in_pressure ? c.dk_dp : c.dk_dd, slope_x, 1e-9, 1e-9 * fabs(kx0) / hx);
    FH_EXACT(in_pressure ? c.dk_dd : c.dk_dp, 0.0);
    FH_NEAR(c.dk_dtheta_mean, slope_t, 1e-9, 1e-9 * fabs(kx0) / ht);
    check_fd(name, d, p, ta, tb, in_pressure ? 1e-6 : hx, in_pressure ? hx : 1.0, ht, right,
             0.0);
}

/*
 * Where central differences are taken in a segment, as a fraction of it: not the middle, so
 * that the point stays clear of the rows of the other temperatures (CTTAB's clearances differ
 * per temperature, and its middles fall on them).
 */
#define OFF_ROW 0.37

/*
 * Points inside every (x segment) x (temperature segment) cell, points beyond the rows and
 * beyond the temperatures, and (one-sided, right) every row and every temperature.
 */
static void table_derivatives(const char *name, const double *rows, int nrows, int ncol,
                              int in_pressure)
{
    double temps[8];
    int nt = 0, r, j;
    if (ncol == 2) {
        temps[nt++] = 250.0; /* any: no temperature dependence */
    } else {
        for (r = 0; r < nrows; r++) {
            if (nt == 0 || rows[r * 3 + 2] != temps[nt - 1]) {
                temps[nt++] = rows[r * 3 + 2];
            }
        }
    }
    for (j = 0; j < nt; j++) {
        /* Temperatures to visit for the rows of temperature j: the row itself, the middle of
         * the segment to its right, below the first and above the last. */
        double tlist[4];
        int ntl = 0, t;
        const double *grp = rows;
        int ng = 0;
        for (r = 0; r < nrows; r++) {
            if (ncol == 2 || rows[r * 3 + 2] == temps[j]) {
                if (ng == 0) {
                    grp = rows + r * ncol;
                }
                ng++;
            }
        }
        tlist[ntl++] = temps[j];
        if (j + 1 < nt) {
            tlist[ntl++] = 0.5 * (temps[j] + temps[j + 1]);
        }
        if (j == 0) {
            tlist[ntl++] = temps[0] - 80.0;
        }
        if (j == nt - 1) {
            tlist[ntl++] = temps[nt - 1] + 80.0;
        }
        for (t = 0; t < ntl; t++) {
            double tm = tlist[t];
            int on_temperature_row = ncol == 3 && tm == temps[j];
            double ht = 0.01 * (nt > 1 ? temps[1] - temps[0] : 100.0);
            double width = grp[(ng - 1) * ncol] - grp[0];
            double hx_out = 0.01 * (width > 0.0 ? width : 1.0);
            int i;
            for (i = 0; i < ng; i++) {
                double x = grp[i * ncol];
                /* On the row (and, on a temperature row, on both kinds of row at once). */
                fh_context("%s: row %d of temperature %g, theta_mean = %g", name, i + 1,
                           ncol == 3 ? temps[j] : 0.0, tm);
                check_table_point(name, rows, nrows, ncol, in_pressure, x, tm,
                                  i + 1 < ng ? 0.01 * (grp[(i + 1) * ncol] - x) : hx_out, ht,
                                  1);
                if (i + 1 < ng) {
                    double x1 = grp[(i + 1) * ncol];
                    fh_context("%s: segment %d-%d of temperature %g, theta_mean = %g", name,
                               i + 1, i + 2, ncol == 3 ? temps[j] : 0.0, tm);
                    check_table_point(name, rows, nrows, ncol, in_pressure,
                                      x + OFF_ROW * (x1 - x), tm, 0.01 * (x1 - x), ht,
                                      on_temperature_row);
                }
            }
            fh_context("%s: below the first row, theta_mean = %g", name, tm);
            check_table_point(name, rows, nrows, ncol, in_pressure, grp[0] - OFF_ROW * width, tm,
                              hx_out, ht, on_temperature_row);
            fh_context("%s: above the last row, theta_mean = %g", name, tm);
            check_table_point(name, rows, nrows, ncol, in_pressure,
                              grp[(ng - 1) * ncol] + OFF_ROW * width, tm, hx_out, ht,
                              on_temperature_row);
        }
    }
}

/*
 * dk/dtheta_mean on the temperature rows, by the rule of docs/config.md ("on a row the segment
 * to its right; outside the table zero"), as the clearance and pressure rows follow it: at the
 * first temperature the slope of the first temperature segment, at an interior temperature
 * the segment above it, at the last temperature zero. (The sweep above checks the same with
 * one-sided differences; this names the rule.)
 */
static void temperature_rows(const char *name, const double *rows, int nrows, int in_pressure,
                             double x, const double *temps, int nt)
{
    int j;
    for (j = 0; j < nt; j++) {
        double tm = temps[j];
        double d = in_pressure ? 3e-4 : x, p = in_pressure ? x : 25.0;
        double want = 0.0;
        IflConductance c;
        if (j + 1 < nt) {
            want = (gh_table_k(rows, nrows, 3, x, temps[j + 1]) -
                    gh_table_k(rows, nrows, 3, x, temps[j])) / (temps[j + 1] - temps[j]);
        }
        fh_context("%s: dk/dtheta_mean on temperature row %d of %d (theta_mean = %g), x = %g: "
                   "the segment to its right", name, j + 1, nt, tm, x);
        c = gh_native_ok(name, d, p, tm + 7.0, tm - 7.0);
        FH_NEAR(c.dk_dtheta_mean, want, 1e-12, 0.0);
    }
}

/*
 * T1_GAS at gap d against its closed form: k and dk/dd as given, dk/dp = dk/dtheta_mean = 0;
 * then the finite differences with the gap step hd, to the relative tolerance rtol.
 */
static void check_gas_gap(double d, double k, double dk_dd, double hd, double rtol)
{
    IflConductance c = gh_native_ok("T1_GAS", d, 40.0, 300.0, 280.0);
    FH_NEAR(c.k, k, 1e-15, 0.0);
    FH_NEAR(c.dk_dd, dk_dd, 1e-14, 0.0);
    FH_EXACT(c.dk_dp, 0.0);
    FH_EXACT(c.dk_dtheta_mean, 0.0);
    check_fd("T1_GAS", d, 40.0, 300.0, 280.0, hd, 1.0, 0.5, 0, rtol);
}

static void gas_gap_and_cmy(void)
{
    static const double gaps[] = {1e-4, 3e-5, 2e-3, 1.5e-5};
    static const double closed[] = {5e-6, 0.0, -1e-4};
    static const double pressures[] = {1e6, 3e5, 2e8, 1.0};
    size_t i;
    for (i = 0; i < sizeof gaps / sizeof gaps[0]; i++) {
        const double d = gaps[i];
        fh_context("gas-gap at d = %g", d);
        check_gas_gap(d, K_GAS / (d + G0), -K_GAS / ((d + G0) * (d + G0)), 1e-4 * (d - MIN_GAP),
                      1e-7);
    }
    /* Below min_gap the gap is taken as min_gap: k stays, dk/dd = 0 (differences exact). */
    for (i = 0; i < sizeof closed / sizeof closed[0]; i++) {
        fh_context("gas-gap at d = %g (below min_gap)", closed[i]);
        check_gas_gap(closed[i], K_GAS / (MIN_GAP + G0), 0.0, 1e-3 * (MIN_GAP - 5e-6), 0.0);
    }
    for (i = 0; i < sizeof pressures / sizeof pressures[0]; i++) {
        double p = pressures[i];
        double h = 1.25 * (CMY_KS * CMY_M / CMY_SIGMA) * pow(p / CMY_HC, 0.95);
        IflConductance c;
        fh_context("cmy at p = %g", p);
        c = gh_native_ok("T1_CMY", 1e-4, p, 300.0, 280.0);
        FH_NEAR(c.k, h, 1e-14, 0.0);
        FH_NEAR(c.dk_dp, 0.95 * h / p, 1e-14, 0.0);
        FH_EXACT(c.dk_dd, 0.0);
        FH_EXACT(c.dk_dtheta_mean, 0.0);
        check_fd("T1_CMY", 1e-4, p, 300.0, 280.0, 1e-6, 1e-5 * p, 0.5, 0, 1e-8);
        /* c = 1 instead of the default 1.25. */
        FH_NEAR(lib_k("T1_CMY_C1", 1e-4, p, 300.0, 280.0), h / 1.25, 1e-14, 0.0);
        /* The T1 closed form with the cmy conductance. */
        check_closed_form("T1_CMY", 1e-4, p, h);
    }
    fh_context("cmy at p <= 0");
    {
        IflConductance c = gh_native_ok("T1_CMY", 1e-4, 0.0, 300.0, 280.0);
        FH_EXACT(c.k, 0.0);
        FH_EXACT(c.dk_dp, 0.0);
        c = gh_native_ok("T1_CMY", 1e-4, -5e5, 300.0, 280.0);
        FH_EXACT(c.k, 0.0);
        FH_EXACT(c.dk_dp, 0.0);
        check_fd("T1_CMY", 1e-4, -5e5, 300.0, 280.0, 1e-6, 1e3, 0.5, 0, 0.0);
        /* An open, non-conducting gap: no flux. */
        check_closed_form("T1_CMY", 1e-4, -5e5, 0.0);
    }
}

int main(int argc, char **argv)
{
    write_config(argc > 1 ? argv[1] : "gapcon_t1.toml");
    closed_form_cases();
    temperature_dependent_case();
    table_derivatives("T1_PTAB", PTAB, PTAB_ROWS, 2, 1);
    table_derivatives("T1_CTAB", CTAB, CTAB_ROWS, 2, 0);
    table_derivatives("T1_TTAB", TTAB, TTAB_ROWS, 3, 1);
    table_derivatives("T1_CTTAB", CTTAB, CTTAB_ROWS, 3, 0);
    {
        static const double ttab_temps[] = {100.0, 400.0, 600.0};
        static const double cttab_temps[] = {0.0, 200.0};
        temperature_rows("T1_TTAB", TTAB, TTAB_ROWS, 1, P_T, ttab_temps, 3);
        temperature_rows("T1_CTTAB", CTTAB, CTTAB_ROWS, 0, 0.5e-4, cttab_temps, 2);
    }
    gas_gap_and_cmy();
    return fh_finish();
}
