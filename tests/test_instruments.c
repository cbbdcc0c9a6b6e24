/* test_instruments.c - spectra as instruments write them: every real export of
 * $LX_SHARED_DIR/spectra/instruments read to the spectrum its SOURCES.md describes (skipped when
 * absent), the synthetic file of each layout in tests/data/instruments/good, each bad variant of
 * tests/data/instruments/bad (line and message from bad_expected.txt), the reader options, the
 * '#' rule, wavelength units and the instrument's own results. */
#include "lx_test.h"

#include <string.h>

#define DATA "tests/data/instruments/"

/* the spectrum every synthetic good file holds (as written there) */
static const double ref_nm[5] = {380, 385, 390, 395, 400};
static const double ref_a[5] = {0.125, 0.25, 0.5, 1.0, 2.0};

static lx_spd_set *read_opts(lx_ctx *ctx, const char *path, const lx_spd_read_opts *o)
{
    lx_spd_set *set = NULL;
    lx_status st = lx_spd_read_file_opts(ctx, path, o, &set);
    if (st != LX_OK) fail_msg("%s: %s: %s", path, lx_strerror(st), lx_ctx_errmsg(ctx));
    return set;
}

static lx_spd_set *read_ok(lx_ctx *ctx, const char *path) { return read_opts(ctx, path, NULL); }

static const char *shared_file(char *buf, size_t cap, const char *name)
{
    const char *dir = lx_test_shared_dir();
    if (!dir) return NULL;
    snprintf(buf, cap, "%s/spectra/instruments/%s", dir, name);
    FILE *f = fopen(buf, "rb");
    if (!f) return NULL;
    fclose(f);
    return buf;
}

#define SHARED(var, name) \
    char var##_buf[1024]; \
    const char *var = shared_file(var##_buf, sizeof var##_buf, name); \
    if (!var) { \
        skip(); \
        return; \
    }

static double sum(const lx_spd *s)
{
    double t = 0;
    for (size_t i = 0; i < s->n; i++) t += s->value[i];
    return t;
}

static double photopic_Y(lx_ctx *ctx, const lx_spd *s)
{
    lx_colorimetry c;
    lx_assert_ok(ctx, lx_spd_colorimetry(ctx, s, LX_OBSERVER_2, LX_METHOD_AUTO, &c));
    return c.Y;
}

/* ---- the real exports (values from SOURCES.md and the files themselves) ---- */

static void test_ocean_optics_flame(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "ocean_optics_flame_spectrometer.txt");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "oceanview");
    assert_int_equal(set->count, 1);
    const lx_spd *s = &set->spd[0];
    assert_int_equal(s->n, 2048); /* "Number of Pixels in Spectrum: 2048" */
    assert_true(s->lambda_nm[0] == 178.179 && s->lambda_nm[2047] == 871.906);
    assert_true(s->value[0] == 556.52 && s->value[11] == -68.82); /* "182.34  -68.82": two spaces */
    assert_string_equal(s->name, "Relative_11-17-02-611.txt");
    assert_string_equal(lx_spd_set_field(set, "Spectrometer"), "FLMS04381");
    assert_string_equal(lx_spd_set_field(set, "Integration Time (sec)"), "7.712000E-2");
    assert_null(set->unit); /* a relative node: no unit */
    lx_spd_set_free(set);
}

