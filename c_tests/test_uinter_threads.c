/*
 * uinter_ from 8 threads at once, compared bit for bit with a serial run of the same points
 * (docs/threads-and-sanitizers.md).
 *
 * 4096 interface points x 256 increments = 1 048 576 uinter_ calls per run. Each point is
 * driven the way a host drives it: STRESS and STATEV carried from one increment to the next,
 * the overclosure RDISP(1) following a wave that closes, pulls apart and re-closes the
 * interface, a random tangential increment DRDISP(2..NDIR). Every point has its own adhesive
 * interaction drawn from a Lehmer generator (x <- 48271 x mod 2^31 - 1) seeded by the point's
 * index, so its calls do not depend on which thread makes them or when: NDIR 2 or 3; mu_s =
 * mu_d or above it; separation adhesion (S_a, N_a > 0: bonded while the tension stays small) or
 * none; rate dependence (k_mu, v_half) or none; heat conduction from the configuration file
 * (PROPS(11) = 1, written to argv[1] before the threads start, so their first calls race for
 * it) and frictional heat, or none; NSTATV 3 or 5. Now and then a NaN in DRDISP: the call is
 * refused (PNEWDT = 0.25, STRESS and STATEV unchanged, the thread's last error names UINTER).
 * Every array uinter_ may touch is its own heap block of exactly the declared size, so an
 * out-of-bounds write is an AddressSanitizer report in the sanitizer build.
 *
 * Compared with the serial run (on the main thread, afterwards): every output of every call
 * (STRESS, DDSDDR, FLUX, DDFDDT, DDFDDR, STATEV, SED, SFD, PNEWDT, LOPENCLOSE, LSTATE) folded
 * into a 64-bit FNV-1a digest per call, the digests compared with memcmp; the final STRESS and
 * STATEV of every point; the counts of each kind of call. Checked on every call, against the
 * law: outputs finite, |tau| <= (mu_s + k_mu rate) p+ + S_a, status in {0 stick, 1 slip,
 * 3 bonded, 4 open} with LSTATE and LOPENCLOSE agreeing, open => zero stress, SED, SFD >= 0,
 * accumulated slip never decreasing, STATEV past 3 untouched.
 *
 * INTERFACIAL_TEST_SHRINK=n divides the number of points by n (valgrind, ASan runs).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "thread_harness.h"

enum { FULL_POINTS = 4096, INCS = 256, MIN_POINTS = 64 };
#define PNEWDT_IN 1e36
#define STATEV_TAIL (-5.5e55)
#define KN 1e4

enum {
    K_STICK,
    K_SLIP,
    K_BONDED,
    K_OPEN,
    K_RECONTACT, /* open at the start, closed at the end */
    K_HEAT,      /* FLUX non-zero */
    K_REFUSED,
    K_NDIR2,
    K_NDIR3,
    N_KINDS
};
static const char *const KIND_NAMES[N_KINDS] = {"stick",  "slip", "bonded", "open", "re-contact",
                                                "heat",   "refused (NaN)", "NDIR 2", "NDIR 3"};

static void violation(th_tally *t, const char *what, int point, int inc)
{
    th_violation(t, "point %d increment %d: %s", point, inc, what);
}

typedef struct {
    double stress[3], statev[5];
} final_rec;

static double *block(size_t n)
{
    return malloc(n * sizeof(double));
}

