/* test_colorimetry.c - integration methods, XYZ/xy/CCT/Duv/efficacy against CIE 015 published
 * values, closed forms and colour-science 0.4.7; Planck and daylight spectra; dominant wavelength
 * and purity (colour-science 0.4.7); peak, FWHM and the noise measure (closed forms). */
#include "lx_test.h"

#include <string.h>

static lx_colorimetry colorimetry_of(lx_ctx *ctx, const lx_spd *s, lx_method m)
{
    lx_colorimetry c;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, s, LX_OBSERVER_2, m, &c));
    return c;
}

/* CIE 015:2018 Table T.3/T.8 (2 deg chromaticities of the standard and fluorescent illuminants),
 * computed by the CIE from the 5 nm tables; the default method must reproduce them within 5e-5. */
static void test_cie15_chromaticities(void **state)
{
    lx_ctx *ctx = *state;
    static const struct {
        const char *name;
        double x, y;
    } ref[] = {
        {"A", 0.44757, 0.40745},  {"D65", 0.31271, 0.32902}, {"D50", 0.34567, 0.35850},
        {"FL2", 0.3721, 0.3751},  {"FL7", 0.3129, 0.3292},   {"FL11", 0.3805, 0.3769},
    };
    for (size_t i = 0; i < sizeof ref / sizeof *ref; i++) {
        lx_spd s;
        lx_assert_ok(ctx, lx_illuminant_get(ctx, ref[i].name, &s));
        assert_int_equal(lx_method_resolve(&s, LX_METHOD_AUTO), LX_METHOD_CIE15); /* 5 nm on whole nm */
        lx_colorimetry c = colorimetry_of(ctx, &s, LX_METHOD_AUTO);
        lx_assert_near(c.x, ref[i].x, 5e-5, 0);
        lx_assert_near(c.y, ref[i].y, 5e-5, 0);
    }
}

/* A 532 nm laser line: a triangle 0.2 nm wide (531.9, 532.0, 532.1 nm), peak 1 W/nm, sampled every
 * 0.1 nm from 520 to 545 nm. Analytic Y: ybar is piecewise linear between the 1 nm rows, and the
 * integral of a linear function against a triangle half is its area (0.05) times the function at
 * the half's centroid (531.9 + 2/3 * 0.1 and 532.1 - 2/3 * 0.1). */
static void test_laser_line(void **state)
{
    lx_ctx *ctx = *state;
    double wl[251], v[251];
    for (int i = 0; i < 251; i++) {
        wl[i] = 520.0 + 0.1 * i;
        v[i] = 0;
    }
    v[120] = 1.0; /* 532.0 nm */
    lx_spd s = {"laser", 251, wl, v}, ybar;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &ybar));
    double y531 = ybar.value[531 - 360], y532 = ybar.value[532 - 360], y533 = ybar.value[533 - 360];
    double yl = y531 + (y532 - y531) * (0.9 + 0.2 / 3.0); /* ybar(531.9667) */
    double yr = y532 + (y533 - y532) * (0.1 / 3.0);       /* ybar(532.0333) */
    double analytic = 683.002 * 0.05 * (yl + yr);
    lx_colorimetry exact = colorimetry_of(ctx, &s, LX_METHOD_EXACT);
    lx_colorimetry autom = colorimetry_of(ctx, &s, LX_METHOD_AUTO);
    assert_int_equal(autom.method, LX_METHOD_EXACT); /* 0.1 nm step: auto picks exact */
    lx_assert_near(exact.Y, analytic, 0, 1e-5);
    lx_assert_near(autom.Y, analytic, 0, 1e-5);
    /* the radiant integral is the triangle's area, 0.1 W */
    lx_assert_near(exact.radiant, 0.1, 0, 1e-12);
    /* Why linear1nm is not the default for such data: resampled at whole nm the line is one
     * sample of height 1 at 532 nm, so the 1 nm sum counts it as 1 nm wide: Y is 10x too large. */
    lx_colorimetry lin = colorimetry_of(ctx, &s, LX_METHOD_LINEAR1NM);
    lx_assert_near(lin.Y, 683.002 * y532, 0, 1e-12);
    assert_true(lin.Y / analytic > 9.9);
    /* the same line shifted by 0.05 nm (531.95..532.15) falls between whole nm for the peak: the
     * 1 nm resampling now sees 0.5 at 532 and 0 elsewhere, half the previous value: unstable */
    for (int i = 0; i < 251; i++) wl[i] += 0.05;
    lin = colorimetry_of(ctx, &s, LX_METHOD_LINEAR1NM);
    exact = colorimetry_of(ctx, &s, LX_METHOD_EXACT);
    lx_assert_near(lin.Y, 683.002 * y532 * 0.5, 0, 1e-9);
    lx_assert_near(exact.Y, analytic, 0, 2e-3); /* exact follows the line (ybar is nearly flat here) */
}

