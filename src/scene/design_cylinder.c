/* design_cylinder.c - cylindrical and semi-cylindrical illuminance (EN 12464-1, EN 13201): the
 * mean illuminance on the curved surface of a very small vertical cylinder (or its half facing a
 * direction) at a receiver point, and the modelling ratio E_z / E_h. The luminaires' direct light
 * by the point-source kernel (integrated over a luminous area), the interreflected light by the
 * mean over azimuth of the room's gather on vertical planes. Daylight is not included. */
#include "scene/design_private.h"
#include "scene/room_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A beam of illuminance E_n (normal to the beam) arriving at angle theta from the vertical lights a
 * surface element of the cylinder with horizontal normal (cos psi, sin psi, 0) with E_n sin(theta)
 * max(0, cos(psi - phi)); over the whole curved surface the mean is E_n sin(theta) / pi, over the
 * half facing f it is E_n sin(theta) (1 + cos(phi_f)) / pi, phi_f the azimuth of the beam's origin
 * seen from f. For a point source E_n = I / d^2 and sin(theta) = h / d (h: the horizontal part of
 * the distance), so E_z = I h / (pi d^3) and E_sz = I (h + h cos(phi_f)) / (pi d^3). */
static double kernel(const double s[3], const double q[3], const double *f, double *u, double *d_out)
{
    double v[3] = {q[0] - s[0], q[1] - s[1], q[2] - s[2]};
    double h = hypot(v[0], v[1]), d = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    *d_out = d;
    if (!(h > 0) || !(d > 0)) return 0;
    for (int k = 0; k < 3; k++) u[k] = v[k] / d;
    double a = f ? h - (v[0] * f[0] + v[1] * f[1]) : h; /* h (1 + cos phi_f): the source is at -v */
    return a > 0 ? a / (LX__PI * d * d * d) : 0;
}

typedef struct cyl_arg {
    lx_counters *cnt;
    const lx__scene_lum *le;
    const double *q, *f;
    const lx__scene_vis *vis;
} cyl_arg;

/* E of a point source at s carrying frac of the luminaire's intensity. */
static double cyl_point(const cyl_arg *A, const double s[3], double frac)
{
    double u[3], d;
    double g = kernel(s, A->q, A->f, u, &d);
    if (!(g > 0)) return 0;
    if (A->vis) {
        A->cnt->visibility_tests++;
        if (!lx__room_visible(A->vis->occ, A->vis->n_occ, s, A->q, A->vis->skip, -1)) return 0;
    }
    return lx__scene_intensity(A->cnt, A->le, u, frac) * g;
}

/* the mean over the n-level cells of the luminous area (as the scene's near field cuts it) */
static double cyl_mean(void *arg, int lev)
{
    const cyl_arg *A = arg;
    const lx_scene_luminaire *l = A->le->l;
    int circular = l->radius_m > 0;
    double w, len;
    lx__scene_lum_extent(l, &w, &len);
    size_t cells = lx__area_cells(circular, lev);
    double frac = 1.0 / (double)cells, sum = 0;
    for (size_t c = 0; c < cells; c++) {
        double a, b, s[3];
        lx__area_cell(circular, w, len, lev, c, &a, &b);
        for (int k = 0; k < 3; k++) s[k] = l->pos_m[k] + a * A->le->ex[k] + b * A->le->ey[k];
        sum += cyl_point(A, s, frac);
    }
    return sum;
}

double lx__design_cyl_E(lx_counters *cnt, const lx__scene_lum *le, const double q[3], const double *facing, double tol,
                        const lx__scene_vis *vis)
{
    if (!(le->k > 0)) return 0;
    cyl_arg A = {cnt, le, q, facing, vis};
    const lx_scene_luminaire *l = le->l;
    if (!(lx__scene_lum_size(l) > 0)) {
        cnt->point_evaluations++;
        return le->k * cyl_point(&A, l->pos_m, 1);
    }
    /* a luminous area: its cells as point sources (the kernel has no closed form over an area);
     * Richardson-refined to tol, or with occluders the finest plain sum (a shadow edge makes the
     * midpoint error first order, which the extrapolation would amplify) */
    unsigned long long patches = 0;
    double x = 0, prev = NAN;
    int circ = l->radius_m > 0;
    if (!vis) x = lx__area_refine(cyl_mean, &A, circ, tol, LX__NEAR_MAX_CELLS, &patches, NULL);
    else
        for (int lev = 2; lev <= 64; lev *= 2) {
            x = cyl_mean(&A, lev);
            patches += lx__area_cells(circ, lev);
            if (lev >= 8 && fabs(x - prev) <= tol * fabs(x)) break;
            prev = x;
        }
    cnt->nearfield_pairs++;
    cnt->nearfield_subdivisions += patches;
    return x > 0 ? le->k * x : 0;
}

