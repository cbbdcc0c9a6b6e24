/* opencl.c - the OpenCL runtime: platform and device discovery and choice, an owned or borrowed
 * context and queue, the program built lazily once per context and device (embedded kernels or
 * LX_KERNEL_DIR) with its build log kept, and OpenCL error names for messages. */
#include "core/core_private.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if LX_OPENCL

#define MAX_PLATFORMS 16
#define MAX_DEVICES 64

const char *lx__cl_errname(cl_int err)
{
    switch (err) {
#define E(x) case x: return #x;
        E(CL_SUCCESS) E(CL_DEVICE_NOT_FOUND) E(CL_DEVICE_NOT_AVAILABLE) E(CL_COMPILER_NOT_AVAILABLE)
        E(CL_MEM_OBJECT_ALLOCATION_FAILURE) E(CL_OUT_OF_RESOURCES) E(CL_OUT_OF_HOST_MEMORY)
        E(CL_PROFILING_INFO_NOT_AVAILABLE) E(CL_MEM_COPY_OVERLAP) E(CL_IMAGE_FORMAT_MISMATCH)
        E(CL_IMAGE_FORMAT_NOT_SUPPORTED) E(CL_BUILD_PROGRAM_FAILURE) E(CL_MAP_FAILURE)
        E(CL_MISALIGNED_SUB_BUFFER_OFFSET) E(CL_COMPILE_PROGRAM_FAILURE) E(CL_LINKER_NOT_AVAILABLE)
        E(CL_LINK_PROGRAM_FAILURE) E(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST) E(CL_INVALID_VALUE) E(CL_INVALID_DEVICE_TYPE) E(CL_INVALID_PLATFORM)
        E(CL_INVALID_DEVICE) E(CL_INVALID_CONTEXT) E(CL_INVALID_QUEUE_PROPERTIES) E(CL_INVALID_COMMAND_QUEUE)
        E(CL_INVALID_HOST_PTR) E(CL_INVALID_MEM_OBJECT) E(CL_INVALID_BINARY) E(CL_INVALID_BUILD_OPTIONS)
        E(CL_INVALID_PROGRAM) E(CL_INVALID_PROGRAM_EXECUTABLE) E(CL_INVALID_KERNEL_NAME)
        E(CL_INVALID_KERNEL_DEFINITION) E(CL_INVALID_KERNEL) E(CL_INVALID_ARG_INDEX) E(CL_INVALID_ARG_VALUE)
        E(CL_INVALID_ARG_SIZE) E(CL_INVALID_KERNEL_ARGS) E(CL_INVALID_WORK_DIMENSION)
        E(CL_INVALID_WORK_GROUP_SIZE) E(CL_INVALID_WORK_ITEM_SIZE) E(CL_INVALID_GLOBAL_OFFSET)
        E(CL_INVALID_EVENT_WAIT_LIST) E(CL_INVALID_EVENT) E(CL_INVALID_OPERATION) E(CL_INVALID_BUFFER_SIZE)
        E(CL_INVALID_GLOBAL_WORK_SIZE)
#undef E
    case -1001: return "CL_PLATFORM_NOT_FOUND_KHR";
    }
    return "CL_UNKNOWN_ERROR";
}

lx_status lx__cl_check(lx_ctx *ctx, cl_int err, const char *call)
{
    if (err == CL_SUCCESS) return LX_OK;
    return lx__error(ctx, LX_EDEVICE, NULL, 0, "%s failed: %s (%d)", call, lx__cl_errname(err), (int)err);
}

static void cl_release(lx_ctx *ctx)
{
    lx__cl *cl = ctx->cl;
    if (!cl) return;
    /* no device work may outlive the context (a failed call can leave commands queued; a process
     * that exits while PoCL still compiles or runs them crashes in LLVM's destructors). The real
     * clFinish, not the fault-injection wrapper. */
    if (cl->queue) (clFinish)(cl->queue);
    if (cl->program) clReleaseProgram(cl->program);
    if (cl->queue) clReleaseCommandQueue(cl->queue);
    if (cl->context) clReleaseContext(cl->context);
    lx__free(cl->build_log);
    lx__free(cl);
    ctx->cl = NULL;
    ctx->cl_release = NULL;
}

