/* photobio.c - weighted quantities of plant lighting and photobiological safety of one spectrum:
 * PAR, ePAR and YPF photon fluxes (ANSI/ASABE S640, McCree 1972), the IEC 62471 / CIE S 009 hazard
 * integrals with the coverage of each weighting function, and the risk groups (batches: lab_batch.c). */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Integral of the piecewise-linear w over [a, b] (zero outside its samples). */
static double w_integral(const lx_spd *w, double a, double b)
{
    double sum = 0.0;
    for (size_t i = 0; i + 1 < w->n; i++) {
        double l0 = w->lambda_nm[i], l1 = w->lambda_nm[i + 1];
        double x0 = l0 > a ? l0 : a, x1 = l1 < b ? l1 : b;
        if (!(x1 > x0)) continue;
        double s = (w->value[i + 1] - w->value[i]) / (l1 - l0);
        double y0 = w->value[i] + s * (x0 - l0), y1 = w->value[i] + s * (x1 - l0);
        sum += 0.5 * (y0 + y1) * (x1 - x0);
    }
    return sum;
}

/* The fraction of w's integral that lies inside [a, b]. */
double lx__coverage(const lx_spd *w, double a, double b)
{
    double all = w_integral(w, w->lambda_nm[0], w->lambda_nm[w->n - 1]);
    return all > 0 ? w_integral(w, a, b) / all : 0.0;
}

int lx__fn_band_exact(lx_function fn)
{
    return fn == LX_FN_PHOTON_PAR || fn == LX_FN_PHOTON_EPAR || fn == LX_FN_YPF_MCCREE;
}

static lx_status integrate_fns(lx_ctx *ctx, const lx_spd *spd, lx_method method, const lx_function *fns, size_t k,
                               double *val, double *cov)
{
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    if ((int)method < LX_METHOD_AUTO || method > LX_METHOD_LINEAR1NM)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown integration method %d", (int)method);
    for (size_t f = 0; f < k; f++) {
        lx_spd w;
        if ((st = lx_function_get(ctx, fns[f], &w)) != LX_OK) return st;
        cov[f] = lx__coverage(&w, spd->lambda_nm[0], spd->lambda_nm[spd->n - 1]);
        if (cov[f] < LX_COVERAGE_MIN) {
            val[f] = NAN;
            continue;
        }
        /* a band integral (ANSI/ASABE S640 defines PPFD as the integral over 400-700 nm): exact,
         * as the radiant integral; the CIE 015 sum of a flat 1 W m-2 nm-1 at 1 nm counts 301 nm of
         * the 300 nm band (1383.89 umol s-1 m-2 instead of 1379.29) */
        lx_method m = lx__fn_band_exact(fns[f]) ? LX_METHOD_EXACT : method;
        if ((st = lx_spd_integrate(ctx, spd, &w, m, &val[f])) != LX_OK) return st;
    }
    return LX_OK;
}

/* ---- PAR ---- */

const lx_function lx__par_fns[3] = {LX_FN_PHOTON_PAR, LX_FN_PHOTON_EPAR, LX_FN_YPF_MCCREE};

