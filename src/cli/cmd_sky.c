/* cmd_sky.c - `luxcalc sky`: a CIE standard general sky (types 1-15) or a Perez all-weather sky,
 * with the sun placed by altitude and azimuth or by date, time and site (NREL SPA), written as a
 * lat-long luminance EXR (the convention of [sky] type = map) and summarised on stdout. */
#include "cli.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DEG_PER_RAD (180 / CLI_PI)

static const char help[] =
    "usage: luxcalc sky --type cie --number N (--zenith-luminance L | --horizontal-illuminance E)\n"
    "                   SUN [--sun-illuminance E] [--ground-reflectance R] [--size WxH] [-o sky.exr]\n"
    "       luxcalc sky --type perez --direct-normal W/m2 --diffuse-horizontal W/m2 SUN [--day-of-year N]\n"
    "                   [--precipitable-water CM] [-o sky.exr]\n"
    "SUN is --sun-altitude A --sun-azimuth Z (azimuth from north towards east), or\n"
    "       --date YYYY-MM-DD --time HH:MM[:SS] --timezone H --latitude A --longitude A\n"
    "       (local standard time, hours east of Greenwich; north and east positive; NREL SPA).\n"
    "\n"
    "Writes the sky (and the sun disc, half angle 0.2665 deg) as a one-channel lat-long EXR whose\n"
    "values are luminance in cd/m2 (whiteLuminance 1), in the layout `luxcalc irradiance` and\n"
    "[sky] type = map read: +z up, +y north, +x east, theta from +z, phi from +x towards +y, row 0\n"
    "at the zenith. Each pixel is the solid-angle mean of the sky over its patch; the sun disc is\n"
    "spread over the pixels it covers so the map carries exactly its direct normal illuminance.\n"
    "Below the horizon: a ground of luminance R (Dv + Evn sin(altitude)) / pi (default R = 0).\n"
    "\n"
    "  --type T                  cie (ISO 15469 / CIE S 011 general sky) or perez (all-weather)\n"
    "  --number N                cie: the sky type 1..15 (1 overcast ... 12 clear ... 15 turbid)\n"
    "  --zenith-luminance L      cie: Lz (cd/m2)\n"
    "  --horizontal-illuminance E  cie: the sky's diffuse horizontal illuminance Dv (lx)\n"
    "  --sun-illuminance E       the sun's direct normal illuminance (lx; perez: from the model)\n"
    "  --direct-normal, --diffuse-horizontal   perez: DNI and DHI irradiance (W/m2)\n"
    "  --day-of-year N           perez: for the extraterrestrial irradiance (default: from --date)\n"
    "  --size WxH                map size (default 1024x512)\n"
    "  --format F                the summary: table (default), csv or json\n"
    "  -o FILE                   the EXR (atomic); without it only the summary is printed\n"
    "\n"
    "csv columns: type,sun_altitude_deg,sun_azimuth_deg,zenith_cd_m2,diffuse_horizontal_lx,\n"
    "sun_normal_lx,global_horizontal_lx,epsilon,delta\n"
    "\n"
    "example: the CIE clear sky at noon in Golden, Colorado, and the illuminance it gives:\n"
    "  luxcalc sky --type cie --number 12 --zenith-luminance 6000cd/m2 --date 2003-10-17 \\\n"
    "      --time 12:30 --timezone -7 --latitude 39.74deg --longitude -105.18deg \\\n"
    "      --sun-illuminance 80000lx -o /tmp/sky.exr\n"
    "  luxcalc irradiance /tmp/sky.exr --normal 0,0,1 --method fast\n";

typedef struct sky_args {
    const char *type, *number, *lz, *dv, *evn, *dni, *dhi, *doy, *water, *alt, *az, *date, *time, *tz, *lat, *lon;
    const char *ground, *size, *out;
} sky_args;

static int quantity(lx_ctx *ctx, const char *opt, const char *text, lx_quantity q, const char *bare, double *out)
{
    lx_quantity got;
    if (lx_quantity_parse(ctx, text, q, bare, out, &got) != LX_OK || !isfinite(*out)) {
        cli_error("sky", "--%s: %s", opt, lx_ctx_errmsg(ctx));
        return -1;
    }
    return 0;
}

