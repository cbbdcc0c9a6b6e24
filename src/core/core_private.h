/* core_private.h - the bottom layer's internals, shared by every library file (never installed):
 * memory (the lx__alloc family), the context layout and its per-layer slots, error recording and the
 * log, physical constants, text input (whole-file reader, line cursor, number parsing), threads,
 * CPU-feature dispatch, the CPU/OpenCL backend rule and the OpenCL runtime. Nothing here knows a higher layer. */
#ifndef LX_CORE_PRIVATE_H
#define LX_CORE_PRIVATE_H

#include "luxcalc.h"

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#include "core/constants.h"
#include "core/limits.h"

#define LX__ERRMSG_MAX 1024

/* ---- memory (alloc.c) ----
 * The library allocates only through these (tests/cli/alloc.sh checks): every size is checked for
 * overflow (a product that does not fit in size_t, or anything from PTRDIFF_MAX up, fails as out of
 * memory), a zero size gives a unique pointer, and failure is NULL; the caller turns it into
 * LX_ENOMEM. Memory from any of them is freed with lx__free (also fine for memory from libc). In the
 * test build (LX_FAULTS) the k-th allocation can be made to fail (tests/test_nomem.c). */
void *lx__alloc(size_t size);
/* n * size bytes (uninitialised); NULL when the product overflows. */
void *lx__alloc_n(size_t n, size_t size);
/* n * size bytes, zeroed. */
void *lx__calloc(size_t n, size_t size);
/* realloc: on failure p is untouched and still owned by the caller. */
void *lx__realloc(void *p, size_t size);
void *lx__realloc_n(void *p, size_t n, size_t size);
/* size bytes aligned to align (a power of two; size is rounded up to a multiple of it). */
void *lx__alloc_aligned(size_t align, size_t size);
/* A copy of the string s (NULL without memory). */
char *lx__strdup(const char *s);
void lx__free(void *p);
/* a * b, or SIZE_MAX when it overflows (which then fails to allocate): for sizes of three factors,
 * lx__alloc_n(lx__size_mul(w, h), sizeof *p). */
size_t lx__size_mul(size_t a, size_t b);
#if defined(LX_FAULTS)
/* The test build: counting restarts at 0; the k-th allocation from now fails (k = 0: none), and with
 * persistent every one after it too. */
void lx__alloc_fault_set(long k, int persistent);
/* Allocations asked for since lx__alloc_fault_set; allocations not yet freed (lx__alloc calls that
 * returned memory minus lx__free calls on non-NULL pointers), since the process started. */
long lx__alloc_calls(void);
long lx__alloc_live(void);
#endif

/* ---- the context ---- */

/* State a higher layer keeps on a context (a cache), freed by its own function when the context
 * is destroyed. The slot ids are only names: core never looks inside. */
typedef enum lx__slot_id {
    LX__SLOT_LOCUS,   /* the Planckian locus tables of the CCT solver (spectral/cct.c) */
    LX__SLOT_WEIGHTS, /* the last CPU batch weights (spectral/batch.c) */
    LX__SLOT_COUNT
} lx__slot_id;

typedef struct lx__slot {
    void *data;
    void (*free_fn)(void *data);
} lx__slot;

struct lx_ctx {
    lx_status status;
    char errmsg[LX__ERRMSG_MAX];
    char errfile[256];
    long errline;
    lx_log_fn log_fn;
    void *log_user;
    lx_log_level log_max;
    lx__slot slot[LX__SLOT_COUNT];
    void *cl;                         /* OpenCL state, NULL until first used */
    void (*cl_release)(lx_ctx *ctx);  /* frees cl; set by whoever creates it */
    lx_counters counters;             /* work counters of the lighting and scene layers */
    size_t input_limit[LX_INPUT_KIND_COUNT]; /* bytes per lx_input_kind; 0: the default */
    lx_backend backend_used;          /* lx_ctx_backend_used: AUTO until a backend-choosing call succeeds */
    lx_irr_method irr_method;         /* lx_ctx_irradiance_method: AUTO until an irradiance call succeeds */
    double irr_fast_cost_ratio;       /* and AUTO's cost estimate for that call (NaN before) */
};

/* The data in slot id of ctx (NULL when empty or ctx is NULL). */
void *lx__slot_get(const lx_ctx *ctx, lx__slot_id id);
/* Replaces slot id's data (the old data is freed with its function); free_fn frees data with the
 * context. Returns data. */
