/* report_pdf.c - the design report of a scene as a PDF (lx_scene_report_write_pdf): evaluates what
 * the report shows (normal and emergency operation, glare, checks, energy), then writes the title
 * page, the luminaire schedule, the rooms, the areas, the checks, glare, emergency lighting, energy
 * and the method with its error contract. */
#include "plot/report_pdf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- tables of strings ---- */

size_t lx__strtab_row(lx__strtab *t, const char *const *cells)
{
    if (t->nrows == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 16;
        void *nc = lx__realloc_n(t->cell, cap, sizeof *t->cell);
        if (nc) t->cell = nc;
        unsigned char *nb = nc ? lx__realloc_n(t->bad, cap, 1) : NULL;
        if (nb) t->bad = nb;
        unsigned char *nr = nb ? lx__realloc_n(t->rule, cap, 1) : NULL;
        if (nr) t->rule = nr;
        if (!nr) {
            t->oom = 1;
            return 0;
        }
        t->cap = cap;
    }
    for (int c = 0; c < t->ncols; c++) snprintf(t->cell[t->nrows][c], sizeof t->cell[0][0], "%s", cells[c] ? cells[c] : "");
    t->bad[t->nrows] = t->rule[t->nrows] = 0;
    return t->nrows++;
}

static const char *strtab_cell(void *arg, size_t r, int c) { return ((lx__strtab *)arg)->cell[r][c]; }
static int strtab_bad(void *arg, size_t r, int c)
{
    (void)c;
    return ((lx__strtab *)arg)->bad[r];
}
static int strtab_rule(void *arg, size_t r) { return ((lx__strtab *)arg)->rule[r]; }

void lx__strtab_show(lx__doc *d, lx__strtab *t, const char *const *head, const double *width, const char *align, double size)
{
    lx__doc_tab tab;
    memset(&tab, 0, sizeof tab);
    tab.ncols = t->ncols;
    for (int c = 0; c < t->ncols; c++) tab.head[c] = head[c], tab.width[c] = width[c], tab.align[c] = align[c];
    tab.size = size;
    tab.nrows = t->oom ? 0 : t->nrows;
    tab.cell = strtab_cell, tab.flag = strtab_bad, tab.rule_after = strtab_rule, tab.arg = t;
    if (t->oom) d->pg.oom = 1;
    lx__doc_table(d, &tab);
    lx__free(t->cell), lx__free(t->bad), lx__free(t->rule);
    memset(t, 0, sizeof *t);
}

void lx__rep_num(char *buf, size_t cap, double v, int sig, const char *unit)
{
    if (!isfinite(v)) {
        snprintf(buf, cap, "-");
        return;
    }
    char n[48];
    lx__fmt_sig(n, sizeof n, v, sig);
    snprintf(buf, cap, "%s%s%s", n, unit && *unit ? " " : "", unit ? unit : "");
}

static const char *base_name(const char *p)
{
    const char *s = p ? strrchr(p, '/') : NULL;
    return s ? s + 1 : p ? p : "";
}

/* ---- evaluation ---- */

static lx_status evaluate(lx__rep *r, lx_backend backend)
{
    const lx_scene *sc = r->sc;
    const lx_scene_design *d = sc->design;
    lx_status st = lx_scene_plan_make(r->ctx, sc, backend, &r->plan);
    if (st == LX_OK) st = lx_scene_eval(r->ctx, sc, r->plan, NULL, &r->res);
    int em = 0;
    for (size_t l = 0; d && l < sc->n_lum; l++) em |= d->lum_mode[l] != LX_LUM_NORMAL;
    if (st == LX_OK && em) st = lx_scene_plan_make_mode(r->ctx, sc, backend, LX_SCENE_EMERGENCY, &r->em_plan);
    if (st == LX_OK && em) st = lx_scene_eval(r->ctx, sc, r->em_plan, NULL, &r->em);
    if (st == LX_OK && sc->n_obs) st = lx_scene_glare_eval(r->ctx, sc, &r->glare);
    if (st == LX_OK && d && d->n_req) st = lx_scene_check(r->ctx, sc, r->res, r->em, r->glare, &r->checks);
    if (st == LX_OK && d && d->has_energy) st = lx_scene_energy(r->ctx, sc, &r->ein, &r->energy), r->has_energy = st == LX_OK;
    return st;
}

