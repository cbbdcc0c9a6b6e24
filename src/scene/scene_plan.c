/* scene_plan.c - the scene planner: which effects a scene needs (and why), which luminaire-
 * receiver pairs take the near-field path (the five-times rule), and the work it expects. */
#include "scene_private.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const effect_names[LX_EFFECT_COUNT] = {
    "inverse_square", "cosine", "spot_falloff", "goniometric", "near_field", "spectral", "environment", "opencl"};

const char *lx_effect_name(lx_effect e)
{
    return (int)e >= 0 && e < LX_EFFECT_COUNT ? effect_names[e] : NULL;
}

void lx__scene_frame(const lx_scene_luminaire *l, double ex[3], double ey[3], double ez[3])
{
    /* the frame lx_grid_illuminance uses: the smallest rotation taking the nadir (0, 0, -1) to
     * aim (Rodrigues: R = I + [v]x + [v]x^2 / (1 + c), v = nadir x aim, c = nadir . aim), then a
     * turn by rotate about the aim */
    const double *a = l->aim;
    double R[3][3], c = -a[2];
    if (c < -1 + 1e-12) { /* straight up: a half turn about x */
        static const double H[3][3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
        memcpy(R, H, sizeof R);
    } else {
        double v[3] = {a[1], -a[0], 0};
        double K[3][3] = {{0, -v[2], v[1]}, {v[2], 0, -v[0]}, {-v[1], v[0], 0}};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double k2 = 0;
                for (int m = 0; m < 3; m++) k2 += K[i][m] * K[m][j];
                R[i][j] = (i == j) + K[i][j] + k2 / (1 + c);
            }
    }
    double cr = cos(l->rotate_rad), sr = sin(l->rotate_rad);
    for (int i = 0; i < 3; i++) {
        ex[i] = cr * R[i][0] + sr * R[i][1];
        ey[i] = -sr * R[i][0] + cr * R[i][1];
        ez[i] = R[i][2];
    }
}

double lx__scene_lum_size(const lx_scene_luminaire *l)
{
    if (l->radius_m > 0) return 2 * l->radius_m;
    if (l->kind == LX_SLUM_RECT || l->kind == LX_SLUM_FILE) return hypot(l->width_m, l->length_m);
    return 0;
}

static void why(lx_scene_plan *p, lx_effect e, int on, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->reason[e], sizeof p->reason[e], fmt, ap);
    va_end(ap);
    p->on[e] = on;
}

void lx_scene_plan_free(lx_scene_plan *plan)
{
    if (!plan) return;
    free(plan->near);
    free(plan->device);
    free(plan);
}

/* Patches the near-field integration is expected to evaluate for one pair (levels 4, 8, 16 ...
 * until the extrapolated estimate changes by less than tol: the midpoint rule's error falls as
 * (size / (n d))^2, its extrapolation as the fourth power). */
static unsigned long long near_patches(double size, double d, double tol, int disk)
{
    unsigned long long total = 0;
    for (int n = 4; n <= LX__NEAR_MAX_CELLS; n *= 2) {
        total += (unsigned long long)n * (unsigned long long)n * (disk ? 2u : 1u);
        double h = size / (n * (d > 1e-9 ? d : 1e-9));
        if (n >= 16 && h * h * h * h < tol) break;
    }
    return total;
}

