/* cmd_spd.c - `luxcalc spd`: colorimetry and photometry of spectra read from files. */
#include "cli.h"
#include "spd_batch.h"
#include "spd_metrics.h"
#include "progress.h"
#include "spd_report.h"
#include "spd_input.h"
#include "spd_unc.h"

#include <getopt.h>

#define LX__ERRMSG_MAX_CLI 1100
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc spd [OPTIONS] FILE...\n"
    "\n"
    "Reads spectral power distributions and prints, for each spectrum, absolute XYZ, xy, u'v',\n"
    "CCT and Duv, luminous efficacy of radiation, scotopic Y and the S/P ratio.\n"
    "FILE: columns (wavelength_nm, value...) or rows (id,380,381,...), separators , ; tab space,\n"
    "'#' comments, optional header (a title or Key: value lines above it are kept as fields);\n"
    "Excel CSV; CGATS/Argyll spectral files; the exports of OceanView and SpectraSuite, Sekonic,\n"
    "UPRtek and LI-COR, IES TM-27 (.spdx), AvaSoft, SpectraWiz, recognised by their content;\n"
    "'-' reads standard input. Text files are read up to 256 MB (luxcalc --max-input-mb N, or\n"
    "LX_MAX_INPUT_MB, raises it); rows-layout files on a 1 or 5 nm grid are streamed at any size\n"
    "(lines up to 4 MB).\n"
    "\n"
    "options:\n"
    "  --observer 2|10        CIE 1931 2 deg (default) or CIE 1964 10 deg observer\n"
    "  --method M             auto (default) | cie15 | exact | linear1nm\n"
    "                         cie15: sum at the data's own uniform step (CIE 015 practice)\n"
    "                         exact: exact integral of piecewise-linear data x piecewise-linear CMFs\n"
    "                         linear1nm: interpolate to 1 nm, then sum\n"
    "                         auto: cie15 for uniform 1 or 5 nm data on whole nm, else exact\n"
    "  --unit U               what the values are: relative | W/nm (Y in lm) | W/m2/nm (lx) |\n"
    "                         W/sr/m2/nm (cd/m2) | W/sr/nm (cd); default: the unit the file's format\n"
    "                         fixes (Sekonic W/m2/nm; UPRtek, LI-COR mW/m2/nm and AvaSoft irradiance\n"
    "                         uW/cm2/nm, converted), else relative\n"
    "  --metrics LIST|all     more columns after the others; LIST is comma-separated groups or column\n"
    "                         names. cri: cri_ra,cri_r1..cri_r14 (CIE 13.3), cri_valid, cri_dc;\n"
    "                         tm30: tm30_rf,tm30_rg (CIE 224 / TM-30-20), hue bins; alphaopic:\n"
    "                         melanopic_edi_lx,melanopic_der, alphaopic_sc,_mc,_lc,_rh,_mel (CIE S 026),\n"
    "                         {cyan,chlor,erythr,rhod}opic_edi/_der; mesopic: mesopic_cd_m2, mesopic_m\n"
    "                         (CIE 191; only with --unit W/sr/m2/nm); vendor: vendor_* (the results the\n"
    "                         instrument wrote into its export); par: par_ppfd,par_epar,par_ypf\n"
    "                         (umol/s per m2 for W/m2/nm; ANSI/ASABE S640, McCree 1972),\n"
    "                         par_photon_efficacy_umol_J, par_dli_mol_m2_d (with --photoperiod);\n"
    "                         hazard: hazard_blue, _thermal, _actinic_uv, _uva (IEC 62471 B, R, S_UV\n"
    "                         weighted; UV-A), their _coverage, hazard_risk_group, _risk_basis,\n"
    "                         _not_covered; binning: binning_ansi_K, _duv_offset (ANSI C78.377-2017),\n"
    "                         binning_flex_K, _duv_offset (flexible CCT), binning_sdcm,\n"
    "                         binning_sdcm_centre (MacAdam steps, IEC 60081 centres).\n"
    "                         A metric undefined for a spectrum is left empty, the reason on stderr;\n"
    "                         a band the data does not cover is \"not covered\", never 0\n"
    ;
