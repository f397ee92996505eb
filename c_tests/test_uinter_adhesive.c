/*
 * The adhesive friction law (seed 004, PROPS(1) = 2) driven step by step as a quasi-static host
 * drives it, through fric_ (tangential part) and uinter_ (the whole interface):
 *
 *   F4  velocity steps: slip at rates v = 0.01, 0.1 (= v_half), 1, 0.3 with k_mu and v_half
 *       both non-zero; once steady, tau = ((mu_s v_half + mu_d v)/(v_half + v) + k_mu v) p + S_a
 *       (the seed's formula, evaluated here), through fric_ (NFDIR = 1, 2) and uinter_ (NDIR 2).
 *   Onset: a ramp of slip at constant p sticks with tau = k_s gamma up to mu_s p + S_a and slides
 *       once the stick stress would exceed it (v_half = 0: the stress drops to the dynamic
 *       strength mu_d p + S_a + k_mu v p at once).
 *   A1  pull-off: bonded, shear S0 held, pulled apart in small steps: the bond holds (stress
 *       -N, LOPENCLOSE = 1) until N = N_a sqrt(1 - (S0/S_a)^2), then breaks (zero stress,
 *       LOPENCLOSE = 0); re-contact bonds again with the full strengths. Energy balance: the
 *       work done on the interface (from STRESS and RDISP only) equals SED + sum SPD after
 *       every increment; SPD = 1/2 S0^2/k_s + 1/2 N_last^2/K_n at the break (the energy held at
 *       the last bonded increment), 1/2 (0.99 N_a)^2/K_n at the second break, 0 otherwise.
 *   gamma_crit = 2 exactly: read as gamma_crit, as 2.0000001 is (law 1's mu-table switch value).
 *   Bad input: negative strengths, coeffStatic < coeff, NaN -> PNEWDT = 0.25, outputs kept,
 *       one message naming the routine and the entry.
 *
 * Parameters: mu_d = 0.3, mu_s = 0.5, S_a = 4, N_a = 10, k_mu = 0.2, v_half = 0.1,
 * gamma_crit = 1e-3, K_n = 1e4, p = 100, DTIME = 0.1. Mirrored by
 * fortran_tests/test_uinter_adhesive.f90.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "uinter_harness.h"

/* UINTER as abi.md documents it, redeclared by hand: a mismatch with interfacial.h is a
 * compile error. */
void uinter_(double *stress, double *ddsddr, double *dviscous, double *dstructural,
             double *flux, double *ddfddt, double *ddsddt, double *ddfddr, double *statev,
             double *sed, double *sfd, double *spd, double *svd, double *scd, double *pnewdt,
             const double *rdisp, const double *drdisp, const double *temp, const double *dtemp,
             const double *predef, const double *dpred, const double *time, const double *dtime,
             const double *freqr, const char *ciname, const char *slname, const char *msname,
             const double *props, const double *coords, const double *alocaldir,
             const double *drot, const double *area, const double *chrlngth, const int *node,
             const int *ndir, const int *nstatv, const int *npred, const int *nprops,
             const int *mcrd, const int *kstep, const int *kinc, const int *kit,
             const int *linper, int *lopenclose, int *lstate, int *lsdi, const int *lprint,
             size_t ciname_len, size_t slname_len, size_t msname_len);

#define MU_D 0.3
#define MU_S 0.5
#define SA 4.0
#define NA 10.0
#define KMU 0.2
#define VHALF 0.1
#define GAMMA_CRIT 1e-3
#define KN 1e4
#define P 100.0
#define DT 0.1

/* The seed's sliding strength. */
static double g(double v, double p, double mu_s, double vhalf, double kmu)
{
    return ((mu_s * vhalf + MU_D * v) / (vhalf + v) + kmu * v) * p + SA;
}

