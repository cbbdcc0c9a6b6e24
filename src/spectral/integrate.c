/* integrate.c - integration of a sampled spectrum against a weighting function: the CIE 015
 * summation, the exact integral of two piecewise-linear functions, and 1 nm resampling; values
 * near the top of the double range are integrated scaled by a power of two (exact). Every method
 * is linear in the values: lx__integrate_weights gives the weight of each sample. */
#include "spectral/spectral_private.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Uniform step of a spectrum (0 when not uniform): every step equal within 1e-9 relative. */
static double uniform_step(const lx_spd *s)
{
    double step = s->lambda_nm[1] - s->lambda_nm[0];
    double tol = 1e-9 * step;
    for (size_t i = 2; i < s->n; i++)
        if (fabs(s->lambda_nm[i] - s->lambda_nm[i - 1] - step) > tol) return 0.0;
    return step;
}

static int whole_nm(const lx_spd *s)
{
    for (size_t i = 0; i < s->n; i++)
        if (fabs(s->lambda_nm[i] - nearbyint(s->lambda_nm[i])) > 1e-9) return 0;
    return 1;
}

lx_method lx_method_resolve(const lx_spd *spd, lx_method method)
{
    if (method != LX_METHOD_AUTO) return method;
    if (!spd || spd->n < 2) return LX_METHOD_EXACT;
    double step = uniform_step(spd);
    if ((fabs(step - 1.0) < 1e-9 || fabs(step - 5.0) < 1e-9) && whole_nm(spd)) return LX_METHOD_CIE15;
    return LX_METHOD_EXACT;
}

lx_status lx_spd_check(lx_ctx *ctx, const lx_spd *s)
{
    LX__NEED_CTX(ctx);
    if (!s || !s->lambda_nm || !s->value) return lx__error(ctx, LX_EINVAL, NULL, 0, "spectrum is NULL");
    const char *name = s->name ? s->name : "spectrum";
    if (s->n < 2) return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: needs at least 2 samples, has %zu", name, s->n);
    for (size_t i = 0; i < s->n; i++) {
        if (!isfinite(s->lambda_nm[i]) || !isfinite(s->value[i]))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: sample %zu is not finite", name, i + 1);
        if (i && !(s->lambda_nm[i] > s->lambda_nm[i - 1]))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: wavelengths not strictly increasing at sample %zu (%g nm)",
                             name, i + 1, s->lambda_nm[i]);
    }
    return LX_OK;
}

/* Weight at lambda: on a 1 nm table starting on a whole nm the row is found by index (and
 * checked to be that wavelength), else by binary search and linear interpolation. */
static double weight_at(const lx_spd *w, int unit_grid, double lambda)
{
    if (unit_grid) {
        double k = lambda - w->lambda_nm[0];
        double kr = nearbyint(k);
        if (kr >= 0 && kr <= (double)(w->n - 1) && fabs(w->lambda_nm[(size_t)kr] - lambda) < 1e-9)
            return w->value[(size_t)kr];
    }
    return lx__interp(w->lambda_nm, w->value, w->n, lambda);
}

static int is_unit_grid(const lx_spd *w)
{
    return fabs(w->lambda_nm[1] - w->lambda_nm[0] - 1.0) < 1e-12 &&
           fabs(w->lambda_nm[0] - nearbyint(w->lambda_nm[0])) < 1e-12;
}

