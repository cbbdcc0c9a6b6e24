/* scene_sky.c - sky and ground irradiance on a receiver of any orientation: a uniform sky (closed
 * form), the CIE standard overcast sky (closed form for horizontal receivers, Gauss-Legendre in
 * zenith angle otherwise), an EXR lat-long radiance map (pixel sums), a CIE general or Perez sky
 * (lx_sky_illuminance) and the sun (Evn max(0, n . s)); the ground below the horizon is a uniform
 * Lambertian surface of luminance rho E_h / pi, E_h the sky's and the sun's horizontal illuminance. */
#include "scene_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* G(theta) = integral over azimuth of max(0, n . omega) for a receiver tilted by beta:
 * with a = cos(beta) cos(theta), b = sin(beta) sin(theta) >= 0, the integrand is a + b cos(phi). */
static double azimuth_integral(double a, double b)
{
    if (a >= b) return 2 * LX__PI * a;
    if (a <= -b) return 0;
    double p0 = acos(-a / b);
    return 2 * (a * p0 + b * sin(p0));
}

/* CIE overcast sky part for tilt beta: integral over the sky of Lz (1 + 2 cos t)/3 max(0, n.w),
 * split at the zenith angle where the receiver's horizon meets the sky's (|pi/2 - beta|). */
static double overcast_tilted(lx_ctx *ctx, double Lz, double beta, int nodes)
{
    double *x = lx__alloc_n(2 * (size_t)nodes, sizeof *x);
    if (!x) return NAN;
    double *w = x + nodes;
    lx__gauss_legendre(nodes, x, w);
    double cut = fabs(LX__PI / 2 - beta), edges[3] = {0, cut, LX__PI / 2}, sum = 0;
    for (int piece = 0; piece < 2; piece++) {
        double t0 = edges[piece], t1 = edges[piece + 1], h = (t1 - t0) / 2;
        if (!(h > 0)) continue;
        for (int i = 0; i < nodes; i++) {
            double t = t0 + h * (x[i] + 1);
            double L = Lz * (1 + 2 * cos(t)) / 3;
            sum += w[i] * h * L * sin(t) * azimuth_integral(cos(beta) * cos(t), sin(beta) * sin(t));
        }
        ctx->counters.environment_samples += (unsigned long long)nodes;
    }
    lx__free(x);
    return sum;
}

typedef struct sky_map {
    const lx_envmap *map; /* the scene's */
    double *L;      /* per-pixel luminance, cd/m2, times the scene's scale */
    double E_h;     /* horizontal illuminance from the upper hemisphere */
} sky_map;

void lx__scene_sky_map_free(void *p)
{
    sky_map *m = p;
    if (!m) return;
    lx__free(m->L);
    lx__free(m);
}

/* Sum over the upper-hemisphere pixels of L times the integral of max(0, n . w) over the pixel
 * (exact, the pixels the receiver's horizon crosses included: lx__irr_rows_exact). Rows whose
 * centre is below the horizon are ground. */
static double map_sum(lx_ctx *ctx, const sky_map *m, const double n[3])
{
    int W = m->map->width, H = m->map->height, rows = 0;
    while (rows < H && (rows + 0.5) / H < 0.5) rows++;
    double sum = 0;
    if (lx__irr_rows_exact(ctx, W, H, m->L, rows, n, &sum) != LX_OK) return NAN;
    ctx->counters.environment_samples += (unsigned long long)W * (unsigned long long)rows;
    return sum;
}

