/* test_uncertainty.c - measurement uncertainty (lx_spd_uncertainty, lx_unc_model_*): the generator
 * against Random123's known answers, the integration weights against the integrals, closed forms
 * (white noise on a flat spectrum, a pure scale, a wavelength shift of a blackbody against finite
 * differences of the exact CCT), GUM against Monte Carlo (JCGM 101 8), reproducibility, Kaerhae et
 * al.'s correlated against uncorrelated u(CCT), CRI and TM-30 against finite differences of
 * lx_cri_compute / lx_tm30_compute, bad input, and the instrument exports of ../shared. Trials
 * shrink under the slow tools (LX_TEST_SLOW). */
#include "lx_test.h"

#include "spectral/unc_private.h"

static int slow(void)
{
    const char *s = getenv("LX_TEST_SLOW");
    int v = s ? atoi(s) : 1;
    return v > 1 ? v : 1;
}

/* trials for a test: n natively, fewer under valgrind and the sanitizers (at least lo) */
static size_t trials(size_t n, size_t lo)
{
    size_t t = n / (size_t)slow();
    return t > lo ? t : lo;
}

/* 380-780 nm at step nm */
static size_t grid(double step, double *lam)
{
    size_t n = (size_t)((780 - 380) / step + 0.5) + 1;
    for (size_t i = 0; i < n; i++) lam[i] = 380 + step * (double)i;
    return n;
}

static lx_unc_model *model1(lx_ctx *ctx, lx_unc_kind kind, double sigma)
{
    lx_unc_model *m = NULL;
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &m));
    lx_unc_component c;
    memset(&c, 0, sizeof c);
    c.kind = kind, c.sigma = sigma;
    lx_assert_ok(ctx, lx_unc_model_add(ctx, m, &c));
    return m;
}

static lx_unc_result *run(lx_ctx *ctx, const lx_spd *s, const lx_unc_model *m, lx_unc_method method, size_t n, unsigned q)
{
    lx_unc_opts o;
    memset(&o, 0, sizeof o);
    o.method = method, o.trials = n, o.quantities = q, o.seed = 7;
    lx_unc_result *r = NULL;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, s, m, &o, &r));
    return r;
}

/* ---- the generator ---- */

/* Random123 1.09 kat_vectors, philox4x32 10 rounds (Salmon et al. 2011) */
static void test_philox_known_answers(void **state)
{
    (void)state;
    static const uint32_t kat[3][10] = {
        {0, 0, 0, 0, 0, 0, 0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8},
        {0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff, 0x408f276d, 0x41c83b0e, 0xa20bc7c6,
         0x6d5451fd},
        {0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344, 0xa4093822, 0x299f31d0, 0xd16cfe09, 0x94fdcceb, 0x5001e420,
         0x24126ea1},
    };
    for (int k = 0; k < 3; k++) {
        uint32_t out[4];
        lx__philox4x32(kat[k], kat[k] + 4, out);
        for (int i = 0; i < 4; i++) assert_int_equal(out[i], kat[k][6 + i]);
    }
}

/* The normal deviates: mean 0, variance 1, kurtosis 3 within their sampling error (2e5 of them). */
static void test_normal_moments(void **state)
{
    (void)state;
    double s1 = 0, s2 = 0, s4 = 0;
    size_t n = 0;
    for (uint64_t t = 0; t < 50000; t++) {
        double z[4];
        lx__unc_normal4(42, t, 0, z);
        for (int i = 0; i < 4; i++) s1 += z[i], s2 += z[i] * z[i], s4 += z[i] * z[i] * z[i] * z[i], n++;
    }
    double m = s1 / n, v = s2 / n, k = s4 / n / (v * v);
    lx_assert_near(m, 0.0, 5 / sqrt((double)n), 0);          /* 5 sigma of the mean */
    lx_assert_near(v, 1.0, 5 * sqrt(2.0 / (double)n), 0);    /* var of s2/n: 2/n */
    lx_assert_near(k, 3.0, 5 * sqrt(96.0 / (double)n), 0);   /* var of the kurtosis estimate: 96/n */
    assert_true(fabs(s1) < 1e9); /* finite */
}

