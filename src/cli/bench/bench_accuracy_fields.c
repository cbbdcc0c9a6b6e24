/* bench_accuracy_fields.c - `luxcalc bench accuracy`, radiance fields and lighting: irradiance
 * methods against brute force at full resolution; point model and near-field subdivision against
 * the closed-form area sources; intensity-table interpolation against the analytic Warn lobe. */
#include "cli/cli.h"
#include "bench_accuracy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---- radiance fields ---- */

/* A 1-channel sky, W x W/2: (0.6 + 1.4 z)(1 + 0.3 x) above the horizon, 0.2 below; with sun, a
 * sun at elevation 35 deg, azimuth 60 deg whose normal irradiance is 5 x the sky's horizontal
 * irradiance, put into the one pixel holding its direction (radiance = irradiance / pixel sr). */
static lx_envmap *sky(lx_ctx *ctx, int W, int sun)
{
    int H = W / 2;
    lx_envmap *m = NULL;
    if (lx_envmap_create(ctx, W, H, 1, &m)) return NULL;
    double eh = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double d[3];
            lx_envmap_direction(W, H, j + 0.5, i + 0.5, d);
            double v = d[2] > 0 ? (0.6 + 1.4 * d[2]) * (1 + 0.3 * d[0]) : 0.2;
            m->data[(size_t)j * W + i] = (float)v;
            if (d[2] > 0) {
                double mm[3];
                lx_envmap_pixel_moment(W, H, j, i, mm);
                eh += v * mm[2];
            }
        }
    if (sun) {
        double el = 35 * PI / 180, az = 60 * PI / 180;
        double th = PI / 2 - el;
        int j = (int)(th / PI * H), i = (int)(az / (2 * PI) * W);
        m->data[(size_t)j * W + i] += (float)(5 * eh / lx_envmap_pixel_sr(W, H, j));
    }
    return m;
}

typedef struct irr_job {
    lx_ctx *ctx;
    const lx_envmap *map;
    int down;          /* brute on a map downsampled by this factor (1: none) */
    int one;           /* one call per normal (the cost rule then sees a single output) */
    lx_irr_opts opts;
    size_t n;
    const double *dirs;
    double *out;
    int ok;
} irr_job;

static void irr_run(void *arg)
{
    irr_job *j = arg;
    lx_irr_opts o = j->opts;
    if (j->down > 1) {
        lx_envmap *d = NULL;
        j->ok = lx_envmap_downsample(j->ctx, j->map, j->map->width / j->down, j->map->height / j->down, &d) == LX_OK &&
                lx_irradiance_dirs(j->ctx, d, j->n, j->dirs, &o, j->out) == LX_OK;
        lx_envmap_free(d);
    } else if (j->one) {
        j->ok = 1;
        for (size_t k = 0; k < j->n && j->ok; k++)
            j->ok = lx_irradiance_dirs(j->ctx, j->map, 1, j->dirs + 3 * k, &o, j->out + k) == LX_OK;
    } else {
        j->ok = lx_irradiance_dirs(j->ctx, j->map, j->n, j->dirs, &o, j->out) == LX_OK;
    }
}

