/* isolux.c - the isolux plot of an illuminance grid, as DIALux and AGi32 print a calculation
 * surface: false colour (or white) under contour lines at round 1-2-5 levels labelled on their
 * lines, luminaire marks with their aim, axes in metres, a legend and a statistics box. */
#include "plot/plot_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FT_M 0.3048
#define LX_PER_FC (1.0 / (FT_M * FT_M)) /* 1 fc = 1 lm/ft2 = 10.7639 lx */

static const unsigned char INK[3] = {30, 30, 30}, GREY[3] = {110, 110, 110}, WHITE[3] = {255, 255, 255},
                           PANEL[3] = {246, 246, 246};

/* the drawing: the plane's grid in display units and its pixel frame */
typedef struct iso {
    const lx_plane *p;
    const double *E;     /* display units (lx or fc) */
    double len;          /* metres per display length unit */
    double A0, A1, B0, B1; /* the view drawn (the area and the luminaires near it), display length units */
    double fA0, fA1, fB0, fB1; /* the calculation area (the field), display length units */
    double pa0, pa1, pb0, pb1; /* the points' extent, display length units */
    lx__box area;        /* the view in pixels */
    lx__box field;       /* the calculation area in pixels */
    lx__scale scale;
    double level[LX__MAX_LEVELS];
    int nlev, geometric, white;
    const char *lunit, *eunit;
    const char *qname, *qsym; /* "Illuminance", "E"; "Daylight factor", "DF" */
} iso;

/* Catmull-Rom weights of the four nodes around fraction t of a cell */
static void cr_weights(double t, double w[4])
{
    double t2 = t * t, t3 = t2 * t;
    w[0] = 0.5 * (-t + 2 * t2 - t3), w[1] = 0.5 * (2 - 5 * t2 + 3 * t3);
    w[2] = 0.5 * (t + 4 * t2 - 3 * t3), w[3] = 0.5 * (t3 - t2);
}

/* E at display coordinates (a, b): bicubic (Catmull-Rom) between the points, so contours are
 * smooth curves (it passes through every computed value; the nodes beyond an edge repeat it); the
 * outer cells' cubics carried on for up to one spacing beyond the outer points (the half cell
 * around cell-centre points), constant beyond that */
static double value_at(const iso *g, double a, double b)
{
    const lx_plane *p = g->p;
    long na = (long)p->na, nb = (long)p->nb;
    double fa = na > 1 && g->pa1 > g->pa0 ? (a - g->pa0) / (g->pa1 - g->pa0) * (na - 1) : 0;
    double fb = nb > 1 && g->pb1 > g->pb0 ? (b - g->pb0) / (g->pb1 - g->pb0) * (nb - 1) : 0;
    fa = fmax(-1, fmin(fa, (double)na));
    fb = fmax(-1, fmin(fb, (double)nb));
    long ia = na > 1 ? (long)fmax(0, fmin(floor(fa), (double)(na - 2))) : 0;
    long ib = nb > 1 ? (long)fmax(0, fmin(floor(fb), (double)(nb - 2))) : 0;
    if (na == 1) fa = 0;
    if (nb == 1) fb = 0;
    double wa[4], wb[4], sum = 0;
    cr_weights(fa - (double)ia, wa);
    cr_weights(fb - (double)ib, wb);
    for (int j = 0; j < 4; j++) {
        long jb = ib - 1 + j;
        jb = jb < 0 ? 0 : jb >= nb ? nb - 1 : jb;
        double r = 0;
        for (int i = 0; i < 4; i++) {
            long ja = ia - 1 + i;
            ja = ja < 0 ? 0 : ja >= na ? na - 1 : ja;
            r += wa[i] * g->E[jb * na + ja];
        }
        sum += wb[j] * r;
    }
    return sum;
}

static double px_x(const iso *g, double a) { return g->area.x0 + (a - g->A0) / (g->A1 - g->A0) * (g->area.x1 - g->area.x0); }
static double px_y(const iso *g, double b) { return g->area.y1 - (b - g->B0) / (g->B1 - g->B0) * (g->area.y1 - g->area.y0); }
static double da_of(const iso *g, double x) { return g->A0 + (x - g->area.x0) / (g->area.x1 - g->area.x0) * (g->A1 - g->A0); }
static double db_of(const iso *g, double y) { return g->B0 + (g->area.y1 - y) / (g->area.y1 - g->area.y0) * (g->B1 - g->B0); }

/* the false-colour field, one value per pixel */
static lx_status draw_field(lx_ctx *ctx, lx__page *pg, const iso *g)
{
    const lx__box F = g->field;
    int w = (int)lround(F.x1 - F.x0), h = (int)lround(F.y1 - F.y0);
    if (w < 1 || h < 1) return LX_OK;
    double *img = lx__alloc_n((size_t)w * (size_t)h, sizeof(double));
    if (!img) return lx__error(ctx, LX_ENOMEM, NULL, 0, "grid plot: out of memory");
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            img[(size_t)y * w + x] = value_at(g, da_of(g, F.x0 + x + 0.5), db_of(g, F.y0 + y + 0.5));
    lx_status st = lx__page_map(ctx, pg, F, img, w, h, &g->scale);
    lx__free(img);
    return st;
}

