/* cmd_scene.c - `luxcalc scene FILE [--explain]`: reads a scene, plans which effects it needs,
 * evaluates it and prints the receivers' results, or (--explain) the plan with its reasons and
 * the estimated and measured work. */
#include "grid.h"
#include "design.h"
#include "spd_report.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc scene FILE [--explain] [--contributions] [--surfaces] [--check] [--energy] [--emergency]\n"
    "                     [--format table|csv|json]\n"
    "                     [-o FILE] [--png DIR] [--backend auto|cpu|opencl]\n"
    "\n"
    "Computes a lighting scene (see README \"Scenes\" for the file format): luminaires (point, spot,\n"
    "disk, rect, IES/LDT file), receivers (points and grids), an optional sky, the outputs wanted.\n"
    "Only the effects the scene needs are simulated; --explain says which, why, and what they cost.\n"
    "\n"
    "  --explain         print the plan: each effect on or off with its reason, the pairs that take\n"
    "                    the near-field path, the estimated and the measured work (json: an object\n"
    "                    with \"effects\", \"reasons\", \"forced\", \"pairs\", \"estimated\", \"measured\")\n"
    "  --contributions   one more column per luminaire (E_NAME_lx; table: E_NAME_avg_lx, the mean over\n"
    "                    the receiver) and, with a sky, the sky (E_sky_lx): their direct light (with\n"
    "                    interreflection the reflected part is indirect_lx)\n"
    "  --glare           UGR (CIE 117) at each [observer]: one row per luminaire that counts with its\n"
    "                    luminance, solid angle, position index and term L^2 w / p^2, and the UGR\n"
    "  --emergency       emergency operation (EN 1838): the emergency luminaires alone at their\n"
    "                    emergency flux, direct light only (--explain says why)\n"
    "  --energy          EN 15193-1 LENI from the [energy] section: installed power, hours, factors,\n"
    "                    the lighting and parasitic energy (kWh a year) and LENI (kWh/(m2 a))\n"
    "  --check           the checks against the scene's [requirement] sections: one row per line\n"
    "                    (requirement, target, quantity, required, computed, pass or FAIL)\n"
    "  --surfaces        rooms: one row per room face, surface side and obstruction face instead:\n"
    "                    surface,area_m2,direct_lx,indirect_lx,illuminance_lx,luminance_cd_m2,reflectance\n"
    "                    (area-weighted averages: the flux each receives over its exposed area)\n"
    "  --format F        table (default: a summary per receiver), csv or json (one row per point)\n"
    "  -o FILE           write to FILE (atomically)\n"
    "  --png DIR         also draw every grid receiver as an isolux plot (contours, luminaires,\n"
    "                    legend, statistics): DIR/SCENE_RECEIVER.png (SCENE: the file name without\n"
    "                    its extension; DIR is created when missing)\n"
    "  --backend B       auto (default, also LX_BACKEND), cpu or opencl: where the far-field work of\n"
    "                    IES luminaires on grids runs (auto: OpenCL from 1e7 evaluations), and the\n"
    "                    form factors and gathers of rooms\n"
    "\n"
    "csv columns: receiver,x,y,z,illuminance_lx, then direct_lx,indirect_lx (interreflection on),\n"
    "luminance_cd_m2 ([output] luminance = yes),\n"
    "cct_K,duv (cct = yes), melanopic_edi_lx (melanopic_edi = yes)\n"
    "\n"
    "example: the office sample, its plan, then its desk grid as csv:\n"
    "  luxcalc scene samples/scenes/office.scene --explain\n"
    "  luxcalc scene samples/scenes/office.scene --format csv -o office.csv\n";

static const char *const counter_names[] = {
    "point_evaluations",      "spot_evaluations",    "goniometric_lookups",
    "nearfield_pairs",        "nearfield_subdivisions", "environment_evaluations",
    "environment_samples",    "spectra_integrated",  "kernel_launches",
    "nearfield_probes",       "closed_form_evaluations", "visibility_tests",
    "form_factors",           "radiosity_patches",   "radiosity_shots",
    "gather_points",          "daylight_evaluations"};
#define N_COUNTERS 17

static unsigned long long counter(const lx_counters *c, int i)
{
    const unsigned long long v[N_COUNTERS] = {c->point_evaluations,     c->spot_evaluations,    c->goniometric_lookups,
                                              c->nearfield_pairs,       c->nearfield_subdivisions, c->environment_evaluations,
                                              c->environment_samples,   c->spectra_integrated,  c->kernel_launches,
                                              c->nearfield_probes,      c->closed_form_evaluations, c->visibility_tests,
                                              c->form_factors,          c->radiosity_patches,   c->radiosity_shots,
                                              c->gather_points,         c->daylight_evaluations};
    return v[i];
}

/* The measured work: the evaluation's, plus the planner's own (its near-field probes). */
static unsigned long long measured(const lx_scene_plan *p, const lx_scene_result *res, int i)
{
    return counter(&res->work, i) + counter(&p->planning, i);
}

static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\') fprintf(f, "\\%c", ch);
        else if (ch < 32) fprintf(f, "\\u%04x", ch);
        else fputc(ch, f);
    }
    fputc('"', f);
}

static const char *backend_name(int b) { return b == LX_BACKEND_OPENCL ? "opencl" : b == LX_BACKEND_CPU ? "cpu" : "auto"; }

