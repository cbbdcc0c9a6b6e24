/* room_polys.c - a scene's rooms, surfaces, obstructions and openings as the radiosity layer's
 * planar polygons (radiosity_private.h): box rooms (six faces facing in), surfaces (one polygon,
 * both sides reflecting), obstructions (six faces facing out, solid inside), openings (holes in
 * the face they lie on, the outside behind them). */
#include "scene/room_private.h"

#include <stdio.h>
#include <string.h>

/* The face k (lx_room_face order) of the box lo..hi as 4 vertices, counter-clockwise seen from
 * inside (a room, inward = 1) or outside (an obstruction). */
static void box_quad(const double lo[3], const double hi[3], int k, int inward, double v[12])
{
    int axis = k < 2 ? 2 : k < 4 ? 0 : 1, at_hi = k % 2;
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    double sign = (at_hi ? 1 : -1) * (inward ? -1 : 1); /* the normal's direction along axis */
    int first = sign > 0 ? a : b, second = sign > 0 ? b : a;
    for (int c = 0; c < 4; c++) {
        double *p = v + 3 * c;
        p[axis] = at_hi ? hi[axis] : lo[axis];
        int s = c == 1 || c == 2, t = c >= 2;
        p[first] = s ? hi[first] : lo[first];
        p[second] = t ? hi[second] : lo[second];
    }
}

lx_status lx__room_geom(lx_ctx *ctx, const lx_scene *sc, lx__rad_geom *g)
{
    static const char *const room_face[6] = {"floor", "ceiling", "wall_xmin", "wall_xmax", "wall_ymin", "wall_ymax"};
    static const char *const box_face[6] = {"bottom", "top", "xmin", "xmax", "ymin", "ymax"};
    char name[200];
    double v[12];
    lx_status st = LX_OK;
    int tag = 0;
    for (size_t r = 0; r < sc->n_room && st == LX_OK; r++)
        for (int k = 0; k < 6 && st == LX_OK; k++, tag++) {
            const lx_scene_room *R = &sc->room[r];
            box_quad(R->min_m, R->max_m, k, 1, v);
            snprintf(name, sizeof name, "%s.%s", R->name, room_face[k]);
            lx__rad_poly p = {.rho_front = R->reflectance[k], .rho_back = -1, .vol_front = (int)r,
                              .vol_back = LX__RAD_OUTSIDE, .tag = tag, .name = name, .file = R->file, .line = R->line};
            st = lx__rad_geom_add(ctx, g, v, 4, &p, NULL);
        }
    for (size_t i = 0; i < sc->n_surf && st == LX_OK; i++, tag += 2) {
        const lx_scene_surface *S = &sc->surf[i];
        double c[3];
        for (int k = 0; k < 3; k++) {
            v[k] = S->corner_m[k];
            v[3 + k] = v[k] + S->edge1_m[k];
            v[6 + k] = v[3 + k] + S->edge2_m[k];
            v[9 + k] = v[k] + S->edge2_m[k];
            c[k] = 0.5 * (v[k] + v[6 + k]);
        }
        int vol = lx__room_cell(sc, c);
        lx__rad_poly p = {.rho_front = S->reflectance, .rho_back = S->reflectance, .vol_front = vol, .vol_back = vol,
                          .tag = tag, .name = S->name, .file = S->file, .line = S->line};
        st = lx__rad_geom_add(ctx, g, v, 4, &p, NULL);
    }
    for (size_t i = 0; i < sc->n_obst && st == LX_OK; i++) {
        const lx_scene_obstruction *O = &sc->obst[i];
        double c[3];
        for (int k = 0; k < 3; k++) c[k] = 0.5 * (O->min_m[k] + O->max_m[k]);
        int vol = lx__room_cell(sc, c);
        for (int k = 0; k < 6 && st == LX_OK; k++, tag++) {
            box_quad(O->min_m, O->max_m, k, 0, v);
            snprintf(name, sizeof name, "%s.%s", O->name, box_face[k]);
            lx__rad_poly p = {.rho_front = O->reflectance, .rho_back = -1, .vol_front = vol, .vol_back = LX__RAD_SOLID,
                              .tag = tag, .name = name, .file = O->file, .line = O->line};
            st = lx__rad_geom_add(ctx, g, v, 4, &p, NULL);
        }
    }
    for (size_t k = 0; k < sc->n_open && st == LX_OK; k++) {
        const lx_scene_opening *O = &sc->open[k];
        const lx_scene_room *R = &sc->room[O->room];
        /* the opening's rectangle, turned to face into its room like the face it lies on */
        double q[12], fn[3], n[3];
        box_quad(R->min_m, R->max_m, (int)O->face, 1, q);
        for (int c = 0; c < 3; c++) {
            v[c] = O->corner_m[c];
            v[3 + c] = v[c] + O->edge1_m[c];
            v[6 + c] = v[3 + c] + O->edge2_m[c];
            v[9 + c] = v[c] + O->edge2_m[c];
        }
        lx__rad_poly_plane(q, 4, fn, NULL, NULL);
        lx__rad_poly_plane(v, 4, n, NULL, NULL);
        if (fn[0] * n[0] + fn[1] * n[1] + fn[2] * n[2] < 0) {
            double t[3];
            memcpy(t, v + 3, sizeof t);
            memcpy(v + 3, v + 9, sizeof t);
            memcpy(v + 9, t, sizeof t);
        }
        lx__rad_poly p = {.rho_front = 0, .rho_back = -1, .tau = O->transmittance, .glazing = (int)O->glazing,
                          .vol_front = (int)O->room, .vol_back = LX__RAD_OUTSIDE, .tag = -1 - (int)k, .name = O->name,
                          .file = O->file, .line = O->line};
        st = lx__rad_geom_add(ctx, g, v, 4, &p, NULL);
    }
    if (st != LX_OK) lx__rad_geom_free(g);
    return st;
}
