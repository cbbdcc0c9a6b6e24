/* test_cube.c - OpenEXR cube maps: texel solid angles and moments against Gauss-Legendre
 * quadrature and sphere totals, face orientation against OpenEXR's own CubeMap::direction
 * (transcribed below), furnace, one bright face, half-lit SH9, fast = brute, EXR round trip. */
#include "lx_test.h"

#include <string.h>
#include <unistd.h>

/* 8-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun, Table 25.4). */
static const double gl_x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
static const double gl_w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

/* integral over [a0,a1] x [b0,b1] of the face point (1, a, b): sr, moment (n, u, v), second
 * moments (nn, uu, vv, nu, nv, uv) in the face frame, by 8x8 Gauss-Legendre on 4x4 sub-squares */
static void quad(double a0, double a1, double b0, double b1, double q[10])
{
    memset(q, 0, 10 * sizeof *q);
    for (int sa = 0; sa < 4; sa++)
        for (int sb = 0; sb < 4; sb++) {
            double A0 = a0 + (a1 - a0) * sa / 4, A1 = a0 + (a1 - a0) * (sa + 1) / 4;
            double B0 = b0 + (b1 - b0) * sb / 4, B1 = b0 + (b1 - b0) * (sb + 1) / 4;
            for (int i = 0; i < 8; i++)
                for (int j = 0; j < 8; j++) {
                    double xa = (i < 4 ? -gl_x[i] : gl_x[i - 4]), wa = gl_w[i < 4 ? i : i - 4];
                    double xb = (j < 4 ? -gl_x[j] : gl_x[j - 4]), wb = gl_w[j < 4 ? j : j - 4];
                    double a = 0.5 * (A0 + A1) + 0.5 * (A1 - A0) * xa, b = 0.5 * (B0 + B1) + 0.5 * (B1 - B0) * xb;
                    double w = wa * wb * 0.25 * (A1 - A0) * (B1 - B0), r2 = 1 + a * a + b * b, r = sqrt(r2);
                    double dw = w / (r2 * r), o[3] = {1 / r, a / r, b / r};
                    q[0] += dw;
                    for (int k = 0; k < 3; k++) q[1 + k] += o[k] * dw;
                    q[4] += o[0] * o[0] * dw, q[5] += o[1] * o[1] * dw, q[6] += o[2] * o[2] * dw;
                    q[7] += o[0] * o[1] * dw, q[8] += o[0] * o[2] * dw, q[9] += o[1] * o[2] * dw;
                }
        }
}

/* the luxcalc frame of face f: (axis, u, v) with world = axis + a u + b v; read back from
 * lx_envmap_cube_direction at the face centre and along its axes (scaled by |(1, a, b)|) */
static void geometry(void **state)
{
    (void)state;
    int sizes[3] = {1, 3, 16};
    for (int z = 0; z < 3; z++) {
        int N = sizes[z];
        double tot = 0, mt[3] = {0, 0, 0};
        for (int R = 0; R < 6 * N; R++)
            for (int c = 0; c < N; c++) {
                double sr = lx_envmap_cube_texel_sr(N, R % N, c), m[3];
                lx_envmap_cube_texel_moment(N, R, c, m);
                tot += sr;
                for (int k = 0; k < 3; k++) mt[k] += m[k];
                if (R < N) { /* face 0: check every texel against quadrature in the face frame */
                    double q[10], a0 = 2.0 * c / N - 1, b0 = 2.0 * R / N - 1;
                    quad(a0, a0 + 2.0 / N, b0, b0 + 2.0 / N, q);
                    lx_assert_near(sr, q[0], 1e-13, 1e-11);
                    /* face 0 (OpenEXR +X) frame: axis +y, u = -x, v = -z (ImfEnvmap.h, mapped to +z up) */
                    lx_assert_near(m[1], q[1], 1e-13, 1e-11);
                    lx_assert_near(-m[0], q[2], 1e-13, 1e-11);
                    lx_assert_near(-m[2], q[3], 1e-13, 1e-11);
                }
            }
        lx_assert_near(tot, 4 * M_PI, 1e-12, 0); /* the cube's texels tile the sphere: 4 pi sr */
        for (int k = 0; k < 3; k++) lx_assert_near(mt[k], 0, 1e-12, 0); /* integral of omega over the sphere = 0 */
    }
}

/* OpenEXR ImfEnvmap.cpp, CubeMap::direction(face, dw, positionInFace) for an N x 6N map, and the
 * inverse of CubeMap::pixelPosition (pixel (x, y) of face f -> positionInFace), transcribed. */
