/* accuracy_plot.c - the error-against-time PNG of `luxcalc bench accuracy`: a log-log scatter plot
 * with one labelled marker per method, decade grid lines and a legend of series, drawn on the
 * canvas of png_plot.c. */
#include "plot/plot_private.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PW 860
#define PH 600
#define ML 96  /* margins: left (tick labels, y title) */
#define MR 190 /* right (legend) */
#define MT 44
#define MB 64

static const unsigned char BLACK[3] = {0, 0, 0}, GRID[3] = {222, 222, 222}, WHITE[3] = {255, 255, 255},
                           DARK[3] = {70, 70, 70};
static const unsigned char COLORS[8][3] = {{214, 39, 40}, {31, 119, 180}, {44, 160, 44}, {255, 127, 14},
                                           {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {23, 190, 207}};

static void hline(lx__canvas *c, int x0, int x1, int y, const unsigned char rgb[3]) { lx__canvas_fill(c, x0, y, x1 - x0 + 1, 1, rgb); }
static void vline(lx__canvas *c, int x, int y0, int y1, const unsigned char rgb[3]) { lx__canvas_fill(c, x, y0, 1, y1 - y0 + 1, rgb); }

/* Marker shapes by series: square, diamond, triangle, cross, ring, then again. */
static void marker(lx__canvas *c, int x, int y, int series, const unsigned char rgb[3])
{
    int shape = series % 5, r = 5;
    for (int dy = -r; dy <= r; dy++)
        for (int dx = -r; dx <= r; dx++) {
            int on = 0, ad = dx < 0 ? -dx : dx, bd = dy < 0 ? -dy : dy;
            switch (shape) {
            case 0: on = ad <= 4 && bd <= 4; break;
            case 1: on = ad + bd <= r; break;
            case 2: on = dy >= -4 && dy <= 4 && 2 * ad <= dy + 5; break;
            case 3: on = (ad == bd || ad + 1 == bd || ad == bd + 1) && ad <= r; break;
            default: on = dx * dx + dy * dy <= 25 && dx * dx + dy * dy >= 9; break;
            }
            if (on) lx__canvas_fill(c, x + dx, y + dy, 1, 1, rgb);
        }
}

static void decade_label(char *buf, size_t n, int e)
{
    if (e == 0) snprintf(buf, n, "1");
    else snprintf(buf, n, "1e%d", e);
}

lx_status lx_png_error_time(lx_ctx *ctx, const char *path, const char *title, const char *x_title, const char *y_title,
                            size_t n, const lx_plot_point *pts, int n_series, const char *const *series_names)
{
    LX__NEED_CTX(ctx);
    if (!path || !pts || n == 0) return lx__error(ctx, LX_EINVAL, NULL, 0, "error-time plot: no points");
    double tmin = INFINITY, tmax = -INFINITY, emin = INFINITY, emax = -INFINITY;
    int any_zero = 0;
    for (size_t k = 0; k < n; k++) {
        if (!(pts[k].time_s > 0) || !isfinite(pts[k].time_s))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "error-time plot: point %zu has time %g s", k + 1, pts[k].time_s);
        tmin = fmin(tmin, pts[k].time_s);
        tmax = fmax(tmax, pts[k].time_s);
        if (pts[k].error > 0 && isfinite(pts[k].error)) {
            emin = fmin(emin, pts[k].error);
            emax = fmax(emax, pts[k].error);
        } else {
            any_zero = 1;
        }
    }
    if (!(emax > 0)) emin = emax = 1e-16;
    int tx0 = (int)floor(log10(tmin)), tx1 = (int)ceil(log10(tmax));
    int ey0 = (int)floor(log10(emin)) - (any_zero ? 1 : 0), ey1 = (int)ceil(log10(emax));
    if (tx1 <= tx0) tx1 = tx0 + 1;
    if (ey1 <= ey0) ey1 = ey0 + 1;
    lx__canvas c;
    lx_status st = lx__canvas_init(ctx, &c, PW, PH, WHITE);
    if (st) return st;
    int x0 = ML, x1 = PW - MR, y0 = MT, y1 = PH - MB; /* plot area, y0 at the top */
    char buf[64];
    for (int e = tx0; e <= tx1; e++) {
        int x = x0 + (int)lround((double)(e - tx0) / (tx1 - tx0) * (x1 - x0));
        vline(&c, x, y0, y1, GRID);
        decade_label(buf, sizeof buf, e);
        lx__canvas_text(&c, x - lx__text_width(buf, 1) / 2, y1 + 8, 1, buf, BLACK);
    }
    int ystep = ey1 - ey0 > 12 ? 2 : 1;
    for (int e = ey0; e <= ey1; e++) {
        int y = y1 - (int)lround((double)(e - ey0) / (ey1 - ey0) * (y1 - y0));
        hline(&c, x0, x1, y, GRID);
        if ((e - ey0) % ystep) continue;
        decade_label(buf, sizeof buf, e);
        lx__canvas_text(&c, x0 - 8 - lx__text_width(buf, 1), y - 3, 1, buf, BLACK);
    }
    hline(&c, x0, x1, y0, DARK);
    hline(&c, x0, x1, y1, DARK);
    vline(&c, x0, y0, y1, DARK);
    vline(&c, x1, y0, y1, DARK);
    if (title) lx__canvas_text(&c, x0, 14, 2, title, BLACK);
    if (x_title) lx__canvas_text(&c, (x0 + x1 - lx__text_width(x_title, 1)) / 2, y1 + 28, 1, x_title, BLACK);
    if (y_title) lx__canvas_text(&c, 6, y0 - 14, 1, y_title, BLACK);
    for (size_t k = 0; k < n; k++) {
        const lx_plot_point *p = &pts[k];
        double tx = (log10(p->time_s) - tx0) / (tx1 - tx0);
        double ty = p->error > 0 && isfinite(p->error) ? (log10(p->error) - ey0) / (double)(ey1 - ey0) : 0;
        int x = x0 + (int)lround(tx * (x1 - x0)), y = y1 - (int)lround(ty * (y1 - y0));
        int s = p->series < 0 ? 0 : p->series;
        marker(&c, x, y, s, COLORS[s % 8]);
        char lab[80];
        snprintf(lab, sizeof lab, "%s%s", p->label ? p->label : "", p->error > 0 ? "" : " =0");
        int lx = x + 8, ly = y - 3 + ((k % 3) == 1 ? -9 : (k % 3) == 2 ? 9 : 0); /* stagger neighbours */
        if (lx + lx__text_width(lab, 1) > x1 - 2) lx = x - 8 - lx__text_width(lab, 1);
        lx__canvas_text(&c, lx, ly, 1, lab, COLORS[s % 8]);
    }
    for (int s = 0; s < n_series && series_names; s++) {
        int ly = y0 + 10 + 22 * s;
        marker(&c, x1 + 20, ly + 3, s, COLORS[s % 8]);
        lx__canvas_text(&c, x1 + 32, ly, 1, series_names[s] ? series_names[s] : "", BLACK);
    }
    if (any_zero) lx__canvas_text(&c, x1 + 14, y1 - 10, 1, "=0: EXACT (BOTTOM)", DARK);
    st = lx__canvas_write_png(ctx, &c, path);
    lx__canvas_free(&c);
    return st;
}
