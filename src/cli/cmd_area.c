/* cmd_area.c - `luxcalc disk` and `luxcalc rect`: Lambertian area sources on a parallel receiver,
 * exact (configuration factor) by default, the point model beside it with its error (--model). */
#include "lighting.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char disk_help[] =
    "usage: luxcalc disk --luminance L --radius R --distance h [--offset r] [--model M] [OPTIONS]\n"
    "\n"
    "Lambertian disk of luminance L; receiver parallel to it at height h, offset r from the axis.\n"
    "Exact: E = pi L F with the configuration factor of a parallel element to a disk (stable form);\n"
    "point model: E = L pi R^2 h^2 / (h^2 + r^2)^2. point_error = point/exact - 1.\n"
    "--distance 0 is the coplanar limit: pi L on the disk, pi L / 2 on its rim, 0 outside.\n"
    "\n"
    "  --luminance L     cd/m2 (nit, fL, lambert; W/sr/m2 with --efficacy or --spd)\n"
    "  --radius R        m (bare number: m)\n"
    "  --distance h      height above the disk's plane, >= 0\n"
    "  --offset r        distance from the axis (default 0)\n"
    "  --model M         auto (default) or exact: illuminance_lx is the exact value (it costs what\n"
    "                    the point model costs); point: the point model (its error stays beside it)\n"
    "  --efficacy K, --spd FILE   efficacy for radiometric input\n"
    "  --format F        table (default), csv or json;   -o FILE  write to FILE\n"
    "\n"
    "csv columns: illuminance_lx,point_illuminance_lx,point_error,exact_illuminance_lx,model,near_field,\n"
    "distance_m (near_field: 1 when the point model errs by more than 1e-4)\n"
    "\n"
    "example: a 1 m round ceiling panel of 1000 cd/m2, desk 1 m below, on axis:\n"
    "  luxcalc disk --luminance 1000cd/m2 --radius 0.5m --distance 1m   # 628.3185 lx\n";

static const char rect_help[] =
    "usage: luxcalc rect --luminance L --width a --length b --distance h [--at corner|centre|X,Y]\n"
    "                    [--model M] [OPTIONS]\n"
    "\n"
    "Lambertian rectangle a x b of luminance L; receiver parallel to it at height h on the normal\n"
    "through a corner or the centre (default centre), or at X,Y metres from the centre along the\n"
    "width and the length. Exact: E = pi L F, F the corner configuration factor (Howell's catalogue\n"
    "B-3) summed over corner rectangles (adaptive quadrature when the receiver is outside);\n"
    "point model: E = L a b h^2 / d^4. point_error = point/exact - 1. --distance 0 is the\n"
    "coplanar limit: pi L inside, pi L / 2 on an edge, pi L / 4 at a corner, 0 outside.\n"
    "\n"
    "  --luminance L     cd/m2 (nit, fL, lambert; W/sr/m2 with --efficacy or --spd)\n"
    "  --width a, --length b   sides (bare number: m)\n"
    "  --distance h      height above the rectangle's plane, >= 0\n"
    "  --at P            corner, centre (or center), or X,Y (bare numbers in m)\n"
    "  --model M         auto (default) or exact: illuminance_lx is the exact value; point: the\n"
    "                    point model (its error stays beside it)\n"
    "  --efficacy K, --spd FILE   efficacy for radiometric input\n"
    "  --format F        table (default), csv or json;   -o FILE  write to FILE\n"
    "\n"
    "csv columns: illuminance_lx,point_illuminance_lx,point_error,exact_illuminance_lx,model,near_field,\n"
    "distance_m (near_field: 1 when the point model errs by more than 1e-4)\n"
    "\n"
    "example: a 0.6 m x 1.2 m panel of 3000 cd/m2, a work plane 2 m below its centre:\n"
    "  luxcalc rect --luminance 3000cd/m2 --width 0.6m --length 1.2m --distance 2m --at centre\n";

static int write_result(const lt_common *co, const lx_source_result *r)
{
    static const char *const names[] = {"illuminance_lx", "point_illuminance_lx", "point_error",
                                        "exact_illuminance_lx", "model", "near_field", "distance_m"};
    static const char *const units[] = {"lx", "lx", "", "lx", "", "", "m"};
    cli_table *t = cli_table_new(7, names, units);
    cli_table_num(t, r->illuminance_lx);
    cli_table_num(t, r->point_lx);
    cli_table_num(t, r->point_error);
    cli_table_num(t, r->exact_lx);
    cli_table_str(t, r->model == LX_MODEL_EXACT ? "exact" : "point");
    cli_table_int(t, r->near_field);
    cli_table_num(t, r->distance_m);
    return lt_emit(co, t);
}

static int parse_model(const char *cmd, const char *s, lx_model *m)
{
    if (!strcmp(s, "auto")) *m = LX_MODEL_AUTO;
    else if (!strcmp(s, "point")) *m = LX_MODEL_POINT;
    else if (!strcmp(s, "exact")) *m = LX_MODEL_EXACT;
    else {
        cli_error(cmd, "--model: unknown model '%s' (auto, point or exact)", s);
        return -1;
    }
    return 0;
}

