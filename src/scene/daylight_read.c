/* daylight_read.c - the scene file's [opening NAME] sections: their keys (corner, edge1, edge2,
 * transmittance, glazing) and the whole-scene checks that place each on a wall or the ceiling of
 * a room (in its plane, inside it, along its edges, overlapping no other opening, leading outside). */
#include "scene/daylight_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_OPENINGS 1000

static const char *const face_name[6] = {"floor", "ceiling", "wall_xmin", "wall_xmax", "wall_ymin", "wall_ymax"};

lx_status lx__scene_open_section(lx_ctx *ctx, lx_scene *sc, const char *name, const char *file, long line)
{
    for (size_t i = 0; i < sc->n_open; i++)
        if (!strcmp(sc->open[i].name, name))
            return lx__error(ctx, LX_EPARSE, file, line, "opening '%s' defined twice (first at %s:%ld)", name, sc->open[i].file,
                             sc->open[i].line);
    if (sc->n_open >= MAX_OPENINGS) return lx__error(ctx, LX_EPARSE, file, line, "more than %d openings", MAX_OPENINGS);
    lx_scene_opening *no = lx__realloc_n(sc->open, sc->n_open + 1, sizeof *no);
    if (!no) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    sc->open = no;
    lx_scene_opening *o = &sc->open[sc->n_open];
    memset(o, 0, sizeof *o);
    size_t l = strlen(name) + 1;
    if (!(o->name = lx__alloc(l))) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    memcpy(o->name, name, l);
    o->file = file;
    o->line = line;
    o->corner_m[0] = o->edge1_m[0] = o->edge2_m[0] = NAN; /* required */
    o->transmittance = NAN;                              /* default: 1, or P(1) for clear glass */
    sc->n_open++;
    return LX_OK;
}

lx_status lx__scene_open_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value)
{
    lx_scene_opening *o = &sc->open[sc->n_open - 1];
    double *v = !strcmp(key, "corner") ? o->corner_m : !strcmp(key, "edge1") ? o->edge1_m : !strcmp(key, "edge2") ? o->edge2_m : NULL;
    if (v) return lx__scene_parse_vec(ctx, file, line, key, value, 3, 3, LX_Q_LENGTH, NULL, v, NULL);
    if (!strcmp(key, "transmittance")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL, &o->transmittance, NULL);
        if (st == LX_OK && !(o->transmittance >= 0 && o->transmittance <= 1))
            return lx__error(ctx, LX_EPARSE, file, line,
                             "transmittance: the glazing's normal-incidence transmittance must be from 0 to 1 (got %g)",
                             o->transmittance);
        return st;
    }
    if (!strcmp(key, "glazing")) {
        if (!strcmp(value, "none")) o->glazing = LX_GLAZING_NONE;
        else if (!strcmp(value, "clear")) o->glazing = LX_GLAZING_CLEAR;
        else
            return lx__error(ctx, LX_EPARSE, file, line,
                             "glazing: expected none (a hole, or a transmittance independent of the angle) or clear "
                             "(clear glass: CIE 171 6 mm angular dependence), got '%s'",
                             value);
        return LX_OK;
    }
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [opening] (keys: corner, edge1, edge2, transmittance, glazing)", key);
}

/* The face of room r that holds the rectangle p[4]: 0..5, -1 when no face's plane holds all four
 * corners; *inside: 1 when the rectangle lies within that face. */
static int face_of(const lx_scene_room *R, const double p[4][3], int *inside)
{
    double e = 1e-6 * (1 + fabs(R->max_m[0] - R->min_m[0]) + fabs(R->max_m[1] - R->min_m[1]) + fabs(R->max_m[2] - R->min_m[2]));
    for (int k = 0; k < 6; k++) {
        int axis = k < 2 ? 2 : k < 4 ? 0 : 1;
        double plane = k % 2 ? R->max_m[axis] : R->min_m[axis];
        int on = 1;
        for (int c = 0; c < 4; c++) on &= fabs(p[c][axis] - plane) <= e;
        if (!on) continue;
        *inside = 1;
        for (int c = 0; c < 4; c++)
            for (int a = 0; a < 3; a++)
                if (a != axis) *inside &= p[c][a] >= R->min_m[a] - e && p[c][a] <= R->max_m[a] + e;
        return k;
    }
    return -1;
}

static void corners(const lx_scene_opening *o, double p[4][3])
{
    for (int a = 0; a < 3; a++) {
        p[0][a] = o->corner_m[a];
        p[1][a] = o->corner_m[a] + o->edge1_m[a];
        p[2][a] = o->corner_m[a] + o->edge1_m[a] + o->edge2_m[a];
        p[3][a] = o->corner_m[a] + o->edge2_m[a];
    }
}

/* The rectangle's extent along the room axes (min, max per axis). */
static void extent(const double p[4][3], double lo[3], double hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = hi[a] = p[0][a];
        for (int c = 1; c < 4; c++) lo[a] = fmin(lo[a], p[c][a]), hi[a] = fmax(hi[a], p[c][a]);
    }
}

