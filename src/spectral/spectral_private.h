/* spectral_private.h - the spectral layer's internals (never installed): the spectrum-set builder
 * shared by the readers, the CGATS reader, the batch weight matrix and the vector CSV line parser. */
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

/* The largest |value| of spd. */
double lx__spd_max_abs(const lx_spd *spd);

/* CGATS / Argyll spectral files (cgats.c): detection by content, and the reader. */
int lx__cgats_detect(const char *text, size_t len);
lx_status lx__cgats_read(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_spd_set **out);

/* The batch weight matrix: w[f * n_lambda + j] = w_f(start + j step) * step (cie15 rule). */
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

/* lx_colorimetry_from_integrals with the CCT by the fast solver when fast (colorimetry.c): the
 * same columns to 1e-10 relative; the exact solver where the fast one does not answer or the
 * answer lies at a validity edge. */
lx_status lx__colorimetry_derive(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime, double radiant,
                                 int fast, lx_colorimetry *out);

#endif /* LX_SPECTRAL_PRIVATE_H */
