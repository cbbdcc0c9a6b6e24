/* batch.c - batch spectral integration: N spectra on one uniform grid against K weighting
 * functions (cie15 rule), on the CPU (AVX-512 or AVX2/FMA, pthreads, double accumulation) or on
 * OpenCL (kernels/spd_batch.cl, chunked by CL_DEVICE_MAX_MEM_ALLOC_SIZE); backend choice; resampling. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#define LX_HAVE_AVX2_PATH 1
#else
#define LX_HAVE_AVX2_PATH 0
#endif

/* Break-even of LX_BACKEND_AUTO, in samples (spectra x wavelengths), measured with `luxcalc bench
 * spd` (README "opencl"). Cold: OpenCL not yet initialised on the context (device start-up and
 * program build, about 0.3-1 s on PoCL); warm: only the per-call overhead remains. A CPU-type
 * OpenCL device runs on the same cores as the CPU path and never repays anything, so AUTO
 * keeps the CPU path for it. */
#define LX_AUTO_COLD_SAMPLES 2000000000.0 /* ~4e6 spectra of 471 samples */
#define LX_AUTO_WARM_SAMPLES 50000000.0   /* ~1e5 spectra of 471 samples */

/* ---- weights ---- */

/* The exact weights of a band function fn on the grid: sample j weighs the integral of its hat
 * function (1 at the sample, 0 at its neighbours; half a hat at the grid's ends, the spectrum being
 * zero outside them) times fn, so that the dot product is lx_spd_integrate's exact method. */
static void band_weights(const lx_spd *fn, double start_nm, double step_nm, size_t n_lambda, double *w)
{
    size_t k = 0; /* fn's first segment that can reach the current hat */
    for (size_t j = 0; j < n_lambda; j++) {
        double l[3], v[3];
        size_t n = 0;
        if (j > 0) l[n] = start_nm + (double)(j - 1) * step_nm, v[n++] = 0.0;
        l[n] = start_nm + (double)j * step_nm, v[n++] = 1.0;
        if (j + 1 < n_lambda) l[n] = start_nm + (double)(j + 1) * step_nm, v[n++] = 0.0;
        w[j] = 0.0;
        if (n < 2 || fn->n < 2 || l[n - 1] <= fn->lambda_nm[0] || l[0] >= fn->lambda_nm[fn->n - 1]) continue;
        while (k + 2 < fn->n && fn->lambda_nm[k + 1] <= l[0]) k++;
        lx_spd hat = {NULL, n, l, v}, part = {NULL, fn->n - k, fn->lambda_nm + k, fn->value + k};
        w[j] = lx__exact_product(&hat, &part);
    }
}

lx_status lx__batch_weights(lx_ctx *ctx, const lx_function *fns, size_t k, double start_nm, double step_nm,
                            size_t n_lambda, double *w)
{
    for (size_t f = 0; f < k; f++) {
        lx_spd fn;
        lx_status st = lx_function_get(ctx, fns[f], &fn);
        if (st) return st;
        if (lx__fn_band_exact(fns[f])) {
            band_weights(&fn, start_nm, step_nm, n_lambda, w + f * n_lambda);
            continue;
        }
        /* lx__interp at increasing wavelengths, its bracket found by walking instead of bisection
         * (the same bracket, so the same values) */
        size_t lo = 0;
        for (size_t j = 0; j < n_lambda; j++) {
            double x = start_nm + (double)j * step_nm, v = 0.0;
            if (fn.n > 0 && x >= fn.lambda_nm[0] && x <= fn.lambda_nm[fn.n - 1]) {
                while (lo + 2 < fn.n && fn.lambda_nm[lo + 1] <= x) lo++;
                size_t hi = lo + 1 < fn.n ? lo + 1 : lo;
                if (x == fn.lambda_nm[lo]) v = fn.value[lo];
                else if (x == fn.lambda_nm[hi]) v = fn.value[hi];
                else v = fn.value[lo] + (x - fn.lambda_nm[lo]) / (fn.lambda_nm[hi] - fn.lambda_nm[lo]) * (fn.value[hi] - fn.value[lo]);
            }
            w[f * n_lambda + j] = v * step_nm;
        }
    }
    return LX_OK;
}

/* ---- the CPU path ---- */

typedef struct cpu_job {
    const lx_batch *b;
    size_t stride, k, k4, nb; /* k4: k rounded up to 4; nb: blocks of 4 wavelengths */
    size_t nb8;               /* blocks of 8 wavelengths (AVX-512 layout) */
    const double *w;          /* row-major k x n_lambda */
    const double *w4;         /* AVX2 layout: [group][block][4 functions][4 lanes], zero padded */
    const double *w8;         /* AVX-512 layout: [group][block][4 functions][8 lanes], 64-byte aligned */
    double *out;
    size_t i0, i1;            /* scalar_rows / avx2_rows: this range */
    _Atomic size_t *next;     /* the shared work counter: threads take LX_CPU_GRAIN spectra at a time */
    size_t n_total;
    int vector;               /* 0 scalar, 1 AVX2, 2 AVX-512 */
} cpu_job;

