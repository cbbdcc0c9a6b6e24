/* exr_io.c - OpenEXR lat-long and cube maps through the OpenEXRCore C API: reading (scanline and tiled,
 * half and float, every compression, data and display windows, chromaticities, whiteLuminance)
 * and atomic writing (float or half, ZIP by default). I/O goes through our own stream callbacks
 * so that OpenEXR never prints: its messages end up in the context's error. */
#include "lx_private.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <openexr.h>

typedef struct stream {
    int fd;
    char msg[512]; /* the last message OpenEXR reported */
} stream;

static void on_error(exr_const_context_t ectx, exr_result_t code, const char *msg)
{
    void *ud = NULL;
    if (exr_get_user_data(ectx, &ud) == EXR_ERR_SUCCESS && ud)
        snprintf(((stream *)ud)->msg, sizeof ((stream *)ud)->msg, "%s (%s)", msg ? msg : "",
                 exr_get_error_code_as_string(code));
}

static int64_t s_read(exr_const_context_t ectx, void *ud, void *buf, uint64_t sz, uint64_t off,
                      exr_stream_error_func_ptr_t err)
{
    (void)ectx;
    (void)err;
    stream *s = ud;
    uint64_t got = 0;
    while (got < sz) {
        ssize_t r = pread(s->fd, (char *)buf + got, (size_t)(sz - got), (off_t)(off + got));
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) return -1;
        if (r == 0) break;
        got += (uint64_t)r;
    }
    return (int64_t)got;
}

static int64_t s_size(exr_const_context_t ectx, void *ud)
{
    (void)ectx;
    struct stat sb;
    return fstat(((stream *)ud)->fd, &sb) == 0 ? (int64_t)sb.st_size : -1;
}

static int64_t s_write(exr_const_context_t ectx, void *ud, const void *buf, uint64_t sz, uint64_t off,
                       exr_stream_error_func_ptr_t err)
{
    (void)ectx;
    (void)err;
    stream *s = ud;
    uint64_t put = 0;
    while (put < sz) {
        ssize_t r = pwrite(s->fd, (const char *)buf + put, (size_t)(sz - put), (off_t)(off + put));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return -1;
        put += (uint64_t)r;
    }
    return (int64_t)put;
}

static lx_status exr_fail(lx_ctx *ctx, const char *path, const stream *s, exr_result_t rv, const char *what)
{
    lx_status st = rv == EXR_ERR_OUT_OF_MEMORY ? LX_ENOMEM
                   : rv == EXR_ERR_FEATURE_NOT_IMPLEMENTED ? LX_EUNSUPPORTED
                   : (rv == EXR_ERR_READ_IO || rv == EXR_ERR_WRITE_IO || rv == EXR_ERR_FILE_ACCESS) ? LX_EIO
                                                                                                     : LX_EPARSE;
    return lx__error(ctx, st, path, 0, "%s: %s", what, s->msg[0] ? s->msg : exr_get_default_error_message(rv));
}

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

/* Decodes one chunk into buf (data-window layout, C floats per pixel, row stride dw_w). */
static lx_status decode_chunk(lx_ctx *ctx, const char *path, stream *s, exr_context_t e, exr_decode_pipeline_t *dec,
                              int *inited, const exr_chunk_info_t *ci, float *buf, int dw_w, int x0, int y0, int C,
                              int single)
{
    exr_result_t rv = *inited ? exr_decoding_update(e, 0, ci, dec) : exr_decoding_initialize(e, 0, ci, dec);
    if (rv) return exr_fail(ctx, path, s, rv, "cannot decode a chunk");
    *inited = 1;
    for (int k = 0; k < dec->channel_count; k++) {
        exr_coding_channel_info_t *ch = &dec->channels[k];
        int slot = channel_slot(ch->channel_name, C, single);
        if (slot < 0 || ch->height == 0) {
            ch->decode_to_ptr = NULL;
            continue;
        }
        ch->decode_to_ptr = (uint8_t *)(buf + ((size_t)y0 * dw_w + x0) * C + slot);
        ch->user_pixel_stride = (int32_t)(C * sizeof(float));
        ch->user_line_stride = (int32_t)((size_t)dw_w * C * sizeof(float));
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
    }
    rv = exr_decoding_choose_default_routines(e, 0, dec);
    if (!rv) rv = exr_decoding_run(e, 0, dec);
    if (rv) return exr_fail(ctx, path, s, rv, "cannot decode a chunk");
    return LX_OK;
}

