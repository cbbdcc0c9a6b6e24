/* cri.c - CIE 13.3-1995 colour rendering index (R1-R14, Ra) with its reference illuminant and
 * von Kries adaptation, plus the sampling grid shared with tm30.c (lx__quality_*). */
#include "colour/colour_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CRI_START 360.0
#define CRI_END 830.0
#define NTCS 14
#define DC_LIMIT 5.4e-3       /* CIE 13.3: Ra is not meaningful beyond this uv distance */
#define DUV_LIMIT 0.05        /* beyond it CCT has no meaning (as lx_spd_colorimetry) */
#define OUTSIDE_LIMIT 0.01    /* refuse when 1 % of the reference's X, Y or Z is outside the data */

double lx__quality_step(const lx_spd *spd)
{
    if (spd->n < 2) return 1.0;
    double l0 = spd->lambda_nm[0];
    if (fabs(l0 / 5.0 - round(l0 / 5.0)) > 1e-9) return 1.0;
    for (size_t i = 1; i < spd->n; i++)
        if (fabs(spd->lambda_nm[i] - spd->lambda_nm[i - 1] - 5.0) > 1e-9) return 1.0;
    return 5.0;
}

void lx__quality_sample(const lx_spd *spd, double start_nm, double step_nm, int n, double *out)
{
    size_t j = 0;
    const double *x = spd->lambda_nm, *y = spd->value;
    for (int i = 0; i < n; i++) {
        double l = start_nm + i * step_nm;
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

void lx__quality_table(const lx__table *t, int col, double start_nm, double step_nm, int n, double *out)
{
    lx_spd v;
    if (lx__table_view(t, col, &v) != 0) {
        for (int i = 0; i < n; i++) out[i] = 0.0;
        return;
    }
    lx__quality_sample(&v, start_nm, step_nm, n, out);
}

/* The 2 deg CMFs sampled on the grid (3 * n doubles). */
static void cmf2_grid(double start_nm, double step_nm, int n, double *xyz)
{
    const lx__table *t = lx__table_find("cie1931_2deg_xyz_1nm");
    static const char *const cols[3] = {"x_bar", "y_bar", "z_bar"};
    for (int c = 0; c < 3; c++) lx__quality_table(t, lx__table_col(t, cols[c]), start_nm, step_nm, n, xyz + c * n);
}

double lx__quality_outside(const double *ref, double start_nm, double step_nm, int n, double lo_nm, double hi_nm)
{
    double *cmf = malloc(sizeof(double) * 3 * (size_t)n);
    if (!cmf) return INFINITY;
    cmf2_grid(start_nm, step_nm, n, cmf);
    double worst = 0.0;
    for (int c = 0; c < 3; c++) {
        double all = 0.0, out = 0.0;
        for (int i = 0; i < n; i++) {
            double l = start_nm + i * step_nm, w = ref[i] * cmf[c * n + i];
            all += w;
            if (l < lo_nm - 1e-9 || l > hi_nm + 1e-9) out += w;
        }
        if (all > 0 && out / all > worst) worst = out / all;
    }
    free(cmf);
    return worst;
}

/* CIE 1960 u, v and Y (scaled) of the colour stimulus illum * refl under the grid CMFs. */
static void stimulus(const double *cmf, int n, const double *illum, const double *refl, double k, double *u,
                     double *v, double *Y)
{
    double X = 0, YY = 0, Z = 0;
    for (int i = 0; i < n; i++) {
        double p = refl ? illum[i] * refl[i] : illum[i];
        X += p * cmf[i];
        YY += p * cmf[n + i];
        Z += p * cmf[2 * n + i];
    }
    X *= k, YY *= k, Z *= k;
    double d = X + 15 * YY + 3 * Z;
    *u = 4 * X / d;
    *v = 6 * YY / d;
    *Y = YY;
}

/* von Kries in CIE 1960 UCS (CIE 13.3 eq. 6-7): c and d of a chromaticity. */
static double cterm(double u, double v) { return (4 - u - 10 * v) / v; }
static double dterm(double u, double v) { return (1.708 * v + 0.404 - 1.481 * u) / v; }

/* U*, V*, W* of the 14 samples under illum (adapted to the reference white ur, vr when the
 * illuminant's white ut, vt differs). */
static void uvw_samples(const double *cmf, int n, const double *illum, const double *tcs, double ut, double vt,
                        double ur, double vr, int adapt, double uvw[NTCS][3])
{
    double uw, vw, Yw;
    stimulus(cmf, n, illum, NULL, 1.0, &uw, &vw, &Yw);
    double k = 100.0 / Yw;
    double cr = cterm(ur, vr), dr = dterm(ur, vr), ct = cterm(ut, vt), dt = dterm(ut, vt);
    for (int s = 0; s < NTCS; s++) {
        double u, v, Y;
        stimulus(cmf, n, illum, tcs + (size_t)s * n, k, &u, &v, &Y);
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

lx_status lx_cri_compute(lx_ctx *ctx, const lx_spd *spd, lx_cri *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "CRI: output is NULL");
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    const lx__table *tt = lx__table_find("cie13_3_tcs");
    if (!tt) return lx__error(ctx, LX_EINVAL, NULL, 0, "CRI: embedded table cie13_3_tcs missing");
    double step = lx__quality_step(spd);
    int n = (int)lround((CRI_END - CRI_START) / step) + 1;
    double *buf = malloc(sizeof(double) * (size_t)n * (3 + NTCS + 3));
    if (!buf) return lx__error(ctx, LX_ENOMEM, NULL, 0, "CRI: out of memory");
    double *cmf = buf, *tcs = cmf + 3 * n, *test = tcs + NTCS * n, *ref = test + n, *lam = ref + n;
    cmf2_grid(CRI_START, step, n, cmf);
    for (int s = 0; s < NTCS; s++) {
        char name[8];
        snprintf(name, sizeof name, "TCS%02d", s + 1);
        lx__quality_table(tt, lx__table_col(tt, name), CRI_START, step, n, tcs + (size_t)s * n);
    }
    lx__quality_sample(spd, CRI_START, step, n, test);
    for (int i = 0; i < n; i++) lam[i] = CRI_START + i * step;

    lx_cri r;
    memset(&r, 0, sizeof r);
    double ut, vt, Yt, T, duv;
    stimulus(cmf, n, test, NULL, 1.0, &ut, &vt, &Yt);
    if (!(Yt > 0) || !isfinite(ut) || !isfinite(vt)) {
        free(buf);
        return lx__error(ctx, LX_ERANGE, NULL, 0, "CRI: the spectrum has no luminous content in 360-830 nm");
    }
    st = lx_cct_from_uv(ctx, LX_OBSERVER_2, ut, vt, &T, &duv);
    if (st != LX_OK) {
        char why[LX__ERRMSG_MAX];
        snprintf(why, sizeof why, "%s", lx_ctx_errmsg(ctx));
        free(buf);
        return lx__error(ctx, LX_ERANGE, NULL, 0, "CRI: no correlated colour temperature: %s", why);
    }
    if (fabs(duv) > DUV_LIMIT) {
        free(buf);
        return lx__error(ctx, LX_ERANGE, NULL, 0,
                         "CRI: Duv %.4f is beyond 0.05: too far from the Planckian locus for a CCT", duv);
    }
    if (T > 25000.0) {
        free(buf);
        return lx__error(ctx, LX_ERANGE, NULL, 0, "CRI: CCT %.0f K is above 25000 K, where CIE daylight is undefined", T);
    }
    r.cct_K = r.ref_cct_K = T;
    r.duv = duv;
    r.ref_daylight = T >= 5000.0;
    if (r.ref_daylight) {
        if ((st = lx_daylight(ctx, T, (size_t)n, lam, ref)) != LX_OK) {
            free(buf);
            return st;
        }
    } else {
        for (int i = 0; i < n; i++) ref[i] = lx_planck(lam[i], T);
    }
    double outside = lx__quality_outside(ref, CRI_START, step, n, spd->lambda_nm[0], spd->lambda_nm[spd->n - 1]);
    if (outside > OUTSIDE_LIMIT) {
        free(buf);
        return lx__error(ctx, LX_ERANGE, NULL, 0,
                         "CRI: the spectrum covers %g-%g nm only; %.1f %% of the reference's tristimulus values "
                         "lie outside it (CIE 13.3 needs 380-780 nm)",
                         spd->lambda_nm[0], spd->lambda_nm[spd->n - 1], 100 * outside);
    }
    double ur, vr, Yr;
    stimulus(cmf, n, ref, NULL, 1.0, &ur, &vr, &Yr);
    r.dc = hypot(ut - ur, vt - vr);
    r.valid = r.dc <= DC_LIMIT;
    double uvw_t[NTCS][3], uvw_r[NTCS][3];
    uvw_samples(cmf, n, test, tcs, ut, vt, ur, vr, 1, uvw_t);
    uvw_samples(cmf, n, ref, tcs, ur, vr, ur, vr, 0, uvw_r);
    double sum = 0;
    for (int s = 0; s < NTCS; s++) {
        double dE = sqrt((uvw_t[s][0] - uvw_r[s][0]) * (uvw_t[s][0] - uvw_r[s][0]) +
                         (uvw_t[s][1] - uvw_r[s][1]) * (uvw_t[s][1] - uvw_r[s][1]) +
                         (uvw_t[s][2] - uvw_r[s][2]) * (uvw_t[s][2] - uvw_r[s][2]));
        r.r[s] = 100.0 - 4.6 * dE;
        if (s < 8) sum += r.r[s];
    }
    r.ra = sum / 8.0;
    free(buf);
    *out = r;
    return LX_OK;
}
