/* test_design.c - the deliverable: maintained values (maintained = new x MF wherever light is
 * computed: points, near-field integration, occlusion, interreflection), the CIE 97:2005 product
 * LLMF x LSF x LMF x RSMF from typed tables (interpolated by hand in the comments), and the
 * scene-file errors of the deliverable's keys (file and line). */
#include "lx_test.h"

#include <string.h>
#include <unistd.h>

/* Reads, plans (mode) and evaluates a scene given as text. */
typedef struct run {
    lx_scene *sc;
    lx_scene_plan *plan;
    lx_scene_result *res;
} run;

static lx_status run_mode(lx_ctx *ctx, const char *name, const char *text, lx_scene_mode mode, run *r)
{
    memset(r, 0, sizeof *r);
    lx_status st = lx_scene_read_mem(ctx, name, text, strlen(text), &r->sc);
    if (st == LX_OK) st = lx_scene_plan_make_mode(ctx, r->sc, LX_BACKEND_CPU, mode, &r->plan);
    if (st == LX_OK) st = lx_scene_eval(ctx, r->sc, r->plan, NULL, &r->res);
    return st;
}

static run must_run(lx_ctx *ctx, const char *name, const char *text, lx_scene_mode mode)
{
    run r;
    lx_assert_ok(ctx, run_mode(ctx, name, text, mode, &r));
    return r;
}

static void run_free(run *r)
{
    lx_scene_result_free(r->res);
    lx_scene_plan_free(r->plan);
    lx_scene_free(r->sc);
}

static void expect_error(lx_ctx *ctx, const char *text, long line, const char *fragment)
{
    lx_scene *sc = NULL;
    lx_status st = lx_scene_read_mem(ctx, "bad.scene", text, strlen(text), &sc);
    lx_scene_free(sc);
    if (st == LX_OK) print_error("accepted: %s\n", text);
    assert_int_not_equal(st, LX_OK);
    if (line >= 0 && lx_ctx_errline(ctx) != line)
        print_error("line %ld, expected %ld: %s\n", lx_ctx_errline(ctx), line, lx_ctx_errmsg(ctx));
    if (line >= 0) assert_int_equal(lx_ctx_errline(ctx), line);
    if (!strstr(lx_ctx_errmsg(ctx), fragment)) print_error("message '%s' lacks '%s'\n", lx_ctx_errmsg(ctx), fragment);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), fragment));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "bad.scene"));
}

/* ---- maintained = new x MF ---- */

/* A small room lit by the office's IES downlights (near-field integration at the desk), a point and
 * a disk, with an obstruction (occlusion) and interreflection at a coarse fixed patch size: every
 * path a luminaire's light takes. */
#define ROOM_SCENE(MF)                                                                                                 \
    "[scene]\ninterreflection_tolerance = 1e-2\npatch_size = 0.75 m\n" MF                                              \
    "[room r]\nsize = 3 m, 2.5 m, 2.5 m\n"                                                                             \
    "[obstruction box]\nmin = 1.2 m, 1.0 m, 0 m\nmax = 1.6 m, 1.4 m, 0.5 m\nreflectance = 0.3\n"                       \
    "[luminaire dl]\ntype = file\nfile = ../ies/downlight_lambert_1000lm.ies\nposition = 1 m, 1 m, 2.45 m\n"          \
    "[luminaire p]\ntype = point\nposition = 2.2 m, 1.5 m, 2.2 m\nflux = 800 lm\n"                                    \
    "[luminaire d]\ntype = disk\nposition = 2 m, 0.8 m, 2.4 m\nradius = 0.15 m\nflux = 600 lm\n"                       \
    "[receiver plane]\ntype = grid\nx = 0.25 m, 2.75 m\ny = 0.25 m, 2.25 m\nz = 0.8 m\nspacing = 0.5 m\n"            \
    "[receiver near]\ntype = point\nposition = 1.05 m, 1 m, 2.2 m\n"                                                   \
    "[receiver wall]\ntype = point\nposition = 2.99 m, 1.2 m, 1.2 m\nnormal = -1, 0, 0\n"                            \
    "[receiver eye]\ntype = point\nposition = 1.6 m, 1.8 m, 1.2 m\ncylindrical = yes\nsemicylindrical = 1, 0, 0\n"

static void test_maintained_is_new_times_mf(void **state)
{
    lx_ctx *ctx = *state;
    const char *name = "samples/scenes/mf_test.scene"; /* the IES path is relative to samples/scenes */
    run a = must_run(ctx, name, ROOM_SCENE(""), LX_SCENE_NORMAL);
    run b = must_run(ctx, name, ROOM_SCENE("maintenance_factor = 0.8\n"), LX_SCENE_NORMAL);
    assert_true(a.plan->on[LX_EFFECT_INTERREFLECTION] && a.plan->on[LX_EFFECT_OCCLUSION] && a.plan->n_near > 0);
    assert_int_equal(a.sc->design->maintained, 0);
    assert_int_equal(b.sc->design->maintained, 1);
    assert_int_equal(a.res->n_points, b.res->n_points);
    double worst = 0;
    for (size_t g = 0; g < a.res->n_points; g++) {
        assert_true(a.res->E_lx[g] > 0);
        lx_assert_near(b.res->E_lx[g], 0.8 * a.res->E_lx[g], 0, 1e-12);
        lx_assert_near(b.res->indirect_lx[g], 0.8 * a.res->indirect_lx[g], 0, 1e-12);
        for (size_t l = 0; l < a.sc->n_lum; l++)
            lx_assert_near(b.res->contrib_lx[g * 4 + l], 0.8 * a.res->contrib_lx[g * 4 + l], 1e-300, 1e-12);
        worst = fmax(worst, fabs(b.res->E_lx[g] / (0.8 * a.res->E_lx[g]) - 1));
        if (!isnan(a.res->cylindrical_lx[g])) { /* cylinders: direct and interreflected */
            lx_assert_near(b.res->cylindrical_lx[g], 0.8 * a.res->cylindrical_lx[g], 0, 1e-12);
            lx_assert_near(b.res->semicylindrical_lx[g], 0.8 * a.res->semicylindrical_lx[g], 0, 1e-12);
            lx_assert_near(b.res->modelling[g], a.res->modelling[g], 0, 1e-12);
        }
    }
    for (size_t s = 0; s < a.res->n_surfaces; s++) {
        if (isnan(a.res->surfaces[s].E_lx)) { /* no exposed area (the box's bottom on the floor) */
            assert_true(isnan(b.res->surfaces[s].E_lx));
            continue;
        }
        lx_assert_near(b.res->surfaces[s].E_lx, 0.8 * a.res->surfaces[s].E_lx, 0, 1e-12);
    }
    print_message("maintained / (0.8 x new) - 1: at most %.2g over %zu points\n", worst, a.res->n_points);
    run_free(&a);
    run_free(&b);
}

/* A luminaire's own factor scales its own part only (linearity). */
static void test_per_luminaire_factor(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 400 cd\nmaintenance_factor = 0.9\n"
                    "[luminaire b]\ntype = point\nposition = 1 m, 0 m, 2 m\nintensity = 400 cd\n"
                    "[receiver r]\ntype = point\nposition = 0 m, 0 m, 0 m\n";
    run r = must_run(ctx, "t.scene", t, LX_SCENE_NORMAL);
    /* a: 400 / 2^2 = 100 lx x 0.9; b: 400 cos / d^2 with d^2 = 5, cos = 2 / sqrt 5, MF 1 */
    lx_assert_near(r.res->contrib_lx[0], 90, 0, 1e-14);
    lx_assert_near(r.res->contrib_lx[1], 400 * 2 / sqrt(5.0) / 5, 0, 1e-14);
    assert_int_equal(r.sc->design->maintained, 1);
    lx_assert_near(r.sc->design->lum_mf[1], 1, 0, 0);
    run_free(&r);
}

/* ---- emergency operation (EN 1838): the emergency luminaires alone at their emergency flux, direct
 * light only ---- */
