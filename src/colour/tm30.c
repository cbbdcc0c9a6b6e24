/* tm30.c - CIE 224:2017 colour fidelity index Rf and ANSI/IES TM-30-20 gamut index Rg with the
 * 16 hue-bin values, in CAM02-UCS (CIECAM02 forward model, Luo et al. 2006 UCS) with 99 CES. */
#include "colour/colour_private.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TM_START 380.0
#define TM_END 780.0
#define NCES 99
#define NBIN 16
#define DUV_LIMIT 0.05
#define OUTSIDE_LIMIT 0.01


/* CIECAM02 viewing conditions of CIE 224: L_A = 100 cd/m2, Y_b = 20, average surround, D = 1. */
typedef struct cam {
    double rgbw_scale[3]; /* Y_w / RGB_w (D = 1) */
    double fl, n, z, nbb, ncb, nc, c, aw;
    double M[3][3];       /* M_HPE * inverse(M_CAT02) */
} cam;

static const double M_CAT02[3][3] = {{0.7328, 0.4296, -0.1624}, {-0.7036, 1.6975, 0.0061}, {0.0030, 0.0136, 0.9834}};
static const double M_HPE[3][3] = {
    {0.38971, 0.68898, -0.07868}, {-0.22981, 1.18340, 0.04641}, {0.00000, 0.00000, 1.00000}};

