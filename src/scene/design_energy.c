/* design_energy.c - the lighting energy numeric indicator of EN 15193-1 (LENI, kWh/(m2 a)): the
 * scene's [energy] section (operating hours, occupancy, constant illuminance control, the daylight
 * dependency factor by the standard's simplified method from the typed supply and control
 * factors, parasitic and emergency charging power) and the computation. */
#include "scene/design_private.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define YEAR_H 8760.0
#define HOUR_S 3600.0

/* the [energy] keys: the index into lx__design.e, the quantity, and the range of plain factors */
static const struct {
    const char *key;
    lx_quantity q;
} keys[9] = {{"area", LX_Q_AREA},
             {"daylight_hours", LX_Q_TIME},
             {"night_hours", LX_Q_TIME},
             {"occupancy_factor", LX_Q_NONE},
             {"daylight_supply", LX_Q_NONE},
             {"daylight_control", LX_Q_NONE},
             {"parasitic_power", LX_Q_RADIANT_FLUX},
             {"emergency_charging_power", LX_Q_RADIANT_FLUX},
             {"emergency_charging_hours", LX_Q_TIME}};

lx_status lx__energy_open(lx_ctx *ctx, lx_scene *sc, const char *file, long line)
{
    lx__design *in = sc->design->internal;
    if (in->energy) return lx__error(ctx, LX_EPARSE, file, line, "section [energy] given twice");
    in->energy = 1;
    sc->design->has_energy = 1;
    in->energy_file = file;
    in->energy_line = line;
    return LX_OK;
}

lx_status lx__energy_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value)
{
    lx__design *in = sc->design->internal;
    if (!strcmp(key, "constant_illuminance")) {
        if (!strcmp(value, "yes")) in->constant = 1;
        else if (!strcmp(value, "no")) in->constant = 0;
        else return lx__error(ctx, LX_EPARSE, file, line, "constant_illuminance: expected yes or no, got '%s'", value);
        return LX_OK;
    }
    for (int k = 0; k < 9; k++) {
        if (strcmp(key, keys[k].key)) continue;
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, keys[k].q, NULL, &in->e[k], NULL);
        if (st != LX_OK) return st;
        if (keys[k].q == LX_Q_TIME) in->e[k] /= HOUR_S;
        if (!(in->e[k] >= 0)) return lx__error(ctx, LX_EPARSE, file, line, "%s: must not be negative", key);
        if (keys[k].q == LX_Q_NONE && !(in->e[k] <= 1))
            return lx__error(ctx, LX_EPARSE, file, line, "%s: a factor from 0 to 1 (got %g)", key, in->e[k]);
        if (k == 0 && !(in->e[k] > 0)) return lx__error(ctx, LX_EPARSE, file, line, "area: must be greater than zero");
        in->has[k] = 1;
        return LX_OK;
    }
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [energy] (keys: area, daylight_hours, night_hours, occupancy_factor, "
                     "constant_illuminance, daylight_supply, daylight_control, parasitic_power, emergency_charging_power, "
                     "emergency_charging_hours)",
                     key);
}

