/* report_pdf_plan.c - the plan of each room in the design report, drawn as vectors: the walls and
 * openings, obstructions and surfaces, the EN 12464-1 and EN 1838 areas (task areas and their bands
 * clipped at the walls, escape routes, open areas), the calculation grids, the luminaires with their
 * names and the observers with their lines of sight; axes in metres and a legend. */
#include "plot/report_pdf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct view {
    double x0, y0, s;   /* page point of world (x0, y0) is at (px0, py0); s points per metre */
    double px0, py0;
} view;

static double PX(const view *v, double x) { return v->px0 + (x - v->x0) * v->s; }
static double PY(const view *v, double y) { return v->py0 - (y - v->y0) * v->s; }

static void rgb(cairo_t *cr, int r, int g, int b) { cairo_set_source_rgb(cr, r / 255.0, g / 255.0, b / 255.0); }

/* a label near (x, y) where it overlaps nothing drawn: right, left, above, below, farther out */
static void label_near(lx__page *pg, double x, double y, double size, const unsigned char c[3], const char *s, lx__box within)
{
    lx__font f = {size, 0, {c[0], c[1], c[2]}, 1};
    static const double off[][4] = {{6, 0, 0, 0.5}, {-6, 0, 1, 0.5}, {0, -6, 0.5, 1}, {0, 6, 0.5, 0},
                                    {10, -8, 0, 1}, {-10, -8, 1, 1}, {10, 8, 0, 0}, {-10, 8, 1, 0},
                                    {18, 0, 0, 0.5}, {-18, 0, 1, 0.5}, {0, -14, 0.5, 1}, {0, 14, 0.5, 0}};
    for (size_t k = 0; k < sizeof off / sizeof off[0]; k++) {
        lx__box b = lx__text_box(pg, &f, x + off[k][0], y + off[k][1], off[k][2], off[k][3], s);
        if (lx__page_free_at(pg, b, 1, within)) {
            lx__page_text(pg, &f, x + off[k][0], y + off[k][1], off[k][2], off[k][3], LX__TEXT_LABEL, NAN, s);
            return;
        }
    }
}

/* an area's outline (and inner edge) in the plan, horizontal areas only */
static void area_path(cairo_t *cr, const view *v, const lx_scene_area *A, const double *poly, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        double a = poly[2 * k], b = poly[2 * k + 1];
        double x = A->origin_m[0] + a * A->u[0] + b * A->v[0], y = A->origin_m[1] + a * A->u[1] + b * A->v[1];
        if (k == 0) cairo_move_to(cr, PX(v, x), PY(v, y));
        else cairo_line_to(cr, PX(v, x), PY(v, y));
    }
    if (n) cairo_close_path(cr);
}

