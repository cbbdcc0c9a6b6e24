/* bench_metrics.c - `luxcalc bench metrics`: colour rendering (CIE 13.3 CRI, CIE 224 / TM-30) and
 * alpha-opic throughput over 1e5 spectra on every core, beside colour-science and luxpy if installed. */
#include "cli/cli.h"
#include "bench_common.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

int cli_bench_metrics(FILE *out);

#define NLAM 81 /* 380-780 nm at 5 nm */

typedef struct job {
    const double *v;
    size_t i0, i1;
    int what; /* 0 CRI, 1 TM-30, 2 alpha-opic one by one */
    size_t refused;
    double checksum;
} job;


static void *worker(void *arg)
{
    job *j = arg;
    lx_ctx *ctx = NULL;
    if (lx_ctx_create(&ctx) != LX_OK) return NULL;
    double wl[NLAM];
    for (int k = 0; k < NLAM; k++) wl[k] = 380.0 + 5.0 * k;
    for (size_t i = j->i0; i < j->i1; i++) {
        lx_spd s = {NULL, NLAM, wl, j->v + i * NLAM};
        if (j->what == 0) {
            lx_cri c;
            if (lx_cri_compute(ctx, &s, &c) == LX_OK) j->checksum += c.ra;
            else j->refused++;
        } else if (j->what == 1) {
            lx_tm30 t;
            if (lx_tm30_compute(ctx, &s, &t) == LX_OK) j->checksum += t.rf;
            else j->refused++;
        } else {
            lx_alphaopic a;
            if (lx_alphaopic_compute(ctx, &s, LX_METHOD_CIE15, &a) == LX_OK) j->checksum += a.der[LX_AO_MEL];
            else j->refused++;
        }
    }
    lx_ctx_destroy(ctx);
    return NULL;
}

/* Runs `what` over n spectra on nt threads; returns the wall time, *refused the refusals. */
static double run_threads(const double *v, size_t n, int what, int nt, size_t *refused)
{
    job jobs[64];
    pthread_t th[64];
    double t0 = cli_bench_now_s();
    for (int k = 0; k < nt; k++) {
        jobs[k] = (job){v, n * (size_t)k / (size_t)nt, n * (size_t)(k + 1) / (size_t)nt, what, 0, 0};
        if (pthread_create(&th[k], NULL, worker, &jobs[k]) != 0) worker(&jobs[k]), th[k] = 0;
    }
    *refused = 0;
    for (int k = 0; k < nt; k++) {
        if (th[k]) pthread_join(th[k], NULL);
        *refused += jobs[k].refused;
    }
    return cli_bench_now_s() - t0;
}

/* ms per spectrum of a peer (python snippet printing one number), or NaN when it fails. */
static double peer_ms(const char *py, const char *code)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "%s -c '%s' 2>/dev/null", py, code);
    FILE *p = popen(cmd, "r");
    if (!p) return NAN;
    double v = NAN;
    if (fscanf(p, "%lf", &v) != 1) v = NAN;
    pclose(p);
    return v;
}

