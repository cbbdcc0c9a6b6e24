/* test_tables.c - the embedded CIE tables: row counts, increasing wavelengths, known sums. */
#include "lx_test.h"

#include <string.h>

static void check_fn(lx_ctx *ctx, lx_function fn, size_t rows, double l0, double l1)
{
    lx_spd s;
    lx_assert_ok(ctx, lx_function_get(ctx, fn, &s));
    assert_int_equal(s.n, rows);
    lx_assert_near(s.lambda_nm[0], l0, 0, 0);
    lx_assert_near(s.lambda_nm[s.n - 1], l1, 0, 0);
    for (size_t i = 1; i < s.n; i++) {
        assert_true(s.lambda_nm[i] > s.lambda_nm[i - 1]);
        lx_assert_near(s.lambda_nm[i] - s.lambda_nm[i - 1], 1.0, 1e-12, 0); /* 1 nm tables */
    }
    for (size_t i = 0; i < s.n; i++) assert_true(isfinite(s.value[i]) && s.value[i] >= 0);
}

static void test_functions_shape(void **state)
{
    lx_ctx *ctx = *state;
    /* CIE 018:2019 / 015:2018: 360-830 nm at 1 nm = 471 rows; V' and S 026: 380-780 nm = 401 rows */
    check_fn(ctx, LX_FN_XBAR_2, 471, 360, 830);
    check_fn(ctx, LX_FN_YBAR_2, 471, 360, 830);
    check_fn(ctx, LX_FN_ZBAR_2, 471, 360, 830);
    check_fn(ctx, LX_FN_XBAR_10, 471, 360, 830);
    check_fn(ctx, LX_FN_YBAR_10, 471, 360, 830);
    check_fn(ctx, LX_FN_ZBAR_10, 471, 360, 830);
    check_fn(ctx, LX_FN_VPRIME, 401, 380, 780);
    for (lx_function f = LX_FN_ALPHA_SC; f <= LX_FN_ALPHA_MEL; f++) check_fn(ctx, f, 401, 380, 780);
    lx_spd s;
    assert_int_equal(lx_function_get(ctx, LX_FN_COUNT, &s), LX_EINVAL);
}

static double sum(const lx_spd *s)
{
    double t = 0;
    for (size_t i = 0; i < s->n; i++) t += s->value[i];
    return t;
}

static void test_known_sums(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd s;
    /* sum of ybar (CIE 1931, 1 nm, 360-830) = 106.856917 (CIE 015:2018 table sum; ../shared/STYLE.md) */
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &s));
    lx_assert_near(sum(&s), 106.856917, 1e-6, 0);
    /* ybar peaks at 1.0 at 555 nm (CIE 1924 V(lambda) definition) */
    lx_assert_near(s.value[555 - 360], 1.0, 1e-12, 0);
    /* V'(lambda) peaks at 1 at 507 nm (CIE 1951 definition) */
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_VPRIME, &s));
    lx_assert_near(s.value[507 - 380], 1.0, 1e-12, 0);
    /* melanopic action spectrum normalised to peak 1 near 490 nm (CIE S 026:2018) */
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_ALPHA_MEL, &s));
    double peak = 0;
    size_t at = 0;
    for (size_t i = 0; i < s.n; i++)
        if (s.value[i] > peak) peak = s.value[i], at = i;
    lx_assert_near(peak, 1.0, 1e-3, 0);
    lx_assert_near(s.lambda_nm[at], 490, 2, 0);
}

static void test_illuminants(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd s;
    /* D65 as shipped (colour-science 0.4.7 dataset of CIE 015:2018 Table 5): 300-780 nm at 5 nm =
     * 97 rows; D65(560) = 100.0 by normalisation */
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &s));
    assert_int_equal(s.n, 97);
    lx_assert_near(s.lambda_nm[0], 300, 0, 0);
    lx_assert_near(s.value[(560 - 300) / 5], 100.0, 1e-9, 0);
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "A", &s));
    lx_assert_near(s.value[(560 - 300) / 5], 100.0, 1e-9, 0);
    /* FL tables: 380-780 nm at 5 nm = 81 rows (CIE 015:2018 Table 10) */
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "FL2", &s));
    assert_int_equal(s.n, 81);
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "HP1", &s));
    assert_int_equal(s.n, 81);
    assert_int_equal(lx_illuminant_get(ctx, "D66", &s), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "D66"));
    int n = 0;
    for (const char *const *p = lx_illuminant_names(); *p; p++) n++;
    /* 6 (A, D50, D55, D65, D75, E) + 27 FL + 14 LED/HP */
    assert_int_equal(n, 6 + 27 + 14);
}

static void test_formula_a_matches_table(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd s;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "A", &s));
    /* the published A table is the formula rounded to 6 significant digits (CIE 015:2018 Table 5) */
    for (size_t i = 0; i < s.n; i++) lx_assert_near(lx_illuminant_a(s.lambda_nm[i]), s.value[i], 0, 5e-6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_functions_shape),
        cmocka_unit_test(test_known_sums),
        cmocka_unit_test(test_illuminants),
        cmocka_unit_test(test_formula_a_matches_table),
    };
    return cmocka_run_group_tests_name("tables", tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
