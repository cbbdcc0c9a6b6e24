/* spectral_exr.c - spectral OpenEXR images (Fichet et al. 2021 layout: S0.<wavelength>nm channels)
 * integrated per pixel into absolute CIE XYZ with the batch path, written as an XYZ float EXR and
 * an sRGB preview PNG. Reads and writes through OpenEXRCore with the stream of exr_stream.c
 * (exr_io.c reads RGB/Y maps). */
#include "exr_private.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

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

typedef struct chan {
    const char *name;
    double lambda_nm;
} chan;

static int cmp_chan(const void *a, const void *b)
{
    double x = ((const chan *)a)->lambda_nm, y = ((const chan *)b)->lambda_nm;
    return (x > y) - (x < y);
}

/* lx__exr_slot_fn of reading: user points to the S0 channels; a channel's slot is its index there */
typedef struct chan_set {
    const chan *ch;
    int nl;
} chan_set;

static int read_slot(const char *name, const void *user)
{
    const chan_set *cs = user;
    for (int q = 0; q < cs->nl; q++)
        if (!strcmp(cs->ch[q].name, name)) return q;
    return -1;
}

/* lx__exr_slot_fn of writing: X, Y, Z */
static int xyz_slot(const char *name, const void *user)
{
    (void)user;
    return name[0] == 'X' ? 0 : name[0] == 'Y' ? 1 : 2;
}

/* The emissive S0 channels of the channel list into ch (room for every channel; names point into
 * the header), sorted by wavelength, at least two and no wavelength twice; *npol counts the S1-S3
 * channels left out. Reflective T. channels alone are LX_EUNSUPPORTED. */
static lx_status pick_s0_channels(lx_ctx *ctx, const char *path, const exr_attr_chlist_t *cl, chan *ch, int *nl_out,
                                  int *npol)
{
    int nl = 0, nrefl = 0;
    lx_status st;
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
        if ((st = lx__exr_check_channel(ctx, path, en))) return st;
        ch[nl].name = en->name.str;
        ch[nl++].lambda_nm = lam;
    }
    *nl_out = nl;
    if (nl == 0) {
        if (nrefl)
            return lx__error(ctx, LX_EUNSUPPORTED, path, 0,
                             "only reflective channels (T.<wavelength>nm, %d of them): reflectance images are not "
                             "supported; luxcalc integrates emissive S0.<wavelength>nm channels",
                             nrefl);
        return lx__error(ctx, LX_EPARSE, path, 0,
                         "no spectral channels named S0.<wavelength>nm (Fichet et al. 2021 layout; first channel '%s')",
                         cl->entries[0].name.str);
    }
    if (nl < 2)
        return lx__error(ctx, LX_EPARSE, path, 0, "only one spectral channel (%s): a spectrum needs at least two",
                         ch[0].name);
    qsort(ch, (size_t)nl, sizeof *ch, cmp_chan);
    for (int k = 1; k < nl; k++)
        if (ch[k].lambda_nm == ch[k - 1].lambda_nm)
            return lx__error(ctx, LX_EPARSE, path, 0, "channels %s and %s name the same wavelength", ch[k - 1].name,
                             ch[k].name);
    return LX_OK;
}

/* The data window (*dw, W x H pixels), checked against the value limit and, as an untrusted
 * count, against the size of the file before anything is sized (and timed) by it. */
static lx_status data_window(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t e, int nl,
                             exr_attr_box2i_t *dw, long *W_out, long *H_out)
{
    exr_result_t rv;
    if ((rv = exr_get_data_window(e, 0, dw))) return lx__exr_fail(ctx, path, s, rv, "no data window");
    long W = (long)dw->max.x - dw->min.x + 1, H = (long)dw->max.y - dw->min.y + 1;
    if (W < 1 || H < 1) return lx__error(ctx, LX_EPARSE, path, 0, "invalid data window %ldx%ld", W, H);
    if ((double)W * H * nl > LX__SPEXR_MAX_VALUES) {
        char lim_s[48];
        lx__fmt_magnitude(lim_s, sizeof lim_s, LX__SPEXR_MAX_VALUES);
        return lx__error(ctx, LX_EPARSE, path, 0, "data window %ldx%ld x %d channels over the limit of %s values", W, H,
                         nl, lim_s);
    }
    /* 1M values, or 64 values per byte of file, beyond what compression reaches on real spectra (a
     * 855-byte file declaring 5.5 Mpixel of zeros took seconds to resample) */
    struct stat sb;
    double fsize = fstat(s->fd, &sb) == 0 ? (double)sb.st_size : 0;
    if ((double)W * H * nl > LX__SPEXR_VALUES_FREE + LX__SPEXR_VALUES_PER_BYTE * fsize)
        return lx__error(ctx, LX_EPARSE, path, 0, "data window %ldx%ld x %d channels too large for a file of %.0f bytes",
                         W, H, nl, fsize);
    *W_out = W;
    *H_out = H;
    return LX_OK;
}

