/* scene_design.c - the deliverable's outputs of `luxcalc scene`: whether values are maintained or
 * new. */
#include "design.h"

#include <math.h>
#include <stdio.h>

const char *cli_scene_values(const lx_scene *sc, char *buf, size_t cap)
{
    const lx_scene_design *d = sc->design;
    if (!d || !d->maintained) {
        snprintf(buf, cap, "new (no maintenance factor)");
        return buf;
    }
    double lo = INFINITY, hi = -INFINITY;
    for (size_t l = 0; l < sc->n_lum; l++) {
        if (d->lum_mode[l] == LX_LUM_EMERGENCY) continue; /* dark in normal operation */
        lo = fmin(lo, d->lum_mf[l]), hi = fmax(hi, d->lum_mf[l]);
    }
    if (!(hi >= lo)) snprintf(buf, cap, "maintained");
    else if (lo == hi) snprintf(buf, cap, "maintained (MF %.4g)", lo);
    else snprintf(buf, cap, "maintained (MF %.4g to %.4g)", lo, hi);
    return buf;
}

void cli_scene_maintenance_text(FILE *f, const lx_scene *sc)
{
    const lx_scene_design *d = sc->design;
    if (!d || !d->maintained) return;
    for (size_t i = 0; i < d->n_maint; i++) {
        const lx_maintenance *m = &d->maint[i];
        fprintf(f, "  scheme %s: MF %.4g = LLMF %.4g x LSF %.4g x LMF %.4g x RSMF %.4g (CIE 97:2005)", m->name, m->mf,
                m->llmf, m->lsf, m->lmf, m->rsmf);
        if (isfinite(m->burning_h)) fprintf(f, "; %.6g h burning", m->burning_h);
        if (isfinite(m->cleaning_a)) fprintf(f, "; luminaires cleaned every %.3g a", m->cleaning_a);
        if (isfinite(m->room_cleaning_a)) fprintf(f, "; room every %.3g a", m->room_cleaning_a);
        fputc('\n', f);
    }
    for (size_t l = 0; l < sc->n_lum; l++)
        fprintf(f, "  %-12s MF %.4g%s%s%s\n", sc->lum[l].name, d->lum_mf[l], d->lum_maint[l] >= 0 ? " (scheme " : "",
                d->lum_maint[l] >= 0 ? d->maint[d->lum_maint[l]].name : "", d->lum_maint[l] >= 0 ? ")" : "");
}

void cli_scene_cylinder_summary(cli_table *t, const lx_scene_result *res, size_t a, size_t b)
{
    double sz = 0, ssz = 0, mlo = INFINITY, mhi = -INFINITY;
    size_t nz = 0, nsz = 0;
    for (size_t g = a; g < b; g++) {
        if (!isnan(res->cylindrical_lx[g])) sz += res->cylindrical_lx[g], nz++;
        if (!isnan(res->semicylindrical_lx[g])) ssz += res->semicylindrical_lx[g], nsz++;
        if (!isnan(res->modelling[g])) mlo = fmin(mlo, res->modelling[g]), mhi = fmax(mhi, res->modelling[g]);
    }
    cli_table_num(t, nz ? sz / (double)nz : NAN);
    cli_table_num(t, nsz ? ssz / (double)nsz : NAN);
    cli_table_num(t, mhi >= mlo ? mlo : NAN);
    cli_table_num(t, mhi >= mlo ? mhi : NAN);
}
