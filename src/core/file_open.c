/* file_open.c - opening input files for the readers ("-" is standard input, directories are refused,
 * a FIFO without a writer does not hang the program) and the one whole-file reader every text
 * reader uses: a size limit per kind of file, binary input refused as it arrives. */
#include "core/core_private.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Seconds a FIFO may take to deliver its first byte (or end of file): LX_FIFO_WAIT_S, default
 * LX__FIFO_WAIT_S; 0 waits for ever, as cat does. */
static int fifo_wait_ms(void)
{
    const char *e = getenv("LX_FIFO_WAIT_S");
    if (!e || !*e) return LX__FIFO_WAIT_S * 1000;
    char *end;
    double s = strtod(e, &end);
    if (*end || !(s >= 0) || s > 86400) return LX__FIFO_WAIT_S * 1000;
    return s == 0 ? -1 : (int)(s * 1000 + 0.5);
}

lx_status lx__open_read(lx_ctx *ctx, const char *path, FILE **out)
{
    *out = NULL;
    if (!strcmp(path, "-")) {
        *out = stdin;
        return LX_OK;
    }
    struct stat sb;
    if (stat(path, &sb) != 0) return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(errno));
    if (S_ISDIR(sb.st_mode)) {
        errno = EISDIR;
        return lx__error(ctx, LX_EIO, path, 0, "cannot read: is a directory");
    }
    if (!S_ISFIFO(sb.st_mode)) {
        FILE *fp = fopen(path, "rb");
        if (!fp) return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(errno));
        *out = fp;
        return LX_OK;
    }
    /* a FIFO: open without blocking on a missing writer, wait for the first data or end of file */
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0) return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(errno));
    int ms = fifo_wait_ms();
    struct pollfd p = {.fd = fd, .events = POLLIN};
    int r;
    do r = poll(&p, 1, ms);
    while (r < 0 && errno == EINTR);
    if (r <= 0) {
        int err = errno;
        close(fd);
        errno = r == 0 ? ETIMEDOUT : err;
        if (r == 0)
            return lx__error(ctx, LX_EIO, path, 0, "a FIFO with no data after %d s (no writer?); LX_FIFO_WAIT_S sets the wait",
                             ms / 1000);
        return lx__error(ctx, LX_EIO, path, 0, "cannot read: %s", strerror(err));
    }
    int fl = fcntl(fd, F_GETFL);
    FILE *fp = fl < 0 || fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) < 0 ? NULL : fdopen(fd, "rb");
    if (!fp) {
        int err = errno;
        close(fd);
        return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(err));
    }
    *out = fp;
    return LX_OK;
}

/* ---- size limits per kind of input ---- */

#define MB ((size_t)1 << 20)

static const struct {
    size_t default_mb;
    const char *what; /* "larger than N MB, the limit for WHAT" */
} kinds[LX_INPUT_KIND_COUNT] = {
    [LX_INPUT_SPECTRUM] = {LX__MAX_SPECTRUM_MB, "a spectrum file"},
    [LX_INPUT_LUMINAIRE] = {LX__MAX_LUMINAIRE_MB, "a photometric file"},
    [LX_INPUT_SCENE] = {LX__MAX_SCENE_MB, "a scene file"},
    [LX_INPUT_KERNEL] = {LX__MAX_KERNEL_MB, "an OpenCL kernel source"},
};

/* LX_MAX_INPUT_MB in bytes, or 0 when unset or not a whole number from 1 to LX__MAX_INPUT_MB_ENV. */
static size_t env_limit(void)
{
    const char *e = getenv("LX_MAX_INPUT_MB");
    if (!e || !*e) return 0;
    size_t mb = 0;
    for (const char *p = e; *p; p++) {
        if (*p < '0' || *p > '9' || mb > LX__MAX_INPUT_MB_ENV) return 0;
        mb = mb * 10 + (size_t)(*p - '0');
    }
    return mb >= 1 && mb <= LX__MAX_INPUT_MB_ENV && mb <= SIZE_MAX / MB ? mb * MB : 0;
}

lx_status lx_ctx_set_input_limit(lx_ctx *ctx, lx_input_kind kind, size_t max_bytes)
{
    LX__NEED_CTX(ctx);
    if ((unsigned)kind >= LX_INPUT_KIND_COUNT)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_ctx_set_input_limit: unknown input kind %d", (int)kind);
    ctx->input_limit[kind] = max_bytes;
    return LX_OK;
}

