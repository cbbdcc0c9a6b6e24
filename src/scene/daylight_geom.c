/* daylight_geom.c - the directions of a planar polygon seen from a point: clipping by planes
 * through the viewpoint, the solid angle, the exact moments of (n . w) (z . w)^q (m . w)^j over the
 * spherical polygon (the closed forms of the sky component), and adaptive cubature over it for any
 * other integrand (CIE general and Perez skies, maps, clamped glazing). */
#include "scene/daylight_private.h"

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

#define EDGE_NODES 16
static double ex_[EDGE_NODES], ew_[EDGE_NODES]; /* Gauss-Legendre on [0, 1] */
static double tx_[4], tw_[4];                   /* 4 nodes on [0, 1] for the triangles */
static pthread_once_t nodes_once = PTHREAD_ONCE_INIT;

static void nodes_init(void)
{
    double x[EDGE_NODES], w[EDGE_NODES];
    lx__gauss_legendre(EDGE_NODES, x, w);
    for (int i = 0; i < EDGE_NODES; i++) ex_[i] = 0.5 * (x[i] + 1), ew_[i] = 0.5 * w[i];
    lx__gauss_legendre(4, x, w);
    for (int i = 0; i < 4; i++) tx_[i] = 0.5 * (x[i] + 1), tw_[i] = 0.5 * w[i];
}

int lx__dl_clip(const double (*in)[3], int n, const double a[3], double sign, double (*out)[3])
{
    double d[LX__DL_VMAX];
    if (n < 3 || n > LX__DL_VMAX - 1) return 0;
    for (int k = 0; k < n; k++) d[k] = sign * dot3(a, in[k]);
    int no = 0;
    for (int k = 0; k < n; k++) {
        int k1 = k + 1 < n ? k + 1 : 0;
        if (d[k] >= 0) memcpy(out[no++], in[k], sizeof out[0]);
        if ((d[k] > 0 && d[k1] < 0) || (d[k] < 0 && d[k1] > 0)) {
            double t = d[k] / (d[k] - d[k1]);
            for (int i = 0; i < 3; i++) out[no][i] = in[k][i] + t * (in[k1][i] - in[k][i]);
            no++;
        }
    }
    /* drop repeated vertices (a vertex on the plane is kept once) */
    int m = 0;
    for (int k = 0; k < no; k++) {
        const double *p = out[k], *q = out[m ? m - 1 : no - 1];
        if (m && p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) continue;
        if (m != k) memcpy(out[m], out[k], sizeof out[0]);
        m++;
    }
    if (m > 1 && out[0][0] == out[m - 1][0] && out[0][1] == out[m - 1][1] && out[0][2] == out[m - 1][2]) m--;
    return m >= 3 ? m : 0;
}

double lx__dl_solid_angle(const double (*p)[3], int nv)
{
    double v[LX__DL_VMAX][3], s = 0;
    for (int k = 0; k < nv; k++) {
        double l = sqrt(dot3(p[k], p[k]));
        for (int i = 0; i < 3; i++) v[k][i] = p[k][i] / l;
    }
    for (int k = 1; k + 1 < nv; k++) {
        double c[3];
        cross3(v[k], v[k + 1], c);
        double num = dot3(v[0], c), den = 1 + dot3(v[0], v[k]) + dot3(v[k], v[k + 1]) + dot3(v[k + 1], v[0]);
        s += 2 * atan2(fabs(num), den);
    }
    return s;
}

double lx__dl_area(const double (*p)[3], int nv)
{
    double s[3] = {0, 0, 0};
    for (int k = 1; k + 1 < nv; k++) {
        double a[3], b[3], c[3];
        for (int i = 0; i < 3; i++) a[i] = p[k][i] - p[0][i], b[i] = p[k + 1][i] - p[0][i];
        cross3(a, b, c);
        for (int i = 0; i < 3; i++) s[i] += c[i];
    }
    return 0.5 * sqrt(dot3(s, s));
}

