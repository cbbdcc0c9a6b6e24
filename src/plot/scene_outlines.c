/* scene_outlines.c - a scene drawn on a plan: its rooms, obstructions, surfaces, openings and
 * luminous areas projected on a receiver's plane as 2-D outlines (plan.c draws them), the plane of
 * a grid receiver, and the isolux plot of one receiver with all of it (lx_scene_receiver_write_png). */
#include "plot/plot_private.h"
#include "scene/scene_private.h"

#include <math.h>
#include <string.h>

#define MAXV 32 /* vertices of one outline: a box's hull has at most 6, a disk 24 */

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* 2-D cross product of (b - a) and (c - a) */
static double cross2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static int cmp_xy(const void *x, const void *y)
{
    const double *a = x, *b = y;
    return a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : a[1] < b[1] ? -1 : a[1] > b[1] ? 1 : 0;
}

/* The convex hull of n points (n <= MAXV, pairs in p; sorted in place) counter-clockwise into out;
 * returns its vertex count: 1 for a point, 2 for a segment (collinear points: the two ends). eps: the
 * distance below which points coincide. */
static size_t hull(double *p, size_t n, double eps, double *out)
{
    qsort(p, n, 2 * sizeof *p, cmp_xy);
    size_t m = 0;
    double tmp[2 * 2 * MAXV];
    for (size_t i = 0; i < n; i++) { /* lower chain */
        while (m >= 2 && cross2(tmp + 2 * (m - 2), tmp + 2 * (m - 1), p + 2 * i) <= eps * eps) m--;
        tmp[2 * m] = p[2 * i], tmp[2 * m + 1] = p[2 * i + 1], m++;
    }
    for (size_t i = n - 1, lo = m + 1; i-- > 0;) { /* upper chain */
        while (m >= lo && cross2(tmp + 2 * (m - 2), tmp + 2 * (m - 1), p + 2 * i) <= eps * eps) m--;
        tmp[2 * m] = p[2 * i], tmp[2 * m + 1] = p[2 * i + 1], m++;
    }
    if (m > 1) m--; /* the first point again */
    /* coincident points (all within eps) collapse to one */
    if (m == 2 && hypot(tmp[2] - tmp[0], tmp[3] - tmp[1]) <= eps) m = 1;
    memcpy(out, tmp, 2 * m * sizeof *out);
    return m;
}

typedef struct builder {
    const lx_plane *p;
    lx_plot_outline *o;
    double *v; /* MAXV pairs per outline */
    size_t n;
    double eps;
} builder;

/* adds the hull of n 3-D points projected on the plane; closed unless it is a segment or a point */
static void add_points(builder *b, lx_outline_kind kind, const char *name, const double (*pts)[3], size_t n)
{
    double q[2 * MAXV];
    for (size_t i = 0; i < n; i++) {
        double d[3] = {pts[i][0] - b->p->origin_m[0], pts[i][1] - b->p->origin_m[1], pts[i][2] - b->p->origin_m[2]};
        q[2 * i] = dot3(d, b->p->u), q[2 * i + 1] = dot3(d, b->p->v);
    }
    double *out = b->v + 2 * MAXV * b->n;
    size_t m = hull(q, n, b->eps, out);
    b->o[b->n] = (lx_plot_outline){.kind = kind, .closed = m > 2, .n = m, .ab_m = out, .name = name};
    b->n++;
}

static void add_box(builder *b, lx_outline_kind kind, const char *name, const double *lo, const double *hi)
{
    double c[8][3];
    for (int i = 0; i < 8; i++) c[i][0] = i & 1 ? hi[0] : lo[0], c[i][1] = i & 2 ? hi[1] : lo[1], c[i][2] = i & 4 ? hi[2] : lo[2];
    add_points(b, kind, name, (const double(*)[3])c, 8);
}

static void add_quad(builder *b, lx_outline_kind kind, const char *name, const double *corner, const double *e1,
                     const double *e2)
{
    double c[4][3];
    for (int k = 0; k < 3; k++) {
        c[0][k] = corner[k], c[1][k] = corner[k] + e1[k];
        c[2][k] = corner[k] + e1[k] + e2[k], c[3][k] = corner[k] + e2[k];
    }
    add_points(b, kind, name, (const double(*)[3])c, 4);
}

