/*
 * Scene F5, pressure ramp while sliding (docs/scene-definitions.md), NFDIR = 1 and 2, driven
 * through fric_ as a quasi-static host: PRESS = p(t_k), DPRESS = p(t_k) - p(t_{k-1}), TAU and
 * STATEV carried over, steady imposed slip DGAM = 0.6 gamma_crit d per increment along a fixed
 * direction d (1-D, or 30 degrees in the tangent plane).
 *
 * Parameters (mirrored by fortran_tests/test_fric_scenes.f90):
 *   mu = 0.3, gamma_crit = 1e-3 (PROPS(5)), tau_max = 20 for the cap cases (mu p = 20 at
 *   p = 66.7, crossed both ways by the ramp); p = 100 for increments 1-2 (first contact in 1),
 *   then 100 -> 200 -> 50 -> 100 in steps of 5 (never exactly on the cap's kink).
 *
 * Closed form: increment 1 sticks (tau = 0.6 tau_crit), increment 2 slips 0.2 gamma_crit,
 * every later one slips 0.6 gamma_crit: the elastic slip at the start, recovered with the
 * start stiffness (gamma_el = TAU gamma_crit/tau_crit(p0)), is gamma_crit d whatever p does.
 * In slip tau = tau_crit(p) d with tau_crit(p) = min(mu p, tau_max); DDTDDP = mu d, 0 on the
 * cap; DDTDDG = (I - d d^T) tau_crit/|gamma_pr|, 0 in 1-D.
 * Tangents are also checked against central finite differences of fric_'s own TAU: in the end
 * pressure (PRESS and DPRESS perturbed together, the start p0 = PRESS - DPRESS held fixed) and
 * in each component of DGAM.
 *
 * Also: during stick a pressure change uses the start-of-increment stiffness: stick at p0,
 * then DGAM = 0 while p doubles -> tau doubles (and p halves -> tau halves).
 */
#include <math.h>
#include <stdio.h>

#include "harness.h"

#define MU 0.3
#define GAMMA_CRIT 1e-3
#define TAU_MAX 20.0
#define STEP (0.6 * GAMMA_CRIT)
#define N_INC 62
/* Finite-difference steps: tau is linear in the end pressure, so only round-off matters
 * (error ~ ulp(30)/dp ~ 4e-13); in DGAM the truncation error ~ dg^2 tau_crit/|gamma_pr|^3
 * ~ 1e-6 and the round-off ~ ulp(30)/dg ~ 4e-7 balance near dg = 1e-8. */
#define FD_DP 1e-2
#define FD_DG 1e-8

/* Contact pressure at the end of increment k (0 before first contact). */
static double pressure(int k)
{
    if (k <= 0) {
        return 0.0;
    }
    if (k <= 2) {
        return 100.0;
    }
    if (k <= 22) {
        return 100.0 + 5.0 * (k - 2);
    }
    if (k <= 52) {
        return 200.0 - 5.0 * (k - 22);
    }
    return 50.0 + 5.0 * (k - 52);
}

static double critical_stress(double p, int capped)
{
    return capped ? fmin(MU * p, TAU_MAX) : MU * p;
}

/* Central differences of TAU: column `col` of d tau/d p (col < 0) or of d tau/d DGAM_col. */
static void fd_column(const fh_fric *start, int col, double *out)
{
    fh_fric plus = *start, minus = *start;
    int a;
    if (col < 0) {
        plus.press += FD_DP;
        plus.dpress += FD_DP;
        minus.press -= FD_DP;
        minus.dpress -= FD_DP;
    } else {
        plus.dgam[col] += FD_DG;
        minus.dgam[col] -= FD_DG;
    }
    fh_call_ok(&plus);
    fh_call_ok(&minus);
    for (a = 0; a < start->nfdir; a++) {
        out[a] = (plus.tau[a] - minus.tau[a]) / (2.0 * (col < 0 ? FD_DP : FD_DG));
    }
}

/* The returned tangents against central differences of fric_ from the same start. */
static void check_tangents_fd(const fh_fric *start, const fh_fric *done, double ks)
{
    double col[2];
    int a, b;
    fd_column(start, -1, col);
    for (a = 0; a < start->nfdir; a++) {
        FH_NEAR(done->ddtddp[a], col[a], 0.0, 1e-7);
    }
    for (b = 0; b < start->nfdir; b++) {
        fd_column(start, b, col);
        for (a = 0; a < start->nfdir; a++) {
            FH_NEAR(fh_ddtddg(done, a + 1, b + 1), col[a], 0.0, 1e-8 * ks);
        }
    }
}

