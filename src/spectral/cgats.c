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
            tok *nt = realloc(ts->t, cap * sizeof *nt);
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

lx_status lx__cgats_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    lx_ctx *ctx = rd->ctx;
    const char *file = rd->file;
    rd->format = "cgats";
    lx_status st = LX_OK;
    lx__lines it = {text, text + len, rd->line0};
    size_t dropped = 0; /* sets left out with skip_bad_rows */
    int first_line = 1;
    const char *s, *e;
    toks ts = {0};
    tok *fields = NULL; /* the field names, pointing into text */
    size_t nfields = 0, fcap = 0;
    kw n_fields = {0}, n_sets = {0}, bands = {0}, start = {0}, end = {0}, norm = {0};
    long fmt_line = 0, fmt_end_line = 0, data_line = 0, end_data_line = 0;
    int state = ST_HEADER;
    /* per field: -1 other, -2 name, >= 0 index of the spectral band */
    int *role = NULL;
    double *field_nm = NULL;
    size_t nspec = 0;
    int name_field = -1, name_rank = 0;
    double *vals = NULL; /* nsets x nspec */
    size_t vcap = 0, nsets = 0, pos = 0; /* pos: index of the next value within the current set */
    long *set_line = NULL;
    size_t lcap = 0;
    char **names = NULL;
    int aligned = -1; /* 1 when each data line holds exactly one set */
    double *lambda = NULL;

    while (lx__next_line(&it, &s, &e)) {
        if (tokenize(s, e, &ts)) goto nomem;
        if (ts.n == 0) continue;
        const char *t0 = ts.t[0].s, *t1 = ts.t[0].e;
        size_t skip = 0;
        if (state == ST_HEADER || state == ST_AFTER) {
            if (tok_is(t0, t1, "BEGIN_DATA_FORMAT")) {
                if (fmt_line) {
                    st = lx__error(ctx, LX_EPARSE, file, it.line, "second BEGIN_DATA_FORMAT (first on line %ld)",
                                   fmt_line);
                    goto done;
                }
                fmt_line = it.line;
                state = ST_FORMAT;
                skip = 1; /* fields may follow on the same line */
            } else if (tok_is(t0, t1, "BEGIN_DATA")) {
                if (state == ST_AFTER) {
                    st = lx__error(ctx, LX_EPARSE, file, it.line, "second BEGIN_DATA (only one table is read)");
                    goto done;
                }
                if (!fmt_end_line) {
                    st = lx__error(ctx, LX_EPARSE, file, it.line, "BEGIN_DATA before BEGIN_DATA_FORMAT ... "
                                   "END_DATA_FORMAT");
                    goto done;
                }
                data_line = it.line;
                state = ST_DATA;
                continue;
            } else if (tok_is(t0, t1, "END_DATA") || tok_is(t0, t1, "END_DATA_FORMAT")) {
                st = lx__error(ctx, LX_EPARSE, file, it.line, "%.*s without its BEGIN", (int)(t1 - t0), t0);
                goto done;
            } else {
                kw *k = tok_is(t0, t1, "NUMBER_OF_FIELDS")    ? &n_fields
                        : tok_is(t0, t1, "NUMBER_OF_SETS")    ? &n_sets
                        : tok_is(t0, t1, "SPECTRAL_BANDS")    ? &bands
                        : tok_is(t0, t1, "SPECTRAL_START_NM") ? &start
                        : tok_is(t0, t1, "SPECTRAL_END_NM")   ? &end
                        : tok_is(t0, t1, "SPECTRAL_NORM")     ? &norm
                                                              : NULL;
                if (k && (st = keyword_num(ctx, file, it.line, &ts, k))) goto done;
                /* every keyword is a header field (not the file identifier, not KEYWORD declarations) */
                if (!(first_line && ts.n == 1) && !tok_is(t0, t1, "KEYWORD") &&
                    lx__rd_field(rd, it.line, t0, t1, ts.n > 1 ? ts.t[1].s : NULL, ts.n > 1 ? ts.t[ts.n - 1].e : NULL))
                    goto nomem;
                first_line = 0;
                continue;
            }
        }
        if (state == ST_FORMAT) {
            for (size_t i = skip; i < ts.n; i++) {
                if (tok_is(ts.t[i].s, ts.t[i].e, "END_DATA_FORMAT")) {
                    fmt_end_line = it.line;
                    state = ST_HEADER;
                    break;
                }
                if (nfields == fcap) {
                    fcap = fcap ? 2 * fcap : 64;
                    tok *nf = realloc(fields, fcap * sizeof *nf);
                    if (!nf) goto nomem;
                    fields = nf;
                }
                fields[nfields++] = ts.t[i];
            }
            if (state == ST_HEADER) { /* the field list is complete: classify it */
                if (nfields == 0) {
                    st = lx__error(ctx, LX_EPARSE, file, fmt_line, "empty BEGIN_DATA_FORMAT field list");
                    goto done;
                }
                role = malloc(nfields * sizeof *role);
                field_nm = malloc(nfields * sizeof *field_nm);
                if (!role || !field_nm) goto nomem;
                for (size_t f = 0; f < nfields; f++) {
                    char nb[32];
                    norm_name(fields[f].s, fields[f].e, nb, sizeof nb);
                    role[f] = -1;
                    if (spectral_field(fields[f].s, fields[f].e, &field_nm[nspec])) {
                        role[f] = (int)nspec++;
                    } else if (strcmp(nb, "SAMPLENAME") == 0 && name_rank < 2) {
                        name_field = (int)f;
                        name_rank = 2;
                    } else if (strcmp(nb, "SAMPLEID") == 0 && name_rank < 1) {
                        name_field = (int)f;
                        name_rank = 1;
                    }
                }
                if (nspec == 0) {
                    st = lx__error(ctx, LX_EPARSE, file, fmt_line,
                                   "no spectral fields (SPECTRAL_NM380, SPEC_380, ...) in the data format");
                    goto done;
                }
                if (n_fields.have && n_fields.v != (double)nfields) {
                    st = lx__error(ctx, LX_EPARSE, file, n_fields.line,
                                   "NUMBER_OF_FIELDS is %.17g but the data format lists %zu fields", n_fields.v,
                                   nfields);
                    goto done;
                }
            }
            continue;
        }
        if (state == ST_DATA) {
            if (tok_is(t0, t1, "END_DATA")) {
                end_data_line = it.line;
                state = ST_AFTER;
                continue;
            }
            if (aligned < 0) aligned = ts.n == nfields;
            if (aligned && ts.n != nfields) {
                if ((st = lx__rd_bad_row(rd, it.line, "row has %zu fields, expected %zu (the data format)", ts.n,
                                         nfields)))
                    goto done;
                dropped++;
                continue;
            }
            int bad = 0;
            for (size_t i = 0; i < ts.n; i++) {
                if (pos == 0) { /* a new set starts */
                    if (nsets == vcap) {
                        size_t cap = vcap ? 2 * vcap : 16;
                        double *nv = realloc(vals, cap * nspec * sizeof *nv);
                        if (!nv) goto nomem;
                        vals = nv;
                        char **nn = realloc(names, cap * sizeof *nn);
                        if (!nn) goto nomem;
                        names = nn;
                        vcap = cap;
                    }
                    if (nsets == lcap) {
                        size_t cap = lcap ? 2 * lcap : 16;
                        long *nl = realloc(set_line, cap * sizeof *nl);
                        if (!nl) goto nomem;
                        set_line = nl;
                        lcap = cap;
                    }
                    names[nsets] = NULL;
                    set_line[nsets] = it.line;
                    nsets++;
                }
                size_t f = pos;
                if (role[f] >= 0 && !bad) {
                    st = lx__parse_field(ctx, file, it.line, ts.t[i].s, ts.t[i].e, 0, "value",
                                         &vals[(nsets - 1) * nspec + (size_t)role[f]]);
                    if (st && (!aligned || (st = lx__rd_bad_field(rd, it.line, st)))) goto done;
                    if (!st && rd->nskipped && rd->skipped[rd->nskipped - 1].line == it.line) bad = 1;
                } else if ((int)f == name_field) {
                    size_t n = (size_t)(ts.t[i].e - ts.t[i].s);
                    char *nm = malloc(n + 1);
                    if (!nm) goto nomem;
                    memcpy(nm, ts.t[i].s, n);
                    nm[n] = '\0';
                    names[nsets - 1] = nm;
                }
                pos = (pos + 1) % nfields;
            }
            if (bad) { /* aligned: this line was one set; leave it out */
                nsets--;
                free(names[nsets]);
                names[nsets] = NULL;
                dropped++;
            }
        }
    }

    if (state == ST_FORMAT) {
        st = lx__error(ctx, LX_EPARSE, file, fmt_line, "BEGIN_DATA_FORMAT without END_DATA_FORMAT");
        goto done;
    }
    if (!fmt_line) {
        st = lx__error(ctx, LX_EPARSE, file, it.line ? it.line : 1, "CGATS file without BEGIN_DATA_FORMAT");
        goto done;
    }
    if (!data_line) {
        st = lx__error(ctx, LX_EPARSE, file, it.line, "CGATS file without BEGIN_DATA (ends at line %ld)", it.line);
        goto done;
    }
    if (state == ST_DATA) {
        st = lx__error(ctx, LX_EPARSE, file, data_line, "BEGIN_DATA without END_DATA");
        goto done;
    }
    if (pos != 0) {
        st = lx__error(ctx, LX_EPARSE, file, set_line[nsets - 1],
                       "incomplete data set: %zu of %zu values before END_DATA", pos, nfields);
        goto done;
    }
    if (nsets == 0) {
        st = lx__error(ctx, LX_EPARSE, file, data_line, "no data sets between BEGIN_DATA and END_DATA");
        goto done;
    }
    if (n_sets.have && n_sets.v != (double)(nsets + dropped)) {
        st = lx__error(ctx, LX_EPARSE, file, n_sets.line,
                       "NUMBER_OF_SETS is %.17g but the data holds %zu sets (lines %ld-%ld)", n_sets.v, nsets,
                       data_line, end_data_line);
        goto done;
    }
    lambda = malloc(nspec * sizeof *lambda);
    if (!lambda) goto nomem;
    if (bands.have || start.have || end.have) {
        if (!(bands.have && start.have && end.have)) {
            long l = bands.have ? bands.line : start.have ? start.line : end.line;
            st = lx__error(ctx, LX_EPARSE, file, l,
                           "SPECTRAL_BANDS, SPECTRAL_START_NM and SPECTRAL_END_NM must appear together");
            goto done;
        }
        if (bands.v != (double)nspec) {
            st = lx__error(ctx, LX_EPARSE, file, bands.line,
                           "SPECTRAL_BANDS is %.17g but the data format has %zu spectral fields", bands.v, nspec);
            goto done;
        }
        if (!(start.v > 0) || !(end.v > start.v)) {
            st = lx__error(ctx, LX_EPARSE, file, end.line,
                           "SPECTRAL_START_NM %.17g and SPECTRAL_END_NM %.17g: need 0 < start < end", start.v,
                           end.v);
            goto done;
        }
        for (size_t j = 0; j < nspec; j++)
            lambda[j] = j + 1 == nspec ? end.v : start.v + (end.v - start.v) * (double)j / (double)(nspec - 1);
    } else {
        for (size_t f = 0; f < nfields; f++)
            if (role[f] >= 0) lambda[role[f]] = field_nm[role[f]];
    }
    if (norm.have) {
        if (!(norm.v > 0)) {
            st = lx__error(ctx, LX_EPARSE, file, norm.line, "SPECTRAL_NORM must be positive: %.17g", norm.v);
            goto done;
        }
        if (norm.v != 1.0)
            for (size_t i = 0; i < nsets * nspec; i++) vals[i] /= norm.v;
    }
    st = lx__spd_set_build(ctx, file, nspec, lambda, 1, NULL, fmt_line, nsets, vals, nspec, 1, names, set_line,
                           out);
    goto done;
nomem:
    st = lx__error(ctx, LX_ENOMEM, file, 0, "out of memory");
done:
    if (names)
        for (size_t i = 0; i < nsets; i++) free(names[i]);
    free(names);
    free(ts.t);
    free(fields);
    free(role);
    free(field_nm);
    free(vals);
    free(set_line);
    free(lambda);
    return st;
}
