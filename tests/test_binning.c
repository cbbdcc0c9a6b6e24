/* test_binning.c - LED binning: the published ANSI C78.377 centres fall in their own categories with
 * CCT and Duv near the table's targets, category and flexible-CCT edges, MacAdam steps in closed
 * form, the table-based CCT of the batch against the exact solve, and the batch against the
 * per-chromaticity path. */
#include "lx_test.h"

#include "spectral/spectral_private.h"

#include <string.h>

static void xy_to_uv(double x, double y, double *u, double *v)
{
    double d = -2 * x + 12 * y + 3;
    *u = 4 * x / d, *v = 6 * y / d;
}

/* the chromaticity at CCT T and Duv d: the Planckian point moved d along the normal in CIE 1960 uv */
static void at_cct_duv(lx_ctx *ctx, double T, double d, double *x, double *y)
{
    double u0, v0, u1, v1;
    lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, T, &u0, &v0));
    lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, T * 1.0001, &u1, &v1));
    double tu = u1 - u0, tv = v1 - v0, n = hypot(tu, tv);
    /* + above the locus: the normal pointing to larger v */
    double nu = tv / n, nv = -tu / n;
    if (nv < 0) nu = -nu, nv = -nv;
    double u = u0 + d * nu, v = v0 + d * nv;
    double den = 2 * u - 8 * v + 4;
    *x = 3 * u / den, *y = 2 * v / den;
}

/* ANSI C78.377-2015/2017 centres and targets (src/data/ansi_c78377_categories.csv) */
static const struct {
    int K;
    double target, tol, duv, cx, cy;
} ansi[] = {
    {2200, 2238, 102, 0.000, 0.5018, 0.4153}, {2500, 2460, 120, 0.000, 0.4806, 0.4141},
    {2700, 2725, 145, 0.000, 0.4578, 0.4101}, {3000, 3045, 175, 0.000, 0.4339, 0.4033},
    {3500, 3465, 245, 0.000, 0.4078, 0.3930}, {4000, 3985, 275, 0.001, 0.3818, 0.3797},
    {4500, 4503, 243, 0.001, 0.3613, 0.3670}, {5000, 5029, 283, 0.002, 0.3446, 0.3551},
    {5700, 5667, 355, 0.002, 0.3287, 0.3425}, {6500, 6532, 510, 0.003, 0.3123, 0.3283},
};

static void test_published_centres(void **state)
{
    lx_ctx *ctx = *state;
    for (size_t i = 0; i < sizeof ansi / sizeof *ansi; i++) {
        double T, d;
        lx_assert_ok(ctx, lx_cct_from_xy(ctx, LX_OBSERVER_2, ansi[i].cx, ansi[i].cy, &T, &d));
        print_message("  %d K: centre CCT %.1f K (target %g), Duv %.5f (target %.3f)\n", ansi[i].K, T, ansi[i].target, d,
                      ansi[i].duv);
        /* the centres are printed to 4 decimals (0.00005 in x, y is about 10 K and 1e-4 in Duv here) and
         * the 2015 centres follow the Duv formula where the table rounds to 0.001: 2 K, 5.5e-4 */
        lx_assert_near(T, ansi[i].target, 2, 0);
        lx_assert_near(d, ansi[i].duv, 5.5e-4, 0);
        lx_binning b;
        lx_assert_ok(ctx, lx_binning_compute(ctx, ansi[i].cx, ansi[i].cy, T, d, &b));
        assert_int_equal(b.ansi_K, ansi[i].K);
        lx_assert_near(b.ansi_duv_offset, d - ansi[i].duv, 1e-15, 0);
    }
}

