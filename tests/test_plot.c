/* test_plot.c - every plot rendered and read back: its size, that every label lies on the page
 * with text in it and overlaps no other, and what each plot must show. Isolux: contours at 1-2-5
 * levels that pass under their labels (checked against the closed form E = I h / d^3 of an
 * isotropic source), the luminaire mark where it stands, round legend ticks, the statistics to
 * their digits. False colour: decade ticks, a two-decade range for a flat map, the map's colours as
 * the legend reads them. Irradiance: a uniform sky gives pi L everywhere. Errors: missing
 * directory (LX_EIO), full disk (LX_EWRITE), nothing left behind. Round numbers of scale.c. Plans:
 * a scene's walls, window, desk, partition and luminous area where they stand, in their colours;
 * the daylight-factor plot. */
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

/* ---- outlines on a plan ---- */

/* the pixel of data coordinates (a, b) on the layout's area */
static void px_of(const lx__layout *L, double a, double b, int *x, int *y)
{
    *x = (int)floor(L->area.x0 + (a - L->ax0) / (L->ax1 - L->ax0) * (L->area.x1 - L->area.x0));
    *y = (int)floor(L->area.y1 - (b - L->ay0) / (L->ay1 - L->ay0) * (L->area.y1 - L->area.y0));
}

/* 1 when pixel (a, b) of the plot has the colour rgb (within tol in every channel) */
static int colour_near(const test_png *png, const lx__layout *L, double a, double b, const unsigned char *rgb, int tol)
{
    int x, y;
    unsigned char c[3];
    px_of(L, a, b, &x, &y);
    test_px(png, x, y, c);
    int ok = abs(c[0] - rgb[0]) <= tol && abs(c[1] - rgb[1]) <= tol && abs(c[2] - rgb[2]) <= tol;
    if (!ok) print_error("(%g, %g) at pixel (%d, %d) is %d %d %d, not %d %d %d\n", a, b, x, y, c[0], c[1], c[2], rgb[0], rgb[1], rgb[2]);
    return ok;
}
#define colour_at(png, L, a, b, rgb) colour_near(png, L, a, b, rgb, 3)

/* a room with a window, a desk, a partition and a turned panel, a second room above it */
static const char PLAN_SCENE[] =
    "[room office]\nsize = 6, 4, 3 m\nceiling = 0.7\nwalls = 0.5\nfloor = 0.2\n"
    "[room above]\norigin = 0, 0, 3 m\nsize = 6, 4, 3 m\n"
    "[opening window]\ncorner = 1, 0, 0.9 m\nedge1 = 2, 0, 0 m\nedge2 = 0, 0, 1.5 m\n"
    "[obstruction desk]\nmin = 1, 1, 0 m\nmax = 2.6, 1.8, 0.75 m\nreflectance = 0.3\n"
    "[surface partition]\ncorner = 3.6, 0.2, 0 m\nedge1 = 0, 1.5, 0 m\nedge2 = 0, 0, 1.6 m\nreflectance = 0.4\n"
    "[luminaire panel]\ntype = rect\nposition = 3, 2, 2.8 m\nluminance = 3000 cd/m2\nwidth = 1.2 m\nlength = 0.3 m\n"
    "rotate = 90 deg\n"
    "[receiver wp]\ntype = grid\nx = 0.5 m, 5.5 m\ny = 0.5 m, 3.5 m\nz = 0.8 m\nspacing = 0.5 m\n"
    "[effects]\ninterreflection = off\n";

static const lx_plot_outline *outline_of(const lx_plot_outline *o, size_t n, lx_outline_kind kind)
{
    for (size_t k = 0; k < n; k++)
        if (o[k].kind == kind) return &o[k];
    return NULL;
}

