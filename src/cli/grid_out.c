/* grid_out.c - an illuminance grid for people (rows and columns, as on a plan) and the summary of a
 * grid in the names scenes use (E_avg ... kept beside them for scripts). */
#include "grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* "x", "y", "z" for a coordinate axis, else the fallback */
static const char *axis_name(const double *u, const char *fallback)
{
    static const char *names[] = {"x", "y", "z"};
    for (int k = 0; k < 3; k++)
        if (fabs(fabs(u[k]) - 1) < 1e-12) return names[k];
    return fallback;
}

int cli_grid_table(FILE *out, const lx_plane *p, const double *E)
{
    cli_column ce, cl;
    cli_column_out("illuminance_lx", "lx", &ce);
    cli_column_out("x", "m", &cl);
    size_t na = p->na, nb = p->nb;
    double da = na > 1 ? (p->a1 - p->a0) / (double)(na - 1) : 0, db = nb > 1 ? (p->b1 - p->b0) / (double)(nb - 1) : 0;
    /* the widest entry sets every column's width */
    int w = 1, wb = 1;
    char buf[64];
    for (size_t i = 0; i < na * nb; i++) {
        cli_number_text(buf, sizeof buf, &ce, E[i] * ce.scale);
        w = (int)strlen(buf) > w ? (int)strlen(buf) : w;
    }
    for (size_t i = 0; i < na; i++) {
        cli_number_text(buf, sizeof buf, &cl, (p->a0 + (double)i * da) * cl.scale);
        w = (int)strlen(buf) > w ? (int)strlen(buf) : w;
    }
    for (size_t j = 0; j < nb; j++) {
        cli_number_text(buf, sizeof buf, &cl, (p->b0 + (double)j * db) * cl.scale);
        wb = (int)strlen(buf) > wb ? (int)strlen(buf) : wb;
    }
    const char *an = axis_name(p->u, "a"), *bn = axis_name(p->v, "b");
    char level[128] = "";
    for (int k = 0; k < 3; k++)
        if (fabs(p->u[k]) < 1e-12 && fabs(p->v[k]) < 1e-12) {
            char v[48];
            cli_number_text(v, sizeof v, &cl, p->origin_m[k] * cl.scale);
            snprintf(level, sizeof level, " on %c = %s %s", "xyz"[k], v, cl.unit);
        }
    fprintf(out, "illuminance (%s)%s: rows %s (%s), columns %s (%s)\n", ce.unit, level, bn, cl.unit, an, cl.unit);
    char corner[32];
    snprintf(corner, sizeof corner, "%s \\ %s", bn, an);
    if ((int)strlen(corner) > wb) wb = (int)strlen(corner);
    fprintf(out, "%*s", wb, corner);
    for (size_t i = 0; i < na; i++) {
        cli_number_text(buf, sizeof buf, &cl, (p->a0 + (double)i * da) * cl.scale);
        fprintf(out, "  %*s", w, buf);
    }
    fputc('\n', out);
    for (size_t jj = nb; jj-- > 0;) { /* the highest B first: north up on a plan */
        cli_number_text(buf, sizeof buf, &cl, (p->b0 + (double)jj * db) * cl.scale);
        fprintf(out, "%*s", wb, buf);
        for (size_t i = 0; i < na; i++) {
            cli_number_text(buf, sizeof buf, &ce, E[jj * na + i] * ce.scale);
            fprintf(out, "  %*s", w, buf);
        }
        fputc('\n', out);
    }
    return ferror(out) ? -1 : 0;
}

cli_table *cli_grid_summary(const double *E, size_t n, cli_format fmt)
{
    /* CLI.md's four first (scripts read them), then the names scenes use and E_min / E_max; the
     * table format (for people) shows the named five only */
    static const char *const names[] = {"E_avg", "E_min", "E_max", "U0", "illuminance_avg_lx", "illuminance_min_lx",
                                        "illuminance_max_lx", "uniformity_u0", "uniformity_min_max"};
    static const char *const units[] = {"lx", "lx", "lx", "", "lx", "lx", "lx", "", ""};
    double sum = 0, mn = INFINITY, mx = -INFINITY;
    for (size_t i = 0; i < n; i++) sum += E[i], mn = fmin(mn, E[i]), mx = fmax(mx, E[i]);
    double avg = n ? sum / (double)n : NAN, u0 = avg > 0 ? mn / avg : NAN, g2 = mx > 0 ? mn / mx : NAN;
    const double v[9] = {avg, mn, mx, u0, avg, mn, mx, u0, g2};
    int table = fmt == CLI_FMT_TABLE;
    cli_table *t = cli_table_new(table ? 5 : 9, names + (table ? 4 : 0), units + (table ? 4 : 0));
    for (int k = table ? 4 : 0; t && k < 9; k++) cli_table_num(t, v[k]);
    return t;
}
