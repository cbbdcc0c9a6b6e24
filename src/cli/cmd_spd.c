/* cmd_spd.c - `luxcalc spd`: colorimetry and photometry of spectra read from files. */
#include "cli.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc spd [OPTIONS] FILE...\n"
    "\n"
    "Reads spectral power distributions and prints, for each spectrum, absolute XYZ, xy, u'v',\n"
    "CCT and Duv, luminous efficacy of radiation, scotopic Y and the S/P ratio.\n"
    "FILE: columns (wavelength_nm, value...) or rows (id,380,381,...), separators , ; tab space,\n"
    "'#' comments, optional header; CGATS/Argyll spectral files; '-' reads standard input.\n"
    "\n"
    "options:\n"
    "  --observer 2|10        CIE 1931 2 deg (default) or CIE 1964 10 deg observer\n"
    "  --method M             auto (default) | cie15 | exact | linear1nm\n"
    "                         cie15: sum at the data's own uniform step (CIE 015 practice)\n"
    "                         exact: exact integral of piecewise-linear data x piecewise-linear CMFs\n"
    "                         linear1nm: interpolate to 1 nm, then sum\n"
    "                         auto: cie15 for uniform 1 or 5 nm data on whole nm, else exact\n"
    "  --unit U               what the values are: relative (default) | W/nm (Y in lm) |\n"
    "                         W/m2/nm (lx) | W/sr/m2/nm (cd/m2) | W/sr/nm (cd)\n"
    "  --format F             table (default) | csv | json\n"
    "  -o FILE                write the results to FILE (atomically)\n"
    "  -v, -q                 more messages / errors only\n"
    "  -h, --help             this help\n"
    "\n"
    "csv columns: file,spectrum,X,Y,Z,x,y,u_prime,v_prime,cct_K,duv,ler_lm_per_W,scotopic_Y,\n"
    "sp_ratio,radiant,method. cct_K and duv are empty where CCT has no meaning (|Duv| > 0.05 or\n"
    "outside 1000-100000 K). A bad file is reported and skipped; the exit status is then 2.\n"
    "\n"
    "example:\n"
    "  luxcalc spd --format csv samples/spd/cie_illuminants.csv\n"
    "  luxcalc spd --unit W/nm --observer 10 lamp.csv\n";

static const struct {
    const char *name, *photometric, *radiant;
} units[] = {
    {"relative", "", ""},
    {"W/nm", "lm", "W"},
    {"W/m2/nm", "lx", "W/m2"},
    {"W/sr/m2/nm", "cd/m2", "W/(sr m2)"},
    {"W/sr/nm", "cd", "W/sr"},
};

static const char *method_name(lx_method m)
{
    switch (m) {
    case LX_METHOD_CIE15: return "cie15";
    case LX_METHOD_EXACT: return "exact";
    case LX_METHOD_LINEAR1NM: return "linear1nm";
    default: return "auto";
    }
}

