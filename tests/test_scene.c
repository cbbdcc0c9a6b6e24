/* test_scene.c - scene files (format and errors), the planner's decisions, the work counters
 * (an effect that is off does none of its work; forcing one on changes the answer by the amount
 * the physics predicts), linearity, and the evaluation against closed forms. References: closed
 * forms derived in the comments, and luxcalc's own independently tested closed-form sources
 * (lx_disk_illuminance, lx_rect_illuminance: tests/test_sources.c) as oracles for the
 * near-field integration. */
#include "lx_test.h"

#include <string.h>
#include <unistd.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

/* Reads, plans and evaluates a scene given as text; returns the status of the first failure. */
typedef struct run {
    lx_scene *sc;
    lx_scene_plan *plan;
    lx_scene_result *res;
} run;

static lx_status run_text(lx_ctx *ctx, const char *text, run *r)
{
    memset(r, 0, sizeof *r);
    lx_status st = lx_scene_read_mem(ctx, "test.scene", text, strlen(text), &r->sc);
    if (st == LX_OK) st = lx_scene_plan_make(ctx, r->sc, LX_BACKEND_CPU, &r->plan);
    if (st == LX_OK) st = lx_scene_eval(ctx, r->sc, r->plan, NULL, &r->res);
    return st;
}

static void run_free(run *r)
{
    lx_scene_result_free(r->res);
    lx_scene_plan_free(r->plan);
    lx_scene_free(r->sc);
}

static run must_run(lx_ctx *ctx, const char *text)
{
    run r;
    lx_assert_ok(ctx, run_text(ctx, text, &r));
    return r;
}

/* ---- format and errors ---- */

static void expect_error(lx_ctx *ctx, const char *text, long line, const char *fragment)
{
    lx_scene *sc = NULL;
    lx_status st = lx_scene_read_mem(ctx, "bad.scene", text, strlen(text), &sc);
    if (st == LX_OK) {
        lx_scene_plan *p = NULL;
        st = lx_scene_plan_make(ctx, sc, LX_BACKEND_CPU, &p);
        lx_scene_plan_free(p);
        lx_scene_free(sc);
        sc = NULL;
    }
    if (st == LX_OK) print_error("accepted: %s\n", text);
    assert_int_not_equal(st, LX_OK);
    assert_null(sc);
    if (line >= 0 && lx_ctx_errline(ctx) != line) print_error("line %ld, expected %ld: %s\n", lx_ctx_errline(ctx), line, lx_ctx_errmsg(ctx));
    if (line >= 0) assert_int_equal(lx_ctx_errline(ctx), line);
    if (!strstr(lx_ctx_errmsg(ctx), fragment)) print_error("message '%s' lacks '%s'\n", lx_ctx_errmsg(ctx), fragment);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), fragment));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "bad.scene"));
}

#define LAMP "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nflux = 1000 lm\n"
#define DESK "[receiver r]\ntype = point\nposition = 0 m, 0 m, 0 m\n"

static void test_errors_name_file_and_line(void **state)
{
    lx_ctx *ctx = *state;
    expect_error(ctx, LAMP "colour = red\n" DESK, 5, "unknown key 'colour'");
    expect_error(ctx, "[lamp x]\n", 1, "unknown section [lamp]");
    expect_error(ctx, "[luminaire a]\ntype = point\nposition = 0, 0, 2\n", 3, "bare number '0'");
    expect_error(ctx, "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 lm\n", 3, "is a luminous flux, expected a length");
    expect_error(ctx, "[luminaire a]\ntype = point\nposition = 0 m, 2 m\n", 3, "expected 3 values");
    expect_error(ctx, "# comment\n\n[luminaire a]\ntype = point\ntype = spot\n", 5, "given twice");
    expect_error(ctx, "[luminaire a]\nposition = 0 m, 0 m, 2 m\nflux = 1 lm\n" DESK, 1, "missing 'type'");
    expect_error(ctx, LAMP "exponent = 3\n" DESK, 1, "'exponent' does not apply to type point");
    expect_error(ctx, "[luminaire a]\ntype = spot\nposition = 0 m, 0 m, 2 m\nflux = 1 lm\nbeam = 30\n", 5, "bare number '30'");
    expect_error(ctx, "type = point\n", 1, "outside a section");
    expect_error(ctx, LAMP DESK "normal = 0 m, 0 m, 1 m\n", 8, "must be a plain number");
    expect_error(ctx, LAMP, 0, "no [receiver NAME]");
    expect_error(ctx, LAMP DESK "[effects]\nnear_field = maybe\n", 9, "expected on, off or auto");
    expect_error(ctx, LAMP DESK "[effects]\nwarp = on\n", 9, "unknown effect 'warp'");
    expect_error(ctx, LAMP DESK "[effects]\nenvironment = on\n", 9, "environment forced on, but the scene has no [sky]");
    expect_error(ctx, LAMP DESK "[sky]\ntype = uniform\n", 8, "missing 'luminance'");
    /* a spectral output with spectra on some sources only cannot be summed: names the source */
    expect_error(ctx, LAMP "cct = 3000 K\n[luminaire b]\ntype = point\nposition = 1 m, 0 m, 2 m\nflux = 10 lm\n" DESK
                 "[output]\ncct = yes\n", 6, "b has no spd or cct");
    expect_error(ctx, "[receiver g]\ntype = grid\nx = 0 m, 1 m\ny = 0 m, 1 m\nz = 0 m, 1 m\nspacing = 0.5 m\n", 1,
                 "one of them a single value");
}

static void test_includes_and_cycles(void **state)
{
    lx_ctx *ctx = *state;
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_file(ctx, "tests/data/scenes/include_main.scene", &sc));
    /* the luminaire comes from sub/lamps.scene, found relative to the including file */
    assert_int_equal(sc->n_lum, 1);
    assert_string_equal(sc->lum[0].name, "bulb");
    assert_non_null(strstr(sc->lum[0].file, "sub/lamps.scene"));
    assert_int_equal(sc->lum[0].line, 2);
    lx_assert_near(sc->lum[0].intensity_cd, 100, 0, 0);
    lx_scene_free(sc);
    sc = NULL;
    assert_int_equal(lx_scene_read_file(ctx, "tests/data/scenes/cycle_a.scene", &sc), LX_EPARSE);
    assert_null(sc);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "include cycle"));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "cycle_b.scene:2"));
}

