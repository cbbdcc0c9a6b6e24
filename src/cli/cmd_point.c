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
        {"efficacy", required_argument, 0, 'K'}, {"spd", required_argument, 0, 'S'},
        {"format", required_argument, 0, 'f'},   {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    const char *cmd = "point";
    const char *flux = NULL, *inten = NULL, *dist = "1", *angle = "0", *eff = NULL, *spd = NULL, *out = NULL;
    cli_format fmt = CLI_FMT_TABLE;
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'F': flux = optarg; break;
        case 'I': inten = optarg; break;
        case 'd': dist = optarg; break;
        case 'a': angle = optarg; break;
        case 'K': eff = optarg; break;
        case 'S': spd = optarg; break;
        case 'o': out = optarg; break;
        case 'f':
            if (lt_format(cmd, optarg, &fmt)) return CLI_USAGE;
            break;
        case 'h': cli_print_help(help); return CLI_OK;
        default:
            cli_error(cmd, "bad option '%s' (see luxcalc point --help)", argv[optind - 1]);
            return CLI_USAGE;
        }
    }
    if (optind < argc) {
        cli_error(cmd, "unexpected argument '%s'", argv[optind]);
        return CLI_USAGE;
    }
    if (!flux == !inten) {
        cli_error(cmd, "give exactly one of --flux and --intensity");
        return CLI_USAGE;
    }
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    double K, f = NAN, i = NAN, d, a, e;
    int rc = lt_efficacy(ctx, cmd, eff, spd, &K);
    if (!rc && flux) rc = lt_quantity(ctx, cmd, "--flux", flux, LX_Q_LUMINOUS_FLUX, NULL, K, &f);
    if (!rc && inten) rc = lt_quantity(ctx, cmd, "--intensity", inten, LX_Q_LUMINOUS_INTENSITY, NULL, K, &i);
    if (!rc) rc = lt_quantity(ctx, cmd, "--distance", dist, LX_Q_LENGTH, NULL, K, &d);
    if (!rc) rc = lt_quantity(ctx, cmd, "--angle", angle, LX_Q_ANGLE, "deg", K, &a);
    if (!rc) {
        lx_status st = LX_OK;
        if (flux) st = lx_point_intensity(ctx, f, &i);
        else if (!(i >= 0)) st = LX_EINVAL, cli_error(cmd, "--intensity: must not be negative"), rc = CLI_INPUT;
        else f = 4 * 3.14159265358979323846 * i;
        if (!rc && st == LX_OK) st = lx_point_illuminance(ctx, i, d, a, &e);
        if (!rc && st != LX_OK) rc = cli_fail(cmd, ctx, st);
    }
    if (!rc) {
        static const char *const names[] = {"flux_lm", "intensity_cd", "illuminance_lx", "distance_m", "angle_deg"};
        static const char *const units[] = {"lm", "cd", "lx", "m", "deg"};
        cli_table *t = cli_table_new(5, names, units);
        cli_table_num(t, f);
        cli_table_num(t, i);
        cli_table_num(t, e);
        cli_table_num(t, d);
        cli_table_num(t, a / LT_DEG);
        rc = lt_write(cmd, t, fmt, out);
        cli_table_free(t);
    }
    lx_ctx_destroy(ctx);
    return rc;
}
