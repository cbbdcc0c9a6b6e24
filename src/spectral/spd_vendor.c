/* spd_vendor.c - the results an instrument's firmware wrote beside the spectrum (Sekonic, UPRtek,
 * LI-COR): its header fields mapped by the names each format uses, for comparison with luxcalc's. */
#include "spectral/spectral_private.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { V_CCT, V_DUV, V_LUX, V_X, V_Y, V_Z, V_SX, V_SY, V_U, V_V, V_RA, V_RF, V_RG, V_PPFD, V_IRR, V_PEAK, V_R1 };

typedef struct vmap {
    const char *key;
    int field;
} vmap;

/* Sekonic SpectroMaster CSV (C-7000 / C-800) */
static const vmap sekonic[] = {
    {"Tcp [K]", V_CCT},
    {"\xe2\x8a\xbfuv", V_DUV}, /* "⊿uv" (U+22BF) */
    {"\xce\x94uv", V_DUV},     /* "Δuv" */
    {"Illuminance [lx]", V_LUX},
    {"Tristimulus Value X", V_X},
    {"Tristimulus Value Y", V_Y},
    {"Tristimulus Value Z", V_Z},
    {"CIE1931 x", V_SX},
    {"CIE1931 y", V_SY},
    {"CIE1976 u'", V_U},
    {"CIE1976 v'", V_V},
    {"CRI Ra", V_RA},
    {"TM-30 Rf", V_RF},
    {"TM-30 Rg", V_RG},
    {"Peak Wavelength [nm]", V_PEAK},
    {"PPFD [*", V_PPFD}, /* "PPFD [umolm⁻²s⁻¹]": a trailing '*' matches any rest */
    {NULL, 0},
};

/* UPRtek (CV600, MK350 family) and LI-COR LI-180 */
static const vmap uprtek[] = {
    {"CCT", V_CCT},  {"Duv", V_DUV}, {"LUX", V_LUX}, {"X", V_X},    {"Y", V_Y},       {"Z", V_Z},
    {"x", V_SX},     {"y", V_SY},    {"u'", V_U},    {"v'", V_V},   {"CRI", V_RA},    {"Rf", V_RF},
    {"Rg", V_RG},    {"PPFD", V_PPFD}, {"IRR", V_IRR}, {"LambdaP", V_PEAK}, {NULL, 0},
};

static double *slot(lx_vendor_results *r, int f)
{
    switch (f) {
    case V_CCT: return &r->cct_K;
    case V_DUV: return &r->duv;
    case V_LUX: return &r->illuminance_lx;
    case V_X: return &r->X;
    case V_Y: return &r->Y;
    case V_Z: return &r->Z;
    case V_SX: return &r->x;
    case V_SY: return &r->y;
    case V_U: return &r->u_prime;
    case V_V: return &r->v_prime;
    case V_RA: return &r->cri_ra;
    case V_RF: return &r->tm30_rf;
    case V_RG: return &r->tm30_rg;
    case V_PPFD: return &r->ppfd_umol_m2_s;
    case V_IRR: return &r->irradiance_W_m2;
    case V_PEAK: return &r->peak_nm;
    default: return f >= V_R1 && f < V_R1 + 15 ? &r->cri_r[f - V_R1] : NULL;
    }
}

/* A field's value as a number ("---" and the like are not numbers: NaN). */
static double number(const char *v)
{
    double d;
    const char *e = v + strlen(v);
    while (e > v && (e[-1] == ' ' || e[-1] == '\t')) e--;
    const char *q = lx__parse_double(v, e, &d);
    return q && q == e && isfinite(d) ? d : NAN;
}

static void put(lx_vendor_results *r, int field, const char *value)
{
    double *p = slot(r, field), d = number(value);
    if (p && isnan(*p) && !isnan(d)) {
        *p = d;
        r->count++;
    }
}

lx_status lx_spd_set_vendor(lx_ctx *ctx, const lx_spd_set *set, lx_vendor_results *out)
{
    LX__NEED_CTX(ctx);
    if (!set || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spd_set_vendor: NULL argument");
    lx_vendor_results r;
    memset(&r, 0, sizeof r);
    double *all = (double *)&r;
    for (size_t i = 0; i < offsetof(lx_vendor_results, count) / sizeof(double); i++) all[i] = NAN;
    r.count = 0;
    const vmap *map = set->format && !strcmp(set->format, "sekonic") ? sekonic
                    : set->format && !strcmp(set->format, "uprtek")  ? uprtek
                                                                     : NULL;
    for (size_t i = 0; map && i < set->nfields; i++) {
        const char *k = set->fields[i].key, *v = set->fields[i].value;
        for (const vmap *m = map; m->key; m++) {
            size_t n = strlen(m->key);
            if (m->key[n - 1] == '*' ? !strncmp(k, m->key, n - 1) : !strcmp(k, m->key)) put(&r, m->field, v);
        }
        /* R1..R15: "CRI R9" (Sekonic), "R9" (UPRtek, LI-COR) */
        const char *rk = map == sekonic && !strncmp(k, "CRI R", 5) ? k + 4 : map == uprtek ? k : NULL;
        int n;
        char tail;
        if (rk && sscanf(rk, "R%d%c", &n, &tail) == 1 && n >= 1 && n <= 15) put(&r, V_R1 + n - 1, v);
    }
    *out = r;
    return LX_OK;
}
