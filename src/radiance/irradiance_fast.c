/* irradiance_fast.c - the exact irradiance of a lat-long map, E(n) = sum_p L_p int_p max(0, n . w) dw,
 * in O(rows + the pixels the horizon crosses) per output normal. In row j the wholly lit pixels form
 * one circular run of columns between the lit arcs of the row's two edge parallels: their sum is
 * n . (their exact first moments), from per-row prefix sums of L, L gx and L gy (double); the pixels
 * the horizon crosses are integrated one by one in closed form (irradiance_horizon.c), once per
 * output row of a lat-long output whose width divides the input's. Rows are processed in blocks
 * to bound memory. */
#include "radiance/radiance_private.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BLOCK_ROWS 64
struct block_cache;

typedef struct fast_job {
    const lx_envmap *map;
    const lx__llgeom *g;
    const lx__hz *z;
    const double *dirs;
    double *out;   /* accumulated over blocks */
    double *pre;   /* BLOCK_ROWS rows x (W + 1) columns x 3 C prefix sums (L, L gx, L gy per channel) */
    int j0, nrows; /* current block */
    double *alpha; /* per thread: LX__HZ_RAY_SCRATCH (the lit half-widths, the meridian cache) */
    struct block_cache *cache; /* per thread */
} fast_job;

static void build_prefix(void *arg, long r0, long r1, int t)
{
    (void)t;
    fast_job *J = arg;
    const lx_envmap *m = J->map;
    int W = m->width, C = m->channels;
    size_t stride = (size_t)W + 1;
    size_t S = 3 * (size_t)C; /* interleaved: column k's 3 C sums together (one or two cache lines) */
    for (long r = r0; r < r1; r++) {
        const float *row = m->data + (size_t)(J->j0 + r) * W * C;
        double *P = J->pre + (size_t)r * S * stride;
        for (int c = 0; c < C; c++) {
            double s0 = 0, sx = 0, sy = 0;
            P[3 * c] = P[3 * c + 1] = P[3 * c + 2] = 0;
            for (int i = 0; i < W; i++) {
                double v = row[(size_t)i * C + c];
                s0 += v;
                sx += v * J->g->col_gx[i];
                sy += v * J->g->col_gy[i];
                double *q = P + (size_t)(i + 1) * S + 3 * c;
                q[0] = s0;
                q[1] = sx;
                q[2] = sy;
            }
        }
    }
}

/* A column index k that may lie outside [0, W] as k = *kk + q W with *kk in [0, W] (the periodic
 * continuation of a prefix sum p: p[k] = p[*kk] + q p[W]); returns q. */
static inline double pref_split(long k, long W, long *kk)
{
    if (k >= 0 && k <= W) {
        *kk = k;
        return 0;
    }
    long q = k >= 0 ? k / W : -((-k + W - 1) / W);
    *kk = k - q * W;
    return (double)q;
}

/* The classification and crossed-pixel weights of one block of rows for a reference normal: a
 * normal with the same n_z and sqrt(nx^2 + ny^2) whose phi_n is the reference's plus a whole number
 * k of columns sees the same pixels k columns on (the map is periodic in phi), so a lat-long output
 * row computes its crossed pixels once. */
typedef struct row_cache {
    int kind;
    long in_lo, in_hi, out_lo, out_hi;
    size_t w0; /* its weights: w[w0 ..], (in_lo - out_lo) + (out_hi - in_hi) of them */
} row_cache;

typedef struct block_cache {
    int valid;
    double nz, st, phin;
    row_cache row[BLOCK_ROWS];
    double *w; /* BLOCK_ROWS x W */
} block_cache;

