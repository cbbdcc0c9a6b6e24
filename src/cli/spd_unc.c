/* spd_unc.c - `luxcalc spd --uncertainty SPEC`: every quantity of a row with its standard
 * uncertainty and coverage interval (lx_spd_uncertainty: Monte Carlo, GUM or both), the columns
 * NAME_u, NAME_lo, NAME_hi after each, the budget and the validation in json, --explain on stderr. */
#include "spd_unc.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

enum { K_COPY, K_U, K_LO, K_HI, K_GUM_U, K_GUM_VALID, K_JSON };

const struct option cli_unc_long_options[] = {
    {"uncertainty", required_argument, NULL, 0x100},
    {"uncertainty-method", required_argument, NULL, 0x101},
    {"trials", required_argument, NULL, 0x102},
    {"coverage", required_argument, NULL, 0x103},
    {"seed", required_argument, NULL, 0x104},
    {"explain", no_argument, NULL, 0x105},
    {"interval", required_argument, NULL, 0x106},
    {"digits", required_argument, NULL, 0x107},
    {NULL, 0, NULL, 0},
};

int cli_unc_option(cli_unc *u, int c, const char *arg, const char *cmd)
{
    char *end;
    switch (c) {
    case 0x100: u->spec = arg; return 1;
    case 0x101:
        if (!strcmp(arg, "mc")) u->o.method = LX_UNC_MC;
        else if (!strcmp(arg, "gum")) u->o.method = LX_UNC_GUM;
        else if (!strcmp(arg, "both")) u->o.method = LX_UNC_BOTH;
        else return cli_error(cmd, "--uncertainty-method: expected mc, gum or both, not '%s'", arg), -1;
        return 1;
    case 0x102: {
        if (!strcmp(arg, "auto")) {
            u->o.trials = 0;
            return 1;
        }
        double t = strtod(arg, &end);
        if (end == arg || *end || !(t >= 2 && t <= 1e9) || t != floor(t))
            return cli_error(cmd, "--trials: expected a whole number of trials from 2 to 1e9, or auto, not '%s'", arg), -1;
        u->o.trials = (size_t)t;
        return 1;
    }
    case 0x103: {
        double p = strtod(arg, &end);
        if (end > arg && *end == '%' && end[1] == 0) p /= 100.0, end++;
        if (end == arg || *end || !(p > 0 && p < 1))
            return cli_error(cmd, "--coverage: expected a probability between 0 and 1 (0.95 or 95%%), not '%s'", arg), -1;
        u->o.coverage = p;
        return 1;
    }
    case 0x104: {
        unsigned long long s = strtoull(arg, &end, 10);
        if (end == arg || *end || arg[0] == '-')
            return cli_error(cmd, "--seed: expected a whole number from 0 to 18446744073709551615, not '%s'", arg), -1;
        u->o.seed = s;
        return 1;
    }
    case 0x105: u->explain = 1; return 1;
    case 0x106:
        if (!strcmp(arg, "symmetric")) u->o.shortest = 0;
        else if (!strcmp(arg, "shortest")) u->o.shortest = 1;
        else return cli_error(cmd, "--interval: expected symmetric or shortest, not '%s'", arg), -1;
        return 1;
    case 0x107:
        if (strcmp(arg, "1") && strcmp(arg, "2"))
            return cli_error(cmd, "--digits: expected 1 or 2 (significant digits of u the trials must settle), not '%s'", arg),
                   -1;
        u->o.digits = arg[0] - '0';
        return 1;
    default: return 0;
    }
}

int cli_unc_check(const cli_unc *u, const char *cmd)
{
    if (u->spec) return 0;
    if (u->o.method || u->o.trials || u->o.coverage || u->o.seed || u->o.shortest || u->o.digits || u->explain) {
        cli_error(cmd, "--uncertainty-method, --trials, --coverage, --seed, --interval, --digits and --explain need "
                       "--uncertainty SPEC");
        return -1;
    }
    return 0;
}

