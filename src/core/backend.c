/* backend.c - the one rule by which every OpenCL user (batch integration, resampling, grids,
 * brute-force irradiance, and any later one) chooses the CPU or OpenCL, falls back, and logs it:
 * the CPU path in double is the reference, and OpenCL is used only where it is asked for or where
 * a job is large enough to pay for it on a device that is not the CPU itself. */
#include "core/core_private.h"

#include <stdlib.h>
#include <string.h>

/* The backend named by text into *out; 0 when text names none (then *out is untouched). */
static int backend_by_name(const char *text, lx_backend *out)
{
    if (!strcmp(text, "auto")) *out = LX_BACKEND_AUTO;
    else if (!strcmp(text, "cpu")) *out = LX_BACKEND_CPU;
    else if (!strcmp(text, "opencl")) *out = LX_BACKEND_OPENCL;
    else return 0;
    return 1;
}

lx_status lx_backend_parse(lx_ctx *ctx, const char *text, lx_backend *out)
{
    LX__NEED_CTX(ctx);
    if (!text || !out) return lx__error(ctx, LX_EINVAL, NULL, 0, "backend: NULL argument");
    if (!backend_by_name(text, out))
        return lx__error(ctx, LX_EINVAL, NULL, 0, "unknown backend '%s' (expected auto, cpu or opencl)", text);
    return LX_OK;
}

lx_backend lx_backend_from_env(void)
{
    const char *s = getenv("LX_BACKEND");
    lx_backend b = LX_BACKEND_AUTO;
    if (s && *s) backend_by_name(s, &b);
    return b;
}

lx_status lx__backend_choose(lx_ctx *ctx, const char *job, lx_backend asked, double work, double break_even,
                             double break_even_warm, lx_backend *out)
{
    if (asked == LX_BACKEND_AUTO) asked = lx_backend_from_env();
    *out = LX_BACKEND_CPU;
    if (asked == LX_BACKEND_CPU) return LX_OK;
#if LX_OPENCL
    if (asked == LX_BACKEND_OPENCL) {
        *out = LX_BACKEND_OPENCL;
        return LX_OK;
    }
    const char *be = getenv("LX_AUTO_BREAK_EVEN"); /* in the job's units; for measuring and tests */
    int forced = be && *be;
    double limit = forced ? atof(be) : lx_cl_ready(ctx) ? break_even_warm : break_even;
    if (!(work >= limit)) {
        lx__log(ctx, LX_LOG_INFO, "%s: backend auto: %.3g below the OpenCL break-even %.3g; using the CPU", job, work,
                limit);
        return LX_OK;
    }
    lx__cl *cl = NULL;
    if (lx__cl_get(ctx, &cl) != LX_OK) {
        lx__log(ctx, LX_LOG_INFO, "%s: backend auto: OpenCL unavailable (%s); falling back to the CPU path", job, lx_ctx_errmsg(ctx));
        return LX_OK;
    }
    if (cl->info.is_cpu && !forced) {
        lx__log(ctx, LX_LOG_INFO, "%s: backend auto: the OpenCL device is a CPU (the same cores); using the CPU", job);
        return LX_OK;
    }
    lx__log(ctx, LX_LOG_INFO, "%s: backend auto: %.3g at or above the OpenCL break-even %.3g; using OpenCL", job, work,
            limit);
    *out = LX_BACKEND_OPENCL;
    return LX_OK;
#else
    (void)work, (void)break_even, (void)break_even_warm;
    if (asked == LX_BACKEND_OPENCL)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "%s: this build has no OpenCL (built with LX_OPENCL=0)", job);
    lx__log(ctx, LX_LOG_INFO, "%s: backend auto: this build has no OpenCL; using the CPU", job);
    return LX_OK;
#endif
}

void lx__backend_used(lx_ctx *ctx, lx_backend used) { ctx->backend_used = used; }

lx_backend lx_ctx_backend_used(const lx_ctx *ctx) { return ctx ? ctx->backend_used : LX_BACKEND_AUTO; }

int lx__backend_fallback(lx_ctx *ctx, const char *job, lx_backend asked, lx_status st)
{
    if (asked == LX_BACKEND_AUTO) asked = lx_backend_from_env();
    if (asked == LX_BACKEND_OPENCL || st == LX_ENOMEM || st == LX_EINVAL) return 0;
    lx__log(ctx, LX_LOG_INFO, "%s: OpenCL failed (%s); falling back to the CPU path for the whole result", job, lx_ctx_errmsg(ctx));
    return 1;
}
