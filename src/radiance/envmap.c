/* envmap.c - lat-long environment maps: creation, pixel directions, exact pixel solid angles and
 * first moments, luminance (Y weights from chromaticities), solid-angle-weighted downsampling. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


/* Rec.709 / sRGB primaries and D65 white (ITU-R BT.709-6, IEC 61966-2-1). */
static const double rec709_xy[8] = {0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290};

lx_status lx_rgb_y_weights(lx_ctx *ctx, const double xy[8], double weights[3])
{
    LX__NEED_CTX(ctx);
    if (!xy || !weights) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_rgb_y_weights: NULL argument");
    /* columns: XYZ of each primary with Y = 1; solve M s = W (white with Y = 1); Y row = s */
    double M[3][3], W[3];
    for (int k = 0; k < 4; k++) {
        double x = xy[2 * k], y = xy[2 * k + 1];
        if (!(fabs(y) > 1e-9) || !isfinite(x) || !isfinite(y) || (k == 3 && !(y > 0)))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "chromaticity %d has y = 0 (or white y <= 0) or is not finite", k);
        double v[3] = {x / y, 1.0, (1 - x - y) / y};
        for (int r = 0; r < 3; r++) {
            if (k < 3) M[r][k] = v[r];
            else W[r] = v[r];
        }
    }
    double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                 M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    if (!(fabs(det) > 1e-12)) return lx__error(ctx, LX_EINVAL, NULL, 0, "RGB primaries are collinear");
    double s[3];
    for (int k = 0; k < 3; k++) { /* Cramer's rule */
        double A[3][3];
        memcpy(A, M, sizeof A);
        for (int r = 0; r < 3; r++) A[r][k] = W[r];
        s[k] = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) / det;
    }
    for (int k = 0; k < 3; k++) weights[k] = s[k];
    return LX_OK;
}

lx_status lx_envmap_create(lx_ctx *ctx, int width, int height, int channels, lx_envmap **out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_envmap_create: NULL output");
    *out = NULL;
    if (width < 1 || height < 1 || (channels != 1 && channels != 3) || (double)width * height > 1e9)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "invalid map size %dx%d with %d channels", width, height, channels);
    lx_envmap *m = lx__calloc(1, sizeof *m);
    if (m) m->data = lx__calloc((size_t)width * height * channels, sizeof *m->data);
    if (!m || !m->data) {
        lx__free(m);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory for a %dx%d map", width, height);
    }
    m->width = width;
    m->height = height;
    m->channels = channels;
    if (channels == 3) lx_rgb_y_weights(ctx, rec709_xy, m->y_weights);
    else m->y_weights[0] = 1.0;
    m->units = LX_ENV_RADIANCE;
    m->lum_per_unit = LX_ENV_DEFAULT_EFFICACY;
    *out = m;
    return LX_OK;
}

void lx_envmap_free(lx_envmap *map)
{
    if (!map) return;
    lx__free(map->data);
    lx__free(map);
}

void lx_envmap_direction(int width, int height, double row, double col, double dir[3])
{
    double t = row * LX__PI / height, p = col * 2 * LX__PI / width;
    double st = sin(t);
    dir[0] = st * cos(p);
    dir[1] = st * sin(p);
    dir[2] = cos(t);
}

double lx_envmap_pixel_sr(int width, int height, int row)
{
    double dt = LX__PI / height, tc = (row + 0.5) * dt;
    return (2 * LX__PI / width) * 2 * sin(tc) * sin(0.5 * dt); /* cos t0 - cos t1 without cancellation */
}

/* Row factors: integrals of sin t, sin^2 t and sin t cos t over [t0, t1], cancellation-free. */
static void row_factors(int height, int row, double *sr, double *s2, double *sc)
{
    double dt = LX__PI / height, tc = (row + 0.5) * dt;
    *sr = 2 * sin(tc) * sin(0.5 * dt);
    *s2 = 0.5 * (dt - cos(2 * tc) * sin(dt));   /* [t/2 - sin 2t / 4] */
    *sc = 0.5 * sin(2 * tc) * sin(dt);          /* [sin^2 t / 2] */
}

static void col_factors(int width, int col, double *gx, double *gy)
{
    double dp = 2 * LX__PI / width, pc = (col + 0.5) * dp, s = 2 * sin(0.5 * dp);
    *gx = cos(pc) * s; /* sin p1 - sin p0 */
    *gy = sin(pc) * s; /* cos p0 - cos p1 */
}

