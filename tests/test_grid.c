/* test_grid.c - illuminance grids: closed forms (an isotropic source, a Lambertian downlight at the
 * table's own angles) within 1e-9, aim and rotation, tilt and maintenance factors, the near-field
 * subdivision against the exact Lambertian rectangle (sources.c), the cosine-indexed table against
 * the exact model, and OpenCL against its CPU twin (1e-6 relative). */
#include "lx_test.h"

#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

static lx_luminaire *model(lx_ctx *ctx, lx_lum_model_kind kind, double flux, double w, double l)
{
    lx_lum_model m = {.kind = kind, .flux_lm = flux, .width_m = w, .length_m = l};
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_from_model(ctx, &m, &lum));
    return lum;
}

/* Isotropic 1000 lm at (1, 2, 3): I = 1000 / (4 pi); on the plane z = 0 (normal +z) at (x, y):
 * E = I h / d^3 with h = 3, d = |p - s| (inverse-square law and cosine law). */
static void test_isotropic(void **state)
{
    lx_ctx *ctx = *state;
    lx_luminaire *lum = model(ctx, LX_LUM_MODEL_POINT, 1000, 0, 0);
    lx_placement pl = {.lum = lum, .pos_m = {1, 2, 3}, .aim = {0, 0, -1}};
    lx_plane p;
    lx_assert_ok(ctx, lx_plane_axis(ctx, 'z', 0, -4, 6, -3, 7, 0.5, 0, 0, &p));
    assert_int_equal(p.na, 21);
    assert_int_equal(p.nb, 21);
    double *pts = NULL;
    size_t n = 0;
    lx_assert_ok(ctx, lx_plane_points(ctx, &p, &pts, &n));
    double *E = malloc(n * sizeof *E);
    for (int interp = 0; interp <= 1; interp++) {
        lx_grid_opts o = {.model = LX_MODEL_POINT, .interp = (lx_interp)interp};
        lx_assert_ok(ctx, lx_grid_illuminance(ctx, &pl, 1, pts, n, p.normal, 1, &o, E));
        for (size_t i = 0; i < n; i++) {
            double dx = pts[3 * i] - 1, dy = pts[3 * i + 1] - 2, d = sqrt(dx * dx + dy * dy + 9);
            lx_assert_near(E[i], 1000 / (4 * PI) * 3 / (d * d * d), 0, 1e-9);
        }
    }
    /* maintenance factor 0.8 and two copies of the source: 1.6 x */
    lx_placement two[2] = {pl, pl};
    lx_grid_opts o = {.model = LX_MODEL_POINT, .maintenance_factor = 0.8};
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, two, 2, pts, 1, p.normal, 1, &o, E));
    double dx = pts[0] - 1, dy = pts[1] - 2, d = sqrt(dx * dx + dy * dy + 9);
    lx_assert_near(E[0], 1.6 * 1000 / (4 * PI) * 3 / (d * d * d), 0, 1e-9);
    lx_grid_stats s;
    double v[4] = {1, 2, 3, 6};
    lx_assert_ok(ctx, lx_grid_stats_compute(ctx, v, 4, &s));
    lx_assert_near(s.avg, 3, 0, 1e-15); /* (1+2+3+6)/4 */
    lx_assert_near(s.u0, 1.0 / 3, 0, 1e-15);
    lx_plane_points_free(pts);
    free(E);
    lx_luminaire_free(lum);
}

/* Lambertian downlight, F = 1000 lm, I = (F/pi) cos g, sampled every 1 deg: at the table's own
 * angles the interpolant is exact, and on a horizontal plane h below, at offset r = h tan g:
 * E = (F/pi) cos g x cos g / (h / cos g)^2 = F cos^4 g / (pi h^2). Also aimed at a wall. */
