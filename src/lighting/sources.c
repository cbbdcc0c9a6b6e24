/* sources.c - light sources for the lighting calculator: isotropic point, Warn spotlight (and the
 * flux in a cone), Lambertian disk and rectangle (exact configuration factors by default, the
 * point model beside them with its error, the coplanar limit), and the Lambertian reflector. */
#include "lighting/lighting_private.h"

#include <float.h>
#include <math.h>


static lx_status check_distance(lx_ctx *ctx, const char *what, double d)
{
    if (!(d > 0) || !isfinite(d))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "%s must be positive and finite (got %g m)", what, d);
    return LX_OK;
}

static lx_status check_finite(lx_ctx *ctx, const char *what, double v, int nonneg)
{
    if (!isfinite(v) || (nonneg && v < 0))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "%s must be %sfinite (got %g)", what, nonneg ? "non-negative and " : "", v);
    return LX_OK;
}

lx_status lx_point_illuminance(lx_ctx *ctx, double intensity_cd, double distance_m, double incidence_rad,
                               double *illuminance_lx)
{
    LX__NEED_CTX(ctx);
    lx_status st;
    if (!illuminance_lx) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_point_illuminance: NULL output");
    if ((st = check_finite(ctx, "intensity", intensity_cd, 1)) != LX_OK) return st;
    if ((st = check_distance(ctx, "distance", distance_m)) != LX_OK) return st;
    if ((st = check_finite(ctx, "incidence angle", incidence_rad, 0)) != LX_OK) return st;
    double c = cos(incidence_rad);
    /* grazing or back-facing: no light on the front face (never negative) */
    double e = c > 0 ? intensity_cd * c / distance_m / distance_m : 0.0;
    if (!isfinite(e))
        return lx__error(ctx, LX_ERANGE, NULL, 0, "illuminance overflows (I %g cd at %g m)", intensity_cd, distance_m);
    *illuminance_lx = e;
    return LX_OK;
}

lx_status lx_point_intensity(lx_ctx *ctx, double flux_lm, double *intensity_cd)
{
    LX__NEED_CTX(ctx);
    lx_status st;
    if (!intensity_cd) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_point_intensity: NULL output");
    if ((st = check_finite(ctx, "flux", flux_lm, 1)) != LX_OK) return st;
    *intensity_cd = flux_lm / (4 * LX__PI);
    return LX_OK;
}

double lx_warn_lobe(double exponent, double angle_rad)
{
    if (isnan(exponent) || isnan(angle_rad) || exponent < 0) return NAN;
    double a = fabs(angle_rad);
    if (a > LX__PI / 2) return 0.0;
    if (exponent == 0) return 1.0;
    double lc; /* log(cos a), accurate near a = 0 where cos a rounds to 1 */
    if (a < LX__PI / 3) {
        double s = sin(0.5 * a);
        lc = log1p(-2 * s * s);
    } else {
        double c = cos(a);
        if (!(c > 0)) return 0.0;
        lc = log(c);
    }
    return exp(exponent * lc); /* underflows to 0 for large S: correct, never NaN */
}

lx_status lx_warn_intensity(lx_ctx *ctx, double flux_lm, double exponent, double angle_rad, double *peak_cd,
                            double *intensity_cd)
{
    LX__NEED_CTX(ctx);
    lx_status st;
    if (!intensity_cd) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_warn_intensity: NULL output");
    if ((st = check_finite(ctx, "flux", flux_lm, 1)) != LX_OK) return st;
    if ((st = check_finite(ctx, "Warn exponent", exponent, 1)) != LX_OK) return st;
    if ((st = check_finite(ctx, "angle", angle_rad, 0)) != LX_OK) return st;
    double c = (exponent + 1) / (2 * LX__PI) * flux_lm;
    if (!isfinite(c))
        return lx__error(ctx, LX_ERANGE, NULL, 0, "peak intensity overflows (S %g, flux %g lm)", exponent, flux_lm);
    double lobe = lx_warn_lobe(exponent, angle_rad);
    if (peak_cd) *peak_cd = c;
    *intensity_cd = c * lobe;
    return LX_OK;
}

