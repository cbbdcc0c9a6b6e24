/* cmd_irradiance.c - `luxcalc irradiance`: an irradiance environment map from a lat-long or cube
 * radiance map (OpenEXR in, OpenEXR out in the same layout), or the irradiance and illuminance for one normal (--normal). */
#include "cli.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char help[] =
    "usage: luxcalc irradiance IN.exr -o OUT.exr [--method auto|fast|sh9|brute] [--size WxH] [--png FILE]\n"
    "       luxcalc irradiance IN.exr --normal X,Y,Z [--method M] [--format table|csv|json]\n"
    "\n"
    "IN is a lat-long radiance map (+z up, theta from +z, phi from +x towards +y, row 0 at theta = 0)\n"
    "or an OpenEXR cube map (envmap attribute cube: N x 6N, faces +X,-X,+Y,-Y,+Z,-Z; the file's +Y\n"
    "face is our zenith +z, its -Z face looks towards +x, its +X face towards +y).\n"
    "OUT holds E(n) = integral L(w) max(0, n.w) dw for the normal n of each pixel centre, in the\n"
    "layout of IN.\n"
    "\n"
    "  --method M       auto (default): fast, unless that would cost more than 10 x sh9 for this\n"
    "                   job (large output maps): then sh9, and a note on stderr says so;\n"
    "                   fast: exact (every pixel's integral of max(0, n.w), the pixels the horizon\n"
    "                   of n crosses in closed form), per-row prefix sums: O(rows) per output;\n"
    "                   sh9: 9 spherical harmonics, approximate: rings around a sun (error up to\n"
    "                   3/32 of the source's integral L dw) and can go negative; warns when it does\n"
    "                   or when a small source holds much of the map's power;\n"
    "                   brute: exact, every input pixel for every output pixel (OpenCL or CPU)\n"
    "  --size WxH       output size (default: the input's; brute/fast cost grows with it); for a\n"
    "                   cube map N x 6N (faces of N x N)\n"
    "  --window W       sh9 window: none (default) or nonneg (1, 6/7, 32/35: never negative)\n"
    "  --backend B      brute only: auto, cpu or opencl (also LX_BACKEND)\n"
    "  --threads N      CPU threads (default: all cores)\n"
    "  --half           write OUT with half channels (default float; ZIP compression)\n"
    "  --png FILE       a preview: the input tone-mapped beside the output as illuminance (lx) in\n"
    "                   false colour with its legend\n"
    "  --scale S        the preview's scale: log (default, decade ticks) or linear (round ticks)\n"
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

/* After SH9: a warning when the result is negative (neg_min < 0: the most negative illuminance,
 * n_neg of n_out outputs) or when a small source holds much of the map's power (10 % or more in
 * pixels covering at most 0.1 % of the sphere: SH9's error reaches 3/32 of that source's power);
 * and, when auto chose SH9, a note that says so. Nothing when -q. */
static void sh9_notes(lx_ctx *ctx, const char *cmd, const lx_envmap *m, const lx_irr_opts *io, double neg_min, size_t n_neg,
                      size_t n_out)
{
    double ratio;
    if (cli_quiet || lx_ctx_irradiance_method(ctx, &ratio) != LX_IRR_SH9) return;
    if (io->method == LX_IRR_AUTO)
        cli_error(cmd, "note: SH9 (approximate) for this map: the exact method (--method fast) would cost about %.0f "
                       "times as much here",
                  ratio);
    if (neg_min < 0) {
        if (n_out == 1)
            cli_error(cmd, "warning: SH9 gives a negative illuminance (%.6g lx): its ringing around a small bright "
                           "source; the exact value (--method fast) is >= 0",
                      neg_min);
        else
            cli_error(cmd, "warning: SH9 gives %zu of %zu outputs a negative illuminance (down to %.6g lx): its ringing "
                           "around a small bright source; --method fast is exact",
                      n_neg, n_out, neg_min);
    }
    double frac = 0, sphere = 4 * 3.14159265358979323846;
    size_t px = 0;
    if (lx_envmap_concentration(ctx, m, 1e-3 * sphere, &frac, &px) == LX_OK && frac >= 0.1)
        cli_error(cmd, "warning: SH9 is approximate and this map has a dominant small source: %.1f %% of its power is in "
                       "%zu pixel%s (at most 0.1 %% of the sphere); SH9 can err by up to 3/32 of that source's power "
                       "(--method fast is exact)",
                  100 * frac, px, px == 1 ? "" : "s");
}

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

