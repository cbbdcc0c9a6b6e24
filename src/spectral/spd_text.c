/* spd_text.c - delimited text spectra: the columns layout (wavelength, value...) and the rows layout
 * (a header of wavelengths, one spectrum per row), as hand-made files, Excel and AvaSoft write them:
 * a preamble of header fields or a title above the header, a units line under it, trailing empty
 * columns and rows, quoted numbers, '#' comments only where they cannot be part of a name. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

typedef struct cell {
    const char *s, *e;
    int quoted; /* the cell was one "quoted" string (quotes stripped): never a comment */
} cell;

typedef struct cells {
    cell *c;
    size_t n, cap;
} cells;

static int cells_push(cells *cs, const char *s, const char *e, int quoted)
{
    if (cs->n == cs->cap) {
        size_t cap = cs->cap ? 2 * cs->cap : 16;
        cell *c = lx__realloc_n(cs->c, cap, sizeof *c);
        if (!c) return -1;
        cs->c = c;
        cs->cap = cap;
    }
    cs->c[cs->n].s = s;
    cs->c[cs->n].e = e;
    cs->c[cs->n].quoted = quoted;
    cs->n++;
    return 0;
}

/* Splits [s, e) into cells at sep (' ' means runs of blanks); trims blanks; strips one pair of
 * double quotes around a cell. A separator inside quotes belongs to the cell. */
static int split(const char *s, const char *e, char sep, cells *cs)
{
    cs->n = 0;
    const char *p = s;
    while (p < e && is_blank(*p)) p++;
    if (p >= e) return 0;
    for (;;) {
        while (p < e && is_blank(*p) && !(sep == '\t' && *p == '\t')) p++;
        const char *cs0 = p;
        if (p < e && *p == '"') { /* a quoted cell followed by '#': the rest of the line is a comment */
            const char *q = memchr(p + 1, '"', (size_t)(e - p - 1));
            const char *r = q ? q + 1 : e;
            while (r < e && is_blank(*r)) r++;
            if (q && r < e && *r == '#') return cells_push(cs, p + 1, q, 1);
        }
        int inq = 0;
        while (p < e) {
            if (*p == '"') inq = !inq;
            else if (!inq && (sep == ' ' ? is_blank(*p) : *p == sep)) break;
            p++;
        }
        const char *ce = p;
        while (ce > cs0 && is_blank(ce[-1]) && !(sep == '\t' && ce[-1] == '\t')) ce--;
        int quoted = 0;
        if (ce - cs0 >= 2 && *cs0 == '"' && ce[-1] == '"') {
            cs0++;
            ce--;
            quoted = 1;
        }
        if (cells_push(cs, cs0, ce, quoted)) return -1;
        if (p >= e) break;
        p++; /* the separator */
        if (sep == ' ') {
            while (p < e && is_blank(*p)) p++;
            if (p >= e) break;
        }
    }
    return 0;
}

/* The separator of a line: ';' if present, else tab, else ',', else runs of blanks (outside quotes). */
static char detect_sep(const char *s, const char *e)
{
    int semi = 0, tab = 0, comma = 0, inq = 0;
    for (const char *p = s; p < e; p++) {
        if (*p == '"') inq = !inq;
        else if (!inq) semi |= *p == ';', tab |= *p == '\t', comma |= *p == ',';
    }
    return semi ? ';' : tab ? '\t' : comma ? ',' : ' ';
}

/* A number in a cell: with any separator but ',' a decimal comma is read too; a quoted cell of a
 * comma-separated file may hold one ("0,5"). */
static char point_of(const cell *c, char sep) { return sep != ',' || c->quoted ? ',' : 0; }

static int cell_is_number(const cell *c, char sep)
{
    double d;
    const char *q = lx__parse_double_ex(c->s, c->e, point_of(c, sep), &d);
    return q && q == c->e;
}

/* '#' in a numeric field starts a comment when it opens the field or follows a blank: the rest of
 * the line is dropped (a field the comment empties too). Names and quoted cells are never cut. */
static void cut_comment(cells *cs, size_t first_numeric)
{
    for (size_t i = first_numeric; i < cs->n; i++) {
        cell *c = &cs->c[i];
        if (c->quoted) continue;
        for (const char *p = c->s; p < c->e; p++) {
            if (*p != '#' || (p > c->s && !is_blank(p[-1]))) continue;
            const char *q = p;
            while (q > c->s && is_blank(q[-1])) q--;
            c->e = q;
            cs->n = q == c->s ? i : i + 1;
            return;
        }
    }
}