/* The exact rule on data that coincide with the CMF rows: a piecewise-linear spectrum times a
 * piecewise-linear CMF integrates to sum h/6 (2 s0 w0 + s0 w1 + s1 w0 + 2 s1 w1) (closed form). */
static void test_exact_closed_form(void **state)
{
    lx_ctx *ctx = *state;
    double wl[3] = {500, 502, 504}, v[3] = {1, 3, 2};
    lx_spd s = {"s", 3, wl, v}, w;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &w));
    double out, ref = 0;
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s, &w, LX_METHOD_EXACT, &out));
    for (int k = 500; k < 504; k++) {
        double s0 = k < 502 ? 1 + (k - 500) : 3 - 0.5 * (k - 502), s1 = k + 1 < 502 ? 1 + (k + 1 - 500) : 3 - 0.5 * (k + 1 - 502);
        double w0 = w.value[k - 360], w1 = w.value[k + 1 - 360];
        ref += 1.0 / 6.0 * (2 * s0 * w0 + s0 * w1 + s1 * w0 + 2 * s1 * w1);
    }
    lx_assert_near(out, ref, 0, 1e-14);
    /* cie15 at 2 nm: plain sum times the step (CIE 015 summation) */
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s, &w, LX_METHOD_CIE15, &out));
    lx_assert_near(out, 2.0 * (1 * w.value[140] + 3 * w.value[142] + 2 * w.value[144]), 0, 1e-14);
    /* cie15 refuses non-uniform data */
    double wl2[3] = {500, 502, 505};
    lx_spd s2 = {"s2", 3, wl2, v};
    assert_int_equal(lx_spd_integrate(ctx, &s2, &w, LX_METHOD_CIE15, &out), LX_EINVAL);
    /* a spectrum outside the CMF range integrates to 0 */
    double wl3[2] = {900, 950};
    lx_spd s3 = {"ir", 2, wl3, v};
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s3, &w, LX_METHOD_EXACT, &out));
    lx_assert_near(out, 0, 0, 0);
}

static void fill_blackbody(double T, double *wl, double *v)
{
    for (int i = 0; i < 471; i++) {
        wl[i] = 360 + i;
        v[i] = lx_planck(wl[i], T);
    }
}

/* CCT round trip against Planck's law: |dT| < 0.1 K from 1000 K to 100000 K, |Duv| < 1e-6. */
/* linear1nm on a spectrum that spans 1 nm to 1e9 nm (a file in the wrong unit, a fuzz input): only
 * the nanometres where the weight is defined are summed, so it takes microseconds, not 1e9 steps,
 * and equals the sum of the linear spectrum times ybar at the table's whole nanometres (closed
 * form of the interpolant: v(k) = 1 + 2e-9 (k - 1) on the straight line between the samples). */
static void test_linear1nm_wide_range(void **state)
{
    lx_ctx *ctx = *state;
    double lam[2] = {1, 1e9}, val[2] = {1, 3};
    lx_spd s = {.n = 2, .lambda_nm = lam, .value = val, .name = "wide"};
    lx_spd ybar;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &ybar));
    double got = 0, want = 0;
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s, &ybar, LX_METHOD_LINEAR1NM, &got));
    for (size_t k = 0; k < ybar.n; k++) {
        double l = ybar.lambda_nm[k];
        want += (1 + (l - 1) * (2.0 / (1e9 - 1))) * ybar.value[k];
    }
    lx_assert_near(got, want, 0, 1e-14);
}