static void outline_extent_is(const lx_plot_outline *o, double a0, double a1, double b0, double b1)
{
    double e[4];
    assert_true(lx__outlines_extent(o, 1, e));
    lx_assert_near(e[0], a0, 1e-12, 0), lx_assert_near(e[1], a1, 1e-12, 0);
    lx_assert_near(e[2], b0, 1e-12, 0), lx_assert_near(e[3], b1, 1e-12, 0);
}

static void plan_outlines(void **state)
{
    lx_ctx *ctx = *state;
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "plan.scene", PLAN_SCENE, sizeof PLAN_SCENE - 1, &sc));
    lx_plane p;
    lx_assert_ok(ctx, lx_scene_receiver_plane(ctx, sc, 0, &p));
    lx_assert_near(p.origin_m[2], 0.8, 0, 0), lx_assert_near(p.a0, 0.5, 0, 0), lx_assert_near(p.b1, 3.5, 0, 0);
    lx_plot_outline *o = NULL;
    size_t n = 0;
    lx_assert_ok(ctx, lx_scene_outlines(ctx, sc, &p, &o, &n));
    /* the office's walls (the room above is not cut by z = 0.8), the window, desk, partition, panel */
    assert_int_equal(n, 5);
    const lx_plot_outline *w = outline_of(o, n, LX_OUTLINE_WALL);
    assert_non_null(w);
    assert_string_equal(w->name, "office");
    assert_true(w->closed && w->n == 4);
    outline_extent_is(w, 0, 6, 0, 4);
    const lx_plot_outline *d = outline_of(o, n, LX_OUTLINE_OBSTRUCTION);
    assert_true(d->closed && d->n == 4);
    outline_extent_is(d, 1, 2.6, 1, 1.8);
    const lx_plot_outline *s = outline_of(o, n, LX_OUTLINE_SURFACE); /* upright: seen edge-on, a segment */
    assert_true(!s->closed && s->n == 2);
    outline_extent_is(s, 3.6, 3.6, 0.2, 1.7);
    const lx_plot_outline *win = outline_of(o, n, LX_OUTLINE_OPENING); /* in the wall y = 0: a segment */
    assert_true(!win->closed && win->n == 2);
    outline_extent_is(win, 1, 3, 0, 0);
    const lx_plot_outline *lum = outline_of(o, n, LX_OUTLINE_LUMINAIRE); /* turned 90 deg: its width along y */
    assert_true(lum->closed && lum->n == 4);
    outline_extent_is(lum, 2.85, 3.15, 1.4, 2.6);
    lx_scene_outlines_free(o);
    /* the plot of the evaluated receiver: the view takes in the room, every kind drawn in its colour */
    lx_scene_plan *plan = NULL;
    lx_scene_result *res = NULL;
    lx_assert_ok(ctx, lx_scene_plan_make(ctx, sc, LX_BACKEND_CPU, &plan));
    lx_assert_ok(ctx, lx_scene_eval(ctx, sc, plan, NULL, &res));
    char path[128];
    snprintf(path, sizeof path, "%s/plan.png", dir);
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__scene_receiver_png(ctx, path, sc, res, 0, NULL, &L));
    assert_true(L.ax0 < 0 && L.ax1 > 6 && L.ay0 < 0 && L.ay1 > 4);
    for (int k = 0; k < 5; k++) assert_int_equal(L.outlines[k], 1);
    test_png png;
    test_png_read(path, &png);
    test_labels_ok(&png, &L);
    assert_true(colour_at(&png, &L, 0, 2, lx__outline_rgb(LX_OUTLINE_WALL)));      /* the west wall */
    assert_true(colour_at(&png, &L, 5, 4, lx__outline_rgb(LX_OUTLINE_WALL)));      /* the north wall */
    assert_true(colour_at(&png, &L, 2, 0, lx__outline_rgb(LX_OUTLINE_OPENING)));   /* the window, over the wall */
    assert_true(colour_at(&png, &L, 4.5, 0, lx__outline_rgb(LX_OUTLINE_WALL)));    /* the wall beside it */
    assert_true(colour_at(&png, &L, 3.6, 1.0, lx__outline_rgb(LX_OUTLINE_SURFACE))); /* the partition */
    assert_true(colour_near(&png, &L, 1, 1.4, lx__outline_rgb(LX_OUTLINE_OBSTRUCTION), 16)); /* the desk's fine edge */
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "Illuminance on wp (z = 0.8 m)"));
    test_png_free(&png);
    lx__layout_free(&L);
    /* without outlines: the view is the receiver's area */
    lx_receiver_png_opts po = {.no_outlines = 1};
    lx_assert_ok(ctx, lx__scene_receiver_png(ctx, path, sc, res, 0, &po, &L));
    for (int k = 0; k < 5; k++) assert_int_equal(L.outlines[k], 0);
    lx_assert_near(L.ax0, 0.5, 1e-12, 0);
    lx__layout_free(&L);
    /* no daylight: no daylight factor to plot, said so */
    po = (lx_receiver_png_opts){.quantity = LX_PLOT_DAYLIGHT_FACTOR};
    assert_int_equal(lx_scene_receiver_write_png(ctx, path, sc, res, 0, &po), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "daylight factor is not defined"));
    po = (lx_receiver_png_opts){.quantity = 7};
    assert_int_equal(lx_scene_receiver_write_png(ctx, path, sc, res, 0, &po), LX_EINVAL);
    assert_int_equal(lx_scene_receiver_write_png(ctx, path, sc, res, 1, NULL), LX_EINVAL);
    lx_scene_result_free(res);
    lx_scene_plan_free(plan);
    lx_scene_free(sc);
}

