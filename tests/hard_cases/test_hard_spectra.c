/* test_hard_spectra.c - hard cases for spectra (issue 9): sub-nm lines between table rows, extreme
 * scales (1e-30, 1e30, denormals) on the double CPU path and the float kernels, a 1e7-term float
 * accumulation, blackbodies at 1 K, 100 K and 1e6 K, CCT at the ends of its range and at |Duv| =
 * 0.05, NaN/Inf rejected with line numbers, bit-identical CPU results, float vs double tolerances.
 * Each test says why the case is hard and where the right answer comes from. */
#include "lx_test.h"

#include <string.h>

static lx_spd cmf_y(lx_ctx *ctx)
{
    lx_spd y;
    lx_function_get(ctx, LX_FN_YBAR_2, &y);
    return y;
}

/* ybar at l from the 1 nm table rows, linearly interpolated (CIE 015 recommends linear
 * interpolation of the CMFs), computed here from the rows themselves. */
static double ybar_at(const lx_spd *y, double l)
{
    size_t k = (size_t)(l - y->lambda_nm[0]);
    double t = l - y->lambda_nm[k];
    return y->value[k] + t * (y->value[k + 1] - y->value[k]);
}

static int have_opencl(lx_ctx *ctx)
{
    lx_cl_device_info info;
    return lx_cl_info(ctx, &info) == LX_OK;
}

/* Hard: a 0.008 nm wide line lies between two 1 nm CMF rows; any method that samples at whole nm
 * misses it or counts it 125x too wide. Right answer (closed form): the integral of a triangle of
 * area a against a function that is linear over its support is a x f(centre). The Na D lines:
 * 588.995 nm (D2) and 589.592 nm (D1), NIST Atomic Spectra Database (Na I, air wavelengths). */
static void sub_nm_lines_between_rows(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd y = cmf_y(ctx);
    const double w = 0.004;
    double l[6] = {588.995 - w, 588.995, 588.995 + w, 589.592 - w, 589.592, 589.592 + w};
    double v[6] = {0, 2.0 / w, 0, 0, 1.0 / w, 0}; /* areas 2 and 1 */
    lx_spd s = {"Na", 6, l, v};
    double got;
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s, &y, LX_METHOD_EXACT, &got));
    double want = 2 * ybar_at(&y, 588.995) + 1 * ybar_at(&y, 589.592);
    lx_assert_near(got, want, 0, 1e-11);
    /* auto resolves to exact for these non-uniform samples; Y = Km x the integral, Km = 683.002 lm/W */
    lx_colorimetry c;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &c));
    assert_int_equal(c.method, LX_METHOD_EXACT);
    lx_assert_near(c.Y, 683.002 * want, 0, 1e-11);
    /* a line centred on a row (532 nm, half-base 0.05): the CMF has a kink there, so the closed form is
     * a f(c) + (a / w)(s_r - s_l) w^2 / 6 with s_l, s_r the slopes per nm left and right of the row
     * (integrate (a/w)(1 - t/w)(f(c) +- s t) over t in [0, w] on each side) */
    double l2[3] = {531.95, 532, 532.05}, v2[3] = {0, 1 / 0.05, 0};
    lx_spd s2 = {"laser", 3, l2, v2};
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s2, &y, LX_METHOD_EXACT, &got));
    size_t k = (size_t)(532 - y.lambda_nm[0]);
    double sl = y.value[k] - y.value[k - 1], sr = y.value[k + 1] - y.value[k];
    lx_assert_near(got, y.value[k] + (1 / 0.05) * (sr - sl) * 0.05 * 0.05 / 6, 0, 1e-12);
}

/* Hard: 1e-30 and 1e30 times a real spectrum; float holds 1.2e-38 .. 3.4e38, so products with small
 * CMF values and sums of many terms approach the float limits. Right answer: integration is
 * linear, so the result is exactly the scale times the unscaled result (to rounding). */
