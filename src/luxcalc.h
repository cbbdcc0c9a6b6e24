/* luxcalc.h - the whole public API of luxcalc, a C11 library for photometry and radiometry.
 * All quantities are double, SI units unless a name says otherwise (_nm, _lm, _lx, _cd, _K).
 * The library never prints and never exits: every call that can fail returns an lx_status. */
#ifndef LUXCALC_H
#define LUXCALC_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define LX_API __declspec(dllexport)
#elif defined(__GNUC__)
#define LX_API __attribute__((visibility("default")))
#else
#define LX_API
#endif

#define LX_VERSION_MAJOR 0
#define LX_VERSION_MINOR 1
#define LX_VERSION_PATCH 0
#define LX_VERSION_STRING "0.1.0"

/** The library version as "MAJOR.MINOR.PATCH" (static storage). Thread-safe. */
LX_API const char *lx_version(void);

/* ------------------------------------------------------------------------------------------ */
/* Status codes and the context                                                                */
/* ------------------------------------------------------------------------------------------ */

typedef enum lx_status {
    LX_OK = 0,           /* success */
    LX_EINVAL = 1,       /* an argument is invalid (NULL, out of range, inconsistent) */
    LX_EPARSE = 2,       /* input text or file is malformed; the message names file and line */
    LX_EIO = 3,          /* a file could not be opened, read or written */
    LX_ENOMEM = 4,       /* out of memory */
    LX_ERANGE = 5,       /* the quantity is undefined for this input (e.g. CCT far off the locus) */
    LX_EUNSUPPORTED = 6, /* not supported by this build or for this input */
    LX_EDEVICE = 7       /* an OpenCL runtime or device error; the message names the call and code */
} lx_status;

/** Static text for a status code ("invalid argument", ...). Never NULL. Thread-safe. */
LX_API const char *lx_strerror(lx_status status);

/** Log levels passed to the log callback. */
typedef enum lx_log_level { LX_LOG_ERROR = 0, LX_LOG_WARN = 1, LX_LOG_INFO = 2, LX_LOG_DEBUG = 3 } lx_log_level;

/** Log callback: receives one message, without a trailing newline. */
typedef void (*lx_log_fn)(void *user, lx_log_level level, const char *message);

/** An opaque library context: error state, log callback, lazily built caches (locus tables,
 * OpenCL programs). One context may be used by one thread at a time; use one per thread. */
typedef struct lx_ctx lx_ctx;

/** Creates a context in *out. Returns LX_ENOMEM on allocation failure (then *out is NULL). */
LX_API lx_status lx_ctx_create(lx_ctx **out);

/** Destroys a context and everything it owns. Accepts NULL. */
LX_API void lx_ctx_destroy(lx_ctx *ctx);

/** The detail of the last error on this context, as "FILE:LINE: what" when a file and line
 * apply, else "what". Empty string when no error occurred. Owned by ctx, valid until the next
 * call that fails on it. */
LX_API const char *lx_ctx_errmsg(const lx_ctx *ctx);

/** The file and line of the last error (NULL and 0 when none apply). */
LX_API const char *lx_ctx_errfile(const lx_ctx *ctx);
LX_API long lx_ctx_errline(const lx_ctx *ctx);

/** Installs a log callback (NULL removes it). Messages at or below max_level are delivered. */
LX_API void lx_ctx_set_log(lx_ctx *ctx, lx_log_fn fn, void *user, lx_log_level max_level);

/* ------------------------------------------------------------------------------------------ */
/* Spectra                                                                                     */
/* ------------------------------------------------------------------------------------------ */

/** A sampled spectrum: a view of n samples at strictly increasing wavelengths. The library
 * treats a spectrum as piecewise linear between samples and zero outside [lambda_nm[0],
 * lambda_nm[n-1]]. The struct does not own its arrays unless a set owns them (see lx_spd_set). */
