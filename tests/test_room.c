/* test_room.c - rooms, surfaces and obstructions: form factors against Howell's catalogue, the
 * gather of a diffuse floor (E = M F), the flux balance of closed rooms (the integrating-sphere
 * law), a black room, occlusion (umbra, a half-hidden area source), the observed convergence
 * order, linearity, the scene-file errors, the counters of open-air scenes, openings, and the
 * OpenCL kernels against their CPU twins.
 * References: J. R. Howell, A Catalog of Radiation Heat Transfer Configuration Factors
 * (thermalradiation.net): B-3 (element to a parallel rectangle, normal through a corner), the
 * element to a perpendicular rectangle on the normal to its edge through a corner (Siegel and
 * Howell, Thermal Radiation Heat Transfer; the sky-factor form), C-11 (identical, parallel,
 * directly opposed rectangles), C-14 (perpendicular rectangles with a common edge). Every value
 * was evaluated from the closed form and checked against scipy 1.17.1 dblquad of the definition
 * cos cos / (pi r^2) (agreement 1e-15; /tmp script in the commit message). */
#include "lx_test.h"

#include <string.h>

#include "scene/room_private.h"

#define PI 3.14159265358979323846

/* ---- form factors ---- */

/* Howell B-3, element on the normal through a corner of an a x b rectangle at distance c. */
static double howell_b3(double a, double b, double c)
{
    double A = a / c, B = b / c;
    return (A / sqrt(1 + A * A) * atan(B / sqrt(1 + A * A)) + B / sqrt(1 + B * B) * atan(A / sqrt(1 + B * B))) / (2 * PI);
}

/* Element at the origin, normal +z; rectangle in the plane y = d, x in [0, a], z in [0, b]. */
static double howell_perp(double a, double b, double d)
{
    double X = a / d, Y = b / d;
    return (atan(X) - atan(X / sqrt(1 + Y * Y)) / sqrt(1 + Y * Y)) / (2 * PI);
}

static void test_form_factors_howell(void **state)
{
    (void)state;
    /* B-3: a = 2, b = 3, c = 1.5: 0.1880837353054102 (closed form = scipy dblquad) */
    double x[3] = {0, 0, 0}, nz[3] = {0, 0, 1};
    double o[3] = {0, 0, 1.5}, u[3] = {2, 0, 0}, v[3] = {0, 3, 0}, down[3] = {0, 0, -1};
    lx_assert_near(lx__room_ff_quad(x, nz, o, u, v, down), 0.1880837353054102, 0, 1e-9);
    lx_assert_near(howell_b3(2, 3, 1.5), 0.1880837353054102, 0, 1e-14);
    /* the same rectangle seen from a point off its corner: superposition of four corner rectangles */
    double x2[3] = {0.7, 1.1, 0}, F4 = howell_b3(0.7, 1.1, 1.5) + howell_b3(1.3, 1.1, 1.5) + howell_b3(0.7, 1.9, 1.5) +
                                      howell_b3(1.3, 1.9, 1.5);
    lx_assert_near(lx__room_ff_quad(x2, nz, o, u, v, down), F4, 0, 1e-9);
    /* perpendicular: a = 2, b = 1.5, d = 1.2: 0.0838981602958004 */
    double op[3] = {0, 1.2, 0}, up[3] = {2, 0, 0}, vp[3] = {0, 0, 1.5}, my[3] = {0, -1, 0};
    lx_assert_near(lx__room_ff_quad(x, nz, op, up, vp, my), 0.0838981602958004, 0, 1e-9);
    lx_assert_near(howell_perp(2, 1.5, 1.2), 0.0838981602958004, 0, 1e-14);
    /* a polygon partly behind the element's tangent plane: only the front part counts (the
     * rectangle z in [-1, 1.5] sees its z >= 0 part, the perpendicular case above) */
    double ob[3] = {0, 1.2, -1}, vb[3] = {0, 0, 2.5};
    lx_assert_near(lx__room_ff_quad(x, nz, ob, up, vb, my), 0.0838981602958004, 0, 1e-9);
    /* seen from behind: nothing */
    double mz[3] = {0, 0, 1};
    lx_assert_near(lx__room_ff_quad(x, nz, o, u, v, mz), 0, 0, 0);
    /* C-11: identical parallel directly opposed 2 x 3 rectangles 1 apart: 0.4755764365329532 */
    double o1[3] = {0, 0, 0}, o2[3] = {0, 0, 1};
    lx_assert_near(lx__room_ff_area(o1, u, v, nz, o2, u, v, down, 1e-11), 0.4755764365329532, 0, 1e-9);
    /* C-14: perpendicular rectangles with a common edge l = 2, w = 1.5, h = 1: 0.18325664801834565 */
    double w1[3] = {0, 1.5, 0}, e[3] = {2, 0, 0}, h2[3] = {0, 0, 1}, py[3] = {0, 1, 0};
    lx_assert_near(lx__room_ff_area(o1, e, w1, nz, o1, e, h2, py, 1e-11), 0.18325664801834565, 0, 1e-9);
    /* and unit squares (C-14: 0.20004377607540316) */
    double e1[3] = {1, 0, 0}, e2[3] = {0, 1, 0}, e3[3] = {0, 0, 1};
    lx_assert_near(lx__room_ff_area(o1, e1, e2, nz, o1, e1, e3, py, 1e-11), 0.20004377607540316, 0, 1e-9);
}

