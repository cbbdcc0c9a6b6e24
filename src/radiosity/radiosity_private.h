/* radiosity_private.h - the radiosity layer (never installed): diffuse interreflection between
 * planar polygons. It knows nothing of scenes, luminaires or skies: its input is a list of
 * polygons (vertices, front normal, reflectances, transmittance, the volume on each side, a tag
 * for messages) and a callback that gives the direct light arriving on them; its output is the
 * exitance of every piece, the flux account and the indirect illuminance at any point with an
 * error estimate. README "Rooms" describes the method and its error contract. */
#ifndef LX_RADIOSITY_PRIVATE_H
#define LX_RADIOSITY_PRIVATE_H

#include "core/core_private.h"

/* ---- the input: planar polygons (rad_geom.c) ---- */

/* Volumes: the closed spaces (rooms) are numbered 0, 1, ...; these two are special. */
#define LX__RAD_OUTSIDE (-1) /* outside every room: open air, the sky side of a window */
#define LX__RAD_SOLID (-2)   /* the inside of a solid (an obstruction, a column): never lit, never seen */

/* One planar polygon. Its vertices are geom.v_m[3 first .. 3 (first + nv) - 1], in metres, in
 * order, counter-clockwise seen from the front (the front normal by the right-hand rule), simple
 * (edges meet only at their shared vertices), convex or not. lx__rad_geom_add fills first, nv and
 * n; the caller fills the rest. */
typedef struct lx__rad_poly {
    size_t first;            /* its first vertex in the pool (set by lx__rad_geom_add) */
    int nv;                  /* vertices, >= 3 (set by lx__rad_geom_add) */
    double n[3];             /* unit front normal (Newell's, from the vertices; set by lx__rad_geom_add) */
    double area_m2;          /* (set by lx__rad_geom_add) */
    double rho_front;        /* diffuse reflectance of the front side, 0 <= rho < 1 */
    double rho_back;         /* of the back side; < 0: the back is not a face (a room's wall seen from
                              * outside, an obstruction's face seen from inside): never lit */
    double tau;              /* 0: opaque. > 0: an opening: 1 a hole (a door, an unglazed window), below 1
                              * glazing, its transmittance at normal incidence (rho_front of it is
                              * reflected, tau passes, the rest is absorbed). An opening lying in the
                              * plane of an opaque polygon and inside it cuts its hole there. */
    int glazing;             /* lx_glazing of the opening's angular transmittance (0: tau at every angle) */
    int vol_front, vol_back; /* the volume each side faces: a room index, LX__RAD_OUTSIDE or LX__RAD_SOLID.
                              * An opening with a room on one side and LX__RAD_OUTSIDE on the other lets
                              * light out of the building (escaped flux); between two rooms, through. */
    int tag;                 /* the caller's index of the object it came from (results per object) */
    const char *name;        /* for messages and per-face results ("office.floor", "plan.obj: face 12");
                              * a copy owned by the geometry */
    const char *file;        /* where it was defined (not owned: the caller keeps it alive), NULL if none */
    long line;               /* its line there (for a model file: the face index), 0 if none */
} lx__rad_poly;

/* The polygons of a scene, with their vertex pool. Zero-initialise, add with lx__rad_geom_add,
 * free with lx__rad_geom_free. */
typedef struct lx__rad_geom {
    size_t n_poly, cap_poly;
    lx__rad_poly *poly;
    size_t n_v, cap_v;
    double *v_m;             /* 3 n_v coordinates */
    int n_vol;               /* rooms 0 .. n_vol - 1 (the largest volume index + 1) */
} lx__rad_geom;

/* Appends the polygon v_m[0 .. 3 nv - 1] with the properties of *info (its first, nv, n and area
 * are computed here; name is copied). The index it gets is *index (may be NULL). Errors
 * (LX_EPARSE naming info->file and info->line): fewer than 3 vertices, zero area, not planar
 * (a vertex farther than 1e-6 of its size, at least 1e-9 m, from its plane: says how far and
 * which vertex), edges that cross, a reflectance outside [0, 1), tau outside [0, 1], rho + tau > 1;
 * LX_ENOMEM. */
lx_status lx__rad_geom_add(lx_ctx *ctx, lx__rad_geom *g, const double *v_m, int nv, const lx__rad_poly *info,
                           size_t *index);
void lx__rad_geom_free(lx__rad_geom *g);
/* The vertices of polygon i. */
static inline const double *lx__rad_poly_v(const lx__rad_geom *g, size_t i) { return g->v_m + 3 * g->poly[i].first; }

/* The plane of polygon v[0 .. nv - 1]: Newell's normal (unit, by the right-hand rule; zero for a
 * degenerate polygon), the signed area, the largest distance of a vertex from the plane through
 * the centroid with that normal (*off_m) and which vertex it is (*worst). Returns the area. */
double lx__rad_poly_plane(const double *v, int nv, double n[3], double *off_m, int *worst);
/* 1 when two edges of the polygon (in its own plane, normal n) cross or touch other than at their
 * shared vertex: *e1, *e2 the edges (edge k runs from vertex k to k + 1). */
int lx__rad_poly_crosses(const double *v, int nv, const double n[3], int *e1, int *e2);

#endif /* LX_RADIOSITY_PRIVATE_H */
