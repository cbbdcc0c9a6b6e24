/* batch_colorimetry.c - every colorimetric quantity for a batch of spectra on one grid: the
 * integrals at once (lx_batch_integrate), then CCT/Duv (the fast solver, cct_fast.c) and the rest
 * per spectrum on threads. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>

typedef struct job {
    const lx_batch *b;
    lx_observer obs;
    double lo_K, hi_K;  /* the CCT range as Planckian radiators at its ends show it on this grid */
    const double *ints; /* n x 4: xbar, ybar, zbar, V' integrals */
    lx_colorimetry *out;
    lx_status st[64];   /* per thread */
} job;

/* Value j of spectrum i, times 2^-e. */
static double value_at(const lx_batch *b, size_t i, size_t j, int e)
{
    size_t stride = b->row_stride ? b->row_stride : b->n_lambda;
    double v = b->dtype == LX_F32 ? (double)((const float *)b->values)[i * stride + j]
                                  : ((const double *)b->values)[i * stride + j];
    return e ? ldexp(v, -e) : v;
}

double lx__batch_radiant(const lx_batch *b, size_t i)
{
    size_t stride = b->row_stride ? b->row_stride : b->n_lambda;
    double sum = 0.0;
    if (b->n_lambda < 2) return 0.0;
    if (b->dtype == LX_F32) {
        const float *v = (const float *)b->values + i * stride;
        for (size_t j = 0; j + 1 < b->n_lambda; j++) sum += (double)v[j] + (double)v[j + 1];
    } else {
        const double *v = (const double *)b->values + i * stride;
        for (size_t j = 0; j + 1 < b->n_lambda; j++) sum += v[j] + v[j + 1];
    }
    double r = 0.5 * b->step_nm * sum; /* the trapezoid rule, as lx_spd_integrate_radiant */
    if (isfinite(r) || !isinf(sum)) return r;
    /* values near the top of the double range: the sum again scaled by 2^-e (exact), then back,
     * so a partial sum that overflowed does not make the integral overflow */
    double m = 0;
    for (size_t j = 0; j < b->n_lambda; j++) m = fmax(m, fabs(value_at(b, i, j, 0)));
    int e = 0;
    frexp(m, &e);
    sum = 0.0;
    for (size_t j = 0; j + 1 < b->n_lambda; j++) sum += value_at(b, i, j, e) + value_at(b, i, j + 1, e);
    return ldexp(0.5 * b->step_nm * sum, e);
}

/* The range ends of the last grids seen in this process (they depend on the grid and observer
 * only; computing them takes two blackbody integrations and exact CCT solves, about 100 us, which
 * a stream of parts of 120 spectra would otherwise pay for every part). */
static struct range_entry {
    int obs;
    size_t n;
    double start, step, lo, hi;
} ranges[4];
static int ranges_next;
static pthread_mutex_t ranges_lock = PTHREAD_MUTEX_INITIALIZER;

static int range_cached(lx_observer obs, const lx_batch *b, double *lo, double *hi)
{
    int hit = 0;
    pthread_mutex_lock(&ranges_lock);
    for (int i = 0; i < 4 && !hit; i++)
        if (ranges[i].n == b->n_lambda && ranges[i].obs == (int)obs && ranges[i].start == b->start_nm &&
            ranges[i].step == b->step_nm)
            *lo = ranges[i].lo, *hi = ranges[i].hi, hit = 1;
    pthread_mutex_unlock(&ranges_lock);
    return hit;
}

static void range_keep(lx_observer obs, const lx_batch *b, double lo, double hi)
{
    pthread_mutex_lock(&ranges_lock);
    ranges[ranges_next] = (struct range_entry){(int)obs, b->n_lambda, b->start_nm, b->step_nm, lo, hi};
    ranges_next = (ranges_next + 1) % 4;
    pthread_mutex_unlock(&ranges_lock);
}

/* Spectrum i of the batch through lx_spd_colorimetry (cie15 at the grid), which scales values near the
 * bottom of the double range up before integrating (the batch sums round every subnormal term). */
