/* cct.c - correlated colour temperature and Duv: an exact solve for the nearest point of the
 * Planckian locus in CIE 1960 uv, the locus computed with the observer's own CMFs (1 nm sums). */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdlib.h>

#define LOCUS_T_MIN 500.0  /* the range searched (CCT outside it: LX_ERANGE) */
#define LOCUS_T_MAX 1.0e6
#define TABLE_T_MIN 400.0  /* the table reaches beyond it, so a CCT near either end is bracketed */
#define TABLE_T_MAX 1.25e6
#define LOCUS_NODES 168

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

/* uv of the Planckian radiator at T and, when du/dv are non-NULL, their derivatives in T, from
 * every `stride`-th wavelength of the CMFs (1: the exact sums; the solver's guide table takes 5,
 * good to 1e-6 in uv, as the table only brackets the root and starts the search). The spectrum is
 * scaled by exp(c2/(lambda_ref T)) so it neither under- nor overflows at any T. */
static void planck_uv_every(const cmf3 *c, size_t stride, double T, double *u, double *v, double *du, double *dv)
{
    double X = 0, Y = 0, Z = 0, dX = 0, dY = 0, dZ = 0;
    /* scale by exp(c2 / (lambda_last T)) so the longest wavelength has factor 1: no underflow */
    double xref = LX__C2_NM_K / (c->y.lambda_nm[c->y.n - 1] * T);
    /* Above 300 K one exp per wavelength does: exp(xref - x) = exp(xref) exp(-x) cannot overflow
     * (xref < 58) and 1 - exp(-x) keeps full precision while x > 0.01 (eps / x < 3e-14). */
    int fast = T >= 300.0;
    double exref = fast ? exp(xref) : 0.0;
    for (size_t i = 0; i < c->y.n; i += stride) {
        double l = c->y.lambda_nm[i];
        double x = LX__C2_NM_K / (l * T);
        double l5 = l * l * l * l * l;
        double e = fast ? exp(-x) : 0.0;
        double q = fast && x > 0.01 ? 1.0 - e : -expm1(-x); /* 1 - exp(-x) */
        double b = (fast ? exref * e : exp(xref - x)) / (l5 * q); /* B(l, T) up to a constant factor */
        double db = b * (x / q) / T; /* dB/dT = B x e^x / ((e^x - 1) T) */
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

static void planck_uv(const cmf3 *c, double T, double *u, double *v, double *du, double *dv)
{
    planck_uv_every(c, 1, T, u, v, du, dv);
}

/* The same uv with their first three derivatives in s = ln T, for the fast solver's table
 * (cct_fast.c). With B = f(x) = 1 / (e^x - 1) per wavelength (up to its constant factor),
 * x = c2 / (lambda T) and r = 1 / (1 - e^-x): dB/ds = x r B, d2B/ds2 = x r B (x (2r - 1) - 1),
 * d3B/ds3 = x r B (1 - 3x (2r - 1) + x^2 (6r^2 - 6r + 1)); then u = N / D by u' = (N' - u D') / D,
 * u'' = (N'' - 2u' D' - u D'') / D, u''' = (N''' - 3u'' D' - 3u' D'' - u D''') / D. */
static void planck_uv_ds3(const cmf3 *c, const double *c2_l, const double *inv_l5, double T, double o[8])
{
    double S[4][3] = {{0}};
    double xref = LX__C2_NM_K / (c->y.lambda_nm[c->y.n - 1] * T), exref = exp(xref), iT = 1 / T;
    const double *w[3] = {c->x.value, c->y.value, c->z.value};
    for (size_t i = 0; i < c->y.n; i++) {
        double x = c2_l[i] * iT;
        double e = exp(-x);
        double r = 1 / (x > 0.01 ? 1 - e : -expm1(-x));
        double b = exref * e * r * inv_l5[i], xr = x * r, tr = 2 * r - 1;
        double d[4] = {b, xr * b, xr * b * (x * tr - 1), xr * b * (1 - 3 * x * tr + x * x * (6 * r * r - 6 * r + 1))};
        for (int m = 0; m < 4; m++)
            for (int k = 0; k < 3; k++) S[m][k] += d[m] * w[k][i];
    }
    double D[4];
    for (int m = 0; m < 4; m++) D[m] = S[m][0] + 15 * S[m][1] + 3 * S[m][2];
    static const double a[2] = {4, 6};
    for (int q = 0; q < 2; q++) {
        double N0 = a[q] * S[0][q], N1 = a[q] * S[1][q], N2 = a[q] * S[2][q], N3 = a[q] * S[3][q];
        double f0 = N0 / D[0];
        double f1 = (N1 - f0 * D[1]) / D[0];
        double f2 = (N2 - 2 * f1 * D[1] - f0 * D[2]) / D[0];
        double f3 = (N3 - 3 * f2 * D[1] - 3 * f1 * D[2] - f0 * D[3]) / D[0];
        o[q] = f0, o[2 + q] = f1, o[4 + q] = f2, o[6 + q] = f3;
    }
}

lx_status lx__planck_uv_ds3(lx_observer obs, size_t n, const double *T, double (*out)[8])
{
    cmf3 c;
    lx_ctx *tmp = NULL; /* the views of the embedded CMFs need a context (for errors only) */
    lx_status st = lx_ctx_create(&tmp);
    if (st == LX_OK) st = get_cmf(tmp, obs, &c);
    lx_ctx_destroy(tmp);
    if (st != LX_OK) return st;
    double *c2_l = lx__alloc_n(2 * c.y.n, sizeof *c2_l), *inv_l5 = c2_l ? c2_l + c.y.n : NULL;
    if (!c2_l) return LX_ENOMEM;
    for (size_t i = 0; i < c.y.n; i++) {
        double l = c.y.lambda_nm[i];
        c2_l[i] = LX__C2_NM_K / l;
        inv_l5[i] = 1 / (l * l * l * l * l);
    }
    for (size_t k = 0; k < n; k++) planck_uv_ds3(&c, c2_l, inv_l5, T[k], out[k]);
    lx__free(c2_l);
    return LX_OK;
}

/* The locus cache of a context (its LX__SLOT_LOCUS): CIE 1960 uv of the Planckian radiator at
 * nodes spaced evenly in log T, one per observer ([0] 2 deg, [1] 10 deg). */
typedef struct lx__locus {
    int ready;
    int n;
    double logt0, dlogt;
    double *u, *v; /* v, du/ds and dv/ds follow u in one block of 4n doubles */
} lx__locus;

static void locus_free(void *p)
{
    lx__locus *pair = p;
    for (int i = 0; i < 2; i++) lx__free(pair[i].u); /* one block holds u, v and their derivatives */
    lx__free(pair);
}

static lx_status locus(lx_ctx *ctx, lx_observer obs, lx__locus **out, cmf3 *c)
{
    lx_status st = get_cmf(ctx, obs, c);
    if (st != LX_OK) return st;
    lx__locus *pair = lx__slot_get(ctx, LX__SLOT_LOCUS);
    if (!pair) {
        pair = lx__calloc(2, sizeof *pair);
        if (!pair) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the locus table");
        lx__slot_set(ctx, LX__SLOT_LOCUS, pair, locus_free);
    }
    lx__locus *L = &pair[obs == LX_OBSERVER_2 ? 0 : 1];
    if (!L->ready) {
        L->n = LOCUS_NODES;
        L->logt0 = log(TABLE_T_MIN);
        L->dlogt = (log(TABLE_T_MAX) - L->logt0) / (L->n - 1);
        /* one block: u, v and their derivatives in s = ln T, for the Hermite first guess */
        L->u = lx__alloc_n(4 * (size_t)L->n, sizeof(double));
        if (!L->u) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the locus table");
        L->v = L->u + L->n;
        double *du = L->u + 2 * L->n, *dv = L->u + 3 * L->n;
        for (int k = 0; k < L->n; k++) {
            double T = exp(L->logt0 + k * L->dlogt);
            planck_uv_every(c, 5, T, &L->u[k], &L->v[k], &du[k], &dv[k]); /* a guide: the solve is exact */
            du[k] *= T, dv[k] *= T;
        }
        L->ready = 1;
    }
    *out = L;
    return LX_OK;
}

lx_status lx_planck_uv(lx_ctx *ctx, lx_observer obs, double T, double *u, double *v)
{
    LX__NEED_CTX(ctx);
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

/* Point of the Hermite-interpolated locus nearest to (u, v) within the intervals around node k:
 * a few Newton steps on the squared distance in each interval, starting from its midpoint. */
static double hermite_guess(const lx__locus *L, int k, double u, double v)
{
    const double *du = L->u + 2 * L->n, *dv = L->u + 3 * L->n, h = L->dlogt;
    double best_s = L->logt0 + k * h, best_d = INFINITY;
    for (int i = k - 1; i <= k; i++) {
        double t = 0.5;
        for (int it = 0; it < 12; it++) {
            double t2 = t * t, t3 = t2 * t;
            double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
            double d00 = 6 * t2 - 6 * t, d10 = 3 * t2 - 4 * t + 1, d01 = -6 * t2 + 6 * t, d11 = 3 * t2 - 2 * t;
            double e00 = 12 * t - 6, e10 = 6 * t - 4, e01 = -12 * t + 6, e11 = 6 * t - 2;
            double pu = h00 * L->u[i] + h10 * h * du[i] + h01 * L->u[i + 1] + h11 * h * du[i + 1];
            double pv = h00 * L->v[i] + h10 * h * dv[i] + h01 * L->v[i + 1] + h11 * h * dv[i + 1];
            double qu = d00 * L->u[i] + d10 * h * du[i] + d01 * L->u[i + 1] + d11 * h * du[i + 1];
            double qv = d00 * L->v[i] + d10 * h * dv[i] + d01 * L->v[i + 1] + d11 * h * dv[i + 1];
            double ru = e00 * L->u[i] + e10 * h * du[i] + e01 * L->u[i + 1] + e11 * h * du[i + 1];
            double rv = e00 * L->v[i] + e10 * h * dv[i] + e01 * L->v[i + 1] + e11 * h * dv[i + 1];
            double g = (pu - u) * qu + (pv - v) * qv, gp = qu * qu + qv * qv + (pu - u) * ru + (pv - v) * rv;
            if (!(gp > 0)) break;
            double tn = t - g / gp;
            tn = tn < 0 ? 0 : tn > 1 ? 1 : tn;
            if (fabs(tn - t) < 1e-15) break;
            t = tn;
        }
        double t2 = t * t, t3 = t2 * t;
        double pu = (2 * t3 - 3 * t2 + 1) * L->u[i] + (t3 - 2 * t2 + t) * h * du[i] + (-2 * t3 + 3 * t2) * L->u[i + 1] +
                    (t3 - t2) * h * du[i + 1];
        double pv = (2 * t3 - 3 * t2 + 1) * L->v[i] + (t3 - 2 * t2 + t) * h * dv[i] + (-2 * t3 + 3 * t2) * L->v[i + 1] +
                    (t3 - t2) * h * dv[i + 1];
        double d = (pu - u) * (pu - u) + (pv - v) * (pv - v);
        if (d < best_d) best_d = d, best_s = L->logt0 + (i + t) * h;
    }
    return best_s;
}

lx_status lx_cct_from_uv(lx_ctx *ctx, lx_observer obs, double u, double v, double *cct_K, double *duv)
{
    LX__NEED_CTX(ctx);
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
    /* First guess: the nearest point of the cubic Hermite interpolant of the locus (nodes and
     * their exact derivatives in s = ln T) over the two intervals around the nearest node; then
     * the exact condition g(s) = 0 by secant steps, kept inside the bracket [s(best-1), s(best+1)]
     * where g changes sign; the Illinois regula falsi takes over if a step leaves it. */
    double a = L->logt0 + (best - 1) * L->dlogt, b = L->logt0 + (best + 1) * L->dlogt;
    double s = hermite_guess(L, best, u, v);
    int converged = 0;
    double s0 = s, g0 = gfun(&c, s0, u, v);
    double s1 = s0 + 1e-7, g1 = gfun(&c, s1, u, v);
    for (int it = 0; it < 8 && g1 != g0; it++) {
        double s2 = s1 - g1 * (s1 - s0) / (g1 - g0);
        if (!(s2 > a && s2 < b)) break;
        if (fabs(s2 - s1) < 1e-13) {
            s = s2;
            converged = 1;
            break;
        }
        s0 = s1, g0 = g1;
        s1 = s2, g1 = gfun(&c, s1, u, v);
        if (g1 == 0) {
            s = s1;
            converged = 1;
            break;
        }
    }
    double ga = 0, gb = 0;
    if (!converged) {
        ga = gfun(&c, a, u, v), gb = gfun(&c, b, u, v);
        if (ga * gb > 0)
            return lx__error(ctx, LX_ERANGE, NULL, 0, "chromaticity (u %g, v %g) is too far from the Planckian locus", u, v);
    }
    int side = 0;
    for (int it = 0; !converged && it < 200; it++) {
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
    if (!(T >= LOCUS_T_MIN * (1 - 1e-12) && T <= LOCUS_T_MAX * (1 + 1e-12)))
        return lx__error(ctx, LX_ERANGE, NULL, 0, "the nearest Planckian point (%.6g K) is outside %g-%g K", T,
                         LOCUS_T_MIN, LOCUS_T_MAX);
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
    LX__NEED_CTX(ctx);
    double d = -2 * x + 12 * y + 3;
    if (!(d != 0) || !isfinite(d)) {
        if (cct_K) *cct_K = NAN;
        if (duv) *duv = NAN;
        return lx__error(ctx, LX_ERANGE, NULL, 0, "chromaticity (x %g, y %g) is undefined", x, y);
    }
    return lx_cct_from_uv(ctx, obs, 4 * x / d, 6 * y / d, cct_K, duv);
}

lx_status lx__cct_from_uv_table(lx_ctx *ctx, lx_observer obs, double u, double v, double *cct_K, double *duv)
{
    *cct_K = *duv = NAN;
    if (!isfinite(u) || !isfinite(v)) return LX_ERANGE;
    /* the one fast solver (cct_fast.c: the exact answer to rounding, 0.15 us); where it does not
     * answer (the nearest point outside 900 K - 120000 K) the exact solve, on ctx */
    if (lx__cct_fast(obs, u, v, cct_K, duv)) return LX_OK;
    lx_status st = lx_cct_from_uv(ctx, obs, u, v, cct_K, duv);
    return st == LX_OK ? LX_OK : LX_ERANGE;
}
