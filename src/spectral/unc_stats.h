/* unc_stats.h - the Monte Carlo statistics of unc_stats.c (JCGM 101 7.6, 7.7, 7.9.2). */
#ifndef LX_UNC_STATS_H
#define LX_UNC_STATS_H

#include "spectral/unc_private.h"

typedef struct lx__unc_stat {
    size_t n;          /* finite values */
    double undefined;  /* fraction of the values that are not finite */
    double mean, u;    /* average and standard deviation (7.6) */
    double lo, hi;     /* coverage interval (7.7) */
} lx__unc_stat;

/* The statistics of v[0 .. n) at coverage probability p (shortest: 7.7.3, else the
 * probabilistically symmetric interval of 7.7.2); tmp holds n doubles. Returns 0 when no value is
 * finite (all NaN). */
int lx__unc_stats(const double *v, size_t n, double p, int shortest, double *tmp, lx__unc_stat *out);
/* The numerical tolerance of a standard uncertainty u (7.9.2): u written as c 10^l with c an integer
 * of `digits` digits, delta = 10^l / 2; never below 1e-12 |y| (a spread that small is rounding). */
double lx__unc_tolerance(double u, double y, int digits);

#endif /* LX_UNC_STATS_H */