static void test_cct_round_trip(void **state)
{
    lx_ctx *ctx = *state;
    double wl[471], v[471];
    lx_spd s = {"bb", 471, wl, v};
    for (double T = 1000; T <= 100000 * 1.0000001; T *= 1.1) {
        fill_blackbody(T, wl, v);
        lx_colorimetry c = colorimetry_of(ctx, &s, LX_METHOD_AUTO);
        assert_true(c.cct_valid);
        lx_assert_near(c.cct_K, T, 0.1, 0);
        lx_assert_near(c.duv, 0, 1e-6, 0);
    }
    fill_blackbody(100000, wl, v);
    lx_colorimetry c = colorimetry_of(ctx, &s, LX_METHOD_AUTO);
    lx_assert_near(c.cct_K, 100000, 0.1, 0);
}

/* The ends of the searched range, 500 K and 1e6 K, solve exactly (the locus table reaches beyond
 * them); just outside is LX_ERANGE (lx_cct_from_uv's documented range). */
static void test_cct_range_ends(void **state)
{
    lx_ctx *ctx = *state;
    static const double ok_T[] = {500, 501, 990000, 999999, 1e6};
    for (size_t i = 0; i < sizeof ok_T / sizeof *ok_T; i++) {
        double u, v, T, duv;
        lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, ok_T[i], &u, &v));
        lx_assert_ok(ctx, lx_cct_from_uv(ctx, LX_OBSERVER_2, u, v, &T, &duv));
        lx_assert_near(T, ok_T[i], 0, 1e-9);
        lx_assert_near(duv, 0, 1e-12, 0);
    }
    static const double bad_T[] = {499, 1.01e6};
    for (size_t i = 0; i < 2; i++) {
        double u, v, T, duv;
        lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, bad_T[i], &u, &v));
        assert_int_equal(lx_cct_from_uv(ctx, LX_OBSERVER_2, u, v, &T, &duv), LX_ERANGE);
        assert_true(isnan(T) && isnan(duv));
    }
}

static void test_cct_of_illuminants(void **state)
{
    lx_ctx *ctx = *state;
    double wl[471], v[471];
    for (int i = 0; i < 471; i++) {
        wl[i] = 360 + i;
        v[i] = lx_illuminant_a(wl[i]);
    }
    lx_spd a = {"A", 471, wl, v}, d65;
    /* A is a 2848 K Planckian with c2 = 1.435e-2: 2848 * 1.4388 / 1.435 = 2855.5 K (CIE 015:2018) */
    lx_colorimetry c = colorimetry_of(ctx, &a, LX_METHOD_AUTO);
    lx_assert_near(c.cct_K, 2855.5, 0.5, 0);
    lx_assert_near(c.duv, 0, 1e-5, 0);
    /* D65: 6504 K nominal; with the 5 nm table 6503 +- 2 K. colour-science 0.4.7
     * uv_to_CCT_Ohno2013 at our xy (0.312711, 0.329008) gives 6503.66 K, Duv 0.0032054. */
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &d65));
    c = colorimetry_of(ctx, &d65, LX_METHOD_AUTO);
    lx_assert_near(c.cct_K, 6503, 2, 0);
    lx_assert_near(c.cct_K, 6503.66, 0.5, 0);
    lx_assert_near(c.duv, 0.0032054, 2e-6, 0);
    /* FL2: colour-science 0.4.7 Ohno 2013 at our xy (0.372068, 0.375123): 4224.49 K, Duv 0.0017888 */
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "FL2", &d65));
    c = colorimetry_of(ctx, &d65, LX_METHOD_AUTO);
    lx_assert_near(c.cct_K, 4224.49, 0.5, 0);
    lx_assert_near(c.duv, 0.0017888, 2e-6, 0);
    /* equal-energy E lies below the locus: colour-science Ohno 2013 gives 5456.3 K, Duv -0.0044395 */
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "E", &d65));
    c = colorimetry_of(ctx, &d65, LX_METHOD_AUTO);
    lx_assert_near(c.cct_K, 5456.3, 0.5, 0);
    lx_assert_near(c.duv, -0.0044395, 2e-6, 0);
}

