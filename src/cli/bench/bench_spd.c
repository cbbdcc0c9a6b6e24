/* bench_spd.c - the `luxcalc bench spd` topic: batch integration in memory (CPU on each SIMD path,
 * and OpenCL) against this machine's read bandwidth, the CSV library path against C strtod and the
 * Python peers, the CLI end to end (bench_spd_cli.c), one-file start-up time. */
#include "cli/cli.h"
#include "bench_spd.h"

#include <math.h>
#include <pthread.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

double cli_bench_cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}


/* ---- read bandwidth: sum a buffer of floats with T threads ---- */
typedef struct rd_job {
    const float *p;
    size_t n;
    float sum;
} rd_job;

static void rd_scalar(rd_job *j)
{
    float s = 0;
    for (size_t i = 0; i < j->n; i++) s += j->p[i];
    j->sum = s;
}

#if defined(__GNUC__) && defined(__x86_64__)
typedef float v8f __attribute__((vector_size(32)));
__attribute__((target("avx2"))) static void rd_avx2(rd_job *j)
{
    v8f a = {0}, b = {0}, c = {0}, d = {0};
    size_t i = 0;
    for (; i + 32 <= j->n; i += 32) {
        v8f x, y, z, w;
        memcpy(&x, j->p + i, 32);
        memcpy(&y, j->p + i + 8, 32);
        memcpy(&z, j->p + i + 16, 32);
        memcpy(&w, j->p + i + 24, 32);
        a += x, b += y, c += z, d += w;
    }
    a += b + c + d;
    float s = 0;
    for (int l = 0; l < 8; l++) s += a[l];
    for (; i < j->n; i++) s += j->p[i];
    j->sum = s;
}
#endif

/* The reader: 4 x 8 floats a step where the CPU has AVX2 (asked of the library's dispatcher: the
 * bandwidth measured is the machine's, whatever LX_SIMD caps), else the plain loop. */
static void *rd_thread(void *arg)
{
#if defined(__GNUC__) && defined(__x86_64__)
    if (lx_simd_cpu() >= LX_SIMD_AVX2) {
        rd_avx2(arg);
        return NULL;
    }
#endif
    rd_scalar(arg);
    return NULL;
}

static double read_bandwidth(const float *p, size_t n, int T)
{
    double t[5];
    for (int r = 0; r < 6; r++) {
        rd_job jobs[16];
        pthread_t tid[16];
        double t0 = cli_bench_now_s();
        for (int i = 0; i < T; i++) {
            jobs[i].p = p + n * (size_t)i / (size_t)T;
            jobs[i].n = n * (size_t)(i + 1) / (size_t)T - n * (size_t)i / (size_t)T;
            if (i) pthread_create(&tid[i], NULL, rd_thread, &jobs[i]);
        }
        rd_thread(&jobs[0]);
        for (int i = 1; i < T; i++) pthread_join(tid[i], NULL);
        if (r) t[r - 1] = cli_bench_now_s() - t0; /* the first pass warms up */
        if (jobs[0].sum == -1.0f) fputc(' ', stderr); /* keep the sum alive */
    }
    return (double)n * sizeof(float) / cli_bench_median(t, 5);
}

/* One timed pass of the bandwidth reader over p[0, n) on T threads (threads created per pass, as
 * lx_batch_integrate creates its own): the same data, the same threads and the same front-to-back
 * split as the batch it is compared with. */
static double read_pass_s(const float *p, size_t n, int T)
{
    rd_job jobs[16];
    pthread_t tid[16];
    double t0 = cli_bench_now_s();
    for (int i = 0; i < T; i++) {
        jobs[i].p = p + n * (size_t)i / (size_t)T;
        jobs[i].n = n * (size_t)(i + 1) / (size_t)T - n * (size_t)i / (size_t)T;
        if (i) pthread_create(&tid[i], NULL, rd_thread, &jobs[i]);
    }
    rd_thread(&jobs[0]);
    for (int i = 1; i < T; i++) pthread_join(tid[i], NULL);
    double t = cli_bench_now_s() - t0;
    if (jobs[0].sum == -1.0f) fputc(' ', stderr); /* keep the sum alive */
    return t;
}

