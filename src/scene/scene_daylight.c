/* scene_daylight.c - daylight in scene files: the [sky] keys of CIE and Perez skies, the [sun]
 * section (a direction, altitude and azimuth, or a date, time and site through NREL SPA), the
 * [observer NAME] sections of glare, and their checks once the whole scene is read. */
#include "scene/design_private.h"
#include "scene/scene_private.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- [sky] type = cie | perez ---- */

lx_status lx__scene_sky_daylight_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key,
                                     const char *value, int *known)
{
    *known = 1;
    double v;
    if (!strcmp(key, "number")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL, &v, NULL);
        if (st == LX_OK && !(v >= 1 && v <= 15 && v == floor(v)))
            return lx__error(ctx, LX_EPARSE, file, line, "number: a CIE standard general sky is 1 to 15");
        if (st == LX_OK) sc->sky_cie_type = (int)v;
        return st;
    }
    if (!strcmp(key, "illuminance")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_ILLUMINANCE, NULL,
                                           &sc->sky_illuminance_lx, NULL);
        if (st == LX_OK && !(sc->sky_illuminance_lx > 0))
            return lx__error(ctx, LX_EPARSE, file, line, "illuminance: must be positive");
        sc->sky_by_illuminance = 1;
        return st;
    }
    double *dst = !strcmp(key, "direct_normal") ? &sc->sky_dni_W_m2 : !strcmp(key, "diffuse_horizontal") ? &sc->sky_dhi_W_m2 : NULL;
    if (dst) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_IRRADIANCE, NULL, dst, NULL);
        if (st == LX_OK && !(*dst >= 0)) return lx__error(ctx, LX_EPARSE, file, line, "%s: must not be negative", key);
        return st;
    }
    if (!strcmp(key, "precipitable_water")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LENGTH, NULL, &v, NULL);
        if (st == LX_OK && !(v > 0 && v < 0.2)) return lx__error(ctx, LX_EPARSE, file, line, "%s: 0 to 20 cm", key);
        if (st == LX_OK) sc->sky_water_cm = v * 100;
        return st;
    }
    if (!strcmp(key, "day_of_year")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL, &v, NULL);
        if (st == LX_OK && !(v >= 1 && v <= 366 && v == floor(v)))
            return lx__error(ctx, LX_EPARSE, file, line, "day_of_year: a whole number from 1 to 366");
        if (st == LX_OK) sc->sky_day_of_year = (int)v;
        return st;
    }
    *known = 0;
    return LX_OK;
}

/* ---- [sun] ---- */

static lx_status parse_ints(lx_ctx *ctx, const char *file, long line, const char *key, const char *v, char sep,
                            int n, int *out, double *last)
{
    const char *p = v;
    for (int i = 0; i < n; i++) {
        if (i && *p++ != sep) goto bad;
        if (i == 0 && *p == '-') p++;
        if (!isdigit((unsigned char)*p)) goto bad;
        char *e;
        if (i == n - 1 && last) {
            *last = strtod(p, &e);
        } else out[i] = (int)strtol(i == 0 && p > v && p[-1] == '-' ? p - 1 : p, &e, 10);
        p = e;
    }
    while (isspace((unsigned char)*p)) p++;
    if (*p) goto bad;
    return LX_OK;
bad:
    return lx__error(ctx, LX_EPARSE, file, line, "%s: expected %s, got '%s'", key,
                     sep == '-' ? "YYYY-MM-DD" : "HH:MM or HH:MM:SS (local standard time)", v);
}

void lx__scene_sun_raw_init(scene__sun_raw *r)
{
    memset(r, 0, sizeof *r);
    r->pressure = 1013.25, r->temp = 15, r->delta_t = 69;
}

