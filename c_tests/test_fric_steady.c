/*
 * Viscous stick for steady-state transport (PROPS(7) = 3, docs/props.md), driven through fric_
 * increment by increment as a host calls it. A disc spins at omega about the z axis; the
 * contact point sits at COORDS = (0.3, 0.4, 2), R = 0.5. The allowable viscous slip rate is
 * gamma_dot_crit = 2 F_f omega R (seed 000, PROPS(16) = 0) or F_f omega R (seed 003,
 * PROPS(16) = 1). With the relative velocity v = |DGAM|/DTIME held constant along d:
 *
 *   stick (v <= gamma_dot_crit): TAU = kappa_s v d, kappa_s = mu p / gamma_dot_crit,
 *     DDTDDG = kappa_s/DTIME I, DDTDDP = (mu v/gamma_dot_crit) d, DSLIP = 0, SED = SFD = 0,
 *     STATEV(3) = 0, STATEV(1) unchanged;
 *   slip (v > gamma_dot_crit): TAU = mu(v - gamma_dot_crit) p d, STATEV(2) = v - gamma_dot_crit,
 *     DSLIP = (v - gamma_dot_crit) DTIME d, SFD = |TAU| |DSLIP|, STATEV(1) grows by |DSLIP|
 *     each increment, DDTDDG = (mu p/(v DTIME)) (I - d d) + d d mu'(v - gamma_dot_crit) p/DTIME,
 *     DDTDDP = mu d;
 *
 * for NFDIR 1 and 2, both variants, constant mu and the exponential decay law
 * mu = mu_k + (mu_s - mu_k) exp(-d_c rate). No memory: the answer does not depend on TAU on
 * entry. Bad input: PROPS(16) = 2 or 0.5, omega = 0, a point on the axis; each refused with
 * PNEWDT < 1, a message naming the cause, TAU and STATEV unchanged.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "props_index.h"

#define MU 0.4
#define MU_K 0.2
#define DC 3.0
#define P 50.0
#define FF 0.01
#define OMEGA 20.0
#define RADIUS 0.5
#define DT 0.1

static void props_steady(double *props, int variant, int decay)
{
    fh_props_coulomb(props, MU);
    props[IFLP_COULOMB_SLIP_TOLERANCE] = FF;
    props[IFLP_COULOMB_STICK] = 3; /* viscous stick, steady-state transport */
    if (decay) {
        props[IFLP_COULOMB_MU_LAW] = 1; /* exponential decay */
        props[IFLP_COULOMB_MU_K] = MU_K;
        props[IFLP_COULOMB_DECAY] = DC;
    }
    props[IFLP_COULOMB_OMEGA] = OMEGA;
    props[IFLP_COULOMB_AXIS] = 3; /* z axis */
    props[IFLP_COULOMB_VISCOUS_REFERENCE] = variant;
}

static double mu_of(int decay, double rate)
{
    return decay ? MU_K + (MU - MU_K) * exp(-DC * rate) : MU;
}

static double dmu_of(int decay, double rate)
{
    return decay ? -DC * (MU - MU_K) * exp(-DC * rate) : 0.0;
}

static void point(fh_fric *h, int nfdir, int variant, int decay)
{
    double props[IFLP_COULOMB_NPROPS];
    props_steady(props, variant, decay);
    fh_init(h, nfdir, props, IFLP_COULOMB_NPROPS);
    h->coords[0] = 0.3;
    h->coords[1] = 0.4;
    h->coords[2] = 2.0;
    h->press = P;
    h->dpress = 0.0;
    h->dtime = DT;
}

