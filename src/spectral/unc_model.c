/* unc_model.c - the input model of a measured spectrum's uncertainty: its components (uncorrelated
 * noise, a scale, a wavelength shift, a bandwidth, Kaerhae's Fourier model, a full covariance) and
 * their binding to one spectrum: grids checked against the spectrum's, relative values made
 * absolute, a covariance checked to be positive semi-definite. */
#include "spectral/unc_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const kind_name[] = {"noise", "scale", "shift", "bandwidth", "fourier", "covariance"};

lx_status lx_unc_model_create(lx_ctx *ctx, lx_unc_model **out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty model: NULL output");
    *out = calloc(1, sizeof **out);
    return *out ? LX_OK : lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
}

static void comp_free(lx__unc_comp *c)
{
    lx__free((void *)c->c.lambda_nm);
    lx__free((void *)c->c.u);
    lx__free((void *)c->c.cov);
    lx__free((void *)c->c.label);
}

void lx_unc_model_free(lx_unc_model *m)
{
    if (!m) return;
    for (size_t i = 0; i < m->count; i++) comp_free(&m->comp[i]);
    lx__free(m->comp);
    lx__free(m);
}

size_t lx_unc_model_count(const lx_unc_model *m) { return m ? m->count : 0; }

const char *lx_unc_model_label(const lx_unc_model *m, size_t i) { return m && i < m->count ? m->comp[i].c.label : NULL; }

int lx_unc_model_uses(const lx_unc_model *m, const lx_spd *spd)
{
    if (!m || !spd) return 0;
    for (size_t i = 0; i < m->ncolumn; i++)
        if (m->column_of[i] == spd) return 1;
    return 0;
}

static double *dup(const double *p, size_t n)
{
    if (!p || !n) return NULL;
    double *q = lx__alloc(n * sizeof *q);
    if (q) memcpy(q, p, n * sizeof *q);
    return q;
}

/* The checks of one component that need no spectrum. */
static lx_status comp_check(lx_ctx *ctx, const lx_unc_component *c, const char *name)
{
    lx_status st = lx__check_reserved(ctx, "uncertainty component", c->reserved, sizeof c->reserved);
    if (st != LX_OK) return st;
    if ((int)c->kind < 0 || c->kind > LX_UNC_COVARIANCE)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty component: unknown kind %d", (int)c->kind);
    if (!(c->sigma >= 0) || !isfinite(c->sigma))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: the standard uncertainty must be finite and not negative, not %g", name,
                         c->sigma);
    if (c->kind == LX_UNC_BANDWIDTH && (!(c->bandwidth_nm >= 0) || !isfinite(c->bandwidth_nm)))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: the nominal bandpass must be finite and not negative, not %g nm", name,
                         c->bandwidth_nm);
    if (c->kind == LX_UNC_FOURIER && (c->terms < 0 || c->terms > 1000))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: the number of terms must be 0 to 1000, not %d", name, c->terms);
    if (c->kind == LX_UNC_COVARIANCE && (!c->cov || c->n < 2))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: needs an n x n matrix (n >= 2)", name);
    if (c->kind == LX_UNC_NOISE && c->n && !c->u) return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: u is NULL", name);
    if (c->n && c->lambda_nm)
        for (size_t i = 0; i < c->n; i++)
            if (!isfinite(c->lambda_nm[i]) || (i && !(c->lambda_nm[i] > c->lambda_nm[i - 1])))
                return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: wavelength %zu (%g nm) is not finite and increasing", name, i + 1,
                                 c->lambda_nm[i]);
    if (c->kind == LX_UNC_NOISE && c->u)
        for (size_t i = 0; i < c->n; i++)
            if (!(c->u[i] >= 0) || !isfinite(c->u[i]))
                return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: the uncertainty at %s%g%s is %g (must be finite, not negative)", name,
                                 c->lambda_nm ? "" : "sample ", c->lambda_nm ? c->lambda_nm[i] : (double)(i + 1),
                                 c->lambda_nm ? " nm" : "", c->u[i]);
    if (c->kind == LX_UNC_COVARIANCE)
        for (size_t i = 0; i < c->n * c->n; i++)
            if (!isfinite(c->cov[i]))
                return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: element (%zu, %zu) is not finite", name, i / c->n + 1, i % c->n + 1);
    return LX_OK;
}

