/* test_faults.c - OpenCL faults injected through LX_CL_FAULT (opencl.c): no platform, a program that
 * fails to build, an allocation failure, a kernel that fails (at launch, at the read-back, at the
 * N-th chunk). With backend opencl each is a clear LX_EDEVICE naming the OpenCL call; with auto the
 * work is redone on the CPU, the fall-back is logged, and the result is the CPU's own, bit for bit
 * (never part device, part CPU). Skips cleanly when the build or the machine has no OpenCL. */
#include "lx_test.h"

#include <stdlib.h>
#include <string.h>

static const lx_function XYZV[4] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2, LX_FN_VPRIME};

static int have_platform(void)
{
#if LX_OPENCL
    unsetenv("LX_CL_FAULT");
    lx_cl_device_info *d = NULL;
    size_t n = 0;
    lx_ctx *ctx = NULL;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    lx_status st = lx_cl_devices(ctx, &d, &n);
    lx_ctx_destroy(ctx);
    lx_cl_devices_free(d);
    return st == LX_OK && n > 0;
#else
    return 0;
#endif
}

#define NEED_OPENCL() \
    do { \
        if (!have_platform()) { \
            print_message("no OpenCL platform (or LX_OPENCL=0): skipped\n"); \
            skip(); \
        } \
    } while (0)

/* the log callback: remembers whether a fall-back was reported */
typedef struct logbook {
    int fallbacks;
    char last[512];
} logbook;

static void on_log(void *user, lx_log_level level, const char *msg)
{
    logbook *b = user;
    if (level <= LX_LOG_INFO && (strstr(msg, "falling back") || strstr(msg, "on the CPU"))) {
        b->fallbacks++;
        snprintf(b->last, sizeof b->last, "%s", msg);
    }
}

/* LX_TEST_FAULTS=LIST runs only the faults whose names are in LIST (for debugging one case) */
static int wanted(const char *fault)
{
    const char *w = getenv("LX_TEST_FAULTS");
    return !w || !*w || strstr(w, fault) != NULL;
}

#define NS 3000 /* spectra */
#define NL 471  /* 360-830 nm at 1 nm */

static double *batch_values(void)
{
    double *v = malloc((size_t)NS * NL * sizeof *v);
    unsigned s = 12345;
    for (size_t i = 0; i < (size_t)NS * NL; i++) {
        s = s * 1664525u + 1013904223u;
        v[i] = 0.05 + (double)(s >> 8) / 16777216.0;
    }
    return v;
}

/* Runs one batch with the fault set; returns its status, the result in out, the backend used. */
static lx_status run_batch(const char *fault, lx_backend backend, size_t chunk, const double *v, double *out,
                           lx_backend *used, logbook *book, char *msg, size_t msglen)
{
    lx_ctx *ctx;
    assert_int_equal(lx_ctx_create(&ctx), LX_OK);
    lx_ctx_set_log(ctx, on_log, book, LX_LOG_INFO);
    if (fault) setenv("LX_CL_FAULT", fault, 1);
    else unsetenv("LX_CL_FAULT");
    setenv("LX_AUTO_BREAK_EVEN", "0", 1); /* auto picks OpenCL for any size */
    lx_batch b = {.n_spectra = NS, .n_lambda = NL, .start_nm = 360, .step_nm = 1, .dtype = LX_F64, .values = v};
    lx_batch_opts o = {.backend = backend, .chunk_spectra = chunk};
    lx_status st = lx_batch_integrate(ctx, &b, XYZV, 4, &o, out);
    *used = lx_ctx_backend_used(ctx);
    if (msg) snprintf(msg, msglen, "%s", lx_ctx_errmsg(ctx));
    unsetenv("LX_CL_FAULT");
    unsetenv("LX_AUTO_BREAK_EVEN");
    lx_ctx_destroy(ctx);
    return st;
}

