/* lx_test.h - shared helpers for the cmocka test binaries: tolerance asserts, context set-up,
 * the path of ../shared (LX_SHARED_DIR) and of the built CLI (LX_BUILD_DIR). */
#ifndef LX_TEST_H
#define LX_TEST_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "luxcalc.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Passes when |a - b| <= abs_tol or |a - b| <= rel_tol * |b|; NaN never passes. */
#define lx_assert_near(a, b, abs_tol, rel_tol) \
    lx_assert_near_(#a, (double)(a), (double)(b), (abs_tol), (rel_tol), __FILE__, __LINE__)

static inline void lx_assert_near_(const char *expr, double a, double b, double abs_tol, double rel_tol,
                                   const char *file, int line)
{
    double d = fabs(a - b);
    if (!(d <= abs_tol || d <= rel_tol * fabs(b))) {
        print_error("%s = %.17g, expected %.17g (|diff| %.3g > abs %.3g, rel %.3g)\n", expr, a, b, d,
                       abs_tol, rel_tol * fabs(b));
        _fail(file, line);
    }
}

/* Asserts a status is LX_OK, printing the context's message otherwise. */
#define lx_assert_ok(ctx, call) \
    do { \
        lx_status st_ = (call); \
        if (st_ != LX_OK) { \
            print_error("%s -> %s: %s\n", #call, lx_strerror(st_), lx_ctx_errmsg(ctx)); \
            _fail(__FILE__, __LINE__); \
        } \
    } while (0)

static inline int lx_test_ctx_setup(void **state)
{
    lx_ctx *ctx = NULL;
    if (lx_ctx_create(&ctx) != LX_OK) return -1;
    *state = ctx;
    return 0;
}

static inline int lx_test_ctx_teardown(void **state)
{
    lx_ctx_destroy((lx_ctx *)*state);
    return 0;
}

/* ../shared (for data the project must not copy, e.g. third-party IES files); NULL if absent. */
static inline const char *lx_test_shared_dir(void)
{
    const char *d = getenv("LX_SHARED_DIR");
    return d && *d ? d : NULL;
}

/* The build directory (for the CLI binary: LX_BUILD_DIR/luxcalc). */
static inline const char *lx_test_build_dir(void)
{
    const char *d = getenv("LX_BUILD_DIR");
    return d && *d ? d : "build";
}

/* SIMD twins, one test per path: lx_test_simd_begin(path) skips the test (cmocka skip(), reported
 * SKIPPED) when this machine cannot run that path, i.e. when the CPU lacks it or the environment
 * the suite runs in caps it (LX_SIMD=scalar|avx2, as CI runs the suite), and otherwise selects it
 * with LX_SIMD; lx_test_simd_end() puts the environment back. */
static char lx_test_simd_saved[32];
static int lx_test_simd_had;
static inline void lx_test_simd_begin(lx_simd path)
{
    if (lx_simd_level() < path) skip(); /* before anything is allocated: skip() leaves the test */
    const char *e = getenv("LX_SIMD");
    lx_test_simd_had = e != NULL;
    snprintf(lx_test_simd_saved, sizeof lx_test_simd_saved, "%s", e ? e : "");
    setenv("LX_SIMD", lx_simd_name(path), 1);
}
static inline void lx_test_simd_end(void)
{
    if (lx_test_simd_had) setenv("LX_SIMD", lx_test_simd_saved, 1);
    else unsetenv("LX_SIMD");
}

/* Rewrites the box2i attribute `name` ("dataWindow", "displayWindow") of the OpenEXR header in
 * path to (0, 0)-(xmax, ymax), in place: a header that declares what the file cannot hold.
 * Returns 0, or -1 when the attribute is not found. */
static inline int lx_test_exr_set_window(const char *path, const char *name, int32_t xmax, int32_t ymax)
{
    FILE *f = fopen(path, "r+b");
    if (!f) return -1;
    unsigned char buf[65536];
    size_t n = fread(buf, 1, sizeof buf, f), nl = strlen(name);
    long at = -1;
    for (size_t i = 0; i + nl + 7 + 4 + 16 <= n && at < 0; i++) /* NAME\0box2i\0 <size 16> <4 x int32> */
        if (!memcmp(buf + i, name, nl) && !memcmp(buf + i + nl, "\0box2i\0", 7))
            at = (long)(i + nl + 7 + 4);
    int rc = -1;
    if (at >= 0) {
        int32_t box[4] = {0, 0, xmax, ymax}; /* little-endian on disk, as this host (x86-64, arm64) */
        rc = fseek(f, at, SEEK_SET) == 0 && fwrite(box, 4, 4, f) == 4 ? 0 : -1;
    }
    if (fclose(f) != 0) rc = -1;
    return rc;
}

#endif /* LX_TEST_H */
