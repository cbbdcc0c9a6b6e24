/* test_sources.c - the lighting sources: point, Warn spotlight, Lambertian disk and rectangle
 * (closed forms, stable limits, the five-times rule), the Lambertian reflector, and the inverse
 * problems of solve.c. References are closed forms derived in the comments, or the textbook
 * formulas evaluated in 60-digit decimal arithmetic (Python 3.11 decimal module; script in the
 * comment of each case: the same formula, computed where cancellation cannot hurt). */
#include "lx_test.h"

#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

static void test_point_closed_form(void **state)
{
    lx_ctx *ctx = *state;
    double i, e;
    lx_assert_ok(ctx, lx_point_intensity(ctx, 1000, &i));
    /* I = F / (4 pi) = 1000 / 4 pi = 79.577471545947667 cd */
    lx_assert_near(i, 1000 / (4 * PI), 0, 1e-15);
    lx_assert_ok(ctx, lx_point_illuminance(ctx, i, 2, 30 * DEG, &e));
    /* issue 4 "must show": E = (1000/4pi) cos 30 / 2^2 = 17.229028 lx (decimal: 17.2290279819310015) */
    lx_assert_near(e, 17.2290279819310015, 0, 1e-14);
    lx_assert_near(e, 17.229028, 5e-7, 0);
}

static void test_point_distances(void **state)
{
    lx_ctx *ctx = *state;
    double e = -1;
    /* inverse square law at the extremes of the contract: E = I / d^2 exactly */
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 1, 1e-6, 0, &e));
    lx_assert_near(e, 1e12, 0, 1e-15);
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 1, 1e6, 0, &e));
    lx_assert_near(e, 1e-12, 0, 1e-15);
    /* distance 0 or negative or NaN: an input error, not infinity; output untouched */
    e = 42;
    assert_int_equal(lx_point_illuminance(ctx, 1, 0, 0, &e), LX_EINVAL);
    assert_int_equal(lx_point_illuminance(ctx, 1, -1, 0, &e), LX_EINVAL);
    assert_int_equal(lx_point_illuminance(ctx, 1, NAN, 0, &e), LX_EINVAL);
    assert_int_equal(lx_point_illuminance(ctx, 1, INFINITY, 0, &e), LX_EINVAL);
    assert_true(e == 42);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "distance"));
}

static void test_point_grazing_backfacing(void **state)
{
    lx_ctx *ctx = *state;
    double e;
    /* grazing: cos(pi/2 as a double) = 6.1e-17: E = I cos / d^2 is tiny and >= 0 */
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 100, 1, 90 * DEG, &e));
    assert_true(e >= 0 && e < 1e-14);
    /* back-facing receivers get nothing, never a negative illuminance */
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 100, 1, 120 * DEG, &e));
    assert_true(e == 0.0);
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 100, 1, 180 * DEG, &e));
    assert_true(e == 0.0);
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 100, 1, -100 * DEG, &e));
    assert_true(e == 0.0);
    /* cosine law: 60 deg halves it (cos 60 = 1/2) */
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 100, 1, 60 * DEG, &e));
    lx_assert_near(e, 50, 0, 1e-14);
}

/* 20-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun table 25.4). */
static const double gl_x[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195, 0.5108670019508271,
                                0.6360536807265150, 0.7463319064601508, 0.8391169718222188, 0.9122344282513259,
                                0.9639719272779138, 0.9931285991850949};
static const double gl_w[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183820, 0.1316886384491766,
                                0.1181945319615184, 0.1019301198172404, 0.0832767415767048, 0.0626720483341091,
                                0.0406014298003869, 0.0176140071391521};

