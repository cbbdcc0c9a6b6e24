/* unc_cri.c - CIE 13.3 and CIE 224 / TM-30 for the uncertainty engine: the test source's side of
 * each as linear integrals of the spectrum (its samples spread onto the colour-quality grid's nodes
 * by the linear interpolation lx__quality_sample does), the rest as a function of them: the CCT by
 * the fast solver, the reference illuminant (Planck's law at the grid's nodes; CIE daylight as the
 * integrals of its basis S0 + M1 S1 + M2 S2, exact since the integrals are linear), the indices
 * (cri.c, tm30.c). A spectrum the index refuses at its measured value (truncated data) gives no
 * index in any trial. The Planckian references of a block of trials are integrated together: their
 * node values times the integrals' node weights, four trials a pass sharing each weight. */
#include "colour/unc_colour.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The weights of the samples of spd in the sum over the grid's nodes of f[i] S(lam[i]): A[j] +=
 * f[i] times the weight of sample j in the linear interpolation at node i (lx__quality_sample). */
static void spread(const lx_spd *spd, const lx__qgrid *g, const double *f, double *A)
{
    size_t n = spd->n, j = 0;
    const double *x = spd->lambda_nm;
    for (size_t k = 0; k < n; k++) A[k] = 0.0;
    for (size_t i = 0; i < g->n; i++) {
        double l = g->lam[i];
        if (l < x[0] || l > x[n - 1]) continue;
        while (j + 2 < n && x[j + 1] <= l) j++;
        if (l == x[j]) A[j] += f[i];
        else if (l == x[j + 1]) A[j + 1] += f[i];
        else {
            double t = (l - x[j]) / (x[j + 1] - x[j]);
            A[j] += f[i] * (1.0 - t), A[j + 1] += f[i] * t;
        }
    }
}

/* The weights of the integrals `integrals` computes of an illuminant: integral r is linear in the
 * illuminant's node values, so its weight at node i is its value for the unit vector e_i. Computed
 * by columns of the identity in blocks would cost n calls; instead each integral's node weights are
 * the product the caller gives (f_of). */
typedef void (*node_weights_fn)(const void *grid, int r, double *f);

static lx_status rows_from(lx_ctx *ctx, const lx_spd *spd, const lx__qgrid *g, int nint, node_weights_fn fw, const void *grid,
                           double *A)
{
    double *f = lx__alloc(g->n * sizeof *f);
    if (!f) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (int r = 0; r < nint; r++) {
        fw(grid, r, f);
        spread(spd, g, f, A + (size_t)r * spd->n);
    }
    lx__free(f);
    return LX_OK;
}

static lx_status basis_integrals(lx_ctx *ctx, const lx__qgrid *g, double *ref, double (*B)[LX__TM30_NINT > LX__CRI_NINT ? LX__TM30_NINT : LX__CRI_NINT],
                                 void (*integrals)(const void *, const double *, double *, double *), const void *grid, double *p)
{
    for (int b = 0; b < 3; b++) {
        for (size_t i = 0; i < g->n; i++) {
            double v[3];
            if (lx__daylight_basis(g->lam[i], v)) return lx__error(ctx, LX_EINVAL, NULL, 0, "embedded daylight basis missing");
            ref[i] = v[b];
        }
        integrals(grid, ref, B[b], p);
    }
    return LX_OK;
}

#define NMAX (LX__TM30_NINT > LX__CRI_NINT ? LX__TM30_NINT : LX__CRI_NINT)
#define BLK 32 /* trials whose Planckian references are integrated together */

/* The node weights of every integral (nint x the grid's n). */
static double *node_matrix(const lx__qgrid *g, int nint, node_weights_fn fw, const void *grid)
{
    double *W = lx__alloc_n(lx__size_mul((size_t)nint, g->n), sizeof *W);
    for (int r = 0; W && r < nint; r++) fw(grid, r, W + (size_t)r * g->n);
    return W;
}

/* Y[t][r] = sum_j X[t][j] W[r][j], t < m (rows of X of length n), r < R (rows of W), Y rows of ldy:
 * four rows of X a pass share each load of W, two sums each (eight independent chains). */
