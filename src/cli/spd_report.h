/* spd_report.h - `luxcalc spd --report DIR` (spd_report.c) and the spectral EXR path (spd_exr.c). */
#ifndef LX_SPD_REPORT_H
#define LX_SPD_REPORT_H

#include "cli.h"

/* Creates DIR (for option opt, "--report") when it does not exist (one level). Returns 0, or
 * prints the error and returns -1. */
int cli_make_dir(const char *cmd, const char *opt, const char *dir);
/* The reports of one run: where they go, how they are drawn, and the names already written. */
typedef struct cli_reports {
    const char *cmd, *dir;
    lx_report_opts opts; /* observer, unit, diagram (title set per report) */
    char **used;         /* file names written in this run */
    size_t n_used, cap_used;
} cli_reports;
/* Writes DIR/<file-stem>_<spectrum>.png (names reduced to [A-Za-z0-9._-], others '_'; an empty
 * spectrum name uses its 1-based index; a name already written in this run gets _2, _3 ...) for
 * spectrum `index` of `file`. Returns an exit code. */
int cli_spd_report(cli_reports *rep, lx_ctx *ctx, const char *file, size_t index, const lx_spd *spd);
/* Frees the list of names. */
void cli_reports_free(cli_reports *rep);

/* 1 when the file's first four bytes are the OpenEXR magic 76 2f 31 01. */
int cli_is_exr(const char *path);
/* A spectral EXR image: integrates it, writes out_exr (XYZ, may be NULL) and png (may be NULL),
 * prints a summary row to stdout. Returns an exit code. */
int cli_spd_exr(lx_ctx *ctx, const char *cmd, const char *path, const char *out_exr, const char *png,
                lx_observer obs, lx_backend backend, cli_format fmt);

#endif
