/*
 * test_pore_pressure.c: steady seepage through two porous layers joined by the interface
 * pore-pressure kernel (ifl_pore_pressure, seed 000), driven step by step as a C host would:
 * linear pressure elements in each layer, the kernel's residual and tangent assembled at the
 * interface node pair (unknowns p1, p2 and q_hat), one Newton iteration per step while the top
 * pressure ramps up. Closed form: q = (p_top - p_base)/(L1/k1 + L2/k2), linear pressure in each
 * layer, p1 = p2, and the flux across the interface q_hat/2 = q (docs/pore-pressure.md).
 * Also: the kernel's outputs against the seed's formula, and a refused call.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"

enum { NE = 4, NP = 2 * (NE + 1), N = NP + 1, QHAT = NP };

static const double L1 = 1.0, L2 = 2.0, K1 = 1e-3, K2 = 1e-4, P_BASE = 0.0;

/* Dense solve with partial pivoting; returns 0 on a zero pivot. */
static int solve(double a[N][N], double b[N])
{
    for (int k = 0; k < N; k++) {
        int p = k;
        for (int i = k + 1; i < N; i++) {
            if (fabs(a[i][k]) > fabs(a[p][k])) {
                p = i;
            }
        }
        if (a[p][k] == 0.0) {
            return 0;
        }
        for (int j = 0; j < N; j++) {
            double t = a[k][j];
            a[k][j] = a[p][j];
            a[p][j] = t;
        }
        double t = b[k];
        b[k] = b[p];
        b[p] = t;
        for (int i = k + 1; i < N; i++) {
            double l = a[i][k] / a[k][k];
            for (int j = k; j < N; j++) {
                a[i][j] -= l * a[k][j];
            }
            b[i] -= l * b[k];
        }
    }
    for (int k = N - 1; k >= 0; k--) {
        double s = b[k];
        for (int j = k + 1; j < N; j++) {
            s -= a[k][j] * b[j];
        }
        b[k] = s / a[k][k];
    }
    return 1;
}

/* Residual R(x) and tangent K = dR/dx of the steady host; p_top held at node 0. */
static int assemble(const double x[N], double p_top, double r[N], double k[N][N])
{
    memset(r, 0, sizeof(double) * N);
    memset(k, 0, sizeof(double) * N * N);
    for (int layer = 0; layer < 2; layer++) {
        double len = (layer == 0 ? L1 : L2) / NE, perm = layer == 0 ? K1 : K2;
        for (int e = 0; e < NE; e++) {
            int a = layer * (NE + 1) + e, b = a + 1;
            /* -int k p' dp' (the continuity equation times -1, rate form). */
            double c = perm / len, f = -c * (x[a] - x[b]);
            r[a] += f;
            r[b] -= f;
            k[a][a] -= c;
            k[a][b] += c;
            k[b][a] += c;
            k[b][b] -= c;
        }
    }
    /* The interface point: side 1 = last node of layer 1, side 2 = first node of layer 2;
     * steady, closed, small sliding, per-side unknowns (h, p1, p2, q_hat). */
    IflPorePressureVariant v = {0, 1, 0, 1};
    double kr[4], kt[16], kg[4];
    int dof[4] = {-1, NE, NE + 1, QHAT};
    IflStatus s = ifl_pore_pressure("seepage", v, x[NE], x[NE + 1], x[QHAT], 0.0, 0.0, 0.0, kr,
                                    kt, kg);
    if (!FH_CHECK(s == IFL_STATUS_OK)) {
        return 0;
    }
    for (int i = 1; i < 4; i++) {
        r[dof[i]] += kr[i];
        FH_EXACT(kg[i], 0.0); /* small sliding: no geometric terms */
        for (int j = 1; j < 4; j++) {
            k[dof[i]][dof[j]] += kt[i + 4 * j]; /* TANGENT(i,j), column-major */
        }
    }
    /* Dirichlet rows: p_top at node 0, P_BASE at the last node. */
    int fixed[2] = {0, NP - 1};
    double value[2] = {p_top, P_BASE};
    for (int i = 0; i < 2; i++) {
        memset(k[fixed[i]], 0, sizeof(double) * N);
        k[fixed[i]][fixed[i]] = 1.0;
        r[fixed[i]] = x[fixed[i]] - value[i];
    }
    return 1;
}

