/* cmd_grid.c - `luxcalc grid`: illuminance on a plane of points from one luminaire given by flags
 * or from a scene's luminaires (--scene): csv x,y,z,illuminance_lx per point (a grid of rows and
 * columns in the table format), the summary, and an isolux plot (--png). */
#include "grid.h"
#include "lighting.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc grid (--ies FILE --at X,Y,Z | --scene FILE) --plane z=H --area A0:A1,B0:B1\n"
    "                    (--spacing S | --points NxM) [OPTIONS]\n"
    "\n"
    "Illuminance E = I(C, gamma) cos(xi) / d^2 on a plane of points, printed as csv x,y,z,illuminance_lx\n"
    "(one row per point, A fastest; --format table prints the grid as rows and columns), then the\n"
    "summary E_avg,E_min,E_max,U0 (U0 = E_min / E_avg), the same as illuminance_avg_lx, _min_lx,\n"
    "_max_lx, uniformity_u0 (the names scenes use) and uniformity_min_max (E_min / E_max), on\n"
    "stderr, or on stdout instead of the points with --summary.\n"
    "\n"
    "options:\n"
    "  --ies FILE              the luminaire (IES LM-63 or EULUMDAT)\n"
    "  --at X,Y,Z              its position (metres; units accepted: 2m,1.5m,2.8m or 6.5,5,9 ft)\n"
    "  --aim X,Y,Z             the direction its nadir points (default 0,0,-1: straight down)\n"
    "  --rotate ANGLE          turn of the C0 plane about the aim axis (default 0; C0 along +x)\n"
    "  --scene FILE            the luminaires of a scene file instead (every kind: point, spot,\n"
    "                          disk, rect, IES/LDT); without --plane its one grid receiver\n"
    "  --plane z=H|x=H|y=H     the plane; its axes are (x, y), (y, z), (x, z)\n"
    "  --area A0:A1,B0:B1      extent along the plane's two axes (metres, or with units)\n"
    "  --spacing S             points at A0, A0+S, ..., A1 (inclusive when on the grid)\n"
    "  --points NxM            N points along A and M along B, ends included\n"
    "  --points-at edges|centres  edges (default, as above) or the centres of cells no larger\n"
    "                          than S (or N x M cells), S/2 inside the edges (EN 12464-1, DIALux)\n"
    "  --normal X,Y,Z          receiver normal (default the plane's axis towards +z, +x or +y)\n"
    "  --model auto|point|area auto (default): each pair with a luminous opening keeps the point\n"
    "                          model where its estimated error (13 probes over the opening) keeps\n"
    "                          the point within --tolerance, else the opening is integrated;\n"
    "                          point: every luminaire a point; area: every pair integrated\n"
    "  --tolerance T           relative tolerance of each point's illuminance (default 1e-4)\n"
    "  --interp bilinear|smooth|table  intensity interpolation (default bilinear; table: the\n"
    "                          cosine-indexed table the OpenCL kernel uses)\n"
    "  --table-rows N          rows per hemisphere of that table (default 1024; implies --interp\n"
    "                          table): fewer is faster and coarser (luxcalc bench grid shows both)\n"
    "  --maintenance MF        maintenance factor in (0, 1] (default 1)\n"
    "  --backend auto|cpu|opencl  (also LX_BACKEND); opencl implies --interp table\n"
    "  --summary               print only the summary\n"
    "  --png FILE              also draw an isolux plot: false colour, contours labelled in lx at\n"
    "                          1-2-5 levels, the luminaires and their aim, axes in metres, a legend\n"
    "                          and the statistics (in fc and ft with --units imperial)\n"
    "  --png-style falsecolor|white   the plot's background (white: coloured contours only)\n"
    "  --format table|csv|tsv|json, -o FILE, --precision N, --units imperial\n"
    "\n"
    "examples:\n"
    "  luxcalc grid --ies samples/ies/downlight_lambert_1000lm.ies --at 2,2,2.8 --plane z=0.8 \\\n"
    "      --area 0:4,0:4 --spacing 0.5 --summary\n"
    "  luxcalc grid --scene samples/scenes/office.scene --plane z=0.75 --area 0:4,0:3 --spacing 0.25 \\\n"
    "      --points-at centres --png office.png --summary\n";