/* The interreflection part of --explain: the planner's estimate and choices, what the solve did. */
static void room_text(FILE *f, const lx_scene_plan *p, const lx_scene_result *res)
{
    const lx_scene_room_plan *R = &p->room;
    const lx_scene_room_stats *S = &res->room;
    fprintf(f, "\ninterreflection:\n");
    fprintf(f, "  estimate      rho %.3g over %.4g m2, %.4g lm: indirect about %.4g lx (rho Phi / (S (1 - rho)));\n"
               "                largest estimated indirect share of a receiver's total %.1f %%\n",
            R->mean_reflectance, R->area_m2, R->flux_lm, R->indirect_est_lx, 100 * R->share_est);
    fprintf(f, "  patches       %zu of <= %.3g m for the solve; %zu elements for the gather (%zu splits near\n"
               "                luminaires, shadow edges and receivers), %zu direct-light nodes; memory %.1f MiB of\n"
               "                the %.0f MiB bound\n",
            R->n_patches, R->patch_size_m, R->n_elements, R->n_refined, R->n_nodes, R->memory_bytes / 1048576.0,
            R->memory_limit_bytes / 1048576.0);
    fprintf(f, "  solve         tolerance %.3g: stop at %.4g lm unshot; %llu sweeps, %llu shots, %.4g lm unshot left\n",
            R->tolerance, R->stop_unshot_lm, S->sweeps, S->shots, S->unshot_lm);
    fprintf(f, "  flux          direct %.6g lm, indirect %.6g lm, absorbed %.6g lm, escaped %.4g lm\n", S->direct_lm,
            S->indirect_lm, S->absorbed_lm, S->escaped_lm);
    fprintf(f, "  measured      indirect share %.1f %% of the receivers' total; the solve's patches against the\n"
               "                exact gather at their elements %.3g %% rms\n",
            100 * S->indirect_share, 100 * S->gather_check);
    fprintf(f, "  backend       %s (asked %s): form factors %.3g s, solve %.3g s, gather %.3g s\n", backend_name(S->backend),
            backend_name(R->backend), S->seconds_ff, S->seconds_solve, S->seconds_gather);
}

static void room_json(FILE *f, const lx_scene_plan *p, const lx_scene_result *res)
{
    const lx_scene_room_plan *R = &p->room;
    const lx_scene_room_stats *S = &res->room;
    const char *k[] = {"mean_reflectance", "area_m2", "flux_lm", "indirect_estimate_lx", "share_estimate", "tolerance",
                       "patch_size_m", "stop_unshot_lm", "memory_bytes", "direct_lm", "indirect_lm", "absorbed_lm",
                       "escaped_lm", "unshot_lm", "indirect_share", "gather_check", "seconds_form_factors",
                       "seconds_solve", "seconds_gather"};
    double v[] = {R->mean_reflectance, R->area_m2, R->flux_lm, R->indirect_est_lx, R->share_est, R->tolerance,
                  R->patch_size_m, R->stop_unshot_lm, R->memory_bytes, S->direct_lm, S->indirect_lm, S->absorbed_lm,
                  S->escaped_lm, S->unshot_lm, S->indirect_share, S->gather_check, S->seconds_ff, S->seconds_solve,
                  S->seconds_gather};
    fprintf(f, "  \"interreflection\": {\"patches\": %zu, \"elements\": %zu, \"refined\": %zu, \"nodes\": %zu, "
               "\"sweeps\": %llu, \"shots\": %llu, \"backend\": \"%s\"",
            R->n_patches, R->n_elements, R->n_refined, R->n_nodes, S->sweeps, S->shots, backend_name(S->backend));
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
        fprintf(f, ", \"%s\": ", k[i]);
        cli_print_exact(f, v[i]);
    }
    fputs("},\n", f);
}

static const char *const face_names[6] = {"floor", "ceiling", "wall_xmin", "wall_xmax", "wall_ymin", "wall_ymax"};

/* The daylight part of --explain: the sky the daylight factor refers to, the openings, the flux. */
static void daylight_text(FILE *f, const lx_scene *sc, const lx_scene_plan *p, const lx_scene_result *res)
{
    const lx_scene_daylight_plan *D = &p->daylight;
    const lx_scene_daylight_stats *S = &res->daylight;
    fprintf(f, "\ndaylight:\n");
    fprintf(f, "  outside       E_h %.6g lx (the sky alone, horizontal, unobstructed); ground %.4g cd/m2\n", D->outside_lx,
            D->ground_cd_m2);
    fprintf(f, "  factor        %s\n", D->df ? "DF = 100 (sky + ground through the openings + interreflected) / E_h"
                                          : "none: defined under an overcast or uniform sky without the sun");
    for (size_t k = 0; k < sc->n_open; k++) {
        const lx_scene_opening *o = &sc->open[k];
        fprintf(f, "  opening       %s: %s.%s, %.4g m2, %s, tau %.4g\n", o->name, sc->room[o->room].name, face_names[o->face],
                o->area_m2, o->glazing == LX_GLAZING_CLEAR ? "clear glass (CIE 171 6 mm angular dependence)" : "no angular dependence",
                o->transmittance);
    }
    fprintf(f, "  sky component %s\n", D->closed_form ? "closed form (exact moments of each opening's directions)"
                                                     : "integrated numerically over each opening's directions");
    fprintf(f, "  flux          in %.6g lm; the faces received %.6g lm directly, %.6g lm after reflections; %.4g lm "
               "left by the openings\n",
            S->flux_in_lm, S->direct_lm, S->indirect_lm, S->escaped_lm);
    fprintf(f, "  solve         %llu sweeps, %.4g lm unshot left; %.3g s for the daylight\n", S->sweeps, S->unshot_lm, S->seconds);
}

