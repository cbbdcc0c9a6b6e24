/* cmd_devices.c - `luxcalc devices`: the OpenCL platforms and devices found, and which one the
 * automatic choice (with LX_PLATFORM / LX_DEVICE) would use. Creates no OpenCL context. */
#include "cli.h"

#include <getopt.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc devices [--format table|csv|json] [-o FILE]\n"
    "\n"
    "Lists every OpenCL device of every platform: indices (as LX_PLATFORM and LX_DEVICE count\n"
    "them), names, type, compute units, memory, CL_DEVICE_MAX_MEM_ALLOC_SIZE (the batch chunk\n"
    "limit), double precision, and 'default' = yes for the device the automatic choice picks\n"
    "(a GPU first, else the first device; LX_PLATFORM=i, LX_DEVICE=j|cpu|gpu override it).\n"
    "No OpenCL platform is not an error: the list is empty and a note goes to stderr.\n"
    "\n"
    "example:\n"
    "  luxcalc devices --format csv\n"
    "  LX_DEVICE=cpu luxcalc devices\n";

int cmd_devices(int argc, char **argv)
{
    static const struct option opts[] = {
        {"format", required_argument, NULL, 'f'}, {"output", required_argument, NULL, 'o'},
        {"help", no_argument, NULL, 'h'},         {NULL, 0, NULL, 0},
    };
    const char *cmd = "devices", *outpath = NULL;
    int fmt = CLI_FMT_TABLE, c;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'f':
            if ((fmt = cli_format_parse(optarg)) < 0)
                return cli_error(cmd, "--format: expected table, csv or json, not '%s'", optarg), CLI_USAGE;
            break;
        case 'o': outpath = optarg; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_bad_option("devices", argv, c);
        }
    }
    if (optind < argc) return cli_error(cmd, "unexpected argument '%s'", argv[optind]), CLI_USAGE;
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    lx_cl_device_info *d = NULL;
    size_t n = 0;
    lx_status st = lx_cl_devices(ctx, &d, &n);
    if (st) {
        int rc = cli_fail(cmd, ctx, st);
        lx_ctx_destroy(ctx);
        return rc;
    }
    static const char *const names[] = {"platform", "device", "platform_name", "device_name", "type",
                                        "compute_units", "global_mem_MiB", "max_alloc_MiB", "fp64", "version", "default"};
    cli_table *t = cli_table_new(11, names, NULL);
    for (size_t i = 0; i < n; i++) {
        cli_table_int(t, d[i].platform);
        cli_table_int(t, d[i].device);
        cli_table_str(t, d[i].platform_name);
        cli_table_str(t, d[i].device_name);
        cli_table_str(t, d[i].is_gpu ? "gpu" : d[i].is_cpu ? "cpu" : "other");
        cli_table_int(t, d[i].compute_units);
        cli_table_int(t, (long long)(d[i].global_mem_bytes >> 20));
        cli_table_int(t, (long long)(d[i].max_alloc_bytes >> 20));
        cli_table_str(t, d[i].fp64 ? "yes" : "no");
        cli_table_str(t, d[i].version);
        cli_table_str(t, d[i].is_default ? "yes" : "no");
    }
    if (n == 0 && !cli_quiet)
#if LX_OPENCL
        cli_error(cmd, "no OpenCL platform found (backend auto uses the CPU)");
#else
        cli_error(cmd, "this build has no OpenCL (built with LX_OPENCL=0); backend auto uses the CPU");
#endif
    cli_output o;
    int rc = CLI_OK;
    if (cli_output_open(&o, outpath, cmd) != 0) rc = CLI_RUNTIME;
    else {
        int bad = cli_table_write(t, (cli_format)fmt, o.fp, 1);
        if (cli_output_close(&o, bad == 0, cmd) != 0 || bad) rc = CLI_RUNTIME;
    }
    cli_table_free(t);
    lx_cl_devices_free(d);
    lx_ctx_destroy(ctx);
    return rc;
}
