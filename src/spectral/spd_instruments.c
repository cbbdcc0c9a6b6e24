/* spd_instruments.c - the line-oriented exports of spectrometer software: Ocean Optics OceanView
 * and SpectraSuite (">>>>>Begin Spectral Data<<<<<"), Sekonic C-7000/C-800 ("Spectral Data
 * 380[nm],v"), UPRtek and LI-COR LI-180 ("380nm<TAB>v"), StellarNet SpectraWiz (quoted header
 * lines, pairs). Everything that is not a data row is kept as a header field. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
static int is_digit(char c) { return c >= '0' && c <= '9'; }

static const char *skip_blanks(const char *s, const char *e)
{
    while (s < e && is_blank(*s)) s++;
    return s;
}

static int blank_line(const char *s, const char *e) { return skip_blanks(s, e) >= e; }

/* A growing sample list of one spectrum (wavelength, value, line). */
typedef struct samples {
    double *l, *v;
    long *line;
    size_t n, cap;
    long first_line;
} samples;

static int samples_push(samples *S, double l, double v, long line)
{
    if (S->n == S->cap) {
        size_t cap = S->cap ? 2 * S->cap : 512;
        double *nl = lx__realloc_n(S->l, cap, sizeof *nl);
        if (nl) S->l = nl;
        double *nv = lx__realloc_n(S->v, cap, sizeof *nv);
        if (nv) S->v = nv;
        long *ln = lx__realloc_n(S->line, cap, sizeof *ln);
        if (ln) S->line = ln;
        if (!nl || !nv || !ln) return -1;
        S->cap = cap;
    }
    if (!S->n) S->first_line = line;
    S->l[S->n] = l, S->v[S->n] = v, S->line[S->n] = line;
    S->n++;
    return 0;
}

static void samples_free(samples *S) { lx__free(S->l), lx__free(S->v), lx__free(S->line); }

/* One spectrum from samples (at least 2) into *out, or merged into it when *out holds one; `last`
 * is the line an empty spectrum's error names. */
static lx_status samples_set(lx__rd *rd, samples *S, const char *name, long last, lx_spd_set **out)
{
    if (S->n < 2)
        return lx__error(rd->ctx, LX_EPARSE, rd->file, S->n ? S->line[0] : last > 0 ? last : 1,
                         "%zu data row%s; a spectrum needs at least 2", S->n, S->n == 1 ? "" : "s");
    char *nm = (char *)name;
    lx_spd_set *set = NULL;
    lx_status st = lx__spd_set_build(rd->ctx, rd->file, S->n, S->l, 1, S->line, 0, 1, S->v, 1, 1,
                                     name && *name ? &nm : NULL, &S->first_line, &set);
    if (st) return st;
    if (!*out) {
        *out = set;
        return LX_OK;
    }
    return lx__spd_set_merge(rd->ctx, *out, set);
}

/* Whitespace-separated tokens of [s, e), at most max (the count is returned, max + 1 when more). */
static size_t tokens(const char *s, const char *e, const char **ts, const char **te, size_t max)
{
    size_t n = 0;
    for (const char *p = skip_blanks(s, e); p < e; p = skip_blanks(p, e)) {
        const char *q = p;
        while (q < e && !is_blank(*q)) q++;
        if (n == max) return max + 1;
        ts[n] = p, te[n] = q, n++;
        p = q;
    }
    return n;
}

/* A row of two whitespace-separated numbers (decimal point or comma) into the samples, or a bad row. */
static lx_status pair_row(lx__rd *rd, samples *S, const char *s, const char *e, long line)
{
    const char *ts[3], *te[3];
    size_t n = tokens(s, e, ts, te, 2);
    if (n != 2)
        return lx__rd_bad_row(rd, line, "row has %s, expected 2 (wavelength, value)", n > 2 ? "more than 2 fields" : "1 field");
    double l, v;
    lx_status st = lx__parse_field(rd->ctx, rd->file, line, ts[0], te[0], ',', "wavelength", &l);
    if (!st) st = lx__parse_field(rd->ctx, rd->file, line, ts[1], te[1], ',', "value", &v);
    if (st) return lx__rd_bad_field(rd, line, st);
    if (!(l > 0)) return lx__rd_bad_row(rd, line, "wavelength must be positive: %.17g nm", l);
    return samples_push(S, l, v, line) ? lx__rd_nomem(rd) : LX_OK;
}

static const char *find(const char *s, const char *e, const char *w)
{
    size_t n = strlen(w);
    for (const char *p = s; p + n <= e; p++)
        if (!memcmp(p, w, n)) return p;
    return NULL;
}

/* ---- Ocean Optics OceanView and SpectraSuite ---- */

