/* grid_simd.c - the table path of the grid (point model) over a block of points for one luminaire:
 * plain C, AVX2 + FMA (4 points at a time in double, table values gathered two floats at a time)
 * and AVX-512 (8 at a time, the same operations), chosen at run time. Same formulas as lx__table_eval and kernels/grid.cl. */
#include "grid_private.h"

#include <stdint.h>
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
        double g = p->scale * cx / (d2 * d); /* the geometric factor: its division overlaps the lookup */
        acc[i] += g * lx__table_eval(p, x, y, z, d);
    }
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define HAVE_AVX2_PATH 1

/* The 8 bytes (two adjacent floats) at T + i, in the low half of a vector (movq: no alignment). */
#define LX_PAIR(T, i) _mm_loadl_epi64((const __m128i_u *)(const void *)((T) + (i)))

/* Two adjacent floats at T + idx[k] for 4 lanes: first and second as doubles (the asymmetric
 * table; an axial one reads its pairs with pairs4). Four 8-byte loads rather than vpgatherdq: on
 * AMD Zen the gather is microcoded, and this loop is bound by the latency of one point's chain,
 * which the gather lengthened (with the division moved off the chain's end, below: 1 thread,
 * axial table read through here, Zen 4, 200 -> 250 M point-luminaires/s). */
__attribute__((target("avx2,fma"))) static inline void gather2(const float *T, __m128i idx, __m256d *first,
                                                                 __m256d *second)
{
    __m128 p01 = _mm_castsi128_ps(_mm_unpacklo_epi64(LX_PAIR(T, _mm_cvtsi128_si32(idx)), LX_PAIR(T, _mm_extract_epi32(idx, 1))));
    __m128 p23 = _mm_castsi128_ps(_mm_unpacklo_epi64(LX_PAIR(T, _mm_extract_epi32(idx, 2)), LX_PAIR(T, _mm_extract_epi32(idx, 3))));
    /* p01 = a0 b0 a1 b1, p23 = a2 b2 a3 b3 */
    *first = _mm256_cvtps_pd(_mm_shuffle_ps(p01, p23, _MM_SHUFFLE(2, 0, 2, 0)));
    *second = _mm256_cvtps_pd(_mm_shuffle_ps(p01, p23, _MM_SHUFFLE(3, 1, 3, 1)));
}

/* The (value, step) pairs of an axial table at rows idx[k] for 4 lanes (lx__plum.pair): four
 * 16-byte loads (aligned: the pairs sit at a 16-byte offset of a malloc block), two inserts and
 * two unpacks; no conversion, no subtraction. */
__attribute__((target("avx2,fma"))) static inline void pairs4(const double *P, __m128i idx, __m256d *value,
                                                                __m256d *step)
{
    __m256d x02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(P + 2 * _mm_cvtsi128_si32(idx))),
                                       _mm_loadu_pd(P + 2 * _mm_extract_epi32(idx, 2)), 1);
    __m256d x13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(P + 2 * _mm_extract_epi32(idx, 1))),
                                       _mm_loadu_pd(P + 2 * _mm_extract_epi32(idx, 3)), 1);
    *value = _mm256_unpacklo_pd(x02, x13);
    *step = _mm256_unpackhi_pd(x02, x13);
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
    const __m256d nqd = _mm256_set1_pd(p->nq);
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
        /* the geometric factor scale cos(eps) / d^3 first: its division runs beside the lookup
         * instead of after it (the loop is bound by the latency of one point's chain) */
        __m256d g = _mm256_and_pd(_mm256_div_pd(_mm256_mul_pd(scale, cx), _mm256_mul_pd(d2, d)), ok);
        __m256d az = _mm256_andnot_pd(sign, lz);
        __m256d rho2 = _mm256_fmadd_pd(lx, lx, _mm256_mul_pd(ly, ly));
        __m256d t = _mm256_mul_pd(nsd, _mm256_sqrt_pd(_mm256_div_pd(rho2, _mm256_mul_pd(d, _mm256_add_pd(d, az)))));
        t = _mm256_and_pd(_mm256_min_pd(t, nsd), ok);
        __m128i r = _mm_min_epi32(_mm256_cvttpd_epi32(t), nsm1);
        __m256d rd = _mm256_cvtepi32_pd(r);
        __m256d fr = _mm256_sub_pd(t, rd);
        /* first index (row + hemisphere offset) x cols in integers: the offset is ready early */
        __m128i hrow = _mm256_cvttpd_epi32(_mm256_and_pd(_mm256_cmp_pd(lz, zero, _CMP_GT_OQ), hoff));
        __m128i idx = _mm_add_epi32(r, hrow);
        if (!axial) idx = _mm_mullo_epi32(idx, colsi);
        __m256d I;
        if (axial) {
            __m256d a, st;
            pairs4(p->pair, idx, &a, &st);
            I = _mm256_fmadd_pd(fr, st, a);
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
        _mm256_storeu_pd(acc + i, _mm256_add_pd(_mm256_loadu_pd(acc + i), _mm256_mul_pd(g, I)));
    }
    if (i < nb) {
        size_t j = shared ? 0 : i;
        block_c(p, nb - i, X + i, Y + i, Z + i, NX + j, NY + j, NZ + j, shared, acc + i);
    }
}

