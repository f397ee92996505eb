/*
 * Scene F1, pull to plateau (docs/scene-definitions.md), driven through fric_ the way a
 * quasi-static host drives one contact point: increment k passes TAU = the stress returned by
 * increment k-1, DGAM = gamma(t_k) - gamma(t_{k-1}), STATEV from increment k-1, PNEWDT = 1e36.
 *
 * Parameters (mirrored by fortran_tests/test_fric_f1.f):
 *   mu = 0.3, p = 100 (so mu*p = 30), gamma_crit = 1e-3 from PROPS(5), or 0.005 x CHRLNGTH
 *   with CHRLNGTH = 0.2 (default tolerance), or PROPS(6) = 0.02 x CHRLNGTH 0.1 (= 2e-3);
 *   tau_max = 20 for the cap cases; NFDIR = 1, and NFDIR = 2 with slip along 30 degrees.
 *   Path: gamma = 0 -> 20 gamma_crit in 146 increments, then -> -20 gamma_crit in 292
 *   (increment 20/146 = 0.137 gamma_crit, chosen so no increment ends exactly on the yield
 *   point: the stick/slip classification of every increment is unambiguous).
 *
 * Closed form (elastic-perfectly-plastic in the slip direction, exact for the backward-Euler
 * return map in 1-D and along a fixed direction): with tau_crit = min(mu p, tau_max) and
 * k_s = tau_crit/gamma_crit, the plastic slip is
 *   loading:   gamma_p = max(gamma - gamma_crit, 0)                (reaches 19 gamma_crit)
 *   unloading: gamma_p = min(19 gamma_crit, gamma + gamma_crit)    (reaches -19 gamma_crit)
 * tau = k_s (gamma - gamma_p), the path length of plastic slip is 19 + 38 = 57 gamma_crit and
 * the dissipated work sum(SFD) = tau_crit * 57 gamma_crit.
 *
 * Also: exact stick (PROPS(7) = 1) with a spring host, rough friction (PROPS(7) = 2), and
 * LM = 2 on entry.
 */
#include <math.h>
#include <stdio.h>

#include "harness.h"

#define MU 0.3
#define P 100.0
#define TAU_MAX 20.0
#define N_UP 146
#define N_DOWN 292
#define DTIME 0.5 /* STATEV(2) = |DSLIP|/DTIME: a DTIME other than 1 shows a missing division */

typedef struct {
    const char *name;
    double props[9];
    int nprops;
    double chrlngth;
    double gamma_crit; /* worked out by hand from PROPS(5), PROPS(6), CHRLNGTH */
    double tau_crit;   /* min(mu p, tau_max) */
    int nstatv;        /* > 3: the host keeps its own state after STATEV(3) */
} f1_case;

static const f1_case CASES[] = {
    /* CHRLNGTH = 1 would give a default gamma_crit of 5e-3: a mix-up of sources shows. */
    {"gamma_crit = PROPS(5)", {1, MU, 0, 0, 1e-3}, 5, 1.0, 1e-3, MU * P, 3},
    {"gamma_crit = PROPS(6) x CHRLNGTH", {1, MU, 0, 0, 0, 0.02}, 6, 0.1, 0.02 * 0.1, MU * P, 5},
    {"gamma_crit = 0.005 x CHRLNGTH", {1, MU}, 2, 0.2, 0.005 * 0.2, MU * P, 3},
    /* Trailing zeros past PROPS(7) are accepted. */
    {"tau_max cap, PROPS(5)", {1, MU, 0, TAU_MAX, 1e-3, 0, 0, 0, 0}, 9, 1.0, 1e-3, TAU_MAX, 3},
    {"tau_max cap, 0.005 x CHRLNGTH", {1, MU, 0, TAU_MAX}, 4, 0.2, 0.005 * 0.2, TAU_MAX, 4},
};

/* Imposed slip along the slip direction at the end of increment k (k = 0: start). */
static double path_gamma(int k, double gamma_crit)
{
    double top = 20.0 * gamma_crit;
    if (k <= N_UP) {
        return top * ((double)k / N_UP);
    }
    return top - 40.0 * gamma_crit * ((double)(k - N_UP) / N_DOWN);
}

/* The plastic part of a path g that rises to `peak` and then falls back, with an elastic band
 * of half-width b (the play operator started at 0): g - b once past b on the way up; on the
 * way down it stays at peak - b until g + b falls below it. */
static double play(double g, double b, double peak, int rising)
{
    double top = peak - b;
    if (rising) {
        return g > b ? g - b : 0.0;
    }
    return g + b < top ? g + b : top;
}

