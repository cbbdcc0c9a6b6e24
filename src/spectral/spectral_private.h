/* spectral_private.h - the spectral layer's internals (never installed): the spectrum-set builder
 * and the reader state shared by the layout readers, the batch weight matrix, the vector CSV line
 * parser and the table-based CCT of the binning batch. */
#ifndef LX_SPECTRAL_PRIVATE_H
#define LX_SPECTRAL_PRIVATE_H

#include "tables/tables_private.h"

/* Builds a set from parsed data: nlam wavelengths lambda[k * lam_stride] (on lines lam_line[k],
 * or all on lam_line_all when lam_line is NULL), nspec spectra whose value at sample k is
 * val[s * ss + k * ks], names[s] (copied; NULL gives "1", "2", ...), lines[s]. Sorts samples by
 * wavelength, rejects duplicates, non-positive or non-finite wavelengths, fewer than 2 samples. */
lx_status lx__spd_set_build(lx_ctx *ctx, const char *file, size_t nlam, const double *lambda,
                            size_t lam_stride, const long *lam_line, long lam_line_all, size_t nspec,
                            const double *val, size_t ss, size_t ks, char *const *names,
                            const long *lines, lx_spd_set **out);

/* The integral of spd x w by method (lx_spd_integrate; w NULL: the radiant integral,
 * lx_spd_integrate_radiant) as the weights of its samples: the integral is sum_i out[i] value[i]
 * (equal to rounding; out: spd->n doubles). spd and w must be valid views. LX_EINVAL as
 * lx_spd_integrate for a method the spectrum does not allow. */
lx_status lx__integrate_weights(lx_ctx *ctx, const lx_spd *spd, const lx_spd *w, lx_method method, double *out);

/* The exact integral of the product of two piecewise-linear functions, each zero outside its
 * samples (integrate.c: the exact method). */
double lx__exact_product(const lx_spd *a, const lx_spd *b);

/* A spectrum whose largest |value| is below LX__SPD_TINY (2^-600), where products with weighting
 * functions and the quantities derived from them (ratios, squares, 100 / Y) leave the normal double
 * range: *scaled gets its values times 2^-e (exact; e the exponent of the largest, which becomes
 * 0.5 .. 1) in *buf (the caller frees it), and e is returned. Otherwise *scaled is spd, *buf NULL
 * and 0 is returned; INT_MIN when out of memory. Scale-invariant results (chromaticities, CRI,
 * TM-30, ratios) are computed on *scaled as they are; absolute ones scaled back by 2^e. */
#define LX__SPD_TINY 0x1p-600
int lx__spd_tiny_scale(const lx_spd *spd, lx_spd *scaled, double **buf);

/* The largest |value| of spd. */
double lx__spd_max_abs(const lx_spd *spd);

/* Adds b's spectra to a (both read from the same file; b is freed, also on failure). */
lx_status lx__spd_set_merge(lx_ctx *ctx, lx_spd_set *a, lx_spd_set *b);

/* ---- the readers of lx_spd_read_*: the state every layout shares (spd_read.c) ---- */
typedef struct lx__rd {
    lx_ctx *ctx;
    const char *file;
    lx_spd_read_opts opts;  /* as given (zero for defaults) */
    long line0;             /* lines before the text (opts.skip_lines): a reader's cursor starts there */
    const char *format;     /* the layout read (static; lx_spd_formats) */
    lx_spd_field *fields;   /* header fields found, moved into the set at the end */
    size_t nfields, fcap;
    lx_spd_skipped *skipped;
    size_t nskipped, scap;
    const char *unit;        /* the values' unit after scaling by unit_scale (NULL: not known) */
    double unit_scale;
    const char *unit_source; /* static text: what the unit was taken from */
    double wl_scale;         /* wavelength unit found in a header (nm per file unit; 0: none found) */
    const char *wl_source;   /* static text: where */
} lx__rd;

/* Keeps a header field (key and value trimmed of blanks and one pair of double quotes). Returns 0,
 * -1 when out of memory. */
int lx__rd_field(lx__rd *rd, long line, const char *ks, const char *ke, const char *vs, const char *ve);
/* A malformed data row: with opts.skip_bad_rows recorded in the skipped list and LX_OK returned (the
 * caller drops the row), else recorded on the context as LX_EPARSE FILE:LINE: what. */
lx_status lx__rd_bad_row(lx__rd *rd, long line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* The same for an error a field parser just recorded on the context (lx__parse_field's st). */
lx_status lx__rd_bad_field(lx__rd *rd, long line, lx_status st);
/* LX_ENOMEM naming the file. */
lx_status lx__rd_nomem(lx__rd *rd);
/* The wavelength unit a header cell names ("Wavelength [nm]", "wl_um", "lambda (µm)", "[A]",
 * "Å"): nm per unit (1, 1000, 0.1), 0 when it names none. */
double lx__wl_unit_word(const char *s, const char *e);
/* 1 when [s, e) starts with blanks then w (case-insensitive). */
int lx__starts_ci(const char *s, const char *e, const char *w);

/* Layout readers: detection by content (1 when the text is that layout) and the reader. The text
 * starts after opts.skip_lines lines (rd->line0); a reader's set gets no fields (rd keeps them). */
int lx__cgats_detect(const char *text, size_t len);
lx_status lx__cgats_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out);
int lx__oceanview_detect(const char *text, size_t len);
lx_status lx__oceanview_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out);
int lx__sekonic_detect(const char *text, size_t len);
lx_status lx__sekonic_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out);
int lx__uprtek_detect(const char *text, size_t len);
lx_status lx__uprtek_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out);
int lx__spectrawiz_detect(const char *text, size_t len);
lx_status lx__spectrawiz_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out);
int lx__tm27_detect(const char *text, size_t len);
lx_status lx__tm27_read(lx__rd *rd, const char *text, size_t len, lx_spd_set **out);
/* Delimited text (spd_text.c): the columns and rows layouts, Excel CSV, a preamble of header fields
 * above the header, AvaSoft exports. layout: 0 either, 1 columns only, 2 rows only. */
