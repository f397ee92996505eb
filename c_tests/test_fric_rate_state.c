/*
 * Rate-and-state friction (PROPS(1) = 3, docs/props.md "Law 3") driven through fric_ as a host
 * drives it, increment by increment, against the closed forms of the Dieterich-Ruina law at a
 * constant slip rate (theta is advanced exactly over an increment at its end-of-increment rate,
 * and a sliding increment keeps the elastic slip at gamma_crit, so these hold to round-off):
 *
 *   Steady sliding at V, NFDIR 1 and 2, aging and slip laws, at two increment sizes (2 L and
 *       L/20 of slip): |TAU| = mu_ss(V) p with mu_ss = mu0 + (a - b) ln(V/V0) (logarithmic
 *       form) or the regularised form's own steady state
 *       a asinh(V/(2 V0) exp((mu0 + b ln(V0/V))/a)), on a parameter set where the two differ;
 *       both sizes give the same stress; STATEV = (slip path, V, 1, L/V), DSLIP = V DTIME d,
 *       SFD = |TAU| V DTIME, SED = |TAU| gamma_crit/2, LM = 0; the slip tangent along d against
 *       a central difference of TAU.
 *   Velocity step V1 -> V2 (up and down) from steady state: at the end of each increment,
 *       TAU/p = mu(V2, theta(t)) with the evolution law's analytic theta(t) at constant V2
 *       (aging: L/V2 + (theta1 - L/V2) e^(-V2 t/L); slip: (L/V2) exp(ln(V2 theta1/L) e^(-V2 t/L))),
 *       STATEV(4) = theta(t); the first increment's jump is a ln(V2/V1) + b ln(theta(dt)/theta1)
 *       (logarithmic form).
 *   Bad input refused (PNEWDT < 1, the message names FRIC, the interaction and the cause; TAU
 *       and STATEV unchanged): NSTATV = 3, a = -0.01 (PROPS(3)), V0 = 0 (PROPS(5)), L = 0
 *       (PROPS(6)), theta < 0 in STATEV(4), DTIME = 0.
 *
 * Every expected value is written out here from the law's definition. Mirrored by
 * fortran_tests/test_fric_rate_state.f90.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"

#define V0 1e-6
#define L_SLIP 1e-5
#define GAMMA_CRIT 1e-7
#define P 50.0
#define NSTATV_RATE_STATE 4

/* Two parameter sets: rock-like (a = 0.01, where the regularised form is the logarithmic one to
 * round-off) and one where the regularisation changes mu by 10 % or more (mu0/a = 1). On the
 * second the logarithmic mu goes below 0 (taken as 0, a stress-free slide) for V below V0 at
 * theta = L/V0, so its scenes slide at V0 and above. */
typedef struct {
    double mu0, a, b;
} rs_set;
static const rs_set SETS[2] = {{0.6, 0.01, 0.015}, {0.1, 0.1, 0.12}};

/* The slip direction in the plane. */
static void direction(int nfdir, double d[2])
{
    d[0] = nfdir == 1 ? 1.0 : 0.6;
    d[1] = nfdir == 1 ? 0.0 : -0.8;
}

/* mu(V, theta) of each form, from the law's definition. */
static double mu_of(const rs_set *s, int regularised, double v, double theta)
{
    double psi = s->mu0 + s->b * log(V0 * theta / L_SLIP);
    if (regularised) {
        return s->a * asinh(v / (2.0 * V0) * exp(psi / s->a));
    }
    return psi + s->a * log(v / V0);
}

/* The steady-state coefficient at V (theta = L/V). */
static double mu_ss(const rs_set *s, int regularised, double v)
{
    if (regularised) {
        return s->a * asinh(v / (2.0 * V0) * exp((s->mu0 + s->b * log(V0 / v)) / s->a));
    }
    return s->mu0 + (s->a - s->b) * log(v / V0);
}

/* theta after sliding at constant V for a time t from theta1: each law's analytic solution. */
static double theta_at(double theta1, double v, double t, int slip_law)
{
    double decay = exp(-v * t / L_SLIP);
    if (slip_law) {
        return L_SLIP / v * exp(log(v * theta1 / L_SLIP) * decay);
    }
    return L_SLIP / v + (theta1 - L_SLIP / v) * decay;
}

/* A point of interaction SI_PAD at first contact (PRESS = DPRESS = P), NSTATV = 4 with STATEV 0
 * (theta not yet started: L/V0), the whole law-3 layout. */
