/*
 * Bad input through gapcon_ (Abaqus signature) and ifl_gap_conductance (docs/gapcon.md,
 * docs/config.md). The configuration is read once per process, so CTest runs this program
 * once per configuration:
 *
 *   test_gapcon_bad_input config-error keep|unset|blank NEEDLE...
 *       INTERFACIAL_CONFIG as CTest set it (keep), removed (unset) or blanks (blank); every
 *       call must fail with a message holding every NEEDLE (for a bad file: "file:line: key:"
 *       and the cause).
 *   test_gapcon_bad_input good
 *       INTERFACIAL_CONFIG = c_tests/configs/gapcon_good.toml (no "*" entry): names matched
 *       exactly after trimming blanks, ignoring case, never by prefix; CHARACTER*8 names;
 *       interactions not configured; NaN and infinite D and TEMP; radiation below absolute
 *       zero and overflowing; NULL pointers; the arguments gapcon_ must not read.
 *   test_gapcon_bad_input fallback
 *       INTERFACIAL_CONFIG = c_tests/configs/gapcon_fallback.toml: prefixes and extensions of
 *       SI1 take the "*" law, not SI1's.
 *
 * Every failure of gapcon_: AK(1) = 0 exactly, AK(2..5) and the slot after untouched (guard
 * values), no input written, ifl_last_error() naming GAPCON, the interaction, "element 17,
 * node 42" and the cause; the same call twice; then a good call works and leaves the last
 * error alone. Every failure of ifl_gap_conductance: the documented non-OK status and *out all
 * zeros. When INTERFACIAL_LOG is set (CTest sets it), the harness empties the file first and
 * at the end checks it holds each distinct message exactly once, in order; a bad
 * configuration is one cause for the whole run: one line per routine, whatever the interaction.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "gapcon_harness.h"

#define K_SI1 2.5      /* configs/gapcon_good.toml, gapcon_fallback.toml */
#define K_CONTACT8 7.0 /* configs/gapcon_good.toml */
#define K_FALLBACK 4.0 /* configs/gapcon_fallback.toml, "*" */
#define OUT_MARK 6.5   /* in every IflConductance field before a failing call */

enum { MAX_MESSAGES = 128, MESSAGE_LEN = 1024 };
static char seen[MAX_MESSAGES][MESSAGE_LEN]; /* distinct messages, in order of appearance */
static int n_seen;

/*
 * A bad or missing configuration file is one cause for the whole run (docs/gapcon.md): it is
 * printed once per routine, whatever the interaction. Other causes are printed once per
 * interaction. Set in config-error mode.
 */
static int once_per_run;

/* The message without its "interaction '...' " part, when the cause is once per run. */
static void dedupe_key(const char *msg, char *key, size_t len)
{
    const char *start = strstr(msg, "interaction '");
    const char *end = start != NULL ? strstr(start, "' (") : NULL;
    size_t head = (!once_per_run || end == NULL) ? strlen(msg) : (size_t)(start - msg);
    const char *tail = (!once_per_run || end == NULL) ? "" : end + 2;
    size_t n_tail = strlen(tail);
    if (head > len - 1) {
        head = len - 1;
    }
    if (n_tail > len - 1 - head) {
        n_tail = len - 1 - head;
    }
    memcpy(key, msg, head);
    memcpy(key + head, tail, n_tail);
    key[head + n_tail] = '\0';
}

static void remember_message(const char *msg)
{
    char key[MESSAGE_LEN], other[MESSAGE_LEN];
    int i;
    dedupe_key(msg, key, sizeof key);
    for (i = 0; i < n_seen; i++) {
        dedupe_key(seen[i], other, sizeof other);
        if (strcmp(other, key) == 0) {
            return;
        }
    }
    if (FH_CHECK(n_seen < MAX_MESSAGES && strlen(msg) < MESSAGE_LEN)) {
        strcpy(seen[n_seen++], msg);
    }
}

/* The last error must hold every one of `needles` (NULL-terminated list). */
static void expect_needles(const char *msg, const char *const *needles)
{
    int i;
    for (i = 0; needles != NULL && needles[i] != NULL; i++) {
        FH_CONTAINS(msg, needles[i]);
    }
}

