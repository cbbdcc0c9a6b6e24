/* report_tm30.c - the ANSI/IES TM-30-20 colour rendition report as the IES calculator prints it:
 * the test and reference spectra at equal luminous flux, the colour vector graphic with its
 * arrows (arrowheads in the bins' colours), the local chroma shift, hue shift and fidelity of the
 * 16 hue bins as bar charts, the fidelity of the 99 colour evaluation samples, and the numbers. The
 * vector graphic is drawn here for the spectrum report too. */
#include "plot/report.h"
#include "colour/colour_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PAGE_W 1200
#define PAGE_H 1080

static const unsigned char INK[3] = {25, 25, 25}, GREY[3] = {150, 150, 150}, LIGHT[3] = {228, 228, 228},
                           WHITE[3] = {255, 255, 255}, TEST_RED[3] = {240, 80, 70};

/* The hue bins' colours of the IES TM-30-20 calculator (bars, and the arrows of the vector
 * graphic), as colour-science 0.4.7 copies them (colour/plotting/tm3018/components.py). */
static const unsigned int BIN_BAR[16] = {0xA35C60, 0xCC765E, 0xCC8145, 0xD8AC62, 0xAC9959, 0x919E5D, 0x668B5E, 0x61B290,
                                         0x7BBAA6, 0x297A7E, 0x55788D, 0x708AB2, 0x988CAA, 0x735877, 0x8F6682, 0xBA7A8E};
static const unsigned int BIN_ARROW[16] = {0xE62828, 0xE74B4B, 0xFB812E, 0xFFB529, 0xCBCA46, 0x7EB94C, 0x41C06D, 0x009C7C,
                                           0x16BCB0, 0x00A4BF, 0x0085C3, 0x3B62AA, 0x4568AE, 0x6A4E85, 0x9D69A1, 0xA74F81};

void lx__tm30_bin_rgb(int bin, int arrow, unsigned char rgb[3])
{
    unsigned int c = (arrow ? BIN_ARROW : BIN_BAR)[bin & 15];
    rgb[0] = (unsigned char)(c >> 16), rgb[1] = (unsigned char)(c >> 8), rgb[2] = (unsigned char)c;
}

/* an arrow from (x0, y0) to (x1, y1), its head a filled triangle at the tip; a dot when shorter
 * than its head */
static void arrow(cairo_t *cr, double x0, double y0, double x1, double y1, double head)
{
    double dx = x1 - x0, dy = y1 - y0, n = hypot(dx, dy);
    if (n < 0.8 * head) {
        cairo_arc(cr, x1, y1, 0.3 * head, 0, 2 * LX__PI);
        cairo_fill(cr);
        return;
    }
    dx /= n, dy /= n;
    double bx = x1 - head * dx, by = y1 - head * dy, w = 0.45 * head;
    cairo_move_to(cr, x0, y0), cairo_line_to(cr, bx, by);
    cairo_stroke(cr);
    cairo_move_to(cr, x1, y1);
    cairo_line_to(cr, bx - w * dy, by + w * dx);
    cairo_line_to(cr, bx + w * dy, by - w * dx);
    cairo_close_path(cr);
    cairo_fill(cr);
}

