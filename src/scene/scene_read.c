/* scene_read.c - the scene file reader: INI-like sections, `key = value` with units on every
 * number, `#` comments, includes relative to the including file (cycles detected). Every error
 * names the scene file and line; unknown sections and keys are errors. */
#include "scene/design_private.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define MAX_DEPTH LX__SCENE_MAX_DEPTH

enum { SEC_NONE = 0, SEC_SCENE, SEC_LUM, SEC_REC, SEC_SKY, SEC_OUTPUT, SEC_EFFECTS, SEC_SUN, SEC_OBS, SEC_ROOM, SEC_OPEN,
       SEC_DESIGN };

/* Keys given in the current section (duplicates are errors). */
#define MAX_KEYS 32
typedef struct reader {
    lx_ctx *ctx;
    lx_scene *sc;
    int sec;
    char seen[MAX_KEYS][32];
    int nseen;
    int sky_seen, output_seen, effects_seen, scene_seen, sun_seen;
    scene__sun_raw sun; /* the [sun] keys, checked when the scene ends */
    struct { dev_t dev; ino_t ino; int known; } stack[MAX_DEPTH]; /* files being read (include cycles) */
    const char *names[MAX_DEPTH];
    int depth;
    long include_line; /* the line of the include being followed */
    /* raw values of the current luminaire / receiver, checked when its section ends */
    scene__lum_raw lraw;
    scene__rec_raw rraw;
    scene__room_raw mraw; /* [room], [surface], [obstruction] */
} reader;

static char *xstrdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = lx__alloc(n);
    if (p) memcpy(p, s, n);
    return p;
}

char *lx__scene_resolve(const char *base_file, const char *rel)
{
    if (rel[0] == '/' || !base_file || !strchr(base_file, '/')) return xstrdup(rel);
    const char *slash = strrchr(base_file, '/');
    size_t nd = (size_t)(slash - base_file) + 1, nr = strlen(rel);
    char *p = lx__alloc(nd + nr + 1);
    if (!p) return NULL;
    memcpy(p, base_file, nd);
    memcpy(p + nd, rel, nr + 1);
    return p;
}

static void trim(char **s, char **e)
{
    while (*s < *e && isspace((unsigned char)**s)) (*s)++;
    while (*e > *s && isspace((unsigned char)(*e)[-1])) (*e)--;
}

/* The unit text of a component ("2.8 m" -> "m"), "" when it is a bare number. */
static const char *unit_part(const char *s)
{
    while (isspace((unsigned char)*s)) s++;
    if (*s == '+' || *s == '-') s++;
    while (isdigit((unsigned char)*s) || *s == '.') s++;
    if ((*s == 'e' || *s == 'E') &&
        (isdigit((unsigned char)s[1]) || ((s[1] == '+' || s[1] == '-') && isdigit((unsigned char)s[2])))) {
        s += 2;
        while (isdigit((unsigned char)*s)) s++;
    }
    while (isspace((unsigned char)*s)) s++;
    return s;
}

