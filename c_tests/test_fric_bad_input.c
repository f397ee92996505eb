/*
 * Bad input through the FRIC ABI (docs/fric.md, "Bad input"), mirrored by
 * fortran_tests/test_fric_bad_input.f. Every case starts from a good call (NFDIR = 1 or 2,
 * mu = 0.3, gamma_crit = 1e-3 from PROPS(5), p = 100, TAU = (12, -5), DGAM = (1e-4, 2e-4),
 * STATEV = (0.5, 0.25, 1), interaction "SI_PAD", element 17, node 42, point 3), breaks one
 * thing, and checks the documented failure: no crash; PNEWDT = 0.25; LM, TAU and STATEV
 * unchanged; DDTDDG, DDTDDP, DSLIP, DDTDDT zeroed and SFD = 0 when NFDIR is 1 or 2 (no array
 * written otherwise); SED not written; guard slots and inputs untouched; ifl_last_error()
 * naming FRIC, the interaction, the point and the cause. Each case is called twice (a repeated
 * cause is logged once) and is followed by a good call, which must work again.
 *
 * The good call's answer is closed-form: DPRESS = 0, so k_s = mu p/gamma_crit = 3e4 at both
 * ends, gamma_el = TAU/k_s and the predictor stays inside gamma_crit: tau = TAU + k_s DGAM
 * = (15, 1).
 *
 * Also: ifl_clear_error, ifl_last_error_copy (truncation, length), ifl_version.
 * argv[1], when given, is the INTERFACIAL_LOG file CTest points the library to: it must hold
 * exactly one line per distinct message, in order of first appearance.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"

#define MU 0.3
#define P 100.0
#define GAMMA_CRIT 1e-3
#define MARK 4.25 /* in every output before a bad call: shows what was (not) written */

enum { MAX_MESSAGES = 128, MESSAGE_LEN = 512 };
static char seen[MAX_MESSAGES][MESSAGE_LEN]; /* distinct messages, in order of appearance */
static int n_seen;

static void remember_message(const char *msg)
{
    int i;
    for (i = 0; i < n_seen; i++) {
        if (strcmp(seen[i], msg) == 0) {
            return;
        }
    }
    if (FH_CHECK(n_seen < MAX_MESSAGES && strlen(msg) < MESSAGE_LEN)) {
        strcpy(seen[n_seen++], msg);
    }
}

static void good_point(fh_fric *h, int nfdir)
{
    static const double props[] = {1, MU, 0, 0, GAMMA_CRIT};
    fh_init(h, nfdir, props, 5);
    h->press = P;
    h->dpress = 0.0;
    h->tau[0] = 12.0;
    h->dgam[0] = 1e-4;
    if (nfdir == 2) {
        h->tau[1] = -5.0;
        h->dgam[1] = 2e-4;
    }
    h->statev[0] = 0.5;
    h->statev[1] = 0.25;
    h->statev[2] = 1.0;
    h->lm = 0;
}

/* The good call of the header comment; `msg_before` is the last error it must not disturb. */
static void expect_good(int nfdir, const char *msg_before)
{
    const double ks = MU * P / GAMMA_CRIT;
    fh_fric h;
    good_point(&h, nfdir);
    fh_call(&h);
    FH_CHECK(h.pnewdt == FH_PNEWDT_IN);
    FH_CHECK(h.lm == 0);
    FH_NEAR(h.tau[0], 12.0 + ks * 1e-4, 1e-14, 0.0);
    if (nfdir == 2) {
        FH_NEAR(h.tau[1], -5.0 + ks * 2e-4, 1e-13, 0.0);
    }
    FH_EXACT(h.statev[0], 0.5);
    FH_EXACT(h.statev[2], 0.0);
    /* A good call leaves the thread's last error alone (only ifl_clear_error empties it). */
    FH_CHECK(strcmp(ifl_last_error(), msg_before) == 0);
}

static int valid_nfdir(int n)
{
    return n == 1 || n == 2;
}

/*
 * Calls the broken point twice, PNEWDT = pnewdt_in on entry, and checks the documented failure
 * outputs each time; PNEWDT is only ever lowered, so it must end at the smaller of pnewdt_in and
 * the cut-back. `name` is how the interaction must appear in the message; `cause` and `cause2`
 * (may be NULL) are words the cause must contain.
 */
