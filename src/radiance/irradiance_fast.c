/* irradiance_fast.c - the brute-force sum sum_p L_p max(0, n . m_p) in O(rows) per output normal.
 * In row j, n . m_p = A cos(phi_i - phi_n) + B (A >= 0), so the pixels that count form one
 * circular run |phi_i - phi_n| < acos(-B / A) of columns; their sum comes from per-row prefix
 * sums of L, L gx and L gy (double). Rows are processed in blocks to bound memory. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BLOCK_ROWS 64

typedef struct fast_job {
    const lx_envmap *map;
    const lx__llgeom *g;
    const double *dirs;
    double *out;   /* accumulated over blocks */
    double *pre;   /* BLOCK_ROWS rows x 3 C x (W + 1) prefix sums */
    int j0, nrows; /* current block */
    double *alpha; /* per thread: BLOCK_ROWS cached half-widths (or -1 none, 4 all) */
} fast_job;

static void build_prefix(void *arg, long r0, long r1, int t)
{
    (void)t;
    fast_job *J = arg;
    const lx_envmap *m = J->map;
    int W = m->width, C = m->channels;
    size_t stride = (size_t)W + 1;
    for (long r = r0; r < r1; r++) {
        const float *row = m->data + (size_t)(J->j0 + r) * W * C;
        double *P = J->pre + (size_t)r * 3 * C * stride;
        for (int c = 0; c < C; c++) {
            double *p0 = P + (3 * c) * stride, *px = p0 + stride, *py = px + stride;
            double s0 = 0, sx = 0, sy = 0;
            p0[0] = px[0] = py[0] = 0;
            for (int i = 0; i < W; i++) {
                double v = row[(size_t)i * C + c];
                s0 += v;
                sx += v * J->g->col_gx[i];
                sy += v * J->g->col_gy[i];
                p0[i + 1] = s0;
                px[i + 1] = sx;
                py[i + 1] = sy;
            }
        }
    }
}

/* prefix value at a column index k that may lie outside [0, W] (periodic continuation) */
static inline double pref(const double *p, long W, long k)
{
    long q = k >= 0 ? k / W : -((-k + W - 1) / W);
    return p[k - q * W] + (double)q * p[W];
}

static void accumulate(void *arg, long o0, long o1, int t)
{
    fast_job *J = arg;
    const lx_envmap *m = J->map;
    const lx__llgeom *g = J->g;
    long W = m->width;
    int C = m->channels;
    size_t stride = (size_t)W + 1;
    double *alpha = J->alpha + (size_t)t * BLOCK_ROWS;
    double last_nz = NAN, dphi = g->dphi, hs = 2 * sin(0.5 * dphi);
    for (long o = o0; o < o1; o++) {
        double nx = J->dirs[3 * o], ny = J->dirs[3 * o + 1], nz = J->dirs[3 * o + 2];
        double st = sqrt(nx * nx + ny * ny);
        if (nz != last_nz) { /* half-widths depend on the row and n_z only */
            for (int r = 0; r < J->nrows; r++) {
                int j = J->j0 + r;
                double A = g->row_s2[j] * hs * st, B = nz * g->row_sc[j] * dphi;
                if (A <= 0) alpha[r] = B > 0 ? 4 : -1;
                else {
                    double q = -B / A;
                    alpha[r] = q <= -1 ? 4 : q >= 1 ? -1 : acos(q);
                }
            }
            last_nz = nz;
        }
        double phin = atan2(ny, nx);
        double e[3] = {0, 0, 0};
        for (int r = 0; r < J->nrows; r++) {
            double al = alpha[r];
            if (al < 0) continue;
            int j = J->j0 + r;
            const double *P = J->pre + (size_t)r * 3 * C * stride;
            double a = g->row_s2[j], b = nz * g->row_sc[j] * dphi;
            long lo, hi;
            if (al > LX__PI) {
                lo = 0;
                hi = W; /* exclusive */
            } else {
                lo = (long)ceil((phin - al) / dphi - 0.5);
                hi = (long)floor((phin + al) / dphi - 0.5) + 1;
                if (hi - lo > W) hi = lo + W;
                if (hi <= lo) continue;
            }
            for (int c = 0; c < C; c++) {
                const double *p0 = P + (3 * c) * stride, *px = p0 + stride, *py = px + stride;
                double s0 = pref(p0, W, hi) - pref(p0, W, lo);
                double sx = pref(px, W, hi) - pref(px, W, lo);
                double sy = pref(py, W, hi) - pref(py, W, lo);
                e[c] += a * (nx * sx + ny * sy) + b * s0;
            }
        }
        for (int c = 0; c < C; c++) J->out[o * C + c] += e[c];
    }
}

lx_status lx__irr_fast(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads,
                       double *out)
{
    int W = map->width, H = map->height, C = map->channels;
    lx__llgeom g;
    lx_status st = lx__llgeom_init(ctx, &g, W, H);
    if (st) return st;
    int nt = lx__threads(threads, 0);
    double *pre = malloc((size_t)BLOCK_ROWS * 3 * C * (W + 1) * sizeof *pre);
    double *alpha = malloc((size_t)nt * BLOCK_ROWS * sizeof *alpha);
    double *acc = calloc(n_dirs * C, sizeof *acc);
    if (!pre || !alpha || !acc) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto done;
    }
    fast_job J = {map, &g, dirs, acc, pre, 0, 0, alpha};
    for (int j0 = 0; j0 < H && !st; j0 += BLOCK_ROWS) {
        J.j0 = j0;
        J.nrows = H - j0 < BLOCK_ROWS ? H - j0 : BLOCK_ROWS;
        st = lx__parallel_for(ctx, lx__threads(nt, J.nrows), J.nrows, build_prefix, &J);
        if (!st) st = lx__parallel_for(ctx, lx__threads(nt, (long)n_dirs), (long)n_dirs, accumulate, &J);
    }
    if (!st) memcpy(out, acc, n_dirs * C * sizeof *out);
done:
    free(pre);
    free(alpha);
    free(acc);
    lx__llgeom_free(&g);
    return st;
}