static void point(fh_fric *h, int nfdir, const rs_set *s, int slip_law, int regularised)
{
    double props[IFLP_RATE_STATE_NPROPS] = {0};
    props[IFLP_RATE_STATE_CODE] = IFLP_LAW_RATE_STATE;
    props[IFLP_RATE_STATE_MU0] = s->mu0;
    props[IFLP_RATE_STATE_A] = s->a;
    props[IFLP_RATE_STATE_B] = s->b;
    props[IFLP_RATE_STATE_V0] = V0;
    props[IFLP_RATE_STATE_L] = L_SLIP;
    props[IFLP_RATE_STATE_EVOLUTION] = slip_law;
    props[IFLP_RATE_STATE_FORM] = regularised;
    props[IFLP_RATE_STATE_GAMMA_CRIT] = GAMMA_CRIT;
    fh_init(h, nfdir, props, IFLP_RATE_STATE_NPROPS);
    h->nstatv = NSTATV_RATE_STATE;
    h->statev[3] = 0.0;
    h->press = P;
    h->dpress = P;
    fh_set_guards(h);
}

/* One increment of slip dg along the direction in time dg/v (a call that must succeed, LM = 0);
 * returns |TAU|. */
static double step(fh_fric *h, double dg, double v)
{
    double d[2], t = 0.0;
    int a;
    direction(h->nfdir, d);
    for (a = 0; a < h->nfdir; a++) {
        h->dgam[a] = dg * d[a];
    }
    h->dtime = dg / v;
    fh_call_ok(h);
    FH_EXACT(h->lm, 0);
    h->dpress = 0.0;
    for (a = 0; a < h->nfdir; a++) {
        t += h->tau[a] * h->tau[a];
    }
    return sqrt(t);
}

static void steady(int set, int slip_law, int regularised, int nfdir)
{
    static const double rates_of_set[2][3] = {{3e-7, 1e-6, 1e-5}, {1e-6, 3e-6, 1e-5}};
    static const double per_l[2] = {0.5, 20.0}; /* increments per slip L */
    const double *rates = rates_of_set[set];
    const rs_set *s = &SETS[set];
    double d[2];
    int i, j, k, a;
    direction(nfdir, d);
    for (i = 0; i < 3; i++) {
        double v = rates[i], want = mu_ss(s, regularised, v) * P, tau[2] = {0.0, 0.0};
        for (j = 0; j < 2; j++) {
            double dg = L_SLIP / per_l[j], path, t = 0.0;
            int n = (int)(60.0 * per_l[j]); /* 60 L of slip: e^(-60) of the way left */
            fh_fric h;
            fh_context("steady set %d evolution %d form %d NFDIR %d V %g, %g increments per L",
                       set, slip_law, regularised, nfdir, v, per_l[j]);
            point(&h, nfdir, s, slip_law, regularised);
            for (k = 0; k < n; k++) {
                t = step(&h, dg, v);
            }
            path = h.statev[0];
            tau[j] = t;
            FH_NEAR(t, want, 1e-13, 0.0);
            /* The stress lies along the slip, and every output is the steady slide's. */
            for (a = 0; a < nfdir; a++) {
                FH_NEAR(h.tau[a], want * d[a], 1e-12, 1e-15 * want);
                FH_NEAR(h.dslip[a], dg * d[a], 1e-12, 1e-15 * dg);
                FH_NEAR(h.ddtddp[a], want / P * d[a], 1e-12, 1e-15);
            }
            FH_NEAR(h.sfd, t * dg, 1e-12, 0.0);
            FH_NEAR(h.sed, 0.5 * t * GAMMA_CRIT, 1e-12, 0.0);
            FH_EXACT(h.statev[2], 1.0);
            FH_NEAR(h.statev[1], v, 1e-12, 0.0);
            FH_NEAR(h.statev[3], L_SLIP / v, 1e-11, 0.0);
            /* The path: the first increment slides dg - gamma_crit, every later one dg. */
            FH_NEAR(path, n * dg - GAMMA_CRIT, 1e-12, 0.0);
            /* The slip tangent along d against a central difference of TAU; its scale is
             * p max(a, |b|)/(V DTIME). */
            fh_check_tangent_along(&h, d, 1e-5 * P * fmax(s->a, fabs(s->b)) / (v * h.dtime));
        }
        fh_context("steady set %d evolution %d form %d NFDIR %d V %g: increment sizes", set,
                   slip_law, regularised, nfdir, v);
        FH_NEAR(tau[0], tau[1], 1e-13, 0.0);
        /* On the second set the regularised steady state is not the logarithmic one: the
         * comparison above tells the two forms apart. */
        if (set == 1) {
            FH_CHECK(fabs(mu_ss(s, 1, v) - mu_ss(s, 0, v)) > 1e-3);
        }
    }
}