static void expect_refused_from(fh_fric *h, double pnewdt_in, const char *name, const char *cause,
                                const char *cause2)
{
    char quoted[128];
    char msg[MESSAGE_LEN];
    int call, i;
    const int n = h->nfdir;
    snprintf(quoted, sizeof quoted, "interaction '%s'", name);
    for (call = 1; call <= 2; call++) {
        fh_fric before;
        for (i = 0; i < FH_VEC; i++) {
            h->ddtddp[i] = MARK;
            h->dslip[i] = MARK;
        }
        for (i = 0; i < FH_MAT; i++) {
            h->ddtddg[i] = MARK;
        }
        for (i = 0; i < FH_DDT; i++) {
            h->ddtddt[i] = MARK;
        }
        h->sed = MARK;
        h->sfd = MARK;
        fh_set_guards(h);
        before = *h;
        ifl_clear_error();

        fh_call_from(h, pnewdt_in); /* guards and inputs checked in there */

        FH_EXACT(h->pnewdt, pnewdt_in < FH_CUTBACK ? pnewdt_in : FH_CUTBACK);
        FH_CHECK(h->pnewdt < 1.0);
        FH_CHECK(memcmp(&h->lm, &before.lm, sizeof h->lm) == 0);
        FH_CHECK(memcmp(h->tau, before.tau, sizeof h->tau) == 0);
        FH_CHECK(memcmp(h->statev, before.statev, sizeof h->statev) == 0);
        FH_EXACT(h->sed, MARK);
        if (valid_nfdir(n)) {
            for (i = 0; i < n * n; i++) {
                FH_EXACT(h->ddtddg[i], 0.0);
            }
            for (i = 0; i < n; i++) {
                FH_EXACT(h->ddtddp[i], 0.0);
                FH_EXACT(h->dslip[i], 0.0);
            }
            for (i = 0; i < 2 * n; i++) {
                FH_EXACT(h->ddtddt[i], 0.0);
            }
            FH_EXACT(h->sfd, 0.0);
        } else {
            FH_CHECK(memcmp(h->ddtddg, before.ddtddg, sizeof h->ddtddg) == 0);
            FH_CHECK(memcmp(h->ddtddp, before.ddtddp, sizeof h->ddtddp) == 0);
            FH_CHECK(memcmp(h->dslip, before.dslip, sizeof h->dslip) == 0);
            FH_CHECK(memcmp(h->ddtddt, before.ddtddt, sizeof h->ddtddt) == 0);
        }

        fh_check_last_message(msg, sizeof msg, "FRIC", quoted, "element 17, node 42, point 3");
        FH_CONTAINS(msg, cause);
        if (cause2 != NULL) {
            FH_CONTAINS(msg, cause2);
        }
        remember_message(msg);
    }
    expect_good(valid_nfdir(n) ? n : 2, msg);
}

/* expect_refused_from a host passing PNEWDT as Abaqus does, large. */
static void expect_refused(fh_fric *h, const char *name, const char *cause, const char *cause2)
{
    expect_refused_from(h, FH_PNEWDT_IN, name, cause, cause2);
}

/* ---- the catalogue -------------------------------------------------------------------- */

typedef struct {
    const char *label;
    void (*breaks)(fh_fric *);
    const char *cause;
    const char *cause2;
} bad_case;

static void nfdir_0(fh_fric *h) { h->nfdir = 0; }
static void nfdir_3(fh_fric *h) { h->nfdir = 3; }
static void nprops_0(fh_fric *h) { h->nprops = 0; }
static void nprops_1(fh_fric *h) { h->nprops = 1; }
static void law_code_4(fh_fric *h) { h->props[0] = 4.0; } /* no law 4 (3 is rate-and-state) */
static void law_code_1_5(fh_fric *h) { h->props[0] = 1.5; }
static void mu_negative(fh_fric *h) { h->props[1] = -MU; }
static void mu2_negative(fh_fric *h) { h->props[2] = -0.4; }
static void stick_mode_5(fh_fric *h)
{
    h->props[6] = 5.0;
    h->nprops = 7;
}
static void props8_nonzero(fh_fric *h)
{
    h->props[7] = 1e-3;
    h->nprops = 8;
}
static void nstatv_2(fh_fric *h) { h->nstatv = 2; }
/* gamma_crit from the default tolerance x CHRLNGTH, with no usable CHRLNGTH. */
static void chrlngth_zero(fh_fric *h)
{
    h->nprops = 2;
    h->chrlngth = 0.0;
}
static void chrlngth_negative(fh_fric *h)
{
    h->nprops = 2;
    h->chrlngth = -0.2;
}
static void lm_7(fh_fric *h) { h->lm = 7; }
static void dtime_nan(fh_fric *h) { h->dtime = NAN; }
static void statev_nan(fh_fric *h) { h->statev[0] = NAN; }
/* Exact stick held by the multipliers: TAULM is read, and must be finite. */
static void taulm_nan(fh_fric *h)
{
    h->props[6] = 1.0;
    h->nprops = 7;
    h->lm = 1;
    h->taulm[0] = NAN;
}