/* A whole number from lo to hi: CLI_USAGE when the text is not a number, CLI_INPUT when it is out of
 * the range (printed), else 0. */
static int whole(const char *opt, const char *text, int lo, int hi, int *out)
{
    char *e;
    errno = 0;
    long v = strtol(text, &e, 10);
    if (*e || e == text) {
        cli_error("sky", "--%s: expected a whole number from %d to %d, got '%s'", opt, lo, hi, text);
        return CLI_USAGE;
    }
    if (errno == ERANGE || v < lo || v > hi) {
        cli_error("sky", "--%s: %s is out of range (%d to %d)", opt, text, lo, hi);
        return CLI_INPUT;
    }
    *out = (int)v;
    return 0;
}

/* The sun's direction from the arguments; *doy gets the day of the year when a date is given. */
static int sun_from_args(lx_ctx *ctx, const sky_args *a, double dir[3], int *doy, double *alt_deg, double *az_deg)
{
    if (a->alt || a->az) {
        if (!a->alt || !a->az || a->date) {
            cli_error("sky", "give --sun-altitude and --sun-azimuth together, or --date and the site");
            return CLI_USAGE;
        }
        double alt, az;
        if (quantity(ctx, "sun-altitude", a->alt, LX_Q_ANGLE, "deg", &alt) || quantity(ctx, "sun-azimuth", a->az, LX_Q_ANGLE, "deg", &az))
            return CLI_USAGE;
        if (!(fabs(alt) <= CLI_PI / 2)) { /* 95 deg is not an 85 deg sun on the other side */
            cli_error("sky", "--sun-altitude: %s is out of range (-90 to 90 deg)", a->alt);
            return CLI_INPUT;
        }
        lx_sun_direction(alt, az, dir);
        *alt_deg = alt * DEG_PER_RAD, *az_deg = az * DEG_PER_RAD;
        return CLI_OK;
    }
    if (!a->date || !a->time || !a->tz || !a->lat || !a->lon) {
        cli_error("sky", "no sun: give --sun-altitude and --sun-azimuth, or --date, --time, --timezone, --latitude and --longitude");
        return CLI_USAGE;
    }
    lx_sun_input in;
    memset(&in, 0, sizeof in);
    int n = 0;
    char tail;
    if (sscanf(a->date, "%d-%d-%d%c", &in.year, &in.month, &in.day, &tail) != 3) {
        cli_error("sky", "--date: expected YYYY-MM-DD, got '%s'", a->date);
        return CLI_USAGE;
    }
    n = sscanf(a->time, "%d:%d:%lf%c", &in.hour, &in.minute, &in.second, &tail);
    if (n != 2 && n != 3) {
        cli_error("sky", "--time: expected HH:MM or HH:MM:SS, got '%s'", a->time);
        return CLI_USAGE;
    }
    double lat, lon;
    if (cli_parse_double(a->tz, &in.timezone_h) != 0) {
        cli_error("sky", "--timezone: expected hours east of Greenwich, got '%s'", a->tz);
        return CLI_USAGE;
    }
    if (quantity(ctx, "latitude", a->lat, LX_Q_ANGLE, "deg", &lat) || quantity(ctx, "longitude", a->lon, LX_Q_ANGLE, "deg", &lon))
        return CLI_USAGE;
    in.latitude_deg = lat * DEG_PER_RAD, in.longitude_deg = lon * DEG_PER_RAD;
    in.delta_t_s = 69, in.pressure_mbar = 1013.25, in.temperature_C = 15, in.refraction_deg = 0.5667;
    lx_sun_position p;
    lx_status st = lx_sun_spa(ctx, &in, &p);
    if (st != LX_OK) return cli_fail("sky", ctx, st); /* a value out of range (latitude 91deg, 2003-02-30): 2 */
    memcpy(dir, p.dir, 3 * sizeof *dir);
    static const int cum[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    int leap = (in.year % 4 == 0 && in.year % 100 != 0) || in.year % 400 == 0;
    *doy = cum[in.month - 1] + in.day + (leap && in.month > 2);
    *alt_deg = 90 - p.zenith_deg, *az_deg = p.azimuth_deg;
    return CLI_OK;
}

static int build_sky(lx_ctx *ctx, const sky_args *a, lx_sky *sky, double *evn, double *alt, double *az)
{
    double dir[3];
    int doy = 0, rc = sun_from_args(ctx, a, dir, &doy, alt, az);
    if (rc != CLI_OK) return rc;
    *evn = 0;
    if (a->evn && quantity(ctx, "sun-illuminance", a->evn, LX_Q_ILLUMINANCE, "lx", evn)) return CLI_USAGE;
    if (!a->type || !strcmp(a->type, "cie")) {
        int number;
        if (!a->number) {
            cli_error("sky", "--type cie needs --number 1..15");
            return CLI_USAGE;
        }
        int e = whole("number", a->number, 1, 15, &number);
        if (e) return e;
        if (!a->lz == !a->dv) {
            cli_error("sky", "give --zenith-luminance or --horizontal-illuminance (one of them)");
            return CLI_USAGE;
        }
        double v;
        if (a->lz ? quantity(ctx, "zenith-luminance", a->lz, LX_Q_LUMINANCE, "cd/m2", &v)
                  : quantity(ctx, "horizontal-illuminance", a->dv, LX_Q_ILLUMINANCE, "lx", &v))
            return CLI_USAGE;
        lx_status st = lx_sky_cie(ctx, number, dir, a->lz ? LX_SKY_BY_ZENITH : LX_SKY_BY_HORIZONTAL, v, sky);
        if (st != LX_OK) return cli_fail("sky", ctx, st);
        return CLI_OK;
    }
    if (strcmp(a->type, "perez")) {
        cli_error("sky", "--type: expected cie or perez, got '%s'", a->type);
        return CLI_USAGE;
    }
    if (!a->dni || !a->dhi) {
        cli_error("sky", "--type perez needs --direct-normal and --diffuse-horizontal (W/m2)");
        return CLI_USAGE;
    }
    lx_perez_input in;
    memset(&in, 0, sizeof in);
    memcpy(in.sun_dir, dir, sizeof in.sun_dir);
    if (quantity(ctx, "direct-normal", a->dni, LX_Q_IRRADIANCE, "W/m2", &in.direct_normal_W_m2) ||
        quantity(ctx, "diffuse-horizontal", a->dhi, LX_Q_IRRADIANCE, "W/m2", &in.diffuse_horizontal_W_m2))
        return CLI_USAGE;
    int e = a->doy ? whole("day-of-year", a->doy, 1, 366, &doy) : 0;
    if (e) return e;
    if (!doy) {
        cli_error("sky", "--type perez with --sun-altitude needs --day-of-year");
        return CLI_USAGE;
    }
    in.day_of_year = doy;
    if (a->water && cli_parse_double(a->water, &in.precipitable_water_cm) != 0) {
        cli_error("sky", "--precipitable-water: expected cm, got '%s'", a->water);
        return CLI_USAGE;
    }
    lx_status st = lx_sky_perez(ctx, &in, sky);
    if (st != LX_OK) return cli_fail("sky", ctx, st);
    if (!a->evn) *evn = sky->sun_normal_lx;
    return CLI_OK;
}

int cmd_sky(int argc, char **argv)
{
    static const struct option opts[] = {
        {"type", required_argument, 0, 1},          {"number", required_argument, 0, 2},
        {"zenith-luminance", required_argument, 0, 3}, {"horizontal-illuminance", required_argument, 0, 4},
        {"sun-illuminance", required_argument, 0, 5}, {"direct-normal", required_argument, 0, 6},
        {"diffuse-horizontal", required_argument, 0, 7}, {"day-of-year", required_argument, 0, 8},
        {"precipitable-water", required_argument, 0, 9}, {"sun-altitude", required_argument, 0, 10},
        {"sun-azimuth", required_argument, 0, 11},  {"date", required_argument, 0, 12},
        {"time", required_argument, 0, 13},         {"timezone", required_argument, 0, 14},
        {"latitude", required_argument, 0, 15},     {"longitude", required_argument, 0, 16},
        {"ground-reflectance", required_argument, 0, 17}, {"size", required_argument, 0, 18},
        {"format", required_argument, 0, 19},       {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    sky_args a;
    memset(&a, 0, sizeof a);
    const char **slot[] = {NULL,    &a.type, &a.number, &a.lz,   &a.dv,  &a.evn, &a.dni, &a.dhi, &a.doy, &a.water,
                           &a.alt,  &a.az,   &a.date,   &a.time, &a.tz,  &a.lat, &a.lon, &a.ground, &a.size};
    cli_format fmt = CLI_FMT_TABLE;
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        if (c >= 1 && c <= 18) *slot[c] = optarg;
        else if (c == 19) {
            int f = cli_format_parse(optarg);
            if (f < 0) {
                cli_error("sky", "--format: expected table, csv or json, got '%s'", optarg);
                return CLI_USAGE;
            }
            fmt = (cli_format)f;
        } else if (c == 'o') a.out = optarg;
        else if (c == 'h') {
            cli_print_help(help);
            return CLI_OK;
        } else
            return cli_bad_option("sky", argv, c);
    }
    if (optind != argc) {
        cli_error("sky", "unexpected argument '%s'", argv[optind]);
        return CLI_USAGE;
    }
    lx_ctx *ctx = cli_ctx("sky");
    if (!ctx) return CLI_RUNTIME;
    lx_sky sky;
    double evn = 0, alt = 0, az = 0;
    int rc = build_sky(ctx, &a, &sky, &evn, &alt, &az);
    lx_sky_map_opts mo;
    memset(&mo, 0, sizeof mo);
    mo.sun_normal_lx = evn;
    if (rc == CLI_OK && a.ground && cli_parse_double(a.ground, &mo.ground_reflectance) != 0) {
        cli_error("sky", "--ground-reflectance: expected 0..1, got '%s'", a.ground);
        rc = CLI_USAGE;
    } else if (rc == CLI_OK && a.ground && !(mo.ground_reflectance >= 0 && mo.ground_reflectance <= 1)) {
        cli_error("sky", "--ground-reflectance: %s is out of range (0 to 1)", a.ground);
        rc = CLI_INPUT;
    }
    if (rc == CLI_OK && a.size) {
        char x, tail;
        if (sscanf(a.size, "%d%c%d%c", &mo.width, &x, &mo.height, &tail) != 3 || (x != 'x' && x != 'X')) {
            cli_error("sky", "--size: expected WxH, got '%s'", a.size);
            rc = CLI_USAGE;
        } else if (mo.width < 1 || mo.height < 1) {
            cli_error("sky", "--size: %s is out of range (at least 1x1)", a.size);
            rc = CLI_INPUT;
        }
    }
    lx_envmap *map = NULL;
    if (rc == CLI_OK && a.out) {
        lx_status st = lx_sky_map(ctx, &sky, &mo, &map);
        if (st == LX_OK) st = lx_envmap_write_exr(ctx, a.out, map, NULL);
        if (st != LX_OK) rc = cli_fail("sky", ctx, st);
        else if (!cli_quiet) fprintf(stderr, "luxcalc: sky: wrote %s (%dx%d)\n", a.out, map->width, map->height);
    }
    if (rc == CLI_OK) {
        static const char *const names[] = {"type", "sun_altitude_deg", "sun_azimuth_deg", "zenith_cd_m2",
                                            "diffuse_horizontal_lx", "sun_normal_lx", "global_horizontal_lx",
                                            "epsilon", "delta"};
        static const char *const units[] = {"", "deg", "deg", "cd/m2", "lx", "lx", "lx", "", ""};
        cli_table *t = cli_table_new(9, names, units);
        char type[32];
        if (sky.model == LX_SKY_MODEL_CIE) snprintf(type, sizeof type, "cie %d", sky.cie_type);
        else snprintf(type, sizeof type, "perez bin %d", sky.perez_bin);
        cli_table_str(t, type);
        cli_table_num(t, alt);
        cli_table_num(t, az);
        cli_table_num(t, sky.zenith_cd_m2);
        cli_table_num(t, sky.diffuse_horizontal_lx);
        cli_table_num(t, evn);
        cli_table_num(t, sky.diffuse_horizontal_lx + (sky.sun_dir[2] > 0 ? evn * sky.sun_dir[2] : 0));
        cli_table_num(t, sky.epsilon);
        cli_table_num(t, sky.delta);
        if (cli_table_write(t, fmt, stdout, 0) != 0) rc = CLI_INPUT;
        cli_table_free(t);
    }
    lx_envmap_free(map);
    lx_ctx_destroy(ctx);
    return rc;
}
