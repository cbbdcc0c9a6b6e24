/* scene_entities.c - the keys of [luminaire], [receiver] and [sky] sections, their checks when a
 * section ends (required keys, exclusive keys, ranges), and the scene's own life cycle. */
#include "scene/design_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *xstrdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = lx__alloc(n);
    if (p) memcpy(p, s, n);
    return p;
}

char *lx__scene_keep_name(lx_scene *sc, const char *name)
{
    for (size_t i = 0; i < sc->n_names; i++)
        if (!strcmp(sc->names[i], name)) return sc->names[i];
    char **nn = lx__realloc_n(sc->names, sc->n_names + 1, sizeof *nn);
    if (!nn) return NULL;
    sc->names = nn;
    char *c = xstrdup(name);
    if (!c) return NULL;
    sc->names[sc->n_names++] = c;
    return c;
}

lx_scene *lx__scene_new(const char *file)
{
    lx_scene *sc = lx__calloc(1, sizeof *sc);
    if (!sc) return NULL;
    sc->file = xstrdup(file);
    sc->title = xstrdup("");
    sc->sky_scale = 1;
    sc->sky_cct_K = NAN;
    sc->sky_samples = 64;
    sc->nearfield_tol = 1e-5;
    sc->interreflection_tol = 1e-3;
    sc->patch_refinement = 1;
    if (!sc->file || !sc->title || lx__design_new(sc) != LX_OK) {
        lx_scene_free(sc);
        return NULL;
    }
    return sc;
}

void lx_scene_free(lx_scene *sc)
{
    if (!sc) return;
    for (size_t i = 0; i < sc->n_lum; i++) {
        lx_scene_luminaire *l = &sc->lum[i];
        lx__free(l->name);
        lx__free(l->lum_path);
        lx__free(l->spd_path);
        lx_luminaire_free(l->lum);
        lx_spd_set_free(l->spd);
    }
    for (size_t i = 0; i < sc->n_rec; i++) {
        lx__free(sc->rec[i].name);
        lx__free(sc->rec[i].points);
    }
    for (size_t i = 0; i < sc->n_names; i++) lx__free(sc->names[i]);
    lx__free(sc->names);
    lx__free(sc->lum);
    lx__free(sc->rec);
    lx__free(sc->sky_path);
    lx_envmap_free(sc->sky_map);
    lx__room_scene_free(sc);
    lx__daylight_scene_free(sc);
    lx__design_free(sc);
    for (size_t i = 0; i < sc->n_obs; i++) lx__free(sc->obs[i].name);
    lx__free(sc->obs);
    lx__free(sc->title);
    lx__free(sc->file);
    lx__free(sc);
}

static lx_status normalise(lx_ctx *ctx, const char *file, long line, const char *what, double v[3])
{
    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(n > 0) || !isfinite(n)) return lx__error(ctx, LX_EPARSE, file, line, "%s: a direction of zero length", what);
    for (int i = 0; i < 3; i++) v[i] /= n;
    return LX_OK;
}

/* ---- luminaires ---- */

void lx__scene_lum_raw_init(scene__lum_raw *r, const char *name, const char *file, long line)
{
    lx__scene_lum_raw_free(r);
    memset(r, 0, sizeof *r);
    r->name = xstrdup(name);
    r->file = file;
    r->line = line;
    r->active = 1;
}

void lx__scene_lum_raw_free(scene__lum_raw *r)
{
    if (!r->active) return;
    lx__free(r->name);
    lx__free(r->type);
    lx__free(r->lum_file);
    lx__free(r->spd);
    lx__free(r->spectrum);
    lx__design_lum_raw_free(&r->design);
    memset(r, 0, sizeof *r);
}

static lx_status str_key(lx_ctx *ctx, const char *file, long line, const char *key, const char *value, char **dst,
                         long *dst_line)
{
    if (!*value) return lx__error(ctx, LX_EPARSE, file, line, "%s: empty value", key);
    *dst = xstrdup(value);
    if (dst_line) *dst_line = line;
    return *dst ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
}

#define VEC(k, n, q, dst, flag)                                                              \
    if (!strcmp(key, k)) {                                                                   \
        flag = 1;                                                                            \
        return lx__scene_parse_vec(ctx, file, line, key, value, n, n, q, NULL, dst, NULL); \
    }

