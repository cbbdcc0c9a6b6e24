/* batch_csv.c - reads a rows-layout batch CSV (header "id,380,381,...": one spectrum per line on a
 * uniform grid) into a float or double batch in parallel (lx_batch_table_read; streamed chunk by
 * chunk in batch_stream.c): the header, and the parser of a part of the text, lines of short
 * decimals by the vector line parser of csv_vector.c, others by a SWAR number parser and
 * lx__parse_double (all exact, as strtod). */
#include "spectral/batch_csv.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

typedef lx__csv_part part;

static int is_skip_line(const char *s, const char *e)
{
    while (s < e && (*s == ' ' || *s == '\t' || *s == '\r')) s++;
    return s == e || *s == '#';
}

/* The end of the line at s (its '\n', or end), or NULL when it is longer than LX__BATCH_LINE_MAX
 * bytes (without its '\n'): the search never looks further than that. */
const char *lx__csv_line_end(const char *s, const char *end)
{
    size_t room = (size_t)(end - s);
    const char *nl = memchr(s, '\n', room > LX__BATCH_LINE_MAX ? LX__BATCH_LINE_MAX + 1 : room);
    return nl ? nl : room > LX__BATCH_LINE_MAX ? NULL : end;
}

lx_status lx__csv_line_too_long(lx_ctx *ctx, const char *file, long line)
{
    return lx__error(ctx, LX_EPARSE, file, line, "line longer than %zu MB, the longest line of a batch CSV file",
                     LX__BATCH_LINE_MAX >> 20);
}

static void *count_part(void *arg)
{
    part *p = arg;
    const char *s = p->s;
    while (s < p->e) {
        const char *nl = memchr(s, '\n', (size_t)(p->e - s));
        const char *le = nl ? nl : p->e;
        p->lines++;
        if (!is_skip_line(s, le)) p->rows++;
        s = nl ? nl + 1 : p->e;
    }
    return NULL;
}

/* Clinger's fast path: up to 15 significant digits and a decimal exponent within +-22 make
 * m / 10^e (or m * 10^e) one correctly rounded operation on exact operands, so the result is the
 * correctly rounded value, as strtod's. Anything else goes to lx__parse_double. */
static const double pow10_exact[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                       1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define LX_SWAR 1
static const uint64_t pow10_u64[8] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000};
static inline uint64_t load8(const char *p)
{
    uint64_t x;
    memcpy(&x, p, 8);
    return x;
}

/* How many of the 8 bytes of x (first character in the low byte) are ASCII digits before the
 * first one that is not: per byte d = c ^ '0' is a digit exactly when d < 10, tested without
 * carries between bytes ((d & 0x7f) + 0x76 sets the high bit from d = 10 on). */
static inline int leading_digits(uint64_t x)
{
    uint64_t d = x ^ 0x3030303030303030ull;
    uint64_t bad = (((d & 0x7f7f7f7f7f7f7f7full) + 0x7676767676767676ull) | d) & 0x8080808080808080ull;
    return bad ? __builtin_ctzll(bad) >> 3 : 8;
}

/* The value of the first k (1..8) digit characters of x: shifted so they fill the high bytes,
 * then the 8-digit multiply-and-fold (zero bytes below count as leading zeros). */
static inline uint64_t digits_value(uint64_t x, int k)
{
    x = (x & 0x0f0f0f0f0f0f0f0full) << (8 * (8 - k));
    x = (x * 10) + (x >> 8);
    x = (((x & 0x000000ff000000ffull) * (100 + (1000000ull << 32))) +
         (((x >> 16) & 0x000000ff000000ffull) * (1 + (10000ull << 32)))) >> 32;
    return x;
}
#else
#define LX_SWAR 0
#endif

static inline int continues_number(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '.' || c == '_';
}

/* s..end: the rest of the line; lim: the end of the readable buffer (8-byte loads stay before
 * it). Short decimals ("0.123456", "-12.5", "3") take the SWAR path: integer digits and fraction
 * digits, up to 8 each and 15 in all, are read 8 bytes at a time. */
