/* photometry.c - the luminaire intensity model: reading by content (IES or EULUMDAT), checking
 * and expanding the stored symmetry to the full sphere, interpolation in (C, gamma) (bilinear or
 * monotone cubic), tilt factors, the exact flux integral, beam and field angles, analytic models. */
#include "lighting/lighting_private.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>


const char *lx_lum_format_name(lx_lum_format f)
{
    switch (f) {
    case LX_LUM_LM63_1986: return "LM-63-1986";
    case LX_LUM_LM63_1991: return "LM-63-1991";
    case LX_LUM_LM63_1995: return "LM-63-1995";
    case LX_LUM_LM63_2002: return "LM-63-2002";
    case LX_LUM_LM63_2019: return "LM-63-2019";
    case LX_LUM_EULUMDAT: return "EULUMDAT";
    }
    return "unknown";
}

const char *lx_lum_symmetry_name(lx_lum_symmetry s)
{
    switch (s) {
    case LX_SYM_AXIAL: return "axial";
    case LX_SYM_QUADRANT: return "quadrant";
    case LX_SYM_C0_C180: return "C0-C180";
    case LX_SYM_C90_C270: return "C90-C270";
    case LX_SYM_NONE: return "none";
    case LX_SYM_B_LATERAL: return "B-lateral";
    }
    return "unknown";
}

lx_luminaire *lx__lum_new(const char *file)
{
    lx_luminaire *l = lx__calloc(1, sizeof *l);
    if (!l) return NULL;
    l->file = lx__strdup(file ? file : "");
    if (!l->file) {
        lx__free(l);
        return NULL;
    }
    l->lamp_lumens = l->stated_lumens = l->input_watts = NAN;
    l->multiplier = l->ballast_factor = l->ballast_lamp_factor = 1;
    l->photometric_type = 1;
    return l;
}

void lx_luminaire_free(lx_luminaire *l)
{
    if (!l) return;
    lx__free(l->file);
    lx__free(l->h_deg);
    lx__free(l->v_deg);
    lx__free(l->cd);
    lx__free(l->c_deg);
    lx__free(l->g_deg);
    lx__free(l->full_cd);
    lx__free(l->tilt_deg);
    lx__free(l->tilt_factor);
    lx__free(l->manufacturer);
    lx__free(l->catalog);
    lx__free(l->description);
    lx__free(l->test);
    lx__free(l->testlab);
    lx__free(l->issuedate);
    lx__free(l->lamp);
    lx__free(l);
}

/* ---- reading ---- */

static int has_tilt_line(const char *text, size_t len)
{
    lx__lines it = {text, text + len, 0};
    const char *s, *e;
    while (lx__next_line(&it, &s, &e)) {
        while (s < e && (*s == ' ' || *s == '\t')) s++;
        if (e - s >= 5 && (s[0] == 'T' || s[0] == 't') && (s[1] == 'I' || s[1] == 'i') && (s[2] == 'L' || s[2] == 'l') &&
            (s[3] == 'T' || s[3] == 't')) {
            const char *q = s + 4;
            while (q < e && *q == ' ') q++;
            if (q < e && *q == '=') return 1;
        }
    }
    return 0;
}

/* 1 when the lines that follow EULUMDAT's first (Ityp, Isym, Mc, Dc, Ng, Dg) hold numbers as far as
 * the file goes; else the line number of the first that does not, in *bad */
static int looks_ldt(const char *text, size_t len, long *bad)
{
    lx__lines it = {text, text + len, 0};
    const char *s, *e;
    if (!lx__next_line(&it, &s, &e)) return 1;
    for (int k = 0; k < 6 && lx__next_line(&it, &s, &e); k++) {
        while (s < e && (*s == ' ' || *s == '\t')) s++;
        while (e > s && (e[-1] == ' ' || e[-1] == '\t')) e--;
        double v;
        if (s == e || lx__parse_double(s, e, &v) != e) {
            *bad = it.line;
            return 0;
        }
    }
    return 1;
}