lx_status lx__scene_parse_vec(lx_ctx *ctx, const char *file, long line, const char *key, const char *value,
                              int nmin, int nmax, lx_quantity q, const char *bare_unit, double *out, int *count)
{
    char buf[LX__SCENE_MAX_VALUE + 1];
    if (strlen(value) >= sizeof buf)
        return lx__error(ctx, LX_EPARSE, file, line, "%s: value too long (more than %d bytes)", key, LX__SCENE_MAX_VALUE);
    strcpy(buf, value);
    char *comp[8];
    int n = 0;
    for (char *p = buf;;) {
        char *c = strchr(p, ',');
        if (n == 8) return lx__error(ctx, LX_EPARSE, file, line, "%s: too many values", key);
        comp[n++] = p;
        if (!c) break;
        *c = '\0';
        p = c + 1;
    }
    if (n < nmin || n > nmax) {
        if (nmin == nmax)
            return lx__error(ctx, LX_EPARSE, file, line, "%s: expected %d value%s, got %d", key, nmin,
                             nmin == 1 ? "" : "s separated by commas", n);
        return lx__error(ctx, LX_EPARSE, file, line, "%s: expected %d to %d values, got %d", key, nmin, nmax, n);
    }
    const char *shared_unit = unit_part(comp[n - 1]); /* "1.5, 1.2, 2.8 m": the last unit applies to all */
    for (int i = 0; i < n; i++) {
        char *s = comp[i], *e = s + strlen(s);
        trim(&s, &e);
        *e = '\0';
        if (!*s) return lx__error(ctx, LX_EPARSE, file, line, "%s: empty value", key);
        double v;
        lx_quantity got = LX_Q_NONE;
        lx_status st = lx_quantity_parse(ctx, s, LX_Q_NONE, NULL, &v, &got);
        if (st != LX_OK) return lx__error(ctx, LX_EPARSE, file, line, "%s: %s", key, lx_ctx_errmsg(ctx));
        if (q == LX_Q_NONE) {
            if (got != LX_Q_NONE)
                return lx__error(ctx, LX_EPARSE, file, line, "%s: '%s' must be a plain number (no unit)", key, s);
        } else if (got == LX_Q_NONE) {
            char tmp[600];
            const char *u = *shared_unit ? shared_unit : bare_unit;
            if (!u)
                return lx__error(ctx, LX_EPARSE, file, line, "%s: bare number '%s': give a unit of %s (e.g. '%s %s')",
                                 key, s, lx_quantity_name(q), s, lx_quantity_si_unit(q));
            snprintf(tmp, sizeof tmp, "%s %s", s, u);
            st = lx_quantity_parse(ctx, tmp, LX_Q_NONE, NULL, &v, &got);
            if (st != LX_OK) return lx__error(ctx, LX_EPARSE, file, line, "%s: %s", key, lx_ctx_errmsg(ctx));
        }
        if (q != LX_Q_NONE && got != q)
            return lx__error(ctx, LX_EPARSE, file, line, "%s: '%s' is a %s, expected a %s", key, s,
                             lx_quantity_name(got), lx_quantity_name(q));
        if (!isfinite(v)) return lx__error(ctx, LX_EPARSE, file, line, "%s: '%s' is not finite", key, s);
        out[i] = v;
    }
    if (count) *count = n;
    return LX_OK;
}

static lx_status parse_bool(lx_ctx *ctx, const char *file, long line, const char *key, const char *v, int *out)
{
    if (!strcmp(v, "yes") || !strcmp(v, "true") || !strcmp(v, "on")) *out = 1;
    else if (!strcmp(v, "no") || !strcmp(v, "false") || !strcmp(v, "off")) *out = 0;
    else return lx__error(ctx, LX_EPARSE, file, line, "%s: expected yes or no, got '%s'", key, v);
    return LX_OK;
}

/* Ends the current luminaire or receiver section: checks and converts its raw values. */
static lx_status close_section(reader *r)
{
    lx_status st = LX_OK;
    if (r->sec == SEC_LUM) st = lx__scene_lum_finish(r->ctx, r->sc, &r->lraw);
    else if (r->sec == SEC_REC) st = lx__scene_rec_finish(r->ctx, r->sc, &r->rraw);
    else if (r->sec == SEC_ROOM) st = lx__room_section_end(r->ctx, r->sc, &r->mraw);
    r->sec = SEC_NONE;
    r->nseen = 0;
    return st;
}