static void test_sekonic(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "RANDOM_001_02._3262K.csv");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "sekonic");
    assert_int_equal(set->count, 2); /* a 5 nm and a 1 nm block; the TM-30 table is not a spectrum */
    assert_int_equal(set->spd[0].n, 81);
    assert_int_equal(set->spd[1].n, 401);
    assert_true(set->spd[0].lambda_nm[0] == 380 && set->spd[0].lambda_nm[80] == 780);
    assert_string_equal(set->spd[0].name, "RANDOM_001_02\xc2\xb0_3262K (5 nm)");
    assert_string_equal(set->spd[1].name, "RANDOM_001_02\xc2\xb0_3262K (1 nm)");
    assert_int_equal(set->line[0], 47);
    assert_int_equal(set->line[1], 129);
    assert_string_equal(set->unit, "W/m2/nm");
    /* colour-science 0.4.7 SpectralDistribution_Sekonic returns the 1 nm block: 401 values summing to
     * 0.099704726796000009; Y = 683.002 sum(E ybar) = 30.084430205881166 by the same CIE 015 sum */
    lx_assert_near(sum(&set->spd[1]), 0.099704726796000009, 0, 1e-12);
    lx_assert_near(photopic_Y(ctx, &set->spd[1]), 30.084430205881166, 0, 1e-12);
    lx_vendor_results v;
    lx_assert_ok(ctx, lx_spd_set_vendor(ctx, set, &v));
    assert_true(v.cct_K == 3262 && v.duv == -0.0029 && v.illuminance_lx == 30.1 && v.x == 0.4159 && v.y == 0.3889);
    assert_true(v.cri_ra == 87.5 && v.cri_r[8] == 31.2 && v.cri_r[14] == 82.5 && v.tm30_rf == 87 && v.tm30_rg == 98);
    assert_true(v.ppfd_umol_m2_s == 0.4 && v.X == 32.1626 && v.peak_nm == 608);
    /* the firmware's illuminance against the standard's sum over its own spectrum: 0.05 % */
    lx_assert_near(photopic_Y(ctx, &set->spd[1]), v.illuminance_lx, 0, 5e-3);
    lx_spd_set_free(set);
}

static void test_uprtek(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "uprtek.xls.txt");
    SHARED(path2, "ESPD2021_0104_231446.xls");
    lx_spd_set *set = read_ok(ctx, path), *lf = read_ok(ctx, path2);
    assert_string_equal(set->format, "uprtek");
    assert_string_equal(lf->format, "uprtek"); /* text despite .xls: by content */
    assert_int_equal(set->count, 1);
    const lx_spd *s = &set->spd[0];
    assert_int_equal(s->n, 401);
    assert_true(s->lambda_nm[0] == 380 && s->lambda_nm[400] == 780);
    /* mW/m2/nm converted to W/m2/nm */
    assert_string_equal(set->unit, "W/m2/nm");
    assert_true(set->unit_scale == 1e-3);
    assert_true(s->value[0] == 0.030267 * 1e-3 && s->value[400] == 0.411766 * 1e-3);
    /* CRLF and LF copies of one measurement read identically */
    assert_int_equal(lf->spd[0].n, 401);
    assert_memory_equal(lf->spd[0].value, s->value, 401 * sizeof(double));
    /* colour-science 0.4.7 SpectralDistribution_UPRTek: 401 values summing to 2608.1131450000003
     * (mW); Y = 683.002 sum(E ybar) = 695.15728814604836 lx */
    lx_assert_near(sum(s) * 1e3, 2608.1131450000003, 0, 1e-12);
    lx_assert_near(photopic_Y(ctx, s), 695.15728814604836, 0, 1e-12);
    assert_string_equal(lx_spd_set_field(set, "Model Name"), "CV600");
    assert_string_equal(lx_spd_set_field(set, "Memo"), "");
    lx_vendor_results v;
    lx_assert_ok(ctx, lx_spd_set_vendor(ctx, set, &v));
    assert_true(v.illuminance_lx == 695.154907 && v.cct_K == 5198 && v.duv == -0.00062 && v.x == 0.339663);
    assert_true(v.cri_ra == 92.956993 && v.cri_r[0] == 91.651062 && v.cri_r[14] == 88.615669);
    assert_true(v.tm30_rf == 87.234917 && v.irradiance_W_m2 == 2.607891 && v.peak_nm == 456);
    lx_assert_near(photopic_Y(ctx, s), v.illuminance_lx, 0, 1e-5); /* the meter's LUX: 3 ppm */
    lx_spd_set_free(set);
    lx_spd_set_free(lf);
}