static void test_emergency_mode(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[scene]\nmaintenance_factor = 0.9\n[room r]\nsize = 4 m, 3 m, 3 m\n"
                    "[luminaire main]\ntype = point\nposition = 1 m, 1.5 m, 2.9 m\nflux = 4000 lm\n"
                    "[luminaire em]\ntype = point\nposition = 3 m, 1.5 m, 2.9 m\nflux = 1000 lm\n"
                    "emergency = non-maintained\nemergency_flux = 200 lm\n"
                    "[luminaire both]\ntype = point\nposition = 2 m, 1 m, 2.9 m\nflux = 1000 lm\nemergency = maintained\n"
                    "emergency_flux = 100 lm\n"
                    "[receiver floor]\ntype = point\nposition = 3 m, 1.5 m, 0 m\n";
    run n = must_run(ctx, "t.scene", t, LX_SCENE_NORMAL);
    run e = must_run(ctx, "t.scene", t, LX_SCENE_EMERGENCY);
    /* normal operation: the non-maintained luminaire is dark */
    lx_assert_near(n.plan->lum_scale[0], 0.9, 0, 0);
    lx_assert_near(n.plan->lum_scale[1], 0, 0, 0);
    lx_assert_near(n.plan->lum_scale[2], 0.9, 0, 0);
    assert_true(n.plan->on[LX_EFFECT_INTERREFLECTION]);
    assert_true(n.res->contrib_lx[1] == 0);
    /* emergency: main dark; em at 200 lm x MF, 2.9 m straight above: I / d^2 = 200 / (4 pi) / 2.9^2 x 0.9 */
    assert_int_equal(e.plan->mode, LX_SCENE_EMERGENCY);
    assert_false(e.plan->on[LX_EFFECT_INTERREFLECTION]);
    assert_non_null(strstr(e.plan->reason[LX_EFFECT_INTERREFLECTION], "EN 1838"));
    assert_null(e.res->indirect_lx);
    lx_assert_near(e.res->contrib_lx[0], 0, 0, 0);
    lx_assert_near(e.res->contrib_lx[1], 0.9 * 200 / (4 * M_PI) / (2.9 * 2.9), 0, 1e-14);
    /* both: 100 lm at (2, 1, 2.9): d^2 = 1 + 0.25 + 8.41, cos = 2.9 / d */
    double d2 = 1 + 0.25 + 2.9 * 2.9;
    lx_assert_near(e.res->contrib_lx[2], 0.9 * 100 / (4 * M_PI) * (2.9 / sqrt(d2)) / d2, 0, 1e-14);
    run_free(&n);
    run_free(&e);
    /* a scene without an emergency luminaire has no emergency operation */
    lx_scene *sc = NULL;
    lx_scene_plan *p = NULL;
    const char *plain = "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nflux = 1000 lm\n"
                        "[receiver r]\ntype = point\nposition = 0 m, 0 m, 0 m\n";
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "plain.scene", plain, strlen(plain), &sc));
    assert_int_equal(lx_scene_plan_make_mode(ctx, sc, LX_BACKEND_CPU, LX_SCENE_EMERGENCY, &p), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "no luminaire has 'emergency"));
    assert_null(p);
    lx_scene_free(sc);
}

/* ---- cylindrical and semi-cylindrical illuminance ----
 * A point source of intensity I at distance d, at angle theta from the vertical: a beam of E_n = I / d^2
 * lights the element of a small vertical cylinder whose horizontal normal is at azimuth psi with
 * E_n sin(theta) max(0, cos(psi - phi)); the mean over the curved surface is E_z = E_n sin(theta) / pi,
 * over the half facing f: E_sz = E_n sin(theta) (1 + cos phi_f) / pi (phi_f: the source's azimuth seen
 * from f). sin(theta) = h / d, h the horizontal distance. */
static void test_cylindrical_point_source(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 3 m\nflux = 1000 lm\n"
                    "[luminaire s]\ntype = spot\nposition = 2.5 m, 1 m, 2.6 m\naim = -0.3, -0.2, -1\nflux = 500 lm\nexponent = 4\n"
                    "[receiver towards]\ntype = point\nposition = 2 m, 0 m, 1.2 m\ncylindrical = yes\nsemicylindrical = -1, 0, 0\n"
                    "[receiver away]\ntype = point\nposition = 2 m, 0 m, 1.2 m\nsemicylindrical = 1, 0, 0\n"
                    "[receiver side]\ntype = point\nposition = 2 m, 0 m, 1.2 m\nsemicylindrical = 0, 1, 0\n"
                    "[receiver below]\ntype = point\nposition = 0 m, 0 m, 0 m\ncylindrical = yes\n";
    run r = must_run(ctx, "t.scene", t, LX_SCENE_NORMAL);
    double I = 1000 / (4 * M_PI), h = 2, d = sqrt(4 + 1.8 * 1.8);
    /* the spot: I(a) = (S + 1) F / (2 pi) cos^S a, a the angle from its axis */
    double ax[3] = {-0.3, -0.2, -1}, na = sqrt(0.09 + 0.04 + 1), v[3] = {2 - 2.5, 0 - 1, 1.2 - 2.6};
    double ds = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), hs = hypot(v[0], v[1]);
    double ca = (v[0] * ax[0] + v[1] * ax[1] + v[2] * ax[2]) / (ds * na), Is = 5 * 500 / (2 * M_PI) * pow(ca, 4);
    double ez = I * h / (M_PI * d * d * d) + Is * hs / (M_PI * ds * ds * ds);
    lx_assert_near(r.res->cylindrical_lx[0], ez, 0, 1e-12);
    /* semi-cylinders at the same point: facing the point source (cos phi = 1), away (-1: 0), sideways
     * (0); the spot's azimuth seen from each facing: -v_h . f / h */
    double cf[3] = {-(v[0] * -1) / hs, -(v[0] * 1) / hs, -(v[1] * 1) / hs};
    double ppart[3] = {2, 0, 1};
    for (int k = 0; k < 3; k++) {
        double e = ppart[k] * I * h / (M_PI * d * d * d) + Is * hs * (1 + cf[k]) / (M_PI * ds * ds * ds);
        lx_assert_near(r.res->semicylindrical_lx[k], e, 1e-300, 1e-12);
    }
    assert_true(isnan(r.res->cylindrical_lx[1])); /* not asked */
    /* modelling: E_z / E_h on a receiver facing up */
    lx_assert_near(r.res->modelling[0], r.res->cylindrical_lx[0] / r.res->E_lx[0], 0, 1e-15);
    /* straight below the point source: only the spot's light is on the cylinder */
    double w[3] = {0 - 2.5, 0 - 1, 0 - 2.6}, dw = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]), hw = hypot(w[0], w[1]);
    double cw = (w[0] * ax[0] + w[1] * ax[1] + w[2] * ax[2]) / (dw * na);
    lx_assert_near(r.res->cylindrical_lx[3], 5 * 500 / (2 * M_PI) * pow(cw, 4) * hw / (M_PI * dw * dw * dw), 0, 1e-12);
    run_free(&r);
}

/* A Lambertian disk (luminous area): the kernel integrated over the disk, against an independent
 * polar quadrature (Gauss-Legendre in the radius, the periodic trapezoid rule in the angle) of
 * L cos(emission) h / (pi d^3) dA. */
static double gl_x[16], gl_w[16];
static void gauss16(void)
{
    /* nodes and weights of 16-point Gauss-Legendre on [-1, 1] by Newton on P16 */
    for (int i = 0; i < 16; i++) {
        double x = cos(M_PI * (i + 0.75) / 16.5), dp = 0;
        for (int it = 0; it < 100; it++) {
            double p0 = 1, p1 = x;
            for (int k = 2; k <= 16; k++) {
                double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1, p1 = p2;
            }
            dp = 16 * (x * p1 - p0) / (x * x - 1);
            double dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16) break;
        }
        gl_x[i] = x;
        gl_w[i] = 2 / ((1 - x * x) * dp * dp);
    }
}

static double disk_ez(double L, double R, const double c[3], const double q[3], const double *f)
{
    gauss16();
    double sum = 0;
    for (int seg = 0; seg < 8; seg++) /* the radius in 8 pieces of 16 Gauss nodes */
        for (int i = 0; i < 16; i++) {
            double r = R * (seg + 0.5 + 0.5 * gl_x[i]) / 8, wr = R / 16 * gl_w[i];
            for (int j = 0; j < 512; j++) {
                double a = 2 * M_PI * (j + 0.5) / 512, s[3] = {c[0] + r * cos(a), c[1] + r * sin(a), c[2]};
                double v[3] = {q[0] - s[0], q[1] - s[1], q[2] - s[2]}, d = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                double h = hypot(v[0], v[1]), ce = -v[2] / d; /* emission cosine (disk faces down) */
                double g = f ? h - (v[0] * f[0] + v[1] * f[1]) : h;
                if (ce > 0 && g > 0) sum += L * ce * g / (M_PI * d * d * d) * r * wr * (2 * M_PI / 512);
            }
        }
    return sum;
}

