/* units.c - quantities with units: the unit table, parsing "1000lm" / "2.5 m" / "46 fc",
 * conversion between units of one quantity, printing, and radiometric <-> photometric
 * conversion with an explicit luminous efficacy (never a silent default). */
#include "lighting/lighting_private.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define FT_M 0.3048  /* international foot, exact by definition (1959) */
#define IN_M 0.0254  /* international inch, exact */

/* Sizes in SI units. fc = lm/ft2 = 1/0.3048^2 lx; fL = (1/pi) cd/ft2; lambert = (1/pi) cd/cm2
 * = 1e4/pi cd/m2; apostilb = (1/pi) cd/m2; stilb = cd/cm2; phot = lm/cm2 (all by definition). */
static const lx_unit units[] = {
    {"lm", LX_Q_LUMINOUS_FLUX, 1.0, 1, "lumen"},
    {"klm", LX_Q_LUMINOUS_FLUX, 1e3, 1, "kilolumen"},
    {"W", LX_Q_RADIANT_FLUX, 1.0, 1, "watt"},
    {"mW", LX_Q_RADIANT_FLUX, 1e-3, 1, "milliwatt"},
    {"kW", LX_Q_RADIANT_FLUX, 1e3, 1, "kilowatt"},
    {"cd", LX_Q_LUMINOUS_INTENSITY, 1.0, 1, "candela"},
    {"kcd", LX_Q_LUMINOUS_INTENSITY, 1e3, 1, "kilocandela"},
    {"W/sr", LX_Q_RADIANT_INTENSITY, 1.0, 1, "watt per steradian"},
    {"mW/sr", LX_Q_RADIANT_INTENSITY, 1e-3, 1, "milliwatt per steradian"},
    {"lx", LX_Q_ILLUMINANCE, 1.0, 1, "lux (lm/m2)"},
    {"lux", LX_Q_ILLUMINANCE, 1.0, 0, "lux"},
    {"lm/m2", LX_Q_ILLUMINANCE, 1.0, 0, "lux"},
    {"klx", LX_Q_ILLUMINANCE, 1e3, 1, "kilolux"},
    {"fc", LX_Q_ILLUMINANCE, 1.0 / (FT_M * FT_M), 1, "foot-candle (lm/ft2)"},
    {"lm/ft2", LX_Q_ILLUMINANCE, 1.0 / (FT_M * FT_M), 0, "foot-candle"},
    {"ph", LX_Q_ILLUMINANCE, 1e4, 1, "phot (lm/cm2)"},
    {"W/m2", LX_Q_IRRADIANCE, 1.0, 1, "watt per square metre"},
    {"mW/cm2", LX_Q_IRRADIANCE, 10.0, 1, "milliwatt per square centimetre"},
    {"W/cm2", LX_Q_IRRADIANCE, 1e4, 1, "watt per square centimetre"},
    {"cd/m2", LX_Q_LUMINANCE, 1.0, 1, "candela per square metre"},
    {"nit", LX_Q_LUMINANCE, 1.0, 1, "nit (cd/m2)"},
    {"nits", LX_Q_LUMINANCE, 1.0, 0, "nit"},
    {"cd/ft2", LX_Q_LUMINANCE, 1.0 / (FT_M * FT_M), 1, "candela per square foot"},
    {"fL", LX_Q_LUMINANCE, 1.0 / (LX__PI * FT_M * FT_M), 1, "foot-lambert ((1/pi) cd/ft2)"},
    {"lambert", LX_Q_LUMINANCE, 1e4 / LX__PI, 1, "lambert ((1/pi) cd/cm2)"},
    {"La", LX_Q_LUMINANCE, 1e4 / LX__PI, 0, "lambert"},
    {"asb", LX_Q_LUMINANCE, 1.0 / LX__PI, 1, "apostilb ((1/pi) cd/m2)"},
    {"sb", LX_Q_LUMINANCE, 1e4, 1, "stilb (cd/cm2)"},
    {"W/sr/m2", LX_Q_RADIANCE, 1.0, 1, "watt per steradian per square metre"},
    {"W/m2/sr", LX_Q_RADIANCE, 1.0, 0, "watt per steradian per square metre"},
    {"sr", LX_Q_SOLID_ANGLE, 1.0, 1, "steradian"},
    {"msr", LX_Q_SOLID_ANGLE, 1e-3, 1, "millisteradian"},
    {"deg2", LX_Q_SOLID_ANGLE, (LX__PI / 180.0) * (LX__PI / 180.0), 1, "square degree"},
    {"m", LX_Q_LENGTH, 1.0, 1, "metre"},
    {"km", LX_Q_LENGTH, 1e3, 1, "kilometre"},
    {"cm", LX_Q_LENGTH, 1e-2, 1, "centimetre"},
    {"mm", LX_Q_LENGTH, 1e-3, 1, "millimetre"},
    {"um", LX_Q_LENGTH, 1e-6, 1, "micrometre"},
    {"ft", LX_Q_LENGTH, FT_M, 1, "foot"},
    {"in", LX_Q_LENGTH, IN_M, 1, "inch"},
    {"yd", LX_Q_LENGTH, 3 * FT_M, 1, "yard"},
    {"rad", LX_Q_ANGLE, 1.0, 1, "radian"},
    {"mrad", LX_Q_ANGLE, 1e-3, 1, "milliradian"},
    {"deg", LX_Q_ANGLE, LX__PI / 180.0, 1, "degree"},
    {"\xc2\xb0", LX_Q_ANGLE, LX__PI / 180.0, 0, "degree"},
    {"arcmin", LX_Q_ANGLE, LX__PI / 10800.0, 1, "minute of arc"},
    {"arcsec", LX_Q_ANGLE, LX__PI / 648000.0, 1, "second of arc"},
    {"K", LX_Q_TEMPERATURE, 1.0, 1, "kelvin"},
    {"lm/W", LX_Q_EFFICACY, 1.0, 1, "lumen per watt"},
    {"s", LX_Q_TIME, 1.0, 1, "second"},
    {"min", LX_Q_TIME, 60.0, 1, "minute"},
    {"h", LX_Q_TIME, 3600.0, 1, "hour"},
    {"d", LX_Q_TIME, 86400.0, 1, "day"},
    {"a", LX_Q_TIME, 8760.0 * 3600.0, 1, "year of 365 days (8760 h, as EN 15193-1 counts a year)"},
    {"year", LX_Q_TIME, 8760.0 * 3600.0, 0, "year"},
    {"m2", LX_Q_AREA, 1.0, 1, "square metre"},
    {"ft2", LX_Q_AREA, FT_M * FT_M, 1, "square foot"},
};

