/* test_numparse.c - the fast float parser (src/core/numparse.c) against the C library's strtod, the
 * oracle: bit-identical results for random doubles in several printed forms, hard cases, and the
 * inputs it must reject. */
#include "lx_test.h"

#include <float.h>
#include <string.h>

#include "core/core_private.h"

static uint64_t rng_state = 0x9E3779B97F4A7C15ULL;
static uint64_t next_u64(void) /* xorshift64*: any fixed generator will do */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 0x2545F4914F6CDD1DULL;
}

static uint64_t bits_of(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

static double from_bits(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

/* Parses the whole of s with lx__parse_double and with strtod; both must consume all of it
 * and agree bit for bit. Returns 0 on success, printing the case otherwise. */
static int same_as_strtod(const char *s)
{
    size_t n = strlen(s);
    double mine = 0, ref;
    const char *end = lx__parse_double(s, s + n, &mine);
    char *rend;
    ref = strtod(s, &rend);
    if (end != s + n || *rend != '\0' || bits_of(mine) != bits_of(ref)) {
        print_error("'%s': parsed %.17g (%016llx, end +%td), strtod %.17g (%016llx)\n", s, mine,
                    (unsigned long long)bits_of(mine), end ? end - s : -1, ref, (unsigned long long)bits_of(ref));
        return 1;
    }
    return 0;
}

static void test_random_doubles(void **state)
{
    (void)state;
    char buf[64];
    int bad = 0;
    /* 1,000,000 random bit patterns (every finite double equally likely per exponent), %.17g:
     * the round-trip form, so the parse must also give back the very same bits. */
    for (int i = 0; i < 1000000 && bad < 10; i++) {
        double d;
        do d = from_bits(next_u64());
        while (!isfinite(d));
        snprintf(buf, sizeof buf, "%.17g", d);
        bad += same_as_strtod(buf);
        double back = 0;
        lx__parse_double(buf, buf + strlen(buf), &back);
        if (bits_of(back) != bits_of(d)) {
            print_error("%.17g does not round-trip\n", d);
            bad++;
        }
        if (i % 4 == 0) {
            snprintf(buf, sizeof buf, "%.6g", d);
            bad += same_as_strtod(buf);
            snprintf(buf, sizeof buf, "%g", d);
            bad += same_as_strtod(buf);
            snprintf(buf, sizeof buf, "%.17e", d);
            bad += same_as_strtod(buf);
        }
    }
    /* values of everyday magnitude, as spectral files hold them */
    for (int i = 0; i < 200000 && bad < 10; i++) {
        double d = (double)(next_u64() >> 11) * 0x1p-53 * 1000.0;
        snprintf(buf, sizeof buf, "%.17g", d);
        bad += same_as_strtod(buf);
        snprintf(buf, sizeof buf, "%.6f", d);
        bad += same_as_strtod(buf);
        snprintf(buf, sizeof buf, "%.3g", d);
        bad += same_as_strtod(buf);
    }
    assert_int_equal(bad, 0);
}

static void test_integers_and_extremes(void **state)
{
    (void)state;
    char buf[64];
    int bad = 0;
    for (long long i = -100000; i <= 100000; i += 7) {
        snprintf(buf, sizeof buf, "%lld", i);
        bad += same_as_strtod(buf);
    }
    for (int i = 0; i < 100000; i++) { /* 64-bit integers: above 2^53 they need rounding */
        snprintf(buf, sizeof buf, "%llu", (unsigned long long)next_u64());
        bad += same_as_strtod(buf);
    }
    for (int i = 0; i < 100000; i++) { /* subnormals: 0 < bits < 2^52 */
        double d = from_bits(next_u64() & 0x000FFFFFFFFFFFFFULL);
        snprintf(buf, sizeof buf, "%.17g", d);
        bad += same_as_strtod(buf);
        snprintf(buf, sizeof buf, "%.6g", d);
        bad += same_as_strtod(buf);
    }
    for (int k = -2000; k <= 2000; k++) { /* neighbours of DBL_MAX, DBL_MIN, DBL_TRUE_MIN, 1 */
        uint64_t bases[4] = {bits_of(DBL_MAX) - 2000, bits_of(DBL_MIN), 1, bits_of(1.0)};
        for (int b = 0; b < 4; b++) {
            uint64_t u = bases[b] + (uint64_t)(k < 0 ? -k : k) + (b == 0 ? 0 : 0);
            if (b == 0 && k > 0) continue;
            double d = from_bits(u);
            snprintf(buf, sizeof buf, "%.17g", d);
            bad += same_as_strtod(buf);
            snprintf(buf, sizeof buf, "%.16g", d);
            bad += same_as_strtod(buf);
        }
    }
    assert_int_equal(bad, 0);
}

static void test_hard_cases(void **state)
{
    (void)state;
    static const char *const cases[] = {
        "0", "-0", "0.0", "+0e10", "1", "-1", ".5", "5.", "+1.5", "1e5", "1E-5", "1e+5", "00000123.4500000",
        "2.2250738585072011e-308",  /* the value that hung PHP and Java: just below DBL_MIN */
        "2.2250738585072012e-308",  /* just at it */
        "4.9406564584124654e-324",  /* DBL_TRUE_MIN */
        "2.4703282292062327e-324",  /* half of it: ties to 0 */
        "2.4703282292062328e-324",  /* just above half: rounds up to DBL_TRUE_MIN */
        "1.7976931348623157e308",   /* DBL_MAX */
        "1.7976931348623158e308",   /* rounds to DBL_MAX */
        "1.7976931348623159e308",   /* overflows to infinity (strtod: HUGE_VAL) */
        "1e999", "-1e999", "1e-999", "1e23", "8.589973e9", "9007199254740993", /* 2^53 + 1: tie, to even */
        "9007199254740993.0000000000000000001",  /* just above the tie */
        "9007199254740992.9999999999999999999", "0.1000000000000000055511151231257827021181583404541015625",
        "0.10000000000000000555111512312578270211815834045410156250000000000001",
        "123456789012345678901234567890", "0.000000000000000000000000000000000000000000001234567890123456789012",
        "7.2057594037927933e16", "3.0517578125e-05", "1e22", "1e-22", "9999999999999999999", "18446744073709551615",
        "18446744073709551616", "1.00000000000000011102230246251565404236316680908203125", /* 1 + 2^-53: tie */
        "1.00000000000000011102230246251565404236316680908203126", "100000000000000000000000000000e-30",
        "1e99999999999999999999", "1e-99999999999999999999", "0e99999999999",
    };
    int bad = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) bad += same_as_strtod(cases[i]);
    assert_int_equal(bad, 0);
}

static void test_rejections(void **state)
{
    (void)state;
    static const char *const bad[] = {
        "", "+", "-", ".", "e5", "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "0x1p3", "0X10", "1e", "1e+",
        "12abc", "1.2.3", "1_000", "\xd9\xa1",      /* ARABIC-INDIC DIGIT ONE, U+0661 */
        "\xef\xbc\x91",                             /* FULLWIDTH DIGIT ONE, U+FF11 */
        "1\xd9\xa3",                                /* an ASCII digit running into U+0663 */
        "5nm", " 5",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        double d = 42;
        const char *r = lx__parse_double(bad[i], bad[i] + strlen(bad[i]), &d);
        if (r) print_error("'%s' was accepted\n", bad[i]);
        assert_null(r);
        assert_true(d == 42); /* untouched */
    }
}

static void test_bounds_and_separators(void **state)
{
    (void)state;
    double d = 0;
    const char *s = "380,0.125;x";
    const char *r = lx__parse_double(s, s + strlen(s), &d);
    assert_ptr_equal(r, s + 3); /* stops at the separator */
    assert_true(d == 380.0);
    r = lx__parse_double(s + 4, s + strlen(s), &d);
    assert_ptr_equal(r, s + 9);
    assert_true(d == 0.125); /* 0.125 = 2^-3 exactly */
    const char *t = "123456";
    r = lx__parse_double(t, t + 3, &d); /* the end bound is honoured */
    assert_ptr_equal(r, t + 3);
    assert_true(d == 123.0);
    /* decimal comma: "0,123" reads as strtod("0.123") */
    const char *c = "0,123";
    r = lx__parse_double_ex(c, c + 5, ',', &d);
    assert_ptr_equal(r, c + 5);
    assert_true(bits_of(d) == bits_of(strtod("0.123", NULL)));
    r = lx__parse_double_ex("2.5", (const char *)"2.5" + 3, ',', &d); /* '.' still accepted */
    assert_non_null(r);
    assert_true(d == 2.5);
    r = lx__parse_double(c, c + 5, &d); /* without the option the comma ends the number */
    assert_ptr_equal(r, c + 1);
    assert_true(d == 0.0);
    /* a long decimal-comma token takes the slow path: still the same bits */
    const char *lc = "0,1000000000000000055511151231257827021181583404541015625";
    r = lx__parse_double_ex(lc, lc + strlen(lc), ',', &d);
    assert_non_null(r);
    assert_true(bits_of(d) == bits_of(0.1)); /* the digits are 0.1's exact binary value */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_doubles),   cmocka_unit_test(test_integers_and_extremes),
        cmocka_unit_test(test_hard_cases),       cmocka_unit_test(test_rejections),
        cmocka_unit_test(test_bounds_and_separators),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