/* ---- the integration weights: sum w_i S_i equals lx_spd_integrate for every method ---- */
static void test_integrate_weights(void **state)
{
    lx_ctx *ctx = *state;
    double lam[2000], v[2000], w[2000];
    /* an irregular grid with a smooth spectrum */
    size_t n = 0;
    for (double l = 371.3; l < 791 && n < 2000; l += 0.7 + 0.6 * sin(l)) lam[n] = l, v[n] = 1 + 0.5 * sin(l / 17.0), n++;
    lx_spd s = {"s", n, lam, v}, f;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &f));
    static const lx_method methods[] = {LX_METHOD_EXACT, LX_METHOD_LINEAR1NM};
    for (int k = 0; k < 2; k++) {
        double ref, sum = 0;
        lx_assert_ok(ctx, lx_spd_integrate(ctx, &s, &f, methods[k], &ref));
        lx_assert_ok(ctx, lx__integrate_weights(ctx, &s, &f, methods[k], w));
        for (size_t i = 0; i < n; i++) sum += w[i] * v[i];
        lx_assert_near(sum, ref, 0, 1e-13);
    }
    double ref, sum = 0;
    lx_assert_ok(ctx, lx_spd_integrate_radiant(ctx, &s, LX_METHOD_AUTO, &ref));
    lx_assert_ok(ctx, lx__integrate_weights(ctx, &s, NULL, LX_METHOD_AUTO, w));
    for (size_t i = 0; i < n; i++) sum += w[i] * v[i];
    lx_assert_near(sum, ref, 0, 1e-13);
    /* a 5 nm grid: cie15 */
    n = grid(5, lam);
    for (size_t i = 0; i < n; i++) v[i] = lx_planck(lam[i], 4000);
    s.n = n;
    sum = 0;
    lx_assert_ok(ctx, lx_spd_integrate(ctx, &s, &f, LX_METHOD_CIE15, &ref));
    lx_assert_ok(ctx, lx__integrate_weights(ctx, &s, &f, LX_METHOD_CIE15, w));
    for (size_t i = 0; i < n; i++) sum += w[i] * v[i];
    lx_assert_near(sum, ref, 0, 1e-13);
}

/* ---- closed forms ---- */

/* Uncorrelated noise u on a flat spectrum at 1 nm (cie15 rule): Y = Km sum ybar_j S_j, so
 * u(Y) = Km u sqrt(sum ybar_j^2), exactly for GUM (Y is linear) and to Monte Carlo's sampling error
 * (the standard deviation of a sample standard deviation: u / sqrt(2 (N - 1))). */
static void test_white_noise_flat(void **state)
{
    lx_ctx *ctx = *state;
    double lam[401], v[401];
    size_t n = grid(1, lam);
    for (size_t i = 0; i < n; i++) v[i] = 2.0;
    lx_spd s = {"flat", n, lam, v}, yb;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &yb));
    double ss = 0;
    for (size_t i = 0; i < n; i++) {
        double y = 0;
        for (size_t k = 0; k < yb.n; k++)
            if (yb.lambda_nm[k] == lam[i]) y = yb.value[k];
        ss += y * y;
    }
    double u_expect = 683.002 * 0.01 * 2.0 * sqrt(ss);
    lx_unc_model *m = model1(ctx, LX_UNC_NOISE, 0.01);
    size_t N = trials(40000, 4000);
    lx_unc_result *r = run(ctx, &s, m, LX_UNC_BOTH, N, 0);
    lx_assert_near(r->q[LX_UQ_Y].gum_u, u_expect, 0, 1e-12);
    lx_assert_near(r->q[LX_UQ_Y].mc_u, u_expect, 5 * u_expect / sqrt(2.0 * (double)N), 0);
    /* the radiant integral: trapezoid weights (0.5, 1, ..., 1, 0.5) nm */
    lx_assert_near(r->q[LX_UQ_RADIANT].gum_u, 0.02 * sqrt(399 + 0.5), 0, 1e-12);
    assert_int_equal(r->trials, N);
    lx_unc_result_free(r);
    lx_unc_model_free(m);
}

/* A fully correlated scale error: chromaticities do not move, u(Y) / Y = sigma. */
static void test_scale_closed_form(void **state)
{
    lx_ctx *ctx = *state;
    double lam[81], v[81];
    size_t n = grid(5, lam);
    for (size_t i = 0; i < n; i++) v[i] = lx_planck(lam[i], 3000) * (1 + 0.3 * sin(lam[i] / 20));
    lx_spd s = {"lamp", n, lam, v};
    lx_unc_model *m = model1(ctx, LX_UNC_SCALE, 0.02);
    size_t N = trials(20000, 2000);
    lx_unc_result *r = run(ctx, &s, m, LX_UNC_BOTH, N, 0);
    const int chrom[] = {LX_UQ_CX, LX_UQ_CY, LX_UQ_U_PRIME, LX_UQ_V_PRIME, LX_UQ_CCT, LX_UQ_DUV, LX_UQ_LER, LX_UQ_SP_RATIO};
    for (size_t k = 0; k < sizeof chrom / sizeof *chrom; k++) {
        const lx_unc_value *q = &r->q[chrom[k]];
        lx_assert_near(q->gum_u, 0, 1e-12 * fabs(q->value), 0);
        lx_assert_near(q->mc_u, 0, 1e-12 * fabs(q->value), 0);
    }
    lx_assert_near(r->q[LX_UQ_Y].gum_u / r->q[LX_UQ_Y].value, 0.02, 0, 1e-12);
    /* Monte Carlo: Y (1 + 0.02 z), so u(Y) / Y is 0.02 times the deviates' standard deviation */
    lx_assert_near(r->q[LX_UQ_Y].mc_u / r->q[LX_UQ_Y].value, 0.02, 5 * 0.02 / sqrt(2.0 * (double)N), 0);
    lx_unc_result_free(r);
    lx_unc_model_free(m);
}