/* "maintained (MF 0.8)" or "new (no maintenance factor)" */
static void values_text(const lx_scene *sc, char *buf, size_t cap)
{
    const lx_scene_design *d = sc->design;
    double lo = INFINITY, hi = -INFINITY;
    for (size_t l = 0; d && l < sc->n_lum; l++)
        if (d->lum_mode[l] != LX_LUM_EMERGENCY) lo = fmin(lo, d->lum_mf[l]), hi = fmax(hi, d->lum_mf[l]);
    if (!d || !d->maintained) snprintf(buf, cap, "new values (no maintenance factor)");
    else if (lo == hi) snprintf(buf, cap, "maintained values (maintenance factor %.4g)", lo);
    else snprintf(buf, cap, "maintained values (maintenance factors %.4g to %.4g)", lo, hi);
}

/* ---- the title page ---- */

static void title_page(lx__rep *r)
{
    lx__doc *d = &r->doc;
    const lx_scene *sc = r->sc;
    lx__font big = {24, 1, {25, 25, 25}, 0}, mid = {13, 0, {60, 60, 60}, 0};
    (void)big;
    d->y = 200;
    lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 24, 1, 0, r->title);
    d->y += 6;
    if (r->project) lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 13, 0, 0, r->project);
    lx__page_text(&d->pg, &mid, LX__DOC_LEFT, d->y + 6, 0, 0, LX__TEXT_TITLE, NAN, "Lighting design report");
    d->y += 40;
    char *date = lx__date_today(), buf[512], vt[160];
    values_text(sc, vt, sizeof vt);
    snprintf(buf, sizeof buf, "Scene: %s\nDate: %s%s%s\nResults: %s.", sc->file, date ? date : "", r->author ? "\nDesigner: " : "",
             r->author ? r->author : "", vt);
    lx__free(date);
    lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 10.5, 0, 0, buf);
    d->y += 14;
    size_t n_area = sc->design ? sc->design->n_area : 0;
    snprintf(buf, sizeof buf, "%zu luminaire%s, %zu room%s, %zu receiver%s (%zu EN 12464-1 / EN 1838 area%s), %zu observer%s.",
             sc->n_lum, sc->n_lum == 1 ? "" : "s", sc->n_room, sc->n_room == 1 ? "" : "s", sc->n_rec, sc->n_rec == 1 ? "" : "s",
             n_area, n_area == 1 ? "" : "s", sc->n_obs, sc->n_obs == 1 ? "" : "s");
    lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 10.5, 0, 0, buf);
    if (r->checks) {
        snprintf(buf, sizeof buf, "Requirements: %zu of %zu checks pass%s.", r->checks->n - r->checks->n_fail, r->checks->n,
                 r->checks->all_pass ? " (all)" : "; the failures are listed under \"Checks\"");
        lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 10.5, 1, 0, buf);
    }
    if (r->has_energy) {
        snprintf(buf, sizeof buf, "Energy: LENI %.3g kWh/(m2 a), %.3g W/m2 installed (EN 15193-1).", r->energy.leni_kWh_m2,
                 r->energy.power_density_W_m2);
        lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 10.5, 0, 0, buf);
    }
    d->y += 16;
    lx__doc_para_at(d, LX__DOC_LEFT, LX__DOC_RIGHT - LX__DOC_LEFT, 10.5, 1, 0, "Contents");
    lx__doc_para_at(d, LX__DOC_LEFT + 12, LX__DOC_RIGHT - LX__DOC_LEFT - 12, 10, 0, 0,
                    "1 Luminaire schedule and maintenance\n2 Rooms\n3 Areas and calculation surfaces\n4 Checks against the "
                    "requirements\n5 Glare (UGR)\n6 Emergency lighting (EN 1838)\n7 Energy (EN 15193-1)\n8 Method and accuracy");
    lx__doc_new_page(d);
    snprintf(d->header, sizeof d->header, "%s - lighting design report", r->title);
}

/* ---- the luminaire schedule ---- */

static void photometry_text(const lx_scene_luminaire *l, char *buf, size_t cap)
{
    switch (l->kind) {
    case LX_SLUM_POINT: snprintf(buf, cap, "isotropic point"); break;
    case LX_SLUM_SPOT: snprintf(buf, cap, "Warn spot, S = %.3g", l->exponent); break;
    case LX_SLUM_DISK: snprintf(buf, cap, "Lambertian disk, r %.3g m", l->radius_m); break;
    case LX_SLUM_RECT: snprintf(buf, cap, "Lambertian panel %.3g x %.3g m", l->width_m, l->length_m); break;
    case LX_SLUM_FILE: {
        const lx_luminaire *L = l->lum;
        const char *cat = L && L->catalog && *L->catalog ? L->catalog : NULL;
        snprintf(buf, cap, "%s%s%s", base_name(l->lum_path), cat ? ": " : "", cat ? cat : "");
        break;
    }
    }
}