static void test_units_and_grid(void **state)
{
    lx_ctx *ctx = *state;
    /* units on every number: 1 ft = 0.3048 m exactly; the trailing unit applies to the bare ones */
    run r = must_run(ctx, "[luminaire a]\ntype = point\nposition = 1, 2, 10 ft\nintensity = 1000 cd\n"
                          "[receiver g]\ntype = grid\nx = 0 m, 2 m\ny = 0 m, 1 m\nz = 0.5 m\nspacing = 0.5 m\n");
    lx_assert_near(r.sc->lum[0].pos_m[2], 3.048, 0, 1e-15);
    lx_assert_near(r.sc->lum[0].pos_m[1], 0.6096, 0, 1e-15);
    /* 0..2 m at 0.5 m: 5 points, 0..1 m: 3 points, x fastest, normal +z */
    assert_int_equal(r.sc->rec[0].na, 5);
    assert_int_equal(r.sc->rec[0].nb, 3);
    assert_int_equal(r.res->n_points, 15);
    lx_assert_near(r.sc->rec[0].points[3 * 6 + 0], 0.5, 0, 1e-15);
    lx_assert_near(r.sc->rec[0].points[3 * 6 + 1], 0.5, 0, 1e-15);
    lx_assert_near(r.sc->rec[0].points[3 * 6 + 2], 0.5, 0, 1e-15);
    lx_assert_near(r.sc->rec[0].normal[2], 1, 0, 0);
    run_free(&r);
}

/* ---- the point law and the cheap path ---- */

static void test_point_only_scene_does_no_costly_work(void **state)
{
    lx_ctx *ctx = *state;
    lx_ctx_counters_reset(ctx);
    run r = must_run(ctx, "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 400 cd\n"
                          "[receiver up]\ntype = point\nposition = 0 m, 0 m, 0 m\n"
                          "[receiver tilted]\ntype = point\nposition = 0 m, 0 m, 0 m\nnormal = 0.8660254037844386, 0, 0.5\n"
                          "[receiver away]\ntype = point\nposition = 0 m, 0 m, 0 m\nnormal = 0, 0, -1\n");
    /* E = I cos(xi) / d^2: 400 / 4 = 100 lx; tilted 60 deg: 100 cos 60 = 50 lx; facing away: 0 */
    lx_assert_near(r.res->E_lx[0], 100, 0, 1e-15);
    lx_assert_near(r.res->E_lx[1], 50, 0, 1e-15);
    assert_true(r.res->E_lx[2] == 0);
    const int *on = r.plan->on;
    assert_true(on[LX_EFFECT_INVERSE_SQUARE] && on[LX_EFFECT_COSINE]);
    assert_false(on[LX_EFFECT_SPOT_FALLOFF] || on[LX_EFFECT_GONIOMETRIC] || on[LX_EFFECT_NEAR_FIELD] ||
                 on[LX_EFFECT_SPECTRAL] || on[LX_EFFECT_ENVIRONMENT] || on[LX_EFFECT_OPENCL]);
    assert_non_null(strstr(r.plan->reason[LX_EFFECT_SPECTRAL], "no spectral output"));
    assert_non_null(strstr(r.plan->reason[LX_EFFECT_ENVIRONMENT], "no [sky]"));
    /* none of the costly work was done: the context's counters and the result's agree */
    lx_counters c;
    lx_ctx_counters(ctx, &c);
    assert_int_equal(c.point_evaluations, 3);
    assert_int_equal(c.spot_evaluations + c.goniometric_lookups + c.nearfield_pairs + c.nearfield_subdivisions +
                         c.environment_evaluations + c.environment_samples + c.spectra_integrated + c.kernel_launches,
                     0);
    assert_memory_equal(&c, &r.res->work, sizeof c);
    assert_memory_equal(&c, &r.plan->estimate, sizeof c);
    lx_ctx_counters_reset(ctx);
    lx_ctx_counters(ctx, &c);
    assert_int_equal(c.point_evaluations, 0);
    run_free(&r);
}

static void test_cosine_forced_off(void **state)
{
    lx_ctx *ctx = *state;
    const char *base = "[luminaire a]\ntype = point\nposition = 1 m, 0 m, 2 m\nintensity = 500 cd\n"
                       "[receiver p]\ntype = point\nposition = 0 m, 0 m, 0 m\n";
    char text[1024];
    run on = must_run(ctx, base);
    snprintf(text, sizeof text, "%s[effects]\ncosine = off\n", base);
    run off = must_run(ctx, text);
    assert_false(off.plan->on[LX_EFFECT_COSINE]);
    assert_true(off.plan->forced[LX_EFFECT_COSINE]);
    /* d^2 = 5, cos(xi) = 2 / sqrt 5: with the cosine 500 * 2 / 5^1.5, without it 500 / 5 */
    lx_assert_near(on.res->E_lx[0], 1000 / pow(5, 1.5), 0, 1e-14);
    lx_assert_near(off.res->E_lx[0], 100, 0, 1e-14);
    lx_assert_near(off.res->E_lx[0] / on.res->E_lx[0], sqrt(5) / 2, 0, 1e-14);
    run_free(&on);
    run_free(&off);
}

static void test_spot_falloff(void **state)
{
    lx_ctx *ctx = *state;
    /* a spot of exponent 10 aimed straight down at 3 m, the receiver 1 m aside (a = atan(1/3)) */
    const char *spot = "[luminaire s]\ntype = spot\nposition = 0 m, 0 m, 3 m\nflux = 800 lm\nexponent = 10\n"
                       "[receiver p]\ntype = point\nposition = 1 m, 0 m, 0 m\n";
    lx_ctx_counters_reset(ctx);
    run on = must_run(ctx, spot);
    assert_true(on.plan->on[LX_EFFECT_SPOT_FALLOFF]);
    assert_int_equal(on.res->work.spot_evaluations, 1);
    /* Warn: I = (S+1) F / (2 pi) cos^S a, E = I cos a / d^2 with cos a = 3 / sqrt 10, d^2 = 10 */
    double ca = 3 / sqrt(10), peak = 11 * 800 / (2 * PI);
    lx_assert_near(on.res->E_lx[0], peak * pow(ca, 10) * ca / 10, 0, 1e-13);
    char text[1024];
    snprintf(text, sizeof text, "%s[effects]\nspot_falloff = off\n", spot);
    run off = must_run(ctx, text);
    assert_false(off.plan->on[LX_EFFECT_SPOT_FALLOFF]);
    assert_int_equal(off.res->work.spot_evaluations, 0);
    /* off: the peak in every forward direction, so the answer grows by exactly 1 / cos^S a */
    lx_assert_near(off.res->E_lx[0] / on.res->E_lx[0], 1 / pow(ca, 10), 0, 1e-13);
    run_free(&on);
    run_free(&off);
}

