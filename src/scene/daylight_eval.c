/* daylight_eval.c - the daylight of an evaluation: the direct daylight at the receiver points, the
 * daylight's own interreflection solve on the rooms' mesh (the faces' direct daylight as the
 * external flux, the luminaires' form factors), its gathers, and the results: daylight_lx, the
 * daylight factor with its sky, externally and internally reflected components, the faces. */
#include "scene/daylight_private.h"

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

static void add_counters(lx_counters *to, const lx_counters *c)
{
    unsigned long long *a = (unsigned long long *)to;
    const unsigned long long *b = (const unsigned long long *)c;
    for (size_t k = 0; k < sizeof *to / sizeof *a; k++) a[k] += b[k];
}

lx_status lx__daylight_begin(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, lx__daylight **out)
{
    *out = NULL;
    if (!plan->on[LX_EFFECT_DAYLIGHT]) return LX_OK;
    lx__daylight *d = NULL;
    lx_status st = lx__daylight_setup(ctx, sc, plan, NULL, &d);
    if (st != LX_OK) return st;
    d->np = plan->n_points;
    size_t np = d->np ? d->np : 1;
    d->sky_lx = lx__calloc(np, sizeof *d->sky_lx);
    d->ground_lx = lx__calloc(np, sizeof *d->ground_lx);
    d->sun_pt_lx = lx__calloc(np, sizeof *d->sun_pt_lx);
    d->ind_lx = lx__calloc(np, sizeof *d->ind_lx);
    const lx__room_mesh *m = plan->room.mesh;
    if (plan->on[LX_EFFECT_INTERREFLECTION] && m && m->n_face) {
        d->n_face = m->n_face;
        d->face_direct_lm = lx__calloc(d->n_face, sizeof *d->face_direct_lm);
        d->face_indirect_lm = lx__calloc(d->n_face, sizeof *d->face_indirect_lm);
    }
    if (!d->sky_lx || !d->ground_lx || !d->sun_pt_lx || !d->ind_lx ||
        (d->n_face && (!d->face_direct_lm || !d->face_indirect_lm))) {
        lx__daylight_free(d);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    d->stats.flux_in_lm = plan->daylight.flux_in_lm;
    *out = d;
    return LX_OK;
}

/* ---- the direct daylight at the receiver points ---- */

typedef struct pt_job {
    lx__daylight *d;
    const double *pts, *nrm;
    lx_counters cnt[64];
} pt_job;

static void pt_run(void *arg, long i0, long i1, int t)
{
    pt_job *J = arg;
    lx__daylight *d = J->d;
    for (long i = i0; i < i1; i++) {
        const double *q = J->pts + 3 * i;
        double out[3];
        lx__daylight_at(d, q, J->nrm + 3 * i, lx__room_cell(d->sc, q), -1, 1, out, &J->cnt[t]);
        d->sky_lx[i] = out[0], d->ground_lx[i] = out[1], d->sun_pt_lx[i] = out[2];
    }
}

/* Every receiver point and its normal, in result order. */
static lx_status receiver_points(lx_ctx *ctx, const lx_scene *sc, size_t np, double **pts, double **nrm, int **cell)
{
    *pts = lx__alloc_n(3 * (np ? np : 1), sizeof **pts);
    *nrm = lx__alloc_n(3 * (np ? np : 1), sizeof **nrm);
    if (cell) *cell = lx__alloc_n(np ? np : 1, sizeof **cell);
    if (!*pts || !*nrm || (cell && !*cell)) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    size_t g = 0;
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
            memcpy(*pts + 3 * g, sc->rec[r].points + 3 * i, 3 * sizeof **pts);
            memcpy(*nrm + 3 * g, sc->rec[r].normal, 3 * sizeof **nrm);
            if (cell) (*cell)[g] = lx__room_cell(sc, *pts + 3 * g);
        }
    return LX_OK;
}

lx_status lx__daylight_points(lx_ctx *ctx, lx__daylight *d, lx_scene_result *res)
{
    double t0 = now_s(), *pts = NULL, *nrm = NULL;
    pt_job *J = lx__calloc(1, sizeof *J);
    lx_status st = J ? receiver_points(ctx, d->sc, d->np, &pts, &nrm, NULL) : lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (st == LX_OK) {
        J->d = d, J->pts = pts, J->nrm = nrm;
        lx__parallel_for(ctx, lx__threads(0, (long)d->np), (long)d->np, pt_run, J);
        for (int t = 0; t < 64; t++) add_counters(&ctx->counters, &J->cnt[t]);
        size_t nc = res->n_lum + 1;
        for (size_t g = 0; g < d->np; g++) {
            double e = d->sky_lx[g] + d->ground_lx[g] + d->sun_pt_lx[g];
            res->contrib_lx[g * nc + res->n_lum] += e;
            res->E_lx[g] += e;
        }
    }
    lx__free(J);
    lx__free(pts);
    lx__free(nrm);
    d->stats.seconds += now_s() - t0;
    return st;
}

