/* rad_geom.c - the radiosity layer's input: planar polygons in a vertex pool, each checked when it
 * is added (enough vertices, an area, planar within 1e-6 of its size, edges that do not cross,
 * reflectances and transmittance in range); Newell's normal and the plane's fit. */
#include "radiosity/radiosity_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void lx__rad_geom_free(lx__rad_geom *g)
{
    if (!g) return;
    for (size_t i = 0; i < g->n_poly; i++) lx__free((char *)g->poly[i].name);
    lx__free(g->poly);
    lx__free(g->v_m);
    memset(g, 0, sizeof *g);
}

double lx__rad_poly_plane(const double *v, int nv, double n[3], double *off_m, int *worst)
{
    double N[3] = {0, 0, 0}, c[3] = {0, 0, 0};
    for (int k = 0; k < nv; k++) {
        const double *a = v + 3 * k, *b = v + 3 * ((k + 1) % nv);
        N[0] += (a[1] - b[1]) * (a[2] + b[2]);
        N[1] += (a[2] - b[2]) * (a[0] + b[0]);
        N[2] += (a[0] - b[0]) * (a[1] + b[1]);
        for (int i = 0; i < 3; i++) c[i] += a[i] / nv;
    }
    double l = sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
    double off = 0;
    int w = 0;
    if (l > 0) {
        for (int i = 0; i < 3; i++) n[i] = N[i] / l;
        for (int k = 0; k < nv; k++) {
            const double *a = v + 3 * k;
            double d = fabs((a[0] - c[0]) * n[0] + (a[1] - c[1]) * n[1] + (a[2] - c[2]) * n[2]);
            if (d > off) off = d, w = k;
        }
    } else
        n[0] = n[1] = n[2] = 0;
    if (off_m) *off_m = off;
    if (worst) *worst = w;
    return 0.5 * l;
}

/* 2D coordinates of a 3D point in the plane with normal n (drop the largest component). */
static void to2d(const double *p, int drop, double q[2])
{
    int a = drop == 0 ? 1 : 0, b = drop == 2 ? 1 : 2;
    q[0] = p[a];
    q[1] = p[b];
}

static double orient(const double a[2], const double b[2], const double c[2])
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* 1 when segments ab and cd share a point (closed segments; collinear overlaps included). */
static int seg_meet(const double a[2], const double b[2], const double c[2], const double d[2], double eps)
{
    double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
    if (((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) && ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps))) return 1;
    /* touching or collinear: a point of one within the other's box and on its line */
    const double *P[4] = {a, b, c, d}, *S0[4] = {c, c, a, a}, *S1[4] = {d, d, b, b};
    double D[4] = {d1, d2, d3, d4};
    for (int k = 0; k < 4; k++)
        if (fabs(D[k]) <= eps && P[k][0] >= fmin(S0[k][0], S1[k][0]) - 1e-12 && P[k][0] <= fmax(S0[k][0], S1[k][0]) + 1e-12 &&
            P[k][1] >= fmin(S0[k][1], S1[k][1]) - 1e-12 && P[k][1] <= fmax(S0[k][1], S1[k][1]) + 1e-12)
            return 1;
    return 0;
}

int lx__rad_poly_crosses(const double *v, int nv, const double n[3], int *e1, int *e2)
{
    int drop = fabs(n[0]) > fabs(n[1]) ? (fabs(n[0]) > fabs(n[2]) ? 0 : 2) : (fabs(n[1]) > fabs(n[2]) ? 1 : 2);
    double size = 0;
    for (int k = 1; k < nv; k++)
        for (int c = 0; c < 3; c++) size = fmax(size, fabs(v[3 * k + c] - v[c]));
    double eps = 1e-12 * size * size;
    for (int i = 0; i < nv; i++) {
        double a[2], b[2];
        to2d(v + 3 * i, drop, a);
        to2d(v + 3 * ((i + 1) % nv), drop, b);
        for (int j = i + 1; j < nv; j++) {
            /* neighbours share a vertex: they may only meet there (a fold back is a crossing) */
            int next = j == i + 1, prev = i == 0 && j == nv - 1;
            double c[2], d[2];
            to2d(v + 3 * j, drop, c);
            to2d(v + 3 * ((j + 1) % nv), drop, d);
            if (next || prev) {
                /* the shared vertex is b = c (next) or a = d (prev): they overlap when collinear and
                 * folding back */
                const double *s = next ? a : c, *m = next ? b : a, *t = next ? d : b;
                double o = orient(s, m, t), dp = (m[0] - s[0]) * (t[0] - m[0]) + (m[1] - s[1]) * (t[1] - m[1]);
                if (fabs(o) <= eps && dp < 0) {
                    if (e1) *e1 = i;
                    if (e2) *e2 = j;
                    return 1;
                }
                continue;
            }
            if (seg_meet(a, b, c, d, eps)) {
                if (e1) *e1 = i;
                if (e2) *e2 = j;
                return 1;
            }
        }
    }
    return 0;
}

