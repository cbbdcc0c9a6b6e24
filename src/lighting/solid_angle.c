/* solid_angle.c - solid angles in steradians: a cone (spherical cap), a pixel of a lat-long
 * map, and a rectangle seen from a point, each in a form free of cancellation. */
#include "lighting/lighting_private.h"

#include <math.h>


lx_status lx_solid_angle_cap(lx_ctx *ctx, double half_angle_rad, double *sr)
{
    LX__NEED_CTX(ctx);
    if (!sr) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_solid_angle_cap: NULL output");
    if (!(half_angle_rad >= 0 && half_angle_rad <= LX__PI))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "cap half-angle must be between 0 and 180 deg (got %g rad)",
                         half_angle_rad);
    double s = sin(0.5 * half_angle_rad);
    *sr = 4 * LX__PI * s * s; /* 2 pi (1 - cos a) without the cancellation at small a */
    return LX_OK;
}

lx_status lx_solid_angle_latlong_pixel(lx_ctx *ctx, int width, int height, int row, double *sr)
{
    LX__NEED_CTX(ctx);
    if (!sr) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_solid_angle_latlong_pixel: NULL output");
    if (width <= 0 || height <= 0 || row < 0 || row >= height)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lat-long pixel row %d outside a %dx%d map", row, width, height);
    double dt = LX__PI / height;
    double t0 = row * dt, t1 = (row + 1) * dt;
    /* cos t0 - cos t1 = 2 sin((t0 + t1)/2) sin((t1 - t0)/2) */
    *sr = (2 * LX__PI / width) * 2 * sin(0.5 * (t0 + t1)) * sin(0.5 * dt);
    return LX_OK;
}

/* The rectangle [0, X] x [0, Y] (X, Y >= 0) at distance d, seen from above its corner:
 * atan(X Y / (d sqrt(X^2 + Y^2 + d^2))) (the solid angle of a right-angled spherical triangle pair). */
static double corner_sr(double X, double Y, double d)
{
    if (X <= 0 || Y <= 0) return 0.0;
    return atan2(X * Y, d * sqrt(X * X + Y * Y + d * d));
}

/* signed: the rectangle between the foot and (X, Y) in any quadrant */
static double signed_corner(double X, double Y, double d)
{
    double v = corner_sr(fabs(X), fabs(Y), d);
    return ((X < 0) != (Y < 0)) ? -v : v;
}

lx_status lx_solid_angle_rect(lx_ctx *ctx, double x0, double x1, double y0, double y1, double distance_m, double *sr)
{
    LX__NEED_CTX(ctx);
    if (!sr) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_solid_angle_rect: NULL output");
    if (!(distance_m > 0) || !isfinite(distance_m))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "distance must be positive and finite (got %g m)", distance_m);
    if (!isfinite(x0) || !isfinite(x1) || !isfinite(y0) || !isfinite(y1) || !(x1 >= x0) || !(y1 >= y0))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "rectangle bounds must be finite with x0 <= x1 and y0 <= y1");
    double s = fmax(fmax(fabs(x0), fabs(x1)), fmax(fmax(fabs(y0), fabs(y1)), distance_m));
    double d = distance_m / s;
    x0 /= s; x1 /= s; y0 /= s; y1 /= s;
    double v;
    if (x0 <= 0 && y0 <= 0 && x1 >= 0 && y1 >= 0) /* foot inside: four positive terms */
        v = corner_sr(x1, y1, d) + corner_sr(-x0, y1, d) + corner_sr(x1, -y0, d) + corner_sr(-x0, -y0, d);
    else
        v = signed_corner(x1, y1, d) - signed_corner(x0, y1, d) - signed_corner(x1, y0, d) +
            signed_corner(x0, y0, d);
    *sr = v > 0 ? v : 0.0;
    return LX_OK;
}