int cmd_spd(int argc, char **argv)
{
    static const struct option opts[] = {
        {"observer", required_argument, NULL, 'b'}, {"method", required_argument, NULL, 'm'},
        {"unit", required_argument, NULL, 'u'},     {"format", required_argument, NULL, 'f'},
        {"output", required_argument, NULL, 'o'},   {"verbose", no_argument, NULL, 'v'},
        {"quiet", no_argument, NULL, 'q'},          {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    const char *cmd = "spd", *outpath = NULL;
    lx_observer obs = LX_OBSERVER_2;
    lx_method method = LX_METHOD_AUTO;
    int fmt = CLI_FMT_TABLE, unit = 0, c;
    optind = 1;
    while ((c = getopt_long(argc, argv, "o:vqh", opts, NULL)) != -1) {
        switch (c) {
        case 'b':
            if (!strcmp(optarg, "2")) obs = LX_OBSERVER_2;
            else if (!strcmp(optarg, "10")) obs = LX_OBSERVER_10;
            else return cli_error(cmd, "--observer: expected 2 or 10, not '%s'", optarg), CLI_USAGE;
            break;
        case 'm':
            if (!strcmp(optarg, "auto")) method = LX_METHOD_AUTO;
            else if (!strcmp(optarg, "cie15")) method = LX_METHOD_CIE15;
            else if (!strcmp(optarg, "exact")) method = LX_METHOD_EXACT;
            else if (!strcmp(optarg, "linear1nm")) method = LX_METHOD_LINEAR1NM;
            else return cli_error(cmd, "--method: expected auto, cie15, exact or linear1nm, not '%s'", optarg), CLI_USAGE;
            break;
        case 'u':
            unit = -1;
            for (int i = 0; i < (int)(sizeof units / sizeof *units); i++)
                if (!strcmp(optarg, units[i].name)) unit = i;
            if (unit < 0)
                return cli_error(cmd, "--unit: expected relative, W/nm, W/m2/nm, W/sr/m2/nm or W/sr/nm, not '%s'", optarg),
                       CLI_USAGE;
            break;
        case 'f':
            if ((fmt = cli_format_parse(optarg)) < 0)
                return cli_error(cmd, "--format: expected table, csv or json, not '%s'", optarg), CLI_USAGE;
            break;
        case 'o': outpath = optarg; break;
        case 'v': cli_verbose++; break;
        case 'q': cli_quiet = 1; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: fprintf(stderr, "%s", help); return CLI_USAGE;
        }
    }
    if (optind >= argc) {
        cli_error(cmd, "no input file (use - for standard input)");
        return CLI_USAGE;
    }
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;

    const char *pu = units[unit].photometric, *ru = units[unit].radiant;
    static char ler_unit[32];
    snprintf(ler_unit, sizeof ler_unit, "%s", unit ? "lm/W" : "");
    const char *names[] = {"file", "spectrum", "X", "Y", "Z", "x", "y", "u_prime", "v_prime", "cct_K", "duv",
                           "ler_lm_per_W", "scotopic_Y", "sp_ratio", "radiant", "method"};
    const char *unitnames[] = {"", "", pu, pu, pu, "", "", "", "", "K", "", ler_unit, pu, "", ru, ""};
    int ncols = (int)(sizeof names / sizeof *names);
    cli_table *t = cli_table_new(ncols, names, unitnames);
    int rc = CLI_OK;
    for (int i = optind; i < argc; i++) {
        lx_spd_set *set = NULL;
        lx_status st = lx_spd_read_file(ctx, argv[i], &set);
        if (st != LX_OK) {
            int e = cli_fail(cmd, ctx, st);
            if (e > rc) rc = e;
            continue;
        }
        for (size_t k = 0; k < set->count; k++) {
            lx_colorimetry r;
            st = lx_spd_colorimetry(ctx, &set->spd[k], obs, method, &r);
            if (st != LX_OK) {
                cli_error(cmd, "%s:%ld: spectrum '%s': %s", set->file, set->line ? set->line[k] : 0L,
                          set->spd[k].name ? set->spd[k].name : "", lx_ctx_errmsg(ctx));
                int e = cli_exit_code(st);
                if (e > rc) rc = e;
                continue;
            }
            cli_table_str(t, set->file);
            cli_table_str(t, set->spd[k].name ? set->spd[k].name : "");
            double v[] = {r.X, r.Y, r.Z, r.x, r.y, r.u_prime, r.v_prime, r.cct_K, r.duv, r.ler_lm_per_W,
                          r.scotopic_Y, r.sp_ratio, r.radiant};
            for (size_t j = 0; j < sizeof v / sizeof *v; j++) cli_table_num(t, v[j]);
            cli_table_str(t, method_name(r.method));
        }
        lx_spd_set_free(set);
    }
    cli_output o;
    if (rc != CLI_OK && cli_table_rows(t) == 0) {
        /* nothing computed: leave any existing output file as it was */
    } else if (cli_output_open(&o, outpath, cmd) != 0) {
        rc = CLI_INPUT;
    } else {
        int ok = cli_table_write(t, (cli_format)fmt, o.fp, 0) == 0;
        if (cli_output_close(&o, ok, cmd) != 0 || !ok) rc = rc ? rc : CLI_INPUT;
    }
    cli_table_free(t);
    lx_ctx_destroy(ctx);
    return rc;
}