static void exr_direction(int N, int f, double x, double y, double d[3])
{
    double px, py; /* positionInFace */
    switch (f) {
    case 0: py = x, px = N - 1 - y; break;         /* +X: pos.x = min.x + pif.y, pos.y = max.y - pif.x */
    case 1: py = N - 1 - x, px = N - 1 - y; break; /* -X: pos.x = max.x - pif.y, pos.y = max.y - pif.x */
    case 2: px = x, py = N - 1 - y; break;         /* +Y: pos.x = min.x + pif.x, pos.y = max.y - pif.y */
    case 3: px = x, py = y; break;                 /* -Y: pos.x = min.x + pif.x, pos.y = min.y + pif.y */
    case 4: px = N - 1 - x, py = N - 1 - y; break; /* +Z: pos.x = max.x - pif.x, pos.y = max.y - pif.y */
    default: px = x, py = N - 1 - y; break;        /* -Z: pos.x = min.x + pif.x, pos.y = max.y - pif.y */
    }
    double a = px / (N - 1) * 2 - 1, b = py / (N - 1) * 2 - 1, e[3];
    switch (f) {
    case 0: e[0] = 1, e[1] = a, e[2] = b; break;
    case 1: e[0] = -1, e[1] = a, e[2] = b; break;
    case 2: e[0] = a, e[1] = 1, e[2] = b; break;
    case 3: e[0] = a, e[1] = -1, e[2] = b; break;
    case 4: e[0] = a, e[1] = b, e[2] = 1; break;
    default: e[0] = a, e[1] = b, e[2] = -1; break;
    }
    /* OpenEXR (y up; lat-long longitude +pi at the left, pi/2 = +x) -> luxcalc (+z up, phi = 0 = +x
     * at the left, pi/2 = +y): (x, y, z)_e -> (-z, x, y), the map under which OpenEXR's lat-long
     * layout (ImfEnvmap.h LatLongMap) and ours (CLI.md) coincide */
    double l = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    d[0] = -e[2] / l, d[1] = e[0] / l, d[2] = e[1] / l;
}

static void orientation(void **state)
{
    lx_ctx *ctx = *state;
    /* directions: OpenEXR samples pixel k of a face at 2k/(N-1) - 1, which is our fractional
     * column k N / (N - 1) */
    int N = 8;
    for (int f = 0; f < 6; f++)
        for (int y = 0; y < N; y++)
            for (int x = 0; x < N; x++) {
                double d[3], e[3];
                exr_direction(N, f, x, y, e);
                /* the last OpenEXR row lies on the face's lower edge: ask just above it (row f N + N is
                 * the next face in the file) */
                double row = y == N - 1 ? f * N + N * (1 - 1e-13) : f * N + (double)y * N / (N - 1);
                lx_envmap_cube_direction(N, row, (double)x * N / (N - 1), d);
                for (int k = 0; k < 3; k++) lx_assert_near(d[k], e[k], 1e-11, 0);
            }
    /* irradiance: a cube map whose texels are set through OpenEXR's mapping (centre of texel (x, y)
     * = OpenEXR pixel position (x + 0.5)(N - 1)/N - 0.5... i.e. our centre) from the linear field
     * L = 2 + 0.6 x + 0.3 y - 0.5 z, and the lat-long map of the same field: E(n) = pi 2 +
     * (2 pi / 3)(0.6, 0.3, -0.5) . n for a linear field (closed form: integral of (c . w) max(0, n . w)
     * = (2 pi / 3) c . n over the sphere), up to the O(h^2) of piecewise-constant sampling */
    N = 64;
    lx_envmap *cube = NULL, *ll = NULL;
    lx_assert_ok(ctx, lx_envmap_create_cube(ctx, N, 1, &cube));
    lx_assert_ok(ctx, lx_envmap_create(ctx, 256, 128, 1, &ll));
    for (int f = 0; f < 6; f++)
        for (int y = 0; y < N; y++)
            for (int x = 0; x < N; x++) {
                double d[3], s = (double)(N - 1) / N;
                exr_direction(N, f, (x + 0.5) * s, (y + 0.5) * s, d);
                cube->data[((size_t)f * N + y) * N + x] = (float)(2 + 0.6 * d[0] + 0.3 * d[1] - 0.5 * d[2]);
            }
    for (int j = 0; j < 128; j++)
        for (int i = 0; i < 256; i++) {
            double d[3];
            lx_envmap_direction(256, 128, j + 0.5, i + 0.5, d);
            ll->data[j * 256 + i] = (float)(2 + 0.6 * d[0] + 0.3 * d[1] - 0.5 * d[2]);
        }
    double dirs[18] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    lx_irr_opts o = {.method = LX_IRR_FAST};
    double Ec[6], El[6];
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, cube, 6, dirs, &o, Ec));
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, ll, 6, dirs, &o, El));
    for (int k = 0; k < 6; k++) {
        const double *n = dirs + 3 * k;
        double ref = 2 * M_PI + 2 * M_PI / 3 * (0.6 * n[0] + 0.3 * n[1] - 0.5 * n[2]);
        lx_assert_near(Ec[k], ref, 0, 2e-4);
        lx_assert_near(El[k], ref, 0, 2e-4);
        lx_assert_near(Ec[k], El[k], 0, 3e-4);
    }
    lx_envmap_free(cube);
    lx_envmap_free(ll);
}

