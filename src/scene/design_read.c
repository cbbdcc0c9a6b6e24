/* design_read.c - the scene file's keys for the deliverable: maintenance factors (typed, or a
 * CIE 97:2005 scheme in [maintenance NAME] whose tables the user types), luminaire power and
 * emergency operation; the checks and references resolved once the whole scene is read. */
#include "scene/design_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HOUR_S 3600.0
#define YEAR_S (8760.0 * 3600.0)

lx_status lx__design_new(lx_scene *sc)
{
    sc->design = lx__calloc(1, sizeof *sc->design);
    lx__design *in = lx__calloc(1, sizeof *in);
    if (!sc->design || !in) {
        lx__free(in);
        return LX_ENOMEM;
    }
    sc->design->internal = in;
    sc->design->scene_mf = 1;
    sc->design->scene_maint = -1;
    return LX_OK;
}

static void factor_free(lx__factor *f)
{
    lx__free(f->t_s);
    lx__free(f->v);
    memset(f, 0, sizeof *f);
}

void lx__design_free(lx_scene *sc)
{
    lx_scene_design *d = sc->design;
    if (!d) return;
    lx__area_free(sc);
    lx__req_free(sc);
    for (size_t i = 0; i < d->n_obs_group; i++) lx__free(d->obs_group_name[i]);
    lx__free(d->obs_group_name);
    lx__free(d->obs_group);
    lx__design *in = d->internal;
    for (size_t i = 0; i < d->n_maint; i++) {
        lx_maintenance *m = &d->maint[i];
        lx__free(m->name);
        lx__free(m->lamp_type);
        lx__free(m->luminaire_type);
        lx__free(m->environment);
        for (int k = 0; in && in->maint && k < 4; k++) factor_free(&in->maint[i].f[k]);
    }
    lx__free(d->maint);
    if (in) {
        lx__free(in->maint);
        lx__free(in->scene_maint);
        for (size_t i = 0; i < in->n_lum; i++) lx__free(in->lum_maint_name[i]);
        lx__free(in->lum_maint_name);
        lx__free(in->lum_maint_line);
        lx__free(in->lum_mf_line);
        lx__free(in->obs_raw);
        lx__free(in);
    }
    lx__free(d->lum_mf);
    lx__free(d->lum_maint);
    lx__free(d->lum_power_W);
    lx__free(d->lum_mode);
    lx__free(d->lum_emergency_lm);
    lx__free(d->rec_cylinder);
    lx__free(d->rec_facing);
    lx__free(d);
    sc->design = NULL;
}

/* ---- one number in (0, 1] ---- */

static lx_status unit_factor(lx_ctx *ctx, const char *file, long line, const char *key, const char *value, double *out)
{
    lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL, out, NULL);
    if (st != LX_OK) return st;
    if (!(*out > 0 && *out <= 1))
        return lx__error(ctx, LX_EPARSE, file, line, "%s: must be greater than 0 and at most 1 (got %g)", key, *out);
    return LX_OK;
}

static lx_status name_key(lx_ctx *ctx, const char *file, long line, const char *key, const char *value, char **dst)
{
    if (!*value) return lx__error(ctx, LX_EPARSE, file, line, "%s: name a [maintenance NAME] section", key);
    lx__free(*dst);
    *dst = lx__strdup(value);
    return *dst ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
}

/* ---- luminaires ---- */

void lx__design_lum_raw_free(scene__lum_design *d)
{
    lx__free(d->maint);
    memset(d, 0, sizeof *d);
}