/* The CCT of a blackbody at T sampled at lam + d, exactly (Planck's law), on the 1 nm grid. */
static double shifted_cct(lx_ctx *ctx, const double *lam, size_t n, double T, double d)
{
    double v[401];
    for (size_t i = 0; i < n; i++) v[i] = lx_planck(lam[i] - d, T);
    lx_spd s = {"bb", n, lam, v};
    lx_colorimetry c;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_AUTO, &c));
    return c.cct_K;
}

/* A wavelength-scale error on a blackbody: GUM u(CCT) = |dCCT/dd| sigma, the derivative by
 * central differences of the exact CCT of the blackbody evaluated at shifted wavelengths (not the
 * engine's interpolated shift); agreement to the O(h^2) of the 1 nm data's slopes. Monte Carlo
 * within its sampling error and that difference. */
static void test_shift_blackbody(void **state)
{
    lx_ctx *ctx = *state;
    double lam[401], v[401];
    size_t n = grid(1, lam);
    const double T = 2856, sigma = 0.1;
    for (size_t i = 0; i < n; i++) v[i] = lx_planck(lam[i], T);
    lx_spd s = {"bb", n, lam, v};
    double h = 0.05, dT = (shifted_cct(ctx, lam, n, T, h) - shifted_cct(ctx, lam, n, T, -h)) / (2 * h);
    lx_unc_model *m = model1(ctx, LX_UNC_SHIFT, sigma);
    size_t N = trials(20000, 2000);
    lx_unc_result *r = run(ctx, &s, m, LX_UNC_BOTH, N, 0);
    lx_assert_near(r->q[LX_UQ_CCT].gum_u, fabs(dT) * sigma, 0, 1e-3);
    lx_assert_near(r->q[LX_UQ_CCT].mc_u, fabs(dT) * sigma, 0, 5 / sqrt(2.0 * (double)N) + 1e-3);
    lx_unc_result_free(r);
    lx_unc_model_free(m);
}

/* ---- GUM against Monte Carlo (JCGM 101 8), reproducibility, adaptive trials ---- */

/* Small uncertainties on a smooth lamp: the model is linear to well within the tolerance, so JCGM
 * 101 8.2 must find GUM adequate (one significant digit: the adaptive trials stay few). */
static void test_gum_valid_small(void **state)
{
    lx_ctx *ctx = *state;
    double lam[81], v[81];
    size_t n = grid(5, lam);
    for (size_t i = 0; i < n; i++) v[i] = lx_planck(lam[i], 4000) * (1 + 0.2 * cos(lam[i] / 30));
    lx_spd s = {"lamp", n, lam, v};
    lx_unc_model *m = model1(ctx, LX_UNC_NOISE, 0.001);
    lx_unc_opts o;
    memset(&o, 0, sizeof o);
    o.method = LX_UNC_BOTH, o.digits = 1, o.seed = 3;
    if (slow() > 1) o.trials = 20000; /* the slow tools: the first two sequences */
    lx_unc_result *r = NULL;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &s, m, &o, &r));
    const int q[] = {LX_UQ_Y, LX_UQ_CX, LX_UQ_CY, LX_UQ_CCT, LX_UQ_DUV};
    for (size_t k = 0; k < sizeof q / sizeof *q; k++) {
        const lx_unc_value *x = &r->q[q[k]];
        assert_int_equal(x->gum_valid, 1);
        lx_assert_near(x->mc_u, x->gum_u, 0, 0.05);
    }
    if (!o.trials) { /* adaptive: stopped when stable, and said how */
        assert_int_equal(r->stable, 1);
        assert_true(r->trials >= 20000 && r->trials % 10000 == 0);
        assert_int_equal(r->sequence, 10000);
        assert_true(r->nhistory >= 1 && r->history_ratio[r->nhistory - 1] <= 1.0);
    }
    lx_unc_result_free(r);
    lx_unc_model_free(m);
}

/* A bandwidth error with no nominal bandwidth term to first order (b0 tiny): the effect is
 * quadratic in the error, GUM sees almost nothing, and JCGM 101 8 must say GUM is not adequate. */
static void test_gum_invalid_quadratic(void **state)
{
    lx_ctx *ctx = *state;
    double lam[81], v[81];
    size_t n = grid(5, lam);
    for (size_t i = 0; i < n; i++) v[i] = exp(-0.5 * pow((lam[i] - 550) / 15, 2)); /* a narrow band: large S'' */
    lx_spd s = {"band", n, lam, v};
    lx_unc_model *m = NULL;
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &m));
    lx_unc_component c;
    memset(&c, 0, sizeof c);
    c.kind = LX_UNC_BANDWIDTH, c.sigma = 2.0, c.bandwidth_nm = 0.01;
    lx_assert_ok(ctx, lx_unc_model_add(ctx, m, &c));
    lx_unc_opts o;
    memset(&o, 0, sizeof o);
    o.method = LX_UNC_BOTH, o.digits = 1, o.max_trials = 400000; /* adaptive: the validation needs a stable reference */
    lx_unc_result *r = NULL;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &s, m, &o, &r));
    const lx_unc_value *y = &r->q[LX_UQ_Y];
    print_message("%zu trials\n", r->trials);
    assert_true(y->gum_u < 0.01 * y->mc_u);
    assert_int_equal(y->stable, 1);
    assert_int_equal(y->gum_valid, 0);
    lx_unc_result_free(r);
    lx_unc_model_free(m);
}

