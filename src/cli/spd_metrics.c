/* spd_metrics.c - `luxcalc spd --metrics`: CIE 13.3 CRI, CIE 224 / TM-30, CIE S 026 alpha-opic and
 * CIE 191 mesopic columns, in the fixed order of ../shared/CLI.md followed by the extra columns. */
#include "spd_metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { G_CRI = 1, G_TM30 = 2, G_AO = 4, G_MES = 8 };

/* Column kinds: where each value comes from. */
enum { K_RA, K_R, K_RF, K_RG, K_MEL_EDI, K_MEL_DER, K_AO_E, K_CRI_VALID, K_CRI_DC, K_RF_H, K_RCS_H, K_RHS_H,
       K_AO_EDI, K_AO_DER, K_MES_L, K_MES_M };

typedef struct col {
    char name[24];
    int group, kind, index;
} col;

static col cols[CLI_METRICS_MAX];
static int ncols;

static void add(const char *name, int group, int kind, int index)
{
    snprintf(cols[ncols].name, sizeof cols[ncols].name, "%s", name);
    cols[ncols].group = group, cols[ncols].kind = kind, cols[ncols].index = index;
    ncols++;
}

static const char *const ao_names[5] = {"sc", "mc", "lc", "rh", "mel"};

static void build(void)
{
    if (ncols) return;
    char nm[24];
    /* the contract columns (CLI.md), in this order */
    add("cri_ra", G_CRI, K_RA, 0);
    for (int i = 0; i < 14; i++) snprintf(nm, sizeof nm, "cri_r%d", i + 1), add(nm, G_CRI, K_R, i);
    add("tm30_rf", G_TM30, K_RF, 0);
    add("tm30_rg", G_TM30, K_RG, 0);
    add("melanopic_edi_lx", G_AO, K_MEL_EDI, 0);
    add("melanopic_der", G_AO, K_MEL_DER, 0);
    for (int i = 0; i < 5; i++) snprintf(nm, sizeof nm, "alphaopic_%s", ao_names[i]), add(nm, G_AO, K_AO_E, i);
    /* extras */
    add("cri_valid", G_CRI, K_CRI_VALID, 0);
    add("cri_dc", G_CRI, K_CRI_DC, 0);
    for (int i = 0; i < 16; i++) snprintf(nm, sizeof nm, "tm30_rf_h%d", i + 1), add(nm, G_TM30, K_RF_H, i);
    for (int i = 0; i < 16; i++) snprintf(nm, sizeof nm, "tm30_rcs_h%d", i + 1), add(nm, G_TM30, K_RCS_H, i);
    for (int i = 0; i < 16; i++) snprintf(nm, sizeof nm, "tm30_rhs_h%d", i + 1), add(nm, G_TM30, K_RHS_H, i);
    for (int i = 0; i < 4; i++) snprintf(nm, sizeof nm, "%sopic_edi", i == 0 ? "cyan" : i == 1 ? "chlor" : i == 2 ? "erythr" : "rhod"), add(nm, G_AO, K_AO_EDI, i);
    for (int i = 0; i < 4; i++) snprintf(nm, sizeof nm, "%sopic_der", i == 0 ? "cyan" : i == 1 ? "chlor" : i == 2 ? "erythr" : "rhod"), add(nm, G_AO, K_AO_DER, i);
    add("mesopic_cd_m2", G_MES, K_MES_L, 0);
    add("mesopic_m", G_MES, K_MES_M, 0);
}

