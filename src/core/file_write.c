/* file_write.c - output files written atomically: a temporary file beside the path, fsynced and
 * renamed into place only when everything was written; a path that exists and is not a regular
 * file (a device such as /dev/null or /dev/full, a FIFO) is written directly, never replaced. */
#include "core/core_private.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

lx_status lx__wfile_open(lx_ctx *ctx, const char *path, lx__wfile *w)
{
    memset(w, 0, sizeof *w);
    w->fd = -1;
    if (!path || !*path) return lx__error(ctx, LX_EINVAL, NULL, 0, "no output path");
    w->path = path;
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode)) {
        if (S_ISDIR(sb.st_mode)) return lx__error(ctx, LX_EIO, path, 0, "cannot write: is a directory");
        w->fd = open(path, O_WRONLY | O_CLOEXEC);
        if (w->fd < 0) return lx__error(ctx, LX_EIO, path, 0, "cannot open: %s", strerror(errno));
        return LX_OK;
    }
    size_t n = strlen(path);
    w->tmp = lx__alloc(n + 16);
    if (!w->tmp) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    snprintf(w->tmp, n + 16, "%s.tmpXXXXXX", path);
    w->fd = mkstemp(w->tmp);
    if (w->fd < 0) {
        lx_status st = lx__error(ctx, LX_EIO, path, 0, "cannot create: %s", strerror(errno));
        lx__free(w->tmp);
        w->tmp = NULL;
        return st;
    }
    mode_t mask = umask(0); /* the usual permissions, not mkstemp's 0600 */
    umask(mask);
    fchmod(w->fd, 0666 & ~mask);
    return LX_OK;
}

lx_status lx__wfile_write(lx_ctx *ctx, lx__wfile *w, const void *buf, size_t n)
{
    const char *p = buf;
    if (w->err) return LX_EWRITE;
    while (n > 0) {
        ssize_t k = write(w->fd, p, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) {
            w->err = k < 0 ? errno : EIO;
            return lx__error(ctx, LX_EWRITE, w->path, 0, "%s", strerror(w->err));
        }
        p += k;
        n -= (size_t)k;
    }
    return LX_OK;
}

lx_status lx__wfile_close(lx_ctx *ctx, lx__wfile *w, lx_status st)
{
    if (w->fd < 0) return st;
    if (!st && w->err) st = lx__error(ctx, LX_EWRITE, w->path, 0, "%s", strerror(w->err));
    if (!st && w->tmp && fsync(w->fd) != 0) st = lx__error(ctx, LX_EWRITE, w->path, 0, "%s", strerror(errno));
    if (close(w->fd) != 0 && !st) st = lx__error(ctx, LX_EWRITE, w->path, 0, "%s", strerror(errno));
    w->fd = -1;
    if (w->tmp) {
        if (!st && rename(w->tmp, w->path) != 0)
            st = lx__error(ctx, LX_EIO, w->path, 0, "cannot rename into place: %s", strerror(errno));
        if (st) unlink(w->tmp);
        lx__free(w->tmp);
        w->tmp = NULL;
    }
    return st;
}

char *lx__date_today(void)
{
    time_t t = time(NULL);
    const char *e = getenv("SOURCE_DATE_EPOCH");
    if (e && *e) {
        char *end;
        long long v = strtoll(e, &end, 10);
        if (!*end && v >= 0) t = (time_t)v;
    }
    struct tm tm;
    char buf[32];
    if (!gmtime_r(&t, &tm) || !strftime(buf, sizeof buf, "%Y-%m-%d", &tm)) snprintf(buf, sizeof buf, "unknown");
    char *s = lx__alloc(strlen(buf) + 1);
    if (s) memcpy(s, buf, strlen(buf) + 1);
    return s;
}