/*
 * gapcon_ at g must fail: twice, each time AK(1) = 0 and the rest as the header says. `shown`
 * is how the interaction must appear in the message.
 */
static void expect_gapcon_refused(gh_gapcon *g, const char *shown, const char *const *needles)
{
    char quoted[160], msg[MESSAGE_LEN];
    int call;
    snprintf(quoted, sizeof quoted, "interaction '%s'", shown);
    for (call = 1; call <= 2; call++) {
        double ak;
        ifl_clear_error();
        ak = gh_call(g); /* AK(1) written, AK(2..5) guards, inputs unchanged */
        FH_EXACT(ak, 0.0);
        FH_CHECK(!signbit(ak));
        fh_check_last_message(msg, sizeof msg, "GAPCON", quoted, "element 17, node 42");
        expect_needles(msg, needles);
        remember_message(msg);
    }
}

/* ifl_gap_conductance must return `status` and zero *out. */
static void expect_native_refused(const char *name, double d, double p, double ta, double tb,
                                  IflStatus status, const char *const *needles)
{
    IflConductance c;
    IflStatus s;
    c.k = c.dk_dd = c.dk_dp = c.dk_dtheta_mean = c.dq_dtheta_a = c.dq_dtheta_b = OUT_MARK;
    ifl_clear_error();
    s = ifl_gap_conductance(name, d, p, ta, tb, &c);
    if (!FH_CHECK(s == status)) {
        fprintf(stderr, "  status %d, expected %d\n", (int)s, (int)status);
    }
    FH_EXACT(c.k, 0.0);
    FH_EXACT(c.dk_dd, 0.0);
    FH_EXACT(c.dk_dp, 0.0);
    FH_EXACT(c.dk_dtheta_mean, 0.0);
    FH_EXACT(c.dq_dtheta_a, 0.0);
    FH_EXACT(c.dq_dtheta_b, 0.0);
    FH_CONTAINS(ifl_last_error(), "ifl_gap_conductance");
    expect_needles(ifl_last_error(), needles);
    remember_message(ifl_last_error());
}

/* A good call after a failure: AK(1) = SI1's k, the last error still the failure's. */
static void expect_good_after(double k_si1)
{
    char before[MESSAGE_LEN];
    gh_gapcon g;
    snprintf(before, sizeof before, "%s", ifl_last_error());
    gh_init(&g, "SI1", 1e-4, 10.0, 300.0, 290.0);
    FH_EXACT(gh_call(&g), k_si1);
    FH_CHECK(strcmp(ifl_last_error(), before) == 0);
}

/* ---- configuration errors --------------------------------------------------------------- */

static void config_error(const char *const *needles)
{
    static const char *const names[] = {"SI1", "OTHER"};
    size_t i;
    for (i = 0; i < sizeof names / sizeof names[0]; i++) {
        gh_gapcon g;
        fh_context("configuration error, gapcon_ for %s", names[i]);
        gh_init(&g, names[i], 1e-4, 10.0, 300.0, 290.0);
        expect_gapcon_refused(&g, names[i], needles);
    }
    fh_context("configuration error, ifl_gap_conductance");
    expect_native_refused("SI1", 1e-4, 10.0, 300.0, 290.0, IFL_STATUS_BAD_PARAMETER, needles);
    /* The file is not re-read: a later call fails the same way. */
    fh_context("configuration error, once more");
    {
        gh_gapcon g;
        gh_init(&g, "SI1", 1e-4, 10.0, 300.0, 290.0);
        expect_gapcon_refused(&g, "SI1", needles);
    }
}

/* ---- a good file ------------------------------------------------------------------------- */

/* A name passed as CINAME (CHARACTER*len) and the conductance it must find; a k <= 0 means
 * what the table using it says. */
typedef struct {
    const char *text;
    size_t len;
    double k;
} name_case;