/* The command line of `irradiance`, parsed by parse_opts. */
typedef struct {
    const char *out, *png, *normal, *units, *eff;
    lx_irr_opts io;
    int W, H, half, fmt;
    lx_plot_scale scale;
} irr_args;

static const char *mname[4] = {"sh9", "brute", "fast", "auto"};

/* The options into *a: -1 to go on, else the exit code (a usage error, or CLI_OK after --help). */
static int parse_opts(const char *cmd, int argc, char **argv, irr_args *a)
{
    static const struct option opts[] = {
        {"method", required_argument, 0, 'm'}, {"size", required_argument, 0, 's'},
        {"window", required_argument, 0, 'W'}, {"backend", required_argument, 0, 'b'},
        {"threads", required_argument, 0, 't'}, {"half", no_argument, 0, 'H'},
        {"png", required_argument, 0, 'p'},   {"normal", required_argument, 0, 'n'},
        {"scale", required_argument, 0, 'S'},
        {"units", required_argument, 0, 'u'}, {"efficacy", required_argument, 0, 'K'},
        {"format", required_argument, 0, 'f'}, {"output", required_argument, 0, 'o'},
        {"help", no_argument, 0, 'h'},        {0, 0, 0, 0}};
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'm':
            if (!strcmp(optarg, "sh9")) a->io.method = LX_IRR_SH9;
            else if (!strcmp(optarg, "brute")) a->io.method = LX_IRR_BRUTE;
            else if (!strcmp(optarg, "fast")) a->io.method = LX_IRR_FAST;
            else if (!strcmp(optarg, "auto")) a->io.method = LX_IRR_AUTO;
            else return cli_error(cmd, "--method: '%s' is not auto, fast, sh9 or brute", optarg), CLI_USAGE;
            break;
        case 's':
            if (parse_size(optarg, &a->W, &a->H)) return cli_error(cmd, "--size: '%s' is not WxH", optarg), CLI_USAGE;
            break;
        case 'W':
            if (!strcmp(optarg, "none")) a->io.window = LX_SH9_WINDOW_NONE;
            else if (!strcmp(optarg, "nonneg")) a->io.window = LX_SH9_WINDOW_NONNEG;
            else return cli_error(cmd, "--window: '%s' is not none or nonneg", optarg), CLI_USAGE;
            break;
        case 'b': {
            lx_ctx *tmp = cli_ctx(cmd);
            if (!tmp) return CLI_RUNTIME;
            lx_status st = lx_backend_parse(tmp, optarg, &a->io.backend);
            lx_ctx_destroy(tmp);
            if (st) return cli_error(cmd, "--backend: '%s' is not auto, cpu or opencl", optarg), CLI_USAGE;
            break;
        }
        case 't': {
            char *end;
            long v = strtol(optarg, &end, 10);
            if (*end || v < 0 || v > 64) return cli_error(cmd, "--threads: '%s' is not 0..64", optarg), CLI_USAGE;
            a->io.threads = (int)v;
            break;
        }
        case 'H': a->half = 1; break;
        case 'p': a->png = optarg; break;
        case 'S':
            if (!strcmp(optarg, "log")) a->scale = LX_PLOT_SCALE_LOG;
            else if (!strcmp(optarg, "linear")) a->scale = LX_PLOT_SCALE_LINEAR;
            else return cli_error(cmd, "--scale: '%s' is not log or linear", optarg), CLI_USAGE;
            break;
        case 'n': a->normal = optarg; break;
        case 'u': a->units = optarg; break;
        case 'K': a->eff = optarg; break;
        case 'f':
            a->fmt = cli_format_parse(optarg);
            if (a->fmt < 0) return cli_error(cmd, "--format: '%s' is not table, csv or json", optarg), CLI_USAGE;
            break;
        case 'o': a->out = optarg; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_bad_option(cmd, argv, c);
        }
    }
    return -1;
}

