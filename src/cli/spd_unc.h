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

void cli_unc_free(cli_unc *u);

#endif /* LX_SPD_UNC_H */
