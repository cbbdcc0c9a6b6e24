/* unc_linalg.c - the linear algebra of the uncertainty engine: the eigenvalues of a symmetric
 * matrix (the positive semi-definite check of a covariance), the pivoted Cholesky factor of a
 * covariance (the draws of its normal part), and the quantile of the normal distribution (the GUM
 * coverage factor). */
#include "spectral/unc_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Householder reduction of the symmetric a (n x n, overwritten) to tridiagonal form: diagonal d,
 * subdiagonal e (e[i] between rows i and i + 1; e[n - 1] = 0). */
static void tridiagonalise(size_t n, double *a, double *d, double *e, double *v, double *p)
{
    for (size_t k = 0; k + 2 < n; k++) {
        size_t m = n - k - 1; /* the trailing block, rows and columns k + 1 .. n - 1 */
        double norm = 0.0;
        for (size_t i = 0; i < m; i++) norm = hypot(norm, a[(k + 1 + i) * n + k]);
        double x0 = a[(k + 1) * n + k];
        double alpha = x0 > 0 ? -norm : norm;
        d[k] = a[k * n + k];
        e[k] = alpha;
        if (norm == 0.0) continue;
        for (size_t i = 0; i < m; i++) v[i] = a[(k + 1 + i) * n + k];
        v[0] -= alpha;
        double vn = 0.0;
        for (size_t i = 0; i < m; i++) vn = hypot(vn, v[i]);
        if (vn == 0.0) continue;
        for (size_t i = 0; i < m; i++) v[i] /= vn;
        /* B <- H B H with H = I - 2 v v^T: p = B v, w = p - (v.p) v, B <- B - 2 v w^T - 2 w v^T */
        double vp = 0.0;
        for (size_t i = 0; i < m; i++) {
            const double *row = a + (k + 1 + i) * n + k + 1;
            double s = 0.0;
            for (size_t j = 0; j < m; j++) s += row[j] * v[j];
            p[i] = s;
            vp += v[i] * s;
        }
        for (size_t i = 0; i < m; i++) p[i] -= vp * v[i];
        for (size_t i = 0; i < m; i++) {
            double *row = a + (k + 1 + i) * n + k + 1;
            for (size_t j = 0; j < m; j++) row[j] -= 2.0 * (v[i] * p[j] + p[i] * v[j]);
        }
    }
    if (n >= 2) {
        d[n - 2] = a[(n - 2) * n + n - 2];
        e[n - 2] = a[(n - 1) * n + n - 2];
    }
    d[n - 1] = a[(n - 1) * n + n - 1];
    e[n - 1] = 0.0;
}

/* The eigenvalues of the symmetric tridiagonal (d, e) into d by the QL method with implicit
 * Wilkinson shifts. Returns 0, or -1 when an eigenvalue takes more than 60 iterations. */
static int tridiagonal_ql(size_t n, double *d, double *e)
{
    double norm = 0.0; /* a zero eigenvalue's neighbours converge to the matrix's scale, not to 0 */
    for (size_t i = 0; i < n; i++) norm = fmax(norm, fabs(d[i]) + fabs(e[i]));
    for (size_t l = 0; l < n; l++) {
        int iter = 0;
        size_t m;
        for (;;) {
            for (m = l; m + 1 < n; m++) {
                double dd = fabs(d[m]) + fabs(d[m + 1]);
                if (fabs(e[m]) <= 1e-16 * dd || fabs(e[m]) <= 1e-300 + 4e-16 * norm) break;
            }
            if (m == l) break;
            if (iter++ == 60) return -1;
            double g = (d[l + 1] - d[l]) / (2.0 * e[l]);
            double r = hypot(g, 1.0);
            g = d[m] - d[l] + e[l] / (g + (g >= 0 ? r : -r));
            double s = 1.0, c = 1.0, p = 0.0;
            int deflated = 0;
            for (size_t i = m; i-- > l;) {
                double f = s * e[i], b = c * e[i];
                r = hypot(f, g);
                e[i + 1] = r;
                if (r == 0.0) {
                    d[i + 1] -= p;
                    e[m] = 0.0;
                    deflated = 1;
                    break;
                }
                s = f / r;
                c = g / r;
                g = d[i + 1] - p;
                r = (d[i] - g) * s + 2.0 * c * b;
                p = s * r;
                d[i + 1] = g + p;
                g = c * r - b;
            }
            if (deflated) continue;
            d[l] -= p;
            e[l] = g;
            e[m] = 0.0;
        }
    }
    return 0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

lx_status lx__sym_eigenvalues(size_t n, const double *a, double *ev)
{
    if (n == 0) return LX_OK;
    double *w = lx__alloc(sizeof(double) * (n * n + 3 * n));
    if (!w) return LX_ENOMEM;
    double *e = w + n * n, *v = e + n, *p = v + n;
    /* symmetrise (the mean of a and its transpose: a file's last digits may differ) */
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) w[i * n + j] = 0.5 * (a[i * n + j] + a[j * n + i]);
    tridiagonalise(n, w, ev, e, v, p);
    int bad = tridiagonal_ql(n, ev, e);
    lx__free(w);
    if (bad) return LX_ERANGE;
    qsort(ev, n, sizeof *ev, cmp_double);
    return LX_OK;
}

