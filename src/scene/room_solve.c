/* room_solve.c - the interreflection solve: the form-factor matrix (each patch's shooting points
 * to every patch, exact point-to-polygon form factors with ray-cast visibility; threads on the
 * CPU or an OpenCL device by the one backend rule), progressive refinement in sweeps until the
 * unshot flux meets the stopping point, and the final gather at points (receivers, patch
 * centres). The CPU functions here are the twins of kernels/room.cl. */
#include "scene/room_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Rays from x to the 3 x 3 lattice of the parallelogram o + s u + t v (corners, edge midpoints,
 * centre) that no occluder (but skip, skip2) cuts: the count, and in *w the visible fraction by
 * the trapezoid weights (corners 1/16, edges 1/8, centre 1/4). */
static int vis9(const lx__room_mesh *m, const double x[3], const double o[3], const double u[3], const double v[3],
                int skip, int skip2, double *w)
{
    static const double wt[3] = {0.25, 0.5, 0.25};
    int seen = 0;
    double f = 0;
    for (int k = 0; k < 9; k++) {
        double y[3];
        int a = k % 3, b = k / 3;
        for (int c = 0; c < 3; c++) y[c] = o[c] + 0.5 * a * u[c] + 0.5 * b * v[c];
        if (lx__room_visible(m->occ, (int)m->n_occ, x, y, skip, skip2)) {
            seen++;
            f += wt[a] * wt[b];
        }
    }
    *w = f;
    return seen;
}

double lx__room_ff_vis(const lx__room_mesh *m, const double x[3], const double n[3], const lx__room_patch *pj, int skip,
                       double f, int levels, unsigned long long *ff, unsigned long long *rays)
{
    /* depth first over the pieces (the kernel's order): a piece its 3 x 3 lattice sees wholly
     * counts its form factor, one it does not see counts nothing, a piece cut by a shadow edge is
     * replaced by its quarters, `levels` levels deep, the last weighted by its visible fraction */
    struct piece { double o[3], u[3], v[3], f; int level; } st[16];
    int top = 0;
    double total = 0;
    for (int c = 0; c < 3; c++) st[0].o[c] = pj->o[c], st[0].u[c] = pj->u[c], st[0].v[c] = pj->v[c];
    st[0].f = f;
    st[0].level = levels;
    top = 1;
    while (top > 0) {
        struct piece e = st[--top];
        double w;
        int k = vis9(m, x, e.o, e.u, e.v, skip, pj->occluder, &w);
        *rays += 9;
        if (k == 9) total += e.f;
        if (k == 9 || k == 0) continue;
        if (e.level == 0) {
            total += w * e.f;
            continue;
        }
        for (int a = 3; a >= 0; a--) {
            struct piece q;
            for (int c = 0; c < 3; c++) {
                q.u[c] = 0.5 * e.u[c];
                q.v[c] = 0.5 * e.v[c];
                q.o[c] = e.o[c] + 0.5 * (a & 1) * e.u[c] + 0.5 * (a >> 1) * e.v[c];
            }
            q.f = lx__room_ff_quad(x, n, q.o, q.u, q.v, pj->n);
            q.level = e.level - 1;
            (*ff)++;
            if (q.f > 0) st[top++] = q;
        }
    }
    return total;
}

/* One matrix entry: from patch i's shooting points to patch j (the twin of room.cl's ff_pair). */
static double ff_pair(const lx__room_mesh *m, const lx__room_patch *pi, const lx__room_patch *pj, unsigned long long *ff,
                      unsigned long long *rays)
{
    if (pi->cell != pj->cell || pi->face == pj->face) return 0;
    double lo[3], hi[3];
    for (int c = 0; c < 3; c++) lo[c] = fmin(pi->lo[c], pj->lo[c]), hi[c] = fmax(pi->hi[c], pj->hi[c]);
    int bv = m->n_occ && lx__room_shaft(m->occ, (int)m->n_occ, lo, hi, pi->c, pj->c, fmax(pi->rad, pj->rad), pi->occluder,
                                        pj->occluder);
    const double *gx, *gw;
    lx__room_gauss(pi->shoot, &gx, &gw);
    double s = 0;
    for (int a = 0; a < pi->shoot; a++)
        for (int b = 0; b < pi->shoot; b++) {
            double x[3];
            for (int c = 0; c < 3; c++) x[c] = pi->o[c] + gx[a] * pi->u[c] + gx[b] * pi->v[c];
            double f = lx__room_ff_quad(x, pi->n, pj->o, pj->u, pj->v, pj->n);
            (*ff)++;
            if (f > 0 && bv) f = lx__room_ff_vis(m, x, pi->n, pj, pi->occluder, f, LX__ROOM_VIS_MATRIX, ff, rays);
            s += gw[a] * gw[b] * f;
        }
    return s;
}

typedef struct ff_job {
    const lx__room_mesh *m;
    double *F;
    unsigned long long ff[64], rays[64];
} ff_job;

