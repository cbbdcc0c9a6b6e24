/* lighting_private.h - the lighting layer's internals (never installed): the luminaire readers
 * and the near-field integration over a luminous opening shared by grids and scenes. */
#ifndef LX_LIGHTING_PRIVATE_H
#define LX_LIGHTING_PRIVATE_H

#include "spectral/spectral_private.h"

/* The readers behind lx_luminaire_read_mem: LM-63 (any version) and EULUMDAT. */
lx_status lx__ies_read(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_luminaire **out);
lx_status lx__ldt_read(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_luminaire **out);
/* Validates the stored table of a freshly read luminaire (angles in order and complete for its
 * type, candela >= 0), sets its symmetry and expands it (full arrays). line_h / line_v: the lines
 * of the horizontal and vertical angle lists for messages. */
lx_status lx__lum_finish(lx_ctx *ctx, lx_luminaire *lum, long line_h, long line_v, long line_cd);
/* A luminaire with every field zero / NaN where that means "unknown" (NULL on no memory). */
lx_luminaire *lx__lum_new(const char *file);

/* Near-field integration over a luminous opening (grid.c; used by scenes too).
 * The n-level midpoint cells of an opening centred at the origin: a rectangle w x l in n x n cells,
 * a disk of diameter w in n rings of equal area x 2n sectors; every cell carries 1 / cells of the
 * area; cell c has its centre at (*a, *b) along the opening's axes. */
size_t lx__area_cells(int circular, int n);
void lx__area_cell(int circular, double w, double l, int n, size_t c, double *a, double *b);
/* Richardson-refined midpoint rule: mean(arg, n) (the mean over the n-level cells) for n = 2, 4,
 * 8, ... n_max; returns (4 S(n) - S(n/2)) / 3 once two successive extrapolations agree within tol
 * relative (n >= 8), else the last one. *cells (may be NULL) adds the cells evaluated; *converged
 * (may be NULL) 1 when the tolerance was met. */
double lx__area_refine(double (*mean)(void *arg, int n), void *arg, int circular, double tol, int n_max,
                       unsigned long long *cells, int *converged);

#endif /* LX_LIGHTING_PRIVATE_H */
