/* cgats.c - reads CGATS spectral files (X-Rite CGATS.17, Argyll .sp/.ti3/.cgats): keywords,
 * BEGIN_DATA_FORMAT field lists with SPECTRAL_NM380 / SPEC_380 style fields, SPECTRAL_BANDS /
 * _START_NM / _END_NM / _NORM, and the data sets, one spectrum per set. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

static int starts_with(const char *s, const char *e, const char *w)
{
    size_t n = strlen(w);
    return (size_t)(e - s) >= n && memcmp(s, w, n) == 0;
}

static int tok_is(const char *s, const char *e, const char *w)
{
    size_t n = strlen(w);
    return (size_t)(e - s) == n && memcmp(s, w, n) == 0;
}

/* The first whitespace-separated token of the first line with content. */
int lx__cgats_detect(const char *text, size_t len)
{
    lx__lines it = {text, text + len, 0};
    const char *s, *e;
    int first = 1;
    size_t scanned = 0;
    while (lx__next_line(&it, &s, &e) && scanned < (1u << 20)) {
        scanned += (size_t)(e - s) + 1;
        while (s < e && is_space(*s)) s++;
        if (s >= e || *s == '#') continue;
        const char *t = s;
        while (t < e && !is_space(*t)) t++;
        if (first) {
            if (starts_with(s, t, "CGATS") || tok_is(s, t, "SPECT") || tok_is(s, t, "CTI1") ||
                tok_is(s, t, "CTI2") || tok_is(s, t, "CTI3") || starts_with(s, t, "IT8."))
                return 1;
            first = 0;
        }
        if (tok_is(s, t, "BEGIN_DATA_FORMAT") || tok_is(s, t, "NUMBER_OF_FIELDS") ||
            tok_is(s, t, "SPECTRAL_BANDS"))
            return 1;
    }
    return 0;
}

/* Tokens of one line: whitespace-separated, "quoted strings" kept whole (quotes stripped),
 * '#' outside quotes starts a comment. */
typedef struct tok {
    const char *s, *e;
} tok;
typedef struct toks {
    tok *t;
    size_t n, cap;
} toks;

static int tokenize(const char *s, const char *e, toks *ts)
{
    ts->n = 0;
    const char *p = s;
    for (;;) {
        while (p < e && is_space(*p)) p++;
        if (p >= e || *p == '#') return 0;
        const char *a, *b;
        if (*p == '"') {
            a = ++p;
            while (p < e && *p != '"') p++;
            b = p;
            if (p < e) p++;
        } else {
            a = p;
            while (p < e && !is_space(*p)) p++;
            b = p;
        }
        if (ts->n == ts->cap) {
            size_t cap = ts->cap ? 2 * ts->cap : 32;
            tok *nt = lx__realloc_n(ts->t, cap, sizeof *nt);
            if (!nt) return -1;
            ts->t = nt;
            ts->cap = cap;
        }
        ts->t[ts->n].s = a;
        ts->t[ts->n].e = b;
        ts->n++;
    }
}

/* Upper-cases [s, e) without underscores into buf (truncated); for field-name comparisons. */
static void norm_name(const char *s, const char *e, char *buf, size_t cap)
{
    size_t n = 0;
    for (; s < e && n + 1 < cap; s++) {
        char c = *s;
        if (c == '_') continue;
        if (c >= 'a' && c <= 'z') c = (char)(c - 'a' + 'A');
        buf[n++] = c;
    }
    buf[n] = '\0';
}

/* A spectral field name (SPECTRAL_NM380, SPECTRAL_NM_380, SPECTRAL_380, SPEC_380, NM380): its
 * wavelength in nm in *nm; returns 0 for any other field. */
static int spectral_field(const char *s, const char *e, double *nm)
{
    static const char *const prefix[] = {"SPECTRAL_NM_", "SPECTRAL_NM", "SPECTRAL_", "SPEC_", "NM_", "NM"};
    for (size_t i = 0; i < sizeof prefix / sizeof prefix[0]; i++) {
        size_t n = strlen(prefix[i]);
        if ((size_t)(e - s) <= n) continue;
        size_t j = 0;
        for (; j < n; j++) {
            char c = s[j];
            if (c >= 'a' && c <= 'z') c = (char)(c - 'a' + 'A');
            if (c != prefix[i][j]) break;
        }
        if (j < n) continue;
        const char *q = lx__parse_double(s + n, e, nm);
        if (q == e && *nm > 0 && isfinite(*nm)) return 1;
    }
    return 0;
}

