/* format.c - how numbers are shown, for every command: the output options (--precision N,
 * --units metric|imperial|UNIT,...), each column's output unit and name (imperial: lx -> fc,
 * m -> ft, cd/m2 -> fL), the digits the table format keeps per quantity, the one style of
 * "unknown option" messages, and standard output that was closed or fills up. */
#include "cli.h"

#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int cli_precision = 0;

/* the context of the unit look-ups (the library wants one; made once, freed at exit) */
static lx_ctx *uctx;
static void free_uctx(void) { lx_ctx_destroy(uctx); }
static lx_ctx *unit_ctx(void)
{
    if (!uctx && lx_ctx_create(&uctx) == LX_OK) atexit(free_uctx);
    return uctx;
}

/* output units by quantity: the unit shown instead of the quantity's SI unit (NULL: SI) */
static const lx_unit *out_unit[LX_Q_COUNT];

static int set_units(const char *text)
{
    const lx_unit *set[LX_Q_COUNT] = {0};
    char buf[256];
    snprintf(buf, sizeof buf, "%s", text);
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (!strcmp(tok, "metric") || !strcmp(tok, "si") || !strcmp(tok, "SI")) {
            memset(set, 0, sizeof set);
            continue;
        }
        if (!strcmp(tok, "imperial")) {
            static const char *const imp[3] = {"fc", "ft", "fL"};
            for (int k = 0; k < 3; k++) {
                const lx_unit *u = NULL;
                if (lx_unit_find(unit_ctx(), imp[k], &u) == LX_OK && u) set[u->quantity] = u;
            }
            continue;
        }
        const lx_unit *u = NULL;
        if (lx_unit_find(unit_ctx(), tok, &u) != LX_OK || !u) return -1; /* not ours: the command's own --units */
        set[u->quantity] = u;
    }
    memcpy(out_unit, set, sizeof set);
    return 0;
}

int cli_output_options(const char *cmd, int *argc, char **argv)
{
    int n = *argc, w = 1;
    for (int r = 1; r < n; r++) {
        const char *a = argv[r], *val = NULL;
        int takes = 0;
        if (!strcmp(a, "--")) { /* the end of options: the rest stays as it is */
            while (r < n) argv[w++] = argv[r++];
            break;
        }
        if (!strcmp(a, "--precision") || !strcmp(a, "--units")) takes = 2, val = r + 1 < n ? argv[r + 1] : NULL;
        else if (!strncmp(a, "--precision=", 12) || !strncmp(a, "--units=", 8)) takes = 1, val = strchr(a, '=') + 1;
        if (!takes) {
            argv[w++] = argv[r];
            continue;
        }
        if (!val) {
            fprintf(stderr, "luxcalc: %s: option '%.*s' needs a value (see luxcalc %s --help)\n", cmd,
                    (int)strcspn(a, "="), a, cmd);
            return CLI_USAGE;
        }
        if (a[2] == 'p') {
            char *end;
            long p = strtol(val, &end, 10);
            if (end == val || *end || p < 1 || p > 17) {
                fprintf(stderr, "luxcalc: %s: --precision: expected significant digits 1 to 17 (got '%s')\n", cmd, val);
                return CLI_USAGE;
            }
            cli_precision = (int)p;
        } else if (set_units(val) != 0) { /* another --units (irradiance: auto|radiance|luminance) */
            argv[w++] = argv[r];
            if (takes == 2) argv[w++] = argv[++r];
            continue;
        }
        r += takes - 1;
    }
    argv[w] = NULL;
    *argc = w;
    return 0;
}

/* a whole argument that is one number */
static int is_number(const char *s)
{
    char *end;
    if (!*s) return 0;
    strtod(s, &end);
    return *end == 0;
}

void cli_join_units(int *argc, char **argv)
{
    static char joined[16][96];
    int n = *argc, w = 1, used = 0;
    for (int r = 1; r < n; r++) {
        argv[w++] = argv[r];
        if (!strcmp(argv[r], "--")) {
            while (++r < n) argv[w++] = argv[r];
            break;
        }
        const lx_unit *u = NULL;
        if (!strncmp(argv[r], "--", 2) && !strchr(argv[r], '=') && r + 2 < n && used < 16 && is_number(argv[r + 1]) &&
            lx_unit_find(unit_ctx(), argv[r + 2], &u) == LX_OK && u) {
            snprintf(joined[used], sizeof joined[used], "%s %s", argv[r + 1], argv[r + 2]);
            argv[w++] = joined[used++];
            r += 2;
        }
    }
    argv[w] = NULL;
    *argc = w;
}

