/* test_radiosity.c - the radiosity layer: its input polygons (the checks when one is added, the
 * scene's rooms, surfaces, obstructions and openings as polygons). */
#include "lx_test.h"

#include <string.h>

#include "scene/room_private.h"

/* ---- the input polygons ---- */

static lx_status add(lx_ctx *ctx, lx__rad_geom *g, const double *v, int nv)
{
    lx__rad_poly p = {.rho_front = 0.5, .rho_back = -1, .vol_front = 0, .vol_back = LX__RAD_OUTSIDE, .name = "p",
                      .file = "t.scene", .line = 7};
    return lx__rad_geom_add(ctx, g, v, nv, &p, NULL);
}

static void expect(lx_ctx *ctx, lx_status st, const char *frag)
{
    assert_int_equal(st, LX_EPARSE);
    if (!strstr(lx_ctx_errmsg(ctx), frag)) {
        print_error("message \"%s\" lacks \"%s\"\n", lx_ctx_errmsg(ctx), frag);
        fail();
    }
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "t.scene:7"));
}

static void test_polygon_checks(void **state)
{
    lx_ctx *ctx = *state;
    lx__rad_geom g;
    memset(&g, 0, sizeof g);
    /* an L-shaped floor (non-convex), counter-clockwise from above: normal +z, area 3 x 2 - 1 x 1 = 5 */
    double L[] = {0, 0, 0, 3, 0, 0, 3, 1, 0, 2, 1, 0, 2, 2, 0, 0, 2, 0};
    lx_assert_ok(ctx, add(ctx, &g, L, 6));
    assert_int_equal(g.n_poly, 1);
    lx_assert_near(g.poly[0].area_m2, 5, 0, 1e-15);
    lx_assert_near(g.poly[0].n[2], 1, 0, 1e-15);
    assert_string_equal(g.poly[0].name, "p");
    assert_int_equal(g.n_vol, 1);
    /* not planar: the 4th vertex 1 mm up */
    double np[] = {0, 0, 0, 1, 0, 0, 1, 1, 0.001, 0, 1, 0};
    expect(ctx, add(ctx, &g, np, 4), "not planar: vertex");
    /* a bow tie: edges 1-2 and 3-4 cross */
    double bow[] = {0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0};
    expect(ctx, add(ctx, &g, bow, 4), "cross");
    /* on one line */
    double line[] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
    expect(ctx, add(ctx, &g, line, 3), "no area");
    expect(ctx, add(ctx, &g, L, 2), "at least 3 vertices");
    /* a spike folding back along itself */
    double spike[] = {0, 0, 0, 2, 0, 0, 1, 0, 0, 1, 1, 0};
    expect(ctx, add(ctx, &g, spike, 4), "cross");
    assert_int_equal(g.n_poly, 1); /* nothing added by the failures */
    lx__rad_geom_free(&g);
}

/* The office sample as polygons: every room face faces into its room, the room's faces enclose
 * its volume (the divergence theorem: sum of A n . c / 3 = V), the desk's faces face out. */
static void test_scene_polygons(void **state)
{
    lx_ctx *ctx = *state;
    const char *text = "[room r]\nsize = 4, 3, 2.5 m\n"
                       "[obstruction desk]\nmin = 1, 1, 0 m\nmax = 2, 1.8, 0.75 m\nreflectance = 0.3\n"
                       "[surface panel]\ncorner = 3, 0.5, 0 m\nedge1 = 0, 1, 0 m\nedge2 = 0, 0, 1.5 m\nreflectance = 0.4\n"
                       "[luminaire l]\ntype = point\nposition = 2, 1.5, 2.4 m\nflux = 1000 lm\n"
                       "[receiver p]\ntype = point\nposition = 0.5, 0.5, 0.8 m\n";
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "t.scene", text, strlen(text), &sc));
    lx__rad_geom g;
    memset(&g, 0, sizeof g);
    lx_assert_ok(ctx, lx__room_geom(ctx, sc, &g));
    assert_int_equal(g.n_poly, 6 + 1 + 6);
    double V = 0, area = 0;
    for (size_t i = 0; i < 6; i++) {
        const lx__rad_poly *p = &g.poly[i];
        const double *v = lx__rad_poly_v(&g, i);
        double c[3] = {0, 0, 0};
        for (int k = 0; k < p->nv; k++)
            for (int j = 0; j < 3; j++) c[j] += v[3 * k + j] / p->nv;
        /* the outward normal is -n: V = sum A (-n . c) / 3 */
        V -= p->area_m2 * (p->n[0] * c[0] + p->n[1] * c[1] + p->n[2] * c[2]) / 3;
        area += p->area_m2;
        assert_int_equal(p->vol_front, 0);
        assert_int_equal(p->tag, (int)i);
    }
    lx_assert_near(V, 4 * 3 * 2.5, 0, 1e-14);
    lx_assert_near(area, 2 * (12 + 10 + 7.5), 0, 1e-14);
    assert_string_equal(g.poly[1].name, "r.ceiling");
    lx_assert_near(g.poly[1].n[2], -1, 0, 0);
    /* the panel: both sides reflect */
    lx_assert_near(g.poly[6].rho_back, 0.4, 0, 0);
    lx_assert_near(g.poly[6].n[0], 1, 0, 0); /* edge1 x edge2 = y x z = x */
    /* the desk: outward, solid behind; its top faces up */
    double Vd = 0;
    for (size_t i = 7; i < 13; i++) {
        const lx__rad_poly *p = &g.poly[i];
        const double *v = lx__rad_poly_v(&g, i);
        Vd += p->area_m2 * (p->n[0] * v[0] + p->n[1] * v[1] + p->n[2] * v[2]) / 3;
        assert_int_equal(p->vol_back, LX__RAD_SOLID);
    }
    lx_assert_near(Vd, 1 * 0.8 * 0.75, 0, 1e-14);
    assert_string_equal(g.poly[8].name, "desk.top");
    lx_assert_near(g.poly[8].n[2], 1, 0, 0);
    lx__rad_geom_free(&g);
    lx_scene_free(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_polygon_checks, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_scene_polygons, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