/* The trials are a function of the seed alone: one thread and two give the same bits; another
 * seed other trials. */
static void test_reproducible(void **state)
{
    lx_ctx *ctx = *state;
    double lam[81], v[81];
    size_t n = grid(5, lam);
    for (size_t i = 0; i < n; i++) v[i] = lx_planck(lam[i], 5000);
    lx_spd s = {"bb", n, lam, v};
    lx_unc_model *m = NULL;
    lx_assert_ok(ctx, lx_unc_model_parse(ctx, "1%+scale=1%+shift=0.3nm+fourier=1%:3+bandwidth=0.5nm@5nm", NULL, &m));
    lx_unc_opts o;
    memset(&o, 0, sizeof o);
    o.trials = 3001, o.seed = 11, o.threads = 1;
    lx_unc_result *a = NULL, *b = NULL, *c = NULL;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &s, m, &o, &a));
    o.threads = 2;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &s, m, &o, &b));
    o.seed = 12;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &s, m, &o, &c));
    for (int q = 0; q <= LX_UQ_RADIANT; q++) {
        assert_memory_equal(&a->q[q].mc_u, &b->q[q].mc_u, sizeof(double));
        assert_memory_equal(&a->q[q].mc_lo, &b->q[q].mc_lo, sizeof(double));
        assert_memory_equal(&a->q[q].mc_mean, &b->q[q].mc_mean, sizeof(double));
    }
    assert_true(a->q[LX_UQ_CCT].mc_u != c->q[LX_UQ_CCT].mc_u);
    lx_unc_result_free(a), lx_unc_result_free(b), lx_unc_result_free(c);
    lx_unc_model_free(m);
}

/* ---- the Fourier model: Kaerhae et al. 2017 (Metrologia 54 524) ---- */

/* CIE illuminant A as a 2856 K blackbody, 360-830 nm at 5 nm, 1 % relative spectral uncertainty.
 * Reference values computed independently with numpy 2.2.6 and luxpy 1.12.5 (scratch script: the
 * GUM sensitivities of luxpy's xyz_to_cct by central differences, the Fourier model's covariance
 * u^2 / (N + 1) (1 + sum_i cos(2 pi i (x - x'))) S S'): uncorrelated u(CCT) = 5.99 K; Fourier with
 * N = 3 (the largest over N) 19.36 K, N = 2 19.19 K. Kaerhae et al.'s abstract gives expanded
 * (k = 2) uncertainties of 12.1 K uncorrelated at 5 nm and 37.2 K for the unfavourable
 * correlation (their Monte Carlo): 6.05 K and 18.6 K standard, a ratio of 3.1 (ours 3.23). */
static void test_fourier_karha(void **state)
{
    lx_ctx *ctx = *state;
    double lam[95], v[95];
    size_t n = 95;
    for (size_t i = 0; i < n; i++) lam[i] = 360 + 5.0 * (double)i, v[i] = lx_planck(lam[i], 2856);
    lx_spd s = {"A", n, lam, v};
    lx_unc_model *mu = model1(ctx, LX_UNC_NOISE, 0.01), *mf = model1(ctx, LX_UNC_FOURIER, 0.01), *m2 = NULL;
    lx_assert_ok(ctx, lx_unc_model_parse(ctx, "fourier=1%:2", NULL, &m2));
    lx_unc_result *ru = run(ctx, &s, mu, LX_UNC_GUM, 0, 0), *rf = run(ctx, &s, mf, LX_UNC_GUM, 0, 0);
    lx_unc_result *r2 = run(ctx, &s, m2, LX_UNC_BOTH, trials(40000, 4000), 0);
    lx_assert_near(ru->q[LX_UQ_CCT].gum_u, 5.992, 0, 2e-3);
    assert_int_equal(rf->fourier_terms, 3); /* the unfavourable N */
    lx_assert_near(rf->q[LX_UQ_CCT].gum_u, 19.36, 0, 2e-3);
    lx_assert_near(r2->q[LX_UQ_CCT].gum_u, 19.19, 0, 2e-3);
    /* Monte Carlo of the same model (random phases and a random unit vector, not a normal): its u
     * is the model's standard deviation, so it meets GUM's within its sampling error */
    lx_assert_near(r2->q[LX_UQ_CCT].mc_u, 19.19, 0, 5 / sqrt(2.0 * (double)r2->trials) + 0.02);
    double ratio = rf->q[LX_UQ_CCT].gum_u / ru->q[LX_UQ_CCT].gum_u;
    assert_true(ratio > 3.0 && ratio < 3.4);
    lx_unc_result_free(ru), lx_unc_result_free(rf), lx_unc_result_free(r2);
    lx_unc_model_free(mu), lx_unc_model_free(mf), lx_unc_model_free(m2);
}

/* ---- colour rendering against finite differences of lx_cri_compute and lx_tm30_compute ---- */

static double ra_of(lx_ctx *ctx, const lx_spd *s)
{
    lx_cri c;
    lx_assert_ok(ctx, lx_cri_compute(ctx, s, &c));
    return c.ra;
}