/* Spectra a thread takes at a time: small enough that a thread descheduled by another process
 * (the cores are shared) leaves little work behind, large enough that the counter costs nothing. */
#define LX_CPU_GRAIN 256

static void scalar_rows(const cpu_job *J)
{
    const lx_batch *b = J->b;
    size_t n = b->n_lambda;
    for (size_t i = J->i0; i < J->i1; i++) {
        for (size_t f = 0; f < J->k; f++) {
            const double *wf = J->w + f * n;
            double a0 = 0, a1 = 0, a2 = 0, a3 = 0;
            size_t j = 0;
            if (b->dtype == LX_F32) {
                const float *r = (const float *)b->values + i * J->stride;
                for (; j + 4 <= n; j += 4) {
                    a0 += (double)r[j] * wf[j];
                    a1 += (double)r[j + 1] * wf[j + 1];
                    a2 += (double)r[j + 2] * wf[j + 2];
                    a3 += (double)r[j + 3] * wf[j + 3];
                }
                for (; j < n; j++) a0 += (double)r[j] * wf[j];
            } else {
                const double *r = (const double *)b->values + i * J->stride;
                for (; j + 4 <= n; j += 4) {
                    a0 += r[j] * wf[j];
                    a1 += r[j + 1] * wf[j + 1];
                    a2 += r[j + 2] * wf[j + 2];
                    a3 += r[j + 3] * wf[j + 3];
                }
                for (; j < n; j++) a0 += r[j] * wf[j];
            }
            J->out[i * J->k + f] = (a0 + a1) + (a2 + a3);
        }
    }
}

#if LX_HAVE_AVX2_PATH
/* Software prefetch distance in rows, into L2 (_MM_HINT_T1): DRAM latency is not hidden by the
 * hardware prefetcher alone, and prefetching into L1 (T0) evicted the weights the loop reads from
 * there (L1 is 32-48 KB; 8 rows ahead x 4 spectra in flight is 15 KB, the weights 15 KB): with T0
 * 10.5-10.9 M spectra/s on 2 Zen 4 cores from DRAM, with T1 15-16.8 M/s, the read bandwidth. */
#ifndef LX_PF_ROWS
#define LX_PF_ROWS 8
#endif
__attribute__((target("avx2,fma"))) static inline double hsum4(__m256d v)
{
    __m128d s = _mm_add_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
    return _mm_cvtsd_f64(_mm_add_sd(s, _mm_unpackhi_pd(s, s)));
}

/* AVX2 (4 doubles a vector): NS spectra per pass share every weight load (four functions x four
 * wavelengths a block), each spectrum's four samples loaded (and converted) once for four FMAs
 * into double accumulators; 2 spectra x 4 functions of accumulators, 4 weights and the samples
 * fill the 16 registers. The last partial block uses masked loads. */
#define LX_AVX2_BLOCK(NS, LOADX, ...)                                                                    \
    {                                                                                                    \
        const double *wq = wg + q * 16;                                                                  \
        __m256d w0 = _mm256_load_pd(wq), w1 = _mm256_load_pd(wq + 4);                                   \
        __m256d w2 = _mm256_load_pd(wq + 8), w3 = _mm256_load_pd(wq + 12);                               \
        _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++) {                                           \
            __VA_ARGS__;                                                                                 \
            __m256d x = LOADX;                                                                           \
            acc[s][0] = _mm256_fmadd_pd(x, w0, acc[s][0]);                                               \
            acc[s][1] = _mm256_fmadd_pd(x, w1, acc[s][1]);                                               \
            acc[s][2] = _mm256_fmadd_pd(x, w2, acc[s][2]);                                               \
            acc[s][3] = _mm256_fmadd_pd(x, w3, acc[s][3]);                                               \
        }                                                                                                \
    }
#define LX_AVX2_ROWS(NAME, NS, T, LOADX, LOADXM, MASK)                                                   \
    __attribute__((target("avx2,fma"))) static void NAME(const cpu_job *J, size_t i)                     \
    {                                                                                                    \
        size_t n = J->b->n_lambda, nb = J->nb, full = n / 4, rem = n % 4;                                \
        const MASK m = LX_AVX2_MASK_##T(rem);                                                            \
        const T *r[NS];                                                                                  \
        _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++) r[s] = (const T *)J->b->values + (i + (size_t)s) * J->stride; \
        for (size_t g = 0; g < J->k4 / 4; g++) {                                                         \
            const double *wg = J->w4 + g * nb * 16;                                                      \
            __m256d acc[NS][4];                                                                          \
            _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++)                                         \
                _Pragma("GCC unroll 4") for (int f = 0; f < 4; f++) acc[s][f] = _mm256_setzero_pd();     \
            size_t q = 0;                                                                                \
            for (; q < full; q++)                                                                        \
                LX_AVX2_BLOCK(NS, LOADX(r[s] + 4 * q),                                                   \
                              _mm_prefetch((const char *)((uintptr_t)(r[s] + 4 * q) +                    \
                                                          LX_PF_ROWS * J->stride * sizeof(T)),           \
                                           _MM_HINT_T1))                                                 \
            if (rem) LX_AVX2_BLOCK(NS, LOADXM(r[s] + 4 * q, m), (void)0)                                 \
            _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++)                                         \
                for (size_t f = 0; f < 4 && 4 * g + f < J->k; f++)                                       \
                    J->out[(i + (size_t)s) * J->k + 4 * g + f] = hsum4(acc[s][f]);                       \
        }                                                                                                \
    }
