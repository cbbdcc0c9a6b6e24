/* ctx.c - the library context: creation, error recording, the log callback, status text. */
#include "core/core_private.h"

#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *lx_version(void) { return LX_VERSION_STRING; }

const char *lx_strerror(lx_status status)
{
    switch (status) {
    case LX_OK: return "success";
    case LX_EINVAL: return "invalid argument";
    case LX_EPARSE: return "malformed input";
    case LX_EIO: return "input/output error";
    case LX_ENOMEM: return "out of memory";
    case LX_ERANGE: return "undefined for this input";
    case LX_EUNSUPPORTED: return "not supported";
    case LX_EDEVICE: return "OpenCL device error";
    case LX_EWRITE: return "write error";
    }
    return "unknown status";
}

lx_status lx_ctx_create(lx_ctx **out)
{
    if (!out) return LX_EINVAL;
    *out = lx__calloc(1, sizeof **out);
    if (!*out) return LX_ENOMEM;
    (*out)->log_max = LX_LOG_WARN;
    (*out)->irr_method = LX_IRR_AUTO;
    (*out)->irr_fast_cost_ratio = NAN;
    return LX_OK;
}

void lx_ctx_destroy(lx_ctx *ctx)
{
    if (!ctx) return;
    if (ctx->cl_release) ctx->cl_release(ctx);
    for (int i = 0; i < LX__SLOT_COUNT; i++)
        if (ctx->slot[i].data && ctx->slot[i].free_fn) ctx->slot[i].free_fn(ctx->slot[i].data);
    lx__free(ctx);
}

void *lx__slot_get(const lx_ctx *ctx, lx__slot_id id) { return ctx ? ctx->slot[id].data : NULL; }

void *lx__slot_set(lx_ctx *ctx, lx__slot_id id, void *data, void (*free_fn)(void *data))
{
    lx__slot *s = &ctx->slot[id];
    if (s->data && s->data != data && s->free_fn) s->free_fn(s->data);
    s->data = data;
    s->free_fn = free_fn;
    return data;
}

const char *lx_ctx_errmsg(const lx_ctx *ctx) { return ctx ? ctx->errmsg : ""; }
const char *lx_ctx_errfile(const lx_ctx *ctx) { return ctx && ctx->errfile[0] ? ctx->errfile : NULL; }
long lx_ctx_errline(const lx_ctx *ctx) { return ctx ? ctx->errline : 0; }

void lx_ctx_set_log(lx_ctx *ctx, lx_log_fn fn, void *user, lx_log_level max_level)
{
    if (!ctx) return;
    ctx->log_fn = fn;
    ctx->log_user = user;
    ctx->log_max = max_level;
}

lx_status lx__error(lx_ctx *ctx, lx_status status, const char *file, long line, const char *fmt, ...)
{
    if (!ctx) return status;
    char what[LX__ERRMSG_MAX - 600];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    ctx->status = status;
    ctx->errline = line > 0 ? line : 0;
    snprintf(ctx->errfile, sizeof ctx->errfile, "%s", file ? file : "");
    if (file && line > 0)
        snprintf(ctx->errmsg, sizeof ctx->errmsg, "%s:%ld: %s", file, line, what);
    else if (file)
        snprintf(ctx->errmsg, sizeof ctx->errmsg, "%s: %s", file, what);
    else
        snprintf(ctx->errmsg, sizeof ctx->errmsg, "%s", what);
    return status;
}

void lx__fmt_magnitude(char *buf, size_t cap, double v)
{
    char t[48];
    snprintf(t, sizeof t, "%.3g", v);
    char *e = strchr(t, 'e');
    if (e) { /* 1e+308 -> 1e308, 3e-05 -> 3e-5 */
        char *q = e + 1, *d = e + 1;
        if (*q == '+') q++;
        else if (*q == '-') *d++ = *q++;
        while (*q == '0' && q[1]) q++;
        memmove(d, q, strlen(q) + 1);
    }
    snprintf(buf, cap, "%s", t);
}

lx_status lx__check_reserved(lx_ctx *ctx, const char *what, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++)
        if (b[i]) return lx__error(ctx, LX_EINVAL, NULL, 0, "%s: reserved must be zero (zero-initialise the struct)", what);
    return LX_OK;
}

void lx_text_free(char *text) { lx__free(text); }

void lx__log(lx_ctx *ctx, lx_log_level level, const char *fmt, ...)
{
    if (!ctx || !ctx->log_fn || level > ctx->log_max) return;
    char msg[LX__ERRMSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    ctx->log_fn(ctx->log_user, level, msg);
}
