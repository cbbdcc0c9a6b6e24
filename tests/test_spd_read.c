/* test_spd_read.c - the spectral-file reader: every layout variant of the same data reads
 * bit-identically, names and lines, stdin, long lines, and each kind of bad input with its status,
 * line and message. Data files live in tests/data/spd/ (run from the repository root). */
#include "lx_test.h"

#include <string.h>

#define DATA "tests/data/spd/"

/* The two spectra of tests/data/spd/good/plain.csv, as written there (the C compiler's own
 * decimal conversion is the independent oracle for the bits). */
static const double ref_nm[5] = {380, 385, 390, 395, 400};
static const double ref_a[5] = {0.12345678901234568, 0.2, 3.0000000000000004, 1e-7, 42};
static const double ref_b[5] = {1.5, 2.5e-3, 17, 0.33333333333333331, 0.1};

static lx_spd_set *read_ok(lx_ctx *ctx, const char *path)
{
    lx_spd_set *set = NULL;
    lx_status st = lx_spd_read_file(ctx, path, &set);
    if (st != LX_OK) fail_msg("%s: %s: %s", path, lx_strerror(st), lx_ctx_errmsg(ctx));
    assert_non_null(set);
    return set;
}

static void assert_same_data(const lx_spd_set *a, const lx_spd_set *b, int check_names)
{
    assert_int_equal(a->count, b->count);
    for (size_t i = 0; i < a->count; i++) {
        assert_int_equal(a->spd[i].n, b->spd[i].n);
        assert_memory_equal(a->spd[i].lambda_nm, b->spd[i].lambda_nm, a->spd[i].n * sizeof(double));
        assert_memory_equal(a->spd[i].value, b->spd[i].value, a->spd[i].n * sizeof(double));
        if (check_names) assert_string_equal(a->spd[i].name, b->spd[i].name);
    }
}

static void test_plain_values(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *set = read_ok(ctx, DATA "good/plain.csv");
    assert_string_equal(set->file, DATA "good/plain.csv");
    assert_int_equal(set->count, 2);
    assert_string_equal(set->spd[0].name, "A");
    assert_string_equal(set->spd[1].name, "B");
    assert_int_equal(set->line[0], 2); /* line 1 is a comment, the header is line 2 */
    assert_int_equal(set->line[1], 2);
    assert_int_equal(set->spd[0].n, 5);
    assert_memory_equal(set->spd[0].lambda_nm, ref_nm, sizeof ref_nm);
    assert_memory_equal(set->spd[1].lambda_nm, ref_nm, sizeof ref_nm);
    assert_memory_equal(set->spd[0].value, ref_a, sizeof ref_a);
    assert_memory_equal(set->spd[1].value, ref_b, sizeof ref_b);
    lx_assert_ok(ctx, lx_spd_check(ctx, &set->spd[0]));
    lx_spd_set_free(set);
}

static void test_variants_identical(void **state)
{
    lx_ctx *ctx = *state;
    static const char *const variants[] = {
        "semicolon_decimal_comma.csv", "semicolon_point.csv", "tab.tsv", "spaces.txt", "crlf.csv", "bom.csv",
        "comments.csv", "unsorted.csv", "rows.csv", "no_trailing_newline.csv", "argyll.sp", "xrite.cgats",
        "argyll.ti3",
    };
    lx_spd_set *ref = read_ok(ctx, DATA "good/plain.csv");
    for (size_t i = 0; i < sizeof variants / sizeof variants[0]; i++) {
        char path[256];
        snprintf(path, sizeof path, DATA "good/%s", variants[i]);
        lx_spd_set *set = read_ok(ctx, path);
        print_message("  %s: %zu spectra, identical\n", variants[i], set->count);
        assert_same_data(ref, set, 1);
        lx_spd_set_free(set);
    }
    lx_spd_set_free(ref);
}

