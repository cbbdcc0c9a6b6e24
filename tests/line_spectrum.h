/* line_spectrum.h - the Hg-line test spectrum of tests/reference/cri_fine_grid.py and
 * tm30_fine_grid.py (shared by test_cri.c, test_tm30.c, test_alphaopic.c): mercury lines at 404.66,
 * 435.83, 546.07, 576.96 and 579.07 nm (powers 0.25, 0.55, 0.60, 0.08, 0.09 W), each a triangle of
 * 0.2 nm base, on a flat 5e-3 W/nm continuum from 380 to 780 nm that steps within 0.01 nm; every
 * line moved by shift nm (a multiple of 0.01 keeps the vertices on the references' 0.01 nm grid). */
#ifndef LX_LINE_SPECTRUM_H
#define LX_LINE_SPECTRUM_H

#include "luxcalc.h"

#define LINE_N 5
#define LINE_MAX_SAMPLES (4 + 3 * LINE_N)

/* Fills lam/val (LINE_MAX_SAMPLES each) and s with the spectrum; returns the sample count. */
static inline size_t line_spectrum(double shift, double *lam, double *val, lx_spd *s)
{
    static const double c[LINE_N] = {404.66, 435.83, 546.07, 576.96, 579.07}, p[LINE_N] = {0.25, 0.55, 0.60, 0.08, 0.09};
    const double half = 0.1, cont = 5e-3;
    size_t n = 0;
    lam[n] = 379.99, val[n++] = 0;
    lam[n] = 380, val[n++] = cont;
    for (int k = 0; k < LINE_N; k++) {
        lam[n] = c[k] + shift - half, val[n++] = cont;
        lam[n] = c[k] + shift, val[n++] = cont + p[k] / half;
        lam[n] = c[k] + shift + half, val[n++] = cont;
    }
    lam[n] = 780, val[n++] = cont;
    lam[n] = 780.01, val[n++] = 0;
    s->n = n;
    s->lambda_nm = lam;
    s->value = val;
    s->name = "Hg lines";
    return n;
}

/* The same function sampled at 1 nm from 360 to 830 nm (what resampling to 1 nm makes of it). */
static inline void line_spectrum_1nm(const lx_spd *line, double *lam, double *val, lx_spd *s)
{
    size_t j = 0;
    for (int i = 0; i <= 470; i++) {
        double l = 360 + i, v = 0;
        while (j + 2 < line->n && line->lambda_nm[j + 1] <= l) j++;
        if (l >= line->lambda_nm[0] && l <= line->lambda_nm[line->n - 1])
            v = line->value[j] + (l - line->lambda_nm[j]) / (line->lambda_nm[j + 1] - line->lambda_nm[j]) *
                                     (line->value[j + 1] - line->value[j]);
        lam[i] = l, val[i] = v;
    }
    s->n = 471;
    s->lambda_nm = lam;
    s->value = val;
    s->name = "Hg lines at 1 nm";
}

#endif