#define NUNITS (sizeof units / sizeof units[0])

const lx_unit *lx_units(size_t *count)
{
    if (count) *count = NUNITS;
    return units;
}

static const char *const qnames[LX_Q_COUNT][2] = {
    {"", ""},
    {"luminous flux", "lm"},
    {"radiant flux", "W"},
    {"luminous intensity", "cd"},
    {"radiant intensity", "W/sr"},
    {"illuminance", "lx"},
    {"irradiance", "W/m2"},
    {"luminance", "cd/m2"},
    {"radiance", "W/sr/m2"},
    {"solid angle", "sr"},
    {"length", "m"},
    {"angle", "rad"},
    {"temperature", "K"},
    {"luminous efficacy", "lm/W"},
    {"time", "s"},
    {"area", "m2"},
};

const char *lx_quantity_name(lx_quantity q) { return q >= 0 && q < LX_Q_COUNT ? qnames[q][0] : ""; }
const char *lx_quantity_si_unit(lx_quantity q) { return q >= 0 && q < LX_Q_COUNT ? qnames[q][1] : ""; }

lx_quantity lx_quantity_counterpart(lx_quantity q)
{
    switch (q) {
    case LX_Q_LUMINOUS_FLUX: return LX_Q_RADIANT_FLUX;
    case LX_Q_RADIANT_FLUX: return LX_Q_LUMINOUS_FLUX;
    case LX_Q_LUMINOUS_INTENSITY: return LX_Q_RADIANT_INTENSITY;
    case LX_Q_RADIANT_INTENSITY: return LX_Q_LUMINOUS_INTENSITY;
    case LX_Q_ILLUMINANCE: return LX_Q_IRRADIANCE;
    case LX_Q_IRRADIANCE: return LX_Q_ILLUMINANCE;
    case LX_Q_LUMINANCE: return LX_Q_RADIANCE;
    case LX_Q_RADIANCE: return LX_Q_LUMINANCE;
    default: return LX_Q_NONE;
    }
}

static int is_photometric(lx_quantity q)
{
    return q == LX_Q_LUMINOUS_FLUX || q == LX_Q_LUMINOUS_INTENSITY || q == LX_Q_ILLUMINANCE ||
           q == LX_Q_LUMINANCE;
}

/* Normalises spellings: "m^2" and "m²" -> "m2", drops spaces; writes at most cap bytes. */
static void normalise(const char *in, char *out, size_t cap)
{
    size_t j = 0;
    for (size_t i = 0; in[i] && j + 1 < cap; i++) {
        unsigned char c = (unsigned char)in[i];
        if (c == ' ' || c == '\t') continue;
        if (c == '^') continue;
        if (c == 0xc2 && (unsigned char)in[i + 1] == 0xb2) { /* U+00B2 superscript two */
            out[j++] = '2';
            i++;
            continue;
        }
        if (c == 0xc2 && (unsigned char)in[i + 1] == 0xb5 && j + 2 < cap) { /* micro sign -> u */
            out[j++] = 'u';
            i++;
            continue;
        }
        out[j++] = (char)c;
    }
    out[j] = '\0';
}