static void test_warn_flux_recovered(void **state)
{
    lx_ctx *ctx = *state;
    const double S[] = {0, 1, 10, 1000, 1e5, 1e6};
    for (size_t k = 0; k < sizeof S / sizeof S[0]; k++) {
        /* Phi = 2 pi int_0^{pi/2} I(t) sin t dt; the lobe has width ~ 1/sqrt(S+1) rad, so integrate in
         * panels of a quarter of that width (up to 60 widths, where cos^S < e^-1800) and then coarser
         * panels to pi/2: 20-point Gauss-Legendre per panel resolves the lobe for every S. */
        double w = 1 / sqrt(S[k] + 1), edge = fmin(PI / 2, 60 * w);
        double sum = 0, peak = 0;
        int panels = (int)ceil(edge / (0.25 * w));
        for (int p = 0; p < panels + 64; p++) {
            double a, b;
            if (p < panels) {
                a = edge * p / panels;
                b = edge * (p + 1) / panels;
            } else {
                if (edge >= PI / 2) break;
                a = edge + (PI / 2 - edge) * (p - panels) / 64;
                b = edge + (PI / 2 - edge) * (p - panels + 1) / 64;
            }
            double c = 0.5 * (a + b), h = 0.5 * (b - a);
            for (int i = 0; i < 10; i++)
                for (int sgn = -1; sgn <= 1; sgn += 2) {
                    double t = c + sgn * h * gl_x[i], I;
                    lx_assert_ok(ctx, lx_warn_intensity(ctx, 1000, S[k], t, &peak, &I));
                    sum += gl_w[i] * h * I * sin(t);
                }
        }
        /* the definition of c = (S+1)/(2 pi) Phi makes the integral exactly Phi = 1000 lm */
        lx_assert_near(2 * PI * sum, 1000, 0, 1e-9);
        lx_assert_near(peak, (S[k] + 1) / (2 * PI) * 1000, 0, 1e-15);
    }
}

/* The flux within a cone: 2 pi int_0^A I(t) sin t dt by 20-point Gauss-Legendre on 400 panels
 * against the closed form F (1 - cos^(S+1) A) of lx_warn_cone_flux; and its ends. */
static void test_warn_cone(void **state)
{
    lx_ctx *ctx = *state;
    const double S[] = {0, 1, 28.8938, 1000};
    const double A[] = {1 * DEG, 12.5 * DEG, 45 * DEG, 89.9 * DEG};
    for (size_t k = 0; k < 4; k++)
        for (size_t j = 0; j < 4; j++) {
            double sum = 0, peak, I;
            for (int p = 0; p < 400; p++) {
                double c = A[j] * (p + 0.5) / 400, h = 0.5 * A[j] / 400;
                for (int i = 0; i < 10; i++)
                    for (int sgn = -1; sgn <= 1; sgn += 2) {
                        double t = c + sgn * h * gl_x[i];
                        lx_assert_ok(ctx, lx_warn_intensity(ctx, 800, S[k], t, &peak, &I));
                        sum += gl_w[i] * h * I * sin(t);
                    }
            }
            double cf, fr;
            lx_assert_ok(ctx, lx_warn_cone_flux(ctx, 800, S[k], A[j], &cf, &fr));
            lx_assert_near(cf, 2 * PI * sum, 1e-12, 1e-11);
            lx_assert_near(fr, cf / 800, 0, 1e-15);
        }
    double cf, fr;
    /* S = 1 (Lambertian) at 60 deg: 1 - cos^2 = 3/4; S = 0 (uniform hemisphere): 1 - cos A */
    lx_assert_ok(ctx, lx_warn_cone_flux(ctx, 800, 1, 60 * DEG, &cf, &fr));
    lx_assert_near(fr, 0.75, 0, 1e-15);
    lx_assert_ok(ctx, lx_warn_cone_flux(ctx, 800, 0, 60 * DEG, &cf, &fr));
    lx_assert_near(fr, 0.5, 0, 1e-15);
    /* the whole lobe from 90 deg on; nothing in a cone of 0 */
    lx_assert_ok(ctx, lx_warn_cone_flux(ctx, 800, 5, 120 * DEG, &cf, &fr));
    lx_assert_near(cf, 800, 0, 0);
    lx_assert_ok(ctx, lx_warn_cone_flux(ctx, 800, 5, 0, &cf, &fr));
    assert_true(fr == 0);
    /* a tiny cone of a huge exponent, S = 1e6, A = 1e-3 rad: cos A rounds away 2e-10 of ln cos A,
     * so the closed form needs log1p(-2 sin^2(A/2)) */
    lx_assert_ok(ctx, lx_warn_cone_flux(ctx, 1, 1e6, 1e-3, &cf, &fr));
    double A2 = 1e-6; /* ln cos A = -A^2/2 - A^4/12 - A^6/45 - ... (the series, exact to 1e-30 here) */
    lx_assert_near(fr, -expm1(-(1e6 + 1) * (A2 / 2 + A2 * A2 / 12 + A2 * A2 * A2 / 45)), 0, 1e-14);
    assert_int_equal(lx_warn_cone_flux(ctx, 800, 5, -0.1, &cf, &fr), LX_EINVAL);
    assert_int_equal(lx_warn_cone_flux(ctx, 800, -1, 0.1, &cf, &fr), LX_EINVAL);
}

