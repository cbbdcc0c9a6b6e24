/* scene_private.h - internals shared by the scene files (scene_read.c, scene_entities.c,
 * scene_plan.c, scene_eval.c, scene_sky.c, scene_spectral.c); never installed. */
#ifndef LX_SCENE_PRIVATE_H
#define LX_SCENE_PRIVATE_H

#include "lighting/lighting_private.h"
#include "radiance/radiance_private.h"


/* The deliverable's keys of a [luminaire] section (design_read.c): maintenance factor or scheme,
 * power, emergency operation. */
typedef struct scene__lum_design {
    int has_mf, has_power, has_eflux, mode;
    double mf, power, eflux;
    char *maint;
    long mf_line, maint_line, power_line, eflux_line, mode_line;
} scene__lum_design;

/* Raw keys of a [luminaire] section, checked when the section ends. */
typedef struct scene__lum_raw {
    char *name;
    const char *file;
    long line;
    int active;
    char *type, *lum_file, *spd, *spectrum;
    long type_line, lum_file_line, spd_line;
    int has_pos, has_aim, has_rotate, has_flux, has_intensity, has_exponent, has_beam, has_luminance,
        has_radius, has_width, has_length, has_cct, has_multiplier;
    double pos[3], aim[3], rotate, flux, intensity, exponent, beam, luminance, radius, width, length, cct,
        multiplier;
    long flux_line, cct_line;
    scene__lum_design design;
} scene__lum_raw;

/* The deliverable's keys of a [receiver] section (design_read.c): cylindrical, semicylindrical. */
typedef struct scene__rec_design {
    int cyl, has_facing;
    double facing[3];
    long line;
} scene__rec_design;

/* Raw keys of a [receiver] section. */
typedef struct scene__rec_raw {
    char *name;
    const char *file;
    long line;
    int active;
    char *type;
    int has_pos, has_normal, has_refl, has_spacing, has_points;
    int nx, ny, nz; /* values given for x, y, z (0: key absent) */
    double pos[3], normal[3], refl, spacing, xr[2], yr[2], zr[2];
    long points[2];
    scene__rec_design design;
} scene__rec_raw;

void lx__scene_lum_raw_init(scene__lum_raw *r, const char *name, const char *file, long line);
void lx__scene_lum_raw_free(scene__lum_raw *r);
lx_status lx__scene_lum_key(lx_ctx *ctx, scene__lum_raw *r, const char *file, long line, const char *key,
                            const char *value);
lx_status lx__scene_lum_finish(lx_ctx *ctx, lx_scene *sc, scene__lum_raw *r);

void lx__scene_rec_raw_init(scene__rec_raw *r, const char *name, const char *file, long line);
void lx__scene_rec_raw_free(scene__rec_raw *r);
lx_status lx__scene_rec_key(lx_ctx *ctx, scene__rec_raw *r, const char *file, long line, const char *key,
                            const char *value);
lx_status lx__scene_rec_finish(lx_ctx *ctx, lx_scene *sc, scene__rec_raw *r);

lx_status lx__scene_sky_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key,
                            const char *value);

/* Daylight (scene_daylight.c): the [sky] keys of cie and perez skies (*known 0 when key is none
 * of them), the raw [sun] keys, [observer NAME] sections, and the whole-scene checks that build
 * the sun's direction (SPA) and the sky model. */
typedef struct scene__sun_raw {
    int has_dir, has_alt, has_az, has_date, has_time, has_tz, has_lat, has_lon, has_illum;
    double dir[3], alt, az, tz, lat, lon, illum, elev, pressure, temp, delta_t;
    int y, mo, d, h, mi;
    double s;
} scene__sun_raw;
lx_status lx__scene_sky_daylight_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key,
                                     const char *value, int *known);
void lx__scene_sun_raw_init(scene__sun_raw *r);
lx_status lx__scene_sun_key(lx_ctx *ctx, lx_scene *sc, scene__sun_raw *r, const char *file, long line, const char *key,
                            const char *value);
lx_status lx__scene_obs_open(lx_ctx *ctx, lx_scene *sc, const char *name, const char *file, long line);
lx_status lx__scene_obs_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value);
lx_status lx__scene_obs_finish(lx_ctx *ctx, lx_scene *sc);
lx_status lx__scene_daylight_finish(lx_ctx *ctx, lx_scene *sc, const scene__sun_raw *sun);

/* A new empty scene (defaults set), its whole-scene checks, and a kept copy of a file name. */
lx_scene *lx__scene_new(const char *file);
lx_status lx__scene_finish(lx_ctx *ctx, lx_scene *sc);
char *lx__scene_keep_name(lx_scene *sc, const char *name);

