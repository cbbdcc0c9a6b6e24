/* test_plot.c - every plot rendered and read back: its size, that every label lies on the page
 * with text in it and overlaps no other, and what each plot must show. Isolux: contours at 1-2-5
 * levels that pass under their labels (checked against the closed form E = I h / d^3 of an
 * isotropic source), the luminaire mark where it stands, round legend ticks, the statistics to
 * their digits. False colour: decade ticks, a two-decade range for a flat map, the map's colours as
 * the legend reads them. Irradiance: a uniform sky gives pi L everywhere. Errors: missing
 * directory (LX_EIO), full disk (LX_EWRITE), nothing left behind. Round numbers of scale.c. */
#include "plot_test.h"

#include <errno.h>
#include <stdio.h>
#include <unistd.h>

static char dir[64];

static int setup(void **state)
{
    snprintf(dir, sizeof dir, "/tmp/lxplotXXXXXX");
    if (!mkdtemp(dir)) return -1;
    return lx_test_ctx_setup(state);
}

static int teardown(void **state)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) return -1;
    return lx_test_ctx_teardown(state);
}

/* ---- round numbers ---- */

static void round_numbers(void **state)
{
    (void)state;
    double v[32], step;
    int geo;
    /* a uniform office: 220-361 lx gives a step of 20 (7 levels), not a 1-2-5 series */
    int n = lx__levels_125(220.5, 361.1, v, 32, &geo);
    assert_int_equal(geo, 0);
    assert_int_equal(n, 7);
    lx_assert_near(v[0], 240, 0, 0), lx_assert_near(v[6], 360, 0, 0);
    /* a spot: 0.0135-668 lx, the 1-2-5 series over the top three decades: 1, 2, 5 ... 500 */
    n = lx__levels_125(0.0135, 668.25, v, 32, &geo);
    assert_int_equal(geo, 1);
    assert_int_equal(n, 9);
    for (int k = 0; k < n; k++) assert_true(test_is_125(v[k]));
    lx_assert_near(v[0], 1, 0, 0), lx_assert_near(v[8], 500, 0, 0);
    n = lx__ticks_linear(0, 4, 6, v, 32, &step);
    lx_assert_near(step, 0.5, 0, 0);
    assert_int_equal(n, 9);
    n = lx__ticks_log(0.01, 1e4, v, 32);
    assert_int_equal(n, 7);
    lx_assert_near(v[6], 1e4, 1e-9, 0);
    char buf[64];
    lx__fmt_sig(buf, sizeof buf, 62.834185983750004, 4), assert_string_equal(buf, "62.83");
    lx__fmt_sig(buf, sizeof buf, 0.013545833789809468, 4), assert_string_equal(buf, "0.01355");
    lx__fmt_sig(buf, sizeof buf, 668.2510966063114, 4), assert_string_equal(buf, "668.3");
    lx__fmt_sig(buf, sizeof buf, 99999.7, 4), assert_string_equal(buf, "100000");
    lx__fmt_tick(buf, sizeof buf, 2.5, 0.25), assert_string_equal(buf, "2.50");
    lx__fmt_tick(buf, sizeof buf, 1.5, 0.5), assert_string_equal(buf, "1.5");
    lx__fmt_decade(buf, sizeof buf, 1e6), assert_string_equal(buf, "10\u2076");
    lx__fmt_decade(buf, sizeof buf, 0.01), assert_string_equal(buf, "0.01");
}

/* ---- isolux ---- */

#define H_M 2.0 /* the source 2 m above the plane z = 0, at (2, 1.5) */
static double closed_form(double I, double x, double y)
{
    double d2 = (x - 2) * (x - 2) + (y - 1.5) * (y - 1.5) + H_M * H_M;
    return I * H_M / (d2 * sqrt(d2)); /* E = I cos(theta) / d^2 = I h / d^3 */
}

/* the data coordinates of pixel (x, y) on the layout's area */
static void data_at(const lx__layout *L, double x, double y, double *a, double *b)
{
    *a = L->ax0 + (x - L->area.x0) / (L->area.x1 - L->area.x0) * (L->ax1 - L->ax0);
    *b = L->ay0 + (L->area.y1 - y) / (L->area.y1 - L->area.y0) * (L->ay1 - L->ay0);
}