/* ---- scenes ---- */

typedef struct run {
    lx_scene *sc;
    lx_scene_plan *plan;
    lx_scene_result *res;
} run;

static lx_status run_text(lx_ctx *ctx, const char *text, const lx_scene_eval_opts *opts, run *r)
{
    memset(r, 0, sizeof *r);
    lx_status st = lx_scene_read_mem(ctx, "room.scene", text, strlen(text), &r->sc);
    if (st == LX_OK) st = lx_scene_plan_make(ctx, r->sc, LX_BACKEND_CPU, &r->plan);
    if (st == LX_OK) st = lx_scene_eval(ctx, r->sc, r->plan, opts, &r->res);
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
    lx_assert_ok(ctx, run_text(ctx, text, NULL, &r));
    return r;
}

/* The area-weighted mean over every face: indirect (or direct) illuminance. */
static double faces_mean(const lx_scene_result *res, int indirect, double *S)
{
    double a = 0, s = 0;
    for (size_t i = 0; i < res->n_surfaces; i++) {
        const lx_scene_surface_result *f = &res->surfaces[i];
        if (!(f->area_m2 > 0)) continue;
        a += f->area_m2;
        s += f->area_m2 * (indirect ? f->indirect_lx : f->direct_lx);
    }
    if (S) *S = a;
    return s / a;
}

/* A closed 4 x 3 x 2.5 m room (S = 59 m2) of one reflectance with an isotropic 1000 lm source. */
static void closed_room(char *buf, size_t n, double rho, const char *extra)
{
    snprintf(buf, n,
             "[scene]\n%s\n[room r]\nsize = 4, 3, 2.5 m\nceiling = %.17g\nwalls = %.17g\nfloor = %.17g\n"
             "[luminaire lamp]\ntype = point\nposition = 1.5, 1.2, 1.4 m\nflux = 1000 lm\n"
             "[receiver p]\ntype = point\nposition = 2.5 m, 1.5 m, 0.8 m\n",
             extra, rho, rho, rho);
}

/* Flux balance (the integrating-sphere law): light first reaching the faces is Phi (closed room),
 * then rho Phi, rho^2 Phi ...: the area-weighted mean indirect illuminance is rho Phi / (S (1 - rho)). */
static void test_flux_balance(void **state)
{
    lx_ctx *ctx = *state;
    const double rhos[] = {0.05, 0.2, 0.5, 0.8, 0.95};
    for (int k = 0; k < 5; k++) {
        for (int tight = 0; tight < 2; tight++) {
            char text[1024];
            double tol = tight ? 1e-5 : 1e-3;
            /* the tight runs fix the patch size: the balance holds for any patches (the form factors
             * of every shooting point sum to 1), only the tolerance's quadrature and sweeps matter */
            closed_room(text, sizeof text, rhos[k],
                        tight ? "interreflection_tolerance = 1e-5\npatch_size = 0.5 m" : "interreflection_tolerance = 1e-3");
            run r = must_run(ctx, text);
            double S, mean = faces_mean(r.res, 1, &S), want = rhos[k] * 1000 / (59 * (1 - rhos[k]));
            print_message("rho %.2f tol %.0e: mean indirect %.10g lx, closed form %.10g (rel %.2e), %zu patches, %llu sweeps\n",
                          rhos[k], tol, mean, want, mean / want - 1, r.res->room.n_patches,
                          (unsigned long long)r.res->room.sweeps);
            lx_assert_near(S, 59, 1e-9, 0);
            lx_assert_near(mean, want, 0, tol);
            /* energy: every lumen the faces received is absorbed or still unshot (closed room) */
            lx_assert_near(r.res->room.direct_lm, 1000, 0, tol);
            lx_assert_near(r.res->room.escaped_lm, 0, 1e-9, 0);
            run_free(&r);
        }
    }
}