/* The moments by the divergence theorem on the cone C = {r w : 0 <= r <= 1, w in A}: for a
 * homogeneous polynomial P of degree p and a constant vector a, div(a P) = a . grad P gives
 *   integral_A (a . w) P dw = (integral_A a . grad P dw - sum_i (a . N_i) E_i[P]) / (p + 2),
 * N_i the outward unit normal of the cone's side through edge i and E_i[P] the integral of P along
 * the edge's arc (its sector contributes E_i[P] / (p + 2)). With P a product of powers of z . w and
 * m . w this lowers the degree by two at each step, down to the solid angle and Lambert's formula. */
void lx__dl_moments(const double (*p)[3], int nv, const double n[3], const double z[3], const double m[3], int J,
                    double K[2][LX__DL_JMAX + 1])
{
    pthread_once(&nodes_once, nodes_init);
    if (J > LX__DL_JMAX) J = LX__DL_JMAX;
    if (J < 0) J = 0;
    memset(K, 0, 2 * sizeof K[0]);
    if (nv < 3) return;
    double v[LX__DL_VMAX][3], c[3] = {0, 0, 0};
    for (int k = 0; k < nv; k++) {
        double l = sqrt(dot3(p[k], p[k]));
        for (int i = 0; i < 3; i++) v[k][i] = p[k][i] / l, c[i] += v[k][i];
    }
    /* edge sums: Sn[q][j] = sum_i (n . N_i) E_i[(z.w)^q (m.w)^j], Sm likewise with m . N_i; Sz0 =
     * sum_i (z . N_i) Gamma_i */
    double Sn[2][LX__DL_JMAX + 1], Sm[2][LX__DL_JMAX + 1], Sz0 = 0;
    memset(Sn, 0, sizeof Sn);
    memset(Sm, 0, sizeof Sm);
    for (int k = 0; k < nv; k++) {
        const double *a = v[k], *b = v[k + 1 < nv ? k + 1 : 0];
        double cr[3];
        cross3(a, b, cr);
        double s = sqrt(dot3(cr, cr));
        if (!(s > 1e-300)) continue;
        double G = atan2(s, dot3(a, b)), N[3], e2[3];
        cross3(cr, a, e2); /* (a x b) x a = b - (a . b) a, of length s */
        for (int i = 0; i < 3; i++) N[i] = cr[i] / s, e2[i] /= s;
        if (dot3(N, c) > 0)
            for (int i = 0; i < 3; i++) N[i] = -N[i];
        double nN = dot3(n, N), mN = dot3(m, N);
        Sz0 += dot3(z, N) * G;
        /* along the arc w(phi) = cos(phi) a + sin(phi) e2: z . w and m . w are A cos + B sin */
        double za = dot3(z, a), ze = dot3(z, e2), ma = dot3(m, a), me = dot3(m, e2);
        double E[2][LX__DL_JMAX + 1];
        memset(E, 0, sizeof E);
        for (int g = 0; g < EDGE_NODES; g++) {
            double ph = G * ex_[g], wt = G * ew_[g], cs = cos(ph), sn = sin(ph);
            double zw = za * cs + ze * sn, mw = ma * cs + me * sn, pw = wt;
            for (int j = 0; j <= J; j++) {
                E[0][j] += pw;
                E[1][j] += pw * zw;
                pw *= mw;
            }
        }
        for (int q = 0; q < 2; q++)
            for (int j = 0; j <= J; j++) Sn[q][j] += nN * E[q][j], Sm[q][j] += mN * E[q][j];
    }
    /* T[q][j] = integral_A (z . w)^q (m . w)^j dw */
    double T[2][LX__DL_JMAX + 1];
    double mz = dot3(m, z), mm = dot3(m, m), nz = dot3(n, z), nm = dot3(n, m);
    T[0][0] = lx__dl_solid_angle(p, nv);
    T[1][0] = -0.5 * Sz0;
    for (int j = 1; j <= J; j++)
        for (int q = 0; q < 2; q++) {
            /* leading factor m . w, P = (z . w)^q (m . w)^(j-1) of degree q + j - 1 */
            double t = -Sm[q][j - 1];
            if (q) t += mz * T[0][j - 1];
            if (j >= 2) t += (j - 1) * mm * T[q][j - 2];
            T[q][j] = t / (q + j + 1);
        }
    for (int q = 0; q < 2; q++)
        for (int j = 0; j <= J; j++) {
            double t = -Sn[q][j];
            if (q) t += nz * T[0][j];
            if (j) t += j * nm * T[q][j - 1];
            K[q][j] = t / (q + j + 2);
        }
}

