/* scene_eval.c - evaluates a planned scene: each luminaire's contribution at each receiver point
 * computed once (point law or near-field patches) and summed (linearity), plus the sky, the
 * Lambertian luminance and the spectral quantities; counts the work per effect. */
#include "scene/daylight_private.h"
#include "scene/design_private.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void lx_ctx_counters(const lx_ctx *ctx, lx_counters *out)
{
    if (!out) return;
    if (!ctx) memset(out, 0, sizeof *out);
    else *out = ctx->counters;
}

void lx_ctx_counters_reset(lx_ctx *ctx)
{
    if (ctx) memset(&ctx->counters, 0, sizeof ctx->counters);
}

void lx_scene_result_free(lx_scene_result *res)
{
    if (!res) return;
    lx__free(res->first);
    lx__free(res->E_lx);
    lx__free(res->contrib_lx);
    lx__free(res->L_cd_m2);
    lx__free(res->cct_K);
    lx__free(res->duv);
    lx__free(res->melanopic_edi_lx);
    lx__free(res->direct_lx);
    lx__free(res->indirect_lx);
    lx__free(res->daylight_lx);
    lx__free(res->daylight_factor);
    lx__free(res->sky_component);
    lx__free(res->externally_reflected);
    lx__free(res->internally_reflected);
    lx__free(res->observer_indirect_lx);
    lx__free(res->cylindrical_lx);
    lx__free(res->semicylindrical_lx);
    lx__free(res->modelling);
    for (size_t i = 0; i < res->n_surfaces; i++) lx__free(res->surfaces[i].name);
    lx__free(res->surfaces);
    lx__free(res);
}

typedef lx__scene_lum lum_eval;