int lx__design_lum_key(lx_ctx *ctx, scene__lum_design *d, const char *file, long line, const char *key,
                       const char *value, lx_status *st)
{
    if (!strcmp(key, "maintenance_factor")) {
        d->has_mf = 1, d->mf_line = line;
        *st = unit_factor(ctx, file, line, key, value, &d->mf);
    } else if (!strcmp(key, "maintenance")) {
        d->maint_line = line;
        *st = name_key(ctx, file, line, key, value, &d->maint);
    } else if (!strcmp(key, "power")) {
        d->has_power = 1, d->power_line = line;
        *st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_RADIANT_FLUX, NULL, &d->power, NULL);
        if (*st == LX_OK && !(d->power > 0))
            *st = lx__error(ctx, LX_EPARSE, file, line, "power: must be greater than zero (the luminaire's input power)");
    } else if (!strcmp(key, "emergency")) {
        d->mode_line = line;
        *st = LX_OK;
        if (!strcmp(value, "no")) d->mode = LX_LUM_NORMAL;
        else if (!strcmp(value, "maintained")) d->mode = LX_LUM_MAINTAINED;
        else if (!strcmp(value, "non-maintained")) d->mode = LX_LUM_EMERGENCY;
        else
            *st = lx__error(ctx, LX_EPARSE, file, line,
                            "emergency: expected no, maintained (lit in normal and emergency operation) or "
                            "non-maintained (emergency operation only), got '%s'",
                            value);
    } else if (!strcmp(key, "emergency_flux")) {
        d->has_eflux = 1, d->eflux_line = line;
        *st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LUMINOUS_FLUX, NULL, &d->eflux, NULL);
        if (*st == LX_OK && !(d->eflux > 0))
            *st = lx__error(ctx, LX_EPARSE, file, line, "emergency_flux: must be greater than zero");
    } else
        return 0;
    return 1;
}

#define GROW(p, n)                                                                                                     \
    do {                                                                                                               \
        void *q_ = lx__realloc_n((p), (n), sizeof *(p));                                                                    \
        if (!q_) return LX_ENOMEM;                                                                                     \
        (p) = q_;                                                                                                      \
    } while (0)

/* grows the per-luminaire arrays to n entries */
static lx_status lum_arrays(lx_scene_design *d, lx__design *in, size_t n)
{
    GROW(d->lum_mf, n);
    GROW(d->lum_maint, n);
    GROW(d->lum_power_W, n);
    GROW(d->lum_mode, n);
    GROW(d->lum_emergency_lm, n);
    GROW(in->lum_maint_name, n);
    GROW(in->lum_maint_line, n);
    GROW(in->lum_mf_line, n);
    in->lum_maint_name[n - 1] = NULL;
    in->n_lum = n;
    return LX_OK;
}

lx_status lx__design_lum_finish(lx_ctx *ctx, lx_scene *sc, scene__lum_design *r)
{
    lx_scene_design *d = sc->design;
    lx__design *in = d->internal;
    size_t i = sc->n_lum - 1;
    const lx_scene_luminaire *l = &sc->lum[i];
    if (lum_arrays(d, in, sc->n_lum) != LX_OK) return lx__error(ctx, LX_ENOMEM, l->file, l->line, "out of memory");
    if (r->has_mf && r->maint)
        return lx__error(ctx, LX_EPARSE, l->file, r->maint_line,
                         "luminaire '%s': give 'maintenance_factor' or 'maintenance' (a scheme), not both", l->name);
    if (r->has_eflux && r->mode == LX_LUM_NORMAL)
        return lx__error(ctx, LX_EPARSE, l->file, r->eflux_line,
                         "luminaire '%s': emergency_flux needs 'emergency = maintained' or 'non-maintained'", l->name);
    d->lum_mf[i] = r->has_mf ? r->mf : NAN; /* NaN: resolved at the end (a scheme, the scene's, or 1) */
    d->lum_maint[i] = -1;
    in->lum_mf_line[i] = r->has_mf ? r->mf_line : 0;
    in->lum_maint_name[i] = r->maint; /* taken */
    in->lum_maint_line[i] = r->maint_line;
    r->maint = NULL;
    d->lum_power_W[i] = r->has_power ? r->power : l->lum && l->lum->input_watts > 0 ? l->lum->input_watts : NAN;
    d->lum_mode[i] = (lx_lum_mode)r->mode;
    d->lum_emergency_lm[i] = r->mode == LX_LUM_NORMAL ? 0 : r->has_eflux ? r->eflux : l->flux_lm;
    return LX_OK;
}

/* ---- receivers ---- */