/* Every value of the W x nl-channel pixels of buf (n values) is finite. */
static lx_status check_finite(lx_ctx *ctx, const char *path, const float *buf, size_t n, long W, const chan *ch,
                              int nl)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(buf[k])) {
            size_t p = k / (size_t)nl;
            return lx__error(ctx, LX_EPARSE, path, 0, "pixel (%zu, %zu), channel %s: value is not finite (NaN, infinite, or missing from a chunk that decoded short)", p % (size_t)W,
                             p / (size_t)W, ch[k % (size_t)nl].name);
        }
    return LX_OK;
}

/* A copy of the nl channels whose names live in the same block (one free()): the names of ch point
 * into the header, which exr_finish frees. */
static lx_status copy_channels(lx_ctx *ctx, const char *path, const chan *ch, int nl, chan **out)
{
    size_t tot = 0;
    for (int k = 0; k < nl; k++) tot += strlen(ch[k].name) + 1;
    chan *cp = lx__alloc(sizeof *cp * (size_t)nl + tot);
    if (!cp) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
    char *names = (char *)(cp + nl);
    for (int k = 0; k < nl; k++) {
        size_t n = strlen(ch[k].name) + 1;
        memcpy(names, ch[k].name, n);
        cp[k].name = names;
        cp[k].lambda_nm = ch[k].lambda_nm;
        names += n;
    }
    *out = cp;
    return LX_OK;
}

/* The pixels of the S0 channels ch (nl of them) of an open file into a new buffer *buf_out
 * (W x H x nl floats, the caller frees it), every value finite. */
static lx_status read_s0_pixels(lx_ctx *ctx, const char *path, lx__exr_stream *s, exr_context_t e,
                                exr_storage_t storage, const chan *ch, int nl, float **buf_out, int *W_out, int *H_out)
{
    exr_attr_box2i_t dw;
    long W = 0, H = 0;
    lx_status st = data_window(ctx, path, s, e, nl, &dw, &W, &H);
    if (st) return st;
    float *buf = lx__calloc((size_t)W * H * nl, sizeof *buf);
    if (!buf) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory for %ldx%ld pixels x %d channels", W, H, nl);
    const chan_set cs = {ch, nl};
    st = lx__exr_read_pixels(ctx, path, s, e, storage, &dw, buf, (int)W, nl, read_slot, &cs);
    if (!st) st = check_finite(ctx, path, buf, (size_t)W * H * nl, W, ch, nl);
    if (st) {
        lx__free(buf);
        return st;
    }
    *buf_out = buf;
    *W_out = (int)W;
    *H_out = (int)H;
    return LX_OK;
}

/* reads the S0 channels: *data (W x H x nl floats), *ch (nl channels by increasing wavelength) */
static lx_status read_spectral(lx_ctx *ctx, const char *path, float **data, chan **chans, int *nl_out, int *W_out,
                               int *H_out, int *npol)
{
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode))
        return lx__error(ctx, LX_EIO, path, 0, "cannot read: not a regular file (OpenEXR files are read by seeking)");
    lx__exr_stream s = {.fd = open(path, O_RDONLY)};
    if (s.fd < 0) return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(errno));
    exr_context_t e = NULL;
    int nl = 0, W = 0, H = 0;
    float *buf = NULL;
    chan *ch = NULL;
    exr_storage_t storage;
    const exr_attr_chlist_t *cl;
    lx_status st = lx__exr_read_begin(ctx, path, &s, &e, &storage, "deep images are not supported");
    if (!st) st = lx__exr_channels(ctx, path, &s, e, &cl);
    if (!st && !(ch = lx__calloc((size_t)cl->num_channels, sizeof *ch))) st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
    if (!st) st = pick_s0_channels(ctx, path, cl, ch, &nl, npol);
    if (!st) st = read_s0_pixels(ctx, path, &s, e, storage, ch, nl, &buf, &W, &H);
    if (!st) st = copy_channels(ctx, path, ch, nl, chans);
    if (!st) {
        *W_out = W;
        *H_out = H;
        *data = buf;
        *nl_out = nl;
        buf = NULL;
    }
    if (e) exr_finish(&e);
    close(s.fd);
    lx__free(ch);
    lx__free(buf);
    return st;
}

