/* lx_private.h - internals shared across the library's source files (never installed).
 * Holds the context layout, the error helpers and the embedded-table registry. */
#ifndef LX_PRIVATE_H
#define LX_PRIVATE_H

#include "luxcalc.h"

#include <stdarg.h>
#include <stddef.h>

#define LX__ERRMSG_MAX 1024

/* The locus cache: CIE 1960 uv of the Planckian radiator at nodes spaced evenly in log T. */
typedef struct lx__locus {
    int ready;
    int n;
    double logt0, dlogt;
    double *u, *v; /* v, du/ds and dv/ds follow u in one block of 4n doubles */
} lx__locus;

struct lx_ctx {
    lx_status status;
    char errmsg[LX__ERRMSG_MAX];
    char errfile[256];
    long errline;
    lx_log_fn log_fn;
    void *log_user;
    lx_log_level log_max;
    lx__locus locus[2]; /* [0] 2 deg, [1] 10 deg */
    void *cl;                         /* OpenCL state, NULL until first used */
    void (*cl_release)(lx_ctx *ctx);  /* frees cl; set by whoever creates it */
    lx_counters counters;             /* work counters (scenes, issue 8) */
    struct lx__wcache *wcache;        /* the last CPU batch weights (batch.c) */
};

/* The vector line parser of the batch CSV reader (csv_vector.c): the line of n short decimals
 * separated by sep that starts at q, up to its '\n' (or '\r\n') before stop, or up to stop itself
 * when whole (stop is the end of the text); 64 bytes past stop are readable. The values go to dst
 * (float when f32), each correctly rounded as strtod; *line_end gets the line's end (its '\n', or
 * stop). 0 when any field is not "-?D+(.D*)?" of at most 15 characters, the count is not n, or no
 * line end comes before stop (the general parser then reads the line). lx__csv_have_fast_line: 1
 * when this CPU runs it (AVX-512 F, BW, DQ, VL, BMI2, POPCNT). */
int lx__csv_fast_line(const char *q, const char *stop, int whole, char sep, size_t n, int f32, void *dst,
                      const char **line_end);
int lx__csv_have_fast_line(void);

/* Frees a context's batch weights (batch.c). */
void lx__wcache_free(struct lx__wcache *c);