/* ---- near field: disks and rectangles in closed form, any receiver orientation ---- */


static void test_near_field_disk(void **state)
{
    lx_ctx *ctx = *state;
    /* a disk of radius 0.25 m facing down at 3 m; one receiver 1 m below it and 0.4 m aside, one
     * 3 m below on the axis: both in closed form (lx_disk_illuminance is the oracle: the
     * configuration factor of a parallel element, to 1e-14) */
    const char *disk = "[luminaire d]\ntype = disk\nposition = 0 m, 0 m, 3 m\nluminance = 5000 cd/m2\nradius = 0.25 m\n"
                       "[receiver near]\ntype = point\nposition = 0.4 m, 0 m, 2 m\n"
                       "[receiver far]\ntype = point\nposition = 0 m, 0 m, 0 m\n";
    lx_ctx_counters_reset(ctx);
    run r = must_run(ctx, disk);
    assert_true(r.plan->on[LX_EFFECT_NEAR_FIELD]);
    assert_int_equal(r.plan->n_near, 2);
    assert_int_equal(r.plan->near[0], 2); /* closed form */
    assert_int_equal(r.plan->near[1], 2);
    assert_int_equal(r.plan->near_why[0], LX_NEAR_CLOSED);
    assert_int_equal(r.res->work.nearfield_pairs, 2);
    assert_int_equal(r.res->work.closed_form_evaluations, 2);
    assert_int_equal(r.res->work.nearfield_subdivisions, 0);
    assert_int_equal(r.res->work.point_evaluations, 0);
    lx_source_result ex, pt;
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 5000, 0.25, 1, 0.4, LX_MODEL_EXACT, &ex));
    lx_assert_near(r.res->E_lx[0], ex.exact_lx, 0, 1e-13);
    /* on the axis: exact pi L R^2 / (h^2 + R^2) */
    lx_assert_near(r.res->E_lx[1], 5000 * PI * 0.0625 / (9 + 0.0625), 0, 1e-13);
    run_free(&r);

    /* forcing near field off: every pair becomes the point model, by exactly its error */
    char text[1024];
    snprintf(text, sizeof text, "%s[effects]\nnear_field = off\n", disk);
    lx_ctx_counters_reset(ctx);
    run off = must_run(ctx, text);
    assert_int_equal(off.plan->n_near, 0);
    assert_int_equal(off.res->work.nearfield_subdivisions, 0);
    assert_int_equal(off.res->work.closed_form_evaluations, 0);
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 5000, 0.25, 1, 0.4, LX_MODEL_POINT, &pt));
    lx_assert_near(off.res->E_lx[0], pt.point_lx, 0, 1e-13);
    lx_assert_near(off.res->E_lx[0] / ex.exact_lx - 1, pt.point_error, 1e-12, 0);
    /* far: the point model E = L pi R^2 / h^2 */
    lx_assert_near(off.res->E_lx[1], 5000 * PI * 0.0625 / 9, 0, 1e-14);
    run_free(&off);

    /* with the receiver's cosine forced off there is no closed form here: patches (2e-5) */
    snprintf(text, sizeof text, "%s[effects]\ncosine = off\n", disk);
    run nc = must_run(ctx, text);
    assert_int_equal(nc.plan->near[0], 1);
    assert_int_equal(nc.plan->near_why[0], LX_NEAR_NO_CLOSED);
    /* on the axis without the receiver's cosine: E = L x the solid angle, 2 pi L (1 - h / sqrt(h^2 + R^2)) */
    lx_assert_near(nc.res->E_lx[1], 5000 * 2 * PI * (1 - 3 / sqrt(9 + 0.0625)), 0, 5e-5);
    run_free(&nc);
}

static void test_near_field_rect_grid(void **state)
{
    lx_ctx *ctx = *state;
    /* a 0.6 x 1.2 m panel 2 m above a grid: closed form at every point (Howell B-3 superposed,
     * lx_rect_illuminance, the oracle) */
    run r = must_run(ctx, "[luminaire p]\ntype = rect\nposition = 0 m, 0 m, 2.8 m\nluminance = 3000 cd/m2\n"
                          "width = 0.6 m\nlength = 1.2 m\n"
                          "[receiver g]\ntype = grid\nx = 0 m, 1.5 m\ny = 0 m, 1 m\nz = 0.8 m\nspacing = 0.5 m\n");
    assert_int_equal(r.plan->n_near, 12);
    for (size_t g = 0; g < r.res->n_points; g++) {
        const double *q = r.sc->rec[0].points + 3 * g;
        lx_source_result ex;
        lx_assert_ok(ctx, lx_rect_illuminance(ctx, 3000, 0.6, 1.2, 2, q[0], q[1], LX_MODEL_EXACT, &ex));
        lx_assert_near(r.res->E_lx[g], ex.exact_lx, 0, 1e-12);
    }
    run_free(&r);
}

/* An adaptive Gauss-Kronrod (7-15) rule for the oracle below (written here, apart from the
 * library's, so the closed forms are checked against an independent integration). */
