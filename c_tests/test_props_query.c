/*
 * test_props_query.c: the PROPS layouts as a pre-processor asks for them (ifl_props_*,
 * docs/c-api.md): law 1's rows listed (index, key, symbol, unit, default, meaning), the laws'
 * facts checked against the layouts' meaning (every index 1..20 once, PROPS(14..16) twice under
 * steady transport, PROPS(5) twice (the constant stick stiffness of PROPS(7) = 4), law 2's seed
 * names), and one good and one bad PROPS checked without an
 * increment: the bad one's message is the cause fric_ reports for the same array.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"

static void list_law_1(void)
{
    fh_context("law 1's rows");
    int n = ifl_props_entry_count(1);
    int seen[21] = {0};
    for (int i = 0; i < n; i++) {
        IflPropsEntry e;
        if (!FH_CHECK(ifl_props_entry(1, i, &e) == IFL_STATUS_OK)) {
            return;
        }
        printf("PROPS(%d) %-18s %-6s %-14s default %-26s %s%s%s\n", e.index, e.key, e.symbol,
               e.unit, e.default_text, e.meaning, e.when[0] ? " -- when " : "", e.when);
        FH_CHECK(e.index >= 1 && e.index <= 20);
        FH_CHECK(e.key[0] != '\0' && strchr(e.key, ' ') == NULL);
        if (e.index >= 1 && e.index <= 20) {
            seen[e.index]++;
        }
        /* The slip tolerance's default is the number 0.005 (docs/props.md). */
        if (e.index == 6) {
            FH_EXACT(e.default_value, 0.005);
        }
        /* μ must be given; μ₂ defaults to μ (a default that is no number). */
        if (e.index == 2) {
            FH_CHECK(e.required == 1);
        }
        if (e.index == 3) {
            FH_CHECK(e.required == 0 && isnan(e.default_value));
        }
    }
    for (int k = 1; k <= 20; k++) {
        fh_context("law 1: PROPS(%d) listed", k);
        FH_CHECK(seen[k] == ((k == 5 || (k >= 14 && k <= 16)) ? 2 : 1));
    }
}

static void law_2_names(void)
{
    static const char *const seed[] = {"coeff", "coeffStatic", "Sa", "Na", "kmu", "vhalf"};
    fh_context("law 2: seed 004's names");
    for (int i = 1; i <= 6; i++) {
        IflPropsEntry e;
        FH_CHECK(ifl_props_entry(2, i, &e) == IFL_STATUS_OK);
        FH_CHECK(e.index == i + 1 && e.seed_name == 1);
        FH_CHECK(strcmp(e.key, seed[i - 1]) == 0);
    }
    fh_context("laws");
    FH_CHECK(ifl_props_law_count() == 3);
    FH_CHECK(ifl_props_law_code(0) == 1 && ifl_props_law_code(1) == 2 &&
             ifl_props_law_code(2) == 3);
    FH_CHECK(ifl_props_law_code(3) == 0 && ifl_props_entry_count(9) == 0);
    IflPropsEntry e;
    FH_CHECK(ifl_props_entry(9, 0, &e) == IFL_STATUS_BAD_PARAMETER);
    FH_CONTAINS(ifl_last_error(), "law 9 is not a law code");
}

static void check_good_and_bad(void)
{
    char msg[512];
    size_t len = 99;
    double good[IFLP_COULOMB_NPROPS], bad[IFLP_COULOMB_NPROPS];
    fh_props_coulomb(good, 0.3);
    fh_props_coulomb(bad, 0.3);
    bad[1] = -0.3;

    fh_context("a good PROPS");
    FH_CHECK(ifl_props_check(good, 5, "SI_PAD", msg, sizeof msg, &len) == IFL_STATUS_OK);
    FH_CHECK(len == 0 && msg[0] == '\0');

    fh_context("a bad PROPS");
    FH_CHECK(ifl_props_check(bad, 5, "SI_PAD", msg, sizeof msg, &len) == IFL_STATUS_BAD_PARAMETER);
    FH_CHECK(len == strlen(msg));
    FH_CONTAINS(msg, "PROPS(2)");
    /* fric_ with the same PROPS reports "...: <the same cause>". */
    fh_fric h;
    fh_init_contact(&h, 2, bad, 10.0, 1.0);
    h.nprops = 5;
    ifl_clear_error();
    fh_call(&h);
    const char *fric_msg = ifl_last_error();
    size_t fl = strlen(fric_msg);
    FH_CHECK(fl > len && strcmp(fric_msg + (fl - len), msg) == 0);
    FH_CONTAINS(fric_msg, "FRIC");

    fh_context("a buffer too small");
    char small[12];
    memset(small, 'x', sizeof small);
    size_t whole = 0;
    FH_CHECK(ifl_props_check(bad, 5, NULL, small, 8, &whole) == IFL_STATUS_BAD_PARAMETER);
    FH_CHECK(whole == len);
    FH_CHECK(strlen(small) == 7 && strncmp(small, msg, 7) == 0);
    FH_CHECK(small[8] == 'x' && small[11] == 'x');
}

int main(void)
{
    list_law_1();
    law_2_names();
    check_good_and_bad();
    return fh_finish();
}