/* Records an error on ctx and returns status. file may be NULL, line <= 0 when it does not apply. */
lx_status lx__error(lx_ctx *ctx, lx_status status, const char *file, long line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

/* Delivers a message to the log callback when one is installed and level <= its maximum. */
void lx__log(lx_ctx *ctx, lx_log_level level, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* ---- embedded tables (generated from the src/data CSV files by src/tools/lxgen.c) ---- */
typedef struct lx__table {
    const char *name;             /* file stem, e.g. "cie1931_2deg_xyz_1nm" */
    const char *provenance;       /* the file's '#' comment lines */
    int nrows, ncols;             /* ncols counts the wavelength column */
    const char *const *colnames;  /* ncols names */
    const double *data;           /* column-major: data[c * nrows + r]; NaN = empty cell */
} lx__table;

extern const lx__table lx__tables[];
extern const int lx__ntables;

/* Finds a table by name (NULL when absent) and a column by name (-1 when absent). */
const lx__table *lx__table_find(const char *name);
int lx__table_col(const lx__table *t, const char *col);

/* A view of column col, trimmed to the rows where it is defined (not NaN). */
int lx__table_view(const lx__table *t, int col, lx_spd *out);

/* ---- embedded kernels (generated from the kernels/ .cl files) ---- */
typedef struct lx__kernel_source {
    const char *name;   /* file name, e.g. "spd_integrate.cl" */
    const char *source; /* the text */
} lx__kernel_source;

extern const lx__kernel_source lx__kernel_sources[];
extern const int lx__nkernel_sources;

/* ---- numerics shared across files ---- */
/* Linear interpolation of a sampled function at x; 0 outside [xs[0], xs[n-1]]. */
double lx__interp(const double *xs, const double *ys, size_t n, double x);

/* ---- OpenCL runtime and batches (issue 3: src/opencl.c, src/batch.c) ---- */
#if LX_OPENCL
#include <CL/cl.h>
/* The OpenCL state behind ctx->cl: the device choice, then (once initialised) the context,
 * queue and the lazily built program with its build log. */
typedef struct lx__cl {
    int sel_platform, sel_device; /* -1: any (environment LX_PLATFORM / LX_DEVICE apply) */
    lx_cl_type sel_type;
    int ready;                    /* context and queue exist */
    int borrowed;                 /* context and queue came from the caller */
    cl_platform_id platform;
    cl_device_id device;
    cl_context context;
    cl_command_queue queue;
    lx_cl_device_info info;
    cl_program program;           /* NULL until the first kernel is needed */
    char *build_log;              /* of the last build (kept for error messages) */
} lx__cl;

/* The OpenCL state of ctx, initialised on first call (platform, device, context, queue). */
lx_status lx__cl_get(lx_ctx *ctx, lx__cl **out);
/* A kernel by name from the program, built on first call (embedded sources or LX_KERNEL_DIR). */
lx_status lx__cl_kernel(lx_ctx *ctx, lx__cl *cl, const char *name, cl_kernel *out);
/* The OpenCL error name for a code ("CL_OUT_OF_RESOURCES"), or "CL_UNKNOWN_ERROR". */
const char *lx__cl_errname(cl_int err);
/* Records LX_EDEVICE "CALL failed: NAME (CODE)" on ctx when err != CL_SUCCESS; returns the status. */
lx_status lx__cl_check(lx_ctx *ctx, cl_int err, const char *call);
#endif
/* The batch weight matrix: w[f * n_lambda + j] = w_f(start + j step) * step (cie15 rule). */
lx_status lx__batch_weights(lx_ctx *ctx, const lx_function *fns, size_t k, double start_nm, double step_nm,
                            size_t n_lambda, double *w);

/* ---- spectral file readers (spd_read.c, cgats.c, numparse.c) ---- */
/* Parses one decimal number at [s, end): optional sign, digits with an optional '.', optional
 * exponent. Returns the end of the number, or NULL when there is none or it runs straight into
 * more word characters ("nan", "inf", "0x1p3", "1e", "12abc" all give NULL). Correctly rounded
 * (bit-identical to strtod); overflow gives +-HUGE_VAL like strtod. Thread-safe. */
const char *lx__parse_double(const char *s, const char *end, double *out);
/* The same, accepting point (e.g. ',') as a decimal point besides '.' (0 for none). */
const char *lx__parse_double_ex(const char *s, const char *end, char point, double *out);

/* A cursor over the lines of a buffer: LF or CRLF; line counts from 1 after the first call. */
typedef struct lx__lines {
    const char *p, *end;
    long line;
} lx__lines;
/* Sets [*s, *e) to the next line without its line ending; returns 0 at the end of the buffer. */
int lx__next_line(lx__lines *it, const char **s, const char **e);

/* Parses the whole of [s, e) as a finite number or records an LX_EPARSE naming file:line and
 * what ("wavelength", "value"): not a number, NaN/Inf text, or overflow. */
lx_status lx__parse_field(lx_ctx *ctx, const char *file, long line, const char *s, const char *e,
                          char point, const char *what, double *out);

/* Builds a set from parsed data: nlam wavelengths lambda[k * lam_stride] (on lines lam_line[k],
 * or all on lam_line_all when lam_line is NULL), nspec spectra whose value at sample k is
 * val[s * ss + k * ks], names[s] (copied; NULL gives "1", "2", ...), lines[s]. Sorts samples by
 * wavelength, rejects duplicates, non-positive or non-finite wavelengths, fewer than 2 samples. */
lx_status lx__spd_set_build(lx_ctx *ctx, const char *file, size_t nlam, const double *lambda,
                            size_t lam_stride, const long *lam_line, long lam_line_all, size_t nspec,
                            const double *val, size_t ss, size_t ks, char *const *names,
                            const long *lines, lx_spd_set **out);

/* CGATS / Argyll spectral files (cgats.c): detection by content, and the reader. */
int lx__cgats_detect(const char *text, size_t len);
lx_status lx__cgats_read(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_spd_set **out);

/* ---- colour rendering (issue 7: src/cri.c, src/tm30.c) ---- */
/* The colour-quality grid for spd: step 5 nm for data uniformly sampled at 5 nm on multiples
 * of 5 nm, else 1 nm. */
double lx__quality_step(const lx_spd *spd);
/* Samples spd on the grid start_nm + i*step_nm, i < n (piecewise linear, zero outside). */
void lx__quality_sample(const lx_spd *spd, double start_nm, double step_nm, int n, double *out);
/* Samples table column col (linear interpolation, zero outside) on the same kind of grid. */
void lx__quality_table(const lx__table *t, int col, double start_nm, double step_nm, int n, double *out);
/* The fraction (max over X, Y, Z with the 2 deg CMFs) of the grid spectrum ref that lies
 * outside [lo_nm, hi_nm]. */
double lx__quality_outside(const double *ref, double start_nm, double step_nm, int n, double lo_nm, double hi_nm);


/* ---- luminaires and grids (issue 5: ies_read.c, ldt_read.c, photometry.c, grid.c) ---- */
/* A copy of [s, e) as a NUL-terminated string (NULL on allocation failure). */
char *lx__strndup(const char *s, const char *e);
/* The readers behind lx_luminaire_read_mem: LM-63 (any version) and EULUMDAT. */
lx_status lx__ies_read(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_luminaire **out);
lx_status lx__ldt_read(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_luminaire **out);
/* Validates the stored table of a freshly read luminaire (angles in order and complete for its
 * type, candela >= 0), sets its symmetry and expands it (full arrays). line_h / line_v: the lines
 * of the horizontal and vertical angle lists for messages. */
lx_status lx__lum_finish(lx_ctx *ctx, lx_luminaire *lum, long line_h, long line_v, long line_cd);
/* A luminaire with every field zero / NaN where that means "unknown" (NULL on no memory). */
lx_luminaire *lx__lum_new(const char *file);
/* Near-field integration over a luminous opening (grid.c; the scheme of scene_eval.c, shareable).
 * The n-level midpoint cells of an opening centred at the origin: a rectangle w x l in n x n cells,
 * a disk of diameter w in n rings of equal area x 2n sectors; every cell carries 1 / cells of the
 * area; cell c has its centre at (*a, *b) along the opening's axes. */
size_t lx__area_cells(int circular, int n);
void lx__area_cell(int circular, double w, double l, int n, size_t c, double *a, double *b);
/* Richardson-refined midpoint rule: mean(arg, n) (the mean over the n-level cells) for n = 2, 4,
 * 8, ... n_max; returns (4 S(n) - S(n/2)) / 3 once two successive extrapolations agree within tol
 * relative (n >= 8), else the last one. *cells (may be NULL) adds the cells evaluated; *converged
 * (may be NULL) 1 when the tolerance was met. */
double lx__area_refine(double (*mean)(void *arg, int n), void *arg, int circular, double tol, int n_max,
                       unsigned long long *cells, int *converged);

/* ---- radiance fields (issue 6: envmap.c, exr_io.c, irradiance*.c, png_plot.c) ---- */
/* Per-row and per-column factors of the exact pixel integrals of a w x h lat-long map: a pixel's
 * solid angle is row_sr[j] * dphi and its first moment (integral of omega) is
 * (row_s2[j] col_gx[i], row_s2[j] col_gy[i], row_sc[j] dphi). */
typedef struct lx__llgeom {
    int w, h;
    double dphi;    /* 2 pi / w */
    double *row_sr; /* cos t0 - cos t1 */
    double *row_s2; /* integral of sin^2 t dt over the row */
    double *row_sc; /* integral of sin t cos t dt over the row */
    double *col_gx; /* sin p1 - sin p0 */
    double *col_gy; /* cos p0 - cos p1 */
} lx__llgeom;
lx_status lx__llgeom_init(lx_ctx *ctx, lx__llgeom *g, int w, int h);
void lx__llgeom_free(lx__llgeom *g);
/* Threads to use for `asked` (0: every online core), at least 1 and at most `work` (when > 0). */
int lx__threads(int asked, long work);
/* Runs fn(arg, i0, i1, t) on `threads` threads (t = 0..threads-1) splitting [0, n) into contiguous
 * ranges; the calling thread runs the last one. LX_ENOMEM when a thread cannot start. */
lx_status lx__parallel_for(lx_ctx *ctx, int threads, long n, void (*fn)(void *arg, long i0, long i1, int t), void *arg);
/* The irradiance back ends: n_dirs unit normals (3 doubles each) -> out[n * channels]. */
lx_status lx__irr_brute_cpu(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads,
                            double *out);
lx_status lx__irr_brute_cl(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, double *out);
lx_status lx__irr_fast(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads,
                       double *out);
lx_status lx__irr_sh9_map(lx_ctx *ctx, const lx_sh9 *sh, lx_sh9_window window, lx_envmap *out);
/* Cube maps (envmap_cube.c). lx__cube_frame[f] = {axis, u, v}: the luxcalc directions of face f's
 * normal, image column and image row (downwards). A face-local table holds, per texel of an N x N
 * face (row-major), LX__CUBE_NT exact integrals over the texel in the frame (axis n, u, v):
 * solid angle, first moment (n, u, v), second moments (nn, uu, vv, nu, nv, uv). */
#define LX__CUBE_NT 10
extern const double lx__cube_frame[6][3][3];
double *lx__cube_table(int n); /* malloc'd N * N * LX__CUBE_NT doubles, NULL on no memory */
lx_status lx__sh9_project_cube(lx_ctx *ctx, const lx_envmap *map, lx_sh9 *out);
lx_status lx__irr_cube(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads, int fast,
                       double *out);

/* PNG plots (png_plot.c), reusable by any plot writer: an RGB8 canvas, a 5x7 font of our own
 * (digits, + - . e E / ( ) : = % and upper-case letters; lower case is drawn upper case), a
 * false-colour scale with a legend, a tone-mapped HDR preview, and an atomic PNG writer. */
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

/* ---- spectrum reports and spectral images (issue 7/3: report_png.c, spectral_exr.c) ---- */
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
/* Parses a Fichet et al. 2021 spectral channel name: *kind 0-3 for S0-S3 (emissive), 4 for T
 * (reflective), wavelength in nm; returns 0 on success, -1 when the name is not spectral. */
int lx__spectral_channel(const char *name, int *kind, double *lambda_nm);

/* ---- robustness (issue 10: file_open.c) ---- */
#include <stdio.h>
/* Opens path for reading: "-" gives stdin; a directory or a missing file is LX_EIO naming the path;
 * a FIFO waits at most LX_FIFO_WAIT_S seconds (default 10, 0: for ever) for its first data. */
lx_status lx__open_read(lx_ctx *ctx, const char *path, FILE **out);
/* Reads a whole input file (as lx__open_read opens it; "-" is standard input) into *text (malloc'ed,
 * not terminated) and *len. Errors name the file: LX_EIO, LX_ENOMEM, and lx__open_read's. */
lx_status lx__read_all(lx_ctx *ctx, const char *path, char **text, size_t *len);

#if LX_OPENCL
/* OpenCL fault injection for tests (opencl.c): with LX_CL_FAULT=CALL (every call of CALL fails) or
 * CALL:N (its N-th call in this process fails, counting from 1), the runtime layer makes that call fail
 * as a real device would: clGetPlatformIDs finds no platform, clBuildProgram fails to build,
 * clCreateBuffer fails to allocate, clEnqueueNDRangeKernel / clEnqueueReadBuffer / clFinish fail as a
 * failing kernel does. Every library file goes through these wrappers (the macros below). */
cl_int lx__clGetPlatformIDs(cl_uint n, cl_platform_id *p, cl_uint *np);
cl_int lx__clBuildProgram(cl_program p, cl_uint nd, const cl_device_id *d, const char *o,
                          void (CL_CALLBACK *fn)(cl_program, void *), void *u);
cl_mem lx__clCreateBuffer(cl_context c, cl_mem_flags f, size_t size, void *host, cl_int *err);
cl_int lx__clEnqueueNDRangeKernel(cl_command_queue q, cl_kernel k, cl_uint dim, const size_t *off, const size_t *gs,
                                  const size_t *ls, cl_uint nw, const cl_event *wl, cl_event *ev);
cl_int lx__clEnqueueReadBuffer(cl_command_queue q, cl_mem b, cl_bool blocking, size_t off, size_t size, void *ptr,
                               cl_uint nw, const cl_event *wl, cl_event *ev);
cl_int lx__clFinish(cl_command_queue q);
#define clGetPlatformIDs(...) lx__clGetPlatformIDs(__VA_ARGS__)
#define clBuildProgram(...) lx__clBuildProgram(__VA_ARGS__)
#define clCreateBuffer(...) lx__clCreateBuffer(__VA_ARGS__)
#define clEnqueueNDRangeKernel(...) lx__clEnqueueNDRangeKernel(__VA_ARGS__)
#define clEnqueueReadBuffer(...) lx__clEnqueueReadBuffer(__VA_ARGS__)
#define clFinish(...) lx__clFinish(__VA_ARGS__)
#endif

#endif /* LX_PRIVATE_H */