int lx__oceanview_detect(const char *text, size_t len)
{
    lx__lines it = {text, text + len, 0};
    const char *s, *e;
    while (lx__next_line(&it, &s, &e) && it.line <= 200) {
        s = skip_blanks(s, e);
        if (lx__starts_ci(s, e, ">>>>>Begin") && find(s, e, "Spectral Data")) return 1;
    }
    return 0;
}

lx_status lx__oceanview_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    rd->format = "oceanview";
    lx__lines it = {text, text + len, rd->line0};
    const char *s, *e;
    samples S = {0};
    char *name = NULL;
    long begin = 0, end_line = 0, count_line = 0, count = -1;
    int processed = 0;
    lx_status st = LX_OK;
    while (st == LX_OK && lx__next_line(&it, &s, &e)) {
        const char *t = skip_blanks(s, e);
        if (t >= e) continue;
        if (!begin) {
            if (lx__starts_ci(t, e, ">>>>>Begin")) {
                begin = it.line;
                processed = find(t, e, "Processed") != NULL;
                continue;
            }
            const char *colon = memchr(t, ':', (size_t)(e - t));
            if (lx__starts_ci(t, e, "Data from ")) {
                const char *v = t + 10, *ve = e;
                while (ve > v && is_blank(ve[-1])) ve--;
                if (ve - v > 5 && !memcmp(ve - 5, " Node", 5)) ve -= 5;
                lx__free(name);
                static const char key[] = "Data from";
                if (!(name = lx__strndup(v, ve)) || lx__rd_field(rd, it.line, key, key + 9, v, ve))
                    st = lx__rd_nomem(rd);
                if (find(v, ve, "AbsoluteIrradiance")) {
                    rd->unit = "W/m2/nm";
                    rd->unit_scale = 0.01; /* OceanView's absolute irradiance: uW cm-2 nm-1 */
                    rd->unit_source = "OceanView absolute irradiance node: uW/cm2/nm";
                }
            } else if (colon) {
                if (lx__rd_field(rd, it.line, t, colon, colon + 1, e)) st = lx__rd_nomem(rd);
                if (lx__starts_ci(t, colon, "Number of Pixels in")) {
                    double c;
                    const char *v = skip_blanks(colon + 1, e), *ve = e;
                    while (ve > v && is_blank(ve[-1])) ve--;
                    if (lx__parse_double(v, ve, &c) == ve && c >= 0 && c < 1e9) count = (long)c, count_line = it.line;
                }
            } else if (lx__rd_field(rd, it.line, t, e, NULL, NULL)) {
                st = lx__rd_nomem(rd);
            }
            continue;
        }
        if (end_line) continue; /* after the End marker */
        if (lx__starts_ci(t, e, ">>>>>End")) {
            end_line = it.line;
            continue;
        }
        st = pair_row(rd, &S, t, e, it.line);
    }
    if (st == LX_OK && !begin)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, it.line ? it.line : 1,
                       "no >>>>>Begin Spectral Data<<<<< line: not an OceanView/SpectraSuite file");
    if (st == LX_OK && processed && !end_line)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, it.line,
                       "truncated: the data begun on line %ld has no >>>>>End Processed Spectral Data<<<<< line", begin);
    if (st == LX_OK && count >= 0 && (size_t)count != S.n + rd->nskipped)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, count_line,
                       "the header gives %ld pixels but the data has %zu rows (lines %ld-%ld)", count,
                       S.n + rd->nskipped, begin + 1, end_line ? end_line - 1 : it.line);
    if (st == LX_OK) {
        S.first_line = begin;
        st = samples_set(rd, &S, name, it.line, out);
    }
    lx__free(name);
    samples_free(&S);
    return st;
}

/* ---- Sekonic C-7000 / C-800 (SpectroMaster) CSV ---- */

/* "Spectral Data 380[nm]": the wavelength label of a data row; [*ls, *le) its number */
static int sekonic_label(const char *s, const char *e, const char **ls, const char **le)
{
    s = skip_blanks(s, e);
    if (!lx__starts_ci(s, e, "Spectral Data ")) return 0;
    const char *p = skip_blanks(s + 14, e), *q = p;
    while (q < e && *q != '[' && *q != ',') q++;
    if (q >= e || *q != '[') return 0;
    *ls = p, *le = q;
    while (*le > *ls && is_blank((*le)[-1])) (*le)--;
    return 1;
}

int lx__sekonic_detect(const char *text, size_t len)
{
    lx__lines it = {text, text + len, 0};
    const char *s, *e, *a, *b;
    while (lx__next_line(&it, &s, &e) && it.line <= 400)
        if (sekonic_label(s, e, &a, &b) && b > a && is_digit(*a)) return 1;
    return 0;
}

