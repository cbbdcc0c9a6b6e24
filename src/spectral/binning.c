/* binning.c - LED binning of white light: the ANSI C78.377-2017 nominal CCT categories and its
 * flexible-CCT rule (CCT and Duv tolerances), and MacAdam steps (SDCM) to the nearest IEC 60081
 * colour centre, for one chromaticity (batches: lab_batch.c). */
#include "spectral/spectral_private.h"

#include <math.h>
#include <pthread.h>
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

static tables tabs;
static int tabs_ok;
static pthread_once_t tabs_once = PTHREAD_ONCE_INIT;
static void find_tables(void);

static lx_status get_tables(lx_ctx *ctx, tables *T)
{
    pthread_once(&tabs_once, find_tables);
    if (!tabs_ok) return lx__error(ctx, LX_EINVAL, NULL, 0, "the embedded binning tables are missing or lack a column");
    *T = tabs;
    return LX_OK;
}

static lx_status lookup_tables(lx_ctx *ctx, tables *T)
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

static void find_tables(void) { tabs_ok = lookup_tables(NULL, &tabs) == LX_OK; }

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
        int lo = (int)floor((cct - 700) / 100) * 100, hi = (int)ceil((cct + 700) / 100) * 100; /* tolerances < 600 K */
        if (lo < FLEX_MIN) lo = FLEX_MIN;
        if (hi > FLEX_MAX) hi = FLEX_MAX;
        for (int Tn = lo; Tn <= hi; Tn += 100) {
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

int lx__bin_xy(double x, double y, double cct_K, double duv, lx_binning *out)
{
    pthread_once(&tabs_once, find_tables);
    if (!tabs_ok) return -1;
    bin_one(&tabs, x, y, cct_K, duv, out);
    return 0;
}
