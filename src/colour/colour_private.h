/* colour_private.h - the colour-quality layer's internals (never installed): the common spectral
 * quadrature of CRI and TM-30 and its sampling. */
#ifndef LX_COLOUR_PRIVATE_H
#define LX_COLOUR_PRIVATE_H

#include "spectral/spectral_private.h"

/* The colour-quality quadrature of a spectrum over [start, end] nm (the integrals of CRI and TM-30
 * are weighted sums sum_i w[i] f(lam[i])), chosen as the headline colorimetry integrates
 * (lx_method_resolve with AUTO):
 * - CIE15 (data uniformly sampled at 1 or 5 nm on whole nm): the CIE 13.3 / CIE 224 sums at 5 nm
 *   (data on multiples of 5 nm) or 1 nm, w = the step;
 * - EXACT (any other data, line spectra): the breakpoints of the data and of the 1 nm tables merged;
 *   on each interval the spectrum and every table (CMFs, test and evaluation samples) are linear,
 *   so their products of up to three are cubics, integrated exactly by Simpson's rule (nodes at the
 *   breakpoints and midpoints). Smooth functions sampled on the nodes (Planck, CIE daylight) are
 *   integrated to O(h^4) with h <= 1 nm. */
typedef struct lx__qgrid {
    size_t n;
    double *lam, *w; /* n nodes and their weights (nm) */
    int exact;       /* 1: the EXACT quadrature */
} lx__qgrid;
lx_status lx__qgrid_make(lx_ctx *ctx, const lx_spd *spd, double start_nm, double end_nm, lx__qgrid *g);
void lx__qgrid_free(lx__qgrid *g);
/* Samples spd (piecewise linear, zero outside) or table column col at the grid's nodes. */
void lx__quality_sample(const lx_spd *spd, const lx__qgrid *g, double *out);
void lx__quality_table(const lx__table *t, int col, const lx__qgrid *g, double *out);
/* The fraction (max over X, Y, Z with the 2 deg CMFs) of the grid spectrum ref that lies
 * outside [lo_nm, hi_nm]. */
double lx__quality_outside(const double *ref, const lx__qgrid *g, double lo_nm, double hi_nm);
/* The reference illuminant of CIE 224 / TM-30 at T (Planckian, CIE daylight, or their Y-normalised
 * mix between 4000 and 5000 K) at 380, 381, ..., 780 nm (for the report's SPD panel). */
lx_status lx__tm30_reference_1nm(lx_ctx *ctx, double T, double ref[401]);

/* ---- CIE 13.3 in pieces (cri.c), for lx_cri_compute and the uncertainty engine ---- */
#define LX__CRI_NTCS 15 /* TCS01-TCS14 of CIE 13.3, then No. 15 of JIS Z 8726 (R15) */
#define LX__CRI_NINT (3 * (LX__CRI_NTCS + 1))
/* The grid of a spectrum (360-830 nm) with the 2 deg CMFs (3 n) and the 15 samples (15 n) on it. */
typedef struct lx__cri_grid {
    lx__qgrid g;
    double *cmf, *tcs;
} lx__cri_grid;
lx_status lx__cri_grid_make(lx_ctx *ctx, const lx_spd *spd, lx__cri_grid *cg);
void lx__cri_grid_free(lx__cri_grid *cg);
/* The LX__CRI_NINT integrals of an illuminant sampled on the grid: [0 .. 2] its X, Y, Z, [3 + 3 s
 * + c] those of sample s (CIE 13.3's sums). */
void lx__cri_integrals(const lx__cri_grid *cg, const double *illum, double *L);
/* 1 when a CCT and Duv allow a CIE 13.3 reference (|Duv| <= 0.05, at most 25000 K). */
int lx__cri_ok(double T, double duv);
/* The reference illuminant at T on the grid: Planck below 5000 K, CIE daylight from 5000 K. */
lx_status lx__cri_reference(lx_ctx *ctx, const lx__cri_grid *cg, double T, double *ref);
/* LX_ERANGE when more than 1 % of the reference's X, Y or Z lies outside the spectrum's range. */
lx_status lx__cri_outside(lx_ctx *ctx, const lx__cri_grid *cg, const lx_spd *spd, const double *ref);
/* R1 .. R14, R15, Ra, dc of the test integrals Lt against the reference's Lr (CCT T, Duv duv). */
void lx__cri_indices(const double *Lt, const double *Lr, double T, double duv, lx_cri *out);

/* ---- CIE 224 / TM-30 in pieces (tm30.c) ---- */
#define LX__TM30_NCES 99
#define LX__TM30_NINT (6 + 3 * LX__TM30_NCES)
/* The grid (380-780 nm) with the 99 samples, the 10 deg and 2 deg CMFs and 3 n of scratch. */
typedef struct lx__tm30_grid {
    lx__qgrid g;
    double *ces, *cmf10, *cmf2, *scratch;
} lx__tm30_grid;
lx_status lx__tm30_grid_make(lx_ctx *ctx, const lx_spd *spd, lx__tm30_grid *tg);
void lx__tm30_grid_free(lx__tm30_grid *tg);
/* The LX__TM30_NINT integrals of an illuminant on the grid: [0 .. 2] its 2 deg X, Y, Z (the CCT),
 * [3 .. 5] its 10 deg ones, [6 + 3 s + c] sample s's (10 deg); p: 3 n of scratch. */
void lx__tm30_integrals(const lx__tm30_grid *tg, const double *illum, double *L, double *p);
int lx__tm30_ok(double T, double duv);
/* The reference at T on the grid (tmp: n of scratch). */
lx_status lx__tm30_reference(lx_ctx *ctx, const lx__tm30_grid *tg, double T, double *ref, double *tmp);
lx_status lx__tm30_outside(lx_ctx *ctx, const lx__tm30_grid *tg, const lx_spd *spd, const double *ref);
/* Rf, Rg and the bins from the test and reference integrals. */
void lx__tm30_indices(const double *Lt, const double *Lr, double T, double duv, lx_tm30 *out);

#endif /* LX_COLOUR_PRIVATE_H */