#define LX_AVX2_MASK_float(rem) _mm_setr_epi32(rem > 0 ? -1 : 0, rem > 1 ? -1 : 0, rem > 2 ? -1 : 0, 0)
#define LX_AVX2_MASK_double(rem) _mm256_setr_epi64x(rem > 0 ? -1 : 0, rem > 1 ? -1 : 0, rem > 2 ? -1 : 0, 0)
#define LX_LD4_F32(p) _mm256_cvtps_pd(_mm_loadu_ps(p))
#define LX_LDM4_F32(p, m) _mm256_cvtps_pd(_mm_maskload_ps(p, m))
#define LX_LD4_F64(p) _mm256_loadu_pd(p)
#define LX_LDM4_F64(p, m) _mm256_maskload_pd(p, m)
LX_AVX2_ROWS(avx2_f32_x2, 2, float, LX_LD4_F32, LX_LDM4_F32, __m128i)
LX_AVX2_ROWS(avx2_f32_x1, 1, float, LX_LD4_F32, LX_LDM4_F32, __m128i)
LX_AVX2_ROWS(avx2_f64_x2, 2, double, LX_LD4_F64, LX_LDM4_F64, __m256i)
LX_AVX2_ROWS(avx2_f64_x1, 1, double, LX_LD4_F64, LX_LDM4_F64, __m256i)
#undef LX_AVX2_ROWS
#undef LX_AVX2_BLOCK

static void avx2_rows(const cpu_job *J)
{
    int f32 = J->b->dtype == LX_F32;
    size_t i = J->i0;
    for (; i + 2 <= J->i1; i += 2) f32 ? avx2_f32_x2(J, i) : avx2_f64_x2(J, i);
    for (; i < J->i1; i++) f32 ? avx2_f32_x1(J, i) : avx2_f64_x1(J, i);
}

/* AVX-512 (8 doubles a vector): NS spectra per pass share every weight load (four functions x
 * eight wavelengths a block), each spectrum's eight samples loaded (and converted) once for four
 * FMAs. Accumulation stays in double, one accumulator per spectrum and function: the same terms as
 * the scalar path summed in another order (the same error bound). The last block is masked. */
#define LX_AVX512_ROWS(NAME, NS, T, LOADX, LOADXM)                                                       \
    __attribute__((target("avx512f,avx512vl,avx512dq,fma"))) static void NAME(const cpu_job *J, size_t i) \
    {                                                                                                    \
        size_t n = J->b->n_lambda, nb8 = J->nb8, full = n / 8;                                           \
        __mmask8 m = (__mmask8)((1u << (n % 8)) - 1u);                                                   \
        const T *r[NS];                                                                                  \
        _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++) r[s] = (const T *)J->b->values + (i + (size_t)s) * J->stride;       \
        for (size_t g = 0; g < J->k4 / 4; g++) {                                                         \
            const double *wg = J->w8 + g * nb8 * 32;                                                     \
            __m512d acc[NS][4];                                                                          \
            _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++)                                                                 \
                _Pragma("GCC unroll 4") for (int f = 0; f < 4; f++) acc[s][f] = _mm512_setzero_pd();                             \
            size_t q = 0;                                                                                \
            for (; q < full; q++) {                                                                      \
                const double *wq = wg + q * 32;                                                          \
                __m512d w0 = _mm512_load_pd(wq), w1 = _mm512_load_pd(wq + 8);                            \
                __m512d w2 = _mm512_load_pd(wq + 16), w3 = _mm512_load_pd(wq + 24);                      \
                _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++) {                                                           \
                    _mm_prefetch((const char *)((uintptr_t)(r[s] + 8 * q) + LX_PF_ROWS * J->stride * sizeof(T)), \
                                 _MM_HINT_T1);                                                           \
                    __m512d x = LOADX(r[s] + 8 * q);                                                     \
                    acc[s][0] = _mm512_fmadd_pd(x, w0, acc[s][0]);                                       \
                    acc[s][1] = _mm512_fmadd_pd(x, w1, acc[s][1]);                                       \
                    acc[s][2] = _mm512_fmadd_pd(x, w2, acc[s][2]);                                       \
                    acc[s][3] = _mm512_fmadd_pd(x, w3, acc[s][3]);                                       \
                }                                                                                        \
            }                                                                                            \
            if (m) {                                                                                     \
                const double *wq = wg + q * 32;                                                          \
                __m512d w0 = _mm512_load_pd(wq), w1 = _mm512_load_pd(wq + 8);                            \
                __m512d w2 = _mm512_load_pd(wq + 16), w3 = _mm512_load_pd(wq + 24);                      \
                _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++) {                                                           \
                    __m512d x = LOADXM(m, r[s] + 8 * q);                                                 \
                    acc[s][0] = _mm512_fmadd_pd(x, w0, acc[s][0]);                                       \
                    acc[s][1] = _mm512_fmadd_pd(x, w1, acc[s][1]);                                       \
                    acc[s][2] = _mm512_fmadd_pd(x, w2, acc[s][2]);                                       \
                    acc[s][3] = _mm512_fmadd_pd(x, w3, acc[s][3]);                                       \
                }                                                                                        \
            }                                                                                            \
            _Pragma("GCC unroll 4") for (int s = 0; s < NS; s++)                                                                 \
                for (size_t f = 0; f < 4 && 4 * g + f < J->k; f++)                                       \
                    J->out[(i + (size_t)s) * J->k + 4 * g + f] = _mm512_reduce_add_pd(acc[s][f]);        \
        }                                                                                                \
    }
