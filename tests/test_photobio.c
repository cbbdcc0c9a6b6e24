/* test_photobio.c - PAR and IEC 62471 quantities: the weighting functions at their tabulated points,
 * closed forms (flat spectra, lines inside a linear stretch of the weight), coverage, the risk
 * groups at the limits, DLI, and the batch path against the per-spectrum path. */
#include "lx_test.h"

#include "tables/tables_private.h"

#include <string.h>

/* h c N_A in J m / mol (SI 2019 exact constants): lambda / (h c N_A) photons per joule, in mol */
#define HCNA (6.62607015e-34 * 299792458.0 * 6.02214076e23)
#define UMOL_PER_J_NM (1e-3 / HCNA) /* umol/J per nm of wavelength */

static double at(lx_ctx *ctx, lx_function fn, double nm)
{
    lx_spd w;
    lx_assert_ok(ctx, lx_function_get(ctx, fn, &w));
    return lx__interp(w.lambda_nm, w.value, w.n, nm);
}

static void test_tables(void **state)
{
    lx_ctx *ctx = *state;
    /* IEC 62471:2006 Table 4.1 as printed (src/data/iec62471_blue_thermal.csv provenance) */
    static const double b[][2] = {{300, 0.01}, {380, 0.01}, {385, 0.013}, {400, 0.10}, {420, 0.90}, {435, 1.0},
                                  {440, 1.0},  {450, 0.94}, {485, 0.40}, {495, 0.16}, {650, 0.001}, {700, 0.001}};
    for (size_t i = 0; i < sizeof b / sizeof *b; i++) lx_assert_near(at(ctx, LX_FN_HAZARD_BLUE, b[i][0]), b[i][1], 0, 1e-12);
    lx_assert_near(at(ctx, LX_FN_HAZARD_BLUE, 550), pow(10, (450 - 550) / 50.0), 0, 1e-12); /* 10^((450-l)/50) */
    assert_true(at(ctx, LX_FN_HAZARD_BLUE, 701) == 0 && at(ctx, LX_FN_HAZARD_BLUE, 299) == 0);
    static const double r[][2] = {{380, 0.1}, {400, 1.0}, {440, 10.0}, {485, 4.0}, {600, 1.0}, {1100, 0.2}, {1400, 0.02}};
    for (size_t i = 0; i < sizeof r / sizeof *r; i++)
        lx_assert_near(at(ctx, LX_FN_HAZARD_THERMAL, r[i][0]), r[i][1], 0, 1e-12);
    lx_assert_near(at(ctx, LX_FN_HAZARD_THERMAL, 800), pow(10, (700 - 800) / 500.0), 0, 1e-12);
    lx_assert_near(at(ctx, LX_FN_HAZARD_THERMAL, 1175), 0.2 * pow(10, 0.02 * (1150 - 1175)), 0, 1e-12);
    assert_true(at(ctx, LX_FN_HAZARD_THERMAL, 379) == 0);
    /* IEC 62471:2006 Table 4.2 S_UV(lambda) */
    static const double s[][2] = {{200, 0.030}, {254, 0.500}, {270, 1.000}, {297, 0.460}, {300, 0.300},
                                  {313, 0.006}, {320, 0.0010}, {360, 0.00013}, {400, 0.000030}};
    for (size_t i = 0; i < sizeof s / sizeof *s; i++)
        lx_assert_near(at(ctx, LX_FN_HAZARD_ACTINIC, s[i][0]), s[i][1], 0, 1e-12);
    /* McCree 1972 Tables IV/III field mean, photon basis */
    static const double q[][2] = {{350, 0.02}, {450, 0.70}, {625, 1.00}, {700, 0.48}, {725, 0.23}};
    for (size_t i = 0; i < sizeof q / sizeof *q; i++)
        lx_assert_near(at(ctx, LX_FN_YPF_MCCREE, q[i][0]), q[i][0] * UMOL_PER_J_NM * q[i][1], 0, 1e-12);
    /* photons per joule: lambda / (h c N_A); 550 nm: 4.5976 umol/J */
    lx_assert_near(at(ctx, LX_FN_PHOTON_PAR, 550), 550 * UMOL_PER_J_NM, 0, 1e-14);
    lx_assert_near(at(ctx, LX_FN_PHOTON_PAR, 550), 4.59764, 1e-5, 0);
    assert_true(at(ctx, LX_FN_PHOTON_PAR, 701) == 0 && at(ctx, LX_FN_PHOTON_EPAR, 750) > 0);
    assert_true(at(ctx, LX_FN_UVA, 315) == 1 && at(ctx, LX_FN_UVA, 400) == 1 && at(ctx, LX_FN_UVA, 401) == 0);
}

