/* tables.c - access to the embedded CIE tables: lookup by name, column views, the weighting
 * functions (colour-matching functions, V', alpha-opic) and the named illuminants. */
#include "tables/tables_private.h"

#include <math.h>
#include <pthread.h>
#include <string.h>

const lx__table *lx__table_find(const char *name)
{
    for (int i = 0; i < lx__ntables; i++)
        if (!strcmp(lx__tables[i].name, name)) return &lx__tables[i];
    return NULL;
}

int lx__table_col(const lx__table *t, const char *col)
{
    if (!t) return -1;
    for (int c = 1; c < t->ncols; c++)
        if (!strcmp(t->colnames[c], col)) return c;
    return -1;
}

int lx__table_view(const lx__table *t, int col, lx_spd *out)
{
    if (!t || col < 1 || col >= t->ncols) return -1;
    const double *v = t->data + (size_t)col * t->nrows;
    int r0 = 0, r1 = t->nrows - 1;
    while (r0 <= r1 && isnan(v[r0])) r0++;
    while (r1 >= r0 && isnan(v[r1])) r1--;
    if (r1 - r0 < 1) return -1;
    for (int r = r0; r <= r1; r++)
        if (isnan(v[r])) return -1; /* a hole inside the defined range is not a valid view */
    out->name = t->colnames[col];
    out->n = (size_t)(r1 - r0 + 1);
    out->lambda_nm = t->data + r0;
    out->value = v + r0;
    return 0;
}

static const struct {
    const char *table, *col;
} fn_source[LX_FN_COUNT] = {
    [LX_FN_XBAR_2] = {"cie1931_2deg_xyz_1nm", "x_bar"},
    [LX_FN_YBAR_2] = {"cie1931_2deg_xyz_1nm", "y_bar"},
    [LX_FN_ZBAR_2] = {"cie1931_2deg_xyz_1nm", "z_bar"},
    [LX_FN_XBAR_10] = {"cie1964_10deg_xyz_1nm", "x_bar_10"},
    [LX_FN_YBAR_10] = {"cie1964_10deg_xyz_1nm", "y_bar_10"},
    [LX_FN_ZBAR_10] = {"cie1964_10deg_xyz_1nm", "z_bar_10"},
    [LX_FN_VPRIME] = {"cie1951_scotopic_1nm", "v_prime"},
    [LX_FN_ALPHA_SC] = {"cie_s026_alphaopic_1nm", "s_cone"},
    [LX_FN_ALPHA_MC] = {"cie_s026_alphaopic_1nm", "m_cone"},
    [LX_FN_ALPHA_LC] = {"cie_s026_alphaopic_1nm", "l_cone"},
    [LX_FN_ALPHA_RH] = {"cie_s026_alphaopic_1nm", "rod"},
    [LX_FN_ALPHA_MEL] = {"cie_s026_alphaopic_1nm", "melanopic"},
    [LX_FN_HAZARD_BLUE] = {"iec62471_blue_thermal", "blue_B"},
    [LX_FN_HAZARD_THERMAL] = {"iec62471_blue_thermal", "thermal_R"},
    [LX_FN_HAZARD_ACTINIC] = {"iec62471_actinic_uv", "actinic_S"},
    /* the photon and box functions are computed (computed_fn below) */
};

/* Functions defined by a formula rather than a table, tabulated once at 1 nm: photons per joule
 * lambda / (h c N_A) over the PAR bands, that times McCree's relative quantum efficiency
 * (src/data/mccree1972_rqe.csv, linear between its 25 nm rows), and the unweighted UV-A band. */
#define PAR_N 301   /* 400-700 nm */
#define EPAR_N 351  /* 400-750 nm */
#define YPF_N 376   /* 350-725 nm */
#define UVA_N 86    /* 315-400 nm */
static double comp_l[EPAR_N + YPF_N + UVA_N], comp_v[PAR_N + EPAR_N + YPF_N + UVA_N];
static pthread_once_t comp_once = PTHREAD_ONCE_INIT;
static int comp_ok;

