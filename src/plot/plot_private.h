/* plot_private.h - the plotting layer's internals (never installed): an RGB8 canvas with a font,
 * false colour and legends, tone mapping, an atomic PNG writer, and the colour helpers of the
 * spectrum report. The top library layer: it may draw what any lower layer computes. */
#ifndef LX_PLOT_PRIVATE_H
#define LX_PLOT_PRIVATE_H

#include "tables/tables_private.h"

/* An RGB8 canvas, a 5x7 font of our own (digits, + - . e E / ( ) : = % and upper-case letters;
 * lower case is drawn upper case), a false-colour scale with a legend, a tone-mapped HDR preview,
 * and an atomic PNG writer (png_plot.c). */
typedef struct lx__canvas {
    int w, h;
    unsigned char *rgb; /* w * h * 3 */
} lx__canvas;
lx_status lx__canvas_init(lx_ctx *ctx, lx__canvas *c, int w, int h, const unsigned char bg[3]);
void lx__canvas_free(lx__canvas *c);
void lx__canvas_fill(lx__canvas *c, int x, int y, int w, int h, const unsigned char rgb[3]);
/* Text at (x, y) (top-left), each font pixel drawn scale x scale; width in pixels of a string. */
void lx__canvas_text(lx__canvas *c, int x, int y, int scale, const char *s, const unsigned char rgb[3]);
int lx__text_width(const char *s, int scale);
/* The false-colour palette (dark blue - cyan - green - yellow - red, the Radiance falsecolor
 * look) at t in [0, 1]; the value mapping t = (v - vmin)/(vmax - vmin), or on log10 when log_scale. */
void lx__falsecolor(double t, unsigned char rgb[3]);
double lx__falsecolor_t(double v, double vmin, double vmax, int log_scale);
/* Draws a vw x vh array of values (row-major, NaN drawn grey) scaled to the w x h rectangle. */
void lx__canvas_values(lx__canvas *c, int x, int y, int w, int h, const double *v, int vw, int vh, double vmin,
                       double vmax, int log_scale);
/* A vertical colour bar with labelled ticks and a title, in the rectangle (labels included). */
void lx__canvas_legend(lx__canvas *c, int x, int y, int w, int h, double vmin, double vmax, int log_scale,
                       const char *title);
/* Tone-mapped preview of linear values (1 or 3 channels, vw x vh) into a w x h rectangle:
 * scaled so that the median luminance maps to 0.18, Reinhard x/(1+x), sRGB encoded. */
void lx__canvas_tonemap(lx__canvas *c, int x, int y, int w, int h, const float *v, int channels, int vw, int vh);
/* Writes the canvas as an 8-bit RGB PNG atomically (temporary file + rename). */
lx_status lx__canvas_write_png(lx_ctx *ctx, const lx__canvas *c, const char *path);
/* The whole false-colour plot in one call: the w x h values drawn (enlarged to at least 512 px
 * wide), a legend with title on the right. vmin/vmax NaN: the values' range (positive for log). */
lx_status lx__png_falsecolor(lx_ctx *ctx, const char *path, int w, int h, const double *values, double vmin,
                             double vmax, int log_scale, const char *legend_title);

/* ---- colour helpers of the spectrum report (report_png.c) ---- */
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

#endif /* LX_PLOT_PRIVATE_H */
