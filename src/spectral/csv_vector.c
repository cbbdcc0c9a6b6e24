/* csv_vector.c - the vector line parser of the batch CSV reader (batch_csv.c): a whole line of
 * short decimals ("0.123456", "-12.5", "3") parsed with AVX-512, four fields per instruction, or
 * by its AVX2 twin (line_avx2 below, two fields per instruction).
 * Anything else (exponents, 16+ characters, spaces, a bad byte) answers 0 and the general parser
 * redoes the line, so this file decides speed, never meaning: every value it returns is the
 * correctly rounded one strtod gives (tests/test_batch.c checks bit for bit).
 *
 * Three passes over a line: (1) separators found 64 bytes at a time give each field's start and
 * length; (2) four fields at a time, one per 128-bit lane, are checked, their '.' closed up and
 * their digits right-aligned and converted by multiply-add pairs (10, 100, 10^4, 10^8) into the
 * signed digits m and the count of fraction digits nf; (3) eight at a time, m / 10^nf in double:
 * at most 15 digits and nf <= 14 make both exact doubles, so one division rounds correctly
 * (Clinger 1990), as strtod does. */
#include "spectral/spectral_private.h"

#include <stdint.h>
#include <string.h>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>

#define LX_AVX512_LINE "avx512f,avx512bw,avx512dq,avx512vl,avx512bitalg,bmi,bmi2,popcnt"

static const double pow10_exact[16] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

/* Fields gathered before conversion (a multiple of 8), and the room one 64-byte block can add
 * beyond it (64 separators, 8 slots written past the last in any case, 4 of padding). */
#define PEND 64
#define PEND_MAX (PEND + 64 + 8 + 4)

/* Pass 2 for four fields of the line at q: field i ends at q + e[i] and starts after the previous
 * end (e[-1] + 1; 16 bytes readable there); lanes from `real` on are padding and read as "0".
 * Writes the digits into m[0..3] and, into nf[0..3], the counts of fraction digits with the
 * sign in bit 7. 0 when a real field is not "-?D+(.D*)?" of 1..15 characters. */
