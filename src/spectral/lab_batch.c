/* lab_batch.c - the lab quantities of a batch in one pass over its values: PAR, IEC 62471 hazards
 * and LED binning from one lx_batch_integrate of every weighting function they need, then each
 * spectrum's derived values on every core (the table-based CCT for the binning). */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { F_PAR = 0, F_HZ = 3, F_XYZ = 3 + LX_HZ_COUNT, F_MAX = 6 + LX_HZ_COUNT };

typedef struct lab_job {
    const lx_batch *b;
    const double *ints; /* n x k */
    size_t k;
    int at_par, at_hz, at_xyz; /* column of each group in ints, -1 when not asked */
    double cov[F_MAX];
    lx_par *par;
    lx_hazard *hz;
    lx_binning *bin;
    lx_status st[64];
} lab_job;

/* The radiant integral of spectrum i (the trapezoid rule, as lx_spd_integrate_radiant): the sum of
 * the values with eight accumulators, less half the two ends; lx__batch_radiant (which scales values
 * near the top of the double range) when that is not finite. */
static double radiant(const lx_batch *b, size_t i)
{
    size_t n = b->n_lambda, stride = b->row_stride ? b->row_stride : n, j = 0;
    double a[8] = {0}, first, last;
    if (b->dtype == LX_F32) {
        const float *v = (const float *)b->values + i * stride;
        for (; j + 8 <= n; j += 8)
            for (int k = 0; k < 8; k++) a[k] += (double)v[j + k];
        for (; j < n; j++) a[0] += (double)v[j];
        first = v[0], last = v[n - 1];
    } else {
        const double *v = (const double *)b->values + i * stride;
        for (; j + 8 <= n; j += 8)
            for (int k = 0; k < 8; k++) a[k] += v[j + k];
        for (; j < n; j++) a[0] += v[j];
        first = v[0], last = v[n - 1];
    }
    double sum = ((a[0] + a[1]) + (a[2] + a[3])) + ((a[4] + a[5]) + (a[6] + a[7]));
    double r = b->step_nm * (sum - 0.5 * (first + last));
    return isfinite(r) ? r : lx__batch_radiant(b, i);
}

static void rows(void *arg, long i0, long i1, int t)
{
    lab_job *j = arg;
    lx_ctx *ctx = NULL; /* the locus table of the table CCT is one context's */
    if (j->bin && (j->st[t] = lx_ctx_create(&ctx)) != LX_OK) return;
    for (long i = i0; i < i1; i++) {
        const double *r = j->ints + j->k * (size_t)i;
        if (j->par) {
            const double *p = r + j->at_par;
            double rad = radiant(j->b, (size_t)i);
            lx_par *o = &j->par[i];
            memset(o, 0, sizeof *o);
            o->ppfd = j->cov[F_PAR] >= LX_COVERAGE_MIN ? p[0] : NAN;
            o->epar = j->cov[F_PAR + 1] >= LX_COVERAGE_MIN ? p[1] : NAN;
            o->ypf = j->cov[F_PAR + 2] >= LX_COVERAGE_MIN ? p[2] : NAN;
            o->photon_efficacy_umol_J = rad > 0 ? o->ppfd / rad : NAN;
        }
        if (j->hz) {
            lx_hazard *o = &j->hz[i];
            memset(o, 0, sizeof *o);
            for (int q = 0; q < LX_HZ_COUNT; q++) {
                o->coverage[q] = j->cov[F_HZ + q];
                o->value[q] = o->coverage[q] >= LX_COVERAGE_MIN ? r[j->at_hz + q] : NAN;
            }
        }
        if (j->bin) {
            const double *p = r + j->at_xyz;
            double sum = p[0] + p[1] + p[2], d = p[0] + 15 * p[1] + 3 * p[2];
            double x = sum != 0 ? p[0] / sum : NAN, y = sum != 0 ? p[1] / sum : NAN, cct = NAN, duv = NAN;
            if (d > 0 && sum > 0) {
                lx_status st = lx__cct_from_uv_table(ctx, LX_OBSERVER_2, 4 * p[0] / d, 6 * p[1] / d, &cct, &duv);
                if (st != LX_OK && st != LX_ERANGE) {
                    j->st[t] = st;
                    break;
                }
            }
            if (lx__bin_xy(x, y, cct, duv, &j->bin[i]) != 0) {
                j->st[t] = LX_EINVAL;
                break;
            }
        }
    }
    lx_ctx_destroy(ctx);
}

