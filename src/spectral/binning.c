/* binning.c - LED binning of white light: the ANSI C78.377-2017 nominal CCT categories and its
 * flexible-CCT rule (CCT and Duv tolerances), and MacAdam steps (SDCM) to the nearest IEC 60081
 * colour centre; for one chromaticity or a whole batch. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ANSI C78.377 flexible CCT: target Duv and CCT tolerance of a nominal CCT T (K) */
static double flex_duv(double T) { return 57700.0 / (T * T) - 44.6 / T + 0.0085; }
static double flex_tol(double T) { return ((1.1900e-8 * T - 1.5434e-4) * T + 0.7168) * T - 902.55; }
#define FLEX_DUV_TOL 0.006
#define FLEX_MIN 2700
#define FLEX_MAX 6500

typedef struct tables {
    const lx__table *ansi, *sdcm;
    int a_t, a_tol, a_duv, a_dtol;   /* columns */
    int s_x, s_y, s_g11, s_g12, s_g22;
} tables;

static lx_status get_tables(lx_ctx *ctx, tables *T)
{
    T->ansi = lx__table_find("ansi_c78377_categories");
    T->sdcm = lx__table_find("iec60081_sdcm_centres");
    if (!T->ansi || !T->sdcm) return lx__error(ctx, LX_EINVAL, NULL, 0, "the embedded binning tables are missing");
    T->a_t = lx__table_col(T->ansi, "target_cct_K"), T->a_tol = lx__table_col(T->ansi, "cct_tolerance_K");
    T->a_duv = lx__table_col(T->ansi, "target_duv"), T->a_dtol = lx__table_col(T->ansi, "duv_tolerance");
    T->s_x = lx__table_col(T->sdcm, "x"), T->s_y = lx__table_col(T->sdcm, "y");
    T->s_g11 = lx__table_col(T->sdcm, "g11"), T->s_g12 = lx__table_col(T->sdcm, "g12"), T->s_g22 = lx__table_col(T->sdcm, "g22");
    if (T->a_t < 0 || T->a_tol < 0 || T->a_duv < 0 || T->a_dtol < 0 || T->s_x < 0 || T->s_y < 0 || T->s_g11 < 0 ||
        T->s_g12 < 0 || T->s_g22 < 0)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the embedded binning tables lack a column");
    return LX_OK;
}

static double cellv(const lx__table *t, int col, int row) { return t->data[(size_t)col * t->nrows + row]; }

static void bin_one(const tables *T, double x, double y, double cct, double duv, lx_binning *b)
{
    memset(b, 0, sizeof *b);
    b->ansi_K = 0, b->ansi_duv_offset = NAN, b->flex_K = 0, b->flex_duv_offset = NAN;
    b->sdcm = NAN, b->sdcm_centre_K = 0;
    if (isfinite(cct) && isfinite(duv)) {
        for (int r = 0; r < T->ansi->nrows && !b->ansi_K; r++) {
            double tt = cellv(T->ansi, T->a_t, r), tol = cellv(T->ansi, T->a_tol, r);
            double td = cellv(T->ansi, T->a_duv, r), dtol = cellv(T->ansi, T->a_dtol, r);
            if (fabs(cct - tt) <= tol && fabs(duv - td) <= dtol + 1e-12) {
                b->ansi_K = (int)cellv(T->ansi, 0, r);
                b->ansi_duv_offset = duv - td;
            }
        }
        double best = INFINITY;
        for (int Tn = FLEX_MIN; Tn <= FLEX_MAX; Tn += 100) {
            double d = fabs(cct - Tn);
            if (d <= flex_tol(Tn) && fabs(duv - flex_duv(Tn)) <= FLEX_DUV_TOL + 1e-12 && d < best) {
                best = d;
                b->flex_K = Tn;
                b->flex_duv_offset = duv - flex_duv(Tn);
            }
        }
    }
    if (isfinite(x) && isfinite(y)) {
        for (int r = 0; r < T->sdcm->nrows; r++) {
            double dx = x - cellv(T->sdcm, T->s_x, r), dy = y - cellv(T->sdcm, T->s_y, r);
            double q = 1e4 * (cellv(T->sdcm, T->s_g11, r) * dx * dx + 2 * cellv(T->sdcm, T->s_g12, r) * dx * dy +
                              cellv(T->sdcm, T->s_g22, r) * dy * dy);
            double n = sqrt(q > 0 ? q : 0);
            if (!(n >= b->sdcm)) {
                b->sdcm = n;
                b->sdcm_centre_K = (int)cellv(T->sdcm, 0, r);
            }
        }
    }
}

lx_status lx_binning_compute(lx_ctx *ctx, double x, double y, double cct_K, double duv, lx_binning *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_binning_compute: NULL argument");
    tables T;
    lx_status st = get_tables(ctx, &T);
    if (st == LX_OK) bin_one(&T, x, y, cct_K, duv, out);
    return st;
}

typedef struct bjob {
    const tables *T;
    const double *xyz;
    lx_binning *out;
    lx_status st[64];
} bjob;

static void bin_range(void *arg, long i0, long i1, int t)
{
    bjob *j = arg;
    lx_ctx *ctx = NULL;
    if ((j->st[t] = lx_ctx_create(&ctx)) != LX_OK) return; /* the locus cache is one context's */
    for (long i = i0; i < i1; i++) {
        const double *p = j->xyz + 3 * i;
        double sum = p[0] + p[1] + p[2], d = p[0] + 15 * p[1] + 3 * p[2];
        double x = sum != 0 ? p[0] / sum : NAN, y = sum != 0 ? p[1] / sum : NAN;
        double cct = NAN, duv = NAN;
        if (d > 0 && sum > 0) {
            lx_status st = lx__cct_from_uv_table(ctx, LX_OBSERVER_2, 4 * p[0] / d, 6 * p[1] / d, &cct, &duv);
            if (st != LX_OK && st != LX_ERANGE) {
                j->st[t] = st;
                break;
            }
        }
        bin_one(j->T, x, y, cct, duv, &j->out[i]);
    }
    lx_ctx_destroy(ctx);
}

lx_status lx_binning_batch(lx_ctx *ctx, const lx_batch *b, const lx_batch_opts *opts, lx_binning *out)
{
    LX__NEED_CTX(ctx);
    if (!b || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_binning_batch: NULL argument");
    if (b->n_spectra == 0) return LX_OK;
    tables T;
    lx_status st = get_tables(ctx, &T);
    if (st != LX_OK) return st;
    static const lx_function fns[3] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2};
    double *xyz = malloc(sizeof(double) * 3 * b->n_spectra);
    if (!xyz) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for %zu spectra", b->n_spectra);
    st = lx_batch_integrate(ctx, b, fns, 3, opts, xyz);
    if (st == LX_OK) {
        int nt = b->n_spectra < 4096 ? 1 : lx__threads(opts ? opts->threads : 0, (long)b->n_spectra);
        bjob J = {.T = &T, .xyz = xyz, .out = out};
        lx__parallel_for(ctx, nt, (long)b->n_spectra, bin_range, &J);
        for (int t = 0; t < nt && st == LX_OK; t++)
            if (J.st[t] != LX_OK) st = lx__error(ctx, J.st[t], NULL, 0, "batch binning failed: %s", lx_strerror(J.st[t]));
    }
    free(xyz);
    return st;
}