lx_status lx__scene_sun_key(lx_ctx *ctx, lx_scene *sc, scene__sun_raw *r, const char *file, long line, const char *key,
                            const char *value)
{
    lx_status st = LX_OK;
    sc->has_sun = 1;
    if (!strcmp(key, "direction")) {
        r->has_dir = 1;
        return lx__scene_parse_vec(ctx, file, line, key, value, 3, 3, LX_Q_NONE, NULL, r->dir, NULL);
    }
    struct { const char *k; lx_quantity q; double *dst; int *flag; } nums[] = {
        {"altitude", LX_Q_ANGLE, &r->alt, &r->has_alt},       {"azimuth", LX_Q_ANGLE, &r->az, &r->has_az},
        {"latitude", LX_Q_ANGLE, &r->lat, &r->has_lat},       {"longitude", LX_Q_ANGLE, &r->lon, &r->has_lon},
        {"illuminance", LX_Q_ILLUMINANCE, &r->illum, &r->has_illum},
        {"timezone", LX_Q_NONE, &r->tz, &r->has_tz},          {"elevation", LX_Q_LENGTH, &r->elev, NULL},
        {"pressure", LX_Q_NONE, &r->pressure, NULL},          {"temperature", LX_Q_NONE, &r->temp, NULL},
        {"delta_t", LX_Q_NONE, &r->delta_t, NULL},
    };
    for (size_t i = 0; i < sizeof nums / sizeof nums[0]; i++)
        if (!strcmp(key, nums[i].k)) {
            if (nums[i].flag) *nums[i].flag = 1;
            return lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, nums[i].q, NULL, nums[i].dst, NULL);
        }
    if (!strcmp(key, "date")) {
        int ymd[3];
        r->has_date = 1;
        st = parse_ints(ctx, file, line, key, value, '-', 3, ymd, NULL);
        r->y = ymd[0], r->mo = ymd[1], r->d = ymd[2];
        return st;
    }
    if (!strcmp(key, "time")) {
        int hm[3] = {0, 0, 0};
        double sec = 0;
        r->has_time = 1;
        int colons = 0;
        for (const char *p = value; *p; p++) colons += *p == ':';
        st = parse_ints(ctx, file, line, key, value, ':', colons == 2 ? 3 : 2, hm, colons == 2 ? &sec : NULL);
        r->h = hm[0], r->mi = hm[1], r->s = sec;
        return st;
    }
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [sun] (keys: direction, altitude, azimuth, date, time, timezone, latitude, "
                     "longitude, elevation, pressure, temperature, delta_t, illuminance)",
                     key);
}