#define LX_LD_F32(p) _mm512_cvtps_pd(_mm256_loadu_ps(p))
#define LX_LDM_F32(m, p) _mm512_cvtps_pd(_mm256_maskz_loadu_ps(m, p))
#define LX_LD_F64(p) _mm512_loadu_pd(p)
#define LX_LDM_F64(m, p) _mm512_maskz_loadu_pd(m, p)
LX_AVX512_ROWS(avx512_f32_x4, 4, float, LX_LD_F32, LX_LDM_F32)
LX_AVX512_ROWS(avx512_f32_x1, 1, float, LX_LD_F32, LX_LDM_F32)
LX_AVX512_ROWS(avx512_f64_x4, 4, double, LX_LD_F64, LX_LDM_F64)
LX_AVX512_ROWS(avx512_f64_x1, 1, double, LX_LD_F64, LX_LDM_F64)
#undef LX_AVX512_ROWS

static void avx512_rows(const cpu_job *J, size_t i0, size_t i1)
{
    int f32 = J->b->dtype == LX_F32;
    size_t i = i0;
    for (; i + 4 <= i1; i += 4) f32 ? avx512_f32_x4(J, i) : avx512_f64_x4(J, i);
    for (; i < i1; i++) f32 ? avx512_f32_x1(J, i) : avx512_f64_x1(J, i);
}

#endif

static void cpu_thread(void *arg, int t)
{
    (void)t;
    cpu_job J = *(const cpu_job *)arg;
    for (;;) {
        size_t i0 = atomic_fetch_add_explicit(J.next, LX_CPU_GRAIN, memory_order_relaxed);
        if (i0 >= J.n_total) break;
        size_t i1 = i0 + LX_CPU_GRAIN < J.n_total ? i0 + LX_CPU_GRAIN : J.n_total;
#if LX_HAVE_AVX2_PATH
        if (J.vector == 2) {
            avx512_rows(&J, i0, i1);
            continue;
        }
        if (J.vector == 1) {
            J.i0 = i0, J.i1 = i1;
            avx2_rows(&J);
            continue;
        }
#endif
        J.i0 = i0, J.i1 = i1;
        scalar_rows(&J);
    }
}

/* The weights of one (functions, grid) in the three layouts the CPU loops read. A context keeps
 * the last one it made (a context is used by one thread at a time): a file streamed in small
 * chunks integrates each against the same weights, and making them costs more than a chunk of
 * 100 spectra does. */
#define LX_FN_COUNT_MAX 32
struct lx__wcache {
    lx_function fns[LX_FN_COUNT_MAX];
    size_t k, n;
    double start_nm, step_nm;
    double *w;  /* row-major k x n_lambda */
    double *w4; /* AVX2 layout: [group][block][4 functions][4 lanes], zero padded */
    double *w8; /* AVX-512 layout: [group][block][4 functions][8 lanes], 64-byte aligned */
};

static void wcache_free(void *p)
{
    struct lx__wcache *c = p;
    if (!c) return;
    lx__free(c->w);
    lx__free(c->w4);
    lx__free(c->w8);
    lx__free(c);
}

