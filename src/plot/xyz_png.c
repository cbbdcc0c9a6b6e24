/* xyz_png.c - an sRGB preview PNG of an XYZ image (what `luxcalc spd IMAGE.exr --png` writes):
 * XYZ to linear sRGB, then the page's exposure, tone curve and encoding (tonemap.c). */
#include "plot/plot_private.h"

#include <stdlib.h>

lx_status lx_xyz_image_write_png(lx_ctx *ctx, const char *path, const lx_xyz_image *img)
{
    LX__NEED_CTX(ctx);
    if (!path || !img || !img->xyz) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_xyz_image_write_png: NULL argument");
    /* XYZ -> linear sRGB (IEC 61966-2-1); lx__page_tonemap does exposure, tone curve, encoding */
    static const double M[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    size_t npix = (size_t)img->width * img->height;
    float *rgb = lx__alloc_n(3 * npix, sizeof(float));
    if (!rgb) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
    for (size_t p = 0; p < npix; p++)
        for (int i = 0; i < 3; i++) {
            const double *q = img->xyz + 3 * p;
            rgb[3 * p + i] = (float)(M[i][0] * q[0] + M[i][1] * q[1] + M[i][2] * q[2]);
        }
    int w = img->width, h = img->height;
    if (w < 256) {
        int s = (256 + w - 1) / w;
        w *= s, h *= s;
    }
    if (w > 4096) h = (int)((long)h * 4096 / w), w = 4096;
    if (h > 4096) w = (int)((long)w * 4096 / h), h = 4096;
    if (w < 1) w = 1;
    if (h < 1) h = 1;
    static const unsigned char black[3] = {0, 0, 0};
    lx__page pg;
    lx_status st = lx__page_init(ctx, &pg, w, h, black);
    if (!st) st = lx__page_tonemap(ctx, &pg, (lx__box){0, 0, w, h}, rgb, 3, img->width, img->height);
    if (!st) st = lx__page_write_png(ctx, &pg, path);
    lx__page_free(&pg);
    lx__free(rgb);
    return st;
}
