/* design_private.h - the deliverable's internals (scene layer; never installed): the scene file's
 * maintenance schemes, luminaire power and emergency keys, and what the reader keeps until the
 * whole scene is read (design_read.c). */
#ifndef LX_DESIGN_PRIVATE_H
#define LX_DESIGN_PRIVATE_H

#include "scene/scene_private.h"

/* A factor typed as a value, or as a table (t_i, v_i) against time, read at a time (design_read.c). */
typedef struct lx__factor {
    int given;     /* 0: not given (1) */
    size_t n;      /* 0: a value; else table points */
    double value;  /* the value, or the factor read off the table at the scheme's time */
    double *t_s, *v;
    long line;
} lx__factor;

/* A maintenance scheme's raw keys, checked when the whole scene is read. */
typedef struct lx__maint_raw {
    lx__factor f[4];           /* LLMF, LSF, LMF, RSMF */
    int has_burning, has_cleaning, has_room_cleaning;
    double burning_s, cleaning_s, room_cleaning_s;
    long burning_line, cleaning_line, room_cleaning_line;
} lx__maint_raw;

/* An [area NAME] section's raw keys, turned into areas and receivers once the scene is read. */
typedef struct lx__area_raw {
    char *name, *room;
    const char *file;
    long line, room_line;
    int type;                  /* lx_area_kind of the section (-1: not given) */
    long type_line;
    int nx, ny, nz;            /* values given for x, y, z */
    double x[2], y[2], z[2];
    int has_surround, has_background, has_margin, has_spacing, rounding, has_from, has_to, has_width;
    double surround, background, margin, spacing, from[3], to[3], width;
    long surround_line, background_line, margin_line;
    scene__rec_design cyl;
} lx__area_raw;

/* An [observer] section's keys for several eye positions and directions of view. */
typedef struct lx__obs_raw {
    long line;                 /* 0: none given */
    int nx, ny, nz, n_dir;
    double x[2], y[2], z, spacing, step, dir[8];
} lx__obs_raw;

/* lx_scene_design.internal */
typedef struct lx__design {
    lx__maint_raw *maint;      /* parallel to lx_scene_design.maint */
    int section;               /* the open design section (LX__DSEC_*), 0 none */
    int scene_has_mf;
    double scene_mf;
    long scene_mf_line;
    char *scene_maint;
    const char *scene_file;    /* the file of [scene] maintenance */
    long scene_maint_line;
    char **lum_maint_name;     /* n_lum: the scheme a luminaire names (NULL: none), resolved at the end */
    long *lum_maint_line;      /* n_lum: its line */
    long *lum_mf_line;         /* n_lum: the line of its maintenance_factor (0: none) */
    size_t n_lum;              /* the per-luminaire arrays' length */
    lx__area_raw *area;        /* [area NAME] sections */
    size_t n_area;
    void *req;                 /* [requirement NAME] sections (design_check.c) */
    size_t n_req;
    lx__obs_raw *obs_raw;      /* per [observer] section, as read */
    size_t n_obs_raw;
    /* [energy] (design_energy.c) */
    int energy, has_area, constant, has[9];
    long energy_line;
    const char *energy_file;
    double e[9];               /* area, t_D, t_N, F_O, F_DS, F_DC, P_pc, P_em, t_em */
} lx__design;

enum { LX__DSEC_NONE = 0, LX__DSEC_MAINT = 1, LX__DSEC_AREA = 2, LX__DSEC_REQ = 3, LX__DSEC_ENERGY = 4 };

/* ---- energy (design_energy.c) ---- */
lx_status lx__energy_open(lx_ctx *ctx, lx_scene *sc, const char *file, long line);
lx_status lx__energy_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value);

/* ---- observers at several positions and directions (design_observers.c) ---- */
/* [observer] keys x, y, z, spacing, directions, direction_step: 1 when key is one. */
int lx__design_obs_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value,
                       lx_status *st);
/* Each [observer] section becomes one observer per position and direction (lx_scene_design.obs_group). */
lx_status lx__design_obs_expand(lx_ctx *ctx, lx_scene *sc);

