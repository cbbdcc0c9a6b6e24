/* error_time.c - the error-against-time PNG of `luxcalc bench accuracy`: a log-log scatter plot
 * with one marker per method, its label placed where it covers no other label or marker (near the
 * marker, else farther off with a leader line), decade grid lines and a legend of series. */
#include "plot/plot_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PW 960
#define PH 640
#define ML 92  /* margins: left (tick labels, y title) */
#define MR 230 /* right (legend) */
#define MT 58
#define MB 70

static const unsigned char GRIDC[3] = {225, 225, 225}, DARK[3] = {90, 90, 90};
static const unsigned char COLORS[8][3] = {{214, 39, 40}, {31, 119, 180}, {44, 160, 44}, {230, 120, 10},
                                           {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {23, 160, 180}};

/* Marker shapes by series: square, diamond, triangle, cross, ring, then again. */
static void marker(cairo_t *cr, double x, double y, int series, const unsigned char rgb[3])
{
    const double r = 5;
    lx__rgb(cr, rgb, 1);
    switch (series % 5) {
    case 0: cairo_rectangle(cr, x - 4.5, y - 4.5, 9, 9); cairo_fill(cr); break;
    case 1:
        cairo_move_to(cr, x, y - r - 1), cairo_line_to(cr, x + r + 1, y), cairo_line_to(cr, x, y + r + 1);
        cairo_line_to(cr, x - r - 1, y), cairo_close_path(cr), cairo_fill(cr);
        break;
    case 2:
        cairo_move_to(cr, x, y - r - 1), cairo_line_to(cr, x + r + 1, y + r), cairo_line_to(cr, x - r - 1, y + r);
        cairo_close_path(cr), cairo_fill(cr);
        break;
    case 3:
        cairo_set_line_width(cr, 2.2);
        cairo_move_to(cr, x - r, y - r), cairo_line_to(cr, x + r, y + r);
        cairo_move_to(cr, x + r, y - r), cairo_line_to(cr, x - r, y + r);
        cairo_stroke(cr);
        break;
    default:
        cairo_set_line_width(cr, 2);
        cairo_arc(cr, x, y, r - 0.5, 0, 2 * LX__PI);
        cairo_stroke(cr);
        break;
    }
}

/* the label of one point: beside the marker at the first free place, nearest first; farther off
 * with a leader line; never over another label or marker */
static void place_label(lx__page *pg, lx__box area, double x, double y, const char *lab, const unsigned char rgb[3])
{
    lx__font f = {11, 0, {rgb[0], rgb[1], rgb[2]}, 0};
    for (int ring = 0; ring < 40; ring++) {
        double d = 8 + 8 * ring;
        int nd = ring < 2 ? 8 : 16;
        for (int k = 0; k < nd; k++) {
            /* directions: right, left, up, down, then the diagonals, then between them */
            static const int order[16] = {0, 8, 4, 12, 2, 14, 6, 10, 1, 15, 7, 9, 3, 13, 5, 11};
            double ang = order[k] * LX__PI / 8, dx = cos(ang), dy = -sin(ang); /* (first rings: k < 8) */
            double ax = dx > 0.3 ? 0 : dx < -0.3 ? 1 : 0.5, ay = dy > 0.3 ? 0 : dy < -0.3 ? 1 : 0.5;
            double lx = x + dx * d, ly = y + dy * d;
            lx__box b = lx__text_box(pg, &f, lx, ly, ax, ay, lab);
            if (!lx__page_free_at(pg, b, 1.5, area)) continue;
            if (ring > 1) { /* a leader line from the marker towards the label */
                cairo_t *cr = pg->cr;
                double tx = fmin(fmax(x, b.x0), b.x1), ty = fmin(fmax(y, b.y0), b.y1);
                double len = hypot(tx - x, ty - y);
                if (len > 8) {
                    lx__rgb(cr, rgb, 0.6);
                    cairo_set_line_width(cr, 0.8);
                    cairo_move_to(cr, x + (tx - x) * 6 / len, y + (ty - y) * 6 / len);
                    cairo_line_to(cr, tx, ty);
                    cairo_stroke(cr);
                }
            }
            lx__page_text(pg, &f, lx, ly, ax, ay, LX__TEXT_LABEL, NAN, lab);
            return;
        }
    }
}

static void decade_axes(lx__page *pg, int tx0, int tx1, int ey0, int ey1, int x0, int x1, int y0, int y1)
{
    cairo_t *cr = pg->cr;
    const lx__font fk = {12, 0, {20, 20, 20}, 0};
    char buf[32];
    cairo_set_line_width(cr, 1);
    for (int e = tx0; e <= tx1; e++) {
        double x = round(x0 + (double)(e - tx0) / (tx1 - tx0) * (x1 - x0)) + 0.5;
        lx__rgb(cr, GRIDC, 1);
        cairo_move_to(cr, x, y0), cairo_line_to(cr, x, y1), cairo_stroke(cr);
        lx__fmt_decade(buf, sizeof buf, pow(10, e));
        lx__page_text(pg, &fk, x, y1 + 8, 0.5, 0, LX__TEXT_TICK, pow(10, e), buf);
    }
    int ystep = ey1 - ey0 > 12 ? 2 : 1;
    for (int e = ey0; e <= ey1; e++) {
        double y = round(y1 - (double)(e - ey0) / (ey1 - ey0) * (y1 - y0)) + 0.5;
        lx__rgb(cr, GRIDC, 1);
        cairo_move_to(cr, x0, y), cairo_line_to(cr, x1, y), cairo_stroke(cr);
        if ((e - ey0) % ystep) continue;
        lx__fmt_decade(buf, sizeof buf, pow(10, e));
        lx__page_text(pg, &fk, x0 - 8, y, 1, 0.5, LX__TEXT_TICK, pow(10, e), buf);
    }
    lx__rgb(cr, DARK, 1);
    cairo_rectangle(cr, x0 + 0.5, y0 + 0.5, x1 - x0, y1 - y0);
    cairo_stroke(cr);
}

lx_status lx__error_time_png(lx_ctx *ctx, const char *path, const char *title, const char *x_title,
                             const char *y_title, size_t n, const lx_plot_point *pts, int n_series,
                             const char *const *series_names, lx__layout *out)
{
    if (!path || !pts || n == 0) return lx__error(ctx, LX_EINVAL, NULL, 0, "error-time plot: no points");
    double tmin = INFINITY, tmax = -INFINITY, emin = INFINITY, emax = -INFINITY;
    int any_zero = 0;
    for (size_t k = 0; k < n; k++) {
        if (!(pts[k].time_s > 0) || !isfinite(pts[k].time_s))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "error-time plot: point %zu has time %g s", k + 1, pts[k].time_s);
        tmin = fmin(tmin, pts[k].time_s), tmax = fmax(tmax, pts[k].time_s);
        if (pts[k].error > 0 && isfinite(pts[k].error)) emin = fmin(emin, pts[k].error), emax = fmax(emax, pts[k].error);
        else any_zero = 1;
    }
    if (!(emax > 0)) emin = emax = 1e-16;
    int tx0 = (int)floor(log10(tmin)), tx1 = (int)ceil(log10(tmax));
    int ey0 = (int)floor(log10(emin)) - (any_zero ? 1 : 0), ey1 = (int)ceil(log10(emax));
    if (tx1 <= tx0) tx1 = tx0 + 1;
    if (ey1 <= ey0) ey1 = ey0 + 1;
    static const unsigned char white[3] = {255, 255, 255};
    lx__page pg;
    lx_status st = lx__page_init(ctx, &pg, PW, PH, white);
    if (st) return st;
    cairo_t *cr = pg.cr;
    int x0 = ML, x1 = PW - MR, y0 = MT, y1 = PH - MB; /* plot area, y0 at the top */
    lx__box area = {x0, y0, x1, y1};
    pg.lay.area = area;
    pg.lay.ax0 = pow(10, tx0), pg.lay.ax1 = pow(10, tx1), pg.lay.ay0 = pow(10, ey0), pg.lay.ay1 = pow(10, ey1);
    pg.lay.ax_log = pg.lay.ay_log = 1;
    decade_axes(&pg, tx0, tx1, ey0, ey1, x0, x1, y0, y1);
    const lx__font ft = {17, 1, {20, 20, 20}, 0}, fa = {12, 0, {20, 20, 20}, 0}, fl = {12, 0, {20, 20, 20}, 0};
    if (title) lx__page_text(&pg, &ft, x0, 16, 0, 0, LX__TEXT_TITLE, NAN, title);
    if (x_title) lx__page_text(&pg, &fa, 0.5 * (x0 + x1), y1 + 32, 0.5, 0, LX__TEXT_AXIS, NAN, x_title);
    if (y_title) lx__page_text_up(&pg, &fa, 18, 0.5 * (y0 + y1), LX__TEXT_AXIS, y_title);
    double (*xy)[2] = lx__alloc_n(n, sizeof *xy);
    if (!xy) {
        lx__page_free(&pg);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    /* every marker first (labels then avoid them all), then the labels */
    for (size_t k = 0; k < n; k++) {
        const lx_plot_point *p = &pts[k];
        double tx = (log10(p->time_s) - tx0) / (tx1 - tx0);
        double ty = p->error > 0 && isfinite(p->error) ? (log10(p->error) - ey0) / (double)(ey1 - ey0) : 0;
        xy[k][0] = x0 + tx * (x1 - x0), xy[k][1] = y1 - ty * (y1 - y0);
        int s = p->series < 0 ? 0 : p->series;
        marker(cr, xy[k][0], xy[k][1], s, COLORS[s % 8]);
        lx__page_keep(&pg, (lx__box){xy[k][0] - 6, xy[k][1] - 6, xy[k][0] + 6, xy[k][1] + 6});
    }
    for (size_t k = 0; k < n; k++) {
        char lab[80];
        snprintf(lab, sizeof lab, "%s%s", pts[k].label ? pts[k].label : "", pts[k].error > 0 ? "" : " (= 0)");
        int s = pts[k].series < 0 ? 0 : pts[k].series;
        if (*lab) place_label(&pg, area, xy[k][0], xy[k][1], lab, COLORS[s % 8]);
    }
    lx__free(xy);
    for (int s = 0; s < n_series && series_names; s++) {
        double ly = y0 + 12 + 24 * s;
        marker(cr, x1 + 22, ly, s, COLORS[s % 8]);
        lx__page_text(&pg, &fl, x1 + 36, ly, 0, 0.5, LX__TEXT_LABEL, NAN, series_names[s] ? series_names[s] : "");
    }
    if (any_zero) {
        const lx__font fn = {11, 0, {90, 90, 90}, 0};
        lx__page_text(&pg, &fn, x1 + 14, y1 - 14, 0, 1, LX__TEXT_NOTE, NAN, "(= 0): exact,");
        lx__page_text(&pg, &fn, x1 + 14, y1, 0, 1, LX__TEXT_NOTE, NAN, "drawn on the bottom edge");
    }
    st = lx__page_write_png(ctx, &pg, path);
    if (!st && out) lx__page_take_layout(&pg, out);
    lx__page_free(&pg);
    return st;
}

lx_status lx_error_time_write_png(lx_ctx *ctx, const char *path, const char *title, const char *x_title,
                                  const char *y_title, size_t n, const lx_plot_point *pts, int n_series,
                                  const char *const *series_names)
{
    LX__NEED_CTX(ctx);
    return lx__error_time_png(ctx, path, title, x_title, y_title, n, pts, n_series, series_names, NULL);
}