/* up to cap - 1 bytes of [s, e) with every byte outside printable ASCII as \xNN */
static void escaped(char *buf, size_t cap, const char *s, const char *e)
{
    size_t k = 0;
    for (; s < e && k + 8 < cap; s++) {
        unsigned char c = (unsigned char)*s;
        if (c >= 32 && c < 127 && c != '\\') buf[k++] = (char)c;
        else k += (size_t)snprintf(buf + k, cap - k, "\\x%02X", c);
    }
    if (s < e && k + 4 < cap) memcpy(buf + k, "...", 3), k += 3; /* cut short */
    buf[k] = 0;
}

lx_status lx_luminaire_read_mem(lx_ctx *ctx, const char *name, const char *text, size_t len, lx_luminaire **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!out || (!text && len)) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_luminaire_read_mem: NULL argument");
    if (!name) name = "(memory)";
    if (len == 0) return lx__error(ctx, LX_EPARSE, name, 1, "empty file");
    /* LM-63 by its TILT= line, or by its version line (then the IES reader reports the missing TILT) */
    size_t skip = len >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3) ? 3 : 0;
    if (len == skip) return lx__error(ctx, LX_EPARSE, name, 1, "empty file (a byte-order mark only)");
    int ies_version = (len - skip >= 6 && !memcmp(text + skip, "IESNA", 5)) || (len - skip >= 4 && !memcmp(text + skip, "IES:", 4));
    if (has_tilt_line(text, len) || ies_version) return lx__ies_read(ctx, name, text, len, out);
    long bad = 0;
    if (!looks_ldt(text + skip, len - skip, &bad)) {
        lx__lines it = {text + skip, text + len, 0};
        const char *s, *e;
        for (long k = 0; k < bad && lx__next_line(&it, &s, &e);) k = it.line;
        char line[64], first[64]; /* excerpts: the message stays short */
        escaped(line, sizeof line, s, e);
        it = (lx__lines){text + skip, text + len, 0};
        lx__next_line(&it, &s, &e);
        escaped(first, sizeof first, s, e);
        return lx__error(ctx, LX_EPARSE, name, bad,
                         "neither IES LM-63 (no TILT= line, no IESNA version line) nor EULUMDAT (line %ld, \"%s\", is not "
                         "a number); the file begins \"%s\"",
                         bad, line, first);
    }
    return lx__ldt_read(ctx, name, text, len, out);
}

lx_status lx_luminaire_read_file(lx_ctx *ctx, const char *path, lx_luminaire **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_luminaire_read_file: NULL argument");
    char *buf;
    size_t len;
    lx_status st = lx__read_all(ctx, path, LX_INPUT_LUMINAIRE, &buf, &len);
    if (st != LX_OK) return st;
    st = lx_luminaire_read_mem(ctx, path, buf, len, out);
    lx__free(buf);
    return st;
}

/* ---- checking and expanding ---- */

#define ANG_EPS 1e-9

static int near(double a, double b) { return fabs(a - b) <= ANG_EPS; }

typedef struct img {
    double ang;
    size_t src;
} img;

static int img_cmp(const void *a, const void *b)
{
    double x = ((const img *)a)->ang, y = ((const img *)b)->ang;
    return x < y ? -1 : x > y;
}

/* Sorts images by angle and drops duplicates (the planes a symmetry maps onto themselves). */
static size_t img_unique(img *v, size_t n)
{
    qsort(v, n, sizeof *v, img_cmp);
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (k == 0 || !near(v[i].ang, v[k - 1].ang)) v[k++] = v[i];
    return k;
}

