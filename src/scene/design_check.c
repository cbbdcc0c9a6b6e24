/* design_check.c - requirements as data ([requirement NAME]: the values a project must meet, typed
 * by the user from the standard's tables) and the check of a scene's results against them: the
 * statistics of each area, UGR at its observers, R_a of its luminaires, the emergency lighting's
 * minimum and ratio; pass or fail per line. */
#include "scene/design_private.h"
#include "scene/room_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The quantities a requirement may give: key, the check's quantity name, unit, <= (1) or >= (0),
 * and where it is rated. */
enum { ON_AREA, ON_SURROUNDING, ON_BACKGROUND, ON_WALLS, ON_CEILING, ON_CYL, ON_MODELLING, ON_UGR, ON_RA, ON_EMERGENCY, ON_EM_BAND };
typedef struct req_kind {
    const char *key, *quantity, *unit;
    int at_most, on, stat; /* stat: 0 mean, 1 U0, 2 min, 3 max/min, 4 modelling min, 5 modelling max, 6 value */
} req_kind;

static const req_kind kinds[] = {
    {"maintained_illuminance", "E_m", "lx", 0, ON_AREA, 0},
    {"uniformity", "U_0", "", 0, ON_AREA, 1},
    {"minimum_illuminance", "E_min", "lx", 0, ON_AREA, 2},
    {"surrounding_illuminance", "E_m", "lx", 0, ON_SURROUNDING, 0},
    {"surrounding_uniformity", "U_0", "", 0, ON_SURROUNDING, 1},
    {"background_illuminance", "E_m", "lx", 0, ON_BACKGROUND, 0},
    {"background_uniformity", "U_0", "", 0, ON_BACKGROUND, 1},
    {"wall_illuminance", "E_m", "lx", 0, ON_WALLS, 0},
    {"wall_uniformity", "U_0", "", 0, ON_WALLS, 1},
    {"ceiling_illuminance", "E_m", "lx", 0, ON_CEILING, 0},
    {"ceiling_uniformity", "U_0", "", 0, ON_CEILING, 1},
    {"cylindrical_illuminance", "E_z", "lx", 0, ON_CYL, 0},
    {"cylindrical_uniformity", "U_0,z", "", 0, ON_CYL, 1},
    {"modelling", "modelling", "", 0, ON_MODELLING, 4}, /* a range: min >= lo and max <= hi */
    {"ugr_limit", "UGR", "", 1, ON_UGR, 6},
    {"ra", "R_a", "", 0, ON_RA, 6},
    {"emergency_minimum", "E_min", "lx", 0, ON_EMERGENCY, 2},
    {"emergency_ratio", "E_max/E_min", "", 1, ON_EMERGENCY, 3},
    {"emergency_uniformity", "U_0", "", 0, ON_EMERGENCY, 1},
    {"emergency_band_minimum", "E_min", "lx", 0, ON_EM_BAND, 2},
};
#define N_KINDS (sizeof kinds / sizeof kinds[0])
#define K_UGR 14 /* kinds[K_UGR] is ugr_limit */

/* a [requirement NAME] section */
typedef struct lx__req {
    char *name, *area, *reference, *observers;
    const char *file;
    long line, area_line, observers_line;
    int has[N_KINDS];
    double value[N_KINDS][2];
    long key_line[N_KINDS];
    /* resolved: the area's index in lx_scene_design.area (-1: a plain receiver rec) */
    long area_index;
    size_t rec;
} lx__req;

lx_status lx__req_open(lx_ctx *ctx, lx_scene *sc, const char *name, const char *file, long line)
{
    lx__design *in = sc->design->internal;
    lx__req *reqs = in->req;
    for (size_t i = 0; i < in->n_req; i++)
        if (!strcmp(reqs[i].name, name)) return lx__error(ctx, LX_EPARSE, file, line, "requirement '%s' defined twice", name);
    lx__req *nr = lx__realloc_n(in->req, (in->n_req + 1), sizeof *nr);
    if (!nr) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    in->req = nr;
    lx__req *r = &nr[in->n_req++];
    memset(r, 0, sizeof *r);
    r->file = file;
    r->line = line;
    r->name = lx__strdup(name);
    r->reference = lx__strdup("");
    sc->design->n_req = in->n_req;
    return r->name && r->reference ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
}

