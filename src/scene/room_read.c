/* room_read.c - the scene file's [room NAME], [surface NAME] and [obstruction NAME] sections and
 * the [scene] keys interreflection_tolerance and patch_size: their keys, the checks when a section
 * ends (required keys, reflectances in [0, 1), degenerate shapes) and the whole-scene checks
 * (luminaires and receivers inside a room and outside every obstruction, rooms that overlap). */
#include "scene/room_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_ROOM_ENTITIES 1000 /* rooms + surfaces + obstructions (every pair is tested per ray) */

static const char *const refl_key[] = {"floor", "ceiling", "wall_xmin", "wall_xmax", "wall_ymin", "wall_ymax", "walls"};

void lx__room_raw_free(scene__room_raw *r)
{
    lx__free(r->name);
    memset(r, 0, sizeof *r);
}

lx_status lx__room_section(lx_ctx *ctx, scene__room_raw *r, int kind, const char *name, const char *file, long line)
{
    lx__room_raw_free(r);
    r->kind = kind;
    r->file = file;
    r->line = line;
    size_t n = strlen(name) + 1;
    r->name = lx__alloc(n);
    if (!r->name) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    memcpy(r->name, name, n);
    return LX_OK;
}

static lx_status vec(lx_ctx *ctx, const char *file, long line, const char *key, const char *value, int n, lx_quantity q,
                     double *dst, int *has)
{
    *has = 1;
    return lx__scene_parse_vec(ctx, file, line, key, value, n, n, q, NULL, dst, NULL);
}

static lx_status refl(lx_ctx *ctx, const char *file, long line, const char *key, const char *value, double *dst,
                      int *has, long *at)
{
    lx_status st = vec(ctx, file, line, key, value, 1, LX_Q_NONE, dst, has);
    if (st != LX_OK) return st;
    *at = line;
    if (!(*dst >= 0 && *dst < 1))
        return lx__error(ctx, LX_EPARSE, file, line,
                         "%s: a reflectance must be at least 0 and below 1 (got %g; 1 would reflect for ever and "
                         "never converge)",
                         key, *dst);
    return LX_OK;
}

lx_status lx__room_key(lx_ctx *ctx, scene__room_raw *r, const char *file, long line, const char *key, const char *value)
{
    switch (r->kind) {
    case SCENE__ROOM:
        if (!strcmp(key, "origin")) return vec(ctx, file, line, key, value, 3, LX_Q_LENGTH, r->origin, &r->has_origin);
        if (!strcmp(key, "size")) return vec(ctx, file, line, key, value, 3, LX_Q_LENGTH, r->size, &r->has_size);
        for (int k = 0; k < 7; k++)
            if (!strcmp(key, refl_key[k])) return refl(ctx, file, line, key, value, &r->refl[k], &r->has_refl[k], &r->refl_line[k]);
        return lx__error(ctx, LX_EPARSE, file, line,
                         "unknown key '%s' in [room] (keys: origin, size, ceiling, walls, floor, wall_xmin, wall_xmax, "
                         "wall_ymin, wall_ymax)",
                         key);
    case SCENE__SURFACE:
        if (!strcmp(key, "corner")) return vec(ctx, file, line, key, value, 3, LX_Q_LENGTH, r->corner, &r->has_corner);
        if (!strcmp(key, "edge1")) return vec(ctx, file, line, key, value, 3, LX_Q_LENGTH, r->edge1, &r->has_edge1);
        if (!strcmp(key, "edge2")) return vec(ctx, file, line, key, value, 3, LX_Q_LENGTH, r->edge2, &r->has_edge2);
        if (!strcmp(key, "reflectance")) return refl(ctx, file, line, key, value, &r->refl[0], &r->has_refl[0], &r->refl_line[0]);
        return lx__error(ctx, LX_EPARSE, file, line,
                         "unknown key '%s' in [surface] (keys: corner, edge1, edge2, reflectance)", key);
    case SCENE__OBSTRUCTION:
        if (!strcmp(key, "min")) return vec(ctx, file, line, key, value, 3, LX_Q_LENGTH, r->min, &r->has_min);
        if (!strcmp(key, "max")) return vec(ctx, file, line, key, value, 3, LX_Q_LENGTH, r->max, &r->has_max);
        if (!strcmp(key, "reflectance")) return refl(ctx, file, line, key, value, &r->refl[0], &r->has_refl[0], &r->refl_line[0]);
        return lx__error(ctx, LX_EPARSE, file, line, "unknown key '%s' in [obstruction] (keys: min, max, reflectance)", key);
    }
    return lx__error(ctx, LX_EPARSE, file, line, "unknown key '%s'", key);
}