static void test_cct_out_of_range(void **state)
{
    lx_ctx *ctx = *state;
    double T, duv;
    /* far off the locus (a saturated green): the nearest locus point exists, |Duv| says it is meaningless */
    lx_assert_ok(ctx, lx_cct_from_xy(ctx, LX_OBSERVER_2, 0.2, 0.7, &T, &duv));
    assert_true(duv > 0.05);
    /* the red end of the spectrum locus (700 nm: x 0.7347, y 0.2653, CIE 015) lies beyond the
     * locus end at 500 K; a deep blue-violet beyond its end at 1e6 K: out of range, NaN outputs */
    assert_int_equal(lx_cct_from_xy(ctx, LX_OBSERVER_2, 0.735, 0.265, &T, &duv), LX_ERANGE);
    assert_true(isnan(T) && isnan(duv));
    assert_int_equal(lx_cct_from_xy(ctx, LX_OBSERVER_2, 0.2, 0.18, &T, &duv), LX_ERANGE);
    assert_true(isnan(T) && isnan(duv));
    /* a monochromatic 470 nm spectrum: colorimetry succeeds, CCT is marked meaningless (|Duv| > 0.05) */
    double wl[3] = {469, 470, 471}, v[3] = {0, 1, 0};
    lx_spd s = {"blue", 3, wl, v};
    lx_colorimetry c = colorimetry_of(ctx, &s, LX_METHOD_EXACT);
    assert_false(c.cct_valid);
    assert_true(isnan(c.cct_K) && isnan(c.duv));
    assert_true(c.Y > 0);
    /* an all-zero spectrum: XYZ 0, chromaticity undefined (NaN), not an error */
    double z[3] = {0, 0, 0};
    lx_spd sz = {"dark", 3, wl, z};
    c = colorimetry_of(ctx, &sz, LX_METHOD_EXACT);
    assert_true(c.Y == 0 && isnan(c.x) && isnan(c.ler_lm_per_W) == 1);
}

/* Luminous efficacy of a blackbody over 360-830 nm relative to its total exitance sigma T^4:
 * 16.45 +- 0.02 lm/W at 2856 K and 95.37 +- 0.05 lm/W at 6504 K (issue #2 reference values, from
 * numerical integration of Planck's law against V(lambda)). Luminance L_v = Km int L ybar; total
 * radiance sigma T^4 / pi. */
static void test_blackbody_efficacy(void **state)
{
    lx_ctx *ctx = *state;
    double wl[471], v[471];
    lx_spd s = {"bb", 471, wl, v};
    fill_blackbody(2856, wl, v);
    lx_colorimetry c = colorimetry_of(ctx, &s, LX_METHOD_AUTO);
    lx_assert_near(c.Y / (lx_stefan_boltzmann(2856) / M_PI), 16.45, 0.02, 0);
    fill_blackbody(6504, wl, v);
    c = colorimetry_of(ctx, &s, LX_METHOD_AUTO);
    lx_assert_near(c.Y / (lx_stefan_boltzmann(6504) / M_PI), 95.37, 0.05, 0);
}