typedef struct seg_list {
    double *xy; /* x0 y0 x1 y1 per segment, pixels */
    size_t n, cap;
    int oom;
    double ox, oy, step;
} seg_list;

static void seg_add(void *arg, double x0, double y0, double x1, double y1)
{
    seg_list *s = arg;
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 1024;
        double *nx = lx__realloc_n(s->xy, cap * 4, sizeof *nx);
        if (!nx) {
            s->oom = 1;
            return;
        }
        s->xy = nx;
        s->cap = cap;
    }
    double *q = s->xy + 4 * s->n++;
    q[0] = s->ox + x0 * s->step, q[1] = s->oy + y0 * s->step, q[2] = s->ox + x1 * s->step, q[3] = s->oy + y1 * s->step;
}

/* contour segments of every level (pixels; segs[k] for level k), on nodes every 2 pixels */
static lx_status contours(lx_ctx *ctx, lx__page *pg, const iso *g, seg_list *segs)
{
    const double step = 2;
    const lx__box F = g->field;
    int gw = (int)floor((F.x1 - F.x0) / step) + 1, gh = (int)floor((F.y1 - F.y0) / step) + 1;
    double *v = lx__alloc_n((size_t)gw * (size_t)gh, sizeof(double));
    if (!v) return lx__error(ctx, LX_ENOMEM, NULL, 0, "grid plot: out of memory");
    for (int j = 0; j < gh; j++)
        for (int i = 0; i < gw; i++)
            v[(size_t)j * gw + i] = value_at(g, da_of(g, F.x0 + i * step), db_of(g, F.y0 + j * step));
    cairo_t *cr = pg->cr;
    for (int k = 0; k < g->nlev; k++) {
        segs[k] = (seg_list){.ox = F.x0, .oy = F.y0, .step = step};
        lx__contour(v, gw, gh, g->level[k], seg_add, &segs[k]);
        if (segs[k].oom) {
            lx__free(v);
            return lx__error(ctx, LX_ENOMEM, NULL, 0, "grid plot: out of memory");
        }
        unsigned char c[3];
        if (g->white) { /* the level's colour, darkened so yellow reads on white */
            lx__falsecolor(lx__scale_t(&g->scale, g->level[k]), c);
            for (int i = 0; i < 3; i++) c[i] = (unsigned char)(c[i] * 0.78);
        } else {
            memcpy(c, INK, 3);
        }
        lx__rgb(cr, c, g->white ? 1 : 0.85);
        cairo_set_line_width(cr, g->white ? 1.8 : 1.2);
        for (size_t s = 0; s < segs[k].n; s++) {
            const double *q = segs[k].xy + 4 * s;
            cairo_move_to(cr, q[0], q[1]);
            cairo_line_to(cr, q[2], q[3]);
        }
        cairo_stroke(cr);
        pg->lay.level[k] = g->level[k];
        pg->lay.level_segments[k] = segs[k].n;
    }
    pg->lay.n_levels = g->nlev;
    lx__free(v);
    return LX_OK;
}

static void level_text(char *buf, size_t cap, const iso *g, int k)
{
    if (g->geometric) lx__fmt_tick(buf, cap, g->level[k], g->level[k]); /* 1-2-5 values: "0.05", "200" */
    else {
        double step = g->nlev > 1 ? g->level[1] - g->level[0] : g->level[0];
        lx__fmt_tick(buf, cap, g->level[k], step);
    }
}