static void test_lines_per_layout(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *set = read_ok(ctx, DATA "good/rows.csv");
    assert_int_equal(set->line[0], 2); /* rows layout: each spectrum's own row */
    assert_int_equal(set->line[1], 3);
    lx_spd_set_free(set);
    set = read_ok(ctx, DATA "good/comments.csv");
    assert_int_equal(set->line[0], 4); /* the header after three comment/blank lines */
    lx_spd_set_free(set);
    set = read_ok(ctx, DATA "good/argyll.sp");
    assert_int_equal(set->line[0], 22); /* the set's data line */
    assert_int_equal(set->line[1], 23);
    lx_spd_set_free(set);
    set = read_ok(ctx, DATA "good/argyll.ti3"); /* a set split over two lines starts on the first */
    assert_int_equal(set->line[0], 11);
    assert_int_equal(set->line[1], 13);
    lx_spd_set_free(set);
}

static void test_no_header_and_defaults(void **state)
{
    lx_ctx *ctx = *state;
    static const char text[] = "380 1 10\n390 2 20\n400 3 30\n";
    lx_spd_set *set = NULL;
    lx_assert_ok(ctx, lx_spd_read_mem(ctx, "mem", text, sizeof text - 1, &set));
    assert_int_equal(set->count, 2);
    assert_string_equal(set->spd[0].name, "1");
    assert_string_equal(set->spd[1].name, "2");
    assert_int_equal(set->line[0], 1); /* no header: the first data line */
    assert_true(set->spd[1].value[2] == 30.0);
    assert_string_equal(set->file, "mem");
    lx_spd_set_free(set);
    /* a header of numbered labels 1, 2 is a columns header, not a rows layout */
    static const char text2[] = "nm,1,2\n380,1,10\n390,2,20\n";
    lx_assert_ok(ctx, lx_spd_read_mem(ctx, "mem2", text2, sizeof text2 - 1, &set));
    assert_int_equal(set->count, 2);
    assert_int_equal(set->spd[0].n, 2);
    assert_true(set->spd[0].lambda_nm[1] == 390.0);
    lx_spd_set_free(set);
}

static void test_cgats_norm(void **state)
{
    lx_ctx *ctx = *state;
    static const char text[] = "SPECT\nSPECTRAL_BANDS \"3\"\nSPECTRAL_START_NM \"400\"\nSPECTRAL_END_NM \"420\"\n"
                               "SPECTRAL_NORM \"100\"\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410 SPEC_420\n"
                               "END_DATA_FORMAT\nBEGIN_DATA\n50 25 100\nEND_DATA\n";
    lx_spd_set *set = NULL;
    lx_assert_ok(ctx, lx_spd_read_mem(ctx, "x.sp", text, sizeof text - 1, &set));
    assert_int_equal(set->count, 1);
    assert_string_equal(set->spd[0].name, "1");
    /* values are divided by SPECTRAL_NORM (Argyll's convention): 50/100, 25/100, 100/100 */
    assert_true(set->spd[0].value[0] == 0.5 && set->spd[0].value[1] == 0.25 && set->spd[0].value[2] == 1.0);
    assert_true(set->spd[0].lambda_nm[1] == 410.0); /* 400 + (420 - 400) * 1 / 2 */
    lx_spd_set_free(set);
}

static void test_stdin(void **state)
{
    lx_ctx *ctx = *state;
    if (!freopen(DATA "good/tab.tsv", "r", stdin)) skip();
    lx_spd_set *set = read_ok(ctx, "-");
    assert_string_equal(set->file, "-");
    lx_spd_set *ref = read_ok(ctx, DATA "good/plain.csv");
    assert_same_data(ref, set, 1);
    lx_spd_set_free(set);
    lx_spd_set_free(ref);
}