static void areas(lx__page *pg, const lx_scene *sc, long room, const view *v)
{
    cairo_t *cr = pg->cr;
    const lx_scene_design *d = sc->design;
    for (size_t i = 0; d && i < d->n_area; i++) {
        const lx_scene_area *A = &d->area[i];
        if (A->room != room || A->kind == LX_AREA_WALL || A->kind == LX_AREA_CEILING) continue;
        static const double dash[2] = {4, 2.5}, dot[2] = {1, 2.5};
        cairo_save(cr);
        cairo_set_line_width(cr, A->kind == LX_AREA_TASK || A->kind == LX_AREA_HIGH_RISK ? 1.4 : 0.9);
        switch (A->kind) {
        case LX_AREA_TASK: rgb(cr, 0, 140, 60); break;
        case LX_AREA_SURROUNDING: rgb(cr, 0, 140, 60), cairo_set_dash(cr, dash, 2, 0); break;
        case LX_AREA_BACKGROUND: rgb(cr, 0, 140, 60), cairo_set_dash(cr, dot, 2, 0); break;
        case LX_AREA_ROOM: rgb(cr, 40, 90, 200), cairo_set_dash(cr, dash, 2, 0); break;
        case LX_AREA_ESCAPE_ROUTE: rgb(cr, 200, 30, 30); break;
        case LX_AREA_ROUTE_BAND: rgb(cr, 200, 30, 30), cairo_set_dash(cr, dot, 2, 0); break;
        case LX_AREA_OPEN: rgb(cr, 220, 120, 0), cairo_set_dash(cr, dash, 2, 0); break;
        default: rgb(cr, 130, 40, 160); break;
        }
        area_path(cr, v, A, A->outline, A->n_outline);
        cairo_stroke(cr);
        if (A->n_inner) {
            area_path(cr, v, A, A->inner, A->n_inner);
            cairo_stroke(cr);
        }
        if (A->kind == LX_AREA_ESCAPE_ROUTE) { /* the centre line with an arrow at its end */
            double L = A->box_m[1], x0 = A->origin_m[0], y0 = A->origin_m[1];
            double x1 = x0 + L * A->u[0], y1 = y0 + L * A->u[1];
            cairo_set_line_width(cr, 1.2);
            cairo_move_to(cr, PX(v, x0), PY(v, y0));
            cairo_line_to(cr, PX(v, x1), PY(v, y1));
            double ux = A->u[0], uy = -A->u[1];
            cairo_move_to(cr, PX(v, x1), PY(v, y1));
            cairo_rel_line_to(cr, -7 * ux - 4 * uy, -7 * uy + 4 * ux);
            cairo_move_to(cr, PX(v, x1), PY(v, y1));
            cairo_rel_line_to(cr, -7 * ux + 4 * uy, -7 * uy - 4 * ux);
            cairo_stroke(cr);
        }
        cairo_restore(cr);
    }
}

/* the room's walls, openings, obstructions, surfaces and luminous areas: the plan drawer's outlines
 * of the scene on a horizontal plane through the room (plan.c: every plan is drawn there) */
static lx_status building(lx_ctx *ctx, lx__page *pg, const lx_scene *sc, long room, const view *v, lx__box box)
{
    const lx_scene_room *R = &sc->room[room];
    lx_plane p;
    memset(&p, 0, sizeof p);
    p.origin_m[2] = 0.5 * (R->min_m[2] + R->max_m[2]);
    p.u[0] = 1, p.v[1] = 1, p.normal[2] = 1;
    p.a0 = R->min_m[0], p.a1 = R->max_m[0], p.b0 = R->min_m[1], p.b1 = R->max_m[1], p.na = p.nb = 2;
    lx_plot_outline *o = NULL;
    size_t n = 0;
    lx_status st = lx_scene_outlines(ctx, sc, &p, &o, &n);
    if (st != LX_OK) return st;
    lx__plan_view pv = {box, 0, 0, 0, 0, 0.7};
    pv.a0 = v->x0 + (box.x0 - v->px0) / v->s, pv.a1 = v->x0 + (box.x1 - v->px0) / v->s;
    pv.b0 = v->y0 + (v->py0 - box.y1) / v->s, pv.b1 = v->y0 + (v->py0 - box.y0) / v->s;
    lx__plan_draw(pg->cr, &pv, o, n, NULL);
    lx_scene_outlines_free(o);
    for (size_t i = 0; i < sc->n_obst; i++) { /* labels must not cover an obstruction */
        const lx_scene_obstruction *b = &sc->obst[i];
        lx__page_keep(pg, (lx__box){PX(v, b->min_m[0]), PY(v, b->max_m[1]), PX(v, b->max_m[0]), PY(v, b->min_m[1])});
    }
    return LX_OK;
}