double lx__pivoted_cholesky(size_t n, const double *a, double tol, double *g, size_t *rank)
{
    *rank = 0;
    if (n == 0) return 0.0;
    size_t *perm = lx__alloc(n * sizeof *perm);
    double *d = lx__alloc(n * sizeof *d);
    if (!perm || !d) {
        lx__free(perm), lx__free(d);
        return NAN;
    }
    double maxd = 0.0;
    for (size_t i = 0; i < n; i++) {
        perm[i] = i;
        d[i] = a[i * n + i];
        if (d[i] > maxd) maxd = d[i];
    }
    size_t k = 0;
    if (maxd > 0) {
        for (; k < n; k++) {
            size_t best = k;
            for (size_t j = k + 1; j < n; j++)
                if (d[perm[j]] > d[perm[best]]) best = j;
            if (!(d[perm[best]] > tol * maxd)) break;
            size_t t = perm[k];
            perm[k] = perm[best], perm[best] = t;
            size_t pk = perm[k];
            double piv = sqrt(d[pk]);
            g[pk * n + k] = piv;
            for (size_t j = k + 1; j < n; j++) {
                size_t pj = perm[j];
                double s = a[pj * n + pk];
                for (size_t m = 0; m < k; m++) s -= g[pj * n + m] * g[pk * n + m];
                g[pj * n + k] = s / piv;
                d[pj] -= g[pj * n + k] * g[pj * n + k];
            }
            for (size_t j = 0; j < k + 1; j++) /* rows already pivoted: zero beyond their pivot */
                if (j < k) g[perm[j] * n + k] = 0.0;
        }
    }
    double rest = 0.0;
    for (size_t j = k; j < n; j++)
        if (maxd > 0 && d[perm[j]] / maxd < rest) rest = d[perm[j]] / maxd;
    *rank = k;
    lx__free(perm), lx__free(d);
    return rest;
}

/* Acklam's rational approximation (relative error 1.15e-9), then one Halley step on erfc. */
double lx__normal_quantile(double p)
{
    if (!(p > 0 && p < 1)) return p == 0 ? -INFINITY : p == 1 ? INFINITY : NAN;
    static const double a[6] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                                1.383577518672690e+02, -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[5] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                6.680131188771972e+01, -1.328068155288572e+01};
    static const double c[6] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                -2.549732539343734e+00, 4.374664141464968e+00, 2.938163982698783e+00};
    static const double d[4] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                3.754408661907416e+00};
    double x;
    if (p < 0.02425) {
        double q = sqrt(-2 * log(p));
        x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
    } else if (p > 1 - 0.02425) {
        double q = sqrt(-2 * log1p(-p));
        x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
    } else {
        double q = p - 0.5, r = q * q;
        x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
            (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
    }
    for (int it = 0; it < 2; it++) {
        double e = 0.5 * erfc(-x / sqrt(2.0)) - p;
        double u = e * sqrt(2 * 3.14159265358979323846) * exp(x * x / 2);
        x = x - u / (1 + x * u / 2);
    }
    return x;
}