lx_status lx__scene_lum_key(lx_ctx *ctx, scene__lum_raw *r, const char *file, long line, const char *key,
                            const char *value)
{
    if (!strcmp(key, "type")) return str_key(ctx, file, line, key, value, &r->type, &r->type_line);
    if (!strcmp(key, "file")) return str_key(ctx, file, line, key, value, &r->lum_file, &r->lum_file_line);
    if (!strcmp(key, "spd")) return str_key(ctx, file, line, key, value, &r->spd, &r->spd_line);
    if (!strcmp(key, "spectrum")) return str_key(ctx, file, line, key, value, &r->spectrum, NULL);
    if (!strcmp(key, "flux")) r->flux_line = line;
    if (!strcmp(key, "cct")) r->cct_line = line;
    VEC("position", 3, LX_Q_LENGTH, r->pos, r->has_pos)
    VEC("aim", 3, LX_Q_NONE, r->aim, r->has_aim)
    VEC("rotate", 1, LX_Q_ANGLE, &r->rotate, r->has_rotate)
    VEC("flux", 1, LX_Q_LUMINOUS_FLUX, &r->flux, r->has_flux)
    VEC("intensity", 1, LX_Q_LUMINOUS_INTENSITY, &r->intensity, r->has_intensity)
    VEC("exponent", 1, LX_Q_NONE, &r->exponent, r->has_exponent)
    VEC("beam", 1, LX_Q_ANGLE, &r->beam, r->has_beam)
    VEC("luminance", 1, LX_Q_LUMINANCE, &r->luminance, r->has_luminance)
    VEC("radius", 1, LX_Q_LENGTH, &r->radius, r->has_radius)
    VEC("width", 1, LX_Q_LENGTH, &r->width, r->has_width)
    VEC("length", 1, LX_Q_LENGTH, &r->length, r->has_length)
    VEC("cct", 1, LX_Q_TEMPERATURE, &r->cct, r->has_cct)
    VEC("multiplier", 1, LX_Q_NONE, &r->multiplier, r->has_multiplier)
    lx_status st = LX_OK;
    if (lx__design_lum_key(ctx, &r->design, file, line, key, value, &st)) return st;
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [luminaire] (keys: type, position, aim, rotate, flux, intensity, exponent, "
                     "beam, luminance, radius, width, length, file, multiplier, spd, spectrum, cct, "
                     "maintenance_factor, maintenance, power, emergency, emergency_flux)",
                     key);
}

/* Which keys each type accepts (besides position, aim, rotate, spd, spectrum, cct). */
static const char *const lum_allowed[] = {
    /* point */ "flux intensity",
    /* spot */ "flux intensity exponent beam",
    /* disk */ "flux luminance radius",
    /* rect */ "flux luminance width length",
    /* file */ "flux multiplier file width length",
};

static int allowed(int kind, const char *key)
{
    const char *a = lum_allowed[kind];
    size_t n = strlen(key);
    for (const char *p = a; (p = strstr(p, key)); p += n)
        if ((p == a || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return 1;
    return 0;
}

/* The type (one of lum_kinds), the keys that type accepts, and the position: in this order. */
static const char *const lum_kinds[] = {"point", "spot", "disk", "rect", "file"};

static lx_status lum_kind(lx_ctx *ctx, const scene__lum_raw *r, int *kind_out)
{
    const char *f = r->file;
    long ln = r->line;
    int kind = -1;
    if (!r->type)
        return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': missing 'type' (point, spot, disk, rect or file)",
                         r->name);
    for (int k = 0; k < 5; k++)
        if (!strcmp(r->type, lum_kinds[k])) kind = k;
    if (kind < 0)
        return lx__error(ctx, LX_EPARSE, f, r->type_line,
                         "type: unknown luminaire type '%s' (point, spot, disk, rect, file)", r->type);
    struct {
        const char *k;
        int has;
    } given[] = {{"flux", r->has_flux},        {"intensity", r->has_intensity}, {"exponent", r->has_exponent},
                 {"beam", r->has_beam},        {"luminance", r->has_luminance}, {"radius", r->has_radius},
                 {"width", r->has_width},      {"length", r->has_length},       {"multiplier", r->has_multiplier},
                 {"file", r->lum_file != NULL}};
    for (size_t i = 0; i < sizeof given / sizeof given[0]; i++)
        if (given[i].has && !allowed(kind, given[i].k))
            return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': '%s' does not apply to type %s", r->name,
                             given[i].k, lum_kinds[kind]);
    if (!r->has_pos) return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': missing 'position'", r->name);
    *kind_out = kind;
    return LX_OK;
}

