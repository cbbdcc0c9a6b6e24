/* illuminants.c - spectra defined by formulas: Planck's law, Stefan-Boltzmann, CIE illuminant A
 * by its defining formula, and the CIE D-series daylight from the S0/S1/S2 basis. */
#include "tables/tables_private.h"

#include <math.h>


double lx_planck(double lambda_nm, double T_K)
{
    if (!(lambda_nm > 0) || !(T_K > 0) || !isfinite(lambda_nm) || !isfinite(T_K)) return NAN;
    double lm = lambda_nm * 1e-9;
    double x = LX__C2 / (lm * T_K);
    double l5 = lm * lm * lm * lm * lm;
    double pre = LX__C1L / l5 * 1e-9; /* per nm */
    if (x > 700.0) return pre * exp(-x); /* exp(x) - 1 == exp(x) here; underflows to 0 cleanly */
    return pre / expm1(x);
}

double lx_stefan_boltzmann(double T_K)
{
    double t2 = T_K * T_K;
    return LX__SIGMA * t2 * t2;
}

double lx_illuminant_a(double lambda_nm)
{
    /* CIE 015:2018 eq. 4.1: S_A = 100 (560/lambda)^5 (exp(1.435e7/(2848*560)) - 1) / (exp(1.435e7/(2848 lambda)) - 1) */
    if (!(lambda_nm > 0)) return NAN;
    double r = 560.0 / lambda_nm;
    return 100.0 * r * r * r * r * r * expm1(1.435e7 / (2848.0 * 560.0)) / expm1(1.435e7 / (2848.0 * lambda_nm));
}

lx_status lx_daylight_xy(lx_ctx *ctx, double T, double *x, double *y)
{
    LX__NEED_CTX(ctx);
    if (!(T >= 4000.0 && T <= 25000.0))
        return lx__error(ctx, LX_ERANGE, NULL, 0, "CIE daylight is defined for 4000 K to 25000 K, not %g K", T);
    double t1 = 1.0 / T, t2 = t1 * t1, t3 = t2 * t1;
    double xd = T <= 7000.0 ? -4.6070e9 * t3 + 2.9678e6 * t2 + 0.09911e3 * t1 + 0.244063
                            : -2.0064e9 * t3 + 1.9018e6 * t2 + 0.24748e3 * t1 + 0.237040;
    if (x) *x = xd;
    if (y) *y = -3.000 * xd * xd + 2.870 * xd - 0.275;
    return LX_OK;
}

lx_status lx__daylight_m(lx_ctx *ctx, double T, double *m1, double *m2)
{
    double xd, yd;
    lx_status st = lx_daylight_xy(ctx, T, &xd, &yd);
    if (st != LX_OK) return st;
    double m = 0.0241 + 0.2562 * xd - 0.7341 * yd;
    /* CIE 015:2018 4.1.2: M1 and M2 rounded to three decimals, as the published D-series tables were */
    *m1 = round((-1.3515 - 1.7703 * xd + 5.9114 * yd) / m * 1000.0) / 1000.0;
    *m2 = round((0.0300 - 31.4424 * xd + 30.0717 * yd) / m * 1000.0) / 1000.0;
    return LX_OK;
}

int lx__daylight_basis(double lambda_nm, double b[3])
{
    const lx__table *t = lx__table_find("cie_daylight_basis");
    if (!t) return -1;
    const double *wl = t->data, *s0 = t->data + t->nrows, *s1 = s0 + t->nrows, *s2 = s1 + t->nrows;
    b[0] = lx__interp(wl, s0, (size_t)t->nrows, lambda_nm);
    b[1] = lx__interp(wl, s1, (size_t)t->nrows, lambda_nm);
    b[2] = lx__interp(wl, s2, (size_t)t->nrows, lambda_nm);
    return 0;
}

lx_status lx_daylight(lx_ctx *ctx, double T, size_t n, const double *lambda_nm, double *value)
{
    LX__NEED_CTX(ctx);
    double m1, m2;
    lx_status st = lx__daylight_m(ctx, T, &m1, &m2);
    if (st != LX_OK) return st;
    if (n && (!lambda_nm || !value)) return lx__error(ctx, LX_EINVAL, NULL, 0, "daylight: NULL array");
    if (!lx__table_find("cie_daylight_basis")) return lx__error(ctx, LX_EINVAL, NULL, 0, "embedded daylight basis missing");
    for (size_t i = 0; i < n; i++) {
        double b[3];
        lx__daylight_basis(lambda_nm[i], b);
        value[i] = b[0] + m1 * b[1] + m2 * b[2];
    }
    return LX_OK;
}
