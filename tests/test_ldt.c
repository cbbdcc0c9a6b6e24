/* test_ldt.c - the EULUMDAT reader: every Isym (0-4) expanded to the same full distribution,
 * cd/klm scaling by the first lamp set (several sets), mm dimensions, absolute photometry, and the
 * ../shared twins (the same luminaire as IES and LDT gives the same flux). */
#include "lx_test.h"

#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

/* The reference distribution: I(C, g) = 100 + 40 cos(2C)... sampled on planes every 30 deg, which
 * is symmetric about both C0-C180 and C90-C270, so every Isym can store it. Gamma 0, 90, 180:
 * the value is (100 + 40 cos 2C) at gamma 0 and 90 and 0 at 180. cd/klm. */
static double ref(double c_deg, double g_deg) { return g_deg >= 180 ? 0 : 100 + 40 * cos(2 * c_deg * DEG); }

static char *make_ldt(int isym, int nsets, int lamps, double flux)
{
    static char buf[8192];
    int mc = 12, ng = 3;
    char *p = buf;
    p += sprintf(p, "Test company\n1\n%d\n%d\n30\n%d\n90\nreport\nname\nnumber\nfile\ndate\n"
                    "1000\n500\n50\n600\n300\n20\n20\n20\n20\n100\n80\n1\n0\n%d\n", isym, mc, ng, nsets);
    for (int k = 0; k < nsets; k++)
        p += sprintf(p, "%d\nLED\n%g\n3000\n80\n10\n", lamps, k == 0 ? flux : 2 * flux);
    for (int k = 0; k < 10; k++) p += sprintf(p, "0.5\n");
    for (int i = 0; i < mc; i++) p += sprintf(p, "%d\n", 30 * i);
    p += sprintf(p, "0\n90\n180\n");
    int first = 0, count = mc;
    if (isym == 1) count = 1;
    if (isym == 2) count = mc / 2 + 1;
    if (isym == 3) first = 3 * mc / 4, count = mc / 2 + 1;
    if (isym == 4) count = mc / 4 + 1;
    for (int k = 0; k < count; k++) {
        int c = 30 * ((first + k) % mc);
        for (int j = 0; j < ng; j++) {
            double v = isym == 1 ? ref(0, 90 * j) : ref(c, 90 * j);
            p += sprintf(p, "%.17g\n", v);
        }
    }
    return buf;
}

static void test_isym_all(void **state)
{
    lx_ctx *ctx = *state;
    lx_luminaire *full = NULL;
    const char *t0 = make_ldt(0, 1, 1, 2000);
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "isym0.ldt", t0, strlen(t0), &full));
    assert_int_equal(full->symmetry, LX_SYM_NONE);
    /* cd = cd/klm x 2000 lm / 1000 */
    lx_assert_near(lx_luminaire_intensity(full, LX_INTERP_BILINEAR, 60 * DEG, 0), 2 * ref(60, 0), 0, 1e-13);
    lx_assert_near(full->length_m, 0.6, 0, 1e-15); /* 600 mm luminous length, along C0-C180 */
    lx_assert_near(full->width_m, 0.3, 0, 1e-15);  /* 300 mm luminous width, along C90-C270 */
    lx_assert_near(full->stated_lumens, 2000 * 0.8, 0, 1e-12); /* lamps x LORL 80 % */
    static const lx_lum_symmetry want[5] = {LX_SYM_NONE, LX_SYM_AXIAL, LX_SYM_C0_C180, LX_SYM_C90_C270, LX_SYM_QUADRANT};
    for (int isym = 2; isym <= 4; isym++) {
        lx_luminaire *l = NULL;
        const char *t = make_ldt(isym, 1, 1, 2000);
        lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "isym.ldt", t, strlen(t), &l));
        assert_int_equal(l->symmetry, want[isym]);
        /* the expanded table equals the full one everywhere (the data are doubly symmetric) */
        for (double c = 0; c < 360; c += 7.5)
            for (double g = 0; g <= 180; g += 15)
                lx_assert_near(lx_luminaire_intensity(l, LX_INTERP_BILINEAR, c * DEG, g * DEG),
                               lx_luminaire_intensity(full, LX_INTERP_BILINEAR, c * DEG, g * DEG), 1e-12, 1e-13);
        lx_luminaire_free(l);
    }
    lx_luminaire *ax = NULL;
    const char *t1 = make_ldt(1, 1, 1, 2000);
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "isym1.ldt", t1, strlen(t1), &ax));
    assert_int_equal(ax->symmetry, LX_SYM_AXIAL);
    /* axial: 2 x (100 + 40) cd at gamma 0, 90; linear to 0 at 180. Flux = 2 pi x 280 x
     * [int_0^{pi/2} sin + int_{pi/2}^{pi} (2 - 2g/pi) sin g dg] = 2 pi 280 (1 + (2 - 2/pi x ... ))
     * int_{pi/2}^{pi} (2 - 2g/pi) sin g dg = 2 [ -cos ]_{pi/2}^{pi} - (2/pi)[sin g - g cos g]_{pi/2}^{pi}
     * = 2 - (2/pi)(pi - 1) = 2/pi; so flux = 2 pi 280 (1 + 2/pi) = 560 pi + 1120 */
    lx_lum_summary s;
    lx_assert_ok(ctx, lx_luminaire_summary(ctx, ax, &s));
    lx_assert_near(s.lumens, 560 * PI + 1120, 0, 1e-13);
    lx_luminaire_free(ax);
    lx_luminaire_free(full);
}