/* Fills the cache for ray (the block's rows). */
static void cache_fill(const fast_job *J, lx__hz_ray *ray, block_cache *bc)
{
    const lx__hz *z = J->z;
    long W = J->map->width;
    size_t nw = 0;
    for (int r = 0; r < J->nrows; r++) {
        int j = J->j0 + r;
        row_cache *rc = &bc->row[r];
        rc->in_lo = rc->in_hi = rc->out_lo = rc->out_hi = 0;
        rc->kind = lx__hz_row((int)W, z->dphi, ray->phin, ray->alpha[j], ray->alpha[j + 1], &rc->in_lo, &rc->in_hi,
                              &rc->out_lo, &rc->out_hi);
        if (rc->kind == LX__HZ_LIT) rc->in_lo = 0, rc->in_hi = W;
        rc->w0 = nw;
        if (rc->kind != LX__HZ_RANGES) continue;
        /* the pixels the horizon crosses, one by one in closed form (n = +-z, whose horizon may run
         * along a row edge, has them checked first) */
        for (int part = 0; part < 2; part++)
            for (long k = part ? rc->in_hi : rc->out_lo, k1 = part ? rc->out_hi : rc->in_lo; k < k1; k++)
                bc->w[nw++] = lx__hz_pixel(z, J->g, ray, j, (int)(((k % W) + W) % W), ray->st == 0);
    }
    bc->valid = 1;
    bc->nz = ray->n[2];
    bc->st = ray->st;
    bc->phin = ray->phin;
}

/* whether the cache serves ray: the same n_z and sqrt(nx^2 + ny^2) */
static inline int n_eq(const block_cache *bc, const lx__hz_ray *ray)
{
    return bc->valid && ray->n[2] == bc->nz && fabs(ray->st - bc->st) <= 1e-14;
}

/* column k (any integer) taken into [0, W) */
static inline long wrap(long k, long W)
{
    if (k >= 0 && k < W) return k;
    k %= W;
    return k < 0 ? k + W : k;
}

/* Outputs that share a block cache (a lat-long output row: the same n_z and st, phi_n a whole
 * number of columns apart) are accumulated together, row by row, so that each input row's prefix
 * sums and pixels are read from cache once for the group rather than once per output. */
#define GROUP_MAX 256

static void accumulate(void *arg, long o0, long o1, int t)
{
    fast_job *J = arg;
    const lx_envmap *m = J->map;
    const lx__llgeom *g = J->g;
    const lx__hz *z = J->z;
    long W = m->width;
    int C = m->channels;
    size_t stride = (size_t)W + 1;
    double *alpha = J->alpha + (size_t)t * LX__HZ_RAY_SCRATCH(m->width, m->height), *tz = alpha + 3 * ((size_t)m->height + 1);
    unsigned *stamp = (unsigned *)(tz + 3 * (W + 1)), gen = 0;
    for (long i = 0; i <= W; i++) stamp[i] = 0;
    block_cache *bc = &J->cache[t];
    bc->valid = 0;
    double last_nz = NAN, last_st = NAN;
    long shifts[GROUP_MAX];
    double e[GROUP_MAX][3];
    for (long o = o0; o < o1;) {
        lx__hz_ray ray;
        lx__hz_ray_init(&ray, J->dirs + 3 * o, alpha, tz, stamp, &gen);
        if (n_eq(bc, &ray)) {
            double q = (ray.phin - bc->phin) / z->dphi, k = nearbyint(q);
            shifts[0] = fabs(q - k) < 1e-9 ? (long)k : LONG_MIN;
        } else {
            shifts[0] = LONG_MIN;
        }
        if (shifts[0] == LONG_MIN) {
            if (ray.n[2] != last_nz || ray.st != last_st) { /* the lit half-widths depend on n_z and st only */
                lx__hz_ray_rows(&ray, z, J->j0, J->j0 + J->nrows);
                last_nz = ray.n[2], last_st = ray.st;
            }
            cache_fill(J, &ray, bc);
            shifts[0] = 0;
        }
        /* the following outputs that the cache serves too */
        long ng = 1;
        while (ng < GROUP_MAX && o + ng < o1) {
            const double *d = J->dirs + 3 * (o + ng);
            double st = sqrt(d[0] * d[0] + d[1] * d[1]);
            if (!(d[2] == bc->nz && fabs(st - bc->st) <= 1e-14 && st > 0)) break;
            double ph = atan2(d[1], d[0]);
            if (ph < 0) ph += 2 * LX__PI;
            double q = (ph - bc->phin) / z->dphi, k = nearbyint(q);
            if (!(fabs(q - k) < 1e-9)) break;
            shifts[ng++] = (long)k;
        }
        for (long u = 0; u < ng; u++) e[u][0] = e[u][1] = e[u][2] = 0;
        for (int r = 0; r < J->nrows; r++) {
            const row_cache *rc = &bc->row[r];
            if (rc->kind == LX__HZ_DARK) continue;
            int j = J->j0 + r;
            const double *P = J->pre + (size_t)r * 3 * C * stride;
            double a = g->row_s2[j], b = bc->nz * g->row_sc[j] * g->dphi;
            const float *row = m->data + (size_t)j * W * C;
            const double *w0 = bc->w + rc->w0;
            for (long u = 0; u < ng; u++) {
                const double *n = J->dirs + 3 * (o + u);
                long shift = shifts[u];
                long in_lo = rc->in_lo + shift, in_hi = rc->in_hi + shift;
                if (in_hi > in_lo) { /* wholly lit: n . the moments, by prefix sums */
                    long kl, kh;
                    double ql = pref_split(in_lo, W, &kl), qh = pref_split(in_hi, W, &kh);
                    const double *ph = P + (size_t)kh * 3 * C, *pl = P + (size_t)kl * 3 * C, *pw = P + (size_t)W * 3 * C;
                    for (int c = 0; c < C; c++) {
                        double s0 = ph[3 * c] - pl[3 * c] + (qh - ql) * pw[3 * c];
                        double sx = ph[3 * c + 1] - pl[3 * c + 1] + (qh - ql) * pw[3 * c + 1];
                        double sy = ph[3 * c + 2] - pl[3 * c + 2] + (qh - ql) * pw[3 * c + 2];
                        e[u][c] += a * (n[0] * sx + n[1] * sy) + b * s0;
                    }
                }
                if (rc->kind != LX__HZ_RANGES) continue;
                const double *w = w0;
                double x0 = 0, x1 = 0, x2 = 0; /* in registers: the sums over the crossed pixels */
                for (int part = 0; part < 2; part++)
                    for (long k = part ? rc->in_hi : rc->out_lo, k1 = part ? rc->out_hi : rc->in_lo; k < k1; k++, w++) {
                        if (!(*w > 0)) continue;
                        const float *px = row + (size_t)wrap(k + shift, W) * C;
                        x0 += *w * px[0];
                        if (C > 1) x1 += *w * px[1], x2 += *w * px[2];
                    }
                e[u][0] += x0;
                if (C > 1) e[u][1] += x1, e[u][2] += x2;
            }
        }
        for (long u = 0; u < ng; u++)
            for (int c = 0; c < C; c++) J->out[(o + u) * C + c] += e[u][c];
        o += ng;
    }
}