static lx_status batch_weights_cached(lx_ctx *ctx, const lx_batch *b, const lx_function *fns, size_t k,
                                      struct lx__wcache **out)
{
    size_t n = b->n_lambda, nb = (n + 3) / 4, nb8 = (n + 7) / 8, k4 = (k + 3) / 4 * 4;
    struct lx__wcache *c = lx__slot_get(ctx, LX__SLOT_WEIGHTS);
    if (c && c->k == k && c->n == n && c->start_nm == b->start_nm && c->step_nm == b->step_nm &&
        !memcmp(c->fns, fns, k * sizeof *fns)) {
        *out = c;
        return LX_OK;
    }
    c = lx__calloc(1, sizeof *c);
    if (c) {
        c->w = lx__alloc_n(k * n, sizeof *c->w);
        c->w4 = lx__alloc_aligned(64, (k4 / 4 * nb * 16 * sizeof *c->w4 + 63) / 64 * 64); /* no load crosses a line */
        c->w8 = lx__alloc_aligned(64, (k4 / 4 * nb8 * 32 * sizeof *c->w8 + 63) / 64 * 64);
    }
    lx_status st = !c || !c->w || !c->w4 || !c->w8 ? lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the batch weights")
                                                 : lx__batch_weights(ctx, fns, k, b->start_nm, b->step_nm, n, c->w);
    if (st) {
        wcache_free(c);
        return st;
    }
    memset(c->w4, 0, k4 / 4 * nb * 16 * sizeof *c->w4);
    memset(c->w8, 0, k4 / 4 * nb8 * 32 * sizeof *c->w8);
    for (size_t f = 0; f < k; f++)
        for (size_t j = 0; j < n; j++) {
            c->w4[((f / 4) * nb + j / 4) * 16 + (f % 4) * 4 + j % 4] = c->w[f * n + j];
            c->w8[((f / 4) * nb8 + j / 8) * 32 + (f % 4) * 8 + j % 8] = c->w[f * n + j];
        }
    c->k = k, c->n = n, c->start_nm = b->start_nm, c->step_nm = b->step_nm;
    if (k <= LX_FN_COUNT_MAX) memcpy(c->fns, fns, k * sizeof *fns);
    if (ctx && k <= LX_FN_COUNT_MAX) lx__slot_set(ctx, LX__SLOT_WEIGHTS, c, wcache_free);
    *out = c;
    return LX_OK;
}

static lx_status batch_cpu(lx_ctx *ctx, const lx_batch *b, const lx_function *fns, size_t k, int threads,
                           double *out)
{
    size_t n = b->n_lambda, nb = (n + 3) / 4, nb8 = (n + 7) / 8, k4 = (k + 3) / 4 * 4;
    struct lx__wcache *c = NULL;
    lx_status st = batch_weights_cached(ctx, b, fns, k, &c);
    if (st) return st;
    const double *w = c->w, *w4 = c->w4, *w8 = c->w8;
    int vector = 0;
#if LX_HAVE_AVX2_PATH
    vector = (int)lx_simd_level();
#endif
    size_t per_thread_min = 512; /* below this a thread costs more than it saves */
    int T = lx__threads(threads, (long)(b->n_spectra / per_thread_min));
    _Atomic size_t next = 0;
    cpu_job J = {.b = b, .stride = b->row_stride ? b->row_stride : n, .k = k, .k4 = k4, .nb = nb, .nb8 = nb8,
                 .w = w, .w4 = w4, .w8 = w8, .out = out, .next = &next, .n_total = b->n_spectra, .vector = vector};
    /* every thread takes spectra from one counter until none are left: a thread that another
     * process keeps off its core holds up at most LX_CPU_GRAIN spectra */
    lx__parallel_run(T, cpu_thread, &J);
    if (c != lx__slot_get(ctx, LX__SLOT_WEIGHTS)) wcache_free(c); /* not kept (no context, or too many functions) */
    return LX_OK;
}

/* ---- the OpenCL path ---- */

