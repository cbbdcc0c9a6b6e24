/* cct.c - correlated colour temperature and Duv: an exact solve for the nearest point of the
 * Planckian locus in CIE 1960 uv, the locus computed with the observer's own CMFs (1 nm sums). */
#include "lx_private.h"

#include <math.h>
#include <stdlib.h>

#define LOCUS_T_MIN 500.0
#define LOCUS_T_MAX 1.0e6
#define LOCUS_NODES 160
#define C2_NM_K 1.4388e7 /* c2 = 1.4388e-2 m K in nm K */

typedef struct cmf3 {
    lx_spd x, y, z;
} cmf3;

static lx_status get_cmf(lx_ctx *ctx, lx_observer obs, cmf3 *c)
{
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    lx_function f0 = obs == LX_OBSERVER_2 ? LX_FN_XBAR_2 : LX_FN_XBAR_10;
    lx_status st = lx_function_get(ctx, f0, &c->x);
    if (st == LX_OK) st = lx_function_get(ctx, f0 + 1, &c->y);
    if (st == LX_OK) st = lx_function_get(ctx, f0 + 2, &c->z);
    return st;
}

/* uv of the Planckian radiator at T and, when du/dv are non-NULL, their derivatives in T. The
 * spectrum is scaled by exp(c2/(lambda_ref T)) so it neither under- nor overflows at any T. */
static void planck_uv(const cmf3 *c, double T, double *u, double *v, double *du, double *dv)
{
    double X = 0, Y = 0, Z = 0, dX = 0, dY = 0, dZ = 0;
    /* scale by exp(c2 / (lambda_last T)) so the longest wavelength has factor 1: no underflow */
    double xref = C2_NM_K / (c->y.lambda_nm[c->y.n - 1] * T);
    for (size_t i = 0; i < c->y.n; i++) {
        double l = c->y.lambda_nm[i];
        double x = C2_NM_K / (l * T);
        double l5 = l * l * l * l * l;
        double b = exp(xref - x) / (l5 * -expm1(-x)); /* B(l, T) up to a constant factor */
        double db = b * (x / -expm1(-x)) / T; /* dB/dT = B x e^x / ((e^x - 1) T) */
        X += b * c->x.value[i];
        Y += b * c->y.value[i];
        Z += b * c->z.value[i];
        dX += db * c->x.value[i];
        dY += db * c->y.value[i];
        dZ += db * c->z.value[i];
    }
    double D = X + 15 * Y + 3 * Z, dD = dX + 15 * dY + 3 * dZ;
    *u = 4 * X / D;
    *v = 6 * Y / D;
    if (du) *du = 4 * (dX * D - X * dD) / (D * D);
    if (dv) *dv = 6 * (dY * D - Y * dD) / (D * D);
}

static lx_status locus(lx_ctx *ctx, lx_observer obs, lx__locus **out, cmf3 *c)
{
    lx_status st = get_cmf(ctx, obs, c);
    if (st != LX_OK) return st;
    lx__locus *L = &ctx->locus[obs == LX_OBSERVER_2 ? 0 : 1];
    if (!L->ready) {
        L->n = LOCUS_NODES;
        L->logt0 = log(LOCUS_T_MIN);
        L->dlogt = (log(LOCUS_T_MAX) - L->logt0) / (L->n - 1);
        L->u = malloc(sizeof(double) * L->n);
        L->v = malloc(sizeof(double) * L->n);
        if (!L->u || !L->v) {
            free(L->u);
            free(L->v);
            L->u = L->v = NULL;
            return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the locus table");
        }
        for (int k = 0; k < L->n; k++) planck_uv(c, exp(L->logt0 + k * L->dlogt), &L->u[k], &L->v[k], NULL, NULL);
        L->ready = 1;
    }
    *out = L;
    return LX_OK;
}

