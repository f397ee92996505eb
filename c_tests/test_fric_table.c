/*
 * mu from a table in the configuration file (PROPS(8) = 2, docs/config.md "Friction tables"),
 * driven through fric_ and fric_coef_ as a host calls them. CTest points INTERFACIAL_CONFIG at
 * c_tests/configs/fric_table.toml (mode "good") or fric_table_bad_unsorted.toml (mode "bad").
 *
 * good: scene F4 velocity steps with the table of SI_PAD: once steady |tau| = mu_tab(v) p and
 * STATEV(2) = v, for NFDIR 1 and 2, elastic and exact stick, implicit and frozen mu, at rates
 * inside the table, on its kink region and beyond its last row; the slip tangent along the
 * slip direction against a central difference of TAU; fric_coef_ of BRAKE (mu(rate, p)) against
 * the hand interpolation with its derivatives; an interaction without a table refused (PNEWDT
 * < 1, message names the interaction and the missing [interactions.NAME.friction], state
 * unchanged).
 * bad: every call refused, the message names the file, line 7, the key and the cause.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "props_index.h"

#define P 50.0
#define GAMMA_CRIT 1e-3
#define DT 0.01

/* SI_PAD's table, by hand. */
static double mu_tab(double v)
{
    if (v <= 0.3) {
        return 0.6 - 0.5 * v;
    }
    if (v <= 1.0) {
        return 0.45 - (0.15 / 0.7) * (v - 0.3);
    }
    return 0.3;
}

static void props_table(double *props, int exact, int frozen)
{
    fh_props_coulomb(props, 1.0); /* μ: reference of the anisotropy ratio only */
    props[IFLP_COULOMB_GAMMA_CRIT] = GAMMA_CRIT;
    props[IFLP_COULOMB_STICK] = exact ? 1 : 0;
    props[IFLP_COULOMB_MU_LAW] = 2; /* the table of the configuration file */
    props[IFLP_COULOMB_FROZEN] = frozen ? 1 : 0;
}

/* At each steady rate, elastic stick only: d tau/d DGAM along d against a central difference. */
static void tangent_unless_exact(const fh_fric *h, const double *d, double v)
{
    (void)v;
    if (h->props[IFLP_COULOMB_STICK] == 0.0) {
        fh_check_tangent_along(h, d, 1e-5 * 0.6 * P / GAMMA_CRIT);
    }
}

static void steps(int nfdir, int exact, int frozen)
{
    static const double rates[5] = {0.05, 0.5, 0.2, 1.5, 0.8};
    double props[IFLP_COULOMB_NPROPS];
    props_table(props, exact, frozen);
    fh_velocity_steps("F4 table", nfdir, props, P, DT, rates, 5, mu_tab, 1e-11,
                      tangent_unless_exact);
}

/* BRAKE at (rate, p) = (0.25, 30): 0.5 - 0.025 = 0.475 at p = 0, 0.375 at p = 100, so
 * mu = 0.475 - 0.3 * 0.1 = 0.445; d mu/d rate = -0.1; d mu/d p = -0.001. */
static void coef_brake(void)
{
    double props[20], fcoef[2], deriv[40], slip[6] = {0}, temp = 20.0, field = 0.0,
                                          rdata[8] = {0}, p = 30.0;
    int nblock = 1, nprops = 20, ntemp = 1, nfields = 0, idata[6] = {0};
    char name[80];
    memset(name, ' ', sizeof name);
    memcpy(name, "brake", 5); /* names match ignoring case */
    props_table(props, 0, 0);
    props[2] = 0.5; /* mu2/mu1 = 0.5 */
    slip[0] = 0.25;
    fh_context("fric_coef_ with the table of BRAKE");
    ifl_clear_error();
    fric_coef_(fcoef, deriv, &nblock, &nprops, &ntemp, &nfields, idata, rdata, name, name, name,
               props, slip, &p, &temp, &field, 80, 80, 80);
    FH_CHECK(ifl_last_error()[0] == '\0');
    FH_NEAR(fcoef[0], 0.445, 1e-14, 0.0);
    FH_NEAR(fcoef[1], 0.5 * 0.445, 1e-14, 0.0);
    FH_NEAR(deriv[0], -0.1, 1e-13, 0.0);
    FH_NEAR(deriv[1], -0.001, 1e-12, 0.0);
    FH_EXACT(deriv[2], 0.0);
    FH_NEAR(deriv[20], -0.05, 1e-13, 0.0);
}

/* A call that must be refused: PNEWDT < 1, the needles in the message, state unchanged. */
static void refused(fh_fric *h, const char *n1, const char *n2)
{
    h->statev[0] = 0.5;
    h->statev[1] = 0.1;
    h->statev[2] = 1.0;
    h->tau[0] = 3.0;
    h->press = 100.0;
    h->dgam[0] = 1e-2;
    h->dtime = DT;
    fh_check_refused(h, n1, n2);
}

int main(int argc, char **argv)
{
    double props[IFLP_COULOMB_NPROPS];
    fh_fric h;
    const char *mode = argc > 1 ? argv[1] : "good";
    const char *config = getenv("INTERFACIAL_CONFIG");
    if (strcmp(mode, "bad") == 0) {
        char where[1200];
        snprintf(where, sizeof where, "%s:7: interactions.SI_PAD.friction.table",
                 config ? config : "?");
        props_table(props, 0, 0);
        fh_init(&h, 2, props, IFLP_COULOMB_NPROPS);
        fh_context("bad table");
        refused(&h, where, "slip rates must be strictly increasing");
        return fh_finish();
    }
    fh_each_nfdir_and_switches(steps);
    coef_brake();
    props_table(props, 0, 0);
    fh_init(&h, 2, props, IFLP_COULOMB_NPROPS);
    fh_set_name(h.ciname, &h.ciname_len, 80, "NO_TABLE");
    fh_context("interaction without a table");
    refused(&h, "'NO_TABLE'", "[interactions.NO_TABLE.friction]");
    return fh_finish();
}
