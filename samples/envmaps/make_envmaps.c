/* make_envmaps.c - writes the sample lat-long maps of samples/envmaps with luxcalc's own EXR
 * writer. Build and run from the repository root after `make`:
 *   cc -std=c11 -Isrc -o build/make_envmaps samples/envmaps/make_envmaps.c build/libluxcalc.a \
 *      -lOpenEXRCore-3_1 -lpng16 -lOpenCL -lm -lpthread && build/make_envmaps samples/envmaps
 * sky_sun.exr: the sky of ../shared/peers/envmap_numpy.py make_sky (gradient (0.6 + 1.4 z)(1 + 0.3 x),
 *   blue tint, grey ground) plus a sun of 0.27 deg radius at elevation 35 deg, azimuth 60 deg whose
 *   normal irradiance is 5x the sky's horizontal irradiance (pixel coverage by 16x16 sub-samples).
 * furnace.exr: a uniform map of radiance 1 W/(sr m2) (E = pi for every normal).
 * half_lit.exr: radiance 1 above the horizon, 0 below (E = pi (1 + n_z) / 2). */
#include "luxcalc.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

static int write(lx_ctx *ctx, const char *dir, const char *name, lx_envmap *m, int half)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    lx_exr_write_opts o = {.half = half};
    if (lx_envmap_write_exr(ctx, path, m, &o)) {
        fprintf(stderr, "make_envmaps: %s\n", lx_ctx_errmsg(ctx));
        return 1;
    }
    printf("wrote %s (%dx%d, %d channels)\n", path, m->width, m->height, m->channels);
    return 0;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    lx_ctx *ctx = NULL;
    lx_ctx_create(&ctx);
    const int W = 256, H = 128;
    lx_envmap *m = NULL;
    if (lx_envmap_create(ctx, W, H, 3, &m)) return 1;
    const double tint[3] = {0.7, 0.85, 1.2}, ground[3] = {0.25, 0.2, 0.15}, sun_tint[3] = {1.0, 0.95, 0.9};
    const double el = 35 * PI / 180, az = 60 * PI / 180, rad = 0.27 * PI / 180;
    const double s[3] = {cos(el) * cos(az), cos(el) * sin(az), sin(el)};
    double e_sky_h = 0, sun_sr = 0;
    float *cover = calloc((size_t)W * H, sizeof *cover);
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double d[3];
            lx_envmap_direction(W, H, j + 0.5, i + 0.5, d);
            float *p = m->data + ((size_t)j * W + i) * 3;
            double sky = (0.6 + 1.4 * d[2]) * (1 + 0.3 * d[0]);
            for (int c = 0; c < 3; c++) p[c] = (float)(d[2] > 0 ? sky * tint[c] : ground[c]);
            if (d[2] > 0) e_sky_h += p[1] * d[2] * lx_envmap_pixel_sr(W, H, j);
            double cs = d[0] * s[0] + d[1] * s[1] + d[2] * s[2];
            if (cs > cos(rad + 0.02)) { /* near the sun: coverage by 16 x 16 sub-samples */
                int in = 0;
                for (int a = 0; a < 16; a++)
                    for (int b = 0; b < 16; b++) {
                        double q[3];
                        lx_envmap_direction(W, H, j + (a + 0.5) / 16, i + (b + 0.5) / 16, q);
                        in += q[0] * s[0] + q[1] * s[1] + q[2] * s[2] > cos(rad);
                    }
                cover[(size_t)j * W + i] = in / 256.0f;
                sun_sr += in / 256.0 * lx_envmap_pixel_sr(W, H, j);
            }
        }
    double L_sun = 5 * e_sky_h / sun_sr;
    for (size_t k = 0; k < (size_t)W * H; k++)
        for (int c = 0; c < 3; c++) m->data[3 * k + c] += (float)(cover[k] * L_sun * sun_tint[c]);
    free(cover);
    int rc = write(ctx, dir, "sky_sun.exr", m, 0); /* float: the sun exceeds half range */
    lx_envmap_free(m);
    if (lx_envmap_create(ctx, 64, 32, 1, &m)) return 1;
    for (int k = 0; k < 64 * 32; k++) m->data[k] = 1.0f;
    rc |= write(ctx, dir, "furnace.exr", m, 0);
    for (int k = 0; k < 64 * 32; k++) m->data[k] = k < 64 * 16 ? 1.0f : 0.0f;
    rc |= write(ctx, dir, "half_lit.exr", m, 0);
    lx_envmap_free(m);
    lx_ctx_destroy(ctx);
    return rc;
}