typedef double (*quad_fn)(void *arg, double x);
static double gk_rule(quad_fn f, void *arg, double a, double b, double *err)
{
    static const double x[8] = {0.991455371120812639, 0.949107912342758525, 0.864864423359769073, 0.741531185599394440,
                                0.586087235467691130, 0.405845151377397167, 0.207784955007898468, 0.0};
    static const double wk[8] = {0.022935322010529225, 0.063092092629978553, 0.104790010322250184, 0.140653259715525919,
                                 0.169004726639267903, 0.190350578064785410, 0.204432940075298892, 0.209482141084727828};
    static const double wg[4] = {0.129484966168869693, 0.279705391489276668, 0.381830050505118945, 0.417959183673469388};
    double c = 0.5 * (a + b), h = 0.5 * (b - a), fc = f(arg, c), k = fc * wk[7], g = fc * wg[3];
    for (int i = 0; i < 7; i++) {
        double f1 = f(arg, c - h * x[i]), f2 = f(arg, c + h * x[i]);
        k += wk[i] * (f1 + f2);
        if (i & 1) g += wg[i / 2] * (f1 + f2);
    }
    *err = fabs((k - g) * h);
    return k * h;
}
static double gk_abs(quad_fn f, void *arg, double a, double b, double tol, int depth)
{
    double err, v = gk_rule(f, arg, a, b, &err);
    if (err <= tol || depth > 30) return v;
    return gk_abs(f, arg, a, 0.5 * (a + b), 0.5 * tol, depth + 1) + gk_abs(f, arg, 0.5 * (a + b), b, 0.5 * tol, depth + 1);
}
/* to rel relative to a first estimate of the integral */
static double gk_adapt(quad_fn f, void *arg, double a, double b, double rel, int depth)
{
    double err, v = gk_rule(f, arg, a, b, &err);
    return gk_abs(f, arg, a, b, rel * fabs(v) + 1e-300, depth);
}

/* The illuminance of a Lambertian disk (radius w) or rectangle (w x l) of luminance 1 facing
 * down from height h, at q with unit normal n: E = int L cos(e) cos(r) / d^2 dA over the part of
 * the source above the receiver's horizon, nested adaptive quadrature with the horizon's line
 * cutting the inner interval exactly (the disk in x = R sin t so the rim has no square root). */
typedef struct src_q {
    int disk;
    double w, l, h, x;
    const double *q, *n;
} src_q;
static double src_inner(void *arg, double y)
{
    const src_q *S = arg;
    double d[3] = {S->x - S->q[0], y - S->q[1], S->h - S->q[2]}, r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    double ce = d[2] / sqrt(r2), cr = (d[0] * S->n[0] + d[1] * S->n[1] + d[2] * S->n[2]) / sqrt(r2);
    return ce > 0 && cr > 0 ? ce * cr / r2 : 0;
}
static double src_outer(void *arg, double t)
{
    src_q S = *(const src_q *)arg;
    double half, jac = 1;
    if (S.disk) S.x = S.w * sin(t), half = S.w * cos(t), jac = S.w * cos(t);
    else S.x = t, half = 0.5 * S.l;
    /* visible: n . (p - q) > 0 with p = (x, y, h): n1 y > c */
    double lo = -half, hi = half, c = -(S.n[0] * (S.x - S.q[0]) + S.n[2] * (S.h - S.q[2])) + S.n[1] * S.q[1];
    if (S.n[1] > 0) lo = fmax(lo, c / S.n[1]);
    else if (S.n[1] < 0) hi = fmin(hi, c / S.n[1]);
    else if (c >= 0) return 0;
    if (!(hi > lo)) return 0;
    return jac * gk_adapt(src_inner, &S, lo, hi, 1e-12, 0);
}
static double source_quadrature(int disk, double L, double w, double l, double h, const double q[3], const double n[3])
{
    src_q S = {disk, w, l, h, 0, q, n};
    double a = disk ? -PI / 2 : -w / 2, b = -a, c = a;
    if (n[1] == 0 && n[0] != 0) {
        /* the horizon's line runs along y: the outer integrand jumps where it crosses, so split there */
        double xc = q[0] - n[2] * (h - q[2]) / n[0];
        c = disk ? asin(fmax(-1.0, fmin(1.0, xc / w))) : fmax(a, fmin(b, xc));
    }
    return L * (gk_adapt(src_outer, &S, a, c, 1e-11, 0) + gk_adapt(src_outer, &S, c, b, 1e-11, 0));
}

static void test_closed_forms_tilted(void **state)
{
    lx_ctx *ctx = *state;
    /* receivers tilted every way, some of them seeing the source cut by their horizon */
    static const double nrm[5][3] = {{0, 0, 1}, {0.5, 0, 0.8660254037844386}, {1, 0, 0}, {0.3, -0.5, 0.8}, {-1, 0, 0.05}};
    static const double pos[3][3] = {{0.1, 0.05, 1.8}, {0.7, -0.2, 1.2}, {0.05, 0, 1.95}};
    double worst = 0;
    for (int kind = 0; kind < 2; kind++)
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 5; b++) {
                double nn = sqrt(nrm[b][0] * nrm[b][0] + nrm[b][1] * nrm[b][1] + nrm[b][2] * nrm[b][2]);
                double n[3] = {nrm[b][0] / nn, nrm[b][1] / nn, nrm[b][2] / nn};
                char text[1024];
                snprintf(text, sizeof text,
                         "[luminaire s]\ntype = %s\nposition = 0 m, 0 m, 2 m\nluminance = 1000 cd/m2\n%s"
                         "[receiver r]\ntype = point\nposition = %.17g m, %.17g m, %.17g m\nnormal = %.17g, %.17g, %.17g\n",
                         kind ? "disk" : "rect", kind ? "radius = 0.5 m\n" : "width = 0.6 m\nlength = 1.2 m\n", pos[a][0],
                         pos[a][1], pos[a][2], n[0], n[1], n[2]);
                run r = must_run(ctx, text);
                assert_int_equal(r.plan->near[0], 2);
                double ref = source_quadrature(kind, 1000, kind ? 0.5 : 0.6, 1.2, 2, pos[a], n);
                double rel = fabs(r.res->E_lx[0] / ref - 1);
                worst = fmax(worst, rel);
                lx_assert_near(r.res->E_lx[0], ref, 1e-9, 1e-10);
                run_free(&r);
            }
    print_message("closed forms on tilted receivers: worst %.2e against nested Gauss-Kronrod\n", worst);
}

/* ---- the sky ---- */