/* each level's value on its line, at up to three places collision-free and well apart */
static void contour_labels(lx__page *pg, const iso *g, const seg_list *segs)
{
    const lx__font f = {11, 1, {20, 20, 20}, 0};
    lx__box inside = {g->field.x0 + 2, g->field.y0 + 2, g->field.x1 - 2, g->field.y1 - 2};
    for (int k = 0; k < g->nlev; k++) {
        const seg_list *s = &segs[k];
        if (s->n == 0) continue;
        char buf[32];
        level_text(buf, sizeof buf, g, k);
        double placed[3][2];
        int np = 0;
        /* visit the segments in a scattered order (a stride prime to n) so labels spread out */
        size_t stride = s->n > 7 ? s->n / 7 + 1 : 1;
        while (stride > 1 && s->n % stride == 0) stride++;
        size_t idx = (size_t)k * 131 % s->n;
        for (size_t t = 0; t < s->n && np < 3; t++, idx = (idx + stride) % s->n) {
            const double *q = s->xy + 4 * idx;
            double cx = 0.5 * (q[0] + q[2]), cy = 0.5 * (q[1] + q[3]);
            int far = 1;
            for (int i = 0; i < np; i++)
                if (hypot(cx - placed[i][0], cy - placed[i][1]) < 140) far = 0;
            if (!far) continue;
            lx__box b = lx__text_box(pg, &f, cx, cy, 0.5, 0.5, buf);
            lx__box pad = {b.x0 - 2, b.y0, b.x1 + 2, b.y1};
            if (!lx__page_free_at(pg, pad, 8, inside)) continue;
            cairo_t *cr = pg->cr;
            lx__rgb(cr, WHITE, 0.9);
            cairo_rectangle(cr, pad.x0, pad.y0, pad.x1 - pad.x0, pad.y1 - pad.y0);
            cairo_fill(cr);
            lx__page_text(pg, &f, cx, cy, 0.5, 0.5, LX__TEXT_CONTOUR, g->level[k], buf);
            placed[np][0] = cx, placed[np][1] = cy, np++;
        }
    }
}

/* a luminaire: a ringed cross at its projection, a line to where its aim meets the plane */
static void marks(lx__page *pg, const iso *g, const lx_isolux_opts *o)
{
    const lx_plane *p = g->p;
    cairo_t *cr = pg->cr;
    for (size_t k = 0; k < o->n_marks && pg->lay.n_marks < 64; k++) {
        const lx_plot_mark *m = &o->marks[k];
        double d[3], n = 0, an = 0, al = 0;
        for (int i = 0; i < 3; i++) d[i] = m->pos_m[i] - p->origin_m[i];
        double a = (d[0] * p->u[0] + d[1] * p->u[1] + d[2] * p->u[2]) / g->len;
        double b = (d[0] * p->v[0] + d[1] * p->v[1] + d[2] * p->v[2]) / g->len;
        if (a < g->A0 - 1e-9 || a > g->A1 + 1e-9 || b < g->B0 - 1e-9 || b > g->B1 + 1e-9) continue;
        double x = px_x(g, a), y = px_y(g, b);
        for (int i = 0; i < 3; i++) n += d[i] * p->normal[i], an += m->aim[i] * p->normal[i], al += m->aim[i] * m->aim[i];
        if (al > 0 && fabs(an) > 1e-9 * sqrt(al) && -n / an > 0) { /* where the aim meets the plane */
            double t = -n / an, q[3];
            for (int i = 0; i < 3; i++) q[i] = d[i] + t * m->aim[i];
            double qa = (q[0] * p->u[0] + q[1] * p->u[1] + q[2] * p->u[2]) / g->len;
            double qb = (q[0] * p->v[0] + q[1] * p->v[1] + q[2] * p->v[2]) / g->len;
            double qx = px_x(g, qa), qy = px_y(g, qb);
            if (hypot(qx - x, qy - y) > 9) {
                cairo_save(cr);
                cairo_rectangle(cr, g->area.x0, g->area.y0, g->area.x1 - g->area.x0, g->area.y1 - g->area.y0);
                cairo_clip(cr);
                lx__rgb(cr, INK, 1);
                cairo_set_line_width(cr, 1.4);
                cairo_move_to(cr, x, y);
                cairo_line_to(cr, qx, qy);
                cairo_stroke(cr);
                cairo_arc(cr, qx, qy, 2.5, 0, 2 * LX__PI);
                cairo_fill(cr);
                cairo_restore(cr);
            }
        }
        lx__rgb(cr, WHITE, 1);
        cairo_arc(cr, x, y, 6.5, 0, 2 * LX__PI);
        cairo_fill_preserve(cr);
        lx__rgb(cr, INK, 1);
        cairo_set_line_width(cr, 1.5);
        cairo_stroke(cr);
        cairo_move_to(cr, x - 4.5, y), cairo_line_to(cr, x + 4.5, y);
        cairo_move_to(cr, x, y - 4.5), cairo_line_to(cr, x, y + 4.5);
        cairo_stroke(cr);
        lx__page_keep(pg, (lx__box){x - 8, y - 8, x + 8, y + 8});
        pg->lay.mark[pg->lay.n_marks][0] = x;
        pg->lay.mark[pg->lay.n_marks][1] = y;
        pg->lay.n_marks++;
    }
}

