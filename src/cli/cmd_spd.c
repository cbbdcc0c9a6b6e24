/* cmd_spd.c - `luxcalc spd`: colorimetry and photometry of spectra read from files. */
#include "cli.h"
#include "spd_batch.h"
#include "spd_metrics.h"
#include "progress.h"
#include "spd_report.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc spd [OPTIONS] FILE...\n"
    "\n"
    "Reads spectral power distributions and prints, for each spectrum, absolute XYZ, xy, u'v',\n"
    "CCT and Duv, luminous efficacy of radiation, scotopic Y and the S/P ratio.\n"
    "FILE: columns (wavelength_nm, value...) or rows (id,380,381,...), separators , ; tab space,\n"
    "'#' comments, optional header; CGATS/Argyll spectral files; '-' reads standard input.\n"
    "Text files are read up to 256 MB (luxcalc --max-input-mb N, or LX_MAX_INPUT_MB, raises it);\n"
    "rows-layout files on a 1 or 5 nm grid are streamed at any size (lines up to 4 MB).\n"
    "\n"
    "options:\n"
    "  --observer 2|10        CIE 1931 2 deg (default) or CIE 1964 10 deg observer\n"
    "  --method M             auto (default) | cie15 | exact | linear1nm\n"
    "                         cie15: sum at the data's own uniform step (CIE 015 practice)\n"
    "                         exact: exact integral of piecewise-linear data x piecewise-linear CMFs\n"
    "                         linear1nm: interpolate to 1 nm, then sum\n"
    "                         auto: cie15 for uniform 1 or 5 nm data on whole nm, else exact\n"
    "  --unit U               what the values are: relative (default) | W/nm (Y in lm) |\n"
    "                         W/m2/nm (lx) | W/sr/m2/nm (cd/m2) | W/sr/nm (cd)\n"
    "  --metrics LIST|all     colour rendering and photobiology columns after the others; LIST is\n"
    "                         comma-separated groups (cri, tm30, alphaopic, mesopic) or column\n"
    "                         names: cri_ra,cri_r1..cri_r14 (CIE 13.3), tm30_rf,tm30_rg (CIE 224 /\n"
    "                         TM-30-20), melanopic_edi_lx,melanopic_der, alphaopic_sc,_mc,_lc,_rh,_mel\n"
    "                         (CIE S 026), then cri_valid,cri_dc, tm30_rf_h1..16, tm30_rcs_h1..16,\n"
    "                         tm30_rhs_h1..16, {cyan,chlor,erythr,rhod}opic_edi/_der, mesopic_cd_m2,\n"
    "                         mesopic_m (CIE 191; only with --unit W/sr/m2/nm). alphaopic_* are\n"
    "                         irradiances in W/m2 and *_edi illuminances in lx for --unit W/m2/nm\n"
    "                         (W/sr/m2/nm: W/(sr m2) and equivalent daylight luminance cd/m2; W/nm:\n"
    "                         W and lm; relative: same arithmetic, no unit). A metric that is\n"
    "                         undefined for a spectrum (far off the locus, truncated data) is left\n"
    "                         empty and the reason printed on stderr.\n"
    "  --format F             table (default) | csv | json\n"
    "  -o FILE                write the results to FILE (atomically)\n"
    "  --backend B            auto (default; also LX_BACKEND) | cpu | opencl: where batches run.\n"
    "                         A file of >= 1024 spectra on one uniform 1 or 5 nm grid (or any\n"
    "                         size with --backend) is integrated as a batch (vectorised, threaded;\n"
    "                         agrees with the per-spectrum path to 1e-9 relative)\n"
    "  --input-format F       text (default) | f32: raw little-endian float32 spectra, one after\n"
    "  --grid START:END:STEP  another, on the grid given by --grid (nm); spectra named 1, 2, ...\n"
    "  --report DIR           one PNG report per spectrum: DIR/<file-stem>_<spectrum>.png (SPD,\n"
    "                         swatch, CIE xy, R1-R14, TM-30 vector graphic, headline numbers)\n"
    "  IMAGE.exr -o X.exr --png P.png  spectral EXR (S0.<nm>nm channels): per-pixel XYZ in cd/m2\n"
    "  -v, -q                 more messages / errors only (-q: no progress bar)\n"
    "  -h, --help             this help\n"
    "\n"
    "csv columns: file,spectrum,X,Y,Z,x,y,u_prime,v_prime,cct_K,duv,ler_lm_per_W,scotopic_Y,\n"
    "sp_ratio,radiant,method. cct_K and duv are empty where CCT has no meaning (|Duv| > 0.05 or\n"
    "outside 1000-100000 K). A bad file is reported and skipped; the exit status is then 2.\n"
    "\n"
    "example:\n"
    "  luxcalc spd --format csv samples/spd/cie_illuminants.csv\n"
    "  luxcalc spd --unit W/nm --observer 10 lamp.csv\n"
    "  luxcalc spd --unit W/m2/nm --metrics all --format csv lamp.csv\n"
    "  luxcalc spd --report reports/ lamp.csv\n";