static double rf_of(lx_ctx *ctx, const lx_spd *s)
{
    lx_tm30 *t = malloc(sizeof *t);
    lx_assert_ok(ctx, lx_tm30_compute(ctx, s, t));
    double r = t->rf;
    free(t);
    return r;
}

/* GUM's u(Ra) and u(Rf) for uncorrelated 1 % noise equal sqrt(sum (dR/dS_j 0.01 S_j)^2) with the
 * derivatives by central differences of the public functions on perturbed spectra: an independent
 * check of the engine's integrals and of its derivatives through the reference illuminant. */
static void test_cri_tm30_gum(void **state)
{
    lx_ctx *ctx = *state;
    double lam[81], v[81], w[81];
    size_t n = grid(5, lam);
    lx_spd led;
    lx_assert_ok(ctx, lx_illuminant_get(ctx, "LED-B3", &led)); /* 380-780 nm at 5 nm, about 4100 K */
    assert_int_equal(led.n, n);
    for (size_t i = 0; i < n; i++) v[i] = led.value[i];
    lx_spd s = {"LED-B3", n, lam, v}, p = {"p", n, lam, w};
    double ssa = 0, ssf = 0;
    int tm = slow() == 1; /* TM-30's 162 evaluations and the engine's 606: natively only */
    for (size_t j = 0; j < n; j++) {
        double h = 1e-4 * v[j] + 1e-9, d[2][2] = {{0, 0}, {0, 0}};
        for (int k = 0; k < 2; k++) {
            memcpy(w, v, sizeof v);
            w[j] += k ? -h : h;
            d[0][k] = ra_of(ctx, &p);
            if (tm) d[1][k] = rf_of(ctx, &p);
        }
        double ga = (d[0][0] - d[0][1]) / (2 * h), gf = (d[1][0] - d[1][1]) / (2 * h);
        ssa += pow(ga * 0.01 * v[j], 2), ssf += pow(gf * 0.01 * v[j], 2);
    }
    lx_unc_model *m = model1(ctx, LX_UNC_NOISE, 0.01);
    lx_unc_result *r = run(ctx, &s, m, LX_UNC_GUM, 0, LX_UNC_CRI | (tm ? LX_UNC_TM30 : 0));
    lx_assert_near(r->q[LX_UQ_RA].value, ra_of(ctx, &s), 1e-9, 0);
    lx_assert_near(r->q[LX_UQ_RA].gum_u, sqrt(ssa), 0, 1e-4);
    if (tm) {
        lx_assert_near(r->q[LX_UQ_RF].value, rf_of(ctx, &s), 1e-9, 0);
        lx_assert_near(r->q[LX_UQ_RF].gum_u, sqrt(ssf), 0, 1e-4);
    }
    lx_unc_result_free(r);
    /* Monte Carlo of Ra on a few trials: near GUM (small uncertainty) */
    size_t N = trials(4000, 200);
    r = run(ctx, &s, m, LX_UNC_MC, N, LX_UNC_CRI);
    lx_assert_near(r->q[LX_UQ_RA].mc_u, sqrt(ssa), 0, 0.05 + 5 / sqrt(2.0 * (double)N));
    lx_unc_result_free(r);
    lx_unc_model_free(m);
}

/* ---- models: equivalent forms, the parser, bad input ---- */

/* A covariance diag(u^2) is the noise u; an all-ones relative covariance sigma^2 is a scale. */
static void test_covariance_equivalents(void **state)
{
    lx_ctx *ctx = *state;
    double lam[81], v[81], C[81 * 81], u[81];
    size_t n = grid(5, lam);
    for (size_t i = 0; i < n; i++) v[i] = lx_planck(lam[i], 6500), u[i] = 0.003 * v[i] * (1 + lam[i] / 800);
    lx_spd s = {"bb", n, lam, v};
    lx_unc_model *a = NULL, *b = NULL, *c = NULL, *d = NULL;
    lx_unc_component k;
    memset(&k, 0, sizeof k);
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &a));
    k.kind = LX_UNC_NOISE, k.n = n, k.lambda_nm = lam, k.u = u;
    lx_assert_ok(ctx, lx_unc_model_add(ctx, a, &k));
    for (size_t i = 0; i < n * n; i++) C[i] = i / n == i % n ? u[i / n] * u[i / n] : 0.0;
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &b));
    memset(&k, 0, sizeof k);
    k.kind = LX_UNC_COVARIANCE, k.n = n, k.cov = C;
    lx_assert_ok(ctx, lx_unc_model_add(ctx, b, &k));
    c = model1(ctx, LX_UNC_SCALE, 0.02);
    for (size_t i = 0; i < n * n; i++) C[i] = 0.02 * 0.02;
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &d));
    k.relative = 1;
    lx_assert_ok(ctx, lx_unc_model_add(ctx, d, &k));
    lx_unc_result *ra = run(ctx, &s, a, LX_UNC_GUM, 0, 0), *rb = run(ctx, &s, b, LX_UNC_GUM, 0, 0);
    lx_unc_result *rc = run(ctx, &s, c, LX_UNC_GUM, 0, 0), *rd = run(ctx, &s, d, LX_UNC_GUM, 0, 0);
    for (int q = 0; q <= LX_UQ_RADIANT; q++) {
        lx_assert_near(rb->q[q].gum_u, ra->q[q].gum_u, 1e-16 + 1e-14 * fabs(ra->q[q].value), 1e-9);
        lx_assert_near(rd->q[q].gum_u, rc->q[q].gum_u, 1e-16 + 1e-14 * fabs(rc->q[q].value), 1e-9);
    }
    lx_unc_result_free(ra), lx_unc_result_free(rb), lx_unc_result_free(rc), lx_unc_result_free(rd);
    lx_unc_model_free(a), lx_unc_model_free(b), lx_unc_model_free(c), lx_unc_model_free(d);
}

