/* luxcalc.h - the whole public API of luxcalc, a C11 library for photometry and radiometry, and its
 * reference manual: the conventions below hold for every function unless its own comment says
 * otherwise; each comment adds what is particular to it (units, ownership, errors).
 *
 * Units: all quantities are double, SI units unless a name says otherwise (_nm, _lm, _lx, _cd, _K,
 * _cd_m2, ...); struct fields carry their unit in their name or comment.
 *
 * Errors: every call that can fail returns an lx_status; the library never prints and never exits.
 * - A NULL context is LX_EINVAL, and nothing is read or written (there is nowhere to put a message).
 *   The functions that accept a NULL context say so: lx_ctx_destroy, the lx_ctx_* getters (they
 *   return "", NULL, 0, LX_BACKEND_AUTO or the default input limit), lx_ctx_set_log and
 *   lx_ctx_counters_reset (no-ops).
 * - LX_EINVAL for a NULL pointer the call needs or an argument outside its documented range;
 *   LX_ENOMEM when memory runs out. Codes beyond these are listed at each function ("Errors:").
 * - After a failure lx_ctx_errmsg(ctx) holds the detail (file and line where they apply); outputs
 *   are untouched, except that a function creating an object sets its *out to NULL.
 *
 * Ownership:
 * - arguments are borrowed for the call only: the library keeps no pointer to them once it returns
 *   (the exceptions say so: lx_cl_borrow retains the OpenCL objects it is given);
 * - an object or array the library makes for the caller comes back through an out pointer; the
 *   caller owns it and frees it with the function the comment names (lx_*_free, never free():
 *   the library may allocate differently in a later release); every lx_*_free accepts NULL;
 * - views (the lx_spd of lx_function_get, lx_illuminant_get, lx_tcs_get; lx_units; every const char *
 *   returned) point to static storage, or into the object they came from and live as long as it;
 *   they are never freed.
 *
 * Thread safety, for every function below unless its comment says otherwise:
 * - a function that takes an lx_ctx may run in several threads at once when each thread uses its
 *   own context (a context holds the last error, caches and the OpenCL state; it is not locked);
 * - a function without a context (lx_planck, lx_version, lx_luminaire_intensity, ...) is pure and
 *   thread-safe;
 * - objects the library returns (lx_spd_set, lx_luminaire, lx_envmap, ...) are read-only once made:
 *   several threads may read them (and pass them to functions) at once; freeing is not concurrent;
 * - the embedded tables and other lazily built globals are initialised safely (pthread_once).
 * tests/test_threads.c checks this: threads with their own contexts and shared objects give
 * bit-identical results to a serial run.
 *
 * ABI policy (README "ABI"). The shared library's soname is libluxcalc.so.MAJOR, so
 * libluxcalc.so.0 for every 0.x release. Within one soname a program built against an earlier
 * release (from 0.2.0 on) runs unchanged against a later one:
 * - functions and enum values are only added (enum values at the end, before a *_COUNT); nothing
 *   exported is removed, renamed, or given another signature or meaning;
 * - structs the caller allocates are of three kinds.
 *   Options (lx_batch_opts, lx_grid_opts, lx_irr_opts, lx_exr_write_opts, lx_scene_eval_opts,
 *   lx_lum_model, lx_sky_map_opts, lx_perez_input, lx_sun_input, lx_leni_input, lx_isolux_opts,
 *   lx_receiver_png_opts, lx_unc_opts, lx_unc_component, lx_pdf_report_opts) are only read: zero-initialise
 *   them (zero is every field's default) and leave
 *   `reserved` zero, which the library checks (LX_EINVAL otherwise); a later option takes reserved
 *   space, its zero meaning the earlier behaviour.
 *   Results (lx_colorimetry, lx_cri, lx_tm30, lx_alphaopic, lx_dominant, lx_spd_shape, lx_source_result,
 *   lx_lum_summary, lx_grid_stats, lx_cl_device_info, lx_counters, lx_sky, lx_sun_position, lx_ugr_table,
 *   lx_en12464_grid, lx_area_stats, lx_leni) are
 *   written whole by the library, `reserved` set to zero; a later result takes reserved space.
 *   Views and values (lx_spd, lx_batch, lx_placement, lx_plane, lx_plot_point, lx_plot_outline,
 *   lx_plot_mark, lx_unit, lx_sh9)
 *   never change within a soname: a new need gets a new type.
 * - structs only the library allocates (lx_spd_set, lx_batch_table, lx_luminaire, lx_envmap,
 *   lx_xyz_image, lx_scene, lx_scene_plan, lx_scene_result, lx_scene_glare, lx_scene_design,
 *   lx_scene_checks, lx_unc_result) grow by fields appended at their end: read their fields, but
 *   never allocate, copy or take the size of one. The structs of their arrays (lx_scene_luminaire,
 *   lx_scene_receiver, lx_scene_observer, lx_glare_term, lx_maintenance, lx_scene_area, lx_check,
 *   lx_unc_value) carry reserved space, as results do. lx_unc_model is opaque.
 * - LX_EFFECT_COUNT sizes arrays inside lx_scene and lx_scene_plan: a new effect changes their
 *   layout and so needs a new soname; LX_FN_COUNT and LX_Q_COUNT size nothing public and may grow.
 * An incompatible change needs a new MAJOR version, whose soname follows it (1.0: libluxcalc.so.1).
 * LX_VERSION_* below are the version this header belongs to; lx_version() the library's. */
#ifndef LUXCALC_H
#define LUXCALC_H

#include <stddef.h>
#include <stdio.h>

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
#define LX_VERSION_MINOR 2
#define LX_VERSION_PATCH 0
#define LX_VERSION_STRING "0.2.0"

/** The library's version as "MAJOR.MINOR.PATCH" (static storage): the version of the library the
 * program runs with, which may be later than the LX_VERSION_* it was compiled with. Thread-safe. */
LX_API const char *lx_version(void);

/* Contents, by layer (each section is one layer of src/, lowest first; README "Development"):
 *   1. core      Context, errors and the log
 *   2. core      Backends, SIMD paths and OpenCL devices
 *   3. tables    Spectra as views; embedded tables: weighting functions, illuminants, test colour samples
 *   4. spectral  Spectra: reading, integration, colorimetry
 *   5. spectral  Correlated colour temperature; LED binning
 *   6. spectral  Batches: many spectra on one grid, CSV files end to end
 *   7. spectral  Photobiology: alpha-opic and mesopic quantities, PAR, IEC 62471 hazards, efficacy of a file
 *   8. colour    Colour rendering: CIE 13.3 CRI, CIE 224 / TM-30
 *  8b. spectral, colour  Measurement uncertainty: input models, GUM and Monte Carlo
 *   9. lighting  Units and quantities
 *  10. lighting  Sources, inverse problems and solid angles
 *  11. lighting  Luminaires (IES LM-63, EULUMDAT) and illuminance grids
 *  12. radiance  Environment maps, OpenEXR and irradiance; daylight skies and the sun
 *  13. radiance  Spectral OpenEXR images
 *  14. scene     Scenes: files, the planner, evaluation and work counters
 *  15. plot      Plots (PNG with cairo, written atomically)
 */

/* ============================================================================================ */
/* 1. Context, errors and the log (src/core) */
/* ============================================================================================ */

typedef enum lx_status {
    LX_OK = 0,           /* success */
    LX_EINVAL = 1,       /* an argument is invalid (NULL, out of range, inconsistent) */
    LX_EPARSE = 2,       /* input text or file is malformed; the message names file and line */
    LX_EIO = 3,          /* a file could not be opened, read or written */
    LX_ENOMEM = 4,       /* out of memory */
    LX_ERANGE = 5,       /* the quantity is undefined for this input (e.g. CCT far off the locus) */
    LX_EUNSUPPORTED = 6, /* not supported by this build or for this input */
    LX_EDEVICE = 7,      /* an OpenCL runtime or device error; the message names the call and code */
    LX_EWRITE = 8        /* writing an output failed part-way (disk full, I/O error, a closed stream):
                          * the message names the file and the system's reason; nothing is left
                          * half-written (a path that cannot be created at all is LX_EIO) */
} lx_status;

/** Static text for a status code ("invalid argument", ...; "unknown status" for another value).
 * Never NULL, static storage. Thread-safe. */
LX_API const char *lx_strerror(lx_status status);

/** Log levels passed to the log callback. */
typedef enum lx_log_level { LX_LOG_ERROR = 0, LX_LOG_WARN = 1, LX_LOG_INFO = 2, LX_LOG_DEBUG = 3 } lx_log_level;

/** Log callback: receives one message, without a trailing newline, valid only during the call. It is
 * called on the thread that called the library function (never concurrently for one context). */
typedef void (*lx_log_fn)(void *user, lx_log_level level, const char *message);

/** An opaque library context: error state, log callback, lazily built caches (locus tables,
 * OpenCL programs). One context may be used by one thread at a time; use one per thread. */
typedef struct lx_ctx lx_ctx;

/** Creates a context in *out; free it with lx_ctx_destroy. Errors: LX_EINVAL (out NULL), LX_ENOMEM
 * (then *out is NULL). Thread-safe. */
LX_API lx_status lx_ctx_create(lx_ctx **out);

/** Destroys a context and everything it owns (caches, the OpenCL state, borrowed OpenCL objects
 * released). Accepts NULL. Objects made with the context (sets, luminaires, maps, ...) do not
 * belong to it and stay valid. */
LX_API void lx_ctx_destroy(lx_ctx *ctx);

/** The detail of the last error on this context, as "FILE:LINE: what" when a file and line
 * apply, else "what". Empty string when no error occurred, and for a NULL context. Owned by ctx,
 * valid until the next call that fails on it. */
LX_API const char *lx_ctx_errmsg(const lx_ctx *ctx);

/** The file and line of the last error (NULL and 0 when none apply, and for a NULL context). The
 * string is owned by ctx, valid until the next call that fails on it. */
LX_API const char *lx_ctx_errfile(const lx_ctx *ctx);
LX_API long lx_ctx_errline(const lx_ctx *ctx);

/** Installs a log callback (fn NULL removes it). Messages at or below max_level are delivered; the
 * default (no callback) delivers none. A NULL context is a no-op. */
LX_API void lx_ctx_set_log(lx_ctx *ctx, lx_log_fn fn, void *user, lx_log_level max_level);

/** The kinds of text file the library reads whole, each with a size limit (README "Robustness",
 * src/core/limits.h). A reader refuses a larger file, device or stream when it reaches the limit
 * ("FILE: larger than N MB (raise with LX_MAX_INPUT_MB)", LX_EIO), and refuses binary data (a NUL
 * byte, UTF-16 text, control bytes in the first block; LX_EPARSE naming the line) as it arrives. */
typedef enum lx_input_kind {
    LX_INPUT_SPECTRUM = 0,  /* spectra: SPD text, CGATS, instrument exports (default 256 MB) */
    LX_INPUT_LUMINAIRE = 1, /* photometric files: IES LM-63, EULUMDAT, TILT tables (default 16 MB) */
    LX_INPUT_SCENE = 2,     /* scene files and their includes (default 16 MB) */
    LX_INPUT_KERNEL = 3     /* OpenCL kernel sources read from LX_KERNEL_DIR (default 16 MB) */
} lx_input_kind;
#define LX_INPUT_KIND_COUNT 4

/** Sets the size limit in bytes for files of `kind` read through ctx; 0 restores the default:
 * the environment variable LX_MAX_INPUT_MB (a whole number of MB of 2^20 bytes, 1 to 1048576,
 * for every kind) when set, else the kind's default. LX_EINVAL for an unknown kind. */
LX_API lx_status lx_ctx_set_input_limit(lx_ctx *ctx, lx_input_kind kind, size_t max_bytes);

/** The size limit in bytes in effect for `kind` on ctx (ctx may be NULL: the default). */
LX_API size_t lx_ctx_input_limit(const lx_ctx *ctx, lx_input_kind kind);

/** Frees text the library wrote to memory for the caller (lx_luminaire_write_ies, lx_ugr_table_text).
 * Accepts NULL. */
LX_API void lx_text_free(char *text);

/** Room lx_double_format needs, the terminating NUL included. */
#define LX_DOUBLE_CHARS 32

/** Writes value as the shortest decimal text that reads back (strtod) as exactly value, the
 * closest such text when there are several (Ryu, Adams 2018), laid out as printf("%.*g", P) with
 * P = max(15, digits) lays out those digits ("0.1", "1e-07", "123456789012345680", "-0"; inf,
 * -inf and nan as printf). out needs LX_DOUBLE_CHARS bytes; returns the length (without the NUL).
 * Thread-safe, no allocation, about 30 ns. */
LX_API size_t lx_double_format(double value, char *out);

/** Opens path for reading as every reader of the library does: "-" is standard input; a missing
 * file or a directory is LX_EIO naming the path; a FIFO waits at most LX_FIFO_WAIT_S seconds
 * (default 10; 0: for ever) for its first data (LX_EIO saying so after that). Close *out with
 * fclose unless it is stdin. Errors: LX_EINVAL (a NULL context, path or out), LX_EIO. */
LX_API lx_status lx_file_open(lx_ctx *ctx, const char *path, FILE **out);

/* ============================================================================================ */
/* 2. Backends, SIMD paths and OpenCL devices (src/core) */
/* ============================================================================================ */

/** Where batch work runs. AUTO: the CPU unless the batch is large enough to repay OpenCL
 * start-up (see README "opencl"); never an error when no OpenCL platform exists. */
typedef enum lx_backend { LX_BACKEND_AUTO = 0, LX_BACKEND_CPU = 1, LX_BACKEND_OPENCL = 2 } lx_backend;

/** Parses "auto", "cpu" or "opencl" into *out. Errors: LX_EINVAL (another text; the message names it). */
LX_API lx_status lx_backend_parse(lx_ctx *ctx, const char *text, lx_backend *out);

/** The backend named by the environment variable LX_BACKEND, or LX_BACKEND_AUTO when unset/invalid.
 * Reads the environment on every call. Thread-safe. */
LX_API lx_backend lx_backend_from_env(void);

/** The backend (LX_BACKEND_CPU or LX_BACKEND_OPENCL) that did the work of the last successful call on
 * this context that chooses one: lx_batch_integrate, lx_batch_resample, lx_batch_colorimetry,
 * lx_alphaopic_batch, lx_spectral_exr_read_xyz, lx_grid_illuminance, lx_irradiance_dirs,
 * lx_irradiance_map, lx_spd_uncertainty (where its Monte Carlo trials were drawn) and lx_scene_eval
 * (OPENCL when any of its grid work ran on a device). A failed
 * call leaves it as it was. LX_BACKEND_AUTO before any such call, and for a NULL context. */
LX_API lx_backend lx_ctx_backend_used(const lx_ctx *ctx);

/** The SIMD paths of the CPU code. A path runs only on a CPU with every instruction-set extension
 * its code uses (AVX2: the x86-64-v3 set, AVX2 FMA F16C BMI1 BMI2 LZCNT MOVBE POPCNT; AVX512: the
 * x86-64-v4 set, adding AVX-512 F CD BW DQ VL). Each SIMD path is a twin of a plain C loop that
 * stays the reference. The environment variable LX_SIMD=scalar|avx2|avx512 caps the path used,
 * in every module alike (it never raises the path above what the CPU has). */
typedef enum lx_simd { LX_SIMD_SCALAR = 0, LX_SIMD_AVX2 = 1, LX_SIMD_AVX512 = 2 } lx_simd;

/** The highest SIMD path this CPU can run, ignoring LX_SIMD. Thread-safe. */
LX_API lx_simd lx_simd_cpu(void);

/** The SIMD path the library uses now: lx_simd_cpu() capped by LX_SIMD (read on every call; an
 * unknown value does not cap). Thread-safe. */
LX_API lx_simd lx_simd_level(void);

/** "scalar", "avx2" or "avx512" (static storage); NULL for a value that is none of them. Thread-safe. */
LX_API const char *lx_simd_name(lx_simd simd);

/** Parses "scalar", "avx2" or "avx512" into *out. Errors: LX_EINVAL (another text; the message names it). */
LX_API lx_status lx_simd_parse(lx_ctx *ctx, const char *text, lx_simd *out);

/** OpenCL device types for the device choice. */
typedef enum lx_cl_type { LX_CL_AUTO = 0, LX_CL_CPU = 1, LX_CL_GPU = 2 } lx_cl_type;

/** Chooses the OpenCL device this context will use, before its first OpenCL work: platform and
 * device indices (negative: any; then the environment LX_PLATFORM / LX_DEVICE apply) and a type
 * (AUTO prefers a GPU, then any device). Releases an OpenCL state the context already holds. Does
 * not initialise OpenCL: indices that name no device fail at the first OpenCL work (LX_EDEVICE).
 * Errors: LX_EINVAL (an unknown type), LX_EUNSUPPORTED (a build without OpenCL). */
LX_API lx_status lx_cl_select(lx_ctx *ctx, int platform, int device, lx_cl_type type);

/** Borrows a caller's OpenCL context and command queue (cl_context and cl_command_queue passed
 * as void*, so this header needs no OpenCL headers). The library retains both (clRetain*) and
 * releases them at lx_ctx_destroy; the caller may release its own references at once. The device
 * is the queue's. Errors: LX_EINVAL (either NULL), LX_EDEVICE (the queue cannot be queried),
 * LX_EUNSUPPORTED (a build without OpenCL). */
LX_API lx_status lx_cl_borrow(lx_ctx *ctx, void *cl_context, void *cl_command_queue);

/** Description of one OpenCL device. A result struct (ABI policy: reserved is written as zero). */
typedef struct lx_cl_device_info {
    int platform, device;           /* indices as LX_PLATFORM / LX_DEVICE count them */
    char platform_name[128];
    char device_name[128];
    char version[64];               /* CL_DEVICE_VERSION */
    int is_gpu, is_cpu;
    unsigned compute_units;
    unsigned long long global_mem_bytes;
    unsigned long long max_alloc_bytes; /* CL_DEVICE_MAX_MEM_ALLOC_SIZE, the chunk limit */
    int fp64;                       /* 1 when cl_khr_fp64 (or OpenCL >= 1.2 double) is available
                                     * and not switched off by LX_CL_FP64=0 */
    int is_default;                 /* 1 for the device the AUTO choice (and environment) picks */
    long long reserved[4];          /* zero: room for later fields */
} lx_cl_device_info;

/** Lists every OpenCL device of every platform into *out, *n of them; free the array with
 * lx_cl_devices_free. No platform is not an error: *n = 0 and *out NULL, also in a build without
 * OpenCL. Does not create an OpenCL context. Errors: only the general ones (NULL arguments,
 * LX_ENOMEM). */
LX_API lx_status lx_cl_devices(lx_ctx *ctx, lx_cl_device_info **out, size_t *n);

/** Frees the array of lx_cl_devices. Accepts NULL. */
LX_API void lx_cl_devices_free(lx_cl_device_info *devices);

/** Initialises OpenCL on ctx if not done yet (device choice, context, queue) and describes the
 * device in use. Errors: LX_EDEVICE (no device can be used; the message names the OpenCL call and
 * code), LX_EUNSUPPORTED (a build without OpenCL). */
LX_API lx_status lx_cl_info(lx_ctx *ctx, lx_cl_device_info *out);

/** 1 when ctx already holds an initialised OpenCL state (start-up already paid), else 0 (also for a
 * NULL context). */
LX_API int lx_cl_ready(const lx_ctx *ctx);

/* ============================================================================================ */
/* 3. Spectra as views; embedded tables: weighting functions, illuminants, test colour samples (src/tables) */
/* ============================================================================================ */

/** A sampled spectrum: a view of n samples at strictly increasing wavelengths. The library
 * treats a spectrum as piecewise linear between samples and zero outside [lambda_nm[0],
 * lambda_nm[n-1]]. The struct does not own its arrays unless a set owns them (see lx_spd_set). */
typedef struct lx_spd {
    const char *name;        /* label: header name, row id, or "1", "2", ... (may be NULL) */
    size_t n;                /* number of samples, >= 2 */
    const double *lambda_nm; /* wavelengths in nm, strictly increasing */
    const double *value;     /* values, unit set by the caller (W/nm, W/m2/nm, relative, ...) */
} lx_spd;

/** Weighting functions embedded from the CIE tables (views valid for the life of the program). */
typedef enum lx_function {
    LX_FN_XBAR_2 = 0, LX_FN_YBAR_2, LX_FN_ZBAR_2,    /* CIE 1931 2 deg, 360-830 nm at 1 nm */
    LX_FN_XBAR_10, LX_FN_YBAR_10, LX_FN_ZBAR_10,     /* CIE 1964 10 deg, 360-830 nm at 1 nm */
    LX_FN_VPRIME,                                    /* CIE 1951 scotopic V'(lambda), 380-780 nm */
    LX_FN_ALPHA_SC, LX_FN_ALPHA_MC, LX_FN_ALPHA_LC,  /* CIE S 026 alpha-opic action spectra, */
    LX_FN_ALPHA_RH, LX_FN_ALPHA_MEL,                 /* 380-780 nm at 1 nm, peak 1 */
    LX_FN_PHOTON_PAR,   /* photons per joule in umol/J (lambda / (h c N_A)), 400-700 nm (ANSI/ASABE S640) */
    LX_FN_PHOTON_EPAR,  /* the same over 400-750 nm (extended PAR) */
    LX_FN_YPF_MCCREE,   /* umol/J times McCree's 1972 relative quantum efficiency, 350-725 nm (1 nm) */
    LX_FN_HAZARD_BLUE,  /* IEC 62471 blue-light hazard B(lambda), 300-700 nm */
    LX_FN_HAZARD_THERMAL, /* IEC 62471 retinal thermal hazard R(lambda), 380-1400 nm */
    LX_FN_HAZARD_ACTINIC, /* IEC 62471 actinic UV hazard S_UV(lambda), 200-400 nm */
    LX_FN_UVA,          /* 1 over 315-400 nm (unweighted UV-A of IEC 62471) */
    LX_FN_COUNT
} lx_function;

/** A view of an embedded weighting function (static storage, never freed). Errors: LX_EINVAL (an
 * unknown id). */
LX_API lx_status lx_function_get(lx_ctx *ctx, lx_function fn, lx_spd *out);

/** A view of a CIE illuminant from the embedded tables by name: "A", "D50", "D55", "D65", "D75",
 * "E", "FL1".."FL12", "FL3.1".."FL3.15", "LED-B1".."LED-V2", "HP1".."HP5" (relative SPDs as
 * published, 5 nm; static storage, never freed). Errors: LX_EINVAL (an unknown name). */
LX_API lx_status lx_illuminant_get(lx_ctx *ctx, const char *name, lx_spd *out);

/** The names of the embedded illuminants, NULL-terminated (static storage). Thread-safe. */
LX_API const char *const *lx_illuminant_names(void);

/** CIE illuminant A by its defining formula (CIE 015:2018 eq. 4.1), relative, any wavelength in nm:
 * 100 at 560 nm. NaN for a wavelength that is not positive. Thread-safe. */
LX_API double lx_illuminant_a(double lambda_nm);

/** Planck's law: spectral radiance of a blackbody in W/(sr m2 nm) at lambda_nm and T_K, with
 * c1L = 1.191042972e-16 W m2/sr and c2 = 1.4388e-2 m K. Stable for 1 K to 1e9 K (no overflow;
 * underflows to 0). Returns NaN when lambda_nm or T_K is not positive and finite. Thread-safe. */
LX_API double lx_planck(double lambda_nm, double T_K);

/** Total radiant exitance of a blackbody, Stefan-Boltzmann sigma T^4 in W/m2 (T_K in K). Thread-safe. */
LX_API double lx_stefan_boltzmann(double T_K);

/** CIE D-series relative SPD for a correlated colour temperature 4000-25000 K (CIE 015:2018
 * 4.1.2; M1, M2 rounded to 3 decimals as the standard prescribes) at n wavelengths lambda_nm into
 * value (n doubles, caller's; 300-830 nm, basis linearly interpolated; 0 outside). Errors: LX_ERANGE
 * (a CCT outside 4000-25000 K), LX_EINVAL (NULL arrays with n > 0). */
LX_API lx_status lx_daylight(lx_ctx *ctx, double cct_K, size_t n, const double *lambda_nm,
                             double *value);

/** Chromaticity x, y (either may be NULL) of CIE daylight at cct_K (CIE 015:2018 eq. 4.7-4.8).
 * Errors: LX_ERANGE (a CCT outside 4000-25000 K). */
LX_API lx_status lx_daylight_xy(lx_ctx *ctx, double cct_K, double *x, double *y);

/** A view of CIE 13.3-1995 test colour sample TCS01..TCS14 (index 1..14): spectral reflectance
 * factor, 360-830 nm at 5 nm, from the embedded table (static storage, never freed). Errors:
 * LX_EINVAL (another index). */
LX_API lx_status lx_tcs_get(lx_ctx *ctx, int index, lx_spd *out);

/* ============================================================================================ */
/* 4. Spectra: reading, integration, colorimetry (src/spectral) */
/* ============================================================================================ */

/** One field of a file's own header as the instrument or its software wrote it (key and value
 * trimmed; value "" when the line has none). An array struct of lx_spd_set (ABI policy: reserved
 * is written as zero). */
typedef struct lx_spd_field {
    char *key;
    char *value;
    long line;
    long long reserved[2]; /* zero: room for later fields */
} lx_spd_field;

/** A data row the reader left out (lx_spd_read_opts.skip_bad_rows): its line and why. An array
 * struct of lx_spd_set (reserved written as zero). */
typedef struct lx_spd_skipped {
    long line;
    char *why;
    long long reserved[2]; /* zero: room for later fields */
} lx_spd_skipped;

/** Spectra read from one file. Owns every array and string it points to; made by lx_spd_read_file
 * or lx_spd_read_mem (and their _opts forms), freed with lx_spd_set_free. The fields after `line`
 * describe what the reader found. */