size_t lx_ctx_input_limit(const lx_ctx *ctx, lx_input_kind kind)
{
    if ((unsigned)kind >= LX_INPUT_KIND_COUNT) return 0;
    if (ctx && ctx->input_limit[kind]) return ctx->input_limit[kind];
    size_t e = env_limit();
    return e ? e : kinds[kind].default_mb * MB;
}

static lx_status too_large(lx_ctx *ctx, const char *path, lx_input_kind kind, size_t limit)
{
    if (limit > SIZE_MAX / 4) limit = SIZE_MAX / 4;
    if (limit % MB == 0)
        return lx__error(ctx, LX_EIO, path, 0, "larger than %zu MB, the limit for %s (raise with LX_MAX_INPUT_MB)",
                         limit / MB, kinds[kind].what);
    return lx__error(ctx, LX_EIO, path, 0, "larger than %zu bytes, the limit for %s (raise with LX_MAX_INPUT_MB)", limit,
                     kinds[kind].what);
}

/* ---- binary input ---- */

/* The line of byte offset off (lines counted from 1). */
static long line_at(const char *buf, size_t off)
{
    long line = 1;
    for (const char *p = buf, *e = buf + off; (p = memchr(p, '\n', (size_t)(e - p))) != NULL; p++) line++;
    return line;
}

/* A control byte that text files do not hold (file(1)'s rule, less BEL, BS and SUB: old DOS files
 * end with ^Z). */
static int binary_control(unsigned char c) { return c < 32 && c != 0 && !(c >= 7 && c <= 13) && c != 26 && c != 27; }

/* The first block: a UTF-16 byte-order mark, or control bytes (NUL bytes are checked everywhere). */
static lx_status probe_first_block(lx_ctx *ctx, const char *path, const unsigned char *b, size_t n)
{
    if (n >= 2 && ((b[0] == 0xFF && b[1] == 0xFE) || (b[0] == 0xFE && b[1] == 0xFF)))
        return lx__error(ctx, LX_EPARSE, path, 1, "UTF-16 text is not supported; save the file as UTF-8");
    size_t count = 0, first = 0;
    for (size_t i = 0; i < n; i++)
        if (binary_control(b[i]) && count++ == 0) first = i;
    if (count >= LX__TEXT_CONTROL_MIN && count * 1000 > (size_t)LX__TEXT_CONTROL_PER_MILLE * n)
        return lx__error(ctx, LX_EPARSE, path, line_at((const char *)b, first),
                         "binary data (%zu control bytes in the first %zu, the first 0x%02x at offset %zu); not a text file",
                         count, n, b[first], first);
    return LX_OK;
}

/* A NUL byte at off: UTF-16 text without a byte-order mark (ASCII in UTF-16 has every other byte
 * NUL) or binary data. */
static lx_status nul_byte(lx_ctx *ctx, const char *path, const char *buf, size_t n, size_t off)
{
    const unsigned char *u = (const unsigned char *)buf;
    if (n >= 2 && ((u[0] == 0xFF && u[1] == 0xFE) || (u[0] == 0xFE && u[1] == 0xFF)))
        return probe_first_block(ctx, path, u, 2); /* its byte-order mark says what it is */
    size_t m = n < 512 ? n : 512, zero[2] = {0, 0};
    for (size_t i = 0; i < m; i++) zero[i & 1] += buf[i] == 0;
    int odd = m >= 8 && zero[1] * 10 >= (m / 2) * 9 && zero[0] * 10 <= m / 2;
    int even = m >= 8 && zero[0] * 10 >= (m / 2) * 9 && zero[1] * 10 <= m / 2;
    if (off < m && (odd || even))
        return lx__error(ctx, LX_EPARSE, path, 1, "UTF-16 text (%s, no byte-order mark) is not supported; save the file as UTF-8",
                         odd ? "little-endian" : "big-endian");
    return lx__error(ctx, LX_EPARSE, path, line_at(buf, off), "binary data (NUL byte at offset %zu); not a text file", off);
}

lx_status lx__input_size_check(lx_ctx *ctx, const char *path, lx_input_kind kind, unsigned long long size)
{
    if ((unsigned)kind >= LX_INPUT_KIND_COUNT)
        return lx__error(ctx, LX_EINVAL, path, 0, "unknown input kind %d", (int)kind);
    size_t limit = lx_ctx_input_limit(ctx, kind);
    return size > limit ? too_large(ctx, path, kind, limit) : LX_OK;
}