static void ui_init(ui_point *u, int ndir, const double *props, int nprops)
{
    int i;
    ui_set(u, "ADHESIVE", ndir, props, nprops, DT);
    u->node = 7;
    u->temp[0] = u->temp[1] = 20.0;
    for (i = 3; i < 6; i++) {
        u->statev[i] = FH_GUARD;
    }
}

static void ui_call(ui_point *u)
{
    int i, n = u->ndir;
    for (i = n; i < 4; i++) {
        u->stress[i] = FH_GUARD;
    }
    for (i = n * n; i < 10; i++) {
        u->ddsddr[i] = FH_GUARD;
    }
    u->pnewdt = FH_PNEWDT_IN;
    ui_call_raw(u);
    for (i = n; i < 4; i++) {
        FH_CHECK(u->stress[i] == FH_GUARD);
    }
    for (i = n * n; i < 10; i++) {
        FH_CHECK(u->ddsddr[i] == FH_GUARD);
    }
    for (i = 3; i < 6; i++) {
        FH_CHECK(u->statev[i] == FH_GUARD);
    }
}

static const double rates[4] = {0.01, 0.1, 1.0, 0.3};

/* F4 through fric_, NFDIR = 1 or 2 (slip along 30 degrees in 3-D). */
static void f4_fric(int nfdir)
{
    const double props[8] = {2.0, MU_D, MU_S, SA, NA, KMU, VHALF, GAMMA_CRIT};
    const double d[2] = {nfdir == 1 ? 1.0 : cos(FH_PI / 6), nfdir == 1 ? 0.0 : sin(FH_PI / 6)};
    fh_fric h;
    int r, k, a;
    fh_init(&h, nfdir, props, 8);
    h.press = P;
    h.dpress = P; /* first contact in the first increment */
    h.dtime = DT;
    for (r = 0; r < 4; r++) {
        double v = rates[r], want = g(v, P, MU_S, VHALF, KMU);
        for (k = 0; k < 40; k++) {
            for (a = 0; a < nfdir; a++) {
                h.dgam[a] = v * DT * d[a];
            }
            fh_context("F4 fric_ NFDIR=%d v=%g increment %d", nfdir, v, k + 1);
            fh_call_ok(&h);
            h.dpress = 0.0;
        }
        fh_context("F4 fric_ NFDIR=%d v=%g steady", nfdir, v);
        FH_NEAR(sqrt(h.tau[0] * h.tau[0] + (nfdir == 2 ? h.tau[1] * h.tau[1] : 0.0)), want,
                1e-12, 0.0);
        for (a = 0; a < nfdir; a++) {
            FH_NEAR(h.tau[a], want * d[a], 1e-12, 1e-12);
        }
        FH_NEAR(h.statev[1], v, 1e-10, 0.0); /* slip rate */
        FH_EXACT(h.statev[2], 1.0);          /* slipping */
        FH_EXACT(h.lm, 0);
    }
}

/* F4 through uinter_, NDIR = 2: the normal stress is K_n h = P. */
static void f4_uinter(void)
{
    const double props[10] = {2.0, MU_D, MU_S, SA, NA, KMU, VHALF, GAMMA_CRIT, 0.0, KN};
    ui_point u;
    int r, k;
    ui_init(&u, 2, props, 10);
    u.rdisp[0] = P / KN;
    for (r = 0; r < 4; r++) {
        double v = rates[r], want = g(v, P, MU_S, VHALF, KMU);
        for (k = 0; k < 40; k++) {
            u.drdisp[1] = v * DT;
            u.rdisp[1] += v * DT;
            fh_context("F4 uinter_ v=%g increment %d", v, k + 1);
            ui_call(&u);
            FH_CHECK(u.pnewdt == FH_PNEWDT_IN);
        }
        fh_context("F4 uinter_ v=%g steady", v);
        FH_NEAR(u.stress[0], P, 1e-12, 0.0);
        FH_NEAR(u.stress[1], want, 1e-12, 0.0);
        FH_EXACT(u.lopenclose, 1);
        FH_EXACT(u.lstate, 1);
        FH_NEAR(u.ddsddr[0], KN, 1e-15, 0.0);
        /* SFD = tau * v * dt once steady. */
        FH_NEAR(u.sfd, want * v * DT, 1e-10, 0.0);
    }
}