void lx__scene_lum_init(lx__scene_lum *e, const lx_scene *sc, size_t li, const lx_scene_plan *plan)
{
    const lx_scene_luminaire *l = &sc->lum[li];
    e->l = l;
    e->k = plan->lum_scale ? plan->lum_scale[li] : 1;
    lx__scene_frame(l, e->ex, e->ey, e->ez);
    e->area = l->radius_m > 0 ? LX__PI * l->radius_m * l->radius_m : l->width_m * l->length_m;
    e->spot_falloff = plan->on[LX_EFFECT_SPOT_FALLOFF];
    e->gonio = plan->on[LX_EFFECT_GONIOMETRIC];
    e->cosine = plan->on[LX_EFFECT_COSINE];
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Intensity (cd) of the whole luminaire (frac = 1) or of a fraction of its luminous area towards
 * the unit direction u (from the luminaire to the receiver). */
static double intensity(lx_counters *cnt, const lum_eval *le, const double u[3], double frac)
{
    const lx_scene_luminaire *l = le->l;
    switch (l->kind) {
    case LX_SLUM_POINT: return l->intensity_cd * frac;
    case LX_SLUM_SPOT: {
        double c = -dot(u, le->ez); /* cosine of the angle from the spot axis (aim = -ez) */
        if (!le->spot_falloff) return c > 0 ? l->intensity_cd * frac : 0;
        cnt->spot_evaluations++;
        return l->intensity_cd * frac * lx_warn_lobe(l->exponent, acos(c > 1 ? 1 : c < -1 ? -1 : c));
    }
    case LX_SLUM_DISK:
    case LX_SLUM_RECT: {
        double c = -dot(u, le->ez); /* Lambertian emitter facing aim: I = L A cos(theta) */
        return c > 0 ? l->luminance_cd_m2 * le->area * c * frac : 0;
    }
    case LX_SLUM_FILE:
        if (!le->gonio) return l->flux_lm / (4 * LX__PI) * frac;
        cnt->goniometric_lookups++;
        return l->scale * frac *
               lx_luminaire_intensity_dir(l->lum, LX_INTERP_BILINEAR, dot(u, le->ex), dot(u, le->ey), dot(u, le->ez));
    }
    return 0;
}

double lx__scene_intensity(lx_counters *cnt, const lx__scene_lum *le, const double u[3], double frac)
{
    return intensity(cnt, le, u, frac);
}

/* E at receiver point q (normal n) from a point source at s with intensity I(u) scaled by frac;
 * with vis, 0 when an occluder cuts the segment. */
static double point_E(lx_counters *cnt, const lx__scene_lum *le, const double s[3], const double q[3], const double n[3],
                      double frac, const lx__scene_vis *vis)
{
    double v[3] = {q[0] - s[0], q[1] - s[1], q[2] - s[2]};
    double d2 = dot(v, v);
    int e = 0; /* closer than 1.5e-154 m d2 underflows: the vector scaled by 2^600 (exact), 1/d2 by 2^1200 */
    if (!(d2 >= DBL_MIN)) {
        if (v[0] == 0 && v[1] == 0 && v[2] == 0) return NAN; /* the source at the point: E is undefined */
        for (int k = 0; k < 3; k++) v[k] = ldexp(v[k], 600);
        d2 = dot(v, v), e = 1200;
    }
    double d = sqrt(d2);
    double u[3] = {v[0] / d, v[1] / d, v[2] / d};
    double cx = le->cosine ? -dot(n, u) : 1; /* cos(xi): the ray arrives against the normal */
    if (cx <= 0) return 0;
    if (vis) {
        cnt->visibility_tests++;
        if (!lx__room_visible(vis->occ, vis->n_occ, s, q, vis->skip, -1)) return 0;
    }
    return ldexp(intensity(cnt, le, u, frac) * cx / d2, e); /* beyond the range: infinite, refused by check_finite */
}

double lx__scene_point_E(lx_ctx *ctx, const lx__scene_lum *le, const double s[3], const double q[3], const double n[3],
                         double frac)
{
    return point_E(&ctx->counters, le, s, q, n, frac, NULL);
}

/* The near field shares the grid engine's scheme (lx__area_cell / lx__area_refine in grid.c):
 * rectangles n x n cells, disks n rings of equal area x 2n sectors, each cell a point source
 * carrying its share of the intensity; n doubles until the Richardson-extrapolated estimate (the
 * midpoint rule's error is even in the cell size) changes by less than tol, or 512 per side.
 * With vis, each cell's rays are tested: only the visible part of the area is integrated. */
typedef struct near_arg {
    lx_counters *cnt;
    const lum_eval *le;
    const double *q, *n;
    const lx__scene_vis *vis;
} near_arg;

static double near_mean(void *arg, int lev)
{
    const near_arg *A = arg;
    const lx_scene_luminaire *l = A->le->l;
    int circular = l->radius_m > 0;
    double w, len;
    lx__scene_lum_extent(l, &w, &len);
    size_t cells = lx__area_cells(circular, lev);
    double frac = 1.0 / (double)cells, sum = 0;
    for (size_t c = 0; c < cells; c++) {
        double a, b, s[3];
        lx__area_cell(circular, w, len, lev, c, &a, &b);
        for (int k = 0; k < 3; k++) s[k] = l->pos_m[k] + a * A->le->ex[k] + b * A->le->ey[k];
        if (!A->vis || circular) {
            sum += point_E(A->cnt, A->le, s, A->q, A->n, frac, A->vis);
            continue;
        }
        /* a rectangle's cell: its visible fraction by the centres of its 3 x 3 sub-cells, so a
         * shadow edge across the cell counts the part on each side (and one along its border none) */
        double fv = 0, hw = w / (3.0 * lev), hl = len / (3.0 * lev);
        for (int k = 0; k < 9; k++) {
            double y[3], da = hw * (k % 3 - 1), db = hl * (k / 3 - 1);
            for (int c3 = 0; c3 < 3; c3++) y[c3] = s[c3] + da * A->le->ex[c3] + db * A->le->ey[c3];
            A->cnt->visibility_tests++;
            if (lx__room_visible(A->vis->occ, A->vis->n_occ, y, A->q, A->vis->skip, -1)) fv += 1.0 / 9;
        }
        if (fv > 0) sum += fv * point_E(A->cnt, A->le, s, A->q, A->n, frac, NULL);
    }
    return sum;
}

static double near_E(lx_counters *cnt, const lum_eval *le, const double q[3], const double n[3], double tol,
                     const lx__scene_vis *vis, int n_max)
{
    unsigned long long patches = 0;
    near_arg A = {cnt, le, q, n, vis};
    double x;
    if (!vis) x = lx__area_refine(near_mean, &A, le->l->radius_m > 0, tol, n_max, &patches, NULL);
    else {
        /* a shadow edge across the area: the midpoint error is first order in the cell size there,
         * which Richardson's extrapolation would amplify; the finest plain sum instead */
        double prev = NAN;
        x = 0;
        for (int lev = 2; lev <= n_max; lev *= 2) {
            x = near_mean(&A, lev);
            patches += lx__area_cells(le->l->radius_m > 0, lev);
            if (lev >= 8 && fabs(x - prev) <= tol * fabs(x)) break;
            prev = x;
        }
    }
    cnt->nearfield_pairs++;
    cnt->nearfield_subdivisions += patches;
    return x > 0 ? x : 0;
}

/* A Lambertian disk or rectangle in closed form (area_exact.c): any receiver orientation. */
static double closed_E(lx_counters *cnt, const lum_eval *le, const double q[3], const double n[3])
{
    const lx_scene_luminaire *l = le->l;
    double m[3] = {-le->ez[0], -le->ez[1], -le->ez[2]}; /* the emitting normal: the aim */
    cnt->nearfield_pairs++;
    cnt->closed_form_evaluations++;
    if (l->kind == LX_SLUM_DISK) return lx__lambert_disk_E(l->luminance_cd_m2, l->pos_m, le->ex, le->ey, m, l->radius_m, q, n, NULL);
    return lx__lambert_rect_E(l->luminance_cd_m2, l->pos_m, le->ex, le->ey, m, l->width_m, l->length_m, q, n);
}

/* Probe points of a luminous area for the partial-visibility test: centre, edge midpoints, corners
 * (a disk: centre and 8 points on its rim). */
static void probe_point(const lx__scene_lum *le, int k, double s[3])
{
    const lx_scene_luminaire *l = le->l;
    double a, b, w, len;
    lx__scene_lum_extent(l, &w, &len);
    if (l->radius_m > 0) {
        double t = 2 * LX__PI * (k - 1) / 8.0;
        a = k ? l->radius_m * cos(t) : 0;
        b = k ? l->radius_m * sin(t) : 0;
    } else {
        a = 0.5 * w * (k % 3 - 1);
        b = 0.5 * len * (k / 3 - 1);
    }
    for (int c = 0; c < 3; c++) s[c] = l->pos_m[c] + a * le->ex[c] + b * le->ey[c];
}

/* The luminaire's light at q by its path, before the plan's factor (lx__scene_lum_E). */
static double lum_E(lx_counters *cnt, const lx__scene_lum *le, const double q[3], const double n[3], int path,
                    double near_tol, const lx__scene_vis *vis)
{
    double size = lx__scene_lum_size(le->l);
    if (vis && size > 0) {
        int seen = 0;
        for (int k = 0; k < 9; k++) {
            double s[3];
            probe_point(le, k, s);
            cnt->visibility_tests++;
            seen += lx__room_visible(vis->occ, vis->n_occ, s, q, vis->skip, -1);
        }
        if (seen == 0) return 0;
        /* partly hidden: integrate the visible part; wholly visible: as without occluders */
        if (seen < 9) return near_E(cnt, le, q, n, near_tol, vis, near_tol >= 1e-4 ? 32 : 128);
        vis = NULL;
    }
    if (path == LX__PATH_CLOSED) return closed_E(cnt, le, q, n);
    if (path) return near_E(cnt, le, q, n, near_tol, NULL, LX__NEAR_MAX_CELLS);
    cnt->point_evaluations++;
    return point_E(cnt, le, le->l->pos_m, q, n, 1, vis);
}

double lx__scene_lum_E(lx_counters *cnt, const lx__scene_lum *le, const double q[3], const double n[3], int path,
                       double near_tol, const lx__scene_vis *vis)
{
    if (!(le->k > 0)) return 0; /* dark in this operation */
    double E = lum_E(cnt, le, q, n, path, near_tol, vis);
    return le->k == 1 ? E : le->k * E;
}

/* The probe function of the near-field decision (as the planner's): the luminaire as a point at
 * offset (a, b) on its opening. */
typedef struct path_arg {
    lx_counters *cnt;
    const lx__scene_lum *le;
    const double *q, *n;
} path_arg;

static double path_g(void *arg, double a, double b)
{
    const path_arg *A = arg;
    double s[3];
    for (int k = 0; k < 3; k++) s[k] = A->le->l->pos_m[k] + a * A->le->ex[k] + b * A->le->ey[k];
    return point_E(A->cnt, A->le, s, A->q, A->n, 1, NULL);
}

int lx__scene_path(lx_counters *cnt, const lx_scene *sc, const lx__scene_lum *le, const double q[3], const double n[3],
                   double tol)
{
    const lx_scene_luminaire *L = le->l;
    lx_effect_force F = sc->force[LX_EFFECT_NEAR_FIELD];
    if (!(lx__scene_lum_size(L) > 0) || F == LX_FORCE_OFF) return LX__PATH_POINT;
    if (L->kind != LX_SLUM_FILE) return le->cosine ? LX__PATH_CLOSED : LX__PATH_AREA;
    if (F == LX_FORCE_ON) return LX__PATH_AREA;
    double ax, ay, d = 0;
    lx__scene_lum_extent(L, &ax, &ay);
    for (int c = 0; c < 3; c++) d += (q[c] - L->pos_m[c]) * (q[c] - L->pos_m[c]);
    path_arg A = {cnt, le, q, n};
    int circ = L->radius_m > 0;
    lx__nf_probe pr;
    lx__nf_probe_pair(path_g, &A, circ, ax, ay, sqrt(d), lx__nf_faces(L->pos_m, le->ex, le->ey, circ, ax, ay, q, n), &pr);
    cnt->nearfield_probes++;
    unsigned char near = 0;
    size_t order = 0;
    lx__nf_decide(1, &pr, pr.point, tol, &near, &order);
    return near ? LX__PATH_AREA : LX__PATH_POINT;
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void counters_diff(const lx_counters *a, const lx_counters *b, lx_counters *out)
{
    const unsigned long long *pa = (const unsigned long long *)a, *pb = (const unsigned long long *)b;
    unsigned long long *po = (unsigned long long *)out;
    for (size_t i = 0; i < sizeof *out / sizeof *po; i++) po[i] = pa[i] - pb[i];
}

/* The device blocks of the plan: each IES luminaire's far-field work on a grid as one
 * lx_grid_illuminance batch on OpenCL (its table kernel), scaled by the luminaire's flux scale
 * (the grid engine applies the TILT factor itself). *done (malloc'ed, n_lum x n_rec) marks the
 * blocks computed; a device failure falls back to the CPU unless the plan requires the device. */
static lx_status device_blocks(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, long only, double *contrib,
                               unsigned char **done)
{
    size_t nl = sc->n_lum, np = plan->n_points, g0 = 0;
    unsigned char *d = lx__calloc(nl * sc->n_rec > 0 ? nl * sc->n_rec : 1, 1);
    double *E = NULL;
    if (!d) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t r = 0; r < sc->n_rec; r++) {
        const lx_scene_receiver *rc = &sc->rec[r];
        for (size_t l = 0; l < nl; l++) {
            if (!plan->device[l * sc->n_rec + r] || (only >= 0 && (long)l != only)) continue;
            const lx_scene_luminaire *L = &sc->lum[l];
            lx_placement pl;
            memset(&pl, 0, sizeof pl);
            pl.lum = L->lum;
            memcpy(pl.pos_m, L->pos_m, sizeof pl.pos_m);
            memcpy(pl.aim, L->aim, sizeof pl.aim);
            pl.rotate_rad = L->rotate_rad;
            lx_grid_opts o;
            memset(&o, 0, sizeof o);
            o.model = LX_MODEL_POINT;
            o.interp = LX_INTERP_TABLE;
            o.backend = LX_BACKEND_OPENCL;
            if (!E && !(E = lx__alloc_n(np, sizeof *E))) {
                lx__free(d);
                return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
            }
            lx_status st = lx_grid_illuminance(ctx, &pl, 1, rc->points, rc->n, rc->normal, 1, &o, E);
            if (st != LX_OK) {
                if (plan->device_required) {
                    lx__free(E);
                    lx__free(d);
                    return st;
                }
                lx__log(ctx, LX_LOG_INFO, "scene: OpenCL failed (%s); computing on the CPU", lx_ctx_errmsg(ctx));
                lx__free(E);
                *done = d; /* what was done stays done; the rest runs on the CPU */
                return LX_OK;
            }
            double tilt = lx_luminaire_tilt_factor(L->lum, acos(fmax(-1.0, fmin(1.0, -L->aim[2]))));
            double k = tilt > 0 ? L->scale / tilt : 0;
            if (plan->lum_scale) k *= plan->lum_scale[l]; /* maintenance, emergency operation */
            for (size_t i = 0; i < rc->n; i++) contrib[(g0 + i) * (nl + 1) + l] = E[i] * k;
            ctx->counters.kernel_launches += lx_ctx_backend_used(ctx) == LX_BACKEND_OPENCL;
            ctx->counters.point_evaluations += rc->n;
            ctx->counters.goniometric_lookups += rc->n;
            d[l * sc->n_rec + r] = 1;
        }
        g0 += rc->n;
    }
    lx__free(E);
    *done = d;
    return LX_OK;
}

/* Every result that is defined must be a number: an infinity or NaN (fluxes, intensities or
 * distances that leave the double range) is an error naming the receiver, its point and the
 * luminaire, never a value handed on to be printed blank. */
static lx_status check_finite(lx_ctx *ctx, const lx_scene *sc, const lx_scene_result *res, size_t nl, int spectral)
{
    for (size_t r = 0; r < sc->n_rec; r++) {
        const lx_scene_receiver *rc = &sc->rec[r];
        for (size_t g = res->first[r]; g < res->first[r + 1]; g++) {
            const double *c = res->contrib_lx + g * (nl + 1), *q = rc->points + 3 * (g - res->first[r]);
            const char *what = NULL, *who = NULL;
            double v = 0;
            for (size_t k = 0; k <= nl && !what; k++)
                if (!isfinite(c[k])) what = "illuminance_lx", v = c[k], who = k < nl ? sc->lum[k].name : NULL;
            if (!what && !isfinite(res->E_lx[g])) what = "illuminance_lx", v = res->E_lx[g];
            if (!what && sc->want_luminance && rc->reflectance >= 0 && !isfinite(res->L_cd_m2[g]))
                what = "luminance_cd_m2", v = res->L_cd_m2[g];
            if (!what && spectral && res->E_lx[g] > 0 && !isfinite(res->melanopic_edi_lx[g]))
                what = "melanopic_edi_lx", v = res->melanopic_edi_lx[g];
            if (what)
                return lx__error(ctx, LX_ERANGE, rc->file, rc->line,
                                 "receiver '%s', point %zu (%g, %g, %g m): %s is %s%s%s%s: the fluxes, intensities or "
                                 "distances leave the double range (or a point source sits on the point)",
                                 rc->name, g - res->first[r] + 1, q[0], q[1], q[2], what, isnan(v) ? "NaN" : "infinite",
                                 who ? " from luminaire '" : "", who ? who : "", who ? "'" : "");
        }
    }
    return LX_OK;
}

/* Each point's luminance, and with spectral on its CCT, Duv and melanopic EDI from the sources'
 * contributions (and the interreflected and daylight parts). */
static void point_colour(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, lx_scene_result *res,
                         const scene__spec *spec, long only,
                         const lx__daylight *day, int spectral)
{
    size_t nl = sc->n_lum, nc = nl + 1;
    for (size_t r = 0; r < sc->n_rec; r++) {
        const lx_scene_receiver *rc = &sc->rec[r];
        for (size_t g = res->first[r]; g < res->first[r + 1]; g++) {
            const double *c = res->contrib_lx + g * nc;
            double Eday = day ? day->ind_lx[g] : 0; /* interreflected daylight: the sky's spectrum */
            double E = res->E_lx[g], Eind = res->indirect_lx ? res->indirect_lx[g] - Eday : 0;
            res->L_cd_m2[g] = sc->want_luminance && rc->reflectance >= 0 ? rc->reflectance * E / LX__PI : NAN;
            res->cct_K[g] = res->duv[g] = res->melanopic_edi_lx[g] = NAN;
            if (spectral && E > 0) {
                /* linearity: X, Y, Z and the melanopic irradiance of the summed spectral
                 * irradiance are the sums of each source's, scaled to its illuminance; the
                 * indirect part has the flux-weighted mixture of the sources' spectra (neutral
                 * reflectances) */
                double X = 0, Z = 0, mel = 0, fl = 0, fx = 0, fz = 0, fm = 0;
                for (size_t k = 0; k < nc; k++) {
                    X += c[k] * spec[k].x_per_lx;
                    Z += c[k] * spec[k].z_per_lx;
                    mel += c[k] * spec[k].mel_W_per_lx;
                }
                for (size_t l = 0; l < nl && Eind > 0; l++)
                    if (only < 0 || (long)l == only) {
                        double f = sc->lum[l].flux_lm * (plan->lum_scale ? plan->lum_scale[l] : 1);
                        fl += f, fx += f * spec[l].x_per_lx, fz += f * spec[l].z_per_lx, fm += f * spec[l].mel_W_per_lx;
                    }
                if (fl > 0) X += Eind * fx / fl, Z += Eind * fz / fl, mel += Eind * fm / fl;
                X += Eday * spec[nl].x_per_lx, Z += Eday * spec[nl].z_per_lx, mel += Eday * spec[nl].mel_W_per_lx;
                res->melanopic_edi_lx[g] = mel / lx_alphaopic_d65_efficacy(LX_AO_MEL);
                double s = X + E + Z, T, duv;
                if (s > 0 && lx_cct_from_xy(ctx, LX_OBSERVER_2, X / s, E / s, &T, &duv) == LX_OK && fabs(duv) <= 0.05 &&
                    T >= 1000 && T <= 100000)
                    res->cct_K[g] = T, res->duv[g] = duv;
            }
        }
    }
}

/* What follows the luminaires' direct light at the points: the cylindrical receivers' direct light,
 * the daylight through the openings, the interreflected part (E_lx gains indirect_lx, the
 * daylight's too) and the modelling ratio. */
static lx_status after_direct(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lum_eval *le,
                              const lx__scene_vis *vis, long only, lx__daylight *day, lx_scene_result *res)
{
    lx_status st = lx__design_cyl_alloc(ctx, sc, res);
    if (st != LX_OK) return st;
    lx__design_cyl_direct(&ctx->counters, sc, plan, le, vis, only, res); /* small vertical cylinders */
    if (day && (st = lx__daylight_points(ctx, day, res)) != LX_OK) return st; /* the sky's column */
    if (plan->on[LX_EFFECT_INTERREFLECTION] && (st = lx__room_eval(ctx, sc, plan, only, day, res)) != LX_OK) return st;
    if (day && (st = lx__daylight_finish(ctx, day, res)) != LX_OK) return st;
    lx__design_cyl_modelling(sc, res);
    return LX_OK;
}

lx_status lx_scene_eval(lx_ctx *ctx, const lx_scene *sc, const lx_scene_plan *plan, const lx_scene_eval_opts *opts,
                        lx_scene_result **out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !plan || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_eval: NULL argument");
    *out = NULL;
    lx_status st0 = opts ? lx__check_reserved(ctx, "scene options", opts->reserved, sizeof opts->reserved) : LX_OK;
    if (st0) return st0;
    long only = opts && opts->single ? (long)opts->index : -1;
    if (opts && opts->single && opts->index >= sc->n_lum)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_eval: no luminaire %zu", opts->index);
    double t0 = now_s();
    lx_counters before = ctx->counters;
    size_t np = plan->n_points, nl = sc->n_lum, nc = nl + 1;
    lx_scene_result *res = lx__calloc(1, sizeof *res);
    lum_eval *le = lx__calloc(nl ? nl : 1, sizeof *le);
    scene__spec *spec = lx__calloc(nc, sizeof *spec);
    void *map = NULL, *occm = NULL;
    unsigned char *ondev = NULL;
    lx__daylight *day = NULL, *sun = NULL; /* daylight through openings; the sun's shade outside rooms */
    lx_status st = LX_OK;
    if (!res || !le || !spec) goto nomem;
    res->n_points = np;
    res->n_lum = nl;
    res->first = lx__alloc_n(sc->n_rec + 1, sizeof *res->first);
    res->E_lx = lx__calloc(np ? np : 1, sizeof *res->E_lx);
    res->contrib_lx = lx__calloc(np * nc > 0 ? np * nc : 1, sizeof *res->contrib_lx);
    res->L_cd_m2 = lx__alloc_n(np ? np : 1, sizeof(double));
    res->cct_K = lx__alloc_n(np ? np : 1, sizeof(double));
    res->duv = lx__alloc_n(np ? np : 1, sizeof(double));
    res->melanopic_edi_lx = lx__alloc_n(np ? np : 1, sizeof(double));
    if (!res->first || !res->E_lx || !res->contrib_lx || !res->L_cd_m2 || !res->cct_K || !res->duv ||
        !res->melanopic_edi_lx)
        goto nomem;
    for (size_t l = 0; l < nl; l++) lx__scene_lum_init(&le[l], sc, l, plan);
    int sky = plan->on[LX_EFFECT_ENVIRONMENT] && only < 0;
    int spectral = plan->on[LX_EFFECT_SPECTRAL];
    if (sky && sc->sky == LX_SKY_MAP && (st = lx__scene_sky_map_load(ctx, sc, &map)) != LX_OK) goto fail;
    if (spectral) {
        for (size_t l = 0; l < nl; l++)
            if ((only < 0 || (long)l == only) &&
                (st = lx__scene_spectrum_weights(ctx, sc->lum[l].file, sc->lum[l].line,
                                                 sc->lum[l].spd ? &sc->lum[l].spd->spd[sc->lum[l].spd_index] : NULL,
                                                 sc->lum[l].cct_K, &spec[l])) != LX_OK)
                goto fail;
        if ((sky || (plan->on[LX_EFFECT_DAYLIGHT] && only < 0)) &&
            (st = lx__scene_spectrum_weights(ctx, sc->sky_file_at, sc->sky_line, NULL, sc->sky_cct_K, &spec[nl])) != LX_OK)
            goto fail;
    }
    /* occlusion: the occluders the flagged pairs are tested against */
    lx__scene_vis vis = {NULL, 0, -1};
    if (plan->occ) {
        lx__room_mesh *om = plan->room.mesh;
        if (!om) {
            if ((st = lx__room_occluders(ctx, sc, &om)) != LX_OK) goto fail;
            occm = om;
        }
        vis.occ = om->occ;
        vis.n_occ = (int)om->n_occ;
    }
    if (only < 0 && (st = lx__daylight_begin(ctx, sc, plan, &day)) != LX_OK) goto fail;
    if (sky && (st = lx__daylight_sun_only(ctx, sc, plan, &sun)) != LX_OK) goto fail;
    /* every luminaire's contribution at every point, once: first the device batches */
    if (plan->on[LX_EFFECT_OPENCL] && (st = device_blocks(ctx, sc, plan, only, res->contrib_lx, &ondev)) != LX_OK) goto fail;
    size_t g = 0;
    for (size_t r = 0; r < sc->n_rec; r++) {
        const lx_scene_receiver *rc = &sc->rec[r];
        res->first[r] = g;
        double E_sky = 0;
        if (sky && (st = lx__scene_sky_eval(ctx, sc, map, rc->normal, &E_sky)) != LX_OK) goto fail;
        for (size_t i = 0; i < rc->n; i++, g++) {
            const double *q = rc->points + 3 * i;
            double *c = res->contrib_lx + g * nc;
            for (size_t l = 0; l < nl; l++) {
                if ((only >= 0 && (long)l != only) || (ondev && ondev[l * sc->n_rec + r])) continue;
                unsigned char o = plan->occ ? plan->occ[l * np + g] : 0;
                if (o == 2) continue; /* another room: its walls are between them */
                c[l] = lx__scene_lum_E(&ctx->counters, &le[l], q, rc->normal, plan->near[l * np + g], sc->nearfield_tol,
                                       o ? &vis : NULL);
            }
            /* the sky does not reach inside a room (but through its openings: daylight); outside, the
             * sun is shaded by rooms, surfaces and obstructions */
            int cell = sc->n_room ? lx__room_cell(sc, q) : -1;
            c[nl] = cell >= 0 ? 0 : E_sky;
            if (cell < 0 && sun && !lx__daylight_sun_visible(sun, q, -1, -1)) c[nl] -= lx__scene_sun_part(sc, rc->normal);
            double E = 0;
            for (size_t k = 0; k < nc; k++) E += c[k];
            res->E_lx[g] = E;
        }
    }
    res->first[sc->n_rec] = g;
    if ((st = after_direct(ctx, sc, plan, le, &vis, only, day, res)) != LX_OK) goto fail;
    point_colour(ctx, sc, plan, res, spec, only, day, spectral);
    if ((st = check_finite(ctx, sc, res, nl, spectral)) != LX_OK) goto fail;
    lx__daylight_free(day);
    lx__daylight_free(sun);
    lx__free(ondev);
    lx__scene_sky_map_free(map);
    lx__room_mesh_free(occm);
    lx__free(le);
    lx__free(spec);
    counters_diff(&ctx->counters, &before, &res->work);
    res->seconds = now_s() - t0;
    lx__backend_used(ctx, res->work.kernel_launches ? LX_BACKEND_OPENCL : LX_BACKEND_CPU);
    *out = res;
    return LX_OK;
nomem:
    st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
fail:
    lx__daylight_free(day);
    lx__daylight_free(sun);
    lx__free(ondev);
    lx__scene_sky_map_free(map);
    lx__room_mesh_free(occm);
    lx_scene_result_free(res);
    lx__free(le);
    lx__free(spec);
    return st;
}
