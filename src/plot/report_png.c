/* report_png.c - a one-page PNG report of one spectrum (issue 7): the SPD filled with wavelength
 * colours, a colour swatch, the CIE xy diagram with spectral and Planckian loci, CIE 13.3 R1-R14
 * bars, the TM-30 colour vector graphic and the headline numbers. Drawn on the png_plot.c canvas. */
#include "plot/plot_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


/* ---- geometry and colour (shared with the tests through lx_private.h) ---- */

/* linear sRGB from XYZ (IEC 61966-2-1, D65 white) */
static const double XYZ_TO_SRGB[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};

static double srgb_encode(double v)
{
    if (v <= 0.0) return 0.0;
    if (v >= 1.0) return 1.0;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1 / 2.4) - 0.055;
}

static unsigned char to8(double v) { return (unsigned char)lround(255.0 * srgb_encode(v)); }

void lx__xyz_to_srgb8(const double xyz[3], unsigned char rgb[3])
{
    double c[3], lo = 0, hi = 0;
    for (int i = 0; i < 3; i++) {
        c[i] = XYZ_TO_SRGB[i][0] * xyz[0] + XYZ_TO_SRGB[i][1] * xyz[1] + XYZ_TO_SRGB[i][2] * xyz[2];
        if (!isfinite(c[i])) c[i] = 0;
    }
    for (int i = 0; i < 3; i++) lo = fmin(lo, c[i]);
    for (int i = 0; i < 3; i++) c[i] -= lo, hi = fmax(hi, c[i]); /* desaturate out-of-gamut colours */
    for (int i = 0; i < 3; i++) rgb[i] = to8(hi > 0 ? c[i] / hi : 0);
}

lx_status lx__locus_xy(lx_ctx *ctx, lx_observer obs, double lambda_nm, double *x, double *y)
{
    lx_function f0 = obs == LX_OBSERVER_10 ? LX_FN_XBAR_10 : LX_FN_XBAR_2;
    double v[3];
    for (int k = 0; k < 3; k++) {
        lx_spd w;
        lx_status st = lx_function_get(ctx, (lx_function)(f0 + k), &w);
        if (st) return st;
        v[k] = lx__interp(w.lambda_nm, w.value, w.n, lambda_nm);
    }
    double s = v[0] + v[1] + v[2];
    if (!(s > 0)) return lx__error(ctx, LX_ERANGE, NULL, 0, "no chromaticity at %g nm", lambda_nm);
    *x = v[0] / s;
    *y = v[1] / s;
    return LX_OK;
}