static void test_licor(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "licor-li180-irrad.txt");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "uprtek");
    assert_int_equal(set->spd[0].n, 401);
    assert_true(set->spd[0].value[0] == 27.503876 * 1e-3 && set->spd[0].value[400] == 82.042412 * 1e-3);
    assert_string_equal(set->unit_source, "LI-COR export: mW/m2/nm");
    lx_vendor_results v;
    lx_assert_ok(ctx, lx_spd_set_vendor(ctx, set, &v));
    /* fields before (PPFD, LUX) and after the spectrum (CCT, CRI) */
    assert_true(v.ppfd_umol_m2_s == 129.87944 && v.illuminance_lx == 7366.741699 && v.cct_K == 5465);
    assert_true(v.cri_ra == 98.779282 && v.cri_r[14] == 97.831963);
    lx_assert_near(photopic_Y(ctx, &set->spd[0]), v.illuminance_lx, 0, 1e-5);
    lx_par p;
    lx_assert_ok(ctx, lx_par_compute(ctx, &set->spd[0], LX_METHOD_AUTO, &p));
    lx_assert_near(p.ppfd, v.ppfd_umol_m2_s, 0, 5e-3); /* the meter's own PPFD: 0.26 % */
    lx_spd_set_free(set);
}

static void test_tm27(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "Fluorescent.spdx");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "tm27");
    assert_int_equal(set->count, 1);
    const lx_spd *s = &set->spd[0];
    /* colour-science 0.4.7 SpectralDistribution_IESTM2714: 85 values, 400.0-850.1 nm, sum 13.394 */
    assert_int_equal(s->n, 85);
    assert_true(s->lambda_nm[0] == 400.0 && s->lambda_nm[84] == 850.1 && s->value[0] == 0.034);
    lx_assert_near(sum(s), 13.393999999999998, 0, 1e-12);
    assert_string_equal(s->name, "Rare earth fluorescent lamp");
    assert_string_equal(lx_spd_set_field(set, "SpectralQuantity"), "relative");
    assert_string_equal(lx_spd_set_field(set, "BandwidthFWHM"), "2.0");
    assert_string_equal(lx_spd_set_field(set, "DocumentCreator"), "byHeart Consultants");
    assert_null(set->unit);
    lx_spd_set_free(set);
}

static void test_xrite(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "X-Rite_Digital_Colour_Checker.txt");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "cgats");
    assert_int_equal(set->count, 10);
    assert_string_equal(set->spd[0].name, "X1");
    assert_string_equal(set->spd[9].name, "X10");
    assert_int_equal(set->spd[0].n, 36);
    assert_true(set->spd[0].lambda_nm[0] == 380 && set->spd[0].lambda_nm[35] == 730);
    /* colour-science 0.4.7 read_sds_from_xrite_file: X1 sums to 0.25429999999999997, X2 0.25719999999999998 */
    lx_assert_near(sum(&set->spd[0]), 0.25429999999999997, 0, 1e-12);
    lx_assert_near(sum(&set->spd[1]), 0.25719999999999998, 0, 1e-12);
    assert_string_equal(lx_spd_set_field(set, "INSTRUMENTATION"), "Spectrolino");
    lx_spd_set_free(set);
}