__attribute__((target(LX_AVX512_LINE))) static inline int convert4(const char *q, const uint32_t *e, int real, int64_t *m,
                                                                  uint8_t *nf)
{
    const __m512i iota = _mm512_broadcast_i32x4(_mm_setr_epi8(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
    const __m512i lane = _mm512_set_epi64(0x0303030303030303ll, 0x0303030303030303ll, 0x0202020202020202ll,
                                          0x0202020202020202ll, 0x0101010101010101ll, 0x0101010101010101ll, 0, 0);
    const uint64_t lane0 = 0x0001000100010001ull;
    __m128i E = _mm_loadu_si128((const __m128i *)(const void *)e);
    __m128i S = _mm_add_epi32(_mm_loadu_si128((const __m128i *)(const void *)(e - 1)), _mm_set1_epi32(1));
    __m128i N = _mm_sub_epi32(E, S);
    if (_mm_movemask_epi8(_mm_cmpgt_epi32(N, _mm_set1_epi32(15)))) return 0; /* 16+ characters */
    uint32_t lp = (uint32_t)_mm_cvtsi128_si32(_mm_shuffle_epi8(N, _mm_setr_epi8(0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1)));
    __m512i x = _mm512_castsi128_si512(_mm_loadu_si128((const __m128i *)(const void *)(q + (uint32_t)_mm_cvtsi128_si32(S))));
    x = _mm512_inserti32x4(x, _mm_loadu_si128((const __m128i *)(const void *)(q + (uint32_t)_mm_extract_epi32(S, 1))), 1);
    x = _mm512_inserti32x4(x, _mm_loadu_si128((const __m128i *)(const void *)(q + (uint32_t)_mm_extract_epi32(S, 2))), 2);
    x = _mm512_inserti32x4(x, _mm_loadu_si128((const __m128i *)(const void *)(q + (uint32_t)_mm_extract_epi32(S, 3))), 3);
    if (real < 4) x = _mm512_mask_blend_epi8(~0ull << (16 * real), x, _mm512_set1_epi8('0'));
    __m512i L = _mm512_shuffle_epi8(_mm512_set1_epi32((int)lp), lane); /* lane i: its length in every byte */
    __mmask64 valid = _mm512_cmpgt_epu8_mask(L, iota);
    __m512i d = _mm512_sub_epi8(x, _mm512_set1_epi8('0'));
    __mmask64 dig = _mm512_mask_cmple_epu8_mask(valid, d, _mm512_set1_epi8(9));
    __mmask64 dot = _mm512_mask_cmpeq_epi8_mask(valid, x, _mm512_set1_epi8('.'));
    __mmask64 neg = _mm512_mask_cmpeq_epi8_mask(valid & lane0, x, _mm512_set1_epi8('-'));
    /* every byte a digit, but a leading '-' and a '.' with a digit before it */
    if ((dig | dot | neg) != valid || (dot & (lane0 | neg << 1))) return 0;
    /* per lane (16-bit words of the masks): at most one '.', at least one digit */
    __m128i D = _mm_cvtsi64_si128((long long)dot), G = _mm_cvtsi64_si128((long long)dig);
    __m128i one = _mm_set1_epi16(1), zero = _mm_setzero_si128();
    __m128i many = _mm_and_si128(D, _mm_sub_epi16(D, one));
    if ((_mm_movemask_epi8(_mm_cmpeq_epi16(many, zero)) & 0xff) != 0xff || (_mm_movemask_epi8(_mm_cmpeq_epi16(G, zero)) & 0xff))
        return 0;
    /* upto: bytes 0..'.' of lanes with a '.'; frac: the bytes after it */
    __m128i hasdot = _mm_andnot_si128(_mm_cmpeq_epi16(D, zero), _mm_set1_epi16(-1));
    __m128i U = _mm_and_si128(_mm_sub_epi16(_mm_slli_epi16(D, 1), one), hasdot);
    uint64_t upto = (uint64_t)_mm_cvtsi128_si64(U);
    __m128i frac = _mm_andnot_si128(U, _mm_and_si128(_mm_cvtsi64_si128((long long)valid), hasdot));
    /* nf: fraction digits (a popcount per lane), and the sign in bit 7 (applied to the double, so
     * "-0" gives -0.0), as 4 bytes */
    __m128i nfw = _mm_or_si128(_mm_popcnt_epi16(frac), _mm_slli_epi16(_mm_cvtsi64_si128((long long)neg), 7));
    uint32_t nf4 = (uint32_t)_mm_cvtsi128_si32(_mm_packus_epi16(nfw, nfw));
    memcpy(nf, &nf4, 4);
    /* the digits: others to 0, the '.' closed up (bytes 0..'.' take their left neighbour), the
     * last digit moved to byte 15 of its lane, then 2, 4, 8 and 16 digits at a time */
    d = _mm512_maskz_mov_epi8(dig, d);
    d = _mm512_mask_blend_epi8(upto, d, _mm512_bslli_epi128(d, 1));
    d = _mm512_shuffle_epi8(d, _mm512_add_epi8(iota, _mm512_sub_epi8(L, _mm512_set1_epi8(16))));
    __m512i t = _mm512_maddubs_epi16(d, _mm512_set1_epi16(0x010a));         /* 10 a + b */
    t = _mm512_madd_epi16(t, _mm512_set1_epi32(0x00010064));                /* 100 a + b */
    t = _mm512_packus_epi32(t, t);                                          /* 4-digit words */
    t = _mm512_madd_epi16(t, _mm512_set1_epi32(0x00012710));                /* 10^4 a + b */
    __m512i v = _mm512_add_epi64(_mm512_mul_epu32(t, _mm512_set1_epi64(100000000)), _mm512_srli_epi64(t, 32));
    v = _mm512_permutexvar_epi64(_mm512_setr_epi64(0, 2, 4, 6, 0, 2, 4, 6), v); /* qword 0 of each lane */
    _mm256_storeu_si256((__m256i *)(void *)m, _mm512_castsi512_si256(v));
    return 1;
}

/* Pass 3: dst[0..k) = -+m[i] / 10^nf[i] (as float when f32). */
__attribute__((target(LX_AVX512_LINE))) static void divide8(const int64_t *m, const uint8_t *nf, size_t k, int f32,
                                                           void *dst)
{
    const __m512d p0 = _mm512_loadu_pd(pow10_exact), p1 = _mm512_loadu_pd(pow10_exact + 8);
    for (size_t i = 0; i < k; i += 8) {
        __mmask8 km = k - i >= 8 ? 0xff : (__mmask8)((1u << (k - i)) - 1);
        __m512i mi = _mm512_maskz_loadu_epi64(km, m + i);
        __m512i ni = _mm512_cvtepu8_epi64(_mm_loadl_epi64((const __m128i *)(const void *)(nf + i)));
        __m512d v = _mm512_div_pd(_mm512_cvtepi64_pd(mi), _mm512_permutex2var_pd(p0, ni, p1)); /* index: bits 0-3 */
        __mmask8 sg = _mm512_test_epi64_mask(ni, _mm512_set1_epi64(0x80));
        v = _mm512_castsi512_pd(_mm512_mask_xor_epi64(_mm512_castpd_si512(v), sg, _mm512_castpd_si512(v),
                                                      _mm512_set1_epi64((long long)0x8000000000000000ull)));
        if (f32) _mm256_mask_storeu_ps((float *)dst + i, km, _mm512_cvtpd_ps(v));
        else _mm512_mask_storeu_pd((double *)dst + i, km, v);
    }
}

/* Passes 2 and 3 on the k fields whose ends are e[0..k) (e[-1]: the end before the first). */
__attribute__((target(LX_AVX512_LINE))) static int flush(const char *q, uint32_t *e, size_t k, int f32, void *dst)
{
    int64_t m[PEND_MAX + 4];
    uint8_t nf[PEND_MAX + 12] = {0};
    for (size_t i = k; i % 4; i++) e[i] = e[i - 1] + 2; /* padding lanes: 1 byte each, inside the readable 64 */
    for (size_t i = 0; i < k; i += 4)
        if (!convert4(q, e + i, k - i < 4 ? (int)(k - i) : 4, m + i, nf + i)) return 0;
    divide8(m, nf, k, f32, dst);
    return 1;
}

__attribute__((target(LX_AVX512_LINE))) static int line_avx512(const char *q, const char *stop, int whole, char sep,
                                                               size_t n, int f32, void *dst, const char **line_end)
{
    if ((size_t)(stop - q) >= 0xffff0000u) stop = q + 0xffff0000u, whole = 0; /* offsets are 32-bit */
    const __m512i vsep = _mm512_set1_epi8(sep), vnl = _mm512_set1_epi8('\n');
    uint32_t ends[PEND_MAX + 1], *e = ends + 1; /* e[-1]: the end before the first field */
    size_t j = 0, k = 0, es = f32 ? sizeof(float) : sizeof(double);
    const char *le = NULL;
    e[-1] = 0xffffffffu; /* + 1 wraps to offset 0 */
    for (const char *b = q; b < stop && !le; b += 64) {
        uint64_t in = _bzhi_u64(~0ull, (unsigned)((size_t)(stop - b) < 64 ? (size_t)(stop - b) : 64));
        __m512i x = _mm512_loadu_si512((const void *)b);
        uint64_t sm = _mm512_cmpeq_epi8_mask(x, vsep) & in, nm = _mm512_cmpeq_epi8_mask(x, vnl) & in;
        if (nm) { /* the line ends in this block: separators after it belong to the next line */
            le = b + _tzcnt_u64(nm);
            sm &= _blsmsk_u64(nm) >> 1;
        }
        /* pass 1: each separator ends a field; 8 slots written whatever the count (no branch
         * per field), the ones past the count overwritten later */
        uint32_t base = (uint32_t)(b - q);
        int cnt = __builtin_popcountll(sm);
        uint32_t *w = e + k;
        for (int i = 0; i < 8; i++) {
            w[i] = base + (uint32_t)_tzcnt_u64(sm);
            sm = _blsr_u64(sm);
        }
        for (int i = 8; i < cnt; i++) {
            w[i] = base + (uint32_t)_tzcnt_u64(sm);
            sm = _blsr_u64(sm);
        }
        k += (size_t)cnt;
        if (k >= PEND) { /* convert a multiple of 8; the rest moves to the front */
            size_t c = k / 8 * 8;
            if (j + c >= n || !flush(q, e, c, f32, (char *)dst + j * es)) return 0;
            e[-1] = e[c - 1];
            memmove(e, e + c, (k - c) * sizeof *e);
            j += c, k -= c;
        }
    }
    if (!le) { /* no newline before stop: the line ends there only if that is the end of the text */
        if (!whole) return 0;
        le = stop;
    }
    const char *fe = le > q && le[-1] == '\r' ? le - 1 : le; /* CRLF */
    e[k++] = (uint32_t)(fe - q);
    if (j + k != n || !flush(q, e, k, f32, (char *)dst + j * es)) return 0;
    *line_end = le;
    return 1;
}


/* ---- the AVX2 twin (x86-64-v3: AVX2, BMI1, BMI2, POPCNT): the same three passes, pass 1 on two
 * 32-byte halves of each 64-byte block, pass 2 two fields per instruction (one per 128-bit lane)
 * with byte masks in place of the mask registers and the checks on their movemasks, pass 3 four
 * values per division, m converted exactly through the 2^52 bias (m < 10^15 < 2^52) ---- */
#define LX_AVX2_LINE "avx2,fma,bmi,bmi2,popcnt"

static inline uint64_t lo_pair(uint32_t a, uint32_t b) { return (uint64_t)a | (uint64_t)b << 32; }

/* Pass 2 for two fields (ends e[0], e[1]; the one before at e[-1]); lanes from `real` on are
 * padding and read as "0". As convert4. */
__attribute__((target(LX_AVX2_LINE))) static inline int convert2(const char *q, const uint32_t *e, int real, int64_t *m,
                                                                uint8_t *nf)
{
    uint32_t s0 = e[-1] + 1, s1 = e[0] + 1, L0 = e[0] - s0, L1 = e[1] - s1;
    if (real < 1) L0 = 1;
    if (real < 2) L1 = 1;
    if (L0 > 15 || L1 > 15) return 0; /* 16+ characters (an empty field wraps round: also refused) */
    const __m256i iota = _mm256_setr_epi8(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9,
                                          10, 11, 12, 13, 14, 15);
    __m256i x = _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_loadu_si128((const __m128i *)(const void *)(q + s0))),
                                        _mm_loadu_si128((const __m128i *)(const void *)(q + s1)), 1);
    if (real < 1) x = _mm256_set1_epi8('0');
    else if (real < 2) x = _mm256_blend_epi32(x, _mm256_set1_epi8('0'), 0xF0);
    __m256i Lv = _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_set1_epi8((char)L0)), _mm_set1_epi8((char)L1), 1);
    __m256i valid = _mm256_cmpgt_epi8(Lv, iota);
    __m256i d = _mm256_sub_epi8(x, _mm256_set1_epi8('0'));
    __m256i dig = _mm256_and_si256(_mm256_cmpeq_epi8(_mm256_min_epu8(d, _mm256_set1_epi8(9)), d), valid);
    uint32_t vm = (uint32_t)_mm256_movemask_epi8(valid), gm = (uint32_t)_mm256_movemask_epi8(dig);
    uint32_t pm = (uint32_t)_mm256_movemask_epi8(_mm256_cmpeq_epi8(x, _mm256_set1_epi8('.'))) & vm;
    uint32_t nm = (uint32_t)_mm256_movemask_epi8(_mm256_cmpeq_epi8(x, _mm256_set1_epi8('-'))) & vm & 0x00010001u;
    /* every byte a digit, but a leading '-' and a '.' with a digit before it */
    if ((gm | pm | nm) != vm || (pm & (0x00010001u | nm << 1))) return 0;
    uint32_t p0 = pm & 0xffff, p1 = pm >> 16;
    /* per lane at most one '.', at least one digit */
    if ((p0 & (p0 - 1)) || (p1 & (p1 - 1)) || !(gm & 0xffff) || !(gm >> 16)) return 0;
    int d0 = p0 ? __builtin_ctz(p0) : -1, d1 = p1 ? __builtin_ctz(p1) : -1;
    /* nf: fraction digits, the sign in bit 7 (applied to the double, so "-0" gives -0.0) */
    nf[0] = (uint8_t)((d0 >= 0 ? (int)L0 - d0 - 1 : 0) | (int)(nm & 1) << 7);
    nf[1] = (uint8_t)((d1 >= 0 ? (int)L1 - d1 - 1 : 0) | (int)(nm >> 16 & 1) << 7);
    /* the digits: others to 0, the '.' closed up (bytes 0..'.' take their left neighbour), the
     * last digit moved to byte 15 of its lane, then 2, 4, 8 and 16 digits at a time */
    __m256i upto = _mm256_cmpgt_epi8(
        _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_set1_epi8((char)(d0 + 1))), _mm_set1_epi8((char)(d1 + 1)), 1), iota);
    d = _mm256_and_si256(d, dig);
    d = _mm256_blendv_epi8(d, _mm256_slli_si256(d, 1), upto);
    d = _mm256_shuffle_epi8(d, _mm256_add_epi8(iota, _mm256_sub_epi8(Lv, _mm256_set1_epi8(16))));
    __m256i t = _mm256_maddubs_epi16(d, _mm256_set1_epi16(0x010a));          /* 10 a + b */
    t = _mm256_madd_epi16(t, _mm256_set1_epi32(0x00010064));                 /* 100 a + b */
    t = _mm256_packus_epi32(t, t);                                           /* 4-digit words */
    t = _mm256_madd_epi16(t, _mm256_set1_epi32(0x00012710));                 /* 10^4 a + b */
    __m256i v = _mm256_add_epi64(_mm256_mul_epu32(t, _mm256_set1_epi64x(100000000)), _mm256_srli_epi64(t, 32));
    v = _mm256_permute4x64_epi64(v, 0x08); /* qword 0 of each lane */
    _mm_storeu_si128((__m128i *)(void *)m, _mm256_castsi256_si128(v));
    return 1;
}

