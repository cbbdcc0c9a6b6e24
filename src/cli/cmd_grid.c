/* cmd_grid.c - `luxcalc grid`: illuminance on a plane of points from one luminaire given by flags
 * (csv x,y,z,illuminance_lx per point; the summary E_avg,E_min,E_max,U0 on stderr or --summary). */
#include "cli.h"
#include "lighting.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc grid --ies FILE --at X,Y,Z --plane z=H --area A0:A1,B0:B1 (--spacing S | --points NxM)\n"
    "                    [OPTIONS]\n"
    "\n"
    "Illuminance E = I(C, gamma) cos(xi) / d^2 on a plane of points, printed as csv x,y,z,illuminance_lx\n"
    "(one row per point, A fastest), then the summary E_avg,E_min,E_max,U0 (U0 = E_min / E_avg) on\n"
    "stderr, or on stdout instead of the points with --summary.\n"
    "\n"
    "options:\n"
    "  --ies FILE              the luminaire (IES LM-63 or EULUMDAT)\n"
    "  --at X,Y,Z              its position in m\n"
    "  --aim X,Y,Z             where its nadir points (default 0,0,-1: straight down)\n"
    "  --rotate ANGLE          turn of the C0 plane about the aim axis (default 0; C0 along +x)\n"
    "  --plane z=H|x=H|y=H     the plane; its axes are (x, y), (y, z), (x, z)\n"
    "  --area A0:A1,B0:B1      extent along the plane's two axes in m\n"
    "  --spacing S             points at A0, A0+S, ..., A1 (inclusive when on the grid)\n"
    "  --points NxM            N points along A and M along B, ends included\n"
    "  --normal X,Y,Z          receiver normal (default the plane's axis towards +z, +x or +y)\n"
    "  --model point|auto      auto (default): subdivide the luminous area closer than 5 x its size\n"
    "  --interp bilinear|smooth|table  intensity interpolation (default bilinear; table: the\n"
    "                          cosine-indexed table the OpenCL kernel uses)\n"
    "  --table-rows N          rows per hemisphere of that table (default 1024; implies --interp\n"
    "                          table): fewer is faster and coarser (luxcalc bench grid shows both)\n"
    "  --maintenance MF        maintenance factor in (0, 1] (default 1)\n"
    "  --backend auto|cpu|opencl  (also LX_BACKEND); opencl implies --interp table\n"
    "  --summary               print only E_avg,E_min,E_max,U0\n"
    "  --png FILE              also draw a false-colour plot: legend in lux, iso-lux contours,\n"
    "                          the luminaire's position, axis ticks in metres\n"
    "  --format table|csv|json, -o FILE\n"
    "\n"
    "example:\n"
    "  luxcalc grid --ies samples/ies/downlight_lambert_1000lm.ies --at 2,2,2.8 --plane z=0.8 \\\n"
    "      --area 0:4,0:4 --spacing 0.5 --summary\n";

static int triple(const char *opt, const char *s, double v[3])
{
    char *e;
    for (int i = 0; i < 3; i++) {
        v[i] = strtod(s, &e);
        if (e == s || !isfinite(v[i]) || (i < 2 && *e != ',') || (i == 2 && *e)) {
            cli_error("grid", "%s: expected X,Y,Z in metres (got '%s')", opt, s);
            return CLI_USAGE;
        }
        s = e + 1;
    }
    return 0;
}

static int range2(const char *s, double r[4])
{
    /* A0:A1,B0:B1 */
    char *e;
    const char *p = s;
    static const char seps[4] = {':', ',', ':', 0};
    for (int i = 0; i < 4; i++) {
        r[i] = strtod(p, &e);
        if (e == p || !isfinite(r[i]) || *e != seps[i]) {
            cli_error("grid", "--area: expected A0:A1,B0:B1 in metres (got '%s')", s);
            return CLI_USAGE;
        }
        p = e + 1;
    }
    return 0;
}

