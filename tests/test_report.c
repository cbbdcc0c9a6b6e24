/* test_report.c - the geometry and colours of the spectrum report (report_png.c): the spectral
 * locus, isotemperature lines, the TM-30 vector graphic normalisation, sRGB conversion, the
 * Fichet et al. channel names, and the report PNG read back: its size, labels that hold text and
 * never overlap, the headline numbers against CIE 015 (D65 chromaticity), the unit of Y, the
 * isotherm and bar labels, the u'v' diagram, a laser's undefined CRI with its reason, and atomic
 * failure; every isotherm label on its own line; the TM-30 page (bars in their bins' colours under
 * colour-science's values, arrowheads). */
#include "plot_test.h"

#include <unistd.h>

#include "radiance/radiance_private.h"
#include "plot/report.h"

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
    lx_report_opts o = {.unit = "W/m2/nm", .title = "D65"};
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__report_png(ctx, &d65, &o, path, &L));
    test_png png;
    test_png_read(path, &png);
    assert_int_equal(png.w, 1200), assert_int_equal(png.h, 880);
    test_labels_ok(&png, &L);
    /* the chromaticity of D65 (CIE 015:2018 Table 3: x 0.31272, y 0.32903) to 5 decimals */
    const lx__label *xy = test_find(&L, LX__TEXT_STATS, "0.3127");
    assert_non_null(xy);
    double x = strtod(xy->text, NULL), y = strtod(strchr(xy->text, ',') + 1, NULL);
    lx_assert_near(x, 0.31272, 2e-5, 0), lx_assert_near(y, 0.32903, 2e-5, 0);
    assert_non_null(strstr(xy->text, ", ")), assert_int_equal((int)(strchr(xy->text, ',') - xy->text), 7);
    /* Y of an irradiance spectrum is an illuminance in lx; the SPD axis carries the unit */
    assert_non_null(test_find(&L, LX__TEXT_STATS, "illuminance"));
    assert_non_null(test_find(&L, LX__TEXT_STATS, " lx"));
    assert_non_null(test_find(&L, LX__TEXT_STATS, " W/m\u00b2"));
    assert_non_null(test_find(&L, LX__TEXT_AXIS, "W/(m\u00b2 nm)"));
    assert_non_null(test_find(&L, LX__TEXT_AXIS, "wavelength (nm)"));
    /* CCT to 0.1 K, Duv to 1e-5 */
    const lx__label *cct = test_find(&L, LX__TEXT_STATS, " K");
    assert_non_null(cct);
    assert_non_null(strchr(cct->text, '.')), assert_int_equal((int)strlen(strchr(cct->text, '.')), 4); /* ".N K" */
    /* at least two isotherms labelled (the others where they would collide), the 15 bars named */
    int iso = 0;
    for (size_t i = 0; i < L.n_label; i++) iso += L.label[i].role == LX__TEXT_LABEL && strstr(L.label[i].text, "0 K") != NULL;
    assert_true(iso >= 2);
    assert_non_null(test_find(&L, LX__TEXT_TICK, "Ra"));
    assert_non_null(test_find(&L, LX__TEXT_TICK, "R14"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "Rf"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "CIE 1931 xy"));
    /* the swatch of D65 is white: D65 is the sRGB white point (IEC 61966-2-1) */
    const lx__label *sw = test_find(&L, LX__TEXT_NOTE, "colour of the light");
    assert_non_null(sw);
    unsigned char c[3];
    test_px(&png, (int)sw->box.x0 + 40, (int)sw->box.y1 + 50, c);
    assert_true(c[0] >= 254 && c[1] >= 254 && c[2] >= 254);
    test_png_free(&png);
    lx__layout_free(&L);
    /* the u'v' diagram; illuminant A (2856 K) is orange-white: red > green > blue */
    lx_spd a;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "A", &a));
    o = (lx_report_opts){.diagram = LX_DIAGRAM_UV};
    lx_assert_ok(ctx, lx__report_png(ctx, &a, &o, path, &L));
    test_png_read(path, &png);
    test_labels_ok(&png, &L);
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "CIE 1976 u\u2032v\u2032"));
    assert_non_null(test_find(&L, LX__TEXT_AXIS, "u\u2032"));
    assert_non_null(test_find(&L, LX__TEXT_STATS, "Y (relative)"));
    sw = test_find(&L, LX__TEXT_NOTE, "colour of the light");
    test_px(&png, (int)sw->box.x0 + 40, (int)sw->box.y1 + 50, c);
    assert_true(c[0] == 255 && c[1] < c[0] && c[2] < c[1]);
    test_png_free(&png);
    lx__layout_free(&L);
    /* a 532 nm laser: CRI is undefined; its reason is shown */
    double wl[3] = {531, 532, 533}, val[3] = {0, 1, 0};
    lx_spd las = {.lambda_nm = wl, .value = val, .n = 3, .name = "laser"};
    lx_assert_ok(ctx, lx__report_png(ctx, &las, NULL, path, &L));
    test_png_read(path, &png);
    test_labels_ok(&png, &L);
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "not defined"));
    assert_non_null(test_find(&L, LX__TEXT_NOTE, "Duv"));
    test_png_free(&png);
    lx__layout_free(&L);
    unlink(path);
    /* a bad unit, and an unwritable place: errors, nothing left behind */
    o = (lx_report_opts){.unit = "W/ft2"};
    assert_int_equal(lx_spd_report_write_png(ctx, &d65, &o, path), LX_EINVAL);
    snprintf(path, sizeof path, "%s/missing/d65.png", dir);
    assert_int_equal(lx_spd_report_write_png(ctx, &d65, NULL, path), LX_EIO);
    assert_int_equal(access(path, F_OK), -1);
    rmdir(dir);
}