lx_status lx__design_cyl_alloc(lx_ctx *ctx, const lx_scene *sc, lx_scene_result *res)
{
    const lx_scene_design *d = sc->design;
    int any = 0;
    for (size_t r = 0; d && d->rec_cylinder && r < sc->n_rec; r++) any |= d->rec_cylinder[r];
    if (!any) return LX_OK;
    size_t n = res->n_points ? res->n_points : 1;
    res->cylindrical_lx = lx__alloc_n(n, sizeof(double));
    res->semicylindrical_lx = lx__alloc_n(n, sizeof(double));
    res->modelling = lx__alloc_n(n, sizeof(double));
    if (!res->cylindrical_lx || !res->semicylindrical_lx || !res->modelling)
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t g = 0; g < res->n_points; g++) res->cylindrical_lx[g] = res->semicylindrical_lx[g] = res->modelling[g] = NAN;
    res->cylinder_tol = sc->nearfield_tol;
    return LX_OK;
}

void lx__design_cyl_direct(lx_counters *cnt, const lx_scene *sc, const lx_scene_plan *plan, const lx__scene_lum *le,
                           const lx__scene_vis *vis, long only, lx_scene_result *res)
{
    if (!res->cylindrical_lx) return;
    const lx_scene_design *d = sc->design;
    size_t np = res->n_points;
    for (size_t r = 0; r < sc->n_rec; r++) {
        unsigned char want = d->rec_cylinder[r];
        const lx_scene_receiver *rc = &sc->rec[r];
        for (size_t i = 0; want && i < rc->n; i++) {
            size_t g = res->first[r] + i;
            const double *q = rc->points + 3 * i;
            double ez = 0, esz = 0;
            for (size_t l = 0; l < sc->n_lum; l++) {
                if (only >= 0 && (long)l != only) continue;
                unsigned char o = plan->occ ? plan->occ[l * np + g] : 0;
                if (o == 2) continue; /* another room */
                if (want & LX_REC_CYLINDRICAL) ez += lx__design_cyl_E(cnt, &le[l], q, NULL, sc->nearfield_tol, o ? vis : NULL);
                if (want & LX_REC_SEMICYLINDRICAL)
                    esz += lx__design_cyl_E(cnt, &le[l], q, d->rec_facing + 3 * r, sc->nearfield_tol, o ? vis : NULL);
            }
            if (want & LX_REC_CYLINDRICAL) res->cylindrical_lx[g] = ez;
            if (want & LX_REC_SEMICYLINDRICAL) res->semicylindrical_lx[g] = esz;
        }
    }
}

/* ---- the interreflected part: the mean over azimuth of the gather on vertical planes ----
 * E_z = (1 / 2 pi) integral of E_v(psi) d psi over the full turn (the beam identity above, summed
 * over the reflected light's directions), E_sz = (1 / pi) integral over psi within 90 deg of the
 * facing direction. E_v(psi) is smooth where a gathered face is not cut by the plane's horizon and
 * has a continuous first derivative everywhere, so the periodic trapezoid rule (full turn) and
 * Simpson's rule (half turn) converge fast; the number of azimuths doubles (8, 16, ... 256) until
 * the estimate changes by less than the tolerance of the point's total. */

#define AZ_MIN 8
#define AZ_MAX 256

typedef struct pending {
    size_t g;        /* the result index */
    double q[3];
    int cell;
    int semi;        /* 0: full turn; 1: half turn about facing */
    double f0;       /* azimuth of the facing direction (semi) */
    double sum_end;  /* semi: the end nodes' sum (weights 1/2) */
    double sum_odd;  /* the latest level's new nodes */
    double sum_all;  /* all interior nodes so far */
    double est, prev;
    int done;
} pending;

/* Gathers E on vertical planes for the pending points at the azimuths of level N that are new
 * (every node at the first level; odd multiples of the half step afterwards) into *E (malloc'ed). */
static lx_status gather_level(lx_ctx *ctx, const lx__room_mesh *m, const double *Be, int backend, pending *P, size_t np,
                              int N, int first, double **E)
{
    size_t k = 0, cap = 0;
    for (size_t i = 0; i < np; i++)
        if (!P[i].done) cap += first ? (size_t)(P[i].semi ? N + 1 : N) : (size_t)(N / 2);
    lx__free(*E);
    *E = lx__alloc_n((cap ? cap : 1), sizeof **E);
    double *pts = lx__alloc_n(3 * (cap ? cap : 1), sizeof *pts), *nrm = lx__alloc_n(3 * (cap ? cap : 1), sizeof *nrm);
    int *cell = lx__alloc_n((cap ? cap : 1), sizeof *cell);
    lx_status st = LX_OK;
    if (!*E || !pts || !nrm || !cell) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto out;
    }
    for (size_t i = 0; i < np; i++) {
        if (P[i].done) continue;
        int nodes = P[i].semi ? N + 1 : N; /* half turn: j = 0..N over 180 deg; full: j = 0..N-1 over 360 deg */
        for (int j = 0; j < nodes; j++) {
            if (!first && j % 2 == 0) continue;
            double psi = P[i].semi ? P[i].f0 - LX__PI / 2 + LX__PI * j / N : 2 * LX__PI * j / N;
            memcpy(pts + 3 * k, P[i].q, 3 * sizeof *pts);
            nrm[3 * k] = cos(psi), nrm[3 * k + 1] = sin(psi), nrm[3 * k + 2] = 0;
            cell[k++] = P[i].cell;
        }
    }
    if (k) {
        int used = 0;
        lx__room_gather_job job = {m, m->elem, m->n_elem, Be, k, pts, nrm, cell, NULL, LX__ROOM_VIS_RECEIVERS};
        st = lx__room_gather(ctx, &job, (lx_backend)backend, *E, &used);
    }