/* The fields every type shares: kind, source line, position, aim (normalised), rotation; the rest unset. */
static lx_status lum_base(lx_ctx *ctx, const scene__lum_raw *r, int kind, lx_scene_luminaire *l)
{
    memset(l, 0, sizeof *l);
    l->kind = (lx_scene_lum_kind)kind;
    l->file = r->file;
    l->line = r->line;
    memcpy(l->pos_m, r->pos, sizeof l->pos_m);
    l->aim[2] = -1;
    if (r->has_aim) {
        memcpy(l->aim, r->aim, sizeof l->aim);
        lx_status st = normalise(ctx, r->file, r->line, "aim", l->aim);
        if (st != LX_OK) return st;
    }
    l->rotate_rad = r->has_rotate ? r->rotate : 0;
    l->cct_K = NAN;
    l->scale = 1;
    l->intensity_cd = l->flux_lm = l->exponent = l->luminance_cd_m2 = NAN;
    return LX_OK;
}

#define NEED_ONE(a, ha, b, hb)                                                                                         \
    if (!(ha) == !(hb))                                                                                                \
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "luminaire '%s': give exactly one of '%s' and '%s'",        \
                         r->name, a, b);
#define POSITIVE(v, k)                                                                                                 \
    if (!((v) > 0))                                                                                                    \
        return lx__error(ctx, LX_EPARSE, r->file, r->line, "luminaire '%s': '%s' must be greater than zero", r->name,  \
                         k);

/* A spot: flux or intensity, exponent or beam. */
static lx_status lum_spot(lx_ctx *ctx, const scene__lum_raw *r, lx_scene_luminaire *l)
{
    const char *f = r->file;
    long ln = r->line;
    NEED_ONE("flux", r->has_flux, "intensity", r->has_intensity);
    NEED_ONE("exponent", r->has_exponent, "beam", r->has_beam);
    if (r->has_beam) {
        if (!(r->beam > 0 && r->beam < LX__PI))
            return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': beam must be between 0 and 180 deg", r->name);
        if (lx_warn_exponent_from_beam(ctx, r->beam, &l->exponent) != LX_OK)
            return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': beam: %s", r->name, lx_ctx_errmsg(ctx));
    } else {
        if (!(r->exponent >= 0))
            return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': exponent must be >= 0", r->name);
        l->exponent = r->exponent;
    }
    l->intensity_cd = r->has_flux ? (l->exponent + 1) * r->flux / (2 * LX__PI) : r->intensity;
    l->flux_lm = 2 * LX__PI * l->intensity_cd / (l->exponent + 1);
    return LX_OK;
}

/* A disk or a rectangle: flux or luminance, and its size. */
static lx_status lum_area(lx_ctx *ctx, const scene__lum_raw *r, lx_scene_luminaire *l)
{
    const char *f = r->file;
    long ln = r->line;
    NEED_ONE("flux", r->has_flux, "luminance", r->has_luminance);
    double area;
    if (l->kind == LX_SLUM_DISK) {
        if (!r->has_radius) return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': missing 'radius'", r->name);
        POSITIVE(r->radius, "radius");
        l->radius_m = r->radius;
        area = LX__PI * r->radius * r->radius;
    } else {
        if (!r->has_width || !r->has_length)
            return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': missing 'width' or 'length'", r->name);
        POSITIVE(r->width, "width");
        POSITIVE(r->length, "length");
        l->width_m = r->width;
        l->length_m = r->length;
        area = r->width * r->length;
    }
    /* a Lambertian emitter: exitance M = pi L, flux F = pi L A */
    l->luminance_cd_m2 = r->has_flux ? r->flux / (LX__PI * area) : r->luminance;
    l->flux_lm = LX__PI * l->luminance_cd_m2 * area;
    l->intensity_cd = l->luminance_cd_m2 * area; /* on the axis */
    return LX_OK;
}

/* A photometric file: read it, take its opening (or width/length), scale it by flux or multiplier and
   its TILT table. On failure nothing it read is kept. */