static void isolux_checks(lx_ctx *ctx, const char *path, const lx_plane *p, const double *E, double I, int white)
{
    lx_plot_mark mk = {{2, 1.5, H_M}, {0, 0, -1}, "L1"};
    lx_isolux_opts o = {.marks = &mk, .n_marks = 1, .source = "/some/dir/point_source.ies",
                        .background = white ? LX_ISOLUX_WHITE : LX_ISOLUX_FALSECOLOR};
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__isolux_png(ctx, path, p, E, &o, &L));
    test_png png;
    test_png_read(path, &png);
    /* the data area keeps the plane's 4:3 aspect, its longer side 640 pixels */
    lx_assert_near(L.area.x1 - L.area.x0, 640, 0, 0);
    lx_assert_near(L.area.y1 - L.area.y0, 480, 0, 0);
    assert_true(png.w > 640 && png.h > 480);
    test_labels_ok(&png, &L);
    /* contours: 1-2-5 levels, each with segments; every contour label names a level and its line
     * passes under it: the level lies between the closed form's least and greatest values over
     * the label's box */
    assert_true(L.n_levels >= 4);
    for (int k = 0; k < L.n_levels; k++) assert_true(L.level_segments[k] > 0);
    int nc = 0;
    for (size_t i = 0; i < L.n_label; i++) {
        const lx__label *l = &L.label[i];
        if (l->role != LX__TEXT_CONTOUR) continue;
        nc++;
        assert_true(test_is_125(l->value) || (L.n_levels > 1 && fmod(l->value, L.level[1] - L.level[0]) < 1e-9));
        assert_true(strtod(l->text, NULL) == l->value); /* the text is the level */
        double lo = INFINITY, hi = -INFINITY;
        for (double y = l->box.y0; y <= l->box.y1; y += 1)
            for (double x = l->box.x0; x <= l->box.x1; x += 1) {
                double a, b;
                data_at(&L, x, y, &a, &b);
                double e = closed_form(I, a, b);
                lo = fmin(lo, e), hi = fmax(hi, e);
            }
        if (!(l->value >= lo && l->value <= hi)) {
            print_error("contour label %s at (%.0f, %.0f): E there is %.4g..%.4g\n", l->text, l->box.x0, l->box.y0, lo, hi);
            fail();
        }
    }
    assert_true(nc >= L.n_levels); /* every level labelled at least once */
    /* the luminaire mark at (2, 1.5): the middle of the area, with ink */
    assert_int_equal(L.n_marks, 1);
    lx_assert_near(L.mark[0][0], 0.5 * (L.area.x0 + L.area.x1), 0.5, 0);
    lx_assert_near(L.mark[0][1], 0.5 * (L.area.y0 + L.area.y1), 0.5, 0);
    lx__box mb = {L.mark[0][0] - 7, L.mark[0][1] - 7, L.mark[0][0] + 7, L.mark[0][1] + 7};
    assert_true(test_ink(&png, mb) > 20);
    /* the legend: a bar, round ticks, the unit in its title */
    assert_true(L.legend_bar.y1 - L.legend_bar.y0 > 100);
    assert_non_null(test_find(&L, LX__TEXT_LEGEND, "lx"));
    int nt = 0;
    for (size_t i = 0; i < L.n_label; i++)
        if (L.label[i].role == LX__TEXT_LEGEND && !isnan(L.label[i].value)) {
            nt++;
            assert_true(test_is_125(L.label[i].value) || L.label[i].value == 0 ||
                        fabs(L.label[i].value / lx__nice_step(L.scale_hi - L.scale_lo, 6) -
                             round(L.label[i].value / lx__nice_step(L.scale_hi - L.scale_lo, 6))) < 1e-9);
        }
    assert_true(nt >= 3);
    /* the title names the plane and the file's base name (not its directory) */
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "z = 0 m"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "point_source.ies"));
    assert_null(test_find(&L, LX__TEXT_TITLE, "/some/dir"));
    /* the statistics: the mean of the values to 4 significant digits, U0 to 3 decimals */
    size_t n = p->na * p->nb;
    double sum = 0, mn = INFINITY, mx = -INFINITY;
    for (size_t i = 0; i < n; i++) sum += E[i], mn = fmin(mn, E[i]), mx = fmax(mx, E[i]);
    const lx__label *s = test_find(&L, LX__TEXT_STATS, "E_avg ");
    assert_non_null(s);
    char want[64];
    lx__fmt_sig(want, sizeof want, sum / n, 4);
    assert_non_null(strstr(s->text, want));
    lx_assert_near(strtod(strchr(s->text, ' ') + 1, NULL), sum / n, 0, 5e-4);
    s = test_find(&L, LX__TEXT_STATS, "U_0 = E_min / E_avg");
    assert_non_null(s);
    snprintf(want, sizeof want, "%.3f", mn / (sum / n));
    assert_non_null(strstr(s->text, want));
    s = test_find(&L, LX__TEXT_STATS, "E_min / E_max");
    assert_non_null(s);
    snprintf(want, sizeof want, "%.3f", mn / mx);
    assert_non_null(strstr(s->text, want));
    if (white) { /* a white field: the corner of the area is white, the contours coloured */
        unsigned char c[3];
        test_px(&png, (int)L.area.x0 + 3, (int)L.area.y0 + 3, c);
        assert_true(c[0] == 255 && c[1] == 255 && c[2] == 255);
    }
    test_png_free(&png);
    lx__layout_free(&L);
}

