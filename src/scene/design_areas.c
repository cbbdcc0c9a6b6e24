/* design_areas.c - EN 12464-1 areas: [area NAME] sections (a task area with its immediate
 * surrounding and background bands clipped at the room's walls, a room's plane less a margin, its
 * walls and its ceiling), their calculation grids (p = 0.2 x 5^log10(d), points at the cells'
 * centres) and the receivers that hold their points. */
#include "scene/design_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXV 64 /* vertices of a clipped outline */

/* ---- the grid rule ---- */

static size_t count_cells(double x, lx_grid_rounding r)
{
    double n = r == LX_GRID_ROUND_UP ? ceil(x * (1 - 1e-12)) : floor(x + 0.5);
    return n < 1 ? 1 : (size_t)n;
}

/* p = 0.2 x 5^log10(d), at most 10 m */
static double rule_p(double d) { return fmin(0.2 * pow(5.0, log10(d)), 10.0); }

lx_status lx_en12464_grid_size(lx_ctx *ctx, double a_m, double b_m, lx_grid_rounding rounding, lx_en12464_grid *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_en12464_grid_size: NULL output");
    if (!(a_m > 0 && b_m > 0 && isfinite(a_m) && isfinite(b_m)))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "an area's sides must be positive and finite (got %g x %g m)", a_m, b_m);
    if (rounding != LX_GRID_ROUND_NEAREST && rounding != LX_GRID_ROUND_UP)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown grid rounding %d", (int)rounding);
    memset(out, 0, sizeof *out);
    double lo = fmin(a_m, b_m), hi = fmax(a_m, b_m);
    /* d: the longer side, or the shorter where the longer is at least twice it */
    int on_a = hi >= 2 * lo ? a_m <= b_m : a_m >= b_m;
    double d = on_a ? a_m : b_m, other = on_a ? b_m : a_m;
    out->d_m = d;
    out->p_m = rule_p(d);
    size_t nd = count_cells(d / out->p_m, rounding);
    double cell = d / (double)nd;
    size_t no = count_cells(other / cell, rounding);
    out->n[on_a ? 0 : 1] = nd, out->n[on_a ? 1 : 0] = no;
    out->cell_m[0] = a_m / (double)out->n[0], out->cell_m[1] = b_m / (double)out->n[1];
    return LX_OK;
}

/* ---- polygons in a plane (a, b) ---- */

static double poly_area(const double (*v)[2], size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) {
        const double *p = v[i], *q = v[(i + 1) % n];
        s += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * s;
}

/* Sutherland-Hodgman: the part of polygon in[0..n-1] (any simple polygon) inside the rectangle
 * [a0, a1] x [b0, b1] (convex, so the clip is exact up to zero-width seams along its edges). */
static size_t clip_rect(const double (*in)[2], size_t n, double a0, double a1, double b0, double b1, double (*out)[2])
{
    double buf[2][MAXV][2];
    size_t m = n < MAXV ? n : MAXV;
    memcpy(buf[0], in, m * sizeof *buf[0]);
    int cur = 0;
    for (int e = 0; e < 4 && m; e++) {
        int axis = e / 2;
        double lim = e == 0 ? a0 : e == 1 ? a1 : e == 2 ? b0 : b1, sgn = e % 2 ? -1 : 1;
        size_t k = 0;
        for (size_t i = 0; i < m; i++) {
            const double *p = buf[cur][i], *q = buf[cur][(i + 1) % m];
            double dp = sgn * (p[axis] - lim), dq = sgn * (q[axis] - lim);
            if (dp >= 0 && k < MAXV) buf[!cur][k][0] = p[0], buf[!cur][k][1] = p[1], k++;
            if ((dp >= 0) != (dq >= 0) && k < MAXV) {
                double t = dp / (dp - dq);
                buf[!cur][k][0] = p[0] + t * (q[0] - p[0]);
                buf[!cur][k][1] = p[1] + t * (q[1] - p[1]);
                k++;
            }
        }
        m = k;
        cur = !cur;
    }
    memcpy(out, buf[cur], m * sizeof *out);
    return m < 3 ? 0 : m;
}

/* crossing number: 1 when (x, y) is inside (a point on an edge counts as inside within eps) */
static int in_poly(double x, double y, const double (*v)[2], size_t n)
{
    int in = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const double *p = v[i], *q = v[j];
        double ex = q[0] - p[0], ey = q[1] - p[1], len = hypot(ex, ey);
        double cross = (x - p[0]) * ey - (y - p[1]) * ex, t = ((x - p[0]) * ex + (y - p[1]) * ey) / (len * len);
        if (len > 0 && fabs(cross) <= 1e-9 * len && t >= -1e-12 && t <= 1 + 1e-12) return 1; /* on the edge */
        if ((p[1] > y) != (q[1] > y) && x < p[0] + (y - p[1]) * ex / ey) in = !in;
    }
    return in;
}

/* distance from (x, y) to the polygon's boundary */
static double boundary_dist(double x, double y, const double (*v)[2], size_t n)
{
    double best = INFINITY;
    for (size_t i = 0; i < n; i++) {
        const double *p = v[i], *q = v[(i + 1) % n];
        double ex = q[0] - p[0], ey = q[1] - p[1], l2 = ex * ex + ey * ey;
        double t = l2 > 0 ? ((x - p[0]) * ex + (y - p[1]) * ey) / l2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        best = fmin(best, hypot(x - p[0] - t * ex, y - p[1] - t * ey));
    }
    return best;
}

/* The floor outline of room r in x, y (counter-clockwise). Rooms are boxes today; a room of any
 * shape gives its polygon here, and the bands, margins and checks below follow it. */