/* Planck's law: closed-form checks and stability at extreme temperatures. */
static void test_planck(void **state)
{
    (void)state;
    /* Wien's displacement law: the peak of B(lambda) is at b / T, b = 2.897771955e-3 m K (CODATA
     * 2018, with the exact c2; our c2 = 1.4388e-2 shifts it by 1.4388/1.438777 - 1 = 1.6e-5). */
    double T = 5000, best = 0, at = 0;
    for (double l = 500; l < 650; l += 0.01) {
        double b = lx_planck(l, T);
        if (b > best) best = b, at = l;
    }
    lx_assert_near(at, 2.897771955e6 / T * 1.4388 / 1.438776877, 0.01, 0);
    /* Rayleigh-Jeans limit at very high T: B -> c1L T / (c2 lambda^4) (1 - x/2 + x^2/12), x = c2/(lambda T) */
    double l = 500e-9, Th = 1e9, xr = 1.4388e-2 / (l * Th);
    lx_assert_near(lx_planck(500, Th), 1.191042972e-16 * Th / (1.4388e-2 * l * l * l * l) * 1e-9 * (1 - xr / 2 + xr * xr / 12),
                   0, 1e-12);
    /* no overflow, no NaN: 1 K and 100 K underflow cleanly, 1e6 K is finite */
    assert_true(lx_planck(360, 1) == 0.0);
    double b100 = lx_planck(830, 100);
    assert_true(isfinite(b100) && b100 >= 0);
    assert_true(isfinite(lx_planck(360, 1e6)) && lx_planck(360, 1e6) > 0);
    assert_true(isnan(lx_planck(500, 0)) && isnan(lx_planck(-1, 5000)) && isnan(lx_planck(500, INFINITY)));
    /* Stefan-Boltzmann: pi * integral of B over all wavelengths = sigma T^4; integrate numerically
     * in log lambda from 10 nm to 1 mm at 1000 K (c2 differs from the exact one by 1.6e-5, so the
     * integral differs from sigma T^4 by about 4 x 1.6e-5) */
    double sum = 0;
    for (double ll = log(10); ll < log(1e6); ll += 1e-4) {
        double lm = exp(ll + 0.5e-4);
        sum += lx_planck(lm, 1000) * lm * 1e-4;
    }
    lx_assert_near(M_PI * sum, lx_stefan_boltzmann(1000), 0, 2e-4);
}

static void test_daylight(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd d65;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &d65));
    /* colour-science 0.4.7 sd_CIE_illuminant_D_series(CCT_to_xy_CIE_D(6504)), normalised to 100 at
     * 560 nm, at a few wavelengths: */
    static const double ref_l[] = {300, 305, 330, 380, 460, 700, 780};
    static const double ref_v[] = {0.03412, 1.66656, 37.0955, 50.014, 117.8448, 71.5958, 63.3724};
    double v[200], v560, l560 = 560;
    lx_assert_ok(ctx, lx_daylight(ctx, 6504, 1, &l560, &v560));
    lx_assert_ok(ctx, lx_daylight(ctx, 6504, 7, ref_l, v));
    for (int i = 0; i < 7; i++) lx_assert_near(v[i] * 100.0 / v560, ref_v[i], 0, 1e-5);
    /* The published D65 table (CIE 015:2018 Table 5) differs from the D-series at 6504 K by up to
     * 0.15 % (colour-science shows the same: 1.66656 vs 1.6643 at 305 nm): */
    lx_assert_ok(ctx, lx_daylight(ctx, 6504, d65.n, d65.lambda_nm, v));
    for (size_t i = 0; i < d65.n; i++) lx_assert_near(v[i] * 100.0 / v560, d65.value[i], 1e-3, 2e-3);
    /* daylight locus at 6504 K, CIE 015:2018 eq. 4.7/4.8: xD = 0.3127141, yD = -3 xD^2 + 2.87 xD -
     * 0.275 = 0.3291191 (colour-science 0.4.7 CCT_to_xy_CIE_D(6504) gives the same) */
    double x, y;
    lx_assert_ok(ctx, lx_daylight_xy(ctx, 6504, &x, &y));
    lx_assert_near(x, 0.3127141, 1e-7, 0);
    lx_assert_near(y, 0.3291191, 1e-7, 0);
    assert_int_equal(lx_daylight(ctx, 3000, 1, &l560, &v560), LX_ERANGE);
    assert_int_equal(lx_daylight(ctx, 30000, 1, &l560, &v560), LX_ERANGE);
}

