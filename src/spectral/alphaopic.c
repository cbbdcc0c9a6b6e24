/* alphaopic.c - CIE S 026:2018 alpha-opic irradiances, equivalent daylight (D65) illuminances
 * (EDI) and daylight efficacy ratios (DER), for one spectrum and for batches. */
#include "spectral/spectral_private.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


/* K_alpha,v^D65 in W/lm, CIE S 026:2018 Table 2 (alpha-opic ELR of D65); also in the provenance
 * header of src/data/cie_s026_alphaopic_1nm.csv. */
static const double k_d65[5] = {0.8173e-3, 1.4558e-3, 1.6289e-3, 1.4497e-3, 1.3262e-3};

double lx_alphaopic_d65_efficacy(lx_alphaopic_kind kind)
{
    if ((int)kind < 0 || (int)kind > 4) return NAN;
    return k_d65[kind];
}

lx_status lx_alphaopic_compute(lx_ctx *ctx, const lx_spd *spd, lx_method method, lx_alphaopic *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "alpha-opic: output is NULL");
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    lx_spd up; /* values near the bottom of the range: scaled up (exact), the absolute results back */
    double *ubuf;
    int te = lx__spd_tiny_scale(spd, &up, &ubuf);
    if (te == INT_MIN) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    if (te) {
        lx_alphaopic a;
        st = lx_alphaopic_compute(ctx, &up, method, &a);
        lx__free(ubuf);
        if (st != LX_OK) return st;
        for (int k = 0; k < 5; k++) a.irradiance[k] = ldexp(a.irradiance[k], te), a.edi[k] = ldexp(a.edi[k], te);
        a.illuminance = ldexp(a.illuminance, te);
        *out = a;
        return LX_OK;
    }
    method = lx_method_resolve(spd, method);
    lx_alphaopic r;
    memset(&r, 0, sizeof r); /* reserved included (ABI policy) */
    lx_spd w;
    for (int k = 0; k < 5; k++) {
        if ((st = lx_function_get(ctx, (lx_function)(LX_FN_ALPHA_SC + k), &w)) != LX_OK) return st;
        if ((st = lx_spd_integrate(ctx, spd, &w, method, &r.irradiance[k])) != LX_OK) return st;
    }
    double y;
    if ((st = lx_function_get(ctx, LX_FN_YBAR_2, &w)) != LX_OK) return st;
    if ((st = lx_spd_integrate(ctx, spd, &w, method, &y)) != LX_OK) return st;
    r.illuminance = LX__KM_2 * y;
    for (int k = 0; k < 5; k++) {
        r.edi[k] = r.irradiance[k] / k_d65[k];
        r.elr[k] = r.illuminance != 0 ? r.irradiance[k] / r.illuminance : NAN;
        r.der[k] = r.elr[k] / k_d65[k];
    }
    *out = r;
    return LX_OK;
}

lx_status lx_alphaopic_batch(lx_ctx *ctx, const lx_batch *batch, const lx_batch_opts *opts, double *out)
{
    LX__NEED_CTX(ctx);
    static const lx_function fns[6] = {LX_FN_ALPHA_SC, LX_FN_ALPHA_MC, LX_FN_ALPHA_LC,
                                       LX_FN_ALPHA_RH, LX_FN_ALPHA_MEL, LX_FN_YBAR_2};
    if (!batch || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "alpha-opic batch: NULL argument");
    lx_status st = lx_batch_integrate(ctx, batch, fns, 6, opts, out);
    if (st != LX_OK) return st;
    for (size_t i = 0; i < batch->n_spectra; i++) out[i * 6 + 5] *= LX__KM_2;
    return LX_OK;
}