static lx_status str_value(lx_ctx *ctx, const char *file, long line, const char *value, char **dst)
{
    lx__free(*dst);
    *dst = lx__strdup(value);
    return *dst ? LX_OK : lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
}

lx_status lx__req_key(lx_ctx *ctx, lx_scene *sc, const char *file, long line, const char *key, const char *value)
{
    lx__design *in = sc->design->internal;
    lx__req *r = &((lx__req *)in->req)[in->n_req - 1];
    if (!strcmp(key, "area")) return r->area_line = line, str_value(ctx, file, line, value, &r->area);
    if (!strcmp(key, "reference")) return str_value(ctx, file, line, value, &r->reference);
    if (!strcmp(key, "observers")) return r->observers_line = line, str_value(ctx, file, line, value, &r->observers);
    for (size_t k = 0; k < N_KINDS; k++) {
        if (strcmp(key, kinds[k].key)) continue;
        const req_kind *K = &kinds[k];
        int n = 0, range = K->stat == 4;
        lx_quantity q = *K->unit ? LX_Q_ILLUMINANCE : LX_Q_NONE;
        lx_status st = lx__scene_parse_vec(ctx, file, line, key, value, range ? 2 : 1, range ? 2 : 1, q, NULL, r->value[k], &n);
        if (st != LX_OK) return st;
        for (int i = 0; i < n; i++)
            if (!(r->value[k][i] >= 0))
                return lx__error(ctx, LX_EPARSE, file, line, "%s: must not be negative", key);
        if ((K->stat == 1 || K->stat == 4) && !(r->value[k][n - 1] <= 1))
            return lx__error(ctx, LX_EPARSE, file, line, "%s: a ratio of at most 1 (got %g)", key, r->value[k][n - 1]);
        if (range && !(r->value[k][1] >= r->value[k][0]))
            return lx__error(ctx, LX_EPARSE, file, line, "%s: the range goes from low to high (e.g. 0.3, 0.6)", key);
        r->has[k] = 1;
        r->key_line[k] = line;
        return LX_OK;
    }
    return lx__error(ctx, LX_EPARSE, file, line,
                     "unknown key '%s' in [requirement] (keys: area, reference, observers, maintained_illuminance, "
                     "uniformity, minimum_illuminance, surrounding_illuminance, surrounding_uniformity, "
                     "background_illuminance, background_uniformity, wall_illuminance, wall_uniformity, ceiling_illuminance, "
                     "ceiling_uniformity, cylindrical_illuminance, cylindrical_uniformity, modelling, ugr_limit, ra, "
                     "emergency_minimum, emergency_ratio, emergency_uniformity, emergency_band_minimum)",
                     key);
}

void lx__req_free(lx_scene *sc)
{
    lx__design *in = sc->design->internal;
    lx__req *reqs = in ? in->req : NULL;
    for (size_t i = 0; in && i < in->n_req; i++) {
        lx__free(reqs[i].name);
        lx__free(reqs[i].area);
        lx__free(reqs[i].reference);
        lx__free(reqs[i].observers);
    }
    if (in) lx__free(in->req), in->req = NULL, in->n_req = 0;
}

/* ---- what each key rates ---- */

/* The first area of kind `kind` belonging to area a (a band of task a) or in a's room (walls, ceiling);
 * -1 when none. For walls, *next walks them all. */
static long related_area(const lx_scene_design *d, long a, lx_area_kind kind, long from)
{
    for (size_t i = (size_t)(from + 1); i < d->n_area; i++) {
        const lx_scene_area *A = &d->area[i];
        if (A->kind != kind) continue;
        if (kind == LX_AREA_SURROUNDING || kind == LX_AREA_BACKGROUND) {
            if (A->task == a) return (long)i;
        } else if (a < 0 || A->room == d->area[a].room)
            return (long)i;
    }
    return -1;
}

