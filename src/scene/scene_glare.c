/* scene_glare.c - UGR at a scene's observers (CIE 117-1995): each luminaire's luminance towards
 * the eye over its projected luminous area, its solid angle and Guth position index; the
 * background luminance from the scene file or, in a room, from the luminaires' interreflected
 * illuminance at the eye (Lb = E_ind / pi). */
#include "scene/room_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void lx_scene_glare_free(lx_scene_glare *g)
{
    if (!g) return;
    lx__free(g->ugr);
    lx__free(g->background_cd_m2);
    lx__free(g->terms);
    lx__free(g->indirect_lx);
    lx__free(g);
}

lx_status lx__glare_room_background(lx_ctx *ctx, const lx_scene *sc, const lx__room_mesh *m, const double *Be, int backend,
                                    lx_scene_result *res)
{
    size_t no = sc->n_obs;
    double *pts = lx__alloc_n(3 * no, sizeof *pts), *nrm = lx__alloc_n(3 * no, sizeof *nrm);
    int *cell = lx__alloc_n(no, sizeof *cell), used = 0;
    res->observer_indirect_lx = lx__calloc(no, sizeof *res->observer_indirect_lx);
    lx_status st = LX_OK;
    if (!pts || !nrm || !cell || !res->observer_indirect_lx) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t o = 0; st == LX_OK && o < no; o++) {
        memcpy(pts + 3 * o, sc->obs[o].pos_m, 3 * sizeof *pts);
        memcpy(nrm + 3 * o, sc->obs[o].view, 3 * sizeof *nrm);
        cell[o] = lx__room_cell(sc, sc->obs[o].pos_m);
    }
    lx__room_gather_job g = {m, m->elem, m->n_elem, Be, no, pts, nrm, cell, NULL, LX__ROOM_VIS_RECEIVERS};
    if (st == LX_OK) st = lx__room_gather(ctx, &g, (lx_backend)backend, res->observer_indirect_lx, &used);
    lx__free(pts);
    lx__free(nrm);
    lx__free(cell);
    return st;
}

/* Lb from the rooms for the observers without background_luminance: the scene planned and evaluated,
 * E_ind at each eye (NaN for the others). */