static size_t trimmed_count(const cells *cs)
{
    size_t n = cs->n;
    while (n > 0 && cs->c[n - 1].s == cs->c[n - 1].e) n--;
    return n;
}

/* A line of blanks and separators only (the empty rows Excel leaves) or a comment line. */
static int is_empty_line(const char *s, const char *e)
{
    const char *p = s;
    while (p < e && (is_blank(*p) || *p == ',' || *p == ';')) p++;
    return p >= e || *p == '#';
}

/* A rows-layout header: every cell after the first is a number, and they are not just the
 * default spectrum labels 1, 2, 3, ... of a columns-layout header. */
static int is_rows_header(const cells *h, size_t n, char sep)
{
    if (n < 3) return 0;
    int counting = 1;
    for (size_t i = 1; i < n; i++) {
        double d;
        const char *q = lx__parse_double_ex(h->c[i].s, h->c[i].e, point_of(&h->c[i], sep), &d);
        if (!q || q != h->c[i].e) return 0;
        if (d != (double)i) counting = 0;
    }
    return !counting && !cell_is_number(&h->c[0], sep);
}

/* A units line under a header: every non-empty cell is "[...]" or "(...)" (AvaSoft: "[nm] ;[counts]"). */
static int is_units_line(const cells *cs)
{
    size_t n = trimmed_count(cs), k = 0;
    for (size_t i = 0; i < n; i++) {
        const cell *c = &cs->c[i];
        if (c->s == c->e) continue;
        if (!((*c->s == '[' && c->e[-1] == ']') || (*c->s == '(' && c->e[-1] == ')'))) return 0;
        k++;
    }
    return k >= 2;
}

/* A preamble line as a header field: "Key-->,value" (AvaSoft), else split at the first ':', tab,
 * ',' or ';', else the whole line as the key. */
static int preamble_field(lx__rd *rd, const char *s, const char *e, long line, int *avasoft)
{
    const char *arrow = NULL;
    for (const char *p = s; p + 3 <= e; p++)
        if (p[0] == '-' && p[1] == '-' && p[2] == '>') {
            arrow = p;
            break;
        }
    if (arrow) {
        const char *v = arrow + 3;
        if (v < e && (*v == ',' || *v == ';' || *v == '\t')) v++;
        *avasoft = 1;
        return lx__rd_field(rd, line, s, arrow, v, e);
    }
    for (const char *p = s; p < e; p++)
        if (*p == ':' || *p == '\t' || *p == ',' || *p == ';') return lx__rd_field(rd, line, s, p, p + 1, e);
    return lx__rd_field(rd, line, s, e, NULL, NULL);
}

/* AvaSoft's "Mode/Unit-->,Irradiance[µWatt/cm²]" (its code page turns µ and ² into '?'). */
static void avasoft_unit(lx__rd *rd)
{
    for (size_t i = 0; i < rd->nfields; i++) {
        const char *k = rd->fields[i].key, *v = rd->fields[i].value;
        if (strcmp(k, "Mode/Unit") != 0 || !lx__starts_ci(v, v + strlen(v), "irradiance")) continue;
        const char *w = strstr(v, "Watt/cm");
        if (w && w > v && (w[-1] == '?' || w[-1] == 'u' || (unsigned char)w[-1] == 0xB5)) {
            rd->unit = "W/m2/nm";
            rd->unit_scale = 0.01;
            rd->unit_source = "AvaSoft Mode/Unit: irradiance in uW/cm2/nm";
        }
    }
}

