/*
 * Scene T2, radiating gap (docs/scene-definitions.md), through gapcon_ (Abaqus signature) and
 * ifl_gap_conductance.
 *
 * Two parallel plates at fixed surface temperatures theta_A, theta_B exchange
 *   q = F sigma ((theta_A - theta_Z)^4 - (theta_B - theta_Z)^4),
 * F = 1/(1/eps_A + 1/eps_B - 1) for parallel plates, theta_Z absolute zero on the model's
 * scale; the library returns it as AK(1) with q = AK(1) (theta_A - theta_B). Checked:
 * - q against the closed form to round-off, in kelvin (theta_Z = 0) and in Celsius
 *   (theta_Z = -273.15), and the two scales against each other for the same physical state;
 *   sigma in mW/(mm^2 K^4) gives q in mW/mm^2 = 1e-3 W/m^2;
 * - theta_A = theta_B: AK(1) = 4 F sigma a^3; a surface exactly at absolute zero;
 * - radiation plus gas-gap conduction: AK(1) = k_gas/(d + g0) + the radiation conductance;
 *   view_factor = 0 leaves the conduction alone;
 * - dq/dtheta_A = 4 F sigma a^3 and dq/dtheta_B = -4 F sigma b^3 from ifl_gap_conductance, and
 *   every derivative against central differences of its own k;
 * - two conducting bars with the radiating gap between them (theta_H, bar A | gap | bar B,
 *   theta_C): Newton through the library (AK(1) from gapcon_, exact flux derivatives from
 *   ifl_gap_conductance) reaches the steady flux found independently by bisection on q, in
 *   both temperature scales, in a few quadratically converging iterations.
 *
 * The configuration is written at run time from the constants below to argv[1] (default
 * ./gapcon_t2.toml) and INTERFACIAL_CONFIG is set before the first call.
 */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gapcon_harness.h"

#define EPS_A 0.8
#define EPS_B 0.6
#define VIEW_F (1.0 / (1.0 / EPS_A + 1.0 / EPS_B - 1.0))
#define SIGMA GH_SIGMA_SI
/* sigma in mW/(mm^2 K^4): 1 W/m^2 = 1e3 mW / 1e6 mm^2. */
#define SIGMA_MM (GH_SIGMA_SI * 1e-3)
#define ZERO_C (-273.15)
#define K_GAS 0.03
#define G0 1e-5

static void write_config(const char *path)
{
    gh_config_open(path, "test_gapcon_t2.c: scene T2");
    gh_config_radiation("RAD_K", VIEW_F, SIGMA, 0.0);
    gh_config_radiation("RAD_C", VIEW_F, SIGMA, ZERO_C);
    gh_config_radiation("RAD_MM", VIEW_F, SIGMA_MM, 0.0);
    gh_config_gas_gap("RAD_GAS", K_GAS, G0);
    gh_config_radiation("RAD_GAS", VIEW_F, SIGMA, 0.0);
    gh_config_gas_gap("RAD_GAS_C", K_GAS, G0);
    gh_config_radiation("RAD_GAS_C", VIEW_F, SIGMA, ZERO_C);
    gh_config_gas_gap("RAD_OFF", K_GAS, G0);
    gh_config_radiation("RAD_OFF", 0.0, SIGMA, 0.0);
    gh_config_close(path);
}

/* F sigma (a^4 - b^4), a, b absolute temperatures, straight from the definition. */
static double rad_flux(double sigma, double a, double b)
{
    return VIEW_F * sigma * (a * a * a * a - b * b * b * b);
}

/* Round-off of rad_flux: a few ulps of each fourth power. */
static double rad_flux_tol(double sigma, double a, double b)
{
    return 16.0 * DBL_EPSILON * VIEW_F * sigma * (a * a * a * a + b * b * b * b);
}

