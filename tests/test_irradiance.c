/* test_irradiance.c - irradiance from lat-long radiance maps: furnace (100 random normals), half-lit
 * sphere, single pixels (the horizon crossing them against an integration written here) and a sun
 * disc against closed forms, the direction convention, SH9's documented error bound and window, fast
 * vs brute force, OpenCL vs CPU parity. */
#include "lx_test.h"

#include <string.h>

static const lx_irr_method methods[3] = {LX_IRR_SH9, LX_IRR_BRUTE, LX_IRR_FAST};

static lx_envmap *make_map(lx_ctx *ctx, int w, int h, int ch)
{
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, w, h, ch, &m));
    return m;
}

/* 26 normals: the axes, the cube diagonals, edge midpoints, and a few odd ones */
static int test_normals(double n[][3])
{
    int k = 0;
    for (int a = -1; a <= 1; a++)
        for (int b = -1; b <= 1; b++)
            for (int c = -1; c <= 1; c++)
                if (a || b || c) {
                    double l = sqrt((double)(a * a + b * b + c * c));
                    n[k][0] = a / l, n[k][1] = b / l, n[k][2] = c / l;
                    k++;
                }
    return k;
}

/* Furnace: L constant gives E = pi L for every normal (integral of max(0, cos) over the sphere is
 * pi). SH9 is exact at any size (only the l = 0 coefficient is non-zero and the pixel solid angles
 * sum to 4 pi exactly); brute force and the fast path integrate max(0, n . w) exactly over every
 * pixel, the ones the horizon of n crosses included (before, they clamped those after integrating:
 * 8.1e-7 at 2048x1024), so 1e-12 holds at any size. */
static void furnace(void **state)
{
    lx_ctx *ctx = *state;
    const double L = 3.5;
    double n[26][3], E[26];
    int nn = test_normals(n);
    lx_envmap *m = make_map(ctx, 2048, 1024, 1);
    for (size_t k = 0; k < 2048u * 1024u; k++) m->data[k] = (float)L;
    for (int q = 0; q < 3; q++) {
        lx_irr_opts o = {.method = methods[q], .backend = LX_BACKEND_CPU};
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, nn, &n[0][0], &o, E));
        for (int k = 0; k < nn; k++) lx_assert_near(E[k], M_PI * L, 0, 1e-12);
    }
    lx_envmap_free(m);
    /* SH9 exact (1e-13) even on a 16x8 map */
    m = make_map(ctx, 16, 8, 1);
    for (int k = 0; k < 128; k++) m->data[k] = (float)L;
    for (int q = 0; q < 3; q++) { /* and the sums too: the horizon crosses big pixels there */
        lx_irr_opts o = {.method = methods[q], .backend = LX_BACKEND_CPU};
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, nn, &n[0][0], &o, E));
        for (int k = 0; k < nn; k++) lx_assert_near(E[k], M_PI * L, 0, q ? 1e-12 : 1e-13);
    }
    lx_envmap_free(m);
}

/* The furnace: L = 2 at 512 x 256 and 100 random normals (the first (0.3, -0.5, 0.8), which
 * gave 6.28311 instead of 2 pi when the crossed pixels were clamped): 2 pi within 1e-9 asked,
 * 1e-12 asserted (measured about 1e-15). */
