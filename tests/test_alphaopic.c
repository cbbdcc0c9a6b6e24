/* test_alphaopic.c - CIE S 026:2018 alpha-opic quantities: the D65 efficacies that define EDI,
 * the melanopic DER of illuminant A, closed forms for EDI/DER, and the batch path. */
#include "lx_test.h"
#include "line_spectrum.h"

/* D65 melanopic ELR 1.3262 mW/lm (CIE S 026:2018 Table 2, K_mel,v^D65, the definition of EDI), and
 * the four others (0.8173, 1.4558, 1.6289, 1.4497 mW/lm), computed from the embedded D65 (5 nm)
 * and action spectra (1 nm) with D65 interpolated to 1 nm as the CIE S 026 toolbox does: equal to
 * the published 4 decimals (+- 0.5 in the last digit, with 0.2e-4 mW/lm of slack for the 5 nm D65). */
static void test_d65_efficacy(void **state)
{
    lx_ctx *ctx = *state;
    static const double pub[5] = {0.8173e-3, 1.4558e-3, 1.6289e-3, 1.4497e-3, 1.3262e-3};
    lx_spd d65;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &d65));
    lx_alphaopic a;
    lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &d65, LX_METHOD_LINEAR1NM, &a));
    for (int k = 0; k < 5; k++) {
        lx_assert_near(a.elr[k], pub[k], 0.7e-7, 0);
        lx_assert_near(lx_alphaopic_d65_efficacy((lx_alphaopic_kind)k), pub[k], 0, 1e-12);
        lx_assert_near(a.der[k], 1.0, 1e-4, 0); /* D65 is its own reference: DER = 1 */
    }
    assert_true(isnan(lx_alphaopic_d65_efficacy((lx_alphaopic_kind)7)));
}

/* Illuminant A: melanopic DER 0.4957 +- 0.001 (the reference, CIE S 026 toolbox); DER
 * and EDI are consistent by definition: EDI = DER * E_v = E_mel / K^D65. */
static void test_illuminant_a(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd a;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "A", &a));
    lx_alphaopic r;
    lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &a, LX_METHOD_AUTO, &r));
    lx_assert_near(r.der[LX_AO_MEL], 0.4957, 0.001, 0);
    for (int k = 0; k < 5; k++) {
        lx_assert_near(r.edi[k], r.der[k] * r.illuminance, 0, 1e-12);
        lx_assert_near(r.edi[k], r.irradiance[k] / lx_alphaopic_d65_efficacy((lx_alphaopic_kind)k), 0, 1e-12);
    }
}

/* Closed form: a flat 1 W/m2/nm spectrum from 380 to 780 nm has E_alpha = the area of the action
 * spectrum (the same cie15 sum of the table taken directly here), and E_v = 683.002 * sum ybar. */
static void test_flat(void **state)
{
    lx_ctx *ctx = *state;
    static double wl[401], v[401];
    for (int i = 0; i < 401; i++) wl[i] = 380 + i, v[i] = 1.0;
    lx_spd s = {"flat", 401, wl, v}, w;
    lx_alphaopic r;
    lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &s, LX_METHOD_CIE15, &r));
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_ALPHA_MEL, &w));
    double area = 0;
    for (size_t i = 0; i < w.n; i++) area += w.value[i];
    lx_assert_near(r.irradiance[LX_AO_MEL], area, 0, 1e-12);
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &w));
    double y = 0;
    for (size_t i = 0; i < w.n; i++)
        if (w.lambda_nm[i] >= 380 && w.lambda_nm[i] <= 780) y += w.value[i];
    lx_assert_near(r.illuminance, 683.002 * y, 0, 1e-12);
    /* zero light: EDI 0, DER undefined (NaN), not an error */
    for (int i = 0; i < 401; i++) v[i] = 0;
    lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &s, LX_METHOD_CIE15, &r));
    assert_true(r.edi[LX_AO_MEL] == 0 && isnan(r.der[LX_AO_MEL]));
}

/* The batch path (lx_batch_integrate, CPU backend) agrees with the one-spectrum path (cie15 rule
 * on the same 5 nm samples) to rounding: both are the same sum. */
static void test_batch(void **state)
{
    lx_ctx *ctx = *state;
    const char *names[3] = {"A", "D65", "FL2"};
    static double vals[3 * 81], wl[81];
    for (int j = 0; j < 81; j++) wl[j] = 380 + 5.0 * j;
    for (int i = 0; i < 3; i++) {
        lx_spd s;
        lx_assert_ok(ctx, lx_illuminant_get(ctx, names[i], &s));
        for (int j = 0; j < 81; j++) {
            vals[i * 81 + j] = NAN;
            for (size_t k = 0; k < s.n; k++)
                if (s.lambda_nm[k] == wl[j]) vals[i * 81 + j] = s.value[k];
            assert_false(isnan(vals[i * 81 + j]));
        }
    }
    lx_batch b = {3, 81, 0, 380.0, 5.0, LX_F64, vals};
    lx_batch_opts o = {.backend = LX_BACKEND_CPU, .threads = 1};
    double out[18];
    lx_assert_ok(ctx, lx_alphaopic_batch(ctx, &b, &o, out));
    for (int i = 0; i < 3; i++) {
        lx_spd one = {names[i], 81, wl, vals + i * 81};
        lx_alphaopic r;
        lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &one, LX_METHOD_CIE15, &r));
        for (int k = 0; k < 5; k++) lx_assert_near(out[i * 6 + k], r.irradiance[k], 0, 1e-12);
        lx_assert_near(out[i * 6 + 5], r.illuminance, 0, 1e-12);
    }
}

/* The line spectrum of tests/line_spectrum.h: the alpha-opic irradiances integrate it exactly
 * (the same integration as the headline colorimetry). Reference: the five integrals of the spectrum
 * times the CIE S 026 action spectra (linear between their 1 nm nodes, 380-780 nm, zero outside)
 * computed in numpy 2.4.6 on the 0.01 nm grid of 380-780 nm that holds every breakpoint, each
 * interval's product of two linear functions integrated in closed form: sc 0.786769274339645,
 * mc 1.25529876869724, lc 1.35072180271254, rh 0.991206944522524, mel 0.79144855806746 W/m2 (per
 * W/m2/nm input); moved by 0.3 nm: mel 0.791789112044904. (Resampled to 1 nm the lines between
 * nodes would be lost: test_cri.c.) */
static void test_line_spectrum(void **state)
{
    lx_ctx *ctx = *state;
    static const double ref[5] = {0.786769274339645, 1.25529876869724, 1.35072180271254, 0.991206944522524, 0.79144855806746};
    double lam[LINE_MAX_SAMPLES], val[LINE_MAX_SAMPLES];
    lx_spd s;
    line_spectrum(0, lam, val, &s);
    lx_alphaopic a;
    lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &s, LX_METHOD_AUTO, &a));
    for (int k = 0; k < 5; k++) lx_assert_near(a.irradiance[k], ref[k], 0, 1e-12);
    line_spectrum(0.3, lam, val, &s);
    lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &s, LX_METHOD_AUTO, &a));
    lx_assert_near(a.irradiance[LX_AO_MEL], 0.791789112044904, 0, 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_d65_efficacy), cmocka_unit_test(test_illuminant_a),
        cmocka_unit_test(test_flat), cmocka_unit_test(test_batch), cmocka_unit_test(test_line_spectrum),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
