/* contour.c - contour lines of a value grid by marching squares: each cell's crossings of the
 * level on its edges (linear interpolation), joined into one or two segments (a saddle is split
 * by the mean of the cell's four corners). */
#include "plot/plot_private.h"

#include <math.h>

size_t lx__contour(const double *v, int vw, int vh, double level,
                   void (*fn)(void *arg, double x0, double y0, double x1, double y1), void *arg)
{
    size_t count = 0;
    for (int j = 0; j + 1 < vh; j++)
        for (int i = 0; i + 1 < vw; i++) {
            /* corners counter-clockwise on the screen: a (i, j), b (i+1, j), c (i+1, j+1), d (i, j+1) */
            double a = v[(size_t)j * vw + i], b = v[(size_t)j * vw + i + 1];
            double c = v[(size_t)(j + 1) * vw + i + 1], d = v[(size_t)(j + 1) * vw + i];
            if (!isfinite(a + b + c + d)) continue;
            int code = (a > level) | (b > level) << 1 | (c > level) << 2 | (d > level) << 3;
            if (code == 0 || code == 15) continue;
            /* crossing points on the edges ab (top), bc (right), cd (bottom), da (left) */
            double px[4], py[4];
            px[0] = i + (level - a) / (b - a), py[0] = j;
            px[1] = i + 1, py[1] = j + (level - b) / (c - b);
            px[2] = i + (level - d) / (c - d), py[2] = j + 1;
            px[3] = i, py[3] = j + (level - a) / (d - a);
            /* which edges each case joins (pairs of edge indices; -1 ends) */
            int e[4] = {-1, -1, -1, -1};
            switch (code) {
            case 1: case 14: e[0] = 3, e[1] = 0; break;
            case 2: case 13: e[0] = 0, e[1] = 1; break;
            case 3: case 12: e[0] = 3, e[1] = 1; break;
            case 4: case 11: e[0] = 1, e[1] = 2; break;
            case 6: case 9: e[0] = 0, e[1] = 2; break;
            case 7: case 8: e[0] = 3, e[1] = 2; break;
            case 5: case 10: {
                /* saddle: a and c on one side, b and d on the other; the centre decides which pair
                 * of opposite corners is joined through the middle */
                int centre_above = 0.25 * (a + b + c + d) > level;
                int a_above = a > level;
                if (centre_above == a_above) e[0] = 0, e[1] = 1, e[2] = 2, e[3] = 3; /* a, c joined: cut b and d off */
                else e[0] = 3, e[1] = 0, e[2] = 1, e[3] = 2;                          /* cut a and c off */
                break;
            }
            }
            for (int s = 0; s < 4 && e[s] >= 0; s += 2) {
                fn(arg, px[e[s]], py[e[s]], px[e[s + 1]], py[e[s + 1]]);
                count++;
            }
        }
    return count;
}
