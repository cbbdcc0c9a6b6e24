/* unc_colour.c - lx_spd_uncertainty, the entry point of the uncertainty engine: the spectral
 * layer's quantities (colorimetry, alpha-opic, PAR) and the colour-rendering ones (CIE 13.3 Ra and
 * R1-R14, CIE 224 / TM-30 Rf and Rg, from unc_cri.c) handed to the engine (spectral/unc_run.c) as
 * functions of linear integrals of the spectrum. */
#include "colour/colour_private.h"
#include "colour/unc_colour.h"

#include <stdlib.h>
#include <string.h>

lx_status lx_spd_uncertainty(lx_ctx *ctx, const lx_spd *spd, const lx_unc_model *m, const lx_unc_opts *opts,
                             lx_unc_result **out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: NULL output");
    *out = NULL;
    lx_status st = lx_spd_check(ctx, spd);
    if (st != LX_OK) return st;
    if (!m) return lx__error(ctx, LX_EINVAL, NULL, 0, "uncertainty: NULL model");
    unsigned want = opts && opts->quantities ? opts->quantities : LX_UNC_COLORIMETRY;
    lx__unc_spectral_state s;
    memset(&s, 0, sizeof s);
    s.obs = opts && opts->observer ? opts->observer : LX_OBSERVER_2;
    s.method = lx_method_resolve(spd, opts ? opts->integration : LX_METHOD_AUTO);
    lx__unc_provider prov[5];
    size_t np = 0;
    lx__unc_colorimetry_provider(&s, &prov[np++]); /* always: the Fourier model's N comes from its CCT */
    if (want & LX_UNC_ALPHAOPIC) lx__unc_alphaopic_provider(&s, &prov[np++]);
    if (want & LX_UNC_PAR) lx__unc_par_provider(&s, &prov[np++]);
    lx__unc_cri_state *cri = NULL;
    lx__unc_tm30_state *tm = NULL;
    if ((want & LX_UNC_CRI) && (st = lx__unc_cri_provider(ctx, spd, &cri, &prov[np])) == LX_OK) np++;
    if (st == LX_OK && (want & LX_UNC_TM30) && (st = lx__unc_tm30_provider(ctx, spd, &tm, &prov[np])) == LX_OK) np++;
    if (st == LX_OK) st = lx__unc_run(ctx, spd, m, opts, prov, np, out);
    lx__unc_cri_free(cri);
    lx__unc_tm30_free(tm);
    return st;
}