/* ---- the daylight's interreflection ---- */

typedef struct el_job {
    const lx__daylight *d;
    const lx__room_mesh *m;
    double tq;
    double *Ed;
    lx_counters cnt[64];
} el_job;

/* The mean direct daylight on elements i0..i1-1: the sky and the ground at the element's Gauss
 * nodes, the sun's beam clipped to it. */
static void el_run(void *arg, long i0, long i1, int t)
{
    el_job *J = arg;
    for (long i = i0; i < i1; i++) {
        const lx__room_patch *p = &J->m->elem[i];
        int order = lx__daylight_order(J->d->sc, p, J->tq);
        const double *gx, *gw;
        lx__room_gauss(order, &gx, &gw);
        double sum = 0;
        for (int a = 0; a < order; a++)
            for (int b = 0; b < order; b++) {
                double x[3], out[3];
                for (int c = 0; c < 3; c++) x[c] = p->o[c] + gx[a] * p->u[c] + gx[b] * p->v[c];
                lx__daylight_at(J->d, x, p->n, p->cell, p->occluder, 0, out, &J->cnt[t]);
                sum += gw[a] * gw[b] * (out[0] + out[1]);
            }
        J->Ed[i] = sum + lx__daylight_sun_flux(J->d, p, order) / p->area_m2;
    }
}

typedef struct room_arrays {
    double *Ed, *phi0, *Ei, *Be, *ept, *enr, *pts, *nrm;
    int *ecell, *eskip, *cell;
} room_arrays;

static void arrays_free(room_arrays *a)
{
    lx__free(a->Ed), lx__free(a->phi0), lx__free(a->Ei), lx__free(a->Be), lx__free(a->ept), lx__free(a->enr), lx__free(a->pts), lx__free(a->nrm);
    lx__free(a->ecell), lx__free(a->eskip), lx__free(a->cell);
}

static lx_status arrays_alloc(lx_ctx *ctx, const lx__daylight *d, const lx__room_mesh *m, room_arrays *a)
{
    size_t n = m->n_patch ? m->n_patch : 1, ne = m->n_elem ? m->n_elem : 1;
    memset(a, 0, sizeof *a);
    a->Ed = lx__alloc_n(ne, sizeof *a->Ed), a->Ei = lx__alloc_n(ne, sizeof *a->Ei), a->Be = lx__alloc_n(ne, sizeof *a->Be);
    a->phi0 = lx__calloc(n, sizeof *a->phi0);
    a->ept = lx__alloc_n(3 * ne, sizeof *a->ept), a->enr = lx__alloc_n(3 * ne, sizeof *a->enr);
    a->ecell = lx__alloc_n(ne, sizeof *a->ecell), a->eskip = lx__alloc_n(ne, sizeof *a->eskip);
    if (!a->Ed || !a->Ei || !a->Be || !a->phi0 || !a->ept || !a->enr || !a->ecell || !a->eskip)
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t e = 0; e < m->n_elem; e++) {
        memcpy(a->ept + 3 * e, m->elem[e].c, 3 * sizeof *a->ept);
        memcpy(a->enr + 3 * e, m->elem[e].n, 3 * sizeof *a->enr);
        a->ecell[e] = m->elem[e].cell;
        a->eskip[e] = m->elem[e].occluder;
    }
    return receiver_points(ctx, d->sc, d->np, &a->pts, &a->nrm, &a->cell);
}

