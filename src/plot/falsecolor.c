/* falsecolor.c - colour scales (log or linear, with a useful automatic range), the false-colour
 * palette in the look of Radiance falsecolor, painting a value array through it, and the colour
 * bar legend with round or decade ticks and the unit. */
#include "plot/plot_private.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double lx__scale_t(const lx__scale *s, double v)
{
    double t;
    if (isnan(v)) return 0;
    if (s->log) t = v > 0 ? (log10(v) - log10(s->lo)) / (log10(s->hi) - log10(s->lo)) : 0;
    else t = s->hi > s->lo ? (v - s->lo) / (s->hi - s->lo) : 0.5;
    return t < 0 ? 0 : t > 1 ? 1 : t;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the 1st percentile of the positive finite values (INFINITY when there are none) */
static double low_positive(const double *v, size_t n)
{
    size_t m = 0;
    double *p = lx__alloc_n(n ? n : 1, sizeof *p), lo = INFINITY;
    for (size_t i = 0; i < n; i++)
        if (isfinite(v[i]) && v[i] > 0) {
            if (p) p[m++] = v[i];
            else lo = fmin(lo, v[i]); /* without memory: the smallest */
        }
    if (p && m) {
        qsort(p, m, sizeof *p, cmp_double);
        lo = p[m / 100];
    }
    lx__free(p);
    return lo;
}

void lx__scale_auto(lx__scale *s, const double *v, size_t n, int log, double lo, double hi)
{
    double mn = INFINITY, mx = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(v[i])) continue;
        mn = fmin(mn, v[i]);
        mx = fmax(mx, v[i]);
    }
    double pos = log && (isnan(lo) || !(lo > 0)) ? low_positive(v, n) : INFINITY;
    s->log = log;
    if (log) {
        double top = isfinite(mx) && mx > 0 ? pow(10, ceil(log10(mx) - 1e-9)) : 1;
        if (!isnan(hi) && hi > 0) top = hi;
        double bot = isfinite(pos) ? pow(10, floor(log10(pos) + 1e-9)) : top / 100;
        if (bot < top * 1e-6) bot = top * 1e-6;
        if (bot > top / 100) bot = top / 100; /* at least two decades: a flat map still shows its levels */
        if (!isnan(lo) && lo > 0) bot = lo;
        if (!(top > bot)) top = bot * 100;
        s->lo = bot;
        s->hi = top;
        return;
    }
    if (!isfinite(mn)) mn = 0, mx = 1;
    double l = mn >= -0.05 * fabs(mx) ? 0 : mn, h = mx; /* a little ringing below 0 does not move the bottom */
    if (!(h > l)) h = l + (l != 0 ? fabs(l) : 1);
    double step = lx__nice_step(h - l, 5);
    l = floor(l / step + 1e-9) * step;
    h = ceil(h / step - 1e-9) * step;
    if (!isnan(lo)) l = lo;
    if (!isnan(hi)) h = hi;
    if (!(h > l)) h = l + 1;
    s->lo = l;
    s->hi = h;
}

size_t lx__scale_auto_map(lx__scale *s, const double *v, size_t n, int log, double lo, double hi, double *above_max)
{
    double cut = INFINITY;
    *above_max = NAN;
    if (isnan(hi)) { /* a small bright source: the values more than 100 times the 99.9th percentile */
        size_t m = 0;
        double *p = lx__alloc_n(n ? n : 1, sizeof *p);
        for (size_t i = 0; p && i < n; i++)
            if (isfinite(v[i]) && v[i] > 0) p[m++] = v[i];
        if (p && m >= 1000) {
            qsort(p, m, sizeof *p, cmp_double);
            double q = p[m - 1 - m / 1000];
            if (q > 0 && p[m - 1] > 1000 * q) cut = 100 * q;
        }
        lx__free(p);
    }
    if (isinf(cut)) {
        lx__scale_auto(s, v, n, log, lo, hi);
        return 0;
    }
    double below = -INFINITY; /* the largest value of the rest */
    for (size_t i = 0; i < n; i++)
        if (isfinite(v[i]) && v[i] <= cut) below = fmax(below, v[i]);
    double top = log ? pow(10, ceil(log10(below) - 1e-9)) : below * (1 + 1e-12);
    if (!log) {
        double step = lx__nice_step(below, 5);
        top = ceil(below / step - 1e-9) * step;
    }
    lx__scale_auto(s, v, n, log, lo, top);
    size_t above = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(v[i]) && v[i] > s->hi) above++, *above_max = isnan(*above_max) ? v[i] : fmax(*above_max, v[i]);
    return above;
}

