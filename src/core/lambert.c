/* lambert.c - Lambert's formula for the projected solid angle of a polygon: the integral of
 * max(0, n . w) over the directions w of a polygon seen from the origin, after clipping it to the
 * half-space n . x >= 0 (shared by the area sources of the lighting layer and the cube-map texels
 * of the radiance layer). */
#include "core/core_private.h"

#include <math.h>

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double lx__lambert_edge(const double a[3], const double b[3], const double n[3])
{
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    double s = sqrt(dot3(c, c));
    if (!(s > 0)) return 0;
    return atan2(s, dot3(a, b)) * dot3(n, c) / s;
}

double lx__polygon_projected(const double (*v)[3], int nv, const double n[3])
{
    if (nv < 3 || nv > LX__POLY_MAX) return 0;
    /* Sutherland-Hodgman against the one plane n . x = 0 through the origin (the receiver); the
     * clipped edge lies in that plane, so its term is the angle it subtends */
    double out[LX__POLY_MAX + 1][3], d[LX__POLY_MAX];
    for (int k = 0; k < nv; k++) d[k] = dot3(n, v[k]);
    int no = 0;
    for (int k = 0; k < nv; k++) {
        int k1 = k + 1 < nv ? k + 1 : 0;
        if (d[k] >= 0) {
            for (int i = 0; i < 3; i++) out[no][i] = v[k][i];
            no++;
        }
        if ((d[k] > 0 && d[k1] < 0) || (d[k] < 0 && d[k1] > 0)) {
            double t = d[k] / (d[k] - d[k1]);
            for (int i = 0; i < 3; i++) out[no][i] = v[k][i] + t * (v[k1][i] - v[k][i]);
            no++;
        }
    }
    if (no < 3) return 0;
    double sum = 0;
    for (int k = 0; k < no; k++) sum += lx__lambert_edge(out[k], out[k + 1 < no ? k + 1 : 0], n);
    return 0.5 * fabs(sum);
}
