/* room_plan.c - the planner's part for rooms: `occlusion` (a bounding-volume test per luminaire-
 * receiver pair decides which are visibility-tested; pairs in different rooms are blocked) and
 * `interreflection` (the integrating-sphere estimate of the indirect light chooses the patch size,
 * the refinement and the stopping point that meet interreflection_tolerance; the mesh is built
 * here, so every evaluation of the plan uses the same patches). */
#include "scene/daylight_private.h" /* the openings (holes) and the daylight's share */

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The discretisation error model: the relative error of the indirect illuminance at a receiver
 * is about ROOM_ERR_C (h / D)^2 for patches of size h in a room whose smallest extent is D
 * (calibrated on `luxcalc bench room`: with 0.05 its worst work-plane point is within the
 * tolerance at 1e-2 and 1e-3; receivers close to a face are the elements' business). */
#define ROOM_ERR_C 0.05

static void why(lx_scene_plan *p, lx_effect e, int on, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->reason[e], sizeof p->reason[e], fmt, ap);
    va_end(ap);
    p->on[e] = on;
}

void lx__room_plan_free(lx_scene_plan *p)
{
    lx__free(p->occ);
    p->occ = NULL;
    lx__room_mesh_free(p->room.mesh);
    p->room.mesh = NULL;
}

int lx__room_lum_bv(const lx__room_mesh *m, const lx__scene_lum *le, const double q[3], int skip)
{
    const lx_scene_luminaire *L = le->l;
    double a = L->radius_m > 0 ? L->radius_m : 0.5 * L->width_m, b = L->radius_m > 0 ? L->radius_m : 0.5 * L->length_m;
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        double ext = fabs(a * le->ex[k]) + fabs(b * le->ey[k]);
        lo[k] = fmin(L->pos_m[k] - ext, q[k]);
        hi[k] = fmax(L->pos_m[k] + ext, q[k]);
    }
    return lx__room_shaft(m->occ, (int)m->n_occ, lo, hi, L->pos_m, q, sqrt(a * a + b * b), skip, -1);
}

/* Occlusion: the flag of every pair, the reason and the estimate. */
static lx_status plan_occlusion(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p, const lx__room_mesh *m,
                                const lx__scene_lum *le)
{
    const lx_effect_force f = sc->force[LX_EFFECT_OCCLUSION];
    size_t n_occ = sc->n_surf + sc->n_obst;
    if (!n_occ && sc->n_room < 2) {
        if (f == LX_FORCE_ON)
            return lx__error(ctx, LX_EPARSE, sc->file, sc->force_line[LX_EFFECT_OCCLUSION],
                             "occlusion forced on, but the scene has no surface, obstruction or second room");
        why(p, LX_EFFECT_OCCLUSION, 0, "no surfaces or obstructions%s", sc->n_room ? " (a room's walls hide nothing inside it)" : "");
        return LX_OK;
    }
    if (f == LX_FORCE_OFF) {
        why(p, LX_EFFECT_OCCLUSION, 0, "forced off in [effects]: surfaces and obstructions block no light");
        return LX_OK;
    }
    p->occ = lx__calloc(p->n_pairs ? p->n_pairs : 1, 1);
    if (!p->occ) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t l = 0; l < sc->n_lum; l++) {
        int lc = lx__room_cell(sc, sc->lum[l].pos_m), area = lx__scene_lum_size(&sc->lum[l]) > 0;
        size_t g = 0;
        for (size_t r = 0; r < sc->n_rec; r++)
            for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
                const double *q = sc->rec[r].points + 3 * i;
                unsigned char *o = &p->occ[l * p->n_points + g];
                if (sc->n_room && lx__room_cell(sc, q) != lc) *o = 2, p->n_occ_blocked++;
                else if (n_occ && lx__room_lum_bv(m, &le[l], q, -1)) {
                    *o = 1;
                    p->n_occ_tested++;
                    p->estimate.visibility_tests += area ? 9 : 1;
                }
            }
    }
    /* the faces are receivers too when they interreflect: their direct light and form factors
     * see the occluders whatever the receivers do */
    int faces = 0;
    if (n_occ && sc->force[LX_EFFECT_INTERREFLECTION] != LX_FORCE_OFF) {
        faces = sc->n_room > 0;
        for (size_t i = 0; i < sc->n_surf; i++) faces |= sc->surf[i].reflectance > 0;
        for (size_t i = 0; i < sc->n_obst; i++) faces |= sc->obst[i].reflectance > 0;
    }
    if (p->n_occ_tested || p->n_occ_blocked || f == LX_FORCE_ON || faces)
    {
        char blocked[96] = "";
        if (p->n_occ_blocked) snprintf(blocked, sizeof blocked, ", %zu blocked (different rooms)", p->n_occ_blocked);
        why(p, LX_EFFECT_OCCLUSION, 1, "%s%zu surfaces and obstructions: %zu of %zu pairs visibility-tested%s%s",
            f == LX_FORCE_ON ? "forced on in [effects]; " : "", n_occ, p->n_occ_tested, p->n_pairs, blocked,
            faces ? "; the faces' direct light and form factors too" : "");
    }
    else
        why(p, LX_EFFECT_OCCLUSION, 0, "no surface or obstruction can cut a luminaire-receiver segment (bounding volumes)");
    if (!p->on[LX_EFFECT_OCCLUSION]) {
        lx__free(p->occ);
        p->occ = NULL;
    }
    return LX_OK;
}

