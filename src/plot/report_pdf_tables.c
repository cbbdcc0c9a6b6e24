/* report_pdf_tables.c - the design report's result sections: the areas and calculation surfaces
 * (statistics, and each grid's isolux plot drawn as vectors), glare (UGR at each observer position
 * and direction, the CIE 190 table of each photometric file) and emergency lighting. */
#include "plot/report_pdf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const kind_name[LX_AREA_KIND_COUNT] = {"task area",  "surrounding", "background",
                                                          "room plane", "wall",        "ceiling",
                                                          "escape route", "route band", "open area", "high risk"};

/* the area a receiver belongs to, or NULL */
static const lx_scene_area *area_of(const lx_scene *sc, size_t rec)
{
    const lx_scene_design *d = sc->design;
    for (size_t i = 0; d && i < d->n_area; i++)
        if (d->area[i].rec == rec) return &d->area[i];
    return NULL;
}

static void stats_row(lx__rep *r, lx__strtab *t, size_t rec, const lx_scene_result *res)
{
    const lx_scene *sc = r->sc;
    const lx_scene_receiver *rc = &sc->rec[rec];
    const lx_scene_area *A = area_of(sc, rec);
    lx_area_stats s;
    if (lx_scene_area_stats(r->ctx, sc, res, rec, &s) != LX_OK) return;
    char n[16], cell[48], m[32], mn[32], mx[32], u0[32], ez[32];
    snprintf(n, sizeof n, "%zu", s.n);
    if (A) snprintf(cell, sizeof cell, "%.3g x %.3g m", A->grid.cell_m[0], A->grid.cell_m[1]);
    else snprintf(cell, sizeof cell, "%s", rc->kind == LX_SREC_GRID ? "user grid" : "points");
    lx__rep_num(m, sizeof m, s.mean_lx, 4, "lx");
    lx__rep_num(mn, sizeof mn, s.min_lx, 4, "lx");
    lx__rep_num(mx, sizeof mx, s.max_lx, 4, "lx");
    lx__rep_num(u0, sizeof u0, s.u0, 3, "");
    lx__rep_num(ez, sizeof ez, s.cyl_mean_lx, 4, "lx");
    const char *row[9] = {rc->name, A ? kind_name[A->kind] : rc->kind == LX_SREC_GRID ? "grid" : "point", n, cell, m, mn, mx, u0,
                          ez};
    lx__strtab_row(t, row);
}

/* each grid's isolux plot, as vectors, with its statistics under it and the scene's outlines on it (the
 * plan drawer of `scene --png`: lx_scene_receiver_plane, lx_scene_outlines) */
static lx_status isolux(lx__rep *r, size_t rec, const lx_plot_mark *mk)
{
    const lx_scene *sc = r->sc;
    const lx_scene_receiver *rc = &sc->rec[rec];
    lx_plane p;
    lx_status st = lx_scene_receiver_plane(r->ctx, sc, rec, &p);
    if (st != LX_OK) return st;
    lx_plot_outline *ol = NULL;
    size_t n_ol = 0;
    if ((st = lx_scene_outlines(r->ctx, sc, &p, &ol, &n_ol)) != LX_OK) return st;
    lx_isolux_opts o;
    memset(&o, 0, sizeof o);
    int vertical = fabs(rc->normal[2]) < 0.5; /* a wall: the luminaires would all sit on its top edge */
    o.marks = vertical ? NULL : mk, o.n_marks = mk && !vertical ? sc->n_lum : 0, o.source = sc->file, o.surface = rc->name, o.caption = sc->title;
    o.imperial = r->imperial;
    o.outlines = ol, o.n_outlines = n_ol;
    const lx_scene_area *A = area_of(sc, rec);
    if (A) { /* the field covers the area's cells, not only the points */
        int k = rc->axis - 'x', ia = k == 0 ? 1 : 0, ib = k == 2 ? 1 : 2;
        o.area_m[0] = A->origin_m[ia] + A->box_m[0], o.area_m[1] = A->origin_m[ia] + A->box_m[1];
        o.area_m[2] = A->origin_m[ib] + A->box_m[2], o.area_m[3] = A->origin_m[ib] + A->box_m[3];
    }
    lx__page pic;
    st = lx__isolux_page(r->ctx, &p, r->res->E_lx + r->res->first[rec], &o, 1, &pic);
    lx_scene_outlines_free(ol);
    if (st != LX_OK) return st;
    lx__doc_drawing(&r->doc, &pic, LX__DOC_RIGHT - LX__DOC_LEFT, 330);
    lx__page_free(&pic);
    return LX_OK;
}