static void furnace_random(void **state)
{
    lx_ctx *ctx = *state;
    enum { N = 100 };
    double n[N][3], E[N];
    unsigned r = 2024;
    for (int k = 0; k < N; k++) {
        double x, y, z, q;
        do {
            r = r * 1103515245u + 12345u, x = ((r >> 8) % 20001) / 10000.0 - 1;
            r = r * 1103515245u + 12345u, y = ((r >> 8) % 20001) / 10000.0 - 1;
            r = r * 1103515245u + 12345u, z = ((r >> 8) % 20001) / 10000.0 - 1;
            q = x * x + y * y + z * z;
        } while (q > 1 || q < 1e-4);
        n[k][0] = x, n[k][1] = y, n[k][2] = z;
    }
    n[0][0] = 0.3, n[0][1] = -0.5, n[0][2] = 0.8;
    lx_envmap *m = make_map(ctx, 512, 256, 1);
    for (size_t k = 0; k < 512u * 256u; k++) m->data[k] = 2.0f;
    double worst = 0;
    for (int q = 1; q < 3; q++) {
        lx_irr_opts o = {.method = methods[q], .backend = LX_BACKEND_CPU};
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, N, &n[0][0], &o, E)); /* normalises the normals */
        for (int k = 0; k < N; k++) {
            worst = fmax(worst, fabs(E[k] / (2 * M_PI) - 1));
            lx_assert_near(E[k], 2 * M_PI, 0, 1e-12);
        }
    }
    print_message("furnace, 100 random normals at 512x256: worst relative error %.2e (brute and fast)\n", worst);
    lx_envmap_free(m);
}

/* int over the pixel [t0, t1] x [p0, p1] of max(0, n . w) dw, by an integration written here: the
 * phi integral of max(0, A cos(phi - phi_n) + B) in closed form for each theta, and adaptive
 * Gauss-Kronrod in theta (its integrand has kinks where the horizon leaves the pixel's columns, and
 * a (theta - theta*)^(3/2) point where it turns; the adaptive rule refines there). */
typedef struct pix_q {
    double n[3], st, phin, p0, p1;
} pix_q;
static double pix_inner(const pix_q *q, double t)
{
    double A = q->st * sin(t), B = q->n[2] * cos(t), sum = 0;
    if (A <= 0) return B > 0 ? B * (q->p1 - q->p0) : 0;
    double c = -B / A;
    if (c >= 1) return 0;
    if (c <= -1) return A * (sin(q->p1 - q->phin) - sin(q->p0 - q->phin)) + B * (q->p1 - q->p0);
    double al = acos(c);
    for (int k = -2; k <= 2; k++) {
        double lo = fmax(q->phin + 2 * M_PI * k - al, q->p0), hi = fmin(q->phin + 2 * M_PI * k + al, q->p1);
        if (hi > lo) sum += A * (sin(hi - q->phin) - sin(lo - q->phin)) + B * (hi - lo);
    }
    return sum;
}
static double pix_gk(const pix_q *q, double a, double b, double *err)
{
    static const double x[8] = {0.991455371120812639, 0.949107912342758525, 0.864864423359769073, 0.741531185599394440,
                                0.586087235467691130, 0.405845151377397167, 0.207784955007898468, 0.0};
    static const double wk[8] = {0.022935322010529225, 0.063092092629978553, 0.104790010322250184, 0.140653259715525919,
                                 0.169004726639267903, 0.190350578064785410, 0.204432940075298892, 0.209482141084727828};
    static const double wg[4] = {0.129484966168869693, 0.279705391489276668, 0.381830050505118945, 0.417959183673469388};
    double c = 0.5 * (a + b), h = 0.5 * (b - a), fc = pix_inner(q, c) * sin(c), k = fc * wk[7], g = fc * wg[3];
    for (int i = 0; i < 7; i++) {
        double t1 = c - h * x[i], t2 = c + h * x[i], f1 = pix_inner(q, t1) * sin(t1), f2 = pix_inner(q, t2) * sin(t2);
        k += wk[i] * (f1 + f2);
        if (i & 1) g += wg[i / 2] * (f1 + f2);
    }
    *err = fabs((k - g) * h);
    return k * h;
}
static double pix_adapt(const pix_q *q, double a, double b, double tol, int depth)
{
    double err, v = pix_gk(q, a, b, &err);
    if (err <= tol || depth > 40) return v;
    return pix_adapt(q, a, 0.5 * (a + b), 0.5 * tol, depth + 1) + pix_adapt(q, 0.5 * (a + b), b, 0.5 * tol, depth + 1);
}