static void test_black_room(void **state)
{
    lx_ctx *ctx = *state;
    char text[1024];
    /* every face black: no light can be reflected, so the planner leaves interreflection off (it
     * solved a room of zeros before), and says why; the receiver gets the point law alone,
     * 1000 / (4 pi) / d^2 cos */
    closed_room(text, sizeof text, 0, "interreflection_tolerance = 1e-5");
    run r = must_run(ctx, text);
    assert_false(r.plan->on[LX_EFFECT_INTERREFLECTION]);
    assert_non_null(strstr(r.plan->reason[LX_EFFECT_INTERREFLECTION], "every reflectance is 0"));
    assert_null(r.res->indirect_lx);
    double d2 = 1.0 + 0.09 + 0.36, E = 1000 / (4 * PI) / d2 * (0.6 / sqrt(d2));
    lx_assert_near(r.res->E_lx[0], E, 0, 1e-12);
    run_free(&r);
}

/* A closed room with a desk standing on its floor: every ray from the source ends on a face (the
 * room's or the desk's; the floor under the desk is no face, the desk's shadow gets nothing), so
 * the faces' direct flux is Phi; and the faces the desk hides from the source get none of it. */
static void test_closed_room_with_desk(void **state)
{
    lx_ctx *ctx = *state;
    run r = must_run(ctx, "[scene]\ninterreflection_tolerance = 1e-3\n[room hall]\nsize = 10, 6, 3 m\n"
                          "[obstruction desk]\nmin = 4.2, 2.6, 0 m\nmax = 5.8, 3.4, 0.75 m\nreflectance = 0.3\n"
                          "[luminaire l]\ntype = point\nposition = 1.25, 1.5, 2.5 m\nflux = 3000 lm\n"
                          "[receiver wp]\ntype = grid\nx = 0.5 m, 9.5 m\ny = 0.5 m, 5.5 m\nz = 0.8 m\nspacing = 0.5 m\n");
    assert_true(r.plan->on[LX_EFFECT_OCCLUSION]); /* no receiver pair is cut, but the desk shadows the floor */
    lx_assert_near(r.res->room.direct_lm, 3000, 0, 1e-3);
    /* the desk's faces: exactly I times their solid angles (the rectangle formula), 17.2208574793 lm
     * for top, xmin and ymin; xmax and ymax face away */
    const lx_scene_surface_result *s = r.res->surfaces;
    double desk = s[7].direct_lx * s[7].area_m2 + s[8].direct_lx * s[8].area_m2 + s[10].direct_lx * s[10].area_m2;
    lx_assert_near(desk, 17.220857479297308, 0, 1e-3);
    assert_true(s[9].direct_lx == 0 && s[11].direct_lx == 0);
    run_free(&r);
}

/* A 4 x 4 floor of exitance M seen from a ceiling point and a wall point: E = M F (closed forms,
 * superposition of Howell's corner rectangles), gathered from the floor's patches. */
static void test_floor_exitance_gather(void **state)
{
    lx_ctx *ctx = *state;
    run r = must_run(ctx, "[scene]\npatch_size = 0.35 m\n[room box]\nsize = 4, 4, 3 m\n"
                          "[luminaire l]\ntype = point\nposition = 2, 2, 1.5 m\nflux = 100 lm\n"
                          "[receiver p]\ntype = point\nposition = 2 m, 2 m, 1 m\n");
    const lx__room_mesh *m = r.plan->room.mesh;
    assert_non_null(m);
    double *B = calloc(m->n_patch, sizeof *B), M = 123.0;
    size_t nf = 0;
    for (size_t i = 0; i < m->n_patch; i++)
        if (!strcmp(m->face[m->patch[i].face].name, "box.floor")) B[i] = M, nf++;
    assert_true(nf > 100);
    double pts[6] = {1.3, 2.2, 3, 0, 1.5, 1.2}, nrm[6] = {0, 0, -1, 1, 0, 0}, E[2];
    int cell[2] = {0, 0};
    lx__room_gather_job g = {m, m->patch, m->n_patch, B, 2, pts, nrm, cell, NULL, LX__ROOM_VIS_RECEIVERS};
    int used = 0;
    lx_assert_ok(ctx, lx__room_gather(ctx, &g, LX_BACKEND_CPU, E, &used));
    /* ceiling (1.3, 2.2, 3): 0.34080700039882694; wall (0, 1.5, 1.2): 0.2809471966898381 */
    lx_assert_near(E[0], M * 0.34080700039882694, 0, 1e-9);
    lx_assert_near(E[1], M * 0.2809471966898381, 0, 1e-9);
    lx_assert_near(howell_b3(1.3, 2.2, 3) + howell_b3(2.7, 2.2, 3) + howell_b3(1.3, 1.8, 3) + howell_b3(2.7, 1.8, 3),
                   0.34080700039882694, 0, 1e-14);
    lx_assert_near(howell_perp(1.5, 4, 1.2) + howell_perp(2.5, 4, 1.2), 0.2809471966898381, 0, 1e-14);
    free(B);
    run_free(&r);
}

