/* bench_accuracy_nearfield.c - `luxcalc bench accuracy`, the near-field decision: when a grid
 * takes the point model and when it integrates the luminous opening. A narrow downlight (the case
 * where a rule by distance / size alone goes wrong) from 0.3 to 10 m, every policy against the
 * opening integrated to 1e-9. */
#include "cli/cli.h"
#include "bench_accuracy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180)

enum { N_DIST = 25, N_ANG = 6, NPT = N_DIST * N_ANG, NROW = 7 };

/* Receivers on a work plane (normal +z) at distances 0.3 .. 10 m from the downlight (log-spaced),
 * on its axis and 3, 6, 10, 20 and 40 deg off it, off the C0 plane too (as tests/test_nearfield.c). */
static void points(double *pts, double *dist)
{
    static const double ang[N_ANG] = {0, 3, 6, 10, 20, 40};
    size_t n = 0;
    for (int i = 0; i < N_DIST; i++) {
        double d = 0.3 * pow(10 / 0.3, i / (double)(N_DIST - 1));
        for (int k = 0; k < N_ANG; k++, n++) {
            pts[3 * n] = d * sin(ang[k] * DEG);
            pts[3 * n + 1] = 0.3 * pts[3 * n];
            pts[3 * n + 2] = -d * cos(ang[k] * DEG);
            dist[n] = sqrt(pts[3 * n] * pts[3 * n] + pts[3 * n + 1] * pts[3 * n + 1] + pts[3 * n + 2] * pts[3 * n + 2]);
        }
    }
}

typedef struct nf_job {
    lx_ctx *ctx;
    const lx_placement *pl;
    const double *pts;
    lx_grid_opts opts;
    int rule5;                  /* the former rule: the point model where d >= 5 x size, else cells */
    const lx_placement *cells;  /* rule5: k x k point sources per k (index k - 1), flux / k^2 each */
    const int *kpt;             /* rule5: k for each point (1: the point model) */
    double *E;
    int ok;
} nf_job;

static void nf_run(void *arg)
{
    nf_job *j = arg;
    static const double up[3] = {0, 0, 1};
    lx_grid_opts o = j->opts;
    if (!j->rule5) {
        j->ok = lx_grid_illuminance(j->ctx, j->pl, 1, j->pts, NPT, up, 1, &o, j->E) == LX_OK;
        return;
    }
    j->ok = 1;
    o.model = LX_MODEL_POINT;
    for (size_t i = 0; i < NPT && j->ok; i++) {
        int k = j->kpt[i];
        const lx_placement *pl = k == 1 ? j->pl : j->cells + (size_t)(k - 1) * 64 * 64;
        j->ok = lx_grid_illuminance(j->ctx, pl, (size_t)k * k, j->pts + 3 * i, 1, up, 1, &o, j->E + i) == LX_OK;
    }
}

/* The former rule's cells: for k = 2..kmax, k x k point sources of model cm with flux F / k^2 each
 * (luminaires into cl[k - 1]) over the side x side opening, into cells. A CLI exit code. */
static int make_cells(lx_ctx *ctx, lx_lum_model cm, double F, double side, int kmax, lx_placement *cells,
                      lx_luminaire *cl[64])
{
    for (int k = 2; k <= kmax; k++) {
        cm.flux_lm = F / (k * k);
        if (lx_luminaire_from_model(ctx, &cm, &cl[k - 1])) return cli_fail("bench", ctx, LX_EINVAL);
        for (int u = 0; u < k; u++)
            for (int v = 0; v < k; v++) {
                lx_placement *x = &cells[(size_t)(k - 1) * 64 * 64 + (size_t)u * k + v];
                x->lum = cl[k - 1];
                x->pos_m[0] = (-0.5 + (u + 0.5) / k) * side;
                x->pos_m[1] = (-0.5 + (v + 0.5) / k) * side;
                x->aim[2] = -1;
            }
    }
    return CLI_OK;
}