static void test_sky_uniform_and_overcast(void **state)
{
    lx_ctx *ctx = *state;
    const char *recs = "[receiver h]\ntype = point\nposition = 0 m, 0 m, 0 m\n"
                       "[receiver v]\ntype = point\nposition = 0 m, 0 m, 0 m\nnormal = 1, 0, 0\n"
                       "[receiver t]\ntype = point\nposition = 0 m, 0 m, 0 m\nnormal = 1, 0, 1\n";
    char text[2048];
    snprintf(text, sizeof text, "%s[sky]\ntype = uniform\nluminance = 1000 cd/m2\nground_reflectance = 0.2\n", recs);
    lx_ctx_counters_reset(ctx);
    run u = must_run(ctx, text);
    assert_true(u.plan->on[LX_EFFECT_ENVIRONMENT]);
    assert_false(u.plan->on[LX_EFFECT_INVERSE_SQUARE]);
    /* uniform sky L: horizontal pi L; a plane tilted by b sees the dome with view factor
     * (1 + cos b)/2 and the ground (luminance rho pi L / pi = rho L) with (1 - cos b)/2 */
    lx_assert_near(u.res->E_lx[0], 1000 * PI, 0, 1e-14);
    lx_assert_near(u.res->E_lx[1], 1000 * PI / 2 + 0.2 * 1000 * PI / 2, 0, 1e-14);
    lx_assert_near(u.res->E_lx[2], 1000 * PI * (1 + sqrt(0.5)) / 2 + 0.2 * 1000 * PI * (1 - sqrt(0.5)) / 2, 0, 1e-14);
    assert_int_equal(u.res->work.environment_evaluations, 3);
    assert_int_equal(u.res->work.environment_samples, 0);
    run_free(&u);

    snprintf(text, sizeof text, "%s[sky]\ntype = overcast\nluminance = 3000 cd/m2\nground_reflectance = 0.2\n", recs);
    run o = must_run(ctx, text);
    /* CIE overcast L = Lz (1 + 2 cos t)/3: horizontal 7 pi Lz / 9 (Moon & Spencer), by the closed form */
    double Eh = 7 * PI * 3000 / 9;
    lx_assert_near(o.res->E_lx[0], Eh, 0, 1e-14);
    /* tilted by b (derivation: the uniform third gives (pi/3)(1 + cos b)/2 Lz; the 2/3 cos t part
     * gives (2/3) Lz times the integral of the product of two clamped cosines at angle b,
     * (2/3)((pi - b) cos b + sin b)); ground rho Eh / 2 (1 - cos b). Vertical: Lz (pi/6 + 4/9),
     * the classical 0.396 vertical-to-horizontal ratio of the overcast sky. */
    for (int k = 1; k <= 2; k++) {
        double b = k == 1 ? PI / 2 : PI / 4;
        double sky = 3000 * (PI * (1 + cos(b)) / 6 + 4.0 / 9 * ((PI - b) * cos(b) + sin(b)));
        lx_assert_near(o.res->E_lx[k], sky + 0.2 * Eh * (1 - cos(b)) / 2, 0, 1e-10);
    }
    lx_assert_near((o.res->E_lx[1] - 0.2 * Eh / 2) / Eh, (PI / 6 + 4.0 / 9) / (7 * PI / 9), 0, 1e-12);
    assert_true(o.res->work.environment_samples > 0);
    run_free(&o);

    /* the sky forced off: the answer drops by exactly the sky's part, with no sky work */
    snprintf(text, sizeof text,
             "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 400 cd\n%s"
             "[sky]\ntype = overcast\nluminance = 3000 cd/m2\n[effects]\nenvironment = off\n",
             recs);
    lx_ctx_counters_reset(ctx);
    run off = must_run(ctx, text);
    assert_false(off.plan->on[LX_EFFECT_ENVIRONMENT]);
    lx_assert_near(off.res->E_lx[0], 100, 0, 1e-14);
    assert_int_equal(off.res->work.environment_evaluations + off.res->work.environment_samples, 0);
    run_free(&off);
}

static void test_sky_map(void **state)
{
    lx_ctx *ctx = *state;
    /* a uniform EXR map of 2000 cd/m2 (luminance units): the pixel moments are exact, so the
     * horizontal receiver gets pi L and the vertical one pi L / 2 (its horizon lies on a pixel
     * boundary) plus the ground, rho pi L / 2 */
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, 64, 32, 1, &m));
    for (int i = 0; i < 64 * 32; i++) m->data[i] = 2000;
    m->units = LX_ENV_LUMINANCE;
    m->lum_per_unit = 1;
    char path[] = "/tmp/lx_scene_skyXXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    char exr[64];
    snprintf(exr, sizeof exr, "%s.exr", path);
    unlink(path);
    lx_assert_ok(ctx, lx_envmap_write_exr(ctx, exr, m, NULL));
    lx_envmap_free(m);
    char text[1024];
    snprintf(text, sizeof text,
             "[receiver h]\ntype = point\nposition = 0 m, 0 m, 0 m\n"
             "[receiver v]\ntype = point\nposition = 0 m, 0 m, 0 m\nnormal = 1, 0, 0\n"
             "[sky]\ntype = map\nfile = %s\nground_reflectance = 0.3\n",
             exr);
    lx_ctx_counters_reset(ctx);
    run r = must_run(ctx, text);
    unlink(exr);
    lx_assert_near(r.res->E_lx[0], 2000 * PI, 0, 1e-6);
    lx_assert_near(r.res->E_lx[1], 2000 * PI / 2 + 0.3 * 2000 * PI / 2, 0, 1e-6);
    /* the map's upper half, once for the horizontal (shared with the ground term), once for v */
    assert_int_equal(r.res->work.environment_samples, 2 * 64 * 16);
    run_free(&r);
}

/* ---- photometric files ---- */

static char *write_model_ies(lx_ctx *ctx, lx_lum_model_kind kind, double flux, double w, double l)
{
    lx_lum_model md;
    memset(&md, 0, sizeof md);
    md.kind = kind;
    md.flux_lm = flux;
    md.width_m = w;
    md.length_m = l;
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_from_model(ctx, &md, &lum));
    char *text = NULL;
    size_t len = 0;
    lx_assert_ok(ctx, lx_luminaire_write_ies(ctx, lum, &text, &len));
    lx_luminaire_free(lum);
    static char path[64];
    snprintf(path, sizeof path, "/tmp/lx_scene_iesXXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, text, len), (long)len);
    close(fd);
    lx_text_free(text);
    return path;
}