int cmd_grid(int argc, char **argv)
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
        {"scene", required_argument, NULL, 'x'},    {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    const char *ies = NULL, *at = NULL, *aim = NULL, *rot = NULL, *plane = NULL, *area = NULL, *spacing = NULL;
    const char *points = NULL, *normal = NULL, *outpath = NULL, *mf_t = NULL, *png = NULL;
    int summary = 0, interp_set = 0;
    cli_format fmt = CLI_FMT_CSV;
    lx_grid_opts go = {0};
    go.model = LX_MODEL_AUTO;
    int c;
    optind = 1;
    while ((c = getopt_long(argc, argv, "o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'i': ies = optarg; break;
        case 'a': at = optarg; break;
        case 'A': aim = optarg; break;
        case 'r': rot = optarg; break;
        case 'p': plane = optarg; break;
        case 'R': area = optarg; break;
        case 's': spacing = optarg; break;
        case 'n': points = optarg; break;
        case 'N': normal = optarg; break;
        case 'M': mf_t = optarg; break;
        case 'S': summary = 1; break;
        case 'P': png = optarg; break;
        case 'T': {
            char *e;
            long v = strtol(optarg, &e, 10);
            if (e == optarg || *e || v < 2 || v > 16384)
                return cli_error("grid", "--table-rows: expected a whole number from 2 to 16384 (got '%s')", optarg), CLI_USAGE;
            go.table_n = (int)v;
            break;
        }
        case 'o': outpath = optarg; break;
        case 'x': cli_error("grid", "--scene: scene files are not supported yet"); return CLI_USAGE;
        case 'f':
            if (lt_format("grid", optarg, &fmt)) return CLI_USAGE;
            break;
        case 'm':
            if (!strcmp(optarg, "point")) go.model = LX_MODEL_POINT;
            else if (!strcmp(optarg, "auto")) go.model = LX_MODEL_AUTO;
            else return cli_error("grid", "--model: expected point or auto (got '%s')", optarg), CLI_USAGE;
            break;
        case 'I':
            interp_set = 1;
            if (!strcmp(optarg, "bilinear")) go.interp = LX_INTERP_BILINEAR;
            else if (!strcmp(optarg, "smooth")) go.interp = LX_INTERP_SMOOTH;
            else if (!strcmp(optarg, "table")) go.interp = LX_INTERP_TABLE;
            else return cli_error("grid", "--interp: expected bilinear, smooth or table (got '%s')", optarg), CLI_USAGE;
            break;
        case 'b': {
            lx_ctx *tmp = NULL;
            lx_backend be;
            lx_ctx_create(&tmp);
            lx_status st = lx_backend_parse(tmp, optarg, &be);
            lx_ctx_destroy(tmp);
            if (st) return cli_error("grid", "--backend: expected auto, cpu or opencl (got '%s')", optarg), CLI_USAGE;
            go.backend = be;
            break;
        }
        case 'h': cli_print_help(help); return CLI_OK;
        default: return CLI_USAGE;
        }
    }
    if (optind < argc) return cli_error("grid", "unexpected argument '%s'", argv[optind]), CLI_USAGE;
    if (!ies || !at || !plane || !area || (!spacing == !points))
        return cli_error("grid", "needs --ies, --at, --plane, --area and one of --spacing or --points (luxcalc grid --help)"),
               CLI_USAGE;
    if (go.table_n) {
        if (interp_set && go.interp != LX_INTERP_TABLE)
            return cli_error("grid", "--table-rows sets the rows of --interp table"), CLI_USAGE;
        go.interp = LX_INTERP_TABLE;
    }
    if (go.backend == LX_BACKEND_AUTO) go.backend = lx_backend_from_env();
    if (go.backend == LX_BACKEND_OPENCL) {
        if (interp_set && go.interp != LX_INTERP_TABLE)
            return cli_error("grid", "--backend opencl computes --interp table only"), CLI_USAGE;
        go.interp = LX_INTERP_TABLE;
    }
    lx_ctx *ctx = cli_ctx("grid");
    if (!ctx) return CLI_RUNTIME;
    int rc = CLI_OK;
    lx_luminaire *lum = NULL;
    double *pts = NULL, *E = NULL;
    cli_table *t = NULL;
    lx_placement pl = {.aim = {0, 0, -1}};
    if ((rc = triple("--at", at, pl.pos_m))) goto done;
    if (aim && (rc = triple("--aim", aim, pl.aim))) goto done;
    if (rot && (rc = lt_quantity(ctx, "grid", "--rotate", rot, LX_Q_ANGLE, "deg", 0, &pl.rotate_rad))) goto done;
    if (mf_t && (rc = lt_quantity(ctx, "grid", "--maintenance", mf_t, LX_Q_NONE, NULL, 0, &go.maintenance_factor))) goto done;
    if (mf_t && !(go.maintenance_factor > 0 && go.maintenance_factor <= 1)) {
        cli_error("grid", "--maintenance must be in (0, 1] (got %s)", mf_t);
        rc = CLI_USAGE;
        goto done;
    }
    if (strlen(plane) < 3 || plane[1] != '=' || !strchr("xyz", plane[0])) {
        cli_error("grid", "--plane: expected z=H, x=H or y=H (got '%s')", plane);
        rc = CLI_USAGE;
        goto done;
    }
    double level, r[4], sp = 0;
    if ((rc = lt_quantity(ctx, "grid", "--plane", plane + 2, LX_Q_LENGTH, NULL, 0, &level))) goto done;
    if ((rc = range2(area, r))) goto done;
    size_t na = 0, nb = 0;
    if (spacing) {
        if ((rc = lt_quantity(ctx, "grid", "--spacing", spacing, LX_Q_LENGTH, NULL, 0, &sp))) goto done;
        if (!(sp > 0)) {
            cli_error("grid", "--spacing must be positive");
            rc = CLI_USAGE;
            goto done;
        }
    } else {
        char *e;
        long a = strtol(points, &e, 10);
        long b = (*e == 'x' || *e == 'X') ? strtol(e + 1, &e, 10) : 0;
        if (a < 1 || b < 1 || *e) {
            cli_error("grid", "--points: expected NxM with N, M >= 1 (got '%s')", points);
            rc = CLI_USAGE;
            goto done;
        }
        na = (size_t)a;
        nb = (size_t)b;
    }
    lx_plane p;
    lx_status st = lx_plane_axis(ctx, plane[0], level, r[0], r[1], r[2], r[3], sp, na, nb, &p);
    if (!st && normal) {
        double nv[3];
        if ((rc = triple("--normal", normal, nv))) goto done;
        double len = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        if (!(len > 0)) {
            cli_error("grid", "--normal must not be zero");
            rc = CLI_USAGE;
            goto done;
        }
        for (int k = 0; k < 3; k++) p.normal[k] = nv[k] / len;
    }
    size_t n = 0;
    if (!st) st = lx_luminaire_read_file(ctx, ies, &lum);
    if (!st) st = lx_plane_points(ctx, &p, &pts, &n);
    if (!st) {
        E = malloc(n * sizeof *E);
        if (!E) {
            cli_error("grid", "out of memory");
            rc = CLI_RUNTIME;
            goto done;
        }
        pl.lum = lum;
        st = lx_grid_illuminance(ctx, &pl, 1, pts, n, p.normal, 1, &go, E);
    }
    if (st) {
        rc = cli_fail("grid", ctx, st);
        goto done;
    }
    if (png && (st = lx_grid_write_png(ctx, png, &p, E, &pl, 1, ies)) != LX_OK) {
        rc = cli_fail("grid", ctx, st);
        goto done;
    }
    lx_grid_stats s;
    lx_grid_stats_compute(ctx, E, n, &s);
    static const char *const sn[] = {"E_avg", "E_min", "E_max", "U0"};
    static const char *const su[] = {"lx", "lx", "lx", NULL};
    cli_table *ts = cli_table_new(4, sn, su);
    cli_table_num(ts, s.avg);
    cli_table_num(ts, s.min);
    cli_table_num(ts, s.max);
    cli_table_num(ts, s.u0);
    if (summary) {
        rc = lt_write("grid", ts, fmt, outpath);
    } else {
        static const char *const names[] = {"x", "y", "z", "illuminance_lx"};
        static const char *const units[] = {"m", "m", "m", "lx"};
        t = cli_table_new(4, names, units);
        for (size_t i = 0; i < n; i++) {
            cli_table_num(t, pts[3 * i]);
            cli_table_num(t, pts[3 * i + 1]);
            cli_table_num(t, pts[3 * i + 2]);
            cli_table_num(t, E[i]);
        }
        rc = lt_write("grid", t, fmt, outpath);
        if (!cli_quiet) cli_table_write(ts, CLI_FMT_CSV, stderr, 0);
    }
    cli_table_free(ts);
done:
    cli_table_free(t);
    lx_plane_points_free(pts);
    free(E);
    lx_luminaire_free(lum);
    lx_ctx_destroy(ctx);
    return rc;
}