void lx__wavelength_srgb8(lx_ctx *ctx, double lambda_nm, unsigned char rgb[3])
{
    lx_spd w[3];
    double v[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        if (lx_function_get(ctx, (lx_function)(LX_FN_XBAR_2 + k), &w[k]) == LX_OK)
            v[k] = lx__interp(w[k].lambda_nm, w[k].value, w[k].n, lambda_nm);
    double s = v[0] + v[1] + v[2];
    if (!(s > 0)) {
        rgb[0] = rgb[1] = rgb[2] = 150; /* outside the colour-matching functions: grey */
        return;
    }
    lx__xyz_to_srgb8(v, rgb);
    /* fade where the eye sees little (the ends of the spectrum): brightness sqrt(sum / 0.4) */
    double f = sqrt(fmin(1.0, s / 0.4));
    for (int k = 0; k < 3; k++) rgb[k] = (unsigned char)lround(rgb[k] * f);
}

lx_status lx__isotemp_xy(lx_ctx *ctx, lx_observer obs, double T_K, double duv, double *x, double *y)
{
    double u, v, u1, v1, u2, v2;
    lx_status st = lx_planck_uv(ctx, obs, T_K, &u, &v);
    if (!st) st = lx_planck_uv(ctx, obs, T_K * (1 - 1e-4), &u1, &v1);
    if (!st) st = lx_planck_uv(ctx, obs, T_K * (1 + 1e-4), &u2, &v2);
    if (st) return st;
    /* unit tangent of the locus in uv, and its normal turned towards +v ("above", Duv > 0) */
    double tu = u2 - u1, tv = v2 - v1, n = hypot(tu, tv);
    tu /= n, tv /= n;
    double nu = -tv, nv = tu;
    if (nv < 0) nu = -nu, nv = -nv;
    u += duv * nu, v += duv * nv;
    double d = 2 * u - 8 * v + 4;
    *x = 3 * u / d;
    *y = 2 * v / d;
    return LX_OK;
}

void lx__cvg_point(const double ref_ab[2], const double test_ab[2], double out[2])
{
    double r = hypot(ref_ab[0], ref_ab[1]), h = atan2(ref_ab[1], ref_ab[0]);
    out[0] = (test_ab[0] - ref_ab[0]) / r + cos(h);
    out[1] = (test_ab[1] - ref_ab[1]) / r + sin(h);
}

/* ---- drawing primitives ---- */

static const unsigned char INK[3] = {25, 25, 25}, GREY[3] = {150, 150, 150}, LIGHT[3] = {225, 225, 225},
                           WHITE[3] = {255, 255, 255}, RED[3] = {200, 30, 30};

static void blend(lx__canvas *c, int x, int y, const unsigned char rgb[3], double a)
{
    if (x < 0 || y < 0 || x >= c->w || y >= c->h) return;
    unsigned char *p = c->rgb + ((size_t)y * c->w + x) * 3;
    for (int k = 0; k < 3; k++) p[k] = (unsigned char)lround(p[k] * (1 - a) + rgb[k] * a);
}

/* a line of width t: discs of radius t/2 stamped every half pixel */
static void line(lx__canvas *c, double x0, double y0, double x1, double y1, double t, const unsigned char rgb[3])
{
    if (!isfinite(x0 + y0 + x1 + y1)) return;
    double len = hypot(x1 - x0, y1 - y0), r = t / 2;
    int n = (int)ceil(len * 2) + 1;
    if (n > 20000) return;
    for (int s = 0; s <= n; s++) {
        double x = x0 + (x1 - x0) * s / n, y = y0 + (y1 - y0) * s / n;
        for (int j = (int)floor(y - r); j <= (int)ceil(y + r); j++)
            for (int i = (int)floor(x - r); i <= (int)ceil(x + r); i++) {
                double d = hypot(i + 0.5 - x, j + 0.5 - y);
                if (d <= r + 0.5) blend(c, i, j, rgb, d <= r - 0.5 ? 1.0 : r + 0.5 - d);
            }
    }
}

static void disc(lx__canvas *c, double x, double y, double r, const unsigned char rgb[3])
{
    for (int j = (int)floor(y - r - 1); j <= (int)ceil(y + r + 1); j++)
        for (int i = (int)floor(x - r - 1); i <= (int)ceil(x + r + 1); i++) {
            double d = hypot(i + 0.5 - x, j + 0.5 - y);
            if (d <= r + 0.5) blend(c, i, j, rgb, d <= r - 0.5 ? 1.0 : r + 0.5 - d);
        }
}

static void rect_outline(lx__canvas *c, int x, int y, int w, int h, const unsigned char rgb[3])
{
    lx__canvas_fill(c, x, y, w, 1, rgb);
    lx__canvas_fill(c, x, y + h - 1, w, 1, rgb);
    lx__canvas_fill(c, x, y, 1, h, rgb);
    lx__canvas_fill(c, x + w - 1, y, 1, h, rgb);
}

static void text(lx__canvas *c, int x, int y, int scale, const char *s) { lx__canvas_text(c, x, y, scale, s, INK); }

static void text_centred(lx__canvas *c, int cx, int y, int scale, const char *s, const unsigned char rgb[3])
{
    lx__canvas_text(c, cx - lx__text_width(s, scale) / 2, y, scale, s, rgb);
}

/* word-wraps s into lines of at most `cols` characters from (x, y); returns the y after it */
static int text_wrap(lx__canvas *c, int x, int y, int cols, const char *s, const unsigned char rgb[3])
{
    char buf[256];
    while (*s) {
        size_t n = strlen(s), take = n;
        if ((int)n > cols) {
            take = (size_t)cols;
            while (take > 0 && s[take] != ' ') take--;
            if (take == 0) take = (size_t)cols;
        }
        if (take >= sizeof buf) take = sizeof buf - 1;
        memcpy(buf, s, take);
        buf[take] = 0;
        lx__canvas_text(c, x, y, 1, buf, rgb);
        y += 11;
        s += take;
        while (*s == ' ') s++;
    }
    return y;
}

static void upper(char *s)
{
    for (; *s; s++)
        if (*s >= 'a' && *s <= 'z') *s = (char)(*s - 'a' + 'A'); /* the font draws a lower-case e */
}

/* ---- the panels ---- */

typedef struct metrics {
    lx_colorimetry col;
    int cri_ok, tm30_ok, ao_ok;
    lx_cri cri;
    lx_tm30 tm;
    lx_alphaopic ao;
    char cri_why[256], tm30_why[256];
} metrics;

static void panel_spd(lx_ctx *ctx, lx__canvas *c, const lx_spd *spd, int X0, int Y0, int W, int H)
{
    text(c, X0 - 50, Y0 - 22, 1, "SPECTRAL POWER DISTRIBUTION (RELATIVE TO ITS PEAK)");
    double l0 = spd->lambda_nm[0], l1 = spd->lambda_nm[spd->n - 1];
    double a = floor(fmin(380.0, l0) / 10) * 10, b = ceil(fmax(780.0, l1) / 10) * 10;
    double vmax = 0;
    for (size_t i = 0; i < spd->n; i++) vmax = fmax(vmax, spd->value[i]);
    if (!(vmax > 0)) vmax = 1;
    /* grid and ticks */
    double step = b - a > 600 ? 100 : 50;
    for (double l = ceil(a / step) * step; l <= b + 1e-9; l += step) {
        int x = X0 + (int)lround((l - a) / (b - a) * (W - 1));
        lx__canvas_fill(c, x, Y0, 1, H, LIGHT);
        lx__canvas_fill(c, x, Y0 + H, 1, 5, INK);
        char buf[16];
        snprintf(buf, sizeof buf, "%.0f", l);
        text_centred(c, x, Y0 + H + 9, 1, buf, INK);
    }
    for (int k = 0; k <= 4; k++) {
        int y = Y0 + H - 1 - (int)lround(k * (H - 1) / 4.0);
        lx__canvas_fill(c, X0, y, W, 1, LIGHT);
        lx__canvas_fill(c, X0 - 5, y, 5, 1, INK);
        char buf[16];
        snprintf(buf, sizeof buf, "%.2f", k / 4.0);
        lx__canvas_text(c, X0 - 8 - lx__text_width(buf, 1), y - 3, 1, buf, INK);
    }
    text_centred(c, X0 + W / 2, Y0 + H + 22, 1, "WAVELENGTH (NM)", INK);
    /* the area under the curve, each column in the colour of its wavelength */
    double prev_y = NAN, prev_x = NAN;
    for (int i = 0; i < W; i++) {
        /* the largest value over the column's wavelengths, so narrow lines keep their peak */
        double l = a + (i + 0.5) / W * (b - a), la = a + (double)i / W * (b - a), lb = a + (i + 1.0) / W * (b - a);
        double v = fmax(lx__interp(spd->lambda_nm, spd->value, spd->n, la), lx__interp(spd->lambda_nm, spd->value, spd->n, lb));
        for (size_t q = 0; q < spd->n; q++)
            if (spd->lambda_nm[q] >= la && spd->lambda_nm[q] < lb) v = fmax(v, spd->value[q]);
        v /= vmax;
        if (v < 0) v = 0;
        int hgt = (int)lround(v * (H - 1));
        unsigned char rgb[3];
        lx__wavelength_srgb8(ctx, l, rgb);
        lx__canvas_fill(c, X0 + i, Y0 + H - hgt, 1, hgt, rgb);
        double y = Y0 + H - 1 - v * (H - 1);
        if (l >= l0 && l <= l1 && isfinite(prev_y)) line(c, prev_x, prev_y, X0 + i + 0.5, y, 1.6, INK);
        prev_x = (l >= l0 && l <= l1) ? X0 + i + 0.5 : NAN;
        prev_y = (l >= l0 && l <= l1) ? y : NAN;
    }
    lx__canvas_fill(c, X0, Y0 + H, W, 1, INK);
    lx__canvas_fill(c, X0 - 1, Y0, 1, H + 1, INK);
}

static void panel_cie(lx_ctx *ctx, lx__canvas *c, lx_observer obs, const metrics *m, int X0, int Y0)
{
    const double S = 440; /* pixels per unit of x and y */
    const int W = (int)(0.8 * S), H = (int)(0.9 * S);
#define PX(x) (X0 + (x) * S)
#define PY(y) (Y0 + H - (y) * S)
    text(c, X0 - 30, Y0 - 22, 1, obs == LX_OBSERVER_10 ? "CIE 1964 X10,Y10 CHROMATICITY (10 LX__DEG)" : "CIE 1931 X,Y CHROMATICITY (2 LX__DEG)");
    /* the spectral locus 380-700 nm (it folds back on itself above 700 nm), closed by the purple line */
    enum { NL = 321 };
    double lx[NL], ly[NL];
    for (int k = 0; k < NL; k++)
        if (lx__locus_xy(ctx, obs, 380.0 + k, &lx[k], &ly[k])) return;
    /* fill inside the locus with its approximate colour, lightened */
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double x = (i + 0.5) / S, y = (H - j - 0.5) / S;
            int in = 0;
            for (int k = 0, q = NL - 1; k < NL; q = k++)
                if ((ly[k] > y) != (ly[q] > y) && x < (lx[q] - lx[k]) * (y - ly[k]) / (ly[q] - ly[k]) + lx[k]) in = !in;
            if (!in) continue;
            double xyz[3] = {x / y, 1.0, (1 - x - y) / y};
            unsigned char rgb[3];
            lx__xyz_to_srgb8(xyz, rgb);
            blend(c, X0 + i, Y0 + j, rgb, 0.55);
        }
    for (int t = 0; t <= 8; t++) {
        int x = (int)lround(PX(t / 10.0));
        lx__canvas_fill(c, x, Y0 + H, 1, 5, INK);
        char buf[8];
        snprintf(buf, sizeof buf, "%.1f", t / 10.0);
        text_centred(c, x, Y0 + H + 9, 1, buf, INK);
    }
    for (int t = 0; t <= 9; t++) {
        int y = (int)lround(PY(t / 10.0));
        lx__canvas_fill(c, X0 - 5, y, 5, 1, INK);
        char buf[8];
        snprintf(buf, sizeof buf, "%.1f", t / 10.0);
        lx__canvas_text(c, X0 - 8 - lx__text_width(buf, 1), y - 3, 1, buf, INK);
    }
    lx__canvas_fill(c, X0, Y0 + H, W, 1, INK);
    lx__canvas_fill(c, X0 - 1, Y0, 1, H + 1, INK);
    text(c, X0 + W - 8, Y0 + H + 20, 1, "X");
    text(c, X0 + 6, Y0 + 2, 1, "Y");
    for (int k = 0; k < NL; k++) {
        int q = (k + 1) % NL;
        line(c, PX(lx[k]), PY(ly[k]), PX(lx[q]), PY(ly[q]), 1.5, INK);
    }
    static const int marks[] = {460, 470, 480, 490, 500, 510, 520, 540, 560, 580, 600, 620};
    for (size_t k = 0; k < sizeof marks / sizeof *marks; k++) {
        double x = lx[marks[k] - 380], y = ly[marks[k] - 380];
        double dx = x - 0.3333, dy = y - 0.3333, n = hypot(dx, dy);
        dx /= n, dy /= n;
        line(c, PX(x), PY(y), PX(x) + 6 * dx, PY(y) - 6 * dy, 1, INK);
        char buf[8];
        snprintf(buf, sizeof buf, "%d", marks[k]);
        int tx = (int)lround(PX(x) + 10 * dx), ty = (int)lround(PY(y) - 10 * dy) - 3;
        if (dx < 0) tx -= lx__text_width(buf, 1);
        lx__canvas_text(c, tx, ty, 1, buf, INK);
    }
    /* the Planckian locus 1000 K - 100000 K and isotemperature ticks at Duv +-0.02 */
    double px = NAN, py = NAN;
    for (int k = 0; k <= 200; k++) {
        double T = 1000.0 * pow(100.0, k / 200.0), x, y;
        if (lx__isotemp_xy(ctx, obs, T, 0.0, &x, &y)) return;
        if (k) line(c, PX(px), PY(py), PX(x), PY(y), 1.3, INK);
        px = x, py = y;
    }
    static const double temps[] = {1500, 2000, 2700, 3000, 4000, 5000, 6500, 10000};
    /* labelled ones, staggered along their lines so neighbours do not collide */
    static const char *const tlabel[] = {NULL, "2000K", NULL, NULL, "4000K", NULL, "6500K", NULL};
    static const double tdist[] = {0, -0.032, 0, 0, -0.032, 0, -0.052, 0};
    for (size_t k = 0; k < sizeof temps / sizeof *temps; k++) {
        double xa, ya, xb, yb;
        if (lx__isotemp_xy(ctx, obs, temps[k], 0.02, &xa, &ya) || lx__isotemp_xy(ctx, obs, temps[k], -0.02, &xb, &yb))
            return;
        line(c, PX(xa), PY(ya), PX(xb), PY(yb), 1.2, INK);
        /* the label beyond the tick's lower end, on the isotemperature line */
        if (tlabel[k] && !lx__isotemp_xy(ctx, obs, temps[k], tdist[k], &xb, &yb))
            text_centred(c, (int)lround(PX(xb)), (int)lround(PY(yb)) - 3, 1, tlabel[k], INK);
    }
    /* the point */
    double x = m->col.x, y = m->col.y;
    if (isfinite(x) && isfinite(y)) {
        disc(c, PX(x), PY(y), 5.5, WHITE);
        disc(c, PX(x), PY(y), 4.0, RED);
        char buf[48];
        snprintf(buf, sizeof buf, "(%.4f, %.4f)", x, y);
        lx__canvas_text(c, X0 + W - lx__text_width(buf, 1) - 4, Y0 + 4, 1, buf, RED);
    }
#undef PX
#undef PY
}

