/* plot_private.h - the plotting layer's internals (never installed): a cairo page whose every
 * label is recorded (so that labels are placed where they collide with nothing, and tests can
 * check what a plot shows), round ticks and colour scales, false colour and its legend, contour
 * lines, tone mapping, the atomic PNG writer, and the colour helpers of the spectrum report.
 * The top library layer: it may draw what any lower layer computes. */
#ifndef LX_PLOT_PRIVATE_H
#define LX_PLOT_PRIVATE_H

#include "tables/tables_private.h"

#include <cairo.h>
#include <cairo-pdf.h>

/* ---- cairo, loaded on the first plot (cairo_load.c) ----
 * luxcalc links no cairo: libcairo.so.2 and the 20-odd libraries it needs (fontconfig, freetype,
 * pixman, X11...) cost 1.3-1.6 ms at every process start, which a command that plots nothing (a
 * one-off `luxcalc spd`) should not pay. lx__cairo_load opens it once per process (thread-safe)
 * and fills the table below; every cairo_* call of this layer goes through it (the macros). Each
 * drawing starts with lx__page_init, which loads it, so no call precedes the load. */
#define LX__CAIRO_FNS(F) F(arc) F(arc_negative) F(clip) F(close_path) F(create) F(destroy) F(fill) \
    F(fill_preserve) F(font_extents) F(get_source) F(image_surface_create) F(image_surface_get_data) \
    F(image_surface_get_stride) F(line_to) F(move_to) F(new_path) F(paint) F(pattern_set_filter) \
    F(rectangle) F(restore) F(rotate) F(save) F(scale) F(select_font_face) F(set_font_size) F(set_line_cap) \
    F(set_dash) F(set_line_join) F(set_line_width) F(set_source_rgb) F(set_source_rgba) F(set_source_surface) \
    F(show_text) F(status) F(status_to_string) F(stroke) F(stroke_preserve) F(surface_destroy) F(surface_flush) \
    F(surface_mark_dirty) F(surface_status) F(surface_write_to_png_stream) F(text_extents) F(text_path) \
    F(translate) F(pdf_surface_create_for_stream) F(pdf_surface_set_metadata) F(recording_surface_create) \
    F(show_page) F(surface_finish) F(rel_line_to)
typedef struct lx__cairo_api {
#define LX__CAIRO_FIELD(n) __typeof__(cairo_##n) *n;
    LX__CAIRO_FNS(LX__CAIRO_FIELD)
#undef LX__CAIRO_FIELD
} lx__cairo_api;
extern lx__cairo_api lx__cairo;
/* Loads cairo (once per process); LX_EUNSUPPORTED naming what failed when it cannot. */
lx_status lx__cairo_load(lx_ctx *ctx);
#define cairo_arc (lx__cairo.arc)
#define cairo_arc_negative (lx__cairo.arc_negative)
#define cairo_clip (lx__cairo.clip)
#define cairo_close_path (lx__cairo.close_path)
#define cairo_create (lx__cairo.create)
#define cairo_destroy (lx__cairo.destroy)
#define cairo_fill (lx__cairo.fill)
#define cairo_fill_preserve (lx__cairo.fill_preserve)
#define cairo_font_extents (lx__cairo.font_extents)
#define cairo_get_source (lx__cairo.get_source)
#define cairo_image_surface_create (lx__cairo.image_surface_create)
#define cairo_image_surface_get_data (lx__cairo.image_surface_get_data)
#define cairo_image_surface_get_stride (lx__cairo.image_surface_get_stride)
#define cairo_line_to (lx__cairo.line_to)
#define cairo_move_to (lx__cairo.move_to)
#define cairo_new_path (lx__cairo.new_path)
#define cairo_paint (lx__cairo.paint)
#define cairo_pattern_set_filter (lx__cairo.pattern_set_filter)
#define cairo_rectangle (lx__cairo.rectangle)
#define cairo_restore (lx__cairo.restore)
#define cairo_rotate (lx__cairo.rotate)
#define cairo_save (lx__cairo.save)
#define cairo_scale (lx__cairo.scale)
#define cairo_select_font_face (lx__cairo.select_font_face)
#define cairo_set_font_size (lx__cairo.set_font_size)
#define cairo_set_line_cap (lx__cairo.set_line_cap)
#define cairo_set_dash (lx__cairo.set_dash)
#define cairo_set_line_join (lx__cairo.set_line_join)
#define cairo_set_line_width (lx__cairo.set_line_width)
#define cairo_set_source_rgb (lx__cairo.set_source_rgb)
#define cairo_set_source_rgba (lx__cairo.set_source_rgba)
#define cairo_set_source_surface (lx__cairo.set_source_surface)
#define cairo_show_text (lx__cairo.show_text)
#define cairo_status (lx__cairo.status)
#define cairo_status_to_string (lx__cairo.status_to_string)
#define cairo_stroke (lx__cairo.stroke)
#define cairo_stroke_preserve (lx__cairo.stroke_preserve)
#define cairo_surface_destroy (lx__cairo.surface_destroy)
#define cairo_surface_flush (lx__cairo.surface_flush)
#define cairo_surface_mark_dirty (lx__cairo.surface_mark_dirty)
#define cairo_surface_status (lx__cairo.surface_status)
#define cairo_surface_write_to_png_stream (lx__cairo.surface_write_to_png_stream)
#define cairo_text_extents (lx__cairo.text_extents)
#define cairo_text_path (lx__cairo.text_path)
#define cairo_translate (lx__cairo.translate)
#define cairo_pdf_surface_create_for_stream (lx__cairo.pdf_surface_create_for_stream)
#define cairo_pdf_surface_set_metadata (lx__cairo.pdf_surface_set_metadata)
#define cairo_recording_surface_create (lx__cairo.recording_surface_create)
#define cairo_show_page (lx__cairo.show_page)
#define cairo_surface_finish (lx__cairo.surface_finish)
#define cairo_rel_line_to (lx__cairo.rel_line_to)

