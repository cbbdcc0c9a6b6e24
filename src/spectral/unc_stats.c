/* unc_stats.c - the statistics of Monte Carlo trials (JCGM 101): the estimate and standard
 * uncertainty of a quantity's values, the probabilistically symmetric or shortest coverage interval
 * from order statistics (7.7), and the numerical tolerance of a standard uncertainty (7.9.2). */
#include "spectral/unc_stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The k-th smallest (from 0) of a[0 .. n) (a is reordered): Wirth's selection (Hoare's partition
 * around a[k]), expected O(n). */
static double select_k(double *a, size_t n, size_t k)
{
    long l = 0, m = (long)n - 1, kk = (long)k;
    while (l < m) {
        double x = a[kk];
        long i = l, j = m;
        do {
            while (a[i] < x) i++;
            while (x < a[j]) j--;
            if (i <= j) {
                double t = a[i];
                a[i] = a[j], a[j] = t;
                i++, j--;
            }
        } while (i <= j);
        if (j < kk) l = i;
        if (kk < i) m = j;
    }
    return a[kk];
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int lx__unc_stats(const double *v, size_t n, double p, int shortest, double *tmp, lx__unc_stat *out)
{
    size_t m = 0;
    double sum = 0.0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(v[i])) tmp[m++] = v[i], sum += v[i];
    out->n = m;
    out->undefined = n ? (double)(n - m) / (double)n : 0.0;
    out->mean = out->u = out->lo = out->hi = NAN;
    if (m == 0) return 0;
    double mean = sum / (double)m, ss = 0.0, c = 0.0;
    for (size_t i = 0; i < m; i++) {
        double d = tmp[i] - mean;
        ss += d * d, c += d;
    }
    mean += c / (double)m; /* the second pass corrects the first's rounding */
    out->mean = mean;
    out->u = m > 1 ? sqrt((ss - c * c / (double)m) / (double)(m - 1)) : 0.0;
    /* JCGM 101 7.7.1: q = pM when an integer, else the integer part of pM + 1/2 */
    double pm = p * (double)m;
    size_t q = fabs(pm - nearbyint(pm)) < 1e-9 ? (size_t)nearbyint(pm) : (size_t)floor(pm + 0.5);
    if (q < 1) q = 1;
    if (q > m) q = m;
    if (shortest) { /* 7.7.3: the shortest of the intervals [y_(r), y_(r+q-1)] */
        qsort(tmp, m, sizeof *tmp, cmp_double);
        size_t best = 0;
        for (size_t r = 0; r + q - 1 < m; r++)
            if (tmp[r + q - 1] - tmp[r] < tmp[best + q - 1] - tmp[best]) best = r;
        out->lo = tmp[best], out->hi = tmp[best + q - 1];
        return 1;
    }
    /* 7.7.2: r = (M - q) / 2 when an integer, else (M - q + 1) / 2; [y_(r), y_(r+q)], 1-based
     * (r = 0 for q = M: the whole range) */
    size_t r = (m - q) % 2 == 0 ? (m - q) / 2 : (m - q + 1) / 2;
    size_t lo = r > 0 ? r - 1 : 0, hi = r + q > 0 ? r + q - 1 : 0;
    if (hi >= m) hi = m - 1;
    out->lo = select_k(tmp, m, lo);
    out->hi = select_k(tmp, m, hi);
    return 1;
}

double lx__unc_tolerance(double u, double y, int digits)
{
    double floor_rel = 1e-12 * fabs(y);
    if (!(u > 0) || !isfinite(u)) return floor_rel;
    double l = floor(log10(u)) - (digits - 1);
    double d = 0.5 * pow(10.0, l);
    /* u = c 10^l with c of `digits` digits: log10 can land a hair low at an exact power of ten */
    if (u / pow(10.0, l) >= pow(10.0, digits)) d *= 10.0;
    return d > floor_rel ? d : floor_rel;
}
