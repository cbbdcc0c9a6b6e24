/* unc_spec.c - an input model from text (lx_unc_model_parse): terms joined with '+' ("1%",
 * "scale=0.5%", "shift=0.1nm", "bandwidth=0.2nm@5nm", "fourier=1%:3", "column=u", "file=U.csv",
 * "covariance=C.csv"), the per-wavelength uncertainties of another spectrum file and a covariance
 * matrix read from CSV. */
#include "spectral/unc_private.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A number at [s, e) with an optional unit suffix: '%' (per cent: *out / 100, *pct 1) or "nm". */
static int number(const char *s, const char *e, double *out, int *pct, int *nm)
{
    while (s < e && isspace((unsigned char)*s)) s++;
    while (e > s && isspace((unsigned char)e[-1])) e--;
    *pct = 0;
    if (nm) *nm = 0;
    if (e > s && e[-1] == '%') *pct = 1, e--;
    else if (nm && e - s > 2 && !strncmp(e - 2, "nm", 2)) *nm = 1, e -= 2;
    while (e > s && isspace((unsigned char)e[-1])) e--;
    const char *q = lx__parse_double(s, e, out);
    if (!q || q != e || !isfinite(*out)) return 0;
    if (*pct) *out /= 100.0;
    return 1;
}

/* ---- a covariance matrix from CSV ---- */

typedef struct rows {
    double *v;
    size_t n, cap;
    size_t *len; /* cells per row */
    long *line;
    size_t nrows, rcap;
    int header;  /* the first row led by a word: its numbers are wavelengths */
} rows;

static int push(double **v, size_t *n, size_t *cap, double x)
{
    if (*n == *cap) {
        size_t c = *cap ? 2 * *cap : 1024;
        double *p = lx__realloc(*v, c * sizeof *p);
        if (!p) return -1;
        *v = p, *cap = c;
    }
    (*v)[(*n)++] = x;
    return 0;
}

static lx_status read_rows(lx_ctx *ctx, const char *path, const char *text, size_t len, rows *R)
{
    lx__lines it = {text, text + len, 0};
    const char *s, *e;
    while (lx__next_line(&it, &s, &e)) {
        while (s < e && isspace((unsigned char)*s)) s++;
        if (s == e || *s == '#') continue;
        if (R->nrows == R->rcap) {
            size_t c = R->rcap ? 2 * R->rcap : 64;
            size_t *l = lx__realloc(R->len, c * sizeof *l);
            if (l) R->len = l;
            long *ln = lx__realloc(R->line, c * sizeof *ln);
            if (ln) R->line = ln;
            if (!l || !ln) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
            R->rcap = c;
        }
        size_t cells = 0;
        const char *p = s;
        while (p < e) {
            const char *q = p;
            while (q < e && *q != ',' && *q != ';' && *q != '\t' && *q != ' ') q++;
            if (q > p) {
                double x;
                const char *end = lx__parse_double(p, q, &x);
                if (!end || end != q || !isfinite(x)) {
                    if (R->nrows == 0 && cells == 0) R->header = 1; /* "nm,380,385,..." */
                    else
                        return lx__error(ctx, LX_EPARSE, path, it.line, "'%.*s' is not a number", (int)(q - p > 40 ? 40 : q - p), p);
                } else if (push(&R->v, &R->n, &R->cap, x)) {
                    return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
                } else {
                    cells++;
                }
            }
            p = q < e ? q + 1 : q;
        }
        R->len[R->nrows] = cells, R->line[R->nrows] = it.line;
        R->nrows++;
    }
    return LX_OK;
}

/* The matrix of a covariance file: n rows of n numbers, or a row of n wavelengths (led by a word or
 * not) and n rows each led by its wavelength. */
