/* test_hard_fields.c - hard cases for lighting and radiance fields (issue 9): Warn S = 1e6, grazing
 * incidence, distances 1e-9 to 1e9 m, a 1e9:1 sun-and-sky map, half-precision EXR near 65504, NaN in
 * maps and photometric files, bit-identical CPU results and float OpenCL against the double CPU. */
#include "lx_test.h"

#include <string.h>
#include <unistd.h>

static int have_opencl(lx_ctx *ctx)
{
    lx_cl_device_info info;
    return lx_cl_info(ctx, &info) == LX_OK;
}

/* Hard: cos^S with S = 1e6 underflows for any visible angle and pow(cos a, S) loses all digits
 * near the axis (cos a = 1 - 5e-7). Right answers: ln cos a = -a^2/2 - a^4/12 - a^6/45 - ..., so at
 * a = 1e-3, cos^S = exp(-0.5 - 8.3333e-8 - 2.2e-14); at 0.1 rad exp(-5008) = 0 (not NaN); the beam
 * angle 2 acos(2^(-1/S)) = 2 sqrt(2 ln 2 / S)(1 - ln2/(6S) + ...) = 2.3548198e-3 rad (acos(1 - y) =
 * sqrt(2y)(1 + y/12 + ...) with y = 1 - 2^(-1/S) = e - e^2/2, e = ln2/S). */
static void warn_exponent_1e6(void **state)
{
    lx_ctx *ctx = *state;
    const double S = 1e6, a = 1e-3;
    double lnc = -a * a / 2 - pow(a, 4) / 12 - pow(a, 6) / 45;
    lx_assert_near(lx_warn_lobe(S, a), exp(S * lnc), 0, 1e-12);
    assert_true(lx_warn_lobe(S, 0.1) == 0.0);
    double peak, I;
    lx_assert_ok(ctx, lx_warn_intensity(ctx, 1000, S, 0, &peak, &I));
    lx_assert_near(peak, (S + 1) / (2 * M_PI) * 1000, 0, 1e-15);
    lx_assert_near(I, peak, 0, 1e-15);
    double beam;
    lx_assert_ok(ctx, lx_warn_beam_from_exponent(ctx, S, &beam));
    double ln2 = log(2.0);
    lx_assert_near(beam, 2 * sqrt(2 * ln2 / S) * (1 - ln2 / (6 * S)), 0, 1e-12);
}

/* Hard: at grazing incidence cos(a) is tiny and a cos computed from a rounded angle keeps only the
 * absolute error. Right answer: E = I cos(a) / d^2 with cos(pi/2 - e) = sin(e) ~ e for e = 1e-9
 * (the double pi/2 is 6.1e-17 below pi/2: 6e-8 relative); at a >= pi/2 + 1e-12, E = 0 (back face). */
static void grazing_incidence(void **state)
{
    lx_ctx *ctx = *state;
    double E;
    /* the angle as a double: cos(a) = sin(pi/2 - a) = sin((M_PI/2 - a) + 6.123233995736766e-17), the
     * first difference exact in double (Sterbenz), the second the gap between pi/2 and M_PI/2 */
    double a = M_PI / 2 - 1e-9;
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 1000, 2, a, &E));
    lx_assert_near(E, 1000 * sin((M_PI / 2 - a) + 6.123233995736766e-17) / 4, 0, 1e-12);
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 1000, 2, M_PI / 2 + 1e-12, &E));
    assert_true(E == 0.0);
    /* a rectangle seen from a point in its own plane's edge: receiver 1e-9 m below a 1 x 1 m square,
     * far outside it (foot 10 m from the centre): the configuration factor tends to 0, never < 0
     * (cancellation of the four corner terms would give noise of either sign) */
    lx_source_result r;
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1, 1, 1e-9, 10, 0, LX_MODEL_EXACT, &r));
    assert_true(r.exact_lx >= 0 && r.exact_lx < 1e-6);
}

/* Hard: distances from 1e-9 to 1e9 m square to 1e-18 .. 1e18, and the closed forms subtract nearly
 * equal numbers at both ends. Right answers: E = I/d^2 exactly; on the axis of a disk the
 * configuration factor is R^2 / (R^2 + h^2) (Howell B-13 with r = 0), so E = pi L R^2 / (R^2 + h^2);
 * a square of side a seen on its axis from h has F = (2/pi)[ (a/2)^2... ] -> 1 - O(h/a) as h/a -> 0. */
