/* bench_daylight.c - the `luxcalc bench daylight` topic: the daylight factor's accuracy against
 * time. A 10 x 6 x 3 m room (ceiling 0.8, walls 0.5, floor 0.2) with two 2.5 x 1.6 m clear-glazed
 * windows in one long wall, the traditional CIE overcast sky with a ground of 0.2, a 0.25 m
 * work-plane grid, computed at interreflection_tolerance 1e-1 ... 1e-3 (the default) on the CPU:
 * the error of the mean daylight factor and of the worst point against a converged reference
 * (patch 0.18 m, tolerance 1e-5), the time (plan and evaluation), patches and memory. */
#include "cli/cli.h"
#include "bench_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>



static void scene_text(char *buf, size_t n, const char *tol, const char *extra)
{
    snprintf(buf, n,
             "[scene]\ninterreflection_tolerance = %s\n%s\n"
             "[room hall]\nsize = 10, 6, 3 m\nceiling = 0.8\nwalls = 0.5\nfloor = 0.2\n"
             "[opening w1]\ncorner = 1.5, 0, 0.9 m\nedge1 = 2.5, 0, 0 m\nedge2 = 0, 0, 1.6 m\nglazing = clear\n"
             "[opening w2]\ncorner = 6, 0, 0.9 m\nedge1 = 2.5, 0, 0 m\nedge2 = 0, 0, 1.6 m\nglazing = clear\n"
             "[sky]\ntype = overcast\nluminance = 10000 cd/m2\nground_reflectance = 0.2\n"
             "[receiver workplane]\ntype = grid\nx = 0.5 m, 9.5 m\ny = 0.5 m, 5.5 m\nz = 0.85 m\nspacing = 0.25 m\n",
             tol, extra);
}

typedef struct day_run {
    double seconds, seconds_daylight, *df, mean;
    size_t n, patches, elements;
    double memory;
} day_run;

static lx_status run_day(lx_ctx *ctx, const char *tol, const char *extra, day_run *out)
{
    char text[4096];
    scene_text(text, sizeof text, tol, extra);
    memset(out, 0, sizeof *out);
    lx_scene *sc = NULL;
    lx_scene_plan *plan = NULL;
    lx_scene_result *res = NULL;
    double t0 = cli_bench_now_s();
    lx_status st = lx_scene_read_mem(ctx, "bench_daylight.scene", text, strlen(text), &sc);
    if (st == LX_OK) st = lx_scene_plan_make(ctx, sc, LX_BACKEND_CPU, &plan);
    if (st == LX_OK) st = lx_scene_eval(ctx, sc, plan, NULL, &res);
    out->seconds = cli_bench_now_s() - t0;
    if (st == LX_OK && res->daylight_factor) {
        out->n = res->n_points;
        out->df = malloc(out->n * sizeof *out->df);
        for (size_t i = 0; out->df && i < out->n; i++) out->df[i] = res->daylight_factor[i], out->mean += out->df[i] / (double)out->n;
        out->patches = plan->room.n_patches;
        out->elements = plan->room.n_elements;
        out->memory = plan->room.memory_bytes;
        out->seconds_daylight = res->daylight.seconds;
    }
    lx_scene_result_free(res);
    lx_scene_plan_free(plan);
    lx_scene_free(sc);
    return st;
}

static void errors(const day_run *r, const day_run *ref, double *mean_err, double *worst)
{
    double w = 0;
    for (size_t i = 0; i < r->n; i++) w = fmax(w, fabs(r->df[i] - ref->df[i]) / fabs(ref->df[i]));
    *mean_err = fabs(r->mean - ref->mean) / fabs(ref->mean);
    *worst = w;
}

int cli_bench_daylight(FILE *out)
{
    lx_ctx *ctx = cli_ctx("bench");
    if (!ctx) return CLI_RUNTIME;
    fprintf(out, "## daylight: the daylight factor, accuracy against time\n\n"
                 "A 10 x 6 x 3 m room (ceiling 0.8, walls 0.5, floor 0.2), two 2.5 x 1.6 m windows with clear glass "
                 "(CIE 171 6 mm) in one long wall, sill 0.9 m; the traditional CIE overcast sky, ground reflectance 0.2; "
                 "a 0.25 m grid at 0.85 m, 0.5 m from the walls (777 points). The sky component is exact (closed "
                 "form); the errors, of the mean daylight factor and of the worst point, are the interreflected "
                 "part's, relative to the reference below. Seconds: plan and evaluation together (the daylight's own "
                 "part in brackets), CPU.\n\n");
    day_run ref, chk;
    lx_status st = run_day(ctx, "1e-5", "patch_size = 0.18 m", &ref);
    if (st != LX_OK || !ref.df) {
        fprintf(out, "reference failed: %s\n\n", lx_ctx_errmsg(ctx));
        free(ref.df);
        lx_ctx_destroy(ctx);
        return CLI_RUNTIME;
    }
    fprintf(out, "reference: patch 0.18 m, tolerance 1e-5, %zu patches, %zu elements, mean DF %.4f %%, %.1f s", ref.patches,
            ref.elements, ref.mean, ref.seconds);
    if (run_day(ctx, "1e-5", "patch_size = 0.22 m", &chk) == LX_OK && chk.df) {
        double me, w;
        errors(&chk, &ref, &me, &w);
        fprintf(out, "; the same at 0.22 m differs from it by %.1e (mean), %.1e (worst point): the reference's own "
                     "error is below these\n\n",
                me, w);
    } else
        fprintf(out, "\n\n");
    free(chk.df);
    fprintf(out, "| tolerance | patches | elements | memory MiB | s | mean DF %% | mean error | worst-point error | load (1 min) |\n"
                 "|---|---|---|---|---|---|---|---|---|\n");
    static const char *const tols[] = {"1e-1", "1e-2", "3e-3", "1e-3"};
    for (int k = 0; k < 4; k++) {
        day_run r;
        st = run_day(ctx, tols[k], "", &r);
        if (st != LX_OK || !r.df) {
            char msg[200];
            snprintf(msg, sizeof msg, "%s", lx_ctx_errmsg(ctx));
            for (char *p = msg; *p; p++)
                if (*p == '|') *p = '/';
            fprintf(out, "| %s | | | | | | refused: %s | | %.2f |\n", tols[k], msg, cli_bench_load1());
            free(r.df);
            continue;
        }
        double me, w;
        errors(&r, &ref, &me, &w);
        fprintf(out, "| %s%s | %zu | %zu | %.1f | %.2f (%.2f) | %.4f | %.1e | %.1e | %.2f |\n", tols[k],
                k == 3 ? " (default)" : "", r.patches, r.elements, r.memory / 1048576.0, r.seconds, r.seconds_daylight, r.mean,
                me, w, cli_bench_load1());
        fflush(out);
        free(r.df);
    }
    fprintf(out, "\n");
    free(ref.df);
    lx_ctx_destroy(ctx);
    return CLI_OK;
}