static inline const char *parse_num(const char *s, const char *end, const char *lim, double *out)
{
    const char *p = s;
    int neg = 0;
    if (p < end && (*p == '-' || *p == '+')) neg = *p++ == '-';
#if LX_SWAR
    if (lim - p >= 18) {
        uint64_t x = load8(p);
        int ni = leading_digits(x);
        if (ni >= 1 && ni < 8) {
            uint64_t m = digits_value(x, ni);
            int nf = 0;
            const char *q = p + ni;
            if (q < end && *q == '.') {
                uint64_t y = load8(q + 1);
                nf = leading_digits(y);
                if (nf == 8) goto slow;
                if (nf) m = m * pow10_u64[nf] + digits_value(y, nf);
                q += 1 + nf;
            }
            if (q < end && continues_number(*q)) goto slow; /* exponent, more digits, "12abc" */
            double v = (double)m;
            if (nf) v /= pow10_exact[nf]; /* ni + nf <= 15 digits: exact operands, one rounding */
            *out = neg ? -v : v;
            return q;
        }
    }
slow:;
#else
    (void)lim;
#endif
    unsigned long long m = 0;
    int nd = 0, e = 0;
    const char *d0 = p;
    while (p < end && (unsigned)(*p - '0') < 10) {
        m = m * 10 + (unsigned)(*p++ - '0');
        nd++;
    }
    int nint = nd;
    if (p < end && *p == '.') {
        p++;
        while (p < end && (unsigned)(*p - '0') < 10) {
            m = m * 10 + (unsigned)(*p++ - '0');
            nd++;
        }
    }
    if (nd == 0 || nd > 15 || nd > (int)(p - d0)) return lx__parse_double(s, end, out);
    e = -(nd - nint);
    if (p < end && (*p == 'e' || *p == 'E')) return lx__parse_double(s, end, out);
    if (p < end && ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || *p == '_'))
        return lx__parse_double(s, end, out); /* "12abc": let the full parser reject it */
    double v = (double)m;
    v = e < 0 ? v / pow10_exact[-e] : v; /* -e <= 15 here */
    *out = neg ? -v : v;
    return p;
}

/* Appends a row's name (len bytes at s) to the part's names; 0 (error set) when out of memory. */
static int keep_name(part *p, const char *s, size_t len, size_t *r, long line)
{
    if (p->names_len + len + 1 > p->names_cap) {
        size_t cap = 2 * (p->names_cap + len + 1);
        char *nb = lx__realloc(p->names, cap);
        if (!nb) {
            p->err_line = line;
            snprintf(p->err, sizeof p->err, "out of memory");
            return 0;
        }
        p->names = nb;
        p->names_cap = cap;
    }
    p->name_at[(*r)++] = p->names_len;
    memcpy(p->names + p->names_len, s, len);
    p->names_len += len;
    p->names[p->names_len++] = 0;
    return 1;
}

static _Atomic unsigned long long fast_rows_total; /* rows the vector line parser took, for the tests */

unsigned long long lx__csv_fast_rows(void) { return atomic_load(&fast_rows_total); }

