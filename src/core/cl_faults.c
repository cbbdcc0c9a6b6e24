/* cl_faults.c - OpenCL fault injection for the test builds only (compiled with LX_FAULTS, never
 * into the shipped library): LX_CL_FAULT=CALL or CALL:N makes that OpenCL call fail as a real
 * device would (core_private.h). The counters are guarded by a lock, so contexts on several
 * threads may run under it. */
#define LX_FAULTS_IMPL 1 /* this file calls the real functions */
#include "core/core_private.h"

#if LX_OPENCL && defined(LX_FAULTS)
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static pthread_mutex_t fault_lock = PTHREAD_MUTEX_INITIALIZER;
static unsigned long fault_epoch; /* bumped each time a context starts OpenCL */

void lx__cl_fault_epoch(void)
{
    pthread_mutex_lock(&fault_lock);
    fault_epoch++;
    pthread_mutex_unlock(&fault_lock);
}

/* 1 when this call of `call` is to fail. CALL:N counts the calls since a context last started
 * OpenCL (lx__cl_get) or LX_CL_FAULT changed. */
static int fault_hit(const char *call)
{
    static char last[128];
    static unsigned long count, epoch;
    const char *f = getenv("LX_CL_FAULT");
    size_t n = strlen(call);
    int hit = 0;
    pthread_mutex_lock(&fault_lock);
    if (!f || !*f) {
        last[0] = 0;
    } else {
        if (strncmp(last, f, sizeof last - 1) != 0 || epoch != fault_epoch) {
            snprintf(last, sizeof last, "%s", f);
            count = 0;
            epoch = fault_epoch;
        }
        if (strncmp(f, call, n) == 0 && (f[n] == 0 || f[n] == ':')) {
            count++;
            hit = f[n] == 0 || strtoul(f + n + 1, NULL, 10) == count;
        }
    }
    pthread_mutex_unlock(&fault_lock);
    return hit;
}

cl_int lx__clGetPlatformIDs(cl_uint n, cl_platform_id *p, cl_uint *np)
{
    if (fault_hit("clGetPlatformIDs")) { /* what an ICD loader without platforms answers */
        if (np) *np = 0;
        return -1001; /* CL_PLATFORM_NOT_FOUND_KHR */
    }
    return (clGetPlatformIDs)(n, p, np);
}

cl_int lx__clBuildProgram(cl_program p, cl_uint nd, const cl_device_id *d, const char *o,
                          void (CL_CALLBACK *fn)(cl_program, void *), void *u)
{
    if (fault_hit("clBuildProgram")) return CL_BUILD_PROGRAM_FAILURE;
    return (clBuildProgram)(p, nd, d, o, fn, u);
}

cl_mem lx__clCreateBuffer(cl_context c, cl_mem_flags f, size_t size, void *host, cl_int *err)
{
    if (fault_hit("clCreateBuffer")) {
        if (err) *err = CL_MEM_OBJECT_ALLOCATION_FAILURE;
        return NULL;
    }
    return (clCreateBuffer)(c, f, size, host, err);
}

cl_int lx__clEnqueueNDRangeKernel(cl_command_queue q, cl_kernel k, cl_uint dim, const size_t *off, const size_t *gs,
                                  const size_t *ls, cl_uint nw, const cl_event *wl, cl_event *ev)
{
    if (fault_hit("clEnqueueNDRangeKernel")) return CL_OUT_OF_RESOURCES;
    return (clEnqueueNDRangeKernel)(q, k, dim, off, gs, ls, nw, wl, ev);
}

cl_int lx__clEnqueueReadBuffer(cl_command_queue q, cl_mem b, cl_bool blocking, size_t off, size_t size, void *ptr,
                               cl_uint nw, const cl_event *wl, cl_event *ev)
{
    if (fault_hit("clEnqueueReadBuffer")) return CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST;
    return (clEnqueueReadBuffer)(q, b, blocking, off, size, ptr, nw, wl, ev);
}

cl_int lx__clFinish(cl_command_queue q)
{
    if (fault_hit("clFinish")) return CL_OUT_OF_RESOURCES;
    return (clFinish)(q);
}

#else
typedef int lx__no_faults; /* ISO C forbids an empty translation unit */
#endif
