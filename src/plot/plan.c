/* plan.c - outlines drawn over a plan or a section in the conventions of lighting-design drawings:
 * rooms' walls, obstructions (desks), partitions, openings (windows, doors, roof lights) and
 * luminous areas, from a list of 2-D outlines in the plane's coordinates. Every plot or page that
 * shows a plan draws it here. */
#include "plot/plot_private.h"

#include <math.h>

/* the style of each kind: line colour and width (pixels at unit 1), a fill */
static const unsigned char WALL[3] = {55, 55, 62}, OBST[3] = {40, 40, 40}, SURF[3] = {122, 74, 30},
                           OPEN_EDGE[3] = {20, 70, 140}, OPEN_FILL[3] = {150, 215, 250}, LUM[3] = {20, 20, 20},
                           WHITE[3] = {255, 255, 255};

const unsigned char *lx__outline_rgb(lx_outline_kind kind)
{
    switch (kind) {
    case LX_OUTLINE_WALL: return WALL;
    case LX_OUTLINE_OBSTRUCTION: return OBST;
    case LX_OUTLINE_SURFACE: return SURF;
    case LX_OUTLINE_OPENING: return OPEN_FILL;
    case LX_OUTLINE_LUMINAIRE: return LUM;
    }
    return NULL;
}

int lx__outlines_extent(const lx_plot_outline *o, size_t n, double ext[4])
{
    int any = 0;
    ext[0] = ext[2] = INFINITY, ext[1] = ext[3] = -INFINITY;
    for (size_t k = 0; k < n; k++)
        for (size_t i = 0; o[k].ab_m && i < o[k].n; i++) {
            double a = o[k].ab_m[2 * i], b = o[k].ab_m[2 * i + 1];
            if (!isfinite(a) || !isfinite(b)) continue;
            ext[0] = fmin(ext[0], a), ext[1] = fmax(ext[1], a), ext[2] = fmin(ext[2], b), ext[3] = fmax(ext[3], b);
            any = 1;
        }
    return any;
}

static double vx(const lx__plan_view *v, double a) { return v->box.x0 + (a - v->a0) / (v->a1 - v->a0) * (v->box.x1 - v->box.x0); }
static double vy(const lx__plan_view *v, double b) { return v->box.y1 - (b - v->b0) / (v->b1 - v->b0) * (v->box.y1 - v->box.y0); }

/* the outline as a cairo path (pixels); 0 when it has no finite vertex */
static int path(cairo_t *cr, const lx__plan_view *v, const lx_plot_outline *o)
{
    int started = 0;
    cairo_new_path(cr);
    for (size_t i = 0; i < o->n; i++) {
        double a = o->ab_m[2 * i], b = o->ab_m[2 * i + 1];
        if (!isfinite(a) || !isfinite(b)) continue;
        if (started) cairo_line_to(cr, vx(v, a), vy(v, b));
        else cairo_move_to(cr, vx(v, a), vy(v, b)), started = 1;
    }
    if (started && o->closed && o->n > 2) cairo_close_path(cr);
    return started;
}

/* one pass: the outlines of one kind */
static void draw_kind(cairo_t *cr, const lx__plan_view *v, const lx_plot_outline *o, size_t n, lx_outline_kind kind,
                      size_t *count)
{
    const double u = v->unit > 0 ? v->unit : 1;
    for (size_t k = 0; k < n; k++) {
        if (o[k].kind != kind || !o[k].ab_m || o[k].n < 1) continue;
        if (o[k].n == 1) { /* a point: a dot */
            double a = o[k].ab_m[0], b = o[k].ab_m[1];
            if (!isfinite(a) || !isfinite(b)) continue;
            lx__rgb(cr, lx__outline_rgb(kind), 1);
            cairo_arc(cr, vx(v, a), vy(v, b), 2.5 * u, 0, 2 * LX__PI);
            cairo_fill(cr);
            if (count) count[kind]++;
            continue;
        }
        if (!path(cr, v, &o[k])) continue;
        switch (kind) {
        case LX_OUTLINE_WALL: /* a room's boundary: a heavy line */
            lx__rgb(cr, WALL, 1);
            cairo_set_line_width(cr, 4 * u);
            cairo_stroke(cr);
            break;
        case LX_OUTLINE_OBSTRUCTION: /* furniture: a veil over what lies under it, a fine outline */
            if (o[k].closed && o[k].n > 2) {
                lx__rgb(cr, WHITE, 0.45);
                cairo_fill_preserve(cr);
            }
            lx__rgb(cr, OBST, 1);
            cairo_set_line_width(cr, 1.5 * u);
            cairo_stroke(cr);
            break;
        case LX_OUTLINE_SURFACE: /* a partition: a medium line in another colour */
            lx__rgb(cr, SURF, 1);
            cairo_set_line_width(cr, 3.5 * u);
            cairo_stroke(cr);
            break;
        case LX_OUTLINE_OPENING: /* a window: a light band edged in dark blue, over the wall */
            lx__rgb(cr, OPEN_EDGE, 1);
            cairo_set_line_width(cr, 8 * u);
            cairo_stroke_preserve(cr);
            lx__rgb(cr, OPEN_FILL, 1);
            cairo_set_line_width(cr, 5 * u);
            cairo_stroke(cr);
            break;
        case LX_OUTLINE_LUMINAIRE: { /* a luminous area: a fine dashed line */
            const double dash[2] = {4 * u, 3 * u};
            lx__rgb(cr, LUM, 1);
            cairo_set_line_width(cr, 1.2 * u);
            cairo_set_dash(cr, dash, 2, 0);
            cairo_stroke(cr);
            cairo_set_dash(cr, NULL, 0, 0);
            break;
        }
        }
        if (count) count[kind]++;
    }
}

void lx__plan_draw(cairo_t *cr, const lx__plan_view *v, const lx_plot_outline *o, size_t n, size_t *count)
{
    if (!o || !n || !(v->a1 > v->a0) || !(v->b1 > v->b0)) return;
    cairo_save(cr);
    cairo_rectangle(cr, v->box.x0, v->box.y0, v->box.x1 - v->box.x0, v->box.y1 - v->box.y0);
    cairo_clip(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    /* under to over: furniture, luminous areas, partitions, walls, the openings in the walls */
    static const lx_outline_kind order[] = {LX_OUTLINE_OBSTRUCTION, LX_OUTLINE_LUMINAIRE, LX_OUTLINE_SURFACE,
                                            LX_OUTLINE_WALL, LX_OUTLINE_OPENING};
    for (size_t i = 0; i < sizeof order / sizeof *order; i++) draw_kind(cr, v, o, n, order[i], count);
    cairo_restore(cr);
}