/* S_UV against ICNIRP 2004 eq. 2a-2c (the fit to the same table): within 13 %, 33 % at 315-328 nm */
static void test_actinic_against_icnirp_fit(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd w;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_HAZARD_ACTINIC, &w));
    for (size_t i = 0; i < w.n; i++) {
        double l = w.lambda_nm[i], e;
        if (l < 210) continue;
        if (l <= 270) e = pow(0.959, 270 - l);
        else if (l <= 300) e = 1 - 0.36 * pow((l - 270) / 20, 1.64);
        else e = 0.3 * pow(0.736, l - 300) + pow(10, 2 - 0.0163 * l);
        lx_assert_near(w.value[i], e, 0, l >= 315 && l <= 328 ? 0.33 : 0.13);
    }
}

static lx_spd flat(double *l, double *v, double a, double b, double step)
{
    size_t n = (size_t)((b - a) / step + 0.5) + 1;
    for (size_t i = 0; i < n; i++) l[i] = a + step * (double)i, v[i] = 1.0;
    return (lx_spd){"flat", n, l, v};
}

static void test_par_closed_forms(void **state)
{
    lx_ctx *ctx = *state;
    static double l[2001], v[2001];
    /* 1 W m-2 nm-1 over 300-800 nm: PPFD = (700^2 - 400^2)/2 / (h c N_A) = 1379.29 umol s-1 m-2 */
    lx_spd s = flat(l, v, 300, 800, 1);
    lx_par p;
    lx_assert_ok(ctx, lx_par_compute(ctx, &s, LX_METHOD_EXACT, &p));
    lx_assert_near(p.ppfd, 0.5 * (700.0 * 700 - 400.0 * 400) * UMOL_PER_J_NM, 0, 1e-12);
    lx_assert_near(p.ppfd, 1379.29229, 1e-4, 0);
    lx_assert_near(p.epar, 0.5 * (750.0 * 750 - 400.0 * 400) * UMOL_PER_J_NM, 0, 1e-12);
    lx_assert_near(p.photon_efficacy_umol_J, p.ppfd / 500.0, 0, 1e-12); /* radiant 500 W m-2 */
    /* YPF of the flat spectrum: k * integral of l * RQE(l), RQE linear between its 25 nm rows; by the
     * exact integral of a linear times a linear over each 25 nm interval (the library tabulates the
     * product at 1 nm, so 1e-5) */
    static const double rq[16] = {0.02, 0.12, 0.42, 0.68, 0.70, 0.63, 0.65, 0.72, 0.82, 0.91, 0.97, 1.00, 0.90, 0.90, 0.48, 0.23};
    double ypf = 0;
    for (int i = 0; i < 15; i++) {
        double a = 350 + 25 * i, b = a + 25, r0 = rq[i], r1 = rq[i + 1];
        /* integral of l (r0 + (r1 - r0)(l - a)/25) dl over [a, b] */
        double m = (r1 - r0) / 25;
        ypf += (r0 - m * a) * (b * b - a * a) / 2 + m * (b * b * b - a * a * a) / 3;
    }
    lx_assert_near(p.ypf, ypf * UMOL_PER_J_NM, 0, 1e-5);
    /* a 660 nm line of 1 W m-2 inside PAR: 660 / (h c N_A) = 5.5172 umol s-1 m-2 */
    for (int i = 0; i <= 500; i++) v[i] = l[i] == 660 ? 1.0 : 0.0;
    lx_assert_ok(ctx, lx_par_compute(ctx, &s, LX_METHOD_EXACT, &p));
    lx_assert_near(p.ppfd, 660 * UMOL_PER_J_NM, 0, 1e-12);
    lx_assert_near(p.photon_efficacy_umol_J, 660 * UMOL_PER_J_NM, 0, 1e-12); /* all of the power in PAR */
    /* a spectrum that misses the band is not covered: NaN, never 0 */
    s = flat(l, v, 500, 800, 1);
    lx_assert_ok(ctx, lx_par_compute(ctx, &s, LX_METHOD_EXACT, &p));
    assert_true(isnan(p.ppfd) && isnan(p.epar) && isnan(p.ypf) && isnan(p.photon_efficacy_umol_J));
    /* DLI: 500 umol s-1 m-2 for 16 h = 28.8 mol m-2 d-1 */
    lx_assert_near(lx_par_dli(500, 16), 28.8, 0, 1e-14);
    assert_true(isnan(lx_par_dli(500, -1)));
}

