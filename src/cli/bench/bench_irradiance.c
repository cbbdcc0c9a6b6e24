/* bench_irradiance.c - `luxcalc bench irradiance`: time and error of each irradiance method on the
 * sky-with-sun map of ../shared/peers/envmap_numpy.py at 512x256, 2048x1024 and 4096x2048, beside
 * the numpy peer (run in the same session when /tmp/peers/bin/python and the script are found). */
#include "cli/cli.h"
#include "bench_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define PI CLI_PI


static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* envmap_numpy.py make_sky(W, sun=True): gradient sky, grey ground, a 0.27 deg sun whose normal
 * irradiance is 5x the sky's horizontal irradiance, put into the pixels whose centres it covers. */
static lx_envmap *make_sky(lx_ctx *ctx, int W)
{
    int H = W / 2;
    lx_envmap *m = NULL;
    if (lx_envmap_create(ctx, W, H, 3, &m)) return NULL;
    const double tint[3] = {0.7, 0.85, 1.2}, ground[3] = {0.25, 0.2, 0.15}, st[3] = {1.0, 0.95, 0.9};
    const double s[3] = {cos(35 * PI / 180) * cos(60 * PI / 180), cos(35 * PI / 180) * sin(60 * PI / 180), sin(35 * PI / 180)};
    double eh = 0, sun_sr = 0, best = -2;
    long bestk = 0;
    char *in = calloc((size_t)W * H, 1);
    if (!in) return lx_envmap_free(m), NULL;
    for (int j = 0; j < H; j++) {
        double th = (j + 0.5) * PI / H, dw = sin(th) * (PI / H) * (2 * PI / W); /* the peer's d omega */
        for (int i = 0; i < W; i++) {
            double ph = (i + 0.5) * 2 * PI / W, d[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
            float *p = m->data + ((size_t)j * W + i) * 3;
            double sky = (0.6 + 1.4 * d[2]) * (1 + 0.3 * d[0]);
            for (int c = 0; c < 3; c++) p[c] = (float)(d[2] > 0 ? sky * tint[c] : ground[c]);
            if (d[2] > 0) eh += sky * tint[1] * d[2] * dw;
            double cs = d[0] * s[0] + d[1] * s[1] + d[2] * s[2];
            if (cs > best) best = cs, bestk = (long)j * W + i;
            if (acos(fmin(1, fmax(-1, cs))) < 0.27 * PI / 180) in[(size_t)j * W + i] = 1, sun_sr += dw;
        }
    }
    if (sun_sr == 0) in[bestk] = 1, sun_sr = sin((bestk / W + 0.5) * PI / H) * (PI / H) * (2 * PI / W);
    double Ls = 5 * eh / sun_sr;
    for (size_t k = 0; k < (size_t)W * H; k++)
        if (in[k])
            for (int c = 0; c < 3; c++) m->data[3 * k + c] += (float)(Ls * st[c]);
    free(in);
    return m;
}

/* luminance of each output direction */
static void lum(const lx_envmap *m, const double *E, size_t n, double *Y)
{
    for (size_t k = 0; k < n; k++) Y[k] = m->y_weights[0] * E[3 * k] + m->y_weights[1] * E[3 * k + 1] + m->y_weights[2] * E[3 * k + 2];
}

static void errors(const double *Y, const double *ref, size_t n, double *maxrel, double *meanrel)
{
    *maxrel = 0, *meanrel = 0;
    for (size_t k = 0; k < n; k++) {
        double r = fabs(Y[k] - ref[k]) / ref[k];
        *maxrel = fmax(*maxrel, r);
        *meanrel += r / n;
    }
}

/* runs the numpy peer "time W reps" and returns sh9_total_s (NAN when unavailable) */
static double peer_sh9(int W, double *bf64)
{
    *bf64 = NAN;
    const char *py = getenv("LX_PEERS_PYTHON");
    if (!py) py = "/tmp/peers/bin/python";
    const char *sh = getenv("LX_SHARED_DIR");
    char script[1024];
    snprintf(script, sizeof script, "%s/peers/envmap_numpy.py", sh && *sh ? sh : "../shared");
    if (access(py, X_OK) || access(script, R_OK)) return NAN;
    char cmd[2300];
    snprintf(cmd, sizeof cmd, "'%s' '%s' time %d 3 2>/dev/null", py, script, W);
    FILE *p = popen(cmd, "r");
    if (!p) return NAN;
    char buf[4096] = {0};
    size_t n = fread(buf, 1, sizeof buf - 1, p);
    buf[n] = 0;
    pclose(p);
    char *q = strstr(buf, "\"sh9_total_s\": ");
    char *r = strstr(buf, "\"bf64_total_s\": ");
    if (r) *bf64 = strtod(r + 16, NULL);
    return q ? strtod(q + 15, NULL) : NAN;
}

int cli_bench_irradiance(FILE *out)
{
    lx_ctx *ctx = cli_ctx("bench");
    if (!ctx) return CLI_RUNTIME;
    char tmp[] = "/tmp/lxbenchirrXXXXXX";
    if (!mkdtemp(tmp)) return cli_error("bench", "cannot create a scratch directory"), CLI_RUNTIME;
    fprintf(out, "\n## irradiance: lat-long sky with a 0.27 deg sun (envmap_numpy.py make_sky), RGB float\n\n"
                 "Errors: luminance of E at the 64x32 output pixel centres against the exact sum (the `fast`\n"
                 "path, equal to `brute` to 1e-12); medians of 5 runs (1 for brute), 2 threads.\n\n"
                 "| map | EXR read s | SH9 project+map s | numpy SH9 s | SH9 max/mean err | SH9 nonneg max/mean err |"
                 " exact (fast) 64x32 s | brute CPU 64x32 s | brute on 64x32 downsample max err | numpy bf64 s |\n"
                 "|---|---|---|---|---|---|---|---|---|---|\n");
    int sizes[3] = {512, 2048, 4096};
    for (int z = 0; z < 3; z++) {
        int W = sizes[z], H = W / 2;
        lx_envmap *m = make_sky(ctx, W), *r = NULL, *e = NULL, *ds = NULL;
        if (!m) break;
        char path[256];
        snprintf(path, sizeof path, "%s/sky.exr", tmp);
        lx_envmap_write_exr(ctx, path, m, NULL);
        double t[5], tread, tsh9, tfast, tbrute = NAN;
        for (int k = 0; k < 5; k++) {
            double t0 = cli_bench_now_s();
            lx_exr_read(ctx, path, &r);
            t[k] = cli_bench_now_s() - t0;
            if (k < 4) lx_envmap_free(r), r = NULL;
        }
        qsort(t, 5, sizeof *t, cmp_d);
        tread = t[2];
        lx_irr_opts o = {.method = LX_IRR_SH9};
        for (int k = 0; k < 5; k++) {
            double t0 = cli_bench_now_s();
            lx_irradiance_map(ctx, r, 0, 0, &o, &e);
            t[k] = cli_bench_now_s() - t0;
            lx_envmap_free(e), e = NULL;
        }
        qsort(t, 5, sizeof *t, cmp_d);
        tsh9 = t[2];
        enum { NO = 64 * 32 };
        double *dirs = malloc(NO * 3 * sizeof *dirs), *E = malloc(NO * 3 * sizeof *E), *ref = malloc(NO * sizeof *ref),
               *Y = malloc(NO * sizeof *Y);
        for (int k = 0; k < NO; k++) lx_envmap_direction(64, 32, k / 64 + 0.5, k % 64 + 0.5, dirs + 3 * k);
        o.method = LX_IRR_FAST;
        for (int k = 0; k < 5; k++) {
            double t0 = cli_bench_now_s();
            lx_irradiance_dirs(ctx, r, NO, dirs, &o, E);
            t[k] = cli_bench_now_s() - t0;
        }
        qsort(t, 5, sizeof *t, cmp_d);
        tfast = t[2];
        lum(r, E, NO, ref);
        if (W <= 2048) {
            o.method = LX_IRR_BRUTE, o.backend = LX_BACKEND_CPU;
            double t0 = cli_bench_now_s();
            lx_irradiance_dirs(ctx, r, NO, dirs, &o, E);
            tbrute = cli_bench_now_s() - t0;
        }
        double sh_max, sh_mean, nn_max, nn_mean, bf_max, bf_mean;
        o.method = LX_IRR_SH9;
        lx_irradiance_dirs(ctx, r, NO, dirs, &o, E);
        lum(r, E, NO, Y);
        errors(Y, ref, NO, &sh_max, &sh_mean);
        o.window = LX_SH9_WINDOW_NONNEG;
        lx_irradiance_dirs(ctx, r, NO, dirs, &o, E);
        lum(r, E, NO, Y);
        errors(Y, ref, NO, &nn_max, &nn_mean);
        lx_envmap_downsample(ctx, r, 64, 32, &ds);
        o.method = LX_IRR_BRUTE, o.backend = LX_BACKEND_CPU;
        lx_irradiance_dirs(ctx, ds, NO, dirs, &o, E);
        lum(r, E, NO, Y);
        errors(Y, ref, NO, &bf_max, &bf_mean);
        double bf64, np = peer_sh9(W, &bf64);
        char brute[64]; /* brute force is O(pixels x outputs): not run above 2048 wide (4 x the row above) */
        if (isnan(tbrute)) snprintf(brute, sizeof brute, "not run (about 4 x the row above)");
        else snprintf(brute, sizeof brute, "%.3f", tbrute);
        fprintf(out, "| %dx%d | %.4f | %.4f | %.3f | %.3g / %.3g | %.3g / %.3g | %.4f | %s | %.3g | %.3f |\n", W, H,
                tread, tsh9, np, sh_max, sh_mean, nn_max, nn_mean, tfast, brute, bf_max, bf64);
        fflush(out);
        free(dirs), free(E), free(ref), free(Y);
        lx_envmap_free(ds);
        lx_envmap_free(r);
        lx_envmap_free(m);
        unlink(path);
    }
    rmdir(tmp);
    fprintf(out, "\nnumpy exact brute force (envmap_numpy.py accuracy, 64x32 output) takes 12-15 s at 2048x1024\n"
                 "on this machine kind (../shared/peers/README.md); `fast` computes the same sum.\n");
    lx_ctx_destroy(ctx);
    return 0;
}
