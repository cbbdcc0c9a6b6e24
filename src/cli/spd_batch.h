/* spd_batch.h - the batch paths of `luxcalc spd` (spd_batch.c). */
#ifndef LX_SPD_BATCH_H
#define LX_SPD_BATCH_H

#include "cli.h"

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
    cli_format format;
    /* the output, for rows the stream writes itself (csv): opened on first use (NULL on failure,
     * printed); private: it is a temporary file of ours (-o), so rows can be taken back */
    FILE *(*open_out)(void *arg);
    int out_private;
} cli_spd_batch;

/* One row of the default columns for spectrum `name` of `file`. */
void cli_spd_add_row(cli_table *t, const char *file, const char *name, const lx_colorimetry *r);
/* 1 when every spectrum of set shares one uniform grid that the method integrates with cie15. */
int cli_spd_batchable(const cli_spd_batch *B, const lx_spd_set *set);
/* Adds one row per spectrum of a batchable set. */
lx_status cli_spd_batch_set(cli_spd_batch *B, const lx_spd_set *set);
/* A rows-layout CSV (spd_stream.c): streamed through lx_batch_table_stream_ex, the colorimetry
 * and the csv text of each part made on the parsing threads, the rows written in order as they
 * come (csv) in bounded memory, and kept only when the whole file streamed (a file with a bad row
 * is skipped whole: rows already written are taken back). Returns 1 when it did the file, -1 when
 * the file failed and the error was printed, 0 when the caller must read it with the general
 * reader: not a plain rows layout, another method, fewer than CLI_SPD_BATCH_MIN spectra without
 * --backend, or an error in a regular file of up to 256 MB (the general reader then reports the
 * file's first problem, FILE:LINE, as before). For a pipe or standard input of up to 8 MB, or
 * any that is not a rows layout, the input read is handed back in *text, *len (malloc'ed: the
 * general reader reads it from memory). */
int cli_spd_batch_file(cli_spd_batch *B, const char *path, char **text, size_t *len);
/* "START:END:STEP" in nm into the grid; 0 on success. */
int cli_spd_parse_grid(const char *s, double *start, double *step, size_t *n);
/* Raw little-endian float32 spectra of n samples each ("-" is stdin); errors are printed. */
lx_status cli_spd_f32_file(cli_spd_batch *B, const char *path, double start, double step, size_t n);

#endif
