/* report_png.c - the one-page PNG report of one spectrum: the SPD with its unit, filled with the
 * colours of its wavelengths; the headline numbers (absolute Y, radiant power, chromaticity, CCT,
 * Duv, colour rendering, melanopic DER); a swatch; CIE 13.3 R1-R14 bars; the chromaticity diagram
 * and the TM-30 vector graphic (report_diagram.c). */
#include "plot/report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PAGE_W 1200
#define PAGE_H 880

static const unsigned char INK[3] = {25, 25, 25}, GREY[3] = {150, 150, 150}, LIGHT[3] = {228, 228, 228},
                           WHITE[3] = {255, 255, 255};

/* the names and units of Y and of the radiant integral for the values' unit */
static int units_of(lx__report *r, const char *unit)
{
    static const struct {
        const char *unit, *y_name, *y_unit, *r_name, *r_unit, *axis;
    } u[] = {
        {"W/nm", "luminous flux", "lm", "radiant flux", "W", "W/nm"},
        {"W/m2/nm", "illuminance", "lx", "irradiance", "W/m\u00b2", "W/(m\u00b2 nm)"},
        {"W/sr/m2/nm", "luminance", "cd/m\u00b2", "radiance", "W/(sr m\u00b2)", "W/(sr m\u00b2 nm)"},
        {"W/sr/nm", "luminous intensity", "cd", "radiant intensity", "W/sr", "W/(sr nm)"},
    };
    r->y_name = "Y (relative)", r->y_unit = "", r->r_name = "radiant (relative)", r->r_unit = "", r->spd_unit = "relative";
    if (!unit || !strcmp(unit, "relative")) return 0;
    for (size_t k = 0; k < sizeof u / sizeof *u; k++)
        if (!strcmp(unit, u[k].unit)) {
            r->y_name = u[k].y_name, r->y_unit = u[k].y_unit, r->r_name = u[k].r_name, r->r_unit = u[k].r_unit;
            r->spd_unit = u[k].axis;
            return 0;
        }
    return -1;
}