/* The AVX-512 twin of block_avx2: 8 points at a time, the same operations in the same order. The
 * table pairs are loaded as in gather2 (eight 8-byte loads: vpgatherdq is microcoded on Zen). */
__attribute__((target("avx512f,avx512dq,avx512vl,fma"))) static inline void gather2x8(const float *T, __m256i idx,
                                                                                       __m512d *first, __m512d *second)
{
    int32_t k[8];
    _mm256_storeu_si256((__m256i *)(void *)k, idx);
    __m128 p01 = _mm_castsi128_ps(_mm_unpacklo_epi64(LX_PAIR(T, k[0]), LX_PAIR(T, k[1])));
    __m128 p23 = _mm_castsi128_ps(_mm_unpacklo_epi64(LX_PAIR(T, k[2]), LX_PAIR(T, k[3])));
    __m128 p45 = _mm_castsi128_ps(_mm_unpacklo_epi64(LX_PAIR(T, k[4]), LX_PAIR(T, k[5])));
    __m128 p67 = _mm_castsi128_ps(_mm_unpacklo_epi64(LX_PAIR(T, k[6]), LX_PAIR(T, k[7])));
    __m256 a = _mm256_set_m128(_mm_shuffle_ps(p45, p67, _MM_SHUFFLE(2, 0, 2, 0)), _mm_shuffle_ps(p01, p23, _MM_SHUFFLE(2, 0, 2, 0)));
    __m256 b = _mm256_set_m128(_mm_shuffle_ps(p45, p67, _MM_SHUFFLE(3, 1, 3, 1)), _mm_shuffle_ps(p01, p23, _MM_SHUFFLE(3, 1, 3, 1)));
    *first = _mm512_cvtps_pd(a);
    *second = _mm512_cvtps_pd(b);
}

/* pairs4 for 8 lanes: eight 16-byte loads into two vectors of four pairs, two unpacks. */
__attribute__((target("avx512f,avx512dq,avx512vl,fma"))) static inline void pairs8(const double *P, __m256i idx,
                                                                                    __m512d *value, __m512d *step)
{
    int32_t k[8];
    _mm256_storeu_si256((__m256i *)(void *)k, idx);
    __m512d x = _mm512_castpd128_pd512(_mm_loadu_pd(P + 2 * k[0])), y = _mm512_castpd128_pd512(_mm_loadu_pd(P + 2 * k[1]));
    x = _mm512_insertf64x2(x, _mm_loadu_pd(P + 2 * k[2]), 1);
    y = _mm512_insertf64x2(y, _mm_loadu_pd(P + 2 * k[3]), 1);
    x = _mm512_insertf64x2(x, _mm_loadu_pd(P + 2 * k[4]), 2);
    y = _mm512_insertf64x2(y, _mm_loadu_pd(P + 2 * k[5]), 2);
    x = _mm512_insertf64x2(x, _mm_loadu_pd(P + 2 * k[6]), 3);
    y = _mm512_insertf64x2(y, _mm_loadu_pd(P + 2 * k[7]), 3);
    *value = _mm512_unpacklo_pd(x, y);
    *step = _mm512_unpackhi_pd(x, y);
}