static void test_lambertian_downlight(void **state)
{
    lx_ctx *ctx = *state;
    lx_luminaire *lum = model(ctx, LX_LUM_MODEL_LAMBERT, 1000, 0, 0);
    double h = 2.5, pts[3 * 80], nz[3] = {0, 0, 1};
    double E[80];
    for (int k = 0; k < 80; k++) {
        double g = k * DEG, r = h * tan(g), az = 0.7 * k; /* any azimuth: the source is axial */
        pts[3 * k] = r * cos(az);
        pts[3 * k + 1] = r * sin(az);
        pts[3 * k + 2] = 0;
    }
    lx_placement pl = {.lum = lum, .pos_m = {0, 0, h}, .aim = {0, 0, -1}, .rotate_rad = 0.3};
    for (int interp = 0; interp <= 1; interp++) {
        lx_grid_opts o = {.model = LX_MODEL_POINT, .interp = (lx_interp)interp};
        lx_assert_ok(ctx, lx_grid_illuminance(ctx, &pl, 1, pts, 80, nz, 1, &o, E));
        for (int k = 0; k < 80; k++) {
            double c = cos(k * DEG);
            lx_assert_near(E[k], 1000 * c * c * c * c / (PI * h * h), 1e-12, 1e-9);
        }
    }
    /* the same luminaire aimed along +x at a wall x = 3 (normal -x, facing it) */
    lx_placement wall = {.lum = lum, .pos_m = {0, 0, 1}, .aim = {1, 0, 0}};
    double nx[3] = {-1, 0, 0};
    for (int k = 0; k < 80; k++) {
        double g = k * DEG, r = 3 * tan(g), az = 0.7 * k;
        pts[3 * k] = 3;
        pts[3 * k + 1] = r * cos(az);
        pts[3 * k + 2] = 1 + r * sin(az);
    }
    lx_grid_opts o = {.model = LX_MODEL_POINT};
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, &wall, 1, pts, 80, nx, 1, &o, E));
    for (int k = 0; k < 80; k++) {
        double c = cos(k * DEG);
        lx_assert_near(E[k], 1000 * c * c * c * c / (PI * 9), 1e-12, 1e-9);
    }
    /* facing away: nothing */
    double away[3] = {1, 0, 0};
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, &wall, 1, pts, 1, away, 1, &o, E));
    assert_true(E[0] == 0);
    lx_luminaire_free(lum);
}

/* Rotation turns C0 about the aim axis: a quadrant luminaire with 10 cd in C0 and 30 cd in C90
 * (constant in gamma), rotated by 90 deg, shows 30 cd along +x. Directly below at distance 1:
 * E = I cos(45)... we look along 45 deg gamma: E = I cos^3(45) / h^2 with h = 1. */
static void test_rotation(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n1 -1 1 2 2 1 2 0 0 0\n1 1 1\n0 90\n0 90\n10 10\n30 30\n";
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "q.ies", t, strlen(t), &lum));
    double pts[6] = {1, 0, 0, 0, 1, 0}, nz[3] = {0, 0, 1}, E[2];
    double c3 = pow(cos(45 * DEG), 3);
    for (int rot = 0; rot <= 1; rot++) {
        lx_placement pl = {.lum = lum, .pos_m = {0, 0, 1}, .aim = {0, 0, -1}, .rotate_rad = rot * 90 * DEG};
        lx_grid_opts o = {.model = LX_MODEL_POINT};
        lx_assert_ok(ctx, lx_grid_illuminance(ctx, &pl, 1, pts, 2, nz, 1, &o, E));
        lx_assert_near(E[0], (rot ? 30 : 10) * c3, 0, 1e-12);
        lx_assert_near(E[1], (rot ? 10 : 30) * c3, 0, 1e-12);
    }
    lx_luminaire_free(lum);
}

/* Near field: Lambertian openings against their closed forms (sources.c). A panel of flux F and
 * area A radiating I = (F / pi) cos g has luminance L = F / (pi A), so the exact illuminance on a
 * parallel receiver is lx_rect_illuminance / lx_disk_illuminance (Howell B-3 superposed; the
 * parallel element-to-disk factor) at that L. The tables are sampled every 0.25 deg (0.5 deg for
 * the disk), so linear interpolation of cos g errs by at most (0.25 deg)^2 / 8 = 2.4e-6 relative
 * (9.5e-6 for 0.5 deg); the refinement stops when the Richardson estimate changes by less than the
 * tolerance 1e-4, whose error is about 1/16 of that change. Bound asserted: 2e-4 relative, at
 * distance / largest dimension 0.1, 0.5, 1, 2, 4.9, under the centre and off it. */
