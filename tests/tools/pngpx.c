/* pngpx.c - reads pixels of a PNG for the CLI tests (the cases in tests/cli check that a mark or a colour
 * is where a plot must draw it), through cairo's PNG reader:
 *   pngpx FILE size                            -> "W H"
 *   pngpx FILE at X Y                          -> "R G B" of pixel (X, Y), (0, 0) the top left
 *   pngpx FILE count RRGGBB TOL [X0 Y0 X1 Y1]  -> pixels within TOL of the colour in every channel
 *   pngpx FILE box RRGGBB TOL [X0 Y0 X1 Y1]    -> "x0 y0 x1 y1 n": their bounding box and count
 *                                                 ("none 0" when there is none)
 * The optional region is half-open: X0 <= x < X1, Y0 <= y < Y1. Exit 2 on a bad PNG or arguments. */
#include <cairo.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void px(cairo_surface_t *s, int x, int y, int rgb[3])
{
    const unsigned char *d = cairo_image_surface_get_data(s);
    uint32_t v = *(const uint32_t *)(const void *)(d + (size_t)y * cairo_image_surface_get_stride(s) + 4 * (size_t)x);
    rgb[0] = (int)(v >> 16 & 255), rgb[1] = (int)(v >> 8 & 255), rgb[2] = (int)(v & 255);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: pngpx FILE size|at X Y|count RRGGBB TOL [X0 Y0 X1 Y1]|box RRGGBB TOL [X0 Y0 X1 Y1]\n");
        return 2;
    }
    cairo_surface_t *s = cairo_image_surface_create_from_png(argv[1]);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "pngpx: %s: %s\n", argv[1], cairo_status_to_string(cairo_surface_status(s)));
        return 2;
    }
    int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s), rc = 0;
    if (!strcmp(argv[2], "size")) printf("%d %d\n", w, h);
    else if (!strcmp(argv[2], "at") && argc == 5) {
        int x = atoi(argv[3]), y = atoi(argv[4]), c[3];
        if (x < 0 || y < 0 || x >= w || y >= h) {
            fprintf(stderr, "pngpx: (%d, %d) outside %d x %d\n", x, y, w, h);
            rc = 2;
        } else {
            px(s, x, y, c);
            printf("%d %d %d\n", c[0], c[1], c[2]);
        }
    } else if ((!strcmp(argv[2], "count") || !strcmp(argv[2], "box")) && (argc == 5 || argc == 9)) {
        unsigned long col = strtoul(argv[3], NULL, 16);
        int want[3] = {(int)(col >> 16 & 255), (int)(col >> 8 & 255), (int)(col & 255)}, tol = atoi(argv[4]);
        int x0 = 0, y0 = 0, x1 = w, y1 = h;
        if (argc == 9) x0 = atoi(argv[5]), y0 = atoi(argv[6]), x1 = atoi(argv[7]), y1 = atoi(argv[8]);
        x0 = x0 < 0 ? 0 : x0, y0 = y0 < 0 ? 0 : y0, x1 = x1 > w ? w : x1, y1 = y1 > h ? h : y1;
        long n = 0;
        int bx0 = w, by0 = h, bx1 = -1, by1 = -1;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++) {
                int c[3];
                px(s, x, y, c);
                if (abs(c[0] - want[0]) <= tol && abs(c[1] - want[1]) <= tol && abs(c[2] - want[2]) <= tol) {
                    n++;
                    if (x < bx0) bx0 = x;
                    if (x > bx1) bx1 = x;
                    if (y < by0) by0 = y;
                    if (y > by1) by1 = y;
                }
            }
        if (!strcmp(argv[2], "count")) printf("%ld\n", n);
        else if (n) printf("%d %d %d %d %ld\n", bx0, by0, bx1, by1, n);
        else printf("none 0\n");
    } else {
        fprintf(stderr, "pngpx: bad arguments\n");
        rc = 2;
    }
    cairo_surface_destroy(s);
    return rc;
}