static const struct {
    const char *name, *photometric, *radiant;
} units[] = {
    {"relative", "", ""},
    {"W/nm", "lm", "W"},
    {"W/m2/nm", "lx", "W/m2"},
    {"W/sr/m2/nm", "cd/m2", "W/(sr m2)"},
    {"W/sr/nm", "cd", "W/sr"},
};

static const char *method_name(lx_method m)
{
    switch (m) {
    case LX_METHOD_CIE15: return "cie15";
    case LX_METHOD_EXACT: return "exact";
    case LX_METHOD_LINEAR1NM: return "linear1nm";
    default: return "auto";
    }
}

/* Output opened on the first rows (so a run that computes nothing leaves -o FILE untouched),
 * then streamed: rows are written as files and chunks complete. */
typedef struct spd_out {
    const char *path;
    cli_table *t;
    cli_format fmt;
    int opened, failed;
    const char *cmd;
    cli_output o;
} spd_out;

static int spd_open(spd_out *so)
{
    if (cli_output_open(&so->o, so->path, so->cmd) != 0) return so->failed = 1, -1;
    so->opened = 1;
    return 0;
}

static FILE *spd_out_fp(void *arg)
{
    spd_out *so = arg;
    if (!so->opened && !so->failed) spd_open(so);
    return so->failed ? NULL : so->o.fp;
}

static void spd_flush(void *arg)
{
    spd_out *so = arg;
    if (so->failed || cli_table_rows(so->t) == 0) return;
    if (!so->opened && spd_open(so) != 0) return;
    if (cli_table_flush(so->t, so->fmt, so->o.fp, 0, 0) != 0) so->failed = 1;
}