/* Single pixels the horizon crosses: one bright pixel at a time, normals whose horizons cut it
 * every way (through two meridians, two parallels, a corner, near the horizon's turning point),
 * against the integration above within 1e-12 of the pixel's solid angle. */
static void crossed_pixels(void **state)
{
    lx_ctx *ctx = *state;
    const int W = 64, H = 32;
    static const int pix[4][2] = {{5, 10}, {15, 40}, {16, 3}, {28, 60}};
    double worst = 0;
    for (int p = 0; p < 4; p++) {
        int j = pix[p][0], i = pix[p][1];
        lx_envmap *m = make_map(ctx, W, H, 1);
        m->data[(size_t)j * W + i] = 1.0f;
        double t0 = j * M_PI / H, t1 = (j + 1) * M_PI / H, p0 = i * 2 * M_PI / W, p1 = (i + 1) * 2 * M_PI / W;
        double dw = (p1 - p0) * (cos(t0) - cos(t1));
        for (int a = 0; a < 24; a++) {
            /* the horizon through a point of the pixel (its centre, corners, mid-edges) in a direction */
            double tq = a % 3 == 0 ? 0.5 * (t0 + t1) : a % 3 == 1 ? t0 : t1, pq = a % 2 ? p1 : 0.5 * (p0 + p1);
            double w[3] = {sin(tq) * cos(pq), sin(tq) * sin(pq), cos(tq)}, u[3] = {-sin(pq), cos(pq), 0};
            double v[3] = {cos(tq) * cos(pq), cos(tq) * sin(pq), -sin(tq)}, ang = a * 0.7853981633974483 * 0.9;
            double n[3];
            for (int k = 0; k < 3; k++) n[k] = cos(ang) * u[k] + sin(ang) * v[k] + 1e-3 * (a % 5 - 2) * w[k];
            double ln = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int k = 0; k < 3; k++) n[k] /= ln;
            pix_q q = {{n[0], n[1], n[2]}, hypot(n[0], n[1]), atan2(n[1], n[0]), p0, p1};
            if (q.phin < 0) q.phin += 2 * M_PI;
            double ref = pix_adapt(&q, t0, t1, 1e-16 * dw, 0);
            for (int meth = 1; meth < 3; meth++) {
                lx_irr_opts o = {.method = methods[meth], .backend = LX_BACKEND_CPU};
                double E;
                lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 1, n, &o, &E));
                worst = fmax(worst, fabs(E - ref) / dw);
                lx_assert_near(E, ref, 1e-12 * dw, 0);
            }
        }
        lx_envmap_free(m);
    }
    print_message("crossed pixels: worst |E - integral| = %.2e of the pixel's solid angle\n", worst);
}

/* Half-lit sphere, L = 1 for z > 0: E(n) = pi (1 + n_z) / 2 (the clamped cosine integrated over the
 * upper hemisphere; derivation: E is linear in n_z for this field because only the l = 0, 1 terms
 * survive the clamped-cosine filter, A_l = 0 for odd l >= 3, and the even l >= 2 terms of L - 1/2
 * vanish). With an even map height the field is exactly piecewise constant, so SH9 with exact
 * pixel integrals is exact to rounding at any size; so are brute force and fast. */
static void half_lit(void **state)
{
    lx_ctx *ctx = *state;
    double n[26][3], E[26];
    int nn = test_normals(n);
    int sizes[2][2] = {{32, 16}, {2048, 1024}};
    for (int s = 0; s < 2; s++) {
        int W = sizes[s][0], H = sizes[s][1];
        lx_envmap *m = make_map(ctx, W, H, 1);
        for (int j = 0; j < H / 2; j++)
            for (int i = 0; i < W; i++) m->data[(size_t)j * W + i] = 1.0f;
        for (int q = 0; q < 3; q++) {
            if (s == 0 && q > 0) continue;
            lx_irr_opts o = {.method = methods[q], .backend = LX_BACKEND_CPU};
            lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, nn, &n[0][0], &o, E));
            for (int k = 0; k < nn; k++) lx_assert_near(E[k], M_PI * (1 + n[k][2]) / 2, 1e-12, 0);
        }
        lx_envmap_free(m);
    }
}