/* Parses nmin..nmax comma-separated numbers of quantity q (LX_Q_NONE: plain numbers only) into
 * out; bare numbers take the unit of the last value, else bare_unit, else are an error naming
 * the key. *count (may be NULL) receives how many. */
lx_status lx__scene_parse_vec(lx_ctx *ctx, const char *file, long line, const char *key, const char *value,
                              int nmin, int nmax, lx_quantity q, const char *bare_unit, double *out, int *count);

/* rel resolved against the directory of base_file (malloc'ed). */
char *lx__scene_resolve(const char *base_file, const char *rel);

/* ---- geometry and evaluation ---- */
/* The luminaire's frame: ex (C0), ey (C90), ez (= -aim, up from the nadir). */
void lx__scene_frame(const lx_scene_luminaire *l, double ex[3], double ey[3], double ez[3]);
/* The size the five-times rule uses: disk diameter, rectangle (or opening) diagonal; 0 for points. */
double lx__scene_lum_size(const lx_scene_luminaire *l);
/* The luminous opening along the luminaire's ex (C0) and ey (C90) axes: a rectangle's width and
 * length; a file luminaire's length (C0-C180) and width (C90-C270), as LM-63 and EULUMDAT define
 * them; a disk's diameter (both). 0 for points. */
void lx__scene_lum_extent(const lx_scene_luminaire *l, double *along_x, double *along_y);
/* Total flux of a file luminaire's table times its scale (lm). */
double lx__scene_file_flux(const lx_scene_luminaire *l);

/* ---- rooms: the keys of [room], [surface], [obstruction] (room_read.c) ---- */
enum { SCENE__ROOM = 1, SCENE__SURFACE = 2, SCENE__OBSTRUCTION = 3 };
/* Raw keys of a [room], [surface] or [obstruction] section, checked when the section ends. */
typedef struct scene__room_raw {
    int kind; /* SCENE__ROOM ... (0: none open) */
    char *name;
    const char *file;
    long line;
    int has_origin, has_size, has_corner, has_edge1, has_edge2, has_min, has_max, has_refl[7];
    double origin[3], size[3], corner[3], edge1[3], edge2[3], min[3], max[3], refl[7];
    long refl_line[7]; /* room: floor, ceiling, wall_xmin .. wall_ymax, walls; others: [0] reflectance */
} scene__room_raw;
lx_status lx__room_section(lx_ctx *ctx, scene__room_raw *r, int kind, const char *name, const char *file, long line);
lx_status lx__room_key(lx_ctx *ctx, scene__room_raw *r, const char *file, long line, const char *key, const char *value);
lx_status lx__room_section_end(lx_ctx *ctx, lx_scene *sc, scene__room_raw *r);
void lx__room_raw_free(scene__room_raw *r);
/* The [scene] keys interreflection_tolerance and patch_size (1 when key is one of them). */
int lx__room_scene_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value,
                       lx_status *st);
/* The whole-scene checks of rooms (luminaires and receivers inside a room and outside every
 * obstruction, rooms not overlapping, surfaces inside one room or none). */
lx_status lx__room_scene_check(lx_ctx *ctx, const lx_scene *sc);
void lx__room_scene_free(lx_scene *sc);
/* The planner's part for occlusion and interreflection (room_plan.c), after the near field. */
lx_status lx__room_plan(lx_ctx *ctx, const lx_scene *sc, int backend, lx_scene_plan *p);
void lx__room_plan_free(lx_scene_plan *p);
/* Evaluation's part: the solve and the gather; adds indirect_lx to res (room_eval.c). day: the
 * daylight of the evaluation (NULL: none), solved with the same form factors. */
struct lx__daylight;
lx_status lx__room_eval(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, long only, struct lx__daylight *day,
                        lx_scene_result *res);

/* What a luminaire needs during evaluation (and the planner's probes): its frame, area and the
 * effects that shape its intensity. */
typedef struct lx__scene_lum {
    const lx_scene_luminaire *l;
    double ex[3], ey[3], ez[3];
    double area;
    int spot_falloff, gonio, cosine;
    double k; /* the plan's factor of its light (maintenance, emergency operation): lx_scene_plan.lum_scale */
} lx__scene_lum;
/* Luminaire l of scene sc as the plan evaluates it. */
void lx__scene_lum_init(lx__scene_lum *e, const lx_scene *sc, size_t l, const lx_scene_plan *plan);
/* The luminaire's intensity (cd, before the plan's factor k) towards the unit direction u (from the
 * luminaire), or that of a fraction frac of its luminous area; counts its spot and table work. */
double lx__scene_intensity(lx_counters *cnt, const lx__scene_lum *le, const double u[3], double frac);
/* E at receiver point q (unit normal n) of the luminaire as a point source at s carrying frac of
 * its intensity (the point model; counts its spot and table work). */