static lx_status open_section(reader *r, const char *file, long line, char *s, char *e)
{
    lx_status st = close_section(r);
    if (st != LX_OK) return st;
    trim(&s, &e);
    char *sp = s;
    while (sp < e && !isspace((unsigned char)*sp)) sp++;
    char kind[32];
    size_t kn = (size_t)(sp - s);
    if (kn == 0 || kn >= sizeof kind) return lx__error(r->ctx, LX_EPARSE, file, line, "empty or bad section header");
    memcpy(kind, s, kn);
    kind[kn] = '\0';
    char *name = sp, *ne = e;
    trim(&name, &ne);
    *ne = '\0';
    static const char *const known[] = {"scene", "luminaire", "receiver", "sky",         "output", "effects",
                                        "sun",   "observer",  "room",     "surface",     "obstruction", "opening"};
    int k = 0;
    while (k < 12 && strcmp(kind, known[k])) k++;
    int design = lx__design_section_kind(kind);
    if (design) {
        if (design == LX__DSEC_ENERGY && *name)
            return lx__error(r->ctx, LX_EPARSE, file, line, "[energy] takes no name (got '%s')", name);
        if (design != LX__DSEC_ENERGY && !*name)
            return lx__error(r->ctx, LX_EPARSE, file, line, "[%s] needs a name: [%s NAME]", kind, kind);
        r->sec = SEC_DESIGN;
        return lx__design_open(r->ctx, r->sc, design, name, file, line);
    }
    if (k == 12)
        return lx__error(r->ctx, LX_EPARSE, file, line,
                         "unknown section [%s] (sections: scene, luminaire NAME, receiver NAME, sky, sun, observer NAME, "
                         "output, effects, room NAME, surface NAME, obstruction NAME, opening NAME, maintenance NAME, "
                         "area NAME, requirement NAME, energy)",
                         kind);
    int room_kind = k == 8 ? SCENE__ROOM : k == 9 ? SCENE__SURFACE : k == 10 ? SCENE__OBSTRUCTION : 0;
    int named = !strcmp(kind, "luminaire") || !strcmp(kind, "receiver") || !strcmp(kind, "observer") || !strcmp(kind, "opening") ||
                room_kind;
    if (named && !*name)
        return lx__error(r->ctx, LX_EPARSE, file, line, "[%s] needs a name: [%s NAME]", kind, kind);
    if (!named && *name)
        return lx__error(r->ctx, LX_EPARSE, file, line, "[%s] takes no name (got '%s')", kind, name);
    int *once = NULL;
    if (!strcmp(kind, "scene")) r->sec = SEC_SCENE, once = &r->scene_seen;
    else if (!strcmp(kind, "sky")) r->sec = SEC_SKY, once = &r->sky_seen;
    else if (!strcmp(kind, "output")) r->sec = SEC_OUTPUT, once = &r->output_seen;
    else if (!strcmp(kind, "effects")) r->sec = SEC_EFFECTS, once = &r->effects_seen;
    else if (!strcmp(kind, "luminaire")) r->sec = SEC_LUM;
    else if (!strcmp(kind, "receiver")) r->sec = SEC_REC;
    else if (!strcmp(kind, "sun")) r->sec = SEC_SUN, once = &r->sun_seen;
    else if (!strcmp(kind, "observer")) r->sec = SEC_OBS;
    else if (!strcmp(kind, "opening")) r->sec = SEC_OPEN;
    else if (room_kind) r->sec = SEC_ROOM;
    else
        return lx__error(r->ctx, LX_EPARSE, file, line,
                         "unknown section [%s] (sections: scene, luminaire NAME, receiver NAME, sky, output, effects)",
                         kind);
    if (once) {
        if (*once) return lx__error(r->ctx, LX_EPARSE, file, line, "section [%s] given twice", kind);
        *once = 1;
    }
    if (named) {
        if (strchr(name, ',') || strchr(name, '"'))
            return lx__error(r->ctx, LX_EPARSE, file, line, "name '%s': no commas or quotes", name);
        for (size_t i = 0; i < r->sc->n_lum; i++)
            if (r->sec == SEC_LUM && !strcmp(r->sc->lum[i].name, name))
                return lx__error(r->ctx, LX_EPARSE, file, line, "luminaire '%s' defined twice", name);
        for (size_t i = 0; i < r->sc->n_rec; i++)
            if (r->sec == SEC_REC && !strcmp(r->sc->rec[i].name, name))
                return lx__error(r->ctx, LX_EPARSE, file, line, "receiver '%s' defined twice", name);
        /* rooms, surfaces and obstructions share one name space (their faces are named after them) */
        const lx_scene *sc = r->sc;
        int dup = 0;
        for (size_t i = 0; r->sec == SEC_ROOM && i < sc->n_room; i++) dup |= !strcmp(sc->room[i].name, name);
        for (size_t i = 0; r->sec == SEC_ROOM && i < sc->n_surf; i++) dup |= !strcmp(sc->surf[i].name, name);
        for (size_t i = 0; r->sec == SEC_ROOM && i < sc->n_obst; i++) dup |= !strcmp(sc->obst[i].name, name);
        if (dup)
            return lx__error(r->ctx, LX_EPARSE, file, line,
                             "'%s' is already the name of a room, surface or obstruction", name);
        if (room_kind && (strchr(name, '.') || strlen(name) > 100))
            return lx__error(r->ctx, LX_EPARSE, file, line, "name '%s': no dots, at most 100 characters", name);
    }
    if (room_kind) return lx__room_section(r->ctx, &r->mraw, room_kind, name, file, line);
    if (r->sec == SEC_LUM) lx__scene_lum_raw_init(&r->lraw, name, file, line);
    if (r->sec == SEC_REC) lx__scene_rec_raw_init(&r->rraw, name, file, line);
    if ((r->sec == SEC_LUM && !r->lraw.name) || (r->sec == SEC_REC && !r->rraw.name))
        return lx__error(r->ctx, LX_ENOMEM, file, line, "out of memory");
    if (r->sec == SEC_SKY) r->sc->sky_line = line, r->sc->sky_file_at = file;
    if (r->sec == SEC_SUN) r->sc->sun_line = line, r->sc->sun_file_at = file, r->sc->has_sun = 1;
    if (r->sec == SEC_OBS) return lx__scene_obs_open(r->ctx, r->sc, name, file, line);
    if (r->sec == SEC_OPEN) return lx__scene_open_section(r->ctx, r->sc, name, file, line);
    return LX_OK;
}