static lx_status covariance_file(lx_ctx *ctx, const char *path, lx_unc_component *c, double **lam, double **cov)
{
    char *text = NULL;
    size_t len = 0;
    lx_status st = lx__read_all(ctx, path, LX_INPUT_SPECTRUM, &text, &len);
    if (st != LX_OK) return st;
    rows R;
    memset(&R, 0, sizeof R);
    st = read_rows(ctx, path, text, len, &R);
    lx__free(text);
    size_t n = 0;
    if (st == LX_OK && R.nrows == 0) st = lx__error(ctx, LX_EPARSE, path, 0, "no numbers: expected a covariance matrix");
    if (st == LX_OK) {
        int labelled = R.header || (R.nrows >= 2 && R.len[1] == R.len[0] + 1);
        n = labelled ? R.len[0] : R.len[0];
        size_t want_rows = labelled ? n + 1 : n;
        if (R.nrows != want_rows)
            st = lx__error(ctx, LX_EPARSE, path, R.line[R.nrows - 1], "%zu rows of numbers: a %zu x %zu matrix needs %zu%s",
                           R.nrows, n, n, want_rows, labelled ? " (a row of wavelengths and one per wavelength)" : "");
        for (size_t i = labelled; st == LX_OK && i < R.nrows; i++)
            if (R.len[i] != n + (size_t)labelled)
                st = lx__error(ctx, LX_EPARSE, path, R.line[i], "%zu numbers in this row, expected %zu", R.len[i],
                               n + (size_t)labelled);
        if (st == LX_OK && n < 2) st = lx__error(ctx, LX_EPARSE, path, R.line[0], "a covariance matrix needs at least 2 rows");
        if (st == LX_OK) {
            *cov = malloc(n * n * sizeof **cov);
            *lam = labelled ? malloc(n * sizeof **lam) : NULL;
            if (!*cov || (labelled && !*lam)) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        }
        for (size_t i = 0; st == LX_OK && i < n; i++) {
            const double *row = R.v + (labelled ? n + i * (n + 1) : i * n);
            if (labelled) {
                (*lam)[i] = R.v[i];
                if (fabs(row[0] - R.v[i]) > 1e-6)
                    st = lx__error(ctx, LX_EPARSE, path, R.line[i + 1], "the row of %g nm where the header's %zu-th wavelength is %g nm",
                                   row[0], i + 1, R.v[i]);
                row++;
            }
            memcpy(*cov + i * n, row, n * sizeof *row);
        }
    }
    lx__free(R.v), lx__free(R.len), lx__free(R.line);
    if (st != LX_OK) {
        lx__free(*cov), lx__free(*lam);
        *cov = *lam = NULL;
        return st;
    }
    c->n = n, c->cov = *cov, c->lambda_nm = *lam;
    return LX_OK;
}

/* ---- the terms ---- */

static lx_status bad(lx_ctx *ctx, const char *term, const char *why)
{
    return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty '%s': %s", term, why);
}

/* "NAME[:%]" or "PATH[:%]": the name and whether the values are per cent. */
static int percent_suffix(char *v)
{
    size_t l = strlen(v);
    if (l > 2 && !strcmp(v + l - 2, ":%")) {
        v[l - 2] = 0;
        return 1;
    }
    return 0;
}

static lx_status term_column(lx_ctx *ctx, lx_unc_model *m, const char *term, char *v, const lx_spd_set *set)
{
    int pc = percent_suffix(v);
    if (!set) return bad(ctx, term, "column= needs the spectrum's own file (a column of it)");
    const lx_spd *col = NULL;
    char *end;
    long idx = strtol(v, &end, 10);
    for (size_t i = 0; i < set->count && !col; i++)
        if (set->spd[i].name && !strcmp(set->spd[i].name, v)) col = &set->spd[i];
    /* a number: the file's column (the first value column is 2) */
    if (!col && *v && !*end && idx >= 2 && (size_t)idx - 2 < set->count) col = &set->spd[idx - 2];
    if (!col) {
        char names[256] = "";
        for (size_t i = 0; i < set->count && strlen(names) < 200; i++)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s'%s'", i ? ", " : "",
                     set->spd[i].name ? set->spd[i].name : "");
        return lx__error(ctx, LX_EINVAL, set->file, 0, "uncertainty '%s': no column '%s' (the file's columns: %s)", term, v, names);
    }
    if (m->ncolumn < sizeof m->column_of / sizeof *m->column_of) m->column_of[m->ncolumn++] = col;
    lx_unc_component c;
    memset(&c, 0, sizeof c);
    c.kind = LX_UNC_NOISE, c.n = col->n, c.lambda_nm = col->lambda_nm, c.u = col->value, c.label = term;
    double *u = NULL;
    if (pc) { /* per cent of the values */
        if (!(u = lx__alloc(col->n * sizeof *u))) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        for (size_t i = 0; i < col->n; i++) u[i] = col->value[i] / 100.0;
        c.u = u, c.relative = 1;
    }
    lx_status st = lx_unc_model_add(ctx, m, &c);
    lx__free(u);
    return st;
}

