/* cmd_refspd.c - `luxcalc blackbody` and `luxcalc daylight`: print a generated spectrum (Planck's
 * law, CIE D-series daylight) as wavelength_nm,value rows. */
#include "cli.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char bb_help[] =
    "usage: luxcalc blackbody --temperature T [--range START:END:STEP] [--format csv|json|table] [-o FILE]\n"
    "\n"
    "Prints the spectral radiance of a blackbody by Planck's law, in W/(sr m2 nm), as csv\n"
    "(wavelength_nm,value). T in kelvin (a bare number or with K: 2856, 2856K). The default\n"
    "range is 360:830:1 (nm). Stable from 1 K to 1e9 K: values that underflow print as 0.\n"
    "\n"
    "example:\n"
    "  luxcalc blackbody --temperature 2856K --range 380:780:5 > a.csv\n";

static const char dl_help[] =
    "usage: luxcalc daylight --cct T [--range START:END:STEP] [--format csv|json|table] [-o FILE]\n"
    "\n"
    "Prints the CIE D-series relative spectral power distribution (CIE 015:2018 4.1.2) for a\n"
    "correlated colour temperature of 4000 K to 25000 K, as csv (wavelength_nm,value). The basis\n"
    "functions S0, S1, S2 are tabulated at 5 nm from 300 to 830 nm and linearly interpolated\n"
    "between; the default range is 300:830:5. D65 is --cct 6504 (6500 K x 1.4388/1.4380).\n"
    "\n"
    "example:\n"
    "  luxcalc daylight --cct 6504 > d65.csv\n";

/* "2856", "2856K", "2856 K" */
static int parse_kelvin(const char *s, double *out)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%s", s);
    size_t n = strlen(buf);
    while (n && buf[n - 1] == ' ') buf[--n] = 0;
    if (n && buf[n - 1] == 'K') buf[--n] = 0;
    return cli_parse_double(buf, out);
}

static int parse_range(const char *s, double *a, double *b, double *step)
{
    char buf[128], *p1, *p2;
    snprintf(buf, sizeof buf, "%s", s);
    if (!(p1 = strchr(buf, ':')) || !(p2 = strchr(p1 + 1, ':'))) return -1;
    *p1 = *p2 = 0;
    if (cli_parse_double(buf, a) || cli_parse_double(p1 + 1, b) || cli_parse_double(p2 + 1, step)) return -1;
    if (!(*a > 0) || !(*b >= *a) || !(*step > 0) || (*b - *a) / *step > 1e7) return -1;
    return 0;
}

static int run(int argc, char **argv, int daylight)
{
    static const struct option opts[] = {
        {"temperature", required_argument, NULL, 't'}, {"cct", required_argument, NULL, 't'},
        {"range", required_argument, NULL, 'r'},       {"format", required_argument, NULL, 'f'},
        {"output", required_argument, NULL, 'o'},      {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    const char *cmd = daylight ? "daylight" : "blackbody", *help = daylight ? dl_help : bb_help;
    const char *outpath = NULL;
    double T = NAN, a = daylight ? 300 : 360, b = 830, step = daylight ? 5 : 1;
    int fmt = CLI_FMT_CSV, c;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 't':
            if (parse_kelvin(optarg, &T) || !(T > 0))
                return cli_error(cmd, "%s: expected a positive temperature in K, not '%s'",
                                 daylight ? "--cct" : "--temperature", optarg), CLI_USAGE;
            break;
        case 'r':
            if (parse_range(optarg, &a, &b, &step))
                return cli_error(cmd, "--range: expected START:END:STEP in nm (START > 0, END >= START, STEP > 0), not '%s'",
                                 optarg), CLI_USAGE;
            break;
        case 'f':
            if ((fmt = cli_format_parse(optarg)) < 0)
                return cli_error(cmd, "--format: expected table, csv or json, not '%s'", optarg), CLI_USAGE;
            break;
        case 'o': outpath = optarg; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_bad_option(cmd, argv, c);
        }
    }
    if (isnan(T)) return cli_error(cmd, "%s is required", daylight ? "--cct" : "--temperature"), CLI_USAGE;
    if (optind < argc) return cli_error(cmd, "unexpected argument '%s'", argv[optind]), CLI_USAGE;
    size_t n = (size_t)floor((b - a) / step + 1e-9) + 1;
    double *wl = malloc(n * sizeof *wl), *val = malloc(n * sizeof *val);
    if (!wl || !val) return free(wl), free(val), cli_error(cmd, "out of memory"), CLI_RUNTIME;
    for (size_t i = 0; i < n; i++) wl[i] = a + (double)i * step;
    int rc = CLI_OK;
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return free(wl), free(val), CLI_RUNTIME;
    if (daylight) {
        lx_status st = lx_daylight(ctx, T, n, wl, val);
        if (st != LX_OK) rc = cli_fail(cmd, ctx, st);
    } else {
        for (size_t i = 0; i < n; i++) val[i] = lx_planck(wl[i], T);
    }
    if (rc == CLI_OK) {
        const char *names[] = {"wavelength_nm", "value"};
        const char *unitn[] = {"nm", daylight ? "" : "W/(sr m2 nm)"};
        cli_table *t = cli_table_new(2, names, unitn);
        for (size_t i = 0; i < n; i++) cli_table_num(t, wl[i]), cli_table_num(t, val[i]);
        cli_output o;
        if (cli_output_open(&o, outpath, cmd) != 0) rc = CLI_INPUT;
        else {
            int ok = cli_table_write(t, (cli_format)fmt, o.fp, 1) == 0;
            if (cli_output_close(&o, ok, cmd) != 0 || !ok) rc = CLI_RUNTIME;
        }
        cli_table_free(t);
    }
    lx_ctx_destroy(ctx);
    free(wl);
    free(val);
    return rc;
}

int cmd_blackbody(int argc, char **argv) { return run(argc, argv, 0); }
int cmd_daylight(int argc, char **argv) { return run(argc, argv, 1); }