static void f5_ramp(int nfdir, int capped)
{
    static const double plain[] = {1, MU, 0, 0, GAMMA_CRIT};
    static const double cap[] = {1, MU, 0, TAU_MAX, GAMMA_CRIT};
    const double d[2] = {nfdir == 1 ? 1.0 : sqrt(3.0) / 2.0, nfdir == 1 ? 0.0 : 0.5};
    double accumulated = 0.0;
    fh_fric h;
    int k, a, b;

    fh_init(&h, nfdir, capped ? cap : plain, 5);
    for (k = 1; k <= N_INC; k++) {
        const double p = pressure(k);
        const double tc = critical_stress(p, capped);
        const double ks = tc / GAMMA_CRIT;
        const int on_cap = capped && MU * p >= TAU_MAX;
        const double slip = k == 1 ? 0.0 : (k == 2 ? 0.2 * GAMMA_CRIT : STEP);
        fh_fric start;
        fh_context("F5 %s, NFDIR=%d, increment %d, p=%g", capped ? "tau_max 20" : "no cap",
                   nfdir, k, p);

        h.press = p;
        h.dpress = p - pressure(k - 1);
        h.kinc = k;
        for (a = 0; a < nfdir; a++) {
            h.dgam[a] = STEP * d[a];
        }
        h.lm = 0;
        start = h;
        fh_call_ok(&h);
        FH_CHECK(h.lm == 0);
        FH_EXACT(h.statev[2], k == 1 ? 0.0 : 1.0);
        accumulated += slip;
        FH_NEAR(h.statev[0], accumulated, 1e-12, 0.0);

        if (k == 1) {
            /* Stick: tau = k_s DGAM. */
            for (a = 0; a < nfdir; a++) {
                FH_NEAR(h.tau[a], 0.6 * tc * d[a], 0.0, 1e-12 * tc);
            }
            check_tangents_fd(&start, &h, ks);
            continue;
        }
        /* Slip: tau = min(mu p, tau_max) along d (exactly in 1-D). */
        for (a = 0; a < nfdir; a++) {
            if (nfdir == 1) {
                FH_EXACT(h.tau[a], tc);
            } else {
                FH_NEAR(h.tau[a], tc * d[a], 1e-13, 1e-13 * tc);
            }
            FH_NEAR(h.ddtddp[a], on_cap ? 0.0 : MU * d[a], 0.0, 1e-14);
            FH_NEAR(h.dslip[a], slip * d[a], 1e-10, 1e-14 * GAMMA_CRIT);
            for (b = 0; b < nfdir; b++) {
                double delta = a == b ? 1.0 : 0.0;
                double want = nfdir == 1 ? 0.0
                                         : (delta - d[a] * d[b]) * tc / (GAMMA_CRIT + slip);
                FH_NEAR(fh_ddtddg(&h, a + 1, b + 1), want, 0.0, 1e-10 * ks);
            }
        }
        if (on_cap) {
            FH_EXACT(h.ddtddp[0], 0.0);
        }
        FH_NEAR(h.sfd, tc * slip, 1e-10, 0.0);
        FH_NEAR(h.sed, tc * GAMMA_CRIT / 2.0, 1e-13, 0.0);
        check_tangents_fd(&start, &h, ks);
    }
}

/*
 * Stick while the pressure changes: the elastic slip of the start is TAU/k_s(p0), so with
 * DGAM = 0 the stress scales with k_s(p)/k_s(p0) = tau_crit(p)/tau_crit(p0).
 *   increment 1: p = 100 (first contact), DGAM = 0.5 gamma_crit d -> tau = 0.5 tau_crit(100) d
 *   increment 2: p = 200, DGAM = 0 -> tau = 0.5 tau_crit(200) d (doubles without the cap)
 *   increment 3: p = 50,  DGAM = 0 -> tau = 0.5 tau_crit(50) d  (a quarter of increment 2)
 * Recovering the elastic slip with the end pressure instead would leave tau unchanged.
 */
static void f5_stick_pressure_change(int nfdir, int capped)
{
    static const double plain[] = {1, MU, 0, 0, GAMMA_CRIT};
    static const double cap[] = {1, MU, 0, TAU_MAX, GAMMA_CRIT};
    static const double p_hist[4] = {0.0, 100.0, 200.0, 50.0};
    const double d[2] = {nfdir == 1 ? 1.0 : sqrt(3.0) / 2.0, nfdir == 1 ? 0.0 : 0.5};
    fh_fric h;
    int k, a, b;

    fh_init(&h, nfdir, capped ? cap : plain, 5);
    for (k = 1; k <= 3; k++) {
        const double p = p_hist[k];
        const double tc = critical_stress(p, capped);
        const double ks = tc / GAMMA_CRIT;
        const int on_cap = capped && MU * p >= TAU_MAX;
        fh_fric start;
        fh_context("F5 stick with pressure change, %s, NFDIR=%d, p=%g",
                   capped ? "tau_max 20" : "no cap", nfdir, p);
        h.press = p;
        h.dpress = p - p_hist[k - 1];
        for (a = 0; a < nfdir; a++) {
            h.dgam[a] = k == 1 ? 0.5 * GAMMA_CRIT * d[a] : 0.0;
        }
        h.lm = 0;
        start = h;
        fh_call_ok(&h);
        FH_CHECK(h.lm == 0);
        FH_EXACT(h.statev[2], 0.0);
        for (a = 0; a < nfdir; a++) {
            FH_NEAR(h.tau[a], 0.5 * tc * d[a], 0.0, 1e-12 * tc);
            /* d tau/d p = gamma_pr mu/gamma_crit in stick, 0 on the cap. */
            FH_NEAR(h.ddtddp[a], on_cap ? 0.0 : 0.5 * MU * d[a], 0.0, 1e-14);
            for (b = 0; b < nfdir; b++) {
                FH_NEAR(fh_ddtddg(&h, a + 1, b + 1), a == b ? ks : 0.0, 1e-14, 0.0);
            }
        }
        FH_EXACT(h.sfd, 0.0);
        check_tangents_fd(&start, &h, ks);
    }
}

int main(void)
{
    int nfdir, capped;
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        for (capped = 0; capped <= 1; capped++) {
            f5_ramp(nfdir, capped);
            f5_stick_pressure_change(nfdir, capped);
        }
    }
    return fh_finish();
}
