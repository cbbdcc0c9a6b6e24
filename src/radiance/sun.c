/* sun.c - the sun's topocentric position by the NREL Solar Position Algorithm (Reda & Andreas
 * 2004, Solar Energy 76(5):577-589; NREL/TP-560-34302 rev. 2008), its periodic terms embedded from
 * src/data (nrel_spa_earth_terms.csv, nrel_spa_nutation.csv); and altitude/azimuth to a direction. */
#include "radiance/radiance_private.h"

#include <math.h>
#include <string.h>

static double rad(double d) { return d * LX__DEG; }
static double deg(double r) { return r / LX__DEG; }

static double limit360(double d)
{
    double x = 360.0 * (d / 360.0 - floor(d / 360.0));
    return x < 0 ? x + 360 : x;
}

void lx_sun_direction(double alt, double az, double dir[3])
{
    dir[0] = cos(alt) * sin(az);
    dir[1] = cos(alt) * cos(az);
    dir[2] = sin(alt);
}

/* Julian day of a UT instant (SPA eq. 4, Meeus): the Gregorian correction after 1582-10-15. */
static double julian_day(int year, int month, int day, int hour, int minute, double second, double dut1, double tz)
{
    double dd = day + (hour - tz + (minute + (second + dut1) / 60.0) / 60.0) / 24.0;
    if (month < 3) month += 12, year--;
    double jd = floor(365.25 * (year + 4716.0)) + floor(30.6001 * (month + 1)) + dd - 1524.5;
    if (jd > 2299160.0) {
        double a = floor(year / 100.0);
        jd += 2 - a + floor(a / 4);
    }
    return jd;
}

/* sum_i (sum_k A cos(B + C jme)) jme^i / 1e8 over the series base..base+n-1 of the Earth table */
static double earth_series(const lx__table *t, int base, int n, double jme)
{
    const double *ser = t->data, *A = t->data + t->nrows, *B = A + t->nrows, *C = B + t->nrows;
    double sum = 0, p = 1;
    for (int i = 0; i < n; i++, p *= jme) {
        double s = 0;
        for (int r = 0; r < t->nrows; r++)
            if ((int)ser[r] == base + i) s += A[r] * cos(B[r] + C[r] * jme);
        sum += s * p;
    }
    return sum / 1e8;
}

static double poly3(double a, double b, double c, double d, double x) { return ((a * x + b) * x + c) * x + d; }