lx_status lx__text_check(lx_ctx *ctx, const char *path, const char *buf, size_t n)
{
    if (n > LX__TEXT_PROBE_BYTES) n = LX__TEXT_PROBE_BYTES;
    const char *nul = n ? memchr(buf, 0, n) : NULL;
    if (nul) return nul_byte(ctx, path, buf, n, (size_t)(nul - buf));
    return probe_first_block(ctx, path, (const unsigned char *)buf, n);
}

/* ---- the whole-file reader ---- */

lx_status lx__read_stream(lx_ctx *ctx, const char *path, lx_input_kind kind, FILE *fp, const char *prefix,
                          size_t prefix_len, char **text, size_t *len)
{
    *text = NULL;
    *len = 0;
    if ((unsigned)kind >= LX_INPUT_KIND_COUNT)
        return lx__error(ctx, LX_EINVAL, path, 0, "lx__read_all: unknown input kind %d", (int)kind);
    size_t limit = lx_ctx_input_limit(ctx, kind);
    if (limit > SIZE_MAX / 4) limit = SIZE_MAX / 4;
    if (!prefix) prefix_len = 0;
    /* a regular file is sized once (and refused unread when too large); a stream grows by doubling */
    struct stat sb;
    size_t cap = 1 << 16;
    if (!prefix_len && fstat(fileno(fp), &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_size > 0) {
        if ((unsigned long long)sb.st_size > limit) return too_large(ctx, path, kind, limit);
        cap = (size_t)sb.st_size + 1; /* + 1: the end of file in the first read */
    }
    if (cap < prefix_len + 1) cap = prefix_len + 1;
    if (cap > limit + 1) cap = limit + 1;
    size_t n = prefix_len < cap ? prefix_len : cap, checked = 0;
    int probed = 0;
    lx_status st = LX_OK;
    char *buf = lx__alloc(cap);
    if (buf && n) memcpy(buf, prefix, n);
    while (buf) {
        if (n == cap) {
            if (n > limit) break;
            size_t nc = cap > limit / 2 ? limit + 1 : 2 * cap;
            char *nb = lx__realloc(buf, nc);
            if (!nb) {
                lx__free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap = nc;
        }
        size_t want = cap - n; /* the first block alone, to refuse binary data before reading on */
        if (!probed && n < LX__TEXT_PROBE_BYTES && want > LX__TEXT_PROBE_BYTES - n) want = LX__TEXT_PROBE_BYTES - n;
        size_t got = n < prefix_len ? 0 : fread(buf + n, 1, want, fp); /* a prefix beyond the limit: refused below */
        n += got;
        /* the new bytes, before reading on: binary input stops here, whatever follows */
        const char *nul = n == checked ? NULL : memchr(buf + checked, 0, n - checked);
        if (nul) st = nul_byte(ctx, path, buf, n, (size_t)(nul - buf));
        checked = n;
        if (!st && !probed && (n >= LX__TEXT_PROBE_BYTES || got == 0)) {
            probed = 1;
            st = probe_first_block(ctx, path, (const unsigned char *)buf, n < LX__TEXT_PROBE_BYTES ? n : LX__TEXT_PROBE_BYTES);
        }
        if (st || got == 0) break;
    }
    if (!buf) st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory reading %zu bytes", n);
    else if (!st && (n > limit || prefix_len > limit)) st = too_large(ctx, path, kind, limit);
    else if (!st && ferror(fp)) st = lx__error(ctx, LX_EIO, path, 0, "read error: %s", strerror(errno));
    if (st != LX_OK) {
        lx__free(buf);
        return st;
    }
    *text = buf;
    *len = n;
    return LX_OK;
}

lx_status lx__read_all(lx_ctx *ctx, const char *path, lx_input_kind kind, char **text, size_t *len)
{
    *text = NULL;
    *len = 0;
    if ((unsigned)kind >= LX_INPUT_KIND_COUNT)
        return lx__error(ctx, LX_EINVAL, path, 0, "lx__read_all: unknown input kind %d", (int)kind);
    FILE *fp = NULL;
    lx_status st = lx__open_read(ctx, path, &fp);
    if (st) return st;
    st = lx__read_stream(ctx, path, kind, fp, NULL, 0, text, len);
    if (fp != stdin) fclose(fp);
    return st;
}

lx_status lx_file_open(lx_ctx *ctx, const char *path, FILE **out)
{
    LX__NEED_CTX(ctx);
    if (out) *out = NULL;
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "file open: NULL argument");
    return lx__open_read(ctx, path, out);
}
