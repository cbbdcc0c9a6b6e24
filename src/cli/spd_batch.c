/* spd_batch.c - the batch paths of `luxcalc spd`: many spectra on one uniform grid go through
 * lx_batch_colorimetry (vectorised, threaded, OpenCL when asked or large), and raw float32 input
 * (--input-format f32 --grid START:END:STEP) for pipelines whose data is already numeric. */
#include "spd_batch.h"
#include "progress.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define CHUNK 65536 /* spectra per batch call: bounds memory, lets output stream */

static void add_row(cli_spd_batch *B, const char *file, const char *name, const lx_colorimetry *r, const lx_par *par,
                    const lx_hazard *hz, const lx_binning *bin)
{
    cli_table *t = B->table;
    cli_table_str(t, file);
    cli_table_str(t, name);
    double v[] = {r->X, r->Y, r->Z, r->x, r->y, r->u_prime, r->v_prime, r->cct_K, r->duv, r->ler_lm_per_W,
                  r->scotopic_Y, r->sp_ratio, r->radiant};
    for (size_t j = 0; j < sizeof v / sizeof *v; j++) cli_table_num(t, v[j]);
    cli_table_str(t, "cie15");
    if (B->metrics && B->metrics->any)
        cli_metrics_row_batch(t, B->ctx, B->metrics, B->unit ? B->unit : "relative", par, hz, bin, B->vendor);
    cli_table_json(t, B->instrument);
}

/* The metric integrals of a batch for rows [0, n) (each array NULL when not needed). */
typedef struct lab {
    lx_par *par;
    lx_hazard *hz;
    lx_binning *bin;
} lab;

static void lab_free(lab *L) { free(L->par), free(L->hz), free(L->bin); }

static lx_status lab_compute(cli_spd_batch *B, const lx_batch *b, const lx_colorimetry *res, lx_batch_opts *opts,
                             lab *L)
{
    memset(L, 0, sizeof *L);
    const cli_metrics *m = B->metrics;
    if (!m || !m->any) return LX_OK;
    size_t n = b->n_spectra ? b->n_spectra : 1;
    int need_par = cli_metrics_need_par(m), need_hz = cli_metrics_need_hazard(m), need_bin = cli_metrics_need_binning(m);
    /* binning from the exact CCT of the colorimetry (2 deg); with --observer 10 the batch's own */
    int table_bin = need_bin && B->observer != LX_OBSERVER_2;
    if ((need_par && !(L->par = malloc(n * sizeof *L->par))) || (need_hz && !(L->hz = malloc(n * sizeof *L->hz))) ||
        (need_bin && !(L->bin = malloc(n * sizeof *L->bin))))
        return LX_ENOMEM;
    lx_status st = LX_OK;
    if (need_par || need_hz || table_bin)
        st = lx_lab_batch(B->ctx, b, opts, L->par, L->hz, table_bin ? L->bin : NULL);
    for (size_t i = 0; need_bin && !table_bin && i < b->n_spectra && st == LX_OK; i++)
        st = lx_binning_compute(B->ctx, res[i].x, res[i].y, res[i].cct_K, res[i].duv, &L->bin[i]);
    return st;
}

/* The largest |value| of spectrum i of b (for the overflow message). */
static double row_max_abs(const lx_batch *b, size_t i)
{
    size_t stride = b->row_stride ? b->row_stride : b->n_lambda;
    double m = 0;
    for (size_t j = 0; j < b->n_lambda; j++) {
        double v = b->dtype == LX_F32 ? (double)((const float *)b->values)[i * stride + j]
                                      : ((const double *)b->values)[i * stride + j];
        if (fabs(v) > m) m = fabs(v);
    }
    return m;
}

/* Colorimetry of spectra [i0, i0+n) of b, one row each; names[i] or the 1-based index, lines[i]
 * (or none). A result lx_colorimetry_check refuses (an overflow, a NaN) is reported on stderr as
 * "FILE:LINE: spectrum 'NAME': why" instead of a row and counted in B->rejected; with stop_at_bad
 * the chunk ends there (LX_ERANGE, the rows before it added). */