static void test_batch_faults(void **state)
{
    (void)state;
    NEED_OPENCL();
    double *v = batch_values();
    size_t n = (size_t)NS * 4;
    double *cpu = malloc(n * sizeof *cpu), *ocl = malloc(n * sizeof *ocl), *got = malloc(n * sizeof *got);
    lx_backend used;
    logbook book = {0};
    char msg[1024];
    /* the references: the CPU path, and the device with no fault (several chunks of 500 spectra) */
    assert_int_equal(run_batch(NULL, LX_BACKEND_CPU, 0, v, cpu, &used, &book, NULL, 0), LX_OK);
    assert_int_equal(run_batch(NULL, LX_BACKEND_OPENCL, 500, v, ocl, &used, &book, NULL, 0), LX_OK);
    assert_int_equal(used, LX_BACKEND_OPENCL);
    assert_int_equal(book.fallbacks, 0);
    size_t differ = 0; /* device sums round differently from the CPU's: that is what shows a mix */
    for (size_t i = 0; i < 4 * 500; i++) differ += memcmp(&cpu[i], &ocl[i], sizeof(double)) != 0;
    print_message("first chunk: %zu of %d device values differ in their bits from the CPU's\n", differ, 4 * 500);

    static const struct {
        const char *fault, *call; /* LX_CL_FAULT, and what the error must name */
    } cases[] = {
        {"clGetPlatformIDs", "no OpenCL platform"},
        {"clBuildProgram", "clBuildProgram failed: CL_BUILD_PROGRAM_FAILURE"},
        {"clCreateBuffer", "CL_MEM_OBJECT_ALLOCATION_FAILURE"},
        {"clCreateBuffer:3", "CL_MEM_OBJECT_ALLOCATION_FAILURE"},
        {"clEnqueueNDRangeKernel", "clEnqueueNDRangeKernel"},
        {"clEnqueueNDRangeKernel:3", "clEnqueueNDRangeKernel"}, /* the third chunk: two already done */
        {"clFinish", "clFinish"},
    };
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        if (!wanted(cases[c].fault)) continue;
        /* opencl asked for: a clear device error naming the call */
        lx_status st = run_batch(cases[c].fault, LX_BACKEND_OPENCL, 500, v, got, &used, &book, msg, sizeof msg);
        print_message("%s, backend opencl: %s\n", cases[c].fault, msg);
        assert_int_equal(st, LX_EDEVICE);
        assert_non_null(strstr(msg, cases[c].call));
        /* auto: the CPU path, logged, and the CPU's result exactly */
        int before = book.fallbacks;
        for (size_t i = 0; i < n; i++) got[i] = -1;
        st = run_batch(cases[c].fault, LX_BACKEND_AUTO, 500, v, got, &used, &book, msg, sizeof msg);
        assert_int_equal(st, LX_OK);
        assert_int_equal(used, LX_BACKEND_CPU);
        assert_int_equal(book.fallbacks, before + 1);
        assert_non_null(strstr(book.last, cases[c].call));
        assert_memory_equal(got, cpu, n * sizeof *got);
    }
    free(v);
    free(cpu);
    free(ocl);
    free(got);
}

/* Grid illuminance on the table kernel: the same contract, 10000 points x 1000 placements of one
 * luminaire, auto made to pick OpenCL with LX_AUTO_BREAK_EVEN=0 (on its own it keeps a PoCL CPU
 * device off, and this job is below the break-even). */
