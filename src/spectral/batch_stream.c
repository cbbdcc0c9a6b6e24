/* batch_stream.c - a rows-layout batch CSV streamed in bounded memory (lx_batch_table_stream_ex,
 * lx_batch_table_stream, lx_batch_table_integrate_file): threads parse the parts of the next
 * round of text (and run the caller's per-part work on them) while the caller's thread emits the
 * parts of the last round in file order. The text is a memory map released behind the reader, or
 * (pipes, standard input) read into two alternating buffers. */
#include "spectral/batch_csv.h"

#include <errno.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

/* A round parses up to PARTS_PER_THREAD parts a thread of this much text each; threads take parts
 * from a counter, so one kept off its core by another process delays a round by one part at most. */
#define PART_BYTES ((size_t)512 << 10)
/* parts in flight per thread: 4 measured 14 % faster than 8 (42 MB, 2 threads): the values of a
 * smaller chunk are still in cache when they are integrated, and fewer buffers are first-touched */
#define PARTS_PER_THREAD 4
#define MAX_PARTS 64
#define PAD 64 /* bytes readable past the text of a buffer (the vector parser's loads), zeros */

typedef struct spart {
    lx__csv_part p;
    size_t cap;                 /* rows p.values holds */
    void *state;                /* the caller's, kept from round to round */
    lx_status work_st;
    unsigned long long end_off; /* input offset of the end of the part */
} spart;

typedef struct sset {
    spart q[MAX_PARTS];
    int count;
    _Atomic int next;           /* the next part to parse */
    long first_line;            /* line number of the first line of q[0] */
    const lx_batch_stream *cb;
    char *buf;                  /* read mode: this round's text, PAD zero bytes after it */
    size_t cap;
} sset;

/* parts of a set taken one at a time from its counter by each thread; the work follows the parse */
static void parse_set(void *arg, int t)
{
    sset *S = arg;
    for (int i; (i = atomic_fetch_add_explicit(&S->next, 1, memory_order_relaxed)) < S->count;) {
        spart *q = &S->q[i];
        lx__csv_parse_part(&q->p);
        q->work_st = LX_OK;
        if (!q->p.err_line && q->p.rows_done && S->cb->work) {
            lx_batch_table view = {.batch = q->p.t->batch, .names = q->p.names, .name_at = q->p.name_at};
            view.batch.n_spectra = q->p.rows_done;
            view.batch.values = q->p.values;
            q->work_st = S->cb->work(S->cb->user, t, &view, &q->state);
        }
    }
}

/* ---- the input: a map (regular files) or reads into the round's buffer ---- */

typedef struct source {
    FILE *f;                    /* read mode (NULL in map mode) */
    int own_f;                  /* close f at the end */
    const char *map;            /* map mode: the whole file */
    size_t map_len, released;   /* bytes from the start already unmapped (page multiple) */
    unsigned long long total;   /* input size, 0 when unknown */
    const char *prefix;         /* read mode: bytes to take before reading f */
    size_t prefix_len;
    char *carry;                /* read mode: the start of a line the last round cut off */
    size_t carry_len, carry_cap;
    unsigned long long off;     /* read mode: input offset of the next round's first byte */
    int eof;
    int too_long;               /* read mode: the carried line is longer than LX__BATCH_LINE_MAX */
} source;