static lx_status run_chunk(cli_spd_batch *B, const lx_batch *b, const char *file, const char *const *names,
                           const long *lines, size_t i0, int stop_at_bad)
{
    lx_colorimetry *res = malloc(sizeof *res * (b->n_spectra ? b->n_spectra : 1));
    if (!res) return LX_ENOMEM;
    lx_batch_opts opts;
    memset(&opts, 0, sizeof opts);
    opts.backend = B->backend;
    lab L = {0};
    lx_status st = lx_batch_colorimetry(B->ctx, b, B->observer, &opts, res);
    if (st == LX_OK) st = lab_compute(B, b, res, &opts, &L);
    if (st == LX_OK) {
        char idx[32];
        for (size_t i = 0; i < b->n_spectra; i++) {
            const char *name = names ? names[i] : (snprintf(idx, sizeof idx, "%zu", i0 + i + 1), idx);
            if (lx_colorimetry_check(B->ctx, &res[i], row_max_abs(b, i)) != LX_OK) {
                if (lines) cli_error(B->cmd, "%s:%ld: spectrum '%s': %s", file, lines[i], name, lx_ctx_errmsg(B->ctx));
                else cli_error(B->cmd, "%s: spectrum %s: %s", file, name, lx_ctx_errmsg(B->ctx));
                B->rejected++;
                if (stop_at_bad) {
                    st = LX_ERANGE;
                    break;
                }
                continue;
            }
            add_row(B, file, name, &res[i], L.par ? &L.par[i] : NULL, L.hz ? &L.hz[i] : NULL, L.bin ? &L.bin[i] : NULL);
        }
        if (B->flush) B->flush(B->flush_arg);
    }
    lab_free(&L);
    free(res);
    return st;
}

int cli_spd_batchable(const cli_spd_batch *B, const lx_spd_set *set)
{
    if (set->count == 0) return 0;
    if (!B->forced && set->count < CLI_SPD_BATCH_MIN) return 0;
    const lx_spd *s0 = &set->spd[0];
    if (lx_method_resolve(s0, B->method) != LX_METHOD_CIE15) return 0;
    for (size_t k = 1; k < set->count; k++) {
        const lx_spd *s = &set->spd[k];
        if (s->n != s0->n || memcmp(s->lambda_nm, s0->lambda_nm, s0->n * sizeof(double)) != 0) return 0;
    }
    for (size_t k = 0; k < set->count; k++)
        if (lx_spd_check(B->ctx, &set->spd[k]) != LX_OK) return 0; /* the scalar path reports it */
    return 1;
}

lx_status cli_spd_batch_set(cli_spd_batch *B, const lx_spd_set *set)
{
    const lx_spd *s0 = &set->spd[0];
    size_t n = s0->n;
    double step = (s0->lambda_nm[n - 1] - s0->lambda_nm[0]) / (double)(n - 1);
    lx_status st = LX_OK;
    cli_progress_start(set->count, set->file);
    for (size_t i0 = 0; i0 < set->count && st == LX_OK; i0 += CHUNK) {
        size_t m = set->count - i0 < CHUNK ? set->count - i0 : CHUNK;
        double *v = malloc(sizeof(double) * m * n);
        const char **names = malloc(sizeof *names * m);
        if (!v || !names) {
            free(v);
            free(names);
            cli_progress_end();
            return LX_ENOMEM;
        }
        for (size_t i = 0; i < m; i++) {
            memcpy(v + i * n, set->spd[i0 + i].value, n * sizeof(double));
            names[i] = set->spd[i0 + i].name ? set->spd[i0 + i].name : "";
        }
        lx_batch b = {m, n, 0, s0->lambda_nm[0], step, LX_F64, v};
        st = run_chunk(B, &b, set->file, names, set->line ? set->line + i0 : NULL, i0, 0);
        free(v);
        free(names);
        cli_progress_update(i0 + m);
    }
    cli_progress_end();
    return st;
}

/* ---- rows-layout files streamed (lx_batch_table_stream) ---- */

typedef struct stream_acc {
    cli_spd_batch *B;
    const char *path;
    int over_cap;      /* the file is larger than the general reader takes */
    unsigned char *bad; /* per row: refused by lx_colorimetry_check (reported, no row) */
    lx_colorimetry *res;
    lx_par *par;
    lx_hazard *hz;
    lx_binning *bin;
    char *names;       /* NUL-separated, in row order */
    size_t rows, cap, names_len, names_cap;
    int checked;       /* the grid was checked on the first chunk */
} stream_acc;

