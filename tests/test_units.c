/* test_units.c - the unit table, quantity parsing ("1000lm", "2.5 m", "46 fc"), conversions and
 * their round trips, printing, and radiometric <-> photometric conversion with an efficacy.
 * Unit sizes are definitions: ft = 0.3048 m and in = 0.0254 m (international yard and pound
 * agreement, 1959); fc = lm/ft2; fL = (1/pi) cd/ft2; lambert = (1/pi) cd/cm2 (CIE S 017 / NIST
 * SP 811 appendix B); decimal values below computed from these in 60-digit decimal arithmetic. */
#include "lx_test.h"

#include <string.h>

#define PI 3.14159265358979323846

static double parse(lx_ctx *ctx, const char *s, lx_quantity q, const char *bare)
{
    double v = NAN;
    lx_assert_ok(ctx, lx_quantity_parse(ctx, s, q, bare, &v, NULL));
    return v;
}

static void test_parse_contract_examples(void **state)
{
    lx_ctx *ctx = *state;
    /* the examples of CLI.md "Conventions" */
    lx_assert_near(parse(ctx, "1000lm", LX_Q_LUMINOUS_FLUX, NULL), 1000, 0, 0);
    lx_assert_near(parse(ctx, "2.5 m", LX_Q_LENGTH, NULL), 2.5, 0, 0);
    lx_assert_near(parse(ctx, "30deg", LX_Q_ANGLE, NULL), PI / 6, 0, 1e-15);
    lx_assert_near(parse(ctx, "8ft", LX_Q_LENGTH, NULL), 2.4384, 0, 1e-15); /* 8 x 0.3048 */
    lx_assert_near(parse(ctx, "500lx", LX_Q_ILLUMINANCE, NULL), 500, 0, 0);
    /* 46 fc = 46 / 0.3048^2 = 495.13987916864722618 lx */
    lx_assert_near(parse(ctx, "46fc", LX_Q_ILLUMINANCE, NULL), 495.13987916864722618, 0, 1e-15);
    lx_assert_near(parse(ctx, "1000cd/m2", LX_Q_LUMINANCE, NULL), 1000, 0, 0);
    lx_assert_near(parse(ctx, "2700K", LX_Q_TEMPERATURE, NULL), 2700, 0, 0);
    lx_assert_near(parse(ctx, "0.5rad", LX_Q_ANGLE, NULL), 0.5, 0, 0);
    /* spellings */
    lx_assert_near(parse(ctx, "1000 cd/m\xc2\xb2", LX_Q_LUMINANCE, NULL), 1000, 0, 0);
    lx_assert_near(parse(ctx, "1000 cd/m^2", LX_Q_LUMINANCE, NULL), 1000, 0, 0);
    lx_assert_near(parse(ctx, "3 nits", LX_Q_LUMINANCE, NULL), 3, 0, 0);
    lx_assert_near(parse(ctx, "12in", LX_Q_LENGTH, NULL), 0.3048, 0, 1e-15);
    lx_assert_near(parse(ctx, "5 mW", LX_Q_RADIANT_FLUX, NULL), 0.005, 0, 1e-15);
    lx_assert_near(parse(ctx, "1e-3", LX_Q_LENGTH, NULL), 1e-3, 0, 0);
    /* a bare number takes the given bare unit, else the SI unit */
    lx_assert_near(parse(ctx, "90", LX_Q_ANGLE, "deg"), PI / 2, 0, 1e-15);
    lx_assert_near(parse(ctx, "2", LX_Q_ANGLE, NULL), 2, 0, 0);
    lx_quantity got = LX_Q_NONE;
    double v;
    lx_assert_ok(ctx, lx_quantity_parse(ctx, "10 fL", LX_Q_NONE, NULL, &v, &got));
    assert_int_equal(got, LX_Q_LUMINANCE);
}

static void test_parse_errors(void **state)
{
    lx_ctx *ctx = *state;
    double v = 7;
    /* mismatched unit: names the unit and both quantities */
    assert_int_equal(lx_quantity_parse(ctx, "3lm", LX_Q_LENGTH, NULL, &v, NULL), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "'lm'"));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "length"));
    /* unknown unit */
    assert_int_equal(lx_quantity_parse(ctx, "3 furlongs", LX_Q_LENGTH, NULL, &v, NULL), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "furlongs"));
    /* not a number */
    assert_int_equal(lx_quantity_parse(ctx, "lm", LX_Q_NONE, NULL, &v, NULL), LX_EPARSE);
    assert_int_equal(lx_quantity_parse(ctx, "", LX_Q_NONE, NULL, &v, NULL), LX_EPARSE);
    assert_int_equal(lx_quantity_parse(ctx, "nan", LX_Q_NONE, NULL, &v, NULL), LX_EPARSE);
    assert_int_equal(lx_quantity_parse(ctx, "1e999 m", LX_Q_NONE, NULL, &v, NULL), LX_EPARSE);
    assert_int_equal(lx_quantity_parse(ctx, "0x10 m", LX_Q_NONE, NULL, &v, NULL), LX_EPARSE);
    assert_true(v == 7); /* untouched on failure */
}

