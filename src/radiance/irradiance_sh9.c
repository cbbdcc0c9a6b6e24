/* irradiance_sh9.c - Ramamoorthi and Hanrahan 2001 irradiance from 9 spherical-harmonic
 * coefficients. The projection integrates each basis function exactly over each lat-long pixel
 * (separable closed forms in theta and phi), so the piecewise-constant map is projected exactly;
 * E(n) = sum_l w_l A_l L_lm Y_lm(n) with A = (pi, 2pi/3, pi/4) and an optional window w. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define LX_SH9_AVX2 1
#endif


/* Normalisation constants of the real SH basis (l <= 2). */
#define SH_C0 0.28209479177387814 /* 1 / (2 sqrt(pi)) */
#define SH_C1 0.48860251190291992 /* sqrt(3 / (4 pi)) */
#define SH_C2 1.09254843059207907 /* sqrt(15 / (4 pi)) */
#define SH_C3 0.31539156525252001 /* sqrt(5 / (16 pi)) */
#define SH_C4 0.54627421529603954 /* sqrt(15 / (16 pi)) */

/* Band factors w_l A_l for a window. */
static void band_factors(lx_sh9_window window, double f[3])
{
    f[0] = LX__PI;
    f[1] = 2 * LX__PI / 3;
    f[2] = LX__PI / 4;
    if (window == LX_SH9_WINDOW_NONNEG) {
        f[1] *= 6.0 / 7.0;
        f[2] *= 32.0 / 35.0;
    }
}

typedef struct proj_job {
    const lx_envmap *map;
    const double *colf; /* 5 column factors per column */
    const double *colx; /* AVX2: the 5 factors expanded to one per value, 5 arrays of C W (NULL: scalar) */
    double (*acc)[9][3]; /* per thread */
} proj_job;

#ifdef LX_SH9_AVX2
/* M[k][c] = sum over the row of value(c) x factor k, the row read as one array of C W floats
 * against the factors expanded to the same layout: 4 pixels (12 values) per step, 3 x 4 double
 * lanes whose value index mod C gives the channel. Two passes (k < 3, k >= 3) keep every
 * accumulator in a register. */
__attribute__((target("avx2,fma"))) static void row_sums_avx2(const float *row, const double *colx, long n, int C,
                                                             double M[5][3])
{
    for (int k = 0; k < 5; k++) M[k][0] = M[k][1] = M[k][2] = 0;
    long n12 = n - n % 12;
    for (int g = 0; g < 2; g++) {
        int k0 = g ? 3 : 0, nk = g ? 2 : 3;
        __m256d a[3][3];
        for (int k = 0; k < 3; k++) a[k][0] = a[k][1] = a[k][2] = _mm256_setzero_pd();
        const double *F0 = colx + (size_t)k0 * n, *F1 = F0 + n, *F2 = F1 + n;
        for (long x = 0; x < n12; x += 12) {
            __m256d v0 = _mm256_cvtps_pd(_mm_loadu_ps(row + x)), v1 = _mm256_cvtps_pd(_mm_loadu_ps(row + x + 4)),
                    v2 = _mm256_cvtps_pd(_mm_loadu_ps(row + x + 8));
            a[0][0] = _mm256_fmadd_pd(v0, _mm256_loadu_pd(F0 + x), a[0][0]);
            a[0][1] = _mm256_fmadd_pd(v1, _mm256_loadu_pd(F0 + x + 4), a[0][1]);
            a[0][2] = _mm256_fmadd_pd(v2, _mm256_loadu_pd(F0 + x + 8), a[0][2]);
            a[1][0] = _mm256_fmadd_pd(v0, _mm256_loadu_pd(F1 + x), a[1][0]);
            a[1][1] = _mm256_fmadd_pd(v1, _mm256_loadu_pd(F1 + x + 4), a[1][1]);
            a[1][2] = _mm256_fmadd_pd(v2, _mm256_loadu_pd(F1 + x + 8), a[1][2]);
            if (nk == 3) {
                a[2][0] = _mm256_fmadd_pd(v0, _mm256_loadu_pd(F2 + x), a[2][0]);
                a[2][1] = _mm256_fmadd_pd(v1, _mm256_loadu_pd(F2 + x + 4), a[2][1]);
                a[2][2] = _mm256_fmadd_pd(v2, _mm256_loadu_pd(F2 + x + 8), a[2][2]);
            }
        }
        for (int k = 0; k < nk; k++) {
            double l[12];
            for (int q = 0; q < 3; q++) _mm256_storeu_pd(l + 4 * q, a[k][q]);
            for (int i = 0; i < 12; i++) M[k0 + k][i % C] += l[i];
            const double *F = colx + (size_t)(k0 + k) * n;
            for (long x = n12; x < n; x++) M[k0 + k][x % C] += row[x] * F[x];
        }
    }
}
#endif