/* 16-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz and Stegun table 25.4). */
static const double gl_x[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                               0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
static const double gl_w[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                               0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};

/* Projected solid angle of the patch theta in [t0, t1], phi in [p0, p1] for normal n, by 2-D
 * Gauss-Legendre quadrature of max(0, n . omega) sin theta (smooth when the patch lies wholly above
 * the horizon of n, so 16 x 16 nodes are exact to ~1e-15 relative for a patch this small). */
static double patch_projected_sr(double t0, double t1, double p0, double p1, const double n[3])
{
    double s = 0;
    for (int a = 0; a < 16; a++) {
        double xa = a < 8 ? -gl_x[7 - a] : gl_x[a - 8], wa = a < 8 ? gl_w[7 - a] : gl_w[a - 8];
        double t = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * xa;
        for (int b = 0; b < 16; b++) {
            double xb = b < 8 ? -gl_x[7 - b] : gl_x[b - 8], wb = b < 8 ? gl_w[7 - b] : gl_w[b - 8];
            double p = 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * xb;
            double c = n[0] * sin(t) * cos(p) + n[1] * sin(t) * sin(p) + n[2] * cos(t);
            s += wa * wb * (c > 0 ? c : 0) * sin(t);
        }
    }
    return s * 0.25 * (t1 - t0) * (p1 - p0);
}

/* One bright pixel whose lower edge is at 30 deg zenith: brute force and the fast path equal the
 * analytic projected solid angle times L for normals that see all of it; SH9 differs by at most
 * (3/32) L d omega (the SH9 response to a point source is (3/32) + c/2 + (15/32) c^2 against
 * max(0, c), largest gap 3/32 at c = 0), with the nonneg window by at most (3/28) L d omega and
 * never below zero ((3/28)(1 + 2c)^2 >= 0). */
static void single_pixel(void **state)
{
    lx_ctx *ctx = *state;
    const int W = 720, H = 360; /* 0.5 deg pixels */
    const int row = 60, col = 90; /* theta 30..30.5 deg, phi 45..45.5 deg */
    const double L = 1000.0;
    lx_envmap *m = make_map(ctx, W, H, 1);
    m->data[(size_t)row * W + col] = (float)L;
    double t0 = row * M_PI / H, t1 = (row + 1) * M_PI / H, p0 = col * 2 * M_PI / W, p1 = (col + 1) * 2 * M_PI / W;
    double dw = (2 * M_PI / W) * (cos(t0) - cos(t1));
    double n[26][3], E[3][26];
    int nn = test_normals(n);
    for (int q = 0; q < 3; q++) {
        lx_irr_opts o = {.method = methods[q], .backend = LX_BACKEND_CPU};
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, nn, &n[0][0], &o, E[q]));
    }
    double max_sh9 = 0;
    for (int k = 0; k < nn; k++) {
        double ref = L * patch_projected_sr(t0, t1, p0, p1, n[k]);
        /* the 2-D Gauss-Legendre reference is smooth only away from the horizon (crossed pixels:
         * crossed_pixels below) */
        double cmin = 1, cmax = -1;
        for (int a = 0; a <= 4; a++)
            for (int b = 0; b <= 4; b++) {
                double t = t0 + (t1 - t0) * a / 4, p = p0 + (p1 - p0) * b / 4;
                double c = n[k][0] * sin(t) * cos(p) + n[k][1] * sin(t) * sin(p) + n[k][2] * cos(t);
                cmin = fmin(cmin, c), cmax = fmax(cmax, c);
            }
        if (cmin < 0.01 && cmax > -0.01) continue;
        lx_assert_near(E[1][k], ref, 1e-6 * L * dw, 1e-9);
        lx_assert_near(E[2][k], ref, 1e-6 * L * dw, 1e-9);
        double err = fabs(E[0][k] - ref);
        max_sh9 = fmax(max_sh9, err / (L * dw));
        assert_true(err <= 3.0 / 32.0 * L * dw * (1 + 1e-9));
    }
    print_message("single pixel: max |SH9 - exact| = %.4f L d omega (bound 3/32 = 0.09375)\n", max_sh9);
    /* the nonneg window */
    lx_irr_opts o = {.method = LX_IRR_SH9, .window = LX_SH9_WINDOW_NONNEG};
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, nn, &n[0][0], &o, E[0]));
    for (int k = 0; k < nn; k++) {
        assert_true(E[0][k] >= 0);
        assert_true(fabs(E[0][k] - L * patch_projected_sr(t0, t1, p0, p1, n[k])) <= 3.0 / 28.0 * L * dw * (1 + 1e-6));
    }
    lx_envmap_free(m);
}

