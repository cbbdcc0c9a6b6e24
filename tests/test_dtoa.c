/* test_dtoa.c - lx_double_format (src/core/dtoa.c) against the C library (ISO C 7.22.1.3: strtod is
 * correctly rounded; glibc's printf prints the exact binary value correctly rounded): every text
 * reads back as the same bits, is the shortest that does (no text with one digit fewer reads back:
 * the nearest such texts below and above are tried), is the closest of that length (it equals
 * printf's correctly rounded digits whenever those read back) and is laid out as printf's
 * "%.*g" with P = max(15, digits). On 1e6 doubles here (random bit patterns, subnormals, every
 * power of ten and its neighbours, short decimals as data files hold them); LX_DTOA_COUNT=1e7
 * runs 1e7 (README: about 20 s on one core). */
#include "lx_test.h"

#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static uint64_t rng = 0x2545F4914F6CDD1Dull;
static uint64_t next64(void)
{
    rng ^= rng >> 12, rng ^= rng << 25, rng ^= rng >> 27; /* xorshift64* */
    return rng * 0x2545F4914F6CDD1Dull;
}

static double from_bits(uint64_t b)
{
    double d;
    memcpy(&d, &b, sizeof d);
    return d;
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* significant digits of a text as lx_double_format writes it (no leading zeros counted) */
static int sig_digits(const char *s, char *digits)
{
    int n = 0, started = 0;
    for (; *s && *s != 'e'; s++) {
        if (*s < '0' || *s > '9') continue;
        if (*s != '0') started = 1;
        if (started) digits[n++] = *s;
    }
    while (n > 1 && digits[n - 1] == '0') n--; /* "1000": one digit */
    digits[n] = 0;
    return n ? n : 1;
}

/* 1 when some decimal of n digits reads back as v: the nearest of n digits and its neighbours
 * one unit away in the last digit (the nearest below and above v are among them) */
static int some_text_of(int n, double v)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.*e", n - 1, v);
    char *e = strchr(buf, 'e');
    int ex = atoi(e + 1);
    long long m = 0;
    for (char *p = buf; p < e; p++)
        if (*p >= '0' && *p <= '9') m = m * 10 + (*p - '0');
    for (int dm = -1; dm <= 1; dm++) {
        char t[64];
        snprintf(t, sizeof t, "%s%llde%d", v < 0 ? "-" : "", (m + dm) < 0 ? -(m + dm) : m + dm, ex - (n - 1));
        if (same_bits(strtod(t, NULL), v)) return 1;
    }
    return 0;
}

typedef struct tally {
    long count, shorter_than_printf, checked_shortest;
} tally;

static void check(double v, int shortest_oracle, tally *t)
{
    char out[LX_DOUBLE_CHARS], ref[64], dig[40], rdig[40];
    size_t len = lx_double_format(v, out);
    assert_int_equal(len, strlen(out));
    assert_true(len < LX_DOUBLE_CHARS);
    double back = strtod(out, NULL);
    if (!same_bits(back, v)) {
        print_error("%a printed as '%s' reads back as %a\n", v, out, back);
        fail();
    }
    int n = sig_digits(out, dig);
    /* closest: printf's correctly rounded n digits, when they read back, are these digits */
    snprintf(ref, sizeof ref, "%.*e", n - 1, v);
    sig_digits(ref, rdig);
    if (same_bits(strtod(ref, NULL), v) && strcmp(dig, rdig) != 0) {
        print_error("%a: '%s' but printf's %d digits '%s' read back too (closer)\n", v, out, n, ref);
        fail();
    }
    /* layout: printf %.Pg with P = max(15, n) wherever its digits are these (everywhere but where
     * the P-digit rounding is not the shortest padded: subnormals, whose gap is wide, and powers of
     * two, whose gap below is half the one above) */
    snprintf(ref, sizeof ref, "%.*g", n > 15 ? n : 15, v);
    sig_digits(ref, rdig);
    if (!strcmp(dig, rdig)) {
        if (strcmp(out, ref) != 0) {
            print_error("%a: '%s', printf %%.%dg gives '%s'\n", v, out, n > 15 ? n : 15, ref);
            fail();
        }
    } else {
        uint64_t b;
        memcpy(&b, &v, sizeof b);
        if (fabs(v) >= DBL_MIN && (b & 0xFFFFFFFFFFFFFull) != 0) {
            print_error("%a: '%s', printf %%.%dg gives '%s' (other digits)\n", v, out, n > 15 ? n : 15, ref);
            fail();
        }
        t->shorter_than_printf++;
    }
    if (shortest_oracle && n > 1 && v != 0) {
        if (some_text_of(n - 1, v)) {
            print_error("%a: '%s' has %d digits but %d suffice\n", v, out, n, n - 1);
            fail();
        }
        t->checked_shortest++;
    }
    t->count++;
}