typedef struct lx_spd_set {
    char *file;    /* the path given to the reader ("-" for standard input) */
    size_t count;  /* number of spectra */
    lx_spd *spd;   /* count spectra */
    long *line;    /* for each spectrum, the line of the file it starts on (rows layout) or its header line */
    const char *format;       /* the layout read: one of lx_spd_formats() (static storage) */
    size_t nfields;           /* the instrument's own header fields, in file order */
    lx_spd_field *fields;
    const char *unit;         /* the values' unit when the file states it or its format fixes it, after
                               * conversion ("W/m2/nm", "W/nm", "W/sr/m2/nm", "W/sr/nm"); NULL: not known */
    double unit_scale;        /* the factor the reader applied to the file's values to reach unit (1e-3 for
                               * mW/m2/nm, 0.01 for uW/cm2/nm); 1 when unit is NULL */
    const char *unit_source;  /* what the unit was taken from ("UPRtek export: mW/m2/nm"; static storage) */
    double wavelength_scale;  /* the factor applied to the file's wavelengths to reach nm (1000 for
                               * micrometres, 0.1 for angstrom), else 1 */
    size_t nskipped;          /* rows left out with skip_bad_rows */
    lx_spd_skipped *skipped;
} lx_spd_set;

/** Options of lx_spd_read_file_opts / lx_spd_read_mem_opts (zero-initialise for the defaults of
 * lx_spd_read_file; ABI policy: reserved stays zero). */
typedef struct lx_spd_read_opts {
    const char *format;          /* NULL or "auto": detected from the content; else a name of lx_spd_formats() */
    long skip_lines;             /* physical lines to ignore at the start (messages still count them) */
    const char *columns;         /* "WL,VALUE[,VALUE...]": header names or 1-based numbers of the columns
                                  * layout's wavelength and value columns; NULL: every column */
    const char *wavelength_unit; /* "nm", "um" (also "µm") or "A" (also "Å"); NULL: from the wavelength
                                  * column's header, else micrometres when every wavelength is below 10 */
    int skip_bad_rows;           /* 1: a malformed data row is left out and recorded in set->skipped
                                  * instead of failing the file (at least 2 good rows must remain) */
    long long reserved[4];       /* zero: room for later options */
} lx_spd_read_opts;

/** The layouts lx_spd_read_file reads, NULL-terminated (static storage): "columns", "rows",
 * "cgats", "oceanview" (OceanView and SpectraSuite), "sekonic", "uprtek" (UPRtek and LI-COR
 * LI-180), "tm27" (IES TM-27 XML), "avantes" (AvaSoft), "spectrawiz" (StellarNet). Thread-safe. */
LX_API const char *const *lx_spd_formats(void);

/** Reads spectra from a text file ("-" is standard input): columns (wavelength in nm, value...) or
 * rows (a header of wavelengths, one spectrum per row), separators , ; tab or spaces, '#' comments,
 * optional header, CRLF, UTF-8 BOM, and CGATS/Argyll spectral files (SPECTRAL_* fields).
 * Unsorted rows are sorted. On success the caller owns *out; free it with lx_spd_set_free. On
 * failure *out is NULL. Errors: LX_EPARSE (malformed data; the message names file and line), LX_EIO
 * (cannot open or read), LX_ENOMEM. */
LX_API lx_status lx_spd_read_file(lx_ctx *ctx, const char *path, lx_spd_set **out);

/** Same as lx_spd_read_file on len bytes of text (need not be NUL-terminated; not kept); name (NULL:
 * "(memory)") is used in messages and copied to set->file. Errors: as lx_spd_read_file, less LX_EIO. */
LX_API lx_status lx_spd_read_mem(lx_ctx *ctx, const char *name, const char *text, size_t len,
                                 lx_spd_set **out);

/** lx_spd_read_file and lx_spd_read_mem with options (opts may be NULL: the defaults). Besides the
 * layouts of lx_spd_read_file they read the exports of spectrometer software (lx_spd_formats,
 * recognised by content, never by file name), keep the file's header fields in set->fields,
 * convert wavelengths to nm and, where the format fixes the values' unit, the values to W-based
 * units (set->unit). Logs at LX_LOG_INFO how the units were found and at LX_LOG_WARN a spectrum
 * with no overlap with 360-830 nm. Errors: as lx_spd_read_file; LX_EINVAL for a bad option (an
 * unknown format or wavelength unit, a column --columns cannot find, negative skip_lines,
 * non-zero reserved). */
LX_API lx_status lx_spd_read_file_opts(lx_ctx *ctx, const char *path, const lx_spd_read_opts *opts,
                                       lx_spd_set **out);
LX_API lx_status lx_spd_read_mem_opts(lx_ctx *ctx, const char *name, const char *text, size_t len,
                                      const lx_spd_read_opts *opts, lx_spd_set **out);

/** The value of header field `key` of a set (exact match, the first one), or NULL (also for a NULL
 * set or key). The string lives as long as the set. Thread-safe. */
LX_API const char *lx_spd_set_field(const lx_spd_set *set, const char *key);

/** The results an instrument wrote into its export beside the spectrum (Sekonic, UPRtek, LI-COR),
 * as its firmware computed them; NaN where the file has no such field. A result struct (ABI
 * policy: reserved is written as zero). */
typedef struct lx_vendor_results {
    double cct_K, duv;
    double illuminance_lx;      /* Sekonic "Illuminance [lx]", UPRtek / LI-COR "LUX" */
    double X, Y, Z, x, y, u_prime, v_prime;
    double cri_ra, cri_r[15];   /* CIE 13.3 Ra, R1..R15 */
    double tm30_rf, tm30_rg;
    double ppfd_umol_m2_s;      /* photosynthetic photon flux density */
    double irradiance_W_m2;     /* UPRtek / LI-COR "IRR" */
    double peak_nm;             /* peak wavelength */
    int count;                  /* how many of the fields above the file holds */
    long long reserved[4];      /* zero: room for later results */
} lx_vendor_results;

/** The instrument's own results from set->fields (by the names each format gives them) into *out;
 * out->count is 0 for formats that carry none. Errors: LX_EINVAL (NULL set or out). */
LX_API lx_status lx_spd_set_vendor(lx_ctx *ctx, const lx_spd_set *set, lx_vendor_results *out);

/** lx_spd_read_file_opts for an open stream (a pipe; not closed) whose first prefix_len bytes at
 * prefix the caller already read from it (prefix may be NULL when none): the rest is read as
 * lx_spd_read_file reads "-", under the spectrum size limit (the prefix counted), binary data
 * refused; name is used in messages and as set->file; opts may be NULL. Errors: those of
 * lx_spd_read_file_opts. */
LX_API lx_status lx_spd_read_stream(lx_ctx *ctx, const char *name, FILE *in, const char *prefix, size_t prefix_len,
                                    const lx_spd_read_opts *opts, lx_spd_set **out);

/** Frees a set. Accepts NULL. */
LX_API void lx_spd_set_free(lx_spd_set *set);

/** Checks a spectrum view: n >= 2, finite values, strictly increasing finite wavelengths. Errors:
 * LX_EINVAL (the message says which sample fails). */
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

/** The method LX_METHOD_AUTO picks for this spectrum (never returns LX_METHOD_AUTO); another method
 * is returned as given. spd must be a valid view (lx_spd_check). Thread-safe. */
LX_API lx_method lx_method_resolve(const lx_spd *spd, lx_method method);

/** Integrates spd * weight over wavelength with the given method into *out, where weight is any
 * sampled function (a colour-matching function, an action spectrum). The result has the unit of
 * spd value x weight x nm. Errors: LX_EINVAL (an invalid view, an unknown method, LX_METHOD_CIE15 on
 * a spectrum that is not uniformly sampled). */
LX_API lx_status lx_spd_integrate(lx_ctx *ctx, const lx_spd *spd, const lx_spd *weight,
                                  lx_method method, double *out);

/** Integral of the spectrum alone over its whole range (the radiant integral, unit of value x nm):
 * the exact integral of the piecewise-linear spectrum (trapezoid rule) whatever the method
 * (validated, otherwise unused). Errors: LX_EINVAL (an invalid view or method). */
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
    long long reserved[4];    /* zero: room for later results (ABI policy) */
} lx_colorimetry;

/** Computes every quantity of lx_colorimetry for one spectrum (values in W/nm give lm, W/m2/nm lx,
 * W/(sr m2 nm) cd/m2). A spectrum with zero luminous content gives X = Y = Z = 0 and NaN
 * chromaticities (not an error; lx_colorimetry_check reports it); a CCT out of range is
 * cct_valid = 0, not an error. Values near the top of the double range are integrated scaled (a
 * spectrum at 1e300 computes). Errors: LX_EINVAL (an invalid view, observer or method), LX_ERANGE
 * "integral overflows: values up to M ..." when a result itself leaves the double range. */
LX_API lx_status lx_spd_colorimetry(lx_ctx *ctx, const lx_spd *spd, lx_observer observer,
                                    lx_method method, lx_colorimetry *out);

/** The derived quantities of lx_colorimetry from the integrals of a spectrum: xyz[k] = integral
 * of S times xbar, ybar, zbar (without Km), vprime = integral of S V', radiant = integral of S.
 * out->method is kept as given (set it before the call); every other field is written. For batch
 * paths that integrate many spectra at once (lx_batch_integrate) and need every other column.
 * Errors: LX_EINVAL (an unknown observer, NULL xyz or out). */
LX_API lx_status lx_colorimetry_from_integrals(lx_ctx *ctx, lx_observer observer, const double xyz[3],
                                               double vprime, double radiant, lx_colorimetry *out);

/** Checks a result before it is reported: LX_ERANGE when an integral left the double range
 * ("integral overflows: values up to M give X beyond the double range"; max_abs, the largest
 * |value| of the spectrum, or NaN when unknown) or when a quantity that is always defined is
 * NaN or infinite ("x is undefined (NaN): X + Y + Z = 0 (no luminous content)"); the message
 * names the quantity. cct_K and duv are not checked (NaN there means no CCT, cct_valid = 0). */
LX_API lx_status lx_colorimetry_check(lx_ctx *ctx, const lx_colorimetry *r, double max_abs);

/** Dominant wavelength and purity (CIE 015:2018 section 9.1) of a chromaticity x, y against the
 * white xw, yw (the achromatic stimulus: for light sources usually illuminant E, 1/3, 1/3; for
 * surface colours the illuminant). Results only: the library writes it whole (ABI policy). */
typedef struct lx_dominant {
    double wavelength_nm;       /* the dominant wavelength: where the ray from the white through the colour
                                 * meets the spectral locus (linear between its 1 nm points; the shortest
                                 * wavelength where the locus folds back beyond 700 nm); for a purple (the
                                 * ray meets the purple line) the complementary wavelength, negative
                                 * ("-509": lambda_c = 509 nm), as colour-science writes it; NaN at the white */
    int purple;                 /* 1: complementary wavelength */
    int outside;                /* 1: the colour lies beyond the locus (excitation purity > 1) */
    double locus_x, locus_y;    /* where the ray meets the locus or the purple line */
    double excitation_purity;   /* pe = (y - yw) / (yd - yw) (or with x, whichever difference is larger):
                                 * 0 at the white, 1 on the locus */
    double colorimetric_purity; /* pc = pe yd / y (eq. 9.2; yd the point on the purple line for purples) */
    long long reserved[4];      /* zero: room for later results (ABI policy) */
} lx_dominant;

/** Dominant (or complementary) wavelength and excitation and colorimetric purity of (x, y) against
 * (xw, yw) on the spectral locus of observer obs (360-830 nm at 1 nm) closed by the purple line.
 * Errors: LX_EINVAL (a bad observer, a value not finite, a white point outside the locus). Pure
 * apart from the context's error; thread-safe. */
LX_API lx_status lx_dominant_wavelength(lx_ctx *ctx, lx_observer obs, double x, double y, double xw, double yw,
                                        lx_dominant *out);

/** The shape of a spectrum (the piecewise-linear function through its samples). A result. */
typedef struct lx_spd_shape {
    double peak_nm;             /* the wavelength of the largest value (the first of equal ones) */
    double peak_value;          /* that value, in the spectrum's unit */
    double half_lo_nm, half_hi_nm; /* the nearest crossings of half the peak value below and above it */
    double fwhm_nm;             /* full width at half maximum: half_hi_nm - half_lo_nm; NaN when the spectrum
                                 * does not fall to half the peak on one side within its data */
    double noise;               /* the median |second difference| of the values over their range: 0 for a
                                 * constant, about 0.25 for white noise (a dark frame, a detector's raw
                                 * counts), under 0.02 for a lamp measured at 1-5 nm steps */
    long long reserved[4];      /* zero: room for later results (ABI policy) */
} lx_spd_shape;

/** Peak wavelength, FWHM and the noise measure of spd. Errors: those of lx_spd_check; LX_ERANGE
 * when no value is positive (no peak); LX_ENOMEM. */
LX_API lx_status lx_spd_shape_compute(lx_ctx *ctx, const lx_spd *spd, lx_spd_shape *out);

/* ============================================================================================ */
/* 5. Correlated colour temperature; LED binning (src/spectral) */
/* ============================================================================================ */

/** CCT (K) and Duv from CIE 1960 (u, v), solved exactly on the Planckian locus computed with the
 * observer's colour-matching functions (360-830 nm, 1 nm) and c2 = 1.4388e-2 m K; the locus tables
 * are built on first use and cached on ctx. Searches 500 K to 1e6 K. cct_K and duv may be NULL;
 * both are set to NaN on failure. Errors: LX_ERANGE (u or v not finite, or the nearest locus point
 * outside that range), LX_EINVAL (an unknown observer). */
LX_API lx_status lx_cct_from_uv(lx_ctx *ctx, lx_observer observer, double u, double v,
                                double *cct_K, double *duv);

/** The same from CIE 1931 x, y. Errors: as lx_cct_from_uv (LX_ERANGE also where x, y has no uv). */
LX_API lx_status lx_cct_from_xy(lx_ctx *ctx, lx_observer observer, double x, double y,
                                double *cct_K, double *duv);

/** CCT and Duv of n chromaticities (CIE 1960 u[i], v[i]) at once, fast: the Planckian locus
 * precomputed once per process (513 nodes in ln T, 900 K - 120000 K, quintic Hermite with exact
 * derivatives), the nearest point found by bisection and Newton steps, no exp (about 0.1 us a point).
 * Agrees with lx_cct_from_uv to rounding (tests/test_cct_fast.c: |dT| < 1e-10 relative, |dDuv| <
 * 1e-12); a point whose nearest locus point is outside the table or more than 0.09 from the locus
 * is solved by lx_cct_from_uv. Where lx_cct_from_uv has no answer (LX_ERANGE) cct_K[i] and duv[i]
 * are NaN; that is not an error. Errors: LX_EINVAL (a NULL context, an unknown observer, NULL
 * arrays with n > 0). */
LX_API lx_status lx_cct_from_uv_batch(lx_ctx *ctx, lx_observer observer, size_t n, const double *u,
                                      const double *v, double *cct_K, double *duv);

/** CIE 1960 u, v (either may be NULL) of the Planckian radiator at T_K with the observer's CMFs.
 * Errors: LX_EINVAL (an unknown observer, T_K not positive and finite). */
LX_API lx_status lx_planck_uv(lx_ctx *ctx, lx_observer observer, double T_K, double *u, double *v);

/* ---- LED binning: ANSI C78.377-2017 and MacAdam steps ---- */

/** Where a white light's chromaticity falls (CIE 1931 2 deg). A result struct (ABI policy: reserved
 * is written as zero). */
typedef struct lx_binning {
    int ansi_K;             /* nominal CCT (2200 ... 6500 K) of the ANSI C78.377-2017 category holding the
                             * point (|CCT - target| <= CCT tolerance and |Duv - target Duv| <= 0.006); 0: none */
    double ansi_duv_offset; /* Duv minus that category's target Duv (NaN when none) */
    int flex_K;             /* the flexible-CCT rule of C78.377 (2700-6500 K in 100 K steps, targets and
                             * tolerances from its formulas): the nearest nominal CCT holding the point; 0: none */
    double flex_duv_offset; /* Duv minus the target Duv of flex_K (NaN when none) */
    double sdcm;            /* MacAdam steps (standard deviations of colour matching) to the nearest
                             * IEC 60081 colour centre (NaN for a NaN chromaticity) */
    int sdcm_centre_K;      /* that centre: 6500, 5000, 4000, 3500, 3000 or 2700 (IEC 60081 F6500 ... F2700) */
    long long reserved[4];  /* zero: room for later results */
} lx_binning;

/** Bins one chromaticity: x, y (CIE 1931) with its CCT and Duv (lx_cct_from_xy, 2 deg; NaN CCT or
 * Duv: no ANSI category) into *out. Tables: src/data/ansi_c78377_categories.csv and
 * iec60081_sdcm_centres.csv. Errors: LX_EINVAL (NULL out). */
LX_API lx_status lx_binning_compute(lx_ctx *ctx, double x, double y, double cct_K, double duv, lx_binning *out);

/* ============================================================================================ */
/* 6. Batches: many spectra on one grid, CSV files end to end (src/spectral) */
/* ============================================================================================ */

/** Element type of batch values. */
typedef enum lx_dtype { LX_F32 = 0, LX_F64 = 1 } lx_dtype;

/** N spectra sampled on one uniform grid start_nm + j * step_nm, j < n_lambda, row-major:
 * spectrum i starts at element i * row_stride (row_stride 0 means n_lambda). A view: it does not
 * own values. */
typedef struct lx_batch {
    size_t n_spectra;
    size_t n_lambda;       /* >= 1 */
    size_t row_stride;     /* elements between spectra, 0 = n_lambda */
    double start_nm, step_nm; /* step_nm > 0 */
    lx_dtype dtype;
    const void *values;    /* float or double, n_spectra rows */
} lx_batch;

/** Options of the batch calls (zero-initialise for defaults; ABI policy: reserved stays zero). The
 * backend that did the work is lx_ctx_backend_used(ctx) afterwards. */
typedef struct lx_batch_opts {
    lx_backend backend;    /* AUTO (default) also reads LX_BACKEND */
    int threads;           /* CPU threads; 0 = every online core */
    size_t chunk_spectra;  /* OpenCL: spectra per chunk; 0 = from CL_DEVICE_MAX_MEM_ALLOC_SIZE */
    long long reserved[4]; /* zero: room for later options */
} lx_batch_opts;

/** Integrates N spectra against K weighting functions at once with the cie15 rule:
 * out[i*k + f] = sum_j value[i][j] * w_f(start_nm + j*step_nm) * step_nm, the weights linearly
 * interpolated from their tables and zero outside them (no Km factor; unit of value x nm). out:
 * n_spectra x k doubles, the caller's. Accumulates in double on both backends (1e-9 relative CPU vs
 * OpenCL for double input, 1e-6 for float). opts may be NULL. A fall-back from OpenCL to the CPU in
 * AUTO is reported through the log callback (LX_LOG_INFO). Errors: LX_EINVAL (an invalid grid,
 * dtype, function id or option), LX_EUNSUPPORTED (OPENCL asked of a build without OpenCL, or double
 * input on a device without fp64), LX_EDEVICE (an OpenCL failure when OPENCL was asked). */
LX_API lx_status lx_batch_integrate(lx_ctx *ctx, const lx_batch *batch, const lx_function *fns, size_t k,
                                    const lx_batch_opts *opts, double *out);

/** A batch read from a rows-layout CSV: one spectrum per line on the header's uniform grid. Made by
 * lx_batch_table_read(_mem), freed with lx_batch_table_free. */
typedef struct lx_batch_table {
    lx_batch batch;  /* owns batch.values */
    char *names;     /* the rows' first cells, NUL-separated ("" when the file has no name column) */
    size_t *name_at; /* batch.n_spectra offsets into names */
} lx_batch_table;

/** Reads a rows-layout batch CSV ("id,380,381,...,780" then "name,v1,v2,..." per line; separators
 * , ; or tab; '#' comment and blank lines skipped; CRLF; BOM) into a float or double batch, in
 * parallel on `threads` threads (0 = every core). "-" is standard input. The caller owns *out; free
 * it with lx_batch_table_free (*out is NULL on failure). Errors: LX_EPARSE (naming file and line),
 * LX_EUNSUPPORTED (the header's wavelengths are not a uniform grid: use lx_spd_read_file), LX_EIO,
 * LX_EINVAL (an unknown dtype). lx_batch_table_read_mem reads len bytes of text (not kept), file
 * naming it in messages. lx_batch_table_free accepts NULL. */
LX_API lx_status lx_batch_table_read(lx_ctx *ctx, const char *path, lx_dtype dtype, int threads,
                                     lx_batch_table **out);
LX_API lx_status lx_batch_table_read_mem(lx_ctx *ctx, const char *file, const char *text, size_t len,
                                         lx_dtype dtype, int threads, lx_batch_table **out);
LX_API void lx_batch_table_free(lx_batch_table *t);

/** Called by lx_batch_table_stream for each chunk of consecutive rows, in file order, on the
 * caller's thread: chunk (owned by the stream, valid only during the call; its names as in
 * lx_batch_table) holds rows row0 .. row0 + chunk->batch.n_spectra - 1 of the file. A non-LX_OK
 * return stops the stream and is returned by it. */
typedef lx_status (*lx_batch_chunk_fn)(void *user, const lx_batch_table *chunk, size_t row0);

/** Reads a rows-layout batch CSV (as lx_batch_table_read; the file is memory-mapped) chunk by
 * chunk: `threads` threads (0 = every core) parse the next chunk while fn handles this one, so
 * memory stays bounded (a few MB of text per thread) and the work overlaps. On LX_EPARSE (file
 * and line of the first bad row in ctx) fn has been called for some, possibly none, of the rows
 * before the bad one: callers that must not act on a bad file keep what fn gives until success.
 * Errors: those of lx_batch_table_read, and fn's own status. */
LX_API lx_status lx_batch_table_stream(lx_ctx *ctx, const char *path, lx_dtype dtype, int threads,
                                       lx_batch_chunk_fn fn, void *user);

/** The callbacks of lx_batch_table_stream_ex (zero-initialise, then set emit at least; ABI policy:
 * reserved stays zero). */
typedef struct lx_batch_stream {
    void *user;
    /* Optional, on the parsing threads: called for each part of the file (consecutive rows, about
     * 512 KB of text) as soon as it is parsed, several at once, in no particular order. thread
     * (0 .. threads - 1, below 64) is the calling thread's index, for per-thread state (a context
     * each: contexts are one thread's); *state is the part's own pointer, kept from one part to the
     * next that takes its place (for buffers). A non-LX_OK return stops the stream when the part
     * comes to be emitted, and is returned by it (ctx holds no message for it). */
    lx_status (*work)(void *user, int thread, const lx_batch_table *part, void **state);
    /* Required, on the caller's thread, every part in file order after its work: rows row0 ..
     * row0 + part->batch.n_spectra - 1; state as work left it. A non-LX_OK return stops the stream. */
    lx_status (*emit)(void *user, const lx_batch_table *part, size_t row0, void *state);
    /* Optional: frees a part's state at the end of the stream. */
    void (*release)(void *user, void *state);
    /* Optional, on the caller's thread after each emitted part: bytes of the input consumed so far
     * and the input's size (0 when unknown: a pipe). */
    void (*progress)(void *user, unsigned long long done_bytes, unsigned long long total_bytes);
    /* Optional: read this open stream instead of opening path (path then names it in messages),
     * after the prefix_len bytes at prefix that the caller already read from it (the start of a
     * pipe it looked at). Not closed. */
    FILE *input;
    const char *prefix;
    size_t prefix_len;
    long long reserved[4]; /* zero: room for later options (ABI policy) */
} lx_batch_stream;

/** lx_batch_table_stream with work on the parsing threads: each part is parsed and handed to
 * cb->work on the thread that parsed it while it is in cache, and the results come to cb->emit
 * in file order, so the per-part work (colorimetry, formatting) runs on every core and overlaps
 * the parsing. Memory stays bounded whatever the file's size: a regular file is memory-mapped and
 * the pages already read are unmapped behind the reader; a pipe or standard input is read into
 * two alternating buffers of a few MB, without the size limit of whole files (a line longer than
 * that grows them, up to the 4 MB a batch line may hold). Errors as lx_batch_table_stream, and
 * LX_EINVAL for a NULL context, path, cb or cb->emit, or non-zero reserved. */
LX_API lx_status lx_batch_table_stream_ex(lx_ctx *ctx, const char *path, lx_dtype dtype, int threads,
                                          const lx_batch_stream *cb);

/** CSV end to end: streams a rows-layout batch CSV (lx_batch_table_stream, double values) and
 * integrates each chunk as lx_batch_integrate on the CPU while the next one parses. *out gets
 * n_spectra x k results, row-major, in file order; the caller owns it and frees it with
 * lx_batch_results_free (*out is NULL on failure). Errors: those of lx_batch_table_read and
 * lx_batch_integrate. */
LX_API lx_status lx_batch_table_integrate_file(lx_ctx *ctx, const char *path, const lx_function *fns, size_t k,
                                               int threads, double **out, size_t *n_spectra);

/** Frees the results of lx_batch_table_integrate_file. Accepts NULL. */
LX_API void lx_batch_results_free(double *results);

/** Resamples N spectra given on their own strictly increasing wavelengths (row i: n_in[i]
 * samples at lambda_nm + offset[i], values at value + offset[i]) onto the uniform grid of dst
 * (dst->values must point to the caller's writable memory of dst->dtype, n_spectra rows; dst->n_spectra
 * is set) by linear interpolation, zero outside each spectrum: the piecewise-linear model the exact
 * method uses. opts (may be NULL) as in lx_batch_integrate (OpenCL: the resample kernel). Errors:
 * LX_EINVAL (an invalid grid, wavelengths not increasing), LX_EUNSUPPORTED and LX_EDEVICE as for
 * lx_batch_integrate (the kernel needs fp64). */
LX_API lx_status lx_batch_resample(lx_ctx *ctx, size_t n_spectra, const double *lambda_nm, const double *value,
                                   const size_t *offset, const size_t *n_in, lx_batch *dst,
                                   const lx_batch_opts *opts);

/** Colorimetry of every spectrum of a batch (N spectra on one uniform grid, lx_batch)
 * with the cie15 rule: the integrals by lx_batch_integrate on opts->backend, the derived
 * quantities (CCT and Duv solved per spectrum) on opts->threads threads. out: n_spectra entries,
 * the caller's. Agrees with lx_spd_colorimetry (method cie15) to 1e-9 relative. opts may be NULL.
 * Errors: those of lx_batch_integrate; LX_EINVAL (an unknown observer, n_lambda < 2). */
LX_API lx_status lx_batch_colorimetry(lx_ctx *ctx, const lx_batch *batch, lx_observer observer,
                                      const lx_batch_opts *opts, lx_colorimetry *out);