static void mark_names(lx__page *pg, const iso *g, const lx_isolux_opts *o)
{
    const lx__font f = {10, 0, {20, 20, 20}, 1};
    for (size_t k = 0, j = 0; k < o->n_marks && j < (size_t)pg->lay.n_marks; k++) {
        const lx_plot_mark *m = &o->marks[k];
        double d[3];
        for (int i = 0; i < 3; i++) d[i] = m->pos_m[i] - g->p->origin_m[i];
        double a = (d[0] * g->p->u[0] + d[1] * g->p->u[1] + d[2] * g->p->u[2]) / g->len;
        double b = (d[0] * g->p->v[0] + d[1] * g->p->v[1] + d[2] * g->p->v[2]) / g->len;
        if (a < g->A0 - 1e-9 || a > g->A1 + 1e-9 || b < g->B0 - 1e-9 || b > g->B1 + 1e-9) continue;
        double x = pg->lay.mark[j][0], y = pg->lay.mark[j][1];
        j++;
        if (!m->name || !*m->name) continue;
        static const double off[4][4] = {{10, -9, 0, 0.5}, {-10, -9, 1, 0.5}, {10, 9, 0, 0.5}, {-10, 9, 1, 0.5}};
        for (int c = 0; c < 4; c++) {
            lx__box bx = lx__text_box(pg, &f, x + off[c][0], y + off[c][1], off[c][2], off[c][3], m->name);
            if (!lx__page_free_at(pg, bx, 1, g->area)) continue;
            lx__page_text(pg, &f, x + off[c][0], y + off[c][1], off[c][2], off[c][3], LX__TEXT_LABEL, NAN, m->name);
            break;
        }
    }
}

/* "x", "y", "z" (or "-x" ...) for an axis along a coordinate axis, else the fallback */
static const char *axis_name(const double *u, const char *fallback)
{
    static const char *names[] = {"x", "y", "z", "-x", "-y", "-z"};
    for (int k = 0; k < 3; k++) {
        if (fabs(u[k] - 1) < 1e-12) return names[k];
        if (fabs(u[k] + 1) < 1e-12) return names[k + 3];
    }
    return fallback;
}

/* frame, round ticks in the length unit, axis titles */
static void axes(lx__page *pg, const iso *g)
{
    const lx__font fk = {11, 0, {30, 30, 30}, 0}, fa = {12, 0, {30, 30, 30}, 0};
    cairo_t *cr = pg->cr;
    lx__box A = g->area;
    lx__rgb(cr, INK, 1);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, A.x0 - 0.5, A.y0 - 0.5, A.x1 - A.x0 + 1, A.y1 - A.y0 + 1);
    cairo_stroke(cr);
    const lx__box F = g->field; /* the calculation area inside a larger view: its own frame */
    if (F.x0 > A.x0 + 0.5 || F.y0 > A.y0 + 0.5 || F.x1 < A.x1 - 0.5 || F.y1 < A.y1 - 0.5) {
        lx__rgb(cr, GREY, 1);
        cairo_rectangle(cr, F.x0 - 0.5, F.y0 - 0.5, F.x1 - F.x0 + 1, F.y1 - F.y0 + 1);
        cairo_stroke(cr);
    }
    double t[64], step;
    lx__box page = {0, 0, pg->w, pg->h};
    int nt = lx__ticks_linear(g->A0, g->A1, (int)fmax(2, (A.x1 - A.x0) / 90), t, 64, &step);
    for (int k = 0; k < nt; k++) {
        double x = round(px_x(g, t[k])) + 0.5;
        cairo_move_to(cr, x, A.y1 + 0.5), cairo_line_to(cr, x, A.y1 + 5.5);
        cairo_stroke(cr);
        char buf[32];
        lx__fmt_tick(buf, sizeof buf, t[k], step);
        lx__box b = lx__text_box(pg, &fk, x, A.y1 + 8, 0.5, 0, buf);
        if (lx__page_free_at(pg, b, 2, page)) lx__page_text(pg, &fk, x, A.y1 + 8, 0.5, 0, LX__TEXT_TICK, t[k], buf);
    }
    nt = lx__ticks_linear(g->B0, g->B1, (int)fmax(2, (A.y1 - A.y0) / 70), t, 64, &step);
    double widest = 0;
    for (int k = 0; k < nt; k++) {
        double y = round(px_y(g, t[k])) + 0.5;
        cairo_move_to(cr, A.x0 - 5.5, y), cairo_line_to(cr, A.x0 - 0.5, y);
        cairo_stroke(cr);
        char buf[32];
        lx__fmt_tick(buf, sizeof buf, t[k], step);
        lx__box b = lx__text_box(pg, &fk, A.x0 - 8, y, 1, 0.5, buf);
        if (!lx__page_free_at(pg, b, 1, page)) continue;
        lx__page_text(pg, &fk, A.x0 - 8, y, 1, 0.5, LX__TEXT_TICK, t[k], buf);
        widest = fmax(widest, b.x1 - b.x0);
    }
    char buf[48];
    snprintf(buf, sizeof buf, "%s (%s)", axis_name(g->p->u, "a"), g->lunit);
    lx__page_text(pg, &fa, 0.5 * (A.x0 + A.x1), A.y1 + 26, 0.5, 0, LX__TEXT_AXIS, NAN, buf);
    snprintf(buf, sizeof buf, "%s (%s)", axis_name(g->p->v, "b"), g->lunit);
    lx__page_text_up(pg, &fa, A.x0 - 8 - widest - 14, 0.5 * (A.y0 + A.y1), LX__TEXT_AXIS, buf);
}