/* ---- what a plot drew (page.c) ---- */

/* Kinds of label, for placement rules and for tests. */
typedef enum lx__role {
    LX__TEXT_TITLE = 0, /* the heading and sub-heading */
    LX__TEXT_AXIS,      /* an axis title */
    LX__TEXT_TICK,      /* an axis tick value */
    LX__TEXT_LEGEND,    /* a legend tick value or the legend's title (its unit) */
    LX__TEXT_CONTOUR,   /* a contour value, on its line */
    LX__TEXT_STATS,     /* a statistics or headline-number entry */
    LX__TEXT_LABEL,     /* a label beside a marker or curve (an accuracy point, an isotherm, a bar) */
    LX__TEXT_NOTE       /* anything else (captions, reasons) */
} lx__role;

typedef struct lx__box {
    double x0, y0, x1, y1; /* pixels, x0 <= x1, y0 <= y1, y down */
} lx__box;

typedef struct lx__label {
    lx__box box;     /* the text's logical box (advance x font ascent + descent) */
    int role;        /* lx__role */
    double value;    /* the number it shows, or NaN */
    char text[96];
} lx__label;

#define LX__MAX_LEVELS 24

/* The record of a page: its labels, the boxes labels must avoid (markers, bars, lines' ends), the
 * data area with its mapping, the colour scale, contour levels and luminaire marks. */
typedef struct lx__layout {
    lx__label *label;
    size_t n_label, cap_label;
    lx__box *keep;
    size_t n_keep, cap_keep;
    lx__box area;                  /* the data area in pixels (0 size: none) */
    double ax0, ax1, ay0, ay1;     /* data coordinates at area.x0, area.x1, area.y1 (bottom), area.y0 */
    int ax_log, ay_log;            /* log10 axes */
    lx__box legend_bar;            /* the colour bar (0 size: none) */
    double scale_lo, scale_hi;     /* its scale: value at the bottom and the top */
    int scale_log;
    int n_levels;                  /* contour levels drawn, and the segments of each */
    double level[LX__MAX_LEVELS];
    size_t level_segments[LX__MAX_LEVELS];
    int n_marks;                   /* luminaire marks drawn (pixel centres) */
    double mark[64][2];
    size_t outlines[5];            /* outlines drawn, per lx_outline_kind */
    size_t above;                  /* values above the colour range (a map's small bright source) */
    int n_iso;                     /* isotherms drawn on a chromaticity diagram: T, then the end away from */
    double iso[8][5];              /* the label and the labelled end, pixels (x0, y0, x1, y1) */
    int n_arrows;                  /* arrows of a TM-30 vector graphic: from (x0, y0) to the tip (x1, y1), */
    double arrow[16][5];           /* and the hue bin (0..15) */
} lx__layout;

