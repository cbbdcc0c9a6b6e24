/* bench_lab.c - `luxcalc bench lab`: the lab quantities on the batch path, in memory: PAR
 * (lx_par_batch), IEC 62471 hazards (lx_hazard_batch) and LED binning (lx_binning_batch) of N
 * spectra (380-780 nm at 1 nm, float32; LX_BENCH_LAB_N, default 250000) on every core, each and all
 * three in one pass (lx_lab_batch), against the goal of 1e6 spectra/s; the per-spectrum calls beside
 * them for scale. */
#include "cli/cli.h"
#include "bench_common.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int cli_bench_lab(FILE *out);

#define NLAM 401 /* 380-780 nm at 1 nm */
#define RUNS 5


/* CPU time of the whole process (every thread): what the work costs, whatever else the machine runs */
static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* what: 0 PAR, 1 hazard, 2 binning, 3 all three. Returns the median wall time of RUNS, *cpu the
 * median CPU time. */
static double timed(lx_ctx *ctx, const lx_batch *b, int what, lx_par *par, lx_hazard *hz, lx_binning *bin, int *fail,
                    double *cpu)
{
    double t[RUNS], c[RUNS];
    for (int r = 0; r < RUNS; r++) {
        double t0 = cli_bench_now_s(), c0 = cpu_s();
        lx_status st = LX_OK;
        if (what == 0) st = lx_par_batch(ctx, b, NULL, par);
        if (what == 1) st = lx_hazard_batch(ctx, b, NULL, hz);
        if (what == 2) st = lx_binning_batch(ctx, b, NULL, bin);
        if (what == 3) st = lx_lab_batch(ctx, b, NULL, par, hz, bin); /* one pass over the values */
        t[r] = cli_bench_now_s() - t0;
        c[r] = cpu_s() - c0;
        if (st != LX_OK) *fail = 1;
    }
    qsort(t, RUNS, sizeof *t, cmp_d);
    qsort(c, RUNS, sizeof *c, cmp_d);
    *cpu = c[RUNS / 2];
    return t[RUNS / 2];
}

/* The same quantities one spectrum at a time (lx_par_compute, lx_hazard_compute, colorimetry and
 * lx_binning_compute) over n spectra on this thread: seconds per spectrum. */
static double one_by_one(lx_ctx *ctx, const float *v, size_t n)
{
    double wl[NLAM], val[NLAM];
    for (int j = 0; j < NLAM; j++) wl[j] = 380 + j;
    double t0 = cli_bench_now_s();
    for (size_t i = 0; i < n; i++) {
        for (int j = 0; j < NLAM; j++) val[j] = v[i * NLAM + j];
        lx_spd s = {NULL, NLAM, wl, val};
        lx_par p;
        lx_hazard h;
        lx_colorimetry c;
        lx_binning b;
        lx_par_compute(ctx, &s, LX_METHOD_CIE15, &p);
        lx_hazard_compute(ctx, &s, LX_METHOD_CIE15, &h);
        if (lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, LX_METHOD_CIE15, &c) == LX_OK)
            lx_binning_compute(ctx, c.x, c.y, c.cct_K, c.duv, &b);
    }
    return (cli_bench_now_s() - t0) / (double)n;
}

int cli_bench_lab(FILE *out)
{
    const char *e = getenv("LX_BENCH_LAB_N");
    size_t n = e && atol(e) > 0 ? (size_t)atol(e) : 250000;
    float *v = malloc(sizeof(float) * NLAM * n);
    lx_par *par = malloc(sizeof *par * n);
    lx_hazard *hz = malloc(sizeof *hz * n);
    lx_binning *bin = malloc(sizeof *bin * n);
    lx_ctx *ctx = NULL;
    if (!v || !par || !hz || !bin || lx_ctx_create(&ctx) != LX_OK) {
        free(v), free(par), free(hz), free(bin);
        fprintf(stderr, "luxcalc: bench: lab: out of memory for %zu spectra\n", n);
        return CLI_RUNTIME;
    }
    /* white LEDs of 2000-8000 K: a blue peak and a phosphor hump, each spectrum different */
    for (size_t i = 0; i < n; i++) {
        double T = 2000 + 6000.0 * (double)(i % 997) / 996.0, blue = 0.2 + 0.8 * (T - 2000) / 6000;
        for (int j = 0; j < NLAM; j++) {
            double l = 380 + j, a = (l - 452) / 10, p = (l - 600 + 0.01 * (T - 4000)) / 60;
            v[i * NLAM + j] = (float)(blue * exp(-0.5 * a * a) + exp(-0.5 * p * p));
        }
    }
    lx_batch b = {n, NLAM, 0, 380, 1, LX_F32, v};
    int fail = 0;
    static const char *const what[4] = {"PAR (ppfd, epar, ypf, efficacy)", "IEC 62471 (B, R, S_UV, UV-A)",
                                        "binning (ANSI C78.377, flexible CCT, SDCM)", "all three in one pass (lx_lab_batch)"};
    double ts[4], cs[4];
    for (int w = 0; w < 4; w++) ts[w] = timed(ctx, &b, w, par, hz, bin, &fail, &cs[w]);
    size_t one_n = n < 2000 ? n : 2000;
    double per = one_by_one(ctx, v, one_n);
    int binned = 0;
    for (size_t i = 0; i < n; i++) binned += bin[i].ansi_K != 0;
    fprintf(out, "## Lab quantities on the batch path (in memory)\n\n");
    fprintf(out, "%zu spectra of %d float32 samples (380-780 nm, 1 nm), every core (lx_batch_opts threads 0), "
                 "median of %d runs; goal: >= 1e6 spectra/s. %d of them fall in an ANSI category.\n\n",
            n, NLAM, RUNS, binned);
    fprintf(out, "CPU s is the process's CPU time over every thread: n / (CPU s / 2) is what 2 cores of their "
                 "own would reach, whatever else the machine runs (wall time depends on that).\n\n");
    fprintf(out, "| quantities | wall s | spectra/s | CPU s | spectra/s on 2 free cores (n / (CPU s / 2)) | goal met |\n"
                 "|---|---|---|---|---|---|\n");
    for (int w = 0; w < 4; w++) {
        double r2 = (double)n / (cs[w] / 2);
        fprintf(out, "| %s | %.4f | %.3g | %.4f | %.3g | %s |\n", what[w], ts[w], (double)n / ts[w], cs[w], r2,
                (double)n / ts[w] >= 1e6 ? "yes" : r2 >= 1e6 ? "on 2 free cores" : "no");
    }
    fprintf(out, "| one spectrum at a time (the four calls, one thread, %zu spectra) | %.3g per spectrum | %.3g | - | - | - |\n\n",
            one_n, per, 1.0 / per);
    free(v), free(par), free(hz), free(bin);
    lx_ctx_destroy(ctx);
    if (fail) fprintf(stderr, "luxcalc: bench: lab: a batch call failed\n");
    return fail ? CLI_RUNTIME : CLI_OK;
}
