/* png_plot.c - reusable PNG plots: an RGB8 canvas, a 5x7 bitmap font of our own, a false-colour
 * scale with a labelled legend (the look of Radiance falsecolor), a tone-mapped HDR preview and an
 * atomic PNG writer (libpng; temporary file + rename). Declarations in lx_private.h. */
#include "plot/plot_private.h"

#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- font: 7 rows of 5 pixels, '#' on; lower case is drawn with the upper-case glyph, except e ---- */
static const struct glyph {
    char c;
    const char *rows; /* 35 characters, row-major */
} font[] = {
    {'0', ".###.#...##..###.#.###..##...#.###."}, {'1', "..#...##....#....#....#....#...###."},
    {'2', ".###.#...#....#...#...#...#...#####"}, {'3', "####.....#....#.###.....#....#####."},
    {'4', "...#...##..#.#.#..#.#####...#....#."}, {'5', "######....####.....#....##...#.###."},
    {'6', "..##..#...#....####.#...##...#.###."}, {'7', "#####....#...#...#...#....#....#..."},
    {'8', ".###.#...##...#.###.#...##...#.###."}, {'9', ".###.#...##...#.####....#...#..##.."},
    {'.', ".........................##...##..."}, {'-', "...............#####..............."},
    {'+', "......#....#..#####..#....#........"}, {'e', "...........###.#...#######.....###."},
    {'/', "....#...#....#...#...#....#...#...."}, {'(', "...#...#...#....#....#.....#.....#."},
    {')', ".#.....#.....#....#....#...#...#..."}, {':', "......##...##........##...##......."},
    {'=', "..........#####.....#####.........."}, {'%', "##...##..#...#...#...#...#..##...##"},
    {'_', "..............................#####"}, {',', "....................##....#...#...."},
    {'A', ".###.#...##...#######...##...##...#"}, {'B', "####.#...##...#####.#...##...#####."},
    {'C', ".###.#...##....#....#....#...#.###."}, {'D', "####.#...##...##...##...##...#####."},
    {'E', "######....#....####.#....#....#####"}, {'F', "######....#....####.#....#....#...."},
    {'G', ".###.#...##....#.####...##...#.####"}, {'H', "#...##...##...#######...##...##...#"},
    {'I', ".###...#....#....#....#....#...###."}, {'J', "..###...#....#....#....##..#..##..."},
    {'K', "#...##..#.#.#..##...#.#..#..#.#...#"}, {'L', "#....#....#....#....#....#....#####"},
    {'M', "#...###.###.#.##.#.##...##...##...#"}, {'N', "#...###..##.#.##..###...##...##...#"},
    {'O', ".###.#...##...##...##...##...#.###."}, {'P', "####.#...##...#####.#....#....#...."},
    {'Q', ".###.#...##...##...##.#.##..#..##.#"}, {'R', "####.#...##...#####.#.#..#..#.#...#"},
    {'S', ".#####....#.....###.....#....#####."}, {'T', "#####..#....#....#....#....#....#.."},
    {'U', "#...##...##...##...##...##...#.###."}, {'V', "#...##...##...##...##...#.#.#...#.."},
    {'W', "#...##...##...##.#.##.#.##.#.#.#.#."}, {'X', "#...##...#.#.#...#...#.#.#...##...#"},
    {'Y', "#...##...#.#.#...#....#....#....#.."}, {'Z', "#####....#...#...#...#...#....#####"},
};

static const char *glyph_rows(char ch)
{
    if (ch >= 'a' && ch <= 'z' && ch != 'e') ch = (char)(ch - 'a' + 'A');
    for (size_t k = 0; k < sizeof font / sizeof font[0]; k++)
        if (font[k].c == ch) return font[k].rows;
    return NULL; /* space and anything unknown: blank */
}

lx_status lx__canvas_init(lx_ctx *ctx, lx__canvas *c, int w, int h, const unsigned char bg[3])
{
    memset(c, 0, sizeof *c);
    if (w < 1 || h < 1 || (double)w * h > 2e8) return lx__error(ctx, LX_EINVAL, NULL, 0, "invalid canvas %dx%d", w, h);
    c->rgb = malloc((size_t)w * h * 3);
    if (!c->rgb) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %dx%d image", w, h);
    c->w = w;
    c->h = h;
    for (size_t p = 0; p < (size_t)w * h; p++) memcpy(c->rgb + 3 * p, bg, 3);
    return LX_OK;
}