/* Onset: slip ramped by 1e-2 gamma_crit per increment at constant p (v_half = 0). */
static void onset(void)
{
    const double props[8] = {2.0, MU_D, MU_S, SA, NA, KMU, 0.0, GAMMA_CRIT};
    const double step = 1e-2 * GAMMA_CRIT, k_s = (MU_S * P + SA) / GAMMA_CRIT;
    double last_stick = 0.0;
    fh_fric h;
    int k, slipped = 0;
    fh_init(&h, 1, props, 8);
    h.press = P;
    h.dpress = P;
    h.dtime = DT;
    for (k = 1; k <= 200 && !slipped; k++) {
        h.dgam[0] = step;
        fh_context("onset increment %d", k);
        fh_call_ok(&h);
        h.dpress = 0.0;
        if (h.statev[2] == 0.0) {
            FH_NEAR(h.tau[0], k_s * step * k, 1e-9, 0.0); /* tau = k_s gamma in stick */
            FH_CHECK(h.tau[0] <= MU_S * P + SA);
            last_stick = h.tau[0];
        } else {
            double v = h.statev[1];
            slipped = 1;
            /* The trial stress of this increment exceeded mu_s p + S_a, the last stick did not. */
            FH_CHECK(last_stick + k_s * step > MU_S * P + SA);
            FH_CHECK(last_stick <= MU_S * P + SA);
            /* Instantaneous drop to the dynamic strength at the end-of-increment rate. */
            FH_NEAR(h.tau[0], (MU_D + KMU * v) * P + SA, 1e-12, 0.0);
            /* The elastic slip stays gamma_crit (docs/props.md, rate-following stiffness): the
             * slip is the trial elastic slip less gamma_crit, k_s dslip = trial - (mu_s p + S_a). */
            FH_NEAR((MU_S * P + SA) + k_s * h.dslip[0], last_stick + k_s * step, 1e-12, 0.0);
        }
    }
    fh_context("onset");
    FH_CHECK(slipped);
    /* The seed's onset stress is reached to within one increment of stick stress. */
    FH_NEAR(last_stick, MU_S * P + SA, 0.0, k_s * step);
}

/* Energy bookkeeping of the A1 scene, from what a host sees: STRESS and RDISP. */
typedef struct {
    double work, spd_sum;
} a1_energy;

/* One A1 increment (NDIR = 3) to the overclosure h with the tangential motion dg along
 * direction 2. The work of the increment is the trapezoid 1/2 (sigma_start + sigma_end) du per
 * component while the point carries stress at the end (exact for the law's linear springs:
 * K_n, and k_s = S_a/gamma_crit at p = 0), and sigma_end du = 0 for an increment that ends
 * open (backward Euler: the break point inside the increment is unknown). Checks
 * W = SED + sum SPD and SPD >= 0; returns SPD. */
static double a1_step(ui_point *u, double h, double dg, a1_energy *e)
{
    const double s_start[3] = {u->stress[0], u->stress[1], u->stress[2]};
    const double du[3] = {h - u->rdisp[0], 0.0, dg};
    int i;
    u->rdisp[0] = h;
    u->drdisp[2] = dg;
    u->spd = -1.0;
    ui_call(u);
    FH_CHECK(u->pnewdt == FH_PNEWDT_IN);
    if (u->lopenclose == 1) {
        for (i = 0; i < 3; i++) {
            e->work += 0.5 * (s_start[i] + u->stress[i]) * du[i];
        }
    }
    FH_CHECK(u->spd >= 0.0 && isfinite(u->spd));
    e->spd_sum += u->spd;
    FH_NEAR(e->work, u->sed + e->spd_sum, 1e-12, 0.0);
    return u->spd;
}