/* Columns given by --columns: names of header cells or 1-based numbers; col[0] the wavelength. */
static lx_status select_columns(lx__rd *rd, const cells *hdr, size_t hn, size_t ncols, long hline,
                                size_t **col, size_t *ncol)
{
    const char *p = rd->opts.columns;
    size_t cap = 8, n = 0;
    size_t *c = lx__alloc_n(cap, sizeof *c);
    if (!c) return lx__rd_nomem(rd);
    while (*p) {
        const char *q = strchr(p, ',');
        const char *e = q ? q : p + strlen(p);
        const char *s = p;
        while (s < e && is_blank(*s)) s++;
        while (e > s && is_blank(e[-1])) e--;
        size_t idx = 0;
        char *end;
        long v = strtol(s, &end, 10);
        if (s < e && end == e && v >= 1) {
            idx = (size_t)v;
        } else {
            for (size_t i = 0; hdr && i < hn && !idx; i++)
                if ((size_t)(hdr->c[i].e - hdr->c[i].s) == (size_t)(e - s) && !memcmp(hdr->c[i].s, s, (size_t)(e - s)))
                    idx = i + 1;
        }
        if (!idx || idx > ncols) {
            lx__free(c);
            if (!idx && !hdr)
                return lx__error(rd->ctx, LX_EINVAL, rd->file, 0, "--columns: '%.*s': the file has no header to name "
                                 "columns; give their numbers", (int)(e - s), s);
            return lx__error(rd->ctx, LX_EINVAL, rd->file, hline, "--columns: no column '%.*s' (the file has %zu)",
                             (int)(e - s), s, ncols);
        }
        if (n == cap) {
            size_t *c2 = lx__realloc_n(c, cap *= 2, sizeof *c);
            if (!c2) return lx__free(c), lx__rd_nomem(rd);
            c = c2;
        }
        c[n++] = idx - 1;
        p = q ? q + 1 : e + strlen(e);
    }
    if (n < 2) {
        lx__free(c);
        return lx__error(rd->ctx, LX_EINVAL, rd->file, 0, "--columns needs a wavelength column and at least one "
                         "value column (WL,VALUE[,...]), not '%s'", rd->opts.columns);
    }
    *col = c;
    *ncol = n;
    return LX_OK;
}

typedef struct tline {
    const char *s, *e;
    long line;
} tline;

/* the parsed table: nrows rows of nv values (columns layout: the wavelength first) */
typedef struct table {
    double *v;
    long *line;
    char **name; /* rows layout: the rows' names */
    size_t n, cap, nv;
} table;

static int table_row(table *t, long line, double **row)
{
    if (t->n == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 256;
        double *v = lx__realloc_n(t->v, cap * t->nv, sizeof *v);
        if (v) t->v = v;
        long *l = lx__realloc_n(t->line, cap, sizeof *l);
        if (l) t->line = l;
        char **nm = lx__realloc_n(t->name, cap, sizeof *nm);
        if (nm) t->name = nm;
        if (!v || !l || !nm) return -1;
        t->cap = cap;
    }
    t->line[t->n] = line;
    t->name[t->n] = NULL;
    *row = t->v + t->n * t->nv;
    return 0;
}

typedef struct sort_ix {
    double l;
    size_t r;
} sort_ix;

static int cmp_ix(const void *a, const void *b)
{
    const sort_ix *x = a, *y = b;
    return x->l < y->l ? -1 : x->l > y->l ? 1 : x->r < y->r ? -1 : x->r > y->r;
}

/* With skip_bad_rows: the later of two rows with one wavelength is a bad row. */
static lx_status drop_duplicates(lx__rd *rd, table *t)
{
    sort_ix *ix = lx__alloc_n(t->n ? t->n : 1, sizeof *ix);
    unsigned char *drop = lx__calloc(t->n ? t->n : 1, 1);
    if (!ix || !drop) return lx__free(ix), lx__free(drop), lx__rd_nomem(rd);
    for (size_t r = 0; r < t->n; r++) ix[r].l = t->v[r * t->nv], ix[r].r = r;
    qsort(ix, t->n, sizeof *ix, cmp_ix);
    lx_status st = LX_OK;
    for (size_t k = 1; k < t->n && st == LX_OK; k++) {
        if (ix[k].l != ix[k - 1].l) continue;
        size_t first = k - 1;
        while (first > 0 && drop[ix[first].r]) first--;
        drop[ix[k].r] = 1;
        st = lx__rd_bad_row(rd, t->line[ix[k].r], "duplicate wavelength %.17g nm (first on line %ld)", ix[k].l,
                            t->line[ix[first].r]);
    }
    size_t w = 0;
    for (size_t r = 0; r < t->n; r++) {
        if (drop[r]) continue;
        memmove(t->v + w * t->nv, t->v + r * t->nv, t->nv * sizeof *t->v);
        t->line[w] = t->line[r];
        w++;
    }
    t->n = w;
    lx__free(ix);
    lx__free(drop);
    return st;
}