static void test_parse(void **state)
{
    lx_ctx *ctx = *state;
    lx_unc_model *m = NULL;
    lx_assert_ok(ctx, lx_unc_model_parse(ctx, " 0.5% + scale=1% +shift=0.1nm+bandwidth=0.2nm@4nm+fourier=2%:5+noise=0.003",
                                         NULL, &m));
    assert_int_equal(lx_unc_model_count(m), 6);
    assert_string_equal(lx_unc_model_label(m, 3), "bandwidth=0.2nm@4nm");
    lx_unc_model_free(m);
    static const char *const bad[] = {"", "1", "scale=1", "shift=1%", "fourier=1%:x", "bandwidth=0.2nm@", "colour=1%",
                                      "1%+", "column=u", "noise=-1", "1%%", "covariance=/nonexistent/C.csv"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        m = (lx_unc_model *)1;
        lx_status st = lx_unc_model_parse(ctx, bad[i], NULL, &m);
        if (st == LX_OK) print_error("'%s' was accepted\n", bad[i]);
        assert_int_not_equal(st, LX_OK);
        assert_null(m);
        assert_true(strlen(lx_ctx_errmsg(ctx)) > 0);
    }
}

static void test_bad_input(void **state)
{
    lx_ctx *ctx = *state;
    double lam[81], v[81], u[81], C[81 * 81];
    size_t n = grid(5, lam);
    for (size_t i = 0; i < n; i++) v[i] = 1, u[i] = 0.01;
    lx_spd s = {"flat", n, lam, v};
    lx_unc_model *m = NULL;
    lx_unc_component k;
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &m));
    /* negative and non-finite uncertainties */
    memset(&k, 0, sizeof k);
    k.kind = LX_UNC_NOISE, k.n = n, k.lambda_nm = lam, k.u = u;
    u[7] = -0.01;
    assert_int_equal(lx_unc_model_add(ctx, m, &k), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "415 nm"));
    u[7] = NAN;
    assert_int_equal(lx_unc_model_add(ctx, m, &k), LX_EINVAL);
    u[7] = 0.01;
    k.kind = LX_UNC_SCALE, k.sigma = INFINITY;
    assert_int_equal(lx_unc_model_add(ctx, m, &k), LX_EINVAL);
    /* a grid that is not the spectrum's */
    double lam2[81];
    memcpy(lam2, lam, sizeof lam);
    lam2[40] += 0.5;
    memset(&k, 0, sizeof k);
    k.kind = LX_UNC_NOISE, k.n = n, k.lambda_nm = lam2, k.u = u;
    lx_assert_ok(ctx, lx_unc_model_add(ctx, m, &k));
    lx_unc_result *r = NULL;
    assert_int_equal(lx_spd_uncertainty(ctx, &s, m, NULL, &r), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "not the spectrum's"));
    assert_null(r);
    lx_unc_model_free(m);
    /* fewer samples than the spectrum */
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &m));
    k.n = 40, k.lambda_nm = lam;
    lx_assert_ok(ctx, lx_unc_model_add(ctx, m, &k));
    assert_int_equal(lx_spd_uncertainty(ctx, &s, m, NULL, &r), LX_EINVAL);
    lx_unc_model_free(m);
    /* a covariance that is not positive semi-definite: a correlation of 1.5 */
    for (size_t i = 0; i < n * n; i++) C[i] = i / n == i % n ? 1e-4 : 0.0;
    C[3 * n + 4] = C[4 * n + 3] = 1.5e-4;
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &m));
    memset(&k, 0, sizeof k);
    k.kind = LX_UNC_COVARIANCE, k.n = n, k.cov = C;
    lx_assert_ok(ctx, lx_unc_model_add(ctx, m, &k));
    assert_int_equal(lx_spd_uncertainty(ctx, &s, m, NULL, &r), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "not positive semi-definite"));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "-5e-05")); /* its smallest eigenvalue: 1e-4 - 1.5e-4 */
    lx_unc_model_free(m);
    /* not symmetric */
    C[3 * n + 4] = 0.5e-4;
    lx_assert_ok(ctx, lx_unc_model_create(ctx, &m));
    lx_assert_ok(ctx, lx_unc_model_add(ctx, m, &k));
    assert_int_equal(lx_spd_uncertainty(ctx, &s, m, NULL, &r), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "not symmetric"));
    lx_unc_model_free(m);
    /* options */
    m = model1(ctx, LX_UNC_NOISE, 0.01);
    lx_unc_opts o;
    memset(&o, 0, sizeof o);
    o.coverage = 1.5;
    assert_int_equal(lx_spd_uncertainty(ctx, &s, m, &o, &r), LX_EINVAL);
    memset(&o, 0, sizeof o);
    o.reserved[2] = 1;
    assert_int_equal(lx_spd_uncertainty(ctx, &s, m, &o, &r), LX_EINVAL);
    assert_int_equal(lx_spd_uncertainty(NULL, &s, m, NULL, &r), LX_EINVAL);
    lx_unc_model_free(m);
}

