/* scale.c - round numbers for plots: 1-2-5 steps and ticks, decade ticks, contour levels from a
 * 1-2-5 series, and the text of tick values, powers of ten and rounded quantities. */
#include "plot/plot_private.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

double lx__nice_step(double span, int n)
{
    if (!(span > 0) || !isfinite(span) || n < 1) return 1;
    double raw = span / n, p = pow(10, floor(log10(raw))), f = raw / p;
    return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

int lx__ticks_linear(double lo, double hi, int n, double *out, int max, double *step)
{
    double s = lx__nice_step(hi - lo, n);
    if (step) *step = s;
    int k = 0;
    if (!(hi > lo)) return 0;
    for (double i = ceil(lo / s - 1e-9); k < max; i++) {
        double v = i * s;
        if (v > hi + 1e-9 * s) break;
        out[k++] = fabs(v) < 1e-12 * s ? 0.0 : v;
    }
    return k;
}

int lx__ticks_log(double lo, double hi, double *out, int max)
{
    if (!(lo > 0) || !(hi > lo) || max < 1) return 0;
    int e0 = (int)ceil(log10(lo) - 1e-9), e1 = (int)floor(log10(hi) + 1e-9);
    int every = 1;
    while ((e1 - e0) / every + 1 > max) every++;
    int k = 0;
    for (int e = e0; e <= e1 && k < max; e += every) out[k++] = pow(10, e);
    return k;
}

int lx__levels_125(double lo, double hi, double *out, int max, int *geometric)
{
    *geometric = 0;
    if (!(hi > lo) || !isfinite(lo) || !isfinite(hi) || max < 1) return 0;
    double floor_lo = lo > hi * 1e-3 ? lo : hi * 1e-3; /* levels span at most three decades */
    int k = 0;
    if (hi > 0 && (lo <= 0 || hi / lo > 20)) {
        /* 1, 2, 5, 10, 20, 50 ...; where that gives more than 10 levels, decades (1, 10, 100 ...),
         * and every other decade where those are still too many */
        *geometric = 1;
        static const double m[3] = {1, 2, 5};
        int e0 = (int)floor(log10(floor_lo)) - 1, e1 = (int)ceil(log10(hi));
        for (int pass = 0; pass < 8; pass++) { /* pass 0: 1-2-5; pass p: every p-th decade */
            int per = pass == 0 ? 3 : 1, every = pass == 0 ? 1 : pass;
            k = 0;
            for (int e = e0; e <= e1; e++) {
                if (((e % every) + every) % every) continue;
                for (int j = 0; j < per; j++) {
                    double v = m[j] * pow(10, e);
                    if (v > lo && v < hi && v >= floor_lo && k < max) out[k++] = v;
                }
            }
            if (k <= 10) break;
        }
        return k;
    }
    /* a 1-2-5 step giving 4 to 9 levels inside (lo, hi) */
    for (int target = 6; target <= 12; target++) {
        double s = lx__nice_step(hi - lo, target);
        k = 0;
        for (double i = floor(lo / s) + 1; k < max; i++) {
            double v = i * s;
            if (!(v < hi - 1e-9 * s)) break;
            if (v > lo + 1e-9 * s) out[k++] = fabs(v) < 1e-12 * s ? 0 : v;
        }
        if (k >= 4) break;
    }
    return k;
}

void lx__fmt_tick(char *buf, size_t cap, double v, double step)
{
    int dec = 0;
    if (step > 0 && step < 1) dec = (int)ceil(-log10(step) - 1e-9);
    double r = pow(10, -dec) * 1e-6;
    if (fabs(v) < r) v = 0;
    /* a step of 2.5 or 0.25 needs one more decimal than its power of ten */
    if (step > 0 && fabs(step * pow(10, dec) - round(step * pow(10, dec))) > 1e-6) dec++;
    snprintf(buf, cap, "%.*f", dec, v);
}

void lx__fmt_decade(char *buf, size_t cap, double v)
{
    int e = (int)lround(log10(v));
    if (e >= -2 && e <= 3) {
        lx__fmt_tick(buf, cap, pow(10, e), pow(10, e));
        return;
    }
    static const char *const sup[10] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                        "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
    char digits[16];
    snprintf(digits, sizeof digits, "%d", e < 0 ? -e : e);
    size_t n = (size_t)snprintf(buf, cap, "10%s", e < 0 ? "\u207b" : "");
    for (const char *d = digits; *d && n + 4 < cap; d++) n += (size_t)snprintf(buf + n, cap - n, "%s", sup[*d - '0']);
}

void lx__fmt_sig(char *buf, size_t cap, double v, int sig)
{
    if (!isfinite(v)) {
        snprintf(buf, cap, "-");
        return;
    }
    if (sig < 1) sig = 1;
    if (v == 0) {
        snprintf(buf, cap, "0");
        return;
    }
    int mag = (int)floor(log10(fabs(v)));
    double q = pow(10, mag - sig + 1), r = round(v / q) * q; /* rounded to sig digits */
    if (r != 0) mag = (int)floor(log10(fabs(r)));
    if (mag >= 7 || mag < -7) {
        snprintf(buf, cap, "%.*e", sig - 1, r);
        return;
    }
    int dec = sig - 1 - mag;
    if (dec < 0) dec = 0;
    snprintf(buf, cap, "%.*f", dec, r);
}
