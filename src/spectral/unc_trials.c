/* unc_trials.c - the Monte Carlo trials in the space of the integrals: for each trial its normal
 * and uniform deviates (unc_rng.c) turned into the integrals of one draw of the spectrum, L = L0 +
 * G z + the shift's, the bandwidths' and the Fourier components' terms. The CPU path in double is
 * the reference; kernels/unc_trials.cl is its twin. */
#include "spectral/unc_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The deviates of one trial: nn normals into z, nu uniforms into u. */
static void draws(uint64_t seed, uint64_t t, size_t nn, size_t nu, double *z, double *u)
{
    double q[4];
    for (size_t i = 0; i < nn; i += 4) {
        lx__unc_normal4(seed, t, (uint32_t)(i / 4), q);
        for (size_t k = 0; k < 4 && i + k < nn; k++) z[i + k] = q[k];
    }
    for (size_t i = 0; i < nu; i += 4) {
        lx__unc_uniform4(seed, t, (uint32_t)(i / 4), q);
        for (size_t k = 0; k < 4 && i + k < nu; k++) u[i + k] = q[k];
    }
}

/* The shift d's term: the table's linear interpolation, or the spectrum integrated at d. */
static void shift_term(const lx__unc_space *sp, double d, double *L, double *tmp)
{
    size_t K = sp->K;
    if (sp->nshift) {
        const double *x = sp->shift_d;
        size_t lo = 0, hi = sp->nshift - 1;
        if (d <= x[0]) hi = 1;
        else if (d >= x[hi]) lo = hi - 1;
        else
            while (hi - lo > 1) {
                size_t mid = (lo + hi) / 2;
                if (x[mid] <= d) lo = mid;
                else hi = mid;
            }
        double w = (d - x[lo]) / (x[hi] - x[lo]);
        const double *a = sp->shift_T + lo * K, *b = sp->shift_T + hi * K;
        for (size_t k = 0; k < K; k++) L[k] += a[k] + w * (b[k] - a[k]);
        return;
    }
    const lx_spd *spd = sp->spd;
    size_t n = sp->n, hint = 0;
    for (size_t j = 0; j < n; j++) tmp[j] = lx__unc_shifted(spd, spd->lambda_nm[j] - d, &hint) - spd->value[j];
    for (size_t k = 0; k < K; k++) {
        const double *a = sp->A + k * n;
        double s = 0.0;
        for (size_t j = 0; j < n; j++) s += a[j] * tmp[j];
        L[k] += s;
    }
}

static void fourier_term(const lx__unc_space *sp, const lx__unc_fourier *f, const double *y, const double *ph, double *L)
{
    size_t K = sp->K;
    int N = f->terms;
    double nrm = 0.0;
    for (int i = 0; i <= N; i++) nrm += y[i] * y[i];
    double s = f->sigma / sqrt(nrm);
    for (size_t k = 0; k < K; k++) L[k] += s * y[0] * f->F[k];
    for (int i = 1; i <= N; i++) {
        double a = 6.283185307179586 * ph[i - 1], cs = s * y[i] * cos(a), sn = s * y[i] * sin(a);
        const double *Fs = f->F + (2 * (size_t)i - 1) * K, *Fc = Fs + K;
        for (size_t k = 0; k < K; k++) L[k] += cs * Fs[k] + sn * Fc[k];
    }
}

void lx__unc_trials_cpu(const lx__unc_space *sp, uint64_t seed, uint64_t t0, size_t m, double *L)
{
    size_t K = sp->K, r = sp->r, nn = sp->nnormal, nu = sp->nuniform;
    double zs[64], us[64];
    double *z = nn > 64 ? lx__alloc(nn * sizeof *z) : zs, *u = nu > 64 ? lx__alloc(nu * sizeof *u) : us;
    double *tmp = sp->shift_sigma > 0 && !sp->nshift ? lx__alloc(sp->n * sizeof *tmp) : NULL;
    if (!z || !u || (sp->shift_sigma > 0 && !sp->nshift && !tmp)) { /* out of memory: NaN trials */
        for (size_t i = 0; i < m * K; i++) L[i] = NAN;
        goto done;
    }
    for (size_t t = 0; t < m; t++) {
        double *l = L + t * K;
        draws(seed, t0 + t, nn, nu, z, u);
        memcpy(l, sp->L0, K * sizeof *l);
        for (size_t j = 0; j < r; j++) {
            const double *g = sp->G + j * K;
            double zj = z[j];
            for (size_t k = 0; k < K; k++) l[k] += zj * g[k];
        }
        size_t iz = r, iu = 0;
        if (sp->shift_sigma > 0) shift_term(sp, sp->shift_sigma * z[iz++], l, tmp);
        for (size_t b = 0; b < sp->nbw; b++) {
            double d = sp->bw_sigma[b] * z[iz++], b0 = sp->bw_b0[b];
            double c = (2.0 * b0 * d + d * d) / 12.0;
            const double *D = sp->bw_D + b * K;
            for (size_t k = 0; k < K; k++) l[k] += c * D[k];
        }
        for (size_t f = 0; f < sp->nfourier; f++) {
            const lx__unc_fourier *F = &sp->fourier[f];
            fourier_term(sp, F, z + iz, u + iu, l);
            iz += (size_t)F->terms + 1, iu += (size_t)F->terms;
        }
    }
done:
    if (z != zs) lx__free(z);
    if (u != us) lx__free(u);
    lx__free(tmp);
}