static const char help_unc[] =
    "  --uncertainty SPEC     every quantity with its standard uncertainty and coverage interval\n"
    "                         (columns NAME_u, NAME_lo, NAME_hi; the table shows value ± u [lo, hi]).\n"
    "                         SPEC: terms joined with +: P% (uncorrelated, per cent of each value),\n"
    "                         noise=V (absolute), column=NAME[:%] (a column of the file),\n"
    "                         file=U.csv[:%], scale=P% (fully correlated), shift=Dnm (wavelength scale),\n"
    "                         bandwidth=Dnm[@Bnm], fourier=P%[:N] (Kaerhae et al. 2017),\n"
    "                         covariance=C.csv[:rel] (a full matrix on the spectrum's grid)\n"
    "  --uncertainty-method M mc (default; JCGM 101 Monte Carlo) | gum (JCGM 100) | both (and JCGM 101\n"
    "                         section 8's validation of GUM: NAME_gum_u, NAME_gum_valid)\n"
    "  --trials N|auto        Monte Carlo trials (default auto: JCGM 101 7.9's adaptive procedure)\n"
    "  --digits 1|2           auto: significant digits of u the results must settle to (default 2)\n"
    "  --coverage P           coverage probability of the intervals (default 0.95)\n"
    "  --interval symmetric|shortest  the coverage interval (default probabilistically symmetric)\n"
    "  --seed S               the trials' seed (default 0): the same results on any number of cores\n"
    "  --explain              on stderr: the trials and why that many, the budget, GUM's validation\n"
    ;
static const char help2[] =
    "  --photoperiod H        hours of light a day for the daily light integral (par_dli_mol_m2_d)\n"
    "  --subtense A           the source's full angular subtense (rad, or 0.6deg) for the IEC 62471\n"
    "                         risk group: blue light by E_B below 0.011 rad, by L_B from it on\n"
    "                         (irradiance / the source's solid angle), and the retinal thermal L_R;\n"
    "                         without it irradiance is judged as a small source, radiance as a large\n"
    "                         one (hazard_risk_basis says which)\n"
    "  --format F             table (default) | csv | json (json adds each file's \"instrument\":\n"
    "                         its layout, unit and header fields)\n"
    "  -o FILE                write the results to FILE (atomically)\n"
    "  --backend B            auto (default; also LX_BACKEND) | cpu | opencl: where batches run (and\n"
    "                         --uncertainty's Monte Carlo trials are drawn).\n"
    "                         A file of >= 1024 spectra on one uniform 1 or 5 nm grid (or any\n"
    "                         size with --backend) is integrated as a batch (vectorised, threaded;\n"
    "                         agrees with the per-spectrum path to 1e-9 relative)\n"
    "  --input-format F       auto (default) | columns | rows | cgats | oceanview | sekonic | uprtek |\n"
    "                         tm27 | avantes | spectrawiz: read every FILE as that layout; f32: raw\n"
    "  --grid START:END:STEP  little-endian float32 spectra, one after another, on the grid given by\n"
    "                         --grid (nm); spectra named 1, 2, ...\n"
    "  --skip-lines N         ignore the first N lines of every file (line numbers still count them)\n"
    "  --columns WL,V[,...]   the wavelength and value columns to read, by header name or number (from 1)\n"
    "  --wavelength-unit U    nm | um | A: the file's wavelength unit (default: from the header, else\n"
    "                         micrometres when every wavelength is below 10; -v says which)\n"
    "  --skip-bad-rows        report each malformed data row (FILE:LINE: why) and read the rest; the\n"
    "                         exit status is then 2\n"
    "  --report DIR           one PNG report per spectrum: DIR/<file-stem>_<spectrum>.png (SPD,\n"
    "                         swatch, CIE xy, R1-R15, TM-30 vector graphic, headline numbers), and\n"
    "                         where TM-30 is defined its page <file-stem>_<spectrum>_tm30.png (as\n"
    "                         the IES TM-30-20 calculator: vector graphic, Rcs/Rhs/Rf by hue bin)\n"
    "  --diagram xy|uv        the report's chromaticity diagram: CIE 1931 xy (default) or\n"
    "                         CIE 1976 u'v'\n"
    "  IMAGE.exr -o X.exr --png P.png  spectral EXR (S0.<nm>nm channels): per-pixel XYZ in cd/m2\n"
    "  -v, -q                 more messages / errors only (-q: no progress bar)\n"
    "  -h, --help             this help\n"
    "\n"
    "csv columns: file,spectrum,X,Y,Z,x,y,u_prime,v_prime,cct_K,duv,ler_lm_per_W,scotopic_Y,\n"
    "sp_ratio,radiant,method. cct_K and duv are empty where CCT has no meaning (|Duv| > 0.05 or\n"
    "outside 1000-100000 K). A bad file is reported and skipped; the exit status is then 2. A\n"
    "spectrum with no overlap with 360-830 nm is reported on stderr (its photometric values are 0).\n"
    "\n"
    "example:\n"
    "  luxcalc spd --format csv samples/spd/cie_illuminants.csv\n"
    "  luxcalc spd --unit W/nm --observer 10 lamp.csv\n"
    "  luxcalc spd --unit W/m2/nm --metrics all --format csv lamp.csv\n"
    "  luxcalc spd --metrics vendor,par,binning --format csv ESPD2021_0104_231446.xls\n"
    "  luxcalc spd --report reports/ lamp.csv\n"
    "  luxcalc spd --unit W/m2/nm --uncertainty '1%+scale=2%+shift=0.2nm' --explain lamp.csv\n";