typedef struct kw {
    int have;
    long line;
    double v;
} kw;

static lx_status keyword_num(lx_ctx *ctx, const char *file, long line, const toks *ts, kw *k)
{
    if (ts->n < 2)
        return lx__error(ctx, LX_EPARSE, file, line, "keyword %.*s has no value", (int)(ts->t[0].e - ts->t[0].s),
                         ts->t[0].s);
    k->have = 1;
    k->line = line;
    return lx__parse_field(ctx, file, line, ts->t[1].s, ts->t[1].e, 0, "keyword value", &k->v);
}

enum { ST_HEADER, ST_FORMAT, ST_DATA, ST_AFTER };

/* The reader's state from line to line. */
typedef struct cgats {
    lx__rd *rd;
    lx_ctx *ctx;
    const char *file;
    int state;
    int first_line;
    toks ts;        /* the tokens of the current line */
    size_t dropped; /* sets left out with skip_bad_rows */
    tok *fields;    /* the field names, pointing into text */
    size_t nfields, fcap;
    kw n_fields, n_sets, bands, start, end, norm;
    long fmt_line, fmt_end_line, data_line, end_data_line;
    int *role; /* per field: -1 other, >= 0 index of the spectral band */
    double *field_nm;
    size_t nspec;
    int name_field, name_rank;
    double *vals;                 /* nsets x nspec */
    size_t vcap, nsets, pos;      /* pos: index of the next value within the current set */
    long *set_line;
    size_t lcap;
    char **names;
    int aligned; /* 1 when each data line holds exactly one set */
    double *lambda;
} cgats;

/* A keyword line of the header: the numeric keywords the reader uses, and every keyword as a header
 * field (not the file identifier, not KEYWORD declarations). */
static lx_status keyword_line(cgats *p, long line)
{
    const toks *ts = &p->ts;
    const char *t0 = ts->t[0].s, *t1 = ts->t[0].e;
    kw *k = tok_is(t0, t1, "NUMBER_OF_FIELDS")    ? &p->n_fields
            : tok_is(t0, t1, "NUMBER_OF_SETS")    ? &p->n_sets
            : tok_is(t0, t1, "SPECTRAL_BANDS")    ? &p->bands
            : tok_is(t0, t1, "SPECTRAL_START_NM") ? &p->start
            : tok_is(t0, t1, "SPECTRAL_END_NM")   ? &p->end
            : tok_is(t0, t1, "SPECTRAL_NORM")     ? &p->norm
                                                  : NULL;
    lx_status st;
    if (k && (st = keyword_num(p->ctx, p->file, line, ts, k))) return st;
    if (!(p->first_line && ts->n == 1) && !tok_is(t0, t1, "KEYWORD") &&
        lx__rd_field(p->rd, line, t0, t1, ts->n > 1 ? ts->t[1].s : NULL, ts->n > 1 ? ts->t[ts->n - 1].e : NULL))
        return lx__rd_nomem(p->rd);
    p->first_line = 0;
    return LX_OK;
}

/* A line before, between or after the field list and the data: the BEGIN_ / END_ markers and the
 * keywords. *format becomes 1 when the line opens the field list (fields may follow on it). */
static lx_status header_line(cgats *p, long line, int *format)
{
    const char *t0 = p->ts.t[0].s, *t1 = p->ts.t[0].e;
    *format = 0;
    if (tok_is(t0, t1, "BEGIN_DATA_FORMAT")) {
        if (p->fmt_line)
            return lx__error(p->ctx, LX_EPARSE, p->file, line, "second BEGIN_DATA_FORMAT (first on line %ld)",
                             p->fmt_line);
        p->fmt_line = line;
        p->state = ST_FORMAT;
        *format = 1;
        return LX_OK;
    }
    if (tok_is(t0, t1, "BEGIN_DATA")) {
        if (p->state == ST_AFTER)
            return lx__error(p->ctx, LX_EPARSE, p->file, line, "second BEGIN_DATA (only one table is read)");
        if (!p->fmt_end_line)
            return lx__error(p->ctx, LX_EPARSE, p->file, line, "BEGIN_DATA before BEGIN_DATA_FORMAT ... "
                             "END_DATA_FORMAT");
        p->data_line = line;
        p->state = ST_DATA;
        return LX_OK;
    }
    if (tok_is(t0, t1, "END_DATA") || tok_is(t0, t1, "END_DATA_FORMAT"))
        return lx__error(p->ctx, LX_EPARSE, p->file, line, "%.*s without its BEGIN", (int)(t1 - t0), t0);
    return keyword_line(p, line);
}

