/* cpu.c - the one CPU-feature dispatcher: which SIMD path this CPU runs, checked against every
 * instruction-set extension each path's code is compiled for, capped by LX_SIMD=scalar|avx2|avx512.
 * Every SIMD twin in the library asks lx_simd_level(); none tests the CPU itself. */
#include "core/core_private.h"

#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define LX__X86 1
#include <cpuid.h>
#else
#define LX__X86 0
#endif

/* The extensions of each path (what its target attributes name; __builtin_cpu_supports also checks
 * that the OS saves the YMM / ZMM state). AVX2: the x86-64-v3 set; AVX-512: x86-64-v4. */
#if LX__X86
/* F16C, MOVBE and LZCNT straight from CPUID (clang's __builtin_cpu_supports does not name them):
 * leaf 1 ECX bits 29 and 22, leaf 0x80000001 ECX bit 5. */
static int cpu_v3_extras(void)
{
    unsigned a, b, c, d;
    if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & (1u << 29)) || !(c & (1u << 22))) return 0;
    if (!__get_cpuid(0x80000001u, &a, &b, &c, &d) || !(c & (1u << 5))) return 0;
    return 1;
}
#endif

static int cpu_avx2(void)
{
#if LX__X86
    return __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
           __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("popcnt") &&
           cpu_v3_extras();
#else
    return 0;
#endif
}

static int cpu_avx512(void)
{
#if LX__X86
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
           __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512vl");
#else
    return 0;
#endif
}

lx_simd lx_simd_cpu(void)
{
    static int cached = -1; /* the answer never changes; a race writes the same value */
    if (cached < 0) {
#if LX__X86
        __builtin_cpu_init();
#endif
        int v2 = cpu_avx2();
        cached = v2 && cpu_avx512() ? LX_SIMD_AVX512 : v2 ? LX_SIMD_AVX2 : LX_SIMD_SCALAR;
    }
    return (lx_simd)cached;
}

int lx__cpu_has_bitalg(void)
{
#if LX__X86
    return lx_simd_cpu() == LX_SIMD_AVX512 && __builtin_cpu_supports("avx512bitalg");
#else
    return 0;
#endif
}

/* The SIMD path named by text into *out; 0 when text names none (then *out is untouched). */
static int simd_by_name(const char *text, lx_simd *out)
{
    if (!strcmp(text, "scalar")) *out = LX_SIMD_SCALAR;
    else if (!strcmp(text, "avx2")) *out = LX_SIMD_AVX2;
    else if (!strcmp(text, "avx512")) *out = LX_SIMD_AVX512;
    else return 0;
    return 1;
}

lx_status lx_simd_parse(lx_ctx *ctx, const char *text, lx_simd *out)
{
    LX__NEED_CTX(ctx);
    if (!text || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "simd: NULL argument");
    if (!simd_by_name(text, out))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown SIMD path '%s' (expected scalar, avx2 or avx512)", text);
    return LX_OK;
}

lx_simd lx_simd_level(void)
{
    lx_simd c = lx_simd_cpu(), cap = LX_SIMD_AVX512;
    const char *e = getenv("LX_SIMD"); /* read on every call: tests change it within one process */
    if (e && *e) simd_by_name(e, &cap);
    return c < cap ? c : cap;
}

const char *lx_simd_name(lx_simd simd)
{
    switch (simd) {
    case LX_SIMD_SCALAR: return "scalar";
    case LX_SIMD_AVX2: return "avx2";
    case LX_SIMD_AVX512: return "avx512";
    }
    return NULL;
}