int acc_radiance(lx_ctx *ctx, FILE *o, const char *png)
{
    enum { W = 512, DW = 48, DH = 24, NMETH = 12 };
    size_t nd = (size_t)DW * DH;
    double *dirs = malloc(nd * 3 * sizeof *dirs), *ref = malloc(nd * sizeof *ref), *got = malloc(nd * sizeof *got);
    if (!dirs || !ref || !got) return CLI_RUNTIME;
    for (int j = 0; j < DH; j++)
        for (int i = 0; i < DW; i++) lx_envmap_direction(DW, DH, j + 0.5, i + 0.5, dirs + 3 * ((size_t)j * DW + i));
    static const char *names0[NMETH] = {"SH9", "SH9 windowed (1, 6/7, 32/35)", "brute force, 1/2 res.", "brute force, 1/4 res.",
                                       "brute force, 1/8 res.", "brute force, 1/16 res.", "brute force, 1/32 res.",
                                       "exact fast path (row prefix sums)", "brute force, full res. (CPU, the reference)",
                                       "brute force, full res. (OpenCL)", "default (auto), all normals in one call",
                                       "default (auto), one normal per call"};
    char names[NMETH][160];
    for (int m = 0; m < NMETH; m++) snprintf(names[m], sizeof names[m], "%s", names0[m]);
    static const char *labels[NMETH] = {"SH9", "SH9 windowed", "brute 1/2", "brute 1/4", "brute 1/8", "brute 1/16",
                                        "brute 1/32", "fast", "brute", "brute CL", "auto", "auto, 1 per call"};
    double emax[2][NMETH], erms[2][NMETH], tt[2][NMETH];
    fprintf(o, "## bench accuracy: radiance fields\n\n");
    fprintf(o, "Irradiance E(n) for %zu normals (a %dx%d lat-long set of directions) from a %dx%d one-channel map: a smooth "
               "sky (gradient, 0.2 below the horizon) and the same sky with a sun (one pixel, normal irradiance 5x the "
               "sky's horizontal irradiance). Reference: brute force at full resolution on the CPU: every pixel's exact "
               "first moment, sum L max(0, n . m), the pixels the receiver's horizon crosses integrated exactly over "
               "their lit part (the map as piecewise-constant radiance, to rounding). The fast path is exact in the "
               "same sense. `default (auto)` is what `lx_irr_opts.method = LX_IRR_AUTO` (the CLI's default) runs: the "
               "fast path unless its estimated cost exceeds 10 x SH9's for the job (the projection of the whole map "
               "counts against SH9 once per call, so many normals in one call pick SH9, one normal per call picks "
               "the fast path). Errors |dE|/E over all normals (max and RMS); time for all normals "
               "(downsampling included), median of 5.\n\n", nd, DW, DH, W, W / 2);
    for (int s = 0; s < 2; s++) {
        lx_envmap *map = sky(ctx, W, s);
        if (!map) return cli_fail("bench", ctx, LX_ENOMEM);
        irr_job rj = {ctx, map, 1, 0, {.method = LX_IRR_BRUTE, .backend = LX_BACKEND_CPU}, nd, dirs, ref, 0};
        irr_run(&rj);
        if (!rj.ok) return cli_fail("bench", ctx, LX_EINVAL);
        for (int m = 0; m < NMETH; m++) {
            irr_job j = {ctx, map, 1, 0, {0}, nd, dirs, got, 0};
            if (m == 0 || m == 1) j.opts.method = LX_IRR_SH9, j.opts.window = m ? LX_SH9_WINDOW_NONNEG : LX_SH9_WINDOW_NONE;
            else if (m <= 6) j.opts.method = LX_IRR_BRUTE, j.opts.backend = LX_BACKEND_CPU, j.down = 1 << (m - 1);
            else if (m == 7) j.opts.method = LX_IRR_FAST;
            else if (m <= 9) j.opts.method = LX_IRR_BRUTE, j.opts.backend = m == 8 ? LX_BACKEND_CPU : LX_BACKEND_OPENCL;
            else j.opts.method = LX_IRR_AUTO, j.one = m == 11;
            irr_run(&j);
            if (m >= 10 && j.ok && s == 0) { /* what the cost rule picked (the same for both skies) */
                double ratio;
                lx_irr_method used = lx_ctx_irradiance_method(ctx, &ratio);
                snprintf(names[m], sizeof names[m], "%s: ran %s (fast / SH9 cost estimated %.3g)", names0[m],
                         used == LX_IRR_FAST ? "fast" : used == LX_IRR_SH9 ? "SH9" : "brute force", ratio);
            }
            emax[s][m] = erms[s][m] = tt[s][m] = NAN;
            if (!j.ok) continue;
            tt[s][m] = acc_time(irr_run, &j, 1000);
            double mx = 0, ss = 0;
            for (size_t k = 0; k < nd; k++) {
                double e = fabs(got[k] - ref[k]) / ref[k];
                mx = fmax(mx, e);
                ss += e * e;
            }
            emax[s][m] = mx;
            erms[s][m] = sqrt(ss / (double)nd);
        }
        lx_envmap_free(map);
    }
    fprintf(o, "| method | time (smooth) | max \\|dE\\|/E smooth | RMS smooth | time (sun) | max \\|dE\\|/E sun | RMS sun |\n"
               "|---|---|---|---|---|---|---|\n");
    for (int m = 0; m < NMETH; m++) {
        if (isnan(tt[0][m]) && isnan(tt[1][m])) {
            fprintf(o, "| %s | not available (%s) | | | | | |\n", names[m], m == 9 ? "no OpenCL device" : "failed");
            continue;
        }
        fprintf(o, "| %s |", names[m]);
        for (int s = 0; s < 2; s++) {
            char a[32], b[32], c[32];
            acc_fmt_time(a, sizeof a, tt[s][m]);
            acc_fmt_err(b, sizeof b, emax[s][m]);
            acc_fmt_err(c, sizeof c, erms[s][m]);
            fprintf(o, " %s | %s | %s |", a, b, c);
        }
        fprintf(o, "\n");
    }
    fprintf(o, "\n");
    if (png) {
        lx_plot_point pts[2 * NMETH];
        int np = 0;
        for (int s = 0; s < 2; s++)
            for (int m = 0; m < NMETH; m++)
                if (!isnan(tt[s][m]) && m != 8) pts[np++] = (lx_plot_point){tt[s][m], emax[s][m], labels[m], s};
        static const char *series[2] = {"smooth sky", "sky with sun"};
        if (lx_error_time_write_png(ctx, png, "Radiance: max |\u0394E| / E against brute force at full resolution",
                                    "time for 1152 normals (s)", "max |\u0394E| / E",
                              (size_t)np, pts, 2, series))
            return cli_fail("bench", ctx, LX_EIO);
    }
    free(dirs);
    free(ref);
    free(got);
    return CLI_OK;
}

