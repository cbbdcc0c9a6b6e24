/* fuzz_units.c - fuzz target: quantity strings with units ("1000lm", "2.5 m", "46fc", ...).
 * Properties: never crash; an accepted value is finite. */
#include "luxcalc.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int fuzz_units_one(const uint8_t *data, size_t size)
{
    if (size > 256) return 0;
    char text[257];
    memcpy(text, data, size);
    text[size] = 0;
    lx_ctx *ctx;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    double v;
    lx_quantity got;
    for (int q = LX_Q_NONE; q < LX_Q_COUNT; q++)
        if (lx_quantity_parse(ctx, text, (lx_quantity)q, NULL, &v, &got) == LX_OK && !isfinite(v)) abort();
    const lx_unit *u;
    if (lx_unit_find(ctx, text, &u) == LX_OK && !(u->to_si > 0)) abort();
    lx_ctx_destroy(ctx);
    return 0;
}

#ifdef LX_FUZZ_MAIN
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_units_one(data, size); }
#endif
