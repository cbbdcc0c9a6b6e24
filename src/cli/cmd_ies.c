/* cmd_ies.c - `luxcalc ies`: summaries of IES LM-63 / EULUMDAT files (flux integrated from the
 * table, peak, beam and field angles, symmetry) and writing LM-63-2002 from a file or a model. */
#include "cli.h"
#include "lighting.h"

#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: luxcalc ies [OPTIONS] FILE...\n"
    "       luxcalc ies --write OUT.ies (FILE | --model point|warn|lambert --flux F [...])\n"
    "\n"
    "Reads IES LM-63 files (1986, 1991, 1995, 2002, 2019) and EULUMDAT (.ldt) files and prints,\n"
    "per file: file,format,lumens,max_intensity_cd,beam_angle_deg,field_angle_deg,symmetry, then\n"
    "rated_lumens (the header's lamp lumens, or the stated luminaire lumens for absolute photometry),\n"
    "stated_lumens (the luminaire flux the file states: [_ABSOLUTELUMENS], EULUMDAT lamps x LORL),\n"
    "lumens_diff (lumens / stated_lumens - 1), photometric_type, planes, angles, the C90-C270 beam\n"
    "and field angles, downward_fraction, the opening's shape (point, rectangle, round, ...), its\n"
    "width_m, length_m, height_m and diameter_m (round openings), lor (relative photometry: lumens /\n"
    "lamp lumens), input_watts, efficacy_lm_per_W (lumens / input watts), manufacturer, catalog.\n"
    "lumens is the exact integral over the sphere of the bilinear interpolant of the table. Beam and\n"
    "field angles: full angles to 50 % and 10 % of the peak in the C0-C180 plane.\n"
    "\n"
    "options:\n"
    "  --format table|csv|json   output format (default table)\n"
    "  -o FILE                   write the results to FILE (atomically)\n"
    "  --write OUT.ies           write LM-63-2002: the one FILE converted (its test, laboratory,\n"
    "                            date, lamp and catalogue fields kept), or the --model\n"
    "  --model point|warn|lambert  isotropic point, Warn spot (I = (S+1)F/2pi cos^S), Lambertian panel\n"
    "  --flux F                  model flux (default unit lm)\n"
    "  --exponent S              Warn exponent (or --beam ANGLE: full 50 % beam angle)\n"
    "  --beam ANGLE              Warn beam angle (e.g. 30deg)\n"
    "  --width W, --length L     luminous opening in m (LM-63: width along C90-C270, length\n"
    "                            along C0-C180)\n"
    "  --step ANGLE              gamma step of the written table (default 1deg, finer for spots)\n"
    "  --catalog TEXT            the [LUMCAT] text of the written file\n"
    "\n"
    "examples:\n"
    "  luxcalc ies --format csv downlight.ies street.ldt\n"
    "  luxcalc ies --write spot30.ies --model warn --beam 30deg --flux 1000lm\n";

static int write_ies(lx_ctx *ctx, const lx_luminaire *l, const char *path)
{
    char *text = NULL;
    size_t len = 0;
    lx_status st = lx_luminaire_write_ies(ctx, l, &text, &len);
    if (st) return cli_fail("ies", ctx, st);
    cli_output o;
    if (cli_output_open(&o, path, "ies")) {
        lx_text_free(text);
        return CLI_RUNTIME;
    }
    size_t w = fwrite(text, 1, len, o.fp);
    lx_text_free(text);
    if (cli_output_close(&o, w == len, "ies") || w != len) return CLI_RUNTIME;
    return CLI_OK;
}

/* The luminous opening's shape from the signs of its dimensions (LM-63-2019 Table 1: negative
 * values are round: width = length < 0 a circle of that diameter, unequal an ellipse; with a
 * height a vertical cylinder, all three equal and negative a sphere; EULUMDAT writes a round
 * area as its diameter and a width of 0). */
static const char *opening(const lx_luminaire *l, double *diameter)
{
    double w = l->width_m, len = l->length_m, h = l->height_m;
    *diameter = NAN;
    if (w == 0 && len == 0 && h == 0) return "point";
    if (l->format == LX_LUM_EULUMDAT && (w == 0) != (len == 0) && w >= 0 && len >= 0) /* EULUMDAT: width 0 is round */
        return *diameter = w > len ? w : len, h > 0 ? "vertical cylinder" : "round";
    if (w >= 0 && len >= 0) return h > 0 ? "box" : "rectangle";
    if (w < 0 && len < 0) {
        if (w == len && h < 0 && h == w) return *diameter = -w, "sphere";
        if (w == len) return *diameter = -w, h > 0 ? "vertical cylinder" : "round";
        return h > 0 ? "elliptical cylinder" : "ellipse";
    }
    return "other";
}

