/* cmd_report.c - `luxcalc report SCENE -o report.pdf`: the design report of a scene as a vector PDF
 * (the library's lx_scene_report_write_pdf). */
#include "cli.h"

#include <getopt.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc report SCENE -o REPORT.pdf [--title T] [--project P] [--author A]\n"
    "                      [--backend auto|cpu|opencl] [--units metric|imperial]\n"
    "\n"
    "The design report of a scene file (see README \"The deliverable\") as a vector PDF: a title page,\n"
    "the luminaire schedule (photometry, flux, power, efficacy, maintenance factor, count), each\n"
    "room's plan with its areas, luminaires and observers, the areas' statistics and each grid's\n"
    "isolux plot, the checks against the scene's [requirement] sections, UGR at the observers and the\n"
    "CIE 190 table of each photometric file, emergency lighting (EN 1838), energy (EN 15193-1) and the\n"
    "method: what was simulated and why, the tolerances and what was approximated by how much.\n"
    "The scene is planned and evaluated (in emergency operation too when it has emergency luminaires).\n"
    "\n"
    "  -o FILE         the PDF (required; written atomically: nothing is left on failure)\n"
    "  --title T       the report's title (default: the scene's [scene] title)\n"
    "  --project P     a line under the title (the project, the client)\n"
    "  --author A      the designer\n"
    "  --backend B     auto (default, also LX_BACKEND), cpu or opencl\n"
    "\n"
    "example:\n"
    "  luxcalc report samples/deliverable/office.scene -o office.pdf --project \"Example office, 2nd floor\"\n";

int cmd_report(int argc, char **argv)
{
    static const struct option opts[] = {{"title", required_argument, 0, 't'},  {"project", required_argument, 0, 'p'},
                                         {"author", required_argument, 0, 'a'}, {"backend", required_argument, 0, 'b'},
                                         {"help", no_argument, 0, 'h'},         {0, 0, 0, 0}};
    const char *cmd = "report", *out = NULL, *backend_text = NULL;
    lx_pdf_report_opts o;
    memset(&o, 0, sizeof o);
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'o': out = optarg; break;
        case 't': o.title = optarg; break;
        case 'p': o.project = optarg; break;
        case 'a': o.author = optarg; break;
        case 'b': backend_text = optarg; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_bad_option(cmd, argv, c);
        }
    }
    if (optind + 1 != argc) {
        cli_error(cmd, optind >= argc ? "no scene file given (see luxcalc report --help)" : "one scene file at a time");
        return CLI_USAGE;
    }
    if (!out) {
        cli_error(cmd, "give the PDF to write with -o FILE");
        return CLI_USAGE;
    }
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    o.backend = lx_backend_from_env();
    if (backend_text && lx_backend_parse(ctx, backend_text, &o.backend) != LX_OK) {
        cli_error(cmd, "--backend: expected auto, cpu or opencl, got '%s'", backend_text);
        lx_ctx_destroy(ctx);
        return CLI_USAGE;
    }
    o.imperial = cli_imperial();
    lx_scene *sc = NULL;
    lx_status st = lx_scene_read_file(ctx, argv[optind], &sc);
    if (st == LX_OK) st = lx_scene_report_write_pdf(ctx, sc, &o, out);
    int rc = st == LX_OK ? CLI_OK : cli_fail(cmd, ctx, st);
    if (st == LX_OK && !cli_quiet) fprintf(stderr, "luxcalc: report: wrote %s\n", out);
    lx_scene_free(sc);
    lx_ctx_destroy(ctx);
    return rc;
}