/* Frees what a layout holds and zeroes it. */
void lx__layout_free(lx__layout *lay);

/* ---- the page (page.c) ---- */

typedef struct lx__page {
    int w, h;
    cairo_surface_t *surface; /* RGB24 image */
    cairo_t *cr;
    lx__layout lay;
    int oom;                  /* a label could not be recorded */
} lx__page;

/* A font for lx__page_text: size in pixels, bold, colour (sRGB 0..255), and a white halo (text
 * over a map). */
typedef struct lx__font {
    double size;
    int bold;
    unsigned char rgb[3];
    int halo;
} lx__font;

/* Creates a w x h page filled with bg. LX_EINVAL for a size out of 1..16384, LX_ENOMEM. */
lx_status lx__page_init(lx_ctx *ctx, lx__page *pg, int w, int h, const unsigned char bg[3]);
/* The same page as a recording of the drawing (cairo's recording surface), to be painted as vectors
 * into another drawing (the PDF report); lx__page_write_png does not apply to it. */
lx_status lx__page_init_vector(lx_ctx *ctx, lx__page *pg, int w, int h, const unsigned char bg[3]);
/* Frees the page (its layout too unless it was moved out with lx__page_take_layout). */
void lx__page_free(lx__page *pg);
/* Moves the page's layout into *out (the caller frees it with lx__layout_free). */
void lx__page_take_layout(lx__page *pg, lx__layout *out);
/* Writes the page as an 8-bit RGB PNG through cairo, atomically (lx__wfile). */
lx_status lx__page_write_png(lx_ctx *ctx, lx__page *pg, const char *path);

/* The box text s would take at (x, y), anchored at fraction (ax, ay) of the box (0, 0: top left;
 * 0.5, 0.5: centre; 0, 1: bottom left at the descent). */
lx__box lx__text_box(lx__page *pg, const lx__font *f, double x, double y, double ax, double ay, const char *s);
/* Draws s there and records it (role, value); returns its box. */
lx__box lx__page_text(lx__page *pg, const lx__font *f, double x, double y, double ax, double ay, int role,
                      double value, const char *s);
/* Text from (x, y) (top left) in at most maxw pixels: the font shrunk down to 70 % when it must be,
 * then the text cut with an ellipsis. */
lx__box lx__page_text_fit(lx__page *pg, const lx__font *f, double x, double y, int role, const char *s, double maxw);
/* The same, turned 90 degrees counter-clockwise (reading upwards), centred on (x, y). */
lx__box lx__page_text_up(lx__page *pg, const lx__font *f, double x, double y, int role, const char *s);
/* Records a box that labels placed later must not cover. */
void lx__page_keep(lx__page *pg, lx__box b);
/* 1 when b (grown by pad) lies inside within and overlaps no recorded label or kept box. */
int lx__page_free_at(const lx__page *pg, lx__box b, double pad, lx__box within);
/* 1 when boxes a and b overlap (touching is not overlapping). */
int lx__box_overlap(lx__box a, lx__box b);
/* Sets cairo's source colour from sRGB bytes, with alpha a (1: opaque). */
void lx__rgb(cairo_t *cr, const unsigned char rgb[3], double a);

/* ---- numbers and ticks (scale.c) ---- */

/* A round step (1, 2 or 5 x 10^k) giving about n intervals over span (> 0). */
double lx__nice_step(double span, int n);
/* Round ticks k x step in [lo, hi] with step = lx__nice_step(hi - lo, n): up to max values into
 * out; returns the count and the step in *step. */
int lx__ticks_linear(double lo, double hi, int n, double *out, int max, double *step);
/* Powers of ten in [lo, hi] (lo > 0), every k-th decade so that at most max are given; returns
 * the count. */
int lx__ticks_log(double lo, double hi, double *out, int max);
/* Contour levels from a 1-2-5 series for values in [lo, hi]: where hi / lo is large (more than
 * 20, or lo <= 0) the series 1, 2, 5, 10, 20, 50 ... itself over the top three decades
 * (*geometric = 1; decades instead where that gives more than 10), else multiples of a 1-2-5
 * step giving 4 to 9 levels. Only levels strictly inside (lo, hi); at most max; returns the count. */
