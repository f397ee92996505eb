/*
 * Scene F4, velocity steps (docs/scene-definitions.md), driven through fric_ for the exponential
 * decay law mu(v) = mu_k + (mu_s - mu_k) exp(-d_c v) (PROPS(8) = 1, PROPS(9) = mu_k,
 * PROPS(10) = d_c): slip at piecewise-constant rates v = 0.05, 0.5, 0.2, 1.5 (DGAM = v DTIME d
 * per increment), NFDIR = 1 and 2, elastic and exact stick, mu at the end-of-increment rate
 * and frozen at the start of the increment (PROPS(20) = 1).
 *
 * Closed form once steady: |tau| = mu(v) p and STATEV(2) = v; fric_coef_ returns the same
 * mu(v) (and d mu/d v = -d_c (mu_s - mu_k) exp(-d_c v)). The slip tangent along the slip
 * direction is checked against a central difference of fric_'s own TAU.
 *
 * Also scene F5 with a pressure-dependent mu = mu0/(1 + p/p_ref) (PROPS(11) = p_ref) and a shear
 * limit tau_max: while sliding tau = min(mu(p) p, tau_max) and DDTDDP = mu0/(1 + p/p_ref)^2
 * below the cap, 0 on it;
 * a damping case (seed 003, PROPS(17) = c0, NSTATV = 3 + NFDIR): tau = mu p + c0 v in
 * steady sliding, tau = (k_s + c0/DTIME) DGAM in a first stick increment; and a bad DTIME with
 * a rate law (refused, PNEWDT < 1, state unchanged).
 */
#include <math.h>
#include <stdio.h>

#include "harness.h"
#include "props_index.h"

#define MU_S 0.6
#define MU_K 0.3
#define DECAY 4.0
#define P 50.0
#define GAMMA_CRIT 1e-3
#define DT 0.01

static double mu_of(double v) { return MU_K + (MU_S - MU_K) * exp(-DECAY * v); }

/* Law 1 with mu and gamma_crit, every other entry 0. */
static void props_coulomb(double *props, double mu)
{
    fh_props_coulomb(props, mu);
    props[IFLP_COULOMB_GAMMA_CRIT] = GAMMA_CRIT;
}

static void props_decay(double *props, int exact, int frozen)
{
    props_coulomb(props, MU_S);
    props[IFLP_COULOMB_STICK] = exact ? 1 : 0;
    props[IFLP_COULOMB_MU_LAW] = 1; /* exponential decay from mu_s to mu_k */
    props[IFLP_COULOMB_MU_K] = MU_K;
    props[IFLP_COULOMB_DECAY] = DECAY;
    props[IFLP_COULOMB_FROZEN] = frozen ? 1 : 0;
}

/* fric_coef_ for one point: mu and d mu/d rate in direction 1. */
static void coef(const double *props, double v, double p, double *mu, double *dmu)
{
    double fcoef[2], deriv[40], slip[6] = {0}, temp = 0.0, field = 0.0, rdata[8] = {0};
    int nblock = 1, nprops = 20, ntemp = 1, nfields = 0, idata[6] = {0};
    char name[80];
    memset(name, ' ', sizeof name);
    slip[0] = v;
    fric_coef_(fcoef, deriv, &nblock, &nprops, &ntemp, &nfields, idata, rdata, name, name, name,
               props, slip, &p, &temp, &field, 80, 80, 80);
    *mu = fcoef[0];
    *dmu = deriv[0];
}

/* At each steady rate of F4: fric_coef_'s mu(v) and d mu/d v against the closed forms, and
 * d tau/d DGAM along d against a central difference (not for frozen: same check). */
static void coef_and_tangent(const fh_fric *h, const double *d, double v)
{
    double mu, dmu;
    coef(h->props, v, P, &mu, &dmu);
    FH_NEAR(mu, mu_of(v), 1e-15, 0.0);
    FH_NEAR(dmu, -DECAY * (MU_S - MU_K) * exp(-DECAY * v), 1e-14, 0.0);
    fh_check_tangent_along(h, d, 1e-5 * MU_S * P / GAMMA_CRIT);
}

static void steps(int nfdir, int exact, int frozen)
{
    static const double rates[4] = {0.05, 0.5, 0.2, 1.5};
    double props[IFLP_COULOMB_NPROPS];
    props_decay(props, exact, frozen);
    fh_velocity_steps("F4", nfdir, props, P, DT, rates, 4, mu_of, 1e-12, coef_and_tangent);
}