/* One data line of the columns layout into t (or a bad row): col[0] the wavelength, col[1..] values. */
static lx_status columns_row(lx__rd *rd, table *t, cells *cs, char sep, const size_t *col, size_t ncol,
                             size_t ncols, size_t nmin, long line, long first_line, int selected)
{
    if (!selected && (cs->n < nmin || cs->n > ncols))
        return lx__rd_bad_row(rd, line, "row has %zu field%s, expected %zu (as on line %ld)", cs->n,
                              cs->n == 1 ? "" : "s", ncols, first_line);
    size_t need = 0;
    for (size_t k = 0; k < ncol; k++)
        if (col[k] + 1 > need) need = col[k] + 1;
    if (selected && cs->n < need)
        return lx__rd_bad_row(rd, line, "row has %zu fields; --columns needs %zu", cs->n, need);
    double *row;
    if (table_row(t, line, &row)) return lx__rd_nomem(rd);
    for (size_t k = 0; k < ncol; k++) {
        const cell *c = col[k] < cs->n ? &cs->c[col[k]] : NULL;
        if (!c || c->s == c->e) {
            if (k == 0) return lx__rd_bad_row(rd, line, "empty wavelength field");
            row[k] = NAN; /* checked per column once every row is in */
            continue;
        }
        lx_status st = lx__parse_field(rd->ctx, rd->file, line, c->s, c->e, point_of(c, sep),
                                       k == 0 ? "wavelength" : "value", &row[k]);
        if (st) return lx__rd_bad_field(rd, line, st);
        if (k == 0 && !(row[0] > 0))
            return lx__rd_bad_row(rd, line, "wavelength must be positive: %.17g nm", row[0]);
    }
    t->n++;
    return LX_OK;
}

static lx_status rows_row(lx__rd *rd, table *t, cells *cs, char sep, size_t ncols, long line, long first_line)
{
    if (cs->n != ncols)
        return lx__rd_bad_row(rd, line, "row has %zu field%s, expected %zu (as on line %ld)", cs->n,
                              cs->n == 1 ? "" : "s", ncols, first_line);
    double *row;
    if (table_row(t, line, &row)) return lx__rd_nomem(rd);
    for (size_t c = 1; c < ncols; c++) {
        if (cs->c[c].s == cs->c[c].e) return lx__rd_bad_row(rd, line, "empty value in column %zu", c + 1);
        lx_status st = lx__parse_field(rd->ctx, rd->file, line, cs->c[c].s, cs->c[c].e, point_of(&cs->c[c], sep),
                                       "value", &row[c - 1]);
        if (st) return lx__rd_bad_field(rd, line, st);
    }
    t->name[t->n] = lx__strndup(cs->c[0].s, cs->c[0].e);
    if (!t->name[t->n]) return lx__rd_nomem(rd);
    t->n++;
    return LX_OK;
}

typedef struct layout {
    int rows;
    size_t header, units, data; /* indexes into the content lines; header/units = nl when absent */
    char sep;
} layout;

/* Where the header and the data start: the first rows-layout header, or the first line whose
 * first cell is a number (the data), with the header (and a units line) just above it; lines
 * above are the preamble. Returns 0, or -1 when neither is found. */
static int find_layout(const tline *L, size_t nl, int want, cells *cs, layout *out)
{
    for (size_t i = 0; i < nl; i++) {
        char sep = detect_sep(L[i].s, L[i].e);
        if (split(L[i].s, L[i].e, sep, cs)) return -2;
        size_t n = trimmed_count(cs);
        if (want != 1 && is_rows_header(cs, n, sep)) {
            *out = (layout){1, i, nl, i + 1, sep};
            return 0;
        }
        if (want != 2 && n >= 1 && cell_is_number(&cs->c[0], sep)) {
            *out = (layout){0, nl, nl, i, sep};
            if (i >= 1) {
                size_t h = i - 1;
                if (split(L[h].s, L[h].e, sep, cs)) return -2;
                if (is_units_line(cs) && i >= 2) {
                    out->units = h--;
                    if (split(L[h].s, L[h].e, sep, cs)) return -2;
                }
                if (trimmed_count(cs) >= 2) out->header = h;
                else out->units = nl; /* a units line needs its header */
            }
            return 0;
        }
    }
    return -1;
}