/* A sun disc of angular radius 0.2666 deg at 30 deg zenith (phi = 60 deg), drawn by area coverage
 * (each pixel's radiance = L x fraction of its solid angle inside the disc, by 32 x 32 sub-samples).
 * Analytic: the first moment of a spherical cap of half-angle d about axis s is pi sin^2(d) s, so
 * a normal that sees the whole disc gets E = L pi sin^2(d) (n . s). Brute force must give the
 * projected solid angle E / L within 1e-6 sr (it is within ~1e-8 sr: the residue, ~1e-4 relative,
 * is the rasterised edge: coverage by sub-samples and the tilt of the cosine across edge pixels);
 * SH9 prints its error, bounded by (3/32) L x disc solid angle. */
static void sun_disc(void **state)
{
    lx_ctx *ctx = *state;
    const int W = 4096, H = 2048;
    const double d = 0.2666 * M_PI / 180, L = 1.0e6, ts = 30 * M_PI / 180, ps = 60 * M_PI / 180;
    const double s[3] = {sin(ts) * cos(ps), sin(ts) * sin(ps), cos(ts)};
    lx_envmap *m = make_map(ctx, W, H, 1);
    int j0 = (int)((ts - 3 * d) / M_PI * H), j1 = (int)((ts + 3 * d) / M_PI * H) + 1;
    int i0 = (int)((ps - 4 * d) / (2 * M_PI) * W), i1 = (int)((ps + 4 * d) / (2 * M_PI) * W) + 1;
    const int S = 32;
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            double in = 0, all = 0;
            for (int a = 0; a < S; a++)
                for (int b = 0; b < S; b++) {
                    double t = (j + (a + 0.5) / S) * M_PI / H, p = (i + (b + 0.5) / S) * 2 * M_PI / W;
                    double w = sin(t), c = s[0] * sin(t) * cos(p) + s[1] * sin(t) * sin(p) + s[2] * cos(t);
                    all += w;
                    if (c > cos(d)) in += w;
                }
            m->data[(size_t)j * W + i] = (float)(L * in / all);
        }
    double n[4][3] = {{0, 0, 1}, {s[0], s[1], s[2]}, {1, 0, 0}, {0.3, 0.8, 0.52}};
    double E[3][4];
    for (int k = 0; k < 4; k++) {
        double l = sqrt(n[k][0] * n[k][0] + n[k][1] * n[k][1] + n[k][2] * n[k][2]);
        for (int c = 0; c < 3; c++) n[k][c] /= l;
    }
    for (int q = 0; q < 3; q++) {
        lx_irr_opts o = {.method = methods[q], .backend = LX_BACKEND_CPU};
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 4, &n[0][0], &o, E[q]));
    }
    double scale = L * M_PI * sin(d) * sin(d), cap_sr = 2 * M_PI * (1 - cos(d));
    for (int k = 0; k < 4; k++) {
        double ref = scale * (n[k][0] * s[0] + n[k][1] * s[1] + n[k][2] * s[2]);
        print_message("sun n=(%.3f,%.3f,%.3f): exact %.9g brute %+.3e fast %+.3e SH9 %+.3e (relative to L pi sin^2 d)\n",
                      n[k][0], n[k][1], n[k][2], ref, (E[1][k] - ref) / scale, (E[2][k] - ref) / scale,
                      (E[0][k] - ref) / scale);
        /* the criterion: projected solid angle E / L within 1e-6 sr of the analytic one */
        lx_assert_near(E[1][k] / L, ref / L, 1e-6, 0);
        lx_assert_near(E[2][k] / L, ref / L, 1e-6, 0);
        /* tighter: the rasterised disc (32 x 32 coverage sub-samples) is within 2e-4 relative */
        lx_assert_near(E[1][k], ref, 2e-4 * scale, 0);
        assert_true(fabs(E[0][k] - ref) <= 3.0 / 32.0 * L * cap_sr * 1.001);
    }
    lx_envmap_free(m);
}

