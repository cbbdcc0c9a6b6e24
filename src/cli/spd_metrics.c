/* spd_metrics.c - `luxcalc spd --metrics`: CIE 13.3 CRI, CIE 224 / TM-30, CIE S 026 alpha-opic and
 * CIE 191 mesopic columns, in the fixed order of ../shared/CLI.md followed by the extra columns; then
 * the instrument's own results (vendor_*), PAR (ANSI/ASABE S640), IEC 62471 hazards and LED binning. */
#include "spd_metrics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { G_CRI = 1, G_TM30 = 2, G_AO = 4, G_MES = 8, G_VENDOR = 16, G_PAR = 32, G_HAZ = 64, G_BIN = 128 };
#define G_BATCHABLE (G_VENDOR | G_PAR | G_HAZ | G_BIN)

/* Column kinds: where each value comes from. */
enum { K_RA, K_R, K_RF, K_RG, K_MEL_EDI, K_MEL_DER, K_AO_E, K_CRI_VALID, K_CRI_DC, K_RF_H, K_RCS_H, K_RHS_H,
       K_AO_EDI, K_AO_DER, K_MES_L, K_MES_M, K_VEND, K_PAR, K_HZ, K_HZ_COV, K_HZ_GROUP, K_HZ_BASIS, K_HZ_ALPHA, K_HZ_NOTCOV,
       K_BIN_ANSI, K_BIN_ANSI_DUV, K_BIN_FLEX, K_BIN_FLEX_DUV, K_BIN_SDCM, K_BIN_CENTRE };

/* the vendor columns, in lx_vendor_results order (index: the field's slot, see vendor_value) */
static const char *const vendor_cols[] = {"cct_K", "duv", "illuminance_lx", "X", "Y", "Z", "x", "y", "u_prime",
                                          "v_prime", "cri_ra"};
static const char *const hz_names[LX_HZ_COUNT] = {"blue", "thermal", "actinic_uv", "uva"};

typedef struct col {
    char name[40];
    int group, kind, index;
} col;

static col cols[CLI_METRICS_MAX];

/* ":LINE" after a file name in messages, or "" for a line below 0 (a streamed row: the file name
 * then says where, "FILE (data row N)") */
static const char *line_text(long line)
{
    static char buf[4][24];
    static int k;
    if (line < 0) return "";
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], ":%ld", line);
    return buf[k];
}
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
    char nm[40];
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
    /* the instrument's own results */
    for (int i = 0; i < 11; i++) snprintf(nm, sizeof nm, "vendor_%s", vendor_cols[i]), add(nm, G_VENDOR, K_VEND, i);
    for (int i = 0; i < 15; i++) snprintf(nm, sizeof nm, "vendor_cri_r%d", i + 1), add(nm, G_VENDOR, K_VEND, 11 + i);
    add("vendor_tm30_rf", G_VENDOR, K_VEND, 26);
    add("vendor_tm30_rg", G_VENDOR, K_VEND, 27);
    add("vendor_ppfd_umol_m2_s", G_VENDOR, K_VEND, 28);
    add("vendor_irradiance_W_m2", G_VENDOR, K_VEND, 29);
    add("vendor_peak_nm", G_VENDOR, K_VEND, 30);
    /* PAR */
    add("par_ppfd", G_PAR, K_PAR, 0);
    add("par_epar", G_PAR, K_PAR, 1);
    add("par_ypf", G_PAR, K_PAR, 2);
    add("par_photon_efficacy_umol_J", G_PAR, K_PAR, 3);
    add("par_dli_mol_m2_d", G_PAR, K_PAR, 4);
    /* IEC 62471 */
    for (int i = 0; i < LX_HZ_COUNT; i++) snprintf(nm, sizeof nm, "hazard_%s", hz_names[i]), add(nm, G_HAZ, K_HZ, i);
    for (int i = 0; i < LX_HZ_COUNT; i++)
        snprintf(nm, sizeof nm, "hazard_%s_coverage", hz_names[i]), add(nm, G_HAZ, K_HZ_COV, i);
    add("hazard_risk_group", G_HAZ, K_HZ_GROUP, 0);
    add("hazard_risk_basis", G_HAZ, K_HZ_BASIS, 0);
    add("hazard_subtense_rad", G_HAZ, K_HZ_ALPHA, 0);
    add("hazard_not_covered", G_HAZ, K_HZ_NOTCOV, 0);
    /* binning */
    add("binning_ansi_K", G_BIN, K_BIN_ANSI, 0);
    add("binning_ansi_duv_offset", G_BIN, K_BIN_ANSI_DUV, 0);
    add("binning_flex_K", G_BIN, K_BIN_FLEX, 0);
    add("binning_flex_duv_offset", G_BIN, K_BIN_FLEX_DUV, 0);
    add("binning_sdcm", G_BIN, K_BIN_SDCM, 0);
    add("binning_sdcm_centre", G_BIN, K_BIN_CENTRE, 0);
}