static void daylight_json(FILE *f, const lx_scene *sc, const lx_scene_plan *p, const lx_scene_result *res)
{
    const lx_scene_daylight_plan *D = &p->daylight;
    const lx_scene_daylight_stats *S = &res->daylight;
    const char *k[] = {"outside_lx", "ground_cd_m2", "flux_in_lm", "share_estimate", "direct_lm", "indirect_lm", "escaped_lm",
                       "unshot_lm", "seconds"};
    double v[] = {D->outside_lx, D->ground_cd_m2, D->flux_in_lm, D->share_est, S->direct_lm, S->indirect_lm, S->escaped_lm,
                  S->unshot_lm, S->seconds};
    fprintf(f, "  \"daylight\": {\"daylight_factor\": %s, \"closed_form\": %s, \"sweeps\": %llu", D->df ? "true" : "false",
            D->closed_form ? "true" : "false", S->sweeps);
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
        fprintf(f, ", \"%s\": ", k[i]);
        cli_print_exact(f, v[i]);
    }
    fputs(", \"openings\": [", f);
    for (size_t i = 0; i < sc->n_open; i++) {
        const lx_scene_opening *o = &sc->open[i];
        fputs(i ? ", {\"name\": " : "{\"name\": ", f);
        json_string(f, o->name);
        fputs(", \"room\": ", f);
        json_string(f, sc->room[o->room].name);
        fprintf(f, ", \"face\": \"%s\", \"glazing\": \"%s\", \"area_m2\": ", face_names[o->face],
                o->glazing == LX_GLAZING_CLEAR ? "clear" : "none");
        cli_print_exact(f, o->area_m2);
        fputs(", \"transmittance\": ", f);
        cli_print_exact(f, o->transmittance);
        fputc('}', f);
    }
    fputs("]},\n", f);
}

/* Near-field points per luminaire-receiver pair. */
static size_t near_points(const lx_scene *sc, const lx_scene_plan *p, size_t l, size_t r)
{
    size_t g0 = 0, k = 0;
    for (size_t i = 0; i < r; i++) g0 += sc->rec[i].n;
    for (size_t i = 0; i < sc->rec[r].n; i++) k += p->near[l * p->n_points + g0 + i] != 0;
    return k;
}

/* The decision of every pair of a luminaire with a luminous area: where, the point model's
 * estimated error relative to the point's illuminance, and the path. Text: at most
 * MAX_PAIR_LINES lines (json has them all). */
#define MAX_PAIR_LINES 2000
static void text_pairs(FILE *f, const lx_scene *sc, const lx_scene_plan *p)
{
    size_t shown = 0, total = 0;
    int header = 0;
    for (size_t l = 0; l < sc->n_lum; l++) {
        size_t g = 0;
        for (size_t r = 0; r < sc->n_rec; r++)
            for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
                size_t at = l * p->n_points + g;
                if (p->near_why[at] == LX_NEAR_NONE) continue;
                total++;
                if (shown >= MAX_PAIR_LINES) continue;
                if (!header) {
                    fprintf(f, "\nnear-field decisions (tolerance %g; estimate: the point model's error relative to "
                               "the point's illuminance):\n  %-12s %-12s %6s %10s %10s %10s %12s  %s\n",
                            sc->nearfield_tol, "luminaire", "receiver", "point", "x_m", "y_m", "z_m", "estimate", "decision");
                    header = 1;
                }
                const double *q = sc->rec[r].points + 3 * i;
                char est[32] = "-";
                if (!isnan(p->near_err[at])) snprintf(est, sizeof est, "%.3g", p->near_err[at]);
                fprintf(f, "  %-12s %-12s %6zu %10.4g %10.4g %10.4g %12s  %s\n", sc->lum[l].name, sc->rec[r].name, i + 1,
                        q[0], q[1], q[2], est, lx_near_why_name((lx_near_why)p->near_why[at]));
                shown++;
            }
    }
    if (total > shown) fprintf(f, "  ... %zu more pairs (all of them: --explain --format json)\n", total - shown);
}

static void json_pairs(FILE *f, const lx_scene *sc, const lx_scene_plan *p)
{
    static const char *const path[3] = {"point", "area", "closed_form"};
    fputs("  \"near_field_decisions\": [", f);
    int first = 1;
    for (size_t l = 0; l < sc->n_lum; l++) {
        size_t g = 0;
        for (size_t r = 0; r < sc->n_rec; r++)
            for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
                size_t at = l * p->n_points + g;
                if (p->near_why[at] == LX_NEAR_NONE) continue;
                fputs(first ? "\n    {\"luminaire\": " : ",\n    {\"luminaire\": ", f);
                json_string(f, sc->lum[l].name);
                fputs(", \"receiver\": ", f);
                json_string(f, sc->rec[r].name);
                fprintf(f, ", \"point\": %zu, \"estimate\": ", i + 1);
                if (isfinite(p->near_err[at])) cli_print_exact(f, p->near_err[at]);
                else fputs("null", f);
                fprintf(f, ", \"path\": \"%s\", \"why\": ", path[p->near[at] < 3 ? p->near[at] : 0]);
                json_string(f, lx_near_why_name((lx_near_why)p->near_why[at]));
                fputc('}', f);
                first = 0;
            }
    }
    fputs(first ? "],\n" : "\n  ],\n", f);
}