/* The [observer] section observer i came from (its name; a section of several positions or
 * directions makes one observer each) */
static const char *obs_group(const lx_scene *sc, size_t i)
{
    const lx_scene_design *d = sc->design;
    return d->obs_group ? d->obs_group_name[d->obs_group[i]] : sc->obs[i].name;
}

/* 1 when observer i is rated by a requirement naming `list` (comma-separated names of [observer]
 * sections; NULL: every observer in room `room`, or every one when room < 0) */
static int observer_rated(const lx_scene *sc, size_t i, const char *list, long room)
{
    const lx_scene_observer *o = &sc->obs[i];
    const char *group = obs_group(sc, i);
    if (!list) return room < 0 || lx__room_cell(sc, o->pos_m) == room;
    size_t n = strlen(group);
    for (const char *p = list; *p;) {
        while (*p == ' ' || *p == ',') p++;
        const char *e = p;
        while (*e && *e != ',') e++;
        const char *t = e;
        while (t > p && t[-1] == ' ') t--;
        if ((size_t)(t - p) == n && !strncmp(p, group, n)) return 1;
        p = e;
    }
    return 0;
}

/* 1 when luminaire l lights area a in normal operation (in its room, or every one without rooms) */
static int lights(const lx_scene *sc, size_t l, long room)
{
    if (sc->design->lum_mode[l] == LX_LUM_EMERGENCY) return 0;
    return room < 0 || lx__room_cell(sc, sc->lum[l].pos_m) == room;
}

