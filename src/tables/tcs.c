/* tcs.c - public views of the CIE 13.3-1995 test colour samples of the embedded table (used by
 * `luxcalc bench accuracy` to show what a 3-coefficient RGB light gets wrong on coloured surfaces). */
#include "tables/tables_private.h"

#include <stdio.h>

lx_status lx_tcs_get(lx_ctx *ctx, int index, lx_spd *out)
{
    LX__NEED_CTX(ctx);
    if (!out || index < 1 || index > 14) return lx__error(ctx, LX_EINVAL, NULL, 0, "test colour sample %d: give 1 to 14", index);
    const lx__table *t = lx__table_find("cie13_3_tcs");
    if (!t) return lx__error(ctx, LX_EINVAL, NULL, 0, "embedded table cie13_3_tcs missing");
    char name[8];
    snprintf(name, sizeof name, "TCS%02d", index);
    int col = lx__table_col(t, name);
    if (col < 0 || lx__table_view(t, col, out) != 0) return lx__error(ctx, LX_EINVAL, NULL, 0, "table cie13_3_tcs has no column %s", name);
    return LX_OK;
}