static void explain(FILE *f, const lx_scene *sc, const lx_scene_plan *p, const lx_scene_result *res, cli_format fmt)
{
    if (fmt == CLI_FMT_JSON) {
        fputs("{\n  \"scene\": ", f);
        json_string(f, sc->file);
        fputs(",\n  \"effects\": {", f);
        for (int e = 0; e < LX_EFFECT_COUNT; e++)
            fprintf(f, "%s\"%s\": %s", e ? ", " : "", lx_effect_name((lx_effect)e), p->on[e] ? "true" : "false");
        fputs("},\n  \"reasons\": {", f);
        for (int e = 0; e < LX_EFFECT_COUNT; e++) {
            fprintf(f, "%s\n    \"%s\": ", e ? "," : "", lx_effect_name((lx_effect)e));
            json_string(f, p->reason[e]);
        }
        char vt[128];
        fputs("\n  },\n  \"values\": ", f);
        json_string(f, cli_scene_values(sc, vt, sizeof vt));
        fputs(",\n  \"forced\": {", f);
        for (int e = 0; e < LX_EFFECT_COUNT; e++)
            fprintf(f, "%s\"%s\": %s", e ? ", " : "", lx_effect_name((lx_effect)e), p->forced[e] ? "true" : "false");
        fprintf(f, "},\n  \"pairs\": {\"total\": %zu, \"near_field\": %zu, \"costly\": [", p->n_pairs, p->n_near);
        int first = 1;
        for (size_t l = 0; l < sc->n_lum; l++)
            for (size_t r = 0; r < sc->n_rec; r++) {
                size_t k = near_points(sc, p, l, r);
                if (!k) continue;
                fputs(first ? "\n    {\"luminaire\": " : ",\n    {\"luminaire\": ", f);
                json_string(f, sc->lum[l].name);
                fputs(", \"receiver\": ", f);
                json_string(f, sc->rec[r].name);
                fprintf(f, ", \"near_field_points\": %zu, \"points\": %zu}", k, sc->rec[r].n);
                first = 0;
            }
        fputs(first ? "]},\n" : "\n  ]},\n", f);
        for (int pass = 0; pass < 2; pass++) {
            fprintf(f, "  \"%s\": {", pass ? "measured" : "estimated");
            for (int i = 0; i < N_COUNTERS; i++)
                fprintf(f, "%s\"%s\": %llu", i ? ", " : "", counter_names[i],
                        pass ? measured(p, res, i) : counter(&p->estimate, i));
            fputs("},\n", f);
        }
        json_pairs(f, sc, p);
        if (p->on[LX_EFFECT_INTERREFLECTION]) room_json(f, p, res);
        if (p->on[LX_EFFECT_DAYLIGHT]) daylight_json(f, sc, p, res);
        fputs("  \"seconds\": ", f);
        cli_print_exact(f, res->seconds);
        fputs("\n}\n", f);
        return;
    }
    if (fmt == CLI_FMT_CSV) {
        fputs("effect,on,forced,reason\n", f);
        for (int e = 0; e < LX_EFFECT_COUNT; e++) {
            fprintf(f, "%s,%d,%d,\"", lx_effect_name((lx_effect)e), p->on[e], p->forced[e]);
            for (const char *s = p->reason[e]; *s; s++) {
                if (*s == '"') fputc('"', f);
                fputc(*s, f);
            }
            fputs("\"\n", f);
        }
        return;
    }
    fprintf(f, "scene %s%s%s%s\n\neffects:\n", sc->file, *sc->title ? " (" : "", sc->title, *sc->title ? ")" : "");
    for (int e = 0; e < LX_EFFECT_COUNT; e++)
        fprintf(f, "  %-15s %-3s %s%s\n", lx_effect_name((lx_effect)e), p->on[e] ? "on" : "off",
                p->forced[e] ? "[forced] " : "", p->reason[e]);
    char vt[128];
    fprintf(f, "\nvalues: %s\n", cli_scene_values(sc, vt, sizeof vt));
    if (p->mode == LX_SCENE_EMERGENCY)
        fprintf(f, "operation: emergency (EN 1838): the emergency luminaires alone at their emergency flux, direct light "
                   "only\n");
    cli_scene_maintenance_text(f, sc);
    fprintf(f, "\npairs: %zu luminaire-receiver point pairs, %zu on the near-field path\n", p->n_pairs, p->n_near);
    for (size_t l = 0; l < sc->n_lum; l++)
        for (size_t r = 0; r < sc->n_rec; r++) {
            size_t k = near_points(sc, p, l, r);
            if (k) fprintf(f, "  %s -> %s: %zu of %zu points near field\n", sc->lum[l].name, sc->rec[r].name, k, sc->rec[r].n);
        }
    text_pairs(f, sc, p);
    fprintf(f, "\nwork:%*s %14s %14s\n", 19, "", "estimated", "measured");
    for (int i = 0; i < N_COUNTERS; i++)
        fprintf(f, "  %-23s %14llu %14llu\n", counter_names[i], counter(&p->estimate, i), measured(p, res, i));
    fprintf(f, "  %-22s %14s %14.3g\n", "seconds", "", res->seconds);
    if (p->on[LX_EFFECT_INTERREFLECTION]) room_text(f, p, res);
    if (p->on[LX_EFFECT_DAYLIGHT]) daylight_text(f, sc, p, res);
}