#if LX_OPENCL
static lx_status batch_opencl(lx_ctx *ctx, const lx_batch *b, const lx_function *fns, size_t k,
                              size_t chunk_spectra, double *out)
{
    lx__cl *cl = NULL;
    lx_status st = lx__cl_get(ctx, &cl);
    if (st) return st;
    const char *acc = getenv("LX_CL_ACCUM"); /* "kahan": compensated float (measurement switch) */
    int kahan = !cl->info.fp64 || (acc && !strcmp(acc, "kahan"));
    if (kahan && b->dtype == LX_F64)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "OpenCL device %s has no fp64 for double input",
                         cl->info.device_name);
    cl_kernel kern;
    st = lx__cl_kernel(ctx, cl, kahan ? "spd_batch_f32_kahan" : b->dtype == LX_F32 ? "spd_batch_f32" : "spd_batch_f64",
                       &kern);
    if (st) return st;
    size_t n = b->n_lambda, stride = b->row_stride ? b->row_stride : n;
    size_t es = b->dtype == LX_F32 ? sizeof(float) : sizeof(double);
    double *w = lx__alloc_n(k * n, sizeof *w);
    float *wf = kahan ? lx__alloc_n(k * n, sizeof *wf) : NULL;
    float *pairs = NULL;
    cl_mem wbuf = NULL;
    cl_int err = CL_SUCCESS;
    if (!w || (kahan && !wf)) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto done;
    }
    st = lx__batch_weights(ctx, fns, k, b->start_nm, b->step_nm, n, w);
    if (st) goto done;
    if (kahan)
        for (size_t i = 0; i < k * n; i++) wf[i] = (float)w[i];
    wbuf = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, k * n * (kahan ? sizeof(float) : sizeof(double)),
                          kahan ? (void *)wf : (void *)w, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(weights)"))) goto done;

    /* Chunk: rows whose input fits CL_DEVICE_MAX_MEM_ALLOC_SIZE (and the caller's cap). */
    unsigned long long max_alloc = cl->info.max_alloc_bytes ? cl->info.max_alloc_bytes : (128ull << 20);
    size_t row_bytes = stride * es, out_row = k * (kahan ? 2 * sizeof(float) : sizeof(double));
    size_t by_alloc = (size_t)(max_alloc / (row_bytes > out_row ? row_bytes : out_row));
    size_t rows_max = by_alloc;
    if (chunk_spectra && chunk_spectra < rows_max) rows_max = chunk_spectra;
    if (rows_max > 0xffffffffu) rows_max = 0xffffffffu;
    if (rows_max == 0) {
        st = lx__error(ctx, LX_EDEVICE, NULL, 0, "one spectrum (%zu bytes) exceeds CL_DEVICE_MAX_MEM_ALLOC_SIZE (%llu)",
                       row_bytes, max_alloc);
        goto done;
    }
    if (kahan) {
        pairs = lx__alloc(rows_max * out_row);
        if (!pairs) {
            st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
            goto done;
        }
    }
    unsigned cu = cl->info.compute_units ? cl->info.compute_units : 1;
    for (size_t r0 = 0; r0 < b->n_spectra && !st; r0 += rows_max) {
        size_t rows = b->n_spectra - r0 < rows_max ? b->n_spectra - r0 : rows_max;
        /* the last row needs only n_lambda elements, not a whole stride */
        size_t in_bytes = ((rows - 1) * stride + n) * es;
        const char *src = (const char *)b->values + r0 * stride * es;
        cl_mem in = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR, in_bytes, (void *)src, &err);
        if ((st = lx__cl_check(ctx, err, "clCreateBuffer(spectra)"))) break;
        void *host_out = kahan ? (void *)pairs : (void *)(out + r0 * k);
        cl_mem ob = clCreateBuffer(cl->context, CL_MEM_WRITE_ONLY | CL_MEM_USE_HOST_PTR, rows * out_row, host_out, &err);
        if ((st = lx__cl_check(ctx, err, "clCreateBuffer(results)"))) {
            clReleaseMemObject(in);
            break;
        }
        /* CPU devices: a few contiguous runs per compute unit; GPUs: one spectrum per work-item */
        size_t items = cl->info.is_cpu ? (size_t)cu * 8 : rows;
        if (items > rows) items = rows;
        cl_uint per_item = (cl_uint)((rows + items - 1) / items);
        size_t global = (rows + per_item - 1) / per_item;
        cl_uint a_n = (cl_uint)rows, a_nl = (cl_uint)n, a_k = (cl_uint)k;
        cl_ulong a_stride = stride;
        err = clSetKernelArg(kern, 0, sizeof in, &in);
        err |= clSetKernelArg(kern, 1, sizeof a_n, &a_n);
        err |= clSetKernelArg(kern, 2, sizeof a_nl, &a_nl);
        err |= clSetKernelArg(kern, 3, sizeof a_stride, &a_stride);
        err |= clSetKernelArg(kern, 4, sizeof wbuf, &wbuf);
        err |= clSetKernelArg(kern, 5, sizeof a_k, &a_k);
        err |= clSetKernelArg(kern, 6, sizeof ob, &ob);
        err |= clSetKernelArg(kern, 7, sizeof per_item, &per_item);
        if (!(st = lx__cl_check(ctx, err, "clSetKernelArg"))) {
            err = clEnqueueNDRangeKernel(cl->queue, kern, 1, NULL, &global, NULL, 0, NULL, NULL);
            st = lx__cl_check(ctx, err, "clEnqueueNDRangeKernel(spd_batch)");
        }
        if (!st) {
            /* mapping the results makes them visible in host_out (zero-copy on CPU devices) */
            void *p = clEnqueueMapBuffer(cl->queue, ob, CL_TRUE, CL_MAP_READ, 0, rows * out_row, 0, NULL, NULL, &err);
            if (!(st = lx__cl_check(ctx, err, "clEnqueueMapBuffer(results)"))) {
                if (p != host_out) memcpy(host_out, p, rows * out_row);
                clEnqueueUnmapMemObject(cl->queue, ob, p, 0, NULL, NULL);
                err = clFinish(cl->queue);
                st = lx__cl_check(ctx, err, "clFinish");
            }
        }
        if (!st && kahan)
            for (size_t i = 0; i < rows * k; i++) out[r0 * k + i] = (double)pairs[2 * i] + (double)pairs[2 * i + 1];
        clReleaseMemObject(in);
        clReleaseMemObject(ob);
    }
done:
    if (wbuf) clReleaseMemObject(wbuf);
    clReleaseKernel(kern);
    lx__free(w);
    lx__free(wf);
    lx__free(pairs);
    return st;
}
#endif

/* ---- backend choice ---- */