static void test_warn_extremes(void **state)
{
    lx_ctx *ctx = *state;
    const double S[] = {0, 1, 10, 1000, 1e5, 1e6, 1e300};
    const double A[] = {0, 1e-9, 1e-3, 0.1, 1, 30, 60, 89, 89.999999, 90, 90.000001, 135, 180};
    for (size_t k = 0; k < sizeof S / sizeof S[0]; k++)
        for (size_t j = 0; j < sizeof A / sizeof A[0]; j++) {
            double peak, I;
            lx_assert_ok(ctx, lx_warn_intensity(ctx, 1000, S[k], A[j] * DEG, &peak, &I));
            assert_true(isfinite(I) && I >= 0 && I <= peak);
            if (A[j] > 90) assert_true(I == 0.0);
        }
    double I, peak;
    /* S = 0: uniform over the forward hemisphere, c = Phi / 2 pi */
    lx_assert_ok(ctx, lx_warn_intensity(ctx, 2 * PI, 0, 80 * DEG, &peak, &I));
    lx_assert_near(I, 1, 0, 1e-15);
    /* S = 1: Lambertian, I = (Phi / pi) cos a; at 60 deg: Phi / (2 pi) */
    lx_assert_ok(ctx, lx_warn_intensity(ctx, PI, 1, 60 * DEG, &peak, &I));
    lx_assert_near(I, 0.5, 0, 1e-14);
    /* S = 1e6 at 1 mrad: cos^S = exp(S ln cos 1e-3) = exp(1e6 (-5e-7 - 4.1667e-14 ...)) =
     * exp(-0.50000004166668) (series ln cos x = -x^2/2 - x^4/12 - x^6/45): a naive pow(cos x, S)
     * is off by S * 1e-16 relative; the stable lobe matches to 1e-13 */
    double x = 1e-3, lnc = -x * x / 2 - pow(x, 4) / 12 - pow(x, 6) / 45;
    lx_assert_near(lx_warn_lobe(1e6, x), exp(1e6 * lnc), 0, 1e-13);
    /* 5 deg at S = 1e6: cos^S underflows to 0, correctly */
    assert_true(lx_warn_lobe(1e6, 5 * DEG) == 0.0);
    /* invalid exponent */
    assert_int_equal(lx_warn_intensity(ctx, 1000, -1, 0, &peak, &I), LX_EINVAL);
    assert_int_equal(lx_warn_intensity(ctx, 1000, NAN, 0, &peak, &I), LX_EINVAL);
}

static void test_warn_beam(void **state)
{
    lx_ctx *ctx = *state;
    double s, beam;
    /* S = 1 (Lambertian): half-peak at 60 deg, beam 120 deg (cos 60 = 1/2) */
    lx_assert_ok(ctx, lx_warn_exponent_from_beam(ctx, 120 * DEG, &s));
    lx_assert_near(s, 1, 0, 1e-13);
    lx_assert_ok(ctx, lx_warn_beam_from_exponent(ctx, 1, &beam));
    lx_assert_near(beam, 120 * DEG, 0, 1e-14);
    /* round trip at a narrow beam, and the defining property cos^S(beam/2) = 1/2 */
    lx_assert_ok(ctx, lx_warn_exponent_from_beam(ctx, 10 * DEG, &s));
    lx_assert_near(lx_warn_lobe(s, 5 * DEG), 0.5, 0, 1e-14);
    lx_assert_ok(ctx, lx_warn_beam_from_exponent(ctx, s, &beam));
    lx_assert_near(beam, 10 * DEG, 0, 1e-13);
}

