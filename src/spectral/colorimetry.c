/* colorimetry.c - all colorimetric and photometric quantities of one spectrum: absolute XYZ,
 * chromaticities, CCT and Duv, luminous efficacy of radiation, scotopic quantities. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


/* The CCT of the integrals (NaN when the solver finds none), keeping the context's error state
 * (an undefined CCT is a result, not an error). */
static double solve_cct(lx_ctx *ctx, lx_observer obs, double u, double v, double *duv)
{
    double T = NAN;
    *duv = NAN;
    lx_status st0 = ctx->status;
    long line0 = ctx->errline;
    char msg0[LX__ERRMSG_MAX], file0[sizeof ctx->errfile];
    memcpy(msg0, ctx->errmsg, sizeof msg0);
    memcpy(file0, ctx->errfile, sizeof file0);
    if (lx_cct_from_uv(ctx, obs, u, v, &T, duv) != LX_OK) {
        T = NAN;
        ctx->status = st0;
        ctx->errline = line0;
        memcpy(ctx->errmsg, msg0, sizeof msg0);
        memcpy(ctx->errfile, file0, sizeof file0);
    }
    return T;
}

lx_status lx__colorimetry_range(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime, double radiant,
                                double lo_K, double hi_K, lx_colorimetry *out, double *solved_K)
{
    if (!out || !xyz) return lx__error(ctx, LX_EINVAL, NULL, 0, "integrals and output are required");
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    double km = obs == LX_OBSERVER_2 ? LX__KM_2 : LX__KM_10;
    lx_colorimetry r;
    r.method = out->method;
    r.X = km * xyz[0];
    r.Y = km * xyz[1];
    r.Z = km * xyz[2];
    double s = r.X + r.Y + r.Z;
    double d = r.X + 15 * r.Y + 3 * r.Z;
    r.x = s != 0 ? r.X / s : NAN;
    r.y = s != 0 ? r.Y / s : NAN;
    r.u_prime = d != 0 ? 4 * r.X / d : NAN;
    r.v_prime = d != 0 ? 9 * r.Y / d : NAN;
    r.radiant = radiant;
    r.ler_lm_per_W = radiant != 0 ? r.Y / radiant : NAN;
    r.scotopic_Y = LX__KM_SCOT * vprime;
    r.sp_ratio = r.Y != 0 ? r.scotopic_Y / r.Y : NAN;
    r.cct_K = r.duv = NAN;
    r.cct_valid = 0;
    double T = NAN, duv = NAN;
    if (d != 0 && isfinite(r.u_prime)) T = solve_cct(ctx, obs, r.u_prime, r.v_prime * 2.0 / 3.0, &duv);
    /* the range ends are inclusive to the solver's precision */
    r.cct_valid = isfinite(T) && fabs(duv) <= 0.05 && T >= lo_K * (1 - 1e-9) && T <= hi_K * (1 + 1e-9);
    if (r.cct_valid) r.cct_K = T, r.duv = duv;
    if (solved_K) *solved_K = isfinite(T) && fabs(duv) <= 0.05 ? T : NAN;
    *out = r;
    return LX_OK;
}

/* The CCT a Planckian radiator at T_K shows when sampled at the spectrum's wavelengths and integrated
 * by the same method (the data's sampling moves it: a 1000 K blackbody summed at 5 nm solves to
 * 999.99935 K, a 100000 K one to 100066 K). NaN when that cannot be computed. */
static double apparent_cct(lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method, double T_K)
{
    double *v = malloc(spd->n * sizeof *v);
    if (!v) return NAN;
    for (size_t i = 0; i < spd->n; i++) v[i] = lx_planck(spd->lambda_nm[i], T_K);
    lx_spd p = *spd;
    p.value = v;
    lx_function f0 = obs == LX_OBSERVER_2 ? LX_FN_XBAR_2 : LX_FN_XBAR_10;
    double xyz[3], T = NAN, duv;
    int ok = 1;
    for (int k = 0; k < 3 && ok; k++) {
        lx_spd w;
        ok = lx_function_get(ctx, f0 + k, &w) == LX_OK && lx_spd_integrate(ctx, &p, &w, method, &xyz[k]) == LX_OK;
    }
    double d = xyz[0] + 15 * xyz[1] + 3 * xyz[2];
    if (ok && d > 0) T = solve_cct(ctx, obs, 4 * xyz[0] / d, 6 * xyz[1] / d, &duv);
    free(v);
    return T;
}

void lx__cct_range_ends(lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method, double *lo_K, double *hi_K)
{
    double lo = apparent_cct(ctx, spd, obs, method, 1000.0), hi = apparent_cct(ctx, spd, obs, method, 100000.0);
    *lo_K = isfinite(lo) ? fmin(lo, 1000.0) : 1000.0;
    *hi_K = isfinite(hi) ? fmax(hi, 100000.0) : 100000.0;
}

lx_status lx_colorimetry_from_integrals(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime,
                                        double radiant, lx_colorimetry *out)
{
    return lx__colorimetry_range(ctx, obs, xyz, vprime, radiant, 1000.0, 100000.0, out, NULL);
}

lx_status lx_spd_colorimetry(lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method, lx_colorimetry *out)
{
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "output is NULL");
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    method = lx_method_resolve(spd, method);
    lx_function f0 = obs == LX_OBSERVER_2 ? LX_FN_XBAR_2 : LX_FN_XBAR_10;
    double xyz[3], scot, radiant;
    for (int k = 0; k < 3; k++) {
        lx_spd w;
        if ((st = lx_function_get(ctx, f0 + k, &w)) != LX_OK) return st;
        if ((st = lx_spd_integrate(ctx, spd, &w, method, &xyz[k])) != LX_OK) return st;
    }
    lx_spd vp;
    if ((st = lx_function_get(ctx, LX_FN_VPRIME, &vp)) != LX_OK) return st;
    if ((st = lx_spd_integrate(ctx, spd, &vp, method, &scot)) != LX_OK) return st;
    if ((st = lx_spd_integrate_radiant(ctx, spd, method, &radiant)) != LX_OK) return st;
    lx_colorimetry r;
    r.method = method;
    double T;
    st = lx__colorimetry_range(ctx, obs, xyz, scot, radiant, 1000.0, 100000.0, &r, &T);
    /* near an end of 1000-100000 K: the ends as a Planckian radiator shows them through this
     * spectrum's sampling and method, so a blackbody at an end is in the range to the solver's
     * precision whatever the step */
    if (st == LX_OK && !r.cct_valid && isfinite(T) && (fabs(T / 1000.0 - 1) < 0.01 || fabs(T / 100000.0 - 1) < 0.01)) {
        double lo, hi;
        lx__cct_range_ends(ctx, spd, obs, method, &lo, &hi);
        st = lx__colorimetry_range(ctx, obs, xyz, scot, radiant, lo, hi, &r, NULL);
    }
    if (st == LX_OK) *out = r;
    return st;
}