static lx_status read_lines(lx__rd *rd, const char *text, size_t len, tline **out, size_t *nl, long *last)
{
    lx__lines it = {text, text + len, rd->line0};
    const char *s, *e;
    size_t cap = 0, n = 0;
    tline *L = NULL;
    while (lx__next_line(&it, &s, &e)) {
        if (is_empty_line(s, e)) continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 256;
            tline *L2 = lx__realloc_n(L, cap, sizeof *L);
            if (!L2) return lx__free(L), lx__rd_nomem(rd);
            L = L2;
        }
        L[n++] = (tline){s, e, it.line};
    }
    *out = L;
    *nl = n;
    *last = it.line;
    return LX_OK;
}

/* The parsed columns of the columns layout into a set: every value column complete; trailing
 * columns with no name and no value (Excel's padding) dropped. */
static lx_status columns_set(lx__rd *rd, table *t, const cells *hdr, size_t hn, long hline, const size_t *col,
                             size_t ncol, lx_spd_set **out)
{
    if (!hdr || hline <= 0) hline = t->n ? t->line[0] : 1; /* no header: errors name the first data row */
    size_t keep = ncol;
    while (keep > 2) { /* Excel pads rows to the widest: unnamed, empty last columns */
        size_t k = keep - 1;
        int named = hdr && col[k] < hn && hdr->c[col[k]].s != hdr->c[col[k]].e, any = 0;
        for (size_t r = 0; r < t->n && !any; r++) any = !isnan(t->v[r * t->nv + k]);
        if (named || any) break;
        keep--;
    }
    for (size_t k = 1; k < keep; k++) {
        size_t nempty = 0, first = 0;
        for (size_t r = 0; r < t->n; r++)
            if (isnan(t->v[r * t->nv + k]) && !nempty++) first = r;
        if (nempty == t->n) {
            const cell *h = hdr && col[k] < hn ? &hdr->c[col[k]] : NULL;
            return lx__error(rd->ctx, LX_EPARSE, rd->file, hline, "column %zu%s%.*s%s is empty", col[k] + 1,
                             h ? " ('" : "", h ? (int)(h->e - h->s) : 0, h ? h->s : "", h ? "')" : "");
        }
        if (nempty && !rd->opts.skip_bad_rows)
            return lx__error(rd->ctx, LX_EPARSE, rd->file, t->line[first], "empty value in column %zu", col[k] + 1);
    }
    if (rd->opts.skip_bad_rows) { /* rows with an empty value are bad rows */
        size_t w = 0;
        for (size_t r = 0; r < t->n; r++) {
            size_t bad = 0;
            for (size_t k = 1; k < keep && !bad; k++)
                if (isnan(t->v[r * t->nv + k])) bad = k;
            if (bad) {
                lx_status st = lx__rd_bad_row(rd, t->line[r], "empty value in column %zu", col[bad] + 1);
                if (st) return st;
                continue;
            }
            memmove(t->v + w * t->nv, t->v + r * t->nv, t->nv * sizeof *t->v);
            t->line[w++] = t->line[r];
        }
        t->n = w;
        lx_status st = drop_duplicates(rd, t);
        if (st) return st;
    }
    if (t->n < 2)
        return lx__error(rd->ctx, LX_EPARSE, rd->file, t->n ? t->line[0] : hline,
                         "only %zu data row%s; a spectrum needs at least 2", t->n, t->n == 1 ? "" : "s");
    size_t nspec = keep - 1;
    char **names = lx__calloc(nspec, sizeof *names);
    long *lines = lx__alloc_n(nspec, sizeof *lines);
    lx_status st = LX_OK;
    if (!names || !lines) st = lx__rd_nomem(rd);
    for (size_t k = 0; st == LX_OK && k < nspec; k++) {
        lines[k] = hdr ? hline : t->line[0];
        const cell *h = hdr && col[k + 1] < hn ? &hdr->c[col[k + 1]] : NULL;
        if (h && h->e > h->s && !(names[k] = lx__strndup(h->s, h->e))) st = lx__rd_nomem(rd);
    }
    if (st == LX_OK)
        st = lx__spd_set_build(rd->ctx, rd->file, t->n, t->v, t->nv, t->line, 0, nspec, t->v + 1, 1, t->nv, names,
                               lines, out);
    for (size_t k = 0; names && k < nspec; k++) lx__free(names[k]);
    lx__free(names);
    lx__free(lines);
    return st;
}