void lx_envmap_pixel_moment(int width, int height, int row, int col, double m[3])
{
    double sr, s2, sc, gx, gy;
    row_factors(height, row, &sr, &s2, &sc);
    col_factors(width, col, &gx, &gy);
    m[0] = s2 * gx;
    m[1] = s2 * gy;
    m[2] = sc * (2 * LX__PI / width);
}

lx_status lx__llgeom_init(lx_ctx *ctx, lx__llgeom *g, int w, int h)
{
    memset(g, 0, sizeof *g);
    g->w = w;
    g->h = h;
    g->dphi = 2 * LX__PI / w;
    g->row_sr = lx__alloc_n(3 * (size_t)h, sizeof(double));
    g->col_gx = lx__alloc_n(2 * (size_t)w, sizeof(double));
    if (!g->row_sr || !g->col_gx) {
        lx__llgeom_free(g);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    g->row_s2 = g->row_sr + h;
    g->row_sc = g->row_s2 + h;
    g->col_gy = g->col_gx + w;
    for (int j = 0; j < h; j++) row_factors(h, j, &g->row_sr[j], &g->row_s2[j], &g->row_sc[j]);
    for (int i = 0; i < w; i++) col_factors(w, i, &g->col_gx[i], &g->col_gy[i]);
    return LX_OK;
}

void lx__llgeom_free(lx__llgeom *g)
{
    lx__free(g->row_sr);
    lx__free(g->col_gx);
    memset(g, 0, sizeof *g);
}

double lx_envmap_y(const lx_envmap *map, const float *pixel)
{
    if (map->channels == 1) return pixel[0];
    return map->y_weights[0] * pixel[0] + map->y_weights[1] * pixel[1] + map->y_weights[2] * pixel[2];
}

lx_status lx_envmap_luminance(lx_ctx *ctx, const lx_envmap *map, double *out)
{
    LX__NEED_CTX(ctx);
    if (!map || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_envmap_luminance: NULL argument");
    size_t n = (size_t)map->width * map->height;
    for (size_t p = 0; p < n; p++) out[p] = map->lum_per_unit * lx_envmap_y(map, map->data + p * map->channels);
    return LX_OK;
}

lx_status lx_envmap_downsample(lx_ctx *ctx, const lx_envmap *in, int width, int height, lx_envmap **out)
{
    LX__NEED_CTX(ctx);
    if (!in || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_envmap_downsample: NULL argument");
    *out = NULL;
    if (in->layout != LX_ENV_LATLONG) return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "downsampling needs a lat-long map");
    if (width < 1 || height < 1 || in->width % width || in->height % height)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "downsample size %dx%d must divide the map's %dx%d", width, height,
                         in->width, in->height);
    lx_envmap *m = NULL;
    lx_status st = lx_envmap_create(ctx, width, height, in->channels, &m);
    if (st) return st;
    memcpy(m->y_weights, in->y_weights, sizeof m->y_weights);
    m->has_chromaticities = in->has_chromaticities;
    memcpy(m->chroma_xy, in->chroma_xy, sizeof m->chroma_xy);
    m->units = in->units;
    m->lum_per_unit = in->lum_per_unit;
    m->irradiance = in->irradiance;
    int fx = in->width / width, fy = in->height / height, C = in->channels;
    double *acc = lx__calloc((size_t)width * C, sizeof *acc);
    if (!acc) {
        lx_envmap_free(m);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (int J = 0; J < height; J++) {
        memset(acc, 0, (size_t)width * C * sizeof *acc);
        double wsum = 0;
        for (int j = J * fy; j < (J + 1) * fy; j++) {
            double w = lx_envmap_pixel_sr(in->width, in->height, j); /* same for every pixel of the row */
            wsum += w;
            const float *r = in->data + (size_t)j * in->width * C;
            for (int i = 0; i < in->width; i++)
                for (int c = 0; c < C; c++) acc[(i / fx) * C + c] += w * r[(size_t)i * C + c];
        }
        for (int I = 0; I < width; I++)
            for (int c = 0; c < C; c++)
                m->data[((size_t)J * width + I) * C + c] = (float)(acc[I * C + c] / (wsum * fx));
    }
    lx__free(acc);
    *out = m;
    return LX_OK;
}