static void panel_spd(lx_ctx *ctx, lx__page *pg, const lx_spd *spd, const lx__report *r, lx__box B)
{
    const lx__font fh = {14, 1, {25, 25, 25}, 0}, fk = {11, 0, {25, 25, 25}, 0}, fa = {12, 0, {25, 25, 25}, 0};
    cairo_t *cr = pg->cr;
    lx__page_text(pg, &fh, B.x0 - 56, B.y0 - 26, 0, 0, LX__TEXT_TITLE, NAN, "spectral power distribution");
    double l0 = spd->lambda_nm[0], l1 = spd->lambda_nm[spd->n - 1];
    double a = floor(fmin(380.0, l0) / 10) * 10, b = ceil(fmax(780.0, l1) / 10) * 10, vmax = 0;
    for (size_t i = 0; i < spd->n; i++) vmax = fmax(vmax, spd->value[i]);
    if (!(vmax > 0)) vmax = 1;
    double t[32], step;
    int nt = lx__ticks_linear(0, vmax, 5, t, 32, &step);
    double top = nt ? fmax(vmax, t[nt - 1]) : vmax; /* the axis ends at a round value */
    if (top < vmax * 1.001) top = vmax * 1.05;
    double W = B.x1 - B.x0, H = B.y1 - B.y0;
    cairo_set_line_width(cr, 1);
    int nx = lx__ticks_linear(a, b, (int)(W / 80), t + 16, 16, &step);
    for (int k = 0; k < nx; k++) {
        double x = round(B.x0 + (t[16 + k] - a) / (b - a) * W) + 0.5;
        lx__rgb(cr, LIGHT, 1), cairo_move_to(cr, x, B.y0), cairo_line_to(cr, x, B.y1), cairo_stroke(cr);
        lx__rgb(cr, INK, 1), cairo_move_to(cr, x, B.y1), cairo_line_to(cr, x, B.y1 + 5), cairo_stroke(cr);
        char buf[16];
        lx__fmt_tick(buf, sizeof buf, t[16 + k], step);
        lx__box tb = lx__text_box(pg, &fk, x, B.y1 + 7, 0.5, 0, buf);
        if (lx__page_free_at(pg, tb, 1, (lx__box){0, 0, pg->w, pg->h}))
            lx__page_text(pg, &fk, x, B.y1 + 7, 0.5, 0, LX__TEXT_TICK, t[16 + k], buf);
    }
    nt = lx__ticks_linear(0, top, 5, t, 16, &step);
    for (int k = 0; k < nt; k++) {
        double y = round(B.y1 - t[k] / top * H) + 0.5;
        lx__rgb(cr, LIGHT, 1), cairo_move_to(cr, B.x0, y), cairo_line_to(cr, B.x1, y), cairo_stroke(cr);
        lx__rgb(cr, INK, 1), cairo_move_to(cr, B.x0 - 5, y), cairo_line_to(cr, B.x0, y), cairo_stroke(cr);
        char buf[32];
        lx__fmt_tick(buf, sizeof buf, t[k], step);
        lx__box tb = lx__text_box(pg, &fk, B.x0 - 8, y, 1, 0.5, buf);
        if (lx__page_free_at(pg, tb, 1, (lx__box){0, 0, pg->w, pg->h}))
            lx__page_text(pg, &fk, B.x0 - 8, y, 1, 0.5, LX__TEXT_TICK, t[k], buf);
    }
    lx__page_text(pg, &fa, B.x0 + W / 2, B.y1 + 24, 0.5, 0, LX__TEXT_AXIS, NAN, "wavelength (nm)");
    char ylab[64];
    snprintf(ylab, sizeof ylab, "%s", r->spd_unit);
    lx__page_text_up(pg, &fa, B.x0 - 64, B.y0 + H / 2, LX__TEXT_AXIS, ylab);
    /* the area under the curve, each column in the colour of its wavelength; the curve keeps the
     * largest value over each column's wavelengths, so narrow lines keep their peak */
    int cols = (int)W;
    for (int i = 0; i < cols; i++) {
        double la = a + (double)i / cols * (b - a), lb = a + (i + 1.0) / cols * (b - a), l = 0.5 * (la + lb);
        double v = fmax(lx__interp(spd->lambda_nm, spd->value, spd->n, la), lx__interp(spd->lambda_nm, spd->value, spd->n, lb));
        for (size_t q = 0; q < spd->n; q++)
            if (spd->lambda_nm[q] >= la && spd->lambda_nm[q] < lb) v = fmax(v, spd->value[q]);
        double y = B.y1 - fmax(0, v) / top * H;
        unsigned char c[3];
        lx__wavelength_srgb8(ctx, l, c);
        lx__rgb(cr, c, 1);
        cairo_rectangle(cr, B.x0 + i, y, 1, B.y1 - y);
        cairo_fill(cr);
    }
    /* the curve over the fill */
    lx__rgb(cr, INK, 1);
    cairo_set_line_width(cr, 1.5);
    int started = 0;
    for (int i = 0; i < cols; i++) {
        double la = a + (double)i / cols * (b - a), lb = a + (i + 1.0) / cols * (b - a), l = 0.5 * (la + lb);
        if (l < l0 || l > l1) continue;
        double v = fmax(lx__interp(spd->lambda_nm, spd->value, spd->n, la), lx__interp(spd->lambda_nm, spd->value, spd->n, lb));
        for (size_t q = 0; q < spd->n; q++)
            if (spd->lambda_nm[q] >= la && spd->lambda_nm[q] < lb) v = fmax(v, spd->value[q]);
        (started++ ? cairo_line_to : cairo_move_to)(cr, B.x0 + i + 0.5, B.y1 - fmax(0, v) / top * H);
    }
    cairo_stroke(cr);
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, B.x0 + 0.5, B.y0), cairo_line_to(cr, B.x0 + 0.5, B.y1 + 0.5), cairo_line_to(cr, B.x1, B.y1 + 0.5);
    cairo_stroke(cr);
}

