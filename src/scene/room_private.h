/* room_private.h - the room solver's internals (scene layer; never installed): faces, patches,
 * occluders and openings; exact point-to-polygon form factors and ray-cast visibility (the CPU
 * twins of kernels/room.cl); the mesh the planner builds; the radiosity solve and the gather.
 *
 * The solver's API is independent of where the light comes from: a mesh of patches (each with a
 * reflectance), the flux each patch receives from external sources (luminaires here; sky and sun
 * through openings for daylight), and holes (openings) in faces that transmit and never reflect. */
#ifndef LX_ROOM_PRIVATE_H
#define LX_ROOM_PRIVATE_H

#include "radiosity/radiosity_private.h"
#include "scene/scene_private.h"

/* ---- geometry (room_geom.c; the CPU twins of kernels/room.cl) ---- */

/* An occluder: an axis-aligned box (an obstruction) or a parallelogram o + s u + t v (a surface).
 * lo/hi bound it in both cases (the bounding-volume test). */
typedef struct lx__room_occ {
    int kind;                      /* 0 box, 1 parallelogram */
    double lo[3], hi[3];
    double o[3], u[3], v[3], n[3]; /* parallelogram: corner, edges, unit normal */
    double uu, uv, vv, det;        /* its Gram matrix (the inside test) */
} lx__room_occ;

/* Fills a parallelogram occluder (kind 1) or a box (kind 0: o = lo, u = hi). */
void lx__room_occ_box(lx__room_occ *oc, const double lo[3], const double hi[3]);
void lx__room_occ_quad(lx__room_occ *oc, const double o[3], const double u[3], const double v[3]);

/* Form factor from a differential area at x with unit normal n to the convex polygon p (nv <=
 * LX__POLY_MAX vertices, xyz each), counting only the part in front of x's tangent plane:
 * Lambert's formula, lx__polygon_projected / pi. A point on an edge of the polygon is moved 1e-9
 * of the polygon's size off its tangent plane (the limit from the front). */
double lx__room_ff_point(const double x[3], const double n[3], const double *p, int nv);

/* The same for the parallelogram o + s u + t v, 0 if x is behind it (n_poly . (x - o) <= 0). */
double lx__room_ff_quad(const double x[3], const double n[3], const double o[3], const double u[3], const double v[3],
                        const double n_poly[3]);

/* 1 when the segment p -> q, less 1e-9 of its length at each end, meets no occluder (skip, skip2:
 * occluders not to test, -1 for none). Touching or grazing a boundary does not block. */
int lx__room_visible(const lx__room_occ *occ, int n_occ, const double p[3], const double q[3], int skip, int skip2);

/* 1 when the box lo..hi overlaps some occluder's box (open intervals: touching is no overlap),
 * other than skip and skip2. The bounding-volume test: 0 means no occluder can cut any segment
 * between points of lo..hi. */
int lx__room_bv(const lx__room_occ *occ, int n_occ, const double lo[3], const double hi[3], int skip, int skip2);
/* The same, tighter, for the shaft between two convex pieces whose points lie within r of centres
 * p and q (the convex hull of both lies within r of the segment p-q): 1 when some occluder's box
 * overlaps lo..hi and its box grown by r meets the segment. 0: nothing can cut the shaft. */
int lx__room_shaft(const lx__room_occ *occ, int n_occ, const double lo[3], const double hi[3], const double p[3],
                   const double q[3], double r, int skip, int skip2);

/* Area-to-area form factor F from parallelogram 1 (o1, u1, v1, unit normal n1) to parallelogram 2:
 * the exact point-to-polygon form factor integrated over 1 by tensor tanh-sinh quadrature (which
 * keeps its accuracy where the integrand is singular, at an edge the two share), refined until
 * two levels agree within tol. For tests and reference values; the solve uses lx__room_ff_quad
 * at Gauss points. */
double lx__room_ff_area(const double o1[3], const double u1[3], const double v1[3], const double n1[3],
                        const double o2[3], const double u2[3], const double v2[3], const double n2[3], double tol);

/* Gauss-Legendre nodes (on [0, 1]) and weights (sum 1) of order m = 1..8. */
void lx__room_gauss(int m, const double **x, const double **w);

/* ---- the scene as the radiosity layer's polygons (room_polys.c) ---- */

/* Appends to g (zero-initialised) every room face (6 a room, lx_room_face order, facing in, the
 * outside behind), surface (one polygon, both sides reflecting), obstruction face (6 each, facing
 * out, solid behind) and opening (a hole in its face, facing into its room, the outside behind).
 * Tags: room r face k 6 r + k; surface i 6 n_room + 2 i (its back + 1); obstruction i face k
 * 6 n_room + 2 n_surf + 6 i + k (the mesh's face order); opening k -1 - k. Frees g on error. */
lx_status lx__room_geom(lx_ctx *ctx, const lx_scene *sc, lx__rad_geom *g);

/* ---- faces, patches and the mesh (room_mesh.c) ---- */

