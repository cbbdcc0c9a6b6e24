/* solve.c - the inverse problems of the lighting calculator: the distance, intensity or flux
 * that gives a target illuminance, for a point source or a Warn spotlight. */
#include "lighting/lighting_private.h"

#include <math.h>


static lx_status check_target(lx_ctx *ctx, double e, double incidence_rad, double *cosb)
{
    if (!(e > 0) || !isfinite(e))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "target illuminance must be positive and finite (got %g lx)", e);
    if (!isfinite(incidence_rad))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "incidence angle must be finite");
    *cosb = cos(incidence_rad);
    if (!(*cosb > 0))
        return lx__error(ctx, LX_ERANGE, NULL, 0,
                         "no solution: at an incidence of %g deg the receiver gets no light",
                         incidence_rad * 180 / LX__PI);
    return LX_OK;
}

lx_status lx_solve_distance(lx_ctx *ctx, double illuminance_lx, double intensity_cd, double incidence_rad,
                            double *distance_m)
{
    LX__NEED_CTX(ctx);
    double cb;
    lx_status st;
    if (!distance_m) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_solve_distance: NULL output");
    if ((st = check_target(ctx, illuminance_lx, incidence_rad, &cb)) != LX_OK) return st;
    if (!(intensity_cd > 0) || !isfinite(intensity_cd))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "intensity must be positive and finite (got %g cd)", intensity_cd);
    /* E = I cos b / d^2; sqrt of each factor keeps extreme ratios from overflowing */
    *distance_m = sqrt(intensity_cd) * sqrt(cb) / sqrt(illuminance_lx);
    return LX_OK;
}

lx_status lx_solve_intensity(lx_ctx *ctx, double illuminance_lx, double distance_m, double incidence_rad,
                             double *intensity_cd)
{
    LX__NEED_CTX(ctx);
    double cb;
    lx_status st;
    if (!intensity_cd) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_solve_intensity: NULL output");
    if ((st = check_target(ctx, illuminance_lx, incidence_rad, &cb)) != LX_OK) return st;
    if (!(distance_m > 0) || !isfinite(distance_m))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "distance must be positive and finite (got %g m)", distance_m);
    double i = illuminance_lx * distance_m * distance_m / cb;
    if (!isfinite(i)) return lx__error(ctx, LX_ERANGE, NULL, 0, "the intensity needed overflows");
    *intensity_cd = i;
    return LX_OK;
}

lx_status lx_solve_flux(lx_ctx *ctx, double illuminance_lx, double distance_m, double incidence_rad,
                        double exponent, double angle_rad, double *flux_lm)
{
    LX__NEED_CTX(ctx);
    double i;
    lx_status st;
    if (!flux_lm) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_solve_flux: NULL output");
    if ((st = lx_solve_intensity(ctx, illuminance_lx, distance_m, incidence_rad, &i)) != LX_OK) return st;
    double f;
    if (exponent < 0) {
        f = 4 * LX__PI * i; /* isotropic: I = F / 4 pi */
    } else {
        if (!isfinite(exponent) || !isfinite(angle_rad))
            return lx__error(ctx, LX_EINVAL, NULL, 0, "Warn exponent and angle must be finite");
        double lobe = lx_warn_lobe(exponent, angle_rad);
        if (!(lobe > 0))
            return lx__error(ctx, LX_ERANGE, NULL, 0,
                             "no solution: a Warn spot of exponent %g sends no light at %g deg off its axis",
                             exponent, angle_rad * 180 / LX__PI);
        f = 2 * LX__PI * i / (exponent + 1) / lobe; /* I(a) = (S+1)/(2 pi) F cos^S a */
    }
    if (!isfinite(f)) return lx__error(ctx, LX_ERANGE, NULL, 0, "the flux needed overflows");
    *flux_lm = f;
    return LX_OK;
}