static lx_status lum_file(lx_ctx *ctx, const scene__lum_raw *r, lx_scene_luminaire *l)
{
    const char *f = r->file;
    long ln = r->line;
    if (!r->lum_file)
        return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': missing 'file' (an IES or LDT file)", r->name);
    if (r->has_flux && r->has_multiplier)
        return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': give 'flux' or 'multiplier', not both", r->name);
    if (r->has_multiplier) POSITIVE(r->multiplier, "multiplier");
    if (r->has_width && !(r->width >= 0)) POSITIVE(r->width, "width");
    if (r->has_length && !(r->length >= 0)) POSITIVE(r->length, "length");
    l->lum_path = lx__scene_resolve(f, r->lum_file);
    if (!l->lum_path) return lx__error(ctx, LX_ENOMEM, f, ln, "out of memory");
    lx_status st = lx_luminaire_read_file(ctx, l->lum_path, &l->lum);
    if (st != LX_OK) {
        char inner[LX__ERRMSG_MAX];
        snprintf(inner, sizeof inner, "%s", lx_ctx_errmsg(ctx));
        st = lx__error(ctx, st, f, r->lum_file_line, "file: %s", inner);
        lx__free(l->lum_path);
        return st;
    }
    /* the luminous opening: negative IES sizes mean round (diameter) */
    double w = l->lum->width_m, len = l->lum->length_m;
    if (w < 0 || len < 0)
        l->radius_m = fabs(w < 0 ? w : len) / 2;
    else
        l->width_m = w, l->length_m = len;
    if (r->has_width || r->has_length) {
        l->radius_m = 0;
        l->width_m = r->has_width ? r->width : l->width_m;
        l->length_m = r->has_length ? r->length : l->length_m;
    }
    lx_lum_summary sum;
    st = lx_luminaire_summary(ctx, l->lum, &sum);
    if (st != LX_OK || !(sum.lumens > 0)) {
        if (st == LX_OK) st = lx__error(ctx, LX_EPARSE, f, r->lum_file_line, "file: the luminaire emits no light");
        lx_luminaire_free(l->lum);
        lx__free(l->lum_path);
        return st;
    }
    l->scale = r->has_flux ? r->flux / sum.lumens : r->has_multiplier ? r->multiplier : 1;
    l->flux_lm = sum.lumens * l->scale;
    /* a TILT table: the lamp output at the luminaire's tilt (as lx_grid_illuminance applies it) */
    l->scale *= lx_luminaire_tilt_factor(l->lum, acos(fmax(-1.0, fmin(1.0, -l->aim[2]))));
    l->intensity_cd = sum.max_intensity_cd * l->scale;
    return LX_OK;
}

/* The photometry of each type: intensity, flux, luminance as the type defines them. */
static lx_status lum_photometry(lx_ctx *ctx, const scene__lum_raw *r, lx_scene_luminaire *l)
{
    if (r->has_flux) POSITIVE(r->flux, "flux");
    if (r->has_intensity) POSITIVE(r->intensity, "intensity");
    if (r->has_luminance) POSITIVE(r->luminance, "luminance");
    switch (l->kind) {
    case LX_SLUM_POINT:
        NEED_ONE("flux", r->has_flux, "intensity", r->has_intensity);
        l->intensity_cd = r->has_flux ? r->flux / (4 * LX__PI) : r->intensity;
        l->flux_lm = 4 * LX__PI * l->intensity_cd;
        break;
    case LX_SLUM_SPOT: return lum_spot(ctx, r, l);
    case LX_SLUM_DISK:
    case LX_SLUM_RECT: return lum_area(ctx, r, l);
    case LX_SLUM_FILE: return lum_file(ctx, r, l);
    }
    return LX_OK;
}

/* The colour: a CCT or a spectrum from an SPD file (one of its spectra by name). The caller frees what
   this read when it fails. */