/** Bins every spectrum of a batch (lx_binning_compute, section 5) into out (n_spectra entries):
 * X, Y, Z by lx_batch_integrate (cie15 rule), CCT and Duv from the cubic Hermite interpolant of the
 * Planckian locus table that lx_cct_from_uv starts from, without its exact solve (within 0.02 K and
 * 1e-8 in Duv of it over 1500-10000 K and Duv -0.02..0.02; tests/test_binning.c). A spectrum whose
 * CCT cannot be found gets ansi_K = flex_K = 0. opts may be NULL. Errors: LX_EINVAL (NULL batch or
 * out, a batch grid lx_batch_integrate refuses), those of lx_batch_integrate. */
LX_API lx_status lx_binning_batch(lx_ctx *ctx, const lx_batch *batch, const lx_batch_opts *opts, lx_binning *out);

/* ============================================================================================ */
/* 7. Photobiology: alpha-opic and mesopic quantities, PAR, IEC 62471 hazards, efficacy of a file (src/spectral) */
/* ============================================================================================ */

/** The five CIE S 026 photoreceptors, in the order of every alpha-opic array. */
typedef enum lx_alphaopic_kind {
    LX_AO_SC = 0, /* S-cone opic (cyanopic) */
    LX_AO_MC = 1, /* M-cone opic (chloropic) */
    LX_AO_LC = 2, /* L-cone opic (erythropic) */
    LX_AO_RH = 3, /* rhodopic (rods) */
    LX_AO_MEL = 4 /* melanopic (ipRGC), the headline quantity */
} lx_alphaopic_kind;

/** CIE S 026:2018 alpha-opic quantities of one spectrum. Units follow the spectrum: for
 * W/m2/nm input, irradiance is in W/m2, illuminance and edi in lx (W/sr/m2/nm: W/(sr m2) and
 * cd/m2, i.e. radiance and equivalent daylight luminance; W/nm: W and lm). */
typedef struct lx_alphaopic {
    double irradiance[5]; /* alpha-opic irradiance E_alpha = integral E(l) s_alpha(l) dl */
    double illuminance;   /* E_v = 683.002 lm/W * integral E(l) V(l) dl (2 deg ybar) */
    double elr[5];        /* alpha-opic efficacy of radiation E_alpha / E_v, W/lm (NaN when E_v = 0) */
    double edi[5];        /* alpha-opic equivalent daylight (D65) illuminance E_alpha / K_alpha^D65, lx */
    double der[5];        /* daylight efficacy ratio elr / K_alpha^D65 (NaN when E_v = 0) */
    long long reserved[4]; /* zero: room for later results (ABI policy) */
} lx_alphaopic;

/** K_alpha,v^D65 of CIE S 026:2018 Table 2 in W/lm (melanopic 1.3262e-3); NaN for a bad index.
 * Thread-safe. */
LX_API double lx_alphaopic_d65_efficacy(lx_alphaopic_kind kind);

/** CIE S 026:2018 alpha-opic irradiances, equivalent daylight illuminances and DERs with the
 * integration method of lx_spd_integrate (action spectra 380-780 nm, 1 nm). Errors: LX_EINVAL (an
 * invalid view or method). */
LX_API lx_status lx_alphaopic_compute(lx_ctx *ctx, const lx_spd *spd, lx_method method, lx_alphaopic *out);

/** The same for a batch (cie15 rule, see lx_batch_integrate; OpenCL when opts->backend asks for
 * it or AUTO finds it pays). out (n_spectra x 6 doubles, the caller's) [i*6 + k]: the five
 * alpha-opic irradiances (k = 0..4, order of lx_alphaopic_kind) and the illuminance E_v (k = 5) of
 * spectrum i; EDI = out[k] / lx_alphaopic_d65_efficacy(k). opts may be NULL. Errors: those of
 * lx_batch_integrate. */
LX_API lx_status lx_alphaopic_batch(lx_ctx *ctx, const lx_batch *batch, const lx_batch_opts *opts,
                                    double *out);

/** CIE 191:2010 MES2 mesopic luminance from photopic luminance L_p and scotopic luminance L_s
 * (cd/m2, L_s with K'm = 1699 lm/W as CIE 191 writes V'(555 nm) = 683/1699): solves
 * L_mes = (m L_p + (1 - m) L_s V'0) / (m + (1 - m) V'0), m = 0.7670 + 0.3334 log10(L_mes)
 * clamped to [0, 1], by the standard's iteration from m = 0.5 (bisection if it ever fails to
 * converge). L_p >= 5 cd/m2 gives m = 1, L_mes = L_p. *m_out (may be NULL) receives m.
 * Errors: LX_EINVAL (negative or non-finite input). */
LX_API lx_status lx_mesopic_luminance(lx_ctx *ctx, double photopic_cd_m2, double scotopic_cd_m2,
                                      double *mesopic_cd_m2, double *m_out);

/* ---- plant lighting: PAR (ANSI/ASABE S640) ---- */

/** Photosynthetically active radiation of one spectrum. Units follow the spectrum: W/m2/nm gives
 * umol s-1 m-2 (PPFD), W/nm umol s-1 (PPF), W/sr/m2/nm umol s-1 sr-1 m-2; relative values the same
 * arithmetic. A quantity whose band the spectrum covers less than LX_COVERAGE_MIN of (weighted,
 * see lx_hazard) is NaN ("not covered"). A result struct (ABI policy: reserved written as zero). */
typedef struct lx_par {
    double ppfd;        /* photon flux 400-700 nm (ANSI/ASABE S640 PPFD / PPF) */
    double epar;        /* photon flux 400-750 nm (extended PAR, ePAR) */
    double ypf;         /* yield photon flux: photons weighted by McCree's (1972) relative quantum
                         * efficiency of field-grown plants, 350-725 nm */
    double photon_efficacy_umol_J; /* ppfd / radiant integral of the whole spectrum (umol per J of radiant
                         * energy; per electrical joule only if the radiant power is the input power) */
    long long reserved[4]; /* zero: room for later results */
} lx_par;

/** Below this fraction of a weighting function's integral inside the spectrum's wavelength range
 * a PAR or hazard quantity is "not covered" (NaN), never 0. */
#define LX_COVERAGE_MIN 0.95

/** PAR of one spectrum with the integration method of lx_spd_integrate into *out. Errors:
 * LX_EINVAL (an invalid view or method, NULL out). */
LX_API lx_status lx_par_compute(lx_ctx *ctx, const lx_spd *spd, lx_method method, lx_par *out);

/** The same for a batch (cie15 rule on the batch grid; one lx_batch_integrate of 3 functions) into
 * out (n_spectra entries). opts may be NULL. Errors: LX_EINVAL (NULL batch or out, fewer than 2
 * samples), those of lx_batch_integrate. */
LX_API lx_status lx_par_batch(lx_ctx *ctx, const lx_batch *batch, const lx_batch_opts *opts, lx_par *out);

/** Daily light integral in mol m-2 d-1 of a PPFD (umol s-1 m-2) held for photoperiod_h hours:
 * ppfd * 3600 * h / 1e6. NaN for a negative or non-finite photoperiod. Thread-safe. */
LX_API double lx_par_dli(double ppfd_umol_m2_s, double photoperiod_h);

/* ---- photobiological safety: IEC 62471:2006 / CIE S 009:2002 ---- */

/** The weighted quantities of IEC 62471, in the order of lx_hazard arrays. */
typedef enum lx_hazard_kind {
    LX_HZ_BLUE = 0,    /* blue-light hazard: integral S B(lambda), 300-700 nm (L_B or E_B) */
    LX_HZ_THERMAL = 1, /* retinal thermal: integral S R(lambda), 380-1400 nm (L_R) */
    LX_HZ_ACTINIC = 2, /* actinic UV, skin and eye: integral S S_UV(lambda), 200-400 nm (E_S) */
    LX_HZ_UVA = 3,     /* near UV, eye: integral S over 315-400 nm unweighted (E_UVA) */
    LX_HZ_COUNT = 4
} lx_hazard_kind;

/** IEC 62471 weighted quantities of one spectrum. Units follow the spectrum (W/sr/m2/nm: radiance
 * L in W m-2 sr-1; W/m2/nm: irradiance E in W m-2). coverage[k] is the fraction of the weighting
 * function's integral over its band that lies inside the spectrum's wavelength range; value[k]
 * is NaN ("not covered") when coverage[k] < LX_COVERAGE_MIN. A result struct (ABI policy). */
typedef struct lx_hazard {
    double value[LX_HZ_COUNT];
    double coverage[LX_HZ_COUNT];
    long long reserved[4]; /* zero: room for later results */
} lx_hazard;

/** IEC 62471 weighted quantities of one spectrum (integration method of lx_spd_integrate) into
 * *out. Errors: LX_EINVAL (an invalid view or method, NULL out). */
LX_API lx_status lx_hazard_compute(lx_ctx *ctx, const lx_spd *spd, lx_method method, lx_hazard *out);

/** The same for a batch (cie15 rule; one lx_batch_integrate of 4 functions) into out (n_spectra
 * entries). opts may be NULL. Errors: as lx_par_batch. */
LX_API lx_status lx_hazard_batch(lx_ctx *ctx, const lx_batch *batch, const lx_batch_opts *opts, lx_hazard *out);

/** IEC 62471 risk groups. */
typedef enum lx_risk_group {
    LX_RISK_NONE = -1,  /* not evaluated (not covered, not applicable to the geometry) */
    LX_RISK_EXEMPT = 0,
    LX_RISK_1 = 1,      /* low risk */
    LX_RISK_2 = 2,      /* moderate risk */
    LX_RISK_3 = 3       /* high risk */
} lx_risk_group;

/** The IEC 62471:2006 Table 6.1 limit a criterion was judged by (lx_hazard_risk.limit). */
typedef enum lx_hazard_limit {
    LX_HZ_LIMIT_NONE = 0, /* not judged */
    LX_HZ_LIMIT_L_B,      /* blue-light radiance L_B (sources of 0.011 rad and more) */
    LX_HZ_LIMIT_E_B,      /* blue-light irradiance E_B of a small source (below 0.011 rad) */
    LX_HZ_LIMIT_L_R,      /* retinal thermal radiance L_R, limits C / alpha */
    LX_HZ_LIMIT_E_S,      /* actinic UV irradiance E_S */
    LX_HZ_LIMIT_E_UVA     /* near-UV irradiance E_UVA */
} lx_hazard_limit;

/** The risk group of each criterion and the worst of them (group: LX_RISK_NONE when none could be
 * evaluated; a criterion that is not covered could raise it), the limit each criterion was judged
 * by, and the source's solid angle used to turn irradiance into radiance or back (0: none). A
 * result struct (ABI policy). */
typedef struct lx_hazard_risk {
    lx_risk_group group;
    lx_risk_group criterion[LX_HZ_COUNT];
    lx_hazard_limit limit[LX_HZ_COUNT]; /* LX_HZ_LIMIT_NONE where criterion is LX_RISK_NONE */
    double source_sr;      /* 2 pi (1 - cos(alpha / 2)): the solid angle of a circular source of full
                            * angle alpha, when a limit needed the other quantity; else 0 */
    long long reserved[1]; /* zero: room for later results */
} lx_hazard_risk;

/** Risk groups from the emission limits of IEC 62471:2006 Table 6.1 (continuous-wave lamps;
 * src/data/iec62471_limits.csv) into *out. alpha_rad: the source's angular subtense (full angle,
 * rad), 0 when not known. radiance 1: h holds radiances (W/sr/m2/nm input); blue light by L_B, or,
 * for a small source (0 < alpha < 0.011 rad), by E_B = L_B Omega; retinal thermal L_R when alpha > 0
 * (limits C / alpha, alpha clamped to 0.0017-0.1 rad). radiance 0: irradiances (W/m2/nm): E_S,
 * E_UVA; blue light by E_B (a small source, assumed when alpha is 0), or, for alpha >= 0.011 rad,
 * by L_B = E_B / Omega; L_R = E_R / Omega when alpha > 0. Omega = 2 pi (1 - cos(alpha / 2)): the
 * source's own radiance, not averaged over the standard's measurement field of view (conservative
 * where the field is larger than the source). Errors: LX_EINVAL (NULL h or out, alpha negative or
 * not finite). */
LX_API lx_status lx_hazard_risk_group(lx_ctx *ctx, const lx_hazard *h, int radiance, double alpha_rad,
                                      lx_hazard_risk *out);

/** "exempt", "RG1", "RG2", "RG3", or "" for LX_RISK_NONE (static storage). Thread-safe. */
LX_API const char *lx_risk_group_name(lx_risk_group g);

/** PAR (par), IEC 62471 quantities (hz) and LED binning (bin, as lx_binning_batch) of every spectrum
 * of a batch in one pass over its values: one lx_batch_integrate of all the weighting functions
 * asked for, then the derived values on opts->threads threads. Each output (n_spectra entries)
 * may be NULL, not all three. opts may be NULL. Errors: as lx_par_batch. */
LX_API lx_status lx_lab_batch(lx_ctx *ctx, const lx_batch *batch, const lx_batch_opts *opts, lx_par *par,
                              lx_hazard *hz, lx_binning *bin);

/** The luminous efficacy of radiation (lm/W, 2 deg observer, auto method) of the single
 * spectrum in a file read with lx_spd_read_file (efficacy.c). Errors: those of lx_spd_read_file;
 * LX_EINVAL (the file holds more than one spectrum, or its radiant integral is zero). */
LX_API lx_status lx_efficacy_from_spd_file(lx_ctx *ctx, const char *path, double *ler_lm_per_W);

/* ============================================================================================ */
/* 8. Colour rendering: CIE 13.3 CRI, CIE 224 / TM-30 (src/colour) */
/* ============================================================================================ */

/** CIE 13.3-1995 colour rendering of one spectrum. */
typedef struct lx_cri {
    double ra;          /* general colour rendering index Ra: mean of R1-R8 */
    double r[14];       /* special indices: r[0] = R1 ... r[13] = R14 */
    double cct_K, duv;  /* of the test source: exact solve, CIE 1931 2 deg (lx_cct_from_uv) */
    double ref_cct_K;   /* temperature of the reference illuminant (= cct_K) */
    int ref_daylight;   /* 0: Planckian reference (CCT < 5000 K), 1: CIE daylight (>= 5000 K) */
    double dc;          /* distance test - reference white in CIE 1960 uv (CIE 13.3 "DC") */
    int valid;          /* 1 when dc <= 5.4e-3; else the CIE says Ra is not meaningful */
    double r15;         /* R15 of JIS Z 8726:1990 (test colour sample No. 15, Japanese complexion),
                         * computed as R9-R14 are (taken from the reserved space) */
    long long reserved[3]; /* zero: room for later results (ABI policy) */
} lx_cri;

/** CIE 13.3-1995 colour rendering index: R1-R14 and Ra (and R15 of JIS Z 8726) with the CIE reference illuminant
 * (Planckian below 5000 K, CIE D-series from 5000 K), von Kries adaptation in CIE 1960 UCS and
 * CIE 1964 U*V*W*. Sums at 5 nm over 360-830 nm for data sampled every 5 nm on multiples of
 * 5 nm, else at 1 nm (spectrum and test colour samples interpolated linearly; spectrum zero
 * outside its data). Refuses with LX_ERANGE (the message says why): |Duv| > 0.05, CCT above
 * 25000 K (CIE daylight undefined) or below 500 K, no luminous content, or more than 1 % of the
 * reference's X, Y or Z outside the spectrum's wavelength range (truncated data). Scale-free.
 * Errors: LX_ERANGE (those refusals), LX_EINVAL (an invalid view). */
LX_API lx_status lx_cri_compute(lx_ctx *ctx, const lx_spd *spd, lx_cri *out);

/** CIE 224:2017 / ANSI/IES TM-30-20 colour fidelity and gamut of one spectrum. */
typedef struct lx_tm30 {
    double rf;          /* fidelity index Rf (CIE 224:2017 Rf and TM-30 Rf are the same number) */
    double rg;          /* gamut index Rg (NaN when a hue bin holds no sample) */
    double cct_K, duv;  /* of the test source (2 deg, exact solve) */
    double rf_ces[99];  /* fidelity of each colour evaluation sample CES1-CES99 */
    double rf_hue[16];  /* local fidelity Rf,h1..h16 (hue bins of 22.5 deg, reference hue) */
    double rcs_hue[16]; /* local chroma shift Rcs,h1..h16, in per cent */
    double rhs_hue[16]; /* local hue shift Rhs,h1..h16 (fraction of the bin radius) */
    double ref_ab[16][2], test_ab[16][2]; /* bin averages of a', b' (the colour vector graphic) */
    long long reserved[4]; /* zero: room for later results (ABI policy) */
} lx_tm30;

/** CIE 224:2017 Rf and ANSI/IES TM-30-20 Rf, Rg, per-bin Rf/Rcs/Rhs in CAM02-UCS (CIECAM02:
 * L_A 100 cd/m2, Y_b 20, average surround, D = 1) with the 99 colour evaluation samples over
 * 380-780 nm (5 nm sums for 5 nm data on multiples of 5 nm, else 1 nm), 10 deg observer for
 * the samples, 2 deg for the CCT. Reference: Planckian below 4000 K, CIE daylight above
 * 5000 K, a Y-normalised mix between. Missing data counts as zero (CIE 224). Errors: LX_ERANGE
 * (refusals as for lx_cri_compute), LX_EINVAL (an invalid view). */
LX_API lx_status lx_tm30_compute(lx_ctx *ctx, const lx_spd *spd, lx_tm30 *out);

/* ============================================================================================ */
/* 8b. Measurement uncertainty of every spectral result: GUM and Monte Carlo (src/spectral: the
 *     input models and the engine; src/colour: colour rendering and the entry point) */
/* ============================================================================================ */

/** The kinds of input uncertainty of a measured spectrum S (README "Measurement uncertainty").
 * Each is a zero-mean error of the values; a model adds any number of them, independent of each
 * other. z below is a standard normal deviate. */
typedef enum lx_unc_kind {
    LX_UNC_NOISE = 0,     /* uncorrelated: S_j + u_j z_j, independent at every sample */
    LX_UNC_SCALE = 1,     /* fully correlated: S (1 + sigma z), sigma relative */
    LX_UNC_SHIFT = 2,     /* a wavelength-scale error: S(lambda - sigma z), sigma in nm, the spectrum
                           * interpolated linearly and its end values held beyond its ends */
    LX_UNC_BANDWIDTH = 3, /* a bandwidth error: S + ((b0 + sigma z)^2 - b0^2) / 12 S'' (the second
                           * term of a triangular bandpass of FWHM b, Stearns and Stearns, CIE
                           * 214), sigma and b0 in nm, S'' by divided differences */
    LX_UNC_FOURIER = 4,   /* unknown correlations, Kaerhae et al. 2017 (Metrologia 54 524): S (1 +
                           * sigma sum_{i=0..N} gamma_i f_i(x)), f_0 = 1, f_i = sqrt2 sin(2 pi i x +
                           * phi_i), x = (lambda - first) / (last - first), phi_i uniform, gamma a
                           * random unit vector (normals over their norm); sigma relative */
    LX_UNC_COVARIANCE = 5 /* a full covariance matrix of the values: a multivariate normal */
} lx_unc_kind;

/** One component of an input model (zero-initialise; ABI policy: reserved stays zero). */
typedef struct lx_unc_component {
    lx_unc_kind kind;
    double sigma;          /* SCALE, FOURIER, and NOISE without u: relative standard uncertainty
                            * (0.01 is 1 %); SHIFT, BANDWIDTH: standard uncertainty in nm */
    double bandwidth_nm;   /* BANDWIDTH: the nominal bandpass b0 (0: the mean sample interval) */
    int terms;             /* FOURIER: N, 0 .. 1000 (0: the N in 1 .. 50 with the largest GUM
                            * u(CCT), Kaerhae's unfavourable case; 3 when the CCT is undefined) */
    int relative;          /* NOISE with u, COVARIANCE: 1 when u (cov) is relative to the values
                            * (fractions; cov[i][j] multiplies S_i S_j) */
    int absolute;          /* NOISE without u: 1 when sigma is in the values' unit at every sample */
    size_t n;              /* NOISE with u, COVARIANCE: the samples of u / cov */
    const double *lambda_nm; /* their wavelengths: the spectrum's own, to 1e-6 nm (NULL: taken to
                            * be the spectrum's, n must then equal its sample count) */
    const double *u;       /* NOISE: n standard uncertainties (NULL: sigma at every sample) */
    const double *cov;     /* COVARIANCE: n x n, row-major, symmetric positive semi-definite */
    const char *label;     /* its name in budgets ("fourier=1%"; NULL: the kind's name) */
    long long reserved[4];
} lx_unc_component;

/** An input model: components added one by one, or parsed from text. Made by lx_unc_model_create
 * or lx_unc_model_parse, freed with lx_unc_model_free; read-only once made (several threads may
 * use one). */
typedef struct lx_unc_model lx_unc_model;

/** An empty model in *out. Errors: LX_ENOMEM. */
LX_API lx_status lx_unc_model_create(lx_ctx *ctx, lx_unc_model **out);

/** Adds a component (its arrays and label are copied). Errors: LX_EINVAL (an unknown kind, a sigma
 * that is negative or not finite, u or cov NULL with n > 0, negative or non-finite u, non-zero
 * reserved; the message names the component). Grids and positive semi-definiteness are checked
 * against the spectrum, in lx_spd_uncertainty. */
LX_API lx_status lx_unc_model_add(lx_ctx *ctx, lx_unc_model *m, const lx_unc_component *c);

/** Parses a model from text, terms joined with '+' (README "Measurement uncertainty"):
 *   P%                  uncorrelated, P per cent of each value (NOISE)
 *   noise=P% | noise=V  uncorrelated, relative or V absolute (the values' unit)
 *   column=NAME[:%]     uncorrelated, the standard uncertainties in the spectrum named NAME of set
 *                       (a column of the same file; :% when they are per cent of the values)
 *   file=PATH[:%]       the same from the single spectrum of another file (lx_spd_read_file)
 *   scale=P%            fully correlated (SCALE)
 *   shift=Dnm           wavelength scale (SHIFT)
 *   bandwidth=Dnm[@Bnm] bandwidth, nominal bandpass B (BANDWIDTH)
 *   fourier=P%[:N]      Kaerhae et al. 2017 with N terms (FOURIER)
 *   covariance=PATH[:rel] a full covariance matrix (COVARIANCE): a CSV of n rows of n numbers, or
 *                       a header row of wavelengths and each row led by its wavelength
 * set may be NULL (column= is then refused). Errors: LX_EINVAL (a term that is none of these, a
 * value out of range: the message names the term), those of the file readers (LX_EIO, LX_EPARSE). */
LX_API lx_status lx_unc_model_parse(lx_ctx *ctx, const char *spec, const lx_spd_set *set, lx_unc_model **out);

/** The number of components of m (0 for NULL) and the label of component i (NULL beyond). */
LX_API size_t lx_unc_model_count(const lx_unc_model *m);
LX_API const char *lx_unc_model_label(const lx_unc_model *m, size_t i);

/** 1 when a column= term of m took its values from spd (a member of the set given to
 * lx_unc_model_parse): that spectrum holds uncertainties, not a measurement. */
LX_API int lx_unc_model_uses(const lx_unc_model *m, const lx_spd *spd);

/** Frees a model. Accepts NULL. */
LX_API void lx_unc_model_free(lx_unc_model *m);

/** The quantities with an uncertainty, in the order of lx_unc_result.q. */
typedef enum lx_unc_quantity {
    LX_UQ_X = 0, LX_UQ_Y, LX_UQ_Z,           /* absolute tristimulus values (lx_colorimetry) */
    LX_UQ_CX, LX_UQ_CY,                      /* chromaticity x, y */
    LX_UQ_U_PRIME, LX_UQ_V_PRIME,            /* CIE 1976 u', v' */
    LX_UQ_CCT, LX_UQ_DUV,                    /* K; CIE 1960 uv */
    LX_UQ_LER, LX_UQ_SCOTOPIC_Y, LX_UQ_SP_RATIO, LX_UQ_RADIANT,
    LX_UQ_AO_SC, LX_UQ_AO_MC, LX_UQ_AO_LC, LX_UQ_AO_RH, LX_UQ_AO_MEL,      /* alpha-opic irradiances */
    LX_UQ_EDI_SC, LX_UQ_EDI_MC, LX_UQ_EDI_LC, LX_UQ_EDI_RH, LX_UQ_EDI_MEL, /* equivalent daylight */
    LX_UQ_DER_SC, LX_UQ_DER_MC, LX_UQ_DER_LC, LX_UQ_DER_RH, LX_UQ_DER_MEL, /* daylight efficacy ratios */
    LX_UQ_PPFD, LX_UQ_EPAR, LX_UQ_YPF,       /* lx_par */
    LX_UQ_RA,                                /* CIE 13.3 Ra, then R1 .. R14 */
    LX_UQ_R1, LX_UQ_R2, LX_UQ_R3, LX_UQ_R4, LX_UQ_R5, LX_UQ_R6, LX_UQ_R7, LX_UQ_R8, LX_UQ_R9, LX_UQ_R10,
    LX_UQ_R11, LX_UQ_R12, LX_UQ_R13, LX_UQ_R14,
    LX_UQ_RF, LX_UQ_RG,                      /* CIE 224 / TM-30 */
    LX_UQ_COUNT
} lx_unc_quantity;

/** The quantity's name ("X", "x", "cct_K", "melanopic_edi", "par_ppfd", "cri_r9", "tm30_rf"; the
 * column names of `luxcalc spd`), NULL for another value. Thread-safe. */
LX_API const char *lx_unc_quantity_name(lx_unc_quantity q);

/** Groups of quantities to compute (lx_unc_opts.quantities, OR-ed). */
#define LX_UNC_COLORIMETRY 1u /* X .. radiant */
#define LX_UNC_ALPHAOPIC 2u   /* alpha-opic irradiances, EDI, DER */
#define LX_UNC_PAR 4u         /* PPFD, ePAR, YPF */
#define LX_UNC_CRI 8u         /* Ra, R1 .. R14 */
#define LX_UNC_TM30 16u       /* Rf, Rg */

/** Methods (lx_unc_opts.method). */
typedef enum lx_unc_method {
    LX_UNC_MC = 0,   /* Monte Carlo, JCGM 101 (GUM Supplement 1) */
    LX_UNC_GUM = 1,  /* the law of propagation of uncertainty, JCGM 100, with analytic derivatives
                      * (central differences for CRI and TM-30) */
    LX_UNC_BOTH = 2  /* both, and JCGM 101 section 8's validation of GUM against Monte Carlo */
} lx_unc_method;