static lx_status read_file(reader *r, const char *path, const char *text, size_t len);

static lx_status do_include(reader *r, const char *file, long line, const char *value)
{
    if (!*value) return lx__error(r->ctx, LX_EPARSE, file, line, "include: no file named");
    char *path = lx__scene_resolve(file, value);
    if (!path) return lx__error(r->ctx, LX_ENOMEM, file, line, "out of memory");
    char *text = NULL;
    size_t len = 0;
    lx_status st = lx__read_all(r->ctx, path, LX_INPUT_SCENE, &text, &len);
    if (st != LX_OK) { /* lx__read_all's reason, at the include line */
        char why[LX__ERRMSG_MAX];
        const char *m = lx_ctx_errmsg(r->ctx);
        size_t pl = strlen(path);
        long at = lx_ctx_errline(r->ctx);
        if (!strncmp(m, path, pl) && m[pl] == ':') { /* the path is said once, its line after the reason */
            const char *q = m + pl;
            if (at > 0) q += strspn(q + 1, "0123456789") + 1; /* "PATH:LINE: why" */
            if (q[0] == ':' && q[1] == ' ') m = q + 2;
        }
        if (at > 0) snprintf(why, sizeof why, "%s (its line %ld)", m, at);
        else snprintf(why, sizeof why, "%s", m);
        lx__error(r->ctx, st, file, line, "include: cannot read '%s': %s", path, why);
        lx__free(path);
        return st;
    }
    if (r->depth >= MAX_DEPTH) st = lx__error(r->ctx, LX_EPARSE, file, line, "include: nested too deep");
    else r->include_line = line, st = read_file(r, path, text, len);
    lx__free(text);
    lx__free(path);
    return st;
}