static lx_luminaire *disk_lum(lx_ctx *ctx, double D, double F)
{
    /* LM-63-2002, type C, absolute (multiplier 1, lamps -1), width = length = -D: a circular opening */
    size_t cap = 1 << 16;
    char *t = malloc(cap), *p = t;
    p += sprintf(p, "IESNA:LM-63-2002\n[TEST] disk\nTILT=NONE\n1 -1 1 361 1 1 2 %.17g %.17g 0\n1 1 1\n", -D, -D);
    for (int g = 0; g <= 360; g++) p += sprintf(p, "%g ", g * 0.5);
    p += sprintf(p, "\n0\n");
    for (int g = 0; g <= 360; g++) p += sprintf(p, "%.17g ", g <= 180 ? F / PI * cos(g * 0.5 * DEG) : 0.0);
    p += sprintf(p, "\n");
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "disk.ies", t, (size_t)(p - t), &lum));
    free(t);
    return lum;
}

static void test_near_field(void **state)
{
    lx_ctx *ctx = *state;
    static const double ratio[5] = {0.1, 0.5, 1, 2, 4.9};
    const double F = 1000, W = 1, Lr = 0.6, D = 0.8;
    /* LM-63 axes: the length (W, along x here) lies along C0-C180, the width (Lr) along C90-C270 */
    lx_lum_model m = {.kind = LX_LUM_MODEL_LAMBERT, .flux_lm = F, .width_m = Lr, .length_m = W, .step_deg = 0.25};
    lx_luminaire *rect = NULL, *disk = disk_lum(ctx, D, F);
    lx_assert_ok(ctx, lx_luminaire_from_model(ctx, &m, &rect));
    double nz[3] = {0, 0, 1}, worst = 0;
    for (int shape = 0; shape < 2; shape++) {
        double size = shape ? D : sqrt(W * W + Lr * Lr); /* the five-times rule's largest dimension */
        for (int k = 0; k < 5; k++)
            for (int off = 0; off < 2; off++) {
                double h = ratio[k] * size, x = off ? 0.3 * W : 0, y = off ? 0.1 * Lr : 0;
                h = sqrt(h * h - x * x - y * y); /* centre-to-point distance = ratio x size */
                if (!(h > 0)) continue;
                lx_source_result ex;
                if (shape) lx_assert_ok(ctx, lx_disk_illuminance(ctx, F / (PI * PI * D * D / 4), D / 2, h, hypot(x, y), LX_MODEL_EXACT, &ex));
                else lx_assert_ok(ctx, lx_rect_illuminance(ctx, F / (PI * W * Lr), W, Lr, h, x, y, LX_MODEL_EXACT, &ex));
                lx_placement pl = {.lum = shape ? disk : rect, .pos_m = {0, 0, h}, .aim = {0, 0, -1}};
                double pt[3] = {x, y, 0}, E = 0;
                lx_counters c0, c1;
                lx_ctx_counters(ctx, &c0);
                for (int interp = 0; interp <= 2; interp += 2) { /* bilinear; table (CPU twin, same near field) */
                    lx_grid_opts o = {.model = LX_MODEL_AUTO, .interp = (lx_interp)interp, .backend = LX_BACKEND_CPU};
                    lx_assert_ok(ctx, lx_grid_illuminance(ctx, &pl, 1, pt, 1, nz, 1, &o, &E));
                    double rel = fabs(E / ex.exact_lx - 1);
                    worst = fmax(worst, rel);
                    if (rel > 2e-4)
                        print_message("%s d/size %.1f off %d interp %d: E %.9g exact %.9g (%+.2e)\n", shape ? "disk" : "rect",
                                      ratio[k], off, interp, E, ex.exact_lx, E / ex.exact_lx - 1);
                    lx_assert_near(E, ex.exact_lx, 0, 2e-4);
                }
                lx_ctx_counters(ctx, &c1);
                assert_int_equal(c1.nearfield_pairs - c0.nearfield_pairs, 2); /* one pair per call */
                assert_true(c1.nearfield_subdivisions - c0.nearfield_subdivisions >= 2 * (4 + 16 + 64)); /* n = 2, 4, 8 at least */
            }
    }
    print_message("near field: worst relative error %.2e against the closed forms (bound 2e-4)\n", worst);
    /* the point model is far off at 0.5 x the diagonal (what the five-times rule is for) */
    lx_source_result ex;
    double h = 0.5 * sqrt(W * W + Lr * Lr), pt[3] = {0, 0, 0}, Ep;
    lx_assert_ok(ctx, lx_rect_illuminance(ctx, F / (PI * W * Lr), W, Lr, h, 0, 0, LX_MODEL_EXACT, &ex));
    lx_placement pl = {.lum = rect, .pos_m = {0, 0, h}, .aim = {0, 0, -1}};
    lx_grid_opts op = {.model = LX_MODEL_POINT};
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, &pl, 1, pt, 1, nz, 1, &op, &Ep));
    assert_true(fabs(Ep / ex.exact_lx - 1) > 0.1);
    /* a tolerance out of range is refused */
    lx_grid_opts bad = {.nearfield_tol = 0.5};
    assert_int_equal(lx_grid_illuminance(ctx, &pl, 1, pt, 1, nz, 1, &bad, &Ep), LX_EINVAL);
    lx_luminaire_free(rect);
    lx_luminaire_free(disk);
}