static void test_goniometric(void **state)
{
    lx_ctx *ctx = *state;
    /* a Lambertian 1000 lm table (I = F/pi cos g, tabulated at 1 deg) scaled to 2000 lm, 3 m up,
     * receiver 1 m aside: cos g = 3 / sqrt 10, E = (2000/pi) cos^2 g / 10; bilinear interpolation
     * of cos g between 1-deg nodes errs by at most (1 deg)^2 / 8 = 3.8e-5 relative */
    const char *ies = write_model_ies(ctx, LX_LUM_MODEL_LAMBERT, 1000, 0, 0);
    char text[1024];
    snprintf(text, sizeof text,
             "[luminaire f]\ntype = file\nfile = %s\nposition = 0 m, 0 m, 3 m\nflux = 2000 lm\n"
             "[receiver p]\ntype = point\nposition = 1 m, 0 m, 0 m\n",
             ies);
    lx_ctx_counters_reset(ctx);
    run r = must_run(ctx, text);
    assert_true(r.plan->on[LX_EFFECT_GONIOMETRIC]);
    assert_false(r.plan->on[LX_EFFECT_NEAR_FIELD]); /* no luminous opening: a point */
    assert_int_equal(r.res->work.goniometric_lookups, 1);
    lx_assert_near(r.res->E_lx[0], 2000 / PI * 0.9 / 10, 0, 4e-5);
    lx_assert_near(r.sc->lum[0].flux_lm, 2000, 0, 1e-9);
    char text2[1200];
    snprintf(text2, sizeof text2, "%s[effects]\ngoniometric = off\n", text);
    run off = must_run(ctx, text2);
    /* off: an isotropic point of the same 2000 lm, E = 2000 / (4 pi) cos a / d^2, no table lookups */
    assert_int_equal(off.res->work.goniometric_lookups, 0);
    lx_assert_near(off.res->E_lx[0], 2000 / (4 * PI) * (3 / sqrt(10)) / 10, 0, 1e-12);
    run_free(&r);
    run_free(&off);
    unlink(ies);

    /* with a 0.6 x 0.6 m opening and the receiver 1 m below, the near-field path integrates the
     * table over the opening: a Lambertian table spread over the opening is a Lambertian
     * rectangle of luminance F / (pi A), whose exact value is the oracle */
    ies = write_model_ies(ctx, LX_LUM_MODEL_LAMBERT, 1000, 0.6, 0.6);
    snprintf(text, sizeof text,
             "[luminaire f]\ntype = file\nfile = %s\nposition = 0 m, 0 m, 1 m\n"
             "[receiver p]\ntype = point\nposition = 0.2 m, 0.1 m, 0 m\n",
             ies);
    lx_ctx_counters_reset(ctx);
    run nf = must_run(ctx, text);
    assert_true(nf.plan->on[LX_EFFECT_NEAR_FIELD]);
    assert_true(nf.res->work.goniometric_lookups == nf.res->work.nearfield_subdivisions);
    lx_source_result ex;
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000 / (PI * 0.36), 0.6, 0.6, 1, 0.2, 0.1, LX_MODEL_EXACT, &ex));
    lx_assert_near(nf.res->E_lx[0], ex.exact_lx, 0, 1e-3);
    run_free(&nf);
    unlink(ies);
}

static void test_matches_grid_engine(void **state)
{
    lx_ctx *ctx = *state;
    /* far-field IES luminaires, tilted and turned: the scene must agree with the grid engine of
     * issue 5 (lx_grid_illuminance, written independently: point model, bilinear, CPU), which
     * uses the same frame convention and tilt handling */
    const char *ies = write_model_ies(ctx, LX_LUM_MODEL_WARN, 5000, 0.2, 0.1);
    char text[2048];
    snprintf(text, sizeof text,
             "[luminaire a]\ntype = file\nfile = %s\nposition = 0 m, -1 m, 8 m\naim = 0, 0.3, -1\nrotate = 20 deg\n"
             "[luminaire b]\ntype = file\nfile = %s\nposition = 20 m, 8 m, 7 m\naim = -0.2, -0.4, -1\n"
             "[receiver road]\ntype = grid\nx = 0 m, 20 m\ny = 0 m, 7 m\nz = 0 m\npoints = 11, 8\n",
             ies, ies);
    /* first with the near-field decisions (auto): the grid engine decides the same way (the same
     * probes against the same tolerance), and both stay within that tolerance of each other */
    run ra = must_run(ctx, text);
    char text_off[2200];
    snprintf(text_off, sizeof text_off, "%s[effects]\nnear_field = off\n", text);
    run r = must_run(ctx, text_off);
    assert_false(r.plan->on[LX_EFFECT_NEAR_FIELD]);
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_read_file(ctx, ies, &lum));
    unlink(ies);
    lx_placement pl[2];
    memset(pl, 0, sizeof pl);
    for (int k = 0; k < 2; k++) {
        pl[k].lum = lum;
        memcpy(pl[k].pos_m, r.sc->lum[k].pos_m, sizeof pl[k].pos_m);
        memcpy(pl[k].aim, r.sc->lum[k].aim, sizeof pl[k].aim);
        pl[k].rotate_rad = r.sc->lum[k].rotate_rad;
    }
    lx_assert_near(pl[0].rotate_rad, 20 * DEG, 0, 1e-15);
    size_t n = r.res->n_points;
    double *E = calloc(n, sizeof *E), normal[3] = {0, 0, 1};
    lx_grid_opts o;
    memset(&o, 0, sizeof o);
    o.model = LX_MODEL_POINT;
    o.backend = LX_BACKEND_CPU;
    o.threads = 1;
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 2, r.sc->rec[0].points, n, normal, 1, &o, E));
    /* the scene scales the 5000 lm table by 1 (no flux given) */
    for (size_t g = 0; g < n; g++) lx_assert_near(r.res->E_lx[g], E[g], 1e-12, 1e-12);
    o.model = LX_MODEL_AUTO;
    o.nearfield_tol = ra.sc->nearfield_tol;
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 2, r.sc->rec[0].points, n, normal, 1, &o, E));
    for (size_t g = 0; g < n; g++) lx_assert_near(ra.res->E_lx[g], E[g], 1e-12, 2 * ra.sc->nearfield_tol);
    run_free(&ra);
    free(E);
    lx_luminaire_free(lum);
    run_free(&r);
}