/* Name rules and CHARACTER lengths that must find the configured law. */
static void names_that_match(void)
{
    static const name_case cases[] = {
        {"SI1", 80, K_SI1},          /* CHARACTER*80, blank-padded */
        {"si1", 80, K_SI1},          /* case ignored */
        {"Si1", 80, K_SI1},
        {"SI1", 3, K_SI1},           /* exactly as long as the name */
        {"MIXED_CASE", 80, -1.0},    /* the file writes Mixed_Case; Abaqus passes upper case */
        {"mixed_case", 80, -1.0},
        {"CONTACT8", 8, K_CONTACT8}, /* CHARACTER*8 */
        {"SI1", 8, K_SI1},
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gh_gapcon g;
        double want = cases[i].k;
        fh_context("name '%s' (CHARACTER*%zu) matches", cases[i].text, cases[i].len);
        gh_init(&g, cases[i].text, 1e-4, 50.0, 300.0, 290.0);
        fh_set_name(g.ciname, &g.ciname_len, cases[i].len, cases[i].text);
        if (cases[i].len < 40) {
            /* What follows the hidden length is not part of the name. */
            memcpy(g.ciname + cases[i].len, "XYZ_NOT_PART_OF_IT", 18);
        }
        if (want < 0.0) {
            want = 1.0 + (3.0 - 1.0) * 50.0 / 100.0; /* Mixed_Case's table at p = 50 */
        }
        FH_EXACT(gh_call_ok(&g), want);
        FH_EXACT(gh_native_ok(cases[i].text, 1e-4, 50.0, 300.0, 290.0).k, want);
    }
}

/*
 * A CHARACTER*len name as the last bytes of a readable page followed by an inaccessible one:
 * a read past the hidden length faults. Returns the name's address (NULL if unavailable).
 */
static char *name_at_page_end(size_t len, const char *text, void **map, size_t *map_len)
{
    long page = sysconf(_SC_PAGESIZE);
    char *base, *name;
    size_t n = strlen(text);
    if (page <= 0) {
        return NULL;
    }
    *map_len = 2 * (size_t)page;
    base = mmap(NULL, *map_len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (base == MAP_FAILED) {
        return NULL;
    }
    if (mprotect(base + page, (size_t)page, PROT_NONE) != 0) {
        munmap(base, *map_len);
        return NULL;
    }
    *map = base;
    name = base + page - len;
    memset(name, ' ', len);
    memcpy(name, text, n < len ? n : len);
    return name;
}

static void names_at_page_end(void)
{
    static const name_case cases[] = {
        {"CONTACT8", 8, K_CONTACT8}, {"SI1", 80, K_SI1}, {"NOPE8", 8, 0.0}};
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        void *map = NULL;
        size_t map_len = 0;
        char *name = name_at_page_end(cases[i].len, cases[i].text, &map, &map_len);
        fh_context("CHARACTER*%zu '%s' ending at a page boundary", cases[i].len, cases[i].text);
        if (!FH_CHECK(name != NULL)) {
            continue;
        }
        {
            double ak[GH_AK] = {GH_AK_MARK, GH_GUARD, GH_GUARD, GH_GUARD, GH_GUARD, GH_GUARD};
            double d[2] = {1e-4, 10.0}, temp[2] = {300.0, 290.0};
            int noel = 17, node = 42;
            gapcon_(ak, d, NULL, temp, NULL, NULL, name, NULL, NULL, NULL, &noel, &node, NULL,
                    NULL, NULL, cases[i].len, 80, 80);
            FH_EXACT(ak[0], cases[i].k);
            FH_CHECK(ak[1] == GH_GUARD && ak[4] == GH_GUARD && ak[5] == GH_GUARD);
            if (cases[i].k == 0.0) {
                FH_CONTAINS(ifl_last_error(), "interaction 'NOPE8'");
                remember_message(ifl_last_error());
            }
        }
        munmap(map, map_len);
    }
}

