/* spectral_exr.c - spectral OpenEXR images (Fichet et al. 2021 layout: S0.<wavelength>nm channels)
 * integrated per pixel into absolute CIE XYZ with the batch path, written as an XYZ float EXR and
 * an sRGB preview PNG. Reads and writes through OpenEXRCore directly (exr_io.c reads RGB/Y maps). */
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

#define KM_2 683.002  /* lm/W, CIE 015:2018, as lx_spd_colorimetry */
#define KM_10 683.599 /* lm/W, 10 deg observer */
#define CHUNK_PIX 65536

int lx__spectral_channel(const char *name, int *kind, double *lambda_nm)
{
    int k;
    const char *p;
    if (name[0] == 'S' && name[1] >= '0' && name[1] <= '3' && name[2] == '.') k = name[1] - '0', p = name + 3;
    else if (name[0] == 'T' && name[1] == '.') k = 4, p = name + 2;
    else return -1;
    const char *e = p;
    while ((*e >= '0' && *e <= '9') || *e == ',' || *e == '.') e++;
    if (e == p) return -1;
    double v;
    const char *end = lx__parse_double_ex(p, e, ',', &v);
    if (!end || end != e || !(v > 0) || !isfinite(v)) return -1;
    static const struct {
        const char *unit;
        double to_nm;
    } units[] = {{"nm", 1.0}, {"um", 1e3}, {"mm", 1e6}, {"m", 1e9}, {"pm", 1e-3}};
    for (size_t u = 0; u < sizeof units / sizeof *units; u++)
        if (!strcmp(e, units[u].unit)) {
            *kind = k;
            *lambda_nm = v * units[u].to_nm;
            return 0;
        }
    return -1; /* frequency units (Hz) and anything else */
}

typedef struct stream {
    int fd;
    char msg[512];
} stream;

