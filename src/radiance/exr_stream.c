/* exr_stream.c - OpenEXRCore plumbing shared by exr_io.c and spectral_exr.c: pread/pwrite stream
 * callbacks that keep OpenEXR's messages for the context's error, atomic file writing, and the
 * chunk loops that decode into / encode from interleaved float pixels. */
#include "exr_private.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void on_error(exr_const_context_t ectx, exr_result_t code, const char *msg)
{
    void *ud = NULL;
    if (exr_get_user_data(ectx, &ud) == EXR_ERR_SUCCESS && ud)
        snprintf(((lx__exr_stream *)ud)->msg, sizeof ((lx__exr_stream *)ud)->msg, "%s (%s)", msg ? msg : "",
                 exr_get_error_code_as_string(code));
}

static int64_t s_read(exr_const_context_t ectx, void *ud, void *buf, uint64_t sz, uint64_t off,
                      exr_stream_error_func_ptr_t err)
{
    (void)ectx;
    (void)err;
    lx__exr_stream *s = ud;
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

int64_t lx__exr_stream_size(const lx__exr_stream *s)
{
    struct stat sb;
    return fstat(s->fd, &sb) == 0 ? (int64_t)sb.st_size : -1;
}

static int64_t s_size(exr_const_context_t ectx, void *ud)
{
    (void)ectx;
    return lx__exr_stream_size(ud);
}

static int64_t s_write(exr_const_context_t ectx, void *ud, const void *buf, uint64_t sz, uint64_t off,
                       exr_stream_error_func_ptr_t err)
{
    (void)ectx;
    (void)err;
    lx__exr_stream *s = ud;
    uint64_t put = 0;
    while (put < sz) {
        ssize_t r = pwrite(s->fd, (const char *)buf + put, (size_t)(sz - put), (off_t)(off + put));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) {
            if (!s->werr) s->werr = r < 0 ? errno : EIO;
            return -1;
        }
        put += (uint64_t)r;
    }
    return (int64_t)put;
}

void lx__exr_stream_init(lx__exr_stream *s, int write, exr_context_initializer_t *init)
{
    const exr_context_initializer_t def = EXR_DEFAULT_CONTEXT_INITIALIZER;
    *init = def;
    init->error_handler_fn = on_error;
    init->user_data = s;
    if (write) {
        init->write_fn = s_write;
    } else {
        init->read_fn = s_read;
        init->size_fn = s_size;
    }
}

lx_status lx__exr_fail(lx_ctx *ctx, const char *path, const lx__exr_stream *s, exr_result_t rv, const char *what)
{
    lx_status st = rv == EXR_ERR_OUT_OF_MEMORY ? LX_ENOMEM
                   : rv == EXR_ERR_FEATURE_NOT_IMPLEMENTED ? LX_EUNSUPPORTED
                   : (rv == EXR_ERR_READ_IO || rv == EXR_ERR_WRITE_IO || rv == EXR_ERR_FILE_ACCESS) ? LX_EIO
                                                                                                     : LX_EPARSE;
    return lx__error(ctx, st, path, 0, "%s: %s", what, s->msg[0] ? s->msg : exr_get_default_error_message(rv));
}

lx_status lx__exr_write_begin(lx_ctx *ctx, const char *path, lx__exr_stream *s)
{
    s->msg[0] = '\0';
    s->werr = 0;
    lx_status st = lx__wfile_open(ctx, path, &s->wf);
    s->fd = s->wf.fd;
    return st;
}

lx_status lx__exr_write_end(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t *e, lx_status st)
{
    if (e && *e) {
        exr_result_t fr = exr_finish(e);
        if (!st && fr) st = lx__exr_fail(ctx, path, s, fr, "cannot finish the file");
    }
    if (s->werr) st = lx__error(ctx, LX_EWRITE, path, 0, "%s", strerror(s->werr));
    return lx__wfile_close(ctx, &s->wf, st);
}

