/*
 * CalculiX's gapcon (docs/gapcon.md, "CalculiX"): 16 arguments, AREA after KINC, then the three
 * hidden name lengths. Linked against Interfacial::interfacial_calculix, which defines
 * INTERFACIAL_CALCULIX so that interfacial.h declares that signature.
 *
 * CalculiX may pass FLOWM, PREDEF, NPRED, SLNAME and MSNAME uninitialised, and the library
 * never reads them nor AREA: they are passed as NULL (a read would fault; no undefined
 * behaviour on the caller's side), and as pointers to garbage (NaN bytes, NPRED = -999999,
 * names of 0xFF bytes). AK(1) is checked against the closed forms of a constant law and a
 * pressure table (linear interpolation by hand, constant outside), also through a T1 two-bar
 * solve (q = (theta_H - theta_C)/(L_A/k_A + 1/h + L_B/k_B)); AK(2..5) are never written; a
 * NaN temperature gives AK(1) = 0 and a GAPCON message.
 *
 * The configuration is written at run time to argv[1] (default ./gapcon_calculix.toml).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gapcon_harness.h"

#if !defined(INTERFACIAL_CALCULIX)
#error "link against Interfacial::interfacial_calculix, which defines INTERFACIAL_CALCULIX"
#endif

#define K_CONST 3.5
static const double PTAB[] = {-1.0, 10.0, 0.0, 20.0, 50.0, 120.0, 150.0, 170.0};
#define PTAB_ROWS 4

/* T1 bars */
#define THETA_H 80.0
#define THETA_C 15.0
#define R_A (0.02 / 45.0)
#define R_B (0.03 / 15.0)

static void write_config(const char *path)
{
    gh_config_open(path, "test_gapcon_calculix.c");
    gh_config_constant("CCX_CONST", K_CONST);
    gh_config_tabulated("CCX_PTAB", "pressure-table", PTAB, PTAB_ROWS, 2);
    gh_config_close(path);
}

/* Calls gapcon_ with every argument the library must not read set to NULL (AREA too). */
static double call_with_nulls(const char *name, double d, double p, double ta, double tb)
{
    double ak[GH_AK];
    double dd[2], temp[2];
    char ciname[80];
    int noel = 5, node = 9, i;
    memset(ciname, ' ', sizeof ciname);
    memcpy(ciname, name, strlen(name));
    for (i = 0; i < GH_AK; i++) {
        ak[i] = GH_GUARD;
    }
    ak[0] = GH_AK_MARK;
    dd[0] = d;
    dd[1] = p;
    temp[0] = ta;
    temp[1] = tb;
    /* ak, d, flowm, temp, predef, time, ciname, slname, msname, coords, noel, node, npred,
     * kstep, kinc, area, hidden lengths */
    gapcon_(ak, dd, NULL, temp, NULL, NULL, ciname, NULL, NULL, NULL, &noel, &node, NULL, NULL,
            NULL, NULL, 80, 80, 80);
    FH_CHECK(ak[1] == GH_GUARD && ak[2] == GH_GUARD && ak[3] == GH_GUARD && ak[4] == GH_GUARD &&
             ak[5] == GH_GUARD);
    return ak[0];
}

/* The same point with the unread arguments pointing to garbage. */
static double call_with_garbage(const char *name, double d, double p, double ta, double tb)
{
    gh_gapcon g;
    gh_init(&g, name, d, p, ta, tb);
    memset(g.flowm, 0xFF, sizeof g.flowm);   /* NaN */
    memset(g.predef, 0xFF, sizeof g.predef);
    memset(&g.area, 0xFF, sizeof g.area);
    g.npred = -999999;
    memset(g.slname, 0xFF, sizeof g.slname);
    memset(g.msname, 0xFF, sizeof g.msname);
    g.slname_len = 80;
    g.msname_len = 80;
    return gh_call_ok(&g); /* checks AK(2..5) and that no input (AREA included) changed */
}