lx_status lx_unc_model_add(lx_ctx *ctx, lx_unc_model *m, const lx_unc_component *c)
{
    LX__NEED_CTX(ctx);
    if (!m || !c) return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty model: NULL argument");
    const char *name = c->label ? c->label : (int)c->kind >= 0 && c->kind <= LX_UNC_COVARIANCE ? kind_name[c->kind] : "?";
    lx_status st = comp_check(ctx, c, name);
    if (st != LX_OK) return st;
    if (m->count == m->cap) {
        size_t cap = m->cap ? 2 * m->cap : 4;
        lx__unc_comp *p = lx__realloc(m->comp, cap * sizeof *p);
        if (!p) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        m->comp = p, m->cap = cap;
    }
    lx__unc_comp k;
    memset(&k, 0, sizeof k);
    k.c = *c;
    k.c.lambda_nm = dup(c->lambda_nm, c->n);
    k.c.u = c->kind == LX_UNC_NOISE ? dup(c->u, c->n) : NULL;
    k.c.cov = c->kind == LX_UNC_COVARIANCE ? dup(c->cov, c->n * c->n) : NULL;
    k.c.label = lx__strdup(name);
    if ((c->lambda_nm && c->n && !k.c.lambda_nm) || (c->kind == LX_UNC_NOISE && c->u && c->n && !k.c.u) ||
        (c->kind == LX_UNC_COVARIANCE && !k.c.cov) || !k.c.label) {
        comp_free(&k);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    if (c->kind != LX_UNC_NOISE && c->kind != LX_UNC_COVARIANCE) k.c.n = 0;
    m->comp[m->count++] = k;
    return LX_OK;
}

/* ---- binding to a spectrum ---- */

double lx__unc_shifted(const lx_spd *spd, double x, size_t *hint)
{
    const double *l = spd->lambda_nm, *v = spd->value;
    size_t n = spd->n;
    if (x <= l[0]) return v[0];
    if (x >= l[n - 1]) return v[n - 1];
    size_t i = hint && *hint < n - 1 ? *hint : 0;
    while (i > 0 && l[i] > x) i--;
    while (i + 2 < n && l[i + 1] <= x) i++;
    if (hint) *hint = i;
    if (x == l[i]) return v[i];
    return v[i] + (x - l[i]) / (l[i + 1] - l[i]) * (v[i + 1] - v[i]);
}

/* The component's grid against the spectrum's: LX_EINVAL naming the first difference. */
static lx_status same_grid(lx_ctx *ctx, const lx_unc_component *c, const lx_spd *spd)
{
    if (c->n != spd->n && c->lambda_nm)
        return lx__error(ctx, LX_EINVAL, NULL, 0,
                         "%s: its grid is not the spectrum's: %zu samples over %g-%g nm, the spectrum's %zu over %g-%g nm",
                         c->label, c->n, c->lambda_nm[0], c->lambda_nm[c->n - 1], spd->n, spd->lambda_nm[0],
                         spd->lambda_nm[spd->n - 1]);
    if (c->n != spd->n)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: %zu values for a spectrum of %zu samples (%g-%g nm)", c->label, c->n,
                         spd->n, spd->lambda_nm[0], spd->lambda_nm[spd->n - 1]);
    if (c->lambda_nm)
        for (size_t i = 0; i < c->n; i++)
            if (fabs(c->lambda_nm[i] - spd->lambda_nm[i]) > 1e-6)
                return lx__error(ctx, LX_EINVAL, NULL, 0,
                                 "%s: its grid is not the spectrum's: sample %zu is at %g nm, the spectrum's at %g nm", c->label,
                                 i + 1, c->lambda_nm[i], spd->lambda_nm[i]);
    return LX_OK;
}

/* A covariance must be symmetric (to 1e-9, the digits of a file) and positive semi-definite: its
 * smallest eigenvalue above -1e-10 of its largest (rounding of a singular matrix). */
static lx_status psd_check(lx_ctx *ctx, const char *label, size_t n, const double *C)
{
    double *ev = lx__alloc(n * sizeof *ev);
    if (!ev) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            double a = C[i * n + j], b = C[j * n + i];
            if (fabs(a - b) > 1e-9 * fmax(fabs(a), fabs(b)) + 1e-12 * sqrt(fabs(C[i * n + i] * C[j * n + j]))) {
                lx__free(ev);
                return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: not symmetric: element (%zu, %zu) is %g, (%zu, %zu) is %g", label,
                                 i + 1, j + 1, a, j + 1, i + 1, b);
            }
        }
    lx_status st = lx__sym_eigenvalues(n, C, ev);
    if (st != LX_OK) {
        lx__free(ev);
        return st == LX_ENOMEM ? lx__error(ctx, st, NULL, 0, "out of memory")
                               : lx__error(ctx, LX_EINVAL, NULL, 0, "%s: its eigenvalues do not converge", label);
    }
    double lo = ev[0], hi = ev[n - 1];
    size_t neg = 0;
    for (size_t i = 0; i < n; i++)
        if (ev[i] < -1e-10 * fabs(hi)) neg++;
    lx__free(ev);
    if (neg || !(hi >= 0))
        return lx__error(ctx, LX_EINVAL, NULL, 0,
                         "%s: not positive semi-definite: %zu negative eigenvalue%s, the smallest %.6g (the largest %.6g); "
                         "no distribution has this covariance",
                         label, neg, neg == 1 ? "" : "s", lo, hi);
    return LX_OK;
}

