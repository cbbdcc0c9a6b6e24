/* lxgen.c - build-time generator: turns the CIE tables (the CSV files of src/data) and the OpenCL kernels
 * (the .cl files of kernels/) into C source, so the library needs no files at run time.
 * and the power-of-5 tables of the shortest number printer (core/dtoa.c), computed exactly in big integers.
 * Usage: lxgen tables OUT.c FILE.csv...   |   lxgen kernels OUT.c FILE.cl...   |   lxgen pow5 OUT.c */
#include <ctype.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void die(const char *file, long line, const char *what)
{
    fprintf(stderr, "lxgen: %s:%ld: %s\n", file, line, what);
    exit(1);
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) die(path, 0, "cannot open");
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap + 1);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) buf = realloc(buf, (cap *= 2) + 1);
    }
    fclose(f);
    if (!buf) die(path, 0, "out of memory");
    buf[n] = 0;
    *len = n;
    return buf;
}

static void c_string(FILE *out, const char *s, size_t len)
{
    fputc('"', out);
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '\n') {
            fputs("\\n\"\n    \"", out);
        } else if (c == '\\' || c == '"') {
            fputc('\\', out);
            fputc(c, out);
        } else if (c < 32 || c >= 127) {
            fprintf(out, "\\%03o", c);
        } else {
            fputc(c, out);
        }
    }
    fputc('"', out);
}

static const char *stem(const char *path, char *buf, size_t cap)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    snprintf(buf, cap, "%s", b);
    char *dot = strrchr(buf, '.');
    if (dot) *dot = 0;
    for (char *p = buf; *p; p++)
        if (!isalnum((unsigned char)*p)) *p = '_';
    return buf;
}

static void gen_table(FILE *out, const char *path, int index)
{
    size_t len;
    char *text = slurp(path, &len);
    char name[256];
    stem(path, name, sizeof name);
    /* provenance: the '#' lines, verbatim */
    fprintf(out, "/* %s */\nstatic const char prov_%d[] = ", path, index);
    char *p = text;
    size_t provlen = 0;
    while (p[provlen] == '#') {
        char *nl = strchr(p + provlen, '\n');
        provlen = nl ? (size_t)(nl - p) + 1 : len;
    }
    c_string(out, p, provlen);
    fputs(";\n", out);
    p += provlen;
    /* header */
    char *nl = strchr(p, '\n');
    if (!nl) die(path, 0, "no header line");
    *nl = 0;
    int ncols = 0;
    fprintf(out, "static const char *const cols_%d[] = {", index);
    for (char *tok = p;; ncols++) {
        char *comma = strchr(tok, ',');
        if (comma) *comma = 0;
        char *cr = strchr(tok, '\r');
        if (cr) *cr = 0;
        fprintf(out, "\"%s\", ", tok);
        if (!comma) break;
        tok = comma + 1;
    }
    ncols++;
    fputs("};\n", out);
    /* rows, then transposed into column-major order */
    size_t cap = 1024, nrows = 0;
    char **cells = malloc(cap * ncols * sizeof *cells);
    long lineno = 1;
    for (char *q = text; q < p; q++) lineno += *q == '\n';
    for (p = nl + 1; *p; lineno++) {
        nl = strchr(p, '\n');
        if (nl) *nl = 0;
        char *cr = strchr(p, '\r');
        if (cr) *cr = 0;
        if (*p) {
            if (nrows == cap) cells = realloc(cells, (cap *= 2) * ncols * sizeof *cells);
            int c = 0;
            for (char *tok = p;; c++) {
                char *comma = strchr(tok, ',');
                if (comma) *comma = 0;
                if (c >= ncols) die(path, lineno, "too many fields");
                cells[nrows * ncols + c] = tok;
                if (!comma) break;
                tok = comma + 1;
            }
            if (c + 1 != ncols) die(path, lineno, "too few fields");
            nrows++;
        }
        if (!nl) break;
        p = nl + 1;
    }
    fprintf(out, "static const double data_%d[] = {\n", index);
    for (int c = 0; c < ncols; c++) {
        for (size_t r = 0; r < nrows; r++) {
            const char *cell = cells[r * ncols + c];
            char *end;
            strtod(cell, &end);
            if (!*cell)
                fputs("NAN,", out);
            else if (*end || end == cell)
                die(path, (long)r, "not a number");
            else
                fprintf(out, "%s,", cell);
            fputc((r % 8 == 7) ? '\n' : ' ', out);
        }
        fputc('\n', out);
    }
    fputs("};\n", out);
    fprintf(out, "#define TABLE_%d {\"%s\", prov_%d, %zu, %d, cols_%d, data_%d}\n\n", index, name, index,
            nrows, ncols, index, index);
    free(cells);
    free(text);
}

/* ---- pow5: big integers of 32-bit limbs, least significant first ---- */
#define BIG_LIMBS 40 /* 1280 bits: 5^341 has 792 */
typedef struct big {
    uint32_t d[BIG_LIMBS];
} big;

static int big_bits(const big *a)
{
    for (int i = BIG_LIMBS - 1; i >= 0; i--)
        if (a->d[i])
            for (int b = 31; b >= 0; b--)
                if (a->d[i] >> b & 1) return 32 * i + b + 1;
    return 0;
}

static int big_bit(const big *a, int k) { return k < 0 || k >= 32 * BIG_LIMBS ? 0 : (int)(a->d[k / 32] >> (k % 32) & 1); }

/* bits [lo, lo + 128) of a (lo may be negative: zeros below bit 0) as two 64-bit halves */
static void big_slice128(const big *a, int lo, uint64_t out[2])
{
    out[0] = out[1] = 0;
    for (int k = 0; k < 128; k++)
        if (big_bit(a, lo + k)) out[k / 64] |= 1ull << (k % 64);
}

