/* fuzz_instruments.c - fuzz target: the readers of instrument exports (OceanView, Sekonic, UPRtek,
 * TM-27 XML, SpectraWiz, AvaSoft, Excel CSV, CGATS) with their options, on any bytes. The first
 * byte picks the options: the layout (detected or forced), skip_bad_rows, skip_lines, the
 * wavelength unit, a column selection. Properties: never crash; an error names a line (or, for a
 * bad option, is LX_EINVAL); an accepted set passes lx_spd_check, its fields and skipped rows are
 * whole strings, skipped lines are increasing line numbers; the vendor results, PAR, hazards and
 * binning of every spectrum compute without crashing. */
#include "luxcalc.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int fuzz_instruments_one(const uint8_t *data, size_t size)
{
    if (size == 0) return 0;
    static const char *const units[4] = {NULL, "nm", "um", "A"};
    static const char *const columns[4] = {NULL, "1,2", "2,3,1", "nm,A"};
    uint8_t k = data[0];
    const char *const *formats = lx_spd_formats();
    size_t nformats = 0;
    while (formats[nformats]) nformats++;
    lx_spd_read_opts o;
    memset(&o, 0, sizeof o);
    size_t f = k % (nformats + 4); /* mostly detection */
    o.format = f < nformats ? formats[f] : NULL;
    o.skip_bad_rows = (k >> 3) & 1;
    o.skip_lines = (k >> 4) & 1 ? 1 : 0;
    o.wavelength_unit = units[(k >> 5) & 3];
    o.columns = (k >> 7) & 1 ? columns[(k >> 1) & 3] : NULL;
    lx_ctx *ctx;
    if (lx_ctx_create(&ctx) != LX_OK) return 0;
    lx_spd_set *set = NULL;
    lx_status st = lx_spd_read_mem_opts(ctx, "fuzz", (const char *)data + 1, size - 1, &o, &set);
    if (st == LX_OK) {
        if (!set->format) abort(); /* every reader names its layout */
        for (size_t i = 0; i < set->nfields; i++)
            if (!set->fields[i].key || !set->fields[i].value || strlen(set->fields[i].key) > size) abort();
        for (size_t i = 0; i < set->nskipped; i++) {
            if (!set->skipped[i].why || set->skipped[i].line <= 0) abort();
            /* in file order, except the delimited reader's second pass (empty values, duplicates) */
            int text = !strcmp(set->format, "columns") || !strcmp(set->format, "avantes");
            if (i && set->skipped[i].line < set->skipped[i - 1].line && !text) abort();
        }
        if (set->nskipped && !o.skip_bad_rows) abort(); /* rows are only left out when asked */
        lx_vendor_results v;
        if (lx_spd_set_vendor(ctx, set, &v) != LX_OK) abort();
        for (size_t i = 0; i < set->count; i++) {
            if (lx_spd_check(ctx, &set->spd[i]) != LX_OK) abort(); /* the reader let a bad spectrum through */
            lx_par p;
            lx_hazard h;
            lx_colorimetry c;
            lx_par_compute(ctx, &set->spd[i], LX_METHOD_AUTO, &p);
            if (lx_hazard_compute(ctx, &set->spd[i], LX_METHOD_AUTO, &h) == LX_OK) {
                lx_hazard_risk r;
                lx_hazard_risk_group(ctx, &h, (int)(i & 1), 0.01, &r);
            }
            if (lx_spd_colorimetry(ctx, &set->spd[i], LX_OBSERVER_2, LX_METHOD_AUTO, &c) == LX_OK) {
                lx_binning b;
                lx_binning_compute(ctx, c.x, c.y, c.cct_K, c.duv, &b);
            }
        }
        lx_spd_set_free(set);
    } else if (st == LX_EPARSE && lx_ctx_errline(ctx) <= 0) {
        abort(); /* a parse error must name its line */
    } else if (set) {
        abort(); /* no result on failure */
    }
    lx_ctx_destroy(ctx);
    return 0;
}

/* A file as it is (no option byte): read with several option bytes, for replaying corpora. */
int fuzz_instruments_file(const uint8_t *data, size_t size)
{
    static const uint8_t opts[] = {0x0c, 0x08, 0x18, 0x2c, 0x4c, 0x6c, 0x84, 0x86, 0, 1, 2, 3, 4, 5, 6, 7, 8};
    uint8_t *buf = malloc(size + 1);
    if (!buf) return 0;
    memcpy(buf + 1, data, size);
    for (size_t i = 0; i < sizeof opts; i++) {
        buf[0] = opts[i];
        fuzz_instruments_one(buf, size + 1);
    }
    free(buf);
    return 0;
}

#ifdef LX_FUZZ_MAIN
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_instruments_one(data, size); }
#endif