/* The complete field list: which fields are spectral bands (and their wavelengths) and which one
 * names the samples (SAMPLE_NAME before SAMPLE_ID); at least one band, NUMBER_OF_FIELDS agreeing. */
static lx_status classify_fields(cgats *p)
{
    if (p->nfields == 0)
        return lx__error(p->ctx, LX_EPARSE, p->file, p->fmt_line, "empty BEGIN_DATA_FORMAT field list");
    p->role = lx__alloc_n(p->nfields, sizeof *p->role);
    p->field_nm = lx__alloc_n(p->nfields, sizeof *p->field_nm);
    if (!p->role || !p->field_nm) return lx__rd_nomem(p->rd);
    for (size_t f = 0; f < p->nfields; f++) {
        char nb[32];
        norm_name(p->fields[f].s, p->fields[f].e, nb, sizeof nb);
        p->role[f] = -1;
        if (spectral_field(p->fields[f].s, p->fields[f].e, &p->field_nm[p->nspec])) {
            p->role[f] = (int)p->nspec++;
        } else if (strcmp(nb, "SAMPLENAME") == 0 && p->name_rank < 2) {
            p->name_field = (int)f;
            p->name_rank = 2;
        } else if (strcmp(nb, "SAMPLEID") == 0 && p->name_rank < 1) {
            p->name_field = (int)f;
            p->name_rank = 1;
        }
    }
    if (p->nspec == 0)
        return lx__error(p->ctx, LX_EPARSE, p->file, p->fmt_line,
                         "no spectral fields (SPECTRAL_NM380, SPEC_380, ...) in the data format");
    if (p->n_fields.have && p->n_fields.v != (double)p->nfields)
        return lx__error(p->ctx, LX_EPARSE, p->file, p->n_fields.line,
                         "NUMBER_OF_FIELDS is %.17g but the data format lists %zu fields", p->n_fields.v, p->nfields);
    return LX_OK;
}

/* A line of the field list from token `skip` on: field names up to END_DATA_FORMAT, which closes
 * the list (the rest of its line is ignored). */
static lx_status format_line(cgats *p, long line, size_t skip)
{
    for (size_t i = skip; i < p->ts.n; i++) {
        if (tok_is(p->ts.t[i].s, p->ts.t[i].e, "END_DATA_FORMAT")) {
            p->fmt_end_line = line;
            p->state = ST_HEADER;
            return classify_fields(p);
        }
        if (p->nfields == p->fcap) {
            p->fcap = p->fcap ? 2 * p->fcap : 64;
            tok *nf = lx__realloc_n(p->fields, p->fcap, sizeof *nf);
            if (!nf) return lx__rd_nomem(p->rd);
            p->fields = nf;
        }
        p->fields[p->nfields++] = p->ts.t[i];
    }
    return LX_OK;
}

/* Opens the next data set, which starts on `line`: room for its values, name and line. Returns -1
 * when memory runs out. */
static int start_set(cgats *p, long line)
{
    if (p->nsets == p->vcap) {
        size_t cap = p->vcap ? 2 * p->vcap : 16;
        double *nv = lx__realloc_n(p->vals, cap * p->nspec, sizeof *nv);
        if (!nv) return -1;
        p->vals = nv;
        char **nn = lx__realloc_n(p->names, cap, sizeof *nn);
        if (!nn) return -1;
        p->names = nn;
        p->vcap = cap;
    }
    if (p->nsets == p->lcap) {
        size_t cap = p->lcap ? 2 * p->lcap : 16;
        long *nl = lx__realloc_n(p->set_line, cap, sizeof *nl);
        if (!nl) return -1;
        p->set_line = nl;
        p->lcap = cap;
    }
    p->names[p->nsets] = NULL;
    p->set_line[p->nsets] = line;
    p->nsets++;
    return 0;
}

/* Token t of a data line as field p->pos of the current set: a band value or the sample name
 * (other fields are ignored). *bad becomes 1 when skip_bad_rows leaves an aligned line out for a
 * bad value; the line's later values are then not parsed. */