static size_t room_outline(const lx_scene *sc, long r, double (*v)[2])
{
    const lx_scene_room *R = &sc->room[r];
    double a0 = R->min_m[0], a1 = R->max_m[0], b0 = R->min_m[1], b1 = R->max_m[1];
    v[0][0] = a0, v[0][1] = b0, v[1][0] = a1, v[1][1] = b0, v[2][0] = a1, v[2][1] = b1, v[3][0] = a0, v[3][1] = b1;
    return 4;
}

/* ---- the [area] section ---- */

static const char *const kind_names[] = {"task", "surrounding", "background", "room",      "walls",
                                         "ceiling", "escape_route", "route_band", "open_area", "high_risk"};

lx_status lx__area_open(lx_ctx *ctx, lx_scene *sc, const char *name, const char *file, long line)
{
    lx__design *in = sc->design->internal;
    for (size_t i = 0; i < in->n_area; i++)
        if (!strcmp(in->area[i].name, name)) return lx__error(ctx, LX_EPARSE, file, line, "area '%s' defined twice", name);
    if (strchr(name, '.')) return lx__error(ctx, LX_EPARSE, file, line, "area '%s': no dots in an area's name", name);
    lx__area_raw *na = lx__realloc_n(in->area, (in->n_area + 1), sizeof *na);
    if (!na) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    in->area = na;
    lx__area_raw *a = &in->area[in->n_area++];
    memset(a, 0, sizeof *a);
    a->file = file;
    a->line = line;
    a->type = -1;
    a->name = lx__strdup(name);
    return a->name ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
}

/* a length, or "no" (0) */
static lx_status width_key(lx_ctx *ctx, const char *file, long line, const char *key, const char *value, double *dst,
                           int *has, long *at)
{
    *has = 1, *at = line;
    if (!strcmp(value, "no")) {
        *dst = 0;
        return LX_OK;
    }
    lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LENGTH, NULL, dst, NULL);
    if (st == LX_OK && !(*dst >= 0)) return lx__error(ctx, LX_EPARSE, file, line, "%s: must not be negative", key);
    return st;
}

lx_status lx__area_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value)
{
    lx__design *in = sc->design->internal;
    lx__area_raw *a = &in->area[in->n_area - 1];
    if (!strcmp(key, "type")) {
        a->type_line = line;
        int k = 0;
        while (k < LX_AREA_KIND_COUNT && strcmp(value, kind_names[k])) k++;
        if (k == LX_AREA_KIND_COUNT || k == LX_AREA_SURROUNDING || k == LX_AREA_BACKGROUND || k == LX_AREA_ROUTE_BAND)
            return lx__error(ctx, LX_EPARSE, file, line,
                             "type: expected task, room, walls, ceiling, escape_route, open_area or high_risk, got '%s'", value);
        a->type = k;
        return LX_OK;
    }
    if (!strcmp(key, "room")) {
        a->room_line = line;
        lx__free(a->room);
        a->room = lx__strdup(value);
        return a->room ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    }
    if (!strcmp(key, "x") || !strcmp(key, "y") || !strcmp(key, "z")) {
        int *n = key[0] == 'x' ? &a->nx : key[0] == 'y' ? &a->ny : &a->nz;
        double *d = key[0] == 'x' ? a->x : key[0] == 'y' ? a->y : a->z;
        return lx__scene_parse_vec(ctx, file, line, key, value, 1, 2, LX_Q_LENGTH, NULL, d, n);
    }
    if (!strcmp(key, "from") || !strcmp(key, "to")) {
        int from = key[0] == 'f';
        *(from ? &a->has_from : &a->has_to) = 1;
        return lx__scene_parse_vec(ctx, file, line, key, value, 3, 3, LX_Q_LENGTH, NULL, from ? a->from : a->to, NULL);
    }
    if (!strcmp(key, "width")) {
        a->has_width = 1;
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LENGTH, NULL, &a->width, NULL);
        if (st == LX_OK && !(a->width > 0)) return lx__error(ctx, LX_EPARSE, file, line, "width: must be greater than zero");
        return st;
    }
    if (!strcmp(key, "surrounding"))
        return width_key(ctx, file, line, key, value, &a->surround, &a->has_surround, &a->surround_line);
    if (!strcmp(key, "background"))
        return width_key(ctx, file, line, key, value, &a->background, &a->has_background, &a->background_line);
    if (!strcmp(key, "margin")) return width_key(ctx, file, line, key, value, &a->margin, &a->has_margin, &a->margin_line);
    if (!strcmp(key, "spacing")) {
        a->has_spacing = 1;
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LENGTH, NULL, &a->spacing, NULL);
        if (st == LX_OK && !(a->spacing > 0)) return lx__error(ctx, LX_EPARSE, file, line, "spacing: must be greater than zero");
        return st;
    }
    if (!strcmp(key, "grid")) {
        if (!strcmp(value, "en12464-1:2021")) a->rounding = LX_GRID_ROUND_NEAREST;
        else if (!strcmp(value, "en12464-1:2011")) a->rounding = LX_GRID_ROUND_UP;
        else
            return lx__error(ctx, LX_EPARSE, file, line,
                             "grid: expected en12464-1:2021 (d / p rounded to the nearest whole number) or en12464-1:2011 "
                             "(rounded up), got '%s'",
                             value);
        return LX_OK;
    }
    lx_status st = LX_OK;
    if (lx__design_rec_key(ctx, &a->cyl, file, line, key, value, &st)) return st;
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [area] (keys: type, room, x, y, z, surrounding, background, margin, spacing, "
                     "grid, cylindrical, semicylindrical, from, to, width)",
                     key);
}