/** Options of lx_spd_uncertainty (zero-initialise for defaults; ABI policy: reserved stays zero). */
typedef struct lx_unc_opts {
    lx_unc_method method;
    unsigned quantities;    /* LX_UNC_* groups; 0: LX_UNC_COLORIMETRY */
    lx_observer observer;   /* 0: 2 deg */
    lx_method integration;  /* the integration method of the quantities (lx_spd_colorimetry) */
    size_t trials;          /* Monte Carlo trials (their values may take at most 2 GB: LX_EINVAL beyond);
                             * 0: adaptive (JCGM 101 7.9): sequences of
                             * max(10^4, 100 / (1 - coverage)) trials until the mean, u and the
                             * interval's ends are stable to `digits` significant digits of u */
    int digits;             /* adaptive: significant digits of u (1 or 2; 0: 2) */
    size_t max_trials;      /* adaptive: the most trials (0: as many as 512 MB of values hold, at
                             * most 10^7: 5.1e6 for the 13 colorimetric quantities) */
    double coverage;        /* coverage probability of the intervals (0: 0.95) */
    int shortest;           /* 1: the shortest coverage interval (JCGM 101 7.7.3), else the
                             * probabilistically symmetric one */
    unsigned long long seed; /* the trials are a function of the seed alone (0 is a seed): the same
                             * on every number of threads and on OpenCL */
    lx_backend backend;     /* where the trials are drawn (AUTO: the CPU below the measured
                             * break-even; also LX_BACKEND) */
    int threads;            /* 0: every core */
    long long reserved[4];
} lx_unc_opts;

/** One quantity's result. A result struct (ABI policy: reserved written as zero). */
typedef struct lx_unc_value {
    int defined;        /* 1 when computed: asked for and defined for the measured spectrum */
    double value;       /* the quantity of the measured spectrum (the estimate y = f(x)) */
    double u;           /* standard uncertainty (Monte Carlo's when it ran, else GUM's) */
    double lo, hi;      /* coverage interval at the coverage probability (Monte Carlo's, else y -+ k u) */
    double mc_mean;     /* Monte Carlo: the average of the trials (NaN without) */
    double mc_u, mc_lo, mc_hi; /* Monte Carlo's (NaN without) */
    double gum_u, gum_lo, gum_hi; /* GUM's: u, y - k u, y + k u with k the normal quantile (NaN without) */
    double delta;       /* the numerical tolerance of u: half a unit of its digits-th significant digit */
    int stable;         /* Monte Carlo: 1 when its mean, u and interval ends are stable to delta
                         * (JCGM 101 7.9.4), 0 not (or trials fixed and not checked: -1) */
    int gum_valid;      /* BOTH: 1 when |y - U - lo_mc| and |y + U - hi_mc| are both within delta
                         * (JCGM 101 8.2), 0 when not, -1 not judged (Monte Carlo not stable to
                         * delta: too few trials to serve as the reference) */
    double d_low, d_high; /* those two differences */
    double undefined;   /* the fraction of trials where the quantity had no value (CCT off the locus, a
                         * refused CRI): the statistics are of the others */
    int top[3];         /* GUM budget: the components (model order) contributing most, -1 none */
    double top_u[3];    /* their u_i(y) = sqrt(J C_i J^T) */
    double peak_nm;     /* GUM: the wavelength of the largest sensitivity to the spectrum (NaN) */
    long long reserved[4];
} lx_unc_value;

/** The uncertainty of every quantity of one spectrum (lx_spd_uncertainty; free with
 * lx_unc_result_free). Only the library allocates it (ABI policy: fields are appended). */
typedef struct lx_unc_result {
    size_t nq;            /* LX_UQ_COUNT of the library that made it */
    lx_unc_value *q;      /* nq entries, by lx_unc_quantity */
    lx_unc_method method;
    size_t trials;        /* Monte Carlo trials run (0: none) */
    size_t sequence;      /* adaptive: trials per sequence (JCGM 101 7.9.4's M); 0 fixed */
    int stable;           /* adaptive: 1 when every computed quantity is stable */
    int digits;
    double coverage, k;   /* coverage probability; the GUM coverage factor */
    int fourier_terms;    /* N of the Fourier components (the chosen one for terms 0; 0 none) */
    lx_backend backend;   /* where the trials ran */
    size_t nhistory;      /* adaptive: one entry per sequence: */
    size_t *history_trials; /* the trials after it */
    double *history_ratio;  /* the largest 2 s / delta over the quantities (stable at <= 1) */
    int *history_worst;     /* the quantity it belongs to */
    size_t rank;          /* the rank of the normal part in the integrals' space (the draws per trial) */
    double seconds_mc, seconds_gum; /* wall time of each method */
    double seconds_draw;  /* of seconds_mc, drawing the trials (OpenCL: the device's calls; CPU: the
                           * threads' time in it over their number) */
} lx_unc_result;

/** The measurement uncertainty of the quantities of one spectrum (opts->quantities) under the input
 * model m, by Monte Carlo (JCGM 101), GUM (JCGM 100) or both with JCGM 101's validation, into *out
 * (free with lx_unc_result_free). Every quantity is a function of a few linear integrals of the
 * spectrum (the weights of opts->integration): the trials draw those integrals from the model's
 * distribution (exact for every kind of component; a multivariate normal for the normal linear
 * ones, through the pivoted Cholesky factor of their covariance), not whole spectra. opts may be
 * NULL (Monte Carlo of the colorimetry, adaptive, 95 %). Errors: those of lx_spd_check and of the
 * quantities (LX_ERANGE when no asked quantity is defined), LX_EINVAL (a component that does not
 * fit the spectrum: a grid that is not the spectrum's, a covariance that is not positive
 * semi-definite, naming its smallest eigenvalue), LX_EUNSUPPORTED and LX_EDEVICE as
 * lx_batch_integrate for OpenCL. */
LX_API lx_status lx_spd_uncertainty(lx_ctx *ctx, const lx_spd *spd, const lx_unc_model *m, const lx_unc_opts *opts,
                                    lx_unc_result **out);

/** Frees a result of lx_spd_uncertainty. Accepts NULL. */
LX_API void lx_unc_result_free(lx_unc_result *r);

/* ============================================================================================ */
/* 9. Units and quantities (src/lighting) */
/* ============================================================================================ */

/* Units and quantities (units.c). Values are converted to and from the SI unit of their
 * quantity (lm, W, cd, W/sr, lx, W/m2, cd/m2, W/sr/m2, sr, m, rad, K, lm/W, s, m2). */

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
    LX_Q_TIME,               /* s (also h, and a = 365 d = 8760 h, the year of EN 15193-1) */
    LX_Q_AREA,               /* m2 */
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

/** The unit table (static storage, *count entries, aliases included; count may be NULL). Thread-safe. */
LX_API const lx_unit *lx_units(size_t *count);

/** The quantity's name ("illuminance") and SI unit ("lx"); "" for LX_Q_NONE. Thread-safe. */
LX_API const char *lx_quantity_name(lx_quantity q);
LX_API const char *lx_quantity_si_unit(lx_quantity q);

/** The photometric counterpart of a radiometric quantity and back (W <-> lm, W/sr <-> cd,
 * W/m2 <-> lx, W/sr/m2 <-> cd/m2); LX_Q_NONE for quantities that have none. Thread-safe. */
LX_API lx_quantity lx_quantity_counterpart(lx_quantity q);

/** Finds a unit by name (case-insensitive where that is unambiguous; "cd/m^2", "cd/m²", "nits",
 * "lux" accepted); *out points into the static table. Errors: LX_EPARSE (an unknown name; the
 * message names it). */
LX_API lx_status lx_unit_find(lx_ctx *ctx, const char *name, const lx_unit **out);

/** Parses "1000lm", "2.5 m", "30deg", "46 fc", or a bare number into *si_value (SI unit of its
 * quantity). expect: the quantity wanted (LX_Q_NONE accepts any); a bare number takes
 * bare_unit (a unit name; NULL means the SI unit of expect). *got (may be NULL) receives the
 * quantity parsed. Errors: LX_EPARSE (malformed text, an unknown unit), LX_EINVAL (a unit of
 * another quantity; the message names the unit and both quantities). */
LX_API lx_status lx_quantity_parse(lx_ctx *ctx, const char *text, lx_quantity expect,
                                   const char *bare_unit, double *si_value, lx_quantity *got);

/** Converts value from unit `from` to unit `to` (both names) into *out. Errors: LX_EINVAL (the
 * quantities differ), LX_EPARSE (an unknown name). */
LX_API lx_status lx_unit_convert(lx_ctx *ctx, double value, const char *from, const char *to,
                                 double *out);

/** Writes "VALUE UNIT" with VALUE = si_value expressed in `unit`, printed in the shortest form
 * that reads back exactly, into buf (the caller's, cap bytes, always terminated). Errors: LX_EINVAL
 * (no buffer, or cap too small: buf then holds the text cut short), LX_EPARSE (an unknown unit). */
LX_API lx_status lx_unit_format(lx_ctx *ctx, double si_value, const char *unit, char *buf,
                                size_t cap);

/** Radiometric -> photometric (or back, with to_photometric = 0) with an explicit luminous
 * efficacy of radiation K in lm/W: photometric = K * radiometric. q is the quantity of the
 * input; *out_q (may be NULL) the quantity of the result. There is no default efficacy: the caller
 * must supply one. Errors: LX_EINVAL (K not positive and finite, a q without counterpart). */
LX_API lx_status lx_radiometric_convert(lx_ctx *ctx, double value_si, lx_quantity q,
                                        double efficacy_lm_per_W, double *out_si,
                                        lx_quantity *out_q);

/* ============================================================================================ */
/* 10. Sources, inverse problems and solid angles (src/lighting) */
/* ============================================================================================ */

/* Sources (sources.c). Distances in m, angles in rad, luminance in cd/m2. Errors of every function
 * here: LX_EINVAL for a distance or size that is zero, negative or not finite (never infinity;
 * except the height of a receiver over a disk or rectangle, where 0 is the coplanar limit), a
 * flux, intensity or luminance that is negative or not finite, a NULL output; LX_ERANGE when the
 * result overflows. Receivers facing away get 0 (not an error). */

/** Illuminance (lx) from a point source of intensity I (cd) at distance d, incidence angle a from
 * the receiver normal: E = I cos(a) / d^2; 0 when cos(a) <= 0 (back-facing or grazing). */
LX_API lx_status lx_point_illuminance(lx_ctx *ctx, double intensity_cd, double distance_m,
                                      double incidence_rad, double *illuminance_lx);

/** Intensity (cd) of an isotropic point source of flux F (lm): I = F / (4 pi). */
LX_API lx_status lx_point_intensity(lx_ctx *ctx, double flux_lm, double *intensity_cd);

/** Warn spotlight of flux F and exponent S >= 0 (finite): I(a) = c cos^S(a) for |a| < pi/2,
 * 0 beyond, c = (S+1)/(2 pi) F. *peak_cd = c (may be NULL). Stable for S up to 1e300:
 * cos^S is evaluated as exp(S log1p(-2 sin^2(a/2))); it underflows to 0, never NaN. */
LX_API lx_status lx_warn_intensity(lx_ctx *ctx, double flux_lm, double exponent, double angle_rad,
                                   double *peak_cd, double *intensity_cd);

/** cos^S(a) for |a| <= pi/2, else 0 (the normalised Warn lobe). NaN for S < 0 or NaN input.
 * Thread-safe. */
LX_API double lx_warn_lobe(double exponent, double angle_rad);

/** The flux of a Warn spotlight (flux F, exponent S >= 0) within the cone of half-angle a about
 * its axis (0 to pi): F (1 - cos^(S+1) a) for a < pi/2, F beyond; *fraction the same over F.
 * Either output may be NULL (not both). Accurate for small a and large S (expm1, log1p). Errors:
 * LX_EINVAL (a half-angle outside 0 to pi, a negative exponent or flux, both outputs NULL). */
LX_API lx_status lx_warn_cone_flux(lx_ctx *ctx, double flux_lm, double exponent, double half_angle_rad,
                                   double *cone_flux_lm, double *fraction);

/** Warn exponent whose full beam angle (where I = I_peak / 2) is beam_rad, and back. Errors:
 * LX_EINVAL (a beam angle outside (0, pi), an exponent that is not positive). */
LX_API lx_status lx_warn_exponent_from_beam(lx_ctx *ctx, double beam_rad, double *exponent);
LX_API lx_status lx_warn_beam_from_exponent(lx_ctx *ctx, double exponent, double *beam_rad);

/** Which model an extended source is evaluated with. */
typedef enum lx_model {
    LX_MODEL_AUTO = 0,  /* disk, rect: the closed form (exact whenever one exists); grids and scenes:
                         * the point model where its estimated error meets the tolerance, else the
                         * luminous area integrated (README "Accuracy by default") */
    LX_MODEL_POINT = 1, /* point source at the centre, I(theta) = L A cos(theta) */
    LX_MODEL_EXACT = 2, /* closed-form configuration factor, E = pi L F */
    LX_MODEL_AREA = 3   /* grids: every pair integrated over the luminous opening (to nearfield_tol);
                         * disk, rect: the same as EXACT */
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
    int near_field;              /* 1 when the point model errs by more than 1e-4 relative (the grids'
                                  * default near-field tolerance), or is undefined */
    lx_model model;              /* LX_MODEL_POINT or LX_MODEL_EXACT (what AUTO and AREA give), never AUTO */
    long long reserved[4];       /* zero: room for later results (ABI policy) */
} lx_source_result;

/** Lambertian disk of luminance L and radius R; receiver parallel to it at height h, offset r
 * from the axis. Exact: configuration factor of a parallel differential element to a disk,
 * F = (1/2)[1 - (h^2 + r^2 - R^2) / sqrt((h^2 + r^2 + R^2)^2 - 4 r^2 R^2)], rewritten so no
 * subtraction cancels (see sources.c). Point: E = L pi R^2 h^2 / (h^2 + r^2)^2. AUTO reports the
 * exact value (the point model is beside it). h = 0 is the coplanar limit h -> 0+: pi L on the
 * disk, pi L / 2 on its rim, 0 outside (the point model is then 0, NaN at the centre). Errors: as
 * above, and LX_EINVAL for an unknown model or an offset that is not finite. */
LX_API lx_status lx_disk_illuminance(lx_ctx *ctx, double luminance_cd_m2, double radius_m,
                                     double height_m, double offset_m, lx_model model,
                                     lx_source_result *out);

/** Lambertian rectangle width a (along x) x length b (along y) of luminance L; receiver parallel
 * at height h, its foot at (x, y) from the rectangle's centre (a corner is (a/2, b/2)). Exact: the
 * corner configuration factor (Howell's catalogue, case B-3) superposed over four corner
 * rectangles with signs. Point: E = L a b h^2 / (h^2 + x^2 + y^2)^2. AUTO reports the exact value.
 * h = 0 is the coplanar limit: pi L inside, pi L / 2 on an edge, pi L / 4 at a corner, 0 outside.
 * Errors: as above, and LX_EINVAL for an unknown model or x, y not finite. */
LX_API lx_status lx_rect_illuminance(lx_ctx *ctx, double luminance_cd_m2, double width_m,
                                     double length_m, double height_m, double x_m, double y_m,
                                     lx_model model, lx_source_result *out);

/** Luminance (cd/m2) of a Lambertian reflector of reflectance rho (0..1) under illuminance E (lx):
 * rho E / pi. Errors: LX_EINVAL (rho outside [0, 1], E negative or not finite). */
LX_API lx_status lx_lambertian_luminance(lx_ctx *ctx, double reflectance, double illuminance_lx,
                                         double *luminance_cd_m2);

/* Inverse problems (solve.c): a point receiver facing the source at incidence a (rad). Errors of
 * each: LX_EINVAL (a target illuminance, intensity or distance that is not positive and finite, an
 * angle that is not finite, a NULL output), LX_ERANGE (no solution: the receiver gets no light at
 * that incidence or angle, or the answer overflows). */

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

/* Solid angles (solid_angle.c), in sr, into *sr. Errors: LX_EINVAL (a NULL output and the ranges
 * each names). */

/** A cone (spherical cap) of half-angle a in [0, pi] (else LX_EINVAL): 2 pi (1 - cos a) =
 * 4 pi sin^2(a/2). */
LX_API lx_status lx_solid_angle_cap(lx_ctx *ctx, double half_angle_rad, double *sr);

/** A pixel of a width x height lat-long map (row 0 at theta = 0, theta from +z, phi from +x):
 * (2 pi / width) (cos theta0 - cos theta1), computed as a product of sines. LX_EINVAL for sizes
 * below 1 or a row outside the map. */
LX_API lx_status lx_solid_angle_latlong_pixel(lx_ctx *ctx, int width, int height, int row,
                                              double *sr);

/** The rectangle [x0, x1] x [y0, y1] of a plane at distance d, seen from the point whose foot on
 * the plane is the origin: corner terms atan(x y / (d sqrt(x^2 + y^2 + d^2))) with signs. LX_EINVAL
 * for d not positive and finite, bounds not finite or out of order. */
LX_API lx_status lx_solid_angle_rect(lx_ctx *ctx, double x0, double x1, double y0, double y1,
                                     double distance_m, double *sr);

/* ============================================================================================ */
/* 11. Luminaires (IES LM-63, EULUMDAT) and illuminance grids (src/lighting) */
/* ============================================================================================ */

/* Photometric files (ies_read.c, ldt_read.c), the intensity model (photometry.c) and the writer
 * (ies_write.c). Angles in the luminaire's own frame: type C, gamma from the nadir (-z, gamma 0)
 * to the zenith (180), C from +x (C0) towards +y (C90). Type B (floodlights): the B axis (H 0,
 * V 0) is the nadir, H is the angle towards +y (the polar axis), V the rotation about +y from
 * the nadir towards +x; a direction is (cos H sin V, sin H, -cos H cos V). */

/** The file formats read (and the version of an LM-63 file). */
typedef enum lx_lum_format {
    LX_LUM_LM63_1986 = 0, /* no version line */
    LX_LUM_LM63_1991,     /* "IESNA91" */
    LX_LUM_LM63_1995,     /* "IESNA:LM-63-1995" (also the non-standard "IESNA95") */
    LX_LUM_LM63_2002,     /* "IESNA:LM-63-2002" */
    LX_LUM_LM63_2019,     /* "IES:LM-63-2019" */
    LX_LUM_EULUMDAT       /* EULUMDAT .ldt */
} lx_lum_format;

/** Symmetry of the stored data, which the model expands to the full sphere. */
typedef enum lx_lum_symmetry {
    LX_SYM_AXIAL = 0,   /* one plane: rotationally symmetric about the vertical axis */
    LX_SYM_QUADRANT,    /* C0-C90 stored: symmetric about the C0-C180 and C90-C270 planes */
    LX_SYM_C0_C180,     /* C0-C180 stored: symmetric about the C0-C180 plane */
    LX_SYM_C90_C270,    /* C90-C270 stored: symmetric about the C90-C270 plane (C -> 180 - C) */
    LX_SYM_NONE,        /* C0-C360 stored */
    LX_SYM_B_LATERAL    /* type B with H 0..90 stored: symmetric about H = 0 */
} lx_lum_symmetry;

/** Static names: "LM-63-1986" ... "LM-63-2019", "EULUMDAT"; "axial", "quadrant", "C0-C180",
 * "C90-C270", "none", "B-lateral". Thread-safe. */
LX_API const char *lx_lum_format_name(lx_lum_format f);
LX_API const char *lx_lum_symmetry_name(lx_lum_symmetry s);

/** A luminaire read from a file or built from a model; freed with lx_luminaire_free. Owns every
 * array and string (a struct only the library allocates: ABI policy). The "file"
 * arrays hold the table as stored (angles in degrees, candela already scaled); the "full" arrays
 * the table expanded to the whole range of planes (C 0..360 inclusive, or H -90..90) that the
 * model interpolates (zero outside its gamma or V range). Read-only after creation: evaluating
 * it is thread-safe. */
typedef struct lx_luminaire {
    char *file;                /* the path or name given to the reader */
    lx_lum_format format;
    int photometric_type;      /* 1 = C, 2 = B (type A is rejected with LX_EUNSUPPORTED) */
    lx_lum_symmetry symmetry;
    size_t n_h, n_v;           /* stored planes (horizontal angles) and vertical angles */
    double *h_deg, *v_deg;     /* as stored, increasing */
    double *cd;                /* n_h x n_v, cd[h * n_v + v], candela (multiplier etc. applied) */
    size_t n_c, n_g;           /* expanded planes and vertical angles */
    double *c_deg, *g_deg;     /* expanded angles, increasing */
    double *full_cd;           /* n_c x n_g, full_cd[c * n_g + g] */
    int absolute;              /* 1: absolute photometry (IES lumens -1, EULUMDAT lamps < 0) */
    int n_lamps;               /* as stated (absolute value) */
    double lamp_lumens;        /* IES: lamps x lumens per lamp (NaN when absolute); LDT: set 1 flux */
    double stated_lumens;      /* the luminaire's own flux when the file states it
                                * (IES [_ABSOLUTELUMENS]; LDT lamp flux x LORL), else NaN */
    double multiplier;         /* IES candela multiplier; LDT conversion factor x flux / 1000 */
    double ballast_factor;     /* applied to cd (IES); 1 for LDT */
    double ballast_lamp_factor;/* LM-63 <= 1995: applied; 2002: future use, ignored; 2019: NaN */
    int file_generation_type;  /* LM-63-2019 only (the field older versions call ballast-lamp factor), else 0 */
    double input_watts;
    double width_m, length_m, height_m; /* luminous opening as LM-63 and EULUMDAT define it: width
                                * along the C90-C270 plane, length along C0-C180; negative width and
                                * length (IES) mean a circle of that diameter (EULUMDAT width 0 is read so) */
    int tilt_include;          /* 1 when a TILT= table was given (INCLUDE or a file) */
    int tilt_geometry;         /* lamp-to-luminaire geometry 1, 2 or 3 */
    size_t n_tilt;
    double *tilt_deg, *tilt_factor;
    char *manufacturer, *catalog, *description; /* [MANUFAC], [LUMCAT], [LUMINAIRE] (or LDT lines); may be "" */
    char *test, *testlab, *issuedate, *lamp; /* [TEST], [TESTLAB], [ISSUEDATE], [LAMP]; EULUMDAT: the
                                * measurement report number and the date/user line; NULL when absent */
} lx_luminaire;

/** Reads an IES LM-63 file (1986, 1991, 1995, 2002, 2019) or EULUMDAT file ("-" is stdin),
 * detected by content. The caller owns *out and frees it with lx_luminaire_free (*out is NULL on
 * failure). Errors name the file and line: LX_EPARSE (malformed data: counts that do not match,
 * truncated tables, negative candela, angles out of order or incomplete), LX_EUNSUPPORTED (type A
 * photometry), LX_EIO. */
LX_API lx_status lx_luminaire_read_file(lx_ctx *ctx, const char *path, lx_luminaire **out);

/** Same, from len bytes of text (not kept); name (NULL: "(memory)") is used in messages and copied
 * to lum->file. Errors: as lx_luminaire_read_file, less LX_EIO. */
LX_API lx_status lx_luminaire_read_mem(lx_ctx *ctx, const char *name, const char *text, size_t len,
                                       lx_luminaire **out);

/** Frees a luminaire. Accepts NULL. */
LX_API void lx_luminaire_free(lx_luminaire *lum);

/** Interpolation in the intensity table. */
typedef enum lx_interp {
    LX_INTERP_BILINEAR = 0, /* bilinear in (C, gamma) (or (H, V)): the reference model */
    LX_INTERP_SMOOTH = 1,   /* monotone piecewise-cubic (PCHIP) in both angles: no overshoot */
    LX_INTERP_TABLE = 2     /* grids only: bilinear resampled on a table indexed by sqrt(1 - |cos gamma|)
                             * and the diamond angle of C (no acos/atan2; CPU twin of the OpenCL kernel) */
} lx_interp;

/** Intensity in cd towards the unit direction (x, y, z) of the luminaire's frame (nadir -z,
 * C0 +x). LX_INTERP_TABLE is treated as bilinear here. Tilt factors are not applied. Thread-safe;
 * lum must be a valid luminaire (no context, so no error: NaN for a NULL one). */
LX_API double lx_luminaire_intensity_dir(const lx_luminaire *lum, lx_interp interp, double x, double y, double z);

/** Intensity in cd at (C, gamma) in radians (type C), or (H, V) for type B. As above. */
LX_API double lx_luminaire_intensity(const lx_luminaire *lum, lx_interp interp, double c_rad, double gamma_rad);

/** The TILT factor for a lamp tilt of tilt_rad (linear in the table, clamped at its ends); 1
 * without a tilt table. Thread-safe. */
LX_API double lx_luminaire_tilt_factor(const lx_luminaire *lum, double tilt_rad);

/** Summary of a luminaire. */
typedef struct lx_lum_summary {
    double lumens;            /* exact integral over the sphere of the bilinear interpolant, tilt factor at 0 */
    double max_intensity_cd;  /* largest table value */
    double peak_c_deg, peak_gamma_deg; /* where it is (expanded table) */
    double beam_angle_deg;    /* full angle to 50 % of the peak, in the C0-C180 plane through the peak */
    double field_angle_deg;   /* the same to 10 % */
    double beam_angle_c90_deg, field_angle_c90_deg; /* the same in the C90-C270 plane */
    double downward_fraction; /* flux below the horizontal / total (NaN for type B or no flux) */
    long long reserved[4];    /* zero: room for later results (ABI policy) */
} lx_lum_summary;

/** Integrates and summarises. Beam and field angles are NaN when the intensity in the plane does
 * not fall to the fraction (or the peak is not in it). Errors: LX_EINVAL (a luminaire without
 * photometry). */
LX_API lx_status lx_luminaire_summary(lx_ctx *ctx, const lx_luminaire *lum, lx_lum_summary *out);

/** Analytic models the writer can sample. */
typedef enum lx_lum_model_kind {
    LX_LUM_MODEL_POINT = 0,   /* isotropic: I = F / (4 pi) */
    LX_LUM_MODEL_WARN = 1,    /* Warn spot: I = (S + 1) F / (2 pi) cos^S gamma, gamma < 90 deg */
    LX_LUM_MODEL_LAMBERT = 2  /* Lambertian panel: I = (F / pi) cos gamma, gamma < 90 deg */
} lx_lum_model_kind;