/* Break-even of LX_BACKEND_AUTO in multiply-adds (trials x K x draws per trial), measured with
 * `luxcalc bench uncertainty` (README "Measurement uncertainty"). Cold: OpenCL not yet initialised
 * (start-up and the program build); warm: the launch and the copies back. The CPU draws 10^5
 * trials of the colorimetry (K 5, 5 draws) in 15 ms, so only large models on a GPU repay it. */
#define LX_UNC_COLD_FMA 2e11
#define LX_UNC_WARM_FMA 5e9

#if LX_OPENCL
/* A buffer of n doubles as the device's real (float without fp64). */
static cl_mem upload(lx_ctx *ctx, lx__cl *cl, const double *v, size_t n, int fp64, lx_status *st)
{
    cl_int err = CL_SUCCESS;
    size_t es = fp64 ? sizeof(double) : sizeof(float);
    void *tmp = NULL;
    double one = 0;
    if (!n) v = &one, n = 1;
    if (!fp64) {
        float *f = lx__alloc(n * sizeof *f);
        if (!f) {
            *st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
            return NULL;
        }
        for (size_t i = 0; i < n; i++) f[i] = (float)v[i];
        tmp = f;
    }
    cl_mem m = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * es, tmp ? tmp : (void *)v, &err);
    lx__free(tmp);
    *st = lx__cl_check(ctx, err, "clCreateBuffer(uncertainty)");
    return *st == LX_OK ? m : NULL;
}

/* The trials on the device: the model's arrays uploaded, one launch per chunk of trials, the
 * changes read back and added to L0. */
