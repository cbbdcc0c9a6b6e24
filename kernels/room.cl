/* room.cl - the interreflection solve's data-parallel parts, in double (cl_khr_fp64): the
 * form-factor matrix (one work-item per shooting patch i and receiving patch j) and the gather
 * (one work-item per point). CPU twins: ff_pair, lx__room_gather_cpu (src/scene/room_solve.c) and
 * the geometry of src/scene/room_geom.c, the same operations in the same order, contraction off.
 * Patch records of 21 doubles: o[3] u[3] v[3] n[3] lo[3] hi[3] c[3], and their radii apart; ints: cell,
 * occluder, face, shoot.
 * Occluder records of 22 doubles: lo[3] hi[3] o[3] u[3] v[3] n[3] uu uv vv det; ints: kind.
 * gauss: nodes then weights of orders 1..8 on [0, 1], 8 per order. */
#if LX_FP64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#pragma OPENCL FP_CONTRACT OFF

#define RP 21 /* o u v n lo hi, c (18..20); rad is passed apart */
#define RO 22

static double r_dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void r_cross(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* lx__lambert_edge and lx__polygon_projected (src/core/lambert.c) */
static double r_edge(const double *a, const double *b, const double *n)
{
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    double s = sqrt(r_dot(c, c));
    if (!(s > 0)) return 0;
    return atan2(s, r_dot(a, b)) * r_dot(n, c) / s;
}

static double r_projected(const double *v, int nv, const double *n)
{
    double out[27], d[8];
    for (int k = 0; k < nv; k++) d[k] = r_dot(n, v + 3 * k);
    int no = 0;
    for (int k = 0; k < nv; k++) {
        int k1 = k + 1 < nv ? k + 1 : 0;
        if (d[k] >= 0) {
            for (int i = 0; i < 3; i++) out[3 * no + i] = v[3 * k + i];
            no++;
        }
        if ((d[k] > 0 && d[k1] < 0) || (d[k] < 0 && d[k1] > 0)) {
            double t = d[k] / (d[k] - d[k1]);
            for (int i = 0; i < 3; i++) out[3 * no + i] = v[3 * k + i] + t * (v[3 * k1 + i] - v[3 * k + i]);
            no++;
        }
    }
    if (no < 3) return 0;
    double sum = 0;
    for (int k = 0; k < no; k++) sum += r_edge(out + 3 * k, out + 3 * (k + 1 < no ? k + 1 : 0), n);
    return 0.5 * fabs(sum);
}

/* lx__room_ff_point */
static double r_ff_point(const double *x, const double *n, const double *p, int nv)
{
    double v[24], y[3] = {x[0], x[1], x[2]};
    for (int pass = 0; pass < 2; pass++) {
        int deg = 0;
        for (int k = 0; k < nv; k++)
            for (int c = 0; c < 3; c++) v[3 * k + c] = p[3 * k + c] - y[c];
        for (int k = 0; k < nv && !pass; k++) {
            const double *a = v + 3 * k, *b = v + 3 * ((k + 1) % nv);
            double c[3];
            r_cross(a, b, c);
            if (!(r_dot(c, c) > 1e-28 * (r_dot(a, a) * r_dot(b, b))) && r_dot(a, b) < 0) deg = 1;
        }
        if (!deg) break;
        double size = 0;
        for (int k = 1; k < nv; k++)
            for (int c = 0; c < 3; c++) size = fmax(size, fabs(p[3 * k + c] - p[c]));
        for (int c = 0; c < 3; c++) y[c] = x[c] + 1e-9 * size * n[c];
    }
    return r_projected(v, nv, n) / 3.14159265358979323846;
}

/* pr: a patch record (o, u, v, n_poly at 0, 3, 6, 9) */
static double r_ff_quad(const double *x, const double *n, const double *pr)
{
    double o[3] = {pr[0], pr[1], pr[2]}, u[3] = {pr[3], pr[4], pr[5]}, v[3] = {pr[6], pr[7], pr[8]};
    double np[3] = {pr[9], pr[10], pr[11]};
    double w[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    if (!(r_dot(np, w) > 0)) return 0;
    double p[12];
    for (int c = 0; c < 3; c++) {
        p[c] = o[c];
        p[3 + c] = o[c] + u[c];
        p[6 + c] = o[c] + u[c] + v[c];
        p[9 + c] = o[c] + v[c];
    }
    return r_ff_point(x, n, p, 4);
}

static int r_hits(__global const double *oc, int kind, const double *p, const double *d, double t0, double t1)
{
    if (kind == 0) {
        double tmin = t0, tmax = t1;
        for (int k = 0; k < 3; k++) {
            double lo = oc[k], hi = oc[3 + k];
            if (d[k] == 0) {
                if (!(p[k] > lo && p[k] < hi)) return 0;
                continue;
            }
            double ta = (lo - p[k]) / d[k], tb = (hi - p[k]) / d[k];
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
    double n[3] = {oc[15], oc[16], oc[17]}, ou[3] = {oc[9], oc[10], oc[11]}, ov[3] = {oc[12], oc[13], oc[14]};
    double den = r_dot(n, d);
    if (den == 0) return 0;
    double w[3] = {oc[6] - p[0], oc[7] - p[1], oc[8] - p[2]};
    double t = r_dot(n, w) / den;
    if (!(t > t0 && t < t1)) return 0;
    double y[3] = {p[0] + t * d[0] - oc[6], p[1] + t * d[1] - oc[7], p[2] + t * d[2] - oc[8]};
    double yu = r_dot(y, ou), yv = r_dot(y, ov);
    double uu = oc[18], uv = oc[19], vv = oc[20], det = oc[21];
    double s = (yu * vv - yv * uv) / det, r = (yv * uu - yu * uv) / det;
    return s > 0 && s < 1 && r > 0 && r < 1;
}

static int r_visible(__global const double *occ, __global const int *okind, int nocc, const double *p, const double *q,
                     int skip, int skip2)
{
    double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    for (int k = 0; k < nocc; k++) {
        if (k == skip || k == skip2) continue;
        if (r_hits(occ + RO * k, okind[k], p, d, 1e-9, 1 - 1e-9)) return 0;
    }
    return 1;
}

static int r_vis9(__global const double *occ, __global const int *okind, int nocc, const double *x, const double *o,
                  const double *u, const double *v, int skip, int skip2, double *w)
{
    const double wt[3] = {0.25, 0.5, 0.25};
    int seen = 0;
    double f = 0;
    for (int k = 0; k < 9; k++) {
        double y[3];
        int a = k % 3, b = k / 3;
        for (int c = 0; c < 3; c++) y[c] = o[c] + 0.5 * a * u[c] + 0.5 * b * v[c];
        if (r_visible(occ, okind, nocc, x, y, skip, skip2)) {
            seen++;
            f += wt[a] * wt[b];
        }
    }
    *w = f;
    return seen;
}

/* pj: a patch record; the same depth-first subdivision as lx__room_ff_vis */
static int r_shaft(__global const double *occ, int nocc, const double *lo, const double *hi, const double *p,
                   const double *q, double r, int skip, int skip2)
{
    double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    for (int k = 0; k < nocc; k++) {
        if (k == skip || k == skip2) continue;
        __global const double *oc = occ + RO * k;
        if (!(lo[0] < oc[3] && oc[0] < hi[0] && lo[1] < oc[4] && oc[1] < hi[1] && lo[2] < oc[5] && oc[2] < hi[2]))
            continue;
        double tmin = 0, tmax = 1;
        int meets = 1;
        for (int c = 0; c < 3 && meets; c++) {
            double a = oc[c] - r, b = oc[3 + c] + r;
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

static double r_ff_vis(__global const double *occ, __global const int *okind, int nocc, const double *x,
                       const double *n, const double *pj, int skip, int skip2, double f, int levels)
{
    double so[16][3], su[16][3], sv[16][3], sf[16];
    int sl[16], top = 1;
    double total = 0, np[3] = {pj[9], pj[10], pj[11]};
    for (int c = 0; c < 3; c++) so[0][c] = pj[c], su[0][c] = pj[3 + c], sv[0][c] = pj[6 + c];
    sf[0] = f;
    sl[0] = levels;
    while (top > 0) {
        top--;
        double eo[3] = {so[top][0], so[top][1], so[top][2]}, eu[3] = {su[top][0], su[top][1], su[top][2]};
        double ev[3] = {sv[top][0], sv[top][1], sv[top][2]}, ef = sf[top], w;
        int el = sl[top];
        int k = r_vis9(occ, okind, nocc, x, eo, eu, ev, skip, skip2, &w);
        if (k == 9) total += ef;
        if (k == 9 || k == 0) continue;
        if (el == 0) {
            total += w * ef;
            continue;
        }
        for (int a = 3; a >= 0; a--) {
            double qo[3], qu[3], qv[3];
            for (int c = 0; c < 3; c++) {
                qu[c] = 0.5 * eu[c];
                qv[c] = 0.5 * ev[c];
                qo[c] = eo[c] + 0.5 * (a & 1) * eu[c] + 0.5 * (a >> 1) * ev[c];
            }
            double rec[12] = {qo[0], qo[1], qo[2], qu[0], qu[1], qu[2], qv[0], qv[1], qv[2], np[0], np[1], np[2]};
            double qf = r_ff_quad(x, n, rec);
            if (qf > 0) {
                for (int c = 0; c < 3; c++) so[top][c] = qo[c], su[top][c] = qu[c], sv[top][c] = qv[c];
                sf[top] = qf;
                sl[top] = el - 1;
                top++;
            }
        }
    }
    return total;
}

static void r_load(__global const double *P, uint i, double *pr)
{
    for (int k = 0; k < RP; k++) pr[k] = P[RP * i + k];
}

/* F[i][j] for rows row0 .. row0 + rows - 1 (out: rows x n, row-major). */
__kernel void lx_room_ff(__global const double *P, __global const double *RAD, __global const int *PI, __global const double *occ,
                         __global const int *okind, int nocc, __global const double *gauss, uint n, uint row0,
                         uint rows, __global double *out)
{
    uint r = get_global_id(0), j = get_global_id(1);
    if (r >= rows || j >= n) return;
    uint i = row0 + r;
    double pi[RP], pj[RP];
    r_load(P, i, pi);
    r_load(P, j, pj);
    int ci = PI[4 * i], oi = PI[4 * i + 1], fi = PI[4 * i + 2], shoot = PI[4 * i + 3];
    int cj = PI[4 * j], oj = PI[4 * j + 1], fj = PI[4 * j + 2];
    double s = 0;
    if (ci == cj && fi != fj) {
        double lo[3], hi[3];
        for (int c = 0; c < 3; c++) lo[c] = fmin(pi[12 + c], pj[12 + c]), hi[c] = fmax(pi[15 + c], pj[15 + c]);
        double ci[3] = {pi[18], pi[19], pi[20]}, cj[3] = {pj[18], pj[19], pj[20]};
        int bv = nocc && r_shaft(occ, nocc, lo, hi, ci, cj, fmax(RAD[i], RAD[j]), oi, oj);
        __global const double *gx = gauss + 8 * (shoot - 1), *gw = gauss + 64 + 8 * (shoot - 1);
        double n[3] = {pi[9], pi[10], pi[11]};
        for (int a = 0; a < shoot; a++)
            for (int b = 0; b < shoot; b++) {
                double x[3];
                for (int c = 0; c < 3; c++) x[c] = pi[c] + gx[a] * pi[3 + c] + gx[b] * pi[6 + c];
                double f = r_ff_quad(x, n, pj);
                if (f > 0 && bv) f = r_ff_vis(occ, okind, nocc, x, n, pj, oi, oj, f, 1);
                s += gw[a] * gw[b] * f;
            }
    }
    out[(ulong)r * n + j] = s;
}

/* The illuminance at point i (skip: an occluder that never blocks its rays) from the patches of exitance B. */
__kernel void lx_room_gather(__global const double *P, __global const double *RAD, __global const int *PI, __global const double *occ,
                             __global const int *okind, int nocc, __global const double *B, uint npatch,
                             __global const double *pts, __global const double *nrm, __global const int *cell,
                             __global const int *skip, int levels, uint npts, __global double *out)
{
    uint i = get_global_id(0);
    if (i >= npts) return;
    double x[3] = {pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]}, n[3] = {nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]};
    int ci = cell[i], sk = skip[i];
    double e = 0, pj[RP];
    for (uint j = 0; j < npatch; j++) {
        if (PI[4 * j] != ci || !(B[j] > 0)) continue;
        r_load(P, j, pj);
        double f = r_ff_quad(x, n, pj);
        if (!(f > 0)) continue;
        if (nocc) {
            double lo[3], hi[3];
            for (int c = 0; c < 3; c++) lo[c] = fmin(x[c], pj[12 + c]), hi[c] = fmax(x[c], pj[15 + c]);
            double cj[3] = {pj[18], pj[19], pj[20]};
            if (r_shaft(occ, nocc, lo, hi, x, cj, RAD[j], sk, PI[4 * j + 1]))
                f = r_ff_vis(occ, okind, nocc, x, n, pj, sk, PI[4 * j + 1], f, levels);
        }
        e += B[j] * f;
    }
    out[i] = e;
}

#pragma OPENCL FP_CONTRACT ON
#endif /* LX_FP64 */
