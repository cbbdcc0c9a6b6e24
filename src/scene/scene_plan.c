/* scene_plan.c - the scene planner: which effects a scene needs (and why), which luminaire-
 * receiver pairs take the near-field path (closed forms; the point model's estimated error
 * against the tolerance, lighting/nearfield.c), and the work it expects. */
#include "scene_private.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const effect_names[LX_EFFECT_COUNT] = {
    "inverse_square", "cosine", "spot_falloff", "goniometric", "near_field", "spectral", "environment", "opencl",
    "occlusion", "interreflection", "daylight"};

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

void lx__scene_lum_extent(const lx_scene_luminaire *l, double *along_x, double *along_y)
{
    double x = 0, y = 0;
    if (l->radius_m > 0) x = y = 2 * l->radius_m;
    else if (l->kind == LX_SLUM_RECT) x = l->width_m, y = l->length_m;
    else if (l->kind == LX_SLUM_FILE) x = l->length_m, y = l->width_m;
    *along_x = x;
    *along_y = y;
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
    lx__free(plan->near);
    lx__free(plan->near_err);
    lx__free(plan->near_why);
    lx__free(plan->device);
    lx__room_plan_free(plan);
    lx__free(plan->lum_scale);
    lx__free(plan->internal); /* an emergency plan's copy of the scene (its arrays are the scene's) */
    lx__free(plan);
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

static const char *const why_names[LX_NEAR_WHY_COUNT] = {
    "point: no luminous area",       "point: estimated error within tolerance", "point: faces away (zero)",
    "area: estimated error over tolerance", "area: probes cannot vouch",      "closed form",
    "area: no closed form without the cosine", "area: forced on",            "point: forced off"};

const char *lx_near_why_name(lx_near_why why)
{
    return (int)why >= 0 && why < LX_NEAR_WHY_COUNT ? why_names[why] : NULL;
}

/* The probe function of the near-field decision: the luminaire as a point at offset (a, b) on
 * its opening, seen from the receiver point. */
typedef struct probe_arg {
    lx_ctx *ctx;
    const lx__scene_lum *le;
    const double *q, *n;
} probe_arg;

static double probe_g(void *arg, double a, double b)
{
    const probe_arg *A = arg;
    const lx__scene_lum *le = A->le;
    double s[3];
    for (int k = 0; k < 3; k++) s[k] = le->l->pos_m[k] + a * le->ex[k] + b * le->ey[k];
    return lx__scene_point_E(A->ctx, le, s, A->q, A->n, 1);
}

/* The near-field path of every pair (p->near, near_err, near_why): none for points; disks and
 * rectangles in closed form (patches when the cosine is forced off); IES/LDT openings decided
 * per receiver point from probes of the point model's error (lx__nf_decide: their summed
 * estimates within tol / 2 of the point's point-model illuminance, else integrated), or all
 * integrated / none when near_field is forced. */
static lx_status plan_near(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p, size_t *n_closed, size_t *n_probed,
                           double *worst_err, size_t *worst_l, size_t *worst_r)
{
    size_t nl = sc->n_lum, np = p->n_points;
    lx_effect_force F = sc->force[LX_EFFECT_NEAR_FIELD];
    lx__scene_lum *le = lx__calloc(nl, sizeof *le);
    lx__nf_probe *pr = lx__alloc_n(nl, sizeof *pr);
    unsigned char *nf = lx__alloc(nl);
    size_t *ord = lx__alloc_n(nl, sizeof *ord), *idx = lx__alloc_n(nl, sizeof *idx);
    if (!le || !pr || !nf || !ord || !idx) {
        lx__free(le), lx__free(pr), lx__free(nf), lx__free(ord), lx__free(idx);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    int any_file = 0;
    for (size_t l = 0; l < nl; l++) {
        lx__scene_lum_init(&le[l], sc, l, p);
        any_file |= sc->lum[l].kind == LX_SLUM_FILE && lx__scene_lum_size(&sc->lum[l]) > 0;
    }
    lx_counters before = ctx->counters;
    *worst_err = 0;
    size_t g = 0;
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++, g++) {
            const double *q = sc->rec[r].points + 3 * i, *n = sc->rec[r].normal;
            double E_point = 0;
            size_t k = 0;
            for (size_t l = 0; l < nl; l++) {
                const lx_scene_luminaire *L = &sc->lum[l];
                size_t at = l * np + g;
                p->near_err[at] = NAN;
                double size = lx__scene_lum_size(L);
                unsigned char path = LX__PATH_POINT, why = LX_NEAR_NONE;
                if (!(size > 0)) why = LX_NEAR_NONE;
                else if (F == LX_FORCE_OFF) why = LX_NEAR_FORCED_OFF;
                else if (L->kind != LX_SLUM_FILE) {
                    path = p->on[LX_EFFECT_COSINE] ? LX__PATH_CLOSED : LX__PATH_AREA;
                    why = p->on[LX_EFFECT_COSINE] ? LX_NEAR_CLOSED : LX_NEAR_NO_CLOSED;
                    *n_closed += path == LX__PATH_CLOSED;
                } else if (F == LX_FORCE_ON) path = LX__PATH_AREA, why = LX_NEAR_FORCED_ON;
                else { /* probed below, with the point's other luminaires */
                    double ax, ay, d = 0;
                    lx__scene_lum_extent(L, &ax, &ay);
                    for (int c = 0; c < 3; c++) d += (q[c] - L->pos_m[c]) * (q[c] - L->pos_m[c]);
                    probe_arg A = {ctx, &le[l], q, n};
                    int circ = L->radius_m > 0;
                    lx__nf_probe_pair(probe_g, &A, circ, ax, ay, sqrt(d),
                                      lx__nf_faces(L->pos_m, le[l].ex, le[l].ey, circ, ax, ay, q, n), &pr[k]);
                    E_point += pr[k].point;
                    idx[k++] = l;
                    ++*n_probed;
                    continue;
                }
                p->near[at] = path;
                p->near_why[at] = why;
                if (any_file && F == LX_FORCE_AUTO) E_point += lx__scene_point_E(ctx, &le[l], L->pos_m, q, n, 1);
            }
            if (!k) continue;
            lx__nf_decide(k, pr, E_point, sc->nearfield_tol, nf, ord);
            for (size_t j = 0; j < k; j++) {
                size_t at = idx[j] * np + g;
                double rel = E_point != 0 ? pr[j].err / fabs(E_point) : pr[j].err > 0 ? INFINITY : 0;
                p->near_err[at] = rel;
                p->near[at] = nf[j] ? LX__PATH_AREA : LX__PATH_POINT;
                p->near_why[at] = nf[j] ? (pr[j].unsure ? LX_NEAR_UNSURE : LX_NEAR_OVER)
                                        : (pr[j].zero ? LX_NEAR_ZERO : LX_NEAR_WITHIN);
                if (!pr[j].unsure && rel > *worst_err) *worst_err = rel, *worst_l = idx[j], *worst_r = r;
            }
        }
    /* what the probes cost, kept apart from the evaluation's work */
    const unsigned long long *a = (const unsigned long long *)&ctx->counters, *b = (const unsigned long long *)&before;
    unsigned long long *o = (unsigned long long *)&p->planning;
    for (size_t c = 0; c < sizeof p->planning / sizeof *o; c++) o[c] = a[c] - b[c];
    p->planning.nearfield_probes = *n_probed;
    ctx->counters.nearfield_probes += *n_probed;
    lx__free(le), lx__free(pr), lx__free(nf), lx__free(ord), lx__free(idx);
    return LX_OK;
}

/* The spectral effect: only when asked for and every source has a spectrum. */
static lx_status plan_spectral(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p)
{
    const lx_effect_force *F = sc->force;
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
        return lx__error(ctx, LX_EPARSE, mfile, mline,
                         "spectral output needs a spectrum for every source: %s has no spd or cct", missing);
    } else {
        why(p, LX_EFFECT_SPECTRAL, 1, "%s asked and all %zu sources have spectra",
            F[LX_EFFECT_SPECTRAL] == LX_FORCE_ON && !asked ? "forced on in [effects];"
            : sc->want_cct && sc->want_melanopic ? "cct and melanopic_edi"
            : sc->want_cct ? "cct" : "melanopic_edi",
            with);
        p->estimate.spectra_integrated = 2 * with;
    }
    return LX_OK;
}

