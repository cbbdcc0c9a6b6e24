/* room_cl.c - the OpenCL host side of the room kernels (kernels/room.cl): the form-factor matrix
 * in blocks of rows that fit the device's allocation limit, and the gather. Double precision only
 * (the CPU twin is the reference and the parity test asks 1e-9): a device without cl_khr_fp64
 * is LX_EUNSUPPORTED, which the backend rule turns into the CPU path under auto. */
#include "scene/room_private.h"

#if LX_OPENCL
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The device copies of the patches, their ints, the occluders and the Gauss table. */
typedef struct cl_mesh {
    cl_mem P, RAD, PI, occ, okind, gauss;
    int nocc;
} cl_mesh;

static void cl_mesh_release(cl_mesh *c)
{
    if (c->P) clReleaseMemObject(c->P);
    if (c->RAD) clReleaseMemObject(c->RAD);
    if (c->PI) clReleaseMemObject(c->PI);
    if (c->occ) clReleaseMemObject(c->occ);
    if (c->okind) clReleaseMemObject(c->okind);
    if (c->gauss) clReleaseMemObject(c->gauss);
    memset(c, 0, sizeof *c);
}

static lx_status buffer(lx_ctx *ctx, lx__cl *cl, size_t bytes, const void *host, cl_mem *out, const char *what)
{
    cl_int err = CL_SUCCESS;
    *out = clCreateBuffer(cl->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes ? bytes : 8, (void *)host, &err);
    if (err != CL_SUCCESS) {
        *out = NULL;
        char call[96];
        snprintf(call, sizeof call, "clCreateBuffer(%s)", what);
        return lx__cl_check(ctx, err, call);
    }
    return LX_OK;
}

static lx_status upload(lx_ctx *ctx, lx__cl *cl, const lx__room_mesh *m, const lx__room_patch *src, size_t n,
                        cl_mesh *c)
{
    size_t no = m->n_occ;
    double *P = lx__alloc_n((n ? n : 1) * 21, sizeof *P), *O = lx__alloc_n((no ? no : 1) * 22, sizeof *O), G[128];
    double *R = lx__alloc_n(n ? n : 1, sizeof *R);
    int *PI = lx__alloc_n((n ? n : 1) * 4, sizeof *PI), *K = lx__alloc_n(no ? no : 1, sizeof *K);
    lx_status st = LX_OK;
    if (!P || !O || !PI || !K || !R) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; st == LX_OK && i < n; i++) {
        const lx__room_patch *p = &src[i];
        for (int k = 0; k < 3; k++) {
            P[21 * i + k] = p->o[k];
            P[21 * i + 3 + k] = p->u[k];
            P[21 * i + 6 + k] = p->v[k];
            P[21 * i + 9 + k] = p->n[k];
            P[21 * i + 12 + k] = p->lo[k];
            P[21 * i + 15 + k] = p->hi[k];
            P[21 * i + 18 + k] = p->c[k];
        }
        R[i] = p->rad;
        PI[4 * i] = p->cell;
        PI[4 * i + 1] = p->occluder;
        PI[4 * i + 2] = p->face;
        PI[4 * i + 3] = p->shoot;
    }
    for (size_t i = 0; st == LX_OK && i < no; i++) {
        const lx__room_occ *o = &m->occ[i];
        double *r = O + 22 * i;
        for (int k = 0; k < 3; k++) {
            r[k] = o->lo[k];
            r[3 + k] = o->hi[k];
            r[6 + k] = o->o[k];
            r[9 + k] = o->u[k];
            r[12 + k] = o->v[k];
            r[15 + k] = o->n[k];
        }
        r[18] = o->uu, r[19] = o->uv, r[20] = o->vv, r[21] = o->det;
        K[i] = o->kind;
    }
    for (int q = 1; st == LX_OK && q <= 8; q++) {
        const double *x, *w;
        lx__room_gauss(q, &x, &w);
        for (int i = 0; i < 8; i++) G[8 * (q - 1) + i] = i < q ? x[i] : 0, G[64 + 8 * (q - 1) + i] = i < q ? w[i] : 0;
    }
    c->nocc = (int)no;
    if (st == LX_OK) st = buffer(ctx, cl, n * 21 * sizeof *P, P, &c->P, "patches");
    if (st == LX_OK) st = buffer(ctx, cl, n * sizeof *R, R, &c->RAD, "patch radii");
    if (st == LX_OK) st = buffer(ctx, cl, n * 4 * sizeof *PI, PI, &c->PI, "patch ints");
    if (st == LX_OK) st = buffer(ctx, cl, no * 22 * sizeof *O, O, &c->occ, "occluders");
    if (st == LX_OK) st = buffer(ctx, cl, no * sizeof *K, K, &c->okind, "occluder kinds");
    if (st == LX_OK) st = buffer(ctx, cl, sizeof G, G, &c->gauss, "gauss");
    lx__free(P);
    lx__free(R);
    lx__free(O);
    lx__free(PI);
    lx__free(K);
    if (st != LX_OK) cl_mesh_release(c);
    return st;
}