/* in the order of cli_spd_unit_names */
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

/* The options of one run. */
typedef struct spd_args {
    const char *cmd, *outpath, *grid, *backend_text, *report_dir, *png;
    lx_observer obs;
    lx_method method;
    int fmt, unit, unit_given, f32, backend_given;
    lx_diagram diagram;
    cli_metrics msel;
    cli_unc unc;
    lx_spd_read_opts ropts;
    int reader_opts; /* any option of the text readers given (the rows-layout stream path then steps aside) */
} spd_args;

static int parse_args(int argc, char **argv, spd_args *a)
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
        {"skip-lines", required_argument, NULL, 'L'}, {"columns", required_argument, NULL, 'C'},
        {"wavelength-unit", required_argument, NULL, 'W'}, {"skip-bad-rows", no_argument, NULL, 'S'},
        {"photoperiod", required_argument, NULL, 'H'}, {"subtense", required_argument, NULL, 'A'},
        {"diagram", required_argument, NULL, 'D'},
        {NULL, 0, NULL, 0},
    };
    struct option all[sizeof opts / sizeof *opts + 16];
    size_t no = sizeof opts / sizeof *opts - 1, nu = 0;
    memcpy(all, opts, no * sizeof *opts);
    while (cli_unc_long_options[nu].name) all[no + nu] = cli_unc_long_options[nu], nu++;
    memset(&all[no + nu], 0, sizeof *all);
    const char *cmd = a->cmd;
    int c;
    char *end;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":o:vqh", all, NULL)) != -1) {
        int uo = cli_unc_option(&a->unc, c, optarg, cmd);
        if (uo < 0) return CLI_USAGE;
        if (uo > 0) continue;
        switch (c) {
        case 'b':
            if (!strcmp(optarg, "2")) a->obs = LX_OBSERVER_2;
            else if (!strcmp(optarg, "10")) a->obs = LX_OBSERVER_10;
            else return cli_error(cmd, "--observer: expected 2 or 10, not '%s'", optarg), CLI_USAGE;
            break;
        case 'm':
            if (!strcmp(optarg, "auto")) a->method = LX_METHOD_AUTO;
            else if (!strcmp(optarg, "cie15")) a->method = LX_METHOD_CIE15;
            else if (!strcmp(optarg, "exact")) a->method = LX_METHOD_EXACT;
            else if (!strcmp(optarg, "linear1nm")) a->method = LX_METHOD_LINEAR1NM;
            else return cli_error(cmd, "--method: expected auto, cie15, exact or linear1nm, not '%s'", optarg), CLI_USAGE;
            break;
        case 'u':
            if ((a->unit = cli_spd_unit_index(optarg)) < 0)
                return cli_error(cmd, "--unit: expected relative, W/nm, W/m2/nm, W/sr/m2/nm or W/sr/nm, not '%s'", optarg),
                       CLI_USAGE;
            a->unit_given = 1;
            break;
        case 'f':
            if ((a->fmt = cli_format_parse(optarg)) < 0)
                return cli_error(cmd, "--format: expected table, csv or json, not '%s'", optarg), CLI_USAGE;
            break;
        case 'M':
            if (cli_metrics_parse(&a->msel, optarg, cmd) != 0) return CLI_USAGE;
            break;
        case 'B': a->backend_text = optarg, a->backend_given = 1; break;
        case 'I':
            if (cli_spd_input_format(cmd, optarg, &a->ropts.format, &a->f32) != 0) return CLI_USAGE;
            if (a->ropts.format) a->reader_opts = 1;
            break;
        case 'L':
            a->ropts.skip_lines = strtol(optarg, &end, 10);
            if (*end || end == optarg || a->ropts.skip_lines < 0)
                return cli_error(cmd, "--skip-lines: expected a count of lines, not '%s'", optarg), CLI_USAGE;
            a->reader_opts = 1;
            break;
        case 'C': a->ropts.columns = optarg, a->reader_opts = 1; break;
        case 'W':
            if (strcmp(optarg, "nm") && strcmp(optarg, "um") && strcmp(optarg, "\xc2\xb5m") && strcmp(optarg, "A") &&
                strcmp(optarg, "\xc3\x85"))
                return cli_error(cmd, "--wavelength-unit: expected nm, um or A, not '%s'", optarg), CLI_USAGE;
            a->ropts.wavelength_unit = optarg, a->reader_opts = 1;
            break;
        case 'S': a->ropts.skip_bad_rows = 1, a->reader_opts = 1; break;
        case 'H': {
            double h = strtod(optarg, &end);
            if (*end == 'h' && end[1] == 0) end++;
            if (*end || end == optarg || !(h >= 0 && h <= 24))
                return cli_error(cmd, "--photoperiod: expected hours of light a day (0-24), not '%s'", optarg), CLI_USAGE;
            a->msel.photoperiod_h = h;
            break;
        }
        case 'A': {
            lx_ctx *ctx = cli_ctx(cmd);
            double v;
            lx_status st = ctx ? lx_quantity_parse(ctx, optarg, LX_Q_ANGLE, "rad", &v, NULL) : LX_ENOMEM;
            if (st != LX_OK || !(v > 0)) {
                cli_error(cmd, "--subtense: expected a positive angle (0.011 for rad, or 0.6deg), not '%s'%s%s", optarg,
                          st != LX_OK && ctx ? ": " : "", st != LX_OK && ctx ? lx_ctx_errmsg(ctx) : "");
                lx_ctx_destroy(ctx);
                return CLI_USAGE;
            }
            lx_ctx_destroy(ctx);
            a->msel.subtense_rad = v;
            break;
        }
        case 'G': a->grid = optarg; break;
        case 'R': a->report_dir = optarg; break;
        case 'D':
            if (!strcmp(optarg, "xy")) a->diagram = LX_DIAGRAM_XY;
            else if (!strcmp(optarg, "uv")) a->diagram = LX_DIAGRAM_UV;
            else return cli_error(cmd, "--diagram: expected xy or uv, not '%s'", optarg), CLI_USAGE;
            break;
        case 'P': a->png = optarg; break;
        case 'o': a->outpath = optarg; break;
        case 'v': cli_verbose++; break;
        case 'q': cli_quiet = 1; break;
        case 'h': cli_print_help(help), cli_print_help(help_unc), cli_print_help(help2); return -1;
        default: return cli_bad_option(cmd, argv, c);
        }
    }
    a->msel.observer = a->obs;
    return cli_unc_check(&a->unc, cmd) ? CLI_USAGE : CLI_OK;
}