static void test_avantes(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "avantes-avaspec-e-irrad.csv");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "avantes");
    assert_int_equal(set->count, 1);
    assert_int_equal(set->spd[0].n, 1604); /* lines 7-1610 */
    assert_string_equal(set->spd[0].name, "1412092U1- f1 g2 kesk 80 cm I");
    assert_true(set->spd[0].lambda_nm[0] == 172.485);
    assert_true(set->spd[0].value[0] == 9.27919E-09 * 0.01); /* uW/cm2/nm to W/m2/nm */
    assert_string_equal(set->unit, "W/m2/nm");
    assert_string_equal(lx_spd_set_field(set, "Mode/Unit"), "Irradiance[?Watt/cm?]");
    assert_string_equal(lx_spd_set_field(set, "NrOfAverages"), "100");
    lx_spd_set_free(set);
    SHARED(path8, "avasoft8.txt");
    set = read_ok(ctx, path8);
    assert_string_equal(set->format, "avantes");
    assert_int_equal(set->count, 4);
    static const char *const names[4] = {"Sample", "Dark", "Reference", "Reflectance"};
    static const double first[4] = {-6.893, -10.335, -9.339, 252.16336}; /* line 9 */
    for (int k = 0; k < 4; k++) {
        assert_string_equal(set->spd[k].name, names[k]);
        assert_int_equal(set->spd[k].n, 401);
        assert_true(set->spd[k].lambda_nm[0] == 300 && set->spd[k].lambda_nm[400] == 700);
        assert_true(set->spd[k].value[0] == first[k]);
    }
    assert_string_equal(lx_spd_set_field(set, "Integration time [ms]"), "6.00");
    lx_spd_set_free(set);
}

static void test_ocean_irradiance(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "oo-spectrum.OVIrrad");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "oceanview");
    assert_int_equal(set->spd[0].n, 2048);
    assert_true(set->spd[0].lambda_nm[0] == 178.699 && set->spd[0].lambda_nm[2047] == 862.714); /* decimal comma */
    assert_string_equal(lx_spd_set_field(set, "Integration Time (sec)"), "1,000000E-1");
    assert_string_equal(set->unit, "W/m2/nm"); /* an absolute irradiance node: uW/cm2/nm */
    assert_true(set->unit_scale == 0.01);
    lx_spd_set_free(set);
    SHARED(path2, "oo-spectrum-comma.SSIrrad");
    set = read_ok(ctx, path2);
    assert_string_equal(set->format, "oceanview");
    assert_int_equal(set->spd[0].n, 1044);
    assert_true(set->spd[0].lambda_nm[0] == 199.08 && set->spd[0].lambda_nm[1043] == 998.61);
    int found = 0; /* "1,3742E02": an exponent without a sign */
    for (size_t i = 0; i < set->spd[0].n; i++) found |= set->spd[0].value[i] == 137.42;
    assert_true(found);
    assert_string_equal(lx_spd_set_field(set, "Spectrometers"), "QEB1523");
    lx_spd_set_free(set);
}

static void test_spectrawiz(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "irr_820_1941.IRR");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "spectrawiz");
    assert_int_equal(set->spd[0].n, 1922);
    assert_true(set->spd[0].lambda_nm[0] == 173.0 && set->spd[0].lambda_nm[1921] == 1133.5);
    assert_string_equal(lx_spd_set_field(set, "trailer"), "5");
    assert_non_null(lx_spd_set_field(set, "File"));
    lx_spd_set_free(set);
}

static void test_argyll(void **state)
{
    lx_ctx *ctx = *state;
    SHARED(path, "example121.sp");
    lx_spd_set *set = read_ok(ctx, path);
    assert_string_equal(set->format, "cgats");
    assert_int_equal(set->spd[0].n, 121);
    lx_assert_near(set->spd[0].lambda_nm[1], 350 + 400.0 / 120, 1e-12, 0); /* not the rounded SPEC_353 */
    assert_true(set->spd[0].value[0] == -0.041690 / 100); /* SPECTRAL_NORM 100 */
    assert_string_equal(lx_spd_set_field(set, "ORIGINATOR"), "Argyll CMS");
    lx_spd_set_free(set);
    SHARED(path2, "CRT.ccss");
    set = read_ok(ctx, path2);
    assert_int_equal(set->count, 14);
    assert_string_equal(set->spd[13].name, "14");
    assert_int_equal(set->spd[0].n, 118);
    assert_true(set->spd[0].lambda_nm[117] == 740.0);
    assert_string_equal(lx_spd_set_field(set, "TECHNOLOGY"), "CRT");
    lx_spd_set_free(set);
}

