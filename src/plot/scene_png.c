/* scene_png.c - one grid receiver of an evaluated scene as an isolux plot (illuminance or the
 * daylight factor), with the scene's luminaires, rooms, obstructions, surfaces and openings drawn
 * on it; and the plane of a grid receiver. */
#include "plot/plot_private.h"

#include <math.h>
#include <string.h>

lx_status lx_scene_receiver_plane(lx_ctx *ctx, const lx_scene *sc, size_t receiver, lx_plane *out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_receiver_plane: NULL argument");
    if (receiver >= sc->n_rec) return lx__error(ctx, LX_EINVAL, NULL, 0, "receiver %zu: the scene has %zu", receiver, sc->n_rec);
    const lx_scene_receiver *rc = &sc->rec[receiver];
    if (rc->kind != LX_SREC_GRID || !rc->points || rc->na < 1 || rc->nb < 1)
        return lx__error(ctx, LX_EINVAL, rc->file, rc->line, "receiver '%s' is not a grid: it has no plane to plot", rc->name);
    lx_plane p;
    memset(&p, 0, sizeof p);
    int k = rc->axis - 'x', ia = k == 0 ? 1 : 0, ib = k == 2 ? 1 : 2;
    p.u[ia] = 1, p.v[ib] = 1;
    p.origin_m[k] = rc->points[k];
    const double *first = rc->points, *last_a = rc->points + 3 * (rc->na - 1), *last_b = rc->points + 3 * (rc->nb - 1) * rc->na;
    p.a0 = first[ia], p.a1 = last_a[ia], p.b0 = first[ib], p.b1 = last_b[ib];
    p.na = rc->na, p.nb = rc->nb;
    memcpy(p.normal, rc->normal, sizeof p.normal);
    *out = p;
    return LX_OK;
}

lx_status lx__scene_receiver_png(lx_ctx *ctx, const char *path, const lx_scene *sc, const lx_scene_result *res,
                                 size_t receiver, const lx_receiver_png_opts *opts, lx__layout *out)
{
    LX__NEED_CTX(ctx);
    if (!path || !sc || !res) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_receiver_write_png: NULL argument");
    lx_receiver_png_opts o = {0};
    if (opts) o = *opts;
    lx_status st = lx__check_reserved(ctx, "receiver plot options", o.reserved, sizeof o.reserved);
    if (st) return st;
    if (o.quantity != LX_PLOT_ILLUMINANCE && o.quantity != LX_PLOT_DAYLIGHT_FACTOR)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "receiver plot: unknown quantity %d", (int)o.quantity);
    lx_plane p;
    if ((st = lx_scene_receiver_plane(ctx, sc, receiver, &p))) return st;
    if (!res->first || res->first[sc->n_rec] != res->n_points || res->first[receiver + 1] - res->first[receiver] != p.na * p.nb)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "receiver plot: the result is not this scene's");
    const double *v = res->E_lx + res->first[receiver];
    if (o.quantity == LX_PLOT_DAYLIGHT_FACTOR) {
        v = res->daylight_factor ? res->daylight_factor + res->first[receiver] : NULL;
        if (!v || !isfinite(v[0]))
            return lx__error(ctx, LX_EINVAL, sc->rec[receiver].file, sc->rec[receiver].line,
                             "receiver '%s': the daylight factor is not defined for this scene (it needs openings and "
                             "a uniform, overcast or CIE 1-5 sky without the sun)", sc->rec[receiver].name);
    }
    lx_plot_mark *mk = sc->n_lum ? lx__calloc(sc->n_lum, sizeof *mk) : NULL;
    if (sc->n_lum && !mk) return lx__error(ctx, LX_ENOMEM, NULL, 0, "receiver plot: out of memory");
    for (size_t l = 0; l < sc->n_lum; l++) {
        memcpy(mk[l].pos_m, sc->lum[l].pos_m, sizeof mk[l].pos_m);
        memcpy(mk[l].aim, sc->lum[l].aim, sizeof mk[l].aim);
        mk[l].name = sc->lum[l].name;
    }
    lx_plot_outline *ol = NULL;
    size_t nol = 0;
    if (!o.no_outlines && (st = lx_scene_outlines(ctx, sc, &p, &ol, &nol))) {
        lx__free(mk);
        return st;
    }
    lx_isolux_opts io = {.background = o.background, .scale = o.scale, .marks = mk, .n_marks = mk ? sc->n_lum : 0,
                         .source = sc->file, .surface = sc->rec[receiver].name, .caption = sc->title,
                         .imperial = o.imperial, .outlines = ol, .n_outlines = nol, .quantity = o.quantity};
    st = lx__isolux_png(ctx, path, &p, v, &io, out);
    lx_scene_outlines_free(ol);
    lx__free(mk);
    return st;
}

lx_status lx_scene_receiver_write_png(lx_ctx *ctx, const char *path, const lx_scene *scene, const lx_scene_result *res,
                                      size_t receiver, const lx_receiver_png_opts *opts)
{
    return lx__scene_receiver_png(ctx, path, scene, res, receiver, opts, NULL);
}