/* --normal into n, or (without it) the checks on -o: -1 to go on, else CLI_USAGE. */
static int check_target(const char *cmd, const irr_args *a, double n[3])
{
    const char *normal = a->normal, *out = a->out;
    if (normal) {
        char *end;
        n[0] = strtod(normal, &end);
        for (int k = 1; k < 3 && *end == ','; k++) n[k] = strtod(end + 1, &end);
        if (*end || !isfinite(n[0] + n[1] + n[2]) || !(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0) ||
            strchr(normal, ',') == strrchr(normal, ','))
            return cli_error(cmd, "--normal: '%s' is not a non-zero vector X,Y,Z", normal), CLI_USAGE;
    } else if (!out) {
        return cli_error(cmd, "-o OUT.exr is required (or --normal X,Y,Z)"), CLI_USAGE;
    } else {
        size_t ol = strlen(out); /* OUT is OpenEXR: never EXR bytes under a picture's name */
        static const char *const pics[] = {".png", ".PNG", ".jpg", ".jpeg", ".JPG", ".tif", ".tiff", ".hdr"};
        for (size_t k = 0; k < sizeof pics / sizeof *pics; k++)
            if (ol >= strlen(pics[k]) && !strcmp(out + ol - strlen(pics[k]), pics[k]))
                return cli_error(cmd, "-o %s: OUT is written as OpenEXR; name it .exr (a picture: --png FILE)", out), CLI_USAGE;
    }
    return -1;
}

/* --normal: the one row for normal n, written to -o or stdout; the exit code. */
static int one_normal(lx_ctx *ctx, const char *cmd, const lx_envmap *m, const irr_args *a, const double n[3])
{
    double E[3];
    lx_status st = lx_irradiance_dirs(ctx, m, 1, n, &a->io, E);
    if (st) return cli_fail(cmd, ctx, st);
    int rc = 0;
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), Y = y_of(m, E);
    static const char *const names[] = {"nx", "ny", "nz", "irradiance", "illuminance_lx", "method",
                                        "irradiance_r", "irradiance_g", "irradiance_b"};
    static const char *const unit_r[] = {"", "", "", "W/m2", "lx", "", "W/m2", "W/m2", "W/m2"};
    cli_table *t = cli_table_new(m->channels == 3 ? 9 : 6, names, unit_r);
    for (int k = 0; k < 3; k++) cli_table_num(t, n[k] / l);
    cli_table_num(t, Y);
    cli_table_num(t, Y * m->lum_per_unit);
    cli_table_str(t, mname[lx_ctx_irradiance_method(ctx, NULL)]);
    if (m->channels == 3)
        for (int k = 0; k < 3; k++) cli_table_num(t, E[k]);
    cli_output o;
    if (cli_output_open(&o, a->out, cmd)) rc = CLI_INPUT;
    else {
        int bad = cli_table_write(t, (cli_format)a->fmt, o.fp, 0);
        if (cli_output_close(&o, !bad, cmd) || bad) rc = CLI_RUNTIME;
    }
    cli_table_free(t);
    sh9_notes(ctx, cmd, m, &a->io, Y < 0 ? Y * m->lum_per_unit : 0, Y < 0, 1);
    return rc;
}

