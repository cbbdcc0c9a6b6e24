/* envmap_cube.c - OpenEXR cube maps (six N x N faces stacked +X, -X, +Y, -Y, +Z, -Z): face frames
 * in luxcalc directions, exact texel solid angles, first and second moments (closed forms), and the
 * cube back ends of SH9 projection and of the exact irradiance sum (brute and fast). */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SH_C0 0.28209479177387814 /* 1 / (2 sqrt(pi)) */
#define SH_C1 0.48860251190291992 /* sqrt(3 / (4 pi)) */
#define SH_C2 1.09254843059207907 /* sqrt(15 / (4 pi)) */
#define SH_C3 0.31539156525252001 /* sqrt(5 / (16 pi)) */
#define SH_C4 0.54627421529603954 /* sqrt(15 / (16 pi)) */

/* Face frames {axis, u (image column, rightwards), v (image row, downwards)} in luxcalc directions.
 * OpenEXR ImfEnvmap.h/.cpp (CubeMap::direction and pixelPosition): +X face: column -> +z_e, row
 * down -> -y_e; -X: column -> -z_e, row -> -y_e; +Y: column -> +x_e, row -> -z_e; -Y: column ->
 * +x_e, row -> +z_e; +Z: column -> -x_e, row -> -y_e; -Z: column -> +x_e, row -> -y_e. Mapped to
 * luxcalc by (x, y, z)_e -> (-z, x, y), the mapping that takes OpenEXR's lat-long layout (top row
 * +y_e, longitude +pi at the left, longitude pi/2 = +x_e) to ours (top row +z, phi = 0 = +x at the
 * left, phi = pi/2 = +y a quarter across). */
const double lx__cube_frame[6][3][3] = {
    {{0, 1, 0}, {-1, 0, 0}, {0, 0, -1}}, /* +X_e: looks towards +y */
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}}, /* -X_e: -y */
    {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}},   /* +Y_e: +z, the zenith */
    {{0, 0, -1}, {0, 1, 0}, {-1, 0, 0}}, /* -Y_e: -z, the nadir */
    {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}, /* +Z_e: -x */
    {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}},  /* -Z_e: +x */
};

lx_status lx_envmap_create_cube(lx_ctx *ctx, int size, int channels, lx_envmap **out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_envmap_create_cube: NULL output");
    *out = NULL;
    if (size < 1 || size > 1 << 14) return lx__error(ctx, LX_EINVAL, NULL, 0, "invalid cube face size %d", size);
    lx_status st = lx_envmap_create(ctx, size, 6 * size, channels, out);
    if (!st) (*out)->layout = LX_ENV_CUBE;
    return st;
}

void lx_envmap_cube_direction(int size, double row, double col, double dir[3])
{
    int f = (int)floor(row / size);
    f = f < 0 ? 0 : f > 5 ? 5 : f;
    double a = 2 * col / size - 1, b = 2 * (row - (double)f * size) / size - 1;
    const double(*F)[3] = lx__cube_frame[f];
    double d[3], l = 0;
    for (int k = 0; k < 3; k++) {
        d[k] = F[0][k] + a * F[1][k] + b * F[2][k];
        l += d[k] * d[k];
    }
    l = sqrt(l);
    for (int k = 0; k < 3; k++) dir[k] = d[k] / l;
}

/* Corner functions whose mixed difference over [a0, a1] x [b0, b1] is the texel integral (the
 * point of the face is (1, a, b), r^2 = 1 + a^2 + b^2, d omega = da db / r^3):
 *   sr  : integral 1 / r^3         = atan(a b / r)
 *   S_nn: integral 1 / r^5         = (atan(a b / r) + a b (2 + a^2 + b^2) / (r (1 + a^2)(1 + b^2))) / 3
 *   S_uu: integral a^2 / r^5       = (atan(a b / r) - a b / (r (1 + a^2))) / 3
 *   S_vv: integral b^2 / r^5       = (atan(a b / r) - a b / (r (1 + b^2))) / 3
 *   S_nu: integral a / r^5         = -b / (3 r (1 + a^2)),  S_nv: -a / (3 r (1 + b^2))
 *   S_uv: integral a b / r^5       = 1 / (3 r)
 * (S_nn and S_uu by differentiating the solid-angle formula of the face scaled by lambda; the
 * trace S_nn + S_uu + S_vv = sr holds exactly). */