/* the colour of test colour sample k (0-based) under D65, for its bar (2 deg CMFs, 5 nm sums) */
static void tcs_colour(lx_ctx *ctx, int k, unsigned char rgb[3])
{
    const lx__table *t = lx__table_find("cie13_3_tcs");
    lx_spd d65, w[3];
    rgb[0] = rgb[1] = rgb[2] = 120;
    if (!t || lx_illuminant_get(ctx, "D65", &d65)) return;
    for (int f = 0; f < 3; f++)
        if (lx_function_get(ctx, (lx_function)(LX_FN_XBAR_2 + f), &w[f])) return;
    double xyz[3] = {0, 0, 0}, yw = 0;
    for (int r = 0; r < t->nrows; r++) {
        double l = t->data[r], refl = t->data[(size_t)(k + 1) * t->nrows + r];
        double e = lx__interp(d65.lambda_nm, d65.value, d65.n, l);
        for (int f = 0; f < 3; f++) xyz[f] += refl * e * lx__interp(w[f].lambda_nm, w[f].value, w[f].n, l);
        yw += e * lx__interp(w[1].lambda_nm, w[1].value, w[1].n, l);
    }
    for (int i = 0; i < 3; i++) {
        double v = (XYZ_TO_SRGB[i][0] * xyz[0] + XYZ_TO_SRGB[i][1] * xyz[1] + XYZ_TO_SRGB[i][2] * xyz[2]) / yw;
        rgb[i] = to8(v);
    }
}