/* The state of ctx, allocated (not initialised) when absent. */
static lx_status cl_state(lx_ctx *ctx, lx__cl **out)
{
    if (!ctx->cl) {
        lx__cl *cl = lx__calloc(1, sizeof *cl);
        if (!cl) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
        cl->sel_platform = cl->sel_device = -1;
        cl->sel_type = LX_CL_AUTO;
        ctx->cl = cl;
        ctx->cl_release = cl_release;
    }
    *out = ctx->cl;
    return LX_OK;
}

static void describe(cl_platform_id p, cl_device_id d, int pi, int di, lx_cl_device_info *info)
{
    memset(info, 0, sizeof *info);
    info->platform = pi;
    info->device = di;
    clGetPlatformInfo(p, CL_PLATFORM_NAME, sizeof info->platform_name - 1, info->platform_name, NULL);
    clGetDeviceInfo(d, CL_DEVICE_NAME, sizeof info->device_name - 1, info->device_name, NULL);
    clGetDeviceInfo(d, CL_DEVICE_VERSION, sizeof info->version - 1, info->version, NULL);
    cl_device_type type = 0;
    clGetDeviceInfo(d, CL_DEVICE_TYPE, sizeof type, &type, NULL);
    info->is_gpu = (type & CL_DEVICE_TYPE_GPU) != 0;
    info->is_cpu = (type & CL_DEVICE_TYPE_CPU) != 0;
    cl_uint cu = 0;
    clGetDeviceInfo(d, CL_DEVICE_MAX_COMPUTE_UNITS, sizeof cu, &cu, NULL);
    info->compute_units = cu;
    cl_ulong g = 0, a = 0;
    clGetDeviceInfo(d, CL_DEVICE_GLOBAL_MEM_SIZE, sizeof g, &g, NULL);
    clGetDeviceInfo(d, CL_DEVICE_MAX_MEM_ALLOC_SIZE, sizeof a, &a, NULL);
    info->global_mem_bytes = g;
    info->max_alloc_bytes = a;
    cl_device_fp_config fp = 0;
    clGetDeviceInfo(d, CL_DEVICE_DOUBLE_FP_CONFIG, sizeof fp, &fp, NULL);
    /* LX_CL_FP64=0 treats the device as one without fp64: the program is built with LX_FP64=0 and
     * every kernel takes its float path (for devices whose fp64 is slow, and so that CI compiles and
     * runs the variants of devices that have none) */
    const char *f = getenv("LX_CL_FP64");
    info->fp64 = fp != 0 && !(f && !strcmp(f, "0"));
}

/* Every device of every platform: ids and descriptions. Returns the count (0 when none). */
static int enumerate(cl_platform_id *pids, cl_device_id *dids, lx_cl_device_info *infos, int max)
{
    cl_platform_id plats[MAX_PLATFORMS];
    cl_uint np = 0;
    if (clGetPlatformIDs(MAX_PLATFORMS, plats, &np) != CL_SUCCESS) return 0;
    int n = 0;
    for (cl_uint p = 0; p < np && p < MAX_PLATFORMS; p++) {
        cl_device_id devs[MAX_DEVICES];
        cl_uint nd = 0;
        if (clGetDeviceIDs(plats[p], CL_DEVICE_TYPE_ALL, MAX_DEVICES, devs, &nd) != CL_SUCCESS) continue;
        for (cl_uint d = 0; d < nd && d < MAX_DEVICES && n < max; d++) {
            pids[n] = plats[p];
            dids[n] = devs[d];
            describe(plats[p], devs[d], (int)p, (int)d, &infos[n]);
            n++;
        }
    }
    return n;
}

/* Reads an integer index or a type name from an environment variable: sets *index or *type. */
static void env_choice(const char *var, int *index, lx_cl_type *type)
{
    const char *s = getenv(var);
    if (!s || !*s) return;
    if (!strcmp(s, "gpu")) *type = LX_CL_GPU;
    else if (!strcmp(s, "cpu")) *type = LX_CL_CPU;
    else if (!strcmp(s, "auto")) *type = LX_CL_AUTO;
    else {
        char *end;
        long v = strtol(s, &end, 10);
        if (!*end && v >= 0 && v < 1000) *index = (int)v;
    }
}

