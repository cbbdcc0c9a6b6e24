/* test_threads.c - thread safety as documented: each thread with its own context gets
 * bit-identical results to a serial run, while sharing read-only objects (a spectral set, a
 * luminaire) and the lazily built tables; functions without a context are pure; threads with their
 * own contexts may use OpenCL at once (each starts its own OpenCL state and builds its program).
 * make tsan runs this file under ThreadSanitizer with OpenCL on. */
#include "lx_test.h"

#include <pthread.h>
#include <string.h>

#define NT 4
#define NJOBS 40

static lx_spd_set *g_set;
static lx_luminaire *g_lum;

typedef struct result {
    double xyz[NJOBS][3], cct[NJOBS], lumens, inten[NJOBS], planck[NJOBS];
    const char *const *names;
    int ok;
} result;

static void work(result *r)
{
    lx_ctx *ctx;
    r->ok = 0;
    if (lx_ctx_create(&ctx) != LX_OK) return;
    const char *const *names = lx_illuminant_names();
    r->names = names;
    for (int j = 0; j < NJOBS; j++) {
        lx_spd s;
        const lx_spd *sp = &s;
        if (j < 20 && names[j]) {
            if (lx_illuminant_get(ctx, names[j], &s) != LX_OK) goto out;
        } else {
            sp = &g_set->spd[(size_t)j % g_set->count];
        }
        lx_colorimetry c;
        if (lx_spd_colorimetry(ctx, sp, LX_OBSERVER_2, LX_METHOD_AUTO, &c) != LX_OK) goto out;
        r->xyz[j][0] = c.X, r->xyz[j][1] = c.Y, r->xyz[j][2] = c.Z, r->cct[j] = c.cct_K;
        r->inten[j] = lx_luminaire_intensity_dir(g_lum, LX_INTERP_BILINEAR, 0.1 * j, 0.05 * j, -1.0);
        r->planck[j] = lx_planck(400 + 5 * j, 1000 + 100 * j);
    }
    lx_lum_summary sum;
    if (lx_luminaire_summary(ctx, g_lum, &sum) != LX_OK) goto out;
    r->lumens = sum.lumens;
    r->ok = 1;
out:
    lx_ctx_destroy(ctx);
}

static void *thread_main(void *arg)
{
    work(arg);
    return NULL;
}

static void test_threads_match_serial(void **state)
{
    lx_ctx *ctx = *state;
    lx_assert_ok(ctx, lx_spd_read_file(ctx, "samples/spd/led_batch.csv", &g_set));
    lx_assert_ok(ctx, lx_luminaire_read_file(ctx, "samples/ies/spot_warn_30deg_800lm.ies", &g_lum));
    static result par[NT], ser;
    pthread_t tid[NT];
    /* the threads start first, so the lazily built tables (illuminant names, locus) race */
    for (int t = 0; t < NT; t++) assert_int_equal(pthread_create(&tid[t], NULL, thread_main, &par[t]), 0);
    for (int t = 0; t < NT; t++) pthread_join(tid[t], NULL);
    work(&ser);
    assert_true(ser.ok);
    for (int t = 0; t < NT; t++) {
        assert_true(par[t].ok);
        assert_ptr_equal(par[t].names, ser.names);
        assert_memory_equal(par[t].xyz, ser.xyz, sizeof ser.xyz); /* bit-identical */
        assert_memory_equal(par[t].cct, ser.cct, sizeof ser.cct);
        assert_memory_equal(par[t].inten, ser.inten, sizeof ser.inten);
        assert_memory_equal(par[t].planck, ser.planck, sizeof ser.planck);
        assert_memory_equal(&par[t].lumens, &ser.lumens, sizeof ser.lumens);
    }
    lx_spd_set_free(g_set);
    lx_luminaire_free(g_lum);
}

/* The CPU path is deterministic: the same input twice gives the same bits (also across the
 * batch path's threads, whose split does not change any sum). */