static lx_status row_exact(lx_ctx *ctx, const job *j, size_t i)
{
    size_t n = j->b->n_lambda;
    double *buf = lx__alloc_n(2 * n, sizeof *buf);
    if (!buf) return LX_ENOMEM;
    for (size_t k = 0; k < n; k++) buf[k] = j->b->start_nm + (double)k * j->b->step_nm, buf[n + k] = value_at(j->b, i, k, 0);
    lx_spd s = {.n = n, .lambda_nm = buf, .value = buf + n, .name = "row"};
    lx_status st = lx_spd_colorimetry(ctx, &s, j->obs, LX_METHOD_CIE15, &j->out[i]);
    lx__free(buf);
    return st;
}

/* Spectra [i0, i1) on thread t, with a context of its own (a context is one thread's). */
static void work(void *arg, long i0, long i1, int t)
{
    job *j = arg;
    lx_ctx *ctx = NULL;
    if ((j->st[t] = lx_ctx_create(&ctx)) != LX_OK) return;
    for (long i = i0; i < i1 && j->st[t] == LX_OK; i++) {
        const double *q = j->ints + 4 * i;
        double rad = lx__batch_radiant(j->b, i), big = fmax(fmax(fabs(q[0]), fabs(q[1])), fmax(fmax(fabs(q[2]), fabs(q[3])), fabs(rad)));
        if (big > 0 && big < 0x1p-540) { /* a row of values below 2^-600 or so: its integrals lost digits */
            j->st[t] = row_exact(ctx, j, (size_t)i);
            continue;
        }
        j->out[i].method = LX_METHOD_CIE15;
        j->st[t] = lx__colorimetry_fast(ctx, j->obs, q, q[3], rad, j->lo_K, j->hi_K, &j->out[i]);
    }
    lx_ctx_destroy(ctx);
}

lx_status lx_batch_colorimetry(lx_ctx *ctx, const lx_batch *b, lx_observer obs, const lx_batch_opts *opts,
                               lx_colorimetry *out)
{
    LX__NEED_CTX(ctx);
    if (!b || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch and output are required");
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    if (b->n_spectra == 0) return LX_OK;
    if (b->n_lambda < 2) return lx__error(ctx, LX_EINVAL, NULL, 0, "a spectrum needs at least 2 samples");
    lx_function f0 = obs == LX_OBSERVER_2 ? LX_FN_XBAR_2 : LX_FN_XBAR_10;
    lx_function fns[4] = {f0, f0 + 1, f0 + 2, LX_FN_VPRIME};
    double *ints = lx__alloc_n(4 * b->n_spectra, sizeof(double));
    if (!ints) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for %zu spectra", b->n_spectra);
    lx_status st = lx_batch_integrate(ctx, b, fns, 4, opts, ints);
    if (st != LX_OK) {
        lx__free(ints);
        return st;
    }
    /* below 256 spectra a thread costs more than the CCT solves it takes over */
    int nt = b->n_spectra < 256 ? 1 : lx__threads(opts ? opts->threads : 0, (long)b->n_spectra);
    job J = {.b = b, .obs = obs, .lo_K = 1000.0, .hi_K = 100000.0, .ints = ints, .out = out};
    /* the range ends through the grid's own sampling (the batch sums at the grid's step, the CIE 015
     * rule), as lx_spd_colorimetry takes them: a blackbody at an end is in the range */
    if (!range_cached(obs, b, &J.lo_K, &J.hi_K)) {
        double *grid = lx__alloc_n(b->n_lambda, sizeof *grid);
        if (grid) {
            for (size_t k = 0; k < b->n_lambda; k++) grid[k] = b->start_nm + (double)k * b->step_nm;
            lx_spd g = {.n = b->n_lambda, .lambda_nm = grid, .value = grid, .name = "grid"};
            lx__cct_range_ends(ctx, &g, obs, LX_METHOD_CIE15, &J.lo_K, &J.hi_K);
            lx__free(grid);
            range_keep(obs, b, J.lo_K, J.hi_K);
        }
    }
    lx__parallel_for(ctx, nt, (long)b->n_spectra, work, &J);
    lx__free(ints);
    for (int t = 0; t < nt; t++)
        if (J.st[t] != LX_OK) return lx__error(ctx, J.st[t], NULL, 0, "batch colorimetry failed: %s", lx_strerror(J.st[t]));
    return LX_OK;
}
