/* exr_private.h - OpenEXRCore plumbing shared by exr_io.c and spectral_exr.c: our own pread/pwrite
 * stream (so OpenEXR never prints), status mapping, atomic writing and chunk decoding/encoding.
 * Needs <openexr.h>, so only the EXR sources include it (radiance_private.h does not). */
#ifndef LX_EXR_PRIVATE_H
#define LX_EXR_PRIVATE_H

#include "radiance/radiance_private.h"

#include <openexr.h>

/* The user data of an OpenEXR context: the file and OpenEXR's last message. */
typedef struct lx__exr_stream {
    int fd;
    int werr;      /* errno of the first failed write (0: none) */
    lx__wfile wf;  /* writing: the atomic output file (core/file_write.c) */
    char msg[512]; /* the last message OpenEXR reported ("" when none) */
} lx__exr_stream;

/* Wires an OpenEXR initializer to s: the error handler that keeps OpenEXR's message in s->msg,
 * and pread read + fstat size callbacks (write = 0) or the pwrite write callback (write = 1).
 * s->fd must be open; init is reset to EXR_DEFAULT_CONTEXT_INITIALIZER first. */
void lx__exr_stream_init(lx__exr_stream *s, int write, exr_context_initializer_t *init);

/* Starts reading path through s (s->fd open for reading): *e, and *storage of part 0, which must
 * be scanline or tiled (deep: LX_EUNSUPPORTED with the message deep_msg). Errors name path and
 * what failed; *e may be set even then (the caller exr_finish-es it). */
lx_status lx__exr_read_begin(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t *e,
                             exr_storage_t *storage, const char *deep_msg);

/* The channel list of part 0 (at least one channel, else "no channels"). */
lx_status lx__exr_channels(lx_ctx *ctx, const char *path, const lx__exr_stream *s, exr_context_t e,
                           const exr_attr_chlist_t **cl);

/* Refuses a channel that is subsampled or holds integers (LX_EUNSUPPORTED naming it). */
lx_status lx__exr_check_channel(lx_ctx *ctx, const char *path, const exr_attr_chlist_entry_t *en);

/* Size in bytes of the file behind s (-1 when fstat fails). */
int64_t lx__exr_stream_size(const lx__exr_stream *s);

/* Records "what: OpenEXR's message" for path with the status that fits rv (no memory: LX_ENOMEM,
 * unimplemented feature: LX_EUNSUPPORTED, read/write/access: LX_EIO, else LX_EPARSE); returns it. */
lx_status lx__exr_fail(lx_ctx *ctx, const char *path, const lx__exr_stream *s, exr_result_t rv, const char *what);

/* Atomic writing (lx__wfile_open: a temporary file beside path, or a device written directly)
 * as s->fd. On failure records "cannot create" and returns LX_EIO (LX_ENOMEM). */
lx_status lx__exr_write_begin(lx_ctx *ctx, const char *path, lx__exr_stream *s);

/* Ends an atomic write begun by lx__exr_write_begin: finishes *e (when not NULL), fsyncs,
 * closes and renames into place when st is LX_OK and all that succeeds, else removes the
 * temporary file. A failed write is LX_EWRITE with the system's reason ("No space left on
 * device"). Returns st or the first failure. Destroy any encode pipeline before. */
lx_status lx__exr_write_end(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t *e, lx_status st);

/* Which slot (0 .. nc-1) of a pixel a file channel feeds, or -1 for none. */
typedef int (*lx__exr_slot_fn)(const char *channel_name, const void *user);

/* Reads every chunk of part 0 (scanline or tiled, one level) and decodes the channels that slot
 * maps into buf: nc floats per pixel, row stride row_px pixels, origin at the data window's corner.
 * Errors name path and what failed ("cannot read a tile", "cannot decode a chunk", ...). */
lx_status lx__exr_read_pixels(lx_ctx *ctx, const char *path, const lx__exr_stream *s, exr_context_t e,
                              exr_storage_t storage, const exr_attr_box2i_t *dw, float *buf, int row_px, int nc,
                              lx__exr_slot_fn slot, const void *user);

/* Encodes one chunk ci of part from src (nc floats per pixel, row stride row_px pixels, the chunk's
 * first pixel at x0, y0); slot gives each channel's slot (must be >= 0). *inited: the pipeline
 * enc is initialised (the caller destroys it). Returns OpenEXR's result. */
exr_result_t lx__exr_encode_chunk(exr_context_t e, int part, exr_encode_pipeline_t *enc, int *inited,
                                  const exr_chunk_info_t *ci, const float *src, int row_px, int x0, int y0, int nc,
                                  lx__exr_slot_fn slot, const void *user);

#endif /* LX_EXR_PRIVATE_H */