/* The largest indirect share of a receiver point's total: E_ind / (E_ind + E_dir), E_dir probed
 * by the point law with visibility (not counted as work). */
static void add_counters(lx_counters *to, const lx_counters *c)
{
    unsigned long long *a = (unsigned long long *)to;
    const unsigned long long *b = (const unsigned long long *)c;
    for (size_t k = 0; k < sizeof *to / sizeof *a; k++) a[k] += b[k];
}

static double share_max(const lx_scene *sc, lx_scene_plan *p, const lx__room_mesh *m, const lx__scene_lum *le,
                        double E_ind)
{
    lx_counters probe;
    memset(&probe, 0, sizeof probe);
    lx__scene_vis vis = {m->occ, (int)m->n_occ, -1};
    double worst = 0;
    size_t g = 0;
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
            const double *q = sc->rec[r].points + 3 * i;
            double E = 0;
            for (size_t l = 0; l < sc->n_lum; l++) {
                unsigned char o = p->occ ? p->occ[l * p->n_points + g] : 0;
                if (o == 2) continue;
                E += lx__scene_lum_E(&probe, &le[l], q, sc->rec[r].normal, 0, 1e-3, o ? &vis : NULL);
            }
            double s = E_ind > 0 ? E_ind / (E_ind + E) : 0;
            if (s > worst) worst = s;
        }
    add_counters(&p->planning, &probe); /* the planner's own work */
    return worst;
}

/* The reflecting area, its mean reflectance and the flux that reaches it (luminaires in a room,
 * or in the open with reflectors there). */
static void flux_balance(const lx_scene *sc, const lx_scene_plan *p, const lx__room_mesh *m, double *S, double *rho,
                         double *flux)
{
    double a = 0, ra = 0;
    int open_reflectors = 0;
    for (size_t i = 0; i < m->n_face; i++) {
        double A = m->face[i].area_m2;
        if (!(A > 0)) {
            const lx__room_face *f = &m->face[i];
            double c[3] = {f->u[1] * f->v[2] - f->u[2] * f->v[1], f->u[2] * f->v[0] - f->u[0] * f->v[2],
                           f->u[0] * f->v[1] - f->u[1] * f->v[0]};
            A = m->n_patch ? 0 : sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]); /* before the mesh: the whole face */
        }
        a += A;
        ra += A * m->face[i].rho;
        open_reflectors |= m->face[i].cell < 0 && m->face[i].rho > 0;
    }
    double F = 0;
    for (size_t l = 0; l < sc->n_lum; l++) {
        int c = lx__room_cell(sc, sc->lum[l].pos_m);
        if (c >= 0 || open_reflectors) F += sc->lum[l].flux_lm * (p->lum_scale ? p->lum_scale[l] : 1);
    }
    *S = a;
    *rho = a > 0 ? ra / a : 0;
    *flux = F;
}

/* The characteristic distance of the discretisation error: the smallest extent of a room, or in
 * the open the largest reflector's size. */
static double extent_m(const lx_scene *sc)
{
    double D = INFINITY;
    for (size_t r = 0; r < sc->n_room; r++)
        for (int k = 0; k < 3; k++) D = fmin(D, sc->room[r].max_m[k] - sc->room[r].min_m[k]);
    if (isfinite(D)) return D;
    D = 0;
    for (size_t i = 0; i < sc->n_surf; i++)
        D = fmax(D, fmax(sqrt(sc->surf[i].edge1_m[0] * sc->surf[i].edge1_m[0] + sc->surf[i].edge1_m[1] * sc->surf[i].edge1_m[1] +
                              sc->surf[i].edge1_m[2] * sc->surf[i].edge1_m[2]),
                         sqrt(sc->surf[i].edge2_m[0] * sc->surf[i].edge2_m[0] + sc->surf[i].edge2_m[1] * sc->surf[i].edge2_m[1] +
                              sc->surf[i].edge2_m[2] * sc->surf[i].edge2_m[2])));
    for (size_t i = 0; i < sc->n_obst; i++)
        for (int k = 0; k < 3; k++) D = fmax(D, sc->obst[i].max_m[k] - sc->obst[i].min_m[k]);
    return D > 0 ? D : 1;
}