void lx__csv_parse_part(part *p)
{
    const lx_batch_table *t = p->t;
    size_t n = t->batch.n_lambda, row = 0;
    long line = p->line0;
    char sep = p->sep;
    int f32 = t->batch.dtype == LX_F32;
    int fast = lx__csv_fast_level();
    unsigned long long fast_rows = 0;
    size_t names_cap = (size_t)(p->e - p->s) / 8 + p->rows_cap + 16, r = 0;
    if (p->names_cap < names_cap) { /* buffers are kept from one chunk to the next when streaming */
        lx__free(p->names);
        p->names = lx__alloc(names_cap);
        p->names_cap = names_cap;
    }
    if (p->name_at_cap < p->rows_cap + 1) {
        lx__free(p->name_at);
        p->name_at = lx__alloc_n(p->rows_cap + 1, sizeof *p->name_at);
        p->name_at_cap = p->rows_cap + 1;
    }
    p->names_len = 0;
    p->err_line = 0;
    if (!p->names || !p->name_at) {
        p->err_line = line;
        snprintf(p->err, sizeof p->err, "out of memory");
        return;
    }
    const char *s = p->s;
    /* the vector parser's 64-byte loads stay inside the text: lines it reads end before stop */
    const char *stop = p->lim - p->e >= 64 ? p->e : p->lim - 64 > p->s ? p->lim - 64 : p->s;
    int whole = stop == p->e;
    for (; s < p->e; line++) {
        if (fast && s < stop && *s != '#' && *s != ' ' && *s != '\t' && *s != '\r' && *s != '\n') {
            /* a row: the vector parser finds the line's end itself (no scan before it) */
            const char *c = s - 1, *le;
            if (p->named)
                for (c = s; c < stop && *c != sep && *c != '\n'; c++) continue;
            if (c < stop && (!p->named || *c == sep) &&
                lx__csv_fast_line(fast, c + 1, stop, whole, sep, n, f32, (char *)p->values + row * n * (f32 ? 4 : 8), &le)) {
                if (!keep_name(p, s, p->named ? (size_t)(c - s) : 0, &r, line)) return;
                row++;
                fast_rows++;
                p->rows_done = row;
                s = le < p->e ? le + 1 : p->e;
                continue;
            }
        }
        const char *nl = memchr(s, '\n', (size_t)(p->e - s));
        const char *le = nl ? nl : p->e, *next = nl ? nl + 1 : p->e;
        if (le > s && le[-1] == '\r') le--;
        if (is_skip_line(s, le)) {
            s = next;
            continue;
        }
        const char *c = p->named ? memchr(s, sep, (size_t)(le - s)) : s - 1;
        if (!c) {
            p->err_line = line;
            snprintf(p->err, sizeof p->err, "a row needs a name and %zu values", n);
            return;
        }
        size_t nl_len = p->named ? (size_t)(c - s) : 0;
        if (!keep_name(p, s, nl_len, &r, line)) return;
        const char *q = c + 1;
        float *of = (float *)p->values + row * n;
        double *od = (double *)p->values + row * n;
        for (size_t j = 0; j < n; j++) {
            while (q < le && *q == ' ') q++;
            double v;
            const char *z = parse_num(q, le, p->lim, &v);
            if (!z || !isfinite(v) || (f32 && fabs(v) > FLT_MAX)) { /* float batches: no silent inf */
                p->err_line = line;
                snprintf(p->err, sizeof p->err, "value %zu of row '%.*s' is not a finite number%s", j + 1,
                         (int)(nl_len < 60 ? nl_len : 60), s, z && isfinite(v) ? " in float range" : "");
                return;
            }
            while (z < le && *z == ' ') z++;
            if (j + 1 < n ? (z >= le || *z != sep) : z != le) {
                p->err_line = line;
                snprintf(p->err, sizeof p->err, "row '%.*s' has %s than %zu values", (int)(nl_len < 60 ? nl_len : 60), s,
                         j + 1 < n ? "fewer" : "more", n);
                return;
            }
            if (f32) of[j] = (float)v;
            else od[j] = v;
            q = z + 1;
        }
        row++;
        p->rows_done = row;
        s = next;
    }
    p->lines_done = line - p->line0;
    atomic_fetch_add(&fast_rows_total, fast_rows);
}

void lx_batch_table_free(lx_batch_table *t)
{
    if (!t) return;
    lx__free((void *)t->batch.values);
    lx__free(t->names);
    lx__free(t->name_at);
    lx__free(t);
}

typedef lx__csv_header csv_header;

/* count_part / parse_part on part t of an array, as thread t of lx__parallel_run */
static void count_each(void *arg, int t) { count_part((part *)arg + t); }
static void parse_each(void *arg, int t) { lx__csv_parse_part((part *)arg + t); }