static void extreme_scales(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd d65;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &d65));
    lx_colorimetry ref;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &d65, LX_OBSERVER_2, LX_METHOD_CIE15, &ref));
    /* the D65 samples on the 1 nm grid 360-830 (linear between the 5 nm rows) for the batch paths */
    static double vd[471];
    static float vf[3][471];
    for (int j = 0; j < 471; j++) {
        double l = 360 + j, x = 0;
        for (size_t r = 0; r + 1 < d65.n; r++)
            if (d65.lambda_nm[r] <= l && l <= d65.lambda_nm[r + 1])
                x = d65.value[r] + (l - d65.lambda_nm[r]) / (d65.lambda_nm[r + 1] - d65.lambda_nm[r]) * (d65.value[r + 1] - d65.value[r]);
        vd[j] = x;
    }
    static const lx_function F[3] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2};
    double base[3];
    lx_batch bd = {.n_spectra = 1, .n_lambda = 471, .start_nm = 360, .step_nm = 1, .dtype = LX_F64, .values = vd};
    lx_batch_opts cpu = {.backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &bd, F, 3, &cpu, base));
    int cl = have_opencl(ctx);
    static const double scales[3] = {1e-30, 1e30, 1e-40};
    for (int s = 0; s < 3; s++) {
        double k = scales[s];
        if (s < 2) { /* double CPU path, the reference: exact linearity */
            double *v = malloc(d65.n * sizeof *v);
            for (size_t i = 0; i < d65.n; i++) v[i] = d65.value[i] * k;
            lx_spd sc = {"scaled", d65.n, d65.lambda_nm, v};
            lx_colorimetry c;
            lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &sc, LX_OBSERVER_2, LX_METHOD_CIE15, &c));
            lx_assert_near(c.Y, ref.Y * k, 0, 1e-14);
            lx_assert_near(c.x, ref.x, 1e-14, 0);
            lx_assert_near(c.y, ref.y, 1e-14, 0);
            lx_assert_near(c.cct_K, ref.cct_K, 1e-8, 0);
            free(v);
        }
        /* float input (1e-40 is a float denormal: 7 significant bits lost, so 1e-2 relative) */
        for (int j = 0; j < 471; j++) vf[s][j] = (float)(vd[j] * k);
        double tol = s == 2 ? 2e-2 : 1e-6; /* float rounding of the input: 6e-8 per value */
        lx_batch bf = {.n_spectra = 1, .n_lambda = 471, .start_nm = 360, .step_nm = 1, .dtype = LX_F32, .values = vf[s]};
        double got[3];
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &bf, F, 3, &cpu, got));
        for (int f = 0; f < 3; f++) lx_assert_near(got[f], base[f] * k, 0, tol);
        if (!cl) continue;
        lx_batch_opts o = {.backend = LX_BACKEND_OPENCL};
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &bf, F, 3, &o, got));
        for (int f = 0; f < 3; f++) lx_assert_near(got[f], base[f] * k, 0, tol);
        setenv("LX_CL_ACCUM", "kahan", 1); /* float weights and float sums: the hardest */
        lx_status st = lx_batch_integrate(ctx, &bf, F, 3, &o, got);
        unsetenv("LX_CL_ACCUM");
        lx_assert_ok(ctx, st);
        for (int f = 0; f < 3; f++) lx_assert_near(got[f], base[f] * k, 0, s == 2 ? 2e-2 : 1e-5);
    }
}

/* Hard: one integral of 1e7 float terms; naive float accumulation loses ~1e7 x 6e-8 relative.
 * Right answer: a spectrum of 1 everywhere integrates to the integral of ybar, i.e. the trapezoid
 * sum of the 1 nm table, sum(ybar) x 1 nm minus half the two end rows (Σȳ = 106.856917, CIE
 * 018:2019 / the table test); the fine cie15 sum adds half an end sample each side (~1e-11). */