void lx__canvas_free(lx__canvas *c)
{
    if (!c) return;
    free(c->rgb);
    memset(c, 0, sizeof *c);
}

static inline void put(lx__canvas *c, int x, int y, const unsigned char rgb[3])
{
    if (x < 0 || y < 0 || x >= c->w || y >= c->h) return;
    memcpy(c->rgb + ((size_t)y * c->w + x) * 3, rgb, 3);
}

void lx__canvas_fill(lx__canvas *c, int x, int y, int w, int h, const unsigned char rgb[3])
{
    for (int j = y; j < y + h; j++)
        for (int i = x; i < x + w; i++) put(c, i, j, rgb);
}

int lx__text_width(const char *s, int scale) { return s && *s ? (int)strlen(s) * 6 * scale - scale : 0; }

void lx__canvas_text(lx__canvas *c, int x, int y, int scale, const char *s, const unsigned char rgb[3])
{
    for (; s && *s; s++, x += 6 * scale) {
        const char *g = glyph_rows(*s);
        if (!g) continue;
        for (int r = 0; r < 7; r++)
            for (int q = 0; q < 5; q++)
                if (g[r * 5 + q] == '#') lx__canvas_fill(c, x + q * scale, y + r * scale, scale, scale, rgb);
    }
}

/* palette stops: dark violet, blue, cyan, green, yellow, orange, red (Radiance falsecolor-like) */
static const double stops[7][3] = {{0.18, 0.00, 0.35}, {0.00, 0.20, 0.90}, {0.00, 0.75, 0.85}, {0.15, 0.80, 0.15},
                                   {0.95, 0.95, 0.10}, {1.00, 0.55, 0.00}, {0.85, 0.00, 0.05}};

void lx__falsecolor(double t, unsigned char rgb[3])
{
    if (!(t >= 0)) t = 0; /* NaN too */
    if (t > 1) t = 1;
    double x = t * 6;
    int k = (int)x;
    if (k > 5) k = 5;
    double f = x - k;
    for (int c = 0; c < 3; c++) rgb[c] = (unsigned char)lround(255 * ((1 - f) * stops[k][c] + f * stops[k + 1][c]));
}

double lx__falsecolor_t(double v, double vmin, double vmax, int log_scale)
{
    if (log_scale) {
        if (!(v > 0)) return 0;
        return (log10(v) - log10(vmin)) / (log10(vmax) - log10(vmin));
    }
    return vmax > vmin ? (v - vmin) / (vmax - vmin) : 0.5;
}

void lx__canvas_values(lx__canvas *c, int x, int y, int w, int h, const double *v, int vw, int vh, double vmin,
                       double vmax, int log_scale)
{
    static const unsigned char grey[3] = {128, 128, 128};
    for (int j = 0; j < h; j++) {
        int sj = (int)((long)j * vh / h);
        for (int i = 0; i < w; i++) {
            double val = v[(size_t)sj * vw + (long)i * vw / w];
            unsigned char rgb[3];
            if (isnan(val)) memcpy(rgb, grey, 3);
            else lx__falsecolor(lx__falsecolor_t(val, vmin, vmax, log_scale), rgb);
            put(c, x + i, y + j, rgb);
        }
    }
}

/* a tick label with 3 significant digits */
static void label(char *buf, size_t n, double v)
{
    if (v != 0 && (fabs(v) >= 1e5 || fabs(v) < 1e-2)) snprintf(buf, n, "%.2e", v);
    else snprintf(buf, n, "%.3g", v);
}