lx_status lx_scene_plan_make(lx_ctx *ctx, const lx_scene *sc, lx_backend backend, lx_scene_plan **out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_plan_make: NULL argument");
    *out = NULL;
    if (backend != LX_BACKEND_AUTO && backend != LX_BACKEND_CPU && backend != LX_BACKEND_OPENCL)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_plan_make: unknown backend %d", (int)backend);
    lx_scene_plan *p = calloc(1, sizeof *p);
    if (!p) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    for (size_t r = 0; r < sc->n_rec; r++) p->n_points += sc->rec[r].n;
    p->n_pairs = p->n_points * sc->n_lum;
    p->n_normals = sc->n_rec;
    p->near = calloc(p->n_pairs ? p->n_pairs : 1, 1);
    p->device = calloc(sc->n_lum * sc->n_rec > 0 ? sc->n_lum * sc->n_rec : 1, 1);
    if (!p->near || !p->device) {
        free(p->near);
        free(p->device);
        free(p);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    const lx_effect_force *F = sc->force;
    lx_status st = LX_OK;
    size_t n_spot = 0, n_file = 0, n_area = 0;
    for (size_t l = 0; l < sc->n_lum; l++) {
        n_spot += sc->lum[l].kind == LX_SLUM_SPOT;
        n_file += sc->lum[l].kind == LX_SLUM_FILE;
        n_area += lx__scene_lum_size(&sc->lum[l]) > 0;
    }
#define FORCED_ON_NOTHING(e, what)                                                                                 \
    if (F[e] == LX_FORCE_ON) {                                                                                     \
        st = lx__error(ctx, LX_EPARSE, sc->file, sc->force_line[e], "%s forced on, but the scene has no %s",      \
                       effect_names[e], what);                                                                     \
        goto fail;                                                                                                 \
    }
    /* inverse square and cosine: the point-source law for every luminaire */
    if (sc->n_lum == 0) {
        FORCED_ON_NOTHING(LX_EFFECT_INVERSE_SQUARE, "luminaires");
        FORCED_ON_NOTHING(LX_EFFECT_COSINE, "luminaires");
        why(p, LX_EFFECT_INVERSE_SQUARE, 0, "no luminaires (sky only)");
        why(p, LX_EFFECT_COSINE, 0, "no luminaires (the sky integration has its own cosine)");
    } else {
        why(p, LX_EFFECT_INVERSE_SQUARE, 1, "%zu luminaire%s x %zu receiver point%s", sc->n_lum,
            sc->n_lum == 1 ? "" : "s", p->n_points, p->n_points == 1 ? "" : "s");
        if (F[LX_EFFECT_COSINE] == LX_FORCE_OFF)
            why(p, LX_EFFECT_COSINE, 0, "forced off in [effects]: every receiver faces each ray (normal illuminance)");
        else
            why(p, LX_EFFECT_COSINE, 1, "receivers have normals: E = I cos(xi) / d^2, 0 when facing away");
    }
    /* spot falloff */
    if (!n_spot) {
        FORCED_ON_NOTHING(LX_EFFECT_SPOT_FALLOFF, "spot luminaires");
        why(p, LX_EFFECT_SPOT_FALLOFF, 0, "no spot luminaires");
    } else if (F[LX_EFFECT_SPOT_FALLOFF] == LX_FORCE_OFF)
        why(p, LX_EFFECT_SPOT_FALLOFF, 0, "forced off in [effects]: spots give their peak intensity in the whole front hemisphere");
    else
        why(p, LX_EFFECT_SPOT_FALLOFF, 1, "%zu spot luminaire%s (Warn cos^S lobes)", n_spot, n_spot == 1 ? "" : "s");
    /* goniometric */
    if (!n_file) {
        FORCED_ON_NOTHING(LX_EFFECT_GONIOMETRIC, "photometric-file luminaires");
        why(p, LX_EFFECT_GONIOMETRIC, 0, "no IES/LDT luminaires");
    } else if (F[LX_EFFECT_GONIOMETRIC] == LX_FORCE_OFF)
        why(p, LX_EFFECT_GONIOMETRIC, 0, "forced off in [effects]: IES/LDT luminaires are isotropic points of their flux");
    else
        why(p, LX_EFFECT_GONIOMETRIC, 1, "%zu IES/LDT luminaire%s (intensity tables)", n_file, n_file == 1 ? "" : "s");
    /* near field: per pair, the five-times rule */
    if (!n_area) {
        FORCED_ON_NOTHING(LX_EFFECT_NEAR_FIELD, "luminaires with a luminous area");
        why(p, LX_EFFECT_NEAR_FIELD, 0, "no luminaire has a luminous area (all are points)");
    } else {
        double worst = INFINITY;
        const char *wl = NULL, *wr = NULL;
        for (size_t l = 0; l < sc->n_lum; l++) {
            const lx_scene_luminaire *L = &sc->lum[l];
            double size = lx__scene_lum_size(L);
            if (!(size > 0)) continue;
            size_t g = 0;
            for (size_t r = 0; r < sc->n_rec; r++)
                for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
                    const double *q = sc->rec[r].points + 3 * i;
                    double d = sqrt((q[0] - L->pos_m[0]) * (q[0] - L->pos_m[0]) + (q[1] - L->pos_m[1]) * (q[1] - L->pos_m[1]) +
                                    (q[2] - L->pos_m[2]) * (q[2] - L->pos_m[2]));
                    int near = F[LX_EFFECT_NEAR_FIELD] == LX_FORCE_ON ? 1
                               : F[LX_EFFECT_NEAR_FIELD] == LX_FORCE_OFF ? 0
                                                                         : d < 5 * size;
                    if (d / size < worst) worst = d / size, wl = L->name, wr = sc->rec[r].name;
                    if (near) {
                        p->near[l * p->n_points + g] = 1;
                        p->n_near++;
                        p->estimate.nearfield_subdivisions +=
                            near_patches(size, d, sc->nearfield_tol, L->radius_m > 0);
                    }
                }
        }
        p->estimate.nearfield_pairs = p->n_near;
        if (F[LX_EFFECT_NEAR_FIELD] == LX_FORCE_OFF)
            why(p, LX_EFFECT_NEAR_FIELD, 0, "forced off in [effects]: every luminaire is a point at its centre");
        else if (F[LX_EFFECT_NEAR_FIELD] == LX_FORCE_ON)
            why(p, LX_EFFECT_NEAR_FIELD, 1, "forced on in [effects]: %zu pairs integrated over the luminous area", p->n_near);
        else if (p->n_near)
            why(p, LX_EFFECT_NEAR_FIELD, 1, "%zu of %zu pairs closer than 5x the luminaire size (closest: %s to %s at %.3g x)",
                p->n_near, p->n_pairs, wl, wr, worst);
        else
            why(p, LX_EFFECT_NEAR_FIELD, 0, "every receiver is at least 5x the luminaire size away (closest: %s to %s at %.3g x)",
                wl, wr, worst);
    }
    /* spectral: only when asked for and every source has a spectrum */
    {
        int asked = sc->want_cct || sc->want_melanopic;
        size_t with = 0, sources = sc->n_lum + (sc->sky != LX_SKY_NONE && F[LX_EFFECT_ENVIRONMENT] != LX_FORCE_OFF);
        const char *missing = NULL, *mfile = sc->file;
        long mline = 0;
        for (size_t l = 0; l < sc->n_lum; l++) {
            if (sc->lum[l].spd || sc->lum[l].cct_K > 0) with++;
            else if (!missing) missing = sc->lum[l].name, mfile = sc->lum[l].file, mline = sc->lum[l].line;
        }
        if (sources > sc->n_lum) {
            if (sc->sky_cct_K > 0) with++;
            else if (!missing) missing = "the sky", mfile = sc->sky_file_at, mline = sc->sky_line;
        }
        if (F[LX_EFFECT_SPECTRAL] == LX_FORCE_OFF)
            why(p, LX_EFFECT_SPECTRAL, 0, "forced off in [effects]");
        else if (!asked && F[LX_EFFECT_SPECTRAL] != LX_FORCE_ON)
            why(p, LX_EFFECT_SPECTRAL, 0, "no spectral output asked (cct, melanopic_edi)");
        else if (with == 0 && F[LX_EFFECT_SPECTRAL] != LX_FORCE_ON)
            why(p, LX_EFFECT_SPECTRAL, 0, "spectral output asked, but no source has an spd or cct: left empty");
        else if (with < sources) {
            st = lx__error(ctx, LX_EPARSE, mfile, mline,
                           "spectral output needs a spectrum for every source: %s has no spd or cct", missing);
            goto fail;
        } else {
            why(p, LX_EFFECT_SPECTRAL, 1, "%s asked and all %zu sources have spectra",
                F[LX_EFFECT_SPECTRAL] == LX_FORCE_ON && !asked ? "forced on in [effects];"
                : sc->want_cct && sc->want_melanopic ? "cct and melanopic_edi"
                : sc->want_cct ? "cct" : "melanopic_edi",
                with);
            p->estimate.spectra_integrated = 2 * with;
        }
    }
    /* environment */
    if (sc->sky == LX_SKY_NONE && !(sc->has_sun && sc->sun_normal_lx > 0)) {
        FORCED_ON_NOTHING(LX_EFFECT_ENVIRONMENT, "[sky]");
        why(p, LX_EFFECT_ENVIRONMENT, 0, "no [sky]");
    } else if (F[LX_EFFECT_ENVIRONMENT] == LX_FORCE_OFF)
        why(p, LX_EFFECT_ENVIRONMENT, 0, "forced off in [effects]: the sky is ignored");
    else {
        static const char *const sk[] = {"no", "uniform", "CIE overcast", "EXR map", "CIE general", "Perez all-weather"};
        char kind[64];
        if (sc->sky == LX_SKY_CIE) snprintf(kind, sizeof kind, "CIE general (type %d)", sc->sky_cie_type);
        else snprintf(kind, sizeof kind, "%s", sk[sc->sky]);
        why(p, LX_EFFECT_ENVIRONMENT, 1, "%s sky%s, ground reflectance %g: one evaluation per receiver normal (%zu)",
            kind, sc->has_sun && sc->sun_normal_lx > 0 ? " and the sun" : "", sc->ground_reflectance, p->n_normals);
        p->estimate.environment_evaluations = p->n_normals;
        if (sc->sky == LX_SKY_MAP) {
            /* the upper half of the map once for the horizontal (the ground term needs it), and
             * again for every receiver that does not face straight up */
            unsigned long long half = (unsigned long long)sc->sky_map->width * (unsigned long long)(sc->sky_map->height / 2);
            p->estimate.environment_samples += half;
            for (size_t r = 0; r < sc->n_rec; r++)
                if (sc->rec[r].normal[2] != 1) p->estimate.environment_samples += half;
        }
        if (sc->sky == LX_SKY_CIE || sc->sky == LX_SKY_PEREZ)
            for (size_t r = 0; r < sc->n_rec; r++)
                if (sc->rec[r].normal[2] != 1) p->estimate.environment_samples += 4ULL * 48 * 48;
        if (sc->sky == LX_SKY_OVERCAST)
            for (size_t r = 0; r < sc->n_rec; r++)
                if (sc->rec[r].normal[2] != 1) {
                    double nz = sc->rec[r].normal[2], cut = fabs(LX__PI / 2 - acos(nz > 1 ? 1 : nz < -1 ? -1 : nz));
                    p->estimate.environment_samples += (unsigned long long)sc->sky_samples * ((cut > 0) + (cut < LX__PI / 2));
                }
    }
    /* the point-source work (far pairs) */
    for (size_t l = 0; l < sc->n_lum; l++) {
        unsigned long long far = 0;
        for (size_t g = 0; g < p->n_points; g++) far += !p->near[l * p->n_points + g];
        p->estimate.point_evaluations += far;
        if (sc->lum[l].kind == LX_SLUM_SPOT && p->on[LX_EFFECT_SPOT_FALLOFF]) p->estimate.spot_evaluations += far;
        if (sc->lum[l].kind == LX_SLUM_FILE && p->on[LX_EFFECT_GONIOMETRIC]) p->estimate.goniometric_lookups += far;
    }
    for (size_t l = 0; l < sc->n_lum; l++)
        if (sc->lum[l].kind == LX_SLUM_FILE && p->on[LX_EFFECT_GONIOMETRIC]) {
            double size = lx__scene_lum_size(&sc->lum[l]);
            size_t g = 0;
            for (size_t r = 0; r < sc->n_rec; r++)
                for (size_t i = 0; i < sc->rec[r].n; i++, g++)
                    if (p->near[l * p->n_points + g]) {
                        const double *q = sc->rec[r].points + 3 * i, *s = sc->lum[l].pos_m;
                        double d = sqrt((q[0] - s[0]) * (q[0] - s[0]) + (q[1] - s[1]) * (q[1] - s[1]) + (q[2] - s[2]) * (q[2] - s[2]));
                        p->estimate.goniometric_lookups += near_patches(size, d, sc->nearfield_tol, sc->lum[l].radius_m > 0);
                    }
        }
    /* OpenCL: the far-field work of IES luminaires on grids can run as lx_grid_illuminance
     * batches on a device (its table kernel); only worth it when large enough to repay the
     * start-up (the grid engine's threshold: 1e7 point-luminaire evaluations), unless asked for.
     * Points, spots, areas, near-field pairs, the sky and spectra stay on the CPU. */
    {
        const double threshold = 1e7;
        double eligible = 0;
        size_t g0 = 0;
        for (size_t r = 0; r < sc->n_rec; r++) {
            const lx_scene_receiver *rc = &sc->rec[r];
            for (size_t l = 0; l < sc->n_lum; l++) {
                if (rc->kind != LX_SREC_GRID || sc->lum[l].kind != LX_SLUM_FILE || !p->on[LX_EFFECT_GONIOMETRIC] ||
                    !p->on[LX_EFFECT_COSINE])
                    continue;
                size_t k = 0;
                for (size_t i = 0; i < rc->n; i++) k += p->near[l * p->n_points + g0 + i];
                if (k == 0) p->device[l * sc->n_rec + r] = 1, eligible += (double)rc->n;
            }
            g0 += rc->n;
        }
        int explicit_on = F[LX_EFFECT_OPENCL] == LX_FORCE_ON || (backend == LX_BACKEND_OPENCL && F[LX_EFFECT_OPENCL] != LX_FORCE_OFF);
        if (F[LX_EFFECT_OPENCL] == LX_FORCE_ON && !(eligible > 0)) {
            st = lx__error(ctx, LX_EPARSE, sc->file, sc->force_line[LX_EFFECT_OPENCL],
                           "opencl forced on, but no IES luminaire lights a grid entirely in its far field");
            goto fail;
        }
        if (F[LX_EFFECT_OPENCL] == LX_FORCE_OFF) why(p, LX_EFFECT_OPENCL, 0, "forced off in [effects]");
        else if (!(eligible > 0))
            why(p, LX_EFFECT_OPENCL, 0, "no device work: only far-field IES luminaires on grids run on OpenCL");
        else if (explicit_on)
            why(p, LX_EFFECT_OPENCL, 1, "%s: %.3g far-field IES evaluations on grids",
                F[LX_EFFECT_OPENCL] == LX_FORCE_ON ? "forced on in [effects]" : "backend opencl", eligible);
        else if (backend == LX_BACKEND_CPU) why(p, LX_EFFECT_OPENCL, 0, "backend cpu");
        else if (eligible < threshold)
            why(p, LX_EFFECT_OPENCL, 0, "%.3g far-field IES evaluations on grids: below the %.0e that repay OpenCL start-up",
                eligible, threshold);
        else why(p, LX_EFFECT_OPENCL, 1, "%.3g far-field IES evaluations on grids: enough to repay OpenCL start-up", eligible);
        if (!p->on[LX_EFFECT_OPENCL]) memset(p->device, 0, sc->n_lum * sc->n_rec);
        p->backend = p->on[LX_EFFECT_OPENCL] ? LX_BACKEND_OPENCL : LX_BACKEND_CPU;
        p->device_required = p->on[LX_EFFECT_OPENCL] && explicit_on;
        if (p->on[LX_EFFECT_OPENCL]) {
            /* one batch (at least one kernel launch) per device block; their lookups leave the
             * CPU estimate of the table work */
            for (size_t l = 0; l < sc->n_lum; l++)
                for (size_t r = 0; r < sc->n_rec; r++)
                    if (p->device[l * sc->n_rec + r]) p->estimate.kernel_launches++;
        }
    }
    for (int e = 0; e < LX_EFFECT_COUNT; e++) p->forced[e] = F[e] != LX_FORCE_AUTO;
    *out = p;
    return LX_OK;
fail:
    lx_scene_plan_free(p);
    return st;
}