/* Resolves each requirement's area and checks that something computes every quantity it gives. */
lx_status lx__req_finish(lx_ctx *ctx, lx_scene *sc)
{
    lx_scene_design *d = sc->design;
    lx__design *in = d->internal;
    lx__req *reqs = in->req;
    for (size_t i = 0; i < in->n_req; i++) {
        lx__req *r = &reqs[i];
        if (!r->area)
            return lx__error(ctx, LX_EPARSE, r->file, r->line, "requirement '%s': missing 'area' (the area it applies to)", r->name);
        r->area_index = -1;
        size_t k = 0;
        while (k < sc->n_rec && strcmp(sc->rec[k].name, r->area)) k++;
        if (k == sc->n_rec)
            return lx__error(ctx, LX_EPARSE, r->file, r->area_line, "area: no area or receiver named '%s'", r->area);
        r->rec = k;
        for (size_t a = 0; a < d->n_area; a++)
            if (d->area[a].rec == k) r->area_index = (long)a;
        long room = r->area_index >= 0 ? d->area[r->area_index].room : lx__room_cell(sc, sc->rec[k].points);
        int any = 0;
        for (size_t q = 0; q < N_KINDS; q++) {
            if (!r->has[q]) continue;
            any = 1;
            const req_kind *K = &kinds[q];
            long line = r->key_line[q];
            const char *why = NULL;
            char buf[300];
            switch (K->on) {
            case ON_SURROUNDING:
            case ON_BACKGROUND:
                if (r->area_index < 0 || d->area[r->area_index].kind != LX_AREA_TASK) why = "its area is not a task area";
                else if (related_area(d, r->area_index, K->on == ON_SURROUNDING ? LX_AREA_SURROUNDING : LX_AREA_BACKGROUND, -1) < 0)
                    why = K->on == ON_SURROUNDING ? "the task area has no surrounding band (surrounding = no, or walls)"
                                                   : "the task area has no background band (background = no, or walls)";
                break;
            case ON_WALLS:
            case ON_CEILING:
                if (room < 0 || related_area(d, r->area_index, K->on == ON_WALLS ? LX_AREA_WALL : LX_AREA_CEILING, -1) < 0)
                    why = K->on == ON_WALLS ? "no [area] of type walls in its room" : "no [area] of type ceiling in its room";
                break;
            case ON_CYL:
            case ON_MODELLING:
                if (!(d->rec_cylinder[k] & LX_REC_CYLINDRICAL)) why = "its area computes no cylindrical illuminance (cylindrical = yes)";
                else if (K->on == ON_MODELLING && !(sc->rec[k].normal[2] == 1)) why = "the modelling ratio needs an area facing up";
                break;
            case ON_UGR: {
                size_t n = 0;
                for (size_t o = 0; o < sc->n_obs; o++) n += observer_rated(sc, o, r->observers, room);
                if (!n) why = r->observers ? "no [observer] of that name" : "no [observer] in its room to rate UGR at";
                break;
            }
            case ON_RA: {
                size_t n = 0;
                for (size_t l = 0; l < sc->n_lum; l++) {
                    if (!lights(sc, l, room)) continue;
                    n++;
                    if (!sc->lum[l].spd) {
                        snprintf(buf, sizeof buf, "luminaire '%s' has no spectrum ('spd') to compute R_a from", sc->lum[l].name);
                        why = buf;
                        break;
                    }
                }
                if (!n) why = "no luminaire lights its room";
                break;
            }
            case ON_EMERGENCY:
            case ON_EM_BAND: {
                size_t n = 0;
                for (size_t l = 0; l < sc->n_lum; l++) n += d->lum_mode[l] != LX_LUM_NORMAL;
                if (!n) why = "no luminaire has 'emergency = maintained' or 'non-maintained'";
                else if (K->on == ON_EM_BAND && (r->area_index < 0 || d->area[r->area_index].kind != LX_AREA_ESCAPE_ROUTE))
                    why = "its area is not an escape route";
                break;
            }
            default: break;
            }
            if (why)
                return lx__error(ctx, LX_EPARSE, r->file, line, "requirement '%s': %s is not computed: %s", r->name, K->key, why);
            d->check_glare |= K->on == ON_UGR;
            d->check_emergency |= K->on == ON_EMERGENCY || K->on == ON_EM_BAND;
        }
        if (r->observers && !r->has[K_UGR])
            return lx__error(ctx, LX_EPARSE, r->file, r->observers_line, "observers: only with ugr_limit");
        if (!any)
            return lx__error(ctx, LX_EPARSE, r->file, r->line, "requirement '%s': no quantity required (e.g. maintained_illuminance)",
                             r->name);
    }
    return LX_OK;
}

/* ---- statistics and the check ---- */

lx_status lx_scene_area_stats(lx_ctx *ctx, const lx_scene *sc, const lx_scene_result *res, size_t rec, lx_area_stats *out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !res || !out || rec >= sc->n_rec) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_area_stats: bad arguments");
    size_t a = res->first[rec], b = res->first[rec + 1];
    if (b - a != sc->rec[rec].n) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_area_stats: a result of another scene");
    memset(out, 0, sizeof *out);
    out->n = b - a;
    double s = 0, mn = INFINITY, mx = -INFINITY, cs = 0, cmn = INFINITY, mlo = INFINITY, mhi = -INFINITY;
    size_t nc = 0;
    for (size_t g = a; g < b; g++) {
        s += res->E_lx[g], mn = fmin(mn, res->E_lx[g]), mx = fmax(mx, res->E_lx[g]);
        if (res->cylindrical_lx && !isnan(res->cylindrical_lx[g]))
            cs += res->cylindrical_lx[g], cmn = fmin(cmn, res->cylindrical_lx[g]), nc++;
        if (res->modelling && !isnan(res->modelling[g])) mlo = fmin(mlo, res->modelling[g]), mhi = fmax(mhi, res->modelling[g]);
    }
    double n = (double)out->n;
    out->mean_lx = s / n, out->min_lx = mn, out->max_lx = mx;
    out->u0 = out->mean_lx > 0 ? mn / out->mean_lx : NAN;
    out->min_max = mx > 0 ? mn / mx : NAN;
    out->cyl_mean_lx = nc ? cs / (double)nc : NAN;
    out->cyl_min_lx = nc ? cmn : NAN;
    out->cyl_u0 = nc && cs > 0 ? cmn / (cs / (double)nc) : NAN;
    out->modelling_min = mhi >= mlo ? mlo : NAN;
    out->modelling_max = mhi >= mlo ? mhi : NAN;
    return LX_OK;
}

