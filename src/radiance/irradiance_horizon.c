/* irradiance_horizon.c - the pixels of a lat-long map that the horizon of a normal n crosses: which
 * they are (per row, from the lit half-width of the row's edge parallels) and the exact integral of
 * max(0, n . w) over each, by Stokes' theorem: int_R n . w dw = (1/2) n . (contour integral of
 * w x dw) over the boundary of R = pixel and {n . w >= 0}: the lit parts of the pixel's two
 * meridians and two parallels in closed form, plus half the length of the horizon inside it. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>

/* Crossings within this (radians) of a pixel's corner are taken as at the corner: the horizon
 * crosses there through both edges, and rounding must not lose it from both. */
#define LX__HZ_EPS 1e-12

lx_status lx__hz_init(lx_ctx *ctx, lx__hz *z, int w, int h)
{
    z->w = w;
    z->h = h;
    z->dphi = 2 * LX__PI / w;
    z->dth = LX__PI / h;
    z->ts = lx__alloc_n(2 * ((size_t)w + (size_t)h + 2), sizeof *z->ts);
    if (!z->ts) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    z->tc = z->ts + h + 1;
    z->ps = z->tc + h + 1;
    z->pc = z->ps + w + 1;
    for (int k = 0; k <= h; k++) {
        /* exact at the poles and the equator (sin(pi) is not 0 in double) */
        z->ts[k] = k == 0 || k == h ? 0 : 2 * k == h ? 1 : sin(k * z->dth);
        z->tc[k] = k == 0 ? 1 : k == h ? -1 : 2 * k == h ? 0 : cos(k * z->dth);
    }
    for (int k = 0; k <= w; k++) {
        z->ps[k] = k == 0 || k == w || 2 * k == w ? 0 : sin(k * z->dphi);
        z->pc[k] = k == 0 || k == w ? 1 : 2 * k == w ? -1 : cos(k * z->dphi);
    }
    return LX_OK;
}

void lx__hz_free(lx__hz *z)
{
    lx__free(z->ts);
    z->ts = NULL;
}

double lx__hz_alpha(double nz, double st, double s, double c)
{
    /* on the parallel of sin s, cos c: n . w = A cos(phi - phi_n) + B */
    double A = st * s, B = nz * c;
    if (A <= 0) return B > 0 ? 4 : (B == 0 && st > 0) ? LX__PI / 2 : -1;
    /* near |q| = 1 the horizon touches the parallel: acos would turn the rounding of q (1e-16) into
     * a lit or dark arc of 1e-8 rad that is not there (the true one, if any, holds a sliver of area
     * below 1e-18 sr) */
    double q = -B / A;
    return q <= -1 + 1e-12 ? 4 : q >= 1 - 1e-12 ? -1 : acos(q);
}

void lx__hz_ray_init(lx__hz_ray *r, const double n[3], double *alpha, double *tz, unsigned *stamp, unsigned *gen)
{
    for (int k = 0; k < 3; k++) r->n[k] = n[k];
    r->st = sqrt(n[0] * n[0] + n[1] * n[1]);
    r->phin = atan2(n[1], n[0]);
    if (r->phin < 0) r->phin += 2 * LX__PI;
    r->cphin = r->st > 0 ? n[0] / r->st : 1;
    r->sphin = r->st > 0 ? n[1] / r->st : 0;
    r->alpha = alpha;
    r->tz = tz;
    r->stamp = stamp;
    r->gen = ++*gen; /* the meridian cache is valid where stamp[i] == gen */
}

void lx__hz_ray_rows(lx__hz_ray *r, const lx__hz *z, int k0, int k1)
{
    double *al = r->alpha, *ca = r->alpha + z->h + 1, *sa = ca + z->h + 1;
    for (int k = k0; k <= k1; k++) {
        al[k] = lx__hz_alpha(r->n[2], r->st, z->ts[k], z->tc[k]);
        /* cos and sin of the half-width without trigonometry: cos alpha = -B / A */
        double A = r->st * z->ts[k], q = al[k] >= 0 && al[k] <= LX__PI && A > 0 ? -r->n[2] * z->tc[k] / A : 0;
        ca[k] = q;
        sa[k] = sqrt(fmax(0.0, 1 - q * q));
    }
}

