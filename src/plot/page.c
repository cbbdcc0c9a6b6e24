/* page.c - the drawing page of every plot: a cairo RGB image, text in DejaVu Sans (cairo's font
 * API through fontconfig) with every label's box recorded, free-space tests for placing labels,
 * and the atomic PNG writer (cairo's PNG encoder into a core/file_write.c file). */
#include "plot/plot_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define FONT "DejaVu Sans"

void lx__layout_free(lx__layout *lay)
{
    if (!lay) return;
    lx__free(lay->label);
    lx__free(lay->keep);
    memset(lay, 0, sizeof *lay);
}

void lx__rgb(cairo_t *cr, const unsigned char rgb[3], double a)
{
    if (a >= 1) cairo_set_source_rgb(cr, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
    else cairo_set_source_rgba(cr, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0, a);
}

/* a page on surface `kind` (0: an RGB image, 1: a recording of the drawing, for vector output) */
static lx_status page_init(lx_ctx *ctx, lx__page *pg, int w, int h, const unsigned char bg[3], int vector)
{
    memset(pg, 0, sizeof *pg);
    if (w < 1 || h < 1 || w > 16384 || h > 16384) return lx__error(ctx, LX_EINVAL, NULL, 0, "invalid plot size %dx%d", w, h);
    lx_status st = lx__cairo_load(ctx);
    if (st) return st;
    cairo_rectangle_t ext = {0, 0, w, h};
    pg->surface = vector ? cairo_recording_surface_create(CAIRO_CONTENT_COLOR, &ext)
                         : cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    if (cairo_surface_status(pg->surface) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(pg->surface);
        pg->surface = NULL;
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %dx%d plot", w, h);
    }
    pg->cr = cairo_create(pg->surface);
    if (cairo_status(pg->cr) != CAIRO_STATUS_SUCCESS) {
        lx__page_free(pg);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %dx%d plot", w, h);
    }
    pg->w = w;
    pg->h = h;
    lx__rgb(pg->cr, bg, 1);
    cairo_paint(pg->cr);
    cairo_set_line_cap(pg->cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(pg->cr, CAIRO_LINE_JOIN_ROUND);
    return LX_OK;
}

lx_status lx__page_init(lx_ctx *ctx, lx__page *pg, int w, int h, const unsigned char bg[3])
{
    return page_init(ctx, pg, w, h, bg, 0);
}

lx_status lx__page_init_vector(lx_ctx *ctx, lx__page *pg, int w, int h, const unsigned char bg[3])
{
    return page_init(ctx, pg, w, h, bg, 1);
}

void lx__page_free(lx__page *pg)
{
    if (!pg) return;
    if (pg->cr) cairo_destroy(pg->cr);
    if (pg->surface) cairo_surface_destroy(pg->surface);
    lx__layout_free(&pg->lay);
    memset(pg, 0, sizeof *pg);
}

void lx__page_take_layout(lx__page *pg, lx__layout *out)
{
    *out = pg->lay;
    memset(&pg->lay, 0, sizeof pg->lay);
}

/* ---- PNG ---- */

typedef struct png_sink {
    lx_ctx *ctx;
    lx__wfile *w;
} png_sink;

static cairo_status_t png_write(void *closure, const unsigned char *data, unsigned int length)
{
    png_sink *s = closure;
    return lx__wfile_write(s->ctx, s->w, data, length) == LX_OK ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

lx_status lx__page_write_png(lx_ctx *ctx, lx__page *pg, const char *path)
{
    if (!pg || !pg->surface || !path) return lx__error(ctx, LX_EINVAL, NULL, 0, "no plot or no path");
    if (pg->oom) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory while drawing");
    cairo_surface_flush(pg->surface);
    lx__wfile w;
    lx_status st = lx__wfile_open(ctx, path, &w);
    if (st) return st;
    png_sink sink = {ctx, &w};
    cairo_status_t cs = cairo_surface_write_to_png_stream(pg->surface, png_write, &sink);
    if (cs != CAIRO_STATUS_SUCCESS) {
        if (w.err) st = LX_EWRITE; /* the message is already recorded */
        else st = lx__error(ctx, cs == CAIRO_STATUS_NO_MEMORY ? LX_ENOMEM : LX_EWRITE, path, 0, "PNG encoding failed: %s",
                            cairo_status_to_string(cs));
    }
    return lx__wfile_close(ctx, &w, st);
}

/* ---- text ---- */

static void set_font(cairo_t *cr, const lx__font *f)
{
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL, f->bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, f->size);
}

/* the logical box of s at the origin, with the baseline at y = 0: [0, advance] x [-ascent, descent] */
static void measure(cairo_t *cr, const lx__font *f, const char *s, double *adv, double *asc, double *desc)
{
    cairo_font_extents_t fe;
    cairo_text_extents_t te;
    set_font(cr, f);
    cairo_font_extents(cr, &fe);
    cairo_text_extents(cr, s, &te);
    *adv = te.x_advance;
    *asc = fe.ascent;
    *desc = fe.descent;
}

lx__box lx__text_box(lx__page *pg, const lx__font *f, double x, double y, double ax, double ay, const char *s)
{
    double adv, asc, desc;
    measure(pg->cr, f, s, &adv, &asc, &desc);
    double h = asc + desc, x0 = x - ax * adv, y0 = y - ay * h;
    return (lx__box){x0, y0, x0 + adv, y0 + h};
}

static void record(lx__page *pg, lx__box b, int role, double value, const char *s)
{
    lx__layout *L = &pg->lay;
    if (L->n_label == L->cap_label) {
        size_t cap = L->cap_label ? 2 * L->cap_label : 64;
        lx__label *nl = lx__realloc_n(L->label, cap, sizeof *nl);
        if (!nl) {
            pg->oom = 1;
            return;
        }
        L->label = nl;
        L->cap_label = cap;
    }
    lx__label *l = &L->label[L->n_label++];
    l->box = b;
    l->role = role;
    l->value = value;
    snprintf(l->text, sizeof l->text, "%s", s);
}

lx__box lx__page_text(lx__page *pg, const lx__font *f, double x, double y, double ax, double ay, int role,
                      double value, const char *s)
{
    lx__box b = lx__text_box(pg, f, x, y, ax, ay, s);
    if (!s || !*s) return b;
    cairo_t *cr = pg->cr;
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe); /* the font set by lx__text_box */
    cairo_move_to(cr, b.x0, b.y0 + fe.ascent);
    if (f->halo) {
        static const unsigned char white[3] = {255, 255, 255};
        cairo_save(cr);
        cairo_text_path(cr, s);
        lx__rgb(cr, white, 0.85);
        cairo_set_line_width(cr, 3.0);
        cairo_stroke(cr);
        cairo_restore(cr);
        cairo_move_to(cr, b.x0, b.y0 + fe.ascent);
    }
    lx__rgb(cr, f->rgb, 1);
    cairo_show_text(cr, s);
    cairo_new_path(cr);
    record(pg, b, role, value, s);
    return b;
}

lx__box lx__page_text_fit(lx__page *pg, const lx__font *f, double x, double y, int role, const char *s, double maxw)
{
    lx__font g = *f;
    lx__box b = lx__text_box(pg, &g, x, y, 0, 0, s);
    while (b.x1 - b.x0 > maxw && g.size > 0.7 * f->size) {
        g.size *= 0.95;
        b = lx__text_box(pg, &g, x, y, 0, 0, s);
    }
    if (b.x1 - b.x0 <= maxw) return lx__page_text(pg, &g, x, y, 0, 0, role, NAN, s);
    char buf[512];
    size_t n = strlen(s) < sizeof buf - 4 ? strlen(s) : sizeof buf - 4;
    for (; n > 0; n--) {
        if (((unsigned char)s[n] & 0xc0) == 0x80) continue; /* cut between UTF-8 characters */
        memcpy(buf, s, n);
        memcpy(buf + n, "\u2026", 4);
        b = lx__text_box(pg, &g, x, y, 0, 0, buf);
        if (b.x1 - b.x0 <= maxw) break;
    }
    return lx__page_text(pg, &g, x, y, 0, 0, role, NAN, n ? buf : "");
}

lx__box lx__page_text_up(lx__page *pg, const lx__font *f, double x, double y, int role, const char *s)
{
    double adv, asc, desc;
    measure(pg->cr, f, s, &adv, &asc, &desc);
    cairo_t *cr = pg->cr;
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rotate(cr, -LX__PI / 2);
    cairo_move_to(cr, -adv / 2, (asc - desc) / 2);
    lx__rgb(cr, f->rgb, 1);
    cairo_show_text(cr, s);
    cairo_new_path(cr);
    cairo_restore(cr);
    double h = asc + desc;
    lx__box b = {x - h / 2, y - adv / 2, x + h / 2, y + adv / 2};
    record(pg, b, role, NAN, s);
    return b;
}

void lx__page_keep(lx__page *pg, lx__box b)
{
    lx__layout *L = &pg->lay;
    if (L->n_keep == L->cap_keep) {
        size_t cap = L->cap_keep ? 2 * L->cap_keep : 32;
        lx__box *nk = lx__realloc_n(L->keep, cap, sizeof *nk);
        if (!nk) {
            pg->oom = 1;
            return;
        }
        L->keep = nk;
        L->cap_keep = cap;
    }
    L->keep[L->n_keep++] = b;
}

int lx__box_overlap(lx__box a, lx__box b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

int lx__page_free_at(const lx__page *pg, lx__box b, double pad, lx__box within)
{
    lx__box g = {b.x0 - pad, b.y0 - pad, b.x1 + pad, b.y1 + pad};
    if (b.x0 < within.x0 || b.y0 < within.y0 || b.x1 > within.x1 || b.y1 > within.y1) return 0;
    for (size_t i = 0; i < pg->lay.n_label; i++)
        if (lx__box_overlap(g, pg->lay.label[i].box)) return 0;
    for (size_t i = 0; i < pg->lay.n_keep; i++)
        if (lx__box_overlap(g, pg->lay.keep[i])) return 0;
    return 1;
}