/* The column units for a file's unit (base columns then metrics), built once per unit. */
typedef struct spd_cols {
    const char *names[16 + CLI_METRICS_MAX + 1];
    const char *unit_cols[5][16 + CLI_METRICS_MAX + 1];
    char ler_unit[5][16];
    int n;
} spd_cols;

/* The columns for every unit; the names are those of unit `named` (metric names can depend on the
 * unit: melanopic_edi_lx, melanopic_edl_cd_m2, ...), the header being printed once per run. */
static void build_cols(spd_cols *C, const cli_metrics *msel, int named)
{
    static const char *const base[] = {"file", "spectrum", "X", "Y", "Z", "x", "y", "u_prime", "v_prime", "cct_K", "duv",
                                       "ler_lm_per_W", "scotopic_Y", "sp_ratio", "radiant", "method"};
    for (int u = 0; u < 5; u++) {
        const char *pu = units[u].photometric, *ru = units[u].radiant;
        snprintf(C->ler_unit[u], sizeof C->ler_unit[u], "%s", u ? "lm/W" : "");
        const char *bu[] = {"", "", pu, pu, pu, "", "", "", "", "K", "", C->ler_unit[u], pu, "", ru, ""};
        memcpy(C->names, base, sizeof base);
        memcpy(C->unit_cols[u], bu, sizeof bu);
        int n = cli_metrics_columns(msel, units[u].name, C->names, C->unit_cols[u], 16);
        C->names[n] = "instrument"; /* json only */
        C->unit_cols[u][n] = "";
        C->n = n + 1;
    }
    const char *scratch[sizeof C->unit_cols[0] / sizeof C->unit_cols[0][0]];
    memcpy(C->names, base, sizeof base);
    cli_metrics_columns(msel, units[named].name, C->names, scratch, 16);
}

