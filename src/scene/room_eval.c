/* room_eval.c - evaluation's part for rooms: the direct light on every element (Gauss-Legendre
 * nodes, each a receiver of the one direct-lighting path, visibility-tested), summed per patch;
 * the form factors and the solve on the patches; the gather at every element centre (from the
 * patches) and at the receiver points (from the elements); the faces' results. */
#include "scene/room_private.h"
#include "scene/design_private.h"

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

typedef struct direct_job {
    const lx_scene *sc;
    const lx__room_mesh *m;
    const lx__scene_lum *le;
    const int *lum_cell;
    long only;
    double near_tol;
    double *E_dir;          /* per element: its mean direct illuminance */
    lx_counters cnt[64];
} direct_job;

/* The direct light on elements i0..i1-1: E at the element's m x m Gauss nodes from every
 * luminaire of its room, weighted by the node weights. */
static void direct_run(void *arg, long i0, long i1, int t)
{
    direct_job *J = arg;
    const lx__room_mesh *m = J->m;
    lx_counters *cnt = &J->cnt[t];
    for (long i = i0; i < i1; i++) {
        const lx__room_patch *p = &m->elem[i];
        const double *gx, *gw;
        lx__room_gauss(p->order, &gx, &gw);
        double sum = 0;
        for (int a = 0; a < p->order; a++)
            for (int b = 0; b < p->order; b++) {
                double x[3], E = 0;
                for (int c = 0; c < 3; c++) x[c] = p->o[c] + gx[a] * p->u[c] + gx[b] * p->v[c];
                for (size_t l = 0; l < J->sc->n_lum; l++) {
                    if ((J->only >= 0 && (long)l != J->only) || J->lum_cell[l] != p->cell) continue;
                    lx__scene_vis vis = {m->occ, (int)m->n_occ, p->occluder};
                    int test = m->n_occ && lx__room_lum_bv(m, &J->le[l], x, p->occluder);
                    E += lx__scene_lum_E(cnt, &J->le[l], x, p->n, lx__scene_path(cnt, J->sc, &J->le[l], x, p->n, J->near_tol), J->near_tol,
                                         test ? &vis : NULL);
                }
                sum += gw[a] * gw[b] * E;
            }
        J->E_dir[i] = sum;
    }
}

static lx_status direct_light(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lx__room_mesh *m, long only,
                              double *E_dir)
{
    direct_job *J = lx__calloc(1, sizeof *J);
    lx__scene_lum *le = lx__calloc(sc->n_lum ? sc->n_lum : 1, sizeof *le);
    int *lc = lx__calloc(sc->n_lum ? sc->n_lum : 1, sizeof *lc);
    if (!J || !le || !lc) {
        lx__free(J), lx__free(le), lx__free(lc);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t l = 0; l < sc->n_lum; l++) {
        lx__scene_lum_init(&le[l], sc, l, plan);
        lc[l] = lx__room_cell(sc, sc->lum[l].pos_m);
    }
    *J = (direct_job){sc, m, le, lc, only, fmax(sc->nearfield_tol, m->quad_tol), E_dir, {{0}}};
    lx__parallel_for(ctx, lx__threads(0, (long)m->n_elem), (long)m->n_elem, direct_run, J);
    unsigned long long *dst = (unsigned long long *)&ctx->counters;
    for (int t = 0; t < 64; t++) {
        const unsigned long long *src = (const unsigned long long *)&J->cnt[t];
        for (size_t k = 0; k < sizeof(lx_counters) / sizeof *dst; k++) dst[k] += src[k];
    }
    lx__free(J);
    lx__free(le);
    lx__free(lc);
    return LX_OK;
}

/* The faces' results: area-weighted averages (received flux / exposed area). */
static lx_status surfaces(lx_ctx *ctx, const lx__room_mesh *m, const double *phi0, const lx__room_solution *sol,
                          lx_scene_result *res)
{
    res->surfaces = lx__calloc(m->n_face ? m->n_face : 1, sizeof *res->surfaces);
    if (!res->surfaces) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    double *d = lx__calloc(2 * (m->n_face ? m->n_face : 1), sizeof *d);
    if (!d) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; i < m->n_patch; i++) {
        d[2 * m->patch[i].face] += phi0[i];
        d[2 * m->patch[i].face + 1] += sol->phi_ind_lm[i];
    }
    res->n_surfaces = m->n_face;
    for (size_t f = 0; f < m->n_face; f++) {
        lx_scene_surface_result *s = &res->surfaces[f];
        size_t nl = strlen(m->face[f].name) + 1;
        s->name = lx__alloc(nl);
        if (!s->name) {
            lx__free(d);
            return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        }
        memcpy(s->name, m->face[f].name, nl);
        double A = m->face[f].area_m2;
        s->area_m2 = A;
        s->reflectance = m->face[f].rho;
        s->direct_lx = A > 0 ? d[2 * f] / A : NAN;
        s->indirect_lx = A > 0 ? d[2 * f + 1] / A : NAN;
        s->E_lx = s->direct_lx + s->indirect_lx;
        s->L_cd_m2 = s->reflectance * s->E_lx / LX__PI;
    }
    lx__free(d);
    return LX_OK;
}