/* Several lamp sets: intensities refer to the first (standard) set; a negative lamp count is
 * absolute photometry whose flux is the luminaire's. */
static void test_lamp_sets_absolute(void **state)
{
    lx_ctx *ctx = *state;
    lx_luminaire *l = NULL;
    const char *t = make_ldt(1, 3, 2, 1500);
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "sets.ldt", t, strlen(t), &l));
    lx_assert_near(l->cd[0], 140 * 1.5, 0, 1e-13); /* 140 cd/klm x 1500 lm / 1000 */
    assert_int_equal(l->n_lamps, 2);
    lx_assert_near(l->lamp_lumens, 1500, 0, 0);
    lx_luminaire_free(l);
    t = make_ldt(1, 1, -1, 321);
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "abs.ldt", t, strlen(t), &l));
    assert_true(l->absolute);
    lx_assert_near(l->stated_lumens, 321, 0, 0);
    lx_luminaire_free(l);
}

static void test_malformed_ldt(void **state)
{
    lx_ctx *ctx = *state;
    char t[8192];
    strcpy(t, make_ldt(4, 1, 1, 1000));
    /* Isym 4 with Mc = 12 stores 4 planes x 3 = 12 values; append one: data after the table */
    strcat(t, "5\n");
    lx_luminaire *l = NULL;
    assert_int_equal(lx_luminaire_read_mem(ctx, "x.ldt", t, strlen(t), &l), LX_EPARSE);
    strcpy(t, make_ldt(2, 1, 1, 1000));
    char *neg = strstr(t + strlen(t) - 40, "\n140\n");
    assert_non_null(neg);
    neg[1] = '-';
    assert_int_equal(lx_luminaire_read_mem(ctx, "x.ldt", t, strlen(t), &l), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "negative"));
    assert_null(l);
}

/* make_ldt's text with line `line` (1-based) replaced by `with`, into out. */
static void replace_line(char *out, size_t cap, const char *text, int line, const char *with)
{
    const char *p = text;
    for (int i = 1; i < line; i++) p = strchr(p, '\n') + 1;
    const char *q = strchr(p, '\n');
    snprintf(out, cap, "%.*s%s%s", (int)(p - text), text, with, q);
}

/* Bad lamp sets, C angles, Isym against Mc and intensities: the status, the line named and the
 * message. make_ldt's layout (one lamp set, Mc 12, Ng 3): Isym on line 3, Mc 4, the lamp set
 * 27-32 (lamps 27, flux 29), direct ratios 33-42, C angles 43-54, gamma 55-57, intensities from 58. */
