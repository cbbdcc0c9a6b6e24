/* test_spectral_exr.c - spectral OpenEXR images (Fichet et al. 2021 channel names) integrated per
 * pixel into XYZ (spectral_exr.c): files written here with OpenEXRCore (scanline and tiled, with
 * polarised channels, non-uniform wavelengths, reflective-only and RGB files), Y per pixel against
 * lx_spd_colorimetry of the same sampled spectrum, the XYZ EXR read back, the PNG, and the CLI. */
#include "lx_test.h"

#include <cairo.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <openexr.h>

#define W 4
#define H 3
#define NL 41 /* 380-780 nm at 10 nm */

static char dir[64];

static void quiet(exr_const_context_t c, exr_result_t code, const char *msg) { (void)c, (void)code, (void)msg; }

/* writes W x H pixels of nl float channels named names[k] (values data[p * nl + k]); tile > 0: tiled */
static int write_exr(const char *path, int nl, char names[][32], const float *data, int tile)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = quiet;
    exr_context_t e = NULL;
    int part = 0;
    if (exr_start_write(&e, path, EXR_WRITE_FILE_DIRECTLY, &init)) return -1;
    exr_result_t rv = exr_add_part(e, "", tile ? EXR_STORAGE_TILED : EXR_STORAGE_SCANLINE, &part);
    if (!rv) rv = exr_initialize_required_attr_simple(e, part, W, H, EXR_COMPRESSION_ZIP);
    if (!rv && tile) rv = exr_set_tile_descriptor(e, part, (uint32_t)tile, (uint32_t)tile, EXR_TILE_ONE_LEVEL, EXR_TILE_ROUND_DOWN);
    for (int k = 0; k < nl && !rv; k++) rv = exr_add_channel(e, part, names[k], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    if (!rv) rv = exr_write_header(e);
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int inited = 0;
    int32_t lpc = 1;
    if (!tile) exr_get_scanlines_per_chunk(e, part, &lpc);
    int ntx = tile ? (W + tile - 1) / tile : 1, nty = tile ? (H + tile - 1) / tile : (H + lpc - 1) / lpc;
    for (int k = 0; k < ntx * nty && !rv; k++) {
        exr_chunk_info_t ci;
        int x0 = tile ? (k % ntx) * tile : 0, y0 = tile ? (k / ntx) * tile : k * lpc;
        rv = tile ? exr_write_tile_chunk_info(e, part, k % ntx, k / ntx, 0, 0, &ci) : exr_write_scanline_chunk_info(e, part, y0, &ci);
        if (!rv) rv = inited ? exr_encoding_update(e, part, &ci, &enc) : exr_encoding_initialize(e, part, &ci, &enc);
        if (rv) break;
        inited = 1;
        for (int q = 0; q < enc.channel_count; q++) {
            exr_coding_channel_info_t *ch = &enc.channels[q];
            int slot = 0;
            for (int j = 0; j < nl; j++)
                if (!strcmp(names[j], ch->channel_name)) slot = j;
            ch->encode_from_ptr = (const uint8_t *)(data + ((size_t)y0 * W + x0) * nl + slot);
            ch->user_pixel_stride = nl * 4;
            ch->user_line_stride = W * nl * 4;
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
        }
        rv = exr_encoding_choose_default_routines(e, part, &enc);
        if (!rv) rv = exr_encoding_run(e, part, &enc);
    }
    if (inited) exr_encoding_destroy(e, &enc);
    exr_result_t fr = exr_finish(&e);
    return rv || fr ? -1 : 0;
}

/* the test image: pixel p is a blackbody at 1500 + 700 p K (radiance W/(sr m2 nm)), except pixel 5,
 * CIE D65 (relative, 10 nm samples of the 5 nm table) */