static lx_status plan_interreflection(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p, lx__room_mesh *occ,
                                      const lx__scene_lum *le)
{
    const lx_effect_force f = sc->force[LX_EFFECT_INTERREFLECTION];
    /* a face of reflectance 0 reflects nothing: a room whose every face is black, with black
     * obstructions and surfaces, holds no indirect light */
    int reflectors = 0, bodies = sc->n_room + sc->n_surf + sc->n_obst > 0;
    for (size_t i = 0; i < sc->n_room; i++)
        for (int k = 0; k < 6; k++) reflectors |= sc->room[i].reflectance[k] > 0;
    for (size_t i = 0; i < sc->n_surf; i++) reflectors |= sc->surf[i].reflectance > 0;
    for (size_t i = 0; i < sc->n_obst; i++) reflectors |= sc->obst[i].reflectance > 0;
    if (!reflectors) {
        if (f == LX_FORCE_ON)
            return lx__error(ctx, LX_EPARSE, sc->file, sc->force_line[LX_EFFECT_INTERREFLECTION],
                             bodies ? "interreflection forced on, but every reflectance of the scene's rooms, surfaces "
                                      "and obstructions is 0: no light is reflected"
                                    : "interreflection forced on, but the scene has no room and no reflecting surface");
        why(p, LX_EFFECT_INTERREFLECTION, 0,
            bodies ? "every reflectance is 0 (rooms, surfaces, obstructions): no light is reflected"
                   : "no room and no reflecting surfaces");
        return LX_OK;
    }
    if (f == LX_FORCE_OFF) {
        why(p, LX_EFFECT_INTERREFLECTION, 0, "forced off in [effects]: direct light only");
        return LX_OK;
    }
    lx_scene_room_plan *R = &p->room;
    double S, rho, flux;
    flux_balance(sc, p, occ, &S, &rho, &flux);
    R->tolerance = sc->interreflection_tol;
    R->indirect_est_lx = S > 0 ? rho * flux / (S * (1 - rho)) : 0;
    R->share_est = share_max(sc, p, occ, le, R->indirect_est_lx);
    R->share_est = fmax(R->share_est, p->daylight.share_est); /* daylight through openings (daylight_plan.c) */
    /* the tolerance on the indirect part that meets tol on the total of the receiver whose
     * indirect share is largest */
    double t_ind = fmin(0.3, R->tolerance / fmax(R->share_est, 1e-3)), D = extent_m(sc);
    double h = sc->patch_size_m > 0 ? sc->patch_size_m : D * sqrt(0.75 * t_ind / ROOM_ERR_C);
    if (!(sc->patch_size_m > 0)) h = fmin(fmax(h, D / 400), D / 2);
    R->patch_size_m = h;
    lx__room_mesh_opts o;
    memset(&o, 0, sizeof o);
    o.h_m = h;
    o.tol = t_ind;
    o.quad_tol = 0.25 * R->tolerance; /* the faces' direct light is a result of its own */
    o.indirect_est_lx = R->indirect_est_lx;
    o.max_depth = sc->patch_refinement ? 3 : 0;
    o.max_patches = lx__room_max_patches();
    o.max_file = sc->interreflection_tol_line ? sc->file : sc->patch_size_line ? sc->file : sc->n_room ? sc->room[0].file : sc->file;
    o.max_line = sc->interreflection_tol_line ? sc->interreflection_tol_line
                 : sc->patch_size_line        ? sc->patch_size_line
                 : sc->n_room                 ? sc->room[0].line
                                              : 0;
    lx__room_mesh *m = NULL;
    void *day = NULL; /* the openings as holes, the daylight the refinement's probes see */
    lx_status st = occ ? lx__daylight_mesh_begin(ctx, sc, p, occ, &o, &day) : LX_OK;
    if (st == LX_OK) st = lx__room_mesh_build(ctx, sc, p, &o, &m);
    lx__daylight_mesh_end(&o, day);
    if (st != LX_OK) return st;
    add_counters(&p->planning, &m->probe);
    if (!p->on[LX_EFFECT_OCCLUSION]) m->n_occ = 0; /* occlusion off: nothing blocks, faces still reflect */
    R->mesh = m;
    flux_balance(sc, p, m, &S, &rho, &flux); /* the exposed area */
    R->flux_lm = flux;
    R->area_m2 = S;
    R->mean_reflectance = rho;
    R->indirect_est_lx = S > 0 ? rho * flux / (S * (1 - rho)) : 0;
    R->n_patches = m->n_patch;
    R->n_elements = m->n_elem;
    R->n_refined = m->n_refined;
    R->n_nodes = m->n_nodes;
    /* what is still unshot comes back as rho^k of itself: U / (1 - rho) more indirect flux
     * against the rho Phi / (1 - rho) of all of it: stop at a quarter of the tolerance (of the
     * tolerance itself: the faces' indirect light is a result too, and sweeps are cheap) */
    R->stop_unshot_lm = 0.25 * R->tolerance * rho * flux;
    R->memory_bytes = lx__room_bytes(m->n_patch, m->n_elem);
    R->memory_limit_bytes = lx__room_memory_limit();
    /* the estimate: the matrix (shooting points x patches of other faces), the gathers at the
     * elements (from the patches) and at the receivers (from the elements), the sweeps, the
     * direct light at every node */
    double nf = 0, *per_face = lx__calloc(m->n_face ? m->n_face : 1, sizeof *per_face);
    if (!per_face) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; i < m->n_patch; i++) per_face[m->patch[i].face] += 1;
    for (size_t i = 0; i < m->n_patch; i++)
        nf += (double)(m->patch[i].shoot * m->patch[i].shoot) * ((double)m->n_patch - per_face[m->patch[i].face]);
    lx__free(per_face);
    nf += (double)m->n_elem * (double)m->n_patch + (double)p->n_points * (double)m->n_elem;
    p->estimate.form_factors += (unsigned long long)nf;
    p->estimate.radiosity_patches += m->n_patch;
    p->estimate.gather_points += p->n_points + m->n_elem;
    double sweeps = rho > 0 && flux > 0 ? ceil(log(R->stop_unshot_lm / (rho * flux)) / log(rho)) : 0;
    if (!(sweeps >= 1)) sweeps = 1;
    p->estimate.radiosity_shots += (unsigned long long)(sweeps * (double)m->n_patch);
    p->estimate.point_evaluations += (unsigned long long)m->n_nodes * sc->n_lum;
    why(p, LX_EFFECT_INTERREFLECTION, 1,
        "%s%.4g m2, rho %.3g, %.4g lm: indirect ~%.4g lx (<= %.0f%% of a total); %zu patches <= %.3g m, %zu elements; "
        "stop at %.3g lm unshot",
        f == LX_FORCE_ON ? "forced on in [effects]; " : "", S, rho, flux, R->indirect_est_lx, 100 * R->share_est, m->n_patch,
        h, m->n_elem, R->stop_unshot_lm);
    return LX_OK;
}

