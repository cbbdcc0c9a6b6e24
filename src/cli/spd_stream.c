/* spd_stream.c - `luxcalc spd` on a rows-layout CSV of any size: lx_batch_table_stream_ex parses
 * parts of the file on every core, and on the thread that parsed it each part gets its colorimetry
 * (lx_batch_colorimetry, the fast CCT) and its csv text (lx_double_format); the caller's thread
 * writes the texts in file order. Memory stays bounded: the rows of a file go to the output as
 * they come (-o: our temporary file, taken back to where the file began if a row turns out bad),
 * or for standard output are held until the file is done (in memory, then in a temporary file). */
#include "spd_batch.h"
#include "progress.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define HOLD_MEM ((size_t)16 << 20)          /* standard output: rows held in memory up to this, then in a file */
#define PIPE_PREFIX ((size_t)8 << 20)        /* a pipe of up to this goes to the general reader whole */
#define MAX_THREADS 64

/* What one part leaves for its emit: colorimetry, and the csv text of its rows. */
typedef struct part_out {
    lx_colorimetry *res;
    size_t res_cap;
    char *text;
    size_t len, cap;
    unsigned char *bad;  /* per row: refused by lx_colorimetry_check (reported, no row) */
    char *why;           /* their messages, NUL-separated, in row order */
    size_t nbad, why_len, why_cap;
} part_out;

typedef struct bstream {
    cli_spd_batch *B;
    const char *path;
    int csv;                  /* rows written as text by the stream (else added to the table at the end) */
    int on_workers;           /* colorimetry on the parsing threads (not with OpenCL: one device, one context) */
    char *file_cell;          /* the file column, csv-quoted */
    size_t file_cell_len;
    lx_ctx *tctx[MAX_THREADS];
    _Atomic int grid;         /* 0 not checked yet, 1 cie15, -1 another method */
    _Atomic int odd_name;     /* a name the general reader would read otherwise (quotes) */
    _Atomic int cb_failed;    /* the status of a failed work or emit (the library holds no message for it) */
    size_t rows;
    /* csv: the rows of this file not yet written, and where they go */
    char *hold;
    size_t hold_len, hold_cap;
    FILE *spill;              /* standard output: rows beyond HOLD_MEM */
    FILE *out;
    long long out0;           /* -o: where this file's rows begin in our temporary file */
    int started, failed;
    int over_cap;             /* larger than the general reader takes (or a pipe): no second reading */
    /* the table path: the results (and metrics), written to the table when the file is done */
    lx_colorimetry *res;
    cli_spd_lab lab;
    struct {
        int par, hz, bin;
    } lab_used;
    char *names;
    size_t res_cap, names_len, names_cap;
    unsigned long long total;
    int bar;
} bstream;

/* ---- the rows ---- */

/* name of row i of a part, trimmed of blanks as the general reader trims cells */
static const char *row_name(const lx_batch_table *part, size_t i, size_t *len)
{
    const char *s = part->names + part->name_at[i];
    size_t n = strlen(s);
    while (n && (*s == ' ' || *s == '\t')) s++, n--;
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r')) n--;
    *len = n;
    return s;
}

static char *put_num(char *p, double v)
{
    if (isfinite(v)) p += lx_double_format(v, p);
    return p;
}

/* the csv text of the part's rows (the columns of cli_spd_add_row) */
static int format_rows(bstream *S, const lx_batch_table *part, part_out *o)
{
    size_t n = part->batch.n_spectra, need = 0;
    for (size_t i = 0; i < n; i++) need += strlen(part->names + part->name_at[i]);
    need = 2 * need + n * (S->file_cell_len + 2 + 13 * (LX_DOUBLE_CHARS + 1) + 8) + 1;
    if (need > o->cap) {
        char *t = realloc(o->text, need);
        if (!t) return -1;
        o->text = t, o->cap = need;
    }
    char *p = o->text;
    for (size_t i = 0; i < n; i++) {
        const lx_colorimetry *r = &o->res[i];
        if (o->nbad && o->bad[i]) continue;
        memcpy(p, S->file_cell, S->file_cell_len);
        p += S->file_cell_len;
        *p++ = ',';
        size_t nl;
        const char *nm = row_name(part, i, &nl);
        p = cli_csv_field(p, nm, nl);
        const double v[] = {r->X, r->Y, r->Z, r->x, r->y, r->u_prime, r->v_prime, r->cct_K, r->duv, r->ler_lm_per_W,
                            r->scotopic_Y, r->sp_ratio, r->radiant};
        for (size_t j = 0; j < sizeof v / sizeof *v; j++) {
            *p++ = ',';
            p = put_num(p, v[j]);
        }
        memcpy(p, ",cie15\n", 7);
        p += 7;
    }
    o->len = (size_t)(p - o->text);
    return 0;
}