static void test_cylindrical_area_source(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[luminaire d]\ntype = disk\nposition = 1 m, 1 m, 2 m\nradius = 0.3 m\nluminance = 5000 cd/m2\n"
                    "[receiver near]\ntype = point\nposition = 1.4 m, 1.1 m, 1.5 m\ncylindrical = yes\nsemicylindrical = -1, 0, 0\n"
                    "[receiver far]\ntype = point\nposition = 4 m, 3 m, 1.2 m\ncylindrical = yes\n";
    run r = must_run(ctx, "t.scene", t, LX_SCENE_NORMAL);
    double c[3] = {1, 1, 2}, q1[3] = {1.4, 1.1, 1.5}, q2[3] = {4, 3, 1.2}, f[3] = {-1, 0, 0};
    double ez1 = disk_ez(5000, 0.3, c, q1, NULL), esz1 = disk_ez(5000, 0.3, c, q1, f), ez2 = disk_ez(5000, 0.3, c, q2, NULL);
    print_message("disk: E_z %.9g (ref %.9g), E_sz %.9g (ref %.9g), far %.9g (ref %.9g)\n", r.res->cylindrical_lx[0], ez1,
                  r.res->semicylindrical_lx[0], esz1, r.res->cylindrical_lx[1], ez2);
    lx_assert_near(r.res->cylindrical_lx[0], ez1, 0, 2e-5);
    lx_assert_near(r.res->semicylindrical_lx[0], esz1, 0, 2e-5);
    lx_assert_near(r.res->cylindrical_lx[1], ez2, 0, 2e-5);
    run_free(&r);
}

/* The interreflected part: the mean over azimuth of the vertical illuminance (E_z), and over the half
 * turn about the facing direction (E_sz); the same room's gather on 64 vertical point receivers at the
 * same point (the trapezoid rule over 64 azimuths; Simpson's over the 33 of the half turn) is the
 * reference of the quadrature. */
static void test_cylindrical_interreflection(void **state)
{
    lx_ctx *ctx = *state;
    char *t = malloc(20000);
    size_t n = (size_t)snprintf(t, 20000,
                                "[scene]\ninterreflection_tolerance = 1e-3\npatch_size = 0.5 m\n"
                                "[room r]\nsize = 3 m, 2.5 m, 2.5 m\n"
                                "[luminaire a]\ntype = point\nposition = 0.8 m, 0.7 m, 2.3 m\nflux = 3000 lm\n"
                                "[receiver c]\ntype = point\nposition = 1.7 m, 1.4 m, 1.2 m\ncylindrical = yes\n"
                                "semicylindrical = 0, 1, 0\n");
    for (int k = 0; k < 64; k++)
        n += (size_t)snprintf(t + n, 20000 - n, "[receiver v%d]\ntype = point\nposition = 1.7 m, 1.4 m, 1.2 m\nnormal = %.17g, %.17g, 0\n",
                              k, cos(2 * M_PI * k / 64), sin(2 * M_PI * k / 64));
    run r = must_run(ctx, "t.scene", t, LX_SCENE_NORMAL);
    double mean = 0, simpson = 0;
    for (int k = 0; k < 64; k++) mean += r.res->indirect_lx[1 + k] / 64;
    for (int k = 0; k <= 32; k++) /* psi from 0 to pi (facing +y: pi/2 +- pi/2) */
        simpson += (k == 0 || k == 32 ? 1 : k % 2 ? 4 : 2) * r.res->indirect_lx[1 + k];
    simpson *= (M_PI / 32) / 3 / M_PI;
    /* the direct parts in closed form */
    double I = 3000 / (4 * M_PI), v[3] = {1.7 - 0.8, 1.4 - 0.7, 1.2 - 2.3}, d = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double h = hypot(v[0], v[1]), ez_dir = I * h / (M_PI * d * d * d), esz_dir = I * (h - v[1]) / (M_PI * d * d * d);
    print_message("indirect E_z %.6g (64 azimuths: %.6g), E_sz %.6g (Simpson: %.6g)\n", r.res->cylindrical_lx[0] - ez_dir,
                  mean, r.res->semicylindrical_lx[0] - esz_dir, simpson);
    assert_true(mean > 0.1 * ez_dir);
    lx_assert_near(r.res->cylindrical_lx[0], ez_dir + mean, 0, 1e-3);
    lx_assert_near(r.res->semicylindrical_lx[0], esz_dir + simpson, 0, 1e-3);
    lx_assert_near(r.res->modelling[0], r.res->cylindrical_lx[0] / r.res->E_lx[0], 0, 1e-15);
    run_free(&r);
    free(t);
}

/* ---- EN 12464-1 calculation grids ----
 * The rule: p = 0.2 x 5^log10(d) (d the longer side, or the shorter where the longer is at least twice
 * it), n = d / p rounded, points at the cells' centres. References: (1) the 2021 rule (rounded to the
 * nearest whole number) as F. Rudawski's egrid implements it (frudawski.de/egrid): a 5 m x 4 m area
 * gives 8 x 6 points; (2) the examples of typical grid sizes quoted from EN 12464-1 (fagerhult.com,
 * "Number of calculation points"): square areas of side 1, 2, 5, 10, 100 m give 5, 6, 8, 10, 20 points
 * a side (the rows for 0.4, 0.6, 25 and 50 m list 3, 3, 12, 17 points, which follow from p rounded to
 * 0.15, 0.2, 2 and 3 m rather than from the formula, which gives 4, 4, 13, 16: those rows are not
 * asserted); (3) p itself: 0.2 m at d = 1 m, 1 m at 10 m, 5 m at 100 m, capped at 10 m. */
static void test_grid_rule(void **state)
{
    lx_ctx *ctx = *state;
    lx_en12464_grid g;
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 5, 4, LX_GRID_ROUND_NEAREST, &g));
    assert_int_equal(g.n[0], 8);
    assert_int_equal(g.n[1], 6);
    lx_assert_near(g.d_m, 5, 0, 0);
    lx_assert_near(g.p_m, 0.2 * pow(5, log10(5.0)), 0, 1e-15);
    lx_assert_near(g.cell_m[0], 0.625, 0, 1e-15);
    lx_assert_near(g.cell_m[1], 4.0 / 6, 0, 1e-15);
    static const double side[] = {1, 2, 5, 10, 100};
    static const size_t n_table[] = {5, 6, 8, 10, 20};
    for (int k = 0; k < 5; k++) {
        lx_assert_ok(ctx, lx_en12464_grid_size(ctx, side[k], side[k], LX_GRID_ROUND_NEAREST, &g));
        assert_int_equal(g.n[0], n_table[k]);
        assert_int_equal(g.n[1], n_table[k]);
    }
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 1, 1, LX_GRID_ROUND_NEAREST, &g));
    lx_assert_near(g.p_m, 0.2, 0, 1e-15);
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 10, 10, LX_GRID_ROUND_NEAREST, &g));
    lx_assert_near(g.p_m, 1, 0, 1e-15);
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 100, 100, LX_GRID_ROUND_NEAREST, &g));
    lx_assert_near(g.p_m, 5, 0, 1e-14);
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 2000, 2000, LX_GRID_ROUND_NEAREST, &g));
    lx_assert_near(g.p_m, 10, 0, 0); /* 0.2 x 5^3.3 = 40 m, capped */
    /* the ratio rule: 20 m x 2 m takes d = 2 m: p = 0.2 x 5^log10(2) = 0.3249, n = round(6.16) = 6 across,
     * cells of 1/3 m, 60 along */
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 20, 2, LX_GRID_ROUND_NEAREST, &g));
    lx_assert_near(g.d_m, 2, 0, 0);
    assert_int_equal(g.n[1], 6);
    assert_int_equal(g.n[0], 60);
    /* EN 12464-1:2011 rounds up: 5 m x 4 m: 5 / 0.6170 = 8.10 -> 9; 4 / (5/9) = 7.2 -> 8 */
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 5, 4, LX_GRID_ROUND_UP, &g));
    assert_int_equal(g.n[0], 9);
    assert_int_equal(g.n[1], 8);
    /* d / p exactly whole is not rounded up past it: 1 m / 0.2 m = 5 */
    lx_assert_ok(ctx, lx_en12464_grid_size(ctx, 1, 1, LX_GRID_ROUND_UP, &g));
    assert_int_equal(g.n[0], 5);
    assert_int_equal(lx_en12464_grid_size(ctx, 0, 1, LX_GRID_ROUND_NEAREST, &g), LX_EINVAL);
}

