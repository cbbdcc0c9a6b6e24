/* report_diagram.c - the spectrum report's CIE 1931 xy or CIE 1976 u'v' chromaticity diagram
 * (spectral locus filled with its colours, wavelength and isotemperature labels placed where they
 * collide with nothing, the Planckian locus, the point) and the TM-30 colour vector graphic with
 * its 16 hue bins. */
#include "plot/report.h"

#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const unsigned char INK[3] = {25, 25, 25}, RED[3] = {200, 30, 30}, WHITE[3] = {255, 255, 255};

typedef struct frame {
    lx__box b;
    double sx, sy;   /* pixels per unit */
    double xmax, ymax;
    int uv;
} frame;

static double fx(const frame *f, double x) { return f->b.x0 + x * f->sx; }
static double fy(const frame *f, double y) { return f->b.y1 - y * f->sy; }

/* xy -> the diagram's coordinates (xy itself, or u'v') */
static void to_diag(const frame *f, double x, double y, double *a, double *b)
{
    if (!f->uv) {
        *a = x, *b = y;
        return;
    }
    double d = -2 * x + 12 * y + 3;
    *a = 4 * x / d, *b = 9 * y / d;
}

static void axes(lx__page *pg, const frame *f)
{
    const lx__font fk = {11, 0, {25, 25, 25}, 0}, fa = {13, 0, {25, 25, 25}, 0};
    cairo_t *cr = pg->cr;
    lx__rgb(cr, INK, 1);
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, f->b.x0 + 0.5, f->b.y0), cairo_line_to(cr, f->b.x0 + 0.5, f->b.y1 + 0.5);
    cairo_line_to(cr, f->b.x1, f->b.y1 + 0.5), cairo_stroke(cr);
    double t[16], step;
    int n = lx__ticks_linear(0, f->xmax, 8, t, 16, &step);
    for (int k = 0; k < n; k++) {
        double x = round(fx(f, t[k])) + 0.5;
        char buf[16];
        cairo_move_to(cr, x, f->b.y1), cairo_line_to(cr, x, f->b.y1 + 5), cairo_stroke(cr);
        lx__fmt_tick(buf, sizeof buf, t[k], step);
        if (lx__page_free_at(pg, lx__text_box(pg, &fk, x, f->b.y1 + 7, 0.5, 0, buf), 1, (lx__box){0, 0, pg->w, pg->h}))
            lx__page_text(pg, &fk, x, f->b.y1 + 7, 0.5, 0, LX__TEXT_TICK, t[k], buf);
    }
    n = lx__ticks_linear(0, f->ymax, 8, t, 16, &step);
    for (int k = 0; k < n; k++) {
        double y = round(fy(f, t[k])) + 0.5;
        char buf[16];
        cairo_move_to(cr, f->b.x0 - 5, y), cairo_line_to(cr, f->b.x0, y), cairo_stroke(cr);
        lx__fmt_tick(buf, sizeof buf, t[k], step);
        if (lx__page_free_at(pg, lx__text_box(pg, &fk, f->b.x0 - 8, y, 1, 0.5, buf), 1, (lx__box){0, 0, pg->w, pg->h}))
            lx__page_text(pg, &fk, f->b.x0 - 8, y, 1, 0.5, LX__TEXT_TICK, t[k], buf);
    }
    lx__page_text(pg, &fa, f->b.x1, f->b.y1 + 22, 1, 0, LX__TEXT_AXIS, NAN, f->uv ? "u\u2032" : "x");
    lx__page_text(pg, &fa, f->b.x0, f->b.y0 - 6, 0.5, 1, LX__TEXT_AXIS, NAN, f->uv ? "v\u2032" : "y");
}