static void on_error(exr_const_context_t ectx, exr_result_t code, const char *msg)
{
    void *ud = NULL;
    if (exr_get_user_data(ectx, &ud) == EXR_ERR_SUCCESS && ud)
        snprintf(((stream *)ud)->msg, sizeof ((stream *)ud)->msg, "%s (%s)", msg ? msg : "",
                 exr_get_error_code_as_string(code));
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

static lx_status fail(lx_ctx *ctx, const char *path, const stream *s, exr_result_t rv, const char *what)
{
    lx_status st = rv == EXR_ERR_OUT_OF_MEMORY ? LX_ENOMEM
                   : rv == EXR_ERR_FEATURE_NOT_IMPLEMENTED ? LX_EUNSUPPORTED
                   : (rv == EXR_ERR_READ_IO || rv == EXR_ERR_WRITE_IO || rv == EXR_ERR_FILE_ACCESS) ? LX_EIO
                                                                                                     : LX_EPARSE;
    return lx__error(ctx, st, path, 0, "%s: %s", what, s->msg[0] ? s->msg : exr_get_default_error_message(rv));
}

typedef struct chan {
    const char *name;
    double lambda_nm;
} chan;

static int cmp_chan(const void *a, const void *b)
{
    double x = ((const chan *)a)->lambda_nm, y = ((const chan *)b)->lambda_nm;
    return (x > y) - (x < y);
}

/* decodes one chunk: the S0 channels into buf (nl floats per pixel, row stride W pixels) */
static lx_status decode(lx_ctx *ctx, const char *path, stream *s, exr_context_t e, exr_decode_pipeline_t *dec,
                        int *inited, const exr_chunk_info_t *ci, float *buf, int W, int x0, int y0, const chan *ch,
                        int nl)
{
    exr_result_t rv = *inited ? exr_decoding_update(e, 0, ci, dec) : exr_decoding_initialize(e, 0, ci, dec);
    if (rv) return fail(ctx, path, s, rv, "cannot decode a chunk");
    *inited = 1;
    for (int k = 0; k < dec->channel_count; k++) {
        exr_coding_channel_info_t *c = &dec->channels[k];
        int slot = -1;
        for (int q = 0; q < nl && slot < 0; q++)
            if (!strcmp(ch[q].name, c->channel_name)) slot = q;
        if (slot < 0 || c->height == 0) {
            c->decode_to_ptr = NULL;
            continue;
        }
        c->decode_to_ptr = (uint8_t *)(buf + ((size_t)y0 * W + x0) * nl + slot);
        c->user_pixel_stride = (int32_t)(nl * sizeof(float));
        c->user_line_stride = (int32_t)((size_t)W * nl * sizeof(float));
        c->user_data_type = EXR_PIXEL_FLOAT;
        c->user_bytes_per_element = 4;
    }
    rv = exr_decoding_choose_default_routines(e, 0, dec);
    if (!rv) rv = exr_decoding_run(e, 0, dec);
    if (rv) return fail(ctx, path, s, rv, "cannot decode a chunk");
    return LX_OK;
}

/* reads the S0 channels: *data (W x H x nl floats), *ch (nl channels by increasing wavelength) */
static lx_status read_spectral(lx_ctx *ctx, const char *path, float **data, chan **chans, int *nl_out, int *W_out,
                               int *H_out, int *npol)
{
    stream s = {.fd = -1};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = &s;
    exr_context_t e = NULL;
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    int inited = 0, nl = 0, nrefl = 0;
    float *buf = NULL;
    chan *ch = NULL;
    lx_status st = LX_OK;
    exr_result_t rv = exr_start_read(&e, path, &init);
    if (rv) {
        st = fail(ctx, path, &s, rv, "not a readable OpenEXR file");
        goto done;
    }
    exr_storage_t storage;
    if ((rv = exr_get_storage(e, 0, &storage))) {
        st = fail(ctx, path, &s, rv, "cannot read the header");
        goto done;
    }
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
        st = lx__error(ctx, LX_EUNSUPPORTED, path, 0, "deep images are not supported");
        goto done;
    }
    const exr_attr_chlist_t *cl = NULL;
    if ((rv = exr_get_channels(e, 0, &cl)) || !cl || cl->num_channels < 1) {
        st = fail(ctx, path, &s, rv ? rv : EXR_ERR_MISSING_REQ_ATTR, "no channels");
        goto done;
    }
    ch = calloc((size_t)cl->num_channels, sizeof *ch);
    if (!ch) {
        st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
        goto done;
    }
    *npol = 0;
    for (int k = 0; k < cl->num_channels; k++) {
        const exr_attr_chlist_entry_t *en = &cl->entries[k];
        int kind;
        double lam;
        if (lx__spectral_channel(en->name.str, &kind, &lam) != 0) continue;
        if (kind == 4) {
            nrefl++;
            continue;
        }
        if (kind != 0) {
            (*npol)++;
            continue;
        }
        if (en->x_sampling != 1 || en->y_sampling != 1) {
            st = lx__error(ctx, LX_EUNSUPPORTED, path, 0, "channel %s is subsampled (%dx%d)", en->name.str,
                           en->x_sampling, en->y_sampling);
            goto done;
        }
        if (en->pixel_type == EXR_PIXEL_UINT) {
            st = lx__error(ctx, LX_EUNSUPPORTED, path, 0, "channel %s holds integers, not radiance", en->name.str);
            goto done;
        }
        ch[nl].name = en->name.str;
        ch[nl++].lambda_nm = lam;
    }
    if (nl == 0) {
        if (nrefl)
            st = lx__error(ctx, LX_EUNSUPPORTED, path, 0,
                           "only reflective channels (T.<wavelength>nm, %d of them): reflectance images are not "
                           "supported; luxcalc integrates emissive S0.<wavelength>nm channels",
                           nrefl);
        else
            st = lx__error(ctx, LX_EPARSE, path, 0,
                           "no spectral channels named S0.<wavelength>nm (Fichet et al. 2021 layout; first channel '%s')",
                           cl->entries[0].name.str);
        goto done;
    }
    if (nl < 2) {
        st = lx__error(ctx, LX_EPARSE, path, 0, "only one spectral channel (%s): a spectrum needs at least two", ch[0].name);
        goto done;
    }
    qsort(ch, (size_t)nl, sizeof *ch, cmp_chan);
    for (int k = 1; k < nl; k++)
        if (ch[k].lambda_nm == ch[k - 1].lambda_nm) {
            st = lx__error(ctx, LX_EPARSE, path, 0, "channels %s and %s name the same wavelength", ch[k - 1].name, ch[k].name);
            goto done;
        }
    exr_attr_box2i_t dw;
    if ((rv = exr_get_data_window(e, 0, &dw))) {
        st = fail(ctx, path, &s, rv, "no data window");
        goto done;
    }
    long W = (long)dw.max.x - dw.min.x + 1, H = (long)dw.max.y - dw.min.y + 1;
    if (W < 1 || H < 1 || (double)W * H * nl > 4e9) {
        st = lx__error(ctx, LX_EPARSE, path, 0, "invalid or too large data window %ldx%ld x %d channels", W, H, nl);
        goto done;
    }
    buf = calloc((size_t)W * H * nl, sizeof *buf);
    if (!buf) {
        st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory for %ldx%ld pixels x %d channels", W, H, nl);
        goto done;
    }
    exr_chunk_info_t ci;
    if (storage == EXR_STORAGE_SCANLINE) {
        int32_t lpc = 1;
        exr_get_scanlines_per_chunk(e, 0, &lpc);
        if (lpc < 1) lpc = 1;
        for (long y = dw.min.y; y <= dw.max.y && !st; y += lpc) {
            if ((rv = exr_read_scanline_chunk_info(e, 0, (int)y, &ci))) {
                st = fail(ctx, path, &s, rv, "cannot read a scanline chunk");
                break;
            }
            st = decode(ctx, path, &s, e, &dec, &inited, &ci, buf, (int)W, 0, (int)(ci.start_y - dw.min.y), ch, nl);
        }
    } else {
        uint32_t tw = 0, th = 0;
        exr_tile_level_mode_t lm;
        exr_tile_round_mode_t rm;
        int32_t lw = 0, lh = 0;
        if ((rv = exr_get_tile_descriptor(e, 0, &tw, &th, &lm, &rm)) || (rv = exr_get_level_sizes(e, 0, 0, 0, &lw, &lh)) ||
            tw == 0 || th == 0) {
            st = fail(ctx, path, &s, rv ? rv : EXR_ERR_INVALID_ATTR, "invalid tile description");
            goto done;
        }
        long ntx = (lw + (long)tw - 1) / tw, nty = (lh + (long)th - 1) / th;
        for (long ty = 0; ty < nty && !st; ty++)
            for (long tx = 0; tx < ntx && !st; tx++) {
                if ((rv = exr_read_tile_chunk_info(e, 0, (int)tx, (int)ty, 0, 0, &ci))) {
                    st = fail(ctx, path, &s, rv, "cannot read a tile");
                    break;
                }
                st = decode(ctx, path, &s, e, &dec, &inited, &ci, buf, (int)W, (int)(tx * tw), (int)(ty * th), ch, nl);
            }
    }
    if (st) goto done;
    for (size_t k = 0; k < (size_t)W * H * nl; k++)
        if (!isfinite(buf[k])) {
            size_t p = k / (size_t)nl;
            st = lx__error(ctx, LX_EPARSE, path, 0, "pixel (%zu, %zu), channel %s: value is not finite", p % (size_t)W,
                           p / (size_t)W, ch[k % (size_t)nl].name);
            goto done;
        }
    *W_out = (int)W;
    *H_out = (int)H;
done:
    if (inited) exr_decoding_destroy(e, &dec);
    /* channel names point into the header, which exr_finish frees: copy them first */
    if (!st) {
        size_t tot = 0;
        for (int k = 0; k < nl; k++) tot += strlen(ch[k].name) + 1;
        chan *cp = malloc(sizeof *cp * (size_t)nl + tot);
        if (!cp) {
            st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
        } else {
            char *names = (char *)(cp + nl);
            for (int k = 0; k < nl; k++) {
                size_t n = strlen(ch[k].name) + 1;
                memcpy(names, ch[k].name, n);
                cp[k].name = names;
                cp[k].lambda_nm = ch[k].lambda_nm;
                names += n;
            }
            *chans = cp;
            *data = buf;
            *nl_out = nl;
            buf = NULL;
        }
    }
    if (e) exr_finish(&e);
    free(ch);
    free(buf);
    return st;
}

