/*
 * Heat flux through uinter_ (adhesive law, PROPS(11) = 1: the conductance of the interaction
 * from the INTERFACIAL_CONFIG file; PROPS(12..13): frictional heat), driven as a host drives it.
 *
 * Scene T1 with the interface as UINTER sees it: bar A (far end at THETA_H, resistance R_A)
 * against bar B (far end at THETA_C, resistance R_B), the interface closed at p = K_n h.
 * Unknowns: the surface temperatures TEMP(1) (slave, A side) and TEMP(2) (master, B side);
 * balances R_1 = (THETA_H - T1)/R_A + FLUX(1) = 0, R_2 = (THETA_C - T2)/R_B + FLUX(2) = 0,
 * Newton with the Jacobian -1/R - DDFDDT (DDFDDT = -dFLUX/dTEMP).
 *   (a) k(p) from a pressure table, no temperature dependence: the exact flux is
 *       q = (THETA_H - THETA_C)/(R_A + 1/k(p) + R_B), with k(p) interpolated here by hand;
 *       the problem is linear, so Newton with the right DDFDDT converges in one iteration.
 *   (b) k(p, theta_mean) from a table linear in theta_mean: Newton converges quadratically
 *       (residual below 1e-9 in at most 6 iterations), and the converged flux equals
 *       k(p, theta_mean*)(T1 - T2) with k worked out by hand at the converged mean.
 *   (c) frictional heat: sliding, eta = 0.8, f = 0.25: FLUX(1) + FLUX(2) = eta SFD/DTIME and
 *       the slave gets f of it.
 *   (d) an open gap with gas conduction: FLUX(1) = k_gas/(d + g0) (T2 - T1).
 * The configuration is written at run time to argv[1] and INTERFACIAL_CONFIG set before the
 * first call.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "uinter_harness.h"

#define THETA_H 400.0
#define THETA_C 20.0
#define R_A 2e-4
#define R_B 1e-3
#define KN 1e4
#define DT 0.5

static void ui_init(ui_point *u, const char *name, double eta)
{
    const double props[13] = {2.0, 0.4, 0.0, 0.0, 0.0, 0.0, 0.0, 1e-3, 0.0, KN, 1.0, eta, 0.25};
    ui_set(u, name, 2, props, 13, DT);
}

static void ui_call(ui_point *u)
{
    u->pnewdt = FH_PNEWDT_IN;
    ifl_clear_error();
    ui_call_raw(u);
    FH_CHECK(u->pnewdt == FH_PNEWDT_IN);
    FH_CHECK(ifl_last_error()[0] == '\0');
}

/* Newton on (T1, T2) at overclosure h; returns the iterations used, the flux from bar A. */
static int solve(const char *name, double h, double *q_out, double *t1, double *t2)
{
    ui_point u;
    int it;
    ui_init(&u, name, 0.0);
    u.rdisp[0] = h;
    u.temp[0] = THETA_H;
    u.temp[1] = THETA_C;
    for (it = 1; it <= 20; it++) {
        double r1, r2, j11, j12, j21, j22, det;
        ui_call(&u);
        r1 = (THETA_H - u.temp[0]) / R_A + u.flux[0];
        r2 = (THETA_C - u.temp[1]) / R_B + u.flux[1];
        /* DDFDDT(i,j) at [(i-1) + 2(j-1)] = -dFLUX(i)/dTEMP(j). */
        j11 = -1.0 / R_A - u.ddfddt[0];
        j12 = -u.ddfddt[2];
        j21 = -u.ddfddt[1];
        j22 = -1.0 / R_B - u.ddfddt[3];
        det = j11 * j22 - j12 * j21;
        u.temp[0] -= (r1 * j22 - r2 * j12) / det;
        u.temp[1] -= (j11 * r2 - j21 * r1) / det;
        ui_call(&u);
        r1 = (THETA_H - u.temp[0]) / R_A + u.flux[0];
        r2 = (THETA_C - u.temp[1]) / R_B + u.flux[1];
        if (fabs(r1) + fabs(r2) < 1e-9 * (THETA_H - THETA_C) / R_A) {
            break;
        }
    }
    *q_out = (THETA_H - u.temp[0]) / R_A;
    *t1 = u.temp[0];
    *t2 = u.temp[1];
    return it;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "uinter_heat.toml";
    FILE *f = fopen(path, "w");
    double q, t1, t2;
    int its;
    if (f == NULL) {
        printf("cannot write %s\n0 passed, 1 failed\n", path);
        return 1;
    }
    fprintf(f, "[interactions.PTAB.conductance]\nlaw = \"pressure-table\"\n"
               "table = [[0.0, 400.0], [20.0, 1000.0], [60.0, 1600.0]]\n"
               "[interactions.TTAB.conductance]\nlaw = \"pressure-table\"\n"
               "table = [[0.0, 400.0, 100.0], [60.0, 1600.0, 100.0],"
               " [0.0, 800.0, 300.0], [60.0, 2400.0, 300.0]]\n"
               "[interactions.GAS.conductance]\nlaw = \"gas-gap\"\nk_gas = 0.025\ng0 = 1e-4\n");
    fclose(f);
    setenv("INTERFACIAL_CONFIG", path, 1);

    /* (a) p = 40: k = 1000 + (1600 - 1000)(40 - 20)/40 = 1300. */
    fh_context("T1 through uinter_, k(p)");
    its = solve("PTAB", 40.0 / KN, &q, &t1, &t2);
    FH_NEAR(q, (THETA_H - THETA_C) / (R_A + 1.0 / 1300.0 + R_B), 1e-10, 0.0);
    FH_NEAR(q, 1300.0 * (t1 - t2), 1e-10, 0.0);
    FH_CHECK(its == 1);

    /* (b) p = 30, k(30, tm) = 1000 + 400 (tm - 100)/200 between tm = 100 and 300. */
    fh_context("T1 through uinter_, k(p, theta_mean)");
    its = solve("TTAB", 30.0 / KN, &q, &t1, &t2);
    {
        double tm = 0.5 * (t1 + t2);
        double k = tm <= 100.0 ? 1000.0 : (tm >= 300.0 ? 1600.0 : 1000.0 + 3.0 * (tm - 100.0));
        FH_CHECK(tm > 100.0 && tm < 300.0);
        FH_NEAR(q, k * (t1 - t2), 1e-9, 0.0);
        FH_NEAR(q, (THETA_H - THETA_C) / (R_A + 1.0 / k + R_B), 1e-9, 0.0);
        FH_CHECK(its <= 6);
        printf("T1 with k(p, theta_mean): %d Newton iterations, q = %.12g, k = %.12g\n", its, q,
               k);
    }

    /* (c) frictional heat while sliding at p = 50. */
    {
        ui_point u, v;
        fh_context("frictional heat");
        ui_init(&u, "PTAB", 0.8);
        u.rdisp[0] = 50.0 / KN;
        u.drdisp[1] = 0.05;
        u.temp[0] = 60.0;
        u.temp[1] = 40.0;
        v = u;
        v.props[11] = 0.0;
        ui_call(&u);
        ui_call(&v);
        FH_CHECK(u.sfd > 0.0 && u.statev[2] == 1.0);
        FH_NEAR(u.flux[0] + u.flux[1], 0.8 * u.sfd / DT, 1e-12, 0.0);
        FH_NEAR(u.flux[0] - v.flux[0], 0.25 * 0.8 * u.sfd / DT, 1e-12, 0.0);
        /* SFD = (mu p)(|dgam| - gamma_crit) for Coulomb from rest. */
        FH_NEAR(u.sfd, 0.4 * 50.0 * (0.05 - 1e-3), 1e-12, 0.0);
    }

    /* (d) open gap 4e-4 (free: no adhesion), gas conduction k = 0.025/(4e-4 + 1e-4) = 50. */
    {
        ui_point u;
        fh_context("open gap");
        ui_init(&u, "GAS", 0.0);
        u.statev[2] = 4.0;
        u.rdisp[0] = -4e-4;
        u.temp[0] = 100.0;
        u.temp[1] = 20.0;
        ui_call(&u);
        FH_EXACT(u.lopenclose, 0);
        FH_EXACT(u.stress[0], 0.0);
        FH_NEAR(u.flux[0], 50.0 * (20.0 - 100.0), 1e-12, 0.0);
        FH_NEAR(u.flux[1], -u.flux[0], 1e-15, 0.0);
        /* dFLUX(1)/dh = -(dk/dh)(T1 - T2), dk/dh = k_gas/(d + g0)^2 = 1e5. */
        FH_NEAR(u.ddfddr[0], -1e5 * 80.0, 1e-10, 0.0);
    }
    return fh_finish();
}
