/* test_opencl.c - the OpenCL runtime and batch kernels: parity with the CPU path (double 1e-9,
 * float 1e-6 relative) across chunk boundaries, N = 1, N not a multiple of any work-group size,
 * empty batches; borrowed context/queue; LX_KERNEL_DIR and build logs; error names; auto fall-back.
 * Every test skips cleanly when the build or the machine has no OpenCL platform. */
#include "lx_test.h"

#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/core_private.h"

static const lx_function XYZV[4] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2, LX_FN_VPRIME};

static int have_platform(void)
{
#if LX_OPENCL
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

static void fill(float *vf, double *vd, size_t ns, size_t stride)
{
    unsigned s = 777;
    for (size_t i = 0; i < ns * stride; i++) {
        s = s * 1664525u + 1013904223u;
        double x = 0.05 + (double)(s >> 8) / 16777216.0; /* noise in [0.05, 1.05): the worst case for sums */
        vf[i] = (float)x;
        vd[i] = x;
    }
}

/* 1 when the context's device computes in double (cl_khr_fp64, not switched off by LX_CL_FP64=0) */
static int device_fp64(lx_ctx *ctx)
{
    lx_cl_device_info info;
    return lx_cl_info(ctx, &info) == LX_OK && info.fp64;
}

/* CPU vs OpenCL for one batch shape, float and double input. On a device without fp64 float input
 * takes the compensated-float kernel (its 1e-6 bound, test_kahan_float_accumulation) and double
 * input is refused (LX_EUNSUPPORTED, as lx_batch_integrate documents). */
static void parity(lx_ctx *ctx, size_t ns, size_t n, size_t stride, double start, double step, size_t chunk,
                   const lx_function *fns, size_t k, double rel_f32, int f32_only)
{
    int fp64 = device_fp64(ctx);
    if (!fp64 && rel_f32 < 1e-6) rel_f32 = 1e-6;
    size_t cnt = ns ? ns * stride : 1;
    float *vf = malloc(cnt * sizeof *vf);
    double *vd = malloc(cnt * sizeof *vd);
    double *a = malloc((ns * k + 1) * sizeof *a), *c = malloc((ns * k + 1) * sizeof *c);
    fill(vf, vd, ns, stride);
    for (int t = 0; t < 2 - f32_only; t++) {
        lx_batch b = {.n_spectra = ns, .n_lambda = n, .row_stride = stride, .start_nm = start, .step_nm = step,
                      .dtype = t ? LX_F64 : LX_F32, .values = t ? (void *)vd : (void *)vf};
        lx_batch_opts ocl = {.backend = LX_BACKEND_OPENCL, .chunk_spectra = chunk};
        lx_batch_opts cpu = {.backend = LX_BACKEND_CPU};
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, fns, k, &cpu, c));
        if (t && !fp64 && ns) {
            assert_int_equal(lx_batch_integrate(ctx, &b, fns, k, &ocl, a), LX_EUNSUPPORTED);
            continue;
        }
        lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, fns, k, &ocl, a));
        if (ns) assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_OPENCL);
        for (size_t i = 0; i < ns * k; i++) lx_assert_near(a[i], c[i], 1e-300, t ? 1e-9 : rel_f32);
    }
    free(vf);
    free(vd);
    free(a);
    free(c);
}

static void test_parity_shapes(void **state)
{
    NEED_OPENCL();
    lx_ctx *ctx = *state;
    lx_function all[LX_FN_COUNT];
    for (int f = 0; f < LX_FN_COUNT; f++) all[f] = (lx_function)f;
    parity(ctx, 1, 471, 471, 360, 1, 0, XYZV, 4, 1e-9, 0);          /* N = 1 */
    parity(ctx, 997, 471, 471, 360, 1, 0, XYZV, 4, 1e-9, 0);        /* prime N: no work-group size divides it */
    parity(ctx, 1000, 471, 473, 360, 1, 64, XYZV, 4, 1e-9, 0);      /* chunk boundaries (64), stride padding */
    parity(ctx, 130, 95, 95, 360, 5, 1, all, LX_FN_COUNT, 1e-9, 0); /* chunk of one spectrum, K = 12 */
    parity(ctx, 33, 7, 7, 550.5, 0.5, 10, XYZV, 3, 1e-9, 0);        /* tail only (< 8 samples), off-grid */
    parity(ctx, 0, 471, 471, 360, 1, 0, XYZV, 4, 1e-9, 0);          /* empty batch */
}

