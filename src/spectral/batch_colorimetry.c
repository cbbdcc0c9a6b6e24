/* batch_colorimetry.c - every colorimetric quantity for a batch of spectra on one grid: the
 * integrals at once (lx_batch_integrate), then CCT/Duv and the rest per spectrum on threads. */
#include "lx_private.h"

#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct job {
    const lx_batch *b;
    lx_observer obs;
    const double *ints; /* n x 4: xbar, ybar, zbar, V' integrals */
    lx_colorimetry *out;
    size_t i0, i1;
    lx_status st;
} job;

static double radiant_of(const lx_batch *b, size_t i)
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
    return 0.5 * b->step_nm * sum; /* the trapezoid rule, as lx_spd_integrate_radiant */
}

static void *work(void *arg)
{
    job *j = arg;
    lx_ctx *ctx = NULL;
    if ((j->st = lx_ctx_create(&ctx)) != LX_OK) return NULL;
    for (size_t i = j->i0; i < j->i1 && j->st == LX_OK; i++) {
        j->out[i].method = LX_METHOD_CIE15;
        j->st = lx_colorimetry_from_integrals(ctx, j->obs, j->ints + 4 * i, j->ints[4 * i + 3], radiant_of(j->b, i),
                                              &j->out[i]);
    }
    lx_ctx_destroy(ctx);
    return NULL;
}

lx_status lx_batch_colorimetry(lx_ctx *ctx, const lx_batch *b, lx_observer obs, lx_batch_opts *opts, lx_colorimetry *out)
{
    if (!b || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch and output are required");
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    if (b->n_spectra == 0) return LX_OK;
    if (b->n_lambda < 2) return lx__error(ctx, LX_EINVAL, NULL, 0, "a spectrum needs at least 2 samples");
    lx_function f0 = obs == LX_OBSERVER_2 ? LX_FN_XBAR_2 : LX_FN_XBAR_10;
    lx_function fns[4] = {f0, f0 + 1, f0 + 2, LX_FN_VPRIME};
    double *ints = malloc(sizeof(double) * 4 * b->n_spectra);
    if (!ints) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for %zu spectra", b->n_spectra);
    lx_status st = lx_batch_integrate(ctx, b, fns, 4, opts, ints);
    if (st != LX_OK) {
        free(ints);
        return st;
    }
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    size_t nt = opts && opts->threads > 0 ? (size_t)opts->threads : ncpu > 0 ? (size_t)ncpu : 1;
    if (nt > 64) nt = 64;
    if (b->n_spectra < 256) nt = 1; /* a thread costs more than a few CCT solves */
    job jobs[64];
    pthread_t tid[64];
    int started[64] = {0};
    for (size_t t = 0; t < nt; t++) {
        jobs[t] = (job){b, obs, ints, out, b->n_spectra * t / nt, b->n_spectra * (t + 1) / nt, LX_OK};
        if (t + 1 < nt && pthread_create(&tid[t], NULL, work, &jobs[t]) == 0) started[t] = 1;
    }
    for (size_t t = 0; t < nt; t++)
        if (!started[t]) work(&jobs[t]); /* the last range, and any whose thread did not start */
    for (size_t t = 0; t < nt; t++)
        if (started[t]) pthread_join(tid[t], NULL);
    free(ints);
    for (size_t t = 0; t < nt; t++)
        if (jobs[t].st != LX_OK) return lx__error(ctx, jobs[t].st, NULL, 0, "batch colorimetry failed: %s", lx_strerror(jobs[t].st));
    return LX_OK;
}