/* Direction convention (CLI.md): +z up, theta from +z, phi from +x towards +y, row 0 at theta = 0. */
static void convention(void **state)
{
    lx_ctx *ctx = *state;
    double d[3];
    lx_envmap_direction(360, 180, 0.0, 0.0, d); /* row 0 edge: the zenith */
    lx_assert_near(d[2], 1.0, 1e-15, 0);
    lx_envmap_direction(360, 180, 90.0, 90.0, d); /* theta 90, phi 90 deg: +y */
    lx_assert_near(d[1], 1.0, 1e-15, 0);
    lx_assert_near(d[0], 0.0, 1e-15, 0);
    /* a map bright only around +x (theta 90 deg, phi 0): E(+x) largest, E(-x) zero, E(+y) = E(-y) */
    lx_envmap *m = make_map(ctx, 64, 32, 3);
    for (int j = 15; j <= 16; j++)
        for (int i = 0; i < 64; i++)
            if (i == 0 || i == 63)
                for (int c = 0; c < 3; c++) m->data[((size_t)j * 64 + i) * 3 + c] = 10.0f;
    double n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, E[18];
    for (int q = 0; q < 3; q++) {
        lx_irr_opts o = {.method = methods[q], .backend = LX_BACKEND_CPU};
        lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, 6, &n[0][0], &o, E));
        for (int k = 1; k < 6; k++) assert_true(E[0] > E[3 * k]);
        if (q) lx_assert_near(E[3], 0.0, 1e-12, 0);
        lx_assert_near(E[6], E[9], 1e-9 * E[0], 0);
        lx_assert_near(E[12], E[15], 1e-9 * E[0], 0);
    }
    lx_envmap_free(m);
}

/* The fast path computes the same sum as brute force (different order): 1e-12 relative on a
 * random map with three channels, at arbitrary normals and on a lat-long output grid. */
static void fast_equals_brute(void **state)
{
    lx_ctx *ctx = *state;
    lx_envmap *m = make_map(ctx, 200, 100, 3);
    unsigned r = 12345;
    for (size_t k = 0; k < 200u * 100u * 3u; k++) {
        r = r * 1103515245u + 12345u;
        m->data[k] = (float)((r >> 8) % 1000) / 100.0f;
    }
    m->data[(37 * 200 + 11) * 3] = 5e5f; /* a sun */
    enum { N = 300 };
    double n[N][3], Eb[3 * N], Ef[3 * N];
    for (int k = 0; k < N; k++) {
        double t = acos(1 - 2 * (k + 0.5) / N), p = k * 2.399963229728653; /* golden-angle spiral */
        n[k][0] = sin(t) * cos(p), n[k][1] = sin(t) * sin(p), n[k][2] = cos(t);
    }
    lx_irr_opts ob = {.method = LX_IRR_BRUTE, .backend = LX_BACKEND_CPU}, of = {.method = LX_IRR_FAST};
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, N, &n[0][0], &ob, Eb));
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, N, &n[0][0], &of, Ef));
    for (int k = 0; k < 3 * N; k++) lx_assert_near(Ef[k], Eb[k], 1e-12 * Eb[k] + 1e-12, 1e-12);
    lx_envmap *a = NULL, *b = NULL;
    lx_assert_ok(ctx, lx_irradiance_map(ctx, m, 32, 16, &ob, &a));
    lx_assert_ok(ctx, lx_irradiance_map(ctx, m, 32, 16, &of, &b));
    for (int k = 0; k < 32 * 16 * 3; k++) lx_assert_near(b->data[k], a->data[k], 0, 1e-6);
    lx_envmap_free(a);
    lx_envmap_free(b);
    lx_envmap_free(m);
}