/* the distance from (px, py) to box b (0 inside) */
static double box_dist(lx__box b, double px, double py)
{
    double dx = fmax(fmax(b.x0 - px, 0), px - b.x1), dy = fmax(fmax(b.y0 - py, 0), py - b.y1);
    return hypot(dx, dy);
}

/* the distance from box b to the ray from the labelled end of isotherm q (lay.iso: T, then the
 * other end and the labelled end) on along the line, up to 70 pixels */
static double ray_dist(const double *q, lx__box b)
{
    double dx = q[3] - q[1], dy = q[4] - q[2], n = hypot(dx, dy), best = INFINITY;
    for (double t = 0; t <= 70; t += 0.25) best = fmin(best, box_dist(b, q[3] + t * dx / n, q[4] + t * dy / n));
    return best;
}

/* Every isotherm label sits on its own line's extension beyond its end (within 2.5 pixels),
 * nearer to it than to any other isotherm's: under its own tick, for both diagrams and the crowded
 * low temperatures of a warm source. */
static void isotherm_labels(void **state)
{
    lx_ctx *ctx = *state;
    char dir[] = "/tmp/lxisoXXXXXX", path[256];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/r.png", dir);
    static const char *const names[] = {"FL2", "A", "D65"};
    for (int k = 0; k < 6; k++) {
        lx_spd s;
        lx_assert_ok(ctx, lx_illuminant_get(ctx, names[k % 3], &s));
        lx_report_opts o = {.diagram = k < 3 ? LX_DIAGRAM_XY : LX_DIAGRAM_UV};
        lx__layout L = {0};
        lx_assert_ok(ctx, lx__report_png(ctx, &s, &o, path, &L));
        assert_int_equal(L.n_iso, 8);
        int labelled = 0;
        for (size_t i = 0; i < L.n_label; i++) {
            const lx__label *l = &L.label[i];
            if (l->role != LX__TEXT_LABEL || !strstr(l->text, " K")) continue;
            int own = -1;
            for (int j = 0; j < L.n_iso; j++)
                if (L.iso[j][0] == l->value) own = j;
            assert_true(own >= 0);
            double d = ray_dist(L.iso[own], l->box);
            if (!(d <= 2.5)) print_error("%s: label %s is %.1f px off its isotherm's extension\n", names[k % 3], l->text, d), fail();
            for (int j = 0; j < L.n_iso; j++)
                if (j != own && !(ray_dist(L.iso[j], l->box) > d)) {
                    print_error("%s: label %s lies as near the %.0f K isotherm as its own\n", names[k % 3], l->text, L.iso[j][0]);
                    fail();
                }
            labelled++;
        }
        assert_true(labelled >= 4); /* most of the eight find room */
        lx__layout_free(&L);
    }
    unlink(path);
    rmdir(dir);
}

