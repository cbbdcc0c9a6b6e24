/* test_batch.c - the batch integration API on the CPU path: published table sums, closed forms,
 * illuminant A against colour-science, vector/scalar/thread agreement with a naive oracle,
 * strides, tails, empty batches, argument errors, backend names, resampling, and the CSV readers
 * (whole and streamed: values bit-identical to strtod, error lines, end-to-end sums). */
#include "lx_test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const lx_function XYZ[3] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2};

/* The piecewise-linear w at x (0 outside its samples). */
static long double lin_at(const lx_spd *w, long double x)
{
    if (x < w->lambda_nm[0] || x > w->lambda_nm[w->n - 1]) return 0;
    for (size_t m = 0; m + 1 < w->n; m++)
        if (x >= w->lambda_nm[m] && x <= w->lambda_nm[m + 1]) {
            long double t = (x - w->lambda_nm[m]) / (w->lambda_nm[m + 1] - w->lambda_nm[m]);
            return w->value[m] + t * (w->value[m + 1] - w->value[m]);
        }
    return 0;
}

/* The band functions (PAR, ePAR, YPF: a step at each end of the band) are integrated exactly: the
 * piecewise-linear spectrum times the piecewise-linear weight, by Simpson's rule between every pair
 * of breakpoints of either (exact for the quadratic product there). */
static long double oracle_band(const lx_spd *w, const double *row, size_t n, double start, double step)
{
    long double s = 0, hi_grid = start + (double)(n - 1) * step;
    long double lo = fmaxl(start, w->lambda_nm[0]), hi = fminl(hi_grid, w->lambda_nm[w->n - 1]);
    long double a = lo;
    while (a < hi) {
        long double b = hi; /* the next breakpoint of either function */
        long double g = start + ceill((a - start) / step + 1e-12L) * step;
        if (g <= a) g += step;
        if (g < b) b = g;
        for (size_t m = 0; m < w->n; m++)
            if (w->lambda_nm[m] > a && w->lambda_nm[m] < b) b = w->lambda_nm[m];
        long double pts[3] = {a, 0.5L * (a + b), b}, f[3];
        for (int q = 0; q < 3; q++) {
            long double k = (pts[q] - start) / step;
            size_t j = (size_t)floorl(k);
            if (j + 1 >= n) j = n - 2;
            long double t = k - (long double)j, sv = row[j] + t * (row[j + 1] - row[j]);
            f[q] = sv * lin_at(w, pts[q]);
        }
        s += (b - a) / 6 * (f[0] + 4 * f[1] + f[2]);
        a = b;
    }
    return s;
}

/* Naive oracle: long double, one term at a time, weights from lx_function_get interpolated by
 * hand (independent of src/spectral/batch.c's weight matrix and vector code). */
static long double oracle(lx_ctx *ctx, const double *row, size_t n, double start, double step, lx_function fn)
{
    lx_spd w;
    lx_assert_ok(ctx, lx_function_get(ctx, fn, &w));
    if (fn == LX_FN_PHOTON_PAR || fn == LX_FN_PHOTON_EPAR || fn == LX_FN_YPF_MCCREE)
        return oracle_band(&w, row, n, start, step);
    long double s = 0;
    for (size_t j = 0; j < n; j++) {
        double x = start + (double)j * step, wv = 0;
        for (size_t m = 0; m + 1 < w.n; m++)
            if (x >= w.lambda_nm[m] && x <= w.lambda_nm[m + 1]) {
                double t = (x - w.lambda_nm[m]) / (w.lambda_nm[m + 1] - w.lambda_nm[m]);
                wv = w.value[m] + t * (w.value[m + 1] - w.value[m]);
                break;
            }
        s += (long double)row[j] * wv * step;
    }
    return s;
}

static void test_table_sums(void **state)
{
    lx_ctx *ctx = *state;
    double ones[471];
    for (int i = 0; i < 471; i++) ones[i] = 1.0;
    lx_function fns[4] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2, LX_FN_VPRIME};
    lx_batch b = {.n_spectra = 1, .n_lambda = 471, .start_nm = 360, .step_nm = 1, .dtype = LX_F64, .values = ones};
    double out[4];
    lx_batch_opts o = {.backend = LX_BACKEND_CPU};
    assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_AUTO); /* no backend-choosing call yet */
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, fns, 4, &o, out));
    assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_CPU);
    /* sums of the CIE 1931 2 deg CMFs 360-830 nm at 1 nm: colour-science 0.4.7
     * MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].values.sum(axis=0); STYLE.md: sum ybar 106.856917 */
    lx_assert_near(out[0], 106.86546949, 0, 1e-9);
    lx_assert_near(out[1], 106.8569171, 0, 1e-9);
    lx_assert_near(out[2], 106.89225128, 0, 1e-9);
    /* sum of V'(lambda) 380-780 nm at 1 nm: colour-science 0.4.7 SDS_LEFS_SCOTOPIC["CIE 1951 Scotopic
     * Standard Observer"].values.sum() = 97.071316574 (zero outside its table) */
    lx_assert_near(out[3], 97.071316574, 0, 1e-9);
}