static void test_hazard_closed_forms(void **state)
{
    lx_ctx *ctx = *state;
    static double l[1201], v[1201];
    lx_spd s = flat(l, v, 200, 1400, 1); /* covers every band */
    for (size_t i = 0; i < s.n; i++) v[i] = 0;
    /* a line of power P (a triangle, 1 nm each side) where the weight is linear across it weighs
     * exactly P w(centre): 437 nm (B = 1, R = 10), 272 nm (S_UV = 1 - 0.04 * 2 / 5), 350 nm (UV-A) */
    v[437 - 200] = 2.0, v[272 - 200] = 3.0, v[350 - 200] = 5.0;
    lx_hazard h;
    lx_assert_ok(ctx, lx_hazard_compute(ctx, &s, LX_METHOD_EXACT, &h));
    for (int k = 0; k < LX_HZ_COUNT; k++) lx_assert_near(h.coverage[k], 1.0, 1e-12, 0);
    double B350 = 0.01, R350 = 0, S437 = 0, S350 = 0.00020; /* S_UV(350) tabulated */
    lx_assert_near(h.value[LX_HZ_BLUE], 2.0 * 1.0 + 5.0 * B350, 0, 1e-12); /* B starts at 300 nm */
    lx_assert_near(h.value[LX_HZ_THERMAL], 2.0 * 10.0 + 5.0 * R350, 0, 1e-12);
    lx_assert_near(h.value[LX_HZ_ACTINIC], 3.0 * (1 - 0.04 * 2 / 5.0) + 5.0 * S350 + 2.0 * S437, 0, 1e-12);
    lx_assert_near(h.value[LX_HZ_UVA], 5.0, 0, 1e-12);
    /* coverage of a 380-780 nm file: UV-A 20 of 85 nm; actinic UV about nothing: "not covered" */
    s = flat(l, v, 380, 780, 1);
    lx_assert_ok(ctx, lx_hazard_compute(ctx, &s, LX_METHOD_EXACT, &h));
    lx_assert_near(h.coverage[LX_HZ_UVA], 20.0 / 85.0, 0, 1e-12);
    assert_true(isnan(h.value[LX_HZ_UVA]) && isnan(h.value[LX_HZ_ACTINIC]) && isnan(h.value[LX_HZ_THERMAL]));
    assert_true(h.coverage[LX_HZ_BLUE] > 0.98 && h.coverage[LX_HZ_BLUE] < 0.99); /* 300-380 nm at 0.01 is 1.2 % */
    /* the flat spectrum's L_B = integral of B over 380-700 nm: the blue-light efficacy check
     * sum of the tabulated B at 5 nm from 380 to 500 (trapezoid) + 50/ln10 (10^-1 - 10^-3) + 0.1 */
    lx_assert_near(h.value[LX_HZ_BLUE], 68.16510, 1e-4, 0);
}

