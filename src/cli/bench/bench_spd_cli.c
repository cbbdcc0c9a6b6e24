/* bench_spd_cli.c - part of the `luxcalc bench spd` topic: the command users run, `luxcalc spd
 * --format csv FILE -o OUT` with all default columns, as a whole process on each SIMD path the CPU
 * has, beside numpy loadtxt + matmul + savetxt and colour-science with Ohno 2013 CCT
 * (spd_cli_peers.py) in the same run; and the two kernels it leans on: the fast CCT against the
 * exact solve, lx_double_format against printf. */
#include "cli/cli.h"
#include "bench_spd.h"

#include <fcntl.h>
#include <math.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

static double children_cpu; /* CPU seconds of the children waited for so far */

int cli_bench_run(char *const argv[], const char *simd, const char *out_path, double *wall_s, double *cpu_s)
{
    {
        struct rusage ru; /* children waited for elsewhere (cli_bench_capture) */
        getrusage(RUSAGE_CHILDREN, &ru);
        children_cpu = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
                       1e-6 * (double)ru.ru_stime.tv_usec;
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, out_path ? out_path : "/dev/null", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    const char *was = getenv("LX_SIMD");
    char keep[32] = "";
    if (was) snprintf(keep, sizeof keep, "%s", was);
    if (simd) setenv("LX_SIMD", simd, 1);
    pid_t pid;
    double t0 = cli_bench_now_s();
    int rc = posix_spawnp(&pid, argv[0], &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (simd) {
        if (was) setenv("LX_SIMD", keep, 1);
        else unsetenv("LX_SIMD");
    }
    if (rc != 0) return -1;
    int status = 1;
    if (waitpid(pid, &status, 0) < 0) return -1;
    *wall_s = cli_bench_now_s() - t0;
    /* the children's CPU time so far, less what it was before this one: one child at a time */
    struct rusage ru;
    getrusage(RUSAGE_CHILDREN, &ru);
    double all = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
                 1e-6 * (double)ru.ru_stime.tv_usec;
    *cpu_s = all - children_cpu;
    children_cpu = all;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

/* spd_cli_peers.py: LX_BENCH_SCRIPTS, else beside this program's sources (build/luxcalc ->
 * src/cli/bench/), else ./src/cli/bench/ */
static const char *find_script(char *buf, size_t cap)
{
    const char *env = getenv("LX_BENCH_SCRIPTS");
    char self[512] = "";
    ssize_t sl = readlink("/proc/self/exe", self, sizeof self - 1);
    if (sl > 0) {
        self[sl] = 0;
        char *slash = strrchr(self, '/');
        if (slash) *slash = 0;
    }
    const char *cands[3] = {env, sl > 0 ? self : NULL, "."};
    const char *rel[3] = {"", "/../src/cli/bench", "/src/cli/bench"};
    for (int i = 0; i < 3; i++) {
        if (!cands[i] || !*cands[i]) continue;
        snprintf(buf, cap, "%s%s/spd_cli_peers.py", cands[i], rel[i]);
        if (access(buf, R_OK) == 0) return buf;
    }
    return NULL;
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* the kernels: CCT (fast batch vs exact), number text (lx_double_format vs the shortest of printf's
 * %.15g..%.17g that reads back, what the CLI printed before) */
static void kernels(FILE *o)
{
    lx_ctx *ctx = cli_ctx("bench");
    if (!ctx) return;
    enum { N = 200000, NE = 2000 };
    double *u = malloc(N * sizeof *u), *v = malloc(N * sizeof *v), *T = malloc(N * sizeof *T), *d = malloc(N * sizeof *d);
    if (!u || !v || !T || !d) goto done;
    unsigned s = 1;
    for (int i = 0; i < N; i++) { /* chromaticities of light sources: 1500-20000 K, within 0.007 of the locus */
        s = s * 1103515245u + 12345u;
        double t = 1500 * pow(20000.0 / 1500, (double)(s >> 8) / 16777216.0), pu, pv;
        lx_planck_uv(ctx, LX_OBSERVER_2, t, &pu, &pv);
        s = s * 1103515245u + 12345u;
        u[i] = pu + 0.01 * ((double)(s >> 8) / 16777216.0 - 0.5);
        s = s * 1103515245u + 12345u;
        v[i] = pv + 0.01 * ((double)(s >> 8) / 16777216.0 - 0.5);
    }
    double c0 = cpu_now();
    lx_cct_from_uv_batch(ctx, LX_OBSERVER_2, 1, u, v, T, d); /* builds the table once per process */
    double build = cpu_now() - c0, best = INFINITY;
    for (int r = 0; r < 3; r++) {
        c0 = cpu_now();
        lx_cct_from_uv_batch(ctx, LX_OBSERVER_2, N, u, v, T, d);
        double t = cpu_now() - c0;
        if (t < best) best = t;
    }
    c0 = cpu_now();
    for (int i = 0; i < NE; i++) lx_cct_from_uv(ctx, LX_OBSERVER_2, u[i], v[i], &T[i], &d[i]);
    double exact = (cpu_now() - c0) / NE;
    /* number text: the columns of a results file */
    char buf[64];
    size_t bytes = 0;
    c0 = cpu_now();
    for (int i = 0; i < N; i++) bytes += lx_double_format(u[i] * 1e5 / (1 + i % 7), buf);
    double ryu = cpu_now() - c0;
    c0 = cpu_now();
    for (int i = 0; i < N / 10; i++) {
        double x = u[i] * 1e5 / (1 + i % 7);
        for (int p = 15; p <= 17; p++) {
            snprintf(buf, sizeof buf, "%.*g", p, x);
            if (strtod(buf, NULL) == x) break;
        }
    }
    double pf = (cpu_now() - c0) * 10;
    fprintf(o, "Kernels (CPU time on one core, %d values):\n\n", N);
    fprintf(o, "| kernel | per value | throughput |\n|---|---|---|\n");
    fprintf(o, "| CCT + Duv, fast (lx_cct_from_uv_batch; table built once per process in %.1f ms) | %.3f us | %.2f M/s |\n",
            build * 1e3, best / N * 1e6, N / best / 1e6);
    fprintf(o, "| CCT + Duv, exact solve (lx_cct_from_uv, %d values) | %.1f us | %.3f M/s |\n", NE, exact * 1e6, 1 / exact / 1e6);
    fprintf(o, "| number text, shortest round trip (lx_double_format) | %.0f ns | %.0f MB/s |\n", ryu / N * 1e9,
            (double)bytes / ryu / 1e6);
    fprintf(o, "| number text, shortest of printf %%.15g-%%.17g that reads back (before) | %.0f ns | %.0f MB/s |\n\n",
            pf / N * 1e9, (double)bytes / pf / 1e6);
done:
    free(u);
    free(v);
    free(T);
    free(d);
    lx_ctx_destroy(ctx);
}

void cli_bench_spd_cli(FILE *o, const char *tmp, const size_t *sizes, int nsizes, const float *v)
{
    char self[512], script[700], csv[600], out[600], wpath[600], pout[600];
    ssize_t sl = readlink("/proc/self/exe", self, sizeof self - 1);
    if (sl <= 0) {
        fprintf(o, "The CLI end to end: not measured (this program's path is unknown).\n\n");
        return;
    }
    self[sl] = 0;
    const char *sc = find_script(script, sizeof script);
    const char *py = getenv("LX_PEERS_PYTHON");
    if (!py || !*py) py = "python3";
    char *const chk_np[] = {(char *)py, "-c", "import numpy", NULL};
    char *const chk_col[] = {(char *)py, "-W", "ignore", "-c", "import numpy, colour", NULL};
    char *r1 = sc ? cli_bench_capture(chk_np, NULL) : NULL, *r2 = sc ? cli_bench_capture(chk_col, NULL) : NULL;
    int have_np = r1 != NULL, have_col = r2 != NULL;
    free(r1);
    free(r2);
    /* the weights the numpy peer multiplies by: luxcalc's own tables (x, y, z bar, V') */
    snprintf(wpath, sizeof wpath, "%s/weights_471x4.bin", tmp);
    {
        lx_ctx *ctx = cli_ctx("bench");
        static const lx_function F[4] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2, LX_FN_VPRIME};
        double w[BENCH_NL][4];
        memset(w, 0, sizeof w);
        for (int k = 0; ctx && k < 4; k++) {
            lx_spd f;
            if (lx_function_get(ctx, F[k], &f) != LX_OK) continue;
            for (size_t j = 0; j < f.n; j++) {
                int at = (int)lround(f.lambda_nm[j] - 360);
                if (at >= 0 && at < BENCH_NL) w[at][k] = f.value[j];
            }
        }
        FILE *f = fopen(wpath, "wb");
        if (f) {
            fwrite(w, sizeof w, 1, f);
            fclose(f);
        }
        lx_ctx_destroy(ctx);
    }
    lx_simd paths[3];
    int np = cli_bench_paths(paths);
    fprintf(o, "The command users run, end to end: `luxcalc spd --format csv FILE -o OUT` (all default columns,\n"
               "CCT and Duv included; a rows-layout CSV of %%.6g values, in the page cache), a whole process from\n"
               "spawn to exit, median of 3 per SIMD path (LX_SIMD); beside it in the same run, as whole processes\n"
               "once each, numpy `loadtxt` + matmul + `savetxt` (every column but CCT and Duv) and colour-science\n"
               "(`msds_to_XYZ`, xy, u'v', `uv_to_CCT_Ohno2013`, scotopic Y; %s). CPU: the child's user + system time.\n\n",
            sc ? "src/cli/bench/spd_cli_peers.py" : "peer script not found");
    fprintf(o, "| N | MB | path | luxcalc s | CPU s | MB/s | numpy s | colour-science s | vs numpy | vs colour-science |\n");
    fprintf(o, "|---|---|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < nsizes; i++) {
        size_t n = sizes[i];
        if (n > 100000) continue; /* a 4 GB text says nothing more than 423 MB */
        snprintf(csv, sizeof csv, "%s/cli_%zu.csv", tmp, n);
        snprintf(out, sizeof out, "%s/cli_%zu_out.csv", tmp, n);
        snprintf(pout, sizeof pout, "%s/cli_%zu_peer.csv", tmp, n);
        if (cli_bench_write_csv(csv, v, n, 1) != 0) {
            fprintf(o, "| %.0e | cannot write %s | | | | | | | | |\n", (double)n, csv);
            continue;
        }
        struct stat st;
        stat(csv, &st);
        double mb = (double)st.st_size / 1e6, t_np = NAN, t_col = NAN, cw;
        if (have_np) {
            char *const a[] = {(char *)py, (char *)sc, "numpy", csv, pout, wpath, NULL};
            if (cli_bench_run(a, NULL, NULL, &t_np, &cw) != 0) t_np = NAN;
        }
        if (have_col) {
            char *const a[] = {(char *)py, (char *)sc, "colour", csv, pout, wpath, NULL};
            if (cli_bench_run(a, NULL, NULL, &t_col, &cw) != 0) t_col = NAN;
        }
        unlink(pout);
        for (int p = 0; p < np; p++) {
            double tw[3], tc[3];
            int ok = 1;
            for (int r = 0; r < 3 && ok; r++) {
                char *const a[] = {self, "spd", "--format", "csv", csv, "-o", out, NULL};
                ok = cli_bench_run(a, lx_simd_name(paths[p]), NULL, &tw[r], &tc[r]) == 0;
            }
            if (!ok) {
                fprintf(o, "| %.0e | %.1f | %s | failed | | | | | | |\n", (double)n, mb, lx_simd_name(paths[p]));
                continue;
            }
            double w = cli_bench_median(tw, 3), c = cli_bench_median(tc, 3);
            fprintf(o, "| %.0e | %.1f | %s | %.3f | %.3f | %.0f |", (double)n, mb, lx_simd_name(paths[p]), w, c, mb / w);
            if (p == 0) {
                if (isnan(t_np)) fprintf(o, " %s |", have_np ? "failed" : "no numpy");
                else fprintf(o, " %.2f |", t_np);
                if (isnan(t_col)) fprintf(o, " %s |", have_col ? "failed" : "no colour-science");
                else fprintf(o, " %.2f |", t_col);
            } else {
                fprintf(o, " | |");
            }
            if (isnan(t_np)) fprintf(o, " - |");
            else fprintf(o, " %.1fx |", t_np / w);
            if (isnan(t_col)) fprintf(o, " - |\n");
            else fprintf(o, " %.0fx |\n", t_col / w);
            fflush(o);
        }
        unlink(out);
        unlink(csv);
    }
    unlink(wpath);
    fprintf(o, "\n");
    kernels(o);
}