/* ---- adaptive cubature over the polygon's triangles ---- */

typedef struct cub {
    const double *m;
    lx__dl_fn g;
    void *arg;
    double tol_abs;
    int max_depth;
    unsigned long long evals;
} cub;

/* The collapsed-Gauss rule on triangle a, b, c (points relative to the viewpoint): y = a + u (b - a)
 * + u t (c - b), dA = 2 area u du dt, dw = (m . y) / |y|^3 dA. */
static double tri_rule(cub *C, const double a[3], const double b[3], const double c[3])
{
    double ab[3], bc[3], cr[3];
    for (int i = 0; i < 3; i++) ab[i] = b[i] - a[i], bc[i] = c[i] - b[i];
    cross3(ab, bc, cr);
    double area2 = sqrt(dot3(cr, cr)), s = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double u = tx_[i], t = tx_[j], y[3];
            for (int k = 0; k < 3; k++) y[k] = a[k] + u * ab[k] + u * t * bc[k];
            double r2 = dot3(y, y), r = sqrt(r2), w[3] = {y[0] / r, y[1] / r, y[2] / r};
            double h = dot3(C->m, y);
            s += tw_[i] * tw_[j] * u * C->g(C->arg, w) * h / (r2 * r);
        }
    C->evals += 16;
    return s * area2;
}

static double tri_adapt(cub *C, const double a[3], const double b[3], const double c[3], double whole, int depth)
{
    double ab[3], bc[3], ca[3];
    for (int i = 0; i < 3; i++) ab[i] = 0.5 * (a[i] + b[i]), bc[i] = 0.5 * (b[i] + c[i]), ca[i] = 0.5 * (c[i] + a[i]);
    double q[4] = {tri_rule(C, a, ab, ca), tri_rule(C, ab, b, bc), tri_rule(C, ca, bc, c), tri_rule(C, ab, bc, ca)};
    double sum = q[0] + q[1] + q[2] + q[3];
    if (depth >= C->max_depth || fabs(sum - whole) <= C->tol_abs) return sum + (sum - whole) / 255.0; /* degree 7: 2^8 - 1 */
    double save = C->tol_abs, r;
    C->tol_abs = 0.5 * save; /* four children share the parent's tolerance (halved: their errors partly cancel) */
    r = tri_adapt(C, a, ab, ca, q[0], depth + 1) + tri_adapt(C, ab, b, bc, q[1], depth + 1) +
        tri_adapt(C, ca, bc, c, q[2], depth + 1) + tri_adapt(C, ab, bc, ca, q[3], depth + 1);
    C->tol_abs = save;
    return r;
}

double lx__dl_integrate(const double (*p)[3], int nv, const double m[3], lx__dl_fn g, void *arg, double tol, double abs_tol,
                        int max_depth, unsigned long long *evals)
{
    pthread_once(&nodes_once, nodes_init);
    if (nv < 3) return 0;
    cub C = {m, g, arg, 0, max_depth, 0};
    double q[LX__DL_VMAX], whole = 0;
    for (int k = 1; k + 1 < nv; k++) whole += q[k] = tri_rule(&C, p[0], p[k], p[k + 1]);
    /* the tolerance of the whole, shared by the fan's triangles */
    C.tol_abs = fmax(fmax(tol * fabs(whole), abs_tol), 1e-300) / (nv - 2);
    double s = 0;
    for (int k = 1; k + 1 < nv; k++) s += tri_adapt(&C, p[0], p[k], p[k + 1], q[k], 1);
    if (evals) *evals += C.evals;
    return s;
}