lx_status lx__exr_read_begin(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t *e,
                             exr_storage_t *storage, const char *deep_msg)
{
    exr_context_initializer_t init;
    lx__exr_stream_init(s, 0, &init);
    exr_result_t rv = exr_start_read(e, path, &init);
    if (rv) return lx__exr_fail(ctx, path, s, rv, "not a readable OpenEXR file");
    if ((rv = exr_get_storage(*e, 0, storage))) return lx__exr_fail(ctx, path, s, rv, "cannot read the header");
    if (*storage != EXR_STORAGE_SCANLINE && *storage != EXR_STORAGE_TILED)
        return lx__error(ctx, LX_EUNSUPPORTED, path, 0, "%s", deep_msg);
    return LX_OK;
}

lx_status lx__exr_channels(lx_ctx *ctx, const char *path, const lx__exr_stream *s, exr_context_t e,
                           const exr_attr_chlist_t **cl)
{
    *cl = NULL;
    exr_result_t rv = exr_get_channels(e, 0, cl);
    if (rv || !*cl || (*cl)->num_channels < 1)
        return lx__exr_fail(ctx, path, s, rv ? rv : EXR_ERR_MISSING_REQ_ATTR, "no channels");
    return LX_OK;
}

lx_status lx__exr_check_channel(lx_ctx *ctx, const char *path, const exr_attr_chlist_entry_t *en)
{
    if (en->x_sampling != 1 || en->y_sampling != 1)
        return lx__error(ctx, LX_EUNSUPPORTED, path, 0, "channel %s is subsampled (%dx%d)", en->name.str,
                         en->x_sampling, en->y_sampling);
    if (en->pixel_type == EXR_PIXEL_UINT)
        return lx__error(ctx, LX_EUNSUPPORTED, path, 0, "channel %s holds integers, not radiance", en->name.str);
    return LX_OK;
}

/* The decoder's buffers, the decompressed one filled with 0xff bytes (NaN in half and float):
 * OpenEXRCore 3.1 does not report every compressed chunk that decodes short (an RLE chunk of a
 * fuzzed file filled part of it), so what it leaves unwritten reads as NaN, which the readers
 * refuse as a non-finite value, instead of uninitialised memory or the previous chunk's pixels. */
static void *decode_alloc(exr_transcoding_pipeline_buffer_id_t id, size_t n)
{
    void *p = lx__alloc(n ? n : 1);
    if (p && id == EXR_TRANSCODE_BUFFER_UNPACKED) memset(p, 0xff, n);
    return p;
}

static void decode_free(exr_transcoding_pipeline_buffer_id_t id, void *p)
{
    (void)id;
    lx__free(p);
}

/* Decodes one chunk into buf (see lx__exr_read_pixels), the chunk's first pixel at x0, y0. */
static lx_status decode_chunk(lx_ctx *ctx, const char *path, const lx__exr_stream *s, exr_context_t e,
                              exr_decode_pipeline_t *dec, int *inited, const exr_chunk_info_t *ci, float *buf,
                              int row_px, int x0, int y0, int nc, lx__exr_slot_fn slot_of, const void *user)
{
    exr_result_t rv = *inited ? exr_decoding_update(e, 0, ci, dec) : exr_decoding_initialize(e, 0, ci, dec);
    if (rv) return lx__exr_fail(ctx, path, s, rv, "cannot decode a chunk");
    *inited = 1;
    for (int k = 0; k < dec->channel_count; k++) {
        exr_coding_channel_info_t *ch = &dec->channels[k];
        int slot = slot_of(ch->channel_name, user);
        if (slot < 0 || ch->height == 0) {
            ch->decode_to_ptr = NULL;
            continue;
        }
        ch->decode_to_ptr = (uint8_t *)(buf + ((size_t)y0 * row_px + x0) * nc + slot);
        ch->user_pixel_stride = (int32_t)(nc * sizeof(float));
        ch->user_line_stride = (int32_t)((size_t)row_px * nc * sizeof(float));
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
    }
    rv = exr_decoding_choose_default_routines(e, 0, dec);
    dec->alloc_fn = decode_alloc;
    dec->free_fn = decode_free;
    if (dec->unpacked_buffer && dec->unpacked_alloc_size) memset(dec->unpacked_buffer, 0xff, dec->unpacked_alloc_size);
    if (!rv) rv = exr_decoding_run(e, 0, dec);
    if (rv) return lx__exr_fail(ctx, path, s, rv, "cannot decode a chunk");
    return LX_OK;
}