void lx__area_free(lx_scene *sc)
{
    lx_scene_design *d = sc->design;
    lx__design *in = d->internal;
    for (size_t i = 0; in && i < in->n_area; i++) {
        lx__free(in->area[i].name);
        lx__free(in->area[i].room);
    }
    if (in) lx__free(in->area), in->area = NULL, in->n_area = 0;
    for (size_t i = 0; i < d->n_area; i++) {
        lx__free(d->area[i].name);
        lx__free(d->area[i].outline);
        lx__free(d->area[i].inner);
    }
    lx__free(d->area);
    d->area = NULL;
    d->n_area = 0;
}

/* ---- building areas and receivers ---- */

/* points being collected for one receiver */
typedef struct pts {
    double *p;
    size_t n, cap;
} pts;

static int pts_add(pts *P, const double q[3])
{
    if (P->n == P->cap) {
        size_t cap = P->cap ? 2 * P->cap : 256;
        double *np = lx__realloc_n(P->p, 3 * cap, sizeof *np);
        if (!np) return -1;
        P->p = np, P->cap = cap;
    }
    memcpy(P->p + 3 * P->n++, q, 3 * sizeof *q);
    return 0;
}

/* 1 when q lies strictly inside an obstruction (no receiver point there) */
static int in_obstruction(const lx_scene *sc, const double q[3])
{
    for (size_t i = 0; i < sc->n_obst; i++) {
        const lx_scene_obstruction *o = &sc->obst[i];
        int in = 1;
        for (int k = 0; k < 3; k++) in &= q[k] > o->min_m[k] && q[k] < o->max_m[k];
        if (in) return 1;
    }
    return 0;
}

/* 1 when q on a room's wall or ceiling is covered by an obstruction standing against it (q inside
 * the obstruction or on its surface: the face there is hidden, not lit) */
static int covered(const lx_scene *sc, const double q[3])
{
    for (size_t i = 0; i < sc->n_obst; i++) {
        const lx_scene_obstruction *o = &sc->obst[i];
        int in = 1;
        for (int k = 0; k < 3; k++) in &= q[k] >= o->min_m[k] - 1e-9 && q[k] <= o->max_m[k] + 1e-9;
        if (in) return 1;
    }
    return 0;
}

/* Appends a receiver holding points P (GRID when it is the whole na x nb grid, else SET) and its
 * area; the area's outline (nv x 2) and inner edge are copied. */
static lx_status add_area(lx_ctx *ctx, lx_scene *sc, const lx__area_raw *r, lx_scene_area *A, const char *name, pts *P,
                          char axis, size_t na, size_t nb, const double normal[3], int cyl_ok)
{
    for (size_t i = 0; i < sc->n_rec; i++)
        if (!strcmp(sc->rec[i].name, name))
            return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': a receiver named '%s' exists already", r->name, name);
    if (!P->n)
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': no calculation point of '%s' lies in its room", r->name,
                         name);
    lx_scene_receiver rc;
    memset(&rc, 0, sizeof rc);
    rc.name = lx__strdup(name);
    rc.file = r->file;
    rc.line = r->line;
    rc.kind = P->n == na * nb ? LX_SREC_GRID : LX_SREC_SET;
    memcpy(rc.normal, normal, sizeof rc.normal);
    rc.reflectance = NAN;
    rc.axis = axis;
    rc.na = na, rc.nb = nb;
    rc.n = P->n;
    rc.points = P->p;
    lx_scene_receiver *nr = rc.name ? lx__realloc_n(sc->rec, (sc->n_rec + 1), sizeof *nr) : NULL;
    lx_scene_area *ar = nr ? lx__realloc_n(sc->design->area, (sc->design->n_area + 1), sizeof *ar) : NULL;
    if (nr) sc->rec = nr;
    if (ar) sc->design->area = ar;
    A->name = lx__strdup(name);
    if (!nr || !ar || !A->name || lx__design_rec_grow_to(sc, sc->n_rec + 1) != LX_OK) {
        lx__free(rc.name);
        lx__free(A->name);
        A->name = NULL;
        return lx__error(ctx, LX_ENOMEM, r->file, r->line, "out of memory");
    }
    /* the receiver owns the points and the area its outlines from here */
    P->p = NULL, P->n = P->cap = 0;
    A->rec = sc->n_rec;
    sc->rec[sc->n_rec++] = rc;
    sc->design->area[sc->design->n_area++] = *A;
    A->name = NULL, A->outline = A->inner = NULL;
    size_t i = sc->n_rec - 1;
    sc->design->rec_cylinder[i] = cyl_ok ? (unsigned char)r->cyl.cyl : 0;
    double *f = sc->design->rec_facing + 3 * i;
    f[0] = r->cyl.has_facing ? r->cyl.facing[0] : 1, f[1] = r->cyl.has_facing ? r->cyl.facing[1] : 0, f[2] = 0;
    return LX_OK;
}

static lx_status set_outline(lx_ctx *ctx, const lx__area_raw *r, lx_scene_area *A, const double (*v)[2], size_t n,
                             const double (*w)[2], size_t m)
{
    A->outline = lx__alloc_n((n ? n : 1) * 2, sizeof(double));
    A->inner = lx__alloc_n((m ? m : 1) * 2, sizeof(double));
    if (!A->outline || !A->inner) {
        lx__free(A->outline), lx__free(A->inner);
        A->outline = A->inner = NULL;
        return lx__error(ctx, LX_ENOMEM, r->file, r->line, "out of memory");
    }
    memcpy(A->outline, v, n * 2 * sizeof(double));
    if (m) memcpy(A->inner, w, m * 2 * sizeof(double));
    A->n_outline = n, A->n_inner = m;
    A->area_m2 = fabs(poly_area(v, n)) - (m ? fabs(poly_area(w, m)) : 0);
    return LX_OK;
}

