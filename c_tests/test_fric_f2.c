/*
 * Scene F2, circle (docs/scene-definitions.md), NFDIR = 2, driven through fric_ as a
 * quasi-static host: the imposed slip follows a circle of radius R,
 *   gamma(theta) = R (cos theta, sin theta),  theta_k = k dtheta,  dtheta = 2 pi / N,
 * so DGAM_k = gamma(theta_k) - gamma(theta_{k-1}), a chord of length c = 2 R sin(dtheta/2)
 * along the tangent at the mid-angle theta_k - dtheta/2. TAU and STATEV are carried over.
 *
 * Parameters (mirrored by fortran_tests/test_fric_scenes.f90):
 *   mu = 0.3, p = 100 (mu p = 30), gamma_crit = 1e-3 (PROPS(5)), R = 0.01 (rho = gamma_crit/R
 *   = 0.1), N = 1000 and 5000 increments per turn, 4 turns, measured over the last turn.
 *
 * Exact steady state of the rate problem: |tau| = mu p and tau lags the slip direction (the
 * tangent t = (-sin theta, cos theta)) by phi with sin phi = rho.
 *
 * Discrete steady state of the backward-Euler return map (derived here, asserted below): in
 * steady slip the elastic slip gamma_el = tau/k_s has length gamma_crit and rotates by dtheta
 * per increment, lagging t by phi_N. Written in the frame of t(theta_k), gamma_el of the start
 * is gamma_crit e(-dtheta - phi_N), the chord is c e(-dtheta/2), and their sum gamma_pr must
 * point along e(-phi_N). Its component across e(-phi_N) vanishes:
 *   -gamma_crit sin(dtheta) + c sin(phi_N - dtheta/2) = 0
 *   => phi_N = dtheta/2 + asin(rho cos(dtheta/2)),
 * and the slip of one increment is its component along e(-phi_N) minus gamma_crit:
 *   s = gamma_crit (cos(dtheta) - 1) + c cos(phi_N - dtheta/2).
 * So the lag error phi_N - asin(rho) = dtheta/2 - rho dtheta^2/(8 sqrt(1 - rho^2)) + O(dtheta^4):
 * first order, with constant 1/2 (scenes.md: N = 1000 -> 3.1e-3, N = 5000 -> 6.3e-4).
 */
#include <math.h>
#include <stdio.h>

#include "harness.h"

#define MU 0.3
#define P 100.0
#define GAMMA_CRIT 1e-3
#define RADIUS 0.01
#define TURNS 4

/* Signed angle from vector a to vector b (positive counter-clockwise). */
static double angle_from_to(const double *a, const double *b)
{
    return atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
}

