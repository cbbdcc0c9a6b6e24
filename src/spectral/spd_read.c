/* spd_read.c - reads spectra from text: the columns layout (wavelength, value...) and the rows
 * layout (a header of wavelengths, one spectrum per row), separator detection, BOM/CRLF/comments,
 * and the lx_spd_set that owns the result. CGATS files are handed to cgats.c. */
#include "spectral/spectral_private.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* ---- small helpers ---- */

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

/* ---- the set ---- */

void lx_spd_set_free(lx_spd_set *set)
{
    if (!set) return;
    if (set->spd) {
        for (size_t i = 0; i < set->count; i++) {
            free((void *)set->spd[i].name);
            free((void *)set->spd[i].lambda_nm);
            free((void *)set->spd[i].value);
        }
    }
    free(set->spd);
    free(set->line);
    free(set->file);
    free(set);
}

/* lx_spd_check lives in integrate.c (written there first, same contract). */

typedef struct sort_key {
    double lambda;
    size_t k;
} sort_key;

static int cmp_key(const void *a, const void *b)
{
    const sort_key *x = a, *y = b;
    if (x->lambda < y->lambda) return -1;
    if (x->lambda > y->lambda) return 1;
    return x->k < y->k ? -1 : x->k > y->k;
}

lx_status lx__spd_set_build(lx_ctx *ctx, const char *file, size_t nlam, const double *lambda,
                            size_t lam_stride, const long *lam_line, long lam_line_all, size_t nspec,
                            const double *val, size_t ss, size_t ks, char *const *names,
                            const long *lines, lx_spd_set **out)
{
#define LAMLINE(k) (lam_line ? lam_line[k] : lam_line_all)
    *out = NULL;
    if (nlam < 2)
        return lx__error(ctx, LX_EPARSE, file, nlam ? LAMLINE(0) : lam_line_all,
                         "%zu wavelength sample%s; a spectrum needs at least 2", nlam, nlam == 1 ? "" : "s");
    for (size_t k = 0; k < nlam; k++) {
        double l = lambda[k * lam_stride];
        if (!isfinite(l) || !(l > 0))
            return lx__error(ctx, LX_EPARSE, file, LAMLINE(k), "wavelength must be positive: %.17g nm", l);
    }
    sort_key *key = malloc(nlam * sizeof *key);
    if (!key) return lx__error(ctx, LX_ENOMEM, file, 0, "out of memory (%zu samples)", nlam);
    int sorted = 1;
    for (size_t k = 0; k < nlam; k++) {
        key[k].lambda = lambda[k * lam_stride];
        key[k].k = k;
        if (k > 0 && !(key[k].lambda > key[k - 1].lambda)) sorted = 0;
    }
    if (!sorted) {
        qsort(key, nlam, sizeof *key, cmp_key);
        for (size_t k = 1; k < nlam; k++) {
            if (key[k].lambda == key[k - 1].lambda) {
                size_t a = key[k - 1].k, b = key[k].k; /* b is the later one in the file */
                lx_status st = lx__error(ctx, LX_EPARSE, file, LAMLINE(b),
                                         "duplicate wavelength %.17g nm (first on line %ld)",
                                         key[k].lambda, LAMLINE(a));
                free(key);
                return st;
            }
        }
    }
    lx_spd_set *set = calloc(1, sizeof *set);
    if (!set) goto nomem;
    set->file = lx__strndup(file, file + strlen(file));
    set->spd = calloc(nspec ? nspec : 1, sizeof *set->spd);
    set->line = calloc(nspec ? nspec : 1, sizeof *set->line);
    if (!set->file || !set->spd || !set->line) goto nomem;
    for (size_t s = 0; s < nspec; s++) {
        char num[32];
        const char *nm = names ? names[s] : NULL;
        if (!nm || !*nm) {
            snprintf(num, sizeof num, "%zu", s + 1);
            nm = num;
        }
        double *l = malloc(nlam * sizeof *l);
        double *v = malloc(nlam * sizeof *v);
        char *name = lx__strndup(nm, nm + strlen(nm));
        set->spd[s].lambda_nm = l;
        set->spd[s].value = v;
        set->spd[s].name = name;
        set->spd[s].n = nlam;
        set->count = s + 1;
        if (!l || !v || !name) goto nomem;
        for (size_t i = 0; i < nlam; i++) {
            size_t k = key[i].k;
            l[i] = key[i].lambda;
            v[i] = val[s * ss + k * ks];
        }
        set->line[s] = lines ? lines[s] : lam_line_all;
    }
    free(key);
    *out = set;
    return LX_OK;
nomem:
    free(key);
    lx_spd_set_free(set);
    return lx__error(ctx, LX_ENOMEM, file, 0, "out of memory");
#undef LAMLINE
}

