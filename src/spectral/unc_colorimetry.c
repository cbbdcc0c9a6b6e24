/* unc_colorimetry.c - the spectral layer's quantities for the uncertainty engine, as functions of
 * linear integrals of the spectrum with their analytic derivatives: colorimetry (X, Y, Z, x, y, u',
 * v', CCT and Duv by implicit differentiation of the nearest-point condition on the Planckian
 * locus, LER, scotopic Y, S/P, radiant), CIE S 026 alpha-opic quantities, and PAR. */
#include "spectral/unc_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- colorimetry: integrals xbar, ybar, zbar (the observer's), V', the radiant integral ---- */

static const int color_q[] = {LX_UQ_X,  LX_UQ_Y,   LX_UQ_Z,          LX_UQ_CX,       LX_UQ_CY,
                              LX_UQ_U_PRIME, LX_UQ_V_PRIME, LX_UQ_CCT, LX_UQ_DUV, LX_UQ_LER,
                              LX_UQ_SCOTOPIC_Y, LX_UQ_SP_RATIO, LX_UQ_RADIANT};
#define NCOLOR 13

static lx_status fn_rows(lx_ctx *ctx, const lx_spd *spd, lx_method method, const lx_function *fns, int k, double *A)
{
    for (int f = 0; f < k; f++) {
        lx_spd w;
        lx_status st = (int)fns[f] < 0 ? LX_OK : lx_function_get(ctx, fns[f], &w);
        if (st == LX_OK) st = lx__integrate_weights(ctx, spd, (int)fns[f] < 0 ? NULL : &w, method, A + (size_t)f * spd->n);
        if (st != LX_OK) return st;
    }
    return LX_OK;
}

static lx_status color_rows(lx_ctx *ctx, void *self, const lx_spd *spd, double *A)
{
    const lx__unc_spectral_state *s = self;
    lx_function f0 = s->obs == LX_OBSERVER_10 ? LX_FN_XBAR_10 : LX_FN_XBAR_2;
    const lx_function fns[5] = {f0, (lx_function)(f0 + 1), (lx_function)(f0 + 2), LX_FN_VPRIME, (lx_function)-1};
    return fn_rows(ctx, spd, s->method, fns, 5, A);
}

typedef struct color_scratch {
    size_t cap;
    double *u, *v, *T, *duv;
} color_scratch;

static void *color_scratch_new(void *self)
{
    (void)self;
    return lx__calloc(1, sizeof(color_scratch));
}

static void color_scratch_free(void *self, void *p)
{
    (void)self;
    color_scratch *s = p;
    if (s) lx__free(s->u);
    lx__free(s);
}

static double km_of(lx_observer obs) { return obs == LX_OBSERVER_10 ? LX__KM_10 : LX__KM_2; }

static void color_eval(lx_ctx *ctx, void *self, void *scratch, size_t m, const double *L, size_t ldl, double *y, size_t ldy)
{
    const lx__unc_spectral_state *st = self;
    color_scratch *s = scratch;
    double km = km_of(st->obs);
    if (s && s->cap < m) {
        lx__free(s->u);
        s->u = lx__alloc(4 * m * sizeof *s->u);
        s->cap = s->u ? m : 0;
        if (s->u) s->v = s->u + m, s->T = s->v + m, s->duv = s->T + m;
    }
    for (size_t t = 0; t < m; t++) {
        const double *l = L + t * ldl;
        double *o = y + t * ldy;
        double X = km * l[0], Y = km * l[1], Z = km * l[2], sum = X + Y + Z, d = X + 15 * Y + 3 * Z;
        o[0] = X, o[1] = Y, o[2] = Z;
        o[3] = sum != 0 ? X / sum : NAN;
        o[4] = sum != 0 ? Y / sum : NAN;
        o[5] = d != 0 ? 4 * X / d : NAN;
        o[6] = d != 0 ? 9 * Y / d : NAN;
        o[9] = l[4] != 0 ? Y / l[4] : NAN;
        o[10] = LX__KM_SCOT * l[3];
        o[11] = Y != 0 ? o[10] / Y : NAN;
        o[12] = l[4];
        if (s && s->cap >= m) s->u[t] = o[5], s->v[t] = o[6] * 2.0 / 3.0;
    }
    if (s && s->cap >= m && lx_cct_from_uv_batch(ctx, st->obs, m, s->u, s->v, s->T, s->duv) == LX_OK) {
        for (size_t t = 0; t < m; t++) {
            double T = s->T[t], duv = s->duv[t];
            int ok = isfinite(T) && fabs(duv) <= 0.05 && T >= 1000.0 * (1 - 1e-9) && T <= 100000.0 * (1 + 1e-9);
            y[t * ldy + 7] = ok ? T : NAN;
            y[t * ldy + 8] = ok ? duv : NAN;
        }
    } else {
        for (size_t t = 0; t < m; t++) y[t * ldy + 7] = y[t * ldy + 8] = NAN;
    }
}