/* The device the selection picks among n devices, or -1. */
static int choose(const lx_cl_device_info *infos, int n, int plat, int dev, lx_cl_type type)
{
    int best = -1, best_rank = -1;
    for (int i = 0; i < n; i++) {
        if (plat >= 0 && infos[i].platform != plat) continue;
        if (dev >= 0 && infos[i].device != dev) continue;
        if (type == LX_CL_GPU && !infos[i].is_gpu) continue;
        if (type == LX_CL_CPU && !infos[i].is_cpu) continue;
        int rank = infos[i].is_gpu ? 2 : 1; /* AUTO: a GPU first, else the first device */
        if (rank > best_rank) {
            best = i;
            best_rank = rank;
        }
    }
    return best;
}

static void effective_choice(const lx__cl *cl, int *plat, int *dev, lx_cl_type *type)
{
    *plat = cl ? cl->sel_platform : -1;
    *dev = cl ? cl->sel_device : -1;
    *type = cl ? cl->sel_type : LX_CL_AUTO;
    int ep = -1, ed = -1;
    lx_cl_type et = *type;
    env_choice("LX_PLATFORM", &ep, &et);
    env_choice("LX_DEVICE", &ed, &et);
    if (*plat < 0) *plat = ep;
    if (*dev < 0) *dev = ed;
    if (*type == LX_CL_AUTO) *type = et;
}

lx_status lx_cl_devices(lx_ctx *ctx, lx_cl_device_info **out, size_t *n)
{
    LX__NEED_CTX(ctx);
    if (!out || !n) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_cl_devices: NULL output");
    cl_platform_id pids[MAX_DEVICES];
    cl_device_id dids[MAX_DEVICES];
    lx_cl_device_info infos[MAX_DEVICES];
    int cnt = enumerate(pids, dids, infos, MAX_DEVICES);
    int plat, dev;
    lx_cl_type type;
    effective_choice(ctx->cl, &plat, &dev, &type);
    int def = choose(infos, cnt, plat, dev, type);
    if (def >= 0) infos[def].is_default = 1;
    *out = NULL;
    *n = 0;
    if (cnt == 0) return LX_OK;
    lx_cl_device_info *r = lx__alloc_n((size_t)cnt, sizeof *r);
    if (!r) return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    memcpy(r, infos, (size_t)cnt * sizeof *r);
    *out = r;
    *n = (size_t)cnt;
    return LX_OK;
}

lx_status lx_cl_select(lx_ctx *ctx, int platform, int device, lx_cl_type type)
{
    LX__NEED_CTX(ctx);
    if (type != LX_CL_AUTO && type != LX_CL_CPU && type != LX_CL_GPU)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_cl_select: unknown device type %d", (int)type);
    if (ctx->cl) cl_release(ctx);
    lx__cl *cl = NULL;
    lx_status st = cl_state(ctx, &cl);
    if (st) return st;
    cl->sel_platform = platform < 0 ? -1 : platform;
    cl->sel_device = device < 0 ? -1 : device;
    cl->sel_type = type;
    return LX_OK;
}

lx_status lx_cl_borrow(lx_ctx *ctx, void *context, void *queue)
{
    LX__NEED_CTX(ctx);
    if (!context || !queue)
        return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_cl_borrow: context and queue are required");
    cl_context c = context;
    cl_command_queue q = queue;
    cl_device_id d;
    cl_int err = clGetCommandQueueInfo(q, CL_QUEUE_DEVICE, sizeof d, &d, NULL);
    if (err) return lx__cl_check(ctx, err, "clGetCommandQueueInfo(CL_QUEUE_DEVICE)");
    cl_platform_id p;
    err = clGetDeviceInfo(d, CL_DEVICE_PLATFORM, sizeof p, &p, NULL);
    if (err) return lx__cl_check(ctx, err, "clGetDeviceInfo(CL_DEVICE_PLATFORM)");
    if (ctx->cl) cl_release(ctx);
    lx__cl *cl = NULL;
    lx_status st = cl_state(ctx, &cl);
    if (st) return st;
    clRetainContext(c);
    clRetainCommandQueue(q);
    cl->context = c;
    cl->queue = q;
    cl->device = d;
    cl->platform = p;
    cl->borrowed = cl->ready = 1;
    describe(p, d, -1, -1, &cl->info);
    cl->info.is_default = 1;
    return LX_OK;
}

