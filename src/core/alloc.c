/* alloc.c - the library's one allocation path (lx__alloc family): sizes checked for overflow, and in
 * the test build (LX_FAULTS) a counter that fails the k-th allocation, for the out-of-memory tests. */
#include "core/core_private.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(LX_FAULTS)
#include <stdatomic.h>
/* the test build: allocations counted from lx__alloc_fault_set; the k-th (and with `persist` every
 * later one) fails; live counts lx__alloc returns minus lx__free calls on non-NULL pointers */
static atomic_long n_calls, fail_at, live;
static atomic_int persist;

void lx__alloc_fault_set(long k, int persistent)
{
    atomic_store(&n_calls, 0);
    atomic_store(&persist, persistent);
    atomic_store(&fail_at, k);
}

long lx__alloc_calls(void) { return atomic_load(&n_calls); }
long lx__alloc_live(void) { return atomic_load(&live); }

/* 1 when this allocation is to fail */
static int fault(void)
{
    long k = atomic_fetch_add(&n_calls, 1) + 1, at = atomic_load(&fail_at);
    return at > 0 && (k == at || (k > at && atomic_load(&persist)));
}
#define FAULT() fault()
#define LIVE(p, d)                                                                                           \
    do {                                                                                                     \
        if (p) atomic_fetch_add(&live, d);                                                                   \
    } while (0)
#else
#define FAULT() 0
#define LIVE(p, d) ((void)0)
#endif

/* sizes at or above this fail without asking the system (no object may exceed PTRDIFF_MAX) */
#define SIZE_CAP ((size_t)PTRDIFF_MAX)

size_t lx__size_mul(size_t a, size_t b)
{
    if (a && b > SIZE_MAX / a) return SIZE_MAX;
    return a * b;
}

void *lx__alloc(size_t size)
{
    if (size >= SIZE_CAP || FAULT()) return NULL;
    void *p = malloc(size ? size : 1);
    LIVE(p, 1);
    return p;
}

void *lx__alloc_n(size_t n, size_t size) { return lx__alloc(lx__size_mul(n, size)); }

void *lx__calloc(size_t n, size_t size)
{
    size_t total = lx__size_mul(n, size);
    if (total >= SIZE_CAP || FAULT()) return NULL;
    void *p = calloc(total ? n : 1, total ? size : 1);
    LIVE(p, 1);
    return p;
}

void *lx__realloc(void *p, size_t size)
{
    if (size >= SIZE_CAP || FAULT()) return NULL;
    void *q = realloc(p, size ? size : 1);
    if (!p) LIVE(q, 1);
    return q;
}

void *lx__realloc_n(void *p, size_t n, size_t size) { return lx__realloc(p, lx__size_mul(n, size)); }

void *lx__alloc_aligned(size_t align, size_t size)
{
    size_t round = size ? (size + align - 1) / align * align : align;
    if (size >= SIZE_CAP - align || FAULT()) return NULL;
    void *p = aligned_alloc(align, round);
    LIVE(p, 1);
    return p;
}

char *lx__strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = lx__alloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

void lx__free(void *p)
{
    LIVE(p, -1);
    free(p);
}