lx_status lx__exr_read_pixels(lx_ctx *ctx, const char *path, const lx__exr_stream *s, exr_context_t e,
                              exr_storage_t storage, const exr_attr_box2i_t *dw, float *buf, int row_px, int nc,
                              lx__exr_slot_fn slot, const void *user)
{
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int inited = 0;
    lx_status st = LX_OK;
    exr_result_t rv;
    exr_chunk_info_t ci;
    if (storage == EXR_STORAGE_SCANLINE) {
        int32_t lpc = 1;
        exr_get_scanlines_per_chunk(e, 0, &lpc);
        if (lpc < 1) lpc = 1;
        for (long y = dw->min.y; y <= dw->max.y && !st; y += lpc) {
            if ((rv = exr_read_scanline_chunk_info(e, 0, (int)y, &ci))) {
                st = lx__exr_fail(ctx, path, s, rv, "cannot read a scanline chunk");
                break;
            }
            st = decode_chunk(ctx, path, s, e, &dec, &inited, &ci, buf, row_px, 0, (int)(ci.start_y - dw->min.y), nc,
                              slot, user);
        }
    } else {
        uint32_t tw = 0, th = 0;
        exr_tile_level_mode_t lm;
        exr_tile_round_mode_t rm;
        int32_t lw = 0, lh = 0;
        if ((rv = exr_get_tile_descriptor(e, 0, &tw, &th, &lm, &rm)) || (rv = exr_get_level_sizes(e, 0, 0, 0, &lw, &lh)) ||
            tw == 0 || th == 0)
            return lx__exr_fail(ctx, path, s, rv ? rv : EXR_ERR_INVALID_ATTR, "invalid tile description");
        long ntx = (lw + (long)tw - 1) / tw, nty = (lh + (long)th - 1) / th;
        for (long ty = 0; ty < nty && !st; ty++)
            for (long tx = 0; tx < ntx && !st; tx++) {
                if ((rv = exr_read_tile_chunk_info(e, 0, (int)tx, (int)ty, 0, 0, &ci))) {
                    st = lx__exr_fail(ctx, path, s, rv, "cannot read a tile");
                    break;
                }
                st = decode_chunk(ctx, path, s, e, &dec, &inited, &ci, buf, row_px, (int)(tx * tw), (int)(ty * th), nc,
                                  slot, user);
            }
    }
    if (inited) exr_decoding_destroy(e, &dec);
    return st;
}

exr_result_t lx__exr_encode_chunk(exr_context_t e, int part, exr_encode_pipeline_t *enc, int *inited,
                                  const exr_chunk_info_t *ci, const float *src, int row_px, int x0, int y0, int nc,
                                  lx__exr_slot_fn slot, const void *user)
{
    exr_result_t rv = *inited ? exr_encoding_update(e, part, ci, enc) : exr_encoding_initialize(e, part, ci, enc);
    if (rv) return rv;
    *inited = 1;
    for (int q = 0; q < enc->channel_count; q++) {
        exr_coding_channel_info_t *ch = &enc->channels[q];
        ch->encode_from_ptr = (const uint8_t *)(src + ((size_t)y0 * row_px + x0) * nc + slot(ch->channel_name, user));
        ch->user_pixel_stride = (int32_t)(nc * sizeof(float));
        ch->user_line_stride = (int32_t)((size_t)row_px * nc * sizeof(float));
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = 4;
    }
    rv = exr_encoding_choose_default_routines(e, part, enc);
    if (!rv) rv = exr_encoding_run(e, part, enc);
    return rv;
}