static void float_accumulation_1e7(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd y = cmf_y(ctx);
    double want = 0;
    for (size_t i = 0; i < y.n; i++) want += y.value[i];
    want -= 0.5 * (y.value[0] + y.value[y.n - 1]);
    const size_t n = 10000001;
    float *v = malloc(n * sizeof *v);
    assert_non_null(v);
    for (size_t j = 0; j < n; j++) v[j] = 1.0f;
    lx_batch b = {.n_spectra = 1, .n_lambda = n, .start_nm = 360, .step_nm = 470.0 / (double)(n - 1), .dtype = LX_F32, .values = v};
    const lx_function F = LX_FN_YBAR_2;
    double got;
    lx_batch_opts cpu = {.backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, &F, 1, &cpu, &got));
    lx_assert_near(got, want, 0, 1e-7);
    if (have_opencl(ctx)) {
        lx_batch_opts o = {.backend = LX_BACKEND_OPENCL};
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, &F, 1, &o, &got));
        lx_assert_near(got, want, 0, 1e-7);
        setenv("LX_CL_ACCUM", "kahan", 1); /* compensated float sums: bounded by ~2 eps, not n eps */
        lx_status st = lx_batch_integrate(ctx, &b, &F, 1, &o, &got);
        unsetenv("LX_CL_ACCUM");
        lx_assert_ok(ctx, st);
        lx_assert_near(got, want, 0, 1e-6);
    }
    free(v);
}

/* Hard: Planck's exponent c2/(lambda T) is 2.9e4 at 1 K and 500 nm (exp overflows) and 0.029 at
 * 1e6 K (exp(x) - 1 cancels). Right answers: the closed form with expm1; at 1 K the value is below
 * the smallest double (exp(-28776)), so exactly 0, never NaN or Inf; at 1e6 K the series
 * 1/(e^x - 1) = 1/x - 1/2 + x/12 - x^3/720 (x = 0.028776, next term 7e-14 relative). */
static void blackbody_extremes(void **state)
{
    (void)state;
    const double c1 = 1.191042972e-16, c2 = 1.4388e-2;
    assert_true(lx_planck(500, 1) == 0.0);
    double l = 500e-9, x = c2 / (l * 1e6);
    double series = 1 / x - 0.5 + x / 12 - x * x * x / 720;
    lx_assert_near(lx_planck(500, 1e6), c1 / pow(l, 5) * series * 1e-9, 0, 1e-12);
    /* 100 K at its Wien peak, 2.8978e-3 m K / 100 K = 28978 nm: x = 4.965, no cancellation */
    l = 28978e-9;
    x = c2 / (l * 100);
    lx_assert_near(lx_planck(28978, 100), c1 / pow(l, 5) / (exp(x) - 1) * 1e-9, 0, 1e-13);
    /* a 1 K blackbody has no visible light: Y = 0 and NaN chromaticity, status OK (documented) */
    double lam[471], val[471];
    for (int j = 0; j < 471; j++) lam[j] = 360 + j, val[j] = lx_planck(lam[j], 1);
    lx_spd s = {"bb1K", 471, lam, val};
    lx_ctx *ctx = *state;
    lx_colorimetry c;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &c));
    assert_true(c.Y == 0.0);
    assert_true(isnan(c.x) && !c.cct_valid);
    /* near 1e6 K, the top of the CCT search: the Planck uv at 9.5e5 K must come back as 9.5e5 K
     * (within half a locus node of 1e6 K, e.g. 9.9e5 K, the nearest node is the last one and the solver answers LX_ERANGE) */
    double u, v, T, duv;
    lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, 9.5e5, &u, &v));
    lx_assert_ok(ctx, lx_cct_from_uv(ctx, LX_OBSERVER_2, u, v, &T, &duv));
    lx_assert_near(T, 9.5e5, 0, 1e-6);
    lx_assert_near(duv, 0, 1e-9, 0);
}

