/* lighting.h - helpers shared by the lighting commands (point, spot, disk, rect, convert, solve):
 * quantity options with units, the efficacy options, writing one result table. */
#ifndef LX_CLI_LIGHTING_H
#define LX_CLI_LIGHTING_H

#include "cli.h"

/* Parses option `opt` (e.g. "--distance") of quantity q; a bare number takes bare_unit (NULL: SI).
 * When photometric q is given in its radiometric counterpart (W, W/sr, W/m2, W/sr/m2) and
 * efficacy > 0 it is converted; without an efficacy that is an error saying to give one.
 * Prints the error and returns CLI_USAGE; 0 on success. */
int lt_quantity(lx_ctx *ctx, const char *cmd, const char *opt, const char *text, lx_quantity q,
                const char *bare_unit, double efficacy, double *out);

/* Resolves --efficacy TEXT or --spd FILE (at most one; both NULL gives 0 = none) into *efficacy
 * in lm/W. Returns 0, or the exit code after printing the error. */
int lt_efficacy(lx_ctx *ctx, const char *cmd, const char *eff_text, const char *spd_path, double *efficacy);

/* Writes the table in the chosen format to -o FILE (atomic) or stdout; returns the exit code. */
int lt_write(const char *cmd, cli_table *t, cli_format fmt, const char *out_path);

/* Parses --format; prints and returns -1 on a bad value. */
int lt_format(const char *cmd, const char *s, cli_format *fmt);

/* radians to degrees as value / (pi/180), the same division the unit table uses, so 30deg prints 30 */
#define LT_DEG (3.14159265358979323846 / 180.0)

#endif