/* A task area 0.2 m from a wall: its surrounding (0.5 m) and background (3 m) bands clipped there.
 * By hand: room [0, 6] x [0, 4]; task [0.2, 1.8] x [1, 2] at 0.75 m.
 * Surrounding: [-0.3, 2.3] x [0.5, 2.5] clipped to x >= 0: 2.3 x 2 = 4.6 m2 less the task's 1.6: 3.0 m2.
 * Its cells: d = 0.5 m (a band's shorter side): p = 0.2 x 5^log10(0.5) = 0.1232, 0.5 / p = 4.06 -> 4
 * cells of 0.125 m across; the strips below and above (2.6 m long: 21 cells, 4 rows) lose the 2
 * columns with x < 0 (centres -0.238, -0.114): 19 x 4 each; the left strip (0.5 m: 4 columns of 8)
 * keeps 2 (centres 0.0125, 0.1375): 16; the right one 32: 76 + 76 + 16 + 32 = 200 points.
 * Background: [-3.3, 5.3] x [-2.5, 5.5] clipped to the room: [0, 5.3] x [0, 4] = 21.2 m2, less the
 * surrounding's outer edge clipped ([0, 2.3] x [0.5, 2.5] = 4.6 m2): 16.6 m2. */
static void test_task_bands(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[room r]\nsize = 6 m, 4 m, 3 m\n"
                    "[luminaire a]\ntype = point\nposition = 3 m, 2 m, 2.8 m\nflux = 3000 lm\n"
                    "[area desk]\ntype = task\nx = 0.2 m, 1.8 m\ny = 1 m, 2 m\nz = 0.75 m\n"
                    "[effects]\ninterreflection = off\n";
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "t.scene", t, strlen(t), &sc));
    const lx_scene_design *d = sc->design;
    assert_int_equal(d->n_area, 3);
    const lx_scene_area *task = &d->area[0], *sur = &d->area[1], *bg = &d->area[2];
    assert_int_equal(task->kind, LX_AREA_TASK);
    assert_int_equal(sur->kind, LX_AREA_SURROUNDING);
    assert_int_equal(bg->kind, LX_AREA_BACKGROUND);
    assert_string_equal(sc->rec[sur->rec].name, "desk.surrounding");
    assert_int_equal(sur->task, 0);
    lx_assert_near(task->area_m2, 1.6, 0, 1e-14);
    lx_assert_near(sur->area_m2, 3.0, 0, 1e-12);
    lx_assert_near(bg->area_m2, 16.6, 0, 1e-12);
    /* the clipped outline of the surrounding: x from the wall at 0 to 2.3, y 0.5 to 2.5 */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t k = 0; k < sur->n_outline; k++)
        for (int c = 0; c < 2; c++) lo[c] = fmin(lo[c], sur->outline[2 * k + c]), hi[c] = fmax(hi[c], sur->outline[2 * k + c]);
    lx_assert_near(lo[0], 0, 1e-15, 0);
    lx_assert_near(hi[0], 2.3, 0, 1e-15);
    lx_assert_near(lo[1], 0.5, 0, 1e-15);
    lx_assert_near(hi[1], 2.5, 0, 1e-15);
    lx_assert_near(sur->grid.cell_m[0], 0.125, 0, 1e-15);
    const lx_scene_receiver *rs = &sc->rec[sur->rec];
    assert_int_equal(rs->kind, LX_SREC_SET);
    assert_int_equal(rs->n, 200);
    for (size_t i = 0; i < rs->n; i++) {
        const double *q = rs->points + 3 * i;
        int in_task = q[0] >= 0.2 && q[0] <= 1.8 && q[1] >= 1 && q[1] <= 2;
        int in_band = q[0] >= 0 && q[0] <= 2.3 && q[1] >= 0.5 && q[1] <= 2.5;
        assert_true(in_band && !in_task);
        lx_assert_near(q[2], 0.75, 0, 0);
    }
    /* the task area: 1.6 x 1 m: d = 1.6 m, p = 0.2 x 5^log10(1.6) = 0.2781, n = round(5.75) = 6 cells of
     * 0.2667 m, across round(3.75) = 4: 24 points at the cells' centres */
    const lx_scene_receiver *rt = &sc->rec[task->rec];
    assert_int_equal(rt->kind, LX_SREC_GRID);
    assert_int_equal(rt->na, 6);
    assert_int_equal(rt->nb, 4);
    lx_assert_near(rt->points[0], 0.2 + 1.6 / 12, 0, 1e-15);
    lx_assert_near(rt->points[1], 1 + 1.0 / 8, 0, 1e-15);
    const lx_scene_receiver *rb = &sc->rec[bg->rec];
    for (size_t i = 0; i < rb->n; i++) {
        const double *q = rb->points + 3 * i;
        assert_true(q[0] >= 0 && q[0] <= 5.3 && q[1] >= 0 && q[1] <= 4);
        assert_false(q[0] <= 2.3 && q[1] >= 0.5 && q[1] <= 2.5);
    }
    lx_scene_free(sc);
}

/* A room's work plane less its 0.5 m margin, its walls and its ceiling. By hand: room 6 x 4 x 2.8 m;
 * the plane 5 x 3 m: d = 5, p = 0.617, 8 x 5 cells (0.625 x 0.6 m); a 4 m x 2.8 m wall: d = 4,
 * p = 0.527, 8 x 6 (cells 0.5 x 0.467 m); a 6 m x 2.8 m wall, more than twice as long as high: d = 2.8,
 * p = 0.411, 7 cells of 0.4 m up and 15 along; the ceiling 6 x 4: d = 6, p = 0.700, 9 x 6. An obstruction takes the plane's points inside it. */
static void test_room_areas(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[room r]\nsize = 6 m, 4 m, 2.8 m\n"
                    "[obstruction cabinet]\nmin = 5 m, 2.9 m, 0 m\nmax = 6 m, 4 m, 2 m\nreflectance = 0.3\n"
                    "[luminaire a]\ntype = point\nposition = 3 m, 2 m, 2.7 m\nflux = 3000 lm\n"
                    "[area plane]\ntype = room\nz = 0.8 m\n"
                    "[area w]\ntype = walls\n"
                    "[area c]\ntype = ceiling\n";
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "t.scene", t, strlen(t), &sc));
    const lx_scene_design *d = sc->design;
    assert_int_equal(d->n_area, 6);
    const lx_scene_receiver *plane = &sc->rec[d->area[0].rec];
    assert_int_equal(d->area[0].grid.n[0], 8);
    assert_int_equal(d->area[0].grid.n[1], 5);
    /* cells of the last column (x 5.1875) in the top row (y 3.2) lie in the cabinet: 1 point lost */
    assert_int_equal(plane->n, 39);
    assert_int_equal(plane->kind, LX_SREC_SET);
    lx_assert_near(plane->points[0], 0.5 + 0.3125, 0, 1e-15);
    lx_assert_near(plane->points[1], 0.5 + 0.3, 0, 1e-15);
    static const size_t na[4] = {8, 8, 15, 15}, nb[4] = {6, 6, 7, 7};
    /* the cabinet stands against x = 6 m and y = 4 m: the wall points it covers are left out (x max:
     * the 2 columns at y 3.25, 3.75 x the 4 rows up to z 1.63 m: 8; y max: the 3 columns at x 5.0, 5.4,
     * 5.8 x the 5 rows up to 1.8 m: 15) */
    static const size_t n_pts[4] = {48, 40, 105, 90};
    static const char *const names[4] = {"w.wall_xmin", "w.wall_xmax", "w.wall_ymin", "w.wall_ymax"};
    for (int k = 0; k < 4; k++) {
        const lx_scene_area *A = &d->area[1 + k];
        const lx_scene_receiver *rc = &sc->rec[A->rec];
        assert_string_equal(rc->name, names[k]);
        assert_int_equal(A->kind, LX_AREA_WALL);
        assert_int_equal(rc->na, na[k]);
        assert_int_equal(rc->nb, nb[k]);
        assert_int_equal(rc->n, n_pts[k]);
        assert_int_equal(rc->kind, n_pts[k] == na[k] * nb[k] ? LX_SREC_GRID : LX_SREC_SET);
        /* on the wall, facing into the room */
        int ax = k / 2;
        lx_assert_near(rc->points[ax], k % 2 ? (ax ? 4 : 6) : 0, 0, 0);
        lx_assert_near(rc->normal[ax], k % 2 ? -1 : 1, 0, 0);
    }
    const lx_scene_receiver *ce = &sc->rec[d->area[5].rec];
    assert_int_equal(ce->na, 9);
    assert_int_equal(ce->nb, 6);
    lx_assert_near(ce->points[2], 2.8, 0, 0);
    lx_assert_near(ce->normal[2], -1, 0, 0);
    lx_scene_free(sc);
}