lx_status lx_warn_cone_flux(lx_ctx *ctx, double flux_lm, double exponent, double half_angle_rad, double *cone_flux_lm,
                            double *fraction)
{
    LX__NEED_CTX(ctx);
    lx_status st;
    if (!cone_flux_lm && !fraction) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_warn_cone_flux: NULL output");
    if ((st = check_finite(ctx, "flux", flux_lm, 1)) != LX_OK) return st;
    if ((st = check_finite(ctx, "Warn exponent", exponent, 1)) != LX_OK) return st;
    if (!(half_angle_rad >= 0 && half_angle_rad <= LX__PI))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the cone's half-angle must be from 0 to 180 deg (got %g deg)",
                         half_angle_rad / LX__DEG);
    /* flux within a: 2 pi c int_0^a cos^S t sin t dt = F (1 - cos^(S+1) a), F = 2 pi c / (S + 1);
     * 1 - cos^(S+1) a = -expm1((S + 1) ln cos a), ln cos a = log1p(-2 sin^2(a/2)) (no cancellation
     * for small a or large S) */
    double f = 1.0;
    if (half_angle_rad < LX__PI / 2) {
        double s = sin(0.5 * half_angle_rad);
        f = -expm1((exponent + 1) * log1p(-2 * s * s));
    }
    if (cone_flux_lm) *cone_flux_lm = flux_lm * f;
    if (fraction) *fraction = f;
    return LX_OK;
}

lx_status lx_warn_exponent_from_beam(lx_ctx *ctx, double beam_rad, double *exponent)
{
    LX__NEED_CTX(ctx);
    if (!exponent) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_warn_exponent_from_beam: NULL output");
    if (!(beam_rad > 0 && beam_rad < LX__PI))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "beam angle must be between 0 and 180 deg (got %g deg)",
                         beam_rad * 180 / LX__PI);
    double s = sin(0.25 * beam_rad); /* half the beam is the half-peak angle a: cos^S a = 1/2 */
    *exponent = -log(2.0) / log1p(-2 * s * s);
    return LX_OK;
}

lx_status lx_warn_beam_from_exponent(lx_ctx *ctx, double exponent, double *beam_rad)
{
    LX__NEED_CTX(ctx);
    if (!beam_rad) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_warn_beam_from_exponent: NULL output");
    if (!(exponent > 0) || !isfinite(exponent))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "Warn exponent must be positive for a beam angle (got %g)", exponent);
    /* cos a = 2^(-1/S); a = 2 asin(sqrt((1 - cos a) / 2)), 1 - cos a = -expm1(-ln2 / S) */
    double one_minus_cos = -expm1(-log(2.0) / exponent);
    *beam_rad = 2 * (2 * asin(sqrt(0.5 * one_minus_cos)));
    return LX_OK;
}

/* ---- extended sources ---- */

/* AUTO is the closed form: it costs what the point model costs. near_field says whether the
 * point model would miss the grids' default tolerance (1e-4 relative). */
static void finish(lx_source_result *r, lx_model model)
{
    r->point_error = r->exact_lx > 0 ? r->point_lx / r->exact_lx - 1 : NAN;
    r->near_field = !(fabs(r->point_error) <= LX__NEARFIELD_TOL);
    r->model = model == LX_MODEL_POINT ? LX_MODEL_POINT : LX_MODEL_EXACT;
    r->illuminance_lx = r->model == LX_MODEL_EXACT ? r->exact_lx : r->point_lx;
}

/* An exact or point illuminance beyond the double range is an error naming it, never an
 * infinity (or the NaN of its error ratio) handed on. */
static lx_status check_result(lx_ctx *ctx, const lx_source_result *r, double luminance)
{
    const char *what = !isfinite(r->exact_lx) ? "the exact illuminance" : !isfinite(r->point_lx) ? "the point-model illuminance" : NULL;
    if (!what) return LX_OK;
    char mb[48];
    lx__fmt_magnitude(mb, sizeof mb, luminance);
    return lx__error(ctx, LX_ERANGE, NULL, 0, "%s overflows (luminance %s cd/m2)", what, mb);
}

static lx_status check_model(lx_ctx *ctx, lx_model model)
{
    if (model != LX_MODEL_AUTO && model != LX_MODEL_POINT && model != LX_MODEL_EXACT && model != LX_MODEL_AREA)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown model %d", (int)model);
    return LX_OK;
}

/* The distance of a receiver from the source's plane: >= 0 and finite (0: the coplanar limit). */
static lx_status check_height(lx_ctx *ctx, double h)
{
    if (!(h >= 0) || !isfinite(h))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "distance must be zero or positive and finite (got %g m)", h);
    return LX_OK;
}

