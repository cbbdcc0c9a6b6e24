/* daylight_plan.c - the planner's part for daylight: `daylight` is on when the scene has a sky
 * (or the sun) and openings; the outside illuminance the daylight factor refers to, the flux in
 * through the openings, the estimated interreflected share that sizes the room's patches; the
 * openings as holes of the mesh; the daylight's set-up shared with the evaluation. */
#include "scene/daylight_private.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void why(lx_scene_plan *p, int on, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->reason[LX_EFFECT_DAYLIGHT], sizeof p->reason[LX_EFFECT_DAYLIGHT], fmt, ap);
    va_end(ap);
    p->on[LX_EFFECT_DAYLIGHT] = on;
}

/* The outward normal of room face k (the face's inward normal reversed). */
static void outward(int k, double m[3])
{
    int axis = k < 2 ? 2 : k < 4 ? 0 : 1;
    m[0] = m[1] = m[2] = 0;
    m[axis] = k % 2 ? 1 : -1;
}

/* A length beyond every entity of the scene: rays that leave a room end there. */
double lx__daylight_far(const lx_scene *sc)
{
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (size_t r = 0; r < sc->n_room; r++)
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], sc->room[r].min_m[k]), hi[k] = fmax(hi[k], sc->room[r].max_m[k]);
    for (size_t r = 0; r < sc->n_obst; r++)
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], sc->obst[r].min_m[k]), hi[k] = fmax(hi[k], sc->obst[r].max_m[k]);
    for (size_t r = 0; r < sc->n_surf; r++)
        for (int k = 0; k < 3; k++) {
            const lx_scene_surface *s = &sc->surf[r];
            double a = s->corner_m[k], b = a + s->edge1_m[k], c = a + s->edge2_m[k], d = b + s->edge2_m[k];
            lo[k] = fmin(lo[k], fmin(fmin(a, b), fmin(c, d))), hi[k] = fmax(hi[k], fmax(fmax(a, b), fmax(c, d)));
        }
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++)
            for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], sc->rec[r].points[3 * i + k]), hi[k] = fmax(hi[k], sc->rec[r].points[3 * i + k]);
    double d = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
    double c = 0;
    for (int k = 0; k < 3; k++) c = fmax(c, fmax(fabs(lo[k]), fabs(hi[k])));
    return 10 * (d + c) + 100;
}

void lx__daylight_free(lx__daylight *d)
{
    if (!d) return;
    lx__scene_sky_map_free(d->map);
    lx__room_mesh_free(d->own_occ);
    lx__free(d->op);
    lx__free(d->sky_lx);
    lx__free(d->ground_lx);
    lx__free(d->sun_pt_lx);
    lx__free(d->ind_lx);
    lx__free(d->face_direct_lm);
    lx__free(d->face_indirect_lm);
    lx__free(d);
}

/* The occluders rays are tested against: the given ones or the plan's, else (when the planner kept
 * none: no luminaire pair needed them) built here, unless occlusion is forced off. */
static lx_status occluders(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lx__room_mesh *occ,
                           lx__daylight *d)
{
    const lx__room_mesh *pm = occ ? occ : plan ? plan->room.mesh : NULL;
    if (pm && pm->n_occ) d->occ = pm->occ, d->n_occ = (int)pm->n_occ;
    else if ((sc->n_surf || sc->n_obst) && sc->force[LX_EFFECT_OCCLUSION] != LX_FORCE_OFF) {
        lx_status st = lx__room_occluders(ctx, sc, &d->own_occ);
        if (st != LX_OK) return st;
        d->occ = d->own_occ->occ, d->n_occ = (int)d->own_occ->n_occ;
    }
    return LX_OK;
}

lx_status lx__daylight_sun_only(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, lx__daylight **out)
{
    *out = NULL;
    if (!(sc->has_sun && sc->sun_normal_lx > 0 && sc->sun_dir[2] > 0) || (!sc->n_room && !sc->n_surf && !sc->n_obst) ||
        sc->force[LX_EFFECT_OCCLUSION] == LX_FORCE_OFF)
        return LX_OK;
    lx__daylight *d = lx__calloc(1, sizeof *d);
    if (!d) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    d->sc = sc;
    d->plan = plan;
    memcpy(d->sun, sc->sun_dir, sizeof d->sun);
    d->sun_lx = sc->sun_normal_lx;
    d->far_m = lx__daylight_far(sc);
    lx_status st = occluders(ctx, sc, plan, NULL, d);
    if (st != LX_OK) {
        lx__daylight_free(d);
        return st;
    }
    *out = d;
    return LX_OK;
}

