/* ugr.c - discomfort glare: the Guth position index, the CIE 117-1995 unified glare rating, the
 * projected luminous area of a luminaire, and the CIE 190:2010 tabular UGR of a luminaire (its
 * background-luminance factors embedded from src/data/cie190_ugr_factors.csv). */
#include "lighting/lighting_private.h"

#include <math.h>
#include <string.h>

double lx_guth_position_index(double sigma, double tau)
{
    if (!(sigma >= 0) || !(tau >= 0) || sigma >= 90) return NAN;
    if (tau <= 90)
        return exp((35.2 - 0.31889 * tau - 1.22 * exp(-2 * tau / 9)) * 1e-3 * sigma +
                   (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma);
    double rd = tan(sigma * LX__DEG);
    return rd < 0.6 ? 1 + 0.8 * rd : 1 + 1.2 * rd;
}

lx_status lx_ugr(lx_ctx *ctx, double Lb, size_t n, const double *L, const double *w, const double *p, double *terms,
                 double *ugr)
{
    LX__NEED_CTX(ctx);
    if (!ugr || (n && (!L || !w || !p))) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_ugr: NULL argument");
    if (!(Lb > 0) || !isfinite(Lb))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "UGR: the background luminance must be positive (got %g cd/m2)", Lb);
    for (size_t i = 0; i < n; i++) /* every source checked before any output is written */
        if (!(L[i] >= 0) || !(w[i] >= 0) || !(p[i] >= 1))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "UGR: source %zu: luminance and solid angle must be >= 0, p >= 1", i);
    double sum = 0;
    for (size_t i = 0; i < n; i++) {
        double t = L[i] * L[i] * w[i] / (p[i] * p[i]);
        if (terms) terms[i] = t;
        sum += t;
    }
    *ugr = sum > 0 ? 8 * log10(0.25 / Lb * sum) : NAN;
    return LX_OK;
}

double lx_luminaire_projected_area(const lx_luminaire *lum, double x, double y, double z)
{
    if (!lum) return 0;
    double W = lum->width_m, Lg = lum->length_m, H = lum->height_m > 0 ? lum->height_m : 0;
    int circular = W < 0 || (W == 0 && Lg > 0);
    if (circular) {
        double D = W < 0 ? -W : Lg;
        return LX__PI * D * D / 4 * fabs(z) + D * H * sqrt(x * x + y * y);
    }
    if (!(W > 0) || !(Lg > 0)) return 0;
    return W * Lg * fabs(z) + H * (Lg * fabs(x) + W * fabs(y));
}

/* ---- CIE 190 tabular method ---- */

#define UGR_H 2.0      /* the luminaire plane above the eye, m (the table does not depend on it) */
#define UGR_SHR 0.25   /* spacing-to-height ratio of the standard arrays */

/* Mean over the C planes (1 degree steps) of the intensity at gamma (deg). */
static double c_mean(const lx_luminaire *lum, double g)
{
    double s = 0;
    for (int c = 0; c < 360; c++) s += lx_luminaire_intensity(lum, LX_INTERP_BILINEAR, (c + 0.5) * LX__DEG, g * LX__DEG);
    return s / 360;
}

/* The room-independent flux fractions of CIE 190 4.2 per 1000 lm of lamp flux: the downward and
 * upward light output ratios and the cumulative zonal sums Phi_zL1..4 (10-degree zone midpoints). */
static void zonal(const lx_luminaire *lum, double lor, double *dlo, double *ulo, double phi[4])
{
    double G[18], sum = 0;
    for (int k = 0; k < 18; k++) {
        double g = 5 + 10 * k;
        G[k] = c_mean(lum, g) * 2 * LX__PI * sin(g * LX__DEG) * 10 * LX__DEG;
        sum += G[k];
    }
    double scale = sum > 0 ? 1000 * lor / sum : 0, down = 0, up = 0;
    for (int k = 0; k < 18; k++) {
        G[k] *= scale;
        if (k < 9) down += G[k];
        else up += G[k];
    }
    *dlo = down / 1000, *ulo = up / 1000;
    double c[9];
    c[0] = G[0];
    for (int k = 1; k < 9; k++) c[k] = c[k - 1] + G[k];
    phi[0] = c[3] + 0.130 * G[4];
    phi[1] = c[5];
    phi[2] = c[6] + 0.547 * G[7];
    phi[3] = c[8];
}