/** A model to sample (options: zero-initialise; reserved stays zero). */
typedef struct lx_lum_model {
    lx_lum_model_kind kind;
    double flux_lm;           /* > 0 */
    double exponent;          /* Warn S >= 0 */
    double width_m, length_m; /* luminous opening (0: a point); width along C90-C270, length along C0-C180 */
    double step_deg;          /* gamma step of the table (0: 1 deg for point/Lambert, finer for narrow spots) */
    const char *catalog;      /* [LUMCAT] text (NULL: a description of the model), copied */
    long long reserved[4];    /* zero: room for later options (ABI policy) */
} lx_lum_model;

/** Samples a model into an axially symmetric luminaire (absolute photometry, LM-63-2002). The
 * caller owns *out (free with lx_luminaire_free; NULL on failure). Errors: LX_EINVAL (an unknown
 * kind, a flux that is not positive and finite, a Warn exponent outside 0 to 1e6, a negative
 * opening, a step outside 0.01 to 45 deg, non-zero reserved). */
LX_API lx_status lx_luminaire_from_model(lx_ctx *ctx, const lx_lum_model *model, lx_luminaire **out);

/** Writes lum as IES LM-63-2002 text (type C; the stored planes and symmetry kept; absolute
 * photometry when lum->absolute, else its lamps and lumens) into *text, *len bytes (NUL-terminated
 * besides); the caller owns *text and frees it with lx_text_free. Numbers are printed so they read
 * back exactly. Errors: LX_EUNSUPPORTED (type B photometry), LX_EINVAL (a luminaire without a table). */
LX_API lx_status lx_luminaire_write_ies(lx_ctx *ctx, const lx_luminaire *lum, char **text, size_t *len);

/* Illuminance grids (grid.c, OpenCL twin kernels/grid.cl). World frame in metres. */

/** A luminaire in a scene: its position, where its nadir (gamma 0) points, and the turn of its
 * C0 plane about that axis. With aim (0,0,-1) and rotate 0, C0 is +x and C90 is +y. A view (ABI
 * policy: frozen). */
typedef struct lx_placement {
    const lx_luminaire *lum;  /* not owned */
    double pos_m[3];
    double aim[3];            /* any length > 0 */
    double rotate_rad;
} lx_placement;

/** A plane of points: origin + a u + b v for a = a0, a0 + da, ..., a1 and the same for b. A value
 * (ABI policy: frozen). */
typedef struct lx_plane {
    double origin_m[3];
    double u[3], v[3];        /* unit, orthogonal axes of the plane */
    double a0, a1, b0, b1;    /* extents along u and v in m */
    size_t na, nb;            /* points along each axis (>= 1; 1 puts the point at a0) */
    double normal[3];         /* the receiver normal (unit) */
} lx_plane;

/** Fills a plane for "z=H" / "x=H" / "y=H" (axis 'x', 'y' or 'z') with the area A0:A1,B0:B1
 * along the plane's axes ((x, y), (y, z), (x, z)) and either a spacing (> 0; the count is
 * floor((A1 - A0) / S + 1e-9) + 1, so A1 is included when it lies on the grid) or na x nb points.
 * The normal is the plane's axis pointing to +z, +x or +y. Errors: LX_EINVAL (another axis, bounds
 * not finite or out of order, no spacing and no counts, too many points). */
LX_API lx_status lx_plane_axis(lx_ctx *ctx, char axis, double level_m, double a0, double a1, double b0,
                               double b1, double spacing_m, size_t na, size_t nb, lx_plane *out);

/** The same area as calculation cells, as EN 12464-1 and DIALux lay out a grid: with a spacing,
 * ceil((A1 - A0) / S) cells along A (at least one; each (A1 - A0) / n <= S) and likewise along B,
 * or na x nb cells; one point at the centre of each cell, so the outer points lie half a cell
 * inside the area's edges. The plane's a0 .. b1 are the outer points' coordinates. */
LX_API lx_status lx_plane_cells(lx_ctx *ctx, char axis, double level_m, double a0, double a1, double b0,
                                double b1, double spacing_m, size_t na, size_t nb, lx_plane *out);

/** Options of lx_grid_illuminance (zero-initialise for defaults; ABI policy: reserved stays zero).
 * The backend that did the work is lx_ctx_backend_used(ctx) afterwards. */
typedef struct lx_grid_opts {
    lx_model model;           /* default 0 = AUTO: each pair of a luminaire with a luminous opening
                               * and a point is probed (13 point evaluations over the opening estimate
                               * the point model's error); the point model is kept where the summed
                               * estimates at the point stay within nearfield_tol / 2 of its
                               * illuminance, else the opening is integrated to nearfield_tol (and
                               * where the probes cannot vouch: a beam cut-off or the receiver's
                               * horizon across the opening, or closer than its size). POINT: every
                               * luminaire a point; AREA: every pair integrated. ctx counters
                               * nearfield_probes, nearfield_pairs, nearfield_subdivisions */
    lx_interp interp;         /* default bilinear */
    double maintenance_factor;/* 0 means 1 */
    lx_backend backend;       /* OpenCL runs LX_INTERP_TABLE only; AUTO (also LX_BACKEND) picks it
                               * for table work of >= 1e7 point-luminaires */
    int threads;              /* CPU threads; 0 = every online core */
    int table_n;              /* LX_INTERP_TABLE: rows per hemisphere, 2 to 16384 (0: 1024) */
    int fp32;                 /* OpenCL: 1 computes in float (else double where the device has it) */
    double nearfield_tol;     /* the relative tolerance of each point's illuminance (0: 1e-4; 1e-12
                               * to 0.1): the point model's budget (AUTO) and the convergence of the
                               * Richardson-extrapolated area sums */
    long long reserved[4];    /* zero: room for later options */
} lx_grid_opts;

/** Illuminance in lx at n points (xyz interleaved, m) on receivers with the given unit normals (n
 * normals, or one when shared_normal), summed over m luminaires (borrowed for the call): E = sum
 * I(C, gamma) cos(xi) / d^2 x tilt factor x maintenance factor, into E_lx (n doubles, the
 * caller's). Points behind a receiver's face get 0. opts may be NULL. Errors: LX_EINVAL (a normal
 * that is not a unit vector, a luminaire without photometry or with a non-finite placement, an
 * option out of its range, OPENCL asked for an interpolation other than the table),
 * LX_EUNSUPPORTED (OPENCL asked of a build without OpenCL), LX_EDEVICE (an OpenCL failure when
 * OPENCL was asked). */
LX_API lx_status lx_grid_illuminance(lx_ctx *ctx, const lx_placement *lums, size_t m, const double *points,
                                     size_t n, const double *normals, int shared_normal, const lx_grid_opts *opts,
                                     double *E_lx);

/** The points of a plane (na x nb, a fastest) into *points (xyz, m), *n of them; the caller owns the
 * array and frees it with lx_plane_points_free. Errors: LX_EINVAL (fewer than 1 x 1 points). */
LX_API lx_status lx_plane_points(lx_ctx *ctx, const lx_plane *plane, double **points, size_t *n);

/** Frees the points of lx_plane_points. Accepts NULL. */
LX_API void lx_plane_points_free(double *points);

/** E_avg, E_min, E_max (the unit of the values, lx for illuminance) and U0 = E_min / E_avg (NaN when
 * E_avg is 0) of n values. A result struct (ABI policy: reserved is written as zero). */
typedef struct lx_grid_stats {
    double avg, min, max, u0;
    long long reserved[4]; /* zero: room for later results */
} lx_grid_stats;

/** Fills *out from n >= 1 values (Neumaier-summed average). Errors: LX_EINVAL (no values). */
LX_API lx_status lx_grid_stats_compute(lx_ctx *ctx, const double *E, size_t n, lx_grid_stats *out);

/* Glare (ugr.c): the CIE 117-1995 unified glare rating and the CIE 190:2010 tabular method. */

/** The Guth position index of a source seen at sigma (the angle between the line of sight and the
 * direction to the source) and tau (the angle, about the line of sight, between the vertical of
 * the visual field and the plane through the line of sight and the source: 0 straight above),
 * both in degrees. Above the line of sight (tau <= 90): the Luckiesh-Guth fit CIE 117 gives,
 * ln p = (35.2 - 0.31889 tau - 1.22 exp(-2 tau / 9)) 1e-3 sigma + (21 + 0.26667 tau - 0.002963
 * tau^2) 1e-5 sigma^2; below it (tau > 90): Iwata & Tokura 1997, p = 1 + 0.8 R/D for R/D < 0.6,
 * else 1 + 1.2 R/D, R/D = tan(sigma) (as Radiance evalglare). Thread-safe. */
LX_API double lx_guth_position_index(double sigma_deg, double tau_deg);

/** UGR = 8 log10(0.25 / Lb sum L^2 omega / p^2) over n glare sources (luminance cd/m2, solid angle
 * sr, position index), background luminance Lb > 0 (cd/m2). terms (n values, may be NULL) gets
 * each source's L^2 omega / p^2. *ugr is NaN when the sum is 0 (no glare source). */
LX_API lx_status lx_ugr(lx_ctx *ctx, double background_cd_m2, size_t n, const double *luminance_cd_m2,
                        const double *solid_angle_sr, const double *position_index, double *terms, double *ugr);

/** The luminous area of a luminaire projected towards the unit direction (x, y, z) of its own frame
 * (nadir -z, C0 +x): W L |z| + H (L |x| + W |y|) for a rectangular opening of width W (along C0),
 * length L and height H; pi D^2/4 |z| + D H sqrt(x^2 + y^2) for a circular one (IES: negative
 * width; EULUMDAT: width 0, length the diameter). 0 for a point (no opening). m^2. Thread-safe. */
LX_API double lx_luminaire_projected_area(const lx_luminaire *lum, double x, double y, double z);

/** The CIE 190:2010 UGR table of a luminaire: 19 rooms X x Y (X across the line of sight, 2H..12H),
 * 5 reflectance combinations (ceiling/walls/floor cavity 70/50/20, 70/30/20, 50/50/20, 50/30/20,
 * 30/30/20), viewed crosswise and endwise, uncorrected (the luminaire's own lamp flux). The
 * observer's eye is H = 2 m below the luminaire plane at the middle of a wall; luminaires on a
 * square grid of spacing 0.25 H; those with T/R > 3 or gamma > 85 deg are left out (CIE 117
 * 4.5); Lb from CIE 190 eqs. 7-12 (10-degree zonal fluxes, Tables 4 and 5). L = I / A_p with A_p
 * the projected luminous area (lx_luminaire_projected_area; LX_EINVAL without one). */
typedef struct lx_ugr_table {
    double x_h[19], y_h[19];       /* room sizes in multiples of H */
    double ugr[19][10];            /* [room][0..4 crosswise, 5..9 endwise] per reflectance combination */
    double lamp_flux_lm;           /* the flux the table is for */
    double spacing_h;              /* 0.25 */
    double lb_cd_m2[19][5];        /* the background luminance per room and reflectance combination */
    long long reserved[4];         /* zero: room for later results (ABI policy) */
} lx_ugr_table;
LX_API lx_status lx_ugr_table_compute(lx_ctx *ctx, const lx_luminaire *lum, lx_ugr_table *out);
/** The table as luminaire data sheets print it (CIE 190:2010 Table 2 layout): three lines of
 * reflectances (ceiling, walls, floor cavity) over the ten columns, then one line per room size
 * (X, shown on the first line of its group, then Y, in multiples of H) with the five crosswise and
 * the five endwise values to one decimal ("-" where undefined); ASCII text, lines ending in '\n',
 * at most 79 columns. The caller owns *text and frees it with lx_text_free. Errors: LX_EINVAL
 * (NULL), LX_ENOMEM. Thread-safe. */
LX_API lx_status lx_ugr_table_text(lx_ctx *ctx, const lx_ugr_table *tab, char **text);

/* ============================================================================================ */
/* 12. Environment maps, OpenEXR and irradiance; daylight skies and the sun (src/radiance) */
/* ============================================================================================ */

/* Lat-long (equirectangular) environment maps (envmap.c). Direction convention (CLI.md): +z up,
 * theta from +z, phi from +x towards +y. In a width x height map, pixel (row j, column i) covers
 * theta in [j, j+1] pi/height and phi in [i, i+1] 2 pi/width; row 0 touches theta = 0. The map is
 * read as piecewise constant: each pixel's radiance holds over its whole patch of sphere. The
 * geometry helpers without a context (directions, solid angles, moments) are pure and thread-safe
 * and do not check their arguments: sizes must be >= 1 and rows and columns inside the map. */

/** What the channels of a map measure. */
typedef enum lx_envmap_units {
    LX_ENV_AUTO = 0,      /* reading: LUMINANCE when the file has a whiteLuminance attribute, else RADIANCE */
    LX_ENV_RADIANCE = 1,  /* W/(sr m2) per channel; luminance = lum_per_unit * Y (efficacy, default 179 lm/W) */
    LX_ENV_LUMINANCE = 2  /* relative photometric values: luminance = lum_per_unit * Y in cd/m2 */
} lx_envmap_units;

/** Luminous efficacy that turns the Y combination of W/(sr m2) channels into cd/m2 by default:
 * 179 lm/W, the white efficacy of the Radiance system (equal-energy white over 380-780 nm). */
#define LX_ENV_DEFAULT_EFFICACY 179.0

/** A lat-long map with 1 (Y) or 3 (R, G, B) channels stored as float (as read; all arithmetic on
 * it is double). Owns data. Made by lx_envmap_create(_cube), lx_exr_read(_any), lx_envmap_downsample
 * or lx_irradiance_map, freed with lx_envmap_free (a struct only the library allocates: ABI
 * policy). The caller may write the pixels and the metadata fields of a map it owns. */
typedef struct lx_envmap {
    int width, height;      /* pixels (any sizes >= 1; lat-long maps are usually width = 2 height) */
    int channels;           /* 1 or 3 */
    float *data;            /* row-major, channels interleaved: data[(j * width + i) * channels + c] */
    double y_weights[3];    /* Y = sum y_weights[c] * channel c: the Y row of RGB->XYZ from the
                             * file's chromaticities, else Rec.709/sRGB (0.2126729, 0.7151522,
                             * 0.0721750); {1, 0, 0} for one channel */
    int has_chromaticities; /* 1 when y_weights came from a chromaticities attribute */
    double chroma_xy[8];    /* that attribute (rx ry gx gy bx by wx wy), written back by lx_envmap_write_exr */
    lx_envmap_units units;  /* RADIANCE or LUMINANCE (never AUTO once read) */
    double lum_per_unit;    /* cd/m2 per unit of Y: efficacy (RADIANCE) or whiteLuminance / 1 (LUMINANCE) */
    int layout;             /* lx_envmap_layout: LATLONG (0, what lx_envmap_create makes) or CUBE */
    int irradiance;         /* 1: the values are irradiance E(n) per normal (W/m2 for RADIANCE
                             * units; lum_per_unit x Y is then an illuminance in lx): the maps
                             * lx_irradiance_map makes, kept through lx_exr_write / lx_exr_read
                             * (string attribute luxcalcQuantity = "irradiance"); 0: radiance */
} lx_envmap;

/** Map layouts. A CUBE map is the OpenEXR cube layout: width N, height 6 N, six N x N faces stacked
 * top to bottom in the file order +X, -X, +Y, -Y, +Z, -Z, each oriented as OpenEXR's ImfEnvmap.h
 * draws it. OpenEXR's axes (y up) become luxcalc's (+z up) by the same mapping that its lat-long
 * layout needs to match ours: (x, y, z)_exr -> (-z, x, y), so the file's +Y face is our zenith,
 * its +X face looks towards our +y and its -Z face towards our +x. Texel (r, c) of a face covers
 * the square [2c/N - 1, 2(c+1)/N - 1] x [2r/N - 1, 2(r+1)/N - 1] of the face at unit distance (the
 * texels tile the cube; OpenEXR's direction() samples texel centres at the face edges instead). */
typedef enum lx_envmap_layout {
    LX_ENV_LATLONG = 0,
    LX_ENV_CUBE = 1
} lx_envmap_layout;

/** Creates a zero-filled cube map with faces of size x size texels (width size, height 6 size),
 * channels 1 or 3; free it with lx_envmap_free (*out NULL on failure). Errors: LX_EINVAL (size
 * outside 1 to 16384, other channels). */
LX_API lx_status lx_envmap_create_cube(lx_ctx *ctx, int size, int channels, lx_envmap **out);

/** Unit vector of a cube-map point at fractional map coordinates (row in [0, 6 size), col in
 * [0, size]); texel centres are (r + 0.5, c + 0.5). */
LX_API void lx_envmap_cube_direction(int size, double row, double col, double dir[3]);

/** Exact solid angle of cube texel (row, col) of a face (row 0..size-1; the same on every face):
 * the corner sum of atan(a b / sqrt(1 + a^2 + b^2)) over the texel's square, in sr. */
LX_API double lx_envmap_cube_texel_sr(int size, int row, int col);

/** Exact first moment (integral of omega d omega, Lambert's polygon formula) of the cube texel at
 * map row (0..6 size - 1) and column. */
LX_API void lx_envmap_cube_texel_moment(int size, int row, int col, double m[3]);

/** Exact solid angle of any pixel of a map (lat-long or cube), in sr. */
LX_API double lx_envmap_texel_sr(const lx_envmap *map, int row, int col);

/** Unit vector of the centre of pixel (row, col) of a map (lat-long or cube). */
LX_API void lx_envmap_texel_direction(const lx_envmap *map, int row, int col, double dir[3]);

/** Creates a zero-filled lat-long map (Rec.709 weights, RADIANCE, efficacy 179 lm/W), channels 1
 * or 3; free it with lx_envmap_free (*out NULL on failure). Errors: LX_EINVAL (a size below 1, more
 * than 1e9 pixels, other channels). */
LX_API lx_status lx_envmap_create(lx_ctx *ctx, int width, int height, int channels, lx_envmap **out);

/** Frees a map. Accepts NULL. */
LX_API void lx_envmap_free(lx_envmap *map);

/** Unit vector of the pixel centre of (row j + 0.5, column i + 0.5) as fractional coordinates
 * (row, col): theta = row pi / height, phi = col 2 pi / width. */
LX_API void lx_envmap_direction(int width, int height, double row, double col, double dir[3]);

/** Exact solid angle of a pixel of row j: (2 pi / width)(cos theta0 - cos theta1), in sr. */
LX_API double lx_envmap_pixel_sr(int width, int height, int row);

/** Exact first moment of a pixel, m = integral over the pixel of omega d omega (a vector whose
 * length is slightly below its solid angle): the projected solid angle seen by a normal n that
 * sees the whole pixel is n . m. */
LX_API void lx_envmap_pixel_moment(int width, int height, int row, int col, double m[3]);

/** Luminance Y of a map's channel values (pixel: map->channels floats): sum y_weights[c] v[c] (no
 * lum_per_unit factor). */
LX_API double lx_envmap_y(const lx_envmap *map, const float *pixel);

/** Per-pixel luminance in cd/m2 (lum_per_unit * Y) into out (width * height doubles, the caller's).
 * Errors: only the general ones (a NULL map or out). */
LX_API lx_status lx_envmap_luminance(lx_ctx *ctx, const lx_envmap *map, double *out);

/** Solid-angle-weighted box filter to a width x height map whose sizes divide the input's: each
 * output pixel is sum(L d omega) / sum(d omega) over the input pixels it covers, so the radiant
 * power of every block is kept exactly. *out is a new map (same weights and units) the caller
 * frees with lx_envmap_free. Errors: LX_EINVAL (sizes that do not divide), LX_EUNSUPPORTED (a cube
 * map). */
LX_API lx_status lx_envmap_downsample(lx_ctx *ctx, const lx_envmap *in, int width, int height, lx_envmap **out);

/** Luminance weights (the Y row of the RGB -> XYZ matrix) of RGB primaries and white point given
 * as CIE xy: rx, ry, gx, gy, bx, by, wx, wy. Errors: LX_EINVAL (degenerate or non-finite primaries). */
LX_API lx_status lx_rgb_y_weights(lx_ctx *ctx, const double xy[8], double weights[3]);

/* OpenEXR input and output (exr_io.c, OpenEXRCore). */

/** Reads a lat-long map from an OpenEXR file: scanline or tiled (level 0 of mip/rip maps), half
 * or float channels, any compression OpenEXR supports, channels R,G,B[,A] or Y (or a single
 * channel of any name); A is ignored. The map covers the display window; data-window pixels
 * outside it are dropped and display pixels without data are 0. chromaticities sets y_weights,
 * whiteLuminance makes units LUMINANCE (lum_per_unit = its value). The caller owns *out and frees
 * it with lx_envmap_free (*out NULL on failure). Errors: LX_EUNSUPPORTED (cube maps, deep and
 * multi-part-only-deep files), LX_EPARSE (a malformed file), LX_EIO (an unreadable one). */
LX_API lx_status lx_exr_read(lx_ctx *ctx, const char *path, lx_envmap **out);

/** As lx_exr_read, and also reads cube maps (envmap attribute cube, display window N x 6N):
 * map->layout says which. For callers that handle both layouts. Errors: as lx_exr_read. */
LX_API lx_status lx_exr_read_any(lx_ctx *ctx, const char *path, lx_envmap **out);

/** EXR compressions (the values of the file format). */
typedef enum lx_exr_compression {
    LX_EXR_NONE = 0, LX_EXR_RLE = 1, LX_EXR_ZIPS = 2, LX_EXR_ZIP = 3, LX_EXR_PIZ = 4,
    LX_EXR_PXR24 = 5, LX_EXR_B44 = 6, LX_EXR_B44A = 7, LX_EXR_DWAA = 8, LX_EXR_DWAB = 9
} lx_exr_compression;

/** Options of lx_envmap_write_exr (zero-initialise for defaults: float, ZIP, scanlines; ABI
 * policy: reserved stays zero). */
typedef struct lx_exr_write_opts {
    int half;                       /* 1: half channels (values rounded to nearest half), 0: float */
    int use_compression;            /* 0: ZIP; 1: the compression below */
    lx_exr_compression compression;
    int tile_size;                  /* > 0: a tiled file with square tiles of this size */
    long long reserved[4];          /* zero: room for later options */
} lx_exr_write_opts;

/** Writes a map as an OpenEXR lat-long or cube file (envmap attribute latlong or cube as map->layout
 * says, channels R,G,B or Y, chromaticities when the map has them, whiteLuminance for LUMINANCE
 * maps) atomically: a temporary file renamed into place, an existing file replaced only on success.
 * opts may be NULL. Errors: LX_EINVAL (an unknown compression, non-zero reserved), LX_EIO (the file
 * cannot be written; nothing is left at path). */
LX_API lx_status lx_envmap_write_exr(lx_ctx *ctx, const char *path, const lx_envmap *map, const lx_exr_write_opts *opts);

/* Irradiance from radiance (irradiance*.c): E(n) = integral L(omega) max(0, n . omega) d omega. */

/** Irradiance methods (see README "radiance"). FAST and BRUTE are exact for the piecewise-constant
 * map (every pixel's integral of max(0, n . w) in closed form, the pixels the horizon of n crosses
 * included); SH9 is an approximation. Zero (the options' default, kept for the ABI) is SH9; the CLI
 * defaults to AUTO. */
typedef enum lx_irr_method {
    LX_IRR_SH9 = 0,   /* 9 spherical-harmonic coefficients, exact per-pixel basis integrals; approximate:
                       * rings around small bright sources (3/32 of their power) and can go negative */
    LX_IRR_BRUTE = 1, /* exact, every input pixel for every output (OpenCL or CPU) */
    LX_IRR_FAST = 2,  /* exact, the same integral as BRUTE: per-row prefix sums for the wholly lit
                       * pixels, the crossed ones in closed form: O(rows + crossed pixels) per output */
    LX_IRR_AUTO = 3   /* FAST, unless its estimated cost for the job is above 10 x SH9's (large
                       * output maps): then SH9, and FAST after all when any SH9 value is negative
                       * (ringing: certainly wrong); lx_ctx_irradiance_method says which ran */
} lx_irr_method;

/** SH9 windows applied to bands l = 0, 1, 2. */
typedef enum lx_sh9_window {
    LX_SH9_WINDOW_NONE = 0,  /* (1, 1, 1): Ramamoorthi-Hanrahan; a point source rings below zero */
    LX_SH9_WINDOW_NONNEG = 1 /* (1, 6/7, 32/35): point-source response (3/28)(1 + 2 cos g)^2 >= 0 */
} lx_sh9_window;

/** Options of the irradiance calls (zero-initialise for defaults; ABI policy: reserved stays zero).
 * Where the work ran is lx_ctx_backend_used(ctx) afterwards (BRUTE on a lat-long map may run on
 * OpenCL; every other method runs on the CPU). */
typedef struct lx_irr_opts {
    lx_irr_method method;
    lx_sh9_window window;    /* SH9 only */
    lx_backend backend;      /* BRUTE only: AUTO uses OpenCL when the work is large, CPU otherwise */
    int threads;             /* CPU threads; 0 = every online core */
    long long reserved[4];   /* zero: room for later options */
} lx_irr_opts;

/** The irradiance method that ran in the last successful lx_irradiance_dirs or lx_irradiance_map on
 * this context (LX_IRR_AUTO resolved to FAST or SH9; LX_IRR_AUTO before any), and in
 * *fast_cost_ratio (may be NULL) AUTO's estimate of FAST's cost over SH9's for that job. NULL
 * context: LX_IRR_AUTO and NaN. */
LX_API lx_irr_method lx_ctx_irradiance_method(const lx_ctx *ctx, double *fast_cost_ratio);

/** How concentrated a map's power is: of the integral of its luminance (Y) over the sphere,
 * *fraction is carried by the brightest pixels whose solid angles add up to at most max_sr, and
 * *pixels is how many they are (the basis of SH9's warning: its error reaches 3/32 of a small
 * source's power). A map without light gives 0 and 0. */
LX_API lx_status lx_envmap_concentration(lx_ctx *ctx, const lx_envmap *map, double max_sr, double *fraction,
                                         size_t *pixels);

/** Spherical-harmonic coefficients L_lm of a map (l <= 2, index l^2 + l + m, real orthonormal
 * basis of Ramamoorthi and Hanrahan 2001), per channel, in the map's unit. A value (ABI policy:
 * frozen). */
typedef struct lx_sh9 {
    int channels;
    double c[9][3];
} lx_sh9;

/** Projects a map onto 9 SH coefficients: each pixel's basis integral is exact (closed forms over
 * its theta and phi range), so the projection of the piecewise-constant map is exact. Errors:
 * LX_EINVAL (a map without data). */