void lx_xyz_image_free(lx_xyz_image *img)
{
    if (!img) return;
    lx__free(img->xyz);
    lx__free(img->lambda_nm);
    lx__free(img);
}

/* The linear1nm rule on nl channels at wavelengths lam as an nl x 3 matrix (row k: the integrals of
 * the k-th unit spectrum, interpolated to whole nm, against fns). The 1 nm grid spans 360-830 nm at
 * most, where the colour-matching functions are defined (0 outside, so nothing is lost), and is never
 * sized by untrusted channel names. */
static lx_status nonuniform_weights(lx_ctx *ctx, const char *path, const double *lam, int nl, const lx_function *fns,
                                    const lx_batch_opts *opts, double **out)
{
    double g0 = fmax(floor(lam[0]), 360.0), g1 = fmin(ceil(lam[nl - 1]), 830.0);
    if (g1 < g0) g0 = g1 = 360.0; /* no overlap: one sample, where every spectrum is 0 */
    /* the unit spectra in blocks of B, so that memory stays O(nl) however many channels the header names */
    enum { B = 64 };
    size_t n = (size_t)nl, ng = (size_t)(g1 - g0) + 1;
    double *rl = lx__alloc_n(B * n, sizeof(double)), *rv = lx__alloc_n(B * n, sizeof(double)), *rg = lx__alloc_n(B * ng, sizeof(double)),
           *w = lx__alloc_n(3 * n, sizeof(double));
    size_t *roff = lx__alloc_n(B, sizeof(size_t)), *rn = lx__alloc_n(B, sizeof(size_t));
    lx_status st = LX_OK;
    if (!rl || !rv || !rg || !w || !roff || !rn) {
        st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < B; i++) {
        roff[i] = i * n, rn[i] = n;
        memcpy(rl + i * n, lam, sizeof(double) * n);
    }
    for (size_t k0 = 0; k0 < n && !st; k0 += B) {
        size_t m = n - k0 < B ? n - k0 : B;
        memset(rv, 0, sizeof(double) * B * n);
        for (size_t i = 0; i < m; i++) rv[i * n + k0 + i] = 1.0;
        lx_batch b = {m, ng, 0, g0, 1.0, LX_F64, rg};
        if (!(st = lx_batch_resample(ctx, m, rl, rv, roff, rn, &b, opts)))
            st = lx_batch_integrate(ctx, &b, fns, 3, opts, w + 3 * k0);
    }
done:
    lx__free(rl), lx__free(rv), lx__free(rg), lx__free(roff), lx__free(rn);
    if (st) lx__free(w);
    else *out = w;
    return st;
}