static void test_observer_10(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd d65;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "D65", &d65));
    lx_colorimetry c;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &d65, LX_OBSERVER_10, LX_METHOD_AUTO, &c));
    /* CIE 015:2018 Table T.3: D65, 10 deg: x10 = 0.31382, y10 = 0.33100 */
    lx_assert_near(c.x, 0.31382, 5e-5, 0);
    lx_assert_near(c.y, 0.33100, 5e-5, 0);
    assert_int_equal(lx_spd_colorimetry(ctx, &d65, (lx_observer)5, LX_METHOD_AUTO, &c), LX_EINVAL);
}

static void test_scotopic_and_ler(void **state)
{
    lx_ctx *ctx = *state;
    /* A monochromatic 555 nm line of 1 W (triangle of area 1 W centred on a row, 0.02 nm wide,
     * integrated exactly: ybar is linear on each side, so Y = Km * mean of ybar at the two
     * centroids ~ Km * ybar(555)): LER ~ 683 lm/W; scotopic Y = 1700.06 * V'(555). */
    double wl[3] = {554.99, 555.0, 555.01}, v[3] = {0, 100.0, 0};
    lx_spd s = {"555", 3, wl, v}, vp;
    lx_colorimetry c = colorimetry_of(ctx, &s, LX_METHOD_EXACT);
    lx_assert_near(c.radiant, 1.0, 1e-12, 0);
    lx_assert_near(c.ler_lm_per_W, 683.002, 0, 1e-5);
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_VPRIME, &vp));
    lx_assert_near(c.scotopic_Y, 1700.06 * vp.value[555 - 380], 0, 1e-4);
    lx_assert_near(c.sp_ratio, c.scotopic_Y / c.Y, 0, 1e-15);
    /* u'v' from XYZ: u' = 4X/(X+15Y+3Z), v' = 9Y/(X+15Y+3Z) (CIE 015:2018 eq. 8.1) */
    double d = c.X + 15 * c.Y + 3 * c.Z;
    lx_assert_near(c.u_prime, 4 * c.X / d, 0, 1e-15);
    lx_assert_near(c.v_prime, 9 * c.Y / d, 0, 1e-15);
}

/* Luminous efficacy of radiation of a flat 1 W/nm spectrum, 380-780 nm at 5 nm: the radiant
 * integral is the exact (trapezoid) 400 W, not the CIE 015 sum 405 W; colour-science 0.4.7
 * colour.luminous_efficacy gives 182.457480537 lm/W for the same data. */
static void test_ler_flat(void **state)
{
    lx_ctx *ctx = *state;
    double wl[81], v[81];
    for (int i = 0; i < 81; i++) wl[i] = 380 + 5 * i, v[i] = 1.0;
    lx_spd s = {"flat", 81, wl, v};
    lx_colorimetry c = colorimetry_of(ctx, &s, LX_METHOD_AUTO);
    lx_assert_near(c.radiant, 400.0, 1e-12, 0);
    lx_assert_near(c.ler_lm_per_W, 182.457480537, 0, 1e-4);
    c = colorimetry_of(ctx, &s, LX_METHOD_LINEAR1NM);
    lx_assert_near(c.radiant, 400.0, 1e-12, 0);
}

static void test_bad_views(void **state)
{
    lx_ctx *ctx = *state;
    double wl[3] = {500, 500, 510}, v[3] = {1, 2, 3};
    lx_spd s = {"dup", 3, wl, v};
    lx_colorimetry c;
    assert_int_equal(lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &c), LX_EINVAL);
    wl[1] = 505;
    v[1] = NAN;
    assert_int_equal(lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &c), LX_EINVAL);
    s.n = 1;
    assert_int_equal(lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &c), LX_EINVAL);
    assert_int_equal(lx_spd_colorimetry(ctx, NULL, LX_OBSERVER_2, LX_METHOD_AUTO, &c), LX_EINVAL);
}

/* Dominant wavelength and purity against illuminant E, CIE 015:2018 9.1: colour-science 0.4.7
 * (colour.dominant_wavelength, excitation_purity, colorimetric_purity on the CIE 1931 2 deg CMFs
 * 360-830 nm at 1 nm), which gives the whole nm nearest the crossing and the purities at the exact
 * crossing; the fractional wavelengths are an independent numpy intersection of the same polyline
 * (the ray from E, the farthest crossing), written out in this comment's test. */