/* The quantity a column holds (-1: none has an uncertainty). */
static int quantity_of(const char *name)
{
    for (int q = 0; q < LX_UQ_COUNT; q++)
        if (!strcmp(name, lx_unc_quantity_name((lx_unc_quantity)q))) return q;
    /* equivalent daylight columns named by their unit: melanopic_edi_lx, melanopic_edl_cd_m2, cyanopic_edl, ... */
    static const char *const ao[5] = {"cyanopic_ed", "chloropic_ed", "erythropic_ed", "rhodopic_ed", "melanopic_ed"};
    for (int k = 0; k < 5; k++)
        if (!strncmp(name, ao[k], strlen(ao[k]))) return LX_UQ_EDI_SC + k;
    return -1;
}

static int add_col(cli_unc *u, int src, int kind, int q, const char *name, const char *const *const units[5])
{
    int i = u->n++;
    u->src[i] = src, u->kind[i] = kind, u->q[i] = q;
    static const char *const suffix[] = {"", "_u", "_lo", "_hi", "_gum_u", "_gum_valid", ""};
    if (kind == K_COPY || kind == K_JSON) u->names[i] = name;
    else {
        char *s = malloc(strlen(name) + 12);
        if (!s) return -1;
        sprintf(s, "%s%s", name, suffix[kind]);
        u->names[i] = s;
    }
    for (int k = 0; k < 5; k++)
        u->units[k][i] = kind == K_JSON || kind == K_GUM_VALID ? "" : units[k][src];
    return 0;
}

int cli_unc_columns(cli_unc *u, const char *const *names, const char *const *const units[5], int n0)
{
    int cap = 6 * n0 + 2;
    u->names = calloc((size_t)cap, sizeof *u->names);
    u->src = calloc((size_t)cap * 3, sizeof *u->src);
    for (int k = 0; k < 5; k++) u->units[k] = calloc((size_t)cap, sizeof *u->units[k]);
    if (!u->names || !u->src || !u->units[0] || !u->units[1] || !u->units[2] || !u->units[3] || !u->units[4]) return -1;
    u->kind = u->src + cap, u->q = u->src + 2 * cap;
    u->n0 = n0, u->n = 0, u->groups = 0;
    for (int c = 0; c < n0; c++) {
        int q = quantity_of(names[c]);
        if (add_col(u, c, K_COPY, q, names[c], units)) return -1;
        if (q < 0) continue;
        u->groups |= q <= LX_UQ_RADIANT ? LX_UNC_COLORIMETRY : q <= LX_UQ_DER_MEL ? LX_UNC_ALPHAOPIC : q <= LX_UQ_YPF ? LX_UNC_PAR
                   : q <= LX_UQ_R14 ? LX_UNC_CRI : LX_UNC_TM30;
        for (int k = K_U; k <= K_HI; k++)
            if (add_col(u, c, k, q, names[c], units)) return -1;
        if (u->o.method == LX_UNC_BOTH)
            for (int k = K_GUM_U; k <= K_GUM_VALID; k++)
                if (add_col(u, c, k, q, names[c], units)) return -1;
    }
    return add_col(u, 0, K_JSON, -1, "uncertainty", units);
}

void cli_unc_table_flags(const cli_unc *u, cli_table *t)
{
    for (int i = 0; i < u->n; i++) {
        if (u->kind[i] == K_JSON) cli_table_json_only(t, i);
        else if (u->kind[i] != K_COPY) cli_table_not_in_table(t, i);
    }
}

void cli_unc_free(cli_unc *u)
{
    for (int i = 0; u->names && i < u->n; i++)
        if (u->kind[i] != K_COPY && u->kind[i] != K_JSON) free((void *)u->names[i]);
    free(u->names), free(u->src);
    for (int k = 0; k < 5; k++) free(u->units[k]);
    memset(u, 0, sizeof *u);
}

/* ---- json details ---- */

typedef struct sbuf {
    char *s;
    size_t n, cap;
} sbuf;

