/* cmd_irradiance.c - `luxcalc irradiance`: an irradiance environment map from a lat-long or cube
 * radiance map (OpenEXR in, OpenEXR out in the same layout), or the irradiance and illuminance for one normal (--normal). */
#include "cli.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char help[] =
    "usage: luxcalc irradiance IN.exr -o OUT.exr [--method sh9|brute|fast] [--size WxH] [--png FILE]\n"
    "       luxcalc irradiance IN.exr --normal X,Y,Z [--method M] [--format table|csv|json]\n"
    "\n"
    "IN is a lat-long radiance map (+z up, theta from +z, phi from +x towards +y, row 0 at theta = 0)\n"
    "or an OpenEXR cube map (envmap attribute cube: N x 6N, faces +X,-X,+Y,-Y,+Z,-Z; the file's +Y\n"
    "face is our zenith +z, its -Z face looks towards +x, its +X face towards +y).\n"
    "OUT holds E(n) = integral L(w) max(0, n.w) dw for the normal n of each pixel centre, in the\n"
    "layout of IN.\n"
    "\n"
    "  --method M       sh9 (default): 9 spherical harmonics, fast, rings around a sun (error up to\n"
    "                   3/32 of the source's integral L dw);\n"
    "                   brute: every input pixel for every output pixel, sum L_p max(0, n.m_p) with\n"
    "                   m_p the exact first moment of the pixel (OpenCL or CPU);\n"
    "                   fast: the same sum as brute by per-row prefix sums, O(rows) per output\n"
    "  --size WxH       output size (default: the input's; brute/fast cost grows with it); for a\n"
    "                   cube map N x 6N (faces of N x N)\n"
    "  --window W       sh9 window: none (default) or nonneg (1, 6/7, 32/35: never negative)\n"
    "  --backend B      brute only: auto, cpu or opencl (also LX_BACKEND)\n"
    "  --threads N      CPU threads (default: all cores)\n"
    "  --half           write OUT with half channels (default float; ZIP compression)\n"
    "  --png FILE       tone-mapped preview of input and output side by side\n"
    "  --normal X,Y,Z   print one row for this normal instead of writing a map\n"
    "  --units U        auto (default: luminance when the file has whiteLuminance), radiance\n"
    "                   (W/sr/m2 per channel) or luminance (cd/m2)\n"
    "  --efficacy K     lm/W turning radiance Y into luminance (default 179, Radiance's white)\n"
    "  --format F       table (default), csv or json (with --normal)\n"
    "  -o FILE          OUT.exr, or the table with --normal (atomic)\n"
    "\n"
    "csv columns (--normal): nx,ny,nz,irradiance,illuminance_lx,method, then irradiance_r,g,b for RGB\n"
    "(irradiance: the Y combination of the channels, W/m2 for radiance maps).\n"
    "\n"
    "example: irradiance of a sky map, and a horizontal receiver:\n"
    "  luxcalc irradiance samples/envmaps/sky_sun.exr -o /tmp/E.exr --png /tmp/E.png\n"
    "  luxcalc irradiance samples/envmaps/sky_sun.exr --normal 0,0,1 --method fast --format csv\n";

int cli_envmap_units(const char *cmd, lx_envmap *m, const char *units, const char *eff); /* shared with luminance-map */

int cli_envmap_units(const char *cmd, lx_envmap *m, const char *units, const char *eff)
{
    double K = LX_ENV_DEFAULT_EFFICACY;
    if (eff) {
        char *end;
        K = strtod(eff, &end);
        if (!strcmp(end, "lm/W") || !strcmp(end, "lm/w")) end += strlen(end);
        if (*end || !(K > 0) || !isfinite(K)) {
            cli_error(cmd, "--efficacy: '%s' is not a positive number of lm/W", eff);
            return CLI_USAGE;
        }
    }
    if (!units || !strcmp(units, "auto")) {
        if (m->units == LX_ENV_RADIANCE) m->lum_per_unit = K;
    } else if (!strcmp(units, "radiance")) {
        m->units = LX_ENV_RADIANCE;
        m->lum_per_unit = K;
    } else if (!strcmp(units, "luminance")) {
        if (m->units != LX_ENV_LUMINANCE) m->lum_per_unit = 1.0;
        m->units = LX_ENV_LUMINANCE;
    } else {
        cli_error(cmd, "--units: '%s' is not auto, radiance or luminance", units);
        return CLI_USAGE;
    }
    return CLI_OK;
}

