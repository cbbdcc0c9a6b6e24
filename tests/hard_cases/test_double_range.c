/* test_double_range.c - values at the top of the double range (issue 22): spectra at 1e300 and
 * 1e305 at fine steps whose partial sums overflow although the integral does not, spectra whose
 * integrals really overflow (an error naming the quantity, never an infinity handed on), NaN
 * results reported with their quantity, luminaire flux, grid means, disk illuminance. The oracle is
 * linearity: every integral here is linear in the values, so at 1e300 x S it must be 1e300 x the
 * integral of S (relative 1e-13: a power of ten is not exact in binary); overflow is decided by the
 * exact size of the result (DBL_MAX = 1.797e308). */
#include "lx_test.h"

#include <float.h>
#include <string.h>

/* D65 at 5 nm, 380-780 nm, times k. */
static lx_spd d65_times(lx_ctx *ctx, double k, double *lam, double *v)
{
    lx_spd d;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &d));
    size_t n = 0;
    for (size_t i = 0; i < d.n; i++)
        if (d.lambda_nm[i] >= 380 && d.lambda_nm[i] <= 780 && fmod(d.lambda_nm[i], 5) == 0) {
            lam[n] = d.lambda_nm[i];
            v[n] = k * d.value[i];
            n++;
        }
    return (lx_spd){"d65", n, lam, v};
}

/* 1e300 x D65 computes: X, Y, Z, radiant and scotopic_Y are 1e300 x D65's, the chromaticities,
 * CCT and efficacy D65's (the three methods). */
static void spectrum_at_1e300(void **state)
{
    lx_ctx *ctx = *state;
    double l1[200], v1[200], l2[200], v2[200];
    lx_spd a = d65_times(ctx, 1.0, l1, v1), b = d65_times(ctx, 1e300, l2, v2);
    assert_int_equal(a.n, 81);
    lx_method methods[] = {LX_METHOD_CIE15, LX_METHOD_EXACT, LX_METHOD_LINEAR1NM};
    for (int m = 0; m < 3; m++) {
        lx_colorimetry ra, rb;
        lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &a, LX_OBSERVER_2, methods[m], &ra));
        lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &b, LX_OBSERVER_2, methods[m], &rb));
        lx_assert_ok(ctx, lx_colorimetry_check(ctx, &rb, 1e300 * 117.812));
        lx_assert_near(rb.X, 1e300 * ra.X, 0, 1e-13);
        lx_assert_near(rb.Y, 1e300 * ra.Y, 0, 1e-13);
        lx_assert_near(rb.Z, 1e300 * ra.Z, 0, 1e-13);
        lx_assert_near(rb.radiant, 1e300 * ra.radiant, 0, 1e-13);
        lx_assert_near(rb.scotopic_Y, 1e300 * ra.scotopic_Y, 0, 1e-13);
        lx_assert_near(rb.x, ra.x, 1e-15, 0);
        lx_assert_near(rb.y, ra.y, 1e-15, 0);
        lx_assert_near(rb.u_prime, ra.u_prime, 1e-15, 0);
        lx_assert_near(rb.cct_K, ra.cct_K, 1e-8, 0);
        lx_assert_near(rb.ler_lm_per_W, ra.ler_lm_per_W, 0, 1e-13);
        lx_assert_near(rb.sp_ratio, ra.sp_ratio, 0, 1e-13);
    }
}

/* 1e305 flat over 380-780 nm at 0.01 nm: 40001 samples. The CIE 015 sum of v x ybar is 1.07e309
 * before its 0.01 nm step, the batch path's trapezoid sum of (v_i + v_i+1) 8e309 before its
 * 0.005 nm factor (both beyond DBL_MAX), but the integrals are 1e305 x those of 1: Y = 1.07e307,
 * radiant = 1e305 x 400 nm = 4e307. */
static void partial_sums_overflow(void **state)
{
    lx_ctx *ctx = *state;
    size_t n = 40001;
    double *lam = malloc(n * sizeof *lam), *one = malloc(n * sizeof *one), *big = malloc(n * sizeof *big);
    assert_non_null(lam), assert_non_null(one), assert_non_null(big);
    for (size_t i = 0; i < n; i++) lam[i] = 380 + 0.01 * (double)i, one[i] = 1, big[i] = 1e305;
    lx_spd s1 = {"one", n, lam, one}, sb = {"big", n, lam, big};
    double r1, rb;
    lx_assert_ok(ctx, lx_spd_integrate_radiant(ctx, &s1, LX_METHOD_EXACT, &r1));
    lx_assert_ok(ctx, lx_spd_integrate_radiant(ctx, &sb, LX_METHOD_EXACT, &rb));
    lx_assert_near(r1, 400, 1e-9, 0);
    lx_assert_near(rb, 4e307, 0, 1e-12);
    lx_spd y;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &y));
    double y1, yb;
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s1, &y, LX_METHOD_CIE15, &y1));
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &sb, &y, LX_METHOD_CIE15, &yb));
    lx_assert_near(yb, 1e305 * y1, 0, 1e-13);
    assert_true(isfinite(yb) && yb > 1e307);
    /* the batch path: its radiant sum the same way */
    lx_batch b = {1, n, 0, 380, 0.01, LX_F64, big};
    lx_colorimetry r;
    lx_batch_opts o = {.backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_batch_colorimetry(ctx, &b, LX_OBSERVER_2, &o, &r));
    lx_assert_near(r.radiant, 4e307, 0, 1e-12);
    free(lam), free(one), free(big);
}

