/*
 * A hand-written C version of the interface pore-pressure kernel's closed-contact,
 * small-sliding, transient form (seed 000): the reference that bench_pore_pressure.c times
 * ifl_pore_pressure against. Same validation (finite inputs, dt > 0), same outputs and layout:
 * residual (h, pbar, phat, qhat), column-major 4x4 tangent, geometric terms (zero).
 * Compiled as its own translation unit so that it is a real call, as the library's is.
 */
#include <math.h>
#include <string.h>

int ref_pore_pressure_closed_small(double p1, double p2, double q_hat, double h, double dh,
                                   double dt, double residual[4], double tangent[16],
                                   double geometric[4])
{
    if (!(isfinite(p1) && isfinite(p2) && isfinite(q_hat) && isfinite(h) && isfinite(dh) &&
          isfinite(dt)) ||
        !(dt > 0.0)) {
        for (int i = 0; i < 4; i++) {
            residual[i] = 0.0;
            geometric[i] = 0.0;
        }
        for (int i = 0; i < 16; i++) {
            tangent[i] = 0.0;
        }
        return 2;
    }
    double p_mean = 0.5 * p1 + 0.5 * p2, p_jump = 0.5 * p1 - 0.5 * p2;
    residual[0] = -p_mean;
    residual[1] = 0.0;
    residual[2] = -dt * q_hat;
    residual[3] = -dt * p_jump;
    if (!(isfinite(residual[2]) && isfinite(residual[3]))) {
        return 3;
    }
    /* Every entry stored once, column-major TANGENT(i,j) at i + 4j (a zeroing loop or a local
     * array compiles to `rep stos`, whose start-up alone costs more than the whole kernel). */
    tangent[0] = 0.0; /* column h: d r / d h = 0 (closed contact) */
    tangent[1] = 0.0;
    tangent[2] = 0.0;
    tangent[3] = 0.0;
    tangent[4] = -1.0; /* column pbar: d r_h / d pbar = -1 */
    tangent[5] = 0.0;
    tangent[6] = 0.0;
    tangent[7] = 0.0;
    tangent[8] = 0.0; /* column phat: d r_qhat / d phat = -dt */
    tangent[9] = 0.0;
    tangent[10] = 0.0;
    tangent[11] = -dt;
    tangent[12] = 0.0; /* column qhat: d r_phat / d qhat = -dt */
    tangent[13] = 0.0;
    tangent[14] = -dt;
    tangent[15] = 0.0;
    static const double zero4[4] = {0.0, 0.0, 0.0, 0.0};
    memcpy(geometric, zero4, sizeof zero4);
    return 0;
}