static void isolux(void **state)
{
    lx_ctx *ctx = *state;
    lx_plane p;
    lx_assert_ok(ctx, lx_plane_axis(ctx, 'z', 0, 0, 4, 0, 3, 0.1, 0, 0, &p));
    assert_int_equal(p.na, 41), assert_int_equal(p.nb, 31);
    const double I = 1000 / (4 * M_PI); /* 1000 lm isotropic */
    double *E = malloc(p.na * p.nb * sizeof *E);
    for (size_t j = 0; j < p.nb; j++)
        for (size_t i = 0; i < p.na; i++) E[j * p.na + i] = closed_form(I, p.a0 + 0.1 * i, p.b0 + 0.1 * j);
    char path[128];
    snprintf(path, sizeof path, "%s/iso.png", dir);
    isolux_checks(ctx, path, &p, E, I, 0);
    isolux_checks(ctx, path, &p, E, I, 1);
    /* imperial: the same plot in fc and ft */
    lx_isolux_opts o = {.imperial = 1};
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__isolux_png(ctx, path, &p, E, &o, &L));
    assert_non_null(test_find(&L, LX__TEXT_AXIS, "x (ft)"));
    assert_non_null(test_find(&L, LX__TEXT_LEGEND, "fc"));
    const lx__label *s = test_find(&L, LX__TEXT_STATS, "E_max ");
    assert_non_null(s);
    double emax = closed_form(I, 2, 1.5) * 0.3048 * 0.3048; /* lx -> fc: 1 fc = 1 lm/ft2 */
    lx_assert_near(strtod(strchr(s->text, ' ') + 1, NULL), emax, 0, 5e-4);
    lx_assert_near(L.ax1, 4 / 0.3048, 1e-9, 0);
    lx__layout_free(&L);
    free(E);
}

/* ---- false colour ---- */