static lx_status key_value(reader *r, const char *file, long line, const char *key, const char *value)
{
    lx_ctx *ctx = r->ctx;
    if (!strcmp(key, "include")) return do_include(r, file, line, value);
    if (r->sec == SEC_NONE)
        return lx__error(ctx, LX_EPARSE, file, line, "'%s' outside a section (start one with [scene], ...)", key);
    for (int i = 0; i < r->nseen; i++)
        if (!strcmp(r->seen[i], key)) return lx__error(ctx, LX_EPARSE, file, line, "'%s' given twice in this section", key);
    if (r->nseen < MAX_KEYS && strlen(key) < sizeof r->seen[0]) strcpy(r->seen[r->nseen++], key);
    lx_scene *sc = r->sc;
    switch (r->sec) {
    case SEC_SCENE:
        if (!strcmp(key, "title")) {
            lx__free(sc->title);
            sc->title = xstrdup(value);
            return sc->title ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
        }
        if (!strcmp(key, "near_field_tolerance")) {
            lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_NONE, NULL,
                                               &sc->nearfield_tol, NULL);
            if (st == LX_OK && !(sc->nearfield_tol >= 1e-9 && sc->nearfield_tol <= 0.1))
                return lx__error(ctx, LX_EPARSE, file, line, "%s: must be from 1e-9 to 0.1", key);
            return st;
        }
        {
            lx_status st = LX_OK;
            if (lx__room_scene_key(ctx, sc, file, line, key, value, &st)) return st;
            if (lx__design_scene_key(ctx, sc, file, line, key, value, &st)) return st;
        }
        return lx__error(ctx, LX_EPARSE, file, line,
                         "unknown key '%s' in [scene] (keys: title, near_field_tolerance, interreflection_tolerance, "
                         "patch_size, patch_refinement, maintenance_factor, maintenance)",
                         key);
    case SEC_LUM: return lx__scene_lum_key(ctx, &r->lraw, file, line, key, value);
    case SEC_REC: return lx__scene_rec_key(ctx, &r->rraw, file, line, key, value);
    case SEC_SKY: return lx__scene_sky_key(ctx, sc, file, line, key, value);
    case SEC_SUN: return lx__scene_sun_key(ctx, sc, &r->sun, file, line, key, value);
    case SEC_OBS: return lx__scene_obs_key(ctx, sc, file, line, key, value);
    case SEC_ROOM: return lx__room_key(ctx, &r->mraw, file, line, key, value);
    case SEC_OPEN: return lx__scene_open_key(ctx, sc, file, line, key, value);
    case SEC_DESIGN: return lx__design_key(ctx, sc, file, line, key, value);
    case SEC_OUTPUT: {
        int b = 0;
        if (!strcmp(key, "illuminance")) {
            lx_status st = parse_bool(ctx, file, line, key, value, &b);
            if (st == LX_OK && !b)
                return lx__error(ctx, LX_EPARSE, file, line, "illuminance is always computed (it cannot be 'no')");
            return st;
        }
        int *dst = !strcmp(key, "luminance") ? &sc->want_luminance
                   : !strcmp(key, "cct") ? &sc->want_cct
                   : !strcmp(key, "melanopic_edi") ? &sc->want_melanopic : NULL;
        if (!dst)
            return lx__error(ctx, LX_EPARSE, file, line,
                             "unknown key '%s' in [output] (keys: illuminance, luminance, cct, melanopic_edi)", key);
        lx_status st = parse_bool(ctx, file, line, key, value, dst);
        if (st == LX_OK && dst != &sc->want_luminance) sc->spectral_line = sc->spectral_line ? sc->spectral_line : line;
        return st;
    }
    case SEC_EFFECTS:
        for (int e = 0; e < LX_EFFECT_COUNT; e++)
            if (!strcmp(key, lx_effect_name((lx_effect)e))) {
                if (!strcmp(value, "on")) sc->force[e] = LX_FORCE_ON;
                else if (!strcmp(value, "off")) sc->force[e] = LX_FORCE_OFF;
                else if (!strcmp(value, "auto")) sc->force[e] = LX_FORCE_AUTO;
                else return lx__error(ctx, LX_EPARSE, file, line, "%s: expected on, off or auto, got '%s'", key, value);
                if (e == LX_EFFECT_INVERSE_SQUARE && sc->force[e] == LX_FORCE_OFF)
                    return lx__error(ctx, LX_EPARSE, file, line,
                                     "inverse_square cannot be turned off (it is the point-source law itself)");
                sc->force_line[e] = line;
                return LX_OK;
            }
        return lx__error(ctx, LX_EPARSE, file, line,
                         "unknown effect '%s' (effects: inverse_square, cosine, spot_falloff, goniometric, "
                         "near_field, spectral, environment, opencl, occlusion, interreflection, daylight)", key);
    }
    return lx__error(ctx, LX_EPARSE, file, line, "unknown key '%s'", key);
}