int lx__levels_125(double lo, double hi, double *out, int max, int *geometric);
/* A tick value printed with the decimals its step needs ("0.25", "100", "-1.5"). */
void lx__fmt_tick(char *buf, size_t cap, double v, double step);
/* A power of ten as text: "0.01" .. "1000", else "10⁻³" / "10⁴" (UTF-8 superscripts). */
void lx__fmt_decade(char *buf, size_t cap, double v);
/* A value rounded to sig significant digits, printed without an exponent where it has at most
 * 7 integer digits and no more than 6 leading zeros ("312.4", "0.004512", "12350"). */
void lx__fmt_sig(char *buf, size_t cap, double v, int sig);

/* ---- colour scales, false colour and its legend (falsecolor.c) ---- */

typedef struct lx__scale {
    double lo, hi; /* values at the bottom and the top of the colour ramp (lo > 0 on a log scale) */
    int log;
} lx__scale;

/* Position in [0, 1] of v on the scale (values below lo give 0, above hi give 1; NaN gives 0). */
double lx__scale_t(const lx__scale *s, double v);
/* A useful scale for n values (NaN skipped): log: from the decade at or below the 1st percentile
 * of the positive values (at most 6 decades below the top) to the decade at or above the largest,
 * at least two decades; linear: 0 (or the round value below a minimum under -5 % of the maximum)
 * to the round value at or above the maximum. lo or hi not NaN are kept as given. */
void lx__scale_auto(lx__scale *s, const double *v, size_t n, int log, double lo, double hi);
/* lx__scale_auto for a map, where a small bright source (the sun disc) would take the range from
 * everything else: with hi not given, values more than 100 times the 99.9th percentile of the
 * positive ones (at least 1000 of them) are left out of the range, which then ends at the decade
 * (log) or round value (linear) above the rest. Returns how many values lie above the range
 * (drawn in its top colour) and their largest in *above_max (NaN when none). */
size_t lx__scale_auto_map(lx__scale *s, const double *v, size_t n, int log, double lo, double hi, double *above_max);
/* The false-colour palette at t in [0, 1] (dark violet, blue, cyan, green, yellow, orange, red:
 * the look of Radiance falsecolor). */
void lx__falsecolor(double t, unsigned char rgb[3]);
/* Paints a vw x vh value array (row 0 at the top, NaN grey) into box through the scale, each
 * value a block (nearest neighbour). */
lx_status lx__page_map(lx_ctx *ctx, lx__page *pg, lx__box box, const double *v, int vw, int vh, const lx__scale *s);
/* A vertical colour bar with the scale's ticks (decades on a log scale, round values on a linear
 * one) and the title (the quantity and its unit) above it, in box (labels included). Records the
 * bar and the scale in the layout. */
void lx__page_legend(lx__page *pg, lx__box box, const lx__scale *s, const char *title);

/* ---- contour lines (contour.c) ---- */

/* Contour lines of level on a vw x vh node grid (row 0 at the top): marching squares with linear
 * interpolation on the cell edges (saddles split by the cell's mean). fn(arg, x0, y0, x1, y1)
 * receives each segment in node coordinates. Returns the number of segments. */
size_t lx__contour(const double *v, int vw, int vh, double level,
                   void (*fn)(void *arg, double x0, double y0, double x1, double y1), void *arg);

/* ---- tone mapping (tonemap.c) ---- */

/* Tone-mapped preview of linear values (1 or 3 channels, vw x vh, row 0 at the top) into box:
 * scaled so that the median luminance maps to 0.18, Reinhard x/(1+x), sRGB encoded. */
lx_status lx__page_tonemap(lx_ctx *ctx, lx__page *pg, lx__box box, const float *v, int channels, int vw, int vh);
/* sRGB encoding of a linear value clamped to [0, 1]. */
double lx__srgb_encode(double v);

/* ---- outlines on a plan or a section (plan.c) ---- */

/* Where a plan goes on the page: the box (pixels, or points on a PDF page) and the plane
 * coordinates in metres at its left, right, bottom and top edges; unit scales every line width
 * (1: the PNG plots' pixels). */
typedef struct lx__plan_view {
    lx__box box;
    double a0, a1, b0, b1;
    double unit;
} lx__plan_view;
/* Draws the outlines into the view, clipped to its box, each kind in its style (under to over:
 * obstructions, luminous areas, surfaces, walls, openings); counts what it drew per kind into
 * count[5] when count is not NULL. Every plan of every plot and report is drawn here. */