/* dT/d(u, v) and dDuv/d(u, v) at the locus point nearest (u, v): with g(s) = (P(s) - p) . P'(s) = 0
 * (s = ln T), ds/dp = P' / (|P'|^2 + (P - p) . P''); Duv = n . (p - P) with n the unit normal
 * towards positive Duv, so dDuv/dp = n (the terms in dn/ds and P' vanish). 0 when there is none. */
static int cct_gradient(lx_ctx *ctx, lx_observer obs, double u, double v, double dT[2], double dD[2])
{
    double T, duv, o[8];
    if (lx__cct_from_uv_table(ctx, obs, u, v, &T, &duv) != LX_OK || !isfinite(T)) return 0;
    if (lx__planck_uv_ds3(obs, 1, &T, (double(*)[8])o) != LX_OK) return 0;
    double pu = u - o[0], pv = v - o[1];
    double den = o[2] * o[2] + o[3] * o[3] - (pu * o[4] + pv * o[5]);
    double tl = hypot(o[2], o[3]);
    if (!(den != 0) || !(tl > 0)) return 0;
    dT[0] = T * o[2] / den, dT[1] = T * o[3] / den;
    double sg = o[2] > 0 ? -1.0 : 1.0;
    dD[0] = sg * o[3] / tl, dD[1] = -sg * o[2] / tl;
    return 1;
}

static int color_jacobian(lx_ctx *ctx, void *self, const double *l, double *J)
{
    const lx__unc_spectral_state *st = self;
    double km = km_of(st->obs);
    const int ni = 5;
    memset(J, 0, sizeof(double) * NCOLOR * ni);
#define JJ(q, i) J[(q) * ni + (i)]
    for (int c = 0; c < 3; c++) JJ(c, c) = km;
    double S = l[0] + l[1] + l[2], D = l[0] + 15 * l[1] + 3 * l[2];
    const double dS[3] = {1, 1, 1}, dDv[3] = {1, 15, 3};
    double du[3], dv[3];
    for (int i = 0; i < 3; i++) {
        JJ(3, i) = ((i == 0) * S - l[0] * dS[i]) / (S * S);
        JJ(4, i) = ((i == 1) * S - l[1] * dS[i]) / (S * S);
        du[i] = 4 * ((i == 0) * D - l[0] * dDv[i]) / (D * D);
        dv[i] = 6 * ((i == 1) * D - l[1] * dDv[i]) / (D * D);
        JJ(5, i) = du[i];
        JJ(6, i) = 1.5 * dv[i];
    }
    double gT[2], gD[2];
    if (D != 0 && cct_gradient(ctx, st->obs, 4 * l[0] / D, 6 * l[1] / D, gT, gD))
        for (int i = 0; i < 3; i++) JJ(7, i) = gT[0] * du[i] + gT[1] * dv[i], JJ(8, i) = gD[0] * du[i] + gD[1] * dv[i];
    else
        for (int i = 0; i < 3; i++) JJ(7, i) = JJ(8, i) = NAN;
    JJ(9, 1) = km / l[4], JJ(9, 4) = -km * l[1] / (l[4] * l[4]);
    JJ(10, 3) = LX__KM_SCOT;
    JJ(11, 3) = LX__KM_SCOT / (km * l[1]), JJ(11, 1) = -LX__KM_SCOT * l[3] / (km * l[1] * l[1]);
    JJ(12, 4) = 1.0;
#undef JJ
    return 1;
}

void lx__unc_colorimetry_provider(lx__unc_spectral_state *s, lx__unc_provider *p)
{
    memset(p, 0, sizeof *p);
    p->nint = 5, p->nout = NCOLOR, p->out_q = color_q;
    p->rows = color_rows, p->eval = color_eval, p->jacobian = color_jacobian;
    p->scratch_new = color_scratch_new, p->scratch_free = color_scratch_free;
    p->self = s;
}

/* ---- alpha-opic: the five action spectra and the 2 deg ybar (illuminance for the DER) ---- */

