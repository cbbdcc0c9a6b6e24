/* area_exact.c - the illuminance from a Lambertian rectangle or disk on a receiver of any
 * orientation, without subdividing it: Lambert's contour form of the projected solid angle,
 * E = (L / 2) n . (contour integral of (v x dv) / |v|^2) over the boundary of the part of the
 * source above the receiver's horizon (v from the receiver to the boundary). A polygon's straight
 * edges have it in closed form; the circle's arc is integrated by adaptive Gauss-Kronrod. */
#include "lighting/lighting_private.h"

#include <math.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

double lx__lambert_rect_E(double L, const double c[3], const double ex[3], const double ey[3], const double m[3],
                          double w, double l, const double q[3], const double n[3])
{
    double cq[3] = {c[0] - q[0], c[1] - q[1], c[2] - q[2]};
    if (!(dot3(m, cq) < 0)) return 0; /* the receiver is behind the emitter's plane (or in it) */
    /* the corners as vectors from the receiver; lx__polygon_projected clips them to its horizon */
    static const int sx[4] = {1, -1, -1, 1}, sy[4] = {1, 1, -1, -1};
    double v[4][3];
    for (int k = 0; k < 4; k++)
        for (int i = 0; i < 3; i++) v[k][i] = cq[i] + 0.5 * (sx[k] * w * ex[i] + sy[k] * l * ey[i]);
    return L * lx__polygon_projected((const double(*)[3])v, 4, n);
}

/* ---- the disk ---- */

typedef struct disk_arg {
    double cq[3], u[3], v[3], n[3]; /* centre - receiver, R ex, R ey, the receiver normal */
    long evals;
    double fmax; /* the largest |integrand| seen */
} disk_arg;

/* n . (v x dv/dphi) / |v|^2 on the rim at phi. */
static double rim_f(disk_arg *A, double phi)
{
    double cp = cos(phi), sp = sin(phi), p[3], t[3], x[3];
    for (int i = 0; i < 3; i++) {
        p[i] = A->cq[i] + cp * A->u[i] + sp * A->v[i];
        t[i] = -sp * A->u[i] + cp * A->v[i];
    }
    cross3(p, t, x);
    A->evals++;
    double f = dot3(A->n, x) / dot3(p, p);
    if (fabs(f) > A->fmax) A->fmax = fabs(f);
    return f;
}

static const double gk_x[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                               0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                               0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                               0.207784955007898467600689403773245, 0.0};
static const double gk_wk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double gk_wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

static double gk15(disk_arg *A, double a, double b, double *err)
{
    double c = 0.5 * (a + b), h = 0.5 * (b - a), fc = rim_f(A, c);
    double k = fc * gk_wk[7], g = fc * gk_wg[3];
    for (int i = 0; i < 7; i++) {
        double f1 = rim_f(A, c - h * gk_x[i]), f2 = rim_f(A, c + h * gk_x[i]);
        k += gk_wk[i] * (f1 + f2);
        if (i & 1) g += gk_wg[i / 2] * (f1 + f2);
    }
    *err = fabs((k - g) * h);
    return k * h;
}

static double adapt(disk_arg *A, double a, double b, double tol, int depth)
{
    double err, v = gk15(A, a, b, &err);
    if (err <= tol || depth >= 16) return v;
    double m = 0.5 * (a + b);
    return adapt(A, a, m, 0.5 * tol, depth + 1) + adapt(A, m, b, 0.5 * tol, depth + 1);
}

double lx__lambert_disk_E(double L, const double c[3], const double ex[3], const double ey[3], const double m[3],
                          double R, const double q[3], const double n[3], long *evals)
{
    disk_arg A;
    for (int i = 0; i < 3; i++) {
        A.cq[i] = c[i] - q[i];
        A.u[i] = R * ex[i];
        A.v[i] = R * ey[i];
        A.n[i] = n[i];
    }
    A.evals = 0;
    A.fmax = 0;
    if (!(dot3(m, A.cq) < 0)) return 0; /* behind the emitter's plane */
    /* n . v on the rim = a0 + rho cos(phi - phi0): the arc above the receiver's horizon */
    double a0 = dot3(n, A.cq), a1 = dot3(n, A.u), a2 = dot3(n, A.v), rho = hypot(a1, a2);
    double lo = 0, hi = 2 * LX__PI, chord = 0;
    if (a0 <= -rho) return 0; /* the whole disk below the horizon */
    if (a0 < rho) {
        double phi0 = atan2(a2, a1), beta = acos(-a0 / rho);
        lo = phi0 - beta, hi = phi0 + beta;
        /* the chord from the arc's end back to its start lies in the receiver's plane */
        double pe[3], ps[3];
        for (int i = 0; i < 3; i++) {
            pe[i] = A.cq[i] + cos(hi) * A.u[i] + sin(hi) * A.v[i];
            ps[i] = A.cq[i] + cos(lo) * A.u[i] + sin(lo) * A.v[i];
        }
        chord = lx__lambert_edge(pe, ps, n);
    }
    /* tolerance: 1e-14 of a first estimate, but not below the rounding of the integrand's own size
     * (for a distant receiver the contour's terms are larger than their sum by distance / size) */
    double e0, first = gk15(&A, lo, hi, &e0);
    double tol = fmax(1e-14 * fabs(first + chord), 1e-15 * (hi - lo) * A.fmax);
    double arc = adapt(&A, lo, hi, tol > 0 ? tol : 1e-300, 0);
    if (evals) *evals += A.evals;
    return 0.5 * L * fabs(arc + chord);
}