lx_status lx_unit_find(lx_ctx *ctx, const char *name, const lx_unit **out)
{
    LX__NEED_CTX(ctx);
    if (!name || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_unit_find: NULL argument");
    char buf[64];
    normalise(name, buf, sizeof buf);
    /* exact spelling first (so "mW" is milliwatt and "MW" would not silently match), then
     * case-insensitive for names that are unambiguous that way */
    for (size_t i = 0; i < NUNITS; i++)
        if (!strcmp(units[i].name, buf)) {
            *out = &units[i];
            return LX_OK;
        }
    const lx_unit *hit = NULL;
    int nhit = 0;
    for (size_t i = 0; i < NUNITS; i++)
        if (!strcasecmp(units[i].name, buf)) {
            if (!hit || hit->quantity != units[i].quantity || hit->to_si != units[i].to_si) nhit++;
            hit = &units[i];
        }
    if (nhit == 1) {
        *out = hit;
        return LX_OK;
    }
    if (nhit > 1) return lx__error(ctx, LX_EPARSE, NULL, 0, "ambiguous unit '%s' (mind upper and lower case)", name);
    return lx__error(ctx, LX_EPARSE, NULL, 0, "unknown unit '%s'", name);
}

lx_status lx_quantity_parse(lx_ctx *ctx, const char *text, lx_quantity expect, const char *bare_unit,
                            double *si_value, lx_quantity *got)
{
    LX__NEED_CTX(ctx);
    if (!text || !si_value) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_quantity_parse: NULL argument");
    const char *s = text;
    while (*s == ' ' || *s == '\t') s++;
    /* the number: strtod, but not "inf"/"nan" and not a hex float */
    if (!*s || !(strchr("+-.0123456789", *s)))
        return lx__error(ctx, LX_EPARSE, NULL, 0, "'%s' is not a number with an optional unit", text);
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')))
        return lx__error(ctx, LX_EPARSE, NULL, 0, "'%s' is not a number with an optional unit", text);
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1.0))
        return lx__error(ctx, LX_EPARSE, NULL, 0, "'%s': number out of range", text);
    while (*end == ' ' || *end == '\t') end++;
    const lx_unit *u = NULL;
    const char *uname = *end ? end : bare_unit;
    if (uname && *uname) {
        lx_status st = lx_unit_find(ctx, uname, &u);
        if (st != LX_OK) return st;
    }
    lx_quantity q = u ? u->quantity : expect;
    if (expect != LX_Q_NONE && q != expect)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unit '%s' is a %s, not a %s", u->name,
                         lx_quantity_name(u->quantity), lx_quantity_name(expect));
    double si = u ? v * u->to_si : v;
    if (!isfinite(si)) return lx__error(ctx, LX_EPARSE, NULL, 0, "'%s': number out of range", text);
    *si_value = si;
    if (got) *got = q;
    return LX_OK;
}

lx_status lx_unit_convert(lx_ctx *ctx, double value, const char *from, const char *to, double *out)
{
    LX__NEED_CTX(ctx);
    const lx_unit *a, *b;
    lx_status st;
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_unit_convert: NULL argument");
    if ((st = lx_unit_find(ctx, from, &a)) != LX_OK) return st;
    if ((st = lx_unit_find(ctx, to, &b)) != LX_OK) return st;
    if (a->quantity != b->quantity)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "cannot convert %s (%s) to %s (%s)", a->name,
                         lx_quantity_name(a->quantity), b->name, lx_quantity_name(b->quantity));
    /* one multiplication or division when either side is the SI unit, so exact factors stay exact */
    if (b->to_si == 1.0) *out = value * a->to_si;
    else if (a->to_si == 1.0) *out = value / b->to_si;
    else *out = value * a->to_si / b->to_si;
    return LX_OK;
}

lx_status lx_unit_format(lx_ctx *ctx, double si_value, const char *unit, char *buf, size_t cap)
{
    LX__NEED_CTX(ctx);
    const lx_unit *u;
    lx_status st;
    if (!buf || cap == 0) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_unit_format: no buffer");
    if ((st = lx_unit_find(ctx, unit, &u)) != LX_OK) return st;
    double v = u->to_si == 1.0 ? si_value : si_value / u->to_si;
    char num[40];
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(num, sizeof num, "%.*g", prec, v);
        if (strtod(num, NULL) == v) break;
    }
    if ((size_t)snprintf(buf, cap, "%s %s", num, u->name) >= cap)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_unit_format: buffer too small");
    return LX_OK;
}

lx_status lx_radiometric_convert(lx_ctx *ctx, double value_si, lx_quantity q, double efficacy_lm_per_W,
                                 double *out_si, lx_quantity *out_q)
{
    LX__NEED_CTX(ctx);
    if (!out_si) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_radiometric_convert: NULL argument");
    lx_quantity c = lx_quantity_counterpart(q);
    if (c == LX_Q_NONE)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "%s has no radiometric/photometric counterpart",
                         *lx_quantity_name(q) ? lx_quantity_name(q) : "a bare number");
    if (!(efficacy_lm_per_W > 0) || !isfinite(efficacy_lm_per_W))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "luminous efficacy must be positive and finite (got %g lm/W)",
                         efficacy_lm_per_W);
    *out_si = is_photometric(q) ? value_si / efficacy_lm_per_W : value_si * efficacy_lm_per_W;
    if (out_q) *out_q = c;
    return LX_OK;
}