/* Integrals that leave the double range: 1e308 x ybar summed is 1e308 x 106.9 (> DBL_MAX); a
 * flat 1e306 over 400 nm has a radiant integral of 4e308. Errors name the quantity. */
static void integrals_overflow(void **state)
{
    lx_ctx *ctx = *state;
    double lam[81], v[81];
    for (int i = 0; i < 81; i++) lam[i] = 380 + 5 * i, v[i] = 1e308;
    lx_spd s = {"a", 81, lam, v};
    lx_colorimetry r;
    memset(&r, 0x5a, sizeof r);
    lx_colorimetry before = r;
    assert_int_equal(lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &r), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "integral overflows: values up to 1e308 give X beyond the double range"));
    assert_memory_equal(&r, &before, sizeof r); /* outputs untouched on failure */
    for (int i = 0; i < 81; i++) v[i] = 1e306;
    assert_int_equal(lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &r), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "values up to 1e306 give radiant beyond"));
    double out;
    assert_int_equal(lx_spd_integrate_radiant(ctx, &s, LX_METHOD_AUTO, &out), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "integral overflows: values up to 1e306"));
    /* the batch path hands the infinity on; the check before printing refuses it */
    lx_batch b = {1, 81, 0, 380, 5, LX_F64, v};
    lx_batch_opts o = {.backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_batch_colorimetry(ctx, &b, LX_OBSERVER_2, &o, &r));
    assert_int_equal(lx_colorimetry_check(ctx, &r, 1e306), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "integral overflows: values up to 1e306 give X beyond the double range"));
    assert_int_equal(lx_colorimetry_check(ctx, &r, NAN), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "integral overflows: X is beyond the double range"));
}

/* Chromaticities of finite X, Y, Z whose sums overflow: X = Y = Z = 683 x 1e305 = 6.8e307 sum to
 * 2e308; x = y = 1/3, u' = 4/19, v' = 9/19 exactly as for any equal-energy triple. */
static void chromaticity_near_the_top(void **state)
{
    lx_ctx *ctx = *state;
    double xyz[3] = {1e305, 1e305, 1e305};
    lx_colorimetry r;
    r.method = LX_METHOD_CIE15;
    lx_assert_ok(ctx, lx_colorimetry_from_integrals(ctx, LX_OBSERVER_2, xyz, 1e305, 1e305, &r));
    lx_assert_ok(ctx, lx_colorimetry_check(ctx, &r, NAN));
    lx_assert_near(r.x, 1.0 / 3, 1e-16, 0);
    lx_assert_near(r.y, 1.0 / 3, 1e-16, 0);
    lx_assert_near(r.u_prime, 4.0 / 19, 1e-16, 0);
    lx_assert_near(r.v_prime, 9.0 / 19, 1e-16, 0);
}

/* NaN results are reported with the quantity and its cause (a spectrum without luminous content). */
static void nan_results_named(void **state)
{
    lx_ctx *ctx = *state;
    double lam[3] = {400, 500, 600}, v[3] = {0, 0, 0};
    lx_spd s = {"dark", 3, lam, v};
    lx_colorimetry r;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_EXACT, &r)); /* documented: NaN, no error */
    assert_true(isnan(r.x));
    assert_int_equal(lx_colorimetry_check(ctx, &r, 0), LX_ERANGE);
    assert_string_equal(lx_ctx_errmsg(ctx), "x is undefined (NaN): X + Y + Z = 0 (no luminous content)");
    double ok_lam[3] = {400, 550, 700}, ok_v[3] = {1, 1, 1};
    lx_spd g = {"flat", 3, ok_lam, ok_v};
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &g, LX_OBSERVER_2, LX_METHOD_EXACT, &r));
    lx_assert_ok(ctx, lx_colorimetry_check(ctx, &r, 1));
    r.sp_ratio = NAN;
    assert_int_equal(lx_colorimetry_check(ctx, &r, 1), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "sp_ratio is undefined (NaN)"));
}