static void corner(double a, double b, double q[7])
{
    double r = sqrt(1 + a * a + b * b), at = atan(a * b / r), ab = a * b / r, ia = 1 / (1 + a * a), ib = 1 / (1 + b * b);
    q[0] = at;
    q[1] = (at + ab * (2 + a * a + b * b) * ia * ib) / 3;
    q[2] = (at - ab * ia) / 3;
    q[3] = (at - ab * ib) / 3;
    q[4] = -b * ia / (3 * r);
    q[5] = -a * ib / (3 * r);
    q[6] = 1 / (3 * r);
}

/* First moment of the face square [a0, a1] x [b0, b1] in the face frame by Lambert's formula:
 * integral of omega over a spherical polygon = 1/2 sum over edges of (edge angle) x (unit normal
 * of the edge's great circle), the edges taken anticlockwise seen from outside the sphere. */
static void lambert(double a0, double a1, double b0, double b1, double m[3])
{
    double P[4][3] = {{1, a0, b0}, {1, a0, b1}, {1, a1, b1}, {1, a1, b0}};
    for (int k = 0; k < 4; k++) {
        double l = sqrt(P[k][0] * P[k][0] + P[k][1] * P[k][1] + P[k][2] * P[k][2]);
        for (int c = 0; c < 3; c++) P[k][c] /= l;
    }
    m[0] = m[1] = m[2] = 0;
    for (int k = 0; k < 4; k++) {
        const double *A = P[k], *B = P[(k + 1) & 3];
        double x[3] = {A[1] * B[2] - A[2] * B[1], A[2] * B[0] - A[0] * B[2], A[0] * B[1] - A[1] * B[0]};
        double s = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), c = A[0] * B[0] + A[1] * B[1] + A[2] * B[2];
        if (!(s > 0)) continue;
        double f = 0.5 * atan2(s, c) / s;
        for (int q = 0; q < 3; q++) m[q] += f * x[q];
    }
    if (m[0] < 0) m[0] = -m[0], m[1] = -m[1], m[2] = -m[2]; /* orientation: the moment points out of the face */
}

static double edge(int n, int k) { return 2.0 * k / n - 1; }

double lx_envmap_cube_texel_sr(int size, int row, int col)
{
    double a0 = edge(size, col), a1 = edge(size, col + 1), b0 = edge(size, row), b1 = edge(size, row + 1);
    double q00[7], q01[7], q10[7], q11[7];
    corner(a0, b0, q00), corner(a0, b1, q01), corner(a1, b0, q10), corner(a1, b1, q11);
    return q11[0] - q10[0] - q01[0] + q00[0];
}

void lx_envmap_cube_texel_moment(int size, int row, int col, double m[3])
{
    int f = row / size, r = row % size;
    double l[3];
    lambert(edge(size, col), edge(size, col + 1), edge(size, r), edge(size, r + 1), l);
    for (int k = 0; k < 3; k++)
        m[k] = l[0] * lx__cube_frame[f][0][k] + l[1] * lx__cube_frame[f][1][k] + l[2] * lx__cube_frame[f][2][k];
}

double lx_envmap_texel_sr(const lx_envmap *map, int row, int col)
{
    if (map->layout == LX_ENV_CUBE) return lx_envmap_cube_texel_sr(map->width, row % map->width, col);
    return lx_envmap_pixel_sr(map->width, map->height, row);
}

