/* cri.c - CIE 13.3-1995 colour rendering index (R1-R14, Ra; R15 of JIS Z 8726) with its reference illuminant and
 * von Kries adaptation, plus the quadrature shared with tm30.c (lx__qgrid, lx__quality_*): the
 * CIE sums for uniformly sampled data, exact integration of line spectra. */
#include "colour/colour_private.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CRI_START 360.0
#define CRI_END 830.0
#define NTCS LX__CRI_NTCS /* CIE 13.3 TCS01-TCS14, then JIS Z 8726 No. 15 (R15, computed as R9-R14 are) */
#define DC_LIMIT 5.4e-3       /* CIE 13.3: Ra is not meaningful beyond this uv distance */
#define DUV_LIMIT 0.05        /* beyond it CCT has no meaning (as lx_spd_colorimetry) */
#define OUTSIDE_LIMIT 0.01    /* refuse when 1 % of the reference's X, Y or Z is outside the data */

/* The CIE15 grid step: 5 nm for data uniformly sampled at 5 nm on multiples of 5 nm, else 1 nm. */
static double cie15_step(const lx_spd *spd)
{
    if (spd->n < 2) return 1.0;
    double l0 = spd->lambda_nm[0];
    if (fabs(l0 / 5.0 - round(l0 / 5.0)) > 1e-9) return 1.0;
    for (size_t i = 1; i < spd->n; i++)
        if (fabs(spd->lambda_nm[i] - spd->lambda_nm[i - 1] - 5.0) > 1e-9) return 1.0;
    return 5.0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

lx_status lx__qgrid_make(lx_ctx *ctx, const lx_spd *spd, double start_nm, double end_nm, lx__qgrid *g)
{
    g->lam = g->w = NULL;
    g->n = 0;
    g->exact = lx_method_resolve(spd, LX_METHOD_AUTO) == LX_METHOD_EXACT;
    if (!g->exact) {
        double step = cie15_step(spd);
        size_t n = (size_t)lround((end_nm - start_nm) / step) + 1;
        g->lam = lx__alloc(2 * n * sizeof *g->lam);
        if (!g->lam) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        g->w = g->lam + n;
        for (size_t i = 0; i < n; i++) g->lam[i] = start_nm + (double)i * step, g->w[i] = step;
        g->n = n;
        return LX_OK;
    }
    /* the breakpoints: every whole nm of [start, end] and every sample of the data inside it */
    size_t nw = (size_t)lround(end_nm - start_nm) + 1, nb = 0;
    double *bp = lx__alloc((nw + spd->n) * sizeof *bp);
    if (!bp) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; i < nw; i++) bp[nb++] = start_nm + (double)i;
    for (size_t i = 0; i < spd->n; i++)
        if (spd->lambda_nm[i] > start_nm && spd->lambda_nm[i] < end_nm) bp[nb++] = spd->lambda_nm[i];
    qsort(bp, nb, sizeof *bp, cmp_double);
    size_t m = 0;
    for (size_t i = 0; i < nb; i++)
        if (m == 0 || bp[i] > bp[m - 1]) bp[m++] = bp[i];
    if (m < 2) {
        lx__free(bp);
        return lx__error(ctx, LX_EINVAL, NULL, 0, "an empty wavelength range (%g-%g nm)", start_nm, end_nm);
    }
    /* Simpson on each interval: nodes at the breakpoints (shared) and the midpoints */
    size_t n = 2 * m - 1;
    g->lam = lx__alloc(2 * n * sizeof *g->lam);
    if (!g->lam) {
        lx__free(bp);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    g->w = g->lam + n;
    for (size_t i = 0; i < n; i++) g->w[i] = 0;
    for (size_t k = 0; k + 1 < m; k++) {
        double h = bp[k + 1] - bp[k];
        g->lam[2 * k] = bp[k];
        g->lam[2 * k + 1] = 0.5 * (bp[k] + bp[k + 1]);
        g->w[2 * k] += h / 6, g->w[2 * k + 1] += 4 * h / 6, g->w[2 * k + 2] += h / 6;
    }
    g->lam[n - 1] = bp[m - 1];
    g->n = n;
    lx__free(bp);
    return LX_OK;
}

void lx__qgrid_free(lx__qgrid *g)
{
    lx__free(g->lam);
    g->lam = g->w = NULL;
}

void lx__quality_sample(const lx_spd *spd, const lx__qgrid *g, double *out)
{
    size_t j = 0;
    const double *x = spd->lambda_nm, *y = spd->value;
    for (size_t i = 0; i < g->n; i++) { /* the nodes increase */
        double l = g->lam[i];
        if (l < x[0] || l > x[spd->n - 1]) {
            out[i] = 0.0;
            continue;
        }
        while (j + 2 < spd->n && x[j + 1] <= l) j++;
        if (l == x[j]) out[i] = y[j];
        else if (l == x[j + 1]) out[i] = y[j + 1];
        else out[i] = y[j] + (l - x[j]) / (x[j + 1] - x[j]) * (y[j + 1] - y[j]);
    }
}

void lx__quality_table(const lx__table *t, int col, const lx__qgrid *g, double *out)
{
    lx_spd v;
    if (lx__table_view(t, col, &v) != 0) {
        for (size_t i = 0; i < g->n; i++) out[i] = 0.0;
        return;
    }
    lx__quality_sample(&v, g, out);
}

/* The 2 deg CMFs sampled on the grid (3 * n doubles). */
static void cmf2_grid(const lx__qgrid *g, double *xyz)
{
    const lx__table *t = lx__table_find("cie1931_2deg_xyz_1nm");
    static const char *const cols[3] = {"x_bar", "y_bar", "z_bar"};
    for (int c = 0; c < 3; c++) lx__quality_table(t, lx__table_col(t, cols[c]), g, xyz + c * g->n);
}

double lx__quality_outside(const double *ref, const lx__qgrid *g, double lo_nm, double hi_nm)
{
    size_t n = g->n;
    double *cmf = lx__alloc(sizeof(double) * 3 * n);
    if (!cmf) return INFINITY;
    cmf2_grid(g, cmf);
    double worst = 0.0;
    for (int c = 0; c < 3; c++) {
        double all = 0.0, out = 0.0;
        for (size_t i = 0; i < n; i++) {
            double l = g->lam[i], w = g->w[i] * ref[i] * cmf[c * n + i];
            all += w;
            if (l < lo_nm - 1e-9 || l > hi_nm + 1e-9) out += w;
        }
        if (all > 0 && out / all > worst) worst = out / all;
    }
    lx__free(cmf);
    return worst;
}

/* The integrals of CIE 13.3 under illum: [0 .. 2] the illuminant's X, Y, Z, [3 + 3 s + c] those of
 * test colour sample s (sums of w illum refl cmf over the grid, as CIE 13.3 sums them). */
void lx__cri_integrals(const lx__cri_grid *cg, const double *illum, double *L)
{
    const lx__qgrid *g = &cg->g;
    size_t n = g->n;
    const double *cmf = cg->cmf;
    for (int s = -1; s < NTCS; s++) {
        const double *refl = s < 0 ? NULL : cg->tcs + (size_t)s * n;
        double X = 0, YY = 0, Z = 0;
        for (size_t i = 0; i < n; i++) {
            double p = g->w[i] * (refl ? illum[i] * refl[i] : illum[i]);
            X += p * cmf[i];
            YY += p * cmf[n + i];
            Z += p * cmf[2 * n + i];
        }
        L[3 + 3 * s] = X, L[4 + 3 * s] = YY, L[5 + 3 * s] = Z;
    }
}

/* CIE 1960 u, v and Y of the tristimulus values xyz scaled by k. */
static void uvY(const double *xyz, double k, double *u, double *v, double *Y)
{
    double X = xyz[0] * k, YY = xyz[1] * k, Z = xyz[2] * k;
    double d = X + 15 * YY + 3 * Z;
    *u = 4 * X / d;
    *v = 6 * YY / d;
    *Y = YY;
}

/* von Kries in CIE 1960 UCS (CIE 13.3 eq. 6-7): c and d of a chromaticity. */
static double cterm(double u, double v) { return (4 - u - 10 * v) / v; }
static double dterm(double u, double v) { return (1.708 * v + 0.404 - 1.481 * u) / v; }

/* U*, V*, W* of the 15 samples from an illuminant's integrals L (adapted to the reference white ur,
 * vr when the illuminant's white ut, vt differs). */
static void uvw_samples(const double *L, double ut, double vt, double ur, double vr, int adapt, double uvw[NTCS][3])
{
    double uw, vw, Yw;
    uvY(L, 1.0, &uw, &vw, &Yw);
    double k = 100.0 / Yw;
    double cr = cterm(ur, vr), dr = dterm(ur, vr), ct = cterm(ut, vt), dt = dterm(ut, vt);
    for (int s = 0; s < NTCS; s++) {
        double u, v, Y;
        uvY(L + 3 + 3 * s, k, &u, &v, &Y);
        if (adapt) {
            double ci = cterm(u, v), di = dterm(u, v);
            double den = 16.518 + 1.481 * (cr / ct) * ci - (dr / dt) * di;
            u = (10.872 + 0.404 * (cr / ct) * ci - 4 * (dr / dt) * di) / den;
            v = 5.520 / den;
        }
        double W = 25.0 * cbrt(Y) - 17.0;
        uvw[s][0] = 13.0 * W * (u - ur);
        uvw[s][1] = 13.0 * W * (v - vr);
        uvw[s][2] = W;
    }
}

/* The test source's CCT and Duv for its reference, or the reason there is none (LX_ERANGE). */
static lx_status cri_cct(lx_ctx *ctx, double ut, double vt, double Yt, double *T, double *duv)
{
    if (!(Yt > 0) || !isfinite(ut) || !isfinite(vt))
        return lx__error(ctx, LX_ERANGE, NULL, 0, "CRI: the spectrum has no luminous content in 360-830 nm");
    if (lx_cct_from_uv(ctx, LX_OBSERVER_2, ut, vt, T, duv) != LX_OK) {
        char why[LX__ERRMSG_MAX];
        snprintf(why, sizeof why, "%s", lx_ctx_errmsg(ctx));
        return lx__error(ctx, LX_ERANGE, NULL, 0, "CRI: no correlated colour temperature: %s", why);
    }
    if (fabs(*duv) > DUV_LIMIT)
        return lx__error(ctx, LX_ERANGE, NULL, 0, "CRI: Duv %.4f is beyond 0.05: too far from the Planckian locus for a CCT",
                         *duv);
    if (*T > 25000.0)
        return lx__error(ctx, LX_ERANGE, NULL, 0, "CRI: CCT %.0f K is above 25000 K, where CIE daylight is undefined", *T);
    return LX_OK;
}

int lx__cri_ok(double T, double duv) { return isfinite(T) && fabs(duv) <= DUV_LIMIT && T <= 25000.0; }

lx_status lx__cri_reference(lx_ctx *ctx, const lx__cri_grid *cg, double T, double *ref)
{
    if (T >= 5000.0) return lx_daylight(ctx, T, cg->g.n, cg->g.lam, ref);
    for (size_t i = 0; i < cg->g.n; i++) ref[i] = lx_planck(cg->g.lam[i], T);
    return LX_OK;
}

void lx__cri_indices(const double *Lt, const double *Lr, double T, double duv, lx_cri *out)
{
    lx_cri r;
    memset(&r, 0, sizeof r);
    double ut, vt, Yt, ur, vr, Yr;
    uvY(Lt, 1.0, &ut, &vt, &Yt);
    uvY(Lr, 1.0, &ur, &vr, &Yr);
    r.cct_K = r.ref_cct_K = T;
    r.duv = duv;
    r.ref_daylight = T >= 5000.0;
    r.dc = hypot(ut - ur, vt - vr);
    r.valid = r.dc <= DC_LIMIT;
    double uvw_t[NTCS][3], uvw_r[NTCS][3];
    uvw_samples(Lt, ut, vt, ur, vr, 1, uvw_t);
    uvw_samples(Lr, ur, vr, ur, vr, 0, uvw_r);
    double sum = 0;
    for (int s = 0; s < NTCS; s++) {
        double dE = sqrt((uvw_t[s][0] - uvw_r[s][0]) * (uvw_t[s][0] - uvw_r[s][0]) +
                         (uvw_t[s][1] - uvw_r[s][1]) * (uvw_t[s][1] - uvw_r[s][1]) +
                         (uvw_t[s][2] - uvw_r[s][2]) * (uvw_t[s][2] - uvw_r[s][2]));
        if (s < 14) r.r[s] = 100.0 - 4.6 * dE;
        else r.r15 = 100.0 - 4.6 * dE;
        if (s < 8) sum += r.r[s];
    }
    r.ra = sum / 8.0;
    *out = r;
}

lx_status lx__cri_grid_make(lx_ctx *ctx, const lx_spd *spd, lx__cri_grid *cg)
{
    memset(cg, 0, sizeof *cg);
    const lx__table *tt = lx__table_find("cie13_3_tcs"), *t15 = lx__table_find("jis_z8726_tcs15");
    if (!tt || !t15) return lx__error(ctx, LX_EINVAL, NULL, 0, "CRI: embedded table cie13_3_tcs or jis_z8726_tcs15 missing");
    lx_status st = lx__qgrid_make(ctx, spd, CRI_START, CRI_END, &cg->g);
    if (st != LX_OK) return st;
    size_t n = cg->g.n;
    if (!(cg->cmf = lx__alloc(sizeof(double) * n * (3 + NTCS)))) {
        lx__qgrid_free(&cg->g);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "CRI: out of memory");
    }
    cg->tcs = cg->cmf + 3 * n;
    cmf2_grid(&cg->g, cg->cmf);
    for (int s = 0; s < NTCS; s++) {
        char name[8];
        snprintf(name, sizeof name, "TCS%02d", s + 1);
        const lx__table *t = s < 14 ? tt : t15;
        lx__quality_table(t, lx__table_col(t, name), &cg->g, cg->tcs + (size_t)s * n);
    }
    return LX_OK;
}