static void distances_1e_9_to_1e9(void **state)
{
    lx_ctx *ctx = *state;
    double E;
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 1, 1e-9, 0, &E));
    lx_assert_near(E, 1e18, 0, 1e-15);
    lx_assert_ok(ctx, lx_point_illuminance(ctx, 1, 1e9, 0, &E));
    lx_assert_near(E, 1e-18, 0, 1e-15);
    static const double RH[4][2] = {{1e-9, 1e9}, {1e9, 1e-9}, {1, 1e9}, {1e-9, 1}};
    for (int k = 0; k < 4; k++) {
        double R = RH[k][0], h = RH[k][1];
        lx_source_result r;
        lx_assert_ok(ctx, lx_disk_illuminance(ctx, 1000, R, h, 0, LX_MODEL_EXACT, &r));
        double F = R > h ? 1 / (1 + (h / R) * (h / R)) : (R / h) * (R / h) / (1 + (R / h) * (R / h));
        lx_assert_near(r.exact_lx, M_PI * 1000 * F, 0, 1e-12);
        /* far away the point model is right to (R/h)^2 */
        if (R / h < 1e-8) lx_assert_near(r.point_lx, r.exact_lx, 0, 1e-12);
    }
    /* a 1e9 m square 1e-9 m away: E = pi L (1 - 8 h / (pi a) + ...) -> pi L to 1e-12 */
    lx_source_result r;
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1e9, 1e9, 1e-9, 0, 0, LX_MODEL_EXACT, &r));
    lx_assert_near(r.exact_lx, M_PI * 1000, 0, 1e-12);
    /* a 1e-9 m square 1e9 m away: E = L a^2 / h^2 (the point limit) */
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, 1000, 1e-9, 1e-9, 1e9, 0, 0, LX_MODEL_EXACT, &r));
    lx_assert_near(r.exact_lx, 1000 * 1e-18 / 1e18, 0, 1e-9);
    /* zero and non-finite distances are refused, never infinity */
    assert_int_equal(lx_point_illuminance(ctx, 1, 0, 0, &E), LX_EINVAL);
    assert_int_equal(lx_point_illuminance(ctx, 1, NAN, 0, &E), LX_EINVAL);
    assert_int_equal(lx_point_illuminance(ctx, 1, INFINITY, 0, &E), LX_EINVAL);
}

/* The exact moment m_z of pixel row j of a w x h map: (2 pi / w) x integral of sin t cos t dt over
 * the row = (pi / w)(sin^2 t1 - sin^2 t0). */
static double moment_z(int w, int h, int j)
{
    double t0 = j * M_PI / h, t1 = (j + 1) * M_PI / h;
    return M_PI / w * (sin(t1) * sin(t1) - sin(t0) * sin(t0));
}

/* Hard: a sun of radiance 1e9 beside a sky of 1: float storage, sums over 1e5 pixels and the SH
 * projection all see a 1e9:1 range. Right answer: the upper hemisphere of radiance 1 gives pi on an
 * upward normal (integral of cos over the hemisphere), plus the sun pixel's (1e9 - 1) m_z. */
static void sun_and_sky_1e9(void **state)
{
    lx_ctx *ctx = *state;
    const int W = 256, H = 128, js = 20, is = 40;
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, W, H, 1, &m));
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) m->data[j * W + i] = j < H / 2 ? 1.0f : 0.0f;
    m->data[js * W + is] = 1e9f;
    double up[3] = {0, 0, 1}, want = M_PI + (1e9 - 1) * moment_z(W, H, js);
    double E[2];
    lx_irr_opts o = {.method = LX_IRR_BRUTE, .backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 1, up, &o, &E[0]));
    lx_assert_near(E[0], want, 0, 1e-12);
    o.method = LX_IRR_FAST;
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 1, up, &o, &E[1]));
    lx_assert_near(E[1], want, 0, 1e-12);
    /* a normal facing away from the sun: only sky (and no sun) must remain, to 1e-12 of the sky */
    double dn[3];
    lx_envmap_direction(W, H, js + 0.5, is + 0.5, dn);
    for (int c = 0; c < 3; c++) dn[c] = -dn[c];
    double Eb[2];
    o.method = LX_IRR_BRUTE;
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 1, dn, &o, &Eb[0]));
    o.method = LX_IRR_FAST;
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 1, dn, &o, &Eb[1]));
    lx_assert_near(Eb[1], Eb[0], 1e-9, 0); /* a sun term cancelling to 1e-9 of 1e9 x m_z would show here */
    assert_true(Eb[0] >= 0 && Eb[0] < M_PI);
    if (have_opencl(ctx)) { /* float or double device sums against the double CPU: 1e-6 relative */
        o.method = LX_IRR_BRUTE;
        o.backend = LX_BACKEND_OPENCL;
        double Ec;
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 1, up, &o, &Ec));
        lx_assert_near(Ec, want, 0, 1e-6);
    }
    lx_envmap_free(m);
}

/* Hard: half floats end at 65504 (the next value would be 65536 = Inf); values near it are spaced
 * 32 apart. Right answers (IEEE 754 binary16): 65504 and 32768 are exact, 65000 rounds to 64992;
 * a uniform map of 65504 gives E(up) = pi x 65504 over the hemisphere (and over the sphere's upper
 * half only, the lower half 0). A value beyond 65504 must not come back as a finite number. */
