/* spd_read.c - the entry points of the spectrum readers: checks of the raw bytes (BOM, UTF-16, NUL),
 * the layout by content detection or by name, the state the layout readers share (header fields,
 * skipped rows), units of wavelength and value, and the lx_spd_set that owns the result. The
 * layouts are in spd_text.c, spd_instruments.c, spd_tm27.c and cgats.c. */
#include "spectral/spectral_private.h"

#include <errno.h>
#include <stdarg.h>
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
            lx__free((void *)set->spd[i].name);
            lx__free((void *)set->spd[i].lambda_nm);
            lx__free((void *)set->spd[i].value);
        }
    }
    for (size_t i = 0; i < set->nfields; i++) {
        lx__free(set->fields[i].key);
        lx__free(set->fields[i].value);
    }
    for (size_t i = 0; i < set->nskipped; i++) lx__free(set->skipped[i].why);
    lx__free(set->fields);
    lx__free(set->skipped);
    lx__free(set->spd);
    lx__free(set->line);
    lx__free(set->file);
    lx__free(set);
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
    sort_key *key = lx__alloc_n(nlam, sizeof *key);
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
                lx__free(key);
                return st;
            }
        }
    }
    lx_spd_set *set = lx__calloc(1, sizeof *set);
    if (!set) goto nomem;
    set->file = lx__strndup(file, file + strlen(file));
    set->unit_scale = 1.0;
    set->wavelength_scale = 1.0;
    set->spd = lx__calloc(nspec ? nspec : 1, sizeof *set->spd);
    set->line = lx__calloc(nspec ? nspec : 1, sizeof *set->line);
    if (!set->file || !set->spd || !set->line) goto nomem;
    for (size_t s = 0; s < nspec; s++) {
        char num[32];
        const char *nm = names ? names[s] : NULL;
        if (!nm || !*nm) {
            snprintf(num, sizeof num, "%zu", s + 1);
            nm = num;
        }
        double *l = lx__alloc_n(nlam, sizeof *l);
        double *v = lx__alloc_n(nlam, sizeof *v);
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
    lx__free(key);
    *out = set;
    return LX_OK;
nomem:
    lx__free(key);
    lx_spd_set_free(set);
    return lx__error(ctx, LX_ENOMEM, file, 0, "out of memory");
#undef LAMLINE
}

lx_status lx__spd_set_merge(lx_ctx *ctx, lx_spd_set *a, lx_spd_set *b)
{
    size_t n = a->count + b->count;
    lx_spd *spd = lx__realloc_n(a->spd, n ? n : 1, sizeof *spd);
    if (spd) a->spd = spd;
    long *line = lx__realloc_n(a->line, n ? n : 1, sizeof *line);
    if (line) a->line = line;
    if (!spd || !line) {
        lx_spd_set_free(b);
        return lx__error(ctx, LX_ENOMEM, a->file, 0, "out of memory");
    }
    memcpy(a->spd + a->count, b->spd, b->count * sizeof *spd);
    memcpy(a->line + a->count, b->line, b->count * sizeof *line);
    a->count = n;
    b->count = 0; /* its arrays now belong to a */
    lx_spd_set_free(b);
    return LX_OK;
}

/* ---- the shared reader state ---- */

static void trim(const char **s, const char **e)
{
    while (*s < *e && is_blank(**s)) (*s)++;
    while (*e > *s && is_blank((*e)[-1])) (*e)--;
    if (*e - *s >= 2 && **s == '"' && (*e)[-1] == '"') (*s)++, (*e)--;
}

int lx__rd_field(lx__rd *rd, long line, const char *ks, const char *ke, const char *vs, const char *ve)
{
    if (rd->nfields == rd->fcap) {
        size_t cap = rd->fcap ? 2 * rd->fcap : 32;
        lx_spd_field *f = lx__realloc_n(rd->fields, cap, sizeof *f);
        if (!f) return -1;
        rd->fields = f;
        rd->fcap = cap;
    }
    trim(&ks, &ke);
    if (vs) trim(&vs, &ve);
    lx_spd_field *f = &rd->fields[rd->nfields];
    memset(f, 0, sizeof *f);
    f->key = lx__strndup(ks, ke);
    f->value = vs ? lx__strndup(vs, ve) : lx__strndup("", "");
    f->line = line;
    if (!f->key || !f->value) {
        lx__free(f->key);
        lx__free(f->value);
        return -1;
    }
    rd->nfields++;
    return 0;
}