int cli_imperial(void)
{
    return out_unit[LX_Q_ILLUMINANCE] && !strcmp(out_unit[LX_Q_ILLUMINANCE]->name, "fc") && out_unit[LX_Q_LENGTH] &&
           !strcmp(out_unit[LX_Q_LENGTH]->name, "ft");
}

const char *cli_luminance_unit(double *scale)
{
    const lx_unit *u = out_unit[LX_Q_LUMINANCE];
    *scale = u ? 1 / u->to_si : 1;
    return u ? u->name : "cd/m2";
}

/* "cd/m2" -> "cd_m2": a unit as it ends a column name */
static void token(char *buf, size_t cap, const char *unit)
{
    size_t k = 0;
    for (; unit[k] && k + 1 < cap; k++) buf[k] = unit[k] == '/' ? '_' : unit[k];
    buf[k] = 0;
}

void cli_column_out(const char *name, const char *unit, cli_column *out)
{
    snprintf(out->name, sizeof out->name, "%s", name);
    snprintf(out->unit, sizeof out->unit, "%s", unit ? unit : "");
    out->scale = 1;
    const lx_unit *u = NULL;
    if (!unit || !*unit || lx_unit_find(unit_ctx(), unit, &u) != LX_OK || !u) return;
    const lx_unit *to = out_unit[u->quantity];
    if (!to || !strcmp(to->name, u->name)) return;
    out->scale = u->to_si / to->to_si;
    snprintf(out->unit, sizeof out->unit, "%s", to->name);
    char from[32], into[32];
    token(from, sizeof from, u->name);
    token(into, sizeof into, to->name);
    size_t nl = strlen(name), fl = strlen(from);
    if (nl > fl + 1 && name[nl - fl - 1] == '_' && !strcmp(name + nl - fl, from))
        snprintf(out->name, sizeof out->name, "%.*s%s", (int)(nl - fl), name, into);
}

/* 1 when a column name ends with suffix */
static int ends_with(const char *name, const char *suffix)
{
    size_t n = strlen(name), k = strlen(suffix);
    return n >= k && !strcmp(name + n - k, suffix);
}

/* the digits a quantity keeps in the table format: decimals (dec >= 0) or significant digits;
 * ratio: a dimensionless ratio (3 decimals), which keeps 2 significant digits where 3 decimals
 * would print a value that is not zero as 0.000 */
static void style(const char *name, const char *unit, int *dec, int *sig, int *trim, int *ratio)
{
    *dec = -1, *sig = 6, *trim = 0, *ratio = 0;
    if (cli_precision > 0) {
        *sig = cli_precision;
        return;
    }
    static const char *const photometric[] = {"lx", "cd", "lm", "klm", "cd/m2", "fc", "fL", "cd/ft2", "nit", "W", "lm/W", "sr",
                                              "h", "kWh", "W/m2", "kWh/(m2 a)"};
    if (!strcmp(name, "duv") || !strcmp(name, "cri_dc") || ends_with(name, "duv_offset") ||
        (!*unit && (!strcmp(name, "x") || !strcmp(name, "y") || !strcmp(name, "u_prime") || !strcmp(name, "v_prime"))))
        *dec = 5;
    else if (!strcmp(unit, "K")) *dec = 1;
    else if (!strncmp(name, "tm30_rhs", 8)) *dec = 3;
    else if (!strncmp(name, "cri_", 4) || !strncmp(name, "tm30_", 5)) *dec = 1;
    else if (!strcmp(name, "ugr") || !strncmp(name, "cross_", 6) || !strncmp(name, "end_", 4)) *dec = 1; /* CIE 117, 190 */
    else if (!strcmp(unit, "%")) *dec = 2;
    else if (!strcmp(name, "U0") || strstr(name, "uniformity") || !strcmp(name, "lor") || !strcmp(name, "downward_fraction") ||
             strstr(name, "reflectance") || strstr(name, "transmittance") || ends_with(name, "_coverage") ||
             !strcmp(name, "position_index") || ends_with(name, "_der") || !strcmp(name, "sp_ratio") ||
             !strncmp(name, "modelling", 9) || ends_with(name, "_factor"))
        *dec = 3, *ratio = 1;
    else if (!strcmp(unit, "m") || !strcmp(unit, "ft") || !strcmp(unit, "deg") || !strcmp(unit, "m2") || !strcmp(unit, "ft2") ||
             ends_with(name, "_H"))
        *dec = 3, *trim = 1;
    else
        for (size_t k = 0; k < sizeof photometric / sizeof *photometric; k++)
            if (!strcmp(unit, photometric[k])) *sig = 4;
}

