/*
 * Compile-time check of include/interfacial.h against the ABI written down by hand in
 * docs/calling-conventions.md: every exported function is redeclared here from the document, and C
 * requires a redeclaration to be compatible with the header's ("conflicting types" otherwise),
 * so a header that drifts from the Fortran calling convention breaks the build of ALL.
 *
 * FRIC rules (abi.md): INCLUDE 'ABA_PARAM.INC' -> names I-N are default INTEGER (32-bit int),
 * everything else REAL*8 (double); every argument by reference; CHARACTER*80 CINAME, SLNAME,
 * MSNAME add three hidden lengths (size_t for gfortran >= 8) after the 39 explicit arguments.
 * Outputs and in/out arguments are plain pointers; pure inputs are const, as the header has it.
 *
 * With -DABI_PROTOTYPES_MISMATCH one type is deliberately wrong (NFDIR as a 64-bit integer, as
 * an -fdefault-integer-8 host would pass it); CTest compiles that variant and expects the
 * compiler to reject it (test c_abi_prototypes_mismatch_rejected), which proves the check bites.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "interfacial.h"

#ifdef ABI_PROTOTYPES_MISMATCH
typedef int64_t abi_nfdir_int;
#else
typedef int abi_nfdir_int;
#endif

/* INTEGER is 32-bit, REAL*8 is 64-bit, the hidden lengths are machine words (x86-64 Linux). */
_Static_assert(sizeof(int) == 4, "default INTEGER must be a 32-bit int");
_Static_assert(sizeof(double) == 8, "REAL*8 must be a 64-bit double");
_Static_assert(sizeof(size_t) == sizeof(void *), "hidden CHARACTER lengths are size_t");

/* SUBROUTINE FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,
 * DPRESS,DDPDDH,SLIP,KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,NPATCH,COORDS,
 * RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,NSTATV,CHRLNGTH,PROPS,NPROPS) */
/* Several arguments to a line, grouped by role; the numbers are the argument positions. */
void fric_(/* 1-10: LM, TAU(NFDIR) in/out; DDTDDG(NFDIR,NFDIR), DDTDDP(NFDIR), DSLIP(NFDIR),
            * SED, SFD, DDTDDT(NFDIR,2), PNEWDT out; STATEV(NSTATV) in/out */
           int *lm, double *tau, double *ddtddg, double *ddtddp, double *dslip, double *sed,
           double *sfd, double *ddtddt, double *pnewdt, double *statev,
           /* 11-16, the increment: DGAM(NFDIR), TAULM(NFDIR), PRESS, DPRESS, DDPDDH, SLIP(NFDIR) */
           const double *dgam, const double *taulm, const double *press, const double *dpress,
           const double *ddpddh, const double *slip,
           /* 17-27, when and where: KSTEP, KINC, TIME(2), DTIME, NOEL, CINAME, SLNAME, MSNAME,
            * NPT, NODE, NPATCH */
           const int *kstep, const int *kinc, const double *time, const double *dtime,
           const int *noel, const char *ciname, const char *slname, const char *msname,
           const int *npt, const int *node, const int *npatch,
           /* 28-32, the point: COORDS(MCRD), RCOORD(MCRD), DROT(2,2), TEMP(2), PREDEF(2,NPRED) */
           const double *coords, const double *rcoord, const double *drot, const double *temp,
           const double *predef,
           /* 33-39, sizes and the law: NFDIR, MCRD, NPRED, NSTATV, CHRLNGTH, PROPS(NPROPS),
            * NPROPS */
           const abi_nfdir_int *nfdir, const int *mcrd, const int *npred, const int *nstatv,
           const double *chrlngth, const double *props, const int *nprops,
           /* the hidden lengths of CINAME, SLNAME, MSNAME */
           size_t ciname_len, size_t slname_len, size_t msname_len);

/* FRIC_COEF (abi.md, current form): 16 arguments by reference + 3 hidden lengths. */
void fric_coef_(double *fcoef,            /* fCoef(nBlock,2) */
                double *fcoef_deriv,      /* fCoefDeriv(nBlock,20,2) */
                const int *nblock,        /* nBlock */
                const int *nprops,        /* nProps */
                const int *ntemp,         /* nTemp */
                const int *nfields,       /* nFields */
                const int *idata,         /* iData */
                const double *rdata,      /* rData */
                const char *surf_int,     /* surfInt */
                const char *surf_sec,     /* surfSec */
                const char *surf_main,    /* surfMain */
                const double *props,      /* props(nProps) */
                const double *slip_data,  /* slipData(nBlock,6) */
                const double *pressure,   /* pressure(nBlock) */
                const double *temp_avg,   /* tempAvg(nBlock) */
                const double *field_avg,  /* fieldAvg(nBlock,nFields) */
                size_t surf_int_len, size_t surf_sec_len, size_t surf_main_len);

const char *ifl_version(void);
const char *ifl_last_error(void);
size_t ifl_last_error_copy(char *buf, size_t len);
void ifl_clear_error(void);
enum IflStatus ifl_fric_batch(size_t npoints, size_t ld, int nfdir, const double *props,
                              int nprops, int nstatv, double dtime, int *lm, double *tau,
                              double *ddtddg, double *ddtddp, double *dslip, double *sed,
                              double *sfd, double *statev, const double *dgam,
                              const double *taulm, const double *press, const double *dpress,
                              const double *chrlngth, double *pnewdt);

/* The interface pore-pressure kernel (docs/pore-pressure.md): the variant is four ints passed
 * by value (Fortran: a bind(C) derived type of four integer(c_int), VALUE); the name either
 * NUL-terminated or with its length (the form Fortran's CHARACTER needs); outputs RESIDUAL(4),
 * TANGENT(4,4), GEOMETRIC(4). */
