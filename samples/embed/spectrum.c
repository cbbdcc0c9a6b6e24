/* spectrum.c - embedding luxcalc: read a spectral file and print its chromaticity and CCT.
 * Build: cc spectrum.c $(pkg-config --cflags --libs luxcalc)   (or -Isrc build/libluxcalc.a -lm ...) */
#include <luxcalc.h>
#include <stdio.h>

int main(int argc, char **argv)
{
    lx_ctx *ctx;
    lx_spd_set *set;
    if (lx_ctx_create(&ctx) != LX_OK) return 3;
    if (argc < 2 || lx_spd_read_file(ctx, argv[1], &set) != LX_OK) {
        fprintf(stderr, "spectrum: %s\n", argc < 2 ? "usage: spectrum FILE" : lx_ctx_errmsg(ctx));
        lx_ctx_destroy(ctx);
        return 2;
    }
    for (size_t i = 0; i < set->count; i++) {
        lx_colorimetry c;
        if (lx_spd_colorimetry(ctx, &set->spd[i], LX_OBSERVER_2, LX_METHOD_AUTO, &c) == LX_OK)
            printf("%s: x=%.5f y=%.5f CCT=%.1f K Duv=%.5f\n", set->spd[i].name, c.x, c.y, c.cct_K, c.duv);
    }
    lx_spd_set_free(set);
    lx_ctx_destroy(ctx);
    return 0;
}