static void test_round_trips(void **state)
{
    lx_ctx *ctx = *state;
    double a, b;
    /* 1 fc = 1/0.3048^2 lx = 10.763910416709722308 lx */
    lx_assert_ok(ctx, lx_unit_convert(ctx, 1, "fc", "lx", &a));
    lx_assert_near(a, 10.763910416709722308, 0, 1e-15);
    /* 1 fL = 1/(pi 0.3048^2) cd/m2 = 3.4262590996353905269 cd/m2 */
    lx_assert_ok(ctx, lx_unit_convert(ctx, 1, "fL", "cd/m2", &a));
    lx_assert_near(a, 3.4262590996353905269, 0, 1e-15);
    /* 1 lambert = 1e4/pi cd/m2 = 3183.0988618379067154 cd/m2 */
    lx_assert_ok(ctx, lx_unit_convert(ctx, 1, "lambert", "cd/m2", &a));
    lx_assert_near(a, 3183.0988618379067154, 0, 1e-15);
    /* 1 fL = 1/(0.3048^2 1e4) lambert = 1.0763910416709722e-3 L (the pi cancels) */
    lx_assert_ok(ctx, lx_unit_convert(ctx, 1, "fL", "lambert", &a));
    lx_assert_near(a, 1.0763910416709722308e-3, 0, 1e-14);
    /* round trips within 1e-12 over a wide range of values */
    const char *pairs[][2] = {{"fc", "lx"}, {"fL", "cd/m2"}, {"lambert", "cd/m2"}, {"fL", "lambert"},
                              {"nit", "fL"}, {"ft", "m"}, {"deg", "rad"}, {"W/cm2", "W/m2"}};
    const double vals[] = {1e-9, 0.37, 1, 46, 1234.5678, 3e8};
    for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; p++)
        for (size_t i = 0; i < sizeof vals / sizeof vals[0]; i++) {
            lx_assert_ok(ctx, lx_unit_convert(ctx, vals[i], pairs[p][0], pairs[p][1], &a));
            lx_assert_ok(ctx, lx_unit_convert(ctx, a, pairs[p][1], pairs[p][0], &b));
            lx_assert_near(b, vals[i], 0, 1e-12);
        }
    assert_int_equal(lx_unit_convert(ctx, 1, "fc", "cd", &a), LX_EINVAL);
    assert_int_equal(lx_unit_convert(ctx, 1, "fc", "nope", &a), LX_EPARSE);
}

static void test_table_and_format(void **state)
{
    lx_ctx *ctx = *state;
    size_t n;
    const lx_unit *u = lx_units(&n);
    /* the units the issue names are all there, with the right quantity */
    const char *names[] = {"lm", "W", "cd", "W/sr", "lx", "W/m2", "fc", "cd/m2", "nit", "fL", "lambert",
                           "sr", "m", "cm", "mm", "ft", "in", "deg", "rad", "K"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        const lx_unit *f;
        lx_assert_ok(ctx, lx_unit_find(ctx, names[i], &f));
        assert_string_equal(f->name, names[i]);
    }
    for (size_t i = 0; i < n; i++) {
        assert_true(u[i].to_si > 0);
        assert_true(u[i].quantity > LX_Q_NONE && u[i].quantity < LX_Q_COUNT);
    }
    assert_string_equal(lx_quantity_si_unit(LX_Q_ILLUMINANCE), "lx");
    char buf[64];
    /* 500 lx in fc: 500 x 0.09290304 = 46.45152 fc exactly in decimal; printed shortest */
    lx_assert_ok(ctx, lx_unit_format(ctx, 500, "fc", buf, sizeof buf));
    assert_string_equal(buf, "46.45152 fc");
    assert_int_equal(lx_unit_format(ctx, 500, "fc", buf, 4), LX_EINVAL);
}

static void test_radiometric(void **state)
{
    lx_ctx *ctx = *state;
    double v;
    lx_quantity q;
    /* photometric = K x radiometric: 2 W at 100 lm/W is 200 lm; back: 200 lx at 100 lm/W is 2 W/m2 */
    lx_assert_ok(ctx, lx_radiometric_convert(ctx, 2, LX_Q_RADIANT_FLUX, 100, &v, &q));
    lx_assert_near(v, 200, 0, 0);
    assert_int_equal(q, LX_Q_LUMINOUS_FLUX);
    lx_assert_ok(ctx, lx_radiometric_convert(ctx, 200, LX_Q_ILLUMINANCE, 100, &v, &q));
    lx_assert_near(v, 2, 0, 0);
    assert_int_equal(q, LX_Q_IRRADIANCE);
    /* no silent default: an efficacy must be given */
    assert_int_equal(lx_radiometric_convert(ctx, 2, LX_Q_RADIANT_FLUX, 0, &v, &q), LX_EINVAL);
    assert_int_equal(lx_radiometric_convert(ctx, 2, LX_Q_RADIANT_FLUX, NAN, &v, &q), LX_EINVAL);
    assert_int_equal(lx_radiometric_convert(ctx, 2, LX_Q_LENGTH, 100, &v, &q), LX_EINVAL);
    assert_int_equal(lx_quantity_counterpart(LX_Q_RADIANCE), LX_Q_LUMINANCE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parse_contract_examples), cmocka_unit_test(test_parse_errors),
        cmocka_unit_test(test_round_trips), cmocka_unit_test(test_table_and_format),
        cmocka_unit_test(test_radiometric),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
