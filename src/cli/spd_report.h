/* spd_report.h - `luxcalc spd --report DIR` (spd_report.c) and the spectral EXR path (spd_exr.c). */
#ifndef LX_SPD_REPORT_H
#define LX_SPD_REPORT_H

#include "cli.h"

/* Creates DIR when it does not exist (one level). Returns 0, or prints the error and returns -1. */
int cli_report_dir(const char *cmd, const char *dir);
/* Writes DIR/<file-stem>_<spectrum>.png (names reduced to [A-Za-z0-9._-], others '_'; an empty
 * spectrum name uses its 1-based index) for spectrum `index` of `file`. Returns an exit code. */
int cli_spd_report(lx_ctx *ctx, const char *cmd, const char *dir, const char *file, size_t index, const lx_spd *spd,
                   lx_observer obs);

/* 1 when the file's first four bytes are the OpenEXR magic 76 2f 31 01. */
int cli_is_exr(const char *path);
/* A spectral EXR image: integrates it, writes out_exr (XYZ, may be NULL) and png (may be NULL),
 * prints a summary row to stdout. Returns an exit code. */
int cli_spd_exr(lx_ctx *ctx, const char *cmd, const char *path, const char *out_exr, const char *png,
                lx_observer obs, lx_backend backend, cli_format fmt);

#endif