/* ---- the synthetic layouts ---- */

static void check_ref(const lx_spd_set *set, size_t k, const char *name, double vscale)
{
    const lx_spd *s = &set->spd[k];
    assert_int_equal(s->n, 5);
    for (int i = 0; i < 5; i++) {
        lx_assert_near(s->lambda_nm[i], ref_nm[i], 1e-12, 1e-15);
        lx_assert_near(s->value[i], ref_a[i] * vscale, 0, 1e-15);
    }
    if (name) assert_string_equal(s->name, name);
}

static void test_good_layouts(void **state)
{
    lx_ctx *ctx = *state;
    static const struct {
        const char *file, *format, *name;
        double vscale;
    } cases[] = {
        {"excel.csv", "columns", "Sample #1", 1},          {"excel_semicolon.csv", "columns", "Sample #1", 1},
        {"preamble.csv", "columns", "Sample #1", 1},       {"micrometres.csv", "columns", "Sample #1", 1},
        {"micrometres_header.csv", "columns", "Sample #1", 1}, {"angstrom.csv", "columns", "Sample #1", 1},
        {"rows_hash.csv", "rows", "Sample #1", 1},         {"oceanview.txt", "oceanview", "Sample #1.txt", 1},
        {"spectrasuite.SSIrrad", "oceanview", "1", 1},     {"sekonic.csv", "sekonic", "Sample #1 (5 nm)", 1},
        {"uprtek.xls", "uprtek", "Sample #1", 1e-3},       {"licor.txt", "uprtek", "1", 1e-3},
        {"tm27.spdx", "tm27", "Sample #1", 1},             {"spectrawiz.IRR", "spectrawiz", "1", 1},
        {"avasoft.csv", "avantes", "Sample #1", 0.01},     {"avasoft8.txt", "avantes", "Sample #1", 1},
        {"cgats_hash.cgats", "cgats", "Sample #1", 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char path[256];
        snprintf(path, sizeof path, DATA "good/%s", cases[i].file);
        print_message("  %s\n", cases[i].file);
        lx_spd_set *set = read_ok(ctx, path);
        assert_string_equal(set->format, cases[i].format);
        check_ref(set, 0, cases[i].name, cases[i].vscale);
        lx_spd_set_free(set);
    }
    /* header fields of the preamble, TM-27 entities, the second rows-layout name after a comment */
    lx_spd_set *set = read_ok(ctx, DATA "good/preamble.csv");
    assert_string_equal(lx_spd_set_field(set, "Operator"), "Sample #1 tester");
    assert_string_equal(lx_spd_set_field(set, "Date"), "2024-03-01 10:00");
    assert_int_equal(set->count, 2);
    lx_spd_set_free(set);
    set = read_ok(ctx, DATA "good/tm27.spdx");
    assert_string_equal(lx_spd_set_field(set, "Manufacturer"), "Lamps & Co");
    assert_string_equal(set->unit, "W/m2/nm"); /* SpectralQuantity irradiance */
    lx_spd_set_free(set);
    set = read_ok(ctx, DATA "good/rows_hash.csv");
    assert_string_equal(set->spd[1].name, "Lamp B");
    lx_spd_set_free(set);
    set = read_ok(ctx, DATA "good/cgats_hash.cgats");
    assert_int_equal(set->count, 2);
    assert_string_equal(set->spd[1].name, "Lamp B");
    lx_spd_set_free(set);
    set = read_ok(ctx, DATA "good/excel.csv"); /* Excel's empty padding columns are not spectra */
    assert_int_equal(set->count, 2);
    lx_spd_set_free(set);
}

/* ---- the bad variants ---- */

static void test_bad_variants(void **state)
{
    lx_ctx *ctx = *state;
    FILE *f = fopen(DATA "bad_expected.txt", "r");
    assert_non_null(f);
    char line[512];
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#') continue;
        char *file = strtok(line, "\t"), *ln = strtok(NULL, "\t"), *frag = strtok(NULL, "\n");
        assert_non_null(frag);
        char path[256];
        snprintf(path, sizeof path, DATA "bad/%s", file);
        lx_spd_set *set = NULL;
        lx_status st = lx_spd_read_file(ctx, path, &set);
        print_message("  %s: %s\n", file, lx_ctx_errmsg(ctx));
        assert_int_equal(st, LX_EPARSE);
        assert_null(set);
        assert_int_equal(lx_ctx_errline(ctx), atol(ln));
        assert_non_null(strstr(lx_ctx_errmsg(ctx), frag));
        n++;
    }
    fclose(f);
    assert_true(n >= 20);
}