/* the plane as text: "z = 0.8 m" when it is a coordinate plane, else its normal */
static void plane_name(char *buf, size_t cap, const iso *g)
{
    const lx_plane *p = g->p;
    for (int k = 0; k < 3; k++)
        if (fabs(p->u[k]) < 1e-12 && fabs(p->v[k]) < 1e-12) {
            snprintf(buf, cap, "%c = %.4g %s", "xyz"[k], p->origin_m[k] / g->len, g->lunit);
            return;
        }
    snprintf(buf, cap, "a plane with normal (%.3g, %.3g, %.3g)", p->normal[0], p->normal[1], p->normal[2]);
}

static void title(lx__page *pg, const iso *g, const lx_isolux_opts *o, double x, double y)
{
    const lx__font ft = {17, 1, {20, 20, 20}, 0}, fs = {12, 0, {90, 90, 90}, 0};
    char head[400], plane[96], sub[400];
    plane_name(plane, sizeof plane, g);
    const char *src = o->source, *base = src ? strrchr(src, '/') : NULL;
    base = base ? base + 1 : src;
    if (o->surface && *o->surface) snprintf(head, sizeof head, "%s on %s (%s)", g->qname, o->surface, plane);
    else snprintf(head, sizeof head, "%s on %s", g->qname, plane);
    if (base && *base) snprintf(head + strlen(head), sizeof head - strlen(head), " \u2014 %s", base);
    double maxw = pg->w - x - 16;
    lx__box b = lx__page_text_fit(pg, &ft, x, y, LX__TEXT_TITLE, head, maxw);
    const lx_plane *p = g->p;
    double sa = p->na > 1 ? (g->pa1 - g->pa0) / (p->na - 1) : 0, sb = p->nb > 1 ? (g->pb1 - g->pb0) / (p->nb - 1) : 0;
    snprintf(sub, sizeof sub, "%zu \u00d7 %zu points, spacing %.4g \u00d7 %.4g %s, contours in %s%s%s", p->na, p->nb, sa,
             sb, g->lunit, g->eunit, o->caption && *o->caption ? " \u00b7 " : "", o->caption ? o->caption : "");
    lx__page_text_fit(pg, &fs, x, b.y1 + 3, LX__TEXT_TITLE, sub, maxw);
}

/* Draws markup at (x, y) (top left): "_word" is a subscript ("E_avg", "U_0 = E_min / E_avg");
 * returns the end x. */
static double rich(lx__page *pg, const lx__font *f, double x, double y, const char *markup)
{
    cairo_t *cr = pg->cr;
    lx__font fs = *f;
    fs.size = f->size * 0.72;
    lx__box b = lx__text_box(pg, f, x, y, 0, 0, "E"); /* sets the font */
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    double base = b.y0 + fe.ascent, cx = x;
    lx__rgb(cr, f->rgb, 1);
    char piece[96];
    for (const char *s = markup; *s;) {
        int sub = *s == '_';
        if (sub) s++;
        size_t n = 0;
        while (s[n] && s[n] != '_' && (!sub || (s[n] != ' ' && s[n] != '/')) && n + 1 < sizeof piece) n++;
        memcpy(piece, s, n);
        piece[n] = 0;
        s += n;
        lx__box pb = lx__text_box(pg, sub ? &fs : f, cx, y, 0, 0, piece);
        cairo_move_to(cr, cx, base + (sub ? 0.3 * f->size : 0));
        cairo_show_text(cr, piece);
        cx = pb.x1;
    }
    cairo_new_path(cr);
    return cx;
}

/* one statistics entry: the quantity in markup, then its value in bold; recorded as one label */
static void stat(lx__page *pg, double x, double y, const char *what, double value, const char *vtext)
{
    const lx__font f = {13, 0, {20, 20, 20}, 0}, fb = {13, 1, {20, 20, 20}, 0};
    double end = rich(pg, &f, x, y, what);
    lx__box vb = lx__text_box(pg, &fb, end + 8, y, 0, 0, vtext);
    lx__box all = {x, vb.y0, vb.x1, vb.y1 + 0.3 * f.size};
    char text[96];
    snprintf(text, sizeof text, "%s %s", what, vtext);
    cairo_font_extents_t fe;
    cairo_font_extents(pg->cr, &fe);
    lx__rgb(pg->cr, fb.rgb, 1);
    cairo_move_to(pg->cr, vb.x0, vb.y0 + fe.ascent);
    cairo_show_text(pg->cr, vtext);
    cairo_new_path(pg->cr);
    lx__layout *L = &pg->lay;
    if (L->n_label == L->cap_label) {
        size_t cap = L->cap_label ? 2 * L->cap_label : 64;
        lx__label *nl = lx__realloc_n(L->label, cap, sizeof *nl);
        if (!nl) {
            pg->oom = 1;
            return;
        }
        L->label = nl;
        L->cap_label = cap;
    }
    lx__label *l = &L->label[L->n_label++];
    l->box = all;
    l->role = LX__TEXT_STATS;
    l->value = value;
    snprintf(l->text, sizeof l->text, "%s", text);
}