/* Pairs of absolute temperatures (K) of the two plates. */
static const double PLATES[][2] = {
    {1000.0, 300.0}, {300.0, 1000.0}, {500.0, 499.9}, {1500.0, 20.0},
    {800.0, 800.0},  {0.0, 300.0},    {300.0, 0.0},   {273.15, 373.15},
};
#define N_PLATES (sizeof PLATES / sizeof PLATES[0])

static void plates(void)
{
    size_t i;
    for (i = 0; i < N_PLATES; i++) {
        const double ta_k = PLATES[i][0], tb_k = PLATES[i][1];
        /* The same state on the Celsius scale, and a, b as the library must form them. */
        const double ta_c = ta_k + ZERO_C, tb_c = tb_k + ZERO_C;
        const double a_c = ta_c - ZERO_C, b_c = tb_c - ZERO_C;
        double ak_k, ak_c, ak_mm, ak_gas, q;
        IflConductance c;

        fh_context("plates %g K, %g K (kelvin)", ta_k, tb_k);
        ak_k = gh_ak("RAD_K", 1e-3, 0.0, ta_k, tb_k);
        q = ak_k * (ta_k - tb_k);
        FH_NEAR(q, rad_flux(SIGMA, ta_k, tb_k), 4.0 * DBL_EPSILON,
                rad_flux_tol(SIGMA, ta_k, tb_k));
        /* The documented equivalent conductance, with no 0/0 at theta_A = theta_B. */
        FH_NEAR(ak_k, VIEW_F * SIGMA * (ta_k + tb_k) * (ta_k * ta_k + tb_k * tb_k),
                8.0 * DBL_EPSILON, 0.0);
        if (ta_k == tb_k) {
            FH_NEAR(ak_k, 4.0 * VIEW_F * SIGMA * ta_k * ta_k * ta_k, 8.0 * DBL_EPSILON, 0.0);
        }

        fh_context("plates %g C, %g C (Celsius, theta_Z = -273.15)", ta_c, tb_c);
        ak_c = gh_ak("RAD_C", 1e-3, 0.0, ta_c, tb_c);
        q = ak_c * (ta_c - tb_c);
        FH_NEAR(q, rad_flux(SIGMA, a_c, b_c), 4.0 * DBL_EPSILON, rad_flux_tol(SIGMA, a_c, b_c));
        if (ta_k == tb_k) {
            FH_NEAR(ak_c, 4.0 * VIEW_F * SIGMA * a_c * a_c * a_c, 8.0 * DBL_EPSILON, 0.0);
        }
        /* One physical state, two scales: the same conductance (up to the offset's rounding). */
        FH_NEAR(ak_c, ak_k, 1e-13, 0.0);

        fh_context("plates %g K, %g K, sigma in mW/(mm^2 K^4)", ta_k, tb_k);
        ak_mm = gh_ak("RAD_MM", 1e-3, 0.0, ta_k, tb_k);
        FH_NEAR(ak_mm, 1e-3 * ak_k, 1e-15, 0.0);

        fh_context("plates %g K, %g K, radiation + gas gap", ta_k, tb_k);
        {
            static const double gaps[] = {1e-4, 2e-3, 0.0};
            size_t g;
            for (g = 0; g < sizeof gaps / sizeof gaps[0]; g++) {
                double d = gaps[g];
                double k_cond = K_GAS / (d + G0);
                ak_gas = gh_ak("RAD_GAS", d, 0.0, ta_k, tb_k);
                FH_NEAR(ak_gas, k_cond + ak_k, 4.0 * DBL_EPSILON, 0.0);
                FH_NEAR(ak_gas * (ta_k - tb_k), k_cond * (ta_k - tb_k) + rad_flux(SIGMA, ta_k, tb_k),
                        4.0 * DBL_EPSILON, rad_flux_tol(SIGMA, ta_k, tb_k));
                FH_NEAR(gh_ak("RAD_GAS_C", d, 0.0, ta_c, tb_c), ak_gas, 1e-13, 0.0);
                /* view_factor = 0: no radiation, the conduction alone. */
                FH_NEAR(gh_ak("RAD_OFF", d, 0.0, ta_k, tb_k), k_cond, 1e-15, 0.0);
            }
        }

        fh_context("plates %g K, %g K: flux derivatives", ta_k, tb_k);
        c = gh_native_ok("RAD_K", 1e-3, 0.0, ta_k, tb_k);
        FH_CHECK(memcmp(&c.k, &ak_k, sizeof ak_k) == 0);
        FH_NEAR(c.dq_dtheta_a, 4.0 * VIEW_F * SIGMA * ta_k * ta_k * ta_k, 8.0 * DBL_EPSILON, 0.0);
        FH_NEAR(c.dq_dtheta_b, -4.0 * VIEW_F * SIGMA * tb_k * tb_k * tb_k, 8.0 * DBL_EPSILON,
                0.0);
        FH_EXACT(c.dk_dd, 0.0);
        FH_EXACT(c.dk_dp, 0.0);
        c = gh_native_ok("RAD_C", 1e-3, 0.0, ta_c, tb_c);
        FH_NEAR(c.dq_dtheta_a, 4.0 * VIEW_F * SIGMA * a_c * a_c * a_c, 8.0 * DBL_EPSILON, 0.0);
        FH_NEAR(c.dq_dtheta_b, -4.0 * VIEW_F * SIGMA * b_c * b_c * b_c, 8.0 * DBL_EPSILON, 0.0);
        /* Conduction adds its own k to dq/dtheta_A and takes it from dq/dtheta_B. */
        c = gh_native_ok("RAD_GAS", 1e-4, 0.0, ta_k, tb_k);
        FH_NEAR(c.dq_dtheta_a, K_GAS / (1e-4 + G0) + 4.0 * VIEW_F * SIGMA * ta_k * ta_k * ta_k,
                8.0 * DBL_EPSILON, 0.0);
        FH_NEAR(c.dq_dtheta_b, -K_GAS / (1e-4 + G0) - 4.0 * VIEW_F * SIGMA * tb_k * tb_k * tb_k,
                8.0 * DBL_EPSILON, 0.0);
    }
}