lx_status lx__text_read(lx__rd *rd, const char *text, size_t len, int layout, lx_spd_set **out);

/* PAR and hazards (photobio.c): their weighting functions, in the order of lx_par and lx_hazard, and
 * the fraction of w's integral inside [a, b]. */
extern const lx_function lx__par_fns[3];
extern const lx_function lx__hazard_fns[LX_HZ_COUNT];
double lx__coverage(const lx_spd *w, double a, double b);
/* 1 for the weighting functions of a band integral (PAR, ePAR, YPF of ANSI/ASABE S640): a step at
 * each end of the band, so they are integrated exactly (piecewise-linear spectrum times the weight)
 * whatever the method: a CIE 015 sum would count the samples at the band's ends a full step wide. */
int lx__fn_band_exact(lx_function fn);
/* One chromaticity binned with the embedded tables (binning.c); -1 when they are missing. */
int lx__bin_xy(double x, double y, double cct_K, double duv, lx_binning *out);

/* CCT and Duv for binning many spectra (cct.c): the fast solver (cct_fast.c), the exact solve where
 * it does not answer; LX_ERANGE where neither finds one (the exact solver's range 500 K - 1e6 K). */
lx_status lx__cct_from_uv_table(lx_ctx *ctx, lx_observer obs, double u, double v, double *cct_K, double *duv);

/* The radiant integral of spectrum i of a batch: the trapezoid rule, as lx_spd_integrate_radiant
 * (batch_colorimetry.c). */
double lx__batch_radiant(const lx_batch *b, size_t i);

/* The batch weight matrix: w[f * n_lambda + j] = w_f(start + j step) * step (cie15 rule); for a band
 * function (lx__fn_band_exact) the exact weight of sample j, the integral of its hat function times
 * w_f, so that the sum is the exact integral of the piecewise-linear spectrum times w_f. */
lx_status lx__batch_weights(lx_ctx *ctx, const lx_function *fns, size_t k, double start_nm, double step_nm,
                            size_t n_lambda, double *w);

/* The vector line parser of the batch CSV reader (csv_vector.c): the line of n short decimals
 * separated by sep that starts at q, up to its '\n' (or '\r\n') before stop, or up to stop itself
 * when whole (stop is the end of the text); 64 bytes past stop are readable. The values go to dst
 * (float when f32), each correctly rounded as strtod; *line_end gets the line's end (its '\n', or
 * stop). 0 when any field is not "-?D+(.D*)?" of at most 15 characters, the count is not n, or no
 * line end comes before stop (the general parser then reads the line). level: what
 * lx__csv_fast_level() says this CPU runs: 2 AVX-512 (with BITALG), 1 AVX2 (+FMA, BMI1/2), 0 none
 * (lx_simd_level() capped). */
int lx__csv_fast_line(int level, const char *q, const char *stop, int whole, char sep, size_t n, int f32, void *dst,
                      const char **line_end);
int lx__csv_fast_level(void);
/* Rows the vector line parser has taken in this process (the tests check that a path ran). */
unsigned long long lx__csv_fast_rows(void);

/* CIE 1960 uv of the Planckian radiator at T[k], k < n (cct.c, the exact solver's sums) with
 * their first three derivatives in s = ln T: out[k] = {u, v, u', v', u'', v'', u''', v'''}.
 * LX_ENOMEM (no message) when out of memory. */
lx_status lx__planck_uv_ds3(lx_observer obs, size_t n, const double *T, double (*out)[8]);

/* The fast CCT solver (cct_fast.c) for one chromaticity: the precomputed locus of the observer,
 * no exp. Returns 1 with *cct_K and *duv when the nearest locus point lies inside its table
 * (LX__CCT_FAST_T_MIN..MAX), else 0 (the caller runs lx_cct_from_uv). Thread-safe. */
#define LX__CCT_FAST_T_MIN 900.0
#define LX__CCT_FAST_T_MAX 120000.0
int lx__cct_fast(lx_observer obs, double u, double v, double *cct_K, double *duv);

/* lx__colorimetry_range with the CCT by the fast solver (colorimetry.c): the same columns to 1e-10
 * relative; the exact solver where the fast one does not answer or the answer lies at an edge. */
lx_status lx__colorimetry_fast(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime, double radiant,
                               double lo_K, double hi_K, lx_colorimetry *out);

/* Colorimetry from integrals with the CCT range [lo_K, hi_K] (inclusive to 1e-9 relative);
 * *solved_K (may be NULL) the solved CCT when |Duv| <= 0.05 whatever the range, else NaN
 * (colorimetry.c). */
lx_status lx__colorimetry_range(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime, double radiant,
                                double lo_K, double hi_K, lx_colorimetry *out, double *solved_K);
/* The ends of 1000-100000 K as Planckian radiators at those temperatures show them when sampled at
 * spd's wavelengths and integrated by method (never inside the nominal range). */
void lx__cct_range_ends(lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method, double *lo_K, double *hi_K);

#endif /* LX_SPECTRAL_PRIVATE_H */