/* palette stops: dark violet, blue, cyan, green, yellow, orange, red (Radiance falsecolor-like) */
static const double stops[7][3] = {{0.18, 0.00, 0.35}, {0.00, 0.20, 0.90}, {0.00, 0.75, 0.85}, {0.15, 0.80, 0.15},
                                   {0.95, 0.95, 0.10}, {1.00, 0.55, 0.00}, {0.85, 0.00, 0.05}};

void lx__falsecolor(double t, unsigned char rgb[3])
{
    if (!(t >= 0)) t = 0; /* NaN too */
    if (t > 1) t = 1;
    double x = t * 6;
    int k = (int)x;
    if (k > 5) k = 5;
    double f = x - k;
    for (int c = 0; c < 3; c++) rgb[c] = (unsigned char)lround(255 * ((1 - f) * stops[k][c] + f * stops[k + 1][c]));
}

lx_status lx__page_map(lx_ctx *ctx, lx__page *pg, lx__box box, const double *v, int vw, int vh, const lx__scale *s)
{
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, vw, vh);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(img);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %dx%d map", vw, vh);
    }
    cairo_surface_flush(img);
    unsigned char *data = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    for (int j = 0; j < vh; j++) {
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)j * stride);
        for (int i = 0; i < vw; i++) {
            double x = v[(size_t)j * vw + i];
            unsigned char c[3] = {128, 128, 128};
            if (!isnan(x)) lx__falsecolor(lx__scale_t(s, x), c);
            row[i] = (uint32_t)c[0] << 16 | (uint32_t)c[1] << 8 | c[2];
        }
    }
    cairo_surface_mark_dirty(img);
    cairo_t *cr = pg->cr;
    cairo_save(cr);
    cairo_rectangle(cr, box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
    cairo_clip(cr);
    cairo_translate(cr, box.x0, box.y0);
    cairo_scale(cr, (box.x1 - box.x0) / vw, (box.y1 - box.y0) / vh);
    cairo_set_source_surface(cr, img, 0, 0);
    /* enlarged: each value a block; reduced: averaged */
    cairo_pattern_set_filter(cairo_get_source(cr), box.x1 - box.x0 >= vw ? CAIRO_FILTER_NEAREST : CAIRO_FILTER_GOOD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);
    return LX_OK;
}

void lx__page_legend(lx__page *pg, lx__box box, const lx__scale *s, const char *title)
{
    static const unsigned char ink[3] = {30, 30, 30};
    const lx__font ft = {12, 1, {30, 30, 30}, 0}, fk = {11, 0, {30, 30, 30}, 0};
    cairo_t *cr = pg->cr;
    double y = box.y0;
    if (title && *title) {
        lx__box tb = lx__page_text(pg, &ft, box.x0, y, 0, 0, LX__TEXT_LEGEND, NAN, title);
        y = tb.y1 + 8;
    }
    double bw = 18, bx = box.x0, by0 = y + 6, by1 = box.y1 - 8;
    if (by1 - by0 < 40) return;
    int n = (int)(by1 - by0);
    for (int j = 0; j < n; j++) {
        unsigned char c[3];
        lx__falsecolor(1.0 - (j + 0.5) / n, c);
        lx__rgb(cr, c, 1);
        cairo_rectangle(cr, bx, by0 + j, bw, 1);
        cairo_fill(cr);
    }
    lx__rgb(cr, ink, 1);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, bx + 0.5, by0 + 0.5, bw - 1, by1 - by0 - 1);
    cairo_stroke(cr);
    lx__box bar = {bx, by0, bx + bw, by1};
    pg->lay.legend_bar = bar;
    pg->lay.scale_lo = s->lo;
    pg->lay.scale_hi = s->hi;
    pg->lay.scale_log = s->log;
    lx__page_keep(pg, bar);
    double t[32], step = 0;
    int nt = s->log ? lx__ticks_log(s->lo, s->hi, t, (int)((by1 - by0) / 18) + 1)
                    : lx__ticks_linear(s->lo, s->hi, 6, t, 32, &step);
    for (int k = 0; k < nt; k++) {
        double ty = by1 - lx__scale_t(s, t[k]) * (by1 - by0);
        lx__rgb(cr, ink, 1);
        cairo_move_to(cr, bx + bw, round(ty) + 0.5);
        cairo_line_to(cr, bx + bw + 5, round(ty) + 0.5);
        cairo_stroke(cr);
        char buf[32];
        if (s->log) lx__fmt_decade(buf, sizeof buf, t[k]);
        else lx__fmt_tick(buf, sizeof buf, t[k], step);
        lx__box lb = lx__text_box(pg, &fk, bx + bw + 8, ty, 0, 0.5, buf);
        if (lx__page_free_at(pg, lb, 1, box)) lx__page_text(pg, &fk, bx + bw + 8, ty, 0, 0.5, LX__TEXT_LEGEND, t[k], buf);
    }
}