/* ---- options ---- */

static void test_options(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_read_opts o;
    memset(&o, 0, sizeof o);
    o.columns = "nm,Sample #1";
    lx_spd_set *set = read_opts(ctx, DATA "good/columns_pick.csv", &o);
    assert_int_equal(set->count, 1);
    check_ref(set, 0, "Sample #1", 1);
    lx_spd_set_free(set);
    o.columns = "2,4,5"; /* by number, from 1 */
    set = read_opts(ctx, DATA "good/columns_pick.csv", &o);
    assert_int_equal(set->count, 2);
    check_ref(set, 0, "Sample #1", 1);
    assert_string_equal(set->spd[1].name, "Lamp B");
    lx_spd_set_free(set);
    o.columns = "nm,Nope";
    set = NULL;
    assert_int_equal(lx_spd_read_file_opts(ctx, DATA "good/columns_pick.csv", &o, &set), LX_EINVAL);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "no column 'Nope'"));
    o.columns = "nm";
    assert_int_equal(lx_spd_read_file_opts(ctx, DATA "good/columns_pick.csv", &o, &set), LX_EINVAL);
    o.columns = NULL;
    /* --skip-lines: the preamble skipped, line numbers still those of the file */
    o.skip_lines = 4;
    set = read_opts(ctx, DATA "good/preamble.csv", &o);
    check_ref(set, 0, "Sample #1", 1);
    assert_int_equal(set->line[0], 5);
    assert_int_equal(set->nfields, 0);
    lx_spd_set_free(set);
    o.skip_lines = 6; /* the header skipped too: the spectra lose their names */
    set = read_opts(ctx, DATA "good/preamble.csv", &o);
    assert_string_equal(set->spd[0].name, "1");
    lx_spd_set_free(set);
    o.skip_lines = 0;
    /* --wavelength-unit overrides the range rule */
    o.wavelength_unit = "nm";
    set = read_opts(ctx, DATA "good/micrometres.csv", &o);
    lx_assert_near(set->spd[0].lambda_nm[0], 0.38, 0, 1e-15);
    assert_true(set->wavelength_scale == 1);
    lx_spd_set_free(set);
    o.wavelength_unit = "um";
    set = read_opts(ctx, DATA "good/micrometres.csv", &o);
    assert_true(set->wavelength_scale == 1000);
    lx_spd_set_free(set);
    o.wavelength_unit = "furlong";
    assert_int_equal(lx_spd_read_file_opts(ctx, DATA "good/micrometres.csv", &o, &set), LX_EINVAL);
    o.wavelength_unit = NULL;
    /* a forced layout, and an unknown one */
    o.format = "columns";
    set = read_opts(ctx, DATA "good/excel.csv", &o);
    lx_spd_set_free(set);
    o.format = "sekonic";
    assert_int_equal(lx_spd_read_file_opts(ctx, DATA "good/excel.csv", &o, &set), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "no 'Spectral Data NNN[nm],value' rows"));
    o.format = "xlsx";
    assert_int_equal(lx_spd_read_file_opts(ctx, DATA "good/excel.csv", &o, &set), LX_EINVAL);
    o.format = NULL;
    o.skip_lines = -1;
    assert_int_equal(lx_spd_read_file_opts(ctx, DATA "good/excel.csv", &o, &set), LX_EINVAL);
}