/* 1 when luminaires a and b are the same product in the same condition (one schedule row) */
static int same_type(const lx_scene *sc, size_t a, size_t b)
{
    const lx_scene_luminaire *A = &sc->lum[a], *B = &sc->lum[b];
    const lx_scene_design *d = sc->design;
    char pa[200], pb[200];
    photometry_text(A, pa, sizeof pa), photometry_text(B, pb, sizeof pb);
    return A->kind == B->kind && !strcmp(pa, pb) && A->flux_lm == B->flux_lm && d->lum_mf[a] == d->lum_mf[b] &&
           d->lum_mode[a] == d->lum_mode[b] && d->lum_emergency_lm[a] == d->lum_emergency_lm[b] &&
           (d->lum_power_W[a] == d->lum_power_W[b] || (isnan(d->lum_power_W[a]) && isnan(d->lum_power_W[b])));
}

static void schedule(lx__rep *r)
{
    lx__doc *d = &r->doc;
    const lx_scene *sc = r->sc;
    const lx_scene_design *de = sc->design;
    lx__doc_heading(d, 1, "1 Luminaire schedule and maintenance");
    lx__strtab t = {8, 0, 0, NULL, NULL, NULL, 0};
    double total_flux = 0, total_power = 0;
    int power_known = 1;
    for (size_t l = 0; l < sc->n_lum; l++) {
        size_t first = 0;
        while (first < l && !same_type(sc, first, l)) first++;
        if (first < l) continue; /* counted in its type's row */
        size_t count = 0;
        char names[96] = "";
        for (size_t k = l; k < sc->n_lum; k++) {
            if (!same_type(sc, l, k)) continue;
            count++;
            size_t n = strlen(names);
            if (n + strlen(sc->lum[k].name) + 3 < sizeof names) snprintf(names + n, sizeof names - n, "%s%s", n ? ", " : "", sc->lum[k].name);
            else if (n + 4 < sizeof names && !strstr(names, "...")) snprintf(names + n, sizeof names - n, " ...");
        }
        char qty[16], ph[200], flux[32], pw[32], eff[32], mf[32], em[64];
        snprintf(qty, sizeof qty, "%zu", count);
        photometry_text(&sc->lum[l], ph, sizeof ph);
        lx__rep_num(flux, sizeof flux, sc->lum[l].flux_lm, 4, "");
        double P = de->lum_power_W[l];
        lx__rep_num(pw, sizeof pw, P, 3, "");
        lx__rep_num(eff, sizeof eff, P > 0 ? sc->lum[l].flux_lm / P : NAN, 3, "");
        snprintf(mf, sizeof mf, "%.3g", de->lum_mf[l]); /* 3 digits: 0.795 */
        if (de->lum_mode[l] == LX_LUM_NORMAL) snprintf(em, sizeof em, "-");
        else snprintf(em, sizeof em, "%s, %.4g lm", de->lum_mode[l] == LX_LUM_MAINTAINED ? "maintained" : "non-maintained",
                      de->lum_emergency_lm[l]);
        const char *row[8] = {qty, names, ph, flux, pw, eff, mf, em};
        lx__strtab_row(&t, row);
        if (de->lum_mode[l] != LX_LUM_EMERGENCY) {
            total_flux += (double)count * sc->lum[l].flux_lm;
            if (P > 0) total_power += (double)count * P;
            else power_known = 0;
        }
    }
    static const char *const head[8] = {"Qty", "Luminaires", "Photometry", "Flux lm", "Power W", "lm/W", "MF", "Emergency"};
    static const double w[8] = {0.45, 1.7, 3.6, 0.9, 0.9, 0.7, 0.75, 1.6};
    lx__strtab_show(d, &t, head, w, "llllrrrl", 8);
    char buf[400], vt[160];
    values_text(sc, vt, sizeof vt);
    snprintf(buf, sizeof buf, "Flux in normal operation %.5g lm%s%.4g W installed. Illuminances in this report are %s.", total_flux,
             power_known ? ", " : "; ", total_power, vt);
    if (!power_known) snprintf(buf + strlen(buf), sizeof buf - strlen(buf), " (the power of some luminaires is not given)");
    lx__doc_para(d, buf);
    if (!de->n_maint) return;
    lx__doc_heading(d, 2, "Maintenance schemes (CIE 97:2005: MF = LLMF x LSF x LMF x RSMF)");
    lx__strtab m = {8, 0, 0, NULL, NULL, NULL, 0};
    for (size_t i = 0; i < de->n_maint; i++) {
        const lx_maintenance *x = &de->maint[i];
        char v[5][24], cond[200];
        double f[5] = {x->llmf, x->lsf, x->lmf, x->rsmf, x->mf};
        for (int k = 0; k < 5; k++) snprintf(v[k], sizeof v[k], "%.4g", f[k]);
        snprintf(cond, sizeof cond, "%s%s%s", *x->lamp_type ? x->lamp_type : "", *x->luminaire_type ? "; " : "", x->luminaire_type);
        char tm[96] = "";
        if (isfinite(x->burning_h)) snprintf(tm, sizeof tm, "%.6g h", x->burning_h);
        if (isfinite(x->cleaning_a)) snprintf(tm + strlen(tm), sizeof tm - strlen(tm), "%sclean %.3g a", *tm ? ", " : "", x->cleaning_a);
        if (isfinite(x->room_cleaning_a))
            snprintf(tm + strlen(tm), sizeof tm - strlen(tm), "%sroom %.3g a", *tm ? ", " : "", x->room_cleaning_a);
        const char *row[8] = {x->name, v[0], v[1], v[2], v[3], v[4], tm, cond};
        lx__strtab_row(&m, row);
    }
    static const char *const mh[8] = {"Scheme", "LLMF", "LSF", "LMF", "RSMF", "MF", "Times", "Lamp; luminaire"};
    static const double mw[8] = {1.1, 0.6, 0.6, 0.6, 0.65, 0.75, 2.0, 3.4};
    lx__strtab_show(d, &m, mh, mw, "lrrrrrll", 8);
    lx__doc_note(d, "The factors are read off the tables typed in the scene file (from CIE 97:2005 or the lamp maker's data) at "
                    "the scheme's burning hours and cleaning intervals, by linear interpolation.");
}