/* Exact integral of the product of two piecewise-linear functions, each zero outside its samples. */
double lx__exact_product(const lx_spd *a, const lx_spd *b)
{
    double lo = fmax(a->lambda_nm[0], b->lambda_nm[0]);
    double hi = fmin(a->lambda_nm[a->n - 1], b->lambda_nm[b->n - 1]);
    if (!(hi > lo)) return 0.0;
    size_t i = 0, j = 0; /* segments [i, i+1] of a and [j, j+1] of b containing the current point */
    while (a->lambda_nm[i + 1] <= lo) i++;
    while (b->lambda_nm[j + 1] <= lo) j++;
    double sum = 0.0, comp = 0.0; /* Neumaier summation */
    double l = lo;
    while (l < hi) {
        double r = fmin(fmin(a->lambda_nm[i + 1], b->lambda_nm[j + 1]), hi);
        double ax0 = a->lambda_nm[i], ax1 = a->lambda_nm[i + 1], bx0 = b->lambda_nm[j], bx1 = b->lambda_nm[j + 1];
        double ta = a->value[i + 1] - a->value[i], tb = b->value[j + 1] - b->value[j];
        double al = a->value[i] + ta * ((l - ax0) / (ax1 - ax0));
        double ar = r == ax1 ? a->value[i + 1] : a->value[i] + ta * ((r - ax0) / (ax1 - ax0));
        double bl = b->value[j] + tb * ((l - bx0) / (bx1 - bx0));
        double br = r == bx1 ? b->value[j + 1] : b->value[j] + tb * ((r - bx0) / (bx1 - bx0));
        /* integral over [l, r] of two linear functions = h/6 (2 al bl + al br + ar bl + 2 ar br) */
        double term = (r - l) / 6.0 * (2.0 * al * bl + al * br + ar * bl + 2.0 * ar * br);
        double t = sum + term;
        comp += fabs(sum) >= fabs(term) ? (sum - t) + term : (term - t) + sum;
        sum = t;
        l = r;
        if (l >= a->lambda_nm[i + 1] && i + 2 < a->n) i++;
        if (l >= b->lambda_nm[j + 1] && j + 2 < b->n) j++;
    }
    return sum + comp;
}

double lx__spd_max_abs(const lx_spd *spd)
{
    double m = 0;
    for (size_t i = 0; i < spd->n; i++)
        if (fabs(spd->value[i]) > m) m = fabs(spd->value[i]);
    return m;
}

int lx__spd_tiny_scale(const lx_spd *spd, lx_spd *scaled, double **buf)
{
    *scaled = *spd;
    *buf = NULL;
    double m = lx__spd_max_abs(spd);
    if (!(m > 0) || m >= LX__SPD_TINY) return 0;
    int e = 0;
    frexp(m, &e); /* m = f 2^e, 0.5 <= f < 1 */
    double *v = lx__alloc_n(spd->n, sizeof *v);
    if (!v) return INT_MIN;
    for (size_t i = 0; i < spd->n; i++) v[i] = ldexp(spd->value[i], -e); /* scaling up: exact, subnormals too */
    scaled->value = v;
    *buf = v;
    return e;
}

/* Calls integral(ctx, spd, arg, out) and, when the result leaves the double range although every
 * value is finite, again on the values scaled by 2^-e (e: the exponent of the largest; exact) and
 * scales the result back: an intermediate product or partial sum that overflowed does not make the
 * integral overflow. LX_ERANGE "integral overflows: values up to M" when the integral itself does. */
static lx_status integrate_scaled(lx_ctx *ctx, const lx_spd *spd, const void *arg,
                                  lx_status (*integral)(lx_ctx *, const lx_spd *, const void *, double *), double *out)
{
    /* values so small that their products with a weight would fall among the subnormal numbers
     * (1e-320 keeps 3 digits): integrated scaled up by a power of two (exact) and scaled back, so the
     * result is rounded once, not every term (a flat 1e-320 moved xy by 1.5e-5) */
    lx_spd up;
    double *ubuf;
    int te = lx__spd_tiny_scale(spd, &up, &ubuf);
    if (te == INT_MIN) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (te) {
        lx_status st = integral(ctx, &up, arg, out);
        lx__free(ubuf);
        if (st == LX_OK) *out = ldexp(*out, te);
        return st;
    }
    lx_status st = integral(ctx, spd, arg, out);
    if (st != LX_OK || isfinite(*out)) return st;
    double m = lx__spd_max_abs(spd), r = NAN;
    int e = 0;
    frexp(m, &e);
    double *v = lx__alloc_n(spd->n, sizeof *v);
    if (!v) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; i < spd->n; i++) v[i] = ldexp(spd->value[i], -e);
    lx_spd scaled = *spd;
    scaled.value = v;
    st = integral(ctx, &scaled, arg, &r);
    lx__free(v);
    if (st != LX_OK) return st;
    r = ldexp(r, e);
    if (!isfinite(r)) {
        char mb[48];
        lx__fmt_magnitude(mb, sizeof mb, m);
        return lx__error(ctx, LX_ERANGE, NULL, 0, "integral overflows: values up to %s", mb);
    }
    *out = r;
    return LX_OK;
}

