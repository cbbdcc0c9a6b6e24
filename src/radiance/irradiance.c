/* irradiance.c - the public irradiance calls: argument checks, normalised directions, the choice
 * of method (AUTO: exact unless that costs more than 10 x SH9) and (for brute force) of backend,
 * irradiance maps at lat-long pixel centres, and how concentrated a map's power is. */
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

/* AUTO's rule: FAST unless it would cost more than AUTO_RATIO x SH9 for the job. Costs in the time
 * of one row step of FAST (a prefix-sum difference per channel, 35-50 ns measured): FAST per output
 * H steps plus its crossed pixels (about W + 3H, 3 steps each to integrate, a tenth of a step to add
 * when a lat-long output row reuses them), SH9 0.2 steps per input pixel to project (9 ns measured)
 * and 2 per output. The ratio is kept on the context (lx_ctx_irradiance_method). */
#define AUTO_RATIO 10.0
static double fast_over_sh9(const lx_envmap *map, double n_out, double n_rows_reuse)
{
    double W = map->width, H = map->height;
    if (map->layout == LX_ENV_CUBE) W = H = 4.0 * map->width; /* six faces of N x N: rows and edges */
    double crossed = W + 3 * H;
    double rows = n_rows_reuse > 0 ? n_rows_reuse : n_out;
    double fast = n_out * (H + 0.1 * crossed) + rows * 3 * crossed;
    double sh9 = 0.2 * (double)map->width * map->height + 2 * n_out;
    return fast / sh9;
}

/* The method that runs: o->method, AUTO resolved by the cost rule (its estimate into *ratio). */
static lx_irr_method resolve(const lx_irr_opts *o, const lx_envmap *map, double n_out, double n_rows_reuse, double *ratio)
{
    *ratio = fast_over_sh9(map, n_out, n_rows_reuse);
    return o->method == LX_IRR_AUTO ? (*ratio <= AUTO_RATIO ? LX_IRR_FAST : LX_IRR_SH9) : o->method;
}

lx_irr_method lx_ctx_irradiance_method(const lx_ctx *ctx, double *fast_cost_ratio)
{
    if (fast_cost_ratio) *fast_cost_ratio = ctx ? ctx->irr_fast_cost_ratio : NAN;
    return ctx ? ctx->irr_method : LX_IRR_AUTO;
}

static lx_status check_method(lx_ctx *ctx, const lx_irr_opts *o)
{
    if ((int)o->method < LX_IRR_SH9 || o->method > LX_IRR_AUTO)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown irradiance method %d", (int)o->method);
    return LX_OK;
}

/* The irradiance for n unit normals by method (resolved); *used: where the work ran. */
static lx_status run_dirs(lx_ctx *ctx, const lx_envmap *map, size_t n, const double *dirs, const lx_irr_opts *o,
                          lx_irr_method method, double *out, lx_backend *used)
{
    *used = LX_BACKEND_CPU;
    switch (method) {
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
            if (!st) return lx__irr_horizon_fix(ctx, map, n, dirs, o->threads, out);
            if (!lx__backend_fallback(ctx, "irradiance", o->backend, st)) return st;
        }
#endif
        /* the clamped sum (the kernel's CPU twin), then the pixels the horizon crosses exactly */
        st = lx__irr_brute_cpu(ctx, map, n, dirs, o->threads, out);
        return st ? st : lx__irr_horizon_fix(ctx, map, n, dirs, o->threads, out);
    }
    default: break;
    }
    return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown irradiance method %d", (int)method);
}

/* AUTO's second rule: SH9 rings below zero around small bright sources (3/32 of their power); a
 * negative irradiance is certainly wrong, and then the exact method runs instead, whatever it costs */
static int any_negative_d(const double *v, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (v[k] < 0) return 1;
    return 0;
}

static int any_negative_f(const float *v, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (v[k] < 0) return 1;
    return 0;
}