/* ---- requirements (design_check.c) ---- */
lx_status lx__req_open(lx_ctx *ctx, lx_scene *sc, const char *name, const char *file, long line);
lx_status lx__req_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value);
/* Resolves each requirement's area; an error names the key whose quantity nothing computes. */
lx_status lx__req_finish(lx_ctx *ctx, lx_scene *sc);
void lx__req_free(lx_scene *sc);

/* ---- EN 12464-1 areas (design_areas.c) ---- */
lx_status lx__area_open(lx_ctx *ctx, lx_scene *sc, const char *name, const char *file, long line);
lx_status lx__area_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value);
/* Every [area] becomes its areas (a task area and its bands) and their receivers. */
lx_status lx__area_finish(lx_ctx *ctx, lx_scene *sc);
void lx__area_free(lx_scene *sc);
/* Grows the per-receiver arrays of the design to the scene's receivers (a receiver just appended). */
lx_status lx__design_rec_grow(lx_scene *sc);
/* The same to n receivers (before one is appended). */
lx_status lx__design_rec_grow_to(lx_scene *sc, size_t n);

/* ---- cylindrical and semi-cylindrical illuminance (design_cylinder.c) ---- */
/* E_z (facing NULL) or E_sz (facing: unit horizontal) of luminaire le at q, times the plan's factor;
 * a luminous area integrated to tol; with vis its rays are tested. */
double lx__design_cyl_E(lx_counters *cnt, const lx__scene_lum *le, const double q[3], const double *facing, double tol,
                        const lx__scene_vis *vis);
/* res->cylindrical_lx, semicylindrical_lx, modelling when some receiver asks (NaN elsewhere). */
lx_status lx__design_cyl_alloc(lx_ctx *ctx, const lx_scene *sc, lx_scene_result *res);
/* The luminaires' direct E_z and E_sz at the receivers that ask (only >= 0: that luminaire alone). */
void lx__design_cyl_direct(lx_counters *cnt, const lx_scene *sc, const lx_scene_plan *plan, const lx__scene_lum *le,
                           const lx__scene_vis *vis, long only, lx_scene_result *res);
/* The interreflected part from the room's elements of exitance Be, to tol of each point's total. */
struct lx__room_mesh;
lx_status lx__design_room_cylinder(lx_ctx *ctx, const lx_scene *sc, const struct lx__room_mesh *m, const double *Be,
                                   int backend, double tol, lx_scene_result *res);
/* E_z / E_h at the cylindrical receivers facing up (after the interreflected part is in E_lx). */
void lx__design_cyl_modelling(const lx_scene *sc, lx_scene_result *res);

/* A new design (every array empty) and its release with the scene. */
lx_status lx__design_new(lx_scene *sc);
void lx__design_free(lx_scene *sc);

/* [luminaire] keys of the deliverable: 1 when key is one (its status in *st). */
int lx__design_lum_key(lx_ctx *ctx, scene__lum_design *d, const char *file, long line, const char *key,
                       const char *value, lx_status *st);
void lx__design_lum_raw_free(scene__lum_design *d);
/* The luminaire just appended to sc->lum takes its design keys. */
lx_status lx__design_lum_finish(lx_ctx *ctx, lx_scene *sc, scene__lum_design *d);
/* [receiver] keys of the deliverable (cylindrical, semicylindrical): 1 when key is one; the
 * receiver just appended to sc->rec takes them. */
int lx__design_rec_key(lx_ctx *ctx, scene__rec_design *d, const char *file, long line, const char *key,
                       const char *value, lx_status *st);
lx_status lx__design_rec_finish(lx_ctx *ctx, lx_scene *sc, const scene__rec_design *d);
/* [scene] keys of the deliverable (maintenance_factor, maintenance): 1 when key is one. */
int lx__design_scene_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value,
                         lx_status *st);
/* A section of the deliverable by its kind ("maintenance"): its LX__DSEC_* (0 when kind is none);
 * opening it (named), its keys. */
int lx__design_section_kind(const char *kind);
lx_status lx__design_open(lx_ctx *ctx, lx_scene *sc, int sec, const char *name, const char *file, long line);
lx_status lx__design_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value);
/* The whole-scene step, after every section is read: schemes evaluated, references resolved. */
lx_status lx__design_finish(lx_ctx *ctx, lx_scene *sc);

#endif /* LX_DESIGN_PRIVATE_H */