int lx__tm30_cvg(lx__page *pg, const lx_tm30 *tm, double cx, double cy, double R, int full)
{
    const lx__font fb = {full ? 11 : 9, 1, {150, 150, 150}, 0}, fw = {9, 0, {80, 80, 80}, 0};
    cairo_t *cr = pg->cr;
    char buf[16];
    double lim = 1.45 * R;
    /* the 16 hue bins as wedges in their colours, numbered around the outside */
    for (int b = 0; b < 16; b++) {
        unsigned char c[3];
        lx__tm30_bin_rgb(b, 0, c);
        lx__rgb(cr, c, 0.35);
        cairo_move_to(cr, cx, cy);
        cairo_arc_negative(cr, cx, cy, lim, -b * 22.5 * LX__PI / 180, -(b + 1) * 22.5 * LX__PI / 180);
        cairo_close_path(cr);
        cairo_fill(cr);
        double a = (b + 0.5) * 22.5 * LX__PI / 180;
        snprintf(buf, sizeof buf, "%d", b + 1);
        lx__page_text(pg, &fb, cx + (lim + 10) * cos(a), cy - (lim + 10) * sin(a), 0.5, 0.5, LX__TEXT_LABEL, b + 1, buf);
    }
    /* the bins' borders, dashed; the +-10 % and +-20 % circles white, the reference black */
    const double dash[2] = {4, 3};
    lx__rgb(cr, GREY, 1);
    cairo_set_line_width(cr, 0.8);
    cairo_set_dash(cr, dash, 2, 0);
    for (int b = 0; b < 16; b++) {
        double a = b * 22.5 * LX__PI / 180;
        cairo_move_to(cr, cx + 0.1 * R * cos(a), cy - 0.1 * R * sin(a)), cairo_line_to(cr, cx + lim * cos(a), cy - lim * sin(a));
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    lx__rgb(cr, WHITE, 1);
    for (int k = 0; k < 4; k++) {
        static const double rr[4] = {0.8, 0.9, 1.1, 1.2};
        cairo_arc(cr, cx, cy, rr[k] * R, 0, 2 * LX__PI);
        cairo_stroke(cr);
    }
    if (full) {
        lx__page_text(pg, &fw, cx - 3, cy + 0.8 * R - 2, 1, 1, LX__TEXT_NOTE, NAN, "-20%");
        lx__page_text(pg, &fw, cx - 3, cy + 1.2 * R + 2, 1, 0, LX__TEXT_NOTE, NAN, "+20%");
    }
    lx__rgb(cr, INK, 1);
    cairo_set_line_width(cr, 1.6);
    cairo_arc(cr, cx, cy, R, 0, 2 * LX__PI);
    cairo_stroke(cr);
    double pt[16][2];
    for (int b = 0; b < 16; b++) {
        if (!isfinite(tm->ref_ab[b][0] + tm->test_ab[b][0])) return 0; /* a bin without samples */
        lx__cvg_point(tm->ref_ab[b], tm->test_ab[b], pt[b]);
    }
    /* the test's shape, then the arrows from the reference on the circle to the test, each with
     * its head, in its bin's colour */
    lx__rgb(cr, TEST_RED, 1);
    cairo_set_line_width(cr, full ? 2.4 : 2);
    for (int b = 0; b <= 16; b++) (b ? cairo_line_to : cairo_move_to)(cr, cx + R * pt[b % 16][0], cy - R * pt[b % 16][1]);
    cairo_stroke(cr);
    cairo_set_line_width(cr, full ? 1.8 : 1.4);
    for (int b = 0; b < 16; b++) {
        unsigned char c[3];
        lx__tm30_bin_rgb(b, 1, c);
        lx__rgb(cr, c, 1);
        double h = atan2(tm->ref_ab[b][1], tm->ref_ab[b][0]);
        arrow(cr, cx + R * cos(h), cy - R * sin(h), cx + R * pt[b][0], cy - R * pt[b][1], full ? 11 : 8);
        if (pg->lay.n_arrows < 16) { /* the arrows, for tests */
            double *q = pg->lay.arrow[pg->lay.n_arrows++];
            q[0] = cx + R * cos(h), q[1] = cy - R * sin(h), q[2] = cx + R * pt[b][0], q[3] = cy - R * pt[b][1], q[4] = b;
        }
    }
    return 1;
}

/* A chart of the 16 bins: bars from zero in the bins' colours, each value on its bar, y ticks at
 * the given step (suffix after each tick value), the bins numbered below (label: the axis title). */
static void bin_chart(lx__page *pg, lx__box B, const double *v, double lo, double hi, double step, const char *fmt,
                      const char *tick_suffix, const char *title, int numbers)
{
    const lx__font fh = {13, 1, {25, 25, 25}, 0}, fk = {10, 0, {25, 25, 25}, 0}, fv = {9, 0, {25, 25, 25}, 0};
    cairo_t *cr = pg->cr;
    lx__page_text(pg, &fh, B.x0 - 44, B.y0 - 28, 0, 0, LX__TEXT_TITLE, NAN, title);
    double H = B.y1 - B.y0, W = B.x1 - B.x0;
#define VY(x) (B.y0 + (hi - (x)) / (hi - lo) * H)
    cairo_set_line_width(cr, 1);
    char buf[32];
    for (double t = lo; t <= hi + 1e-9 * step; t += step) {
        double y = round(VY(t)) + 0.5;
        lx__rgb(cr, fabs(t) < 1e-9 * step ? GREY : LIGHT, 1);
        cairo_move_to(cr, B.x0, y), cairo_line_to(cr, B.x1, y), cairo_stroke(cr);
        lx__fmt_tick(buf, sizeof buf - 4, fabs(t) < 1e-9 * step ? 0 : t, step);
        strcat(buf, tick_suffix);
        lx__page_text(pg, &fk, B.x0 - 6, y, 1, 0.5, LX__TEXT_TICK, t, buf);
    }
    double slot = W / 16, bw = slot * 0.8;
    for (int b = 0; b < 16; b++) {
        double x = B.x0 + b * slot + (slot - bw) / 2;
        unsigned char c[3];
        lx__tm30_bin_rgb(b, 0, c);
        if (isfinite(v[b])) {
            double vc = fmax(lo, fmin(hi, v[b])), y0 = VY(fmax(lo, fmin(hi, 0))), y1 = VY(vc);
            lx__rgb(cr, c, 1);
            cairo_rectangle(cr, x, fmin(y0, y1), bw, fmax(1, fabs(y1 - y0)));
            cairo_fill(cr);
            snprintf(buf, sizeof buf, fmt, v[b]);
            if (buf[0] == '-' && strtod(buf + 1, NULL) == 0) memmove(buf, buf + 1, strlen(buf)); /* "0%", not "-0%" */
            int up = v[b] >= 0;
            double ty = up ? y1 - 2 : y1 + 2;
            if (up && ty - 11 < B.y0) ty = y1 + 2, up = 0; /* a full bar: the value inside it */
            else if (!up && ty + 11 > B.y1) ty = y1 - 2, up = 1;
            lx__page_text(pg, &fv, x + bw / 2, ty, 0.5, up ? 1 : 0, LX__TEXT_LABEL, v[b], buf);
        }
        if (numbers) {
            snprintf(buf, sizeof buf, "%d", b + 1);
            lx__page_text(pg, &fk, x + bw / 2, B.y1 + 4, 0.5, 0, LX__TEXT_TICK, b + 1, buf);
        }
    }
#undef VY
    if (numbers) lx__page_text(pg, &fk, B.x0 + W / 2, B.y1 + 18, 0.5, 0, LX__TEXT_AXIS, NAN, "hue-angle bin (j)");
    lx__rgb(cr, INK, 1);
    cairo_move_to(cr, B.x0 + 0.5, B.y0), cairo_line_to(cr, B.x0 + 0.5, B.y1 + 0.5);
    cairo_stroke(cr);
}

/* the test and its reference at equal luminous flux, 380-780 nm */
static void panel_spectra(lx_ctx *ctx, lx__page *pg, const lx_spd *spd, const lx_tm30 *tm, lx__box B)
{
    const lx__font fh = {13, 1, {25, 25, 25}, 0}, fk = {10, 0, {25, 25, 25}, 0}, fl = {11, 0, {25, 25, 25}, 0};
    cairo_t *cr = pg->cr;
    lx__page_text(pg, &fh, B.x0 - 44, B.y0 - 22, 0, 0, LX__TEXT_TITLE, NAN, "test and reference at equal luminous flux");
    double ref[401], test[401], ybar[401], yr = 0, yt = 0;
    lx_spd yb;
    if (lx__tm30_reference_1nm(ctx, tm->cct_K, ref) || lx_function_get(ctx, LX_FN_YBAR_2, &yb)) return;
    for (int i = 0; i < 401; i++) {
        ybar[i] = lx__interp(yb.lambda_nm, yb.value, yb.n, 380 + i);
        test[i] = lx__interp(spd->lambda_nm, spd->value, spd->n, 380 + i);
        if (380 + i < spd->lambda_nm[0] || 380 + i > spd->lambda_nm[spd->n - 1]) test[i] = 0;
        yr += ref[i] * ybar[i], yt += test[i] * ybar[i];
    }
    double top = 0;
    for (int i = 0; i < 401; i++) {
        ref[i] /= yr, test[i] = yt > 0 ? test[i] / yt : 0;
        top = fmax(top, fmax(ref[i], test[i]));
    }
    top *= 1.05;
    double W = B.x1 - B.x0, H = B.y1 - B.y0;
    cairo_set_line_width(cr, 1);
    for (int l = 400; l <= 780; l += 50) {
        double x = round(B.x0 + (l - 380) / 400.0 * W) + 0.5;
        lx__rgb(cr, LIGHT, 1), cairo_move_to(cr, x, B.y0), cairo_line_to(cr, x, B.y1), cairo_stroke(cr);
        char buf[8];
        snprintf(buf, sizeof buf, "%d", l);
        if (l % 100 == 0) lx__page_text(pg, &fk, x, B.y1 + 4, 0.5, 0, LX__TEXT_TICK, l, buf);
    }
    lx__page_text(pg, &fk, B.x0 + W / 2, B.y1 + 18, 0.5, 0, LX__TEXT_AXIS, NAN, "wavelength (nm)");
    for (int k = 0; k < 2; k++) {
        const double *v = k ? test : ref;
        lx__rgb(cr, k ? TEST_RED : INK, 1);
        cairo_set_line_width(cr, k ? 2 : 1.6);
        for (int i = 0; i < 401; i++) (i ? cairo_line_to : cairo_move_to)(cr, B.x0 + i / 400.0 * W, B.y1 - v[i] / top * H);
        cairo_stroke(cr);
    }
    lx__rgb(cr, INK, 1);
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, B.x0 + 0.5, B.y0), cairo_line_to(cr, B.x0 + 0.5, B.y1 + 0.5), cairo_line_to(cr, B.x1, B.y1 + 0.5);
    cairo_stroke(cr);
    /* the key */
    double kx = B.x1 - 150, ky = B.y0 + 6;
    lx__rgb(cr, INK, 1), cairo_set_line_width(cr, 1.6), cairo_move_to(cr, kx, ky + 6), cairo_line_to(cr, kx + 24, ky + 6);
    cairo_stroke(cr);
    lx__page_text(pg, &fl, kx + 30, ky, 0, 0, LX__TEXT_NOTE, NAN, "reference");
    lx__rgb(cr, TEST_RED, 1), cairo_set_line_width(cr, 2), cairo_move_to(cr, kx, ky + 24), cairo_line_to(cr, kx + 24, ky + 24);
    cairo_stroke(cr);
    lx__page_text(pg, &fl, kx + 30, ky + 18, 0, 0, LX__TEXT_NOTE, NAN, "test");
}