/* Pass 3: dst[0..k) = -+m[i] / 10^nf[i] (as float when f32), four at a time. */
__attribute__((target(LX_AVX2_LINE))) static void divide4(const int64_t *m, const uint8_t *nf, size_t k, int f32, void *dst)
{
    const __m256i bias = _mm256_set1_epi64x(0x4330000000000000ll); /* 2^52 as a double */
    for (size_t i = 0; i < k; i += 4) {
        size_t c = k - i < 4 ? k - i : 4;
        __m256i mi = _mm256_loadu_si256((const __m256i *)(const void *)(m + i));
        __m256d v = _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(mi, bias)), _mm256_castsi256_pd(bias));
        int32_t n4;
        memcpy(&n4, nf + i, 4);
        __m128i nb = _mm_cvtsi32_si128(n4);
        __m256d p = _mm256_i32gather_pd(pow10_exact, _mm_and_si128(_mm_cvtepu8_epi32(nb), _mm_set1_epi32(15)), 8);
        v = _mm256_div_pd(v, p);
        __m256i sg = _mm256_slli_epi64(_mm256_and_si256(_mm256_cvtepu8_epi64(nb), _mm256_set1_epi64x(0x80)), 56);
        v = _mm256_castsi256_pd(_mm256_xor_si256(_mm256_castpd_si256(v), sg));
        __m256i keep = _mm256_cmpgt_epi64(_mm256_set1_epi64x((long long)c), _mm256_setr_epi64x(0, 1, 2, 3));
        if (f32) {
            __m128i k32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(keep, _mm256_setr_epi32(0, 2, 4, 6, 0, 0, 0, 0)));
            _mm_maskstore_ps((float *)dst + i, k32, _mm256_cvtpd_ps(v));
        } else {
            _mm256_maskstore_pd((double *)dst + i, keep, v);
        }
    }
}