typedef struct lx_spd {
    const char *name;        /* label: header name, row id, or "1", "2", ... (may be NULL) */
    size_t n;                /* number of samples, >= 2 */
    const double *lambda_nm; /* wavelengths in nm, strictly increasing */
    const double *value;     /* values, unit set by the caller (W/nm, W/m2/nm, relative, ...) */
} lx_spd;

/** Spectra read from one file. Owns every array and string it points to. */
typedef struct lx_spd_set {
    char *file;    /* the path given to the reader ("-" for standard input) */
    size_t count;  /* number of spectra */
    lx_spd *spd;   /* count spectra */
    long *line;    /* for each spectrum, the line of the file it starts on (rows layout) or its header line */
} lx_spd_set;

/** Reads spectra from a text file ("-" is standard input): columns (wavelength, value...) or rows
 * (a header of wavelengths, one spectrum per row), separators , ; tab or spaces, '#' comments,
 * optional header, CRLF, UTF-8 BOM, and CGATS/Argyll spectral files (SPECTRAL_* fields).
 * Unsorted rows are sorted. Errors (LX_EPARSE, LX_EIO) name the file and line. On success *out
 * owns the result; free it with lx_spd_set_free. On failure *out is NULL. */
LX_API lx_status lx_spd_read_file(lx_ctx *ctx, const char *path, lx_spd_set **out);

/** Same as lx_spd_read_file on a memory buffer; name is used in messages and as set->file. */
LX_API lx_status lx_spd_read_mem(lx_ctx *ctx, const char *name, const char *text, size_t len,
                                 lx_spd_set **out);

/** Frees a set. Accepts NULL. */
LX_API void lx_spd_set_free(lx_spd_set *set);

/** Checks a spectrum view: n >= 2, finite values, strictly increasing wavelengths. */
LX_API lx_status lx_spd_check(lx_ctx *ctx, const lx_spd *spd);

/** Integration methods (see README): */
typedef enum lx_method {
    LX_METHOD_AUTO = 0,     /* cie15 for uniform 1 or 5 nm data on whole nm, else exact */
    LX_METHOD_CIE15 = 1,    /* sum at the data's own uniform step, weights at those wavelengths */
    LX_METHOD_EXACT = 2,    /* exact integral of piecewise-linear x piecewise-linear */
    LX_METHOD_LINEAR1NM = 3 /* interpolate the spectrum to whole nm, then sum with step 1 nm */
} lx_method;

/** Standard observers. */
typedef enum lx_observer { LX_OBSERVER_2 = 2, LX_OBSERVER_10 = 10 } lx_observer;

/** The method LX_METHOD_AUTO picks for this spectrum (never returns LX_METHOD_AUTO). */
LX_API lx_method lx_method_resolve(const lx_spd *spd, lx_method method);

/** Integrates spd * weight over wavelength with the given method, where weight is any sampled
 * function (a colour-matching function, an action spectrum). The result has the unit of
 * spd value x weight x nm. For LX_METHOD_CIE15 spd must be uniformly sampled (else LX_EINVAL). */
LX_API lx_status lx_spd_integrate(lx_ctx *ctx, const lx_spd *spd, const lx_spd *weight,
                                  lx_method method, double *out);

/** Integral of the spectrum alone over its whole range (the radiant integral) with the method's rule. */
LX_API lx_status lx_spd_integrate_radiant(lx_ctx *ctx, const lx_spd *spd, lx_method method,
                                          double *out);

/** Colorimetric and photometric results of one spectrum. */
typedef struct lx_colorimetry {
    double X, Y, Z;           /* absolute: Km * integral(S xbar) etc.; Km 683.002 (2 deg), 683.599 (10 deg) */
    double x, y;              /* CIE xy chromaticity */
    double u_prime, v_prime;  /* CIE 1976 UCS */
    double cct_K;             /* correlated colour temperature (NaN when cct_valid is 0) */
    double duv;               /* distance from the Planckian locus in CIE 1960 uv, + above (NaN when invalid) */
    int cct_valid;            /* 1 when |duv| <= 0.05 and 1000 K <= CCT <= 100000 K */
    double radiant;           /* integral of S over the whole spectrum (W for W/nm input) */
    double ler_lm_per_W;      /* luminous efficacy of radiation Y / radiant (NaN when radiant is 0) */
    double scotopic_Y;        /* K'm * integral(S V') with K'm = 1700.06 lm/W */
    double sp_ratio;          /* scotopic_Y / Y (NaN when Y is 0) */
    lx_method method;         /* the method used (auto resolved) */
} lx_colorimetry;

