/* scene_design.c - the deliverable's outputs of `luxcalc scene`: whether values are maintained or
 * new. */
#include "design.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *cli_scene_values(const lx_scene *sc, char *buf, size_t cap)
{
    const lx_scene_design *d = sc->design;
    if (!d || !d->maintained) {
        snprintf(buf, cap, "new (no maintenance factor)");
        return buf;
    }
    double lo = INFINITY, hi = -INFINITY;
    for (size_t l = 0; l < sc->n_lum; l++) {
        if (d->lum_mode[l] == LX_LUM_EMERGENCY) continue; /* dark in normal operation */
        lo = fmin(lo, d->lum_mf[l]), hi = fmax(hi, d->lum_mf[l]);
    }
    if (!(hi >= lo)) snprintf(buf, cap, "maintained");
    else if (lo == hi) snprintf(buf, cap, "maintained (MF %.4g)", lo);
    else snprintf(buf, cap, "maintained (MF %.4g to %.4g)", lo, hi);
    return buf;
}

void cli_scene_maintenance_text(FILE *f, const lx_scene *sc)
{
    const lx_scene_design *d = sc->design;
    if (!d || !d->maintained) return;
    for (size_t i = 0; i < d->n_maint; i++) {
        const lx_maintenance *m = &d->maint[i];
        fprintf(f, "  scheme %s: MF %.4g = LLMF %.4g x LSF %.4g x LMF %.4g x RSMF %.4g (CIE 97:2005)", m->name, m->mf,
                m->llmf, m->lsf, m->lmf, m->rsmf);
        if (isfinite(m->burning_h)) fprintf(f, "; %.6g h burning", m->burning_h);
        if (isfinite(m->cleaning_a)) fprintf(f, "; luminaires cleaned every %.3g a", m->cleaning_a);
        if (isfinite(m->room_cleaning_a)) fprintf(f, "; room every %.3g a", m->room_cleaning_a);
        fputc('\n', f);
    }
    for (size_t l = 0; l < sc->n_lum; l++)
        fprintf(f, "  %-12s MF %.4g%s%s%s\n", sc->lum[l].name, d->lum_mf[l], d->lum_maint[l] >= 0 ? " (scheme " : "",
                d->lum_maint[l] >= 0 ? d->maint[d->lum_maint[l]].name : "", d->lum_maint[l] >= 0 ? ")" : "");
}

void cli_scene_cylinder_summary(cli_table *t, const lx_scene_result *res, size_t a, size_t b)
{
    double sz = 0, ssz = 0, mlo = INFINITY, mhi = -INFINITY;
    size_t nz = 0, nsz = 0;
    for (size_t g = a; g < b; g++) {
        if (!isnan(res->cylindrical_lx[g])) sz += res->cylindrical_lx[g], nz++;
        if (!isnan(res->semicylindrical_lx[g])) ssz += res->semicylindrical_lx[g], nsz++;
        if (!isnan(res->modelling[g])) mlo = fmin(mlo, res->modelling[g]), mhi = fmax(mhi, res->modelling[g]);
    }
    cli_table_num(t, nz ? sz / (double)nz : NAN);
    cli_table_num(t, nsz ? ssz / (double)nsz : NAN);
    cli_table_num(t, mhi >= mlo ? mlo : NAN);
    cli_table_num(t, mhi >= mlo ? mhi : NAN);
}

void cli_design_results_free(cli_design_results *r)
{
    lx_scene_glare_free(r->glare);
    lx_scene_result_free(r->em);
    lx_scene_plan_free(r->em_plan);
    lx_scene_checks_free(r->checks);
    memset(r, 0, sizeof *r);
}

int cli_design_evaluate(const char *cmd, lx_ctx *ctx, const lx_scene *sc, lx_backend backend, const lx_scene_result *res,
                        cli_design_results *out)
{
    memset(out, 0, sizeof *out);
    const lx_scene_design *d = sc->design;
    lx_status st = LX_OK;
    if (d->check_glare) st = lx_scene_glare_eval(ctx, sc, &out->glare);
    if (st == LX_OK && d->check_emergency) st = lx_scene_plan_make_mode(ctx, sc, backend, LX_SCENE_EMERGENCY, &out->em_plan);
    if (st == LX_OK && d->check_emergency) st = lx_scene_eval(ctx, sc, out->em_plan, NULL, &out->em);
    if (st == LX_OK) st = lx_scene_check(ctx, sc, res, out->em, out->glare, &out->checks);
    if (st != LX_OK) {
        cli_design_results_free(out);
        return cli_fail(cmd, ctx, st);
    }
    return 0;
}

/* a check's number as people read it: lx to 4 significant digits (or fc), ratios to 3 decimals, UGR
 * and R_a to 0.1 */
static void value_text(char *buf, size_t cap, const lx_check *k, double v)
{
    cli_column col;
    int ratio = !*k->unit && strcmp(k->quantity, "UGR") && strcmp(k->quantity, "R_a") && strcmp(k->quantity, "E_max/E_min");
    cli_column_out(*k->unit ? "illuminance_lx" : ratio ? "uniformity" : "cri_ra", k->unit, &col);
    if (!isfinite(v)) {
        snprintf(buf, cap, "-");
        return;
    }
    char n[64];
    cli_number_text(n, sizeof n, &col, v);
    snprintf(buf, cap, "%s%s%s", n, *col.unit ? " " : "", col.unit);
}