void lx_envmap_texel_direction(const lx_envmap *map, int row, int col, double dir[3])
{
    if (map->layout == LX_ENV_CUBE) lx_envmap_cube_direction(map->width, row + 0.5, col + 0.5, dir);
    else lx_envmap_direction(map->width, map->height, row + 0.5, col + 0.5, dir);
}

double *lx__cube_table(int n)
{
    double *t = lx__alloc_n((size_t)n * n * LX__CUBE_NT, sizeof *t);
    double *c0 = lx__alloc_n((size_t)(n + 1) * 7 * 2, sizeof *c0);
    if (!t || !c0) {
        lx__free(t);
        lx__free(c0);
        return NULL;
    }
    double *lo = c0, *hi = c0 + (size_t)(n + 1) * 7;
    for (int i = 0; i <= n; i++) corner(edge(n, i), edge(n, 0), lo + 7 * i);
    for (int r = 0; r < n; r++) {
        for (int i = 0; i <= n; i++) corner(edge(n, i), edge(n, r + 1), hi + 7 * i);
        for (int c = 0; c < n; c++) {
            double *o = t + ((size_t)r * n + c) * LX__CUBE_NT, d[7];
            for (int k = 0; k < 7; k++) d[k] = hi[7 * (c + 1) + k] - hi[7 * c + k] - lo[7 * (c + 1) + k] + lo[7 * c + k];
            o[0] = d[0];
            lambert(edge(n, c), edge(n, c + 1), edge(n, r), edge(n, r + 1), o + 1);
            for (int k = 1; k < 7; k++) o[3 + k] = d[k]; /* nn uu vv nu nv uv */
        }
        double *sw = lo;
        lo = hi;
        hi = sw;
    }
    lx__free(c0);
    return t;
}

lx_status lx__sh9_project_cube(lx_ctx *ctx, const lx_envmap *map, lx_sh9 *out)
{
    int N = map->width, C = map->channels;
    double *t = lx__cube_table(N);
    if (!t) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %d-texel cube face table", N);
    memset(out, 0, sizeof *out);
    out->channels = C;
    for (int f = 0; f < 6; f++) {
        double a[3][LX__CUBE_NT] = {{0}};
        const float *L = map->data + (size_t)f * N * N * C;
        for (size_t p = 0; p < (size_t)N * N; p++) {
            const double *g = t + p * LX__CUBE_NT;
            for (int c = 0; c < C; c++) {
                double v = L[p * C + c];
                for (int k = 0; k < LX__CUBE_NT; k++) a[c][k] += v * g[k];
            }
        }
        const double(*F)[3] = lx__cube_frame[f];
        for (int c = 0; c < C; c++) {
            double m[3], S[3][3];
            /* local symmetric tensor -> world: S_w = R S R^T, R columns = (axis, u, v) */
            double Sl[3][3] = {{a[c][4], a[c][7], a[c][8]}, {a[c][7], a[c][5], a[c][9]}, {a[c][8], a[c][9], a[c][6]}};
            for (int x = 0; x < 3; x++) {
                m[x] = a[c][1] * F[0][x] + a[c][2] * F[1][x] + a[c][3] * F[2][x];
                for (int y = 0; y < 3; y++) {
                    double s = 0;
                    for (int i = 0; i < 3; i++)
                        for (int j = 0; j < 3; j++) s += F[i][x] * Sl[i][j] * F[j][y];
                    S[x][y] = s;
                }
            }
            double sr = a[c][0];
            out->c[0][c] += SH_C0 * sr;
            out->c[1][c] += SH_C1 * m[1];
            out->c[2][c] += SH_C1 * m[2];
            out->c[3][c] += SH_C1 * m[0];
            out->c[4][c] += SH_C2 * S[0][1];
            out->c[5][c] += SH_C2 * S[1][2];
            out->c[6][c] += SH_C3 * (3 * S[2][2] - sr);
            out->c[7][c] += SH_C2 * S[0][2];
            out->c[8][c] += SH_C4 * (S[0][0] - S[1][1]);
        }
    }
    lx__free(t);
    return LX_OK;
}