/* Closed-form plastic slip gamma_p after increment k (see the header comment). */
static double plastic_slip(int k, double gamma_crit)
{
    return play(path_gamma(k, gamma_crit), gamma_crit, path_gamma(N_UP, gamma_crit), k <= N_UP);
}

/* Closed-form path length of plastic slip after increment k (STATEV(1)). */
static double slip_path_length(int k, double gamma_crit)
{
    double top = plastic_slip(N_UP, gamma_crit);
    if (k <= N_UP) {
        return plastic_slip(k, gamma_crit);
    }
    return top + (top - plastic_slip(k, gamma_crit));
}

static void f1_elastic(const f1_case *c, int nfdir)
{
    const double gc = c->gamma_crit;
    const double tc = c->tau_crit;
    const double ks = tc / gc;
    const int capped = tc < MU * P;
    /* Fixed slip direction: 1-D, or 30 degrees in the tangent plane. */
    const double d[2] = {nfdir == 1 ? 1.0 : sqrt(3.0) / 2.0, nfdir == 1 ? 0.0 : 0.5};
    const double host_state[2] = {123.0, -4.5};
    double sum_sfd = 0.0;
    fh_fric h;
    int k, a, b;

    fh_init(&h, nfdir, c->props, c->nprops);
    h.chrlngth = c->chrlngth;
    h.nstatv = c->nstatv;
    h.dtime = DTIME;
    for (a = 3; a < c->nstatv; a++) {
        h.statev[a] = host_state[a - 3];
    }

    for (k = 1; k <= N_UP + N_DOWN; k++) {
        const double dg = path_gamma(k, gc) - path_gamma(k - 1, gc);
        const double gp = plastic_slip(k, gc);
        const double dgp = gp - plastic_slip(k - 1, gc); /* signed slip increment along d */
        const int slipping = dgp != 0.0;
        const double tau_exp = ks * (path_gamma(k, gc) - gp);
        const double sgn = dgp > 0.0 ? 1.0 : -1.0;
        fh_context("F1 %s, NFDIR=%d, increment %d", c->name, nfdir, k);

        /* First contact in increment 1 (p0 = 0), constant p afterwards. */
        h.press = P;
        h.dpress = k == 1 ? P : 0.0;
        h.kinc = k;
        h.time[0] = h.time[1] = k * DTIME;
        for (a = 0; a < nfdir; a++) {
            h.dgam[a] = dg * d[a];
        }
        h.lm = 0;
        fh_call_ok(&h);

        FH_CHECK(h.lm == 0);
        /* tau = k_s (gamma - gamma_p) along d; in 1-D slip exactly +-tau_crit. */
        for (a = 0; a < nfdir; a++) {
            if (slipping && nfdir == 1) {
                FH_EXACT(h.tau[a], sgn * tc);
            } else {
                FH_NEAR(h.tau[a], tau_exp * d[a], 0.0, 1e-11 * tc);
            }
        }
        if (slipping) {
            double mag = 0.0;
            for (a = 0; a < nfdir; a++) {
                mag += h.tau[a] * h.tau[a];
            }
            FH_NEAR(sqrt(mag), tc, 1e-14, 0.0); /* plateau min(mu p, tau_max) */
        }
        /* DDTDDG: k_s I in stick; (I - n n^T) tau_crit/|gamma_pr| in slip, exactly 0 in 1-D,
         * with |gamma_pr| = gamma_crit + |slip increment| and n = +-d. */
        for (a = 1; a <= nfdir; a++) {
            for (b = 1; b <= nfdir; b++) {
                double delta = a == b ? 1.0 : 0.0;
                if (!slipping) {
                    FH_NEAR(fh_ddtddg(&h, a, b), ks * delta, 1e-14, 0.0);
                } else if (nfdir == 1) {
                    FH_EXACT(fh_ddtddg(&h, a, b), 0.0);
                } else {
                    double want = (delta - d[a - 1] * d[b - 1]) * tc / (gc + fabs(dgp));
                    FH_NEAR(fh_ddtddg(&h, a, b), want, 0.0, 1e-10 * ks);
                }
            }
        }
        /* DDTDDP = d tau/d p: gamma_pr mu/gamma_crit in stick, mu n in slip, 0 on the cap. */
        for (a = 0; a < nfdir; a++) {
            double want = capped ? 0.0 : (slipping ? MU * sgn * d[a] : tau_exp / ks * MU / gc * d[a]);
            FH_NEAR(h.ddtddp[a], want, 0.0, 1e-12);
            FH_NEAR(h.dslip[a], dgp * d[a], 0.0, 1e-12 * gc);
        }
        for (a = 0; a < 2 * nfdir; a++) {
            FH_EXACT(h.ddtddt[a], 0.0);
        }
        /* SED = tau^2/(2 k_s); SFD = tau_crit |dgamma_p| >= 0. */
        FH_NEAR(h.sed, tau_exp * tau_exp / (2.0 * ks), 0.0, 1e-11 * tc * gc);
        FH_CHECK(h.sfd >= 0.0);
        FH_NEAR(h.sfd, tc * fabs(dgp), 0.0, 1e-11 * tc * gc);
        sum_sfd += h.sfd;
        /* STATEV(1) path length of plastic slip, (2) slip rate, (3) 0 stick / 1 slip. */
        FH_NEAR(h.statev[0], slip_path_length(k, gc), 0.0, 1e-11 * gc);
        FH_NEAR(h.statev[1], fabs(dgp) / DTIME, 0.0, 1e-11 * gc);
        FH_EXACT(h.statev[2], slipping ? 1.0 : 0.0);
        for (a = 3; a < c->nstatv; a++) {
            FH_EXACT(h.statev[a], host_state[a - 3]);
        }
    }
    fh_context("F1 %s, NFDIR=%d, end of path", c->name, nfdir);
    /* Plastic work along 0 -> 20 -> -20 gamma_crit: tau_crit (19 + 38) gamma_crit. */
    FH_NEAR(sum_sfd, tc * 57.0 * gc, 1e-11, 0.0);
    FH_NEAR(h.statev[0], 57.0 * gc, 1e-11, 0.0);
}