static long count_from_env(void)
{
    const char *e = getenv("LX_DTOA_COUNT");
    double n = e && *e ? strtod(e, NULL) : 1e6; /* valgrind.sh sets 1e5 */
    return n >= 1e3 ? (long)n : 1000000L;
}

static void test_random_doubles(void **state)
{
    (void)state;
    long total = count_from_env();
    tally t = {0, 0, 0};
    char text[40];
    for (long i = 0; i < total; i++) {
        uint64_t r = next64();
        double v;
        switch (i % 8) {
        case 0: /* a subnormal: exponent field 0 */
            v = from_bits(r & 0x800FFFFFFFFFFFFFull);
            break;
        case 1: { /* a short decimal as data files hold it: 1-15 digits, exponent -20..20 */
            int nd = 1 + (int)(next64() % 15);
            long long m = (long long)(next64() % 1000000000000000ull);
            for (int k = nd; k < 15; k++) m /= 10;
            snprintf(text, sizeof text, "%s%llde%d", r & 1 ? "-" : "", m, (int)(next64() % 41) - 20);
            v = strtod(text, NULL);
            break;
        }
        case 2: /* an exponent near the ends */
            v = from_bits((r & 0x800FFFFFFFFFFFFFull) | ((uint64_t)(r % 2 ? 1 + (r >> 52) % 8 : 2046 - (r >> 52) % 8) << 52));
            break;
        default: /* any finite bit pattern */
            v = from_bits(r);
            if (!isfinite(v)) v = from_bits(r & 0xBFFFFFFFFFFFFFFFull);
            break;
        }
        check(v, i % 4 == 0, &t);
    }
    print_message("%ld doubles read back exactly; %ld checked to be shortest; %ld laid out other than printf's %%.15g (subnormals, powers of 2)\n",
                  t.count, t.checked_shortest, t.shorter_than_printf);
}

static void test_powers_and_edges(void **state)
{
    (void)state;
    tally t = {0, 0, 0};
    char text[40];
    for (int e = -325; e <= 308; e++) { /* every power of ten and the doubles beside it */
        snprintf(text, sizeof text, "1e%d", e);
        double v = strtod(text, NULL);
        check(v, 1, &t);
        check(nextafter(v, 0), 1, &t);
        check(nextafter(v, INFINITY), 1, &t);
        check(-v, 1, &t);
    }
    for (int e = -1074; e <= 1023; e++) { /* every power of two: the lower gap is half the upper */
        double v = ldexp(1.0, e);
        check(v, 1, &t);
        check(nextafter(v, 0), 1, &t);
    }
    static const double edges[] = {DBL_MIN, DBL_MAX, DBL_TRUE_MIN, DBL_EPSILON, 1, 0.1, 0.3, 2.0 / 3, 9007199254740993.0,
                                   123456789012345678.0, 5e-324, 1.7976931348623157e308, 2.2250738585072009e-308};
    for (size_t i = 0; i < sizeof edges / sizeof *edges; i++) check(edges[i], 1, &t), check(-edges[i], 1, &t);
    /* exact texts: the layout users see */
    static const struct {
        double v;
        const char *s;
    } fixed[] = {
        {0.0, "0"}, {-0.0, "-0"}, {1, "1"}, {0.1, "0.1"}, {-2.5, "-2.5"}, {100, "100"}, {1e15, "1e+15"},
        {123456789012345.0, "123456789012345"}, {1234567890123456.0, "1234567890123456"}, {1e-4, "0.0001"},
        {1.5e-5, "1.5e-05"}, {1e23, "1e+23"}, {5e-324, "5e-324"}, {2.2250738585072014e-308, "2.2250738585072014e-308"}, {1.0 / 3, "0.3333333333333333"},
        {1.7976931348623157e308, "1.7976931348623157e+308"}, {2855.5697279956457, "2855.5697279956457"},
        {683.002, "683.002"}, {1e100, "1e+100"},
    };
    for (size_t i = 0; i < sizeof fixed / sizeof *fixed; i++) {
        char out[LX_DOUBLE_CHARS];
        lx_double_format(fixed[i].v, out);
        assert_string_equal(out, fixed[i].s);
    }
    char out[LX_DOUBLE_CHARS];
    lx_double_format(INFINITY, out);
    assert_string_equal(out, "inf");
    lx_double_format(-INFINITY, out);
    assert_string_equal(out, "-inf");
    lx_double_format(NAN, out);
    assert_string_equal(out, "nan");
    print_message("%ld powers, neighbours and edges; %ld with other digits than printf's %%.15g\n", t.count, t.shorter_than_printf);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_powers_and_edges),
        cmocka_unit_test(test_random_doubles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