/* Names that must not find a law: not configured, prefixes, extensions. */
static void names_that_do_not_match(const char *path)
{
    static const struct {
        const char *text;
        size_t len;
        const char *shown;
    } cases[] = {
        {"NOPE", 80, "NOPE"},
        {"SI1A", 80, "SI1A"},           /* SI1 is a prefix of it */
        {"SI", 80, "SI"},               /* a prefix of SI1 */
        {"SI1_", 80, "SI1_"},
        {" SI1", 80, " SI1"},           /* leading blanks are part of a Fortran name */
        {"CONTACT8", 7, "CONTACT"},     /* CHARACTER*7: the 8 is past the hidden length */
        {"NOPE8", 8, "NOPE8"},          /* CHARACTER*8, then "XYZ..." that must not be read */
        {"SI1A", 8, "SI1A"},
        {"", 80, ""},                   /* all blanks */
    };
    char where[600];
    const char *needles[3];
    size_t i;
    snprintf(where, sizeof where, "interaction not found in %s", path);
    needles[0] = where;
    needles[1] = "(and no \"*\" entry)";
    needles[2] = NULL;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gh_gapcon g;
        fh_context("name '%s' (CHARACTER*%zu) is not configured", cases[i].text, cases[i].len);
        gh_init(&g, cases[i].text, 1e-4, 50.0, 300.0, 290.0);
        fh_set_name(g.ciname, &g.ciname_len, cases[i].len, cases[i].text);
        if (cases[i].len < 40) {
            memcpy(g.ciname + cases[i].len, "XYZ_NOT_PART_OF_IT", 18);
        }
        expect_gapcon_refused(&g, cases[i].shown, needles);
        FH_CHECK(strstr(ifl_last_error(), "XYZ") == NULL);
        expect_good_after(K_SI1);
        if (cases[i].len >= strlen(cases[i].text)) {
            expect_native_refused(cases[i].text, 1e-4, 50.0, 300.0, 290.0,
                                  IFL_STATUS_BAD_PARAMETER, needles);
        }
    }
}

typedef struct {
    const char *label;
    const char *name;
    double d, p, ta, tb;
    IflStatus status;
    const char *cause;
} bad_value;

static void bad_values(void)
{
    static const bad_value cases[] = {
        {"TEMP(1) = NaN", "SI1", 1e-4, 10.0, NAN, 290.0, IFL_STATUS_BAD_INPUT,
         "TEMP(1) is NaN or infinite"},
        {"TEMP(2) = NaN", "SI1", 1e-4, 10.0, 300.0, NAN, IFL_STATUS_BAD_INPUT,
         "TEMP(2) is NaN or infinite"},
        {"D(1) = NaN", "SI1", NAN, 10.0, 300.0, 290.0, IFL_STATUS_BAD_INPUT,
         "D(1) is NaN or infinite"},
        {"D(2) = NaN", "SI1", 1e-4, NAN, 300.0, 290.0, IFL_STATUS_BAD_INPUT,
         "D(2) is NaN or infinite"},
        {"TEMP(1) = +Inf", "SI1", 1e-4, 10.0, INFINITY, 290.0, IFL_STATUS_BAD_INPUT,
         "TEMP(1) is NaN or infinite"},
        {"TEMP(2) = -Inf", "SI1", 1e-4, 10.0, 300.0, -INFINITY, IFL_STATUS_BAD_INPUT,
         "TEMP(2) is NaN or infinite"},
        {"D(1) = -Inf", "SI1", -INFINITY, 10.0, 300.0, 290.0, IFL_STATUS_BAD_INPUT,
         "D(1) is NaN or infinite"},
        {"D(2) = +Inf", "SI1", 1e-4, INFINITY, 300.0, 290.0, IFL_STATUS_BAD_INPUT,
         "D(2) is NaN or infinite"},
        /* A table law reads D(2); NaN must not slip through the interpolation. */
        {"D(2) = NaN, table", "MIXED_CASE", 1e-4, NAN, 300.0, 290.0, IFL_STATUS_BAD_INPUT,
         "D(2) is NaN or infinite"},
        {"TEMP = NaN, radiation", "HOT", 1e-4, 0.0, NAN, 20.0, IFL_STATUS_BAD_INPUT,
         "TEMP(1) is NaN or infinite"},
        /* HOT is in Celsius: -300 C is below absolute zero. */
        {"TEMP(1) below absolute zero", "HOT", 1e-4, 0.0, -300.0, 20.0, IFL_STATUS_BAD_INPUT,
         "below absolute zero"},
        {"TEMP(2) below absolute zero", "HOT", 1e-4, 0.0, 20.0, -273.2, IFL_STATUS_BAD_INPUT,
         "below absolute zero"},
        /* The radiation conductance F sigma (a + b)(a^2 + b^2) ~ 3e-8 (1e110)^3 overflows. */
        {"radiation overflow", "HOT", 1e-4, 0.0, 1e110, 20.0, IFL_STATUS_NUMERICAL_FAILURE,
         "overflow"},
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const bad_value *b = &cases[i];
        const char *needles[2];
        gh_gapcon g;
        needles[0] = b->cause;
        needles[1] = NULL;
        fh_context("%s (gapcon_)", b->label);
        gh_init(&g, b->name, b->d, b->p, b->ta, b->tb);
        expect_gapcon_refused(&g, b->name, needles);
        expect_good_after(K_SI1);
        fh_context("%s (ifl_gap_conductance)", b->label);
        expect_native_refused(b->name, b->d, b->p, b->ta, b->tb, b->status, needles);
    }
    /* At absolute zero exactly, radiation is fine: q = -F sigma b^4 (b = 293.15 K). */
    fh_context("HOT at absolute zero");
    {
        double b = 20.0 + 273.15;
        FH_NEAR(gh_ak("HOT", 1e-4, 0.0, -273.15, 20.0) * (-273.15 - 20.0),
                -0.5 * GH_SIGMA_SI * b * b * b * b, 1e-13, 0.0);
    }
}