static int parse_size(const char *s, int *w, int *h)
{
    char *end;
    long a = strtol(s, &end, 10);
    if (*end != 'x' && *end != 'X') return -1;
    long b = strtol(end + 1, &end, 10);
    if (*end || a < 1 || b < 1 || a > 65536 || b > 65536) return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

static double y_of(const lx_envmap *m, const double *e)
{
    return m->channels == 3 ? m->y_weights[0] * e[0] + m->y_weights[1] * e[1] + m->y_weights[2] * e[2] : e[0];
}

int cmd_irradiance(int argc, char **argv)
{
    static const struct option opts[] = {
        {"method", required_argument, 0, 'm'}, {"size", required_argument, 0, 's'},
        {"window", required_argument, 0, 'W'}, {"backend", required_argument, 0, 'b'},
        {"threads", required_argument, 0, 't'}, {"half", no_argument, 0, 'H'},
        {"png", required_argument, 0, 'p'},   {"normal", required_argument, 0, 'n'},
        {"units", required_argument, 0, 'u'}, {"efficacy", required_argument, 0, 'K'},
        {"format", required_argument, 0, 'f'}, {"output", required_argument, 0, 'o'},
        {"help", no_argument, 0, 'h'},        {0, 0, 0, 0}};
    const char *cmd = "irradiance", *out = NULL, *png = NULL, *normal = NULL, *units = NULL, *eff = NULL;
    lx_irr_opts io = {0};
    int W = 0, H = 0, half = 0, c, fmt = CLI_FMT_TABLE;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'm':
            if (!strcmp(optarg, "sh9")) io.method = LX_IRR_SH9;
            else if (!strcmp(optarg, "brute")) io.method = LX_IRR_BRUTE;
            else if (!strcmp(optarg, "fast")) io.method = LX_IRR_FAST;
            else return cli_error(cmd, "--method: '%s' is not sh9, brute or fast", optarg), CLI_USAGE;
            break;
        case 's':
            if (parse_size(optarg, &W, &H)) return cli_error(cmd, "--size: '%s' is not WxH", optarg), CLI_USAGE;
            break;
        case 'W':
            if (!strcmp(optarg, "none")) io.window = LX_SH9_WINDOW_NONE;
            else if (!strcmp(optarg, "nonneg")) io.window = LX_SH9_WINDOW_NONNEG;
            else return cli_error(cmd, "--window: '%s' is not none or nonneg", optarg), CLI_USAGE;
            break;
        case 'b': {
            lx_ctx *tmp = cli_ctx(cmd);
            if (!tmp) return CLI_RUNTIME;
            lx_status st = lx_backend_parse(tmp, optarg, &io.backend);
            lx_ctx_destroy(tmp);
            if (st) return cli_error(cmd, "--backend: '%s' is not auto, cpu or opencl", optarg), CLI_USAGE;
            break;
        }
        case 't': {
            char *end;
            long v = strtol(optarg, &end, 10);
            if (*end || v < 0 || v > 64) return cli_error(cmd, "--threads: '%s' is not 0..64", optarg), CLI_USAGE;
            io.threads = (int)v;
            break;
        }
        case 'H': half = 1; break;
        case 'p': png = optarg; break;
        case 'n': normal = optarg; break;
        case 'u': units = optarg; break;
        case 'K': eff = optarg; break;
        case 'f':
            fmt = cli_format_parse(optarg);
            if (fmt < 0) return cli_error(cmd, "--format: '%s' is not table, csv or json", optarg), CLI_USAGE;
            break;
        case 'o': out = optarg; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_error(cmd, "bad option '%s' (see luxcalc irradiance --help)", argv[optind - 1]), CLI_USAGE;
        }
    }
    if (optind + 1 != argc) return cli_error(cmd, "give exactly one input map (see --help)"), CLI_USAGE;
    const char *in = argv[optind];
    double n[3];
    if (normal) {
        char *end;
        n[0] = strtod(normal, &end);
        for (int k = 1; k < 3 && *end == ','; k++) n[k] = strtod(end + 1, &end);
        if (*end || !isfinite(n[0] + n[1] + n[2]) || !(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0) ||
            strchr(normal, ',') == strrchr(normal, ','))
            return cli_error(cmd, "--normal: '%s' is not a non-zero vector X,Y,Z", normal), CLI_USAGE;
    } else if (!out) {
        return cli_error(cmd, "-o OUT.exr is required (or --normal X,Y,Z)"), CLI_USAGE;
    }
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    lx_envmap *m = NULL, *e = NULL;
    lx_status st = lx_exr_read_any(ctx, in, &m);
    int rc = st ? cli_fail(cmd, ctx, st) : cli_envmap_units(cmd, m, units, eff);
    static const char *mname[3] = {"sh9", "brute", "fast"};
    if (!rc && normal) {
        double E[3];
        st = lx_irradiance_dirs(ctx, m, 1, n, &io, E);
        if (st) rc = cli_fail(cmd, ctx, st);
        else {
            double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), Y = y_of(m, E);
            static const char *const names[] = {"nx", "ny", "nz", "irradiance", "illuminance_lx", "method",
                                                "irradiance_r", "irradiance_g", "irradiance_b"};
            static const char *const unit_r[] = {"", "", "", "W/m2", "lx", "", "W/m2", "W/m2", "W/m2"};
            cli_table *t = cli_table_new(m->channels == 3 ? 9 : 6, names, unit_r);
            for (int k = 0; k < 3; k++) cli_table_num(t, n[k] / l);
            cli_table_num(t, Y);
            cli_table_num(t, Y * m->lum_per_unit);
            cli_table_str(t, mname[io.method]);
            if (m->channels == 3)
                for (int k = 0; k < 3; k++) cli_table_num(t, E[k]);
            cli_output o;
            if (cli_output_open(&o, out, cmd)) rc = CLI_INPUT;
            else {
                int bad = cli_table_write(t, (cli_format)fmt, o.fp, 0);
                if (cli_output_close(&o, !bad, cmd) || bad) rc = CLI_INPUT;
            }
            cli_table_free(t);
        }
    } else if (!rc && m->layout == LX_ENV_CUBE && W && H != 6 * W) {
        cli_error(cmd, "--size: %dx%d: the input is a cube map, give N x 6N", W, H);
        rc = CLI_USAGE;
    } else if (!rc) {
        if (io.method != LX_IRR_SH9 && W == 0 && (double)m->width * m->height * m->width * m->height > 4e10 &&
            io.method == LX_IRR_BRUTE && io.backend != LX_BACKEND_OPENCL)
            cli_error(cmd, "warning: brute force %dx%d -> %dx%d is %.2g pixel pairs; consider --size or --method fast",
                      m->width, m->height, m->width, m->height, (double)m->width * m->height * m->width * m->height);
        struct timespec t0, t1;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        st = lx_irradiance_map(ctx, m, W, H, &io, &e);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        lx_exr_write_opts wo = {.half = half};
        if (!st) st = lx_envmap_write_exr(ctx, out, e, &wo);
        if (!st && png) {
            const lx_envmap *maps[2] = {m, e};
            char lab[64];
            snprintf(lab, sizeof lab, "IRRADIANCE (%s)", mname[io.method]);
            const char *labels[2] = {"RADIANCE (INPUT)", lab};
            st = lx_png_preview(ctx, png, 2, maps, labels);
        }
        if (st) rc = cli_fail(cmd, ctx, st);
        else if (cli_verbose)
            fprintf(stderr, "luxcalc: irradiance: %s %dx%d -> %dx%d in %.3f s (%s)\n", mname[io.method], m->width,
                    m->height, e->width, e->height, (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec),
                    lx_ctx_backend_used(ctx) == LX_BACKEND_OPENCL ? "opencl" : "cpu");
    }
    lx_envmap_free(e);
    lx_envmap_free(m);
    lx_ctx_destroy(ctx);
    return rc;
}