static void panel_cri(lx_ctx *ctx, lx__page *pg, const lx__report *r, lx__box B)
{
    const lx__font fh = {14, 1, {25, 25, 25}, 0}, fk = {11, 0, {25, 25, 25}, 0}, fv = {10, 0, {25, 25, 25}, 0};
    cairo_t *cr = pg->cr;
    char buf[160];
    if (!r->cri_ok) {
        lx__page_text(pg, &fh, B.x0 - 56, B.y0 - 36, 0, 0, LX__TEXT_TITLE, NAN, "CIE 13.3 colour rendering: not defined");
        lx__page_text(pg, &fk, B.x0, B.y0 + 10, 0, 0, LX__TEXT_NOTE, NAN, r->cri_why);
        return;
    }
    snprintf(buf, sizeof buf, "CIE 13.3 colour rendering: Ra %.1f, R9 %.1f%s", r->cri.ra, r->cri.r[8],
             r->cri.valid ? "" : "  (DC > 5.4e-3: Ra not meaningful)");
    lx__page_text(pg, &fh, B.x0 - 56, B.y0 - 36, 0, 0, LX__TEXT_TITLE, NAN, buf);
    double lo = 0, hi = 100, H = B.y1 - B.y0;
    for (int k = 0; k < 14; k++) lo = fmin(lo, r->cri.r[k]);
    lo = fmin(lo, r->cri.r15);
    lo = fmax(-200.0, floor(lo / 50) * 50);
#define VY(v) (B.y0 + (hi - (v)) / (hi - lo) * H)
    cairo_set_line_width(cr, 1);
    for (double v = lo; v <= hi + 1e-9; v += 50) {
        double y = round(VY(v)) + 0.5;
        lx__rgb(cr, v == 0 ? GREY : LIGHT, 1), cairo_move_to(cr, B.x0, y), cairo_line_to(cr, B.x1, y), cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%.0f", v);
        lx__page_text(pg, &fk, B.x0 - 8, y, 1, 0.5, LX__TEXT_TICK, v, buf);
    }
    double slot = (B.x1 - B.x0) / 16, bw = slot * 0.66;
    for (int k = 0; k < 16; k++) { /* Ra, R1-R14, R15 (JIS Z 8726) */
        double v = k == 0 ? r->cri.ra : k == 15 ? r->cri.r15 : r->cri.r[k - 1], vc = fmax(lo, fmin(hi, v));
        unsigned char c[3] = {90, 90, 90};
        if (k) lx__tcs_srgb8(ctx, k - 1, c);
        double x = B.x0 + k * slot + (slot - bw) / 2, y0 = VY(0), y1 = VY(vc);
        double top = fmin(y0, y1), h = fmax(1, fabs(y1 - y0));
        lx__rgb(cr, c, 1), cairo_rectangle(cr, x, top, bw, h), cairo_fill_preserve(cr);
        lx__rgb(cr, INK, 1), cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%.0f", v);
        lx__page_text(pg, &fv, x + bw / 2, v >= 0 ? y1 - 2 : y1 + 2, 0.5, v >= 0 ? 1 : 0, LX__TEXT_LABEL, v, buf);
        snprintf(buf, sizeof buf, k ? "R%d" : "Ra", k);
        lx__page_text(pg, &fk, x + bw / 2, B.y1 + 5, 0.5, 0, LX__TEXT_TICK, NAN, buf);
    }
#undef VY
}

/* name and value in two columns, value right-aligned in its column */
static void row(lx__page *pg, double x, double y, double w, const char *name, const char *value, double num)
{
    const lx__font fn = {13, 0, {70, 70, 70}, 0}, fv = {13, 1, {25, 25, 25}, 0};
    lx__page_text(pg, &fn, x, y, 0, 0, LX__TEXT_STATS, NAN, name);
    lx__page_text(pg, &fv, x + w, y, 1, 0, LX__TEXT_STATS, num, value);
}