static void panel_cri(lx_ctx *ctx, lx__canvas *c, const metrics *m, int X0, int Y0, int W, int H)
{
    char buf[128];
    if (!m->cri_ok) {
        text(c, X0 - 50, Y0 - 22, 1, "CIE 13.3 COLOUR RENDERING: NOT DEFINED FOR THIS SPECTRUM");
        rect_outline(c, X0, Y0, W, H, GREY);
        text_wrap(c, X0 + 10, Y0 + 12, (W - 20) / 6, m->cri_why, INK);
        return;
    }
    snprintf(buf, sizeof buf, "CIE 13.3 COLOUR RENDERING: RA %.1f  R9 %.1f%s", m->cri.ra, m->cri.r[8],
             m->cri.valid ? "" : "  (DC > 5.4E-3: RA NOT MEANINGFUL)");
    text(c, X0 - 50, Y0 - 22, 1, buf);
    double lo = 0;
    for (int k = 0; k < 14; k++) lo = fmin(lo, m->cri.r[k]);
    lo = fmax(-200.0, floor(lo / 50) * 50);
    double hi = 100;
#define VY(v) (Y0 + (int)lround((hi - (v)) / (hi - lo) * (H - 1)))
    for (double v = lo; v <= hi + 1e-9; v += 50) {
        int y = VY(v);
        lx__canvas_fill(c, X0, y, W, 1, v == 0 ? GREY : LIGHT);
        snprintf(buf, sizeof buf, "%.0f", v);
        lx__canvas_text(c, X0 - 8 - lx__text_width(buf, 1), y - 3, 1, buf, INK);
    }
    int n = 15, slot = W / n, bw = slot * 2 / 3;
    for (int k = 0; k < n; k++) {
        double v = k == 0 ? m->cri.ra : m->cri.r[k - 1];
        double vc = fmax(lo, fmin(hi, v));
        unsigned char rgb[3] = {90, 90, 90};
        if (k) tcs_colour(ctx, k - 1, rgb);
        int x = X0 + k * slot + (slot - bw) / 2, y0 = VY(0), y1 = VY(vc);
        int top = y0 < y1 ? y0 : y1, hgt = abs(y1 - y0);
        lx__canvas_fill(c, x, top, bw, hgt ? hgt : 1, rgb);
        rect_outline(c, x, top, bw, hgt ? hgt + 1 : 1, INK);
        snprintf(buf, sizeof buf, "%.0f", v);
        text_centred(c, x + bw / 2, v >= 0 ? y1 - 10 : y1 + 3, 1, buf, INK);
        if (k == 0) snprintf(buf, sizeof buf, "RA");
        else snprintf(buf, sizeof buf, "R%d", k);
        text_centred(c, x + bw / 2, Y0 + H + 5, 1, buf, INK);
    }
#undef VY
}