/* The daylight-factor plot: % in the legend and statistics, contours at the 1-2-5 % series, values
 * never converted to imperial units. */
static void daylight_factor_plot(void **state)
{
    lx_ctx *ctx = *state;
    lx_plane p;
    lx_assert_ok(ctx, lx_plane_axis(ctx, 'z', 0.85, 0, 4, 0, 3, 0.25, 0, 0, &p));
    double *v = malloc(p.na * p.nb * sizeof *v);
    for (size_t j = 0; j < p.nb; j++) /* a side-lit room: 12 % at the window, falling away from it */
        for (size_t i = 0; i < p.na; i++) v[j * p.na + i] = 12 * exp(-1.2 * (p.b0 + 0.25 * j)) + 0.2;
    char path[128];
    snprintf(path, sizeof path, "%s/df.png", dir);
    lx_isolux_opts o = {.quantity = LX_PLOT_DAYLIGHT_FACTOR, .imperial = 1};
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__isolux_png(ctx, path, &p, v, &o, &L));
    assert_non_null(test_find(&L, LX__TEXT_LEGEND, "DF (%)"));
    assert_non_null(test_find(&L, LX__TEXT_TITLE, "Daylight factor on"));
    const lx__label *s = test_find(&L, LX__TEXT_STATS, "DF_max ");
    assert_non_null(s);
    lx_assert_near(strtod(strchr(s->text, ' ') + 1, NULL), 12.2, 0, 5e-4); /* % stays %, with imperial */
    assert_non_null(strstr(s->text, "%"));
    assert_int_equal(L.n_levels, 4); /* 1, 2, 5, 10 % */
    static const double want[4] = {1, 2, 5, 10};
    for (int k = 0; k < 4; k++) assert_true(L.level[k] == want[k] && L.level_segments[k] > 0);
    test_png png;
    test_png_read(path, &png);
    test_labels_ok(&png, &L);
    test_png_free(&png);
    lx__layout_free(&L);
    o.quantity = 2;
    assert_int_equal(lx_grid_write_png(ctx, path, &p, v, &o), LX_EINVAL);
    o.quantity = 0, o.n_outlines = 1;
    assert_int_equal(lx_grid_write_png(ctx, path, &p, v, &o), LX_EINVAL); /* a count without outlines */
    free(v);
}