/* One run over the files. */
typedef struct spd_run {
    spd_args *a;
    lx_ctx *ctx;
    cli_table *t;
    spd_out so;
    spd_cols C;
    int table_unit;
    cli_spd_batch B;
    cli_reports reports;
    cli_table *row; /* --uncertainty: the plain row of a spectrum, before its uncertainty joins it */
    lx_unc_model *model; /* --uncertainty without column=: parsed once for every file */
    const char *stream_file; /* the file a stream's rows belong to */
    int rc;
} spd_run;

static void set_unit(spd_run *R, int u)
{
    if (u == R->table_unit) return;
    spd_flush(&R->so);
    cli_table_set_units(R->t, R->a->unc.spec ? R->a->unc.units[u] : R->C.unit_cols[u]);
    if (R->row) cli_table_set_units(R->row, R->C.unit_cols[u]);
    R->table_unit = u;
}

/* The unit of a file: --unit, else the one its format fixes, else relative. */
static int file_unit(spd_run *R, const lx_spd_set *set)
{
    int fu = cli_spd_unit_index(set->unit);
    if (!R->a->unit_given) return fu >= 0 ? fu : 0;
    if (set->unit && fu != R->a->unit && !cli_quiet)
        cli_error(R->a->cmd, "%s: warning: its format gives values in %s (%s); computing as --unit %s", set->file,
                  set->unit, set->unit_source ? set->unit_source : "", units[R->a->unit].name);
    return R->a->unit;
}

static void fail(spd_run *R, lx_status st)
{
    int e = cli_fail(R->a->cmd, R->ctx, st);
    if (e > R->rc) R->rc = e;
}

/* The plain row of one spectrum into t (the columns without uncertainty): 0 when it has none (the
 * reason printed, R->rc raised). line < 0: file says where ("FILE (data row N)"). */
static int plain_row(spd_run *R, cli_table *t, const lx_spd *spd, const char *file, long line, int u,
                     const lx_vendor_results *vendor, const char *inst)
{
    spd_args *a = R->a;
    char where[1100];
    if (line >= 0) snprintf(where, sizeof where, "%s:%ld", file, line);
    else snprintf(where, sizeof where, "%s", file);
    const char *label = spd->name ? spd->name : "";
    lx_colorimetry r;
    lx_status st = lx_spd_colorimetry(R->ctx, spd, a->obs, a->method, &r);
    if (st == LX_OK) st = lx_colorimetry_check(R->ctx, &r, NAN); /* before printing: no blank columns */
    if (st != LX_OK) {
        cli_error(a->cmd, "%s: spectrum '%s': %s", where, label, lx_ctx_errmsg(R->ctx));
        if (cli_exit_code(st) > R->rc) R->rc = cli_exit_code(st);
        return 0;
    }
    if (!r.cct_valid && !cli_quiet) { /* every empty cell says why */
        char why[LX__ERRMSG_MAX_CLI];
        cli_cct_reason(R->ctx, &r, a->obs, why, sizeof why);
        cli_error(a->cmd, "%s: spectrum '%s': cct_K and duv empty: %s", where, label, why);
    }
    cli_table_str(t, line >= 0 ? file : R->stream_file);
    cli_table_str(t, label);
    double v[] = {r.X, r.Y, r.Z, r.x, r.y, r.u_prime, r.v_prime, r.cct_K, r.duv, r.ler_lm_per_W, r.scotopic_Y, r.sp_ratio, r.radiant};
    for (size_t j = 0; j < sizeof v / sizeof *v; j++) cli_table_num(t, v[j]);
    cli_table_str(t, method_name(r.method));
    if (a->msel.any && cli_metrics_row(t, R->ctx, &a->msel, spd, a->method, units[u].name, &r, vendor, file, line, a->cmd) > 0 &&
        R->rc < CLI_INPUT)
        R->rc = CLI_INPUT;
    cli_table_json(t, inst);
    return 1;
}