/* ---- occlusion ---- */

/* A 400 cd point 3 m above the floor, a box 1..1.5 m high over [-0.5, 0.5]^2 (black: no
 * interreflection): its shadow on z = 0 is [-1, 1]^2 (the top face projected from the source, x 2);
 * outside it E = I cos / d^2 = 400 * 3 / d^3. */
static void test_occlusion_umbra(void **state)
{
    lx_ctx *ctx = *state;
    run r = must_run(ctx, "[luminaire l]\ntype = point\nposition = 0, 0, 3 m\nintensity = 400 cd\n"
                          "[obstruction box]\nmin = -0.5, -0.5, 1 m\nmax = 0.5, 0.5, 1.5 m\nreflectance = 0\n"
                          "[receiver floor]\ntype = grid\nx = -1.95 m, 1.95 m\ny = -1.95 m, 1.95 m\nz = 0 m\nspacing = 0.3 m\n");
    assert_true(r.plan->on[LX_EFFECT_OCCLUSION]);
    assert_false(r.plan->on[LX_EFFECT_INTERREFLECTION]);
    size_t dark = 0;
    for (size_t g = 0; g < r.res->n_points; g++) {
        const double *q = r.sc->rec[0].points + 3 * g;
        double d = sqrt(q[0] * q[0] + q[1] * q[1] + 9);
        int umbra = fabs(q[0]) < 1 && fabs(q[1]) < 1;
        dark += umbra;
        lx_assert_near(r.res->E_lx[g], umbra ? 0 : 400 * 3 / (d * d * d), 1e-12, 1e-12);
    }
    assert_int_equal(dark, 36); /* 6 x 6 grid points inside */
    assert_true(r.res->work.visibility_tests > 0);
    run_free(&r);
}

/* A Lambertian 1 x 0.6 m panel of 1000 cd/m2 2 m above a point, half of it hidden by a black
 * plane at 1 m whose edge lies under the panel's centre line: E = pi L F(visible half), F by
 * Howell B-3 (two 0.5 x 0.3 corner rectangles): 0.02260061778565885. With the edge 0.1 m off
 * (x < 0.2 of the panel hidden): 2 (B3(0.5, 0.3, 2) - B3(0.2, 0.3, 2)) = 0.013253437002217577. */
static void test_half_hidden_area_source(void **state)
{
    lx_ctx *ctx = *state;
    const char *fmt = "[luminaire panel]\ntype = rect\nposition = 0, 0, 2 m\nluminance = 1000 cd/m2\nwidth = 1 m\nlength = 0.6 m\n"
                      "[surface edge]\ncorner = -5, -5, 1 m\nedge1 = %.17g, 0, 0 m\nedge2 = 0, 10, 0 m\nreflectance = 0\n"
                      "[receiver p]\ntype = point\nposition = 0 m, 0 m, 0 m\n";
    char text[1024];
    snprintf(text, sizeof text, fmt, 5.0);
    run r = must_run(ctx, text);
    assert_true(r.plan->on[LX_EFFECT_OCCLUSION]);
    lx_assert_near(r.res->E_lx[0], PI * 1000 * 0.02260061778565885, 0, 2e-5);
    lx_assert_near(PI * 1000 * 2 * howell_b3(0.5, 0.3, 2), PI * 1000 * 0.02260061778565885, 0, 1e-14);
    assert_true(r.res->work.nearfield_pairs == 1); /* the visible part, integrated */
    run_free(&r);
    snprintf(text, sizeof text, fmt, 5.1);
    r = must_run(ctx, text);
    /* the edge cuts cells: the midpoint rule's error is first order there (128 cells a side) */
    lx_assert_near(r.res->E_lx[0], PI * 1000 * 0.013253437002217577, 0, 3e-3);
    run_free(&r);
}

/* ---- convergence, linearity, counters ---- */