static int grid_ok(bstream *S, const lx_batch *b)
{
    int g = atomic_load(&S->grid);
    if (g) return g > 0;
    double *lam = malloc(b->n_lambda * sizeof *lam);
    if (!lam) return 0;
    for (size_t j = 0; j < b->n_lambda; j++) lam[j] = b->start_nm + (double)j * b->step_nm;
    lx_spd s0 = {NULL, b->n_lambda, lam, lam};
    g = b->n_lambda >= 2 && lx_method_resolve(&s0, S->B->method) == LX_METHOD_CIE15 ? 1 : -1;
    free(lam);
    atomic_store(&S->grid, g);
    return g > 0;
}

/* colorimetry (and csv text) of a part into o, on ctx */
static lx_status part_rows(bstream *S, lx_ctx *ctx, lx_backend backend, const lx_batch_table *part, part_out *o)
{
    const lx_batch *b = &part->batch;
    if (!grid_ok(S, b)) return LX_EUNSUPPORTED;
    for (size_t i = 0; i < b->n_spectra; i++) {
        const char *nm = part->names + part->name_at[i];
        if (strchr(nm, '"')) { /* the general reader strips quotes: let it read this file */
            atomic_store(&S->odd_name, 1);
            return LX_EUNSUPPORTED;
        }
    }
    if (b->n_spectra > o->res_cap) {
        lx_colorimetry *r = realloc(o->res, b->n_spectra * sizeof *r);
        if (!r) return LX_ENOMEM;
        o->res = r, o->res_cap = b->n_spectra;
    }
    lx_batch_opts opts = {.backend = backend, .threads = 1}; /* the other cores parse meanwhile */
    lx_status st = lx_batch_colorimetry(ctx, b, S->B->observer, &opts, o->res);
    o->nbad = o->why_len = 0;
    for (size_t i = 0; st == LX_OK && i < b->n_spectra; i++) {
        /* the row's largest value only names the overflow in the message: looked for when it fails */
        if (lx_colorimetry_check(ctx, &o->res[i], NAN) == LX_OK ||
            lx_colorimetry_check(ctx, &o->res[i], cli_spd_row_max_abs(b, i)) == LX_OK) {
            if (o->nbad) o->bad[i] = 0;
            continue;
        }
        if (!S->over_cap) return LX_EUNSUPPORTED; /* the general reader reports it with its line */
        if (!o->nbad) { /* the first refused row of this part */
            unsigned char *f = realloc(o->bad, b->n_spectra);
            if (!f) return LX_ENOMEM;
            o->bad = f;
            memset(f, 0, b->n_spectra);
        }
        o->bad[i] = 1;
        o->nbad++;
        const char *msg = lx_ctx_errmsg(ctx);
        size_t l = strlen(msg) + 1;
        if (o->why_len + l > o->why_cap) {
            char *w = realloc(o->why, 2 * (o->why_len + l));
            if (!w) return LX_ENOMEM;
            o->why = w, o->why_cap = 2 * (o->why_len + l);
        }
        memcpy(o->why + o->why_len, msg, l);
        o->why_len += l;
    }
    if (st == LX_OK && S->csv && format_rows(S, part, o) != 0) st = LX_ENOMEM;
    return st;
}

static lx_status on_work(void *user, int thread, const lx_batch_table *part, void **state)
{
    bstream *S = user;
    if (!S->on_workers) return LX_OK;
    part_out *o = *state;
    if (!o && !(o = *state = calloc(1, sizeof *o))) return LX_ENOMEM;
    if (thread < 0 || thread >= MAX_THREADS) return LX_EINVAL;
    lx_status st = LX_ENOMEM;
    if (S->tctx[thread] || lx_ctx_create(&S->tctx[thread]) == LX_OK) st = part_rows(S, S->tctx[thread], LX_BACKEND_CPU, part, o);
    if (st != LX_OK) atomic_store(&S->cb_failed, (int)st);
    return st;
}

