/* cmd_solve.c - `luxcalc solve`: the inverse problems of a point source or a Warn spot (distance,
 * intensity, flux for a target illuminance; Warn exponent <-> beam angle; reflected luminance). */
#include "lighting.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>

static const char help[] =
    "usage: luxcalc solve [--illuminance E] [--intensity I | --flux F | --distance d] [--exponent S]\n"
    "                     [--beam-angle B] [--angle a] [--incidence b] [--reflectance rho] [OPTIONS]\n"
    "\n"
    "Solves for what is missing (receiver at incidence b, default 0; bare angles are degrees):\n"
    "  --illuminance E --intensity I     -> distance_m = sqrt(I cos b / E)\n"
    "  --illuminance E --distance d      -> intensity_cd = E d^2 / cos b, and flux_lm: of an isotropic\n"
    "                                       point (4 pi I), or with --exponent S / --beam-angle B of a\n"
    "                                       Warn spot seen at --angle a off axis (2 pi I/((S+1) cos^S a))\n"
    "  --illuminance E --flux F          -> distance_m for an isotropic point, or a Warn spot with\n"
    "                                       --exponent / --beam-angle at --angle a\n"
    "  --beam-angle B (alone)            -> exponent;  --exponent S (alone) -> beam_angle_deg\n"
    "  --illuminance E --reflectance rho -> luminance_cd_m2 = rho E / pi (Lambertian reflector)\n"
    "  --efficacy K, --spd FILE          efficacy for radiometric input;  --format F;  -o FILE\n"
    "\n"
    "examples: how far can a 2000 cd spot be for 500 lx? what flux does a 30 deg spot need for\n"
    "300 lx at 3 m?\n"
    "  luxcalc solve --illuminance 500lx --intensity 2000cd            # distance_m 2\n"
    "  luxcalc solve --illuminance 300lx --distance 3m --beam-angle 30deg\n";

