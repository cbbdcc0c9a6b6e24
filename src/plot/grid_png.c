/* grid_png.c - the false-colour plot of an illuminance grid: the plane's values, iso-lux contour
 * lines, the luminaires' positions, axis ticks in metres and a colour legend in lux. */
#include "plot/plot_private.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const unsigned char INK[3] = {20, 20, 20}, WHITE[3] = {255, 255, 255}, BG[3] = {250, 250, 250};

/* A "nice" step (1, 2 or 5 x 10^k) giving about n intervals over span. */
static double nice_step(double span, int n)
{
    if (!(span > 0)) return 1;
    double raw = span / n, p = pow(10, floor(log10(raw))), f = raw / p;
    return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

/* Bilinear value of the na x nb grid (A fastest) at fractional grid coordinates (ga, gb). */
static double sample(const double *E, size_t na, size_t nb, double ga, double gb)
{
    if (na == 1 && nb == 1) return E[0];
    double fa = na > 1 ? ga : 0, fb = nb > 1 ? gb : 0;
    size_t ia = na > 1 ? (size_t)fmin(floor(fa), (double)(na - 2)) : 0;
    size_t ib = nb > 1 ? (size_t)fmin(floor(fb), (double)(nb - 2)) : 0;
    double ta = na > 1 ? fa - (double)ia : 0, tb = nb > 1 ? fb - (double)ib : 0;
    size_t ia1 = na > 1 ? ia + 1 : ia, ib1 = nb > 1 ? ib + 1 : ib;
    double e00 = E[ib * na + ia], e10 = E[ib * na + ia1], e01 = E[ib1 * na + ia], e11 = E[ib1 * na + ia1];
    return (1 - tb) * ((1 - ta) * e00 + ta * e10) + tb * ((1 - ta) * e01 + ta * e11);
}

static void disc(lx__canvas *c, int cx, int cy, int r, const unsigned char rgb[3])
{
    for (int y = -r; y <= r; y++)
        for (int x = -r; x <= r; x++)
            if (x * x + y * y <= r * r) lx__canvas_fill(c, cx + x, cy + y, 1, 1, rgb);
}

/* "X", "Y" or "Z" for an axis along a coordinate axis, else the fallback. */
static const char *axis_name(const double *u, const char *fallback)
{
    static const char *names[] = {"X", "Y", "Z", "-X", "-Y", "-Z"};
    for (int k = 0; k < 3; k++) {
        if (u[k] == 1) return names[k];
        if (u[k] == -1) return names[k + 3];
    }
    return fallback;
}

static void tick_label(char *buf, size_t cap, double v, double step)
{
    int dec = step >= 1 ? 0 : (int)ceil(-log10(step) - 1e-9);
    snprintf(buf, cap, "%.*f", dec, fabs(v) < 1e-12 ? 0.0 : v);
}

lx_status lx_grid_write_png(lx_ctx *ctx, const char *path, const lx_plane *p, const double *E,
                            const lx_placement *lums, size_t m, const char *title)
{
    LX__NEED_CTX(ctx);
    if (!path || !p || !E || p->na < 1 || p->nb < 1) return lx__error(ctx, LX_EINVAL, NULL, 0, "grid plot: bad arguments");
    double wa = p->a1 - p->a0, wb = p->b1 - p->b0;
    if (!(wa >= 0 && wb >= 0)) return lx__error(ctx, LX_EINVAL, NULL, 0, "grid plot: empty area");
    /* plot area: the longer side 560 px, the aspect of the plane kept */
    int pw = 560, ph = 560;
    if (wa > wb && wa > 0) ph = (int)fmax(120, lround(560 * wb / wa));
    else if (wb > 0) pw = (int)fmax(120, lround(560 * wa / wb));
    int left = 60, top = title && *title ? 34 : 16, legend_w = 120, bottom = 44;
    lx__canvas c;
    lx_status st = lx__canvas_init(ctx, &c, left + pw + 20 + legend_w, top + ph + bottom, BG);
    if (st != LX_OK) return st;
    double vmin = INFINITY, vmax = -INFINITY;
    size_t n = p->na * p->nb;
    for (size_t i = 0; i < n; i++)
        if (isfinite(E[i])) vmin = fmin(vmin, E[i]), vmax = fmax(vmax, E[i]);
    if (!(vmax >= vmin)) vmin = 0, vmax = 1;
    if (vmax == vmin) vmax = vmin + 1;
    /* values, resampled per pixel (row 0 at the top is b1) */
    double *img = malloc(sizeof(double) * (size_t)pw * (size_t)ph);
    if (!img) {
        lx__canvas_free(&c);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "grid plot: out of memory");
    }
    for (int y = 0; y < ph; y++)
        for (int x = 0; x < pw; x++) {
            double ga = (p->na - 1) * (pw > 1 ? (double)x / (pw - 1) : 0);
            double gb = (p->nb - 1) * (ph > 1 ? 1.0 - (double)y / (ph - 1) : 0);
            img[(size_t)y * pw + x] = sample(E, p->na, p->nb, ga, gb);
        }
    lx__canvas_values(&c, left, top, pw, ph, img, pw, ph, vmin, vmax, 0);
    /* iso-lux contours at nice levels: a pixel is on a contour where the level lies between it
     * and its right or lower neighbour */
    double cstep = nice_step(vmax - vmin, 6);
    for (double level = ceil(vmin / cstep) * cstep; level < vmax; level += cstep) {
        if (level <= vmin) continue;
        for (int y = 0; y < ph; y++)
            for (int x = 0; x < pw; x++) {
                double v = img[(size_t)y * pw + x];
                double r = x + 1 < pw ? img[(size_t)y * pw + x + 1] : v, d = y + 1 < ph ? img[(size_t)(y + 1) * pw + x] : v;
                if ((v - level) * (r - level) < 0 || (v - level) * (d - level) < 0 || v == level)
                    lx__canvas_fill(&c, left + x, top + y, 1, 1, INK);
            }
    }
    free(img);
    /* frame, axis ticks in metres */
    lx__canvas_fill(&c, left - 1, top - 1, pw + 2, 1, INK);
    lx__canvas_fill(&c, left - 1, top + ph, pw + 2, 1, INK);
    lx__canvas_fill(&c, left - 1, top - 1, 1, ph + 2, INK);
    lx__canvas_fill(&c, left + pw, top - 1, 1, ph + 2, INK);
    char buf[48];
    double sa = nice_step(wa, 6), sb = nice_step(wb, 6);
    for (double a = ceil(p->a0 / sa - 1e-9) * sa; wa > 0 && a <= p->a1 + 1e-9 * sa; a += sa) {
        int x = left + (int)lround((a - p->a0) / wa * (pw - 1));
        lx__canvas_fill(&c, x, top + ph, 1, 5, INK);
        tick_label(buf, sizeof buf, a, sa);
        lx__canvas_text(&c, x - lx__text_width(buf, 1) / 2, top + ph + 8, 1, buf, INK);
    }
    for (double b = ceil(p->b0 / sb - 1e-9) * sb; wb > 0 && b <= p->b1 + 1e-9 * sb; b += sb) {
        int y = top + (int)lround((1.0 - (b - p->b0) / wb) * (ph - 1));
        lx__canvas_fill(&c, left - 5, y, 5, 1, INK);
        tick_label(buf, sizeof buf, b, sb);
        lx__canvas_text(&c, left - 8 - lx__text_width(buf, 1), y - 3, 1, buf, INK);
    }
    snprintf(buf, sizeof buf, "%s (M)", axis_name(p->u, "U"));
    lx__canvas_text(&c, left + pw / 2 - lx__text_width(buf, 1) / 2, top + ph + 24, 1, buf, INK);
    snprintf(buf, sizeof buf, "%s (M)", axis_name(p->v, "V"));
    lx__canvas_text(&c, 4, top - 12 > 0 ? top - 12 : 0, 1, buf, INK);
    /* luminaires: their positions projected on the plane */
    for (size_t k = 0; k < m; k++) {
        double d[3] = {lums[k].pos_m[0] - p->origin_m[0], lums[k].pos_m[1] - p->origin_m[1], lums[k].pos_m[2] - p->origin_m[2]};
        double a = d[0] * p->u[0] + d[1] * p->u[1] + d[2] * p->u[2];
        double b = d[0] * p->v[0] + d[1] * p->v[1] + d[2] * p->v[2];
        if (wa > 0 && (a < p->a0 || a > p->a1)) continue;
        if (wb > 0 && (b < p->b0 || b > p->b1)) continue;
        int x = left + (wa > 0 ? (int)lround((a - p->a0) / wa * (pw - 1)) : pw / 2);
        int y = top + (wb > 0 ? (int)lround((1.0 - (b - p->b0) / wb) * (ph - 1)) : ph / 2);
        disc(&c, x, y, 6, INK);
        disc(&c, x, y, 4, WHITE);
    }
    if (title && *title) {
        char t[96];
        size_t k = 0;
        for (; title[k] && k + 1 < sizeof t; k++) t[k] = (char)toupper((unsigned char)title[k]); /* the font is upper case */
        t[k] = 0;
        lx__canvas_text(&c, left, 10, 2, t, INK);
    }
    lx__canvas_legend(&c, left + pw + 20, top, legend_w, ph, vmin, vmax, 0, "LX");
    st = lx__canvas_write_png(ctx, &c, path);
    lx__canvas_free(&c);
    return st;
}
