/* colorimetry.c - all colorimetric and photometric quantities of one spectrum: absolute XYZ,
 * chromaticities, CCT and Duv, luminous efficacy of radiation, scotopic quantities. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <string.h>


static lx_status overflow_check(lx_ctx *ctx, const lx_colorimetry *r, double max_abs);

/* The CCT columns of r from its u', v': by the fast table (cct_fast.c) when fast and the answer is
 * clear of the validity edges (|Duv| 0.05, 1000 K, 100000 K: there the two solvers' last bits could
 * disagree, so the exact one decides), else by the exact solver. An invalid fast answer is final:
 * within 0.1 of the locus the root it finds is the only one (cct_fast.c), so a point it puts
 * farther than 0.05 from the locus, or whose root it finds outside its table (900 K - 120000 K),
 * has no CCT in 1000 K - 100000 K within 0.05 either. */
static void cct_columns(lx_ctx *ctx, lx_observer obs, lx_colorimetry *r, int fast)
{
    double u = r->u_prime, v = r->v_prime * 2.0 / 3.0, T, duv;
    int got = fast ? lx__cct_fast(obs, u, v, &T, &duv) : 0;
    /* the nearest locus point beyond 900 K - 120000 K: CCT outside 1000-100000 K or |Duv| > 0.1 */
    if (fast && !got) return;
    if (got) {
        double ad = fabs(duv);
        int edge = fabs(ad - 0.05) < 1e-9 || fabs(T - 1000.0) < 1e-4 || fabs(T - 100000.0) < 1e-2;
        if (!edge) {
            r->cct_valid = ad <= 0.05 && T >= 1000.0 && T <= 100000.0;
            if (r->cct_valid) r->cct_K = T, r->duv = duv;
            return;
        }
    }
    /* an undefined CCT is a result, not an error: keep the context's error state */
    lx_status st0 = ctx->status;
    long line0 = ctx->errline;
    char msg0[LX__ERRMSG_MAX], file0[sizeof ctx->errfile];
    memcpy(msg0, ctx->errmsg, sizeof msg0);
    memcpy(file0, ctx->errfile, sizeof file0);
    if (lx_cct_from_uv(ctx, obs, u, v, &T, &duv) == LX_OK) {
        /* the range ends are inclusive to solver precision (a 1000 K blackbody solves to 1000 K - 1e-9) */
        r->cct_valid = fabs(duv) <= 0.05 && T >= 1000.0 * (1 - 1e-9) && T <= 100000.0 * (1 + 1e-9);
        if (r->cct_valid) r->cct_K = T, r->duv = duv;
    } else {
        ctx->status = st0;
        ctx->errline = line0;
        memcpy(ctx->errmsg, msg0, sizeof msg0);
        memcpy(ctx->errfile, file0, sizeof file0);
    }
}

lx_status lx__colorimetry_derive(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime, double radiant,
                                 int fast, lx_colorimetry *out)
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
    if (d != 0 && isfinite(r.u_prime)) cct_columns(ctx, obs, &r, fast);
    *out = r;
    return LX_OK;
}

lx_status lx_colorimetry_from_integrals(lx_ctx *ctx, lx_observer obs, const double xyz[3], double vprime,
                                        double radiant, lx_colorimetry *out)
{
    return lx__colorimetry_derive(ctx, obs, xyz, vprime, radiant, 0, out);
}

lx_status lx_spd_colorimetry(lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method, lx_colorimetry *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "output is NULL");
    if (obs != LX_OBSERVER_2 && obs != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "observer must be 2 or 10 degrees, not %d", (int)obs);
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
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
    st = lx_colorimetry_from_integrals(ctx, obs, xyz, scot, radiant, &r);
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