/* The symmetric eigenvalues against a matrix with known ones (Q diag Q^T, Q a product of
 * rotations), and the pivoted Cholesky factor of a rank-2 matrix. */
static void test_linalg(void **state)
{
    (void)state;
    enum { N = 12 };
    double Q[N * N], A[N * N], ev[N], want[N];
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) Q[i * N + j] = i == j;
    for (int r = 0; r < 30; r++) { /* random plane rotations */
        int p = (r * 5) % N, q = (r * 7 + 3) % N;
        if (p == q) continue;
        double c = cos(0.3 + r), s = sin(0.3 + r);
        for (int i = 0; i < N; i++) {
            double a = Q[i * N + p], b = Q[i * N + q];
            Q[i * N + p] = c * a - s * b, Q[i * N + q] = s * a + c * b;
        }
    }
    for (int k = 0; k < N; k++) want[k] = k - 3.5; /* some negative */
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            double s = 0;
            for (int k = 0; k < N; k++) s += Q[i * N + k] * want[k] * Q[j * N + k];
            A[i * N + j] = s;
        }
    assert_int_equal(lx__sym_eigenvalues(N, A, ev), LX_OK);
    for (int k = 0; k < N; k++) lx_assert_near(ev[k], want[k], 1e-12, 0);
    double B[N * N], G[N * N];
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) B[i * N + j] = (1.0 + i) * (1.0 + j) + cos(i) * cos(j);
    size_t rank = 0;
    lx__pivoted_cholesky(N, B, 1e-14, G, &rank);
    assert_int_equal(rank, 2);
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            double s = 0;
            for (size_t k = 0; k < rank; k++) s += G[i * N + k] * G[j * N + k];
            lx_assert_near(s, B[i * N + j], 1e-10, 1e-12);
        }
    lx_assert_near(lx__normal_quantile(0.975), 1.959963984540054, 1e-14, 0);
    lx_assert_near(lx__normal_quantile(0.005), -2.5758293035489004, 1e-13, 0);
}

/* ---- OpenCL: the kernel (kernels/unc_trials.cl) against its CPU twin ---- */

/* The integrals of the same trials drawn by the kernel and by the CPU: 1e-12 of their spread with
 * fp64, 2e-5 without (float); then a whole Monte Carlo run on each backend. SKIPPED without a device. */
static void test_opencl_parity(void **state)
{
    lx_ctx *ctx = *state;
    lx_cl_device_info info;
    if (lx_cl_info(ctx, &info) != LX_OK) skip();
    double lam[81], v[81];
    size_t n = grid(5, lam);
    for (size_t i = 0; i < n; i++) v[i] = lx_planck(lam[i], 3500) * (1 + 0.3 * sin(lam[i] / 25));
    lx_spd s = {"lamp", n, lam, v};
    lx_unc_model *m = NULL;
    lx_assert_ok(ctx, lx_unc_model_parse(ctx, "1%+scale=1%+shift=0.3nm+bandwidth=0.5nm@5nm+fourier=1%:4", NULL, &m));
    lx__unc_bound *b = NULL;
    lx_assert_ok(ctx, lx__unc_bind(ctx, m, &s, &b));
    lx__unc_spectral_state st = {.obs = LX_OBSERVER_2, .method = LX_METHOD_CIE15};
    lx__unc_provider p[2];
    lx__unc_colorimetry_provider(&st, &p[0]);
    lx__unc_alphaopic_provider(&st, &p[1]);
    lx__unc_space sp;
    lx_assert_ok(ctx, lx__unc_space_make(ctx, &s, b, lx_unc_model_count(m), p, 2, &sp));
    assert_int_equal(lx__unc_space_finish(&sp, b), LX_OK);
    assert_true(sp.nshift > 0);
    size_t N = trials(4096, 256), K = sp.K;
    double *cpu = malloc(N * K * sizeof *cpu), *dev = NULL;
    lx__unc_trials_cpu(&sp, 99, 1000, N, cpu);
    lx_backend used = LX_BACKEND_AUTO;
    lx_assert_ok(ctx, lx__unc_trials_device(ctx, &sp, 99, 1000, N, LX_BACKEND_OPENCL, &dev, &used));
    assert_int_equal(used, LX_BACKEND_OPENCL);
    assert_non_null(dev);
    double tol = info.fp64 ? 1e-12 : 2e-5;
    for (size_t k = 0; k < K; k++) {
        double lo = INFINITY, hi = -INFINITY, worst = 0;
        for (size_t t = 0; t < N; t++) lo = fmin(lo, cpu[t * K + k]), hi = fmax(hi, cpu[t * K + k]);
        for (size_t t = 0; t < N; t++) worst = fmax(worst, fabs(dev[t * K + k] - cpu[t * K + k]));
        if (!(worst <= tol * (hi - lo))) print_error("integral %zu: |device - cpu| %.3g of a spread %.3g\n", k, worst, hi - lo);
        assert_true(worst <= tol * (hi - lo));
    }
    free(cpu), free(dev);
    lx__unc_space_free(&sp);
    lx__unc_unbind(b, lx_unc_model_count(m));
    /* end to end: the same statistics on either backend */
    lx_unc_opts o;
    memset(&o, 0, sizeof o);
    o.trials = trials(5000, 500), o.seed = 4, o.backend = LX_BACKEND_CPU;
    lx_unc_result *rc = NULL, *ro = NULL;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &s, m, &o, &rc));
    o.backend = LX_BACKEND_OPENCL;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &s, m, &o, &ro));
    assert_int_equal(ro->backend, LX_BACKEND_OPENCL);
    assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_OPENCL);
    for (int q = 0; q <= LX_UQ_RADIANT; q++)
        if (rc->q[q].defined) lx_assert_near(ro->q[q].mc_u, rc->q[q].mc_u, 1e-300, info.fp64 ? 1e-9 : 1e-3);
    lx_unc_result_free(rc), lx_unc_result_free(ro);
    lx_unc_model_free(m);
}