static void test_convergence_order(void **state)
{
    lx_ctx *ctx = *state;
    double mean[4], h[4] = {1.0, 0.5, 0.25, 0.125};
    for (int k = 0; k < 4; k++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "[scene]\ninterreflection_tolerance = 1e-5\npatch_size = %g m\npatch_refinement = no\n"
                 "[room r]\nsize = 4, 3, 2.5 m\nceiling = 0.7\nwalls = 0.5\nfloor = 0.2\n"
                 "[luminaire lamp]\ntype = point\nposition = 1.3, 1.1, 2.2 m\nflux = 1000 lm\n"
                 "[receiver wp]\ntype = grid\nx = 0.5 m, 3.5 m\ny = 0.5 m, 2.5 m\nz = 0.8 m\nspacing = 0.5 m\n",
                 h[k]);
        run r = must_run(ctx, text);
        double s = 0;
        for (size_t g = 0; g < r.res->n_points; g++) s += r.res->indirect_lx[g];
        mean[k] = s / (double)r.res->n_points;
        run_free(&r);
    }
    double d1 = fabs(mean[0] - mean[1]), d2 = fabs(mean[1] - mean[2]), d3 = fabs(mean[2] - mean[3]);
    double p1 = log2(d1 / d2), p2 = log2(d2 / d3);
    print_message("work-plane mean indirect: %.10g %.10g %.10g %.10g lx; changes %.3e %.3e %.3e; observed order %.2f, %.2f\n",
                  mean[0], mean[1], mean[2], mean[3], d1, d2, d3, p1, p2);
    /* converging: each halving changes the mean less, at an order near 2 (piecewise-constant
     * exitance, midpoint-like) */
    assert_true(d2 < d1 && d3 < d2);
    assert_true(p2 > 1.3 && p2 < 3.5);
}

static const char *office =
    "[scene]\ninterreflection_tolerance = 1e-4\npatch_size = 0.5 m\n"
    "[room office]\nsize = 5, 4, 2.8 m\n"
    "[obstruction desk]\nmin = 1, 1, 0 m\nmax = 2.6, 1.8, 0.75 m\nreflectance = 0.3\n"
    "[luminaire a]\ntype = point\nposition = 1.5, 1.5, 2.6 m\nflux = 1000 lm\n"
    "[luminaire b]\ntype = spot\nposition = 3.5, 2.5, 2.6 m\nflux = 800 lm\nexponent = 3\n"
    "[luminaire c]\ntype = rect\nposition = 2.5, 3, 2.7 m\nluminance = 2000 cd/m2\nwidth = 0.6 m\nlength = 0.6 m\n"
    "[receiver wp]\ntype = grid\nx = 0.5 m, 4.5 m\ny = 0.5 m, 3.5 m\nz = 0.8 m\nspacing = 0.5 m\n";

/* Linearity: one luminaire at a time, summed, equals all of them at once (one mesh, one plan). */
static void test_linearity(void **state)
{
    lx_ctx *ctx = *state;
    run all = must_run(ctx, office);
    size_t np = all.res->n_points;
    double *sum = calloc(np, sizeof *sum);
    for (size_t l = 0; l < all.sc->n_lum; l++) {
        lx_scene_eval_opts o;
        memset(&o, 0, sizeof o);
        o.single = 1;
        o.index = l;
        lx_scene_result *res = NULL;
        lx_assert_ok(ctx, lx_scene_eval(ctx, all.sc, all.plan, &o, &res));
        for (size_t g = 0; g < np; g++) sum[g] += res->E_lx[g];
        lx_scene_result_free(res);
    }
    for (size_t g = 0; g < np; g++) lx_assert_near(sum[g], all.res->E_lx[g], 0, 1e-4);
    free(sum);
    run_free(&all);
}

static int costly(const lx_counters *c)
{
    return c->visibility_tests || c->form_factors || c->radiosity_patches || c->radiosity_shots || c->gather_points;
}

/* An open-air scene does no occlusion or interreflection work; a room with interreflection
 * forced off does none of the radiosity work and gives the direct light. */
