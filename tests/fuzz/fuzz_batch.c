/* fuzz_batch.c - fuzz target: the parallel rows-layout batch reader (lx_batch_table_read_mem, the
 * path of `luxcalc spd` for big batches) on any bytes, in float and double, on 1 and 2 threads.
 * Properties: never crash; a parse error names a line; an accepted batch has a finite uniform grid,
 * a name per row and finite values; the vector line parser (csv_vector.c, where the CPU has
 * AVX-512) and the general one (LX_SIMD=scalar) agree: same status, same error line, the same
 * values bit for bit and the same names. */
#include "luxcalc.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The double batch read again by the general parser alone: same outcome as t / st, else abort. */
static void same_without_vector(lx_ctx *ctx, const uint8_t *data, size_t size, lx_status st, long line,
                                const lx_batch_table *t)
{
    const char *was = getenv("LX_SIMD");
    if (was) return; /* already the general parser */
    setenv("LX_SIMD", "scalar", 1);
    lx_batch_table *g = NULL;
    lx_status sg = lx_batch_table_read_mem(ctx, "fuzz.csv", (const char *)data, size, LX_F64, 1, &g);
    unsetenv("LX_SIMD");
    if (sg != st) abort();
    if (st != LX_OK) {
        if (st == LX_EPARSE && lx_ctx_errline(ctx) != line) abort();
        return;
    }
    const lx_batch *a = &t->batch, *b = &g->batch;
    if (a->n_spectra != b->n_spectra || a->n_lambda != b->n_lambda) abort();
    if (a->n_spectra && memcmp(a->values, b->values, a->n_spectra * a->n_lambda * sizeof(double))) abort();
    for (size_t i = 0; i < a->n_spectra; i++)
        if (strcmp(t->names + t->name_at[i], g->names + g->name_at[i])) abort();
    lx_batch_table_free(g);
}

int fuzz_batch_one(const uint8_t *data, size_t size)
{
    lx_ctx *ctx;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    for (int k = 0; k < 2; k++) {
        lx_batch_table *t = NULL;
        lx_status st = lx_batch_table_read_mem(ctx, "fuzz.csv", (const char *)data, size, k ? LX_F64 : LX_F32, 1 + k, &t);
        if (k) same_without_vector(ctx, data, size, st, lx_ctx_errline(ctx), t);
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