static void test_grid_faults(void **state)
{
    (void)state;
    NEED_OPENCL();
    lx_ctx *ctx;
    assert_int_equal(lx_ctx_create(&ctx), LX_OK);
    lx_lum_model model = {.kind = LX_LUM_MODEL_WARN, .flux_lm = 1000, .exponent = 8};
    lx_luminaire *lum = NULL;
    assert_int_equal(lx_luminaire_from_model(ctx, &model, &lum), LX_OK);
    lx_ctx_destroy(ctx);
    enum { N = 10000, M = 1000 };
    lx_placement *pl = malloc(M * sizeof *pl);
    for (int k = 0; k < M; k++)
        pl[k] = (lx_placement){.lum = lum, .pos_m = {(k % 40) * 0.5 - 10, (k / 40) * 0.5 - 6, 3}, .aim = {0, 0, -1}};
    double *pts = malloc(3 * N * sizeof *pts), *cpu = malloc(N * sizeof *cpu), *got = malloc(N * sizeof *got);
    for (int i = 0; i < N; i++) pts[3 * i] = (i % 100) * 0.2 - 10, pts[3 * i + 1] = (i / 100) * 0.2 - 10, pts[3 * i + 2] = 0;
    const double up[3] = {0, 0, 1};
    lx_grid_opts o = {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU};
    assert_int_equal(lx_ctx_create(&ctx), LX_OK);
    assert_int_equal(lx_grid_illuminance(ctx, pl, M, pts, N, up, 1, &o, cpu), LX_OK);
    lx_ctx_destroy(ctx);
    static const char *faults[] = {"clGetPlatformIDs", "clBuildProgram", "clCreateBuffer", "clEnqueueNDRangeKernel"};
    for (size_t c = 0; c < sizeof faults / sizeof *faults; c++) {
        if (!wanted(faults[c])) continue;
        logbook book = {0};
        setenv("LX_CL_FAULT", faults[c], 1);
        assert_int_equal(lx_ctx_create(&ctx), LX_OK);
        lx_ctx_set_log(ctx, on_log, &book, LX_LOG_INFO);
        o.backend = LX_BACKEND_OPENCL;
        for (int i = 0; i < N; i++) got[i] = -1;
        assert_int_equal(lx_grid_illuminance(ctx, pl, M, pts, N, up, 1, &o, got), LX_EDEVICE);
        print_message("grid, %s, backend opencl: %s\n", faults[c], lx_ctx_errmsg(ctx));
        o.backend = LX_BACKEND_AUTO;
        setenv("LX_AUTO_BREAK_EVEN", "0", 1);
        assert_int_equal(lx_grid_illuminance(ctx, pl, M, pts, N, up, 1, &o, got), LX_OK);
        unsetenv("LX_AUTO_BREAK_EVEN");
        assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_CPU);
        assert_int_equal(book.fallbacks, 1);
        assert_memory_equal(got, cpu, N * sizeof *got);
        lx_ctx_destroy(ctx);
        unsetenv("LX_CL_FAULT");
    }
    free(pts);
    free(cpu);
    free(got);
    free(pl);
    lx_luminaire_free(lum);
}

/* Irradiance (brute force on the device): opencl asked for gives a clear error. */
static void test_irradiance_faults(void **state)
{
    (void)state;
    NEED_OPENCL();
    lx_ctx *ctx;
    assert_int_equal(lx_ctx_create(&ctx), LX_OK);
    lx_envmap *map = NULL;
    assert_int_equal(lx_envmap_create(ctx, 32, 16, 1, &map), LX_OK);
    for (int i = 0; i < 32 * 16; i++) map->data[i] = 1.0f;
    lx_ctx_destroy(ctx);
    const double dir[3] = {0, 0, 1};
    static const char *faults[] = {"clGetPlatformIDs", "clBuildProgram", "clCreateBuffer", "clEnqueueNDRangeKernel",
                                   "clEnqueueReadBuffer"};
    for (size_t c = 0; c < sizeof faults / sizeof *faults; c++) {
        if (!wanted(faults[c])) continue;
        setenv("LX_CL_FAULT", faults[c], 1);
        assert_int_equal(lx_ctx_create(&ctx), LX_OK);
        lx_irr_opts o = {.method = LX_IRR_BRUTE, .backend = LX_BACKEND_OPENCL};
        double E = -1;
        lx_status st = lx_irradiance_dirs(ctx, map, 1, dir, &o, &E);
        print_message("irradiance, %s, backend opencl: %s\n", faults[c], lx_ctx_errmsg(ctx));
        assert_int_equal(st, LX_EDEVICE);
        assert_true(E == -1); /* output untouched */
        lx_ctx_destroy(ctx);
        unsetenv("LX_CL_FAULT");
    }
    lx_envmap_free(map);
}

/* Monte Carlo trials of the uncertainty engine (kernels/unc_trials.cl): the same contract; the
 * statistics of the trials are the CPU's bit for bit after a fall-back. */