static void test_disk_closed_form(void **state)
{
    lx_ctx *ctx = *state;
    lx_source_result r;
    /* issue 4: L = 1000 cd/m2, R = 0.5 m, on axis at h = 1 m: pi L R^2/(R^2 + h^2) = 200 pi = 628.3185 lx */
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, 1, 0, LX_MODEL_EXACT, &r));
    lx_assert_near(r.exact_lx, 200 * PI, 0, 1e-15);
    lx_assert_near(r.illuminance_lx, 628.3185, 5e-5, 0);
    assert_int_equal(r.model, LX_MODEL_EXACT);
    /* point model error at h = 5 D on axis: point/exact - 1 = (R^2 + h^2)/h^2 - 1 = R^2/h^2 = 1/100 */
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, 5, 0, LX_MODEL_AUTO, &r));
    lx_assert_near(r.point_error, 0.01, 0, 1e-13);
    assert_int_equal(r.near_field, 1); /* the point model misses 1e-4 */
    lx_assert_near(r.largest_dimension_m, 1, 0, 0);
    /* auto is exact at any distance (the closed form costs what the point model costs): at 5, 10
     * and 1000 diameters; the point model is one flag away with its error beside it */
    static const double hs[3] = {5, 10, 1000};
    for (int k = 0; k < 3; k++) {
        lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, hs[k], 0, LX_MODEL_AUTO, &r));
        assert_int_equal(r.model, LX_MODEL_EXACT);
        lx_assert_near(r.illuminance_lx, 1000 * PI * 0.25 / (0.25 + hs[k] * hs[k]), 0, 1e-14);
        assert_int_equal(r.near_field, hs[k] < 50); /* R^2 / h^2 > 1e-4 */
        lx_source_result p;
        lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, hs[k], 0, LX_MODEL_POINT, &p));
        assert_int_equal(p.model, LX_MODEL_POINT);
        lx_assert_near(p.illuminance_lx, 1000 * PI * 0.25 / (hs[k] * hs[k]), 0, 1e-14);
        lx_assert_near(p.point_error, 0.25 / (hs[k] * hs[k]), 1e-15, 1e-12);
    }
}

static void test_disk_references(void **state)
{
    lx_ctx *ctx = *state;
    /* E/L and point_error from F = (1/2)[1 - (h^2+r^2-R^2)/sqrt((h^2+r^2+R^2)^2 - 4r^2R^2)] evaluated in
     * 60-digit decimal (no cancellation at that precision); point = pi R^2 h^2/(h^2+r^2)^2 */
    static const struct { double R, h, r, e, err; } c[] = {
        {1, 1e6, 0, 3.14159265358665164581e-12, 1.00000000000000000000e-12},
        {1, 1e6, 3e5, 2.64421568351790672637e-12, 6.90177594478712498954e-13},
        {1, 1e3, 2, 3.14156437948524533109e-6, 9.99984000119999240005e-7},
        {1e-3, 1e3, 0.5, 3.14159108279091390405e-12, 9.99999000000437500344e-13},
        {0.5, 1e-9, 0.25, 3.14159265358979321612e+0, -9.99999999999999936000e-1},
        {0.5, 1, 0.5, 4.60075592255305057477e-1, 9.25483399593904156165e-2},
        {0.5, 1, 2, 3.36939189517753886262e-2, -6.76084138249945256842e-2},
        {0.5, 0.01, 2, 5.58472596517152005184e-6, -1.21086133120442764422e-1},
        {1, 2, 1e3, 1.25662952163239828104e-11, -1.99997900013599926400e-6},
        {0.3, 1e-6, 0.3, 1.57079370880101863137e+0, -9.99999999977777740741e-1},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        lx_source_result r;
        lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1, c[i].R, c[i].h, c[i].r, LX_MODEL_EXACT, &r));
        lx_assert_near(r.exact_lx, c[i].e, 0, 1e-13);
        /* point_error = ratio - 1: absolute accuracy a few ulp of 1 */
        lx_assert_near(r.point_error, c[i].err, 1e-15, 1e-12);
        assert_true(r.exact_lx >= 0 && r.point_lx >= 0);
    }
}

