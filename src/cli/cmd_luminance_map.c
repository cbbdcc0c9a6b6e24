/* cmd_luminance_map.c - `luxcalc luminance-map`: per-pixel luminance of an HDR map, its
 * statistics, and a false-colour PNG with a legend (the Radiance falsecolor look). */
#include "cli.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc luminance-map IN.exr [--png FILE] [--scale log|linear] [--range MIN:MAX]\n"
    "\n"
    "Per-pixel luminance L = k (wR R + wG G + wB B): weights from the file's chromaticities, else\n"
    "Rec.709/sRGB (0.2126, 0.7152, 0.0722 with D65); k = whiteLuminance when the file has it\n"
    "(values are then relative luminance), else the efficacy (179 lm/W) for W/sr/m2 radiance.\n"
    "Prints min, max, mean and median over the pixels (cd/m2; lx for an irradiance map that luxcalc\n"
    "irradiance wrote: its values are illuminances), and with --png draws the map in false colour,\n"
    "the look of Radiance falsecolor: a log scale with decade ticks (a flat map keeps two decades)\n"
    "or a linear one with round ticks, and the unit on the legend. A small bright source (the sun\n"
    "disc: values over 100 times the 99.9th percentile) is left out of the automatic range, drawn in\n"
    "the top colour and named under the title, so the sky keeps the palette; --range keeps it in.\n"
    "\n"
    "  --png FILE       false-colour PNG with a legend (atomic)\n"
    "  --scale S        log (default) or linear\n"
    "  --range MIN:MAX  legend range in cd/m2 (lx) (default: the map's, less a small bright source;\n"
    "                   log needs MIN > 0)\n"
    "  --units U        auto (default), radiance or luminance (see luxcalc irradiance --help)\n"
    "  --efficacy K     lm/W for radiance maps (default 179)\n"
    "  --format F       table (default), csv or json\n"
    "  -o FILE          write the statistics to FILE (atomic)\n"
    "\n"
    "csv columns: min,max,mean,median,mean_sr_weighted,width,height,file (luminances in cd/m2;\n"
    "mean_sr_weighted is the mean over the sphere, each pixel weighted by its solid angle)\n"
    "\n"
    "example:\n"
    "  luxcalc luminance-map samples/envmaps/sky_sun.exr --png /tmp/sky_lum.png --format csv\n";