double lx__scene_point_E(lx_ctx *ctx, const lx__scene_lum *le, const double s[3], const double q[3], const double n[3],
                         double frac);

/* The paths of lx_scene_plan.near: the point model, the luminous area integrated in patches, a
 * disk or rectangle in closed form. */
enum { LX__PATH_POINT = 0, LX__PATH_AREA = 1, LX__PATH_CLOSED = 2 };

/* ---- the one direct-lighting path (scene_eval.c): receiver points and room patches alike ---- */
/* Occluders a contribution is tested against (NULL: none can cut it). */
struct lx__room_occ;
typedef struct lx__scene_vis {
    const struct lx__room_occ *occ;
    int n_occ;
    int skip; /* an occluder the receiver is part of (never blocks it), -1 none */
} lx__scene_vis;
/* The illuminance (lx) luminaire le gives at q (unit normal n) by `path` (LX__PATH_*: the point
 * model, the luminous area integrated to near_tol, a closed form). With vis every ray is tested;
 * an area luminaire partly hidden (its 3 x 3 probe points disagree) is integrated over its
 * luminous area with each cell's visible fraction (the visible part only), one wholly hidden gives
 * 0. Adds its work to cnt. Thread-safe for distinct cnt. */
double lx__scene_lum_E(lx_counters *cnt, const lx__scene_lum *le, const double q[3], const double n[3], int path,
                       double near_tol, const lx__scene_vis *vis);
/* The path of luminaire le for a receiver point the planner did not see (a room's patch): the
 * planner's rule for one pair (closed forms for disks and rectangles, the point model's probed
 * error against tol for IES/LDT openings, [effects] near_field). Counts its probes in cnt. */
int lx__scene_path(lx_counters *cnt, const lx_scene *sc, const lx__scene_lum *le, const double q[3], const double n[3],
                   double tol);

/* Sky illuminance on a receiver with unit normal n (lx): sky plus ground. Counts its work. */
lx_status lx__scene_sky_eval(lx_ctx *ctx, const lx_scene *sc, const void *map, const double n[3], double *E_lx);
/* Loads the map of a LX_SKY_MAP scene into *map (free with lx__scene_sky_map_free). */
lx_status lx__scene_sky_map_load(lx_ctx *ctx, const lx_scene *sc, void **map);
void lx__scene_sky_map_free(void *map);
/* The loaded map's luminance (cd/m2, times the scene's scale) towards unit w: its pixel. */
double lx__scene_sky_map_L(const void *map, const double w[3]);
/* The sky's horizontal illuminance outside: the sky alone, and with the sun (the ground's E_h). */
void lx__scene_sky_horizontal(const lx_scene *sc, const void *map, double *sky_lx, double *with_sun_lx);
/* The sun's part of lx__scene_sky_eval on a receiver with unit normal n (Evn max(0, n . s)). */
double lx__scene_sun_part(const lx_scene *sc, const double n[3]);

/* Spectral weights of a source: per lux of its illuminance, the X, Z (Y = 1) and melanopic
 * irradiance (W/m2). Counts the spectra it integrates. */
typedef struct scene__spec { double x_per_lx, z_per_lx, mel_W_per_lx; int valid; } scene__spec;
lx_status lx__scene_spectrum_weights(lx_ctx *ctx, const char *file, long line, const lx_spd *spd, double cct_K,
                                     scene__spec *out);

/* ---- daylight: openings and the light through them (daylight_*.c, scene_glare.c; README "Daylight") ---- */
/* [opening NAME]: a new opening, its keys; the whole-scene checks (which room and face, inside it,
 * overlaps); freeing. */
lx_status lx__scene_open_section(lx_ctx *ctx, lx_scene *sc, const char *name, const char *file, long line);
lx_status lx__scene_open_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value);
lx_status lx__daylight_scene_check(lx_ctx *ctx, lx_scene *sc);
void lx__daylight_scene_free(lx_scene *sc);
/* The planner's part: the daylight effect (before the rooms' part, whose mesh takes its openings
 * and share), then the reasons and estimates that need the rooms' plan. */
lx_status lx__daylight_plan(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p);
lx_status lx__daylight_plan_after(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p);
/* Hooks of the rooms' evaluation (room_eval.c): the daylight's own solve with the form factors F
 * of mesh m; the luminaires' interreflected illuminance at the observers' eyes from the elements'
 * exitance Be (res->observer_indirect_lx). */
struct lx__room_mesh;
lx_status lx__daylight_room(lx_ctx *ctx, struct lx__daylight *d, const struct lx__room_mesh *m, const double *F);
lx_status lx__glare_room_background(lx_ctx *ctx, const lx_scene *sc, const struct lx__room_mesh *m, const double *Be,
                                    int backend, lx_scene_result *res);

#endif /* LX_SCENE_PRIVATE_H */
