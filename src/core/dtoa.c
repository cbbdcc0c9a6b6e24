/* dtoa.c - shortest round-trip decimal text of a double (lx_double_format): the Ryu algorithm
 * (Ulf Adams, "Ryu: fast float-to-string conversion", PLDI 2018), written here from the paper,
 * with its power-of-5 tables generated exactly at build time (src/tools/lxgen.c pow5), then laid
 * out as printf's %.17g would lay out those digits. */
#include "core/core_private.h"

#include <stdint.h>
#include <string.h>

#define MANT_BITS 52
#define EXP_BITS 11
#define BIAS 1023
#define POW5_INV_BITCOUNT 125
#define POW5_BITCOUNT 125

extern const uint64_t lx__pow5_split[326][2];     /* 5^i to 125 bits */
extern const uint64_t lx__pow5_inv_split[342][2]; /* 2^k / 5^q rounded up, 125-126 bits */

#if defined(__SIZEOF_INT128__)
__extension__ typedef unsigned __int128 u128;
/* (m * mul) >> j for a 55-bit m and a 128-bit mul, j >= 64 */
static inline uint64_t mul_shift64(uint64_t m, const uint64_t *mul, int j)
{
    u128 b0 = (u128)m * mul[0], b2 = (u128)m * mul[1];
    return (uint64_t)(((b0 >> 64) + b2) >> (j - 64));
}
#else
static inline uint64_t umul128(uint64_t a, uint64_t b, uint64_t *hi)
{
    uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p10 + (uint32_t)p01;
    *hi = p11 + (p10 >> 32) + (p01 >> 32) + (mid >> 32);
    return (mid << 32) | (uint32_t)p00;
}
static inline uint64_t mul_shift64(uint64_t m, const uint64_t *mul, int j)
{
    uint64_t h0, h1;
    (void)umul128(m, mul[0], &h0);
    uint64_t l1 = umul128(m, mul[1], &h1);
    uint64_t sum = h0 + l1; /* bits 64..127 of the product, carry into bits 128.. */
    h1 += sum < h0;
    int s = j - 64; /* 0 < s < 64 in every use */
    return (sum >> s) | (h1 << (64 - s));
}
#endif

static inline int pow5bits(int e) { return ((e * 1217359) >> 19) + 1; }  /* ceil(log2(5^e)), e >= 1; 1 at 0 */
static inline int log10pow2(int e) { return (e * 78913) >> 18; }        /* floor(log10(2^e)), 0 <= e <= 1650 */
static inline int log10pow5(int e) { return (e * 732923) >> 20; }       /* floor(log10(5^e)), 0 <= e <= 2620 */

static inline int pow5_factor(uint64_t v)
{
    int n = 0;
    while (v % 5 == 0) v /= 5, n++;
    return n;
}
static inline int multiple_of_pow5(uint64_t v, int p) { return pow5_factor(v) >= p; }
static inline int multiple_of_pow2(uint64_t v, int p) { return (v & ((1ull << p) - 1)) == 0; }

/* The shortest decimal d * 10^e that reads back as the double with these bits (finite, nonzero or
 * zero), the closest to it when there are several (ties to even digit). */
static void shortest(uint64_t ieee_m, uint32_t ieee_e, uint64_t *digits, int *exp10)
{
    int e2;
    uint64_t m2;
    if (ieee_e == 0) {
        e2 = 1 - BIAS - MANT_BITS - 2; /* 2 more bits for the bounds */
        m2 = ieee_m;
    } else {
        e2 = (int)ieee_e - BIAS - MANT_BITS - 2;
        m2 = (1ull << MANT_BITS) | ieee_m;
    }
    int accept_bounds = (m2 & 1) == 0; /* round-half-even reading keeps an even mantissa's bounds */
    uint64_t mv = 4 * m2;
    uint32_t mm_shift = ieee_m != 0 || ieee_e <= 1; /* the lower gap is half as wide at a power of 2 */
    uint64_t vr, vp, vm;
    int e10, vm_tz = 0, vr_tz = 0;
    if (e2 >= 0) {
        int q = log10pow2(e2) - (e2 > 3);
        e10 = q;
        int k = POW5_INV_BITCOUNT + pow5bits(q) - 1, i = -e2 + q + k;
        vr = mul_shift64(4 * m2, lx__pow5_inv_split[q], i);
        vp = mul_shift64(4 * m2 + 2, lx__pow5_inv_split[q], i);
        vm = mul_shift64(4 * m2 - 1 - mm_shift, lx__pow5_inv_split[q], i);
        if (q <= 21) { /* only one of mp, mv, mm can be a multiple of 5 */
            if (mv % 5 == 0) vr_tz = multiple_of_pow5(mv, q);
            else if (accept_bounds) vm_tz = multiple_of_pow5(mv - 1 - mm_shift, q);
            else vp -= (uint64_t)multiple_of_pow5(mv + 2, q);
        }
    } else {
        int q = log10pow5(-e2) - (-e2 > 1);
        e10 = q + e2;
        int i = -e2 - q, k = pow5bits(i) - POW5_BITCOUNT, j = q - k;
        vr = mul_shift64(4 * m2, lx__pow5_split[i], j);
        vp = mul_shift64(4 * m2 + 2, lx__pow5_split[i], j);
        vm = mul_shift64(4 * m2 - 1 - mm_shift, lx__pow5_split[i], j);
        if (q <= 1) { /* mv = 4 m2 has at least 2 trailing zero bits */
            vr_tz = 1;
            if (accept_bounds) vm_tz = mm_shift == 1;
            else --vp;
        } else if (q < 63) {
            vr_tz = multiple_of_pow2(mv, q);
        }
    }
    /* remove digits while the interval still holds a number with fewer */
    int removed = 0;
    unsigned last = 0;
    uint64_t out;
    if (vm_tz || vr_tz) { /* the rare general case: exact trailing zeros decide ties */
        for (; vp / 10 > vm / 10; removed++) {
            vm_tz &= vm % 10 == 0;
            vr_tz &= last == 0;
            last = (unsigned)(vr % 10);
            vr /= 10, vp /= 10, vm /= 10;
        }
        if (vm_tz)
            for (; vm % 10 == 0; removed++) {
                vr_tz &= last == 0;
                last = (unsigned)(vr % 10);
                vr /= 10, vp /= 10, vm /= 10;
            }
        if (vr_tz && last == 5 && vr % 2 == 0) last = 4; /* exactly ...50..0: round to even */
        out = vr + ((vr == vm && (!accept_bounds || !vm_tz)) || last >= 5);
    } else {
        int round_up = 0;
        if (vp / 100 > vm / 100) { /* two digits at a time first */
            round_up = vr % 100 >= 50;
            vr /= 100, vp /= 100, vm /= 100;
            removed += 2;
        }
        for (; vp / 10 > vm / 10; removed++) {
            round_up = vr % 10 >= 5;
            vr /= 10, vp /= 10, vm /= 10;
        }
        out = vr + (vr == vm || round_up);
    }
    *digits = out;
    *exp10 = e10 + removed;
}