/*
 * Exact stick (PROPS(7) = 1), NFDIR = 1, with a spring host: a spring of stiffness K (per unit
 * contact area) pulls the slider; its driver end moves u(t): 0 -> 10 mu p/K -> -10 mu p/K.
 * While the point is stuck (LM = 1) the host holds gamma and passes TAULM = K (u - gamma);
 * when fric_ answers LM = 0 the host solves K (u - gamma) = tau for gamma by Newton with the
 * returned DDTDDG (= 0 in 1-D slip, so one step is exact) and calls again to confirm.
 * Closed form, with u_rel = mu p / K:
 *   loading:   gamma = max(0, u - u_rel)     (stuck until K u reaches mu p)
 *   unloading: gamma = min(9 u_rel, u + u_rel) (stuck until the spring force reaches -mu p)
 * Slip path 9 + 18 = 27 u_rel, dissipation sum(SFD) = mu p * 27 u_rel.
 */
#define SPRING_K 1e4
#define SPRING_UP 73
#define SPRING_DOWN 146

static double spring_u(int k, double u_rel)
{
    if (k <= SPRING_UP) {
        return 10.0 * u_rel * ((double)k / SPRING_UP);
    }
    return 10.0 * u_rel - 20.0 * u_rel * ((double)(k - SPRING_UP) / SPRING_DOWN);
}

static double spring_gamma(int k, double u_rel)
{
    return play(spring_u(k, u_rel), u_rel, spring_u(SPRING_UP, u_rel), k <= SPRING_UP);
}