static const int ao_q[15] = {LX_UQ_AO_SC,  LX_UQ_AO_MC,  LX_UQ_AO_LC,  LX_UQ_AO_RH,  LX_UQ_AO_MEL,
                             LX_UQ_EDI_SC, LX_UQ_EDI_MC, LX_UQ_EDI_LC, LX_UQ_EDI_RH, LX_UQ_EDI_MEL,
                             LX_UQ_DER_SC, LX_UQ_DER_MC, LX_UQ_DER_LC, LX_UQ_DER_RH, LX_UQ_DER_MEL};

static lx_status ao_rows(lx_ctx *ctx, void *self, const lx_spd *spd, double *A)
{
    const lx__unc_spectral_state *s = self;
    const lx_function fns[6] = {LX_FN_ALPHA_SC, LX_FN_ALPHA_MC, LX_FN_ALPHA_LC, LX_FN_ALPHA_RH, LX_FN_ALPHA_MEL, LX_FN_YBAR_2};
    return fn_rows(ctx, spd, s->method, fns, 6, A);
}

static void ao_eval(lx_ctx *ctx, void *self, void *scratch, size_t m, const double *L, size_t ldl, double *y, size_t ldy)
{
    (void)ctx, (void)self, (void)scratch;
    for (size_t t = 0; t < m; t++) {
        const double *l = L + t * ldl;
        double *o = y + t * ldy, ev = LX__KM_2 * l[5];
        for (int k = 0; k < 5; k++) {
            double K = lx_alphaopic_d65_efficacy((lx_alphaopic_kind)k);
            o[k] = l[k];
            o[5 + k] = l[k] / K;
            o[10 + k] = ev != 0 ? l[k] / ev / K : NAN;
        }
    }
}

static int ao_jacobian(lx_ctx *ctx, void *self, const double *l, double *J)
{
    (void)ctx, (void)self;
    memset(J, 0, sizeof(double) * 15 * 6);
    double ev = LX__KM_2 * l[5];
    for (int k = 0; k < 5; k++) {
        double K = lx_alphaopic_d65_efficacy((lx_alphaopic_kind)k);
        J[k * 6 + k] = 1.0;
        J[(5 + k) * 6 + k] = 1.0 / K;
        J[(10 + k) * 6 + k] = 1.0 / (ev * K);
        J[(10 + k) * 6 + 5] = -l[k] * LX__KM_2 / (ev * ev * K);
    }
    return 1;
}

void lx__unc_alphaopic_provider(lx__unc_spectral_state *s, lx__unc_provider *p)
{
    memset(p, 0, sizeof *p);
    p->nint = 6, p->nout = 15, p->out_q = ao_q;
    p->rows = ao_rows, p->eval = ao_eval, p->jacobian = ao_jacobian;
    p->self = s;
}

/* ---- PAR: photon fluxes (a band the spectrum covers less than LX_COVERAGE_MIN of: NaN) ---- */

static const int par_q[3] = {LX_UQ_PPFD, LX_UQ_EPAR, LX_UQ_YPF};

static lx_status par_rows(lx_ctx *ctx, void *self, const lx_spd *spd, double *A)
{
    lx__unc_spectral_state *s = self;
    for (int f = 0; f < 3; f++) {
        lx_spd w;
        lx_status st = lx_function_get(ctx, lx__par_fns[f], &w);
        if (st != LX_OK) return st;
        s->par_ok[f] = lx__coverage(&w, spd->lambda_nm[0], spd->lambda_nm[spd->n - 1]) >= LX_COVERAGE_MIN;
    }
    return fn_rows(ctx, spd, s->method, lx__par_fns, 3, A);
}

static void par_eval(lx_ctx *ctx, void *self, void *scratch, size_t m, const double *L, size_t ldl, double *y, size_t ldy)
{
    (void)ctx, (void)scratch;
    const lx__unc_spectral_state *s = self;
    for (size_t t = 0; t < m; t++)
        for (int f = 0; f < 3; f++) y[t * ldy + f] = s->par_ok[f] ? L[t * ldl + f] : NAN;
}

static int par_jacobian(lx_ctx *ctx, void *self, const double *l, double *J)
{
    (void)ctx, (void)l;
    const lx__unc_spectral_state *s = self;
    memset(J, 0, sizeof(double) * 9);
    for (int f = 0; f < 3; f++) J[f * 3 + f] = s->par_ok[f] ? 1.0 : NAN;
    return 1;
}

void lx__unc_par_provider(lx__unc_spectral_state *s, lx__unc_provider *p)
{
    memset(p, 0, sizeof *p);
    p->nint = 3, p->nout = 3, p->out_q = par_q;
    p->rows = par_rows, p->eval = par_eval, p->jacobian = par_jacobian;
    p->self = s;
}