static void test_long_lines(void **state)
{
    lx_ctx *ctx = *state;
    /* rows layout with 200000 wavelengths: lines of about 1.5 MB */
    size_t n = 200000, cap = n * 24 + 64, len = 0;
    char *buf = malloc(cap);
    assert_non_null(buf);
    len += (size_t)snprintf(buf + len, cap - len, "id");
    for (size_t k = 0; k < n; k++) len += (size_t)snprintf(buf + len, cap - len, ",%zu.5", 300 + k);
    len += (size_t)snprintf(buf + len, cap - len, "\nS");
    for (size_t k = 0; k < n; k++) len += (size_t)snprintf(buf + len, cap - len, ",%zu", k % 1000);
    len += (size_t)snprintf(buf + len, cap - len, "\n");
    lx_spd_set *set = NULL;
    lx_assert_ok(ctx, lx_spd_read_mem(ctx, "long", buf, len, &set));
    assert_int_equal(set->count, 1);
    assert_int_equal(set->spd[0].n, n);
    assert_true(set->spd[0].lambda_nm[n - 1] == 300.0 + (double)(n - 1) + 0.5); /* as written */
    assert_true(set->spd[0].value[123456] == 456.0);                            /* 123456 % 1000 */
    lx_spd_set_free(set);
    free(buf);
}

static void test_free_null_and_args(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set_free(NULL);
    lx_spd_set *set = (lx_spd_set *)1;
    assert_int_equal(lx_spd_read_mem(ctx, "x", NULL, 5, &set), LX_EINVAL);
    assert_null(set);
    assert_int_equal(lx_spd_read_file(ctx, NULL, &set), LX_EINVAL);
}

static void test_eio_missing(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *set = (lx_spd_set *)1;
    assert_int_equal(lx_spd_read_file(ctx, DATA "no_such_file.csv", &set), LX_EIO);
    assert_null(set);
    assert_int_equal(lx_ctx_errline(ctx), 0);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), DATA "no_such_file.csv: cannot open"));
}

static void test_eio_directory(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *set = NULL;
    assert_int_equal(lx_spd_read_file(ctx, DATA "good", &set), LX_EIO);
    assert_null(set);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), DATA "good: cannot read: is a directory"));
}

/* One bad input: status, line and a fragment of the message (which starts "FILE:LINE: "). */
static void check_bad(lx_ctx *ctx, const char *file, long line, const char *fragment)
{
    char path[256], prefix[300];
    snprintf(path, sizeof path, DATA "bad/%s", file);
    lx_spd_set *set = (lx_spd_set *)1;
    lx_status st = lx_spd_read_file(ctx, path, &set);
    if (st != LX_EPARSE) print_error("%s: status %d, message '%s'\n", path, st, lx_ctx_errmsg(ctx));
    assert_int_equal(st, LX_EPARSE);
    assert_null(set);
    if (lx_ctx_errline(ctx) != line) print_error("%s: '%s'\n", path, lx_ctx_errmsg(ctx));
    assert_int_equal(lx_ctx_errline(ctx), line);
    snprintf(prefix, sizeof prefix, "%s:%ld: ", path, line);
    assert_true(strncmp(lx_ctx_errmsg(ctx), prefix, strlen(prefix)) == 0);
    if (!strstr(lx_ctx_errmsg(ctx), fragment)) print_error("%s: '%s'\n", path, lx_ctx_errmsg(ctx));
    assert_non_null(strstr(lx_ctx_errmsg(ctx), fragment));
}

/* The same cases as tests/data/spd/bad_expected.txt (which the CLI test reads). */
#define BAD(name, file, line, fragment) \
    static void test_bad_##name(void **state) { check_bad(*state, file, line, fragment); }
