/* room_geom.c - the geometry of rooms: exact point-to-polygon form factors (Lambert's formula of
 * core/lambert.c, the polygon clipped to the receiver's hemisphere), segment-occluder visibility,
 * the bounding-volume test, area-to-area form factors by tanh-sinh quadrature, Gauss-Legendre
 * nodes. The form factor and visibility functions are the CPU twins of kernels/room.cl: the
 * kernel repeats the same operations in the same order (no contraction on either side). */
#include "scene/room_private.h"

#include <math.h>
#include <pthread.h>
#include <string.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

void lx__room_occ_box(lx__room_occ *oc, const double lo[3], const double hi[3])
{
    memset(oc, 0, sizeof *oc);
    oc->kind = 0;
    memcpy(oc->lo, lo, sizeof oc->lo);
    memcpy(oc->hi, hi, sizeof oc->hi);
}

void lx__room_occ_quad(lx__room_occ *oc, const double o[3], const double u[3], const double v[3])
{
    memset(oc, 0, sizeof *oc);
    oc->kind = 1;
    memcpy(oc->o, o, sizeof oc->o);
    memcpy(oc->u, u, sizeof oc->u);
    memcpy(oc->v, v, sizeof oc->v);
    cross3(u, v, oc->n);
    double l = sqrt(dot3(oc->n, oc->n));
    for (int k = 0; k < 3; k++) oc->n[k] /= l;
    oc->uu = dot3(u, u);
    oc->uv = dot3(u, v);
    oc->vv = dot3(v, v);
    oc->det = oc->uu * oc->vv - oc->uv * oc->uv;
    for (int k = 0; k < 3; k++) {
        double a = o[k], b = o[k] + u[k], c = o[k] + v[k], d = o[k] + u[k] + v[k];
        oc->lo[k] = fmin(fmin(a, b), fmin(c, d));
        oc->hi[k] = fmax(fmax(a, b), fmax(c, d));
    }
}

double lx__room_ff_point(const double x[3], const double n[3], const double *p, int nv)
{
    /* Lambert's formula (core/lambert.c) on the vertices seen from x; a point on one of the
     * polygon's edges (whose term is undefined there) is moved 1e-9 of the polygon's size off
     * its tangent plane: the limit from the front */
    double v[LX__POLY_MAX][3], y[3] = {x[0], x[1], x[2]};
    if (nv < 3 || nv > LX__POLY_MAX) return 0;
    for (int pass = 0; pass < 2; pass++) {
        int deg = 0;
        for (int k = 0; k < nv; k++)
            for (int c = 0; c < 3; c++) v[k][c] = p[3 * k + c] - y[c];
        for (int k = 0; k < nv && !pass; k++) {
            const double *a = v[k], *b = v[(k + 1) % nv];
            double c[3];
            cross3(a, b, c);
            if (!(dot3(c, c) > 1e-28 * (dot3(a, a) * dot3(b, b))) && dot3(a, b) < 0) deg = 1;
        }
        if (!deg) break;
        double size = 0;
        for (int k = 1; k < nv; k++)
            for (int c = 0; c < 3; c++) size = fmax(size, fabs(p[3 * k + c] - p[c]));
        for (int c = 0; c < 3; c++) y[c] = x[c] + 1e-9 * size * n[c];
    }
    return lx__polygon_projected((const double(*)[3])v, nv, n) / LX__PI;
}