static void test_risk_groups(void **state)
{
    lx_ctx *ctx = *state;
    lx_hazard h = {{0}, {1, 1, 1, 1}, {0}};
    lx_hazard_risk r;
    /* radiance: L_B limits 100, 1e4, 4e6 W m-2 sr-1 */
    static const double lb[][2] = {{100, 0}, {100.01, 1}, {1e4, 1}, {4e6, 2}, {4.1e6, 3}};
    for (size_t i = 0; i < sizeof lb / sizeof *lb; i++) {
        h.value[LX_HZ_BLUE] = lb[i][0];
        h.value[LX_HZ_THERMAL] = 0;
        lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &h, 1, 0, &r));
        assert_int_equal(r.criterion[LX_HZ_BLUE], (int)lb[i][1]);
        assert_int_equal(r.criterion[LX_HZ_THERMAL], LX_RISK_NONE); /* no subtense: L_R not evaluated */
        assert_int_equal(r.group, (int)lb[i][1]);
    }
    /* L_R: exempt up to 28000/alpha, RG2 up to 71000/alpha; alpha clamped to 0.0017-0.1 rad */
    h.value[LX_HZ_BLUE] = 1;
    h.value[LX_HZ_THERMAL] = 28000 / 0.01;
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &h, 1, 0.01, &r));
    assert_int_equal(r.criterion[LX_HZ_THERMAL], LX_RISK_EXEMPT);
    h.value[LX_HZ_THERMAL] = 71000 / 0.01;
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &h, 1, 0.01, &r));
    assert_int_equal(r.criterion[LX_HZ_THERMAL], LX_RISK_2);
    assert_int_equal(r.group, LX_RISK_2);
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &h, 1, 0.5, &r)); /* alpha 0.5 -> 0.1: limits 280000, 710000 */
    assert_int_equal(r.criterion[LX_HZ_THERMAL], LX_RISK_3);
    /* irradiance: E_S 0.001/0.003/0.03, E_UVA 10/33/100, E_B 1/1/400 W m-2 */
    lx_hazard e = {{0.5, NAN, 0.002, 50}, {1, 0.5, 1, 1}, {0}};
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0, &r));
    assert_int_equal(r.criterion[LX_HZ_BLUE], LX_RISK_EXEMPT);
    assert_int_equal(r.criterion[LX_HZ_ACTINIC], LX_RISK_1);
    assert_int_equal(r.criterion[LX_HZ_UVA], LX_RISK_2);
    assert_int_equal(r.criterion[LX_HZ_THERMAL], LX_RISK_NONE);
    assert_int_equal(r.group, LX_RISK_2);
    e.value[LX_HZ_ACTINIC] = NAN; /* not covered: not evaluated, never exempt */
    e.value[LX_HZ_UVA] = NAN;
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0, &r));
    assert_int_equal(r.criterion[LX_HZ_ACTINIC], LX_RISK_NONE);
    assert_int_equal(r.group, LX_RISK_EXEMPT);
    assert_string_equal(lx_risk_group_name(LX_RISK_2), "RG2");
    assert_string_equal(lx_risk_group_name(LX_RISK_NONE), "");
}

/* PAR is the integral over its band whatever the method asked for: a flat 1 W m-2 nm-1 gives
 * (700^2 - 400^2)/2 / (h c N_A) = 1379.29 umol s-1 m-2 with auto, cie15, exact and linear1nm, on 1 nm
 * and 5 nm data spanning the band exactly or beyond it, per spectrum and as a batch. The CIE 015 sum
 * at 1 nm counted 301 nm of the 300 nm band: 1383.89 (closed form: 301 x 550 / (h c N_A)). */