/* Hard: at 1000 K the locus bends fastest, at 100000 K it crowds (1 K moves uv by 1e-9), and at
 * |Duv| = 0.05 the solver must find the foot of the perpendicular far from the curve. Right answer
 * (geometry): a point at distance 0.05 along the locus normal at T has CCT T and Duv +-0.05; the
 * normal comes from the locus tangent by central differences (relative step 1e-4). */
static void cct_range_ends_and_duv(void **state)
{
    lx_ctx *ctx = *state;
    static const double Ts[3] = {1000, 6504, 100000};
    for (int k = 0; k < 3; k++) {
        double T = Ts[k], u0, v0, u1, v1, u, v;
        lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, T * (1 - 1e-4), &u0, &v0));
        lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, T * (1 + 1e-4), &u1, &v1));
        lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, T, &u, &v));
        double tu = u1 - u0, tv = v1 - v0, tl = hypot(tu, tv);
        /* Duv > 0 above the locus (towards +v): the normal (-tv, tu) when it points to +v */
        double nu = -tv / tl, nv = tu / tl;
        if (nv < 0) nu = -nu, nv = -nv;
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double cct, duv;
            lx_assert_ok(ctx, lx_cct_from_uv(ctx, LX_OBSERVER_2, u + sgn * 0.05 * nu, v + sgn * 0.05 * nv, &cct, &duv));
            lx_assert_near(duv, sgn * 0.05, 2e-6, 0); /* the chord normal's angle error is O(1e-8) */
            lx_assert_near(cct, T, 0, 2e-4);
        }
        double cct, duv;
        lx_assert_ok(ctx, lx_cct_from_uv(ctx, LX_OBSERVER_2, u, v, &cct, &duv));
        lx_assert_near(cct, T, 0, 1e-6);
        lx_assert_near(duv, 0, 1e-10, 0);
    }
    /* cct_valid: |Duv| 0.049 is valid, 0.051 is not (CLI.md: empty beyond 0.05) */
    double u, v, u0, v0, u1, v1, xyz[3];
    lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, 3000, &u, &v));
    lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, 3000 * (1 - 1e-4), &u0, &v0));
    lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, 3000 * (1 + 1e-4), &u1, &v1));
    double tl = hypot(u1 - u0, v1 - v0), nu = -(v1 - v0) / tl, nv = (u1 - u0) / tl;
    if (nv < 0) nu = -nu, nv = -nv;
    for (int k = 0; k < 2; k++) {
        double d = k ? 0.051 : 0.049, uu = u + d * nu, vv = v + d * nv; /* Duv = d along the normal */
        u = uu;
        /* uv -> xyz with Y = 1: x = 3u / (2u - 8v + 4), y = 2v / (2u - 8v + 4) (CIE 1960 UCS) */
        double den = 2 * u - 8 * vv + 4, x = 3 * u / den, y = 2 * vv / den;
        xyz[0] = x / y, xyz[1] = 1, xyz[2] = (1 - x - y) / y;
        lx_colorimetry c;
        c.method = LX_METHOD_EXACT;
        lx_assert_ok(ctx, lx_colorimetry_from_integrals(ctx, LX_OBSERVER_2, xyz, 1, 1, &c));
        assert_int_equal(c.cct_valid, k ? 0 : 1);
        u -= d * nu;
    }
}

/* Hard: a NaN or Inf hidden in a file must stop the read with the line, never flow into sums.
 * Right answer: LX_EPARSE, lx_ctx_errline = the offending line. */