/* The solve's account: fluxes, and the discretisation check (each patch's indirect illuminance in
 * the solve against the area-weighted mean of the exact gathers at its elements). */
static lx_status stats(lx_ctx *ctx, const lx__room_mesh *m, const double *phi0, const lx__room_solution *sol,
                       const double *Ei, lx_scene_room_stats *R)
{
    size_t n = m->n_patch;
    R->n_patches = n;
    R->sweeps = sol->sweeps;
    R->shots = sol->shots;
    R->unshot_lm = sol->unshot_lm;
    R->escaped_lm = sol->escaped_lm;
    for (size_t i = 0; i < n; i++) {
        R->direct_lm += phi0[i];
        R->indirect_lm += sol->phi_ind_lm[i];
        R->absorbed_lm += (1 - m->patch[i].rho) * (phi0[i] + sol->phi_ind_lm[i]);
    }
    double *ga = lx__calloc(n ? n : 1, sizeof *ga), w = 0, e2 = 0;
    if (!ga) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t e = 0; e < m->n_elem; e++) ga[m->elem[e].parent] += Ei[e] * m->elem[e].area_m2;
    for (size_t i = 0; i < n; i++) {
        double A = m->patch[i].area_m2, s = sol->phi_ind_lm[i] / A, d = ga[i] / A - s;
        e2 += A * d * d;
        w += A * s * s;
    }
    lx__free(ga);
    R->gather_check = w > 0 ? sqrt(e2 / w) : 0;
    return LX_OK;
}

/* Gather job arrays for the element centres (*list: their indices, *count of them). Every element
 * is gathered, an unrefined patch's one too: the exact gather at its centre is the better
 * exitance for the receivers' gather than the solve's patch mean (bench room: the work-plane
 * mean 2e-5 from the reference against 1.7e-4; README "Rooms"). */
static lx_status element_points(const lx__room_mesh *m, double **pts, double **nrm, int **cell, int **skip,
                                size_t **list, size_t *count)
{
    size_t n = m->n_elem ? m->n_elem : 1, k = 0;
    *pts = lx__alloc_n(3 * n, sizeof **pts);
    *nrm = lx__alloc_n(3 * n, sizeof **nrm);
    *cell = lx__alloc_n(n, sizeof **cell);
    *skip = lx__alloc_n(n, sizeof **skip);
    *list = lx__alloc_n(n, sizeof **list);
    if (!*pts || !*nrm || !*cell || !*skip || !*list) return LX_ENOMEM;
    for (size_t e = 0; e < m->n_elem; e++) {
        memcpy(*pts + 3 * k, m->elem[e].c, 3 * sizeof **pts);
        memcpy(*nrm + 3 * k, m->elem[e].n, 3 * sizeof **nrm);
        (*cell)[k] = m->elem[e].cell;
        (*skip)[k] = m->elem[e].occluder;
        (*list)[k++] = e;
    }
    *count = k;
    return LX_OK;
}