/* Day of the year of a date (1..366). */
static int day_of_year(int y, int m, int d)
{
    static const int cum[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    int leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    return cum[m - 1] + d + (leap && m > 2);
}

static lx_status sun_finish(lx_ctx *ctx, lx_scene *sc, const scene__sun_raw *r)
{
    const char *f = sc->sun_file_at;
    long ln = sc->sun_line;
    lx_status st = LX_OK;
    int by_dir = r->has_dir, by_angles = r->has_alt || r->has_az, by_date = r->has_date || r->has_time || r->has_lat ||
                                                                             r->has_lon || r->has_tz;
    if (by_dir + by_angles + by_date != 1)
        return lx__error(ctx, LX_EPARSE, f, ln,
                         "[sun]: give one of 'direction', 'altitude' and 'azimuth', or 'date', 'time', 'timezone', "
                         "'latitude' and 'longitude'");
    if (by_dir) {
        if ((st = lx__unit3(ctx, "[sun] direction", r->dir, sc->sun_dir)) != LX_OK)
            return lx__error(ctx, LX_EPARSE, f, ln, "[sun]: direction of zero length");
    } else if (by_angles) {
        if (!r->has_alt || !r->has_az) return lx__error(ctx, LX_EPARSE, f, ln, "[sun]: 'altitude' needs 'azimuth' and back");
        if (!(fabs(r->alt) <= LX__PI / 2)) return lx__error(ctx, LX_EPARSE, f, ln, "[sun]: altitude must be -90..90 deg");
        lx_sun_direction(r->alt, r->az, sc->sun_dir);
    } else {
        if (!(r->has_date && r->has_time && r->has_tz && r->has_lat && r->has_lon))
            return lx__error(ctx, LX_EPARSE, f, ln,
                             "[sun]: a sun placed by date needs 'date', 'time', 'timezone', 'latitude' and 'longitude'");
        lx_sun_input in;
        memset(&in, 0, sizeof in);
        in.year = r->y, in.month = r->mo, in.day = r->d, in.hour = r->h, in.minute = r->mi, in.second = r->s;
        in.timezone_h = r->tz, in.delta_t_s = r->delta_t, in.latitude_deg = r->lat / LX__DEG;
        in.longitude_deg = r->lon / LX__DEG, in.elevation_m = r->elev, in.pressure_mbar = r->pressure;
        in.temperature_C = r->temp, in.refraction_deg = 0.5667;
        if ((st = lx_sun_spa(ctx, &in, &sc->sun_position)) != LX_OK) {
            char why[LX__ERRMSG_MAX];
            snprintf(why, sizeof why, "%s", lx_ctx_errmsg(ctx));
            return lx__error(ctx, LX_EPARSE, f, ln, "[sun]: %s", why);
        }
        memcpy(sc->sun_dir, sc->sun_position.dir, sizeof sc->sun_dir);
        sc->sun_by_date = 1;
        if (!sc->sky_day_of_year && r->mo >= 1 && r->mo <= 12) sc->sky_day_of_year = day_of_year(r->y, r->mo, r->d);
    }
    if (r->has_illum) {
        if (!(r->illum >= 0)) return lx__error(ctx, LX_EPARSE, f, ln, "[sun]: illuminance must not be negative");
        sc->sun_normal_lx = r->illum;
    } else if (sc->sky != LX_SKY_PEREZ)
        return lx__error(ctx, LX_EPARSE, f, ln,
                         "[sun]: missing 'illuminance' (its direct normal illuminance; a Perez sky gives it instead)");
    return LX_OK;
}

/* ---- whole-scene checks: the sky model and the sun ---- */

lx_status lx__scene_daylight_finish(lx_ctx *ctx, lx_scene *sc, const scene__sun_raw *sun)
{
    lx_status st;
    if (sc->has_sun && (st = sun_finish(ctx, sc, sun)) != LX_OK) return st;
    const char *f = sc->sky_file_at;
    long ln = sc->sky_line;
    int cie = sc->sky == LX_SKY_CIE, perez = sc->sky == LX_SKY_PEREZ;
    if (sc->sky_cie_type && !cie) return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: 'number' applies to type cie only");
    if (sc->sky_by_illuminance && !cie)
        return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: 'illuminance' applies to type cie only");
    if ((sc->sky_dni_W_m2 > 0 || sc->sky_dhi_W_m2 > 0) && !perez)
        return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: 'direct_normal' and 'diffuse_horizontal' apply to type perez only");
    if (!cie && !perez) return LX_OK;
    if (cie) {
        if (!sc->sky_cie_type) return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: a cie sky needs 'number' (1 to 15)");
        if (sc->sky_by_illuminance == (sc->sky_luminance_cd_m2 > 0))
            return lx__error(ctx, LX_EPARSE, f, ln,
                             "[sky]: give 'luminance' (zenith) or 'illuminance' (horizontal), one of them");
        int uniform = sc->sky_cie_type == 1 || sc->sky_cie_type == 3 || sc->sky_cie_type == 5;
        double none[3] = {0, 0, 1};
        if (!sc->has_sun && !uniform)
            return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: CIE sky %d depends on the sun's position: add a [sun] section",
                             sc->sky_cie_type);
        st = lx_sky_cie(ctx, sc->sky_cie_type, sc->has_sun ? sc->sun_dir : none,
                        sc->sky_by_illuminance ? LX_SKY_BY_HORIZONTAL : LX_SKY_BY_ZENITH,
                        sc->sky_by_illuminance ? sc->sky_illuminance_lx : sc->sky_luminance_cd_m2, &sc->sky_model);
    } else {
        if (!sc->has_sun) return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: a perez sky needs a [sun] section");
        if (!(sc->sky_dhi_W_m2 > 0))
            return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: a perez sky needs 'diffuse_horizontal' (W/m2, > 0) and 'direct_normal'");
        if (!sc->sky_day_of_year)
            return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: a perez sky needs 'day_of_year' (or a [sun] placed by date)");
        lx_perez_input in;
        memset(&in, 0, sizeof in);
        memcpy(in.sun_dir, sc->sun_dir, sizeof in.sun_dir);
        in.direct_normal_W_m2 = sc->sky_dni_W_m2;
        in.diffuse_horizontal_W_m2 = sc->sky_dhi_W_m2;
        in.day_of_year = sc->sky_day_of_year;
        in.precipitable_water_cm = sc->sky_water_cm;
        st = lx_sky_perez(ctx, &in, &sc->sky_model);
        if (st == LX_OK && sc->has_sun && !(sc->sun_normal_lx > 0)) sc->sun_normal_lx = sc->sky_model.sun_normal_lx;
    }
    if (st != LX_OK) {
        char why[LX__ERRMSG_MAX];
        snprintf(why, sizeof why, "%s", lx_ctx_errmsg(ctx));
        return lx__error(ctx, LX_EPARSE, f, ln, "[sky]: %s", why);
    }
    return LX_OK;
}