out:
    lx__free(pts);
    lx__free(nrm);
    lx__free(cell);
    return st;
}

lx_status lx__design_room_cylinder(lx_ctx *ctx, const lx_scene *sc, const lx__room_mesh *m, const double *Be, int backend,
                                   double tol, lx_scene_result *res)
{
    if (!res->cylindrical_lx) return LX_OK;
    const lx_scene_design *d = sc->design;
    size_t np = 0;
    for (size_t r = 0; r < sc->n_rec; r++)
        np += (size_t)((d->rec_cylinder[r] & 1) + ((d->rec_cylinder[r] >> 1) & 1)) * sc->rec[r].n;
    if (!np) return LX_OK;
    pending *P = lx__calloc(np, sizeof *P);
    double *E = NULL;
    lx_status st = LX_OK;
    if (!P) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto out;
    }
    size_t k = 0;
    for (size_t r = 0; r < sc->n_rec; r++)
        for (int semi = 0; semi < 2; semi++) {
            if (!(d->rec_cylinder[r] & (semi ? LX_REC_SEMICYLINDRICAL : LX_REC_CYLINDRICAL))) continue;
            for (size_t i = 0; i < sc->rec[r].n; i++, k++) {
                P[k].g = res->first[r] + i;
                memcpy(P[k].q, sc->rec[r].points + 3 * i, sizeof P[k].q);
                P[k].cell = lx__room_cell(sc, P[k].q);
                P[k].semi = semi;
                P[k].f0 = atan2(d->rec_facing[3 * r + 1], d->rec_facing[3 * r]);
                P[k].est = P[k].prev = NAN;
            }
        }
    for (int N = AZ_MIN; N <= AZ_MAX; N *= 2) {
        int first = N == AZ_MIN;
        if ((st = gather_level(ctx, m, Be, backend, P, np, N, first, &E)) != LX_OK) goto out;
        size_t e = 0, left = 0;
        for (size_t i = 0; i < np; i++) {
            pending *p = &P[i];
            if (p->done) continue;
            int nodes = p->semi ? N + 1 : N;
            double s_new = 0;
            for (int j = 0; j < nodes; j++) {
                if (!first && j % 2 == 0) continue;
                double v = E[e++];
                if (p->semi && (j == 0 || j == N)) p->sum_end += v;
                else s_new += v;
            }
            double s_old = p->sum_all;
            p->sum_all += s_new;
            double est;
            if (!p->semi) est = p->sum_all / N; /* periodic trapezoid: the mean of the nodes */
            else {
                /* trapezoid on [-90, 90] deg: h (ends / 2 + interior), mean = that / pi; Simpson from
                 * this level and the one before: (4 T_N - T_N/2) / 3 */
                double tN = (0.5 * p->sum_end + p->sum_all) / N, tH = first ? NAN : (0.5 * p->sum_end + s_old) / (N / 2);
                est = first ? tN : (4 * tN - tH) / 3;
            }
            p->prev = p->est;
            p->est = est;
            double *out = p->semi ? res->semicylindrical_lx : res->cylindrical_lx;
            double total = out[p->g] + est;
            if (!first && fabs(est - p->prev) <= tol * fabs(total)) p->done = 1;
            else left++;
        }
        if (!left) break;
    }
    for (size_t i = 0; i < np; i++) {
        double *out = P[i].semi ? res->semicylindrical_lx : res->cylindrical_lx;
        out[P[i].g] += P[i].est > 0 ? P[i].est : 0;
    }
    res->cylinder_tol = fmax(res->cylinder_tol, tol);
out:
    lx__free(P);
    lx__free(E);
    return st;
}

void lx__design_cyl_modelling(const lx_scene *sc, lx_scene_result *res)
{
    if (!res->cylindrical_lx) return;
    const lx_scene_design *d = sc->design;
    size_t nc = sc->n_lum + 1;
    for (size_t r = 0; r < sc->n_rec; r++) {
        const lx_scene_receiver *rc = &sc->rec[r];
        if (!(d->rec_cylinder[r] & LX_REC_CYLINDRICAL) || !(rc->normal[2] == 1)) continue;
        for (size_t i = 0; i < rc->n; i++) {
            size_t g = res->first[r] + i;
            /* the luminaires' horizontal illuminance: the total less the sky's and the daylight's */
            double Eh = res->E_lx[g] - (res->daylight_lx ? res->daylight_lx[g] : res->contrib_lx[g * nc + sc->n_lum]);
            res->modelling[g] = Eh > 0 ? res->cylindrical_lx[g] / Eh : NAN;
        }
    }
}