/* Runs N increments per turn; returns the lag error phi - asin(rho) at the last increment. */
static double f2_circle(int n_per_turn)
{
    static const double props[] = {1, MU, 0, 0, GAMMA_CRIT};
    const double tc = MU * P;
    const double ks = tc / GAMMA_CRIT;
    const double rho = GAMMA_CRIT / RADIUS;
    const double dtheta = 2.0 * FH_PI / n_per_turn;
    const double dtime = 1.0 / n_per_turn; /* one turn per unit time */
    const double chord = 2.0 * RADIUS * sin(dtheta / 2.0);
    const double phi_n = dtheta / 2.0 + asin(rho * cos(dtheta / 2.0));
    const double s_n = GAMMA_CRIT * (cos(dtheta) - 1.0) + chord * cos(phi_n - dtheta / 2.0);
    const int n_total = TURNS * n_per_turn;
    int slipped = 0; /* once slipping, the point slips in every later increment */
    double phi = 0.0;
    double max_phi_dev = 0.0;
    fh_fric h;
    int k, a, b;

    fh_init(&h, 2, props, 5);
    h.dtime = dtime;
    for (k = 1; k <= n_total; k++) {
        const double th = k * dtheta, th0 = (k - 1) * dtheta;
        const double t[2] = {-sin(th), cos(th)}; /* slip (tangent) direction at the end */
        /* Distance from the start of the path: stick while it is within gamma_crit. */
        const double from_start = 2.0 * RADIUS * sin(th / 2.0);
        const int stick_exp = !slipped && from_start <= GAMMA_CRIT;
        double mag;
        fh_context("F2 N=%d, increment %d", n_per_turn, k);

        h.press = P;
        h.dpress = k == 1 ? P : 0.0;
        h.kinc = k;
        h.dgam[0] = RADIUS * (cos(th) - cos(th0));
        h.dgam[1] = RADIUS * (sin(th) - sin(th0));
        h.lm = 0;
        fh_call_ok(&h);
        FH_CHECK(h.lm == 0);
        FH_CHECK(h.sfd >= 0.0);
        FH_EXACT(h.statev[2], stick_exp ? 0.0 : 1.0);
        mag = sqrt(h.tau[0] * h.tau[0] + h.tau[1] * h.tau[1]);
        if (stick_exp) {
            /* Elastic: tau = k_s (gamma(theta_k) - gamma(0)). */
            FH_NEAR(h.tau[0], ks * RADIUS * (cos(th) - 1.0), 0.0, 1e-11 * tc);
            FH_NEAR(h.tau[1], ks * RADIUS * sin(th), 0.0, 1e-11 * tc);
            FH_EXACT(h.sfd, 0.0);
            continue;
        }
        slipped = 1;
        /* On the cone to round-off. */
        FH_NEAR(mag, tc, 1e-14, 0.0);
        phi = angle_from_to(h.tau, t);
        /* Lagging, by less than a right angle, throughout the transient. */
        FH_CHECK(phi > 0.0 && phi < FH_PI / 2.0);

        if (k > n_total - n_per_turn) {
            /* Last turn: the discrete steady state, in every output. */
            const double n[2] = {cos(th + FH_PI / 2.0 - phi_n), sin(th + FH_PI / 2.0 - phi_n)};
            double dev = fabs(phi - phi_n);
            if (dev > max_phi_dev) {
                max_phi_dev = dev;
            }
            for (a = 0; a < 2; a++) {
                FH_NEAR(h.tau[a], tc * n[a], 0.0, 1e-9 * tc);
                FH_NEAR(h.dslip[a], s_n * n[a], 0.0, 1e-9 * GAMMA_CRIT);
                FH_NEAR(h.ddtddp[a], MU * n[a], 0.0, 1e-9 * MU);
                for (b = 0; b < 2; b++) {
                    double delta = a == b ? 1.0 : 0.0;
                    /* (I - n n^T) tau_crit/|gamma_pr|, |gamma_pr| = gamma_crit + s. */
                    FH_NEAR(fh_ddtddg(&h, a + 1, b + 1),
                            (delta - n[a] * n[b]) * tc / (GAMMA_CRIT + s_n), 0.0, 1e-9 * ks);
                }
            }
            FH_NEAR(h.sfd, tc * s_n, 1e-9, 0.0);
            FH_NEAR(h.sed, tc * GAMMA_CRIT / 2.0, 1e-14, 0.0);
            FH_NEAR(h.statev[1], s_n / dtime, 1e-9, 0.0);
        }
    }
    fh_context("F2 N=%d, steady state over the last turn", n_per_turn);
    /* The lag is the discrete steady state phi_N everywhere on the last turn. */
    FH_NEAR(max_phi_dev, 0.0, 0.0, 1e-10);
    /* ... which converges to asin(rho) with an error of at most the step angle. */
    FH_CHECK(fabs(phi - asin(rho)) <= dtheta);
    FH_NEAR(phi - asin(rho), dtheta / 2.0, 1e-3, 0.0);
    return phi - asin(rho);
}

int main(void)
{
    double e1000 = f2_circle(1000);
    double e5000 = f2_circle(5000);
    double ratio = e1000 / e5000;
    fh_context("F2 order of convergence");
    /*
     * First order: error = dtheta/2 (1 - rho dtheta/(4 sqrt(1 - rho^2)) + ...), so
     * e(1000)/e(5000) = 5 (1 - rho (dtheta_1000 - dtheta_5000)/(4 sqrt(1 - rho^2)) + ...)
     * = 5 (1 - 1.3e-4) = 4.9994 in theory. The transient has died out after 4 turns (the lag
     * contracts by about 1/(1 + c/gamma_crit) per increment: below e^-100 after 3 turns) and
     * round-off in phi is ~1e-15 rad against errors >= 6e-4, so the measured ratio sits within
     * 1e-3 of 4.9994. The band [4.95, 5.05] (1%) is ten times that margin and still rejects
     * any other order: an order q gives 5^q (q = 2: 25; q = 0.9: 4.26; q = 1.1: 5.87). The
     * error constant 1/2 itself is checked in f2_circle (relative 1e-3).
     */
    printf("F2 lag error: N=1000 %.6e, N=5000 %.6e, ratio %.6f (theory 4.9994)\n", e1000,
           e5000, ratio);
    FH_CHECK(ratio > 4.95 && ratio < 5.05);
    return fh_finish();
}