/* ---- lighting ---- */

typedef struct src_job {
    lx_ctx *ctx;
    int rect;
    double d;
    lx_model model;
    lx_source_result r;
} src_job;

static void src_run(void *arg)
{
    src_job *j = arg;
    if (j->rect) lx_rect_illuminance(j->ctx, 1000, 1, 1, j->d, 0, 0, j->model, &j->r);
    else lx_disk_illuminance(j->ctx, 1000, 0.5, j->d, 0, j->model, &j->r);
}

typedef struct grid_job {
    lx_ctx *ctx;
    const lx_placement *pl;
    size_t m, n;
    const double *pts;
    lx_grid_opts opts;
    double *E;
    int ok;
} grid_job;

static void grid_run(void *arg)
{
    grid_job *j = arg;
    lx_grid_opts o = j->opts;
    static const double up[3] = {0, 0, 1};
    j->ok = lx_grid_illuminance(j->ctx, j->pl, j->m, j->pts, j->n, up, 1, &o, j->E) == LX_OK;
}

/* (a) The point model against the closed-form disk and rectangle on the axis, by d / size; one plot
 * point per distance into pts (series 0). */
static void lighting_point(lx_ctx *ctx, FILE *o, lx_plot_point *pts, int *np)
{
    char a[32], b[32];
    static const double ratio[8] = {0.25, 0.5, 1, 2, 3, 5, 10, 20};
    static const char *rl[8] = {"0.25", "0.5", "1", "2", "3", "5", "10", "20"};
    fprintf(o, "Point model against the exact area source (closed-form configuration factors, `lx_disk_illuminance` / "
               "`lx_rect_illuminance`), receiver on the axis, parallel, at distance d; size: the disk's diameter (1 m), "
               "the square's diagonal (1 x 1 m). Signed error point/exact - 1. Time per call (each call computes both "
               "models; the result's near_field flag is set where |point error| > 1e-4, the default model is the "
               "closed form at every distance).\n\n");
    fprintf(o, "| d / size | disk: point error | rectangle: point error | time exact (disk) | time point (disk) |\n|---|---|---|---|---|\n");
    for (int k = 0; k < 8; k++) {
        src_job dj = {.ctx = ctx, .rect = 0, .d = ratio[k] * 1.0, .model = LX_MODEL_EXACT};
        src_job rj = {.ctx = ctx, .rect = 1, .d = ratio[k] * sqrt(2.0), .model = LX_MODEL_EXACT};
        double te = acc_time(src_run, &dj, 1000000);
        dj.model = LX_MODEL_POINT;
        double tp = acc_time(src_run, &dj, 1000000);
        src_run(&rj);
        acc_fmt_time(a, sizeof a, te);
        acc_fmt_time(b, sizeof b, tp);
        fprintf(o, "| %s | %+.3e | %+.3e | %s | %s |\n", rl[k], dj.r.point_error, rj.r.point_error, a, b);
        char *lab = malloc(24);
        snprintf(lab, 24, "d/size %s", rl[k]);
        pts[(*np)++] = (lx_plot_point){tp, fabs(dj.r.point_error), lab, 0};
    }
    fprintf(o, "\n");
}