int lx_cl_ready(const lx_ctx *ctx) { return ctx && ctx->cl && ((const lx__cl *)ctx->cl)->ready; }

lx_status lx__cl_get(lx_ctx *ctx, lx__cl **out)
{
    lx__cl *cl = NULL;
    lx_status st = cl_state(ctx, &cl);
    if (st) return st;
    if (cl->ready) {
        *out = cl;
        return LX_OK;
    }
    cl_platform_id pids[MAX_DEVICES];
    cl_device_id dids[MAX_DEVICES];
    lx_cl_device_info infos[MAX_DEVICES];
#if defined(LX_FAULTS)
    lx__cl_fault_epoch(); /* test builds: LX_CL_FAULT=CALL:N counts from here */
#endif
    int cnt = enumerate(pids, dids, infos, MAX_DEVICES);
    if (cnt == 0) return lx__error(ctx, LX_EDEVICE, NULL, 0, "no OpenCL platform or device found");
    int plat, dev;
    lx_cl_type type;
    effective_choice(cl, &plat, &dev, &type);
    int i = choose(infos, cnt, plat, dev, type);
    if (i < 0)
        return lx__error(ctx, LX_EDEVICE, NULL, 0, "no OpenCL device matches platform %d, device %d, type %s (%d found)",
                         plat, dev, type == LX_CL_GPU ? "gpu" : type == LX_CL_CPU ? "cpu" : "auto", cnt);
    cl_int err;
    cl_context_properties props[] = {CL_CONTEXT_PLATFORM, (cl_context_properties)pids[i], 0};
    cl_context c = clCreateContext(props, 1, &dids[i], NULL, NULL, &err);
    if (err) return lx__cl_check(ctx, err, "clCreateContext");
    cl_command_queue q = clCreateCommandQueue(c, dids[i], 0, &err);
    if (err) {
        clReleaseContext(c);
        return lx__cl_check(ctx, err, "clCreateCommandQueue");
    }
    cl->platform = pids[i];
    cl->device = dids[i];
    cl->context = c;
    cl->queue = q;
    cl->info = infos[i];
    cl->info.is_default = 1;
    cl->ready = 1;
    lx__log(ctx, LX_LOG_INFO, "OpenCL device: %s (%s)", cl->info.device_name, cl->info.platform_name);
    *out = cl;
    return LX_OK;
}

lx_status lx_cl_info(lx_ctx *ctx, lx_cl_device_info *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_cl_info: NULL argument");
    lx__cl *cl = NULL;
    lx_status st = lx__cl_get(ctx, &cl);
    if (st) return st;
    *out = cl->info;
    return LX_OK;
}