/* Steady sliding at v1 (60 L at 20 increments per L), then increments of L/per_l at v2. */
static void velocity_step(int set, int slip_law, int regularised, double v1, double v2,
                          double per_l)
{
    const rs_set *s = &SETS[set];
    double dg1 = L_SLIP / 20.0, dg = L_SLIP / per_l, dt = dg / v2, theta1, t, to_ss, decayed;
    int k, n = (int)(10.0 * per_l);
    fh_fric h;
    fh_context("step set %d evolution %d form %d V %g -> %g, %g increments per L", set,
               slip_law, regularised, v1, v2, per_l);
    point(&h, 1, s, slip_law, regularised);
    for (k = 0; k < 1200; k++) {
        t = step(&h, dg1, v1);
    }
    FH_NEAR(t, mu_ss(s, regularised, v1) * P, 1e-12, 0.0);
    theta1 = h.statev[3];
    FH_NEAR(theta1, L_SLIP / v1, 1e-11, 0.0);
    for (k = 1; k <= n; k++) {
        double theta = theta_at(theta1, v2, k * dt, slip_law);
        t = step(&h, dg, v2);
        FH_NEAR(t / P, mu_of(s, regularised, v2, theta), 0.0, 1e-12);
        FH_NEAR(h.statev[3], theta, 1e-10, 0.0);
        if (k == 1 && !regularised) {
            /* The direct effect a ln(V2/V1) and the evolution over the first increment. */
            FH_NEAR(t / P - mu_ss(s, 0, v1),
                    s->a * log(v2 / v1) + s->b * log(theta / theta1), 0.0, 1e-12);
        }
    }
    /* After 10 L of slip: within the decayed distance from the new steady state,
     * b |ln(theta/theta_ss)| with ln(V2 theta/L) = ln(V2/V1) e^(-10) (slip law) or
     * V2 theta/L - 1 = (V2/V1 - 1) e^(-10) (aging law), |ln(1 + x)| <= |x|/(1 - |x|). */
    to_ss = fabs(t / P - mu_ss(s, regularised, v2));
    decayed = (slip_law ? fabs(log(v2 / v1)) : fabs(v2 / v1 - 1.0)) * exp(-10.0);
    FH_CHECK(to_ss <= s->b * decayed / (1.0 - decayed) * (1.0 + 1e-9) + 1e-12);
}

/* A point that has slid (state in STATEV(1..4)), spoiled by the caller, must be refused by a
 * message naming needle; STATEV(4) is left as it was too. */
static void refused(fh_fric *h, const char *needle)
{
    double theta = h->statev[3];
    int nstatv = h->nstatv;
    fh_check_refused(h, needle, "SI_PAD");
    if (nstatv >= NSTATV_RATE_STATE) {
        FH_CHECK(memcmp(&h->statev[3], &theta, sizeof theta) == 0);
    }
}

/* A point of the rock-like set after one sliding increment, about to slide another. */
static void slid_point(fh_fric *h, int nfdir)
{
    point(h, nfdir, &SETS[0], 0, 0);
    step(h, 1e-6, 1e-6);
    h->dgam[0] = 1e-6;
    h->dtime = 1.0;
}

static void bad_input(int nfdir)
{
    fh_fric h;
    fh_context("bad input NFDIR %d: NSTATV = 3", nfdir);
    slid_point(&h, nfdir);
    h.nstatv = 3;
    refused(&h, "NSTATV = 3");
    fh_context("bad input NFDIR %d: a = -0.01", nfdir);
    slid_point(&h, nfdir);
    h.props[IFLP_RATE_STATE_A] = -0.01;
    refused(&h, "PROPS(3)");
    fh_context("bad input NFDIR %d: V0 = 0", nfdir);
    slid_point(&h, nfdir);
    h.props[IFLP_RATE_STATE_V0] = 0.0;
    refused(&h, "PROPS(5)");
    fh_context("bad input NFDIR %d: L = 0", nfdir);
    slid_point(&h, nfdir);
    h.props[IFLP_RATE_STATE_L] = 0.0;
    refused(&h, "PROPS(6)");
    fh_context("bad input NFDIR %d: theta < 0", nfdir);
    slid_point(&h, nfdir);
    h.statev[3] = -1.0;
    refused(&h, "STATEV(4)");
    fh_context("bad input NFDIR %d: DTIME = 0", nfdir);
    slid_point(&h, nfdir);
    h.dtime = 0.0;
    refused(&h, "DTIME");
}

int main(void)
{
    int set, slip_law, regularised, nfdir;
    for (set = 0; set < 2; set++) {
        for (slip_law = 0; slip_law <= 1; slip_law++) {
            for (regularised = 0; regularised <= 1; regularised++) {
                for (nfdir = 1; nfdir <= 2; nfdir++) {
                    steady(set, slip_law, regularised, nfdir);
                }
                velocity_step(set, slip_law, regularised, 1e-6, 1e-5, 2.0);
                velocity_step(set, slip_law, regularised, 1e-6, 1e-5, 200.0);
                /* Down: on the second set the logarithmic mu(V0, L/(10 V0)) < 0. */
                if (set == 0 || regularised) {
                    velocity_step(set, slip_law, regularised, 1e-5, 1e-6, 20.0);
                }
            }
        }
    }
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        bad_input(nfdir);
    }
    return fh_finish();
}