static void damping(int nfdir)
{
    const double c0 = 2.0, v = 0.4;
    double props[IFLP_COULOMB_NPROPS];
    const double d[2] = {nfdir == 1 ? 1.0 : 0.6, nfdir == 1 ? 0.0 : 0.8};
    const double ks = MU_S * P / GAMMA_CRIT;
    double tau_eq = 0.0;
    fh_fric h;
    int k, a;
    props_coulomb(props, MU_S);
    props[IFLP_COULOMB_DAMPING] = c0;
    fh_init(&h, nfdir, props, IFLP_COULOMB_NPROPS);
    h.nstatv = 3 + nfdir;
    fh_set_guards(&h);
    h.press = P;
    h.dpress = P;
    h.dtime = DT;
    fh_context("damping NFDIR=%d, first stick increment", nfdir);
    h.dgam[0] = 1e-5;
    fh_call_ok(&h);
    FH_NEAR(h.tau[0], (ks + c0 / DT) * 1e-5, 1e-13, 0.0);
    FH_NEAR(fh_ddtddg(&h, 1, 1), ks + c0 / DT, 1e-13, 0.0);
    FH_NEAR(h.statev[3], c0 / DT * 1e-5, 1e-13, 0.0);
    h.dpress = 0.0;
    fh_context("damping NFDIR=%d, steady sliding at v=%g", nfdir, v);
    for (k = 0; k < 50; k++) {
        for (a = 0; a < nfdir; a++) {
            h.dgam[a] = v * DT * d[a];
        }
        fh_call_ok(&h);
    }
    for (a = 0; a < nfdir; a++) {
        tau_eq += h.tau[a] * h.tau[a];
    }
    FH_NEAR(sqrt(tau_eq), MU_S * P + c0 * v, 1e-12, 0.0);
    FH_NEAR(h.sfd, (MU_S * P + c0 * v) * v * DT, 1e-10, 0.0);
}

static void f5_pressure_mu(int nfdir)
{
    const double mu0 = 0.5, p_ref = 100.0, tau_max = 30.0;
    const double d[2] = {nfdir == 1 ? 1.0 : 0.8, nfdir == 1 ? 0.0 : -0.6};
    double props[IFLP_COULOMB_NPROPS], p_before = 0.0;
    fh_fric h;
    int k, a;
    props_coulomb(props, mu0);
    props[IFLP_COULOMB_TAU_MAX] = tau_max;
    props[IFLP_COULOMB_P_REF] = p_ref;
    fh_init(&h, nfdir, props, IFLP_COULOMB_P_REF + 1);
    for (k = 1; k <= 200; k++) {
        /* 2, 4, ..., 400, never exactly on the cap mu(p) p = 30 (p = 150). */
        const double p = 2.0 * k + 0.5;
        const double mu_p = mu0 * p / (1.0 + p / p_ref);
        fh_context("F5 pressure-dependent mu, NFDIR=%d, p=%g", nfdir, p);
        h.press = p;
        h.dpress = p - p_before;
        p_before = p;
        for (a = 0; a < nfdir; a++) {
            h.dgam[a] = 0.5 * GAMMA_CRIT * d[a];
        }
        fh_call_ok(&h);
        if (k > 5) {
            const double tc = fmin(mu_p, tau_max);
            const double slope = mu_p < tau_max ? mu0 / pow(1.0 + p / p_ref, 2) : 0.0;
            for (a = 0; a < nfdir; a++) {
                FH_NEAR(h.tau[a], tc * d[a], 1e-12, 1e-13);
                FH_NEAR(h.ddtddp[a], slope * d[a], 0.0, 1e-14);
            }
        }
    }
}

static void bad_dtime(void)
{
    double props[IFLP_COULOMB_NPROPS];
    fh_fric h, before;
    props_decay(props, 0, 0);
    fh_init(&h, 2, props, IFLP_COULOMB_NPROPS);
    fh_context("rate law with DTIME = 0");
    h.press = P;
    h.dtime = 0.0;
    h.statev[0] = 0.5;
    h.statev[1] = 0.25;
    h.statev[2] = 1.0;
    h.tau[0] = 3.0;
    h.dgam[0] = 1e-3;
    before = h;
    ifl_clear_error();
    fh_call(&h);
    FH_CHECK(h.pnewdt < 1.0);
    FH_CONTAINS(ifl_last_error(), "DTIME");
    FH_EXACT(h.tau[0], before.tau[0]);
    FH_EXACT(h.statev[0], 0.5);
    FH_EXACT(h.statev[1], 0.25);
    FH_EXACT(h.statev[2], 1.0);
}

int main(void)
{
    int nfdir;
    fh_each_nfdir_and_switches(steps);
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        damping(nfdir);
        f5_pressure_mu(nfdir);
    }
    bad_dtime();
    return fh_finish();
}
