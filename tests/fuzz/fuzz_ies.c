/* fuzz_ies.c - fuzz target: the photometric readers (IES LM-63 any version, EULUMDAT) on any bytes
 * through lx_luminaire_read_mem. Properties: never crash; an error names the file (and a line when the
 * input is not empty); an accepted luminaire has a consistent, finite, non-negative table whose
 * intensities and summary evaluate to finite numbers. */
#include "luxcalc.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

int fuzz_ies_one(const uint8_t *data, size_t size)
{
    lx_ctx *ctx;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    lx_luminaire *lum = NULL;
    /* a name without a folder: a TILT=<file> reference resolves against the working directory */
    lx_status st = lx_luminaire_read_mem(ctx, "fuzz.ies", (const char *)data, size, &lum);
    if (st == LX_OK) {
        if (!lum || lum->n_h < 1 || lum->n_v < 1 || lum->n_c < 1 || lum->n_g < 1) abort();
        for (size_t i = 0; i < lum->n_h * lum->n_v; i++)
            if (!(lum->cd[i] >= 0) || !isfinite(lum->cd[i])) abort(); /* the reader let a bad value through */
        for (size_t i = 0; i < lum->n_c * lum->n_g; i++)
            if (!(lum->full_cd[i] >= 0) || !isfinite(lum->full_cd[i])) abort();
        static const double dirs[6][3] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0.6, 0, -0.8}, {-0.48, 0.6, -0.64}};
        for (int k = 0; k < 6; k++)
            for (int m = 0; m < 2; m++) {
                double I = lx_luminaire_intensity_dir(lum, (lx_interp)m, dirs[k][0], dirs[k][1], dirs[k][2]);
                if (!(I >= 0) || !isfinite(I)) abort();
            }
        if (lum->n_c * lum->n_g <= 20000) { /* keep each run fast: the summary integrates the whole table */
            lx_lum_summary s;
            if (lx_luminaire_summary(ctx, lum, &s) == LX_OK && (!isfinite(s.lumens) || s.lumens < 0)) abort();
        }
        lx_luminaire_free(lum);
    } else {
        if (lum) abort(); /* *out stays NULL on failure */
        if (st == LX_EPARSE && (!lx_ctx_errfile(ctx) || (size > 0 && lx_ctx_errline(ctx) <= 0))) abort();
    }
    lx_ctx_destroy(ctx);
    return 0;
}

#ifdef LX_FUZZ_MAIN
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_ies_one(data, size); }
#endif