/** Computes every quantity of lx_colorimetry for one spectrum. A spectrum with zero luminous
 * content gives X = Y = Z = 0 and NaN chromaticities (not an error). */
LX_API lx_status lx_spd_colorimetry(lx_ctx *ctx, const lx_spd *spd, lx_observer observer,
                                    lx_method method, lx_colorimetry *out);

/* ------------------------------------------------------------------------------------------ */
/* CIE tables, illuminants, Planck and daylight                                                */
/* ------------------------------------------------------------------------------------------ */

/** Weighting functions embedded from the CIE tables (views valid for the life of the program). */
typedef enum lx_function {
    LX_FN_XBAR_2 = 0, LX_FN_YBAR_2, LX_FN_ZBAR_2,    /* CIE 1931 2 deg, 360-830 nm at 1 nm */
    LX_FN_XBAR_10, LX_FN_YBAR_10, LX_FN_ZBAR_10,     /* CIE 1964 10 deg, 360-830 nm at 1 nm */
    LX_FN_VPRIME,                                    /* CIE 1951 scotopic V'(lambda), 380-780 nm */
    LX_FN_ALPHA_SC, LX_FN_ALPHA_MC, LX_FN_ALPHA_LC,  /* CIE S 026 alpha-opic action spectra, */
    LX_FN_ALPHA_RH, LX_FN_ALPHA_MEL,                 /* 380-780 nm at 1 nm, peak 1 */
    LX_FN_COUNT
} lx_function;

/** A view of an embedded weighting function. Returns LX_EINVAL for an unknown id. */
LX_API lx_status lx_function_get(lx_ctx *ctx, lx_function fn, lx_spd *out);

/** A view of a CIE illuminant from the embedded tables by name: "A", "D50", "D55", "D65", "D75",
 * "E", "FL1".."FL12", "FL3.1".."FL3.15", "LED-B1".."LED-V2", "HP1".."HP5" (relative SPDs as
 * published, 5 nm). Returns LX_EINVAL for an unknown name. */
LX_API lx_status lx_illuminant_get(lx_ctx *ctx, const char *name, lx_spd *out);

/** The names of the embedded illuminants, NULL-terminated (static storage). */
LX_API const char *const *lx_illuminant_names(void);

/** CIE illuminant A by its defining formula (CIE 015:2018 eq. 4.1), any wavelength: 100 at 560 nm. */
LX_API double lx_illuminant_a(double lambda_nm);

/** Planck's law: spectral radiance of a blackbody in W/(sr m2 nm) at lambda_nm and T_K, with
 * c1L = 1.191042972e-16 W m2/sr and c2 = 1.4388e-2 m K. Stable for 1 K to 1e9 K (no overflow;
 * underflows to 0). Returns NaN when lambda_nm or T_K is not positive and finite. Thread-safe. */
LX_API double lx_planck(double lambda_nm, double T_K);

/** Total radiant exitance of a blackbody, Stefan-Boltzmann sigma T^4 in W/m2. */
LX_API double lx_stefan_boltzmann(double T_K);

/** CIE D-series relative SPD for a correlated colour temperature 4000-25000 K (CIE 015:2018
 * 4.1.2; M1, M2 rounded to 3 decimals as the standard prescribes) at n wavelengths (300-830 nm,
 * basis linearly interpolated; 0 outside). Returns LX_ERANGE for a CCT outside 4000-25000 K. */
LX_API lx_status lx_daylight(lx_ctx *ctx, double cct_K, size_t n, const double *lambda_nm,
                             double *value);

/** Chromaticity of CIE daylight at cct_K (CIE 015:2018 eq. 4.7-4.8). */
LX_API lx_status lx_daylight_xy(lx_ctx *ctx, double cct_K, double *x, double *y);