/* An IES table with 1e308 cd at the nadir falling to 0 at 45 deg: each cell's corner sum (2e308)
 * overflows, the flux 2 pi 1e308 (1 - sin(pi/4)/(pi/4)) = 6.2634e307 does not. The same table at
 * 100 cd gives the reference (linearity). All of it at 1e308 overflows for real (4 pi 1e308). */
static const char ies_fmt[] = "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 2 1 2 0 0 0\n1 1 10\n0 45 90\n0 90\n%s\n%s\n";

static void luminaire_flux_near_the_top(void **state)
{
    lx_ctx *ctx = *state;
    char text[512];
    lx_luminaire *l = NULL;
    lx_lum_summary s100, sbig;
    snprintf(text, sizeof text, ies_fmt, "100 0 0", "100 0 0");
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "small.ies", text, strlen(text), &l));
    lx_assert_ok(ctx, lx_luminaire_summary(ctx, l, &s100));
    lx_luminaire_free(l);
    lx_assert_near(s100.lumens, 2 * M_PI * 100 * (1 - sin(M_PI / 4) / (M_PI / 4)), 0, 1e-12);
    snprintf(text, sizeof text, ies_fmt, "1e308 0 0", "1e308 0 0");
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "big.ies", text, strlen(text), &l));
    lx_assert_ok(ctx, lx_luminaire_summary(ctx, l, &sbig));
    lx_luminaire_free(l);
    lx_assert_near(sbig.lumens, 1e306 * s100.lumens, 0, 1e-13);
    lx_assert_near(sbig.downward_fraction, s100.downward_fraction, 1e-15, 0);
    snprintf(text, sizeof text, ies_fmt, "1e308 1e308 1e308", "1e308 1e308 1e308");
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "huge.ies", text, strlen(text), &l));
    assert_int_equal(lx_luminaire_summary(ctx, l, &sbig), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "huge.ies: integral overflows: candela values up to 1e308 give lumens"));
    lx_grid_stats gs;
    double E[3] = {1e308, 1.5e308, 1.7e308}; /* their sum 4.2e308, their mean 1.4e308 */
    lx_assert_ok(ctx, lx_grid_stats_compute(ctx, E, 3, &gs));
    lx_assert_near(gs.avg, 1.4e308, 0, 1e-15);
    lx_assert_near(gs.u0, 1e308 / 1.4e308, 0, 1e-15);
    /* a point 1 mm under 1e308 cd: E = 1e308 / 1e-6 is beyond the range: refused with the point */
    lx_placement pl = {.lum = l, .pos_m = {0, 0, 1e-3}, .aim = {0, 0, -1}};
    double pt[3] = {0, 0, 0}, nrm[3] = {0, 0, 1}, e1;
    lx_grid_opts go = {.model = LX_MODEL_POINT, .backend = LX_BACKEND_CPU};
    assert_int_equal(lx_grid_illuminance(ctx, &pl, 1, pt, 1, nrm, 1, &go, &e1), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "illuminance at point 1 (0, 0, 0 m) is infinite"));
    lx_luminaire_free(l);
}

/* A Lambertian disk of 1e308 cd/m2, R = 0.5 m, 1 m above on its axis: E = pi L R^2 / (h^2 + R^2)
 * = 6.2832e307, although pi L alone is beyond the range; 1 mm above, E = 3.1e308 is refused. */
static void disk_near_the_top(void **state)
{
    lx_ctx *ctx = *state;
    lx_source_result r;
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1e308, 0.5, 1, 0, LX_MODEL_AUTO, &r));
    lx_assert_near(r.exact_lx, M_PI * 0.25 / 1.25 * 1e308, 0, 1e-14);
    lx_assert_near(r.point_lx, M_PI * 0.25 * 1e308, 0, 1e-14);
    assert_int_equal(lx_disk_illuminance(ctx, 1e308, 0.5, 1e-3, 0, LX_MODEL_AUTO, &r), LX_ERANGE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "the exact illuminance overflows (luminance 1e308 cd/m2)"));
    assert_int_equal(lx_rect_illuminance(ctx, 1e308, 1, 1, 1e-3, 0, 0, LX_MODEL_AUTO, &r), LX_ERANGE);
}

/* The bottom of the range: D65 times 2^-1060 (subnormal: about 14 bits of mantissa) and times 1e-300
 * (normal, but its products with the weights and CRI's 100 / Y leave the normal range). The results
 * follow from D65's by the same oracle, linearity: chromaticities, CCT, efficacy, CRI, TM-30 and DER
 * are scale-free and must equal D65's (1e-12); X, Y, Z, radiant and the alpha-opic irradiances are
 * D65's times the factor, rounded once (the subnormal ulp 4.9e-324 of the result). Before, every
 * product was rounded to the subnormal grid: a flat 1e-320 moved xy by 1.5e-5 and CRI and TM-30
 * were NaN. The batch path likewise (its rows of such values go through the scaled path). */