int cmd_solve(int argc, char **argv)
{
    static const struct option opts[] = {
        {"illuminance", required_argument, 0, 'E'}, {"intensity", required_argument, 0, 'I'},
        {"flux", required_argument, 0, 'F'},        {"distance", required_argument, 0, 'd'},
        {"exponent", required_argument, 0, 'x'},    {"beam-angle", required_argument, 0, 'B'},
        {"angle", required_argument, 0, 'a'},       {"incidence", required_argument, 0, 'b'},
        {"reflectance", required_argument, 0, 'r'}, LT_COMMON_LONGOPTS,
        {0, 0, 0, 0}};
    lt_common co;
    lt_common_init(&co, "solve", help);
    const char *cmd = co.cmd;
    const char *E_s = NULL, *I_s = NULL, *F_s = NULL, *d_s = NULL, *x_s = NULL, *B_s = NULL, *a_s = "0", *b_s = "0";
    const char *rho_s = NULL;
    int c, rc;
    while ((c = getopt_long(argc, argv, LT_SHORTOPTS, opts, NULL)) != -1) {
        switch (c) {
        case 'E': E_s = optarg; break;
        case 'I': I_s = optarg; break;
        case 'F': F_s = optarg; break;
        case 'd': d_s = optarg; break;
        case 'x': x_s = optarg; break;
        case 'B': B_s = optarg; break;
        case 'a': a_s = optarg; break;
        case 'b': b_s = optarg; break;
        case 'r': rho_s = optarg; break;
        default:
            if ((rc = lt_common_opt(&co, c, argv)) != LT_NEXT) return rc;
        }
    }
    if (lt_no_operands(&co, argc, argv)) return CLI_USAGE;
    if (x_s && B_s) {
        cli_error(cmd, "give --exponent or --beam-angle, not both");
        return CLI_USAGE;
    }
    int given = !!I_s + !!F_s + !!d_s + !!rho_s;
    if (given > 1 || (given == 1 && !E_s) || (given == 0 && (E_s || (!x_s && !B_s)))) {
        cli_error(cmd, "nothing to solve: see luxcalc solve --help for the combinations");
        return CLI_USAGE;
    }
    lx_ctx *ctx;
    rc = lt_start(&co, &ctx);
    if (!ctx) return rc;
    double K = co.efficacy, E = 0, I = 0, F = 0, d = 0, S = -1, B = NAN, a = 0, b = 0, rho = 0;
    if (!rc && E_s) rc = lt_quantity(ctx, cmd, "--illuminance", E_s, LX_Q_ILLUMINANCE, NULL, K, &E);
    if (!rc && I_s) rc = lt_quantity(ctx, cmd, "--intensity", I_s, LX_Q_LUMINOUS_INTENSITY, NULL, K, &I);
    if (!rc && F_s) rc = lt_quantity(ctx, cmd, "--flux", F_s, LX_Q_LUMINOUS_FLUX, NULL, K, &F);
    if (!rc && d_s) rc = lt_quantity(ctx, cmd, "--distance", d_s, LX_Q_LENGTH, NULL, K, &d);
    if (!rc && B_s) rc = lt_quantity(ctx, cmd, "--beam-angle", B_s, LX_Q_ANGLE, "deg", K, &B);
    if (!rc) rc = lt_quantity(ctx, cmd, "--angle", a_s, LX_Q_ANGLE, "deg", K, &a);
    if (!rc) rc = lt_quantity(ctx, cmd, "--incidence", b_s, LX_Q_ANGLE, "deg", K, &b);
    if (!rc && x_s && cli_parse_double(x_s, &S) != 0) {
        cli_error(cmd, "--exponent: '%s' is not a number", x_s);
        rc = CLI_USAGE;
    }
    if (!rc && rho_s && cli_parse_double(rho_s, &rho) != 0) {
        cli_error(cmd, "--reflectance: '%s' is not a number", rho_s);
        rc = CLI_USAGE;
    }
    const char *names[4], *units[4];
    double vals[4];
    int n = 0;
    lx_status st = LX_OK;
    if (!rc) {
        int warn = x_s || B_s;
        if (B_s) st = lx_warn_exponent_from_beam(ctx, B, &S);
        else if (x_s && S > 0) st = lx_warn_beam_from_exponent(ctx, S, &B);
        else if (x_s && !(S >= 0)) st = LX_EINVAL, cli_error(cmd, "--exponent: must be >= 0"), rc = CLI_INPUT;
        if (!rc && st == LX_OK) {
            if (I_s) {
                st = lx_solve_distance(ctx, E, I, b, &d);
                names[n] = "distance_m", units[n] = "m", vals[n++] = d;
            } else if (d_s) {
                st = lx_solve_intensity(ctx, E, d, b, &I);
                if (st == LX_OK) st = lx_solve_flux(ctx, E, d, b, warn ? S : -1, a, &F);
                names[n] = "intensity_cd", units[n] = "cd", vals[n++] = I;
                names[n] = "flux_lm", units[n] = "lm", vals[n++] = F;
            } else if (F_s) {
                /* the intensity towards the receiver, then the distance */
                if (warn) st = lx_warn_intensity(ctx, F, S, a, NULL, &I);
                else st = lx_point_intensity(ctx, F, &I);
                if (st == LX_OK) st = lx_solve_distance(ctx, E, I, b, &d);
                names[n] = "distance_m", units[n] = "m", vals[n++] = d;
                names[n] = "intensity_cd", units[n] = "cd", vals[n++] = I;
            } else if (rho_s) {
                double L;
                st = lx_lambertian_luminance(ctx, rho, E, &L);
                names[n] = "luminance_cd_m2", units[n] = "cd/m2", vals[n++] = L;
            }
            if (warn) {
                names[n] = "exponent", units[n] = "", vals[n++] = S;
                names[n] = "beam_angle_deg", units[n] = "deg", vals[n++] = B_s ? lt_echo(B / LT_DEG) : B / LT_DEG; /* an input echoed as given */
            }
        }
        if (!rc && st != LX_OK) rc = cli_fail(cmd, ctx, st);
    }
    if (!rc) rc = lt_emit_nums(&co, n, names, units, vals);
    lx_ctx_destroy(ctx);
    return rc;
}