/* ---- data ---- */
#define NL BENCH_NL
/* Smooth spectra 360-830 nm: 64 distinct shapes (two Gaussians and a pedestal), each row scaled. */
static void make_spectra(float *v, size_t ns)
{
    static float base[64][NL];
    unsigned s = 1;
    for (int q = 0; q < 64; q++) {
        double p[5];
        for (int k = 0; k < 5; k++) {
            s = s * 1103515245u + 12345u;
            p[k] = (double)(s >> 8) / 16777216.0;
        }
        for (int j = 0; j < NL; j++) {
            double x = 360 + j;
            base[q][j] = (float)(p[4] * exp(-0.5 * pow((x - 400 - 350 * p[0]) / (15 + 100 * p[1]), 2)) +
                                 exp(-0.5 * pow((x - 400 - 350 * p[2]) / (20 + 80 * p[3]), 2)) + 0.05);
        }
    }
    for (size_t i = 0; i < ns; i++) {
        float k = 0.5f + (float)(i % 997) / 997.0f;
        const float *bq = base[i % 64];
        for (int j = 0; j < NL; j++) v[i * NL + j] = bq[j] * k;
    }
}

static const lx_function FNS[4] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2, LX_FN_VPRIME};

/* Median seconds of lx_batch_integrate over reps runs after one warm-up; -1 on failure. */
static double time_batch(lx_ctx *ctx, const lx_batch *bt, lx_backend be, double *out, int reps)
{
    double t[9];
    for (int r = 0; r <= reps; r++) {
        lx_batch_opts o = {.backend = be};
        double t0 = cli_bench_now_s();
        if (lx_batch_integrate(ctx, bt, FNS, 4, &o, out) != LX_OK) return -1;
        if (r) t[r - 1] = cli_bench_now_s() - t0;
    }
    return cli_bench_median(t, reps);
}

/* Runs a command; returns its standard output (malloc'ed, NULL on failure). */
char *cli_bench_capture(char *const argv[], const char *envset)
{
    char path[512];
    snprintf(path, sizeof path, "%s", "/tmp/lxbench-capXXXXXX");
    int fd = mkstemp(path);
    if (fd < 0) return NULL;
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, fd, 1);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", 0, 0);
    if (envset) setenv("PERF_DATA", envset, 1);
    pid_t pid;
    int rc = posix_spawnp(&pid, argv[0], &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    int status = 1;
    if (rc == 0) waitpid(pid, &status, 0);
    char *buf = NULL;
    if (rc == 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        off_t len = lseek(fd, 0, SEEK_END);
        buf = malloc((size_t)len + 1);
        if (buf && pread(fd, buf, (size_t)len, 0) == len) buf[len] = 0;
        else {
            free(buf);
            buf = NULL;
        }
    }
    close(fd);
    unlink(path);
    return buf;
}

double cli_bench_json_num(const char *js, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    const char *p = js ? strstr(js, pat) : NULL;
    return p ? strtod(p + strlen(pat), NULL) : NAN;
}

int cli_bench_write_csv(const char *path, const float *v, size_t ns, int named)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    if (named) fputs("id,", f);
    for (int j = 0; j < NL; j++) fprintf(f, "%s%d", j ? "," : "", 360 + j);
    fputc('\n', f);
    for (size_t i = 0; i < ns; i++) {
        if (named) fprintf(f, "s%zu,", i);
        for (int j = 0; j < NL; j++) fprintf(f, "%.6g%c", (double)v[i * NL + j], j == NL - 1 ? '\n' : ',');
    }
    return fclose(f);
}

int cli_bench_paths(lx_simd paths[3])
{
    int n = 0;
    for (int p = (int)lx_simd_cpu(); p >= 0; p--) paths[n++] = (lx_simd)p;
    return n;
}

