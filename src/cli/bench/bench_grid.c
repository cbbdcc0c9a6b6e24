/* bench_grid.c - the `luxcalc bench grid` topic: point-luminaires per second for 1e6 points x 10
 * luminaires (CPU exact bilinear, the CPU table twin at 1024 rows on each SIMD path the CPU has and
 * at 256 and 128 rows, OpenCL table in float and double), each table run's largest error against
 * the exact bilinear result, beside the numpy peer ../shared/peers/illum_numpy.py run in the same
 * process tree. */
#include "cli/cli.h"
#include "bench_common.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>



static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Median seconds of reps runs (after one warm-up); NaN when the computation fails. */
static double time_grid(lx_ctx *ctx, const lx_placement *pl, size_t m, const double *pts, size_t n, const double *nz,
                        lx_grid_opts o, double *E, int reps, int *used)
{
    double t[16];
    if (lx_grid_illuminance(ctx, pl, m, pts, n, nz, 1, &o, E)) return NAN;
    *used = lx_ctx_backend_used(ctx);
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now_s();
        if (lx_grid_illuminance(ctx, pl, m, pts, n, nz, 1, &o, E)) return NAN;
        t[r] = cli_bench_now_s() - t0;
    }
    qsort(t, (size_t)reps, sizeof t[0], cmp_d);
    return t[reps / 2];
}

/* The 1-minute load average (other work on the cores), NaN when unknown. */

static double peer_numpy(size_t n, int m)
{
    const char *dir = getenv("LX_SHARED_DIR");
    const char *py = getenv("LX_PEERS_PYTHON");
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s %s/peers/illum_numpy.py %zu %d 3 interp1d,bilin37x25 2>/dev/null",
             py && *py ? py : "python3", dir && *dir ? dir : "../shared", n, m);
    FILE *p = popen(cmd, "r");
    if (!p) return NAN;
    char buf[4096];
    size_t len = fread(buf, 1, sizeof buf - 1, p);
    buf[len] = 0;
    pclose(p);
    const char *k = strstr(buf, "\"interp1d\"");
    if (!k) return NAN;
    const char *v = strstr(k, "\"pl_per_s\":");
    return v ? strtod(v + 11, NULL) : NAN;
}