/* hue colour of a CAM02-UCS hue angle (deg): 0 red, 90 yellow, 180 green, 270 blue */
static void hue_rgb(double h, unsigned char rgb[3])
{
    static const double st[5][3] = {{0.85, 0.2, 0.3}, {0.9, 0.8, 0.1}, {0.2, 0.7, 0.3}, {0.2, 0.4, 0.9}, {0.85, 0.2, 0.3}};
    h = fmod(h + 360.0, 360.0);
    int k = (int)(h / 90);
    double f = h / 90 - k;
    for (int i = 0; i < 3; i++) rgb[i] = (unsigned char)lround(255 * ((1 - f) * st[k][i] + f * st[k + 1][i]));
}

static void panel_cvg(lx__canvas *c, const metrics *m, int cx, int cy, int R)
{
    char buf[128];
    if (!m->tm30_ok) {
        text(c, cx - 140, cy - R - 50, 1, "TM-30 COLOUR VECTOR GRAPHIC: NOT DEFINED FOR THIS SPECTRUM");
        text_wrap(c, cx - 140, cy - R - 26, 50, m->tm30_why, INK);
        return;
    }
    snprintf(buf, sizeof buf, "TM-30 COLOUR VECTOR GRAPHIC: RF %.0f  RG %.0f", m->tm.rf, m->tm.rg);
    text(c, cx - 140, cy - R - 50, 1, buf);
    double lim = 1.4 * R;
    for (int j = (int)-lim; j <= (int)lim; j++)
        for (int i = (int)-lim; i <= (int)lim; i++) {
            double r = hypot(i, j);
            if (r > lim) continue;
            double h = atan2(-j, i) * 180 / LX__PI;
            unsigned char rgb[3];
            hue_rgb(floor(fmod(h + 360, 360) / 22.5) * 22.5 + 11.25, rgb);
            blend(c, cx + i, cy + j, rgb, 0.22);
        }
    for (int b = 0; b < 16; b++) {
        double a = b * 22.5 * LX__PI / 180;
        line(c, cx, cy, cx + lim * cos(a), cy - lim * sin(a), 1, WHITE);
    }
    double pr = NAN, pq = NAN;
    for (int k = 0; k <= 180; k++) {
        double a = k * 2 * LX__PI / 180, x = cx + R * cos(a), y = cy - R * sin(a);
        if (k) line(c, pr, pq, x, y, 1.6, INK);
        pr = x, pq = y;
    }
    double pt[16][2];
    int ok = 1;
    for (int b = 0; b < 16; b++) {
        if (!isfinite(m->tm.ref_ab[b][0] + m->tm.test_ab[b][0])) ok = 0;
        else lx__cvg_point(m->tm.ref_ab[b], m->tm.test_ab[b], pt[b]);
    }
    if (!ok) {
        text(c, cx - R, cy + R + 26, 1, "A HUE BIN HOLDS NO SAMPLE");
        return;
    }
    for (int b = 0; b < 16; b++) {
        int e = (b + 1) % 16;
        line(c, cx + R * pt[b][0], cy - R * pt[b][1], cx + R * pt[e][0], cy - R * pt[e][1], 2.2, RED);
        double h = atan2(m->tm.ref_ab[b][1], m->tm.ref_ab[b][0]);
        line(c, cx + R * cos(h), cy - R * sin(h), cx + R * pt[b][0], cy - R * pt[b][1], 1.2, INK);
        disc(c, cx + R * pt[b][0], cy - R * pt[b][1], 2.5, RED);
    }
    text(c, cx + (int)lim + 30, cy + 40, 1, "BLACK: REFERENCE");
    lx__canvas_text(c, cx + (int)lim + 30, cy + 54, 1, "RED: TEST", RED);
}