static void spectrum_near_the_bottom(void **state)
{
    lx_ctx *ctx = *state;
    double l1[200], v1[200], l2[200], v2[200];
    lx_spd a = d65_times(ctx, 1.0, l1, v1);
    const double k[2] = {ldexp(1.0, -1060), 1e-300};
    for (int q = 0; q < 2; q++) {
        lx_spd b = d65_times(ctx, k[q], l2, v2);
        for (size_t i = 0; i < b.n; i++) v2[i] = k[q] * v1[i]; /* k times each value, as the file would hold it */
        /* the reference: the same values (subnormals hold only 14 bits of D65's: a slightly other
         * spectrum) times 2^1060 or 2^997, exactly, computed in the normal range */
        static double v3[200];
        int up = q == 0 ? 1060 : 997;
        for (size_t i = 0; i < b.n; i++) v3[i] = ldexp(v2[i], up);
        lx_spd a3 = {"d65 again", b.n, l2, v3};
        double kk = q == 0 ? k[0] : ldexp(1.0, -up); /* b = kk x a3, exactly */
        lx_colorimetry ra, rb, rd;
        lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &a, LX_OBSERVER_2, LX_METHOD_CIE15, &rd));
        lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &a3, LX_OBSERVER_2, LX_METHOD_CIE15, &ra));
        lx_assert_near(ra.x, rd.x, q == 0 ? 1e-6 : 1e-14, 0); /* and that is D65 to its rounding */
        lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &b, LX_OBSERVER_2, LX_METHOD_CIE15, &rb));
        lx_assert_near(rb.x, ra.x, 1e-14, 0);
        lx_assert_near(rb.y, ra.y, 1e-14, 0);
        lx_assert_near(rb.u_prime, ra.u_prime, 1e-14, 0);
        lx_assert_near(rb.cct_K, ra.cct_K, 0, 1e-12);
        lx_assert_near(rb.ler_lm_per_W, ra.ler_lm_per_W, 0, 1e-12);
        /* absolute values: the reference's times kk, rounded once (2^-1060 x 7e4: 1e-9 relative) */
        double tol = q == 0 ? 1e-9 : 1e-15;
        lx_assert_near(rb.Y, kk * ra.Y, 0, tol);
        lx_assert_near(rb.radiant, kk * ra.radiant, 0, tol);
        lx_cri ca, cb;
        lx_assert_ok(ctx, lx_cri_compute(ctx, &a3, &ca));
        lx_assert_ok(ctx, lx_cri_compute(ctx, &b, &cb));
        lx_assert_near(cb.ra, ca.ra, 1e-9, 0);
        lx_assert_near(cb.r[8], ca.r[8], 1e-9, 0);
        static lx_tm30 ta, tb;
        lx_assert_ok(ctx, lx_tm30_compute(ctx, &a3, &ta));
        lx_assert_ok(ctx, lx_tm30_compute(ctx, &b, &tb));
        lx_assert_near(tb.rf, ta.rf, 1e-9, 0);
        lx_assert_near(tb.rg, ta.rg, 1e-9, 0);
        lx_alphaopic aa, ab;
        lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &a3, LX_METHOD_CIE15, &aa));
        lx_assert_ok(ctx, lx_alphaopic_compute(ctx, &b, LX_METHOD_CIE15, &ab));
        lx_assert_near(ab.der[4], aa.der[4], 0, 1e-12);
        lx_assert_near(ab.irradiance[4], kk * aa.irradiance[4], 0, tol);
        /* the batch path: the same row among ordinary ones */
        double rows[3 * 81];
        for (int r = 0; r < 3; r++)
            for (size_t i = 0; i < 81; i++) rows[r * 81 + i] = r == 1 ? v2[i] : v1[i];
        lx_batch bt = {3, 81, 0, 380, 5, LX_F64, rows};
        lx_colorimetry out[3];
        lx_assert_ok(ctx, lx_batch_colorimetry(ctx, &bt, LX_OBSERVER_2, NULL, out));
        lx_assert_near(out[1].x, ra.x, 1e-14, 0);
        lx_assert_near(out[1].y, ra.y, 1e-14, 0);
        lx_assert_near(out[1].Y, kk * ra.Y, 0, tol);
        lx_assert_near(out[0].x, rd.x, 1e-14, 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(spectrum_at_1e300, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(partial_sums_overflow, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(integrals_overflow, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(chromaticity_near_the_top, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(nan_results_named, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(luminaire_flux_near_the_top, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(disk_near_the_top, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(spectrum_near_the_bottom, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