lx_status lx__daylight_setup(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lx__room_mesh *occ,
                             lx__daylight **out)
{
    *out = NULL;
    lx__daylight *d = lx__calloc(1, sizeof *d);
    if (!d) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    d->sc = sc;
    d->plan = plan;
    lx_status st = LX_OK;
    if (sc->sky == LX_SKY_MAP && (st = lx__scene_sky_map_load(ctx, sc, &d->map)) != LX_OK) goto fail;
    if (sc->sky == LX_SKY_UNIFORM) d->closed = 1, d->L0 = sc->sky_luminance_cd_m2;
    if (sc->sky == LX_SKY_OVERCAST)
        d->closed = 1, d->L0 = sc->sky_luminance_cd_m2 / 3, d->L1 = 2 * sc->sky_luminance_cd_m2 / 3;
    double E_sun_h;
    lx__scene_sky_horizontal(sc, d->map, &d->E_h, &E_sun_h);
    d->Lg = sc->ground_reflectance * E_sun_h / LX__PI;
    if (sc->has_sun && sc->sun_normal_lx > 0 && sc->sun_dir[2] > 0) {
        memcpy(d->sun, sc->sun_dir, sizeof d->sun);
        d->sun_lx = sc->sun_normal_lx;
    }
    d->tol = plan && plan->daylight.quad_tol > 0 ? plan->daylight.quad_tol : 0.1 * sc->interreflection_tol;
    d->far_m = lx__daylight_far(sc);
    if ((st = occluders(ctx, sc, plan, occ, d)) != LX_OK) goto fail;
    d->n_op = sc->n_open;
    d->op = lx__calloc(d->n_op ? d->n_op : 1, sizeof *d->op);
    if (!d->op) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        goto fail;
    }
    for (size_t k = 0; k < d->n_op; k++) {
        const lx_scene_opening *so = &sc->open[k];
        lx__dl_open *op = &d->op[k];
        for (int i = 0; i < 3; i++) {
            op->o[i] = so->corner_m[i], op->u[i] = so->edge1_m[i], op->v[i] = so->edge2_m[i];
            double a = op->o[i], b = a + op->u[i], c = a + op->v[i], e = b + op->v[i];
            op->lo[i] = fmin(fmin(a, b), fmin(c, e)), op->hi[i] = fmax(fmax(a, b), fmax(c, e));
        }
        op->size_m = sqrt(dot3(op->u, op->u) + dot3(op->v, op->v));
        op->area_m2 = so->area_m2;
        outward(so->face, op->m);
        op->room = (int)so->room;
        op->face = 6 * (int)so->room + (int)so->face;
        lx__daylight_glazing(op, so->glazing, so->transmittance);
        /* something beyond its plane may cut the rays that leave through it */
        int axis = so->face < 2 ? 2 : so->face < 4 ? 0 : 1;
        double plane = op->o[axis], sg = op->m[axis], e = 1e-9 * (1 + fabs(plane));
        for (int i = 0; i < d->n_occ && !op->outside_occ; i++)
            op->outside_occ = sg > 0 ? d->occ[i].hi[axis] > plane + e : d->occ[i].lo[axis] < plane - e;
        for (size_t r = 0; r < sc->n_room && !op->outside_occ; r++)
            if ((int)r != op->room) {
                const lx_scene_room *R = &sc->room[r];
                op->outside_occ = sg > 0 ? R->max_m[axis] > plane + e : R->min_m[axis] < plane - e;
            }
    }
    *out = d;
    return LX_OK;
fail:
    lx__daylight_free(d);
    return st;
}

lx_status lx__daylight_mesh_openings(lx_ctx *ctx, const lx_scene *sc, const lx__room_mesh *occ, lx__room_opening **open,
                                     size_t *n)
{
    *open = NULL;
    *n = 0;
    if (!sc->n_open) return LX_OK;
    lx__room_opening *o = lx__alloc_n(sc->n_open, sizeof *o);
    if (!o) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t k = 0; k < sc->n_open; k++) {
        const lx_scene_opening *so = &sc->open[k];
        int fi = 6 * (int)so->room + (int)so->face;
        const lx__room_face *f = &occ->face[fi];
        double s0 = INFINITY, s1 = -INFINITY, t0 = INFINITY, t1 = -INFINITY;
        double uu = dot3(f->u, f->u), vv = dot3(f->v, f->v);
        for (int c = 0; c < 4; c++) {
            double y[3];
            for (int i = 0; i < 3; i++)
                y[i] = so->corner_m[i] + ((c == 1 || c == 2) ? so->edge1_m[i] : 0) + (c >= 2 ? so->edge2_m[i] : 0) - f->o[i];
            double s = dot3(y, f->u) / uu, t = dot3(y, f->v) / vv; /* room faces are rectangles */
            s0 = fmin(s0, s), s1 = fmax(s1, s), t0 = fmin(t0, t), t1 = fmax(t1, t);
        }
        o[k] = (lx__room_opening){fi, fmax(0, s0), fmin(1, s1), fmax(0, t0), fmin(1, t1)};
    }
    *open = o;
    *n = sc->n_open;
    return LX_OK;
}

