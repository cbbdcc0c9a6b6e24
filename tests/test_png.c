/* test_png.c - the reusable PNG plot module: palette ends and monotone luminance ramp, the
 * false-colour plot read back with libpng (size, colours at known places), text drawing, the
 * tone-mapped preview, and atomic failure. */
#include "lx_test.h"

#include <png.h>
#include <string.h>
#include <unistd.h>

#include "plot/plot_private.h"

/* reads an 8-bit RGB PNG into a malloc'ed buffer; returns NULL on failure */
static unsigned char *read_png(const char *path, int *w, int *h)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path)) return NULL;
    img.format = PNG_FORMAT_RGB;
    unsigned char *buf = malloc(PNG_IMAGE_SIZE(img));
    if (!buf || !png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        free(buf);
        return NULL;
    }
    *w = (int)img.width;
    *h = (int)img.height;
    return buf;
}

static void palette(void **state)
{
    (void)state;
    unsigned char a[3], b[3];
    /* ends of the palette as defined in png_plot.c: dark violet (0.18, 0, 0.35), red (0.85, 0, 0.05) */
    lx__falsecolor(0, a);
    assert_int_equal(a[0], 46), assert_int_equal(a[1], 0), assert_int_equal(a[2], 89);
    lx__falsecolor(1, b);
    assert_int_equal(b[0], 217), assert_int_equal(b[1], 0), assert_int_equal(b[2], 13);
    lx__falsecolor(NAN, a); /* NaN clamps to the low end */
    assert_int_equal(a[0], 46);
    /* log mapping: 10 between 1 and 100 is the middle (log10 definition) */
    lx_assert_near(lx__falsecolor_t(10, 1, 100, 1), 0.5, 1e-15, 0);
    lx_assert_near(lx__falsecolor_t(25, 0, 100, 0), 0.25, 1e-15, 0);
    assert_int_equal(lx__text_width("1.5e+03", 1), 7 * 6 - 1);
}

static void falsecolor_plot(void **state)
{
    lx_ctx *ctx = *state;
    char path[] = "/tmp/lxpngXXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    double v[4 * 2] = {1, 10, 100, 1000, 1, 10, 100, 1000};
    lx_assert_ok(ctx, lx_png_falsecolor(ctx, path, 4, 2, v, NAN, NAN, 1, "LUMINANCE CD/M2"));
    int w, h;
    unsigned char *px = read_png(path, &w, &h);
    assert_non_null(px);
    /* layout of lx__png_falsecolor: margin 10, the 4x2 map enlarged by 128 to 512x256, legend 150 */
    assert_int_equal(w, 10 + 512 + 10 + 150);
    assert_int_equal(h, 10 + 260 + 10);
    unsigned char lo[3], hi[3];
    lx__falsecolor(0, lo);
    lx__falsecolor(1, hi);
    assert_memory_equal(px + (20 * w + 20) * 3, lo, 3);         /* first cell: the minimum, 1 */
    assert_memory_equal(px + (20 * w + 10 + 500) * 3, hi, 3);   /* last cell: the maximum, 1000 */
    /* the title is drawn in dark ink somewhere in the legend's first 14 rows */
    int ink = 0;
    for (int y = 10; y < 24; y++)
        for (int x = 532; x < w; x++) ink += px[(y * w + x) * 3] == 20;
    assert_true(ink > 20);
    free(px);
    unlink(path);
    /* a missing directory: LX_EIO, nothing left behind */
    assert_int_equal(lx_png_falsecolor(ctx, "/nonexistent/dir/x.png", 4, 2, v, NAN, NAN, 0, "T"), LX_EIO);
}

static void preview(void **state)
{
    lx_ctx *ctx = *state;
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_envmap_create(ctx, 8, 4, 3, &m));
    for (int k = 0; k < 8 * 4 * 3; k++) m->data[k] = 0.5f; /* uniform: median maps to 0.18 */
    char path[] = "/tmp/lxpngXXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    const lx_envmap *maps[2] = {m, m};
    const char *labels[2] = {"A", "B"};
    lx_assert_ok(ctx, lx_png_preview(ctx, path, 2, maps, labels));
    int w, h;
    unsigned char *px = read_png(path, &w, &h);
    assert_non_null(px);
    assert_int_equal(w, 10 + 2 * (512 + 10));
    assert_int_equal(h, 10 + 18 + 256 + 10);
    /* 0.18 -> Reinhard 0.18/1.18 = 0.152542 -> sRGB 1.055 x^(1/2.4) - 0.055 = 0.42695 -> 109 */
    unsigned char *p = px + ((10 + 18 + 100) * w + 100) * 3;
    assert_int_equal(p[0], 109);
    assert_int_equal(p[1], 109);
    free(px);
    unlink(path);
    lx_envmap_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(palette),
        cmocka_unit_test_setup_teardown(falsecolor_plot, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(preview, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
