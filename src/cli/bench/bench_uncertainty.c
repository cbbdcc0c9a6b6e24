/* bench_uncertainty.c - `luxcalc bench uncertainty`: the measurement uncertainty of one 401-sample
 * spectrum (a white LED, 380-780 nm at 1 nm) under the model "1%+scale=2%+shift=0.2nm", on the
 * path users run (`luxcalc spd --uncertainty`, the whole process): 10^5 Monte Carlo trials of the
 * colorimetry (goal < 2 s on 2 cores), with Ra and Rf (goal < 20 s), GUM (goal < 50 ms), the
 * adaptive procedure; the library's own time split (trials drawn, GUM); the trials drawn on the CPU
 * against OpenCL (cold and warm) for the backend rule's break-even; and luxpy doing the same trials
 * (src/cli/bench/unc_peers.py) in the same run, with the uncertainties both find. */
#include "cli/cli.h"
#include "bench_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

int cli_bench_uncertainty(FILE *out, const char *tmp);

#define SPEC "1%+scale=2%+shift=0.2nm"

/* The spectrum: a blue LED and a broad phosphor, 380-780 nm at 1 nm. */
static void spectrum(double *lam, double *v)
{
    for (int i = 0; i < 401; i++) {
        double l = 380 + i, a = (l - 452) / 10, p = (l - 590) / 55;
        lam[i] = l, v[i] = exp(-0.5 * a * a) + 0.9 * exp(-0.5 * p * p);
    }
}

static double children_cpu(void)
{
    struct rusage ru;
    getrusage(RUSAGE_CHILDREN, &ru);
    return (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
           1e-6 * (double)ru.ru_stime.tv_usec;
}

/* Runs a shell command with its output to `capture` (NULL: discarded): wall and CPU seconds; -1 on failure. */
static int run_cmd(const char *cmd, const char *capture, double *wall, double *cpu)
{
    char full[4096];
    snprintf(full, sizeof full, "%s >%s 2>/dev/null", cmd, capture ? capture : "/dev/null");
    double c0 = children_cpu(), t0 = cli_bench_now_s();
    int rc = system(full);
    *wall = cli_bench_now_s() - t0;
    *cpu = children_cpu() - c0;
    return rc == 0 ? 0 : -1;
}

/* "luxcalc spd ..." end to end, the median of `runs` (wall and CPU). */
static int cli_row(FILE *o, const char *self, const char *args, const char *file, int runs, const char *what,
                   const char *goal, double goal_s)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s' spd %s '%s'", self, args, file);
    double w[5], c[5];
    for (int r = 0; r < runs; r++)
        if (run_cmd(cmd, NULL, &w[r], &c[r]) != 0) {
            fprintf(o, "| %s | `luxcalc spd %s` | failed | - | - | %s | - |\n", what, args, goal);
            return -1;
        }
    double wm = cli_bench_median(w, runs), cm = cli_bench_median(c, runs);
    /* on 2 cores of its own the run takes about CPU / 2 (it uses every core) */
    double free2 = cm / 2;
    fprintf(o, "| %s | `luxcalc spd %s` | %.3f | %.3f | %.3f | %s | %s |\n", what, args, wm, cm, free2, goal,
            free2 < goal_s ? "yes" : wm < goal_s ? "yes (wall)" : "no");
    return 0;
}

/* The library's split for one configuration. */
static void lib_row(FILE *o, lx_ctx *ctx, const lx_spd *s, const lx_unc_model *m, lx_unc_method method, size_t trials,
                    unsigned q, const char *what)
{
    lx_unc_opts opt = {.method = method, .trials = trials, .quantities = q};
    lx_unc_result *r = NULL;
    double t0 = cli_bench_now_s();
    if (lx_spd_uncertainty(ctx, s, m, &opt, &r) != LX_OK) {
        fprintf(o, "| %s | failed: %s | | | | |\n", what, lx_ctx_errmsg(ctx));
        return;
    }
    double t = cli_bench_now_s() - t0;
    fprintf(o, "| %s | %zu | %.4f | %.4f | %.4f | %.4f | %zu |\n", what, r->trials, t, r->seconds_gum, r->seconds_mc,
            r->seconds_draw, r->rank);
    lx_unc_result_free(r);
}