static void spectra(lx_ctx *ctx, const double *lam, int nl, float *data)
{
    lx_spd d65;
    lx_illuminant_get(ctx, "D65", &d65);
    for (int p = 0; p < W * H; p++)
        for (int k = 0; k < nl; k++) {
            double v = p == 5 ? 0 : lx_planck(lam[k], 1500.0 + 700.0 * p);
            for (size_t i = 0; p == 5 && i < d65.n; i++)
                if (d65.lambda_nm[i] == lam[k]) v = d65.value[i];
            data[p * nl + k] = (float)v;
        }
}

/* Y (and X, Z) of each pixel by lx_spd_colorimetry on the same float samples */
static void check_xyz(lx_ctx *ctx, const lx_xyz_image *img, const double *lam, int nl, const float *data,
                      lx_method method)
{
    double val[64];
    assert_int_equal(img->width, W);
    assert_int_equal(img->height, H);
    for (int p = 0; p < W * H; p++) {
        for (int k = 0; k < nl; k++) val[k] = data[p * nl + k];
        lx_spd s = {"px", (size_t)nl, lam, val};
        lx_colorimetry c;
        lx_assert_ok(ctx, lx_spd_colorimetry(ctx, &s, LX_OBSERVER_2, method, &c));
        /* the same sums in double (batch vs per-spectrum: 1e-9 relative, lx_batch_colorimetry's contract) */
        lx_assert_near(img->xyz[3 * p + 0], c.X, 1e-300, 1e-9);
        lx_assert_near(img->xyz[3 * p + 1], c.Y, 1e-300, 1e-9);
        lx_assert_near(img->xyz[3 * p + 2], c.Z, 1e-300, 1e-9);
    }
}

static void uniform_scanline(void **state)
{
    lx_ctx *ctx = *state;
    double lam[NL];
    char names[NL + 3][32];
    float data[W * H * (NL + 3)];
    for (int k = 0; k < NL; k++) lam[k] = 380 + 10 * k, snprintf(names[k], 32, "S0.%d,000000nm", 380 + 10 * k);
    spectra(ctx, lam, NL, data);
    char path[128];
    snprintf(path, sizeof path, "%s/uniform.exr", dir);
    assert_int_equal(write_exr(path, NL, names, data, 0), 0);
    lx_xyz_image *img = NULL;
    lx_batch_opts o;
    memset(&o, 0, sizeof o);
    o.backend = LX_BACKEND_CPU;
    lx_assert_ok(ctx, lx_spectral_exr_read_xyz(ctx, path, LX_OBSERVER_2, &o, &img));
    assert_int_equal(img->n_lambda, NL);
    assert_int_equal(img->resampled, 0);
    check_xyz(ctx, img, lam, NL, data, LX_METHOD_CIE15);
    /* pixel 3 by hand: Km sum S(l) ybar(l) 10 nm (the cie15 rule, CIE 015:2018 7.1; Km 683.002 lm/W) */
    lx_spd ybar;
    lx_assert_ok(ctx, lx_function_get(ctx, LX_FN_YBAR_2, &ybar));
    double y = 0;
    for (int k = 0; k < NL; k++) y += (double)data[3 * NL + k] * ybar.value[(int)lam[k] - 360] * 10.0;
    lx_assert_near(img->xyz[3 * 3 + 1], 683.002 * y, 0, 1e-9);

    /* the XYZ EXR: channels X, Y, Z; Y read back through lx_exr_read (a Y-only luminance map) */
    char out[128];
    snprintf(out, sizeof out, "%s/xyz.exr", dir);
    lx_assert_ok(ctx, lx_xyz_image_write_exr(ctx, out, img));
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = quiet;
    exr_context_t e = NULL;
    assert_int_equal(exr_start_read(&e, out, &init), 0);
    const exr_attr_chlist_t *cl = NULL;
    assert_int_equal(exr_get_channels(e, 0, &cl), 0);
    assert_int_equal(cl->num_channels, 3);
    assert_string_equal(cl->entries[0].name.str, "X");
    assert_string_equal(cl->entries[1].name.str, "Y");
    assert_string_equal(cl->entries[2].name.str, "Z");
    exr_finish(&e);
    lx_envmap *m = NULL;
    lx_assert_ok(ctx, lx_exr_read(ctx, out, &m));
    assert_int_equal(m->channels, 1);
    for (int p = 0; p < W * H; p++) assert_true(m->data[p] == (float)img->xyz[3 * p + 1]);
    lx_envmap_free(m);

    /* the PNG preview: enlarged to 256 x 192 */
    snprintf(out, sizeof out, "%s/xyz.png", dir);
    lx_assert_ok(ctx, lx_xyz_image_write_png(ctx, out, img));
    cairo_surface_t *pi = cairo_image_surface_create_from_png(out);
    assert_int_equal(cairo_surface_status(pi), CAIRO_STATUS_SUCCESS);
    assert_int_equal(cairo_image_surface_get_width(pi), 256), assert_int_equal(cairo_image_surface_get_height(pi), 192);
    cairo_surface_destroy(pi);
    /* an unwritable place: LX_EIO and nothing left */
    snprintf(out, sizeof out, "%s/none/xyz.exr", dir);
    assert_int_equal(lx_xyz_image_write_exr(ctx, out, img), LX_EIO);
    assert_int_equal(access(out, F_OK), -1);
    lx_xyz_image_free(img);

    /* the CLI: IMAGE.exr -o OUT.exr --png OUT.png */
    char cli[256], cmd[1024];
    snprintf(cli, sizeof cli, "%s/luxcalc", lx_test_build_dir());
    if (access(cli, X_OK) == 0) {
        snprintf(cmd, sizeof cmd, "'%s' spd '%s' -o '%s/cli.exr' --png '%s/cli.png' --format csv > '%s/cli.csv'", cli,
                 path, dir, dir, dir);
        assert_int_equal(system(cmd), 0);
        snprintf(out, sizeof out, "%s/cli.exr", dir);
        lx_assert_ok(ctx, lx_exr_read(ctx, out, &m));
        assert_int_equal(m->width, W);
        lx_envmap_free(m);
        snprintf(out, sizeof out, "%s/cli.png", dir);
        assert_int_equal(access(out, F_OK), 0);
    }
}