/* A1: pull-off at N_a sqrt(1 - (S0/S_a)^2), reversible, with its energy balance. */
static void pull_off(void)
{
    const double props[10] = {2.0, MU_D, MU_S, SA, NA, 0.0, 0.0, GAMMA_CRIT, 0.0, KN};
    const double s0 = 3.0, k_s = SA / GAMMA_CRIT;
    double n_break, last_n = 0.0, spd;
    a1_energy e = {0.0, 0.0};
    ui_point u;
    int k, broke = 0;
    ui_init(&u, 3, props, 10);
    /* Bonded at zero pressure (touching) with shear S0 along direction 2: k_s = S_a/gamma_crit. */
    fh_context("A1 bond");
    spd = a1_step(&u, 0.0, s0 / k_s, &e);
    FH_NEAR(u.stress[2], s0, 1e-12, 0.0);
    FH_EXACT(u.stress[1], 0.0);
    FH_EXACT(u.lopenclose, 1);
    FH_EXACT(spd, 0.0);
    FH_NEAR(e.work, 0.5 * s0 * s0 / k_s, 1e-12, 0.0);
    n_break = NA * sqrt(1.0 - (s0 / SA) * (s0 / SA));
    for (k = 1; k <= 1000 && !broke; k++) {
        double n = 1e-2 * k;
        fh_context("A1 pull N = %g", n);
        spd = a1_step(&u, -n / KN, 0.0, &e);
        if (u.lopenclose == 1) {
            FH_EXACT(spd, 0.0);
            FH_CHECK(n < n_break);
            FH_NEAR(u.stress[0], -n, 1e-9, 0.0);
            FH_NEAR(u.stress[2], s0, 1e-12, 0.0);
            FH_EXACT(u.statev[2], 3.0);
            FH_EXACT(u.lstate, 3);
            last_n = n;
        } else {
            broke = 1;
            FH_CHECK(n >= n_break && last_n < n_break);
            FH_EXACT(u.stress[0], 0.0);
            FH_EXACT(u.stress[2], 0.0);
            FH_EXACT(u.ddsddr[0], 0.0);
            FH_EXACT(u.lstate, 4);
            FH_EXACT(u.sed, 0.0);
            /* The energy the bond held at the last bonded increment, from K_n, k_s and the
             * stresses the host imposed there. */
            FH_NEAR(spd, 0.5 * s0 * s0 / k_s + 0.5 * last_n * last_n / KN, 1e-12, 0.0);
        }
    }
    fh_context("A1 break");
    FH_CHECK(broke);
    FH_NEAR(last_n, n_break, 0.0, 1e-2);
    /* Closer again but still apart, then touching: free, no work, no SPD. */
    FH_EXACT(a1_step(&u, -1e-9, 0.0, &e), 0.0);
    FH_EXACT(u.lopenclose, 0);
    FH_EXACT(a1_step(&u, 0.0, 0.0, &e), 0.0);
    FH_EXACT(u.lopenclose, 0);
    /* Re-contact, then pull to 0.99 N_a (no shear now): bonded again. */
    fh_context("A1 re-contact");
    FH_EXACT(a1_step(&u, 1e-4, 0.0, &e), 0.0);
    FH_EXACT(u.lopenclose, 1);
    FH_NEAR(u.stress[0], 1.0, 1e-12, 0.0);
    FH_EXACT(a1_step(&u, -0.99 * NA / KN, 0.0, &e), 0.0);
    FH_EXACT(u.lopenclose, 1);
    FH_NEAR(u.stress[0], -0.99 * NA, 1e-12, 0.0);
    /* Broken again: the re-formed bond's energy is reported again. */
    fh_context("A1 second break");
    spd = a1_step(&u, -1.01 * NA / KN, 0.0, &e);
    FH_EXACT(u.lopenclose, 0);
    FH_NEAR(spd, 0.5 * (0.99 * NA) * (0.99 * NA) / KN, 1e-12, 0.0);
}