lx_status lx__irr_fast(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads,
                       double *out)
{
    int W = map->width, H = map->height, C = map->channels;
    lx__llgeom g;
    lx_status st = lx__llgeom_init(ctx, &g, W, H);
    if (st) return st;
    lx__hz z;
    if ((st = lx__hz_init(ctx, &z, W, H))) {
        lx__llgeom_free(&g);
        return st;
    }
    int nt = lx__threads(threads, 0);
    double *pre = lx__alloc_n((size_t)BLOCK_ROWS * 3 * C * (W + 1), sizeof *pre);
    double *alpha = lx__alloc_n((size_t)nt * LX__HZ_RAY_SCRATCH(W, H), sizeof *alpha);
    double *acc = lx__calloc(n_dirs * C, sizeof *acc);
    struct block_cache *cache = lx__calloc((size_t)nt, sizeof *cache);
    double *wbuf = lx__alloc_n((size_t)nt * BLOCK_ROWS * W, sizeof *wbuf);
    if (!pre || !alpha || !acc || !cache || !wbuf) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto done;
    }
    for (int t = 0; t < nt; t++) cache[t].w = wbuf + (size_t)t * BLOCK_ROWS * W;
    fast_job J = {map, &g, &z, dirs, acc, pre, 0, 0, alpha, cache};
    for (int j0 = 0; j0 < H && !st; j0 += BLOCK_ROWS) {
        J.j0 = j0;
        J.nrows = H - j0 < BLOCK_ROWS ? H - j0 : BLOCK_ROWS;
        st = lx__parallel_for(ctx, lx__threads(nt, J.nrows), J.nrows, build_prefix, &J);
        if (!st) st = lx__parallel_for(ctx, lx__threads(nt, (long)n_dirs), (long)n_dirs, accumulate, &J);
    }
    if (!st) memcpy(out, acc, n_dirs * C * sizeof *out);
done:
    lx__free(pre);
    lx__free(alpha);
    lx__free(acc);
    lx__free(cache);
    lx__free(wbuf);
    lx__hz_free(&z);
    lx__llgeom_free(&g);
    return st;
}