int cli_bench_grid(FILE *out)
{
    lx_ctx *ctx = cli_ctx("bench");
    if (!ctx) return CLI_RUNTIME;
    const size_t side = 1000, n = side * side;
    const int M = 10;
    double *pts = malloc(3 * n * sizeof *pts), *E = malloc(n * sizeof *E);
    if (!pts || !E) {
        free(pts);
        free(E);
        lx_ctx_destroy(ctx);
        return CLI_RUNTIME;
    }
    /* the peer's layout: a 20 m x 20 m plane at 0.85 m, luminaires at 3 m on a 5-wide layout */
    for (size_t j = 0; j < side; j++)
        for (size_t i = 0; i < side; i++) {
            double *q = pts + 3 * (j * side + i);
            q[0] = (i + 0.5) * 20.0 / side;
            q[1] = (j + 0.5) * 20.0 / side;
            q[2] = 0.85;
        }
    lx_lum_model mw = {.kind = LX_LUM_MODEL_WARN, .flux_lm = 3000, .exponent = 1.5, .step_deg = 5};
    lx_luminaire *axial = NULL;
    lx_luminaire_from_model(ctx, &mw, &axial);
    /* an asymmetric luminaire: 37 gamma x 25 C planes as the peer's bilin37x25 */
    char *ies = malloc(1 << 16), *p = ies;
    p += sprintf(p, "IESNA:LM-63-2002\n[TEST] bench\nTILT=NONE\n1 -1 1 37 25 1 2 0 0 0\n1 1 1\n");
    for (int g = 0; g <= 180; g += 5) p += sprintf(p, "%d ", g);
    p += sprintf(p, "\n");
    for (int c = 0; c <= 360; c += 15) p += sprintf(p, "%d ", c);
    p += sprintf(p, "\n");
    for (int c = 0; c <= 360; c += 15)
        for (int g = 0; g <= 180; g += 5) {
            double gr = g * CLI_PI / 180, i1 = 1000 * pow(fmax(cos(gr), 0), 1.5) + 20;
            p += sprintf(p, "%.6f\n", i1 * (1 + 0.2 * cos(c * CLI_PI / 180) * sin(gr)));
        }
    lx_luminaire *asym = NULL;
    lx_luminaire_read_mem(ctx, "bench.ies", ies, strlen(ies), &asym);
    free(ies);
    lx_placement pl[2][10];
    for (int k = 0; k < M; k++) {
        double x = 2 + 4 * (k % 5), y = k < 5 ? 4 : 16;
        pl[0][k] = (lx_placement){.lum = axial, .pos_m = {x, y, 3}, .aim = {0, 0, -1}};
        pl[1][k] = (lx_placement){.lum = asym, .pos_m = {x, y, 3}, .aim = {0, 0, -1}};
    }
    double nz[3] = {0, 0, 1};
    fprintf(out, "## grid: illuminance, %zu points x %d luminaires (point model), median of 5\n\n", n, M);
    fprintf(out, "| luminaire | path | backend | s | M point-luminaires/s | M per CPU-second (all threads) | max error vs exact (of E max) | load (1 min) |\n"
                 "|---|---|---|---|---|---|---|---|\n");
    const char *se = getenv("LX_SIMD");
    char simd_env[32] = "";
    if (se) snprintf(simd_env, sizeof simd_env, "%s", se);
    double *Ex = malloc(n * sizeof *Ex); /* the exact bilinear result of each luminaire: the reference */
    static const char *names[2] = {"axial Warn (37 gamma)", "asymmetric (37 gamma x 25 C)"};
    for (int L = 0; L < 2; L++) {
        struct {
            const char *path;
            lx_grid_opts o;
            const char *simd; /* LX_SIMD for this run (NULL: as the environment says) */
        } runs[] = {
            {"exact bilinear (acos, atan2)", {.model = LX_MODEL_POINT, .backend = LX_BACKEND_CPU}, NULL},
            {"table (CPU twin, double), AVX-512", {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU}, "avx512"},
            {"table (CPU twin, double), AVX2", {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU}, "avx2"},
            {"table (CPU twin, double), scalar", {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU}, "scalar"},
            {"table, 256 rows (CPU)", {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU, .table_n = 256}, NULL},
            {"table, 128 rows (CPU)", {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_CPU, .table_n = 128}, NULL},
            {"table, OpenCL double", {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_OPENCL}, NULL},
            {"table, OpenCL float", {.model = LX_MODEL_POINT, .interp = LX_INTERP_TABLE, .backend = LX_BACKEND_OPENCL, .fp32 = 1}, NULL},
        };
        for (size_t r = 0; r < sizeof runs / sizeof runs[0]; r++) {
            int used = 0;
            lx_simd want = LX_SIMD_SCALAR;
            if (runs[r].simd && (lx_simd_parse(ctx, runs[r].simd, &want) != LX_OK || want > lx_simd_cpu())) continue;
            if (runs[r].simd) setenv("LX_SIMD", runs[r].simd, 1); /* the twin of this path (restored below) */
            double c0 = cpu_s();
            double t = time_grid(ctx, pl[L], M, pts, n, nz, runs[r].o, E, 5, &used);
            double cs = (cpu_s() - c0) / 6; /* the warm-up and 5 runs */
            if (runs[r].simd) {
                if (simd_env[0]) setenv("LX_SIMD", simd_env, 1);
                else unsetenv("LX_SIMD");
            }
            if (isnan(t)) {
                fprintf(out, "| %s | %s | - | failed: %s | | | | |\n", names[L], runs[r].path, lx_ctx_errmsg(ctx));
                fflush(out);
                continue;
            }
            char err[32] = "(reference)";
            if (r == 0 && Ex) {
                memcpy(Ex, E, n * sizeof *E);
            } else if (Ex) {
                double em = 0, w = 0;
                for (size_t i = 0; i < n; i++) em = fmax(em, Ex[i]);
                for (size_t i = 0; i < n; i++) w = fmax(w, fabs(E[i] - Ex[i]));
                snprintf(err, sizeof err, "%.1e", em > 0 ? w / em : 0);
            }
            fprintf(out, "| %s | %s | %s | %.3f | %.1f | %.1f | %s | %.2f |\n", names[L], runs[r].path,
                    used == LX_BACKEND_OPENCL ? "opencl" : "cpu", t, n * (double)M / t / 1e6, n * (double)M / cs / 1e6, err,
                    cli_bench_load1());
            fflush(out);
        }
    }
    double np = peer_numpy(n, M);
    if (isnan(np)) fprintf(out, "\nnumpy peer (illum_numpy.py interp1d): not run (python3 with numpy not found)\n\n");
    else fprintf(out, "\nnumpy peer (../shared/peers/illum_numpy.py, interp1d, same run): %.1f M point-luminaires/s\n\n", np / 1e6);
    lx_luminaire_free(axial);
    lx_luminaire_free(asym);
    free(Ex);
    free(pts);
    free(E);
    lx_ctx_destroy(ctx);
    return CLI_OK;
}
