/* file_open.c - opening input files for the readers: "-" is standard input, directories are refused,
 * and a FIFO without a writer does not hang the program (it waits a bounded time for data). */
#include "core/core_private.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Seconds a FIFO may take to deliver its first byte (or end of file): LX_FIFO_WAIT_S, default 10;
 * 0 waits for ever, as cat does. */
static int fifo_wait_ms(void)
{
    const char *e = getenv("LX_FIFO_WAIT_S");
    if (!e || !*e) return 10000;
    char *end;
    double s = strtod(e, &end);
    if (*end || !(s >= 0) || s > 86400) return 10000;
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

lx_status lx__read_all(lx_ctx *ctx, const char *path, char **text, size_t *len)
{
    *text = NULL;
    *len = 0;
    FILE *fp = NULL;
    lx_status st = lx__open_read(ctx, path, &fp);
    if (st) return st;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    for (;;) {
        if (!buf) {
            st = lx__error(ctx, LX_ENOMEM, path, 0, "out of memory reading %zu bytes", n);
            break;
        }
        if (n == cap) {
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                continue;
            }
            buf = nb;
            cap *= 2;
        }
        size_t got = fread(buf + n, 1, cap - n, fp);
        n += got;
        if (got == 0) break;
    }
    if (st == LX_OK && ferror(fp)) st = lx__error(ctx, LX_EIO, path, 0, "read error: %s", strerror(errno));
    if (fp != stdin) fclose(fp);
    if (st != LX_OK) {
        free(buf);
        return st;
    }
    *text = buf;
    *len = n;
    return LX_OK;
}

lx_status lx_file_open(lx_ctx *ctx, const char *path, FILE **out)
{
    if (!path || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "file open: NULL argument");
    return lx__open_read(ctx, path, out);
}
