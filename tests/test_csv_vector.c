/* test_csv_vector.c - the vector line parser of the batch CSV reader (src/spectral/csv_vector.c),
 * each of its twins on its own (AVX-512 with BITALG, AVX2; SKIPPED where this machine cannot run
 * it) and the general parser (LX_SIMD=scalar), against the C library's strtod (ISO C 7.22.1.3:
 * correctly rounded), bit for bit (so -0 stays -0.0), on a million random short decimals of every
 * length 1-15, every '.' position and sign, mixed with fields it must leave to the general parser
 * (exponents, 16+ characters, '+', spaces) and with bad fields, which must give the same error
 * line as the general parser. Row widths 1-471 put fields across the parser's 64-byte blocks and
 * 64-field batches; some lines end in CRLF. Each path's test also checks that the path ran: the
 * vector parser takes every line of vector-only fields (its row counter, lx__csv_fast_rows). */
#include "lx_test.h"

/* internals of src/spectral (the static library exports them): which vector parser runs, and
 * how many rows it has taken */
int lx__csv_fast_level(void);
unsigned long long lx__csv_fast_rows(void);

/* Selects a path (skip() when this machine cannot run it; AVX-512 also needs BITALG). */
static void path_begin(lx_simd path)
{
    lx_test_simd_begin(path);
    int want = path == LX_SIMD_AVX512 ? 2 : path == LX_SIMD_AVX2 ? 1 : 0;
    if (lx__csv_fast_level() != want) {
        lx_test_simd_end();
        skip(); /* an AVX-512 CPU without BITALG runs the AVX2 twin: that test covers it */
    }
}

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned long long rng = 88172645463325252ull;
static unsigned rnd(unsigned n)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17; /* xorshift64 */
    return (unsigned)((rng >> 11) % n);
}

/* A random field: mostly what the vector parser takes, sometimes what it leaves to the other. */
static void field(char *c, int vector_only)
{
    int kind = vector_only ? 0 : (int)rnd(20);
    if (kind == 1) { /* %.17g of a double: 16-17 digits, exponents */
        double x = (double)rnd(1u << 30) / (double)(1 + rnd(1u << 20)) * (rnd(2) ? 1e-9 : 1e9);
        snprintf(c, 40, "%.17g", rnd(2) ? -x : x);
        return;
    }
    if (kind == 2) { /* what strtod takes and the vector parser does not */
        static const char *other[] = {"+1.5", "1e5", "2.5E-3", ".5", "-.25", "1234567890123456", "0.000000000000001",
                                      "-9999999.99999999", "12345678.1234567"};
        strcpy(c, other[rnd(9)]);
        return;
    }
    /* "-?D{ni}(.D{nf})?": 1-15 digits, up to 15 characters */
    int nd = 1 + (int)rnd(15), ni = 1 + (int)rnd((unsigned)nd), neg = rnd(4) == 0, dot = ni < nd || rnd(4) == 0;
    if (neg + nd + dot > 15) neg = 0;
    if (nd + dot > 15) dot = 0, ni = nd;
    char *p = c;
    if (neg) *p++ = '-';
    for (int i = 0; i < ni; i++) *p++ = (char)('0' + (i == 0 && rnd(3) == 0 ? 0 : rnd(10)));
    if (dot) *p++ = '.';
    for (int i = ni; i < nd; i++) *p++ = (char)('0' + rnd(10));
    *p = 0;
}

/* A table of rows x n fields and its strtod values. */
static char *table(size_t rows, size_t n, int vector_only, double *want, size_t *len)
{
    size_t cap = 64 + n * 8 + rows * (16 + n * 42), o = 0;
    char *t = malloc(cap);
    assert_non_null(t);
    o += (size_t)sprintf(t + o, "id");
    for (size_t j = 0; j < n; j++) o += (size_t)sprintf(t + o, ",%zu", 400 + j);
    t[o++] = '\n';
    for (size_t i = 0; i < rows; i++) {
        o += (size_t)sprintf(t + o, "r%zu", i);
        for (size_t j = 0; j < n; j++) {
            char c[48];
            field(c, vector_only);
            want[i * n + j] = strtod(c, NULL);
            o += (size_t)sprintf(t + o, ",%s", c);
        }
        if (i % 5 == 2) t[o++] = '\r'; /* CRLF on some lines */
        t[o++] = '\n';
    }
    *len = o;
    return t;
}

static size_t bit_mismatches(const lx_batch_table *t, const double *want, size_t count, int f32)
{
    size_t bad = 0;
    for (size_t i = 0; i < count; i++) {
        if (f32) {
            float a = ((const float *)t->batch.values)[i], b = (float)want[i];
            bad += memcmp(&a, &b, sizeof a) != 0;
        } else {
            bad += memcmp((const double *)t->batch.values + i, want + i, sizeof(double)) != 0;
        }
    }
    return bad;
}

static void million_against_strtod(void **state, lx_simd path)
{
    lx_ctx *ctx = *state;
    path_begin(path);
    size_t rows = 2200, n = 471, len; /* 1,036,200 values */
    double *want = malloc(rows * n * sizeof *want);
    for (int vector_only = 1; vector_only >= 0; vector_only--) {
        char *text = table(rows, n, vector_only, want, &len);
        for (int f32 = 0; f32 <= 1; f32++) {
            lx_batch_table *t = NULL;
            unsigned long long fast0 = lx__csv_fast_rows();
            lx_assert_ok(ctx, lx_batch_table_read_mem(ctx, "v.csv", text, len, f32 ? LX_F32 : LX_F64, 2, &t));
            unsigned long long fast = lx__csv_fast_rows() - fast0;
            assert_int_equal(t->batch.n_spectra, rows);
            size_t bad = bit_mismatches(t, want, rows * n, f32);
            print_message("%s, %s fields, %s: %zu of %zu values differ from strtod; %llu of %zu rows by the vector parser\n",
                          lx_simd_name(path), vector_only ? "vector-parser" : "mixed", f32 ? "float" : "double", bad,
                          rows * n, fast, rows);
            assert_int_equal(bad, 0);
            /* the path ran: every row of short decimals (the last ones, within 64 bytes of the
             * end of the text, go to the general parser) */
            if (path == LX_SIMD_SCALAR) assert_int_equal(fast, 0);
            else if (vector_only) assert_true(fast >= rows - 2);
            lx_batch_table_free(t);
        }
        free(text);
    }
    free(want);
    lx_test_simd_end();
}