static lx_status source_open(lx_ctx *ctx, const char *path, const lx_batch_stream *cb, source *src)
{
    memset(src, 0, sizeof *src);
    if (cb->input) {
        src->f = cb->input;
        src->prefix = cb->prefix;
        src->prefix_len = cb->prefix ? cb->prefix_len : 0;
        return LX_OK;
    }
    FILE *f = NULL;
    lx_status st = lx__open_read(ctx, path, &f);
    if (st) return st;
    struct stat sb;
    if (f != stdin && fstat(fileno(f), &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_size > 0) {
        void *m = mmap(NULL, (size_t)sb.st_size, PROT_READ, MAP_PRIVATE, fileno(f), 0);
        if (m != MAP_FAILED) {
            posix_madvise(m, (size_t)sb.st_size, POSIX_MADV_SEQUENTIAL);
            fclose(f);
            src->map = m;
            src->map_len = src->total = (unsigned long long)sb.st_size;
            return lx__text_check(ctx, path, src->map, src->map_len); /* binary data: refused at once */
        }
        src->total = (unsigned long long)sb.st_size;
    }
    src->f = f;
    src->own_f = f != stdin;
    return LX_OK;
}

static void source_close(source *src)
{
    if (src->map && src->map_len > src->released)
        munmap((void *)(src->map + src->released), src->map_len - src->released);
    if (src->own_f) fclose(src->f);
    lx__free(src->carry);
}

/* Map mode: unmaps the whole pages before offset `to` (the text of emitted rounds). */
static void source_release(source *src, size_t to)
{
    long pg = sysconf(_SC_PAGESIZE);
    size_t page = pg > 0 ? (size_t)pg : 4096, end = to / page * page;
    if (!src->map || end <= src->released) return;
    munmap((void *)(src->map + src->released), end - src->released);
    src->released = end;
}

/* Read mode: fills S->buf with the carried line start, then input, up to `want` bytes of whole
 * lines (more when one line is longer); *len gets the bytes of whole lines (all that is left at
 * the end of the input), the rest is carried. `need_header`: also keep reading until the first
 * line with content is complete. */
static lx_status source_fill(lx_ctx *ctx, const char *path, source *src, sset *S, size_t want, int need_header,
                             size_t *len)
{
    size_t n = 0;
    for (;;) {
        size_t room = want > n ? want - n : 0;
        if (S->cap < n + room + PAD + 1 || S->cap < src->carry_len + PAD + 1) {
            size_t cap = 2 * (n + room + src->carry_len) + PAD + 1;
            char *b = lx__realloc(S->buf, cap);
            if (!b) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory for %zu bytes of input", cap);
            S->buf = b, S->cap = cap;
        }
        if (src->carry_len) {
            memcpy(S->buf + n, src->carry, src->carry_len);
            n += src->carry_len, src->carry_len = 0;
        }
        while (n < want && !src->eof) {
            size_t got;
            if (src->prefix_len) {
                got = src->prefix_len < want - n ? src->prefix_len : want - n;
                memcpy(S->buf + n, src->prefix, got);
                src->prefix += got, src->prefix_len -= got;
            } else {
                got = fread(S->buf + n, 1, want - n, src->f);
                if (got == 0) {
                    if (ferror(src->f)) return lx__error(ctx, LX_EIO, path, 0, "read error: %s", strerror(errno));
                    src->eof = 1;
                }
            }
            n += got;
        }
        /* whole lines: up to the last '\n' (everything at the end of the input) */
        const char *nl = NULL;
        for (const char *p = S->buf + n; p > S->buf; p--)
            if (p[-1] == '\n') {
                nl = p;
                break;
            }
        int header_ok = 1;
        if (need_header && nl) { /* the first line with content must end before nl */
            const char *p = S->buf, *e = nl;
            if (e - p >= 3 && !memcmp(p, "\xEF\xBB\xBF", 3)) p += 3;
            header_ok = 0;
            while (p < e && !header_ok) {
                const char *le = memchr(p, '\n', (size_t)(e - p));
                const char *c = p;
                while (c < le && (*c == ' ' || *c == '\t' || *c == '\r')) c++;
                if (c < le && *c != '#') header_ok = 1;
                p = le + 1;
            }
        }
        if (src->eof || (nl && header_ok)) {
            size_t whole = src->eof ? n : (size_t)(nl - S->buf);
            size_t rest = n - whole;
            if (rest) {
                if (src->carry_cap < rest) {
                    char *c = lx__realloc(src->carry, rest);
                    if (!c) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
                    src->carry = c, src->carry_cap = rest;
                }
                memcpy(src->carry, S->buf + whole, rest);
                src->carry_len = rest;
            }
            memset(S->buf + whole, 0, PAD);
            *len = whole;
            return LX_OK;
        }
        /* a line longer than the round: read on, up to the longest line a batch file may hold
         * (then the header is left to lx__csv_read_header, a row is refused once the rows before
         * it are emitted) */
        if (n > LX__BATCH_LINE_MAX + 1) {
            if (need_header) {
                memset(S->buf + n, 0, PAD);
                *len = n;
                return LX_OK;
            }
            src->too_long = 1;
            src->carry_len = 0;
            *len = 0;
            return LX_OK;
        }
        want = 2 * (n > want ? n : want);
        if (want > LX__BATCH_LINE_MAX + 2) want = LX__BATCH_LINE_MAX + 2;
        src->carry_len = 0;
        size_t keep = n;
        n = 0;
        if (src->carry_cap < keep) {
            char *c = lx__realloc(src->carry, keep);
            if (!c) return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
            src->carry = c, src->carry_cap = keep;
        }
        memcpy(src->carry, S->buf, keep);
        src->carry_len = keep;
    }
}

/* Cuts [pos, end) into parts of S at line boundaries, up to max_parts; lim: the end of the
 * readable text; off0: the input offset of `base`. Returns where it stopped. */
static const char *cut_parts(lx_ctx *ctx, const char *path, sset *S, const char *pos, const char *end, const char *lim,
                             const char *base, unsigned long long off0, int max_parts, const lx_batch_table *tmpl,
                             const lx__csv_header *H, const char **too_long, lx_status *st)
{
    size_t n = tmpl->batch.n_lambda, es = tmpl->batch.dtype == LX_F32 ? sizeof(float) : sizeof(double);
    const char *set_start = pos;
    /* a set holds about max_parts parts' worth of text, however long its lines */
    while (pos < end && S->count < max_parts && (size_t)(pos - set_start) < (size_t)max_parts * PART_BYTES) {
        spart *q = &S->q[S->count];
        const char *pe = (size_t)(end - pos) > PART_BYTES ? pos + PART_BYTES : end;
        if (pe < end) { /* the end of the line at the cut: the only line of the part that can be long */
            const char *nl = lx__csv_line_end(pe, end), *ls = NULL;
            if (!nl || (size_t)(nl - pos) > LX__BATCH_LINE_MAX) {
                for (ls = pe; ls > pos && ls[-1] != '\n'; ls--) continue;
                if (nl && (size_t)(nl - ls) <= LX__BATCH_LINE_MAX) ls = NULL;
            }
            if (ls) { /* the rows before it are parsed and emitted; then the error */
                *too_long = ls;
                pe = ls;
            } else {
                pe = nl < end ? nl + 1 : end;
            }
        }
        if (pe == pos) break;
        /* a row takes at least 2 n - 1 bytes (n one-character values and their separators) */
        size_t cap = (size_t)(pe - pos) / (2 * n - 1 + (n == 1)) + 1;
        if (cap > q->cap) {
            lx__free(q->p.values);
            q->p.values = lx__alloc(cap * n * es);
            q->cap = q->p.values ? cap : 0;
            if (!q->p.values) {
                *st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory for a chunk of %zu spectra", cap);
                return pos;
            }
        }
        q->p.s = pos;
        q->p.e = pe;
        q->p.lim = lim;
        q->p.t = tmpl;
        q->p.sep = H->sep;
        q->p.named = H->named;
        q->p.line0 = 0;
        q->p.rows_cap = cap;
        q->p.rows_done = 0;
        q->p.lines_done = 0;
        q->end_off = off0 + (unsigned long long)(pe - base);
        pos = pe;
        S->count++;
        if (*too_long) break;
    }
    return pos;
}

/* Emits the parts of P in order; row0 advances. */
static lx_status emit_set(const lx_batch_stream *cb, sset *P, size_t *row0, unsigned long long total)
{
    lx_status st = LX_OK;
    for (int i = 0; i < P->count && !st; i++) {
        spart *q = &P->q[i];
        if (q->work_st) return q->work_st;
        lx_batch_table view = {.batch = q->p.t->batch, .names = q->p.names, .name_at = q->p.name_at};
        view.batch.n_spectra = q->p.rows_done;
        view.batch.values = q->p.values;
        if (q->p.rows_done) st = cb->emit(cb->user, &view, *row0, q->state);
        *row0 += q->p.rows_done;
        if (!st && cb->progress) cb->progress(cb->user, q->end_off, total);
    }
    return st;
}

/* Read mode: the whole lines [p, p + n) the round did not take go back before the carried text. */
static int source_unread(source *src, const char *p, size_t n)
{
    if (!n) return 0;
    if (src->carry_cap < n + src->carry_len) {
        char *c = lx__realloc(src->carry, n + src->carry_len);
        if (!c) return -1;
        src->carry = c, src->carry_cap = n + src->carry_len;
    }
    memmove(src->carry + n, src->carry, src->carry_len);
    memcpy(src->carry, p, n);
    src->carry_len += n;
    return 0;
}

lx_status lx_batch_table_stream_ex(lx_ctx *ctx, const char *path, lx_dtype dtype, int threads, const lx_batch_stream *cb)
{
    LX__NEED_CTX(ctx);
    if (!path || !cb || !cb->emit) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch csv: NULL argument");
    if (dtype != LX_F32 && dtype != LX_F64) return lx__error(ctx, LX_EINVAL, path, 0, "batch csv: unknown dtype");
    lx_status st = lx__check_reserved(ctx, "batch stream callbacks", cb->reserved, sizeof cb->reserved);
    if (st) return st;
    int T = lx__threads(threads, 0);
    if (T > MAX_PARTS) T = MAX_PARTS;
    int max_parts = PARTS_PER_THREAD * T < MAX_PARTS ? PARTS_PER_THREAD * T : MAX_PARTS;
    size_t round_bytes = (size_t)max_parts * PART_BYTES;
    source src;
    if ((st = source_open(ctx, path, cb, &src))) {
        source_close(&src);
        return st;
    }
    sset *sets = lx__calloc(2, sizeof *sets);
    if (!sets) {
        source_close(&src);
        return lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
    }
    sets[0].cb = sets[1].cb = cb;
    /* the header: from the map, or from the first round's buffer */
    lx__csv_header H;
    const char *pos = NULL, *end = NULL, *too_long = NULL;
    size_t len = 0;
    if (src.map) {
        st = lx__csv_read_header(ctx, path, src.map, src.map_len, &H);
        pos = H.body, end = src.map + src.map_len;
    } else if (!(st = source_fill(ctx, path, &src, &sets[0], round_bytes, 1, &len)) &&
               !(st = lx__text_check(ctx, path, sets[0].buf, len))) {
        st = lx__csv_read_header(ctx, path, sets[0].buf, len, &H);
        pos = H.body, end = sets[0].buf + len;
        src.off = len;
    }
    /* the table parse_part reads its grid and dtype from */
    lx_batch_table tmpl = {.batch = {.n_lambda = st ? 1 : H.n, .dtype = dtype}};
    if (!st) tmpl.batch.start_nm = H.start, tmpl.batch.step_nm = H.step;
    long next_line = st ? 0 : H.line + 1;
    size_t row0 = 0;
    int cur = 0, have_prev = 0, first = 1;
    while (!st) {
        sset *S = &sets[cur], *P = &sets[cur ^ 1];
        S->count = 0;
        S->first_line = next_line;
        if (src.map) {
            if (!too_long) pos = cut_parts(ctx, path, S, pos, end, end, src.map, 0, max_parts, &tmpl, &H, &too_long, &st);
        } else if (!too_long && !src.too_long) {
            unsigned long long off = 0;
            if (!first) { /* the next round of text into this set's buffer */
                off = src.off;
                len = 0;
                if (!(src.eof && !src.carry_len) && (st = source_fill(ctx, path, &src, S, round_bytes, 0, &len))) break;
                pos = end = S->buf;
                if (len) end = S->buf + len;
            }
            if (len) pos = cut_parts(ctx, path, S, pos, end, end + PAD, S->buf, off, max_parts, &tmpl, &H, &too_long, &st);
            /* the lines this round did not take (a set's text is bounded) go back to the input */
            if (!st && !too_long && pos < end && source_unread(&src, pos, (size_t)(end - pos)))
                st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
            src.off = off + (unsigned long long)(pos - S->buf);
            if (first) src.off = (unsigned long long)(pos - S->buf);
        }
        first = 0;
        if (st) break;
        int more = too_long || src.too_long ? 0 : src.map ? pos < end : !(src.eof && !src.carry_len);
        if (S->count == 0 && !have_prev && !more) break;
        lx__team team = {.started = 0};
        atomic_store(&S->next, 0);
        if (S->count) lx__team_start(&team, T, 0, parse_set, S);
        /* meanwhile: the last round, in file order, on this thread */
        if (have_prev) {
            st = emit_set(cb, P, &row0, src.total);
            /* its text is no longer needed: resident memory stays a few rounds, not the file */
            if (src.map) source_release(&src, (size_t)((S->count ? S->q[0].p.s : pos) - src.map));
            have_prev = 0;
        }
        lx__team_join(&team);
        parse_set(S, 0); /* parts no thread took (none started, say) */
        if (st) break;
        long line = S->first_line;
        for (int i = 0; i < S->count && !st; i++) {
            spart *q = &S->q[i];
            if (q->p.err_line) st = lx__error(ctx, LX_EPARSE, path, line + q->p.err_line, "%s", q->p.err);
            line += q->p.lines_done;
        }
        next_line = line;
        have_prev = S->count > 0;
        cur ^= 1;
    }
    /* a line beyond LX__BATCH_LINE_MAX: refused once every row before it was emitted */
    if (!st && (too_long || src.too_long)) st = lx__csv_line_too_long(ctx, path, next_line);
    for (int k = 0; k < 2; k++) {
        for (int i = 0; i < MAX_PARTS; i++) {
            spart *q = &sets[k].q[i];
            if (q->state && cb->release) cb->release(cb->user, q->state);
            lx__free(q->p.values);
            lx__free(q->p.names);
            lx__free(q->p.name_at);
        }
        lx__free(sets[k].buf);
    }
    lx__free(sets);
    source_close(&src);
    return st;
}

/* lx_batch_table_stream: its one callback as the emit of lx_batch_table_stream_ex */
typedef struct plain {
    lx_batch_chunk_fn fn;
    void *user;
} plain;

static lx_status plain_emit(void *user, const lx_batch_table *part, size_t row0, void *state)
{
    (void)state;
    plain *p = user;
    return p->fn(p->user, part, row0);
}

lx_status lx_batch_table_stream(lx_ctx *ctx, const char *path, lx_dtype dtype, int threads, lx_batch_chunk_fn fn,
                                void *user)
{
    LX__NEED_CTX(ctx);
    if (!path || !fn) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch csv: NULL argument");
    plain p = {fn, user};
    lx_batch_stream cb = {.user = &p, .emit = plain_emit};
    return lx_batch_table_stream_ex(ctx, path, dtype, threads, &cb);
}

/* lx_batch_table_integrate_file: every chunk integrated into a growing result on the caller's thread */
typedef struct integ {
    lx_ctx *ctx;
    const lx_function *fns;
    size_t k, cap, rows;
    double *out;
} integ;

static lx_status integ_chunk(void *user, const lx_batch_table *chunk, size_t row0)
{
    integ *I = user;
    size_t need = (row0 + chunk->batch.n_spectra) * I->k;
    if (need > I->cap) {
        size_t cap = need > 2 * I->cap ? need : 2 * I->cap;
        double *o = lx__realloc_n(I->out, cap, sizeof *o);
        if (!o) return lx__error(I->ctx, LX_ENOMEM, NULL, 0, "out of memory for the results");
        I->out = o;
        I->cap = cap;
    }
    /* one thread: the other cores are parsing the next chunk */
    lx_batch_opts o = {.backend = LX_BACKEND_CPU, .threads = 1};
    I->rows = row0 + chunk->batch.n_spectra;
    return lx_batch_integrate(I->ctx, &chunk->batch, I->fns, I->k, &o, I->out + row0 * I->k);
}

void lx_batch_results_free(double *results) { lx__free(results); }

lx_status lx_batch_table_integrate_file(lx_ctx *ctx, const char *path, const lx_function *fns, size_t k, int threads,
                                        double **out, size_t *n_spectra)
{
    LX__NEED_CTX(ctx);
    if (!path || !fns || !k || !out || !n_spectra) return lx__error(ctx, LX_EINVAL, NULL, 0, "batch csv: NULL argument");
    *out = NULL;
    integ I = {ctx, fns, k, 0, 0, NULL};
    /* double values: the same numbers strtod gives, summed in double */
    lx_status st = lx_batch_table_stream(ctx, path, LX_F64, threads, integ_chunk, &I);
    if (!st && !I.out && !(I.out = lx__alloc(sizeof(double)))) st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory");
    if (st) {
        lx__free(I.out);
        return st;
    }
    *out = I.out;
    *n_spectra = I.rows;
    return LX_OK;
}
