/* spd_tm27.c - IES TM-27 spectral data documents (.spdx, XML): <Header> fields, one spectrum per
 * <SpectralDistribution> from its <SpectralData wavelength="...">value</SpectralData> elements,
 * matched by local name (any namespace prefix). A small XML scanner: elements, attributes,
 * comments, processing instructions, CDATA and the five entities plus character references. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

int lx__tm27_detect(const char *text, size_t len)
{
    size_t n = len < 4096 ? len : 4096;
    size_t i = 0;
    while (i < n && is_space(text[i])) i++;
    if (i >= n || text[i] != '<') return 0;
    for (size_t k = i; k + 9 <= n; k++)
        if (!memcmp(text + k, "IESTM2714", 9) || (k + 13 <= n && !memcmp(text + k, "<SpectralData", 13))) return 1;
    return 0;
}

typedef struct xml {
    lx__rd *rd;
    const char *p, *end, *lstart; /* lstart: where p's line was counted to */
    long line;
} xml;

static long line_at(xml *x, const char *q)
{
    for (; x->lstart < q; x->lstart++) x->line += *x->lstart == '\n';
    return x->line;
}

/* The local name of a qualified name [s, e): after the last ':' */
static const char *local(const char *s, const char *e)
{
    for (const char *p = e; p > s; p--)
        if (p[-1] == ':') return p;
    return s;
}

static int name_is(const char *s, const char *e, const char *w)
{
    s = local(s, e);
    return (size_t)(e - s) == strlen(w) && !memcmp(s, w, (size_t)(e - s));
}

/* Decodes the text [s, e) (entities, CDATA, trimmed) into a new string; NULL when out of memory.
 * *bad is set to an unknown entity. */
