/* irradiance_brute.c - brute-force irradiance: for every output normal n, the sum over every input
 * pixel p of L_p max(0, n . m_p), m_p the exact first moment of the pixel (lx_envmap_pixel_moment).
 * CPU twin (double, pthreads over outputs) and the OpenCL host of kernels/irradiance.cl. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct brute_job {
    const lx_envmap *map;
    const lx__llgeom *g;
    const double *dirs;
    double *out;
    double *tcol; /* per thread: W doubles */
} brute_job;

static void brute_outputs(void *arg, long o0, long o1, int t)
{
    brute_job *J = arg;
    const lx_envmap *m = J->map;
    const lx__llgeom *g = J->g;
    int W = m->width, H = m->height, C = m->channels;
    double *tc = J->tcol + (size_t)t * W;
    for (long o = o0; o < o1; o++) {
        double nx = J->dirs[3 * o], ny = J->dirs[3 * o + 1], nz = J->dirs[3 * o + 2];
        for (int i = 0; i < W; i++) tc[i] = nx * g->col_gx[i] + ny * g->col_gy[i];
        double e[3] = {0, 0, 0};
        for (int j = 0; j < H; j++) {
            double a = g->row_s2[j], b = nz * g->row_sc[j] * g->dphi;
            const float *row = m->data + (size_t)j * W * C;
            if (C == 3) {
                double r0 = 0, r1 = 0, r2 = 0;
                for (int i = 0; i < W; i++) {
                    double v = a * tc[i] + b;
                    v = v > 0 ? v : 0;
                    r0 += v * row[3 * i];
                    r1 += v * row[3 * i + 1];
                    r2 += v * row[3 * i + 2];
                }
                e[0] += r0;
                e[1] += r1;
                e[2] += r2;
            } else {
                double r0 = 0;
                for (int i = 0; i < W; i++) {
                    double v = a * tc[i] + b;
                    r0 += (v > 0 ? v : 0) * row[i];
                }
                e[0] += r0;
            }
        }
        for (int c = 0; c < C; c++) J->out[o * C + c] = e[c];
    }
}

lx_status lx__irr_brute_cpu(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads,
                            double *out)
{
    lx__llgeom g;
    lx_status st = lx__llgeom_init(ctx, &g, map->width, map->height);
    if (st) return st;
    int nt = lx__threads(threads, (long)n_dirs);
    double *tcol = lx__alloc_n((size_t)nt * map->width, sizeof *tcol);
    if (!tcol) {
        lx__llgeom_free(&g);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    brute_job J = {map, &g, dirs, out, tcol};
    st = lx__parallel_for(ctx, nt, (long)n_dirs, brute_outputs, &J);
    lx__free(tcol);
    lx__llgeom_free(&g);
    return st;
}

#if LX_OPENCL
lx_status lx__irr_brute_cl(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, double *out)
{
    lx__cl *cl = NULL;
    lx_status st = lx__cl_get(ctx, &cl);
    if (st) return st;
    cl_kernel k = NULL;
    st = lx__cl_kernel(ctx, cl, "irradiance_brute", &k);
    if (st) return st;
    int W = map->width, H = map->height, C = map->channels, fp64 = cl->info.fp64;
    size_t rs = fp64 ? sizeof(double) : sizeof(float);
    lx__llgeom g;
    st = lx__llgeom_init(ctx, &g, W, H);
    if (st) {
        clReleaseKernel(k);
        return st;
    }
    /* geometry: row_s2[H], row_scdp[H], col_gx[W], col_gy[W], dirs[3n] in the kernel's real type */
    size_t ngeo = 2 * (size_t)H + 2 * (size_t)W + 3 * n_dirs;
    void *geo = lx__alloc(ngeo * rs);
    void *res = lx__alloc(n_dirs * C * rs);
    cl_mem bL = NULL, bG = NULL, bO = NULL;
    cl_int err = CL_SUCCESS;
    if (!geo || !res) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto done;
    }
    for (size_t q = 0; q < ngeo; q++) {
        double v;
        if (q < (size_t)H) v = g.row_s2[q];
        else if (q < 2 * (size_t)H) v = g.row_sc[q - H] * g.dphi;
        else if (q < 2 * (size_t)H + W) v = g.col_gx[q - 2 * H];
        else if (q < 2 * (size_t)H + 2 * W) v = g.col_gy[q - 2 * H - W];
        else v = dirs[q - 2 * H - 2 * W];
        if (fp64) ((double *)geo)[q] = v;
        else ((float *)geo)[q] = (float)v;
    }
    bL = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, (size_t)W * H * C * sizeof(float),
                        map->data, &err);
    if (!err) bG = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, ngeo * rs, geo, &err);
    if (!err) bO = clCreateBuffer(cl->context, CL_MEM_WRITE_ONLY, n_dirs * C * rs, NULL, &err);
    if (err) {
        st = lx__cl_check(ctx, err, "clCreateBuffer");
        goto done;
    }
    cl_int cw = W, ch = H, cc = C;
    cl_uint cn = (cl_uint)n_dirs;
    err |= clSetKernelArg(k, 0, sizeof bL, &bL);
    err |= clSetKernelArg(k, 1, sizeof cw, &cw);
    err |= clSetKernelArg(k, 2, sizeof ch, &ch);
    err |= clSetKernelArg(k, 3, sizeof cc, &cc);
    err |= clSetKernelArg(k, 4, sizeof bG, &bG);
    err |= clSetKernelArg(k, 5, sizeof cn, &cn);
    err |= clSetKernelArg(k, 6, sizeof bO, &bO);
    if (err) {
        st = lx__cl_check(ctx, err, "clSetKernelArg");
        goto done;
    }
    size_t local = 64, global = (n_dirs + local - 1) / local * local;
    err = clEnqueueNDRangeKernel(cl->queue, k, 1, NULL, &global, &local, 0, NULL, NULL);
    if (err == CL_INVALID_WORK_GROUP_SIZE) err = clEnqueueNDRangeKernel(cl->queue, k, 1, NULL, &global, NULL, 0, NULL, NULL);
    if (err) {
        st = lx__cl_check(ctx, err, "clEnqueueNDRangeKernel(irradiance_brute)");
        goto done;
    }
    err = clEnqueueReadBuffer(cl->queue, bO, CL_TRUE, 0, n_dirs * C * rs, res, 0, NULL, NULL);
    if (err) {
        st = lx__cl_check(ctx, err, "clEnqueueReadBuffer");
        goto done;
    }
    for (size_t q = 0; q < n_dirs * C; q++) out[q] = fp64 ? ((double *)res)[q] : ((float *)res)[q];
done:
    if (bL) clReleaseMemObject(bL);
    if (bG) clReleaseMemObject(bG);
    if (bO) clReleaseMemObject(bO);
    clReleaseKernel(k);
    lx__free(geo);
    lx__free(res);
    lx__llgeom_free(&g);
    return st;
}
#else
lx_status lx__irr_brute_cl(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, double *out)
{
    (void)map;
    (void)n_dirs;
    (void)dirs;
    (void)out;
    return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "this build has no OpenCL (LX_OPENCL=0)");
}
#endif
