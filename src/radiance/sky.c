/* sky.c - sky luminance distributions: the 15 CIE standard general skies (ISO 15469 / CIE S 011,
 * parameters embedded from src/data/cie_s011_sky_types.csv) and the evaluation shared with the
 * Perez sky (sky_perez.c): luminance towards a direction and the illuminance on a plane of any
 * orientation by piecewise Gauss-Legendre quadrature. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

lx_status lx__unit3(lx_ctx *ctx, const char *what, const double v[3], double u[3])
{
    double n = v ? sqrt(dot3(v, v)) : 0;
    if (!(n > 0) || !isfinite(n)) return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: a direction of zero length", what);
    for (int i = 0; i < 3; i++) u[i] = v[i] / n;
    return LX_OK;
}

lx_status lx_sky_cie_params(lx_ctx *ctx, int type, double params[5])
{
    LX__NEED_CTX(ctx);
    const lx__table *t = lx__table_find("cie_s011_sky_types");
    if (!t || t->ncols != 8 || t->nrows != 15)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "CIE sky: the sky-type table is missing from this build");
    if (type < 1 || type > 15 || !params)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "CIE sky: type %d is not one of the standard skies 1..15", type);
    for (int r = 0; r < 15; r++)
        if ((int)t->data[r] == type) {
            for (int k = 0; k < 5; k++) params[k] = t->data[(3 + k) * t->nrows + r];
            return LX_OK;
        }
    return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "CIE sky: type %d missing from the table", type);
}

/* The relative luminance (unscaled: gradation times indicatrix) towards unit dir. */
double lx__sky_rel(const lx_sky *s, const double dir[3])
{
    double cz = dir[2];
    if (!(cz > 0)) return 0;
    double grad = 1 + s->a * exp(s->b / cz);
    double cchi = dot3(dir, s->sun_dir);
    cchi = cchi > 1 ? 1 : cchi < -1 ? -1 : cchi;
    double chi = acos(cchi), ind;
    if (s->model == LX_SKY_MODEL_CIE) ind = 1 + s->c * (exp(s->d * chi) - exp(s->d * LX__PI / 2)) + s->e * cchi * cchi;
    else ind = 1 + s->c * exp(s->d * chi) + s->e * cchi * cchi;
    double v = grad * ind;
    return v > 0 ? v : 0; /* the Perez fit can dip below zero near the horizon: no negative luminance */
}

/* rel at the zenith: the normalisation of L = Lz rel / rel_zenith */
static double rel_zenith(const lx_sky *s)
{
    static const double up[3] = {0, 0, 1};
    return lx__sky_rel(s, up);
}

double lx_sky_luminance(const lx_sky *sky, const double dir[3])
{
    double n = sqrt(dot3(dir, dir));
    if (!sky || !(n > 0)) return 0;
    double u[3] = {dir[0] / n, dir[1] / n, dir[2] / n};
    double z = rel_zenith(sky);
    return z > 0 ? sky->zenith_cd_m2 * lx__sky_rel(sky, u) / z : 0;
}