/* A shift on a dense irregular grid is integrated per trial, which the kernel does not do: OpenCL
 * asked for is refused (LX_EUNSUPPORTED, saying why), AUTO stays on the CPU. */
static void test_opencl_irregular_shift(void **state)
{
    lx_ctx *ctx = *state;
    lx_cl_device_info info;
    if (lx_cl_info(ctx, &info) != LX_OK) skip();
    double lam[3000], v[3000];
    size_t n = 0;
    for (double l = 380; l < 780 && n < 3000; l += 0.13 + 0.05 * sin(l * 7)) lam[n] = l, v[n] = 1 + 0.2 * sin(l / 9), n++;
    lx_spd s = {"dense", n, lam, v};
    lx_unc_model *m = model1(ctx, LX_UNC_SHIFT, 2.0);
    lx_unc_opts o;
    memset(&o, 0, sizeof o);
    o.trials = 200, o.backend = LX_BACKEND_OPENCL;
    lx_unc_result *r = NULL;
    assert_int_equal(lx_spd_uncertainty(ctx, &s, m, &o, &r), LX_EUNSUPPORTED);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "per trial"));
    o.backend = LX_BACKEND_CPU;
    lx_assert_ok(ctx, lx_spd_uncertainty(ctx, &s, m, &o, &r));
    assert_true(r->q[LX_UQ_CCT].mc_u > 0);
    lx_unc_result_free(r);
    lx_unc_model_free(m);
}

/* ---- a real instrument export (../shared, LX_SHARED_DIR): the UPRtek CV600 file ---- */
static void test_instrument_export(void **state)
{
    lx_ctx *ctx = *state;
    const char *dir = lx_test_shared_dir();
    if (!dir) skip();
    char path[1024];
    snprintf(path, sizeof path, "%s/spectra/instruments/uprtek.xls.txt", dir);
    lx_spd_set *set = NULL;
    if (lx_spd_read_file(ctx, path, &set) != LX_OK) skip();
    lx_unc_model *m = NULL;
    lx_assert_ok(ctx, lx_unc_model_parse(ctx, "2%+scale=3%+shift=0.5nm", set, &m));
    lx_unc_result *r = run(ctx, &set->spd[0], m, LX_UNC_BOTH, trials(20000, 3000), LX_UNC_COLORIMETRY | LX_UNC_CRI);
    lx_colorimetry c;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &set->spd[0], LX_OBSERVER_2, LX_METHOD_AUTO, &c));
    lx_assert_near(r->q[LX_UQ_CCT].value, c.cct_K, 0, 1e-9);
    lx_assert_near(r->q[LX_UQ_Y].gum_u / c.Y, 0.03, 0, 0.02); /* the scale dominates Y */
    assert_true(r->q[LX_UQ_CCT].mc_u > 0 && fabs(r->q[LX_UQ_CCT].mc_u / r->q[LX_UQ_CCT].gum_u - 1) < 0.1);
    assert_true(r->q[LX_UQ_RA].defined && r->q[LX_UQ_RA].mc_u > 0);
    lx_unc_result_free(r);
    lx_unc_model_free(m);
    lx_spd_set_free(set);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_philox_known_answers),
        cmocka_unit_test(test_normal_moments),
        cmocka_unit_test_setup_teardown(test_integrate_weights, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_white_noise_flat, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_scale_closed_form, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_shift_blackbody, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_gum_valid_small, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_gum_invalid_quadratic, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_reproducible, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_fourier_karha, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_cri_tm30_gum, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_covariance_equivalents, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_parse, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_bad_input, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test(test_linalg),
        cmocka_unit_test_setup_teardown(test_opencl_parity, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_opencl_irregular_shift, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_instrument_export, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