/* the inside of the spectral locus in its (approximate, lightened) colours */
static lx_status fill_locus(lx_ctx *ctx, lx__page *pg, const frame *f, const double *la, const double *lb, int nl)
{
    int W = (int)(f->b.x1 - f->b.x0), H = (int)(f->b.y1 - f->b.y0);
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, W, H);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(img);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    cairo_surface_flush(img);
    unsigned char *data = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    for (int j = 0; j < H; j++) {
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)j * stride);
        for (int i = 0; i < W; i++) {
            double a = (i + 0.5) / f->sx, b = (H - j - 0.5) / f->sy;
            int in = 0;
            for (int k = 0, q = nl - 1; k < nl; q = k++)
                if ((lb[k] > b) != (lb[q] > b) && a < (la[q] - la[k]) * (b - lb[k]) / (lb[q] - lb[k]) + la[k]) in = !in;
            row[i] = 0;
            if (!in) continue;
            double x = a, y = b; /* back to xy */
            if (f->uv) {
                double d = 6 * a - 16 * b + 12;
                x = 9 * a / d, y = 4 * b / d;
            }
            double xyz[3] = {x / y, 1.0, (1 - x - y) / y};
            unsigned char c[3];
            lx__xyz_to_srgb8(xyz, c);
            const double al = 0.6; /* premultiplied over white */
            row[i] = 0xffu << 24 | (uint32_t)lround(c[0] * al + 255 * (1 - al)) << 16 |
                     (uint32_t)lround(c[1] * al + 255 * (1 - al)) << 8 | (uint32_t)lround(c[2] * al + 255 * (1 - al));
        }
    }
    cairo_surface_mark_dirty(img);
    cairo_set_source_surface(pg->cr, img, f->b.x0, f->b.y0);
    cairo_paint(pg->cr);
    cairo_surface_destroy(img);
    return LX_OK;
}

/* the distance from box b to the isotherm e (from (x0, y0) to (x1, y1)) carried on 70 pixels
 * beyond (x1, y1) */
static double ray_box(const double *e, lx__box b)
{
    double dx = e[2] - e[0], dy = e[3] - e[1], n = hypot(dx, dy), best = INFINITY;
    for (double t = 0; t <= 70; t += 1) {
        double px = e[2] + t * dx / n, py = e[3] + t * dy / n;
        best = fmin(best, hypot(fmax(fmax(b.x0 - px, 0), px - b.x1), fmax(fmax(b.y0 - py, 0), py - b.y1)));
    }
    return best;
}

/* a label near (x, y) along direction (dx, dy) (unit, pixels), at the first free distance */
static void label_out(lx__page *pg, const lx__font *ft, double x, double y, double dx0, double dy0, const char *s,
                      lx__box within)
{
    static const double turn[5] = {0, 0.5, -0.5, 1.0, -1.0}; /* radians off the direction asked */
    for (int t = 0; t < 5; t++) {
        double dx = dx0 * cos(turn[t]) - dy0 * sin(turn[t]), dy = dx0 * sin(turn[t]) + dy0 * cos(turn[t]);
        for (double d = 3; d <= 21; d += 3) {
            double ax = dx < -0.3 ? 1 : dx > 0.3 ? 0 : 0.5, ay = dy < -0.3 ? 1 : dy > 0.3 ? 0 : 0.5;
            lx__box b = lx__text_box(pg, ft, x + d * dx, y + d * dy, ax, ay, s);
            if (!lx__page_free_at(pg, b, 1, within)) continue;
            lx__page_text(pg, ft, x + d * dx, y + d * dy, ax, ay, LX__TEXT_LABEL, NAN, s);
            return;
        }
    }
}

