/* grid_simd.c - the table path of the grid (point model) over a block of points for one luminaire:
 * plain C, and AVX2 + FMA (4 points at a time in double, table values gathered two floats at a
 * time) chosen at run time. Same formulas as lx__table_eval and kernels/grid.cl. */
#include "grid_private.h"

#include <stdlib.h>
#include <string.h>

static void block_c(const lx__plum *p, size_t nb, const double *X, const double *Y, const double *Z, const double *NX,
                    const double *NY, const double *NZ, int shared, double *acc)
{
    for (size_t i = 0; i < nb; i++) {
        size_t j = shared ? 0 : i;
        double w0 = X[i] - p->pos[0], w1 = Y[i] - p->pos[1], w2 = Z[i] - p->pos[2];
        double d2 = w0 * w0 + w1 * w1 + w2 * w2;
        double cx = -(w0 * NX[j] + w1 * NY[j] + w2 * NZ[j]);
        if (!(d2 > 0) || cx <= 0) continue;
        double d = sqrt(d2);
        double x = w0 * p->ex[0] + w1 * p->ex[1] + w2 * p->ex[2];
        double y = w0 * p->ey[0] + w1 * p->ey[1] + w2 * p->ey[2];
        double z = w0 * p->ez[0] + w1 * p->ez[1] + w2 * p->ez[2];
        acc[i] += p->scale * lx__table_eval(p, x, y, z, d) * cx / (d2 * d);
    }
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define HAVE_AVX2_PATH 1

/* Two adjacent floats at T + idx[k] for 4 lanes: first and second as doubles. */
__attribute__((target("avx2,fma"))) static inline void gather2(const float *T, __m128i idx, __m256d *first,
                                                                 __m256d *second)
{
    __m256i g = _mm256_i32gather_epi64((const long long *)(const void *)T, idx, 4);
    __m256 f = _mm256_permutevar8x32_ps(_mm256_castsi256_ps(g), _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7));
    *first = _mm256_cvtps_pd(_mm256_castps256_ps128(f));
    *second = _mm256_cvtps_pd(_mm256_extractf128_ps(f, 1));
}