static lx_status lum_colour(lx_ctx *ctx, const scene__lum_raw *r, lx_scene_luminaire *l)
{
    const char *f = r->file;
    long ln = r->line;
    if (r->spd && r->has_cct)
        return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': give 'spd' or 'cct', not both", r->name);
    if (r->spectrum && !r->spd)
        return lx__error(ctx, LX_EPARSE, f, ln, "luminaire '%s': 'spectrum' needs 'spd'", r->name);
    if (r->has_cct) {
        if (!(r->cct >= 1000 && r->cct <= 25000))
            return lx__error(ctx, LX_EPARSE, f, r->cct_line, "cct: must be from 1000 K to 25000 K");
        l->cct_K = r->cct;
    }
    if (!r->spd) return LX_OK;
    l->spd_path = lx__scene_resolve(f, r->spd);
    if (!l->spd_path) return lx__error(ctx, LX_ENOMEM, f, ln, "out of memory");
    lx_status st = lx_spd_read_file(ctx, l->spd_path, &l->spd);
    if (st != LX_OK) {
        char inner[LX__ERRMSG_MAX];
        snprintf(inner, sizeof inner, "%s", lx_ctx_errmsg(ctx));
        return lx__error(ctx, st, f, r->spd_line, "spd: %s", inner);
    }
    if (r->spectrum) {
        size_t k = 0;
        while (k < l->spd->count && !(l->spd->spd[k].name && !strcmp(l->spd->spd[k].name, r->spectrum)))
            k++;
        if (k == l->spd->count)
            return lx__error(ctx, LX_EPARSE, f, r->spd_line, "spd: no spectrum named '%s' in %s", r->spectrum,
                             l->spd_path);
        l->spd_index = k;
    } else if (l->spd->count != 1) {
        return lx__error(ctx, LX_EPARSE, f, r->spd_line, "spd: %s holds %zu spectra: choose one with 'spectrum = NAME'",
                         l->spd_path, l->spd->count);
    }
    return LX_OK;
}

#undef NEED_ONE
#undef POSITIVE

lx_status lx__scene_lum_finish(lx_ctx *ctx, lx_scene *sc, scene__lum_raw *r)
{
    lx_scene_luminaire l;
    int kind = -1;
    lx_status st = lum_kind(ctx, r, &kind);
    if (st == LX_OK) st = lum_base(ctx, r, kind, &l);
    if (st == LX_OK) st = lum_photometry(ctx, r, &l);
    if (st != LX_OK) goto out;
    if ((st = lum_colour(ctx, r, &l)) != LX_OK) goto fail_l;
    lx_scene_luminaire *nl = lx__realloc_n(sc->lum, sc->n_lum + 1, sizeof *nl);
    if (!nl) {
        st = lx__error(ctx, LX_ENOMEM, r->file, r->line, "out of memory");
        goto fail_l;
    }
    sc->lum = nl;
    l.name = r->name;
    r->name = NULL;
    sc->lum[sc->n_lum++] = l;
    st = lx__design_lum_finish(ctx, sc, &r->design);
    goto out;
fail_l:
    lx_luminaire_free(l.lum);
    lx_spd_set_free(l.spd);
    lx__free(l.lum_path);
    lx__free(l.spd_path);
out:
    lx__scene_lum_raw_free(r);
    return st;
}

/* ---- receivers ---- */

void lx__scene_rec_raw_init(scene__rec_raw *r, const char *name, const char *file, long line)
{
    lx__scene_rec_raw_free(r);
    memset(r, 0, sizeof *r);
    r->name = xstrdup(name);
    r->file = file;
    r->line = line;
    r->active = 1;
}

void lx__scene_rec_raw_free(scene__rec_raw *r)
{
    if (!r->active) return;
    lx__free(r->name);
    lx__free(r->type);
    memset(r, 0, sizeof *r);
}

lx_status lx__scene_rec_key(lx_ctx *ctx, scene__rec_raw *r, const char *file, long line, const char *key,
                            const char *value)
{
    if (!strcmp(key, "type")) return str_key(ctx, file, line, key, value, &r->type, NULL);
    VEC("position", 3, LX_Q_LENGTH, r->pos, r->has_pos)
    VEC("normal", 3, LX_Q_NONE, r->normal, r->has_normal)
    VEC("reflectance", 1, LX_Q_NONE, &r->refl, r->has_refl)
    VEC("spacing", 1, LX_Q_LENGTH, &r->spacing, r->has_spacing)
    {
        lx_status st = LX_OK;
        if (lx__design_rec_key(ctx, &r->design, file, line, key, value, &st)) return st;
    }
    if (!strcmp(key, "x") || !strcmp(key, "y") || !strcmp(key, "z")) {
        int *n = key[0] == 'x' ? &r->nx : key[0] == 'y' ? &r->ny : &r->nz;
        double *d = key[0] == 'x' ? r->xr : key[0] == 'y' ? r->yr : r->zr;
        return lx__scene_parse_vec(ctx, file, line, key, value, 1, 2, LX_Q_LENGTH, NULL, d, n);
    }
    if (!strcmp(key, "points")) {
        double p[2];
        r->has_points = 1;
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 2, 2, LX_Q_NONE, NULL, p, NULL);
        if (st != LX_OK) return st;
        for (int i = 0; i < 2; i++) {
            if (!(p[i] >= 1 && p[i] <= LX__SCENE_MAX_POINTS_AXIS) || p[i] != floor(p[i]))
                return lx__error(ctx, LX_EPARSE, file, line, "points: whole numbers from 1 to %d", LX__SCENE_MAX_POINTS_AXIS);
            r->points[i] = (long)p[i];
        }
        return LX_OK;
    }
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [receiver] (keys: type, position, normal, reflectance, x, y, z, spacing, "
                     "points, cylindrical, semicylindrical)",
                     key);
}

