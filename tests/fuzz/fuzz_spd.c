/* fuzz_spd.c - fuzz target: the spectral-file readers (text columns/rows, CGATS) on any bytes.
 * Properties: never crash; an error names a line; an accepted set passes lx_spd_check. */
#include "luxcalc.h"

#include <stdint.h>
#include <stdlib.h>

int fuzz_spd_one(const uint8_t *data, size_t size)
{
    lx_ctx *ctx;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    lx_spd_set *set = NULL;
    lx_status st = lx_spd_read_mem(ctx, "fuzz", (const char *)data, size, &set);
    if (st == LX_OK) {
        for (size_t i = 0; i < set->count; i++) {
            if (lx_spd_check(ctx, &set->spd[i]) != LX_OK) abort(); /* the reader let a bad spectrum through */
            lx_colorimetry c;
            lx_spd_colorimetry(ctx, &set->spd[i], LX_OBSERVER_2, LX_METHOD_AUTO, &c);
        }
        lx_spd_set_free(set);
    } else if (st == LX_EPARSE && lx_ctx_errline(ctx) <= 0) {
        abort(); /* a parse error must name its line */
    }
    lx_ctx_destroy(ctx);
    return 0;
}

#ifdef LX_FUZZ_MAIN
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_spd_one(data, size); }
#endif