static void falsecolor(void **state)
{
    lx_ctx *ctx = *state;
    enum { W = 64, H = 32 };
    double v[W * H];
    for (int k = 0; k < W * H; k++) v[k] = k < W * H / 2 ? 179 : 0; /* samples/envmaps/half_lit.exr */
    char path[128];
    snprintf(path, sizeof path, "%s/fc.png", dir);
    lx_falsecolor_opts o = {.quantity = "luminance", .unit = "cd/m\u00b2", .title = "half lit"};
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__falsecolor_png(ctx, path, W, H, v, &o, &L));
    test_png png;
    test_png_read(path, &png);
    test_labels_ok(&png, &L);
    /* the 64 x 32 map enlarged by 8 to 512 x 256 */
    lx_assert_near(L.area.x1 - L.area.x0, 512, 0, 0), lx_assert_near(L.area.y1 - L.area.y0, 256, 0, 0);
    /* a flat map keeps two decades: 10 to 1000 around 179, every decade a tick */
    lx_assert_near(L.scale_lo, 10, 1e-12, 0), lx_assert_near(L.scale_hi, 1000, 1e-12, 0);
    assert_int_equal(L.scale_log, 1);
    const lx__label *t10 = test_find(&L, LX__TEXT_LEGEND, "10"), *t1000 = test_find(&L, LX__TEXT_LEGEND, "1000");
    assert_non_null(test_find(&L, LX__TEXT_LEGEND, "cd/m\u00b2"));
    assert_non_null(t1000);
    assert_non_null(t10);
    /* reading the legend as a person does: the bar's colour at the height of 179 between the
     * ticks 10 and 1000 (log) is the colour of the lit half; the dark half has the bottom colour */
    double y10 = 0.5 * (t10->box.y0 + t10->box.y1), y1000 = 0.5 * (t1000->box.y0 + t1000->box.y1);
    double y179 = y10 + (log10(179) - 1) / 2 * (y1000 - y10);
    unsigned char bar[3], lit[3], dark[3], bottom[3];
    test_px(&png, (int)(L.legend_bar.x0 + 9), (int)round(y179), bar);
    test_px(&png, (int)(L.area.x0 + 100), (int)(L.area.y0 + 60), lit);
    test_px(&png, (int)(L.area.x0 + 100), (int)(L.area.y1 - 60), dark);
    test_px(&png, (int)(L.legend_bar.x0 + 9), (int)(L.legend_bar.y1 - 3), bottom);
    for (int c = 0; c < 3; c++) {
        assert_true(abs(bar[c] - lit[c]) <= 6);
        assert_true(abs(bottom[c] - dark[c]) <= 12); /* two rows above the bar's end */
    }
    assert_true(abs(lit[0] - dark[0]) + abs(lit[1] - dark[1]) + abs(lit[2] - dark[2]) > 150);
    test_png_free(&png);
    lx__layout_free(&L);
    /* linear: round ticks from 0 to the round value above 179 */
    o.scale = LX_PLOT_SCALE_LINEAR;
    lx_assert_ok(ctx, lx__falsecolor_png(ctx, path, W, H, v, &o, &L));
    lx_assert_near(L.scale_lo, 0, 0, 0), lx_assert_near(L.scale_hi, 200, 0, 0);
    assert_non_null(test_find(&L, LX__TEXT_LEGEND, "200"));
    assert_non_null(test_find(&L, LX__TEXT_NOTE, "max 179.0 cd/m\u00b2"));
    lx__layout_free(&L);
}

/* ---- irradiance preview ---- */

static void irradiance_preview(void **state)
{
    lx_ctx *ctx = *state;
    lx_envmap *m = NULL, *e = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, 32, 16, 1, &m));
    for (int k = 0; k < 32 * 16; k++) m->data[k] = 1.0f; /* uniform radiance L = 1 W/(sr m2) */
    m->units = LX_ENV_RADIANCE, m->lum_per_unit = 179;
    lx_assert_ok(ctx, lx_irradiance_map(ctx, m, 32, 16, NULL, &e));
    char path[128];
    snprintf(path, sizeof path, "%s/irr.png", dir);
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__irradiance_png(ctx, path, m, e, "sh9", LX_PLOT_SCALE_LOG, &L));
    test_png png;
    test_png_read(path, &png);
    test_labels_ok(&png, &L);
    assert_non_null(test_find(&L, LX__TEXT_LEGEND, "illuminance (lx)"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "(sh9)"));
    /* any normal under a uniform sphere of radiance L sees E = pi L: 179 pi = 562.3 lx everywhere,
     * so the caption says so and the legend's range holds it */
    assert_non_null(test_find(&L, LX__TEXT_NOTE, "max 562.3 lx"));
    assert_true(L.scale_lo < 562.3 && L.scale_hi > 562.3);
    test_png_free(&png);
    lx__layout_free(&L);
    lx_envmap_free(e);
    lx_envmap_free(m);
}

/* ---- tone-mapped previews ---- */