static void test_million_avx512(void **state) { million_against_strtod(state, LX_SIMD_AVX512); }
static void test_million_avx2(void **state) { million_against_strtod(state, LX_SIMD_AVX2); }
static void test_million_general(void **state) { million_against_strtod(state, LX_SIMD_SCALAR); }

static void widths_and_edges(void **state, lx_simd path)
{
    lx_ctx *ctx = *state;
    path_begin(path);
    static const size_t widths[] = {1, 2, 3, 4, 5, 7, 8, 9, 31, 63, 64, 65, 66, 127, 128, 129, 200};
    for (size_t w = 0; w < sizeof widths / sizeof *widths; w++) {
        size_t n = widths[w], rows = 300, len;
        double *want = malloc(rows * n * sizeof *want);
        char *text = table(rows, n, 1, want, &len);
        lx_batch_table *t = NULL;
        lx_assert_ok(ctx, lx_batch_table_read_mem(ctx, "w.csv", text, len, LX_F64, 1, &t));
        assert_int_equal(bit_mismatches(t, want, rows * n, 0), 0);
        lx_batch_table_free(t);
        free(text);
        free(want);
    }
    /* fixed edge cases, each in a row long enough for the vector parser (not near the end) */
    static const char *edge[] = {"0",    "-0",   "0.",   "-0.0", "5.",        "00012.5000", "999999999999999",
                                 "-99999999999999", "1.00000000000000", "0.00000000000001", "7", "-7.", "123456789012.345"};
    for (size_t e = 0; e < sizeof edge / sizeof *edge; e++) {
        char text[4096];
        int o = sprintf(text, "id,1,2,3\n");
        for (int r = 0; r < 40; r++) o += sprintf(text + o, "r%d,%s,1.5,%s\n", r, edge[e], edge[e]);
        lx_batch_table *t = NULL;
        lx_assert_ok(ctx, lx_batch_table_read_mem(ctx, "e.csv", text, (size_t)o, LX_F64, 1, &t));
        double want = strtod(edge[e], NULL);
        const double *v = t->batch.values;
        for (int r = 0; r < 40; r++) {
            assert_memory_equal(&v[3 * r], &want, sizeof want);
            assert_memory_equal(&v[3 * r + 2], &want, sizeof want);
        }
        lx_batch_table_free(t);
    }
    lx_test_simd_end();
}

static void test_widths_avx512(void **state) { widths_and_edges(state, LX_SIMD_AVX512); }
static void test_widths_avx2(void **state) { widths_and_edges(state, LX_SIMD_AVX2); }
static void test_widths_general(void **state) { widths_and_edges(state, LX_SIMD_SCALAR); }

/* A bad field in row 25 (file line 28): the same error from the vector parser of this path as
 * from the general one. */
static void bad_fields_same_error(void **state, lx_simd path)
{
    lx_ctx *ctx = *state;
    path_begin(path);
    lx_test_simd_end();
    static const char *bad[] = {"1.2.3", "--1", "1-", ".", "-", "", "1..", "1.-2", "0x10", "1,5", "١٢٣", "12a", "-.",
                                "1 2"};
    for (size_t b = 0; b < sizeof bad / sizeof *bad; b++) {
        long line[2];
        char msg[2][256];
        for (int general = 0; general <= 1; general++) {
            lx_test_simd_begin(general ? LX_SIMD_SCALAR : path);
            char text[8192];
            int o = sprintf(text, "# c\nid,1,2,3,4\n");
            for (int r = 0; r < 60; r++) o += sprintf(text + o, "r%d,0.5,%s,1.25,3\n", r, r == 25 ? bad[b] : "2.75");
            lx_batch_table *t = NULL;
            assert_int_equal(lx_batch_table_read_mem(ctx, "b.csv", text, (size_t)o, LX_F64, 1, &t), LX_EPARSE);
            line[general] = lx_ctx_errline(ctx);
            snprintf(msg[general], sizeof msg[general], "%s", lx_ctx_errmsg(ctx));
            lx_test_simd_end();
        }
        assert_int_equal(line[0], 28);
        assert_int_equal(line[1], 28);
        assert_string_equal(msg[0], msg[1]);
    }
}

static void test_bad_fields_avx512(void **state) { bad_fields_same_error(state, LX_SIMD_AVX512); }
static void test_bad_fields_avx2(void **state) { bad_fields_same_error(state, LX_SIMD_AVX2); }

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_million_avx512), cmocka_unit_test(test_million_avx2),
        cmocka_unit_test(test_million_general), cmocka_unit_test(test_widths_avx512),
        cmocka_unit_test(test_widths_avx2),    cmocka_unit_test(test_widths_general),
        cmocka_unit_test(test_bad_fields_avx512), cmocka_unit_test(test_bad_fields_avx2),
    };
    return cmocka_run_group_tests(tests, lx_test_ctx_setup, lx_test_ctx_teardown);
}