/* The result columns. */
static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The daylight factor's mean, minimum and median over points a..b-1 (NaN when undefined). */
static void df_stats(const lx_scene_result *res, size_t a, size_t b, double out[3])
{
    out[0] = out[1] = out[2] = NAN;
    double *v = malloc((b - a + 1) * sizeof *v), s = 0;
    size_t n = 0;
    for (size_t g = a; v && g < b; g++)
        if (isfinite(res->daylight_factor[g])) v[n++] = res->daylight_factor[g], s += res->daylight_factor[g];
    if (n) {
        qsort(v, n, sizeof *v, cmp_double);
        out[0] = s / (double)n, out[1] = v[0], out[2] = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }
    free(v);
}

/* What the result table holds: summary rows (table) or one row per point, and which optional columns. */
typedef struct {
    int table, sky, day, df, contrib;
} res_cols;

/* The column names and units being collected for the result table. */
typedef struct {
    char **names, **units;
    size_t nn;
} col_list;

#define COL(n, u) (c->names[c->nn] = strdup(n), c->units[c->nn] = strdup(u), c->nn++)

/* The columns of the summary table: one row per receiver. */
static void summary_columns(const lx_scene *sc, const lx_scene_result *res, const res_cols *w, col_list *c)
{
    COL("points", "");
    COL("values", "");
    COL("illuminance_avg_lx", "lx");
    COL("illuminance_min_lx", "lx");
    COL("illuminance_max_lx", "lx");
    COL("uniformity_u0", "");
    COL("uniformity_min_max", "");
    if (res->indirect_lx) COL("indirect_avg_lx", "lx");
    if (w->day) COL("daylight_avg_lx", "lx");
    if (w->df) COL("daylight_factor_avg", "%"), COL("daylight_factor_min", "%"), COL("daylight_factor_median", "%");
    if (sc->want_luminance) COL("luminance_avg_cd_m2", "cd/m2");
    if (sc->want_cct) COL("cct_avg_K", "K");
    if (sc->want_melanopic) COL("melanopic_edi_avg_lx", "lx");
    if (res->cylindrical_lx)
        COL("cylindrical_avg_lx", "lx"), COL("semicylindrical_avg_lx", "lx"), COL("modelling_min", ""), COL("modelling_max", "");
    if (w->contrib) {
        for (size_t l = 0; l < sc->n_lum; l++) {
            char b[300];
            snprintf(b, sizeof b, "E_%s_avg_lx", sc->lum[l].name);
            COL(b, "lx");
        }
        if (w->sky) COL("E_sky_avg_lx", "lx");
    }
}

/* The columns of the point table (csv, json): one row per receiver point. */
static void point_columns(const lx_scene *sc, const lx_scene_result *res, const res_cols *w, col_list *c)
{
    COL("x", "m");
    COL("y", "m");
    COL("z", "m");
    COL("illuminance_lx", "lx");
    if (res->indirect_lx) COL("direct_lx", "lx"), COL("indirect_lx", "lx");
    if (w->day) COL("daylight_lx", "lx");
    if (w->df)
        COL("daylight_factor", "%"), COL("sky_component", "%"), COL("externally_reflected", "%"),
            COL("internally_reflected", "%");
    if (sc->want_luminance) COL("luminance_cd_m2", "cd/m2");
    if (sc->want_cct) COL("cct_K", "K"), COL("duv", "");
    if (sc->want_melanopic) COL("melanopic_edi_lx", "lx");
    if (res->cylindrical_lx) COL("cylindrical_lx", "lx"), COL("semicylindrical_lx", "lx"), COL("modelling", "");
    if (w->contrib) {
        for (size_t l = 0; l < sc->n_lum; l++) {
            char b[300];
            snprintf(b, sizeof b, "E_%s_lx", sc->lum[l].name);
            COL(b, "lx");
        }
        if (w->sky) COL("E_sky_lx", "lx");
    }
    if (sc->design && sc->design->maintained) COL("values", "");
}

#undef COL

/* Receiver r's summary row: its points' mean, minimum, maximum, uniformities and optional means. */
static void summary_row(cli_table *t, const lx_scene *sc, const lx_scene_result *res, const res_cols *w, size_t r)
{
    size_t a = res->first[r], b = res->first[r + 1];
    double sum = 0, mn = INFINITY, mx = -INFINITY, ls = 0, cs = 0, ms = 0, is = 0, ds = 0;
    size_t cn = 0;
    for (size_t g = a; g < b; g++) {
        double e = res->E_lx[g];
        sum += e;
        if (res->indirect_lx) is += res->indirect_lx[g];
        if (w->day) ds += res->daylight_lx[g];
        mn = e < mn ? e : mn;
        mx = e > mx ? e : mx;
        ls += res->L_cd_m2[g];
        ms += res->melanopic_edi_lx[g];
        if (isfinite(res->cct_K[g])) cs += res->cct_K[g], cn++;
    }
    double n = (double)(b - a), avg = sum / n;
    if (!isfinite(avg)) { /* finite values whose sum overflows: the mean of e / n instead */
        avg = 0;
        for (size_t g = a; g < b; g++) avg += res->E_lx[g] / n;
    }
    char vt[128];
    cli_table_str(t, sc->rec[r].name);
    cli_table_int(t, (long long)(b - a));
    cli_table_str(t, cli_scene_values(sc, vt, sizeof vt));
    cli_table_num(t, avg);
    cli_table_num(t, mn);
    cli_table_num(t, mx);
    cli_table_num(t, avg > 0 ? mn / avg : NAN);
    cli_table_num(t, mx > 0 ? mn / mx : NAN);
    if (res->indirect_lx) cli_table_num(t, is / n);
    if (w->day) cli_table_num(t, ds / n);
    if (w->df) {
        double st3[3];
        df_stats(res, a, b, st3);
        for (int k = 0; k < 3; k++) cli_table_num(t, st3[k]);
    }
    if (sc->want_luminance) cli_table_num(t, ls / n);
    if (sc->want_cct) cli_table_num(t, cn == b - a ? cs / (double)cn : NAN);
    if (sc->want_melanopic) cli_table_num(t, ms / n);
    if (res->cylindrical_lx) cli_scene_cylinder_summary(t, res, a, b);
    for (size_t l = 0; w->contrib && l < sc->n_lum + (size_t)w->sky; l++) {
        double c = 0;
        for (size_t g = a; g < b; g++) c += res->contrib_lx[g * (sc->n_lum + 1) + l];
        cli_table_num(t, c / n);
    }
}