static lx_status grow(lx_ctx *ctx, void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap) return LX_OK;
    size_t nc = *cap ? *cap : 64;
    while (nc < need) nc *= 2;
    void *np = lx__realloc_n(*p, nc, size);
    if (!np) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the polygons");
    *p = np;
    *cap = nc;
    return LX_OK;
}

lx_status lx__rad_geom_add(lx_ctx *ctx, lx__rad_geom *g, const double *v_m, int nv, const lx__rad_poly *info,
                           size_t *index)
{
    const char *nm = info->name ? info->name : "polygon";
    if (nv < 3) return lx__error(ctx, LX_EPARSE, info->file, info->line, "%s: a polygon needs at least 3 vertices (got %d)", nm, nv);
    for (int k = 0; k < 3 * nv; k++)
        if (!isfinite(v_m[k])) return lx__error(ctx, LX_EPARSE, info->file, info->line, "%s: vertex %d is not finite", nm, k / 3 + 1);
    double n[3], off;
    int worst;
    double area = lx__rad_poly_plane(v_m, nv, n, &off, &worst), size = 0;
    for (int k = 1; k < nv; k++)
        for (int c = 0; c < 3; c++) size = fmax(size, fabs(v_m[3 * k + c] - v_m[c]));
    /* edges that cross first (a symmetric bow tie has no net area): in the plane of the largest
     * corner when Newell's normal vanishes */
    double nc[3] = {n[0], n[1], n[2]};
    for (int k = 0; k < nv && !(nc[0] || nc[1] || nc[2]); k++) {
        const double *a = v_m + 3 * k, *b = v_m + 3 * ((k + 1) % nv), *c = v_m + 3 * ((k + 2) % nv);
        double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, f[3] = {c[0] - b[0], c[1] - b[1], c[2] - b[2]};
        double x[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
        if (x[0] * x[0] + x[1] * x[1] + x[2] * x[2] > 1e-24 * size * size * size * size) memcpy(nc, x, sizeof nc);
    }
    int e1, e2;
    if ((nc[0] || nc[1] || nc[2]) && (!(off > fmax(1e-6 * size, 1e-9)) || !(area > 0)) &&
        lx__rad_poly_crosses(v_m, nv, nc, &e1, &e2))
        return lx__error(ctx, LX_EPARSE, info->file, info->line,
                         "%s: the polygon's edges %d-%d and %d-%d cross or overlap (a polygon must not intersect itself)", nm,
                         e1 + 1, (e1 + 1) % nv + 1, e2 + 1, (e2 + 1) % nv + 1);
    if (!(area > 1e-12 * size * size) || !(area > 0))
        return lx__error(ctx, LX_EPARSE, info->file, info->line, "%s: the polygon has no area (its vertices are on one line or one point)", nm);
    if (off > fmax(1e-6 * size, 1e-9))
        return lx__error(ctx, LX_EPARSE, info->file, info->line,
                         "%s: the polygon is not planar: vertex %d is %.3g m off the plane of the others (%.3g of its size; at most 1e-6)",
                         nm, worst + 1, off, off / size);
    if (!(info->rho_front >= 0 && info->rho_front < 1) || !(info->rho_back < 1))
        return lx__error(ctx, LX_EPARSE, info->file, info->line, "%s: a reflectance must be at least 0 and below 1", nm);
    if (!(info->tau >= 0 && info->tau <= 1) || !(info->rho_front + info->tau <= 1))
        return lx__error(ctx, LX_EPARSE, info->file, info->line,
                         "%s: the transmittance must be within 0..1 and reflectance + transmittance at most 1", nm);
    lx_status st = grow(ctx, (void **)&g->poly, &g->cap_poly, g->n_poly + 1, sizeof *g->poly);
    if (st == LX_OK) st = grow(ctx, (void **)&g->v_m, &g->cap_v, g->n_v + (size_t)nv, 3 * sizeof *g->v_m);
    if (st != LX_OK) return st;
    char *name = NULL;
    if (info->name) {
        size_t l = strlen(info->name) + 1;
        name = lx__alloc(l);
        if (!name) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the polygons");
        memcpy(name, info->name, l);
    }
    lx__rad_poly *p = &g->poly[g->n_poly];
    *p = *info;
    p->name = name;
    p->first = g->n_v;
    p->nv = nv;
    p->area_m2 = area;
    memcpy(p->n, n, sizeof p->n);
    memcpy(g->v_m + 3 * g->n_v, v_m, 3 * (size_t)nv * sizeof *v_m);
    g->n_v += (size_t)nv;
    if (p->vol_front + 1 > g->n_vol) g->n_vol = p->vol_front + 1;
    if (p->vol_back + 1 > g->n_vol) g->n_vol = p->vol_back + 1;
    if (index) *index = g->n_poly;
    g->n_poly++;
    return LX_OK;
}