static void integrals_block(size_t m, size_t R, size_t n, const double *X, const double *W, double *Y, size_t ldy)
{
    size_t t = 0;
    for (; t + 4 <= m; t += 4) {
        const double *x0 = X + t * n, *x1 = x0 + n, *x2 = x1 + n, *x3 = x2 + n;
        for (size_t r = 0; r < R; r++) {
            const double *w = W + r * n;
            double a0 = 0, a1 = 0, a2 = 0, a3 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0;
            size_t j = 0;
            for (; j + 2 <= n; j += 2) {
                a0 += x0[j] * w[j], b0 += x0[j + 1] * w[j + 1];
                a1 += x1[j] * w[j], b1 += x1[j + 1] * w[j + 1];
                a2 += x2[j] * w[j], b2 += x2[j + 1] * w[j + 1];
                a3 += x3[j] * w[j], b3 += x3[j + 1] * w[j + 1];
            }
            if (j < n) a0 += x0[j] * w[j], a1 += x1[j] * w[j], a2 += x2[j] * w[j], a3 += x3[j] * w[j];
            Y[t * ldy + r] = a0 + b0, Y[(t + 1) * ldy + r] = a1 + b1;
            Y[(t + 2) * ldy + r] = a2 + b2, Y[(t + 3) * ldy + r] = a3 + b3;
        }
    }
    for (; t < m; t++)
        for (size_t r = 0; r < R; r++) {
            const double *x = X + t * n, *w = W + r * n;
            double a = 0, b = 0;
            size_t j = 0;
            for (; j + 2 <= n; j += 2) a += x[j] * w[j], b += x[j + 1] * w[j + 1];
            if (j < n) a += x[j] * w[j];
            Y[t * ldy + r] = a + b;
        }
}

/* The CCT of a trial's integrals (the 2 deg X, Y, Z first), 0 when there is none. */
static int trial_cct(lx_ctx *ctx, const double *Lt, double *T, double *duv)
{
    double d = Lt[0] + 15 * Lt[1] + 3 * Lt[2];
    if (!(Lt[1] > 0) || !(d > 0)) return 0;
    return lx__cct_from_uv_table(ctx, LX_OBSERVER_2, 4 * Lt[0] / d, 6 * Lt[1] / d, T, duv) == LX_OK;
}

/* ---- CIE 13.3 ---- */

struct lx__unc_cri_state {
    lx__cri_grid cg;
    double *W;         /* the integrals' node weights (LX__CRI_NINT x nodes) */
    double B[3][NMAX]; /* the daylight basis' integrals */
    int refused;       /* the measured spectrum has no CRI (truncated data): none in any trial */
};

static const int cri_q[15] = {LX_UQ_RA, LX_UQ_R1, LX_UQ_R2, LX_UQ_R3, LX_UQ_R4, LX_UQ_R5, LX_UQ_R6, LX_UQ_R7,
                              LX_UQ_R8, LX_UQ_R9, LX_UQ_R10, LX_UQ_R11, LX_UQ_R12, LX_UQ_R13, LX_UQ_R14};

static void cri_node_weights(const void *grid, int r, double *f)
{
    const lx__cri_grid *cg = grid;
    size_t n = cg->g.n;
    int s = r / 3 - 1, c = r % 3;
    for (size_t i = 0; i < n; i++) f[i] = cg->g.w[i] * (s < 0 ? 1.0 : cg->tcs[(size_t)s * n + i]) * cg->cmf[c * n + i];
}

static void cri_integrals(const void *grid, const double *illum, double *L, double *p)
{
    (void)p;
    lx__cri_integrals(grid, illum, L);
}

static lx_status cri_rows(lx_ctx *ctx, void *self, const lx_spd *spd, double *A)
{
    struct lx__unc_cri_state *s = self;
    return rows_from(ctx, spd, &s->cg.g, LX__CRI_NINT, cri_node_weights, &s->cg, A);
}

static void *cri_scratch_new(void *self)
{
    struct lx__unc_cri_state *s = self;
    return lx__alloc_n(BLK * (s->cg.g.n + LX__CRI_NINT), sizeof(double));
}

static void cri_scratch_free(void *self, void *p)
{
    (void)self;
    lx__free(p);
}