int cli_envmap_units(const char *cmd, lx_envmap *m, const char *units, const char *eff);

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int cmd_luminance_map(int argc, char **argv)
{
    static const struct option opts[] = {
        {"png", required_argument, 0, 'p'},    {"scale", required_argument, 0, 's'},
        {"range", required_argument, 0, 'r'},  {"units", required_argument, 0, 'u'},
        {"efficacy", required_argument, 0, 'K'}, {"format", required_argument, 0, 'f'},
        {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    const char *cmd = "luminance-map", *png = NULL, *out = NULL, *units = NULL, *eff = NULL;
    int log_scale = 1, fmt = CLI_FMT_TABLE, c;
    double vmin = NAN, vmax = NAN;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'p': png = optarg; break;
        case 's':
            if (!strcmp(optarg, "log")) log_scale = 1;
            else if (!strcmp(optarg, "linear")) log_scale = 0;
            else return cli_error(cmd, "--scale: '%s' is not log or linear", optarg), CLI_USAGE;
            break;
        case 'r': {
            char *end;
            vmin = strtod(optarg, &end);
            if (*end == ':') vmax = strtod(end + 1, &end);
            if (*end || !isfinite(vmin) || !isfinite(vmax) || !(vmax > vmin))
                return cli_error(cmd, "--range: '%s' is not MIN:MAX with MIN < MAX", optarg), CLI_USAGE;
            break;
        }
        case 'u': units = optarg; break;
        case 'K': eff = optarg; break;
        case 'f':
            fmt = cli_format_parse(optarg);
            if (fmt < 0) return cli_error(cmd, "--format: '%s' is not table, csv or json", optarg), CLI_USAGE;
            break;
        case 'o': out = optarg; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_bad_option(cmd, argv, c);
        }
    }
    if (optind + 1 != argc) return cli_error(cmd, "give exactly one input map (see --help)"), CLI_USAGE;
    if (log_scale && !isnan(vmin) && !(vmin > 0)) return cli_error(cmd, "--range: a log scale needs MIN > 0"), CLI_USAGE;
    const char *in = argv[optind];
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    lx_envmap *m = NULL;
    double *lum = NULL, *sorted = NULL;
    lx_status st = lx_exr_read_any(ctx, in, &m);
    int rc = st ? cli_fail(cmd, ctx, st) : cli_envmap_units(cmd, m, units, eff);
    if (!rc) {
        size_t n = (size_t)m->width * m->height;
        lum = malloc(n * sizeof *lum);
        sorted = malloc(n * sizeof *sorted);
        if (!lum || !sorted) rc = CLI_RUNTIME, cli_error(cmd, "out of memory");
        if (!rc) st = lx_envmap_luminance(ctx, m, lum);
        if (!rc && st) rc = cli_fail(cmd, ctx, st);
        if (!rc) {
            double sum = 0, wsum = 0, wtot = 0;
            for (size_t p = 0; p < n; p++) {
                double w = lx_envmap_texel_sr(m, (int)(p / m->width), (int)(p % m->width));
                sum += lum[p];
                wsum += w * lum[p];
                wtot += w;
            }
            memcpy(sorted, lum, n * sizeof *sorted);
            qsort(sorted, n, sizeof *sorted, cmp_double);
            double med = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
            static const char *const names[] = {"min", "max", "mean", "median", "mean_sr_weighted", "width", "height", "file"};
            /* an irradiance map (luxcalc irradiance -o) holds illuminance per normal, in lx */
            const char *u = m->irradiance ? "lx" : "cd/m2";
            const char *unit_s[] = {u, u, u, u, u, "px", "px", ""};
            cli_table *t = cli_table_new(8, names, unit_s);
            cli_table_num(t, sorted[0]);
            cli_table_num(t, sorted[n - 1]);
            cli_table_num(t, sum / n);
            cli_table_num(t, med);
            cli_table_num(t, wsum / wtot);
            cli_table_int(t, m->width);
            cli_table_int(t, m->height);
            cli_table_str(t, in);
            if (png) {
                const char *base = strrchr(in, '/');
                char title[300], unit[32];
                snprintf(title, sizeof title, "%s \u2014 %s", m->irradiance ? "Illuminance of each normal" : "Luminance",
                         base ? base + 1 : in);
                cli_column col; /* the output unit (--units imperial: fc, fL) */
                cli_column_out("v", u, &col);
                for (size_t p = 0; col.scale != 1 && p < n; p++) lum[p] *= col.scale;
                if (!strcmp(col.unit, "cd/m2")) snprintf(unit, sizeof unit, "cd/m\u00b2");
                else if (!strcmp(col.unit, "cd/ft2")) snprintf(unit, sizeof unit, "cd/ft\u00b2");
                else snprintf(unit, sizeof unit, "%s", col.unit);
                lx_falsecolor_opts fo = {.scale = log_scale ? LX_PLOT_SCALE_LOG : LX_PLOT_SCALE_LINEAR,
                                         .lo = isnan(vmin) ? 0 : vmin * col.scale, .hi = isnan(vmax) ? 0 : vmax * col.scale,
                                         .quantity = m->irradiance ? "illuminance" : "luminance", .unit = unit,
                                         .title = title};
                st = lx_falsecolor_write_png(ctx, png, m->width, m->height, lum, &fo);
                if (st) rc = cli_fail(cmd, ctx, st);
            }
            if (!rc) {
                cli_output o;
                if (cli_output_open(&o, out, cmd)) rc = CLI_INPUT;
                else {
                    int bad = cli_table_write(t, (cli_format)fmt, o.fp, 0);
                    if (cli_output_close(&o, !bad, cmd) || bad) rc = CLI_RUNTIME;
                }
            }
            cli_table_free(t);
        }
    }
    free(lum);
    free(sorted);
    lx_envmap_free(m);
    lx_ctx_destroy(ctx);
    return rc;
}