static lx_status device(lx_ctx *ctx, lx__cl **cl)
{
    lx_status st = lx__cl_get(ctx, cl);
    if (st != LX_OK) return st;
    if (!(*cl)->info.fp64)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "room kernels: the OpenCL device has no double precision (cl_khr_fp64)");
    return LX_OK;
}

lx_status lx__room_cl_ff(lx_ctx *ctx, const lx__room_mesh *m, double *F)
{
    lx__cl *cl = NULL;
    lx_status st = device(ctx, &cl);
    if (st != LX_OK) return st;
    cl_kernel k = NULL;
    if ((st = lx__cl_kernel(ctx, cl, "lx_room_ff", &k)) != LX_OK) return st;
    cl_mesh c;
    memset(&c, 0, sizeof c);
    cl_mem out = NULL;
    cl_int err = CL_SUCCESS;
    size_t n = m->n_patch;
    if ((st = upload(ctx, cl, m, m->patch, n, &c)) != LX_OK) goto done;
    /* blocks of rows within a quarter of the allocation limit */
    unsigned long long cap = cl->info.max_alloc_bytes ? cl->info.max_alloc_bytes / 4 : 64ull << 20;
    size_t rows = n ? (size_t)(cap / (n * sizeof(double))) : 1;
    if (rows < 1) rows = 1;
    if (rows > n) rows = n;
    out = clCreateBuffer(cl->context, CL_MEM_WRITE_ONLY, (rows ? rows : 1) * (n ? n : 1) * sizeof(double), NULL, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(form factors)")) != LX_OK) goto done;
    cl_uint un = (cl_uint)n;
    for (size_t r0 = 0; r0 < n; r0 += rows) {
        cl_uint ur0 = (cl_uint)r0, urows = (cl_uint)(r0 + rows <= n ? rows : n - r0);
        err = clSetKernelArg(k, 0, sizeof c.P, &c.P);
        err |= clSetKernelArg(k, 1, sizeof c.RAD, &c.RAD);
        err |= clSetKernelArg(k, 2, sizeof c.PI, &c.PI);
        err |= clSetKernelArg(k, 3, sizeof c.occ, &c.occ);
        err |= clSetKernelArg(k, 4, sizeof c.okind, &c.okind);
        err |= clSetKernelArg(k, 5, sizeof c.nocc, &c.nocc);
        err |= clSetKernelArg(k, 6, sizeof c.gauss, &c.gauss);
        err |= clSetKernelArg(k, 7, sizeof un, &un);
        err |= clSetKernelArg(k, 8, sizeof ur0, &ur0);
        err |= clSetKernelArg(k, 9, sizeof urows, &urows);
        err |= clSetKernelArg(k, 10, sizeof out, &out);
        if ((st = lx__cl_check(ctx, err, "clSetKernelArg(lx_room_ff)")) != LX_OK) goto done;
        size_t local[2] = {1, 64}, global[2] = {urows, (n + 63) / 64 * 64};
        err = clEnqueueNDRangeKernel(cl->queue, k, 2, NULL, global, local, 0, NULL, NULL);
        if ((st = lx__cl_check(ctx, err, "clEnqueueNDRangeKernel(lx_room_ff)")) != LX_OK) goto done;
        err = clEnqueueReadBuffer(cl->queue, out, CL_TRUE, 0, (size_t)urows * n * sizeof(double), F + r0 * n, 0, NULL, NULL);
        if ((st = lx__cl_check(ctx, err, "clEnqueueReadBuffer(lx_room_ff)")) != LX_OK) goto done;
    }
done:
    if (out) clReleaseMemObject(out);
    cl_mesh_release(&c);
    clReleaseKernel(k);
    return st;
}

lx_status lx__room_cl_gather(lx_ctx *ctx, const lx__room_gather_job *g, double *E_lx)
{
    lx__cl *cl = NULL;
    lx_status st = device(ctx, &cl);
    if (st != LX_OK) return st;
    cl_kernel k = NULL;
    if ((st = lx__cl_kernel(ctx, cl, "lx_room_gather", &k)) != LX_OK) return st;
    cl_mesh c;
    memset(&c, 0, sizeof c);
    cl_mem bB = NULL, bp = NULL, bn = NULL, bc = NULL, bs = NULL, out = NULL;
    cl_int err = CL_SUCCESS;
    size_t n = g->n;
    int *skip = lx__alloc_n(n ? n : 1, sizeof *skip);
    if (!skip) {
        clReleaseKernel(k);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t i = 0; i < n; i++) skip[i] = g->skip ? g->skip[i] : -1;
    if ((st = upload(ctx, cl, g->m, g->src, g->n_src, &c)) != LX_OK) goto done;
    if ((st = buffer(ctx, cl, g->n_src * sizeof *g->B, g->B, &bB, "exitance")) != LX_OK) goto done;
    if ((st = buffer(ctx, cl, 3 * n * sizeof *g->pts, g->pts, &bp, "points")) != LX_OK) goto done;
    if ((st = buffer(ctx, cl, 3 * n * sizeof *g->nrm, g->nrm, &bn, "normals")) != LX_OK) goto done;
    if ((st = buffer(ctx, cl, n * sizeof *g->cell, g->cell, &bc, "cells")) != LX_OK) goto done;
    if ((st = buffer(ctx, cl, n * sizeof *skip, skip, &bs, "skips")) != LX_OK) goto done;
    out = clCreateBuffer(cl->context, CL_MEM_WRITE_ONLY, (n ? n : 1) * sizeof(double), NULL, &err);
    if ((st = lx__cl_check(ctx, err, "clCreateBuffer(gather)")) != LX_OK) goto done;
    cl_uint unp = (cl_uint)g->n_src, un = (cl_uint)n;
    err = clSetKernelArg(k, 0, sizeof c.P, &c.P);
    err |= clSetKernelArg(k, 1, sizeof c.RAD, &c.RAD);
    err |= clSetKernelArg(k, 2, sizeof c.PI, &c.PI);
    err |= clSetKernelArg(k, 3, sizeof c.occ, &c.occ);
    err |= clSetKernelArg(k, 4, sizeof c.okind, &c.okind);
    err |= clSetKernelArg(k, 5, sizeof c.nocc, &c.nocc);
    err |= clSetKernelArg(k, 6, sizeof bB, &bB);
    err |= clSetKernelArg(k, 7, sizeof unp, &unp);
    err |= clSetKernelArg(k, 8, sizeof bp, &bp);
    err |= clSetKernelArg(k, 9, sizeof bn, &bn);
    err |= clSetKernelArg(k, 10, sizeof bc, &bc);
    cl_int lev = g->vis_levels;
    err |= clSetKernelArg(k, 11, sizeof bs, &bs);
    err |= clSetKernelArg(k, 12, sizeof lev, &lev);
    err |= clSetKernelArg(k, 13, sizeof un, &un);
    err |= clSetKernelArg(k, 14, sizeof out, &out);
    if ((st = lx__cl_check(ctx, err, "clSetKernelArg(lx_room_gather)")) != LX_OK) goto done;
    size_t local = 64, global = (n + 63) / 64 * 64;
    if (n) {
        err = clEnqueueNDRangeKernel(cl->queue, k, 1, NULL, &global, &local, 0, NULL, NULL);
        if ((st = lx__cl_check(ctx, err, "clEnqueueNDRangeKernel(lx_room_gather)")) != LX_OK) goto done;
        err = clEnqueueReadBuffer(cl->queue, out, CL_TRUE, 0, n * sizeof(double), E_lx, 0, NULL, NULL);
        if ((st = lx__cl_check(ctx, err, "clEnqueueReadBuffer(lx_room_gather)")) != LX_OK) goto done;
    }
done:
    if (bB) clReleaseMemObject(bB);
    if (bp) clReleaseMemObject(bp);
    if (bn) clReleaseMemObject(bn);
    if (bc) clReleaseMemObject(bc);
    if (bs) clReleaseMemObject(bs);
    if (out) clReleaseMemObject(out);
    cl_mesh_release(&c);
    clReleaseKernel(k);
    lx__free(skip);
    return st;
}
#else
typedef int lx__room_cl_unused; /* ISO C: a translation unit is not empty */
#endif