lx_status lx__scene_sky_map_load(lx_ctx *ctx, const lx_scene *sc, void **out)
{
    sky_map *m = lx__calloc(1, sizeof *m);
    if (!m) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    m->map = sc->sky_map;
    m->L = lx__alloc_n((size_t)m->map->width * m->map->height, sizeof *m->L);
    if (!m->L) {
        lx__free(m);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    lx_status st = lx_envmap_luminance(ctx, m->map, m->L);
    if (st != LX_OK) {
        lx__scene_sky_map_free(m);
        return st;
    }
    for (size_t k = 0; k < (size_t)m->map->width * m->map->height; k++) m->L[k] *= sc->sky_scale;
    static const double up[3] = {0, 0, 1};
    m->E_h = map_sum(ctx, m, up);
    *out = m;
    return LX_OK;
}

lx_status lx__scene_sky_eval(lx_ctx *ctx, const lx_scene *sc, const void *map, const double n[3], double *E_lx)
{
    double cb = n[2] > 1 ? 1 : n[2] < -1 ? -1 : n[2], beta = acos(cb);
    double E_sky, E_h;
    ctx->counters.environment_evaluations++;
    switch (sc->sky) {
    case LX_SKY_UNIFORM:
        /* isotropic sky: the view factor of the sky dome from a plane tilted by beta is
         * (1 + cos beta)/2, so E = pi L (1 + cos beta)/2 (horizontal: pi L, vertical: pi L / 2) */
        E_h = LX__PI * sc->sky_luminance_cd_m2;
        E_sky = E_h * (1 + cb) / 2;
        break;
    case LX_SKY_OVERCAST:
        /* CIE standard overcast sky (Moon & Spencer 1942, CIE S 011 type 1): L = Lz (1 + 2 cos t)/3,
         * horizontal E = 2 pi Lz/3 (1/2 + 2/3) = 7 pi Lz / 9 */
        E_h = 7 * LX__PI * sc->sky_luminance_cd_m2 / 9;
        if (cb == 1) E_sky = E_h;
        else E_sky = overcast_tilted(ctx, sc->sky_luminance_cd_m2, beta, sc->sky_samples);
        if (!isfinite(E_sky)) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        break;
    case LX_SKY_MAP: {
        const sky_map *m = map;
        E_h = m->E_h;
        E_sky = cb == 1 ? E_h : map_sum(ctx, m, n);
        break;
    }
    case LX_SKY_CIE:
    case LX_SKY_PEREZ: {
        E_h = sc->sky_model.diffuse_horizontal_lx;
        if (cb == 1) E_sky = E_h;
        else {
            lx_status st = lx_sky_illuminance(ctx, &sc->sky_model, n, 0, &E_sky);
            if (st != LX_OK) return st;
        }
        break;
    }
    default: E_h = E_sky = 0; break;
    }
    /* the sun: a distant source of direct normal illuminance Evn above the horizon */
    if (sc->has_sun && sc->sun_normal_lx > 0 && sc->sun_dir[2] > 0) {
        double c = n[0] * sc->sun_dir[0] + n[1] * sc->sun_dir[1] + n[2] * sc->sun_dir[2];
        E_sky += c > 0 ? sc->sun_normal_lx * c : 0;
        E_h += sc->sun_normal_lx * sc->sun_dir[2];
    }
    /* the ground: uniform Lambertian luminance rho E_h / pi below the horizon, seen with the
     * view factor (1 - cos beta)/2 */
    double Lg = sc->ground_reflectance * E_h / LX__PI;
    *E_lx = E_sky + LX__PI * Lg * (1 - cb) / 2;
    return LX_OK;
}

double lx__scene_sky_map_L(const void *p, const double w[3])
{
    const sky_map *m = p;
    int W = m->map->width, H = m->map->height;
    double cz = w[2] > 1 ? 1 : w[2] < -1 ? -1 : w[2], ph = atan2(w[1], w[0]);
    if (ph < 0) ph += 2 * LX__PI;
    int r = (int)(acos(cz) / LX__PI * H), c = (int)(ph / (2 * LX__PI) * W);
    r = r < 0 ? 0 : r >= H ? H - 1 : r;
    c = c < 0 ? 0 : c >= W ? W - 1 : c;
    return m->L[(size_t)r * W + c];
}

void lx__scene_sky_horizontal(const lx_scene *sc, const void *map, double *sky_lx, double *with_sun_lx)
{
    double E = 0;
    switch (sc->sky) {
    case LX_SKY_UNIFORM: E = LX__PI * sc->sky_luminance_cd_m2; break;
    case LX_SKY_OVERCAST: E = 7 * LX__PI * sc->sky_luminance_cd_m2 / 9; break;
    case LX_SKY_MAP: E = map ? ((const sky_map *)map)->E_h : 0; break;
    case LX_SKY_CIE:
    case LX_SKY_PEREZ: E = sc->sky_model.diffuse_horizontal_lx; break;
    default: break;
    }
    *sky_lx = E;
    if (sc->has_sun && sc->sun_normal_lx > 0 && sc->sun_dir[2] > 0) E += sc->sun_normal_lx * sc->sun_dir[2];
    *with_sun_lx = E;
}

double lx__scene_sun_part(const lx_scene *sc, const double n[3])
{
    if (!(sc->has_sun && sc->sun_normal_lx > 0 && sc->sun_dir[2] > 0)) return 0;
    double c = n[0] * sc->sun_dir[0] + n[1] * sc->sun_dir[1] + n[2] * sc->sun_dir[2];
    return c > 0 ? sc->sun_normal_lx * c : 0;
}