/* ---- the exact sum sum_p L_p max(0, n . m_p) on a cube map ---- */

typedef struct cube_job {
    const lx_envmap *map;
    const double *mom;  /* face-local first moments, 3 per texel */
    const double *pre;  /* fast: per row, 3 C prefix arrays of N + 1 (L m_n, L m_u, L m_v) for face f */
    const double *dirs;
    double *out;        /* accumulated over faces */
    int f, fast;
} cube_job;

/* Texel p (row r, column q of the face): L_p times the integral of max(0, n . w) over it. The sign
 * of n . w on the face is that of g(a, b) = nl0 + nl1 a + nl2 b, affine in the face point (1, a, b):
 * a texel with every corner lit is wholly lit (n . its first moment), one whose corners straddle
 * g = 0 is crossed by the horizon and integrated in closed form (Lambert's formula on the texel's
 * square clipped to the horizon, lx__polygon_projected: the texel edges are great-circle arcs). */
static inline double texel_term(const cube_job *J, const float *L, int C, size_t p, const double nl[3], double *e)
{
    int N = J->map->width, r = (int)(p / (size_t)N), q = (int)(p % (size_t)N);
    double a0 = edge(N, q), a1 = edge(N, q + 1), b0 = edge(N, r), b1 = edge(N, r + 1);
    double g00 = nl[0] + nl[1] * a0 + nl[2] * b0, g10 = nl[0] + nl[1] * a1 + nl[2] * b0;
    double g01 = nl[0] + nl[1] * a0 + nl[2] * b1, g11 = nl[0] + nl[1] * a1 + nl[2] * b1;
    double lo = fmin(fmin(g00, g10), fmin(g01, g11)), hi = fmax(fmax(g00, g10), fmax(g01, g11)), v;
    if (hi <= 0) return 0;
    if (lo >= 0) {
        const double *m = J->mom + 3 * p;
        v = nl[0] * m[0] + nl[1] * m[1] + nl[2] * m[2];
    } else {
        const double sq[4][3] = {{1, a0, b0}, {1, a1, b0}, {1, a1, b1}, {1, a0, b1}};
        v = lx__polygon_projected(sq, 4, nl);
    }
    if (v > 0)
        for (int c = 0; c < C; c++) e[c] += v * L[p * C + c];
    return v;
}

static void cube_outputs(void *arg, long o0, long o1, int t)
{
    (void)t;
    cube_job *J = arg;
    int N = J->map->width, C = J->map->channels;
    const float *L = J->map->data + (size_t)J->f * N * N * C;
    const double(*F)[3] = lx__cube_frame[J->f];
    size_t stride = (size_t)N + 1;
    for (long o = o0; o < o1; o++) {
        const double *n = J->dirs + 3 * o;
        double nl[3], e[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++) nl[k] = n[0] * F[k][0] + n[1] * F[k][1] + n[2] * F[k][2];
        /* the horizon n . (1, a, b) = 0 on the face: g(a, b) = nl0 + nl1 a + nl2 b */
        for (int r = 0; r < N; r++) {
            double b0 = edge(N, r), b1 = edge(N, r + 1);
            double gmin = nl[0] + fmin(nl[2] * b0, nl[2] * b1), gmax = nl[0] + fmax(nl[2] * b0, nl[2] * b1);
            int c0 = 0, c1 = N; /* columns [c0, c1) evaluated one by one */
            int lit0 = 0, lit1 = 0; /* columns [lit0, lit1) wholly lit, summed by prefix sums */
            if (J->fast) {
                if (fabs(nl[1]) * N < 1e-9) { /* the row sees (almost) no change along a */
                    if (gmin - fabs(nl[1]) > 0) c0 = c1 = 0, lit0 = 0, lit1 = N;
                    else if (gmax + fabs(nl[1]) < 0) c0 = c1 = 0;
                } else {
                    /* corners lit where a > -g / nl1 (nl1 > 0) or below (nl1 < 0), g in [gmin, gmax] */
                    double x0 = (-gmax / nl[1] + 1) * N / 2, x1 = (-gmin / nl[1] + 1) * N / 2;
                    double lo = fmin(x0, x1), hi = fmax(x0, x1);
                    long s0 = (long)floor(fmax(fmin(lo, N + 2.0), -2.0)) - 1, s1 = (long)ceil(fmax(fmin(hi, N + 2.0), -2.0)) + 1;
                    c0 = (int)(s0 < 0 ? 0 : s0 > N ? N : s0);
                    c1 = (int)(s1 < 0 ? 0 : s1 > N ? N : s1);
                    if (nl[1] > 0) lit0 = c1, lit1 = N;
                    else lit0 = 0, lit1 = c0;
                }
            }
            for (int c = c0; c < c1; c++) texel_term(J, L, C, (size_t)r * N + c, nl, e);
            if (lit1 > lit0) {
                const double *P = J->pre + (size_t)r * 3 * C * stride;
                for (int c = 0; c < C; c++) {
                    const double *pn = P + 3 * c * stride, *pu = pn + stride, *pv = pu + stride;
                    e[c] += nl[0] * (pn[lit1] - pn[lit0]) + nl[1] * (pu[lit1] - pu[lit0]) + nl[2] * (pv[lit1] - pv[lit0]);
                }
            }
        }
        for (int c = 0; c < C; c++) J->out[o * C + c] += e[c];
    }
}