/* cli_unc_stream's plain row: a streamed spectrum of the current file (where: "FILE (data row N)") */
static int stream_plain(void *arg, cli_table *t, const lx_spd *spd, const char *where)
{
    spd_run *R = arg;
    int rc0 = R->rc, ok = plain_row(R, t, spd, where, -1, R->table_unit, NULL, NULL);
    int e = R->rc;
    R->rc = rc0;
    return ok ? (e > rc0 ? e : 0) : -(e > 0 ? e : CLI_INPUT);
}

static void do_set(spd_run *R, lx_spd_set *set)
{
    spd_args *a = R->a;
    int e = cli_spd_report_skipped(a->cmd, set);
    if (e > R->rc) R->rc = e;
    int u = file_unit(R, set);
    set_unit(R, u);
    lx_vendor_results vendor;
    int have_vendor = lx_spd_set_vendor(R->ctx, set, &vendor) == LX_OK && vendor.count > 0;
    char *inst = cli_spd_instrument_json(set);
    cli_spd_batch *B = &R->B;
    B->unit = units[u].name, B->vendor = have_vendor ? &vendor : NULL, B->instrument = inst;
    if ((!a->msel.any || cli_metrics_batchable(&a->msel)) && !a->report_dir && !a->unc.spec && cli_spd_batchable(B, set)) {
        lx_status st = cli_spd_batch_set(B, set);
        if (st != LX_OK) fail(R, st);
        B->vendor = NULL, B->instrument = NULL;
        free(inst);
        return;
    }
    B->vendor = NULL, B->instrument = NULL;
    cli_table *t = a->unc.spec ? R->row : R->t;
    lx_unc_model *own = NULL, *model = R->model;
    if (a->unc.spec && !model) { /* column= refers to this file's columns */
        lx_status ms = lx_unc_model_parse(R->ctx, a->unc.spec, set, &own);
        if (ms != LX_OK) {
            fail(R, ms);
            free(inst);
            return;
        }
        model = own;
    }
    if (set->count >= (a->report_dir || a->unc.spec ? 8 : 256)) cli_progress_start(set->count, set->file);
    for (size_t k = 0; k < set->count; k++) {
        cli_progress_update(k);
        if (model && lx_unc_model_uses(model, &set->spd[k])) continue; /* a column of uncertainties */
        long line = set->line ? set->line[k] : 0L;
        int ok = plain_row(R, t, &set->spd[k], set->file, line, u, have_vendor ? &vendor : NULL, inst);
        if (ok && model) {
            int e2 = cli_unc_row(&a->unc, R->t, t, R->ctx, &set->spd[k], a->obs, a->method, model, set->file, line, a->cmd);
            if (e2 > R->rc) R->rc = e2;
            if (cli_table_rows(R->t) % 64 == 0) spd_flush(&R->so); /* a long batch goes out as it comes */
        }
        if (ok && a->report_dir) {
            R->reports.opts.unit = units[u].name;
            int re = cli_spd_report(&R->reports, R->ctx, set->file, k, &set->spd[k]);
            if (re > R->rc) R->rc = re;
        }
    }
    cli_progress_end();
    lx_unc_model_free(own);
    free(inst);
}