static void preview(void **state)
{
    lx_ctx *ctx = *state;
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, 8, 4, 3, &m));
    for (int k = 0; k < 8 * 4 * 3; k++) m->data[k] = 0.5f; /* uniform: the median maps to 0.18 */
    char path[128];
    snprintf(path, sizeof path, "%s/pv.png", dir);
    const lx_envmap *maps[2] = {m, m};
    const char *labels[2] = {"left", "right"};
    lx_assert_ok(ctx, lx_envmap_preview_write_png(ctx, path, 2, maps, labels));
    test_png png;
    test_png_read(path, &png);
    assert_int_equal(png.w, 12 + 2 * (512 + 12));
    /* 0.18 -> Reinhard 0.18/1.18 = 0.152542 -> sRGB 1.055 x^(1/2.4) - 0.055 = 0.42695 -> 109 */
    unsigned char c[3];
    test_px(&png, 100, 12 + 22 + 100, c);
    assert_int_equal(c[0], 109), assert_int_equal(c[1], 109), assert_int_equal(c[2], 109);
    test_png_free(&png);
    lx_envmap_free(m);
}

/* ---- the error-against-time plot: crowded labels never overprint ---- */

static void error_time(void **state)
{
    lx_ctx *ctx = *state;
    enum { N = 28 };
    lx_plot_point pts[N];
    char lab[N][24];
    for (int k = 0; k < N; k++) { /* clusters of near-identical points, as the accuracy bench has */
        snprintf(lab[k], sizeof lab[k], "method %d", k);
        pts[k] = (lx_plot_point){1e-6 * (1 + 0.02 * (k % 7)), k < 4 ? 0 : 1e-4 * (1 + 0.05 * (k % 5)), lab[k], k % 3};
    }
    const char *series[3] = {"first", "second", "third"};
    char path[128];
    snprintf(path, sizeof path, "%s/et.png", dir);
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__error_time_png(ctx, path, "title", "time (s)", "error", N, pts, 3, series, &L));
    test_png png;
    test_png_read(path, &png);
    test_labels_ok(&png, &L);
    /* every point's label was placed (with the series names), and none covers a marker */
    assert_int_equal(test_count(&L, LX__TEXT_LABEL), N + 3);
    for (size_t i = 0; i < L.n_label; i++)
        for (size_t j = 0; j < L.n_keep; j++) assert_false(lx__box_overlap(L.label[i].box, L.keep[j]));
    assert_non_null(test_find(&L, LX__TEXT_LABEL, "method 0 (= 0)"));
    assert_non_null(test_find(&L, LX__TEXT_TICK, "10\u207b\u2076"));
    test_png_free(&png);
    lx__layout_free(&L);
}

/* ---- writing: atomic, and failures reported ---- */

static void write_errors(void **state)
{
    lx_ctx *ctx = *state;
    double v[4] = {1, 2, 3, 4};
    assert_int_equal(lx_falsecolor_write_png(ctx, "/nonexistent/dir/x.png", 2, 2, v, NULL), LX_EIO);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "/nonexistent/dir/x.png"));
    if (access("/dev/full", W_OK) != 0) {
        skip(); /* no /dev/full on this machine */
        return;
    }
    /* a full disk: LX_EWRITE with the system's reason; the device itself stays a device */
    assert_int_equal(lx_falsecolor_write_png(ctx, "/dev/full", 2, 2, v, NULL), LX_EWRITE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), strerror(ENOSPC)));
    /* an existing file is replaced only on success; no temporary file is left */
    char path[128], cmd[256];
    snprintf(path, sizeof path, "%s/keep.png", dir);
    FILE *f = fopen(path, "w");
    fputs("keep", f);
    fclose(f);
    assert_int_equal(lx_falsecolor_write_png(ctx, path, 0, 2, v, NULL), LX_EINVAL);
    f = fopen(path, "r");
    char buf[8] = "";
    assert_non_null(fgets(buf, sizeof buf, f));
    fclose(f);
    assert_string_equal(buf, "keep");
    snprintf(cmd, sizeof cmd, "ls '%s' | grep -q tmp", dir);
    assert_int_not_equal(system(cmd), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(round_numbers),
        cmocka_unit_test_setup_teardown(isolux, setup, teardown),
        cmocka_unit_test_setup_teardown(falsecolor, setup, teardown),
        cmocka_unit_test_setup_teardown(irradiance_preview, setup, teardown),
        cmocka_unit_test_setup_teardown(preview, setup, teardown),
        cmocka_unit_test_setup_teardown(error_time, setup, teardown),
        cmocka_unit_test_setup_teardown(write_errors, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