static const bad_case CATALOGUE[] = {
    {"NFDIR = 0", nfdir_0, "NFDIR = 0", NULL},
    {"NFDIR = 3", nfdir_3, "NFDIR = 3", NULL},
    {"NPROPS = 0", nprops_0, "NPROPS = 0", NULL},
    {"NPROPS = 1", nprops_1, "NPROPS = 1", NULL},
    {"PROPS(1) = 4", law_code_4, "PROPS(1) = 4", "not a known law code"},
    {"PROPS(1) = 1.5", law_code_1_5, "PROPS(1) = 1.5", "integer"},
    {"mu < 0", mu_negative, "PROPS(2)", NULL},
    {"mu2 < 0", mu2_negative, "PROPS(3)", NULL},
    {"PROPS(7) = 5", stick_mode_5, "PROPS(7)", NULL},
    {"PROPS(8) != 0", props8_nonzero, "PROPS(8)", NULL},
    {"NSTATV = 2", nstatv_2, "NSTATV = 2", NULL},
    {"CHRLNGTH = 0, PROPS(5) = 0", chrlngth_zero, "CHRLNGTH", NULL},
    {"CHRLNGTH < 0, PROPS(5) = 0", chrlngth_negative, "CHRLNGTH", NULL},
    {"LM = 7 on entry", lm_7, "LM = 7", NULL},
    {"DTIME = NaN", dtime_nan, "DTIME", NULL},
    {"STATEV(1) = NaN", statev_nan, "STATEV", NULL},
    {"TAULM = NaN with LM = 1", taulm_nan, "TAULM", NULL},
};

/*
 * The inputs that must be finite, each refused with NaN, +Inf and -Inf in turn; the cause names
 * the input (" PRESS" with its blank, so that "DPRESS" does not count) and says "NaN" for all
 * three values. An array input gets the value in its last component, so that a check of the
 * first one only would miss it.
 */
typedef struct {
    const char *name;
    const char *cause;
    double *(*slot)(fh_fric *);
} finite_input;

static double *press_slot(fh_fric *h) { return &h->press; }
static double *dpress_slot(fh_fric *h) { return &h->dpress; }
static double *dgam_slot(fh_fric *h) { return &h->dgam[h->nfdir - 1]; }
static double *tau_slot(fh_fric *h) { return &h->tau[h->nfdir - 1]; }

static const finite_input FINITE_INPUTS[] = {
    {"PRESS", " PRESS", press_slot},
    {"DPRESS", "DPRESS", dpress_slot},
    {"DGAM", "DGAM", dgam_slot},
    {"TAU", "TAU", tau_slot},
};

static const struct {
    const char *label;
    double value;
} NON_FINITE[] = {{"NaN", NAN}, {"+Inf", INFINITY}, {"-Inf", -INFINITY}};

static void non_finite_inputs(int nfdir)
{
    size_t c, v;
    for (c = 0; c < sizeof FINITE_INPUTS / sizeof FINITE_INPUTS[0]; c++) {
        for (v = 0; v < sizeof NON_FINITE / sizeof NON_FINITE[0]; v++) {
            fh_fric h;
            fh_context("%s = %s, NFDIR=%d", FINITE_INPUTS[c].name, NON_FINITE[v].label, nfdir);
            good_point(&h, nfdir);
            *FINITE_INPUTS[c].slot(&h) = NON_FINITE[v].value;
            expect_refused(&h, "SI_PAD", FINITE_INPUTS[c].cause, "NaN");
        }
    }
}

/*
 * mu < 0 from a host that had already asked for a smaller increment (PNEWDT = 0.1 on entry):
 * PNEWDT is only ever lowered, so it stays 0.1; every other failure output as always.
 */
static void lowered_pnewdt(int nfdir)
{
    fh_fric h;
    fh_context("mu < 0 with PNEWDT = 0.1 on entry, NFDIR=%d", nfdir);
    good_point(&h, nfdir);
    mu_negative(&h);
    expect_refused_from(&h, 0.1, "SI_PAD", "PROPS(2)", NULL);
}

/* Old host code: CHARACTER*8 CINAME. The bytes after the 8 are not part of the name. */
static void short_name(fh_fric *h)
{
    fh_set_name(h->ciname, &h->ciname_len, 8, "CONTACT8");
    memcpy(h->ciname + 8, "XYZ_NOT_PART_OF_IT", 18);
}