static void nan_inf_rejected_with_lines(void **state)
{
    lx_ctx *ctx = *state;
    static const char *bad[4] = {"wavelength,v\n380,1\n385,2\n390,nan\n395,1\n", "380,1\n385,inf\n390,1\n",
                                 "# c\n380,1\n385,1e400\n", "380,1\n-inf,2\n390,1\n"};
    static const long line[4] = {4, 2, 3, 2};
    for (int k = 0; k < 4; k++) {
        lx_spd_set *set = NULL;
        lx_status st = lx_spd_read_mem(ctx, "bad.csv", bad[k], strlen(bad[k]), &set);
        assert_int_equal(st, LX_EPARSE);
        assert_null(set);
        assert_int_equal(lx_ctx_errline(ctx), line[k]);
    }
    /* views built by the caller: lx_spd_check refuses NaN and Inf values and wavelengths */
    double l[3] = {380, 385, 390}, v[3] = {1, NAN, 1};
    lx_spd s = {"v", 3, l, v};
    double out = 42;
    assert_int_equal(lx_spd_integrate(ctx, &s, &s, LX_METHOD_EXACT, &out), LX_EINVAL);
    assert_true(out == 42); /* outputs untouched on failure */
    v[1] = INFINITY;
    lx_colorimetry c;
    assert_int_equal(lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &c), LX_EINVAL);
}

/* Hard: double denormals (1e-310) lose relative precision in every product. Right answer: the
 * chromaticity of a spectrum does not depend on its scale (x, y of D65 x 1e-310 = those of D65). */
static void denormal_spectrum(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd d65;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &d65));
    lx_colorimetry ref, c;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &d65, LX_OBSERVER_2, LX_METHOD_EXACT, &ref));
    double *v = malloc(d65.n * sizeof *v);
    for (size_t i = 0; i < d65.n; i++) v[i] = d65.value[i] * 1e-310;
    lx_spd s = {"denormal", d65.n, d65.lambda_nm, v};
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_EXACT, &c));
    lx_assert_near(c.Y, ref.Y * 1e-310, 0, 1e-9);
    lx_assert_near(c.x, ref.x, 1e-9, 0);
    lx_assert_near(c.y, ref.y, 1e-9, 0);
    assert_true(c.cct_valid);
    lx_assert_near(c.cct_K, ref.cct_K, 1e-3, 0);
    free(v);
}

/* Same input, same bits: the CPU batch path on 1 and 2 threads and on repeated runs. Float OpenCL
 * against the double CPU reference: 1e-6 relative (the documented tolerance of lx_batch_integrate
 * for float input; the device accumulates in double). */
static void bit_identical_and_parity(void **state)
{
    lx_ctx *ctx = *state;
    enum { N = 500, NL = 471 };
    float *v = malloc(sizeof(float) * N * NL);
    unsigned s = 7;
    for (int i = 0; i < N * NL; i++) {
        s = s * 1103515245u + 12345u;
        v[i] = (float)((s >> 8) / 16777216.0 * 100.0 + 1e-3);
    }
    static const lx_function F[4] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2, LX_FN_VPRIME};
    lx_batch b = {.n_spectra = N, .n_lambda = NL, .start_nm = 360, .step_nm = 1, .dtype = LX_F32, .values = v};
    double *r[3];
    for (int k = 0; k < 3; k++) {
        r[k] = malloc(sizeof(double) * N * 4);
        lx_batch_opts o = {.backend = LX_BACKEND_CPU, .threads = k == 1 ? 1 : 2};
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, F, 4, &o, r[k]));
    }
    assert_memory_equal(r[0], r[1], sizeof(double) * N * 4);
    assert_memory_equal(r[0], r[2], sizeof(double) * N * 4);
    if (have_opencl(ctx)) {
        lx_batch_opts o = {.backend = LX_BACKEND_OPENCL};
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, F, 4, &o, r[1]));
        for (int i = 0; i < N * 4; i++) lx_assert_near(r[1][i], r[0][i], 0, 1e-6);
    }
    for (int k = 0; k < 3; k++) free(r[k]);
    free(v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(sub_nm_lines_between_rows, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(extreme_scales, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(float_accumulation_1e7, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(blackbody_extremes, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(cct_range_ends_and_duv, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(nan_inf_rejected_with_lines, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(denormal_spectrum, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(bit_identical_and_parity, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