/* The environment effect (sky and sun) and its work estimate. */
static lx_status plan_environment(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p)
{
    const lx_effect_force *F = sc->force;
    if (sc->sky == LX_SKY_NONE && !(sc->has_sun && sc->sun_normal_lx > 0)) {
        if (F[LX_EFFECT_ENVIRONMENT] == LX_FORCE_ON)
            return lx__error(ctx, LX_EPARSE, sc->file, sc->force_line[LX_EFFECT_ENVIRONMENT],
                             "%s forced on, but the scene has no %s", effect_names[LX_EFFECT_ENVIRONMENT], "[sky]");
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
    return LX_OK;
}

/* A plan with its per-pair and per-block arrays, sized for the scene; NULL on no memory. */
static lx_scene_plan *plan_alloc(const lx_scene *sc)
{
    lx_scene_plan *p = lx__calloc(1, sizeof *p);
    if (!p) return NULL;
    for (size_t r = 0; r < sc->n_rec; r++)
        p->n_points += sc->rec[r].n;
    p->n_pairs = p->n_points * sc->n_lum;
    p->n_normals = sc->n_rec;
    p->near = lx__calloc(p->n_pairs ? p->n_pairs : 1, 1);
    p->near_why = lx__calloc(p->n_pairs ? p->n_pairs : 1, 1);
    p->near_err = lx__alloc_n(p->n_pairs ? p->n_pairs : 1, sizeof *p->near_err);
    p->device = lx__calloc(sc->n_lum * sc->n_rec > 0 ? sc->n_lum * sc->n_rec : 1, 1);
    if (!p->near || !p->near_why || !p->near_err || !p->device) {
        lx_scene_plan_free(p);
        return NULL;
    }
    for (size_t k = 0; k < p->n_pairs; k++)
        p->near_err[k] = NAN;
    return p;
}

#define FORCED_ON_NOTHING(e, what)                                                                                     \
    if (sc->force[e] == LX_FORCE_ON)                                                                                   \
        return lx__error(ctx, LX_EPARSE, sc->file, sc->force_line[e], "%s forced on, but the scene has no %s",         \
                         effect_names[e], what);

/* The point-source effects: inverse square and cosine for every luminaire, spot falloff, goniometric. */
static lx_status plan_point_laws(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p)
{
    const lx_effect_force *F = sc->force;
    size_t n_spot = 0, n_file = 0;
    for (size_t l = 0; l < sc->n_lum; l++) {
        n_spot += sc->lum[l].kind == LX_SLUM_SPOT;
        n_file += sc->lum[l].kind == LX_SLUM_FILE;
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
        why(p, LX_EFFECT_SPOT_FALLOFF, 0,
            "forced off in [effects]: spots give their peak intensity in the whole front hemisphere");
    else
        why(p, LX_EFFECT_SPOT_FALLOFF, 1, "%zu spot luminaire%s (Warn cos^S lobes)", n_spot, n_spot == 1 ? "" : "s");
    /* goniometric */
    if (!n_file) {
        FORCED_ON_NOTHING(LX_EFFECT_GONIOMETRIC, "photometric-file luminaires");
        why(p, LX_EFFECT_GONIOMETRIC, 0, "no IES/LDT luminaires");
    } else if (F[LX_EFFECT_GONIOMETRIC] == LX_FORCE_OFF)
        why(p, LX_EFFECT_GONIOMETRIC, 0,
            "forced off in [effects]: IES/LDT luminaires are isotropic points of their flux");
    else
        why(p, LX_EFFECT_GONIOMETRIC, 1, "%zu IES/LDT luminaire%s (intensity tables)", n_file, n_file == 1 ? "" : "s");
    return LX_OK;
}

/* Counts the pairs plan_near put on a near path (p->n_near) and estimates the subdivisions of those
 * on the area path; returns how many are on the area path. */
static size_t plan_near_pairs(const lx_scene *sc, lx_scene_plan *p)
{
    size_t g = 0, n_area_pairs = 0;
    for (size_t r = 0; r < sc->n_rec; r++)
        for (size_t i = 0; i < sc->rec[r].n; i++, g++)
            for (size_t l = 0; l < sc->n_lum; l++) {
                const lx_scene_luminaire *L = &sc->lum[l];
                size_t at = l * p->n_points + g;
                if (!p->near[at]) continue;
                p->n_near++;
                if (p->near[at] == LX__PATH_AREA) {
                    n_area_pairs++;
                    const double *q = sc->rec[r].points + 3 * i;
                    double d =
                        sqrt((q[0] - L->pos_m[0]) * (q[0] - L->pos_m[0]) + (q[1] - L->pos_m[1]) * (q[1] - L->pos_m[1]) +
                             (q[2] - L->pos_m[2]) * (q[2] - L->pos_m[2]));
                    p->estimate.nearfield_subdivisions +=
                        near_patches(lx__scene_lum_size(L), d, sc->nearfield_tol, L->radius_m > 0);
                }
            }
    return n_area_pairs;
}

/* The near-field effect: per pair, from the closed forms and the point model's estimated error. */
static lx_status plan_near_field(lx_ctx *ctx, const lx_scene *sc, lx_scene_plan *p)
{
    const lx_effect_force *F = sc->force;
    size_t n_area = 0;
    for (size_t l = 0; l < sc->n_lum; l++)
        n_area += lx__scene_lum_size(&sc->lum[l]) > 0;
    if (!n_area) {
        FORCED_ON_NOTHING(LX_EFFECT_NEAR_FIELD, "luminaires with a luminous area");
        why(p, LX_EFFECT_NEAR_FIELD, 0, "no luminaire has a luminous area (all are points)");
        return LX_OK;
    }
    size_t n_closed = 0, n_probed = 0, wl = 0, wr = 0;
    double worst = 0;
    lx_status st = plan_near(ctx, sc, p, &n_closed, &n_probed, &worst, &wl, &wr);
    if (st != LX_OK) return st;
    size_t n_area_pairs = plan_near_pairs(sc, p);
    p->estimate.nearfield_pairs = p->n_near;
    p->estimate.nearfield_probes = n_probed;
    p->estimate.closed_form_evaluations = n_closed;
    if (F[LX_EFFECT_NEAR_FIELD] == LX_FORCE_OFF)
        why(p, LX_EFFECT_NEAR_FIELD, 0, "forced off in [effects]: every luminaire is a point at its centre");
    else if (F[LX_EFFECT_NEAR_FIELD] == LX_FORCE_ON)
        why(p, LX_EFFECT_NEAR_FIELD, 1,
            "forced on in [effects]: %zu pairs integrated over the luminous area, %zu in closed form", n_area_pairs,
            n_closed);
    else if (p->n_near) {
        char parts[3][96] = {"", "", ""};
        if (n_closed) snprintf(parts[0], sizeof parts[0], "; %zu disk/rect in closed form", n_closed);
        if (n_area_pairs)
            snprintf(parts[1], sizeof parts[1], "; %zu integrated (point-model error estimated over %g, or unsure)",
                     n_area_pairs, sc->nearfield_tol);
        if (n_probed)
            snprintf(parts[2], sizeof parts[2], "; %zu of %zu probed pairs kept as points", n_probed - n_area_pairs,
                     n_probed);
        why(p, LX_EFFECT_NEAR_FIELD, 1, "%zu of %zu pairs on the area path%s%s%s", p->n_near, p->n_pairs, parts[0],
            parts[1], parts[2]);
    } else
        why(p, LX_EFFECT_NEAR_FIELD, 0,
            "the point model's estimated error meets the tolerance %g on all %zu probed pairs "
            "(largest %.2g: %s to %s)",
            sc->nearfield_tol, n_probed, worst, sc->lum[wl].name, sc->rec[wr].name);
    return LX_OK;
}

#undef FORCED_ON_NOTHING

/* The point-source work estimate: the far pairs, and the table lookups of IES luminaires. */
static void plan_point_work(const lx_scene *sc, lx_scene_plan *p)
{
    for (size_t l = 0; l < sc->n_lum; l++) {
        unsigned long long far = 0;
        for (size_t g = 0; g < p->n_points; g++)
            far += !p->near[l * p->n_points + g];
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
                    if (p->near[l * p->n_points + g] == LX__PATH_AREA) {
                        const double *q = sc->rec[r].points + 3 * i, *s = sc->lum[l].pos_m;
                        double d = sqrt((q[0] - s[0]) * (q[0] - s[0]) + (q[1] - s[1]) * (q[1] - s[1]) +
                                        (q[2] - s[2]) * (q[2] - s[2]));
                        p->estimate.goniometric_lookups +=
                            near_patches(size, d, sc->nearfield_tol, sc->lum[l].radius_m > 0);
                    }
        }
}

/* Marks the device blocks (IES luminaire x grid receiver, every pair far and unoccluded); returns
 * their evaluations. */
static double plan_device_blocks(const lx_scene *sc, lx_scene_plan *p)
{
    double eligible = 0;
    size_t g0 = 0;
    for (size_t r = 0; r < sc->n_rec; r++) {
        const lx_scene_receiver *rc = &sc->rec[r];
        for (size_t l = 0; l < sc->n_lum; l++) {
            if (rc->kind != LX_SREC_GRID || sc->lum[l].kind != LX_SLUM_FILE || !p->on[LX_EFFECT_GONIOMETRIC] ||
                !p->on[LX_EFFECT_COSINE])
                continue;
            size_t k = 0;
            for (size_t i = 0; i < rc->n; i++)
                k += p->near[l * p->n_points + g0 + i] || (p->occ && p->occ[l * p->n_points + g0 + i]);
            if (k == 0) p->device[l * sc->n_rec + r] = 1, eligible += (double)rc->n;
        }
        g0 += rc->n;
    }
    return eligible;
}

/* OpenCL: the far-field work of IES luminaires on grids can run as lx_grid_illuminance
 * batches on a device (its table kernel); only worth it when large enough to repay the
 * start-up (the grid engine's threshold: 1e7 point-luminaire evaluations), unless asked for.
 * Points, spots, areas, near-field pairs, the sky and spectra stay on the CPU. */
static lx_status plan_opencl(lx_ctx *ctx, const lx_scene *sc, lx_backend backend, lx_scene_plan *p)
{
    const lx_effect_force *F = sc->force;
    const double threshold = 1e7;
    double eligible = plan_device_blocks(sc, p);
    int explicit_on =
        F[LX_EFFECT_OPENCL] == LX_FORCE_ON || (backend == LX_BACKEND_OPENCL && F[LX_EFFECT_OPENCL] != LX_FORCE_OFF);
    if (F[LX_EFFECT_OPENCL] == LX_FORCE_ON && !(eligible > 0))
        return lx__error(ctx, LX_EPARSE, sc->file, sc->force_line[LX_EFFECT_OPENCL],
                         "opencl forced on, but no IES luminaire lights a grid entirely in its far field");
    if (F[LX_EFFECT_OPENCL] == LX_FORCE_OFF)
        why(p, LX_EFFECT_OPENCL, 0, "forced off in [effects]");
    else if (!(eligible > 0))
        why(p, LX_EFFECT_OPENCL, 0, "no device work: only far-field IES luminaires on grids run on OpenCL");
    else if (explicit_on)
        why(p, LX_EFFECT_OPENCL, 1, "%s: %.3g far-field IES evaluations on grids",
            F[LX_EFFECT_OPENCL] == LX_FORCE_ON ? "forced on in [effects]" : "backend opencl", eligible);
    else if (backend == LX_BACKEND_CPU)
        why(p, LX_EFFECT_OPENCL, 0, "backend cpu");
    else if (eligible < threshold)
        why(p, LX_EFFECT_OPENCL, 0,
            "%.3g far-field IES evaluations on grids: below the %.0e that repay OpenCL start-up", eligible, threshold);
    else
        why(p, LX_EFFECT_OPENCL, 1, "%.3g far-field IES evaluations on grids: enough to repay OpenCL start-up",
            eligible);
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
    return LX_OK;
}

/* The factor of each luminaire's light in the plan's operation (lx_scene_plan.lum_scale). */
static lx_status plan_scale(lx_ctx *ctx, const lx_scene *sc, lx_scene_mode mode, lx_scene_plan *p)
{
    const lx_scene_design *d = sc->design;
    p->mode = (int)mode;
    p->lum_scale = lx__alloc_n((sc->n_lum ? sc->n_lum : 1), sizeof *p->lum_scale);
    if (!p->lum_scale) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    size_t n_em = 0;
    for (size_t l = 0; l < sc->n_lum; l++) {
        double mf = d && d->lum_mf ? d->lum_mf[l] : 1;
        lx_lum_mode m = d && d->lum_mode ? d->lum_mode[l] : LX_LUM_NORMAL;
        if (mode == LX_SCENE_NORMAL) p->lum_scale[l] = m == LX_LUM_EMERGENCY ? 0 : mf;
        else {
            p->lum_scale[l] = m == LX_LUM_NORMAL ? 0 : mf * d->lum_emergency_lm[l] / sc->lum[l].flux_lm;
            n_em += m != LX_LUM_NORMAL;
        }
    }
    if (mode == LX_SCENE_EMERGENCY && !n_em)
        return lx__error(ctx, LX_EPARSE, sc->file, 0,
                         "emergency lighting: no luminaire has 'emergency = maintained' or 'non-maintained'");
    return LX_OK;
}

lx_status lx_scene_plan_make(lx_ctx *ctx, const lx_scene *sc, lx_backend backend, lx_scene_plan **out)
{
    return lx_scene_plan_make_mode(ctx, sc, backend, LX_SCENE_NORMAL, out);
}

/* EN 1838's emergency operation counts direct light only: the scene planned with interreflection,
 * daylight and the sky forced off (a copy of the scene's header that the plan keeps: the mesh and
 * the daylight state point to it) and those reasons saying why. */
static const char emergency_why[] = "emergency lighting (EN 1838): direct light only, as the standard counts it";

lx_status lx_scene_plan_make_mode(lx_ctx *ctx, const lx_scene *sc, lx_backend backend, lx_scene_mode mode,
                                  lx_scene_plan **out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_plan_make: NULL argument");
    *out = NULL;
    if (backend != LX_BACKEND_AUTO && backend != LX_BACKEND_CPU && backend != LX_BACKEND_OPENCL)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_plan_make: unknown backend %d", (int)backend);
    if (mode != LX_SCENE_NORMAL && mode != LX_SCENE_EMERGENCY)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_plan_make_mode: unknown mode %d", (int)mode);
    lx_scene_plan *p = plan_alloc(sc);
    if (!p) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    lx_status st;
    if ((st = plan_scale(ctx, sc, mode, p)) != LX_OK) goto fail;
    if (mode == LX_SCENE_EMERGENCY) {
        lx_scene *em = lx__alloc(sizeof *em);
        if (!em) {
            st = lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
            goto fail;
        }
        *em = *sc;
        em->force[LX_EFFECT_INTERREFLECTION] = em->force[LX_EFFECT_DAYLIGHT] = em->force[LX_EFFECT_ENVIRONMENT] =
            LX_FORCE_OFF;
        p->internal = em;
        sc = em;
    }
    if ((st = plan_point_laws(ctx, sc, p)) != LX_OK || (st = plan_near_field(ctx, sc, p)) != LX_OK) goto fail;
    /* spectral: only when asked for and every source has a spectrum; the environment */
    if ((st = plan_spectral(ctx, sc, p)) != LX_OK || (st = plan_environment(ctx, sc, p)) != LX_OK) goto fail;
    plan_point_work(sc, p);
    /* daylight through openings (daylight_plan.c: before the rooms, whose mesh takes its openings),
     * occlusion and interreflection (room_plan.c) */
    if ((st = lx__daylight_plan(ctx, sc, p)) != LX_OK) goto fail;
    if ((st = lx__room_plan(ctx, sc, backend, p)) != LX_OK) goto fail;
    if ((st = lx__daylight_plan_after(ctx, sc, p)) != LX_OK) goto fail;
    if ((st = plan_opencl(ctx, sc, backend, p)) != LX_OK) goto fail;
    for (int e = 0; e < LX_EFFECT_COUNT; e++)
        p->forced[e] = sc->force[e] != LX_FORCE_AUTO;
    if (mode == LX_SCENE_EMERGENCY) {
        snprintf(p->reason[LX_EFFECT_INTERREFLECTION], sizeof p->reason[0], "%s", emergency_why);
        snprintf(p->reason[LX_EFFECT_DAYLIGHT], sizeof p->reason[0], "%s", emergency_why);
        snprintf(p->reason[LX_EFFECT_ENVIRONMENT], sizeof p->reason[0], "%s", emergency_why);
    }
    *out = p;
    return LX_OK;
fail:
    lx_scene_plan_free(p);
    return st;
}