void lx__canvas_legend(lx__canvas *c, int x, int y, int w, int h, double vmin, double vmax, int log_scale,
                       const char *title)
{
    static const unsigned char ink[3] = {20, 20, 20};
    int th = title && *title ? 14 : 0;
    if (th) lx__canvas_text(c, x, y, 1, title, ink);
    int bx = x, by = y + th + 6, bw = 18, bh = h - th - 12;
    if (bh < 20) return;
    (void)w;
    for (int j = 0; j < bh; j++) {
        unsigned char rgb[3];
        lx__falsecolor(1.0 - (double)j / (bh - 1), rgb);
        lx__canvas_fill(c, bx, by + j, bw, 1, rgb);
    }
    const int nt = 6;
    for (int k = 0; k < nt; k++) {
        double t = (double)k / (nt - 1);
        double v = log_scale ? pow(10, log10(vmin) + t * (log10(vmax) - log10(vmin))) : vmin + t * (vmax - vmin);
        int ty = by + (int)lround((1 - t) * (bh - 1));
        lx__canvas_fill(c, bx + bw, ty, 4, 1, ink);
        char buf[32];
        label(buf, sizeof buf, v);
        lx__canvas_text(c, bx + bw + 7, ty - 3, 1, buf, ink);
    }
}

static double srgb_encode(double v)
{
    if (v <= 0.0031308) return 12.92 * v;
    return 1.055 * pow(v, 1 / 2.4) - 0.055;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void lx__canvas_tonemap(lx__canvas *c, int x, int y, int w, int h, const float *v, int channels, int vw, int vh)
{
    /* exposure from the median luminance of (at most 4096) samples, mapped to middle grey 0.18 */
    size_t n = (size_t)vw * vh, step = n > 4096 ? n / 4096 : 1, m = 0;
    double *s = malloc((n / step + 1) * sizeof *s);
    double key = 1;
    if (s) {
        for (size_t p = 0; p < n; p += step) {
            const float *q = v + p * channels;
            s[m++] = channels == 3 ? 0.2126 * q[0] + 0.7152 * q[1] + 0.0722 * q[2] : q[0];
        }
        qsort(s, m, sizeof *s, cmp_double);
        key = s[m / 2];
        free(s);
    }
    double k = key > 0 ? 0.18 / key : 1;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            const float *q = v + ((size_t)((long)j * vh / h) * vw + (long)i * vw / w) * channels;
            unsigned char rgb[3];
            for (int ch = 0; ch < 3; ch++) {
                double l = k * q[channels == 3 ? ch : 0];
                l = l > 0 ? l / (1 + l) : 0;
                rgb[ch] = (unsigned char)lround(255 * srgb_encode(l));
            }
            put(c, x + i, y + j, rgb);
        }
}

lx_status lx__canvas_write_png(lx_ctx *ctx, const lx__canvas *c, const char *path)
{
    if (!c || !c->rgb || !path) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx__canvas_write_png: NULL argument");
    size_t n = strlen(path);
    char *tmp = malloc(n + 16);
    if (!tmp) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    snprintf(tmp, n + 16, "%s.tmpXXXXXX", path);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        lx_status st = lx__error(ctx, LX_EIO, path, 0, "cannot create: %s", strerror(errno));
        free(tmp);
        return st;
    }
    fchmod(fd, 0644);
    FILE *f = fdopen(fd, "wb");
    png_structp png = f ? png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL) : NULL;
    png_infop info = png ? png_create_info_struct(png) : NULL;
    lx_status st = LX_OK;
    if (!f || !png || !info) {
        st = lx__error(ctx, LX_ENOMEM, path, 0, "cannot start the PNG writer");
    } else if (setjmp(png_jmpbuf(png))) {
        st = lx__error(ctx, LX_EIO, path, 0, "PNG write failed");
    } else {
        png_init_io(png, f);
        png_set_IHDR(png, info, (png_uint_32)c->w, (png_uint_32)c->h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        for (int j = 0; j < c->h; j++) png_write_row(png, c->rgb + (size_t)j * c->w * 3);
        png_write_end(png, NULL);
    }
    if (png) png_destroy_write_struct(&png, info ? &info : NULL);
    if (f) {
        if (!st && (fflush(f) != 0 || fsync(fileno(f)) != 0)) st = lx__error(ctx, LX_EIO, path, 0, "cannot write: %s", strerror(errno));
        if (fclose(f) != 0 && !st) st = lx__error(ctx, LX_EIO, path, 0, "cannot write: %s", strerror(errno));
    } else {
        close(fd);
    }
    if (!st && rename(tmp, path) != 0) st = lx__error(ctx, LX_EIO, path, 0, "cannot rename into place: %s", strerror(errno));
    if (st) unlink(tmp);
    free(tmp);
    return st;
}