/* the fidelity of the 99 colour evaluation samples, each bar in the sample's colour under D65 */
static void panel_ces(lx_ctx *ctx, lx__page *pg, const lx_tm30 *tm, lx__box B)
{
    const lx__font fh = {13, 1, {25, 25, 25}, 0}, fk = {10, 0, {25, 25, 25}, 0}, fs = {8, 0, {60, 60, 60}, 0};
    cairo_t *cr = pg->cr;
    lx__page_text(pg, &fh, B.x0 - 44, B.y0 - 28, 0, 0, LX__TEXT_TITLE, NAN, "colour sample fidelity Rf,CESi");
    double H = B.y1 - B.y0, W = B.x1 - B.x0, slot = W / 99;
    cairo_set_line_width(cr, 1);
    for (int t = 0; t <= 100; t += 20) {
        double y = round(B.y1 - t / 100.0 * H) + 0.5;
        lx__rgb(cr, t ? LIGHT : GREY, 1), cairo_move_to(cr, B.x0, y), cairo_line_to(cr, B.x1, y), cairo_stroke(cr);
        char buf[8];
        snprintf(buf, sizeof buf, "%d", t);
        lx__page_text(pg, &fk, B.x0 - 6, y, 1, 0.5, LX__TEXT_TICK, t, buf);
    }
    const lx__table *tc = lx__table_find("ies_tm30_ces_1nm");
    for (int s = 0; s < 99; s++) {
        unsigned char c[3] = {120, 120, 120};
        if (tc) lx__refl_srgb8(ctx, tc, s + 1, c);
        double v = fmax(0, fmin(100, tm->rf_ces[s])), x = B.x0 + s * slot + 0.1 * slot;
        lx__rgb(cr, c, 1);
        cairo_rectangle(cr, x, B.y1 - v / 100 * H, 0.8 * slot, v / 100 * H);
        cairo_fill(cr);
        if (s % 3 == 0) {
            char buf[8];
            snprintf(buf, sizeof buf, "%d", s + 1);
            lx__page_text(pg, &fs, x + 0.4 * slot, B.y1 + 3, 0.5, 0, LX__TEXT_TICK, s + 1, buf);
        }
    }
    lx__page_text(pg, &fk, B.x0 + W / 2, B.y1 + 16, 0.5, 0, LX__TEXT_AXIS, NAN, "colour evaluation sample (CES)");
}