/* UGR of one room and orientation (endwise: the luminaire turned by 90 deg) for background Lb. */
static double room_ugr(const lx_luminaire *lum, double xh, double yh, int endwise, double Lb)
{
    double S = UGR_SHR * UGR_H, X = xh * UGR_H, Y = yh * UGR_H, sum = 0;
    int nt = (int)lround(X / S / 2), nr = (int)lround(Y / S);
    for (int a = 0; a < nr; a++) {
        double R = (a + 0.5) * S;
        for (int b = -nt; b < nt; b++) {
            double T = fabs((b + 0.5) * S), d2 = R * R + T * T + UGR_H * UGR_H, d = sqrt(d2);
            double gam = atan2(sqrt(R * R + T * T), UGR_H) / LX__DEG;
            if (T / R > 3 || gam > 85) continue; /* CIE 117 4.5 */
            /* the direction from the luminaire to the eye in its frame: C0 along the line of sight
             * crosswise, across it endwise */
            double ux = -(endwise ? T : R) / d, uy = -(endwise ? R : T) / d, uz = -UGR_H / d;
            double I = lx_luminaire_intensity_dir(lum, LX_INTERP_BILINEAR, ux, uy, uz);
            double Ap = lx_luminaire_projected_area(lum, ux, uy, uz);
            if (!(Ap > 0) || !(I > 0)) continue;
            double L = I / Ap, w = Ap / d2;
            double sigma = acos(R / d) / LX__DEG, tau = atan2(T, UGR_H) / LX__DEG;
            double p = lx_guth_position_index(sigma, tau);
            sum += L * L * w / (p * p);
        }
    }
    return sum > 0 ? 8 * log10(0.25 / Lb * sum) : NAN;
}

lx_status lx_ugr_table_compute(lx_ctx *ctx, const lx_luminaire *lum, lx_ugr_table *out)
{
    LX__NEED_CTX(ctx);
    if (!lum || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_ugr_table_compute: NULL argument");
    const lx__table *t = lx__table_find("cie190_ugr_factors");
    if (!t || t->nrows != 19 || t->ncols != 23)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "UGR table: the CIE 190 factors are missing from this build");
    if (!(lx_luminaire_projected_area(lum, 0, 0, -1) > 0) && !(lx_luminaire_projected_area(lum, 1, 0, 0) > 0))
        return lx__error(ctx, LX_EINVAL, lum->file, 0,
                         "UGR table: the luminaire has no luminous area (its width and length are 0)");
    lx_lum_summary sum;
    lx_status st = lx_luminaire_summary(ctx, lum, &sum);
    if (st != LX_OK) return st;
    double lamp = lum->lamp_lumens > 0 ? lum->lamp_lumens : sum.lumens;
    if (!(lamp > 0) || !(sum.lumens > 0))
        return lx__error(ctx, LX_EINVAL, lum->file, 0, "UGR table: the luminaire emits no flux");
    double lor = sum.lumens / lamp, dlo, ulo, phi[4];
    zonal(lum, lor, &dlo, &ulo, phi);
    memset(out, 0, sizeof *out);
    out->lamp_flux_lm = lamp;
    out->spacing_h = UGR_SHR;
    const double *D = t->data;
    for (int r = 0; r < 19; r++) {
        double xh = D[1 * 19 + r], yh = D[2 * 19 + r];
        out->x_h[r] = xh, out->y_h[r] = yh;
        /* CIE 190 eqs. 10-12: direct flux fractions on the floor cavity, walls and ceiling */
        double phiz = 0;
        for (int k = 0; k < 4; k++) phiz += phi[k] * D[(4 + k) * 19 + r];
        double fdf = phiz / 1000, fdw = dlo - fdf, fdc = ulo;
        /* eqs. 7 and 8b: B = N Phi / A_w, E_WID = B F_UWID, Lb = E_WID / pi */
        double S = UGR_SHR * UGR_H;
        long n = lround(xh * UGR_H / S / 2) * 2 * lround(yh * UGR_H / S);
        double Aw = 2 * UGR_H * (xh + yh) * UGR_H, B = lamp * (double)n / Aw;
        for (int c = 0; c < 5; c++) {
            double fu = fdf * D[(8 + 3 * c) * 19 + r] + fdw * D[(9 + 3 * c) * 19 + r] + fdc * D[(10 + 3 * c) * 19 + r];
            double Lb = B * fu / LX__PI;
            out->lb_cd_m2[r][c] = Lb;
            for (int e = 0; e < 2; e++) out->ugr[r][5 * e + c] = Lb > 0 ? room_ugr(lum, xh, yh, e, Lb) : NAN;
        }
    }
    return LX_OK;
}