static void test_par_band_integral(void **state)
{
    lx_ctx *ctx = *state;
    static double l[401], v[401];
    const double ppfd = 0.5 * (700.0 * 700 - 400.0 * 400) * UMOL_PER_J_NM;
    const double epar = 0.5 * (750.0 * 750 - 400.0 * 400) * UMOL_PER_J_NM;
    static const double span[][3] = {{400, 700, 1}, {380, 780, 1}, {380, 780, 5}, {400, 750, 5}};
    static const lx_method meth[] = {LX_METHOD_AUTO, LX_METHOD_CIE15, LX_METHOD_EXACT, LX_METHOD_LINEAR1NM};
    for (size_t i = 0; i < sizeof span / sizeof *span; i++) {
        lx_spd s = flat(l, v, span[i][0], span[i][1], span[i][2]);
        for (size_t m = 0; m < sizeof meth / sizeof *meth; m++) {
            lx_par p;
            lx_assert_ok(ctx, lx_par_compute(ctx, &s, meth[m], &p));
            lx_assert_near(p.ppfd, ppfd, 0, 1e-12);
            lx_assert_near(p.ppfd, 1379.29229, 1e-4, 0);
            if (span[i][1] >= 750) lx_assert_near(p.epar, epar, 0, 1e-12);
        }
        /* the batch path: the same integral (the sample weights are the hat functions' exact integrals) */
        size_t n = s.n;
        static double vb[3 * 401];
        for (size_t k = 0; k < 3 * n; k++) vb[k] = 1.0 + (double)(k / n); /* 1, 2 and 3 W m-2 nm-1 */
        lx_batch b = {3, n, 0, span[i][0], span[i][2], LX_F64, vb};
        lx_par pb[3];
        lx_assert_ok(ctx, lx_par_batch(ctx, &b, NULL, pb));
        for (int k = 0; k < 3; k++) lx_assert_near(pb[k].ppfd, (k + 1) * ppfd, 0, 1e-12);
    }
    /* the CIE 015 sum itself is unchanged for a caller who asks lx_spd_integrate for it */
    lx_spd s = flat(l, v, 400, 700, 1), w;
    double sum;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_PHOTON_PAR, &w));
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s, &w, LX_METHOD_CIE15, &sum));
    lx_assert_near(sum, 301 * 550 * UMOL_PER_J_NM, 0, 1e-12);
    /* an unknown method is still refused */
    lx_par p;
    assert_int_equal(lx_par_compute(ctx, &s, (lx_method)99, &p), LX_EINVAL);
}

/* The source's size decides the blue-light limit (IEC 62471:2006 4.3.3/4.3.4): E_B for a small source
 * (alpha < 0.011 rad), L_B for a larger one, the data turned into the limit's quantity by the
 * source's solid angle Omega = 2 pi (1 - cos(alpha / 2)) (about pi alpha^2 / 4); the result says
 * which limit and which Omega. The LI-COR LI-180 file's E_B = 5.881 W m-2 is RG2 as a small source
 * (1 < E_B <= 400) and RG1 as a 0.1 rad one (L_B = 5.881 / 7.851e-3 = 749 W m-2 sr-1, 100 < L_B <= 1e4). */
static void test_risk_subtense(void **state)
{
    lx_ctx *ctx = *state;
    lx_hazard_risk r;
    lx_hazard e = {{5.881, NAN, NAN, NAN}, {0.99, 0.87, 0, 0.24}, {0}};
    double om01 = 2 * M_PI * (1 - cos(0.05));
    lx_assert_near(om01, M_PI * 0.1 * 0.1 / 4, 0, 1e-3); /* the small-angle area of the disc */
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0, &r)); /* not known: a small source */
    assert_int_equal(r.criterion[LX_HZ_BLUE], LX_RISK_2);
    assert_int_equal(r.limit[LX_HZ_BLUE], LX_HZ_LIMIT_E_B);
    assert_true(r.source_sr == 0);
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0.005, &r)); /* small: E_B */
    assert_int_equal(r.criterion[LX_HZ_BLUE], LX_RISK_2);
    assert_int_equal(r.limit[LX_HZ_BLUE], LX_HZ_LIMIT_E_B);
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0.1, &r)); /* large: L_B = E_B / Omega */
    assert_int_equal(r.criterion[LX_HZ_BLUE], LX_RISK_1);
    assert_int_equal(r.limit[LX_HZ_BLUE], LX_HZ_LIMIT_L_B);
    lx_assert_near(r.source_sr, om01, 0, 1e-15);
    assert_int_equal(r.group, LX_RISK_1);
    /* at the L_B limit 100 exactly (exempt) and just above it (RG1) */
    e.value[LX_HZ_BLUE] = 100 * om01;
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0.1, &r));
    assert_int_equal(r.criterion[LX_HZ_BLUE], LX_RISK_EXEMPT);
    e.value[LX_HZ_BLUE] = 100.01 * om01;
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0.1, &r));
    assert_int_equal(r.criterion[LX_HZ_BLUE], LX_RISK_1);
    /* irradiance with a subtense: L_R = E_R / Omega against 28000 / alpha (exempt), 71000 / alpha (RG2) */
    double om05 = 2 * M_PI * (1 - cos(0.025));
    e.value[LX_HZ_THERMAL] = 28000 / 0.05 * om05;
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0.05, &r));
    assert_int_equal(r.criterion[LX_HZ_THERMAL], LX_RISK_EXEMPT);
    assert_int_equal(r.limit[LX_HZ_THERMAL], LX_HZ_LIMIT_L_R);
    e.value[LX_HZ_THERMAL] = 71000 / 0.05 * om05 * 1.001;
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &e, 0, 0.05, &r));
    assert_int_equal(r.criterion[LX_HZ_THERMAL], LX_RISK_3);
    /* radiance of a small source: E_B = L_B Omega; 5000 W m-2 sr-1 at 0.005 rad is 0.098 W m-2: exempt */
    lx_hazard l = {{5000, NAN, NAN, NAN}, {1, 1, 1, 1}, {0}};
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &l, 1, 0.005, &r));
    assert_int_equal(r.criterion[LX_HZ_BLUE], LX_RISK_EXEMPT);
    assert_int_equal(r.limit[LX_HZ_BLUE], LX_HZ_LIMIT_E_B);
    lx_assert_near(r.source_sr, 2 * M_PI * (1 - cos(0.0025)), 0, 1e-15);
    lx_assert_ok(ctx, lx_hazard_risk_group(ctx, &l, 1, 0, &r)); /* not known: L_B, RG1 */
    assert_int_equal(r.criterion[LX_HZ_BLUE], LX_RISK_1);
    assert_int_equal(r.limit[LX_HZ_BLUE], LX_HZ_LIMIT_L_B);
    assert_true(r.reserved[0] == 0);
    assert_int_equal(lx_hazard_risk_group(ctx, &l, 1, -0.1, &r), LX_EINVAL);
    assert_int_equal(lx_hazard_risk_group(ctx, &l, 1, NAN, &r), LX_EINVAL);
}