void lx_xyz_image_free(lx_xyz_image *img)
{
    if (!img) return;
    free(img->xyz);
    free(img->lambda_nm);
    free(img);
}

lx_status lx_spectral_exr_read_xyz(lx_ctx *ctx, const char *path, lx_observer observer, lx_batch_opts *opts,
                                   lx_xyz_image **out)
{
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spectral_exr_read_xyz: NULL argument");
    *out = NULL;
    if (observer != LX_OBSERVER_2 && observer != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spectral_exr_read_xyz: observer must be 2 or 10");
    int fd = open(path, O_RDONLY);
    if (fd < 0) return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(errno));
    close(fd);
    float *data = NULL;
    chan *ch = NULL;
    int nl = 0, W = 0, H = 0, npol = 0;
    lx_status st = read_spectral(ctx, path, &data, &ch, &nl, &W, &H, &npol);
    if (st) return st;
    lx_xyz_image *img = calloc(1, sizeof *img);
    size_t npix = (size_t)W * H;
    double *res = malloc(sizeof(double) * 3 * (npix < CHUNK_PIX ? npix : CHUNK_PIX));
    if (img) {
        img->xyz = malloc(sizeof(double) * 3 * npix);
        img->lambda_nm = malloc(sizeof(double) * (size_t)nl);
    }
    if (!img || !res || !img->xyz || !img->lambda_nm) {
        st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
        goto done;
    }
    img->width = W, img->height = H, img->n_lambda = (size_t)nl, img->polarised_ignored = npol;
    for (int k = 0; k < nl; k++) img->lambda_nm[k] = ch[k].lambda_nm;
    const double *lam = img->lambda_nm;
    double step = (lam[nl - 1] - lam[0]) / (nl - 1);
    int uniform = 1;
    for (int k = 1; k < nl; k++)
        if (fabs(lam[k] - lam[k - 1] - step) > 1e-6 * step) uniform = 0;
    img->resampled = !uniform;
    const lx_function f2[3] = {LX_FN_XBAR_2, LX_FN_YBAR_2, LX_FN_ZBAR_2},
                      f10[3] = {LX_FN_XBAR_10, LX_FN_YBAR_10, LX_FN_ZBAR_10};
    const lx_function *fns = observer == LX_OBSERVER_10 ? f10 : f2;
    const double km = observer == LX_OBSERVER_10 ? KM_10 : KM_2;
    /* non-uniform wavelengths: resample every pixel to 1 nm over the whole range first */
    double g0 = floor(lam[0]), g1 = ceil(lam[nl - 1]);
    size_t ng = (size_t)(g1 - g0) + 1;
    double *rl = NULL, *rv = NULL, *rg = NULL;
    size_t *roff = NULL, *rn = NULL;
    if (!uniform) {
        size_t m = npix < CHUNK_PIX / 16 ? npix : CHUNK_PIX / 16;
        rl = malloc(sizeof(double) * m * (size_t)nl);
        rv = malloc(sizeof(double) * m * (size_t)nl);
        rg = malloc(sizeof(double) * m * ng);
        roff = malloc(sizeof(size_t) * m);
        rn = malloc(sizeof(size_t) * m);
        if (!rl || !rv || !rg || !roff || !rn) {
            st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
            goto done_r;
        }
    }
    size_t chunk = uniform ? CHUNK_PIX : CHUNK_PIX / 16;
    for (size_t p0 = 0; p0 < npix && !st; p0 += chunk) {
        size_t m = npix - p0 < chunk ? npix - p0 : chunk;
        lx_batch b;
        if (uniform) {
            b = (lx_batch){m, (size_t)nl, 0, lam[0], step, LX_F32, data + p0 * (size_t)nl};
        } else {
            for (size_t i = 0; i < m; i++) {
                roff[i] = i * (size_t)nl;
                rn[i] = (size_t)nl;
                for (int k = 0; k < nl; k++) {
                    rl[i * nl + k] = lam[k];
                    rv[i * nl + k] = data[(p0 + i) * nl + k];
                }
            }
            b = (lx_batch){m, ng, 0, g0, 1.0, LX_F64, rg};
            if ((st = lx_batch_resample(ctx, m, rl, rv, roff, rn, &b, opts))) break;
        }
        if ((st = lx_batch_integrate(ctx, &b, fns, 3, opts, res))) break;
        for (size_t i = 0; i < 3 * m; i++) img->xyz[3 * p0 + i] = km * res[i];
    }
done_r:
    free(rl), free(rv), free(rg), free(roff), free(rn);
done:
    free(res);
    free(data);
    free(ch);
    if (st) lx_xyz_image_free(img);
    else *out = img;
    return st;
}