lx_status lx__room_plan(lx_ctx *ctx, const lx_scene *sc, int backend, lx_scene_plan *p)
{
    const lx_effect_force fo = sc->force[LX_EFFECT_OPENCL];
    p->room.backend = fo == LX_FORCE_OFF ? LX_BACKEND_CPU : fo == LX_FORCE_ON ? LX_BACKEND_OPENCL : backend;
    if (!sc->n_room && !sc->n_surf && !sc->n_obst) {
        lx_status st = plan_occlusion(ctx, sc, p, NULL, NULL);
        if (st == LX_OK) st = plan_interreflection(ctx, sc, p, NULL, NULL);
        return st;
    }
    lx__scene_lum *le = lx__calloc(sc->n_lum ? sc->n_lum : 1, sizeof *le);
    lx__room_mesh *occ = NULL;
    if (!le) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t l = 0; l < sc->n_lum; l++) lx__scene_lum_init(&le[l], sc, l, p);
    lx_status st = lx__room_occluders(ctx, sc, &occ); /* and the faces, without patches */
    if (st == LX_OK) st = plan_occlusion(ctx, sc, p, occ, le);
    if (st == LX_OK) st = plan_interreflection(ctx, sc, p, occ, le);
    if (st == LX_OK && !p->room.mesh && p->on[LX_EFFECT_OCCLUSION]) {
        p->room.mesh = occ; /* occlusion alone: the occluders */
        occ = NULL;
    }
    /* the sky does not reach inside a closed room */
    if (st == LX_OK && sc->n_room && p->on[LX_EFFECT_ENVIRONMENT]) {
        int outside = 0;
        for (size_t r = 0; r < sc->n_rec && !outside; r++)
            for (size_t i = 0; i < sc->rec[r].n && !outside; i++) outside = lx__room_cell(sc, sc->rec[r].points + 3 * i) < 0;
        if (!outside) why(p, LX_EFFECT_ENVIRONMENT, 0, "every receiver is inside a closed room: the sky does not reach it");
    }
    lx__room_mesh_free(occ);
    lx__free(le);
    return st;
}