__attribute__((target("avx2,fma"))) static void block_avx2(const lx__plum *p, size_t nb, const double *X,
                                                             const double *Y, const double *Z, const double *NX,
                                                             const double *NY, const double *NZ, int shared,
                                                             double *acc)
{
    const __m256d px = _mm256_set1_pd(p->pos[0]), py = _mm256_set1_pd(p->pos[1]), pz = _mm256_set1_pd(p->pos[2]);
    const __m256d e00 = _mm256_set1_pd(p->ex[0]), e01 = _mm256_set1_pd(p->ex[1]), e02 = _mm256_set1_pd(p->ex[2]);
    const __m256d e10 = _mm256_set1_pd(p->ey[0]), e11 = _mm256_set1_pd(p->ey[1]), e12 = _mm256_set1_pd(p->ey[2]);
    const __m256d e20 = _mm256_set1_pd(p->ez[0]), e21 = _mm256_set1_pd(p->ez[1]), e22 = _mm256_set1_pd(p->ez[2]);
    const __m256d zero = _mm256_setzero_pd(), sign = _mm256_set1_pd(-0.0), one = _mm256_set1_pd(1);
    const __m256d scale = _mm256_set1_pd(p->scale), nsd = _mm256_set1_pd(p->ns), hoff = _mm256_set1_pd(p->ns + 1);
    const __m256d colsd = _mm256_set1_pd(p->cols), nqd = _mm256_set1_pd(p->nq);
    const __m128i nsm1 = _mm_set1_epi32(p->ns - 1), colsm2 = _mm_set1_epi32(p->cols - 2), colsi = _mm_set1_epi32(p->cols);
    const int axial = p->cols == 1;
    __m256d nx = _mm256_set1_pd(NX[0]), ny = _mm256_set1_pd(NY[0]), nz = _mm256_set1_pd(NZ[0]);
    size_t i = 0;
    for (; i + 4 <= nb; i += 4) {
        __m256d wx = _mm256_sub_pd(_mm256_loadu_pd(X + i), px);
        __m256d wy = _mm256_sub_pd(_mm256_loadu_pd(Y + i), py);
        __m256d wz = _mm256_sub_pd(_mm256_loadu_pd(Z + i), pz);
        if (!shared) {
            nx = _mm256_loadu_pd(NX + i);
            ny = _mm256_loadu_pd(NY + i);
            nz = _mm256_loadu_pd(NZ + i);
        }
        __m256d d2 = _mm256_fmadd_pd(wx, wx, _mm256_fmadd_pd(wy, wy, _mm256_mul_pd(wz, wz)));
        __m256d cx = _mm256_xor_pd(_mm256_fmadd_pd(wx, nx, _mm256_fmadd_pd(wy, ny, _mm256_mul_pd(wz, nz))), sign);
        __m256d ok = _mm256_and_pd(_mm256_cmp_pd(d2, zero, _CMP_GT_OQ), _mm256_cmp_pd(cx, zero, _CMP_GT_OQ));
        if (_mm256_movemask_pd(ok) == 0) continue;
        d2 = _mm256_blendv_pd(one, d2, ok); /* keep the masked-off lanes finite */
        __m256d lx = _mm256_fmadd_pd(wx, e00, _mm256_fmadd_pd(wy, e01, _mm256_mul_pd(wz, e02)));
        __m256d ly = _mm256_fmadd_pd(wx, e10, _mm256_fmadd_pd(wy, e11, _mm256_mul_pd(wz, e12)));
        __m256d lz = _mm256_fmadd_pd(wx, e20, _mm256_fmadd_pd(wy, e21, _mm256_mul_pd(wz, e22)));
        __m256d d = _mm256_sqrt_pd(d2);
        __m256d az = _mm256_andnot_pd(sign, lz);
        __m256d rho2 = _mm256_fmadd_pd(lx, lx, _mm256_mul_pd(ly, ly));
        __m256d t = _mm256_mul_pd(nsd, _mm256_sqrt_pd(_mm256_div_pd(rho2, _mm256_mul_pd(d, _mm256_add_pd(d, az)))));
        t = _mm256_and_pd(_mm256_min_pd(t, nsd), ok);
        __m128i r = _mm_min_epi32(_mm256_cvttpd_epi32(t), nsm1);
        __m256d rd = _mm256_cvtepi32_pd(r);
        __m256d fr = _mm256_sub_pd(t, rd);
        __m256d row = _mm256_add_pd(rd, _mm256_and_pd(_mm256_cmp_pd(lz, zero, _CMP_GT_OQ), hoff));
        __m128i idx = _mm256_cvttpd_epi32(_mm256_mul_pd(row, colsd));
        __m256d I;
        if (axial) {
            __m256d a, b;
            gather2(p->table, idx, &a, &b);
            I = _mm256_fmadd_pd(fr, _mm256_sub_pd(b, a), a);
        } else {
            __m256d ax = _mm256_andnot_pd(sign, lx), ay = _mm256_andnot_pd(sign, ly), s = _mm256_add_pd(ax, ay);
            __m256d yge = _mm256_cmp_pd(ly, zero, _CMP_GE_OQ), xge = _mm256_cmp_pd(lx, zero, _CMP_GE_OQ);
            __m256d xlt = _mm256_cmp_pd(lx, zero, _CMP_LT_OQ);
            /* y >= 0: x >= 0 ? y / s : 1 + |x| / s; y < 0: x < 0 ? 2 + |y| / s : 3 + |x| / s */
            __m256d use_y = _mm256_or_pd(_mm256_and_pd(yge, xge), _mm256_andnot_pd(yge, xlt));
            __m256d num = _mm256_blendv_pd(ax, ay, use_y);
            __m256d base = _mm256_blendv_pd(_mm256_blendv_pd(_mm256_set1_pd(3), _mm256_set1_pd(2), xlt),
                                            _mm256_blendv_pd(one, zero, xge), yge);
            __m256d spos = _mm256_cmp_pd(s, zero, _CMP_GT_OQ);
            __m256d q = _mm256_and_pd(_mm256_add_pd(base, _mm256_div_pd(num, _mm256_blendv_pd(one, s, spos))), spos);
            __m256d tc = _mm256_mul_pd(q, nqd);
            __m128i k = _mm_min_epi32(_mm256_cvttpd_epi32(tc), colsm2);
            __m256d fc = _mm256_sub_pd(tc, _mm256_cvtepi32_pd(k));
            __m128i ia = _mm_add_epi32(idx, k);
            __m256d a0, a1, b0, b1;
            gather2(p->table, ia, &a0, &a1);
            gather2(p->table, _mm_add_epi32(ia, colsi), &b0, &b1);
            __m256d va = _mm256_fmadd_pd(fc, _mm256_sub_pd(a1, a0), a0);
            __m256d vb = _mm256_fmadd_pd(fc, _mm256_sub_pd(b1, b0), b0);
            I = _mm256_fmadd_pd(fr, _mm256_sub_pd(vb, va), va);
        }
        __m256d e = _mm256_div_pd(_mm256_mul_pd(_mm256_mul_pd(scale, I), cx), _mm256_mul_pd(d2, d));
        _mm256_storeu_pd(acc + i, _mm256_add_pd(_mm256_loadu_pd(acc + i), _mm256_and_pd(e, ok)));
    }
    if (i < nb) {
        size_t j = shared ? 0 : i;
        block_c(p, nb - i, X + i, Y + i, Z + i, NX + j, NY + j, NZ + j, shared, acc + i);
    }
}
#endif

int lx__grid_simd(void)
{
#ifdef HAVE_AVX2_PATH
    const char *e = getenv("LX_NOVECTOR");
    if (e && *e && strcmp(e, "0") != 0) return 0;
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return 0;
#endif
}


void lx__grid_table_block(const lx__plum *p, size_t nb, const double *x, const double *y, const double *z,
                          const double *nx, const double *ny, const double *nz, int shared, int simd, double *acc)
{
#ifdef HAVE_AVX2_PATH
    if (simd) {
        block_avx2(p, nb, x, y, z, nx, ny, nz, shared, acc);
        return;
    }
#endif
    block_c(p, nb, x, y, z, nx, ny, nz, shared, acc);
}