/* ------------------------------------------------------------------------------------------ */
/* Chromaticity                                                                                */
/* ------------------------------------------------------------------------------------------ */

/** CCT and Duv from CIE 1960 (u, v), solved exactly on the Planckian locus computed with the
 * observer's colour-matching functions (360-830 nm, 1 nm) and c2 = 1.4388e-2 m K. Searches
 * 500 K to 1e6 K; returns LX_ERANGE (and NaN outputs) when the nearest locus point is outside that. */
LX_API lx_status lx_cct_from_uv(lx_ctx *ctx, lx_observer observer, double u, double v,
                                double *cct_K, double *duv);

/** Convenience: from CIE xy. */
LX_API lx_status lx_cct_from_xy(lx_ctx *ctx, lx_observer observer, double x, double y,
                                double *cct_K, double *duv);

/** CIE 1960 uv of the Planckian radiator at T_K with the observer's CMFs. */
LX_API lx_status lx_planck_uv(lx_ctx *ctx, lx_observer observer, double T_K, double *u, double *v);

/* ---- lighting (issue 4) ---- */

/* Units and quantities (units.c). Values are converted to and from the SI unit of their
 * quantity (lm, W, cd, W/sr, lx, W/m2, cd/m2, W/sr/m2, sr, m, rad, K, lm/W). */

/** Physical quantities the unit parser knows. */
typedef enum lx_quantity {
    LX_Q_NONE = 0,           /* no quantity: "any" when expected, a bare number when parsed */
    LX_Q_LUMINOUS_FLUX,      /* lm */
    LX_Q_RADIANT_FLUX,       /* W */
    LX_Q_LUMINOUS_INTENSITY, /* cd */
    LX_Q_RADIANT_INTENSITY,  /* W/sr */
    LX_Q_ILLUMINANCE,        /* lx */
    LX_Q_IRRADIANCE,         /* W/m2 */
    LX_Q_LUMINANCE,          /* cd/m2 */
    LX_Q_RADIANCE,           /* W/sr/m2 */
    LX_Q_SOLID_ANGLE,        /* sr */
    LX_Q_LENGTH,             /* m */
    LX_Q_ANGLE,              /* rad */
    LX_Q_TEMPERATURE,        /* K */
    LX_Q_EFFICACY,           /* lm/W */
    LX_Q_COUNT
} lx_quantity;

/** One unit: value_SI = value * to_si. Entries with primary = 0 are aliases ("nits", "lux"). */
typedef struct lx_unit {
    const char *name;     /* as printed and parsed, e.g. "fc" */
    lx_quantity quantity; /* what it measures */
    double to_si;         /* size of one unit in the SI unit of the quantity */
    int primary;          /* 1 for the name listed by lx_units/convert, 0 for an alias */
    const char *title;    /* long name, e.g. "foot-candle (lm/ft2)" */
} lx_unit;

/** The unit table (static storage, *count entries, aliases included). Thread-safe. */
LX_API const lx_unit *lx_units(size_t *count);

/** The quantity's name ("illuminance") and SI unit ("lx"); "" for LX_Q_NONE. Thread-safe. */
LX_API const char *lx_quantity_name(lx_quantity q);
LX_API const char *lx_quantity_si_unit(lx_quantity q);

/** The photometric counterpart of a radiometric quantity and back (W <-> lm, W/sr <-> cd,
 * W/m2 <-> lx, W/sr/m2 <-> cd/m2); LX_Q_NONE for quantities that have none. Thread-safe. */
LX_API lx_quantity lx_quantity_counterpart(lx_quantity q);

/** Finds a unit by name (case-insensitive; "cd/m^2", "cd/m²", "nits", "lux" accepted).
 * Returns LX_EPARSE naming the unit when it is unknown. */
LX_API lx_status lx_unit_find(lx_ctx *ctx, const char *name, const lx_unit **out);

