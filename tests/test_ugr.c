/* test_ugr.c - glare: the CIE 117 formula on hand-computed configurations, the Guth position index
 * against CIE 117's table at a few points, UGR at scene observers against a computation written
 * out here, and the CIE 190 table of a real luminaire against an independent implementation
 * (eulumdat-ugr 1.0.2, PyPI). */
#include "lx_test.h"

#include <string.h>

#define DEG (M_PI / 180)

static void test_formula(void **state)
{
    lx_ctx *ctx = *state;
    /* one source L = 10000 cd/m2, omega = 0.01 sr, p = 1, Lb = 40 cd/m2:
     * 8 log10(0.25 / 40 * 1e8 * 0.01) = 8 log10(6250) = 8 x 3.7958800 = 30.367040 */
    double L = 10000, w = 0.01, p = 1, t, u;
    lx_assert_ok(ctx, lx_ugr(ctx, 40, 1, &L, &w, &p, &t, &u));
    lx_assert_near(u, 8 * log10(6250.0), 1e-12, 0);
    lx_assert_near(u, 30.367040, 1e-6, 0);
    lx_assert_near(t, 1e6, 1e-6, 0);
    /* two equal sources: + 8 log10(2) = 2.408 */
    double L2[2] = {10000, 10000}, w2[2] = {0.01, 0.01}, p2[2] = {1, 1}, u2;
    lx_assert_ok(ctx, lx_ugr(ctx, 40, 2, L2, w2, p2, NULL, &u2));
    lx_assert_near(u2 - u, 8 * log10(2.0), 1e-12, 0);
    /* p = 2 quarters the term: - 8 log10(4) */
    double p4 = 2, u4;
    lx_assert_ok(ctx, lx_ugr(ctx, 40, 1, &L, &w, &p4, NULL, &u4));
    lx_assert_near(u - u4, 8 * log10(4.0), 1e-12, 0);
    /* nothing in view: NaN; Lb must be positive */
    double un;
    lx_assert_ok(ctx, lx_ugr(ctx, 40, 0, NULL, NULL, NULL, NULL, &un));
    assert_true(isnan(un));
    assert_int_equal(lx_ugr(ctx, 0, 1, &L, &w, &p, NULL, &u), LX_EINVAL);
}

static void test_position_index(void **state)
{
    (void)state;
    /* on the line of sight p = 1 */
    lx_assert_near(lx_guth_position_index(0, 0), 1, 1e-15, 0);
    /* hand-computed: sigma 30, tau 0: ln p = (35.2 - 1.22) 1e-3 30 + 21e-5 900 = 1.2084 */
    lx_assert_near(lx_guth_position_index(30, 0), exp(1.2084), 1e-12, 1e-12);
    /* against CIE 117 Table 4.1 (Guth), T/R = 0: H/R = 0.5 (sigma 26.565, tau 0) is 2.86, H/R =
     * 1.0 (sigma 45) is 7.00; T/R = 1, H/R = 1 (sigma 54.74, tau 45) is 7.00: the fit is within
     * 4 % of the table there */
    lx_assert_near(lx_guth_position_index(atan(0.5) / DEG, 0), 2.86, 0, 0.04);
    lx_assert_near(lx_guth_position_index(45, 0), 7.00, 0, 0.04);
    lx_assert_near(lx_guth_position_index(acos(1 / sqrt(3.0)) / DEG, 45), 7.00, 0, 0.04);
    /* below the line of sight (Iwata & Tokura): R/D = tan 20 = 0.364 < 0.6: 1 + 0.8 R/D */
    lx_assert_near(lx_guth_position_index(20, 180), 1 + 0.8 * tan(20 * DEG), 1e-12, 0);
    lx_assert_near(lx_guth_position_index(40, 135), 1 + 1.2 * tan(40 * DEG), 1e-12, 0);
    assert_true(isnan(lx_guth_position_index(95, 0)));
}