static void test_half_nm_grid_is_trapezoid(void **state)
{
    lx_ctx *ctx = *state;
    /* A unit spectrum on 360.5, 361.5, ..., 829.5: each weight is the mean of its two 1 nm neighbours,
     * so the sum is sum(w) - (w(360) + w(830)) / 2 (trapezoid rule). With colour-science 0.4.7's CMFs:
     * v.sum(0) - (v[0] + v[-1]) / 2 = 106.86540391, 106.85691492, 106.89194823. */
    double ones[470];
    for (int i = 0; i < 470; i++) ones[i] = 1.0;
    lx_batch b = {.n_spectra = 1, .n_lambda = 470, .start_nm = 360.5, .step_nm = 1, .dtype = LX_F64, .values = ones};
    double out[3];
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, XYZ, 3, &(lx_batch_opts){.backend = LX_BACKEND_CPU}, out));
    lx_assert_near(out[0], 106.86540391, 0, 1e-9);
    lx_assert_near(out[1], 106.85691492, 0, 1e-9);
    lx_assert_near(out[2], 106.89194823, 0, 1e-9);
}

static void test_illuminant_a(void **state)
{
    lx_ctx *ctx = *state;
    /* CIE A by CIE 015:2018 eq. 4.1 (c2 = 1.435e-2 m K) times colour-science 0.4.7's CMFs, summed in
     * numpy: 1 nm -> 11852.36540397, 10789.5575544, 3839.45745787;
     *        5 nm (x 5) -> 11852.36711593, 10789.5687106, 3839.46352473 */
    double a1[471], a5[95];
    float f1[471];
    for (int i = 0; i < 471; i++) {
        a1[i] = lx_illuminant_a(360.0 + i);
        f1[i] = (float)a1[i];
    }
    for (int i = 0; i < 95; i++) a5[i] = lx_illuminant_a(360.0 + 5.0 * i);
    double out[3];
    lx_batch b = {.n_spectra = 1, .n_lambda = 471, .start_nm = 360, .step_nm = 1, .dtype = LX_F64, .values = a1};
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, XYZ, 3, NULL, out));
    lx_assert_near(out[0], 11852.36540397, 0, 1e-9);
    lx_assert_near(out[1], 10789.5575544, 0, 1e-9);
    lx_assert_near(out[2], 3839.45745787, 0, 1e-9);
    b.dtype = LX_F32;
    b.values = f1; /* float input: each value rounded by <= 6e-8 relative, so the sums too */
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, XYZ, 3, NULL, out));
    lx_assert_near(out[0], 11852.36540397, 0, 1e-6);
    lx_assert_near(out[1], 10789.5575544, 0, 1e-6);
    lx_assert_near(out[2], 3839.45745787, 0, 1e-6);
    b = (lx_batch){.n_spectra = 1, .n_lambda = 95, .start_nm = 360, .step_nm = 5, .dtype = LX_F64, .values = a5};
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, XYZ, 3, NULL, out));
    lx_assert_near(out[0], 11852.36711593, 0, 1e-9);
    lx_assert_near(out[1], 10789.5687106, 0, 1e-9);
    lx_assert_near(out[2], 3839.46352473, 0, 1e-9);
}

/* Smooth pseudo-random spectra (sum of two Gaussians plus a pedestal), deterministic. */
static void fill(double *v, size_t ns, size_t n, size_t stride, double start, double step)
{
    unsigned s = 12345;
    for (size_t i = 0; i < ns; i++) {
        double p[5];
        for (int q = 0; q < 5; q++) {
            s = s * 1103515245u + 12345u;
            p[q] = (double)(s >> 8) / 16777216.0;
        }
        for (size_t j = 0; j < stride; j++) {
            double x = start + (double)j * step;
            double g1 = exp(-0.5 * pow((x - (400 + 350 * p[0])) / (15 + 100 * p[1]), 2));
            double g2 = exp(-0.5 * pow((x - (400 + 350 * p[2])) / (20 + 80 * p[3]), 2));
            v[i * stride + j] = j < n ? p[4] * g1 + g2 + 0.05 : NAN; /* padding is never read */
        }
    }
}