int lx__hz_row(int w, double dphi, double phin, double a0, double a1, long *in_lo, long *in_hi, long *out_lo, long *out_hi)
{
    double ain = fmin(a0, a1), aout = fmax(a0, a1);
    if (aout < 0) return LX__HZ_DARK;
    if (ain >= 4) return LX__HZ_LIT;
    int empty = 1;
    if (ain >= 0) {
        *in_lo = (long)ceil((phin - ain) / dphi);
        *in_hi = (long)floor((phin + ain) / dphi);
        empty = *in_hi <= *in_lo;
    }
    if (aout < 4 && aout <= LX__PI - dphi) {
        *out_lo = (long)floor((phin - aout) / dphi);
        *out_hi = (long)ceil((phin + aout) / dphi);
        if (*out_hi - *out_lo <= w) {
            if (empty) *in_lo = *in_hi = *out_lo;
            return LX__HZ_RANGES;
        }
    }
    /* the horizon turns in this row (or the lit arc nearly closes): every column that is not
     * wholly lit is crossed */
    if (empty) *in_lo = *in_hi = *out_lo = 0, *out_hi = w;
    else *out_lo = *in_lo, *out_hi = *in_lo + w;
    return LX__HZ_RANGES;
}

/* n . (int of w x dw) along the parallel (s, c) for phi from a to b (sines and cosines given). */
static inline double par_term(const double n[3], double s, double c, double a, double sa, double ca, double b,
                              double sb, double cb)
{
    return -s * c * (n[0] * (sb - sa) - n[1] * (cb - ca)) + n[2] * s * s * (b - a);
}

/* The lit part of [pa, pb] (the pixel's columns, sines and cosines sp, cp) on the parallel of edge
 * k: its term, and the horizon's crossings into P. The lit arc is phi_n +- alpha (and its copies
 * 2 pi away); its ends, where the horizon crosses, have cos/sin by the angle-addition formulas. */
static double parallel(const lx__hz *z, const lx__hz_ray *r, int k, double pa, double spa, double cpa, double pb,
                       double spb, double cpb, double P[][3], int *np)
{
    double s = z->ts[k], c = z->tc[k], al = r->alpha[k];
    if (al < 0) return 0;
    if (al >= 4) return par_term(r->n, s, c, pa, spa, cpa, pb, spb, cpb);
    const double *ca = r->alpha + z->h + 1, *sa = ca + z->h + 1;
    /* the ends phi_n -+ alpha */
    double cl = r->cphin * ca[k] + r->sphin * sa[k], sl = r->sphin * ca[k] - r->cphin * sa[k];
    double ch = r->cphin * ca[k] - r->sphin * sa[k], sh = r->sphin * ca[k] + r->cphin * sa[k];
    double sum = 0;
    for (int kk = -1; kk <= 1; kk++) {
        double lo = r->phin + 2 * LX__PI * kk - al, hi = r->phin + 2 * LX__PI * kk + al;
        /* an end within rounding of a corner still counts as a crossing (the meridian may miss it) */
        if (hi < pa - LX__HZ_EPS || lo > pb + LX__HZ_EPS) continue;
        double x = lo, sx = sl, cx = cl, y = hi, sy = sh, cy = ch;
        if (lo >= pa - LX__HZ_EPS && *np < 8) P[*np][0] = s * cl, P[*np][1] = s * sl, P[*np][2] = c, ++*np;
        if (hi <= pb + LX__HZ_EPS && *np < 8) P[*np][0] = s * ch, P[*np][1] = s * sh, P[*np][2] = c, ++*np;
        if (lo < pa) x = pa, sx = spa, cx = cpa;
        if (hi > pb) y = pb, sy = spb, cy = cpb;
        if (y > x) sum += par_term(r->n, s, c, x, sx, cx, y, sy, cy);
    }
    return sum;
}

/* The lit part of the meridian of column edge i for theta in [ta, tb]: its term (oriented from ta
 * to tb) and the horizon's crossing (where A sin t + B cos t = 0: (sin, cos) ~ (-B, A) sign B). */
static double meridian(const lx__hz *z, const lx__hz_ray *r, int i, double ta, double tb, double P[][3], int *np)
{
    double sp = z->ps[i], cp = z->pc[i], A = r->n[0] * cp + r->n[1] * sp, B = r->n[2];
    double lo = ta, hi = tb;
    if (B == 0) {
        if (!(A > 0)) return 0;
    } else {
        double *tc = r->tz + 3 * (size_t)i; /* the zero, its sine and cosine */
        if (r->stamp[i] != r->gen) {
            double t = atan2(-B, A), R = sqrt(A * A + B * B);
            tc[0] = t < 0 ? t + LX__PI : t; /* the zero in (0, pi): lit below it when B > 0, above it when B < 0 */
            tc[1] = fabs(B) / R;
            tc[2] = (B > 0 ? -A : A) / R;
            r->stamp[i] = r->gen;
        }
        double tz = tc[0];
        if (B > 0) hi = fmin(tb, tz);
        else lo = fmax(ta, tz);
        if (tz >= ta - LX__HZ_EPS && tz <= tb + LX__HZ_EPS && *np < 8) {
            P[*np][0] = tc[1] * cp;
            P[*np][1] = tc[1] * sp;
            P[*np][2] = tc[2];
            ++*np;
        }
    }
    return hi > lo ? (-r->n[0] * sp + r->n[1] * cp) * (hi - lo) : 0;
}