static void scene(int nfdir, int variant, int decay)
{
    const double d[2] = {nfdir == 1 ? 1.0 : 0.6, nfdir == 1 ? 0.0 : -0.8};
    const double rate_crit = (variant ? 1.0 : 2.0) * FF * OMEGA * RADIUS;
    const double kappa = MU * P / rate_crit;
    /* Two speeds in stick (one just below the limit), then two in slip, then stick again. */
    const double speeds[5] = {0.4 * rate_crit, 0.999 * rate_crit, 1.5 * rate_crit,
                              4.0 * rate_crit, 0.7 * rate_crit};
    fh_fric h;
    int s, k, a, b;
    double path = 0.0;
    point(&h, nfdir, variant, decay);
    for (s = 0; s < 5; s++) {
        const double v = speeds[s];
        const int sticks = v <= rate_crit;
        fh_context("steady transport NFDIR=%d PROPS(16)=%d decay=%d v=%g (gamma_dot_crit %g)",
                   nfdir, variant, decay, v, rate_crit);
        for (k = 0; k < 3; k++) {
            /* TAU on entry is never read: give a different one each increment. */
            for (a = 0; a < nfdir; a++) {
                h.tau[a] = 17.0 * (k + 1) * (a ? -1.0 : 1.0);
                h.dgam[a] = v * DT * d[a];
            }
            fh_call_ok(&h);
            FH_CHECK(h.lm == 0);
            if (sticks) {
                for (a = 0; a < nfdir; a++) {
                    FH_NEAR(h.tau[a], kappa * v * d[a], 1e-13, 1e-13 * MU * P);
                    FH_EXACT(h.dslip[a], 0.0);
                    FH_NEAR(h.ddtddp[a], MU * v / rate_crit * d[a], 1e-13, 1e-15);
                    for (b = 0; b < nfdir; b++) {
                        FH_NEAR(fh_ddtddg(&h, a + 1, b + 1), a == b ? kappa / DT : 0.0, 1e-13,
                                1e-13 * kappa / DT);
                    }
                }
                FH_EXACT(h.sfd, 0.0);
                FH_EXACT(h.statev[2], 0.0);
                FH_EXACT(h.statev[1], 0.0);
            } else {
                const double rate = v - rate_crit;
                const double t = mu_of(decay, rate) * P;
                for (a = 0; a < nfdir; a++) {
                    FH_NEAR(h.tau[a], t * d[a], 1e-13, 1e-13 * MU * P);
                    FH_NEAR(h.dslip[a], rate * DT * d[a], 1e-13, 1e-16);
                    FH_NEAR(h.ddtddp[a], mu_of(decay, rate) * d[a], 1e-13, 1e-15);
                    for (b = 0; b < nfdir; b++) {
                        const double delta = a == b ? 1.0 : 0.0;
                        const double proj = nfdir == 1 ? 0.0 : delta - d[a] * d[b];
                        const double want =
                            (t / v * proj + d[a] * d[b] * dmu_of(decay, rate) * P) / DT;
                        FH_NEAR(fh_ddtddg(&h, a + 1, b + 1), want, 1e-12, 1e-12 * kappa / DT);
                    }
                }
                path += rate * DT;
                FH_NEAR(h.sfd, t * rate * DT, 1e-13, 0.0);
                FH_EXACT(h.statev[2], 1.0);
                FH_NEAR(h.statev[1], rate, 1e-13, 0.0);
            }
            FH_EXACT(h.sed, 0.0);
            FH_NEAR(h.statev[0], path, 1e-13, 0.0);
        }
    }
}

/* A call that must be refused: PNEWDT < 1, the needle in the message, TAU and STATEV unchanged. */
static void refused(fh_fric *h, const char *needle)
{
    h->statev[0] = 0.5;
    h->statev[1] = 0.1;
    h->statev[2] = 1.0;
    h->tau[0] = 3.0;
    h->tau[1] = -2.0;
    h->dgam[0] = 1e-3;
    fh_check_refused(h, needle, NULL);
}

static void bad_input(void)
{
    fh_fric h;
    fh_context("steady transport: PROPS(16) = 2");
    point(&h, 2, 2, 0);
    refused(&h, "PROPS(16) = 2 must select");
    fh_context("steady transport: PROPS(16) = 0.5");
    point(&h, 2, 0, 0);
    h.props[IFLP_COULOMB_VISCOUS_REFERENCE] = 0.5;
    refused(&h, "PROPS(16) = 0.5 must select");
    fh_context("steady transport: omega = 0");
    point(&h, 2, 1, 0);
    h.props[IFLP_COULOMB_OMEGA] = 0.0;
    refused(&h, "PROPS(14)");
    fh_context("steady transport: a point on the axis, seed 003");
    point(&h, 2, 1, 0);
    h.coords[0] = 0.0;
    h.coords[1] = 0.0;
    refused(&h, "F_f·ω·R must be > 0");
}

int main(void)
{
    fh_each_nfdir_and_switches(scene);
    bad_input();
    return fh_finish();
}