static void test_disk_limits(void **state)
{
    lx_ctx *ctx = *state;
    lx_source_result r;
    /* h -> 0 under the disk: the receiver sees a hemisphere of luminance L: E -> pi L, not NaN */
    const double hs[] = {1e-3, 1e-6, 1e-9, 1e-12};
    for (size_t i = 0; i < 4; i++) {
        lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, hs[i], 0.2, LX_MODEL_EXACT, &r));
        assert_true(isfinite(r.exact_lx));
        lx_assert_near(r.exact_lx, 1000 * PI, 0, 1e-2 * hs[i] / 1e-3 + 1e-15);
    }
    /* h >> R on axis: exact = pi L R^2/(R^2+h^2), point = pi L R^2/h^2, so point_error = R^2/h^2
     * exactly; a cancelling formula would lose every digit of it */
    const double hr[] = {1e2, 1e4, 1e6, 1e7};
    for (size_t i = 0; i < 4; i++) {
        lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1, 0.1, 0.1 * hr[i], 0, LX_MODEL_EXACT, &r));
        lx_assert_near(r.exact_lx, PI * 0.01 / (0.01 + 0.01 * hr[i] * hr[i]), 0, 1e-14);
        lx_assert_near(r.point_error, 1 / (hr[i] * hr[i]), 1e-15, 1e-9); /* ratio - 1: a few ulp of 1 */
        if (hr[i] >= 1e7) lx_assert_near(r.exact_lx, r.point_lx, 0, 1e-12); /* physical error 1e-14 */
    }
    /* h = 0 is the coplanar limit of those: pi L on the disk, pi L / 2 on its rim, 0 outside */
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, 0, 0.2, LX_MODEL_AUTO, &r));
    lx_assert_near(r.illuminance_lx, 1000 * PI, 0, 1e-15);
    lx_assert_near(r.point_error, -1, 0, 0); /* the point model gives 0 there */
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, 0, 0.5, LX_MODEL_AUTO, &r));
    lx_assert_near(r.illuminance_lx, 1000 * PI / 2, 0, 1e-15);
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, 0, 0.7, LX_MODEL_AUTO, &r));
    assert_true(r.illuminance_lx == 0);
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, 0, 0, LX_MODEL_AUTO, &r));
    assert_true(isnan(r.point_lx)); /* the point model is undefined at its own centre */
    /* ... and the limit of small heights: at 1e-12 m, within 1e-12 */
    lx_source_result s;
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, 0.5, 1e-12, 0.5, LX_MODEL_EXACT, &s));
    lx_assert_near(s.exact_lx, 1000 * PI / 2, 0, 1e-9);
    /* invalid input */
    assert_int_equal(lx_disk_illuminance(ctx, 1, 0.5, -1, 0, LX_MODEL_EXACT, &r), LX_EINVAL);
    assert_int_equal(lx_disk_illuminance(ctx, 1, 0.5, NAN, 0, LX_MODEL_EXACT, &r), LX_EINVAL);
    assert_int_equal(lx_disk_illuminance(ctx, 1, 0, 1, 0, LX_MODEL_EXACT, &r), LX_EINVAL);
    assert_int_equal(lx_disk_illuminance(ctx, -1, 1, 1, 0, LX_MODEL_EXACT, &r), LX_EINVAL);
}