/* A face: one reflecting side of a planar parallelogram o + s u + t v (unit normal n = u x v). */
typedef struct lx__room_face {
    char name[160];                /* ROOM.floor, SURFACE.front, OBSTRUCTION.top, ... */
    double o[3], u[3], v[3], n[3];
    double rho;
    int cell;                      /* the room it belongs to, -1 outside every room */
    int occluder;                  /* the occluder it is part of (never blocks its own rays), -1 none */
    int axis;                      /* 0, 1, 2: axis-aligned with that normal axis; -1 otherwise */
    double area_m2;                /* its exposed area (the patches') */
} lx__room_face;

/* An opening: a hole in face `face` over the parameter rectangle s0..s1 x t0..t1 of its edges. The
 * mesh leaves it without patches: light that reaches it leaves the room (escaped flux), and a
 * caller may let light in through it as a source of direct flux on the patches. */
typedef struct lx__room_opening {
    int face;
    double s0, s1, t0, t1;
} lx__room_opening;

/* A patch: the parallelogram o + s u + t v, a piece of face `face`. The solve runs on patches;
 * each patch is cut into elements (itself when not refined) where the light varies fast, and the
 * final gather resolves the elements. */
typedef struct lx__room_patch {
    double o[3], u[3], v[3], c[3], n[3]; /* corner, edges, centre, unit normal */
    double lo[3], hi[3];                 /* bounding box */
    double area_m2, rho, size_m;         /* size: the longer edge */
    double rad;                          /* half its longer diagonal: every point within rad of c */
    int face, cell, occluder;
    int order;                           /* elements: Gauss-Legendre nodes per side of the direct light */
    int shoot;                           /* patches: Gauss-Legendre nodes per side it shoots from (1: centre) */
    size_t parent;                       /* elements: the patch they are part of */
} lx__room_patch;

/* The mesh: the faces, their patches and elements, and the occluders of a scene. */
typedef struct lx__room_mesh {
    size_t n_face, n_patch, n_elem, n_occ, n_open;
    lx__room_face *face;
    lx__room_patch *patch;               /* the solve's patches */
    lx__room_patch *elem;                /* the gather's elements (each in one patch) */
    lx__room_occ *occ;
    lx__room_opening *open;
    double h_m;                          /* the base patch size */
    double tol;                          /* the relative tolerance of the indirect part it was built for */
    double quad_tol;                     /* and of the elements' direct light */
    size_t n_nodes;                      /* direct-light quadrature nodes over all elements */
    size_t n_refined;                    /* elements split by the refinement */
    const lx_scene *sc;                  /* the scene the faces came from (not owned) */
    lx_counters probe;                   /* the work of the refinement's probes (the planner's) */
    int *obst_occ, *surf_occ;            /* the occluder of each obstruction and surface */
} lx__room_mesh;

/* What the mesh builder is asked for. */
typedef struct lx__room_mesh_opts {
    double h_m;                  /* base patch size along each face edge */
    double tol;                  /* relative tolerance of the indirect part the refinement aims at */
    double quad_tol;             /* relative tolerance of each element's direct light (quadrature orders) */
    double indirect_est_lx;      /* the expected indirect illuminance (refinement: variations below a
                                  * fraction of it do not matter) */
    int max_depth;               /* quadtree levels of the refinement (0: none) */
    size_t max_patches;          /* the memory bound: LX_EPARSE naming max_line beyond it */
    size_t max_elem;             /* the refinement stops at this many elements (0: 400000) */
    const char *max_file;        /* where to point an error */
    long max_line;
    const lx__room_opening *open;/* holes (may be NULL) */
    size_t n_open;
    /* more direct light for the refinement's probes to see (daylight through openings; NULL: none) */
    double (*probe_extra)(void *arg, const lx__room_patch *p, const double x[3]);
    void *probe_arg;
} lx__room_mesh_opts;

/* The occluders of a scene (every surface and obstruction), without patches: for occlusion alone. */
lx_status lx__room_occluders(lx_ctx *ctx, const lx_scene *sc, lx__room_mesh **out);
/* The faces and patches of a scene (every room face, surface side and obstruction face with its
 * reflectance), with the occluders. Patches: each face cut at its openings and at the footprints
 * of obstructions standing on it (covered parts have no patches), into pieces of at most h_m,
 * then split in four where the estimated direct illuminance varies fast (near a luminaire, at a
 * shadow edge). Probes the luminaires through lx__scene_lum_E (not counted as work). */
lx_status lx__room_mesh_build(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lx__room_mesh_opts *o,
                              lx__room_mesh **out);
void lx__room_mesh_free(lx__room_mesh *m);
/* The room (index) a point lies in (inclusive boundaries), -1 outside every room. */
int lx__room_cell(const lx_scene *sc, const double q[3]);
/* Bytes the solve allocates for n patches (form-factor matrix and vectors) and n_elem elements. */
double lx__room_bytes(size_t n_patches, size_t n_elem);
/* The bound: LX_ROOM_MEMORY_MB or 1 GiB. */
double lx__room_memory_limit(void);
/* The most patches the bound allows. */
size_t lx__room_max_patches(void);