static void parity_case(lx_ctx *ctx, lx_simd path, size_t ns, size_t n, size_t stride, double start, double step,
                        const lx_function *fns, size_t k)
{
    double *v = malloc(ns * stride * sizeof *v + 1);
    float *vf = malloc(ns * stride * sizeof *vf + 1);
    double *out = malloc(ns * k * sizeof *out + 1), *out2 = malloc(ns * k * sizeof *out + 1);
    fill(v, ns, n, stride, start, step);
    for (size_t i = 0; i < ns * stride; i++) vf[i] = (float)v[i];
    lx_batch b = {.n_spectra = ns, .n_lambda = n, .row_stride = stride, .start_nm = start, .step_nm = step,
                  .dtype = LX_F64, .values = v};
    /* this path on 2 threads and on 1 */
    for (int mode = 0; mode < 2; mode++) {
        setenv("LX_SIMD", lx_simd_name(path), 1);
        lx_batch_opts o = {.backend = LX_BACKEND_CPU, .threads = mode == 1 ? 1 : 2};
        b.dtype = LX_F64;
        b.values = v;
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, fns, k, &o, out));
        b.dtype = LX_F32;
        b.values = vf;
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, fns, k, &o, out2));
        for (size_t i = 0; i < ns; i += (ns > 50 ? 7 : 1))
            for (size_t f = 0; f < k; f++) {
                double ref = (double)oracle(ctx, v + i * stride, n, start, step, fns[f]);
                lx_assert_near(out[i * k + f], ref, 1e-300, 1e-12);
                lx_assert_near(out2[i * k + f], ref, 1e-300, 1e-6);
            }
    }
    free(v);
    free(vf);
    free(out);
    free(out2);
}

/* The integration loops of one SIMD path (tests/lx_test.h: SKIPPED where this machine cannot run
 * it) against the long double oracle: 1e-12 relative for double input, 1e-6 for float. */
static void parity_with_oracle(void **state, lx_simd path)
{
    lx_ctx *ctx = *state;
    lx_test_simd_begin(path);
    lx_function all[LX_FN_COUNT];
    for (int f = 0; f < LX_FN_COUNT; f++) all[f] = (lx_function)f;
    parity_case(ctx, path, 1, 471, 471, 360, 1, XYZ, 3);
    parity_case(ctx, path, 2049, 471, 480, 360, 1, all, LX_FN_COUNT); /* stride padding, K = 12 */
    parity_case(ctx, path, 37, 3, 3, 550, 1, XYZ, 3);                  /* only a tail block */
    parity_case(ctx, path, 5, 1, 1, 555, 1, all, 5);                   /* one wavelength */
    parity_case(ctx, path, 1000, 81, 81, 380, 5, all, 7);              /* 5 nm, K not a multiple of 4 */
    parity_case(ctx, path, 64, 400, 401, 340.25, 1.25, XYZ, 3);        /* off-grid: interpolated weights */
    lx_test_simd_end();
}

static void test_parity_avx512(void **state) { parity_with_oracle(state, LX_SIMD_AVX512); }
static void test_parity_avx2(void **state) { parity_with_oracle(state, LX_SIMD_AVX2); }
static void test_parity_scalar(void **state) { parity_with_oracle(state, LX_SIMD_SCALAR); }

static void test_empty_and_errors(void **state)
{
    lx_ctx *ctx = *state;
    double out[3] = {-1, -1, -1};
    lx_batch b = {.n_spectra = 0, .n_lambda = 471, .start_nm = 360, .step_nm = 1, .dtype = LX_F32, .values = NULL};
    lx_batch_opts o = {0};
    assert_int_equal(lx_batch_integrate(ctx, &b, XYZ, 3, &o, out), LX_OK);
    assert_true(out[0] == -1); /* nothing written for an empty batch */
    double v[4] = {1, 2, 3, 4};
    b = (lx_batch){.n_spectra = 1, .n_lambda = 4, .start_nm = 500, .step_nm = 0, .dtype = LX_F64, .values = v};
    assert_int_equal(lx_batch_integrate(ctx, &b, XYZ, 3, NULL, out), LX_EINVAL);
    b.step_nm = 1;
    b.row_stride = 2;
    assert_int_equal(lx_batch_integrate(ctx, &b, XYZ, 3, NULL, out), LX_EINVAL);
    b.row_stride = 0;
    lx_function bad = (lx_function)99;
    assert_int_equal(lx_batch_integrate(ctx, &b, &bad, 1, NULL, out), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "99"));
    assert_int_equal(lx_batch_integrate(ctx, NULL, XYZ, 3, NULL, out), LX_EINVAL);
    assert_true(out[0] == -1); /* outputs untouched on failure */
}

