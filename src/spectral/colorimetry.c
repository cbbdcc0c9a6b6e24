/* colorimetry.c - all colorimetric and photometric quantities of one spectrum: absolute XYZ,
 * chromaticities, CCT and Duv, luminous efficacy of radiation, scotopic quantities. */
#include "spectral/spectral_private.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


static lx_status overflow_check(lx_ctx *ctx, const lx_colorimetry *r, double max_abs);

/* The CCT of u, v (NaN when the solver finds none), keeping the context's error state (an undefined
 * CCT is a result, not an error). */
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

/* The CCT of u, v by the fast table (cct_fast.c): 1 with *T, *duv when the answer is clear of the
 * validity edges (|Duv| 0.05, lo_K, hi_K: there the two solvers' last bits could disagree, so the
 * exact one decides), 1 with T NaN when the fast answer says there is no CCT to report, 0 when the
 * exact solver must decide. An invalid fast answer is final: within 0.1 of the locus the root it
 * finds is the only one (cct_fast.c), so a point it puts farther than 0.05 from the locus, or whose
 * root it finds outside its table (900 K - 120000 K, beyond the range ends), has no CCT in the
 * range within 0.05 either. */
static int fast_cct(lx_observer obs, double u, double v, double lo_K, double hi_K, double *T, double *duv)
{
    double t, d;
    *T = *duv = NAN;
    if (!lx__cct_fast(obs, u, v, &t, &d)) return 1; /* beyond the table: CCT outside the range, or |Duv| > 0.1 */
    double ad = fabs(d);
    if (fabs(ad - 0.05) < 1e-9 || fabs(t / lo_K - 1) < 1e-7 || fabs(t / hi_K - 1) < 1e-7) return 0;
    if (ad <= 0.05) *T = t, *duv = d;
    return 1;
}

static lx_status colorimetry(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime, double radiant,
                             double lo_K, double hi_K, int fast, lx_colorimetry *out, double *solved_K)
{
    LX__NEED_CTX(ctx);
    if (!out || !xyz) return lx__error(ctx, LX_EINVAL, NULL, 0, "integrals and output are required");
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    double km = obs == LX_OBSERVER_2 ? LX__KM_2 : LX__KM_10;
    lx_colorimetry r;
    memset(&r, 0, sizeof r); /* reserved included (ABI policy) */
    r.method = out->method;
    r.X = km * xyz[0];
    r.Y = km * xyz[1];
    r.Z = km * xyz[2];
    /* chromaticities of finite X, Y, Z near the top of the range: their sums scaled by a power
     * of two (exact; ratios unchanged), so they do not overflow */
    double X = r.X, Y = r.Y, Z = r.Z, s = X + Y + Z, d = X + 15 * Y + 3 * Z;
    if ((!isfinite(s) || !isfinite(d)) && isfinite(X) && isfinite(Y) && isfinite(Z)) {
        int e = 0;
        frexp(fmax(fabs(X), fmax(fabs(Y), fabs(Z))), &e);
        X = ldexp(X, -e - 4), Y = ldexp(Y, -e - 4), Z = ldexp(Z, -e - 4);
        s = X + Y + Z, d = X + 15 * Y + 3 * Z;
    }
    r.x = s != 0 ? X / s : NAN;
    r.y = s != 0 ? Y / s : NAN;
    r.u_prime = d != 0 ? 4 * X / d : NAN;
    r.v_prime = d != 0 ? 9 * Y / d : NAN;
    r.radiant = radiant;
    r.ler_lm_per_W = radiant != 0 ? r.Y / radiant : NAN;
    r.scotopic_Y = LX__KM_SCOT * vprime;
    r.sp_ratio = r.Y != 0 ? r.scotopic_Y / r.Y : NAN;
    r.cct_K = r.duv = NAN;
    r.cct_valid = 0;
    double T = NAN, duv = NAN, u = r.u_prime, v = r.v_prime * 2.0 / 3.0;
    /* solved_K asks for a CCT outside the range too: only the exact solver has the whole locus */
    if (d != 0 && isfinite(u) && !(fast && !solved_K && fast_cct(obs, u, v, lo_K, hi_K, &T, &duv)))
        T = solve_cct(ctx, obs, u, v, &duv);
    /* the range ends are inclusive to the solver's precision */
    r.cct_valid = isfinite(T) && fabs(duv) <= 0.05 && T >= lo_K * (1 - 1e-9) && T <= hi_K * (1 + 1e-9);
    if (r.cct_valid) r.cct_K = T, r.duv = duv;
    if (solved_K) *solved_K = isfinite(T) && fabs(duv) <= 0.05 ? T : NAN;
    *out = r;
    return LX_OK;
}

lx_status lx__colorimetry_range(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime, double radiant,
                                double lo_K, double hi_K, lx_colorimetry *out, double *solved_K)
{
    return colorimetry(ctx, obs, xyz, vprime, radiant, lo_K, hi_K, 0, out, solved_K);
}

lx_status lx__colorimetry_fast(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime, double radiant,
                               double lo_K, double hi_K, lx_colorimetry *out)
{
    return colorimetry(ctx, obs, xyz, vprime, radiant, lo_K, hi_K, 1, out, NULL);
}

lx_status lx_colorimetry_from_integrals(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime,
                                        double radiant, lx_colorimetry *out)
{
    return lx__colorimetry_range(ctx, obs, xyz, vprime, radiant, 1000.0, 100000.0, out, NULL);
}

