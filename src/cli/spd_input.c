/* spd_input.c - what `luxcalc spd` tells about the files it reads: --input-format names, rows left
 * out by --skip-bad-rows, the unit a file's format fixes, the instrument's fields as JSON. */
#include "spd_input.h"

#include <stdlib.h>
#include <string.h>

const char *const cli_spd_unit_names[] = {"relative", "W/nm", "W/m2/nm", "W/sr/m2/nm", "W/sr/nm", NULL};

int cli_spd_unit_index(const char *name)
{
    for (int i = 0; name && cli_spd_unit_names[i]; i++)
        if (!strcmp(name, cli_spd_unit_names[i])) return i;
    return -1;
}

int cli_spd_input_format(const char *cmd, const char *arg, const char **format, int *f32)
{
    *format = NULL;
    *f32 = 0;
    if (!strcmp(arg, "auto") || !strcmp(arg, "text")) return 0;
    if (!strcmp(arg, "f32")) return *f32 = 1, 0;
    const char *const *f = lx_spd_formats();
    for (int i = 0; f[i]; i++)
        if (!strcmp(arg, f[i])) return *format = f[i], 0;
    char list[256] = "auto";
    for (int i = 0; f[i]; i++) snprintf(list + strlen(list), sizeof list - strlen(list), ", %s", f[i]);
    cli_error(cmd, "--input-format: expected %s or f32, not '%s'", list, arg);
    return -1;
}

int cli_spd_report_skipped(const char *cmd, const lx_spd_set *set)
{
    if (!set->nskipped) return CLI_OK;
    for (size_t i = 0; i < set->nskipped; i++)
        cli_error(cmd, "%s:%ld: bad row skipped: %s", set->file, set->skipped[i].line, set->skipped[i].why);
    cli_error(cmd, "%s: %zu bad row%s skipped", set->file, set->nskipped, set->nskipped == 1 ? "" : "s");
    return CLI_INPUT;
}

char *cli_spd_instrument_json(const lx_spd_set *set)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f) return NULL;
    fputs("{\"format\": ", f);
    cli_json_string(f, set->format ? set->format : "");
    fputs(", \"unit\": ", f);
    if (set->unit) {
        cli_json_string(f, set->unit);
        fputs(", \"unit_scale\": ", f);
        cli_print_exact(f, set->unit_scale);
        fputs(", \"unit_source\": ", f);
        cli_json_string(f, set->unit_source ? set->unit_source : "");
    } else {
        fputs("null", f);
    }
    fputs(", \"wavelength_scale\": ", f);
    cli_print_exact(f, set->wavelength_scale > 0 ? set->wavelength_scale : 1.0);
    fprintf(f, ", \"skipped_rows\": %zu, \"fields\": {", set->nskipped);
    for (size_t i = 0; i < set->nfields; i++) {
        int seen = 1;
        for (size_t j = 0; j < i; j++) seen += !strcmp(set->fields[j].key, set->fields[i].key);
        char key[512];
        if (seen > 1) snprintf(key, sizeof key, "%s (%d)", set->fields[i].key, seen);
        else snprintf(key, sizeof key, "%s", set->fields[i].key);
        fputs(i ? ", " : "", f);
        cli_json_string(f, key);
        fputs(": ", f);
        cli_json_string(f, set->fields[i].value);
    }
    fputs("}}", f);
    if (fclose(f) != 0) {
        free(buf);
        return NULL;
    }
    return buf;
}
