/* plot_test.h - helpers of the tests that read back the PNGs the plots write (through cairo's PNG
 * reader): the picture's size and pixels, whether a region holds text (ink), and the checks every
 * plot must pass: every recorded label lies on the page, holds ink, and overlaps no other label. */
#ifndef LX_PLOT_TEST_H
#define LX_PLOT_TEST_H

#include "lx_test.h"

#include <cairo.h>
#include <stdint.h>
#include <string.h>

#include "plot/plot_private.h"

typedef struct test_png {
    int w, h, stride;
    cairo_surface_t *s;
    const unsigned char *data;
} test_png;

/* Reads path; fails the test when it is not a PNG. */
static inline void test_png_read(const char *path, test_png *p)
{
    p->s = cairo_image_surface_create_from_png(path);
    if (cairo_surface_status(p->s) != CAIRO_STATUS_SUCCESS) {
        print_error("%s: not a readable PNG (%s)\n", path, cairo_status_to_string(cairo_surface_status(p->s)));
        fail();
    }
    p->w = cairo_image_surface_get_width(p->s);
    p->h = cairo_image_surface_get_height(p->s);
    p->stride = cairo_image_surface_get_stride(p->s);
    p->data = cairo_image_surface_get_data(p->s);
}

static inline void test_png_free(test_png *p)
{
    cairo_surface_destroy(p->s);
    memset(p, 0, sizeof *p);
}

/* The sRGB bytes of pixel (x, y). */
static inline void test_px(const test_png *p, int x, int y, unsigned char rgb[3])
{
    uint32_t v = *(const uint32_t *)(const void *)(p->data + (size_t)y * p->stride + 4 * (size_t)x);
    rgb[0] = (unsigned char)(v >> 16), rgb[1] = (unsigned char)(v >> 8), rgb[2] = (unsigned char)v;
}

/* Pixels in box that differ from the box's most frequent colour by more than 60 in a channel:
 * the strokes of text (glyphs are drawn in a colour far from what they are drawn on). */
static inline int test_ink(const test_png *p, lx__box b)
{
    int x0 = (int)floor(b.x0), y0 = (int)floor(b.y0), x1 = (int)ceil(b.x1), y1 = (int)ceil(b.y1);
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > p->w) x1 = p->w;
    if (y1 > p->h) y1 = p->h;
    /* the most frequent colour, quantised to 4 bits a channel */
    static int hist[4096];
    memset(hist, 0, sizeof hist);
    int best = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            unsigned char c[3];
            test_px(p, x, y, c);
            int q = (c[0] >> 4) << 8 | (c[1] >> 4) << 4 | (c[2] >> 4);
            if (++hist[q] > hist[best]) best = q;
        }
    int bg[3] = {((best >> 8) & 15) * 16 + 8, ((best >> 4) & 15) * 16 + 8, (best & 15) * 16 + 8}, n = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            unsigned char c[3];
            test_px(p, x, y, c);
            if (abs(c[0] - bg[0]) > 60 || abs(c[1] - bg[1]) > 60 || abs(c[2] - bg[2]) > 60) n++;
        }
    return n;
}

/* Every recorded label: inside the page, with ink in its box (at least 4 pixels and 2 % of the
 * box), and overlapping no other label. Returns the number of labels. */
static inline size_t test_labels_ok(const test_png *p, const lx__layout *lay)
{
    for (size_t i = 0; i < lay->n_label; i++) {
        const lx__label *l = &lay->label[i];
        lx__box b = l->box;
        if (b.x0 < -0.5 || b.y0 < -0.5 || b.x1 > p->w + 0.5 || b.y1 > p->h + 0.5) {
            print_error("label '%s' (%.1f %.1f %.1f %.1f) is off the %dx%d page\n", l->text, b.x0, b.y0, b.x1, b.y1, p->w, p->h);
            fail();
        }
        int ink = test_ink(p, b);
        double area = (b.x1 - b.x0) * (b.y1 - b.y0);
        if (ink < 4 || ink < 0.02 * area) {
            print_error("label '%s' holds no text: %d ink pixels in %.0f\n", l->text, ink, area);
            fail();
        }
        for (size_t j = 0; j < i; j++)
            if (lx__box_overlap(b, lay->label[j].box)) {
                print_error("labels '%s' and '%s' overlap\n", l->text, lay->label[j].text);
                fail();
            }
    }
    return lay->n_label;
}

/* The number of labels of a role, and the first whose text contains s (NULL if none). */
static inline int test_count(const lx__layout *lay, int role)
{
    int n = 0;
    for (size_t i = 0; i < lay->n_label; i++) n += lay->label[i].role == role;
    return n;
}

static inline const lx__label *test_find(const lx__layout *lay, int role, const char *s)
{
    for (size_t i = 0; i < lay->n_label; i++)
        if ((role < 0 || lay->label[i].role == role) && strstr(lay->label[i].text, s)) return &lay->label[i];
    return NULL;
}

/* 1 when v is d x 10^k with d in {1, 2, 5} (a value of the 1-2-5 series). */
static inline int test_is_125(double v)
{
    if (!(v > 0)) return 0;
    double m = v / pow(10, floor(log10(v) + 1e-9));
    return fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 5) < 1e-9 || fabs(m - 10) < 1e-9;
}

#endif /* LX_PLOT_TEST_H */