static lx_status read_file(reader *r, const char *path, const char *text, size_t len)
{
    lx_ctx *ctx = r->ctx;
    struct stat sb;
    int known = strcmp(path, "-") && stat(path, &sb) == 0;
    for (int i = 0; i < r->depth; i++)
        if (known && r->stack[i].known && r->stack[i].dev == sb.st_dev && r->stack[i].ino == sb.st_ino)
            return lx__error(ctx, LX_EPARSE, r->names[r->depth - 1], r->include_line,
                             "include cycle: '%s' is already being read (included from %s)", path, r->names[i]);
    /* the file name as given is kept in the scene (messages of later checks name it) */
    char *keep = lx__scene_keep_name(r->sc, path);
    if (!keep) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
    r->stack[r->depth].known = known;
    if (known) r->stack[r->depth].dev = sb.st_dev, r->stack[r->depth].ino = sb.st_ino;
    r->names[r->depth++] = keep;
    lx_status st = LX_OK;
    lx__lines it = {text, text + len, 0};
    const char *s, *e;
    if (len >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3)) it.p += 3;
    while (st == LX_OK && lx__next_line(&it, &s, &e)) {
        long line = it.line;
        char buf[LX__SCENE_MAX_LINE + 1];
        const char *hash = memchr(s, '#', (size_t)(e - s));
        if (hash) e = hash;
        if ((size_t)(e - s) >= sizeof buf) {
            st = lx__error(ctx, LX_EPARSE, keep, line, "line too long (more than %d bytes before any comment)", LX__SCENE_MAX_LINE);
            break;
        }
        memcpy(buf, s, (size_t)(e - s));
        buf[e - s] = '\0';
        char *b = buf, *be = buf + (e - s);
        trim(&b, &be);
        *be = '\0';
        if (!*b) continue;
        if (*b == '[') {
            if (be[-1] != ']') {
                st = lx__error(ctx, LX_EPARSE, keep, line, "section header without ']'");
                break;
            }
            be[-1] = '\0';
            st = open_section(r, keep, line, b + 1, be - 1);
            continue;
        }
        char *eq = strchr(b, '=');
        if (!eq) {
            st = lx__error(ctx, LX_EPARSE, keep, line, "expected 'key = value' or '[section]', got '%s'", b);
            break;
        }
        char *ks = b, *ke = eq, *vs = eq + 1, *ve = be;
        trim(&ks, &ke);
        trim(&vs, &ve);
        *ke = '\0';
        *ve = '\0';
        if (!*ks) {
            st = lx__error(ctx, LX_EPARSE, keep, line, "missing key before '='");
            break;
        }
        st = key_value(r, keep, line, ks, vs);
    }
    r->depth--;
    return st;
}


lx_status lx_scene_read_mem(lx_ctx *ctx, const char *name, const char *text, size_t len, lx_scene **out)
{
    LX__NEED_CTX(ctx);
    if (!name || (!text && len) || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_read_mem: NULL argument");
    *out = NULL;
    reader r;
    memset(&r, 0, sizeof r);
    r.ctx = ctx;
    r.sc = lx__scene_new(name);
    if (!r.sc) return lx__error(ctx, LX_ENOMEM, name, 0, "out of memory");
    lx__scene_sun_raw_init(&r.sun);
    lx_status st = read_file(&r, name, text ? text : "", len);
    if (st == LX_OK) st = close_section(&r);
    else {
        lx__scene_lum_raw_free(&r.lraw);
        lx__scene_rec_raw_free(&r.rraw);
    }
    lx__room_raw_free(&r.mraw);
    if (st == LX_OK) st = lx__scene_daylight_finish(ctx, r.sc, &r.sun);
    if (st == LX_OK) st = lx__scene_obs_finish(ctx, r.sc);
    if (st == LX_OK) st = lx__design_finish(ctx, r.sc);
    if (st == LX_OK) st = lx__scene_finish(ctx, r.sc);
    if (st != LX_OK) {
        lx_scene_free(r.sc);
        return st;
    }
    *out = r.sc;
    return LX_OK;
}

lx_status lx_scene_read_file(lx_ctx *ctx, const char *path, lx_scene **out)
{
    LX__NEED_CTX(ctx);
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_read_file: NULL argument");
    *out = NULL;
    char *text = NULL;
    size_t len = 0;
    lx_status st = lx__read_all(ctx, path, LX_INPUT_SCENE, &text, &len); /* its errors name the file */
    if (st != LX_OK) return st;
    st = lx_scene_read_mem(ctx, path, text, len, out);
    lx__free(text);
    return st;
}
