/* main.c - luxcalc entry point: global options, the command table, generated help. */
#include "cli.h"

#include <stdlib.h>
#include <string.h>

int cmd_spd(int argc, char **argv);
int cmd_blackbody(int argc, char **argv);
int cmd_daylight(int argc, char **argv);
int cmd_ies(int argc, char **argv);
int cmd_grid(int argc, char **argv);
/* ---- command declarations (one line per command) ---- */
int cmd_sky(int argc, char **argv);
int cmd_ugr(int argc, char **argv);
int cmd_report(int argc, char **argv);
int cmd_irradiance(int argc, char **argv);
int cmd_luminance_map(int argc, char **argv);
int cmd_scene(int argc, char **argv);
int cmd_devices(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_point(int argc, char **argv);
int cmd_spot(int argc, char **argv);
int cmd_disk(int argc, char **argv);
int cmd_rect(int argc, char **argv);
int cmd_convert(int argc, char **argv);
int cmd_solve(int argc, char **argv);

const cli_cmd cli_commands[] = {
    {"spd", cmd_spd, "colorimetry and photometry of measured spectra (XYZ, xy, CCT, Duv, efficacy)"},
    {"blackbody", cmd_blackbody, "Planck spectral radiance of a blackbody as csv"},
    {"daylight", cmd_daylight, "CIE D-series daylight relative SPD as csv"},
    {"point", cmd_point, "illuminance from an isotropic point source (inverse square, cosine law)"},
    {"spot", cmd_spot, "Warn spotlight: intensity and illuminance off its axis"},
    {"disk", cmd_disk, "Lambertian disk on a parallel receiver: exact, point model and its error"},
    {"rect", cmd_rect, "Lambertian rectangle on a parallel receiver: exact, point model and its error"},
    {"convert", cmd_convert, "a quantity in every unit (lx, fc, cd/m2, fL, ...; W <-> lm with an efficacy)"},
    {"solve", cmd_solve, "inverse problems: distance, intensity or flux for a target illuminance"},
    {"ies", cmd_ies, "luminaire photometry: IES LM-63 / EULUMDAT summaries, LM-63-2002 from models"},
    {"grid", cmd_grid, "illuminance on a grid of points from luminaires (csv, summary, PNG)"},
    {"irradiance", cmd_irradiance, "irradiance environment map (or one normal) from a lat-long radiance EXR"},
    {"luminance-map", cmd_luminance_map, "luminance statistics and a false-colour PNG of an HDR map"},
    {"scene", cmd_scene, "a lighting scene file: only the effects it needs (--explain says which and why)"},
    {"devices", cmd_devices, "the OpenCL platforms and devices, and which one auto would use"},
    {"bench", cmd_bench, "measured performance and accuracy-against-time tables (spd, metrics, irradiance, grid, accuracy)"},
    /* ---- command table entries (one line per command) ---- */
    {"sky", cmd_sky, "a CIE standard general or Perez sky with the sun as a lat-long luminance EXR"},
    {"ugr", cmd_ugr, "the CIE 190 tabular UGR table of an IES/EULUMDAT luminaire"},
    {"report", cmd_report, "the design report of a scene as a PDF: schedule, plans, isolux, checks, UGR, energy"},
    {NULL, NULL, NULL},
};

static void usage(FILE *out)
{
    fprintf(out, "usage: luxcalc [--version] [-v|-q] [--max-input-mb N] COMMAND [OPTIONS] [ARGS]\n\n"
                 "Photometry and radiometry: spectra, lighting calculations, luminaires, radiance maps.\n\n"
                 "commands:\n");
    for (const cli_cmd *c = cli_commands; c->name; c++) fprintf(out, "  %-14s %s\n", c->name, c->summary);
    fprintf(out, "\nOptions of every command that prints results: --format table|csv|tsv|json, -o FILE,\n"
                 "--precision N (significant digits in the table format), --units metric|imperial (fc, ft,\n"
                 "fL; or unit names, e.g. --units imperial,cd/ft2).\n"
                 "\nRun 'luxcalc COMMAND --help' for a command's options and an example.\n"
                 "Exit status: 0 success, 1 usage error, 2 input error, 3 runtime error.\n"
                 "--max-input-mb N (or LX_MAX_INPUT_MB=N): the size limit of every text input file in MB\n"
                 "(default 256 for spectra, 16 for photometric and scene files; README \"Robustness\").\n");
}

int main(int argc, char **argv)
{
    cli_stdout_guard();
    int i = 1;
    for (; i < argc && argv[i][0] == '-'; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--version") || !strcmp(a, "-V")) {
            printf("luxcalc %s\n", lx_version());
            return CLI_OK;
        } else if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return CLI_OK;
        } else if (!strcmp(a, "-v") || !strcmp(a, "--verbose")) {
            cli_verbose++;
        } else if (!strcmp(a, "-vv")) {
            cli_verbose += 2;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            cli_quiet = 1;
        } else if (!strcmp(a, "--max-input-mb") || !strncmp(a, "--max-input-mb=", 15)) {
            const char *v = a[14] == '=' ? a + 15 : i + 1 < argc ? argv[++i] : NULL;
            if (cli_parse_input_mb(v, &cli_max_input_mb) != 0) {
                fprintf(stderr, "luxcalc: --max-input-mb: expected a whole number of MB from 1 to %d, not '%s'\n",
                        CLI_MAX_INPUT_MB, v ? v : "");
                return CLI_USAGE;
            }
        } else {
            fprintf(stderr, "luxcalc: unknown option '%s'\n", a);
            usage(stderr);
            return CLI_USAGE;
        }
    }
    if (i >= argc) {
        usage(stderr);
        return CLI_USAGE;
    }
    /* the environment's switches, checked once for every command (the library ignores bad values) */
    const char *simd = getenv("LX_SIMD"), *backend = getenv("LX_BACKEND");
    if ((simd && *simd) || (backend && *backend)) {
        lx_simd sp;
        lx_backend bp;
        lx_ctx *ctx = NULL;
        if (lx_ctx_create(&ctx) != LX_OK) {
            fprintf(stderr, "luxcalc: out of memory\n");
            return CLI_RUNTIME;
        }
        int bad_simd = simd && *simd && lx_simd_parse(ctx, simd, &sp) != LX_OK;
        int bad_backend = !bad_simd && backend && *backend && lx_backend_parse(ctx, backend, &bp) != LX_OK;
        lx_ctx_destroy(ctx);
        if (bad_simd) {
            fprintf(stderr, "luxcalc: LX_SIMD='%s' is not scalar, avx2 or avx512\n", simd);
            return CLI_USAGE;
        }
        if (bad_backend) {
            fprintf(stderr, "luxcalc: LX_BACKEND='%s' is not auto, cpu or opencl\n", backend);
            return CLI_USAGE;
        }
    }
    const char *maxin = getenv("LX_MAX_INPUT_MB");
    size_t mb;
    if (maxin && *maxin && cli_parse_input_mb(maxin, &mb) != 0) {
        fprintf(stderr, "luxcalc: LX_MAX_INPUT_MB='%s' is not a whole number of MB from 1 to %d\n", maxin, CLI_MAX_INPUT_MB);
        return CLI_USAGE;
    }
    for (const cli_cmd *c = cli_commands; c->name; c++)
        if (!strcmp(c->name, argv[i])) {
            int n = argc - i;
            if (cli_output_options(c->name, &n, argv + i)) return CLI_USAGE;
            cli_join_units(&n, argv + i);
            int rc = c->run(n, argv + i);
            int w = cli_stdout_check(c->name); /* what a command printed itself, and a closed stdout */
            return w ? w : rc;
        }
    if (!strcmp(argv[i], "help")) {
        if (i + 1 < argc)
            for (const cli_cmd *c = cli_commands; c->name; c++)
                if (!strcmp(c->name, argv[i + 1])) {
                    char *hv[] = {argv[i + 1], "--help", NULL};
                    return c->run(2, hv);
                }
        usage(stdout);
        return CLI_OK;
    }
    fprintf(stderr, "luxcalc: unknown command '%s'\n", argv[i]);
    usage(stderr);
    return CLI_USAGE;
}
