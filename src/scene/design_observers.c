/* design_observers.c - UGR observers at several positions and in several directions (CIE 117
 * rates glare per observer position and line of sight): an [observer] section with a grid of eye
 * positions (x, y ranges, z, spacing) and/or a list of horizontal directions of view becomes one
 * observer per position and direction, grouped under the section's name. */
#include "scene/design_private.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MAX_OBSERVERS 100000 /* observers one section may make */

/* the raw keys of observer section i, grown to the sections read */
static lx__obs_raw *raw_at(lx_ctx *ctx, lx_scene *sc, const char *file, long line)
{
    lx__design *in = sc->design->internal;
    size_t i = sc->n_obs - 1;
    if (in->n_obs_raw <= i) {
        lx__obs_raw *n = lx__realloc_n(in->obs_raw, sc->n_obs, sizeof *n);
        if (!n) {
            lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
            return NULL;
        }
        memset(n + in->n_obs_raw, 0, (sc->n_obs - in->n_obs_raw) * sizeof *n);
        in->obs_raw = n;
        in->n_obs_raw = sc->n_obs;
    }
    return &in->obs_raw[i];
}

int lx__design_obs_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value,
                       lx_status *st)
{
    int grid = !strcmp(key, "x") || !strcmp(key, "y") || !strcmp(key, "z");
    if (!grid && strcmp(key, "spacing") && strcmp(key, "directions") && strcmp(key, "direction_step")) return 0;
    lx__obs_raw *r = raw_at(ctx, sc, file, line);
    if (!r) {
        *st = LX_ENOMEM;
        return 1;
    }
    r->line = line;
    if (grid) {
        int *n = key[0] == 'x' ? &r->nx : key[0] == 'y' ? &r->ny : &r->nz;
        double *d = key[0] == 'x' ? r->x : key[0] == 'y' ? r->y : &r->z;
        *st = lx__scene_parse_vec(ctx, file, line, key, value, key[0] == 'z' ? 1 : 2, key[0] == 'z' ? 1 : 2, LX_Q_LENGTH,
                                  NULL, d, n);
        if (*st == LX_OK && key[0] != 'z' && !(d[1] >= d[0]))
            *st = lx__error(ctx, LX_EPARSE, file, line, "%s: the range goes from low to high", key);
    } else if (!strcmp(key, "spacing")) {
        *st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_LENGTH, NULL, &r->spacing, NULL);
        if (*st == LX_OK && !(r->spacing > 0)) *st = lx__error(ctx, LX_EPARSE, file, line, "spacing: must be greater than zero");
    } else if (!strcmp(key, "directions")) {
        *st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 8, LX_Q_ANGLE, NULL, r->dir, &r->n_dir);
    } else {
        double s = 0;
        *st = lx__scene_parse_vec(ctx, file, line, key, value, 1, 1, LX_Q_ANGLE, NULL, &s, NULL);
        if (*st == LX_OK && !(s > 0 && s <= 2 * LX__PI))
            *st = lx__error(ctx, LX_EPARSE, file, line, "direction_step: from above 0 to 360 deg");
        r->step = s;
    }
    return 1;
}

/* Positions of section raw r (a grid, ends included where they fall on it) into *pos (n x 3). */
static lx_status positions(lx_ctx *ctx, const lx_scene_observer *o, const lx__obs_raw *r, double **pos, size_t *n)
{
    if (!r || (!r->nx && !r->ny && !r->nz && !(r->spacing > 0))) {
        *pos = lx__alloc_n(3, sizeof **pos);
        if (!*pos) return lx__error(ctx, LX_ENOMEM, o->file, o->line, "out of memory");
        memcpy(*pos, o->pos_m, 3 * sizeof **pos);
        *n = 1;
        return LX_OK;
    }
    if (!isnan(o->pos_m[0]))
        return lx__error(ctx, LX_EPARSE, o->file, o->line, "observer '%s': give 'position' or a grid of positions (x, y, z, "
                         "spacing), not both", o->name);
    if (r->nx != 2 || r->ny != 2 || r->nz != 1 || !(r->spacing > 0))
        return lx__error(ctx, LX_EPARSE, o->file, o->line,
                         "observer '%s': a grid of eye positions takes x and y ranges, the eye height z and spacing", o->name);
    size_t na = (size_t)floor((r->x[1] - r->x[0]) / r->spacing + 1e-9) + 1, nb = (size_t)floor((r->y[1] - r->y[0]) / r->spacing + 1e-9) + 1;
    if ((double)na * (double)nb > MAX_OBSERVERS)
        return lx__error(ctx, LX_EPARSE, o->file, o->line, "observer '%s': more than %d positions", o->name, MAX_OBSERVERS);
    *pos = lx__alloc_n(lx__size_mul(3, lx__size_mul(na, nb)), sizeof **pos);
    if (!*pos) return lx__error(ctx, LX_ENOMEM, o->file, o->line, "out of memory");
    for (size_t j = 0, k = 0; j < nb; j++)
        for (size_t i = 0; i < na; i++, k++) {
            (*pos)[3 * k] = r->x[0] + (double)i * r->spacing;
            (*pos)[3 * k + 1] = r->y[0] + (double)j * r->spacing;
            (*pos)[3 * k + 2] = r->z;
        }
    *n = na * nb;
    return LX_OK;
}