LX_API lx_status lx_sh9_project(lx_ctx *ctx, const lx_envmap *map, lx_sh9 *out);

/** E(n) per channel from SH9 coefficients: sum_l w_l A_l L_lm Y_lm(n), A = (pi, 2pi/3, pi/4).
 * n need not be normalised (it is). out has sh->channels values. Errors: LX_EINVAL (n zero or not
 * finite). */
LX_API lx_status lx_sh9_irradiance(lx_ctx *ctx, const lx_sh9 *sh, lx_sh9_window window, const double n[3], double *out);

/** Irradiance for n_dirs normals (3 doubles each) into out (n_dirs * map->channels doubles, the
 * caller's, in the map's unit times sr: W/m2 for RADIANCE maps). opts may be NULL (SH9, the zero
 * value; the CLI passes LX_IRR_AUTO). The method that ran is lx_ctx_irradiance_method(ctx) after
 * the call. Errors: LX_EINVAL (an invalid map, a non-finite pixel, a zero or non-finite normal, an
 * unknown method), LX_EUNSUPPORTED and LX_EDEVICE as for lx_batch_integrate (BRUTE with OPENCL
 * asked). */
LX_API lx_status lx_irradiance_dirs(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs,
                                    const lx_irr_opts *opts, double *out);

/** Irradiance environment map: E at the pixel centre directions of a width x height map in the
 * input's layout (the input's size when both are 0; a cube input needs height = 6 width). *out is a
 * new map with the input's channels, weights and units, which the caller frees with lx_envmap_free
 * (NULL on failure). opts may be NULL (SH9, the zero value; the CLI passes LX_IRR_AUTO). Errors: as
 * lx_irradiance_dirs, and LX_EINVAL for a size that does not fit the layout. */
LX_API lx_status lx_irradiance_map(lx_ctx *ctx, const lx_envmap *map, int width, int height,
                                   const lx_irr_opts *opts, lx_envmap **out);

/* Daylight: the CIE standard general skies, the Perez all-weather sky (sky.c, sky_perez.c), the
 * sun's position (sun.c, NREL SPA) and sky maps (sky_map.c). World directions: +z up, +y north,
 * +x east (the convention of Radiance gensky/gendaylit); solar azimuth is measured from north
 * towards east. Luminance in cd/m2, illuminance in lx, irradiance in W/m2. */

/** Sky models. */
typedef enum lx_sky_model {
    LX_SKY_MODEL_CIE = 0,   /* ISO 15469 / CIE S 011 standard general sky, types 1..15 */
    LX_SKY_MODEL_PEREZ = 1  /* Perez, Seals & Michalsky 1993 all-weather sky */
} lx_sky_model;

/** A sky luminance distribution L(dir) = zenith_cd_m2 * rel(dir) / rel(zenith), zero below the
 * horizon. rel = (1 + a exp(b / cos Z)) * indicatrix(chi): CIE 1 + c (exp(d chi) - exp(d pi/2))
 * + e cos^2 chi; Perez 1 + c exp(d chi) + e cos^2 chi (Z zenith angle of the element, chi its
 * angle from the sun). Plain data: copy freely; evaluating it is thread-safe. A result (ABI policy:
 * reserved is written as zero; lx_scene embeds one). */
typedef struct lx_sky {
    lx_sky_model model;
    int cie_type;               /* 1..15 (CIE), 0 for Perez */
    double a, b, c, d, e;       /* the model's parameters */
    double sun_dir[3];          /* unit vector towards the sun (may be below the horizon for CIE types
                                 * whose indicatrix is uniform: 1, 3, 5) */
    double zenith_cd_m2;        /* Lz */
    double diffuse_horizontal_lx; /* Dv: the horizontal illuminance from the sky (without the sun) */
    double epsilon, delta;      /* Perez: sky clearness and brightness (NaN for CIE) */
    int perez_bin;              /* Perez: clearness bin 1..8 (0 for CIE) */
    double sun_normal_lx;       /* Perez: the direct normal illuminance Evn from the efficacy model (lx);
                                 * CIE: NaN (the sun's illuminance is given separately) */
    long long reserved[4];      /* zero: room for later fields */
} lx_sky;

/** How a CIE sky is scaled: by its zenith luminance (cd/m2) or by its diffuse horizontal
 * illuminance Dv (lx). */
typedef enum lx_sky_scale { LX_SKY_BY_ZENITH = 0, LX_SKY_BY_HORIZONTAL = 1 } lx_sky_scale;

/** A CIE standard general sky of type 1..15 with the sun towards sun_dir (any length > 0), scaled
 * to value (zenith luminance or horizontal illuminance, > 0). Dv is the exact integral of the
 * distribution (adaptive quadrature to 1e-12 relative). LX_EINVAL for a bad type, value or a sun
 * below the horizon on a type whose indicatrix is not uniform. */
LX_API lx_status lx_sky_cie(lx_ctx *ctx, int type, const double sun_dir[3], lx_sky_scale scale, double value,
                            lx_sky *out);

/** The parameters (a, b, c, d, e) of CIE type 1..15 from the embedded table (src/data). */
LX_API lx_status lx_sky_cie_params(lx_ctx *ctx, int type, double params[5]);

/** Inputs of the Perez sky: the sun and the measured irradiance, as gendaylit -W takes them (options:
 * zero-initialise, reserved stays zero). */
typedef struct lx_perez_input {
    double sun_dir[3];           /* towards the sun, above the horizon */
    double direct_normal_W_m2;   /* DNI, >= 0 */
    double diffuse_horizontal_W_m2; /* DHI, > 0 */
    int day_of_year;             /* 1..366 (the extraterrestrial irradiance's eccentricity factor) */
    double precipitable_water_cm;/* atmospheric precipitable water for the efficacy models (0: 2 cm, gendaylit's default) */
    long long reserved[4];       /* zero: room for later inputs */
} lx_perez_input;

/** The Perez all-weather sky for the given irradiance: sky clearness epsilon and brightness Delta
 * (Perez 1990: Kasten air mass, solar constant 1367 W/m2), the coefficients of its clearness bin
 * (Perez 1993, gendaylit's adjustments: Delta >= 0.2 for 1.065 < epsilon < 2.8), the diffuse
 * horizontal and direct normal illuminance from the Perez 1990 efficacy models, and the
 * distribution scaled so its horizontal illuminance is that diffuse illuminance (exact quadrature;
 * gendaylit uses a 145-point sum instead). epsilon is clamped to at most 12 (gendaylit's range);
 * Delta is clamped to 0.01..0.6 (gendaylit's range) and the luminance to >= 0. LX_EINVAL for a sun at or
 * below the horizon or bad irradiance. */
LX_API lx_status lx_sky_perez(lx_ctx *ctx, const lx_perez_input *in, lx_sky *out);

/** Luminance (cd/m2) of the sky towards dir (any length > 0); 0 below the horizon. Thread-safe. */
LX_API double lx_sky_luminance(const lx_sky *sky, const double dir[3]);

/** Illuminance (lx) from the sky alone (no sun, no ground) on a plane with normal n (any length
 * > 0): the integral of L max(0, n . w) over the sky hemisphere by Gauss-Legendre quadrature on
 * pieces split at the receiver's horizon and at the sun (nodes per piece and axis, 8..1024; 0:
 * 48: 1e-8 relative or better on the CIE skies). Thread-safe. */
LX_API lx_status lx_sky_illuminance(lx_ctx *ctx, const lx_sky *sky, const double n[3], int nodes, double *E_lx);

/** Inputs of the solar position algorithm (NREL SPA, Reda & Andreas 2004; options: zero-initialise,
 * reserved stays zero). */
typedef struct lx_sun_input {
    int year, month, day, hour, minute; /* local standard time; year -2000..6000 */
    double second;
    double timezone_h;        /* hours east of Greenwich (-7 for US Mountain Standard Time) */
    double delta_ut1_s;       /* UT1 - UTC, -1..1 s (0 when unknown) */
    double delta_t_s;         /* TT - UT1 (about 69 s in the 2020s) */
    double latitude_deg;      /* north positive */
    double longitude_deg;     /* east positive */
    double elevation_m;
    double pressure_mbar;     /* annual mean local pressure (for refraction; 1013.25 at sea level) */
    double temperature_C;     /* annual mean local temperature */
    double refraction_deg;    /* atmospheric refraction at sunrise and sunset (0.5667 usually) */
    long long reserved[4];    /* zero: room for later inputs */
} lx_sun_input;

/** The sun's position and the intermediate SPA values the algorithm's published test prints. A result
 * (reserved written as zero; lx_scene embeds one). */
typedef struct lx_sun_position {
    double julian_day;
    double L_deg, B_deg, R_au;     /* Earth heliocentric longitude, latitude, radius vector */
    double delta_psi_deg, delta_epsilon_deg, epsilon_deg; /* nutation and true obliquity */
    double hour_angle_deg;         /* observer local hour angle H (before parallax) */
    double declination_deg;        /* topocentric declination */
    double zenith_deg;             /* topocentric zenith angle, refraction applied */
    double azimuth_deg;            /* from north towards east, 0..360 */
    double dir[3];                 /* unit vector towards the sun (x east, y north, z up) */
    long long reserved[4];         /* zero: room for later results */
} lx_sun_position;

/** NREL SPA (Reda & Andreas 2004, NREL/TP-560-34302): the sun's topocentric zenith and azimuth,
 * uncertainty +-0.0003 deg for years -2000..6000. LX_EINVAL (message names the field) for inputs
 * outside SPA's ranges. Thread-safe. */
LX_API lx_status lx_sun_spa(lx_ctx *ctx, const lx_sun_input *in, lx_sun_position *out);

/** The direction towards the sun (x east, y north, z up) at altitude and azimuth (from north
 * towards east), in radians. Thread-safe. */
LX_API void lx_sun_direction(double altitude_rad, double azimuth_rad, double dir[3]);

/** Half the angle the solar disc subtends: 0.2665 deg (Radiance gendaylit), in radians. */
#define LX_SUN_HALF_ANGLE_RAD (0.2665 * 3.14159265358979323846 / 180.0)

/** Options of lx_sky_map (zero-initialise for defaults; reserved stays zero). */
typedef struct lx_sky_map_opts {
    int width, height;           /* lat-long size (0: 1024 x 512) */
    double sun_normal_lx;        /* direct normal illuminance of the sun disc (0: no sun) */
    double ground_reflectance;   /* below the horizon: uniform rho (Dv + Evn sin(altitude)) / pi (0: black) */
    int supersample;             /* sky samples per pixel and axis, Gauss-Legendre in cos(theta) and phi (0: 4) */
    long long reserved[4];       /* zero: room for later options */
} lx_sky_map_opts;

/** Renders a sky (and the sun disc) as a one-channel (Y) lat-long map in the convention of
 * lx_envmap (+z up, theta from +z, phi from +x towards +y) with units LUMINANCE (lum_per_unit 1:
 * values are cd/m2). Each sky pixel holds the solid-angle mean of the luminance over its patch;
 * the sun disc (half angle LX_SUN_HALF_ANGLE_RAD) is spread over the pixels it covers in proportion
 * to the covered solid angle, scaled so the map's sum of L dOmega over the disc is exactly
 * sun_normal_lx. *out is a new map. */
LX_API lx_status lx_sky_map(lx_ctx *ctx, const lx_sky *sky, const lx_sky_map_opts *opts, lx_envmap **out);

/* ============================================================================================ */
/* 13. Spectral OpenEXR images (src/radiance) */
/* ============================================================================================ */

/* Spectral EXR images in the layout of Fichet et al. 2021, "An OpenEXR Layout for Spectral
 * Images" (JCGT 10(3)): emissive channels "S0.<wavelength, comma as decimal point><unit>", e.g.
 * "S0.550,000000nm" (units nm, um, mm, m, pm); polarised S1-S3 channels are ignored; reflective
 * "T." channels alone are LX_EUNSUPPORTED. Values are spectral radiance W/(sr m2 nm). */

/** A spectral image integrated per pixel to absolute CIE XYZ. Owns its arrays; made by
 * lx_spectral_exr_read_xyz, freed with lx_xyz_image_free (a struct only the library allocates). */
typedef struct lx_xyz_image {
    int width, height;     /* the data window */
    double *xyz;           /* width * height * 3, row-major, X Y Z interleaved: Km * integral of S xbar
                            * etc. (cd/m2 for radiance channels; Km 683.002, 10 deg: 683.599) */
    size_t n_lambda;       /* S0 channels used */
    double *lambda_nm;     /* their wavelengths, increasing */
    int resampled;         /* 0: summed on the channels' own uniform grid (cie15 rule, as
                            * lx_spd_colorimetry with LX_METHOD_CIE15); 1: wavelengths not uniform,
                            * resampled to 1 nm (lx_batch_resample, the exact method's model) first */
    int polarised_ignored; /* number of S1-S3 channels ignored */
} lx_xyz_image;

/** Reads a spectral OpenEXR file (scanline or tiled, half or float, any compression; first part)
 * and integrates every pixel with lx_batch_integrate (opts may be NULL; opts->backend chooses CPU
 * or OpenCL). Errors name the file: LX_EPARSE (not EXR, no S0 channels, a malformed wavelength,
 * a duplicate or non-finite value), LX_EUNSUPPORTED (reflective only, subsampled or integer
 * channels, deep data), LX_EIO; LX_EINVAL (an unknown observer) and those of lx_batch_integrate.
 * The caller owns *out and frees it with lx_xyz_image_free (*out NULL on failure). */
LX_API lx_status lx_spectral_exr_read_xyz(lx_ctx *ctx, const char *path, lx_observer observer,
                                          const lx_batch_opts *opts, lx_xyz_image **out);

/** Writes the image as a float OpenEXR with channels X, Y, Z (ZIP), atomically (temporary file +
 * rename; an existing file is replaced only on success). Errors: LX_EINVAL (an image without data),
 * LX_EIO (the file cannot be written; nothing is left at path). */
LX_API lx_status lx_xyz_image_write_exr(lx_ctx *ctx, const char *path, const lx_xyz_image *img);

/** Frees an image. Accepts NULL. */
LX_API void lx_xyz_image_free(lx_xyz_image *img);

/* ============================================================================================ */
/* 14. Scenes: files, the planner, evaluation and work counters (src/scene) */
/* ============================================================================================ */

/* Scene files (scene_read.c), the planner (scene_plan.c) and the evaluation (scene_eval.c,
 * scene_sky.c, scene_spectral.c). World frame in metres, z up. See README "scenes" for the format. */

/** Work counters: what the library computed, per effect. Every scene evaluation adds to the
 * context's counters; tests read them to prove that an effect that was off did none of its work. */
typedef struct lx_counters {
    unsigned long long point_evaluations;      /* luminaire-receiver evaluations as a point source */
    unsigned long long spot_evaluations;       /* Warn spot-falloff evaluations (cos^S) */
    unsigned long long goniometric_lookups;    /* intensity-table (IES/LDT) lookups */
    unsigned long long nearfield_pairs;        /* luminaire-receiver pairs integrated over the luminous area */
    unsigned long long nearfield_subdivisions; /* luminous-area patches evaluated by those integrations */
    unsigned long long environment_evaluations;/* receiver-normal sky evaluations (closed form or numeric) */
    unsigned long long environment_samples;    /* numerical sky samples (quadrature nodes, map pixels) */
    unsigned long long spectra_integrated;     /* spectrum integrations (colorimetry, alpha-opic: one each per source) */
    unsigned long long kernel_launches;        /* OpenCL batches run by scene evaluation (each >= 1 kernel launch) */
    unsigned long long nearfield_probes;       /* pairs whose point-model error was estimated (13 point
                                                * evaluations each: the near-field decision) */
    unsigned long long closed_form_evaluations;/* disk and rectangle luminaires evaluated in closed form */
    /* rooms: occlusion and interreflection (README "Rooms") */
    unsigned long long visibility_tests;       /* segments tested against surfaces and obstructions (ray casts) */
    unsigned long long form_factors;           /* point-to-polygon form factors (patch matrix and gathers) */
    unsigned long long radiosity_patches;      /* patches of the interreflection solves */
    unsigned long long radiosity_shots;        /* patch shots of the progressive refinement */
    unsigned long long gather_points;          /* receiver points and element centres gathered */
    /* daylight (README "Daylight") */
    unsigned long long daylight_evaluations;   /* point-opening evaluations of the sky (and ground) seen through an
                                                * opening: receiver points and element nodes */
    unsigned long long reserved[1];            /* zero: room for later counters (ABI policy) */
} lx_counters;

/** Copies the context's counters into *out (zeros for a NULL ctx; nothing for a NULL out). */
LX_API void lx_ctx_counters(const lx_ctx *ctx, lx_counters *out);
/** Sets the context's counters to zero (a NULL context is a no-op). */
LX_API void lx_ctx_counters_reset(lx_ctx *ctx);

/** The effects a scene may need. */
typedef enum lx_effect {
    LX_EFFECT_INVERSE_SQUARE = 0, /* E = I / d^2 from point-like luminaires */
    LX_EFFECT_COSINE,             /* the receiver's cosine factor cos(xi) (off: every receiver faces the ray) */
    LX_EFFECT_SPOT_FALLOFF,       /* Warn spot lobes cos^S (off: the peak in the whole front hemisphere) */
    LX_EFFECT_GONIOMETRIC,        /* intensity tables of IES/LDT files (off: isotropic of the file's flux) */
    LX_EFFECT_NEAR_FIELD,         /* luminous-area integration where d < 5 x the luminaire's size */
    LX_EFFECT_SPECTRAL,           /* spectral sums: CCT and melanopic EDI at receivers */
    LX_EFFECT_ENVIRONMENT,        /* sky and ground irradiance */
    LX_EFFECT_OPENCL,             /* grid work on an OpenCL device */
    LX_EFFECT_OCCLUSION,          /* surfaces and obstructions that cut luminaire-receiver segments */
    LX_EFFECT_INTERREFLECTION,    /* diffuse interreflection between the faces of rooms, surfaces, obstructions */
    LX_EFFECT_DAYLIGHT,           /* sky, ground and sun through the openings of rooms (daylight factor) */
    LX_EFFECT_COUNT
} lx_effect;

/** "inverse_square", "cosine", "spot_falloff", "goniometric", "near_field", "spectral",
 * "environment", "opencl", "occlusion", "interreflection", "daylight" (static storage; NULL for a
 * bad value).
 * Thread-safe. */
LX_API const char *lx_effect_name(lx_effect e);

/** Luminaire kinds of a scene. */
typedef enum lx_scene_lum_kind {
    LX_SLUM_POINT = 0, /* isotropic point: flux or intensity */
    LX_SLUM_SPOT,      /* Warn spot: flux or peak intensity, exponent or beam angle */
    LX_SLUM_DISK,      /* Lambertian disk: luminance or flux, radius */
    LX_SLUM_RECT,      /* Lambertian rectangle: luminance or flux, width (local x) x length (local y) */
    LX_SLUM_FILE       /* IES LM-63 or EULUMDAT file, optionally scaled to a flux */
} lx_scene_lum_kind;

/** One luminaire of a scene. Its frame is the one lx_grid_illuminance uses: the smallest rotation
 * taking the nadir (0, 0, -1) to aim (the nadir, spot axis and emitting normal), then a turn by
 * rotate about the aim; with aim (0, 0, -1) and rotate 0, C0 and the rectangle width are +x. An
 * element of lx_scene.lum (ABI policy: reserved space, as results). */
typedef struct lx_scene_luminaire {
    char *name;
    const char *file;         /* the scene file and line of its section header (names kept by the scene) */
    long line;
    lx_scene_lum_kind kind;
    double pos_m[3];
    double aim[3];            /* unit */
    double rotate_rad;
    double intensity_cd;      /* point: isotropic intensity; spot: peak; derived from flux when given */
    double flux_lm;           /* emitted flux (point, spot, disk, rect; file: after scaling) */
    double exponent;          /* spot: Warn S */
    double luminance_cd_m2;   /* disk, rect */
    double radius_m;          /* disk */
    double width_m, length_m; /* rect: width along local x (C0), length along local y; file: the
                               * luminous opening as in lx_luminaire (width along C90-C270, length
                               * along C0-C180; 0: a point) */
    double scale;             /* file: candela multiplier applied to the table (flux / table lumens),
                               * times the file's TILT factor at the tilt of aim from the nadir */
    char *lum_path;           /* file: the photometric file (resolved against the scene file) */
    lx_luminaire *lum;        /* file: owned */
    char *spd_path;           /* the SPD file (resolved), or NULL */
    lx_spd_set *spd;          /* owned, when spd_path is set (the first spectrum, or `spectrum`) */
    size_t spd_index;
    double cct_K;             /* NaN unless cct was given */
    long long reserved[4];    /* zero: room for later fields */
} lx_scene_luminaire;

/** Receiver kinds. */
typedef enum lx_scene_rec_kind {
    LX_SREC_POINT = 0,
    LX_SREC_GRID = 1,
    LX_SREC_SET = 2   /* points of an area that is not a whole grid (an EN 12464-1 band): the cell centres of
                       * na x nb cells that lie inside it (lx_scene_design.area) */
} lx_scene_rec_kind;

/** One receiver: a point, or a grid of na x nb points on a plane x, y or z = level. An element of
 * lx_scene.rec (ABI policy: reserved space, as results). */
typedef struct lx_scene_receiver {
    char *name;
    const char *file;         /* the scene file and line of its section header */
    long line;
    lx_scene_rec_kind kind;
    double normal[3];         /* unit */
    double reflectance;       /* NaN when none (no luminance output) */
    char axis;                /* grid: 'x', 'y' or 'z' (the fixed coordinate) */
    size_t na, nb;            /* grid: points along the first and second free axes (x before y before z) */
    size_t n;                 /* points */
    double *points;           /* n x 3 (grids: a fastest), owned */
    long long reserved[4];    /* zero: room for later fields */
} lx_scene_receiver;

/** The sky kinds. */
typedef enum lx_scene_sky_kind {
    LX_SKY_NONE = 0, LX_SKY_UNIFORM, LX_SKY_OVERCAST, LX_SKY_MAP,
    LX_SKY_CIE,   /* a CIE standard general sky (type 1..15), by zenith luminance or horizontal illuminance */
    LX_SKY_PEREZ  /* the Perez all-weather sky from direct-normal and diffuse-horizontal irradiance */
} lx_scene_sky_kind;

/** A glare observer: UGR (CIE 117) at an eye position looking along view. */
typedef struct lx_scene_observer {
    char *name;
    const char *file;         /* the scene file and line of its section header */
    long line;
    double pos_m[3];          /* the eye */
    double view[3];           /* unit line of sight */
    double up[3];             /* unit, orthogonal to view: the vertical of the visual field (from +z) */
    double background_cd_m2;  /* Lb given in the scene (NaN: none) */
    long long reserved[4];    /* zero: room for later fields (an element of lx_scene.obs) */
} lx_scene_observer;

/** Forced state of an effect in [effects]. */
typedef enum lx_effect_force { LX_FORCE_AUTO = 0, LX_FORCE_ON = 1, LX_FORCE_OFF = 2 } lx_effect_force;

/** The faces of a room, in this order (the index of lx_scene_room.reflectance; `--surfaces` rows). */
typedef enum lx_room_face {
    LX_ROOM_FLOOR = 0, LX_ROOM_CEILING, LX_ROOM_WALL_XMIN, LX_ROOM_WALL_XMAX, LX_ROOM_WALL_YMIN, LX_ROOM_WALL_YMAX
} lx_room_face;

/** A room: an axis-aligned box whose six faces reflect diffusely on their inside. The luminaires
 * and receivers inside it see its inside only (no light passes its walls). */
typedef struct lx_scene_room {
    char *name;
    const char *file;         /* the scene file and line of its section header */
    long line;
    double min_m[3], max_m[3];
    double reflectance[6];    /* per lx_room_face, 0 <= rho < 1 */
    long long reserved[4];    /* zero: room for later fields (an element of lx_scene.room: ABI policy) */
} lx_scene_room;

/** A surface: the planar parallelogram corner + s edge1 + t edge2 (0 <= s, t <= 1), Lambertian on
 * both sides with one reflectance; it blocks light. Its front is the side edge1 x edge2 points to. */
typedef struct lx_scene_surface {
    char *name;
    const char *file;
    long line;
    double corner_m[3], edge1_m[3], edge2_m[3];
    double reflectance;       /* 0 <= rho < 1 */
    long long reserved[4];    /* zero: room for later fields */
} lx_scene_surface;

/** An obstruction: an axis-aligned box that blocks light; its six faces reflect diffusely. */
typedef struct lx_scene_obstruction {
    char *name;
    const char *file;
    long line;
    double min_m[3], max_m[3];
    double reflectance;       /* 0 <= rho < 1 */
    long long reserved[4];    /* zero: room for later fields */
} lx_scene_obstruction;

/** The glazing of an opening ([opening] glazing). */
typedef enum lx_glazing {
    LX_GLAZING_NONE = 0, /* an open hole, or a transmittance that does not depend on the angle */
    LX_GLAZING_CLEAR     /* clear glass: the normal-incidence transmittance times the angular dependence of
                          * 6 mm clear float glass (lx_glazing_transmittance) */
} lx_glazing;

/** The directional transmittance of glazing g at incidence cos_incidence = cos(theta) (0..1, from the
 * glazing's normal) for the normal-incidence transmittance tau_normal. NONE: tau_normal. CLEAR:
 * tau_normal P(c) / P(1) with the 6 mm clear-glass polynomial of CIE 171:2006 (test cases 5.10, 5.12;
 * Tregenza & Sharples, Daylighting Algorithms, 1993, algorithm 2.34) P(c) = -0.028378 + 3.156075 c
 * - 3.058376 c^2 - 1.428919 c^3 + 4.014235 c^4 - 1.775827 c^5, P(1) = 0.878810; 0 where P < 0 (within
 * 0.52 deg of grazing). 0 for cos_incidence outside 0..1 or NaN. Pure, thread-safe. */
LX_API double lx_glazing_transmittance(lx_glazing g, double tau_normal, double cos_incidence);

/** An opening ([opening NAME]): the rectangle corner + s edge1 + t edge2 (0 <= s, t <= 1) in a wall or
 * the ceiling of a room, a hole in that face: it reflects nothing, lets the room's light out (lost)
 * and, with a sky or the sun, daylight in, times its glazing's transmittance. An element of
 * lx_scene.open (ABI policy: reserved space, as results). */