static void test_rect_closed_form(void **state)
{
    lx_ctx *ctx = *state;
    lx_source_result r;
    /* issue 4: square at h = 5 side, centre: point error 1.3325 % (decimal closed form 1.33245778056780e-2) */
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1, 1, 1, 5, 0, 0, LX_MODEL_AUTO, &r));
    lx_assert_near(r.point_error, 1.33245778056780250807e-2, 0, 1e-12);
    lx_assert_near(r.point_error * 100, 1.3325, 5e-5, 0);
    /* the centre is four corner rectangles (a/2 x b/2) */
    lx_source_result c;
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1, 0.5, 0.5, 5, 0.25, 0.25, LX_MODEL_EXACT, &c));
    lx_assert_near(r.exact_lx, 4 * c.exact_lx, 0, 1e-15);
    /* h -> 0: centre sees the whole hemisphere (E -> pi L), a corner a quarter of it (pi L / 4) */
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1, 2, 1e-9, 0, 0, LX_MODEL_EXACT, &r));
    lx_assert_near(r.exact_lx, 1000 * PI, 0, 1e-8);
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1, 2, 1e-12, 0.5, 1, LX_MODEL_EXACT, &r));
    lx_assert_near(r.exact_lx, 1000 * PI / 4, 0, 1e-11);
    /* auto is exact at any distance; near_field says the point model misses 1e-4 */
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1, 1, 1, 50, 0, 0, LX_MODEL_AUTO, &r));
    assert_int_equal(r.model, LX_MODEL_EXACT);
    lx_assert_near(r.illuminance_lx, r.exact_lx, 0, 0);
    /* the unit square's point error is about (1/3)(a/h)^2 (1.3325 % at 5 sides, above): 1.3e-4 at
     * 50 sides, 6.8e-5 at 70 */
    assert_int_equal(r.near_field, 1);
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1, 1, 1, 70, 0, 0, LX_MODEL_AUTO, &r));
    assert_int_equal(r.near_field, 0);
    /* h = 0: the coplanar limit, pi L inside, pi L / 2 on an edge, pi L / 4 at a corner, 0 outside */
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1, 2, 0, 0.1, 0.2, LX_MODEL_AUTO, &r));
    lx_assert_near(r.illuminance_lx, 1000 * PI, 0, 1e-15);
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1, 2, 0, 0.5, 0.2, LX_MODEL_AUTO, &r));
    lx_assert_near(r.illuminance_lx, 500 * PI, 0, 1e-15);
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1, 2, 0, 0.5, 1, LX_MODEL_AUTO, &r));
    lx_assert_near(r.illuminance_lx, 250 * PI, 0, 1e-15);
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1, 2, 0, 0.6, 0, LX_MODEL_AUTO, &r));
    assert_true(r.illuminance_lx == 0);
}

static void test_rect_references(void **state)
{
    lx_ctx *ctx = *state;
    /* E/L by the corner form (Howell B-3) superposed with signs, in 60-digit decimal */
    static const struct { double a, b, h, x, y, e, err; } c[] = {
        {1, 2, 1, 3, 0, 2.01146414960626626378e-2, -5.69940538513217447174e-3},
        {1, 2, 1, 3, 4, 3.19441906622414987748e-3, -7.38285051767207594556e-2},
        {1, 1, 0.01, 0.6, 0, 7.51076411643638215869e-3, -8.97323836103446001844e-1},
        {1, 1, 1e6, 0, 0, 9.99999999999666666667e-13, 3.33333333333327777778e-13},
        {2, 1, 1, 0.5, 0.25, 9.51869135719513479191e-1, 2.19703096632827616831e-1},
        {1, 1, 1, 10, 10, 2.48336578578218588561e-5, -3.29372662823922066337e-3},
        {1, 1, 1e-3, 0.2, 0.1, 3.14157784634223373348e+0, -9.99872680538237913782e-1},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        lx_source_result r;
        lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1, c[i].a, c[i].b, c[i].h, c[i].x, c[i].y, LX_MODEL_EXACT, &r));
        lx_assert_near(r.exact_lx, c[i].e, 0, 1e-12);
        assert_true(r.exact_rel_error <= 1e-12);
        lx_assert_near(r.point_error, c[i].err, 1e-15, 1e-10);
    }
    lx_source_result r;
    /* h >> size: matches the point model to 1e-12 (physical error (a^2+b^2)/(6 h^2) ~ 3e-13 here) */
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1, 1, 1, 1e6, 0, 0, LX_MODEL_EXACT, &r));
    lx_assert_near(r.exact_lx, r.point_lx, 0, 1e-12);
    assert_int_equal(lx_rect_illuminance(ctx, 1, 1, 1, -1e-3, 0, 0, LX_MODEL_EXACT, &r), LX_EINVAL);
    assert_int_equal(lx_rect_illuminance(ctx, 1, 1, -1, 1, 0, 0, LX_MODEL_EXACT, &r), LX_EINVAL);
}

