/* parallel.c - the library's one way to run work on several threads: a static split of a range
 * (lx__parallel_for) and one call per thread for work that hands out its own pieces
 * (lx__parallel_run). Threads are started per call: every caller's work runs for milliseconds or
 * more, against ~20 us to start and join a thread, and no thread outlives the call that made it. */
#include "core/core_private.h"

#include <pthread.h>
#include <unistd.h>

#define LX__THREADS_MAX 64

int lx__threads(int asked, long work)
{
    long n = asked > 0 ? asked : sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1) n = 1;
    if (n > LX__THREADS_MAX) n = LX__THREADS_MAX;
    if (work > 0 && n > work) n = work;
    return (int)n;
}

typedef struct range_job {
    void (*fn)(void *, long, long, int);
    void *arg;
    long i0, i1;
    int t;
} range_job;

static void *range_run(void *p)
{
    range_job *j = p;
    j->fn(j->arg, j->i0, j->i1, j->t);
    return NULL;
}

lx_status lx__parallel_for(lx_ctx *ctx, int threads, long n, void (*fn)(void *arg, long i0, long i1, int t), void *arg)
{
    (void)ctx;
    if (n <= 0) return LX_OK;
    if (threads < 1) threads = 1;
    if (threads > LX__THREADS_MAX) threads = LX__THREADS_MAX;
    if (threads > n) threads = (int)n;
    if (threads == 1) {
        fn(arg, 0, n, 0);
        return LX_OK;
    }
    pthread_t tid[LX__THREADS_MAX];
    range_job jobs[LX__THREADS_MAX];
    int started = 0;
    for (int t = 0; t < threads; t++) jobs[t] = (range_job){fn, arg, n * t / threads, n * (t + 1) / threads, t};
    for (int t = 0; t < threads - 1; t++, started++)
        if (pthread_create(&tid[t], NULL, range_run, &jobs[t]) != 0) break;
    for (int t = started; t < threads; t++) range_run(&jobs[t]); /* the rest, on this thread */
    for (int t = 0; t < started; t++) pthread_join(tid[t], NULL);
    return LX_OK;
}

static void *each_run(void *p)
{
    lx__team_job *j = p;
    j->fn(j->arg, j->t);
    return NULL;
}

int lx__team_start(lx__team *team, int threads, int t0, void (*fn)(void *arg, int t), void *arg)
{
    team->started = 0;
    if (threads > LX__THREADS_MAX) threads = LX__THREADS_MAX;
    for (int i = 0; i < threads; i++) {
        team->job[i] = (lx__team_job){fn, arg, t0 + i};
        if (pthread_create(&team->tid[i], NULL, each_run, &team->job[i]) != 0) break;
        team->started++;
    }
    return team->started;
}

void lx__team_join(lx__team *team)
{
    for (int i = 0; i < team->started; i++) pthread_join(team->tid[i], NULL);
    team->started = 0;
}

int lx__parallel_run(int threads, void (*fn)(void *arg, int t), void *arg)
{
    if (threads < 1) threads = 1;
    if (threads > LX__THREADS_MAX) threads = LX__THREADS_MAX;
    lx__team team;
    int started = lx__team_start(&team, threads - 1, 1, fn, arg);
    fn(arg, 0);
    lx__team_join(&team);
    return started + 1;
}