static void check_point(const char *name, double d, double p, double ta, double tb, double h)
{
    fh_context("%s at d = %g, p = %g, theta = (%g, %g): h = %g by hand", name, d, p, ta, tb, h);
    ifl_clear_error();
    FH_NEAR(call_with_nulls(name, d, p, ta, tb), h, 1e-15, 0.0);
    FH_CHECK(ifl_last_error()[0] == '\0');
    FH_NEAR(call_with_garbage(name, d, p, ta, tb), h, 1e-15, 0.0);
    {
        gh_gapcon g;
        gh_init(&g, name, d, p, ta, tb); /* AREA = 0.25, plausible values everywhere */
        FH_NEAR(gh_call_ok(&g), h, 1e-15, 0.0);
    }
    FH_NEAR(gh_native_ok(name, d, p, ta, tb).k, h, 1e-15, 0.0);
}

/* T1 through the CalculiX entry point: h does not depend on temperature, one Newton step. */
static void two_bars(const char *name, double p, double h)
{
    double ta = THETA_H, tb = THETA_C, q_want = (THETA_H - THETA_C) / (R_A + 1.0 / h + R_B);
    int it;
    fh_context("T1 through CalculiX's gapcon: %s at p = %g", name, p);
    for (it = 0; it < 3; it++) {
        double ak = call_with_nulls(name, 1e-4, p, ta, tb);
        double q = ak * (ta - tb);
        double ra = (THETA_H - ta) / R_A - q, rb = q - (tb - THETA_C) / R_B;
        double j11 = -1.0 / R_A - ak, j12 = ak, j21 = ak, j22 = -ak - 1.0 / R_B;
        double det = j11 * j22 - j12 * j21;
        ta += (-ra * j22 + rb * j12) / det;
        tb += (-rb * j11 + ra * j21) / det;
    }
    FH_NEAR(call_with_nulls(name, 1e-4, p, ta, tb) * (ta - tb), q_want, 1e-12, 0.0);
    FH_NEAR((THETA_H - ta) / R_A, q_want, 1e-11, 0.0);
}

int main(int argc, char **argv)
{
    static const double pcases[][2] = {
        {-0.5, 10.0 + (20.0 - 10.0) * 0.5},
        {25.0, 20.0 + (120.0 - 20.0) * 25.0 / 50.0},
        {50.0, 120.0},
        {100.0, 120.0 + (170.0 - 120.0) * 50.0 / 100.0},
        {-3.0, 10.0},  /* below the first row */
        {400.0, 170.0} /* above the last */
    };
    size_t i;
    write_config(argc > 1 ? argv[1] : "gapcon_calculix.toml");

    check_point("CCX_CONST", 1e-4, 10.0, 60.0, 20.0, K_CONST);
    check_point("CCX_CONST", -2e-5, -4.0, 20.0, 60.0, K_CONST);
    two_bars("CCX_CONST", 10.0, K_CONST);
    for (i = 0; i < sizeof pcases / sizeof pcases[0]; i++) {
        FH_NEAR(gh_lerp_table(PTAB, PTAB_ROWS, 2, pcases[i][0]), pcases[i][1], 1e-15, 0.0);
        check_point("CCX_PTAB", 3e-4, pcases[i][0], 60.0, 20.0, pcases[i][1]);
        two_bars("CCX_PTAB", pcases[i][0], pcases[i][1]);
    }

    fh_context("CalculiX: NaN TEMP(2)");
    {
        gh_gapcon g;
        gh_init(&g, "CCX_CONST", 1e-4, 10.0, 60.0, NAN);
        ifl_clear_error();
        FH_EXACT(gh_call(&g), 0.0);
        FH_CONTAINS(ifl_last_error(), "GAPCON");
        FH_CONTAINS(ifl_last_error(), "interaction 'CCX_CONST'");
        FH_CONTAINS(ifl_last_error(), "TEMP(2) is NaN or infinite");
        FH_EXACT(call_with_nulls("CCX_CONST", 1e-4, 10.0, 60.0, 20.0), K_CONST);
    }
    return fh_finish();
}
