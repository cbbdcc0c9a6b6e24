/* common.c - CLI plumbing shared by every command: errors and exit codes, the result table in
 * table/csv/json, exact number printing, atomic output files. */
#include "cli.h"

#include <errno.h>
#include <fcntl.h>
#include <glob.h>
#include <signal.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int cli_verbose = 0;
int cli_quiet = 0;
size_t cli_max_input_mb = 0;

void cli_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "luxcalc: %s: ", cmd);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

int cli_exit_code(lx_status st)
{
    switch (st) {
    case LX_OK: return CLI_OK;
    case LX_EPARSE:
    case LX_EIO:
    case LX_ERANGE:
    case LX_EINVAL:
    case LX_EUNSUPPORTED: return CLI_INPUT;
    case LX_ENOMEM:
    case LX_EWRITE:
    case LX_EDEVICE: return CLI_RUNTIME;
    }
    return CLI_RUNTIME;
}

int cli_fail(const char *cmd, lx_ctx *ctx, lx_status st)
{
    const char *msg = lx_ctx_errmsg(ctx);
    cli_error(cmd, "%s", msg && *msg ? msg : lx_strerror(st));
    return cli_exit_code(st);
}

void cli_log(void *user, lx_log_level level, const char *msg)
{
    const char *cmd = user ? (const char *)user : "luxcalc";
    static const char *names[] = {"error", "warning", "info", "debug"};
    fprintf(stderr, "luxcalc: %s: %s: %s\n", cmd, names[level], msg);
}

lx_ctx *cli_ctx(const char *cmd)
{
    lx_ctx *ctx = NULL;
    if (lx_ctx_create(&ctx) != LX_OK) {
        cli_error(cmd, "out of memory");
        return NULL;
    }
    lx_log_level max = cli_quiet ? LX_LOG_ERROR : cli_verbose >= 2 ? LX_LOG_DEBUG : cli_verbose ? LX_LOG_INFO : LX_LOG_WARN;
    lx_ctx_set_log(ctx, cli_log, (void *)cmd, max);
    for (int k = 0; cli_max_input_mb && k < LX_INPUT_KIND_COUNT; k++)
        lx_ctx_set_input_limit(ctx, (lx_input_kind)k, cli_max_input_mb << 20);
    return ctx;
}

int cli_format_parse(const char *s)
{
    if (!strcmp(s, "table")) return CLI_FMT_TABLE;
    if (!strcmp(s, "csv")) return CLI_FMT_CSV;
    if (!strcmp(s, "json")) return CLI_FMT_JSON;
    if (!strcmp(s, "tsv")) return CLI_FMT_TSV;
    return -1;
}

int cli_parse_double(const char *s, double *out)
{
    char *end;
    if (!s || !*s) return -1;
    errno = 0;
    double v = strtod(s, &end);
    while (*end == ' ') end++;
    if (*end || !isfinite(v) || errno == ERANGE) return -1;
    *out = v;
    return 0;
}

int cli_parse_input_mb(const char *s, size_t *mb)
{
    size_t v = 0;
    if (!s || !*s) return -1;
    for (; *s; s++) {
        if (*s < '0' || *s > '9' || v > CLI_MAX_INPUT_MB) return -1;
        v = v * 10 + (size_t)(*s - '0');
    }
    if (v < 1 || v > CLI_MAX_INPUT_MB) return -1;
    *mb = v;
    return 0;
}

void cli_print_help(const char *text) { fputs(text, stdout); }

void cli_print_exact(FILE *out, double v)
{
    char buf[LX_DOUBLE_CHARS];
    size_t n = lx_double_format(v, buf); /* the shortest text that reads back exactly */
    fwrite(buf, 1, n, out);
}

/* ---- the result table ---- */
typedef struct cell {
    int kind; /* 0 number, 1 string, 2 integer, 3 JSON text, 4 number with its uncertainty */
    double num;
    long long integer;
    char *str;
    double u, lo, hi; /* kind 4: the table shows "num ± u [lo, hi]", the others num */
} cell;

struct cli_table {
    int ncols;
    const char *const *names;
    const char *const *units;
    cli_column *col;  /* the columns as they go out (output units), made on the first write */
    cell *cells;
    size_t ncells, cap;
    size_t emitted;   /* rows already written by cli_table_flush */
    int header_done;  /* csv header / json '[' written */
    int json_array;   /* json: an array was opened */
    unsigned char *json_only; /* ncols: columns csv, tsv and table leave out (NULL: none) */
    unsigned char *not_table; /* ncols: columns the table format leaves out (NULL: none) */
};