static void test_open_air_does_no_room_work(void **state)
{
    lx_ctx *ctx = *state;
    lx_ctx_counters_reset(ctx);
    run r = must_run(ctx, "[luminaire l]\ntype = point\nposition = 0, 0, 2 m\nflux = 1000 lm\n"
                          "[receiver g]\ntype = grid\nx = -1 m, 1 m\ny = -1 m, 1 m\nz = 0 m\nspacing = 0.5 m\n");
    assert_false(r.plan->on[LX_EFFECT_OCCLUSION]);
    assert_false(r.plan->on[LX_EFFECT_INTERREFLECTION]);
    assert_null(r.plan->occ);
    assert_null(r.res->indirect_lx);
    assert_int_equal(r.res->n_surfaces, 0);
    assert_false(costly(&r.res->work));
    assert_false(costly(&r.plan->estimate));
    lx_counters c;
    lx_ctx_counters(ctx, &c);
    assert_false(costly(&c));
    run_free(&r);
    char text[1024];
    closed_room(text, sizeof text, 0.5, "");
    strcat(text, "[effects]\ninterreflection = off\n");
    r = must_run(ctx, text);
    assert_false(r.plan->on[LX_EFFECT_INTERREFLECTION]);
    assert_false(costly(&r.res->work));
    double d2 = 1.45, E = 1000 / (4 * PI) / d2 * (0.6 / sqrt(d2));
    lx_assert_near(r.res->E_lx[0], E, 0, 1e-12);
    run_free(&r);
}

/* The faces: names, exposed areas (the desk's footprint is not floor), results. */
static void test_surfaces(void **state)
{
    lx_ctx *ctx = *state;
    run r = must_run(ctx, office);
    assert_int_equal(r.res->n_surfaces, 12);
    const lx_scene_surface_result *s = r.res->surfaces;
    assert_string_equal(s[0].name, "office.floor");
    assert_string_equal(s[5].name, "office.wall_ymax");
    assert_string_equal(s[6].name, "desk.bottom");
    assert_string_equal(s[7].name, "desk.top");
    lx_assert_near(s[0].area_m2, 20 - 1.6 * 0.8, 1e-9, 0);
    lx_assert_near(s[6].area_m2, 0, 0, 0); /* standing on the floor */
    assert_true(isnan(s[6].E_lx));
    lx_assert_near(s[7].area_m2, 1.6 * 0.8, 1e-9, 0);
    lx_assert_near(s[1].area_m2, 20, 1e-9, 0);
    for (int k = 0; k < 6; k++) {
        assert_true(s[k].direct_lx >= 0 && s[k].indirect_lx > 0);
        lx_assert_near(s[k].L_cd_m2, s[k].reflectance * s[k].E_lx / PI, 0, 1e-12);
    }
    /* the ceiling gets no direct light from luminaires in its plane or aimed down... but the
     * spot and point are below it: some */
    assert_true(s[1].direct_lx > 0);
    run_free(&r);
}

/* ---- errors ---- */