static void seepage(void)
{
    double x[N] = {0}, r[N], k[N][N];
    for (int step = 1; step <= 5; step++) {
        double p_top = 20.0 * step;
        fh_context("steady seepage, step %d, p_top %g", step, p_top);
        if (!assemble(x, p_top, r, k) || !FH_CHECK(solve(k, r))) {
            return;
        }
        for (int i = 0; i < N; i++) {
            x[i] -= r[i];
        }
        double q = (p_top - P_BASE) / (L1 / K1 + L2 / K2);
        double p_i = p_top - q * L1 / K1;
        FH_NEAR(0.5 * x[QHAT], q, 1e-12, 0.0);
        FH_NEAR(x[NE], p_i, 1e-12, 1e-12 * p_top);
        FH_NEAR(x[NE + 1], p_i, 1e-12, 1e-12 * p_top);
        for (int layer = 0; layer < 2; layer++) {
            double len = (layer == 0 ? L1 : L2) / NE, perm = layer == 0 ? K1 : K2;
            for (int n = 0; n <= NE; n++) {
                double top = layer == 0 ? p_top : p_i;
                FH_NEAR(x[layer * (NE + 1) + n], top - q * n * len / perm, 0.0, 1e-12 * p_top);
            }
        }
        /* The residual after the Newton update vanishes: the kernel's tangent is consistent. */
        if (assemble(x, p_top, r, k)) {
            double worst = 0.0;
            for (int i = 0; i < N; i++) {
                worst = fmax(worst, fabs(r[i]));
            }
            FH_NEAR(worst, 0.0, 0.0, 1e-14 * p_top);
        }
    }
}

static void kernel_values(void)
{
    fh_context("kernel values, open transient finite sliding, (h, pbar, phat, qhat)");
    IflPorePressureVariant v = {1, 0, 1, 0};
    double r[4], t[16], g[4];
    double p1 = 130.0, p2 = 70.0, q = -2.5e-3, dh = 1.5e-4, dt = 0.8;
    FH_CHECK(ifl_pore_pressure(NULL, v, p1, p2, q, 4e-4, dh, dt, r, t, g) == IFL_STATUS_OK);
    /* dPi = -[dh dpbar + pbar dh + dt (qhat dphat + phat dqhat)], pbar = 100, phat = 30. */
    FH_EXACT(r[0], -100.0);
    FH_EXACT(r[1], -dh);
    FH_EXACT(r[2], -dt * q);
    FH_EXACT(r[3], -dt * 30.0);
    for (int i = 0; i < 4; i++) {
        FH_EXACT(g[i], r[i]);
        for (int j = 0; j < 4; j++) {
            double want = 0.0;
            if ((i == 0 && j == 1) || (i == 1 && j == 0)) {
                want = -1.0;
            } else if ((i == 2 && j == 3) || (i == 3 && j == 2)) {
                want = -dt;
            }
            FH_EXACT(t[i + 4 * j], want);
        }
    }
    fh_context("refused: transient with dt = 0");
    IflStatus s = ifl_pore_pressure("seepage", v, p1, p2, q, 0.0, dh, 0.0, r, t, g);
    FH_CHECK(s == IFL_STATUS_BAD_INPUT);
    FH_CONTAINS(ifl_last_error(), "ifl_pore_pressure");
    FH_CONTAINS(ifl_last_error(), "'seepage'");
    FH_CONTAINS(ifl_last_error(), "dt = 0");
    for (int i = 0; i < 4; i++) {
        FH_EXACT(r[i], 0.0);
    }
    fh_context("refused: flag 3");
    IflPorePressureVariant bad = {3, 0, 0, 0};
    FH_CHECK(ifl_pore_pressure(NULL, bad, 1, 1, 0, 0, 0, 1, r, t, g) == IFL_STATUS_BAD_PARAMETER);
    FH_CONTAINS(ifl_last_error(), "variant.open = 3");
}

int main(void)
{
    seepage();
    kernel_values();
    return fh_finish();
}