/* The baseline a C programmer writes: fgets + strtod per value, then the cie15 sums. */
static double strtod_e2e(const char *path, const double *w, size_t *rows)
{
    double t0 = cli_bench_now_s();
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    size_t cap = 1 << 16;
    char *line = malloc(cap);
    double acc = 0;
    *rows = 0;
    int first = 1;
    while (fgets(line, (int)cap, f)) {
        if (first) {
            first = 0;
            continue;
        }
        char *p = line;
        double s[4] = {0, 0, 0, 0};
        for (int j = 0; j < NL; j++) {
            double x = strtod(p, &p);
            if (*p == ',') p++;
            for (int k = 0; k < 4; k++) s[k] += x * w[k * NL + j];
        }
        acc += s[1];
        (*rows)++;
    }
    fclose(f);
    free(line);
    if (acc < 0) fputc(' ', stderr);
    return cli_bench_now_s() - t0;
}

static const char *find_peers(char *buf, size_t cap)
{
    const char *sd = getenv("LX_SHARED_DIR");
    const char *cands[3] = {sd, "../shared", "/work/shared"};
    for (int i = 0; i < 3; i++) {
        if (!cands[i] || !*cands[i]) continue;
        snprintf(buf, cap, "%s/peers/spd_text_peers.py", cands[i]);
        if (access(buf, R_OK) == 0) {
            snprintf(buf, cap, "%s/peers", cands[i]);
            return buf;
        }
    }
    return NULL;
}

/* The machine's read bandwidth (1 thread and cores threads, over at least 256 MB) and the topic's
 * header with it; returns the bandwidth on cores threads (bytes/s). */
static double bandwidth_header(FILE *o, float *v, size_t nmax, int cores)
{
    size_t bw_n = nmax * NL < (size_t)64 << 20 ? (size_t)64 << 20 : nmax * NL; /* at least 256 MB */
    float *bw_buf = bw_n > nmax * NL ? malloc(bw_n * sizeof *bw_buf) : v;
    if (!bw_buf) bw_buf = v, bw_n = nmax * NL;
    if (bw_buf != v)
        for (size_t i = 0; i < bw_n; i++) bw_buf[i] = (float)(i & 1023); /* real pages, not the zero page */
    double bw1 = read_bandwidth(bw_buf, bw_n, 1), bwT = read_bandwidth(bw_buf, bw_n, cores);
    if (bw_buf != v) free(bw_buf);
    fprintf(o, "## bench spd: spectra of %d samples (360-830 nm, 1 nm) -> X, Y, Z, V' (float input, double sums)\n\n", NL);
    fprintf(o, "Read bandwidth measured in this run (sum of floats, %zu MB): %.1f GB/s on 1 thread, %.1f GB/s on %d.\n\n",
            bw_n * 4 >> 20, bw1 / 1e9, bwT / 1e9, cores);
    return bwT;
}

/* OpenCL cold start on a fresh context: device, context, queue, program build, first call (s;
 * -1 when OpenCL failed); the device into *info. */
static double cl_cold_start(lx_ctx *ctx, const float *v, double *out, lx_cl_device_info *info)
{
    double cold = -1;
    memset(info, 0, sizeof *info);
    lx_batch one = {.n_spectra = 1, .n_lambda = NL, .start_nm = 360, .step_nm = 1, .dtype = LX_F32, .values = v};
    lx_batch_opts oo = {.backend = LX_BACKEND_OPENCL};
    double t0 = cli_bench_now_s();
    if (lx_batch_integrate(ctx, &one, FNS, 4, &oo, out) == LX_OK) cold = cli_bench_now_s() - t0;
    lx_cl_info(ctx, info);
    return cold;
}

/* The state the in-memory table shares between its rows. */
typedef struct {
    lx_ctx *ctx;
    const float *v;
    double *out, bwT, cold, last_cpu, last_cl;
    int cores;
} mem_run;

/* One row of the in-memory table: n spectra on SIMD path `path` (OpenCL beside it when cl). For
 * the first path (first), the per-spectrum times at this N go into r->last_cpu, r->last_cl. */