/* A gapcon_ call with only the arguments it reads (AK, D, TEMP, CINAME, NOEL, NODE; every other
 * one NULL), AK(1) preset to the mark and the thread's message cleared first. */
static void gapcon_reads_only(double *ak, double *d, double *temp, char *name, int *noel,
                              int *node)
{
    if (ak != NULL) {
        ak[0] = GH_AK_MARK;
    }
    ifl_clear_error();
    gapcon_(ak, d, NULL, temp, NULL, NULL, name, NULL, NULL, NULL, noel, node, NULL, NULL, NULL,
            80, 80, 80);
}

/* NULL pointers: what the host must pass, and what gapcon_ must never read. */
static void null_pointers(void)
{
    double ak[GH_AK];
    double d[2] = {1e-4, 10.0}, temp[2] = {300.0, 290.0};
    int noel = 17, node = 42;
    char name[80];
    int i;
    const char *needles[2] = {NULL, NULL};
    memset(name, ' ', sizeof name);
    memcpy(name, "SI1", 3);

    /* FLOWM, PREDEF, TIME, SLNAME, MSNAME, COORDS, NPRED, KSTEP, KINC are not read. */
    fh_context("unread arguments NULL");
    for (i = 0; i < GH_AK; i++) {
        ak[i] = GH_GUARD;
    }
    gapcon_reads_only(ak, d, temp, name, &noel, &node);
    FH_EXACT(ak[0], K_SI1);
    FH_CHECK(ak[1] == GH_GUARD && ak[2] == GH_GUARD && ak[3] == GH_GUARD && ak[4] == GH_GUARD &&
             ak[5] == GH_GUARD);
    FH_CHECK(ifl_last_error()[0] == '\0');

    /* NOEL and NODE are only read for messages: NULL shows as '?'. */
    fh_context("NOEL, NODE NULL in a failing call");
    d[0] = NAN;
    name[0] = 'C'; /* "CI1": not configured, a cause of its own */
    gapcon_reads_only(ak, d, temp, name, NULL, NULL);
    FH_EXACT(ak[0], 0.0);
    FH_CONTAINS(ifl_last_error(), "interaction 'CI1' (element ?, node ?)");
    remember_message(ifl_last_error());
    d[0] = 1e-4;
    name[0] = 'S';

    for (i = 0; i < 2; i++) {
        fh_context(i == 0 ? "D NULL" : "TEMP NULL");
        gapcon_reads_only(ak, i == 0 ? NULL : d, i == 0 ? temp : NULL, name, &noel, &node);
        FH_EXACT(ak[0], 0.0);
        FH_CONTAINS(ifl_last_error(), i == 0 ? "D is a NULL pointer" : "TEMP is a NULL pointer");
        remember_message(ifl_last_error());
    }

    fh_context("AK NULL: reported, no crash");
    gapcon_reads_only(NULL, d, temp, name, &noel, &node);
    FH_CONTAINS(ifl_last_error(), "AK is a NULL pointer");
    remember_message(ifl_last_error());

    fh_context("ifl_gap_conductance: interaction NULL");
    needles[0] = "NULL pointer";
    expect_native_refused(NULL, 1e-4, 10.0, 300.0, 290.0, IFL_STATUS_BAD_INPUT, needles);
    fh_context("ifl_gap_conductance: out NULL");
    ifl_clear_error();
    FH_CHECK(ifl_gap_conductance("SI1", 1e-4, 10.0, 300.0, 290.0, NULL) == IFL_STATUS_BAD_INPUT);
    FH_CONTAINS(ifl_last_error(), "NULL pointer");
    remember_message(ifl_last_error());
}