static void sb_printf(sbuf *b, const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int k = vsnprintf(b->s ? b->s + b->n : NULL, b->s ? b->cap - b->n : 0, fmt, ap);
        va_end(ap);
        if (k < 0) return;
        if (b->s && b->n + (size_t)k < b->cap) {
            b->n += (size_t)k;
            return;
        }
        size_t cap = (b->cap ? 2 * b->cap : 1024) + (size_t)k;
        char *p = realloc(b->s, cap);
        if (!p) {
            fprintf(stderr, "luxcalc: out of memory\n");
            exit(CLI_RUNTIME);
        }
        b->s = p, b->cap = cap;
    }
}

static void sb_num(sbuf *b, double v)
{
    char t[LX_DOUBLE_CHARS];
    if (!isfinite(v)) sb_printf(b, "null");
    else lx_double_format(v, t), sb_printf(b, "%s", t);
}

static void sb_str(sbuf *b, const char *s)
{
    sb_printf(b, "\"");
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\') sb_printf(b, "\\%c", ch);
        else if (ch < 32) sb_printf(b, "\\u%04x", ch);
        else sb_printf(b, "%c", ch);
    }
    sb_printf(b, "\"");
}

static const char *method_name(lx_unc_method m) { return m == LX_UNC_GUM ? "gum" : m == LX_UNC_BOTH ? "both" : "mc"; }

static char *details(const cli_unc *u, const lx_unc_result *r, const lx_unc_model *m)
{
    sbuf b = {0};
    sb_printf(&b, "{\"method\": \"%s\", \"trials\": %zu, \"adaptive\": %s, \"stable\": %s, \"coverage\": ", method_name(r->method),
              r->trials, r->sequence ? "true" : "false", r->stable < 0 ? "null" : r->stable ? "true" : "false");
    sb_num(&b, r->coverage);
    sb_printf(&b, ", \"k\": ");
    sb_num(&b, r->k);
    sb_printf(&b, ", \"seed\": %llu, \"backend\": \"%s\", \"draws_normal\": %zu, \"fourier_terms\": %d, \"model\": [",
              u->o.seed, r->backend == LX_BACKEND_OPENCL ? "opencl" : "cpu", r->rank, r->fourier_terms);
    for (size_t i = 0; i < lx_unc_model_count(m); i++) sb_printf(&b, "%s", i ? ", " : ""), sb_str(&b, lx_unc_model_label(m, i));
    sb_printf(&b, "], \"quantities\": {");
    int first = 1;
    for (int i = 0; i < u->n; i++) {
        if (u->kind[i] != K_COPY || u->q[i] < 0 || !r->q[u->q[i]].defined) continue;
        const lx_unc_value *v = &r->q[u->q[i]];
        sb_printf(&b, "%s", first ? "" : ", ");
        first = 0;
        sb_str(&b, u->names[i]);
        sb_printf(&b, ": {\"value\": "), sb_num(&b, v->value);
        sb_printf(&b, ", \"u\": "), sb_num(&b, v->u);
        sb_printf(&b, ", \"lo\": "), sb_num(&b, v->lo);
        sb_printf(&b, ", \"hi\": "), sb_num(&b, v->hi);
        if (r->method != LX_UNC_GUM) {
            sb_printf(&b, ", \"mc_mean\": "), sb_num(&b, v->mc_mean);
            sb_printf(&b, ", \"undefined\": "), sb_num(&b, v->undefined);
            sb_printf(&b, ", \"stable\": %s", v->stable < 0 ? "null" : v->stable ? "true" : "false");
        }
        if (r->method != LX_UNC_MC) {
            sb_printf(&b, ", \"gum_u\": "), sb_num(&b, v->gum_u);
            sb_printf(&b, ", \"peak_nm\": "), sb_num(&b, v->peak_nm);
            sb_printf(&b, ", \"budget\": [");
            for (int t = 0; t < 3 && v->top[t] >= 0; t++) {
                sb_printf(&b, "%s{\"component\": ", t ? ", " : "");
                sb_str(&b, lx_unc_model_label(m, (size_t)v->top[t]));
                sb_printf(&b, ", \"u\": "), sb_num(&b, v->top_u[t]);
                sb_printf(&b, "}");
            }
            sb_printf(&b, "]");
        }
        if (r->method == LX_UNC_BOTH) {
            sb_printf(&b, ", \"gum_valid\": %s, \"d_low\": ", v->gum_valid < 0 ? "null" : v->gum_valid ? "true" : "false");
            sb_num(&b, v->d_low);
            sb_printf(&b, ", \"d_high\": "), sb_num(&b, v->d_high);
            sb_printf(&b, ", \"delta\": "), sb_num(&b, v->delta);
        }
        sb_printf(&b, "}");
    }
    sb_printf(&b, "}}");
    return b.s;
}