static lx_status exr_read(lx_ctx *ctx, const char *path, int allow_cube, lx_envmap **out)
{
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_exr_read: NULL argument");
    *out = NULL;
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode))
        return lx__error(ctx, LX_EIO, path, 0, "cannot read: not a regular file (OpenEXR files are read by seeking)");
    stream s = {.fd = open(path, O_RDONLY)};
    if (s.fd < 0) return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(errno));
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = &s;
    init.read_fn = s_read;
    init.size_fn = s_size;
    exr_context_t e = NULL;
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int inited = 0;
    float *buf = NULL;
    lx_envmap *m = NULL;
    lx_status st = LX_OK;
    exr_result_t rv = exr_start_read(&e, path, &init);
    if (rv) {
        st = exr_fail(ctx, path, &s, rv, "not a readable OpenEXR file");
        goto done;
    }
    exr_storage_t storage;
    int nparts = 0;
    exr_get_count(e, &nparts);
    if ((rv = exr_get_storage(e, 0, &storage))) {
        st = exr_fail(ctx, path, &s, rv, "cannot read the header");
        goto done;
    }
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
        st = lx__error(ctx, LX_EUNSUPPORTED, path, 0, "deep images are not radiance maps");
        goto done;
    }
    exr_envmap_t env;
    int cube = exr_attr_get_envmap(e, 0, "envmap", &env) == EXR_ERR_SUCCESS && env == EXR_ENVMAP_CUBE;
    if (cube && !allow_cube) {
        st = lx__error(ctx, LX_EUNSUPPORTED, path, 0, "this command takes lat-long maps, not cube-face maps");
        goto done;
    }
    const exr_attr_chlist_t *cl = NULL;
    if ((rv = exr_get_channels(e, 0, &cl)) || !cl || cl->num_channels < 1) {
        st = exr_fail(ctx, path, &s, rv ? rv : EXR_ERR_MISSING_REQ_ATTR, "no channels");
        goto done;
    }
    int has[4] = {0, 0, 0, 0}; /* R G B Y */
    for (int k = 0; k < cl->num_channels; k++) {
        const exr_attr_chlist_entry_t *en = &cl->entries[k];
        const char *n = en->name.str;
        int idx = !strcmp(n, "R") ? 0 : !strcmp(n, "G") ? 1 : !strcmp(n, "B") ? 2 : !strcmp(n, "Y") ? 3 : -1;
        if (idx >= 0) has[idx] = 1;
        if (idx >= 0 || cl->num_channels == 1) {
            if (en->x_sampling != 1 || en->y_sampling != 1) {
                st = lx__error(ctx, LX_EUNSUPPORTED, path, 0, "channel %s is subsampled (%dx%d)", n, en->x_sampling,
                               en->y_sampling);
                goto done;
            }
            if (en->pixel_type == EXR_PIXEL_UINT) {
                st = lx__error(ctx, LX_EUNSUPPORTED, path, 0, "channel %s holds integers, not radiance", n);
                goto done;
            }
        }
    }
    int C, single = 0;
    if (has[0] && has[1] && has[2]) C = 3;
    else if (has[3]) C = 1;
    else if (cl->num_channels == 1) C = 1, single = 1;
    else {
        st = lx__error(ctx, LX_EPARSE, path, 0, "no R,G,B or Y channels (%d channels, first '%s')", cl->num_channels,
                       cl->entries[0].name.str);
        goto done;
    }
    exr_attr_box2i_t dw, disp;
    if ((rv = exr_get_data_window(e, 0, &dw)) || (rv = exr_get_display_window(e, 0, &disp))) {
        st = exr_fail(ctx, path, &s, rv, "no data or display window");
        goto done;
    }
    long W = (long)disp.max.x - disp.min.x + 1, H = (long)disp.max.y - disp.min.y + 1;
    long dw_w = (long)dw.max.x - dw.min.x + 1, dw_h = (long)dw.max.y - dw.min.y + 1;
    if (W < 1 || H < 1 || dw_w < 1 || dw_h < 1 || (double)W * H > 1e9 || (double)dw_w * dw_h > 1e9) {
        st = lx__error(ctx, LX_EPARSE, path, 0, "invalid windows: display %ldx%ld, data %ldx%ld", W, H, dw_w, dw_h);
        goto done;
    }
    /* the windows are untrusted counts: before sizing buffers by them, check them against the file
     * (16 Mpixel, or 64 pixels per byte of file: beyond what real compression reaches on real maps) */
    double fsize = (double)s_size(e, &s), lim = 16777216.0 + 64.0 * (fsize > 0 ? fsize : 0);
    if ((double)W * H > lim || (double)dw_w * dw_h > lim) {
        st = lx__error(ctx, LX_EPARSE, path, 0, "windows (display %ldx%ld, data %ldx%ld) too large for a file of %.0f bytes",
                       W, H, dw_w, dw_h, fsize);
        goto done;
    }
    if (cube && H != 6 * W) {
        st = lx__error(ctx, LX_EPARSE, path, 0, "cube map display window %ldx%ld is not N x 6N", W, H);
        goto done;
    }
    st = cube ? lx_envmap_create_cube(ctx, (int)W, C, &m) : lx_envmap_create(ctx, (int)W, (int)H, C, &m);
    if (st) goto done;
    buf = calloc((size_t)dw_w * dw_h * C, sizeof *buf);
    if (!buf) {
        st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory for %ldx%ld pixels", dw_w, dw_h);
        goto done;
    }
    exr_chunk_info_t ci;
    if (storage == EXR_STORAGE_SCANLINE) {
        int32_t lpc = 1;
        exr_get_scanlines_per_chunk(e, 0, &lpc);
        if (lpc < 1) lpc = 1;
        for (long y = dw.min.y; y <= dw.max.y && !st; y += lpc) {
            if ((rv = exr_read_scanline_chunk_info(e, 0, (int)y, &ci))) {
                st = exr_fail(ctx, path, &s, rv, "cannot read a scanline chunk");
                break;
            }
            st = decode_chunk(ctx, path, &s, e, &dec, &inited, &ci, buf, (int)dw_w, 0, (int)(ci.start_y - dw.min.y), C,
                              single);
        }
    } else {
        uint32_t tw = 0, th = 0;
        exr_tile_level_mode_t lm;
        exr_tile_round_mode_t rm;
        int32_t lw = 0, lh = 0;
        if ((rv = exr_get_tile_descriptor(e, 0, &tw, &th, &lm, &rm)) || (rv = exr_get_level_sizes(e, 0, 0, 0, &lw, &lh)) ||
            tw == 0 || th == 0) {
            st = exr_fail(ctx, path, &s, rv ? rv : EXR_ERR_INVALID_ATTR, "invalid tile description");
            goto done;
        }
        long ntx = (lw + (long)tw - 1) / tw, nty = (lh + (long)th - 1) / th;
        for (long ty = 0; ty < nty && !st; ty++)
            for (long tx = 0; tx < ntx && !st; tx++) {
                if ((rv = exr_read_tile_chunk_info(e, 0, (int)tx, (int)ty, 0, 0, &ci))) {
                    st = exr_fail(ctx, path, &s, rv, "cannot read a tile");
                    break;
                }
                st = decode_chunk(ctx, path, &s, e, &dec, &inited, &ci, buf, (int)dw_w, (int)(tx * tw), (int)(ty * th),
                                  C, single);
            }
    }
    if (st) goto done;
    /* place the data window into the display window */
    for (long y = 0; y < dw_h; y++) {
        long my = y + dw.min.y - disp.min.y;
        if (my < 0 || my >= H) continue;
        for (long x = 0; x < dw_w; x++) {
            long mx = x + dw.min.x - disp.min.x;
            if (mx < 0 || mx >= W) continue;
            memcpy(m->data + ((size_t)my * W + mx) * C, buf + ((size_t)y * dw_w + x) * C, C * sizeof(float));
        }
    }
    exr_attr_chromaticities_t chr;
    if (C == 3 && exr_attr_get_chromaticities(e, 0, "chromaticities", &chr) == EXR_ERR_SUCCESS) {
        double xy[8] = {chr.red_x, chr.red_y, chr.green_x, chr.green_y, chr.blue_x, chr.blue_y, chr.white_x, chr.white_y};
        st = lx_rgb_y_weights(ctx, xy, m->y_weights);
        if (st) {
            lx__error(ctx, LX_EPARSE, path, 0, "invalid chromaticities attribute: %s", lx_ctx_errmsg(ctx));
            goto done;
        }
        m->has_chromaticities = 1;
        memcpy(m->chroma_xy, xy, sizeof xy);
    }
    float wl;
    if (exr_attr_get_float(e, 0, "whiteLuminance", &wl) == EXR_ERR_SUCCESS && isfinite(wl) && wl > 0) {
        m->units = LX_ENV_LUMINANCE;
        m->lum_per_unit = wl;
    }
    size_t n = (size_t)W * H * C;
    for (size_t k = 0; k < n; k++)
        if (!isfinite(m->data[k])) {
            st = lx__error(ctx, LX_EPARSE, path, 0, "pixel (%zu, %zu) is not finite", (k / C) % W, (k / C) / W);
            goto done;
        }
