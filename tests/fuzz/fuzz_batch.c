/* fuzz_batch.c - fuzz target: the parallel rows-layout batch reader (lx_batch_table_read_mem, the
 * path of `luxcalc spd` for big batches) on any bytes, in float and double, on 1 and 2 threads.
 * Properties: never crash; a parse error names a line; an accepted batch has a finite uniform grid,
 * a name per row and finite values. */
#include "luxcalc.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

int fuzz_batch_one(const uint8_t *data, size_t size)
{
    lx_ctx *ctx;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    for (int k = 0; k < 2; k++) {
        lx_batch_table *t = NULL;
        lx_status st = lx_batch_table_read_mem(ctx, "fuzz.csv", (const char *)data, size, k ? LX_F64 : LX_F32, 1 + k, &t);
        if (st == LX_OK) {
            if (!t) abort();
            const lx_batch *b = &t->batch;
            if (b->n_lambda < 1 || !(b->step_nm > 0) || !isfinite(b->start_nm) || !isfinite(b->step_nm)) abort();
            size_t stride = b->row_stride ? b->row_stride : b->n_lambda;
            for (size_t i = 0; i < b->n_spectra; i++) {
                if (!t->name_at) abort();
                for (size_t j = 0; j < b->n_lambda; j++) {
                    double v = k ? ((const double *)b->values)[i * stride + j] : ((const float *)b->values)[i * stride + j];
                    if (!isfinite(v)) abort();
                }
            }
            lx_batch_table_free(t);
        } else {
            if (t) abort();
            if (st == LX_EPARSE && (!lx_ctx_errfile(ctx) || (size > 0 && lx_ctx_errline(ctx) <= 0))) abort();
        }
    }
    lx_ctx_destroy(ctx);
    return 0;
}

#ifdef LX_FUZZ_MAIN
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_batch_one(data, size); }
#endif