/* ---------------------------------------------------------------------------------------- */
/* Derivatives against central differences of the library's own k                           */

static double lib_k(const char *name, double d, double ta, double tb)
{
    return gh_native_ok(name, d, 0.0, ta, tb).k;
}

static void fd_derivatives(const char *name, double d, double theta_z, double ta, double tb)
{
    /* q is a quartic in each temperature: the central-difference error in dq/dtheta_B is
     * 4 F sigma b h^2, relative (h/b)^2 to 4 F sigma b^3; h = 1e-3 min(a, b) keeps it at 1e-6,
     * and the round-off eps q/h stays below 1e-5 of the derivative for these plates. */
    const double a = ta - theta_z, b = tb - theta_z;
    const double h = 1e-3 * fmin(a, b);
    IflConductance c = gh_native_ok(name, d, 0.0, ta, tb);
    double fd_qa, fd_qb, fd_km, fd_kd;
    fh_context("%s at d = %g, theta = (%g, %g): central differences", name, d, ta, tb);
    fd_qa = (lib_k(name, d, ta + h, tb) * (ta + h - tb) -
             lib_k(name, d, ta - h, tb) * (ta - h - tb)) / (2.0 * h);
    fd_qb = (lib_k(name, d, ta, tb + h) * (ta - tb - h) -
             lib_k(name, d, ta, tb - h) * (ta - tb + h)) / (2.0 * h);
    fd_km = (lib_k(name, d, ta + h, tb + h) - lib_k(name, d, ta - h, tb - h)) / (2.0 * h);
    fd_kd = (lib_k(name, d, ta, tb) == 0.0) ? 0.0
            : (lib_k(name, d + 1e-3 * d, ta, tb) - lib_k(name, d - 1e-3 * d, ta, tb)) /
                  (2e-3 * d);
    FH_NEAR(c.dq_dtheta_a, fd_qa, 1e-5, 0.0);
    FH_NEAR(c.dq_dtheta_b, fd_qb, 1e-5, 0.0);
    FH_NEAR(c.dk_dtheta_mean, fd_km, 1e-5, 0.0);
    FH_NEAR(c.dk_dd, fd_kd, 1e-5, 1e-12 * c.k / d);
    /* q = k(theta_mean, jump) jump: moving both temperatures together changes q by
     * (dk/dtheta_mean) jump, so the two flux derivatives must add up to that. */
    FH_NEAR(c.dq_dtheta_a + c.dq_dtheta_b, c.dk_dtheta_mean * (ta - tb), 1e-12,
            1e-12 * fabs(c.dq_dtheta_a));
}