static void free_outline(lx_scene_area *A)
{
    lx__free(A->outline), lx__free(A->inner);
    A->outline = A->inner = NULL;
}

/* The room area r's plane lies in: named, or the one containing q; -1 for a scene without rooms.
 * An error when there are rooms and none contains q, or the name is unknown. */
static lx_status find_room(lx_ctx *ctx, const lx_scene *sc, const lx__area_raw *r, const double q[3], long *out)
{
    *out = -1;
    if (r->room) {
        for (size_t i = 0; i < sc->n_room; i++)
            if (!strcmp(sc->room[i].name, r->room)) *out = (long)i;
        if (*out < 0) return lx__error(ctx, LX_EPARSE, r->file, r->room_line, "room: no [room %s]", r->room);
        return LX_OK;
    }
    if (!sc->n_room) return LX_OK;
    for (size_t i = 0; i < sc->n_room; i++) {
        const lx_scene_room *R = &sc->room[i];
        int in = 1;
        for (int k = 0; k < 3; k++) in &= q[k] >= R->min_m[k] && q[k] <= R->max_m[k];
        if (in) *out = (long)i;
    }
    if (*out < 0)
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': outside every room (at %g, %g, %g m)", r->name, q[0],
                         q[1], q[2]);
    return LX_OK;
}

/* A band of width w around the rectangle [x0, x1] x [y0, y1] at height z: four strips (below, above,
 * left, right), each gridded with cells of the band's size c (the rule with d = w, the band's shorter
 * dimension) across and about c along; the centres inside the room's outline (v, nv) are kept. */
static int band_points(const lx_scene *sc, const double inner[4], double w, double c, double z, const double (*v)[2], size_t nv,
                       pts *P)
{
    double o[4] = {inner[0] - w, inner[1] + w, inner[2] - w, inner[3] + w};
    double strips[4][4] = {{o[0], o[1], o[2], inner[2]},
                           {o[0], o[1], inner[3], o[3]},
                           {o[0], inner[0], inner[2], inner[3]},
                           {inner[1], o[1], inner[2], inner[3]}};
    for (int s = 0; s < 4; s++) {
        double a0 = strips[s][0], a1 = strips[s][1], b0 = strips[s][2], b1 = strips[s][3];
        if (!(a1 > a0 && b1 > b0)) continue;
        size_t na = count_cells((a1 - a0) / c, LX_GRID_ROUND_NEAREST), nb = count_cells((b1 - b0) / c, LX_GRID_ROUND_NEAREST);
        for (size_t j = 0; j < nb; j++)
            for (size_t i = 0; i < na; i++) {
                double q[3] = {a0 + (a1 - a0) * (i + 0.5) / na, b0 + (b1 - b0) * (j + 0.5) / nb, z};
                if (nv && !in_poly(q[0], q[1], v, nv)) continue;
                if (in_obstruction(sc, q)) continue;
                if (pts_add(P, q)) return -1;
            }
    }
    return 0;
}

/* The immediate surrounding or the background of task area `task`: the band between the rectangles
 * inner and inner grown by w, clipped at the room's walls. */
static lx_status make_band(lx_ctx *ctx, lx_scene *sc, const lx__area_raw *r, lx_area_kind kind, size_t task, long room,
                           const double inner[4], double w, double z)
{
    double rv[MAXV][2], ov[MAXV][2], iv[MAXV][2];
    size_t nv = room >= 0 ? room_outline(sc, room, rv) : 0, no, ni;
    double outer[4] = {inner[0] - w, inner[1] + w, inner[2] - w, inner[3] + w};
    if (nv) {
        no = clip_rect((const double(*)[2])rv, nv, outer[0], outer[1], outer[2], outer[3], ov);
        ni = clip_rect((const double(*)[2])rv, nv, inner[0], inner[1], inner[2], inner[3], iv);
    } else {
        double q[4][2] = {{outer[0], outer[2]}, {outer[1], outer[2]}, {outer[1], outer[3]}, {outer[0], outer[3]}};
        double p[4][2] = {{inner[0], inner[2]}, {inner[1], inner[2]}, {inner[1], inner[3]}, {inner[0], inner[3]}};
        memcpy(ov, q, sizeof q), memcpy(iv, p, sizeof p);
        no = ni = 4;
    }
    lx_scene_area A;
    memset(&A, 0, sizeof A);
    A.file = r->file, A.line = r->line, A.kind = kind, A.task = (long)task, A.room = room;
    A.u[0] = 1, A.v[1] = 1, A.origin_m[2] = z;
    lx_status st = set_outline(ctx, r, &A, (const double(*)[2])ov, no, (const double(*)[2])iv, ni);
    if (st != LX_OK) return st;
    if (!(A.area_m2 > 1e-9)) { /* the walls leave no band */
        free_outline(&A);
        return LX_OK;
    }
    /* the rule with d = w: a band is at least twice as long as it is wide */
    A.grid.d_m = w;
    A.grid.p_m = rule_p(w);
    A.grid.n[0] = count_cells(w / A.grid.p_m, (lx_grid_rounding)r->rounding);
    double c = r->has_spacing ? r->spacing : w / (double)A.grid.n[0];
    A.grid.cell_m[0] = A.grid.cell_m[1] = c;
    A.box_m[0] = outer[0], A.box_m[1] = outer[1], A.box_m[2] = outer[2], A.box_m[3] = outer[3];
    pts P = {0};
    if (band_points(sc, inner, w, c, z, (const double(*)[2])rv, nv, &P)) {
        lx__free(P.p), free_outline(&A);
        return lx__error(ctx, LX_ENOMEM, r->file, r->line, "out of memory");
    }
    char name[300];
    snprintf(name, sizeof name, "%s.%s", r->name, kind == LX_AREA_SURROUNDING ? "surrounding" : "background");
    static const double up[3] = {0, 0, 1};
    if (!P.n) { /* the band lies behind the walls */
        free_outline(&A);
        return LX_OK;
    }
    st = add_area(ctx, sc, r, &A, name, &P, 'z', 0, 0, up, 1);
    if (st != LX_OK) lx__free(P.p), free_outline(&A);
    return st;
}