static void test_opencl_blocks(void **state)
{
    lx_ctx *ctx = *state;
    /* far-field IES work on a grid: AUTO keeps it on the CPU below 1e7 evaluations; backend
     * opencl sends it to the device as one grid batch per luminaire (the grid engine's table
     * kernel). The oracle is the CPU path (bilinear): tests/test_grid.c bounds the kernel's
     * resampled-table model at 1e-3 of the peak for a coarse 30-deg table; this Warn table is
     * tabulated finely (1 deg and finer), so 1e-4 of the largest value is asked here. */
    const char *ies = write_model_ies(ctx, LX_LUM_MODEL_WARN, 12000, 0.3, 0.3);
    char text[1024];
    snprintf(text, sizeof text,
             "[luminaire a]\ntype = file\nfile = %s\nposition = 0 m, -1 m, 8 m\naim = 0, 0.2, -1\n"
             "[luminaire b]\ntype = file\nfile = %s\nposition = 30 m, -1 m, 8 m\naim = 0, 0.2, -1\n"
             "[receiver road]\ntype = grid\nx = 0 m, 30 m\ny = 0 m, 7 m\nz = 0 m\nspacing = 1 m\n"
             "[effects]\nnear_field = off\n", /* device batches take all-far grids only */
             ies, ies);
    run cpu = must_run(ctx, text);
    assert_false(cpu.plan->on[LX_EFFECT_OPENCL]);
    assert_non_null(strstr(cpu.plan->reason[LX_EFFECT_OPENCL], "backend cpu"));
    lx_scene_plan *autop = NULL;
    lx_assert_ok(ctx, lx_scene_plan_make(ctx, cpu.sc, LX_BACKEND_AUTO, &autop));
    assert_false(autop->on[LX_EFFECT_OPENCL]);
    assert_non_null(strstr(autop->reason[LX_EFFECT_OPENCL], "below the 1e+07"));
    lx_scene_plan_free(autop);
    lx_cl_device_info info;
    if (lx_cl_info(ctx, &info) != LX_OK) {
        unlink(ies);
        run_free(&cpu);
        skip();
    }
    lx_scene_plan *clp = NULL;
    lx_assert_ok(ctx, lx_scene_plan_make(ctx, cpu.sc, LX_BACKEND_OPENCL, &clp));
    assert_true(clp->on[LX_EFFECT_OPENCL]);
    lx_scene_result *res = NULL;
    lx_assert_ok(ctx, lx_scene_eval(ctx, cpu.sc, clp, NULL, &res));
    assert_int_equal(res->work.kernel_launches, 2);
    assert_int_equal(cpu.res->work.kernel_launches, 0);
    double emax = 0;
    for (size_t g = 0; g < res->n_points; g++) emax = fmax(emax, cpu.res->E_lx[g]);
    for (size_t g = 0; g < res->n_points; g++) lx_assert_near(res->E_lx[g], cpu.res->E_lx[g], 1e-4 * emax, 0);
    lx_scene_result_free(res);
    lx_scene_plan_free(clp);
    unlink(ies);
    run_free(&cpu);
}

/* ---- spectral ---- */

static void test_spectral_planner_and_values(void **state)
{
    lx_ctx *ctx = *state;
    const char *two = "[luminaire warm]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 400 cd\ncct = 3000 K\n"
                      "[luminaire day]\ntype = point\nposition = 0 m, 0 m, 4 m\nintensity = 1600 cd\ncct = 6504 K\n"
                      "[receiver eye]\ntype = point\nposition = 0 m, 0 m, 0 m\n";
    /* spectra present but no spectral output asked: no spectral work */
    lx_ctx_counters_reset(ctx);
    run r = must_run(ctx, two);
    assert_false(r.plan->on[LX_EFFECT_SPECTRAL]);
    assert_int_equal(r.res->work.spectra_integrated, 0);
    assert_true(isnan(r.res->cct_K[0]) && isnan(r.res->melanopic_edi_lx[0]));
    run_free(&r);
    /* asked, but no source has a spectrum: off, and the columns stay empty */
    run none = must_run(ctx, "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 4 cd\n"
                             "[receiver eye]\ntype = point\nposition = 0 m, 0 m, 0 m\n[output]\ncct = yes\n");
    assert_false(none.plan->on[LX_EFFECT_SPECTRAL]);
    assert_non_null(strstr(none.plan->reason[LX_EFFECT_SPECTRAL], "no source has an spd or cct"));
    assert_int_equal(none.res->work.spectra_integrated, 0);
    run_free(&none);

    /* one daylight source at 6504 K: CIE daylight at 6504 K is D65 (CIE 015:2018 defines D65 by
     * that CCT), whose melanopic DER is 1 by the definition of EDI (CIE S 026), so EDI = E */
    run d = must_run(ctx, "[luminaire day]\ntype = point\nposition = 0 m, 0 m, 4 m\nintensity = 1600 cd\ncct = 6504 K\n"
                          "[receiver eye]\ntype = point\nposition = 0 m, 0 m, 0 m\n[output]\nmelanopic_edi = yes\ncct = yes\n");
    assert_true(d.plan->on[LX_EFFECT_SPECTRAL]);
    lx_assert_near(d.res->E_lx[0], 100, 0, 1e-14);
    lx_assert_near(d.res->melanopic_edi_lx[0], 100, 0, 2e-3);
    /* and its CCT is the CCT it was made with (the D-series formula is fitted to it), within 0.1 % */
    lx_assert_near(d.res->cct_K[0], 6504, 0, 1e-3);
    run_free(&d);

    /* a Planckian source's CCT is its temperature (Duv 0) */
    run p = must_run(ctx, "[luminaire w]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 400 cd\ncct = 2700 K\n"
                          "[receiver eye]\ntype = point\nposition = 0 m, 0 m, 0 m\n[output]\ncct = yes\n");
    lx_assert_near(p.res->cct_K[0], 2700, 0.5, 0);
    lx_assert_near(p.res->duv[0], 0, 1e-5, 0);
    run_free(&p);

    /* the mixture: by linearity the scene's X, Y, Z and melanopic irradiance must equal those of
     * the summed spectral irradiance, each source scaled to its illuminance (100 lx each here);
     * the oracle sums the spectra explicitly and integrates the sum with the library's spectral
     * functions */
    char text[1200];
    snprintf(text, sizeof text, "%s[output]\ncct = yes\nmelanopic_edi = yes\n", two);
    lx_ctx_counters_reset(ctx);
    run m = must_run(ctx, text);
    assert_true(m.plan->on[LX_EFFECT_SPECTRAL]);
    assert_int_equal(m.res->work.spectra_integrated, 4); /* colorimetry + alpha-opic, per source */
    double lam[471], a[471], b[471], sum[471];
    for (int i = 0; i < 471; i++) {
        lam[i] = 360 + i;
        a[i] = lx_planck(lam[i], 3000);
    }
    lx_assert_ok(ctx, lx_daylight(ctx, 6504, 471, lam, b));
    lx_spd sa = {"a", 471, lam, a}, sb = {"b", 471, lam, b}, ss = {"sum", 471, lam, sum};
    lx_colorimetry ca, cb, cs;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &sa, LX_OBSERVER_2, LX_METHOD_AUTO, &ca));
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &sb, LX_OBSERVER_2, LX_METHOD_AUTO, &cb));
    for (int i = 0; i < 471; i++) sum[i] = a[i] * 100 / ca.Y + b[i] * 100 / cb.Y;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &ss, LX_OBSERVER_2, LX_METHOD_AUTO, &cs));
    lx_alphaopic ao;
    lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &ss, LX_METHOD_AUTO, &ao));
    lx_assert_near(m.res->E_lx[0], cs.Y, 0, 1e-12);
    lx_assert_near(m.res->cct_K[0], cs.cct_K, 0, 1e-9);
    lx_assert_near(m.res->melanopic_edi_lx[0], ao.edi[LX_AO_MEL], 0, 1e-9);
    /* and it lies between its parts */
    assert_true(m.res->cct_K[0] > 3000 && m.res->cct_K[0] < 6504);
    run_free(&m);
}

