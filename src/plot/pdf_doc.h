/* pdf_doc.h - the PDF document of the design report (pdf_doc.c): A4 pages in points, a cursor that
 * moves down the page, text, tables and drawings that start a new page when they do not fit. */
#ifndef LX_PLOT_PDF_DOC_H
#define LX_PLOT_PDF_DOC_H

#include "plot/plot_private.h"

#define LX__DOC_W 595.28   /* A4 in points */
#define LX__DOC_H 841.89
#define LX__DOC_LEFT 56.0
#define LX__DOC_RIGHT (LX__DOC_W - 56.0)
#define LX__DOC_TOP 60.0
#define LX__DOC_BOTTOM (LX__DOC_H - 52.0)
#define LX__DOC_MAXCOL 16

typedef struct lx__doc {
    lx_ctx *ctx;
    const char *path;
    lx__wfile w;
    int open;
    lx__page pg;        /* the PDF surface and its drawing (labels recorded per page) */
    int page;           /* the current page, from 1 */
    double y;           /* the cursor: the top of the next line */
    char header[160];   /* the running header (from the second page) */
} lx__doc;

/* Opens path (atomically: a temporary file renamed into place by lx__doc_close on success) with the
 * PDF's title and author (may be NULL). */
lx_status lx__doc_open(lx_ctx *ctx, lx__doc *d, const char *path, const char *title, const char *author);
/* Ends the current page (its header and number) and starts the next. */
void lx__doc_new_page(lx__doc *d);
/* Starts a new page when h points do not fit below the cursor; returns 1 when it did. */
int lx__doc_room(lx__doc *d, double h);
/* Finishes the document: with st == LX_OK writes and renames it into place, otherwise removes it;
 * returns the first error. */
lx_status lx__doc_close(lx__doc *d, lx_status st);

/* Text: a heading (level 1, 2, 3), a paragraph of running text, a small grey note, text at x wrapped
 * to width; the width a string takes. */
void lx__doc_heading(lx__doc *d, int level, const char *s);
void lx__doc_para(lx__doc *d, const char *s);
void lx__doc_note(lx__doc *d, const char *s);
void lx__doc_para_at(lx__doc *d, double x, double width, double size, int bold, int grey, const char *s);
double lx__doc_text_width(lx__doc *d, double size, int bold, const char *s);

/* A table: ncols columns of relative widths, 'l' or 'r' aligned, cells from a callback; rows a
 * flag marks (a failed check) are red and bold; a rule after rows rule_after marks. */
typedef struct lx__doc_tab {
    int ncols;
    const char *head[LX__DOC_MAXCOL];
    double width[LX__DOC_MAXCOL];
    char align[LX__DOC_MAXCOL];
    double size;
    size_t nrows;
    const char *(*cell)(void *arg, size_t row, int col);
    int (*flag)(void *arg, size_t row, int col);
    int (*rule_after)(void *arg, size_t row);
    void *arg;
} lx__doc_tab;
void lx__doc_table(lx__doc *d, const lx__doc_tab *t);

/* A drawing recorded on a vector page, scaled to fit max_w x max_h and centred. */
void lx__doc_drawing(lx__doc *d, lx__page *pic, double max_w, double max_h);

#endif /* LX_PLOT_PDF_DOC_H */