static void cri_eval(lx_ctx *ctx, void *self, void *scratch, size_t m, const double *L, size_t ldl, double *y, size_t ldy)
{
    const struct lx__unc_cri_state *s = self;
    size_t n = s->cg.g.n;
    double *P = scratch, *LP = P + BLK * n;
    for (size_t b0 = 0; b0 < m; b0 += BLK) {
        size_t bm = m - b0 < BLK ? m - b0 : BLK, np = 0;
        double T[BLK], duv[BLK];
        int idx[BLK]; /* -2 no index, -1 a daylight reference, else the row of its Planckian one */
        for (size_t t = 0; t < bm; t++) {
            idx[t] = -2;
            if (s->refused || !scratch || !trial_cct(ctx, L + (b0 + t) * ldl, &T[t], &duv[t]) || !lx__cri_ok(T[t], duv[t]))
                continue;
            if (T[t] >= 5000.0) {
                idx[t] = -1;
                continue;
            }
            for (size_t i = 0; i < n; i++) P[np * n + i] = lx_planck(s->cg.g.lam[i], T[t]);
            idx[t] = (int)np++;
        }
        integrals_block(np, LX__CRI_NINT, n, P, s->W, LP, LX__CRI_NINT);
        for (size_t t = 0; t < bm; t++) {
            double *o = y + (b0 + t) * ldy, Ld[LX__CRI_NINT], m1, m2;
            for (int k = 0; k < 15; k++) o[k] = NAN;
            const double *Lr = idx[t] >= 0 ? LP + (size_t)idx[t] * LX__CRI_NINT : Ld;
            if (idx[t] == -2 || (idx[t] == -1 && lx__daylight_m(ctx, T[t], &m1, &m2) != LX_OK)) continue;
            if (idx[t] == -1)
                for (int k = 0; k < LX__CRI_NINT; k++) Ld[k] = s->B[0][k] + m1 * s->B[1][k] + m2 * s->B[2][k];
            lx_cri r;
            lx__cri_indices(L + (b0 + t) * ldl, Lr, T[t], duv[t], &r);
            o[0] = r.ra;
            for (int k = 0; k < 14; k++) o[1 + k] = r.r[k];
        }
    }
}

void lx__unc_cri_free(lx__unc_cri_state *s)
{
    if (!s) return;
    lx__cri_grid_free(&s->cg);
    lx__free(s->W);
    lx__free(s);
}

lx_status lx__unc_cri_provider(lx_ctx *ctx, const lx_spd *spd, lx__unc_cri_state **out, lx__unc_provider *p)
{
    *out = NULL;
    struct lx__unc_cri_state *s = lx__calloc(1, sizeof *s);
    if (!s) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    lx_status st = lx__cri_grid_make(ctx, spd, &s->cg);
    double *ref = st == LX_OK ? lx__alloc(s->cg.g.n * sizeof *ref) : NULL;
    if (st == LX_OK && !ref) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (st == LX_OK) st = basis_integrals(ctx, &s->cg.g, ref, s->B, cri_integrals, &s->cg, NULL);
    if (st == LX_OK && !(s->W = node_matrix(&s->cg.g, LX__CRI_NINT, cri_node_weights, &s->cg)))
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (st == LX_OK) { /* the refusal of the measured spectrum (the data's range against its reference) */
        lx_cri c;
        s->refused = lx_cri_compute(ctx, spd, &c) != LX_OK;
    }
    lx__free(ref);
    if (st != LX_OK) {
        lx__unc_cri_free(s);
        return st;
    }
    memset(p, 0, sizeof *p);
    p->nint = LX__CRI_NINT, p->nout = 15, p->out_q = cri_q;
    p->rows = cri_rows, p->eval = cri_eval;
    p->scratch_new = cri_scratch_new, p->scratch_free = cri_scratch_free;
    p->self = s;
    *out = s;
    return LX_OK;
}

/* ---- CIE 224 / TM-30 ---- */

struct lx__unc_tm30_state {
    lx__tm30_grid tg;
    double *W;         /* the integrals' node weights (LX__TM30_NINT x nodes) */
    double B[3][NMAX];
    int refused;
};

static const int tm30_q[2] = {LX_UQ_RF, LX_UQ_RG};

static void tm30_node_weights(const void *grid, int r, double *f)
{
    const lx__tm30_grid *tg = grid;
    size_t n = tg->g.n;
    if (r < 3) {
        for (size_t i = 0; i < n; i++) f[i] = tg->g.w[i] * tg->cmf2[(size_t)r * n + i];
        return;
    }
    int s = r / 3 - 2, c = r % 3;
    for (size_t i = 0; i < n; i++) f[i] = tg->g.w[i] * tg->cmf10[(size_t)c * n + i] * (s < 0 ? 1.0 : tg->ces[(size_t)s * n + i]);
}

static void tm30_integrals(const void *grid, const double *illum, double *L, double *p)
{
    lx__tm30_integrals(grid, illum, L, p);
}

static lx_status tm30_rows(lx_ctx *ctx, void *self, const lx_spd *spd, double *A)
{
    struct lx__unc_tm30_state *s = self;
    return rows_from(ctx, spd, &s->tg.g, LX__TM30_NINT, tm30_node_weights, &s->tg, A);
}

static void *tm30_scratch_new(void *self)
{
    struct lx__unc_tm30_state *s = self;
    return lx__alloc_n(BLK * (s->tg.g.n + LX__TM30_NINT) + 2 * LX__TM30_NINT, sizeof(double));
}

/* The reference's integrals at T (CIE 224: Planck below 4000 K, daylight from 5000 K, between a mix
 * of the two normalised to equal Y, so its integrals mix the two's) from its Planckian integrals LP
 * (below 5000 K). 0 when CIE daylight is undefined there. */