/* Receiver r's points, one row each. */
static void point_rows(cli_table *t, const lx_scene *sc, const lx_scene_result *res, const res_cols *w, size_t r)
{
    size_t a = res->first[r], b = res->first[r + 1];
    for (size_t g = a; g < b; g++) {
        const double *q = sc->rec[r].points + 3 * (g - a);
        cli_table_str(t, sc->rec[r].name);
        for (int k = 0; k < 3; k++) cli_table_num(t, q[k]);
        cli_table_num(t, res->E_lx[g]);
        if (res->indirect_lx) cli_table_num(t, res->direct_lx[g]), cli_table_num(t, res->indirect_lx[g]);
        if (w->day) cli_table_num(t, res->daylight_lx[g]);
        if (w->df) {
            cli_table_num(t, res->daylight_factor[g]);
            cli_table_num(t, res->sky_component[g]);
            cli_table_num(t, res->externally_reflected[g]);
            cli_table_num(t, res->internally_reflected[g]);
        }
        if (sc->want_luminance) cli_table_num(t, res->L_cd_m2[g]);
        if (sc->want_cct) cli_table_num(t, res->cct_K[g]), cli_table_num(t, res->duv[g]);
        if (sc->want_melanopic) cli_table_num(t, res->melanopic_edi_lx[g]);
        if (res->cylindrical_lx) {
            cli_table_num(t, res->cylindrical_lx[g]);
            cli_table_num(t, res->semicylindrical_lx[g]);
            cli_table_num(t, res->modelling[g]);
        }
        if (w->contrib)
            for (size_t l = 0; l < sc->n_lum + (size_t)w->sky; l++) cli_table_num(t, res->contrib_lx[g * (sc->n_lum + 1) + l]);
        if (sc->design && sc->design->maintained) cli_table_str(t, "maintained");
    }
}

static cli_table *results(const lx_scene *sc, const lx_scene_plan *plan, const lx_scene_result *res, cli_format fmt,
                          int contrib, char ***names_out, size_t *n_names)
{
    size_t cap = 2 * (24 + sc->n_lum);
    char **names = calloc(2 * cap, sizeof *names); /* the names, then the units */
    if (!names) return NULL;
    col_list c = {names, names + cap, 0};
    int day = res->daylight_lx != NULL;
    res_cols w = {fmt == CLI_FMT_TABLE, sc->sky != LX_SKY_NONE, day, day && plan->daylight.df, contrib};
    c.names[c.nn] = strdup("receiver"), c.units[c.nn] = strdup(""), c.nn++;
    if (w.table) summary_columns(sc, res, &w, &c);
    else point_columns(sc, res, &w, &c);
    cli_table *t = cli_table_new((int)c.nn, (const char *const *)c.names, (const char *const *)c.units);
    if (!t) {
        for (size_t i = 0; i < 2 * cap; i++) free(names[i]);
        free(names);
        return NULL;
    }
    for (size_t r = 0; r < sc->n_rec; r++) {
        if (w.table) summary_row(t, sc, res, &w, r);
        else point_rows(t, sc, res, &w, r);
    }
    *names_out = names;
    *n_names = 2 * cap;
    return t;
}

/* --surfaces: one row per room face, surface side and obstruction face. */
static cli_table *surfaces_table(const lx_scene_result *res)
{
    static const char *const names[] = {"surface", "area_m2", "direct_lx", "indirect_lx", "illuminance_lx",
                                        "luminance_cd_m2", "reflectance"};
    static const char *const units[] = {"", "m2", "lx", "lx", "lx", "cd/m2", ""};
    cli_table *t = cli_table_new(7, names, units);
    if (!t) return NULL;
    for (size_t i = 0; i < res->n_surfaces; i++) {
        const lx_scene_surface_result *s = &res->surfaces[i];
        cli_table_str(t, s->name);
        cli_table_num(t, s->area_m2);
        cli_table_num(t, s->direct_lx);
        cli_table_num(t, s->indirect_lx);
        cli_table_num(t, s->E_lx);
        cli_table_num(t, s->L_cd_m2);
        cli_table_num(t, s->reflectance);
    }
    return t;
}