/* ---- text layouts ---- */

typedef struct cell {
    const char *s, *e;
} cell;

typedef struct cells {
    cell *c;
    size_t n, cap;
} cells;

static int cells_push(cells *cs, const char *s, const char *e)
{
    if (cs->n == cs->cap) {
        size_t cap = cs->cap ? 2 * cs->cap : 16;
        cell *c = realloc(cs->c, cap * sizeof *c);
        if (!c) return -1;
        cs->c = c;
        cs->cap = cap;
    }
    cs->c[cs->n].s = s;
    cs->c[cs->n].e = e;
    cs->n++;
    return 0;
}

/* The end of a line's content: before a '#' outside double quotes, trailing blanks trimmed. */
static const char *content_end(const char *s, const char *e)
{
    int inq = 0;
    const char *p = s;
    for (; p < e; p++) {
        if (*p == '"') inq = !inq;
        else if (*p == '#' && !inq) break;
    }
    while (p > s && is_blank(p[-1])) p--;
    return p;
}

/* Splits [s, e) into cells at sep (' ' means runs of blanks); trims blanks; strips one pair of
 * double quotes around a cell. */
static int split(const char *s, const char *e, char sep, cells *cs)
{
    cs->n = 0;
    const char *p = s;
    while (p < e && is_blank(*p)) p++;
    if (p >= e) return 0;
    for (;;) {
        while (p < e && is_blank(*p) && !(sep == '\t' && *p == '\t')) p++;
        const char *cs0 = p;
        int inq = 0;
        while (p < e) {
            if (*p == '"') inq = !inq;
            else if (!inq && (sep == ' ' ? is_blank(*p) : *p == sep)) break;
            p++;
        }
        const char *ce = p;
        while (ce > cs0 && is_blank(ce[-1]) && !(sep == '\t' && ce[-1] == '\t')) ce--;
        if (ce - cs0 >= 2 && *cs0 == '"' && ce[-1] == '"') {
            cs0++;
            ce--;
        }
        if (cells_push(cs, cs0, ce)) return -1;
        if (p >= e) break;
        p++; /* the separator */
        if (sep == ' ') {
            while (p < e && is_blank(*p)) p++;
            if (p >= e) break;
        }
    }
    return 0;
}

static char detect_sep(const char *s, const char *e)
{
    if (memchr(s, ';', (size_t)(e - s))) return ';';
    if (memchr(s, '\t', (size_t)(e - s))) return '\t';
    if (memchr(s, ',', (size_t)(e - s))) return ',';
    return ' ';
}

/* A growable array of doubles and one of longs. */
typedef struct dvec {
    double *v;
    size_t n, cap;
} dvec;
typedef struct lvec {
    long *v;
    size_t n, cap;
} lvec;

static int dvec_reserve(dvec *d, size_t more)
{
    if (d->n + more <= d->cap) return 0;
    size_t cap = d->cap ? d->cap : 256;
    while (cap < d->n + more) cap *= 2;
    double *v = realloc(d->v, cap * sizeof *v);
    if (!v) return -1;
    d->v = v;
    d->cap = cap;
    return 0;
}

static int lvec_push(lvec *l, long x)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        long *v = realloc(l->v, cap * sizeof *v);
        if (!v) return -1;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = x;
    return 0;
}

/* A rows-layout header: every cell after the first is a number, and they are not just the
 * default spectrum labels 1, 2, 3, ... of a columns-layout header. */
static int is_rows_header(const cells *h, char point)
{
    if (h->n < 3) return 0;
    int counting = 1;
    for (size_t i = 1; i < h->n; i++) {
        double d;
        const char *q = lx__parse_double_ex(h->c[i].s, h->c[i].e, point, &d);
        if (!q || q != h->c[i].e) return 0;
        if (d != (double)i) counting = 0;
    }
    return !counting;
}