static void mat3_vec(const double m[3][3], const double v[3], double o[3])
{
    for (int i = 0; i < 3; i++) o[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

/* M_HPE * inverse(M_CAT02), computed once per call (cheap, no global state). */
static void hpe_cat_inv(double m[3][3])
{
    const double(*a)[3] = M_CAT02;
    double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                 a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    double inv[3][3] = {
        {(a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det, (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det,
         (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det},
        {(a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det, (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det,
         (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det},
        {(a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det, (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det,
         (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) m[i][j] = M_HPE[i][0] * inv[0][j] + M_HPE[i][1] * inv[1][j] + M_HPE[i][2] * inv[2][j];
}

/* Post-adaptation non-linear compression (CIECAM02 eq. 7.11, signed as colour-science does). */
static double compress(double fl, double x)
{
    double p = pow(fl * fabs(x) / 100.0, 0.42);
    return (x < 0 ? -400.0 : 400.0) * p / (27.13 + p) + 0.1;
}

/* Adapted, compressed cone responses of XYZ. */
static void cam_rgba(const cam *cm, const double XYZ[3], double rgba[3])
{
    double rgb[3], rgbc[3], rgbp[3];
    mat3_vec(M_CAT02, XYZ, rgb);
    for (int i = 0; i < 3; i++) rgbc[i] = cm->rgbw_scale[i] * rgb[i];
    mat3_vec(cm->M, rgbc, rgbp);
    for (int i = 0; i < 3; i++) rgba[i] = compress(cm->fl, rgbp[i]);
}

static void cam_init(cam *cm, const double XYZw[3])
{
    hpe_cat_inv(cm->M);
    const double LA = 100.0, Yb = 20.0;
    double rgbw[3];
    mat3_vec(M_CAT02, XYZw, rgbw);
    for (int i = 0; i < 3; i++) cm->rgbw_scale[i] = XYZw[1] / rgbw[i];
    double k = 1.0 / (5.0 * LA + 1.0), k4 = k * k * k * k;
    cm->fl = 0.2 * k4 * (5.0 * LA) + 0.1 * (1.0 - k4) * (1.0 - k4) * cbrt(5.0 * LA);
    cm->n = Yb / XYZw[1];
    cm->z = 1.48 + sqrt(cm->n);
    cm->nbb = cm->ncb = 0.725 * pow(1.0 / cm->n, 0.2);
    cm->nc = 1.0, cm->c = 0.69; /* average surround */
    double a[3];
    cam_rgba(cm, XYZw, a);
    cm->aw = (2.0 * a[0] + a[1] + a[2] / 20.0 - 0.305) * cm->nbb;
}

/* CAM02-UCS J', a', b' of XYZ (and the CIECAM02 hue angle in degrees). */
static void cam02ucs(const cam *cm, const double XYZ[3], double jab[3], double *h_deg)
{
    double ra[3];
    cam_rgba(cm, XYZ, ra);
    double a = ra[0] - 12.0 * ra[1] / 11.0 + ra[2] / 11.0;
    double b = (ra[0] + ra[1] - 2.0 * ra[2]) / 9.0;
    double h = atan2(b, a) * 180.0 / LX__PI;
    if (h < 0) h += 360.0;
    double et = 0.25 * (cos(h * LX__PI / 180.0 + 2.0) + 3.8);
    double A = (2.0 * ra[0] + ra[1] + ra[2] / 20.0 - 0.305) * cm->nbb;
    double J = A > 0 ? 100.0 * pow(A / cm->aw, cm->c * cm->z) : 0.0;
    double t = (50000.0 / 13.0 * cm->nc * cm->ncb) * et * hypot(a, b) / (ra[0] + ra[1] + 21.0 / 20.0 * ra[2]);
    double C = pow(t, 0.9) * sqrt(J / 100.0) * pow(1.64 - pow(0.29, cm->n), 0.73);
    double Mc = C * pow(cm->fl, 0.25);
    double Mp = log1p(0.0228 * Mc) / 0.0228;
    jab[0] = 1.7 * J / (1.0 + 0.007 * J);
    jab[1] = Mp * cos(h * LX__PI / 180.0);
    jab[2] = Mp * sin(h * LX__PI / 180.0);
    if (h_deg) *h_deg = h;
}

static double rf_of(double dE) { return 10.0 * log1p(exp((100.0 - 6.73 * dE) / 10.0)); }

/* The reference illuminant of CIE 224 at T on the grid; ybar2 for the Y normalisation of the mix. */
static lx_status reference(lx_ctx *ctx, double T, const lx__qgrid *g, const double *ybar2, double *ref, double *tmp)
{
    size_t n = g->n;
    const double *lam = g->lam;
    if (T < 4000.0) {
        for (size_t i = 0; i < n; i++) ref[i] = lx_planck(lam[i], T);
        return LX_OK;
    }
    lx_status st = lx_daylight(ctx, T, n, lam, ref);
    if (st != LX_OK || T >= 5000.0) return st;
    double yp = 0, yd = 0, m = (T - 4000.0) / 1000.0;
    for (size_t i = 0; i < n; i++) {
        tmp[i] = lx_planck(lam[i], T);
        yp += g->w[i] * tmp[i] * ybar2[i];
        yd += g->w[i] * ref[i] * ybar2[i];
    }
    for (size_t i = 0; i < n; i++) ref[i] = (1.0 - m) * tmp[i] / yp + m * ref[i] / yd;
    return LX_OK;
}

lx_status lx__tm30_reference_1nm(lx_ctx *ctx, double T, double ref[401])
{
    const lx__table *t2 = lx__table_find("cie1931_2deg_xyz_1nm");
    if (!t2) return lx__error(ctx, LX_EINVAL, NULL, 0, "TM-30: embedded tables missing");
    double lam[401], w[401], ybar[401], tmp[401];
    for (int i = 0; i < 401; i++) lam[i] = 380 + i, w[i] = 1;
    lx__qgrid g = {401, lam, w, 0};
    lx__quality_table(t2, lx__table_col(t2, "y_bar"), &g, ybar);
    return reference(ctx, T, &g, ybar, ref, tmp);
}

lx_status lx__tm30_reference(lx_ctx *ctx, const lx__tm30_grid *tg, double T, double *ref, double *tmp)
{
    return reference(ctx, T, &tg->g, tg->cmf2 + tg->g.n, ref, tmp);
}

void lx__tm30_integrals(const lx__tm30_grid *tg, const double *illum, double *L, double *p)
{
    const lx__qgrid *g = &tg->g;
    size_t n = g->n;
    const double *cmf2 = tg->cmf2, *cmf10 = tg->cmf10;
    double X = 0, Y = 0, Z = 0;
    for (size_t i = 0; i < n; i++)
        X += g->w[i] * illum[i] * cmf2[i], Y += g->w[i] * illum[i] * cmf2[n + i], Z += g->w[i] * illum[i] * cmf2[2 * n + i];
    L[0] = X, L[1] = Y, L[2] = Z;
    /* the 10 deg white and the samples: the terms w illum cmf10 once, then each sample's weighted sum */
    for (int c = 0; c < 3; c++) {
        double w = 0;
        for (size_t i = 0; i < n; i++) {
            p[c * n + i] = g->w[i] * illum[i] * cmf10[c * n + i];
            w += p[c * n + i];
        }
        L[3 + c] = w;
    }
    for (int s = 0; s < NCES; s++) {
        const double *r = tg->ces + (size_t)s * n;
        for (int c = 0; c < 3; c++) {
            const double *pc = p + c * n;
            double acc = 0;
            for (size_t i = 0; i < n; i++) acc += pc[i] * r[i];
            L[6 + 3 * s + c] = acc;
        }
    }
}

/* J'a'b' of the 99 samples and the CAM hue of each, from an illuminant's integrals (10 deg). */
static void samples_jab(const double *L, double jab[NCES][3], double hue[NCES])
{
    double k = 100.0 / L[4];
    double XYZw[3] = {k * L[3], 100.0, k * L[5]};
    cam cm;
    cam_init(&cm, XYZw);
    for (int s = 0; s < NCES; s++) {
        double XYZ[3];
        for (int c = 0; c < 3; c++) XYZ[c] = k * L[6 + 3 * s + c];
        cam02ucs(&cm, XYZ, jab[s], &hue[s]);
    }
}

int lx__tm30_ok(double T, double duv) { return isfinite(T) && fabs(duv) <= DUV_LIMIT && T <= 25000.0; }

void lx__tm30_indices(const double *Lt, const double *Lr, double T, double duv, lx_tm30 *out)
{
    static lx_tm30 zero;
    lx_tm30 r = zero;
    r.cct_K = T, r.duv = duv;
    double jt[NCES][3], jr[NCES][3], ht[NCES], hr[NCES];
    samples_jab(Lt, jt, ht);
    samples_jab(Lr, jr, hr);
    double sum = 0, bin_dE[NBIN] = {0}, at[NBIN][2] = {{0}}, ar[NBIN][2] = {{0}};
    int cnt[NBIN] = {0};
    for (int s = 0; s < NCES; s++) {
        double dE = sqrt((jt[s][0] - jr[s][0]) * (jt[s][0] - jr[s][0]) + (jt[s][1] - jr[s][1]) * (jt[s][1] - jr[s][1]) +
                         (jt[s][2] - jr[s][2]) * (jt[s][2] - jr[s][2]));
        r.rf_ces[s] = rf_of(dE);
        sum += dE;
        int b = (int)floor(hr[s] / 22.5);
        if (b < 0) b = 0;
        if (b >= NBIN) b = NBIN - 1;
        cnt[b]++;
        bin_dE[b] += dE;
        at[b][0] += jt[s][1], at[b][1] += jt[s][2];
        ar[b][0] += jr[s][1], ar[b][1] += jr[s][2];
    }
    r.rf = rf_of(sum / NCES);
    int empty = 0;
    for (int b = 0; b < NBIN; b++) {
        if (!cnt[b]) {
            empty = 1;
            r.rf_hue[b] = r.rcs_hue[b] = r.rhs_hue[b] = NAN;
            r.test_ab[b][0] = r.test_ab[b][1] = r.ref_ab[b][0] = r.ref_ab[b][1] = NAN;
            continue;
        }
        for (int c = 0; c < 2; c++) r.test_ab[b][c] = at[b][c] / cnt[b], r.ref_ab[b][c] = ar[b][c] / cnt[b];
        r.rf_hue[b] = rf_of(bin_dE[b] / cnt[b]);
        double ang = (22.5 * b + 11.25) * LX__PI / 180.0, norm = hypot(r.ref_ab[b][0], r.ref_ab[b][1]);
        double da = r.test_ab[b][0] - r.ref_ab[b][0], db = r.test_ab[b][1] - r.ref_ab[b][1];
        r.rcs_hue[b] = 100.0 * (da * cos(ang) + db * sin(ang)) / norm;
        r.rhs_hue[b] = (-da * sin(ang) + db * cos(ang)) / norm;
    }
    if (empty) {
        r.rg = NAN;
    } else {
        double area_t = 0, area_r = 0;
        for (int b = 0; b < NBIN; b++) {
            int e = (b + 1) % NBIN;
            area_t += 0.5 * (r.test_ab[b][0] * r.test_ab[e][1] - r.test_ab[b][1] * r.test_ab[e][0]);
            area_r += 0.5 * (r.ref_ab[b][0] * r.ref_ab[e][1] - r.ref_ab[b][1] * r.ref_ab[e][0]);
        }
        r.rg = 100.0 * area_t / area_r;
    }
    *out = r;
}

lx_status lx__tm30_grid_make(lx_ctx *ctx, const lx_spd *spd, lx__tm30_grid *tg)
{
    memset(tg, 0, sizeof *tg);
    const lx__table *tc = lx__table_find("ies_tm30_ces_1nm");
    const lx__table *t10 = lx__table_find("cie1964_10deg_xyz_1nm");
    const lx__table *t2 = lx__table_find("cie1931_2deg_xyz_1nm");
    if (!tc || !t10 || !t2) return lx__error(ctx, LX_EINVAL, NULL, 0, "TM-30: embedded tables missing");
    lx_status st = lx__qgrid_make(ctx, spd, TM_START, TM_END, &tg->g);
    if (st != LX_OK) return st;
    size_t n = tg->g.n;
    if (!(tg->ces = lx__alloc(sizeof(double) * n * (NCES + 3 + 3 + 3)))) {
        lx__qgrid_free(&tg->g);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "TM-30: out of memory");
    }
    tg->cmf10 = tg->ces + (size_t)NCES * n, tg->cmf2 = tg->cmf10 + 3 * n, tg->scratch = tg->cmf2 + 3 * n;
    static const char *const c10[3] = {"x_bar_10", "y_bar_10", "z_bar_10"}, *const c2[3] = {"x_bar", "y_bar", "z_bar"};
    for (int c = 0; c < 3; c++) {
        lx__quality_table(t10, lx__table_col(t10, c10[c]), &tg->g, tg->cmf10 + c * n);
        lx__quality_table(t2, lx__table_col(t2, c2[c]), &tg->g, tg->cmf2 + c * n);
    }
    for (int s = 0; s < NCES; s++) {
        char name[8];
        snprintf(name, sizeof name, "CES%02d", s + 1);
        lx__quality_table(tc, lx__table_col(tc, name), &tg->g, tg->ces + (size_t)s * n);
    }
    return LX_OK;
}

void lx__tm30_grid_free(lx__tm30_grid *tg)
{
    lx__free(tg->ces);
    lx__qgrid_free(&tg->g);
    tg->ces = tg->cmf10 = tg->cmf2 = tg->scratch = NULL;
}

/* Why the spectrum has no TM-30 (a message in msg), or NULL. */
static const char *refusal(lx_ctx *ctx, const double *L, double *T, double *duv, char *msg, size_t cap)
{
    double X = L[0], Y = L[1], Z = L[2], d = X + 15 * Y + 3 * Z;
    if (!(Y > 0) || !(d > 0)) return "the spectrum has no luminous content in 380-780 nm";
    if (lx_cct_from_uv(ctx, LX_OBSERVER_2, 4 * X / d, 6 * Y / d, T, duv) != LX_OK) {
        snprintf(msg, cap, "no correlated colour temperature: %s", lx_ctx_errmsg(ctx));
        return msg;
    }
    if (fabs(*duv) > DUV_LIMIT) {
        snprintf(msg, cap, "Duv %.4f is beyond 0.05: too far from the Planckian locus for a CCT", *duv);
        return msg;
    }
    if (*T > 25000.0) {
        snprintf(msg, cap, "CCT %.0f K is above 25000 K, where CIE daylight is undefined", *T);
        return msg;
    }
    return NULL;
}

lx_status lx__tm30_outside(lx_ctx *ctx, const lx__tm30_grid *tg, const lx_spd *spd, const double *ref)
{
    double outside = lx__quality_outside(ref, &tg->g, spd->lambda_nm[0], spd->lambda_nm[spd->n - 1]);
    if (outside > OUTSIDE_LIMIT)
        return lx__error(ctx, LX_ERANGE, NULL, 0,
                         "TM-30: the spectrum covers %g-%g nm only; %.1f %% of the reference's tristimulus values lie "
                         "outside it (CIE 224 needs 380-780 nm)",
                         spd->lambda_nm[0], spd->lambda_nm[spd->n - 1], 100 * outside);
    return LX_OK;
}

/* The work of lx_tm30_compute on a checked spectrum. */
static lx_status tm30_compute_spd(lx_ctx *ctx, const lx_spd *spd, lx_tm30 *out)
{
    lx_status st;
    lx__tm30_grid tg;
    if ((st = lx__tm30_grid_make(ctx, spd, &tg)) != LX_OK) return st;
    size_t n = tg.g.n;
    double *buf = lx__alloc(sizeof(double) * (3 * n + 2 * LX__TM30_NINT));
    if (!buf) {
        lx__tm30_grid_free(&tg);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "TM-30: out of memory");
    }
    double *test = buf, *ref = test + n, *tmp = ref + n, *Lt = tmp + n, *Lr = Lt + LX__TM30_NINT;
    lx__quality_sample(spd, &tg.g, test);
    lx__tm30_integrals(&tg, test, Lt, tg.scratch);
    double T = NAN, duv = NAN;
    char msg[LX__ERRMSG_MAX];
    const char *why = refusal(ctx, Lt, &T, &duv, msg, sizeof msg);
    if (why) st = lx__error(ctx, LX_ERANGE, NULL, 0, "TM-30: %s", why);
    if (st == LX_OK) st = lx__tm30_reference(ctx, &tg, T, ref, tmp);
    if (st == LX_OK) st = lx__tm30_outside(ctx, &tg, spd, ref);
    if (st == LX_OK) {
        lx__tm30_integrals(&tg, ref, Lr, tg.scratch);
        lx__tm30_indices(Lt, Lr, T, duv, out);
    }
    lx__free(buf);
    lx__tm30_grid_free(&tg);
    return st;
}

lx_status lx_tm30_compute(lx_ctx *ctx, const lx_spd *spd, lx_tm30 *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "TM-30: output is NULL");
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    /* values near the bottom of the double range: the same spectrum scaled up by a power of two
     * (exact; every result is scale-free) */
    lx_spd up;
    double *ubuf;
    int te = lx__spd_tiny_scale(spd, &up, &ubuf);
    if (te == INT_MIN) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    st = tm30_compute_spd(ctx, te ? &up : spd, out);
    lx__free(ubuf);
    return st;
}