lx_status lx__daylight_room(lx_ctx *ctx, lx__daylight *d, const lx__room_mesh *m, const double *F)
{
    double t0 = now_s();
    const lx_scene_plan *plan = d->plan;
    size_t n = m->n_patch, ne = m->n_elem;
    lx_backend backend = (lx_backend)plan->room.backend;
    room_arrays a;
    lx__room_solution sol;
    memset(&a, 0, sizeof a);
    memset(&sol, 0, sizeof sol);
    el_job *J = lx__calloc(1, sizeof *J);
    lx_status st = J ? arrays_alloc(ctx, d, m, &a) : lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (st != LX_OK) goto out;
    /* 1. the direct daylight on the elements: each patch receives its elements' flux */
    *J = (el_job){d, m, 0.25 * d->sc->interreflection_tol, a.Ed, {{0}}};
    lx__parallel_for(ctx, lx__threads(0, (long)ne), (long)ne, el_run, J);
    for (int t = 0; t < 64; t++) add_counters(&ctx->counters, &J->cnt[t]);
    double total = 0;
    for (size_t e = 0; e < ne; e++) a.phi0[m->elem[e].parent] += a.Ed[e] * m->elem[e].area_m2;
    for (size_t i = 0; i < n; i++) total += a.phi0[i];
    /* 2. the solve with the luminaires' form factors, stopped as theirs is (a quarter of the
     * tolerance of what the faces reflect) */
    double stop = 0.25 * d->sc->interreflection_tol * plan->room.mean_reflectance * total;
    if ((st = lx__room_solve(ctx, m, F, a.phi0, stop, &sol)) != LX_OK) goto out;
    /* 3. the gathers: every element's centre from the patches, the receivers from the elements */
    int used = 0;
    lx__room_gather_job ge = {m, m->patch, n, sol.B, ne, a.ept, a.enr, a.ecell, a.eskip, LX__ROOM_VIS_ELEMENTS};
    if (ne && (st = lx__room_gather(ctx, &ge, backend, a.Ei, &used)) != LX_OK) goto out;
    for (size_t e = 0; e < ne; e++) a.Be[e] = m->elem[e].rho * (a.Ed[e] + a.Ei[e]);
    lx__room_gather_job gr = {m, m->elem, ne, a.Be, d->np, a.pts, a.nrm, a.cell, NULL, LX__ROOM_VIS_RECEIVERS};
    if (d->np && (st = lx__room_gather(ctx, &gr, backend, d->ind_lx, &used)) != LX_OK) goto out;
    for (size_t i = 0; i < n && d->n_face; i++) {
        d->face_direct_lm[m->patch[i].face] += a.phi0[i];
        d->face_indirect_lm[m->patch[i].face] += sol.phi_ind_lm[i];
    }
    d->stats.direct_lm = total;
    for (size_t i = 0; i < n; i++) d->stats.indirect_lm += sol.phi_ind_lm[i];
    d->stats.escaped_lm = sol.escaped_lm;
    d->stats.unshot_lm = sol.unshot_lm;
    d->stats.sweeps = sol.sweeps;
out:
    lx__room_solution_free(&sol);
    arrays_free(&a);
    lx__free(J);
    d->stats.seconds += now_s() - t0;
    return st;
}

/* ---- the results ---- */

lx_status lx__daylight_finish(lx_ctx *ctx, lx__daylight *d, lx_scene_result *res)
{
    size_t np = d->np ? d->np : 1;
    double **arr[5] = {&res->daylight_lx, &res->daylight_factor, &res->sky_component, &res->externally_reflected,
                       &res->internally_reflected};
    for (int k = 0; k < 5; k++)
        if (!(*arr[k] = lx__alloc_n(np, sizeof(double)))) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    const lx_scene *sc = d->sc;
    int df = d->plan->daylight.df;
    double k100 = df ? 100 / d->E_h : NAN, sum_ind = 0, sum_all = 0;
    size_t g = 0;
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
            double ind = d->ind_lx[g];
            if (res->indirect_lx) {
                res->indirect_lx[g] += ind;
                res->E_lx[g] += ind;
                sum_ind += res->indirect_lx[g];
                sum_all += res->E_lx[g];
            }
            res->daylight_lx[g] = d->sky_lx[g] + d->ground_lx[g] + d->sun_pt_lx[g] + ind;
            int in = lx__room_cell(sc, sc->rec[r].points + 3 * i) >= 0;
            res->sky_component[g] = df && in ? k100 * d->sky_lx[g] : NAN;
            res->externally_reflected[g] = df && in ? k100 * d->ground_lx[g] : NAN;
            res->internally_reflected[g] = df && in ? k100 * ind : NAN;
            res->daylight_factor[g] = df && in ? res->sky_component[g] + res->externally_reflected[g] + res->internally_reflected[g] : NAN;
        }
    if (res->indirect_lx) res->room.indirect_share = sum_all > 0 ? sum_ind / sum_all : 0;
    for (size_t f = 0; f < d->n_face && f < res->n_surfaces; f++) {
        lx_scene_surface_result *s = &res->surfaces[f];
        if (!(s->area_m2 > 0)) continue;
        s->direct_lx += d->face_direct_lm[f] / s->area_m2;
        s->indirect_lx += d->face_indirect_lm[f] / s->area_m2;
        s->E_lx = s->direct_lx + s->indirect_lx;
        s->L_cd_m2 = s->reflectance * s->E_lx / LX__PI;
    }
    res->daylight = d->stats;
    return LX_OK;
}