_Static_assert(sizeof(IflPorePressureVariant) == 4 * sizeof(int), "variant is four ints");
_Static_assert(offsetof(IflPorePressureVariant, open) == 0, "open first");
_Static_assert(offsetof(IflPorePressureVariant, steady) == sizeof(int), "steady second");
_Static_assert(offsetof(IflPorePressureVariant, finite_sliding) == 2 * sizeof(int),
               "finite_sliding third");
_Static_assert(offsetof(IflPorePressureVariant, per_side) == 3 * sizeof(int), "per_side last");
enum IflStatus ifl_pore_pressure(const char *interaction, IflPorePressureVariant variant,
                                 double p1, double p2, double q_hat, double h, double dh,
                                 double dt, double *residual, double *tangent,
                                 double *geometric);
enum IflStatus ifl_pore_pressure_n(const char *interaction, size_t interaction_len,
                                   IflPorePressureVariant variant, double p1, double p2,
                                   double q_hat, double h, double dh, double dt,
                                   double *residual, double *tangent, double *geometric);

/* VFRIC (abi.md, section "VFRIC"), double-precision build: vaba_param.inc = IMPLICIT REAL*8, so
 * every real is double and names starting I-N (nContact, jConSlvid, lContType, ...) are int;
 * 42 explicit arguments + the hidden lengths of surfInt, surfSlv, surfMst. */
void vfric_(double *fTangential, double *statev, const int *kStep, const int *kInc,
            const int *nContact, const int *nFacNod, const int *nSlvNod, const int *nMstNod,
            const int *nFricDir, const int *nDir, const int *nStateVar, const int *nProps,
            const int *nTemp, const int *nPred, const int *numDefTfv, const int *jSlvUid,
            const int *jMstUid, const int *jConSlvid, const int *jConMstid,
            const double *timStep, const double *timGlb, const double *dTimCur,
            const char *surfInt, const char *surfSlv, const char *surfMst,
            const int *lContType, const double *dSlipFric, const double *fStickForce,
            const double *fTangPrev, const double *fNormal, const double *frictionWork,
            const double *shape, const double *coordSlv, const double *coordMst,
            const double *dircosSl, const double *dircosN, const double *props,
            const double *areaSlv, const double *tempSlv, const double *preDefSlv,
            const double *tempMst, const double *preDefMst, size_t surfInt_len,
            size_t surfSlv_len, size_t surfMst_len);

/* Function-pointer types spelled out once more: assigning the library's functions to them is
 * a constraint violation if the types differ. */
typedef void fric_fn(int *, double *, double *, double *, double *, double *, double *,
                     double *, double *, double *, const double *, const double *,
                     const double *, const double *, const double *, const double *,
                     const int *, const int *, const double *, const double *, const int *,
                     const char *, const char *, const char *, const int *, const int *,
                     const int *, const double *, const double *, const double *,
                     const double *, const double *, const abi_nfdir_int *, const int *,
                     const int *, const int *, const double *, const double *, const int *,
                     size_t, size_t, size_t);

int main(void)
{
    fric_fn *const fric = fric_;
    const char *(*const version)(void) = ifl_version;
    const char *(*const last_error)(void) = ifl_last_error;
    size_t (*const error_copy)(char *, size_t) = ifl_last_error_copy;
    void (*const clear_error)(void) = ifl_clear_error;
    enum IflStatus (*const batch)(size_t, size_t, int, const double *, int, int, double, int *,
                                  double *, double *, double *, double *, double *, double *,
                                  double *, const double *, const double *, const double *,
                                  const double *, const double *, double *) = ifl_fric_batch;
    enum IflStatus (*const pore)(const char *, IflPorePressureVariant, double, double, double,
                                 double, double, double, double *, double *,
                                 double *) = ifl_pore_pressure;
    enum IflStatus (*const pore_n)(const char *, size_t, IflPorePressureVariant, double, double,
                                   double, double, double, double, double *, double *,
                                   double *) = ifl_pore_pressure_n;
    int passed = 0, failed = 0;

    /* Linked and callable through the hand-written types. */
    if (fric != NULL && version != NULL && last_error != NULL && error_copy != NULL &&
        clear_error != NULL && batch != NULL && pore != NULL && pore_n != NULL) {
        passed++;
    } else {
        failed++;
    }
    if (version() != NULL && strlen(version()) > 0) {
        passed++;
    } else {
        failed++;
    }
    /* Both name forms through the hand-written types, on a name without a NUL in its 7 bytes:
     * closed, transient, small sliding, p_mean = 2, p_jump = 1, q_hat = 0.5, dt = 0.25 give
     * residual -(p_mean, 0, dt q_hat, dt p_jump) (seed 000, closed contact). */
    {
        const char name[7] = {'c', 'o', 'l', 'u', 'm', 'n', ' '};
        const IflPorePressureVariant closed = {0, 0, 0, 0};
        const double want[4] = {-2.0, 0.0, -0.125, -0.25};
        double r[4], t[16], g[4], rn[4], tn[16], gn[4];
        int same = 1;
        int i;
        enum IflStatus s = pore("column", closed, 3.0, 1.0, 0.5, 0.0, 0.0, 0.25, r, t, g);
        enum IflStatus sn =
            pore_n(name, sizeof name, closed, 3.0, 1.0, 0.5, 0.0, 0.0, 0.25, rn, tn, gn);
        for (i = 0; i < 4; i++) {
            same = same && r[i] == want[i] && rn[i] == want[i];
        }
        if (s == IFL_STATUS_OK && sn == IFL_STATUS_OK && same) {
            passed++;
        } else {
            failed++;
        }
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