/* a luminaire's luminous area (a disk, or a rectangle in its own frame: lx__scene_frame) */
static void add_luminaire(builder *b, const lx_scene_luminaire *l)
{
    double ex[3], ey[3], ez[3], w = 0, len = 0, r = l->radius_m;
    if (!(r > 0)) lx__scene_lum_extent(l, &w, &len); /* along the frame's x and y */
    if (!(r > 0) && !(w > 0 && len > 0)) return;    /* a point source: its mark says where it is */
    lx__scene_frame(l, ex, ey, ez);
    double pts[24][3];
    size_t n = 0;
    if (r > 0)
        for (; n < 24; n++) {
            double t = 2 * LX__PI * (double)n / 24, cx = r * cos(t), cy = r * sin(t);
            for (int i = 0; i < 3; i++) pts[n][i] = l->pos_m[i] + cx * ex[i] + cy * ey[i];
        }
    else
        for (; n < 4; n++) {
            double sx = (n == 1 || n == 2) ? 0.5 : -0.5, sy = n >= 2 ? 0.5 : -0.5;
            for (int i = 0; i < 3; i++) pts[n][i] = l->pos_m[i] + sx * w * ex[i] + sy * len * ey[i];
        }
    add_points(b, LX_OUTLINE_LUMINAIRE, l->name, (const double(*)[3])pts, n);
}

/* 1 when the plane cuts the box (or touches it) */
static int plane_cuts_box(const lx_plane *p, const double *lo, const double *hi)
{
    double mn = INFINITY, mx = -INFINITY;
    for (int i = 0; i < 8; i++) {
        double c[3] = {(i & 1 ? hi[0] : lo[0]) - p->origin_m[0], (i & 2 ? hi[1] : lo[1]) - p->origin_m[1],
                       (i & 4 ? hi[2] : lo[2]) - p->origin_m[2]};
        double d = dot3(c, p->normal);
        mn = fmin(mn, d), mx = fmax(mx, d);
    }
    return mn <= 1e-9 && mx >= -1e-9;
}

lx_status lx_scene_outlines(lx_ctx *ctx, const lx_scene *sc, const lx_plane *plane, lx_plot_outline **out, size_t *n_out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !plane || !out || !n_out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_outlines: NULL argument");
    size_t cap = sc->n_room + sc->n_obst + sc->n_surf + sc->n_open + sc->n_lum;
    /* one block: the outlines, then MAXV vertex pairs for each */
    size_t head = (cap * sizeof(lx_plot_outline) + 15) / 16 * 16;
    unsigned char *mem = cap ? lx__alloc(head + lx__size_mul(cap, 2 * MAXV * sizeof(double))) : NULL;
    if (cap && !mem) return lx__error(ctx, LX_ENOMEM, NULL, 0, "scene outlines: out of memory");
    double ext = 0;
    for (size_t r = 0; r < sc->n_room; r++)
        for (int k = 0; k < 3; k++) ext = fmax(ext, fmax(fabs(sc->room[r].min_m[k]), fabs(sc->room[r].max_m[k])));
    builder b = {.p = plane, .o = (lx_plot_outline *)(void *)mem, .v = (double *)(void *)(mem + head), .eps = 1e-9 * fmax(1, ext)};
    for (size_t r = 0; r < sc->n_room; r++) /* the rooms the plane passes through */
        if (plane_cuts_box(plane, sc->room[r].min_m, sc->room[r].max_m))
            add_box(&b, LX_OUTLINE_WALL, sc->room[r].name, sc->room[r].min_m, sc->room[r].max_m);
    for (size_t k = 0; k < sc->n_obst; k++)
        add_box(&b, LX_OUTLINE_OBSTRUCTION, sc->obst[k].name, sc->obst[k].min_m, sc->obst[k].max_m);
    for (size_t k = 0; k < sc->n_surf; k++)
        add_quad(&b, LX_OUTLINE_SURFACE, sc->surf[k].name, sc->surf[k].corner_m, sc->surf[k].edge1_m, sc->surf[k].edge2_m);
    for (size_t k = 0; k < sc->n_open; k++)
        add_quad(&b, LX_OUTLINE_OPENING, sc->open[k].name, sc->open[k].corner_m, sc->open[k].edge1_m, sc->open[k].edge2_m);
    for (size_t k = 0; k < sc->n_lum; k++) add_luminaire(&b, &sc->lum[k]);
    if (!b.n) {
        lx__free(mem);
        mem = NULL;
    }
    *out = (lx_plot_outline *)(void *)mem;
    *n_out = b.n;
    return LX_OK;
}

void lx_scene_outlines_free(lx_plot_outline *outlines) { lx__free(outlines); }