/* A rectangle [a0, a1] x [b0, b1] of a plane gridded by the rule (or the spacing): its cell centres,
 * those inside the room's outline at least `margin` from it (horizontal planes) and outside
 * obstructions. */
static lx_status grid_rect(lx_ctx *ctx, const lx_scene *sc, const lx__area_raw *r, lx_scene_area *A, const double (*rv)[2],
                           size_t nv, double margin, pts *P)
{
    double a0 = A->box_m[0], a1 = A->box_m[1], b0 = A->box_m[2], b1 = A->box_m[3];
    lx_status st = lx_en12464_grid_size(ctx, a1 - a0, b1 - b0, (lx_grid_rounding)r->rounding, &A->grid);
    if (st != LX_OK) return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': %s", r->name, lx_ctx_errmsg(ctx));
    if (r->has_spacing)
        for (int k = 0; k < 2; k++) {
            double side = k ? b1 - b0 : a1 - a0;
            A->grid.n[k] = count_cells(side / r->spacing, LX_GRID_ROUND_NEAREST);
            A->grid.cell_m[k] = side / (double)A->grid.n[k];
        }
    for (size_t j = 0; j < A->grid.n[1]; j++)
        for (size_t i = 0; i < A->grid.n[0]; i++) {
            double a = a0 + (i + 0.5) * A->grid.cell_m[0], b = b0 + (j + 0.5) * A->grid.cell_m[1], q[3];
            for (int k = 0; k < 3; k++) q[k] = A->origin_m[k] + a * A->u[k] + b * A->v[k];
            if (nv && (!in_poly(a, b, rv, nv) || boundary_dist(a, b, rv, nv) < margin * (1 - 1e-9))) continue;
            if (A->kind == LX_AREA_WALL || A->kind == LX_AREA_CEILING ? covered(sc, q) : in_obstruction(sc, q)) continue;
            if (pts_add(P, q)) return lx__error(ctx, LX_ENOMEM, r->file, r->line, "out of memory");
        }
    return LX_OK;
}

/* A task area and its bands (an EN 1838 high-risk task area: none). */
static lx_status make_task(lx_ctx *ctx, lx_scene *sc, const lx__area_raw *r)
{
    int high_risk = r->type == LX_AREA_HIGH_RISK;
    if (r->nx != 2 || r->ny != 2 || r->nz != 1)
        return lx__error(ctx, LX_EPARSE, r->file, r->line,
                         "area '%s': a task area takes x and y ranges and its height z (e.g. x = 1 m, 2.6 m; y = 1 m, 1.8 m; "
                         "z = 0.75 m)",
                         r->name);
    if (!(r->x[1] > r->x[0] && r->y[1] > r->y[0]))
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': x and y must go from low to high", r->name);
    double rect[4] = {r->x[0], r->x[1], r->y[0], r->y[1]}, z = r->z[0];
    double c[3] = {0.5 * (rect[0] + rect[1]), 0.5 * (rect[2] + rect[3]), z};
    long room;
    lx_status st = find_room(ctx, sc, r, c, &room);
    if (st != LX_OK) return st;
    double rv[MAXV][2];
    size_t nv = room >= 0 ? room_outline(sc, room, rv) : 0;
    if (room >= 0) {
        const lx_scene_room *R = &sc->room[room];
        double corner[4][2] = {{rect[0], rect[2]}, {rect[1], rect[2]}, {rect[1], rect[3]}, {rect[0], rect[3]}};
        int out = !(z >= R->min_m[2] && z <= R->max_m[2]);
        for (int k = 0; k < 4; k++) out |= !in_poly(corner[k][0], corner[k][1], (const double(*)[2])rv, nv);
        if (out)
            return lx__error(ctx, LX_EPARSE, r->file, r->line,
                             "area '%s': the task area (x %g to %g m, y %g to %g m, z %g m) reaches outside room '%s' (x %g to "
                             "%g m, y %g to %g m, z %g to %g m)",
                             r->name, rect[0], rect[1], rect[2], rect[3], z, R->name, R->min_m[0], R->max_m[0], R->min_m[1],
                             R->max_m[1], R->min_m[2], R->max_m[2]);
    }
    lx_scene_area A;
    memset(&A, 0, sizeof A);
    A.file = r->file, A.line = r->line, A.kind = (lx_area_kind)r->type, A.task = -1, A.room = room;
    A.u[0] = 1, A.v[1] = 1, A.origin_m[2] = z;
    memcpy(A.box_m, rect, sizeof rect);
    double ov[4][2] = {{rect[0], rect[2]}, {rect[1], rect[2]}, {rect[1], rect[3]}, {rect[0], rect[3]}};
    if ((st = set_outline(ctx, r, &A, (const double(*)[2])ov, 4, NULL, 0)) != LX_OK) return st;
    pts P = {0};
    if ((st = grid_rect(ctx, sc, r, &A, NULL, 0, 0, &P)) != LX_OK) goto fail;
    static const double up[3] = {0, 0, 1};
    size_t task = sc->design->n_area;
    if ((st = add_area(ctx, sc, r, &A, r->name, &P, 'z', A.grid.n[0], A.grid.n[1], up, 1)) != LX_OK) goto fail;
    double w1 = high_risk ? 0 : r->has_surround ? r->surround : 0.5, w2 = high_risk ? 0 : r->has_background ? r->background : 3;
    if (w1 > 0 && (st = make_band(ctx, sc, r, LX_AREA_SURROUNDING, task, room, rect, w1, z)) != LX_OK) return st;
    double grown[4] = {rect[0] - w1, rect[1] + w1, rect[2] - w1, rect[3] + w1};
    if (w2 > 0 && (st = make_band(ctx, sc, r, LX_AREA_BACKGROUND, task, room, w1 > 0 ? grown : rect, w2, z)) != LX_OK)
        return st;
    return LX_OK;
fail:
    lx__free(P.p);
    free_outline(&A);
    return st;
}