/* ---- checks ---- */

static void fmt_check(char *buf, size_t cap, const lx_check *k, double v)
{
    int ratio = !*k->unit;
    lx__rep_num(buf, cap, v, ratio ? 3 : 4, k->unit);
}

static void checks(lx__rep *r)
{
    lx__doc *d = &r->doc;
    lx__doc_heading(d, 1, "4 Checks against the requirements");
    if (!r->checks) {
        lx__doc_para(d, "The scene gives no requirements ([requirement] sections).");
        return;
    }
    lx__strtab t = {6, 0, 0, NULL, NULL, NULL, 0};
    for (size_t i = 0; i < r->checks->n; i++) {
        const lx_check *k = &r->checks->check[i];
        char q[64], req[64], val[64];
        snprintf(q, sizeof q, "%s%s", k->quantity, k->emergency ? " (emergency)" : "");
        char num[48];
        fmt_check(num, sizeof num, k, k->required);
        snprintf(req, sizeof req, "%s %s", k->at_most ? "<=" : ">=", num);
        fmt_check(val, sizeof val, k, k->value);
        const char *row[6] = {k->requirement, k->target, q, req, val, k->pass ? "pass" : "FAIL"};
        size_t n = lx__strtab_row(&t, row);
        if (!t.oom) t.bad[n] = !k->pass;
        if (!t.oom && i + 1 < r->checks->n && strcmp(k->requirement, r->checks->check[i + 1].requirement)) t.rule[n] = 1;
    }
    static const char *const head[6] = {"Requirement", "Rated", "Quantity", "Required", "Computed", "Result"};
    static const double w[6] = {1.2, 1.9, 2.0, 1.3, 1.3, 0.6};
    lx__strtab_show(d, &t, head, w, "lllrrl", 8.5);
    char buf[300], vt[160];
    values_text(r->sc, vt, sizeof vt);
    snprintf(buf, sizeof buf, "%zu of %zu checks pass. Computed with %s.", r->checks->n - r->checks->n_fail, r->checks->n, vt);
    lx__doc_para(d, buf);
    /* where the required values come from */
    const char *last = NULL;
    for (size_t i = 0; i < r->checks->n; i++) {
        const lx_check *k = &r->checks->check[i];
        if (!*k->reference || (last && !strcmp(last, k->requirement))) continue;
        last = k->requirement;
        snprintf(buf, sizeof buf, "%s: %s", k->requirement, k->reference);
        lx__doc_note(d, buf);
    }
    lx__doc_note(d, "The required values are typed in the scene file by its author from the standard's tables for the task; "
                    "luxcalc ships no copy of them.");
}