/* luminaires and observers, and their names */
static void people_and_lights(lx__page *pg, const lx_scene *sc, long room, const view *v, lx__box within)
{
    cairo_t *cr = pg->cr;
    const lx_scene_room *R = &sc->room[room];
    const lx_scene_design *d = sc->design;
    static const unsigned char ink[3] = {25, 25, 25}, em[3] = {0, 120, 50}, obs[3] = {40, 90, 200};
    for (size_t l = 0; l < sc->n_lum; l++) {
        const double *p = sc->lum[l].pos_m;
        if (!(p[0] >= R->min_m[0] && p[0] <= R->max_m[0] && p[1] >= R->min_m[1] && p[1] <= R->max_m[1])) continue;
        double x = PX(v, p[0]), y = PY(v, p[1]);
        int e = d && d->lum_mode[l] != LX_LUM_NORMAL;
        cairo_new_path(cr);
        cairo_arc(cr, x, y, 4.5, 0, 2 * LX__PI);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_fill_preserve(cr);
        lx__rgb(cr, e ? em : ink, 1);
        cairo_set_line_width(cr, 1.1);
        cairo_stroke(cr);
        cairo_move_to(cr, x - 4.5, y), cairo_line_to(cr, x + 4.5, y);
        cairo_move_to(cr, x, y - 4.5), cairo_line_to(cr, x, y + 4.5);
        cairo_stroke(cr);
        lx__page_keep(pg, (lx__box){x - 5, y - 5, x + 5, y + 5});
    }
    for (size_t o = 0; o < sc->n_obs; o++) {
        const lx_scene_observer *ob = &sc->obs[o];
        const double *p = ob->pos_m;
        if (!(p[0] >= R->min_m[0] && p[0] <= R->max_m[0] && p[1] >= R->min_m[1] && p[1] <= R->max_m[1])) continue;
        double x = PX(v, p[0]), y = PY(v, p[1]), h = hypot(ob->view[0], ob->view[1]);
        lx__rgb(cr, obs, 1);
        cairo_new_path(cr);
        cairo_arc(cr, x, y, 2, 0, 2 * LX__PI);
        cairo_fill(cr);
        if (h > 0) {
            cairo_move_to(cr, x, y);
            cairo_line_to(cr, x + 10 * ob->view[0] / h, y - 10 * ob->view[1] / h);
            cairo_set_line_width(cr, 0.9);
            cairo_stroke(cr);
        }
        lx__page_keep(pg, (lx__box){x - 3, y - 3, x + 3, y + 3});
    }
    for (size_t l = 0; l < sc->n_lum; l++) {
        const double *p = sc->lum[l].pos_m;
        if (!(p[0] >= R->min_m[0] && p[0] <= R->max_m[0] && p[1] >= R->min_m[1] && p[1] <= R->max_m[1])) continue;
        label_near(pg, PX(v, p[0]), PY(v, p[1]), 7, d && d->lum_mode[l] != LX_LUM_NORMAL ? em : ink, sc->lum[l].name, within);
    }
}

/* metre ticks along the bottom and left of the room */
static void axes(lx__page *pg, const lx_scene_room *R, const view *v)
{
    cairo_t *cr = pg->cr;
    lx__font f = {7, 0, {90, 90, 90}, 0};
    double span = fmax(R->max_m[0] - R->min_m[0], R->max_m[1] - R->min_m[1]), step = lx__nice_step(span, 6);
    rgb(cr, 90, 90, 90);
    cairo_set_line_width(cr, 0.5);
    for (double x = ceil(R->min_m[0] / step - 1e-9) * step; x <= R->max_m[0] + 1e-9; x += step) {
        double px = PX(v, x), py = PY(v, R->min_m[1]) + 6;
        cairo_move_to(cr, px, py - 3), cairo_line_to(cr, px, py);
        cairo_stroke(cr);
        char t[32];
        lx__fmt_tick(t, sizeof t, x, step);
        lx__page_text(pg, &f, px, py + 1, 0.5, 0, LX__TEXT_TICK, x, t);
    }
    for (double y = ceil(R->min_m[1] / step - 1e-9) * step; y <= R->max_m[1] + 1e-9; y += step) {
        double px = PX(v, R->min_m[0]) - 6, py = PY(v, y);
        cairo_move_to(cr, px, py), cairo_line_to(cr, px + 3, py);
        cairo_stroke(cr);
        char t[32];
        lx__fmt_tick(t, sizeof t, y, step);
        lx__page_text(pg, &f, px - 2, py, 1, 0.5, LX__TEXT_TICK, y, t);
    }
    lx__page_text(pg, &f, PX(v, R->max_m[0]), PY(v, R->min_m[1]) + 18, 1, 0, LX__TEXT_AXIS, NAN, "x (m)");
}