/* ---- --explain ---- */

static void explain(const cli_unc *u, const lx_unc_result *r, const lx_unc_model *m, const char *where, const char *label,
                    const char *cmd)
{
    FILE *f = stderr;
    fprintf(f, "luxcalc: %s: %s: spectrum '%s': uncertainty by %s, coverage %g %%, model ", cmd, where, label,
            r->method == LX_UNC_GUM ? "the GUM law of propagation (JCGM 100)"
            : r->method == LX_UNC_BOTH ? "Monte Carlo (JCGM 101) and GUM (JCGM 100), GUM validated per JCGM 101 8"
                                       : "Monte Carlo (JCGM 101)",
            100 * r->coverage);
    for (size_t i = 0; i < lx_unc_model_count(m); i++) fprintf(f, "%s%s", i ? " + " : "", lx_unc_model_label(m, i));
    fputc('\n', f);
    if (r->fourier_terms) fprintf(f, "  Fourier model: N = %d terms\n", r->fourier_terms);
    if (r->method != LX_UNC_GUM) {
        fprintf(f, "  trials drawn in the space of the integrals: %zu normal deviates a trial (the rank of the normal part), "
                   "seed %llu, on the %s\n",
                r->rank, u->o.seed, r->backend == LX_BACKEND_OPENCL ? "OpenCL device" : "CPU");
        if (r->sequence) {
            fprintf(f, "  %zu trials, adaptive (JCGM 101 7.9): sequences of %zu until the mean, u and both interval ends of "
                       "every quantity are stable to %d significant digit%s of u (2 s <= delta):\n",
                    r->trials, r->sequence, r->digits, r->digits == 1 ? "" : "s");
        } else {
            fprintf(f, "  %zu trials, as asked (--trials)%s\n", r->trials,
                    r->nhistory ? "; their stability over sequences of 10^4:" : " (fewer than two sequences of 10^4: stability not checked)");
        }
        /* the first sequences, then every doubling of the trials, and the last */
        size_t next = 0;
        for (size_t h = 0; h < r->nhistory; h++) {
            if (h + 1 < r->nhistory && r->history_trials[h] < next) continue;
            fprintf(f, "    %9zu trials: largest 2 s / delta %.3g (%s)\n", r->history_trials[h], r->history_ratio[h],
                    lx_unc_quantity_name((lx_unc_quantity)r->history_worst[h]));
            if (h >= 2) next = 2 * r->history_trials[h];
        }
        if (r->sequence)
            fprintf(f, "  %s after %zu trials\n", r->stable == 1 ? "stable" : "NOT stable (the most trials reached; --trials N runs more)",
                    r->trials);
        fprintf(f, "  Monte Carlo: %.3f s\n", r->seconds_mc);
    }
    if (r->method != LX_UNC_MC) fprintf(f, "  GUM: %.4f s; coverage factor k = %.4f (normal)\n", r->seconds_gum, r->k);
    for (int i = 0; i < u->n; i++) {
        if (u->kind[i] != K_COPY || u->q[i] < 0) continue;
        const lx_unc_value *v = &r->q[u->q[i]];
        if (!v->defined) continue;
        fprintf(f, "  %-16s u %.3g", u->names[i], v->u);
        if (r->method != LX_UNC_GUM && v->undefined > 0) fprintf(f, ", undefined in %.3g %% of the trials", 100 * v->undefined);
        if (r->method == LX_UNC_BOTH)
            fprintf(f, "; GUM u %.3g %s (|d_low| %.2g, |d_high| %.2g, delta %.2g)", v->gum_u,
                    v->gum_valid < 0 ? "not judged: Monte Carlo not stable to delta"
                    : v->gum_valid ? "adequate" : "NOT adequate", v->d_low, v->d_high, v->delta);
        if (r->method != LX_UNC_MC && v->top[0] >= 0) {
            fprintf(f, "; budget");
            for (int t = 0; t < 3 && v->top[t] >= 0; t++)
                fprintf(f, "%s %s %.3g", t ? "," : "", lx_unc_model_label(m, (size_t)v->top[t]), v->top_u[t]);
            if (isfinite(v->peak_nm)) fprintf(f, "; most sensitive at %g nm", v->peak_nm);
        }
        fputc('\n', f);
    }
}