static void test_kahan_float_accumulation(void **state)
{
    NEED_OPENCL();
    lx_ctx *ctx = *state;
    /* the compensated-float kernel (devices without fp64) must keep the float tolerance */
    setenv("LX_CL_ACCUM", "kahan", 1);
    parity(ctx, 517, 471, 471, 360, 1, 100, XYZV, 4, 1e-6, 1);
    unsetenv("LX_CL_ACCUM");
}

static void test_resample_parity(void **state)
{
    NEED_OPENCL();
    lx_ctx *ctx = *state;
    /* 50 spectra with differing non-uniform grids (steps 0.7-3.1 nm, offsets) -> 360-830 at 1 nm */
    size_t ns = 50, off[50], nin[50], tot = 0;
    for (size_t i = 0; i < ns; i++) {
        off[i] = tot;
        nin[i] = 100 + 3 * i;
        tot += nin[i];
    }
    double *lam = malloc(tot * sizeof *lam), *val = malloc(tot * sizeof *val);
    for (size_t i = 0; i < ns; i++) {
        double x = 350 + (double)i;
        for (size_t j = 0; j < nin[i]; j++) {
            x += 0.7 + 2.4 * (double)((i * 31 + j * 17) % 13) / 12.0;
            lam[off[i] + j] = x;
            val[off[i] + j] = sin(x / 40.0) + 1.5;
        }
    }
    for (int t = 0; t < 2; t++) {
        size_t es = t ? sizeof(double) : sizeof(float);
        void *a = malloc(ns * 471 * es), *c = malloc(ns * 471 * es);
        lx_batch da = {.n_lambda = 471, .start_nm = 360, .step_nm = 1, .dtype = t ? LX_F64 : LX_F32, .values = a};
        lx_batch dc = da;
        dc.values = c;
        lx_batch_opts ocl = {.backend = LX_BACKEND_OPENCL}, cpu = {.backend = LX_BACKEND_CPU};
        if (!device_fp64(ctx)) { /* the resample kernel needs fp64 (lx_batch_resample) */
            assert_int_equal(lx_batch_resample(ctx, ns, lam, val, off, nin, &da, &ocl), LX_EUNSUPPORTED);
            free(a);
            free(c);
            continue;
        }
        lx_assert_ok(ctx, lx_batch_resample(ctx, ns, lam, val, off, nin, &da, &ocl));
        assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_OPENCL);
        lx_assert_ok(ctx, lx_batch_resample(ctx, ns, lam, val, off, nin, &dc, &cpu));
        assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_CPU);
        for (size_t i = 0; i < ns * 471; i++) {
            double x = t ? ((double *)a)[i] : ((float *)a)[i], y = t ? ((double *)c)[i] : ((float *)c)[i];
            lx_assert_near(x, y, 1e-15, t ? 1e-12 : 1e-7);
        }
        free(a);
        free(c);
    }
    free(lam);
    free(val);
}

