/* exr_io.c - OpenEXR lat-long and cube maps through the OpenEXRCore C API: reading (scanline and tiled,
 * half and float, every compression, data and display windows, chromaticities, whiteLuminance)
 * and atomic writing (float or half, ZIP by default). I/O goes through our own stream callbacks
 * so that OpenEXR never prints: its messages end up in the context's error. */
#include "exr_private.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Which map channel a file channel feeds (-1: none). */
static int channel_slot(const char *name, int nch, int single)
{
    if (single) return 0;
    if (nch == 3) {
        if (!strcmp(name, "R")) return 0;
        if (!strcmp(name, "G")) return 1;
        if (!strcmp(name, "B")) return 2;
        return -1;
    }
    return !strcmp(name, "Y") ? 0 : -1;
}

/* lx__exr_slot_fn of reading: user points to {channels, single} */
static int read_slot(const char *name, const void *user)
{
    const int *cs = user;
    return channel_slot(name, cs[0], cs[1]);
}

/* lx__exr_slot_fn of writing: user points to the channel count; an unknown name feeds slot 0 */
static int write_slot(const char *name, const void *user)
{
    int slot = channel_slot(name, *(const int *)user, 0);
    return slot < 0 ? 0 : slot;
}

/* The channels the map takes: R, G, B (C = 3), else Y (C = 1), else a file's one channel (single). */
static lx_status exr_pick_channels(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t e, int *C_out,
                                   int *single_out)
{
    const exr_attr_chlist_t *cl;
    lx_status st = lx__exr_channels(ctx, path, s, e, &cl);
    if (st) return st;
    int has[4] = {0, 0, 0, 0}; /* R G B Y */
    for (int k = 0; k < cl->num_channels; k++) {
        const exr_attr_chlist_entry_t *en = &cl->entries[k];
        const char *n = en->name.str;
        int idx = !strcmp(n, "R") ? 0 : !strcmp(n, "G") ? 1 : !strcmp(n, "B") ? 2 : !strcmp(n, "Y") ? 3 : -1;
        if (idx >= 0) has[idx] = 1;
        if ((idx >= 0 || cl->num_channels == 1) && (st = lx__exr_check_channel(ctx, path, en))) return st;
    }
    int C, single = 0;
    if (has[0] && has[1] && has[2])
        C = 3;
    else if (has[3])
        C = 1;
    else if (cl->num_channels == 1)
        C = 1, single = 1;
    else
        return lx__error(ctx, LX_EPARSE, path, 0, "no R,G,B or Y channels (%d channels, first '%s')", cl->num_channels,
                         cl->entries[0].name.str);
    *C_out = C;
    *single_out = single;
    return LX_OK;
}

/* The data and display windows, checked: not empty, under the pixel limit, plausible for the file's
 * size, N x 6N for a cube map. wh: display W, H, data width, height. */
