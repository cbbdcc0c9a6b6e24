/* spd_exr.c - `luxcalc spd IMAGE.exr -o OUT.exr --png OUT.png`: a spectral OpenEXR image
 * (S0.<wavelength>nm channels) integrated per pixel into XYZ, written as EXR and PNG. */
#include "spd_report.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

int cli_is_exr(const char *path)
{
    struct stat sb; /* sniff regular files only: opening a FIFO would block and eat its data */
    if (stat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) return 0;
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    unsigned char m[4] = {0, 0, 0, 0};
    size_t n = fread(m, 1, 4, f);
    fclose(f);
    return n == 4 && m[0] == 0x76 && m[1] == 0x2f && m[2] == 0x31 && m[3] == 0x01;
}

int cli_spd_exr(lx_ctx *ctx, const char *cmd, const char *path, const char *out_exr, const char *png,
                lx_observer obs, lx_backend backend, cli_format fmt)
{
    lx_batch_opts opts;
    memset(&opts, 0, sizeof opts);
    opts.backend = backend;
    lx_xyz_image *img = NULL;
    lx_status st = lx_spectral_exr_read_xyz(ctx, path, obs, &opts, &img);
    if (st != LX_OK) return cli_fail(cmd, ctx, st);
    if (img->polarised_ignored && !cli_quiet)
        fprintf(stderr, "luxcalc: %s: %s: %d polarised channels (S1-S3) ignored\n", cmd, path, img->polarised_ignored);
    int rc = CLI_OK;
    if (out_exr && (st = lx_xyz_image_write_exr(ctx, out_exr, img)) != LX_OK) rc = cli_fail(cmd, ctx, st);
    if (!rc && png && (st = lx_xyz_image_write_png(ctx, png, img)) != LX_OK) rc = cli_fail(cmd, ctx, st);
    if (!rc) {
        size_t n = (size_t)img->width * img->height;
        double lo = INFINITY, hi = -INFINITY, sum = 0;
        for (size_t p = 0; p < n; p++) {
            double y = img->xyz[3 * p + 1];
            lo = fmin(lo, y), hi = fmax(hi, y), sum += y;
        }
        const char *names[] = {"file", "width", "height", "channels", "lambda_min_nm", "lambda_max_nm", "resampled",
                               "Y_min", "Y_mean", "Y_max"};
        const char *units[] = {"", "", "", "", "nm", "nm", "", "cd/m2", "cd/m2", "cd/m2"};
        cli_table *t = cli_table_new(10, names, units);
        cli_table_str(t, path);
        cli_table_int(t, img->width);
        cli_table_int(t, img->height);
        cli_table_int(t, (long long)img->n_lambda);
        cli_table_num(t, img->lambda_nm[0]);
        cli_table_num(t, img->lambda_nm[img->n_lambda - 1]);
        cli_table_int(t, img->resampled);
        cli_table_num(t, lo);
        cli_table_num(t, sum / (double)n);
        cli_table_num(t, hi);
        if (cli_table_write(t, fmt, stdout, 0) != 0) rc = CLI_INPUT;
        cli_table_free(t);
    }
    lx_xyz_image_free(img);
    return rc;
}
