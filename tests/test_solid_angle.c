/* test_solid_angle.c - solid angles of a cap, a lat-long pixel and a rectangle, and the
 * uniform hemisphere sky (E = pi L) integrated over lat-long pixels. References: closed forms
 * derived in the comments. */
#include "lx_test.h"

#define PI 3.14159265358979323846

static void test_cap(void **state)
{
    lx_ctx *ctx = *state;
    double s;
    /* hemisphere 2 pi, sphere 4 pi, 60 deg cone: 2 pi (1 - 1/2) = pi */
    lx_assert_ok(ctx, lx_solid_angle_cap(ctx, PI / 2, &s));
    lx_assert_near(s, 2 * PI, 0, 1e-15);
    lx_assert_ok(ctx, lx_solid_angle_cap(ctx, PI, &s));
    lx_assert_near(s, 4 * PI, 0, 1e-15);
    lx_assert_ok(ctx, lx_solid_angle_cap(ctx, PI / 3, &s));
    lx_assert_near(s, PI, 0, 1e-15);
    /* small cone: pi a^2 (1 - a^2/12) to O(a^6); 2 pi (1 - cos a) would lose every digit at 1e-9 */
    lx_assert_ok(ctx, lx_solid_angle_cap(ctx, 1e-9, &s));
    lx_assert_near(s, PI * 1e-18, 0, 1e-15);
    /* the Sun (half-angle 0.2666 deg): 6.8e-5 sr; series 2 pi (1 - cos a) = pi a^2 (1 - a^2/12 + a^4/360) */
    double a = 0.2666 * PI / 180;
    lx_assert_ok(ctx, lx_solid_angle_cap(ctx, a, &s));
    lx_assert_near(s, PI * a * a * (1 - a * a / 12 + a * a * a * a / 360), 0, 1e-14);
    assert_int_equal(lx_solid_angle_cap(ctx, -0.1, &s), LX_EINVAL);
}

static void test_latlong(void **state)
{
    lx_ctx *ctx = *state;
    /* the pixels of a map tile the sphere: sum = 4 pi */
    int w = 64, h = 32;
    double sum = 0, s;
    for (int r = 0; r < h; r++) {
        lx_assert_ok(ctx, lx_solid_angle_latlong_pixel(ctx, w, h, r, &s));
        assert_true(s > 0);
        sum += w * s;
    }
    lx_assert_near(sum, 4 * PI, 0, 1e-14);
    /* one row of a 1 x 2 map is a hemisphere */
    lx_assert_ok(ctx, lx_solid_angle_latlong_pixel(ctx, 1, 2, 0, &s));
    lx_assert_near(s, 2 * PI, 0, 1e-15);
    assert_int_equal(lx_solid_angle_latlong_pixel(ctx, w, h, h, &s), LX_EINVAL);
}

static void test_hemisphere_sky(void **state)
{
    lx_ctx *ctx = *state;
    /* uniform sky of luminance L: E = int L cos t dOmega over the upper hemisphere = pi L. Per pixel row
     * the exact integral of cos t sin t dt dphi is (dphi/2)(sin^2 t1 - sin^2 t0), so summing it with
     * the pixel solid angle x cos(centre) converges as O(1/h^2): check to 1e-6 at h = 2048. */
    int w = 8, h = 2048;
    double L = 1000, e = 0, s;
    for (int r = 0; r < h / 2; r++) {
        lx_assert_ok(ctx, lx_solid_angle_latlong_pixel(ctx, w, h, r, &s));
        double tc = (r + 0.5) * PI / h;
        e += w * s * L * cos(tc);
    }
    lx_assert_near(e, PI * L, 0, 1e-6);
    /* and the disk of huge radius at tiny height is the same sky: E = pi L */
    lx_source_result d;
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, L, 1e6, 1e-6, 0, LX_MODEL_EXACT, &d));
    lx_assert_near(d.exact_lx, PI * L, 0, 1e-14);
}

static void test_rect(void **state)
{
    lx_ctx *ctx = *state;
    double s;
    /* a cube face seen from the centre: 4 pi / 6 */
    lx_assert_ok(ctx, lx_solid_angle_rect(ctx, -1, 1, -1, 1, 1, &s));
    lx_assert_near(s, 4 * PI / 6, 0, 1e-15);
    /* an infinite quadrant (large rectangle at the corner): a quarter hemisphere pi/2 */
    lx_assert_ok(ctx, lx_solid_angle_rect(ctx, 0, 1e9, 0, 1e9, 1e-3, &s));
    lx_assert_near(s, PI / 2, 0, 1e-9);
    /* additivity: two halves of a rectangle off to the side */
    double a, b;
    lx_assert_ok(ctx, lx_solid_angle_rect(ctx, 2, 4, 1, 3, 1.5, &s));
    lx_assert_ok(ctx, lx_solid_angle_rect(ctx, 2, 3, 1, 3, 1.5, &a));
    lx_assert_ok(ctx, lx_solid_angle_rect(ctx, 3, 4, 1, 3, 1.5, &b));
    lx_assert_near(s, a + b, 0, 1e-14);
    /* far away: the small-angle limit area / d^2 (1 - O((size/d)^2)) */
    lx_assert_ok(ctx, lx_solid_angle_rect(ctx, -0.5, 0.5, -0.5, 0.5, 1e4, &s));
    lx_assert_near(s, 1e-8, 0, 1e-8);
    assert_int_equal(lx_solid_angle_rect(ctx, 0, 1, 0, 1, 0, &s), LX_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cap), cmocka_unit_test(test_latlong), cmocka_unit_test(test_hemisphere_sky),
        cmocka_unit_test(test_rect),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