/* Tilt: the factor of the lamp tilt (the aim's angle from the nadir) scales the result. */
static void test_tilt(void **state)
{
    lx_ctx *ctx = *state;
    const char *t = "IESNA:LM-63-2002\n[TEST] x\nTILT=INCLUDE\n1\n2\n0 90\n1 0.5\n1 -1 1 2 1 1 2 0 0 0\n1 1 1\n0 180\n0\n100 100\n";
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "t.ies", t, strlen(t), &lum));
    lx_placement pl = {.lum = lum, .pos_m = {0, 0, 0}, .aim = {1, 0, -1}}; /* 45 deg: factor 0.75 */
    double pt[3] = {0, 0, -2}, nz[3] = {0, 0, 1}, E;
    lx_grid_opts o = {.model = LX_MODEL_POINT};
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, &pl, 1, pt, 1, nz, 1, &o, &E));
    lx_assert_near(E, 0.75 * 100 / 4.0, 0, 1e-12); /* 0.75 x 100 cd / 2^2 */
    lx_luminaire_free(lum);
}

/* A scene: 3 luminaires over a 10 x 8 m plane, with an asymmetric synthetic luminaire (the
 * C90-C270 kind) aimed and rotated. */
static lx_luminaire *asym(lx_ctx *ctx)
{
    const char *t = "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n1 -1 1 4 5 1 2 0 0 0\n1 1 1\n0 30 60 90\n90 135 180 225 270\n"
                    "600 400 100 0\n600 500 200 10\n600 300 100 5\n600 600 300 20\n600 800 200 0\n";
    lx_luminaire *lum = NULL;
    lx_assert_ok(ctx, lx_luminaire_read_mem(ctx, "a.ies", t, strlen(t), &lum));
    return lum;
}

static void scene(lx_luminaire *a, lx_luminaire *b, lx_placement pl[3])
{
    pl[0] = (lx_placement){.lum = a, .pos_m = {2, 2, 3}, .aim = {0, 0, -1}, .rotate_rad = 0.4};
    pl[1] = (lx_placement){.lum = a, .pos_m = {7, 5, 2.8}, .aim = {0.3, -0.2, -1}, .rotate_rad = -1.1};
    pl[2] = (lx_placement){.lum = b, .pos_m = {5, 3, 3.2}, .aim = {0, 0, -1}};
}