static double norm3(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

static lx_status append(lx_ctx *ctx, void **arr, size_t *n, size_t size, const void *item, const char *file, long line)
{
    char *p = lx__realloc(*arr, (*n + 1) * size);
    if (!p) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    memcpy(p + *n * size, item, size);
    *arr = p;
    (*n)++;
    return LX_OK;
}

static lx_status finish_room(lx_ctx *ctx, lx_scene *sc, scene__room_raw *r)
{
    const char *f = r->file;
    long ln = r->line;
    if (!r->has_size) return lx__error(ctx, LX_EPARSE, f, ln, "room '%s': missing 'size' (x, y, z extents)", r->name);
    for (int k = 0; k < 3; k++)
        if (!(r->size[k] > 0))
            return lx__error(ctx, LX_EPARSE, f, ln, "room '%s': every extent of 'size' must be greater than zero",
                             r->name);
    lx_scene_room room;
    memset(&room, 0, sizeof room);
    room.file = f;
    room.line = ln;
    for (int k = 0; k < 3; k++) {
        room.min_m[k] = r->has_origin ? r->origin[k] : 0;
        room.max_m[k] = room.min_m[k] + r->size[k];
    }
    /* defaults: ceiling 0.7, walls 0.5, floor 0.2 (the usual design values); walls sets all four,
     * wall_xmin .. wall_ymax one each */
    double walls = r->has_refl[6] ? r->refl[6] : 0.5;
    room.reflectance[LX_ROOM_FLOOR] = r->has_refl[0] ? r->refl[0] : 0.2;
    room.reflectance[LX_ROOM_CEILING] = r->has_refl[1] ? r->refl[1] : 0.7;
    for (int k = 2; k < 6; k++) room.reflectance[k] = r->has_refl[k] ? r->refl[k] : walls;
    for (size_t i = 0; i < sc->n_room; i++) {
        const lx_scene_room *o = &sc->room[i];
        int overlap = 1;
        for (int k = 0; k < 3; k++) overlap &= room.min_m[k] < o->max_m[k] && o->min_m[k] < room.max_m[k];
        if (overlap)
            return lx__error(ctx, LX_EPARSE, f, ln, "room '%s' overlaps room '%s' (%s:%ld): rooms may touch, not overlap",
                             r->name, o->name, o->file, o->line);
    }
    room.name = r->name;
    lx_status st = append(ctx, (void **)&sc->room, &sc->n_room, sizeof room, &room, f, ln);
    if (st == LX_OK) r->name = NULL;
    return st;
}

static lx_status finish_surface(lx_ctx *ctx, lx_scene *sc, scene__room_raw *r)
{
    const char *f = r->file;
    long ln = r->line;
    if (!r->has_corner || !r->has_edge1 || !r->has_edge2)
        return lx__error(ctx, LX_EPARSE, f, ln, "surface '%s': give 'corner', 'edge1' and 'edge2'", r->name);
    if (!r->has_refl[0]) return lx__error(ctx, LX_EPARSE, f, ln, "surface '%s': missing 'reflectance'", r->name);
    double c[3] = {r->edge1[1] * r->edge2[2] - r->edge1[2] * r->edge2[1], r->edge1[2] * r->edge2[0] - r->edge1[0] * r->edge2[2],
                   r->edge1[0] * r->edge2[1] - r->edge1[1] * r->edge2[0]};
    double a = norm3(c), l1 = norm3(r->edge1), l2 = norm3(r->edge2);
    if (!(l1 > 0) || !(l2 > 0) || !(a > 1e-9 * l1 * l2) || !(a > 1e-12))
        return lx__error(ctx, LX_EPARSE, f, ln,
                         "surface '%s': zero area (edge1 and edge2 must be non-zero and not parallel)", r->name);
    lx_scene_surface s;
    memset(&s, 0, sizeof s);
    s.file = f;
    s.line = ln;
    memcpy(s.corner_m, r->corner, sizeof s.corner_m);
    memcpy(s.edge1_m, r->edge1, sizeof s.edge1_m);
    memcpy(s.edge2_m, r->edge2, sizeof s.edge2_m);
    s.reflectance = r->refl[0];
    s.name = r->name;
    lx_status st = append(ctx, (void **)&sc->surf, &sc->n_surf, sizeof s, &s, f, ln);
    if (st == LX_OK) r->name = NULL;
    return st;
}

static lx_status finish_obstruction(lx_ctx *ctx, lx_scene *sc, scene__room_raw *r)
{
    const char *f = r->file;
    long ln = r->line;
    if (!r->has_min || !r->has_max) return lx__error(ctx, LX_EPARSE, f, ln, "obstruction '%s': give 'min' and 'max'", r->name);
    if (!r->has_refl[0]) return lx__error(ctx, LX_EPARSE, f, ln, "obstruction '%s': missing 'reflectance'", r->name);
    for (int k = 0; k < 3; k++)
        if (!(r->max[k] > r->min[k]))
            return lx__error(ctx, LX_EPARSE, f, ln,
                             "obstruction '%s': max must exceed min along x, y and z (a box with volume)", r->name);
    lx_scene_obstruction o;
    memset(&o, 0, sizeof o);
    o.file = f;
    o.line = ln;
    memcpy(o.min_m, r->min, sizeof o.min_m);
    memcpy(o.max_m, r->max, sizeof o.max_m);
    o.reflectance = r->refl[0];
    o.name = r->name;
    lx_status st = append(ctx, (void **)&sc->obst, &sc->n_obst, sizeof o, &o, f, ln);
    if (st == LX_OK) r->name = NULL;
    return st;
}

lx_status lx__room_section_end(lx_ctx *ctx, lx_scene *sc, scene__room_raw *r)
{
    lx_status st = LX_OK;
    if (r->kind && sc->n_room + sc->n_surf + sc->n_obst >= MAX_ROOM_ENTITIES)
        st = lx__error(ctx, LX_EPARSE, r->file, r->line, "more than %d rooms, surfaces and obstructions",
                       MAX_ROOM_ENTITIES);
    else if (r->kind == SCENE__ROOM) st = finish_room(ctx, sc, r);
    else if (r->kind == SCENE__SURFACE) st = finish_surface(ctx, sc, r);
    else if (r->kind == SCENE__OBSTRUCTION) st = finish_obstruction(ctx, sc, r);
    lx__room_raw_free(r);
    return st;
}

int lx__room_scene_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value,
                       lx_status *st)
{
    if (!strcmp(key, "interreflection_tolerance")) {
        *st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL, &sc->interreflection_tol, NULL);
        if (*st == LX_OK && !(sc->interreflection_tol >= 1e-6 && sc->interreflection_tol <= 0.5))
            *st = lx__error(ctx, LX_EPARSE, file, line, "%s: must be from 1e-6 to 0.5 (relative)", key);
        sc->interreflection_tol_line = line;
        return 1;
    }
    if (!strcmp(key, "patch_refinement")) {
        if (!strcmp(value, "yes")) sc->patch_refinement = 1;
        else if (!strcmp(value, "no")) sc->patch_refinement = 0;
        else *st = lx__error(ctx, LX_EPARSE, file, line, "%s: expected yes or no, got '%s'", key, value);
        return 1;
    }
    if (!strcmp(key, "patch_size")) {
        *st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LENGTH, NULL, &sc->patch_size_m, NULL);
        if (*st == LX_OK && !(sc->patch_size_m > 0))
            *st = lx__error(ctx, LX_EPARSE, file, line, "%s: must be greater than zero", key);
        sc->patch_size_line = line;
        return 1;
    }
    return 0;
}