typedef struct grid_args {
    const char *ies, *scene, *at, *aim, *rot, *plane, *area, *spacing, *points, *normal, *outpath, *mf, *png, *tol;
    int summary, interp_set, centres, white;
    cli_format fmt;
    lx_grid_opts go;
} grid_args;

/* the options; returns -1 to go on, else the exit code */
static int parse(int argc, char **argv, grid_args *g)
{
    static const struct option opts[] = {
        {"ies", required_argument, NULL, 'i'},      {"at", required_argument, NULL, 'a'},
        {"aim", required_argument, NULL, 'A'},      {"rotate", required_argument, NULL, 'r'},
        {"plane", required_argument, NULL, 'p'},    {"area", required_argument, NULL, 'R'},
        {"spacing", required_argument, NULL, 's'},  {"points", required_argument, NULL, 'n'},
        {"normal", required_argument, NULL, 'N'},   {"model", required_argument, NULL, 'm'},
        {"interp", required_argument, NULL, 'I'},   {"maintenance", required_argument, NULL, 'M'},
        {"backend", required_argument, NULL, 'b'},  {"summary", no_argument, NULL, 'S'},
        {"png", required_argument, NULL, 'P'},      {"table-rows", required_argument, NULL, 'T'},
        {"format", required_argument, NULL, 'f'},   {"output", required_argument, NULL, 'o'},
        {"scene", required_argument, NULL, 'x'},    {"points-at", required_argument, NULL, 'C'},
        {"png-style", required_argument, NULL, 'W'}, {"help", no_argument, NULL, 'h'},
        {"tolerance", required_argument, NULL, 'O'},
        {NULL, 0, NULL, 0},
    };
    int c;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'i': g->ies = optarg; break;
        case 'a': g->at = optarg; break;
        case 'A': g->aim = optarg; break;
        case 'r': g->rot = optarg; break;
        case 'p': g->plane = optarg; break;
        case 'R': g->area = optarg; break;
        case 's': g->spacing = optarg; break;
        case 'n': g->points = optarg; break;
        case 'N': g->normal = optarg; break;
        case 'M': g->mf = optarg; break;
        case 'O': g->tol = optarg; break;
        case 'S': g->summary = 1; break;
        case 'P': g->png = optarg; break;
        case 'x': g->scene = optarg; break;
        case 'o': g->outpath = optarg; break;
        case 'C':
            if (!strcmp(optarg, "centres") || !strcmp(optarg, "centers")) g->centres = 1;
            else if (!strcmp(optarg, "edges")) g->centres = 0;
            else return cli_error("grid", "--points-at: expected edges or centres (got '%s')", optarg), CLI_USAGE;
            break;
        case 'W':
            if (!strcmp(optarg, "white")) g->white = 1;
            else if (!strcmp(optarg, "falsecolor")) g->white = 0;
            else return cli_error("grid", "--png-style: expected falsecolor or white (got '%s')", optarg), CLI_USAGE;
            break;
        case 'T': {
            char *e;
            long v = strtol(optarg, &e, 10);
            if (e == optarg || *e || v < 2 || v > 16384)
                return cli_error("grid", "--table-rows: expected a whole number from 2 to 16384 (got '%s')", optarg), CLI_USAGE;
            g->go.table_n = (int)v;
            break;
        }
        case 'f':
            if (lt_format("grid", optarg, &g->fmt)) return CLI_USAGE;
            break;
        case 'm':
            if (!strcmp(optarg, "point")) g->go.model = LX_MODEL_POINT;
            else if (!strcmp(optarg, "auto")) g->go.model = LX_MODEL_AUTO;
            else if (!strcmp(optarg, "area")) g->go.model = LX_MODEL_AREA;
            else return cli_error("grid", "--model: expected auto, point or area (got '%s')", optarg), CLI_USAGE;
            break;
        case 'I':
            g->interp_set = 1;
            if (!strcmp(optarg, "bilinear")) g->go.interp = LX_INTERP_BILINEAR;
            else if (!strcmp(optarg, "smooth")) g->go.interp = LX_INTERP_SMOOTH;
            else if (!strcmp(optarg, "table")) g->go.interp = LX_INTERP_TABLE;
            else return cli_error("grid", "--interp: expected bilinear, smooth or table (got '%s')", optarg), CLI_USAGE;
            break;
        case 'b':
            if (!strcmp(optarg, "auto")) g->go.backend = LX_BACKEND_AUTO;
            else if (!strcmp(optarg, "cpu")) g->go.backend = LX_BACKEND_CPU;
            else if (!strcmp(optarg, "opencl")) g->go.backend = LX_BACKEND_OPENCL;
            else return cli_error("grid", "--backend: expected auto, cpu or opencl (got '%s')", optarg), CLI_USAGE;
            break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_bad_option("grid", argv, c);
        }
    }
    if (optind < argc) return cli_error("grid", "unexpected argument '%s'", argv[optind]), CLI_USAGE;
    int flags = g->plane || g->area || g->spacing || g->points;
    if (!g->ies == !g->scene || (g->ies && !g->at) || (g->scene && g->at) || ((g->ies || flags) && (!g->plane || !g->area || !g->spacing == !g->points)))
        return cli_error("grid", "needs --ies FILE --at X,Y,Z (or --scene FILE), --plane, --area and one of --spacing or "
                                 "--points (luxcalc grid --help)"),
               CLI_USAGE;
    if (g->go.table_n) {
        if (g->interp_set && g->go.interp != LX_INTERP_TABLE)
            return cli_error("grid", "--table-rows sets the rows of --interp table"), CLI_USAGE;
        g->go.interp = LX_INTERP_TABLE;
    }
    if (g->go.backend == LX_BACKEND_AUTO) g->go.backend = lx_backend_from_env();
    if (g->go.backend == LX_BACKEND_OPENCL) {
        if (g->interp_set && g->go.interp != LX_INTERP_TABLE)
            return cli_error("grid", "--backend opencl computes --interp table only"), CLI_USAGE;
        g->go.interp = LX_INTERP_TABLE;
    }
    return -1;
}

