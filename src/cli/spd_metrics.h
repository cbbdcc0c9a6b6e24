/* spd_metrics.h - the --metrics columns of `luxcalc spd` (colour rendering and photobiology). */
#ifndef LX_SPD_METRICS_H
#define LX_SPD_METRICS_H

#include "cli.h"

#define CLI_METRICS_MAX 96

/* Which metric columns are selected (sel[i] for column i of the fixed order). */
typedef struct cli_metrics {
    unsigned char sel[CLI_METRICS_MAX];
    int any;
} cli_metrics;

/* Parses "all" or a comma-separated list of groups (cri, tm30, alphaopic, mesopic) and column
 * names into *m (adding to what is there). Prints the error and returns -1 for an unknown name. */
int cli_metrics_parse(cli_metrics *m, const char *list, const char *cmd);

/* Appends the selected column names and their units (for unit, the --unit name) after the n
 * base columns in names/units (arrays of at least n + CLI_METRICS_MAX); returns the new count. */
int cli_metrics_columns(const cli_metrics *m, const char *unit, const char **names, const char **units, int n);

/* Computes the selected metrics of one spectrum and appends one cell per selected column (empty
 * where a metric is refused; the reason goes to stderr unless -q). c: its colorimetry. Returns
 * the number of metrics that were computed but are not finite (each reported on stderr with its
 * column name: the caller's exit status is then 2). */
int cli_metrics_row(cli_table *t, lx_ctx *ctx, const cli_metrics *m, const lx_spd *spd, lx_method method,
                     const char *unit, const lx_colorimetry *c, const char *file, long line, const char *cmd);

#endif