cli_table *cli_table_new(int ncols, const char *const *names, const char *const *units)
{
    cli_table *t = calloc(1, sizeof *t);
    if (!t) return NULL;
    t->ncols = ncols;
    t->names = names;
    t->units = units;
    return t;
}

static cell *push(cli_table *t)
{
    if (t->ncells == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 64;
        cell *c = realloc(t->cells, cap * sizeof *c);
        if (!c) {
            fprintf(stderr, "luxcalc: out of memory\n");
            exit(CLI_RUNTIME);
        }
        t->cells = c;
        t->cap = cap;
    }
    cell *c = &t->cells[t->ncells++];
    memset(c, 0, sizeof *c);
    return c;
}

void cli_table_str(cli_table *t, const char *s)
{
    cell *c = push(t);
    c->kind = 1;
    c->str = strdup(s ? s : "");
}

void cli_table_num(cli_table *t, double v) { push(t)->num = v; }

void cli_table_num_pm(cli_table *t, double v, double u, double lo, double hi)
{
    cell *c = push(t);
    c->kind = isfinite(v) && isfinite(u) ? 4 : 0;
    c->num = v, c->u = u, c->lo = lo, c->hi = hi;
}

void cli_table_not_in_table(cli_table *t, int col)
{
    if (col < 0 || col >= t->ncols) return;
    if (!t->not_table && !(t->not_table = calloc((size_t)t->ncols, 1))) return;
    t->not_table[col] = 1;
}

int cli_table_cell_num(const cli_table *t, int col, double *v)
{
    size_t i = t->ncells - t->ncells % (size_t)t->ncols; /* the row being filled */
    if (t->ncells % (size_t)t->ncols == 0 && t->ncells) i -= (size_t)t->ncols; /* ... or the last complete one */
    if (col < 0 || col >= t->ncols || i + (size_t)col >= t->ncells) return -1;
    const cell *c = &t->cells[i + (size_t)col];
    if (c->kind != 0 && c->kind != 4) return -1;
    *v = c->num;
    return 0;
}

void cli_table_copy_cell(cli_table *dst, const cli_table *src, int col)
{
    size_t i = src->ncells - (src->ncells % (size_t)src->ncols ? src->ncells % (size_t)src->ncols : (size_t)src->ncols);
    const cell *c = col >= 0 && col < src->ncols && i + (size_t)col < src->ncells ? &src->cells[i + (size_t)col] : NULL;
    cell *d = push(dst);
    if (!c) {
        d->num = NAN;
        return;
    }
    *d = *c;
    if (c->str && !(d->str = strdup(c->str))) {
        fprintf(stderr, "luxcalc: out of memory\n");
        exit(CLI_RUNTIME);
    }
}

void cli_table_discard(cli_table *t)
{
    for (size_t i = 0; i < t->ncells; i++) free(t->cells[i].str);
    t->ncells = 0;
}

void cli_table_int(cli_table *t, long long v)
{
    cell *c = push(t);
    c->kind = 2;
    c->integer = v;
}

int cli_table_rows(const cli_table *t) { return (int)(t->emitted + t->ncells / (size_t)t->ncols); }

void cli_table_json(cli_table *t, const char *json)
{
    cell *c = push(t);
    c->kind = 3;
    c->str = strdup(json ? json : "null");
}

void cli_table_json_only(cli_table *t, int col)
{
    if (col < 0 || col >= t->ncols) return;
    if (!t->json_only && !(t->json_only = calloc((size_t)t->ncols, 1))) return;
    t->json_only[col] = 1;
}

void cli_table_set_units(cli_table *t, const char *const *units)
{
    t->units = units;
    free(t->col); /* the output columns are made again with these units at the next write */
    t->col = NULL;
}

static int shown(const cli_table *t, int c, cli_format fmt)
{
    if (fmt == CLI_FMT_TABLE && t->not_table && t->not_table[c]) return 0;
    return fmt == CLI_FMT_JSON || !t->json_only || !t->json_only[c];
}

void cli_table_free(cli_table *t)
{
    if (!t) return;
    for (size_t i = 0; i < t->ncells; i++) free(t->cells[i].str);
    free(t->cells);
    free(t->col);
    free(t->not_table);
    free(t->json_only);
    free(t);
}

char *cli_csv_field(char *dst, const char *s, size_t len)
{
    if (memchr(s, ',', len) || memchr(s, '"', len) || memchr(s, '\n', len) || memchr(s, '\r', len)) {
        *dst++ = '"';
        for (size_t i = 0; i < len; i++) {
            if (s[i] == '"') *dst++ = '"';
            *dst++ = s[i];
        }
        *dst++ = '"';
    } else {
        memcpy(dst, s, len);
        dst += len;
    }
    return dst;
}