/** Parses "1000lm", "2.5 m", "30deg", "46 fc", or a bare number into *si_value (SI unit of its
 * quantity). expect: the quantity wanted (LX_Q_NONE accepts any); a bare number takes
 * bare_unit (a unit name; NULL means the SI unit of expect). *got (may be NULL) receives the
 * quantity parsed. Errors: LX_EPARSE for malformed text or an unknown unit, LX_EINVAL for a
 * unit of another quantity (the message names the unit and both quantities). */
LX_API lx_status lx_quantity_parse(lx_ctx *ctx, const char *text, lx_quantity expect,
                                   const char *bare_unit, double *si_value, lx_quantity *got);

/** Converts value from unit `from` to unit `to` (both names). LX_EINVAL when the quantities
 * differ, LX_EPARSE for unknown names. */
LX_API lx_status lx_unit_convert(lx_ctx *ctx, double value, const char *from, const char *to,
                                 double *out);

/** Writes "VALUE UNIT" with VALUE = si_value expressed in `unit`, printed in the shortest form
 * that reads back exactly, into buf (cap bytes, always terminated). */
LX_API lx_status lx_unit_format(lx_ctx *ctx, double si_value, const char *unit, char *buf,
                                size_t cap);

/** Radiometric -> photometric (or back, with to_photometric = 0) with an explicit luminous
 * efficacy of radiation K in lm/W: photometric = K * radiometric. q is the quantity of the
 * input; *out_q the quantity of the result. LX_EINVAL for K not positive and finite or a q
 * without counterpart. There is no default efficacy: the caller must supply one. */
LX_API lx_status lx_radiometric_convert(lx_ctx *ctx, double value_si, lx_quantity q,
                                        double efficacy_lm_per_W, double *out_si,
                                        lx_quantity *out_q);

/** The luminous efficacy of radiation (lm/W, 2 deg observer, auto method) of the single
 * spectrum in a file read with lx_spd_read_file (efficacy.c). LX_EINVAL when the file holds
 * more than one spectrum or its radiant integral is zero. */
LX_API lx_status lx_efficacy_from_spd_file(lx_ctx *ctx, const char *path, double *ler_lm_per_W);

/* Sources (sources.c). Distances in m, angles in rad, luminance in cd/m2. A distance that is
 * zero, negative or not finite is LX_EINVAL (never infinity). Receivers facing away get 0. */

/** Illuminance from a point source of intensity I at distance d, incidence angle a from the
 * receiver normal: E = I cos(a) / d^2; 0 when cos(a) <= 0 (back-facing or grazing). */
LX_API lx_status lx_point_illuminance(lx_ctx *ctx, double intensity_cd, double distance_m,
                                      double incidence_rad, double *illuminance_lx);

/** Intensity of an isotropic point source of flux F: I = F / (4 pi). */
LX_API lx_status lx_point_intensity(lx_ctx *ctx, double flux_lm, double *intensity_cd);

/** Warn spotlight of flux F and exponent S >= 0 (finite): I(a) = c cos^S(a) for |a| < pi/2,
 * 0 beyond, c = (S+1)/(2 pi) F. *peak_cd = c (may be NULL). Stable for S up to 1e300:
 * cos^S is evaluated as exp(S log1p(-2 sin^2(a/2))); it underflows to 0, never NaN. */
LX_API lx_status lx_warn_intensity(lx_ctx *ctx, double flux_lm, double exponent, double angle_rad,
                                   double *peak_cd, double *intensity_cd);

/** cos^S(a) for |a| <= pi/2, else 0 (the normalised Warn lobe). NaN for S < 0 or NaN input. */
LX_API double lx_warn_lobe(double exponent, double angle_rad);

/** Warn exponent whose full beam angle (where I = I_peak / 2) is beam_rad, and back. */
LX_API lx_status lx_warn_exponent_from_beam(lx_ctx *ctx, double beam_rad, double *exponent);
LX_API lx_status lx_warn_beam_from_exponent(lx_ctx *ctx, double exponent, double *beam_rad);