static void test_backend_names(void **state)
{
    lx_ctx *ctx = *state;
    lx_backend b;
    lx_assert_ok(ctx, lx_backend_parse(ctx, "cpu", &b));
    assert_int_equal(b, LX_BACKEND_CPU);
    lx_assert_ok(ctx, lx_backend_parse(ctx, "opencl", &b));
    assert_int_equal(b, LX_BACKEND_OPENCL);
    lx_assert_ok(ctx, lx_backend_parse(ctx, "auto", &b));
    assert_int_equal(b, LX_BACKEND_AUTO);
    assert_int_equal(lx_backend_parse(ctx, "gpu", &b), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "gpu"));
    setenv("LX_BACKEND", "cpu", 1);
    assert_int_equal(lx_backend_from_env(), LX_BACKEND_CPU);
    unsetenv("LX_BACKEND");
    assert_int_equal(lx_backend_from_env(), LX_BACKEND_AUTO);
#if !LX_OPENCL
    double v[2] = {1, 1}, out[1];
    lx_batch bt = {.n_spectra = 1, .n_lambda = 2, .start_nm = 555, .step_nm = 1, .dtype = LX_F64, .values = v};
    assert_int_equal(lx_batch_integrate(ctx, &bt, XYZ, 1, &(lx_batch_opts){.backend = LX_BACKEND_OPENCL}, out),
                     LX_EUNSUPPORTED);
#endif
}

static void test_auto_small_batch_stays_on_cpu(void **state)
{
    lx_ctx *ctx = *state;
    double v[471] = {0};
    lx_batch b = {.n_spectra = 1, .n_lambda = 471, .start_nm = 360, .step_nm = 1, .dtype = LX_F64, .values = v};
    lx_batch_opts o = {.backend = LX_BACKEND_AUTO};
    double out[3];
    unsetenv("LX_BACKEND");
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, XYZ, 3, &o, out));
    assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_CPU);
    assert_int_equal(lx_cl_ready(ctx), 0); /* a one-off calculation never starts OpenCL */
}

static void test_resample_cpu(void **state)
{
    lx_ctx *ctx = *state;
    /* spectrum 0: the line y = 2x - 700 sampled at 400, 410.5, 433, 500 nm: interpolation is exact on
     * a line, zero outside [400, 500]. spectrum 1: one sample (555 nm, 3): only the grid point 555 gets 3. */
    double lam[5] = {400, 410.5, 433, 500, 555}, val[5];
    for (int i = 0; i < 4; i++) val[i] = 2 * lam[i] - 700;
    val[4] = 3;
    size_t off[2] = {0, 4}, nin[2] = {4, 1};
    double dst[2 * 200];
    lx_batch d = {.n_lambda = 200, .start_nm = 390, .step_nm = 1, .dtype = LX_F64, .values = dst};
    lx_batch_opts o = {.backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_batch_resample(ctx, 2, lam, val, off, nin, &d, &o));
    assert_int_equal(d.n_spectra, 2);
    for (int j = 0; j < 200; j++) {
        double x = 390 + j;
        double want = x >= 400 && x <= 500 ? 2 * x - 700 : 0;
        lx_assert_near(dst[j], want, 1e-12, 1e-14);
        lx_assert_near(dst[200 + j], x == 555 ? 3 : 0, 0, 0);
    }
    double bad[2] = {500, 500};
    size_t off1[1] = {0}, n1[1] = {2};
    assert_int_equal(lx_batch_resample(ctx, 1, bad, val, off1, n1, &d, &o), LX_EINVAL);
}


