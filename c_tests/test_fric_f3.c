/*
 * Scene F3, the friction ellipse (docs/scene-definitions.md; seed 000, anisotropic friction),
 * NFDIR = 2, driven through fric_: mu1 = 0.5 (PROPS(2)), mu2 = 0.2 (PROPS(3)), p = 100,
 * gamma_crit = 1e-3, steady imposed slip DGAM = 0.3 gamma_crit d per increment along d at
 * twelve angles.
 *
 * Closed form once sliding: the stress is on the ellipse (tau1/mu1)^2 + (tau2/mu2)^2 = p^2 and
 * parallel to (mu1^2 d1, mu2^2 d2) (associated slip law in the scaled variables of
 * Eq. 5.2.3-10/11). In stick: k_i = (mu_i/mubar)^2 kbar_s with mubar = sqrt((mu1^2 + mu2^2)/2)
 * and kbar_s = mubar p/gamma_crit. In slip the tangent DDTDDG is checked against central
 * differences of fric_'s own TAU.
 */
#include <math.h>
#include <stdio.h>

#include "harness.h"

#define MU1 0.5
#define MU2 0.2
#define P 100.0
#define GAMMA_CRIT 1e-3
#define FD_DG 1e-9

static const double PROPS[5] = {1, MU1, MU2, 0, GAMMA_CRIT};

static void ellipse(int k)
{
    const double angle = k * FH_PI / 6.0 + 0.1;
    const double d[2] = {cos(angle), sin(angle)};
    const double w[2] = {MU1 * MU1 * d[0], MU2 * MU2 * d[1]};
    fh_fric h;
    int inc, a, b;
    fh_init(&h, 2, PROPS, 5);
    h.press = P;
    h.dpress = P;
    fh_context("F3 ellipse, angle %.3f", angle);
    for (inc = 0; inc < 60; inc++) {
        h.dgam[0] = 0.3 * GAMMA_CRIT * d[0];
        h.dgam[1] = 0.3 * GAMMA_CRIT * d[1];
        fh_call_ok(&h);
        FH_CHECK(h.lm == 0);
        h.dpress = 0.0;
    }
    FH_NEAR(sqrt(pow(h.tau[0] / MU1, 2) + pow(h.tau[1] / MU2, 2)), P, 1e-13, 0.0);
    /* Parallel to (mu1^2 d1, mu2^2 d2), same sense. */
    FH_NEAR(h.tau[0] * w[1] - h.tau[1] * w[0], 0.0, 0.0, 1e-11 * P * MU1 * MU1);
    FH_CHECK(h.tau[0] * w[0] + h.tau[1] * w[1] > 0.0);
    FH_EXACT(h.statev[2], 1.0);
    FH_CHECK(h.sfd > 0.0);
    /* The slip tangent against central differences from the same start. */
    {
        fh_fric start = h;
        const double kbar = sqrt(0.5 * (MU1 * MU1 + MU2 * MU2)) * P / GAMMA_CRIT;
        fh_call_ok(&start); /* start = one more steady increment, from h's start */
        for (b = 0; b < 2; b++) {
            fh_fric plus = h, minus = h;
            plus.dgam[b] += FD_DG;
            minus.dgam[b] -= FD_DG;
            fh_call_ok(&plus);
            fh_call_ok(&minus);
            for (a = 0; a < 2; a++) {
                FH_NEAR(fh_ddtddg(&start, a + 1, b + 1),
                        (plus.tau[a] - minus.tau[a]) / (2.0 * FD_DG), 0.0, 1e-6 * kbar);
            }
        }
    }
}

static void stick_stiffnesses(void)
{
    const double mbar2 = 0.5 * (MU1 * MU1 + MU2 * MU2);
    const double kbar = sqrt(mbar2) * P / GAMMA_CRIT;
    fh_fric h;
    fh_init(&h, 2, PROPS, 5);
    fh_context("F3 stick stiffnesses");
    h.press = P;
    h.dpress = P;
    h.dgam[0] = 1e-5;
    h.dgam[1] = -2e-5;
    fh_call_ok(&h);
    FH_NEAR(fh_ddtddg(&h, 1, 1), MU1 * MU1 / mbar2 * kbar, 1e-13, 0.0);
    FH_NEAR(fh_ddtddg(&h, 2, 2), MU2 * MU2 / mbar2 * kbar, 1e-13, 0.0);
    FH_EXACT(fh_ddtddg(&h, 1, 2), 0.0);
    FH_EXACT(fh_ddtddg(&h, 2, 1), 0.0);
    FH_NEAR(h.tau[0], MU1 * MU1 / mbar2 * kbar * 1e-5, 1e-13, 0.0);
    FH_NEAR(h.tau[1], -MU2 * MU2 / mbar2 * kbar * 2e-5, 1e-13, 0.0);
    /* SED = sum tau_i^2/(2 k_i). */
    FH_NEAR(h.sed,
            h.tau[0] * h.tau[0] / (2.0 * MU1 * MU1 / mbar2 * kbar) +
                h.tau[1] * h.tau[1] / (2.0 * MU2 * MU2 / mbar2 * kbar),
            1e-13, 0.0);
}

int main(void)
{
    int k;
    for (k = 0; k < 12; k++) {
        ellipse(k);
    }
    stick_stiffnesses();
    return fh_finish();
}