/* Gauss-Legendre nodes and weights on [-1, 1], by Newton on P_n (n <= 1024). */
void lx__gauss_legendre(int n, double *x, double *w)
{
    for (int i = 0; i < (n + 1) / 2; i++) {
        double z = cos(LX__PI * (i + 0.75) / (n + 0.5)), dp = 1;
        for (int it = 0; it < 100; it++) {
            double p0 = 1, p1 = z;
            for (int k = 2; k <= n; k++) {
                double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            if (n == 1) p1 = z, p0 = 1;
            dp = n * (z * p1 - p0) / (z * z - 1);
            double dz = p1 / dp;
            z -= dz;
            if (fabs(dz) < 1e-16) break;
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        w[i] = w[n - 1 - i] = 2 / ((1 - z * z) * dp * dp);
    }
}

/* Integral over the sky (theta in [0, pi/2]) of rel(w) max(0, n . w) d omega for unit n. In
 * zenith angle the pieces are split where the receiver's horizon meets the sky's (|pi/2 - beta|)
 * and at the sun's zenith angle; for each theta the azimuths where n . w > 0 form one arc
 * (closed form), split at the sun's azimuth, each piece by Gauss-Legendre: the integrand is
 * smooth inside every piece except for the cusp of exp(d chi) at the sun, which lies on a corner. */
double lx__sky_integral(const lx_sky *s, const double n[3], int nodes, const double *x, const double *w)
{
    double beta = acos(n[2] > 1 ? 1 : n[2] < -1 ? -1 : n[2]);
    double phin = atan2(n[1], n[0]), sb = sin(beta), cb = cos(beta);
    double sz = acos(s->sun_dir[2] > 1 ? 1 : s->sun_dir[2] < -1 ? -1 : s->sun_dir[2]);
    double phis = atan2(s->sun_dir[1], s->sun_dir[0]);
    double cuts[4] = {0, fabs(LX__PI / 2 - beta), sz, LX__PI / 2};
    /* sort the inner cuts */
    if (cuts[1] > cuts[2]) { double t = cuts[1]; cuts[1] = cuts[2]; cuts[2] = t; }
    double sum = 0;
    for (int piece = 0; piece < 3; piece++) {
        double t0 = cuts[piece], t1 = cuts[piece + 1];
        if (t1 > LX__PI / 2) t1 = LX__PI / 2;
        if (!(t1 - t0 > 1e-15)) continue;
        double ht = (t1 - t0) / 2;
        for (int i = 0; i < nodes; i++) {
            double t = t0 + ht * (x[i] + 1), st = sin(t), ct = cos(t);
            /* n . w = a + b cos(phi - phin) */
            double a = cb * ct, b = sb * st, half;
            if (b <= 1e-300 || a >= b) half = LX__PI;
            else if (a <= -b) continue;
            else half = acos(-a / b);
            double p0 = phin - half, p1 = phin + half;
            /* split at the sun's azimuth (brought into [p0, p0 + 2 pi)) when it lies inside */
            double ps = phis;
            while (ps < p0) ps += 2 * LX__PI;
            while (ps >= p0 + 2 * LX__PI) ps -= 2 * LX__PI;
            double edges[3] = {p0, ps, p1};
            int np = ps > p0 && ps < p1 ? 2 : 1;
            if (np == 1) edges[1] = p1;
            double row = 0;
            for (int q = 0; q < np; q++) {
                double q0 = edges[q], q1 = edges[q + 1], hp = (q1 - q0) / 2;
                for (int k = 0; k < nodes; k++) {
                    double ph = q0 + hp * (x[k] + 1);
                    double dir[3] = {st * cos(ph), st * sin(ph), ct};
                    double c = dot3(n, dir);
                    if (c > 0) row += w[k] * hp * lx__sky_rel(s, dir) * c;
                }
            }
            sum += w[i] * ht * st * row;
        }
    }
    return sum;
}

/* The horizontal integral of rel to 1e-12 relative: doubled node counts until they agree. */
double lx__sky_horizontal_rel(const lx_sky *s)
{
    static const double up[3] = {0, 0, 1};
    double prev = NAN;
    for (int nodes = 24; nodes <= 384; nodes *= 2) {
        double *x = lx__alloc_n(2 * (size_t)nodes, sizeof *x);
        if (!x) return NAN;
        lx__gauss_legendre(nodes, x, x + nodes);
        double v = lx__sky_integral(s, up, nodes, x, x + nodes);
        lx__free(x);
        if (fabs(v - prev) <= 1e-12 * fabs(v)) return v;
        prev = v;
    }
    return prev;
}

lx_status lx_sky_illuminance(lx_ctx *ctx, const lx_sky *sky, const double n[3], int nodes, double *E_lx)
{
    LX__NEED_CTX(ctx);
    if (!sky || !E_lx) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_sky_illuminance: NULL argument");
    if (nodes == 0) nodes = 48;
    if (nodes < 8 || nodes > 1024) return lx__error(ctx, LX_EINVAL, NULL, 0, "sky illuminance: nodes must be 8..1024");
    double u[3];
    lx_status st = lx__unit3(ctx, "sky illuminance: normal", n, u);
    if (st != LX_OK) return st;
    double *x = lx__alloc_n(2 * (size_t)nodes, sizeof *x);
    if (!x) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    lx__gauss_legendre(nodes, x, x + nodes);
    double z = rel_zenith(sky);
    *E_lx = z > 0 ? sky->zenith_cd_m2 / z * lx__sky_integral(sky, u, nodes, x, x + nodes) : 0;
    lx__free(x);
    if (ctx) ctx->counters.environment_samples += 4ULL * (unsigned long long)nodes * (unsigned long long)nodes;
    return LX_OK;
}

/* Scales a sky whose shape is set: by zenith luminance or by horizontal illuminance. */
lx_status lx__sky_scale(lx_ctx *ctx, lx_sky *s, lx_sky_scale scale, double value)
{
    if (!(value > 0) || !isfinite(value))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "sky: the %s must be positive and finite",
                         scale == LX_SKY_BY_ZENITH ? "zenith luminance" : "horizontal illuminance");
    double z = rel_zenith(s), h = lx__sky_horizontal_rel(s);
    if (!(z > 0) || !(h > 0) || !isfinite(h))
        return lx__error(ctx, LX_ERANGE, NULL, 0, "sky: the distribution has no positive zenith luminance");
    if (scale == LX_SKY_BY_ZENITH) {
        s->zenith_cd_m2 = value;
        s->diffuse_horizontal_lx = value * h / z;
    } else {
        s->diffuse_horizontal_lx = value;
        s->zenith_cd_m2 = value * z / h;
    }
    return LX_OK;
}

lx_status lx_sky_cie(lx_ctx *ctx, int type, const double sun_dir[3], lx_sky_scale scale, double value, lx_sky *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_sky_cie: NULL argument");
    double p[5];
    lx_status st = lx_sky_cie_params(ctx, type, p);
    if (st != LX_OK) return st;
    lx_sky s;
    memset(&s, 0, sizeof s);
    s.model = LX_SKY_MODEL_CIE;
    s.cie_type = type;
    s.a = p[0], s.b = p[1], s.c = p[2], s.d = p[3], s.e = p[4];
    s.epsilon = s.delta = s.sun_normal_lx = NAN;
    if ((st = lx__unit3(ctx, "CIE sky: sun direction", sun_dir, s.sun_dir)) != LX_OK) return st;
    int uniform_azimuth = s.c == 0 && s.e == 0;
    if (!uniform_azimuth && !(s.sun_dir[2] > 0))
        return lx__error(ctx, LX_EINVAL, NULL, 0,
                         "CIE sky type %d depends on the sun, which is at or below the horizon (altitude %.3g deg)",
                         type, asin(s.sun_dir[2]) / LX__DEG);
    if ((st = lx__sky_scale(ctx, &s, scale, value)) != LX_OK) return st;
    *out = s;
    return LX_OK;
}
