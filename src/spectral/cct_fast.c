/* cct_fast.c - CCT and Duv without exp, for batches: the Planckian locus precomputed once per
 * process at 513 nodes evenly spaced in s = ln T (900 K - 120000 K) with its first three
 * derivatives (exact, cct.c), two quintic Hermite polynomials per interval (the locus P from P, P',
 * P''; its tangent Q = P' from P', P'', P'''), the interval found by bisection on the sign of
 * g(s) = (P(s) - p) . P'(s) at the nodes and the root of (P - p) . Q solved by Newton steps.
 *
 * Why this is the exact answer to rounding: the interpolants differ from Planck's law by less
 * than 2e-16 in uv and 3e-13 relative in the tangent (the tangent has its own polynomial: the
 * derivative of the position's would magnify the node values' rounding noise by 1/h = 107), and
 * for every point within 0.1 of the locus whose foot lies in 900 K - 120000 K, g changes sign
 * exactly once over the exact solver's whole range 500 K - 1e6 K (checked for both observers on
 * 2e5 points: the locus's smallest radius of curvature is 0.100, at 5191 K), so the bracket is
 * the one the exact solver (cct.c) finds. tests/test_cct_fast.c holds it against lx_cct_from_uv. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>

#define FAST_NODES 513 /* 512 intervals: bisection in 9 steps */
#define FAST_INTERVALS (FAST_NODES - 1)
#define LX__CCT_NEWTON 3

typedef struct fast_locus {
    int ok;
    double s0, h;
    double T[FAST_NODES];            /* exp(s0 + k h) */
    double node[FAST_NODES][4];      /* u, v, du/ds, dv/ds: the bisection reads these */
    double poly[FAST_INTERVALS][24]; /* per interval, in tau = (s - s_k) / h, c0..c5 of: u, v, du/ds, dv/ds */
} fast_locus;

static fast_locus locus2, locus10;
static pthread_once_t once2 = PTHREAD_ONCE_INIT, once10 = PTHREAD_ONCE_INIT;

/* The quintic Hermite polynomial on [0, 1] through y0, y1 with slopes d0, d1 and second
 * derivatives e0, e1 (all in tau units), as monomial coefficients c[0..5]. */
static void hermite5(double y0, double d0, double e0, double y1, double d1, double e1, double *c)
{
    double dy = y1 - y0;
    c[0] = y0;
    c[1] = d0;
    c[2] = 0.5 * e0;
    c[3] = 10 * dy - 6 * d0 - 4 * d1 - 0.5 * (3 * e0 - e1);
    c[4] = -15 * dy + 8 * d0 + 7 * d1 + 0.5 * (3 * e0 - 2 * e1);
    c[5] = 6 * dy - 3 * d0 - 3 * d1 - 0.5 * (e0 - e1);
}

static void build(fast_locus *L, lx_observer obs)
{
    L->s0 = log(LX__CCT_FAST_T_MIN);
    L->h = (log(LX__CCT_FAST_T_MAX) - L->s0) / FAST_INTERVALS;
    double(*o)[8] = lx__alloc_n(FAST_NODES, sizeof *o), h = L->h, h2 = h * h;
    for (int k = 0; k < FAST_NODES; k++) L->T[k] = exp(L->s0 + k * h);
    if (!o || lx__planck_uv_ds3(obs, FAST_NODES, L->T, o) != LX_OK) {
        lx__free(o);
        return;
    }
    for (int k = 0; k < FAST_NODES; k++) {
        for (int m = 0; m < 4; m++) L->node[k][m] = o[k][m];
        if (k)
            for (int m = 0; m < 4; m++) /* m = 0, 1: u, v from their values and two derivatives; 2, 3: du/ds, dv/ds */
                hermite5(o[k - 1][m], o[k - 1][2 + m] * h, o[k - 1][4 + m] * h2, o[k][m], o[k][2 + m] * h,
                         o[k][4 + m] * h2, L->poly[k - 1] + 6 * m);
    }
    lx__free(o);
    L->ok = 1;
}

static void build2(void) { build(&locus2, LX_OBSERVER_2); }
static void build10(void) { build(&locus10, LX_OBSERVER_10); }

static const fast_locus *get_locus(lx_observer obs)
{
    if (obs == LX_OBSERVER_2) {
        pthread_once(&once2, build2);
        return locus2.ok ? &locus2 : NULL;
    }
    if (obs == LX_OBSERVER_10) {
        pthread_once(&once10, build10);
        return locus10.ok ? &locus10 : NULL;
    }
    return NULL;
}

static inline double g_node(const double *n, double u, double v) { return (n[0] - u) * n[2] + (n[1] - v) * n[3]; }

/* exp(x) for 0 <= x <= h (< 0.0095): Taylor to x^8, truncation below 2e-24 relative */
static inline double exp_small(double x)
{
    return 1 + x * (1 + x * (1.0 / 2 + x * (1.0 / 6 + x * (1.0 / 24 + x * (1.0 / 120 + x * (1.0 / 720 + x * (1.0 / 5040 + x * (1.0 / 40320))))))));
}

