/* report.h - the spectrum report's shared state (report_png.c draws the page, the SPD, the bars and
 * the numbers; report_diagram.c the chromaticity diagram and the TM-30 colour vector graphic). */
#ifndef LX_PLOT_REPORT_H
#define LX_PLOT_REPORT_H

#include "plot/plot_private.h"

typedef struct lx__report {
    lx_observer obs;
    lx_diagram diagram;
    lx_colorimetry col;
    int cri_ok, tm30_ok, ao_ok;
    lx_cri cri;
    lx_tm30 tm;
    lx_alphaopic ao;
    char cri_why[256], tm30_why[256];
    const char *y_name, *y_unit; /* "luminous flux", "lm" ... ("Y", "" for relative values) */
    const char *r_name, *r_unit; /* "radiant flux", "W" ... */
    const char *spd_unit;        /* the values' unit on the SPD axis ("W/nm"; "relative") */
} lx__report;

/* The chromaticity diagram (xy or u'v') in box, with the loci, labelled isotherms and the point. */
lx_status lx__report_diagram(lx_ctx *ctx, lx__page *pg, const lx__report *r, lx__box box);
/* The TM-30 colour vector graphic centred at (cx, cy) with reference radius R (or the reason it is
 * undefined), its title above. */
void lx__report_cvg(lx__page *pg, const lx__report *r, double cx, double cy, double R);

/* The TM-30 colour vector graphic of tm centred at (cx, cy), reference radius R: the 16 bins'
 * wedges numbered, the +-10 % and +-20 % circles, the reference circle, the test's shape and the
 * arrows from reference to test with their heads in the bins' colours (full: the report page's
 * size, with the +-20 % marks); records each arrow in the layout. 0 when a bin has no sample
 * (the background is drawn, no shape). (report_tm30.c) */
int lx__tm30_cvg(lx__page *pg, const lx_tm30 *tm, double cx, double cy, double R, int full);
/* The colour of hue bin `bin` (0..15) in the IES calculator: its bars (arrow 0) or arrows (1). */
void lx__tm30_bin_rgb(int bin, int arrow, unsigned char rgb[3]);

#endif /* LX_PLOT_REPORT_H */