static void test_repeatable(void **state)
{
    lx_ctx *ctx = *state;
    double v[401 * 64];
    for (int i = 0; i < 64; i++)
        for (int j = 0; j < 401; j++) v[i * 401 + j] = lx_planck(380 + j, 1500 + 300 * i);
    lx_batch b = {64, 401, 0, 380, 1, LX_F64, v};
    lx_colorimetry r1[64], r2[64];
    lx_batch_opts o1 = {.backend = LX_BACKEND_CPU, .threads = 1}, o2 = {.backend = LX_BACKEND_CPU, .threads = 2};
    lx_assert_ok(ctx, lx_batch_colorimetry(ctx, &b, LX_OBSERVER_2, &o1, r1));
    lx_assert_ok(ctx, lx_batch_colorimetry(ctx, &b, LX_OBSERVER_2, &o2, r2));
    for (int i = 0; i < 64; i++) { /* member by member: the struct's padding bytes are never written */
        const double a[] = {r1[i].X, r1[i].Y, r1[i].Z, r1[i].x, r1[i].y, r1[i].u_prime, r1[i].v_prime, r1[i].cct_K,
                            r1[i].duv, r1[i].radiant, r1[i].ler_lm_per_W, r1[i].scotopic_Y, r1[i].sp_ratio};
        const double c[] = {r2[i].X, r2[i].Y, r2[i].Z, r2[i].x, r2[i].y, r2[i].u_prime, r2[i].v_prime, r2[i].cct_K,
                            r2[i].duv, r2[i].radiant, r2[i].ler_lm_per_W, r2[i].scotopic_Y, r2[i].sp_ratio};
        assert_memory_equal(a, c, sizeof a);
        assert_int_equal(r1[i].cct_valid, r2[i].cct_valid);
        assert_int_equal(r1[i].method, r2[i].method);
    }
}

/* ---- OpenCL from several threads at once ---- */

#define CL_NS 64
#define CL_NL 471
static float g_cl_values[CL_NS * CL_NL];
static const lx_function CL_FNS[4] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2, LX_FN_VPRIME};

typedef struct cl_job {
    double out[CL_NS * 4];
    lx_status st;
    lx_backend used;
} cl_job;

static void *cl_thread(void *arg)
{
    cl_job *j = arg;
    lx_ctx *ctx = NULL;
    if ((j->st = lx_ctx_create(&ctx)) != LX_OK) return NULL;
    lx_batch b = {.n_spectra = CL_NS, .n_lambda = CL_NL, .start_nm = 360, .step_nm = 1, .dtype = LX_F32,
                  .values = g_cl_values};
    lx_batch_opts o = {.backend = LX_BACKEND_OPENCL, .chunk_spectra = 16};
    j->st = lx_batch_integrate(ctx, &b, CL_FNS, 4, &o, j->out);
    j->used = lx_ctx_backend_used(ctx);
    lx_ctx_destroy(ctx);
    return NULL;
}

static void test_opencl_contexts_in_parallel(void **state)
{
    lx_ctx *ctx = *state;
    lx_cl_device_info *d = NULL;
    size_t n = 0;
    lx_assert_ok(ctx, lx_cl_devices(ctx, &d, &n));
    lx_cl_devices_free(d);
    if (n == 0) {
        print_message("no OpenCL device (or LX_OPENCL=0): skipped\n");
        skip();
    }
    for (int i = 0; i < CL_NS * CL_NL; i++) g_cl_values[i] = (float)lx_planck(360 + i % CL_NL, 2000 + 50 * (i / CL_NL));
    /* the reference: the CPU path; the device's float sums agree to the documented 1e-6 */
    lx_batch b = {.n_spectra = CL_NS, .n_lambda = CL_NL, .start_nm = 360, .step_nm = 1, .dtype = LX_F32,
                  .values = g_cl_values};
    lx_batch_opts cpu = {.backend = LX_BACKEND_CPU};
    static double ref[CL_NS * 4];
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, CL_FNS, 4, &cpu, ref));
    static cl_job jobs[NT];
    pthread_t tid[NT];
    for (int t = 0; t < NT; t++) assert_int_equal(pthread_create(&tid[t], NULL, cl_thread, &jobs[t]), 0);
    for (int t = 0; t < NT; t++) pthread_join(tid[t], NULL);
    for (int t = 0; t < NT; t++) {
        assert_int_equal(jobs[t].st, LX_OK);
        assert_int_equal(jobs[t].used, LX_BACKEND_OPENCL);
        for (int i = 0; i < CL_NS * 4; i++) lx_assert_near(jobs[t].out[i], ref[i], 1e-300, 1e-6);
        assert_memory_equal(jobs[t].out, jobs[0].out, sizeof jobs[0].out); /* one device, one program: the same bits */
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_threads_match_serial),
        cmocka_unit_test(test_repeatable),
        cmocka_unit_test(test_opencl_contexts_in_parallel),
    };
    return cmocka_run_group_tests_name("threads", tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