/* three plain numbers X,Y,Z (a direction) */
static int triple(const char *opt, const char *s, double v[3])
{
    char *e;
    for (int i = 0; i < 3; i++) {
        v[i] = strtod(s, &e);
        if (e == s || !isfinite(v[i]) || (i < 2 && *e != ',') || (i == 2 && *e)) {
            cli_error("grid", "%s: expected X,Y,Z (got '%s')", opt, s);
            return CLI_USAGE;
        }
        s = e + 1;
    }
    return 0;
}

/* the plane of the flags: --plane, --area, --spacing or --points, --points-at, --normal */
static int make_plane(lx_ctx *ctx, const grid_args *g, lx_plane *p)
{
    if (strlen(g->plane) < 3 || g->plane[1] != '=' || !strchr("xyz", g->plane[0])) {
        cli_error("grid", "--plane: expected z=H, x=H or y=H (got '%s')", g->plane);
        return CLI_USAGE;
    }
    double level, r[4], sp = 0;
    int rc;
    if ((rc = lt_quantity(ctx, "grid", "--plane", g->plane + 2, LX_Q_LENGTH, NULL, 0, &level))) return rc;
    if ((rc = lt_lengths(ctx, "grid", "--area", g->area, ":,:", "A0:A1,B0:B1 (metres; 0:13,0:10 ft)", r))) return rc;
    size_t na = 0, nb = 0;
    if (g->spacing) {
        if ((rc = lt_quantity(ctx, "grid", "--spacing", g->spacing, LX_Q_LENGTH, NULL, 0, &sp))) return rc;
        if (!(sp > 0)) return cli_error("grid", "--spacing must be positive"), CLI_USAGE;
    } else {
        char *e;
        long a = strtol(g->points, &e, 10);
        long b = (*e == 'x' || *e == 'X') ? strtol(e + 1, &e, 10) : 0;
        if (a < 1 || b < 1 || *e) return cli_error("grid", "--points: expected NxM with N, M >= 1 (got '%s')", g->points), CLI_USAGE;
        na = (size_t)a, nb = (size_t)b;
    }
    lx_status st = g->centres ? lx_plane_cells(ctx, g->plane[0], level, r[0], r[1], r[2], r[3], sp, na, nb, p)
                              : lx_plane_axis(ctx, g->plane[0], level, r[0], r[1], r[2], r[3], sp, na, nb, p);
    if (st) return cli_fail("grid", ctx, st);
    if (g->normal) {
        double nv[3];
        if ((rc = triple("--normal", g->normal, nv))) return rc;
        double len = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        if (!(len > 0)) return cli_error("grid", "--normal must not be zero"), CLI_USAGE;
        for (int k = 0; k < 3; k++) p->normal[k] = nv[k] / len;
    }
    return 0;
}