static void derivatives(void)
{
    size_t i;
    for (i = 0; i < N_PLATES; i++) {
        double ta_k = PLATES[i][0], tb_k = PLATES[i][1];
        if (ta_k < 10.0 || tb_k < 10.0) {
            continue; /* differences would step below absolute zero */
        }
        fd_derivatives("RAD_K", 1e-3, 0.0, ta_k, tb_k);
        fd_derivatives("RAD_C", 1e-3, ZERO_C, ta_k + ZERO_C, tb_k + ZERO_C);
        fd_derivatives("RAD_GAS", 1e-4, 0.0, ta_k, tb_k);
        fd_derivatives("RAD_GAS_C", 3e-4, ZERO_C, ta_k + ZERO_C, tb_k + ZERO_C);
    }
}

/* ---------------------------------------------------------------------------------------- */
/* Bars on both sides                                                                        */

#define THETA_H_K 1200.0
#define THETA_C_K 300.0
#define R_A (0.01 / 1.0)  /* L_A = 0.01, k_A = 1 */
#define R_B (0.01 / 2.0)  /* L_B = 0.01, k_B = 2 */
#define BAR_GAP 2e-4      /* clearance for the gas-gap variant */

enum { MAX_IT = 40 };

typedef struct {
    const char *name;
    double d;        /* clearance */
    double theta_z;  /* absolute zero of the scale used */
    double k_cond;   /* conduction in parallel, by hand (0: radiation only) */
} bar_case;

/* Steady flux by hand: the flux through the bars and through the gap agree. */
static double mismatch(const bar_case *bc, double q)
{
    double th = THETA_H_K + bc->theta_z, tc = THETA_C_K + bc->theta_z;
    double ta = th - q * R_A, tb = tc + q * R_B;
    return rad_flux(SIGMA, ta - bc->theta_z, tb - bc->theta_z) + bc->k_cond * (ta - tb) - q;
}