/* The TM-30 page of FL2: the values of colour-science 0.4.7's TM-30-18 report (Rcs,h1 -25 %, Rhs,h3
 * 0.24, Rf,h6 88, as its plot_single_sd_colour_rendition_report prints them) on the bars; each bar
 * in its bin's colour under its value; each arrow's head in its bin's colour, at the test point;
 * the labels on the page, never overlapping. */
static void tm30_page(void **state)
{
    lx_ctx *ctx = *state;
    char dir[] = "/tmp/lxtm30XXXXXX", path[256];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/fl2_tm30.png", dir);
    lx_spd fl2;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "FL2", &fl2));
    lx_tm30 tm;
    lx_assert_ok(ctx, lx_tm30_compute(ctx, &fl2, &tm));
    lx_report_opts o = {.title = "FL2"};
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__tm30_png(ctx, &fl2, &o, path, &L));
    test_png png;
    test_png_read(path, &png);
    assert_int_equal(png.w, 1200), assert_int_equal(png.h, 1080);
    test_labels_ok(&png, &L);
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "TM-30-20 colour rendition report"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "local chroma shift Rcs,hj"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "local hue shift Rhs,hj"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "local colour fidelity Rf,hj"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "Rf,CESi"));
    assert_non_null(test_find(&L, LX__TEXT_LABEL, "-25%"));
    assert_non_null(test_find(&L, LX__TEXT_LABEL, "0.24"));
    assert_non_null(test_find(&L, LX__TEXT_LABEL, "88"));
    /* the bars: each Rf,hj value label stands on its bar, which has its bin's colour just below it */
    int bars = 0;
    for (size_t i = 0; i < L.n_label; i++) {
        const lx__label *l = &L.label[i];
        if (l->role != LX__TEXT_LABEL || strchr(l->text, '%') || strchr(l->text, '.')) continue;
        for (int b = 0; b < 16; b++) {
            char want[16];
            snprintf(want, sizeof want, "%.0f", tm.rf_hue[b]);
            if (l->value != tm.rf_hue[b] || strcmp(l->text, want)) continue;
            unsigned char c[3], bin[3];
            test_px(&png, (int)(0.5 * (l->box.x0 + l->box.x1)), (int)l->box.y1 + 6, c);
            lx__tm30_bin_rgb(b, 0, bin);
            if (abs(c[0] - bin[0]) > 2 || abs(c[1] - bin[1]) > 2 || abs(c[2] - bin[2]) > 2)
                print_error("bin %d: %d %d %d under its value, not %d %d %d\n", b + 1, c[0], c[1], c[2], bin[0], bin[1], bin[2]), fail();
            bars++;
        }
    }
    assert_int_equal(bars, 16);
    /* the arrows: 16, from the reference circle to the test point; a head in the bin's colour
     * 4 pixels back from the tip */
    assert_int_equal(L.n_arrows, 16);
    int heads = 0;
    for (int a = 0; a < 16; a++) {
        const double *q = L.arrow[a];
        double dx = q[2] - q[0], dy = q[3] - q[1], n = hypot(dx, dy);
        if (n < 12) continue; /* a short one is a dot */
        unsigned char c[3], bin[3];
        test_px(&png, (int)lround(q[2] - 4 * dx / n), (int)lround(q[3] - 4 * dy / n), c);
        lx__tm30_bin_rgb((int)q[4], 1, bin);
        if (abs(c[0] - bin[0]) > 40 || abs(c[1] - bin[1]) > 40 || abs(c[2] - bin[2]) > 40)
            print_error("arrow %d: %d %d %d at its head, not %d %d %d\n", a + 1, c[0], c[1], c[2], bin[0], bin[1], bin[2]), fail();
        heads++;
    }
    assert_true(heads >= 12);
    test_png_free(&png);
    lx__layout_free(&L);
    /* undefined TM-30 (a laser line): an error, no file */
    double wl[3] = {531, 532, 533}, val[3] = {0, 1, 0};
    lx_spd las = {.lambda_nm = wl, .value = val, .n = 3, .name = "laser"};
    unlink(path);
    assert_int_equal(lx_tm30_report_write_png(ctx, &las, NULL, path), LX_ERANGE);
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
        cmocka_unit_test_setup_teardown(isotherm_labels, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(tm30_page, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