/* The mean of the two one-sided slopes at each sample (the ends: half their one slope, the value
 * being held beyond them): the derivative of the shifted spectrum's mean response. */
static void slopes(const lx_spd *s, double *out)
{
    size_t n = s->n;
    for (size_t i = 0; i < n; i++) {
        double l = i > 0 ? (s->value[i] - s->value[i - 1]) / (s->lambda_nm[i] - s->lambda_nm[i - 1]) : 0.0;
        double r = i + 1 < n ? (s->value[i + 1] - s->value[i]) / (s->lambda_nm[i + 1] - s->lambda_nm[i]) : 0.0;
        out[i] = -0.5 * (l + r); /* S(lambda - d): d/dd = -S' */
    }
}

static void second_differences(const lx_spd *s, double *out)
{
    size_t n = s->n;
    out[0] = out[n - 1] = 0.0;
    for (size_t i = 1; i + 1 < n; i++) {
        double h0 = s->lambda_nm[i] - s->lambda_nm[i - 1], h1 = s->lambda_nm[i + 1] - s->lambda_nm[i];
        out[i] = 2.0 * ((s->value[i + 1] - s->value[i]) / h1 - (s->value[i] - s->value[i - 1]) / h0) / (h0 + h1);
    }
}

static lx_status bind_one(lx_ctx *ctx, const lx_unc_component *c, const lx_spd *spd, lx__unc_bound *b)
{
    size_t n = spd->n;
    b->kind = c->kind, b->sigma = c->sigma, b->label = c->label, b->terms = c->terms;
    lx_status st;
    switch (c->kind) {
    case LX_UNC_NOISE:
        if (c->u && (st = same_grid(ctx, c, spd)) != LX_OK) return st;
        if (!(b->u2 = lx__alloc(n * sizeof *b->u2))) break;
        for (size_t i = 0; i < n; i++) {
            double u = !c->u ? (c->absolute ? c->sigma : c->sigma * spd->value[i]) : c->relative ? c->u[i] * spd->value[i] : c->u[i];
            b->u2[i] = u * u;
        }
        return LX_OK;
    case LX_UNC_COVARIANCE:
        if ((st = same_grid(ctx, c, spd)) != LX_OK) return st;
        if ((st = psd_check(ctx, c->label, n, c->cov)) != LX_OK) return st;
        if (!(b->u2 = lx__alloc(n * n * sizeof *b->u2))) break;
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++) {
                double v = 0.5 * (c->cov[i * n + j] + c->cov[j * n + i]);
                b->u2[i * n + j] = c->relative ? v * spd->value[i] * spd->value[j] : v;
            }
        return LX_OK;
    case LX_UNC_SCALE:
    case LX_UNC_FOURIER:
        if (!(b->vec = dup(spd->value, n))) break;
        return LX_OK;
    case LX_UNC_SHIFT:
        if (!(b->vec = lx__alloc(n * sizeof *b->vec))) break;
        slopes(spd, b->vec);
        return LX_OK;
    case LX_UNC_BANDWIDTH:
        if (!(b->vec = lx__alloc(n * sizeof *b->vec))) break;
        second_differences(spd, b->vec);
        b->b0 = c->bandwidth_nm > 0 ? c->bandwidth_nm : (spd->lambda_nm[n - 1] - spd->lambda_nm[0]) / (double)(n - 1);
        return LX_OK;
    }
    return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
}

void lx__unc_unbind(lx__unc_bound *b, size_t count)
{
    if (!b) return;
    for (size_t i = 0; i < count; i++) lx__free(b[i].u2), lx__free(b[i].vec);
    lx__free(b);
}

lx_status lx__unc_bind(lx_ctx *ctx, const lx_unc_model *m, const lx_spd *spd, lx__unc_bound **out)
{
    *out = NULL;
    lx__unc_bound *b = lx__calloc(m->count ? m->count : 1, sizeof *b);
    if (!b) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; i < m->count; i++) {
        lx_status st = bind_one(ctx, &m->comp[i].c, spd, &b[i]);
        if (st != LX_OK) {
            lx__unc_unbind(b, m->count);
            return st;
        }
    }
    *out = b;
    return LX_OK;
}