static void test_device_list_and_info(void **state)
{
    NEED_OPENCL();
    lx_ctx *ctx = *state;
    lx_cl_device_info *d = NULL;
    size_t n = 0;
    lx_assert_ok(ctx, lx_cl_devices(ctx, &d, &n));
    int defaults = 0;
    for (size_t i = 0; i < n; i++) {
        defaults += d[i].is_default;
        assert_true(d[i].max_alloc_bytes > 0);
        assert_true(strlen(d[i].device_name) > 0);
    }
    assert_int_equal(defaults, 1);
    assert_int_equal(lx_cl_ready(ctx), 0); /* listing creates no context */
    lx_cl_device_info in_use;
    lx_assert_ok(ctx, lx_cl_info(ctx, &in_use));
    assert_int_equal(lx_cl_ready(ctx), 1);
    for (size_t i = 0; i < n; i++)
        if (d[i].is_default) assert_string_equal(d[i].device_name, in_use.device_name);
    lx_cl_devices_free(d);
    /* LX_CL_FP64=0 (make test-nofp64) must switch the device's fp64 off, so that the run really
     * builds and checks the kernels' variants for devices without it */
    const char *f = getenv("LX_CL_FP64");
    if (f && !strcmp(f, "0")) {
        print_message("LX_CL_FP64=0: %s runs the no-fp64 kernels\n", in_use.device_name);
        assert_int_equal(in_use.fp64, 0);
    }
}

static void capture_log(void *user, lx_log_level level, const char *msg)
{
    (void)level;
    char *buf = user;
    size_t l = strlen(buf);
    snprintf(buf + l, 1024 - l, "%s\n", msg);
}

static void test_selection_errors_and_fallback(void **state)
{
    NEED_OPENCL();
    lx_ctx *ctx = *state;
    lx_assert_ok(ctx, lx_cl_select(ctx, 99, -1, LX_CL_AUTO));
    lx_cl_device_info info;
    assert_int_equal(lx_cl_info(ctx, &info), LX_EDEVICE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "platform 99"));
    /* auto with the break-even forced to 0 tries OpenCL, fails, and says so through the log */
    char logbuf[1024] = "";
    setenv("LX_AUTO_BREAK_EVEN", "0", 1);
    double v[471], out[4];
    for (int i = 0; i < 471; i++) v[i] = 1;
    lx_batch b = {.n_spectra = 1, .n_lambda = 471, .start_nm = 360, .step_nm = 1, .dtype = LX_F64, .values = v};
    lx_ctx_set_log(ctx, capture_log, logbuf, LX_LOG_INFO);
    lx_batch_opts o = {.backend = LX_BACKEND_AUTO};
    lx_assert_ok(ctx, lx_batch_integrate(ctx, &b, XYZV, 4, &o, out));
    unsetenv("LX_AUTO_BREAK_EVEN");
    assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_CPU);
    assert_non_null(strstr(logbuf, "falling back to the CPU"));
    /* sum of ybar 360-830 nm: colour-science 0.4.7 CMF table sum (see test_batch.c) */
    lx_assert_near(out[1], 106.8569171, 0, 1e-9);
    /* asking for OpenCL explicitly is an error, not a fall-back */
    o.backend = LX_BACKEND_OPENCL;
    assert_int_equal(lx_batch_integrate(ctx, &b, XYZV, 4, &o, out), LX_EDEVICE);
}

