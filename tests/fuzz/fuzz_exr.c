/* fuzz_exr.c - fuzz target: the OpenEXR readers (lx_exr_read for radiance maps and
 * lx_spectral_exr_read_xyz for spectral images, OpenEXRCore underneath) on any bytes. They take a
 * path, so each input is written to one temporary file first. Properties: never crash; an error
 * names the file; an accepted map or image is well formed and finite. */
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
    lx_batch_opts o = {.backend = LX_BACKEND_CPU};
    lx_xyz_image *img = NULL;
    st = lx_spectral_exr_read_xyz(ctx, fuzz_exr_path, LX_OBSERVER_2, &o, &img);
    if (st == LX_OK) {
        if (!img || img->width < 1 || img->height < 1 || img->n_lambda < 1 || !img->xyz) abort();
        for (size_t i = 0; i < (size_t)img->width * img->height * 3; i++)
            if (!isfinite(img->xyz[i])) abort();
        lx_xyz_image_free(img);
    } else {
        if (img) abort();
        if (!lx_ctx_errfile(ctx)) abort();
    }
    lx_ctx_destroy(ctx);
    return 0;
}

#ifdef LX_FUZZ_MAIN
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_exr_one(data, size); }
#endif
