/* test_report.c - the geometry and colours of the spectrum report (report_png.c): the spectral
 * locus, isotemperature lines, the TM-30 vector graphic normalisation, sRGB conversion, the
 * Fichet et al. channel names, and the report PNG itself (size, swatch, atomic failure). */
#include "lx_test.h"

#include <png.h>
#include <string.h>
#include <unistd.h>

#include "plot/plot_private.h"
#include "radiance/radiance_private.h"

static unsigned char *read_png(const char *path, int *w, int *h)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path)) return NULL;
    img.format = PNG_FORMAT_RGB;
    unsigned char *buf = malloc(PNG_IMAGE_SIZE(img));
    if (!buf || !png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        free(buf);
        return NULL;
    }
    *w = (int)img.width;
    *h = (int)img.height;
    return buf;
}

static void spectral_locus(void **state)
{
    lx_ctx *ctx = *state;
    double x, y;
    lx_assert_ok(ctx, lx__locus_xy(ctx, LX_OBSERVER_2, 520, &x, &y));
    /* CIE 015:2018 Table 11 (chromaticity of the spectrum locus, 2 deg): 520 nm (0.0743, 0.8338) */
    lx_assert_near(x, 0.0743, 6e-5, 0);
    lx_assert_near(y, 0.8338, 6e-5, 0);
    lx_assert_ok(ctx, lx__locus_xy(ctx, LX_OBSERVER_2, 600, &x, &y));
    /* CIE 015:2018 Table 11: 600 nm (0.6270, 0.3725) */
    lx_assert_near(x, 0.6270, 6e-5, 0);
    lx_assert_near(y, 0.3725, 6e-5, 0);
}

static void isotemperature(void **state)
{
    lx_ctx *ctx = *state;
    /* a point at distance duv along the locus normal has its nearest locus point at T: the exact
     * CCT solver (cct.c, an independent search) must give back T and duv (sign: + above) */
    const double T[] = {2000, 3000, 6500}, D[] = {0.01, -0.02, 0.015};
    for (int k = 0; k < 3; k++) {
        double x, y, cct, duv;
        lx_assert_ok(ctx, lx__isotemp_xy(ctx, LX_OBSERVER_2, T[k], D[k], &x, &y));
        lx_assert_ok(ctx, lx_cct_from_xy(ctx, LX_OBSERVER_2, x, y, &cct, &duv));
        lx_assert_near(cct, T[k], 0, 1e-4);
        lx_assert_near(duv, D[k], 1e-6, 0);
    }
}

static void cvg_normalisation(void **state)
{
    (void)state;
    /* closed form: ref (3, 4) has |ref| = 5 and hue (0.6, 0.8); test = ref maps onto the unit circle,
     * test = 1.1 ref to radius 1.1 at the same hue */
    double ref[2] = {3, 4}, t1[2] = {3, 4}, t2[2] = {3.3, 4.4}, o[2];
    lx__cvg_point(ref, t1, o);
    lx_assert_near(o[0], 0.6, 1e-15, 0);
    lx_assert_near(o[1], 0.8, 1e-15, 0);
    lx__cvg_point(ref, t2, o);
    lx_assert_near(o[0], 0.66, 1e-15, 0);
    lx_assert_near(o[1], 0.88, 1e-15, 0);
}

static void srgb(void **state)
{
    lx_ctx *ctx = *state;
    unsigned char c[3];
    /* IEC 61966-2-1: D65 (XYZ 0.95047, 1, 1.08883) is sRGB white; the red primary (0.4124, 0.2126,
     * 0.0193) is pure red */
    double d65[3] = {0.95047, 1.0, 1.08883}, red[3] = {0.4124, 0.2126, 0.0193};
    lx__xyz_to_srgb8(d65, c);
    assert_int_equal(c[0], 255), assert_int_equal(c[1], 255), assert_int_equal(c[2], 255);
    lx__xyz_to_srgb8(red, c);
    assert_int_equal(c[0], 255), assert_true(c[1] <= 1), assert_true(c[2] <= 1);
    /* monochromatic light: 450 nm lies in the blue, 530 nm in the green, 620 nm in the red corner
     * of the xy diagram (CIE 015 Table 11: (0.1566, 0.0177), (0.1547, 0.8059), (0.6915, 0.3083)) */
    lx__wavelength_srgb8(ctx, 450, c);
    assert_true(c[2] > c[0] && c[2] > c[1]);
    lx__wavelength_srgb8(ctx, 530, c);
    assert_true(c[1] > c[0] && c[1] > c[2]);
    lx__wavelength_srgb8(ctx, 620, c);
    assert_true(c[0] > c[1] && c[0] > c[2]);
}

static void channel_names(void **state)
{
    (void)state;
    int k;
    double l;
    /* Fichet et al. 2021 section 3: "S0.550,000000nm" is the emissive Stokes-0 channel at 550 nm */
    assert_int_equal(lx__spectral_channel("S0.550,000000nm", &k, &l), 0);
    assert_int_equal(k, 0);
    lx_assert_near(l, 550, 0, 0);
    assert_int_equal(lx__spectral_channel("S2.400,5nm", &k, &l), 0);
    assert_int_equal(k, 2);
    lx_assert_near(l, 400.5, 0, 0);
    assert_int_equal(lx__spectral_channel("T.700,0nm", &k, &l), 0);
    assert_int_equal(k, 4);
    assert_int_equal(lx__spectral_channel("S0.0,55um", &k, &l), 0);
    lx_assert_near(l, 550, 1e-12, 0);
    assert_int_equal(lx__spectral_channel("R", &k, &l), -1);
    assert_int_equal(lx__spectral_channel("S0.550Hz", &k, &l), -1);
    assert_int_equal(lx__spectral_channel("S0.nm", &k, &l), -1);
    assert_int_equal(lx__spectral_channel("S4.550nm", &k, &l), -1);
}

static void report_png(void **state)
{
    lx_ctx *ctx = *state;
    char dir[] = "/tmp/lxreportXXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[256];
    snprintf(path, sizeof path, "%s/d65.png", dir);
    lx_spd d65;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &d65));
    lx_assert_ok(ctx, lx_spd_report_png(ctx, &d65, LX_OBSERVER_2, "D65", path));
    int w = 0, h = 0;
    unsigned char *img = read_png(path, &w, &h);
    assert_non_null(img);
    assert_int_equal(w, 1100), assert_int_equal(h, 800);
    /* the swatch (990..1069, 556..635) of D65 is white: D65 is the sRGB white point (IEC 61966-2-1) */
    const unsigned char *p = img + ((size_t)596 * w + 1030) * 3;
    assert_true(p[0] >= 254 && p[1] >= 254 && p[2] >= 254);
    free(img);
    unlink(path);
    /* illuminant A (2856 K) is orange-white: red > green > blue */
    lx_spd a;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "A", &a));
    lx_assert_ok(ctx, lx_spd_report_png(ctx, &a, LX_OBSERVER_2, NULL, path));
    img = read_png(path, &w, &h);
    assert_non_null(img);
    p = img + ((size_t)596 * w + 1030) * 3;
    assert_true(p[0] == 255 && p[1] < p[0] && p[2] < p[1]);
    free(img);
    unlink(path);
    /* unwritable place: LX_EIO and nothing left behind */
    snprintf(path, sizeof path, "%s/missing/d65.png", dir);
    assert_int_equal(lx_spd_report_png(ctx, &d65, LX_OBSERVER_2, NULL, path), LX_EIO);
    assert_int_equal(access(path, F_OK), -1);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(spectral_locus, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(isotemperature, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(cvg_normalisation, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(srgb, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(channel_names, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(report_png, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