/* Two Lambertian panels in front of an observer looking along +y, written out by hand. */
static void test_scene_observer(void **state)
{
    lx_ctx *ctx = *state;
    const char *text = "[luminaire p1]\ntype = rect\nposition = 0, 3, 2.8 m\nluminance = 4000 cd/m2\n"
                       "width = 0.6 m\nlength = 0.6 m\n"
                       "[luminaire p2]\ntype = rect\nposition = 1.5, 6, 2.8 m\nluminance = 4000 cd/m2\n"
                       "width = 0.6 m\nlength = 0.6 m\n"
                       "[luminaire behind]\ntype = rect\nposition = 0, -3, 2.8 m\nluminance = 4000 cd/m2\n"
                       "width = 0.6 m\nlength = 0.6 m\n"
                       "[luminaire dot]\ntype = point\nposition = 0, 2, 2.8 m\nflux = 1000 lm\n"
                       "[receiver r]\ntype = point\nposition = 0, 0, 0 m\n"
                       "[observer eye]\nposition = 0, 0, 1.2 m\nview = 0, 1, 0\nbackground_luminance = 30 cd/m2\n";
    lx_scene *sc = NULL;
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "glare.scene", text, strlen(text), &sc));
    lx_scene_glare *g = NULL;
    lx_assert_ok(ctx, lx_scene_glare_eval(ctx, sc, &g));
    assert_int_equal(g->n_obs, 1);
    double sum = 0;
    double pos[2][3] = {{0, 3, 2.8}, {1.5, 6, 2.8}};
    for (int k = 0; k < 2; k++) {
        double dx = pos[k][0], dy = pos[k][1], dz = pos[k][2] - 1.2, d2 = dx * dx + dy * dy + dz * dz, d = sqrt(d2);
        /* a panel facing down seen from below: L = 4000, omega = A cos(theta) / d^2 with cos theta = dz / d */
        double w = 0.36 * dz / d / d2;
        double sigma = acos(dy / d) / DEG, tau = atan2(fabs(dx), dz) / DEG;
        double lnp = (35.2 - 0.31889 * tau - 1.22 * exp(-2 * tau / 9)) * 1e-3 * sigma +
                     (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma;
        double p = exp(lnp), term = 4000.0 * 4000.0 * w / (p * p);
        const lx_glare_term *t = &g->terms[k];
        assert_int_equal(t->visible, 1);
        lx_assert_near(t->luminance_cd_m2, 4000, 1e-9, 0);
        lx_assert_near(t->solid_angle_sr, w, 0, 1e-12);
        lx_assert_near(t->sigma_deg, sigma, 1e-9, 0);
        lx_assert_near(t->tau_deg, tau, 1e-9, 0);
        lx_assert_near(t->term, term, 0, 1e-12);
        sum += term;
    }
    assert_int_equal(g->terms[2].visible, 0); /* behind the eye */
    assert_int_equal(g->terms[3].visible, 0); /* a point has no luminous area */
    lx_assert_near(g->ugr[0], 8 * log10(0.25 / 30 * sum), 1e-12, 0);
    lx_scene_glare_free(g);
    lx_scene_free(sc);
    /* without a background luminance: an error naming the observer's section */
    const char *nob = "[luminaire p1]\ntype = rect\nposition = 0, 3, 2.8 m\nluminance = 4000 cd/m2\n"
                      "width = 0.6 m\nlength = 0.6 m\n[receiver r]\ntype = point\nposition = 0, 0, 0 m\n"
                      "[observer eye]\nposition = 0, 0, 1.2 m\nview = 0, 1, 0\n";
    lx_assert_ok(ctx, lx_scene_read_mem(ctx, "nob.scene", nob, strlen(nob), &sc));
    assert_int_equal(lx_scene_glare_eval(ctx, sc, &g), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 10);
    lx_scene_free(sc);
}