static const char digit_pairs[201] = "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
                                     "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
                                     "8081828384858687888990919293949596979899";

/* the n decimal digits of v into p[0..n) */
static inline void put_digits(char *p, uint64_t v, int n)
{
    while (n >= 2) {
        memcpy(p + n - 2, digit_pairs + 2 * (v % 100), 2);
        v /= 100, n -= 2;
    }
    if (n) p[0] = (char)('0' + v);
}

static inline int count_digits(uint64_t v)
{
    int n = 1;
    for (uint64_t p = 10; n < 20 && v >= p; p *= 10) n++;
    return n;
}

size_t lx_double_format(double value, char *out)
{
    uint64_t bits;
    memcpy(&bits, &value, sizeof bits);
    int neg = (int)(bits >> 63);
    uint64_t ieee_m = bits & ((1ull << MANT_BITS) - 1);
    uint32_t ieee_e = (uint32_t)(bits >> MANT_BITS) & ((1u << EXP_BITS) - 1);
    char *p = out;
    if (ieee_e == (1u << EXP_BITS) - 1) { /* as printf: inf, -inf, nan */
        const char *s = ieee_m ? "nan" : neg ? "-inf" : "inf";
        size_t n = strlen(s);
        memcpy(out, s, n + 1);
        return n;
    }
    if (neg) *p++ = '-';
    if (ieee_e == 0 && ieee_m == 0) {
        *p++ = '0';
        *p = 0;
        return (size_t)(p - out);
    }
    uint64_t d;
    int e;
    shortest(ieee_m, ieee_e, &d, &e);
    int n = count_digits(d), x = e + n - 1; /* value = d.ddd x 10^x */
    /* %.Pg's choice with P = max(n, 15) (so the text is what the shortest of %.15g, %.16g and %.17g
     * that reads back would print): fixed for -4 <= x < P, else exponential; no trailing zeros */
    int prec = n > 15 ? n : 15;
    if (x >= -4 && x < prec) {
        if (x < 0) { /* 0.000ddd */
            *p++ = '0';
            *p++ = '.';
            for (int i = -1; i > x; i--) *p++ = '0';
            put_digits(p, d, n);
            p += n;
        } else if (x + 1 >= n) { /* ddd000 */
            put_digits(p, d, n);
            p += n;
            for (int i = n; i <= x; i++) *p++ = '0';
        } else { /* dd.ddd */
            char tmp[20];
            put_digits(tmp, d, n);
            memcpy(p, tmp, (size_t)x + 1);
            p += x + 1;
            *p++ = '.';
            memcpy(p, tmp + x + 1, (size_t)(n - x - 1));
            p += n - x - 1;
        }
    } else {
        char tmp[20];
        put_digits(tmp, d, n);
        *p++ = tmp[0];
        if (n > 1) {
            *p++ = '.';
            memcpy(p, tmp + 1, (size_t)n - 1);
            p += n - 1;
        }
        *p++ = 'e';
        *p++ = x < 0 ? '-' : '+';
        int ax = x < 0 ? -x : x;
        if (ax >= 100) {
            *p++ = (char)('0' + ax / 100);
            ax %= 100;
        }
        memcpy(p, digit_pairs + 2 * ax, 2);
        p += 2;
    }
    *p = 0;
    return (size_t)(p - out);
}