static void stats_box(lx__page *pg, const iso *g, lx__box box)
{
    const lx_plane *p = g->p;
    size_t n = p->na * p->nb;
    double sum = 0, mn = INFINITY, mx = -INFINITY;
    for (size_t i = 0; i < n; i++) sum += g->E[i], mn = fmin(mn, g->E[i]), mx = fmax(mx, g->E[i]);
    double avg = sum / (double)n, u0 = avg > 0 ? mn / avg : NAN, g2 = mx > 0 ? mn / mx : NAN;
    cairo_t *cr = pg->cr;
    lx__rgb(cr, PANEL, 1);
    cairo_rectangle(cr, box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
    cairo_fill(cr);
    lx__rgb(cr, GREY, 1);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, box.x0 + 0.5, box.y0 + 0.5, box.x1 - box.x0 - 1, box.y1 - box.y0 - 1);
    cairo_stroke(cr);
    char v[5][48];
    lx__fmt_sig(v[0], 40, avg, 4), lx__fmt_sig(v[1], 40, mn, 4), lx__fmt_sig(v[2], 40, mx, 4);
    for (int k = 0; k < 3; k++) strcat(v[k], strcmp(g->eunit, "%") ? " " : ""), strcat(v[k], g->eunit);
    snprintf(v[3], 48, isfinite(u0) ? "%.3f" : "-", u0);
    snprintf(v[4], 48, isfinite(g2) ? "%.3f" : "-", g2);
    double col = (box.x1 - box.x0 - 24) / 3, y0 = box.y0 + 9, y1 = box.y0 + 33;
    char q[5][48];
    const char *e = g->qsym;
    snprintf(q[0], sizeof q[0], "%s_avg", e), snprintf(q[1], sizeof q[1], "%s_min", e);
    snprintf(q[2], sizeof q[2], "%s_max", e);
    snprintf(q[3], sizeof q[3], "U_0 = %s_min / %s_avg", e, e), snprintf(q[4], sizeof q[4], "%s_min / %s_max", e, e);
    stat(pg, box.x0 + 12, y0, q[0], avg, v[0]);
    stat(pg, box.x0 + 12 + col, y0, q[1], mn, v[1]);
    stat(pg, box.x0 + 12 + 2 * col, y0, q[2], mx, v[2]);
    stat(pg, box.x0 + 12, y1, q[3], u0, v[3]);
    stat(pg, box.x0 + 12 + 2 * col, y1, q[4], g2, v[4]);
}