/* ---- whole-scene checks ---- */

int lx__room_cell(const lx_scene *sc, const double q[3])
{
    for (size_t i = 0; i < sc->n_room; i++) {
        const lx_scene_room *r = &sc->room[i];
        double e = 1e-9 * (1 + fabs(r->max_m[0] - r->min_m[0]) + fabs(r->max_m[1] - r->min_m[1]) + fabs(r->max_m[2] - r->min_m[2]));
        int in = 1;
        for (int k = 0; k < 3; k++) in &= q[k] >= r->min_m[k] - e && q[k] <= r->max_m[k] + e;
        if (in) return (int)i;
    }
    return -1;
}

/* The obstruction q lies strictly inside, or -1. */
static int inside_obstruction(const lx_scene *sc, const double q[3])
{
    for (size_t i = 0; i < sc->n_obst; i++) {
        const lx_scene_obstruction *o = &sc->obst[i];
        if (q[0] > o->min_m[0] && q[0] < o->max_m[0] && q[1] > o->min_m[1] && q[1] < o->max_m[1] && q[2] > o->min_m[2] &&
            q[2] < o->max_m[2])
            return (int)i;
    }
    return -1;
}

/* Where the points (n x 3) lie: every one in the same room (that room), all outside every room
 * (-1), or spread (-2). */
static int points_room(const lx_scene *sc, const double *p, int n)
{
    int c0 = lx__room_cell(sc, p);
    for (int i = 1; i < n; i++)
        if (lx__room_cell(sc, p + 3 * i) != c0) return -2;
    if (c0 == -1) /* outside: also not cutting through a room */
        for (size_t i = 0; i < sc->n_room; i++) {
            const lx_scene_room *r = &sc->room[i];
            int overlap = 1;
            for (int k = 0; k < 3; k++) {
                double lo = p[k], hi = p[k];
                for (int j = 1; j < n; j++) lo = fmin(lo, p[3 * j + k]), hi = fmax(hi, p[3 * j + k]);
                overlap &= lo < r->max_m[k] && r->min_m[k] < hi;
            }
            if (overlap) return -2;
        }
    return c0;
}

