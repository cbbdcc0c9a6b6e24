/* spd_input.h - what `luxcalc spd` tells about the files it reads (spd_input.c): the layout names of
 * --input-format, rows skipped with --skip-bad-rows, the unit a file's format fixes, and the
 * instrument's header fields as a JSON object for --format json. */
#ifndef LX_SPD_INPUT_H
#define LX_SPD_INPUT_H

#include "cli.h"

/* The index in the CLI's unit list of a unit name ("relative", "W/nm", "W/m2/nm", "W/sr/m2/nm",
 * "W/sr/nm"), -1 when it is none of them. */
int cli_spd_unit_index(const char *name);
/* The unit names in that order, NULL-terminated. */
extern const char *const cli_spd_unit_names[];

/* Parses --input-format: NULL (auto, text) or a layout of lx_spd_formats into *format, 1 into *f32
 * for f32. Prints the error and returns -1 for another name. */
int cli_spd_input_format(const char *cmd, const char *arg, const char **format, int *f32);

/* Prints each row the reader left out (FILE:LINE: why) and their count; returns the exit code for
 * them (2 when any, else 0). */
int cli_spd_report_skipped(const char *cmd, const lx_spd_set *set);

/* The set's layout, unit, wavelength scale, skipped rows and header fields as one JSON object
 * (malloc'ed; NULL when out of memory). Repeated keys get " (2)", " (3)", ... */
char *cli_spd_instrument_json(const lx_spd_set *set);

#endif