static lx_status run_unc(const char *fault, lx_backend backend, lx_unc_result **r, logbook *book, char *msg, size_t msglen)
{
    lx_ctx *ctx;
    assert_int_equal(lx_ctx_create(&ctx), LX_OK);
    lx_ctx_set_log(ctx, on_log, book, LX_LOG_INFO);
    if (fault) setenv("LX_CL_FAULT", fault, 1);
    else unsetenv("LX_CL_FAULT");
    setenv("LX_AUTO_BREAK_EVEN", "0", 1);
    static double lam[81], v[81];
    for (int i = 0; i < 81; i++) lam[i] = 380 + 5 * i, v[i] = lx_planck(lam[i], 3000);
    lx_spd s = {"bb", 81, lam, v};
    lx_unc_model *m = NULL;
    assert_int_equal(lx_unc_model_parse(ctx, "1%+shift=0.2nm+fourier=1%:3", NULL, &m), LX_OK);
    lx_unc_opts o = {.trials = 3000, .seed = 5, .backend = backend};
    *r = NULL;
    lx_status st = lx_spd_uncertainty(ctx, &s, m, &o, r);
    if (msg) snprintf(msg, msglen, "%s", lx_ctx_errmsg(ctx));
    unsetenv("LX_CL_FAULT");
    unsetenv("LX_AUTO_BREAK_EVEN");
    lx_unc_model_free(m);
    lx_ctx_destroy(ctx);
    return st;
}

static void test_uncertainty_faults(void **state)
{
    (void)state;
    NEED_OPENCL();
    logbook book = {0};
    char msg[1024];
    lx_unc_result *cpu = NULL, *got = NULL;
    assert_int_equal(run_unc(NULL, LX_BACKEND_CPU, &cpu, &book, NULL, 0), LX_OK);
    assert_int_equal(run_unc(NULL, LX_BACKEND_OPENCL, &got, &book, NULL, 0), LX_OK);
    assert_int_equal(got->backend, LX_BACKEND_OPENCL);
    lx_unc_result_free(got);
    static const struct {
        const char *fault, *call;
    } cases[] = {
        {"clGetPlatformIDs", "no OpenCL platform"},
        {"clBuildProgram", "clBuildProgram failed: CL_BUILD_PROGRAM_FAILURE"},
        {"clCreateBuffer", "CL_MEM_OBJECT_ALLOCATION_FAILURE"},
        {"clCreateBuffer:4", "CL_MEM_OBJECT_ALLOCATION_FAILURE"},
        {"clEnqueueNDRangeKernel", "clEnqueueNDRangeKernel"},
        {"clEnqueueReadBuffer", "clEnqueueReadBuffer"},
        {"clFinish", "clFinish"},
    };
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        if (!wanted(cases[c].fault)) continue;
        lx_status st = run_unc(cases[c].fault, LX_BACKEND_OPENCL, &got, &book, msg, sizeof msg);
        print_message("uncertainty, %s, backend opencl: %s\n", cases[c].fault, msg);
        assert_int_equal(st, LX_EDEVICE);
        assert_null(got);
        assert_non_null(strstr(msg, cases[c].call));
        int before = book.fallbacks;
        st = run_unc(cases[c].fault, LX_BACKEND_AUTO, &got, &book, msg, sizeof msg);
        assert_int_equal(st, LX_OK);
        assert_int_equal(got->backend, LX_BACKEND_CPU);
        assert_int_equal(book.fallbacks, before + 1);
        for (int q = 0; q <= LX_UQ_RADIANT; q++) {
            assert_memory_equal(&got->q[q].mc_u, &cpu->q[q].mc_u, sizeof(double));
            assert_memory_equal(&got->q[q].mc_lo, &cpu->q[q].mc_lo, sizeof(double));
        }
        lx_unc_result_free(got);
    }
    lx_unc_result_free(cpu);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_batch_faults),
        cmocka_unit_test(test_grid_faults),
        cmocka_unit_test(test_irradiance_faults),
        cmocka_unit_test(test_uncertainty_faults),
    };
    return cmocka_run_group_tests_name("opencl faults", tests, NULL, NULL);
}