static char *decode(const char *s, const char *e, int *bad)
{
    char *out = lx__alloc((size_t)(e - s) + 1), *o = out;
    if (!out) return NULL;
    while (s < e) {
        if (e - s >= 9 && !memcmp(s, "<![CDATA[", 9)) {
            const char *c = s + 9, *q = c;
            while (q + 3 <= e && memcmp(q, "]]>", 3)) q++;
            memcpy(o, c, (size_t)(q - c));
            o += q - c;
            s = q + 3 <= e ? q + 3 : e;
            continue;
        }
        if (*s != '&') {
            *o++ = *s++;
            continue;
        }
        const char *semi = memchr(s, ';', (size_t)(e - s));
        size_t n = semi ? (size_t)(semi - s) + 1 : 0;
        static const struct {
            const char *ent;
            char c;
        } ents[] = {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
        int done = 0;
        for (size_t i = 0; i < sizeof ents / sizeof *ents && !done; i++)
            if (n == strlen(ents[i].ent) && !memcmp(s, ents[i].ent, n)) *o++ = ents[i].c, done = 1;
        if (!done && n >= 4 && s[1] == '#') {
            unsigned long cp = strtoul(s + (s[2] == 'x' || s[2] == 'X' ? 3 : 2), NULL, s[2] == 'x' || s[2] == 'X' ? 16 : 10);
            if (cp > 0 && cp < 0x80) *o++ = (char)cp, done = 1;
            else if (cp >= 0x80 && cp < 0x800) *o++ = (char)(0xC0 | (cp >> 6)), *o++ = (char)(0x80 | (cp & 0x3F)), done = 1;
            else if (cp >= 0x800 && cp < 0x10000 && n >= 5)
                *o++ = (char)(0xE0 | (cp >> 12)), *o++ = (char)(0x80 | ((cp >> 6) & 0x3F)), *o++ = (char)(0x80 | (cp & 0x3F)),
                done = 1;
        }
        if (!done) {
            *bad = 1;
            *o++ = *s++;
            continue;
        }
        s += n;
    }
    *o = '\0';
    /* trim */
    char *a = out;
    while (*a && is_space(*a)) a++;
    size_t m = strlen(a);
    while (m && is_space(a[m - 1])) m--;
    memmove(out, a, m);
    out[m] = '\0';
    return out;
}

/* The value of attribute `name` (local name, case-insensitive) in the tag body [s, e) */
static int attribute(const char *s, const char *e, const char *name, const char **vs, const char **ve)
{
    const char *p = s;
    while (p < e && !is_space(*p)) p++; /* the element name */
    while (p < e) {
        while (p < e && is_space(*p)) p++;
        const char *a = p;
        while (p < e && !is_space(*p) && *p != '=') p++;
        const char *ae = p, *la = local(a, ae);
        while (p < e && is_space(*p)) p++;
        if (p >= e || *p != '=') return 0;
        p++;
        while (p < e && is_space(*p)) p++;
        if (p >= e || (*p != '"' && *p != '\'')) return 0;
        char q = *p++;
        const char *v = p;
        while (p < e && *p != q) p++;
        if (p >= e) return 0;
        if ((size_t)(ae - la) == strlen(name) && lx__starts_ci(la, ae, name)) {
            *vs = v, *ve = p;
            return 1;
        }
        p++;
    }
    return 0;
}

#define XML_DEPTH 32

/* The reader's state: the open elements, where we are, and the spectrum being collected. */
typedef struct tm27 {
    lx__rd *rd;
    struct {
        const char *s, *e;   /* the element's name */
        const char *content; /* after its start tag */
        long line;
    } stack[XML_DEPTH];
    int depth, in_header, in_dist, ndist;
    double *l, *v;
    long *ln;
    size_t n, cap;
    long dist_line;
    char *desc, *quantity;
    lx_spd_set **out;
} tm27;

/* </SpectralDistribution>: its samples become one spectrum, merged into *out. */
static lx_status end_distribution(tm27 *S)
{
    lx__rd *rd = S->rd;
    S->in_dist = 0;
    S->ndist++;
    if (S->n < 2)
        return lx__error(rd->ctx, LX_EPARSE, rd->file, S->dist_line,
                         "SpectralDistribution with %zu SpectralData element%s; a spectrum needs at least 2", S->n,
                         S->n == 1 ? "" : "s");
    char *nm = S->desc;
    lx_spd_set *set = NULL;
    lx_status st = lx__spd_set_build(rd->ctx, rd->file, S->n, S->l, 1, S->ln, 0, 1, S->v, 1, 1, S->desc ? &nm : NULL,
                                     &S->dist_line, &set);
    S->n = 0;
    if (st != LX_OK) return st;
    if (!*S->out) return *S->out = set, LX_OK;
    return lx__spd_set_merge(rd->ctx, *S->out, set);
}

/* </SpectralData>: one sample from the wavelength attribute of its start tag [as, ae) and its text. */
static lx_status end_data(tm27 *S, const char *as, const char *ae, const char *cs, const char *ce, long dl)
{
    lx__rd *rd = S->rd;
    const char *ws, *we;
    if (!attribute(as, ae, "wavelength", &ws, &we)) return lx__rd_bad_row(rd, dl, "SpectralData without a wavelength attribute");
    int bad = 0;
    char *txt = decode(cs, ce, &bad);
    if (!txt) return lx__rd_nomem(rd);
    double wl, val;
    while (ws < we && is_space(*ws)) ws++;
    while (we > ws && is_space(we[-1])) we--;
    lx_status fs = lx__parse_field(rd->ctx, rd->file, dl, ws, we, 0, "wavelength", &wl);
    if (!fs) fs = lx__parse_field(rd->ctx, rd->file, dl, txt, txt + strlen(txt), 0, "value", &val);
    lx__free(txt);
    if (fs) return lx__rd_bad_field(rd, dl, fs);
    if (!(wl > 0)) return lx__rd_bad_row(rd, dl, "wavelength must be positive: %.17g nm", wl);
    if (S->n == S->cap) {
        size_t cap = S->cap ? 2 * S->cap : 256;
        double *l2 = lx__realloc_n(S->l, cap, sizeof *l2);
        if (l2) S->l = l2;
        double *v2 = lx__realloc_n(S->v, cap, sizeof *v2);
        if (v2) S->v = v2;
        long *n2 = lx__realloc_n(S->ln, cap, sizeof *n2);
        if (n2) S->ln = n2;
        if (!l2 || !v2 || !n2) return lx__rd_nomem(rd);
        S->cap = cap;
    }
    S->l[S->n] = wl, S->v[S->n] = val, S->ln[S->n] = dl, S->n++;
    return LX_OK;
}

/* An end tag </ns..ne> at lt, line `line`: checks it closes the open element, then handles it. */
static lx_status end_tag(tm27 *S, const char *ns, const char *ne, const char *lt, long line)
{
    lx__rd *rd = S->rd;
    int d = S->depth;
    if (d == 0 || (size_t)(ne - ns) != (size_t)(S->stack[d - 1].e - S->stack[d - 1].s) ||
        memcmp(ns, S->stack[d - 1].s, (size_t)(ne - ns)))
        return lx__error(rd->ctx, LX_EPARSE, rd->file, line, "XML end tag </%.*s> does not close %s%.*s%s",
                         (int)(ne - ns), ns, d ? "<" : "any element", d ? (int)(S->stack[d - 1].e - S->stack[d - 1].s) : 0,
                         d ? S->stack[d - 1].s : "", d ? ">" : "");
    d = --S->depth;
    const char *cs = S->stack[d].content, *ce = lt;
    if (name_is(ns, ne, "Header")) {
        S->in_header = 0;
        return LX_OK;
    }
    if (name_is(ns, ne, "SpectralDistribution")) return end_distribution(S);
    if (S->in_dist && name_is(ns, ne, "SpectralData"))
        return end_data(S, S->stack[d].s, S->stack[d].content - 1, cs, ce, S->stack[d].line);
    if (!((S->in_header || S->in_dist) && d == 2)) return LX_OK;
    /* a field of Header or SpectralDistribution */
    int bad = 0;
    char *txt = decode(cs, ce, &bad);
    if (!txt) return lx__rd_nomem(rd);
    const char *k = local(ns, ne);
    lx_status st = lx__rd_field(rd, S->stack[d].line, k, ne, txt, txt + strlen(txt)) ? lx__rd_nomem(rd) : LX_OK;
    if (S->in_header && name_is(ns, ne, "Description") && !S->desc) S->desc = txt, txt = NULL;
    else if (S->in_dist && name_is(ns, ne, "SpectralQuantity") && !S->quantity) S->quantity = txt, txt = NULL;
    lx__free(txt);
    return st;
}

/* Skips a comment or CDATA section at lt (open, its closing marker); returns 0 when lt is neither. */
static int skip_section(xml *x, const char *lt, const char *e, const char **p, lx_status *st)
{
    static const struct {
        const char *open, *close, *what;
    } sec[2] = {{"<!--", "-->", "comment"}, {"<![CDATA[", "]]>", "CDATA"}};
    for (int i = 0; i < 2; i++) {
        size_t no = strlen(sec[i].open);
        if ((size_t)(e - lt) < no || memcmp(lt, sec[i].open, no)) continue;
        const char *c = lt + no;
        while (c + 3 <= e && memcmp(c, sec[i].close, 3)) c++;
        if (c + 3 > e)
            *st = lx__error(x->rd->ctx, LX_EPARSE, x->rd->file, line_at(x, lt), "truncated XML: %s not closed", sec[i].what);
        *p = c + 3;
        return 1;
    }
    return 0;
}

lx_status lx__tm27_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    rd->format = "tm27";
    xml x = {rd, text, text + len, text, rd->line0 + 1};
    tm27 *S = lx__calloc(1, sizeof *S);
    if (!S) return lx__rd_nomem(rd);
    S->rd = rd, S->out = out;
    lx_status st = LX_OK;
    const char *p = text, *e = text + len;
    while (st == LX_OK && p < e) {
        const char *lt = memchr(p, '<', (size_t)(e - p));
        if (!lt) break;
        if (skip_section(&x, lt, e, &p, &st)) continue;
        long line = line_at(&x, lt);
        const char *gt = memchr(lt, '>', (size_t)(e - lt));
        if (!gt) {
            st = lx__error(rd->ctx, LX_EPARSE, rd->file, line, "truncated XML: a tag is not closed");
            break;
        }
        p = gt + 1;
        if (lt[1] == '?' || lt[1] == '!') continue; /* declaration, processing instruction, DOCTYPE */
        if (lt[1] == '/') {
            const char *ns = lt + 2, *ne = ns;
            while (ne < gt && !is_space(*ne)) ne++;
            st = end_tag(S, ns, ne, lt, line);
            continue;
        }
        /* a start tag (an empty element <x/> holds nothing) */
        const char *ns = lt + 1, *ne = ns;
        while (ne < gt && !is_space(*ne) && *ne != '/') ne++;
        if (gt[-1] == '/') continue;
        if (S->depth == XML_DEPTH) {
            st = lx__error(rd->ctx, LX_EPARSE, rd->file, line, "XML nested deeper than %d elements", XML_DEPTH);
            break;
        }
        int d = S->depth++;
        S->stack[d].s = ns, S->stack[d].e = ne, S->stack[d].content = gt + 1, S->stack[d].line = line;
        if (d == 1 && name_is(ns, ne, "Header")) S->in_header = 1;
        if (d == 1 && name_is(ns, ne, "SpectralDistribution")) S->in_dist = 1, S->dist_line = line, S->n = 0;
    }
    if (st == LX_OK && S->depth > 0)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, S->stack[S->depth - 1].line, "truncated XML: <%.*s> is not closed",
                       (int)(S->stack[S->depth - 1].e - S->stack[S->depth - 1].s), S->stack[S->depth - 1].s);
    if (st == LX_OK && !S->ndist)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, line_at(&x, e), "no <SpectralDistribution> element: not a TM-27 document");
    if (st == LX_OK && S->quantity) {
        static const struct {
            const char *q, *unit;
        } qu[] = {{"flux", "W/nm"}, {"irradiance", "W/m2/nm"}, {"radiance", "W/sr/m2/nm"}, {"intensity", "W/sr/nm"}};
        for (size_t i = 0; i < sizeof qu / sizeof *qu; i++)
            if (!strcmp(S->quantity, qu[i].q)) rd->unit = qu[i].unit, rd->unit_scale = 1.0, rd->unit_source = "TM-27 SpectralQuantity";
    }
    if (st != LX_OK && *out) {
        lx_spd_set_free(*out);
        *out = NULL;
    }
    lx__free(S->l), lx__free(S->v), lx__free(S->ln), lx__free(S->desc), lx__free(S->quantity), lx__free(S);
    return st;
}