static lx_status exr_windows(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t e, int cube,
                             exr_attr_box2i_t *dw, exr_attr_box2i_t *disp, long wh[4])
{
    exr_result_t rv;
    if ((rv = exr_get_data_window(e, 0, dw)) || (rv = exr_get_display_window(e, 0, disp)))
        return lx__exr_fail(ctx, path, s, rv, "no data or display window");
    long W = (long)disp->max.x - disp->min.x + 1, H = (long)disp->max.y - disp->min.y + 1;
    long dw_w = (long)dw->max.x - dw->min.x + 1, dw_h = (long)dw->max.y - dw->min.y + 1;
    if (W < 1 || H < 1 || dw_w < 1 || dw_h < 1)
        return lx__error(ctx, LX_EPARSE, path, 0, "invalid windows: display %ldx%ld, data %ldx%ld", W, H, dw_w, dw_h);
    if ((double)W * H > LX__EXR_MAX_PIXELS || (double)dw_w * dw_h > LX__EXR_MAX_PIXELS) {
        char lim_s[48];
        lx__fmt_magnitude(lim_s, sizeof lim_s, LX__EXR_MAX_PIXELS);
        return lx__error(ctx, LX_EPARSE, path, 0, "windows (display %ldx%ld, data %ldx%ld) over the limit of %s pixels",
                         W, H, dw_w, dw_h, lim_s);
    }
    /* the windows are untrusted counts: before sizing buffers by them, check them against the file
     * (16 Mpixel, or 64 pixels per byte of file: beyond what real compression reaches on real maps) */
    double fsize = (double)lx__exr_stream_size(s),
           lim = LX__EXR_PIXELS_FREE + LX__EXR_PIXELS_PER_BYTE * (fsize > 0 ? fsize : 0);
    if ((double)W * H > lim || (double)dw_w * dw_h > lim)
        return lx__error(ctx, LX_EPARSE, path, 0,
                         "windows (display %ldx%ld, data %ldx%ld) too large for a file of %.0f bytes", W, H, dw_w, dw_h,
                         fsize);
    if (cube && H != 6 * W)
        return lx__error(ctx, LX_EPARSE, path, 0, "cube map display window %ldx%ld is not N x 6N", W, H);
    wh[0] = W, wh[1] = H, wh[2] = dw_w, wh[3] = dw_h;
    return LX_OK;
}

/* The map's attributes: chromaticities (its Y weights), luxcalcQuantity, whiteLuminance. */
static lx_status exr_attributes(lx_ctx *ctx, const char *path, exr_context_t e, int C, lx_envmap *m)
{
    exr_attr_chromaticities_t chr;
    if (C == 3 && exr_attr_get_chromaticities(e, 0, "chromaticities", &chr) == EXR_ERR_SUCCESS) {
        double xy[8] = {chr.red_x,  chr.red_y,  chr.green_x, chr.green_y,
                        chr.blue_x, chr.blue_y, chr.white_x, chr.white_y};
        lx_status st = lx_rgb_y_weights(ctx, xy, m->y_weights);
        if (st) {
            lx__error(ctx, LX_EPARSE, path, 0, "invalid chromaticities attribute: %s", lx_ctx_errmsg(ctx));
            return st;
        }
        m->has_chromaticities = 1;
        memcpy(m->chroma_xy, xy, sizeof xy);
    }
    const char *q = NULL;
    int32_t ql = 0;
    if (exr_attr_get_string(e, 0, "luxcalcQuantity", &ql, &q) == EXR_ERR_SUCCESS && q && ql == 10 &&
        !memcmp(q, "irradiance", 10))
        m->irradiance = 1;
    float wl;
    if (exr_attr_get_float(e, 0, "whiteLuminance", &wl) == EXR_ERR_SUCCESS && isfinite(wl) && wl > 0) {
        m->units = LX_ENV_LUMINANCE;
        m->lum_per_unit = wl;
    }
    return LX_OK;
}

/* The pixels: the data window read into a buffer, placed into the display window of m, all finite. */
static lx_status exr_pixels(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t e, exr_storage_t storage,
                            const exr_attr_box2i_t *dw, const exr_attr_box2i_t *disp, const long wh[4], int C,
                            int single, lx_envmap *m)
{
    long W = wh[0], H = wh[1], dw_w = wh[2], dw_h = wh[3];
    float *buf = lx__calloc((size_t)dw_w * dw_h * C, sizeof *buf);
    if (!buf) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory for %ldx%ld pixels", dw_w, dw_h);
    const int slot_spec[2] = {C, single};
    lx_status st = lx__exr_read_pixels(ctx, path, s, e, storage, dw, buf, (int)dw_w, C, read_slot, slot_spec);
    if (st) {
        lx__free(buf);
        return st;
    }
    /* place the data window into the display window */
    for (long y = 0; y < dw_h; y++) {
        long my = y + dw->min.y - disp->min.y;
        if (my < 0 || my >= H) continue;
        for (long x = 0; x < dw_w; x++) {
            long mx = x + dw->min.x - disp->min.x;
            if (mx < 0 || mx >= W) continue;
            memcpy(m->data + ((size_t)my * W + mx) * C, buf + ((size_t)y * dw_w + x) * C, C * sizeof(float));
        }
    }
    lx__free(buf);
    return LX_OK;
}

