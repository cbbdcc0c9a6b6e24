/* spd_batch.h - the batch paths of `luxcalc spd` (spd_batch.c, spd_stream.c). */
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
    cli_format format;
    /* the output, for rows the stream writes itself (csv): opened on first use (NULL on failure,
     * printed); private: it is a temporary file of ours (-o), so rows can be taken back */
    FILE *(*open_out)(void *arg);
    int out_private;
    const lx_spd_read_opts *ropts; /* the general reader's options (a pipe read here for it) */
} cli_spd_batch;

/* The metric integrals of a batch for rows [0, n) (each array NULL when not needed). */
typedef struct cli_spd_lab {
    lx_par *par;
    lx_hazard *hz;
    lx_binning *bin;
} cli_spd_lab;

/* The metrics B asks for of the batch b whose colorimetry is res (on B->ctx); free with
 * cli_spd_lab_free. */
lx_status cli_spd_lab_compute(cli_spd_batch *B, const lx_batch *b, const lx_colorimetry *res, lx_batch_opts *opts,
                              cli_spd_lab *L);
void cli_spd_lab_free(cli_spd_lab *L);
/* One row of the columns for spectrum `name` of `file` (par, hz, bin: its metrics, or NULL). */
void cli_spd_add_row(cli_spd_batch *B, const char *file, const char *name, const lx_colorimetry *r, const lx_par *par,
                     const lx_hazard *hz, const lx_binning *bin);
/* The largest |value| of spectrum i of b (for lx_colorimetry_check's overflow message). */
double cli_spd_row_max_abs(const lx_batch *b, size_t i);

/* 1 when every spectrum of set shares one uniform grid that the method integrates with cie15. */
int cli_spd_batchable(const cli_spd_batch *B, const lx_spd_set *set);
/* Adds one row per spectrum of a batchable set. */
lx_status cli_spd_batch_set(cli_spd_batch *B, const lx_spd_set *set);
/* A rows-layout CSV (spd_stream.c): streamed through lx_batch_table_stream_ex, the colorimetry
 * (and, for csv without metrics, the text) of each part made on the parsing threads, the rows
 * written in order as they come in bounded memory, and kept only when the whole file streamed (a
 * file with a bad row is skipped whole: rows already written are taken back). Returns 1 when it
 * did the file, -EXIT when the file failed and the error was printed (EXIT: its exit status), 0
 * when the caller must read it with the general reader: not a plain rows layout, another method,
 * fewer than CLI_SPD_BATCH_MIN spectra without --backend, or an error in a regular file the
 * general reader takes (within the spectrum size limit; it then reports the file's first
 * problem, FILE:LINE, as before). Beyond that limit (and from a pipe) a result
 * lx_colorimetry_check refuses is reported (FILE: spectrum 'NAME' (data row N): why) and counted
 * in B->rejected instead of a row. A pipe, standard input or a device of up to 8 MB, or one that
 * is not a rows layout, is read whole by the general reader here (B->ropts, its size limit): 0
 * and its spectra in *set (the caller's), or -EXIT. */
int cli_spd_batch_file(cli_spd_batch *B, const char *path, lx_spd_set **set);
/* "START:END:STEP" in nm into the grid; 0 on success. */
int cli_spd_parse_grid(const char *s, double *start, double *step, size_t *n);
/* Raw little-endian float32 spectra of n samples each ("-" is stdin); errors are printed. */
lx_status cli_spd_f32_file(cli_spd_batch *B, const char *path, double start, double step, size_t n);

#endif