/* The section's header: the downlight, the receivers, the reference and the policies. */
static void nf_header(FILE *o, double beam, double S, double F, double side, double size)
{
    fprintf(o, "## bench accuracy: the near-field decision\n\n");
    fprintf(o, "When a grid takes the point model for a luminaire-receiver pair and when it integrates the luminous "
               "opening. A Warn downlight (beam %.1f deg, S = %.1f, %.0f lm) with a %.1f x %.1f m opening (size: the "
               "diagonal, %.3f m) above %d receivers on a work plane: %d distances from 0.3 to 10 m (log-spaced), on the "
               "axis and 3, 6, 10, 20 and 40 deg off it (`lx_grid_illuminance`, bilinear, one thread). Reference: every "
               "pair integrated over the opening to 1e-9 (`model area`). The former five-times rule (emulated: the point "
               "model at d >= 5 size, else k x k point-source cells, k = floor(5 size / d) + 1) judged by distance alone; "
               "`auto` estimates each pair's point-model error from probes of the opening (its centre against a 3 x 3 "
               "Simpson and a 2 x 2 Gauss rule) and takes the point model only where the estimates at the point add up "
               "to at most half the tolerance. Max and RMS |dE|/E over the points; pairs integrated (the former rule: "
               "cut into cells); the worst pair that took the point path; time per point, median of 5. The point "
               "model's largest relative errors are 40 deg off the axis, outside the beam (the intensity there is "
               "%.1e of the peak's), where the lobe changes most across the opening.\n\n",
            beam, S, F, side, side, size, NPT, N_DIST, pow(cos(40 * DEG), S));
    fprintf(o, "| policy | max \\|dE\\|/E | RMS | pairs integrated | worst point-path pair | time per point |\n"
               "|---|---|---|---|---|---|\n");
}

/* What every policy row runs on: the downlight, the points, the former rule's cells and k per
 * point, and the reference illuminance. */
typedef struct {
    lx_ctx *ctx;
    const lx_placement *pl, *cells;
    const double *pts, *ref;
    const int *kpt;
} nf_case;

static const char *const nf_names[NROW] = {"point model everywhere",
                                           "former five-times rule (d / size >= 5: point)",
                                           "auto, tolerance 1e-2",
                                           "auto, tolerance 1e-3",
                                           "auto, tolerance 1e-4 (the default)",
                                           "auto, tolerance 1e-5",
                                           "area everywhere (tolerance 1e-4)"};
static const char *const nf_labels[NROW] = {"point", "5x rule", "auto 1e-2", "auto 1e-3", "auto 1e-4", "auto 1e-5", "area"};
static const double nf_tols[NROW] = {0, 0, 1e-2, 1e-3, 1e-4, 1e-5, 1e-4};

/* Policy row r: its errors against the reference, the pairs it integrated, its worst point-path
 * pair and its time; the row's plot point into *pp. 0 when the policy failed (a row saying so). */
static int policy_row(FILE *o, const nf_case *nc, int r, lx_plot_point *pp)
{
    lx_ctx *ctx = nc->ctx;
    const int *kpt = nc->kpt;
    const double *ref = nc->ref;
    double E[NPT];
    nf_job j = {ctx, nc->pl, nc->pts, {.backend = LX_BACKEND_CPU, .threads = 1, .nearfield_tol = nf_tols[r]}, r == 1, nc->cells,
                kpt, E, 0};
    j.opts.model = r == 0 ? LX_MODEL_POINT : r == NROW - 1 ? LX_MODEL_AREA : LX_MODEL_AUTO;
    lx_counters c0, c1;
    lx_ctx_counters(ctx, &c0);
    nf_run(&j);
    lx_ctx_counters(ctx, &c1);
    if (!j.ok) {
        fprintf(o, "| %s | failed (%s) | | | | |\n", nf_names[r], lx_ctx_errmsg(ctx));
        return 0;
    }
    unsigned long long near = c1.nearfield_pairs - c0.nearfield_pairs;
    int subdivided = 0;
    if (r == 1)
        for (int i = 0; i < NPT; i++) subdivided += kpt[i] > 1;
    double mx = 0, ss = 0, far = -1;
    for (int i = 0; i < NPT; i++) {
        double e = fabs(E[i] / ref[i] - 1);
        mx = fmax(mx, e);
        ss += e * e;
    }
    /* the pairs on the point path: where the result is the point model's (rows 0, 1: by construction) */
    double Ep[NPT];
    nf_job pj = {ctx, nc->pl, nc->pts, {.model = LX_MODEL_POINT, .backend = LX_BACKEND_CPU, .threads = 1}, 0, nc->cells, kpt, Ep, 0};
    nf_run(&pj);
    for (int i = 0; i < NPT; i++)
        if (pj.ok && (r == 1 ? kpt[i] == 1 : E[i] == Ep[i])) far = fmax(far, fabs(E[i] / ref[i] - 1));
    double t = acc_time(nf_run, &j, 1000) / NPT;
    char a[32], b[32], c[32], d[32], n[32];
    acc_fmt_err(a, sizeof a, mx);
    acc_fmt_err(b, sizeof b, sqrt(ss / NPT));
    acc_fmt_err(c, sizeof c, far < 0 ? NAN : far);
    acc_fmt_time(d, sizeof d, t);
    snprintf(n, sizeof n, "%llu of %d", r == 1 ? (unsigned long long)subdivided : near, NPT);
    fprintf(o, "| %s | %s | %s | %s | %s | %s |\n", nf_names[r], a, b, n, far < 0 ? "(none)" : c, d);
    *pp = (lx_plot_point){t, mx, nf_labels[r], r == 0 || r == 1 ? 0 : r == NROW - 1 ? 2 : 1};
    return 1;
}