static void panel_numbers(lx__canvas *c, const metrics *m, lx_observer obs, int X0, int Y0)
{
    char l[10][64];
    const lx_colorimetry *r = &m->col;
    snprintf(l[0], 64, "X      %.4f", r->x);
    snprintf(l[1], 64, "Y      %.4f", r->y);
    if (r->cct_valid) snprintf(l[2], 64, "CCT    %.0f K", r->cct_K), snprintf(l[3], 64, "DUV    %+.4f", r->duv);
    else snprintf(l[2], 64, "CCT    -"), snprintf(l[3], 64, "DUV    -");
    if (m->cri_ok) snprintf(l[4], 64, "RA     %.1f", m->cri.ra), snprintf(l[5], 64, "R9     %.1f", m->cri.r[8]);
    else snprintf(l[4], 64, "RA     -"), snprintf(l[5], 64, "R9     -");
    if (m->tm30_ok) {
        snprintf(l[6], 64, "RF     %.1f", m->tm.rf);
        if (isfinite(m->tm.rg)) snprintf(l[7], 64, "RG     %.1f", m->tm.rg);
        else snprintf(l[7], 64, "RG     -");
    } else {
        snprintf(l[6], 64, "RF     -"), snprintf(l[7], 64, "RG     -");
    }
    if (m->ao_ok && isfinite(m->ao.der[LX_AO_MEL])) snprintf(l[8], 64, "MEL DER %.3f", m->ao.der[LX_AO_MEL]);
    else snprintf(l[8], 64, "MEL DER -");
    snprintf(l[9], 64, "%s LX__DEG OBSERVER (CHROMATICITY)", obs == LX_OBSERVER_10 ? "10" : "2");
    for (int k = 0; k < 9; k++) text(c, X0 + (k / 5) * 230, Y0 + (k % 5) * 24, 2, l[k]);
    text(c, X0, Y0 + 5 * 24 + 4, 1, l[9]);
}