static void test_area_errors(void **state)
{
    lx_ctx *ctx = *state;
    const char *room = "[room r]\nsize = 4 m, 3 m, 3 m\n[luminaire a]\ntype = point\nposition = 2 m, 1 m, 2.5 m\nflux = 1 lm\n";
    char t[2048];
    snprintf(t, sizeof t, "%s[area desk]\ntype = task\nx = 3 m, 4.5 m\ny = 1 m, 2 m\nz = 0.75 m\n", room);
    expect_error(ctx, t, 7, "the task area (x 3 to 4.5 m, y 1 to 2 m, z 0.75 m) reaches outside room 'r'");
    snprintf(t, sizeof t, "%s[area desk]\ntype = task\nx = 5 m, 6 m\ny = 1 m, 2 m\nz = 0.75 m\n", room);
    expect_error(ctx, t, 7, "area 'desk': outside every room");
    snprintf(t, sizeof t, "%s[area desk]\ntype = task\nx = 1 m, 2 m\ny = 1 m, 2 m\n", room);
    expect_error(ctx, t, 7, "a task area takes x and y ranges and its height z");
    snprintf(t, sizeof t, "%s[area p]\ntype = room\nz = 0.8 m\nmargin = 2 m\n", room);
    expect_error(ctx, t, 10, "the margin of 2 m leaves nothing");
    snprintf(t, sizeof t, "%s[area p]\ntype = hall\n", room);
    expect_error(ctx, t, 8, "type: expected task, room, walls, ceiling, escape_route, open_area or high_risk");
    snprintf(t, sizeof t, "%s[area p]\nz = 0.8 m\n", room);
    expect_error(ctx, t, 7, "missing 'type'");
    snprintf(t, sizeof t, "%s[area p]\ntype = room\nz = 0.8 m\nsurrounding = 0.5 m\n", room);
    expect_error(ctx, t, 10, "bands belong to task areas");
    snprintf(t, sizeof t, "%s[receiver desk]\ntype = point\nposition = 1 m, 1 m, 1 m\n[area desk]\ntype = task\nx = 1 m, 2 m\n"
                          "y = 1 m, 2 m\nz = 0.75 m\n", room);
    expect_error(ctx, t, 10, "a receiver named 'desk' exists already");
    expect_error(ctx, "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nflux = 1 lm\n[area w]\ntype = walls\n", 5,
                 "a walls area needs a [room]");
}

/* ---- requirements and the check ----
 * One isotropic point of 4000 lm (I = 4000 / 4 pi cd) 2 m above a task area: the check's values are the
 * area's statistics (mean, U0 = min / mean) and pass exactly where the typed value is met. */
static void test_check(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[scene]\nmaintenance_factor = 0.8\n[room r]\nsize = 4 m, 4 m, 3 m\n"
                    "[luminaire a]\ntype = point\nposition = 2 m, 2 m, 2.75 m\nflux = 4000 lm\n"
                    "[area desk]\ntype = task\nx = 1.5 m, 2.5 m\ny = 1.5 m, 2.5 m\nz = 0.75 m\nbackground = no\n"
                    "[area w]\ntype = walls\n"
                    "[requirement office]\narea = desk\nreference = typed for the test\n"
                    "maintained_illuminance = 50 lx\nuniformity = 0.99\nminimum_illuminance = 10 lx\n"
                    "surrounding_illuminance = 20 lx\nwall_uniformity = 0.1\n"
                    "[effects]\ninterreflection = off\n";
    run r = must_run(ctx, "t.scene", t, LX_SCENE_NORMAL);
    lx_scene_checks *c = NULL;
    lx_assert_ok(ctx, lx_scene_check(ctx, r.sc, r.res, NULL, NULL, &c));
    /* maintained_illuminance, uniformity, minimum, surrounding, 4 walls' uniformity */
    assert_int_equal(c->n, 8);
    lx_area_stats st;
    lx_assert_ok(ctx, lx_scene_area_stats(ctx, r.sc, r.res, r.sc->design->area[0].rec, &st));
    /* the task's points by hand: 1 m x 1 m, d = 1 m, p = 0.2 m, 5 x 5 cells; E = 0.8 I h / d^3 */
    double I = 4000 / (4 * M_PI), sum = 0, mn = INFINITY;
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 5; i++) {
            double x = 1.5 + 0.2 * (i + 0.5) - 2, y = 1.5 + 0.2 * (j + 0.5) - 2, d2 = x * x + y * y + 4;
            double e = 0.8 * I * 2 / (d2 * sqrt(d2));
            sum += e, mn = fmin(mn, e);
        }
    lx_assert_near(st.mean_lx, sum / 25, 0, 1e-12);
    lx_assert_near(st.min_lx, mn, 0, 1e-12);
    const lx_check *k = &c->check[0];
    assert_string_equal(k->quantity, "E_m");
    assert_string_equal(k->target, "desk");
    assert_string_equal(k->reference, "typed for the test");
    assert_int_equal(k->line, 20);
    lx_assert_near(k->value, sum / 25, 0, 1e-12);
    assert_true(k->pass); /* 60.08 lx against 50 */
    assert_string_equal(c->check[1].quantity, "U_0");
    lx_assert_near(c->check[1].value, mn / (sum / 25), 0, 1e-12);
    assert_false(c->check[1].pass); /* 0.99 is not met */
    assert_string_equal(c->check[2].quantity, "E_min");
    lx_assert_near(c->check[2].value, mn, 0, 1e-12);
    assert_string_equal(c->check[3].target, "desk.surrounding");
    assert_string_equal(c->check[4].target, "w.wall_xmin");
    assert_int_equal(c->n_fail, 1);
    assert_false(c->all_pass);
    lx_scene_checks_free(c);
    run_free(&r);
}

/* A requirement for a quantity that is not computed: an error naming the key's line. */
static void test_requirement_errors(void **state)
{
    lx_ctx *ctx = *state;
    const char *base = "[room r]\nsize = 4 m, 4 m, 3 m\n[luminaire a]\ntype = point\nposition = 2 m, 2 m, 2.5 m\nflux = 4000 lm\n"
                       "[area desk]\ntype = task\nx = 1.5 m, 2.5 m\ny = 1.5 m, 2.5 m\nz = 0.75 m\n"
                       "[requirement q]\narea = desk\n"; /* the section at line 12, its keys from 14 */
    char t[2048];
    snprintf(t, sizeof t, "%scylindrical_illuminance = 150 lx\n", base);
    expect_error(ctx, t, 14, "cylindrical_illuminance is not computed: its area computes no cylindrical illuminance");
    snprintf(t, sizeof t, "%smaintained_illuminance = 500 lx\nwall_illuminance = 75 lx\n", base);
    expect_error(ctx, t, 15, "wall_illuminance is not computed: no [area] of type walls in its room");
    snprintf(t, sizeof t, "%sugr_limit = 19\n", base);
    expect_error(ctx, t, 14, "ugr_limit is not computed: no [observer] in its room");
    snprintf(t, sizeof t, "%sra = 80\n", base);
    expect_error(ctx, t, 14, "ra is not computed: luminaire 'a' has no spectrum");
    snprintf(t, sizeof t, "%semergency_minimum = 1 lx\n", base);
    expect_error(ctx, t, 14, "emergency_minimum is not computed: no luminaire has 'emergency");
    snprintf(t, sizeof t, "%smodelling = 0.3, 0.6\n", base);
    expect_error(ctx, t, 14, "modelling is not computed");
    snprintf(t, sizeof t, "%suniformity = 1.5\n", base);
    expect_error(ctx, t, 14, "uniformity: a ratio of at most 1");
    snprintf(t, sizeof t, "%smodelling = 0.6, 0.3\n", base);
    expect_error(ctx, t, 14, "from low to high");
    snprintf(t, sizeof t, "%smaintained_illuminance = 500\n", base);
    expect_error(ctx, t, 14, "bare number '500'");
    snprintf(t, sizeof t, "%scolour = red\n", base);
    expect_error(ctx, t, 14, "unknown key 'colour' in [requirement]");
    snprintf(t, sizeof t, "%s", base);
    expect_error(ctx, t, 12, "no quantity required");
    expect_error(ctx, "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nflux = 1 lm\n[receiver r]\ntype = point\n"
                      "position = 0 m, 0 m, 0 m\n[requirement q]\narea = nowhere\nuniformity = 0.5\n",
                 9, "area: no area or receiver named 'nowhere'");
}