static lx_status data_value(cgats *p, long line, const tok *t, int *bad)
{
    size_t f = p->pos;
    if (p->role[f] >= 0 && !*bad) {
        lx_status st = lx__parse_field(p->ctx, p->file, line, t->s, t->e, 0, "value",
                                       &p->vals[(p->nsets - 1) * p->nspec + (size_t)p->role[f]]);
        if (st && (!p->aligned || (st = lx__rd_bad_field(p->rd, line, st)))) return st;
        if (!st && p->rd->nskipped && p->rd->skipped[p->rd->nskipped - 1].line == line) *bad = 1;
    } else if ((int)f == p->name_field) {
        size_t n = (size_t)(t->e - t->s);
        char *nm = lx__alloc(n + 1);
        if (!nm) return lx__rd_nomem(p->rd);
        memcpy(nm, t->s, n);
        nm[n] = '\0';
        p->names[p->nsets - 1] = nm;
    }
    return LX_OK;
}

/* A line between BEGIN_DATA and END_DATA. Sets may span lines (values are taken in field order);
 * when the first line holds exactly one set every line must (aligned), and skip_bad_rows can then
 * leave a line out. */
static lx_status data_line(cgats *p, long line)
{
    const toks *ts = &p->ts;
    if (tok_is(ts->t[0].s, ts->t[0].e, "END_DATA")) {
        p->end_data_line = line;
        p->state = ST_AFTER;
        return LX_OK;
    }
    if (p->aligned < 0) p->aligned = ts->n == p->nfields;
    if (p->aligned && ts->n != p->nfields) {
        lx_status st = lx__rd_bad_row(p->rd, line, "row has %zu fields, expected %zu (the data format)", ts->n,
                                      p->nfields);
        if (!st) p->dropped++;
        return st;
    }
    int bad = 0;
    for (size_t i = 0; i < ts->n; i++) {
        if (p->pos == 0 && start_set(p, line)) return lx__rd_nomem(p->rd);
        lx_status st = data_value(p, line, &ts->t[i], &bad);
        if (st) return st;
        p->pos = (p->pos + 1) % p->nfields;
    }
    if (bad) { /* aligned: this line was one set; leave it out */
        p->nsets--;
        lx__free(p->names[p->nsets]);
        p->names[p->nsets] = NULL;
        p->dropped++;
    }
    return LX_OK;
}

/* Every line of the text, through the header, the field list and the data. */
static lx_status read_lines(cgats *p, lx__lines *it)
{
    const char *s, *e;
    while (lx__next_line(it, &s, &e)) {
        if (tokenize(s, e, &p->ts)) return lx__rd_nomem(p->rd);
        if (p->ts.n == 0) continue;
        size_t skip = 0;
        lx_status st = LX_OK;
        if (p->state == ST_HEADER || p->state == ST_AFTER) {
            int format;
            if ((st = header_line(p, it->line, &format))) return st;
            if (!format) continue;
            skip = 1; /* fields may follow BEGIN_DATA_FORMAT on its line */
        }
        if (p->state == ST_FORMAT)
            st = format_line(p, it->line, skip);
        else if (p->state == ST_DATA)
            st = data_line(p, it->line);
        if (st) return st;
    }
    return LX_OK;
}

/* After the last line (last_line): one field list and one data table, both closed, whole sets, and
 * NUMBER_OF_SETS agreeing (counting the sets skip_bad_rows left out). */
static lx_status check_complete(const cgats *p, long last_line)
{
    lx_ctx *ctx = p->ctx;
    const char *file = p->file;
    if (p->state == ST_FORMAT)
        return lx__error(ctx, LX_EPARSE, file, p->fmt_line, "BEGIN_DATA_FORMAT without END_DATA_FORMAT");
    if (!p->fmt_line)
        return lx__error(ctx, LX_EPARSE, file, last_line ? last_line : 1, "CGATS file without BEGIN_DATA_FORMAT");
    if (!p->data_line)
        return lx__error(ctx, LX_EPARSE, file, last_line, "CGATS file without BEGIN_DATA (ends at line %ld)",
                         last_line);
    if (p->state == ST_DATA) return lx__error(ctx, LX_EPARSE, file, p->data_line, "BEGIN_DATA without END_DATA");
    if (p->pos != 0)
        return lx__error(ctx, LX_EPARSE, file, p->set_line[p->nsets - 1],
                         "incomplete data set: %zu of %zu values before END_DATA", p->pos, p->nfields);
    if (p->nsets == 0)
        return lx__error(ctx, LX_EPARSE, file, p->data_line, "no data sets between BEGIN_DATA and END_DATA");
    if (p->n_sets.have && p->n_sets.v != (double)(p->nsets + p->dropped))
        return lx__error(ctx, LX_EPARSE, file, p->n_sets.line,
                         "NUMBER_OF_SETS is %.17g but the data holds %zu sets (lines %ld-%ld)", p->n_sets.v,
                         p->nsets, p->data_line, p->end_data_line);
    return LX_OK;
}