static void csv_str(FILE *out, const char *s)
{
    size_t n = strlen(s);
    char stack[256], *b = 2 * n + 2 <= sizeof stack ? stack : malloc(2 * n + 2);
    if (!b) {
        fprintf(stderr, "luxcalc: out of memory\n");
        exit(CLI_RUNTIME);
    }
    fwrite(b, 1, (size_t)(cli_csv_field(b, s, n) - b), out);
    if (b != stack) free(b);
}

static void tsv_str(FILE *out, const char *s)
{
    for (; *s; s++) fputc(*s == '\t' || *s == '\n' || *s == '\r' ? ' ' : *s, out);
}

void cli_json_string(FILE *out, const char *s);
static void json_str(FILE *out, const char *s) { cli_json_string(out, s); }

void cli_json_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\') fprintf(out, "\\%c", ch);
        else if (ch == '\n') fputs("\\n", out);
        else if (ch == '\t') fputs("\\t", out);
        else if (ch < 32) fprintf(out, "\\u%04x", ch);
        else fputc(ch, out);
    }
    fputc('"', out);
}

static void cell_text(const cell *c, const cli_column *col, char *buf, size_t cap)
{
    if (c->kind == 1 || c->kind == 3) snprintf(buf, cap, "%s", c->str);
    else if (c->kind == 2) snprintf(buf, cap, "%lld", c->integer);
    else cli_number_text(buf, cap, col, c->num * col->scale);
}

static void write_row(const cli_table *t, const cell *row, cli_format fmt, FILE *out, size_t index)
{
    if (fmt == CLI_FMT_CSV || fmt == CLI_FMT_TSV) {
        for (int c = 0, k = 0; c < t->ncols; c++) {
            const cell *x = &row[c];
            if (!shown(t, c, fmt)) continue;
            if (k++) fputc(fmt == CLI_FMT_CSV ? ',' : '\t', out);
            if (x->kind == 1 || x->kind == 3) (fmt == CLI_FMT_CSV ? csv_str : tsv_str)(out, x->str);
            else if (x->kind == 2) fprintf(out, "%lld", x->integer);
            else if (isfinite(x->num)) cli_print_exact(out, x->num * t->col[c].scale);
        }
        fputc('\n', out);
    } else if (fmt == CLI_FMT_JSON) {
        fputs(t->json_array ? (index ? ",\n  {" : "  {") : "{", out);
        for (int c = 0; c < t->ncols; c++) {
            const cell *x = &row[c];
            fprintf(out, "%s\"%s\": ", c ? ", " : "", t->col[c].name);
            if (x->kind == 3) fputs(x->str, out);
            else if (x->kind == 1) json_str(out, x->str);
            else if (x->kind == 2) fprintf(out, "%lld", x->integer);
            else if (isfinite(x->num)) cli_print_exact(out, x->num * t->col[c].scale);
            else fputs("null", out);
        }
        fputs(t->json_array ? "}" : "}\n", out);
    } else {
        /* people: one block per row, "name  value unit", aligned, numbers to their quantity's digits */
        int w = 0;
        for (int c = 0; c < t->ncols; c++) {
            int l = (int)strlen(t->col[c].name);
            if (l > w && shown(t, c, fmt)) w = l;
        }
        if (index) fputc('\n', out);
        for (int c = 0; c < t->ncols; c++) {
            char buf[512];
            if (!shown(t, c, fmt)) continue;
            cell_text(&row[c], &t->col[c], buf, sizeof buf);
            if (row[c].kind == 4) { /* "value ± u unit [lo, hi]" */
                char ub[64], lb[64], hb[64];
                double sc = t->col[c].scale, u = row[c].u * sc;
                if (cli_precision || !(u > 0)) {
                    cli_number_text(ub, sizeof ub, &t->col[c], u);
                    cli_number_text(lb, sizeof lb, &t->col[c], row[c].lo * sc);
                    cli_number_text(hb, sizeof hb, &t->col[c], row[c].hi * sc);
                } else { /* the uncertainty to two significant digits, the value and the interval to its last (GUM 7.2.6) */
                    int d = 1 - (int)floor(log10(u));
                    if (u * pow(10.0, d) >= 99.5) d--; /* 9.96 rounds to 10 */
                    double q = pow(10.0, -d);
                    int dec = d > 0 ? d : 0;
                    snprintf(buf, sizeof buf, "%.*f", dec, d >= 0 ? row[c].num * sc : nearbyint(row[c].num * sc / q) * q);
                    snprintf(ub, sizeof ub, "%.*f", dec, d >= 0 ? u : nearbyint(u / q) * q);
                    snprintf(lb, sizeof lb, "%.*f", dec, d >= 0 ? row[c].lo * sc : nearbyint(row[c].lo * sc / q) * q);
                    snprintf(hb, sizeof hb, "%.*f", dec, d >= 0 ? row[c].hi * sc : nearbyint(row[c].hi * sc / q) * q);
                }
                const char *un = t->col[c].unit;
                fprintf(out, "%-*s  %s \xc2\xb1 %s%s%s  [%s, %s]\n", w, t->col[c].name, buf, ub, *un ? " " : "", un, lb, hb);
                continue;
            }
            /* the unit follows a number (or a number echoed as text), never a word: "not covered" */
            char *end;
            (void)strtod(buf, &end);
            const char *u = strcmp(buf, "-") && end != buf ? t->col[c].unit : "";
            fprintf(out, "%-*s  %s%s%s\n", w, t->col[c].name, buf, *u ? " " : "", u);
        }
    }
}