/* The trials drawn on one backend: seconds drawing (0 when it is unavailable: *why says). */
static double draw_s(const lx_spd *s, const lx_unc_model *m, size_t trials, lx_backend be, int warm, char *why, size_t cap)
{
    lx_ctx *ctx = NULL;
    if (lx_ctx_create(&ctx) != LX_OK) return NAN;
    lx_unc_opts opt = {.trials = trials, .quantities = LX_UNC_CRI, .backend = be};
    lx_unc_result *r = NULL;
    double d = NAN;
    for (int k = 0; k <= warm; k++) {
        lx_unc_result_free(r);
        r = NULL;
        if (lx_spd_uncertainty(ctx, s, m, &opt, &r) != LX_OK) {
            snprintf(why, cap, "%s", lx_ctx_errmsg(ctx));
            break;
        }
        d = r->seconds_draw;
    }
    lx_unc_result_free(r);
    lx_ctx_destroy(ctx);
    return d;
}

/* unc_peers.py: LX_BENCH_SCRIPTS, else beside this program's sources, else ./src/cli/bench/ */
static const char *peer_script(char *buf, size_t cap)
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
        snprintf(buf, cap, "%s%s/unc_peers.py", cands[i], rel[i]);
        if (access(buf, R_OK) == 0) return buf;
    }
    return NULL;
}

/* A number from the peer's JSON line ("key": value), NaN when absent. */
static double json_num(const char *j, const char *key)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(j, k);
    return p ? strtod(p + strlen(k), NULL) : NAN;
}

static void peers(FILE *o, const char *tmp, const char *file, const double *lx_u)
{
    const char *py = getenv("LX_PEERS_PYTHON");
    if (!py || !*py) py = "python3";
    char script[1024], cmd[4096], res[1024], line[2048] = "";
    if (!peer_script(script, sizeof script)) {
        fprintf(o, "luxpy: src/cli/bench/unc_peers.py not found (LX_BENCH_SCRIPTS names its folder)\n\n");
        return;
    }
    snprintf(res, sizeof res, "%s/unc_peer.json", tmp);
    fprintf(o, "luxpy doing the same trials (%s, `%s`): numpy draws N spectra of the same model, luxpy 1.12.5 "
               "integrates them, solves CCT and Duv and computes Ra and Rf over all of them at once; the whole "
               "process, one run.\n\n", py, "src/cli/bench/unc_peers.py");
    fprintf(o, "| peer job | trials | wall s | CPU s | of which import s | per 10^5 trials s | u(CCT) K | u(Y)/Y | u(Ra) | u(Rf) |\n"
               "|---|---|---|---|---|---|---|---|---|---|\n");
    static const struct {
        const char *what;
        size_t n;
    } jobs[2] = {{"xyz", 100000}, {"cri", 1000}};
    for (int k = 0; k < 2; k++) {
        snprintf(cmd, sizeof cmd, "'%s' '%s' '%s' %zu %s", py, script, file, jobs[k].n, jobs[k].what);
        double w, c;
        line[0] = 0;
        if (run_cmd(cmd, res, &w, &c) == 0) {
            FILE *f = fopen(res, "r");
            if (f) {
                if (!fgets(line, sizeof line, f)) line[0] = 0;
                fclose(f);
            }
        }
        if (!line[0]) {
            fprintf(o, "| %s | %zu | failed or luxpy not installed | | | | | | | |\n", jobs[k].what, jobs[k].n);
            continue;
        }
        double imp = json_num(line, "import_s"), work = json_num(line, "total_s") - imp;
        fprintf(o, "| %s | %zu | %.2f | %.2f | %.2f | %.1f | %.3f | %.5f | %.3f | %.3f |\n",
                k ? "X, Y, Z, CCT, Duv, Ra, Rf" : "X, Y, Z, x, y, CCT, Duv", jobs[k].n, w, c, imp,
                work * 1e5 / (double)jobs[k].n, json_num(line, "u_cct_K"), json_num(line, "u_Y_rel"), json_num(line, "u_ra"),
                json_num(line, "u_rf"));
    }
    fprintf(o, "| luxcalc, the same model (10^5 trials) | 100000 | | | | | %.3f | %.5f | %.3f | %.3f |\n\n", lx_u[0], lx_u[1],
            lx_u[2], lx_u[3]);
    fprintf(o, "The uncertainties agree within the trials' sampling error (about 0.5 %% of u at 10^5 trials, 2 %% at "
               "10^3): the same model, independently drawn and computed. luxpy has no GUM and no adaptive procedure.\n\n");
}

