/* batch_csv.c - reads a rows-layout batch CSV (header "id,380,381,...": one spectrum per line on a
 * uniform grid) straight into a float or double batch, in parallel (lines split between threads),
 * numbers parsed by lx__parse_double. The fast input of `luxcalc spd` batches and `bench spd`. */
#include "lx_private.h"

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

typedef struct part {
    const char *s, *e;   /* whole lines */
    size_t rows, lines;  /* data rows and all lines in the part (pass 1) */
    size_t row0;         /* first row index (pass 2) */
    long line0;          /* line number of its first line */
    /* pass 2 */
    const lx_batch_table *t;
    char sep;
    int named;           /* rows start with a name cell */
    char *names;         /* this part's names, NUL-separated */
    size_t names_len;
    size_t *name_at;     /* local offsets */
    long err_line;       /* 0: no error */
    char err[256];
} part;

static int is_skip_line(const char *s, const char *e)
{
    while (s < e && (*s == ' ' || *s == '\t' || *s == '\r')) s++;
    return s == e || *s == '#';
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

static inline const char *parse_num(const char *s, const char *end, double *out)
{
    const char *p = s;
    int neg = 0;
    if (p < end && (*p == '-' || *p == '+')) neg = *p++ == '-';
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

static void *parse_part(void *arg)
{
    part *p = arg;
    const lx_batch_table *t = p->t;
    size_t n = t->batch.n_lambda, row = p->row0;
    long line = p->line0;
    char sep = p->sep;
    int f32 = t->batch.dtype == LX_F32;
    p->names = malloc((size_t)(p->e - p->s) / 8 + p->rows + 16);
    p->name_at = malloc((p->rows + 1) * sizeof *p->name_at);
    if (!p->names || !p->name_at) {
        p->err_line = line;
        snprintf(p->err, sizeof p->err, "out of memory");
        return NULL;
    }
    size_t names_cap = (size_t)(p->e - p->s) / 8 + p->rows + 16, r = 0;
    const char *s = p->s;
    for (; s < p->e; line++) {
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
            return NULL;
        }
        size_t nl_len = p->named ? (size_t)(c - s) : 0;
        if (p->names_len + nl_len + 1 > names_cap) {
            names_cap = 2 * (names_cap + nl_len + 1);
            char *nb = realloc(p->names, names_cap);
            if (!nb) {
                p->err_line = line;
                snprintf(p->err, sizeof p->err, "out of memory");
                return NULL;
            }
            p->names = nb;
        }
        p->name_at[r++] = p->names_len;
        memcpy(p->names + p->names_len, s, nl_len);
        p->names_len += nl_len;
        p->names[p->names_len++] = 0;
        const char *q = c + 1;
        float *of = (float *)t->batch.values + row * n;
        double *od = (double *)t->batch.values + row * n;
        for (size_t j = 0; j < n; j++) {
            while (q < le && *q == ' ') q++;
            double v;
            const char *z = parse_num(q, le, &v);
            if (!z || !isfinite(v)) {
                p->err_line = line;
                snprintf(p->err, sizeof p->err, "value %zu of row '%.*s' is not a finite number", j + 1,
                         (int)(nl_len < 60 ? nl_len : 60), s);
                return NULL;
            }
            while (z < le && *z == ' ') z++;
            if (j + 1 < n ? (z >= le || *z != sep) : z != le) {
                p->err_line = line;
                snprintf(p->err, sizeof p->err, "row '%.*s' has %s than %zu values", (int)(nl_len < 60 ? nl_len : 60), s,
                         j + 1 < n ? "fewer" : "more", n);
                return NULL;
            }
            if (f32) of[j] = (float)v;
            else od[j] = v;
            q = z + 1;
        }
        row++;
        s = next;
    }
    return NULL;
}

void lx_batch_table_free(lx_batch_table *t)
{
    if (!t) return;
    free((void *)t->batch.values);
    free(t->names);
    free(t->name_at);
    free(t);
}

lx_status lx_batch_table_read_mem(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_dtype dtype,
                                  int threads, lx_batch_table **out)
{
    if (!text || !out) return lx__error(ctx, LX_EINVAL, file, 0, "batch csv: NULL argument");
    *out = NULL;
    const char *end = text + len, *s = text;
    if (len >= 3 && !memcmp(s, "\xEF\xBB\xBF", 3)) s += 3;
    long line = 1;
    const char *hs = NULL, *he = NULL;
    while (s < end) { /* the header: the first line that is not blank or a comment */
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        const char *le = nl ? nl : end;
        if (!is_skip_line(s, le)) {
            hs = s;
            he = le > s && le[-1] == '\r' ? le - 1 : le;
            s = nl ? nl + 1 : end;
            break;
        }
        s = nl ? nl + 1 : end;
        line++;
    }
    if (!hs) return lx__error(ctx, LX_EPARSE, file, 0, "empty file: no header line");
    char sep = 0;
    for (const char *c = hs; c < he && !sep; c++)
        if (*c == ',' || *c == ';' || *c == '\t') sep = *c;
    if (!sep) return lx__error(ctx, LX_EPARSE, file, line, "batch header needs separators (, ; or tab)");
    /* header: name, then wavelengths on a uniform grid */
    size_t n = 0, cap = 512;
    double *lam = malloc(cap * sizeof *lam);
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
        if (!z || z != b || !(v > 0)) {
            free(lam);
            return lx__error(ctx, LX_EPARSE, file, line, "header cell %zu ('%.*s') is not a wavelength in nm", n + 2,
                             (int)(b - a < 40 ? b - a : 40), a);
        }
        if (n == cap) {
            double *l2 = realloc(lam, (cap *= 2) * sizeof *lam);
            if (!l2) {
                free(lam);
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
            free(lam);
            return lx__error(ctx, LX_EUNSUPPORTED, file, line,
                             "the header's wavelengths are not a uniform increasing grid (at %.17g nm)", bad);
        }
    free(lam);

    /* split the rest into parts at line boundaries; count rows in parallel */
    int T = threads > 0 ? threads : (int)sysconf(_SC_NPROCESSORS_ONLN);
    if (T < 1) T = 1;
    if (T > 64) T = 64;
    if ((size_t)(end - s) < ((size_t)1 << 20)) T = 1;
    part parts[64];
    pthread_t tid[64];
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
    for (int i = 1; i < T; i++)
        if (pthread_create(&tid[i], NULL, count_part, &parts[i])) {
            count_part(&parts[i]);
            tid[i] = 0;
        }
    count_part(&parts[0]);
    for (int i = 1; i < T; i++)
        if (tid[i]) pthread_join(tid[i], NULL);
    size_t rows = 0;
    long ln = line + 1;
    for (int i = 0; i < T; i++) {
        parts[i].row0 = rows;
        parts[i].line0 = ln;
        rows += parts[i].rows;
        ln += (long)parts[i].lines;
    }
    lx_batch_table *t = calloc(1, sizeof *t);
    size_t es = dtype == LX_F32 ? sizeof(float) : sizeof(double);
    void *vals = t ? malloc(rows * n * es + 1) : NULL;
    if (!t || !vals) {
        free(t);
        return lx__error(ctx, LX_ENOMEM, file, 0, "out of memory for %zu spectra x %zu samples", rows, n);
    }
    t->batch = (lx_batch){.n_spectra = rows, .n_lambda = n, .start_nm = start, .step_nm = step, .dtype = dtype,
                          .values = vals};
    for (int i = 0; i < T; i++) {
        parts[i].t = t;
        parts[i].sep = sep;
        parts[i].named = named;
    }
    for (int i = 1; i < T; i++)
        if (pthread_create(&tid[i], NULL, parse_part, &parts[i])) {
            parse_part(&parts[i]);
            tid[i] = 0;
        }
    parse_part(&parts[0]);
    for (int i = 1; i < T; i++)
        if (tid[i]) pthread_join(tid[i], NULL);
    lx_status st = LX_OK;
    size_t names_len = 0;
    for (int i = 0; i < T && !st; i++) {
        if (parts[i].err_line) st = lx__error(ctx, LX_EPARSE, file, parts[i].err_line, "%s", parts[i].err);
        names_len += parts[i].names_len;
    }
    if (!st) {
        t->names = malloc(names_len + 1);
        t->name_at = malloc((rows + 1) * sizeof *t->name_at);
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
        free(parts[i].names);
        free(parts[i].name_at);
    }
    if (st) {
        lx_batch_table_free(t);
        return st;
    }
    *out = t;
    return LX_OK;
}

lx_status lx_batch_table_read(lx_ctx *ctx, const char *path, lx_dtype dtype, int threads, lx_batch_table **out)
{
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch csv: NULL argument");
    FILE *f = NULL;
    lx_status ost = lx__open_read(ctx, path, &f);
    if (ost) return ost;
    struct stat sb;
    size_t cap = f != stdin && fstat(fileno(f), &sb) == 0 && sb.st_size > 0 ? (size_t)sb.st_size + 1 : 1 << 20;
    size_t len = 0, got;
    char *buf = malloc(cap);
    while (buf && (got = fread(buf + len, 1, cap - len, f)) > 0) {
        len += got;
        if (len == cap) {
            char *b = realloc(buf, cap *= 2);
            if (!b) free(buf);
            buf = b;
        }
    }
    int rerr = ferror(f);
    if (f != stdin) fclose(f);
    if (!buf) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory reading the file");
    if (rerr) {
        free(buf);
        return lx__error(ctx, LX_EIO, path, 0, "read error");
    }
    lx_status st = lx_batch_table_read_mem(ctx, path, buf, len, dtype, threads, out);
    free(buf);
    return st;
}