/* the columns as they go out: names and units in the output units (--units) */
static int make_columns(cli_table *t)
{
    if (t->col) return 0;
    t->col = calloc((size_t)t->ncols, sizeof *t->col);
    if (!t->col) return -1;
    for (int c = 0; c < t->ncols; c++) cli_column_out(t->names[c], t->units ? t->units[c] : NULL, &t->col[c]);
    return 0;
}

int cli_table_flush(cli_table *t, cli_format fmt, FILE *out, int json_array, int final)
{
    size_t rows = t->ncells / (size_t)t->ncols;
    if (make_columns(t)) return -1;
    /* json prints one object for exactly one row: hold a lone first row until we know */
    if (fmt == CLI_FMT_JSON && !t->header_done && !final && !json_array && t->emitted + rows < 2) return 0;
    if (!t->header_done) {
        if (fmt == CLI_FMT_CSV || fmt == CLI_FMT_TSV) {
            for (int c = 0, k = 0; c < t->ncols; c++)
                if (shown(t, c, fmt)) fprintf(out, "%s%s", k++ ? (fmt == CLI_FMT_CSV ? "," : "\t") : "", t->col[c].name);
            fputc('\n', out);
        } else if (fmt == CLI_FMT_JSON) {
            t->json_array = json_array || t->emitted + rows != 1;
            if (t->json_array) fputs("[\n", out);
        }
        t->header_done = 1;
    }
    for (size_t r = 0; r < rows; r++) write_row(t, &t->cells[r * t->ncols], fmt, out, t->emitted + r);
    for (size_t i = 0; i < t->ncells; i++) free(t->cells[i].str);
    t->emitted += rows;
    t->ncells = 0;
    if (final && fmt == CLI_FMT_JSON && t->json_array) fputs(t->emitted ? "\n]\n" : "]\n", out);
    return ferror(out) ? -1 : 0;
}

int cli_table_header(cli_table *t, cli_format fmt, FILE *out)
{
    if (fmt != CLI_FMT_CSV || t->header_done) return 0;
    if (make_columns(t)) return -1;
    for (int c = 0, k = 0; c < t->ncols; c++)
        if (shown(t, c, fmt)) fprintf(out, "%s%s", k++ ? "," : "", t->col[c].name);
    fputc('\n', out);
    t->header_done = 1;
    return ferror(out) ? -1 : 0;
}

int cli_table_plain_csv(cli_table *t, int n)
{
    if (make_columns(t) || n > t->ncols) return 0;
    for (int c = 0; c < t->ncols; c++)
        if ((c < n && (t->col[c].scale != 1 || !shown(t, c, CLI_FMT_CSV))) || (c >= n && shown(t, c, CLI_FMT_CSV))) return 0;
    return 1;
}

void cli_table_count_written(cli_table *t, size_t rows) { t->emitted += rows; }

int cli_table_write(cli_table *t, cli_format fmt, FILE *out, int json_array)
{
    return cli_table_flush(t, fmt, out, json_array, 1);
}

/* ---- atomic output ---- */
/* Temporary files being written, removed by the signal handler on SIGINT/SIGTERM/SIGHUP so an
 * interrupted run leaves no temporary file and the existing output untouched. */
#define MAX_TMP 8
static char *volatile pending[MAX_TMP];

static void on_signal(int sig)
{
    for (int i = 0; i < MAX_TMP; i++)
        if (pending[i]) unlink(pending[i]); /* async-signal-safe */
    signal(sig, SIG_DFL);
    raise(sig);
}