lx_status lx__sekonic_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    rd->format = "sekonic";
    rd->unit = "W/m2/nm"; /* the SpectroMaster exports spectral irradiance in W m-2 nm-1 */
    rd->unit_scale = 1.0;
    rd->unit_source = "Sekonic export: W/m2/nm";
    lx__lines it = {text, text + len, rd->line0};
    const char *s, *e, *ls, *le;
    samples blk[16];
    size_t nblk = 0;
    int open = 0;
    lx_status st = LX_OK;
    memset(blk, 0, sizeof blk);
    while (st == LX_OK && lx__next_line(&it, &s, &e)) {
        if (blank_line(s, e)) {
            open = 0;
            continue;
        }
        if (!sekonic_label(s, e, &ls, &le)) {
            const char *c = memchr(s, ',', (size_t)(e - s));
            if (lx__rd_field(rd, it.line, s, c ? c : e, c ? c + 1 : NULL, e)) st = lx__rd_nomem(rd);
            open = 0;
            continue;
        }
        double l, v;
        const char *c = memchr(le, ',', (size_t)(e - le));
        if (!c) {
            st = lx__rd_bad_row(rd, it.line, "row has 1 field, expected 2 (Spectral Data NNN[nm],value)");
            continue;
        }
        const char *vs = skip_blanks(c + 1, e), *ve = e;
        while (ve > vs && is_blank(ve[-1])) ve--;
        lx_status fs = lx__parse_field(rd->ctx, rd->file, it.line, ls, le, 0, "wavelength", &l);
        if (!fs) fs = lx__parse_field(rd->ctx, rd->file, it.line, vs, ve, 0, "value", &v);
        if (fs) {
            st = lx__rd_bad_field(rd, it.line, fs);
            continue;
        }
        if (!(l > 0)) {
            st = lx__rd_bad_row(rd, it.line, "wavelength must be positive: %.17g nm", l);
            continue;
        }
        /* a new block after a blank or other line, or where the wavelengths start again */
        if (!open || (blk[nblk - 1].n && l <= blk[nblk - 1].l[blk[nblk - 1].n - 1])) {
            if (nblk == sizeof blk / sizeof *blk) {
                st = lx__error(rd->ctx, LX_EPARSE, rd->file, it.line, "more than %zu spectral data blocks", nblk);
                continue;
            }
            nblk++;
            open = 1;
        }
        if (samples_push(&blk[nblk - 1], l, v, it.line)) st = lx__rd_nomem(rd);
    }
    if (st == LX_OK && nblk == 0)
        st = lx__error(rd->ctx, LX_EPARSE, rd->file, it.line ? it.line : 1, "no 'Spectral Data NNN[nm],value' rows");
    const char *title = NULL;
    for (size_t i = 0; i < rd->nfields && !title; i++)
        if (!strcmp(rd->fields[i].key, "Title")) title = rd->fields[i].value;
    for (size_t b = 0; b < nblk && st == LX_OK; b++) {
        char name[320];
        samples *B = &blk[b];
        double step = B->n >= 2 ? (B->l[B->n - 1] - B->l[0]) / (double)(B->n - 1) : 0;
        if (nblk == 1) snprintf(name, sizeof name, "%s", title ? title : "");
        else snprintf(name, sizeof name, "%s%s(%.6g nm)", title ? title : "", title && *title ? " " : "", step);
        st = samples_set(rd, B, name, it.line, out);
    }
    for (size_t b = 0; b < nblk; b++) samples_free(&blk[b]);
    return st;
}

/* ---- UPRtek (CV600, MK350 family) and LI-COR LI-180 ---- */

/* A data row "380nm<TAB>v" (or ','): [*ls, *le) the number, *sep its separator */
static int nm_label(const char *s, const char *e, const char **ls, const char **le, const char **sep)
{
    s = skip_blanks(s, e);
    const char *p = s;
    while (p < e && (is_digit(*p) || *p == '.')) p++;
    if (p == s || p + 2 > e || p[0] != 'n' || p[1] != 'm') return 0;
    const char *q = p + 2;
    while (q < e && *q == ' ') q++;
    if (q < e && *q != '\t' && *q != ',') return 0;
    *ls = s, *le = p, *sep = q;
    return 1;
}

int lx__uprtek_detect(const char *text, size_t len)
{
    lx__lines it = {text, text + len, 0};
    const char *s, *e, *a, *b, *c;
    int n = 0;
    while (lx__next_line(&it, &s, &e) && it.line <= 400)
        if (nm_label(s, e, &a, &b, &c) && c < e && ++n >= 2) return 1;
    return 0;
}