/* the grid in display units, its extents, the scale and the contour levels */
static lx_status setup(lx_ctx *ctx, iso *g, const lx_plane *p, const double *E_lx, const lx_isolux_opts *o, double **Eu)
{
    memset(g, 0, sizeof *g);
    g->p = p;
    int df = o->quantity == LX_PLOT_DAYLIGHT_FACTOR;
    g->len = o->imperial ? FT_M : 1;
    g->lunit = o->imperial ? "ft" : "m";
    g->eunit = df ? "%" : o->imperial ? "fc" : "lx";
    g->qname = df ? "Daylight factor" : "Illuminance";
    g->qsym = df ? "DF" : "E";
    g->white = o->background == LX_ISOLUX_WHITE;
    size_t n = p->na * p->nb;
    double *E = lx__alloc_n(n, sizeof *E);
    if (!E) return lx__error(ctx, LX_ENOMEM, NULL, 0, "grid plot: out of memory");
    double mn = INFINITY, mx = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(E_lx[i])) {
            lx__free(E);
            return lx__error(ctx, LX_EINVAL, NULL, 0, "grid plot: value %zu is not finite", i);
        }
        E[i] = o->imperial && !df ? E_lx[i] / LX_PER_FC : E_lx[i];
        mn = fmin(mn, E[i]), mx = fmax(mx, E[i]);
    }
    g->E = *Eu = E;
    g->pa0 = p->a0 / g->len, g->pa1 = p->a1 / g->len, g->pb0 = p->b0 / g->len, g->pb1 = p->b1 / g->len;
    int area = o->area_m[1] > o->area_m[0] || o->area_m[3] > o->area_m[2];
    g->A0 = area ? o->area_m[0] / g->len : g->pa0, g->A1 = area ? o->area_m[1] / g->len : g->pa1;
    g->B0 = area ? o->area_m[2] / g->len : g->pb0, g->B1 = area ? o->area_m[3] / g->len : g->pb1;
    double wa = g->A1 - g->A0, wb = g->B1 - g->B0, w = fmax(wa, wb) > 0 ? fmax(wa, wb) : 1;
    if (!(wa > 0)) g->A0 -= 0.05 * w, g->A1 += 0.05 * w; /* a line of points: a strip */
    if (!(wb > 0)) g->B0 -= 0.05 * w, g->B1 += 0.05 * w;
    g->fA0 = g->A0, g->fA1 = g->A1, g->fB0 = g->B0, g->fB1 = g->B1;
    /* the view takes in the luminaires just outside the area (street lights beside a road): those
     * within half the area's size of it, with a margin */
    wa = g->A1 - g->A0, wb = g->B1 - g->B0;
    double pad = 0.03 * fmax(wa, wb);
    for (size_t k = 0; k < o->n_marks; k++) {
        double d[3];
        for (int i = 0; i < 3; i++) d[i] = o->marks[k].pos_m[i] - p->origin_m[i];
        double a = (d[0] * p->u[0] + d[1] * p->u[1] + d[2] * p->u[2]) / g->len;
        double b = (d[0] * p->v[0] + d[1] * p->v[1] + d[2] * p->v[2]) / g->len;
        if (a < g->fA0 - 0.5 * wa || a > g->fA1 + 0.5 * wa || b < g->fB0 - 0.5 * wb || b > g->fB1 + 0.5 * wb) continue;
        if (a < g->fA0 || a > g->fA1 || b < g->fB0 || b > g->fB1) {
            g->A0 = fmin(g->A0, a - pad), g->A1 = fmax(g->A1, a + pad);
            g->B0 = fmin(g->B0, b - pad), g->B1 = fmax(g->B1, b + pad);
        }
    }
    /* and the outlines that reach within half the area's size of it (the room around a work plane) */
    for (size_t k = 0; k < o->n_outlines; k++) {
        double ext[4];
        if (!lx__outlines_extent(&o->outlines[k], 1, ext)) continue;
        for (int i = 0; i < 4; i++) ext[i] /= g->len;
        if (ext[1] < g->fA0 - 0.5 * wa || ext[0] > g->fA1 + 0.5 * wa || ext[3] < g->fB0 - 0.5 * wb || ext[2] > g->fB1 + 0.5 * wb)
            continue;
        double pa = o->outlines[k].kind == LX_OUTLINE_WALL || o->outlines[k].kind == LX_OUTLINE_OPENING ? pad : 0;
        g->A0 = fmin(g->A0, ext[0] - pa), g->A1 = fmax(g->A1, ext[1] + pa);
        g->B0 = fmin(g->B0, ext[2] - pa), g->B1 = fmax(g->B1, ext[3] + pa);
    }
    g->nlev = lx__levels_125(mn, mx, g->level, LX__MAX_LEVELS, &g->geometric);
    if (df) { /* the daylight factor: the 1-2-5 % series designers read (2 % and 5 %: BS 8206-2, EN 17037) */
        static const double dfl[] = {0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50};
        int n = 0;
        for (size_t k = 0; k < sizeof dfl / sizeof *dfl; k++)
            if (dfl[k] > mn && dfl[k] < mx) g->level[n++] = dfl[k];
        if (n) g->nlev = n, g->geometric = 1;
    }
    int log = o->scale == LX_PLOT_SCALE_LOG || (o->scale == LX_PLOT_SCALE_AUTO && g->geometric && !(df && mx / mn <= 20));
    if (log && !(mx > 0)) log = 0;
    if (log) lx__scale_auto(&g->scale, E, n, 1, NAN, NAN);
    else {
        double step = lx__nice_step(mx - mn > 0 ? mx - mn : fabs(mx) + 1, 5);
        lx__scale_auto(&g->scale, E, n, 0, floor(mn / step + 1e-9) * step, ceil(mx / step - 1e-9) * step);
    }
    return LX_OK;
}