static lx_status loci(lx_ctx *ctx, lx__page *pg, const lx__report *r, const frame *f, lx__box within)
{
    enum { NL = 321 }; /* 380-700 nm: the locus folds back on itself above 700 nm */
    double la[NL], lb[NL];
    for (int k = 0; k < NL; k++) {
        double x, y;
        lx_status st = lx__locus_xy(ctx, r->obs, 380.0 + k, &x, &y);
        if (st) return st;
        to_diag(f, x, y, &la[k], &lb[k]);
    }
    lx_status st = fill_locus(ctx, pg, f, la, lb, NL);
    if (st) return st;
    cairo_t *cr = pg->cr;
    lx__rgb(cr, INK, 1);
    cairo_set_line_width(cr, 1.5);
    for (int k = 0; k < NL; k++) (k ? cairo_line_to : cairo_move_to)(cr, fx(f, la[k]), fy(f, lb[k]));
    cairo_close_path(cr);
    cairo_stroke(cr);
    /* the Planckian locus 1000 K - 100000 K */
    cairo_set_line_width(cr, 1.3);
    for (int k = 0; k <= 200; k++) {
        double T = 1000.0 * pow(100.0, k / 200.0), x, y, a, b;
        if ((st = lx__isotemp_xy(ctx, r->obs, T, 0.0, &x, &y))) return st;
        to_diag(f, x, y, &a, &b);
        (k ? cairo_line_to : cairo_move_to)(cr, fx(f, a), fy(f, b));
    }
    cairo_stroke(cr);
    /* isotemperature lines at Duv +-0.02, their labels beyond the lower end where free */
    static const double temps[] = {1500, 2000, 2500, 3000, 4000, 5000, 6500, 10000};
    const lx__font fl = {10, 0, {25, 25, 25}, 0};
    double ends[8][4];
    for (int k = 0; k < 8; k++) {
        double xa, ya, xb, yb;
        if ((st = lx__isotemp_xy(ctx, r->obs, temps[k], 0.02, &xa, &ya)) || (st = lx__isotemp_xy(ctx, r->obs, temps[k], -0.02, &xb, &yb)))
            return st;
        to_diag(f, xa, ya, &xa, &ya);
        to_diag(f, xb, yb, &xb, &yb);
        ends[k][0] = fx(f, xa), ends[k][1] = fy(f, ya), ends[k][2] = fx(f, xb), ends[k][3] = fy(f, yb);
        cairo_set_line_width(cr, 1.1);
        cairo_move_to(cr, ends[k][0], ends[k][1]), cairo_line_to(cr, ends[k][2], ends[k][3]);
        cairo_stroke(cr);
        for (int q = 0; q <= 24; q++) { /* labels keep off the line (small boxes along it) */
            double px = ends[k][0] + (ends[k][2] - ends[k][0]) * q / 24, py = ends[k][1] + (ends[k][3] - ends[k][1]) * q / 24;
            lx__page_keep(pg, (lx__box){px - 2, py - 2, px + 2, py + 2});
        }
    }
    /* the wavelength marks, then the isotherm labels, each where it is free */
    static const int marks[] = {460, 470, 480, 490, 500, 510, 520, 540, 560, 580, 600, 620};
    double wx = 0.3333, wy = 0.3333, wa, wb;
    to_diag(f, wx, wy, &wa, &wb);
    for (size_t k = 0; k < sizeof marks / sizeof *marks; k++) {
        double a = la[marks[k] - 380], b = lb[marks[k] - 380];
        double dx = fx(f, a) - fx(f, wa), dy = fy(f, b) - fy(f, wb), n = hypot(dx, dy);
        dx /= n, dy /= n;
        cairo_set_line_width(cr, 1);
        cairo_move_to(cr, fx(f, a), fy(f, b)), cairo_line_to(cr, fx(f, a) + 5 * dx, fy(f, b) + 5 * dy);
        cairo_stroke(cr);
        char buf[8];
        snprintf(buf, sizeof buf, "%d", marks[k]);
        label_out(pg, &fl, fx(f, a) + 2 * dx, fy(f, b) + 2 * dy, dx, dy, buf, within);
    }
    /* each isotherm's label on its own line carried on beyond its upper end (Duv +0.02, where the
     * isotherms fan out), at the first distance where it is free and crosses no other isotherm's
     * way, joined to the end by a fine leader; left out when nothing within 60 pixels is free (a
     * label never drifts sideways to another line's end) */
    double up[8][4]; /* each isotherm from its lower to its upper end: the way its label goes */
    for (int k = 0; k < 8; k++) up[k][0] = ends[k][2], up[k][1] = ends[k][3], up[k][2] = ends[k][0], up[k][3] = ends[k][1];
    for (int k = 0; k < 8; k++) {
        char buf[16];
        snprintf(buf, sizeof buf, "%.0f K", temps[k]);
        double dx = up[k][2] - up[k][0], dy = up[k][3] - up[k][1], n = hypot(dx, dy);
        dx /= n, dy /= n;
        double ax = dx < -0.3 ? 1 : dx > 0.3 ? 0 : 0.5, ay = dy < -0.3 ? 1 : dy > 0.3 ? 0 : 0.5;
        if (pg->lay.n_iso < 8) {
            double *q = pg->lay.iso[pg->lay.n_iso++];
            q[0] = temps[k], q[1] = up[k][0], q[2] = up[k][1], q[3] = up[k][2], q[4] = up[k][3];
        }
        for (double d = 3; d <= 60; d += 2) {
            double px = up[k][2] + d * dx, py = up[k][3] + d * dy;
            lx__box b = lx__text_box(pg, &fl, px, py, ax, ay, buf);
            if (!lx__page_free_at(pg, b, 1, within)) continue;
            int across = 0; /* on another isotherm's way: it would read as that one's */
            for (int j = 0; j < 8 && !across; j++) across = j != k && ray_box(up[j], b) < 2;
            if (across) continue;
            if (d > 5) {
                static const unsigned char lead[3] = {110, 110, 110};
                lx__rgb(cr, lead, 1);
                cairo_set_line_width(cr, 0.7);
                cairo_move_to(cr, up[k][2] + 2 * dx, up[k][3] + 2 * dy), cairo_line_to(cr, px - dx, py - dy);
                cairo_stroke(cr);
            }
            lx__page_text(pg, &fl, px, py, ax, ay, LX__TEXT_LABEL, temps[k], buf);
            break;
        }
    }
    return LX_OK;
}

