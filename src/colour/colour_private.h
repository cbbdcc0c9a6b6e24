/* colour_private.h - the colour-quality layer's internals (never installed): the common spectral
 * grid of CRI and TM-30 and its sampling. */
#ifndef LX_COLOUR_PRIVATE_H
#define LX_COLOUR_PRIVATE_H

#include "spectral/spectral_private.h"

/* The colour-quality grid for spd: step 5 nm for data uniformly sampled at 5 nm on multiples
 * of 5 nm, else 1 nm. */
double lx__quality_step(const lx_spd *spd);
/* Samples spd on the grid start_nm + i*step_nm, i < n (piecewise linear, zero outside). */
void lx__quality_sample(const lx_spd *spd, double start_nm, double step_nm, int n, double *out);
/* Samples table column col (linear interpolation, zero outside) on the same kind of grid. */
void lx__quality_table(const lx__table *t, int col, double start_nm, double step_nm, int n, double *out);
/* The fraction (max over X, Y, Z with the 2 deg CMFs) of the grid spectrum ref that lies
 * outside [lo_nm, hi_nm]. */
double lx__quality_outside(const double *ref, double start_nm, double step_nm, int n, double lo_nm, double hi_nm);

#endif /* LX_COLOUR_PRIVATE_H */