void lx__cri_grid_free(lx__cri_grid *cg)
{
    lx__free(cg->cmf);
    lx__qgrid_free(&cg->g);
    cg->cmf = cg->tcs = NULL;
}

lx_status lx__cri_outside(lx_ctx *ctx, const lx__cri_grid *cg, const lx_spd *spd, const double *ref)
{
    double outside = lx__quality_outside(ref, &cg->g, spd->lambda_nm[0], spd->lambda_nm[spd->n - 1]);
    if (outside > OUTSIDE_LIMIT)
        return lx__error(ctx, LX_ERANGE, NULL, 0,
                         "CRI: the spectrum covers %g-%g nm only; %.1f %% of the reference's tristimulus values "
                         "lie outside it (CIE 13.3 needs 380-780 nm)",
                         spd->lambda_nm[0], spd->lambda_nm[spd->n - 1], 100 * outside);
    return LX_OK;
}

/* The work of lx_cri_compute on a checked spectrum. */
static lx_status cri_compute_spd(lx_ctx *ctx, const lx_spd *spd, lx_cri *out)
{
    lx_status st;
    lx__cri_grid cg;
    if ((st = lx__cri_grid_make(ctx, spd, &cg)) != LX_OK) return st;
    size_t n = cg.g.n;
    double *buf = lx__alloc(sizeof(double) * 2 * n), Lt[LX__CRI_NINT], Lr[LX__CRI_NINT];
    if (!buf) {
        lx__cri_grid_free(&cg);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "CRI: out of memory");
    }
    double *test = buf, *ref = buf + n;
    lx__quality_sample(spd, &cg.g, test);
    lx__cri_integrals(&cg, test, Lt);
    double ut, vt, Yt, T, duv;
    uvY(Lt, 1.0, &ut, &vt, &Yt);
    if ((st = cri_cct(ctx, ut, vt, Yt, &T, &duv)) == LX_OK && (st = lx__cri_reference(ctx, &cg, T, ref)) == LX_OK &&
        (st = lx__cri_outside(ctx, &cg, spd, ref)) == LX_OK) {
        lx__cri_integrals(&cg, ref, Lr);
        lx__cri_indices(Lt, Lr, T, duv, out);
    }
    lx__free(buf);
    lx__cri_grid_free(&cg);
    return st;
}

lx_status lx_cri_compute(lx_ctx *ctx, const lx_spd *spd, lx_cri *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "CRI: output is NULL");
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    /* values near the bottom of the double range: the same spectrum scaled up by a power of two
     * (exact; every result is scale-free) */
    lx_spd up;
    double *ubuf;
    int te = lx__spd_tiny_scale(spd, &up, &ubuf);
    if (te == INT_MIN) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    st = cri_compute_spd(ctx, te ? &up : spd, out);
    lx__free(ubuf);
    return st;
}