/* 1 when the direction d lies in the pixel [ta, tb] x [pa, pb]. */
static int inside(const double d[3], double ta, double tb, double pa, double pb)
{
    double t = atan2(hypot(d[0], d[1]), d[2]), p = atan2(d[1], d[0]);
    if (p < 0) p += 2 * LX__PI;
    return t >= ta && t <= tb && ((p >= pa && p <= pb) || (p + 2 * LX__PI >= pa && p + 2 * LX__PI <= pb));
}

/* The length of the horizon of n inside the pixel, from its crossings of the pixel's edges. */
static double horizon_length(const lx__hz *z, const double n[3], double P[][3], int np, double ta, double tb, double pa,
                             double pb)
{
    /* drop repeated crossings (at a corner the horizon meets two edges) */
    int m = 0;
    for (int k = 0; k < np; k++) {
        int dup = 0;
        for (int q = 0; q < m && !dup; q++)
            dup = fabs(P[k][0] - P[q][0]) + fabs(P[k][1] - P[q][1]) + fabs(P[k][2] - P[q][2]) < 4 * LX__HZ_EPS;
        if (!dup)
            for (int i = 0; i < 3; i++) P[m][i] = P[k][i];
        m += !dup;
    }
    if (m == 0) return 0;
    if (m == 2 && z->w >= 4 && z->h >= 2) { /* a pixel smaller than a quarter sphere: the shorter arc */
        double c[3] = {P[0][1] * P[1][2] - P[0][2] * P[1][1], P[0][2] * P[1][0] - P[0][0] * P[1][2],
                       P[0][0] * P[1][1] - P[0][1] * P[1][0]};
        return atan2(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), P[0][0] * P[1][0] + P[0][1] * P[1][1] + P[0][2] * P[1][2]);
    }
    /* in general: the crossings as angles along the horizon, each arc between two of them inside
     * or outside as its midpoint is */
    double u[3], v[3], ref[3] = {fabs(n[0]) < 0.9 ? 1 : 0, fabs(n[0]) < 0.9 ? 0 : 1, 0};
    u[0] = ref[1] * n[2] - ref[2] * n[1], u[1] = ref[2] * n[0] - ref[0] * n[2], u[2] = ref[0] * n[1] - ref[1] * n[0];
    double lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int i = 0; i < 3; i++) u[i] /= lu;
    v[0] = n[1] * u[2] - n[2] * u[1], v[1] = n[2] * u[0] - n[0] * u[2], v[2] = n[0] * u[1] - n[1] * u[0];
    double psi[8];
    for (int k = 0; k < m; k++) {
        psi[k] = atan2(P[k][0] * v[0] + P[k][1] * v[1] + P[k][2] * v[2], P[k][0] * u[0] + P[k][1] * u[1] + P[k][2] * u[2]);
        for (int q = k; q > 0 && psi[q - 1] > psi[q]; q--) {
            double t = psi[q];
            psi[q] = psi[q - 1];
            psi[q - 1] = t;
        }
    }
    double len = 0;
    for (int k = 0; k < m; k++) {
        double a = psi[k], b = k + 1 < m ? psi[k + 1] : psi[0] + 2 * LX__PI, mid = 0.5 * (a + b);
        double d[3] = {cos(mid) * u[0] + sin(mid) * v[0], cos(mid) * u[1] + sin(mid) * v[1], cos(mid) * u[2] + sin(mid) * v[2]};
        if (inside(d, ta, tb, pa, pb)) len += b - a;
    }
    return len;
}

