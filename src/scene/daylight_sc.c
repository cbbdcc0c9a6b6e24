/* daylight_sc.c - the direct daylight through a room's openings: the sky and the ground seen
 * through each opening from a point (closed forms for the uniform and overcast skies, adaptive
 * cubature for the others, a hierarchy of visible pieces where occluders may cut it), the sun
 * through them (exact at points, its beam clipped to elements), the light on an opening's outer
 * side, and the glazing's directional transmittance. */
#include "scene/daylight_private.h"

#include <math.h>
#include <string.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* CIE 171:2006 test cases 5.10 and 5.12 (Tregenza & Sharples 1993, algorithm 2.34): 6 mm clear glass,
 * tau(theta) = sum P[j] cos^j(theta), 0.87881 at normal incidence */
static const double P6MM[6] = {-0.028378, 3.156075, -3.058376, -1.428919, 4.014235, -1.775827};

double lx_glazing_transmittance(lx_glazing g, double tau_n, double c)
{
    if (!(c >= 0 && c <= 1)) return 0;
    if (g != LX_GLAZING_CLEAR) return tau_n;
    double p = 0, cj = 1, p1 = 0;
    for (int j = 0; j < 6; j++) p += P6MM[j] * cj, p1 += P6MM[j], cj *= c;
    return p > 0 ? tau_n * p / p1 : 0;
}

/* The glazing of op as sum tau[j] c^j, and where it turns negative. */
void lx__daylight_glazing(lx__dl_open *op, lx_glazing g, double tau_n)
{
    memset(op->tau, 0, sizeof op->tau);
    op->glazing = g;
    op->tau_n = tau_n;
    op->c_neg = 0;
    if (g != LX_GLAZING_CLEAR) {
        op->tau[0] = tau_n;
        op->J = 0;
        return;
    }
    double p1 = 0;
    for (int j = 0; j < 6; j++) p1 += P6MM[j];
    for (int j = 0; j < 6; j++) op->tau[j] = tau_n * P6MM[j] / p1;
    op->J = 5;
    /* the root near grazing: P(0) < 0 < P(0.02), P increasing there (bisection) */
    double a = 0, b = 0.05;
    for (int it = 0; it < 100; it++) {
        double c = 0.5 * (a + b), p = 0, cj = 1;
        for (int j = 0; j < 6; j++) p += P6MM[j] * cj, cj *= c;
        if (p < 0) a = c;
        else b = c;
    }
    op->c_neg = b;
}

static double tau_c(const lx__dl_open *op, double c)
{
    double p = 0, cj = 1;
    for (int j = 0; j <= op->J; j++) p += op->tau[j] * cj, cj *= c;
    return p > 0 ? p : 0;
}

double lx__daylight_sky_L(const lx__daylight *d, const double w[3])
{
    const lx_scene *sc = d->sc;
    if (!(w[2] >= 0)) return 0;
    switch (sc->sky) {
    case LX_SKY_UNIFORM:
    case LX_SKY_OVERCAST: return d->L0 + d->L1 * w[2];
    case LX_SKY_CIE:
    case LX_SKY_PEREZ: return lx_sky_luminance(&sc->sky_model, w);
    case LX_SKY_MAP: return d->map ? lx__scene_sky_map_L(d->map, w) : 0;
    default: return 0;
    }
}

/* ---- rays that leave a room ---- */