/* A point receiver: its position, facing up unless a normal is given. */
static lx_status rec_point(lx_ctx *ctx, const scene__rec_raw *r, lx_scene_receiver *rc)
{
    rc->kind = LX_SREC_POINT;
    if (!r->has_pos || r->nx || r->ny || r->nz || r->has_spacing || r->has_points)
        return lx__error(ctx, LX_EPARSE, r->file, r->line,
                         "receiver '%s': a point takes 'position' (and normal, reflectance), not x/y/z/spacing/points",
                         r->name);
    rc->normal[2] = 1;
    rc->n = 1;
    rc->points = lx__alloc_n(3, sizeof *rc->points);
    if (!rc->points) return lx__error(ctx, LX_ENOMEM, r->file, r->line, "out of memory");
    memcpy(rc->points, r->pos, 3 * sizeof *rc->points);
    return LX_OK;
}

/* The number of grid points along the free axes A and B (given by 'points' or from the spacing). */
static lx_status rec_grid_counts(lx_ctx *ctx, const scene__rec_raw *r, const double *rg[3], int A, int B, size_t cnt[2])
{
    for (int k = 0; k < 2; k++) {
        const double *q = rg[k ? B : A];
        if (!(q[1] >= q[0]))
            return lx__error(ctx, LX_EPARSE, r->file, r->line, "receiver '%s': %c range must go from low to high",
                             r->name, 'x' + (k ? B : A));
        if (r->has_points)
            cnt[k] = (size_t)r->points[k];
        else {
            double c = floor((q[1] - q[0]) / r->spacing + 1e-9) + 1;
            if (c > LX__SCENE_MAX_POINTS_AXIS)
                return lx__error(ctx, LX_EPARSE, r->file, r->line, "receiver '%s': more than %d points along an axis",
                                 r->name, LX__SCENE_MAX_POINTS_AXIS);
            cnt[k] = (size_t)c;
        }
    }
    return LX_OK;
}

/* A grid receiver: one of x, y, z fixed (the plane), the other two ranges; its points row by row. */
static lx_status rec_grid(lx_ctx *ctx, const scene__rec_raw *r, lx_scene_receiver *rc)
{
    const char *f = r->file;
    long ln = r->line;
    rc->kind = LX_SREC_GRID;
    int ns[3] = {r->nx, r->ny, r->nz};
    const double *rg[3] = {r->xr, r->yr, r->zr};
    int fixed = -1, nfix = 0;
    for (int a = 0; a < 3; a++)
        if (ns[a] == 1) fixed = a, nfix++;
    if (r->has_pos || nfix != 1 || !ns[0] || !ns[1] || !ns[2])
        return lx__error(ctx, LX_EPARSE, f, ln,
                         "receiver '%s': a grid takes x, y and z: one of them a single value (the plane), the "
                         "other two 'FROM, TO' ranges (e.g. x = 0 m, 4 m; y = 0 m, 3 m; z = 0.8 m)",
                         r->name);
    if (r->has_spacing == r->has_points)
        return lx__error(ctx, LX_EPARSE, f, ln, "receiver '%s': give exactly one of 'spacing' and 'points'", r->name);
    if (r->has_spacing && !(r->spacing > 0))
        return lx__error(ctx, LX_EPARSE, f, ln, "receiver '%s': spacing must be greater than zero", r->name);
    rc->axis = (char)('x' + fixed);
    int A = fixed == 0 ? 1 : 0, B = fixed == 2 ? 1 : 2; /* the free axes, in x, y, z order */
    size_t cnt[2];
    lx_status st = rec_grid_counts(ctx, r, rg, A, B, cnt);
    if (st != LX_OK) return st;
    rc->na = cnt[0];
    rc->nb = cnt[1];
    rc->n = rc->na * rc->nb;
    if (rc->n > LX__SCENE_MAX_POINTS)
        return lx__error(ctx, LX_EPARSE, f, ln, "receiver '%s': more than %d points", r->name, LX__SCENE_MAX_POINTS);
    rc->points = lx__alloc_n(3 * rc->n, sizeof *rc->points);
    if (!rc->points) return lx__error(ctx, LX_ENOMEM, f, ln, "out of memory");
    double da = 0, db = 0;
    if (r->has_spacing)
        da = db = r->spacing;
    else {
        da = rc->na > 1 ? (rg[A][1] - rg[A][0]) / (double)(rc->na - 1) : 0;
        db = rc->nb > 1 ? (rg[B][1] - rg[B][0]) / (double)(rc->nb - 1) : 0;
    }
    for (size_t j = 0; j < rc->nb; j++)
        for (size_t i = 0; i < rc->na; i++) {
            double *p = rc->points + 3 * (j * rc->na + i);
            p[fixed] = rg[fixed][0];
            p[A] = rg[A][0] + (double)i * da;
            p[B] = rg[B][0] + (double)j * db;
        }
    rc->normal[fixed] = 1;
    return LX_OK;
}