typedef struct lx_scene_opening {
    char *name;
    const char *file;         /* the scene file and line of its section header */
    long line;
    double corner_m[3], edge1_m[3], edge2_m[3];
    size_t room;              /* the room (index into lx_scene.room) */
    lx_room_face face;        /* its face: a wall or the ceiling */
    double area_m2;
    double transmittance;     /* normal-incidence tau, 0..1 (1: unglazed; CLEAR without a value: P(1)) */
    lx_glazing glazing;
    long long reserved[4];    /* zero: room for later fields */
} lx_scene_opening;

/** A scene read from a file. Owns everything it points to. Read-only after reading; freed with
 * lx_scene_free (a struct only the library allocates: ABI policy). */
typedef struct lx_scene {
    char *file;
    char *title;                          /* [scene] title, or "" */
    size_t n_lum, n_rec;
    lx_scene_luminaire *lum;
    lx_scene_receiver *rec;
    lx_scene_sky_kind sky;
    double sky_luminance_cd_m2;           /* uniform: L; overcast: zenith Lz */
    double sky_scale;                     /* map: multiplier of the map's values (default 1) */
    char *sky_path;                       /* map: the EXR file (resolved) */
    lx_envmap *sky_map;                   /* map: the map read from it (owned) */
    double ground_reflectance;            /* 0..1 (default 0) */
    double sky_cct_K;                     /* NaN unless given (spectral sky: CIE daylight) */
    int sky_samples;                      /* overcast quadrature nodes per piece / map: unused (default 64) */
    int want_luminance, want_cct, want_melanopic; /* [output] */
    lx_effect_force force[LX_EFFECT_COUNT];       /* [effects] */
    long force_line[LX_EFFECT_COUNT];
    double nearfield_tol;                 /* [scene] near_field_tolerance: relative convergence (default 1e-5) */
    const char *sky_file_at;              /* the scene file and line of [sky] (NULL, 0 when none) */
    long sky_line, sky_file_line;         /* [sky] and its 'file' key */
    long spectral_line;                   /* the [output] line that first asked for cct or melanopic_edi */
    char **names;                         /* the file names the entities point to (owned) */
    size_t n_names;
    /* daylight: CIE and Perez skies, the sun, glare observers (scene_daylight.c) */
    int sky_cie_type;                     /* cie: 1..15 */
    int sky_by_illuminance;               /* cie: scaled by `illuminance` (Dv) instead of `luminance` (Lz) */
    double sky_illuminance_lx;            /* cie: the horizontal illuminance given */
    double sky_dni_W_m2, sky_dhi_W_m2;    /* perez: direct normal and diffuse horizontal irradiance */
    double sky_water_cm;                  /* perez: precipitable water (0: 2 cm) */
    int sky_day_of_year;                  /* perez: from [sky] day_of_year or the [sun] date (0: unset) */
    lx_sky sky_model;                     /* cie, perez: the distribution, set when the scene is read */
    int has_sun;                          /* a [sun] section */
    double sun_dir[3];                    /* towards the sun (x east, y north, z up) */
    double sun_normal_lx;                 /* its direct normal illuminance (0: the sun only places the sky) */
    int sun_by_date;                      /* 1: placed by date, time and site (sun_position holds SPA's result) */
    lx_sun_position sun_position;
    const char *sun_file_at;              /* the scene file and line of [sun] */
    long sun_line;
    size_t n_obs;                         /* [observer NAME] sections */
    lx_scene_observer *obs;
    /* rooms, surfaces and obstructions (README "Rooms") */
    size_t n_room, n_surf, n_obst;
    lx_scene_room *room;
    lx_scene_surface *surf;
    lx_scene_obstruction *obst;
    double interreflection_tol;           /* [scene] interreflection_tolerance: relative, on every receiver's
                                           * total illuminance (default 1e-3) */
    double patch_size_m;                  /* [scene] patch_size: the radiosity patch size (0: the planner chooses) */
    int patch_refinement;                 /* [scene] patch_refinement: 1 (default) splits patches near luminaires,
                                           * shadow edges and receivers; 0 keeps them uniform */
    long interreflection_tol_line, patch_size_line; /* their lines (0 when not given) */
    /* openings in the faces of rooms (README "Daylight") */
    size_t n_open;
    lx_scene_opening *open;
    /* the deliverable: maintenance factors, EN 12464-1 areas and requirements, emergency lighting,
     * energy (README "The deliverable"; never NULL in a scene the library read) */
    struct lx_scene_design *design;
} lx_scene;

/** Reads a scene file ('-' is standard input); includes are resolved relative to the including
 * file. Errors (LX_EPARSE naming file and line: unknown section or key, bare dimensional
 * number, wrong unit, missing key, include cycle; LX_EIO; errors of referenced IES/SPD files)
 * leave *out NULL. Referenced photometric and spectral files are read here. The caller owns *out
 * and frees it with lx_scene_free. */
LX_API lx_status lx_scene_read_file(lx_ctx *ctx, const char *path, lx_scene **out);
/** Same from len bytes of text (not kept); name (required) is used in messages and to resolve
 * includes (its directory). Errors: as lx_scene_read_file. */
LX_API lx_status lx_scene_read_mem(lx_ctx *ctx, const char *name, const char *text, size_t len, lx_scene **out);
/** Frees a scene. Accepts NULL. */
LX_API void lx_scene_free(lx_scene *scene);

/** The planner's interreflection choices (all zero when interreflection is off). */
typedef struct lx_scene_room_plan {
    double flux_lm;            /* luminaire flux the reflecting faces can receive (in rooms, or in the open
                                * with reflecting surfaces) */
    double area_m2;            /* S: the exposed reflecting area */
    double mean_reflectance;   /* the area-weighted reflectance rho */
    double indirect_est_lx;    /* the integrating-sphere estimate rho Phi / (S (1 - rho)) */
    double share_est;          /* the largest estimated indirect share of a receiver point's total */
    double tolerance;          /* interreflection_tolerance */
    double patch_size_m;       /* chosen (or given by patch_size) */
    size_t n_patches;          /* the solve's patches */
    size_t n_elements;         /* the gather's elements: the patches, split where the light varies fast or a
                                * receiver is close (the final gather resolves them) */
    size_t n_refined;          /* splits the refinement made (near luminaires, shadow edges, receivers) */
    size_t n_nodes;            /* direct-light quadrature nodes over all elements */
    double stop_unshot_lm;     /* the solve iterates until the unshot flux is below this */
    double memory_bytes;       /* what the solve allocates (the form-factor matrix dominates) */
    double memory_limit_bytes; /* the bound (1 GiB; LX_ROOM_MEMORY_MB overrides) */
    int backend;               /* lx_backend for the form factors and gathers (AUTO: the size decides) */
    void *mesh;                /* the patches, faces and occluders (internal; owned) */
    long long reserved[4];     /* zero: room for later fields (embedded in lx_scene_plan: ABI policy) */
} lx_scene_room_plan;

/** The planner's daylight choices (all zero when daylight is off). */
typedef struct lx_scene_daylight_plan {
    int df;                    /* 1 when the daylight factor is defined: a uniform, overcast or CIE 1..5 sky
                                * without sun illuminance */
    int closed_form;           /* 1 when every sky component takes a closed form (uniform or overcast sky:
                                * exact moments of the opening's directions); 0: numerical integration */
    double outside_lx;         /* E_h: the unobstructed sky's horizontal illuminance outside (the daylight
                                * factor's denominator; without the sun) */
    double ground_cd_m2;       /* the ground's luminance rho_g (E_h + the sun's) / pi, seen below the horizon */
    double flux_in_lm;         /* the flux entering through every opening: the sky's, the ground's and the
                                * sun's light on its outer side, times its glazing (integrated exactly) */
    double share_est;          /* the largest estimated interreflected share of a receiver's daylight */
    double quad_tol;           /* relative tolerance of the numerical sky integrations */
    long long reserved[4];     /* zero: room for later fields (embedded in lx_scene_plan: ABI policy) */
} lx_scene_daylight_plan;

/** The planner's decision. */
/** Why a luminaire-receiver pair takes its path (lx_scene_plan.near_why). */
typedef enum lx_near_why {
    LX_NEAR_NONE = 0,    /* point model: the luminaire has no luminous area */
    LX_NEAR_WITHIN,      /* point model: its estimated error fits the point's share of the tolerance */
    LX_NEAR_ZERO,        /* point model: the receiver faces away from the whole opening (both give 0) */
    LX_NEAR_OVER,        /* integrated: the point model's estimated error exceeds the tolerance */
    LX_NEAR_UNSURE,      /* integrated: the probes cannot vouch (a beam cut-off or the receiver's horizon
                          * across the opening, or the receiver closer than the opening's size) */
    LX_NEAR_CLOSED,      /* a disk or rectangle in closed form (exact) */
    LX_NEAR_NO_CLOSED,   /* integrated: a disk or rectangle without the receiver's cosine (no closed form) */
    LX_NEAR_FORCED_ON,   /* integrated: near_field forced on in [effects] */
    LX_NEAR_FORCED_OFF,  /* point model: near_field forced off in [effects] */
    LX_NEAR_WHY_COUNT
} lx_near_why;

/** A short name for a decision ("point: within tolerance", ...; static storage; NULL for a bad value). */
LX_API const char *lx_near_why_name(lx_near_why why);

/** The planner's decision; made by lx_scene_plan_make, freed with lx_scene_plan_free (a struct only
 * the library allocates). */
typedef struct lx_scene_plan {
    int on[LX_EFFECT_COUNT];          /* 1 when the effect is simulated */
    int forced[LX_EFFECT_COUNT];      /* 1 when [effects] decided it */
    char reason[LX_EFFECT_COUNT][256];/* why, for people */
    size_t n_points;                  /* receiver points over all receivers */
    size_t n_pairs;                   /* luminaire x receiver-point pairs */
    size_t n_near;                    /* pairs that take the near-field path */
    unsigned char *near;              /* n_lum x n_points (luminaire-major): 0 = point model, 1 = the
                                       * luminous area integrated (patches), 2 = a disk or rectangle in
                                       * closed form; owned */
    size_t n_normals;                 /* distinct receiver normals (sky evaluations) */
    lx_counters estimate;             /* the work the plan expects */
    lx_backend backend;               /* OPENCL when some grid work runs on a device, else CPU */
    unsigned char *device;            /* n_lum x n_rec: 1 = this IES luminaire's work on this grid (all
                                       * far field) runs as one lx_grid_illuminance OpenCL batch; owned */
    int device_required;              /* 1 when asked for explicitly: a device failure is then an error */
    /* appended (ABI policy: a library-allocated struct grows at its end) */
    double *near_err;                 /* n_lum x n_points: the point model's estimated error relative to
                                       * the point's illuminance (NaN where it was not estimated); owned */
    unsigned char *near_why;          /* n_lum x n_points: an lx_near_why; owned */
    lx_counters planning;             /* the work the planner did itself (the near-field probes) */
    /* occlusion and interreflection (README "Rooms") */
    unsigned char *occ;               /* n_lum x n_points (luminaire-major): 0 no surface or obstruction can cut
                                       * the pair (bounding-volume test), 1 visibility-tested, 2 blocked (the pair
                                       * is in different rooms); owned; NULL when occlusion is off */
    size_t n_occ_tested, n_occ_blocked;
    lx_scene_room_plan room;
    /* daylight through openings (README "Daylight") */
    lx_scene_daylight_plan daylight;
    /* the deliverable (README "The deliverable") */
    int mode;                         /* lx_scene_mode the plan was made for */
    double *lum_scale;                /* n_lum: the factor every luminaire's light is multiplied by in this mode:
                                       * its maintenance factor; in emergency operation MF x emergency flux / flux
                                       * (0 for a luminaire dark in the mode); owned */
    void *internal;                   /* the planner's own state (owned) */
} lx_scene_plan;

/** Plans a scene: which effects, and which pairs take the near-field path. backend: AUTO lets
 * the size of the work decide (OpenCL for >= 1e7 far-field IES evaluations on grids), CPU never
 * uses a device, OPENCL sends every eligible grid batch to one. Errors: LX_EPARSE (naming the [effects]
 * or [output] line) when a forced effect cannot be honoured (spectral forced on without spectra,
 * environment forced on without a sky); LX_EINVAL (an unknown backend). The caller owns *out (NULL
 * on failure) and frees it with lx_scene_plan_free, which accepts NULL. The plan refers to the
 * scene: use it only with that scene, and free it before the scene. */
LX_API lx_status lx_scene_plan_make(lx_ctx *ctx, const lx_scene *scene, lx_backend backend, lx_scene_plan **out);

/** The operation a scene is planned for. */
typedef enum lx_scene_mode {
    LX_SCENE_NORMAL = 0,    /* every luminaire but the non-maintained emergency ones, at its maintenance factor */
    LX_SCENE_EMERGENCY = 1  /* EN 1838: the emergency luminaires alone at their emergency flux (times their
                             * maintenance factor), direct light only: interreflection, daylight and the sky
                             * are off (the standard counts no reflected light) */
} lx_scene_mode;

/** lx_scene_plan_make for an operation (lx_scene_plan_make is LX_SCENE_NORMAL). In emergency
 * operation the reasons of interreflection, daylight and environment say why they are off. Errors:
 * those of lx_scene_plan_make; LX_EINVAL (an unknown mode); LX_EPARSE (emergency operation of a
 * scene without an emergency luminaire, naming the scene file). */
LX_API lx_status lx_scene_plan_make_mode(lx_ctx *ctx, const lx_scene *scene, lx_backend backend, lx_scene_mode mode,
                                         lx_scene_plan **out);
LX_API void lx_scene_plan_free(lx_scene_plan *plan);

/** One face's results (`luxcalc scene --surfaces`): area-weighted averages over its exposed area
 * (the flux it receives divided by its area). */
typedef struct lx_scene_surface_result {
    char *name;                 /* ROOM.floor, ROOM.ceiling, ROOM.wall_xmin ... ROOM.wall_ymax,
                                 * SURFACE.front, SURFACE.back, OBSTRUCTION.bottom, .top, .xmin ... .ymax */
    double area_m2;             /* exposed area (less what an obstruction standing on it covers) */
    double direct_lx, indirect_lx, E_lx;
    double L_cd_m2;             /* rho E / pi */
    double reflectance;
    long long reserved[4];      /* zero: room for later results (an element of lx_scene_result.surfaces) */
} lx_scene_surface_result;

/** What the interreflection solve did. */
typedef struct lx_scene_room_stats {
    size_t n_patches;
    unsigned long long sweeps;  /* progressive-refinement sweeps over the patches */
    unsigned long long shots;   /* patch shots */
    double direct_lm;           /* flux the faces received directly from the sources */
    double indirect_lm;         /* flux they received after one or more reflections */
    double absorbed_lm;         /* (1 - rho) x received, over every face */
    double escaped_lm;          /* reflected flux that reached no face (open scenes) */
    double unshot_lm;           /* reflected flux not yet distributed when the solve stopped */
    double indirect_share;      /* measured: sum of indirect / sum of total over the receiver points */
    double gather_check;        /* rms relative difference between each patch's indirect illuminance in the
                                 * solve and the exact-form-factor gather at its centre (discretisation) */
    int backend;                /* lx_backend the form factors and gathers ran on */
    double seconds_ff, seconds_solve, seconds_gather;
    long long reserved[4];      /* zero: room for later results (embedded in lx_scene_result) */
} lx_scene_room_stats;

/** What the daylight evaluation did (zero when daylight is off). */
typedef struct lx_scene_daylight_stats {
    double flux_in_lm;          /* entering through the openings (lx_scene_daylight_plan.flux_in_lm) */
    double direct_lm;           /* what the faces received directly (flux_in_lm less what leaves at once by
                                 * another opening, up to the quadrature of the faces' direct light) */
    double indirect_lm;         /* what they received after reflections */
    double escaped_lm;          /* reflected daylight that left through the openings */
    double unshot_lm;           /* reflected daylight not yet distributed when the solve stopped */
    unsigned long long sweeps;  /* the daylight solve's sweeps */
    double seconds;             /* the daylight's own time (direct at the points and faces, solve, gathers) */
    long long reserved[4];      /* zero: room for later results (embedded in lx_scene_result) */
} lx_scene_daylight_stats;

/** Results at every receiver point (receiver order, then point order). */
/** Results at every receiver point (receiver order, then point order); made by lx_scene_eval,
 * freed with lx_scene_result_free (a struct only the library allocates). */
typedef struct lx_scene_result {
    size_t n_points, n_lum;
    size_t *first;              /* n_rec + 1: receiver r has points first[r] .. first[r+1]-1 */
    double *E_lx;               /* n_points: total illuminance */
    double *contrib_lx;         /* n_points x (n_lum + 1): each luminaire's part, last the sky's (direct
                                 * light: with interreflection on, the reflected part is indirect_lx) */
    double *L_cd_m2;            /* n_points: rho E / pi (NaN without a reflectance or not asked) */
    double *cct_K, *duv;        /* n_points (NaN when spectral is off or CCT undefined) */
    double *melanopic_edi_lx;   /* n_points (NaN when spectral is off) */
    lx_counters work;           /* the work this evaluation did */
    double seconds;             /* wall-clock time of the evaluation */
    /* interreflection (NULL and zero when it is off): E_lx = direct_lx + indirect_lx */
    double *direct_lx, *indirect_lx;   /* n_points */
    size_t n_surfaces;                 /* room faces, surface sides, obstruction faces */
    lx_scene_surface_result *surfaces;
    lx_scene_room_stats room;
    /* daylight through openings (NULL when daylight is off): daylight_lx is part of E_lx, its direct
     * part is the sky's column of contrib_lx and its interreflected part is in indirect_lx */
    double *daylight_lx;        /* n_points: sky, ground and sun through the openings, direct and reflected */
    double *daylight_factor;    /* n_points: DF (%) = sky_component + externally_reflected +
                                 * internally_reflected (NaN everywhere when plan.daylight.df is 0) */
    double *sky_component;      /* n_points: SC (%): the sky seen through the openings */
    double *externally_reflected; /* n_points: ERC (%): the ground seen through the openings */
    double *internally_reflected; /* n_points: IRC (%): the daylight reflected in the room */
    double *observer_indirect_lx; /* n_obs: the luminaires' interreflected illuminance at each observer's eye on
                                 * the plane facing the line of sight (NULL without interreflection or
                                 * observers) */
    lx_scene_daylight_stats daylight;
    /* the deliverable: the luminaires' light on small vertical cylinders (direct and interreflected;
     * daylight not included), NULL when no receiver asks; NaN at the points of receivers that do not */
    double *cylindrical_lx;     /* n_points: E_z */
    double *semicylindrical_lx; /* n_points: E_sz towards the receiver's facing direction */
    double *modelling;          /* n_points: E_z / E_h with E_h the luminaires' horizontal illuminance (receivers
                                 * facing up; NaN elsewhere) */
    double cylinder_tol;        /* the relative tolerance the interreflected part of E_z and E_sz met */
} lx_scene_result;

/** Options of lx_scene_eval (zero-initialise for defaults: everything; ABI policy: reserved stays
 * zero). */
typedef struct lx_scene_eval_opts {
    int single;                 /* 1: evaluate luminaire `index` alone (no sky) */
    size_t index;
    long long reserved[4];      /* zero: room for later options */
} lx_scene_eval_opts;

/** Evaluates a planned scene (opts may be NULL). Adds its work to the context's counters, and sets
 * lx_ctx_backend_used. The caller owns *out and frees it with lx_scene_result_free (accepts NULL).
 * Errors: LX_EINVAL (an index outside the scene, non-zero reserved), LX_EDEVICE (a device failure
 * when the plan requires the device; otherwise the work falls back to the CPU), LX_ENOMEM. */
LX_API lx_status lx_scene_eval(lx_ctx *ctx, const lx_scene *scene, const lx_scene_plan *plan,
                               const lx_scene_eval_opts *opts, lx_scene_result **out);
LX_API void lx_scene_result_free(lx_scene_result *res);

/** One luminaire as a glare source for one observer (CIE 117). */
typedef struct lx_glare_term {
    int visible;                /* 1 when it counts: a luminous area, in front of the eye (sigma < 90 deg) and lit towards it */
    double luminance_cd_m2;     /* L = I(towards the eye) / projected luminous area */
    double solid_angle_sr;      /* omega = projected area / d^2 */
    double position_index;      /* Guth p (lx_guth_position_index) */
    double sigma_deg, tau_deg;  /* the source's angle from the line of sight, and about it from the vertical */
    double term;                /* L^2 omega / p^2 */
    long long reserved[4];      /* zero: room for later fields (an element of lx_scene_glare.terms) */
} lx_glare_term;

/** The glare of a scene at its observers; made by lx_scene_glare_eval, freed with lx_scene_glare_free
 * (a struct only the library allocates). */
typedef struct lx_scene_glare {
    size_t n_obs, n_lum;
    double *ugr;                /* n_obs: UGR (NaN when no luminaire counts) */
    double *background_cd_m2;   /* n_obs: Lb used */
    lx_glare_term *terms;       /* n_obs x n_lum, observer-major */
    /* appended (ABI policy) */
    double *indirect_lx;        /* n_obs: the interreflected illuminance at the eye Lb came from (Lb = E_ind / pi);
                                 * NaN where the scene file's background_luminance was used */
} lx_scene_glare;

/** UGR (CIE 117-1995) at every [observer]: UGR = 8 log10(0.25 / Lb sum L^2 omega / p^2) over the
 * luminaires with a luminous area (disk, rect, file luminaires with an opening; points and spots
 * have none and are left out). Lb is the observer's background_luminance when the scene gives one;
 * otherwise, for an observer inside a room, E_ind / pi (CIE 117) with E_ind the luminaires'
 * interreflected illuminance at the eye on the plane facing the line of sight: the scene is then
 * planned (LX_BACKEND_AUTO) and evaluated for it. Errors: LX_EPARSE naming the observer when it has
 * no background_luminance and no room to take it from (outside every room, or interreflection
 * forced off); the scene's evaluation errors. Free with lx_scene_glare_free. */
LX_API lx_status lx_scene_glare_eval(lx_ctx *ctx, const lx_scene *scene, lx_scene_glare **out);
LX_API void lx_scene_glare_free(lx_scene_glare *glare);

/* ---- The deliverable (README "The deliverable"): maintained values, EN 12464-1 areas and
 * requirements, emergency lighting (EN 1838), energy (EN 15193-1) (src/scene/design_*.c) ---- */

/** A maintenance scheme ([maintenance NAME]): CIE 97:2005 MF = LLMF x LSF x LMF x RSMF. Each factor is
 * typed as a value, or as a table against time that the user reads off the publication or the
 * lamp maker's data (luxcalc ships no copy of those tables), interpolated linearly at the scheme's
 * burning hours (LLMF, LSF) or cleaning intervals (LMF, RSMF). An element of lx_scene_design.maint
 * (ABI policy: reserved space, as results). */
typedef struct lx_maintenance {
    char *name;
    const char *file;           /* the scene file and line of its section header */
    long line;
    double llmf, lsf, lmf, rsmf;/* lamp lumen maintenance, lamp survival, luminaire maintenance and room
                                 * surface maintenance factors (1 where not given) */
    double mf;                  /* their product: the maintenance factor */
    double burning_h;           /* lamp burning hours the lamp factors are read at (NaN: not given) */
    double cleaning_a;          /* luminaire cleaning interval, years (NaN: not given) */
    double room_cleaning_a;     /* room surface cleaning interval, years (NaN: not given) */
    char *lamp_type, *luminaire_type, *environment; /* free text for the report ("" when not given) */
    long long reserved[4];      /* zero: room for later fields */
} lx_maintenance;

/** Kinds of an area ([area NAME] type; the bands are generated from a task area). */
typedef enum lx_area_kind {
    LX_AREA_TASK = 0,        /* EN 12464-1 task area: a rectangle on a horizontal plane */
    LX_AREA_SURROUNDING,     /* its immediate surrounding: a band around it (0.5 m), clipped at the room's walls */
    LX_AREA_BACKGROUND,      /* its background: a band around the surrounding (3 m), clipped at the walls */
    LX_AREA_ROOM,            /* a room's plane at a height, less a margin from the walls (0.5 m) */
    LX_AREA_WALL,            /* a wall of a room (one area each), less a margin */
    LX_AREA_CEILING,         /* a room's ceiling, less a margin */
    LX_AREA_ESCAPE_ROUTE,    /* EN 1838: the centre line of an escape route on the floor */
    LX_AREA_ROUTE_BAND,      /* its central band (half the route's width) */
    LX_AREA_OPEN,            /* EN 1838 open (anti-panic) area on the floor, less a 0.5 m border */
    LX_AREA_HIGH_RISK,       /* EN 1838 high-risk task area */
    LX_AREA_KIND_COUNT
} lx_area_kind;

/** Rounding of EN 12464-1's number of grid points d / p. */
typedef enum lx_grid_rounding {
    LX_GRID_ROUND_NEAREST = 0, /* the nearest whole number (EN 12464-1:2021) */
    LX_GRID_ROUND_UP = 1       /* the next whole number up (EN 12464-1:2011) */
} lx_grid_rounding;

/** An EN 12464-1 calculation grid (lx_en12464_grid). */
typedef struct lx_en12464_grid {
    double d_m;              /* the dimension the rule was applied to */
    double p_m;              /* the maximum cell size 0.2 x 5^log10(d), at most 10 m */
    size_t n[2];             /* cells (points at their centres) along the first and second sides */
    double cell_m[2];        /* the cell sizes: side / n */
    long long reserved[4];   /* zero: room for later results */
} lx_en12464_grid;

/** The calculation grid EN 12464-1 (after EN 12193) gives an area of sides a x b (m): the maximum cell
 * size p = 0.2 x 5^log10(d), at most 10 m, with d the longer side, or the shorter one where the longer
 * is at least twice it; along d, n = d / p cells (rounded as `rounding` says, at least 1), of size
 * d / n; along the other side as many cells of about that size (the same rounding), so that the cells
 * are nearly square. Points lie at the cells' centres. Errors: LX_EINVAL (a side not positive and
 * finite, an unknown rounding). Pure, thread-safe. */
LX_API lx_status lx_en12464_grid_size(lx_ctx *ctx, double a_m, double b_m, lx_grid_rounding rounding, lx_en12464_grid *out);

/** An area of a scene ([area NAME], and the bands of a task area): its plane, outline and grid, and
 * the receiver that holds its points. An element of lx_scene_design.area (ABI policy: reserved space). */
