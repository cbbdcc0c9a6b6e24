/* lighting_private.h - the lighting layer's internals (never installed): the luminaire readers
 * and the near-field integration over a luminous opening shared by grids and scenes. */
#ifndef LX_LIGHTING_PRIVATE_H
#define LX_LIGHTING_PRIVATE_H

#include "spectral/spectral_private.h"

/* The default relative tolerance of the near field (grids; the near_field flag of disk and rect). */
#define LX__NEARFIELD_TOL 1e-4

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
 * 8, ... n_max; returns (4 S(n) - S(n/2)) / 3 once the last change of the extrapolation and a
 * quarter of the change before it are within tol relative (n >= 8; at n = 4 the change is taken
 * from S(2)), else the last one. *cells (may be NULL) adds the cells evaluated; *converged
 * (may be NULL) 1 when the tolerance was met. */
double lx__area_refine(double (*mean)(void *arg, int n), void *arg, int circular, double tol, int n_max,
                       unsigned long long *cells, int *converged);

/* The point model's error on one luminaire-receiver pair (nearfield.c; grids and scenes). g(arg,
 * a, b): the illuminance at the receiver of the whole luminaire moved to offset (a, b) along the
 * opening's axes (the point model is g(arg, 0, 0)). The opening: a rectangle w x l, or a disk of
 * diameter w when circular. dist: centre to receiver; faces: lx__nf_faces for the pair. */
typedef double (*lx__nf_fn)(void *arg, double a, double b);
typedef struct lx__nf_probe {
    double point; /* the point model, g(0, 0) */
    double best;  /* a fourth-order area rule over the opening (the better estimate) */
    double err;   /* the point model's estimated absolute error */
    int unsure;   /* 1: the probes cannot vouch for the estimate (the opening straddles a zero of the
                   * integrand, or the receiver is closer than the opening's size): integrate */
    int zero;     /* 1: the receiver faces away from the whole opening, so both models give 0 */
} lx__nf_probe;
void lx__nf_probe_pair(lx__nf_fn g, void *arg, int circular, double w, double l, double dist, int faces,
                       lx__nf_probe *out);
/* 1 when the receiver at q with unit normal n faces some point of the opening (pos, axes ex, ey,
 * w x l, or a disk of diameter w). */
int lx__nf_faces(const double pos[3], const double ex[3], const double ey[3], int circular, double w, double l,
                 const double q[3], const double n[3]);
/* The k pairs of one receiver point with their probes: near[i] = 0 for the pairs that take the
 * point model, 1 for those to integrate. Zero pairs take the point model; unsure ones never;
 * the others, smallest estimated error first, while the sum of their estimated errors stays
 * within tol / 2 of E_point (the point model's illuminance of every luminaire at the point).
 * order: k indices of scratch. Returns the number of point-model pairs. */
size_t lx__nf_decide(size_t k, const lx__nf_probe *pr, double E_point, double tol, unsigned char *near, size_t *order);

/* Illuminance (lx) at q on a receiver with unit normal n from a Lambertian source of luminance L
 * centred at c with unit axes ex, ey and unit emitting normal m (area_exact.c): a rectangle w
 * (along ex) x l (along ey), or a disk of radius R. Exact for any orientation: Lambert's contour
 * form over the part above the receiver's horizon (the rectangle in closed form; the disk's arc by
 * adaptive Gauss-Kronrod to 1e-14 relative, *evals (may be NULL) adds its integrand evaluations).
 * 0 when the receiver is behind the emitter or the source below its horizon. */
double lx__lambert_rect_E(double L, const double c[3], const double ex[3], const double ey[3], const double m[3],
                          double w, double l, const double q[3], const double n[3]);
double lx__lambert_disk_E(double L, const double c[3], const double ex[3], const double ey[3], const double m[3],
                          double R, const double q[3], const double n[3], long *evals);

#endif /* LX_LIGHTING_PRIVATE_H */