static void expect_error(lx_ctx *ctx, const char *text, long line, const char *fragment)
{
    lx_scene *sc = NULL;
    lx_scene_plan *p = NULL;
    lx_status st = lx_scene_read_mem(ctx, "bad.scene", text, strlen(text), &sc);
    if (st == LX_OK) st = lx_scene_plan_make(ctx, sc, LX_BACKEND_CPU, &p);
    lx_scene_plan_free(p);
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

#define LUM "[luminaire l]\ntype = point\nposition = 1, 1, 2 m\nflux = 100 lm\n"
#define REC "[receiver p]\ntype = point\nposition = 1 m, 1 m, 0.5 m\n"

static void test_errors(void **state)
{
    lx_ctx *ctx = *state;
    expect_error(ctx, "[room r]\nsize = 4, 4, 3 m\nwalls = 1\n" LUM REC, 3, "below 1");
    expect_error(ctx, "[room r]\nsize = 4, 4, 3 m\nfloor = -0.1\n" LUM REC, 3, "at least 0");
    expect_error(ctx, "[room r]\nsize = 4, 0, 3 m\n" LUM REC, 1, "greater than zero");
    expect_error(ctx, "[room r]\norigin = 0, 0, 0 m\n" LUM REC, 1, "missing 'size'");
    expect_error(ctx, "[room r]\nsize = 4, 4, 3 m\ncolour = red\n", 3, "unknown key 'colour' in [room]");
    expect_error(ctx, "[surface s]\ncorner = 0, 0, 0 m\nedge1 = 1, 0, 0 m\nedge2 = 2, 0, 0 m\nreflectance = 0.5\n" LUM REC, 1,
                 "zero area");
    expect_error(ctx, "[surface s]\ncorner = 0, 0, 0 m\nedge1 = 0, 0, 0 m\nedge2 = 0, 1, 0 m\nreflectance = 0.5\n" LUM REC, 1,
                 "zero area");
    expect_error(ctx, "[surface s]\ncorner = 0, 0, 0 m\nedge1 = 1, 0, 0 m\nedge2 = 0, 1, 0 m\n" LUM REC, 1,
                 "missing 'reflectance'");
    expect_error(ctx, "[obstruction o]\nmin = 0, 0, 0 m\nmax = 1, 0, 1 m\nreflectance = 0.3\n" LUM REC, 1,
                 "max must exceed min");
    expect_error(ctx, "[room r]\nsize = 4, 4, 3 m\n[luminaire l]\ntype = point\nposition = 5, 1, 2 m\nflux = 1 lm\n" REC, 3,
                 "outside every room");
    expect_error(ctx, "[room r]\nsize = 4, 4, 3 m\n" LUM "[receiver p]\ntype = grid\nx = 0 m, 5 m\ny = 1 m\nz = 1 m, 2 m\n"
                      "points = 3, 3\n", 7, "outside every room");
    expect_error(ctx, "[obstruction desk]\nmin = 0, 0, 0 m\nmax = 2, 2, 0.75 m\nreflectance = 0.3\n" LUM REC, 9,
                 "inside obstruction 'desk'");
    expect_error(ctx, "[room a]\nsize = 4, 4, 3 m\n[room b]\norigin = 3, 0, 0 m\nsize = 4, 4, 3 m\n" LUM REC, 3,
                 "overlaps room 'a'");
    expect_error(ctx, "[room a]\nsize = 4, 4, 3 m\n[surface s]\ncorner = 3, 1, 0 m\nedge1 = 2, 0, 0 m\nedge2 = 0, 0, 1 m\n"
                      "reflectance = 0.5\n" LUM REC, 3, "partly outside its room");
    expect_error(ctx, "[room a]\nsize = 4, 4, 3 m\n[surface s]\ncorner = 0, 1, 0.5 m\nedge1 = 0, 1, 0 m\nedge2 = 0, 0, 1 m\n"
                      "reflectance = 0.5\n" LUM REC, 3, "lies on a face of room 'a'");
    expect_error(ctx, "[scene]\ninterreflection_tolerance = 2\n", 2, "must be from 1e-6 to 0.5");
    expect_error(ctx, "[room a]\nsize = 4, 4, 3 m\n[room a]\nsize = 1, 1, 1 m\n", 3, "already the name");
    expect_error(ctx, "[room a]\nsize = 4, 4, 3 m\n" LUM REC "[effects]\nocclusion = on\n", 11, "occlusion forced on");
    expect_error(ctx, LUM REC "[effects]\ninterreflection = on\n", 9, "interreflection forced on");
    /* the memory bound: say how many patches the tolerance needs and how many it allows */
    const char *big = "[scene]\ninterreflection_tolerance = 1e-4\n[room r]\nsize = 10, 10, 3 m\n" LUM REC;
    lx_scene *sc = NULL;
    lx_scene_plan *p = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "bad.scene", big, strlen(big), &sc));
    setenv("LX_ROOM_MEMORY_MB", "1", 1);
    lx_status st = lx_scene_plan_make(ctx, sc, LX_BACKEND_CPU, &p);
    unsetenv("LX_ROOM_MEMORY_MB");
    lx_scene_free(sc);
    assert_int_equal(st, LX_EPARSE);
    assert_null(p);
    assert_int_equal(lx_ctx_errline(ctx), 2);
    print_message("%s\n", lx_ctx_errmsg(ctx));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "interreflection needs "));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "the memory bound of 1 MiB allows "));
}

/* ---- openings (the internal API daylight builds on) ---- */

/* A hole over the whole ceiling of a closed room: no patches there, the light reaching it leaves:
 * direct = absorbed + escaped + unshot at the end, and the ceiling's exposed area is 0. */