BAD(dup_wavelength, "dup_wavelength.csv", 4, "duplicate wavelength 380 nm (first on line 2)")
BAD(nan_value, "nan_value.csv", 3, "value is not finite: 'nan'")
BAD(inf_value, "inf_value.csv", 3, "value is not finite: '-inf'")
BAD(overflow, "overflow.csv", 4, "value is out of range (not finite): '1e999'")
BAD(non_numeric, "non_numeric.csv", 3, "value is not a number: 'abc'")
BAD(short_row, "short_row.csv", 3, "row has 2 fields, expected 3")
BAD(long_row, "long_row.csv", 4, "row has 4 fields, expected 3")
BAD(one_row, "one_row.csv", 2, "only 1 data row")
BAD(zero_wavelength, "zero_wavelength.csv", 2, "wavelength must be positive")
BAD(inf_wavelength, "inf_wavelength.csv", 3, "wavelength is not finite")
BAD(empty, "empty.csv", 1, "empty file")
BAD(comments_only, "comments_only.csv", 3, "no data")
BAD(header_only, "header_only.csv", 1, "header but no data rows")
BAD(binary, "binary.csv", 3, "binary data")
BAD(utf16, "utf16.csv", 1, "UTF-16")
BAD(one_column, "one_column.csv", 1, "need a wavelength and at least one value")
BAD(rows_decreasing, "rows_decreasing.csv", 1, "header wavelengths must increase")
BAD(rows_short_row, "rows_short_row.csv", 3, "row has 3 fields, expected 4")
BAD(rows_no_data, "rows_no_data.csv", 1, "header but no data rows")
BAD(empty_column, "empty_column.csv", 1, "column 3 ('B') is empty")
BAD(missing_value, "missing_value.csv", 3, "empty value in column 3")
BAD(cgats_no_begin_data, "cgats_no_begin_data.sp", 6, "without BEGIN_DATA")
BAD(cgats_no_end_data, "cgats_no_end_data.sp", 5, "BEGIN_DATA without END_DATA")
BAD(cgats_sets_mismatch, "cgats_sets_mismatch.cgats", 5, "NUMBER_OF_SETS is 3 but the data holds 2 sets")
BAD(cgats_short_row, "cgats_short_row.ti3", 7, "row has 2 fields, expected 3")
BAD(cgats_incomplete, "cgats_incomplete.cgats", 8, "incomplete data set: 2 of 4 values")
BAD(cgats_bands_mismatch, "cgats_bands_mismatch.sp", 2, "SPECTRAL_BANDS is 4 but the data format has 3")
BAD(cgats_no_spectral, "cgats_no_spectral.cgats", 2, "no spectral fields")
BAD(cgats_nan, "cgats_nan.sp", 7, "value is not finite: 'NaN'")

/* In-memory bad inputs that need no file. */
static void test_bad_mem(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *set = NULL;
    static const char neg[] = "nm;A\n380;1\n-390;2\n";
    assert_int_equal(lx_spd_read_mem(ctx, "neg", neg, sizeof neg - 1, &set), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 3);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "neg:3: wavelength must be positive: -390 nm"));
    static const char rdup[] = "id,380,390,390\nA,1,2,3\n";
    assert_int_equal(lx_spd_read_mem(ctx, "rdup", rdup, sizeof rdup - 1, &set), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 1);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "header wavelengths must increase"));
    static const char unsorted_dup[] = "nm\tA\n400\t1\n380\t2\n400\t3\n";
    assert_int_equal(lx_spd_read_mem(ctx, "ud", unsorted_dup, sizeof unsorted_dup - 1, &set), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 4);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "duplicate wavelength 400 nm (first on line 2)"));
    static const char nofmt_end[] = "CGATS.17\nBEGIN_DATA_FORMAT\nSPEC_380 SPEC_390\n";
    assert_int_equal(lx_spd_read_mem(ctx, "nf", nofmt_end, sizeof nofmt_end - 1, &set), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 2);
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "BEGIN_DATA_FORMAT without END_DATA_FORMAT"));
    assert_null(set);
}

/* The CGATS reader's structural errors, each on a hand-written file: the line named is the one
 * that holds the offending keyword or marker, counted by hand in the text. */