static lx_status skip_row(lx__rd *rd, long line, const char *what)
{
    if (rd->nskipped == rd->scap) {
        size_t cap = rd->scap ? 2 * rd->scap : 16;
        lx_spd_skipped *k = lx__realloc_n(rd->skipped, cap, sizeof *k);
        if (!k) return lx__rd_nomem(rd);
        rd->skipped = k;
        rd->scap = cap;
    }
    char *why = lx__strndup(what, what + strlen(what));
    if (!why) return lx__rd_nomem(rd);
    memset(&rd->skipped[rd->nskipped], 0, sizeof rd->skipped[rd->nskipped]);
    rd->skipped[rd->nskipped].line = line;
    rd->skipped[rd->nskipped].why = why;
    rd->nskipped++;
    return LX_OK;
}

lx_status lx__rd_bad_row(lx__rd *rd, long line, const char *fmt, ...)
{
    char what[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (rd->opts.skip_bad_rows) return skip_row(rd, line, what);
    return lx__error(rd->ctx, LX_EPARSE, rd->file, line, "%s", what);
}

lx_status lx__rd_bad_field(lx__rd *rd, long line, lx_status st)
{
    if (st != LX_EPARSE || !rd->opts.skip_bad_rows) return st;
    /* the context holds "FILE:LINE: what": keep the what */
    const char *m = lx_ctx_errmsg(rd->ctx);
    char prefix[320];
    int n = snprintf(prefix, sizeof prefix, "%s:%ld: ", rd->file, line);
    if (n > 0 && (size_t)n < sizeof prefix && !strncmp(m, prefix, (size_t)n)) m += n;
    return skip_row(rd, line, m);
}

lx_status lx__rd_nomem(lx__rd *rd) { return lx__error(rd->ctx, LX_ENOMEM, rd->file, 0, "out of memory"); }

int lx__starts_ci(const char *s, const char *e, const char *w)
{
    while (s < e && is_blank(*s)) s++;
    size_t n = strlen(w);
    if ((size_t)(e - s) < n) return 0;
    for (size_t i = 0; i < n; i++) {
        char a = s[i], b = w[i];
        if (a >= 'A' && a <= 'Z') a = (char)(a - 'A' + 'a');
        if (b >= 'A' && b <= 'Z') b = (char)(b - 'A' + 'a');
        if (a != b) return 0;
    }
    return 1;
}

/* nm per unit of a unit word, 0 for none */
static double unit_scale_of(const char *s, const char *e)
{
    size_t n = (size_t)(e - s);
    struct {
        const char *w;
        double scale;
    } const units[] = {
        {"nm", 1.0}, {"nanometer", 1.0}, {"nanometers", 1.0}, {"nanometre", 1.0}, {"nanometres", 1.0},
        {"um", 1000.0}, {"\xc2\xb5m", 1000.0}, {"\xce\xbcm", 1000.0}, {"micron", 1000.0}, {"microns", 1000.0},
        {"micrometer", 1000.0}, {"micrometers", 1000.0}, {"micrometre", 1000.0}, {"micrometres", 1000.0},
        {"A", 0.1}, {"\xc3\x85", 0.1}, {"\xe2\x84\xab", 0.1}, {"angstrom", 0.1}, {"angstroms", 0.1},
    };
    for (size_t i = 0; i < sizeof units / sizeof *units; i++) {
        size_t m = strlen(units[i].w);
        if (m != n) continue;
        /* "A" only in capitals (a lower-case "a" is too common); the words in any case */
        if (!strcmp(units[i].w, "A") ? !memcmp(s, "A", 1) : lx__starts_ci(s, e, units[i].w)) return units[i].scale;
    }
    return 0.0;
}

double lx__wl_unit_word(const char *s, const char *e)
{
    while (s < e && is_blank(*s)) s++;
    while (e > s && is_blank(e[-1])) e--;
    if (s >= e) return 0.0;
    /* a unit in brackets or parentheses anywhere: "Wavelength [nm]", "lambda (um)", "[A]" */
    for (const char *p = s; p < e; p++) {
        if (*p != '[' && *p != '(') continue;
        char close = *p == '[' ? ']' : ')';
        const char *q = memchr(p + 1, close, (size_t)(e - p - 1));
        if (!q) break;
        const char *a = p + 1, *b = q;
        while (a < b && is_blank(*a)) a++;
        while (b > a && is_blank(b[-1])) b--;
        double k = unit_scale_of(a, b);
        if (k > 0) return k;
    }
    /* the whole cell, or its last word after '_', '-', ' ' or '/': "nm", "wavelength_um", "wl A" */
    double k = unit_scale_of(s, e);
    if (k > 0) return k;
    for (const char *p = e; p > s; p--) {
        if (p[-1] == '_' || p[-1] == '-' || p[-1] == ' ' || p[-1] == '/') return unit_scale_of(p, e);
    }
    return 0.0;
}

/* ---- the layouts ---- */

static const char *const formats[] = {"columns", "rows", "cgats", "oceanview", "sekonic", "uprtek",
                                      "tm27", "avantes", "spectrawiz", NULL};

const char *const *lx_spd_formats(void) { return formats; }

const char *lx_spd_set_field(const lx_spd_set *set, const char *key)
{
    if (!set || !key) return NULL;
    for (size_t i = 0; i < set->nfields; i++)
        if (!strcmp(set->fields[i].key, key)) return set->fields[i].value;
    return NULL;
}

static lx_status read_layout(lx__rd *rd, const char *text, size_t len, lx_spd_set **out)
{
    const char *f = rd->opts.format;
    if (f && *f && strcmp(f, "auto") != 0) {
        if (!strcmp(f, "columns")) return lx__text_read(rd, text, len, 1, out);
        if (!strcmp(f, "rows")) return lx__text_read(rd, text, len, 2, out);
        if (!strcmp(f, "avantes")) return rd->format = "avantes", lx__text_read(rd, text, len, 1, out);
        if (!strcmp(f, "cgats")) return lx__cgats_read(rd, text, len, out);
        if (!strcmp(f, "oceanview")) return lx__oceanview_read(rd, text, len, out);
        if (!strcmp(f, "sekonic")) return lx__sekonic_read(rd, text, len, out);
        if (!strcmp(f, "uprtek")) return lx__uprtek_read(rd, text, len, out);
        if (!strcmp(f, "tm27")) return lx__tm27_read(rd, text, len, out);
        if (!strcmp(f, "spectrawiz")) return lx__spectrawiz_read(rd, text, len, out);
        return lx__error(rd->ctx, LX_EINVAL, rd->file, 0,
                         "unknown input format '%s' (columns, rows, cgats, oceanview, sekonic, uprtek, tm27, "
                         "avantes, spectrawiz)", f);
    }
    if (lx__tm27_detect(text, len)) return lx__tm27_read(rd, text, len, out);
    if (lx__cgats_detect(text, len)) return lx__cgats_read(rd, text, len, out);
    if (lx__oceanview_detect(text, len)) return lx__oceanview_read(rd, text, len, out);
    if (lx__sekonic_detect(text, len)) return lx__sekonic_read(rd, text, len, out);
    if (lx__uprtek_detect(text, len)) return lx__uprtek_read(rd, text, len, out);
    if (lx__spectrawiz_detect(text, len)) return lx__spectrawiz_read(rd, text, len, out);
    return lx__text_read(rd, text, len, 0, out);
}

static double max_wavelength(const lx_spd_set *set)
{
    double m = 0;
    for (size_t i = 0; i < set->count; i++)
        if (set->spd[i].n && set->spd[i].lambda_nm[set->spd[i].n - 1] > m) m = set->spd[i].lambda_nm[set->spd[i].n - 1];
    return m;
}

/* Wavelengths to nm: --wavelength-unit, else a unit a header named, else micrometres when every
 * wavelength is below 10 (no spectrum of light is sampled below 10 nm). */
static lx_status wavelength_units(lx__rd *rd, lx_spd_set *set)
{
    double k = 1.0;
    const char *wu = rd->opts.wavelength_unit;
    if (wu && *wu) {
        k = unit_scale_of(wu, wu + strlen(wu));
        if (!strcmp(wu, "a")) k = 0.1;
        if (!(k > 0))
            return lx__error(rd->ctx, LX_EINVAL, rd->file, 0, "unknown wavelength unit '%s' (nm, um or A)", wu);
    } else if (rd->wl_scale > 0) {
        k = rd->wl_scale;
        if (k != 1.0)
            lx__log(rd->ctx, LX_LOG_INFO, "%s: wavelengths in %s (%s): converted to nm", rd->file,
                    k == 1000.0 ? "micrometres" : "angstrom", rd->wl_source ? rd->wl_source : "header");
    } else if (max_wavelength(set) < 10.0) {
        k = 1000.0;
        lx__log(rd->ctx, LX_LOG_INFO,
                "%s: every wavelength is below 10: read as micrometres (--wavelength-unit nm keeps them)", rd->file);
    }
    set->wavelength_scale = k;
    if (k != 1.0)
        for (size_t i = 0; i < set->count; i++) {
            double *l = (double *)set->spd[i].lambda_nm;
            for (size_t j = 0; j < set->spd[i].n; j++) l[j] *= k;
        }
    return LX_OK;
}

static void finish(lx__rd *rd, lx_spd_set *set)
{
    set->format = rd->format ? rd->format : "columns";
    set->fields = rd->fields, set->nfields = rd->nfields;
    set->skipped = rd->skipped, set->nskipped = rd->nskipped;
    rd->fields = NULL, rd->nfields = rd->fcap = 0;
    rd->skipped = NULL, rd->nskipped = rd->scap = 0;
    if (rd->unit) {
        set->unit = rd->unit;
        set->unit_scale = rd->unit_scale > 0 ? rd->unit_scale : 1.0;
        set->unit_source = rd->unit_source;
        if (set->unit_scale != 1.0)
            for (size_t i = 0; i < set->count; i++) {
                double *v = (double *)set->spd[i].value;
                for (size_t j = 0; j < set->spd[i].n; j++) v[j] *= set->unit_scale;
            }
        lx__log(rd->ctx, LX_LOG_INFO, "%s: values in %s (%s)%s", rd->file, set->unit,
                rd->unit_source ? rd->unit_source : "the format", set->unit_scale != 1.0 ? ", converted" : "");
    }
    for (size_t i = 0; i < set->count; i++) {
        const lx_spd *s = &set->spd[i];
        if (s->n && (s->lambda_nm[s->n - 1] < 360.0 || s->lambda_nm[0] > 830.0))
            lx__log(rd->ctx, LX_LOG_WARN,
                    "%s:%ld: spectrum '%s' (%.6g-%.6g nm) has no overlap with 360-830 nm: its photometric values are 0",
                    set->file, set->line ? set->line[i] : 0L, s->name ? s->name : "", s->lambda_nm[0],
                    s->lambda_nm[s->n - 1]);
    }
}

static void rd_free(lx__rd *rd)
{
    for (size_t i = 0; i < rd->nfields; i++) {
        lx__free(rd->fields[i].key);
        lx__free(rd->fields[i].value);
    }
    for (size_t i = 0; i < rd->nskipped; i++) lx__free(rd->skipped[i].why);
    lx__free(rd->fields);
    lx__free(rd->skipped);
}

/* ---- entry points ---- */

lx_status lx_spd_read_mem_opts(lx_ctx *ctx, const char *name, const char *text, size_t len,
                               const lx_spd_read_opts *opts, lx_spd_set **out)
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
    lx__rd rd;
    memset(&rd, 0, sizeof rd);
    rd.ctx = ctx;
    rd.file = file;
    if (opts) rd.opts = *opts;
    for (size_t k = 0; k < sizeof rd.opts.reserved / sizeof *rd.opts.reserved; k++)
        if (rd.opts.reserved[k]) return lx__error(ctx, LX_EINVAL, file, 0, "lx_spd_read_opts: reserved must be zero");
    if (rd.opts.skip_lines < 0)
        return lx__error(ctx, LX_EINVAL, file, 0, "skip_lines must not be negative (%ld)", rd.opts.skip_lines);
    for (long k = 0; k < rd.opts.skip_lines && len; k++) { /* whole lines, counted */
        const char *nl = memchr(text, '\n', len);
        size_t step = nl ? (size_t)(nl - text) + 1 : len;
        text += step;
        len -= step;
        rd.line0++;
    }
    lx_spd_set *set = NULL;
    lx_status st = read_layout(&rd, text, len, &set);
    if (st == LX_OK) st = wavelength_units(&rd, set);
    if (st == LX_OK) {
        finish(&rd, set);
        *out = set;
    } else {
        lx_spd_set_free(set);
    }
    rd_free(&rd);
    return st;
}