static void in_memory_row(FILE *o, mem_run *r, lx_simd path, size_t n, int cl, int first)
{
    lx_ctx *ctx = r->ctx;
    setenv("LX_SIMD", lx_simd_name(path), 1); /* the CPU loops of this path */
    lx_batch bt = {.n_spectra = n, .n_lambda = NL, .start_nm = 360, .step_nm = 1, .dtype = LX_F32, .values = r->v};
    double bytes = (double)n * NL * sizeof(float);
    enum { PAIRS = 9 };
    double tcs[PAIRS], trs[PAIRS], ratio[PAIRS];
    int failed = 0;
    time_batch(ctx, &bt, LX_BACKEND_CPU, r->out, 1); /* warm-up */
    for (int k = 0; k < PAIRS && !failed; k++) {
        trs[k] = read_pass_s(r->v, n * NL, r->cores);
        lx_batch_opts oc = {.backend = LX_BACKEND_CPU};
        double t0 = cli_bench_now_s();
        failed = lx_batch_integrate(ctx, &bt, FNS, 4, &oc, r->out) != LX_OK;
        tcs[k] = cli_bench_now_s() - t0;
        ratio[k] = trs[k] / tcs[k];
    }
    double tc = cli_bench_median(tcs, PAIRS), tr = cli_bench_median(trs, PAIRS), rr = cli_bench_median(ratio, PAIRS);
    unsetenv("LX_SIMD");
    double tg = cl ? time_batch(ctx, &bt, LX_BACKEND_OPENCL, r->out, 5) : -1;
    setenv("LX_CL_ACCUM", "kahan", 1);
    double tk = cl ? time_batch(ctx, &bt, LX_BACKEND_OPENCL, r->out, 5) : -1;
    unsetenv("LX_CL_ACCUM");
    fprintf(o, "| %s | %.0e | %.3g M | %.1f | %.1f | %.0f %% | %.0f %% |", lx_simd_name(path), (double)n, n / tc / 1e6,
            bytes / tc / 1e9, bytes / tr / 1e9, 100 * rr, 100 * bytes / tc / r->bwT);
    if (tg > 0) fprintf(o, " %.3g M | %.0f %% | %.3g M |\n", n / tg / 1e6, 100 * bytes / tg / r->bwT, n / tk / 1e6);
    else fprintf(o, " %s | | |\n", r->cold >= 0 ? "" : "no OpenCL");
    fflush(o);
    if (first) {
        r->last_cpu = tc / (double)n;
        r->last_cl = tg > 0 ? tg / (double)n : 0;
    }
}

/* The OpenCL device, its cold start and the break-even N for `auto` (or why there is none). */
static void cl_summary(FILE *o, lx_ctx *ctx, const mem_run *r, const lx_cl_device_info *info)
{
    if (r->cold >= 0) {
        fprintf(o, "OpenCL device: %s (%s), %u compute units, fp64 %s. Cold start (context, queue, program build, "
                   "first call): %.3f s (PoCL kernel cache in POCL_CACHE_DIR makes later starts faster).\n",
                info->device_name, info->platform_name, info->compute_units, info->fp64 ? "yes" : "no", r->cold);
        if (r->last_cl > 0 && r->last_cl < r->last_cpu)
            fprintf(o, "Break-even for `auto` (cold): N = %.3g spectra (start-up / per-spectrum saving).\n\n",
                    r->cold / (r->last_cpu - r->last_cl));
        else
            fprintf(o, "Break-even for `auto`: never on this device: OpenCL is not faster per spectrum than the CPU "
                       "path (%.3g vs %.3g us per spectrum at the largest N), so `auto` keeps the CPU.\n\n",
                    r->last_cl * 1e6, r->last_cpu * 1e6);
    } else {
        fprintf(o, "OpenCL: not available (%s).\n\n", lx_ctx_errmsg(ctx));
    }
}