static void f1_exact_stick_spring(void)
{
    static const double props[] = {1, MU, 0, 0, 1e-3, 0, 1};
    const double tc = MU * P;
    const double u_rel = tc / SPRING_K;
    const double untouched = 4.25; /* marks outputs that LM = 1 must not write */
    double gamma = 0.0, tau_conv = 0.0, sum_sfd = 0.0;
    double statev_conv[3] = {0.0, 0.0, 0.0};
    int lm_conv = 1; /* first contact: held by the multipliers */
    fh_fric h;
    int k, it, i;

    fh_init(&h, 1, props, 7);
    h.press = P;
    for (k = 1; k <= SPRING_UP + SPRING_DOWN; k++) {
        const double u = spring_u(k, u_rel);
        const double gamma_exp = spring_gamma(k, u_rel);
        const int stuck_exp = gamma_exp == spring_gamma(k - 1, u_rel);
        const double gamma_old = gamma;
        double gamma_trial = gamma_old;
        int lm = lm_conv;
        int converged = 0;
        fh_context("F1 exact stick spring host, increment %d", k);
        h.kinc = k;

        for (it = 0; it < 8 && !converged; it++) {
            /* Every iteration starts from the converged state of increment k-1. */
            for (i = 0; i < 3; i++) {
                h.statev[i] = statev_conv[i];
            }
            h.tau[0] = tau_conv;
            h.ddtddg[0] = untouched;
            h.ddtddp[0] = untouched;
            h.lm = lm;
            if (lm == 1) {
                h.dgam[0] = 0.0;
                h.taulm[0] = SPRING_K * (u - gamma_old);
                fh_call_ok(&h);
                if (h.lm == 1) {
                    gamma_trial = gamma_old;
                    converged = 1;
                } else {
                    /* Released: tau = tau_crit along TAULM; solve K (u - gamma) = tau. */
                    FH_CHECK(h.lm == 0);
                    FH_EXACT(h.tau[0], h.taulm[0] > 0.0 ? tc : -tc);
                    lm = 0;
                    gamma_trial = u - h.tau[0] / SPRING_K;
                }
            } else {
                double next;
                h.dgam[0] = gamma_trial - gamma_old;
                fh_call_ok(&h);
                if (h.lm == 1) {
                    /* Motion reversed against the stress of the start: stuck again. */
                    lm = 1;
                    gamma_trial = gamma_old;
                    continue;
                }
                FH_CHECK(h.lm == 0);
                FH_EXACT(h.ddtddg[0], 0.0);
                /* Newton on R(gamma) = K (u - gamma) - tau(gamma), dR/dgamma = -(K + DDTDDG). */
                next = gamma_trial + (SPRING_K * (u - gamma_trial) - h.tau[0]) /
                                         (SPRING_K + h.ddtddg[0]);
                converged = fabs(next - gamma_trial) <= 1e-12 * u_rel;
                gamma_trial = next;
            }
        }
        FH_CHECK(converged);
        gamma = gamma_trial;

        FH_CHECK(h.lm == (stuck_exp ? 1 : 0));
        FH_NEAR(gamma, gamma_exp, 0.0, 1e-12 * u_rel);
        if (h.lm == 1) {
            /* No relative motion at all; TAU, DDTDDG, DDTDDP not written. */
            FH_EXACT(gamma, gamma_old);
            FH_EXACT(h.tau[0], tau_conv);
            FH_EXACT(h.ddtddg[0], untouched);
            FH_EXACT(h.ddtddp[0], untouched);
            FH_EXACT(h.dslip[0], 0.0);
            FH_EXACT(h.sed, 0.0);
            FH_EXACT(h.sfd, 0.0);
            FH_EXACT(h.statev[2], 2.0);
            /* The multiplier stress stays inside the cone. */
            FH_CHECK(fabs(SPRING_K * (u - gamma)) <= tc);
            tau_conv = SPRING_K * (u - gamma);
        } else {
            /* Sliding: tau = +-mu p along the motion, all motion is slip. */
            const double dgam = gamma_exp - spring_gamma(k - 1, u_rel);
            FH_EXACT(h.tau[0], dgam > 0.0 ? tc : -tc);
            FH_NEAR(h.dslip[0], dgam, 0.0, 1e-12 * u_rel);
            FH_EXACT(h.sed, 0.0);
            FH_NEAR(h.sfd, tc * fabs(dgam), 0.0, 1e-12 * tc * u_rel);
            FH_EXACT(h.ddtddp[0], dgam > 0.0 ? MU : -MU);
            FH_EXACT(h.statev[2], 1.0);
            tau_conv = h.tau[0];
        }
        FH_CHECK(h.sfd >= 0.0);
        sum_sfd += h.sfd;
        lm_conv = h.lm;
        for (i = 0; i < 3; i++) {
            statev_conv[i] = h.statev[i];
        }
        /* The accumulated slip is the closed-form slip path so far. */
        {
            double top = spring_gamma(SPRING_UP, u_rel);
            double path = k <= SPRING_UP ? gamma_exp : top + (top - gamma_exp);
            FH_NEAR(statev_conv[0], path, 0.0, 1e-11 * u_rel);
        }
    }
    fh_context("F1 exact stick spring host, end of path");
    FH_NEAR(sum_sfd, tc * 27.0 * u_rel, 1e-11, 0.0);
    FH_NEAR(statev_conv[0], 27.0 * u_rel, 1e-11, 0.0);
    FH_NEAR(gamma, -9.0 * u_rel, 0.0, 1e-12 * u_rel);
}