lx_status lx__scene_rec_finish(lx_ctx *ctx, lx_scene *sc, scene__rec_raw *r)
{
    const char *f = r->file;
    long ln = r->line;
    lx_status st = LX_OK;
    lx_scene_receiver rc;
    memset(&rc, 0, sizeof rc);
    rc.file = f;
    rc.line = ln;
    rc.reflectance = NAN;
    if (!r->type || (strcmp(r->type, "point") && strcmp(r->type, "grid"))) {
        st = lx__error(ctx, LX_EPARSE, f, ln, "receiver '%s': 'type' must be point or grid", r->name);
        goto out;
    }
    if (r->has_refl) {
        if (!(r->refl >= 0 && r->refl <= 1)) {
            st = lx__error(ctx, LX_EPARSE, f, ln, "receiver '%s': reflectance must be from 0 to 1", r->name);
            goto out;
        }
        rc.reflectance = r->refl;
    }
    st = !strcmp(r->type, "point") ? rec_point(ctx, r, &rc) : rec_grid(ctx, r, &rc);
    if (st != LX_OK) goto out;
    if (r->has_normal) {
        memcpy(rc.normal, r->normal, sizeof rc.normal);
        if ((st = normalise(ctx, f, ln, "normal", rc.normal)) != LX_OK) goto out;
    }
    lx_scene_receiver *nr = lx__realloc_n(sc->rec, sc->n_rec + 1, sizeof *nr);
    if (!nr) {
        st = lx__error(ctx, LX_ENOMEM, f, ln, "out of memory"); /* the points are freed below */
        goto out;
    }
    sc->rec = nr;
    rc.name = r->name;
    r->name = NULL;
    sc->rec[sc->n_rec++] = rc;
    scene__rec_design dz = r->design;
    lx__scene_rec_raw_free(r);
    return lx__design_rec_finish(ctx, sc, &dz);
out:
    if (st != LX_OK) lx__free(rc.points);
    lx__scene_rec_raw_free(r);
    return st;
}

/* ---- sky ---- */