int lx__design_rec_key(lx_ctx *ctx, scene__rec_design *d, const char *file, long line, const char *key,
                       const char *value, lx_status *st)
{
    if (!strcmp(key, "cylindrical")) {
        d->line = line;
        *st = LX_OK;
        if (!strcmp(value, "yes")) d->cyl |= LX_REC_CYLINDRICAL;
        else if (strcmp(value, "no"))
            *st = lx__error(ctx, LX_EPARSE, file, line, "cylindrical: expected yes or no, got '%s'", value);
    } else if (!strcmp(key, "semicylindrical")) {
        d->line = line;
        d->cyl |= LX_REC_SEMICYLINDRICAL;
        d->has_facing = 1;
        *st = lx__scene_parse_vec(ctx, file, line, key, value, 3, 3, LX_Q_NONE, NULL, d->facing, NULL);
        double h = hypot(d->facing[0], d->facing[1]);
        if (*st == LX_OK && !(h > 0 && isfinite(h)))
            *st = lx__error(ctx, LX_EPARSE, file, line,
                            "semicylindrical: the direction the half-cylinder faces needs a horizontal part (x, y)");
        if (*st == LX_OK) d->facing[0] /= h, d->facing[1] /= h, d->facing[2] = 0;
    } else
        return 0;
    return 1;
}

lx_status lx__design_rec_grow(lx_scene *sc) { return lx__design_rec_grow_to(sc, sc->n_rec); }

lx_status lx__design_rec_grow_to(lx_scene *sc, size_t n)
{
    lx_scene_design *d = sc->design;
    unsigned char *c = lx__realloc_n(d->rec_cylinder, n, sizeof *c);
    if (c) d->rec_cylinder = c;
    double *f = c ? lx__realloc_n(d->rec_facing, 3 * n, sizeof *f) : NULL;
    if (f) d->rec_facing = f;
    return c && f ? LX_OK : LX_ENOMEM;
}

lx_status lx__design_rec_finish(lx_ctx *ctx, lx_scene *sc, const scene__rec_design *r)
{
    lx_scene_design *d = sc->design;
    size_t i = sc->n_rec - 1;
    if (lx__design_rec_grow(sc) != LX_OK) return lx__error(ctx, LX_ENOMEM, sc->rec[i].file, sc->rec[i].line, "out of memory");
    unsigned char *c = d->rec_cylinder;
    double *f = d->rec_facing;
    c[i] = (unsigned char)r->cyl;
    f[3 * i] = r->has_facing ? r->facing[0] : 1, f[3 * i + 1] = r->has_facing ? r->facing[1] : 0, f[3 * i + 2] = 0;
    return LX_OK;
}

/* ---- [scene] ---- */

int lx__design_scene_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value,
                         lx_status *st)
{
    lx__design *in = sc->design->internal;
    if (!strcmp(key, "maintenance_factor")) {
        in->scene_has_mf = 1, in->scene_mf_line = line;
        *st = unit_factor(ctx, file, line, key, value, &in->scene_mf);
    } else if (!strcmp(key, "maintenance")) {
        in->scene_maint_line = line, in->scene_file = file;
        *st = name_key(ctx, file, line, key, value, &in->scene_maint);
    } else
        return 0;
    return 1;
}

/* ---- [maintenance NAME] ---- */

int lx__design_section_kind(const char *kind)
{
    if (!strcmp(kind, "maintenance")) return LX__DSEC_MAINT;
    if (!strcmp(kind, "area")) return LX__DSEC_AREA;
    if (!strcmp(kind, "requirement")) return LX__DSEC_REQ;
    if (!strcmp(kind, "energy")) return LX__DSEC_ENERGY;
    return LX__DSEC_NONE;
}