static double bisect(const bar_case *bc)
{
    double lo = 0.0, hi = (THETA_H_K - THETA_C_K) / (R_A + R_B);
    int i;
    FH_CHECK(mismatch(bc, lo) > 0.0 && mismatch(bc, hi) < 0.0);
    for (i = 0; i < 400; i++) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) {
            break;
        }
        if (mismatch(bc, mid) > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

static double bars(const bar_case *bc)
{
    const double th = THETA_H_K + bc->theta_z, tc = THETA_C_K + bc->theta_z;
    const double q_ref = bisect(bc);
    const double ta_ref = th - q_ref * R_A, tb_ref = tc + q_ref * R_B;
    double ta = th, tb = tc, e_prev = 0.0, q;
    int it, n_conv = -1;

    printf("T2 bars, %s (theta_Z = %g): q = %.10g by bisection\n", bc->name, bc->theta_z,
           q_ref);
    printf("  %3s %22s %22s %10s %12s\n", "k", "theta_A", "theta_B", "error", "e_k/e_k-1^2");
    for (it = 0; it <= MAX_IT; it++) {
        double e = fmax(fabs(ta - ta_ref), fabs(tb - tb_ref));
        double ak, ra, rb, j11, j12, j21, j22, det, dta, dtb;
        IflConductance c;
        gh_gapcon g;
        if (it == 0) {
            printf("  %3d %22.14f %22.14f %10.3e\n", it, ta, tb, e);
        } else {
            printf("  %3d %22.14f %22.14f %10.3e %12.4e\n", it, ta, tb, e, e / (e_prev * e_prev));
        }
        fh_context("T2 bars, %s, iteration %d", bc->name, it);
        /* Quadratic: near the solution e_k/e_{k-1}^2 stays near (q''/2)/|J| from the quartic,
         * 12 F sigma a^2/2 ~ 0.2 against conductances ~ 1/R ~ 300: ~1e-3 per kelvin; the
         * bound 1e-2 allows a factor 10. */
        if (it > 0 && e_prev < 1.0 && e > 1e-9) {
            FH_CHECK(e / (e_prev * e_prev) < 1e-2);
        }
        if (n_conv < 0 && e <= 1e-12 * (THETA_H_K - THETA_C_K)) {
            n_conv = it;
        }
        e_prev = e;
        gh_init(&g, bc->name, bc->d, 0.0, ta, tb);
        ak = gh_call_ok(&g);
        c = gh_native_ok(bc->name, bc->d, 0.0, ta, tb);
        FH_CHECK(memcmp(&c.k, &ak, sizeof ak) == 0);
        q = ak * (ta - tb);
        ra = (th - ta) / R_A - q;
        rb = q - (tb - tc) / R_B;
        j11 = -1.0 / R_A - c.dq_dtheta_a;
        j12 = -c.dq_dtheta_b;
        j21 = c.dq_dtheta_a;
        j22 = c.dq_dtheta_b - 1.0 / R_B;
        det = j11 * j22 - j12 * j21;
        dta = (-ra * j22 + rb * j12) / det;
        dtb = (-rb * j11 + ra * j21) / det;
        if (fmax(fabs(dta), fabs(dtb)) <= 1e-14 * (THETA_H_K - THETA_C_K)) {
            break;
        }
        ta += dta;
        tb += dtb;
    }
    printf("  iterations to |error| <= 1e-12 (theta_H - theta_C): %d\n", n_conv);
    fh_context("T2 bars, %s: converged", bc->name);
    FH_CHECK(n_conv >= 0 && n_conv <= 8);
    q = gh_ak(bc->name, bc->d, 0.0, ta, tb) * (ta - tb);
    FH_NEAR(q, q_ref, 1e-12, 0.0);
    FH_NEAR((th - ta) / R_A, q_ref, 1e-11, 0.0);
    FH_NEAR((tb - tc) / R_B, q_ref, 1e-11, 0.0);
    /* The gap's flux by the closed form at the converged surface temperatures. */
    FH_NEAR(q, rad_flux(SIGMA, ta - bc->theta_z, tb - bc->theta_z) + bc->k_cond * (ta - tb),
            1e-12, 0.0);
    return q;
}

int main(int argc, char **argv)
{
    static const bar_case cases[] = {
        {"RAD_K", 1e-3, 0.0, 0.0},
        {"RAD_C", 1e-3, ZERO_C, 0.0},
        {"RAD_GAS", BAR_GAP, 0.0, K_GAS / (BAR_GAP + G0)},
        {"RAD_GAS_C", BAR_GAP, ZERO_C, K_GAS / (BAR_GAP + G0)},
    };
    double q[4];
    size_t i;
    write_config(argc > 1 ? argv[1] : "gapcon_t2.toml");
    plates();
    derivatives();
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        q[i] = bars(&cases[i]);
    }
    /* One physical problem on two scales: the same flux through the library. */
    fh_context("T2 bars: kelvin and Celsius");
    FH_NEAR(q[1], q[0], 1e-12, 0.0);
    FH_NEAR(q[3], q[2], 1e-12, 0.0);
    /* Conduction in parallel only adds. */
    FH_CHECK(q[2] > q[0]);
    return fh_finish();
}