/* ---- energy ---- */

static void energy(lx__rep *r)
{
    lx__doc *d = &r->doc;
    lx__doc_heading(d, 1, "7 Energy (EN 15193-1)");
    if (!r->has_energy) {
        lx__doc_para(d, "The scene gives no [energy] section.");
        return;
    }
    const lx_leni_input *x = &r->ein;
    const lx_leni *e = &r->energy;
    lx__strtab t = {3, 0, 0, NULL, NULL, NULL, 0};
    struct {
        const char *what, *sym;
        double v;
        const char *unit;
    } rows[] = {{"floor area", "A", x->area_m2, "m2"},
                {"installed power, normal operation", "P_n", x->power_W, "W"},
                {"power density", "P_n / A", e->power_density_W_m2, "W/m2"},
                {"operating hours with daylight", "t_D", x->daylight_h, "h"},
                {"operating hours without daylight", "t_N", x->night_h, "h"},
                {"constant illuminance factor", "F_C", x->constant_factor, ""},
                {"occupancy dependency factor", "F_O", x->occupancy_factor, ""},
                {"daylight dependency factor (simplified method)", "F_D", x->daylight_factor, ""},
                {"parasitic power of the controls", "P_pc", x->parasitic_W, "W"},
                {"emergency charging power", "P_em", x->emergency_W, "W"},
                {"lighting energy", "W_L", e->lighting_kWh, "kWh/a"},
                {"parasitic energy", "W_P", e->parasitic_kWh, "kWh/a"},
                {"lighting energy numeric indicator", "LENI", e->leni_kWh_m2, "kWh/(m2 a)"}};
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        char v[48];
        lx__rep_num(v, sizeof v, rows[i].v, 4, rows[i].unit);
        const char *row[3] = {rows[i].what, rows[i].sym, v};
        lx__strtab_row(&t, row);
    }
    static const char *const head[3] = {"Quantity", "Symbol", "Value"};
    static const double w[3] = {4, 1.2, 1.6};
    lx__strtab_show(d, &t, head, w, "llr", 9);
    lx__doc_note(d, "W_L = P_n F_C F_O (t_D F_D + t_N) / 1000; W_P = (P_pc (8760 h - t_D - t_N) + P_em t_em) / 1000; LENI = "
                    "(W_L + W_P) / A. F_D = 1 - F_DS x F_DC by the standard's simplified method, the supply and control factors "
                    "typed from its tables (no annual daylight simulation); F_C = (1 + MF) / 2 under constant illuminance "
                    "control.");
}

/* ---- method and accuracy ---- */

static void effects_table(lx__doc *d, const lx_scene_plan *p)
{
    lx__strtab t = {3, 0, 0, NULL, NULL, NULL, 0};
    for (int e = 0; e < LX_EFFECT_COUNT; e++) {
        const char *row[3] = {lx_effect_name((lx_effect)e), p->on[e] ? (p->forced[e] ? "on (forced)" : "on")
                                                                     : (p->forced[e] ? "off (forced)" : "off"),
                              p->reason[e]};
        lx__strtab_row(&t, row);
    }
    static const char *const head[3] = {"Effect", "", "Why"};
    static const double w[3] = {1.3, 0.8, 6.5};
    lx__strtab_show(d, &t, head, w, "lll", 7.5);
}