lx_status lx_planck_uv(lx_ctx *ctx, lx_observer obs, double T, double *u, double *v)
{
    cmf3 c;
    lx_status st = get_cmf(ctx, obs, &c);
    if (st != LX_OK) return st;
    if (!(T > 0) || !isfinite(T)) return lx__error(ctx, LX_EINVAL, NULL, 0, "temperature must be positive, not %g K", T);
    double uu, vv;
    planck_uv(&c, T, &uu, &vv, NULL, NULL);
    if (u) *u = uu;
    if (v) *v = vv;
    return LX_OK;
}

/* g(T) = (P(T) - p) . P'(T), zero at the nearest locus point. Parameterised in s = ln T. */
static double gfun(const cmf3 *c, double s, double u, double v)
{
    double pu, pv, du, dv;
    planck_uv(c, exp(s), &pu, &pv, &du, &dv);
    return (pu - u) * du + (pv - v) * dv;
}

lx_status lx_cct_from_uv(lx_ctx *ctx, lx_observer obs, double u, double v, double *cct_K, double *duv)
{
    if (cct_K) *cct_K = NAN;
    if (duv) *duv = NAN;
    if (!isfinite(u) || !isfinite(v)) return lx__error(ctx, LX_ERANGE, NULL, 0, "chromaticity is not finite");
    cmf3 c;
    lx__locus *L = NULL;
    lx_status st = locus(ctx, obs, &L, &c);
    if (st != LX_OK) return st;
    int best = 0;
    double bd = INFINITY;
    for (int k = 0; k < L->n; k++) {
        double d = (L->u[k] - u) * (L->u[k] - u) + (L->v[k] - v) * (L->v[k] - v);
        if (d < bd) bd = d, best = k;
    }
    if (best == 0 || best == L->n - 1)
        return lx__error(ctx, LX_ERANGE, NULL, 0, "the nearest Planckian point is outside %g-%g K", LOCUS_T_MIN,
                         LOCUS_T_MAX);
    /* root of g in [s(best-1), s(best+1)] by the Illinois variant of regula falsi */
    double a = L->logt0 + (best - 1) * L->dlogt, b = L->logt0 + (best + 1) * L->dlogt;
    double ga = gfun(&c, a, u, v), gb = gfun(&c, b, u, v);
    if (ga * gb > 0) {
        /* not bracketed (a point far off the locus): take the better half and golden-search d^2 */
        return lx__error(ctx, LX_ERANGE, NULL, 0, "chromaticity (u %g, v %g) is too far from the Planckian locus", u, v);
    }
    double s = a;
    int side = 0;
    for (int it = 0; it < 100; it++) {
        s = (a * gb - b * ga) / (gb - ga);
        double gs = gfun(&c, s, u, v);
        if (gs == 0 || fabs(b - a) < 1e-15) break;
        if (gs * gb > 0) {
            b = s, gb = gs;
            if (side == -1) ga *= 0.5;
            side = -1;
        } else {
            a = s, ga = gs;
            if (side == 1) gb *= 0.5;
            side = 1;
        }
        if (fabs(b - a) < 1e-14) break;
    }
    double T = exp(s), pu, pv, du, dv;
    planck_uv(&c, T, &pu, &pv, &du, &dv);
    double dist = hypot(u - pu, v - pv);
    /* sign: + above the locus (towards green, larger v); the tangent points to lower u as T grows */
    double cross = du * (v - pv) - dv * (u - pu);
    double sgn = cross < 0 ? 1.0 : -1.0;
    if (du > 0) sgn = -sgn;
    if (cct_K) *cct_K = T;
    if (duv) *duv = sgn * dist;
    return LX_OK;
}

lx_status lx_cct_from_xy(lx_ctx *ctx, lx_observer obs, double x, double y, double *cct_K, double *duv)
{
    double d = -2 * x + 12 * y + 3;
    if (!(d != 0) || !isfinite(d)) {
        if (cct_K) *cct_K = NAN;
        if (duv) *duv = NAN;
        return lx__error(ctx, LX_ERANGE, NULL, 0, "chromaticity (x %g, y %g) is undefined", x, y);
    }
    return lx_cct_from_uv(ctx, obs, 4 * x / d, 6 * y / d, cct_K, duv);
}
