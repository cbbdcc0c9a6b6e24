/* irradiance.c - the public irradiance calls: argument checks, normalised directions, the choice
 * of method and (for brute force) of backend, and irradiance maps at lat-long pixel centres. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Break-even of AUTO for brute force on OpenCL, in (output normal, input pixel) pairs (an estimate:
 * no GPU has been measured; a CPU-type OpenCL device is never chosen by auto). */
#define LX_IRR_AUTO_CL_PAIRS 2e9

static lx_status check_shape(lx_ctx *ctx, const lx_envmap *map)
{
    if (!map || !map->data || map->width < 1 || map->height < 1 || (map->channels != 1 && map->channels != 3) ||
        (map->layout != LX_ENV_LATLONG && map->layout != LX_ENV_CUBE) ||
        (map->layout == LX_ENV_CUBE && map->height != 6 * map->width))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "invalid radiance map");
    return LX_OK;
}

static lx_status check_map(lx_ctx *ctx, const lx_envmap *map)
{
    lx_status st0 = check_shape(ctx, map);
    if (st0) return st0;
    /* a NaN or Inf pixel would spread into every irradiance it touches (all of them for SH9): refuse it */
    size_t n = (size_t)map->width * map->height * map->channels;
    for (size_t k = 0; k < n; k++)
        if (!isfinite(map->data[k]))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "radiance map pixel (column %zu, row %zu) is not finite",
                             k / map->channels % map->width, k / map->channels / map->width);
    return LX_OK;
}

/* The irradiance for n unit normals by o->method; *used: where the work ran. */
static lx_status run_dirs(lx_ctx *ctx, const lx_envmap *map, size_t n, const double *dirs, const lx_irr_opts *o,
                          double *out, lx_backend *used)
{
    *used = LX_BACKEND_CPU;
    switch (o->method) {
    case LX_IRR_SH9: {
        lx_sh9 sh;
        lx_status st = lx_sh9_project(ctx, map, &sh);
        for (size_t k = 0; k < n && !st; k++) st = lx_sh9_irradiance(ctx, &sh, o->window, dirs + 3 * k, out + k * map->channels);
        return st;
    }
    case LX_IRR_FAST:
        if (map->layout == LX_ENV_CUBE) return lx__irr_cube(ctx, map, n, dirs, o->threads, 1, out);
        return lx__irr_fast(ctx, map, n, dirs, o->threads, out);
    case LX_IRR_BRUTE: {
        if (map->layout == LX_ENV_CUBE) return lx__irr_cube(ctx, map, n, dirs, o->threads, 0, out); /* CPU only */
        lx_backend b;
        lx_status st = lx__backend_choose(ctx, "irradiance", o->backend, (double)n * map->width * map->height,
                                          LX_IRR_AUTO_CL_PAIRS, LX_IRR_AUTO_CL_PAIRS, &b);
        if (st) return st;
#if LX_OPENCL
        if (b == LX_BACKEND_OPENCL) {
            st = lx__irr_brute_cl(ctx, map, n, dirs, out);
            if (!st) *used = LX_BACKEND_OPENCL;
            /* a failure under auto: the whole result again on the CPU (never a mix of devices) */
            if (!st || !lx__backend_fallback(ctx, "irradiance", o->backend, st)) return st;
        }
#endif
        return lx__irr_brute_cpu(ctx, map, n, dirs, o->threads, out);
    }
    }
    return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown irradiance method %d", (int)o->method);
}