/** Which model an extended source is evaluated with. */
typedef enum lx_model {
    LX_MODEL_AUTO = 0,  /* exact when distance < 5 x the source's largest dimension, else point */
    LX_MODEL_POINT = 1, /* point source at the centre, I(theta) = L A cos(theta) */
    LX_MODEL_EXACT = 2  /* closed-form configuration factor, E = pi L F */
} lx_model;

/** The illuminance of an extended Lambertian source on a parallel receiver. */
typedef struct lx_source_result {
    double illuminance_lx;       /* by the model used */
    double exact_lx;             /* closed form */
    double point_lx;             /* point-source approximation */
    double point_error;          /* point_lx / exact_lx - 1 (NaN when exact_lx is 0) */
    double exact_rel_error;      /* bound on the relative error of exact_lx (closed form: 1e-14;
                                  * adaptive quadrature: its estimate) */
    double distance_m;           /* centre of the source to the receiver */
    double largest_dimension_m;  /* disk: diameter; rectangle: diagonal */
    int near_field;              /* 1 when distance_m < 5 x largest_dimension_m */
    lx_model model;              /* LX_MODEL_POINT or LX_MODEL_EXACT, never AUTO */
} lx_source_result;

/** Lambertian disk of luminance L and radius R; receiver parallel to it at height h, offset r
 * from the axis. Exact: configuration factor of a parallel differential element to a disk,
 * F = (1/2)[1 - (h^2 + r^2 - R^2) / sqrt((h^2 + r^2 + R^2)^2 - 4 r^2 R^2)], rewritten so no
 * subtraction cancels (see sources.c). Point: E = L pi R^2 h^2 / (h^2 + r^2)^2. */
LX_API lx_status lx_disk_illuminance(lx_ctx *ctx, double luminance_cd_m2, double radius_m,
                                     double height_m, double offset_m, lx_model model,
                                     lx_source_result *out);

/** Lambertian rectangle width a (along x) x length b (along y) of luminance L; receiver parallel
 * at height h, its foot at (x, y) from the rectangle's centre (a corner is (a/2, b/2)). Exact: the
 * corner configuration factor (Howell's catalogue, case B-3) superposed over four corner
 * rectangles with signs. Point: E = L a b h^2 / (h^2 + x^2 + y^2)^2. */
LX_API lx_status lx_rect_illuminance(lx_ctx *ctx, double luminance_cd_m2, double width_m,
                                     double length_m, double height_m, double x_m, double y_m,
                                     lx_model model, lx_source_result *out);

/** Luminance of a Lambertian reflector of reflectance rho (0..1) under illuminance E: rho E / pi. */
LX_API lx_status lx_lambertian_luminance(lx_ctx *ctx, double reflectance, double illuminance_lx,
                                         double *luminance_cd_m2);

/* Inverse problems (solve.c): a point receiver facing the source at incidence a (rad). */

/** Distance at which intensity I gives illuminance E: d = sqrt(I cos a / E). */
LX_API lx_status lx_solve_distance(lx_ctx *ctx, double illuminance_lx, double intensity_cd,
                                   double incidence_rad, double *distance_m);

/** Intensity needed for illuminance E at distance d: I = E d^2 / cos a. */
LX_API lx_status lx_solve_intensity(lx_ctx *ctx, double illuminance_lx, double distance_m,
                                    double incidence_rad, double *intensity_cd);

/** Flux needed for illuminance E at distance d: isotropic point (exponent < 0: F = 4 pi I) or a
 * Warn spot of exponent S >= 0 seen at angle `angle_rad` off its axis (F = 2 pi I / ((S+1) cos^S)). */
LX_API lx_status lx_solve_flux(lx_ctx *ctx, double illuminance_lx, double distance_m,
                               double incidence_rad, double exponent, double angle_rad,
                               double *flux_lm);

/* Solid angles (solid_angle.c), in sr. */

/** A cone (spherical cap) of half-angle a in [0, pi]: 2 pi (1 - cos a) = 4 pi sin^2(a/2). */
LX_API lx_status lx_solid_angle_cap(lx_ctx *ctx, double half_angle_rad, double *sr);