static void test_batch_matches(void **state)
{
    lx_ctx *ctx = *state;
    enum { N = 700, NL = 81 }; /* 380-780 nm at 5 nm */
    static double v[N * NL], l[NL];
    for (int j = 0; j < NL; j++) l[j] = 380 + 5 * j;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < NL; j++) v[i * NL + j] = lx_planck(l[j], 1500 + 10 * i) * (1 + 0.1 * sin(0.3 * j + i));
    lx_batch b = {N, NL, 0, 380, 5, LX_F64, v};
    static lx_par pb[N];
    static lx_hazard hb[N];
    lx_assert_ok(ctx, lx_par_batch(ctx, &b, NULL, pb));
    lx_assert_ok(ctx, lx_hazard_batch(ctx, &b, NULL, hb));
    for (int i = 0; i < N; i += 7) {
        lx_spd s = {"s", NL, l, v + i * NL};
        lx_par p;
        lx_hazard h;
        lx_assert_ok(ctx, lx_par_compute(ctx, &s, LX_METHOD_CIE15, &p));
        lx_assert_ok(ctx, lx_hazard_compute(ctx, &s, LX_METHOD_CIE15, &h));
        lx_assert_near(pb[i].ppfd, p.ppfd, 0, 1e-9);
        lx_assert_near(pb[i].epar, p.epar, 0, 1e-9);
        lx_assert_near(pb[i].ypf, p.ypf, 0, 1e-9);
        lx_assert_near(pb[i].photon_efficacy_umol_J, p.photon_efficacy_umol_J, 0, 1e-9);
        lx_assert_near(hb[i].value[LX_HZ_BLUE], h.value[LX_HZ_BLUE], 0, 1e-9);
        assert_true(isnan(hb[i].value[LX_HZ_ACTINIC]) && isnan(h.value[LX_HZ_ACTINIC]));
        for (int k = 0; k < LX_HZ_COUNT; k++) lx_assert_near(hb[i].coverage[k], h.coverage[k], 1e-15, 0);
    }
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, lx_test_ctx_setup, lx_test_ctx_teardown)
    const struct CMUnitTest tests[] = {
        T(test_tables), T(test_actinic_against_icnirp_fit), T(test_par_closed_forms), T(test_hazard_closed_forms),
        T(test_risk_groups), T(test_batch_matches), T(test_par_band_integral), T(test_risk_subtense),
    };
    return cmocka_run_group_tests_name("photobio", tests, NULL, NULL);
}