/* Configuration factor from a differential element to a coaxial-parallel disk, in lengths
 * scaled so the largest is 1. With A = h2 + r2 + R2 and D = sqrt(A^2 - 4 r2 R2), the textbook
 * F = (1/2)(1 - (A - 2 R2)/D) is rewritten without cancelling subtractions:
 *   D^2 = (h2 + (r-R)^2)(h2 + (r+R)^2)                      (a product of sums)
 *   1 - (A - 2R2)/D = (D - A + 2R2)/D,  D - A = -4 r2 R2/(D + A)
 *   => F = R2 N / (D (D + A)),  N = D + m,  m = h2 + R2 - r2,
 *   and when m < 0: N = (D^2 - m^2)/(D - m) = 4 r2 h2 / (D - m)   (D^2 - m^2 = 4 r2 h2). */
static double disk_factor(double R, double h, double r)
{
    double h2 = h * h, R2 = R * R, r2 = r * r;
    double dm = r - R, dp = r + R;
    double D = sqrt(h2 + dm * dm) * sqrt(h2 + dp * dp);
    double A = h2 + r2 + R2;
    double m = h2 + (R - r) * (R + r); /* exact difference of squares near the rim */
    double N = m >= 0 ? D + m : 4 * r2 * h2 / (D - m);
    return R2 * N / (D * (D + A));
}

lx_status lx_disk_illuminance(lx_ctx *ctx, double luminance_cd_m2, double radius_m, double height_m, double offset_m,
                              lx_model model, lx_source_result *out)
{
    LX__NEED_CTX(ctx);
    lx_status st;
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_disk_illuminance: NULL output");
    if ((st = check_finite(ctx, "luminance", luminance_cd_m2, 1)) != LX_OK) return st;
    if ((st = check_distance(ctx, "radius", radius_m)) != LX_OK) return st;
    if ((st = check_height(ctx, height_m)) != LX_OK) return st;
    if ((st = check_finite(ctx, "offset", offset_m, 0)) != LX_OK) return st;
    if ((st = check_model(ctx, model)) != LX_OK) return st;
    double r = fabs(offset_m);
    if (height_m == 0) {
        /* the coplanar limit h -> 0+: on the disk it fills the receiver's hemisphere (F = 1), on
         * the rim half of it, outside it is seen edge-on (F = 0); the point model is 0 there,
         * and undefined at the centre */
        lx_source_result res = {0};
        res.exact_lx = LX__PI * luminance_cd_m2 * (r < radius_m ? 1.0 : r == radius_m ? 0.5 : 0.0);
        res.exact_rel_error = 1e-16;
        res.point_lx = r > 0 ? 0.0 : NAN;
        res.distance_m = r;
        res.largest_dimension_m = 2 * radius_m;
        finish(&res, model);
        *out = res;
        return LX_OK;
    }
    double s = fmax(radius_m, fmax(height_m, r)); /* scale so no square over- or underflows */
    double R = radius_m / s, h = height_m / s, x = r / s;
    lx_source_result res = {0};
    res.exact_lx = LX__PI * luminance_cd_m2 * disk_factor(R, h, x);
    res.exact_rel_error = 1e-14;
    /* point: I(theta) = L pi R^2 cos theta at distance d, incidence theta: E = I cos theta / d^2 */
    double d2 = h * h + x * x;
    res.point_lx = luminance_cd_m2 * LX__PI * (R * R) * (h * h) / (d2 * d2);
    /* L near the top of the double range: pi L overflows where the result need not; the
     * luminance multiplies last then */
    if (!isfinite(res.exact_lx)) res.exact_lx = luminance_cd_m2 * (LX__PI * disk_factor(R, h, x));
    if (!isfinite(res.point_lx)) res.point_lx = luminance_cd_m2 * (LX__PI * (R * R) * (h * h) / (d2 * d2));
    res.distance_m = sqrt(d2) * s;
    res.largest_dimension_m = 2 * radius_m;
    finish(&res, model);
    if ((st = check_result(ctx, &res, luminance_cd_m2)) != LX_OK) return st;
    *out = res;
    return LX_OK;
}