/* The range of n . w over the pixel (its boundary, and +-1 where n or -n lies inside). */
static void pixel_range(const lx__hz *z, const lx__hz_ray *r, int j, int i, double *lo, double *hi)
{
    const double *n = r->n;
    double ta = j * z->dth, tb = (j + 1) * z->dth, pa = i * z->dphi, pb = (i + 1) * z->dphi;
    double mn = INFINITY, mx = -INFINITY;
    for (int e = 0; e < 2; e++) {
        double s = z->ts[j + e], c = z->tc[j + e];
        for (int f = 0; f < 2; f++) { /* the corners */
            double v = r->st * s * (z->pc[i + f] * r->cphin + z->ps[i + f] * r->sphin) + n[2] * c;
            mn = fmin(mn, v), mx = fmax(mx, v);
        }
        for (int k = -1; k <= 2; k++) { /* the parallels' extremes at phi_n (max) and phi_n + pi (min) */
            double ph = r->phin + LX__PI * k;
            if (ph > pa && ph < pb) {
                double v = (k & 1 ? -1 : 1) * r->st * s + n[2] * c;
                mn = fmin(mn, v), mx = fmax(mx, v);
            }
        }
        /* the meridians' extremes, where tan t = A / B */
        double cp = z->pc[i + e], sp = z->ps[i + e], A = n[0] * cp + n[1] * sp, B = n[2];
        double te = atan2(A, B);
        for (int k = -1; k <= 1; k++) {
            double t = te + LX__PI * k;
            if (t > ta && t < tb) {
                double v = A * sin(t) + B * cos(t);
                mn = fmin(mn, v), mx = fmax(mx, v);
            }
        }
    }
    double dn[3] = {n[0], n[1], n[2]}, dm[3] = {-n[0], -n[1], -n[2]};
    if (inside(dn, ta, tb, pa, pb)) mx = 1;
    if (inside(dm, ta, tb, pa, pb)) mn = -1;
    *lo = mn;
    *hi = mx;
}

double lx__hz_pixel(const lx__hz *z, const lx__llgeom *g, const lx__hz_ray *r, int j, int i, int check)
{
    const double *n = r->n;
    if (check) { /* rows the classification cannot vouch for: wholly lit or dark pixels first */
        double lo, hi;
        pixel_range(z, r, j, i, &lo, &hi);
        if (hi <= 0) return 0;
        if (lo >= 0) return g->row_s2[j] * (n[0] * g->col_gx[i] + n[1] * g->col_gy[i]) + n[2] * g->row_sc[j] * g->dphi;
    }
    double ta = j * z->dth, tb = (j + 1) * z->dth, pa = i * z->dphi, pb = (i + 1) * z->dphi;
    double P[8][3], sum = 0;
    int np = 0;
    /* the boundary, counterclockwise seen from outside (in (theta, phi): phi = pa from ta to tb,
     * theta = tb from pa to pb, phi = pb back to ta, theta = ta back to pa) */
    sum += meridian(z, r, i, ta, tb, P, &np);
    sum += parallel(z, r, j + 1, pa, z->ps[i], z->pc[i], pb, z->ps[i + 1], z->pc[i + 1], P, &np);
    sum -= meridian(z, r, i + 1, ta, tb, P, &np);
    sum -= parallel(z, r, j, pa, z->ps[i], z->pc[i], pb, z->ps[i + 1], z->pc[i + 1], P, &np);
    double v = 0.5 * (sum + horizon_length(z, n, P, np, ta, tb, pa, pb));
    return v > 0 ? v : 0;
}

/* ---- the exact sums: brute force (the clamped sum corrected) and the horizon rows of fast ---- */

typedef struct fix_job {
    const lx_envmap *map;
    const lx__llgeom *g;
    const lx__hz *z;
    const double *dirs;
    double *out;
    double *alpha; /* per thread: h + 1 */
} fix_job;

/* e[c] += the map's channel c weighted by the exact integral minus the clamped moment, over the
 * pixels of row j that the horizon crosses (or every pixel of an EACH row). */
static void fix_row(const fix_job *J, const lx__hz_ray *r, int j, double *e)
{
    const lx__hz *z = J->z;
    const lx__llgeom *g = J->g;
    const double *n = r->n;
    int W = z->w, C = J->map->channels;
    long in_lo, in_hi, out_lo, out_hi;
    int kind = lx__hz_row(W, z->dphi, r->phin, r->alpha[j], r->alpha[j + 1], &in_lo, &in_hi, &out_lo, &out_hi);
    if (kind == LX__HZ_DARK || kind == LX__HZ_LIT) return;
    const float *row = J->map->data + (size_t)j * W * C;
    double a = g->row_s2[j], b = n[2] * g->row_sc[j] * g->dphi;
    for (int part = 0; part < 2; part++)
        for (long k = part ? in_hi : out_lo, k1 = part ? out_hi : in_lo; k < k1; k++) {
            int i = (int)(((k % W) + W) % W);
            double m = a * (n[0] * g->col_gx[i] + n[1] * g->col_gy[i]) + b;
            double d = lx__hz_pixel(z, g, r, j, i, r->st == 0) - (m > 0 ? m : 0);
            if (d != 0)
                for (int c = 0; c < C; c++) e[c] += d * row[(size_t)i * C + c];
        }
}