static int run(int argc, char **argv, int is_rect)
{
    static const struct option opts[] = {
        {"luminance", required_argument, 0, 'L'}, {"radius", required_argument, 0, 'R'},
        {"width", required_argument, 0, 'w'},     {"length", required_argument, 0, 'l'},
        {"distance", required_argument, 0, 'd'},  {"offset", required_argument, 0, 'r'},
        {"at", required_argument, 0, 'A'},        {"model", required_argument, 0, 'm'},
        LT_COMMON_LONGOPTS,                       {0, 0, 0, 0}};
    lt_common co;
    lt_common_init(&co, is_rect ? "rect" : "disk", is_rect ? rect_help : disk_help);
    const char *cmd = co.cmd;
    const char *lum = NULL, *rad = NULL, *wid = NULL, *len = NULL, *dist = NULL, *off = "0", *at = "centre";
    lx_model model = LX_MODEL_AUTO;
    int c, rc, li = -1;
    while ((c = getopt_long(argc, argv, LT_SHORTOPTS, opts, &li)) != -1) {
        int wrong = 0;
        switch (c) {
        case 'L': lum = optarg; break;
        case 'R': rad = optarg; wrong = is_rect; break;
        case 'w': wid = optarg; wrong = !is_rect; break;
        case 'l': len = optarg; wrong = !is_rect; break;
        case 'd': dist = optarg; break;
        case 'r': off = optarg; wrong = is_rect; break;
        case 'A': at = optarg; wrong = !is_rect; break;
        case 'm':
            if (parse_model(cmd, optarg, &model)) return CLI_USAGE;
            break;
        default:
            if ((rc = lt_common_opt(&co, c, argv)) != LT_NEXT) return rc;
        }
        if (wrong) {
            fprintf(stderr, "luxcalc: %s: option '--%s' applies to %s only (see luxcalc %s --help)\n", cmd,
                    li >= 0 ? opts[li].name : "?", is_rect ? "disk" : "rect", cmd);
            return CLI_USAGE;
        }
        li = -1;
    }
    if (lt_no_operands(&co, argc, argv)) return CLI_USAGE;
    if (!lum || !dist || (is_rect ? (!wid || !len) : !rad)) {
        cli_error(cmd, is_rect ? "--luminance, --width, --length and --distance are required"
                               : "--luminance, --radius and --distance are required");
        return CLI_USAGE;
    }
    lx_ctx *ctx;
    rc = lt_start(&co, &ctx);
    if (!ctx) return rc;
    double K = co.efficacy, L, h, R = 0, r = 0, a = 0, b = 0, x = 0, y = 0;
    if (!rc) rc = lt_quantity(ctx, cmd, "--luminance", lum, LX_Q_LUMINANCE, NULL, K, &L);
    if (!rc) rc = lt_quantity(ctx, cmd, "--distance", dist, LX_Q_LENGTH, NULL, K, &h);
    if (!rc && !is_rect) rc = lt_quantity(ctx, cmd, "--radius", rad, LX_Q_LENGTH, NULL, K, &R);
    if (!rc && !is_rect) rc = lt_quantity(ctx, cmd, "--offset", off, LX_Q_LENGTH, NULL, K, &r);
    if (!rc && is_rect) rc = lt_quantity(ctx, cmd, "--width", wid, LX_Q_LENGTH, NULL, K, &a);
    if (!rc && is_rect) rc = lt_quantity(ctx, cmd, "--length", len, LX_Q_LENGTH, NULL, K, &b);
    if (!rc && is_rect) {
        if (!strcmp(at, "corner")) x = 0.5 * a, y = 0.5 * b;
        else if (!strcmp(at, "centre") || !strcmp(at, "center")) x = y = 0;
        else {
            const char *comma = strchr(at, ',');
            char xs[128];
            if (!comma || (size_t)(comma - at) >= sizeof xs) {
                cli_error(cmd, "--at: '%s' is not corner, centre or X,Y", at);
                rc = CLI_USAGE;
            } else {
                memcpy(xs, at, (size_t)(comma - at));
                xs[comma - at] = '\0';
                rc = lt_quantity(ctx, cmd, "--at", xs, LX_Q_LENGTH, NULL, K, &x);
                if (!rc) rc = lt_quantity(ctx, cmd, "--at", comma + 1, LX_Q_LENGTH, NULL, K, &y);
            }
        }
    }
    if (!rc) {
        lx_source_result res;
        lx_status st = is_rect ? lx_rect_illuminance(ctx, L, a, b, h, x, y, model, &res)
                               : lx_disk_illuminance(ctx, L, R, h, r, model, &res);
        rc = st != LX_OK ? cli_fail(cmd, ctx, st) : write_result(&co, &res);
    }
    lx_ctx_destroy(ctx);
    return rc;
}

int cmd_disk(int argc, char **argv) { return run(argc, argv, 0); }
int cmd_rect(int argc, char **argv) { return run(argc, argv, 1); }