/* ---- EN 1838 emergency lighting ----
 * A corridor 10 m x 2 m x 3 m with reflecting walls and two non-maintained emergency luminaires,
 * isotropic points of 120 lm emergency flux (I = 120 / 4 pi cd) 2.8 m above the floor at x = 2.5 and
 * 7.5 m on the centre line. EN 1838 counts direct light only: on the centre line E(x) =
 * sum I h / d^3, h = 2.8 m, d^2 = (x - x_l)^2 + h^2. The route's cells: its width 2 m gives p = 0.325 m,
 * 6 cells of 1/3 m across, so 27 points along its 9 m at x = 0.5 + (k + 0.5) / 3 m; its central band
 * (1 m: p = 0.2 m, 5 cells of 0.2 m) 45 x 5 points. */
static void test_emergency_corridor(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[room corridor]\nsize = 10 m, 2 m, 3 m\nwalls = 0.7\nfloor = 0.5\n"
                    "[luminaire main]\ntype = point\nposition = 5 m, 1 m, 2.8 m\nflux = 2000 lm\n"
                    "[luminaire e1]\ntype = point\nposition = 2.5 m, 1 m, 2.8 m\nflux = 800 lm\n"
                    "emergency = non-maintained\nemergency_flux = 120 lm\n"
                    "[luminaire e2]\ntype = point\nposition = 7.5 m, 1 m, 2.8 m\nflux = 800 lm\n"
                    "emergency = non-maintained\nemergency_flux = 120 lm\n"
                    "[area route]\ntype = escape_route\nfrom = 0.5 m, 1 m, 0 m\nto = 9.5 m, 1 m, 0 m\nwidth = 2 m\n"
                    "[requirement en1838]\narea = route\nemergency_minimum = 1 lx\nemergency_ratio = 40\n"
                    "emergency_band_minimum = 0.5 lx\n"
                    "[scene]\ninterreflection_tolerance = 1e-2\npatch_size = 1 m\n";
    run n = must_run(ctx, "corridor.scene", t, LX_SCENE_NORMAL);
    run e = must_run(ctx, "corridor.scene", t, LX_SCENE_EMERGENCY);
    assert_true(n.plan->on[LX_EFFECT_INTERREFLECTION]);   /* normal operation reflects */
    assert_false(e.plan->on[LX_EFFECT_INTERREFLECTION]);  /* emergency: direct light only, and says why */
    assert_non_null(strstr(e.plan->reason[LX_EFFECT_INTERREFLECTION], "EN 1838"));
    const lx_scene_design *d = e.sc->design;
    assert_int_equal(d->n_area, 2);
    assert_int_equal(d->area[0].kind, LX_AREA_ESCAPE_ROUTE);
    assert_int_equal(d->area[1].kind, LX_AREA_ROUTE_BAND);
    const lx_scene_receiver *line = &e.sc->rec[d->area[0].rec], *band = &e.sc->rec[d->area[1].rec];
    assert_int_equal(line->n, 27);
    assert_int_equal(band->n, 225);
    double I = 120 / (4 * M_PI), h = 2.8, mn = INFINITY, mx = 0;
    for (size_t k = 0; k < 27; k++) {
        double x = 0.5 + (k + 0.5) / 3, E = 0;
        lx_assert_near(line->points[3 * k], x, 0, 1e-14);
        lx_assert_near(line->points[3 * k + 1], 1, 0, 0);
        for (int l = 0; l < 2; l++) {
            double dx = x - (l ? 7.5 : 2.5), d2 = dx * dx + h * h;
            E += I * h / (d2 * sqrt(d2));
        }
        lx_assert_near(e.res->E_lx[e.res->first[d->area[0].rec] + k], E, 0, 1e-12);
        mn = fmin(mn, E), mx = fmax(mx, E);
    }
    lx_scene_checks *c = NULL;
    lx_assert_ok(ctx, lx_scene_check(ctx, e.sc, n.res, e.res, NULL, &c));
    assert_int_equal(c->n, 3);
    assert_true(c->check[0].emergency);
    lx_assert_near(c->check[0].value, mn, 0, 1e-12);
    assert_int_equal(c->check[0].pass, mn >= 1);
    lx_assert_near(c->check[1].value, mx / mn, 0, 1e-12);
    assert_true(c->check[1].pass);
    assert_string_equal(c->check[2].target, "route.central_band");
    print_message("EN 1838 corridor: centre line E_min %.4g lx, E_max %.4g lx, ratio %.3g (closed form); band min %.4g lx\n",
                  mn, mx, mx / mn, c->check[2].value);
    lx_scene_checks_free(c);
    /* without the emergency results the check refuses */
    assert_int_equal(lx_scene_check(ctx, e.sc, n.res, NULL, NULL, &c), LX_EINVAL);
    run_free(&n);
    run_free(&e);
}

/* ---- UGR per observer position and direction (CIE 117) ----
 * An [observer] with a grid of eye positions and a list of directions becomes one observer per pair;
 * each rates as the single observer at its position looking that way (the same CIE 117 terms), and a
 * requirement's ugr_limit rates the section by its highest UGR. */
