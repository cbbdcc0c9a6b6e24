/* bench_room.c - the `luxcalc bench room` topic: interreflection accuracy against time. A
 * 10 x 6 x 3 m room (ceiling 0.8, walls 0.5, floor 0.2), 8 IES downlights, a desk and a 0.25 m
 * work-plane grid, computed at interreflection_tolerance 1e-1 ... 1e-4 on the CPU and OpenCL:
 * the error of the work-plane mean and of the worst point against a converged reference (patch
 * 0.2 m, tolerance 1e-5), the time (plan and evaluation), patches and memory. */
#include "cli/cli.h"
#include "bench_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>



/* The scene; `extra`: more [scene] keys. Named in samples/scenes so its IES path resolves. */
static void scene_text(char *buf, size_t n, const char *tol, const char *extra)
{
    int k = snprintf(buf, n,
                     "[scene]\ninterreflection_tolerance = %s\n%s\n"
                     "[room hall]\nsize = 10, 6, 3 m\nceiling = 0.8\nwalls = 0.5\nfloor = 0.2\n"
                     "[obstruction desk]\nmin = 4.2, 2.6, 0 m\nmax = 5.8, 3.4, 0.75 m\nreflectance = 0.3\n",
                     tol, extra);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 2; j++)
            k += snprintf(buf + k, n - (size_t)k,
                          "[luminaire dl%d%d]\ntype = file\nfile = ../ies/downlight_lambert_1000lm.ies\n"
                          "position = %g, %g, 3 m\nflux = 3000 lm\n",
                          i, j, 1.25 + 2.5 * i, 1.5 + 3 * j);
    snprintf(buf + k, n - (size_t)k,
             "[receiver workplane]\ntype = grid\nx = 0.5 m, 9.5 m\ny = 0.5 m, 5.5 m\nz = 0.8 m\nspacing = 0.25 m\n");
}

typedef struct room_run {
    double seconds, *E;
    size_t n, patches, elements;
    double memory;
    int backend;
} room_run;

static lx_status run_room(lx_ctx *ctx, const char *tol, const char *extra, lx_backend backend, room_run *out)
{
    char text[8192];
    scene_text(text, sizeof text, tol, extra);
    memset(out, 0, sizeof *out);
    lx_scene *sc = NULL;
    lx_scene_plan *plan = NULL;
    lx_scene_result *res = NULL;
    double t0 = cli_bench_now_s();
    lx_status st = lx_scene_read_mem(ctx, "samples/scenes/bench_room.scene", text, strlen(text), &sc);
    if (st == LX_OK) st = lx_scene_plan_make(ctx, sc, backend, &plan);
    if (st == LX_OK) st = lx_scene_eval(ctx, sc, plan, NULL, &res);
    out->seconds = cli_bench_now_s() - t0;
    if (st == LX_OK) {
        out->n = res->n_points;
        out->E = malloc(out->n * sizeof *out->E);
        if (out->E) memcpy(out->E, res->E_lx, out->n * sizeof *out->E);
        out->patches = plan->room.n_patches;
        out->elements = plan->room.n_elements;
        out->memory = plan->room.memory_bytes;
        out->backend = res->room.backend;
    }
    lx_scene_result_free(res);
    lx_scene_plan_free(plan);
    lx_scene_free(sc);
    return st;
}

static void errors(const room_run *r, const room_run *ref, double *mean_err, double *worst)
{
    double m = 0, mr = 0, w = 0;
    for (size_t i = 0; i < r->n; i++) {
        m += r->E[i];
        mr += ref->E[i];
        w = fmax(w, fabs(r->E[i] - ref->E[i]) / fabs(ref->E[i]));
    }
    *mean_err = fabs(m - mr) / fabs(mr);
    *worst = w;
}

int cli_bench_room(FILE *out)
{
    lx_ctx *ctx = cli_ctx("bench");
    if (!ctx) return CLI_RUNTIME;
    fprintf(out, "## room: interreflection, accuracy against time\n\n"
                 "A 10 x 6 x 3 m room (ceiling 0.8, walls 0.5, floor 0.2), 8 IES downlights of 3000 lm, a 1.6 x 0.8 m "
                 "desk, a 0.25 m work-plane grid at 0.8 m (777 points). Errors of the work-plane mean and of the "
                 "worst point are relative to the reference below; seconds are plan and evaluation together.\n\n");
    room_run ref, chk;
    lx_status st = run_room(ctx, "1e-5", "patch_size = 0.2 m", LX_BACKEND_CPU, &ref);
    if (st != LX_OK || !ref.E) {
        fprintf(out, "reference failed: %s (run from the source tree: the scene reads samples/ies)\n\n",
                lx_ctx_errmsg(ctx));
        lx_ctx_destroy(ctx);
        return CLI_RUNTIME;
    }
    fprintf(out, "reference: patch 0.2 m, tolerance 1e-5, %zu patches, %zu elements, %.1f s (CPU)", ref.patches,
            ref.elements, ref.seconds);
    if (run_room(ctx, "1e-5", "patch_size = 0.28 m", LX_BACKEND_CPU, &chk) == LX_OK && chk.E) {
        double me, w;
        errors(&chk, &ref, &me, &w);
        fprintf(out, "; the same at 0.28 m differs from it by %.1e (mean), %.1e (worst point): the reference's own "
                     "error is below these\n\n",
                me, w);
    } else
        fprintf(out, "\n\n");
    free(chk.E);
    fprintf(out, "| tolerance | backend | patches | elements | memory MiB | s | mean error | worst-point error | load (1 min) |\n"
                 "|---|---|---|---|---|---|---|---|---|\n");
    static const char *const tols[] = {"1e-1", "1e-2", "1e-3", "1e-4"};
    for (int b = 0; b < 2; b++)
        for (int k = 0; k < 4; k++) {
            room_run r;
            lx_backend be = b ? LX_BACKEND_OPENCL : LX_BACKEND_CPU;
            st = run_room(ctx, tols[k], "", be, &r);
            if (st != LX_OK || !r.E) {
                char msg[200];
                snprintf(msg, sizeof msg, "%s", lx_ctx_errmsg(ctx));
                for (char *p = msg; *p; p++)
                    if (*p == '|') *p = '/';
                fprintf(out, "| %s | %s | | | | | refused: %s | | %.2f |\n", tols[k], b ? "opencl" : "cpu", msg, cli_bench_load1());
                fflush(out);
                free(r.E);
                continue;
            }
            double me, w;
            errors(&r, &ref, &me, &w);
            fprintf(out, "| %s | %s | %zu | %zu | %.1f | %.2f | %.1e | %.1e | %.2f |\n", tols[k],
                    r.backend == LX_BACKEND_OPENCL ? "opencl" : "cpu", r.patches, r.elements, r.memory / 1048576.0,
                    r.seconds, me, w, cli_bench_load1());
            fflush(out);
            free(r.E);
        }
    fprintf(out, "\n");
    free(ref.E);
    lx_ctx_destroy(ctx);
    return CLI_OK;
}