/* What the reader knows once the layout is found; the working buffers of both layouts. */
typedef struct parse {
    lx__rd *rd;
    const tline *L;
    size_t nl;
    layout ly;
    cells cs, hdr;
    size_t hn;         /* header cells (0 without a header) */
    long hline;        /* the header's line (0 without one) */
    long first_line;   /* the header's line, else the first data line's */
    table t;
    size_t *col, ncol; /* the columns read (columns layout) */
    double *wl;        /* the header's wavelengths (rows layout) */
} parse;

/* The rows layout: the header's wavelengths, one spectrum per data line. */
static lx_status rows_layout(parse *P, lx_spd_set **out)
{
    lx__rd *rd = P->rd;
    if (rd->opts.columns)
        return lx__error(rd->ctx, LX_EINVAL, rd->file, P->hline, "--columns applies to the columns layout (one "
                         "wavelength column), not to this rows layout");
    size_t ncols = trimmed_count(&P->hdr);
    if (!(P->wl = lx__alloc_n(ncols > 1 ? ncols - 1 : 1, sizeof *P->wl))) return lx__rd_nomem(rd);
    for (size_t i = 1; i < ncols; i++) {
        const cell *h = &P->hdr.c[i];
        double *w = &P->wl[i - 1];
        lx_status st = lx__parse_field(rd->ctx, rd->file, P->hline, h->s, h->e, point_of(h, P->ly.sep), "wavelength", w);
        if (st) return st;
        if (!(*w > 0))
            return lx__error(rd->ctx, LX_EPARSE, rd->file, P->hline, "wavelength must be positive: %.17g nm", *w);
        if (i > 1 && !(*w > w[-1]))
            return lx__error(rd->ctx, LX_EPARSE, rd->file, P->hline,
                             "header wavelengths must increase: %.17g nm after %.17g nm (column %zu)", *w, w[-1], i + 1);
    }
    double k = lx__wl_unit_word(P->hdr.c[0].s, P->hdr.c[0].e);
    if (k > 0) rd->wl_scale = k, rd->wl_source = "the header's first cell";
    P->t.nv = ncols - 1;
    for (size_t i = P->ly.data; i < P->nl; i++) {
        cells *cs = &P->cs;
        if (split(P->L[i].s, P->L[i].e, P->ly.sep, cs)) return lx__rd_nomem(rd);
        cut_comment(cs, 1);
        while (cs->n > ncols && cs->c[cs->n - 1].s == cs->c[cs->n - 1].e) cs->n--;
        if (trimmed_count(cs) == 0) continue;
        lx_status st = rows_row(rd, &P->t, cs, P->ly.sep, ncols, P->L[i].line, P->first_line);
        if (st) return st;
    }
    if (P->t.n == 0)
        return lx__error(rd->ctx, LX_EPARSE, rd->file, P->hline, rd->nskipped ? "no good data rows" : "header but no data rows");
    return lx__spd_set_build(rd->ctx, rd->file, ncols - 1, P->wl, 1, NULL, P->hline, P->t.n, P->t.v, P->t.nv, 1,
                             P->t.name, P->t.line, out);
}

