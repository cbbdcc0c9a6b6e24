/* daylight_private.h - the daylight module's internals (scene layer; never installed): openings
 * seen from a point (clipping, exact moments of a spherical polygon, adaptive cubature), the sky,
 * ground and sun through openings at receiver points and room elements, the daylight's own
 * interreflection solve on the room mesh, and the planner's part. */
#ifndef LX_DAYLIGHT_PRIVATE_H
#define LX_DAYLIGHT_PRIVATE_H

#include "scene/room_private.h"

/* ---- directions of a planar polygon seen from a point (daylight_geom.c) ---- */

#define LX__DL_JMAX 5  /* the highest power of cos(incidence) in a glazing polynomial */
#define LX__DL_VMAX 12 /* vertices of a clipped polygon */
#define LX__GLASS_6MM_TAU 0.878810 /* P(1) of lx_glazing_transmittance's polynomial: 6 mm clear glass at normal incidence */

/* Sutherland-Hodgman: the part of the convex polygon in[0..n-1] (points relative to the viewpoint)
 * where sign * (a . p) >= 0, into out (at most n + 1 vertices); returns its count (< 3: empty). */
int lx__dl_clip(const double (*in)[3], int n, const double a[3], double sign, double (*out)[3]);

/* The moments K[q][j] = integral over the directions w of the polygon p[0..nv-1] (a convex planar
 * polygon, vertices relative to the viewpoint, in order, its plane not through the viewpoint) of
 * (n . w) (z . w)^q (m . w)^j dw, q = 0, 1, j = 0..J (J <= LX__DL_JMAX). Exact: the divergence
 * theorem on the cone over the polygon (README "Daylight") reduces each to lower moments and edge
 * integrals, which are trigonometric polynomials of degree <= J + 2 integrated by 16-point
 * Gauss-Legendre (1e-15). n, z, m: any vectors (unit for the usual meaning). */
void lx__dl_moments(const double (*p)[3], int nv, const double n[3], const double z[3], const double m[3], int J,
                    double K[2][LX__DL_JMAX + 1]);

/* The solid angle of the polygon's directions (Van Oosterom & Strackee on a fan). */
double lx__dl_solid_angle(const double (*p)[3], int nv);

/* The integral of g(w) dw over the directions of the convex planar polygon p[0..nv-1] (relative to
 * the viewpoint; m: the unit normal of its plane pointing away from the viewpoint) by adaptive
 * cubature on its triangles (collapsed 4 x 4 Gauss-Legendre, split in four until the children's sum
 * agrees with the parent within tol of the whole or abs_tol, at most max_depth levels). *evals (may
 * be NULL) gains the evaluations of g. */
typedef double (*lx__dl_fn)(void *arg, const double w[3]);
double lx__dl_integrate(const double (*p)[3], int nv, const double m[3], lx__dl_fn g, void *arg, double tol, double abs_tol,
                        int max_depth, unsigned long long *evals);

/* The area of a convex planar polygon (3D vertices). */
double lx__dl_area(const double (*p)[3], int nv);

/* ---- the daylight of one evaluation (daylight_sc.c, daylight_eval.c) ---- */

/* An opening prepared for evaluation. */
typedef struct lx__dl_open {
    double o[3], u[3], v[3]; /* corner and edges */
    double m[3];             /* unit normal towards the outside (the sky) */
    double lo[3], hi[3];     /* bounding box */
    double size_m;           /* its diagonal */
    double area_m2;
    double tau[LX__DL_JMAX + 1]; /* the glazing: tau(c) = sum tau[j] c^j for c = cos(incidence) */
    int J;                   /* its degree */
    double c_neg;            /* the polynomial is negative below this cosine (0: never) */
    lx_glazing glazing;
    double tau_n;
    int room, face;          /* its room and the mesh face index 6 room + lx_room_face */
    int outside_occ;         /* 1 when some occluder or another room lies on its outer side */
} lx__dl_open;

/* The daylight of an evaluation: the sky model, the openings, the occluders and the per-point and
 * per-face results. */
typedef struct lx__daylight {
    const lx_scene *sc;
    const lx_scene_plan *plan;
    void *map;                /* the sky map (LX_SKY_MAP), loaded for this evaluation */
    lx__dl_open *op;
    size_t n_op;
    const lx__room_occ *occ;  /* the occluders rays are tested against (NULL, 0: none) */
    int n_occ;
    lx__room_mesh *own_occ;   /* occluders built here when the plan has none (freed with the run) */
    double E_h;               /* the sky's horizontal illuminance outside (no sun) */
    double Lg;                /* the ground's luminance below the horizon */
    double sun[3], sun_lx;    /* towards the sun and its direct normal illuminance (0: none above the horizon) */
    int closed;               /* uniform or overcast: L(w) = L0 + L1 w_z, the sky component in closed form */
    double L0, L1;
    double tol;               /* relative tolerance of the numerical integrations */
    double far_m;             /* length of the rays that leave a room (beyond every entity of the scene) */
    size_t np;
    double *sky_lx, *ground_lx, *sun_pt_lx, *ind_lx; /* per receiver point */
    double *face_direct_lm, *face_indirect_lm;       /* per mesh face */
    size_t n_face;
    lx_scene_daylight_stats stats;
} lx__daylight;