lx_status lx__uprtek_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    rd->format = "uprtek";
    lx__lines it = {text, text + len, rd->line0};
    const char *s, *e, *ls, *le, *sp;
    samples S = {0};
    long data_end = 0; /* the first non-data line after the data */
    lx_status st = LX_OK;
    while (st == LX_OK && lx__next_line(&it, &s, &e)) {
        if (blank_line(s, e)) continue;
        if (!nm_label(s, e, &ls, &le, &sp)) {
            const char *t = memchr(s, '\t', (size_t)(e - s));
            if (!t) t = memchr(s, ',', (size_t)(e - s));
            if (lx__rd_field(rd, it.line, s, t ? t : e, t ? t + 1 : NULL, e)) st = lx__rd_nomem(rd);
            if ((S.n || rd->nskipped) && !data_end) data_end = it.line;
            continue;
        }
        if (data_end) {
            st = lx__error(rd->ctx, LX_EPARSE, rd->file, it.line,
                           "a second block of wavelength rows (the first ended before line %ld)", data_end);
            continue;
        }
        if (sp >= e) {
            st = lx__rd_bad_row(rd, it.line, "row has 1 field, expected 2 (NNNnm, value)");
            continue;
        }
        const char *vs = skip_blanks(sp + 1, e), *ve = e;
        while (ve > vs && is_blank(ve[-1])) ve--;
        double l, v;
        lx_status fs = lx__parse_field(rd->ctx, rd->file, it.line, ls, le, 0, "wavelength", &l);
        if (!fs) fs = lx__parse_field(rd->ctx, rd->file, it.line, vs, ve, 0, "value", &v);
        if (fs) {
            st = lx__rd_bad_field(rd, it.line, fs);
            continue;
        }
        if (!(l > 0)) {
            st = lx__rd_bad_row(rd, it.line, "wavelength must be positive: %.17g nm", l);
            continue;
        }
        if (samples_push(&S, l, v, it.line)) st = lx__rd_nomem(rd);
    }
    const char *model = NULL, *memo = NULL;
    for (size_t i = 0; i < rd->nfields; i++) {
        if (!strcmp(rd->fields[i].key, "Model Name") && !model) model = rd->fields[i].value;
        if (!strcmp(rd->fields[i].key, "Memo") && !memo) memo = rd->fields[i].value;
    }
    /* both write spectral irradiance in mW m-2 nm-1 (their LUX is 0.683 integral E V) */
    rd->unit = "W/m2/nm";
    rd->unit_scale = 1e-3;
    rd->unit_source = model && !strncmp(model, "LI-", 3) ? "LI-COR export: mW/m2/nm" : "UPRtek export: mW/m2/nm";
    if (st == LX_OK) st = samples_set(rd, &S, memo, it.line, out);
    samples_free(&S);
    return st;
}

/* ---- StellarNet SpectraWiz (.IRR, .SSM, ...) ---- */

int lx__spectrawiz_detect(const char *text, size_t len)
{
    lx__lines it = {text, text + len, 0};
    const char *s, *e;
    int quoted = 0;
    while (lx__next_line(&it, &s, &e) && it.line <= 20) {
        const char *t = skip_blanks(s, e);
        if (t >= e) continue;
        if (*t == '"') {
            quoted++;
            continue;
        }
        if (!quoted) return 0;
        const char *ts[3], *te[3];
        double d;
        return tokens(t, e, ts, te, 2) == 2 && lx__parse_double(ts[0], te[0], &d) == te[0] &&
               lx__parse_double(ts[1], te[1], &d) == te[1];
    }
    return 0;
}

lx_status lx__spectrawiz_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    rd->format = "spectrawiz";
    lx__lines it = {text, text + len, rd->line0};
    const char *s, *e;
    samples S = {0};
    long trailer = 0;
    lx_status st = LX_OK;
    static const char header_key[] = "header", trailer_key[] = "trailer";
    while (st == LX_OK && lx__next_line(&it, &s, &e)) {
        const char *t = skip_blanks(s, e);
        if (t >= e) continue;
        if (*t == '"' || *t == ':') {
            const char *v = skip_blanks(t + 1, e);
            const char *c = v;
            while (c < e && ((*c >= 'A' && *c <= 'Z') || (*c >= 'a' && *c <= 'z') || *c == ' ')) c++;
            int kv = *t == '"' && c > v && c < e && *c == ':';
            const char *k = kv ? v : *t == '"' ? header_key : trailer_key;
            const char *ke = kv ? c : k + strlen(k);
            if (lx__rd_field(rd, it.line, k, ke, kv ? c + 1 : v, e)) st = lx__rd_nomem(rd);
            if (*t == ':') trailer = it.line;
            continue;
        }
        if (trailer) {
            st = lx__error(rd->ctx, LX_EPARSE, rd->file, it.line, "data after the ': ' trailer line %ld", trailer);
            continue;
        }
        st = pair_row(rd, &S, t, e, it.line);
    }
    if (st == LX_OK) st = samples_set(rd, &S, NULL, it.line, out);
    samples_free(&S);
    return st;
}
