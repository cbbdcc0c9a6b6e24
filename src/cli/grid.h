/* grid.h - what `luxcalc grid` and `luxcalc scene` share: the scene's luminaires as plot marks
 * (cmd_scene.c), the grid printed as a grid and the grid summary (grid_out.c). */
#ifndef LX_CLI_GRID_H
#define LX_CLI_GRID_H

#include "cli.h"

/* The scene's luminaires as plot marks (free with free()); NULL when there are none or no memory. */
lx_plot_mark *cli_scene_marks(const lx_scene *sc);

/* Writes the na x nb values E (A fastest) of plane p as a grid for people: a heading naming the
 * quantity and the plane, then one row per B value (the highest first, as on a plan) with one
 * column per A value; numbers in the table format's digits and the output units. Returns 0, or -1
 * on a write error. */
int cli_grid_table(FILE *out, const lx_plane *p, const double *E);

/* The summary of n values: CLI.md's E_avg, E_min, E_max, U0 (E_min / E_avg), then the same under
 * the names scenes use (illuminance_avg_lx, illuminance_min_lx, illuminance_max_lx, uniformity_u0)
 * and uniformity_min_max (E_min / E_max); the table format shows the named five only. NULL
 * without memory. */
cli_table *cli_grid_summary(const double *E, size_t n, cli_format fmt);

#endif /* LX_CLI_GRID_H */