static void test_category_edges(void **state)
{
    lx_ctx *ctx = *state;
    lx_binning b;
    /* 2870 K is the shared edge of 2700 (2725 + 145) and 3000 (3045 - 175): the first holds it */
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.45, 0.41, 2870, 0.0, &b));
    assert_int_equal(b.ansi_K, 2700);
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.45, 0.41, 2870.5, 0.0, &b));
    assert_int_equal(b.ansi_K, 3000);
    /* Duv tolerance 0.006 around the target (4000 K: 0.001) */
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.38, 0.38, 4000, 0.007, &b));
    assert_int_equal(b.ansi_K, 4000);
    lx_assert_near(b.ansi_duv_offset, 0.006, 1e-15, 0);
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.38, 0.38, 4000, 0.0071, &b));
    assert_int_equal(b.ansi_K, 0);
    assert_true(isnan(b.ansi_duv_offset));
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.38, 0.38, 4000, -0.0051, &b));
    assert_int_equal(b.ansi_K, 0);
    /* outside 2136-7042 K: no category */
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.3, 0.3, 7100, 0.003, &b));
    assert_int_equal(b.ansi_K, 0);
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.5, 0.4, NAN, NAN, &b));
    assert_int_equal(b.ansi_K, 0);
    assert_int_equal(b.flex_K, 0);
}

static void test_flexible_cct(void **state)
{
    lx_ctx *ctx = *state;
    lx_binning b;
    /* the formulas of C78.377: target Duv 57700/T^2 - 44.6/T + 0.0085, tolerance
     * 1.19e-8 T^3 - 1.5434e-4 T^2 + 0.7168 T - 902.55 (3300 K: Duv 0.00028, +-209.8 K) */
    double T = 3300, duv = 57700 / (T * T) - 44.6 / T + 0.0085, tol = ((1.19e-8 * T - 1.5434e-4) * T + 0.7168) * T - 902.55;
    lx_assert_near(duv, 0.000283, 1e-6, 0);
    lx_assert_near(tol, 209.78, 0.01, 0);
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.41, 0.39, 3330, duv + 0.002, &b));
    assert_int_equal(b.flex_K, 3300);
    lx_assert_near(b.flex_duv_offset, 0.002, 1e-15, 0);
    assert_int_equal(b.ansi_K, 3500); /* 3330 K: beyond 3000's 3045 + 175, inside 3500's 3465 - 245 */
    /* 3300 + 210 K holds, 3300 + 215 K is nearer 3500 */
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.41, 0.39, 3505, 0.0, &b));
    assert_int_equal(b.flex_K, 3500);
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.41, 0.39, 3000, duv - 0.0065, &b));
    assert_int_equal(b.flex_K, 0); /* below every target Duv's tolerance nearby */
    /* the flexible rule stops at 2700 K (C78.377-2011's range): 2600 K is nearest to 2700 K */
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.46, 0.41, 2600, 0.0, &b));
    assert_int_equal(b.flex_K, 2700);
}

static void test_sdcm(void **state)
{
    lx_ctx *ctx = *state;
    lx_binning b;
    /* IEC 60081 F4000 (0.380, 0.380), g11 39.5e4: dx = 1/sqrt(g11) is one step; 3 dx three */
    double dx = 1 / sqrt(39.5e4);
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.380, 0.380, NAN, NAN, &b));
    lx_assert_near(b.sdcm, 0, 1e-12, 0);
    assert_int_equal(b.sdcm_centre_K, 4000);
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.380 + 3 * dx, 0.380, NAN, NAN, &b));
    lx_assert_near(b.sdcm, 3, 0, 1e-12);
    assert_int_equal(b.sdcm_centre_K, 4000);
    /* along y with g22 26e4, and along the diagonal with 2 g12 (F6500: 86, -40, 45) */
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.380, 0.380 - 2 / sqrt(26e4), NAN, NAN, &b));
    lx_assert_near(b.sdcm, 2, 0, 1e-12);
    double t = 1e-3;
    lx_assert_ok(ctx, lx_binning_compute(ctx, 0.313 + t, 0.337 + t, NAN, NAN, &b));
    assert_int_equal(b.sdcm_centre_K, 6500);
    lx_assert_near(b.sdcm, sqrt(1e4 * (86 - 2 * 40 + 45)) * t, 0, 1e-12);
    /* the F6500 ellipse against MacAdam's 1942 ellipse at (0.305, 0.323): semi-axes 0.0009 and
     * 0.0023, major axis at 58 deg (colour-science 0.4.7 DATA_MACADAM_1942_ELLIPSES) */
    double a = 86, c = 45, g = -40, tr = a + c, det = a * c - g * g, disc = sqrt(tr * tr / 4 - det);
    double lmin = tr / 2 - disc, lmax = tr / 2 + disc;
    lx_assert_near(1 / sqrt(lmin * 1e4), 0.0023, 0.0002, 0);
    lx_assert_near(1 / sqrt(lmax * 1e4), 0.0009, 0.0001, 0);
    lx_assert_near(atan2(a - lmin, -g) * 180 / M_PI, 58, 1.5, 0);
}