/* The CCT a Planckian radiator at T_K shows when sampled at the spectrum's wavelengths and integrated
 * by the same method (the data's sampling moves it: a 1000 K blackbody summed at 5 nm solves to
 * 999.99935 K, a 100000 K one to 100066 K). NaN when that cannot be computed. */
static double apparent_cct(lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method, double T_K)
{
    double *v = lx__alloc_n(spd->n, sizeof *v);
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
    lx__free(v);
    return T;
}

void lx__cct_range_ends(lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method, double *lo_K, double *hi_K)
{
    double lo = apparent_cct(ctx, spd, obs, method, 1000.0), hi = apparent_cct(ctx, spd, obs, method, 100000.0);
    *lo_K = isfinite(lo) ? fmin(lo, 1000.0) : 1000.0;
    *hi_K = isfinite(hi) ? fmax(hi, 100000.0) : 100000.0;
}

lx_status lx_spd_colorimetry(lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method, lx_colorimetry *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "output is NULL");
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    /* values near the bottom of the range: the colorimetry of the spectrum scaled up by 2^-e
     * (exact), its absolute quantities scaled back; chromaticities, CCT and ratios as they are */
    lx_spd up;
    double *ubuf;
    int te = lx__spd_tiny_scale(spd, &up, &ubuf);
    if (te == INT_MIN) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (te) {
        lx_colorimetry r;
        st = lx_spd_colorimetry(ctx, &up, obs, method, &r);
        lx__free(ubuf);
        if (st != LX_OK) return st;
        r.X = ldexp(r.X, te), r.Y = ldexp(r.Y, te), r.Z = ldexp(r.Z, te);
        r.radiant = ldexp(r.radiant, te), r.scotopic_Y = ldexp(r.scotopic_Y, te);
        *out = r;
        return LX_OK;
    }
    method = lx_method_resolve(spd, method);
    lx_function f0 = obs == LX_OBSERVER_2 ? LX_FN_XBAR_2 : LX_FN_XBAR_10;
    double xyz[3], scot, radiant;
    static const char *const name[] = {"X", "Y", "Z", "scotopic_Y", "radiant"};
    for (int k = 0; k < 5 && st == LX_OK; k++) {
        lx_spd w;
        if (k < 4 && (st = lx_function_get(ctx, k < 3 ? f0 + k : LX_FN_VPRIME, &w)) != LX_OK) return st;
        st = k < 3 ? lx_spd_integrate(ctx, spd, &w, method, &xyz[k])
             : k == 3 ? lx_spd_integrate(ctx, spd, &w, method, &scot)
                      : lx_spd_integrate_radiant(ctx, spd, method, &radiant);
        if (st == LX_ERANGE) { /* an integral beyond the double range: say which quantity */
            char mb[48];
            lx__fmt_magnitude(mb, sizeof mb, lx__spd_max_abs(spd));
            return lx__error(ctx, st, NULL, 0, "integral overflows: values up to %s give %s beyond the double range", mb, name[k]);
        }
    }
    if (st != LX_OK) return st;
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
    if (st == LX_OK && (st = overflow_check(ctx, &r, lx__spd_max_abs(spd))) == LX_OK) *out = r;
    return st;
}

/* LX_ERANGE when an integral (times Km) left the double range. */
static lx_status overflow_check(lx_ctx *ctx, const lx_colorimetry *r, double max_abs)
{
    const struct {
        const char *name;
        double v;
    } q[] = {{"X", r->X}, {"Y", r->Y}, {"Z", r->Z}, {"scotopic_Y", r->scotopic_Y}, {"radiant", r->radiant}};
    for (size_t i = 0; i < sizeof q / sizeof *q; i++)
        if (!isfinite(q[i].v)) {
            if (!isfinite(max_abs))
                return lx__error(ctx, LX_ERANGE, NULL, 0, "integral overflows: %s is beyond the double range", q[i].name);
            char mb[48];
            lx__fmt_magnitude(mb, sizeof mb, max_abs);
            return lx__error(ctx, LX_ERANGE, NULL, 0, "integral overflows: values up to %s give %s beyond the double range", mb,
                             q[i].name);
        }
    return LX_OK;
}

lx_status lx_colorimetry_check(lx_ctx *ctx, const lx_colorimetry *r, double max_abs)
{
    LX__NEED_CTX(ctx);
    if (!r) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_colorimetry_check: NULL result");
    lx_status st = overflow_check(ctx, r, max_abs);
    if (st != LX_OK) return st;
    /* the always-defined quantities: a NaN here is reported with its name and its cause */
    double sum = r->X + r->Y + r->Z;
    const struct {
        const char *name;
        double v;
        const char *why;
    } q[] = {
        {"x", r->x, sum == 0 ? "X + Y + Z = 0 (no luminous content)" : NULL},
        {"y", r->y, sum == 0 ? "X + Y + Z = 0 (no luminous content)" : NULL},
        {"u_prime", r->u_prime, "X + 15 Y + 3 Z = 0"},
        {"v_prime", r->v_prime, "X + 15 Y + 3 Z = 0"},
        {"ler_lm_per_W", r->ler_lm_per_W, r->radiant == 0 ? "the radiant integral is 0" : NULL},
        {"sp_ratio", r->sp_ratio, r->Y == 0 ? "Y = 0" : NULL},
    };
    for (size_t i = 0; i < sizeof q / sizeof *q; i++)
        if (!isfinite(q[i].v))
            return lx__error(ctx, LX_ERANGE, NULL, 0, "%s is undefined (%s): %s", q[i].name, isnan(q[i].v) ? "NaN" : "infinite",
                             q[i].why ? q[i].why : "not finite in double arithmetic");
    return LX_OK;
}