static void test_batch_csv(void **state)
{
    lx_ctx *ctx = *state;
    /* named rows, CRLF, a comment and a blank line, values that exercise both number parsers */
    const char text[] = "# comment\r\nid,500,501,502\r\nlamp a,1,0.1,2.5e-3\r\n\r\nb,-0.000123456789012345,"
                        "123456.7890123,1e300\r\n";
    lx_batch_table *t = NULL;
    lx_assert_ok(ctx, lx_batch_table_read_mem(ctx, "mem.csv", text, sizeof text - 1, LX_F64, 0, &t));
    assert_int_equal(t->batch.n_spectra, 2);
    assert_int_equal(t->batch.n_lambda, 3);
    lx_assert_near(t->batch.start_nm, 500, 0, 0);
    lx_assert_near(t->batch.step_nm, 1, 0, 0);
    assert_string_equal(t->names + t->name_at[0], "lamp a");
    assert_string_equal(t->names + t->name_at[1], "b");
    const double *v = t->batch.values;
    /* bit-identical to the C library's correctly rounded strtod (ISO C 7.22.1.3) */
    const char *lit[6] = {"1", "0.1", "2.5e-3", "-0.000123456789012345", "123456.7890123", "1e300"};
    for (int i = 0; i < 6; i++) assert_true(v[i] == strtod(lit[i], NULL));
    lx_batch_table_free(t);
    /* no name column (numpy-style), float values, tab separated */
    const char t2[] = "380\t385\t390\n0.5\t0.25\t0.125\n";
    lx_assert_ok(ctx, lx_batch_table_read_mem(ctx, "t2", t2, sizeof t2 - 1, LX_F32, 1, &t));
    assert_int_equal(t->batch.n_spectra, 1);
    lx_assert_near(t->batch.step_nm, 5, 0, 0);
    assert_true(((const float *)t->batch.values)[2] == 0.125f);
    lx_batch_table_free(t);
    /* errors name the line: a short row on line 4, a bad number on line 3, a non-uniform header */
    const char bad1[] = "id,1,2\na,1,2\n#c\nb,1\n";
    assert_int_equal(lx_batch_table_read_mem(ctx, "bad1", bad1, sizeof bad1 - 1, LX_F64, 1, &t), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 4);
    const char bad2[] = "id,1,2\na,1,2\nb,1,x\n";
    assert_int_equal(lx_batch_table_read_mem(ctx, "bad2", bad2, sizeof bad2 - 1, LX_F64, 1, &t), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 3);
    const char bad3[] = "id,1,2,4\na,1,2,3\n";
    assert_int_equal(lx_batch_table_read_mem(ctx, "bad3", bad3, sizeof bad3 - 1, LX_F64, 1, &t), LX_EUNSUPPORTED);
    assert_int_equal(lx_batch_table_read_mem(ctx, "empty", "", 0, LX_F64, 1, &t), LX_EPARSE);
    /* header only: an empty batch */
    lx_assert_ok(ctx, lx_batch_table_read_mem(ctx, "h", "id,1,2\n", 7, LX_F64, 1, &t));
    assert_int_equal(t->batch.n_spectra, 0);
    lx_batch_table_free(t);
}

/* ---- streaming CSV (lx_batch_table_stream, lx_batch_table_integrate_file) ---- */

typedef struct stream_check {
    const double *want; /* strtod of every value written, row-major */
    size_t n, rows_seen, calls;
    int bad;
} stream_check;

static lx_status check_chunk(void *user, const lx_batch_table *chunk, size_t row0)
{
    stream_check *c = user;
    if (row0 != c->rows_seen || chunk->batch.n_lambda != c->n) c->bad++;
    const double *v = chunk->batch.values;
    for (size_t i = 0; i < chunk->batch.n_spectra; i++) {
        char name[32];
        snprintf(name, sizeof name, "s%zu", row0 + i);
        if (strcmp(chunk->names + chunk->name_at[i], name)) c->bad++;
        for (size_t j = 0; j < c->n; j++) /* bit-identical to strtod (ISO C 7.22.1.3, correctly rounded) */
            if (v[i * c->n + j] != c->want[(row0 + i) * c->n + j]) c->bad++;
    }
    c->rows_seen += chunk->batch.n_spectra;
    c->calls++;
    return LX_OK;
}

/* Writes rows named s0, s1, ... of 471 values (360-830 nm) in the formats a spectrometer CSV
 * has: mostly %.6g, some the vector line parser leaves to the general one (exponents, long
 * fractions, 8+ integer digits, spaces, "-0", "1.", ".5"). Returns the strtod values. */
static double *write_stream_csv(const char *path, size_t rows, long bad_row)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    double *want = malloc(rows * 471 * sizeof *want);
    fprintf(f, "# streamed\nid");
    for (int j = 0; j < 471; j++) fprintf(f, ",%d", 360 + j);
    fprintf(f, "\n");
    unsigned s = 7;
    for (size_t i = 0; i < rows; i++) {
        fprintf(f, "s%zu", i);
        for (int j = 0; j < 471; j++) {
            s = s * 1103515245u + 12345u;
            double x = 0.01 + 2.0 * (double)(s >> 8) / 16777216.0;
            char cell[64];
            switch (i % 3 ? 99 : (s >> 4) % 23) { /* two rows in three: %.6g only */
            case 0: snprintf(cell, sizeof cell, "%.9g", x); break;
            case 1: snprintf(cell, sizeof cell, "%.3e", x); break;
            case 2: snprintf(cell, sizeof cell, "%.6g", -x); break;
            case 3: snprintf(cell, sizeof cell, "%.1f", x * 1e8); break;
            case 4: snprintf(cell, sizeof cell, " %.6g", x); break;
            case 5: snprintf(cell, sizeof cell, "%s", (s >> 9) % 3 ? "-0" : (s >> 9) % 2 ? "1." : ".5"); break;
            case 6: snprintf(cell, sizeof cell, "%.0f", x * 100); break;
            default: snprintf(cell, sizeof cell, "%.6g", x); break;
            }
            if ((long)i == bad_row && j == 300) snprintf(cell, sizeof cell, "0.5x");
            fprintf(f, ",%s", cell);
            want[i * 471 + (size_t)j] = strtod(cell, NULL);
        }
        fprintf(f, i % 97 == 5 ? "\r\n\n" : "\n"); /* CRLF and blank lines move line numbers */
    }
    assert_int_equal(fclose(f), 0);
    return want;
}