lx_status lx__rep_surfaces(lx__rep *r)
{
    lx__doc *d = &r->doc;
    const lx_scene *sc = r->sc;
    lx__doc_new_page(d);
    lx__doc_heading(d, 1, "3 Areas and calculation surfaces");
    char vt[200];
    snprintf(vt, sizeof vt, "Statistics over each area's calculation points (E_m the mean, U0 = E_min / E_m)%s.",
             r->res->cylindrical_lx ? "; E_z the mean cylindrical illuminance where it is computed" : "");
    lx__doc_para(d, vt);
    lx__strtab t = {9, 0, 0, NULL, NULL, NULL, 0};
    for (size_t i = 0; i < sc->n_rec; i++) stats_row(r, &t, i, r->res);
    static const char *const head[9] = {"Receiver", "Kind", "Points", "Cells", "E_m", "E_min", "E_max", "U0", "E_z"};
    static const double w[9] = {2.2, 1.2, 0.6, 1.6, 1.0, 1.0, 1.0, 0.6, 0.9};
    lx__strtab_show(d, &t, head, w, "llrlrrrrr", 7.5);
    lx_plot_mark *mk = sc->n_lum ? lx__calloc(sc->n_lum, sizeof *mk) : NULL;
    if (sc->n_lum && !mk) return lx__error(r->ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t l = 0; l < sc->n_lum; l++) {
        memcpy(mk[l].pos_m, sc->lum[l].pos_m, sizeof mk[l].pos_m);
        memcpy(mk[l].aim, sc->lum[l].aim, sizeof mk[l].aim);
        mk[l].name = sc->lum[l].name;
    }
    lx_status st = LX_OK;
    for (size_t i = 0; i < sc->n_rec && st == LX_OK; i++) {
        const lx_scene_receiver *rc = &sc->rec[i];
        if (rc->kind != LX_SREC_GRID || rc->n < 4) continue;
        lx__doc_room(d, 330);
        st = isolux(r, i, mk);
    }
    lx__free(mk);
    return st;
}

/* ---- glare ---- */

static void mono_lines(lx__doc *d, const char *text, double size)
{
    cairo_t *cr = d->pg.cr;
    for (const char *p = text; *p;) {
        const char *e = strchr(p, '\n');
        size_t n = e ? (size_t)(e - p) : strlen(p);
        char line[160];
        snprintf(line, sizeof line, "%.*s", (int)(n < sizeof line - 1 ? n : sizeof line - 1), p);
        lx__doc_room(d, size * 1.3);
        cairo_select_font_face(cr, "DejaVu Sans Mono", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr, size);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, LX__DOC_LEFT, d->y + size);
        cairo_show_text(cr, line);
        cairo_new_path(cr);
        d->y += size * 1.3;
        p += n + (e != NULL);
    }
}

lx_status lx__rep_glare(lx__rep *r)
{
    lx__doc *d = &r->doc;
    const lx_scene *sc = r->sc;
    const lx_scene_design *de = sc->design;
    lx__doc_new_page(d);
    lx__doc_heading(d, 1, "5 Glare (UGR)");
    if (!r->glare) lx__doc_para(d, "The scene has no observers ([observer] sections): no UGR at positions was computed.");
    else {
        lx__doc_para(d, "UGR (CIE 117-1995) at each observer position and line of sight; Lb the background luminance (given, or "
                        "the luminaires' interreflected illuminance at the eye over pi).");
        size_t ng = de && de->n_obs_group ? de->n_obs_group : sc->n_obs;
        for (size_t g = 0; g < ng; g++) {
            lx__strtab t = {6, 0, 0, NULL, NULL, NULL, 0};
            double worst = -INFINITY;
            size_t wi = 0;
            for (size_t o = 0; o < sc->n_obs; o++) {
                if (de && de->obs_group ? (size_t)de->obs_group[o] != g : o != g) continue;
                const lx_scene_observer *ob = &sc->obs[o];
                char pos[64], az[32], ugr[32], lb[32];
                snprintf(pos, sizeof pos, "%.3g, %.3g, %.3g m", ob->pos_m[0], ob->pos_m[1], ob->pos_m[2]);
                double a = atan2(ob->view[1], ob->view[0]) * 180 / LX__PI;
                snprintf(az, sizeof az, "%.4g deg", a < 0 ? a + 360 : a);
                lx__rep_num(ugr, sizeof ugr, r->glare->ugr[o], 3, "");
                if (isfinite(r->glare->ugr[o])) snprintf(ugr, sizeof ugr, "%.1f", r->glare->ugr[o]);
                lx__rep_num(lb, sizeof lb, r->glare->background_cd_m2[o], 3, "cd/m2");
                const char *row[6] = {ob->name, pos, az, ugr, lb, ""};
                size_t k = lx__strtab_row(&t, row);
                if (isfinite(r->glare->ugr[o]) && r->glare->ugr[o] > worst) worst = r->glare->ugr[o], wi = k;
            }
            if (t.nrows && isfinite(worst) && !t.oom) snprintf(t.cell[wi][5], sizeof t.cell[0][0], "highest");
            char h[160];
            snprintf(h, sizeof h, "Observer %s", de && de->obs_group_name ? de->obs_group_name[g] : sc->obs[g].name);
            lx__doc_heading(d, 3, h);
            static const char *const head[6] = {"Observer", "Eye", "Line of sight", "UGR", "Lb", ""};
            static const double w[6] = {1.3, 2.2, 1.3, 0.8, 1.3, 0.9};
            lx__strtab_show(d, &t, head, w, "lllrrl", 8);
        }
    }
    /* the CIE 190 table of each photometric file (its own lamp flux, uncorrected) */
    for (size_t l = 0; l < sc->n_lum; l++) {
        const lx_scene_luminaire *L = &sc->lum[l];
        if (L->kind != LX_SLUM_FILE) continue;
        size_t k = 0;
        while (k < l && !(sc->lum[k].kind == LX_SLUM_FILE && !strcmp(sc->lum[k].lum_path, L->lum_path))) k++;
        if (k < l) continue;
        lx_ugr_table *tab = lx__alloc(sizeof *tab);
        char *text = NULL;
        if (!tab) return lx__error(r->ctx, LX_ENOMEM, NULL, 0, "out of memory");
        lx_status st = lx_ugr_table_compute(r->ctx, L->lum, tab);
        if (st == LX_OK) st = lx_ugr_table_text(r->ctx, tab, &text);
        lx__free(tab);
        if (st != LX_OK) { /* a luminaire without a luminous opening has no table: say why */
            char why[600];
            snprintf(why, sizeof why, "CIE 190 table of %s: not computed (%s).", L->lum_path, lx_ctx_errmsg(r->ctx));
            lx__doc_note(d, why);
            continue;
        }
        char h[300];
        const char *b = strrchr(L->lum_path, '/');
        snprintf(h, sizeof h, "CIE 190:2010 UGR table: %s", b ? b + 1 : L->lum_path);
        lx__doc_heading(d, 3, h);
        mono_lines(d, text, 7.2);
        lx_text_free(text);
        lx__doc_note(d, "Uncorrected (the file's lamp flux), luminaires at 0.25 H spacing, H = 2 m, the observer at the middle of "
                        "a wall; crosswise and endwise per reflectance combination (ceiling, walls, floor cavity).");
    }
    return LX_OK;
}

