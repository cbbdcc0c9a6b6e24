/* report_pdf.h - the design report's shared state (report_pdf.c: the evaluation, the title page,
 * the luminaire schedule, the checks, energy and the method; report_pdf_plan.c: the room plans;
 * report_pdf_tables.c: the areas, the calculation surfaces, glare and emergency lighting). */
#ifndef LX_PLOT_REPORT_PDF_H
#define LX_PLOT_REPORT_PDF_H

#include "plot/pdf_doc.h"

typedef struct lx__rep {
    lx_ctx *ctx;
    const lx_scene *sc;
    lx__doc doc;
    lx_scene_plan *plan, *em_plan;
    lx_scene_result *res, *em;
    lx_scene_glare *glare;
    lx_scene_checks *checks;
    int has_energy;
    lx_leni_input ein;
    lx_leni energy;
    int imperial;
    const char *title, *project, *author;
} lx__rep;

/* A table of strings filled row by row (cells of at most 255 bytes), shown with lx__doc_table. */
typedef struct lx__strtab {
    int ncols;
    size_t nrows, cap;
    char (*cell)[LX__DOC_MAXCOL][256];
    unsigned char *bad;   /* per row: 1 draws it red (a failed check) */
    unsigned char *rule;  /* per row: a rule below it */
    int oom;
} lx__strtab;
/* Appends a row (ncols strings); returns its index. */
size_t lx__strtab_row(lx__strtab *t, const char *const *cells);
/* Shows it with the header, widths and alignment given, and frees it. */
void lx__strtab_show(lx__doc *d, lx__strtab *t, const char *const *head, const double *width, const char *align, double size);
/* v to sig significant digits with its unit ("312.4 lx"); "-" for NaN. */
void lx__rep_num(char *buf, size_t cap, double v, int sig, const char *unit);

/* The plan of each room (report_pdf_plan.c). */
lx_status lx__rep_plans(lx__rep *r);
/* The EN 12464-1 areas and each grid's isolux plot (report_pdf_tables.c). */
lx_status lx__rep_surfaces(lx__rep *r);
/* UGR at the observers and the CIE 190 tables of the luminaires (report_pdf_tables.c). */
lx_status lx__rep_glare(lx__rep *r);
/* Emergency lighting (report_pdf_tables.c). */
void lx__rep_emergency(lx__rep *r);

#endif /* LX_PLOT_REPORT_PDF_H */