static lx_status room_background(lx_ctx *ctx, const lx_scene *sc, double *E_ind)
{
    for (size_t o = 0; o < sc->n_obs; o++) {
        const lx_scene_observer *ob = &sc->obs[o];
        E_ind[o] = NAN;
        if (ob->background_cd_m2 > 0) continue;
        if (!sc->n_room || lx__room_cell(sc, ob->pos_m) < 0)
            return lx__error(ctx, LX_EPARSE, ob->file, ob->line,
                             "observer '%s': no 'background_luminance', and no room around the eye to take it from (CIE "
                             "117: Lb = E_ind / pi, the indirect illuminance at the eye)",
                             ob->name);
    }
    lx_scene_plan *plan = NULL;
    lx_scene_result *res = NULL;
    lx_status st = lx_scene_plan_make(ctx, sc, LX_BACKEND_AUTO, &plan);
    if (st == LX_OK) st = lx_scene_eval(ctx, sc, plan, NULL, &res);
    if (st == LX_OK && !res->observer_indirect_lx) {
        size_t o = 0;
        while (sc->obs[o].background_cd_m2 > 0) o++;
        st = lx__error(ctx, LX_EPARSE, sc->obs[o].file, sc->obs[o].line,
                       "observer '%s': no 'background_luminance', and interreflection is off (%s)", sc->obs[o].name,
                       plan->reason[LX_EFFECT_INTERREFLECTION]);
    }
    for (size_t o = 0; st == LX_OK && o < sc->n_obs; o++)
        if (!(sc->obs[o].background_cd_m2 > 0)) E_ind[o] = res->observer_indirect_lx[o];
    lx_scene_result_free(res);
    lx_scene_plan_free(plan);
    return st;
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Intensity towards the unit direction u (luminaire to eye) and projected luminous area. */
static void source(const lx_scene_luminaire *l, const double u[3], double *I, double *Ap)
{
    double ex[3], ey[3], ez[3];
    lx__scene_frame(l, ex, ey, ez);
    double x = dot(u, ex), y = dot(u, ey), z = dot(u, ez), c = -z; /* c: cosine from the emitting normal (aim) */
    *I = *Ap = 0;
    switch (l->kind) {
    case LX_SLUM_DISK:
    case LX_SLUM_RECT: {
        double A = l->kind == LX_SLUM_DISK ? LX__PI * l->radius_m * l->radius_m : l->width_m * l->length_m;
        if (c > 0) *I = l->luminance_cd_m2 * A * c, *Ap = A * c;
        break;
    }
    case LX_SLUM_FILE: {
        lx_luminaire tmp = *l->lum; /* the scene's width and length override the file's opening */
        if (l->width_m > 0 && l->length_m > 0) tmp.width_m = l->width_m, tmp.length_m = l->length_m;
        *I = l->scale * lx_luminaire_intensity_dir(l->lum, LX_INTERP_BILINEAR, x, y, z);
        *Ap = lx_luminaire_projected_area(&tmp, x, y, z);
        break;
    }
    default: break; /* points and spots: no luminous area */
    }
}

lx_status lx_scene_glare_eval(lx_ctx *ctx, const lx_scene *sc, lx_scene_glare **out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_glare_eval: NULL argument");
    *out = NULL;
    lx_scene_glare *g = lx__calloc(1, sizeof *g);
    size_t no = sc->n_obs, nl = sc->n_lum;
    if (!g || !(g->ugr = lx__alloc_n(no ? no : 1, sizeof *g->ugr)) ||
        !(g->background_cd_m2 = lx__alloc_n(no ? no : 1, sizeof(double))) ||
        !(g->indirect_lx = lx__alloc_n(no ? no : 1, sizeof(double))) ||
        !(g->terms = lx__calloc(no * nl > 0 ? no * nl : 1, sizeof *g->terms))) {
        lx_scene_glare_free(g);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    int from_room = 0;
    for (size_t o = 0; o < no; o++) {
        g->indirect_lx[o] = NAN;
        from_room |= !(sc->obs[o].background_cd_m2 > 0);
    }
    lx_status st = from_room ? room_background(ctx, sc, g->indirect_lx) : LX_OK;
    if (st != LX_OK) {
        lx_scene_glare_free(g);
        return st;
    }
    g->n_obs = no, g->n_lum = nl;
    for (size_t o = 0; o < no; o++) {
        const lx_scene_observer *ob = &sc->obs[o];
        double right[3] = {ob->view[1] * ob->up[2] - ob->view[2] * ob->up[1], ob->view[2] * ob->up[0] - ob->view[0] * ob->up[2],
                           ob->view[0] * ob->up[1] - ob->view[1] * ob->up[0]};
        double sum = 0;
        for (size_t l = 0; l < nl; l++) {
            lx_glare_term *t = &g->terms[o * nl + l];
            const lx_scene_luminaire *L = &sc->lum[l];
            double s[3] = {L->pos_m[0] - ob->pos_m[0], L->pos_m[1] - ob->pos_m[1], L->pos_m[2] - ob->pos_m[2]};
            double d2 = dot(s, s), d = sqrt(d2);
            t->sigma_deg = t->tau_deg = t->position_index = NAN;
            if (!(d > 0)) continue;
            for (int k = 0; k < 3; k++) s[k] /= d;
            double cs = dot(s, ob->view);
            t->sigma_deg = acos(cs > 1 ? 1 : cs < -1 ? -1 : cs) / LX__DEG;
            t->tau_deg = atan2(fabs(dot(s, right)), dot(s, ob->up)) / LX__DEG;
            double u[3] = {-s[0], -s[1], -s[2]}, I, Ap;
            source(L, u, &I, &Ap);
            if (!(t->sigma_deg < 90) || !(Ap > 0) || !(I > 0)) continue;
            t->visible = 1;
            t->luminance_cd_m2 = I / Ap;
            t->solid_angle_sr = Ap / d2;
            t->position_index = lx_guth_position_index(t->sigma_deg, t->tau_deg);
            t->term = t->luminance_cd_m2 * t->luminance_cd_m2 * t->solid_angle_sr /
                      (t->position_index * t->position_index);
            sum += t->term;
        }
        double Lb = ob->background_cd_m2 > 0 ? ob->background_cd_m2 : g->indirect_lx[o] / LX__PI;
        g->background_cd_m2[o] = Lb;
        g->ugr[o] = sum > 0 && Lb > 0 ? 8 * log10(0.25 / Lb * sum) : NAN;
    }
    *out = g;
    return LX_OK;
}
