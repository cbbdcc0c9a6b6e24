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

#endif /* LX_CLI_DESIGN_H */