static lx_status check_one(lx_ctx *ctx, lx_scene *sc, size_t i)
{
    lx_scene_opening *o = &sc->open[i];
    const char *f = o->file;
    long ln = o->line;
    if (isnan(o->corner_m[0]) || isnan(o->edge1_m[0]) || isnan(o->edge2_m[0]))
        return lx__error(ctx, LX_EPARSE, f, ln, "opening '%s': give 'corner', 'edge1' and 'edge2' (a rectangle in a wall or "
                                                "the ceiling)", o->name);
    /* along the room's axes: each edge has one non-zero component, the two on different axes */
    int ax[2];
    for (int k = 0; k < 2; k++) {
        const double *e = k ? o->edge2_m : o->edge1_m;
        double l = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        int nz = 0;
        ax[k] = -1;
        for (int a = 0; a < 3; a++)
            if (fabs(e[a]) > 1e-9 * l) nz++, ax[k] = a;
        if (!(l > 0))
            return lx__error(ctx, LX_EPARSE, f, ln, "opening '%s': edge%d has zero length", o->name, k + 1);
        if (nz != 1)
            return lx__error(ctx, LX_EPARSE, f, ln,
                             "opening '%s': edge%d must run along x, y or z (along the edges of the room's face)", o->name,
                             k + 1);
    }
    if (ax[0] == ax[1])
        return lx__error(ctx, LX_EPARSE, f, ln, "opening '%s': edge1 and edge2 are parallel (a rectangle needs two axes)",
                         o->name);
    double p[4][3];
    corners(o, p);
    int found = -1, inside = 0;
    size_t room = 0;
    for (size_t r = 0; r < sc->n_room && found < 0; r++) {
        int k = face_of(&sc->room[r], (const double(*)[3])p, &inside);
        if (k >= 0 && inside) found = k, room = r;
    }
    if (found < 0) {
        for (size_t r = 0; r < sc->n_room; r++) {
            int k = face_of(&sc->room[r], (const double(*)[3])p, &inside);
            if (k >= 0)
                return lx__error(ctx, LX_EPARSE, f, ln, "opening '%s' extends outside the face %s.%s (it must lie within it)",
                                 o->name, sc->room[r].name, face_name[k]);
        }
        return lx__error(ctx, LX_EPARSE, f, ln,
                         "opening '%s' is not on a face of a room: its corners must lie in the plane of a wall or the "
                         "ceiling%s",
                         o->name, sc->n_room ? "" : " (the scene has no [room])");
    }
    if (found == LX_ROOM_FLOOR)
        return lx__error(ctx, LX_EPARSE, f, ln, "opening '%s' is in the floor of room '%s': openings are in walls or the ceiling",
                         o->name, sc->room[room].name);
    /* it must lead outside: no other room's face may hold any of it */
    double lo[3], hi[3];
    extent((const double(*)[3])p, lo, hi);
    int axis = found < 2 ? 2 : found < 4 ? 0 : 1;
    for (size_t r = 0; r < sc->n_room; r++) {
        if (r == room) continue;
        const lx_scene_room *R = &sc->room[r];
        double e = 1e-6 * (1 + fabs(lo[axis]));
        if (fabs(R->min_m[axis] - lo[axis]) > e && fabs(R->max_m[axis] - lo[axis]) > e) continue;
        int overlap = 1;
        for (int a = 0; a < 3; a++)
            if (a != axis) overlap &= lo[a] < R->max_m[a] && R->min_m[a] < hi[a];
        if (overlap)
            return lx__error(ctx, LX_EPARSE, f, ln,
                             "opening '%s' is in a face room '%s' touches: an opening must lead outside (daylight does not "
                             "pass between rooms)",
                             o->name, R->name);
    }
    o->room = room;
    o->face = (lx_room_face)found;
    o->area_m2 = (hi[(axis + 1) % 3] - lo[(axis + 1) % 3]) * (hi[(axis + 2) % 3] - lo[(axis + 2) % 3]);
    if (!(o->area_m2 > 0))
        return lx__error(ctx, LX_EPARSE, f, ln, "opening '%s': zero area", o->name);
    if (isnan(o->transmittance)) o->transmittance = o->glazing == LX_GLAZING_CLEAR ? LX__GLASS_6MM_TAU : 1;
    return LX_OK;
}

lx_status lx__daylight_scene_check(lx_ctx *ctx, lx_scene *sc)
{
    for (size_t i = 0; i < sc->n_open; i++) {
        lx_status st = check_one(ctx, sc, i);
        if (st != LX_OK) return st;
    }
    /* openings of one face do not overlap (touching is allowed) */
    for (size_t i = 0; i < sc->n_open; i++)
        for (size_t j = 0; j < i; j++) {
            const lx_scene_opening *a = &sc->open[i], *b = &sc->open[j];
            if (a->room != b->room || a->face != b->face) continue;
            double pa[4][3], pb[4][3], la[3], ha[3], lb[3], hb[3];
            corners(a, pa);
            corners(b, pb);
            extent((const double(*)[3])pa, la, ha);
            extent((const double(*)[3])pb, lb, hb);
            int axis = a->face < 2 ? 2 : a->face < 4 ? 0 : 1, overlap = 1;
            for (int k = 0; k < 3; k++)
                if (k != axis) overlap &= la[k] < hb[k] - 1e-9 && lb[k] < ha[k] - 1e-9;
            if (overlap)
                return lx__error(ctx, LX_EPARSE, a->file, a->line, "opening '%s' overlaps opening '%s' (%s:%ld)", a->name,
                                 b->name, b->file, b->line);
        }
    return LX_OK;
}

void lx__daylight_scene_free(lx_scene *sc)
{
    for (size_t i = 0; i < sc->n_open; i++) lx__free(sc->open[i].name);
    lx__free(sc->open);
}