/* the scene with one more grid receiver (the plane of the flags) after its own, read from memory */
static int read_scene(lx_ctx *ctx, const char *path, const lx_plane *p, int with_plane, lx_scene **sc)
{
    FILE *f = strcmp(path, "-") ? fopen(path, "rb") : stdin;
    if (!f) return cli_error("grid", "%s: cannot open: %s", path, strerror(errno)), CLI_INPUT;
    /* bounded like the library's own reader (README "Bounded on any input"): the scene-file size
     * limit, and a NUL byte (binary data, /dev/zero) refused in the block it arrives in */
    size_t cap = 1 << 16, len = 0, limit = lx_ctx_input_limit(ctx, LX_INPUT_SCENE);
    char *text = malloc(cap + 1024);
    for (size_t k; text && (k = fread(text + len, 1, cap - len, f)) > 0;) {
        const char *nul = memchr(text + len, '\0', k);
        len += k;
        if (nul || len > limit) {
            long line = 1;
            for (const char *q = text; nul && q < nul; q++) line += *q == '\n';
            if (nul)
                cli_error("grid", "%s:%ld: binary data (NUL byte at offset %zu); not a text file", path, line,
                          (size_t)(nul - text));
            else if (limit % (1u << 20) == 0)
                cli_error("grid", "%s: larger than %zu MB, the limit for a scene file (raise with LX_MAX_INPUT_MB)", path,
                          limit >> 20);
            else
                cli_error("grid", "%s: larger than %zu bytes, the limit for a scene file (raise with LX_MAX_INPUT_MB)",
                          path, limit);
            if (f != stdin) fclose(f);
            free(text);
            return CLI_INPUT;
        }
        if (len == cap) {
            char *nt = realloc(text, 2 * cap + 1024);
            if (!nt) free(text);
            text = nt, cap *= 2;
        }
    }
    int bad = ferror(f);
    if (f != stdin) fclose(f);
    if (!text) return cli_error("grid", "out of memory"), CLI_RUNTIME;
    if (bad) return free(text), cli_error("grid", "%s: cannot read: %s", path, strerror(errno)), CLI_INPUT;
    if (with_plane) {
        int k = 2;
        for (int q = 0; q < 3; q++)
            if (fabs(p->u[q]) < 1e-12 && fabs(p->v[q]) < 1e-12) k = q;
        int ia = k == 0 ? 1 : 0, ib = k == 2 ? 1 : 2;
        char rng[3][96];
        snprintf(rng[k], sizeof rng[k], "%.17g m", p->origin_m[k]);
        snprintf(rng[ia], sizeof rng[ia], "%.17g m, %.17g m", p->a0, p->a1);
        snprintf(rng[ib], sizeof rng[ib], "%.17g m, %.17g m", p->b0, p->b1);
        len += (size_t)snprintf(text + len, 1024,
                                "\n[receiver luxcalc_grid]\ntype = grid\nx = %s\ny = %s\nz = %s\npoints = %zu, %zu\n"
                                "normal = %.17g, %.17g, %.17g\n",
                                rng[0], rng[1], rng[2], p->na, p->nb, p->normal[0], p->normal[1], p->normal[2]);
    }
    lx_status st = lx_scene_read_mem(ctx, path, text, len, sc);
    free(text);
    return st ? cli_fail("grid", ctx, st) : 0;
}