static void test_kernel_dir(void **state)
{
    NEED_OPENCL();
    lx_ctx *ctx = *state;
    float v[8] = {1, 1, 1, 1, 1, 1, 1, 1}; /* float input: every device runs it, with or without fp64 */
    double out[4];
    lx_batch b = {.n_spectra = 1, .n_lambda = 8, .start_nm = 550, .step_nm = 1, .dtype = LX_F32, .values = v};
    lx_batch_opts o = {.backend = LX_BACKEND_OPENCL};
    setenv("LX_KERNEL_DIR", "/nonexistent-lx-kernels", 1);
    assert_int_equal(lx_batch_integrate(ctx, &b, XYZV, 4, &o, out), LX_EIO);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "/nonexistent-lx-kernels/"));
    /* a directory whose kernels do not compile: the message carries the build log */
    char dir[] = "/tmp/lxkernXXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[256];
    for (int i = 0; i < lx__nkernel_sources; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, lx__kernel_sources[i].name);
        FILE *f = fopen(path, "w");
        assert_non_null(f);
        fputs(i == 0 ? "__kernel void broken(__global float *x) { x[0] = undeclared_symbol_lx; }\n" : "\n", f);
        fclose(f);
    }
    setenv("LX_KERNEL_DIR", dir, 1);
    lx_ctx *c2 = NULL;
    lx_assert_ok(c2, lx_ctx_create(&c2));
    assert_int_equal(lx_batch_integrate(c2, &b, XYZV, 4, &o, out), LX_EDEVICE);
    assert_non_null(strstr(lx_ctx_errmsg(c2), "CL_BUILD_PROGRAM_FAILURE"));
    assert_non_null(strstr(lx_ctx_errmsg(c2), "undeclared_symbol_lx"));
    lx_ctx_destroy(c2);
    /* the real kernels from kernels/ on disk (when run from the source tree) work like the embedded ones */
    unsetenv("LX_KERNEL_DIR");
    if (access("kernels/spd_batch.cl", R_OK) == 0) {
        setenv("LX_KERNEL_DIR", "kernels", 1);
        lx_ctx *c3 = NULL;
        lx_assert_ok(c3, lx_ctx_create(&c3));
        lx_assert_ok(c3, lx_batch_integrate(c3, &b, XYZV, 4, &o, out));
        lx_ctx_destroy(c3);
        unsetenv("LX_KERNEL_DIR");
    }
    for (int i = 0; i < lx__nkernel_sources; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, lx__kernel_sources[i].name);
        unlink(path);
    }
    rmdir(dir);
}

static void test_borrowed_context(void **state)
{
    NEED_OPENCL();
#if LX_OPENCL
    lx_ctx *ctx = *state;
    cl_platform_id p;
    cl_device_id d;
    assert_int_equal(clGetPlatformIDs(1, &p, NULL), CL_SUCCESS);
    assert_int_equal(clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, 1, &d, NULL), CL_SUCCESS);
    cl_int err;
    cl_context c = clCreateContext(NULL, 1, &d, NULL, NULL, &err);
    assert_int_equal(err, CL_SUCCESS);
    cl_command_queue q = clCreateCommandQueue(c, d, 0, &err);
    assert_int_equal(err, CL_SUCCESS);
    lx_assert_ok(ctx, lx_cl_borrow(ctx, c, q));
    clReleaseCommandQueue(q); /* the library holds its own references */
    clReleaseContext(c);
    parity(ctx, 300, 471, 471, 360, 1, 0, XYZV, 4, 1e-9, 0);
    lx_cl_device_info info;
    lx_assert_ok(ctx, lx_cl_info(ctx, &info));
    assert_true(strlen(info.device_name) > 0);
#endif
}

static void test_error_names(void **state)
{
    (void)state;
#if LX_OPENCL
    /* the OpenCL 1.2 specification's error codes (CL/cl.h): -5 and -11 */
    assert_string_equal(lx__cl_errname(-5), "CL_OUT_OF_RESOURCES");
    assert_string_equal(lx__cl_errname(-11), "CL_BUILD_PROGRAM_FAILURE");
    lx_ctx *ctx = *state;
    assert_int_equal(lx__cl_check(ctx, -5, "clEnqueueNDRangeKernel"), LX_EDEVICE);
    assert_string_equal(lx_ctx_errmsg(ctx), "clEnqueueNDRangeKernel failed: CL_OUT_OF_RESOURCES (-5)");
#else
    lx_ctx *ctx = *state;
    assert_int_equal(lx_cl_select(ctx, 0, 0, LX_CL_AUTO), LX_EUNSUPPORTED);
    lx_cl_device_info *d = NULL;
    size_t n = 5;
    lx_assert_ok(ctx, lx_cl_devices(ctx, &d, &n));
    assert_int_equal(n, 0);
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_error_names, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_device_list_and_info, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_parity_shapes, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_kahan_float_accumulation, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_resample_parity, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_borrowed_context, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_selection_errors_and_fallback, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(test_kernel_dir, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
