/* fuzz_exr.c - fuzz target: the OpenEXR reader (lx_exr_read, OpenEXRCore underneath) on any bytes.
 * lx_exr_read takes a path, so each input is written to one temporary file first.
 * Properties: never crash; an error names the file; an accepted map is well formed and finite. */
#include "luxcalc.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static char fuzz_exr_path[64];

static void fuzz_exr_cleanup(void)
{
    if (fuzz_exr_path[0]) unlink(fuzz_exr_path);
}

int fuzz_exr_one(const uint8_t *data, size_t size)
{
    if (!fuzz_exr_path[0]) {
        snprintf(fuzz_exr_path, sizeof fuzz_exr_path, "%s/lxfuzzexr.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
        int fd = mkstemp(fuzz_exr_path);
        if (fd < 0) abort();
        close(fd);
        atexit(fuzz_exr_cleanup);
    }
    FILE *f = fopen(fuzz_exr_path, "wb");
    if (!f) abort();
    if (size && fwrite(data, 1, size, f) != size) abort();
    fclose(f);
    lx_ctx *ctx;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    lx_envmap *m = NULL;
    lx_status st = lx_exr_read(ctx, fuzz_exr_path, &m);
    if (st == LX_OK) {
        if (!m || m->width < 1 || m->height < 1 || (m->channels != 1 && m->channels != 3) || !m->data) abort();
        size_t n = (size_t)m->width * m->height * m->channels;
        for (size_t i = 0; i < n; i++)
            if (!isfinite(m->data[i])) abort(); /* the reader promises finite pixels */
        if (!(m->lum_per_unit > 0) || !isfinite(m->lum_per_unit)) abort();
        lx_envmap_free(m);
    } else {
        if (m) abort();
        if (!lx_ctx_errfile(ctx)) abort(); /* every error names the file */
    }
    lx_ctx_destroy(ctx);
    return 0;
}

#ifdef LX_FUZZ_MAIN
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_exr_one(data, size); }
#endif