static void proj_rows(void *arg, long j0, long j1, int t)
{
    proj_job *J = arg;
    const lx_envmap *m = J->map;
    int W = m->width, H = m->height, C = m->channels;
    double dt = LX__PI / H;
    double acc[9][3];
    memset(acc, 0, sizeof acc);
    for (long j = j0; j < j1; j++) {
        double t0 = j * dt, t1 = (j + 1) * dt, tc = (j + 0.5) * dt;
        double c0 = cos(t0), c1 = cos(t1), s0 = sin(t0), s1 = sin(t1);
        double T0 = 2 * sin(tc) * sin(0.5 * dt);              /* int sin t */
        double T1 = 0.5 * (dt - cos(2 * tc) * sin(dt));        /* int sin^2 t */
        double T2 = 0.5 * sin(2 * tc) * sin(dt);               /* int sin t cos t */
        double q = c0 * c0 + c0 * c1 + c1 * c1;
        double T3 = T0 * (1 - q / 3);                          /* int sin^3 t */
        double T4 = 2 * cos(tc) * sin(0.5 * dt) * (s1 * s1 + s1 * s0 + s0 * s0) / 3; /* int sin^2 t cos t */
        double T5 = T0 * (q - 1);                              /* int (3 cos^2 t - 1) sin t */
        double M[5][3] = {{0}};
        const float *row = m->data + (size_t)j * W * C;
#ifdef LX_SH9_AVX2
        if (J->colx) row_sums_avx2(row, J->colx, (long)W * C, C, M);
        else
#endif
        if (C == 3) {
            double a[5][3] = {{0}};
            for (int i = 0; i < W; i++) {
                const double *f = J->colf + 5 * i;
                double r = row[3 * i], g = row[3 * i + 1], b = row[3 * i + 2];
                for (int k = 0; k < 5; k++) {
                    a[k][0] += r * f[k];
                    a[k][1] += g * f[k];
                    a[k][2] += b * f[k];
                }
            }
            memcpy(M, a, sizeof M);
        } else {
            for (int i = 0; i < W; i++) {
                const double *f = J->colf + 5 * i;
                double v = row[i];
                for (int k = 0; k < 5; k++) M[k][0] += v * f[k];
            }
        }
        for (int c = 0; c < C; c++) {
            acc[0][c] += SH_C0 * T0 * M[0][c];
            acc[1][c] += SH_C1 * T1 * M[1][c];
            acc[2][c] += SH_C1 * T2 * M[0][c];
            acc[3][c] += SH_C1 * T1 * M[2][c];
            acc[4][c] += SH_C2 * T3 * M[3][c];
            acc[5][c] += SH_C2 * T4 * M[1][c];
            acc[6][c] += SH_C3 * T5 * M[0][c];
            acc[7][c] += SH_C2 * T4 * M[2][c];
            acc[8][c] += SH_C4 * T3 * M[4][c];
        }
    }
    memcpy(J->acc[t], acc, sizeof acc);
}