static void do_file(spd_run *R, const char *arg, double g_start, double g_step, size_t g_n)
{
    spd_args *a = R->a;
    if (a->f32) {
        set_unit(R, a->unit);
        R->B.unit = units[a->unit].name;
        lx_status st = cli_spd_f32_file(&R->B, arg, g_start, g_step, g_n);
        if (st != LX_OK && cli_exit_code(st) > R->rc) R->rc = cli_exit_code(st);
        spd_flush(&R->so);
        return;
    }
    /* rows-layout files: streamed, part by part on every core (spd_stream.c); else the general
     * reader (a pipe the stream looked at comes back read) */
    set_unit(R, a->unit);
    R->B.unit = units[a->unit].name;
    lx_spd_set *set = NULL;
    if (a->unc.spec && R->model && !a->report_dir && !a->reader_opts) { /* a large rows-layout file: streamed */
        cli_unc_rows rows = {.plain = stream_plain, .flush = spd_flush, .arg = R, .row = R->row, .dst = R->t, .flush_arg = &R->so};
        int rc = 0;
        R->stream_file = arg;
        if (cli_unc_stream(&a->unc, R->ctx, arg, R->model, a->obs, a->method, &rows, a->cmd, &rc)) {
            if (rc > R->rc) R->rc = rc;
            spd_flush(&R->so);
            return;
        }
    }
    int streamed = (!a->msel.any || cli_metrics_batchable(&a->msel)) && !a->report_dir && !a->reader_opts && !a->unc.spec
                       ? cli_spd_batch_file(&R->B, arg, &set) : 0;
    if (streamed < 0 && -streamed > R->rc) R->rc = -streamed;
    if (streamed) {
        spd_flush(&R->so);
        return;
    }
    lx_status st = set ? LX_OK : lx_spd_read_file_opts(R->ctx, arg, &a->ropts, &set);
    if (st != LX_OK) {
        fail(R, st);
        return;
    }
    do_set(R, set);
    lx_spd_set_free(set);
    spd_flush(&R->so);
}

