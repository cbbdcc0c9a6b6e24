/* design.h - the deliverable in `luxcalc scene` and `luxcalc report`: what the values are
 * (maintained or new), and (scene_design.c) the outputs of the deliverable's options. */
#ifndef LX_CLI_DESIGN_H
#define LX_CLI_DESIGN_H

#include "cli.h"

/* "maintained (MF 0.8)", "maintained (MF 0.72 to 0.8)" or "new (no maintenance factor)" into buf
 * (cap bytes); returns buf. */
const char *cli_scene_values(const lx_scene *sc, char *buf, size_t cap);
/* The maintenance factor of each luminaire and the schemes (CIE 97: LLMF x LSF x LMF x RSMF), for
 * --explain; nothing when the values are new. */
void cli_scene_maintenance_text(FILE *f, const lx_scene *sc);
/* The summary cells of points a..b-1: cylindrical_avg_lx, semicylindrical_avg_lx, modelling_min,
 * modelling_max (empty where the receiver asks none). */
void cli_scene_cylinder_summary(cli_table *t, const lx_scene_result *res, size_t a, size_t b);

/* --energy: LENI and its parts, one row; returns the exit code. */
int cli_energy_out(const char *cmd, lx_ctx *ctx, const lx_scene *sc, cli_format fmt, const char *out);
/* The eye's position and the azimuth of the line of sight (deg from +x towards +y): 4 cells. */
void cli_observer_cells(cli_table *t, const lx_scene_observer *o);
/* The scene's results, and those its requirements rate besides: the glare at its observers and the
 * emergency operation's results (each NULL when no requirement needs it). Prints and returns the
 * exit code on failure (0 on success; free what it made with cli_design_results_free). */
typedef struct cli_design_results {
    lx_scene_glare *glare;
    lx_scene_plan *em_plan;
    lx_scene_result *em;
    lx_scene_checks *checks;
} cli_design_results;
int cli_design_evaluate(const char *cmd, lx_ctx *ctx, const lx_scene *sc, lx_backend backend, const lx_scene_result *res,
                        cli_design_results *out);
void cli_design_results_free(cli_design_results *r);
/* --check: one row per check line (requirement, target, quantity, required, computed, pass) and, in the
 * table format, a closing count; returns 0 or -1 on a write error. */
int cli_check_write(FILE *f, const lx_scene *sc, const lx_scene_checks *c, cli_format fmt);

#endif /* LX_CLI_DESIGN_H */