/* ---- [observer NAME] ---- */

lx_status lx__scene_obs_open(lx_ctx *ctx, lx_scene *sc, const char *name, const char *file, long line)
{
    for (size_t i = 0; i < sc->n_obs; i++)
        if (!strcmp(sc->obs[i].name, name)) return lx__error(ctx, LX_EPARSE, file, line, "observer '%s' defined twice", name);
    lx_scene_observer *no = lx__realloc_n(sc->obs, sc->n_obs + 1, sizeof *no);
    if (!no) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    sc->obs = no;
    lx_scene_observer *o = &sc->obs[sc->n_obs];
    memset(o, 0, sizeof *o);
    o->name = lx__alloc(strlen(name) + 1);
    if (!o->name) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    strcpy(o->name, name);
    o->file = file;
    o->line = line;
    o->pos_m[0] = NAN; /* required */
    o->view[0] = NAN;
    o->background_cd_m2 = NAN;
    sc->n_obs++;
    return LX_OK;
}

lx_status lx__scene_obs_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value)
{
    lx_scene_observer *o = &sc->obs[sc->n_obs - 1];
    if (!strcmp(key, "position"))
        return lx__scene_parse_vec(ctx, file, line, key, value, 3, 3, LX_Q_LENGTH, NULL, o->pos_m, NULL);
    if (!strcmp(key, "view")) return lx__scene_parse_vec(ctx, file, line, key, value, 3, 3, LX_Q_NONE, NULL, o->view, NULL);
    if (!strcmp(key, "background_luminance")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LUMINANCE, NULL,
                                           &o->background_cd_m2, NULL);
        if (st == LX_OK && !(o->background_cd_m2 > 0))
            return lx__error(ctx, LX_EPARSE, file, line, "background_luminance: must be positive");
        return st;
    }
    lx_status st = LX_OK;
    if (lx__design_obs_key(ctx, sc, file, line, key, value, &st)) return st;
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [observer] (keys: position, view, background_luminance, x, y, z, spacing, "
                     "directions, direction_step)",
                     key);
}

lx_status lx__scene_obs_finish(lx_ctx *ctx, lx_scene *sc)
{
    lx_status est = lx__design_obs_expand(ctx, sc); /* several positions and directions */
    if (est != LX_OK) return est;
    for (size_t i = 0; i < sc->n_obs; i++) {
        lx_scene_observer *o = &sc->obs[i];
        if (isnan(o->pos_m[0]) || isnan(o->view[0]))
            return lx__error(ctx, LX_EPARSE, o->file, o->line, "observer '%s': needs 'position' and 'view'", o->name);
        double v[3];
        if (lx__unit3(ctx, "view", o->view, v) != LX_OK)
            return lx__error(ctx, LX_EPARSE, o->file, o->line, "observer '%s': view of zero length", o->name);
        if (fabs(v[2]) > 0.999)
            return lx__error(ctx, LX_EPARSE, o->file, o->line,
                             "observer '%s': a line of sight straight up or down has no vertical of the visual field",
                             o->name);
        memcpy(o->view, v, sizeof v);
        /* the visual field's vertical: +z made orthogonal to the line of sight */
        double up[3] = {-v[2] * v[0], -v[2] * v[1], 1 - v[2] * v[2]};
        lx__unit3(ctx, "up", up, o->up);
    }
    return LX_OK;
}