static void furnace_and_faces(void **state)
{
    lx_ctx *ctx = *state;
    int N = 32; /* exact at any size (768 was needed for 1e-6 when crossed texels were clamped) */
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_envmap_create_cube(ctx, N, 3, &m));
    for (size_t k = 0; k < (size_t)6 * N * N * 3; k++) m->data[k] = 1;
    double n[12] = {0.3, -0.2, 0.9, 0, 0, 1, -0.7, 0.1, 0.2, 0.5, 0.5, -0.5}, E[12];
    for (int k = 0; k < 4; k++) {
        double l = sqrt(n[3 * k] * n[3 * k] + n[3 * k + 1] * n[3 * k + 1] + n[3 * k + 2] * n[3 * k + 2]);
        for (int c = 0; c < 3; c++) n[3 * k + c] /= l;
    }
    for (int meth = LX_IRR_AUTO; meth <= LX_IRR_BRUTE; meth++) {
        lx_irr_opts o = {.method = (lx_irr_method)meth};
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 4, n, &o, E));
        /* furnace: E = pi L; SH9 exactly, the sums too: the texels the horizon cuts are integrated in
         * closed form (Lambert's formula on the clipped texel; clamping them after integration
         * erred by 2.2e-4 at N = 32, 1.03e-6 at 512) */
        for (int k = 0; k < 12; k++) lx_assert_near(E[k], M_PI, 0, 1e-12);
        lx_assert_near(E[3], M_PI, 0, 1e-12); /* n = +z: no texel straddles, the sums are exact */
    }
    /* one face bright (L = 1): E for the face's axis = projected solid angle of the face. Lambert:
     * 4 edges of angle acos(1/3) (corners (1, +-1, +-1)/sqrt 3) with great-circle normals at 45 deg
     * to the axis: 1/2 * 4 acos(1/3) / sqrt 2 = sqrt 2 acos(1/3) = 1.7408 sr. The horizon of the
     * axis runs along texel edges of the side faces (N even), so the sums are exact. */
    const double face_axis[6][3] = {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {-1, 0, 0}, {1, 0, 0}};
    double want = sqrt(2.0) * acos(1.0 / 3);
    lx_envmap_free(m);
    N = 32;
    lx_assert_ok(ctx, lx_envmap_create_cube(ctx, N, 3, &m));
    for (int f = 0; f < 6; f++) {
        memset(m->data, 0, (size_t)6 * N * N * 3 * sizeof(float));
        for (size_t k = (size_t)f * N * N * 3; k < (size_t)(f + 1) * N * N * 3; k++) m->data[k] = 1;
        for (int meth = LX_IRR_FAST; meth <= LX_IRR_BRUTE; meth += LX_IRR_BRUTE - LX_IRR_FAST) { /* the sums */
            lx_irr_opts o = {.method = (lx_irr_method)meth};
            lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 1, face_axis[f], &o, E));
            for (int c = 0; c < 3; c++) lx_assert_near(E[c], want, 0, 1e-12);
        }
        /* SH9: within 3/32 of the face's integral L d omega = 4 pi / 6 (README "SH9 ringing") */
        lx_irr_opts o = {.method = LX_IRR_SH9};
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 1, face_axis[f], &o, E));
        lx_assert_near(E[0], want, 3.0 / 32 * 4 * M_PI / 6, 0);
    }
    lx_envmap_free(m);
}

/* half-lit (L = 1 where z > 0): E(n) = pi (1 + n_z) / 2 has no l = 2 part (the integral of
 * P2(z) over z in [0, 1] is 0), so SH9 is exact: a test of the exact second moments */
