/* cairo_load.c - opens libcairo.so.2 on the first plot and resolves the functions the plotting
 * layer calls (plot_private.h: LX__CAIRO_FNS), once per process. */
#include "plot/plot_private.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

lx__cairo_api lx__cairo;

static pthread_once_t cairo_once = PTHREAD_ONCE_INIT;
static int cairo_ready;
static char cairo_why[320];

static void cairo_open(void)
{
    void *h = dlopen("libcairo.so.2", RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *e = dlerror();
        snprintf(cairo_why, sizeof cairo_why, "%s", e ? e : "libcairo.so.2: cannot be opened");
        return;
    }
    lx__cairo_api a;
    void *f;
#define LX__CAIRO_SYM(n)                                                                        \
    if (!(f = dlsym(h, "cairo_" #n))) {                                                         \
        snprintf(cairo_why, sizeof cairo_why, "libcairo.so.2 has no function cairo_" #n);      \
        return;                                                                                 \
    }                                                                                           \
    memcpy(&a.n, &f, sizeof f);
    LX__CAIRO_FNS(LX__CAIRO_SYM)
#undef LX__CAIRO_SYM
    lx__cairo = a;
    cairo_ready = 1;
}

lx_status lx__cairo_load(lx_ctx *ctx)
{
    pthread_once(&cairo_once, cairo_open);
    if (!cairo_ready)
        return lx__error(ctx, LX_EUNSUPPORTED, NULL, 0, "plots need the cairo library: %s (Debian: apt-get install libcairo2)",
                         cairo_why);
    return LX_OK;
}