int cli_bench_uncertainty(FILE *o, const char *tmp)
{
    double lam[401], v[401];
    spectrum(lam, v);
    char file[1024], self[1024];
    snprintf(file, sizeof file, "%s/unc_led.csv", tmp);
    FILE *f = fopen(file, "w");
    if (!f) return CLI_RUNTIME;
    fprintf(f, "# a white LED for luxcalc bench uncertainty\n");
    for (int i = 0; i < 401; i++) fprintf(f, "%g,%.17g\n", lam[i], v[i]);
    fclose(f);
    ssize_t sl = readlink("/proc/self/exe", self, sizeof self - 1);
    if (sl <= 0) return CLI_RUNTIME;
    self[sl] = 0;
    fprintf(o, "## Uncertainty of one spectrum: Monte Carlo, GUM, luxpy\n\n");
    fprintf(o, "A white LED, 401 samples (380-780 nm at 1 nm), model `%s` (1 %% uncorrelated, a 2 %% scale, a "
               "0.2 nm wavelength shift). End to end: the whole `luxcalc spd` process, median of 3 runs (1 for "
               "Ra and Rf); CPU s is the process's CPU time on every core, so CPU s / 2 is what 2 cores of their own "
               "take whatever else the machine runs.\n\n", SPEC);
    fprintf(o, "| job | command | wall s | CPU s | on 2 free cores s | goal | met |\n|---|---|---|---|---|---|---|\n");
    cli_row(o, self, "--uncertainty '" SPEC "' --trials 100000 --format csv", file, 3,
            "Monte Carlo 10^5 trials: X, Y, Z, x, y, u'v', CCT, Duv, LER, S/P", "< 2 s", 2.0);
    cli_row(o, self, "--uncertainty '" SPEC "' --trials 100000 --metrics cri_ra,tm30_rf --format csv", file, 1,
            "the same with Ra (R1-R14) and Rf (Rg)", "< 20 s", 20.0);
    cli_row(o, self, "--uncertainty '" SPEC "' --uncertainty-method gum --format csv", file, 3, "GUM, the colorimetry",
            "< 50 ms", 0.05);
    cli_row(o, self, "--uncertainty '" SPEC "' --uncertainty-method gum --metrics cri_ra,tm30_rf --format csv", file, 3,
            "GUM with Ra and Rf (central differences)", "-", 1e9);
    cli_row(o, self, "--uncertainty '" SPEC "' --digits 1 --format csv", file, 1,
            "Monte Carlo, adaptive (JCGM 101 7.9, 1 digit), the colorimetry", "-", 1e9);
    fprintf(o, "\n");

    lx_ctx *ctx = NULL;
    lx_unc_model *m = NULL;
    if (lx_ctx_create(&ctx) != LX_OK || lx_unc_model_parse(ctx, SPEC, NULL, &m) != LX_OK) {
        lx_ctx_destroy(ctx);
        return CLI_RUNTIME;
    }
    lx_spd s = {"led", 401, lam, v};
    fprintf(o, "In the library (lx_spd_uncertainty, one call, every core): where the time goes.\n\n");
    fprintf(o, "| job | trials | total s | GUM s | Monte Carlo s | of which drawing s | normal draws a trial |\n"
               "|---|---|---|---|---|---|---|\n");
    lib_row(o, ctx, &s, m, LX_UNC_GUM, 0, LX_UNC_COLORIMETRY, "GUM, colorimetry");
    lib_row(o, ctx, &s, m, LX_UNC_GUM, 0, LX_UNC_COLORIMETRY | LX_UNC_CRI | LX_UNC_TM30, "GUM, with Ra and Rf");
    lib_row(o, ctx, &s, m, LX_UNC_MC, 100000, LX_UNC_COLORIMETRY, "Monte Carlo, colorimetry");
    lib_row(o, ctx, &s, m, LX_UNC_MC, 10000, LX_UNC_COLORIMETRY | LX_UNC_CRI | LX_UNC_TM30, "Monte Carlo, with Ra and Rf");
    lib_row(o, ctx, &s, m, LX_UNC_BOTH, 100000, LX_UNC_COLORIMETRY | LX_UNC_ALPHAOPIC | LX_UNC_PAR,
            "both and the validation, colorimetry, alpha-opic, PAR");
    fprintf(o, "\n");

    /* the backend rule: drawing the trials of the CRI's 50 integrals on each backend */
    fprintf(o, "Drawing the trials (the integrals of the colorimetry and CIE 13.3: K = 50, 52 deviates a trial) on "
               "the CPU and on OpenCL; the rule (src/core/backend.c) keeps a CPU-type device off and picks OpenCL "
               "from 2e11 multiply-adds (trials x K x deviates) on a cold context, 5e9 warm.\n\n");
    fprintf(o, "| trials | multiply-adds | CPU s | OpenCL cold s | OpenCL warm s |\n|---|---|---|---|---|\n");
    static const size_t ns[3] = {10000, 30000, 100000};
    for (int k = 0; k < 3; k++) {
        char why[512] = "";
        double c = draw_s(&s, m, ns[k], LX_BACKEND_CPU, 0, why, sizeof why);
        double oc = draw_s(&s, m, ns[k], LX_BACKEND_OPENCL, 0, why, sizeof why);
        double ow = draw_s(&s, m, ns[k], LX_BACKEND_OPENCL, 1, why, sizeof why);
        if (isnan(oc)) fprintf(o, "| %zu | %.3g | %.4f | unavailable: %s | |\n", ns[k], (double)ns[k] * 50 * 52, c, why);
        else fprintf(o, "| %zu | %.3g | %.4f | %.4f | %.4f |\n", ns[k], (double)ns[k] * 50 * 52, c, oc, ow);
    }
    fprintf(o, "\n");

    /* the same model's uncertainties, for the peers' table */
    double lu[4] = {NAN, NAN, NAN, NAN};
    lx_unc_opts opt = {.trials = 100000, .quantities = LX_UNC_COLORIMETRY | LX_UNC_CRI | LX_UNC_TM30};
    lx_unc_result *r = NULL;
    if (lx_spd_uncertainty(ctx, &s, m, &opt, &r) == LX_OK) {
        lu[0] = r->q[LX_UQ_CCT].u, lu[1] = r->q[LX_UQ_Y].u / r->q[LX_UQ_Y].value;
        lu[2] = r->q[LX_UQ_RA].u, lu[3] = r->q[LX_UQ_RF].u;
    }
    lx_unc_result_free(r);
    peers(o, tmp, file, lu);
    lx_unc_model_free(m);
    lx_ctx_destroy(ctx);
    remove(file);
    return CLI_OK;
}