/* In memory: for each path and N, 9 interleaved pairs (read the batch's own buffer with the
 * bandwidth reader, then integrate it), so both see the same data, threads and load; the ratio
 * column is the median of the 9 per-pair ratios (robust to load changing during the run). Then the
 * OpenCL summary. */
static void in_memory(FILE *o, lx_ctx *ctx, const float *v, double *out, const size_t *sizes, int nsizes, int cores,
                      double bwT, const lx_simd *paths, int npaths)
{
    lx_cl_device_info info;
    mem_run r = {.ctx = ctx, .v = v, .out = out, .bwT = bwT, .cores = cores};
    r.cold = cl_cold_start(ctx, v, out, &info);
    fprintf(o, "| path | N | CPU spectra/s | CPU GB/s | read GB/s (same buffer) | CPU / read (median of pairs) | CPU / bandwidth above | "
               "OpenCL spectra/s | OpenCL / bandwidth above | OpenCL compensated float |\n");
    fprintf(o, "|---|---|---|---|---|---|---|---|---|---|\n");
    for (int pi = 0; pi < npaths; pi++)
        for (int i = 0; i < nsizes; i++) in_memory_row(o, &r, paths[pi], sizes[i], r.cold >= 0 && pi == 0, pi == 0);
    unsetenv("LX_SIMD");
    fprintf(o, "\n");
    cl_summary(o, ctx, &r, &info);
}

/* The CMF table the peer scripts read (path: 471 x 3 doubles). */
static void write_cmf(lx_ctx *ctx, const char *path)
{
    FILE *f = fopen(path, "wb");
    lx_spd fx[3];
    for (int k = 0; k < 3; k++) lx_function_get(ctx, FNS[k], &fx[k]);
    for (int j = 0; f && j < NL; j++)
        for (int k = 0; k < 3; k++) fwrite(&fx[k].value[j], sizeof(double), 1, f);
    if (f) fclose(f);
}

/* The peers on n spectra: numpy loadtxt + matmul end to end (*np_s) and colour-science's
 * msds_to_XYZ in memory (*col), seconds (NaN when they did not run). */
static void peer_times(const char *peers, const char *py, const char *tmp, const float *v, size_t n, double *np_s,
                       double *col)
{
    char script[600], nbuf[32];
    snprintf(script, sizeof script, "%s/spd_text_peers.py", peers);
    snprintf(nbuf, sizeof nbuf, "%zu", n);
    char *const a1[] = {(char *)py, script, "csv_np_loadtxt", nbuf, NULL};
    char *js = cli_bench_capture(a1, tmp);
    *np_s = cli_bench_json_num(js, "total_s");
    free(js);
    /* colour-science on the same spectra in memory (its binary input file) */
    char bin[600];
    snprintf(bin, sizeof bin, "%s/spd_%zu_f32.bin", tmp, n);
    FILE *f = fopen(bin, "wb");
    if (f) {
        fwrite(v, sizeof(float), n * NL, f);
        fclose(f);
        snprintf(script, sizeof script, "%s/spd_xyz_peers.py", peers);
        char *const a2[] = {(char *)py, script, "colour_msds_nd", nbuf, "f32", "3", NULL};
        js = cli_bench_capture(a2, tmp);
        *col = cli_bench_json_num(js, "median_s");
        free(js);
        unlink(bin);
    }
}

/* One row of the CSV table: the library's CSV path on the file at path (n spectra, size bytes) on
 * SIMD path `path_simd`, beside C strtod (ms) and, on the first path (first), the peers. */