/* The band wavelengths into p->lambda: evenly spaced from SPECTRAL_BANDS, SPECTRAL_START_NM and
 * SPECTRAL_END_NM when the header gives them (all three, agreeing with the field list), else those
 * of the field names. */
static lx_status band_wavelengths(cgats *p)
{
    const kw *bands = &p->bands, *start = &p->start, *end = &p->end;
    size_t nspec = p->nspec;
    p->lambda = lx__alloc_n(nspec, sizeof *p->lambda);
    if (!p->lambda) return lx__rd_nomem(p->rd);
    if (!(bands->have || start->have || end->have)) {
        for (size_t f = 0; f < p->nfields; f++)
            if (p->role[f] >= 0) p->lambda[p->role[f]] = p->field_nm[p->role[f]];
        return LX_OK;
    }
    if (!(bands->have && start->have && end->have)) {
        long l = bands->have ? bands->line : start->have ? start->line : end->line;
        return lx__error(p->ctx, LX_EPARSE, p->file, l,
                         "SPECTRAL_BANDS, SPECTRAL_START_NM and SPECTRAL_END_NM must appear together");
    }
    if (bands->v != (double)nspec)
        return lx__error(p->ctx, LX_EPARSE, p->file, bands->line,
                         "SPECTRAL_BANDS is %.17g but the data format has %zu spectral fields", bands->v, nspec);
    if (!(start->v > 0) || !(end->v > start->v))
        return lx__error(p->ctx, LX_EPARSE, p->file, end->line,
                         "SPECTRAL_START_NM %.17g and SPECTRAL_END_NM %.17g: need 0 < start < end", start->v,
                         end->v);
    for (size_t j = 0; j < nspec; j++)
        p->lambda[j] = j + 1 == nspec ? end->v : start->v + (end->v - start->v) * (double)j / (double)(nspec - 1);
    return LX_OK;
}

/* Divides the values by SPECTRAL_NORM (Argyll's convention) when the header gives it; it must be
 * positive. */
static lx_status apply_norm(cgats *p)
{
    if (!p->norm.have) return LX_OK;
    if (!(p->norm.v > 0))
        return lx__error(p->ctx, LX_EPARSE, p->file, p->norm.line, "SPECTRAL_NORM must be positive: %.17g",
                         p->norm.v);
    if (p->norm.v != 1.0)
        for (size_t i = 0; i < p->nsets * p->nspec; i++) p->vals[i] /= p->norm.v;
    return LX_OK;
}

static void cgats_free(cgats *p)
{
    if (p->names)
        for (size_t i = 0; i < p->nsets; i++) lx__free(p->names[i]);
    lx__free(p->names);
    lx__free(p->ts.t);
    lx__free(p->fields);
    lx__free(p->role);
    lx__free(p->field_nm);
    lx__free(p->vals);
    lx__free(p->set_line);
    lx__free(p->lambda);
}

lx_status lx__cgats_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    rd->format = "cgats";
    cgats p = {.rd = rd, .ctx = rd->ctx, .file = rd->file, .state = ST_HEADER, .first_line = 1, .name_field = -1,
               .aligned = -1};
    lx__lines it = {text, text + len, rd->line0};
    lx_status st = read_lines(&p, &it);
    if (!st) st = check_complete(&p, it.line);
    if (!st) st = band_wavelengths(&p);
    if (!st) st = apply_norm(&p);
    if (!st)
        st = lx__spd_set_build(p.ctx, p.file, p.nspec, p.lambda, 1, NULL, p.fmt_line, p.nsets, p.vals, p.nspec, 1,
                               p.names, p.set_line, out);
    cgats_free(&p);
    return st;
}
