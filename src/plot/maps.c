/* maps.c - pictures of maps: the false-colour plot of a value map (luminance-map), tone-mapped
 * previews of environment maps side by side, and the irradiance preview (input tone-mapped,
 * output as illuminance in false colour with its legend). */
#include "plot/plot_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const unsigned char WHITE[3] = {255, 255, 255};

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* min, median and max of the finite values ("min 0 - median 89.5 - max 179 cd/m²") */
static lx_status summary(lx_ctx *ctx, const double *v, size_t n, const char *unit, char *buf, size_t cap)
{
    double *s = lx__alloc_n(n ? n : 1, sizeof *s);
    if (!s) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(v[i])) s[m++] = v[i];
    if (!m) {
        snprintf(buf, cap, "no finite values");
        lx__free(s);
        return LX_OK;
    }
    qsort(s, m, sizeof *s, cmp_double);
    char a[32], b[32], c[32];
    lx__fmt_sig(a, sizeof a, s[0], 4);
    lx__fmt_sig(b, sizeof b, m % 2 ? s[m / 2] : 0.5 * (s[m / 2 - 1] + s[m / 2]), 4);
    lx__fmt_sig(c, sizeof c, s[m - 1], 4);
    snprintf(buf, cap, "min %s  \u00b7  median %s  \u00b7  max %s%s%s", a, b, c, unit && *unit ? " " : "", unit ? unit : "");
    lx__free(s);
    return LX_OK;
}

static void legend_title(char *buf, size_t cap, const char *quantity, const char *unit)
{
    if (quantity && *quantity && unit && *unit) snprintf(buf, cap, "%s (%s)", quantity, unit);
    else snprintf(buf, cap, "%s", quantity && *quantity ? quantity : unit ? unit : "");
}

lx_status lx__falsecolor_png(lx_ctx *ctx, const char *path, int w, int h, const double *values,
                             const lx_falsecolor_opts *opts, lx__layout *out)
{
    if (!path || !values || w < 1 || h < 1) return lx__error(ctx, LX_EINVAL, NULL, 0, "false-colour plot: no values");
    lx_falsecolor_opts o = {0};
    if (opts) o = *opts;
    lx_status rs = lx__check_reserved(ctx, "false-colour options", o.reserved, sizeof o.reserved);
    if (rs) return rs;
    lx__scale s;
    int log = o.scale != LX_PLOT_SCALE_LINEAR;
    double lo = o.hi > o.lo && (!log || o.lo > 0) ? o.lo : NAN, hi = o.hi > o.lo ? o.hi : NAN;
    double above_max;
    size_t above = lx__scale_auto_map(&s, values, (size_t)w * h, log, lo, hi, &above_max);
    /* the map enlarged by a whole factor to at least 512 pixels wide, reduced beyond 1600 x 1200 */
    double k = w >= 512 ? 1 : ceil(512.0 / w);
    double iw = w * k, ih = h * k;
    if (iw > 1600) ih *= 1600 / iw, iw = 1600;
    if (ih > 1200) iw *= 1200 / ih, ih = 1200;
    iw = fmax(1, round(iw)), ih = fmax(1, round(ih));
    const int m = 16, legend_w = 150;
    int head = (o.title ? 56 : 32) + (above ? 17 : 0), body = ih > 280 ? (int)ih : 280;
    lx__page pg;
    lx_status st = lx__page_init(ctx, &pg, m + (int)iw + 20 + legend_w + m, head + body + m, WHITE);
    if (st) return st;
    const lx__font ft = {16, 1, {20, 20, 20}, 0}, fc = {12, 0, {90, 90, 90}, 0};
    char cap[200], lt[96];
    double cy = 10;
    if (o.title) cy = lx__page_text_fit(&pg, &ft, m, 10, LX__TEXT_TITLE, o.title, pg.w - 2 * m).y1 + 2;
    if ((st = summary(ctx, values, (size_t)w * h, o.unit, cap, sizeof cap))) goto done;
    cy = lx__page_text(&pg, &fc, m, cy, 0, 0, LX__TEXT_NOTE, NAN, cap).y1 + 1;
    if (above) { /* say what the range leaves out */
        char top[32], mx[32], note[256];
        if (s.log) lx__fmt_decade(top, sizeof top, s.hi);
        else lx__fmt_sig(top, sizeof top, s.hi, 3);
        lx__fmt_sig(mx, sizeof mx, above_max, 4);
        snprintf(note, sizeof note, "range without a small bright source (the sun?): %zu pixel%s (%.2g %%) above %s%s%s, up to %s, "
                 "drawn in the top colour", above, above == 1 ? "" : "s", 100.0 * (double)above / ((double)w * h), top,
                 o.unit ? " " : "", o.unit ? o.unit : "", mx);
        const lx__font fn = {12, 0, {150, 30, 20}, 0};
        lx__page_text_fit(&pg, &fn, m, cy, LX__TEXT_NOTE, note, pg.w - 2 * m);
    }
    pg.lay.above = above;
    lx__box map = {m, head, m + iw, head + ih};
    pg.lay.area = map;
    if ((st = lx__page_map(ctx, &pg, map, values, w, h, &s))) goto done;
    legend_title(lt, sizeof lt, o.quantity, o.unit);
    lx__page_legend(&pg, (lx__box){m + iw + 20, head, m + iw + 20 + legend_w, head + body}, &s, lt);
    st = lx__page_write_png(ctx, &pg, path);
    if (!st && out) lx__page_take_layout(&pg, out);
done:
    lx__page_free(&pg);
    return st;
}