static void fix_outputs(void *arg, long o0, long o1, int t)
{
    fix_job *J = arg;
    const lx__hz *z = J->z;
    double *al = J->alpha + (size_t)t * LX__HZ_RAY_SCRATCH(z->w, z->h), *tz = al + 3 * (z->h + 1);
    unsigned *stamp = (unsigned *)(tz + 3 * (z->w + 1)), gen = 0;
    for (int i = 0; i <= z->w; i++) stamp[i] = 0;
    int C = J->map->channels;
    for (long o = o0; o < o1; o++) {
        lx__hz_ray r;
        lx__hz_ray_init(&r, J->dirs + 3 * o, al, tz, stamp, &gen);
        lx__hz_ray_rows(&r, z, 0, z->h);
        double e[3] = {0, 0, 0};
        for (int j = 0; j < z->h; j++) fix_row(J, &r, j, e);
        for (int c = 0; c < C; c++) J->out[o * C + c] += e[c];
    }
}

lx_status lx__irr_horizon_fix(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads, double *out)
{
    lx__llgeom g;
    lx__hz z;
    lx_status st = lx__llgeom_init(ctx, &g, map->width, map->height);
    if (st) return st;
    if ((st = lx__hz_init(ctx, &z, map->width, map->height))) {
        lx__llgeom_free(&g);
        return st;
    }
    int nt = lx__threads(threads, (long)n_dirs);
    double *alpha = lx__alloc_n((size_t)nt * LX__HZ_RAY_SCRATCH(map->width, map->height), sizeof *alpha);
    if (!alpha) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    fix_job J = {map, &g, &z, dirs, out, alpha};
    if (!st) st = lx__parallel_for(ctx, nt, (long)n_dirs, fix_outputs, &J);
    lx__free(alpha);
    lx__hz_free(&z);
    lx__llgeom_free(&g);
    return st;
}

lx_status lx__irr_rows_exact(lx_ctx *ctx, int w, int h, const double *L, int rows, const double n[3], double *sum)
{
    lx__llgeom g;
    lx__hz z;
    lx_status st = lx__llgeom_init(ctx, &g, w, h);
    if (st) return st;
    if ((st = lx__hz_init(ctx, &z, w, h))) {
        lx__llgeom_free(&g);
        return st;
    }
    double *al = lx__alloc_n(LX__HZ_RAY_SCRATCH(w, h), sizeof *al);
    unsigned char *crossed = lx__alloc((size_t)w);
    if (!al || !crossed) {
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    } else {
        double *tz = al + 3 * ((size_t)h + 1);
        unsigned *stamp = (unsigned *)(tz + 3 * ((size_t)w + 1)), gen = 0;
        for (int i = 0; i <= w; i++) stamp[i] = 0;
        lx__hz_ray r;
        lx__hz_ray_init(&r, n, al, tz, stamp, &gen);
        lx__hz_ray_rows(&r, &z, 0, h);
        double s = 0;
        for (int j = 0; j < rows && j < h; j++) {
            long in_lo = 0, in_hi = 0, out_lo = 0, out_hi = 0;
            int kind = lx__hz_row(w, z.dphi, r.phin, al[j], al[j + 1], &in_lo, &in_hi, &out_lo, &out_hi);
            if (kind == LX__HZ_DARK) continue;
            for (int i = 0; i < w; i++) crossed[i] = 0;
            if (kind == LX__HZ_RANGES)
                for (int part = 0; part < 2; part++)
                    for (long k = part ? in_hi : out_lo, k1 = part ? out_hi : in_lo; k < k1; k++) crossed[((k % w) + w) % w] = 1;
            double a = g.row_s2[j], b = n[2] * g.row_sc[j] * g.dphi;
            for (int i = 0; i < w; i++) {
                double v = a * (n[0] * g.col_gx[i] + n[1] * g.col_gy[i]) + b; /* n . the pixel's first moment */
                if (crossed[i]) v = lx__hz_pixel(&z, &g, &r, j, i, r.st == 0);
                if (v > 0) s += L[(size_t)j * w + i] * v;
            }
        }
        *sum = s;
    }
    lx__free(al);
    lx__free(crossed);
    lx__hz_free(&z);
    lx__llgeom_free(&g);
    return st;
}