int lx__daylight_order(const lx_scene *sc, const lx__room_patch *e, double tol)
{
    double dmin = INFINITY;
    for (size_t k = 0; k < sc->n_open; k++) {
        const lx_scene_opening *so = &sc->open[k];
        if ((int)so->room != e->cell) continue;
        double m[3], c[3];
        outward(so->face, m);
        for (int i = 0; i < 3; i++) c[i] = so->corner_m[i] + 0.5 * (so->edge1_m[i] + so->edge2_m[i]) - e->c[i];
        if (!(dot3(m, c) > 1e-9)) continue; /* its own plane */
        /* the distance to the rectangle: the centre's offset clamped to it (axis-aligned) */
        double dd = 0;
        for (int i = 0; i < 3; i++) {
            double a = so->corner_m[i], b = a + so->edge1_m[i] + so->edge2_m[i], lo = fmin(a, b), hi = fmax(a, b);
            double q = e->c[i] < lo ? lo - e->c[i] : e->c[i] > hi ? e->c[i] - hi : 0;
            dd += q * q;
        }
        dmin = fmin(dmin, sqrt(dd));
    }
    if (!isfinite(dmin)) return 1;
    double r = 0.5 * e->size_m / fmax(dmin, 0.5 * e->size_m);
    int m = 1;
    while (m < 8 && 0.5 * pow(r, 2 * m) > tol) m++;
    return m;
}

/* The kind of sky for the reason and the daylight factor. */
static const char *sky_words(const lx_scene *sc, char *buf, size_t n)
{
    switch (sc->sky) {
    case LX_SKY_UNIFORM: snprintf(buf, n, "uniform sky (%.4g cd/m2)", sc->sky_luminance_cd_m2); break;
    case LX_SKY_OVERCAST: snprintf(buf, n, "traditional CIE overcast sky (Lz %.4g cd/m2, E_h = 7 pi Lz / 9)", sc->sky_luminance_cd_m2); break;
    case LX_SKY_CIE: snprintf(buf, n, "CIE general sky type %d", sc->sky_cie_type); break;
    case LX_SKY_PEREZ: snprintf(buf, n, "Perez sky"); break;
    case LX_SKY_MAP: snprintf(buf, n, "EXR sky map"); break;
    default: snprintf(buf, n, "no sky"); break;
    }
    return buf;
}

/* The largest interreflected share of a receiver point's daylight: the integrating-sphere estimate
 * rho Phi_in / (S (1 - rho)) of each room with openings against the direct daylight at the point as
 * a uniform sky of the same horizontal illuminance would give it (closed form, no occluders). */
static double share(const lx_scene *sc, lx__daylight *d, const double *flux_room)
{
    lx__daylight u = *d;
    u.closed = 1, u.L0 = d->E_h / LX__PI, u.L1 = 0, u.n_occ = 0;
    for (size_t k = 0; k < u.n_op; k++) u.op[k].outside_occ = 0; /* the copy shares op: restored below */
    double *ind = lx__calloc(sc->n_room ? sc->n_room : 1, sizeof *ind), worst = 0;
    if (!ind) return 1;
    for (size_t r = 0; r < sc->n_room; r++) {
        const lx_scene_room *R = &sc->room[r];
        double L[3], S = 0, rs = 0;
        for (int k = 0; k < 3; k++) L[k] = R->max_m[k] - R->min_m[k];
        double A[6] = {L[0] * L[1], L[0] * L[1], L[1] * L[2], L[1] * L[2], L[0] * L[2], L[0] * L[2]};
        for (int k = 0; k < 6; k++) S += A[k], rs += A[k] * R->reflectance[k];
        double rho = rs / S;
        ind[r] = rho < 1 ? rho * flux_room[r] / (S * (1 - rho)) : 0;
    }
    lx_counters cnt;
    memset(&cnt, 0, sizeof cnt);
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++) {
            const double *q = sc->rec[r].points + 3 * i;
            int c = lx__room_cell(sc, q);
            if (c < 0 || !(ind[c] > 0)) continue;
            double out[3];
            lx__daylight_at(&u, q, sc->rec[r].normal, c, -1, 1, out, &cnt);
            double dir = out[0] + out[1] + out[2], s = ind[c] / (ind[c] + dir);
            worst = fmax(worst, s);
        }
    lx__free(ind);
    return worst;
}

