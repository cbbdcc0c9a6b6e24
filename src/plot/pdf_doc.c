/* pdf_doc.c - a vector PDF document of A4 pages through cairo's PDF surface, written atomically
 * (core/file_write.c): running text wrapped to the page, headings, tables that continue on the next
 * page with their header, drawings placed from a recording; page header and footer. */
#include "plot/pdf_doc.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const unsigned char INK[3] = {25, 25, 25}, GREY[3] = {105, 105, 105}, RULE[3] = {180, 180, 180};

static cairo_status_t pdf_write(void *closure, const unsigned char *data, unsigned int length)
{
    lx__doc *d = closure;
    return lx__wfile_write(d->ctx, &d->w, data, length) == LX_OK ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

lx_status lx__doc_open(lx_ctx *ctx, lx__doc *d, const char *path, const char *title, const char *author)
{
    memset(d, 0, sizeof *d);
    d->ctx = ctx;
    d->path = path;
    lx_status st = lx__cairo_load(ctx);
    if (st) return st;
    if ((st = lx__wfile_open(ctx, path, &d->w)) != LX_OK) return st;
    d->open = 1;
    d->pg.surface = cairo_pdf_surface_create_for_stream(pdf_write, d, LX__DOC_W, LX__DOC_H);
    if (cairo_surface_status(d->pg.surface) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(d->pg.surface);
        d->pg.surface = NULL;
        return lx__doc_close(d, lx__error(ctx, LX_ENOMEM, path, 0, "out of memory for a PDF"));
    }
    if (title) cairo_pdf_surface_set_metadata(d->pg.surface, CAIRO_PDF_METADATA_TITLE, title);
    if (author) cairo_pdf_surface_set_metadata(d->pg.surface, CAIRO_PDF_METADATA_AUTHOR, author);
    cairo_pdf_surface_set_metadata(d->pg.surface, CAIRO_PDF_METADATA_CREATOR, "luxcalc " LX_VERSION_STRING);
    d->pg.cr = cairo_create(d->pg.surface);
    d->pg.w = (int)LX__DOC_W, d->pg.h = (int)LX__DOC_H;
    cairo_set_line_cap(d->pg.cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(d->pg.cr, CAIRO_LINE_JOIN_ROUND);
    d->page = 1;
    d->y = LX__DOC_TOP;
    return LX_OK;
}

/* the running header (not on the title page) and the page number */
static void furniture(lx__doc *d)
{
    lx__font f = {7.5, 0, {105, 105, 105}, 0};
    cairo_t *cr = d->pg.cr;
    char n[32];
    snprintf(n, sizeof n, "page %d", d->page);
    lx__page_text(&d->pg, &f, LX__DOC_RIGHT, LX__DOC_H - 30, 1, 0, LX__TEXT_NOTE, NAN, n);
    if (!d->header[0]) return;
    lx__page_text(&d->pg, &f, LX__DOC_LEFT, 28, 0, 0, LX__TEXT_NOTE, NAN, d->header);
    lx__rgb(cr, RULE, 1);
    cairo_set_line_width(cr, 0.5);
    cairo_move_to(cr, LX__DOC_LEFT, 40);
    cairo_line_to(cr, LX__DOC_RIGHT, 40);
    cairo_stroke(cr);
}

void lx__doc_new_page(lx__doc *d)
{
    furniture(d);
    cairo_show_page(d->pg.cr);
    lx__layout_free(&d->pg.lay); /* labels are placed per page */
    d->page++;
    d->y = LX__DOC_TOP;
}

int lx__doc_room(lx__doc *d, double h)
{
    if (d->y + h <= LX__DOC_BOTTOM) return 0;
    lx__doc_new_page(d);
    return 1;
}

lx_status lx__doc_close(lx__doc *d, lx_status st)
{
    if (d->pg.cr) {
        if (st == LX_OK) furniture(d);
        cairo_destroy(d->pg.cr);
        d->pg.cr = NULL;
    }
    if (d->pg.surface) {
        cairo_surface_finish(d->pg.surface); /* writes the rest of the file */
        cairo_status_t cs = cairo_surface_status(d->pg.surface);
        if (st == LX_OK && cs != CAIRO_STATUS_SUCCESS)
            st = d->w.err ? LX_EWRITE
                          : lx__error(d->ctx, cs == CAIRO_STATUS_NO_MEMORY ? LX_ENOMEM : LX_EWRITE, d->path, 0,
                                      "PDF: %s", cairo_status_to_string(cs));
        cairo_surface_destroy(d->pg.surface);
        d->pg.surface = NULL;
    }
    if (st == LX_OK && d->pg.oom) st = lx__error(d->ctx, LX_ENOMEM, d->path, 0, "out of memory while drawing");
    lx__layout_free(&d->pg.lay);
    if (d->open) st = lx__wfile_close(d->ctx, &d->w, st);
    d->open = 0;
    return st;
}

/* ---- text ---- */

static lx__font font(double size, int bold, const unsigned char rgb[3])
{
    lx__font f = {size, bold, {rgb[0], rgb[1], rgb[2]}, 0};
    return f;
}

double lx__doc_text_width(lx__doc *d, double size, int bold, const char *s)
{
    lx__font f = font(size, bold, INK);
    lx__box b = lx__text_box(&d->pg, &f, 0, 0, 0, 0, s);
    return b.x1 - b.x0;
}

void lx__doc_heading(lx__doc *d, int level, const char *s)
{
    double size = level == 1 ? 15 : level == 2 ? 11.5 : 10;
    lx__doc_room(d, size * 3.2);
    d->y += level == 1 ? 4 : 8;
    lx__font f = font(size, 1, INK);
    lx__page_text(&d->pg, &f, LX__DOC_LEFT, d->y, 0, 0, LX__TEXT_TITLE, NAN, s);
    d->y += size * 1.5;
    if (level == 1) {
        cairo_t *cr = d->pg.cr;
        lx__rgb(cr, INK, 1);
        cairo_set_line_width(cr, 0.8);
        cairo_move_to(cr, LX__DOC_LEFT, d->y - 4);
        cairo_line_to(cr, LX__DOC_RIGHT, d->y - 4);
        cairo_stroke(cr);
        d->y += 4;
    }
}

void lx__doc_para_at(lx__doc *d, double x, double width, double size, int bold, int grey, const char *s)
{
    lx__font f = font(size, bold, grey ? GREY : INK);
    double line = size * 1.35;
    const char *p = s;
    char buf[600];
    while (*p) {
        /* the longest run of words that fits the width (a word longer than the line is cut) */
        size_t best = 0, n = 0;
        while (p[n] && p[n] != '\n') {
            size_t m = n;
            while (p[m] == ' ') m++;
            while (p[m] && p[m] != ' ' && p[m] != '\n') m++;
            if (m >= sizeof buf) break;
            memcpy(buf, p, m);
            buf[m] = '\0';
            lx__box b = lx__text_box(&d->pg, &f, 0, 0, 0, 0, buf);
            if (b.x1 - b.x0 > width && best) break;
            best = m;
            n = m;
        }
        if (!best) best = n ? n : strlen(p) < sizeof buf - 1 ? strlen(p) : sizeof buf - 1;
        memcpy(buf, p, best);
        buf[best] = '\0';
        lx__doc_room(d, line);
        lx__page_text(&d->pg, &f, x, d->y, 0, 0, LX__TEXT_NOTE, NAN, buf);
        d->y += line;
        p += best;
        while (*p == ' ') p++;
        if (*p == '\n') p++;
    }
}

void lx__doc_para(lx__doc *d, const char *s)
{
    lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 9, 0, 0, s);
    d->y += 3;
}

void lx__doc_note(lx__doc *d, const char *s)
{
    lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 7.5, 0, 1, s);
    d->y += 2;
}