static lx_status read_text(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_spd_set **out)
{
    lx_status st = LX_OK;
    lx__lines it = {text, text + len, 0};
    const char *s, *e;
    cells cs = {0}, hdr = {0};
    dvec data = {0};
    lvec rowline = {0};
    char **names = NULL;
    long *lines = NULL;
    size_t nnames = 0;
    char sep = 0, point = 0;
    long first_line = 0, header_line = 0;
    int header = 0, rows = 0;
    size_t ncols = 0;
    double *wl = NULL;

    while (lx__next_line(&it, &s, &e)) {
        e = content_end(s, e);
        const char *t = s;
        while (t < e && is_blank(*t)) t++;
        if (t >= e) continue;
        if (!sep) { /* the first line with content decides the separator and the layout */
            sep = detect_sep(t, e);
            point = sep == ',' ? 0 : ',';
            first_line = it.line;
            if (split(t, e, sep, &hdr)) goto nomem;
            double d;
            const char *q = lx__parse_double_ex(hdr.c[0].s, hdr.c[0].e, point, &d);
            header = !(q && q == hdr.c[0].e);
            ncols = hdr.n;
            if (header) {
                header_line = it.line;
                rows = is_rows_header(&hdr, point);
                if (rows) {
                    wl = malloc((ncols - 1) * sizeof *wl);
                    if (!wl) goto nomem;
                    for (size_t i = 1; i < ncols; i++) {
                        st = lx__parse_field(ctx, file, it.line, hdr.c[i].s, hdr.c[i].e, point,
                                             "wavelength", &wl[i - 1]);
                        if (st) goto done;
                        if (!(wl[i - 1] > 0)) {
                            st = lx__error(ctx, LX_EPARSE, file, it.line,
                                           "wavelength must be positive: %.17g nm", wl[i - 1]);
                            goto done;
                        }
                        if (i > 1 && !(wl[i - 1] > wl[i - 2])) {
                            st = lx__error(ctx, LX_EPARSE, file, it.line,
                                           "header wavelengths must increase: %.17g nm after %.17g nm "
                                           "(column %zu)", wl[i - 1], wl[i - 2], i + 1);
                            goto done;
                        }
                    }
                }
                if (ncols < 2) {
                    st = lx__error(ctx, LX_EPARSE, file, it.line,
                                   "header has 1 column; need a wavelength column and a value column");
                    goto done;
                }
                continue;
            }
            if (ncols < 2) {
                st = lx__error(ctx, LX_EPARSE, file, it.line,
                               "row has 1 field; need a wavelength and at least one value");
                goto done;
            }
        }
        if (split(t, e, sep, &cs)) goto nomem;
        if (cs.n != ncols) {
            st = lx__error(ctx, LX_EPARSE, file, it.line, "row has %zu fields, expected %zu (as on line %ld)",
                           cs.n, ncols, first_line);
            goto done;
        }
        if (dvec_reserve(&data, ncols) || lvec_push(&rowline, it.line)) goto nomem;
        double *row = data.v + data.n;
        if (rows) {
            row[0] = 0; /* the id cell is kept as the spectrum's name below */
        } else {
            if (cs.c[0].s == cs.c[0].e) {
                st = lx__error(ctx, LX_EPARSE, file, it.line, "empty wavelength field");
                goto done;
            }
            st = lx__parse_field(ctx, file, it.line, cs.c[0].s, cs.c[0].e, point, "wavelength", &row[0]);
            if (st) goto done;
            if (!(row[0] > 0)) {
                st = lx__error(ctx, LX_EPARSE, file, it.line, "wavelength must be positive: %.17g nm", row[0]);
                goto done;
            }
        }
        for (size_t c = 1; c < ncols; c++) {
            if (cs.c[c].s == cs.c[c].e) {
                if (rows) {
                    st = lx__error(ctx, LX_EPARSE, file, it.line, "empty value in column %zu", c + 1);
                    goto done;
                }
                row[c] = NAN; /* checked per column below */
                continue;
            }
            st = lx__parse_field(ctx, file, it.line, cs.c[c].s, cs.c[c].e, point, "value", &row[c]);
            if (st) goto done;
        }
        if (rows) { /* keep the row's name */
            char **nn = realloc(names, (nnames + 1) * sizeof *nn);
            if (!nn) goto nomem;
            names = nn;
            names[nnames] = lx__strndup(cs.c[0].s, cs.c[0].e);
            if (!names[nnames]) goto nomem;
            nnames++;
        }
        data.n += ncols;
    }

    size_t nrows = ncols ? data.n / ncols : 0;
    if (!sep) {
        st = lx__error(ctx, LX_EPARSE, file, it.line ? it.line : 1,
                       len ? "no data: only blank or comment lines" : "empty file");
        goto done;
    }
    if (nrows == 0) {
        st = lx__error(ctx, LX_EPARSE, file, header_line, "header but no data rows");
        goto done;
    }
    if (rows) {
        st = lx__spd_set_build(ctx, file, ncols - 1, wl, 1, NULL, header_line, nrows, data.v + 1, ncols, 1,
                               names, rowline.v, out);
        goto done;
    }
    if (nrows < 2) {
        st = lx__error(ctx, LX_EPARSE, file, rowline.v[0], "only 1 data row; a spectrum needs at least 2");
        goto done;
    }
    /* columns layout: every value column must be complete */
    for (size_t c = 1; c < ncols; c++) {
        size_t nempty = 0, first = 0;
        for (size_t r = 0; r < nrows; r++) {
            if (isnan(data.v[r * ncols + c])) {
                if (!nempty) first = r;
                nempty++;
            }
        }
        if (nempty == nrows) {
            st = lx__error(ctx, LX_EPARSE, file, header ? header_line : first_line,
                           "column %zu%s%.*s%s is empty", c + 1, header ? " ('" : "",
                           header ? (int)(hdr.c[c].e - hdr.c[c].s) : 0, header ? hdr.c[c].s : "",
                           header ? "')" : "");
            goto done;
        }
        if (nempty) {
            st = lx__error(ctx, LX_EPARSE, file, rowline.v[first], "empty value in column %zu", c + 1);
            goto done;
        }
    }
    names = calloc(ncols - 1, sizeof *names);
    lines = malloc((ncols - 1) * sizeof *lines);
    if (!names || !lines) goto nomem;
    nnames = ncols - 1;
    for (size_t c = 1; c < ncols; c++) {
        lines[c - 1] = header ? header_line : first_line;
        if (header && hdr.c[c].e > hdr.c[c].s) {
            names[c - 1] = lx__strndup(hdr.c[c].s, hdr.c[c].e);
            if (!names[c - 1]) goto nomem;
        }
    }
    st = lx__spd_set_build(ctx, file, nrows, data.v, ncols, rowline.v, 0, ncols - 1, data.v + 1, 1, ncols,
                           names, lines, out);
    goto done;
nomem:
    st = lx__error(ctx, LX_ENOMEM, file, 0, "out of memory");
done:
    for (size_t i = 0; i < nnames; i++) free(names[i]);
    free(names);
    free(lines);
    free(cs.c);
    free(hdr.c);
    free(data.v);
    free(rowline.v);
    free(wl);
    return st;
}