static void test_skip_bad_rows(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *set = NULL;
    assert_int_equal(lx_spd_read_file(ctx, DATA "good/skip_bad_rows.csv", &set), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 3);
    lx_spd_read_opts o;
    memset(&o, 0, sizeof o);
    o.skip_bad_rows = 1;
    set = read_opts(ctx, DATA "good/skip_bad_rows.csv", &o);
    static const long lines[4] = {3, 5, 6, 8};
    static const char *const why[4] = {"value is not a number: 'abc'", "row has 3 fields, expected 2",
                                       "row has 1 field, expected 2", "duplicate wavelength 395 nm (first on line 7)"};
    assert_int_equal(set->nskipped, 4);
    for (int i = 0; i < 4; i++) {
        assert_int_equal(set->skipped[i].line, lines[i]);
        assert_non_null(strstr(set->skipped[i].why, why[i]));
    }
    static const double l[4] = {380, 385, 395, 400}, v[4] = {0.125, 0.25, 1, 2};
    assert_int_equal(set->spd[0].n, 4);
    assert_memory_equal(set->spd[0].lambda_nm, l, sizeof l);
    assert_memory_equal(set->spd[0].value, v, sizeof v);
    lx_spd_set_free(set);
    /* the instrument layouts skip bad rows too; a count that disagrees stays an error */
    set = read_opts(ctx, DATA "bad/uprtek_value.xls", &o);
    assert_int_equal(set->nskipped, 1);
    assert_int_equal(set->skipped[0].line, 4);
    assert_int_equal(set->spd[0].n, 2);
    lx_spd_set_free(set);
    set = read_opts(ctx, DATA "bad/tm27_no_wavelength.spdx", &o);
    assert_int_equal(set->nskipped, 1);
    lx_spd_set_free(set);
    assert_int_equal(lx_spd_read_file_opts(ctx, DATA "bad/oceanview_count.txt", &o, &set), LX_EPARSE);
    /* every row bad: an error, not an empty spectrum */
    static const char all_bad[] = "nm,A\n380,x\n385,y\n";
    assert_int_equal(lx_spd_read_mem_opts(ctx, "mem", all_bad, sizeof all_bad - 1, &o, &set), LX_EPARSE);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "no good data rows"));
}

/* ---- '#' is a comment only where it cannot be part of a name ---- */

static void test_hash_rule(void **state)
{
    lx_ctx *ctx = *state;
    static const char *const ok_texts[] = {
        "nm,Sample #1\n380,0.125\n385,0.25  # a comment\n",               /* columns header */
        "nm\tSample #1\n380\t0.125\n385\t0.25\t# a comment\n",            /* tab */
        "nm;Sample #1\n380;0,125\n385;0,25 # a comment\n",                /* semicolon, decimal comma */
        "id,380,385\nSample #1,0.125,0.25 # comment\n",                   /* rows layout name */
        "\"nm\",\"Sample #1\"  # header comment\n380,0.125\n385,0.25\n",  /* after a quoted cell */
        "  # a whole-line comment\nnm,Sample #1\n380,0.125,# rest\n385,0.25\n",
        "SPECT\nNUMBER_OF_FIELDS 3\nBEGIN_DATA_FORMAT\nSAMPLE_NAME SPEC_380 SPEC_385\nEND_DATA_FORMAT\n"
        "NUMBER_OF_SETS 1\nBEGIN_DATA\n\"Sample #1\" 0.125 0.25 # comment\nEND_DATA\n",
    };
    for (size_t i = 0; i < sizeof ok_texts / sizeof *ok_texts; i++) {
        lx_spd_set *set = NULL;
        lx_status st = lx_spd_read_mem(ctx, "mem", ok_texts[i], strlen(ok_texts[i]), &set);
        if (st != LX_OK) fail_msg("case %zu: %s", i, lx_ctx_errmsg(ctx));
        assert_string_equal(set->spd[0].name, "Sample #1");
        assert_int_equal(set->spd[0].n, 2);
        assert_true(set->spd[0].value[0] == 0.125 && set->spd[0].value[1] == 0.25);
        lx_spd_set_free(set);
    }
    /* '#' glued to a number is not a comment: the field is malformed */
    static const char glued[] = "nm,A\n380,0.125\n385,0.25#3\n";
    lx_spd_set *set = NULL;
    assert_int_equal(lx_spd_read_mem(ctx, "mem", glued, sizeof glued - 1, &set), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 3);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "'0.25#3'"));
}