/* 1 when the file's first content line is a header the general reader also reads as a rows
 * layout with names: one kind of separator (, ; or tab), a first cell that is not a number,
 * at least two more cells, no quotes. Anything else goes to the general reader. */
static int plain_rows_header(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    static char buf[1 << 16];
    size_t len = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[len] = 0;
    char *s = buf;
    if (len >= 3 && !memcmp(s, "\xEF\xBB\xBF", 3)) s += 3;
    for (;;) { /* skip blank and comment lines */
        char *e = strchr(s, '\n');
        char *t = s;
        while (*t == ' ' || *t == '\t' || *t == '\r') t++;
        if (*t && *t != '\n' && *t != '#') break;
        if (!e) return 0;
        s = e + 1;
    }
    char *e = strchr(s, '\n');
    if (!e) return 0; /* the header must end within the first 64 KB */
    *e = 0;
    int kinds = (strchr(s, ',') != NULL) + (strchr(s, ';') != NULL) + (strchr(s, '\t') != NULL);
    if (kinds != 1 || strchr(s, '"')) return 0;
    char sep = strchr(s, ',') ? ',' : strchr(s, ';') ? ';' : '\t';
    char *c1 = strchr(s, sep);
    char *end;
    strtod(s, &end);
    if (end == c1 || s == c1) return 0; /* a numeric or empty first cell */
    char *c2 = strchr(c1 + 1, sep);
    return c2 != NULL;
}

/* A file within the spectrum-file limit: every result is kept until the whole file parsed (so a
 * problem falls back to the general reader, which names lines). A larger file, which the general
 * reader cannot take: each chunk's rows are printed as it completes (memory stays a chunk), and a
 * spectrum that fails is reported and skipped. */