/* The output map m's texels by method, through run_dirs (every method but SH9 on a lat-long map). */
static lx_status map_by_dirs(lx_ctx *ctx, const lx_envmap *map, lx_envmap *m, const lx_irr_opts *o, lx_irr_method method,
                             lx_backend *used)
{
    size_t n = (size_t)m->width * m->height;
    lx_status st = LX_OK;
    double *dirs = lx__calloc(n * 3, sizeof *dirs), *res = lx__alloc_n(n * map->channels, sizeof *res);
    if (!dirs || !res) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %dx%d map", m->width, m->height);
    for (size_t k = 0; k < n && !st; k++) lx_envmap_texel_direction(m, (int)(k / m->width), (int)(k % m->width), dirs + 3 * k);
    if (!st) st = run_dirs(ctx, map, n, dirs, o, method, res, used);
    for (size_t k = 0; k < n * map->channels && !st; k++) m->data[k] = (float)res[k];
    lx__free(dirs);
    lx__free(res);
    return st;
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
    if ((st = check_method(ctx, o))) return st;
    double ratio;
    lx_irr_method method = resolve(o, map, (double)n_dirs, 0, &ratio);
    double *nd = lx__alloc_n((n_dirs ? n_dirs : 1) * 3, sizeof *nd);
    double *res = lx__alloc_n((n_dirs ? n_dirs : 1) * map->channels, sizeof *res);
    if (!nd || !res) {
        lx__free(nd);
        lx__free(res);
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
    if (!st) st = run_dirs(ctx, map, n_dirs, nd, o, method, res, &used);
    if (!st && o->method == LX_IRR_AUTO && method == LX_IRR_SH9 && any_negative_d(res, n_dirs * map->channels)) {
        method = LX_IRR_FAST; /* AUTO's second rule: a negative SH9 result is wrong, the exact one runs */
        st = run_dirs(ctx, map, n_dirs, nd, o, method, res, &used);
    }
    if (!st) {
        memcpy(out, res, n_dirs * map->channels * sizeof *out);
        lx__backend_used(ctx, used);
        ctx->irr_method = method;
        ctx->irr_fast_cost_ratio = ratio;
    }
    lx__free(nd);
    lx__free(res);
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
    lx_status st = check_shape(ctx, map);
    if (st) return st;
    if ((st = lx__check_reserved(ctx, "irradiance options", o->reserved, sizeof o->reserved))) return st;
    if ((st = check_method(ctx, o))) return st;
    if (width == 0 && height == 0) {
        width = map->width;
        height = map->height;
    }
    /* a lat-long output whose width divides the input's: FAST integrates each output row's crossed
     * pixels once */
    int reuse = map->layout == LX_ENV_LATLONG && width > 0 && map->width % width == 0;
    double ratio;
    lx_irr_method method = resolve(o, map, (double)width * height, reuse ? height : 0, &ratio);
    /* SH9 on a lat-long map checks the pixels after the projection: a non-finite pixel makes the
     * coefficients non-finite, and only then is the map scanned for it (saves a pass) */
    int lazy = method == LX_IRR_SH9 && map->layout == LX_ENV_LATLONG;
    if (!lazy && (st = check_map(ctx, map))) return st;
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
    m->irradiance = 1;
    if (method == LX_IRR_SH9 && map->layout == LX_ENV_LATLONG) {
        lx_sh9 sh;
        st = lx_sh9_project(ctx, map, &sh);
        for (int k = 0; k < 9 && !st; k++)
            for (int c = 0; c < map->channels && !st; c++)
                if (!isfinite(sh.c[k][c])) {
                    st = check_map(ctx, map);
                    if (!st) st = lx__error(ctx, LX_EINVAL, NULL, 0, "SH9 coefficients overflow (radiance too large)");
                }
        if (!st) st = lx__irr_sh9_map(ctx, &sh, o->window, m);
        if (!st && o->method == LX_IRR_AUTO && any_negative_f(m->data, (size_t)width * height * map->channels)) {
            method = LX_IRR_FAST; /* AUTO's second rule: a negative SH9 result is wrong, the exact one runs */
            if (!(st = check_map(ctx, map))) st = map_by_dirs(ctx, map, m, o, method, &used);
        }
    } else {
        st = map_by_dirs(ctx, map, m, o, method, &used);
    }
    if (st) {
        lx_envmap_free(m);
    } else {
        *out = m;
        lx__backend_used(ctx, used);
        ctx->irr_method = method;
        ctx->irr_fast_cost_ratio = ratio;
    }
    return st;
}

/* ---- how concentrated the power is (SH9's warning) ---- */

typedef struct conc_px {
    double L, sr;
} conc_px;

static int by_radiance_desc(const void *a, const void *b)
{
    double x = ((const conc_px *)a)->L, y = ((const conc_px *)b)->L;
    return x < y ? 1 : x > y ? -1 : 0;
}

/* Pixel p's luminance (the Y combination of its channels) and solid angle. */
static conc_px pixel_at(const lx_envmap *m, size_t p)
{
    const float *v = m->data + p * m->channels;
    int row = (int)(p / (size_t)m->width), col = (int)(p % (size_t)m->width);
    conc_px c;
    c.L = m->channels == 3 ? m->y_weights[0] * v[0] + m->y_weights[1] * v[1] + m->y_weights[2] * v[2] : v[0];
    c.sr = m->layout == LX_ENV_CUBE ? lx_envmap_cube_texel_sr(m->width, row % m->width, col)
                                    : lx_envmap_pixel_sr(m->width, m->height, row);
    return c;
}

lx_status lx_envmap_concentration(lx_ctx *ctx, const lx_envmap *map, double max_sr, double *fraction, size_t *pixels)
{
    LX__NEED_CTX(ctx);
    if (!fraction || !pixels) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_envmap_concentration: NULL output");
    lx_status st = check_map(ctx, map);
    if (st) return st;
    if (!(max_sr >= 0)) return lx__error(ctx, LX_EINVAL, NULL, 0, "the solid angle must be >= 0 (got %g sr)", max_sr);
    size_t n = (size_t)map->width * map->height, m = 0;
    double total = 0, Lmax = 0;
    for (size_t p = 0; p < n; p++) {
        conc_px c = pixel_at(map, p);
        if (c.L > 0) total += c.L * c.sr, Lmax = c.L > Lmax ? c.L : Lmax;
    }
    *fraction = 0;
    *pixels = 0;
    if (!(total > 0)) return LX_OK;
    /* the candidates: every pixel at or above a cut that halves from Lmax until the pixels above it
     * cover max_sr (so only the bright few are sorted) */
    double cut = Lmax;
    for (;;) {
        double sr = 0;
        m = 0;
        for (size_t p = 0; p < n; p++) {
            conc_px c = pixel_at(map, p);
            if (c.L > 0 && c.L >= cut) sr += c.sr, m++;
        }
        if (sr >= max_sr || m == n || !(cut > 0)) break;
        cut *= 0.5;
    }
    conc_px *c = lx__alloc_n(m ? m : 1, sizeof *c);
    if (!c) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    size_t k = 0;
    for (size_t p = 0; p < n && k < m; p++) {
        conc_px q = pixel_at(map, p);
        if (q.L > 0 && q.L >= cut) c[k++] = q;
    }
    qsort(c, k, sizeof *c, by_radiance_desc);
    double sr = 0, pw = 0;
    size_t used = 0;
    for (; used < k && sr + c[used].sr <= max_sr; used++) sr += c[used].sr, pw += c[used].L * c[used].sr;
    lx__free(c);
    *fraction = pw / total;
    *pixels = used;
    return LX_OK;
}