static void cube_prefix(void *arg, long r0, long r1, int t)
{
    (void)t;
    cube_job *J = arg;
    int N = J->map->width, C = J->map->channels;
    const float *L = J->map->data + (size_t)J->f * N * N * C;
    size_t stride = (size_t)N + 1;
    double *pre = (double *)J->pre;
    for (long r = r0; r < r1; r++)
        for (int c = 0; c < C; c++) {
            double *pn = pre + ((size_t)r * 3 * C + 3 * c) * stride, *pu = pn + stride, *pv = pu + stride;
            double sn = 0, su = 0, sv = 0;
            pn[0] = pu[0] = pv[0] = 0;
            for (int i = 0; i < N; i++) {
                size_t p = (size_t)r * N + i;
                double v = L[p * C + c];
                sn += v * J->mom[3 * p];
                su += v * J->mom[3 * p + 1];
                sv += v * J->mom[3 * p + 2];
                pn[i + 1] = sn, pu[i + 1] = su, pv[i + 1] = sv;
            }
        }
}

lx_status lx__irr_cube(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads, int fast,
                       double *out)
{
    int N = map->width, C = map->channels;
    double *mom = lx__alloc_n((size_t)N * N * 3, sizeof *mom);
    double *acc = lx__calloc(n_dirs ? n_dirs * C : 1, sizeof *acc);
    double *pre = fast ? lx__alloc_n((size_t)N * 3 * C * (N + 1), sizeof *pre) : NULL;
    lx_status st = LX_OK;
    if (!mom || !acc || (fast && !pre)) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %d-texel cube map", N);
        goto done;
    }
    for (int r = 0; r < N; r++)
        for (int c = 0; c < N; c++)
            lambert(edge(N, c), edge(N, c + 1), edge(N, r), edge(N, r + 1), mom + 3 * ((size_t)r * N + c));
    cube_job J = {map, mom, pre, dirs, acc, 0, fast};
    int nt = lx__threads(threads, (long)n_dirs);
    for (int f = 0; f < 6 && !st; f++) {
        J.f = f;
        if (fast) st = lx__parallel_for(ctx, lx__threads(threads, N), N, cube_prefix, &J);
        if (!st) st = lx__parallel_for(ctx, nt, (long)n_dirs, cube_outputs, &J);
    }
    if (!st) memcpy(out, acc, n_dirs * C * sizeof *out);
done:
    lx__free(mom);
    lx__free(acc);
    lx__free(pre);
    return st;
}
