/* radiance_private.h - the radiance-field layer's internals (never installed): exact pixel
 * geometry of lat-long maps, the irradiance back ends, cube-map texel integrals and spectral
 * channel names. */
#ifndef LX_RADIANCE_PRIVATE_H
#define LX_RADIANCE_PRIVATE_H

#include "spectral/spectral_private.h"

/* Per-row and per-column factors of the exact pixel integrals of a w x h lat-long map: a pixel's
 * solid angle is row_sr[j] * dphi and its first moment (integral of omega) is
 * (row_s2[j] col_gx[i], row_s2[j] col_gy[i], row_sc[j] dphi). */
typedef struct lx__llgeom {
    int w, h;
    double dphi;    /* 2 pi / w */
    double *row_sr; /* cos t0 - cos t1 */
    double *row_s2; /* integral of sin^2 t dt over the row */
    double *row_sc; /* integral of sin t cos t dt over the row */
    double *col_gx; /* sin p1 - sin p0 */
    double *col_gy; /* cos p0 - cos p1 */
} lx__llgeom;
lx_status lx__llgeom_init(lx_ctx *ctx, lx__llgeom *g, int w, int h);
void lx__llgeom_free(lx__llgeom *g);

/* The pixels the horizon of a normal crosses (irradiance_horizon.c): sines and cosines of the
 * pixel edges of a w x h lat-long map, the lit half-width of a parallel, the classification of a
 * row and the exact integral of max(0, n . w) over one pixel. */
typedef struct lx__hz {
    int w, h;
    double dphi, dth;
    double *ts, *tc; /* sin, cos of theta at the h + 1 row edges */
    double *ps, *pc; /* sin, cos of phi at the w + 1 column edges */
} lx__hz;
lx_status lx__hz_init(lx_ctx *ctx, lx__hz *z, int w, int h);
void lx__hz_free(lx__hz *z);
/* The lit half-width about phi_n of the parallel with sin s, cos c for a unit normal with z
 * component nz and st = sqrt(nx^2 + ny^2): acos(-nz c / (st s)) in [0, pi], 4 when the whole
 * parallel is lit, -1 when none of it is. */
double lx__hz_alpha(double nz, double st, double s, double c);
/* Row j between parallels of lit half-widths a0 and a1 (phin = phi_n in [0, 2 pi)): DARK (no lit
 * pixel), LIT (every pixel wholly lit) or RANGES: columns [in_lo, in_hi) wholly lit, [out_lo,
 * in_lo) and [in_hi, out_hi) possibly crossed by the horizon (lx__hz_pixel), the others dark;
 * indices mod w, in_lo <= in_hi, out_lo <= in_lo, in_hi <= out_hi, out_hi - out_lo <= w. */
enum { LX__HZ_DARK, LX__HZ_LIT, LX__HZ_RANGES };
int lx__hz_row(int w, double dphi, double phin, double a0, double a1, long *in_lo, long *in_hi, long *out_lo, long *out_hi);
/* One normal as the horizon code uses it: n, sqrt(nx^2 + ny^2), phi_n in [0, 2 pi) with its cosine
 * and sine, the lit half-widths of the h + 1 row edges with their cosines and sines (alpha: 3 (h +
 * 1) doubles, filled by lx__hz_ray_rows), and a cache of the meridians' horizon crossings (tz: 3 (w +
 * 1) doubles, angle, sine, cosine; valid where stamp[i] == gen). Scratch: LX__HZ_RAY_SCRATCH doubles (stamps included,
 * zeroed once), gen a counter kept with it. */
typedef struct lx__hz_ray {
    double n[3], st, phin, cphin, sphin;
    double *alpha;
    double *tz;
    unsigned *stamp, gen;
} lx__hz_ray;
#define LX__HZ_RAY_SCRATCH(w, h) (3 * ((size_t)(h) + 1) + 4 * ((size_t)(w) + 1))
void lx__hz_ray_init(lx__hz_ray *r, const double n[3], double *alpha, double *tz, unsigned *stamp, unsigned *gen);
/* The lit half-widths of row edges k0..k1 (they depend on n_z and st only). */
void lx__hz_ray_rows(lx__hz_ray *r, const lx__hz *z, int k0, int k1);
/* The exact integral of max(0, n . w) over pixel (j, i) (closed form). check: first test whether
 * the pixel is wholly lit or dark (for EACH rows; RANGES rows vouch for their crossed pixels). */