/* The equivalent-daylight columns are named by what they hold (CIE S 026: equivalent daylight
 * illuminance, luminance, flux, intensity): suffixes per --unit (relative keeps the EDI names). */
static const struct {
    const char *unit, *mel, *other;
} ed_names[] = {
    {"W/sr/m2/nm", "melanopic_edl_cd_m2", "_edl"},
    {"W/nm", "melanopic_ed_flux_lm", "_ed_flux"},
    {"W/sr/nm", "melanopic_ed_intensity_cd", "_ed_intensity"},
};

/* The name column i has for unit (a static buffer for the renamed ones). */
static const char *col_name(int i, const char *unit)
{
    static char buf[CLI_METRICS_MAX][40];
    int k = cols[i].kind;
    if (k != K_MEL_EDI && k != K_AO_EDI) return cols[i].name;
    for (size_t u = 0; u < sizeof ed_names / sizeof *ed_names; u++) {
        if (!unit || strcmp(unit, ed_names[u].unit)) continue;
        if (k == K_MEL_EDI) return ed_names[u].mel;
        /* "cyanopic_edi" -> "cyanopic_edl" etc. */
        size_t len = strlen(cols[i].name) - 4;
        snprintf(buf[i], sizeof buf[i], "%.*s%s", (int)len, cols[i].name, ed_names[u].other);
        return buf[i];
    }
    return cols[i].name;
}

/* 1 when tok names column i for some unit (the EDI names, or the names they have for another unit). */
static int names_col(const char *tok, int i)
{
    if (!strcmp(cols[i].name, tok)) return 1;
    for (size_t u = 0; u < sizeof ed_names / sizeof *ed_names; u++)
        if (!strcmp(col_name(i, ed_names[u].unit), tok)) return 1;
    return 0;
}

static int selected_groups(const cli_metrics *m)
{
    build();
    int g = 0;
    for (int i = 0; i < ncols; i++)
        if (m->sel[i]) g |= cols[i].group;
    return g;
}

int cli_metrics_batchable(const cli_metrics *m) { return (selected_groups(m) & ~G_BATCHABLE) == 0; }
int cli_metrics_need_par(const cli_metrics *m) { return (selected_groups(m) & G_PAR) != 0; }
int cli_metrics_need_hazard(const cli_metrics *m) { return (selected_groups(m) & G_HAZ) != 0; }
int cli_metrics_need_binning(const cli_metrics *m) { return (selected_groups(m) & G_BIN) != 0; }