static void fallback_names(void)
{
    static const name_case cases[] = {
        {"SI1", 80, K_SI1},       {"si1", 80, K_SI1},         {"SI1", 8, K_SI1},
        {"SI1A", 80, K_FALLBACK}, {"SI", 80, K_FALLBACK},     {"SI1_", 80, K_FALLBACK},
        {"SI1A", 8, K_FALLBACK},  {"OTHER", 80, K_FALLBACK},  {"", 80, K_FALLBACK},
        {"SI1", 2, K_FALLBACK},   /* CHARACTER*2: "SI" */
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gh_gapcon g;
        fh_context("fallback file: '%s' (CHARACTER*%zu)", cases[i].text, cases[i].len);
        gh_init(&g, cases[i].text, 1e-4, 50.0, 300.0, 290.0);
        fh_set_name(g.ciname, &g.ciname_len, cases[i].len, cases[i].text);
        FH_EXACT(gh_call_ok(&g), cases[i].k);
        if (cases[i].len >= strlen(cases[i].text)) {
            FH_EXACT(gh_native_ok(cases[i].text, 1e-4, 50.0, 300.0, 290.0).k, cases[i].k);
        }
    }
    /* The fallback does not swallow bad input. */
    {
        const char *needles[] = {"TEMP(1) is NaN or infinite", NULL};
        gh_gapcon g;
        fh_context("fallback file: NaN for a fallback name");
        gh_init(&g, "OTHER", 1e-4, 50.0, NAN, 290.0);
        expect_gapcon_refused(&g, "OTHER", needles);
    }
}

static int usage(void)
{
    fprintf(stderr, "usage: test_gapcon_bad_input config-error keep|unset|blank NEEDLE...\n"
                    "       test_gapcon_bad_input good|fallback\n");
    return 2;
}

int main(int argc, char **argv)
{
    const char *log = getenv("INTERFACIAL_LOG");
    const char *mode = argc > 1 ? argv[1] : "";
    /* The library appends to the log: start from an empty one (before its first message). */
    if (log != NULL && log[0] != '\0') {
        remove(log);
    }
    if (strcmp(mode, "config-error") == 0 && argc > 3) {
        const char *env = argv[2];
        if (strcmp(env, "unset") == 0) {
            unsetenv("INTERFACIAL_CONFIG");
        } else if (strcmp(env, "blank") == 0) {
            setenv("INTERFACIAL_CONFIG", "   ", 1);
        } else if (strcmp(env, "keep") != 0) {
            return usage();
        }
        once_per_run = 1;
        config_error((const char *const *)(argv + 3));
    } else if (strcmp(mode, "good") == 0) {
        const char *path = getenv("INTERFACIAL_CONFIG");
        if (!FH_CHECK(path != NULL)) {
            return fh_finish();
        }
        names_that_match();
        names_at_page_end();
        names_that_do_not_match(path);
        bad_values();
        null_pointers();
    } else if (strcmp(mode, "fallback") == 0) {
        fallback_names();
    } else {
        return usage();
    }
    if (log != NULL && log[0] != '\0') {
        fh_check_log(log, &seen[0][0], MESSAGE_LEN, n_seen);
    }
    return fh_finish();
}