lx_status lx_falsecolor_write_png(lx_ctx *ctx, const char *path, int w, int h, const double *values,
                                  const lx_falsecolor_opts *opts)
{
    LX__NEED_CTX(ctx);
    return lx__falsecolor_png(ctx, path, w, h, values, opts, NULL);
}

lx_status lx_envmap_preview_write_png(lx_ctx *ctx, const char *path, int n, const lx_envmap *const *maps,
                                      const char *const *labels)
{
    LX__NEED_CTX(ctx);
    if (!path || n < 1 || !maps) return lx__error(ctx, LX_EINVAL, NULL, 0, "preview: nothing to draw");
    const int pw = 512, m = 12, lab = 22;
    int ph = 0;
    for (int k = 0; k < n; k++) {
        if (!maps[k] || !maps[k]->data) return lx__error(ctx, LX_EINVAL, NULL, 0, "preview: map %d is NULL", k);
        int h = (int)((long)maps[k]->height * pw / maps[k]->width);
        ph = h > ph ? h : ph;
    }
    ph = ph < 1 ? 1 : ph;
    lx__page pg;
    lx_status st = lx__page_init(ctx, &pg, m + n * (pw + m), m + lab + ph + m, WHITE);
    if (st) return st;
    const lx__font f = {13, 0, {20, 20, 20}, 0};
    for (int k = 0; k < n && !st; k++) {
        const lx_envmap *e = maps[k];
        double x = m + k * (pw + m), h = fmax(1, (double)e->height * pw / e->width);
        if (labels && labels[k]) lx__page_text(&pg, &f, x, m, 0, 0, LX__TEXT_TITLE, NAN, labels[k]);
        st = lx__page_tonemap(ctx, &pg, (lx__box){x, m + lab, x + pw, m + lab + h}, e->data, e->channels, e->width,
                              e->height);
    }
    if (!st) st = lx__page_write_png(ctx, &pg, path);
    lx__page_free(&pg);
    return st;
}

lx_status lx__irradiance_png(lx_ctx *ctx, const char *path, const lx_envmap *rad, const lx_envmap *irr,
                             const char *label, lx_plot_scale scale, lx__layout *out)
{
    if (!path || !rad || !irr || !rad->data || !irr->data)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "irradiance preview: NULL argument");
    size_t n = (size_t)irr->width * irr->height;
    double *E = lx__alloc_n(n, sizeof *E);
    if (!E) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t p = 0; p < n; p++) {
        const float *q = irr->data + p * irr->channels;
        double Y = irr->channels == 3 ? irr->y_weights[0] * q[0] + irr->y_weights[1] * q[1] + irr->y_weights[2] * q[2] : q[0];
        E[p] = Y * irr->lum_per_unit;
    }
    const int pw = 512, m = 16, lab = 22, legend_w = 150;
    double rh = fmax(1, (double)rad->height * pw / rad->width), eh = fmax(1, (double)irr->height * pw / irr->width);
    int body = (int)fmax(fmax(rh, eh) + 24, 280);
    lx__page pg;
    lx_status st = lx__page_init(ctx, &pg, m + pw + m + pw + 20 + legend_w + m, 50 + lab + body + m, WHITE);
    if (st) {
        lx__free(E);
        return st;
    }
    const lx__font ft = {16, 1, {20, 20, 20}, 0}, f = {13, 0, {20, 20, 20}, 0}, fc = {12, 0, {90, 90, 90}, 0};
    lx__page_text(&pg, &ft, m, 12, 0, 0, LX__TEXT_TITLE, NAN, "Irradiance from a radiance map");
    char cap[200], right[128];
    summary(ctx, E, n, "lx", cap, sizeof cap);
    double y = 50;
    lx__page_text(&pg, &f, m, y, 0, 0, LX__TEXT_TITLE, NAN, "radiance (input, tone-mapped)");
    snprintf(right, sizeof right, "illuminance of each normal%s%s%s", label ? " (" : "", label ? label : "", label ? ")" : "");
    lx__page_text(&pg, &f, m + pw + m, y, 0, 0, LX__TEXT_TITLE, NAN, right);
    y += lab;
    st = lx__page_tonemap(ctx, &pg, (lx__box){m, y, m + pw, y + rh}, rad->data, rad->channels, rad->width, rad->height);
    lx__scale s;
    lx__scale_auto(&s, E, n, scale != LX_PLOT_SCALE_LINEAR, NAN, NAN);
    lx__box map = {m + pw + m, y, m + pw + m + pw, y + eh};
    pg.lay.area = map;
    lx__page_text(&pg, &fc, map.x0, map.y1 + 6, 0, 0, LX__TEXT_NOTE, NAN, cap);
    if (!st) st = lx__page_map(ctx, &pg, map, E, irr->width, irr->height, &s);
    lx__page_legend(&pg, (lx__box){m + 2 * pw + m + 20, y, m + 2 * pw + m + 20 + legend_w, y + body}, &s, "illuminance (lx)");
    if (!st) st = lx__page_write_png(ctx, &pg, path);
    if (!st && out) lx__page_take_layout(&pg, out);
    lx__page_free(&pg);
    lx__free(E);
    return st;
}

lx_status lx_irradiance_write_png(lx_ctx *ctx, const char *path, const lx_envmap *radiance, const lx_envmap *irradiance,
                                  const char *label, lx_plot_scale scale)
{
    LX__NEED_CTX(ctx);
    return lx__irradiance_png(ctx, path, radiance, irradiance, label, scale, NULL);
}