int cli_metrics_parse(cli_metrics *m, const char *list, const char *cmd)
{
    build();
    char *copy = strdup(list ? list : "");
    if (!copy) return cli_error(cmd, "out of memory"), -1;
    int rc = 0;
    for (char *save = NULL, *tok = strtok_r(copy, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        while (*tok == ' ') tok++;
        int g = !strcmp(tok, "all") ? 0xff : !strcmp(tok, "cri") ? G_CRI : !strcmp(tok, "tm30") ? G_TM30
              : !strcmp(tok, "alphaopic") ? G_AO : !strcmp(tok, "mesopic") ? G_MES : !strcmp(tok, "vendor") ? G_VENDOR
              : !strcmp(tok, "par") ? G_PAR : !strcmp(tok, "hazard") ? G_HAZ : !strcmp(tok, "binning") ? G_BIN : 0;
        int found = 0;
        for (int i = 0; i < ncols; i++)
            if ((cols[i].group & g) || names_col(tok, i)) m->sel[i] = 1, found = 1;
        if (!found) {
            cli_error(cmd, "--metrics: unknown group or column '%s' (groups: all, cri, tm30, alphaopic, mesopic, vendor, "
                      "par, hazard, binning)", tok);
            rc = -1;
            break;
        }
        m->any = 1;
    }
    free(copy);
    return rc;
}

static const char *par_unit(const char *unit)
{
    return !strcmp(unit, "W/m2/nm") ? "umol/(s m2)" : !strcmp(unit, "W/nm") ? "umol/s" : !strcmp(unit, "W/sr/m2/nm")
           ? "umol/(s sr m2)" : !strcmp(unit, "W/sr/nm") ? "umol/(s sr)" : "";
}

static const char *hz_unit(const char *unit)
{
    return !strcmp(unit, "W/m2/nm") ? "W/m2" : !strcmp(unit, "W/nm") ? "W" : !strcmp(unit, "W/sr/m2/nm") ? "W/(sr m2)"
           : !strcmp(unit, "W/sr/nm") ? "W/sr" : "";
}

int cli_metrics_columns(const cli_metrics *m, const char *unit, const char **names, const char **units, int n)
{
    build();
    const char *edi_unit, *ao_unit;
    edi_unit = !strcmp(unit, "W/m2/nm") ? "lx" : !strcmp(unit, "W/sr/m2/nm") ? "cd/m2" : !strcmp(unit, "W/nm") ? "lm"
             : !strcmp(unit, "W/sr/nm") ? "cd" : "";
    ao_unit = hz_unit(unit);
    for (int i = 0; i < ncols; i++) {
        if (!m->sel[i]) continue;
        int k = cols[i].kind, x = cols[i].index;
        names[n] = col_name(i, unit);
        units[n] = k == K_MEL_EDI || k == K_AO_EDI ? edi_unit : k == K_AO_E ? ao_unit : k == K_MES_L ? "cd/m2"
                 : k == K_PAR ? (x < 3 ? par_unit(unit) : x == 3 ? "umol/J" : "mol/(m2 d)")
                 : k == K_HZ ? hz_unit(unit) : k == K_HZ_ALPHA ? "rad" : k == K_VEND ? (x == 0 ? "K" : x == 2 ? "lx" : "") : "";
        n++;
    }
    return n;
}

/* 1 when a column of kind k is selected. */
static int sel_kind(const cli_metrics *m, int k)
{
    for (int i = 0; i < ncols; i++)
        if (m->sel[i] && cols[i].kind == k) return 1;
    return 0;
}

void cli_cct_reason(lx_ctx *ctx, const lx_colorimetry *c, lx_observer obs, char *buf, size_t size)
{
    double d = c->X + 15 * c->Y + 3 * c->Z, T, duv;
    if (!(c->Y > 0) || !(d > 0)) snprintf(buf, size, "the spectrum has no luminous content");
    else if (lx_cct_from_uv(ctx, obs, c->u_prime, c->v_prime * 2.0 / 3.0, &T, &duv) != LX_OK)
        snprintf(buf, size, "no correlated colour temperature: %s", lx_ctx_errmsg(ctx));
    else if (fabs(duv) > 0.05) snprintf(buf, size, "Duv %.4f is beyond 0.05 (too far from the Planckian locus for a CCT)", duv);
    else snprintf(buf, size, "the CCT solves to %.6g K, outside 1000-100000 K", T);
}

static double vendor_value(const lx_vendor_results *v, int x)
{
    if (!v) return NAN;
    const double head[] = {v->cct_K, v->duv, v->illuminance_lx, v->X, v->Y, v->Z, v->x, v->y, v->u_prime, v->v_prime,
                           v->cri_ra};
    if (x < 11) return head[x];
    if (x < 26) return v->cri_r[x - 11];
    const double tail[] = {v->tm30_rf, v->tm30_rg, v->ppfd_umol_m2_s, v->irradiance_W_m2, v->peak_nm};
    return x - 26 < 5 ? tail[x - 26] : NAN;
}

/* How a criterion was judged, for hazard_risk_basis: the limit, and how the data reached its
 * quantity (the source's solid angle Omega from --subtense) or which source size was assumed. */
static const char *basis_text(lx_hazard_limit lim, int radiance, int alpha_given)
{
    switch (lim) {
    case LX_HZ_LIMIT_L_B:
        return !radiance ? "L_B (E_B/Omega)" : alpha_given ? "L_B" : "L_B (large source assumed)";
    case LX_HZ_LIMIT_E_B:
        return radiance ? "E_B (L_B*Omega)" : alpha_given ? "E_B" : "E_B (small source assumed)";
    case LX_HZ_LIMIT_L_R: return radiance ? "L_R" : "L_R (E_R/Omega)";
    case LX_HZ_LIMIT_E_S: return "E_S";
    case LX_HZ_LIMIT_E_UVA: return "E_UVA";
    default: return "";
    }
}

/* Appends the cells of the groups computed elsewhere (vendor, PAR, hazard, binning) for column i;
 * returns 0 when column i is not one of them. */
static int append_lab(cli_table *t, const cli_metrics *m, int i, const char *unit, const lx_par *par,
                      const lx_hazard *hz, const lx_hazard_risk *risk, const lx_binning *bin,
                      const lx_vendor_results *vendor)
{
    int x = cols[i].index, radiance = !strcmp(unit, "W/sr/m2/nm"), irradiance = !strcmp(unit, "W/m2/nm");
    (void)m;
    switch (cols[i].kind) {
    case K_VEND: cli_table_num(t, vendor_value(vendor, x)); return 1;
    case K_PAR: {
        double v = !par ? NAN : x == 0 ? par->ppfd : x == 1 ? par->epar : x == 2 ? par->ypf : x == 3
                 ? par->photon_efficacy_umol_J : irradiance ? lx_par_dli(par->ppfd, m->photoperiod_h) : NAN;
        if (par && x < 3 && isnan(v)) cli_table_str(t, "not covered");
        else cli_table_num(t, v);
        return 1;
    }
    case K_HZ:
        if (hz && isnan(hz->value[x])) cli_table_str(t, "not covered");
        else cli_table_num(t, hz ? hz->value[x] : NAN);
        return 1;
    case K_HZ_COV: cli_table_num(t, hz ? hz->coverage[x] : NAN); return 1;
    case K_HZ_GROUP: cli_table_str(t, risk ? lx_risk_group_name(risk->group) : ""); return 1;
    case K_HZ_BASIS: {
        char buf[160] = "";
        for (int k = 0; risk && k < LX_HZ_COUNT; k++)
            if (risk->criterion[k] != LX_RISK_NONE)
                snprintf(buf + strlen(buf), sizeof buf - strlen(buf), "%s%s", *buf ? "," : "",
                         basis_text(risk->limit[k], radiance, m->subtense_rad > 0));
        cli_table_str(t, risk ? buf : "");
        return 1;
    }
    case K_HZ_ALPHA: cli_table_num(t, risk && m->subtense_rad > 0 ? m->subtense_rad : NAN); return 1;
    case K_HZ_NOTCOV: {
        char buf[64] = "";
        for (int k = 0; hz && k < LX_HZ_COUNT; k++)
            if (isnan(hz->value[k]))
                snprintf(buf + strlen(buf), sizeof buf - strlen(buf), "%s%s", *buf ? "," : "", hz_names[k]);
        cli_table_str(t, buf);
        return 1;
    }
    case K_BIN_ANSI:
        if (bin && bin->ansi_K) cli_table_int(t, bin->ansi_K);
        else cli_table_num(t, NAN);
        return 1;
    case K_BIN_ANSI_DUV: cli_table_num(t, bin ? bin->ansi_duv_offset : NAN); return 1;
    case K_BIN_FLEX:
        if (bin && bin->flex_K) cli_table_int(t, bin->flex_K);
        else cli_table_num(t, NAN);
        return 1;
    case K_BIN_FLEX_DUV: cli_table_num(t, bin ? bin->flex_duv_offset : NAN); return 1;
    case K_BIN_SDCM: cli_table_num(t, bin ? bin->sdcm : NAN); return 1;
    case K_BIN_CENTRE: {
        char buf[40] = "";
        if (bin && bin->sdcm_centre_K) snprintf(buf, sizeof buf, "IEC 60081 F%d", bin->sdcm_centre_K);
        cli_table_str(t, buf);
        return 1;
    }
    default: return 0;
    }
}

/* The risk group of h for the file's unit (only radiance and irradiance have limits). */
static int risk_of(lx_ctx *ctx, const cli_metrics *m, const char *unit, const lx_hazard *h, lx_hazard_risk *r)
{
    int radiance = !strcmp(unit, "W/sr/m2/nm"), irradiance = !strcmp(unit, "W/m2/nm");
    if (!radiance && !irradiance) return 0;
    return lx_hazard_risk_group(ctx, h, radiance, m->subtense_rad, r) == LX_OK;
}

void cli_metrics_row_batch(cli_table *t, lx_ctx *ctx, const cli_metrics *m, const char *unit, const lx_par *par,
                           const lx_hazard *hz, const lx_binning *bin, const lx_vendor_results *vendor)
{
    build();
    lx_hazard_risk risk;
    int have_risk = hz && risk_of(ctx, m, unit, hz, &risk);
    for (int i = 0; i < ncols; i++)
        if (m->sel[i] && !append_lab(t, m, i, unit, par, hz, have_risk ? &risk : NULL, bin, vendor))
            cli_table_num(t, NAN); /* not a batch column (cli_metrics_batchable said none is selected) */
}

/* An empty binning cell says why on stderr (a missing CCT has said so already). */
static void say_binning_empty(const char *cmd, const char *file, long line, const char *label, const cli_metrics *m,
                              const lx_colorimetry *cc, const lx_binning *bin)
{
    if (!isfinite(cc->cct_K) || (bin->ansi_K != 0 && bin->flex_K != 0)) return;
    if (!(sel_kind(m, K_BIN_ANSI) || sel_kind(m, K_BIN_ANSI_DUV) || sel_kind(m, K_BIN_FLEX) || sel_kind(m, K_BIN_FLEX_DUV)))
        return;
    int both = bin->ansi_K == 0 && bin->flex_K == 0;
    cli_error(cmd,
              "%s%s: spectrum '%s': %s empty: CCT %.1f K, Duv %.5f lies in no %s of ANSI C78.377-2017 "
              "(nominal 2200-6500 K, flexible 2700-6500 K; Duv within 0.006 of the target)",
              file, line_text(line), label,
              both ? "binning_ansi_* and binning_flex_*" : bin->ansi_K == 0 ? "binning_ansi_*" : "binning_flex_*",
              cc->cct_K, cc->duv,
              both ? "quadrangle and no flexible-CCT bin" : bin->ansi_K == 0 ? "nominal-CCT quadrangle" : "flexible-CCT bin");
}

int cli_metrics_row(cli_table *t, lx_ctx *ctx, const cli_metrics *m, const lx_spd *spd, lx_method method,
                    const char *unit, const lx_colorimetry *c, const lx_vendor_results *vendor, const char *file,
                    long line, const char *cmd)
{
    int bad = 0;
    build();
    int need = selected_groups(m);
    const char *label = spd->name ? spd->name : "";
    lx_cri cri;
    lx_tm30 *tm = NULL;
    lx_alphaopic ao;
    lx_par par;
    lx_hazard hz;
    lx_hazard_risk risk;
    lx_binning bin;
    int have_cri = 0, have_tm = 0, have_ao = 0, have_mes = 0, have_par = 0, have_hz = 0, have_risk = 0, have_bin = 0;
    double lmes = NAN, mm = NAN;
    if ((need & G_CRI)) {
        have_cri = lx_cri_compute(ctx, spd, &cri) == LX_OK;
        if (!have_cri && !cli_quiet) cli_error(cmd, "%s%s: spectrum '%s': %s", file, line_text(line), label, lx_ctx_errmsg(ctx));
    }
    if ((need & G_TM30) && (tm = malloc(sizeof *tm)) != NULL) {
        have_tm = lx_tm30_compute(ctx, spd, tm) == LX_OK;
        if (!have_tm && !cli_quiet) cli_error(cmd, "%s%s: spectrum '%s': %s", file, line_text(line), label, lx_ctx_errmsg(ctx));
    }
    int say = !cli_quiet;
    if ((need & G_AO)) {
        have_ao = lx_alphaopic_compute(ctx, spd, method, &ao) == LX_OK;
        if (!have_ao && say) cli_error(cmd, "%s%s: spectrum '%s': alpha-opic columns empty: %s", file, line_text(line), label, lx_ctx_errmsg(ctx));
        else if (say && !(ao.illuminance != 0) && (sel_kind(m, K_MEL_DER) || sel_kind(m, K_AO_DER)))
            cli_error(cmd, "%s%s: spectrum '%s': the DER columns are empty: the spectrum has no luminous content", file, line_text(line),
                      label);
    }
    if ((need & G_MES)) {
        /* only luminance is meaningful here: L_p = Y, L_s with K'm = 1699 lm/W as CIE 191 uses
         * (the ratio first: scotopic_Y near the top of the double range times 1699 would overflow) */
        if (!strcmp(unit, "W/sr/m2/nm")) {
            have_mes = lx_mesopic_luminance(ctx, c->Y, c->scotopic_Y * (1699.0 / 1700.06), &lmes, &mm) == LX_OK;
            if (!have_mes && say)
                cli_error(cmd, "%s%s: spectrum '%s': mesopic columns empty: %s", file, line_text(line), label, lx_ctx_errmsg(ctx));
        } else if (say) {
            cli_error(cmd, "%s%s: spectrum '%s': mesopic columns empty: they need luminance (--unit W/sr/m2/nm, not %s)",
                      file, line_text(line), label, unit);
        }
    }
    if (have_tm && say && isnan(tm->rg)) {
        /* an empty hue bin: no gamut polygon (TM-30 needs all 16) */
        char bins[96] = "";
        size_t off = 0;
        for (int b = 0; b < 16; b++)
            if (isnan(tm->rf_hue[b]) && off < sizeof bins - 4) off += (size_t)snprintf(bins + off, sizeof bins - off, "%s%d", off ? ", " : "", b + 1);
        cli_error(cmd, "%s%s: spectrum '%s': tm30_rg (and those bins' tm30_*_h values) empty: hue bin%s %s hold%s none of "
                       "the 99 colour evaluation samples under the reference (%.0f K), so TM-30's gamut polygon is undefined",
                  file, line_text(line), label, strchr(bins, ',') ? "s" : "", bins, strchr(bins, ',') ? "" : "s", tm->cct_K);
    }
    if ((need & G_PAR)) have_par = lx_par_compute(ctx, spd, method, &par) == LX_OK;
    if ((need & G_HAZ)) {
        have_hz = lx_hazard_compute(ctx, spd, method, &hz) == LX_OK;
        have_risk = have_hz && risk_of(ctx, m, unit, &hz, &risk);
    }
    if ((need & G_BIN)) { /* ANSI binning is defined in CIE 1931 2 deg */
        lx_colorimetry c2;
        const lx_colorimetry *cc = c;
        if (m->observer == LX_OBSERVER_10 && lx_spd_colorimetry(ctx, spd, LX_OBSERVER_2, method, &c2) == LX_OK) cc = &c2;
        have_bin = lx_binning_compute(ctx, cc->x, cc->y, cc->cct_K, cc->duv, &bin) == LX_OK;
        if (have_bin && say) say_binning_empty(cmd, file, line, label, m, cc, &bin);
    }
    for (int i = 0; i < ncols; i++) {
        if (!m->sel[i]) continue;
        int x = cols[i].index;
        double v = NAN;
        if (append_lab(t, m, i, unit, have_par ? &par : NULL, have_hz ? &hz : NULL, have_risk ? &risk : NULL,
                       have_bin ? &bin : NULL, vendor))
            continue;
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
        /* the empties explained above: Rg and the hue bins with no sample, DER without light */
        int k = cols[i].kind;
        if (have_tm && (k == K_RG || k == K_RF_H || k == K_RCS_H || k == K_RHS_H) && isnan(tm->rg) && isnan(v)) computed = 0;
        if (have_ao && (k == K_MEL_DER || k == K_AO_DER) && !(ao.illuminance != 0)) computed = 0;
        if (computed && !isfinite(v)) {
            cli_error(cmd, "%s%s: spectrum '%s': %s is not finite (%s)", file, line_text(line), label, cols[i].name,
                      isnan(v) ? "NaN" : "infinite");
            bad++;
        }
        cli_table_num(t, v);
    }
    free(tm);
    return bad;
}
