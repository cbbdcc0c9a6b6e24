/* cmd_convert.c - `luxcalc convert VALUE UNIT`: the value in every unit of its quantity, and with
 * --efficacy or --spd also in every unit of its radiometric/photometric counterpart. */
#include "lighting.h"

#include <getopt.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc convert VALUE UNIT [--efficacy K | --spd FILE] [--format F] [-o FILE]\n"
    "       luxcalc convert VALUEUNIT ...\n"
    "\n"
    "Prints VALUE in every unit of the same quantity (lm, W, cd, W/sr, lx, fc, W/m2, cd/m2, nit,\n"
    "fL, lambert, sr, m, ft, in, deg, rad, K, ...). Radiometric <-> photometric needs an efficacy:\n"
    "with --efficacy K (lm/W) or --spd FILE (the luminous efficacy of radiation of that spectrum)\n"
    "the counterpart's units are listed too; without one they are not (never assumed).\n"
    "\n"
    "csv columns: unit,value\n"
    "\n"
    "examples: a 46 fc recommendation in lux; 10 W of radiation at 300 lm/W:\n"
    "  luxcalc convert 46 fc\n"
    "  luxcalc convert 10W --efficacy 300lm/W\n";

int cmd_convert(int argc, char **argv)
{
    static const struct option opts[] = {LT_COMMON_LONGOPTS, {0, 0, 0, 0}};
    lt_common co;
    lt_common_init(&co, "convert", help);
    const char *cmd = co.cmd;
    int c, rc;
    /* a negative VALUE goes after "--": luxcalc convert -- -5 deg */
    while ((c = getopt_long(argc, argv, LT_SHORTOPTS, opts, NULL)) != -1)
        if ((rc = lt_common_opt(&co, c, argv)) != LT_NEXT) return rc;
    int nargs = argc - optind;
    if (nargs < 1 || nargs > 2) {
        cli_error(cmd, "give VALUE UNIT (e.g. 46 fc)");
        return CLI_USAGE;
    }
    char text[256];
    snprintf(text, sizeof text, "%s%s%s", argv[optind], nargs == 2 ? " " : "", nargs == 2 ? argv[optind + 1] : "");
    lx_ctx *ctx;
    rc = lt_start(&co, &ctx);
    if (!ctx) return rc;
    double K = co.efficacy, si;
    lx_quantity q = LX_Q_NONE;
    if (!rc) {
        lx_status st = lx_quantity_parse(ctx, text, LX_Q_NONE, NULL, &si, &q);
        if (st != LX_OK) {
            cli_error(cmd, "%s", lx_ctx_errmsg(ctx));
            rc = CLI_USAGE;
        } else if (q == LX_Q_NONE) {
            cli_error(cmd, "'%s' has no unit: give VALUE UNIT", text);
            rc = CLI_USAGE;
        }
    }
    if (!rc) {
        static const char *const names[] = {"unit", "value", "quantity"};
        cli_table *t = cli_table_new(3, names, NULL);
        size_t n;
        const lx_unit *u = lx_units(&n);
        lx_quantity cq = K > 0 ? lx_quantity_counterpart(q) : LX_Q_NONE;
        double csi = 0;
        if (cq != LX_Q_NONE) lx_radiometric_convert(ctx, si, q, K, &csi, NULL);
        for (int pass = 0; pass < 2; pass++)
            for (size_t i = 0; i < n; i++) {
                lx_quantity want = pass ? cq : q;
                if (want == LX_Q_NONE || u[i].quantity != want || !u[i].primary) continue;
                double v = pass ? csi : si;
                cli_table_str(t, u[i].name);
                cli_table_num(t, u[i].to_si == 1.0 ? v : v / u[i].to_si);
                cli_table_str(t, lx_quantity_name(want));
            }
        if (co.fmt == CLI_FMT_TABLE) {
            /* people: one line per unit */
            cli_output o;
            if (cli_output_open(&o, co.out, cmd) != 0) rc = CLI_INPUT;
            else {
                for (int pass = 0; pass < 2; pass++)
                    for (size_t i = 0; i < n; i++) {
                        lx_quantity want = pass ? cq : q;
                        if (want == LX_Q_NONE || u[i].quantity != want || !u[i].primary) continue;
                        double v = pass ? csi : si;
                        fprintf(o.fp, "%16.10g %-8s %s\n", u[i].to_si == 1.0 ? v : v / u[i].to_si, u[i].name, u[i].title);
                    }
                if (cq != LX_Q_NONE) fprintf(o.fp, "(%s <-> %s at %g lm/W)\n", lx_quantity_name(q), lx_quantity_name(cq), K);
                int ok = !ferror(o.fp);
                if (cli_output_close(&o, ok, cmd) != 0) rc = CLI_RUNTIME;
            }
            cli_table_free(t);
        } else {
            rc = lt_emit(&co, t);
        }
    }
    lx_ctx_destroy(ctx);
    return rc;
}