/* ---- linearity ---- */

static void test_linearity(void **state)
{
    lx_ctx *ctx = *state;
    const char *ies = write_model_ies(ctx, LX_LUM_MODEL_WARN, 1500, 0.3, 0.3);
    char text[2048];
    snprintf(text, sizeof text,
             "[luminaire a]\ntype = point\nposition = 1 m, 1 m, 2.5 m\nflux = 1200 lm\n"
             "[luminaire s]\ntype = spot\nposition = 2 m, 0 m, 2.5 m\naim = 0.2, 0, -1\nflux = 800 lm\nbeam = 40 deg\n"
             "[luminaire d]\ntype = disk\nposition = 0 m, 2 m, 2 m\nluminance = 2000 cd/m2\nradius = 0.3 m\n"
             "[luminaire r]\ntype = rect\nposition = 2 m, 2 m, 2.2 m\nluminance = 1500 cd/m2\nwidth = 0.3 m\nlength = 1.2 m\n"
             "[luminaire f]\ntype = file\nfile = %s\nposition = 0.5 m, 0.5 m, 1.2 m\n"
             "[receiver g]\ntype = grid\nx = 0 m, 2 m\ny = 0 m, 2 m\nz = 0.8 m\npoints = 5, 4\n"
             "[receiver wall]\ntype = point\nposition = 0 m, 1 m, 1.5 m\nnormal = 1, 0, 0\n"
             "[sky]\ntype = overcast\nluminance = 500 cd/m2\nground_reflectance = 0.2\n",
             ies);
    run full = must_run(ctx, text);
    unlink(ies);
    assert_true(full.plan->on[LX_EFFECT_NEAR_FIELD] && full.plan->on[LX_EFFECT_GONIOMETRIC] &&
                full.plan->on[LX_EFFECT_SPOT_FALLOFF] && full.plan->on[LX_EFFECT_ENVIRONMENT]);
    size_t np = full.res->n_points, nl = full.sc->n_lum;
    double *sum = calloc(np, sizeof *sum);
    for (size_t l = 0; l < nl; l++) {
        lx_scene_eval_opts o = {.single = 1, .index = l};
        lx_scene_result *one = NULL;
        lx_assert_ok(ctx, lx_scene_eval(ctx, full.sc, full.plan, &o, &one));
        for (size_t g = 0; g < np; g++) {
            sum[g] += one->E_lx[g];
            /* each luminaire alone gives exactly its part of the whole */
            assert_true(one->E_lx[g] == full.res->contrib_lx[g * (nl + 1) + l]);
        }
        lx_scene_result_free(one);
    }
    for (size_t g = 0; g < np; g++) {
        double sky = full.res->contrib_lx[g * (nl + 1) + nl];
        assert_true(sky > 0);
        lx_assert_near(sum[g] + sky, full.res->E_lx[g], 0, 1e-13);
    }
    free(sum);
    run_free(&full);
}

static void test_luminance_output(void **state)
{
    lx_ctx *ctx = *state;
    run r = must_run(ctx, "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 400 cd\n"
                          "[receiver desk]\ntype = point\nposition = 0 m, 0 m, 0 m\nreflectance = 0.5\n"
                          "[receiver floor]\ntype = point\nposition = 0 m, 0 m, 0 m\n[output]\nluminance = yes\n");
    /* Lambertian reflector: L = rho E / pi = 0.5 * 100 / pi; no reflectance: no luminance */
    lx_assert_near(r.res->L_cd_m2[0], 50 / PI, 0, 1e-15);
    assert_true(isnan(r.res->L_cd_m2[1]));
    run_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_errors_name_file_and_line, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_includes_and_cycles, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_units_and_grid, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_point_only_scene_does_no_costly_work, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_cosine_forced_off, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_spot_falloff, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_near_field_disk, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_near_field_rect_grid, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_sky_uniform_and_overcast, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_sky_map, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_goniometric, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_closed_forms_tilted, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_matches_grid_engine, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_opencl_blocks, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_spectral_planner_and_values, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_linearity, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_luminance_output, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests_name("scene", tests, NULL, NULL);
}