int lx__cct_fast(lx_observer obs, double u, double v, double *cct_K, double *duv)
{
    const fast_locus *L = get_locus(obs);
    if (!L) return 0;
    /* g increases through its one root: g(first node) <= 0 < g(last node) when the root is inside */
    double g0 = g_node(L->node[0], u, v), g1 = g_node(L->node[FAST_INTERVALS], u, v);
    if (!(g0 <= 0) || !(g1 > 0)) return 0; /* also NaN */
    int k = 0;
    for (int step = FAST_INTERVALS / 2; step; step >>= 1) { /* the last node k with g <= 0 */
        double g = g_node(L->node[k + step], u, v);
        k = g <= 0 ? k + step : k;
    }
    g0 = g_node(L->node[k], u, v);
    g1 = g_node(L->node[k + 1], u, v);
    const double *cu = L->poly[k], *cv = cu + 6, *qu = cu + 12, *qv = cu + 18;
    /* regula falsi start, then three Newton steps on G(t) = (U - u) Qu + (V - v) Qv: the steps
     * shrink as 7e-3, 1e-6, 4e-12 (the last at the rounding noise of G), measured over 3e5 points
     * within 0.09 of the locus; a fixed count keeps the twins branch-free */
    double t = g0 / (g0 - g1), h = L->h, U, V, Qu, Qv;
    for (int it = 0; it < LX__CCT_NEWTON; it++) {
        U = cu[0] + t * (cu[1] + t * (cu[2] + t * (cu[3] + t * (cu[4] + t * cu[5]))));
        V = cv[0] + t * (cv[1] + t * (cv[2] + t * (cv[3] + t * (cv[4] + t * cv[5]))));
        Qu = qu[0] + t * (qu[1] + t * (qu[2] + t * (qu[3] + t * (qu[4] + t * qu[5]))));
        Qv = qv[0] + t * (qv[1] + t * (qv[2] + t * (qv[3] + t * (qv[4] + t * qv[5]))));
        double Ru = qu[1] + t * (2 * qu[2] + t * (3 * qu[3] + t * (4 * qu[4] + t * 5 * qu[5])));
        double Rv = qv[1] + t * (2 * qv[2] + t * (3 * qv[3] + t * (4 * qv[4] + t * 5 * qv[5])));
        double G = (U - u) * Qu + (V - v) * Qv, Gp = h * (Qu * Qu + Qv * Qv) + (U - u) * Ru + (V - v) * Rv;
        t -= Gp > 0 ? G / Gp : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
    }
    U = cu[0] + t * (cu[1] + t * (cu[2] + t * (cu[3] + t * (cu[4] + t * cu[5]))));
    V = cv[0] + t * (cv[1] + t * (cv[2] + t * (cv[3] + t * (cv[4] + t * cv[5]))));
    Qu = qu[0] + t * (qu[1] + t * (qu[2] + t * (qu[3] + t * (qu[4] + t * qu[5]))));
    Qv = qv[0] + t * (qv[1] + t * (qv[2] + t * (qv[3] + t * (qv[4] + t * qv[5]))));
    /* sign as lx_cct_from_uv: + above the locus (towards larger v); the tangent points to lower u */
    double cross = Qu * (v - V) - Qv * (u - U);
    double sgn = cross < 0 ? 1.0 : -1.0;
    if (Qu > 0) sgn = -sgn;
    *cct_K = L->T[k] * exp_small(t * h);
    *duv = sgn * sqrt((u - U) * (u - U) + (v - V) * (v - V));
    return 1;
}

lx_status lx_cct_from_uv_batch(lx_ctx *ctx, lx_observer obs, size_t n, const double *u, const double *v,
                               double *cct_K, double *duv)
{
    LX__NEED_CTX(ctx);
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    if (n && (!u || !v || !cct_K || !duv)) return lx__error(ctx, LX_EINVAL, NULL, 0, "cct batch: NULL argument");
    if (!get_locus(obs)) return lx__error(ctx, LX_ENOMEM, NULL, 0, "the fast locus table could not be built");
    lx_ctx *exact = NULL; /* for the few the exact solver decides: its own context, so an undefined
                           * CCT (NaN here) leaves ctx's error state alone */
    lx_status st = LX_OK;
    for (size_t i = 0; i < n && st == LX_OK; i++) {
        double T, d;
        /* beyond 0.09 from the locus the one-root property is not checked: the exact solver decides */
        if (lx__cct_fast(obs, u[i], v[i], &T, &d) && fabs(d) <= 0.09) {
            cct_K[i] = T;
            duv[i] = d;
            continue;
        }
        if (!exact && lx_ctx_create(&exact) != LX_OK) {
            st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
            break;
        }
        lx_status e = lx_cct_from_uv(exact, obs, u[i], v[i], &T, &d);
        if (e == LX_ENOMEM) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for the locus table");
        cct_K[i] = e == LX_OK ? T : NAN;
        duv[i] = e == LX_OK ? d : NAN;
    }
    lx_ctx_destroy(exact);
    return st;
}