lx_status lx__tm30_png(lx_ctx *ctx, const lx_spd *spd, const lx_report_opts *opts, const char *path, lx__layout *out)
{
    if (!spd || !path) return lx__error(ctx, LX_EINVAL, NULL, 0, "TM-30 report: NULL argument");
    lx_report_opts o = {0};
    if (opts) o = *opts;
    lx_status st = lx__check_reserved(ctx, "report options", o.reserved, sizeof o.reserved);
    if (st) return st;
    if ((st = lx_spd_check(ctx, spd))) return st;
    lx_tm30 *tm = lx__calloc(1, sizeof *tm);
    if (!tm) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    lx_colorimetry col;
    lx_cri cri;
    int cri_ok = 0;
    if ((st = lx_tm30_compute(ctx, spd, tm))) goto out; /* the page is TM-30's: undefined is an error */
    if ((st = lx_spd_colorimetry(ctx, spd, LX_OBSERVER_2, LX_METHOD_AUTO, &col))) goto out;
    cri_ok = lx_cri_compute(ctx, spd, &cri) == LX_OK;
    lx__page pg;
    if ((st = lx__page_init(ctx, &pg, PAGE_W, PAGE_H, WHITE))) goto out;
    const lx__font fh = {20, 1, {20, 20, 20}, 0}, fs = {12, 0, {100, 100, 100}, 0}, fbig = {28, 1, {20, 20, 20}, 0},
                   fsm = {12, 0, {60, 60, 60}, 0}, fn = {13, 0, {70, 70, 70}, 0}, fv = {13, 1, {25, 25, 25}, 0};
    const char *t = o.title ? o.title : spd->name ? spd->name : "";
    char buf[200];
    snprintf(buf, sizeof buf, "ANSI/IES TM-30-20 colour rendition report%s%.110s", *t ? " \u2014 " : "", t);
    lx__page_text(&pg, &fh, 24, 14, 0, 0, LX__TEXT_TITLE, NAN, buf);
    snprintf(buf, sizeof buf, "CIE 224:2017 / TM-30-20: CAM02-UCS, 99 colour evaluation samples (CIE 1964 10\u00b0), "
             "reference %s at the CCT", tm->cct_K < 4000 ? "Planckian" : tm->cct_K >= 5000 ? "CIE daylight" : "a Planckian-daylight mix");
    lx__page_text(&pg, &fs, 24, 42, 0, 0, LX__TEXT_TITLE, NAN, buf);
    cairo_set_line_width(pg.cr, 1);
    lx__rgb(pg.cr, GREY, 1);
    cairo_move_to(pg.cr, 24, 64.5), cairo_line_to(pg.cr, PAGE_W - 24, 64.5), cairo_stroke(pg.cr);
    /* left: the spectra, the vector graphic with Rf, Rg, CCT and Duv at its corners */
    panel_spectra(ctx, &pg, spd, tm, (lx__box){84, 104, 560, 280});
    double cx = 322, cy = 560, R = 130, lim = 1.45 * R;
    lx__page_text(&pg, &(lx__font){13, 1, {25, 25, 25}, 0}, 40, cy - lim - 46, 0, 0, LX__TEXT_TITLE, NAN, "colour vector graphic");
    if (!lx__tm30_cvg(&pg, tm, cx, cy, R, 1))
        lx__page_text(&pg, &fn, cx - R, cy + lim + 24, 0, 0, LX__TEXT_NOTE, NAN, "a hue bin holds no sample: no vector graphic");
    snprintf(buf, sizeof buf, "%.0f", tm->rf);
    lx__page_text(&pg, &fbig, cx - lim - 16, cy - lim - 22, 0, 0, LX__TEXT_STATS, tm->rf, buf);
    lx__page_text(&pg, &fsm, cx - lim - 16, cy - lim + 12, 0, 0, LX__TEXT_NOTE, NAN, "Rf");
    snprintf(buf, sizeof buf, "%.0f", tm->rg);
    lx__page_text(&pg, &fbig, cx + lim + 16, cy - lim - 22, 1, 0, LX__TEXT_STATS, tm->rg, isfinite(tm->rg) ? buf : "-");
    lx__page_text(&pg, &fsm, cx + lim + 16, cy - lim + 12, 1, 0, LX__TEXT_NOTE, NAN, "Rg");
    snprintf(buf, sizeof buf, "%.0f K", tm->cct_K);
    lx__page_text(&pg, &fsm, cx - lim - 16, cy + lim - 16, 0, 1, LX__TEXT_NOTE, NAN, "CCT");
    lx__page_text(&pg, &(lx__font){18, 1, {20, 20, 20}, 0}, cx - lim - 16, cy + lim + 8, 0, 1, LX__TEXT_STATS, tm->cct_K, buf);
    snprintf(buf, sizeof buf, "%.4f", tm->duv);
    lx__page_text(&pg, &fsm, cx + lim + 16, cy + lim - 16, 1, 1, LX__TEXT_NOTE, NAN, "Duv");
    lx__page_text(&pg, &(lx__font){18, 1, {20, 20, 20}, 0}, cx + lim + 16, cy + lim + 8, 1, 1, LX__TEXT_STATS, tm->duv, buf);
    /* right: the three hue-bin charts, as the calculator stacks them */
    bin_chart(&pg, (lx__box){684, 104, 1170, 264}, tm->rcs_hue, -40, 40, 10, "%.0f%%", "%",
              "local chroma shift Rcs,hj", 0);
    bin_chart(&pg, (lx__box){684, 318, 1170, 478}, tm->rhs_hue, -0.5, 0.5, 0.1, "%.2f", "",
              "local hue shift Rhs,hj", 0);
    bin_chart(&pg, (lx__box){684, 532, 1170, 692}, tm->rf_hue, 0, 100, 20, "%.0f", "",
              "local colour fidelity Rf,hj", 1);
    /* below: the 99 samples, then the numbers */
    panel_ces(ctx, &pg, tm, (lx__box){84, 800, 1170, 960});
    double y = 1000, x0 = 48, w = 230;
    struct {
        const char *name;
        char value[48];
        double num;
    } rows[8];
    snprintf(rows[0].value, 48, "%.1f", tm->rf), rows[0].name = "fidelity Rf", rows[0].num = tm->rf;
    snprintf(rows[1].value, 48, isfinite(tm->rg) ? "%.1f" : "-", tm->rg), rows[1].name = "gamut Rg", rows[1].num = tm->rg;
    snprintf(rows[2].value, 48, "%.0f K", tm->cct_K), rows[2].name = "CCT", rows[2].num = tm->cct_K;
    snprintf(rows[3].value, 48, "%+.4f", tm->duv), rows[3].name = "Duv", rows[3].num = tm->duv;
    snprintf(rows[4].value, 48, "%.4f, %.4f", col.x, col.y), rows[4].name = "x, y", rows[4].num = NAN;
    snprintf(rows[5].value, 48, "%.4f, %.4f", col.u_prime, col.v_prime), rows[5].name = "u\u2032, v\u2032", rows[5].num = NAN;
    snprintf(rows[6].value, 48, cri_ok ? "%.0f" : "-", cri_ok ? cri.ra : NAN), rows[6].name = "CIE 13.3 Ra", rows[6].num = NAN;
    snprintf(rows[7].value, 48, cri_ok ? "%.0f" : "-", cri_ok ? cri.r[8] : NAN), rows[7].name = "CIE 13.3 R9", rows[7].num = NAN;
    for (int k = 0; k < 8; k++) {
        double x = x0 + (k / 2) * (w + 54), yy = y + (k % 2) * 24;
        lx__page_text(&pg, &fn, x, yy, 0, 0, LX__TEXT_STATS, NAN, rows[k].name);
        lx__page_text(&pg, &fv, x + w, yy, 1, 0, LX__TEXT_STATS, rows[k].num, rows[k].value);
    }
    lx__page_text(&pg, &(lx__font){10, 0, {120, 120, 120}, 0}, 24, PAGE_H - 22, 0, 0, LX__TEXT_NOTE, NAN,
                  "Colours of the bins and samples are for orientation only (sRGB under D65).");
    st = lx__page_write_png(ctx, &pg, path);
    if (!st && out) lx__page_take_layout(&pg, out);
    lx__page_free(&pg);
out:
    lx__free(tm);
    return st;
}

lx_status lx_tm30_report_write_png(lx_ctx *ctx, const lx_spd *spd, const lx_report_opts *opts, const char *path)
{
    LX__NEED_CTX(ctx);
    return lx__tm30_png(ctx, spd, opts, path, NULL);
}