static lx_status stream_chunk(void *user, const lx_batch_table *chunk, size_t row0)
{
    stream_acc *A = user;
    cli_spd_batch *B = A->B;
    const lx_batch *b = &chunk->batch;
    size_t n = b->n_lambda, base = A->over_cap ? 0 : row0; /* where this chunk's results go */
    if (!A->checked) {
        double *lam = malloc(n * sizeof *lam);
        if (!lam) return LX_ENOMEM;
        for (size_t j = 0; j < n; j++) lam[j] = b->start_nm + (double)j * b->step_nm;
        lx_spd s0 = {NULL, n, lam, lam};
        int ok = n >= 2 && lx_method_resolve(&s0, B->method) == LX_METHOD_CIE15;
        free(lam);
        if (!ok) return LX_EUNSUPPORTED;
        A->checked = 1;
    }
    if (base + b->n_spectra > A->cap) {
        size_t cap = 2 * (base + b->n_spectra);
        lx_colorimetry *r = realloc(A->res, cap * sizeof *r);
        if (r) A->res = r;
        unsigned char *f = r ? realloc(A->bad, cap) : NULL;
        if (!f) return LX_ENOMEM;
        A->bad = f;
        lx_par *p = realloc(A->par, cap * sizeof *p);
        if (!p) return LX_ENOMEM;
        A->par = p;
        lx_hazard *h = realloc(A->hz, cap * sizeof *h);
        if (!h) return LX_ENOMEM;
        A->hz = h;
        lx_binning *g = realloc(A->bin, cap * sizeof *g);
        if (!g) return LX_ENOMEM;
        A->bin = g;
        A->cap = cap;
    }
    memset(A->bad + base, 0, b->n_spectra);
    for (size_t i = 0; i < b->n_spectra; i++) { /* names as the general reader keeps them */
        const char *nm = chunk->names + chunk->name_at[i];
        size_t l = strlen(nm);
        /* the checks of the general path (cli_spd_batchable): each spectrum as lx_spd_check sees it */
        const double *v = (const double *)b->values + i * n;
        size_t j = 0;
        while (j < n && isfinite(v[j])) j++;
        if (A->over_cap) {
            if (j < n) {
                cli_error(B->cmd, "%s: spectrum '%s' (data row %zu): value %zu (%g nm) is not finite", A->path, nm, row0 + i + 1,
                          j + 1, b->start_nm + (double)j * b->step_nm);
                A->bad[i] = 1;
                B->rejected++;
            }
            continue;
        }
        if (j < n || (l && (nm[0] == ' ' || nm[l - 1] == ' ' || nm[l - 1] == '\t' || nm[0] == '\t'))) return LX_EUNSUPPORTED;
        if (A->names_len + l + 1 > A->names_cap) {
            size_t cap = 2 * (A->names_len + l + 1) + 4096;
            char *q = realloc(A->names, cap);
            if (!q) return LX_ENOMEM;
            A->names = q;
            A->names_cap = cap;
        }
        memcpy(A->names + A->names_len, nm, l + 1);
        A->names_len += l + 1;
    }
    lx_batch_opts opts;
    memset(&opts, 0, sizeof opts);
    opts.backend = B->backend;
    opts.threads = 1; /* the other cores parse the next chunk meanwhile */
    lx_status st = lx_batch_colorimetry(B->ctx, b, B->observer, &opts, A->res + base);
    lab L = {0};
    if (st == LX_OK) st = lab_compute(B, b, A->res + base, &opts, &L);
    if (st == LX_OK) {
        if (L.par) memcpy(A->par + base, L.par, b->n_spectra * sizeof *L.par);
        if (L.hz) memcpy(A->hz + base, L.hz, b->n_spectra * sizeof *L.hz);
        if (L.bin) memcpy(A->bin + base, L.bin, b->n_spectra * sizeof *L.bin);
    }
    lab_free(&L);
    A->rows = row0 + b->n_spectra;
    for (size_t i = 0; st == LX_OK && i < b->n_spectra; i++) {
        if (A->bad[base + i] || lx_colorimetry_check(B->ctx, &A->res[base + i], row_max_abs(b, i)) == LX_OK) continue;
        if (!A->over_cap) return LX_EUNSUPPORTED; /* the general reader reports it with its line */
        cli_error(B->cmd, "%s: spectrum '%s' (data row %zu): %s", A->path, chunk->names + chunk->name_at[i], row0 + i + 1,
                  lx_ctx_errmsg(B->ctx));
        A->bad[base + i] = 1;
        B->rejected++;
    }
    if (st == LX_OK && A->over_cap) {
        const cli_metrics *m = B->metrics;
        int par = m && cli_metrics_need_par(m), hz = m && cli_metrics_need_hazard(m), bin = m && cli_metrics_need_binning(m);
        for (size_t i = 0; i < b->n_spectra; i++)
            if (!A->bad[i])
                add_row(B, A->path, chunk->names + chunk->name_at[i], &A->res[i], par ? &A->par[i] : NULL,
                        hz ? &A->hz[i] : NULL, bin ? &A->bin[i] : NULL);
        if (B->flush) B->flush(B->flush_arg);
    }
    return st;
}

int cli_spd_batch_file(cli_spd_batch *B, const char *path)
{
    /* only regular files: a FIFO or a device must be read once, by the general reader */
    struct stat sb;
    if (!strcmp(path, "-") || stat(path, &sb) != 0 || !S_ISREG(sb.st_mode) || !plain_rows_header(path)) return 0;
    stream_acc A;
    memset(&A, 0, sizeof A);
    A.B = B;
    A.path = path;
    A.over_cap = (unsigned long long)sb.st_size > lx_ctx_input_limit(B->ctx, LX_INPUT_SPECTRUM);
    lx_status st = lx_batch_table_stream(B->ctx, path, LX_F64, 0, stream_chunk, &A);
    int done = st == LX_OK && A.rows > 0 && (B->forced || A.over_cap || A.rows >= CLI_SPD_BATCH_MIN);
    /* a file the general reader would refuse for its size: the stream's own error stands (and
     * the rows before it were printed) */
    if (st != LX_OK && (st != LX_EUNSUPPORTED || A.rows > 0) && A.over_cap) {
        free(A.res);
        free(A.par);
        free(A.hz);
        free(A.bin);
        free(A.names);
        free(A.bad);
        return -cli_fail(B->cmd, B->ctx, st);
    }
    if (done && !A.over_cap) {
        size_t off = 0;
        const cli_metrics *m = B->metrics;
        int par = m && cli_metrics_need_par(m), hz = m && cli_metrics_need_hazard(m), bin = m && cli_metrics_need_binning(m);
        for (size_t i = 0; i < A.rows; i++) {
            if (!A.bad[i]) add_row(B, path, A.names + off, &A.res[i], par ? &A.par[i] : NULL, hz ? &A.hz[i] : NULL, bin ? &A.bin[i] : NULL);
            off += strlen(A.names + off) + 1;
            if (B->flush && (i + 1) % CHUNK == 0) B->flush(B->flush_arg); /* the table holds a chunk at most */
        }
        if (B->flush) B->flush(B->flush_arg);
    }
    free(A.res);
    free(A.par);
    free(A.hz);
    free(A.bin);
    free(A.names);
    free(A.bad);
    return done ? 1 : 0;
}

