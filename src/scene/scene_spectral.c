/* scene_spectral.c - a source's spectral weights for scene sums: X, Z and the melanopic
 * irradiance per lux of its illuminance, from its SPD or from its CCT (Planck below 5000 K, CIE
 * daylight from 5000 K, as CIE 13.3 and CIE 224 choose their reference illuminants). */
#include "scene_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

lx_status lx__scene_spectrum_weights(lx_ctx *ctx, const char *file, long line, const lx_spd *spd, double cct_K,
                                     scene__spec *out)
{
    double lam[471], val[471];
    lx_spd gen = {"cct", 471, lam, val};
    lx_status st;
    if (!spd) {
        for (int i = 0; i < 471; i++) lam[i] = 360 + i;
        if (cct_K < 5000)
            for (int i = 0; i < 471; i++) val[i] = lx_planck(lam[i], cct_K);
        else if ((st = lx_daylight(ctx, cct_K, 471, lam, val)) != LX_OK)
            return lx__error(ctx, st, file, line, "cct %g K: %s", cct_K, lx_ctx_errmsg(ctx));
        spd = &gen;
    }
    lx_colorimetry c;
    lx_alphaopic a;
    if ((st = lx_spd_colorimetry(ctx, spd, LX_OBSERVER_2, LX_METHOD_AUTO, &c)) != LX_OK ||
        (ctx->counters.spectra_integrated++, st = lx_alphaopic_compute(ctx, spd, LX_METHOD_AUTO, &a)) != LX_OK) {
        char inner[LX__ERRMSG_MAX];
        snprintf(inner, sizeof inner, "%s", lx_ctx_errmsg(ctx));
        return lx__error(ctx, st, file, line, "spectrum: %s", inner);
    }
    ctx->counters.spectra_integrated++;
    if (!(c.Y > 0)) return lx__error(ctx, LX_ERANGE, file, line, "spectrum: no luminous content (Y = 0)");
    out->x_per_lx = c.X / c.Y;
    out->z_per_lx = c.Z / c.Y;
    /* the alpha-opic irradiance of the same spectrum over its own Y (683.002 lm/W * int S ybar) */
    out->mel_W_per_lx = a.irradiance[LX_AO_MEL] / c.Y;
    out->valid = 1;
    return LX_OK;
}