static void test_observer_positions_directions(void **state)
{
    lx_ctx *ctx = *state;
    const char *lums = "[luminaire p1]\ntype = rect\nposition = 2 m, 2 m, 2.8 m\nwidth = 0.6 m\nlength = 0.6 m\nflux = 3000 lm\n"
                       "[luminaire p2]\ntype = rect\nposition = 4 m, 2.5 m, 2.8 m\nwidth = 0.6 m\nlength = 0.6 m\nflux = 3000 lm\n"
                       "[area desk]\ntype = task\nx = 0.5 m, 1.5 m\ny = 1 m, 2 m\nz = 0.75 m\nsurrounding = no\nbackground = no\n";
    char t[4096];
    snprintf(t, sizeof t,
             "%s[observer seat]\nx = 0.5 m, 1.5 m\ny = 1 m, 2 m\nz = 1.2 m\nspacing = 1 m\ndirections = 0 deg, 90 deg\n"
             "background_luminance = 40 cd/m2\n[requirement glare]\narea = desk\nugr_limit = 16\nobservers = seat\n",
             lums);
    run r = must_run(ctx, "t.scene", t, LX_SCENE_NORMAL);
    assert_int_equal(r.sc->n_obs, 8);
    const lx_scene_design *d = r.sc->design;
    assert_int_equal(d->n_obs_group, 1);
    assert_string_equal(d->obs_group_name[0], "seat");
    assert_string_equal(r.sc->obs[3].name, "seat.4"); /* position 2 (1.5, 1), direction 2 (90 deg) */
    lx_assert_near(r.sc->obs[3].pos_m[0], 1.5, 0, 0);
    lx_assert_near(r.sc->obs[3].view[1], 1, 0, 1e-15);
    lx_scene_glare *g = NULL;
    lx_assert_ok(ctx, lx_scene_glare_eval(ctx, r.sc, &g));
    double worst = -INFINITY;
    for (size_t o = 0; o < 8; o++) worst = fmax(worst, g->ugr[o]);
    /* each equals the single observer at its position and direction */
    for (size_t o = 0; o < 8; o++) {
        const lx_scene_observer *ob = &r.sc->obs[o];
        snprintf(t, sizeof t, "%s[observer one]\nposition = %.17g m, %.17g m, %.17g m\nview = %.17g, %.17g, %.17g\n"
                              "background_luminance = 40 cd/m2\n",
                 lums, ob->pos_m[0], ob->pos_m[1], ob->pos_m[2], ob->view[0], ob->view[1], ob->view[2]);
        lx_scene *one = NULL;
        lx_scene_glare *g1 = NULL;
        lx_assert_ok(ctx, lx_scene_read_mem(ctx, "one.scene", t, strlen(t), &one));
        lx_assert_ok(ctx, lx_scene_glare_eval(ctx, one, &g1));
        lx_assert_near(g->ugr[o], g1->ugr[0], 0, 1e-14);
        lx_scene_glare_free(g1);
        lx_scene_free(one);
    }
    lx_scene_checks *c = NULL;
    lx_assert_ok(ctx, lx_scene_check(ctx, r.sc, r.res, NULL, g, &c));
    assert_int_equal(c->n, 1);
    assert_string_equal(c->check[0].target, "seat");
    lx_assert_near(c->check[0].value, worst, 0, 0);
    assert_int_equal(c->check[0].pass, worst <= 16);
    print_message("UGR over 4 positions x 2 directions: highest %.2f\n", worst);
    lx_scene_checks_free(c);
    lx_scene_glare_free(g);
    run_free(&r);
    snprintf(t, sizeof t, "%s[observer s]\nposition = 1 m, 1 m, 1.2 m\nx = 0 m, 1 m\ny = 0 m, 1 m\nz = 1.2 m\nspacing = 1 m\n"
                          "view = 1, 0, 0\n", lums);
    expect_error(ctx, t, 20, "give 'position' or a grid of positions");
    snprintf(t, sizeof t, "%s[observer s]\nposition = 1 m, 1 m, 1.2 m\nview = 1, 0, 0\ndirections = 0 deg\n", lums);
    expect_error(ctx, t, 20, "give 'view' or directions of view");
    snprintf(t, sizeof t, "%s[observer s]\nx = 0 m, 1 m\nz = 1.2 m\nspacing = 1 m\nview = 1, 0, 0\n", lums);
    expect_error(ctx, t, 20, "a grid of eye positions takes x and y ranges");
}

/* EN 1838 open areas (the floor less a 0.5 m border: a 6 x 4 m room leaves 5 x 3 m, 8 x 5 points at
 * z = 0) and high-risk task areas (a task area without bands). */
static void test_emergency_areas(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "[room r]\nsize = 6 m, 4 m, 3 m\n[luminaire a]\ntype = point\nposition = 3 m, 2 m, 2.8 m\nflux = 1 lm\n"
                    "emergency = maintained\n"
                    "[area hall]\ntype = open_area\n"
                    "[area saw]\ntype = high_risk\nx = 1 m, 2 m\ny = 1 m, 2 m\nz = 0.9 m\n";
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "t.scene", t, strlen(t), &sc));
    const lx_scene_design *d = sc->design;
    assert_int_equal(d->n_area, 2);
    assert_int_equal(d->area[0].kind, LX_AREA_OPEN);
    const lx_scene_receiver *hall = &sc->rec[d->area[0].rec];
    assert_int_equal(hall->na, 8);
    assert_int_equal(hall->nb, 5);
    assert_int_equal(hall->n, 40);
    lx_assert_near(hall->points[0], 0.5 + 5.0 / 16, 0, 1e-15);
    lx_assert_near(hall->points[2], 0, 0, 0);
    assert_int_equal(d->area[1].kind, LX_AREA_HIGH_RISK);
    assert_string_equal(sc->rec[d->area[1].rec].name, "saw");
    lx_scene_free(sc);
}

/* ---- EN 15193-1 LENI ----
 * By hand (the standard's method, simplified daylight dependency): a 6 m x 4 m office (A = 24 m2), four
 * 35 W luminaires (P_n = 140 W) at MF 0.8 under constant illuminance control: F_C = (1 + 0.8) / 2 = 0.9;
 * t_D = 2250 h, t_N = 250 h, F_O = 0.9; F_D = 1 - F_DS F_DC = 1 - 0.6 x 0.75 = 0.55;
 * W_L = 140 x 0.9 x 0.9 x (2250 x 0.55 + 250) / 1000 = 113.4 x 1487.5 / 1000 = 168.6825 kWh;
 * W_P = (5 W x (8760 - 2500) h + 2 W x 8760 h) / 1000 = (31300 + 17520) / 1000 = 48.82 kWh;
 * LENI = (168.6825 + 48.82) / 24 = 217.5025 / 24 = 9.06260416667 kWh/(m2 a). */
static void test_leni(void **state)
{
    lx_ctx *ctx = *state;
    lx_leni_input in = {.area_m2 = 24, .power_W = 140, .daylight_h = 2250, .night_h = 250, .constant_factor = 0.9,
                        .occupancy_factor = 0.9, .daylight_factor = 0.55, .parasitic_W = 5, .emergency_W = 2,
                        .emergency_h = 8760};
    lx_leni e;
    lx_assert_ok(ctx, lx_leni_compute(ctx, &in, &e));
    lx_assert_near(e.lighting_kWh, 168.6825, 0, 1e-14);
    lx_assert_near(e.parasitic_kWh, 48.82, 0, 1e-14);
    lx_assert_near(e.leni_kWh_m2, 217.5025 / 24, 0, 1e-14);
    lx_assert_near(e.power_density_W_m2, 140.0 / 24, 0, 1e-15);
    /* the same from a scene file's [energy] section */
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_file(ctx, "tests/data/design/energy.scene", &sc));
    lx_leni_input si;
    lx_leni se;
    lx_assert_ok(ctx, lx_scene_energy(ctx, sc, &si, &se));
    lx_assert_near(si.power_W, 140, 0, 0);
    lx_assert_near(si.area_m2, 24, 0, 1e-15);
    lx_assert_near(si.constant_factor, 0.9, 0, 1e-15);
    lx_assert_near(si.daylight_factor, 0.55, 0, 1e-15);
    lx_assert_near(se.leni_kWh_m2, 217.5025 / 24, 0, 1e-14);
    lx_scene_free(sc);
    in.daylight_h = 9000;
    assert_int_equal(lx_leni_compute(ctx, &in, &e), LX_EINVAL);
    expect_error(ctx, "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nflux = 1 lm\n[receiver r]\ntype = point\n"
                      "position = 0 m, 0 m, 0 m\n[energy]\noccupancy_factor = 1.5\n",
                 9, "occupancy_factor: a factor from 0 to 1");
    const char *nopower = "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nflux = 1 lm\n[receiver r]\ntype = point\n"
                          "position = 0 m, 0 m, 0 m\n[energy]\narea = 10 m2\nnight_hours = 100 h\n";
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "bad.scene", nopower, strlen(nopower), &sc));
    assert_int_equal(lx_scene_energy(ctx, sc, &si, &se), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "bad.scene:1: luminaire 'a': no power"));
    lx_scene_free(sc);
}