lx_status lx__png_falsecolor(lx_ctx *ctx, const char *path, int w, int h, const double *values, double vmin,
                             double vmax, int log_scale, const char *legend_title)
{
    if (!values || w < 1 || h < 1) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx__png_falsecolor: no values");
    if (isnan(vmin) || isnan(vmax)) { /* the data's range (positive values only on a log scale) */
        double lo = INFINITY, hi = -INFINITY;
        for (size_t p = 0; p < (size_t)w * h; p++) {
            double v = values[p];
            if (isnan(v) || (log_scale && !(v > 0))) continue;
            lo = fmin(lo, v), hi = fmax(hi, v);
        }
        if (!(lo <= hi)) lo = log_scale ? 1 : 0, hi = log_scale ? 10 : 1;
        if (isnan(vmin)) vmin = lo;
        if (isnan(vmax)) vmax = hi;
    }
    if (log_scale && !(vmin > 0)) vmin = vmax > 0 ? vmax * 1e-6 : 1e-6;
    if (!(vmax > vmin)) vmax = log_scale ? vmin * 10 : vmin + 1;
    int scale = w >= 512 ? 1 : (512 + w - 1) / w;
    int iw = w * scale, ih = h * scale;
    if (iw > 2048) iw = 2048, ih = (int)((long)h * 2048 / w);
    if (ih < 1) ih = 1;
    int legend_w = 150, m = 10;
    int cw = m + iw + m + legend_w, ch = m + (ih > 260 ? ih : 260) + m;
    static const unsigned char white[3] = {255, 255, 255};
    lx__canvas c;
    lx_status st = lx__canvas_init(ctx, &c, cw, ch, white);
    if (st) return st;
    lx__canvas_values(&c, m, m, iw, ih, values, w, h, vmin, vmax, log_scale);
    lx__canvas_legend(&c, m + iw + m, m, legend_w, ch - 2 * m, vmin, vmax, log_scale, legend_title);
    st = lx__canvas_write_png(ctx, &c, path);
    lx__canvas_free(&c);
    return st;
}

lx_status lx_png_falsecolor(lx_ctx *ctx, const char *path, int w, int h, const double *values, double vmin,
                            double vmax, int log_scale, const char *legend_title)
{
    LX__NEED_CTX(ctx);
    if (!path) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_png_falsecolor: NULL path");
    return lx__png_falsecolor(ctx, path, w, h, values, vmin, vmax, log_scale, legend_title);
}

lx_status lx_png_preview(lx_ctx *ctx, const char *path, int n, const lx_envmap *const *maps, const char *const *labels)
{
    LX__NEED_CTX(ctx);
    if (!path || n < 1 || !maps) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_png_preview: nothing to draw");
    const int pw = 512, m = 10, lab = 18;
    int ph = 0;
    for (int k = 0; k < n; k++) {
        if (!maps[k] || !maps[k]->data) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_png_preview: map %d is NULL", k);
        int h = (int)((long)maps[k]->height * pw / maps[k]->width);
        if (h < 1) h = 1;
        if (h > ph) ph = h;
    }
    static const unsigned char white[3] = {255, 255, 255}, ink[3] = {20, 20, 20};
    lx__canvas c;
    lx_status st = lx__canvas_init(ctx, &c, m + n * (pw + m), m + lab + ph + m, white);
    if (st) return st;
    for (int k = 0; k < n; k++) {
        const lx_envmap *e = maps[k];
        int x = m + k * (pw + m), h = (int)((long)e->height * pw / e->width);
        if (labels && labels[k]) lx__canvas_text(&c, x, m, 1, labels[k], ink);
        lx__canvas_tonemap(&c, x, m + lab, pw, h < 1 ? 1 : h, e->data, e->channels, e->width, e->height);
    }
    st = lx__canvas_write_png(ctx, &c, path);
    lx__canvas_free(&c);
    return st;
}