/* The direct daylight at point x (unit normal n) in room `cell` through that room's openings:
 * out[0] the sky, out[1] the ground (both through the glazing), out[2] the sun (when `sun`), in lx.
 * skip: an occluder x is part of (never blocks its rays), -1 none. Counts its evaluations in cnt. */
void lx__daylight_at(const lx__daylight *d, const double x[3], const double n[3], int cell, int skip, int sun, double out[3],
                     lx_counters *cnt);
/* The sun's flux (lm) on the parallelogram element e through the openings of its room: exact (the
 * beam through each opening clipped to the element) when no occluder can cut it, else the element's
 * `order` x `order` Gauss nodes with visibility. */
double lx__daylight_sun_flux(const lx__daylight *d, const lx__room_patch *e, int order);
/* The illuminance (lx) on the outer side of opening k from the sky, the ground and the sun, through
 * its glazing: its flux in is this times its area. Gauss-Legendre, 64 nodes in the angle from the
 * opening's normal x 64 in azimuth per arc (split where the horizon cuts). */
double lx__daylight_opening_E(const lx__daylight *d, size_t k);
/* 1 when the ray from q towards the sun meets no occluder (but skip) and no room other than `cell`. */
int lx__daylight_sun_visible(const lx__daylight *d, const double q[3], int cell, int skip);
/* The glazing of op as a polynomial in cos(incidence) (tau, J) and where it turns negative (c_neg). */
void lx__daylight_glazing(lx__dl_open *op, lx_glazing g, double tau_n);
/* The sky's luminance towards w (w_z >= 0; 0 for no sky). */
double lx__daylight_sky_L(const lx__daylight *d, const double w[3]);

/* The length of the rays that leave a room: beyond every entity of the scene. */
double lx__daylight_far(const lx_scene *sc);
/* For the sun alone (receivers outside rooms): the scene's occluders and rooms, no openings; *out
 * NULL when the sun does not shine or nothing can shade it. */
lx_status lx__daylight_sun_only(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, lx__daylight **out);
/* Prepares the daylight of an evaluation (*out NULL when daylight is off). */
lx_status lx__daylight_begin(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, lx__daylight **out);
void lx__daylight_free(lx__daylight *d);
/* The direct daylight at every receiver point inside a room: into the sky's column of contrib_lx and
 * E_lx. */
lx_status lx__daylight_points(lx_ctx *ctx, lx__daylight *d, lx_scene_result *res);
/* The results: daylight_lx, the daylight factor and its components, the faces' daylight. */
lx_status lx__daylight_finish(lx_ctx *ctx, lx__daylight *d, lx_scene_result *res);
/* Gauss-Legendre nodes per side of an element's direct daylight: the smallest m whose estimated error
 * 0.5 (r / 2)^(2m) meets tol, r = the element's size over its distance to the nearest opening of its
 * room (1 when it sees none). */
int lx__daylight_order(const lx_scene *sc, const lx__room_patch *e, double tol);

/* ---- the planner (daylight_plan.c) and the openings' keys (daylight_read.c) ---- */

/* The daylight of a scene without its per-point arrays: the sky model, the openings (prepared),
 * the occluders (occ may be NULL: built from the scene), the ground's luminance, the sun. map: the
 * loaded sky map or NULL (then loaded here for LX_SKY_MAP). For the planner and lx__daylight_begin. */
lx_status lx__daylight_setup(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lx__room_mesh *occ,
                             lx__daylight **out);

/* The openings as holes of the mesh faces (occ: the faces from lx__room_occluders or the mesh);
 * *open malloc'ed (NULL when there are none). */
lx_status lx__daylight_mesh_openings(lx_ctx *ctx, const lx_scene *sc, const lx__room_mesh *occ, lx__room_opening **open,
                                     size_t *n);
/* The rooms' planner's hook before it builds the mesh: the openings as holes (o->open), and with
 * daylight on, the daylight its refinement probes (o->probe_extra: sky, ground and sun at a point of
 * a patch) and the daylight's integrating-sphere estimate added to o->indirect_est_lx. *state: free
 * with lx__daylight_mesh_end after the build. */
lx_status lx__daylight_mesh_begin(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *p, const lx__room_mesh *occ,
                                  lx__room_mesh_opts *o, void **state);
void lx__daylight_mesh_end(lx__room_mesh_opts *o, void *state);

#endif /* LX_DAYLIGHT_PRIVATE_H */