/* ---- tables ---- */

static void table_header(lx__doc *d, const lx__doc_tab *t, const double *x)
{
    lx__font f = font(t->size, 1, INK);
    for (int c = 0; c < t->ncols; c++) {
        double ax = t->align[c] == 'r' ? 1 : 0;
        lx__page_text(&d->pg, &f, t->align[c] == 'r' ? x[c + 1] - 4 : x[c], d->y, ax, 0, LX__TEXT_LABEL, NAN, t->head[c]);
    }
    d->y += t->size * 1.45;
    cairo_t *cr = d->pg.cr;
    lx__rgb(cr, INK, 1);
    cairo_set_line_width(cr, 0.6);
    cairo_move_to(cr, x[0], d->y - 2.5);
    cairo_line_to(cr, x[t->ncols], d->y - 2.5);
    cairo_stroke(cr);
}

/* Cuts s into lines of at most width (at spaces, commas and slashes where it can, else anywhere) into
 * lines[][96]; returns their count (at most max). */
static int wrap(lx__doc *d, const lx__font *f, const char *s, double width, char lines[][96], int max)
{
    int n = 0;
    const char *p = s;
    while (*p && n < max) {
        size_t len = strlen(p), best = 0, fit = 0;
        char buf[96];
        for (size_t m = 1; m <= len && m < sizeof buf; m++) {
            if (((unsigned char)p[m] & 0xc0) == 0x80) continue; /* whole UTF-8 characters */
            memcpy(buf, p, m);
            buf[m] = '\0';
            lx__box b = lx__text_box(&d->pg, f, 0, 0, 0, 0, buf);
            if (b.x1 - b.x0 > width) break;
            fit = m;
            if (m == len || p[m] == ' ' || p[m - 1] == ',' || p[m - 1] == '/' || p[m - 1] == ';') best = m;
        }
        if (!fit) fit = 1;
        size_t cut = fit == len || fit >= sizeof buf - 1 ? fit : best ? best : fit;
        snprintf(lines[n++], 96, "%.*s", (int)cut, p);
        p += cut;
        while (*p == ' ') p++;
    }
    return n ? n : (lines[0][0] = '\0', 1);
}