/* ---- wavelength units and the 360-830 nm warning ---- */

static int warnings;
static void count_warn(void *user, lx_log_level level, const char *msg)
{
    (void)user;
    if (level == LX_LOG_WARN && strstr(msg, "no overlap with 360-830 nm")) warnings++;
}

static void test_wavelength_units(void **state)
{
    lx_ctx *ctx = *state;
    static const struct {
        const char *text;
        double scale;
    } cases[] = {
        {"wl_um,A\n0.38,1\n0.385,2\n", 1000}, {"Wavelength (micron),A\n0.38,1\n0.385,2\n", 1000},
        {"lambda [A],A\n3800,1\n3850,2\n", 0.1}, {"angstrom A\n3800 1\n3850 2\n", 0.1},
        {"nm,A\n0.38,1\n0.385,2\n", 1}, /* the header says nm: kept (and warned about) */
        {"0.38,1\n0.385,2\n", 1000},     /* no header: every wavelength below 10 */
        {"380,1\n385,2\n", 1},
    };
    lx_ctx_set_log(ctx, count_warn, NULL, LX_LOG_WARN);
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        lx_spd_set *set = NULL;
        warnings = 0;
        lx_status st = lx_spd_read_mem(ctx, "mem", cases[i].text, strlen(cases[i].text), &set);
        if (st != LX_OK) fail_msg("case %zu: %s", i, lx_ctx_errmsg(ctx));
        assert_true(set->wavelength_scale == cases[i].scale);
        lx_assert_near(set->spd[0].lambda_nm[0], cases[i].scale == 1 ? (i == 4 ? 0.38 : 380) : 380, 1e-9, 0);
        assert_int_equal(warnings, i == 4);
        lx_spd_set_free(set);
    }
    lx_ctx_set_log(ctx, NULL, NULL, LX_LOG_WARN);
}

/* ---- vendor results of formats without them ---- */

static void test_vendor_none(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *set = read_ok(ctx, DATA "good/excel.csv");
    lx_vendor_results v;
    lx_assert_ok(ctx, lx_spd_set_vendor(ctx, set, &v));
    assert_int_equal(v.count, 0);
    assert_true(isnan(v.cct_K) && isnan(v.cri_r[14]) && isnan(v.peak_nm));
    lx_spd_set_free(set);
    set = read_ok(ctx, DATA "good/sekonic.csv");
    lx_assert_ok(ctx, lx_spd_set_vendor(ctx, set, &v));
    assert_true(v.cct_K == 3262 && v.cri_r[8] == 31.2 && v.ppfd_umol_m2_s == 0.4);
    assert_true(isnan(v.cri_r[0])); /* "SSI1,---" and absent fields stay NaN */
    assert_int_equal(v.count, 8);
    lx_spd_set_free(set);
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, lx_test_ctx_setup, lx_test_ctx_teardown)
    const struct CMUnitTest tests[] = {
        T(test_ocean_optics_flame), T(test_sekonic), T(test_uprtek), T(test_licor), T(test_tm27), T(test_xrite),
        T(test_avantes), T(test_ocean_irradiance), T(test_spectrawiz), T(test_argyll), T(test_good_layouts),
        T(test_bad_variants), T(test_options), T(test_skip_bad_rows), T(test_hash_rule), T(test_wavelength_units),
        T(test_vendor_none),
    };
    return cmocka_run_group_tests_name("instruments", tests, NULL, NULL);
}
