/* cmd_spot.c - `luxcalc spot`: a Warn spotlight I(a) = c cos^S(a), c = (S+1)/(2 pi) F, the
 * illuminance it gives on a receiver at distance d along direction a, and the flux in a cone. */
#include "lighting.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>

static const char help[] =
    "usage: luxcalc spot --flux F (--exponent S | --beam-angle B) [--angle a] [--distance d]\n"
    "                    [--incidence b] [--cone A] [OPTIONS]\n"
    "\n"
    "Warn spotlight: I(a) = c cos^S(a) for a < 90 deg (0 beyond), c = (S+1)/(2 pi) F. The receiver\n"
    "is at distance d along direction a from the beam axis, its normal at angle b to the ray:\n"
    "E = I(a) cos(b) / d^2.\n"
    "\n"
    "  --flux F          luminous flux (lm; W with --efficacy or --spd)\n"
    "  --exponent S      Warn exponent, >= 0 (0: uniform hemisphere, 1: Lambertian)\n"
    "  --beam-angle B    instead of S: the full angle where I falls to half the peak\n"
    "  --angle a         direction off the beam axis (default 0; bare number: degrees)\n"
    "  --distance d      distance, > 0 (default 1 m; bare number: m)\n"
    "  --incidence b     receiver normal to the ray (default 0; bare number: degrees)\n"
    "  --cone A          also the flux within the cone of half-angle A about the axis and its\n"
    "                    fraction of F: F (1 - cos^(S+1) A), the closed form of the cos^S lobe\n"
    "  --efficacy K, --spd FILE   efficacy for radiometric input (e.g. 100lm/W)\n"
    "  --format F        table (default), csv or json;   -o FILE  write to FILE\n"
    "\n"
    "csv columns: peak_intensity_cd,intensity_cd,illuminance_lx,exponent,beam_angle_deg\n"
    "(with --cone: cone_half_angle_deg,cone_flux_lm,cone_fraction)\n"
    "\n"
    "example: an 800 lm spot with a 25 deg beam, a table 2.5 m below, 10 deg off axis:\n"
    "  luxcalc spot --flux 800lm --beam-angle 25deg --angle 10deg --distance 2.5m --incidence 10deg\n";

int cmd_spot(int argc, char **argv)
{
    static const struct option opts[] = {
        {"flux", required_argument, 0, 'F'},      {"exponent", required_argument, 0, 'x'},
        {"beam-angle", required_argument, 0, 'B'}, {"angle", required_argument, 0, 'a'},
        {"distance", required_argument, 0, 'd'},  {"incidence", required_argument, 0, 'b'},
        {"cone", required_argument, 0, 'c'},      LT_COMMON_LONGOPTS,
        {0, 0, 0, 0}};
    lt_common co;
    lt_common_init(&co, "spot", help);
    const char *cmd = co.cmd;
    const char *flux = NULL, *expo = NULL, *beam = NULL, *angle = "0", *dist = "1", *inc = "0", *cone = NULL;
    int c, rc;
    while ((c = getopt_long(argc, argv, LT_SHORTOPTS, opts, NULL)) != -1) {
        switch (c) {
        case 'F': flux = optarg; break;
        case 'x': expo = optarg; break;
        case 'B': beam = optarg; break;
        case 'a': angle = optarg; break;
        case 'd': dist = optarg; break;
        case 'b': inc = optarg; break;
        case 'c': cone = optarg; break;
        default:
            if ((rc = lt_common_opt(&co, c, argv)) != LT_NEXT) return rc;
        }
    }
    if (lt_no_operands(&co, argc, argv)) return CLI_USAGE;
    if (!flux || !expo == !beam) {
        cli_error(cmd, "give --flux and exactly one of --exponent and --beam-angle");
        return CLI_USAGE;
    }
    lx_ctx *ctx;
    rc = lt_start(&co, &ctx);
    if (!ctx) return rc;
    double K = co.efficacy, f, s = NAN, bm = NAN, a, d, b, peak, i, e, ca = NAN, cf = NAN, cfr = NAN;
    if (!rc) rc = lt_quantity(ctx, cmd, "--flux", flux, LX_Q_LUMINOUS_FLUX, NULL, K, &f);
    if (!rc && expo && cli_parse_double(expo, &s) != 0) {
        cli_error(cmd, "--exponent: '%s' is not a number", expo);
        rc = CLI_USAGE;
    }
    if (!rc && beam) rc = lt_quantity(ctx, cmd, "--beam-angle", beam, LX_Q_ANGLE, "deg", K, &bm);
    if (!rc) rc = lt_quantity(ctx, cmd, "--angle", angle, LX_Q_ANGLE, "deg", K, &a);
    if (!rc) rc = lt_quantity(ctx, cmd, "--distance", dist, LX_Q_LENGTH, NULL, K, &d);
    if (!rc) rc = lt_quantity(ctx, cmd, "--incidence", inc, LX_Q_ANGLE, "deg", K, &b);
    if (!rc && cone) rc = lt_quantity(ctx, cmd, "--cone", cone, LX_Q_ANGLE, "deg", K, &ca);
    if (!rc) {
        lx_status st = LX_OK;
        if (beam) st = lx_warn_exponent_from_beam(ctx, bm, &s);
        else if (s > 0) st = lx_warn_beam_from_exponent(ctx, s, &bm);
        else bm = NAN;
        if (st == LX_OK) st = lx_warn_intensity(ctx, f, s, a, &peak, &i);
        if (st == LX_OK) st = lx_point_illuminance(ctx, i, d, b, &e);
        if (st == LX_OK && cone) st = lx_warn_cone_flux(ctx, f, s, ca, &cf, &cfr);
        if (st != LX_OK) rc = cli_fail(cmd, ctx, st);
    }
    if (!rc) {
        static const char *const names[] = {"peak_intensity_cd", "intensity_cd", "illuminance_lx", "exponent",
                                            "beam_angle_deg", "cone_half_angle_deg", "cone_flux_lm", "cone_fraction"};
        static const char *const units[] = {"cd", "cd", "lx", "", "deg", "deg", "lm", ""};
        const double vals[] = {peak, i, e, s, beam ? lt_echo(bm / LT_DEG) : bm / LT_DEG, cone ? lt_echo(ca / LT_DEG) : NAN, cf, cfr};
        rc = lt_emit_nums(&co, cone ? 8 : 5, names, units, vals);
    }
    lx_ctx_destroy(ctx);
    return rc;
}