static int tm30_ref(lx_ctx *ctx, const struct lx__unc_tm30_state *s, double T, const double *LP, double *Lr)
{
    double m1 = 0, m2 = 0;
    if (T < 4000.0) {
        memcpy(Lr, LP, LX__TM30_NINT * sizeof *Lr);
        return 1;
    }
    if (lx__daylight_m(ctx, T, &m1, &m2) != LX_OK) return 0;
    for (int k = 0; k < LX__TM30_NINT; k++) Lr[k] = s->B[0][k] + m1 * s->B[1][k] + m2 * s->B[2][k];
    if (T < 5000.0) {
        double mix = (T - 4000.0) / 1000.0, yp = LP[1], yd = Lr[1];
        for (int k = 0; k < LX__TM30_NINT; k++) Lr[k] = (1.0 - mix) * LP[k] / yp + mix * Lr[k] / yd;
    }
    return 1;
}

static void tm30_eval(lx_ctx *ctx, void *self, void *scratch, size_t m, const double *L, size_t ldl, double *y, size_t ldy)
{
    const struct lx__unc_tm30_state *s = self;
    size_t n = s->tg.g.n;
    double *P = scratch, *LP = P + BLK * n, *Lr = LP + BLK * LX__TM30_NINT;
    lx_tm30 *r = lx__alloc(sizeof *r);
    for (size_t b0 = 0; b0 < m; b0 += BLK) {
        size_t bm = m - b0 < BLK ? m - b0 : BLK, np = 0;
        double T[BLK], duv[BLK];
        int idx[BLK]; /* -2 no index, -1 daylight only, else the row of its Planckian integrals */
        for (size_t t = 0; t < bm; t++) {
            idx[t] = -2;
            if (s->refused || !scratch || !r || !trial_cct(ctx, L + (b0 + t) * ldl, &T[t], &duv[t]) ||
                !lx__tm30_ok(T[t], duv[t]))
                continue;
            if (T[t] >= 5000.0) {
                idx[t] = -1;
                continue;
            }
            for (size_t i = 0; i < n; i++) P[np * n + i] = lx_planck(s->tg.g.lam[i], T[t]);
            idx[t] = (int)np++;
        }
        integrals_block(np, LX__TM30_NINT, n, P, s->W, LP, LX__TM30_NINT);
        for (size_t t = 0; t < bm; t++) {
            double *o = y + (b0 + t) * ldy;
            o[0] = o[1] = NAN;
            if (idx[t] == -2 || !tm30_ref(ctx, s, T[t], idx[t] >= 0 ? LP + (size_t)idx[t] * LX__TM30_NINT : NULL, Lr)) continue;
            lx__tm30_indices(L + (b0 + t) * ldl, Lr, T[t], duv[t], r);
            o[0] = r->rf, o[1] = r->rg;
        }
    }
    lx__free(r);
}

void lx__unc_tm30_free(lx__unc_tm30_state *s)
{
    if (!s) return;
    lx__tm30_grid_free(&s->tg);
    lx__free(s->W);
    lx__free(s);
}

lx_status lx__unc_tm30_provider(lx_ctx *ctx, const lx_spd *spd, lx__unc_tm30_state **out, lx__unc_provider *p)
{
    *out = NULL;
    struct lx__unc_tm30_state *s = lx__calloc(1, sizeof *s);
    if (!s) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    lx_status st = lx__tm30_grid_make(ctx, spd, &s->tg);
    double *ref = st == LX_OK ? lx__alloc(s->tg.g.n * sizeof *ref) : NULL;
    if (st == LX_OK && !ref) st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (st == LX_OK) st = basis_integrals(ctx, &s->tg.g, ref, s->B, tm30_integrals, &s->tg, s->tg.scratch);
    if (st == LX_OK && !(s->W = node_matrix(&s->tg.g, LX__TM30_NINT, tm30_node_weights, &s->tg)))
        st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (st == LX_OK) {
        lx_tm30 *c = lx__alloc(sizeof *c);
        s->refused = !c || lx_tm30_compute(ctx, spd, c) != LX_OK;
        lx__free(c);
    }
    lx__free(ref);
    if (st != LX_OK) {
        lx__unc_tm30_free(s);
        return st;
    }
    memset(p, 0, sizeof *p);
    p->nint = LX__TM30_NINT, p->nout = 2, p->out_q = tm30_q;
    p->rows = tm30_rows, p->eval = tm30_eval;
    p->scratch_new = tm30_scratch_new, p->scratch_free = cri_scratch_free;
    p->self = s;
    *out = s;
    return LX_OK;
}