__attribute__((target("avx512f,avx512dq,avx512vl,fma"))) static void block_avx512(const lx__plum *p, size_t nb,
                                                                                  const double *X, const double *Y,
                                                                                  const double *Z, const double *NX,
                                                                                  const double *NY, const double *NZ,
                                                                                  int shared, double *acc)
{
    const __m512d px = _mm512_set1_pd(p->pos[0]), py = _mm512_set1_pd(p->pos[1]), pz = _mm512_set1_pd(p->pos[2]);
    const __m512d e00 = _mm512_set1_pd(p->ex[0]), e01 = _mm512_set1_pd(p->ex[1]), e02 = _mm512_set1_pd(p->ex[2]);
    const __m512d e10 = _mm512_set1_pd(p->ey[0]), e11 = _mm512_set1_pd(p->ey[1]), e12 = _mm512_set1_pd(p->ey[2]);
    const __m512d e20 = _mm512_set1_pd(p->ez[0]), e21 = _mm512_set1_pd(p->ez[1]), e22 = _mm512_set1_pd(p->ez[2]);
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1);
    const __m512d scale = _mm512_set1_pd(p->scale), nsd = _mm512_set1_pd(p->ns), nqd = _mm512_set1_pd(p->nq);
    const __m256i nsm1 = _mm256_set1_epi32(p->ns - 1), colsm2 = _mm256_set1_epi32(p->cols - 2), colsi = _mm256_set1_epi32(p->cols);
    const __m256i hoffi = _mm256_set1_epi32(p->ns + 1);
    const int axial = p->cols == 1;
    __m512d nx = _mm512_set1_pd(NX[0]), ny = _mm512_set1_pd(NY[0]), nz = _mm512_set1_pd(NZ[0]);
    size_t i = 0;
    for (; i + 8 <= nb; i += 8) {
        __m512d wx = _mm512_sub_pd(_mm512_loadu_pd(X + i), px);
        __m512d wy = _mm512_sub_pd(_mm512_loadu_pd(Y + i), py);
        __m512d wz = _mm512_sub_pd(_mm512_loadu_pd(Z + i), pz);
        if (!shared) {
            nx = _mm512_loadu_pd(NX + i);
            ny = _mm512_loadu_pd(NY + i);
            nz = _mm512_loadu_pd(NZ + i);
        }
        __m512d d2 = _mm512_fmadd_pd(wx, wx, _mm512_fmadd_pd(wy, wy, _mm512_mul_pd(wz, wz)));
        __m512d cx = _mm512_sub_pd(zero, _mm512_fmadd_pd(wx, nx, _mm512_fmadd_pd(wy, ny, _mm512_mul_pd(wz, nz))));
        __mmask8 ok = _mm512_cmp_pd_mask(d2, zero, _CMP_GT_OQ) & _mm512_cmp_pd_mask(cx, zero, _CMP_GT_OQ);
        if (!ok) continue;
        d2 = _mm512_mask_blend_pd(ok, one, d2); /* keep the masked-off lanes finite */
        __m512d lx = _mm512_fmadd_pd(wx, e00, _mm512_fmadd_pd(wy, e01, _mm512_mul_pd(wz, e02)));
        __m512d ly = _mm512_fmadd_pd(wx, e10, _mm512_fmadd_pd(wy, e11, _mm512_mul_pd(wz, e12)));
        __m512d lz = _mm512_fmadd_pd(wx, e20, _mm512_fmadd_pd(wy, e21, _mm512_mul_pd(wz, e22)));
        __m512d d = _mm512_sqrt_pd(d2);
        __m512d g = _mm512_maskz_div_pd(ok, _mm512_mul_pd(scale, cx), _mm512_mul_pd(d2, d)); /* as in block_avx2 */
        __m512d az = _mm512_abs_pd(lz);
        __m512d rho2 = _mm512_fmadd_pd(lx, lx, _mm512_mul_pd(ly, ly));
        __m512d t = _mm512_mul_pd(nsd, _mm512_sqrt_pd(_mm512_div_pd(rho2, _mm512_mul_pd(d, _mm512_add_pd(d, az)))));
        t = _mm512_maskz_mov_pd(ok, _mm512_min_pd(t, nsd));
        __m256i r = _mm256_min_epi32(_mm512_cvttpd_epi32(t), nsm1);
        __m512d rd = _mm512_cvtepi32_pd(r);
        __m512d fr = _mm512_sub_pd(t, rd);
        __m256i hrow = _mm256_maskz_mov_epi32(_mm512_cmp_pd_mask(lz, zero, _CMP_GT_OQ), hoffi);
        __m256i idx = _mm256_add_epi32(r, hrow);
        if (!axial) idx = _mm256_mullo_epi32(idx, colsi);
        __m512d I;
        if (axial) {
            __m512d a, st;
            pairs8(p->pair, idx, &a, &st);
            I = _mm512_fmadd_pd(fr, st, a);
        } else {
            __m512d ax = _mm512_abs_pd(lx), ay = _mm512_abs_pd(ly), s = _mm512_add_pd(ax, ay);
            __mmask8 yge = _mm512_cmp_pd_mask(ly, zero, _CMP_GE_OQ), xge = _mm512_cmp_pd_mask(lx, zero, _CMP_GE_OQ);
            __mmask8 xlt = _mm512_cmp_pd_mask(lx, zero, _CMP_LT_OQ);
            /* y >= 0: x >= 0 ? y / s : 1 + |x| / s; y < 0: x < 0 ? 2 + |y| / s : 3 + |x| / s */
            __mmask8 use_y = (yge & xge) | (~yge & xlt);
            __m512d num = _mm512_mask_blend_pd(use_y, ax, ay);
            __m512d base = _mm512_mask_blend_pd(yge, _mm512_mask_blend_pd(xlt, _mm512_set1_pd(3), _mm512_set1_pd(2)),
                                                _mm512_mask_blend_pd(xge, one, zero));
            __mmask8 spos = _mm512_cmp_pd_mask(s, zero, _CMP_GT_OQ);
            __m512d q = _mm512_maskz_add_pd(spos, base, _mm512_div_pd(num, _mm512_mask_blend_pd(spos, one, s)));
            __m512d tc = _mm512_mul_pd(q, nqd);
            __m256i k = _mm256_min_epi32(_mm512_cvttpd_epi32(tc), colsm2);
            __m512d fc = _mm512_sub_pd(tc, _mm512_cvtepi32_pd(k));
            __m256i ia = _mm256_add_epi32(idx, k);
            __m512d a0, a1, b0, b1;
            gather2x8(p->table, ia, &a0, &a1);
            gather2x8(p->table, _mm256_add_epi32(ia, colsi), &b0, &b1);
            __m512d va = _mm512_fmadd_pd(fc, _mm512_sub_pd(a1, a0), a0);
            __m512d vb = _mm512_fmadd_pd(fc, _mm512_sub_pd(b1, b0), b0);
            I = _mm512_fmadd_pd(fr, _mm512_sub_pd(vb, va), va);
        }
        _mm512_storeu_pd(acc + i, _mm512_add_pd(_mm512_loadu_pd(acc + i), _mm512_mul_pd(g, I)));
    }
    if (i < nb) {
        size_t j = shared ? 0 : i;
        block_avx2(p, nb - i, X + i, Y + i, Z + i, NX + j, NY + j, NZ + j, shared, acc + i);
    }
}
#endif

int lx__grid_simd(void)
{
#ifdef HAVE_AVX2_PATH
    return (int)lx_simd_level();
#else
    return 0;
#endif
}


void lx__grid_table_block(const lx__plum *p, size_t nb, const double *x, const double *y, const double *z,
                          const double *nx, const double *ny, const double *nz, int shared, int simd, double *acc)
{
#ifdef HAVE_AVX2_PATH
    if (simd == 2) {
        block_avx512(p, nb, x, y, z, nx, ny, nz, shared, acc);
        return;
    }
    if (simd) {
        block_avx2(p, nb, x, y, z, nx, ny, nz, shared, acc);
        return;
    }
#endif
    block_c(p, nb, x, y, z, nx, ny, nz, shared, acc);
}