/* No NaN or infinity in the map (a chunk that decoded short leaves NaN). */
static lx_status exr_check_finite(lx_ctx *ctx, const char *path, const lx_envmap *m, long W, long H, int C)
{
    size_t n = (size_t)W * H * C;
    for (size_t k = 0; k < n; k++)
        if (!isfinite(m->data[k]))
            return lx__error(
                ctx, LX_EPARSE, path, 0,
                "pixel (%zu, %zu) is not finite (NaN, infinite, or missing from a chunk that decoded short)",
                (k / C) % W, (k / C) / W);
    return LX_OK;
}

static lx_status exr_read(lx_ctx *ctx, const char *path, int allow_cube, lx_envmap **out)
{
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_exr_read: NULL argument");
    *out = NULL;
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode))
        return lx__error(ctx, LX_EIO, path, 0, "cannot read: not a regular file (OpenEXR files are read by seeking)");
    lx__exr_stream s = {.fd = open(path, O_RDONLY)};
    if (s.fd < 0) return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(errno));
    exr_context_t e = NULL;
    lx_envmap *m = NULL;
    exr_storage_t storage;
    lx_status st = lx__exr_read_begin(ctx, path, &s, &e, &storage, "deep images are not radiance maps");
    if (st) goto done;
    exr_envmap_t env;
    int cube = exr_attr_get_envmap(e, 0, "envmap", &env) == EXR_ERR_SUCCESS && env == EXR_ENVMAP_CUBE;
    if (cube && !allow_cube) {
        st = lx__error(ctx, LX_EUNSUPPORTED, path, 0, "this command takes lat-long maps, not cube-face maps");
        goto done;
    }
    int C = 0, single = 0;
    if ((st = exr_pick_channels(ctx, path, &s, e, &C, &single))) goto done;
    exr_attr_box2i_t dw, disp;
    long wh[4] = {0, 0, 0, 0}; /* display W, H; data width, height */
    if ((st = exr_windows(ctx, path, &s, e, cube, &dw, &disp, wh))) goto done;
    st = cube ? lx_envmap_create_cube(ctx, (int)wh[0], C, &m) : lx_envmap_create(ctx, (int)wh[0], (int)wh[1], C, &m);
    if (st) goto done;
    if ((st = exr_pixels(ctx, path, &s, e, storage, &dw, &disp, wh, C, single, m))) goto done;
    if ((st = exr_attributes(ctx, path, e, C, m))) goto done;
    st = exr_check_finite(ctx, path, m, wh[0], wh[1], C);
done:
    if (e) exr_finish(&e);
    close(s.fd);
    if (st)
        lx_envmap_free(m);
    else
        *out = m;
    return st;
}

lx_status lx_exr_read(lx_ctx *ctx, const char *path, lx_envmap **out)
{
    LX__NEED_CTX(ctx);
    return exr_read(ctx, path, 0, out);
}

lx_status lx_exr_read_any(lx_ctx *ctx, const char *path, lx_envmap **out) {
    LX__NEED_CTX(ctx); return exr_read(ctx, path, 1, out); }