lx_status lx_spectral_exr_read_xyz(lx_ctx *ctx, const char *path, lx_observer observer, const lx_batch_opts *opts,
                                   lx_xyz_image **out)
{
    LX__NEED_CTX(ctx);
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spectral_exr_read_xyz: NULL argument");
    *out = NULL;
    if (observer != LX_OBSERVER_2 && observer != LX_OBSERVER_10)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_spectral_exr_read_xyz: observer must be 2 or 10");
    float *data = NULL;
    chan *ch = NULL;
    int nl = 0, W = 0, H = 0, npol = 0;
    lx_status st = read_spectral(ctx, path, &data, &ch, &nl, &W, &H, &npol);
    if (st) return st;
    lx_xyz_image *img = lx__calloc(1, sizeof *img);
    size_t npix = (size_t)W * H;
    double *res = lx__alloc_n(3 * (npix < CHUNK_PIX ? npix : CHUNK_PIX), sizeof(double)), *wts = NULL;
    if (img) {
        img->xyz = lx__alloc_n(3 * npix, sizeof(double));
        img->lambda_nm = lx__alloc_n((size_t)nl, sizeof(double));
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
    const double km = observer == LX_OBSERVER_10 ? LX__KM_10 : LX__KM_2;
    /* non-uniform wavelengths: the linear1nm rule (interpolate linearly to whole nm over 360-830 nm,
     * where the colour-matching functions are defined, then sum at 1 nm). Interpolation and the sum
     * are both linear in the samples, so the rule is one nl x 3 matrix: resample and integrate the nl
     * unit spectra once, then each pixel costs nl x 3 multiply-adds instead of a 1 nm resampling (a
     * 762-byte file declaring 266k pixels took 0.4 s, and over 10 s under sanitizers, before). */
    if (!uniform) {
        st = nonuniform_weights(ctx, path, lam, nl, fns, opts, &wts);
        if (st) goto done;
        for (size_t p = 0; p < npix; p++) {
            const float *v = data + p * (size_t)nl;
            double s0 = 0, s1 = 0, s2 = 0;
            for (int k = 0; k < nl; k++) {
                s0 += v[k] * wts[3 * k];
                s1 += v[k] * wts[3 * k + 1];
                s2 += v[k] * wts[3 * k + 2];
            }
            img->xyz[3 * p] = km * s0, img->xyz[3 * p + 1] = km * s1, img->xyz[3 * p + 2] = km * s2;
        }
        goto done;
    }
    for (size_t p0 = 0; p0 < npix && !st; p0 += CHUNK_PIX) {
        size_t m = npix - p0 < CHUNK_PIX ? npix - p0 : CHUNK_PIX;
        lx_batch b = {m, (size_t)nl, 0, lam[0], step, LX_F32, data + p0 * (size_t)nl};
        if ((st = lx_batch_integrate(ctx, &b, fns, 3, opts, res))) break;
        for (size_t i = 0; i < 3 * m; i++) img->xyz[3 * p0 + i] = km * res[i];
    }
done:
    lx__free(wts);
    lx__free(res);
    lx__free(data);
    lx__free(ch);
    if (st) lx_xyz_image_free(img);
    else *out = img;
    return st;
}

lx_status lx_xyz_image_write_exr(lx_ctx *ctx, const char *path, const lx_xyz_image *img)
{
    LX__NEED_CTX(ctx);
    if (!path || !img || !img->xyz) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_xyz_image_write_exr: NULL argument");
    lx__exr_stream s = {.fd = -1};
    lx_status st = lx__exr_write_begin(ctx, path, &s);
    if (st) return st;
    exr_context_initializer_t init;
    lx__exr_stream_init(&s, 1, &init);
    exr_context_t e = NULL;
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int inited = 0, part = 0, W = img->width, H = img->height;
    size_t npix = (size_t)W * H;
    float *f = lx__alloc_n(3 * (npix ? npix : 1), sizeof(float));
    if (!f) return lx__exr_write_end(ctx, path, &s, NULL, lx__error(ctx, LX_ENOMEM, path, 0, "out of memory"));
    for (size_t i = 0; i < 3 * npix; i++) f[i] = (float)img->xyz[i];
    exr_result_t rv = exr_start_write(&e, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (!rv) rv = exr_add_part(e, "", EXR_STORAGE_SCANLINE, &part);
    if (!rv) rv = exr_initialize_required_attr_simple(e, part, W, H, EXR_COMPRESSION_ZIP);
    static const char *names[3] = {"X", "Y", "Z"};
    for (int c = 0; c < 3 && !rv; c++) rv = exr_add_channel(e, part, names[c], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    if (!rv) rv = exr_write_header(e);
    if (rv) {
        st = lx__exr_fail(ctx, path, &s, rv, "cannot write the header");
        goto done;
    }
    int32_t lpc = 1;
    exr_get_scanlines_per_chunk(e, part, &lpc);
    if (lpc < 1) lpc = 1;
    for (long y0 = 0; y0 < H; y0 += lpc) {
        exr_chunk_info_t ci;
        rv = exr_write_scanline_chunk_info(e, part, (int)y0, &ci);
        if (!rv) rv = lx__exr_encode_chunk(e, part, &enc, &inited, &ci, f, W, 0, (int)y0, 3, xyz_slot, NULL);
        if (rv) break;
    }
    if (rv) st = lx__exr_fail(ctx, path, &s, rv, "cannot encode the pixels");
done:
    if (inited) exr_encoding_destroy(e, &enc);
    st = lx__exr_write_end(ctx, path, &s, &e, st);
    lx__free(f);
    return st;
}