/* ---- a row ---- */

lx_unc_result *cli_unc_compute(const cli_unc *u, lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method,
                               const lx_unc_model *m, int threads, lx_status *st, char **msg)
{
    lx_unc_opts o = u->o;
    o.observer = obs, o.integration = method, o.quantities = u->groups ? u->groups : LX_UNC_COLORIMETRY;
    if (threads) o.threads = threads;
    lx_unc_result *r = NULL;
    *st = lx_spd_uncertainty(ctx, spd, m, &o, &r);
    *msg = *st != LX_OK ? strdup(lx_ctx_errmsg(ctx)) : NULL;
    return r;
}

int cli_unc_write(const cli_unc *u, cli_table *dst, cli_table *src, lx_unc_result *r, lx_status st, const char *msg,
                  const lx_unc_model *m, const char *where, const char *label, const char *cmd)
{
    int rc = 0;
    if (st != LX_OK) {
        cli_error(cmd, "%s: spectrum '%s': no uncertainty: %s", where, label, msg ? msg : "out of memory");
        rc = cli_exit_code(st);
    }
    for (int i = 0; i < u->n; i++) {
        int q = u->q[i];
        const lx_unc_value *v = r && q >= 0 && r->q[q].defined ? &r->q[q] : NULL;
        double x;
        switch (u->kind[i]) {
        case K_COPY:
            if (v && cli_table_cell_num(src, u->src[i], &x) == 0) cli_table_num_pm(dst, x, v->u, v->lo, v->hi);
            else cli_table_copy_cell(dst, src, u->src[i]);
            break;
        case K_U: cli_table_num(dst, v ? v->u : NAN); break;
        case K_LO: cli_table_num(dst, v ? v->lo : NAN); break;
        case K_HI: cli_table_num(dst, v ? v->hi : NAN); break;
        case K_GUM_U: cli_table_num(dst, v ? v->gum_u : NAN); break;
        case K_GUM_VALID:
            if (v && v->gum_valid >= 0) cli_table_int(dst, v->gum_valid);
            else cli_table_num(dst, NAN);
            break;
        case K_JSON: {
            char *j = r ? details(u, r, m) : NULL;
            cli_table_json(dst, j ? j : "null");
            free(j);
            break;
        }
        }
    }
    cli_table_discard(src);
    if (r && u->explain && !cli_quiet) explain(u, r, m, where, label, cmd);
    if (r && r->sequence && r->stable == 0 && !cli_quiet)
        cli_error(cmd, "%s: spectrum '%s': warning: the Monte Carlo results are not stable to %d digits after %zu trials "
                       "(the most; --trials N runs more, --digits 1 asks less)",
                  where, label, r->digits, r->trials);
    lx_unc_result_free(r);
    return rc;
}

int cli_unc_row(const cli_unc *u, cli_table *dst, cli_table *src, lx_ctx *ctx, const lx_spd *spd, lx_observer obs,
                lx_method method, const lx_unc_model *m, const char *file, long line, const char *cmd)
{
    lx_status st;
    char *msg = NULL, where[1100];
    lx_unc_result *r = cli_unc_compute(u, ctx, spd, obs, method, m, 0, &st, &msg);
    snprintf(where, sizeof where, "%s:%ld", file, line);
    int rc = cli_unc_write(u, dst, src, r, st, msg, m, where, spd->name ? spd->name : "", cmd);
    free(msg);
    return rc;
}
