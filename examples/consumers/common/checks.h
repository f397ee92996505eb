/*
 * What every C consumer checks, from the installed header only: closed forms through fric_ and
 * ifl_gap_conductance_n, the error text of a failure, the version. Prints "N passed, M failed"
 * last and returns the failure count.
 *
 * Friction (PROPS(1) = 1, mu = 0.3, gamma_crit = 1e-3 from PROPS(5)), NFDIR = 1, p = 100 held
 * (DPRESS = 0), TAU = 0 at the start: k_s = mu p / gamma_crit = 3e4, so a slip increment of
 * 5e-4 sticks with tau = k_s * 5e-4 = 15, and 5e-3 slides with tau = mu p = 30.
 * Conductance: interaction SI1 is law "constant", k = 2 (the INTERFACIAL_CONFIG file that
 * scripts/test-consumers.sh writes).
 */
#include <stdio.h>
#include <string.h>

#include "interfacial.h"

static int n_pass, n_fail;

static void check(int ok, const char *what)
{
    if (ok) {
        n_pass++;
    } else {
        n_fail++;
        printf("FAIL %s\n", what);
    }
}

static int close_to(double a, double b) { return a - b < 1e-12 * (1 + b) && b - a < 1e-12 * (1 + b); }

static double one_fric_increment(double dgam)
{
    int lm = 0, kstep = 1, kinc = 1, noel = 0, npt = 1, node = 1, npatch = 1;
    int nfdir = 1, mcrd = 2, npred = 0, nstatv = 3, nprops = 5;
    double tau = 0, ddtddg = 0, ddtddp = 0, dslip = 0, sed = 0, sfd = 0, ddtddt[2] = {0, 0};
    double pnewdt = 1e36, statev[3] = {0, 0, 0}, taulm = 0, press = 100, dpress = 0;
    double ddpddh = 0, slip = 0, time[2] = {0, 0}, dtime = 1, coords[2] = {0, 0};
    double rcoord[2] = {0, 0}, drot[4] = {1, 0, 0, 1}, temp[2] = {20, 20}, predef[2] = {0, 0};
    double chrlngth = 1, props[5] = {1, 0.3, 0, 0, 1e-3};
    char name[80];
    memset(name, ' ', sizeof name);
    memcpy(name, "SI1", 3);
    fric_(&lm, &tau, &ddtddg, &ddtddp, &dslip, &sed, &sfd, ddtddt, &pnewdt, statev, &dgam, &taulm,
          &press, &dpress, &ddpddh, &slip, &kstep, &kinc, time, &dtime, &noel, name, name, name,
          &npt, &node, &npatch, coords, rcoord, drot, temp, predef, &nfdir, &mcrd, &npred,
          &nstatv, &chrlngth, props, &nprops, 80, 80, 80);
    check(pnewdt == 1e36, "fric_ accepted the increment");
    return tau;
}

static int run_checks(const char *expected_version)
{
    IflConductance out;
    IflStatus st;
    check(strcmp(ifl_version(), expected_version) == 0, "ifl_version() is the package version");
    check(close_to(one_fric_increment(5e-4), 15.0), "stick: tau = k_s dgam = 15");
    check(close_to(one_fric_increment(5e-3), 30.0), "slip: tau = mu p = 30");
    /* A blank-padded name with its length, no NUL; the bytes after it are not read. */
    st = ifl_gap_conductance_n("si1     XX", 8, 0.0, 1.0, 300.0, 290.0, &out);
    check(st == IFL_STATUS_OK && out.k == 2.0, "ifl_gap_conductance_n: k = 2");
    st = ifl_gap_conductance_n("NOPE", 4, 0.0, 1.0, 300.0, 290.0, &out);
    check(st == IFL_STATUS_BAD_PARAMETER && out.k == 0.0, "an unknown interaction is refused");
    check(strstr(ifl_last_error(), "ifl_gap_conductance_n") != NULL &&
              strstr(ifl_last_error(), "'NOPE'") != NULL,
          "the message names the routine and the interaction");
    ifl_clear_error();
    check(ifl_last_error()[0] == '\0', "ifl_clear_error empties it");
    printf("%d passed, %d failed\n", n_pass, n_fail);
    return n_fail;
}