/* (b) Near-field subdivision of a Lambertian panel into k x k point cells, auto and area, against
 * the closed-form rectangle; one plot point per row into pts (series 1). A CLI exit code. */
static int lighting_cells(lx_ctx *ctx, FILE *o, lx_plot_point *pts, int *np)
{
    char a[32], b[32];
    /* a 0.6 x 0.6 m Lambertian panel (1000 lm) 0.3 m above the plane */
    const double F = 1000, A = 0.6, h = 0.3;
    const double Lum = F / (PI * A * A);
    enum { NP = 21 };
    double *P = malloc(NP * NP * 3 * sizeof *P), *E = malloc(NP * NP * sizeof *E), *Ex = malloc(NP * NP * sizeof *Ex);
    for (int j = 0; j < NP; j++)
        for (int i = 0; i < NP; i++) {
            double *p = P + 3 * (j * NP + i);
            p[0] = -0.6 + 1.2 * i / (NP - 1), p[1] = -0.6 + 1.2 * j / (NP - 1), p[2] = 0;
            lx_source_result r;
            lx_rect_illuminance(ctx, Lum, A, A, h, p[0], p[1], LX_MODEL_EXACT, &r);
            Ex[j * NP + i] = r.exact_lx;
        }
    fprintf(o, "Near-field subdivision: a %.1f x %.1f m Lambertian panel of %.0f lm facing down, %.1f m above a %dx%d grid "
               "of points over 1.2 x 1.2 m (d / size 0.35 to 0.9); the panel cut into k x k cells, each a point source "
               "(`lx_grid_illuminance`, point model, one placement per cell), against the closed-form rectangle at every "
               "point. The intensity table is the Lambertian model sampled every 0.25 deg (interpolation error ~2e-6). "
               "`auto` is the library's default (`LX_MODEL_AUTO`, tolerance 1e-4): the point model's error estimated per "
               "pair, and the opening integrated (2, 4, 8 ... cells per side, to the tolerance) where the estimate asks for "
               "it, here at every point; `area` integrates every pair. Max |dE|/E over the points; time per point.\n\n", A, A, F, h, NP, NP);
    fprintf(o, "| cells | max \\|dE\\|/E | time per point |\n|---|---|---|\n");
    static const int ks[8] = {1, 2, 4, 8, 16, 32, 0, -1};
    for (int q = 0; q < 8; q++) {
        int k = ks[q] > 0 ? ks[q] : 0, area = ks[q] < 0;
        lx_lum_model mdl = {.kind = LX_LUM_MODEL_LAMBERT, .flux_lm = k ? F / (k * k) : F, .step_deg = 0.25};
        if (!k) mdl.width_m = mdl.length_m = A;
        lx_luminaire *lum = NULL;
        if (lx_luminaire_from_model(ctx, &mdl, &lum)) return cli_fail("bench", ctx, LX_EINVAL);
        int m = k ? k * k : 1;
        lx_placement *pl = calloc((size_t)m, sizeof *pl);
        for (int u = 0; u < (k ? k : 1); u++)
            for (int v = 0; v < (k ? k : 1); v++) {
                lx_placement *x = &pl[u * (k ? k : 1) + v];
                x->lum = lum;
                x->pos_m[0] = k ? (-0.5 + (u + 0.5) / k) * A : 0;
                x->pos_m[1] = k ? (-0.5 + (v + 0.5) / k) * A : 0;
                x->pos_m[2] = h;
                x->aim[2] = -1;
            }
        grid_job gj = {ctx, pl, (size_t)m, NP * NP, P, {.model = k ? LX_MODEL_POINT : area ? LX_MODEL_AREA : LX_MODEL_AUTO, .backend = LX_BACKEND_CPU, .threads = 1}, E, 0};
        grid_run(&gj);
        if (!gj.ok) return cli_fail("bench", ctx, LX_EINVAL);
        double t = acc_time(grid_run, &gj, 10000) / (NP * NP), mx = 0;
        for (int i = 0; i < NP * NP; i++) mx = fmax(mx, fabs(E[i] / Ex[i] - 1));
        acc_fmt_err(a, sizeof a, mx);
        acc_fmt_time(b, sizeof b, t);
        char *lab = malloc(32);
        if (k) snprintf(lab, 32, "%d\u00d7%d cells", k, k);
        else snprintf(lab, 32, area ? "area" : "auto");
        char row[32];
        if (k) snprintf(row, sizeof row, "%d x %d", k, k);
        fprintf(o, "| %s | %s | %s |\n", k ? row : area ? "area (every pair integrated)" : "auto (the default)", a, b);
        pts[(*np)++] = (lx_plot_point){t, mx, lab, 1};
        free(pl);
        lx_luminaire_free(lum);
    }
    fprintf(o, "\n");
    free(P);
    free(E);
    free(Ex);

    return CLI_OK;
}

