/* unc_colour.h - the colour-rendering quantities of the uncertainty engine (unc_cri.c): CIE 13.3
 * and CIE 224 / TM-30 as functions of linear integrals of the spectrum. */
#ifndef LX_UNC_COLOUR_H
#define LX_UNC_COLOUR_H

#include "colour/colour_private.h"
#include "spectral/unc_private.h"

typedef struct lx__unc_cri_state lx__unc_cri_state;
typedef struct lx__unc_tm30_state lx__unc_tm30_state;

/* The CRI provider of spd (Ra, R1 .. R14; its integrals: the test source's X, Y, Z and the 14
 * samples' under it, on CIE 13.3's grid): *s its state, freed with lx__unc_cri_free. */
lx_status lx__unc_cri_provider(lx_ctx *ctx, const lx_spd *spd, lx__unc_cri_state **s, lx__unc_provider *p);
void lx__unc_cri_free(lx__unc_cri_state *s);
/* The TM-30 provider (Rf, Rg; integrals: the 2 deg X, Y, Z and the 10 deg white and 99 samples). */
lx_status lx__unc_tm30_provider(lx_ctx *ctx, const lx_spd *spd, lx__unc_tm30_state **s, lx__unc_provider *p);
void lx__unc_tm30_free(lx__unc_tm30_state *s);

#endif /* LX_UNC_COLOUR_H */