void cli_number_text(char *buf, size_t cap, const cli_column *col, double v)
{
    int dec, sig, trim, ratio;
    style(col->name, col->unit, &dec, &sig, &trim, &ratio);
    if (!isfinite(v)) {
        snprintf(buf, cap, "-");
        return;
    }
    if (ratio && v != 0 && fabs(v) < 0.0005) dec = -1, sig = 2; /* 0.00031, not 0.000 */
    if (dec >= 0) {
        snprintf(buf, cap, "%.*f", dec, v);
        if (trim && strchr(buf, '.')) {
            size_t n = strlen(buf);
            while (n > 0 && buf[n - 1] == '0') buf[--n] = 0;
            if (n > 0 && buf[n - 1] == '.') buf[--n] = 0;
        }
        if (!strcmp(buf, "-0") || (strspn(buf, "-0.") == strlen(buf) && buf[0] == '-')) memmove(buf, buf + 1, strlen(buf));
        return;
    }
    if (v == 0) {
        snprintf(buf, cap, "0");
        return;
    }
    /* sig significant digits, without an exponent for 1e-6 <= |v| < 1e7 */
    int mag = (int)floor(log10(fabs(v)));
    double q = pow(10, mag - sig + 1), r = round(v / q) * q;
    if (r != 0) mag = (int)floor(log10(fabs(r)));
    if (mag >= 7 || mag < -6) snprintf(buf, cap, "%.*e", sig - 1, r);
    else snprintf(buf, cap, "%.*f", sig - 1 - mag > 0 ? sig - 1 - mag : 0, r);
}

/* ---- options a command does not know ---- */

int cli_bad_option(const char *cmd, char **argv, int c)
{
    const char *a = optind > 0 ? argv[optind - 1] : NULL;
    char name[80];
    if (a && a[0] == '-' && a[1] == '-') snprintf(name, sizeof name, "%.*s", (int)strcspn(a, "="), a);
    else snprintf(name, sizeof name, "-%c", optopt ? optopt : '?');
    if (c == ':') fprintf(stderr, "luxcalc: %s: option '%s' needs a value (see luxcalc %s --help)\n", cmd, name, cmd);
    else fprintf(stderr, "luxcalc: %s: unknown option '%s' (see luxcalc %s --help)\n", cmd, name, cmd);
    return CLI_USAGE;
}

/* ---- standard output ---- */

static int stdout_closed;   /* fd 1 was closed at start: it holds a scratch file instead */
static int write_reported;  /* a write error was already reported */

void cli_stdout_guard(void)
{
    if (fcntl(1, F_GETFD) != -1 || errno != EBADF) return;
    /* keep fd 1 taken, so that no file this run opens becomes standard output; what lands in the
     * scratch file is reported as a write to a closed standard output */
    FILE *f = tmpfile();
    if (f && dup2(fileno(f), 1) == 1) stdout_closed = 1;
}

int cli_stdout_check(const char *cmd)
{
    if (write_reported) return CLI_RUNTIME;
    int err = 0;
    errno = 0;
    if (fflush(stdout) != 0) err = errno ? errno : EIO;
    else if (ferror(stdout)) err = EIO;
    else if (stdout_closed) {
        struct stat sb;
        if (fstat(1, &sb) == 0 && sb.st_size > 0) err = EBADF;
    }
    if (!err) return 0;
    cli_error(cmd, "stdout: %s", strerror(err));
    write_reported = 1;
    return CLI_RUNTIME;
}

int cli_write_failed(const char *cmd, const char *path, int err)
{
    if (!write_reported) cli_error(cmd, "%s: %s", path ? path : "stdout", strerror(err ? err : EIO));
    write_reported = 1;
    return CLI_RUNTIME;
}
