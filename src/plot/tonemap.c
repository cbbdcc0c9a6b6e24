/* tonemap.c - tone-mapped previews of linear HDR values: exposure from the median luminance
 * (mapped to middle grey 0.18), the Reinhard curve x / (1 + x), sRGB encoding. */
#include "plot/plot_private.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

double lx__srgb_encode(double v)
{
    if (!(v > 0)) return 0;
    if (v >= 1) return 1;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1 / 2.4) - 0.055;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

lx_status lx__page_tonemap(lx_ctx *ctx, lx__page *pg, lx__box box, const float *v, int channels, int vw, int vh)
{
    /* exposure from the median luminance of (at most 4096) samples, mapped to middle grey 0.18 */
    size_t n = (size_t)vw * vh, step = n > 4096 ? n / 4096 : 1, m = 0;
    double *s = lx__alloc_n(n / step + 1, sizeof *s);
    if (!s) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t p = 0; p < n; p += step) {
        const float *q = v + p * channels;
        s[m++] = channels == 3 ? 0.2126 * q[0] + 0.7152 * q[1] + 0.0722 * q[2] : q[0];
    }
    qsort(s, m, sizeof *s, cmp_double);
    double key = s[m / 2], k = key > 0 ? 0.18 / key : 1;
    lx__free(s);
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, vw, vh);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(img);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %dx%d preview", vw, vh);
    }
    cairo_surface_flush(img);
    unsigned char *data = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    for (int j = 0; j < vh; j++) {
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)j * stride);
        for (int i = 0; i < vw; i++) {
            const float *q = v + ((size_t)j * vw + i) * channels;
            uint32_t px = 0;
            for (int ch = 0; ch < 3; ch++) {
                double l = k * q[channels == 3 ? ch : 0];
                l = l > 0 ? l / (1 + l) : 0;
                px = px << 8 | (uint32_t)lround(255 * lx__srgb_encode(l));
            }
            row[i] = px;
        }
    }
    cairo_surface_mark_dirty(img);
    cairo_t *cr = pg->cr;
    cairo_save(cr);
    cairo_rectangle(cr, box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
    cairo_clip(cr);
    cairo_translate(cr, box.x0, box.y0);
    cairo_scale(cr, (box.x1 - box.x0) / vw, (box.y1 - box.y0) / vh);
    cairo_set_source_surface(cr, img, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), box.x1 - box.x0 >= vw ? CAIRO_FILTER_NEAREST : CAIRO_FILTER_GOOD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);
    return LX_OK;
}