int cli_spd_parse_grid(const char *s, double *start, double *step, size_t *n)
{
    char buf[128], *p1, *p2, *end;
    snprintf(buf, sizeof buf, "%s", s);
    if (!(p1 = strchr(buf, ':')) || !(p2 = strchr(p1 + 1, ':'))) return -1;
    *p1++ = 0;
    *p2++ = 0;
    double a = strtod(buf, &end);
    if (*end) return -1;
    double b = strtod(p1, &end);
    if (*end) return -1;
    double st = strtod(p2, &end);
    if (*end || !(a > 0) || !(b > a) || !(st > 0) || !isfinite(a + b + st)) return -1;
    double k = (b - a) / st;
    if (fabs(k - nearbyint(k)) > 1e-6 * (k > 1 ? k : 1) || k > 1e6) return -1;
    *start = a;
    *step = st;
    *n = (size_t)nearbyint(k) + 1;
    return 0;
}

lx_status cli_spd_f32_file(cli_spd_batch *B, const char *path, double start, double step, size_t n)
{
    FILE *f = !strcmp(path, "-") ? stdin : fopen(path, "rb");
    if (!f) {
        cli_error(B->cmd, "%s: cannot open: %s", path, strerror(errno));
        return LX_EIO;
    }
    size_t per = n * sizeof(float), total = 0;
    float *buf = malloc(per * CHUNK);
    if (!buf) {
        if (f != stdin) fclose(f);
        return LX_ENOMEM;
    }
    lx_status st = LX_OK;
    struct stat sb; /* a bar only where the size is known (a regular file) */
    if (f != stdin && fstat(fileno(f), &sb) == 0 && S_ISREG(sb.st_mode)) cli_progress_start((size_t)sb.st_size / per, path);
    for (;;) {
        size_t got = fread(buf, 1, per * CHUNK, f);
        if (got % per) {
            /* read to the end to report the real size */
            size_t rest = got;
            while (!feof(f) && !ferror(f)) rest += fread(buf, 1, per * CHUNK, f);
            cli_error(B->cmd, "%s: %zu bytes is not a whole number of spectra of %zu float32 samples (%zu bytes each)",
                      path, total + rest, n, per);
            st = LX_EPARSE;
            break;
        }
        size_t m = got / per;
        if (m) {
            /* little-endian on disk; this build's host order is checked at start-up of the command */
            for (size_t i = 0; i < m * n && st == LX_OK; i++)
                if (!isfinite(buf[i])) {
                    cli_error(B->cmd, "%s: spectrum %zu, sample %zu (%g nm): value is not finite", path,
                              total / per + i / n + 1, i % n + 1, start + (double)(i % n) * step);
                    st = LX_EPARSE;
                }
            if (st != LX_OK) break;
            lx_batch b = {m, n, 0, start, step, LX_F32, buf};
            st = run_chunk(B, &b, path, NULL, NULL, total / per, 1); /* the first bad spectrum ends the file */
            if (st != LX_OK) {
                if (st != LX_ERANGE) cli_error(B->cmd, "%s: %s", path, lx_ctx_errmsg(B->ctx));
                break;
            }
            total += got;
            cli_progress_update(total / per);
        }
        if (got < per * CHUNK) break;
    }
    cli_progress_end();
    if (ferror(f)) {
        cli_error(B->cmd, "%s: read error", path);
        st = LX_EIO;
    }
    free(buf);
    if (f != stdin) fclose(f);
    return st;
}