lx_status lx_spd_report_png(lx_ctx *ctx, const lx_spd *spd, lx_observer observer, const char *title, const char *path)
{
    LX__NEED_CTX(ctx);
    if (!spd || !path) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spd_report_png: NULL argument");
    if (observer != LX_OBSERVER_2 && observer != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spd_report_png: observer must be 2 or 10");
    lx_status st = lx_spd_check(ctx, spd);
    if (st) return st;
    metrics *m = calloc(1, sizeof *m);
    if (!m) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    st = lx_spd_colorimetry(ctx, spd, observer, LX_METHOD_AUTO, &m->col);
    if (st) {
        free(m);
        return st;
    }
    /* undefined metrics are shown with their reason; only memory failures abort */
    st = lx_cri_compute(ctx, spd, &m->cri);
    m->cri_ok = st == LX_OK;
    if (!m->cri_ok) snprintf(m->cri_why, sizeof m->cri_why, "%s", lx_ctx_errmsg(ctx)), upper(m->cri_why);
    if (st == LX_ENOMEM) goto out;
    st = lx_tm30_compute(ctx, spd, &m->tm);
    m->tm30_ok = st == LX_OK;
    if (!m->tm30_ok) snprintf(m->tm30_why, sizeof m->tm30_why, "%s", lx_ctx_errmsg(ctx)), upper(m->tm30_why);
    if (st == LX_ENOMEM) goto out;
    m->ao_ok = lx_alphaopic_compute(ctx, spd, LX_METHOD_AUTO, &m->ao) == LX_OK;

    lx__canvas c;
    if ((st = lx__canvas_init(ctx, &c, 1100, 800, WHITE))) goto out;
    char head[160];
    const char *t = title ? title : spd->name ? spd->name : "";
    snprintf(head, sizeof head, "LUXCALC SPECTRUM REPORT  %.60s", t);
    upper(head);
    text(&c, 20, 14, 2, head);
    lx__canvas_fill(&c, 20, 36, 1060, 1, GREY);
    panel_spd(ctx, &c, spd, 70, 78, 520, 230);
    panel_cri(ctx, &c, m, 70, 382, 520, 150);
    panel_numbers(&c, m, observer, 20, 590);
    panel_cie(ctx, &c, observer, m, 680, 78);
    panel_cvg(&c, m, 810, 660, 92);
    /* the swatch: the colour of the light, normalised (its luminance is not shown) */
    double xyz[3] = {m->col.X, m->col.Y, m->col.Z};
    unsigned char sw[3];
    lx__xyz_to_srgb8(xyz, sw);
    text(&c, 990, 540, 1, "COLOUR");
    if (m->col.Y > 0) lx__canvas_fill(&c, 990, 556, 80, 80, sw);
    else text(&c, 990, 590, 1, "NONE");
    rect_outline(&c, 989, 555, 82, 82, INK);
    char hex[16];
    snprintf(hex, sizeof hex, "%02X%02X%02X", sw[0], sw[1], sw[2]);
    if (m->col.Y > 0) text(&c, 990, 644, 1, hex);
    st = lx__canvas_write_png(ctx, &c, path);
    lx__canvas_free(&c);
out:
    free(m);
    return st;
}