/* The floor's height under q: its room's floor, or z when given (a scene without rooms needs it). */
static lx_status floor_z(lx_ctx *ctx, const lx_scene *sc, const lx__area_raw *r, long room, double *z)
{
    if (r->nz == 1) *z = r->z[0];
    else if (room >= 0) *z = sc->room[room].min_m[2];
    else return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': give the floor's height z (no room around it)", r->name);
    return LX_OK;
}

/* An EN 1838 escape route: its centre line on the floor from `from` to `to` and its central band of
 * half its width, each on cells of the size the rule gives the width (a route is a band: d is its
 * width); points outside the room or in an obstruction are dropped. */
static lx_status make_route(lx_ctx *ctx, lx_scene *sc, const lx__area_raw *r)
{
    if (!r->has_from || !r->has_to || !r->has_width || r->nx || r->ny)
        return lx__error(ctx, LX_EPARSE, r->file, r->line,
                         "area '%s': an escape route takes from, to (its centre line's ends) and width", r->name);
    double dx = r->to[0] - r->from[0], dy = r->to[1] - r->from[1], L = hypot(dx, dy);
    if (!(L > 0) || fabs(r->to[2] - r->from[2]) > 1e-9)
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': from and to must differ, at one height", r->name);
    long room;
    lx_status st = find_room(ctx, sc, r, r->from, &room);
    if (st != LX_OK) return st;
    double rv[MAXV][2];
    size_t nv = room >= 0 ? room_outline(sc, room, rv) : 0;
    if (nv && !in_poly(r->to[0], r->to[1], (const double(*)[2])rv, nv))
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': the route's end 'to' lies outside room '%s'", r->name,
                         sc->room[room].name);
    double z = r->nz ? r->z[0] : r->from[2];
    double u[3] = {dx / L, dy / L, 0}, v[3] = {-dy / L, dx / L, 0};
    for (int band = 0; band < 2; band++) {
        double w = band ? 0.5 * r->width : r->width;
        lx_scene_area A;
        memset(&A, 0, sizeof A);
        A.file = r->file, A.line = r->line, A.kind = band ? LX_AREA_ROUTE_BAND : LX_AREA_ESCAPE_ROUTE, A.room = room;
        A.task = band ? (long)sc->design->n_area - 1 : -1;
        memcpy(A.u, u, sizeof u), memcpy(A.v, v, sizeof v);
        A.origin_m[0] = r->from[0], A.origin_m[1] = r->from[1], A.origin_m[2] = z;
        A.box_m[0] = 0, A.box_m[1] = L, A.box_m[2] = -0.5 * w, A.box_m[3] = 0.5 * w;
        A.grid.d_m = w, A.grid.p_m = rule_p(w);
        size_t across = count_cells(w / A.grid.p_m, (lx_grid_rounding)r->rounding);
        double c = r->has_spacing ? r->spacing : w / (double)across;
        if (r->has_spacing) across = count_cells(w / c, LX_GRID_ROUND_NEAREST);
        size_t along = count_cells(L / c, LX_GRID_ROUND_NEAREST), rows = band ? across : 1;
        A.grid.n[0] = along, A.grid.n[1] = rows, A.grid.cell_m[0] = L / (double)along, A.grid.cell_m[1] = w / (double)rows;
        double ov[4][2] = {{0, -0.5 * w}, {L, -0.5 * w}, {L, 0.5 * w}, {0, 0.5 * w}};
        if ((st = set_outline(ctx, r, &A, (const double(*)[2])ov, 4, NULL, 0)) != LX_OK) return st;
        pts P = {0};
        for (size_t j = 0; j < rows && st == LX_OK; j++)
            for (size_t i = 0; i < along && st == LX_OK; i++) {
                double a = (i + 0.5) * A.grid.cell_m[0], b = band ? -0.5 * w + (j + 0.5) * A.grid.cell_m[1] : 0, q[3];
                for (int k = 0; k < 3; k++) q[k] = A.origin_m[k] + a * u[k] + b * v[k];
                if ((nv && !in_poly(q[0], q[1], (const double(*)[2])rv, nv)) || in_obstruction(sc, q)) continue;
                if (pts_add(&P, q)) st = lx__error(ctx, LX_ENOMEM, r->file, r->line, "out of memory");
            }
        char name[300];
        snprintf(name, sizeof name, band ? "%s.central_band" : "%s", r->name);
        static const double up[3] = {0, 0, 1};
        if (st == LX_OK) st = add_area(ctx, sc, r, &A, name, &P, 'z', along, rows, up, 0);
        if (st != LX_OK) {
            lx__free(P.p), free_outline(&A);
            return st;
        }
        sc->rec[sc->n_rec - 1].kind = LX_SREC_SET; /* along a line of any direction */
    }
    return LX_OK;
}

/* An EN 1838 open (anti-panic) area: the floor of the x, y rectangle (or of the whole room) less a
 * border (margin, default 0.5 m), on the rule's grid. */
