/* sky_map.c - a sky (CIE or Perez) and the sun disc rendered as a lat-long luminance map: each
 * pixel the solid-angle mean of the sky over its patch (Gauss-Legendre in cos(theta) and phi), the
 * ground below the horizon, and the sun disc spread over the pixels it covers so that the map
 * carries exactly its direct normal illuminance. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Solid-angle mean of the sky luminance over the part of row j, column i above the horizon,
 * divided by the whole pixel's solid angle; *above the fraction of the pixel above it. */
static double pixel_sky(const lx_sky *s, double scale, int W, int H, int j, int i, int ns, const double *x,
                        const double *w, double *above)
{
    double t0 = LX__PI * j / H, t1 = LX__PI * (j + 1) / H;
    double c0 = cos(t0), c1 = cos(t1), dphi = 2 * LX__PI / W, p0 = dphi * i;
    double full = (c0 - c1) * dphi;
    double lo = c1 > 0 ? c1 : 0; /* cos(theta) from lo to c0 is sky */
    *above = c0 > lo ? (c0 - lo) * dphi / full : 0;
    if (!(c0 > lo)) return 0;
    double hu = (c0 - lo) / 2, hp = dphi / 2, sum = 0;
    for (int a = 0; a < ns; a++) {
        double u = lo + hu * (x[a] + 1), st = sqrt(1 - u * u);
        for (int b = 0; b < ns; b++) {
            double ph = p0 + hp * (x[b] + 1);
            double dir[3] = {st * cos(ph), st * sin(ph), u};
            sum += w[a] * w[b] * lx__sky_rel(s, dir);
        }
    }
    return scale * sum * hu * hp / full;
}

/* Adds the sun disc: covered solid angle per pixel by an n x n Gauss-Legendre-cell count, then
 * Evn shared in proportion. Returns 0, or -1 on no memory. */
static int add_sun(lx_envmap *m, const double sdir[3], double Evn)
{
    int W = m->width, H = m->height;
    double del = LX_SUN_HALF_ANGLE_RAD, cd = cos(del);
    double ts = acos(sdir[2]), dphi = 2 * LX__PI / W, dth = LX__PI / H;
    int j0 = (int)floor((ts - del) / dth), j1 = (int)floor((ts + del) / dth);
    j0 = j0 < 0 ? 0 : j0;
    j1 = j1 >= H ? H - 1 : j1;
    int nsub = (int)ceil((dth > dphi ? dth : dphi) / (del / 8));
    nsub = nsub < 4 ? 4 : nsub > 512 ? 512 : nsub;
    size_t cap = 64, n = 0;
    size_t *idx = lx__alloc_n(cap, sizeof *idx);
    double *cov = lx__alloc_n(cap, sizeof *cov), total = 0;
    if (!idx || !cov) goto nomem;
    for (int j = j0; j <= j1; j++) {
        double c0 = cos(dth * j), c1 = cos(dth * (j + 1));
        for (int i = 0; i < W; i++) {
            double d[3];
            lx_envmap_direction(W, H, j + 0.5, i + 0.5, d);
            double half = 0.5 * sqrt(dth * dth + dphi * dphi);
            double cc = d[0] * sdir[0] + d[1] * sdir[1] + d[2] * sdir[2];
            if (acos(cc > 1 ? 1 : cc < -1 ? -1 : cc) > del + half) continue;
            /* midpoint cells in (cos theta, phi): equal solid angle each */
            double area = 0, du = (c0 - c1) / nsub, dp = dphi / nsub;
            for (int a = 0; a < nsub; a++) {
                double u = c0 - du * (a + 0.5), st = sqrt(1 - u * u);
                for (int b = 0; b < nsub; b++) {
                    double ph = dphi * i + dp * (b + 0.5);
                    double q = st * cos(ph) * sdir[0] + st * sin(ph) * sdir[1] + u * sdir[2];
                    if (q >= cd) area += du * dp;
                }
            }
            if (area <= 0) continue;
            if (n == cap) {
                cap *= 2;
                size_t *ni = lx__realloc_n(idx, cap, sizeof *ni);
                if (!ni) goto nomem;
                idx = ni;
                double *nc = lx__realloc_n(cov, cap, sizeof *nc);
                if (!nc) goto nomem;
                cov = nc;
            }
            idx[n] = (size_t)j * W + i;
            cov[n++] = area;
            total += area;
        }
    }
    if (n == 0) { /* the disc fell between the cells (only for very coarse maps): the centre pixel */
        int j = (int)(ts / dth), i = (int)(fmod(atan2(sdir[1], sdir[0]) + 2 * LX__PI, 2 * LX__PI) / dphi);
        j = j >= H ? H - 1 : j;
        i = i >= W ? W - 1 : i;
        idx[0] = (size_t)j * W + i;
        cov[0] = total = 1;
        n = 1;
    }
    for (size_t k = 0; k < n; k++) {
        int j = (int)(idx[k] / W);
        m->data[idx[k]] += (float)(Evn * (cov[k] / total) / lx_envmap_pixel_sr(W, H, j));
    }
    lx__free(idx);
    lx__free(cov);
    return 0;
nomem:
    lx__free(idx);
    lx__free(cov);
    return -1;
}

lx_status lx_sky_map(lx_ctx *ctx, const lx_sky *sky, const lx_sky_map_opts *opts, lx_envmap **out)
{
    LX__NEED_CTX(ctx);
    if (!sky || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_sky_map: NULL argument");
    *out = NULL;
    lx_sky_map_opts o;
    memset(&o, 0, sizeof o);
    if (opts) o = *opts;
    lx_status st0 = lx__check_reserved(ctx, "sky map options", o.reserved, sizeof o.reserved);
    if (st0) return st0;
    int W = o.width ? o.width : 1024, H = o.height ? o.height : 512, ns = o.supersample ? o.supersample : 4;
    if (W < 1 || H < 1 || W > 65536 || H > 32768 || ns < 1 || ns > 64)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "sky map: size %dx%d or supersampling %d out of range", W, H, ns);
    if (!(o.sun_normal_lx >= 0) || !isfinite(o.sun_normal_lx) || !(o.ground_reflectance >= 0 && o.ground_reflectance <= 1))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "sky map: sun illuminance must be >= 0, ground reflectance 0..1");
    lx_envmap *m = NULL;
    lx_status st = lx_envmap_create(ctx, W, H, 1, &m);
    if (st != LX_OK) return st;
    m->units = LX_ENV_LUMINANCE;
    m->lum_per_unit = 1;
    double *x = lx__alloc_n(2 * (size_t)ns, sizeof *x);
    if (!x) {
        lx_envmap_free(m);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    lx__gauss_legendre(ns, x, x + ns);
    static const double up[3] = {0, 0, 1};
    double zrel = lx__sky_rel(sky, up), scale = zrel > 0 ? sky->zenith_cd_m2 / zrel : 0;
    double sun_h = sky->sun_dir[2] > 0 ? o.sun_normal_lx * sky->sun_dir[2] : 0;
    double Lg = o.ground_reflectance * (sky->diffuse_horizontal_lx + sun_h) / LX__PI;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double above;
            double L = pixel_sky(sky, scale, W, H, j, i, ns, x, x + ns, &above);
            m->data[(size_t)j * W + i] = (float)(L + (1 - above) * Lg);
        }
    lx__free(x);
    if (o.sun_normal_lx > 0 && sky->sun_dir[2] > 0 && add_sun(m, sky->sun_dir, o.sun_normal_lx) != 0) {
        lx_envmap_free(m);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    *out = m;
    return LX_OK;
}