typedef struct weighted_arg {
    const lx_spd *w;
    lx_method method; /* resolved */
} weighted_arg;

static lx_status weighted(lx_ctx *ctx, const lx_spd *spd, const void *arg, double *out);

lx_status lx_spd_integrate(lx_ctx *ctx, const lx_spd *spd, const lx_spd *w, lx_method method, double *out)
{
    LX__NEED_CTX(ctx);
    lx_status st = lx_spd_check(ctx, spd);
    if (st == LX_OK) st = lx_spd_check(ctx, w);
    if (st != LX_OK) return st;
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "output is NULL");
    weighted_arg a = {w, lx_method_resolve(spd, method)};
    return integrate_scaled(ctx, spd, &a, weighted, out);
}

/* The integral of spd x w by the method of arg (a weighted_arg). */
static lx_status weighted(lx_ctx *ctx, const lx_spd *spd, const void *arg, double *out)
{
    const weighted_arg *a = arg;
    const lx_spd *w = a->w;
    lx_method method = a->method;
    double sum = 0.0;
    if (method == LX_METHOD_EXACT) {
        sum = lx__exact_product(spd, w);
    } else if (method == LX_METHOD_CIE15) {
        double step = uniform_step(spd);
        if (step <= 0)
            return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: method cie15 needs uniformly spaced wavelengths",
                             spd->name ? spd->name : "spectrum");
        int ug = is_unit_grid(w);
        for (size_t i = 0; i < spd->n; i++) sum += spd->value[i] * weight_at(w, ug, spd->lambda_nm[i]);
        sum *= step;
    } else if (method == LX_METHOD_LINEAR1NM) {
        int ug = is_unit_grid(w);
        /* only the whole nanometres where the weight is defined (it is zero outside): the work is
         * bounded by the weight's range, whatever the spectrum's (a file in the wrong unit can span
         * 1e9 nm) */
        double k0 = fmax(ceil(spd->lambda_nm[0]), ceil(w->lambda_nm[0]));
        double k1 = fmin(floor(spd->lambda_nm[spd->n - 1]), floor(w->lambda_nm[w->n - 1]));
        size_t i = 0;
        for (double k = k0; k <= k1; k += 1.0) {
            while (i + 2 < spd->n && spd->lambda_nm[i + 1] <= k) i++;
            double x0 = spd->lambda_nm[i], x1 = spd->lambda_nm[i + 1];
            double s = spd->value[i] + (spd->value[i + 1] - spd->value[i]) * ((k - x0) / (x1 - x0));
            sum += s * weight_at(w, ug, k);
        }
    } else {
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown integration method %d", (int)method);
    }
    *out = sum;
    return LX_OK;
}

static lx_status trapezoid(lx_ctx *ctx, const lx_spd *spd, const void *arg, double *out);

lx_status lx_spd_integrate_radiant(lx_ctx *ctx, const lx_spd *spd, lx_method method, double *out)
{
    LX__NEED_CTX(ctx);
    /* The radiant integral is a property of the spectrum, not of a weighting: whatever the
     * method, it is the exact integral of the piecewise-linear spectrum (the trapezoid rule).
     * A CIE 015 sum would count the end samples a full step wide (405 W instead of 400 W for
     * 1 W/nm from 380 to 780 nm at 5 nm). The method is accepted for symmetry and validated. */
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "output is NULL");
    if ((int)method < LX_METHOD_AUTO || method > LX_METHOD_LINEAR1NM)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown integration method %d", (int)method);
    return integrate_scaled(ctx, spd, NULL, trapezoid, out);
}

/* The exact integral of the piecewise-linear spectrum (arg unused). */
static lx_status trapezoid(lx_ctx *ctx, const lx_spd *spd, const void *arg, double *out)
{
    (void)ctx, (void)arg;
    double sum = 0.0, comp = 0.0;
    for (size_t i = 0; i + 1 < spd->n; i++) {
        double term = 0.5 * (spd->lambda_nm[i + 1] - spd->lambda_nm[i]) * (spd->value[i] + spd->value[i + 1]);
        double t = sum + term;
        comp += fabs(sum) >= fabs(term) ? (sum - t) + term : (term - t) + sum;
        sum = t;
    }
    *out = sum + comp;
    return LX_OK;
}