/* One point, all increments; digests[inc] per call, final state in *fin. */
static void run_point(int ip, uint64_t *digests, void *fin_out, th_tally *t)
{
    final_rec *fin = fin_out;
    uint32_t rng = 1u + (uint32_t)ip * 7919u;
    const int ndir = (th_lehmer(&rng) & 1u) ? 3 : 2;
    const int nstatv = (th_lehmer(&rng) & 1u) ? 5 : 3;
    const int adhesion = th_lehmer(&rng) % 3u != 0;
    const int rate = th_lehmer(&rng) % 4u == 0;
    const int heat = th_lehmer(&rng) % 2u == 0;
    double props[13] = {2.0};
    double *stress = block((size_t)ndir), *ddsddr = block((size_t)(ndir * ndir));
    double *dvisc = block((size_t)(ndir * ndir)), *dstruct = block((size_t)(ndir * ndir));
    double *flux = block(2), *ddfddt = block(4), *ddsddt = block((size_t)(2 * ndir));
    double *ddfddr = block((size_t)(2 * ndir)), *statev = block((size_t)nstatv);
    double *rdisp = block((size_t)ndir), *drdisp = block((size_t)ndir), *temp = block(2);
    double *dtemp = block(2), *predef = block(2), *dpred = block(2), *time = block(2);
    double *coords = block(3), *alocaldir = block(9), *drot = block(4);
    double sed, sfd, spd, svd, scd, pnewdt, dtime = 0.01, freqr = 0.0, area = 1.0;
    double chrlngth = 1.0, amp, offset, omega, slide_amp;
    int node = ip + 1, npred = 1, nprops = 13, mcrd = 3, kstep = 1, kinc, kit = 1, linper = 0;
    int lopenclose = -1, lstate = -1, lsdi = 0, lprint = 0, inc, k;
    char ciname[80], slname[80], msname[80];

    if (!stress || !ddsddr || !dvisc || !dstruct || !flux || !ddfddt || !ddsddt || !ddfddr ||
        !statev || !rdisp || !drdisp || !temp || !dtemp || !predef || !dpred || !time ||
        !coords || !alocaldir || !drot) {
        violation(t, "allocation failed", ip, 0);
        return;
    }
    props[1] = th_uniform(&rng, 0.1, 0.5);                                   /* mu_d */
    props[2] = (th_lehmer(&rng) & 1u) ? props[1] + th_uniform(&rng, 0.0, 0.2) : 0.0; /* mu_s */
    props[3] = adhesion ? th_uniform(&rng, 1.0, 20.0) : 0.0;                 /* S_a */
    props[4] = adhesion ? th_uniform(&rng, 5.0, 50.0) : 0.0;                 /* N_a */
    props[5] = rate ? th_uniform(&rng, 0.0, 0.5) : 0.0;                      /* k_mu */
    props[6] = rate ? th_uniform(&rng, 0.01, 1.0) : 0.0;                     /* v_half */
    props[7] = th_uniform(&rng, 1e-4, 1e-3);                                 /* gamma_crit */
    props[9] = KN;
    props[10] = heat ? 1.0 : 0.0;
    props[11] = heat ? 0.5 : 0.0;
    props[12] = 0.5;
    memset(ciname, ' ', 80);
    memset(slname, ' ', 80);
    memset(msname, ' ', 80);
    memcpy(ciname, "PTAB", 4);
    memset(stress, 0, (size_t)ndir * sizeof(double));
    statev[0] = statev[1] = statev[2] = 0.0;
    for (k = 3; k < nstatv; k++) {
        statev[k] = STATEV_TAIL;
    }
    memset(rdisp, 0, (size_t)ndir * sizeof(double));
    /* Outputs a refused call leaves alone (FLUX) must hold the same bits in both runs. */
    flux[0] = flux[1] = -1.0;
    for (k = 0; k < 4; k++) {
        ddfddt[k] = -1.0;
    }
    for (k = 0; k < 2 * ndir; k++) {
        ddsddt[k] = ddfddr[k] = -1.0;
    }
    sed = sfd = spd = svd = scd = -1.0;
    temp[0] = th_uniform(&rng, 300.0, 400.0);
    temp[1] = th_uniform(&rng, 20.0, 100.0);
    dtemp[0] = dtemp[1] = predef[0] = predef[1] = dpred[0] = dpred[1] = 0.0;
    time[0] = time[1] = 0.0;
    memset(coords, 0, 3 * sizeof(double));
    memset(alocaldir, 0, 9 * sizeof(double));
    memset(drot, 0, 4 * sizeof(double));
    /* Overclosure wave: mostly closed (p up to ~ KN amp), dipping into tension (bonded) and,
     * for larger amplitudes, apart (open), then back in contact. */
    amp = th_uniform(&rng, 1e-4, 2e-3);
    offset = th_uniform(&rng, -0.5, 0.6) * amp;
    omega = th_uniform(&rng, 0.05, 0.3);
    slide_amp = th_uniform(&rng, 0.2, 3.0) * props[7];
    t->kinds[ndir == 2 ? K_NDIR2 : K_NDIR3] += INCS;

    for (inc = 0; inc < INCS; inc++) {
        double stress0[3], statev0[5], status0 = statev[2], tau = 0.0, p, bound, mu;
        int refuse = th_lehmer(&rng) % 997u == 0, a, finite = 1;
        uint64_t h = 1469598103934665603ull;
        memcpy(stress0, stress, (size_t)ndir * sizeof(double));
        memcpy(statev0, statev, (size_t)nstatv * sizeof(double));
        rdisp[0] = offset + amp * sin(omega * inc);
        drdisp[0] = 0.0;
        for (a = 1; a < ndir; a++) {
            drdisp[a] = th_uniform(&rng, -slide_amp, slide_amp);
            rdisp[a] += drdisp[a];
        }
        if (refuse) {
            drdisp[1] = NAN;
        }
        for (k = 0; k < ndir * ndir; k++) {
            ddsddr[k] = dvisc[k] = dstruct[k] = -1.0;
        }
        pnewdt = PNEWDT_IN;
        kinc = inc + 1;
        uinter_(stress, ddsddr, dvisc, dstruct, flux, ddfddt, ddsddt, ddfddr, statev, &sed, &sfd,
                &spd, &svd, &scd, &pnewdt, rdisp, drdisp, temp, dtemp, predef, dpred, time,
                &dtime, &freqr, ciname, slname, msname, props, coords, alocaldir, drot, &area,
                &chrlngth, &node, &ndir, &nstatv, &npred, &nprops, &mcrd, &kstep, &kinc, &kit,
                &linper, &lopenclose, &lstate, &lsdi, &lprint, 80, 80, 80);
        h = th_fnv(h, stress, (size_t)ndir * sizeof(double));
        h = th_fnv(h, ddsddr, (size_t)(ndir * ndir) * sizeof(double));
        h = th_fnv(h, flux, 2 * sizeof(double));
        h = th_fnv(h, ddfddt, 4 * sizeof(double));
        h = th_fnv(h, ddfddr, (size_t)(2 * ndir) * sizeof(double));
        h = th_fnv(h, statev, (size_t)nstatv * sizeof(double));
        h = th_fnv(h, &sed, sizeof sed);
        h = th_fnv(h, &sfd, sizeof sfd);
        h = th_fnv(h, &spd, sizeof spd);
        h = th_fnv(h, &pnewdt, sizeof pnewdt);
        h = th_fnv(h, &lopenclose, sizeof lopenclose);
        h = th_fnv(h, &lstate, sizeof lstate);
        digests[inc] = h;
        for (k = 3; k < nstatv; k++) {
            if (statev[k] != STATEV_TAIL) {
                violation(t, "STATEV past 3 written", ip, inc);
            }
        }
        if (refuse) {
            t->kinds[K_REFUSED]++;
            if (pnewdt != 0.25 || memcmp(stress0, stress, (size_t)ndir * sizeof(double)) != 0 ||
                memcmp(statev0, statev, (size_t)nstatv * sizeof(double)) != 0 ||
                strstr(ifl_last_error(), "UINTER") == NULL) {
                violation(t, "a NaN in DRDISP was not refused cleanly", ip, inc);
            }
            drdisp[1] = 0.0;
            continue;
        }
        if (pnewdt != PNEWDT_IN) {
            violation(t, "a good call lowered PNEWDT", ip, inc);
            continue;
        }
        for (a = 0; a < ndir; a++) {
            finite = finite && isfinite(stress[a]);
        }
        for (k = 0; k < ndir * ndir; k++) {
            finite = finite && isfinite(ddsddr[k]);
        }
        for (k = 0; k < 2 * ndir; k++) {
            finite = finite && isfinite(ddfddr[k]);
        }
        finite = finite && isfinite(flux[0]) && isfinite(flux[1]) && isfinite(sed) &&
                 isfinite(sfd) && isfinite(spd) && isfinite(statev[0]) && isfinite(statev[1]);
        if (!finite) {
            violation(t, "non-finite output", ip, inc);
        }
        for (a = 1; a < ndir; a++) {
            tau = hypot(tau, stress[a]);
        }
        p = stress[0];
        mu = props[2] > props[1] ? props[2] : props[1];
        /* After a slip a stick increment keeps the start rate's strength (docs/props.md). */
        bound = (mu + props[5] * (statev0[2] == 1.0 && statev0[1] > statev[1] ? statev0[1]
                                                                             : statev[1])) *
                    (p > 0.0 ? p : 0.0) +
                props[3];
        if (tau > bound * (1.0 + 1e-12)) {
            violation(t, "|tau| above the strength", ip, inc);
        }
        if (sed < 0.0 || sfd < 0.0 || spd < 0.0 || statev[0] < statev0[0] || statev[1] < 0.0) {
            violation(t, "negative energy or decreasing slip", ip, inc);
        }
        if (lstate != (int)statev[2] || lopenclose != (statev[2] != 4.0)) {
            violation(t, "LSTATE/LOPENCLOSE disagree with STATEV(3)", ip, inc);
        }
        if (statev[2] == 0.0) {
            t->kinds[K_STICK]++;
        } else if (statev[2] == 1.0) {
            t->kinds[K_SLIP]++;
        } else if (statev[2] == 3.0) {
            t->kinds[K_BONDED]++;
            if (tau >= props[3] || p > 0.0) {
                violation(t, "bonded beyond S_a or in compression", ip, inc);
            }
        } else if (statev[2] == 4.0) {
            t->kinds[K_OPEN]++;
            if (p != 0.0 || tau != 0.0) {
                violation(t, "open with a stress", ip, inc);
            }
        } else {
            violation(t, "unknown status", ip, inc);
        }
        if (status0 == 4.0 && (statev[2] == 0.0 || statev[2] == 1.0)) {
            t->kinds[K_RECONTACT]++;
        }
        if (flux[0] != 0.0 || flux[1] != 0.0) {
            t->kinds[K_HEAT]++;
        }
    }
    memset(fin, 0, sizeof *fin);
    memcpy(fin->stress, stress, (size_t)ndir * sizeof(double));
    memcpy(fin->statev, statev, (size_t)nstatv * sizeof(double));
    free(stress), free(ddsddr), free(dvisc), free(dstruct), free(flux), free(ddfddt);
    free(ddsddt), free(ddfddr), free(statev), free(rdisp), free(drdisp), free(temp);
    free(dtemp), free(predef), free(dpred), free(time), free(coords), free(alocaldir);
    free(drot);
}

static void report_tally(const char *run, const th_tally *t)
{
    th_report(run, t, KIND_NAMES, N_KINDS, "", "%ld calls", (long)t->points);
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "uinter_threads.toml";
    int points = FULL_POINTS / th_shrink_factor(FULL_POINTS / MIN_POINTS);
    FILE *f;

    fh_context("configuration");
    f = fopen(path, "w");
    if (!FH_CHECK(f != NULL)) {
        return fh_finish();
    }
    fputs("[interactions.PTAB.conductance]\nlaw = \"pressure-table\"\n"
          "table = [[0.0, 400.0], [20.0, 1000.0], [60.0, 1600.0]]\n",
          f);
    fclose(f);
    setenv("INTERFACIAL_CONFIG", path, 1);
    th_point_runs("uinter_", points, INCS, run_point, sizeof(final_rec), report_tally, KIND_NAMES,
                  N_KINDS);
    return fh_finish();
}
