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
    char *out = malloc((size_t)(e - s) + 1), *o = out;
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

lx_status lx__tm27_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    rd->format = "tm27";
    xml x = {rd, text, text + len, text, rd->line0 + 1};
    struct {
        const char *s, *e; /* name */
        const char *content; /* after the start tag */
        long line;
    } stack[XML_DEPTH];
    int depth = 0;
    lx_status st = LX_OK;
    double *l = NULL, *v = NULL;
    long *ln = NULL;
    size_t n = 0, cap = 0;
    int in_header = 0, in_dist = 0, ndist = 0;
    char *desc = NULL, *quantity = NULL;
    long dist_line = 0;
    const char *p = text, *e = text + len;
    while (st == LX_OK && p < e) {
        const char *lt = memchr(p, '<', (size_t)(e - p));
        if (!lt) break;
        long line = line_at(&x, lt);
        if (e - lt >= 4 && !memcmp(lt, "<!--", 4)) {
            const char *c = lt + 4;
            while (c + 3 <= e && memcmp(c, "-->", 3)) c++;
            if (c + 3 > e) st = lx__error(rd->ctx, LX_EPARSE, rd->file, line, "truncated XML: comment not closed");
            p = c + 3;
            continue;
        }
        if (e - lt >= 9 && !memcmp(lt, "<![CDATA[", 9)) {
            const char *c = lt + 9;
            while (c + 3 <= e && memcmp(c, "]]>", 3)) c++;
            if (c + 3 > e) st = lx__error(rd->ctx, LX_EPARSE, rd->file, line, "truncated XML: CDATA not closed");
            p = c + 3;
            continue;
        }
        const char *gt = memchr(lt, '>', (size_t)(e - lt));
        if (!gt) {
            st = lx__error(rd->ctx, LX_EPARSE, rd->file, line, "truncated XML: a tag is not closed");
            break;
        }
        p = gt + 1;
        if (lt[1] == '?' || lt[1] == '!') continue; /* declaration, processing instruction, DOCTYPE */
        if (lt[1] == '/') { /* end tag */
            const char *ns = lt + 2, *ne = ns;
            while (ne < gt && !is_space(*ne)) ne++;
            if (depth == 0 || (size_t)(ne - ns) != (size_t)(stack[depth - 1].e - stack[depth - 1].s) ||
                memcmp(ns, stack[depth - 1].s, (size_t)(ne - ns))) {
                st = lx__error(rd->ctx, LX_EPARSE, rd->file, line, "XML end tag </%.*s> does not close %s%.*s%s",
                               (int)(ne - ns), ns, depth ? "<" : "any element", depth ? (int)(stack[depth - 1].e - stack[depth - 1].s) : 0,
                               depth ? stack[depth - 1].s : "", depth ? ">" : "");
                break;
            }
            depth--;
            const char *cs = stack[depth].content, *ce = lt;
            int bad = 0;
            if (name_is(ns, ne, "Header")) in_header = 0;
            else if (name_is(ns, ne, "SpectralDistribution")) {
                in_dist = 0;
                ndist++;
                lx_spd_set *set = NULL;
                if (n < 2) {
                    st = lx__error(rd->ctx, LX_EPARSE, rd->file, dist_line,
                                   "SpectralDistribution with %zu SpectralData element%s; a spectrum needs at least 2", n,
                                   n == 1 ? "" : "s");
                    break;
                }
                char *nm = desc;
                st = lx__spd_set_build(rd->ctx, rd->file, n, l, 1, ln, 0, 1, v, 1, 1, desc ? &nm : NULL, &dist_line, &set);
                if (st == LX_OK) st = *out ? lx__spd_set_merge(rd->ctx, *out, set) : (*out = set, LX_OK);
                n = 0;
            } else if (in_dist && name_is(ns, ne, "SpectralData")) {
                const char *as = stack[depth].s, *ae = stack[depth].content - 1, *ws, *we;
                long dl = stack[depth].line;
                if (!attribute(as, ae, "wavelength", &ws, &we)) {
                    st = lx__rd_bad_row(rd, dl, "SpectralData without a wavelength attribute");
                    continue;
                }
                char *txt = decode(cs, ce, &bad);
                if (!txt) {
                    st = lx__rd_nomem(rd);
                    break;
                }
                double wl, val;
                while (ws < we && is_space(*ws)) ws++;
                while (we > ws && is_space(we[-1])) we--;
                lx_status fs = lx__parse_field(rd->ctx, rd->file, dl, ws, we, 0, "wavelength", &wl);
                if (!fs) fs = lx__parse_field(rd->ctx, rd->file, dl, txt, txt + strlen(txt), 0, "value", &val);
                free(txt);
                if (fs) {
                    st = lx__rd_bad_field(rd, dl, fs);
                    continue;
                }
                if (!(wl > 0)) {
                    st = lx__rd_bad_row(rd, dl, "wavelength must be positive: %.17g nm", wl);
                    continue;
                }
                if (n == cap) {
                    cap = cap ? 2 * cap : 256;
                    double *l2 = realloc(l, cap * sizeof *l2);
                    if (l2) l = l2;
                    double *v2 = realloc(v, cap * sizeof *v2);
                    if (v2) v = v2;
                    long *n2 = realloc(ln, cap * sizeof *n2);
                    if (n2) ln = n2;
                    if (!l2 || !v2 || !n2) {
                        st = lx__rd_nomem(rd);
                        break;
                    }
                }
                l[n] = wl, v[n] = val, ln[n] = dl, n++;
            } else if ((in_header && depth == 2) || (in_dist && depth == 2)) { /* a field of Header or SpectralDistribution */
                char *txt = decode(cs, ce, &bad);
                if (!txt) {
                    st = lx__rd_nomem(rd);
                    break;
                }
                const char *k = local(ns, ne);
                if (lx__rd_field(rd, stack[depth].line, k, ne, txt, txt + strlen(txt))) st = lx__rd_nomem(rd);
                if (in_header && name_is(ns, ne, "Description") && !desc) desc = txt, txt = NULL;
                else if (in_dist && name_is(ns, ne, "SpectralQuantity") && !quantity) quantity = txt, txt = NULL;
                free(txt);
            }
            continue;
        }
        /* a start tag (or an empty element <x/>) */
        const char *ns = lt + 1, *ne = ns;
        while (ne < gt && !is_space(*ne) && *ne != '/') ne++;
        int empty = gt > lt && gt[-1] == '/';
        if (empty) continue;
        if (depth == XML_DEPTH) {
            st = lx__error(rd->ctx, LX_EPARSE, rd->file, line, "XML nested deeper than %d elements", XML_DEPTH);
            break;
        }
        stack[depth].s = ns, stack[depth].e = ne, stack[depth].content = gt + 1, stack[depth].line = line;
        depth++;
        if (depth == 2 && name_is(ns, ne, "Header")) in_header = 1;
        if (depth == 2 && name_is(ns, ne, "SpectralDistribution")) in_dist = 1, dist_line = line, n = 0;
    }
    if (st == LX_OK && depth > 0)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, stack[depth - 1].line, "truncated XML: <%.*s> is not closed",
                       (int)(stack[depth - 1].e - stack[depth - 1].s), stack[depth - 1].s);
    if (st == LX_OK && !ndist)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, line_at(&x, e), "no <SpectralDistribution> element: not a TM-27 document");
    if (st == LX_OK && quantity) {
        static const struct {
            const char *q, *unit;
        } qu[] = {{"flux", "W/nm"}, {"irradiance", "W/m2/nm"}, {"radiance", "W/sr/m2/nm"}, {"intensity", "W/sr/nm"}};
        for (size_t i = 0; i < sizeof qu / sizeof *qu; i++)
            if (!strcmp(quantity, qu[i].q)) {
                rd->unit = qu[i].unit;
                rd->unit_scale = 1.0;
                rd->unit_source = "TM-27 SpectralQuantity";
            }
    }
    if (st != LX_OK && *out) {
        lx_spd_set_free(*out);
        *out = NULL;
    }
    free(l);
    free(v);
    free(ln);
    free(desc);
    free(quantity);
    return st;
}
