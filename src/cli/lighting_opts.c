/* lighting_opts.c - option helpers of the lighting commands: quantities with units (a bare angle
 * is in degrees), the --efficacy / --spd pair, the options they all share, and writing one result
 * table (-o atomic). */
#include "lighting.h"

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double lt_echo(double v)
{
    char buf[32];
    snprintf(buf, sizeof buf, "%.15g", v);
    return strtod(buf, NULL);
}

int lt_format(const char *cmd, const char *s, cli_format *fmt)
{
    int f = cli_format_parse(s);
    if (f < 0) {
        cli_error(cmd, "--format: unknown format '%s' (table, csv or json)", s);
        return -1;
    }
    *fmt = (cli_format)f;
    return 0;
}

int lt_quantity(lx_ctx *ctx, const char *cmd, const char *opt, const char *text, lx_quantity q, const char *bare_unit,
                double efficacy, double *out)
{
    double v;
    lx_quantity got;
    lx_status st = lx_quantity_parse(ctx, text, LX_Q_NONE, bare_unit ? bare_unit : lx_quantity_si_unit(q), &v, &got);
    if (st != LX_OK) {
        cli_error(cmd, "%s: %s", opt, lx_ctx_errmsg(ctx));
        return CLI_USAGE;
    }
    if (got == q) {
        *out = v;
        return 0;
    }
    if (got == lx_quantity_counterpart(q) && q != LX_Q_NONE) {
        if (!(efficacy > 0)) {
            cli_error(cmd, "%s: '%s' is a %s: give --efficacy (e.g. 100lm/W) or --spd FILE to convert it to %s",
                      opt, text, lx_quantity_name(got), lx_quantity_si_unit(q));
            return CLI_USAGE;
        }
        lx_quantity oq;
        if (lx_radiometric_convert(ctx, v, got, efficacy, out, &oq) != LX_OK) {
            cli_error(cmd, "%s: %s", opt, lx_ctx_errmsg(ctx));
            return CLI_USAGE;
        }
        return 0;
    }
    const char *u = text + strspn(text, " \t+-.0123456789eE");
    cli_error(cmd, "%s: unit '%s' is a %s, not a %s", opt, u, lx_quantity_name(got), lx_quantity_name(q));
    return CLI_USAGE;
}

int lt_lengths(lx_ctx *ctx, const char *cmd, const char *opt, const char *text, const char *seps, const char *expect,
               double *out)
{
    int n = (int)strlen(seps) + 1;
    char tok[8][64] = {{0}};
    const char *p = text;
    for (int i = 0; i < n; i++) {
        size_t len = i < n - 1 ? strcspn(p, (char[]){seps[i], 0}) : strlen(p);
        if ((i < n - 1 && p[len] != seps[i]) || len >= sizeof tok[i] || n > 8) {
            cli_error(cmd, "%s: expected %s (got '%s')", opt, expect, text);
            return CLI_USAGE;
        }
        memcpy(tok[i], p, len);
        tok[i][len] = 0;
        p += len + (i < n - 1);
    }
    /* the unit written after the last number, for the bare ones before it */
    char *end;
    strtod(tok[n - 1], &end);
    const char *unit = end + strspn(end, " ");
    for (int i = 0; i < n; i++) {
        char buf[200];
        strtod(tok[i], &end);
        int bare = *(end + strspn(end, " ")) == 0;
        snprintf(buf, sizeof buf, "%.63s%s%.63s", tok[i], bare && *unit ? " " : "", bare ? unit : "");
        if (lt_quantity(ctx, cmd, opt, buf, LX_Q_LENGTH, NULL, 0, &out[i])) return CLI_USAGE;
    }
    return 0;
}

int lt_efficacy(lx_ctx *ctx, const char *cmd, const char *eff_text, const char *spd_path, double *efficacy)
{
    *efficacy = 0;
    if (eff_text && spd_path) {
        cli_error(cmd, "give --efficacy or --spd, not both");
        return CLI_USAGE;
    }
    if (eff_text) {
        int rc = lt_quantity(ctx, cmd, "--efficacy", eff_text, LX_Q_EFFICACY, "lm/W", 0, efficacy);
        if (rc) return rc;
        if (!(*efficacy > 0)) {
            cli_error(cmd, "--efficacy: must be positive (got %s)", eff_text);
            return CLI_INPUT;
        }
    } else if (spd_path) {
        lx_status st = lx_efficacy_from_spd_file(ctx, spd_path, efficacy);
        if (st != LX_OK) return cli_fail(cmd, ctx, st);
    }
    return 0;
}

int lt_write(const char *cmd, cli_table *t, cli_format fmt, const char *out_path)
{
    cli_output o;
    if (cli_output_open(&o, out_path, cmd) != 0) return CLI_INPUT;
    int ok = cli_table_write(t, fmt, o.fp, 0) == 0;
    if (cli_output_close(&o, ok, cmd) != 0 || !ok) return CLI_RUNTIME;
    return CLI_OK;
}

void lt_common_init(lt_common *co, const char *cmd, const char *help)
{
    *co = (lt_common){.cmd = cmd, .help = help, .fmt = CLI_FMT_TABLE};
    optind = 1;
    opterr = 0;
}

int lt_bad_option(const lt_common *co, char **argv, int c) { return cli_bad_option(co->cmd, argv, c); }

int lt_common_opt(lt_common *co, int c, char **argv)
{
    switch (c) {
    case 'K': co->eff = optarg; return LT_NEXT;
    case 'S': co->spd = optarg; return LT_NEXT;
    case 'o': co->out = optarg; return LT_NEXT;
    case 'f': return lt_format(co->cmd, optarg, &co->fmt) ? CLI_USAGE : LT_NEXT;
    case 'h': cli_print_help(co->help); return CLI_OK;
    default: return lt_bad_option(co, argv, c);
    }
}

int lt_no_operands(const lt_common *co, int argc, char **argv)
{
    if (optind < argc) {
        cli_error(co->cmd, "unexpected argument '%s'", argv[optind]);
        return CLI_USAGE;
    }
    return 0;
}

int lt_start(lt_common *co, lx_ctx **ctx)
{
    *ctx = cli_ctx(co->cmd);
    if (!*ctx) return CLI_RUNTIME;
    return lt_efficacy(*ctx, co->cmd, co->eff, co->spd, &co->efficacy);
}

int lt_emit(const lt_common *co, cli_table *t)
{
    int rc = lt_write(co->cmd, t, co->fmt, co->out);
    cli_table_free(t);
    return rc;
}

int lt_emit_nums(const lt_common *co, int n, const char *const *names, const char *const *units, const double *vals)
{
    cli_table *t = cli_table_new(n, names, units);
    for (int i = 0; i < n; i++) cli_table_num(t, vals[i]);
    return lt_emit(co, t);
}