static void tiled_polarised(void **state)
{
    lx_ctx *ctx = *state;
    double lam[NL];
    enum { N2 = NL + 2 };
    char names[N2][32];
    float d0[W * H * NL], data[W * H * N2];
    for (int k = 0; k < NL; k++) lam[k] = 380 + 10 * k, snprintf(names[k], 32, "S0.%d,000000nm", 380 + 10 * k);
    snprintf(names[NL], 32, "S1.550,000000nm");
    snprintf(names[NL + 1], 32, "S3.550,000000nm");
    spectra(ctx, lam, NL, d0);
    for (int p = 0; p < W * H; p++) {
        for (int k = 0; k < NL; k++) data[p * N2 + k] = d0[p * NL + k];
        data[p * N2 + NL] = data[p * N2 + NL + 1] = 7.0f;
    }
    char path[128];
    snprintf(path, sizeof path, "%s/tiled.exr", dir);
    assert_int_equal(write_exr(path, N2, names, data, 2), 0);
    lx_xyz_image *img = NULL;
    lx_assert_ok(ctx, lx_spectral_exr_read_xyz(ctx, path, LX_OBSERVER_2, NULL, &img));
    assert_int_equal(img->polarised_ignored, 2);
    check_xyz(ctx, img, lam, NL, d0, LX_METHOD_CIE15);
    lx_xyz_image_free(img);
}