void lx__plan_draw(cairo_t *cr, const lx__plan_view *v, const lx_plot_outline *o, size_t n, size_t *count);
/* The extent of the outlines' finite vertices: a0, a1, b0, b1 in ext; 0 when there is none. */
int lx__outlines_extent(const lx_plot_outline *o, size_t n, double ext[4]);
/* The colour a kind is drawn in (an opening: its light band), for tests and legends. */
const unsigned char *lx__outline_rgb(lx_outline_kind kind);

/* ---- the plots, with their layout for tests (each public writer is one of these with NULL) ---- */

/* The isolux plot drawn on a new page (an image, or with vector = 1 a recording to paint into another
 * drawing), into *pg (the caller frees it with lx__page_free); its width and height are pg->w, pg->h. */
lx_status lx__isolux_page(lx_ctx *ctx, const lx_plane *plane, const double *E, const lx_isolux_opts *opts, int vector,
                          lx__page *pg);
lx_status lx__isolux_png(lx_ctx *ctx, const char *path, const lx_plane *plane, const double *E,
                         const lx_isolux_opts *opts, lx__layout *out);
lx_status lx__scene_receiver_png(lx_ctx *ctx, const char *path, const lx_scene *scene, const lx_scene_result *res,
                                 size_t receiver, const lx_receiver_png_opts *opts, lx__layout *out);
lx_status lx__falsecolor_png(lx_ctx *ctx, const char *path, int w, int h, const double *values,
                             const lx_falsecolor_opts *opts, lx__layout *out);
lx_status lx__irradiance_png(lx_ctx *ctx, const char *path, const lx_envmap *radiance, const lx_envmap *irradiance,
                             const char *label, lx_plot_scale scale, lx__layout *out);
lx_status lx__report_png(lx_ctx *ctx, const lx_spd *spd, const lx_report_opts *opts, const char *path,
                         lx__layout *out);
lx_status lx__tm30_png(lx_ctx *ctx, const lx_spd *spd, const lx_report_opts *opts, const char *path, lx__layout *out);
lx_status lx__error_time_png(lx_ctx *ctx, const char *path, const char *title, const char *x_title,
                             const char *y_title, size_t n, const lx_plot_point *pts, int n_series,
                             const char *const *series_names, lx__layout *out);

/* ---- colour helpers of the spectrum report (report_colour.c) ---- */
/* sRGB of XYZ, negative channels desaturated away and normalised to a maximum of 1, encoded. */
void lx__xyz_to_srgb8(const double xyz[3], unsigned char rgb[3]);
/* Chromaticity of the spectral locus at lambda_nm (CMFs of obs, interpolated). */
lx_status lx__locus_xy(lx_ctx *ctx, lx_observer obs, double lambda_nm, double *x, double *y);
/* Approximate sRGB of monochromatic light (2 deg CMFs; dimmed at the ends; grey outside them). */
void lx__wavelength_srgb8(lx_ctx *ctx, double lambda_nm, unsigned char rgb[3]);
/* xy of the point at distance duv (CIE 1960 uv) from the Planckian locus at T_K along its normal,
 * + towards +v ("above", the sign of Duv): the isotemperature line. */
lx_status lx__isotemp_xy(lx_ctx *ctx, lx_observer obs, double T_K, double duv, double *x, double *y);
/* TM-30 colour vector graphic: a hue bin's test point normalised so the reference lies on the
 * unit circle at its own hue: (test - ref) / |ref| + (cos h_ref, sin h_ref). */
void lx__cvg_point(const double ref_ab[2], const double test_ab[2], double out[2]);
/* The colour of CIE 13.3 test colour sample k (0-based, 0..13; 14: JIS Z 8726 No. 15) under D65 (2 deg, sRGB). */
void lx__tcs_srgb8(lx_ctx *ctx, int k, unsigned char rgb[3]);
/* The colour under D65 of the reflectance in column col (1-based) of table t (the first column the
 * wavelength), 2 deg, sRGB; grey when t is NULL. */
void lx__refl_srgb8(lx_ctx *ctx, const lx__table *t, int col, unsigned char rgb[3]);

#endif /* LX_PLOT_PRIVATE_H */