lx_status lx__report_diagram(lx_ctx *ctx, lx__page *pg, const lx__report *r, lx__box box)
{
    const lx__font fh = {14, 1, {25, 25, 25}, 0}, fp = {11, 1, {200, 30, 30}, 1};
    int uv = r->diagram == LX_DIAGRAM_UV;
    char head[96];
    snprintf(head, sizeof head, "%s chromaticity (%s\u00b0 observer)", uv ? "CIE 1976 u\u2032v\u2032" : "CIE 1931 xy",
             r->obs == LX_OBSERVER_10 ? "10" : "2");
    lx__box hb = lx__page_text(pg, &fh, box.x0, box.y0, 0, 0, LX__TEXT_TITLE, NAN, head);
    frame f = {.uv = uv, .xmax = uv ? 0.65 : 0.8, .ymax = uv ? 0.6 : 0.9};
    double top = hb.y1 + 26, left = box.x0 + 38, bottom = box.y1 - 40;
    double s = fmin((box.x1 - left) / f.xmax, (bottom - top) / f.ymax);
    f.sx = f.sy = s;
    f.b = (lx__box){left, bottom - f.ymax * s, left + f.xmax * s, bottom};
    axes(pg, &f);
    lx_status st = loci(ctx, pg, r, &f, box);
    if (st) return st;
    double x = r->col.x, y = r->col.y;
    if (isfinite(x) && isfinite(y)) {
        double a, b;
        to_diag(&f, x, y, &a, &b);
        cairo_t *cr = pg->cr;
        lx__rgb(cr, WHITE, 1);
        cairo_arc(cr, fx(&f, a), fy(&f, b), 6, 0, 2 * LX__PI), cairo_fill(cr);
        lx__rgb(cr, RED, 1);
        cairo_arc(cr, fx(&f, a), fy(&f, b), 4.2, 0, 2 * LX__PI), cairo_fill(cr);
        char buf[64];
        if (uv) snprintf(buf, sizeof buf, "u\u2032 %.4f, v\u2032 %.4f", r->col.u_prime, r->col.v_prime);
        else snprintf(buf, sizeof buf, "x %.4f, y %.4f", x, y);
        lx__page_text(pg, &fp, f.b.x1, f.b.y0 + 4, 1, 0, LX__TEXT_LABEL, NAN, buf);
    }
    return LX_OK;
}

void lx__report_cvg(lx__page *pg, const lx__report *r, double cx, double cy, double R)
{
    const lx__font fh = {14, 1, {25, 25, 25}, 0}, fn = {11, 0, {25, 25, 25}, 0};
    char buf[128];
    double lim = 1.45 * R;
    if (!r->tm30_ok) {
        lx__page_text(pg, &fh, cx - lim, cy - lim - 40, 0, 0, LX__TEXT_TITLE, NAN, "TM-30 colour vector graphic: not defined");
        lx__page_text(pg, &fn, cx - lim, cy - lim - 18, 0, 0, LX__TEXT_NOTE, NAN, r->tm30_why);
        return;
    }
    snprintf(buf, sizeof buf, "TM-30 colour vector graphic: Rf %.0f, Rg %.0f", r->tm.rf, r->tm.rg);
    lx__page_text(pg, &fh, cx - lim, cy - lim - 40, 0, 0, LX__TEXT_TITLE, NAN, buf);
    if (!lx__tm30_cvg(pg, &r->tm, cx, cy, R, 0)) {
        lx__page_text(pg, &fn, cx - R, cy + lim + 16, 0, 0, LX__TEXT_NOTE, NAN, "a hue bin holds no sample");
        return;
    }
    const lx__font fr = {11, 0, {240, 80, 70}, 0};
    lx__page_text(pg, &fn, cx + lim + 24, cy + lim - 16, 0, 1, LX__TEXT_NOTE, NAN, "black: reference");
    lx__page_text(pg, &fr, cx + lim + 24, cy + lim, 0, 1, LX__TEXT_NOTE, NAN, "red: test");
}
