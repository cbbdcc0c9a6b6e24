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
    double *u, *v;
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
};

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

#endif /* LX_PRIVATE_H */