static void legend(lx__doc *d)
{
    lx__doc_note(d, "Plan: walls, openings (light blue), obstructions, surfaces and luminous areas as the plots draw them; "
                    "task areas green (the immediate "
                    "surrounding dashed, the background dotted), room planes blue dashed, escape routes red (the central band "
                    "dotted), open areas orange; luminaires as crossed circles (emergency luminaires green), observers as blue "
                    "dots with their line of sight.");
}

lx_status lx__rep_plans(lx__rep *r)
{
    lx__doc *d = &r->doc;
    const lx_scene *sc = r->sc;
    lx__doc_new_page(d);
    lx__doc_heading(d, 1, "2 Rooms");
    if (!sc->n_room) {
        lx__doc_para(d, "The scene has no rooms: its luminaires and receivers are in the open.");
        return LX_OK;
    }
    for (size_t i = 0; i < sc->n_room; i++) {
        const lx_scene_room *R = &sc->room[i];
        char buf[400];
        snprintf(buf, sizeof buf, "Room %s: %.4g m x %.4g m x %.4g m", R->name, R->max_m[0] - R->min_m[0], R->max_m[1] - R->min_m[1],
                 R->max_m[2] - R->min_m[2]);
        if (i) lx__doc_new_page(d);
        lx__doc_heading(d, 2, buf);
        snprintf(buf, sizeof buf,
                 "Reflectances: ceiling %.2g, floor %.2g, walls %.2g / %.2g / %.2g / %.2g (x min, x max, y min, y max).",
                 R->reflectance[LX_ROOM_CEILING], R->reflectance[LX_ROOM_FLOOR], R->reflectance[LX_ROOM_WALL_XMIN],
                 R->reflectance[LX_ROOM_WALL_XMAX], R->reflectance[LX_ROOM_WALL_YMIN], R->reflectance[LX_ROOM_WALL_YMAX]);
        lx__doc_para(d, buf);
        double w = R->max_m[0] - R->min_m[0], h = R->max_m[1] - R->min_m[1];
        double avail_w = LX__DOC_RIGHT - LX__DOC_LEFT - 50, avail_h = fmin(420, LX__DOC_BOTTOM - d->y - 90);
        if (avail_h < 150) {
            lx__doc_new_page(d);
            avail_h = 420;
        }
        view v;
        v.s = fmin(avail_w / w, avail_h / h);
        v.x0 = R->min_m[0], v.y0 = R->min_m[1];
        v.px0 = LX__DOC_LEFT + 30 + 0.5 * (avail_w - w * v.s);
        v.py0 = d->y + 12 + h * v.s;
        lx__box within = {LX__DOC_LEFT, d->y, LX__DOC_RIGHT, v.py0 + 30};
        lx__box frame = {PX(&v, R->min_m[0]) - 8, PY(&v, R->max_m[1]) - 8, PX(&v, R->max_m[0]) + 8, PY(&v, R->min_m[1]) + 8};
        lx_status st = building(r->ctx, &d->pg, sc, (long)i, &v, frame);
        if (st != LX_OK) return st;
        areas(&d->pg, sc, (long)i, &v);
        people_and_lights(&d->pg, sc, (long)i, &v, within);
        axes(&d->pg, R, &v);
        d->y = v.py0 + 34;
        legend(d);
    }
    return LX_OK;
}