lx_status lx__daylight_plan(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p)
{
    lx_effect_force F = sc->force[LX_EFFECT_DAYLIGHT];
    memset(&p->daylight, 0, sizeof p->daylight);
    int sky = sc->sky != LX_SKY_NONE || (sc->has_sun && sc->sun_normal_lx > 0);
    if (!sc->n_open || !sky) {
        if (F == LX_FORCE_ON)
            return lx__error(ctx, LX_EPARSE, sc->file, sc->force_line[LX_EFFECT_DAYLIGHT],
                             "daylight forced on, but the scene has no %s", sc->n_open ? "[sky] or [sun]" : "[opening]");
        if (!sc->n_open) why(p, 0, "no [opening] in a room");
        else why(p, 0, "no [sky] or sun: the %zu openings are holes that let the rooms' light out", sc->n_open);
        return LX_OK;
    }
    if (F == LX_FORCE_OFF) {
        why(p, 0, "forced off in [effects]: the openings are holes that let the rooms' light out and no daylight in");
        return LX_OK;
    }
    lx__daylight *d = NULL;
    lx_status st = lx__daylight_setup(ctx, sc, p, NULL, &d);
    if (st != LX_OK) return st;
    lx_scene_daylight_plan *D = &p->daylight;
    D->quad_tol = 0.1 * sc->interreflection_tol;
    d->tol = D->quad_tol;
    D->outside_lx = d->E_h;
    D->ground_cd_m2 = d->Lg;
    D->closed_form = d->closed;
    int overcast = sc->sky == LX_SKY_UNIFORM || sc->sky == LX_SKY_OVERCAST || (sc->sky == LX_SKY_CIE && sc->sky_cie_type <= 5);
    D->df = overcast && !(d->sun_lx > 0) && d->E_h > 0;
    double *flux_room = lx__calloc(sc->n_room ? sc->n_room : 1, sizeof *flux_room), area = 0;
    if (!flux_room) {
        lx__daylight_free(d);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t k = 0; k < d->n_op; k++) {
        double phi = d->op[k].area_m2 * lx__daylight_opening_E(d, k);
        D->flux_in_lm += phi;
        flux_room[d->op[k].room] += phi;
        area += d->op[k].area_m2;
    }
    unsigned char *saved = lx__alloc(d->n_op ? d->n_op : 1);
    for (size_t k = 0; saved && k < d->n_op; k++) saved[k] = (unsigned char)d->op[k].outside_occ;
    D->share_est = p->on[LX_EFFECT_INTERREFLECTION] || sc->force[LX_EFFECT_INTERREFLECTION] != LX_FORCE_OFF ? share(sc, d, flux_room) : 0;
    for (size_t k = 0; saved && k < d->n_op; k++) d->op[k].outside_occ = saved[k];
    lx__free(saved);
    lx__free(flux_room);
    /* the work: every receiver point inside a room with openings, once per opening of its room */
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++) {
            int c = lx__room_cell(sc, sc->rec[r].points + 3 * i);
            for (size_t k = 0; c >= 0 && k < d->n_op; k++) p->estimate.daylight_evaluations += d->op[k].room == c;
        }
    char sk[160], dfw[200];
    sky_words(sc, sk, sizeof sk);
    if (D->df)
        snprintf(dfw, sizeof dfw, "daylight factor against E_h = %.6g lx outside (%s)", D->outside_lx,
                 sc->sky == LX_SKY_OVERCAST ? "the traditional overcast sky" : sc->sky == LX_SKY_UNIFORM ? "a uniform sky" : "CIE sky type 1..5");
    else
        snprintf(dfw, sizeof dfw, "no daylight factor (%s)",
                 d->sun_lx > 0 ? "the sun shines: it is defined under an overcast sky alone" : "defined under overcast skies only");
    why(p, 1, "%s%s%s; %zu opening%s (%.4g m2): %.6g lm in; sky component %s; %s", F == LX_FORCE_ON ? "forced on in [effects]; " : "",
        sk, d->sun_lx > 0 ? " and the sun" : "", d->n_op, d->n_op == 1 ? "" : "s", area, D->flux_in_lm,
        D->closed_form ? "in closed form" : "integrated numerically", dfw);
    lx__daylight_free(d);
    return LX_OK;
}

