/* cmd_point.c - `luxcalc point`: illuminance from an isotropic point source (inverse square and
 * cosine laws). */
#include "lighting.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>

static const char help[] =
    "usage: luxcalc point (--flux F | --intensity I) [--distance d] [--angle a] [OPTIONS]\n"
    "\n"
    "Isotropic point source (I = F / 4 pi), receiver at distance d, its normal at angle a to the\n"
    "ray: E = I cos(a) / d^2 (0 for a receiver facing away).\n"
    "\n"
    "  --flux F          luminous flux (lm; W with --efficacy or --spd)\n"
    "  --intensity I     luminous intensity (cd; W/sr with --efficacy or --spd)\n"
    "  --distance d      distance, > 0 (default 1 m; bare number: m; ft, in, cm, mm accepted)\n"
    "  --angle a         incidence angle (default 0; bare number: degrees; or 0.5rad)\n"
    "  --efficacy K      luminous efficacy for radiometric input (e.g. 100lm/W)\n"
    "  --spd FILE        take the efficacy from a measured spectrum (one spectrum)\n"
    "  --format F        table (default), csv or json\n"
    "  -o FILE           write to FILE (atomically)\n"
    "\n"
    "csv columns: flux_lm,intensity_cd,illuminance_lx,distance_m,angle_deg\n"
    "\n"
    "example: a 1000 lm lamp 2 m away, light arriving 30 deg off the normal:\n"
    "  luxcalc point --flux 1000lm --distance 2m --angle 30deg   # 17.229 lx\n";

int cmd_point(int argc, char **argv)
{
    static const struct option opts[] = {
        {"flux", required_argument, 0, 'F'},     {"intensity", required_argument, 0, 'I'},
        {"distance", required_argument, 0, 'd'}, {"angle", required_argument, 0, 'a'},
        LT_COMMON_LONGOPTS,                      {0, 0, 0, 0}};
    lt_common co;
    lt_common_init(&co, "point", help);
    const char *cmd = co.cmd;
    const char *flux = NULL, *inten = NULL, *dist = "1", *angle = "0";
    int c, rc;
    while ((c = getopt_long(argc, argv, LT_SHORTOPTS, opts, NULL)) != -1) {
        switch (c) {
        case 'F': flux = optarg; break;
        case 'I': inten = optarg; break;
        case 'd': dist = optarg; break;
        case 'a': angle = optarg; break;
        default:
            if ((rc = lt_common_opt(&co, c, argv)) != LT_NEXT) return rc;
        }
    }
    if (lt_no_operands(&co, argc, argv)) return CLI_USAGE;
    if (!flux == !inten) {
        cli_error(cmd, "give exactly one of --flux and --intensity");
        return CLI_USAGE;
    }
    lx_ctx *ctx;
    rc = lt_start(&co, &ctx);
    if (!ctx) return rc;
    double K = co.efficacy, f = NAN, i = NAN, d, a, e;
    if (!rc && flux) rc = lt_quantity(ctx, cmd, "--flux", flux, LX_Q_LUMINOUS_FLUX, NULL, K, &f);
    if (!rc && inten) rc = lt_quantity(ctx, cmd, "--intensity", inten, LX_Q_LUMINOUS_INTENSITY, NULL, K, &i);
    if (!rc) rc = lt_quantity(ctx, cmd, "--distance", dist, LX_Q_LENGTH, NULL, K, &d);
    if (!rc) rc = lt_quantity(ctx, cmd, "--angle", angle, LX_Q_ANGLE, "deg", K, &a);
    if (!rc) {
        lx_status st = LX_OK;
        if (flux) st = lx_point_intensity(ctx, f, &i);
        else if (!(i >= 0)) st = LX_EINVAL, cli_error(cmd, "--intensity: must not be negative"), rc = CLI_INPUT;
        else f = 4 * CLI_PI * i;
        if (!rc && st == LX_OK) st = lx_point_illuminance(ctx, i, d, a, &e);
        if (!rc && st != LX_OK) rc = cli_fail(cmd, ctx, st);
    }
    if (!rc) {
        static const char *const names[] = {"flux_lm", "intensity_cd", "illuminance_lx", "distance_m", "angle_deg"};
        static const char *const units[] = {"lm", "cd", "lx", "m", "deg"};
        const double vals[] = {f, i, e, lt_echo(d), lt_echo(a / LT_DEG)};
        rc = lt_emit_nums(&co, 5, names, units, vals);
    }
    lx_ctx_destroy(ctx);
    return rc;
}