static void test_dominant(void **state)
{
    lx_ctx *ctx = *state;
    static const struct {
        double x, y, wl_cs, wl, pe, pc;
    } ref[] = {
        {0.6835, 0.3150, 617, 616.9733767463, 0.995998000100234, 0.995765079471147},
        {0.17, 0.70, 525, 524.9442224412, 0.743686408645106, 0.877945908878622},
        {0.14, 0.05, 466, 465.6155633729, 0.971242758400854, 0.808285056005692},
        {0.40, 0.20, -521, -521.1203913014, 0.645291538529675, 0.408819230882792}, /* a purple */
        {0.56, 0.43, 589, 588.5480638283, 0.971910982280252, 0.978225567659110},
        {0.34, 0.35, 568, 567.7435129176, 0.070291960856833, 0.114563772244603},
    };
    for (size_t i = 0; i < sizeof ref / sizeof *ref; i++) {
        lx_dominant d;
        lx_assert_ok(ctx, lx_dominant_wavelength(ctx, LX_OBSERVER_2, ref[i].x, ref[i].y, 1.0 / 3, 1.0 / 3, &d));
        lx_assert_near(d.wavelength_nm, ref[i].wl, 1e-8, 0);
        assert_true(fabs(d.wavelength_nm - ref[i].wl_cs) <= 0.5); /* colour-science's nearest whole nm */
        lx_assert_near(d.excitation_purity, ref[i].pe, 1e-12, 0);
        lx_assert_near(d.colorimetric_purity, ref[i].pc, 1e-12, 0);
        assert_int_equal(d.purple, ref[i].wl < 0);
        assert_int_equal(d.outside, 0);
    }
    /* another white: D65 (0.31271, 0.32902): colour-science 584 nm, pe 0.610624772223150 */
    lx_dominant d;
    lx_assert_ok(ctx, lx_dominant_wavelength(ctx, LX_OBSERVER_2, 0.45, 0.41, 0.31271, 0.32902, &d));
    assert_true(fabs(d.wavelength_nm - 584) <= 0.5);
    lx_assert_near(d.excitation_purity, 0.610624772223150, 1e-12, 0);
    /* monochromatic light lies on the locus: its own wavelength, purity 1 (a 1 nm point, exact) */
    lx_spd cmf[3];
    for (int k = 0; k < 3; k++) lx_assert_ok(ctx, lx_function_get(ctx, (lx_function)(LX_FN_XBAR_2 + k), &cmf[k]));
    for (int wl = 450; wl <= 650; wl += 50) {
        size_t i = (size_t)(wl - 360);
        double X = cmf[0].value[i], Y = cmf[1].value[i], Z = cmf[2].value[i];
        lx_assert_ok(ctx, lx_dominant_wavelength(ctx, LX_OBSERVER_2, X / (X + Y + Z), Y / (X + Y + Z), 1.0 / 3, 1.0 / 3, &d));
        lx_assert_near(d.wavelength_nm, wl, 1e-9, 0);
        lx_assert_near(d.excitation_purity, 1, 1e-12, 0);
        lx_assert_near(d.colorimetric_purity, 1, 1e-12, 0);
    }
    /* the white itself: no wavelength, purity 0; a white outside the locus is an error */
    lx_assert_ok(ctx, lx_dominant_wavelength(ctx, LX_OBSERVER_2, 1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0 / 3, &d));
    assert_true(isnan(d.wavelength_nm) && d.excitation_purity == 0);
    assert_int_equal(lx_dominant_wavelength(ctx, LX_OBSERVER_2, 0.3, 0.3, 0.9, 0.9, &d), LX_EINVAL);
    assert_int_equal(lx_dominant_wavelength(ctx, LX_OBSERVER_2, NAN, 0.3, 0.3, 0.3, &d), LX_EINVAL);
    /* beyond the locus (a point no light reaches): flagged */
    lx_assert_ok(ctx, lx_dominant_wavelength(ctx, LX_OBSERVER_2, 0.05, 0.9, 1.0 / 3, 1.0 / 3, &d));
    assert_int_equal(d.outside, 1);
}