void lx_scene_checks_free(lx_scene_checks *c)
{
    if (!c) return;
    lx__free(c->check);
    lx__free(c);
}

static lx_status push(lx_ctx *ctx, lx_scene_checks *c, const lx_check *k)
{
    lx_check *n = lx__realloc_n(c->check, (c->n + 1), sizeof *n);
    if (!n) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    c->check = n;
    c->check[c->n++] = *k;
    return LX_OK;
}

/* one line: the statistic `stat` of receiver rec against the requirement */
static lx_status area_line(lx_ctx *ctx, const lx_scene *sc, const lx_scene_result *res, size_t rec, const req_kind *K,
                           double required, int at_most, const char *quantity, lx_check *k, lx_scene_checks *c)
{
    lx_area_stats st;
    lx_status s = lx_scene_area_stats(ctx, sc, res, rec, &st);
    if (s != LX_OK) return s;
    int cyl = K->on == ON_CYL;
    double v = K->stat == 0 ? (cyl ? st.cyl_mean_lx : st.mean_lx)
               : K->stat == 1 ? (cyl ? st.cyl_u0 : st.u0)
               : K->stat == 2 ? st.min_lx
               : K->stat == 3 ? (st.min_lx > 0 ? st.max_lx / st.min_lx : INFINITY)
               : K->stat == 4 ? st.modelling_min
                              : st.modelling_max;
    k->target = sc->rec[rec].name;
    k->quantity = quantity;
    k->unit = K->unit;
    k->required = required;
    k->at_most = at_most;
    k->value = v;
    k->pass = at_most ? v <= required : v >= required;
    return push(ctx, c, k);
}