/* SH9 map reconstruction (per-row Fourier form) equals lx_sh9_irradiance at the pixel centres. */
static void sh9_map_matches_eval(void **state)
{
    lx_ctx *ctx = *state;
    lx_envmap *m = make_map(ctx, 64, 32, 3), *e = NULL;
    for (size_t k = 0; k < 64u * 32u * 3u; k++) m->data[k] = (float)(1 + sin(0.37 * k) * 0.5);
    lx_sh9 sh;
    lx_assert_ok(ctx, lx_sh9_project(ctx, m, &sh));
    lx_irr_opts o = {.method = LX_IRR_SH9, .window = LX_SH9_WINDOW_NONNEG};
    lx_assert_ok(ctx, lx_irradiance_map(ctx, m, 24, 12, &o, &e));
    for (int j = 0; j < 12; j++)
        for (int i = 0; i < 24; i++) {
            double d[3], E[3];
            lx_envmap_direction(24, 12, j + 0.5, i + 0.5, d);
            lx_assert_ok(ctx, lx_sh9_irradiance(ctx, &sh, LX_SH9_WINDOW_NONNEG, d, E));
            for (int c = 0; c < 3; c++) lx_assert_near(e->data[(j * 24 + i) * 3 + c], E[c], 0, 1e-6);
        }
    lx_envmap_free(e);
    lx_envmap_free(m);
}

/* The AVX2 twins of the SH9 projection (row sums) and of the map reconstruction (rows) against
 * the plain loops (LX_SIMD=scalar; SKIPPED where this machine cannot run AVX2, tests/lx_test.h):
 * the same sums in another order with FMA, so the coefficients agree to 1e-12 relative and the
 * float maps to 1e-6 relative. A width that is not a multiple of 4 exercises the tails. */
static void sh9_twin_avx2(void **state)
{
    lx_ctx *ctx = *state;
    lx_test_simd_begin(LX_SIMD_AVX2);
    lx_test_simd_end();
    lx_envmap *m = make_map(ctx, 70, 35, 3), *e[2] = {NULL, NULL};
    for (size_t k = 0; k < 70u * 35u * 3u; k++) m->data[k] = (float)(1 + sin(0.37 * k) * 0.5 + (k % 11 == 0 ? 20 : 0));
    lx_sh9 sh[2];
    lx_irr_opts o = {.method = LX_IRR_SH9, .window = LX_SH9_WINDOW_NONNEG};
    for (int path = 0; path < 2; path++) {
        lx_test_simd_begin(path ? LX_SIMD_AVX2 : LX_SIMD_SCALAR);
        lx_assert_ok(ctx, lx_sh9_project(ctx, m, &sh[path]));
        lx_assert_ok(ctx, lx_irradiance_map(ctx, m, 37, 18, &o, &e[path]));
        lx_test_simd_end();
    }
    for (int k = 0; k < 9; k++)
        for (int c = 0; c < 3; c++) lx_assert_near(sh[1].c[k][c], sh[0].c[k][c], 1e-12 * fabs(sh[0].c[0][c]), 1e-12);
    for (size_t k = 0; k < 37u * 18u * 3u; k++) lx_assert_near(e[1]->data[k], e[0]->data[k], 0, 1e-6);
    lx_envmap_free(e[0]);
    lx_envmap_free(e[1]);
    lx_envmap_free(m);
}