/* ---- where the csv rows go ---- */

static void put(bstream *S, const char *p, size_t n);

/* the output opened, its header written, the rows held so far moved there (or, for standard
 * output, kept held until the end) */
static int start_output(bstream *S)
{
    cli_spd_batch *B = S->B;
    S->started = 1;
    if (!B->out_private) return 0; /* standard output: everything waits for the end of the file */
    if (!(S->out = B->open_out(B->flush_arg)) || cli_table_header(B->table, CLI_FMT_CSV, S->out) != 0) return S->failed = 1, -1;
    fflush(S->out);
    S->out0 = (long long)ftello(S->out);
    if (S->hold_len && fwrite(S->hold, 1, S->hold_len, S->out) != S->hold_len) S->failed = 1;
    S->hold_len = 0;
    return 0;
}

static void put(bstream *S, const char *p, size_t n)
{
    if (S->failed) return;
    if (S->out) {
        if (fwrite(p, 1, n, S->out) != n) S->failed = 1;
        return;
    }
    if (S->started && S->hold_len + n > HOLD_MEM) { /* standard output: the rest in a temporary file */
        if (!S->spill && !(S->spill = tmpfile())) {
            cli_error(S->B->cmd, "%s: cannot create a temporary file for the rows", S->path);
            S->failed = 1;
            return;
        }
        if (fwrite(S->hold, 1, S->hold_len, S->spill) != S->hold_len) S->failed = 1;
        S->hold_len = 0;
        if (fwrite(p, 1, n, S->spill) != n) S->failed = 1;
        return;
    }
    if (S->hold_len + n > S->hold_cap) {
        size_t cap = 2 * (S->hold_len + n);
        char *h = realloc(S->hold, cap);
        if (!h) {
            S->failed = 1;
            return;
        }
        S->hold = h, S->hold_cap = cap;
    }
    memcpy(S->hold + S->hold_len, p, n);
    S->hold_len += n;
}

/* the whole file streamed: what is held goes out; the rows are counted as the table's */
static int commit(bstream *S)
{
    cli_spd_batch *B = S->B;
    if (!S->started && start_output(S) != 0) return -1;
    if (!S->out) { /* standard output */
        FILE *o = B->open_out(B->flush_arg);
        if (!o || cli_table_header(B->table, CLI_FMT_CSV, o) != 0) return -1;
        if (S->spill) {
            char buf[1 << 16];
            size_t got;
            rewind(S->spill);
            while ((got = fread(buf, 1, sizeof buf, S->spill)) > 0)
                if (fwrite(buf, 1, got, o) != got) return -1;
            if (ferror(S->spill)) return -1;
        }
        if (S->hold_len && fwrite(S->hold, 1, S->hold_len, o) != S->hold_len) return -1;
    }
    cli_table_count_written(B->table, S->rows);
    return S->failed ? -1 : 0;
}

/* the file failed: nothing of it stays in the output */
static void take_back(bstream *S)
{
    if (S->out) {
        fflush(S->out);
        if (ftruncate(fileno(S->out), (off_t)S->out0) != 0 || fseeko(S->out, (off_t)S->out0, SEEK_SET) != 0)
            cli_error(S->B->cmd, "%s: cannot take back the rows written", S->path);
    }
    S->hold_len = 0;
}

/* ---- the table path: formats other than plain csv, metric columns, unit scaling ---- */

/* grows the held results to n rows (colorimetry and the metrics B asks for) */
static int hold_rows(bstream *S, size_t n, const cli_spd_lab *L)
{
    if (n <= S->res_cap) return 0;
    size_t cap = 2 * n;
    lx_colorimetry *r = realloc(S->res, cap * sizeof *r);
    if (r) S->res = r;
    lx_par *pa = r && L->par ? realloc(S->lab.par, cap * sizeof *pa) : S->lab.par;
    if (pa) S->lab.par = pa;
    lx_hazard *hz = r && L->hz ? realloc(S->lab.hz, cap * sizeof *hz) : S->lab.hz;
    if (hz) S->lab.hz = hz;
    lx_binning *bi = r && L->bin ? realloc(S->lab.bin, cap * sizeof *bi) : S->lab.bin;
    if (bi) S->lab.bin = bi;
    if (!r || (L->par && !pa) || (L->hz && !hz) || (L->bin && !bi)) return -1;
    S->res_cap = cap;
    return 0;
}

