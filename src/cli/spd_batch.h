/* spd_batch.h - the batch paths of `luxcalc spd` (spd_batch.c). */
#ifndef LX_SPD_BATCH_H
#define LX_SPD_BATCH_H

#include "cli.h"
#include "spd_metrics.h"

/* A file with at least this many spectra on one uniform grid takes the batch path even without
 * --backend (results agree with the per-spectrum path to 1e-9 relative, not bit for bit). */
#define CLI_SPD_BATCH_MIN 1024

typedef struct cli_spd_batch {
    lx_ctx *ctx;
    const char *cmd;
    cli_table *table;
    lx_observer observer;
    lx_method method;
    lx_backend backend;
    int forced;                 /* --backend or LX_BACKEND given: batch even small sets */
    void (*flush)(void *arg);   /* called after each chunk's rows were added */
    void *flush_arg;
    size_t rejected;            /* spectra reported on stderr instead of a row (exit status 2) */
    const cli_metrics *metrics; /* the --metrics selection (batchable groups only), NULL for none */
    const char *unit;           /* the current file's unit name (the metrics' units) */
    const lx_vendor_results *vendor; /* the current file's instrument results, NULL for none */
    const char *instrument;     /* the current file's instrument JSON cell, NULL for null */
} cli_spd_batch;

/* 1 when every spectrum of set shares one uniform grid that the method integrates with cie15. */
int cli_spd_batchable(const cli_spd_batch *B, const lx_spd_set *set);
/* Adds one row per spectrum of a batchable set. */
lx_status cli_spd_batch_set(cli_spd_batch *B, const lx_spd_set *set);
/* A rows-layout CSV file (not "-") read by lx_batch_table_stream: chunks are integrated
 * (lx_batch_colorimetry) while the next ones parse, and the rows are added to the table only
 * once the whole file parsed and every spectrum is batchable. Returns 1 when it did the file,
 * 0 when the caller must use the general reader instead (not a plain rows layout, another
 * method, fewer than CLI_SPD_BATCH_MIN spectra without --backend, or any error: the general
 * reader then reports the file's first problem, FILE:LINE, exactly as before), and -EXIT when
 * the file failed and is larger than the general reader's size limit: the error was printed
 * (FILE:LINE) and EXIT is its exit status. A file larger than that limit is printed chunk by
 * chunk as it is computed (memory stays a chunk, whatever the number of rows), a spectrum that
 * fails reported as "FILE: spectrum 'NAME' (data row N): why" and skipped (B->rejected). */
int cli_spd_batch_file(cli_spd_batch *B, const char *path);
/* "START:END:STEP" in nm into the grid; 0 on success. */
int cli_spd_parse_grid(const char *s, double *start, double *step, size_t *n);
/* Raw little-endian float32 spectra of n samples each ("-" is stdin); errors are printed. */
lx_status cli_spd_f32_file(cli_spd_batch *B, const char *path, double start, double step, size_t n);

#endif