static void test_opening_is_a_hole(void **state)
{
    lx_ctx *ctx = *state;
    char text[1024];
    closed_room(text, sizeof text, 0.6, "interreflection_tolerance = 1e-5\npatch_size = 0.5 m");
    run r = must_run(ctx, text);
    lx__room_opening hole = {LX_ROOM_CEILING, 0, 1, 0, 1};
    lx__room_mesh_opts o;
    memset(&o, 0, sizeof o);
    o.h_m = 0.5;
    o.tol = 1e-3;
    o.quad_tol = 1e-6;
    o.max_patches = 100000;
    o.open = &hole;
    o.n_open = 1;
    lx__room_mesh *m = NULL;
    lx_assert_ok(ctx, lx__room_mesh_build(ctx, r.sc, r.plan, &o, &m));
    lx_assert_near(m->face[LX_ROOM_CEILING].area_m2, 0, 0, 0);
    lx_assert_near(m->face[LX_ROOM_FLOOR].area_m2, 12, 1e-9, 0);
    for (size_t i = 0; i < m->n_patch; i++) assert_int_not_equal(m->patch[i].face, LX_ROOM_CEILING);
    /* external light: 1 lm on every patch (any source: the solver takes it as given) */
    double *phi0 = malloc(m->n_patch * sizeof *phi0), *F = NULL, total = 0;
    for (size_t i = 0; i < m->n_patch; i++) phi0[i] = 1, total += 1;
    int used = 0;
    lx_assert_ok(ctx, lx__room_ff_matrix(ctx, m, LX_BACKEND_CPU, &F, &used));
    lx__room_solution sol;
    lx_assert_ok(ctx, lx__room_solve(ctx, m, F, phi0, 1e-9, &sol));
    double absorbed = 0;
    for (size_t i = 0; i < m->n_patch; i++) absorbed += (1 - m->patch[i].rho) * (phi0[i] + sol.phi_ind_lm[i]);
    /* every received lumen is absorbed (1 - rho), escapes through the hole, or waits unshot */
    lx_assert_near(absorbed + sol.escaped_lm + sol.unshot_lm, total, 0, 1e-12);
    assert_true(sol.escaped_lm > 0.1 * total);
    lx__room_solution_free(&sol);
    free(F);
    free(phi0);
    lx__room_mesh_free(m);
    run_free(&r);
}

/* ---- OpenCL twins ---- */

static void test_opencl_parity(void **state)
{
    lx_ctx *ctx = *state;
#if LX_OPENCL
    lx_cl_device_info info;
    if (lx_cl_info(ctx, &info) != LX_OK) {
        skip(); /* no OpenCL device on this machine */
        return;
    }
    if (!info.fp64) {
        skip(); /* the room kernels are double precision */
        return;
    }
    run r = must_run(ctx, office);
    const lx__room_mesh *m = r.plan->room.mesh;
    size_t n = m->n_patch;
    double *Fc = malloc(n * n * sizeof *Fc), *Fd = malloc(n * n * sizeof *Fd);
    lx__room_ff_rows(m, 0, n, Fc);
    lx_assert_ok(ctx, lx__room_cl_ff(ctx, m, Fd));
    double worst = 0;
    for (size_t k = 0; k < n * n; k++) {
        double d = fabs(Fd[k] - Fc[k]), s = fabs(Fc[k]);
        if (d > 1e-15) worst = fmax(worst, d / s);
        lx_assert_near(Fd[k], Fc[k], 1e-15, 1e-9);
    }
    /* a gather at the receivers from the elements, exitance 1 .. 2 */
    size_t ne = m->n_elem, np = r.res->n_points;
    double *B = malloc(ne * sizeof *B), *pts = malloc(3 * np * sizeof *pts), *nrm = malloc(3 * np * sizeof *nrm);
    double *Ec = malloc(np * sizeof *Ec), *Ed = malloc(np * sizeof *Ed);
    int *cell = calloc(np, sizeof *cell);
    for (size_t e = 0; e < ne; e++) B[e] = 1 + (double)(e % 7) / 7;
    for (size_t g = 0; g < np; g++) {
        memcpy(pts + 3 * g, r.sc->rec[0].points + 3 * g, 3 * sizeof *pts);
        nrm[3 * g] = nrm[3 * g + 1] = 0, nrm[3 * g + 2] = 1;
    }
    lx__room_gather_job g = {m, m->elem, ne, B, np, pts, nrm, cell, NULL, LX__ROOM_VIS_RECEIVERS};
    lx__room_gather_cpu(&g, 0, np, Ec);
    lx_assert_ok(ctx, lx__room_cl_gather(ctx, &g, Ed));
    for (size_t k = 0; k < np; k++) {
        worst = fmax(worst, fabs(Ed[k] - Ec[k]) / fabs(Ec[k]));
        lx_assert_near(Ed[k], Ec[k], 0, 1e-9);
    }
    print_message("OpenCL (%s) against the CPU twins: %zu x %zu form factors, %zu gathers, largest relative "
                  "difference %.3g\n", info.device_name, n, n, np, worst);
    free(Fc), free(Fd), free(B), free(pts), free(nrm), free(Ec), free(Ed), free(cell);
    run_free(&r);
#else
    (void)ctx;
    skip(); /* built without OpenCL */
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_form_factors_howell),
        cmocka_unit_test_setup_teardown(test_floor_exitance_gather, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_flux_balance, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_black_room, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_closed_room_with_desk, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_occlusion_umbra, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_half_hidden_area_source, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_convergence_order, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_linearity, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_open_air_does_no_room_work, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_surfaces, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_errors, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_opening_is_a_hole, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_opencl_parity, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