lx_status lx__isolux_page(lx_ctx *ctx, const lx_plane *p, const double *E_lx, const lx_isolux_opts *opts, int vector,
                          lx__page *pg_out)
{
    if (!p || !E_lx || p->na < 1 || p->nb < 1) return lx__error(ctx, LX_EINVAL, NULL, 0, "grid plot: bad arguments");
    if (!(p->a1 >= p->a0 && p->b1 >= p->b0)) return lx__error(ctx, LX_EINVAL, NULL, 0, "grid plot: empty area");
    lx_isolux_opts o = {0};
    if (opts) o = *opts;
    lx_status rs = lx__check_reserved(ctx, "isolux options", o.reserved, sizeof o.reserved);
    if (rs) return rs;
    if (o.quantity != LX_PLOT_ILLUMINANCE && o.quantity != LX_PLOT_DAYLIGHT_FACTOR)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "grid plot: unknown quantity %d", o.quantity);
    if (o.n_outlines && !o.outlines) return lx__error(ctx, LX_EINVAL, NULL, 0, "grid plot: n_outlines without outlines");
    iso g;
    double *E = NULL;
    lx_status st = setup(ctx, &g, p, E_lx, &o, &E);
    if (st) return st;
    /* the view keeps the plane's aspect: the longer side 640 pixels (up to 960 for a long strip,
     * whose shorter side then gets 240), the shorter at least 160 */
    double wa = g.A1 - g.A0, wb = g.B1 - g.B0;
    int pw = 640, ph = 640;
    if (wa >= wb) {
        pw = (int)fmin(960, fmax(640, lround(240 * wa / wb)));
        ph = (int)fmax(160, lround(pw * wb / wa));
    } else {
        ph = (int)fmin(960, fmax(640, lround(240 * wb / wa)));
        pw = (int)fmax(160, lround(ph * wa / wb));
    }
    const int left = 84, top = 66, gap = 26, legend_w = 120, right = 16, below = 54, stats_h = 60;
    int body = ph > 220 ? ph : 220;
    int W = left + pw + gap + legend_w + right, H = top + body + below + stats_h + 14;
    if (W < 720) W = 720;
    static const unsigned char bg[3] = {255, 255, 255};
    lx__page pg;
    if ((st = vector ? lx__page_init_vector(ctx, &pg, W, H, bg) : lx__page_init(ctx, &pg, W, H, bg))) goto fail;
    g.area = (lx__box){left, top, left + pw, top + ph};
    g.field = (lx__box){px_x(&g, g.fA0), px_y(&g, g.fB1), px_x(&g, g.fA1), px_y(&g, g.fB0)};
    pg.lay.area = g.area;
    if (!g.white && (g.field.x0 > g.area.x0 + 0.5 || g.field.y0 > g.area.y0 + 0.5 || g.field.x1 < g.area.x1 - 0.5 ||
                     g.field.y1 < g.area.y1 - 0.5)) { /* outside the calculation area */
        static const unsigned char around[3] = {236, 236, 236};
        lx__rgb(pg.cr, around, 1);
        cairo_rectangle(pg.cr, g.area.x0, g.area.y0, g.area.x1 - g.area.x0, g.area.y1 - g.area.y0);
        cairo_fill(pg.cr);
    }
    pg.lay.ax0 = g.A0, pg.lay.ax1 = g.A1, pg.lay.ay0 = g.B0, pg.lay.ay1 = g.B1;
    seg_list segs[LX__MAX_LEVELS];
    memset(segs, 0, sizeof segs);
    if (!g.white && (st = draw_field(ctx, &pg, &g))) goto done;
    if ((st = contours(ctx, &pg, &g, segs))) goto done;
    if (o.n_outlines && o.outlines) {
        lx__plan_view pv = {g.area, g.A0 * g.len, g.A1 * g.len, g.B0 * g.len, g.B1 * g.len, 1};
        lx__plan_draw(pg.cr, &pv, o.outlines, o.n_outlines, pg.lay.outlines);
    }
    title(&pg, &g, &o, left, 12);
    marks(&pg, &g, &o);
    axes(&pg, &g);
    contour_labels(&pg, &g, segs);
    mark_names(&pg, &g, &o);
    char lt[32];
    snprintf(lt, sizeof lt, "%s (%s)", g.qsym, g.eunit);
    lx__page_legend(&pg, (lx__box){left + pw + gap, top, W - right, top + body}, &g.scale, lt);
    stats_box(&pg, &g, (lx__box){left, top + body + below, left + pw + gap + legend_w, top + body + below + stats_h});
done:
    for (int k = 0; k < LX__MAX_LEVELS; k++) lx__free(segs[k].xy);
    if (st) lx__page_free(&pg);
    else *pg_out = pg;
fail:
    lx__free(E);
    return st;
}

lx_status lx__isolux_png(lx_ctx *ctx, const char *path, const lx_plane *p, const double *E_lx,
                         const lx_isolux_opts *opts, lx__layout *out)
{
    if (!path) return lx__error(ctx, LX_EINVAL, NULL, 0, "grid plot: bad arguments");
    lx__page pg;
    lx_status st = lx__isolux_page(ctx, p, E_lx, opts, 0, &pg);
    if (st) return st;
    st = lx__page_write_png(ctx, &pg, path);
    if (!st && out) lx__page_take_layout(&pg, out);
    lx__page_free(&pg);
    return st;
}

lx_status lx_grid_write_png(lx_ctx *ctx, const char *path, const lx_plane *plane, const double *E_lx,
                            const lx_isolux_opts *opts)
{
    LX__NEED_CTX(ctx);
    return lx__isolux_png(ctx, path, plane, E_lx, opts, NULL);
}