static lx_status check_chunk_count(void *user, const lx_batch_table *chunk, size_t row0)
{
    stream_check *c = user;
    if (row0 != c->rows_seen) c->bad++;
    c->rows_seen += chunk->batch.n_spectra;
    return LX_OK;
}

static void test_batch_stream(void **state)
{
    lx_ctx *ctx = *state;
    char path[] = "/tmp/lx_test_stream_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    size_t rows = 1500; /* ~6 MB: several rounds of parts on 1 and on 2 threads */
    double *want = write_stream_csv(path, rows, -1);
    for (int mode = 0; mode < 4; mode++) { /* vector line parser on 1 and 2 threads, general parser likewise */
        if (mode >= 2) setenv("LX_SIMD", "scalar", 1);
        stream_check c = {want, 471, 0, 0, 0};
        lx_assert_ok(ctx, lx_batch_table_stream(ctx, path, LX_F64, 1 + mode % 2, check_chunk, &c));
        assert_int_equal(c.bad, 0);
        assert_int_equal(c.rows_seen, rows);
        assert_true(c.calls > 2);
        unsetenv("LX_SIMD");
    }
    /* end to end against the long double oracle on the strtod values */
    lx_function fns[4] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2, LX_FN_VPRIME};
    double *out = NULL;
    size_t got = 0;
    lx_assert_ok(ctx, lx_batch_table_integrate_file(ctx, path, fns, 4, 2, &out, &got));
    assert_int_equal(got, rows);
    for (size_t i = 0; i < rows; i += 13)
        for (int f = 0; f < 4; f++)
            lx_assert_near(out[i * 4 + (size_t)f], (double)oracle(ctx, want + i * 471, 471, 360, 1, fns[f]), 1e-12, 1e-12);
    lx_batch_results_free(out);
    free(want);
    /* a bad value in row 1234: file line = 1 comment + 1 header + 1234 rows before it + the blank
     * lines after rows i % 97 == 5 below 1234 (i = 5, 102, ..., 1169: 13 of them) + 1 */
    want = write_stream_csv(path, rows, 1234);
    free(want);
    stream_check c = {NULL, 471, 0, 0, 0};
    c.want = NULL;
    assert_int_equal(lx_batch_table_integrate_file(ctx, path, fns, 4, 2, &out, &got), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 1 + 1 + 1234 + 13 + 1);
    assert_int_equal(lx_batch_table_stream(ctx, path, LX_F32, 1, check_chunk_count, &c), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 1 + 1 + 1234 + 13 + 1);
    assert_true(c.rows_seen <= 1234);
    unlink(path);
}

/* ---- lx_batch_table_stream_ex: work on the parsing threads, read mode, long lines ---- */

static lx_status plain_count(void *user, const lx_batch_table *part, size_t row0, void *state)
{
    (void)state;
    return check_chunk_count(user, part, row0);
}

typedef struct long_check {
    size_t rows;
    int bad;
} long_check;

static lx_status long_emit(void *user, const lx_batch_table *part, size_t row0, void *state)
{
    (void)state;
    long_check *c = user;
    const double *v = part->batch.values;
    if (part->batch.n_lambda != 400000 || part->batch.start_nm != 100 || part->batch.step_nm != 1) c->bad++;
    for (size_t i = 0; i < part->batch.n_spectra; i++)
        for (size_t j = 0; j < part->batch.n_lambda; j += 997)
            if (v[i * part->batch.n_lambda + j] != (double)((j + row0 + i) % 10) + 0.5) c->bad++;
    c->rows += part->batch.n_spectra;
    return LX_OK;
}


typedef struct ex_check {
    stream_check c;   /* the emitted rows, as check_chunk checks them */
    _Atomic int works, bad_thread, threads;
    size_t progress_calls;
    unsigned long long last_done, total;
} ex_check;