lx_status lx__scene_sky_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key,
                            const char *value)
{
    if (!strcmp(key, "type")) {
        if (!strcmp(value, "uniform")) sc->sky = LX_SKY_UNIFORM;
        else if (!strcmp(value, "overcast")) sc->sky = LX_SKY_OVERCAST;
        else if (!strcmp(value, "map")) sc->sky = LX_SKY_MAP;
        else if (!strcmp(value, "cie")) sc->sky = LX_SKY_CIE;
        else if (!strcmp(value, "perez")) sc->sky = LX_SKY_PEREZ;
        else return lx__error(ctx, LX_EPARSE, file, line, "type: unknown sky '%s' (uniform, overcast, map, cie, perez)", value);
        return LX_OK;
    }
    if (!strcmp(key, "luminance")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LUMINANCE, NULL,
                                           &sc->sky_luminance_cd_m2, NULL);
        if (st == LX_OK && !(sc->sky_luminance_cd_m2 >= 0))
            return lx__error(ctx, LX_EPARSE, file, line, "luminance: must not be negative");
        return st;
    }
    if (!strcmp(key, "file")) {
        if (!*value) return lx__error(ctx, LX_EPARSE, file, line, "file: empty value");
        sc->sky_file_line = line;
        sc->sky_path = lx__scene_resolve(file, value);
        return sc->sky_path ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    }
    if (!strcmp(key, "scale")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL, &sc->sky_scale, NULL);
        if (st == LX_OK && !(sc->sky_scale >= 0)) return lx__error(ctx, LX_EPARSE, file, line, "scale: must not be negative");
        return st;
    }
    if (!strcmp(key, "ground_reflectance")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL,
                                           &sc->ground_reflectance, NULL);
        if (st == LX_OK && !(sc->ground_reflectance >= 0 && sc->ground_reflectance <= 1))
            return lx__error(ctx, LX_EPARSE, file, line, "ground_reflectance: must be from 0 to 1");
        return st;
    }
    if (!strcmp(key, "cct")) {
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_TEMPERATURE, NULL, &sc->sky_cct_K,
                                           NULL);
        if (st == LX_OK && !(sc->sky_cct_K >= 4000 && sc->sky_cct_K <= 25000))
            return lx__error(ctx, LX_EPARSE, file, line, "cct: a daylight sky takes 4000 K to 25000 K");
        return st;
    }
    if (!strcmp(key, "samples")) {
        double v;
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL, &v, NULL);
        if (st == LX_OK && !(v >= 4 && v <= LX__SCENE_MAX_SKY_SAMPLES && v == floor(v)))
            return lx__error(ctx, LX_EPARSE, file, line, "samples: a whole number from 4 to %d", LX__SCENE_MAX_SKY_SAMPLES);
        if (st == LX_OK) sc->sky_samples = (int)v;
        return st;
    }
    int known = 0;
    lx_status st = lx__scene_sky_daylight_key(ctx, sc, file, line, key, value, &known);
    if (known) return st;
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [sky] (keys: type, luminance, file, scale, ground_reflectance, cct, samples; "
                     "cie: number, luminance or illuminance; perez: direct_normal, diffuse_horizontal, day_of_year, "
                     "precipitable_water)",
                     key);
}

lx_status lx__scene_finish(lx_ctx *ctx, lx_scene *sc)
{
    if (sc->sky_line) {
        const char *f = sc->sky_file_at;
        if (sc->sky == LX_SKY_NONE) return lx__error(ctx, LX_EPARSE, f, sc->sky_line, "[sky]: missing 'type'");
        if (sc->sky == LX_SKY_MAP && !sc->sky_path)
            return lx__error(ctx, LX_EPARSE, f, sc->sky_line, "[sky]: a map sky needs 'file' (an EXR radiance map)");
        if (sc->sky != LX_SKY_MAP && sc->sky_path)
            return lx__error(ctx, LX_EPARSE, f, sc->sky_line, "[sky]: 'file' applies to type map only");
        if (sc->sky == LX_SKY_MAP) {
            lx_status st = lx_exr_read(ctx, sc->sky_path, &sc->sky_map);
            if (st != LX_OK) {
                char inner[LX__ERRMSG_MAX];
                snprintf(inner, sizeof inner, "%s", lx_ctx_errmsg(ctx));
                return lx__error(ctx, st, f, sc->sky_file_line, "file: %s", inner);
            }
        }
        if ((sc->sky == LX_SKY_UNIFORM || sc->sky == LX_SKY_OVERCAST) && !(sc->sky_luminance_cd_m2 > 0))
            return lx__error(ctx, LX_EPARSE, f, sc->sky_line, "[sky]: missing 'luminance' (a %s sky needs one)",
                             sc->sky == LX_SKY_UNIFORM ? "uniform" : "overcast (zenith)");
    }
    if (sc->n_rec == 0) return lx__error(ctx, LX_EPARSE, sc->file, 0, "the scene has no [receiver NAME] section");
    if (sc->n_lum == 0 && sc->sky == LX_SKY_NONE && !(sc->has_sun && sc->sun_normal_lx > 0))
        return lx__error(ctx, LX_EPARSE, sc->file, 0, "the scene has neither a luminaire nor a sky (nor a sun)");
    lx_status rst = lx__room_scene_check(ctx, sc);
    if (rst == LX_OK) rst = lx__daylight_scene_check(ctx, sc);
    if (rst != LX_OK) return rst;
    if (sc->want_luminance) {
        size_t k = 0;
        while (k < sc->n_rec && !(sc->rec[k].reflectance >= 0)) k++;
        if (k == sc->n_rec)
            return lx__error(ctx, LX_EPARSE, sc->file, 0,
                             "[output] luminance = yes, but no receiver has a 'reflectance'");
    }
    return LX_OK;
}