static void ff_rows_count(const lx__room_mesh *m, size_t i0, size_t i1, double *F, unsigned long long *ff,
                          unsigned long long *rays)
{
    size_t n = m->n_patch;
    for (size_t i = i0; i < i1; i++)
        for (size_t j = 0; j < n; j++) F[(i - i0) * n + j] = ff_pair(m, &m->patch[i], &m->patch[j], ff, rays);
}

void lx__room_ff_rows(const lx__room_mesh *m, size_t i0, size_t i1, double *F)
{
    unsigned long long ff = 0, rays = 0;
    ff_rows_count(m, i0, i1, F, &ff, &rays);
}

static void ff_run(void *arg, long i0, long i1, int t)
{
    ff_job *j = arg;
    ff_rows_count(j->m, (size_t)i0, (size_t)i1, j->F + (size_t)i0 * j->m->n_patch, &j->ff[t], &j->rays[t]);
}

/* The work of the matrix in form factors (its shooting points x patches). */
static double ff_work(const lx__room_mesh *m)
{
    double w = 0;
    for (size_t i = 0; i < m->n_patch; i++) w += (double)(m->patch[i].shoot * m->patch[i].shoot);
    return w * (double)m->n_patch;
}

lx_status lx__room_ff_matrix(lx_ctx *ctx, const lx__room_mesh *m, lx_backend backend, double **Fout, int *used)
{
    size_t n = m->n_patch;
    double *F = lx__alloc_n(n ? n * n : 1, sizeof *F);
    if (!F) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the %zu x %zu form-factor matrix", n, n);
    lx_backend be = LX_BACKEND_CPU;
    lx_status st = lx__backend_choose(ctx, "room form factors", backend, ff_work(m), LX__ROOM_CL_COLD, LX__ROOM_CL_WARM, &be);
    if (st != LX_OK) {
        lx__free(F);
        return st;
    }
    *used = LX_BACKEND_CPU;
#if LX_OPENCL
    if (be == LX_BACKEND_OPENCL) {
        st = lx__room_cl_ff(ctx, m, F);
        if (st == LX_OK) {
            *used = LX_BACKEND_OPENCL;
            ctx->counters.kernel_launches++;
            /* the device computed the same entries: count them as the CPU would */
            unsigned long long ff = 0, rays = 0;
            for (size_t i = 0; i < n; i++)
                for (size_t j = 0; j < n; j++) {
                    const lx__room_patch *pi = &m->patch[i], *pj = &m->patch[j];
                    if (pi->cell != pj->cell || pi->face == pj->face) continue;
                    ff += (unsigned long long)(pi->shoot * pi->shoot);
                    (void)rays;
                }
            ctx->counters.form_factors += ff;
            *Fout = F;
            return LX_OK;
        }
        if (!lx__backend_fallback(ctx, "room form factors", backend, st)) {
            lx__free(F);
            return st;
        }
    }
#endif
    ff_job job;
    memset(&job, 0, sizeof job);
    job.m = m;
    job.F = F;
    int threads = lx__threads(0, (long)n);
    lx__parallel_for(ctx, threads, (long)n, ff_run, &job);
    for (int t = 0; t < 64; t++) {
        ctx->counters.form_factors += job.ff[t];
        ctx->counters.visibility_tests += job.rays[t];
    }
    *Fout = F;
    return LX_OK;
}

void lx__room_solution_free(lx__room_solution *sol)
{
    if (!sol) return;
    lx__free(sol->phi_ind_lm);
    lx__free(sol->B);
    memset(sol, 0, sizeof *sol);
}