/* work: the sum of each row into the part's state (a buffer kept from part to part) */
static lx_status ex_work(void *user, int thread, const lx_batch_table *part, void **state)
{
    ex_check *e = user;
    if (thread < 0 || thread >= e->threads) e->bad_thread++;
    double *sum = realloc(*state, (part->batch.n_spectra + 1) * sizeof *sum);
    if (!sum) return LX_ENOMEM;
    *state = sum;
    const double *v = part->batch.values;
    sum[0] = (double)part->batch.n_spectra;
    for (size_t i = 0; i < part->batch.n_spectra; i++) {
        double a = 0;
        for (size_t j = 0; j < part->batch.n_lambda; j++) a += v[i * part->batch.n_lambda + j];
        sum[i + 1] = a;
    }
    e->works++;
    return LX_OK;
}

static lx_status ex_emit(void *user, const lx_batch_table *part, size_t row0, void *state)
{
    ex_check *e = user;
    const double *sum = state, *v = part->batch.values;
    if (!sum || sum[0] != (double)part->batch.n_spectra) e->c.bad++;
    for (size_t i = 0; sum && i < part->batch.n_spectra; i++) {
        double a = 0;
        for (size_t j = 0; j < part->batch.n_lambda; j++) a += v[i * part->batch.n_lambda + j];
        if (a != sum[i + 1]) e->c.bad++; /* the work saw this very part */
    }
    return check_chunk(&e->c, part, row0);
}

static void ex_progress(void *user, unsigned long long done, unsigned long long total)
{
    ex_check *e = user;
    if (done < e->last_done) e->c.bad++;
    e->last_done = done;
    e->total = total;
    e->progress_calls++;
}

static void ex_release(void *user, void *state)
{
    (void)user;
    free(state);
}

static void test_batch_stream_ex(void **state)
{
    lx_ctx *ctx = *state;
    char path[] = "/tmp/lx_test_streamex_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    size_t rows = 1500;
    double *want = write_stream_csv(path, rows, -1);
    struct stat sb;
    assert_int_equal(stat(path, &sb), 0);
    /* mode 0: the map; 1: read from an open stream (a pipe's path); 2: the same after a prefix the
     * caller read itself; on 1 and 2 threads */
    for (int mode = 0; mode < 6; mode++) {
        int threads = 1 + mode % 2, how = mode / 2;
        ex_check e;
        memset(&e, 0, sizeof e);
        e.c = (stream_check){want, 471, 0, 0, 0};
        e.threads = threads;
        lx_batch_stream cb = {.user = &e, .work = ex_work, .emit = ex_emit, .release = ex_release, .progress = ex_progress};
        FILE *f = NULL;
        char prefix[5000];
        if (how) {
            f = fopen(path, "rb");
            assert_non_null(f);
            cb.input = f;
            if (how == 2) { /* a prefix that ends inside the header line */
                cb.prefix_len = fread(prefix, 1, sizeof prefix, f);
                cb.prefix = prefix;
            }
        }
        lx_assert_ok(ctx, lx_batch_table_stream_ex(ctx, path, LX_F64, threads, &cb));
        if (f) fclose(f);
        assert_int_equal(e.c.bad, 0);
        assert_int_equal(e.bad_thread, 0);
        assert_int_equal(e.c.rows_seen, rows);
        assert_true(e.works >= 2 && e.c.calls == (size_t)e.works);
        assert_true(e.progress_calls >= 2);
        assert_true(e.last_done == (unsigned long long)sb.st_size); /* the whole input consumed */
        assert_true(e.total == (how ? 0 : (unsigned long long)sb.st_size)); /* a stream has no size */
    }
    free(want);
    /* a bad row: the same line from the map and from a stream */
    want = write_stream_csv(path, rows, 1234);
    free(want);
    for (int how = 0; how < 2; how++) {
        ex_check e;
        memset(&e, 0, sizeof e);
        e.c = (stream_check){NULL, 471, 0, 0, 0};
        e.threads = 2;
        lx_batch_stream cb = {.user = &e, .emit = plain_count, .input = how ? fopen(path, "rb") : NULL};
        assert_int_equal(lx_batch_table_stream_ex(ctx, path, LX_F64, 2, &cb), LX_EPARSE);
        assert_int_equal(lx_ctx_errline(ctx), 1 + 1 + 1234 + 13 + 1);
        if (cb.input) fclose(cb.input);
    }
    /* lines longer than a round of text (one thread: 4 parts of 512 KB): a header of 400000
     * wavelengths (2.7 MB) and rows of 400000 values, read from a stream */
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("id", f);
    for (int j = 0; j < 400000; j++) fprintf(f, ",%d", 100 + j);
    for (int r = 0; r < 3; r++) {
        fprintf(f, "\nr%d", r);
        for (int j = 0; j < 400000; j++) fprintf(f, ",%d.5", (j + r) % 10);
    }
    fputc('\n', f);
    assert_int_equal(fclose(f), 0);
    long_check lc = {0, 0};
    lx_batch_stream cb = {.user = &lc, .emit = long_emit, .input = fopen(path, "rb")};
    lx_assert_ok(ctx, lx_batch_table_stream_ex(ctx, path, LX_F64, 1, &cb));
    fclose(cb.input);
    assert_int_equal(lc.rows, 3);
    assert_int_equal(lc.bad, 0);
    unlink(path);
}