static void panel_numbers(lx__page *pg, const lx__report *r, double X0, double Y0)
{
    const lx__font fh = {14, 1, {25, 25, 25}, 0};
    lx__page_text(pg, &fh, X0, Y0, 0, 0, LX__TEXT_TITLE, NAN, "headline numbers");
    const lx_colorimetry *c = &r->col;
    char v[16][64], n[16][64];
    int k = 0;
    snprintf(n[k], 64, "%s", r->y_name), lx__fmt_sig(v[k], 48, c->Y, 4);
    if (*r->y_unit) strcat(v[k], " "), strcat(v[k], r->y_unit);
    k++;
    snprintf(n[k], 64, "%s", r->r_name), lx__fmt_sig(v[k], 48, c->radiant, 4);
    if (*r->r_unit) strcat(v[k], " "), strcat(v[k], r->r_unit);
    k++;
    snprintf(n[k], 64, "x, y"), snprintf(v[k++], 64, "%.5f, %.5f", c->x, c->y);
    snprintf(n[k], 64, "u\u2032, v\u2032"), snprintf(v[k++], 64, "%.5f, %.5f", c->u_prime, c->v_prime);
    snprintf(n[k], 64, "CCT");
    if (c->cct_valid) snprintf(v[k++], 64, "%.1f K", c->cct_K);
    else snprintf(v[k++], 64, "- (|Duv| > 0.05)");
    snprintf(n[k], 64, "Duv");
    if (c->cct_valid) snprintf(v[k++], 64, "%+.5f", c->duv);
    else snprintf(v[k++], 64, "-");
    snprintf(n[k], 64, "CIE Ra, R9");
    if (r->cri_ok) snprintf(v[k++], 64, "%.1f, %.1f", r->cri.ra, r->cri.r[8]);
    else snprintf(v[k++], 64, "-");
    snprintf(n[k], 64, "TM-30 Rf, Rg");
    if (r->tm30_ok) snprintf(v[k++], 64, isfinite(r->tm.rg) ? "%.1f, %.1f" : "%.1f, -", r->tm.rf, r->tm.rg);
    else snprintf(v[k++], 64, "-");
    snprintf(n[k], 64, "melanopic DER");
    if (r->ao_ok && isfinite(r->ao.der[LX_AO_MEL])) snprintf(v[k++], 64, "%.3f", r->ao.der[LX_AO_MEL]);
    else snprintf(v[k++], 64, "-");
    snprintf(n[k], 64, "efficacy (LER)");
    if (isfinite(c->ler_lm_per_W)) lx__fmt_sig(v[k], 48, c->ler_lm_per_W, 4), strcat(v[k++], " lm/W");
    else snprintf(v[k++], 64, "-");
    for (int i = 0; i < k; i++) {
        double col = i < 5 ? 0 : 300, y = Y0 + 24 + (i % 5) * 21;
        row(pg, X0 + col, y, 280, n[i], v[i], NAN);
    }
}

static void swatch(lx__page *pg, const lx__report *r, double x, double y)
{
    const lx__font fk = {11, 0, {25, 25, 25}, 0};
    cairo_t *cr = pg->cr;
    lx__page_text(pg, &fk, x, y, 0, 0, LX__TEXT_NOTE, NAN, "colour of the light");
    double xyz[3] = {r->col.X, r->col.Y, r->col.Z};
    unsigned char sw[3];
    lx__xyz_to_srgb8(xyz, sw);
    lx__box b = {x, y + 18, x + 90, y + 108};
    if (r->col.Y > 0) lx__rgb(cr, sw, 1), cairo_rectangle(cr, b.x0, b.y0, 90, 90), cairo_fill(cr);
    lx__rgb(cr, INK, 1);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, b.x0 - 0.5, b.y0 - 0.5, 91, 91);
    cairo_stroke(cr);
    lx__page_keep(pg, b);
    char hex[16];
    snprintf(hex, sizeof hex, r->col.Y > 0 ? "#%02X%02X%02X" : "none", sw[0], sw[1], sw[2]);
    lx__page_text(pg, &fk, x, b.y1 + 6, 0, 0, LX__TEXT_NOTE, NAN, hex);
}

/* colorimetry and the metrics; an undefined metric keeps its reason (only memory failures abort) */
static lx_status compute(lx_ctx *ctx, const lx_spd *spd, lx__report *r)
{
    lx_status st = lx_spd_colorimetry(ctx, spd, r->obs, LX_METHOD_AUTO, &r->col);
    if (st) return st;
    st = lx_cri_compute(ctx, spd, &r->cri);
    r->cri_ok = st == LX_OK;
    if (!r->cri_ok) snprintf(r->cri_why, sizeof r->cri_why, "%s", lx_ctx_errmsg(ctx));
    if (st == LX_ENOMEM) return st;
    st = lx_tm30_compute(ctx, spd, &r->tm);
    r->tm30_ok = st == LX_OK;
    if (!r->tm30_ok) snprintf(r->tm30_why, sizeof r->tm30_why, "%s", lx_ctx_errmsg(ctx));
    if (st == LX_ENOMEM) return st;
    r->ao_ok = lx_alphaopic_compute(ctx, spd, LX_METHOD_AUTO, &r->ao) == LX_OK;
    return LX_OK;
}