/* The weight of each sample in the exact integral: on every interval between merged breakpoints,
 * the hat functions of the two samples around it times the linear weight (the terms of
 * exact_product, split by sample). */
static void exact_weights(const lx_spd *a, const lx_spd *b, double *out)
{
    for (size_t k = 0; k < a->n; k++) out[k] = 0.0;
    double lo = fmax(a->lambda_nm[0], b->lambda_nm[0]);
    double hi = fmin(a->lambda_nm[a->n - 1], b->lambda_nm[b->n - 1]);
    if (!(hi > lo)) return;
    size_t i = 0, j = 0;
    while (a->lambda_nm[i + 1] <= lo) i++;
    while (b->lambda_nm[j + 1] <= lo) j++;
    double l = lo;
    while (l < hi) {
        double r = fmin(fmin(a->lambda_nm[i + 1], b->lambda_nm[j + 1]), hi);
        double ax0 = a->lambda_nm[i], ax1 = a->lambda_nm[i + 1], bx0 = b->lambda_nm[j], bx1 = b->lambda_nm[j + 1];
        double tb = b->value[j + 1] - b->value[j];
        double pl = (ax1 - l) / (ax1 - ax0), pr = r == ax1 ? 0.0 : (ax1 - r) / (ax1 - ax0); /* the hat of sample i */
        double bl = b->value[j] + tb * ((l - bx0) / (bx1 - bx0));
        double br = r == bx1 ? b->value[j + 1] : b->value[j] + tb * ((r - bx0) / (bx1 - bx0));
        double h6 = (r - l) / 6.0;
        out[i] += h6 * (2.0 * pl * bl + pl * br + pr * bl + 2.0 * pr * br);
        double ql = 1.0 - pl, qr = 1.0 - pr; /* the hat of sample i + 1 */
        out[i + 1] += h6 * (2.0 * ql * bl + ql * br + qr * bl + 2.0 * qr * br);
        l = r;
        if (l >= a->lambda_nm[i + 1] && i + 2 < a->n) i++;
        if (l >= b->lambda_nm[j + 1] && j + 2 < b->n) j++;
    }
}

lx_status lx__integrate_weights(lx_ctx *ctx, const lx_spd *spd, const lx_spd *w, lx_method method, double *out)
{
    method = lx_method_resolve(spd, method);
    size_t n = spd->n;
    if (!w) { /* the radiant integral: the trapezoid rule */
        for (size_t i = 0; i < n; i++) {
            double l = i > 0 ? spd->lambda_nm[i] - spd->lambda_nm[i - 1] : 0.0;
            double r = i + 1 < n ? spd->lambda_nm[i + 1] - spd->lambda_nm[i] : 0.0;
            out[i] = 0.5 * (l + r);
        }
        return LX_OK;
    }
    if (method == LX_METHOD_EXACT) {
        exact_weights(spd, w, out);
    } else if (method == LX_METHOD_CIE15) {
        double step = uniform_step(spd);
        if (step <= 0)
            return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: method cie15 needs uniformly spaced wavelengths",
                             spd->name ? spd->name : "spectrum");
        int ug = is_unit_grid(w);
        for (size_t i = 0; i < n; i++) out[i] = step * weight_at(w, ug, spd->lambda_nm[i]);
    } else if (method == LX_METHOD_LINEAR1NM) {
        for (size_t i = 0; i < n; i++) out[i] = 0.0;
        int ug = is_unit_grid(w);
        double k0 = fmax(ceil(spd->lambda_nm[0]), ceil(w->lambda_nm[0]));
        double k1 = fmin(floor(spd->lambda_nm[n - 1]), floor(w->lambda_nm[w->n - 1]));
        size_t i = 0;
        for (double k = k0; k <= k1; k += 1.0) {
            while (i + 2 < n && spd->lambda_nm[i + 1] <= k) i++;
            double x0 = spd->lambda_nm[i], x1 = spd->lambda_nm[i + 1], t = (k - x0) / (x1 - x0), wk = weight_at(w, ug, k);
            out[i] += (1.0 - t) * wk;
            out[i + 1] += t * wk;
        }
    } else {
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown integration method %d", (int)method);
    }
    return LX_OK;
}