static void nonuniform(void **state)
{
    lx_ctx *ctx = *state;
    /* 380-780 at 10 nm without 500 and 510 nm: not uniform, resampled to 1 nm first, which is what
     * the linear1nm method does (interpolate to whole nm, sum at 1 nm) */
    double lam[NL];
    char names[NL][32];
    int n = 0;
    for (int k = 0; k < NL; k++) {
        int l = 380 + 10 * k;
        if (l == 500 || l == 510) continue;
        lam[n] = l;
        snprintf(names[n++], 32, "S0.%d,0nm", l);
    }
    float data[W * H * NL];
    spectra(ctx, lam, n, data);
    char path[128];
    snprintf(path, sizeof path, "%s/nonuniform.exr", dir);
    assert_int_equal(write_exr(path, n, names, data, 0), 0);
    lx_xyz_image *img = NULL;
    lx_assert_ok(ctx, lx_spectral_exr_read_xyz(ctx, path, LX_OBSERVER_2, NULL, &img));
    assert_int_equal(img->resampled, 1);
    check_xyz(ctx, img, lam, n, data, LX_METHOD_LINEAR1NM);
    lx_xyz_image_free(img);
}

static void refusals(void **state)
{
    lx_ctx *ctx = *state;
    char names[3][32] = {"T.500,0nm", "T.600,0nm", "T.700,0nm"};
    float data[W * H * 3];
    for (int i = 0; i < W * H * 3; i++) data[i] = 0.5f;
    char path[128];
    lx_xyz_image *img = NULL;
    snprintf(path, sizeof path, "%s/refl.exr", dir);
    assert_int_equal(write_exr(path, 3, names, data, 0), 0);
    assert_int_equal(lx_spectral_exr_read_xyz(ctx, path, LX_OBSERVER_2, NULL, &img), LX_EUNSUPPORTED);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "reflective"));
    char rgb[3][32] = {"B", "G", "R"};
    snprintf(path, sizeof path, "%s/rgb.exr", dir);
    assert_int_equal(write_exr(path, 3, rgb, data, 0), 0);
    assert_int_equal(lx_spectral_exr_read_xyz(ctx, path, LX_OBSERVER_2, NULL, &img), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "S0."));
    snprintf(path, sizeof path, "%s/missing.exr", dir);
    assert_int_equal(lx_spectral_exr_read_xyz(ctx, path, LX_OBSERVER_2, NULL, &img), LX_EIO);
    assert_null(img);
}

/* A spectral header declaring 100000 x 100000 pixels x 3 channels (3e10 values) is refused before
 * allocation (the limit: 4e9 values), and 3000 x 3000 in a small file by the per-byte bound. */
static void window_that_lies(void **state)
{
    lx_ctx *ctx = *state;
    char names[3][32] = {"S0.500nm", "S0.600nm", "S0.700nm"};
    float data[W * H * 3];
    for (int i = 0; i < W * H * 3; i++) data[i] = 1.0f;
    char path[128];
    snprintf(path, sizeof path, "%s/lie.exr", dir);
    assert_int_equal(write_exr(path, 3, names, data, 0), 0);
    assert_int_equal(lx_test_exr_set_window(path, "dataWindow", 99999, 99999), 0);
    lx_xyz_image *img = NULL;
    assert_int_equal(lx_spectral_exr_read_xyz(ctx, path, LX_OBSERVER_2, NULL, &img), LX_EPARSE);
    assert_null(img);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "data window 100000x100000 x 3 channels over the limit of 4e9 values"));
    assert_int_equal(write_exr(path, 3, names, data, 0), 0);
    assert_int_equal(lx_test_exr_set_window(path, "dataWindow", 2999, 2999), 0);
    assert_int_equal(lx_spectral_exr_read_xyz(ctx, path, LX_OBSERVER_2, NULL, &img), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "too large for a file of"));
}

static int setup_dir(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/lxspexrXXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown_dir(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(uniform_scanline, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(tiled_polarised, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(nonuniform, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(refusals, lx_test_ctx_setup, lx_test_ctx_teardown),
        cmocka_unit_test_setup_teardown(window_that_lies, lx_test_ctx_setup, lx_test_ctx_teardown),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