static void half_lit_sh9(void **state)
{
    lx_ctx *ctx = *state;
    int N = 16;
    lx_envmap *m = NULL, *e = NULL;
    lx_assert_ok(ctx, lx_envmap_create_cube(ctx, N, 1, &m));
    for (int R = 0; R < 6 * N; R++)
        for (int c = 0; c < N; c++) {
            double d[3];
            lx_envmap_texel_direction(m, R, c, d);
            m->data[(size_t)R * N + c] = d[2] > 0 ? 1.0f : 0.0f;
        }
    double n[9] = {1, 0, 0, 0, 0, 1, 0.6, 0, -0.8}, E[3];
    lx_irr_opts o = {.method = LX_IRR_SH9}; /* the half-lit sphere needs SH9's exact second moments */
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 3, n, &o, E));
    for (int k = 0; k < 3; k++) lx_assert_near(E[k], M_PI * (1 + n[3 * k + 2]) / 2, 1e-12, 0);
    lx_sh9 sh;
    lx_assert_ok(ctx, lx_sh9_project(ctx, m, &sh));
    for (int k = 4; k < 9; k++) lx_assert_near(sh.c[k][0], 0, 1e-13, 0);
    /* map output: a cube map of the same size, each texel E at its centre */
    lx_assert_ok(ctx, lx_irradiance_map(ctx, m, 0, 0, &o, &e));
    assert_int_equal(e->layout, LX_ENV_CUBE);
    assert_int_equal(e->height, 6 * N);
    for (int R = 0; R < 6 * N; R += 5)
        for (int c = 0; c < N; c += 3) {
            double d[3];
            lx_envmap_texel_direction(e, R, c, d);
            lx_assert_near(e->data[(size_t)R * N + c], M_PI * (1 + d[2]) / 2, 1e-6, 0);
        }
    lx_envmap_free(e);
    lx_envmap_free(m);
}

static void fast_equals_brute(void **state)
{
    lx_ctx *ctx = *state;
    int N = 24;
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_envmap_create_cube(ctx, N, 3, &m));
    unsigned r = 12345;
    for (size_t k = 0; k < (size_t)6 * N * N * 3; k++) {
        r = r * 1664525u + 1013904223u;
        m->data[k] = (float)((r >> 8) / 16777216.0 * ((k / 3) % 37 == 0 ? 100 : 1));
    }
    enum { ND = 200 };
    double dirs[3 * ND], Eb[3 * ND], Ef[3 * ND];
    for (int k = 0; k < ND; k++) {
        double z = 1 - 2 * (k + 0.5) / ND, p = k * 2.399963229728653; /* golden-angle spiral */
        dirs[3 * k] = sqrt(1 - z * z) * cos(p), dirs[3 * k + 1] = sqrt(1 - z * z) * sin(p), dirs[3 * k + 2] = z;
    }
    dirs[0] = 1, dirs[1] = 0, dirs[2] = 0; /* along an axis: rows parallel to the horizon */
    dirs[3] = 0.6, dirs[4] = 0.8, dirs[5] = 0;
    lx_irr_opts ob = {.method = LX_IRR_BRUTE}, of = {.method = LX_IRR_FAST};
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, ND, dirs, &ob, Eb));
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, ND, dirs, &of, Ef));
    for (int k = 0; k < 3 * ND; k++) lx_assert_near(Ef[k], Eb[k], 1e-12, 1e-12);
    lx_envmap_free(m);
}

static void exr_roundtrip(void **state)
{
    lx_ctx *ctx = *state;
    char dir[] = "/tmp/lxcubeXXXXXX", path[64];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/cube.exr", dir);
    int N = 20;
    lx_envmap *m = NULL, *r = NULL;
    lx_assert_ok(ctx, lx_envmap_create_cube(ctx, N, 3, &m));
    for (size_t k = 0; k < (size_t)6 * N * N * 3; k++) m->data[k] = (float)ldexp(1.0 + (k % 97) / 97.0, (int)(k % 13) - 6);
    lx_assert_ok(ctx, lx_envmap_write_exr(ctx, path, m, NULL));
    assert_int_equal(lx_exr_read(ctx, path, &r), LX_EUNSUPPORTED); /* lat-long-only readers refuse it */
    lx_assert_ok(ctx, lx_exr_read_any(ctx, path, &r));
    assert_int_equal(r->layout, LX_ENV_CUBE);
    assert_int_equal(r->width, N);
    assert_int_equal(r->height, 6 * N);
    assert_memory_equal(r->data, m->data, (size_t)6 * N * N * 3 * sizeof(float)); /* float: bit-exact */
    lx_envmap_free(r);
    lx_envmap *ll = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, 8, 4, 1, &ll));
    lx_assert_ok(ctx, lx_envmap_write_exr(ctx, path, ll, NULL));
    lx_assert_ok(ctx, lx_exr_read_any(ctx, path, &r));
    assert_int_equal(r->layout, LX_ENV_LATLONG);
    lx_envmap_free(r);
    lx_envmap_free(ll);
    lx_envmap_free(m);
    unlink(path);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(geometry),
        cmocka_unit_test_setup_teardown(orientation, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(furnace_and_faces, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(half_lit_sh9, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(fast_equals_brute, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(exr_roundtrip, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