/* The CIE 190 table of ../shared/ies/ldt/avad_srl_isym4.ldt against eulumdat-ugr 1.0.2 (PyPI;
 * UgrCalculator.compute with pyldt's reader), which follows CIE 190 with the Guth table of CIE 117
 * (here: the Luckiesh-Guth fit) and its own luminance tables: within 0.3 UGR in every cell. */
static const double REF[19][10] = {
    {18.3, 19.8, 18.7, 20.1, 20.4, 20.2, 21.6, 20.6, 21.9, 22.2}, {19.1, 20.4, 19.5, 20.8, 21.1, 21.0, 22.2, 21.4, 22.6, 22.9},
    {19.4, 20.6, 19.8, 21.0, 21.4, 21.2, 22.4, 21.6, 22.8, 23.2}, {19.6, 20.7, 20.0, 21.1, 21.5, 21.4, 22.5, 21.8, 22.8, 23.2},
    {19.6, 20.7, 20.1, 21.1, 21.5, 21.4, 22.4, 21.8, 22.8, 23.2}, {19.6, 20.6, 20.1, 21.0, 21.4, 21.4, 22.4, 21.8, 22.8, 23.2},
    {18.8, 20.0, 19.2, 20.4, 20.8, 20.4, 21.6, 20.8, 21.9, 22.3}, {19.9, 20.8, 20.3, 21.3, 21.7, 21.3, 22.3, 21.8, 22.7, 23.2},
    {20.3, 21.1, 20.7, 21.6, 22.0, 21.7, 22.6, 22.1, 23.0, 23.4}, {20.5, 21.3, 21.0, 21.7, 22.2, 21.9, 22.7, 22.4, 23.1, 23.6},
    {20.6, 21.3, 21.0, 21.7, 22.2, 21.9, 22.6, 22.4, 23.1, 23.6}, {20.6, 21.2, 21.1, 21.7, 22.2, 21.9, 22.6, 22.4, 23.1, 23.5},
    {20.4, 21.1, 20.9, 21.6, 22.1, 21.8, 22.5, 22.2, 22.9, 23.4}, {20.8, 21.3, 21.3, 21.8, 22.3, 22.0, 22.6, 22.5, 23.1, 23.6},
    {20.9, 21.4, 21.4, 21.9, 22.4, 22.1, 22.6, 22.6, 23.1, 23.6}, {20.9, 21.4, 21.4, 21.9, 22.4, 22.1, 22.6, 22.6, 23.1, 23.7},
    {20.4, 21.1, 20.9, 21.5, 22.0, 21.7, 22.4, 22.2, 22.9, 23.3}, {20.8, 21.3, 21.3, 21.8, 22.3, 22.0, 22.5, 22.6, 23.0, 23.6},
    {20.9, 21.4, 21.4, 21.9, 22.4, 22.1, 22.6, 22.6, 23.1, 23.6},
};

static void test_cie190_table(void **state)
{
    lx_ctx *ctx = *state;
    const char *shared = getenv("LX_SHARED_DIR");
    char path[1024];
    if (!shared) skip();
    snprintf(path, sizeof path, "%s/ies/ldt/avad_srl_isym4.ldt", shared);
    FILE *f = fopen(path, "rb");
    if (!f) skip();
    fclose(f);
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_read_file(ctx, path, &lum));
    lx_ugr_table tab;
    lx_assert_ok(ctx, lx_ugr_table_compute(ctx, lum, &tab));
    static const double X[19] = {2, 2, 2, 2, 2, 2, 4, 4, 4, 4, 4, 4, 8, 8, 8, 8, 12, 12, 12};
    static const double Y[19] = {2, 3, 4, 6, 8, 12, 2, 3, 4, 6, 8, 12, 4, 6, 8, 12, 4, 6, 8};
    for (int r = 0; r < 19; r++) {
        assert_true(tab.x_h[r] == X[r] && tab.y_h[r] == Y[r]);
        for (int c = 0; c < 10; c++) lx_assert_near(tab.ugr[r][c], REF[r][c], 0.3, 0);
    }
    lx_assert_near(tab.lamp_flux_lm, 3673, 1e-9, 0);
    /* the background: brighter ceilings and walls raise Lb and lower UGR */
    assert_true(tab.lb_cd_m2[10][0] > tab.lb_cd_m2[10][4] && tab.ugr[10][0] < tab.ugr[10][4]);
    lx_luminaire_free(lum);
}