/* 1 when the open segment p -> q meets the inside of a room other than `cell`. */
static int rooms_block(const lx_scene *sc, const double p[3], const double q[3], int cell)
{
    double dd[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    for (size_t r = 0; r < sc->n_room; r++) {
        if ((int)r == cell) continue;
        const lx_scene_room *R = &sc->room[r];
        double t0 = 1e-9, t1 = 1 - 1e-9;
        int hit = 1;
        for (int k = 0; k < 3 && hit; k++) {
            if (dd[k] == 0) {
                hit = p[k] > R->min_m[k] && p[k] < R->max_m[k];
                continue;
            }
            double a = (R->min_m[k] - p[k]) / dd[k], b = (R->max_m[k] - p[k]) / dd[k];
            if (a > b) {
                double s = a;
                a = b;
                b = s;
            }
            t0 = fmax(t0, a), t1 = fmin(t1, b);
            hit = t0 < t1;
        }
        if (hit) return 1;
    }
    return 0;
}

/* 1 when the ray from x along dir (any length) to the far distance is clear. */
static int ray_clear(const lx__daylight *d, const double x[3], const double dir[3], int cell, int skip)
{
    double l = sqrt(dot3(dir, dir)), q[3];
    for (int k = 0; k < 3; k++) q[k] = x[k] + dir[k] * (d->far_m / l);
    if (d->n_occ && !lx__room_visible(d->occ, d->n_occ, x, q, skip, -1)) return 0;
    return !rooms_block(d->sc, x, q, cell);
}

int lx__daylight_sun_visible(const lx__daylight *d, const double q[3], int cell, int skip)
{
    return ray_clear(d, q, d->sun, cell, skip);
}

/* ---- the sky and the ground through (a piece of) an opening ---- */

typedef struct sky_arg {
    const lx__daylight *d;
    const lx__dl_open *op;
    const double *n;
    int ground;
    int negative; /* 1: the part the clamp adds to the polynomial, max(0, -tau) */
} sky_arg;

static double sky_g(void *arg, const double w[3])
{
    const sky_arg *A = arg;
    double nw = dot3(A->n, w);
    if (!(nw > 0)) return 0;
    double L = A->ground ? (w[2] <= 0 ? A->d->Lg : 0) : lx__daylight_sky_L(A->d, w);
    double c = dot3(A->op->m, w), t;
    if (A->negative) {
        double p = 0, cj = 1;
        for (int j = 0; j <= A->op->J; j++) p += A->op->tau[j] * cj, cj *= c;
        t = p < 0 ? -p : 0;
    } else t = tau_c(A->op, c);
    return L * t * nw;
}

/* out[0] the sky, out[1] the ground through the parallelogram o + s u + t v of opening op, seen
 * from x with unit normal n. */
static void piece(const lx__daylight *d, const lx__dl_open *op, const double x[3], const double n[3], const double o[3],
                  const double u[3], const double v[3], double out[2], unsigned long long *ev)
{
    static const double z[3] = {0, 0, 1};
    double P[4][3], Q[LX__DL_VMAX][3], S[LX__DL_VMAX][3];
    for (int k = 0; k < 3; k++) {
        P[0][k] = o[k] - x[k];
        P[1][k] = o[k] + u[k] - x[k];
        P[2][k] = o[k] + u[k] + v[k] - x[k];
        P[3][k] = o[k] + v[k] - x[k];
    }
    out[0] = out[1] = 0;
    int nq = lx__dl_clip((const double(*)[3])P, 4, n, 1, Q);
    if (nq < 3) return;
    /* does the glazing polynomial turn negative (within 0.52 deg of grazing) on the polygon? its least
     * cosine is at a vertex (the farthest point of the plane) */
    int poly_ok = 1;
    for (int k = 0; k < nq && op->c_neg > 0; k++)
        if (dot3(op->m, Q[k]) < op->c_neg * sqrt(dot3(Q[k], Q[k]))) poly_ok = 0;
    for (int part = 0; part < 2; part++) {
        if (part == 1 && !(d->Lg > 0)) continue;
        int ns = lx__dl_clip((const double(*)[3])Q, nq, z, part ? -1 : 1, S);
        if (ns < 3) continue;
        double e = 0;
        if (part == 1 || d->closed) {
            /* the polynomial's moments, exact; where it turns negative the clamp's part max(0, -tau)
             * (tiny: |tau| < 0.029 there) added by quadrature to the tolerance of the whole */
            double K[2][LX__DL_JMAX + 1];
            lx__dl_moments((const double(*)[3])S, ns, n, z, op->m, op->J, K);
            for (int j = 0; j <= op->J; j++)
                e += op->tau[j] * (part ? d->Lg * K[0][j] : d->L0 * K[0][j] + d->L1 * K[1][j]);
            if (!poly_ok) {
                sky_arg A = {d, op, n, part, 1};
                e += lx__dl_integrate((const double(*)[3])S, ns, op->m, sky_g, &A, d->tol, d->tol * fabs(e), 10, ev);
            }
        } else {
            sky_arg A = {d, op, n, part, 0};
            e = lx__dl_integrate((const double(*)[3])S, ns, op->m, sky_g, &A, d->tol, 0, 10, ev);
        }
        out[part] = e > 0 ? e : 0;
    }
}

/* The same with visibility: the opening's pieces whose 3 x 3 lattice of rays is clear count whole,
 * those wholly hidden nothing, the others are quartered `levels` deep, the last weighted by their
 * lattice's clear fraction (trapezoid weights); as the rooms' gathers do (lx__room_ff_vis). */
static void piece_vis(const lx__daylight *d, const lx__dl_open *op, const double x[3], const double n[3], int cell,
                      int skip, int levels, double out[2], unsigned long long *ev)
{
    static const double wt[3] = {0.25, 0.5, 0.25};
    struct pc { double o[3], u[3], v[3]; int level; } st[64];
    int top = 1;
    memcpy(st[0].o, op->o, sizeof st[0].o);
    memcpy(st[0].u, op->u, sizeof st[0].u);
    memcpy(st[0].v, op->v, sizeof st[0].v);
    st[0].level = levels;
    out[0] = out[1] = 0;
    while (top > 0) {
        struct pc e = st[--top];
        int seen = 0;
        double frac = 0;
        for (int k = 0; k < 9; k++) {
            int a = k % 3, b = k / 3;
            double dir[3];
            for (int c = 0; c < 3; c++) dir[c] = e.o[c] + 0.5 * a * e.u[c] + 0.5 * b * e.v[c] - x[c];
            if (ray_clear(d, x, dir, cell, skip)) seen++, frac += wt[a] * wt[b];
        }
        if (seen == 0) continue;
        if (seen == 9 || e.level == 0) {
            double s[2];
            piece(d, op, x, n, e.o, e.u, e.v, s, ev);
            double f = seen == 9 ? 1 : frac;
            out[0] += f * s[0], out[1] += f * s[1];
            continue;
        }
        for (int q = 3; q >= 0 && top < 64; q--) {
            struct pc c;
            for (int k = 0; k < 3; k++) {
                c.u[k] = 0.5 * e.u[k];
                c.v[k] = 0.5 * e.v[k];
                c.o[k] = e.o[k] + 0.5 * (q & 1) * e.u[k] + 0.5 * (q >> 1) * e.v[k];
            }
            c.level = e.level - 1;
            st[top++] = c;
        }
    }
}

/* The parameters (s, t) of point y in the plane of o + s u + t v. */
static void params(const double o[3], const double u[3], const double v[3], const double y[3], double *s, double *t)
{
    double w[3] = {y[0] - o[0], y[1] - o[1], y[2] - o[2]};
    double uu = dot3(u, u), vv = dot3(v, v), uv = dot3(u, v), det = uu * vv - uv * uv;
    double wu = dot3(w, u), wv = dot3(w, v);
    *s = (wu * vv - wv * uv) / det;
    *t = (wv * uu - wu * uv) / det;
}

/* The sun through opening op at x (unit normal n): E, or 0 when its ray does not pass. */
static double sun_at(const lx__daylight *d, const lx__dl_open *op, const double x[3], const double n[3], int cell, int skip,
                     int *through)
{
    *through = 0;
    double ms = dot3(op->m, d->sun), h = dot3(op->m, op->o) - dot3(op->m, x);
    if (!(ms > 0) || !(h > 0)) return 0;
    double y[3], s, t;
    for (int k = 0; k < 3; k++) y[k] = x[k] + h / ms * d->sun[k];
    params(op->o, op->u, op->v, y, &s, &t);
    if (!(s >= 0 && s <= 1 && t >= 0 && t <= 1)) return 0;
    *through = 1; /* the ray leaves the room here: no other opening */
    double ns = dot3(n, d->sun);
    if (!(ns > 0) || !lx__daylight_sun_visible(d, x, cell, skip)) return 0;
    return d->sun_lx * tau_c(op, ms) * ns;
}

void lx__daylight_at(const lx__daylight *d, const double x[3], const double n[3], int cell, int skip, int sun, double out[3],
                     lx_counters *cnt)
{
    out[0] = out[1] = out[2] = 0;
    if (cell < 0) return;
    unsigned long long ev = 0;
    for (size_t k = 0; k < d->n_op; k++) {
        const lx__dl_open *op = &d->op[k];
        if (op->room != cell) continue;
        double h = dot3(op->m, op->o) - dot3(op->m, x);
        if (!(h > 1e-9 * op->size_m)) continue; /* in the opening's plane: it sees none of it */
        int front = 0;
        for (int c = 0; c < 4 && !front; c++) {
            double y[3];
            for (int i = 0; i < 3; i++) y[i] = op->o[i] + (c & 1) * op->u[i] + (c >> 1) * op->v[i] - x[i];
            front = dot3(n, y) > 0;
        }
        if (!front) continue;
        cnt->daylight_evaluations++;
        double lo[3], hi[3], sg[2];
        for (int i = 0; i < 3; i++) lo[i] = fmin(x[i], op->lo[i]), hi[i] = fmax(x[i], op->hi[i]);
        double oc[3];
        for (int i = 0; i < 3; i++) oc[i] = op->o[i] + 0.5 * (op->u[i] + op->v[i]);
        int test = op->outside_occ || (d->n_occ && lx__room_shaft(d->occ, d->n_occ, lo, hi, x, oc, 0.5 * op->size_m, skip, -1));
        if (test) piece_vis(d, op, x, n, cell, skip, LX__ROOM_VIS_RECEIVERS, sg, &ev);
        else piece(d, op, x, n, op->o, op->u, op->v, sg, &ev);
        out[0] += sg[0];
        out[1] += sg[1];
    }
    if (sun && d->sun_lx > 0)
        for (size_t k = 0; k < d->n_op; k++) {
            int through = 0;
            if (d->op[k].room != cell) continue;
            out[2] += sun_at(d, &d->op[k], x, n, cell, skip, &through);
            if (through) break;
        }
    (void)ev; /* quadrature nodes: not counted (daylight_evaluations counts the point-opening pairs) */
}

/* ---- the sun's beam on an element ---- */

/* The area of the part of the convex polygon p (points in the plane of e) inside parallelogram e. */
static double clip_area(const lx__room_patch *e, double (*p)[3], int np)
{
    double s[LX__DL_VMAX][2], t[LX__DL_VMAX][2];
    int n = np;
    for (int k = 0; k < n; k++) params(e->o, e->u, e->v, p[k], &s[k][0], &s[k][1]);
    /* clip in parameter space against 0 <= s, t <= 1 */
    for (int side = 0; side < 4; side++) {
        int ax = side / 2, no = 0;
        double lim = side % 2 ? 1 : 0, sg = side % 2 ? -1 : 1;
        for (int k = 0; k < n && n < LX__DL_VMAX - 1; k++) {
            const double *a = s[k], *b = s[(k + 1) % n];
            double da = sg * (a[ax] - lim), db = sg * (b[ax] - lim);
            if (da >= 0) t[no][0] = a[0], t[no][1] = a[1], no++;
            if ((da > 0 && db < 0) || (da < 0 && db > 0)) {
                double f = da / (da - db);
                t[no][0] = a[0] + f * (b[0] - a[0]), t[no][1] = a[1] + f * (b[1] - a[1]), no++;
            }
        }
        n = no;
        memcpy(s, t, sizeof s);
        if (n < 3) return 0;
    }
    double a2 = 0;
    for (int k = 0; k < n; k++) a2 += s[k][0] * s[(k + 1) % n][1] - s[(k + 1) % n][0] * s[k][1];
    return 0.5 * fabs(a2) * e->area_m2;
}

double lx__daylight_sun_flux(const lx__daylight *d, const lx__room_patch *e, int order)
{
    if (!(d->sun_lx > 0)) return 0;
    double ns = dot3(e->n, d->sun);
    if (!(ns > 0)) return 0;
    double flux = 0;
    for (size_t k = 0; k < d->n_op; k++) {
        const lx__dl_open *op = &d->op[k];
        double ms = dot3(op->m, d->sun);
        if (op->room != e->cell || !(ms > 0)) continue;
        double lo[3], hi[3];
        for (int i = 0; i < 3; i++) lo[i] = fmin(e->lo[i], op->lo[i]), hi[i] = fmax(e->hi[i], op->hi[i]);
        double oc[3];
        for (int i = 0; i < 3; i++) oc[i] = op->o[i] + 0.5 * (op->u[i] + op->v[i]);
        int test = op->outside_occ ||
                   (d->n_occ && lx__room_shaft(d->occ, d->n_occ, lo, hi, e->c, oc, fmax(e->rad, 0.5 * op->size_m), e->occluder, -1));
        if (!test) {
            /* the opening's corners carried along -s onto the element's plane */
            double p[4][3];
            int ok = 1;
            for (int c = 0; c < 4; c++) {
                double y[3];
                for (int i = 0; i < 3; i++) y[i] = op->o[i] + ((c == 1 || c == 2) ? op->u[i] : 0) + (c >= 2 ? op->v[i] : 0);
                double w[3] = {y[0] - e->o[0], y[1] - e->o[1], y[2] - e->o[2]}, t = dot3(e->n, w) / ns;
                if (t < -1e-9 * op->size_m) ok = 0;
                for (int i = 0; i < 3; i++) p[c][i] = y[i] - t * d->sun[i];
            }
            if (ok) flux += d->sun_lx * tau_c(op, ms) * ns * clip_area(e, p, 4);
            continue;
        }
        const double *gx, *gw;
        lx__room_gauss(order, &gx, &gw);
        for (int a = 0; a < order; a++)
            for (int b = 0; b < order; b++) {
                double x[3];
                int through = 0;
                for (int i = 0; i < 3; i++) x[i] = e->o[i] + gx[a] * e->u[i] + gx[b] * e->v[i];
                flux += gw[a] * gw[b] * e->area_m2 * sun_at(d, op, x, e->n, e->cell, e->occluder, &through);
            }
    }
    return flux;
}

/* ---- the light on an opening's outer side ---- */

double lx__daylight_opening_E(const lx__daylight *d, size_t k)
{
    enum { NC = 64, NP = 64 };
    const lx__dl_open *op = &d->op[k];
    double xc[NC], wc[NC], xp[NP], wp[NP], a[3], b[3];
    lx__gauss_legendre(NC, xc, wc);
    lx__gauss_legendre(NP, xp, wp);
    /* a frame about the outward normal m */
    const double *m = op->m;
    double t[3] = {fabs(m[0]) < 0.9 ? 1 : 0, fabs(m[0]) < 0.9 ? 0 : 1, 0};
    a[0] = t[1] * m[2] - t[2] * m[1], a[1] = t[2] * m[0] - t[0] * m[2], a[2] = t[0] * m[1] - t[1] * m[0];
    double la = sqrt(dot3(a, a));
    for (int i = 0; i < 3; i++) a[i] /= la;
    b[0] = m[1] * a[2] - m[2] * a[1], b[1] = m[2] * a[0] - m[0] * a[2], b[2] = m[0] * a[1] - m[1] * a[0];
    /* theta from m over [0, acos(c_neg)] (the clamped glazing transmits nothing beyond; in theta, not
     * cos(theta), the integrand is smooth at the normal); for each theta the azimuth in arcs of sky and
     * ground: w_z = sin(theta) R cos(phi - ph0) + cos(theta) m_z */
    double t1 = acos(op->c_neg), E = 0, R = hypot(a[2], b[2]), ph0 = atan2(b[2], a[2]);
    for (int i = 0; i < NC; i++) {
        double th = 0.5 * t1 * (xc[i] + 1), wti = 0.5 * t1 * wc[i], c = cos(th), s = sin(th);
        double tc = tau_c(op, c), arcs[3];
        if (!(tc > 0)) continue;
        double r = R * s > 0 ? -c * m[2] / (R * s) : (c * m[2] >= 0 ? -2 : 2);
        int na = 1;
        if (r > -1 && r < 1) {
            double half = acos(r);
            arcs[0] = ph0 - half, arcs[1] = ph0 + half, arcs[2] = ph0 - half + 2 * LX__PI, na = 2;
        } else arcs[0] = 0, arcs[1] = 2 * LX__PI;
        for (int q = 0; q < na; q++) {
            double p0 = arcs[q], p1 = arcs[q + 1], sum = 0;
            for (int j = 0; j < NP; j++) {
                double ph = p0 + 0.5 * (p1 - p0) * (xp[j] + 1), w[3];
                for (int l = 0; l < 3; l++) w[l] = s * (cos(ph) * a[l] + sin(ph) * b[l]) + c * m[l];
                sum += wp[j] * (w[2] >= 0 ? lx__daylight_sky_L(d, w) : d->Lg);
            }
            E += wti * s * tc * c * 0.5 * (p1 - p0) * sum;
        }
    }
    double ms = dot3(m, d->sun);
    if (d->sun_lx > 0 && ms > 0) E += d->sun_lx * tau_c(op, ms) * ms;
    return E;
}