/* A plane every point of which has its back to every luminaire gets zeros: say so, and say so
 * when the light does not reach a plane that faces it. */
static void warn_zeros(const double *pts, size_t n, const double *normal, int shared, const double (*pos)[3], size_t m,
                       const double *E)
{
    if (cli_quiet) return;
    for (size_t i = 0; i < n; i++)
        if (E[i] != 0) return;
    int faces = 0;
    for (size_t i = 0; i < n && !faces; i++) {
        const double *q = pts + 3 * i, *nv = shared ? normal : normal + 3 * i;
        for (size_t l = 0; l < m && !faces; l++)
            faces = (pos[l][0] - q[0]) * nv[0] + (pos[l][1] - q[1]) * nv[1] + (pos[l][2] - q[2]) * nv[2] > 0;
    }
    if (!faces)
        cli_error("grid", "warning: the plane faces away from every luminaire (its normal %.3g,%.3g,%.3g points away from "
                          "them), so every point gets 0 lx; give --normal or move the plane",
                  normal[0], normal[1], normal[2]);
    else cli_error("grid", "warning: every point gets 0 lx: the luminaires' light does not reach the plane (check --aim)");
}

/* the points' table (or the grid itself in the table format), then the summary */
static int output(const grid_args *g, const lx_plane *p, const double *pts, const double *E, size_t n)
{
    cli_table *ts = cli_grid_summary(E, n, g->fmt);
    if (!ts) return cli_error("grid", "out of memory"), CLI_RUNTIME;
    int rc;
    if (g->summary) rc = lt_write("grid", ts, g->fmt, g->outpath);
    else if (g->fmt == CLI_FMT_TABLE) {
        cli_output o;
        if (cli_output_open(&o, g->outpath, "grid") != 0) rc = CLI_INPUT;
        else {
            int bad = cli_grid_table(o.fp, p, E);
            rc = cli_output_close(&o, !bad, "grid") || bad ? CLI_RUNTIME : CLI_OK;
        }
        if (!rc && !cli_quiet) fputc('\n', stderr), cli_table_write(ts, g->fmt, stderr, 0);
    } else {
        static const char *const names[] = {"x", "y", "z", "illuminance_lx"};
        static const char *const units[] = {"m", "m", "m", "lx"};
        cli_table *t = cli_table_new(4, names, units);
        for (size_t i = 0; i < n; i++) {
            for (int k = 0; k < 3; k++) cli_table_num(t, pts[3 * i + k]);
            cli_table_num(t, E[i]);
        }
        rc = lt_write("grid", t, g->fmt, g->outpath);
        cli_table_free(t);
        if (!rc && !cli_quiet) cli_table_write(ts, g->fmt == CLI_FMT_JSON ? CLI_FMT_JSON : g->fmt, stderr, 0);
    }
    cli_table_free(ts);
    return rc;
}

