/* report_colour.c - the colour and geometry helpers of the spectrum report: XYZ and monochromatic
 * light as sRGB, the spectral locus, isotemperature lines, the TM-30 vector graphic's
 * normalisation and the colours of the CIE 13.3 test samples under D65. */
#include "plot/plot_private.h"

#include <math.h>

/* linear sRGB from XYZ (IEC 61966-2-1, D65 white) */
static const double XYZ_TO_SRGB[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};

static unsigned char to8(double v) { return (unsigned char)lround(255.0 * lx__srgb_encode(v)); }

void lx__xyz_to_srgb8(const double xyz[3], unsigned char rgb[3])
{
    double c[3], lo = 0, hi = 0;
    for (int i = 0; i < 3; i++) {
        c[i] = XYZ_TO_SRGB[i][0] * xyz[0] + XYZ_TO_SRGB[i][1] * xyz[1] + XYZ_TO_SRGB[i][2] * xyz[2];
        if (!isfinite(c[i])) c[i] = 0;
    }
    for (int i = 0; i < 3; i++) lo = fmin(lo, c[i]);
    for (int i = 0; i < 3; i++) c[i] -= lo, hi = fmax(hi, c[i]); /* desaturate out-of-gamut colours */
    for (int i = 0; i < 3; i++) rgb[i] = to8(hi > 0 ? c[i] / hi : 0);
}

lx_status lx__locus_xy(lx_ctx *ctx, lx_observer obs, double lambda_nm, double *x, double *y)
{
    lx_function f0 = obs == LX_OBSERVER_10 ? LX_FN_XBAR_10 : LX_FN_XBAR_2;
    double v[3];
    for (int k = 0; k < 3; k++) {
        lx_spd w;
        lx_status st = lx_function_get(ctx, (lx_function)(f0 + k), &w);
        if (st) return st;
        v[k] = lx__interp(w.lambda_nm, w.value, w.n, lambda_nm);
    }
    double s = v[0] + v[1] + v[2];
    if (!(s > 0)) return lx__error(ctx, LX_ERANGE, NULL, 0, "no chromaticity at %g nm", lambda_nm);
    *x = v[0] / s;
    *y = v[1] / s;
    return LX_OK;
}

void lx__wavelength_srgb8(lx_ctx *ctx, double lambda_nm, unsigned char rgb[3])
{
    lx_spd w[3];
    double v[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        if (lx_function_get(ctx, (lx_function)(LX_FN_XBAR_2 + k), &w[k]) == LX_OK)
            v[k] = lx__interp(w[k].lambda_nm, w[k].value, w[k].n, lambda_nm);
    double s = v[0] + v[1] + v[2];
    if (!(s > 0)) {
        rgb[0] = rgb[1] = rgb[2] = 150; /* outside the colour-matching functions: grey */
        return;
    }
    lx__xyz_to_srgb8(v, rgb);
    /* fade where the eye sees little (the ends of the spectrum): brightness sqrt(sum / 0.4) */
    double f = sqrt(fmin(1.0, s / 0.4));
    for (int k = 0; k < 3; k++) rgb[k] = (unsigned char)lround(rgb[k] * f);
}

lx_status lx__isotemp_xy(lx_ctx *ctx, lx_observer obs, double T_K, double duv, double *x, double *y)
{
    double u, v, u1, v1, u2, v2;
    lx_status st = lx_planck_uv(ctx, obs, T_K, &u, &v);
    if (!st) st = lx_planck_uv(ctx, obs, T_K * (1 - 1e-4), &u1, &v1);
    if (!st) st = lx_planck_uv(ctx, obs, T_K * (1 + 1e-4), &u2, &v2);
    if (st) return st;
    /* unit tangent of the locus in uv, and its normal turned towards +v ("above", Duv > 0) */
    double tu = u2 - u1, tv = v2 - v1, n = hypot(tu, tv);
    tu /= n, tv /= n;
    double nu = -tv, nv = tu;
    if (nv < 0) nu = -nu, nv = -nv;
    u += duv * nu, v += duv * nv;
    double d = 2 * u - 8 * v + 4;
    *x = 3 * u / d;
    *y = 2 * v / d;
    return LX_OK;
}

void lx__cvg_point(const double ref_ab[2], const double test_ab[2], double out[2])
{
    double r = hypot(ref_ab[0], ref_ab[1]), h = atan2(ref_ab[1], ref_ab[0]);
    out[0] = (test_ab[0] - ref_ab[0]) / r + cos(h);
    out[1] = (test_ab[1] - ref_ab[1]) / r + sin(h);
}

/* the colour of test colour sample k (0-based) under D65, for its bar (2 deg CMFs, 5 nm sums) */
void lx__tcs_srgb8(lx_ctx *ctx, int k, unsigned char rgb[3])
{
    if (k < 14) lx__refl_srgb8(ctx, lx__table_find("cie13_3_tcs"), k + 1, rgb);
    else lx__refl_srgb8(ctx, lx__table_find("jis_z8726_tcs15"), 1, rgb);
}

void lx__refl_srgb8(lx_ctx *ctx, const lx__table *t, int col, unsigned char rgb[3])
{
    int k = col - 1;
    lx_spd d65, w[3];
    rgb[0] = rgb[1] = rgb[2] = 120;
    if (!t || lx_illuminant_get(ctx, "D65", &d65)) return;
    for (int f = 0; f < 3; f++)
        if (lx_function_get(ctx, (lx_function)(LX_FN_XBAR_2 + f), &w[f])) return;
    double xyz[3] = {0, 0, 0}, yw = 0;
    for (int r = 0; r < t->nrows; r++) {
        double l = t->data[r], refl = t->data[(size_t)(k + 1) * t->nrows + r];
        double e = lx__interp(d65.lambda_nm, d65.value, d65.n, l);
        for (int f = 0; f < 3; f++) xyz[f] += refl * e * lx__interp(w[f].lambda_nm, w[f].value, w[f].n, l);
        yw += e * lx__interp(w[1].lambda_nm, w[1].value, w[1].n, l);
    }
    for (int i = 0; i < 3; i++) {
        double v = (XYZ_TO_SRGB[i][0] * xyz[0] + XYZ_TO_SRGB[i][1] * xyz[1] + XYZ_TO_SRGB[i][2] * xyz[2]) / yw;
        rgb[i] = to8(v);
    }
}