/* Passes 2 and 3 on the k fields whose ends are e[0..k) (e[-1]: the end before the first). */
__attribute__((target(LX_AVX2_LINE))) static int flush2(const char *q, uint32_t *e, size_t k, int f32, void *dst)
{
    int64_t m[PEND_MAX + 4];
    uint8_t nf[PEND_MAX + 12] = {0};
    for (size_t i = k; i % 4; i++) e[i] = e[i - 1] + 2; /* padding lanes: 1 byte each, inside the readable 64 */
    for (size_t i = 0; i < k; i += 2) {
        int real = k - i < 2 ? (int)(k - i) : 2;
        if (!convert2(q, e + i, real, m + i, nf + i)) return 0;
    }
    divide4(m, nf, k, f32, dst);
    return 1;
}

__attribute__((target(LX_AVX2_LINE))) static int line_avx2(const char *q, const char *stop, int whole, char sep, size_t n,
                                                          int f32, void *dst, const char **line_end)
{
    if ((size_t)(stop - q) >= 0xffff0000u) stop = q + 0xffff0000u, whole = 0; /* offsets are 32-bit */
    const __m256i vsep = _mm256_set1_epi8(sep), vnl = _mm256_set1_epi8('\n');
    uint32_t ends[PEND_MAX + 1], *e = ends + 1; /* e[-1]: the end before the first field */
    size_t j = 0, k = 0, es = f32 ? sizeof(float) : sizeof(double);
    const char *le = NULL;
    e[-1] = 0xffffffffu; /* + 1 wraps to offset 0 */
    for (const char *b = q; b < stop && !le; b += 64) {
        uint64_t in = _bzhi_u64(~0ull, (unsigned)((size_t)(stop - b) < 64 ? (size_t)(stop - b) : 64));
        __m256i x0 = _mm256_loadu_si256((const __m256i *)(const void *)b);
        __m256i x1 = _mm256_loadu_si256((const __m256i *)(const void *)(b + 32));
        uint64_t sm = lo_pair((uint32_t)_mm256_movemask_epi8(_mm256_cmpeq_epi8(x0, vsep)),
                              (uint32_t)_mm256_movemask_epi8(_mm256_cmpeq_epi8(x1, vsep))) & in;
        uint64_t nm = lo_pair((uint32_t)_mm256_movemask_epi8(_mm256_cmpeq_epi8(x0, vnl)),
                              (uint32_t)_mm256_movemask_epi8(_mm256_cmpeq_epi8(x1, vnl))) & in;
        if (nm) { /* the line ends in this block: separators after it belong to the next line */
            le = b + _tzcnt_u64(nm);
            sm &= _blsmsk_u64(nm) >> 1;
        }
        /* pass 1: each separator ends a field; 8 slots written whatever the count */
        uint32_t base = (uint32_t)(b - q);
        int cnt = __builtin_popcountll(sm);
        uint32_t *w = e + k;
        for (int i = 0; i < 8; i++) {
            w[i] = base + (uint32_t)_tzcnt_u64(sm);
            sm = _blsr_u64(sm);
        }
        for (int i = 8; i < cnt; i++) {
            w[i] = base + (uint32_t)_tzcnt_u64(sm);
            sm = _blsr_u64(sm);
        }
        k += (size_t)cnt;
        if (k >= PEND) { /* convert a multiple of 8; the rest moves to the front */
            size_t c = k / 8 * 8;
            if (j + c >= n || !flush2(q, e, c, f32, (char *)dst + j * es)) return 0;
            e[-1] = e[c - 1];
            memmove(e, e + c, (k - c) * sizeof *e);
            j += c, k -= c;
        }
    }
    if (!le) { /* no newline before stop: the line ends there only if that is the end of the text */
        if (!whole) return 0;
        le = stop;
    }
    const char *fe = le > q && le[-1] == '\r' ? le - 1 : le; /* CRLF */
    e[k++] = (uint32_t)(fe - q);
    if (j + k != n || !flush2(q, e, k, f32, (char *)dst + j * es)) return 0;
    *line_end = le;
    return 1;
}

int lx__csv_fast_line(int level, const char *q, const char *stop, int whole, char sep, size_t n, int f32, void *dst,
                      const char **line_end)
{
    if (level == 2) return line_avx512(q, stop, whole, sep, n, f32, dst, line_end);
    if (level == 1) return line_avx2(q, stop, whole, sep, n, f32, dst, line_end);
    return 0;
}

int lx__csv_fast_level(void)
{
    lx_simd l = lx_simd_level();
    if (l == LX_SIMD_AVX512 && lx__cpu_has_bitalg()) return 2;
    return l >= LX_SIMD_AVX2 ? 1 : 0; /* AVX-512 without BITALG runs the AVX2 twin */
}

#else

int lx__csv_fast_line(int level, const char *q, const char *stop, int whole, char sep, size_t n, int f32, void *dst,
                      const char **line_end)
{
    (void)level, (void)q, (void)stop, (void)whole, (void)sep, (void)n, (void)f32, (void)dst, (void)line_end;
    return 0;
}

int lx__csv_fast_level(void) { return 0; }

#endif
