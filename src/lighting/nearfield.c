/* nearfield.c - when a luminaire-receiver pair may be computed as a point source: the point model's
 * error estimated from probes of the luminous opening (two fourth-order area rules against the
 * centre value), and the per-point choice of which pairs take the point path within a budget. */
#include "lighting/lighting_private.h"

#include <math.h>

int lx__nf_faces(const double pos[3], const double ex[3], const double ey[3], int circular, double w, double l,
                 const double q[3], const double n[3])
{
    /* n . (s - q) is affine in the point s of the opening: it is <= 0 over the whole opening
     * exactly when it is <= 0 at the corners of the bounding rectangle (a circle's square) */
    double hx = 0.5 * w, hy = 0.5 * (circular ? w : l);
    for (int i = -1; i <= 1; i += 2)
        for (int j = -1; j <= 1; j += 2) {
            double t = 0;
            for (int k = 0; k < 3; k++) t += n[k] * (pos[k] + i * hx * ex[k] + j * hy * ey[k] - q[k]);
            if (t > 0) return 1;
        }
    return 0;
}

/* The probe rules. Rectangle w x l, offsets in units of the half sides (A, B):
 *   S: the 3 x 3 Simpson product rule, weights (1 4 1)/6 per axis (exact for bicubics);
 *   G: the 2 x 2 Gauss-Legendre product rule at +-1/sqrt(3) (exact for bicubics).
 * Disk of radius R (mean of a^2 over the disk: R^2 / 4):
 *   S: the centre (1/2) and the four rim points on the axes (1/8 each);
 *   G: four points at radius R / sqrt(2) on the diagonals (1/4 each);
 * both exact for quadratics. For a smooth integrand both rules differ from the area mean by
 * terms of fourth order in size / distance, so max(|S - P|, |G - P|) estimates the point model's
 * error |P - mean|; where the integrand has a kink inside the opening (an interpolated intensity
 * table) the two rules see it differently and the larger difference still bounds the error of a
 * piecewise-linear integrand (a kink at the centre: the error is k A / 2, S - P = k A / 3,
 * G - P = k A / sqrt 3). */
void lx__nf_probe_pair(lx__nf_fn g, void *arg, int circular, double w, double l, double dist, int faces,
                       lx__nf_probe *out)
{
    lx__nf_probe r = {0, 0, 0, 0, 0};
    double P = g(arg, 0, 0), S, G;
    int nonzero = P != 0, zeros = P == 0, negative = P < 0;
    if (circular) {
        double R = 0.5 * w, rd = 0.5 * R; /* R / sqrt 2 on a diagonal: (R / 2, R / 2) */
        double rim[4] = {g(arg, R, 0), g(arg, 0, R), g(arg, -R, 0), g(arg, 0, -R)};
        double dia[4] = {g(arg, rd, rd), g(arg, -rd, rd), g(arg, -rd, -rd), g(arg, rd, -rd)};
        S = 0.5 * P + 0.125 * (rim[0] + rim[1] + rim[2] + rim[3]);
        G = 0.25 * (dia[0] + dia[1] + dia[2] + dia[3]);
        for (int k = 0; k < 4; k++) {
            nonzero += (rim[k] != 0) + (dia[k] != 0);
            zeros += (rim[k] == 0) + (dia[k] == 0);
            negative |= rim[k] < 0 || dia[k] < 0;
        }
    } else {
        static const double ws[3] = {1.0 / 6, 4.0 / 6, 1.0 / 6};
        double A = 0.5 * w, B = 0.5 * l, ga = A / sqrt(3.0), gb = B / sqrt(3.0);
        S = 0;
        for (int i = -1; i <= 1; i++)
            for (int j = -1; j <= 1; j++) {
                double v = i == 0 && j == 0 ? P : g(arg, i * A, j * B);
                S += ws[i + 1] * ws[j + 1] * v;
                if (i || j) {
                    nonzero += v != 0;
                    zeros += v == 0;
                    negative |= v < 0;
                }
            }
        double q[4] = {g(arg, ga, gb), g(arg, -ga, gb), g(arg, -ga, -gb), g(arg, ga, -gb)};
        G = 0.25 * (q[0] + q[1] + q[2] + q[3]);
        for (int k = 0; k < 4; k++) {
            nonzero += q[k] != 0;
            zeros += q[k] == 0;
            negative |= q[k] < 0;
        }
    }
    r.point = P;
    r.best = S;
    r.err = fmax(fabs(S - P), fabs(G - P));
    double size = circular ? w : sqrt(w * w + l * l);
    if (!nonzero) {
        /* zero at every probe: exact when the receiver faces away from the whole opening; else
         * an intensity table could be non-zero between the probes */
        r.zero = !faces;
        r.unsure = faces;
    } else if (zeros || negative) {
        r.unsure = 1; /* the opening straddles a zero: a beam's cut-off, the receiver's horizon */
    } else if (!(dist > size)) {
        r.unsure = 1; /* closer than the opening's size: the expansion in offset / distance fails */
    }
    *out = r;
}

size_t lx__nf_decide(size_t k, const lx__nf_probe *pr, double E_point, double tol, unsigned char *near, size_t *order)
{
    /* the pairs the probes can vouch for, smallest estimated error first (insertion sort: k is
     * the number of luminaires with an opening, small) */
    size_t m = 0;
    for (size_t i = 0; i < k; i++) {
        near[i] = 1;
        if (pr[i].zero) near[i] = 0;
        else if (!pr[i].unsure) {
            size_t j = m++;
            while (j > 0 && pr[order[j - 1]].err > pr[i].err) {
                order[j] = order[j - 1];
                j--;
            }
            order[j] = i;
        }
    }
    double budget = 0.5 * tol * fabs(E_point), used = 0;
    size_t far = 0;
    for (size_t j = 0; j < m; j++) {
        const lx__nf_probe *p = &pr[order[j]];
        if (used + p->err > budget) break;
        used += p->err;
        near[order[j]] = 0;
        far++;
    }
    for (size_t i = 0; i < k; i++) far += pr[i].zero;
    return far;
}