/* The columns layout: a wavelength column and value columns (all of them, or --columns). */
static lx_status columns_layout(parse *P, lx_spd_set **out)
{
    lx__rd *rd = P->rd;
    const layout *ly = &P->ly;
    int has_hdr = ly->header < P->nl;
    if (split(P->L[ly->data].s, P->L[ly->data].e, ly->sep, &P->cs)) return lx__rd_nomem(rd);
    cut_comment(&P->cs, 0);
    size_t ncols = has_hdr ? P->hn : P->cs.n, nmin = has_hdr ? trimmed_count(&P->hdr) : trimmed_count(&P->cs);
    if (!has_hdr && nmin < 2)
        return lx__error(rd->ctx, LX_EPARSE, rd->file, P->L[ly->data].line,
                         "row has 1 field; need a wavelength and at least one value");
    if (nmin < 2) nmin = 2;
    if (rd->opts.columns) {
        lx_status st = select_columns(rd, has_hdr ? &P->hdr : NULL, P->hn, ncols, P->hline, &P->col, &P->ncol);
        if (st) return st;
    } else {
        if (!(P->col = lx__alloc_n(ncols, sizeof *P->col))) return lx__rd_nomem(rd);
        for (size_t k = 0; k < ncols; k++) P->col[k] = k;
        P->ncol = ncols;
    }
    /* the wavelength unit: the units line's cell of the wavelength column, else its header cell */
    double k = 0;
    if (ly->units < P->nl) {
        if (split(P->L[ly->units].s, P->L[ly->units].e, ly->sep, &P->cs)) return lx__rd_nomem(rd);
        if (P->col[0] < P->cs.n) k = lx__wl_unit_word(P->cs.c[P->col[0]].s, P->cs.c[P->col[0]].e);
    } else if (has_hdr && P->col[0] < P->hn) {
        k = lx__wl_unit_word(P->hdr.c[P->col[0]].s, P->hdr.c[P->col[0]].e);
    }
    if (k > 0) rd->wl_scale = k, rd->wl_source = "the wavelength column's header";
    P->t.nv = P->ncol;
    for (size_t i = ly->data; i < P->nl; i++) {
        cells *cs = &P->cs;
        if (split(P->L[i].s, P->L[i].e, ly->sep, cs)) return lx__rd_nomem(rd);
        cut_comment(cs, 0);
        while (cs->n > ncols && cs->c[cs->n - 1].s == cs->c[cs->n - 1].e) cs->n--;
        if (trimmed_count(cs) == 0) continue;
        lx_status st = columns_row(rd, &P->t, cs, ly->sep, P->col, P->ncol, ncols, nmin, P->L[i].line, P->first_line,
                                   rd->opts.columns != NULL);
        if (st) return st;
    }
    if (P->t.n == 0)
        return lx__error(rd->ctx, LX_EPARSE, rd->file, P->first_line, rd->nskipped ? "no good data rows" : "header but no data rows");
    return columns_set(rd, &P->t, has_hdr ? &P->hdr : NULL, P->hn, P->hline, P->col, P->ncol, out);
}

/* The preamble above the header (header fields, a title) and what it says about the layout. */
static lx_status preamble(parse *P)
{
    lx__rd *rd = P->rd;
    const layout *ly = &P->ly;
    int avasoft = 0;
    size_t top = ly->header < P->nl ? ly->header : ly->data;
    for (size_t i = 0; i < top; i++)
        if (preamble_field(rd, P->L[i].s, P->L[i].e, P->L[i].line, &avasoft)) return lx__rd_nomem(rd);
    static const char units_key[] = "units";
    if (ly->units < P->nl &&
        lx__rd_field(rd, P->L[ly->units].line, units_key, units_key + 5, P->L[ly->units].s, P->L[ly->units].e))
        return lx__rd_nomem(rd);
    if (ly->header < P->nl) {
        P->hline = P->L[ly->header].line;
        if (split(P->L[ly->header].s, P->L[ly->header].e, ly->sep, &P->hdr)) return lx__rd_nomem(rd);
        P->hn = P->hdr.n;
    }
    P->first_line = ly->header < P->nl ? P->hline : P->L[ly->data].line;
    if (!rd->format)
        rd->format = ly->rows ? "rows" : avasoft || (ly->units < P->nl && lx__starts_ci(P->hdr.c[0].s, P->hdr.c[0].e, "wave"))
                                           ? "avantes" : "columns";
    if (avasoft) avasoft_unit(rd);
    return LX_OK;
}

lx_status lx__text_read(lx__rd *rd, const char *text, size_t len, int want, lx_spd_set **out)
{
    parse P;
    memset(&P, 0, sizeof P);
    P.rd = rd;
    tline *L = NULL;
    long last = 0;
    lx_status st = read_lines(rd, text, len, &L, &P.nl, &last);
    if (st) return st;
    P.L = L;
    int found = P.nl ? find_layout(L, P.nl, want, &P.cs, &P.ly) : -1;
    if (P.nl == 0)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, last ? last : 1, len ? "no data: only blank or comment lines" : "empty file");
    else if (found == -2)
        st = lx__rd_nomem(rd);
    else if (found < 0)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, L[P.nl - 1].line, want == 2 ? "no rows-layout header "
                       "(a name cell, then the wavelengths)" : "header but no data rows");
    if (st == LX_OK) st = preamble(&P);
    if (st == LX_OK) st = P.ly.rows ? rows_layout(&P, out) : columns_layout(&P, out);
    for (size_t r = 0; P.t.name && r < P.t.n; r++) lx__free(P.t.name[r]);
    lx__free(P.t.name);
    lx__free(P.t.v);
    lx__free(P.t.line);
    lx__free(P.cs.c);
    lx__free(P.hdr.c);
    lx__free(P.col);
    lx__free(P.wl);
    lx__free(L);
    return st;
}
