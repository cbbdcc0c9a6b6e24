/* room_mesh.c - the faces, patches and occluders of a scene's rooms, surfaces and obstructions:
 * every face cut at its openings and at the footprints of obstructions standing on it, into
 * pieces of at most the base patch size, then split in four where the estimated direct
 * illuminance varies fast (near a luminaire, across a shadow edge), within the memory bound;
 * each patch gets the quadrature order its direct light needs. */
#include "scene/room_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const room_face_name[6] = {"floor", "ceiling", "wall_xmin", "wall_xmax", "wall_ymin", "wall_ymax"};
static const char *const box_face_name[6] = {"bottom", "top", "xmin", "xmax", "ymin", "ymax"};

double lx__room_bytes(size_t n, size_t n_elem)
{
    /* the form-factor matrix in double, the patch records and solve vectors, the elements */
    return (double)n * (double)n * sizeof(double) + (double)n * (sizeof(lx__room_patch) + 8 * sizeof(double)) +
           (double)n_elem * (sizeof(lx__room_patch) + 8 * sizeof(double));
}

double lx__room_memory_limit(void)
{
    const char *e = getenv("LX_ROOM_MEMORY_MB");
    double mb = e && *e ? atof(e) : 1024;
    return (mb > 0 ? mb : 1024) * 1048576.0;
}

size_t lx__room_max_patches(void)
{
    double lim = lx__room_memory_limit();
    size_t n = (size_t)sqrt(lim / sizeof(double));
    while (n > 1 && lx__room_bytes(n, n) > lim) n--;
    return n;
}