static lx_status build_program(lx_ctx *ctx, lx__cl *cl)
{
    int n = lx__nkernel_sources;
    if (n == 0) return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "no OpenCL kernels were embedded in this build");
    const char **srcs = lx__calloc((size_t)n, sizeof *srcs);
    char **owned = lx__calloc((size_t)n, sizeof *owned);
    size_t *lens = lx__calloc((size_t)n, sizeof *lens);
    if (!srcs || !owned || !lens) {
        lx__free(srcs);
        lx__free(owned);
        lx__free(lens);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    const char *dir = getenv("LX_KERNEL_DIR");
    lx_status st = LX_OK;
    for (int i = 0; i < n && !st; i++) {
        if (dir && *dir) { /* kernel work: the files of LX_KERNEL_DIR instead of the embedded text */
            char path[1024];
            snprintf(path, sizeof path, "%s/%s", dir, lx__kernel_sources[i].name);
            st = lx__read_all(ctx, path, LX_INPUT_KERNEL, &owned[i], &lens[i]);
            if (st) { /* the reader's message names the file; say where the path came from */
                char why[LX__ERRMSG_MAX / 2];
                snprintf(why, sizeof why, "%s", lx_ctx_errmsg(ctx));
                lx__error(ctx, st, NULL, 0, "cannot read kernel (LX_KERNEL_DIR): %s", why);
            }
            srcs[i] = owned[i];
        } else {
            srcs[i] = lx__kernel_sources[i].source;
            lens[i] = strlen(srcs[i]);
        }
    }
    cl_int err = CL_SUCCESS;
    cl_program prog = NULL;
    if (!st) {
        prog = clCreateProgramWithSource(cl->context, (cl_uint)n, srcs, lens, &err);
        st = lx__cl_check(ctx, err, "clCreateProgramWithSource");
    }
    if (!st) {
        const char *opts = cl->info.fp64 ? "-cl-std=CL1.2 -DLX_FP64=1" : "-cl-std=CL1.2 -DLX_FP64=0";
        err = clBuildProgram(prog, 1, &cl->device, opts, NULL, NULL);
        size_t len = 0;
        clGetProgramBuildInfo(prog, cl->device, CL_PROGRAM_BUILD_LOG, 0, NULL, &len);
        lx__free(cl->build_log);
        cl->build_log = lx__alloc(len + 1);
        if (cl->build_log) {
            cl->build_log[0] = 0;
            clGetProgramBuildInfo(prog, cl->device, CL_PROGRAM_BUILD_LOG, len, cl->build_log, NULL);
            cl->build_log[len] = 0;
        }
        if (err) {
            int has_log = cl->build_log && cl->build_log[0];
            st = lx__error(ctx, LX_EDEVICE, dir && *dir ? dir : NULL, 0, "clBuildProgram failed: %s (%d)%s%.700s",
                           lx__cl_errname(err), (int)err, has_log ? ": " : " (empty build log)",
                           has_log ? cl->build_log : "");
            clReleaseProgram(prog);
            prog = NULL;
        }
    }
    for (int i = 0; i < n; i++) lx__free(owned[i]);
    lx__free(owned);
    lx__free(srcs);
    lx__free(lens);
    if (!st) cl->program = prog;
    return st;
}

lx_status lx__cl_kernel(lx_ctx *ctx, lx__cl *cl, const char *name, cl_kernel *out)
{
    if (!cl->program) {
        lx_status st = build_program(ctx, cl);
        if (st) return st;
    }
    cl_int err;
    cl_kernel k = clCreateKernel(cl->program, name, &err);
    if (err) return lx__error(ctx, LX_EDEVICE, NULL, 0, "clCreateKernel(%s) failed: %s (%d)", name,
                              lx__cl_errname(err), (int)err);
    *out = k;
    return LX_OK;
}

#else /* !LX_OPENCL */

static lx_status no_cl(lx_ctx *ctx)
{
    LX__NEED_CTX(ctx);
    return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "this build has no OpenCL (built with LX_OPENCL=0)");
}

lx_status lx_cl_select(lx_ctx *ctx, int platform, int device, lx_cl_type type)
{
    (void)platform, (void)device, (void)type;
    return no_cl(ctx);
}

lx_status lx_cl_borrow(lx_ctx *ctx, void *cl_context, void *cl_command_queue)
{
    (void)cl_context, (void)cl_command_queue;
    return no_cl(ctx);
}

lx_status lx_cl_devices(lx_ctx *ctx, lx_cl_device_info **out, size_t *n)
{
    LX__NEED_CTX(ctx);
    if (!out || !n) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_cl_devices: NULL output");
    *out = NULL;
    *n = 0;
    return LX_OK;
}

lx_status lx_cl_info(lx_ctx *ctx, lx_cl_device_info *out)
{
    LX__NEED_CTX(ctx);
    if (!out) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_cl_info: NULL argument");
    return no_cl(ctx);
}

int lx_cl_ready(const lx_ctx *ctx)
{
    (void)ctx;
    return 0;
}

#endif /* LX_OPENCL */

void lx_cl_devices_free(lx_cl_device_info *devices) { lx__free(devices); }