static void test_bad_cgats_mem(void **state)
{
    lx_ctx *ctx = *state;
    static const struct {
        const char *text;
        long line;
        const char *fragment;
    } cases[] = {
        {"CGATS.17\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\nEND_DATA_FORMAT\nBEGIN_DATA_FORMAT\n", 5,
         "second BEGIN_DATA_FORMAT (first on line 2)"},
        {"CGATS.17\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\nEND_DATA_FORMAT\nBEGIN_DATA\n1 2\nEND_DATA\nBEGIN_DATA\n", 8,
         "second BEGIN_DATA (only one table is read)"},
        {"CGATS.17\nBEGIN_DATA\n1 2\nEND_DATA\n", 2, "BEGIN_DATA before BEGIN_DATA_FORMAT"},
        {"CGATS.17\nNUMBER_OF_SETS 1\nEND_DATA\n", 3, "END_DATA without its BEGIN"},
        {"CGATS.17\nEND_DATA_FORMAT\n", 2, "END_DATA_FORMAT without its BEGIN"},
        {"CGATS.17\nNUMBER_OF_SETS\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\n", 2, "keyword NUMBER_OF_SETS has no value"},
        {"CGATS.17\nBEGIN_DATA_FORMAT\nEND_DATA_FORMAT\n", 2, "empty BEGIN_DATA_FORMAT field list"},
        {"CGATS.17\nNUMBER_OF_FIELDS 3\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\nEND_DATA_FORMAT\n", 2,
         "NUMBER_OF_FIELDS is 3 but the data format lists 2 fields"},
        {"CGATS.17\nNUMBER_OF_SETS 1\n", 2, "CGATS file without BEGIN_DATA_FORMAT"},
        {"CGATS.17\nBEGIN_DATA_FORMAT SPEC_400 SPEC_410 END_DATA_FORMAT\nBEGIN_DATA\nEND_DATA\n", 3,
         "no data sets between BEGIN_DATA and END_DATA"},
        /* sets may span lines (the first line holds other than one set): 1 2 | 3 then END_DATA */
        {"CGATS.17\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\nEND_DATA_FORMAT\nBEGIN_DATA\n1 2 3\nEND_DATA\n", 6,
         "incomplete data set: 1 of 2 values before END_DATA"},
        /* the three spectral keywords go together: the message names SPECTRAL_BANDS's line when given */
        {"CGATS.17\nSPECTRAL_END_NM 410\nSPECTRAL_BANDS 2\nBEGIN_DATA_FORMAT SPEC_400 SPEC_410 END_DATA_FORMAT\n"
         "BEGIN_DATA\n1 2\nEND_DATA\n",
         3, "SPECTRAL_BANDS, SPECTRAL_START_NM and SPECTRAL_END_NM must appear together"},
        {"CGATS.17\nSPECTRAL_END_NM 410\nBEGIN_DATA_FORMAT SPEC_400 SPEC_410 END_DATA_FORMAT\nBEGIN_DATA\n1 2\nEND_DATA\n",
         2, "must appear together"},
        {"CGATS.17\nSPECTRAL_BANDS 2\nSPECTRAL_START_NM 420\nSPECTRAL_END_NM 410\n"
         "BEGIN_DATA_FORMAT SPEC_400 SPEC_410 END_DATA_FORMAT\nBEGIN_DATA\n1 2\nEND_DATA\n",
         4, "SPECTRAL_START_NM 420 and SPECTRAL_END_NM 410: need 0 < start < end"},
        {"CGATS.17\nSPECTRAL_NORM 0\nBEGIN_DATA_FORMAT SPEC_400 SPEC_410 END_DATA_FORMAT\nBEGIN_DATA\n1 2\nEND_DATA\n",
         2, "SPECTRAL_NORM must be positive: 0"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        lx_spd_set *set = (lx_spd_set *)1;
        lx_status st = lx_spd_read_mem(ctx, "c.cgats", cases[i].text, strlen(cases[i].text), &set);
        if (st != LX_EPARSE || lx_ctx_errline(ctx) != cases[i].line || !strstr(lx_ctx_errmsg(ctx), cases[i].fragment))
            print_error("case %zu: status %d, '%s'\n", i, st, lx_ctx_errmsg(ctx));
        assert_int_equal(st, LX_EPARSE);
        assert_null(set);
        assert_int_equal(lx_ctx_errline(ctx), cases[i].line);
        assert_non_null(strstr(lx_ctx_errmsg(ctx), cases[i].fragment));
    }
}

/* CGATS data: sets spanning lines, the sample name (SAMPLE_NAME before SAMPLE_ID), and
 * skip_bad_rows, which leaves out a one-set line with a bad value or the wrong field count but
 * cannot leave out part of a set that spans lines. */
static void test_cgats_sets(void **state)
{
    lx_ctx *ctx = *state;
    lx_spd_set *set = NULL;
    static const char spans[] = "CGATS.17\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_400 SPEC_410\nEND_DATA_FORMAT\n"
                                "BEGIN_DATA\nA 1 2 B\n3 4\nEND_DATA\n";
    lx_assert_ok(ctx, lx_spd_read_mem(ctx, "s", spans, sizeof spans - 1, &set));
    assert_int_equal(set->count, 2);
    assert_string_equal(set->spd[0].name, "A");
    assert_string_equal(set->spd[1].name, "B");
    assert_int_equal(set->line[0], 6); /* each set's line is the one it starts on */
    assert_int_equal(set->line[1], 6);
    assert_true(set->spd[1].value[0] == 3.0 && set->spd[1].value[1] == 4.0);
    lx_spd_set_free(set);

    static const char named[] = "CGATS.17\nNUMBER_OF_SETS 4\nBEGIN_DATA_FORMAT\nSAMPLE_ID SAMPLE_NAME SPEC_400 SPEC_410\n"
                                "END_DATA_FORMAT\nBEGIN_DATA\n1 one 1 2\n2 two 1 x\n3 three 5 6\n4 four 7\nEND_DATA\n";
    assert_int_equal(lx_spd_read_mem(ctx, "n", named, sizeof named - 1, &set), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 8); /* without skip_bad_rows the first bad line fails */
    assert_non_null(strstr(lx_ctx_errmsg(ctx), "value is not a number: 'x'"));
    lx_spd_read_opts o = {.skip_bad_rows = 1};
    lx_assert_ok(ctx, lx_spd_read_mem_opts(ctx, "n", named, sizeof named - 1, &o, &set));
    assert_int_equal(set->count, 2); /* NUMBER_OF_SETS 4 counts the two left out */
    assert_string_equal(set->spd[0].name, "one");
    assert_string_equal(set->spd[1].name, "three");
    assert_int_equal(set->line[1], 9);
    assert_true(set->spd[1].value[0] == 5.0 && set->spd[1].value[1] == 6.0);
    assert_int_equal(set->nskipped, 2);
    assert_int_equal(set->skipped[0].line, 8);
    assert_int_equal(set->skipped[1].line, 10);
    assert_non_null(strstr(set->skipped[1].why, "row has 3 fields, expected 4"));
    lx_spd_set_free(set);

    static const char spans_bad[] = "CGATS.17\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\nEND_DATA_FORMAT\n"
                                    "BEGIN_DATA\n1 2 3\nx\nEND_DATA\n";
    assert_int_equal(lx_spd_read_mem_opts(ctx, "sb", spans_bad, sizeof spans_bad - 1, &o, &set), LX_EPARSE);
    assert_int_equal(lx_ctx_errline(ctx), 7);
    assert_null(set);
}

int main(void)
{
#define T(f) cmocka_unit_test_setup_teardown(f, lx_test_ctx_setup, lx_test_ctx_teardown)
#define B(n) T(test_bad_##n)
    const struct CMUnitTest tests[] = {
        T(test_plain_values), T(test_variants_identical), T(test_lines_per_layout), T(test_no_header_and_defaults),
        T(test_cgats_norm), T(test_stdin), T(test_long_lines), T(test_free_null_and_args), T(test_eio_missing),
        T(test_eio_directory), B(dup_wavelength), B(nan_value), B(inf_value), B(overflow), B(non_numeric),
        B(short_row), B(long_row), B(one_row), B(zero_wavelength), B(inf_wavelength), B(empty),
        B(comments_only), B(header_only), B(binary), B(utf16), B(one_column), B(rows_decreasing),
        B(rows_short_row), B(rows_no_data), B(empty_column), B(missing_value), B(cgats_no_begin_data),
        B(cgats_no_end_data), B(cgats_sets_mismatch), B(cgats_short_row), B(cgats_incomplete),
        B(cgats_bands_mismatch), B(cgats_no_spectral), B(cgats_nan), T(test_bad_mem), T(test_bad_cgats_mem),
        T(test_cgats_sets),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