static lx_status check_batch(lx_ctx *ctx, const lx_batch *b, const lx_function *fns, size_t k, const double *out)
{
    if (!b || !out || (k && !fns)) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch: NULL argument");
    if (b->n_spectra && !b->values) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch: NULL values");
    if (b->n_lambda < 1) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch: n_lambda must be at least 1");
    if (b->row_stride && b->row_stride < b->n_lambda)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "batch: row_stride %zu < n_lambda %zu", b->row_stride, b->n_lambda);
    if (!(b->step_nm > 0) || !isfinite(b->step_nm) || !isfinite(b->start_nm))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "batch: the grid needs a finite start and a positive step");
    if (b->dtype != LX_F32 && b->dtype != LX_F64) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch: unknown dtype");
    for (size_t f = 0; f < k; f++)
        if ((int)fns[f] < 0 || fns[f] >= LX_FN_COUNT)
            return lx__error(ctx, LX_EINVAL, NULL, 0, "batch: unknown weighting function %d", (int)fns[f]);
    return LX_OK;
}

lx_status lx_batch_integrate(lx_ctx *ctx, const lx_batch *b, const lx_function *fns, size_t k,
                             const lx_batch_opts *opts, double *out)
{
    LX__NEED_CTX(ctx);
    lx_status st = check_batch(ctx, b, fns, k, out);
    if (st) return st;
    const lx_batch_opts defaults = {0};
    if (!opts) opts = &defaults;
    if ((st = lx__check_reserved(ctx, "batch options", opts->reserved, sizeof opts->reserved))) return st;
    if (b->n_spectra == 0 || k == 0) {
        lx__backend_used(ctx, LX_BACKEND_CPU);
        return LX_OK;
    }
    lx_backend be;
    st = lx__backend_choose(ctx, "batch", opts->backend, (double)b->n_spectra * (double)b->n_lambda,
                            LX_AUTO_COLD_SAMPLES, LX_AUTO_WARM_SAMPLES, &be);
    if (st) return st;
#if LX_OPENCL
    if (be == LX_BACKEND_OPENCL) {
        st = batch_opencl(ctx, b, fns, k, opts->chunk_spectra, out);
        if (st == LX_OK) {
            lx__backend_used(ctx, LX_BACKEND_OPENCL);
            return LX_OK;
        }
        if (!lx__backend_fallback(ctx, "batch", opts->backend, st)) return st;
    }
#endif
    st = batch_cpu(ctx, b, fns, k, opts->threads, out);
    if (!st) lx__backend_used(ctx, LX_BACKEND_CPU);
    return st;
}

/* ---- resampling ---- */

static double resample_at(const double *x, const double *y, size_t n, size_t *lo, double xq)
{
    if (n < 1 || !(xq >= x[0]) || !(xq <= x[n - 1])) return 0.0;
    while (*lo + 2 < n && x[*lo + 1] <= xq) (*lo)++;
    size_t l = *lo, h = l + 1 < n ? l + 1 : l;
    if (xq == x[l]) return y[l];
    if (xq == x[h]) return y[h];
    double t = (xq - x[l]) / (x[h] - x[l]);
    return y[l] + t * (y[h] - y[l]);
}

static void resample_cpu(size_t ns, const double *lam, const double *val, const size_t *offset, const size_t *n_in,
                         lx_batch *dst)
{
    size_t stride = dst->row_stride ? dst->row_stride : dst->n_lambda;
    for (size_t i = 0; i < ns; i++) {
        size_t lo = 0;
        const double *x = lam + offset[i], *y = val + offset[i];
        for (size_t j = 0; j < dst->n_lambda; j++) {
            double r = resample_at(x, y, n_in[i], &lo, dst->start_nm + (double)j * dst->step_nm);
            if (dst->dtype == LX_F32) ((float *)(uintptr_t)dst->values)[i * stride + j] = (float)r;
            else ((double *)(uintptr_t)dst->values)[i * stride + j] = r;
        }
    }
}

