/* test_cct_fast.c - the fast CCT solver (src/spectral/cct_fast.c, lx_cct_from_uv_batch) against
 * its references: Planck's law itself (a blackbody's own uv must come back as its temperature:
 * round trip) and the exact solver lx_cct_from_uv (the same nearest point to rounding), for both
 * observers, on the locus, off it up to |Duv| 0.09 and far from it (where the batch hands over to
 * the exact solver and must say exactly what it says, NaN for LX_ERANGE). */
#include "lx_test.h"

#include <string.h>

static unsigned long long rng = 0x9E3779B97F4A7C15ull;
static double uniform(void) /* [0, 1) */
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

/* Round trip: T from 1000 K to 100000 K (2000 log-spaced values and 2000 random ones) through
 * Planck's law and back: |dT| < 1e-6 K (README: the exact solver's accuracy) and |Duv| < 1e-12. */
static void test_round_trip(void **state)
{
    lx_ctx *ctx = *state;
    enum { N = 4000 };
    static double u[N], v[N], T[N], cct[N], duv[N];
    for (int obs = 0; obs < 2; obs++) {
        lx_observer o = obs ? LX_OBSERVER_10 : LX_OBSERVER_2;
        for (int i = 0; i < N; i++) {
            double f = i < N / 2 ? (double)i / (N / 2 - 1) : uniform();
            T[i] = 1000 * pow(100, f);
            lx_assert_ok(ctx, lx_planck_uv(ctx, o, T[i], &u[i], &v[i]));
        }
        lx_assert_ok(ctx, lx_cct_from_uv_batch(ctx, o, N, u, v, cct, duv));
        double worst = 0;
        for (int i = 0; i < N; i++) {
            lx_assert_near(cct[i], T[i], 1e-6, 0);
            lx_assert_near(duv[i], 0, 1e-12, 0);
            if (fabs(cct[i] - T[i]) > worst) worst = fabs(cct[i] - T[i]);
        }
        print_message("observer %d: round trip worst |dT| %.3g K over 1000-100000 K\n", obs ? 10 : 2, worst);
    }
}

/* Off the locus: points at |Duv| <= 0.09 along the locus normal at random T in 950-110000 K; the
 * fast answer against lx_cct_from_uv on the same (u, v): |dT| < 1e-10 relative, |dDuv| < 1e-12 (measured:
 * 1e-11 and 8e-16, at 0.09 from the locus above 40000 K where the tangent turns slowest). */
static void test_against_exact(void **state)
{
    lx_ctx *ctx = *state;
    enum { N = 3000 };
    static double u[N], v[N], cct[N], duv[N];
    for (int obs = 0; obs < 2; obs++) {
        lx_observer o = obs ? LX_OBSERVER_10 : LX_OBSERVER_2;
        for (int i = 0; i < N; i++) {
            double T = 950 * pow(110000.0 / 950, uniform()), d = (2 * uniform() - 1) * 0.09;
            if (i % 10 == 0) d = i % 20 ? 0.05 : -0.05; /* the validity edge */
            double u0, v0, u1, v1, uc, vc;
            lx_assert_ok(ctx, lx_planck_uv(ctx, o, T * (1 - 1e-5), &u0, &v0));
            lx_assert_ok(ctx, lx_planck_uv(ctx, o, T * (1 + 1e-5), &u1, &v1));
            lx_assert_ok(ctx, lx_planck_uv(ctx, o, T, &uc, &vc));
            double tl = hypot(u1 - u0, v1 - v0), nu = -(v1 - v0) / tl, nv = (u1 - u0) / tl;
            u[i] = uc + d * nu;
            v[i] = vc + d * nv;
        }
        lx_assert_ok(ctx, lx_cct_from_uv_batch(ctx, o, N, u, v, cct, duv));
        double wT = 0, wD = 0;
        for (int i = 0; i < N; i++) {
            double T, d;
            lx_assert_ok(ctx, lx_cct_from_uv(ctx, o, u[i], v[i], &T, &d));
            lx_assert_near(cct[i], T, 0, 1e-10);
            lx_assert_near(duv[i], d, 1e-12, 0);
            if (fabs(cct[i] - T) / T > wT) wT = fabs(cct[i] - T) / T;
            if (fabs(duv[i] - d) > wD) wD = fabs(duv[i] - d);
        }
        print_message("observer %d: worst |dT|/T %.3g, |dDuv| %.3g against the exact solver\n", obs ? 10 : 2, wT, wD);
    }
}

/* Anywhere in the diagram (u 0-0.65, v 0-0.6), the ends of the range and NaN: where the fast path
 * does not answer, the batch gives what the exact solver gives (NaN for LX_ERANGE) and leaves
 * the context's error state alone. */
static void test_far_and_edges(void **state)
{
    lx_ctx *ctx = *state;
    enum { N = 2000 };
    static double u[N], v[N], cct[N], duv[N];
    for (int i = 0; i < N; i++) u[i] = 0.65 * uniform(), v[i] = 0.6 * uniform();
    u[0] = NAN;
    /* beyond the fast table: 600 K, 500000 K */
    lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, 600, &u[1], &v[1]));
    lx_assert_ok(ctx, lx_planck_uv(ctx, LX_OBSERVER_2, 5e5, &u[2], &v[2]));
    lx_assert_ok(ctx, lx_cct_from_uv(ctx, LX_OBSERVER_2, 0.2, 0.3, NULL, NULL)); /* a clean error state */
    lx_assert_ok(ctx, lx_cct_from_uv_batch(ctx, LX_OBSERVER_2, N, u, v, cct, duv));
    assert_string_equal(lx_ctx_errmsg(ctx), "");
    int far = 0;
    for (int i = 0; i < N; i++) {
        double T, d;
        lx_status st = lx_cct_from_uv(ctx, LX_OBSERVER_2, u[i], v[i], &T, &d);
        if (st != LX_OK) {
            assert_true(isnan(cct[i]) && isnan(duv[i]));
            far++;
            continue;
        }
        lx_assert_near(cct[i], T, 0, 1e-9);
        lx_assert_near(duv[i], d, 1e-12, 0);
    }
    lx_assert_near(cct[1], 600, 1e-6, 0);
    lx_assert_near(cct[2], 5e5, 0, 1e-6);
    assert_true(far > 100); /* the sample reaches where no CCT exists */
    assert_int_equal(lx_cct_from_uv_batch(ctx, (lx_observer)7, 1, u, v, cct, duv), LX_EINVAL);
    assert_int_equal(lx_cct_from_uv_batch(ctx, LX_OBSERVER_2, 1, NULL, v, cct, duv), LX_EINVAL);
    lx_assert_ok(ctx, lx_cct_from_uv_batch(ctx, LX_OBSERVER_2, 0, NULL, NULL, NULL, NULL));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_against_exact),
        cmocka_unit_test(test_far_and_edges),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