/** A pixel of a width x height lat-long map (row 0 at theta = 0, theta from +z, phi from +x):
 * (2 pi / width) (cos theta0 - cos theta1), computed as a product of sines. */
LX_API lx_status lx_solid_angle_latlong_pixel(lx_ctx *ctx, int width, int height, int row,
                                              double *sr);

/** The rectangle [x0, x1] x [y0, y1] of a plane at distance d, seen from the point whose foot on
 * the plane is the origin: corner terms atan(x y / (d sqrt(x^2 + y^2 + d^2))) with signs. */
LX_API lx_status lx_solid_angle_rect(lx_ctx *ctx, double x0, double x1, double y0, double y1,
                                     double distance_m, double *sr);

/* ---- OpenCL runtime and batches (issue 3) ---- */

/** Where batch work runs. AUTO: the CPU unless the batch is large enough to repay OpenCL
 * start-up (see README "opencl"); never an error when no OpenCL platform exists. */
typedef enum lx_backend { LX_BACKEND_AUTO = 0, LX_BACKEND_CPU = 1, LX_BACKEND_OPENCL = 2 } lx_backend;

/** Parses "auto", "cpu" or "opencl" into *out; returns LX_EINVAL (message names the text) otherwise. */
LX_API lx_status lx_backend_parse(lx_ctx *ctx, const char *text, lx_backend *out);

/** The backend named by the environment variable LX_BACKEND, or LX_BACKEND_AUTO when unset/invalid. */
LX_API lx_backend lx_backend_from_env(void);

/** OpenCL device types for the device choice. */
typedef enum lx_cl_type { LX_CL_AUTO = 0, LX_CL_CPU = 1, LX_CL_GPU = 2 } lx_cl_type;

/** Chooses the OpenCL device this context will use, before its first OpenCL work: platform and
 * device indices (-1: any; then the environment LX_PLATFORM / LX_DEVICE apply) and a type (AUTO
 * prefers a GPU, then any device). Releases an OpenCL state the context already holds.
 * Returns LX_EUNSUPPORTED in a build without OpenCL. Does not initialise OpenCL. */
LX_API lx_status lx_cl_select(lx_ctx *ctx, int platform, int device, lx_cl_type type);

/** Borrows a caller's OpenCL context and command queue (cl_context and cl_command_queue passed
 * as void*, so this header needs no OpenCL headers). The library retains both and releases them
 * at lx_ctx_destroy; the device is the queue's. Returns LX_EUNSUPPORTED without OpenCL. */
LX_API lx_status lx_cl_borrow(lx_ctx *ctx, void *cl_context, void *cl_command_queue);

/** Description of one OpenCL device. */
typedef struct lx_cl_device_info {
    int platform, device;           /* indices as LX_PLATFORM / LX_DEVICE count them */
    char platform_name[128];
    char device_name[128];
    char version[64];               /* CL_DEVICE_VERSION */
    int is_gpu, is_cpu;
    unsigned compute_units;
    unsigned long long global_mem_bytes;
    unsigned long long max_alloc_bytes; /* CL_DEVICE_MAX_MEM_ALLOC_SIZE, the chunk limit */
    int fp64;                       /* 1 when cl_khr_fp64 (or OpenCL >= 1.2 double) is available */
    int is_default;                 /* 1 for the device the AUTO choice (and environment) picks */
} lx_cl_device_info;

/** Lists every OpenCL device of every platform into *out (malloc'ed, free with free()), *n of
 * them. No platform is not an error: *n = 0. Does not create an OpenCL context. */
LX_API lx_status lx_cl_devices(lx_ctx *ctx, lx_cl_device_info **out, size_t *n);

/** Initialises OpenCL on ctx if not done yet (device choice, context, queue) and describes the
 * device in use. LX_EDEVICE when no device can be used, with the OpenCL call and code. */
LX_API lx_status lx_cl_info(lx_ctx *ctx, lx_cl_device_info *out);

/** 1 when ctx already holds an initialised OpenCL state (start-up already paid), else 0. */
LX_API int lx_cl_ready(const lx_ctx *ctx);