static void half_exr_near_65504(void **state)
{
    lx_ctx *ctx = *state;
    char path[] = "/tmp/lx_hard_halfXXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    lx_envmap *m = NULL, *r = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, 64, 32, 1, &m));
    for (int k = 0; k < 64 * 32; k++) m->data[k] = k < 64 * 16 ? 65504.0f : 0.0f;
    m->data[0] = 65000.0f;
    m->data[1] = 32768.0f;
    lx_exr_write_opts wo = {.half = 1};
    lx_assert_ok(ctx, lx_envmap_write_exr(ctx, path, m, &wo));
    lx_assert_ok(ctx, lx_exr_read(ctx, path, &r));
    assert_true(r->data[0] == 64992.0f);
    assert_true(r->data[1] == 32768.0f);
    assert_true(r->data[2] == 65504.0f);
    r->data[0] = r->data[1] = 65504.0f;
    double up[3] = {0, 0, 1}, E;
    lx_irr_opts o = {.method = LX_IRR_FAST};
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, r, 1, up, &o, &E));
    lx_assert_near(E, M_PI * 65504, 0, 1e-12);
    lx_envmap_free(r);
    r = NULL;
    m->data[5] = 70000.0f; /* not representable: Inf in half */
    lx_status st = lx_envmap_write_exr(ctx, path, m, &wo);
    if (st == LX_OK) {
        st = lx_exr_read(ctx, path, &r);
        assert_int_equal(st, LX_EPARSE); /* the reader refuses the Inf pixel, naming it */
        assert_null(r);
    }
    unlink(path);
    lx_envmap_free(m);
}

/* NaN in a map built in memory and in a photometric file: refused, never propagated. */
static void nan_in_maps_and_ies(void **state)
{
    lx_ctx *ctx = *state;
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, 16, 8, 1, &m));
    for (int k = 0; k < 128; k++) m->data[k] = 1.0f;
    m->data[37] = NAN;
    double up[3] = {0, 0, 1}, E = 42;
    for (int meth = LX_IRR_AUTO; meth <= LX_IRR_BRUTE; meth++) {
        lx_irr_opts o = {.method = (lx_irr_method)meth, .backend = LX_BACKEND_CPU};
        lx_status st = lx_irradiance_dirs(ctx, m, 1, up, &o, &E);
        assert_int_not_equal(st, LX_OK);
        assert_true(E == 42);
    }
    lx_envmap_free(m);
    static const char ies[] = "IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 45 90\n0\n100 nan 10\n";
    lx_luminaire *lum = NULL;
    assert_int_equal(lx_luminaire_read_mem(ctx, "nan.ies", ies, sizeof ies - 1, &lum), LX_EPARSE);
    assert_null(lum);
    assert_int_equal(lx_ctx_errline(ctx), 7);
}

/* Same input, same bits on the CPU; the float OpenCL grid table against the double CPU table. */
static void grid_bit_identical_and_parity(void **state)
{
    lx_ctx *ctx = *state;
    lx_lum_model mdl = {.kind = LX_LUM_MODEL_WARN, .flux_lm = 1000, .exponent = 12};
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_from_model(ctx, &mdl, &lum));
    lx_placement pl[2] = {{lum, {0, 0, 3}, {0, 0, -1}, 0}, {lum, {2, 1, 2.5}, {0.3, 0, -1}, 0.4}};
    lx_plane p;
    lx_assert_ok(ctx, lx_plane_axis(ctx, 'z', 0, -4, 4, -4, 4, 0, 101, 101, &p));
    double *pts = NULL;
    size_t n = 0;
    lx_assert_ok(ctx, lx_plane_points(ctx, &p, &pts, &n));
    double *E[3];
    for (int k = 0; k < 3; k++) {
        E[k] = malloc(n * sizeof(double));
        lx_grid_opts o = {.interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU, .threads = k == 1 ? 1 : 2};
        lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 2, pts, n, p.normal, 1, &o, E[k]));
    }
    assert_memory_equal(E[0], E[1], n * sizeof(double));
    assert_memory_equal(E[0], E[2], n * sizeof(double));
    if (have_opencl(ctx)) {
        double emax = 0;
        for (size_t i = 0; i < n; i++) emax = fmax(emax, E[0][i]);
        lx_grid_opts o = {.interp = LX_INTERP_TABLE, .backend = LX_BACKEND_OPENCL, .fp32 = 1};
        lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 2, pts, n, p.normal, 1, &o, E[1]));
        /* float geometry and table: 1e-5 of the peak (float eps 6e-8 x ~100 operations) */
        for (size_t i = 0; i < n; i++) lx_assert_near(E[1][i], E[0][i], 1e-5 * emax, 0);
    }
    for (int k = 0; k < 3; k++) free(E[k]);
    lx_plane_points_free(pts);
    lx_luminaire_free(lum);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(warn_exponent_1e6, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(grazing_incidence, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(distances_1e_9_to_1e9, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(sun_and_sky_1e9, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(half_exr_near_65504, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(nan_in_maps_and_ies, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(grid_bit_identical_and_parity, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