/* ---- emergency lighting ---- */

void lx__rep_emergency(lx__rep *r)
{
    lx__doc *d = &r->doc;
    const lx_scene *sc = r->sc;
    const lx_scene_design *de = sc->design;
    lx__doc_heading(d, 1, "6 Emergency lighting (EN 1838)");
    if (!r->em) {
        lx__doc_para(d, "The scene has no emergency luminaires.");
        return;
    }
    lx__doc_para(d, "Emergency operation: the emergency luminaires alone at their emergency flux (times their maintenance "
                    "factor), direct light only: EN 1838's minimum values count no light reflected by the room's surfaces, so "
                    "the planner turns interreflection, daylight and the sky off for this operation.");
    lx__strtab t = {4, 0, 0, NULL, NULL, NULL, 0};
    for (size_t l = 0; l < sc->n_lum; l++) {
        if (de->lum_mode[l] == LX_LUM_NORMAL) continue;
        char f[32], mf[32];
        lx__rep_num(f, sizeof f, de->lum_emergency_lm[l], 4, "lm");
        snprintf(mf, sizeof mf, "%.3g", de->lum_mf[l]);
        const char *row[4] = {sc->lum[l].name, de->lum_mode[l] == LX_LUM_MAINTAINED ? "maintained" : "non-maintained", f, mf};
        lx__strtab_row(&t, row);
    }
    static const char *const head[4] = {"Luminaire", "Operation", "Emergency flux", "MF"};
    static const double w[4] = {2, 2, 1.5, 1};
    lx__strtab_show(d, &t, head, w, "llrr", 8.5);
    lx__strtab a = {9, 0, 0, NULL, NULL, NULL, 0};
    for (size_t i = 0; i < sc->n_rec; i++) {
        const lx_scene_area *A = area_of(sc, i);
        if (!A || A->kind < LX_AREA_ESCAPE_ROUTE) continue;
        stats_row(r, &a, i, r->em);
        lx_area_stats s;
        if (!a.oom && a.nrows && lx_scene_area_stats(r->ctx, sc, r->em, i, &s) == LX_OK)
            lx__rep_num(a.cell[a.nrows - 1][8], sizeof a.cell[0][0], s.min_lx > 0 ? s.max_lx / s.min_lx : INFINITY, 3, "");
    }
    static const char *const ah[9] = {"Area", "Kind", "Points", "Cells", "E_m", "E_min", "E_max", "U0", "max/min"};
    static const double aw[9] = {2.0, 1.2, 0.6, 1.6, 1.0, 1.0, 1.0, 0.6, 0.8};
    if (a.nrows) lx__strtab_show(d, &a, ah, aw, "llrlrrrrr", 7.5);
    else {
        lx__strtab_show(d, &a, ah, aw, "llrlrrrrr", 7.5);
        lx__doc_para(d, "No escape routes, open areas or high-risk task areas are given ([area] types escape_route, open_area, "
                        "high_risk).");
    }
}