/* ---- the PDF report (its content is read back with pdftotext in tests/cli/design.sh) ---- */
static void test_report_pdf(void **state)
{
    lx_ctx *ctx = *state;
    /* small: the content of a whole report is read back in tests/cli/design.sh */
    const char *t = "[scene]\ntitle = small\n[room r]\nsize = 3 m, 2 m, 2.5 m\n[effects]\ninterreflection = off\n"
                    "[luminaire a]\ntype = rect\nposition = 1.5 m, 1 m, 2.49 m\nwidth = 0.6 m\nlength = 0.6 m\nflux = 3000 lm\n"
                    "power = 30 W\n[luminaire e]\ntype = point\nposition = 1 m, 1 m, 2.4 m\nflux = 100 lm\n"
                    "emergency = non-maintained\n[area desk]\ntype = task\nx = 1 m, 2 m\ny = 0.5 m, 1.5 m\nz = 0.75 m\n"
                    "[observer o]\nposition = 1.5 m, 0.2 m, 1.2 m\nview = 0, 1, 0\nbackground_luminance = 20 cd/m2\n"
                    "[requirement q]\narea = desk\nmaintained_illuminance = 500 lx\n[energy]\nnight_hours = 2000 h\n";
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "small.scene", t, strlen(t), &sc));
    char path[256];
    snprintf(path, sizeof path, "%s/lx_report_%d.pdf", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp", (int)getpid());
    lx_pdf_report_opts o = {.title = "A title", .backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_scene_report_write_pdf(ctx, sc, &o, path));
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    static char buf[1 << 20];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    assert_true(n > 1000);
    assert_memory_equal(buf, "%PDF-", 5);
    assert_non_null(strstr(buf + n - 8, "%%EOF"));
    size_t pages = 0;
    for (const char *p = buf; (p = memchr(p, '/', (size_t)(buf + n - p))) && p < buf + n - 12; p++)
        pages += !strncmp(p, "/Type /Page\n", 12) || !strncmp(p, "/Type /Page ", 12) || !strncmp(p, "/Type /Page/", 12);
    print_message("report: %zu bytes, %zu page objects\n", n, pages);
    assert_true(pages >= 5); /* title, schedule, rooms, areas, glare; the rest where they fit */
    remove(path);
    /* a failed write leaves nothing behind */
    assert_int_equal(lx_scene_report_write_pdf(ctx, sc, &o, "/nonexistent_dir/r.pdf"), LX_EIO);
    lx_scene_free(sc);
}

/* ---- CIE 97:2005: MF = LLMF x LSF x LMF x RSMF from typed tables ----
 * The publication's tables are the user's to type (luxcalc ships no copy); what is checked here is
 * the method: each factor read off its table at the scheme's time by linear interpolation (at a
 * node: the node's value), and the product. Hand computation of the scheme below:
 *   LLMF at 30000 h between (25000 h, 0.90) and (50000 h, 0.80): 0.90 - 0.10 x 5000 / 25000 = 0.88
 *   LSF at 30000 h between (20000 h, 1.00) and (40000 h, 0.96): 1 - 0.04 x 10000 / 20000 = 0.98
 *   LMF at 1.5 a between (1 a, 0.95) and (2 a, 0.92): 0.935
 *   RSMF at 3 a, a node: 0.94
 *   MF = 0.88 x 0.98 x 0.935 x 0.94 = 0.757983... */
static const char scheme[] = "[scene]\nmaintenance = office\n"
                             "[maintenance office]\n"
                             "lamp_type = LED module L80 at 50000 h\n"
                             "lamp_lumen_maintenance = 0 h: 1, 25000 h: 0.90, 50000 h: 0.80\n"
                             "lamp_survival = 0 h: 1, 20000 h: 1, 40000 h: 0.96\n"
                             "luminaire_maintenance = 0.5 a: 0.97, 1 a: 0.95, 2 a: 0.92, 3 a: 0.90\n"
                             "room_surface_maintenance = 1 a: 0.97, 2 a: 0.96, 3 a: 0.94\n"
                             "burning_hours = 30000 h\ncleaning_interval = 1.5 a\nroom_cleaning_interval = 3 a\n"
                             "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nintensity = 400 cd\n"
                             "[receiver r]\ntype = point\nposition = 0 m, 0 m, 0 m\n";

static void test_cie97_scheme(void **state)
{
    lx_ctx *ctx = *state;
    run r = must_run(ctx, "t.scene", scheme, LX_SCENE_NORMAL);
    const lx_scene_design *d = r.sc->design;
    assert_int_equal(d->n_maint, 1);
    const lx_maintenance *m = &d->maint[0];
    lx_assert_near(m->llmf, 0.88, 0, 1e-15);
    lx_assert_near(m->lsf, 0.98, 0, 1e-15);
    lx_assert_near(m->lmf, 0.935, 0, 1e-15);
    lx_assert_near(m->rsmf, 0.94, 0, 0); /* a node: exactly its value */
    lx_assert_near(m->mf, 0.88 * 0.98 * 0.935 * 0.94, 0, 1e-15);
    lx_assert_near(m->burning_h, 30000, 0, 1e-15);
    lx_assert_near(m->cleaning_a, 1.5, 0, 1e-15);
    assert_string_equal(m->lamp_type, "LED module L80 at 50000 h");
    /* the scene's default reaches the luminaire, and its light: 400 / 4 x MF */
    assert_int_equal(d->lum_maint[0], 0);
    lx_assert_near(d->lum_mf[0], m->mf, 0, 0);
    lx_assert_near(r.res->E_lx[0], 100 * m->mf, 0, 1e-14);
    run_free(&r);
}

/* ---- errors ---- */

#define LAMP "[luminaire a]\ntype = point\nposition = 0 m, 0 m, 2 m\nflux = 1000 lm\n"
#define DESK "[receiver r]\ntype = point\nposition = 0 m, 0 m, 0 m\n"

static void test_errors(void **state)
{
    lx_ctx *ctx = *state;
    expect_error(ctx, LAMP "maintenance_factor = 1.2\n" DESK, 5, "maintenance_factor: must be greater than 0 and at most 1");
    expect_error(ctx, LAMP "maintenance_factor = 0\n" DESK, 5, "at most 1 (got 0)");
    expect_error(ctx, "[scene]\nmaintenance_factor = -0.5\n" LAMP DESK, 2, "maintenance_factor");
    expect_error(ctx, LAMP "maintenance_factor = 0.8\nmaintenance = x\n" DESK, 6, "not both");
    expect_error(ctx, LAMP "maintenance = nowhere\n" DESK, 5, "no [maintenance nowhere] section");
    expect_error(ctx, "[scene]\nmaintenance = x\n" LAMP DESK, 2, "no [maintenance x] section");
    expect_error(ctx, "[maintenance m]\nlamp_lumen_maintenance = 0 h: 1, 10000 h: 0.9\nburning_hours = 20000 h\n" LAMP DESK,
                 2, "burning_hours 20000 h lies outside the table of lamp_lumen_maintenance (0 to 10000 h");
    expect_error(ctx, "[maintenance m]\nluminaire_maintenance = 1 a: 0.9, 2 a: 0.8\n" LAMP DESK, 2,
                 "luminaire_maintenance is a table against time: give 'cleaning_interval'");
    expect_error(ctx, "[maintenance m]\nlamp_survival = 10000 h: 0.9, 5000 h: 0.95\n" LAMP DESK, 2, "the times must increase");
    expect_error(ctx, "[maintenance m]\nlamp_survival = 10000: 0.9, 20000 h: 0.95\n" LAMP DESK, 2, "must be a time with its unit");
    expect_error(ctx, "[maintenance m]\nlamp_survival = 1 h: 0.9, 2 h: 1.5\n" LAMP DESK, 2, "at most 1");
    expect_error(ctx, "[maintenance m]\nburning_hours = 100 h\n" LAMP DESK, 1, "give at least one of");
    expect_error(ctx, "[maintenance m]\ncolour = red\n" LAMP DESK, 2, "unknown key 'colour' in [maintenance]");
    expect_error(ctx, "[maintenance m]\nlamp_survival = 0.9\n[maintenance m]\n" LAMP DESK, 3, "defined twice");
    expect_error(ctx, LAMP "emergency_flux = 100 lm\n" DESK, 5, "emergency_flux needs 'emergency");
    expect_error(ctx, LAMP "emergency = sometimes\n" DESK, 5, "emergency: expected no, maintained");
    expect_error(ctx, LAMP "power = 0 W\n" DESK, 5, "power: must be greater than zero");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_maintained_is_new_times_mf),
        cmocka_unit_test(test_per_luminaire_factor),
        cmocka_unit_test(test_cie97_scheme),
        cmocka_unit_test(test_emergency_mode),
        cmocka_unit_test(test_cylindrical_point_source),
        cmocka_unit_test(test_cylindrical_area_source),
        cmocka_unit_test(test_cylindrical_interreflection),
        cmocka_unit_test(test_grid_rule),
        cmocka_unit_test(test_task_bands),
        cmocka_unit_test(test_room_areas),
        cmocka_unit_test(test_area_errors),
        cmocka_unit_test(test_check),
        cmocka_unit_test(test_requirement_errors),
        cmocka_unit_test(test_emergency_corridor),
        cmocka_unit_test(test_observer_positions_directions),
        cmocka_unit_test(test_emergency_areas),
        cmocka_unit_test(test_leni),
        cmocka_unit_test(test_report_pdf),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