static void bad_input(void)
{
    static const struct {
        double props[10];
        const char *needle;
    } cases[] = {
        {{2.0, MU_D, MU_S, -1.0, NA, 0.0, 0.0, GAMMA_CRIT, 0.0, KN}, "PROPS(4): Sa"},
        {{2.0, MU_D, MU_S, SA, -1.0, 0.0, 0.0, GAMMA_CRIT, 0.0, KN}, "PROPS(5): Na"},
        {{2.0, MU_D, 0.2, SA, NA, 0.0, 0.0, GAMMA_CRIT, 0.0, KN}, "PROPS(3): coeffStatic"},
        {{2.0, MU_D, MU_S, SA, NA, NAN, 0.0, GAMMA_CRIT, 0.0, KN}, "PROPS(6): kmu"},
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ui_point u;
        fh_fric h;
        ui_init(&u, 2, cases[i].props, 10);
        u.stress[0] = 5.0;
        u.stress[1] = 1.0;
        u.rdisp[0] = 1e-3;
        fh_context("bad input %s (uinter_)", cases[i].needle);
        ui_call(&u);
        FH_EXACT(u.pnewdt, FH_CUTBACK);
        FH_EXACT(u.stress[0], 5.0);
        FH_EXACT(u.stress[1], 1.0);
        FH_EXACT(u.lopenclose, -1);
        FH_CONTAINS(ifl_last_error(), "UINTER");
        FH_CONTAINS(ifl_last_error(), cases[i].needle);
        fh_init(&h, 1, cases[i].props, 10);
        h.press = 10.0;
        h.tau[0] = 1.0;
        h.dgam[0] = 1e-3;
        fh_context("bad input %s (fric_)", cases[i].needle);
        fh_check_refused(&h, cases[i].needle, NULL); /* "FRIC", TAU and STATEV unchanged */
        FH_EXACT(h.pnewdt, FH_CUTBACK);
    }
    {
        const double props[10] = {2.0, MU_D, MU_S, SA, NA, 0.0, 0.0, GAMMA_CRIT, 0.0, KN};
        ui_point u;
        ui_init(&u, 2, props, 10);
        u.rdisp[0] = 1e-3;
        u.drdisp[1] = NAN;
        fh_context("bad input NaN DRDISP");
        ui_call(&u);
        FH_EXACT(u.pnewdt, FH_CUTBACK);
        FH_CONTAINS(ifl_last_error(), "DRDISP is NaN");
    }
}

/*
 * gamma_crit = 2 exactly (PROPS(8) = 2, law 1's mu-table switch in the other layout) is read as
 * gamma_crit: fric_ sticks with tau = k_s dgam, k_s = (mu_s p + S_a)/2, like gamma_crit = 2.0000001.
 */
static void gamma_crit_two(void)
{
    const double g[2] = {2.0, 2.0000001};
    double tau[2];
    int i, nfdir;
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        for (i = 0; i < 2; i++) {
            const double props[8] = {2.0, MU_D, MU_S, SA, NA, 0.0, 0.0, g[i]};
            fh_fric h;
            fh_init(&h, nfdir, props, 8);
            h.press = P;
            h.dpress = P;
            h.dtime = DT;
            h.dgam[0] = 0.5;
            fh_context("gamma_crit = %.7f, NFDIR %d", g[i], nfdir);
            fh_call_ok(&h);
            FH_NEAR(h.tau[0], (MU_S * P + SA) / g[i] * 0.5, 1e-12, 0.0);
            tau[i] = h.tau[0];
        }
        FH_NEAR(tau[0], tau[1], 1e-6, 0.0);
    }
}

int main(void)
{
    f4_fric(1);
    f4_fric(2);
    f4_uinter();
    onset();
    gamma_crit_two();
    pull_off();
    bad_input();
    return fh_finish();
}