double lx__room_ff_quad(const double x[3], const double n[3], const double o[3], const double u[3], const double v[3],
                        const double n_poly[3])
{
    double w[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    if (!(dot3(n_poly, w) > 0)) return 0; /* behind the polygon: it sees the other side */
    double p[12];
    for (int c = 0; c < 3; c++) {
        p[c] = o[c];
        p[3 + c] = o[c] + u[c];
        p[6 + c] = o[c] + u[c] + v[c];
        p[9 + c] = o[c] + v[c];
    }
    return lx__room_ff_point(x, n, p, 4);
}

/* 1 when the open segment p + t d, t0 < t < t1, meets the occluder's inside. */
static int hits(const lx__room_occ *oc, const double p[3], const double d[3], double t0, double t1)
{
    if (oc->kind == 0) {
        double tmin = t0, tmax = t1;
        for (int k = 0; k < 3; k++) {
            if (d[k] == 0) {
                if (!(p[k] > oc->lo[k] && p[k] < oc->hi[k])) return 0;
                continue;
            }
            double ta = (oc->lo[k] - p[k]) / d[k], tb = (oc->hi[k] - p[k]) / d[k];
            if (ta > tb) {
                double s = ta;
                ta = tb;
                tb = s;
            }
            if (ta > tmin) tmin = ta;
            if (tb < tmax) tmax = tb;
            if (!(tmin < tmax)) return 0;
        }
        return 1;
    }
    double den = dot3(oc->n, d);
    if (den == 0) return 0;
    double w[3] = {oc->o[0] - p[0], oc->o[1] - p[1], oc->o[2] - p[2]};
    double t = dot3(oc->n, w) / den;
    if (!(t > t0 && t < t1)) return 0;
    double y[3] = {p[0] + t * d[0] - oc->o[0], p[1] + t * d[1] - oc->o[1], p[2] + t * d[2] - oc->o[2]};
    double yu = dot3(y, oc->u), yv = dot3(y, oc->v);
    double s = (yu * oc->vv - yv * oc->uv) / oc->det, r = (yv * oc->uu - yu * oc->uv) / oc->det;
    return s > 0 && s < 1 && r > 0 && r < 1;
}

int lx__room_visible(const lx__room_occ *occ, int n_occ, const double p[3], const double q[3], int skip, int skip2)
{
    double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    for (int k = 0; k < n_occ; k++) {
        if (k == skip || k == skip2) continue;
        if (hits(&occ[k], p, d, 1e-9, 1 - 1e-9)) return 0;
    }
    return 1;
}

int lx__room_bv(const lx__room_occ *occ, int n_occ, const double lo[3], const double hi[3], int skip, int skip2)
{
    for (int k = 0; k < n_occ; k++) {
        if (k == skip || k == skip2) continue;
        const lx__room_occ *oc = &occ[k];
        /* open intervals: a flat occluder (lo = hi on an axis) overlaps when its plane is strictly inside */
        if (lo[0] < oc->hi[0] && oc->lo[0] < hi[0] && lo[1] < oc->hi[1] && oc->lo[1] < hi[1] && lo[2] < oc->hi[2] &&
            oc->lo[2] < hi[2])
            return 1;
    }
    return 0;
}

int lx__room_shaft(const lx__room_occ *occ, int n_occ, const double lo[3], const double hi[3], const double p[3],
                   const double q[3], double r, int skip, int skip2)
{
    double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    for (int k = 0; k < n_occ; k++) {
        if (k == skip || k == skip2) continue;
        const lx__room_occ *oc = &occ[k];
        if (!(lo[0] < oc->hi[0] && oc->lo[0] < hi[0] && lo[1] < oc->hi[1] && oc->lo[1] < hi[1] && lo[2] < oc->hi[2] &&
              oc->lo[2] < hi[2]))
            continue;
        /* the segment against the box grown by r (closed: conservative) */
        double tmin = 0, tmax = 1;
        int meets = 1;
        for (int c = 0; c < 3 && meets; c++) {
            double a = oc->lo[c] - r, b = oc->hi[c] + r;
            if (d[c] == 0) {
                meets = p[c] >= a && p[c] <= b;
                continue;
            }
            double ta = (a - p[c]) / d[c], tb = (b - p[c]) / d[c];
            if (ta > tb) {
                double t = ta;
                ta = tb;
                tb = t;
            }
            if (ta > tmin) tmin = ta;
            if (tb < tmax) tmax = tb;
            meets = tmin <= tmax;
        }
        if (meets) return 1;
    }
    return 0;
}

/* ---- quadrature ---- */

#define GAUSS_MAX 8
static double gx[GAUSS_MAX + 1][GAUSS_MAX], gw[GAUSS_MAX + 1][GAUSS_MAX];
static pthread_once_t gauss_once = PTHREAD_ONCE_INIT;

/* Gauss-Legendre nodes by Newton's method on P_m (the standard recurrence), mapped to [0, 1]. */
static void gauss_init(void)
{
    for (int m = 1; m <= GAUSS_MAX; m++)
        for (int i = 0; i < m; i++) {
            double z = cos(LX__PI * (i + 0.75) / (m + 0.5)), pp = 1;
            for (int it = 0; it < 100; it++) {
                double p1 = 1, p2 = 0;
                for (int j = 1; j <= m; j++) {
                    double p3 = p2;
                    p2 = p1;
                    p1 = ((2 * j - 1) * z * p2 - (j - 1) * p3) / j;
                }
                pp = m * (z * p1 - p2) / (z * z - 1);
                double dz = p1 / pp;
                z -= dz;
                if (fabs(dz) < 1e-16) break;
            }
            gx[m][i] = 0.5 * (1 - z);
            gw[m][i] = 1 / ((1 - z * z) * pp * pp); /* 2 / ((1 - z^2) P'^2), halved for [0, 1] */
        }
}

void lx__room_gauss(int m, const double **x, const double **w)
{
    pthread_once(&gauss_once, gauss_init);
    if (m < 1) m = 1;
    if (m > GAUSS_MAX) m = GAUSS_MAX;
    *x = gx[m];
    *w = gw[m];
}

/* Tanh-sinh nodes on [0, 1] with step h: x_k = (1 + tanh(pi/2 sinh(k h)))/2, |k h| <= 3.6. */
static int tanh_sinh(double h, double *x, double *w, int cap)
{
    int n = 0;
    for (int k = -(int)(3.6 / h); k <= (int)(3.6 / h) && n < cap; k++) {
        double t = k * h, s = 0.5 * LX__PI * sinh(t), e = exp(-2 * fabs(s));
        x[n] = s >= 0 ? 1 / (1 + e) : e / (1 + e); /* (1 + tanh s) / 2 without cancellation */
        double ch = cosh(s);
        w[n] = h * 0.25 * LX__PI * cosh(t) / (ch * ch);
        if (x[n] > 0 && x[n] < 1 && w[n] > 0) n++;
    }
    return n;
}

double lx__room_ff_area(const double o1[3], const double u1[3], const double v1[3], const double n1[3],
                        const double o2[3], const double u2[3], const double v2[3], const double n2[3], double tol)
{
    enum { CAP = 1200 };
    static _Thread_local double x[CAP], w[CAP];
    double prev = NAN, I = 0;
    for (double h = 0.25; h >= 1.0 / 128; h /= 2) {
        int n = tanh_sinh(h, x, w, CAP);
        I = 0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                double p[3];
                for (int c = 0; c < 3; c++) p[c] = o1[c] + x[i] * u1[c] + x[j] * v1[c];
                I += w[i] * w[j] * lx__room_ff_quad(p, n1, o2, u2, v2, n2);
            }
        if (fabs(I - prev) <= tol * fabs(I)) break;
        prev = I;
    }
    return I;
}