int cmd_spd(int argc, char **argv)
{
    static const struct option opts[] = {
        {"observer", required_argument, NULL, 'b'}, {"method", required_argument, NULL, 'm'},
        {"unit", required_argument, NULL, 'u'},     {"format", required_argument, NULL, 'f'},
        {"output", required_argument, NULL, 'o'},   {"verbose", no_argument, NULL, 'v'},
        {"quiet", no_argument, NULL, 'q'},          {"help", no_argument, NULL, 'h'},
        {"metrics", required_argument, NULL, 'M'},
        {"backend", required_argument, NULL, 'B'},  {"input-format", required_argument, NULL, 'I'},
        {"grid", required_argument, NULL, 'G'},
        {"report", required_argument, NULL, 'R'}, {"png", required_argument, NULL, 'P'},
        {NULL, 0, NULL, 0},
    };
    const char *cmd = "spd", *outpath = NULL;
    lx_observer obs = LX_OBSERVER_2;
    lx_method method = LX_METHOD_AUTO;
    int fmt = CLI_FMT_TABLE, unit = 0, c;
    cli_metrics msel = {{0}, 0};
    int f32 = 0, backend_given = getenv("LX_BACKEND") != NULL;
    const char *grid = NULL, *backend_text = getenv("LX_BACKEND");
    const char *report_dir = NULL, *png = NULL;
    optind = 1;
    while ((c = getopt_long(argc, argv, "o:vqh", opts, NULL)) != -1) {
        switch (c) {
        case 'b':
            if (!strcmp(optarg, "2")) obs = LX_OBSERVER_2;
            else if (!strcmp(optarg, "10")) obs = LX_OBSERVER_10;
            else return cli_error(cmd, "--observer: expected 2 or 10, not '%s'", optarg), CLI_USAGE;
            break;
        case 'm':
            if (!strcmp(optarg, "auto")) method = LX_METHOD_AUTO;
            else if (!strcmp(optarg, "cie15")) method = LX_METHOD_CIE15;
            else if (!strcmp(optarg, "exact")) method = LX_METHOD_EXACT;
            else if (!strcmp(optarg, "linear1nm")) method = LX_METHOD_LINEAR1NM;
            else return cli_error(cmd, "--method: expected auto, cie15, exact or linear1nm, not '%s'", optarg), CLI_USAGE;
            break;
        case 'u':
            unit = -1;
            for (int i = 0; i < (int)(sizeof units / sizeof *units); i++)
                if (!strcmp(optarg, units[i].name)) unit = i;
            if (unit < 0)
                return cli_error(cmd, "--unit: expected relative, W/nm, W/m2/nm, W/sr/m2/nm or W/sr/nm, not '%s'", optarg),
                       CLI_USAGE;
            break;
        case 'f':
            if ((fmt = cli_format_parse(optarg)) < 0)
                return cli_error(cmd, "--format: expected table, csv or json, not '%s'", optarg), CLI_USAGE;
            break;
        case 'M':
            if (cli_metrics_parse(&msel, optarg, cmd) != 0) return CLI_USAGE;
            break;
        case 'B': backend_text = optarg, backend_given = 1; break;
        case 'I':
            if (!strcmp(optarg, "f32")) f32 = 1;
            else if (!strcmp(optarg, "text")) f32 = 0;
            else return cli_error(cmd, "--input-format: expected text or f32, not '%s'", optarg), CLI_USAGE;
            break;
        case 'G': grid = optarg; break;
        case 'R': report_dir = optarg; break;
        case 'P': png = optarg; break;
        case 'o': outpath = optarg; break;
        case 'v': cli_verbose++; break;
        case 'q': cli_quiet = 1; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: fprintf(stderr, "%s", help); return CLI_USAGE;
        }
    }
    if (optind >= argc) {
        cli_error(cmd, "no input file (use - for standard input)");
        return CLI_USAGE;
    }
    double g_start = 0, g_step = 0;
    size_t g_n = 0;
    if (f32 && (!grid || cli_spd_parse_grid(grid, &g_start, &g_step, &g_n) != 0))
        return cli_error(cmd, "--input-format f32 needs --grid START:END:STEP in nm (END - START a whole number of steps), not '%s'",
                         grid ? grid : ""), CLI_USAGE;
    if (f32 && msel.any) return cli_error(cmd, "--metrics is not available with --input-format f32"), CLI_USAGE;
    if (f32 && report_dir)
        return cli_error(cmd, "--report is not available with --input-format f32 (reports need the text path, one spectrum at a time)"), CLI_USAGE;
    int exr = !f32 && strcmp(argv[optind], "-") != 0 && cli_is_exr(argv[optind]);
    if (exr && (argc - optind != 1 || msel.any || report_dir))
        return cli_error(cmd, "a spectral EXR image is processed alone, without --metrics or --report"), CLI_USAGE;
    if (png && !exr) return cli_error(cmd, "--png applies to a spectral EXR image input"), CLI_USAGE;
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    lx_backend backend = LX_BACKEND_AUTO;
    if (backend_text && lx_backend_parse(ctx, backend_text, &backend) != LX_OK) {
        cli_error(cmd, "--backend: expected auto, cpu or opencl, not '%s'", backend_text);
        lx_ctx_destroy(ctx);
        return CLI_USAGE;
    }
    if (exr) {
        int e = cli_spd_exr(ctx, cmd, argv[optind], outpath, png, obs, backend, (cli_format)fmt);
        lx_ctx_destroy(ctx);
        return e;
    }
    if (report_dir && cli_report_dir(cmd, report_dir) != 0) {
        lx_ctx_destroy(ctx);
        return CLI_INPUT;
    }

    const char *pu = units[unit].photometric, *ru = units[unit].radiant;
    static char ler_unit[32];
    snprintf(ler_unit, sizeof ler_unit, "%s", unit ? "lm/W" : "");
    const char *names[] = {"file", "spectrum", "X", "Y", "Z", "x", "y", "u_prime", "v_prime", "cct_K", "duv",
                           "ler_lm_per_W", "scotopic_Y", "sp_ratio", "radiant", "method"};
    const char *unitnames[] = {"", "", pu, pu, pu, "", "", "", "", "K", "", ler_unit, pu, "", ru, ""};
    int ncols = (int)(sizeof names / sizeof *names);
    const char *allnames[sizeof names / sizeof *names + CLI_METRICS_MAX], *allunits[sizeof allnames / sizeof *allnames];
    memcpy(allnames, names, sizeof names);
    memcpy(allunits, unitnames, sizeof unitnames);
    ncols = cli_metrics_columns(&msel, units[unit].name, allnames, allunits, ncols);
    cli_table *t = cli_table_new(ncols, allnames, allunits);
    int rc = CLI_OK;
    spd_out so;
    memset(&so, 0, sizeof so);
    so.t = t, so.fmt = (cli_format)fmt, so.cmd = cmd;
    cli_spd_batch B = {ctx, cmd, t, obs, method, backend, backend_given, spd_flush, &so, 0, (cli_format)fmt, spd_out_fp,
                       outpath && strcmp(outpath, "-") != 0};
    so.path = outpath;
    int nfiles = 0;
    char **files = cli_expand_files(argc - optind, argv + optind, &nfiles);
    for (int fi = 0; files && fi < nfiles; fi++) {
        char *arg = files[fi];
        if (f32) {
            lx_status st = cli_spd_f32_file(&B, arg, g_start, g_step, g_n);
            if (st != LX_OK && cli_exit_code(st) > rc) rc = cli_exit_code(st);
            spd_flush(&so);
            continue;
        }
        /* rows-layout files: streamed, part by part on every core (spd_stream.c); else the general
         * reader (a pipe the stream looked at comes back read) */
        lx_spd_set *set = NULL;
        int streamed = !msel.any && !report_dir ? cli_spd_batch_file(&B, arg, &set) : 0;
        if (streamed < 0 && -streamed > rc) rc = -streamed;
        if (streamed) {
            spd_flush(&so);
            continue;
        }
        lx_status st = set ? LX_OK : lx_spd_read_file(ctx, arg, &set);
        if (st != LX_OK) {
            int e = cli_fail(cmd, ctx, st);
            if (e > rc) rc = e;
            continue;
        }
        if (!msel.any && !report_dir && cli_spd_batchable(&B, set)) {
            if ((st = cli_spd_batch_set(&B, set)) != LX_OK) {
                int e = cli_fail(cmd, ctx, st);
                if (e > rc) rc = e;
            }
            lx_spd_set_free(set);
            continue;
        }
        if (set->count >= (report_dir ? 8 : 256)) cli_progress_start(set->count, set->file);
        for (size_t k = 0; k < set->count; k++) {
            cli_progress_update(k);
            lx_colorimetry r;
            st = lx_spd_colorimetry(ctx, &set->spd[k], obs, method, &r);
            if (st == LX_OK) st = lx_colorimetry_check(ctx, &r, NAN); /* before printing: no blank columns */
            if (st != LX_OK) {
                cli_error(cmd, "%s:%ld: spectrum '%s': %s", set->file, set->line ? set->line[k] : 0L,
                          set->spd[k].name ? set->spd[k].name : "", lx_ctx_errmsg(ctx));
                int e = cli_exit_code(st);
                if (e > rc) rc = e;
                continue;
            }
            cli_table_str(t, set->file);
            cli_table_str(t, set->spd[k].name ? set->spd[k].name : "");
            double v[] = {r.X, r.Y, r.Z, r.x, r.y, r.u_prime, r.v_prime, r.cct_K, r.duv, r.ler_lm_per_W,
                          r.scotopic_Y, r.sp_ratio, r.radiant};
            for (size_t j = 0; j < sizeof v / sizeof *v; j++) cli_table_num(t, v[j]);
            cli_table_str(t, method_name(r.method));
            if (msel.any && cli_metrics_row(t, ctx, &msel, &set->spd[k], method, units[unit].name, &r, set->file,
                                            set->line ? set->line[k] : 0L, cmd) > 0 && rc < CLI_INPUT)
                rc = CLI_INPUT;
            if (report_dir) {
                int e = cli_spd_report(ctx, cmd, report_dir, set->file, k, &set->spd[k], obs);
                if (e > rc) rc = e;
            }
        }
        cli_progress_end();
        lx_spd_set_free(set);
        spd_flush(&so);
    }
    if (B.rejected && rc < CLI_INPUT) rc = CLI_INPUT; /* batch spectra reported instead of printed */
    /* nothing computed and something failed: leave any existing output file as it was */
    if (!(rc != CLI_OK && cli_table_rows(t) == 0)) {
        if (!so.opened && spd_open(&so) != 0) rc = CLI_INPUT;
        if (so.opened) {
            int ok = !so.failed && cli_table_flush(t, so.fmt, so.o.fp, 0, 1) == 0;
            if (cli_output_close(&so.o, ok, cmd) != 0 || !ok) rc = rc ? rc : CLI_INPUT;
        }
    }
    cli_free_files(files, nfiles);
    cli_table_free(t);
    lx_ctx_destroy(ctx);
    return rc;
}