/** Element type of batch values. */
typedef enum lx_dtype { LX_F32 = 0, LX_F64 = 1 } lx_dtype;

/** N spectra sampled on one uniform grid start_nm + j * step_nm, j < n_lambda, row-major:
 * spectrum i starts at element i * row_stride (row_stride 0 means n_lambda). Not owned. */
typedef struct lx_batch {
    size_t n_spectra;
    size_t n_lambda;       /* >= 1 */
    size_t row_stride;     /* elements between spectra, 0 = n_lambda */
    double start_nm, step_nm; /* step_nm > 0 */
    lx_dtype dtype;
    const void *values;    /* float or double, n_spectra rows */
} lx_batch;

/** Options of lx_batch_integrate (zero-initialise for defaults). */
typedef struct lx_batch_opts {
    lx_backend backend;    /* AUTO (default) also reads LX_BACKEND */
    int threads;           /* CPU threads; 0 = every online core */
    size_t chunk_spectra;  /* OpenCL: spectra per chunk; 0 = from CL_DEVICE_MAX_MEM_ALLOC_SIZE */
    lx_backend used;       /* OUT: the backend that did the work */
} lx_batch_opts;

/** Integrates N spectra against K weighting functions at once with the cie15 rule:
 * out[i*k + f] = sum_j value[i][j] * w_f(start_nm + j*step_nm) * step_nm, the weights linearly
 * interpolated from their tables and zero outside them (no Km factor). Accumulates in double on
 * both backends (1e-9 relative CPU vs OpenCL for double input, 1e-6 for float). opts may be NULL.
 * A fall-back from OpenCL to the CPU in AUTO is reported through the log callback (LX_LOG_INFO).
 * Thread-safe for distinct contexts. Outputs untouched on failure. */
LX_API lx_status lx_batch_integrate(lx_ctx *ctx, const lx_batch *batch, const lx_function *fns, size_t k,
                                    lx_batch_opts *opts, double *out);

/** Resamples N spectra given on their own strictly increasing wavelengths (row i: n_in[i]
 * samples at lambda_nm + offset[i], values at value + offset[i]) onto the uniform grid of dst
 * (dst->values must point to writable memory of dst->dtype, n_spectra rows) by linear
 * interpolation, zero outside each spectrum: the piecewise-linear model the exact method uses.
 * backend as in lx_batch_integrate (OpenCL: the resample kernel). */
/** A batch read from a rows-layout CSV: one spectrum per line on the header's uniform grid. */
typedef struct lx_batch_table {
    lx_batch batch;  /* owns batch.values */
    char *names;     /* the rows' first cells, NUL-separated ("" when the file has no name column) */
    size_t *name_at; /* batch.n_spectra offsets into names */
} lx_batch_table;

/** Reads a rows-layout batch CSV ("id,380,381,...,780" then "name,v1,v2,..." per line; separators
 * , ; or tab; '#' comment and blank lines skipped; CRLF; BOM) into a float or double batch, in
 * parallel on `threads` threads (0 = every core). The header's wavelengths must form a uniform
 * grid (else LX_EUNSUPPORTED: use lx_spd_read_file). Errors (LX_EPARSE) name file and line.
 * "-" is standard input. Free *out with lx_batch_table_free. */
LX_API lx_status lx_batch_table_read(lx_ctx *ctx, const char *path, lx_dtype dtype, int threads,
                                     lx_batch_table **out);
LX_API lx_status lx_batch_table_read_mem(lx_ctx *ctx, const char *file, const char *text, size_t len,
                                         lx_dtype dtype, int threads, lx_batch_table **out);
LX_API void lx_batch_table_free(lx_batch_table *t);

LX_API lx_status lx_batch_resample(lx_ctx *ctx, size_t n_spectra, const double *lambda_nm, const double *value,
                                   const size_t *offset, const size_t *n_in, lx_batch *dst, lx_batch_opts *opts);

#ifdef __cplusplus
}
#endif
#endif /* LUXCALC_H */