/* the summary of every FILE (argv[first] ...): one row each, a bad file reported and skipped */
static int summaries(lx_ctx *ctx, int first, int argc, char **argv, cli_format fmt, const char *outpath)
{
    int rc = CLI_OK;
    static const char *const names[] = {"file", "format", "lumens", "max_intensity_cd", "beam_angle_deg", "field_angle_deg",
                                        "symmetry", "rated_lumens", "stated_lumens", "lumens_diff", "photometric_type",
                                        "planes", "angles", "beam_angle_c90_deg", "field_angle_c90_deg",
                                        "downward_fraction", "shape", "width_m", "length_m", "height_m", "diameter_m",
                                        "lor", "input_watts", "efficacy_lm_per_W", "manufacturer", "catalog"};
    static const char *const units[] = {NULL, NULL, "lm", "cd", "deg", "deg", NULL, "lm", "lm", NULL, NULL, NULL, NULL,
                                        "deg", "deg", NULL, NULL, "m", "m", "m", "m", NULL, "W", "lm/W", NULL, NULL};
    cli_table *t = cli_table_new(26, names, units);
    if (!t) return cli_error("ies", "out of memory"), CLI_RUNTIME;
    for (int i = first; i < argc; i++) {
        lx_luminaire *l = NULL;
        lx_lum_summary s;
        lx_status st = lx_luminaire_read_file(ctx, argv[i], &l);
        if (!st) st = lx_luminaire_summary(ctx, l, &s);
        if (st) {
            int r = cli_fail("ies", ctx, st);
            if (r > rc) rc = r;
            lx_luminaire_free(l);
            continue;
        }
        double rated = isfinite(l->lamp_lumens) ? l->lamp_lumens : l->stated_lumens;
        cli_table_str(t, argv[i]);
        cli_table_str(t, lx_lum_format_name(l->format));
        cli_table_num(t, s.lumens);
        cli_table_num(t, s.max_intensity_cd);
        cli_table_num(t, s.beam_angle_deg);
        cli_table_num(t, s.field_angle_deg);
        cli_table_str(t, lx_lum_symmetry_name(l->symmetry));
        cli_table_num(t, rated);
        cli_table_num(t, l->stated_lumens);
        cli_table_num(t, isfinite(l->stated_lumens) ? s.lumens / l->stated_lumens - 1 : NAN);
        cli_table_str(t, l->photometric_type == 1 ? "C" : "B");
        cli_table_int(t, (long long)l->n_h);
        cli_table_int(t, (long long)l->n_v);
        cli_table_num(t, s.beam_angle_c90_deg);
        cli_table_num(t, s.field_angle_c90_deg);
        cli_table_num(t, s.downward_fraction);
        double dia = NAN;
        cli_table_str(t, opening(l, &dia));
        cli_table_num(t, isfinite(dia) ? dia : fabs(l->width_m)); /* round: its diameter both ways */
        cli_table_num(t, isfinite(dia) ? dia : fabs(l->length_m));
        cli_table_num(t, fabs(l->height_m));
        cli_table_num(t, dia);
        /* the light output ratio of relative photometry: the luminaire's flux over its lamps' */
        cli_table_num(t, !l->absolute && rated > 0 ? s.lumens / rated : NAN);
        double watts = l->input_watts > 0 ? l->input_watts : NAN;
        cli_table_num(t, watts);
        cli_table_num(t, s.lumens / watts);
        cli_table_str(t, l->manufacturer ? l->manufacturer : "");
        cli_table_str(t, l->catalog ? l->catalog : "");
        lx_luminaire_free(l);
    }
    if (cli_table_rows(t) > 0) {
        int r = lt_write("ies", t, fmt, outpath);
        if (r > rc) rc = r;
    }
    cli_table_free(t);
    return rc;
}

/* The --model options as given (NULL when absent). */
typedef struct {
    const char *model, *flux, *exp, *beam, *w, *l, *step;
} model_args;

/* --exponent or --beam (exactly one) into m->exponent for the warn model; the exit code. */
static int warn_exponent(lx_ctx *ctx, const model_args *t, lx_lum_model *m)
{
    int rc;
    if (!!t->exp == !!t->beam) {
        cli_error("ies", "--model warn needs one of --exponent or --beam");
        return CLI_USAGE;
    }
    if (t->exp && (rc = lt_quantity(ctx, "ies", "--exponent", t->exp, LX_Q_NONE, NULL, 0, &m->exponent))) return rc;
    if (t->beam) {
        double b;
        if ((rc = lt_quantity(ctx, "ies", "--beam", t->beam, LX_Q_ANGLE, "deg", 0, &b))) return rc;
        lx_status st = lx_warn_exponent_from_beam(ctx, b, &m->exponent);
        if (st) return cli_fail("ies", ctx, st);
    }
    return CLI_OK;
}