static lx_status trials_opencl(lx_ctx *ctx, const lx__unc_space *sp, uint64_t seed, uint64_t t0, size_t count, double *L)
{
    lx__cl *cl = NULL;
    lx_status st = lx__cl_get(ctx, &cl);
    if (st) return st;
    if (sp->shift_sigma > 0 && !sp->nshift)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0,
                         "uncertainty trials: a wavelength shift on this irregular grid is integrated per trial, on the CPU only");
    cl_kernel kern;
    if ((st = lx__cl_kernel(ctx, cl, "unc_trials", &kern))) return st;
    int fp64 = cl->info.fp64;
    size_t K = sp->K, es = fp64 ? sizeof(double) : sizeof(float);
    size_t nfv = 0;
    for (size_t f = 0; f < sp->nfourier; f++) nfv += (2 * (size_t)sp->fourier[f].terms + 1) * K;
    double *bw = lx__alloc((2 * sp->nbw + 2 * sp->nfourier + 2) * sizeof *bw), *F = lx__alloc((nfv + 1) * sizeof *F);
    cl_mem m[8] = {0}, out = NULL;
    void *host = NULL;
    if (!bw || !F) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto done;
    }
    double *fs = bw + 2 * sp->nbw;
    for (size_t b = 0; b < sp->nbw; b++) bw[2 * b] = sp->bw_sigma[b], bw[2 * b + 1] = sp->bw_b0[b];
    for (size_t f = 0, o = 0; f < sp->nfourier; f++) {
        size_t len = (2 * (size_t)sp->fourier[f].terms + 1) * K;
        fs[2 * f] = sp->fourier[f].sigma, fs[2 * f + 1] = sp->fourier[f].terms;
        memcpy(F + o, sp->fourier[f].F, len * sizeof *F);
        o += len;
    }
    const double *src[7] = {sp->G, sp->shift_d, sp->shift_T, bw, sp->bw_D, F, fs};
    size_t len[7] = {sp->r * K, sp->nshift, sp->nshift * K, 2 * sp->nbw, sp->nbw * K, nfv, 2 * sp->nfourier};
    for (int i = 0; i < 7 && st == LX_OK; i++) m[i] = upload(ctx, cl, src[i], len[i], fp64, &st);
    if (st) goto done;
    unsigned long long max_alloc = cl->info.max_alloc_bytes ? cl->info.max_alloc_bytes : (128ull << 20);
    size_t chunk = (size_t)(max_alloc / (K * es));
    if (chunk > (1u << 20)) chunk = 1u << 20;
    if (chunk > count) chunk = count;
    if (!(host = lx__alloc(chunk * K * es))) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto done;
    }
    cl_int err = CL_SUCCESS;
    out = clCreateBuffer(cl->context, CL_MEM_WRITE_ONLY, chunk * K * es, NULL, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(uncertainty trials)"))) goto done;
    for (size_t c0 = 0; c0 < count && !st; c0 += chunk) {
        cl_uint n = (cl_uint)(count - c0 < chunk ? count - c0 : chunk), aK = (cl_uint)K, ar = (cl_uint)sp->r;
        cl_uint ans = (cl_uint)sp->nshift, anbw = (cl_uint)sp->nbw, anf = (cl_uint)sp->nfourier;
        cl_ulong aseed = seed, at0 = t0 + c0;
        double ssd = sp->shift_sigma;
        float ssf = (float)sp->shift_sigma;
        err = clSetKernelArg(kern, 0, sizeof aseed, &aseed);
        err |= clSetKernelArg(kern, 1, sizeof at0, &at0);
        err |= clSetKernelArg(kern, 2, sizeof n, &n);
        err |= clSetKernelArg(kern, 3, sizeof aK, &aK);
        err |= clSetKernelArg(kern, 4, sizeof ar, &ar);
        err |= clSetKernelArg(kern, 5, sizeof m[0], &m[0]);
        err |= clSetKernelArg(kern, 6, sizeof ans, &ans);
        err |= fp64 ? clSetKernelArg(kern, 7, sizeof ssd, &ssd) : clSetKernelArg(kern, 7, sizeof ssf, &ssf);
        err |= clSetKernelArg(kern, 8, sizeof m[1], &m[1]);
        err |= clSetKernelArg(kern, 9, sizeof m[2], &m[2]);
        err |= clSetKernelArg(kern, 10, sizeof anbw, &anbw);
        err |= clSetKernelArg(kern, 11, sizeof m[3], &m[3]);
        err |= clSetKernelArg(kern, 12, sizeof m[4], &m[4]);
        err |= clSetKernelArg(kern, 13, sizeof anf, &anf);
        err |= clSetKernelArg(kern, 14, sizeof m[6], &m[6]);
        err |= clSetKernelArg(kern, 15, sizeof m[5], &m[5]);
        err |= clSetKernelArg(kern, 16, sizeof out, &out);
        if ((st = lx__cl_check(ctx, err, "clSetKernelArg(unc_trials)"))) break;
        size_t global = n;
        err = clEnqueueNDRangeKernel(cl->queue, kern, 1, NULL, &global, NULL, 0, NULL, NULL);
        if ((st = lx__cl_check(ctx, err, "clEnqueueNDRangeKernel(unc_trials)"))) break;
        err = clEnqueueReadBuffer(cl->queue, out, CL_TRUE, 0, (size_t)n * K * es, host, 0, NULL, NULL);
        if ((st = lx__cl_check(ctx, err, "clEnqueueReadBuffer(unc_trials)"))) break;
        err = clFinish(cl->queue);
        if ((st = lx__cl_check(ctx, err, "clFinish"))) break;
        for (size_t k = 0; k < K; k++) /* column-major changes to row-major integrals */
            for (size_t t = 0; t < n; t++)
                L[(c0 + t) * K + k] = sp->L0[k] + (fp64 ? ((double *)host)[k * n + t] : (double)((float *)host)[k * n + t]);
    }
done:
    for (int i = 0; i < 7; i++)
        if (m[i]) clReleaseMemObject(m[i]);
    if (out) clReleaseMemObject(out);
    clReleaseKernel(kern);
    lx__free(bw), lx__free(F), lx__free(host);
    return st;
}
#endif

lx_status lx__unc_trials_device(lx_ctx *ctx, const lx__unc_space *sp, uint64_t seed, uint64_t t0, size_t count,
                                lx_backend asked, double **L, lx_backend *used)
{
    *L = NULL;
    *used = LX_BACKEND_CPU;
    size_t draws = sp->nnormal + sp->nuniform + (sp->nshift ? 0 : sp->n);
    double work = (double)count * (double)sp->K * (double)(draws ? draws : 1);
    lx_backend b = LX_BACKEND_CPU;
    lx_status st = lx__backend_choose(ctx, "uncertainty trials", asked, work, LX_UNC_COLD_FMA, LX_UNC_WARM_FMA, &b);
    if (st != LX_OK || b == LX_BACKEND_CPU) return st;
#if LX_OPENCL
    double *buf = lx__alloc(count * sp->K * sizeof *buf);
    if (!buf) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for %zu trials of %zu integrals", count, sp->K);
    st = trials_opencl(ctx, sp, seed, t0, count, buf);
    if (st == LX_OK) {
        *L = buf, *used = LX_BACKEND_OPENCL;
        return LX_OK;
    }
    lx__free(buf);
    if (lx__backend_fallback(ctx, "uncertainty trials", asked, st)) return LX_OK; /* the CPU draws them */
    return st;
#else
    (void)seed, (void)t0;
    return LX_OK;
#endif
}
