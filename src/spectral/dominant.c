/* dominant.c - dominant (or complementary) wavelength and excitation and colorimetric purity of a
 * chromaticity against a white point (CIE 015:2018 section 9.1), on the spectral locus of the
 * 1 nm colour-matching functions closed by the purple line. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <string.h>

/* Where the ray from w along d first leaves through the segment a-b: the ray's parameter t > 0
 * (in units of |d|) and the segment's s in [0, 1]; 0 when it does not cross it. */
static int ray_segment(const double w[2], const double d[2], const double a[2], const double b[2], double *t, double *s)
{
    double e[2] = {b[0] - a[0], b[1] - a[1]}, den = d[0] * e[1] - d[1] * e[0];
    if (den == 0) return 0; /* parallel */
    double f[2] = {a[0] - w[0], a[1] - w[1]};
    double tt = (f[0] * e[1] - f[1] * e[0]) / den, ss = (f[0] * d[1] - f[1] * d[0]) / den;
    if (!(tt > 0) || ss < -1e-12 || ss > 1 + 1e-12) return 0;
    *t = tt, *s = fmin(1, fmax(0, ss));
    return 1;
}

/* The farthest crossing of the ray from w along d with the locus (points lam[i], xy[i], i < n,
 * closed by the purple line from the last point back to the first): its parameter t, the
 * wavelength there (linear between the samples; NaN on the purple line) and the point. Among
 * crossings within 1e-12 of the farthest (where the locus folds back on itself beyond 700 nm) the
 * shortest wavelength. 0 when none. */
static int locus_hit(const double (*xy)[2], const double *lam, size_t n, const double w[2], const double d[2], double *t,
                     double *wl, double hit[2])
{
    double best = -1, bw = NAN;
    for (size_t i = 0; i < n; i++) {
        size_t j = i + 1 < n ? i + 1 : 0; /* the last segment is the purple line */
        double tt, ss;
        if (!ray_segment(w, d, xy[i], xy[j], &tt, &ss)) continue;
        double wi = j == 0 ? NAN : lam[i] + ss * (lam[j] - lam[i]);
        if (tt > best * (1 + 1e-12) || (fabs(tt - best) <= 1e-12 * best && wi < bw)) best = tt, bw = wi;
    }
    if (!(best > 0)) return 0;
    *t = best, *wl = bw;
    hit[0] = w[0] + best * d[0], hit[1] = w[1] + best * d[1];
    return 1;
}

/* 1 when p lies inside the closed locus (crossing number) */
static int inside(const double (*xy)[2], size_t n, const double p[2])
{
    int in = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++)
        if ((xy[i][1] > p[1]) != (xy[j][1] > p[1]) &&
            p[0] < (xy[j][0] - xy[i][0]) * (p[1] - xy[i][1]) / (xy[j][1] - xy[i][1]) + xy[i][0])
            in = !in;
    return in;
}

lx_status lx_dominant_wavelength(lx_ctx *ctx, lx_observer obs, double x, double y, double xw, double yw, lx_dominant *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_dominant_wavelength: NULL output");
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10) return lx__error(ctx, LX_EINVAL, NULL, 0, "dominant wavelength: bad observer");
    if (!isfinite(x) || !isfinite(y) || !isfinite(xw) || !isfinite(yw))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "dominant wavelength: chromaticity not finite");
    lx_spd cmf[3];
    lx_function f0 = obs == LX_OBSERVER_10 ? LX_FN_XBAR_10 : LX_FN_XBAR_2;
    for (int k = 0; k < 3; k++) {
        lx_status st = lx_function_get(ctx, (lx_function)(f0 + k), &cmf[k]);
        if (st) return st;
    }
    size_t n = cmf[0].n;
    double(*loc)[2] = lx__alloc_n(n, sizeof *loc);
    if (!loc) return lx__error(ctx, LX_ENOMEM, NULL, 0, "dominant wavelength: out of memory");
    size_t m = 0;
    double *lam = lx__alloc_n(n, sizeof *lam);
    if (!lam) {
        lx__free(loc);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "dominant wavelength: out of memory");
    }
    for (size_t i = 0; i < n; i++) {
        double X = cmf[0].value[i], Y = cmf[1].value[i], Z = cmf[2].value[i], s = X + Y + Z;
        if (!(s > 0)) continue;
        loc[m][0] = X / s, loc[m][1] = Y / s, lam[m] = cmf[0].lambda_nm[i], m++;
    }
    lx_dominant r;
    memset(&r, 0, sizeof r);
    lx_status st = LX_OK;
    const double w[2] = {xw, yw}, d[2] = {x - xw, y - yw};
    if (!inside((const double(*)[2])loc, m, w)) {
        st = lx__error(ctx, LX_EINVAL, NULL, 0, "dominant wavelength: the white point (%.5f, %.5f) is not inside the spectral locus", xw, yw);
        goto done;
    }
    double len = hypot(d[0], d[1]), t, wl, hit[2];
    if (len == 0) { /* the white itself: no hue, purity 0 */
        r.wavelength_nm = NAN, r.locus_x = r.locus_y = NAN;
        goto done;
    }
    if (!locus_hit((const double(*)[2])loc, lam, m, w, d, &t, &wl, hit)) {
        st = lx__error(ctx, LX_EINVAL, NULL, 0, "dominant wavelength: the white point (%.5f, %.5f) is not inside the spectral locus", xw, yw);
        goto done;
    }
    r.locus_x = hit[0], r.locus_y = hit[1];
    /* CIE 015 eq. 9.1: the excitation purity along the larger of the two coordinate differences */
    double dx = hit[0] - xw, dy = hit[1] - yw;
    r.excitation_purity = fabs(dy) >= fabs(dx) ? (y - yw) / dy : (x - xw) / dx;
    r.colorimetric_purity = r.excitation_purity * hit[1] / y; /* eq. 9.2: pc = pe yd / y */
    if (isnan(wl)) { /* on the purple line: the complementary wavelength, the ray reversed */
        const double back[2] = {-d[0], -d[1]};
        double t2, wl2, hit2[2];
        if (!locus_hit((const double(*)[2])loc, lam, m, w, back, &t2, &wl2, hit2) || isnan(wl2)) {
            st = lx__error(ctx, LX_EINVAL, NULL, 0, "dominant wavelength: no complementary wavelength for (%.5f, %.5f)", x, y);
            goto done;
        }
        r.purple = 1;
        r.wavelength_nm = -wl2; /* pc keeps the purple line's point for yd, as colour-science does */
    } else {
        r.wavelength_nm = wl;
    }
    if (r.excitation_purity > 1 + 1e-9) r.outside = 1; /* beyond the locus: not a real colour */
done:
    lx__free(loc);
    lx__free(lam);
    if (st == LX_OK) *out = r;
    return st;
}