/* the table for people: one aligned line per check */
static int check_lines(FILE *f, const lx_scene *sc, const lx_scene_checks *c)
{
    enum { NC = 6 };
    static const char *const head[NC] = {"requirement", "target", "quantity", "required", "computed", "result"};
    size_t n = c->n;
    char(*cell)[NC][96] = calloc(n ? n : 1, sizeof *cell);
    if (!cell) return -1;
    int w[NC];
    for (int j = 0; j < NC; j++) w[j] = (int)strlen(head[j]);
    for (size_t i = 0; i < n; i++) {
        const lx_check *k = &c->check[i];
        char num[80];
        snprintf(cell[i][0], 96, "%s", k->requirement);
        snprintf(cell[i][1], 96, "%s", k->target);
        snprintf(cell[i][2], 96, "%s%s", k->quantity, k->emergency ? " (emergency)" : "");
        value_text(num, sizeof num, k, k->required);
        snprintf(cell[i][3], 96, "%s %s", k->at_most ? "<=" : ">=", num);
        value_text(cell[i][4], 96, k, k->value);
        snprintf(cell[i][5], 96, "%s", k->pass ? "pass" : "FAIL");
        for (int j = 0; j < NC; j++) w[j] = (int)strlen(cell[i][j]) > w[j] ? (int)strlen(cell[i][j]) : w[j];
    }
    for (int j = 0; j < NC; j++) fprintf(f, "%-*s%s", j < NC - 1 ? w[j] : 0, head[j], j < NC - 1 ? "  " : "\n");
    for (size_t i = 0; i < n; i++)
        for (int j = 0; j < NC; j++) /* numbers right-aligned */
            fprintf(f, j == 3 || j == 4 ? "%*s%s" : "%-*s%s", j < NC - 1 ? w[j] : 0, cell[i][j], j < NC - 1 ? "  " : "\n");
    char vt[128];
    fprintf(f, "\nchecks: %zu of %zu pass; values %s\n", c->n - c->n_fail, c->n, cli_scene_values(sc, vt, sizeof vt));
    free(cell);
    return ferror(f) ? -1 : 0;
}

int cli_check_write(FILE *f, const lx_scene *sc, const lx_scene_checks *c, cli_format fmt)
{
    if (fmt == CLI_FMT_TABLE) return check_lines(f, sc, c);
    static const char *const names[] = {"requirement", "target", "quantity", "operation", "comparison", "required",
                                        "value", "unit", "pass", "reference", "line"};
    static const char *const units[] = {"", "", "", "", "", "", "", "", "", "", ""};
    cli_table *t = cli_table_new(11, names, units);
    if (!t) return -1;
    for (size_t i = 0; i < c->n; i++) {
        const lx_check *k = &c->check[i];
        cli_table_str(t, k->requirement);
        cli_table_str(t, k->target);
        cli_table_str(t, k->quantity);
        cli_table_str(t, k->emergency ? "emergency" : "normal");
        cli_table_str(t, k->at_most ? "at_most" : "at_least");
        cli_table_num(t, k->required);
        cli_table_num(t, k->value);
        cli_table_str(t, k->unit);
        cli_table_str(t, k->pass ? "pass" : "fail");
        cli_table_str(t, k->reference);
        cli_table_int(t, k->line);
    }
    int rc = cli_table_write(t, fmt, f, 1);
    cli_table_free(t);
    return rc || ferror(f) ? -1 : 0;
}

void cli_observer_cells(cli_table *t, const lx_scene_observer *o)
{
    for (int k = 0; k < 3; k++) cli_table_num(t, o->pos_m[k]);
    double az = atan2(o->view[1], o->view[0]) * 180 / CLI_PI;
    cli_table_num(t, az < 0 ? az + 360 : az);
}

int cli_energy_out(const char *cmd, lx_ctx *ctx, const lx_scene *sc, cli_format fmt, const char *out)
{
    lx_leni_input in;
    lx_leni e;
    lx_status st = lx_scene_energy(ctx, sc, &in, &e);
    if (st != LX_OK) return cli_fail(cmd, ctx, st);
    static const char *const names[] = {"area_m2", "power_W", "power_density_W_m2", "daylight_hours_h", "night_hours_h",
                                        "constant_factor", "occupancy_factor", "daylight_factor", "parasitic_power_W",
                                        "emergency_charging_W", "lighting_kWh", "parasitic_kWh", "total_kWh",
                                        "leni_kWh_m2_a"};
    static const char *const units[] = {"m2", "W", "W/m2", "h", "h", "", "", "", "W", "W", "kWh", "kWh", "kWh", "kWh/(m2 a)"};
    double v[] = {in.area_m2,          in.power_W,         e.power_density_W_m2, in.daylight_h,  in.night_h,
                  in.constant_factor,  in.occupancy_factor, in.daylight_factor,  in.parasitic_W, in.emergency_W,
                  e.lighting_kWh,      e.parasitic_kWh,    e.total_kWh,          e.leni_kWh_m2};
    cli_table *t = cli_table_new(14, names, units);
    if (!t) return CLI_RUNTIME;
    for (int k = 0; k < 14; k++) cli_table_num(t, v[k]);
    int rc = CLI_OK;
    cli_output o;
    if (cli_output_open(&o, out, cmd) != 0) rc = CLI_INPUT;
    else {
        int ok = cli_table_write(t, fmt, o.fp, 0) == 0;
        if (cli_output_close(&o, ok, cmd) != 0 || !ok) rc = CLI_RUNTIME;
    }
    cli_table_free(t);
    return rc;
}