done:
    if (inited) exr_decoding_destroy(e, &dec);
    if (e) exr_finish(&e);
    close(s.fd);
    free(buf);
    if (st) lx_envmap_free(m);
    else *out = m;
    return st;
}

lx_status lx_exr_read(lx_ctx *ctx, const char *path, lx_envmap **out) { return exr_read(ctx, path, 0, out); }

lx_status lx_exr_read_any(lx_ctx *ctx, const char *path, lx_envmap **out) { return exr_read(ctx, path, 1, out); }

lx_status lx_exr_write(lx_ctx *ctx, const char *path, const lx_envmap *map, const lx_exr_write_opts *opts)
{
    if (!path || !map || !map->data) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_exr_write: NULL argument");
    lx_exr_write_opts o = {0};
    if (opts) o = *opts;
    exr_compression_t comp = o.use_compression ? (exr_compression_t)o.compression : EXR_COMPRESSION_ZIP;
    if ((int)comp < 0 || comp >= EXR_COMPRESSION_LAST_TYPE)
        return lx__error(ctx, LX_EINVAL, path, 0, "unknown EXR compression %d", (int)comp);
    size_t plen = strlen(path);
    char *tmp = malloc(plen + 16);
    if (!tmp) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    snprintf(tmp, plen + 16, "%s.tmpXXXXXX", path);
    stream s = {.fd = mkstemp(tmp)};
    if (s.fd < 0) {
        lx_status st = lx__error(ctx, LX_EIO, path, 0, "cannot create: %s", strerror(errno));
        free(tmp);
        return st;
    }
    fchmod(s.fd, 0644);
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = &s;
    init.write_fn = s_write;
    exr_context_t e = NULL;
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int inited = 0, part = 0, C = map->channels, W = map->width, H = map->height;
    lx_status st = LX_OK;
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
    if (!rv) rv = exr_write_header(e);
    if (rv) {
        st = exr_fail(ctx, path, &s, rv, "cannot write the header");
        goto done;
    }
    const size_t row_bytes = (size_t)W * C * sizeof(float);
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
        if (!rv) rv = inited ? exr_encoding_update(e, part, &ci, &enc) : exr_encoding_initialize(e, part, &ci, &enc);
        if (rv) break;
        inited = 1;
        for (int q = 0; q < enc.channel_count; q++) {
            exr_coding_channel_info_t *ch = &enc.channels[q];
            int slot = channel_slot(ch->channel_name, C, 0);
            if (slot < 0) slot = 0;
            ch->encode_from_ptr = (const uint8_t *)(map->data + ((size_t)y0 * W + x0) * C + slot);
            ch->user_pixel_stride = (int32_t)(C * sizeof(float));
            ch->user_line_stride = (int32_t)row_bytes;
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
        }
        rv = exr_encoding_choose_default_routines(e, part, &enc);
        if (!rv) rv = exr_encoding_run(e, part, &enc);
        if (rv) break;
    }
    if (rv) st = exr_fail(ctx, path, &s, rv, "cannot encode the pixels");
done:
    if (inited) exr_encoding_destroy(e, &enc);
    if (e) {
        exr_result_t fr = exr_finish(&e);
        if (!st && fr) st = exr_fail(ctx, path, &s, fr, "cannot finish the file");
    }
    if (!st && fsync(s.fd) != 0) st = lx__error(ctx, LX_EIO, path, 0, "cannot write: %s", strerror(errno));
    if (close(s.fd) != 0 && !st) st = lx__error(ctx, LX_EIO, path, 0, "cannot write: %s", strerror(errno));
    if (!st && rename(tmp, path) != 0) st = lx__error(ctx, LX_EIO, path, 0, "cannot rename into place: %s", strerror(errno));
    if (st) unlink(tmp);
    free(tmp);
    return st;
}