/* ---- false colour ---- */

/* A sky with the sun: 128 x 64, the sky 2000-8000 cd/m2 above the horizon, the ground 0, the sun
 * two pixels of 2e8. The range is the sky's (up to 10000, two decades at least), the sun above it in the top
 * colour, said in a note; the sky's darkest and brightest pixels then differ by most of the
 * palette. With the range given, everything is in it and nothing is said. */
static void falsecolor_sun(void **state)
{
    lx_ctx *ctx = *state;
    enum { W = 128, H = 64 };
    static double v[W * H];
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) v[j * W + i] = j < H / 2 ? 2000 + 6000 * (double)i / (W - 1) : 0;
    v[10 * W + 100] = v[10 * W + 101] = 2e8;
    char path[128];
    snprintf(path, sizeof path, "%s/sun.png", dir);
    lx_falsecolor_opts o = {.quantity = "luminance", .unit = "cd/m\u00b2", .title = "sky"};
    lx__layout L = {0};
    lx_assert_ok(ctx, lx__falsecolor_png(ctx, path, W, H, v, &o, &L));
    lx_assert_near(L.scale_hi, 1e4, 1e-9, 0);
    lx_assert_near(L.scale_lo, 1e2, 1e-9, 0);
    assert_int_equal(L.above, 2);
    const lx__label *n = test_find(&L, LX__TEXT_NOTE, "range without a small bright source");
    assert_non_null(n);
    assert_non_null(strstr(n->text, "2 pixels"));
    test_png png;
    test_png_read(path, &png);
    test_labels_ok(&png, &L);
    unsigned char lo[3], hi[3], top[3];
    test_px(&png, (int)L.area.x0 + 2, (int)L.area.y0 + 40, lo);  /* 2000 cd/m2: 65 % up the palette */
    test_px(&png, (int)L.area.x1 - 3, (int)L.area.y0 + 40, hi);  /* 8000 cd/m2: 95 % up */
    test_px(&png, (int)(L.area.x0 + 100.5 * (L.area.x1 - L.area.x0) / W), (int)(L.area.y0 + 10.5 * (L.area.y1 - L.area.y0) / H), top);
    unsigned char want_lo[3], want_hi[3], want_top[3];
    lx__falsecolor(log10(2000 / 100.0) / 2, want_lo), lx__falsecolor(log10(8000 / 100.0) / 2, want_hi), lx__falsecolor(1, want_top);
    for (int c = 0; c < 3; c++)
        assert_true(abs(lo[c] - want_lo[c]) <= 8 && abs(hi[c] - want_hi[c]) <= 8 && top[c] == want_top[c]);
    assert_true(abs(lo[0] - hi[0]) + abs(lo[1] - hi[1]) + abs(lo[2] - hi[2]) > 200); /* the sky shows its range */
    test_png_free(&png);
    lx__layout_free(&L);
    o.lo = 1, o.hi = 1e9; /* given: all of it, nothing left out */
    lx_assert_ok(ctx, lx__falsecolor_png(ctx, path, W, H, v, &o, &L));
    assert_int_equal(L.above, 0);
    assert_null(test_find(&L, LX__TEXT_NOTE, "range without"));
    lx__layout_free(&L);
}

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
        cmocka_unit_test_setup_teardown(plan_outlines, setup, teardown),
        cmocka_unit_test_setup_teardown(daylight_factor_plot, setup, teardown),
        cmocka_unit_test_setup_teardown(falsecolor, setup, teardown),
        cmocka_unit_test_setup_teardown(falsecolor_sun, setup, teardown),
        cmocka_unit_test_setup_teardown(irradiance_preview, setup, teardown),
        cmocka_unit_test_setup_teardown(preview, setup, teardown),
        cmocka_unit_test_setup_teardown(error_time, setup, teardown),
        cmocka_unit_test_setup_teardown(write_errors, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