lx_status lx_leni_compute(lx_ctx *ctx, const lx_leni_input *in, lx_leni *out)
{
    LX__NEED_CTX(ctx);
    if (!in || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_leni_compute: NULL argument");
    lx_status rs = lx__check_reserved(ctx, "LENI inputs", in->reserved, sizeof in->reserved);
    if (rs) return rs;
    if (!(in->area_m2 > 0 && isfinite(in->area_m2)) || !(in->power_W >= 0 && isfinite(in->power_W)))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "LENI: the area must be positive and the power not negative, both finite");
    if (!(in->daylight_h >= 0 && in->night_h >= 0 && in->daylight_h + in->night_h <= YEAR_H && in->emergency_h >= 0 &&
          in->emergency_h <= YEAR_H))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "LENI: the operating hours must not be negative nor exceed a year (8760 h)");
    double f[3] = {in->constant_factor, in->occupancy_factor, in->daylight_factor};
    for (int k = 0; k < 3; k++)
        if (!(f[k] >= 0 && f[k] <= 1)) return lx__error(ctx, LX_EINVAL, NULL, 0, "LENI: the factors F_C, F_O, F_D lie in 0..1");
    if (!(in->parasitic_W >= 0 && in->emergency_W >= 0 && isfinite(in->parasitic_W) && isfinite(in->emergency_W)))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "LENI: the parasitic and charging powers must not be negative");
    memset(out, 0, sizeof *out);
    out->lighting_kWh = in->power_W * in->constant_factor * in->occupancy_factor *
                        (in->daylight_h * in->daylight_factor + in->night_h) / 1000;
    out->parasitic_kWh = (in->parasitic_W * (YEAR_H - (in->daylight_h + in->night_h)) + in->emergency_W * in->emergency_h) / 1000;
    out->total_kWh = out->lighting_kWh + out->parasitic_kWh;
    out->leni_kWh_m2 = out->total_kWh / in->area_m2;
    out->power_density_W_m2 = in->power_W / in->area_m2;
    return LX_OK;
}

lx_status lx_scene_energy(lx_ctx *ctx, const lx_scene *sc, lx_leni_input *in_out, lx_leni *out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !in_out || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_energy: NULL argument");
    const lx_scene_design *d = sc->design;
    const lx__design *in = d->internal;
    if (!in->energy) return lx__error(ctx, LX_EPARSE, sc->file, 0, "the scene has no [energy] section");
    lx_leni_input x;
    memset(&x, 0, sizeof x);
    double pw = 0, mfw = 0;
    for (size_t l = 0; l < sc->n_lum; l++) {
        if (d->lum_mode[l] == LX_LUM_EMERGENCY) continue; /* charged, not lit, in normal operation */
        if (!(d->lum_power_W[l] > 0))
            return lx__error(ctx, LX_EPARSE, sc->lum[l].file, sc->lum[l].line,
                             "luminaire '%s': no power for the energy (give 'power', e.g. power = 35 W)", sc->lum[l].name);
        pw += d->lum_power_W[l];
        mfw += d->lum_power_W[l] * d->lum_mf[l];
    }
    double area = in->e[0];
    if (!in->has[0]) {
        area = 0;
        for (size_t r = 0; r < sc->n_room; r++)
            area += (sc->room[r].max_m[0] - sc->room[r].min_m[0]) * (sc->room[r].max_m[1] - sc->room[r].min_m[1]);
        if (!(area > 0))
            return lx__error(ctx, LX_EPARSE, in->energy_file, in->energy_line, "[energy]: give 'area' (the scene has no room)");
    }
    x.area_m2 = area;
    x.power_W = pw;
    x.daylight_h = in->has[1] ? in->e[1] : 0;
    x.night_h = in->has[2] ? in->e[2] : 0;
    if (!(x.daylight_h + x.night_h > 0))
        return lx__error(ctx, LX_EPARSE, in->energy_file, in->energy_line,
                         "[energy]: give the operating hours (daylight_hours, night_hours)");
    double mf = pw > 0 ? mfw / pw : 1;
    x.constant_factor = in->constant ? (1 + mf) / 2 : 1;
    x.occupancy_factor = in->has[3] ? in->e[3] : 1;
    x.daylight_factor = 1 - (in->has[4] ? in->e[4] : 0) * (in->has[5] ? in->e[5] : 0);
    x.parasitic_W = in->has[6] ? in->e[6] : 0;
    x.emergency_W = in->has[7] ? in->e[7] : 0;
    x.emergency_h = in->has[8] ? in->e[8] : (x.emergency_W > 0 ? YEAR_H : 0);
    lx_status st = lx_leni_compute(ctx, &x, out);
    if (st != LX_OK) return lx__error(ctx, LX_EPARSE, in->energy_file, in->energy_line, "[energy]: %s", lx_ctx_errmsg(ctx));
    *in_out = x;
    return LX_OK;
}