static void csv_row(FILE *o, lx_ctx *ctx, const char *path, size_t n, double size, lx_simd path_simd, int first, double ms,
                    double np_s, double col)
{
    double tl[3], tcpu[3];
    int good = 1;
    setenv("LX_SIMD", lx_simd_name(path_simd), 1);
    for (int r = 0; r < 3 && good; r++) {
        /* the library's CSV path end to end: mapped file, parsed on every core chunk by
         * chunk, each chunk integrated while the next one parses */
        double t0 = cli_bench_now_s(), c0 = cli_bench_cpu_s(), *res = NULL;
        size_t got = 0;
        if (lx_batch_table_integrate_file(ctx, path, FNS, 4, 0, &res, &got) != LX_OK || got != n) {
            cli_fail("bench", ctx, LX_EPARSE);
            good = 0;
        }
        tl[r] = cli_bench_now_s() - t0;
        tcpu[r] = cli_bench_cpu_s() - c0;
        lx_batch_results_free(res);
    }
    unsetenv("LX_SIMD");
    if (!good) return;
    double ml = cli_bench_median(tl, 3), mc = cli_bench_median(tcpu, 3);
    fprintf(o, "| %.0e | %.1f | %s | %.4f | %.0f | %.4f | %.0f |", (double)n, size / 1e6, lx_simd_name(path_simd), ml,
            size / ml / 1e6, mc, size / mc / 1e6);
    if (!first) fprintf(o, " | | |");
    else {
        fprintf(o, " %.4f |", ms);
        if (isnan(np_s)) fprintf(o, " not installed |");
        else fprintf(o, " %.4f |", np_s);
        if (isnan(col)) fprintf(o, " not installed |");
        else fprintf(o, " %.4f |", col);
    }
    fprintf(o, " %.1fx |", ms / ml);
    if (isnan(np_s)) fprintf(o, " - |\n");
    else fprintf(o, " %.1fx |\n", np_s / ml);
    fflush(o);
}

/* CSV end to end: the library's CSV path against C strtod and the Python peers (py, when it has
 * numpy and colour), for each N up to 1e5. */
static void csv_end_to_end(FILE *o, lx_ctx *ctx, const char *tmp, const char *py, const float *v, const size_t *sizes,
                           int nsizes, const lx_simd *paths, int npaths)
{
    char pbuf[512], path[600], cmf[600];
    const char *peers = find_peers(pbuf, sizeof pbuf);
    char *const pycheck[] = {(char *)py, "-c", "import numpy, colour; print(1)", NULL};
    char *ok = peers ? cli_bench_capture(pycheck, NULL) : NULL;
    int have_py = ok != NULL;
    free(ok);
    snprintf(cmf, sizeof cmf, "%s/cmf_1931_2.bin", tmp);
    write_cmf(ctx, cmf);
    double w[4 * NL];
    for (int k = 0; k < 4; k++) {
        lx_spd fx;
        lx_function_get(ctx, FNS[k], &fx);
        for (int j = 0; j < NL; j++) w[k * NL + j] = 0;
        for (size_t j = 0; j < fx.n; j++) w[k * NL + (int)(fx.lambda_nm[j] - 360)] = fx.value[j];
    }
    fprintf(o, "The CSV library path (`lx_batch_table_integrate_file`: file in the page cache -> X, Y, Z, V'), medians of 3,\n"
               "seconds, per SIMD path; CPU: this process's CPU time over the call (every thread), MB/CPU-s: MB per\n"
               "core-second, what a loaded machine cannot steal:\n\n");
    fprintf(o, "| N | MB | path | luxcalc | MB/s | CPU s | MB/CPU-s | C strtod | numpy loadtxt + matmul | colour msds_to_XYZ (in memory) | vs strtod | vs numpy |\n");
    fprintf(o, "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < nsizes; i++) {
        size_t n = sizes[i];
        if (n > 100000) continue; /* a 4 GB text file says nothing more */
        snprintf(path, sizeof path, "%s/spd_%zu.csv", tmp, n);
        if (cli_bench_write_csv(path, v, n, 0) != 0) {
            cli_error("bench", "%s: cannot write", path);
            break;
        }
        struct stat stt;
        stat(path, &stt);
        double ts[3];
        size_t rows = 0;
        for (int r = 0; r < 3; r++) ts[r] = strtod_e2e(path, w, &rows);
        double ms = cli_bench_median(ts, 3), np_s = NAN, col = NAN;
        if (have_py) peer_times(peers, py, tmp, v, n, &np_s, &col);
        for (int pi = 0; pi < npaths; pi++) csv_row(o, ctx, path, n, (double)stt.st_size, paths[pi], pi == 0, ms, np_s, col);
        unlink(path);
    }
    unlink(cmf);
    fprintf(o, "\n");
}