lx_status lx_sh9_project(lx_ctx *ctx, const lx_envmap *map, lx_sh9 *out)
{
    LX__NEED_CTX(ctx);
    if (!map || !out || !map->data) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_sh9_project: NULL argument");
    if (map->layout == LX_ENV_CUBE) return lx__sh9_project_cube(ctx, map, out);
    int W = map->width;
    double dp = 2 * LX__PI / W;
    double *colf = lx__alloc_n((size_t)W * 5, sizeof *colf);
    int nt = lx__threads(0, map->height / 8 + 1);
    double(*acc)[9][3] = lx__calloc((size_t)nt, sizeof *acc);
    if (!colf || !acc) {
        lx__free(colf);
        lx__free(acc);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (int i = 0; i < W; i++) {
        double pc = (i + 0.5) * dp, sh = 2 * sin(0.5 * dp);
        colf[5 * i + 0] = dp;                          /* int 1 */
        colf[5 * i + 1] = sin(pc) * sh;                /* int sin p = cos p0 - cos p1 */
        colf[5 * i + 2] = cos(pc) * sh;                /* int cos p = sin p1 - sin p0 */
        colf[5 * i + 3] = 0.5 * sin(2 * pc) * sin(dp); /* int sin p cos p */
        colf[5 * i + 4] = cos(2 * pc) * sin(dp);       /* int cos 2p */
    }
    double *colx = NULL;
#ifdef LX_SH9_AVX2
    if (lx_simd_level() >= LX_SIMD_AVX2) {
        size_t n = (size_t)W * map->channels;
        colx = lx__alloc_n(5 * n, sizeof *colx);
        for (size_t x = 0; colx && x < n; x++)
            for (int k = 0; k < 5; k++) colx[k * n + x] = colf[5 * (x / map->channels) + k];
    }
#endif
    proj_job J = {map, colf, colx, acc};
    lx_status st = lx__parallel_for(ctx, nt, map->height, proj_rows, &J);
    lx__free(colx);
    if (!st) {
        memset(out, 0, sizeof *out);
        out->channels = map->channels;
        for (int t = 0; t < nt; t++)
            for (int k = 0; k < 9; k++)
                for (int c = 0; c < 3; c++) out->c[k][c] += acc[t][k][c];
    }
    lx__free(colf);
    lx__free(acc);
    return st;
}

lx_status lx_sh9_irradiance(lx_ctx *ctx, const lx_sh9 *sh, lx_sh9_window window, const double n[3], double *out)
{
    LX__NEED_CTX(ctx);
    if (!sh || !n || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_sh9_irradiance: NULL argument");
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0) || !isfinite(len)) return lx__error(ctx, LX_EINVAL, NULL, 0, "normal must be a non-zero finite vector");
    double x = n[0] / len, y = n[1] / len, z = n[2] / len, f[3];
    band_factors(window, f);
    double Y[9] = {SH_C0, SH_C1 * y, SH_C1 * z, SH_C1 * x, SH_C2 * x * y, SH_C2 * y * z, SH_C3 * (3 * z * z - 1),
                   SH_C2 * x * z, SH_C4 * (x * x - y * y)};
    for (int c = 0; c < sh->channels; c++) {
        double e = 0;
        for (int k = 0; k < 9; k++) e += f[k == 0 ? 0 : k < 4 ? 1 : 2] * sh->c[k][c] * Y[k];
        out[c] = e;
    }
    return LX_OK;
}

typedef struct recon_job {
    const lx_sh9 *sh;
    const double *f;
    const double *cols; /* cos p, sin p, cos 2p, sin 2p per output column */
    const double *colx; /* AVX2: the 4 expanded to one per output value, 4 arrays of C W (NULL: scalar) */
    lx_envmap *out;
} recon_job;

#ifdef LX_SH9_AVX2
/* out[x] = P + Qc cos p + Qs sin p + U cos 2p + V sin 2p over a row of C W values, 12 at a time;
 * coef[5][12]: the five row coefficients of each of the 12 lanes' channels */
__attribute__((target("avx2,fma"))) static void recon_row_avx2(float *row, const double *colx, long n, int C,
                                                               const double coef[5][12], const double cc[5][3])
{
    long n12 = n - n % 12;
    const double *q0 = colx, *q1 = q0 + n, *q2 = q1 + n, *q3 = q2 + n;
    for (long x = 0; x < n12; x += 12)
        for (int q = 0; q < 3; q++) {
            long y = x + 4 * q;
            __m256d r = _mm256_loadu_pd(coef[0] + 4 * q);
            r = _mm256_fmadd_pd(_mm256_loadu_pd(coef[1] + 4 * q), _mm256_loadu_pd(q0 + y), r);
            r = _mm256_fmadd_pd(_mm256_loadu_pd(coef[2] + 4 * q), _mm256_loadu_pd(q1 + y), r);
            r = _mm256_fmadd_pd(_mm256_loadu_pd(coef[3] + 4 * q), _mm256_loadu_pd(q2 + y), r);
            r = _mm256_fmadd_pd(_mm256_loadu_pd(coef[4] + 4 * q), _mm256_loadu_pd(q3 + y), r);
            _mm_storeu_ps(row + y, _mm256_cvtpd_ps(r));
        }
    for (long x = n12; x < n; x++) {
        int c = (int)(x % C);
        row[x] = (float)(cc[0][c] + cc[1][c] * q0[x] + cc[2][c] * q1[x] + cc[3][c] * q2[x] + cc[4][c] * q3[x]);
    }
}
#endif