lx_status lx__room_solve(lx_ctx *ctx, const lx__room_mesh *m, const double *F, const double *phi0_lm,
                         double stop_unshot_lm, lx__room_solution *sol)
{
    size_t n = m->n_patch;
    double t0 = now_s();
    memset(sol, 0, sizeof *sol);
    double *X = lx__calloc(n ? n : 1, sizeof *X), *rho = lx__alloc_n(n ? n : 1, sizeof *rho);
    sol->phi_ind_lm = lx__calloc(n ? n : 1, sizeof *sol->phi_ind_lm);
    sol->B = lx__alloc_n(n ? n : 1, sizeof *sol->B);
    if (!X || !rho || !sol->phi_ind_lm || !sol->B) {
        lx__free(X);
        lx__free(rho);
        lx__room_solution_free(sol);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    double unshot = 0, shot = 0, received = 0;
    for (size_t i = 0; i < n; i++) {
        rho[i] = m->patch[i].rho;
        X[i] = rho[i] * phi0_lm[i];
        unshot += X[i];
    }
    /* progressive refinement in sweeps: every patch in turn shoots its unshot reflected flux X_i
     * (what arrives on j in the same sweep is shot when j's turn comes); a patch whose unshot
     * flux is below a 1/(4n) share of the stopping point waits for a later sweep */
    double small = 0.25 * stop_unshot_lm / (double)(n ? n : 1);
    while (unshot > stop_unshot_lm && sol->sweeps < 100000) {
        sol->sweeps++;
        for (size_t i = 0; i < n; i++) {
            double x = X[i];
            if (!(x > small)) continue;
            X[i] = 0;
            shot += x;
            sol->shots++;
            const double *row = F + i * n;
            double *pin = sol->phi_ind_lm;
            for (size_t j = 0; j < n; j++) {
                double d = x * row[j];
                pin[j] += d;
                X[j] += rho[j] * d;
            }
        }
        unshot = 0;
        for (size_t i = 0; i < n; i++) unshot += X[i];
        if (!(unshot > small * (double)n)) break; /* everything left is below the share */
    }
    for (size_t i = 0; i < n; i++) {
        received += sol->phi_ind_lm[i];
        sol->B[i] = rho[i] * (phi0_lm[i] + sol->phi_ind_lm[i]) / m->patch[i].area_m2;
    }
    sol->unshot_lm = unshot;
    sol->escaped_lm = shot - received;
    if (sol->escaped_lm < 0) sol->escaped_lm = 0;
    ctx->counters.radiosity_patches += n;
    ctx->counters.radiosity_shots += sol->shots;
    sol->seconds_solve = now_s() - t0;
    lx__free(X);
    lx__free(rho);
    return LX_OK;
}

/* ---- the gather ---- */

static void gather_rows(const lx__room_gather_job *g, size_t i0, size_t i1, double *E_lx, unsigned long long *ff,
                        unsigned long long *rays);

void lx__room_gather_cpu(const lx__room_gather_job *g, size_t i0, size_t i1, double *E_lx)
{
    unsigned long long ff = 0, rays = 0;
    gather_rows(g, i0, i1, E_lx, &ff, &rays);
}

static void gather_rows(const lx__room_gather_job *g, size_t i0, size_t i1, double *E_lx, unsigned long long *ff,
                        unsigned long long *rays)
{
    const lx__room_mesh *m = g->m;
    for (size_t i = i0; i < i1; i++) {
        const double *x = g->pts + 3 * i, *n = g->nrm + 3 * i;
        int skip = g->skip ? g->skip[i] : -1;
        double e = 0;
        for (size_t j = 0; j < g->n_src; j++) {
            const lx__room_patch *pj = &g->src[j];
            if (pj->cell != g->cell[i] || !(g->B[j] > 0)) continue;
            double f = lx__room_ff_quad(x, n, pj->o, pj->u, pj->v, pj->n);
            (*ff)++;
            if (!(f > 0)) continue;
            if (m->n_occ) {
                double lo[3], hi[3];
                for (int c = 0; c < 3; c++) lo[c] = fmin(x[c], pj->lo[c]), hi[c] = fmax(x[c], pj->hi[c]);
                if (lx__room_shaft(m->occ, (int)m->n_occ, lo, hi, x, pj->c, pj->rad, skip, pj->occluder))
                    f = lx__room_ff_vis(m, x, n, pj, skip, f, g->vis_levels, ff, rays);
            }
            e += g->B[j] * f;
        }
        E_lx[i] = e;
    }
}

typedef struct gather_arg {
    const lx__room_gather_job *g;
    double *E;
    unsigned long long ff[64], rays[64];
} gather_arg;

static void gather_run(void *arg, long i0, long i1, int t)
{
    gather_arg *a = arg;
    gather_rows(a->g, (size_t)i0, (size_t)i1, a->E, &a->ff[t], &a->rays[t]);
}

lx_status lx__room_gather(lx_ctx *ctx, const lx__room_gather_job *g, lx_backend backend, double *E_lx, int *used)
{
    lx_backend be = LX_BACKEND_CPU;
    lx_status st = lx__backend_choose(ctx, "room gather", backend, (double)g->n * (double)g->n_src, LX__ROOM_CL_COLD,
                                      LX__ROOM_CL_WARM, &be);
    if (st != LX_OK) return st;
    *used = LX_BACKEND_CPU;
    ctx->counters.gather_points += g->n;
#if LX_OPENCL
    if (be == LX_BACKEND_OPENCL) {
        st = lx__room_cl_gather(ctx, g, E_lx);
        if (st == LX_OK) {
            *used = LX_BACKEND_OPENCL;
            ctx->counters.kernel_launches++;
            return LX_OK;
        }
        if (!lx__backend_fallback(ctx, "room gather", backend, st)) return st;
    }
#endif
    gather_arg *a = lx__calloc(1, sizeof *a);
    if (!a) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    a->g = g;
    a->E = E_lx;
    lx__parallel_for(ctx, lx__threads(0, (long)g->n), (long)g->n, gather_run, a);
    for (int t = 0; t < 64; t++) {
        ctx->counters.form_factors += a->ff[t];
        ctx->counters.visibility_tests += a->rays[t];
    }
    lx__free(a);
    return LX_OK;
}