/* Rough friction (PROPS(7) = 2): LM = 1 on every call, whatever the motion and the stress. */
static void f1_rough(int nfdir)
{
    static const double props[] = {1, MU, 0, 0, 1e-3, 0, 2};
    const double untouched = 4.25;
    fh_fric h;
    int k, a;
    fh_init(&h, nfdir, props, 7);
    h.press = P;
    h.statev[0] = 0.75; /* slip accumulated before: kept */
    for (k = 1; k <= 12; k++) {
        fh_context("F1 rough, NFDIR=%d, call %d", nfdir, k);
        h.lm = k % 2; /* the host may pass either flag */
        for (a = 0; a < nfdir; a++) {
            h.dgam[a] = (k - 6) * 0.05 * (a + 1); /* from -0.25 to 0.3: far beyond any cone */
            h.tau[a] = 1000.0 * (a - 0.5) * k;
            h.taulm[a] = -500.0 * k;
            h.ddtddg[a] = untouched;
            h.ddtddp[a] = untouched;
            h.dslip[a] = untouched;
        }
        {
            double tau_before[2] = {h.tau[0], h.tau[1]};
            fh_call_ok(&h);
            FH_CHECK(h.lm == 1);
            for (a = 0; a < nfdir; a++) {
                FH_EXACT(h.tau[a], tau_before[a]);
                FH_EXACT(h.ddtddg[a], untouched);
                FH_EXACT(h.ddtddp[a], untouched);
                FH_EXACT(h.dslip[a], 0.0);
            }
        }
        FH_EXACT(h.sed, 0.0);
        FH_EXACT(h.sfd, 0.0);
        FH_EXACT(h.statev[0], 0.75);
        FH_EXACT(h.statev[1], 0.0);
        FH_EXACT(h.statev[2], 2.0);
    }
}

/* LM = 2 on entry (frictionless): fric_ returns at once and writes nothing. */
static void f1_lm2(int nfdir, const double *props, int nprops, const char *mode)
{
    const double mark = 4.25;
    fh_fric h, before;
    int i;
    fh_init(&h, nfdir, props, nprops);
    fh_context("F1 LM = 2 on entry, %s, NFDIR=%d", mode, nfdir);
    h.lm = 2;
    h.press = P;
    h.dpress = 10.0;
    for (i = 0; i < nfdir; i++) {
        h.tau[i] = mark + i;
        h.ddtddp[i] = mark;
        h.dslip[i] = mark;
        h.dgam[i] = 1e-2;
        h.taulm[i] = 1e3;
    }
    for (i = 0; i < nfdir * nfdir; i++) {
        h.ddtddg[i] = mark;
    }
    for (i = 0; i < 2 * nfdir; i++) {
        h.ddtddt[i] = mark;
    }
    h.sed = mark;
    h.sfd = mark;
    h.statev[0] = 0.5;
    h.statev[1] = 0.25;
    h.statev[2] = 1.0;
    h.pnewdt = FH_PNEWDT_IN;
    before = h;
    fh_call_ok(&h);
    FH_CHECK(h.lm == 2);
    FH_CHECK(memcmp(h.tau, before.tau, sizeof h.tau) == 0);
    FH_CHECK(memcmp(h.ddtddg, before.ddtddg, sizeof h.ddtddg) == 0);
    FH_CHECK(memcmp(h.ddtddp, before.ddtddp, sizeof h.ddtddp) == 0);
    FH_CHECK(memcmp(h.dslip, before.dslip, sizeof h.dslip) == 0);
    FH_CHECK(memcmp(h.ddtddt, before.ddtddt, sizeof h.ddtddt) == 0);
    FH_CHECK(memcmp(h.statev, before.statev, sizeof h.statev) == 0);
    FH_EXACT(h.sed, mark);
    FH_EXACT(h.sfd, mark);
}

int main(void)
{
    static const double elastic[] = {1, MU, 0, 0, 1e-3};
    static const double exact[] = {1, MU, 0, 0, 1e-3, 0, 1};
    static const double rough[] = {1, MU, 0, 0, 1e-3, 0, 2};
    size_t c;
    int nfdir;
    for (c = 0; c < sizeof CASES / sizeof CASES[0]; c++) {
        for (nfdir = 1; nfdir <= 2; nfdir++) {
            f1_elastic(&CASES[c], nfdir);
        }
    }
    f1_exact_stick_spring();
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        f1_rough(nfdir);
        f1_lm2(nfdir, elastic, 5, "elastic stick");
        f1_lm2(nfdir, exact, 7, "exact stick");
        f1_lm2(nfdir, rough, 7, "rough");
    }
    return fh_finish();
}