lx_status lx__design_open(lx_ctx *ctx, lx_scene *sc, int sec, const char *name, const char *file, long line)
{
    lx_scene_design *d = sc->design;
    lx__design *in = d->internal;
    in->section = sec;
    if (sec == LX__DSEC_AREA) return lx__area_open(ctx, sc, name, file, line);
    if (sec == LX__DSEC_REQ) return lx__req_open(ctx, sc, name, file, line);
    if (sec == LX__DSEC_ENERGY) return lx__energy_open(ctx, sc, file, line);
    if (sec != LX__DSEC_MAINT) return LX_OK;
    for (size_t i = 0; i < d->n_maint; i++)
        if (!strcmp(d->maint[i].name, name))
            return lx__error(ctx, LX_EPARSE, file, line, "maintenance scheme '%s' defined twice", name);
    lx_maintenance *nm = lx__realloc_n(d->maint, (d->n_maint + 1), sizeof *nm);
    if (!nm) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    d->maint = nm;
    lx__maint_raw *nr = lx__realloc_n(in->maint, (d->n_maint + 1), sizeof *nr);
    if (!nr) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    in->maint = nr;
    lx_maintenance *m = &d->maint[d->n_maint];
    memset(m, 0, sizeof *m);
    memset(&in->maint[d->n_maint], 0, sizeof in->maint[0]);
    d->n_maint++;
    m->file = file;
    m->line = line;
    m->burning_h = m->cleaning_a = m->room_cleaning_a = NAN;
    m->name = lx__strdup(name);
    m->lamp_type = lx__strdup("");
    m->luminaire_type = lx__strdup("");
    m->environment = lx__strdup("");
    if (!m->name || !m->lamp_type || !m->luminaire_type || !m->environment)
        return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    return LX_OK;
}

/* A factor: one number in (0, 1], or a table "T1: v1, T2: v2, ..." (times with their unit,
 * increasing; at least two points). */
static lx_status factor_key(lx_ctx *ctx, const char *file, long line, const char *key, const char *value, lx__factor *f)
{
    factor_free(f);
    f->given = 1;
    f->line = line;
    if (!strchr(value, ':')) return unit_factor(ctx, file, line, key, value, &f->value);
    size_t cap = 1;
    for (const char *p = value; *p; p++) cap += *p == ',';
    f->t_s = lx__alloc_n(cap, sizeof *f->t_s);
    f->v = lx__alloc_n(cap, sizeof *f->v);
    if (!f->t_s || !f->v) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    const char *p = value;
    while (*p) {
        const char *e = strchr(p, ','), *end = e ? e : p + strlen(p);
        char item[160];
        if ((size_t)(end - p) >= sizeof item) return lx__error(ctx, LX_EPARSE, file, line, "%s: entry too long", key);
        memcpy(item, p, (size_t)(end - p));
        item[end - p] = '\0';
        char *colon = strchr(item, ':');
        if (!colon)
            return lx__error(ctx, LX_EPARSE, file, line,
                             "%s: '%s' is not 'TIME: FACTOR' (a table is 'T1: v1, T2: v2, ...', e.g. '6000 h: 0.93, "
                             "12000 h: 0.89')",
                             key, item);
        *colon = '\0';
        double t, v;
        lx_quantity got = LX_Q_NONE;
        lx_status st = lx_quantity_parse(ctx, item, LX_Q_NONE, NULL, &t, &got);
        if (st != LX_OK) return lx__error(ctx, LX_EPARSE, file, line, "%s: %s", key, lx_ctx_errmsg(ctx));
        if (got != LX_Q_TIME)
            return lx__error(ctx, LX_EPARSE, file, line, "%s: '%s' must be a time with its unit (h, or a for years)", key,
                             item);
        if ((st = unit_factor(ctx, file, line, key, colon + 1, &v)) != LX_OK) return st;
        if (f->n && !(t > f->t_s[f->n - 1]))
            return lx__error(ctx, LX_EPARSE, file, line, "%s: the times must increase", key);
        if (!(t >= 0)) return lx__error(ctx, LX_EPARSE, file, line, "%s: a time must not be negative", key);
        f->t_s[f->n] = t, f->v[f->n] = v, f->n++;
        p = e ? e + 1 : end;
    }
    if (f->n < 2) return lx__error(ctx, LX_EPARSE, file, line, "%s: a table needs at least two points", key);
    return LX_OK;
}