/* Peak and FWHM of a triangle and of a Gaussian sampled every 1 nm (FWHM 2 sqrt(2 ln 2) sigma,
 * within the linear interpolation's error), a one-sided spectrum (no FWHM), the noise measure of
 * smooth, constant and noisy data. */
static void test_shape(void **state)
{
    lx_ctx *ctx = *state;
    double wl[401], v[401];
    for (int i = 0; i < 401; i++) wl[i] = 380 + i, v[i] = fmax(0, 1 - fabs(wl[i] - 555.5) / 20);
    lx_spd s = {"tri", 401, wl, v};
    lx_spd_shape sh;
    lx_assert_ok(ctx, lx_spd_shape_compute(ctx, &s, &sh));
    /* samples at 555 and 556 are equal (0.975): the first */
    lx_assert_near(sh.peak_nm, 555, 0, 0);
    lx_assert_near(sh.peak_value, 0.975, 1e-15, 0);
    /* half of 0.975 = 0.4875: the triangle crosses it at 555.5 -+ 20 (1 - 0.4875) = 545.25 / 565.75 */
    lx_assert_near(sh.half_lo_nm, 545.25, 1e-9, 0);
    lx_assert_near(sh.half_hi_nm, 565.75, 1e-9, 0);
    lx_assert_near(sh.fwhm_nm, 20.5, 1e-9, 0);
    assert_true(sh.noise < 0.02);
    for (int i = 0; i < 401; i++) v[i] = exp(-0.5 * (wl[i] - 530) * (wl[i] - 530) / 100); /* sigma 10 nm */
    lx_assert_ok(ctx, lx_spd_shape_compute(ctx, &s, &sh));
    lx_assert_near(sh.peak_nm, 530, 0, 0);
    lx_assert_near(sh.fwhm_nm, 2 * sqrt(2 * log(2)) * 10, 0.01, 0);
    for (int i = 0; i < 401; i++) v[i] = 1 + 0.001 * i; /* rising to the last sample: no upper crossing */
    lx_assert_ok(ctx, lx_spd_shape_compute(ctx, &s, &sh));
    lx_assert_near(sh.peak_nm, 780, 0, 0);
    assert_true(isnan(sh.fwhm_nm) && isnan(sh.half_hi_nm) && isnan(sh.half_lo_nm));
    for (int i = 0; i < 401; i++) v[i] = 5;
    lx_assert_ok(ctx, lx_spd_shape_compute(ctx, &s, &sh));
    assert_true(sh.noise == 0);
    unsigned u = 12345; /* a dark frame: counts around 1000 with noise (an LCG, reproducible) */
    for (int i = 0; i < 401; i++) u = u * 1103515245u + 12345u, v[i] = 1000 + (double)(u >> 16 & 1023) / 1023 * 20 - 10;
    lx_assert_ok(ctx, lx_spd_shape_compute(ctx, &s, &sh));
    assert_true(sh.noise > 0.15);
    for (int i = 0; i < 401; i++) v[i] = -1;
    assert_int_equal(lx_spd_shape_compute(ctx, &s, &sh), LX_ERANGE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cie15_chromaticities), cmocka_unit_test(test_laser_line),
        cmocka_unit_test(test_exact_closed_form),    cmocka_unit_test(test_cct_round_trip),
        cmocka_unit_test(test_cct_of_illuminants),   cmocka_unit_test(test_cct_out_of_range),
        cmocka_unit_test(test_blackbody_efficacy),   cmocka_unit_test(test_planck),
        cmocka_unit_test(test_daylight),             cmocka_unit_test(test_observer_10),
        cmocka_unit_test(test_scotopic_and_ler),     cmocka_unit_test(test_bad_views),
        cmocka_unit_test(test_ler_flat),
        cmocka_unit_test(test_cct_range_ends),
        cmocka_unit_test(test_linear1nm_wide_range),
        cmocka_unit_test(test_dominant),
        cmocka_unit_test(test_shape),
    };
    return cmocka_run_group_tests_name("colorimetry", tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