/* Illuminance / L from the rectangle [0, X] x [0, Y] on a parallel receiver at height h below
 * the corner (X, Y >= 0): the configuration factor of Howell's catalogue case B-3 (plane element
 * to a parallel rectangle, normal through a corner), F = 1/(2 pi) [x/sqrt(1+x^2) atan(y/sqrt(1+x^2))
 * + y/sqrt(1+y^2) atan(x/sqrt(1+y^2))] with x = X/h, y = Y/h, times pi. Every term is >= 0. */
static double rect_corner(double X, double Y, double h)
{
    if (X <= 0 || Y <= 0) return 0.0;
    double px = hypot(X, h), py = hypot(Y, h);
    return 0.5 * (X / px * atan(Y / px) + Y / py * atan(X / py));
}

/* ---- adaptive Gauss-Kronrod (7-15) for the rectangle when the receiver's foot is outside it ---- */
static const double gk_x[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                               0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                               0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                               0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
static const double gk_wk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double gk_wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

typedef struct rect_q {
    double h, y0, y1, x;   /* inner: fixed x, integrate y over [y0, y1] */
    double tol;
    int depth_exceeded;
} rect_q;

typedef double (*fn1)(rect_q *q, double t);

static double gk15(fn1 f, rect_q *q, double a, double b, double *err)
{
    double c = 0.5 * (a + b), hw = 0.5 * (b - a);
    double fc = f(q, c);
    double k = fc * gk_wk[7], g = fc * gk_wg[3];
    for (int i = 0; i < 7; i++) {
        double f1 = f(q, c - hw * gk_x[i]), f2 = f(q, c + hw * gk_x[i]);
        k += gk_wk[i] * (f1 + f2);
        if (i & 1) g += gk_wg[i / 2] * (f1 + f2);
    }
    *err = fabs((k - g) * hw);
    return k * hw;
}

static double adapt(fn1 f, rect_q *q, double a, double b, double tol, int depth, double *errsum)
{
    double err, v = gk15(f, q, a, b, &err);
    if (err <= tol || depth >= 40) {
        if (err > tol) q->depth_exceeded = 1;
        *errsum += err;
        return v;
    }
    double m = 0.5 * (a + b);
    return adapt(f, q, a, m, 0.5 * tol, depth + 1, errsum) + adapt(f, q, m, b, 0.5 * tol, depth + 1, errsum);
}

/* integrand of E/L = h^2 / (h^2 + x^2 + y^2)^2 dx dy (a parallel Lambertian element) */
static double inner_f(rect_q *q, double y)
{
    double s = q->h * q->h + q->x * q->x + y * y;
    return q->h * q->h / (s * s);
}

static double inner_tol_scale(rect_q *q)
{
    /* the integrand's size on this row: bounds the absolute tolerance of the inner integral */
    double ymin = (q->y0 > 0) ? q->y0 : (q->y1 < 0 ? -q->y1 : 0);
    double s = q->h * q->h + q->x * q->x + ymin * ymin;
    return q->h * q->h / (s * s) * (q->y1 - q->y0);
}

static double outer_f(rect_q *q, double x)
{
    rect_q in = *q;
    in.x = x;
    double e = 0;
    double v = adapt(inner_f, &in, q->y0, q->y1, q->tol * inner_tol_scale(&in), 0, &e);
    if (in.depth_exceeded) q->depth_exceeded = 1;
    return v;
}

lx_status lx_rect_illuminance(lx_ctx *ctx, double luminance_cd_m2, double width_m, double length_m, double height_m,
                              double x_m, double y_m, lx_model model, lx_source_result *out)
{
    LX__NEED_CTX(ctx);
    lx_status st;
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_rect_illuminance: NULL output");
    if ((st = check_finite(ctx, "luminance", luminance_cd_m2, 1)) != LX_OK) return st;
    if ((st = check_distance(ctx, "width", width_m)) != LX_OK) return st;
    if ((st = check_distance(ctx, "length", length_m)) != LX_OK) return st;
    if ((st = check_height(ctx, height_m)) != LX_OK) return st;
    if ((st = check_finite(ctx, "offset x", x_m, 0)) != LX_OK) return st;
    if ((st = check_finite(ctx, "offset y", y_m, 0)) != LX_OK) return st;
    if ((st = check_model(ctx, model)) != LX_OK) return st;
    if (height_m == 0) {
        /* the coplanar limit: inside pi L, on an edge pi L / 2, at a corner pi L / 4, outside 0 */
        double fx = fabs(x_m) < 0.5 * width_m ? 1 : fabs(x_m) == 0.5 * width_m ? 0.5 : 0;
        double fy = fabs(y_m) < 0.5 * length_m ? 1 : fabs(y_m) == 0.5 * length_m ? 0.5 : 0;
        lx_source_result res = {0};
        res.exact_lx = LX__PI * luminance_cd_m2 * fx * fy;
        res.exact_rel_error = 1e-16;
        res.distance_m = hypot(x_m, y_m);
        res.point_lx = res.distance_m > 0 ? 0.0 : NAN;
        res.largest_dimension_m = hypot(width_m, length_m);
        finish(&res, model);
        *out = res;
        return LX_OK;
    }
    double s = fmax(fmax(width_m, length_m), fmax(height_m, fmax(fabs(x_m), fabs(y_m))));
    double a = width_m / s, b = length_m / s, h = height_m / s, x = x_m / s, y = y_m / s;
    /* the rectangle in coordinates centred on the receiver's foot */
    double x0 = -0.5 * a - x, x1 = 0.5 * a - x, y0 = -0.5 * b - y, y1 = 0.5 * b - y;
    lx_source_result res = {0};
    if (x0 <= 0 && x1 >= 0 && y0 <= 0 && y1 >= 0) {
        /* foot inside: four corner rectangles, all added (no cancellation) */
        res.exact_lx = luminance_cd_m2 * (rect_corner(x1, y1, h) + rect_corner(-x0, y1, h) +
                                          rect_corner(x1, -y0, h) + rect_corner(-x0, -y0, h));
        res.exact_rel_error = 1e-14;
    } else {
        /* foot outside: the signed superposition would cancel; integrate E = L h^2 / rho^4 over the
         * rectangle by nested adaptive Gauss-Kronrod to a relative tolerance of 1e-13 */
        rect_q q = {h, y0, y1, 0, 1e-13, 0};
        double xm = x0 > 0 ? x0 : (x1 < 0 ? -x1 : 0);
        double ym = y0 > 0 ? y0 : (y1 < 0 ? -y1 : 0);
        double smin = h * h + xm * xm + ym * ym;
        double scale = h * h / (smin * smin) * (x1 - x0) * (y1 - y0); /* upper bound of the integral */
        double e = 0;
        double v = adapt(outer_f, &q, x0, x1, 1e-7 * scale, 0, &e); /* a first estimate, then */
        if (v > 0 && v < scale) {                                   /* tolerance relative to it */
            q.tol = 1e-13 * v / scale;
            q.depth_exceeded = 0;
            scale = v;
            e = 0;
            v = adapt(outer_f, &q, x0, x1, 1e-13 * scale, 0, &e);
        }
        res.exact_lx = luminance_cd_m2 * v;
        res.exact_rel_error = v > 0 ? fmax((e + 1e-13 * scale) / v, 1e-14) : 1.0;
        if (q.depth_exceeded) lx__log(ctx, LX_LOG_WARN, "rectangle quadrature did not reach its tolerance");
    }
    res.exact_rel_error = fmin(res.exact_rel_error, 1.0);
    double d2 = h * h + x * x + y * y;
    res.point_lx = luminance_cd_m2 * a * b * (h * h) / (d2 * d2);
    if (!isfinite(res.point_lx)) res.point_lx = luminance_cd_m2 * (a * b * (h * h) / (d2 * d2));
    res.distance_m = sqrt(d2) * s;
    res.largest_dimension_m = hypot(width_m, length_m);
    finish(&res, model);
    if ((st = check_result(ctx, &res, luminance_cd_m2)) != LX_OK) return st;
    *out = res;
    return LX_OK;
}

lx_status lx_lambertian_luminance(lx_ctx *ctx, double reflectance, double illuminance_lx, double *luminance_cd_m2)
{
    LX__NEED_CTX(ctx);
    lx_status st;
    if (!luminance_cd_m2) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_lambertian_luminance: NULL output");
    if (!(reflectance >= 0 && reflectance <= 1))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "reflectance must be between 0 and 1 (got %g)", reflectance);
    if ((st = check_finite(ctx, "illuminance", illuminance_lx, 1)) != LX_OK) return st;
    *luminance_cd_m2 = reflectance * illuminance_lx / LX__PI;
    return LX_OK;
}