static int big_cmp(const big *a, const big *b)
{
    for (int i = BIG_LIMBS - 1; i >= 0; i--)
        if (a->d[i] != b->d[i]) return a->d[i] < b->d[i] ? -1 : 1;
    return 0;
}

static void big_sub(big *a, const big *b) /* a -= b, a >= b */
{
    uint64_t borrow = 0;
    for (int i = 0; i < BIG_LIMBS; i++) {
        uint64_t t = (uint64_t)a->d[i] - b->d[i] - borrow;
        a->d[i] = (uint32_t)t;
        borrow = t >> 63;
    }
}

static void big_shl1_add(big *a, int bit) /* a = 2a + bit */
{
    uint32_t carry = (uint32_t)bit;
    for (int i = 0; i < BIG_LIMBS; i++) {
        uint32_t c = a->d[i] >> 31;
        a->d[i] = a->d[i] << 1 | carry;
        carry = c;
    }
}

/* Ryu's tables (Adams 2018, "Ryu: fast float-to-string conversion", section 3.3, 125-bit
 * factors): split[i] = 5^i scaled by a power of 2 to exactly 125 bits; inv[i] =
 * floor(2^(bits(5^i) - 1 + 125) / 5^i) + 1. */
static void gen_pow5(FILE *out)
{
    enum { SPLIT = 326, INV = 342, BITS = 125 };
    big p = {{1}};
    fprintf(out, "const uint64_t lx__pow5_split[%d][2] = {\n", SPLIT);
    big pows[INV];
    for (int i = 0; i < INV; i++) {
        pows[i] = p;
        uint64_t carry = 0; /* p *= 5 */
        for (int k = 0; k < BIG_LIMBS; k++) {
            uint64_t t = (uint64_t)p.d[k] * 5 + carry;
            p.d[k] = (uint32_t)t;
            carry = t >> 32;
        }
        if (carry) die("pow5", i, "overflow");
    }
    for (int i = 0; i < SPLIT; i++) {
        uint64_t v[2];
        big_slice128(&pows[i], big_bits(&pows[i]) - BITS, v);
        fprintf(out, "    {%lluu, %lluu},\n", (unsigned long long)v[0], (unsigned long long)v[1]);
    }
    fprintf(out, "};\nconst uint64_t lx__pow5_inv_split[%d][2] = {\n", INV);
    for (int i = 0; i < INV; i++) {
        int j = big_bits(&pows[i]) - 1 + BITS;
        big r = {{0}};
        uint64_t q[2] = {0, 0};
        for (int b = j; b >= 0; b--) { /* binary long division of 2^j by 5^i */
            big_shl1_add(&r, b == j);
            if (big_cmp(&r, &pows[i]) >= 0) {
                big_sub(&r, &pows[i]);
                if (b >= 128) die("pow5", i, "quotient beyond 128 bits");
                q[b / 64] |= 1ull << (b % 64);
            }
        }
        if (++q[0] == 0) q[1]++;
        fprintf(out, "    {%lluu, %lluu},\n", (unsigned long long)q[0], (unsigned long long)q[1]);
    }
    fputs("};\n", out);
}

int main(int argc, char **argv)
{
    if (argc == 3 && !strcmp(argv[1], "pow5")) {
        char tmp[4096];
        snprintf(tmp, sizeof tmp, "%s.tmp", argv[2]);
        FILE *out = fopen(tmp, "w");
        if (!out) die(tmp, 0, "cannot create");
        fputs("/* Generated by src/tools/lxgen.c (pow5). Do not edit. */\n#include <stdint.h>\n\n", out);
        gen_pow5(out);
        if (fclose(out) != 0 || rename(tmp, argv[2]) != 0) die(argv[2], 0, "cannot write");
        return 0;
    }
    if (argc < 3 || (strcmp(argv[1], "tables") && strcmp(argv[1], "kernels"))) {
        fprintf(stderr, "usage: lxgen tables|kernels OUT.c FILE... | lxgen pow5 OUT.c\n");
        return 1;
    }
    int tables = !strcmp(argv[1], "tables");
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp", argv[2]);
    FILE *out = fopen(tmp, "w");
    if (!out) die(tmp, 0, "cannot create");
    fputs("/* Generated by src/tools/lxgen.c from", out);
    for (int i = 3; i < argc; i++) fprintf(out, " %s", argv[i]);
    fprintf(out, ". Do not edit. */\n#include \"%s\"\n#include <math.h>\n\n",
            tables ? "tables/tables_private.h" : "core/core_private.h");
    int n = argc - 3;
    if (tables) {
        for (int i = 0; i < n; i++) gen_table(out, argv[3 + i], i);
        fputs("const lx__table lx__tables[] = {\n", out);
        for (int i = 0; i < n; i++) fprintf(out, "    TABLE_%d,\n", i);
        fprintf(out, "};\nconst int lx__ntables = %d;\n", n);
    } else {
        fputs("const lx__kernel_source lx__kernel_sources[] = {\n", out);
        for (int i = 0; i < n; i++) {
            size_t len;
            char *text = slurp(argv[3 + i], &len);
            const char *base = strrchr(argv[3 + i], '/');
            fprintf(out, "    {\"%s\",\n    ", base ? base + 1 : argv[3 + i]);
            c_string(out, text, len);
            fputs("},\n", out);
            free(text);
        }
        if (n == 0) fputs("    {NULL, NULL},\n", out);
        fprintf(out, "};\nconst int lx__nkernel_sources = %d;\n", n);
    }
    if (fclose(out) != 0 || rename(tmp, argv[2]) != 0) die(argv[2], 0, "cannot write");
    return 0;
}