lx_status lx__csv_read_header(lx_ctx *ctx, const char *file, const char *text, size_t len, csv_header *H)
{
    const char *end = text + len, *s = text;
    if (len >= 3 && !memcmp(s, "\xEF\xBB\xBF", 3)) s += 3;
    long line = 1;
    const char *hs = NULL, *he = NULL;
    while (s < end) { /* the header: the first line that is not blank or a comment */
        const char *le = lx__csv_line_end(s, end), *nl = le && le < end ? le : NULL;
        if (!le) return lx__csv_line_too_long(ctx, file, line);
        if (!is_skip_line(s, le)) {
            hs = s;
            he = le > s && le[-1] == '\r' ? le - 1 : le;
            s = nl ? nl + 1 : end;
            break;
        }
        s = nl ? nl + 1 : end;
        line++;
    }
    if (!hs) /* name the last line (1 for an empty file) */
        return lx__error(ctx, LX_EPARSE, file, line > 1 ? line - 1 : 1,
                         "no header line: the file is empty or holds only blank and comment lines");
    char sep = 0;
    for (const char *c = hs; c < he && !sep; c++)
        if (*c == ',' || *c == ';' || *c == '\t') sep = *c;
    if (!sep) return lx__error(ctx, LX_EPARSE, file, line, "batch header needs separators (, ; or tab)");
    /* header: name, then wavelengths on a uniform grid */
    size_t n = 0, cap = 512;
    double *lam = lx__alloc_n(cap, sizeof *lam);
    if (!lam) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    /* a first cell that is a number means there is no name column (numpy-style files) */
    const char *q = (const char *)memchr(hs, sep, (size_t)(he - hs)) + 1;
    {
        double v;
        const char *a = hs;
        while (a < q - 1 && *a == ' ') a++;
        const char *z = lx__parse_double(a, q - 1, &v);
        if (z && z == q - 1) q = hs;
    }
    int named = q != hs;
    while (q <= he) {
        const char *ce = memchr(q, sep, (size_t)(he - q));
        if (!ce) ce = he;
        const char *a = q, *b = ce;
        while (a < b && (*a == ' ' || *a == '"')) a++;
        while (b > a && (b[-1] == ' ' || b[-1] == '"')) b--;
        double v;
        const char *z = lx__parse_double(a, b, &v);
        if (!z || z != b || !(v > 0) || !isfinite(v)) { /* 1e999 parses as inf */
            lx__free(lam);
            return lx__error(ctx, LX_EPARSE, file, line, "header cell %zu ('%.*s') is not a wavelength in nm", n + 2,
                             (int)(b - a < 40 ? b - a : 40), a);
        }
        if (n == cap) {
            double *l2 = lx__realloc_n(lam, cap *= 2, sizeof *lam);
            if (!l2) {
                lx__free(lam);
                return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
            }
            lam = l2;
        }
        lam[n++] = v;
        q = ce + 1;
    }
    double step = n > 1 ? (lam[n - 1] - lam[0]) / (double)(n - 1) : 1.0, start = lam[0];
    for (size_t j = 1; j < n; j++)
        if (!(fabs(lam[j] - (start + (double)j * step)) <= 1e-9 * fabs(lam[j])) || !(step > 0)) {
            double bad = lam[j];
            lx__free(lam);
            return lx__error(ctx, LX_EUNSUPPORTED, file, line,
                             "the header's wavelengths are not a uniform increasing grid (at %.17g nm)", bad);
        }
    lx__free(lam);
    *H = (csv_header){s, line, sep, named, n, start, step};
    return LX_OK;
}

lx_status lx_batch_table_read_mem(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_dtype dtype,
                                  int threads, lx_batch_table **out)
{
    LX__NEED_CTX(ctx);
    if (!text || !out) return lx__error(ctx, LX_EINVAL, file, 0, "batch csv: NULL argument");
    *out = NULL;
    if (dtype != LX_F32 && dtype != LX_F64) return lx__error(ctx, LX_EINVAL, file, 0, "batch csv: unknown dtype");
    csv_header H;
    lx_status hst = lx__csv_read_header(ctx, file, text, len, &H);
    if (hst) return hst;
    const char *end = text + len, *s = H.body;
    long line = H.line;
    char sep = H.sep;
    int named = H.named;
    size_t n = H.n;
    double start = H.start, step = H.step;

    /* split the rest into parts at line boundaries; count rows in parallel */
    int T = (size_t)(end - s) < ((size_t)1 << 20) ? 1 : lx__threads(threads, 0);
    part parts[64];
    memset(parts, 0, sizeof parts);
    const char *ps = s;
    for (int i = 0; i < T; i++) {
        const char *pe = i == T - 1 ? end : s + (size_t)(end - s) * (size_t)(i + 1) / (size_t)T;
        if (pe < ps) pe = ps;
        if (i < T - 1) {
            const char *nl = memchr(pe, '\n', (size_t)(end - pe));
            pe = nl ? nl + 1 : end;
        }
        parts[i].s = ps;
        parts[i].e = pe;
        ps = pe;
    }
    for (int i = lx__parallel_run(T, count_each, parts); i < T; i++) count_part(&parts[i]);
    size_t rows = 0;
    long ln = line + 1;
    for (int i = 0; i < T; i++) {
        parts[i].row0 = rows;
        parts[i].line0 = ln;
        rows += parts[i].rows;
        ln += (long)parts[i].lines;
    }
    lx_batch_table *t = lx__calloc(1, sizeof *t);
    size_t es = dtype == LX_F32 ? sizeof(float) : sizeof(double);
    void *vals = t ? lx__alloc(rows * n * es + 1) : NULL;
    if (!t || !vals) {
        lx__free(t);
        return lx__error(ctx, LX_ENOMEM, file, 0, "out of memory for %zu spectra x %zu samples", rows, n);
    }
    t->batch = (lx_batch){.n_spectra = rows, .n_lambda = n, .start_nm = start, .step_nm = step, .dtype = dtype,
                          .values = vals};
    for (int i = 0; i < T; i++) {
        parts[i].t = t;
        parts[i].sep = sep;
        parts[i].named = named;
        parts[i].lim = end;
        parts[i].rows_cap = parts[i].rows;
        parts[i].values = (char *)vals + parts[i].row0 * n * es;
    }
    for (int i = lx__parallel_run(T, parse_each, parts); i < T; i++) lx__csv_parse_part(&parts[i]);
    lx_status st = LX_OK;
    size_t names_len = 0;
    for (int i = 0; i < T && !st; i++) {
        if (parts[i].err_line) st = lx__error(ctx, LX_EPARSE, file, parts[i].err_line, "%s", parts[i].err);
        names_len += parts[i].names_len;
    }
    if (!st) {
        t->names = lx__alloc(names_len + 1);
        t->name_at = lx__alloc_n(rows + 1, sizeof *t->name_at);
        if (!t->names || !t->name_at) st = lx__error(ctx, LX_ENOMEM, file, 0, "out of memory");
    }
    if (!st) {
        size_t off = 0;
        for (int i = 0; i < T; i++) {
            if (parts[i].names_len) memcpy(t->names + off, parts[i].names, parts[i].names_len);
            for (size_t r = 0; r < parts[i].rows; r++) t->name_at[parts[i].row0 + r] = off + parts[i].name_at[r];
            off += parts[i].names_len;
        }
    }
    for (int i = 0; i < T; i++) {
        lx__free(parts[i].names);
        lx__free(parts[i].name_at);
    }
    if (st) {
        lx_batch_table_free(t);
        return st;
    }
    *out = t;
    return LX_OK;
}