static lx_status check_surfaces(lx_ctx *ctx, const lx_scene *sc)
{
    for (size_t i = 0; i < sc->n_surf; i++) {
        const lx_scene_surface *s = &sc->surf[i];
        double p[12];
        for (int k = 0; k < 3; k++) {
            p[k] = s->corner_m[k];
            p[3 + k] = s->corner_m[k] + s->edge1_m[k];
            p[6 + k] = s->corner_m[k] + s->edge1_m[k] + s->edge2_m[k];
            p[9 + k] = s->corner_m[k] + s->edge2_m[k];
        }
        int c = points_room(sc, p, 4);
        if (c == -2)
            return lx__error(ctx, LX_EPARSE, s->file, s->line,
                             "surface '%s' lies partly outside its room (a surface is inside one room or outside them all)",
                             s->name);
        if (c < 0) continue;
        /* not on a face of its room: that would be two coincident reflectors */
        const lx_scene_room *r = &sc->room[c];
        for (int k = 0; k < 3; k++) {
            int lo = 1, hi = 1;
            for (int j = 0; j < 4; j++) {
                lo &= fabs(p[3 * j + k] - r->min_m[k]) < 1e-6;
                hi &= fabs(p[3 * j + k] - r->max_m[k]) < 1e-6;
            }
            if (lo || hi)
                return lx__error(ctx, LX_EPARSE, s->file, s->line,
                                 "surface '%s' lies on a face of room '%s': give that face its reflectance, or move the "
                                 "surface off it (by 1 mm or more)",
                                 s->name, r->name);
        }
    }
    for (size_t i = 0; i < sc->n_obst; i++) {
        const lx_scene_obstruction *o = &sc->obst[i];
        double p[6] = {o->min_m[0], o->min_m[1], o->min_m[2], o->max_m[0], o->max_m[1], o->max_m[2]};
        if (points_room(sc, p, 2) == -2)
            return lx__error(ctx, LX_EPARSE, o->file, o->line,
                             "obstruction '%s' lies partly outside its room (an obstruction is inside one room or "
                             "outside them all)",
                             o->name);
    }
    return LX_OK;
}

lx_status lx__room_scene_check(lx_ctx *ctx, const lx_scene *sc)
{
    if (!sc->n_room && !sc->n_surf && !sc->n_obst) return LX_OK;
    for (size_t l = 0; l < sc->n_lum; l++) {
        const lx_scene_luminaire *L = &sc->lum[l];
        if (sc->n_room && lx__room_cell(sc, L->pos_m) < 0)
            return lx__error(ctx, LX_EPARSE, L->file, L->line, "luminaire '%s' at %g, %g, %g m is outside every room", L->name,
                             L->pos_m[0], L->pos_m[1], L->pos_m[2]);
        int o = inside_obstruction(sc, L->pos_m);
        if (o >= 0)
            return lx__error(ctx, LX_EPARSE, L->file, L->line, "luminaire '%s' is inside obstruction '%s'", L->name,
                             sc->obst[o].name);
    }
    for (size_t r = 0; r < sc->n_rec; r++) {
        const lx_scene_receiver *R = &sc->rec[r];
        for (size_t i = 0; i < R->n; i++) {
            const double *q = R->points + 3 * i;
            if (sc->n_room && lx__room_cell(sc, q) < 0)
                return lx__error(ctx, LX_EPARSE, R->file, R->line, "receiver '%s': point %g, %g, %g m is outside every room",
                                 R->name, q[0], q[1], q[2]);
            int o = inside_obstruction(sc, q);
            if (o >= 0)
                return lx__error(ctx, LX_EPARSE, R->file, R->line, "receiver '%s': point %g, %g, %g m is inside obstruction '%s'",
                                 R->name, q[0], q[1], q[2], sc->obst[o].name);
        }
    }
    return check_surfaces(ctx, sc);
}

void lx__room_scene_free(lx_scene *sc)
{
    for (size_t i = 0; i < sc->n_room; i++) lx__free(sc->room[i].name);
    for (size_t i = 0; i < sc->n_surf; i++) lx__free(sc->surf[i].name);
    for (size_t i = 0; i < sc->n_obst; i++) lx__free(sc->obst[i].name);
    lx__free(sc->room);
    lx__free(sc->surf);
    lx__free(sc->obst);
}