int cli_metrics_parse(cli_metrics *m, const char *list, const char *cmd)
{
    build();
    char *copy = strdup(list ? list : "");
    if (!copy) return cli_error(cmd, "out of memory"), -1;
    int rc = 0;
    for (char *save = NULL, *tok = strtok_r(copy, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        while (*tok == ' ') tok++;
        int g = !strcmp(tok, "all") ? 0xff : !strcmp(tok, "cri") ? G_CRI : !strcmp(tok, "tm30") ? G_TM30
              : !strcmp(tok, "alphaopic") ? G_AO : !strcmp(tok, "mesopic") ? G_MES : 0;
        int found = 0;
        for (int i = 0; i < ncols; i++)
            if ((cols[i].group & g) || !strcmp(cols[i].name, tok)) m->sel[i] = 1, found = 1;
        if (!found) {
            cli_error(cmd, "--metrics: unknown group or column '%s' (groups: all, cri, tm30, alphaopic, mesopic)", tok);
            rc = -1;
            break;
        }
        m->any = 1;
    }
    free(copy);
    return rc;
}

int cli_metrics_columns(const cli_metrics *m, const char *unit, const char **names, const char **units, int n)
{
    build();
    static const char *edi_unit, *ao_unit;
    edi_unit = !strcmp(unit, "W/m2/nm") ? "lx" : !strcmp(unit, "W/sr/m2/nm") ? "cd/m2" : !strcmp(unit, "W/nm") ? "lm"
             : !strcmp(unit, "W/sr/nm") ? "cd" : "";
    ao_unit = !strcmp(unit, "W/m2/nm") ? "W/m2" : !strcmp(unit, "W/sr/m2/nm") ? "W/(sr m2)" : !strcmp(unit, "W/nm") ? "W"
            : !strcmp(unit, "W/sr/nm") ? "W/sr" : "";
    for (int i = 0; i < ncols; i++) {
        if (!m->sel[i]) continue;
        int k = cols[i].kind;
        names[n] = cols[i].name;
        units[n] = k == K_MEL_EDI || k == K_AO_EDI ? edi_unit : k == K_AO_E ? ao_unit : k == K_MES_L ? "cd/m2" : "";
        n++;
    }
    return n;
}

int cli_metrics_row(cli_table *t, lx_ctx *ctx, const cli_metrics *m, const lx_spd *spd, lx_method method,
                    const char *unit, const lx_colorimetry *c, const char *file, long line, const char *cmd)
{
    int bad = 0;
    build();
    int need = 0;
    for (int i = 0; i < ncols; i++)
        if (m->sel[i]) need |= cols[i].group;
    const char *label = spd->name ? spd->name : "";
    lx_cri cri;
    lx_tm30 *tm = NULL;
    lx_alphaopic ao;
    int have_cri = 0, have_tm = 0, have_ao = 0, have_mes = 0;
    double lmes = NAN, mm = NAN;
    if ((need & G_CRI)) {
        have_cri = lx_cri_compute(ctx, spd, &cri) == LX_OK;
        if (!have_cri && !cli_quiet) cli_error(cmd, "%s:%ld: spectrum '%s': %s", file, line, label, lx_ctx_errmsg(ctx));
    }
    if ((need & G_TM30) && (tm = malloc(sizeof *tm)) != NULL) {
        have_tm = lx_tm30_compute(ctx, spd, tm) == LX_OK;
        if (!have_tm && !cli_quiet) cli_error(cmd, "%s:%ld: spectrum '%s': %s", file, line, label, lx_ctx_errmsg(ctx));
    }
    if ((need & G_AO)) {
        have_ao = lx_alphaopic_compute(ctx, spd, method, &ao) == LX_OK;
        if (!have_ao && !cli_quiet) cli_error(cmd, "%s:%ld: spectrum '%s': alpha-opic: %s", file, line, label, lx_ctx_errmsg(ctx));
    }
    if ((need & G_MES) && !strcmp(unit, "W/sr/m2/nm")) {
        /* only luminance is meaningful here: L_p = Y, L_s with K'm = 1699 lm/W as CIE 191 uses
         * (the ratio first: scotopic_Y near the top of the double range times 1699 would overflow) */
        have_mes = lx_mesopic_luminance(ctx, c->Y, c->scotopic_Y * (1699.0 / 1700.06), &lmes, &mm) == LX_OK;
        if (!have_mes && !cli_quiet) cli_error(cmd, "%s:%ld: spectrum '%s': %s", file, line, label, lx_ctx_errmsg(ctx));
    }
    for (int i = 0; i < ncols; i++) {
        if (!m->sel[i]) continue;
        int x = cols[i].index;
        double v = NAN;
        switch (cols[i].kind) {
        case K_RA: if (have_cri) v = cri.ra; break;
        case K_R: if (have_cri) v = cri.r[x]; break;
        case K_CRI_DC: if (have_cri) v = cri.dc; break;
        case K_CRI_VALID:
            if (have_cri) cli_table_int(t, cri.valid);
            else cli_table_num(t, NAN);
            continue;
        case K_RF: if (have_tm) v = tm->rf; break;
        case K_RG: if (have_tm) v = tm->rg; break;
        case K_RF_H: if (have_tm) v = tm->rf_hue[x]; break;
        case K_RCS_H: if (have_tm) v = tm->rcs_hue[x]; break;
        case K_RHS_H: if (have_tm) v = tm->rhs_hue[x]; break;
        case K_MEL_EDI: if (have_ao) v = ao.edi[LX_AO_MEL]; break;
        case K_MEL_DER: if (have_ao) v = ao.der[LX_AO_MEL]; break;
        case K_AO_E: if (have_ao) v = ao.irradiance[x]; break;
        case K_AO_EDI: if (have_ao) v = ao.edi[x]; break;
        case K_AO_DER: if (have_ao) v = ao.der[x]; break;
        case K_MES_L: if (have_mes) v = lmes; break;
        case K_MES_M: if (have_mes) v = mm; break;
        }
        /* a metric its group computed must be a number: a NaN or infinity is reported, never a
         * silent blank (the undefined ones were reported above, with their reason) */
        int computed = (cols[i].group == G_CRI && have_cri) || (cols[i].group == G_TM30 && have_tm) ||
                       (cols[i].group == G_AO && have_ao) || (cols[i].group == G_MES && have_mes);
        if (computed && !isfinite(v)) {
            cli_error(cmd, "%s:%ld: spectrum '%s': %s is not finite (%s)", file, line, label, cols[i].name,
                      isnan(v) ? "NaN" : "infinite");
            bad++;
        }
        cli_table_num(t, v);
    }
    free(tm);
    return bad;
}