/* ---- the planner's tests (room_plan.c) ---- */

/* 1 when some occluder (other than skip) may cut a segment from luminaire le's luminous extent
 * to q: the bounding-volume test. */
int lx__room_lum_bv(const lx__room_mesh *m, const lx__scene_lum *le, const double q[3], int skip);

/* ---- the solve and the gather (room_solve.c, room_cl.c) ---- */

/* The solution of one interreflection solve. */
typedef struct lx__room_solution {
    double *phi_ind_lm;          /* per patch: flux received after reflections */
    double *B;                   /* per patch: exitance rho (received) / area (lm/m2) */
    unsigned long long sweeps, shots;
    double unshot_lm, escaped_lm;
    double seconds_solve;
} lx__room_solution;

/* The form-factor matrix F (n x n patches, row i: from patch i's shooting points to every patch,
 * with visibility; patches in other rooms 0), on the CPU (threads) or an OpenCL device as the one
 * backend rule chooses. *F is malloc'ed. *used: the backend it ran on. */
lx_status lx__room_ff_matrix(lx_ctx *ctx, const lx__room_mesh *m, lx_backend backend, double **F, int *used);
/* CPU twin of the matrix kernel for rows i0..i1-1 (row-major n columns into F). */
void lx__room_ff_rows(const lx__room_mesh *m, size_t i0, size_t i1, double *F);

/* Solves the interreflection: phi0_lm (per patch, flux received from external sources) is
 * reflected (rho) and shot, progressive refinement in sweeps over the patches, until the unshot
 * flux is at most stop_unshot_lm. F from lx__room_ff_matrix. Fills sol (free with
 * lx__room_solution_free). */
lx_status lx__room_solve(lx_ctx *ctx, const lx__room_mesh *m, const double *F, const double *phi0_lm,
                         double stop_unshot_lm, lx__room_solution *sol);
void lx__room_solution_free(lx__room_solution *sol);

/* A gather job: the illuminance at n points (pts n x 3, unit normals nrm n x 3, rooms cell[n],
 * skip[n]: an occluder that never blocks the point's rays, or NULL) from the n_src patches src of
 * exitance B: sum_j B_j F(x -> src j) V(x, src j), exact point-to-polygon form factors and
 * ray-cast visibility (rays to 2 x 2 points of the patch where the bounding-volume test asks). */
typedef struct lx__room_gather_job {
    const lx__room_mesh *m;      /* the occluders */
    const lx__room_patch *src;
    size_t n_src;
    const double *B;
    size_t n;
    const double *pts, *nrm;
    const int *cell, *skip;
    int vis_levels;              /* LX__ROOM_VIS_ELEMENTS or LX__ROOM_VIS_RECEIVERS */
} lx__room_gather_job;

/* Runs a gather on the CPU or OpenCL (the one backend rule) into E_lx; counts its work. */
lx_status lx__room_gather(lx_ctx *ctx, const lx__room_gather_job *g, lx_backend backend, double *E_lx, int *used);
/* CPU twin of the gather kernel for points i0..i1-1. */
void lx__room_gather_cpu(const lx__room_gather_job *g, size_t i0, size_t i1, double *E_lx);
/* The visible part of the form factor f = F(x, n -> pj) when the bounding-volume test says an
 * occluder may cut it: rays to pj's 3 x 3 lattice (corners, edge midpoints, centre); all seen: f,
 * none: 0, else the exact form factors of its quarters, each tested the same way, `levels` levels
 * deep, the last weighted by its lattice's visible fraction (trapezoid weights). Adds the form
 * factors and rays it computes. */
double lx__room_ff_vis(const lx__room_mesh *m, const double x[3], const double n[3], const lx__room_patch *pj, int skip,
                       double f, int levels, unsigned long long *ff, unsigned long long *rays);
/* The levels of that subdivision: patch to patch in the matrix, the gathers at elements and at
 * receivers (each level 4 times the pieces where a shadow edge crosses). */
#define LX__ROOM_VIS_MATRIX 1
#define LX__ROOM_VIS_ELEMENTS 2
#define LX__ROOM_VIS_RECEIVERS 3

#if LX_OPENCL
/* The OpenCL twins (room_cl.c): the matrix; a gather. */
lx_status lx__room_cl_ff(lx_ctx *ctx, const lx__room_mesh *m, double *F);
lx_status lx__room_cl_gather(lx_ctx *ctx, const lx__room_gather_job *g, double *E_lx);
#endif

/* OpenCL break-even of the form-factor and gather jobs, in form factors (README "Rooms"): the
 * measured start-up on a cold context (7.6 s with PoCL's compile, an empty kernel cache) over the
 * measured CPU cost (0.46 us a pair of patches, 2 threads under load), and a warm context's 0.1 s
 * of uploads and launches over it; a device at least as fast per pair as these 2 cores is
 * assumed (PoCL's CPU device is not: 2.7 us, so the rule's CPU-device exclusion applies). */
#define LX__ROOM_CL_COLD 2e7
#define LX__ROOM_CL_WARM 2e5

#endif /* LX_ROOM_PRIVATE_H */