double lx__hz_pixel(const lx__hz *z, const lx__llgeom *g, const lx__hz_ray *r, int j, int i, int check);

/* sum over the rows 0 .. rows - 1 of a w x h lat-long map of L (one double per pixel) times the
 * exact integral of max(0, n . w) over each pixel (n unit): the scene's EXR sky. */
lx_status lx__irr_rows_exact(lx_ctx *ctx, int w, int h, const double *L, int rows, const double n[3], double *sum);
/* Makes a clamped sum exact: adds to out (n_dirs x channels) the difference between the exact
 * integral of max(0, n . w) and max(0, n . m_p), times L_p, over the pixels each normal's horizon
 * crosses (brute force on the CPU and on OpenCL). */
lx_status lx__irr_horizon_fix(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads, double *out);

/* The irradiance back ends: n_dirs unit normals (3 doubles each) -> out[n * channels]. */
lx_status lx__irr_brute_cpu(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads,
                            double *out);
lx_status lx__irr_brute_cl(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, double *out);
lx_status lx__irr_fast(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads,
                       double *out);
lx_status lx__irr_sh9_map(lx_ctx *ctx, const lx_sh9 *sh, lx_sh9_window window, lx_envmap *out);

/* Cube maps (envmap_cube.c). lx__cube_frame[f] = {axis, u, v}: the luxcalc directions of face f's
 * normal, image column and image row (downwards). A face-local table holds, per texel of an N x N
 * face (row-major), LX__CUBE_NT exact integrals over the texel in the frame (axis n, u, v):
 * solid angle, first moment (n, u, v), second moments (nn, uu, vv, nu, nv, uv). */
#define LX__CUBE_NT 10
extern const double lx__cube_frame[6][3][3];
double *lx__cube_table(int n); /* malloc'd N * N * LX__CUBE_NT doubles, NULL on no memory */
lx_status lx__sh9_project_cube(lx_ctx *ctx, const lx_envmap *map, lx_sh9 *out);
lx_status lx__irr_cube(lx_ctx *ctx, const lx_envmap *map, size_t n_dirs, const double *dirs, int threads, int fast,
                       double *out);

/* Parses a Fichet et al. 2021 spectral channel name: *kind 0-3 for S0-S3 (emissive), 4 for T
 * (reflective), wavelength in nm; returns 0 on success, -1 when the name is not spectral. */
int lx__spectral_channel(const char *name, int *kind, double *lambda_nm);

/* Skies (sky.c, sky_perez.c, sky_map.c). */
/* u = v / |v|, or LX_EINVAL naming `what` for a zero or non-finite vector. */
lx_status lx__unit3(lx_ctx *ctx, const char *what, const double v[3], double u[3]);
/* Gauss-Legendre nodes x and weights w on [-1, 1] (n <= 1024). */
void lx__gauss_legendre(int n, double *x, double *w);
/* The sky's unscaled relative luminance (gradation x indicatrix) towards unit dir; 0 below the horizon. */
double lx__sky_rel(const lx_sky *s, const double dir[3]);
/* Integral of rel max(0, n . w) d omega over the sky for unit n, with nodes-point rules x, w. */
double lx__sky_integral(const lx_sky *s, const double n[3], int nodes, const double *x, const double *w);
/* The horizontal integral of rel, converged to 1e-12 relative. */
double lx__sky_horizontal_rel(const lx_sky *s);
/* Sets zenith_cd_m2 and diffuse_horizontal_lx of a sky whose shape is set. */
lx_status lx__sky_scale(lx_ctx *ctx, lx_sky *s, lx_sky_scale scale, double value);

#endif /* LX_RADIANCE_PRIVATE_H */