lx_status lx__lum_finish(lx_ctx *ctx, lx_luminaire *l, long line_h, long line_v, long line_cd)
{
    const char *f = l->file;
    size_t nh = l->n_h, nv = l->n_v;
    (void)line_cd;
    for (size_t i = 1; i < nv; i++)
        if (!(l->v_deg[i] > l->v_deg[i - 1]))
            return lx__error(ctx, LX_EPARSE, f, line_v, "vertical angles out of order (%g after %g)", l->v_deg[i], l->v_deg[i - 1]);
    for (size_t i = 1; i < nh; i++)
        if (!(l->h_deg[i] > l->h_deg[i - 1]))
            return lx__error(ctx, LX_EPARSE, f, line_h, "horizontal angles out of order (%g after %g)", l->h_deg[i], l->h_deg[i - 1]);
    double v0 = l->v_deg[0], v1 = l->v_deg[nv - 1], h0 = l->h_deg[0], h1 = l->h_deg[nh - 1];
    img *ci = NULL, *gi = NULL;
    size_t nc = 0, ng = 0;
    if (l->photometric_type == 1) {
        if (!(near(v0, 0) || near(v0, 90)) || !(near(v1, 90) || near(v1, 180)) || nv < 2)
            return lx__error(ctx, LX_EPARSE, f, line_v,
                             "incomplete vertical angle set %g..%g (type C needs 0 or 90 to 90 or 180, at least 2 angles)", v0, v1);
        if (near(h0, 0) && nh == 1) l->symmetry = LX_SYM_AXIAL;
        else if (near(h0, 0) && near(h1, 90)) l->symmetry = LX_SYM_QUADRANT;
        else if (near(h0, 0) && near(h1, 180)) l->symmetry = LX_SYM_C0_C180;
        else if (near(h0, 90) && near(h1, 270)) l->symmetry = LX_SYM_C90_C270;
        else if (near(h0, 0) && h1 > 180 && h1 <= 360 + ANG_EPS) l->symmetry = LX_SYM_NONE;
        else
            return lx__error(ctx, LX_EPARSE, f, line_h,
                             "incomplete horizontal angle set %g..%g (expected 0, 0-90, 0-180, 90-270 or 0-360)", h0, h1);
        ci = lx__alloc_n(4 * nh + 2, sizeof *ci);
        gi = lx__alloc_n(nv, sizeof *gi);
        if (!ci || !gi) goto nomem;
        for (size_t j = 0; j < nv; j++) gi[ng++] = (img){l->v_deg[j], j};
        for (size_t i = 0; i < nh; i++) {
            double h = l->h_deg[i];
            switch (l->symmetry) {
            case LX_SYM_AXIAL: ci[nc++] = (img){0, i}; break;
            case LX_SYM_QUADRANT:
                ci[nc++] = (img){h, i};
                ci[nc++] = (img){180 - h, i};
                ci[nc++] = (img){180 + h, i};
                ci[nc++] = (img){360 - h, i};
                break;
            case LX_SYM_C0_C180:
                ci[nc++] = (img){h, i};
                ci[nc++] = (img){360 - h, i};
                break;
            case LX_SYM_C90_C270: /* mirror about the C90-C270 plane: C -> 180 - C (mod 360) */
                ci[nc++] = (img){h, i};
                if (h >= 90 - ANG_EPS && h <= 180 + ANG_EPS) ci[nc++] = (img){180 - h, i};
                if (h >= 180 - ANG_EPS) ci[nc++] = (img){540 - h, i};
                break;
            default:
                ci[nc++] = (img){h, i};
                if (near(h, 0) && !near(h1, 360)) ci[nc++] = (img){360, i}; /* close the circle */
                break;
            }
        }
    } else { /* type B: H -90..90 (or 0..90, laterally symmetric), V -90..90 (or 0..90, symmetric) */
        if (!(near(h0, -90) || near(h0, 0)) || !near(h1, 90) || nh < 2)
            return lx__error(ctx, LX_EPARSE, f, line_h, "incomplete horizontal angle set %g..%g (type B needs -90 or 0 to 90)", h0, h1);
        if (!(v0 >= -180 - ANG_EPS && v1 <= 180 + ANG_EPS) || nv < 2 || !(near(v0, 0) || v0 < 0))
            return lx__error(ctx, LX_EPARSE, f, line_v, "incomplete vertical angle set %g..%g (type B needs -90 or 0 to 90)", v0, v1);
        l->symmetry = near(h0, 0) ? LX_SYM_B_LATERAL : LX_SYM_NONE;
        ci = lx__alloc_n(2 * nh, sizeof *ci);
        gi = lx__alloc_n(2 * nv, sizeof *gi);
        if (!ci || !gi) goto nomem;
        for (size_t i = 0; i < nh; i++) {
            ci[nc++] = (img){l->h_deg[i], i};
            if (near(h0, 0)) ci[nc++] = (img){-l->h_deg[i], i};
        }
        for (size_t j = 0; j < nv; j++) {
            gi[ng++] = (img){l->v_deg[j], j};
            if (near(v0, 0)) gi[ng++] = (img){-l->v_deg[j], j};
        }
    }
    nc = img_unique(ci, nc);
    ng = img_unique(gi, ng);
    l->n_c = nc;
    l->n_g = ng;
    l->c_deg = lx__alloc_n(nc, sizeof(double));
    l->g_deg = lx__alloc_n(ng, sizeof(double));
    l->full_cd = lx__alloc_n(nc * ng, sizeof(double));
    if (!l->c_deg || !l->g_deg || !l->full_cd) goto nomem;
    for (size_t i = 0; i < nc; i++) l->c_deg[i] = ci[i].ang;
    for (size_t j = 0; j < ng; j++) l->g_deg[j] = gi[j].ang;
    for (size_t i = 0; i < nc; i++)
        for (size_t j = 0; j < ng; j++) l->full_cd[i * ng + j] = l->cd[ci[i].src * nv + gi[j].src];
    lx__free(ci);
    lx__free(gi);
    return LX_OK;
nomem:
    lx__free(ci);
    lx__free(gi);
    return lx__error(ctx, LX_ENOMEM, f, 0, "out of memory");
}