lx_status lx__report_png(lx_ctx *ctx, const lx_spd *spd, const lx_report_opts *opts, const char *path, lx__layout *out)
{
    if (!spd || !path) return lx__error(ctx, LX_EINVAL, NULL, 0, "spectrum report: NULL argument");
    lx_report_opts o = {0};
    if (opts) o = *opts;
    lx_status rs = lx__check_reserved(ctx, "report options", o.reserved, sizeof o.reserved);
    if (rs) return rs;
    if (o.observer == 0) o.observer = LX_OBSERVER_2;
    if (o.observer != LX_OBSERVER_2 && o.observer != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "spectrum report: observer must be 2 or 10");
    if (o.diagram != LX_DIAGRAM_XY && o.diagram != LX_DIAGRAM_UV)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "spectrum report: unknown diagram %d", (int)o.diagram);
    lx_status st = lx_spd_check(ctx, spd);
    if (st) return st;
    lx__report *r = lx__calloc(1, sizeof *r);
    if (!r) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    r->obs = o.observer;
    r->diagram = o.diagram;
    if (units_of(r, o.unit)) {
        st = lx__error(ctx, LX_EINVAL, NULL, 0, "spectrum report: unknown unit '%s' (relative, W/nm, W/m2/nm, W/sr/m2/nm, W/sr/nm)", o.unit);
        goto out;
    }
    if ((st = compute(ctx, spd, r))) goto out;
    lx__page pg;
    if ((st = lx__page_init(ctx, &pg, PAGE_W, PAGE_H, WHITE))) goto out;
    const lx__font fh = {20, 1, {20, 20, 20}, 0}, fs = {12, 0, {100, 100, 100}, 0};
    const char *t = o.title ? o.title : spd->name ? spd->name : "";
    char head[200], sub[160];
    snprintf(head, sizeof head, "Spectrum report%s%.120s", *t ? " \u2014 " : "", t);
    lx__page_text(&pg, &fh, 24, 14, 0, 0, LX__TEXT_TITLE, NAN, head);
    snprintf(sub, sizeof sub, "CIE %s %s\u00b0 observer \u00b7 %s%s \u00b7 %zu samples, %.4g\u2013%.4g nm",
             r->obs == LX_OBSERVER_10 ? "1964" : "1931", r->obs == LX_OBSERVER_10 ? "10" : "2",
             strcmp(r->spd_unit, "relative") ? "values in " : "relative values", strcmp(r->spd_unit, "relative") ? r->spd_unit : "", spd->n,
             spd->lambda_nm[0], spd->lambda_nm[spd->n - 1]);
    lx__page_text(&pg, &fs, 24, 42, 0, 0, LX__TEXT_TITLE, NAN, sub);
    cairo_set_line_width(pg.cr, 1);
    lx__rgb(pg.cr, GREY, 1);
    cairo_move_to(pg.cr, 24, 64.5), cairo_line_to(pg.cr, PAGE_W - 24, 64.5), cairo_stroke(pg.cr);
    panel_spd(ctx, &pg, spd, r, (lx__box){104, 110, 650, 330});
    panel_cri(ctx, &pg, r, (lx__box){104, 420, 650, 580});
    panel_numbers(&pg, r, 48, 636);
    if ((st = lx__report_diagram(ctx, &pg, r, (lx__box){700, 84, 1176, 540}))) goto page;
    lx__report_cvg(&pg, r, 860, 720, 88);
    swatch(&pg, r, 1060, 600);
    st = lx__page_write_png(ctx, &pg, path);
    if (!st && out) lx__page_take_layout(&pg, out);
page:
    lx__page_free(&pg);
out:
    lx__free(r);
    return st;
}

lx_status lx_spd_report_write_png(lx_ctx *ctx, const lx_spd *spd, const lx_report_opts *opts, const char *path)
{
    LX__NEED_CTX(ctx);
    return lx__report_png(ctx, spd, opts, path, NULL);
}