/* ---- entry points ---- */

lx_status lx_spd_read_mem(lx_ctx *ctx, const char *name, const char *text, size_t len, lx_spd_set **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!out || (!text && len)) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spd_read_mem: NULL argument");
    const char *file = name ? name : "(memory)";
    if (len >= 2 && ((unsigned char)text[0] == 0xFF && (unsigned char)text[1] == 0xFE))
        return lx__error(ctx, LX_EPARSE, file, 1, "UTF-16 text is not supported; save the file as UTF-8");
    if (len >= 2 && ((unsigned char)text[0] == 0xFE && (unsigned char)text[1] == 0xFF))
        return lx__error(ctx, LX_EPARSE, file, 1, "UTF-16 text is not supported; save the file as UTF-8");
    const char *nul = len ? memchr(text, '\0', len) : NULL;
    if (nul) {
        long line = 1;
        for (const char *p = text; p < nul; p++) line += *p == '\n';
        return lx__error(ctx, LX_EPARSE, file, line, "binary data (NUL byte at offset %zu); not a text file",
                         (size_t)(nul - text));
    }
    if (len >= 3 && (unsigned char)text[0] == 0xEF && (unsigned char)text[1] == 0xBB &&
        (unsigned char)text[2] == 0xBF) {
        text += 3;
        len -= 3;
    }
    if (lx__cgats_detect(text, len)) return lx__cgats_read(ctx, file, text, len, out);
    return read_text(ctx, file, text, len, out);
}

lx_status lx_spd_read_file(lx_ctx *ctx, const char *path, lx_spd_set **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spd_read_file: NULL argument");
    char *buf;
    size_t len;
    lx_status st = lx__read_all(ctx, path, LX_INPUT_SPECTRUM, &buf, &len);
    if (st != LX_OK) return st;
    st = lx_spd_read_mem(ctx, path, buf, len, out);
    free(buf);
    return st;
}

lx_status lx_spd_read_stream(lx_ctx *ctx, const char *name, FILE *in, const char *prefix, size_t prefix_len,
                             lx_spd_set **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!in || !out || (!prefix && prefix_len)) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spd_read_stream: NULL argument");
    const char *file = name ? name : "(stream)";
    char *buf;
    size_t len;
    lx_status st = lx__read_stream(ctx, file, LX_INPUT_SPECTRUM, in, prefix, prefix_len, &buf, &len);
    if (st != LX_OK) return st;
    st = lx_spd_read_mem(ctx, file, buf, len, out);
    free(buf);
    return st;
}