static void track(char *tmp)
{
    static int installed;
    if (!installed) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        static const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
        for (int i = 0; i < 3; i++) { /* a signal ignored by our parent (nohup, a background job) stays ignored */
            struct sigaction old;
            if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN) continue;
            sigaction(sigs[i], &sa, NULL);
        }
        installed = 1;
    }
    for (int i = 0; i < MAX_TMP; i++)
        if (!pending[i]) {
            pending[i] = tmp;
            return;
        }
}

static void untrack(const char *tmp)
{
    for (int i = 0; i < MAX_TMP; i++)
        if (pending[i] == tmp) pending[i] = NULL;
}

int cli_output_open(cli_output *o, const char *path, const char *cmd)
{
    memset(o, 0, sizeof *o);
    if (!path || !strcmp(path, "-")) {
        o->fp = stdout;
        return 0;
    }
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode) && !S_ISDIR(sb.st_mode)) {
        /* a device or FIFO (/dev/null, /dev/full, a pipe): written directly, never replaced */
        o->fp = fopen(path, "w");
        if (!o->fp) {
            cli_error(cmd, "%s: cannot open: %s", path, strerror(errno));
            return -1;
        }
        o->path = strdup(path);
        if (!o->path) {
            fclose(o->fp);
            cli_error(cmd, "out of memory");
            return -1;
        }
        return 0;
    }
    size_t n = strlen(path);
    o->path = strdup(path);
    o->tmp = malloc(n + 16);
    if (!o->path || !o->tmp) {
        cli_error(cmd, "out of memory");
        return -1;
    }
    snprintf(o->tmp, n + 16, "%s.tmpXXXXXX", path);
    track(o->tmp); /* before the file exists: a signal during mkstemp must not leave it behind */
    int fd = mkstemp(o->tmp);
    if (fd < 0) {
        untrack(o->tmp);
        cli_error(cmd, "%s: cannot create: %s", path, strerror(errno));
        free(o->path);
        free(o->tmp);
        o->path = o->tmp = NULL;
        return -1;
    }
    mode_t mask = umask(0); /* give the file the usual permissions, not mkstemp's 0600 */
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    o->fp = fdopen(fd, "w");
    if (!o->fp) {
        cli_error(cmd, "%s: cannot write: %s", path, strerror(errno));
        close(fd);
        unlink(o->tmp);
        untrack(o->tmp);
        free(o->path);
        free(o->tmp);
        o->path = o->tmp = NULL;
        return -1;
    }
    return 0;
}

int cli_output_close(cli_output *o, int ok, const char *cmd)
{
    if (!o->path) return cli_stdout_check(cmd); /* standard output */
    /* a failed write shows in the stream's error flag; flushing again reproduces its errno */
    int err = 0;
    errno = 0;
    if (fflush(o->fp) != 0) err = errno ? errno : EIO;
    else if (ferror(o->fp)) err = EIO;
    if (!err && ok && o->tmp && fsync(fileno(o->fp)) != 0) err = errno;
    if (fclose(o->fp) != 0 && !err) err = errno ? errno : EIO;
    int rc = 0;
    if (err) rc = cli_write_failed(cmd, o->path, err);
    if (o->tmp) {
        if (ok && !err && rename(o->tmp, o->path) != 0) rc = cli_write_failed(cmd, o->path, errno);
        if (!ok || rc) unlink(o->tmp);
        untrack(o->tmp);
    }
    free(o->path);
    free(o->tmp);
    o->path = o->tmp = NULL;
    return rc;
}

/* ---- file arguments ---- */
char **cli_expand_files(int n, char **args, int *nout)
{
    size_t cap = (size_t)n + 16, k = 0;
    char **out = malloc(cap * sizeof *out);
    if (!out) return NULL;
    for (int i = 0; i < n; i++) {
        struct stat sb;
        glob_t g;
        const char *a = args[i];
        if (strcmp(a, "-") != 0 && strpbrk(a, "*?[") && stat(a, &sb) != 0 && glob(a, 0, NULL, &g) == 0) {
            for (size_t j = 0; j < g.gl_pathc; j++) {
                if (k == cap) {
                    char **o2 = realloc(out, (cap *= 2) * sizeof *out);
                    if (!o2) break;
                    out = o2;
                }
                out[k++] = strdup(g.gl_pathv[j]);
            }
            globfree(&g);
            continue;
        }
        if (k == cap) {
            char **o2 = realloc(out, (cap *= 2) * sizeof *out);
            if (!o2) break;
            out = o2;
        }
        out[k++] = strdup(a);
    }
    *nout = (int)k;
    return out;
}

void cli_free_files(char **files, int n)
{
    for (int i = 0; files && i < n; i++) free(files[i]);
    free(files);
}