/* A luminaire without a luminous opening cannot have a UGR table. */
static void test_no_area(void **state)
{
    lx_ctx *ctx = *state;
    lx_lum_model m;
    memset(&m, 0, sizeof m);
    m.kind = LX_LUM_MODEL_LAMBERT, m.flux_lm = 3000;
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_from_model(ctx, &m, &lum));
    lx_ugr_table tab;
    assert_int_equal(lx_ugr_table_compute(ctx, lum, &tab), LX_EINVAL);
    lx_luminaire_free(lum);
    /* with an opening 0.6 x 0.6 m a Lambertian panel's luminance is F / (pi A) at every angle:
     * the table depends on the projected area only through L */
    m.width_m = m.length_m = 0.6;
    lx_assert_ok(ctx, lx_luminaire_from_model(ctx, &m, &lum));
    lx_assert_ok(ctx, lx_ugr_table_compute(ctx, lum, &tab));
    /* a Lambertian panel is the same crosswise and endwise */
    for (int r = 0; r < 19; r++)
        for (int c = 0; c < 5; c++) lx_assert_near(tab.ugr[r][c], tab.ugr[r][5 + c], 1e-6, 0);
    lx_assert_near(lx_luminaire_projected_area(lum, 0.6, 0, -0.8), 0.36 * 0.8, 1e-12, 0);
    lx_luminaire_free(lum);
}

/* The matrix text: a made-up table whose cell (r, c) is r + c / 10 + 0.04, so each printed cell
 * names its own place; NaN prints "-". */
static void test_table_text(void **state)
{
    lx_ctx *ctx = *state;
    lx_ugr_table tab;
    memset(&tab, 0, sizeof tab);
    static const double X[19] = {2, 2, 2, 2, 2, 2, 4, 4, 4, 4, 4, 4, 8, 8, 8, 8, 12, 12, 12};
    static const double Y[19] = {2, 3, 4, 6, 8, 12, 2, 3, 4, 6, 8, 12, 4, 6, 8, 12, 4, 6, 8};
    for (int r = 0; r < 19; r++) {
        tab.x_h[r] = X[r], tab.y_h[r] = Y[r];
        for (int c = 0; c < 10; c++) tab.ugr[r][c] = 10 + r + c / 10.0 + 0.04;
    }
    tab.ugr[18][9] = NAN;
    char *text = NULL;
    lx_assert_ok(ctx, lx_ugr_table_text(ctx, &tab, &text));
    assert_non_null(strstr(text, "reflectances\n  ceiling         0.70  0.70  0.50  0.50  0.30     0.70  0.70  0.50  0.50  0.30\n"));
    assert_non_null(strstr(text, "\n          2H  2H  10.0  10.1  10.2  10.3  10.4     10.5  10.6  10.7  10.8  10.9\n"));
    assert_non_null(strstr(text, "\n              3H  11.0  11.1"));      /* X only on the first line of its group */
    assert_non_null(strstr(text, "\n         12H  4H  26.0"));
    assert_non_null(strstr(text, "28.8     -\n"));                      /* the NaN */
    size_t lines = 0, widest = 0, w = 0;
    for (const char *s = text; *s; s++) {
        if (*s == '\n') lines++, widest = w > widest ? w : widest, w = 0;
        else w++;
    }
    assert_int_equal(lines, 4 + 2 + 19); /* reflectances (4), blank and heads (2), 19 rooms */
    assert_true(widest <= 79);
    lx_text_free(text);
    assert_int_equal(lx_ugr_table_text(ctx, NULL, &text), LX_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_formula, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_position_index, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_scene_observer, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_cie190_table, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_no_area, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_table_text, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