lx_status lx_lab_batch(lx_ctx *ctx, const lx_batch *b, const lx_batch_opts *opts, lx_par *par, lx_hazard *hz,
                       lx_binning *bin)
{
    LX__NEED_CTX(ctx);
    if (!b || (!par && !hz && !bin)) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_lab_batch: NULL batch or no output");
    if (b->n_spectra == 0) return LX_OK;
    if (b->n_lambda < 2 || !(b->step_nm > 0))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "a batch needs at least 2 samples and a positive step");
    lx_function fns[F_MAX];
    static const lx_function xyz[3] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2};
    lab_job J;
    memset(&J, 0, sizeof J);
    J.b = b, J.par = par, J.hz = hz, J.bin = bin, J.at_par = J.at_hz = J.at_xyz = -1;
    size_t k = 0;
    if (par) J.at_par = (int)k, memcpy(fns + k, lx__par_fns, sizeof lx__par_fns), k += 3;
    if (hz) J.at_hz = (int)k, memcpy(fns + k, lx__hazard_fns, sizeof lx__hazard_fns), k += LX_HZ_COUNT;
    if (bin) J.at_xyz = (int)k, memcpy(fns + k, xyz, sizeof xyz), k += 3;
    /* coverage of each function over the grid: the same for every spectrum */
    double a = b->start_nm, e = b->start_nm + (double)(b->n_lambda - 1) * b->step_nm;
    for (int f = 0; f < F_XYZ; f++) {
        lx_spd w;
        lx_status st = lx_function_get(ctx, f < F_HZ ? lx__par_fns[f] : lx__hazard_fns[f - F_HZ], &w);
        if (st != LX_OK) return st;
        J.cov[f] = lx__coverage(&w, a, e);
    }
    double *ints = lx__alloc_n(k * b->n_spectra, sizeof(double));
    if (!ints) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for %zu spectra", b->n_spectra);
    lx_status st = lx_batch_integrate(ctx, b, fns, k, opts, ints);
    if (st == LX_OK) {
        J.ints = ints, J.k = k;
        int nt = b->n_spectra < 4096 ? 1 : lx__threads(opts ? opts->threads : 0, (long)b->n_spectra);
        lx__parallel_for(ctx, nt, (long)b->n_spectra, rows, &J);
        for (int t = 0; t < nt && st == LX_OK; t++)
            if (J.st[t] != LX_OK) st = lx__error(ctx, J.st[t], NULL, 0, "batch lab quantities failed: %s", lx_strerror(J.st[t]));
    }
    lx__free(ints);
    return st;
}

lx_status lx_par_batch(lx_ctx *ctx, const lx_batch *b, const lx_batch_opts *opts, lx_par *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_par_batch: NULL output");
    return lx_lab_batch(ctx, b, opts, out, NULL, NULL);
}

lx_status lx_hazard_batch(lx_ctx *ctx, const lx_batch *b, const lx_batch_opts *opts, lx_hazard *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_hazard_batch: NULL output");
    return lx_lab_batch(ctx, b, opts, NULL, out, NULL);
}

lx_status lx_binning_batch(lx_ctx *ctx, const lx_batch *b, const lx_batch_opts *opts, lx_binning *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_binning_batch: NULL output");
    return lx_lab_batch(ctx, b, opts, NULL, NULL, out);
}
