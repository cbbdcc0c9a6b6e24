/* cmd_ugr.c - `luxcalc ugr FILE.ies|.ldt`: the CIE 190:2010 tabular UGR of a luminaire (19 rooms,
 * 5 reflectance combinations, crosswise and endwise), as luminaire data sheets print it. */
#include "cli.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc ugr FILE.ies|FILE.ldt [--format table|csv|tsv|json] [-o FILE]\n"
    "\n"
    "The CIE 190:2010 UGR table of the luminaire at its own lamp flux (uncorrected): rooms X x Y\n"
    "from 2H x 2H to 12H x 8H (X across the line of sight, H the luminaire plane above the eye),\n"
    "luminaires on a square grid of spacing 0.25H, the observer at the middle of a wall, reflectances\n"
    "ceiling/walls/floor cavity 70/50/20, 70/30/20, 50/50/20, 50/30/20, 30/30/20, viewed crosswise\n"
    "(the luminaire's C0-C180 plane along the line of sight) and endwise (turned by 90 deg).\n"
    "The luminance of each luminaire is its intensity towards the eye over its projected luminous\n"
    "area (the file's luminous opening: width, length and height); the background luminance follows\n"
    "CIE 190 eqs. 7-12; the position index is the Luckiesh-Guth formula of CIE 117.\n"
    "\n"
    "The table format prints the matrix of data sheets: the reflectances over ten columns, then a\n"
    "line per room size (X, Y) with the crosswise and endwise values to one decimal. csv, tsv and\n"
    "json print one row per room, every digit: x_H,y_H, then cross_70_50_20 ... cross_30_30_20,\n"
    "end_70_50_20 ... end_30_30_20.\n"
    "\n"
    "example:\n"
    "  luxcalc ugr luminaire.ldt\n";

int cmd_ugr(int argc, char **argv)
{
    static const struct option opts[] = {{"format", required_argument, 0, 'f'}, {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    const char *out = NULL;
    cli_format fmt = CLI_FMT_TABLE;
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        if (c == 'f') {
            int f = cli_format_parse(optarg);
            if (f < 0) {
                cli_error("ugr", "--format: expected table, csv, tsv or json, got '%s'", optarg);
                return CLI_USAGE;
            }
            fmt = (cli_format)f;
        } else if (c == 'o') out = optarg;
        else if (c == 'h') {
            cli_print_help(help);
            return CLI_OK;
        } else
            return cli_bad_option("ugr", argv, c);
    }
    if (optind + 1 != argc) {
        cli_error("ugr", optind >= argc ? "no luminaire file given (see luxcalc ugr --help)" : "one luminaire file at a time");
        return CLI_USAGE;
    }
    lx_ctx *ctx = cli_ctx("ugr");
    if (!ctx) return CLI_RUNTIME;
    lx_luminaire *lum = NULL;
    lx_ugr_table tab;
    lx_status st = lx_luminaire_read_file(ctx, argv[optind], &lum);
    if (st == LX_OK) st = lx_ugr_table_compute(ctx, lum, &tab);
    int rc = CLI_OK;
    if (st != LX_OK) rc = cli_fail("ugr", ctx, st);
    else {
        static const char *const refl[5] = {"70_50_20", "70_30_20", "50_50_20", "50_30_20", "30_30_20"};
        char names[12][32];
        const char *np[12], *units[12];
        snprintf(names[0], sizeof names[0], "x_H");
        snprintf(names[1], sizeof names[1], "y_H");
        for (int k = 0; k < 10; k++) snprintf(names[2 + k], sizeof names[0], "%s_%s", k < 5 ? "cross" : "end", refl[k % 5]);
        for (int k = 0; k < 12; k++) np[k] = names[k], units[k] = "";
        cli_table *t = cli_table_new(12, np, units);
        for (int r = 0; r < 19; r++) {
            cli_table_num(t, tab.x_h[r]);
            cli_table_num(t, tab.y_h[r]);
            for (int k = 0; k < 10; k++) cli_table_num(t, tab.ugr[r][k]);
        }
        char *matrix = NULL;
        if (fmt == CLI_FMT_TABLE && (st = lx_ugr_table_text(ctx, &tab, &matrix)) != LX_OK) rc = cli_fail("ugr", ctx, st);
        cli_output o;
        if (rc != CLI_OK) {
        } else if (cli_output_open(&o, out, "ugr") != 0) rc = CLI_INPUT;
        else {
            int ok;
            if (fmt == CLI_FMT_TABLE) { /* the matrix of data sheets; csv, tsv and json one row per room */
                fprintf(o.fp, "UGR table (CIE 190:2010), %s, lamp flux %.0f lm, spacing %.2fH, uncorrected\n\n",
                        argv[optind], tab.lamp_flux_lm, tab.spacing_h);
                ok = fputs(matrix, o.fp) >= 0;
            } else
                ok = cli_table_write(t, fmt, o.fp, 1) == 0;
            if (cli_output_close(&o, ok, "ugr") != 0 || !ok) rc = CLI_INPUT;
        }
        lx_text_free(matrix);
        cli_table_free(t);
    }
    lx_luminaire_free(lum);
    lx_ctx_destroy(ctx);
    return rc;
}