lx_status lx__room_eval(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, long only, struct lx__daylight *day,
                        lx_scene_result *res)
{
    const lx__room_mesh *m = plan->room.mesh;
    size_t n = m->n_patch, ne = m->n_elem, np = res->n_points;
    lx_backend backend = (lx_backend)plan->room.backend;
    double *phi0 = lx__calloc(n ? n : 1, sizeof *phi0), *F = NULL, *Ed = lx__alloc_n(ne ? ne : 1, sizeof *Ed);
    double *Ei = lx__alloc_n(ne ? ne : 1, sizeof *Ei), *Be = lx__alloc_n(ne ? ne : 1, sizeof *Be);
    double *pts = lx__alloc_n(3 * (np ? np : 1), sizeof *pts), *nrm = lx__alloc_n(3 * (np ? np : 1), sizeof *nrm);
    double *ept = NULL, *enr = NULL, *Eg = lx__alloc_n(ne ? ne : 1, sizeof *Eg);
    int *cell = lx__alloc_n(np ? np : 1, sizeof *cell), *ecell = NULL, *eskip = NULL;
    size_t *elist = NULL, n_eg = 0;
    res->direct_lx = lx__alloc_n(np ? np : 1, sizeof *res->direct_lx);
    res->indirect_lx = lx__alloc_n(np ? np : 1, sizeof *res->indirect_lx);
    lx__room_solution sol;
    memset(&sol, 0, sizeof sol);
    lx_status st = LX_OK;
    if (!phi0 || !Ed || !Ei || !Be || !Eg || !pts || !nrm || !cell || !res->direct_lx || !res->indirect_lx ||
        element_points(m, &ept, &enr, &ecell, &eskip, &elist, &n_eg) != LX_OK) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto out;
    }
    lx_scene_room_stats *R = &res->room;
    /* 1. the direct light on the elements; each patch receives its elements' flux */
    if ((st = direct_light(ctx, sc, plan, m, only, Ed)) != LX_OK) goto out;
    for (size_t e = 0; e < ne; e++) phi0[m->elem[e].parent] += Ed[e] * m->elem[e].area_m2;
    /* 2. the form factors and the solve on the patches */
    double t1 = now_s();
    int used = LX_BACKEND_CPU, gu1 = LX_BACKEND_CPU, gu2 = LX_BACKEND_CPU;
    if ((st = lx__room_ff_matrix(ctx, m, backend, &F, &used)) != LX_OK) goto out;
    double t2 = now_s();
    if ((st = lx__room_solve(ctx, m, F, phi0, plan->room.stop_unshot_lm, &sol)) != LX_OK) goto out;
    if (day && (st = lx__daylight_room(ctx, day, m, F)) != LX_OK) goto out; /* its own solve, the same F */
    lx__free(F);
    F = NULL;
    /* 3. the gather at the centre of every element from the patches: its exitance resolves what
     * varies within a patch (its own direct light, the indirect light arriving there) */
    double t3 = now_s();
    lx__room_gather_job ge = {m, m->patch, n, sol.B, n_eg, ept, enr, ecell, eskip, LX__ROOM_VIS_ELEMENTS};
    if (n_eg && (st = lx__room_gather(ctx, &ge, backend, Eg, &gu1)) != LX_OK) goto out;
    for (size_t e = 0; e < ne; e++) {
        size_t i = m->elem[e].parent;
        Ei[e] = sol.phi_ind_lm[i] / m->patch[i].area_m2;
    }
    for (size_t k = 0; k < n_eg; k++) Ei[elist[k]] = Eg[k];
    for (size_t e = 0; e < ne; e++) Be[e] = m->elem[e].rho * (Ed[e] + Ei[e]);
    if (sc->n_obs && (st = lx__glare_room_background(ctx, sc, m, Be, backend, res)) != LX_OK) goto out; /* UGR's Lb */
    /* cylindrical receivers: the interreflected light on small vertical cylinders */
    if ((st = lx__design_room_cylinder(ctx, sc, m, Be, backend, 0.25 * plan->room.tolerance, res)) != LX_OK) goto out;
    /* 4. the gather at the receiver points from the elements */
    size_t g = 0;
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
            memcpy(pts + 3 * g, sc->rec[r].points + 3 * i, 3 * sizeof *pts);
            memcpy(nrm + 3 * g, sc->rec[r].normal, 3 * sizeof *nrm);
            cell[g] = lx__room_cell(sc, pts + 3 * g);
        }
    lx__room_gather_job gr = {m, m->elem, ne, Be, np, pts, nrm, cell, NULL, LX__ROOM_VIS_RECEIVERS};
    if ((st = lx__room_gather(ctx, &gr, backend, res->indirect_lx, &gu2)) != LX_OK) goto out;
    double t4 = now_s(), sum_ind = 0, sum_all = 0;
    for (g = 0; g < np; g++) {
        res->direct_lx[g] = res->E_lx[g];
        res->E_lx[g] += res->indirect_lx[g];
        sum_ind += res->indirect_lx[g];
        sum_all += res->E_lx[g];
    }
    if ((st = surfaces(ctx, m, phi0, &sol, res)) != LX_OK) goto out;
    if ((st = stats(ctx, m, phi0, &sol, Ei, R)) != LX_OK) goto out;
    R->indirect_share = sum_all > 0 ? sum_ind / sum_all : 0;
    R->backend = used == LX_BACKEND_OPENCL || gu1 == LX_BACKEND_OPENCL || gu2 == LX_BACKEND_OPENCL ? LX_BACKEND_OPENCL
                                                                                                    : LX_BACKEND_CPU;
    R->seconds_ff = t2 - t1;
    R->seconds_solve = sol.seconds_solve;
    R->seconds_gather = t4 - t3;
out:
    if (st != LX_OK) {
        lx__free(res->direct_lx);
        lx__free(res->indirect_lx);
        res->direct_lx = res->indirect_lx = NULL;
    }
    lx__room_solution_free(&sol);
    lx__free(F);
    lx__free(phi0);
    lx__free(Ed);
    lx__free(Ei);
    lx__free(Be);
    lx__free(pts);
    lx__free(nrm);
    lx__free(cell);
    lx__free(ept);
    lx__free(enr);
    lx__free(ecell);
    lx__free(eskip);
    lx__free(elist);
    lx__free(Eg);
    return st;
}