static lx_status term_file(lx_ctx *ctx, lx_unc_model *m, const char *term, char *v, int covariance)
{
    int pc = covariance ? 0 : percent_suffix(v);
    size_t l = strlen(v);
    int rel = covariance && l > 4 && !strcmp(v + l - 4, ":rel");
    if (rel) v[l - 4] = 0;
    lx_unc_component c;
    memset(&c, 0, sizeof c);
    c.label = term;
    if (covariance) {
        double *lam = NULL, *cov = NULL;
        lx_status st = covariance_file(ctx, v, &c, &lam, &cov);
        if (st != LX_OK) return st;
        c.kind = LX_UNC_COVARIANCE, c.relative = rel;
        st = lx_unc_model_add(ctx, m, &c);
        lx__free(lam), lx__free(cov);
        return st;
    }
    lx_spd_set *set = NULL;
    lx_status st = lx_spd_read_file(ctx, v, &set);
    if (st != LX_OK) return st;
    if (set->count != 1) {
        size_t k = set->count;
        lx_spd_set_free(set);
        return lx__error(ctx, LX_EINVAL, v, 0, "uncertainty '%s': the file holds %zu spectra; expected one column of uncertainties",
                         term, k);
    }
    const lx_spd *s = &set->spd[0];
    double *u = lx__alloc(s->n * sizeof *u);
    if (!u) {
        lx_spd_set_free(set);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t i = 0; i < s->n; i++) u[i] = pc ? s->value[i] / 100.0 : s->value[i];
    c.kind = LX_UNC_NOISE, c.n = s->n, c.lambda_nm = s->lambda_nm, c.u = u, c.relative = pc;
    st = lx_unc_model_add(ctx, m, &c);
    lx__free(u);
    lx_spd_set_free(set);
    return st;
}