static void recon_rows(void *arg, long j0, long j1, int t)
{
    (void)t;
    recon_job *J = arg;
    lx_envmap *o = J->out;
    int W = o->width, C = o->channels;
    const double *f = J->f;
    for (long j = j0; j < j1; j++) {
        double th = (j + 0.5) * LX__PI / o->height, z = cos(th), s = sin(th);
        double P[3], Qc[3], Qs[3], U[3], V[3];
        for (int c = 0; c < C; c++) {
            const double L[9] = {J->sh->c[0][c], J->sh->c[1][c], J->sh->c[2][c], J->sh->c[3][c], J->sh->c[4][c],
                                 J->sh->c[5][c], J->sh->c[6][c], J->sh->c[7][c], J->sh->c[8][c]};
            P[c] = f[0] * SH_C0 * L[0] + f[1] * SH_C1 * L[2] * z + f[2] * SH_C3 * L[6] * (3 * z * z - 1);
            Qc[c] = f[1] * SH_C1 * L[3] * s + f[2] * SH_C2 * L[7] * s * z;
            Qs[c] = f[1] * SH_C1 * L[1] * s + f[2] * SH_C2 * L[5] * s * z;
            U[c] = f[2] * SH_C4 * L[8] * s * s;
            V[c] = f[2] * SH_C2 * L[4] * s * s * 0.5;
        }
        float *row = o->data + (size_t)j * W * C;
#ifdef LX_SH9_AVX2
        if (J->colx) {
            double coef[5][12], cc[5][3];
            for (int c = 0; c < C; c++) cc[0][c] = P[c], cc[1][c] = Qc[c], cc[2][c] = Qs[c], cc[3][c] = U[c], cc[4][c] = V[c];
            for (int k = 0; k < 5; k++)
                for (int i = 0; i < 12; i++) coef[k][i] = cc[k][i % C];
            recon_row_avx2(row, J->colx, (long)W * C, C, (const double(*)[12])coef, (const double(*)[3])cc);
            continue;
        }
#endif
        for (int i = 0; i < W; i++) {
            const double *q = J->cols + 4 * i;
            for (int c = 0; c < C; c++)
                row[(size_t)i * C + c] = (float)(P[c] + Qc[c] * q[0] + Qs[c] * q[1] + U[c] * q[2] + V[c] * q[3]);
        }
    }
}

lx_status lx__irr_sh9_map(lx_ctx *ctx, const lx_sh9 *sh, lx_sh9_window window, lx_envmap *out)
{
    int W = out->width;
    double *cols = lx__alloc_n((size_t)W * 4, sizeof *cols), f[3];
    if (!cols) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    band_factors(window, f);
    for (int i = 0; i < W; i++) {
        double p = (i + 0.5) * 2 * LX__PI / W;
        cols[4 * i] = cos(p);
        cols[4 * i + 1] = sin(p);
        cols[4 * i + 2] = cos(2 * p);
        cols[4 * i + 3] = sin(2 * p);
    }
    double *colx = NULL;
#ifdef LX_SH9_AVX2
    if (lx_simd_level() >= LX_SIMD_AVX2) {
        size_t n = (size_t)W * out->channels;
        colx = lx__alloc_n(4 * n, sizeof *colx);
        for (size_t x = 0; colx && x < n; x++)
            for (int k = 0; k < 4; k++) colx[k * n + x] = cols[4 * (x / out->channels) + k];
    }
#endif
    recon_job J = {sh, f, cols, colx, out};
    lx_status st = lx__parallel_for(ctx, lx__threads(0, out->height / 8 + 1), out->height, recon_rows, &J);
    lx__free(cols);
    lx__free(colx);
    return st;
}