static lx_status make_open(lx_ctx *ctx, lx_scene *sc, const lx__area_raw *r)
{
    if ((r->nx || r->ny) && (r->nx != 2 || r->ny != 2))
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': an open area takes x and y ranges (or none: its room)",
                         r->name);
    double q[3] = {r->nx ? 0.5 * (r->x[0] + r->x[1]) : 0, r->ny ? 0.5 * (r->y[0] + r->y[1]) : 0, r->nz ? r->z[0] : 0};
    long room = -1;
    lx_status st;
    if (r->nx) {
        if ((st = find_room(ctx, sc, r, q, &room)) != LX_OK) return st;
    } else {
        if (!sc->n_room) return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': give x and y (no room)", r->name);
        if (!r->room && sc->n_room > 1) return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': name its room (room = NAME)", r->name);
        room = 0;
        if (r->room && (st = find_room(ctx, sc, r, q, &room)) != LX_OK) return st;
    }
    double z = 0, border = r->has_margin ? r->margin : 0.5, rv[MAXV][2];
    if ((st = floor_z(ctx, sc, r, room, &z)) != LX_OK) return st;
    size_t nv = room >= 0 ? room_outline(sc, room, rv) : 0;
    double box[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    if (r->nx) box[0] = r->x[0], box[1] = r->x[1], box[2] = r->y[0], box[3] = r->y[1];
    else
        for (size_t k = 0; k < nv; k++)
            box[0] = fmin(box[0], rv[k][0]), box[1] = fmax(box[1], rv[k][0]), box[2] = fmin(box[2], rv[k][1]),
            box[3] = fmax(box[3], rv[k][1]);
    lx_scene_area A;
    memset(&A, 0, sizeof A);
    A.file = r->file, A.line = r->line, A.kind = LX_AREA_OPEN, A.task = -1, A.room = room;
    A.u[0] = 1, A.v[1] = 1, A.origin_m[2] = z;
    A.box_m[0] = box[0] + border, A.box_m[1] = box[1] - border, A.box_m[2] = box[2] + border, A.box_m[3] = box[3] - border;
    if (!(A.box_m[1] > A.box_m[0] && A.box_m[3] > A.box_m[2]))
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': the border of %g m leaves no core area", r->name, border);
    double ov[4][2] = {{A.box_m[0], A.box_m[2]}, {A.box_m[1], A.box_m[2]}, {A.box_m[1], A.box_m[3]}, {A.box_m[0], A.box_m[3]}};
    if ((st = set_outline(ctx, r, &A, (const double(*)[2])ov, 4, NULL, 0)) != LX_OK) return st;
    pts P = {0};
    static const double up[3] = {0, 0, 1};
    /* the core of the area: the room's outline (its walls) less the border too */
    if ((st = grid_rect(ctx, sc, r, &A, (const double(*)[2])rv, nv, r->nx ? 0 : border, &P)) == LX_OK)
        st = add_area(ctx, sc, r, &A, r->name, &P, 'z', A.grid.n[0], A.grid.n[1], up, 0);
    if (st != LX_OK) lx__free(P.p), free_outline(&A);
    return st;
}

/* The room's plane at height z less the margin from its walls. */
static lx_status make_room_plane(lx_ctx *ctx, lx_scene *sc, const lx__area_raw *r, long room)
{
    if (r->nx || r->ny || r->nz != 1)
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': a room area takes its height z only (z = 0.8 m)",
                         r->name);
    const lx_scene_room *R = &sc->room[room];
    double z = r->z[0], margin = r->has_margin ? r->margin : 0.5;
    if (!(z >= R->min_m[2] && z <= R->max_m[2]))
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': z %g m is outside room '%s' (%g to %g m)", r->name, z,
                         R->name, R->min_m[2], R->max_m[2]);
    double rv[MAXV][2];
    size_t nv = room_outline(sc, room, rv);
    double box[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (size_t k = 0; k < nv; k++)
        box[0] = fmin(box[0], rv[k][0]), box[1] = fmax(box[1], rv[k][0]), box[2] = fmin(box[2], rv[k][1]),
        box[3] = fmax(box[3], rv[k][1]);
    lx_scene_area A;
    memset(&A, 0, sizeof A);
    A.file = r->file, A.line = r->line, A.kind = LX_AREA_ROOM, A.task = -1, A.room = room;
    A.u[0] = 1, A.v[1] = 1, A.origin_m[2] = z;
    A.box_m[0] = box[0] + margin, A.box_m[1] = box[1] - margin, A.box_m[2] = box[2] + margin, A.box_m[3] = box[3] - margin;
    if (!(A.box_m[1] > A.box_m[0] && A.box_m[3] > A.box_m[2]))
        return lx__error(ctx, LX_EPARSE, r->file, r->margin_line ? r->margin_line : r->line,
                         "area '%s': the margin of %g m leaves nothing of room '%s'", r->name, margin, R->name);
    /* the outline: the room's, less the margin (a box room: its rectangle shrunk) */
    double ov[4][2] = {{A.box_m[0], A.box_m[2]}, {A.box_m[1], A.box_m[2]}, {A.box_m[1], A.box_m[3]}, {A.box_m[0], A.box_m[3]}};
    lx_status st = set_outline(ctx, r, &A, (const double(*)[2])ov, 4, NULL, 0);
    if (st != LX_OK) return st;
    pts P = {0};
    static const double up[3] = {0, 0, 1};
    if ((st = grid_rect(ctx, sc, r, &A, (const double(*)[2])rv, nv, margin, &P)) == LX_OK)
        st = add_area(ctx, sc, r, &A, r->name, &P, 'z', A.grid.n[0], A.grid.n[1], up, 1);
    if (st != LX_OK) lx__free(P.p), free_outline(&A);
    return st;
}