static lx_status check_input(lx_ctx *ctx, const lx_sun_input *in)
{
    struct { const char *what; int bad; } c[] = {
        {"year (-2000..6000)", in->year < -2000 || in->year > 6000},
        {"month (1..12)", in->month < 1 || in->month > 12},
        {"day (1..31)", in->day < 1 || in->day > 31},
        {"hour (0..24)", in->hour < 0 || in->hour > 24},
        {"minute (0..59)", in->minute < 0 || in->minute > 59},
        {"second (0..<60)", !(in->second >= 0 && in->second < 60)},
        {"time after 24:00", in->hour == 24 && (in->minute > 0 || in->second > 0)},
        {"timezone (-18..18 h)", !(fabs(in->timezone_h) <= 18)},
        {"delta_ut1 (-1..1 s)", !(in->delta_ut1_s > -1 && in->delta_ut1_s < 1)},
        {"delta_t (|dT| <= 8000 s)", !(fabs(in->delta_t_s) <= 8000)},
        {"latitude (-90..90 deg)", !(fabs(in->latitude_deg) <= 90)},
        {"longitude (-180..180 deg)", !(fabs(in->longitude_deg) <= 180)},
        {"elevation (>= -6500000 m)", !(in->elevation_m >= -6500000) || !isfinite(in->elevation_m)},
        {"pressure (0..5000 mbar)", !(in->pressure_mbar >= 0 && in->pressure_mbar <= 5000)},
        {"temperature (-273..6000 C)", !(in->temperature_C > -273 && in->temperature_C <= 6000)},
        {"refraction (|r| <= 5 deg)", !(fabs(in->refraction_deg) <= 5)},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
        if (c[i].bad) return lx__error(ctx, LX_EINVAL, NULL, 0, "sun position: %s out of range", c[i].what);
    /* the day exists in its month: the Gregorian calendar from 1582-10-15 on, the Julian before it
     * (as julian_day counts), and 1582-10-05 .. 14 never existed */
    int y = in->year, m = in->month, gregorian = y > 1582 || (y == 1582 && m > 10) || (y == 1582 && m == 10 && in->day >= 15);
    int leap = gregorian ? (y % 4 == 0 && y % 100 != 0) || y % 400 == 0 : ((y % 4) + 4) % 4 == 0;
    static const int dim[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int days = dim[m - 1] + (m == 2 && leap);
    if (in->day > days)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "sun position: day %d out of range (%04d-%02d has %d days)", in->day, y, m,
                         days);
    if (y == 1582 && m == 10 && in->day > 4 && in->day < 15)
        return lx__error(ctx, LX_EINVAL, NULL, 0,
                         "sun position: 1582-10-%02d does not exist (the Gregorian calendar follows 1582-10-04 with 10-15)",
                         in->day);
    return LX_OK;
}

lx_status lx_sun_spa(lx_ctx *ctx, const lx_sun_input *in, lx_sun_position *out)
{
    LX__NEED_CTX(ctx);
    if (!in || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_sun_spa: NULL argument");
    lx_status st = lx__check_reserved(ctx, "sun input", in->reserved, sizeof in->reserved);
    if (st == LX_OK) st = check_input(ctx, in);
    if (st != LX_OK) return st;
    const lx__table *et = lx__table_find("nrel_spa_earth_terms"), *nt = lx__table_find("nrel_spa_nutation");
    if (!et || !nt || et->ncols != 4 || nt->ncols != 10)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "sun position: SPA tables missing from this build");
    lx_sun_position p;
    memset(&p, 0, sizeof p);
    /* time scales (SPA 3.1) */
    double jd = julian_day(in->year, in->month, in->day, in->hour, in->minute, in->second, in->delta_ut1_s,
                           in->timezone_h);
    double jc = (jd - 2451545.0) / 36525.0, jde = jd + in->delta_t_s / 86400.0;
    double jce = (jde - 2451545.0) / 36525.0, jme = jce / 10.0;
    p.julian_day = jd;
    /* Earth heliocentric longitude, latitude, radius vector (3.2) */
    p.L_deg = limit360(deg(earth_series(et, 0, 6, jme)));
    p.B_deg = deg(earth_series(et, 10, 2, jme));
    p.R_au = earth_series(et, 20, 5, jme);
    /* geocentric longitude and latitude (3.3) */
    double theta = limit360(p.L_deg + 180.0), beta = -p.B_deg;
    /* nutation (3.4): mean elongation of the moon, anomalies of sun and moon, argument of latitude
     * of the moon, longitude of its ascending node */
    double X[5] = {poly3(1.0 / 189474.0, -0.0019142, 445267.11148, 297.85036, jce),
                   poly3(-1.0 / 300000.0, -0.0001603, 35999.05034, 357.52772, jce),
                   poly3(1.0 / 56250.0, 0.0086972, 477198.867398, 134.96298, jce),
                   poly3(1.0 / 327270.0, -0.0036825, 483202.017538, 93.27191, jce),
                   poly3(1.0 / 450000.0, 0.0020708, -1934.136261, 125.04452, jce)};
    double dpsi = 0, deps = 0;
    for (int r = 0; r < nt->nrows; r++) {
        double arg = 0;
        for (int j = 0; j < 5; j++) arg += X[j] * nt->data[(1 + j) * nt->nrows + r];
        arg = rad(arg);
        const double *col = nt->data + 6 * nt->nrows + r;
        dpsi += (col[0] + col[nt->nrows] * jce) * sin(arg);
        deps += (col[2 * nt->nrows] + col[3 * nt->nrows] * jce) * cos(arg);
    }
    p.delta_psi_deg = dpsi / 36000000.0;
    p.delta_epsilon_deg = deps / 36000000.0;
    /* true obliquity of the ecliptic (3.5) */
    double U = jme / 10.0, e0 = 0;
    static const double ec[11] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                  -39.05,    7.12,     27.87, 5.79,    2.45};
    for (int i = 10; i >= 0; i--) e0 = e0 * U + ec[i];
    p.epsilon_deg = e0 / 3600.0 + p.delta_epsilon_deg;
    /* aberration, apparent sun longitude (3.6, 3.7) */
    double lambda = theta + p.delta_psi_deg - 20.4898 / (3600.0 * p.R_au);
    /* apparent sidereal time at Greenwich (3.8) */
    double nu0 = limit360(280.46061837 + 360.98564736629 * (jd - 2451545.0) + jc * jc * (0.000387933 - jc / 38710000.0));
    double nu = nu0 + p.delta_psi_deg * cos(rad(p.epsilon_deg));
    /* geocentric right ascension and declination (3.9, 3.10) */
    double lr = rad(lambda), er = rad(p.epsilon_deg), br = rad(beta);
    double alpha = limit360(deg(atan2(sin(lr) * cos(er) - tan(br) * sin(er), cos(lr))));
    double delta = deg(asin(sin(br) * cos(er) + cos(br) * sin(er) * sin(lr)));
    /* observer local hour angle (3.11) */
    p.hour_angle_deg = limit360(nu + in->longitude_deg - alpha);
    /* topocentric right ascension, declination and hour angle: parallax (3.12, 3.13) */
    double xi = rad(8.794 / (3600.0 * p.R_au)), lat = rad(in->latitude_deg), H = rad(p.hour_angle_deg);
    double u = atan(0.99664719 * tan(lat));
    double x = cos(u) + in->elevation_m / 6378140.0 * cos(lat);
    double y = 0.99664719 * sin(u) + in->elevation_m / 6378140.0 * sin(lat);
    double dr = rad(delta);
    double dalpha = atan2(-x * sin(xi) * sin(H), cos(dr) - x * sin(xi) * cos(H));
    double dprime = atan2((sin(dr) - y * sin(xi)) * cos(dalpha), cos(dr) - x * sin(xi) * cos(H));
    double Hp = H - dalpha;
    p.declination_deg = deg(dprime);
    /* topocentric elevation with refraction, zenith and azimuth (3.14 - 3.16) */
    double e0d = deg(asin(sin(lat) * sin(dprime) + cos(lat) * cos(dprime) * cos(Hp))), de = 0;
    if (e0d >= -1.0 * (0.26667 + in->refraction_deg))
        de = (in->pressure_mbar / 1010.0) * (283.0 / (273.0 + in->temperature_C)) * 1.02 /
             (60.0 * tan(rad(e0d + 10.3 / (e0d + 5.11))));
    double e = e0d + de;
    p.zenith_deg = 90.0 - e;
    double gamma = limit360(deg(atan2(sin(Hp), cos(Hp) * sin(lat) - tan(dprime) * cos(lat))));
    p.azimuth_deg = limit360(gamma + 180.0);
    lx_sun_direction(rad(e), rad(p.azimuth_deg), p.dir);
    *out = p;
    return LX_OK;
}
