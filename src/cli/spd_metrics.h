/* spd_metrics.h - the --metrics columns of `luxcalc spd` (colour rendering, photobiology, plant
 * lighting, photobiological safety, LED binning, the instrument's own results). */
#ifndef LX_SPD_METRICS_H
#define LX_SPD_METRICS_H

#include "cli.h"

#define CLI_METRICS_MAX 160

/* Which metric columns are selected (sel[i] for column i of the fixed order), and the options of
 * the groups that take one. */
typedef struct cli_metrics {
    unsigned char sel[CLI_METRICS_MAX];
    int any;
    double photoperiod_h; /* --photoperiod (DLI); NaN when not given */
    double subtense_rad;  /* --subtense (IEC 62471 L_R limits); 0 when not given */
    lx_observer observer; /* of the colorimetry passed in (binning needs 2 deg) */
} cli_metrics;

/* Parses "all" or a comma-separated list of groups (cri, tm30, alphaopic, mesopic, vendor, par,
 * hazard, binning) and column names into *m (adding to what is there). Prints the error and
 * returns -1 for an unknown name. */
int cli_metrics_parse(cli_metrics *m, const char *list, const char *cmd);

/* 1 when every selected column can be computed on the batch path (vendor, par, hazard, binning). */
int cli_metrics_batchable(const cli_metrics *m);
/* 1 when a selected column needs the PAR or the hazard integrals. */
int cli_metrics_need_par(const cli_metrics *m);
int cli_metrics_need_hazard(const cli_metrics *m);
/* 1 when a selected column is a binning column. */
int cli_metrics_need_binning(const cli_metrics *m);

/* One batch row's metric cells from integrals computed for the whole batch (par, hz may be NULL
 * when not needed; bin: the spectrum's binning, NULL when not needed; vendor may be NULL). */
void cli_metrics_row_batch(cli_table *t, lx_ctx *ctx, const cli_metrics *m, const char *unit, const lx_par *par,
                           const lx_hazard *hz, const lx_binning *bin, const lx_vendor_results *vendor);

/* Appends the selected column names and their units (for unit, the --unit name) after the n
 * base columns in names/units (arrays of at least n + CLI_METRICS_MAX); returns the new count. */
int cli_metrics_columns(const cli_metrics *m, const char *unit, const char **names, const char **units, int n);

/* Computes the selected metrics of one spectrum and appends one cell per selected column (empty
 * where a metric is refused; the reason goes to stderr unless -q). c: its colorimetry; vendor: the
 * file's instrument results (NULL: none). Returns the number of metrics that were computed but are
 * not finite (each reported on stderr with its column name: the caller's exit status is then 2). */
int cli_metrics_row(cli_table *t, lx_ctx *ctx, const cli_metrics *m, const lx_spd *spd, lx_method method,
                    const char *unit, const lx_colorimetry *c, const lx_vendor_results *vendor, const char *file,
                    long line, const char *cmd);

/* Why c has no CCT (cct_valid 0): no light, no Planckian point, |Duv| > 0.05, or outside the range. */
void cli_cct_reason(lx_ctx *ctx, const lx_colorimetry *c, lx_observer obs, char *buf, size_t size);

#endif