lx_status lx__daylight_plan_after(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p)
{
    (void)ctx;
    if (!p->on[LX_EFFECT_ENVIRONMENT]) /* the rooms' rule may have turned it off after its estimate */
        p->estimate.environment_evaluations = p->estimate.environment_samples = 0;
    if (!p->on[LX_EFFECT_DAYLIGHT]) return LX_OK;
    /* the rooms' rule turned the sky off for receivers inside rooms: it reaches them through openings */
    if (!p->on[LX_EFFECT_ENVIRONMENT] && !strncmp(p->reason[LX_EFFECT_ENVIRONMENT], "every receiver is inside", 24))
        snprintf(p->reason[LX_EFFECT_ENVIRONMENT], sizeof p->reason[LX_EFFECT_ENVIRONMENT],
                 "every receiver is inside a room: the sky reaches them through the openings only (daylight)");
    if (p->on[LX_EFFECT_INTERREFLECTION]) {
        char *r = p->reason[LX_EFFECT_INTERREFLECTION];
        size_t l = strlen(r);
        snprintf(r + l, sizeof p->reason[LX_EFFECT_INTERREFLECTION] - l, "; and the daylight's %.4g lm (reflected share <= %.0f%%)",
                 p->daylight.flux_in_lm, 100 * p->daylight.share_est);
    }
    const lx__room_mesh *m = p->room.mesh;
    if (p->on[LX_EFFECT_INTERREFLECTION] && m && m->elem) {
        double tq = 0.25 * sc->interreflection_tol;
        for (size_t e = 0; e < m->n_elem; e++) {
            int o = lx__daylight_order(sc, &m->elem[e], tq);
            for (size_t k = 0; k < sc->n_open; k++)
                p->estimate.daylight_evaluations += (unsigned long long)(o * o) * ((int)sc->open[k].room == m->elem[e].cell);
        }
    }
    return LX_OK;
}

/* ---- the rooms' mesh ---- */

typedef struct mesh_state {
    lx__room_opening *holes;
    lx__daylight *d;
} mesh_state;

static double probe(void *arg, const lx__room_patch *p, const double x[3])
{
    lx_counters cnt; /* the planner's probes: not the evaluation's work */
    double out[3];
    lx__daylight_at(arg, x, p->n, p->cell, p->occluder, 1, out, &cnt);
    return out[0] + out[1] + out[2];
}

lx_status lx__daylight_mesh_begin(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *p, const lx__room_mesh *occ,
                                  lx__room_mesh_opts *o, void **state)
{
    *state = NULL;
    if (!sc->n_open) return LX_OK;
    mesh_state *ms = lx__calloc(1, sizeof *ms);
    if (!ms) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    lx_status st = lx__daylight_mesh_openings(ctx, sc, occ, &ms->holes, &o->n_open);
    o->open = ms->holes;
    if (st == LX_OK && p->on[LX_EFFECT_DAYLIGHT] && (st = lx__daylight_setup(ctx, sc, p, occ, &ms->d)) == LX_OK) {
        o->probe_extra = probe;
        o->probe_arg = ms->d;
        /* the daylight's integrating-sphere level in its rooms: variations below half of it do not matter */
        double worst = 0;
        for (size_t r = 0; r < sc->n_room; r++) {
            const lx_scene_room *R = &sc->room[r];
            double L[3], S = 0, rs = 0, phi = 0;
            for (int k = 0; k < 3; k++) L[k] = R->max_m[k] - R->min_m[k];
            double A[6] = {L[0] * L[1], L[0] * L[1], L[1] * L[2], L[1] * L[2], L[0] * L[2], L[0] * L[2]};
            for (int k = 0; k < 6; k++) S += A[k], rs += A[k] * R->reflectance[k];
            for (size_t k = 0; k < ms->d->n_op; k++)
                if (ms->d->op[k].room == (int)r) phi += ms->d->op[k].area_m2 * lx__daylight_opening_E(ms->d, k);
            double rho = rs / S;
            if (rho < 1) worst = fmax(worst, rho * phi / (S * (1 - rho)));
        }
        o->indirect_est_lx += worst;
    }
    *state = ms;
    if (st != LX_OK) lx__daylight_mesh_end(o, ms), *state = NULL;
    return st;
}

void lx__daylight_mesh_end(lx__room_mesh_opts *o, void *state)
{
    mesh_state *ms = state;
    o->open = NULL;
    o->n_open = 0;
    o->probe_extra = NULL;
    o->probe_arg = NULL;
    if (!ms) return;
    lx__free(ms->holes);
    lx__daylight_free(ms->d);
    lx__free(ms);
}