lx_status lx_envmap_write_exr(lx_ctx *ctx, const char *path, const lx_envmap *map, const lx_exr_write_opts *opts)
{
    LX__NEED_CTX(ctx);
    if (!path || !map || !map->data) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_envmap_write_exr: NULL argument");
    lx_exr_write_opts o = {0};
    if (opts) o = *opts;
    lx_status st0 = lx__check_reserved(ctx, "EXR options", o.reserved, sizeof o.reserved);
    if (st0) return st0;
    exr_compression_t comp = o.use_compression ? (exr_compression_t)o.compression : EXR_COMPRESSION_ZIP;
    if ((int)comp < 0 || comp >= EXR_COMPRESSION_LAST_TYPE)
        return lx__error(ctx, LX_EINVAL, path, 0, "unknown EXR compression %d", (int)comp);
    lx__exr_stream s = {.fd = -1};
    lx_status st = lx__exr_write_begin(ctx, path, &s);
    if (st) return st;
    exr_context_initializer_t init;
    lx__exr_stream_init(&s, 1, &init);
    exr_context_t e = NULL;
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int inited = 0, part = 0, C = map->channels, W = map->width, H = map->height;
    exr_result_t rv = exr_start_write(&e, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (!rv) rv = exr_add_part(e, "", o.tile_size > 0 ? EXR_STORAGE_TILED : EXR_STORAGE_SCANLINE, &part);
    if (!rv) rv = exr_initialize_required_attr_simple(e, part, W, H, comp);
    if (!rv && o.tile_size > 0)
        rv = exr_set_tile_descriptor(e, part, (uint32_t)o.tile_size, (uint32_t)o.tile_size, EXR_TILE_ONE_LEVEL,
                                     EXR_TILE_ROUND_DOWN);
    exr_pixel_type_t pt = o.half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT;
    static const char *rgb[3] = {"R", "G", "B"};
    for (int c = 0; c < C && !rv; c++)
        if (exr_add_channel(e, part, C == 3 ? rgb[c] : "Y", pt, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1)) rv = EXR_ERR_INVALID_ARGUMENT;
    if (!rv)
        rv = exr_attr_set_envmap(e, part, "envmap", map->layout == LX_ENV_CUBE ? EXR_ENVMAP_CUBE : EXR_ENVMAP_LATLONG);
    if (!rv && C == 3 && map->has_chromaticities) {
        const double *q = map->chroma_xy;
        exr_attr_chromaticities_t chr = {(float)q[0], (float)q[1], (float)q[2], (float)q[3],
                                         (float)q[4], (float)q[5], (float)q[6], (float)q[7]};
        rv = exr_attr_set_chromaticities(e, part, "chromaticities", &chr);
    }
    if (!rv && map->units == LX_ENV_LUMINANCE) rv = exr_attr_set_float(e, part, "whiteLuminance", (float)map->lum_per_unit);
    if (!rv && map->irradiance) rv = exr_attr_set_string(e, part, "luxcalcQuantity", "irradiance");
    if (!rv) rv = exr_write_header(e);
    if (rv) {
        st = lx__exr_fail(ctx, path, &s, rv, "cannot write the header");
        goto done;
    }
    long nchunks, tsz = o.tile_size, ntx = 1;
    int32_t lpc = 1;
    if (tsz > 0) {
        ntx = (W + tsz - 1) / tsz;
        nchunks = ntx * ((H + tsz - 1) / tsz);
    } else {
        exr_get_scanlines_per_chunk(e, part, &lpc);
        if (lpc < 1) lpc = 1;
        nchunks = (H + lpc - 1) / lpc;
    }
    for (long k = 0; k < nchunks; k++) {
        exr_chunk_info_t ci;
        int x0 = 0, y0;
        if (tsz > 0) {
            x0 = (int)((k % ntx) * tsz);
            y0 = (int)((k / ntx) * tsz);
            rv = exr_write_tile_chunk_info(e, part, (int)(k % ntx), (int)(k / ntx), 0, 0, &ci);
        } else {
            y0 = (int)(k * lpc);
            rv = exr_write_scanline_chunk_info(e, part, y0, &ci);
        }
        if (!rv) rv = lx__exr_encode_chunk(e, part, &enc, &inited, &ci, map->data, W, x0, y0, C, write_slot, &C);
        if (rv) break;
    }
    if (rv) st = lx__exr_fail(ctx, path, &s, rv, "cannot encode the pixels");
done:
    if (inited) exr_encoding_destroy(e, &enc);
    return lx__exr_write_end(ctx, path, &s, &e, st);
}
