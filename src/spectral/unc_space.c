/* unc_space.c - an input model in the space of the integrals the quantities are computed from.
 * Every quantity of lx_spd_uncertainty is a function of K linear integrals L = A S of the spectrum
 * (A: the weights of the integration method), so every component's effect is its effect on L:
 * the normal linear ones (noise, a covariance, a scale) a multivariate normal with covariance
 * A C A^T, drawn through its pivoted Cholesky factor; a wavelength shift a piecewise-linear function
 * of the shift, tabulated at its breakpoints; a bandwidth error a multiple of A S''; Kaerhae's
 * Fourier model a combination of 2 N + 1 fixed vectors. A trial then costs O(K r), not O(K n). */
#include "spectral/unc_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SHIFT_TABLE_MAX 4096 /* breakpoints; beyond it a shift is integrated per trial */
#define FOURIER_AUTO_MAX 50  /* terms scanned for the unfavourable N */

/* y = A x (K x n times n) */
static void matvec(const double *A, size_t K, size_t n, const double *x, double *y)
{
    for (size_t k = 0; k < K; k++) {
        const double *a = A + k * n;
        double s = 0.0;
        for (size_t j = 0; j < n; j++) s += a[j] * x[j];
        y[k] = s;
    }
}


static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The breakpoints of the shift within +-dmax: where a sample lambda_j - d meets a sample. */
static size_t shift_breakpoints(const lx_spd *spd, double dmax, double *d, size_t cap)
{
    size_t nb = 0, n = spd->n;
    d[nb++] = -dmax, d[nb++] = 0.0, d[nb++] = dmax;
    for (size_t i = 0; i < n && nb <= cap; i++)
        for (size_t j = i + 1; j < n && spd->lambda_nm[j] - spd->lambda_nm[i] < dmax; j++) {
            if (nb + 2 > cap) return cap + 1;
            double g = spd->lambda_nm[j] - spd->lambda_nm[i];
            d[nb++] = g, d[nb++] = -g;
        }
    qsort(d, nb, sizeof *d, cmp_double);
    size_t m = 0;
    for (size_t i = 0; i < nb; i++)
        if (m == 0 || d[i] > d[m - 1]) d[m++] = d[i];
    return m;
}

static lx_status shift_table(lx_ctx *ctx, lx__unc_space *sp)
{
    const lx_spd *spd = sp->spd;
    size_t n = sp->n, K = sp->K;
    double dmax = LX__UNC_Z_MAX * sp->shift_sigma * (1 + 1e-9);
    double *d = lx__alloc((SHIFT_TABLE_MAX + 2) * sizeof *d);
    if (!d) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    size_t nb = shift_breakpoints(spd, dmax, d, SHIFT_TABLE_MAX);
    if (nb > SHIFT_TABLE_MAX) { /* a dense irregular grid: the shift is integrated per trial */
        lx__free(d);
        return LX_OK;
    }
    double *T = lx__alloc(nb * K * sizeof *T), *s = lx__alloc(n * sizeof *s);
    if (!T || !s) {
        lx__free(d), lx__free(T), lx__free(s);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t b = 0; b < nb; b++) {
        size_t hint = 0;
        for (size_t j = 0; j < n; j++) s[j] = lx__unc_shifted(spd, spd->lambda_nm[j] - d[b], &hint);
        matvec(sp->A, K, n, s, T + b * K);
        for (size_t k = 0; k < K; k++) T[b * K + k] -= sp->L0[k];
    }
    lx__free(s);
    sp->nshift = nb, sp->shift_d = d, sp->shift_T = T;
    return LX_OK;
}

/* The normal part's factor: the pivoted Cholesky factor of the sum of the normal components'
 * covariances, scaled to unit diagonal first (the integrals differ by orders of magnitude), to
 * 1e-14 of the largest variance. */