/* After an SH9 map e of m: its negative outputs (how many, the most negative illuminance) to sh9_notes. */
static void sh9_map_notes(lx_ctx *ctx, const char *cmd, const lx_envmap *m, const lx_envmap *e, const lx_irr_opts *io)
{
    size_t n_out = (size_t)e->width * e->height, n_neg = 0;
    double neg = 0;
    for (size_t k = 0; k < n_out; k++) {
        double v[3] = {0, 0, 0};
        for (int c = 0; c < e->channels; c++) v[c] = e->data[k * e->channels + c];
        double y = y_of(e, v) * e->lum_per_unit;
        if (y < 0) n_neg++, neg = y < neg ? y : neg;
    }
    sh9_notes(ctx, cmd, m, io, neg, n_neg, n_out);
}

/* The irradiance map of m into *e, written to -o (and --png); the exit code. */
static int irr_map(lx_ctx *ctx, const char *cmd, const lx_envmap *m, const irr_args *a, lx_envmap **e)
{
    int W = a->W, H = a->H;
    const lx_irr_opts *io = &a->io;
    if (W == 0 && (double)m->width * m->height * m->width * m->height > 4e10 && io->method == LX_IRR_BRUTE &&
        io->backend != LX_BACKEND_OPENCL)
        cli_error(cmd, "warning: brute force %dx%d -> %dx%d is %.2g pixel pairs; consider --size or --method fast",
                  m->width, m->height, m->width, m->height, (double)m->width * m->height * m->width * m->height);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    lx_status st = lx_irradiance_map(ctx, m, W, H, io, e);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    lx_exr_write_opts wo = {.half = a->half};
    if (!st) st = lx_envmap_write_exr(ctx, a->out, *e, &wo);
    lx_irr_method ran = lx_ctx_irradiance_method(ctx, NULL);
    if (!st && ran == LX_IRR_SH9) sh9_map_notes(ctx, cmd, m, *e, io);
    if (!st && a->png) {
        st = lx_irradiance_write_png(ctx, a->png, m, *e, mname[ran], a->scale);
    }
    if (st) return cli_fail(cmd, ctx, st);
    if (cli_verbose)
        fprintf(stderr, "luxcalc: irradiance: %s %dx%d -> %dx%d in %.3f s (%s)\n", mname[ran], m->width,
                m->height, (*e)->width, (*e)->height, (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec),
                lx_ctx_backend_used(ctx) == LX_BACKEND_OPENCL ? "opencl" : "cpu");
    return 0;
}

int cmd_irradiance(int argc, char **argv)
{
    const char *cmd = "irradiance";
    irr_args a = {.io = {.method = LX_IRR_AUTO}, .fmt = CLI_FMT_TABLE, .scale = LX_PLOT_SCALE_LOG};
    int rc = parse_opts(cmd, argc, argv, &a);
    if (rc >= 0) return rc;
    if (optind + 1 != argc) return cli_error(cmd, "give exactly one input map (see --help)"), CLI_USAGE;
    const char *in = argv[optind];
    double n[3] = {0, 0, 0}; /* "X,Y" leaves n[2] unparsed: the checks below read it */
    if ((rc = check_target(cmd, &a, n)) >= 0) return rc;
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    lx_envmap *m = NULL, *e = NULL;
    lx_status st = lx_exr_read_any(ctx, in, &m);
    rc = st ? cli_fail(cmd, ctx, st) : cli_envmap_units(cmd, m, a.units, a.eff);
    if (!rc && a.normal) {
        rc = one_normal(ctx, cmd, m, &a, n);
    } else if (!rc && m->layout == LX_ENV_CUBE && a.W && a.H != 6 * a.W) {
        cli_error(cmd, "--size: %dx%d: the input is a cube map, give N x 6N", a.W, a.H);
        rc = CLI_USAGE;
    } else if (!rc) {
        rc = irr_map(ctx, cmd, m, &a, &e);
    }
    lx_envmap_free(e);
    lx_envmap_free(m);
    lx_ctx_destroy(ctx);
    return rc;
}