int cmd_spd(int argc, char **argv)
{
    spd_args a;
    memset(&a, 0, sizeof a);
    a.cmd = "spd", a.obs = LX_OBSERVER_2, a.method = LX_METHOD_AUTO, a.fmt = CLI_FMT_TABLE;
    a.backend_given = getenv("LX_BACKEND") != NULL, a.backend_text = getenv("LX_BACKEND");
    a.msel.photoperiod_h = NAN;
    a.diagram = LX_DIAGRAM_XY;
    int pe = parse_args(argc, argv, &a);
    if (pe < 0) return CLI_OK; /* --help */
    if (pe != CLI_OK) return pe;
    const char *cmd = a.cmd;
    if (optind >= argc) {
        cli_error(cmd, "no input file (use - for standard input)");
        return CLI_USAGE;
    }
    double g_start = 0, g_step = 0;
    size_t g_n = 0;
    if (a.f32 && (!a.grid || cli_spd_parse_grid(a.grid, &g_start, &g_step, &g_n) != 0))
        return cli_error(cmd, "--input-format f32 needs --grid START:END:STEP in nm (END - START a whole number of steps), not '%s'",
                         a.grid ? a.grid : ""), CLI_USAGE;
    if (a.f32 && a.msel.any) return cli_error(cmd, "--metrics is not available with --input-format f32"), CLI_USAGE;
    if (a.f32 && a.report_dir)
        return cli_error(cmd, "--report is not available with --input-format f32 (reports need the text path, one spectrum at a time)"), CLI_USAGE;
    if (a.f32 && a.reader_opts)
        return cli_error(cmd, "--skip-lines, --columns, --wavelength-unit and --skip-bad-rows apply to text files, not to --input-format f32"), CLI_USAGE;
    int exr = !a.f32 && strcmp(argv[optind], "-") != 0 && cli_is_exr(argv[optind]);
    if (exr && (argc - optind != 1 || a.msel.any || a.report_dir))
        return cli_error(cmd, "a spectral EXR image is processed alone, without --metrics or --report"), CLI_USAGE;
    if (a.png && !exr) return cli_error(cmd, "--png applies to a spectral EXR image input"), CLI_USAGE;
    if (a.unc.spec && (exr || a.f32))
        return cli_error(cmd, "--uncertainty applies to spectra read from text (not to %s)", exr ? "a spectral EXR image" : "--input-format f32"),
               CLI_USAGE;
    lx_ctx *ctx = cli_ctx(cmd);
    if (!ctx) return CLI_RUNTIME;
    lx_backend backend = LX_BACKEND_AUTO;
    if (a.backend_text && lx_backend_parse(ctx, a.backend_text, &backend) != LX_OK) {
        cli_error(cmd, "--backend: expected auto, cpu or opencl, not '%s'", a.backend_text);
        lx_ctx_destroy(ctx);
        return CLI_USAGE;
    }
    a.unc.o.backend = backend; /* --backend: where the Monte Carlo trials are drawn, too */
    if (exr) {
        int e = cli_spd_exr(ctx, cmd, argv[optind], a.outpath, a.png, a.obs, backend, (cli_format)a.fmt);
        lx_ctx_destroy(ctx);
        return e;
    }
    lx_unc_model *model = NULL;
    if (a.unc.spec && !strstr(a.unc.spec, "column=")) { /* the model once, its syntax a usage error */
        lx_status ms = lx_unc_model_parse(ctx, a.unc.spec, NULL, &model);
        if (ms != LX_OK) {
            int e = cli_fail(cmd, ctx, ms);
            lx_ctx_destroy(ctx);
            return ms == LX_EINVAL ? CLI_USAGE : e;
        }
    }
    if (a.report_dir && cli_make_dir(cmd, "--report", a.report_dir) != 0) {
        lx_unc_model_free(model);
        lx_ctx_destroy(ctx);
        return CLI_INPUT;
    }
    spd_run *R = calloc(1, sizeof *R);
    if (!R) {
        lx_unc_model_free(model);
        lx_ctx_destroy(ctx);
        return cli_error(cmd, "out of memory"), CLI_RUNTIME;
    }
    R->a = &a, R->ctx = ctx, R->model = model;
    build_cols(&R->C, &a.msel, a.unit);
    if (a.unc.spec) {
        const char *const *uc[5] = {R->C.unit_cols[0], R->C.unit_cols[1], R->C.unit_cols[2], R->C.unit_cols[3], R->C.unit_cols[4]};
        if (cli_unc_columns(&a.unc, R->C.names, uc, R->C.n) != 0 || !(R->row = cli_table_new(R->C.n, R->C.names, R->C.unit_cols[a.unit]))) {
            cli_unc_free(&a.unc);
            lx_unc_model_free(model);
            free(R);
            lx_ctx_destroy(ctx);
            return cli_error(cmd, "out of memory"), CLI_RUNTIME;
        }
        R->t = cli_table_new(a.unc.n, a.unc.names, a.unc.units[a.unit]);
        cli_unc_table_flags(&a.unc, R->t);
    } else {
        R->t = cli_table_new(R->C.n, R->C.names, R->C.unit_cols[a.unit]);
    }
    cli_table_json_only(R->t, a.unc.spec ? a.unc.n - 2 : R->C.n - 1); /* "instrument" */
    R->table_unit = a.unit;
    R->so.t = R->t, R->so.fmt = (cli_format)a.fmt, R->so.cmd = cmd, R->so.path = a.outpath;
    cli_spd_batch B = {ctx, cmd, R->t, a.obs, a.method, backend, a.backend_given, spd_flush, &R->so, 0,
                       a.msel.any ? &a.msel : NULL, units[a.unit].name, NULL, NULL, (cli_format)a.fmt,
                       spd_out_fp, a.outpath && strcmp(a.outpath, "-") != 0, &a.ropts};
    R->B = B;
    R->reports.cmd = cmd, R->reports.dir = a.report_dir;
    R->reports.opts.observer = a.obs, R->reports.opts.unit = units[a.unit].name, R->reports.opts.diagram = a.diagram;
    int nfiles = 0;
    char **files = cli_expand_files(argc - optind, argv + optind, &nfiles);
    for (int fi = 0; files && fi < nfiles; fi++) do_file(R, files[fi], g_start, g_step, g_n);
    int rc = R->rc;
    if (R->B.rejected && rc < CLI_INPUT) rc = CLI_INPUT; /* batch spectra reported instead of printed */
    /* nothing computed and something failed: leave any existing output file as it was */
    if (!(rc != CLI_OK && cli_table_rows(R->t) == 0)) {
        if (!R->so.opened && spd_open(&R->so) != 0) rc = CLI_INPUT;
        if (R->so.opened) {
            int ok = !R->so.failed && cli_table_flush(R->t, R->so.fmt, R->so.o.fp, 0, 1) == 0;
            int e = cli_output_close(&R->so.o, ok, cmd);
            if (e || !ok) rc = e ? e : rc ? rc : CLI_RUNTIME;
        }
    }
    cli_free_files(files, nfiles);
    cli_reports_free(&R->reports);
    cli_table_free(R->t);
    cli_table_free(R->row);
    cli_unc_free(&a.unc);
    lx_unc_model_free(model);
    free(R);
    lx_ctx_destroy(ctx);
    return rc;
}