static lx_status term(lx_ctx *ctx, lx_unc_model *m, const char *t, const lx_spd_set *set)
{
    lx_unc_component c;
    memset(&c, 0, sizeof c);
    c.label = t;
    const char *eq = strchr(t, '=');
    double x;
    int pct, nm;
    if (!eq) {
        if (!number(t, t + strlen(t), &x, &pct, NULL) || !pct)
            return bad(ctx, t, "expected P% (uncorrelated, per cent of each value) or KEY=VALUE with KEY one of noise, "
                               "column, file, scale, shift, bandwidth, fourier, covariance");
        c.kind = LX_UNC_NOISE, c.sigma = x;
        return lx_unc_model_add(ctx, m, &c);
    }
    size_t kl = (size_t)(eq - t);
    char *v = lx__strdup(eq + 1);
    if (!v) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    lx_status st = LX_OK;
    const char *ve = v + strlen(v);
#define KEY(k) (kl == strlen(k) && !strncmp(t, k, kl))
    if (KEY("column")) {
        st = term_column(ctx, m, t, v, set);
    } else if (KEY("file") || KEY("covariance")) {
        st = *v ? term_file(ctx, m, t, v, KEY("covariance")) : bad(ctx, t, "a file name is missing");
    } else if (KEY("noise")) {
        if (!number(v, ve, &x, &pct, NULL)) st = bad(ctx, t, "expected P% or an absolute value in the values' unit");
        else if (pct) c.kind = LX_UNC_NOISE, c.sigma = x, st = lx_unc_model_add(ctx, m, &c);
        else { /* absolute: u at every sample, the spectrum's grid */
            c.kind = LX_UNC_NOISE, c.sigma = x, c.absolute = 1;
            st = lx_unc_model_add(ctx, m, &c);
        }
    } else if (KEY("scale")) {
        if (!number(v, ve, &x, &pct, NULL) || !pct) st = bad(ctx, t, "expected P% (relative)");
        else c.kind = LX_UNC_SCALE, c.sigma = x, st = lx_unc_model_add(ctx, m, &c);
    } else if (KEY("shift")) {
        if (!number(v, ve, &x, &pct, &nm) || pct) st = bad(ctx, t, "expected a wavelength in nm (0.1nm)");
        else c.kind = LX_UNC_SHIFT, c.sigma = x, st = lx_unc_model_add(ctx, m, &c);
    } else if (KEY("bandwidth")) {
        char *at = strchr(v, '@');
        double b0 = 0;
        if (at && (!number(at + 1, ve, &b0, &pct, &nm) || pct || !(b0 > 0)))
            st = bad(ctx, t, "expected the nominal bandpass after '@' in nm (0.2nm@5nm)");
        else if (!number(v, at ? at : ve, &x, &pct, &nm) || pct) st = bad(ctx, t, "expected a bandwidth in nm (0.2nm)");
        else c.kind = LX_UNC_BANDWIDTH, c.sigma = x, c.bandwidth_nm = b0, st = lx_unc_model_add(ctx, m, &c);
    } else if (KEY("fourier")) {
        char *colon = strchr(v, ':');
        long terms = 0;
        char *end = NULL;
        if (colon) terms = strtol(colon + 1, &end, 10);
        if (colon && (end == colon + 1 || *end || terms < 0 || terms > 1000))
            st = bad(ctx, t, "expected the number of terms after ':' (0 to 1000)");
        else if (!number(v, colon ? colon : ve, &x, &pct, NULL) || !pct) st = bad(ctx, t, "expected P% (relative)");
        else c.kind = LX_UNC_FOURIER, c.sigma = x, c.terms = (int)terms, st = lx_unc_model_add(ctx, m, &c);
    } else {
        st = bad(ctx, t, "unknown key (expected noise, column, file, scale, shift, bandwidth, fourier or covariance)");
    }
#undef KEY
    lx__free(v);
    return st;
}

lx_status lx_unc_model_parse(lx_ctx *ctx, const char *spec, const lx_spd_set *set, lx_unc_model **out)
{
    LX__NEED_CTX(ctx);
    if (!spec || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: NULL argument");
    *out = NULL;
    lx_unc_model *m = NULL;
    lx_status st = lx_unc_model_create(ctx, &m);
    if (st != LX_OK) return st;
    /* no empty term: a '+' at either end or two together */
    const char *p = spec;
    while (*p == ' ') p++;
    for (const char *q = spec; st == LX_OK && *q; q++) {
        const char *r = q + 1;
        while (*r == ' ') r++;
        if (*q == '+' && (q == p || !*r || *r == '+')) st = lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty '%s': an empty term", spec);
    }
    char *copy = st == LX_OK ? lx__strdup(spec) : NULL;
    if (st != LX_OK) {
        lx_unc_model_free(m);
        return st;
    }
    if (!copy) {
        lx_unc_model_free(m);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (char *save = NULL, *tok = strtok_r(copy, "+", &save); st == LX_OK && tok; tok = strtok_r(NULL, "+", &save)) {
        while (isspace((unsigned char)*tok)) tok++;
        char *e = tok + strlen(tok);
        while (e > tok && isspace((unsigned char)e[-1])) *--e = 0;
        if (!*tok) st = lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty '%s': an empty term", spec);
        else st = term(ctx, m, tok, set);
    }
    if (st == LX_OK && m->count == 0) st = lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: no term in '%s'", spec);
    lx__free(copy);
    if (st != LX_OK) {
        lx_unc_model_free(m);
        return st;
    }
    *out = m;
    return LX_OK;
}
