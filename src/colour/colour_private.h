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

#endif /* LX_COLOUR_PRIVATE_H */