lx_status lx_spd_read_mem(lx_ctx *ctx, const char *name, const char *text, size_t len, lx_spd_set **out)
{
    return lx_spd_read_mem_opts(ctx, name, text, len, NULL, out);
}

lx_status lx_spd_read_file_opts(lx_ctx *ctx, const char *path, const lx_spd_read_opts *opts, lx_spd_set **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spd_read_file: NULL argument");
    char *buf;
    size_t len;
    lx_status st = lx__read_all(ctx, path, LX_INPUT_SPECTRUM, &buf, &len);
    if (st != LX_OK) return st;
    st = lx_spd_read_mem_opts(ctx, path, buf, len, opts, out);
    lx__free(buf);
    return st;
}

lx_status lx_spd_read_file(lx_ctx *ctx, const char *path, lx_spd_set **out)
{
    return lx_spd_read_file_opts(ctx, path, NULL, out);
}

lx_status lx_spd_read_stream(lx_ctx *ctx, const char *name, FILE *in, const char *prefix, size_t prefix_len,
                             const lx_spd_read_opts *opts, lx_spd_set **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!in || !out || (!prefix && prefix_len)) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spd_read_stream: NULL argument");
    const char *file = name ? name : "(stream)";
    char *buf;
    size_t len;
    lx_status st = lx__read_stream(ctx, file, LX_INPUT_SPECTRUM, in, prefix, prefix_len, &buf, &len);
    if (st != LX_OK) return st;
    st = lx_spd_read_mem_opts(ctx, file, buf, len, opts, out);
    lx__free(buf);
    return st;
}