/* ---- interpolation ---- */

/* Index i with xs[i] <= x <= xs[i+1] (n >= 2, x inside). */
static size_t cell(const double *xs, size_t n, double x)
{
    size_t lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (xs[mid] <= x) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* Fritsch-Carlson slope at a node from the secants on each side (0 at extrema). */
static double pchip_slope(double h0, double d0, double h1, double d1)
{
    if (d0 * d1 <= 0) return 0;
    double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
    return (w1 + w2) / (w1 / d0 + w2 / d1);
}

/* Monotone cubic on the cell [x1, x2] with neighbours x0 (NaN: none) and x3 (NaN: none). */
static double pchip4(double x0, double y0, double x1, double y1, double x2, double y2, double x3, double y3, double x)
{
    double h = x2 - x1;
    if (!(h > 0)) return y1;
    double d = (y2 - y1) / h;
    double m1 = isnan(x0) ? d : pchip_slope(x1 - x0, (y1 - y0) / (x1 - x0), h, d);
    double m2 = isnan(x3) ? d : pchip_slope(h, d, x3 - x2, (y3 - y2) / (x3 - x2));
    double t = (x - x1) / h, t2 = t * t, t3 = t2 * t;
    double v = (2 * t3 - 3 * t2 + 1) * y1 + (t3 - 2 * t2 + t) * h * m1 + (-2 * t3 + 3 * t2) * y2 + (t3 - t2) * h * m2;
    return v < 0 ? 0 : v;
}

/* Smooth interpolation along the vertical angle in plane i at g, inside [g0, g_last]. */
static double smooth_g(const lx_luminaire *l, size_t i, size_t j, double g)
{
    const double *gs = l->g_deg, *y = l->full_cd + i * l->n_g;
    size_t n = l->n_g;
    double x0 = j > 0 ? gs[j - 1] : NAN, y0 = j > 0 ? y[j - 1] : 0;
    double x3 = j + 2 < n ? gs[j + 2] : NAN, y3 = j + 2 < n ? y[j + 2] : 0;
    return pchip4(x0, y0, gs[j], y[j], gs[j + 1], y[j + 1], x3, y3, g);
}

/* Intensity at plane angle c and vertical angle g (degrees), both in the expanded frame. */
static double eval_cg(const lx_luminaire *l, lx_interp interp, double c, double g)
{
    const double *gs = l->g_deg;
    size_t ng = l->n_g, nc = l->n_c;
    if (g < gs[0] - ANG_EPS || g > gs[ng - 1] + ANG_EPS) return 0;
    if (g < gs[0]) g = gs[0];
    if (g > gs[ng - 1]) g = gs[ng - 1];
    size_t j = ng >= 2 ? cell(gs, ng, g) : 0;
    double tg = ng >= 2 ? (g - gs[j]) / (gs[j + 1] - gs[j]) : 0;
    int periodic = l->photometric_type == 1;
    if (periodic) {
        c = fmod(c, 360.0);
        if (c < 0) c += 360.0;
    }
    if (nc == 1) {
        if (interp == LX_INTERP_SMOOTH && ng >= 2) return smooth_g(l, 0, j, g);
        const double *y = l->full_cd;
        return ng >= 2 ? y[j] + tg * (y[j + 1] - y[j]) : y[0];
    }
    const double *cs = l->c_deg;
    if (c < cs[0] - ANG_EPS || c > cs[nc - 1] + ANG_EPS) return 0; /* type B outside H */
    if (c < cs[0]) c = cs[0];
    if (c > cs[nc - 1]) c = cs[nc - 1];
    size_t i = cell(cs, nc, c);
    double tc = (c - cs[i]) / (cs[i + 1] - cs[i]);
    if (interp != LX_INTERP_SMOOTH || ng < 2) {
        const double *a = l->full_cd + i * ng, *b = a + ng;
        if (ng < 2) return a[0] + tc * (b[0] - a[0]);
        double va = a[j] + tg * (a[j + 1] - a[j]);
        double vb = b[j] + tg * (b[j + 1] - b[j]);
        return va + tc * (vb - va);
    }
    /* smooth: cubic along g in four planes, then along c (wrapping for type C: C0 = C360) */
    double xs[4], ys[4];
    for (int k = -1; k <= 2; k++) {
        long ii = (long)i + k;
        double off = 0;
        if (periodic) {
            if (ii < 0) {
                ii += (long)nc - 1;
                off = -360;
            } else if (ii >= (long)nc) {
                ii -= (long)nc - 1;
                off = 360;
            }
        }
        if (ii < 0 || ii >= (long)nc) {
            xs[k + 1] = NAN;
            ys[k + 1] = 0;
            continue;
        }
        xs[k + 1] = cs[ii] + off;
        ys[k + 1] = smooth_g(l, (size_t)ii, j, g);
    }
    return pchip4(xs[0], ys[0], xs[1], ys[1], xs[2], ys[2], xs[3], ys[3], c);
}

double lx_luminaire_intensity(const lx_luminaire *l, lx_interp interp, double c_rad, double gamma_rad)
{
    if (!l || !l->full_cd) return NAN;
    return eval_cg(l, interp, c_rad / LX__DEG, gamma_rad / LX__DEG);
}

double lx_luminaire_intensity_dir(const lx_luminaire *l, lx_interp interp, double x, double y, double z)
{
    if (!l || !l->full_cd) return NAN;
    double r = sqrt(x * x + y * y + z * z);
    if (!(r > 0)) return NAN;
    x /= r;
    y /= r;
    z /= r;
    if (l->photometric_type == 1) {
        double g = atan2(hypot(x, y), -z) / LX__DEG;
        double c = (x == 0 && y == 0) ? 0 : atan2(y, x) / LX__DEG;
        return eval_cg(l, interp, c, g);
    }
    double h = asin(y > 1 ? 1 : y < -1 ? -1 : y) / LX__DEG;
    double v = atan2(x, -z) / LX__DEG;
    return eval_cg(l, interp, h, v);
}

double lx_luminaire_tilt_factor(const lx_luminaire *l, double tilt_rad)
{
    if (!l || !l->tilt_include || l->n_tilt == 0) return 1.0;
    double a = tilt_rad / LX__DEG;
    const double *x = l->tilt_deg, *y = l->tilt_factor;
    size_t n = l->n_tilt;
    if (n == 1 || a <= x[0]) return y[0];
    if (a >= x[n - 1]) return y[n - 1];
    size_t i = cell(x, n, a);
    return y[i] + (a - x[i]) / (x[i + 1] - x[i]) * (y[i + 1] - y[i]);
}

/* ---- the exact integral ---- */

/* Integrals over [a, b] (radians) of the two linear basis functions times w(x):
 * type C, w = sin x: lo = (h cos a + sin a - sin b) / h, hi = (sin b - sin a - h cos b) / h;
 * type B, w = cos x: lo = (cos a - cos b - h sin a) / h, hi = (h sin b + cos b - cos a) / h.
 * sin b - sin a = 2 cos((a+b)/2) sin(h/2) and cos a - cos b = 2 sin((a+b)/2) sin(h/2) avoid the
 * cancellation of the differences. */
static void basis_w(int type, double a, double b, double *lo, double *hi)
{
    double h = b - a, s2 = 2 * sin(0.5 * h), m = 0.5 * (a + b);
    if (type == 1) {
        double ds = cos(m) * s2; /* sin b - sin a */
        *lo = (h * cos(a) - ds) / h;
        *hi = (ds - h * cos(b)) / h;
    } else {
        double dc = sin(m) * s2; /* cos a - cos b */
        *lo = (dc - h * sin(a)) / h;
        *hi = (h * sin(b) - dc) / h;
    }
}

/* Flux of the bilinear interpolant with the vertical angle clipped to [glo, ghi] degrees (type C). */
static double integrate(const lx_luminaire *l, double glo, double ghi)
{
    const double *g = l->g_deg, *c = l->c_deg, *I = l->full_cd;
    size_t ng = l->n_g, nc = l->n_c;
    double sum = 0;
    if (l->photometric_type == 1) {
        /* sum over cells of dc/2 x sum of corners x basis_w in gamma */
        for (size_t j = 0; j + 1 < ng; j++) {
            double a = g[j], b = g[j + 1];
            if (b <= glo || a >= ghi) continue;
            double a2 = a < glo ? glo : a, b2 = b > ghi ? ghi : b;
            double lo, hi;
            basis_w(1, a2 * LX__DEG, b2 * LX__DEG, &lo, &hi);
            double ta = (a2 - a) / (b - a), tb = (b2 - a) / (b - a);
            if (nc == 1) {
                double ya = I[j] + ta * (I[j + 1] - I[j]), yb = I[j] + tb * (I[j + 1] - I[j]);
                sum += 2 * LX__PI * (ya * lo + yb * hi);
                continue;
            }
            for (size_t i = 0; i + 1 < nc; i++) {
                double dc = (c[i + 1] - c[i]) * LX__DEG;
                const double *p = I + i * ng, *q = p + ng;
                double pa = p[j] + ta * (p[j + 1] - p[j]), pb = p[j] + tb * (p[j + 1] - p[j]);
                double qa = q[j] + ta * (q[j + 1] - q[j]), qb = q[j] + tb * (q[j + 1] - q[j]);
                sum += 0.5 * dc * ((pa + qa) * lo + (pb + qb) * hi);
            }
        }
        return sum;
    }
    /* type B: planes H carry the weight cos H, V is linear */
    (void)glo;
    (void)ghi;
    for (size_t i = 0; i + 1 < nc; i++) {
        double lo, hi;
        basis_w(2, c[i] * LX__DEG, c[i + 1] * LX__DEG, &lo, &hi);
        const double *p = I + i * ng, *q = p + ng;
        for (size_t j = 0; j + 1 < ng; j++) {
            double dv = (g[j + 1] - g[j]) * LX__DEG;
            sum += 0.5 * dv * ((p[j] + p[j + 1]) * lo + (q[j] + q[j + 1]) * hi);
        }
    }
    return sum;
}

/* Walks the plane pair (ca, ca + 180) from the in-plane peak both ways to where I falls below
 * frac x that peak; the full angle between the two crossings (NaN when it never falls). */
static double spread_angle(const lx_luminaire *l, double ca, double frac, double *peak_out)
{
    const double step = 0.01;
    int n = (int)(360 / step);
    /* t in [-180, 180]: t >= 0 is plane ca at gamma t, t < 0 is plane ca + 180 at gamma -t */
    double best = -1, tbest = 0;
    for (int k = 0; k <= n; k++) {
        double t = -180 + k * step;
        double v = t >= 0 ? eval_cg(l, LX_INTERP_BILINEAR, ca, t) : eval_cg(l, LX_INTERP_BILINEAR, ca + 180, -t);
        if (v > best) {
            best = v;
            tbest = t;
        }
    }
    if (peak_out) *peak_out = best;
    if (!(best > 0)) return NAN;
    double thr = frac * best, ends[2];
    for (int side = 0; side < 2; side++) {
        double dir = side ? 1 : -1, prev = best, t = tbest;
        ends[side] = NAN;
        for (;;) {
            double tn = t + dir * step;
            if (tn < -180 - 1e-9 || tn > 180 + 1e-9) break;
            double v = tn >= 0 ? eval_cg(l, LX_INTERP_BILINEAR, ca, tn) : eval_cg(l, LX_INTERP_BILINEAR, ca + 180, -tn);
            if (v < thr) {
                ends[side] = t + dir * step * (prev - thr) / (prev - v);
                break;
            }
            prev = v;
            t = tn;
        }
        if (isnan(ends[side])) return NAN;
    }
    return ends[1] - ends[0];
}

lx_status lx_luminaire_summary(lx_ctx *ctx, const lx_luminaire *l, lx_lum_summary *out)
{
    LX__NEED_CTX(ctx);
    if (!l || !out || !l->full_cd) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_luminaire_summary: NULL argument");
    lx_lum_summary s;
    memset(&s, 0, sizeof s); /* reserved included (ABI policy) */
    double tf = lx_luminaire_tilt_factor(l, 0), down = NAN;
    s.lumens = tf * integrate(l, -1e9, 1e9);
    if (l->photometric_type == 1) down = tf * integrate(l, -1e9, 90);
    double peak = 0;
    for (size_t k = 0; k < l->n_c * l->n_g; k++) peak = fmax(peak, fabs(l->full_cd[k]));
    if (!isfinite(s.lumens) && isfinite(peak)) {
        /* candela near the top of the double range: the cell sums again on the table scaled by
         * 2^-e (exact), then back, so a partial sum that overflowed does not make the flux overflow */
        int e = 0;
        frexp(peak, &e);
        lx_luminaire scaled = *l;
        double *cd = lx__alloc_n(l->n_c * l->n_g, sizeof *cd);
        if (!cd) return lx__error(ctx, LX_ENOMEM, l->file, 0, "out of memory");
        for (size_t k = 0; k < l->n_c * l->n_g; k++) cd[k] = ldexp(l->full_cd[k], -e);
        scaled.full_cd = cd;
        s.lumens = ldexp(tf * integrate(&scaled, -1e9, 1e9), e);
        if (l->photometric_type == 1) down = ldexp(tf * integrate(&scaled, -1e9, 90), e);
        lx__free(cd);
    }
    if (!isfinite(s.lumens)) {
        char mb[48];
        lx__fmt_magnitude(mb, sizeof mb, peak);
        return lx__error(ctx, LX_ERANGE, l->file, 0, "integral overflows: candela values up to %s give lumens beyond the double range",
                         mb);
    }
    s.downward_fraction = NAN;
    if (l->photometric_type == 1 && s.lumens > 0) s.downward_fraction = down / s.lumens;
    s.max_intensity_cd = 0;
    s.peak_c_deg = s.peak_gamma_deg = 0;
    for (size_t i = 0; i < l->n_c; i++)
        for (size_t j = 0; j < l->n_g; j++)
            if (l->full_cd[i * l->n_g + j] > s.max_intensity_cd) {
                s.max_intensity_cd = l->full_cd[i * l->n_g + j];
                s.peak_c_deg = l->c_deg[i];
                s.peak_gamma_deg = l->g_deg[j];
            }
    s.max_intensity_cd *= tf;
    s.beam_angle_deg = s.field_angle_deg = s.beam_angle_c90_deg = s.field_angle_c90_deg = NAN;
    if (l->photometric_type == 1) {
        s.beam_angle_deg = spread_angle(l, 0, 0.5, NULL);
        s.field_angle_deg = spread_angle(l, 0, 0.1, NULL);
        s.beam_angle_c90_deg = spread_angle(l, 90, 0.5, NULL);
        s.field_angle_c90_deg = spread_angle(l, 90, 0.1, NULL);
    }
    *out = s;
    return LX_OK;
}

/* ---- analytic models ---- */

lx_status lx_luminaire_from_model(lx_ctx *ctx, const lx_lum_model *m, lx_luminaire **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!m || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_luminaire_from_model: NULL argument");
    lx_status st0 = lx__check_reserved(ctx, "luminaire model", m->reserved, sizeof m->reserved);
    if (st0) return st0;
    if (m->kind != LX_LUM_MODEL_POINT && m->kind != LX_LUM_MODEL_WARN && m->kind != LX_LUM_MODEL_LAMBERT)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown luminaire model %d", (int)m->kind);
    if (!(m->flux_lm > 0) || !isfinite(m->flux_lm))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the model's flux must be positive and finite (got %g lm)", m->flux_lm);
    if (m->kind == LX_LUM_MODEL_WARN && (!(m->exponent >= 0) || !isfinite(m->exponent) || m->exponent > 1e6))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the Warn exponent must be from 0 to 1e6 (got %g)", m->exponent);
    if (!(m->width_m >= 0) || !(m->length_m >= 0) || !isfinite(m->width_m) || !isfinite(m->length_m))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the luminous opening must be non-negative and finite");
    double step = m->step_deg;
    if (step == 0) {
        step = 1;
        if (m->kind == LX_LUM_MODEL_WARN) {
            double beam = NAN;
            if (m->exponent > 0 && lx_warn_beam_from_exponent(ctx, m->exponent, &beam) == LX_OK) {
                double b = beam / LX__DEG / 40; /* about 20 steps across the half beam */
                if (b < step) step = b < 0.05 ? 0.05 : b;
            }
        }
    }
    if (!(step >= 0.01) || step > 45)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the angle step must be from 0.01 to 45 deg (got %g)", step);
    double last = m->kind == LX_LUM_MODEL_POINT ? 180 : 90;
    size_t n = (size_t)ceil(last / step - 1e-9) + 1;
    lx_luminaire *l = lx__lum_new("(model)");
    if (!l) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    l->format = LX_LUM_LM63_2002;
    l->n_h = 1;
    l->n_v = n;
    l->h_deg = lx__calloc(1, sizeof(double));
    l->v_deg = lx__alloc_n(n, sizeof(double));
    l->cd = lx__alloc_n(n, sizeof(double));
    const char *what = m->kind == LX_LUM_MODEL_POINT ? "isotropic point source" : m->kind == LX_LUM_MODEL_WARN ? "Warn spotlight" : "Lambertian panel";
    char desc[160];
    if (m->kind == LX_LUM_MODEL_WARN)
        snprintf(desc, sizeof desc, "%s, exponent %.17g, %.17g lm (analytic model sampled by luxcalc)", what, m->exponent, m->flux_lm);
    else
        snprintf(desc, sizeof desc, "%s, %.17g lm (analytic model sampled by luxcalc)", what, m->flux_lm);
    l->description = lx__strdup(desc);
    l->catalog = lx__strdup(m->catalog ? m->catalog : what);
    l->manufacturer = lx__strdup("luxcalc (an analytic model, no manufacturer)");
    l->test = lx__strdup("computed by luxcalc " LX_VERSION_STRING " from an analytic model (not a measurement)");
    l->testlab = lx__strdup("none: an analytic model, not a measurement");
    l->lamp = lx__strdup(what);
    l->issuedate = lx__date_today();
    if (!l->h_deg || !l->v_deg || !l->cd || !l->description || !l->catalog || !l->manufacturer || !l->test ||
        !l->testlab || !l->lamp || !l->issuedate) {
        lx_luminaire_free(l);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    for (size_t j = 0; j < n; j++) {
        double g = j + 1 == n ? last : j * step;
        l->v_deg[j] = g;
        double I;
        if (m->kind == LX_LUM_MODEL_POINT) I = m->flux_lm / (4 * LX__PI);
        else if (m->kind == LX_LUM_MODEL_LAMBERT) I = g >= 90 ? 0 : m->flux_lm / LX__PI * cos(g * LX__DEG);
        else I = g >= 90 ? 0 : (m->exponent + 1) / (2 * LX__PI) * m->flux_lm * lx_warn_lobe(m->exponent, g * LX__DEG);
        l->cd[j] = I;
    }
    l->absolute = 1;
    l->n_lamps = 1;
    l->stated_lumens = m->flux_lm;
    l->width_m = m->width_m;
    l->length_m = m->length_m;
    lx_status st = lx__lum_finish(ctx, l, 0, 0, 0);
    if (st) {
        lx_luminaire_free(l);
        return st;
    }
    *out = l;
    return LX_OK;
}