/* The table path against the exact bilinear model: the resampling error on a smooth-ish table. */
static void test_table_vs_exact(void **state)
{
    lx_ctx *ctx = *state;
    lx_luminaire *a = asym(ctx), *b = model(ctx, LX_LUM_MODEL_LAMBERT, 2000, 0, 0);
    lx_placement pl[3];
    scene(a, b, pl);
    lx_plane p;
    lx_assert_ok(ctx, lx_plane_axis(ctx, 'z', 0.8, 0, 10, 0, 8, 0.1, 0, 0, &p));
    double *pts;
    size_t n;
    lx_assert_ok(ctx, lx_plane_points(ctx, &p, &pts, &n));
    double *E0 = malloc(n * sizeof *E0), *E1 = malloc(n * sizeof *E1);
    lx_grid_opts o0 = {.model = LX_MODEL_POINT}, o1 = {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 3, pts, n, p.normal, 1, &o0, E0));
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 3, pts, n, p.normal, 1, &o1, E1));
    double worst = 0, emax = 0;
    for (size_t i = 0; i < n; i++) emax = fmax(emax, E0[i]);
    for (size_t i = 0; i < n; i++) worst = fmax(worst, fabs(E1[i] - E0[i]) / emax);
    print_message("table vs exact bilinear: max |diff| / E_max = %.2e over %zu points\n", worst, n);
    /* resampling a 30-deg table at about 0.1-0.2 deg: measured 2e-4 of the peak; bound 1e-3 */
    assert_true(worst < 1e-3);
    lx_plane_points_free(pts);
    free(E0);
    free(E1);
    lx_luminaire_free(a);
    lx_luminaire_free(b);
}

/* A vectorised table path (AVX-512, 8 points at a time; AVX2, 4 at a time; luminaire-outer blocks;
 * SKIPPED where this machine cannot run it, tests/lx_test.h) against the plain C loop
 * (LX_SIMD=scalar): the same formulas, so they agree to rounding (FMA); bound 1e-12 relative to
 * the point's value. Per-point normals (tilted both ways, some facing away) and a count that is
 * not a multiple of 8 exercise the unshared path and the tails. */
static void simd_twin(void **state, lx_simd path)
{
    lx_ctx *ctx = *state;
    lx_test_simd_begin(path);
    lx_test_simd_end();
    lx_luminaire *a = asym(ctx), *b = model(ctx, LX_LUM_MODEL_LAMBERT, 2000, 0, 0);
    lx_placement pl[3];
    scene(a, b, pl);
    const size_t n = 10003;
    double *pts = malloc(3 * n * sizeof *pts), *nrm = malloc(3 * n * sizeof *nrm);
    double *E0 = malloc(n * sizeof *E0), *E1 = malloc(n * sizeof *E1);
    for (size_t i = 0; i < n; i++) {
        double u = (double)(i % 101) / 100, v = (double)(i / 101) / 99, tx = 0.9 * sin(0.37 * (double)i);
        pts[3 * i] = 10 * u;
        pts[3 * i + 1] = 8 * v;
        pts[3 * i + 2] = 0.8 + 0.5 * cos(0.11 * (double)i);
        nrm[3 * i] = tx;
        nrm[3 * i + 1] = 0;
        nrm[3 * i + 2] = sqrt(1 - tx * tx);
    }
    for (int run = 0; run < 2; run++) {
        int shared = run & 1;
        lx_grid_opts o = {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU};
        lx_test_simd_begin(LX_SIMD_SCALAR);
        lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 3, pts, n, shared ? nrm + 3 : nrm, shared, &o, E0));
        lx_test_simd_end();
        lx_test_simd_begin(path);
        lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 3, pts, n, shared ? nrm + 3 : nrm, shared, &o, E1));
        lx_test_simd_end();
        size_t zeros = 0;
        for (size_t i = 0; i < n; i++) {
            lx_assert_near(E1[i], E0[i], 1e-300, 1e-12);
            zeros += E0[i] == 0;
        }
        if (!shared) assert_true(zeros < n); /* some light arrives */
    }
    free(pts);
    free(nrm);
    free(E0);
    free(E1);
    lx_luminaire_free(a);
    lx_luminaire_free(b);
}

static void test_simd_twin_avx512(void **state) { simd_twin(state, LX_SIMD_AVX512); }
static void test_simd_twin_avx2(void **state) { simd_twin(state, LX_SIMD_AVX2); }

/* OpenCL kernel against its CPU twin (same table): 1e-6 relative in double (the default kernel
 * wherever the device has fp64; measured 1.4e-14). The float kernel (opts.fp32) is bounded by 1e-5
 * of max(E, 1e-3 E_max): a float direction is off by ~6e-8 relative, and the table's slope
 * (d ln I / d ln t up to ~50 on this luminaire) multiplies that; measured with the kernel edited:
 * double arithmetic on float-rounded inputs 8.5e-7, the direction computed in double and rounded
 * to float 4.1e-6, all float 5.9e-6. So 1e-6 in float is out of reach for steep photometry; the
 * double kernel meets it. Skips without a device. */