/* ---- files: mapped (page cache, no copy) or read (standard input, pipes) ---- */

typedef struct text_file {
    const char *text;
    size_t len;
    void *map;   /* mmap'ed, or NULL */
    char *buf;   /* read, or NULL */
} text_file;

static void text_close(text_file *tf);

/* Regular files are mapped: whole (lx_batch_table_read, `whole` = 1) within the spectrum-file
 * size limit, streamed at any size. Standard input, pipes, FIFOs and devices are read by
 * lx__read_all under that limit, so memory stays bounded whatever they deliver. */
static lx_status text_open(lx_ctx *ctx, const char *path, int whole, text_file *tf)
{
    memset(tf, 0, sizeof *tf);
    struct stat sb;
    if (strcmp(path, "-") != 0 && stat(path, &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_size > 0) {
        lx_status st = whole ? lx__input_size_check(ctx, path, LX_INPUT_SPECTRUM, (unsigned long long)sb.st_size) : LX_OK;
        FILE *f = NULL;
        if (!st) st = lx__open_read(ctx, path, &f);
        if (st) return st;
        void *m = fstat(fileno(f), &sb) == 0 && sb.st_size > 0
                      ? mmap(NULL, (size_t)sb.st_size, PROT_READ, MAP_PRIVATE, fileno(f), 0)
                      : MAP_FAILED;
        fclose(f);
        if (m != MAP_FAILED) {
            posix_madvise(m, (size_t)sb.st_size, POSIX_MADV_SEQUENTIAL);
            tf->map = m;
            tf->text = m;
            tf->len = (size_t)sb.st_size;
            if ((st = lx__text_check(ctx, path, tf->text, tf->len))) text_close(tf);
            return st;
        }
    }
    char *buf = NULL;
    size_t len = 0;
    lx_status st = lx__read_all(ctx, path, LX_INPUT_SPECTRUM, &buf, &len);
    if (st) return st;
    tf->buf = buf;
    tf->text = buf;
    tf->len = len;
    return LX_OK;
}

static void text_close(text_file *tf)
{
    if (tf->map) munmap(tf->map, tf->len);
    lx__free(tf->buf);
}

lx_status lx_batch_table_read(lx_ctx *ctx, const char *path, lx_dtype dtype, int threads, lx_batch_table **out)
{
    LX__NEED_CTX(ctx);
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch csv: NULL argument");
    *out = NULL;
    text_file tf;
    lx_status st = text_open(ctx, path, 1, &tf);
    if (st) return st;
    st = lx_batch_table_read_mem(ctx, path, tf.text, tf.len, dtype, threads, out);
    text_close(&tf);
    return st;
}