void *lx__slot_set(lx_ctx *ctx, lx__slot_id id, void *data, void (*free_fn)(void *data));

/* The first statement of every public function that takes a context: a NULL context is LX_EINVAL
 * (there is nowhere to put the message; nothing else is read or written). */
#define LX__NEED_CTX(ctx)                                                                                    \
    do {                                                                                                     \
        if (!(ctx)) return LX_EINVAL;                                                                        \
    } while (0)

/* Records an error on ctx and returns status. file may be NULL, line <= 0 when it does not apply. */
lx_status lx__error(lx_ctx *ctx, lx_status status, const char *file, long line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

/* v as "%.3g" with a bare exponent (1e308, 2.5e-7), for messages. */
void lx__fmt_magnitude(char *buf, size_t cap, double v);
/* Checks the reserved space of an option struct (ABI policy, luxcalc.h): n bytes at p must be zero,
 * else LX_EINVAL naming what ("batch options"). */
lx_status lx__check_reserved(lx_ctx *ctx, const char *what, const void *p, size_t n);

/* Delivers a message to the log callback when one is installed and level <= its maximum. */
void lx__log(lx_ctx *ctx, lx_log_level level, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* ---- text input (file_open.c, lines.c, numparse.c) ---- */

/* Opens path for reading: "-" gives stdin; a directory or a missing file is LX_EIO naming the path;
 * a FIFO waits at most LX_FIFO_WAIT_S seconds (default LX__FIFO_WAIT_S, 0: for ever) for its first data. */
lx_status lx__open_read(lx_ctx *ctx, const char *path, FILE **out);
/* Reads a whole text input file of `kind` (as lx__open_read opens it; "-" is standard input: a
 * regular file, a character device, a FIFO or a pipe alike) into *text (malloc'ed, not terminated)
 * and *len, under the kind's size limit (lx_ctx_input_limit): a regular file larger than the limit
 * is refused before it is read, a stream when the limit is reached ("FILE: larger than N MB (raise
 * with LX_MAX_INPUT_MB)", LX_EIO). Binary input is refused as it arrives (LX_EPARSE, FILE:LINE): a
 * NUL byte anywhere; in the first LX__TEXT_PROBE_BYTES a UTF-16 byte-order mark or pattern, or
 * control bytes. Memory stays within the limit plus one block. Errors name the file: LX_EIO,
 * LX_EPARSE, LX_ENOMEM, LX_EINVAL (an unknown kind), and lx__open_read's. */
lx_status lx__read_all(lx_ctx *ctx, const char *path, lx_input_kind kind, char **text, size_t *len);
/* The same on a stream the caller opened (not closed), after the prefix_len bytes at prefix it
 * already read from it (they count towards the limit and are checked as the rest). */
lx_status lx__read_stream(lx_ctx *ctx, const char *path, lx_input_kind kind, FILE *fp, const char *prefix,
                          size_t prefix_len, char **text, size_t *len);
/* For readers that map a file instead (the streamed batch CSV): LX_OK when size is within kind's
 * limit, else lx__read_all's "larger than" error; and lx__read_all's binary-data checks on the
 * first block [buf, buf + n) of a text (only its first LX__TEXT_PROBE_BYTES are looked at). */
lx_status lx__input_size_check(lx_ctx *ctx, const char *path, lx_input_kind kind, unsigned long long size);
lx_status lx__text_check(lx_ctx *ctx, const char *path, const char *buf, size_t n);

/* ---- output files (file_write.c) ---- */

/* An output file written atomically: lx__wfile_open creates a temporary file beside path
 * (LX_EIO naming path when it cannot), lx__wfile_write writes all of buf (LX_EWRITE with the
 * system's reason: "No space left on device"), lx__wfile_close(ctx, w, st) with st == LX_OK
 * fsyncs, closes and renames into place, otherwise (or when anything failed) removes the
 * temporary file and returns the first error. A path that exists and is not a regular file (a
 * device, a FIFO) is opened and written directly (it is never replaced). */
typedef struct lx__wfile {
    int fd;
    int err;          /* errno of the first failed write (0: none) */
    const char *path; /* not owned */
    char *tmp;        /* the temporary file, NULL when writing path directly */
} lx__wfile;
lx_status lx__wfile_open(lx_ctx *ctx, const char *path, lx__wfile *w);
lx_status lx__wfile_write(lx_ctx *ctx, lx__wfile *w, const void *buf, size_t n);
lx_status lx__wfile_close(lx_ctx *ctx, lx__wfile *w, lx_status st);
/* Today's date as "YYYY-MM-DD" (UTC; SOURCE_DATE_EPOCH's when it is set, for reproducible
 * output), malloc'ed; NULL without memory. For the dates files carry (the IES [ISSUEDATE]). */
char *lx__date_today(void);

/* A cursor over the lines of a buffer: LF or CRLF; line counts from 1 after the first call. */
typedef struct lx__lines {
    const char *p, *end;
    long line;
} lx__lines;
/* Sets [*s, *e) to the next line without its line ending; returns 0 at the end of the buffer. */
int lx__next_line(lx__lines *it, const char **s, const char **e);
/* A copy of [s, e) as a NUL-terminated string (NULL on allocation failure). */
char *lx__strndup(const char *s, const char *e);

/* Parses one decimal number at [s, end): optional sign, digits with an optional '.', optional
 * exponent. Returns the end of the number, or NULL when there is none or it runs straight into
 * more word characters ("nan", "inf", "0x1p3", "1e", "12abc" all give NULL). Correctly rounded
 * (bit-identical to strtod); overflow gives +-HUGE_VAL like strtod. Thread-safe. */
const char *lx__parse_double(const char *s, const char *end, double *out);
/* The same, accepting point (e.g. ',') as a decimal point besides '.' (0 for none). */
const char *lx__parse_double_ex(const char *s, const char *end, char point, double *out);
/* Parses the whole of [s, e) as a finite number or records an LX_EPARSE naming file:line and
 * what ("wavelength", "value"): not a number, NaN/Inf text, or overflow. */
lx_status lx__parse_field(lx_ctx *ctx, const char *file, long line, const char *s, const char *e,
                          char point, const char *what, double *out);

/* ---- threads (parallel.c) ---- */

/* Threads to use for `asked` (0: every online core), at least 1 and at most `work` (when > 0). */
int lx__threads(int asked, long work);
/* Runs fn(arg, i0, i1, t) on `threads` threads (t = 0..threads-1) splitting [0, n) into contiguous
 * ranges; the calling thread runs the last one. A thread that cannot start leaves its range to the
 * calling thread, so the work is always done. */
lx_status lx__parallel_for(lx_ctx *ctx, int threads, long n, void (*fn)(void *arg, long i0, long i1, int t), void *arg);
/* Runs fn(arg, t) once on each of `threads` threads (t = 0..threads-1; the calling thread runs
 * t = 0), for work that hands out its own pieces (an atomic counter) or keeps per-thread state.
 * Returns the number of threads that ran (at least 1: when a thread cannot start, its t is not run,
 * and fn must not rely on every t running). */
int lx__parallel_run(int threads, void (*fn)(void *arg, int t), void *arg);
/* A team of threads running fn(arg, t) for t = t0 .. t0 + threads - 1 in the background while the
 * caller goes on (a pipeline: parse the next chunk while the caller hands on the last one).
 * lx__team_start returns how many started (the first that fails to start stops it; the caller
 * does the rest of the work itself); lx__team_join waits for them. */
#include <pthread.h>
typedef struct lx__team_job {
    void (*fn)(void *, int);
    void *arg;
    int t;
} lx__team_job;
typedef struct lx__team {
    pthread_t tid[64];
    lx__team_job job[64];
    int started;
} lx__team;
int lx__team_start(lx__team *team, int threads, int t0, void (*fn)(void *arg, int t), void *arg);
void lx__team_join(lx__team *team);

/* ---- CPU features (cpu.c) ---- */

/* The SIMD level is public (lx_simd_cpu, lx_simd_level, lx_simd_name in luxcalc.h). Extras
 * beyond a level's set, for the one path that uses them: */
/* 1 when the CPU has AVX-512 BITALG besides the AVX-512 set (the vector CSV line parser). */
int lx__cpu_has_bitalg(void);

/* ---- geometry (lambert.c) ---- */

/* The integral of max(0, n . w) dw over the directions w of the polygon v[0..nv-1] (vertices as
 * vectors from the viewpoint, in order, planar and convex; at most LX__POLY_MAX) seen from the
 * origin: Lambert's formula on the polygon clipped to n . x >= 0. n: unit. Exact (closed form). */
#define LX__POLY_MAX 8
double lx__polygon_projected(const double (*v)[3], int nv, const double n[3]);
/* Lambert's term of the straight edge a -> b (vectors from the viewpoint): the angle it subtends
 * times n . (a x b) / |a x b| (0 for a degenerate edge). Half the sum over a closed polygon's
 * edges is its projected solid angle, with the sign of its orientation. */
double lx__lambert_edge(const double a[3], const double b[3], const double n[3]);

/* ---- the backend rule (backend.c) ---- */

/* The backend for `work` units of a job whose OpenCL break-even is break_even units on a cold
 * context (OpenCL not yet initialised: the estimate includes starting it) and break_even_warm on
 * a warm one: asked (AUTO reads LX_BACKEND) resolved to CPU or OPENCL in *out. AUTO picks the CPU
 * when the build has no OpenCL, when work is below the break-even (OpenCL is then never touched),
 * when no device starts, or when the device is a CPU (the same cores); every decision is logged at
 * debug level as "JOB: backend auto: ...". LX_AUTO_BREAK_EVEN (in the job's units) overrides both
 * break-evens and the CPU-device rule (for measuring and tests). LX_EUNSUPPORTED when OPENCL is
 * asked of a build without OpenCL. */
lx_status lx__backend_choose(lx_ctx *ctx, const char *job, lx_backend asked, double work, double break_even,
                             double break_even_warm, lx_backend *out);
/* Records on ctx the backend a successful backend-choosing call used (lx_ctx_backend_used). */
void lx__backend_used(lx_ctx *ctx, lx_backend used);
/* After an OpenCL attempt failed with st: logs "JOB: OpenCL failed (...), using the CPU path" at
 * warning level and returns 1 when the caller should fall back (AUTO asked), else 0 (OPENCL asked:
 * the error stands). */
int lx__backend_fallback(lx_ctx *ctx, const char *job, lx_backend asked, lx_status st);

/* ---- OpenCL runtime (opencl.c) and the embedded kernels ---- */
typedef struct lx__kernel_source {
    const char *name;   /* file name in kernels/, e.g. "spd_batch.cl" */
    const char *source; /* the text */
} lx__kernel_source;

extern const lx__kernel_source lx__kernel_sources[];
extern const int lx__nkernel_sources;

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

#if defined(LX_FAULTS)
/* OpenCL fault injection, compiled only into test builds (LX_FAULTS; cl_faults.c): with
 * LX_CL_FAULT=CALL (every call of CALL fails) or CALL:N (its N-th call in this process fails,
 * counting from 1), the wrapped call fails as a real device would: clGetPlatformIDs finds no
 * platform, clBuildProgram fails to build, clCreateBuffer fails to allocate,
 * clEnqueueNDRangeKernel / clEnqueueReadBuffer / clFinish fail as a failing kernel does. The call
 * counters are atomic, so contexts on several threads may use it. */
cl_int lx__clGetPlatformIDs(cl_uint n, cl_platform_id *p, cl_uint *np);
cl_int lx__clBuildProgram(cl_program p, cl_uint nd, const cl_device_id *d, const char *o,
                          void (CL_CALLBACK *fn)(cl_program, void *), void *u);
cl_mem lx__clCreateBuffer(cl_context c, cl_mem_flags f, size_t size, void *host, cl_int *err);
cl_int lx__clEnqueueNDRangeKernel(cl_command_queue q, cl_kernel k, cl_uint dim, const size_t *off, const size_t *gs,
                                  const size_t *ls, cl_uint nw, const cl_event *wl, cl_event *ev);
cl_int lx__clEnqueueReadBuffer(cl_command_queue q, cl_mem b, cl_bool blocking, size_t off, size_t size, void *ptr,
                               cl_uint nw, const cl_event *wl, cl_event *ev);
cl_int lx__clFinish(cl_command_queue q);
/* Called when a context starts OpenCL: CALL:N counts from there. */
void lx__cl_fault_epoch(void);
#if !defined(LX_FAULTS_IMPL)
#define clGetPlatformIDs(...) lx__clGetPlatformIDs(__VA_ARGS__)
#define clBuildProgram(...) lx__clBuildProgram(__VA_ARGS__)
#define clCreateBuffer(...) lx__clCreateBuffer(__VA_ARGS__)
#define clEnqueueNDRangeKernel(...) lx__clEnqueueNDRangeKernel(__VA_ARGS__)
#define clEnqueueReadBuffer(...) lx__clEnqueueReadBuffer(__VA_ARGS__)
#define clFinish(...) lx__clFinish(__VA_ARGS__)
#endif
#endif /* LX_FAULTS */
#endif /* LX_OPENCL */

#endif /* LX_CORE_PRIVATE_H */
