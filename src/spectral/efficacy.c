/* efficacy.c - the luminous efficacy of radiation of a measured spectrum file, for the
 * radiometric <-> photometric conversions of the lighting commands (uses the spectra API). */
#include "spectral/spectral_private.h"

#include <math.h>

lx_status lx_efficacy_from_spd_file(lx_ctx *ctx, const char *path, double *ler_lm_per_W)
{
    LX__NEED_CTX(ctx);
    if (!path || !ler_lm_per_W) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_efficacy_from_spd_file: NULL argument");
    lx_spd_set *set = NULL;
    lx_status st = lx_spd_read_file(ctx, path, &set);
    if (st != LX_OK) return st;
    if (set->count != 1) {
        st = lx__error(ctx, LX_EINVAL, path, 0, "holds %zu spectra; the efficacy needs exactly one", set->count);
        lx_spd_set_free(set);
        return st;
    }
    lx_colorimetry c;
    st = lx_spd_colorimetry(ctx, &set->spd[0], LX_OBSERVER_2, LX_METHOD_AUTO, &c);
    if (st == LX_OK && !(c.ler_lm_per_W > 0 && isfinite(c.ler_lm_per_W)))
        st = lx__error(ctx, LX_ERANGE, path, set->line ? set->line[0] : 0,
                       "the spectrum has no luminous efficacy (radiant integral %g, Y %g)", c.radiant, c.Y);
    if (st == LX_OK) *ler_lm_per_W = c.ler_lm_per_W;
    lx_spd_set_free(set);
    return st;
}