void lx__doc_table(lx__doc *d, const lx__doc_tab *t)
{
    double x[LX__DOC_MAXCOL + 1], total = 0;
    for (int c = 0; c < t->ncols; c++) total += t->width[c];
    x[0] = LX__DOC_LEFT;
    for (int c = 0; c < t->ncols; c++) x[c + 1] = x[c] + t->width[c] * (LX__DOC_RIGHT - LX__DOC_LEFT) / total;
    double row = t->size * 1.4;
    lx__doc_room(d, 3 * row);
    table_header(d, t, x);
    for (size_t r = 0; r < t->nrows; r++) {
        /* every cell wrapped to its column: the row is as tall as its longest cell */
        char lines[LX__DOC_MAXCOL][6][96];
        int nl[LX__DOC_MAXCOL], tall = 1;
        int bad = t->flag && t->flag(t->arg, r, 0);
        lx__font f = font(t->size, bad, bad ? (const unsigned char[3]){190, 20, 20} : INK);
        for (int c = 0; c < t->ncols; c++) {
            nl[c] = wrap(d, &f, t->cell(t->arg, r, c), x[c + 1] - x[c] - 6, lines[c], 6);
            tall = nl[c] > tall ? nl[c] : tall;
        }
        double h = row + (tall - 1) * t->size * 1.2;
        if (lx__doc_room(d, h)) table_header(d, t, x);
        for (int c = 0; c < t->ncols; c++)
            for (int k = 0; k < nl[c]; k++) {
                double y = d->y + k * t->size * 1.2;
                if (t->align[c] == 'r') lx__page_text(&d->pg, &f, x[c + 1] - 4, y, 1, 0, LX__TEXT_LABEL, NAN, lines[c][k]);
                else lx__page_text(&d->pg, &f, x[c], y, 0, 0, LX__TEXT_LABEL, NAN, lines[c][k]);
            }
        d->y += h;
        if (r + 1 < t->nrows && t->rule_after && t->rule_after(t->arg, r)) {
            cairo_t *cr = d->pg.cr;
            lx__rgb(cr, RULE, 1);
            cairo_set_line_width(cr, 0.4);
            cairo_move_to(cr, x[0], d->y - 3);
            cairo_line_to(cr, x[t->ncols], d->y - 3);
            cairo_stroke(cr);
        }
    }
    d->y += 6;
}

/* ---- drawings ---- */

void lx__doc_drawing(lx__doc *d, lx__page *pic, double max_w, double max_h)
{
    double s = fmin(max_w / pic->w, max_h / pic->h);
    double w = pic->w * s, h = pic->h * s;
    lx__doc_room(d, h + 6);
    cairo_t *cr = d->pg.cr;
    cairo_save(cr);
    cairo_translate(cr, LX__DOC_LEFT + 0.5 * (LX__DOC_RIGHT - LX__DOC_LEFT - w), d->y);
    cairo_scale(cr, s, s);
    cairo_rectangle(cr, 0, 0, pic->w, pic->h);
    cairo_clip(cr);
    cairo_set_source_surface(cr, pic->surface, 0, 0);
    cairo_paint(cr);
    cairo_restore(cr);
    d->y += h + 6;
}