/* The walls (one area each) or the ceiling of a box room, less the margin. */
static lx_status make_faces(lx_ctx *ctx, lx_scene *sc, const lx__area_raw *r, long room)
{
    if (r->nx || r->ny || r->nz)
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': %s areas take no x, y or z (they are the room's)", r->name,
                         kind_names[r->type]);
    const lx_scene_room *R = &sc->room[room];
    double margin = r->has_margin ? r->margin : 0, *lo = (double *)R->min_m, *hi = (double *)R->max_m;
    static const char *const face[] = {"wall_xmin", "wall_xmax", "wall_ymin", "wall_ymax", "ceiling"};
    int f0 = r->type == LX_AREA_CEILING ? 4 : 0, f1 = r->type == LX_AREA_CEILING ? 5 : 4;
    for (int f = f0; f < f1; f++) {
        lx_scene_area A;
        memset(&A, 0, sizeof A);
        A.file = r->file, A.line = r->line, A.kind = f == 4 ? LX_AREA_CEILING : LX_AREA_WALL, A.task = -1, A.room = room;
        double n[3] = {0, 0, 0}, ext[2];
        char axis;
        if (f == 4) { /* the ceiling from below: x, y */
            memcpy(A.origin_m, lo, sizeof A.origin_m);
            A.origin_m[2] = hi[2];
            A.u[0] = 1, A.v[1] = 1, n[2] = -1, axis = 'z';
            ext[0] = hi[0] - lo[0], ext[1] = hi[1] - lo[1];
        } else {
            int k = f / 2; /* the fixed axis: x for xmin, xmax; y for ymin, ymax */
            memcpy(A.origin_m, lo, sizeof A.origin_m);
            if (f % 2) A.origin_m[k] = hi[k];
            n[k] = f % 2 ? -1 : 1;
            A.u[k ? 0 : 1] = 1, A.v[2] = 1, axis = (char)('x' + k);
            ext[0] = hi[k ? 0 : 1] - lo[k ? 0 : 1], ext[1] = hi[2] - lo[2];
        }
        A.box_m[0] = margin, A.box_m[1] = ext[0] - margin, A.box_m[2] = margin, A.box_m[3] = ext[1] - margin;
        if (!(A.box_m[1] > A.box_m[0] && A.box_m[3] > A.box_m[2]))
            return lx__error(ctx, LX_EPARSE, r->file, r->margin_line ? r->margin_line : r->line,
                             "area '%s': the margin of %g m leaves nothing of %s.%s", r->name, margin, R->name, face[f]);
        double ov[4][2] = {{A.box_m[0], A.box_m[2]}, {A.box_m[1], A.box_m[2]}, {A.box_m[1], A.box_m[3]}, {A.box_m[0], A.box_m[3]}};
        lx_status st = set_outline(ctx, r, &A, (const double(*)[2])ov, 4, NULL, 0);
        if (st != LX_OK) return st;
        pts P = {0};
        char name[300];
        snprintf(name, sizeof name, "%s.%s", r->name, face[f]);
        if ((st = grid_rect(ctx, sc, r, &A, NULL, 0, 0, &P)) == LX_OK)
            st = add_area(ctx, sc, r, &A, name, &P, axis, A.grid.n[0], A.grid.n[1], n, 0);
        if (st != LX_OK) {
            lx__free(P.p), free_outline(&A);
            return st;
        }
    }
    return LX_OK;
}

lx_status lx__area_finish(lx_ctx *ctx, lx_scene *sc)
{
    lx__design *in = sc->design->internal;
    for (size_t i = 0; i < in->n_area; i++) {
        const lx__area_raw *r = &in->area[i];
        lx_status st;
        if (r->type < 0)
            return lx__error(ctx, LX_EPARSE, r->file, r->line,
                             "area '%s': missing 'type' (task, room, walls, ceiling, escape_route, open_area or high_risk)",
                             r->name);
        if ((r->has_from || r->has_to || r->has_width) && r->type != LX_AREA_ESCAPE_ROUTE)
            return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': from, to and width belong to escape routes", r->name);
        if (r->type == LX_AREA_ESCAPE_ROUTE) st = make_route(ctx, sc, r);
        else if (r->type == LX_AREA_OPEN) st = make_open(ctx, sc, r);
        else if (r->type == LX_AREA_TASK || r->type == LX_AREA_HIGH_RISK) {
            if (r->has_margin)
                return lx__error(ctx, LX_EPARSE, r->file, r->margin_line, "area '%s': a task area takes no margin", r->name);
            st = make_task(ctx, sc, r);
        } else {
            if (r->has_surround || r->has_background)
                return lx__error(ctx, LX_EPARSE, r->file, r->has_surround ? r->surround_line : r->background_line,
                                 "area '%s': surrounding and background bands belong to task areas", r->name);
            double q[3] = {0, 0, r->nz ? r->z[0] : 0};
            long room = -1;
            if (!sc->n_room)
                return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': a %s area needs a [room]", r->name,
                                 kind_names[r->type]);
            if (r->room || sc->n_room > 1) {
                if (!r->room)
                    return lx__error(ctx, LX_EPARSE, r->file, r->line, "area '%s': name its room (room = NAME)", r->name);
                st = find_room(ctx, sc, r, q, &room);
                if (st != LX_OK) return st;
            } else
                room = 0;
            st = r->type == LX_AREA_ROOM ? make_room_plane(ctx, sc, r, room) : make_faces(ctx, sc, r, room);
        }
        if (st != LX_OK) return st;
    }
    return LX_OK;
}