/* A part's rows through the table: written at once for a file the general reader cannot take
 * again (beyond its size limit, or a pipe: memory stays a part), else kept until the file is
 * done. The metrics are computed here, on B's context. */
static lx_status table_rows(bstream *S, const lx_batch_table *part, part_out *o)
{
    cli_spd_batch *B = S->B;
    lx_batch_opts opts = {.backend = B->backend, .threads = 1};
    cli_spd_lab L = {0};
    lx_status st = cli_spd_lab_compute(B, &part->batch, o->res, &opts, &L);
    size_t n = part->batch.n_spectra, kept = 0;
    if (st == LX_OK && !S->over_cap && hold_rows(S, S->rows + n, &L) != 0) st = LX_ENOMEM;
    for (size_t i = 0; st == LX_OK && i < n; i++) {
        if (o->nbad && o->bad[i]) continue;
        size_t l;
        const char *nm = row_name(part, i, &l);
        char name[1024];
        snprintf(name, sizeof name, "%.*s", (int)(l < sizeof name - 1 ? l : sizeof name - 1), nm);
        if (S->over_cap) {
            cli_spd_add_row(B, S->path, name, &o->res[i], L.par ? &L.par[i] : NULL, L.hz ? &L.hz[i] : NULL,
                            L.bin ? &L.bin[i] : NULL);
            kept++;
            continue;
        }
        if (S->names_len + l + 1 > S->names_cap) {
            size_t cap = 2 * (S->names_len + l + 1) + 4096;
            char *q = realloc(S->names, cap);
            if (!q) {
                st = LX_ENOMEM;
                break;
            }
            S->names = q, S->names_cap = cap;
        }
        memcpy(S->names + S->names_len, nm, l);
        S->names[S->names_len + l] = 0;
        S->names_len += l + 1;
        size_t at = S->rows + kept++;
        S->res[at] = o->res[i];
        if (L.par) S->lab.par[at] = L.par[i];
        if (L.hz) S->lab.hz[at] = L.hz[i];
        if (L.bin) S->lab.bin[at] = L.bin[i];
    }
    S->lab_used.par |= L.par != NULL, S->lab_used.hz |= L.hz != NULL, S->lab_used.bin |= L.bin != NULL;
    cli_spd_lab_free(&L);
    if (st == LX_OK) S->rows += kept;
    if (st == LX_OK && S->over_cap && B->flush) B->flush(B->flush_arg);
    return st;
}

/* ---- emit: in file order, on this thread ---- */

static lx_status on_emit(void *user, const lx_batch_table *part, size_t row0, void *state)
{
    bstream *S = user;
    cli_spd_batch *B = S->B;
    part_out local = {0}, *o = S->on_workers ? state : &local;
    lx_status st = LX_OK;
    if (!S->on_workers) st = part_rows(S, B->ctx, B->backend, part, o);
    size_t n = part->batch.n_spectra;
    if (st == LX_OK && o->nbad) { /* refused results: reported in file order, no row */
        const char *why = o->why;
        for (size_t i = 0; i < n; i++) {
            if (!o->bad[i]) continue;
            size_t l;
            const char *nm = row_name(part, i, &l);
            cli_error(B->cmd, "%s: spectrum '%.*s' (data row %zu): %s", S->path, (int)l, nm, row0 + i + 1, why);
            why += strlen(why) + 1;
            B->rejected++;
        }
    }
    if (st == LX_OK && S->csv) {
        put(S, o->text, o->len);
        S->rows += n - o->nbad;
        if (!S->started && (B->forced || S->rows >= CLI_SPD_BATCH_MIN)) start_output(S);
    } else if (st == LX_OK) { /* the table (other formats, metrics, units): its rows */
        st = table_rows(S, part, o);
    }
    free(local.res);
    free(local.text);
    free(local.bad);
    free(local.why);
    if (st == LX_OK && S->failed) st = LX_EIO;
    if (st != LX_OK) atomic_store(&S->cb_failed, (int)st);
    return st;
}

static void on_release(void *user, void *state)
{
    (void)user;
    part_out *o = state;
    free(o->res);
    free(o->text);
    free(o->bad);
    free(o->why);
    free(o);
}