static lx_status time_key(lx_ctx *ctx, const char *file, long line, const char *key, const char *value, double *dst,
                          int *has, long *at)
{
    *has = 1, *at = line;
    lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_TIME, NULL, dst, NULL);
    if (st == LX_OK && !(*dst > 0)) return lx__error(ctx, LX_EPARSE, file, line, "%s: must be greater than zero", key);
    return st;
}

static lx_status text_key(lx_ctx *ctx, const char *file, long line, const char *value, char **dst)
{
    lx__free(*dst);
    *dst = lx__strdup(value);
    return *dst ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
}

static const char *const factor_keys[4] = {"lamp_lumen_maintenance", "lamp_survival", "luminaire_maintenance",
                                           "room_surface_maintenance"};

lx_status lx__design_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value)
{
    lx_scene_design *d = sc->design;
    lx__design *in = d->internal;
    if (in->section == LX__DSEC_AREA) return lx__area_key(ctx, sc, file, line, key, value);
    if (in->section == LX__DSEC_REQ) return lx__req_key(ctx, sc, file, line, key, value);
    if (in->section == LX__DSEC_ENERGY) return lx__energy_key(ctx, sc, file, line, key, value);
    lx_maintenance *m = &d->maint[d->n_maint - 1];
    lx__maint_raw *r = &in->maint[d->n_maint - 1];
    for (int k = 0; k < 4; k++)
        if (!strcmp(key, factor_keys[k])) return factor_key(ctx, file, line, key, value, &r->f[k]);
    if (!strcmp(key, "burning_hours"))
        return time_key(ctx, file, line, key, value, &r->burning_s, &r->has_burning, &r->burning_line);
    if (!strcmp(key, "cleaning_interval"))
        return time_key(ctx, file, line, key, value, &r->cleaning_s, &r->has_cleaning, &r->cleaning_line);
    if (!strcmp(key, "room_cleaning_interval"))
        return time_key(ctx, file, line, key, value, &r->room_cleaning_s, &r->has_room_cleaning, &r->room_cleaning_line);
    if (!strcmp(key, "lamp_type")) return text_key(ctx, file, line, value, &m->lamp_type);
    if (!strcmp(key, "luminaire_type")) return text_key(ctx, file, line, value, &m->luminaire_type);
    if (!strcmp(key, "environment")) return text_key(ctx, file, line, value, &m->environment);
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [maintenance] (keys: lamp_lumen_maintenance, lamp_survival, "
                     "luminaire_maintenance, room_surface_maintenance, burning_hours, cleaning_interval, "
                     "room_cleaning_interval, lamp_type, luminaire_type, environment)",
                     key);
}

/* ---- the whole scene ---- */

/* A table factor read at time t (s): linear between the typed points; no extrapolation. */
static lx_status factor_at(lx_ctx *ctx, const lx_maintenance *m, lx__factor *f, const char *key, const char *tkey,
                           int has_t, double t_s, double unit_s, const char *unit)
{
    if (!f->given) {
        f->value = 1;
        return LX_OK;
    }
    if (!f->n) return LX_OK;
    if (!has_t)
        return lx__error(ctx, LX_EPARSE, m->file, f->line, "maintenance '%s': %s is a table against time: give '%s'",
                         m->name, key, tkey);
    if (t_s < f->t_s[0] || t_s > f->t_s[f->n - 1])
        return lx__error(ctx, LX_EPARSE, m->file, f->line,
                         "maintenance '%s': %s %g %s lies outside the table of %s (%g to %g %s; luxcalc does not "
                         "extrapolate)",
                         m->name, tkey, t_s / unit_s, unit, key, f->t_s[0] / unit_s, f->t_s[f->n - 1] / unit_s, unit);
    size_t k = 0;
    while (k + 2 < f->n && t_s > f->t_s[k + 1]) k++;
    double u = (t_s - f->t_s[k]) / (f->t_s[k + 1] - f->t_s[k]);
    f->value = t_s == f->t_s[k + 1] ? f->v[k + 1] : f->v[k] + u * (f->v[k + 1] - f->v[k]);
    return LX_OK;
}