/* A line longer than the documented maximum (4 MB, README "Robustness") is refused with its
 * line, after every row before it was handed on; a line of exactly 4 MB is read. So is a header
 * line that long; lx_batch_table_read (the whole file in memory) keeps the spectrum-file limit. */
static lx_status count_rows(void *user, const lx_batch_table *chunk, size_t row0)
{
    stream_check *c = user;
    if (row0 != c->rows_seen) c->bad++;
    const double *v = chunk->batch.values;
    for (size_t i = 0; i < chunk->batch.n_spectra * chunk->batch.n_lambda; i++)
        if (v[i] != 1) c->bad++;
    c->rows_seen += chunk->batch.n_spectra;
    return LX_OK;
}

static void write_long_line_csv(const char *path, size_t rows_before, size_t long_bytes, size_t rows_after)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "id,400,500,600\n");
    for (size_t i = 0; i < rows_before; i++) fprintf(f, "r%zu,1,1,1\n", i);
    /* a comment line of long_bytes bytes: skipped when it is allowed, refused when too long */
    fputc('#', f);
    for (size_t i = 1; i < long_bytes; i++) fputc('x', f);
    fputc('\n', f);
    for (size_t i = 0; i < rows_after; i++) fprintf(f, "t%zu,1,1,1\n", i);
    assert_int_equal(fclose(f), 0);
}

static void test_batch_line_limit(void **state)
{
    lx_ctx *ctx = *state;
    char path[] = "/tmp/lx_test_longline_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    size_t max = (size_t)4 << 20;
    write_long_line_csv(path, 100000, max, 10); /* 1.3 MB of rows first: the line straddles parts */
    stream_check c = {NULL, 3, 0, 0, 0};
    lx_assert_ok(ctx, lx_batch_table_stream(ctx, path, LX_F64, 2, count_rows, &c));
    assert_int_equal(c.rows_seen, 100010);
    assert_int_equal(c.bad, 0);
    write_long_line_csv(path, 100000, max + 1, 10);
    memset(&c, 0, sizeof c);
    assert_int_equal(lx_batch_table_stream(ctx, path, LX_F64, 2, count_rows, &c), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 1 + 100000 + 1);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), ":100002: line longer than 4 MB, the longest line of a batch CSV file"));
    assert_int_equal(c.rows_seen, 100000); /* every row before it */
    assert_int_equal(c.bad, 0);
    write_long_line_csv(path, 0, 5 << 20, 3); /* at the start of the body */
    memset(&c, 0, sizeof c);
    assert_int_equal(lx_batch_table_stream(ctx, path, LX_F64, 1, count_rows, &c), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 2);
    assert_int_equal(c.rows_seen, 0);
    /* a header line too long, and a file with no line end at all */
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("id", f);
    for (size_t i = 0; i < max / 4; i++) fputs(",500", f);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(lx_batch_table_stream(ctx, path, LX_F64, 1, count_rows, &c), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 1);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "line longer than 4 MB"));
    /* the whole-file reader keeps the spectrum-file size limit */
    write_long_line_csv(path, 1000, 10, 0);
    lx_batch_table *t = NULL;
    lx_assert_ok(ctx, lx_ctx_set_input_limit(ctx, LX_INPUT_SPECTRUM, 1000));
    assert_int_equal(lx_batch_table_read(ctx, path, LX_F64, 1, &t), LX_EIO);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "larger than 1000 bytes"));
    memset(&c, 0, sizeof c); /* streaming is bounded by its chunks, not by the limit */
    lx_assert_ok(ctx, lx_batch_table_stream(ctx, path, LX_F64, 1, count_rows, &c));
    assert_int_equal(c.rows_seen, 1000);
    lx_assert_ok(ctx, lx_ctx_set_input_limit(ctx, LX_INPUT_SPECTRUM, 0));
    lx_assert_ok(ctx, lx_batch_table_read(ctx, path, LX_F64, 1, &t));
    assert_int_equal(t->batch.n_spectra, 1000);
    lx_batch_table_free(t);
    unlink(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_table_sums, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_half_nm_grid_is_trapezoid, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_illuminant_a, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_parity_avx512, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_parity_avx2, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_parity_scalar, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_empty_and_errors, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_backend_names, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_auto_small_batch_stays_on_cpu, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_resample_cpu, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_batch_csv, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_batch_stream, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_batch_stream_ex, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_batch_line_limit, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