typedef struct lx_scene_area {
    char *name;                /* the receiver's name: NAME, NAME.surrounding, NAME.background, NAME.wall_xmin ... */
    const char *file;          /* the scene file and line of its section */
    long line;
    lx_area_kind kind;
    size_t rec;                /* its receiver (index into lx_scene.rec) */
    long task;                 /* a band: the index of its task area (-1 otherwise) */
    long room;                 /* its room (index into lx_scene.room; -1 none) */
    double origin_m[3], u[3], v[3]; /* its plane: origin + a u + b v (u, v unit) */
    size_t n_outline;          /* the outline's vertices (plane coordinates a, b; counter-clockwise) */
    double *outline;           /* n_outline x 2 (owned) */
    size_t n_inner;            /* a band's inner edge (the area it surrounds, clipped), 0 otherwise */
    double *inner;             /* n_inner x 2 (owned) */
    double area_m2;            /* the outline's area less the inner edge's */
    lx_en12464_grid grid;      /* the grid over the outline's bounding box; a band keeps the cell centres inside it */
    double box_m[4];           /* that box: a0, a1, b0, b1 */
    long long reserved[4];     /* zero: room for later fields */
} lx_scene_area;

/** Luminaire modes ([luminaire] emergency). */
typedef enum lx_lum_mode {
    LX_LUM_NORMAL = 0,       /* lights in normal operation only */
    LX_LUM_MAINTAINED = 1,   /* normal operation and, at its emergency flux, emergency operation */
    LX_LUM_EMERGENCY = 2     /* emergency operation only (a non-maintained emergency luminaire) */
} lx_lum_mode;

/** What a scene holds for the deliverable (a struct only the library allocates: ABI policy). */
typedef struct lx_scene_design {
    size_t n_maint;
    lx_maintenance *maint;      /* [maintenance NAME] schemes */
    double *lum_mf;             /* n_lum: each luminaire's maintenance factor (1: new values) */
    long *lum_maint;            /* n_lum: the scheme it takes its factor from (-1: typed, or none) */
    int maintained;             /* 1 when a maintenance factor or scheme is given (for the scene or a luminaire):
                                 * results are maintained values; 0: new values */
    double scene_mf;            /* [scene] maintenance_factor or its scheme's (1 when none) */
    long scene_maint;           /* [scene] maintenance: the scheme (-1: none) */
    double *lum_power_W;        /* n_lum: the luminaire's power ([luminaire] power; an IES file's input
                                 * watts), NaN when unknown */
    lx_lum_mode *lum_mode;      /* n_lum */
    double *lum_emergency_lm;   /* n_lum: the flux in emergency operation (0 for LX_LUM_NORMAL) */
    void *internal;             /* the reader's own state (owned) */
    unsigned char *rec_cylinder;/* n_rec: LX_REC_CYLINDRICAL | LX_REC_SEMICYLINDRICAL ([receiver] cylindrical,
                                 * semicylindrical) */
    double *rec_facing;         /* n_rec x 3: the direction a semi-cylinder faces (unit, horizontal) */
    size_t n_area;
    lx_scene_area *area;        /* the areas: each task area is followed by its bands */
    size_t n_req;               /* [requirement NAME] sections (checked by lx_scene_check) */
    long *obs_group;            /* n_obs: the [observer] section each observer came from (index into
                                 * obs_group_name); NULL when every observer is its own section */
    char **obs_group_name;
    size_t n_obs_group;
    int check_glare;            /* 1 when a requirement rates UGR (lx_scene_check needs lx_scene_glare_eval's) */
    int check_emergency;        /* 1 when a requirement rates emergency lighting (it needs the emergency results) */
    int has_energy;             /* 1 with an [energy] section (lx_scene_energy) */
} lx_scene_design;

/** Statistics of a receiver's points (an area's grid): the mean, minimum and maximum and the
 * uniformities U0 = E_min / E_mean and E_min / E_max, of its illuminance and, where asked, of its
 * cylindrical illuminance (NaN otherwise). */
typedef struct lx_area_stats {
    size_t n;                   /* points */
    double mean_lx, min_lx, max_lx, u0, min_max;
    double cyl_mean_lx, cyl_min_lx, cyl_u0;
    double modelling_min, modelling_max;
    long long reserved[4];      /* zero: room for later results */
} lx_area_stats;

/** The statistics of receiver rec's points in res. Errors: LX_EINVAL (rec outside the scene, res of
 * another scene). */
LX_API lx_status lx_scene_area_stats(lx_ctx *ctx, const lx_scene *scene, const lx_scene_result *res, size_t rec,
                                     lx_area_stats *out);

/** One line of the check against the requirements ([requirement NAME]). */
typedef struct lx_check {
    const char *requirement;    /* the requirement's name */
    const char *reference;      /* its `reference` text ("" when none) */
    const char *file;           /* the scene file and line of the key it checks */
    long line;
    const char *target;         /* what is rated: an area (receiver), an observer, a luminaire */
    const char *quantity;       /* "E_m", "U_0", "E_min", "E_z", "U_0,z", "modelling", "UGR", "R_a", "E_max/E_min" */
    const char *unit;           /* "lx" or "" */
    int at_most;                /* 0: value >= required; 1: value <= required */
    double required;
    double value;               /* computed (maintained values where a maintenance factor is given) */
    int pass;                   /* 1 when the value meets the requirement */
    int emergency;              /* 1: rated in emergency operation */
    long long reserved[4];      /* zero: room for later fields (an element of lx_scene_checks.check) */
} lx_check;

/** The checks of a scene against its requirements; made by lx_scene_check, freed with
 * lx_scene_checks_free (a struct only the library allocates). */
typedef struct lx_scene_checks {
    size_t n;
    lx_check *check;
    int all_pass;               /* 1 when every line passes */
    size_t n_fail;
} lx_scene_checks;

/** Checks the scene's results against its [requirement] sections: each given quantity of the
 * requirement's area (E_m, U_0, E_min of the area and of its bands, E_z and U_0,z, the modelling range
 * of its points, the walls' and the ceiling's E_m and U_0) from res, UGR at its observers from glare
 * (the highest of each observer's directions), R_a of the luminaires that light the area (CIE 13.3
 * from their spectra), and the emergency lighting's minimum and E_max / E_min from emergency.
 * glare and emergency may be NULL when no requirement needs them (LX_EINVAL otherwise). The quantities
 * a requirement may name were checked when the scene was read (an error there names the key's line
 * when nothing computes one). */
LX_API lx_status lx_scene_check(lx_ctx *ctx, const lx_scene *scene, const lx_scene_result *res,
                                const lx_scene_result *emergency, const lx_scene_glare *glare, lx_scene_checks **out);
LX_API void lx_scene_checks_free(lx_scene_checks *checks);

/** The inputs of EN 15193-1's lighting energy numeric indicator (LENI), per year. */
typedef struct lx_leni_input {
    double area_m2;             /* A: the floor area the energy is spread over */
    double power_W;             /* P_n: the installed power of the luminaires in normal operation */
    double daylight_h;          /* t_D: operating hours with daylight */
    double night_h;             /* t_N: operating hours without */
    double constant_factor;     /* F_C: 1, or (1 + MF) / 2 under constant illuminance control */
    double occupancy_factor;    /* F_O (0..1) */
    double daylight_factor;     /* F_D (0..1): 1 - F_DS x F_DC by the simplified method */
    double parasitic_W;         /* P_pc: controls' standby power, drawn in the hours the lighting is off */
    double emergency_W;         /* P_em: emergency batteries' charging power */
    double emergency_h;         /* t_em: its hours */
    long long reserved[4];      /* zero: room for later inputs */
} lx_leni_input;

/** LENI and its parts. */
typedef struct lx_leni {
    double lighting_kWh;        /* W_L = P_n F_C F_O (t_D F_D + t_N) / 1000 */
    double parasitic_kWh;       /* W_P = (P_pc (t_y - (t_D + t_N)) + P_em t_em) / 1000, t_y = 8760 h */
    double total_kWh;           /* W = W_L + W_P */
    double leni_kWh_m2;         /* LENI = W / A, kWh / (m2 a) */
    double power_density_W_m2;  /* P_n / A */
    long long reserved[4];      /* zero: room for later results */
} lx_leni;

/** EN 15193-1 LENI from its inputs (t_y = 8760 h). Errors: LX_EINVAL (an area or power that is not
 * positive and finite, hours negative or more than a year together, factors outside 0..1, non-zero
 * reserved). Pure, thread-safe. */
LX_API lx_status lx_leni_compute(lx_ctx *ctx, const lx_leni_input *in, lx_leni *out);

/** The scene's [energy] section as LENI inputs: P_n the sum of its luminaires' power in normal
 * operation ([luminaire] power, or an IES file's input watts), F_C from their power-weighted
 * maintenance factor when constant illuminance control is on, F_D = 1 - F_DS x F_DC from the typed
 * daylight supply and control factors, A given or the rooms' floor area. Errors: LX_EPARSE naming the
 * scene file when it has no [energy] section, or a luminaire that has no power (its section's line). */
LX_API lx_status lx_scene_energy(lx_ctx *ctx, const lx_scene *scene, lx_leni_input *in, lx_leni *out);

/** What a receiver asks besides its plane's illuminance (lx_scene_design.rec_cylinder). */
enum {
    LX_REC_CYLINDRICAL = 1,     /* the cylindrical illuminance E_z (EN 12464-1): the mean illuminance on the curved
                                 * surface of a very small vertical cylinder at the point; with a receiver facing up
                                 * (normal 0, 0, 1), the modelling ratio E_z / E_h */
    LX_REC_SEMICYLINDRICAL = 2  /* the semi-cylindrical illuminance E_sz: the mean on the curved half of such a
                                 * cylinder facing rec_facing */
};

/* ============================================================================================ */
/* 15. Plots (PNG with cairo, written atomically) (src/plot) */
/* ============================================================================================ */

/* Every writer below draws with cairo (text in DejaVu Sans, through fontconfig) and writes an
 * 8-bit RGB PNG atomically: a temporary file beside path, renamed into place only on success, so
 * nothing is left at path on failure (a path that exists and is not a regular file, such as
 * /dev/null, is written directly). Errors: LX_EINVAL (bad arguments), LX_EIO (path cannot be
 * created: a missing directory), LX_EWRITE (writing failed part-way: a full disk; the message
 * has the system's reason), LX_ENOMEM. Labels are placed where they overlap no other label.
 * Thread-safe for distinct contexts. */

/** Colour scales of the false-colour plots. */
typedef enum lx_plot_scale {
    LX_PLOT_SCALE_AUTO = 0,  /* the plot's own choice (log for maps, by dynamic range for grids) */
    LX_PLOT_SCALE_LOG = 1,   /* log10, ticks at decades */
    LX_PLOT_SCALE_LINEAR = 2 /* linear, ticks at round 1-2-5 values */
} lx_plot_scale;

/** Options of lx_falsecolor_write_png (zero-initialise for defaults). */
typedef struct lx_falsecolor_opts {
    lx_plot_scale scale;   /* AUTO: log */
    double lo, hi;         /* the colour range when hi > lo (log: lo <= 0 leaves the bottom
                            * automatic); otherwise automatic: log from the decade at or below
                            * the 1st percentile of the positive values (at most 6 decades below
                            * the top, at least 2) to the decade at or above the largest; linear
                            * from 0 (or a round value below a minimum under -5 % of the largest)
                            * to the round value above the largest; where a small bright source
                            * (values over 100 times the 99.9th percentile: the sun disc) would take
                            * the range, it ends above the rest instead, the source drawn in the top
                            * colour and a line under the title saying so. Values below the range
                            * take its lowest colour. */
    const char *quantity;  /* the legend's quantity ("luminance"; NULL: none) */
    const char *unit;      /* its unit ("cd/m²"; NULL: none) */
    const char *title;     /* the heading (NULL: none); a line of min / median / max follows it */
    long long reserved[4]; /* zero: room for later options (ABI policy) */
} lx_falsecolor_opts;

/** A false-colour PNG of w x h values (row-major, row 0 at the top; NaN drawn grey) in the look of
 * Radiance falsecolor: the palette dark violet - blue - cyan - green - yellow - orange - red, a
 * colour bar with decade (log) or round (linear) ticks and the unit. Maps narrower than 512
 * pixels are enlarged by a whole factor (each value a block). */
LX_API lx_status lx_falsecolor_write_png(lx_ctx *ctx, const char *path, int w, int h, const double *values,
                                         const lx_falsecolor_opts *opts);

/** Tone-mapped previews of n maps side by side (each panel 512 pixels wide, its own exposure:
 * median luminance to 0.18, Reinhard x/(1+x), sRGB), each labelled with labels[k] (may be NULL). */
LX_API lx_status lx_envmap_preview_write_png(lx_ctx *ctx, const char *path, int n, const lx_envmap *const *maps,
                                             const char *const *labels);

/** The preview of an irradiance computation: the radiance map tone-mapped on the left, the
 * irradiance map as illuminance (lum_per_unit x Y, lx) in false colour on the right (scale LOG or
 * AUTO: decade ticks; LINEAR: round ticks), with its legend and its minimum, median and maximum;
 * label (may be NULL) names the method. Both maps in the same layout (lat-long or cube). */
LX_API lx_status lx_irradiance_write_png(lx_ctx *ctx, const char *path, const lx_envmap *radiance,
                                         const lx_envmap *irradiance, const char *label, lx_plot_scale scale);

/** Chromaticity diagrams of the spectrum report. */
typedef enum lx_diagram { LX_DIAGRAM_XY = 0 /* CIE 1931 x, y */, LX_DIAGRAM_UV = 1 /* CIE 1976 u', v' */ } lx_diagram;

/** Options of lx_spd_report_write_png (zero-initialise for defaults). */
typedef struct lx_report_opts {
    lx_observer observer;  /* of the colorimetry and the diagram (0: LX_OBSERVER_2) */
    const char *unit;      /* what the values are, as `luxcalc spd --unit` takes them: "W/nm" (Y in
                            * lm), "W/m2/nm" (lx), "W/sr/m2/nm" (cd/m²), "W/sr/nm" (cd), NULL or
                            * "relative" (Y without a unit); LX_EINVAL for others */
    lx_diagram diagram;    /* the chromaticity diagram */
    const char *title;     /* the heading (NULL: spd->name) */
    long long reserved[4]; /* zero: room for later options (ABI policy) */
} lx_report_opts;

/** One-page PNG report of one spectrum (1200 x 860 pixels): the SPD with its unit and the area
 * under it in the colour of each wavelength (approximate sRGB); the headline numbers (absolute Y
 * in lm, lx, cd/m² or cd per the unit, radiant power, x, y, u', v', CCT, Duv, Ra, R9, Rf, Rg,
 * melanopic DER, efficacy); the colour of the light as a normalised sRGB swatch; the CIE 1931 xy
 * or 1976 u'v' diagram (spectral locus, Planckian locus, isotemperature lines labelled where the
 * labels collide with nothing, the point); CIE 13.3 Ra and R1-R14 bars and R15 (JIS Z 8726) with their values; the
 * TM-30 colour vector graphic with its 16 hue bins and an arrow with its head in each (the whole
 * TM-30 page: lx_tm30_report_write_png). A metric that is undefined for the spectrum
 * (lx_cri_compute or lx_tm30_compute refuse) is shown with its reason instead. Errors: those of
 * lx_spd_check and lx_spd_colorimetry, and the writers' above. */
LX_API lx_status lx_spd_report_write_png(lx_ctx *ctx, const lx_spd *spd, const lx_report_opts *opts,
                                         const char *path);

/** The ANSI/IES TM-30-20 colour rendition report of one spectrum as a PNG page (1200 x 1080), laid
 * out as the IES TM-30-20 calculator prints it: the test and reference spectra at equal luminous
 * flux; the colour vector graphic (the hue bins in the calculator's colours, the +-10 % and +-20 %
 * chroma circles, the reference circle, the test's shape in red, an arrow with its head from the
 * reference to the test in each bin) with Rf, Rg, CCT and Duv at its corners; bar charts of the
 * local chroma shift Rcs,hj (-40..40 %), hue shift Rhs,hj (-0.5..0.5) and fidelity Rf,hj (0..100)
 * of the 16 bins, each value on its bar; the fidelity of the 99 samples (Rf,CESi, each bar in the
 * sample's colour under D65); and the numbers (Rf, Rg, CCT, Duv, x, y, u', v', CIE Ra and R9).
 * opts: only title is used (may be NULL). Errors: those of lx_tm30_compute (LX_ERANGE where TM-30
 * is undefined: the page would have nothing to show) and the writers' above. */
LX_API lx_status lx_tm30_report_write_png(lx_ctx *ctx, const lx_spd *spd, const lx_report_opts *opts, const char *path);

/** Writes an sRGB preview PNG of an XYZ image (XYZ -> linear sRGB, exposure from the median
 * luminance, Reinhard tone curve), enlarged to at least 256 pixels wide. */
LX_API lx_status lx_xyz_image_write_png(lx_ctx *ctx, const char *path, const lx_xyz_image *img);

/** Kinds of outline on a plan, each drawn in its own style as lighting-design plans draw them. */
typedef enum lx_outline_kind {
    LX_OUTLINE_WALL = 0,    /* a room's boundary: a heavy line, sRGB (55, 55, 62), 4 px */
    LX_OUTLINE_OBSTRUCTION, /* furniture (a desk): a fine dark outline over a light veil */
    LX_OUTLINE_SURFACE,     /* a partition or free-standing surface: a brown line, (122, 74, 30), 3.5 px */
    LX_OUTLINE_OPENING,     /* a window, door or roof light: a light-blue band (150, 215, 250) edged in dark blue */
    LX_OUTLINE_LUMINAIRE    /* a luminaire's luminous area: a fine dashed line */
} lx_outline_kind;

/** A 2-D outline on a plot's plane: n vertices (a, b) in metres along the plane's u and v from its
 * origin (the coordinates of lx_plane's a0 .. b1). A value (ABI policy: never changes). */
typedef struct lx_plot_outline {
    lx_outline_kind kind;
    int closed;             /* 1: the last vertex joins the first (a polygon); 0: a polyline */
    size_t n;               /* vertices (1: drawn as a dot) */
    const double *ab_m;     /* n x 2 */
    const char *name;       /* what it is ("office", "desk"; NULL: none) */
} lx_plot_outline;

/** What an isolux plot shows. */
typedef enum lx_plot_quantity {
    LX_PLOT_ILLUMINANCE = 0,    /* illuminance in lx (fc with imperial) */
    LX_PLOT_DAYLIGHT_FACTOR = 1 /* the daylight factor in % (never converted) */
} lx_plot_quantity;

/** A luminaire marked on an isolux plot: where it is, where its nadir points, its name. */
typedef struct lx_plot_mark {
    double pos_m[3];
    double aim[3];          /* any length > 0; (0, 0, 0): not drawn */
    const char *name;       /* drawn beside the mark where it fits (NULL: none) */
} lx_plot_mark;

/** Backgrounds of isolux plots. */
typedef enum lx_isolux_background {
    LX_ISOLUX_FALSECOLOR = 0, /* false colour under dark contour lines */
    LX_ISOLUX_WHITE = 1       /* white, contour lines in the colours of their levels */
} lx_isolux_background;

/** Options of lx_grid_write_png (zero-initialise for defaults). */
typedef struct lx_isolux_opts {
    lx_isolux_background background;
    lx_plot_scale scale;          /* AUTO: log where E_max / E_min > 20, else linear */
    const lx_plot_mark *marks;    /* the luminaires (marks outside the area are left out) */
    size_t n_marks;
    const char *source;           /* the file the light comes from; its base name goes in the title */
    const char *surface;          /* the calculation surface's name ("desk"; NULL: none) */
    const char *caption;          /* a line under the title (a scene's title; NULL: none) */
    double area_m[4];             /* A0, A1, B0, B1 of the area drawn when A1 > A0 or B1 > B0 (the
                                   * calculation area around cell-centre points); else the points' extent */
    int imperial;                 /* 1: fc and ft instead of lx and m */
    /* taken from the reserved space (ABI policy: the struct keeps its size and offsets on LP64) */
    const lx_plot_outline *outlines; /* walls, obstructions, partitions, openings and luminous areas drawn
                                   * over the plot (lx_scene_outlines makes a scene's; NULL: none); the
                                   * view grows to take in those that reach within half the area's size */
    size_t n_outlines;
    int quantity;                 /* lx_plot_quantity of the values (0: illuminance) */
    long long reserved[1];        /* zero: room for later options (ABI policy) */
} lx_isolux_opts;

/** An isolux plot of the illuminance E on a plane (na x nb values, A fastest, as lx_plane_points
 * orders them), the way DIALux and AGi32 print a calculation surface: the plane in false colour
 * (or white) under contour lines at round levels of a 1-2-5 series, each labelled in lx on its
 * line; the luminaires' positions (projected along the plane's normal) with their aim; axes in
 * metres with round ticks; a legend with round (or decade) ticks and the unit; the plane and the
 * source file's base name in the title; and a statistics box: E_avg, E_min, E_max, U0 = E_min /
 * E_avg and E_min / E_max (4 significant digits, U0 3 decimals). opts may be NULL. */
LX_API lx_status lx_grid_write_png(lx_ctx *ctx, const char *path, const lx_plane *plane, const double *E_lx,
                                   const lx_isolux_opts *opts);

/** Options of lx_scene_report_write_pdf (zero-initialise for defaults). */
typedef struct lx_pdf_report_opts {
    const char *title;        /* the report's title (NULL: the scene's title, or its file name) */
    const char *project;      /* a line under it: the project, the client (NULL: none) */
    const char *author;       /* the designer (NULL: none) */
    lx_backend backend;       /* where the scene's work runs (AUTO: the size decides) */
    int imperial;             /* 1: fc and ft in the plots and tables */
    long long reserved[4];    /* zero: room for later options (ABI policy) */
} lx_pdf_report_opts;

/** The design report of a scene as a vector PDF (A4, DejaVu Sans; written atomically): a title page
 * (the values maintained or new, the checks' count), the luminaire schedule (photometry, flux, power,
 * efficacy, maintenance factor, count), each room's plan (walls, obstructions, areas, luminaires,
 * observers), the areas' statistics and each grid's isolux plot, the checks against the requirements,
 * UGR at the observers and the CIE 190 table of each photometric file, emergency lighting (EN 1838),
 * energy (EN 15193-1) and the method: the planner's effects and reasons, the tolerances and what was
 * approximated by how much. The scene is planned and evaluated here (and in emergency operation, its
 * glare and energy, where it has what they need). Errors: those of planning and evaluating the scene,
 * of the checks, and the plot writers' (LX_EIO, LX_EWRITE: nothing is left at path). opts may be NULL. */
LX_API lx_status lx_scene_report_write_pdf(lx_ctx *ctx, const lx_scene *scene, const lx_pdf_report_opts *opts,
                                           const char *path);
/** A scene's geometry on the plane of a plot, as outlines for lx_isolux_opts: the walls of every room
 * the plane passes through, every obstruction, surface and opening, and the luminous area of every
 * luminaire that has one (disk, rectangle, a photometric file's opening), each projected along the
 * plane's normal as the convex hull of its corners (a partition or a window seen edge-on is a
 * segment). Names point into the scene (valid while it lives). *out is one block, NULL when there
 * is nothing to draw, freed with lx_scene_outlines_free (accepts NULL). Errors: LX_EINVAL (NULL),
 * LX_ENOMEM. Thread-safe for distinct contexts. */
LX_API lx_status lx_scene_outlines(lx_ctx *ctx, const lx_scene *scene, const lx_plane *plane, lx_plot_outline **out,
                                   size_t *n);
LX_API void lx_scene_outlines_free(lx_plot_outline *outlines);

/** The plane of grid receiver `receiver` as lx_grid_write_png takes it: its first free axis (x
 * before y before z) as u, the second as v, the points' extent, na x nb, the receiver's normal.
 * Errors: LX_EINVAL (NULL, an index out of range, a point receiver). */
LX_API lx_status lx_scene_receiver_plane(lx_ctx *ctx, const lx_scene *scene, size_t receiver, lx_plane *out);

/** Options of lx_scene_receiver_write_png (zero-initialise for defaults). */
typedef struct lx_receiver_png_opts {
    lx_plot_quantity quantity;        /* ILLUMINANCE (the result's E_lx) or DAYLIGHT_FACTOR (daylight_factor) */
    lx_isolux_background background;
    lx_plot_scale scale;              /* AUTO: as lx_grid_write_png */
    int imperial;                     /* 1: fc and ft */
    int no_outlines;                  /* 1: the luminaires' marks only (no rooms, obstructions, surfaces, openings) */
    long long reserved[4];            /* zero: room for later options (ABI policy) */
} lx_receiver_png_opts;

/** The isolux plot of grid receiver `receiver` of an evaluated scene (res: lx_scene_eval of this
 * scene), as lx_grid_write_png draws it, with the scene's luminaires marked and its outlines
 * (lx_scene_outlines) drawn; the view takes in the rooms the plane cuts. The title names the
 * receiver, the plane and the scene file, the caption is the scene's title. DAYLIGHT_FACTOR plots
 * res->daylight_factor in % with DF contours and statistics. Errors: LX_EINVAL (NULL, an index out
 * of range, a point receiver, a result of another scene, a daylight factor the scene does not
 * define), and those of lx_grid_write_png. opts may be NULL. */
LX_API lx_status lx_scene_receiver_write_png(lx_ctx *ctx, const char *path, const lx_scene *scene,
                                             const lx_scene_result *res, size_t receiver,
                                             const lx_receiver_png_opts *opts);

/** One point of an error-against-time plot: a method's time (s) and error (any unit > 0; 0 or
 * less is drawn on the bottom edge, marked "= 0"), its label and series (marker shape and colour). */
typedef struct lx_plot_point {
    double time_s;
    double error;
    const char *label;   /* drawn beside the marker where it collides with nothing, else joined
                          * to it by a leader line (may be NULL) */
    int series;          /* 0 .. n_series - 1 */
} lx_plot_point;

/** A log-log scatter plot as PNG: error (vertical, log10) against time (horizontal, log10), one
 * marker and label per point, a legend of the series names, axis titles and a title (all may be
 * NULL). LX_EINVAL for n = 0 or a point whose time is not positive and finite. */
LX_API lx_status lx_error_time_write_png(lx_ctx *ctx, const char *path, const char *title, const char *x_title,
                                         const char *y_title, size_t n, const lx_plot_point *pts, int n_series,
                                         const char *const *series_names);

#ifdef __cplusplus
}
#endif
#endif /* LUXCALC_H */