/* The scene's luminaires as plot marks (free with free()); NULL when there are none or no memory. */
lx_plot_mark *cli_scene_marks(const lx_scene *sc)
{
    lx_plot_mark *mk = sc->n_lum ? calloc(sc->n_lum, sizeof *mk) : NULL;
    for (size_t l = 0; mk && l < sc->n_lum; l++) {
        memcpy(mk[l].pos_m, sc->lum[l].pos_m, sizeof mk[l].pos_m);
        memcpy(mk[l].aim, sc->lum[l].aim, sizeof mk[l].aim);
        mk[l].name = sc->lum[l].name;
    }
    return mk;
}

/* Each grid receiver's illuminance as an isolux plot DIR/SCENE_RECEIVER.png (DIR created when
 * missing), seen from the side its normal points to (the first free axis to the right, the second
 * upwards), with the scene's rooms, obstructions, surfaces, openings and luminaires drawn on it
 * (lx_scene_receiver_write_png); and where the scene defines the daylight factor, its plot
 * DIR/SCENE_RECEIVER_df.png too. */
static lx_status write_pngs(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lx_scene_result *res,
                            const char *scene_path, const char *dir, int imperial)
{
    const char *base = strrchr(scene_path, '/');
    base = base ? base + 1 : scene_path;
    size_t bl = strlen(base);
    const char *dot = strrchr(base, '.');
    if (dot && dot != base) bl = (size_t)(dot - base);
    lx_status st = LX_OK;
    for (size_t r = 0; r < sc->n_rec && !st; r++) {
        const lx_scene_receiver *rc = &sc->rec[r];
        if (rc->kind != LX_SREC_GRID) continue;
        for (int q = 0; q < 2 && !st; q++) {
            if (q == 1 && !(plan->on[LX_EFFECT_DAYLIGHT] && plan->daylight.df)) break;
            char path[4096];
            snprintf(path, sizeof path, "%s/%.*s_%s%s.png", dir, (int)bl, base, rc->name, q ? "_df" : "");
            lx_receiver_png_opts po = {.quantity = q ? LX_PLOT_DAYLIGHT_FACTOR : LX_PLOT_ILLUMINANCE, .imperial = imperial};
            st = lx_scene_receiver_write_png(ctx, path, sc, res, r, &po);
            if (!st && !cli_quiet) fprintf(stderr, "luxcalc: scene: wrote %s\n", path);
        }
    }
    return st;
}

/* --glare: one row per observer and luminaire that counts, with the observer's UGR */
static int glare_out(const char *cmd, lx_ctx *ctx, const lx_scene *sc, cli_format fmt, const char *out)
{
    lx_scene_glare *g = NULL;
    lx_status st = lx_scene_glare_eval(ctx, sc, &g);
    if (st != LX_OK) return cli_fail(cmd, ctx, st);
    static const char *const names[] = {"observer", "luminaire", "luminance_cd_m2", "solid_angle_sr", "sigma_deg",
                                        "tau_deg", "position_index", "term", "background_cd_m2", "ugr",
                                        "eye_x", "eye_y", "eye_z", "view_azimuth_deg"};
    static const char *const units[] = {"", "", "cd/m2", "sr", "deg", "deg", "", "", "cd/m2", "", "m", "m", "m", "deg"};
    cli_table *t = cli_table_new(14, names, units);
    for (size_t o = 0; o < g->n_obs; o++) {
        int any = 0;
        for (size_t l = 0; l < g->n_lum; l++) {
            const lx_glare_term *x = &g->terms[o * g->n_lum + l];
            if (!x->visible) continue;
            any = 1;
            cli_table_str(t, sc->obs[o].name);
            cli_table_str(t, sc->lum[l].name);
            cli_table_num(t, x->luminance_cd_m2);
            cli_table_num(t, x->solid_angle_sr);
            cli_table_num(t, x->sigma_deg);
            cli_table_num(t, x->tau_deg);
            cli_table_num(t, x->position_index);
            cli_table_num(t, x->term);
            cli_table_num(t, g->background_cd_m2[o]);
            cli_table_num(t, g->ugr[o]);
            cli_observer_cells(t, &sc->obs[o]);
        }
        if (!any) { /* no glare source in view: one row, UGR empty */
            cli_table_str(t, sc->obs[o].name);
            cli_table_str(t, "");
            for (int k = 0; k < 6; k++) cli_table_num(t, NAN);
            cli_table_num(t, g->background_cd_m2[o]);
            cli_table_num(t, NAN);
            cli_observer_cells(t, &sc->obs[o]);
        }
    }
    int rc = CLI_OK;
    cli_output o;
    if (cli_output_open(&o, out, cmd) != 0) rc = CLI_INPUT;
    else {
        int ok = cli_table_write(t, fmt, o.fp, 1) == 0;
        if (cli_output_close(&o, ok, cmd) != 0 || !ok) rc = CLI_INPUT;
    }
    cli_table_free(t);
    lx_scene_glare_free(g);
    return rc;
}