/* Downsampling keeps the radiant power sum(L d omega) of the map (to float rounding). */
static void downsample_keeps_power(void **state)
{
    lx_ctx *ctx = *state;
    lx_envmap *m = make_map(ctx, 128, 64, 1), *d = NULL;
    for (size_t k = 0; k < 128u * 64u; k++) m->data[k] = (float)((k * 7919) % 101);
    lx_assert_ok(ctx, lx_envmap_downsample(ctx, m, 32, 16, &d));
    double p0 = 0, p1 = 0;
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 128; i++) p0 += m->data[j * 128 + i] * lx_envmap_pixel_sr(128, 64, j);
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 32; i++) p1 += d->data[j * 32 + i] * lx_envmap_pixel_sr(32, 16, j);
    lx_assert_near(p1, p0, 0, 1e-6);
    lx_envmap *bad = NULL; /* a failed call sets its output to NULL: d is freed below */
    assert_int_equal(lx_envmap_downsample(ctx, m, 30, 16, &bad), LX_EINVAL);
    assert_null(bad);
    lx_envmap_free(d);
    lx_envmap_free(m);
}

/* OpenCL brute force against its CPU twin: 1e-9 relative with fp64, 2e-5 with float. */
static void opencl_parity(void **state)
{
    lx_ctx *ctx = *state;
    lx_cl_device_info info;
    if (lx_cl_info(ctx, &info) != LX_OK) {
        print_message("no OpenCL device: %s\n", lx_ctx_errmsg(ctx));
        skip();
    }
    lx_envmap *m = make_map(ctx, 256, 128, 3);
    for (size_t k = 0; k < 256u * 128u * 3u; k++) m->data[k] = (float)(2 + sin(0.011 * k));
    m->data[(20 * 256 + 40) * 3 + 1] = 1e4f;
    enum { N = 257 };
    double n[N][3], Ec[3 * N], Eg[3 * N];
    for (int k = 0; k < N; k++) {
        double t = acos(1 - 2 * (k + 0.5) / N), p = k * 2.399963229728653;
        n[k][0] = sin(t) * cos(p), n[k][1] = sin(t) * sin(p), n[k][2] = cos(t);
    }
    lx_irr_opts oc = {.method = LX_IRR_BRUTE, .backend = LX_BACKEND_CPU}, og = {.method = LX_IRR_BRUTE, .backend = LX_BACKEND_OPENCL};
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, N, &n[0][0], &oc, Ec));
    assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_CPU);
    lx_assert_ok(ctx, lx_irradiance_dirs(ctx, m, N, &n[0][0], &og, Eg));
    assert_int_equal(lx_ctx_backend_used(ctx), LX_BACKEND_OPENCL);
    double tol = info.fp64 ? 1e-9 : 2e-5;
    for (int k = 0; k < 3 * N; k++) lx_assert_near(Eg[k], Ec[k], 1e-9, tol);
    lx_envmap_free(m);
}

static void bad_args(void **state)
{
    lx_ctx *ctx = *state;
    lx_envmap *m = make_map(ctx, 8, 4, 1);
    double n[3] = {0, 0, 0}, E[1];
    assert_int_equal(lx_irradiance_dirs(ctx, m, 1, n, NULL, E), LX_EINVAL);
    lx_envmap *bad = NULL;
    assert_int_equal(lx_envmap_create(ctx, 8, 4, 2, &bad), LX_EINVAL);
    assert_null(bad);
    lx_envmap_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(furnace, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(furnace_random, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(crossed_pixels, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(half_lit, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(single_pixel, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(sun_disc, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(convention, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(fast_equals_brute, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(sh9_map_matches_eval, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(sh9_twin_avx2, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(downsample_keeps_power, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(opencl_parity, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(bad_args, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