static lx_status normal_factor(lx_ctx *ctx, lx__unc_space *sp)
{
    size_t K = sp->K;
    double *U = lx__calloc(K * K, sizeof *U), *g = lx__calloc(K * K, sizeof *g), *s = lx__alloc(K * sizeof *s);
    if (!U || !g || !s) {
        lx__free(U), lx__free(g), lx__free(s);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    int any = 0;
    for (size_t c = 0; c < sp->ncomp; c++) {
        if (!sp->gauss[c]) continue;
        any = 1;
        const lx__unc_factor *f = &sp->fac[c];
        for (size_t r = 0; r < f->m; r++) {
            const double *v = f->F + r * K;
            for (size_t i = 0; i < K; i++)
                if (v[i] != 0.0)
                    for (size_t j = 0; j < K; j++) U[i * K + j] += v[i] * v[j];
        }
    }
    size_t r = 0;
    if (any) {
        for (size_t i = 0; i < K; i++) s[i] = U[i * K + i] > 0 ? sqrt(U[i * K + i]) : 0.0;
        for (size_t i = 0; i < K; i++)
            for (size_t j = 0; j < K; j++) U[i * K + j] = s[i] > 0 && s[j] > 0 ? U[i * K + j] / (s[i] * s[j]) : 0.0;
        lx__pivoted_cholesky(K, U, 1e-14, g, &r);
    }
    sp->r = r;
    sp->G = lx__alloc((K * r > 0 ? K * r : 1) * sizeof *sp->G);
    if (!sp->G) {
        lx__free(U), lx__free(g), lx__free(s);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t i = 0; i < K; i++) /* stored by columns: column k of the factor is row k of G */
        for (size_t k = 0; k < r; k++) sp->G[k * K + i] = s[i] * g[i * K + k];
    lx__free(U), lx__free(g), lx__free(s);
    return LX_OK;
}

/* The Fourier model's vectors: A S, then A (S sqrt2 sin(2 pi i x)), A (S sqrt2 cos(2 pi i x)). */
static lx_status fourier_vectors(lx_ctx *ctx, lx__unc_space *sp, lx__unc_fourier *f, int nmax)
{
    size_t n = sp->n, K = sp->K;
    const lx_spd *spd = sp->spd;
    f->F = lx__alloc((2 * (size_t)nmax + 1) * K * sizeof *f->F);
    double *v = lx__alloc(n * sizeof *v);
    if (!f->F || !v) {
        lx__free(v);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    memcpy(f->F, sp->L0, K * sizeof *f->F);
    double l0 = spd->lambda_nm[0], span = spd->lambda_nm[n - 1] - l0;
    for (int i = 1; i <= nmax; i++)
        for (int c = 0; c < 2; c++) {
            for (size_t j = 0; j < n; j++) {
                double a = 2 * LX__PI * i * (spd->lambda_nm[j] - l0) / span;
                v[j] = spd->value[j] * sqrt(2.0) * (c ? cos(a) : sin(a));
            }
            matvec(sp->A, K, n, v, f->F + (2 * (size_t)i - 1 + (size_t)c) * K);
        }
    lx__free(v);
    return LX_OK;
}

/* The Fourier component's factor with N terms: E[gamma_i^2] = 1 / (N + 1), and over the phase
 * f_i(x) f_i(x') averages to cos(2 pi i (x - x')), half from the sine and half from the cosine. */
static lx_status fourier_factor(const lx__unc_space *sp, const lx__unc_fourier *f, lx__unc_factor *out)
{
    size_t K = sp->K, m = 2 * (size_t)f->terms + 1;
    if (!(out->F = lx__alloc(m * K * sizeof *out->F))) return LX_ENOMEM;
    out->m = m;
    double s0 = f->sigma / sqrt(f->terms + 1.0), s1 = s0 / sqrt(2.0);
    for (size_t r = 0; r < m; r++)
        for (size_t k = 0; k < K; k++) out->F[r * K + k] = (r ? s1 : s0) * f->F[r * K + k];
    return LX_OK;
}

/* One component's factor: its covariance of the integrals is F^T F (rows of K); Fourier's once its
 * N is known (lx__unc_space_finish). */
static lx_status comp_factor(lx_ctx *ctx, lx__unc_space *sp, const lx__unc_bound *b, lx__unc_factor *out)
{
    size_t n = sp->n, K = sp->K;
    const double *A = sp->A;
    out->m = 0, out->F = NULL;
    size_t m = b->kind == LX_UNC_NOISE ? n : b->kind == LX_UNC_COVARIANCE || b->kind == LX_UNC_FOURIER ? 0 : 1;
    double *V = NULL, *col = NULL;
    if (b->kind == LX_UNC_COVARIANCE) { /* U = V V^T, then F = (A V)^T */
        if (!(V = lx__alloc(n * n * sizeof *V)) || !(col = lx__alloc(n * sizeof *col))) {
            lx__free(V);
            return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        }
        lx__pivoted_cholesky(n, b->u2, 1e-14, V, &m);
    }
    if (m && !(out->F = lx__alloc(m * K * sizeof *out->F))) {
        lx__free(V), lx__free(col);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    out->m = m;
    switch (b->kind) {
    case LX_UNC_NOISE:
        for (size_t j = 0; j < n; j++) {
            double u = sqrt(b->u2[j]);
            for (size_t k = 0; k < K; k++) out->F[j * K + k] = u * A[k * n + j];
        }
        break;
    case LX_UNC_COVARIANCE:
        for (size_t l = 0; l < m; l++) {
            for (size_t j = 0; j < n; j++) col[j] = V[j * n + l];
            matvec(A, K, n, col, out->F + l * K);
        }
        break;
    case LX_UNC_SCALE:
        for (size_t k = 0; k < K; k++) out->F[k] = b->sigma * sp->L0[k];
        break;
    case LX_UNC_SHIFT:
    case LX_UNC_BANDWIDTH: /* the bandwidth's linear term: ((b0 + d)^2 - b0^2) / 12 ~ b0 d / 6 */
        matvec(A, K, n, b->vec, out->F);
        for (size_t k = 0; k < K; k++) out->F[k] *= b->sigma * (b->kind == LX_UNC_SHIFT ? 1.0 : b->b0 / 6.0);
        break;
    case LX_UNC_FOURIER: break;
    }
    lx__free(V), lx__free(col);
    return LX_OK;
}

static lx_status make_rows(lx_ctx *ctx, const lx_spd *spd, const lx__unc_provider *prov, size_t nprov, lx__unc_space *sp)
{
    size_t K = 0, n = spd->n;
    for (size_t p = 0; p < nprov; p++) K += (size_t)prov[p].nint;
    sp->n = n, sp->K = K, sp->spd = spd;
    sp->A = lx__alloc(K * n * sizeof *sp->A);
    sp->L0 = lx__alloc(K * sizeof *sp->L0);
    if (!sp->A || !sp->L0) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    size_t row = 0;
    for (size_t p = 0; p < nprov; p++) {
        lx_status st = prov[p].rows(ctx, prov[p].self, spd, sp->A + row * n);
        if (st != LX_OK) return st;
        row += (size_t)prov[p].nint;
    }
    matvec(sp->A, K, n, spd->value, sp->L0);
    return LX_OK;
}

lx_status lx__unc_space_make(lx_ctx *ctx, const lx_spd *spd, const lx__unc_bound *b, size_t ncomp,
                             const lx__unc_provider *prov, size_t nprov, lx__unc_space *sp)
{
    memset(sp, 0, sizeof *sp);
    lx_status st = make_rows(ctx, spd, prov, nprov, sp);
    if (st != LX_OK) return st;
    size_t K = sp->K;
    sp->ncomp = ncomp;
    sp->fac = lx__calloc(ncomp ? ncomp : 1, sizeof *sp->fac);
    sp->gauss = lx__calloc(ncomp ? ncomp : 1, sizeof *sp->gauss);
    sp->bw_sigma = lx__calloc(2 * ncomp + 1, sizeof *sp->bw_sigma);
    sp->bw_D = lx__calloc(ncomp * K + 1, sizeof *sp->bw_D);
    sp->fourier = lx__calloc(ncomp ? ncomp : 1, sizeof *sp->fourier);
    if (!sp->fac || !sp->gauss || !sp->bw_sigma || !sp->bw_D || !sp->fourier)
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    sp->bw_b0 = sp->bw_sigma + ncomp;
    double s2 = 0.0;
    for (size_t c = 0; c < ncomp; c++) {
        if ((st = comp_factor(ctx, sp, &b[c], &sp->fac[c])) != LX_OK) return st;
        lx_unc_kind k = b[c].kind;
        sp->gauss[c] = k == LX_UNC_NOISE || k == LX_UNC_COVARIANCE || k == LX_UNC_SCALE;
        if (k == LX_UNC_SHIFT) s2 += b[c].sigma * b[c].sigma;
        if (k == LX_UNC_BANDWIDTH && b[c].sigma > 0) {
            matvec(sp->A, K, sp->n, b[c].vec, sp->bw_D + sp->nbw * K);
            sp->bw_sigma[sp->nbw] = b[c].sigma, sp->bw_b0[sp->nbw] = b[c].b0;
            sp->nbw++;
        }
        if (k == LX_UNC_FOURIER && b[c].sigma > 0) {
            lx__unc_fourier *f = &sp->fourier[sp->nfourier++];
            f->sigma = b[c].sigma, f->terms = b[c].terms;
            if ((st = fourier_vectors(ctx, sp, f, f->terms ? f->terms : FOURIER_AUTO_MAX)) != LX_OK) return st;
        }
    }
    if ((st = normal_factor(ctx, sp)) != LX_OK) return st;
    sp->shift_sigma = sqrt(s2);
    if (sp->shift_sigma > 0 && (st = shift_table(ctx, sp)) != LX_OK) return st;
    return LX_OK;
}

int lx__unc_fourier_auto_max(void) { return FOURIER_AUTO_MAX; }

lx_status lx__unc_space_finish(lx__unc_space *sp, const lx__unc_bound *b)
{
    size_t fi = 0;
    for (size_t c = 0; c < sp->ncomp; c++)
        if (b[c].kind == LX_UNC_FOURIER && b[c].sigma > 0 && fourier_factor(sp, &sp->fourier[fi++], &sp->fac[c]) != LX_OK)
            return LX_ENOMEM;
    sp->nnormal = sp->r + (sp->shift_sigma > 0) + sp->nbw;
    sp->nuniform = 0;
    for (size_t f = 0; f < sp->nfourier; f++) {
        sp->nnormal += (size_t)sp->fourier[f].terms + 1;
        sp->nuniform += (size_t)sp->fourier[f].terms;
    }
    return LX_OK;
}

void lx__unc_space_free(lx__unc_space *sp)
{
    lx__free(sp->A), lx__free(sp->L0);
    for (size_t c = 0; sp->fac && c < sp->ncomp; c++) lx__free(sp->fac[c].F);
    lx__free(sp->fac), lx__free(sp->gauss), lx__free(sp->G), lx__free(sp->shift_d), lx__free(sp->shift_T);
    lx__free(sp->bw_sigma), lx__free(sp->bw_D);
    for (size_t f = 0; sp->fourier && f < sp->nfourier; f++) lx__free(sp->fourier[f].F);
    lx__free(sp->fourier);
    memset(sp, 0, sizeof *sp);
}