/* One small file, whole process: `luxcalc spd` (this executable) spawned on an 81-sample file,
 * and beside it the start-up of colour-science in py. */
static void one_file(FILE *o, const char *tmp, const char *py)
{
    char self[512], path[600];
    ssize_t sl = readlink("/proc/self/exe", self, sizeof self - 1);
    if (sl <= 0) return;
    self[sl] = 0;
    snprintf(path, sizeof path, "%s/one.csv", tmp);
    FILE *f = fopen(path, "w");
    if (!f) return;
    fprintf(f, "wavelength_nm,value\n");
    for (int j = 0; j < 81; j++) fprintf(f, "%d,%.6g\n", 380 + 5 * j, lx_illuminant_a(380 + 5 * j));
    fclose(f);
    double t[11];
    int good = 1;
    for (int r = 0; r < 11 && good; r++) {
        char *const a[] = {self, "spd", "--format", "csv", path, NULL};
        double t0 = cli_bench_now_s();
        char *res = cli_bench_capture(a, NULL);
        t[r] = cli_bench_now_s() - t0;
        good = res != NULL;
        free(res);
    }
    if (good) fprintf(o, "`luxcalc spd` on one 81-sample file, whole process (spawn to exit), median of 11: %.2f ms.\n",
                      cli_bench_median(t, 11) * 1e3);
    else fprintf(o, "`luxcalc spd` on one small file: the command failed.\n");
    /* the peer's start-up alone: what a one-off calculation costs in Python */
    double tp[3];
    int have = 1;
    for (int r = 0; r < 3 && have; r++) {
        char *const a[] = {(char *)py, "-c", "import colour", NULL};
        double t0 = cli_bench_now_s();
        char *res = cli_bench_capture(a, NULL);
        tp[r] = cli_bench_now_s() - t0;
        have = res != NULL;
        free(res);
    }
    if (have) fprintf(o, "Beside it, `%s -c 'import colour'` (colour-science start-up alone), median of 3: %.0f ms.\n\n", py,
                      cli_bench_median(tp, 3) * 1e3);
    else fprintf(o, "Beside it, `%s -c 'import colour'`: colour-science not installed.\n\n", py);
    unlink(path);
}

int cli_bench_spd(FILE *report, const char *tmp, const size_t *sizes, int nsizes)
{
    FILE *o = report;
    size_t nmax = 0;
    for (int i = 0; i < nsizes; i++)
        if (sizes[i] > nmax) nmax = sizes[i];
    float *v = malloc(nmax * NL * sizeof *v);
    double *out = malloc(nmax * 4 * sizeof *out);
    if (!v || !out) {
        cli_error("bench", "out of memory for %zu spectra", nmax);
        return CLI_RUNTIME;
    }
    make_spectra(v, nmax);
    int cores = (int)sysconf(_SC_NPROCESSORS_ONLN);
    if (cores < 1) cores = 1;
    if (cores > 16) cores = 16;
    double bwT = bandwidth_header(o, v, nmax, cores);
    lx_ctx *ctx = cli_ctx("bench");
    if (!ctx) return CLI_RUNTIME;
    lx_simd paths[3];
    int npaths = cli_bench_paths(paths);
    in_memory(o, ctx, v, out, sizes, nsizes, cores, bwT, paths, npaths);
    const char *py = getenv("LX_PEERS_PYTHON");
    if (!py || !*py) py = "python3";
    csv_end_to_end(o, ctx, tmp, py, v, sizes, nsizes, paths, npaths);
    cli_bench_spd_cli(o, tmp, sizes, nsizes, v);
    one_file(o, tmp, py);
    lx_ctx_destroy(ctx);
    free(v);
    free(out);
    return CLI_OK;
}