static lx_status maint_finish(lx_ctx *ctx, lx_maintenance *m, lx__maint_raw *r)
{
    lx_status st;
    if ((st = factor_at(ctx, m, &r->f[0], factor_keys[0], "burning_hours", r->has_burning, r->burning_s, HOUR_S, "h")) ||
        (st = factor_at(ctx, m, &r->f[1], factor_keys[1], "burning_hours", r->has_burning, r->burning_s, HOUR_S, "h")) ||
        (st = factor_at(ctx, m, &r->f[2], factor_keys[2], "cleaning_interval", r->has_cleaning, r->cleaning_s, YEAR_S, "a")) ||
        (st = factor_at(ctx, m, &r->f[3], factor_keys[3], "room_cleaning_interval", r->has_room_cleaning, r->room_cleaning_s,
                        YEAR_S, "a")))
        return st;
    if (!r->f[0].given && !r->f[1].given && !r->f[2].given && !r->f[3].given)
        return lx__error(ctx, LX_EPARSE, m->file, m->line,
                         "maintenance '%s': give at least one of lamp_lumen_maintenance, lamp_survival, "
                         "luminaire_maintenance, room_surface_maintenance",
                         m->name);
    m->llmf = r->f[0].value, m->lsf = r->f[1].value, m->lmf = r->f[2].value, m->rsmf = r->f[3].value;
    m->mf = m->llmf * m->lsf * m->lmf * m->rsmf;
    m->burning_h = r->has_burning ? r->burning_s / HOUR_S : NAN;
    m->cleaning_a = r->has_cleaning ? r->cleaning_s / YEAR_S : NAN;
    m->room_cleaning_a = r->has_room_cleaning ? r->room_cleaning_s / YEAR_S : NAN;
    return LX_OK;
}

static long find_maint(const lx_scene_design *d, const char *name)
{
    for (size_t i = 0; i < d->n_maint; i++)
        if (!strcmp(d->maint[i].name, name)) return (long)i;
    return -1;
}

lx_status lx__design_finish(lx_ctx *ctx, lx_scene *sc)
{
    lx_scene_design *d = sc->design;
    lx__design *in = d->internal;
    lx_status st;
    for (size_t i = 0; i < d->n_maint; i++)
        if ((st = maint_finish(ctx, &d->maint[i], &in->maint[i])) != LX_OK) return st;
    /* the scene's default */
    if (in->scene_has_mf && in->scene_maint)
        return lx__error(ctx, LX_EPARSE, sc->file, in->scene_maint_line,
                         "[scene]: give 'maintenance_factor' or 'maintenance' (a scheme), not both");
    int any = in->scene_has_mf;
    d->scene_mf = in->scene_has_mf ? in->scene_mf : 1;
    if (in->scene_maint) {
        d->scene_maint = find_maint(d, in->scene_maint);
        if (d->scene_maint < 0)
            return lx__error(ctx, LX_EPARSE, in->scene_file, in->scene_maint_line,
                             "maintenance: no [maintenance %s] section", in->scene_maint);
        d->scene_mf = d->maint[d->scene_maint].mf;
        any = 1;
    }
    for (size_t i = 0; i < sc->n_lum; i++) {
        const lx_scene_luminaire *l = &sc->lum[i];
        if (in->lum_maint_name[i]) {
            d->lum_maint[i] = find_maint(d, in->lum_maint_name[i]);
            if (d->lum_maint[i] < 0)
                return lx__error(ctx, LX_EPARSE, l->file, in->lum_maint_line[i], "maintenance: no [maintenance %s] section",
                                 in->lum_maint_name[i]);
            d->lum_mf[i] = d->maint[d->lum_maint[i]].mf;
            any = 1;
        } else if (isnan(d->lum_mf[i])) {
            d->lum_mf[i] = d->scene_mf;
            d->lum_maint[i] = d->scene_maint;
        } else
            any = 1;
    }
    d->maintained = any;
    lx_status ast = lx__area_finish(ctx, sc);
    return ast == LX_OK ? lx__req_finish(ctx, sc) : ast;
}