static void test_lambertian_reflector(void **state)
{
    lx_ctx *ctx = *state;
    double L;
    /* L = rho E / pi: a white (rho = 0.8) wall under 500 lx has 400/pi = 127.32 cd/m2 */
    lx_assert_ok(ctx, lx_lambertian_luminance(ctx, 0.8, 500, &L));
    lx_assert_near(L, 400 / PI, 0, 1e-15);
    /* energy balance: that reflector, seen as a huge disk at h -> 0, gives back E' = pi L = rho E */
    lx_source_result r;
    lx_assert_ok(ctx, lx_disk_illuminance(ctx, L, 1e3, 1e-3, 0, LX_MODEL_EXACT, &r));
    lx_assert_near(r.exact_lx, 0.8 * 500, 0, 1e-11);
    assert_int_equal(lx_lambertian_luminance(ctx, 1.5, 500, &L), LX_EINVAL);
}

static void test_solve(void **state)
{
    lx_ctx *ctx = *state;
    double d, i, f, e;
    /* d = sqrt(I / E): 2000 cd for 500 lx -> 2 m */
    lx_assert_ok(ctx, lx_solve_distance(ctx, 500, 2000, 0, &d));
    lx_assert_near(d, 2, 0, 1e-15);
    /* I = E d^2 / cos b: 500 lx at 2 m, 60 deg incidence -> 4000 cd */
    lx_assert_ok(ctx, lx_solve_intensity(ctx, 500, 2, 60 * DEG, &i));
    lx_assert_near(i, 4000, 0, 1e-14);
    /* isotropic: F = 4 pi E d^2 */
    lx_assert_ok(ctx, lx_solve_flux(ctx, 500, 2, 0, -1, 0, &f));
    lx_assert_near(f, 8000 * PI, 0, 1e-15);
    /* Warn: forward check through lx_warn_intensity and lx_point_illuminance */
    lx_assert_ok(ctx, lx_solve_flux(ctx, 300, 3, 10 * DEG, 20, 15 * DEG, &f));
    lx_assert_ok(ctx, lx_warn_intensity(ctx, f, 20, 15 * DEG, NULL, &i));
    lx_assert_ok(ctx, lx_point_illuminance(ctx, i, 3, 10 * DEG, &e));
    lx_assert_near(e, 300, 0, 1e-13);
    /* no solution behind the receiver or outside the beam */
    assert_int_equal(lx_solve_distance(ctx, 500, 2000, 100 * DEG, &d), LX_ERANGE);
    assert_int_equal(lx_solve_flux(ctx, 500, 2, 0, 1e6, 10 * DEG, &f), LX_ERANGE);
    assert_int_equal(lx_solve_distance(ctx, 0, 2000, 0, &d), LX_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_point_closed_form),  cmocka_unit_test(test_point_distances),
        cmocka_unit_test(test_point_grazing_backfacing), cmocka_unit_test(test_warn_flux_recovered),
        cmocka_unit_test(test_warn_extremes),      cmocka_unit_test(test_warn_beam),
        cmocka_unit_test(test_warn_cone),
        cmocka_unit_test(test_disk_closed_form),   cmocka_unit_test(test_disk_references),
        cmocka_unit_test(test_disk_limits),        cmocka_unit_test(test_rect_closed_form),
        cmocka_unit_test(test_rect_references),    cmocka_unit_test(test_lambertian_reflector),
        cmocka_unit_test(test_solve),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