static void name_cases(void)
{
    fh_fric h;
    int nfdir;
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        fh_context("CHARACTER*8 name, bad NSTATV, NFDIR=%d", nfdir);
        good_point(&h, nfdir);
        short_name(&h);
        nstatv_2(&h);
        expect_refused(&h, "CONTACT8", "NSTATV = 2", NULL);
        FH_CHECK(strstr(ifl_last_error(), "XYZ") == NULL);

        fh_context("CHARACTER*8 name, good call, NFDIR=%d", nfdir);
        good_point(&h, nfdir);
        short_name(&h);
        fh_call_ok(&h);
        FH_CHECK(h.lm == 0);

        fh_context("all-blank name, LM = 7, NFDIR=%d", nfdir);
        good_point(&h, nfdir);
        fh_set_name(h.ciname, &h.ciname_len, 80, "");
        lm_7(&h);
        expect_refused(&h, "", "LM = 7", NULL);
    }
}

/* ---- the native API --------------------------------------------------------------------- */

static void native_api(void)
{
    char msg[MESSAGE_LEN], big[64], exact[MESSAGE_LEN], one[2];
    size_t full, got;
    int i, untouched;
    fh_fric h;
    const char *version = ifl_version();

    fh_context("ifl_version");
    FH_CHECK(version != NULL && version[0] >= '0' && version[0] <= '9');
    FH_CHECK(version != NULL && strchr(version, '.') != NULL);

    fh_context("ifl_clear_error");
    good_point(&h, 2);
    nstatv_2(&h);
    fh_call(&h);
    FH_CHECK(ifl_last_error()[0] != '\0');
    ifl_clear_error();
    FH_CHECK(ifl_last_error()[0] == '\0');
    FH_CHECK(ifl_last_error_copy(NULL, 0) == 0);

    fh_context("ifl_last_error_copy");
    good_point(&h, 2);
    nstatv_2(&h);
    fh_call(&h);
    snprintf(msg, sizeof msg, "%s", ifl_last_error());
    full = strlen(msg);
    FH_CHECK(full > 16);
    /* Length only. */
    FH_CHECK(ifl_last_error_copy(NULL, 0) == full);
    FH_CHECK(ifl_last_error_copy(NULL, 100) == full);
    /* Truncated into 16 bytes: 15 characters and a NUL, nothing written past them. */
    memset(big, 'Z', sizeof big);
    got = ifl_last_error_copy(big, 16);
    FH_CHECK(got == full);
    FH_CHECK(memcmp(big, msg, 15) == 0);
    FH_CHECK(big[15] == '\0');
    untouched = 1;
    for (i = 16; i < (int)sizeof big; i++) {
        untouched &= big[i] == 'Z';
    }
    FH_CHECK(untouched);
    /* len = 1: only the NUL; len = 0: nothing at all. */
    one[0] = one[1] = 'Z';
    FH_CHECK(ifl_last_error_copy(one, 1) == full);
    FH_CHECK(one[0] == '\0' && one[1] == 'Z');
    one[0] = 'Z';
    FH_CHECK(ifl_last_error_copy(one, 0) == full);
    FH_CHECK(one[0] == 'Z' && one[1] == 'Z');
    /* Exactly enough room: the whole message. */
    memset(exact, 'Z', sizeof exact);
    FH_CHECK(ifl_last_error_copy(exact, full + 1) == full);
    FH_CHECK(memcmp(exact, msg, full) == 0 && exact[full] == '\0');
    FH_CHECK(exact[full + 1] == 'Z');
    /* The copy does not consume the message. */
    FH_CHECK(strcmp(ifl_last_error(), msg) == 0);
    ifl_clear_error();
}

int main(int argc, char **argv)
{
    size_t c;
    int nfdir;
    /* The library appends to the log: start from an empty one (before its first message). */
    if (argc > 1) {
        remove(argv[1]);
    }
    for (nfdir = 1; nfdir <= 2; nfdir++) {
        for (c = 0; c < sizeof CATALOGUE / sizeof CATALOGUE[0]; c++) {
            fh_fric h;
            fh_context("%s, NFDIR=%d", CATALOGUE[c].label, nfdir);
            good_point(&h, nfdir);
            CATALOGUE[c].breaks(&h);
            expect_refused(&h, "SI_PAD", CATALOGUE[c].cause, CATALOGUE[c].cause2);
        }
        non_finite_inputs(nfdir);
        lowered_pnewdt(nfdir);
    }
    name_cases();
    native_api();
    if (argc > 1) {
        fh_check_log(argv[1], &seen[0][0], MESSAGE_LEN, n_seen);
    }
    return fh_finish();
}