int cmd_scene(int argc, char **argv)
{
    static const struct option opts[] = {{"explain", no_argument, 0, 'e'},      {"contributions", no_argument, 0, 'c'},
                                         {"format", required_argument, 0, 'f'}, {"backend", required_argument, 0, 'b'},
                                         {"png", required_argument, 0, 'p'},     {"glare", no_argument, 0, 'g'},
                                         {"surfaces", no_argument, 0, 's'},      {"check", no_argument, 0, 'k'},
                                         {"energy", no_argument, 0, 'E'},        {"emergency", no_argument, 0, 'M'},
                                         {"help", no_argument, 0, 'h'},         {0, 0, 0, 0}};
    const char *cmd = "scene", *out = NULL, *backend_text = NULL, *png_dir = NULL;
    int do_explain = 0, contrib = 0, glare = 0, do_surfaces = 0, do_check = 0, do_energy = 0, emergency = 0, c;
    cli_format fmt = CLI_FMT_TABLE;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'e': do_explain = 1; break;
        case 'c': contrib = 1; break;
        case 'g': glare = 1; break;
        case 's': do_surfaces = 1; break;
        case 'k': do_check = 1; break;
        case 'E': do_energy = 1; break;
        case 'M': emergency = 1; break;
        case 'o': out = optarg; break;
        case 'b': backend_text = optarg; break;
        case 'p': png_dir = optarg; break;
        case 'f': {
            int f = cli_format_parse(optarg);
            if (f < 0) {
                cli_error(cmd, "--format: expected table, csv or json, got '%s'", optarg);
                return CLI_USAGE;
            }
            fmt = (cli_format)f;
            break;
        }
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_bad_option(cmd, argv, c);
        }
    }
    if (optind + 1 != argc) {
        cli_error(cmd, optind >= argc ? "no scene file given (see luxcalc scene --help)" : "one scene file at a time");
        return CLI_USAGE;
    }
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    lx_backend backend = lx_backend_from_env();
    if (backend_text && lx_backend_parse(ctx, backend_text, &backend) != LX_OK) {
        cli_error(cmd, "--backend: expected auto, cpu or opencl, got '%s'", backend_text);
        lx_ctx_destroy(ctx);
        return CLI_USAGE;
    }
    lx_scene *sc = NULL;
    lx_scene_plan *plan = NULL;
    lx_scene_result *res = NULL;
    lx_status st = lx_scene_read_file(ctx, argv[optind], &sc);
    if (st == LX_OK && do_energy) {
        int erc = cli_energy_out(cmd, ctx, sc, fmt, out);
        lx_scene_free(sc);
        lx_ctx_destroy(ctx);
        return erc;
    }
    if (st == LX_OK && glare) {
        int grc = glare_out(cmd, ctx, sc, fmt, out);
        lx_scene_free(sc);
        lx_ctx_destroy(ctx);
        return grc;
    }
    if (st == LX_OK) st = lx_scene_plan_make_mode(ctx, sc, backend, emergency ? LX_SCENE_EMERGENCY : LX_SCENE_NORMAL, &plan);
    if (st == LX_OK) st = lx_scene_eval(ctx, sc, plan, NULL, &res);
    int rc = CLI_OK;
    if (st == LX_OK && png_dir && cli_make_dir(cmd, "--png", png_dir) != 0) {
        lx_scene_result_free(res);
        lx_scene_plan_free(plan);
        lx_scene_free(sc);
        lx_ctx_destroy(ctx);
        return CLI_INPUT;
    }
    if (st == LX_OK && png_dir) st = write_pngs(ctx, sc, plan, res, argv[optind], png_dir, cli_imperial());
    if (st == LX_OK && do_surfaces && !res->surfaces) {
        cli_error(cmd, "%s: --surfaces: interreflection is off (%s)", argv[optind], plan->reason[LX_EFFECT_INTERREFLECTION]);
        rc = CLI_INPUT;
    } else if (st != LX_OK) rc = cli_fail(cmd, ctx, st);
    else {
        cli_output o;
        if (cli_output_open(&o, out, cmd) != 0) rc = CLI_INPUT;
        else if (do_explain) {
            explain(o.fp, sc, plan, res, fmt);
            if (cli_output_close(&o, !ferror(o.fp), cmd) != 0) rc = CLI_RUNTIME;
        } else if (do_check) {
            cli_design_results dr;
            int drc = cli_design_evaluate(cmd, ctx, sc, backend, res, &dr);
            if (drc) rc = drc;
            else if (cli_check_write(o.fp, sc, dr.checks, fmt) != 0) rc = CLI_RUNTIME;
            cli_design_results_free(&dr);
            if (cli_output_close(&o, rc == CLI_OK, cmd) != 0 && rc == CLI_OK) rc = CLI_RUNTIME;
        } else if (do_surfaces) {
            cli_table *t = surfaces_table(res);
            int ok = t && cli_table_write(t, fmt, o.fp, 1) == 0;
            if (!t) cli_error(cmd, "out of memory");
            if (cli_output_close(&o, ok, cmd) != 0 || !ok) rc = t ? CLI_INPUT : CLI_RUNTIME;
            cli_table_free(t);
        } else {
            char **names = NULL;
            size_t nn = 0;
            cli_table *t = results(sc, plan, res, fmt, contrib, &names, &nn);
            int ok = t && cli_table_write(t, fmt, o.fp, 1) == 0;
            if (!t) cli_error(cmd, "out of memory");
            if (cli_output_close(&o, ok, cmd) != 0 || !ok) rc = CLI_RUNTIME;
            cli_table_free(t);
            for (size_t i = 0; i < nn; i++) free(names[i]);
            free(names);
        }
    }
    lx_scene_result_free(res);
    lx_scene_plan_free(plan);
    lx_scene_free(sc);
    lx_ctx_destroy(ctx);
    return rc;
}