/* (c) Intensity-table interpolation of a Warn spot tabulated every 5 and 1 deg, against the
 * analytic E; one plot point per row that ran into pts (series 2). A CLI exit code. */
static int lighting_interp(lx_ctx *ctx, FILE *o, lx_plot_point *pts, int *np)
{
    const double F = 1000;
    char a[32], c[32];
    /* a Warn spot S = 30 sampled every 5 and every 1 deg */
    const double S = 30, H = 3;
    enum { NG = 61 };
    double *G = malloc(NG * NG * 3 * sizeof *G), *Eg = malloc(NG * NG * sizeof *Eg), *Et = malloc(NG * NG * sizeof *Et);
    double Emax = 0;
    for (int j = 0; j < NG; j++)
        for (int i = 0; i < NG; i++) {
            double *p = G + 3 * (j * NG + i);
            p[0] = -3 + 6.0 * i / (NG - 1), p[1] = -3 + 6.0 * j / (NG - 1), p[2] = 0;
            double d = sqrt(p[0] * p[0] + p[1] * p[1] + H * H), cg = H / d;
            Et[j * NG + i] = (S + 1) * F / (2 * PI) * pow(cg, S) * cg / (d * d); /* I(gamma) cos(gamma) / d^2 */
            Emax = fmax(Emax, Et[j * NG + i]);
        }
    fprintf(o, "Intensity-table interpolation: a Warn spot (S = %.0f, %.0f lm, beam %.1f deg) tabulated every 5 deg and every "
               "1 deg, %.0f m above a %dx%d grid over 6 x 6 m; the analytic E = I(gamma) cos(gamma) / d^2 as reference. "
               "Max |dE| / E_max over the grid; time per point (one thread; OpenCL: the whole grid's call / points).\n\n",
            S, F, 2 * acos(pow(0.5, 1 / S)) * 180 / PI, H, NG, NG);
    fprintf(o, "| interpolation | table step | max \\|dE\\|/E_max | time per point |\n|---|---|---|---|\n");
    static const char *in[5] = {"bilinear", "smooth (PCHIP)", "table (CPU)", "table (OpenCL, double)", "table (OpenCL, float)"};
    static const char *il[5] = {"bilinear", "smooth", "table", "table CL", "table CL f32"};
    static const double steps[2] = {5, 1};
    for (int s = 0; s < 2; s++) {
        lx_lum_model mdl = {.kind = LX_LUM_MODEL_WARN, .flux_lm = F, .exponent = S, .step_deg = steps[s]};
        lx_luminaire *lum = NULL;
        if (lx_luminaire_from_model(ctx, &mdl, &lum)) return cli_fail("bench", ctx, LX_EINVAL);
        lx_placement pl = {lum, {0, 0, H}, {0, 0, -1}, 0};
        for (int v = 0; v < 5; v++) {
            grid_job gj = {ctx, &pl, 1, NG * NG, G, {.model = LX_MODEL_POINT, .threads = 1}, Eg, 0};
            gj.opts.interp = v == 0 ? LX_INTERP_BILINEAR : v == 1 ? LX_INTERP_SMOOTH : LX_INTERP_TABLE;
            gj.opts.backend = v >= 3 ? LX_BACKEND_OPENCL : LX_BACKEND_CPU;
            gj.opts.fp32 = v == 4;
            grid_run(&gj);
            if (!gj.ok) {
                fprintf(o, "| %s | %.0f deg | not available (%s) | |\n", in[v], steps[s], lx_ctx_errmsg(ctx));
                continue;
            }
            double t = acc_time(grid_run, &gj, 1000) / (NG * NG), mx = 0;
            for (int i = 0; i < NG * NG; i++) mx = fmax(mx, fabs(Eg[i] - Et[i]) / Emax);
            acc_fmt_err(a, sizeof a, mx);
            acc_fmt_time(c, sizeof c, t);
            fprintf(o, "| %s | %.0f deg | %s | %s |\n", in[v], steps[s], a, c);
            char *lab = malloc(24);
            snprintf(lab, 24, "%s %.0f\u00b0", il[v], steps[s]);
            pts[(*np)++] = (lx_plot_point){t, mx, lab, 2};
        }
        lx_luminaire_free(lum);
    }
    fprintf(o, "\n");
    free(G);
    free(Eg);
    free(Et);
    return CLI_OK;
}

int acc_lighting(lx_ctx *ctx, FILE *o, const char *png)
{
    lx_plot_point pts[64];
    int np = 0;
    fprintf(o, "## bench accuracy: lighting\n\n");
    lighting_point(ctx, o, pts, &np);
    int rc = lighting_cells(ctx, o, pts, &np);
    if (rc) return rc;
    if ((rc = lighting_interp(ctx, o, pts, &np))) return rc;
    if (png) {
        static const char *series[3] = {"point model (disk)", "near-field cells", "IES interpolation"};
        if (lx_error_time_write_png(ctx, png, "Lighting: error against time", "time per evaluation (s)", "relative error",
                              (size_t)np, pts, 3, series))
            rc = cli_fail("bench", ctx, LX_EIO);
    }
    for (int k = 0; k < np; k++) free((char *)(uintptr_t)pts[k].label);
    return rc;
}