/* Lines of sight of section raw r: horizontal at the given azimuths (from +x towards +y), or every
 * step; else the section's view. */
static lx_status directions(lx_ctx *ctx, const lx_scene_observer *o, const lx__obs_raw *r, double **dir, size_t *n)
{
    size_t nd = r ? (r->n_dir ? (size_t)r->n_dir : r->step > 0 ? (size_t)floor(2 * LX__PI / r->step + 1e-9) : 0) : 0;
    if (r && r->n_dir && r->step > 0)
        return lx__error(ctx, LX_EPARSE, o->file, o->line, "observer '%s': give 'directions' or 'direction_step', not both",
                         o->name);
    if (nd && !isnan(o->view[0]))
        return lx__error(ctx, LX_EPARSE, o->file, o->line, "observer '%s': give 'view' or directions of view, not both",
                         o->name);
    if (!nd) nd = 1;
    *dir = lx__alloc_n(lx__size_mul(3, nd), sizeof **dir);
    if (!*dir) return lx__error(ctx, LX_ENOMEM, o->file, o->line, "out of memory");
    for (size_t k = 0; k < nd; k++) {
        if (!r || (!r->n_dir && !(r->step > 0))) {
            memcpy(*dir, o->view, 3 * sizeof **dir);
            break;
        }
        double az = r->n_dir ? r->dir[k] : (double)k * r->step;
        (*dir)[3 * k] = cos(az), (*dir)[3 * k + 1] = sin(az), (*dir)[3 * k + 2] = 0;
    }
    *n = nd;
    return LX_OK;
}

lx_status lx__design_obs_expand(lx_ctx *ctx, lx_scene *sc)
{
    lx_scene_design *d = sc->design;
    lx__design *in = d->internal;
    size_t n_sec = sc->n_obs, total = 0;
    lx_scene_observer *out = NULL;
    long *group = NULL;
    d->obs_group_name = lx__calloc(n_sec ? n_sec : 1, sizeof *d->obs_group_name);
    if (!d->obs_group_name) return lx__error(ctx, LX_ENOMEM, sc->file, 0, "out of memory");
    lx_status st = LX_OK;
    for (size_t s = 0; s < n_sec && st == LX_OK; s++) {
        lx_scene_observer *o = &sc->obs[s];
        const lx__obs_raw *r = s < in->n_obs_raw && in->obs_raw[s].line ? &in->obs_raw[s] : NULL;
        double *pos = NULL, *dir = NULL;
        size_t np = 0, nd = 0;
        if ((st = positions(ctx, o, r, &pos, &np)) == LX_OK) st = directions(ctx, o, r, &dir, &nd);
        size_t m = np * nd;
        lx_scene_observer *no = st == LX_OK ? lx__realloc_n(out, total + m, sizeof *no) : NULL;
        long *ng = no ? lx__realloc_n(group, total + m, sizeof *ng) : NULL;
        if (no) out = no;
        if (ng) group = ng;
        if (st == LX_OK && (!no || !ng)) st = lx__error(ctx, LX_ENOMEM, o->file, o->line, "out of memory");
        for (size_t k = 0; st == LX_OK && k < m; k++) {
            lx_scene_observer *x = &out[total + k];
            *x = *o;
            memcpy(x->pos_m, pos + 3 * (k / nd), sizeof x->pos_m);
            memcpy(x->view, dir + 3 * (k % nd), sizeof x->view);
            char name[320];
            if (m == 1) snprintf(name, sizeof name, "%s", o->name);
            else snprintf(name, sizeof name, "%s.%zu", o->name, k + 1);
            x->name = lx__strdup(name);
            group[total + k] = (long)s;
            if (!x->name) st = lx__error(ctx, LX_ENOMEM, o->file, o->line, "out of memory");
        }
        if (st == LX_OK) total += m;
        lx__free(pos);
        lx__free(dir);
        d->obs_group_name[s] = o->name; /* the section's name moves to the group */
        o->name = NULL;
        d->n_obs_group = s + 1;
    }
    if (st != LX_OK) {
        for (size_t k = 0; k < total; k++) lx__free(out[k].name);
        lx__free(out);
        lx__free(group);
        return st;
    }
    lx__free(sc->obs);
    sc->obs = out;
    sc->n_obs = total;
    d->obs_group = group;
    return LX_OK;
}