/* one luminaire from the flags */
static int from_ies(lx_ctx *ctx, const grid_args *g, const lx_plane *p, double **pts, double **E, size_t *n, lx_plot_mark *mk)
{
    lx_placement pl = {.aim = {0, 0, -1}};
    int rc;
    if ((rc = lt_lengths(ctx, "grid", "--at", g->at, ",,", "X,Y,Z (metres; 2m,1.5m,2.8m or 6.5,5,9 ft)", pl.pos_m))) return rc;
    if (g->aim && (rc = triple("--aim", g->aim, pl.aim))) return rc;
    if (g->rot && (rc = lt_quantity(ctx, "grid", "--rotate", g->rot, LX_Q_ANGLE, "deg", 0, &pl.rotate_rad))) return rc;
    lx_luminaire *lum = NULL;
    lx_status st = lx_luminaire_read_file(ctx, g->ies, &lum);
    if (!st) st = lx_plane_points(ctx, p, pts, n);
    if (!st && !(*E = malloc(*n * sizeof **E))) st = LX_ENOMEM;
    lx_grid_opts go = g->go;
    pl.lum = lum;
    if (!st) st = lx_grid_illuminance(ctx, &pl, 1, *pts, *n, p->normal, 1, &go, *E);
    lx_luminaire_free(lum);
    if (st == LX_ENOMEM && !lx_ctx_errmsg(ctx)[0]) return cli_error("grid", "out of memory"), CLI_RUNTIME;
    if (st) return cli_fail("grid", ctx, st);
    memcpy(mk->pos_m, pl.pos_m, sizeof mk->pos_m);
    memcpy(mk->aim, pl.aim, sizeof mk->aim);
    const double pos[1][3] = {{pl.pos_m[0], pl.pos_m[1], pl.pos_m[2]}};
    warn_zeros(*pts, *n, p->normal, 1, pos, 1, *E);
    return 0;
}

/* the luminaires of a scene: the plane of the flags as one more receiver, or the scene's one grid */
static int from_scene(lx_ctx *ctx, const grid_args *g, lx_plane *p, double **pts, double **E, size_t *n,
                      lx_plot_mark **marks, size_t *n_marks, lx_scene **scene)
{
    lx_scene *sc = NULL;
    lx_scene_plan *plan = NULL;
    lx_scene_result *res = NULL;
    int rc = read_scene(ctx, g->scene, p, g->plane != NULL, &sc);
    if (rc) return rc;
    size_t r = sc->n_rec;
    if (g->plane) r = sc->n_rec - 1;
    else {
        int grids = 0;
        for (size_t k = 0; k < sc->n_rec; k++)
            if (sc->rec[k].kind == LX_SREC_GRID) grids++, r = k;
        if (grids != 1) {
            cli_error("grid", "%s: the scene has %d grid receivers: give --plane, --area and --spacing (or use luxcalc scene)",
                      g->scene, grids);
            lx_scene_free(sc);
            return CLI_USAGE;
        }
        lx_status sp = lx_scene_receiver_plane(ctx, sc, r, p);
        if (sp) {
            lx_scene_free(sc);
            return cli_fail("grid", ctx, sp);
        }
    }
    lx_status st = lx_scene_plan_make(ctx, sc, (int)g->go.backend, &plan);
    if (!st) st = lx_scene_eval(ctx, sc, plan, NULL, &res);
    if (!st) {
        const lx_scene_receiver *rc_ = &sc->rec[r];
        *n = rc_->n;
        *pts = malloc(3 * *n * sizeof **pts);
        *E = malloc(*n * sizeof **E);
        double (*pos)[3] = malloc((sc->n_lum ? sc->n_lum : 1) * sizeof *pos);
        *marks = cli_scene_marks(sc);
        if (!*pts || !*E || !pos || (!*marks && sc->n_lum)) {
            cli_error("grid", "out of memory");
            rc = CLI_RUNTIME;
        } else {
            memcpy(*pts, rc_->points, 3 * *n * sizeof **pts);
            for (size_t i = 0; i < *n; i++) (*E)[i] = res->E_lx[res->first[r] + i] * (g->mf ? g->go.maintenance_factor : 1);
            for (size_t l = 0; l < sc->n_lum; l++) memcpy(pos[l], sc->lum[l].pos_m, sizeof pos[l]);
            *n_marks = sc->n_lum;
            warn_zeros(*pts, *n, rc_->normal, 1, (const double (*)[3])pos, sc->n_lum, *E);
        }
        free(pos);
    }
    if (st) rc = cli_fail("grid", ctx, st);
    lx_scene_result_free(res);
    lx_scene_plan_free(plan);
    *scene = sc; /* the marks' names are the scene's */
    return rc;
}

