/* main.c - luxcalc entry point: global options, the command table, generated help. */
#include "cli.h"

#include <stdlib.h>
#include <string.h>

int cmd_spd(int argc, char **argv);
int cmd_blackbody(int argc, char **argv);
int cmd_daylight(int argc, char **argv);
/* ---- command declarations (one line per command) ---- */

const cli_cmd cli_commands[] = {
    {"spd", cmd_spd, "colorimetry and photometry of measured spectra (XYZ, xy, CCT, Duv, efficacy)"},
    {"blackbody", cmd_blackbody, "Planck spectral radiance of a blackbody as csv"},
    {"daylight", cmd_daylight, "CIE D-series daylight relative SPD as csv"},
    /* ---- command table entries (one line per command) ---- */
    {NULL, NULL, NULL},
};

static void usage(FILE *out)
{
    fprintf(out, "usage: luxcalc [--version] [-v|-q] COMMAND [OPTIONS] [ARGS]\n\n"
                 "Photometry and radiometry: spectra, lighting calculations, luminaires, radiance maps.\n\n"
                 "commands:\n");
    for (const cli_cmd *c = cli_commands; c->name; c++) fprintf(out, "  %-14s %s\n", c->name, c->summary);
    fprintf(out, "\nRun 'luxcalc COMMAND --help' for a command's options and an example.\n"
                 "Exit status: 0 success, 1 usage error, 2 input error, 3 runtime error.\n");
}

int main(int argc, char **argv)
{
    int i = 1;
    for (; i < argc && argv[i][0] == '-'; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--version") || !strcmp(a, "-V")) {
            printf("luxcalc %s\n", lx_version());
            return CLI_OK;
        } else if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return CLI_OK;
        } else if (!strcmp(a, "-v") || !strcmp(a, "--verbose")) {
            cli_verbose++;
        } else if (!strcmp(a, "-vv")) {
            cli_verbose += 2;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            cli_quiet = 1;
        } else {
            fprintf(stderr, "luxcalc: unknown option '%s'\n", a);
            usage(stderr);
            return CLI_USAGE;
        }
    }
    if (i >= argc) {
        usage(stderr);
        return CLI_USAGE;
    }
    for (const cli_cmd *c = cli_commands; c->name; c++)
        if (!strcmp(c->name, argv[i])) return c->run(argc - i, argv + i);
    if (!strcmp(argv[i], "help")) {
        if (i + 1 < argc)
            for (const cli_cmd *c = cli_commands; c->name; c++)
                if (!strcmp(c->name, argv[i + 1])) {
                    char *hv[] = {argv[i + 1], "--help", NULL};
                    return c->run(2, hv);
                }
        usage(stdout);
        return CLI_OK;
    }
    fprintf(stderr, "luxcalc: unknown command '%s'\n", argv[i]);
    usage(stderr);
    return CLI_USAGE;
}