static void on_progress(void *user, unsigned long long done, unsigned long long total)
{
    (void)user, (void)total;
    cli_progress_update((size_t)done);
}

/* ---- which inputs, and the general reader's share ---- */

/* 1 when the text's first content line is a header the general reader also reads as a rows
 * layout with names: one kind of separator (, ; or tab), a first cell that is not a number, at
 * least two more cells, no quotes; the line must end within len. */
static int plain_rows_header(const char *buf, size_t len)
{
    const char *s = buf, *end = buf + len;
    if (len >= 3 && !memcmp(s, "\xEF\xBB\xBF", 3)) s += 3;
    for (;;) { /* skip blank and comment lines */
        const char *e = memchr(s, '\n', (size_t)(end - s));
        const char *t = s;
        while (t < end && (*t == ' ' || *t == '\t' || *t == '\r')) t++;
        if (t < end && *t != '\n' && *t != '#') break;
        if (!e) return 0;
        s = e + 1;
    }
    const char *e = memchr(s, '\n', (size_t)(end - s));
    if (!e) return 0; /* the header must end within the text looked at */
    size_t hl = (size_t)(e - s);
    int kinds = (memchr(s, ',', hl) != NULL) + (memchr(s, ';', hl) != NULL) + (memchr(s, '\t', hl) != NULL);
    if (kinds != 1 || memchr(s, '"', hl)) return 0;
    char sep = memchr(s, ',', hl) ? ',' : memchr(s, ';', hl) ? ';' : '\t';
    const char *c1 = memchr(s, sep, hl);
    char first[64];
    size_t fl = (size_t)(c1 - s) < sizeof first - 1 ? (size_t)(c1 - s) : sizeof first - 1;
    memcpy(first, s, fl);
    first[fl] = 0;
    char *fe;
    strtod(first, &fe);
    if (fe == first + fl || c1 == s) return 0; /* a numeric or empty first cell */
    return memchr(c1 + 1, sep, (size_t)(e - c1 - 1)) != NULL;
}

static int plain_rows_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    static char buf[1 << 16];
    size_t len = fread(buf, 1, sizeof buf, f);
    fclose(f);
    return plain_rows_header(buf, len);
}

/* A pipe: reads up to PIPE_PREFIX; *all when that was all of it. NULL on failure (printed). */
static char *read_prefix(cli_spd_batch *B, const char *path, FILE *f, size_t *len, int *all)
{
    char *buf = malloc(PIPE_PREFIX + 1);
    size_t n = 0, got = 1;
    while (buf && n < PIPE_PREFIX && (got = fread(buf + n, 1, PIPE_PREFIX - n, f)) > 0) n += got;
    if (!buf || ferror(f)) {
        cli_error(B->cmd, "%s: %s", path, buf ? "read error" : "out of memory");
        free(buf);
        return NULL;
    }
    *all = n < PIPE_PREFIX;
    if (!*all) { /* one byte more tells whether it ends here */
        int c = fgetc(f);
        if (c == EOF) *all = 1;
        else ungetc(c, f);
    }
    *len = n;
    return buf;
}

static int run_stream(bstream *S, FILE *in, const char *prefix, size_t prefix_len, lx_status *st)
{
    cli_spd_batch *B = S->B;
    lx_batch_stream cb = {.user = S, .work = on_work, .emit = on_emit, .release = on_release, .progress = on_progress,
                          .input = in, .prefix = prefix, .prefix_len = prefix_len};
    cli_progress_start_bytes(S->total, S->path);
    *st = lx_batch_table_stream_ex(B->ctx, S->path, LX_F64, 0, &cb);
    cli_progress_end();
    for (int t = 0; t < MAX_THREADS; t++) lx_ctx_destroy(S->tctx[t]);
    return *st == LX_OK && S->rows > 0 && (B->forced || S->rows >= CLI_SPD_BATCH_MIN || in);
}