/* The single point where the former rule first trusted the point model, and 10 m on the axis:
 * point model against the opening integrated. */
static void axis_note(lx_ctx *ctx, FILE *o, const lx_placement *pl, double size)
{
    double q[3] = {0, 0, -5 * size * 1.06}, ep, ea;
    static const double up[3] = {0, 0, 1};
    lx_grid_opts o1 = {.model = LX_MODEL_POINT}, o2 = {.model = LX_MODEL_AREA, .nearfield_tol = 1e-9};
    double q10[3] = {0, 0, -10}, ep10, ea10;
    if (!lx_grid_illuminance(ctx, pl, 1, q, 1, up, 1, &o1, &ep) && !lx_grid_illuminance(ctx, pl, 1, q, 1, up, 1, &o2, &ea) &&
        !lx_grid_illuminance(ctx, pl, 1, q10, 1, up, 1, &o1, &ep10) &&
        !lx_grid_illuminance(ctx, pl, 1, q10, 1, up, 1, &o2, &ea10))
        fprintf(o, "\nOn the axis at %.2f m (d / size = %.1f, where the five-times rule took the point model): point "
                   "model %.5g lx, opening integrated %.5g lx (%+.1f %%). At 10 m on the axis (d / size = %.0f) this "
                   "beam's point model still errs by %+.2e.\n",
                -q[2], -q[2] / size, ep, ea, 100 * (ep / ea - 1), 10 / size, ep10 / ea10 - 1);
}

int acc_nearfield(lx_ctx *ctx, FILE *o, const char *png)
{
    const double F = 1000, beam = 15.7, side = 0.1, size = side * sqrt(2.0);
    double S;
    if (lx_warn_exponent_from_beam(ctx, beam * DEG, &S)) return cli_fail("bench", ctx, LX_EINVAL);
    lx_lum_model mdl = {.kind = LX_LUM_MODEL_WARN, .flux_lm = F, .exponent = S, .width_m = side, .length_m = side};
    lx_luminaire *lum = NULL;
    if (lx_luminaire_from_model(ctx, &mdl, &lum)) return cli_fail("bench", ctx, LX_EINVAL);
    /* the same lobe as a point source of flux / k^2, for the emulated former rule's cells */
    lx_lum_model cm = mdl;
    cm.width_m = cm.length_m = 0;
    lx_luminaire *cl[64] = {NULL};
    double pts[3 * NPT], dist[NPT], ref[NPT];
    int kpt[NPT], kmax = 1;
    points(pts, dist);
    for (int i = 0; i < NPT; i++) {
        kpt[i] = dist[i] >= 5 * size ? 1 : (int)floor(5 * size / dist[i]) + 1;
        if (kpt[i] > 64) kpt[i] = 64;
        if (kpt[i] > kmax) kmax = kpt[i];
    }
    lx_placement pl = {.lum = lum, .pos_m = {0, 0, 0}, .aim = {0, 0, -1}};
    lx_placement *cells = calloc((size_t)kmax * 64 * 64, sizeof *cells);
    if (!cells) return cli_fail("bench", ctx, LX_ENOMEM);
    int rc = make_cells(ctx, cm, F, side, kmax, cells, cl);
    if (rc) goto done;
    nf_job rj = {ctx, &pl, pts, {.model = LX_MODEL_AREA, .backend = LX_BACKEND_CPU, .threads = 1, .nearfield_tol = 1e-9},
                 0, cells, kpt, ref, 0};
    nf_run(&rj);
    if (!rj.ok) {
        rc = cli_fail("bench", ctx, LX_EINVAL);
        goto done;
    }
    nf_header(o, beam, S, F, side, size);
    nf_case nc = {ctx, &pl, cells, pts, ref, kpt};
    lx_plot_point pp[NROW];
    int np = 0;
    for (int r = 0; r < NROW; r++) np += policy_row(o, &nc, r, &pp[np]);
    axis_note(ctx, o, &pl, size);
    fprintf(o, "\n");
    if (png && np) {
        static const char *series[3] = {"by distance alone", "auto (estimated error)", "area everywhere"};
        if (lx_error_time_write_png(ctx, png, "Near field: max |\u0394E| / E of a 15.7\u00b0 downlight, 0.3 to 10 m",
                                    "time per point (s)", "max |\u0394E| / E", (size_t)np, pp, 3, series))
            rc = cli_fail("bench", ctx, LX_EIO);
    }
done:
    for (int k = 0; k < 64; k++) lx_luminaire_free(cl[k]);
    free(cells);
    lx_luminaire_free(lum);
    return rc;
}