static void method(lx__rep *r)
{
    lx__doc *d = &r->doc;
    const lx_scene *sc = r->sc;
    const lx_scene_plan *p = r->plan;
    lx__doc_heading(d, 1, "8 Method and accuracy");
    lx__doc_para(d, "luxcalc simulates only the effects the scene calls for; the planner's decisions and their reasons, in "
                    "normal operation:");
    effects_table(d, p);
    char buf[900];
    double worst = 0;
    size_t kept = 0, decided = 0;
    for (size_t k = 0; k < p->n_pairs; k++)
        if (p->near_why && (p->near_why[k] == LX_NEAR_WITHIN)) kept++, worst = fmax(worst, p->near_err[k]);
        else if (p->near_why && p->near_why[k] != LX_NEAR_NONE) decided++;
    snprintf(buf, sizeof buf,
             "Direct light: every luminaire at every point by the inverse-square and cosine laws with its intensity "
             "distribution; a luminous area is integrated where the point model's estimated error exceeds half of the "
             "near-field tolerance %.3g: %zu of %zu pairs integrated (or in closed form), %zu kept as points with estimated "
             "errors up to %.2g of the point's illuminance.",
             sc->nearfield_tol, p->n_near, p->n_pairs, kept, worst);
    lx__doc_para(d, buf);
    (void)decided;
    if (p->on[LX_EFFECT_INTERREFLECTION]) {
        const lx_scene_room_plan *R = &p->room;
        const lx_scene_room_stats *S = &r->res->room;
        snprintf(buf, sizeof buf,
                 "Interreflection: radiosity on %zu patches of at most %.3g m (%zu elements for the final gather), chosen for "
                 "a tolerance of %.3g on every receiver's total; %.4g lm of %.5g lm reflected flux left unshot when the solve "
                 "stopped; the solve's patches differ from the exact gather at their elements by %.3g %% rms "
                 "(discretisation).",
                 R->n_patches, R->patch_size_m, R->n_elements, R->tolerance, S->unshot_lm, S->indirect_lm + S->unshot_lm,
                 100 * S->gather_check);
        lx__doc_para(d, buf);
    }
    if (r->res->cylindrical_lx) {
        snprintf(buf, sizeof buf,
                 "Cylindrical illuminance: direct light by the point kernel I h (1 + cos phi) / (pi d^3) integrated over luminous "
                 "areas to %.3g; the interreflected part as the mean over azimuth of the gather on vertical planes to %.3g of "
                 "each point's total. Daylight is not included in E_z or the modelling ratio.",
                 sc->nearfield_tol, r->res->cylinder_tol);
        lx__doc_para(d, buf);
    }
    lx__doc_para(d, "Calculation grids: EN 12464-1:2021, p = 0.2 x 5^log10(d) (d the longer side, or the shorter where the "
                    "longer is at least twice it), d / p rounded to the nearest whole number, points at the cells' centres; "
                    "bands (immediate surrounding 0.5 m, background 3 m, escape routes) take d as their width and are "
                    "clipped at the room's walls. Statistics are the arithmetic means and minima over the points.");
    if (r->em_plan) {
        lx__doc_heading(d, 2, "Emergency operation");
        effects_table(d, r->em_plan);
    }
    if (r->glare)
        lx__doc_para(d, "UGR: CIE 117-1995 at each observer position and direction, with new (initial) values as the CIE 190 "
                        "tables are; luminaires without a luminous area (points, spots) do not count.");
    snprintf(buf, sizeof buf, "Evaluated in %.3g s; luxcalc %s.", r->res->seconds, lx_version());
    lx__doc_note(d, buf);
}

/* ---- the report ---- */

lx_status lx_scene_report_write_pdf(lx_ctx *ctx, const lx_scene *sc, const lx_pdf_report_opts *opts, const char *path)
{
    LX__NEED_CTX(ctx);
    if (!sc || !path) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_report_write_pdf: NULL argument");
    lx_pdf_report_opts o;
    memset(&o, 0, sizeof o);
    if (opts) o = *opts;
    lx_status st = lx__check_reserved(ctx, "report options", o.reserved, sizeof o.reserved);
    if (st) return st;
    lx__rep r;
    memset(&r, 0, sizeof r);
    r.ctx = ctx, r.sc = sc, r.imperial = o.imperial, r.project = o.project, r.author = o.author;
    r.title = o.title ? o.title : *sc->title ? sc->title : base_name(sc->file);
    st = lx__doc_open(ctx, &r.doc, path, r.title, r.author); /* a path that cannot be written fails first */
    if (st == LX_OK && (st = evaluate(&r, o.backend)) != LX_OK) st = lx__doc_close(&r.doc, st);
    else if (st == LX_OK) {
        title_page(&r);
        schedule(&r);
        st = lx__rep_plans(&r);
        if (st == LX_OK) st = lx__rep_surfaces(&r);
        if (st == LX_OK) checks(&r);
        if (st == LX_OK) st = lx__rep_glare(&r);
        if (st == LX_OK) lx__rep_emergency(&r);
        if (st == LX_OK) energy(&r);
        if (st == LX_OK) method(&r);
        st = lx__doc_close(&r.doc, st);
    }
    lx_scene_checks_free(r.checks);
    lx_scene_glare_free(r.glare);
    lx_scene_result_free(r.em);
    lx_scene_plan_free(r.em_plan);
    lx_scene_result_free(r.res);
    lx_scene_plan_free(r.plan);
    return st;
}