lx_status lx_par_compute(lx_ctx *ctx, const lx_spd *spd, lx_method method, lx_par *out)
{
    LX__NEED_CTX(ctx);
    if (!spd || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_par_compute: NULL argument");
    double v[3], cov[3], radiant;
    lx_status st = integrate_fns(ctx, spd, method, lx__par_fns, 3, v, cov);
    if (st == LX_OK) st = lx_spd_integrate_radiant(ctx, spd, method, &radiant);
    if (st != LX_OK) return st;
    lx_par p = {v[0], v[1], v[2], radiant > 0 ? v[0] / radiant : NAN, {0}};
    *out = p;
    return LX_OK;
}

double lx_par_dli(double ppfd_umol_m2_s, double photoperiod_h)
{
    if (!isfinite(photoperiod_h) || photoperiod_h < 0) return NAN;
    return ppfd_umol_m2_s * 3600.0 * photoperiod_h * 1e-6;
}

/* ---- IEC 62471 ---- */

const lx_function lx__hazard_fns[LX_HZ_COUNT] = {LX_FN_HAZARD_BLUE, LX_FN_HAZARD_THERMAL, LX_FN_HAZARD_ACTINIC,
                                                 LX_FN_UVA};

lx_status lx_hazard_compute(lx_ctx *ctx, const lx_spd *spd, lx_method method, lx_hazard *out)
{
    LX__NEED_CTX(ctx);
    if (!spd || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_hazard_compute: NULL argument");
    lx_hazard h;
    memset(&h, 0, sizeof h);
    lx_status st = integrate_fns(ctx, spd, method, lx__hazard_fns, LX_HZ_COUNT, h.value, h.coverage);
    if (st == LX_OK) *out = h;
    return st;
}

const char *lx_risk_group_name(lx_risk_group g)
{
    switch (g) {
    case LX_RISK_EXEMPT: return "exempt";
    case LX_RISK_1: return "RG1";
    case LX_RISK_2: return "RG2";
    case LX_RISK_3: return "RG3";
    default: return "";
    }
}

/* Limits of row q of src/data/iec62471_limits.csv (0 E_S, 1 E_UVA, 2 L_B, 3 E_B, 4 L_R as C/alpha). */
static int limits(int q, double lim[3])
{
    const lx__table *t = lx__table_find("iec62471_limits");
    if (!t || t->ncols != 4) return -1;
    for (int r = 0; r < t->nrows; r++)
        if (t->data[r] == (double)q) {
            for (int k = 0; k < 3; k++) lim[k] = t->data[(size_t)(k + 1) * t->nrows + r];
            return 0;
        }
    return -1;
}

static lx_risk_group group_of(double x, const double lim[3])
{
    if (isnan(x)) return LX_RISK_NONE;
    return x <= lim[0] ? LX_RISK_EXEMPT : x <= lim[1] ? LX_RISK_1 : x <= lim[2] ? LX_RISK_2 : LX_RISK_3;
}

lx_status lx_hazard_risk_group(lx_ctx *ctx, const lx_hazard *h, int radiance, double alpha_rad, lx_hazard_risk *out)
{
    LX__NEED_CTX(ctx);
    if (!h || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_hazard_risk_group: NULL argument");
    if (!(alpha_rad >= 0) || !isfinite(alpha_rad))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the angular subtense must be 0 (not known) or positive (got %g rad)",
                         alpha_rad);
    lx_hazard_risk r;
    memset(&r, 0, sizeof r);
    for (int k = 0; k < LX_HZ_COUNT; k++) r.criterion[k] = LX_RISK_NONE;
    /* the source's solid angle: a circular source of full angle alpha */
    double omega = alpha_rad > 0 ? 2 * LX__PI * (1 - cos(0.5 * alpha_rad)) : 0;
    /* per criterion: the limits row (0 E_S, 1 E_UVA, 2 L_B, 3 E_B, 4 L_R), the value in that row's
     * quantity, the limit named; -1: not judged */
    int row[LX_HZ_COUNT] = {-1, -1, -1, -1};
    double val[LX_HZ_COUNT] = {NAN, NAN, NAN, NAN};
    int conv[LX_HZ_COUNT] = {0};
    int small = alpha_rad > 0 && alpha_rad < 0.011;
    if (radiance) {
        if (small) row[LX_HZ_BLUE] = 3, val[LX_HZ_BLUE] = h->value[LX_HZ_BLUE] * omega, conv[LX_HZ_BLUE] = 1;
        else row[LX_HZ_BLUE] = 2, val[LX_HZ_BLUE] = h->value[LX_HZ_BLUE];
        if (alpha_rad > 0) row[LX_HZ_THERMAL] = 4, val[LX_HZ_THERMAL] = h->value[LX_HZ_THERMAL];
    } else {
        if (alpha_rad >= 0.011) row[LX_HZ_BLUE] = 2, val[LX_HZ_BLUE] = h->value[LX_HZ_BLUE] / omega, conv[LX_HZ_BLUE] = 1;
        else row[LX_HZ_BLUE] = 3, val[LX_HZ_BLUE] = h->value[LX_HZ_BLUE];
        if (alpha_rad > 0) row[LX_HZ_THERMAL] = 4, val[LX_HZ_THERMAL] = h->value[LX_HZ_THERMAL] / omega, conv[LX_HZ_THERMAL] = 1;
        row[LX_HZ_ACTINIC] = 0, val[LX_HZ_ACTINIC] = h->value[LX_HZ_ACTINIC];
        row[LX_HZ_UVA] = 1, val[LX_HZ_UVA] = h->value[LX_HZ_UVA];
    }
    static const lx_hazard_limit named[5] = {LX_HZ_LIMIT_E_S, LX_HZ_LIMIT_E_UVA, LX_HZ_LIMIT_L_B, LX_HZ_LIMIT_E_B,
                                             LX_HZ_LIMIT_L_R};
    for (int k = 0; k < LX_HZ_COUNT; k++) {
        double lim[3];
        if (row[k] < 0) continue;
        if (limits(row[k], lim) != 0)
            return lx__error(ctx, LX_EINVAL, NULL, 0, "the embedded IEC 62471 limits table lacks row %d", row[k]);
        if (row[k] == 4) { /* L_R: C / alpha, alpha clamped to 1.7 mrad ... 100 mrad */
            double a = alpha_rad < 0.0017 ? 0.0017 : alpha_rad > 0.1 ? 0.1 : alpha_rad;
            for (int j = 0; j < 3; j++) lim[j] /= a;
        }
        r.criterion[k] = group_of(val[k], lim);
        if (r.criterion[k] != LX_RISK_NONE) {
            r.limit[k] = named[row[k]];
            if (conv[k]) r.source_sr = omega;
        }
    }
    r.group = LX_RISK_NONE;
    for (int k = 0; k < LX_HZ_COUNT; k++)
        if (r.criterion[k] > r.group) r.group = r.criterion[k];
    *out = r;
    return LX_OK;
}