/* the table-based CCT of the batch path against the exact solve */
static void test_table_cct(void **state)
{
    lx_ctx *ctx = *state;
    double worst_T = 0, worst_d = 0;
    for (double T = 1500; T <= 10000; T *= 1.01)
        for (double d = -0.02; d <= 0.0201; d += 0.005) {
            double x, y, u, v, Te, de, Tt, dt;
            at_cct_duv(ctx, T, d, &x, &y);
            xy_to_uv(x, y, &u, &v);
            lx_assert_ok(ctx, lx_cct_from_uv(ctx, LX_OBSERVER_2, u, v, &Te, &de));
            lx_assert_ok(ctx, lx__cct_from_uv_table(ctx, LX_OBSERVER_2, u, v, &Tt, &dt));
            if (fabs(Tt - Te) > worst_T) worst_T = fabs(Tt - Te);
            if (fabs(dt - de) > worst_d) worst_d = fabs(dt - de);
        }
    print_message("  worst |dT| %.3g K, |dDuv| %.3g over 1500-10000 K, Duv -0.02..0.02\n", worst_T, worst_d);
    assert_true(worst_T < 0.02);
    assert_true(worst_d < 1e-8);
}

static void test_batch_matches(void **state)
{
    lx_ctx *ctx = *state;
    enum { N = 600, NL = 471 };
    static double v[N * NL];
    for (int i = 0; i < N; i++)
        for (int j = 0; j < NL; j++) v[i * NL + j] = lx_planck(360 + j, 2000 + 8 * i) * (1 + 0.05 * sin(0.01 * j * (i % 7)));
    lx_batch b = {N, NL, 0, 360, 1, LX_F64, v};
    static lx_binning bb[N];
    lx_assert_ok(ctx, lx_binning_batch(ctx, &b, NULL, bb));
    int bins = 0;
    for (int i = 0; i < N; i++) {
        double l[NL];
        for (int j = 0; j < NL; j++) l[j] = 360 + j;
        lx_spd s = {"s", NL, l, v + i * NL};
        lx_colorimetry c;
        lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_CIE15, &c));
        lx_binning r;
        lx_assert_ok(ctx, lx_binning_compute(ctx, c.x, c.y, c.cct_K, c.duv, &r));
        assert_int_equal(bb[i].ansi_K, r.ansi_K);
        assert_int_equal(bb[i].flex_K, r.flex_K);
        assert_int_equal(bb[i].sdcm_centre_K, r.sdcm_centre_K);
        lx_assert_near(bb[i].sdcm, r.sdcm, 1e-9, 1e-9);
        if (r.ansi_K) lx_assert_near(bb[i].ansi_duv_offset, r.ansi_duv_offset, 2e-7, 0);
        bins += r.ansi_K != 0;
    }
    assert_true(bins > N / 2);
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, lx_test_ctx_setup, lx_test_ctx_teardown)
    const struct CMUnitTest tests[] = {
        T(test_published_centres), T(test_category_edges), T(test_flexible_cct), T(test_sdcm), T(test_table_cct),
        T(test_batch_matches),
    };
    return cmocka_run_group_tests_name("binning", tests, NULL, NULL);
}