int cli_bench_metrics(FILE *o)
{
    const char *env = getenv("LX_BENCH_METRICS_N");
    size_t n = env && atol(env) > 0 ? (size_t)atol(env) : 100000;
    long nc = sysconf(_SC_NPROCESSORS_ONLN);
    int nt = nc < 1 ? 1 : nc > 64 ? 64 : (int)nc;
    lx_ctx *ctx = NULL;
    if (lx_ctx_create(&ctx) != LX_OK) return CLI_RUNTIME;
    /* the input: every embedded CIE illuminant resampled to 380-780 nm at 5 nm, cycled and scaled */
    const char *const *names = lx_illuminant_names();
    int nn = 0;
    while (names[nn]) nn++;
    double *v = malloc(sizeof(double) * NLAM * n);
    if (!v || !nn) {
        free(v);
        lx_ctx_destroy(ctx);
        return CLI_RUNTIME;
    }
    for (size_t i = 0; i < n; i++) {
        lx_spd s;
        lx_illuminant_get(ctx, names[i % (size_t)nn], &s);
        double scale = 1.0 + 1e-3 * (double)(i % 997);
        size_t j = 0;
        for (int k = 0; k < NLAM; k++) {
            double l = 380.0 + 5.0 * k, y = 0;
            while (j + 1 < s.n && s.lambda_nm[j + 1] <= l) j++;
            if (l >= s.lambda_nm[0] && l <= s.lambda_nm[s.n - 1])
                y = j + 1 < s.n ? s.value[j] + (l - s.lambda_nm[j]) / (s.lambda_nm[j + 1] - s.lambda_nm[j]) *
                                                  (s.value[j + 1] - s.value[j])
                                : s.value[j];
            v[i * NLAM + k] = scale * y;
        }
    }
    fprintf(o, "## metrics: colour rendering and photobiology per spectrum\n\n");
    fprintf(o, "%zu spectra (the %d embedded CIE illuminants cycled, 380-780 nm at 5 nm), %d threads, one "
               "context per thread; wall time of the whole batch.\n\n", n, nn, nt);
    fprintf(o, "| metric | spectra | wall s | spectra/s | us per spectrum per thread | refused |\n|---|---|---|---|---|---|\n");
    static const char *const what[3] = {"CRI (CIE 13.3: Ra, R1-R14)", "TM-30 / CIE 224 (Rf, Rg, 16 bins)",
                                        "alpha-opic (5 irradiances, EDI, DER)"};
    for (int w = 0; w < 3; w++) {
        size_t refused;
        double t = run_threads(v, n, w, nt, &refused);
        fprintf(o, "| %s | %zu | %.2f | %.0f | %.1f | %zu |\n", what[w], n, t, (double)n / t, t * nt / (double)n * 1e6,
                refused);
    }
    /* alpha-opic through the batch integrator (cie15 sums, CPU threads and OpenCL) */
    double *res = malloc(sizeof(double) * 6 * n);
    lx_batch b = {n, NLAM, 0, 380.0, 5.0, LX_F64, v};
    static const char *const bname[3] = {"CPU", "OpenCL, first call: start-up and kernel build", "OpenCL, warm"};
    for (int be = 0; res && be < 3; be++) {
        lx_batch_opts opt = {.backend = be ? LX_BACKEND_OPENCL : LX_BACKEND_CPU};
        double t0 = cli_bench_now_s();
        lx_status st = lx_alphaopic_batch(ctx, &b, &opt, res);
        double t = cli_bench_now_s() - t0;
        if (st == LX_OK)
            fprintf(o, "| alpha-opic batch (lx_alphaopic_batch, %s) | %zu | %.3f | %.0f | - | 0 |\n", bname[be], n,
                    t, (double)n / t);
        else
            fprintf(o, "| alpha-opic batch (%s) | - | - | - | - | unavailable: %s |\n", bname[be], lx_ctx_errmsg(ctx));
    }
    free(res);
    const char *py = getenv("LX_PEERS_PYTHON");
    if (!py || !*py) py = "python3";
    double cs = peer_ms(py, "import warnings,time;warnings.filterwarnings(\"ignore\");import colour;"
                            "sd=colour.SDS_ILLUMINANTS[\"FL2\"];colour.colour_rendering_index(sd);t=time.perf_counter();"
                            "[colour.colour_rendering_index(sd) for i in range(20)];print((time.perf_counter()-t)/20*1e3)");
    double cst = peer_ms(py, "import warnings,time;warnings.filterwarnings(\"ignore\");import colour;"
                             "from colour.quality import colour_fidelity_index_ANSIIESTM3018 as f;"
                             "sd=colour.SDS_ILLUMINANTS[\"FL2\"];f(sd,True);"
                             "t=time.perf_counter();[f(sd,True) for i in range(10)];"
                             "print((time.perf_counter()-t)/10*1e3)");
    double lp = peer_ms(py, "import warnings,time;warnings.filterwarnings(\"ignore\");import luxpy as lx;"
                            "s=lx._CIE_ILLUMINANTS[\"F4\"];lx.cri.spd_to_cri(s);t=time.perf_counter();"
                            "[lx.cri.spd_to_cri(s) for i in range(20)];print((time.perf_counter()-t)/20*1e3)");
    fprintf(o, "\nPeers, one spectrum (FL2) at a time, one thread (%s):\n\n", py);
    fprintf(o, "| peer | metric | ms per spectrum |\n|---|---|---|\n");
    if (isnan(cs)) fprintf(o, "| colour-science | CRI | not installed |\n");
    else fprintf(o, "| colour-science | CRI (colour_rendering_index) | %.2f |\n", cs);
    if (!isnan(cs)) fprintf(o, "| colour-science | TM-30 (colour_fidelity_index_ANSIIESTM3018) | %s%.2f |\n",
                            isnan(cst) ? "failed " : "", cst);
    if (isnan(lp)) fprintf(o, "| luxpy | CRI | not installed |\n");
    else fprintf(o, "| luxpy | CRI (cri.spd_to_cri) | %.2f |\n", lp);
    fprintf(o, "\n");
    free(v);
    lx_ctx_destroy(ctx);
    return CLI_OK;
}