lx_status lx_xyz_exr_write(lx_ctx *ctx, const char *path, const lx_xyz_image *img)
{
    if (!path || !img || !img->xyz) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_xyz_exr_write: NULL argument");
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
    int inited = 0, part = 0, W = img->width, H = img->height;
    lx_status st = LX_OK;
    size_t npix = (size_t)W * H;
    float *f = malloc(sizeof(float) * 3 * (npix ? npix : 1));
    if (!f) {
        close(s.fd);
        unlink(tmp);
        free(tmp);
        return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
    }
    for (size_t i = 0; i < 3 * npix; i++) f[i] = (float)img->xyz[i];
    exr_result_t rv = exr_start_write(&e, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (!rv) rv = exr_add_part(e, "", EXR_STORAGE_SCANLINE, &part);
    if (!rv) rv = exr_initialize_required_attr_simple(e, part, W, H, EXR_COMPRESSION_ZIP);
    static const char *names[3] = {"X", "Y", "Z"};
    for (int c = 0; c < 3 && !rv; c++) rv = exr_add_channel(e, part, names[c], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    if (!rv) rv = exr_write_header(e);
    if (rv) {
        st = fail(ctx, path, &s, rv, "cannot write the header");
        goto done;
    }
    int32_t lpc = 1;
    exr_get_scanlines_per_chunk(e, part, &lpc);
    if (lpc < 1) lpc = 1;
    for (long y0 = 0; y0 < H; y0 += lpc) {
        exr_chunk_info_t ci;
        rv = exr_write_scanline_chunk_info(e, part, (int)y0, &ci);
        if (!rv) rv = inited ? exr_encoding_update(e, part, &ci, &enc) : exr_encoding_initialize(e, part, &ci, &enc);
        if (rv) break;
        inited = 1;
        for (int q = 0; q < enc.channel_count; q++) {
            exr_coding_channel_info_t *c = &enc.channels[q];
            int slot = c->channel_name[0] == 'X' ? 0 : c->channel_name[0] == 'Y' ? 1 : 2;
            c->encode_from_ptr = (const uint8_t *)(f + (size_t)y0 * W * 3 + slot);
            c->user_pixel_stride = (int32_t)(3 * sizeof(float));
            c->user_line_stride = (int32_t)((size_t)W * 3 * sizeof(float));
            c->user_data_type = EXR_PIXEL_FLOAT;
            c->user_bytes_per_element = 4;
        }
        rv = exr_encoding_choose_default_routines(e, part, &enc);
        if (!rv) rv = exr_encoding_run(e, part, &enc);
        if (rv) break;
    }
    if (rv) st = fail(ctx, path, &s, rv, "cannot encode the pixels");
done:
    if (inited) exr_encoding_destroy(e, &enc);
    if (e) {
        exr_result_t fr = exr_finish(&e);
        if (!st && fr) st = fail(ctx, path, &s, fr, "cannot finish the file");
    }
    if (!st && fsync(s.fd) != 0) st = lx__error(ctx, LX_EIO, path, 0, "cannot write: %s", strerror(errno));
    if (close(s.fd) != 0 && !st) st = lx__error(ctx, LX_EIO, path, 0, "cannot write: %s", strerror(errno));
    if (!st && rename(tmp, path) != 0) st = lx__error(ctx, LX_EIO, path, 0, "cannot rename into place: %s", strerror(errno));
    if (st) unlink(tmp);
    free(tmp);
    free(f);
    return st;
}

lx_status lx_xyz_png_write(lx_ctx *ctx, const char *path, const lx_xyz_image *img)
{
    if (!path || !img || !img->xyz) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_xyz_png_write: NULL argument");
    /* XYZ -> linear sRGB (IEC 61966-2-1); lx__canvas_tonemap does exposure, tone curve, encoding */
    static const double M[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    size_t npix = (size_t)img->width * img->height;
    float *rgb = malloc(sizeof(float) * 3 * npix);
    if (!rgb) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
    for (size_t p = 0; p < npix; p++)
        for (int i = 0; i < 3; i++) {
            const double *q = img->xyz + 3 * p;
            rgb[3 * p + i] = (float)(M[i][0] * q[0] + M[i][1] * q[1] + M[i][2] * q[2]);
        }
    int w = img->width, h = img->height;
    if (w < 256) {
        int s = (256 + w - 1) / w;
        w *= s, h *= s;
    }
    if (w > 4096) h = (int)((long)h * 4096 / w), w = 4096;
    if (h > 4096) w = (int)((long)w * 4096 / h), h = 4096;
    if (w < 1) w = 1;
    if (h < 1) h = 1;
    static const unsigned char black[3] = {0, 0, 0};
    lx__canvas c;
    lx_status st = lx__canvas_init(ctx, &c, w, h, black);
    if (!st) {
        lx__canvas_tonemap(&c, 0, 0, w, h, rgb, 3, img->width, img->height);
        st = lx__canvas_write_png(ctx, &c, path);
    }
    lx__canvas_free(&c);
    free(rgb);
    return st;
}