/* The cells of one requirement. */
static lx_status check_req(lx_ctx *ctx, const lx_scene *sc, const lx__req *r, const lx_scene_result *res,
                           const lx_scene_result *em, const lx_scene_glare *glare, lx_scene_checks *c)
{
    const lx_scene_design *d = sc->design;
    long room = r->area_index >= 0 ? d->area[r->area_index].room : lx__room_cell(sc, sc->rec[r->rec].points);
    lx_status st = LX_OK;
    for (size_t q = 0; q < N_KINDS && st == LX_OK; q++) {
        if (!r->has[q]) continue;
        const req_kind *K = &kinds[q];
        lx_check k;
        memset(&k, 0, sizeof k);
        k.requirement = r->name, k.reference = r->reference, k.file = r->file, k.line = r->key_line[q];
        switch (K->on) {
        case ON_AREA:
        case ON_CYL: st = area_line(ctx, sc, res, r->rec, K, r->value[q][0], K->at_most, K->quantity, &k, c); break;
        case ON_MODELLING: {
            req_kind lo = *K, hi = *K;
            hi.stat = 5;
            st = area_line(ctx, sc, res, r->rec, &lo, r->value[q][0], 0, "modelling min", &k, c);
            if (st == LX_OK) st = area_line(ctx, sc, res, r->rec, &hi, r->value[q][1], 1, "modelling max", &k, c);
            break;
        }
        case ON_SURROUNDING:
        case ON_BACKGROUND:
        case ON_WALLS:
        case ON_CEILING: {
            lx_area_kind kind = K->on == ON_SURROUNDING ? LX_AREA_SURROUNDING
                                : K->on == ON_BACKGROUND ? LX_AREA_BACKGROUND
                                : K->on == ON_WALLS      ? LX_AREA_WALL
                                                         : LX_AREA_CEILING;
            for (long a = related_area(d, r->area_index, kind, -1); a >= 0 && st == LX_OK; a = related_area(d, r->area_index, kind, a)) {
                st = area_line(ctx, sc, res, d->area[a].rec, K, r->value[q][0], 0, K->quantity, &k, c);
                if (kind == LX_AREA_SURROUNDING || kind == LX_AREA_BACKGROUND) break;
            }
            break;
        }
        case ON_EM_BAND:
        case ON_EMERGENCY:
            if (!em) return lx__error(ctx, LX_EINVAL, r->file, k.line, "requirement '%s': %s needs the emergency operation's results",
                                      r->name, K->key);
            k.emergency = 1;
            st = area_line(ctx, sc, em, K->on == ON_EM_BAND ? d->area[r->area_index + 1].rec : r->rec, K, r->value[q][0],
                           K->at_most, K->quantity, &k, c);
            break;
        case ON_UGR: {
            if (!glare) return lx__error(ctx, LX_EINVAL, r->file, k.line, "requirement '%s': ugr_limit needs the glare results", r->name);
            /* the highest UGR of each rated observer (over its positions and directions) */
            for (size_t o = 0; o < sc->n_obs && st == LX_OK; o++) {
                if (!observer_rated(sc, o, r->observers, room)) continue;
                const char *group = obs_group(sc, o);
                int seen = 0;
                for (size_t p = 0; p < o && !seen; p++) seen = observer_rated(sc, p, r->observers, room) && !strcmp(obs_group(sc, p), group);
                if (seen) continue;
                double worst = -INFINITY;
                for (size_t p = o; p < sc->n_obs; p++)
                    if (!strcmp(obs_group(sc, p), group) && !isnan(glare->ugr[p])) worst = fmax(worst, glare->ugr[p]);
                k.target = group;
                k.quantity = K->quantity, k.unit = K->unit, k.at_most = 1, k.required = r->value[q][0];
                k.value = worst > -INFINITY ? worst : NAN; /* no glare source in view: nothing to rate */
                k.pass = isnan(k.value) || k.value <= k.required;
                st = push(ctx, c, &k);
            }
            break;
        }
        case ON_RA:
            for (size_t l = 0; l < sc->n_lum && st == LX_OK; l++) {
                if (!lights(sc, l, room)) continue;
                lx_cri cri;
                const lx_scene_luminaire *L = &sc->lum[l];
                if ((st = lx_cri_compute(ctx, &L->spd->spd[L->spd_index], &cri)) != LX_OK)
                    return lx__error(ctx, st, L->file, L->line, "luminaire '%s': R_a: %s", L->name, lx_ctx_errmsg(ctx));
                k.target = L->name, k.quantity = K->quantity, k.unit = "", k.at_most = 0, k.required = r->value[q][0];
                k.value = cri.ra;
                k.pass = cri.ra >= k.required;
                st = push(ctx, c, &k);
            }
            break;
        }
    }
    return st;
}

lx_status lx_scene_check(lx_ctx *ctx, const lx_scene *sc, const lx_scene_result *res, const lx_scene_result *em,
                         const lx_scene_glare *glare, lx_scene_checks **out)
{
    LX__NEED_CTX(ctx);
    if (!sc || !res || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_scene_check: NULL argument");
    *out = NULL;
    lx_scene_checks *c = lx__calloc(1, sizeof *c);
    if (!c) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    const lx__design *in = sc->design->internal;
    const lx__req *reqs = in->req;
    lx_status st = LX_OK;
    for (size_t i = 0; i < in->n_req && st == LX_OK; i++) st = check_req(ctx, sc, &reqs[i], res, em, glare, c);
    if (st != LX_OK) {
        lx_scene_checks_free(c);
        return st;
    }
    for (size_t i = 0; i < c->n; i++) c->n_fail += !c->check[i].pass;
    c->all_pass = c->n_fail == 0;
    *out = c;
    return LX_OK;
}
