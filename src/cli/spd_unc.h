/* spd_unc.h - `luxcalc spd --uncertainty SPEC`: the options, the columns of every quantity with its
 * standard uncertainty and coverage interval (NAME_u, NAME_lo, NAME_hi; NAME_gum_u, NAME_gum_valid
 * with both methods; the details in json), one row per spectrum, and --explain. */
#ifndef LX_SPD_UNC_H
#define LX_SPD_UNC_H

#include "cli.h"

#include <getopt.h>

typedef struct cli_unc {
    const char *spec;  /* --uncertainty (NULL: off) */
    lx_unc_opts o;     /* --uncertainty-method, --trials, --coverage, --seed, --interval, --digits */
    int explain;       /* --explain */
    /* the columns: the plain run's n0 columns with, after each quantity that has an uncertainty, its
     * own; per column its source (a plain column), what it holds and its quantity */
    int n0, n;
    const char **names;
    const char **units[5];
    int *src, *kind, *q;
    unsigned groups;   /* LX_UNC_* the columns need */
} cli_unc;

/* Takes one of the uncertainty options (getopt's c, its argument); returns 1 when c is one of them
 * and was valid, 0 when it is not one of them, -1 (printed) when its value is invalid. */
int cli_unc_option(cli_unc *u, int c, const char *arg, const char *cmd);
/* The long options of the uncertainty, for getopt_long (terminated by a zero entry). */
extern const struct option cli_unc_long_options[];
/* Checks the options together (after parsing); -1 (printed) when they conflict. */
int cli_unc_check(const cli_unc *u, const char *cmd);

/* The columns: names[0 .. n0) and units[unit][0 .. n0) are the plain run's (the last one the json
 * "instrument"), expanded into u->names, u->units; a json-only "uncertainty" column last. */
int cli_unc_columns(cli_unc *u, const char *const *names, const char *const *const units[5], int n0);
/* Marks the columns the table format and csv leave out (after cli_table_new with u's columns). */
void cli_unc_table_flags(const cli_unc *u, cli_table *t);

/* The row of one spectrum: the plain row pending in src (its n0 cells), copied into dst with the
 * uncertainty of its quantities under model m (lx_spd_uncertainty); src's row is then discarded.
 * Prints the reason a quantity has none and, with --explain, the run. Returns the exit status the
 * row calls for (0, or CLI_INPUT / CLI_RUNTIME when the uncertainty could not be computed: the
 * plain row is still written, its uncertainty cells empty). */
int cli_unc_row(const cli_unc *u, cli_table *dst, cli_table *src, lx_ctx *ctx, const lx_spd *spd, lx_observer obs,
                lx_method method, const lx_unc_model *m, const char *file, long line, const char *cmd);

/* The two halves of cli_unc_row, for rows computed on other threads: the uncertainty of spd (on
 * ctx, `threads` threads for Monte Carlo, 0: u's), its status and message (malloc'ed) on failure;
 * and the row written from it (r is freed; where: "FILE:LINE" or "FILE (data row N)"). */
lx_unc_result *cli_unc_compute(const cli_unc *u, lx_ctx *ctx, const lx_spd *spd, lx_observer obs, lx_method method,
                               const lx_unc_model *m, int threads, lx_status *st, char **msg);
int cli_unc_write(const cli_unc *u, cli_table *dst, cli_table *src, lx_unc_result *r, lx_status st, const char *msg,
                  const lx_unc_model *m, const char *where, const char *label, const char *cmd);

/* The rows of a rows-layout CSV streamed (spd_unc_stream.c): a first pass checks the whole file
 * (a bad row: 0, the caller's general reader reports it as for any file), the second parses it part
 * by part on every core and computes each spectrum's uncertainty there (Monte Carlo on one thread a
 * spectrum), and the rows go out in file order as the parts come: plain(arg, t, spd, where) appends
 * the spectrum's plain row to t (returns an exit status), then its uncertainty joins it in dst, and
 * flush(arg) writes dst's rows. Returns 1 when it did the file (*rc its worst exit status), 0 when
 * the caller reads it (not a regular file, not a rows layout on a uniform grid, a bad row). */
typedef struct cli_unc_rows {
    /* > 0 or 0: the row was added (its exit status), < 0: none (minus the exit status; printed) */
    int (*plain)(void *arg, cli_table *t, const lx_spd *spd, const char *where);
    void (*flush)(void *arg);
    void *arg;
    cli_table *row, *dst;
    void *flush_arg;
} cli_unc_rows;
int cli_unc_stream(const cli_unc *u, lx_ctx *ctx, const char *path, const lx_unc_model *m, lx_observer obs,
                   lx_method method, const cli_unc_rows *rows, const char *cmd, int *rc);

void cli_unc_free(cli_unc *u);

#endif /* LX_SPD_UNC_H */