/* The --model options into m (kind, flux, exponent, width, length, step); the exit code. */
static int model_params(lx_ctx *ctx, const model_args *t, lx_lum_model *m)
{
    int rc;
    if (!strcmp(t->model, "point")) m->kind = LX_LUM_MODEL_POINT;
    else if (!strcmp(t->model, "warn")) m->kind = LX_LUM_MODEL_WARN;
    else if (!strcmp(t->model, "lambert")) m->kind = LX_LUM_MODEL_LAMBERT;
    else {
        cli_error("ies", "--model: unknown model '%s' (point, warn or lambert)", t->model);
        return CLI_USAGE;
    }
    if (!t->flux) {
        cli_error("ies", "--model needs --flux");
        return CLI_USAGE;
    }
    if ((rc = lt_quantity(ctx, "ies", "--flux", t->flux, LX_Q_LUMINOUS_FLUX, NULL, 0, &m->flux_lm))) return rc;
    if (m->kind == LX_LUM_MODEL_WARN && (rc = warn_exponent(ctx, t, m))) return rc;
    if (t->w && (rc = lt_quantity(ctx, "ies", "--width", t->w, LX_Q_LENGTH, NULL, 0, &m->width_m))) return rc;
    if (t->l && (rc = lt_quantity(ctx, "ies", "--length", t->l, LX_Q_LENGTH, NULL, 0, &m->length_m))) return rc;
    if (t->step) {
        double s;
        if ((rc = lt_quantity(ctx, "ies", "--step", t->step, LX_Q_ANGLE, "deg", 0, &s))) return rc;
        m->step_deg = s / LT_DEG;
    }
    return CLI_OK;
}

/* --model: the model luminaire written to --write (no FILE may be given); the exit code. */
static int write_model(lx_ctx *ctx, const char *write, int has_files, const model_args *t, lx_lum_model *m)
{
    if (!write) {
        cli_error("ies", "--model needs --write OUT.ies");
        return CLI_USAGE;
    }
    if (has_files) {
        cli_error("ies", "give either FILE or --model, not both");
        return CLI_USAGE;
    }
    int rc = model_params(ctx, t, m);
    if (rc) return rc;
    lx_luminaire *l = NULL;
    lx_status st = lx_luminaire_from_model(ctx, m, &l);
    if (st) return cli_fail("ies", ctx, st);
    rc = write_ies(ctx, l, write);
    lx_luminaire_free(l);
    return rc;
}

/* --write with FILE: the one file (nfiles of them given) converted to IES; the exit code. */
static int convert_one(lx_ctx *ctx, int nfiles, const char *file, const char *write)
{
    if (nfiles != 1) {
        cli_error("ies", "--write converts exactly one FILE");
        return CLI_USAGE;
    }
    lx_luminaire *l = NULL;
    lx_status st = lx_luminaire_read_file(ctx, file, &l);
    if (st) return cli_fail("ies", ctx, st);
    int rc = write_ies(ctx, l, write);
    lx_luminaire_free(l);
    return rc;
}

int cmd_ies(int argc, char **argv)
{
    static const struct option opts[] = {
        {"format", required_argument, NULL, 'f'}, {"output", required_argument, NULL, 'o'},
        {"write", required_argument, NULL, 'w'},  {"model", required_argument, NULL, 'm'},
        {"flux", required_argument, NULL, 'F'},   {"exponent", required_argument, NULL, 'S'},
        {"beam", required_argument, NULL, 'B'},   {"width", required_argument, NULL, 'W'},
        {"length", required_argument, NULL, 'L'}, {"step", required_argument, NULL, 's'},
        {"catalog", required_argument, NULL, 'c'}, {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    cli_format fmt = CLI_FMT_TABLE;
    const char *outpath = NULL, *write = NULL;
    model_args t = {0};
    lx_lum_model m = {0};
    int c;
    optind = 1;
    while ((c = getopt_long(argc, argv, ":o:h", opts, NULL)) != -1) {
        switch (c) {
        case 'f':
            if (lt_format("ies", optarg, &fmt)) return CLI_USAGE;
            break;
        case 'o': outpath = optarg; break;
        case 'w': write = optarg; break;
        case 'm': t.model = optarg; break;
        case 'F': t.flux = optarg; break;
        case 'S': t.exp = optarg; break;
        case 'B': t.beam = optarg; break;
        case 'W': t.w = optarg; break;
        case 'L': t.l = optarg; break;
        case 's': t.step = optarg; break;
        case 'c': m.catalog = optarg; break;
        case 'h': cli_print_help(help); return CLI_OK;
        default: return cli_bad_option("ies", argv, c);
        }
    }
    if (write) { /* the writer writes IES LM-63-2002 only: a .ldt name would hold the wrong format */
        size_t wl = strlen(write);
        if (wl >= 4 && (!strcmp(write + wl - 4, ".ldt") || !strcmp(write + wl - 4, ".LDT")))
            return cli_error("ies", "%s: --write writes IES LM-63-2002, not EULUMDAT: name the file .ies", write), CLI_USAGE;
    }
    lx_ctx *ctx = cli_ctx("ies");
    if (!ctx) return CLI_RUNTIME;
    int rc;
    if (t.model) rc = write_model(ctx, write, optind < argc, &t, &m);
    else if (optind >= argc) {
        cli_error("ies", "no FILE given (luxcalc ies --help)");
        rc = CLI_USAGE;
    } else if (write) rc = convert_one(ctx, argc - optind, argv[optind], write);
    else rc = summaries(ctx, optind, argc, argv, fmt, outpath);
    lx_ctx_destroy(ctx);
    return rc;
}