static void test_malformed_ldt_fields(void **state)
{
    lx_ctx *ctx = *state;
    static const struct {
        int isym, line;
        const char *with;
        long err_line;
        const char *fragment;
    } cases[] = {
        {1, 27, "0", 27, "the number of lamps must be a non-zero whole number of at most"},
        {1, 27, "1.5", 27, "the number of lamps must be a non-zero whole number"},
        {1, 29, "0", 29, "the lamps' luminous flux must be positive (got 0 lm)"},
        {1, 44, "0", 44, "C angles out of order (0 after 0)"},
        {1, 43, "10", 43, "the C angles must run from 0 to below 360 (got 10..330)"},
        {2, 4, "11", 3, "Isym 2 needs an even number of C-planes (Mc = 11)"},
        {3, 4, "6", 3, "Isym 3 needs a number of C-planes divisible by 4 (Mc = 6)"},
        {4, 4, "6", 3, "Isym 4 needs a number of C-planes divisible by 4 (Mc = 6)"},
        {1, 59, "-5", 59, "negative luminous intensity -5 cd/klm"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char t[8192];
        replace_line(t, sizeof t, make_ldt(cases[i].isym, 1, 1, 1000), cases[i].line, cases[i].with);
        lx_luminaire *l = (lx_luminaire *)1;
        lx_status st = lx_luminaire_read_mem(ctx, "f.ldt", t, strlen(t), &l);
        if (st != LX_EPARSE || lx_ctx_errline(ctx) != cases[i].err_line || !strstr(lx_ctx_errmsg(ctx), cases[i].fragment))
            print_error("case %zu: status %d line %ld '%s'\n", i, st, lx_ctx_errline(ctx), lx_ctx_errmsg(ctx));
        assert_int_equal(st, LX_EPARSE);
        assert_int_equal(lx_ctx_errline(ctx), cases[i].err_line);
        assert_non_null(strstr(lx_ctx_errmsg(ctx), cases[i].fragment));
        assert_null(l);
    }
}

/* ../shared twins: the LDT and IES files of one luminaire hold the same table; the fluxes agree
 * to the rounding of the candela values in the two files (0.1 % bound). */
static void test_twins(void **state)
{
    lx_ctx *ctx = *state;
    const char *dir = lx_test_shared_dir();
    if (!dir) skip();
    const char *pairs[3][2] = {{"ldt/bega_50975_isym1.ldt", "08_bega_50975_axial_lm95.ies"},
                               {"ldt/erco_33499000_isym2.ldt", "09_erco_33499000_bilateral_lm95.ies"},
                               {"ldt/avad_srl_isym4.ldt", "10_avad_srl_quadrant_lm95.ies"}};
    for (int i = 0; i < 3; i++) {
        char a[1024], b[1024];
        snprintf(a, sizeof a, "%s/ies/%s", dir, pairs[i][0]);
        snprintf(b, sizeof b, "%s/ies/%s", dir, pairs[i][1]);
        lx_luminaire *la = NULL, *lb = NULL;
        if (lx_luminaire_read_file(ctx, a, &la) == LX_EIO) skip();
        assert_non_null(la);
        lx_assert_ok(ctx, lx_luminaire_read_file(ctx, b, &lb));
        lx_lum_summary sa, sb;
        lx_assert_ok(ctx, lx_luminaire_summary(ctx, la, &sa));
        lx_assert_ok(ctx, lx_luminaire_summary(ctx, lb, &sb));
        assert_int_equal(la->symmetry, lb->symmetry);
        lx_assert_near(sa.lumens, sb.lumens, 0, 1e-3);
        print_message("%s: %.3f lm, %s: %.3f lm\n", pairs[i][0], sa.lumens, pairs[i][1], sb.lumens);
        lx_luminaire_free(la);
        lx_luminaire_free(lb);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_isym_all),
        cmocka_unit_test(test_lamp_sets_absolute),
        cmocka_unit_test(test_malformed_ldt),
        cmocka_unit_test(test_malformed_ldt_fields),
        cmocka_unit_test(test_twins),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