void lx__room_mesh_free(lx__room_mesh *m)
{
    if (!m) return;
    lx__free(m->face);
    lx__free(m->patch);
    lx__free(m->elem);
    lx__free(m->occ);
    lx__free(m->open);
    lx__free(m->obst_occ);
    lx__free(m->surf_occ);
    lx__free(m);
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* The occluders: every obstruction (a box), then every surface (a parallelogram). */
static lx_status make_occluders(lx_ctx *ctx, const lx_scene *sc, lx__room_mesh *m)
{
    m->n_occ = sc->n_obst + sc->n_surf;
    m->occ = lx__calloc(m->n_occ ? m->n_occ : 1, sizeof *m->occ);
    m->obst_occ = lx__calloc(sc->n_obst ? sc->n_obst : 1, sizeof *m->obst_occ);
    m->surf_occ = lx__calloc(sc->n_surf ? sc->n_surf : 1, sizeof *m->surf_occ);
    if (!m->occ || !m->obst_occ || !m->surf_occ) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    size_t k = 0;
    for (size_t i = 0; i < sc->n_obst; i++, k++) {
        lx__room_occ_box(&m->occ[k], sc->obst[i].min_m, sc->obst[i].max_m);
        m->obst_occ[i] = (int)k;
    }
    for (size_t i = 0; i < sc->n_surf; i++, k++) {
        lx__room_occ_quad(&m->occ[k], sc->surf[i].corner_m, sc->surf[i].edge1_m, sc->surf[i].edge2_m);
        m->surf_occ[i] = (int)k;
    }
    return LX_OK;
}

/* A face of the box lo..hi: k = lx_room_face order (bottom/floor, top/ceiling, xmin, xmax, ymin,
 * ymax), inward (a room) or outward (an obstruction) normal, u x v = n. */
static void box_face(const double lo[3], const double hi[3], int k, int inward, lx__room_face *f)
{
    double L[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    int axis = k < 2 ? 2 : k < 4 ? 0 : 1, at_hi = k % 2; /* floor/bottom at lo z, ceiling/top at hi z, xmin, ... */
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    /* the normal points away from the face's side of the box when outward */
    double sign = (at_hi ? 1 : -1) * (inward ? -1 : 1);
    memset(f, 0, sizeof *f);
    memcpy(f->o, lo, sizeof f->o);
    f->o[axis] = at_hi ? hi[axis] : lo[axis];
    /* (e_a, e_b) is right-handed about +axis; swap for a normal towards -axis */
    int first = sign > 0 ? a : b, second = sign > 0 ? b : a;
    f->u[first] = L[first];
    f->v[second] = L[second];
    f->n[axis] = sign;
    f->axis = axis;
}

static lx_status add_face(lx_ctx *ctx, lx__room_mesh *m, const lx__room_face *f)
{
    lx__room_face *nf = lx__realloc_n(m->face, m->n_face + 1, sizeof *nf);
    if (!nf) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    m->face = nf;
    m->face[m->n_face++] = *f;
    return LX_OK;
}

/* Every reflecting face: rooms (6 each, inward), surfaces (front and back), obstructions (6
 * each, outward), in that order. */
static lx_status make_faces(lx_ctx *ctx, const lx_scene *sc, lx__room_mesh *m)
{
    lx_status st = LX_OK;
    for (size_t r = 0; r < sc->n_room && !st; r++)
        for (int k = 0; k < 6 && !st; k++) {
            lx__room_face f;
            box_face(sc->room[r].min_m, sc->room[r].max_m, k, 1, &f);
            snprintf(f.name, sizeof f.name, "%s.%s", sc->room[r].name, room_face_name[k]);
            f.rho = sc->room[r].reflectance[k];
            f.cell = (int)r;
            f.occluder = -1;
            st = add_face(ctx, m, &f);
        }
    for (size_t i = 0; i < sc->n_surf && !st; i++) {
        const lx_scene_surface *s = &sc->surf[i];
        double c[3];
        for (int k = 0; k < 3; k++) c[k] = s->corner_m[k] + 0.5 * (s->edge1_m[k] + s->edge2_m[k]);
        for (int side = 0; side < 2 && !st; side++) {
            lx__room_face f;
            memset(&f, 0, sizeof f);
            snprintf(f.name, sizeof f.name, "%s.%s", s->name, side ? "back" : "front");
            memcpy(f.o, s->corner_m, sizeof f.o);
            memcpy(f.u, side ? s->edge2_m : s->edge1_m, sizeof f.u);
            memcpy(f.v, side ? s->edge1_m : s->edge2_m, sizeof f.v);
            f.n[0] = f.u[1] * f.v[2] - f.u[2] * f.v[1];
            f.n[1] = f.u[2] * f.v[0] - f.u[0] * f.v[2];
            f.n[2] = f.u[0] * f.v[1] - f.u[1] * f.v[0];
            double l = sqrt(dot3(f.n, f.n));
            f.axis = -1;
            for (int k = 0; k < 3; k++) {
                f.n[k] /= l;
                if (fabs(f.n[k]) == 1) f.axis = k;
            }
            f.rho = s->reflectance;
            f.cell = lx__room_cell(sc, c);
            f.occluder = m->surf_occ[i];
            st = add_face(ctx, m, &f);
        }
    }
    for (size_t i = 0; i < sc->n_obst && !st; i++) {
        const lx_scene_obstruction *o = &sc->obst[i];
        double c[3];
        for (int k = 0; k < 3; k++) c[k] = 0.5 * (o->min_m[k] + o->max_m[k]);
        for (int k = 0; k < 6 && !st; k++) {
            lx__room_face f;
            box_face(o->min_m, o->max_m, k, 0, &f);
            snprintf(f.name, sizeof f.name, "%s.%s", o->name, box_face_name[k]);
            f.rho = o->reflectance;
            f.cell = lx__room_cell(sc, c);
            f.occluder = m->obst_occ[i];
            st = add_face(ctx, m, &f);
        }
    }
    return st;
}

/* ---- cutting a face into cells ---- */

typedef struct rect2 { double s0, s1, t0, t1; } rect2;

/* The parts of axis-aligned face f that obstructions standing on it cover (their face in f's
 * plane, facing it), as parameter rectangles. */
static int covered(const lx_scene *sc, const lx__room_mesh *m, const lx__room_face *f, rect2 *out, int cap)
{
    if (f->axis < 0) return 0;
    int a = f->axis, n = 0;
    int au = fabs(f->u[0]) > 0 ? 0 : fabs(f->u[1]) > 0 ? 1 : 2, av = fabs(f->v[0]) > 0 ? 0 : fabs(f->v[1]) > 0 ? 1 : 2;
    double plane = f->o[a], sg = f->n[a];
    /* an obstruction's face on a face of its room (a desk's bottom on the floor): all covered */
    if (f->occluder >= 0 && f->cell >= 0) {
        const lx_scene_room *R = &sc->room[f->cell];
        double e = 1e-9 * (1 + fabs(plane));
        if ((sg < 0 && fabs(R->min_m[a] - plane) <= e) || (sg > 0 && fabs(R->max_m[a] - plane) <= e)) {
            out[0] = (rect2){0, 1, 0, 1};
            return 1;
        }
    }
    for (size_t i = 0; i < sc->n_obst && n < cap; i++) {
        if (m->obst_occ[i] == f->occluder) continue;
        const lx_scene_obstruction *o = &sc->obst[i];
        double e = 1e-9 * (1 + fabs(plane));
        if (!(sg > 0 ? fabs(o->min_m[a] - plane) <= e : fabs(o->max_m[a] - plane) <= e)) continue;
        double s0 = (o->min_m[au] - f->o[au]) / f->u[au], s1 = (o->max_m[au] - f->o[au]) / f->u[au];
        double t0 = (o->min_m[av] - f->o[av]) / f->v[av], t1 = (o->max_m[av] - f->o[av]) / f->v[av];
        rect2 r = {fmax(0, fmin(s0, s1)), fmin(1, fmax(s0, s1)), fmax(0, fmin(t0, t1)), fmin(1, fmax(t0, t1))};
        if (r.s1 > r.s0 && r.t1 > r.t0) out[n++] = r;
    }
    return n;
}

/* Cut positions along f's edges where a surface stands on it (an edge of the surface lies in f's
 * plane along one of f's axes): *ns along u, *nt along v. */
static void contact_lines(const lx_scene *sc, const lx__room_face *f, double *cs, int *ns, double *ct, int *nt, int cap)
{
    if (f->axis < 0) return;
    int a = f->axis, au = fabs(f->u[0]) > 0 ? 0 : fabs(f->u[1]) > 0 ? 1 : 2, av = fabs(f->v[0]) > 0 ? 0 : fabs(f->v[1]) > 0 ? 1 : 2;
    double e = 1e-9 * (1 + fabs(f->o[a]));
    for (size_t i = 0; i < sc->n_surf; i++) {
        const lx_scene_surface *S = &sc->surf[i];
        for (int k = 0; k < 4; k++) {
            const double *d = k % 2 ? S->edge2_m : S->edge1_m, *other = k % 2 ? S->edge1_m : S->edge2_m;
            double p0[3], p1[3];
            for (int c = 0; c < 3; c++) {
                p0[c] = S->corner_m[c] + (k >= 2 ? other[c] : 0);
                p1[c] = p0[c] + d[c];
            }
            if (fabs(p0[a] - f->o[a]) > e || fabs(p1[a] - f->o[a]) > e) continue; /* not in the plane */
            /* along u: the line is at a fixed v (t); along v: at a fixed u (s) */
            if (fabs(d[av]) <= e && *nt < cap) ct[(*nt)++] = (p0[av] - f->o[av]) / f->v[av];
            if (fabs(d[au]) <= e && *ns < cap) cs[(*ns)++] = (p0[au] - f->o[au]) / f->u[au];
        }
    }
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The cut positions along one parameter: 0, 1, the given ones inside, then each interval split
 * into pieces of at most h metres (len: the edge length). Returns the count (<= cap). */
static int cuts(const double *given, int ng, double len, double h, double *out, int cap)
{
    double b[130];
    int nb = 0;
    b[nb++] = 0;
    b[nb++] = 1;
    for (int i = 0; i < ng && nb < 128; i++)
        if (given[i] > 0 && given[i] < 1) b[nb++] = given[i];
    qsort(b, (size_t)nb, sizeof *b, cmp_d);
    int n = 0;
    for (int i = 0; i < nb; i++) {
        if (n && b[i] - out[n - 1] < 1e-9) continue;
        if (n) {
            double lo = out[n - 1], w = (b[i] - lo) * len;
            int k = (int)ceil(w / h - 1e-9);
            if (k < 1) k = 1;
            for (int j = 1; j < k && n < cap - 1; j++) out[n++] = lo + (b[i] - lo) * j / k;
        }
        if (n < cap) out[n++] = b[i];
    }
    return n;
}

static int in_rects(const rect2 *r, int n, double s, double t)
{
    for (int i = 0; i < n; i++)
        if (s > r[i].s0 && s < r[i].s1 && t > r[i].t0 && t < r[i].t1) return 1;
    return 0;
}

/* ---- patches and their refinement ---- */

typedef struct builder {
    lx_ctx *ctx;
    const lx_scene *sc;
    lx__room_mesh *m;
    const lx__room_mesh_opts *o;
    lx__scene_lum *le;      /* the luminaires, prepared */
    int *lum_cell;
    size_t cap, cap_e;
    size_t max_elem;        /* the refinement stops here */
    lx__scene_vis vis;
    lx_counters probe;      /* the probes' work (not the scene's) */
    double kappa;           /* patches larger than kappa x their distance to a receiver are split */
} builder;

static void set_patch(lx__room_patch *p, const lx__room_face *f, int fi, double s0, double s1, double t0, double t1)
{
    memset(p, 0, sizeof *p);
    for (int k = 0; k < 3; k++) {
        p->o[k] = f->o[k] + s0 * f->u[k] + t0 * f->v[k];
        p->u[k] = (s1 - s0) * f->u[k];
        p->v[k] = (t1 - t0) * f->v[k];
        p->c[k] = p->o[k] + 0.5 * (p->u[k] + p->v[k]);
        p->n[k] = f->n[k];
    }
    for (int k = 0; k < 3; k++) {
        double a = p->o[k], b = a + p->u[k], c = a + p->v[k], d = a + p->u[k] + p->v[k];
        p->lo[k] = fmin(fmin(a, b), fmin(c, d));
        p->hi[k] = fmax(fmax(a, b), fmax(c, d));
    }
    double cr[3] = {p->u[1] * p->v[2] - p->u[2] * p->v[1], p->u[2] * p->v[0] - p->u[0] * p->v[2],
                    p->u[0] * p->v[1] - p->u[1] * p->v[0]};
    p->area_m2 = sqrt(dot3(cr, cr));
    p->size_m = fmax(sqrt(dot3(p->u, p->u)), sqrt(dot3(p->v, p->v)));
    double d1[3] = {p->u[0] + p->v[0], p->u[1] + p->v[1], p->u[2] + p->v[2]};
    double d2[3] = {p->u[0] - p->v[0], p->u[1] - p->v[1], p->u[2] - p->v[2]};
    p->rad = 0.5 * fmax(sqrt(dot3(d1, d1)), sqrt(dot3(d2, d2)));
    p->rho = f->rho;
    p->face = fi;
    p->cell = f->cell;
    p->occluder = f->occluder;
    p->order = 1;
    p->shoot = 1;
}

/* The estimated direct illuminance at a point of patch p (probes: point law with visibility). */
static double probe_E(builder *b, const lx__room_patch *p, const double x[3])
{
    double E = 0;
    lx__scene_vis vis = b->vis;
    vis.skip = p->occluder;
    for (size_t l = 0; l < b->sc->n_lum; l++) {
        if (b->lum_cell[l] != p->cell) continue;
        E += lx__scene_lum_E(&b->probe, &b->le[l], x, p->n, 0, 1e-3, vis.n_occ ? &vis : NULL);
    }
    if (b->o->probe_extra) E += b->o->probe_extra(b->o->probe_arg, p, x);
    return E;
}

/* The distance from point q to patch p (its closest point: the parameters clamped to [0, 1]). */
static double point_patch_dist(const lx__room_patch *p, const double q[3])
{
    double w[3] = {q[0] - p->o[0], q[1] - p->o[1], q[2] - p->o[2]};
    double uu = dot3(p->u, p->u), vv = dot3(p->v, p->v), uv = dot3(p->u, p->v), det = uu * vv - uv * uv;
    double wu = dot3(w, p->u), wv = dot3(w, p->v);
    double s = (wu * vv - wv * uv) / det, t = (wv * uu - wu * uv) / det;
    s = fmin(1, fmax(0, s)), t = fmin(1, fmax(0, t));
    double d[3];
    for (int c = 0; c < 3; c++) d[c] = q[c] - (p->o[c] + s * p->u[c] + t * p->v[c]);
    return sqrt(dot3(d, d));
}

/* The distance from patch p to the nearest receiver point in front of it: for a grid, the grid
 * points nearest to the projections of the patch's centre and corners (INFINITY: none). */
static double receiver_dist(const builder *b, const lx__room_patch *p)
{
    double best = INFINITY;
    for (size_t r = 0; r < b->sc->n_rec; r++) {
        const lx_scene_receiver *rc = &b->sc->rec[r];
        if (lx__room_cell(b->sc, rc->points) != p->cell) continue;
        size_t na = rc->kind == LX_SREC_GRID ? rc->na : 1, nb = rc->kind == LX_SREC_GRID ? rc->nb : 1;
        int fixed = rc->kind == LX_SREC_GRID ? rc->axis - 'x' : 0, A = fixed == 0 ? 1 : 0, B = fixed == 2 ? 1 : 2;
        const double *q0 = rc->points;
        double da = na > 1 ? rc->points[3 + A] - q0[A] : 0, db = nb > 1 ? rc->points[3 * na + B] - q0[B] : 0;
        for (int k = 0; k < 5; k++) {
            double s = k == 4 ? 0.5 : (k & 1), t = k == 4 ? 0.5 : (k >> 1), x[3];
            for (int c = 0; c < 3; c++) x[c] = p->o[c] + s * p->u[c] + t * p->v[c];
            double ia = da > 0 ? floor((x[A] - q0[A]) / da + 0.5) : 0, ib = db > 0 ? floor((x[B] - q0[B]) / db + 0.5) : 0;
            ia = fmin(fmax(ia, 0), (double)(na - 1));
            ib = fmin(fmax(ib, 0), (double)(nb - 1));
            const double *q = rc->points + 3 * ((size_t)ib * na + (size_t)ia);
            double w[3] = {q[0] - p->c[0], q[1] - p->c[1], q[2] - p->c[2]};
            if (!(dot3(w, p->n) > 0)) continue; /* behind the patch: it does not see it */
            best = fmin(best, point_patch_dist(p, q));
        }
    }
    return best;
}

/* 1 when patch p should be split: its direct illuminance, probed at the corners and the centre,
 * varies by more than `var` of its level (plus the indirect level, which smooths it), or a
 * luminaire in front of it is closer than its size. */
static int wants_split(builder *b, const lx__room_patch *p, double var, int receivers)
{
    double E[5], mn = INFINITY, mx = -INFINITY, sum = 0;
    for (int k = 0; k < 5; k++) {
        double s = k == 4 ? 0.5 : (k & 1), t = k == 4 ? 0.5 : (k >> 1), x[3];
        for (int c = 0; c < 3; c++) x[c] = p->o[c] + s * p->u[c] + t * p->v[c];
        E[k] = probe_E(b, p, x);
        mn = fmin(mn, E[k]), mx = fmax(mx, E[k]), sum += E[k];
    }
    if (mx - mn > var * (sum / 5 + b->o->indirect_est_lx)) return 1;
    /* a receiver close to it: the gather's error grows as (size / distance)^2 */
    if (receivers && p->size_m > b->kappa * receiver_dist(b, p)) return 1;
    for (size_t l = 0; l < b->sc->n_lum; l++) {
        const lx_scene_luminaire *L = &b->sc->lum[l];
        if (b->lum_cell[l] != p->cell) continue;
        double w[3] = {L->pos_m[0] - p->c[0], L->pos_m[1] - p->c[1], L->pos_m[2] - p->c[2]};
        if (dot3(w, p->n) > 1e-9 && sqrt(dot3(w, w)) < p->size_m) return 1;
    }
    return 0;
}

static lx_status push(builder *b, lx__room_patch **arr, size_t *n, size_t *cap, const lx__room_patch *p)
{
    if (*n == *cap) {
        size_t nc = *cap ? 2 * *cap : 1024;
        lx__room_patch *np = lx__realloc_n(*arr, nc, sizeof *np);
        if (!np) return lx__error(b->ctx, LX_ENOMEM, NULL, 0, "out of memory for the patches");
        *arr = np;
        *cap = nc;
    }
    (*arr)[(*n)++] = *p;
    return LX_OK;
}

static lx_status push_patch(builder *b, const lx__room_patch *p) { return push(b, &b->m->patch, &b->m->n_patch, &b->cap, p); }
static lx_status push_elem(builder *b, const lx__room_patch *p) { return push(b, &b->m->elem, &b->m->n_elem, &b->cap_e, p); }

/* The base cells of every face (count only: *needed, when count_only). */
static lx_status base_patches(builder *b, int count_only, size_t *needed)
{
    const lx__room_mesh_opts *o = b->o;
    lx__room_mesh *m = b->m;
    *needed = 0;
    for (size_t fi = 0; fi < m->n_face; fi++) {
        const lx__room_face *f = &m->face[fi];
        rect2 cov[64], holes[16];
        int nc = covered(b->sc, m, f, cov, 48), nh = 0;
        for (size_t k = 0; k < o->n_open && nh < 16; k++)
            if (o->open[k].face == (int)fi) holes[nh++] = (rect2){o->open[k].s0, o->open[k].s1, o->open[k].t0, o->open[k].t1};
        double gs[160], gt[160], cs[4100], ct[4100];
        int ng = 0, ngs, ngt;
        for (int k = 0; k < nc; k++) gs[ng] = cov[k].s0, gt[ng++] = cov[k].t0, gs[ng] = cov[k].s1, gt[ng++] = cov[k].t1;
        for (int k = 0; k < nh; k++) gs[ng] = holes[k].s0, gt[ng++] = holes[k].t0, gs[ng] = holes[k].s1, gt[ng++] = holes[k].t1;
        ngs = ngt = ng;
        contact_lines(b->sc, f, gs, &ngs, gt, &ngt, 160);
        double lu = sqrt(dot3(f->u, f->u)), lv = sqrt(dot3(f->v, f->v));
        if (lu / o->h_m > 4000 || lv / o->h_m > 4000)
            return lx__error(b->ctx, LX_EPARSE, o->max_file, o->max_line,
                             "%s: more than 4000 patches of %.3g m along an edge", f->name, o->h_m);
        int ns = cuts(gs, ngs, lu, o->h_m, cs, 4100), nt = cuts(gt, ngt, lv, o->h_m, ct, 4100);
        for (int j = 0; j + 1 < nt; j++)
            for (int i = 0; i + 1 < ns; i++) {
                double sm = 0.5 * (cs[i] + cs[i + 1]), tm = 0.5 * (ct[j] + ct[j + 1]);
                if (in_rects(cov, nc, sm, tm) || in_rects(holes, nh, sm, tm)) continue;
                (*needed)++;
                if (count_only) continue;
                lx__room_patch p;
                set_patch(&p, f, (int)fi, cs[i], cs[i + 1], ct[j], ct[j + 1]);
                lx_status st = push_patch(b, &p);
                if (st != LX_OK) return st;
            }
    }
    return LX_OK;
}

/* Splits patch or element i of *arr (n of them) in four: its first quarter replaces it, the
 * others are appended. */
static lx_status split(builder *b, int elements, size_t i)
{
    lx__room_patch p = elements ? b->m->elem[i] : b->m->patch[i], q[4];
    const lx__room_face *f = &b->m->face[p.face];
    double lu = dot3(f->u, f->u), lv = dot3(f->v, f->v);
    /* parameters of the piece in its face */
    double w[3] = {p.o[0] - f->o[0], p.o[1] - f->o[1], p.o[2] - f->o[2]};
    double uv = dot3(f->u, f->v), det = lu * lv - uv * uv;
    double wu = dot3(w, f->u), wv = dot3(w, f->v);
    double s0 = (wu * lv - wv * uv) / det, t0 = (wv * lu - wu * uv) / det;
    double ds = sqrt(dot3(p.u, p.u) / lu), dt = sqrt(dot3(p.v, p.v) / lv);
    for (int k = 0; k < 4; k++) {
        double a = s0 + ds * 0.5 * (k & 1), c = t0 + dt * 0.5 * (k >> 1);
        set_patch(&q[k], f, p.face, a, a + 0.5 * ds, c, c + 0.5 * dt);
        q[k].parent = p.parent;
    }
    if (elements) b->m->elem[i] = q[0];
    else b->m->patch[i] = q[0];
    for (int k = 1; k < 4; k++) {
        lx_status st = elements ? push_elem(b, &q[k]) : push_patch(b, &q[k]);
        if (st != LX_OK) return st;
    }
    b->m->n_refined++;
    return LX_OK;
}

/* Refinement passes: every piece whose probed direct light varies too much (or, for elements,
 * that is large for its distance to a receiver) is split, level by level (each level looks at
 * the pieces the last one made), while the bound allows. Patches (the solve) are split for the
 * direct light only, elements for both. */
static lx_status refine(builder *b, int elements, int depth_max, size_t bound)
{
    const double var = 0.5; /* a piece whose direct light varies by half its level (and the indirect's) */
    size_t *count = elements ? &b->m->n_elem : &b->m->n_patch;
    size_t n = *count, *cand = lx__alloc_n(n ? n : 1, sizeof *cand), nc = n;
    if (!cand) return lx__error(b->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t i = 0; i < n; i++) cand[i] = i;
    lx_status st = LX_OK;
    for (int depth = 0; depth < depth_max && nc && st == LX_OK; depth++) {
        size_t todo = 0;
        for (size_t k = 0; k < nc; k++)
            if (wants_split(b, elements ? &b->m->elem[cand[k]] : &b->m->patch[cand[k]], var, elements)) cand[todo++] = cand[k];
        if (!todo || *count + 3 * todo > bound) break; /* the bound: stop refining */
        size_t *next = lx__alloc_n(4 * todo, sizeof *next), nn = 0;
        if (!next) {
            st = lx__error(b->ctx, LX_ENOMEM, NULL, 0, "out of memory");
            break;
        }
        for (size_t k = 0; k < todo && st == LX_OK; k++) {
            next[nn++] = cand[k];
            for (int q = 0; q < 3; q++) next[nn++] = *count + (size_t)q;
            st = split(b, elements, cand[k]);
        }
        lx__free(cand);
        cand = next;
        nc = nn;
    }
    lx__free(cand);
    return st;
}

/* Quadrature orders: Gauss-Legendre m x m nodes for an element's direct light, m the smallest
 * whose estimated error 0.5 (r / 2)^(2m) is within the tolerance, r = element size / distance to
 * the nearest luminaire in front of it; patches on their face's boundary shoot from 2 x 2 points. */
static void orders(builder *b)
{
    lx__room_mesh *m = b->m;
    double tq = b->o->quad_tol > 0 ? b->o->quad_tol : 0.25 * b->o->tol;
    m->n_nodes = 0;
    for (size_t i = 0; i < m->n_elem; i++) {
        lx__room_patch *p = &m->elem[i];
        double dmin = INFINITY;
        for (size_t l = 0; l < b->sc->n_lum; l++) {
            const lx_scene_luminaire *L = &b->sc->lum[l];
            if (b->lum_cell[l] != p->cell) continue;
            double w[3] = {L->pos_m[0] - p->c[0], L->pos_m[1] - p->c[1], L->pos_m[2] - p->c[2]};
            if (!(dot3(w, p->n) > 0)) continue;
            dmin = fmin(dmin, fmax(sqrt(dot3(w, w)) - 0.5 * lx__scene_lum_size(L), 0.5 * p->size_m));
        }
        int mq = 1;
        if (isfinite(dmin)) {
            double r = 0.5 * p->size_m / dmin;
            while (mq < 8 && 0.5 * pow(r, 2 * mq) > tq) mq++;
        }
        p->order = mq;
        m->n_nodes += (size_t)(mq * mq);
    }
    for (size_t i = 0; i < m->n_patch; i++) {
        lx__room_patch *p = &m->patch[i];
        const lx__room_face *f = &m->face[p->face];
        double w[3] = {p->c[0] - f->o[0], p->c[1] - f->o[1], p->c[2] - f->o[2]};
        double lu = dot3(f->u, f->u), lv = dot3(f->v, f->v);
        double s = dot3(w, f->u) / lu, t = dot3(w, f->v) / lv; /* faces are rectangles or near enough */
        double hs = 0.5 * sqrt(dot3(p->u, p->u) / lu), ht = 0.5 * sqrt(dot3(p->v, p->v) / lv);
        int edge = s - hs < 1e-9 || s + hs > 1 - 1e-9 || t - ht < 1e-9 || t + ht > 1 - 1e-9;
        p->shoot = edge ? 2 : 1;
    }
}

lx_status lx__room_mesh_build(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lx__room_mesh_opts *o,
                              lx__room_mesh **out)
{
    *out = NULL;
    lx__room_mesh *m = lx__calloc(1, sizeof *m);
    builder b;
    memset(&b, 0, sizeof b);
    b.ctx = ctx;
    b.sc = sc;
    b.m = m;
    b.o = o;
    /* the gather's error near a patch, about 5e-3 (size / distance)^2 relative (measured on
     * samples/scenes/office_room.scene, README "Rooms") */
    b.kappa = fmin(2, fmax(0.1, sqrt(o->tol / 5e-3)));
    if (!m) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    m->sc = sc;
    m->h_m = o->h_m;
    m->tol = o->tol;
    m->quad_tol = o->quad_tol > 0 ? o->quad_tol : 0.25 * o->tol;
    lx_status st = make_occluders(ctx, sc, m);
    if (st == LX_OK) st = make_faces(ctx, sc, m);
    b.le = lx__calloc(sc->n_lum ? sc->n_lum : 1, sizeof *b.le);
    b.lum_cell = lx__calloc(sc->n_lum ? sc->n_lum : 1, sizeof *b.lum_cell);
    if (st == LX_OK && (!b.le || !b.lum_cell)) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (st == LX_OK && o->n_open) {
        m->open = lx__alloc_n(o->n_open, sizeof *m->open);
        if (!m->open) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        else memcpy(m->open, o->open, o->n_open * sizeof *m->open), m->n_open = o->n_open;
    }
    for (size_t l = 0; st == LX_OK && l < sc->n_lum; l++) {
        lx__scene_lum_init(&b.le[l], sc, l, plan);
        b.lum_cell[l] = lx__room_cell(sc, sc->lum[l].pos_m);
    }
    b.vis.occ = m->occ;
    b.vis.n_occ = (int)m->n_occ;
    b.vis.skip = -1;
    size_t needed = 0;
    if (st == LX_OK) st = base_patches(&b, 1, &needed);
    if (st == LX_OK && needed > o->max_patches)
        st = lx__error(ctx, LX_EPARSE, o->max_file, o->max_line,
                       "interreflection needs %zu patches of %.3g m: the memory bound of %.0f MiB allows %zu (the "
                       "form-factor matrix takes 8 bytes per pair of patches); raise interreflection_tolerance or "
                       "patch_size, or set LX_ROOM_MEMORY_MB",
                       needed, o->h_m, lx__room_memory_limit() / 1048576.0, o->max_patches);
    if (st == LX_OK) st = base_patches(&b, 0, &needed);
    /* the patches split where the direct light varies fast (two levels), then the elements:
     * every patch, split further there and near receivers (two more levels) */
    if (st == LX_OK) st = refine(&b, 0, o->max_depth < 2 ? o->max_depth : 2, o->max_patches);
    b.max_elem = o->max_elem ? o->max_elem : 400000;
    for (size_t i = 0; st == LX_OK && i < m->n_patch; i++) {
        m->patch[i].parent = i;
        st = push_elem(&b, &m->patch[i]);
    }
    if (st == LX_OK) st = refine(&b, 1, o->max_depth, b.max_elem);
    if (st == LX_OK) {
        orders(&b);
        for (size_t i = 0; i < m->n_patch; i++) m->face[m->patch[i].face].area_m2 += m->patch[i].area_m2;
    }
    lx__free(b.le);
    lx__free(b.lum_cell);
    m->probe = b.probe;
    if (st != LX_OK) {
        lx__room_mesh_free(m);
        return st;
    }
    *out = m;
    return LX_OK;
}

lx_status lx__room_occluders(lx_ctx *ctx, const lx_scene *sc, lx__room_mesh **out)
{
    lx__room_mesh *m = lx__calloc(1, sizeof *m);
    if (!m) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    m->sc = sc;
    lx_status st = make_occluders(ctx, sc, m);
    if (st == LX_OK) st = make_faces(ctx, sc, m);
    if (st != LX_OK) {
        lx__room_mesh_free(m);
        return st;
    }
    *out = m;
    return LX_OK;
}