int cmd_grid(int argc, char **argv)
{
    grid_args g = {.fmt = CLI_FMT_CSV, .go = {.model = LX_MODEL_AUTO}};
    int rc = parse(argc, argv, &g);
    if (rc >= 0) return rc;
    lx_ctx *ctx = cli_ctx("grid");
    if (!ctx) return CLI_RUNTIME;
    double *pts = NULL, *E = NULL;
    size_t n = 0, n_marks = 0;
    lx_plot_mark mk = {{0, 0, 0}, {0, 0, -1}, NULL}, *marks = NULL;
    lx_scene *sc = NULL;
    lx_plane p;
    memset(&p, 0, sizeof p);
    rc = 0;
    if (g.mf && (rc = lt_quantity(ctx, "grid", "--maintenance", g.mf, LX_Q_NONE, NULL, 0, &g.go.maintenance_factor))) goto done;
    if (g.tol && (rc = lt_quantity(ctx, "grid", "--tolerance", g.tol, LX_Q_NONE, NULL, 0, &g.go.nearfield_tol))) goto done;
    if (g.tol && !(g.go.nearfield_tol >= 1e-12 && g.go.nearfield_tol <= 0.1)) {
        cli_error("grid", "--tolerance must be in [1e-12, 0.1] (got %s)", g.tol);
        rc = CLI_USAGE;
        goto done;
    }
    if (g.mf && !(g.go.maintenance_factor > 0 && g.go.maintenance_factor <= 1)) {
        cli_error("grid", "--maintenance must be in (0, 1] (got %s)", g.mf);
        rc = CLI_USAGE;
        goto done;
    }
    if (g.plane && (rc = make_plane(ctx, &g, &p))) goto done;
    if (g.ies) rc = from_ies(ctx, &g, &p, &pts, &E, &n, &mk);
    else rc = from_scene(ctx, &g, &p, &pts, &E, &n, &marks, &n_marks, &sc);
    if (rc) goto done;
    if (g.png) {
        lx_isolux_opts io = {.background = g.white ? LX_ISOLUX_WHITE : LX_ISOLUX_FALSECOLOR,
                             .marks = marks ? marks : &mk, .n_marks = marks ? n_marks : 1,
                             .source = g.ies ? g.ies : g.scene, .caption = sc && *sc->title ? sc->title : NULL,
                             .surface = sc && !g.plane ? "the scene's grid" : NULL, .imperial = cli_imperial()};
        if (g.centres && g.plane) { /* the calculation area around the cell centres */
            double da = p.na > 1 ? (p.a1 - p.a0) / (p.na - 1) : 0, db = p.nb > 1 ? (p.b1 - p.b0) / (p.nb - 1) : 0;
            io.area_m[0] = p.a0 - da / 2, io.area_m[1] = p.a1 + da / 2, io.area_m[2] = p.b0 - db / 2, io.area_m[3] = p.b1 + db / 2;
        }
        lx_plot_outline *ol = NULL; /* the scene's rooms, obstructions, surfaces, openings on the plane */
        lx_status st = sc ? lx_scene_outlines(ctx, sc, &p, &ol, &io.n_outlines) : LX_OK;
        io.outlines = ol;
        if (!st) st = lx_grid_write_png(ctx, g.png, &p, E, &io);
        lx_scene_outlines_free(ol);
        if (st) {
            rc = cli_fail("grid", ctx, st);
            goto done;
        }
    }
    rc = output(&g, &p, pts, E, n);
done:
    lx_plane_points_free(pts);
    free(E);
    free(marks);
    lx_scene_free(sc);
    lx_ctx_destroy(ctx);
    return rc;
}
