/* plane_cells.c - calculation grids with points at cell centres, as EN 12464-1 and DIALux place
 * them: the area cut into cells no larger than the spacing, one point in the middle of each. */
#include "lighting/lighting_private.h"

#include <math.h>

/* cells along one side of length w for spacing s (at least one; the cell is w / n <= s) */
static double cells(double w, double s) { return w > 0 ? fmax(1, ceil(w / s - 1e-9)) : 1; }

lx_status lx_plane_cells(lx_ctx *ctx, char axis, double level_m, double a0, double a1, double b0, double b1,
                         double spacing_m, size_t na, size_t nb, lx_plane *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_plane_cells: NULL argument");
    if (!isfinite(a0) || !isfinite(a1) || !isfinite(b0) || !isfinite(b1) || a1 < a0 || b1 < b0)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "the area must be finite with A0 <= A1 and B0 <= B1");
    if (spacing_m > 0) {
        double fa = cells(a1 - a0, spacing_m), fb = cells(b1 - b0, spacing_m);
        if (fa * fb > 1e9) return lx__error(ctx, LX_EINVAL, NULL, 0, "the spacing gives more than 1e9 points");
        na = (size_t)fa, nb = (size_t)fb;
    } else if (na < 1 || nb < 1 || (double)na * (double)nb > 1e9) {
        return lx__error(ctx, LX_EINVAL, NULL, 0, "give a positive spacing or 1 to 1e9 points");
    }
    double da = (a1 - a0) / (double)na, db = (b1 - b0) / (double)nb;
    return lx_plane_axis(ctx, axis, level_m, a0 + 0.5 * da, a1 - 0.5 * da, b0 + 0.5 * db, b1 - 0.5 * db, 0, na, nb, out);
}