static void test_opencl_parity(void **state)
{
    lx_ctx *ctx = *state;
    lx_cl_device_info info;
    if (lx_cl_info(ctx, &info) != LX_OK) skip();
    lx_luminaire *a = asym(ctx), *b = model(ctx, LX_LUM_MODEL_LAMBERT, 2000, 0, 0);
    lx_placement pl[3];
    scene(a, b, pl);
    lx_plane p;
    lx_assert_ok(ctx, lx_plane_axis(ctx, 'z', 0.8, 0, 10, 0, 8, 0.05, 0, 0, &p));
    double *pts;
    size_t n;
    lx_assert_ok(ctx, lx_plane_points(ctx, &p, &pts, &n));
    double *Ec = malloc(n * sizeof *Ec), *Eg = malloc(n * sizeof *Eg);
    lx_grid_opts oc = {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU};
    lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 3, pts, n, p.normal, 1, &oc, Ec));
    for (int fp32 = 0; fp32 <= 1; fp32++) {
        if (!fp32 && !info.fp64) continue;
        lx_grid_opts og = {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_OPENCL, .fp32 = fp32};
        lx_assert_ok(ctx, lx_grid_illuminance(ctx, pl, 3, pts, n, p.normal, 1, &og, Eg));
        assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_OPENCL);
        double emax = 0, worst = 0;
        for (size_t i = 0; i < n; i++) emax = fmax(emax, Ec[i]);
        for (size_t i = 0; i < n; i++) {
            double rel = fabs(Eg[i] - Ec[i]) / fmax(Ec[i], fp32 ? 1e-3 * emax : 1e-300);
            worst = fmax(worst, rel);
        }
        print_message("OpenCL %s vs CPU twin: max relative difference %.2e (%zu points)\n", fp32 ? "float" : "double", worst, n);
        assert_true(worst <= (fp32 ? 1e-5 : 1e-6));
    }
    lx_plane_points_free(pts);
    free(Ec);
    free(Eg);
    lx_luminaire_free(a);
    lx_luminaire_free(b);
}

static void test_errors(void **state)
{
    lx_ctx *ctx = *state;
    lx_luminaire *lum = model(ctx, LX_LUM_MODEL_POINT, 1000, 0, 0);
    lx_placement pl = {.lum = lum, .pos_m = {0, 0, 1}, .aim = {0, 0, 0}};
    double pt[3] = {0, 0, 0}, nz[3] = {0, 0, 1}, E = -7;
    assert_int_equal(lx_grid_illuminance(ctx, &pl, 1, pt, 1, nz, 1, NULL, &E), LX_EINVAL); /* zero aim */
    pl.aim[2] = -1;
    double bad[3] = {0, 0, 2};
    assert_int_equal(lx_grid_illuminance(ctx, &pl, 1, pt, 1, bad, 1, NULL, &E), LX_EINVAL); /* not unit */
    lx_grid_opts o = {.maintenance_factor = 1.5};
    assert_int_equal(lx_grid_illuminance(ctx, &pl, 1, pt, 1, nz, 1, &o, &E), LX_EINVAL);
    lx_grid_opts ot = {.interp = LX_INTERP_TABLE, .table_n = 1}; /* table rows: 2 to 16384 */
    assert_int_equal(lx_grid_illuminance(ctx, &pl, 1, pt, 1, nz, 1, &ot, &E), LX_EINVAL);
    ot.table_n = 16385;
    assert_int_equal(lx_grid_illuminance(ctx, &pl, 1, pt, 1, nz, 1, &ot, &E), LX_EINVAL);
    assert_true(E == -7); /* untouched on failure */
    lx_luminaire_free(lum);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_isotropic),      cmocka_unit_test(test_lambertian_downlight),
        cmocka_unit_test(test_rotation),       cmocka_unit_test(test_near_field),
        cmocka_unit_test(test_tilt),           cmocka_unit_test(test_table_vs_exact),
        cmocka_unit_test(test_simd_twin_avx512), cmocka_unit_test(test_simd_twin_avx2),
        cmocka_unit_test(test_opencl_parity),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
