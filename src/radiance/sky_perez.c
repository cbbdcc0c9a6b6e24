/* sky_perez.c - the Perez all-weather sky (Perez, Seals & Michalsky 1993) from direct-normal and
 * diffuse-horizontal irradiance, as Radiance gendaylit -W builds it: sky clearness and brightness
 * (Perez 1990), the bin's coefficients (src/data/perez1993_sky_coefficients.csv) and the luminous
 * efficacy models (src/data/perez1990_efficacy.csv) that give the diffuse and direct illuminance. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <string.h>

#define SOLAR_CONSTANT_W_M2 1367.0 /* gendaylit's solar_constant_e */

/* Kasten's relative air mass (1966), as gendaylit's air_mass(): zenith in degrees. */
static double air_mass(double zdeg) { return 1 / (cos(zdeg * LX__DEG) + 0.15 * pow(93.885 - zdeg, -1.253)); }

/* The eccentricity correction (R0/R)^2 of Spencer 1971 for day number dn (gendaylit's get_eccentricity). */
static double eccentricity(int dn)
{
    double g = 2 * LX__PI * (dn - 1) / 365.0;
    return 1.00011 + 0.034221 * cos(g) + 0.00128 * sin(g) + 0.000719 * cos(2 * g) + 0.000077 * sin(2 * g);
}

lx_status lx_sky_perez(lx_ctx *ctx, const lx_perez_input *in, lx_sky *out)
{
    LX__NEED_CTX(ctx);
    if (!in || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_sky_perez: NULL argument");
    lx_status st0 = lx__check_reserved(ctx, "Perez sky input", in->reserved, sizeof in->reserved);
    if (st0) return st0;
    const lx__table *ct = lx__table_find("perez1993_sky_coefficients"), *et = lx__table_find("perez1990_efficacy");
    if (!ct || !et || ct->ncols != 23 || ct->nrows != 8 || et->ncols != 9 || et->nrows != 8)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "Perez sky: coefficient tables missing from this build");
    lx_sky s;
    memset(&s, 0, sizeof s);
    s.model = LX_SKY_MODEL_PEREZ;
    lx_status st = lx__unit3(ctx, "Perez sky: sun direction", in->sun_dir, s.sun_dir);
    if (st != LX_OK) return st;
    if (!(s.sun_dir[2] > 0))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "Perez sky: the sun is at or below the horizon (altitude %.3g deg)",
                         asin(s.sun_dir[2]) / LX__DEG);
    double Ib = in->direct_normal_W_m2, Id = in->diffuse_horizontal_W_m2;
    if (!(Ib >= 0 && Ib <= SOLAR_CONSTANT_W_M2) || !(Id > 0 && Id <= SOLAR_CONSTANT_W_M2))
        return lx__error(ctx, LX_EINVAL, NULL, 0,
                         "Perez sky: direct normal (0..1367 W/m2) or diffuse horizontal (> 0) irradiance out of range");
    if (in->day_of_year < 1 || in->day_of_year > 366)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "Perez sky: day of year %d is not 1..366", in->day_of_year);
    double W = in->precipitable_water_cm > 0 ? in->precipitable_water_cm : 2.0;
    double Z = acos(s.sun_dir[2]), zdeg = Z / LX__DEG, z3 = 1.041 * Z * Z * Z;
    /* sky clearness and brightness (Perez 1990 eqs. 1 and 2; zenith in radians) */
    double eps = ((Id + Ib) / Id + z3) / (1 + z3);
    double delta = Id * air_mass(zdeg) / (SOLAR_CONSTANT_W_M2 * eccentricity(in->day_of_year));
    /* gendaylit's range: epsilon 1..12, Delta 0.01..0.6 (clamped here; gendaylit refuses) */
    eps = eps > 12 ? 12 : eps;
    delta = delta < 0.01 ? 0.01 : delta > 0.6 ? 0.6 : delta;
    int bin = 0;
    while (bin < 7 && !(eps < ct->data[2 * 8 + bin])) bin++;
    s.epsilon = eps;
    s.delta = delta;
    s.perez_bin = bin + 1;
    /* luminous efficacies (Perez 1990, table 4) */
    const double *E = et->data;
    double k_dif = E[1 * 8 + bin] + E[2 * 8 + bin] * W + E[3 * 8 + bin] * cos(Z) + E[4 * 8 + bin] * log(delta);
    double k_dir = E[5 * 8 + bin] + E[6 * 8 + bin] * W + E[7 * 8 + bin] * exp(5.73 * Z - 5) + E[8 * 8 + bin] * delta;
    if (k_dir < 0) k_dir = 0;
    s.sun_normal_lx = Ib * k_dir;
    double Dv = Id * k_dif;
    /* the distribution's coefficients (Perez 1993, table 1), with gendaylit's floor on Delta */
    double dl = eps > 1.065 && eps < 2.8 && delta < 0.2 ? 0.2 : delta;
    double x[5][4];
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 4; j++) x[i][j] = ct->data[(3 + 4 * i + j) * 8 + bin];
    double c[5];
    for (int i = 0; i < 5; i++) c[i] = x[i][0] + x[i][1] * Z + dl * (x[i][2] + x[i][3] * Z);
    if (bin == 0) {
        c[2] = exp(pow(dl * (x[2][0] + x[2][1] * Z), x[2][2])) - x[2][3];
        c[3] = -exp(dl * (x[3][0] + x[3][1] * Z)) + x[3][2] + dl * x[3][3];
    }
    s.a = c[0], s.b = c[1], s.c = c[2], s.d = c[3], s.e = c[4];
    if (!(Dv > 0))
        return lx__error(ctx, LX_ERANGE, NULL, 0, "Perez sky: the diffuse efficacy model gives no illuminance (%.4g lm/W)",
                         k_dif);
    if ((st = lx__sky_scale(ctx, &s, LX_SKY_BY_HORIZONTAL, Dv)) != LX_OK) return st;
    *out = s;
    return LX_OK;
}