#if LX_OPENCL
static lx_status resample_opencl(lx_ctx *ctx, size_t ns, const double *lam, const double *val, const size_t *offset,
                                 const size_t *n_in, lx_batch *dst)
{
    lx__cl *cl = NULL;
    lx_status st = lx__cl_get(ctx, &cl);
    if (st) return st;
    if (!cl->info.fp64) return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "the resample kernel needs fp64");
    cl_kernel kern;
    st = lx__cl_kernel(ctx, cl, dst->dtype == LX_F32 ? "spd_resample_f32" : "spd_resample_f64", &kern);
    if (st) return st;
    size_t total = 0;
    for (size_t i = 0; i < ns; i++)
        if (offset[i] + n_in[i] > total) total = offset[i] + n_in[i];
    if (total == 0) total = 1;
    cl_ulong *off = lx__alloc_n(ns, sizeof *off);
    cl_uint *cnt = lx__alloc_n(ns, sizeof *cnt);
    size_t stride = dst->row_stride ? dst->row_stride : dst->n_lambda;
    size_t es = dst->dtype == LX_F32 ? sizeof(float) : sizeof(double);
    size_t out_bytes = ((ns - 1) * stride + dst->n_lambda) * es;
    cl_mem m[5] = {0};
    cl_int err = CL_SUCCESS;
    if (!off || !cnt) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < ns; i++) {
        off[i] = offset[i];
        cnt[i] = (cl_uint)n_in[i];
    }
    cl_mem_flags ro = CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR;
    m[0] = clCreateBuffer(cl->context, ro, total * sizeof(double), (void *)lam, &err);
    if (!err) m[1] = clCreateBuffer(cl->context, ro, total * sizeof(double), (void *)val, &err);
    if (!err) m[2] = clCreateBuffer(cl->context, ro, ns * sizeof *off, off, &err);
    if (!err) m[3] = clCreateBuffer(cl->context, ro, ns * sizeof *cnt, cnt, &err);
    if (!err) m[4] = clCreateBuffer(cl->context, CL_MEM_WRITE_ONLY | CL_MEM_USE_HOST_PTR, out_bytes, (void *)(uintptr_t)dst->values, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(resample)"))) goto done;
    cl_uint a_ns = (cl_uint)ns, a_no = (cl_uint)dst->n_lambda;
    cl_double a_start = dst->start_nm, a_step = dst->step_nm;
    cl_ulong a_stride = stride;
    for (int a = 0; a < 4; a++) err |= clSetKernelArg(kern, (cl_uint)a, sizeof(cl_mem), &m[a]);
    err |= clSetKernelArg(kern, 4, sizeof a_ns, &a_ns);
    err |= clSetKernelArg(kern, 5, sizeof a_start, &a_start);
    err |= clSetKernelArg(kern, 6, sizeof a_step, &a_step);
    err |= clSetKernelArg(kern, 7, sizeof a_no, &a_no);
    err |= clSetKernelArg(kern, 8, sizeof a_stride, &a_stride);
    err |= clSetKernelArg(kern, 9, sizeof(cl_mem), &m[4]);
    if ((st = lx__cl_check(ctx, err, "clSetKernelArg(resample)"))) goto done;
    size_t global = ns;
    err = clEnqueueNDRangeKernel(cl->queue, kern, 1, NULL, &global, NULL, 0, NULL, NULL);
    if ((st = lx__cl_check(ctx, err, "clEnqueueNDRangeKernel(spd_resample)"))) goto done;
    void *p = clEnqueueMapBuffer(cl->queue, m[4], CL_TRUE, CL_MAP_READ, 0, out_bytes, 0, NULL, NULL, &err);
    if ((st = lx__cl_check(ctx, err, "clEnqueueMapBuffer(resample)"))) goto done;
    if (p != dst->values) memcpy((void *)(uintptr_t)dst->values, p, out_bytes);
    clEnqueueUnmapMemObject(cl->queue, m[4], p, 0, NULL, NULL);
    st = lx__cl_check(ctx, clFinish(cl->queue), "clFinish");
done:
    for (int a = 0; a < 5; a++)
        if (m[a]) clReleaseMemObject(m[a]);
    clReleaseKernel(kern);
    lx__free(off);
    lx__free(cnt);
    return st;
}
#endif

lx_status lx_batch_resample(lx_ctx *ctx, size_t n_spectra, const double *lambda_nm, const double *value,
                            const size_t *offset, const size_t *n_in, lx_batch *dst, const lx_batch_opts *opts)
{
    LX__NEED_CTX(ctx);
    if (!dst || (n_spectra && (!lambda_nm || !value || !offset || !n_in || !dst->values)))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "resample: NULL argument");
    if (dst->n_lambda < 1 || !(dst->step_nm > 0) || (dst->row_stride && dst->row_stride < dst->n_lambda) ||
        (dst->dtype != LX_F32 && dst->dtype != LX_F64))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "resample: invalid destination grid");
    for (size_t i = 0; i < n_spectra; i++) {
        const double *x = lambda_nm + offset[i];
        for (size_t j = 1; j < n_in[i]; j++)
            if (!(x[j] > x[j - 1]))
                return lx__error(ctx, LX_EINVAL, NULL, 0, "resample: spectrum %zu: wavelengths not strictly increasing at sample %zu", i, j);
    }
    const lx_batch_opts defaults = {0};
    if (!opts) opts = &defaults;
    lx_status st = lx__check_reserved(ctx, "batch options", opts->reserved, sizeof opts->reserved);
    if (st) return st;
    dst->n_spectra = n_spectra;
    if (n_spectra == 0) {
        lx__backend_used(ctx, LX_BACKEND_CPU);
        return LX_OK;
    }
    lx_backend be;
    st = lx__backend_choose(ctx, "resample", opts->backend, (double)n_spectra * (double)dst->n_lambda,
                                      LX_AUTO_COLD_SAMPLES, LX_AUTO_WARM_SAMPLES, &be);
    if (st) return st;
#if LX_OPENCL
    if (be == LX_BACKEND_OPENCL) {
        st = resample_opencl(ctx, n_spectra, lambda_nm, value, offset, n_in, dst);
        if (st == LX_OK) {
            lx__backend_used(ctx, LX_BACKEND_OPENCL);
            return LX_OK;
        }
        if (!lx__backend_fallback(ctx, "resample", opts->backend, st)) return st;
    }
#endif
    resample_cpu(n_spectra, lambda_nm, value, offset, n_in, dst);
    lx__backend_used(ctx, LX_BACKEND_CPU);
    return LX_OK;
}