lx_status lx_irradiance_dirs(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs,
                             const lx_irr_opts *opts, double *out)
{
    LX__NEED_CTX(ctx);
    lx_status st = check_map(ctx, map);
    if (st) return st;
    if ((!dirs || !out) && n_dirs) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_irradiance_dirs: NULL argument");
    const lx_irr_opts local = {0};
    const lx_irr_opts *o = opts ? opts : &local;
    if ((st = lx__check_reserved(ctx, "irradiance options", o->reserved, sizeof o->reserved))) return st;
    double *nd = malloc((n_dirs ? n_dirs : 1) * 3 * sizeof *nd);
    double *res = malloc((n_dirs ? n_dirs : 1) * map->channels * sizeof *res);
    if (!nd || !res) {
        free(nd);
        free(res);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t k = 0; k < n_dirs && !st; k++) {
        const double *d = dirs + 3 * k;
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(len > 0) || !isfinite(len))
            st = lx__error(ctx, LX_EINVAL, NULL, 0, "normal %zu (%g, %g, %g) is not a non-zero finite vector", k, d[0],
                           d[1], d[2]);
        for (int c = 0; c < 3; c++) nd[3 * k + c] = d[c] / len;
    }
    lx_backend used = LX_BACKEND_CPU;
    if (!st) st = run_dirs(ctx, map, n_dirs, nd, o, res, &used);
    if (!st) {
        memcpy(out, res, n_dirs * map->channels * sizeof *out);
        lx__backend_used(ctx, used);
    }
    free(nd);
    free(res);
    return st;
}

lx_status lx_irradiance_map(lx_ctx *ctx, const lx_envmap *map, int width, int height, const lx_irr_opts *opts,
                            lx_envmap **out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_irradiance_map: NULL output");
    *out = NULL;
    const lx_irr_opts local = {0};
    const lx_irr_opts *o = opts ? opts : &local;
    lx_backend used = LX_BACKEND_CPU;
    /* SH9 on a lat-long map checks the pixels after the projection: a non-finite pixel makes the
     * coefficients non-finite, and only then is the map scanned for it (saves a pass) */
    int lazy = o->method == LX_IRR_SH9 && map && map->layout == LX_ENV_LATLONG;
    lx_status st = lazy ? check_shape(ctx, map) : check_map(ctx, map);
    if (st) return st;
    if ((st = lx__check_reserved(ctx, "irradiance options", o->reserved, sizeof o->reserved))) return st;
    if (width == 0 && height == 0) {
        width = map->width;
        height = map->height;
    }
    if (map->layout == LX_ENV_CUBE && (width < 1 || height != 6 * width))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "a cube map's irradiance map is a cube map: size %dx%d is not N x 6N",
                         width, height);
    lx_envmap *m = NULL;
    st = map->layout == LX_ENV_CUBE ? lx_envmap_create_cube(ctx, width, map->channels, &m)
                                    : lx_envmap_create(ctx, width, height, map->channels, &m);
    if (st) return st;
    memcpy(m->y_weights, map->y_weights, sizeof m->y_weights);
    memcpy(m->chroma_xy, map->chroma_xy, sizeof m->chroma_xy);
    m->has_chromaticities = map->has_chromaticities;
    m->units = map->units;
    m->lum_per_unit = map->lum_per_unit;
    if (o->method == LX_IRR_SH9 && map->layout == LX_ENV_LATLONG) {
        lx_sh9 sh;
        st = lx_sh9_project(ctx, map, &sh);
        for (int k = 0; k < 9 && !st; k++)
            for (int c = 0; c < map->channels && !st; c++)
                if (!isfinite(sh.c[k][c])) {
                    st = check_map(ctx, map);
                    if (!st) st = lx__error(ctx, LX_EINVAL, NULL, 0, "SH9 coefficients overflow (radiance too large)");
                }
        if (!st) st = lx__irr_sh9_map(ctx, &sh, o->window, m);
    } else {
        size_t n = (size_t)width * height;
        double *dirs = malloc(n * 3 * sizeof *dirs), *res = malloc(n * map->channels * sizeof *res);
        if (!dirs || !res) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %dx%d map", width, height);
        for (size_t k = 0; k < n && !st; k++)
            lx_envmap_texel_direction(m, (int)(k / width), (int)(k % width), dirs + 3 * k);
        if (!st) st = run_dirs(ctx, map, n, dirs, o, res, &used);
        for (size_t k = 0; k < n * map->channels && !st; k++) m->data[k] = (float)res[k];
        free(dirs);
        free(res);
    }
    if (st) {
        lx_envmap_free(m);
    } else {
        *out = m;
        lx__backend_used(ctx, used);
    }
    return st;
}