static void fill_computed(void)
{
    double *par = comp_v, *epar = par + PAR_N, *ypf = epar + EPAR_N, *uva = ypf + YPF_N;
    double *l_epar = comp_l, *l_ypf = l_epar + EPAR_N, *l_uva = l_ypf + YPF_N;
    for (int i = 0; i < EPAR_N; i++) {
        l_epar[i] = 400.0 + i;
        epar[i] = l_epar[i] * LX__UMOL_PER_J_NM;
        if (i < PAR_N) par[i] = epar[i];
    }
    const lx__table *t = lx__table_find("mccree1972_rqe");
    int c = lx__table_col(t, "field_mean");
    if (c < 0) return;
    const double *tl = t->data, *tv = t->data + (size_t)c * t->nrows;
    for (int i = 0; i < YPF_N; i++) {
        l_ypf[i] = 350.0 + i;
        ypf[i] = l_ypf[i] * LX__UMOL_PER_J_NM * lx__interp(tl, tv, (size_t)t->nrows, l_ypf[i]);
    }
    for (int i = 0; i < UVA_N; i++) l_uva[i] = 315.0 + i, uva[i] = 1.0;
    comp_ok = 1;
}

static int computed_fn(lx_function fn, lx_spd *out)
{
    pthread_once(&comp_once, fill_computed);
    if (!comp_ok) return -1;
    static const char *const names[] = {"photon_par", "photon_epar", "ypf_mccree", "uva"};
    double *l_epar = comp_l, *l_ypf = l_epar + EPAR_N, *l_uva = l_ypf + YPF_N;
    double *par = comp_v, *epar = par + PAR_N, *ypf = epar + EPAR_N, *uva = ypf + YPF_N;
    switch (fn) {
    case LX_FN_PHOTON_PAR: *out = (lx_spd){names[0], PAR_N, l_epar, par}; return 0;
    case LX_FN_PHOTON_EPAR: *out = (lx_spd){names[1], EPAR_N, l_epar, epar}; return 0;
    case LX_FN_YPF_MCCREE: *out = (lx_spd){names[2], YPF_N, l_ypf, ypf}; return 0;
    case LX_FN_UVA: *out = (lx_spd){names[3], UVA_N, l_uva, uva}; return 0;
    default: return -1;
    }
}

lx_status lx_function_get(lx_ctx *ctx, lx_function fn, lx_spd *out)
{
    LX__NEED_CTX(ctx);
    if (!out || (int)fn < 0 || fn >= LX_FN_COUNT) return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown weighting function %d", (int)fn);
    if (!fn_source[fn].table) {
        if (computed_fn(fn, out) == 0) return LX_OK;
        return lx__error(ctx, LX_EINVAL, NULL, 0, "weighting function %d: its table is missing", (int)fn);
    }
    const lx__table *t = lx__table_find(fn_source[fn].table);
    if (lx__table_view(t, lx__table_col(t, fn_source[fn].col), out) != 0)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "embedded table %s lacks column %s", fn_source[fn].table,
                         fn_source[fn].col);
    return LX_OK;
}

static const char *const illum_tables[] = {"cie_illuminants_a_d", "cie_illuminants_fl", "cie_illuminants_led_hp"};

lx_status lx_illuminant_get(lx_ctx *ctx, const char *name, lx_spd *out)
{
    LX__NEED_CTX(ctx);
    if (!name || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "illuminant name and output are required");
    for (size_t i = 0; i < sizeof illum_tables / sizeof *illum_tables; i++) {
        const lx__table *t = lx__table_find(illum_tables[i]);
        int c = lx__table_col(t, name);
        if (c > 0 && lx__table_view(t, c, out) == 0) return LX_OK;
    }
    return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown illuminant '%s'", name);
}

static const char *illum_names[64];
static pthread_once_t illum_once = PTHREAD_ONCE_INIT;

static void fill_illum_names(void)
{
    int k = 0;
    for (size_t i = 0; i < sizeof illum_tables / sizeof *illum_tables; i++) {
        const lx__table *t = lx__table_find(illum_tables[i]);
        for (int c = 1; t && c < t->ncols && k < 63; c++) illum_names[k++] = t->colnames[c];
    }
    illum_names[k] = NULL;
}

const char *const *lx_illuminant_names(void)
{
    pthread_once(&illum_once, fill_illum_names); /* thread-safe first call */
    return illum_names;
}

double lx__interp(const double *xs, const double *ys, size_t n, double x)
{
    if (n == 0 || !(x >= xs[0]) || !(x <= xs[n - 1])) return 0.0;
    size_t lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (xs[mid] <= x) lo = mid;
        else hi = mid;
    }
    if (x == xs[lo]) return ys[lo];
    if (x == xs[hi]) return ys[hi];
    double t = (x - xs[lo]) / (xs[hi] - xs[lo]);
    return ys[lo] + t * (ys[hi] - ys[lo]);
}