int cli_spd_batch_file(cli_spd_batch *B, const char *path, lx_spd_set **set)
{
    *set = NULL;
    struct stat sb;
    int std_in = !strcmp(path, "-"), have = !std_in && stat(path, &sb) == 0;
    int regular = have && S_ISREG(sb.st_mode), pipe_in = std_in || (have && (S_ISFIFO(sb.st_mode) || S_ISCHR(sb.st_mode)));
    if (!regular && !pipe_in) return 0;
    if (regular && !plain_rows_file(path)) return 0;
    bstream S;
    memset(&S, 0, sizeof S);
    S.B = B;
    S.path = path;
    /* rows as text made on the parsing threads: plain csv of the default columns */
    S.csv = B->format == CLI_FMT_CSV && !(B->metrics && B->metrics->any) && cli_table_plain_csv(B->table, 16);
    S.on_workers = B->backend != LX_BACKEND_OPENCL && lx_backend_from_env() != LX_BACKEND_OPENCL;
    S.total = regular ? (unsigned long long)sb.st_size : 0;
    /* beyond the general reader's size limit (or from a pipe) nothing can be read twice */
    S.over_cap = !regular || (unsigned long long)sb.st_size > lx_ctx_input_limit(B->ctx, LX_INPUT_SPECTRUM);
    size_t pl = strlen(path);
    S.file_cell = malloc(2 * pl + 2);
    if (!S.file_cell) return 0;
    S.file_cell_len = (size_t)(cli_csv_field(S.file_cell, path, pl) - S.file_cell);
    FILE *in = NULL;
    char *prefix = NULL;
    size_t prefix_len = 0;
    if (pipe_in) { /* the start of the pipe decides; a short or other pipe goes to the general reader */
        lx_status ost = lx_file_open(B->ctx, path, &in);
        if (ost != LX_OK) {
            free(S.file_cell);
            return -cli_fail(B->cmd, B->ctx, ost);
        }
        int all = 0;
        prefix = read_prefix(B, path, in, &prefix_len, &all);
        if (!prefix || all || !plain_rows_header(prefix, prefix_len)) {
            /* the general reader, on what was read and the rest of the pipe (its size limit) */
            lx_status st = prefix ? lx_spd_read_stream(B->ctx, path, in, prefix, prefix_len, B->ropts, set) : LX_EIO;
            if (in != stdin) fclose(in);
            free(S.file_cell);
            if (st != LX_OK) {
                int e = prefix ? -cli_fail(B->cmd, B->ctx, st) : -CLI_INPUT;
                free(prefix);
                return e;
            }
            free(prefix);
            return 0;
        }
    }
    lx_status st;
    int done = run_stream(&S, in, prefix, prefix_len, &st);
    if (done && S.csv && commit(&S) != 0) {
        cli_error(B->cmd, "%s: cannot write the results", path);
        take_back(&S);
        done = -CLI_INPUT;
    } else if (!done) {
        take_back(&S);
        if (!S.over_cap) {
            done = 0; /* the general reader: its messages, or the rows of a small or odd file */
        } else if (st == LX_OK) {
            cli_error(B->cmd, "%s: no spectra", path);
            done = -CLI_INPUT;
        } else if (!S.cb_failed) {
            done = -cli_fail(B->cmd, B->ctx, st); /* the library's message: FILE:LINE */
        } else {
            cli_error(B->cmd, "%s: %s", path,
                      S.odd_name ? "a row name in double quotes: the streamed reader takes plain names only"
                      : S.grid < 0 ? "its wavelengths need another method than cie15 (a pipe or a file beyond the size limit is streamed)"
                      : S.failed   ? "cannot write the results"
                                   : lx_strerror(st));
            done = -cli_exit_code(st);
        }
    }
    if (done == 1 && !S.csv && !S.over_cap) {
        size_t off = 0;
        for (size_t i = 0; i < S.rows; i++) {
            cli_spd_add_row(B, path, S.names + off, &S.res[i], S.lab_used.par ? &S.lab.par[i] : NULL,
                            S.lab_used.hz ? &S.lab.hz[i] : NULL, S.lab_used.bin ? &S.lab.bin[i] : NULL);
            off += strlen(S.names + off) + 1;
            if (B->flush && (i + 1) % 65536 == 0) B->flush(B->flush_arg); /* the table holds a chunk at most */
        }
        if (B->flush) B->flush(B->flush_arg);
    }
    if (in && in != stdin) fclose(in);
    if (S.spill) fclose(S.spill);
    free(prefix);
    free(S.hold);
    free(S.res);
    cli_spd_lab_free(&S.lab);
    free(S.names);
    free(S.file_cell);
    return done;
}
