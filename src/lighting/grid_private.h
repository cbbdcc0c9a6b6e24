/* grid_private.h - what grid.c and grid_simd.c share: a placed luminaire prepared for one
 * computation, the cosine-indexed table lookup (the CPU twin of kernels/grid.cl) and the block
 * routine that adds one luminaire's point-model illuminance to a block of points. */
#ifndef LX_GRID_PRIVATE_H
#define LX_GRID_PRIVATE_H

#include "lighting/lighting_private.h"

#include <math.h>
#include <stddef.h>

/* Per-luminaire data of one computation. */
typedef struct lx__plum {
    const lx_luminaire *lum;
    double pos[3], ex[3], ey[3], ez[3];
    double scale;       /* tilt factor x maintenance factor */
    double size_m;      /* largest dimension of the luminous opening (0: a point) */
    int circular;
    double w, l;        /* opening along ex and ey (circular: w = l = the diameter) */
    const float *table; /* LX_INTERP_TABLE: rows x cols */
    int ns, nq, cols;   /* table: rows per hemisphere - 1, columns per quadrant (0: axial), columns */
    size_t toff;        /* offset of the table in the shared table array */
    const double *pair; /* axial tables: per row (value, next row's value - value) in double, 16-byte
                         * aligned, in the table's allocation (the SIMD loops: one 16-byte load a point);
                         * NULL otherwise */
} lx__plum;

/* The table lookup in local coordinates (x, y, z) at distance d (the CPU twin of grid.cl).
 * Row r of hemisphere h (0: below, z <= 0) is at sqrt(1 - |cos g|) = r / ns; column k at
 * diamond angle 4 k / cols. */
static inline double lx__table_eval(const lx__plum *p, double x, double y, double z, double d)
{
    /* 1 - |cos g| = (d - |z|) / d = (x^2 + y^2) / (d (d + |z|)): no cancellation near the poles */
    int h = z > 0;
    double t = (double)p->ns * sqrt((x * x + y * y) / (d * (d + fabs(z))));
    if (t > p->ns) t = p->ns;
    int r = (int)t;
    if (r > p->ns - 1) r = p->ns - 1;
    double fr = t - r;
    const float *row = p->table + ((size_t)h * (p->ns + 1) + r) * p->cols;
    if (p->cols == 1) return row[0] + fr * (row[1] - row[0]);
    double ax = fabs(x), ay = fabs(y), s = ax + ay, q;
    if (s > 0) {
        /* diamond angle in [0, 4) */
        if (y >= 0) q = x >= 0 ? y / s : 1 + ax / s;
        else q = x < 0 ? 2 + ay / s : 3 + ax / s;
    } else {
        q = 0;
    }
    double tc = q * p->nq;
    int k = (int)tc;
    if (k > p->cols - 2) k = p->cols - 2;
    double fc = tc - k;
    const float *a = row + k, *b = row + p->cols + k;
    double va = a[0] + fc * (a[1] - a[0]);
    double vb = b[0] + fc * (b[1] - b[0]);
    return va + fr * (vb - va);
}

/* Adds to acc[i] (i < nb) the point-model illuminance of luminaire p through its table at the
 * points (x[i], y[i], z[i]) with normals (nx, ny, nz)[i], or nx[0], ny[0], nz[0] for all when
 * shared. simd (from lx__grid_simd): 2 runs AVX-512 (8 points at a time), 1 AVX2 + FMA (4 at a
 * time), 0 plain C; they agree to rounding (FMA). Thread-safe. */
void lx__grid_table_block(const lx__plum *p, size_t nb, const double *x, const double *y, const double *z,
                          const double *nx, const double *ny, const double *nz, int shared, int simd, double *acc);

/* The SIMD path of the table loop: lx_simd_level() (0 scalar, 1 AVX2, 2 AVX-512). */
int lx__grid_simd(void);

#endif /* LX_GRID_PRIVATE_H */
