/* progress.c - a progress bar on stderr for long batches: only when stderr is a terminal and not
 * with -q, redrawn with '\r' at most ~10 times a second, coloured unless NO_COLOR is set; counts
 * units (spectra) or bytes read (then the rate and the time left too). */
#include "progress.h"

#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define BAR_WIDTH 30
#define REDRAW_S 0.1

static struct {
    int on, colour, bytes;
    size_t total, done;
    double t0, last;
    char label[48];
} P;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* "4.23 GB", "812 MB", "12.5 kB" */
static void human(char *buf, size_t cap, double b)
{
    static const char *u[] = {"B", "kB", "MB", "GB", "TB"};
    int k = 0;
    while (b >= 1000 && k < 4) b /= 1000, k++;
    snprintf(buf, cap, b >= 99.95 || k == 0 ? "%.0f %s" : b >= 9.995 ? "%.1f %s" : "%.2f %s", b, u[k]);
}

static void draw_bytes(void)
{
    double el = now_s() - P.t0, rate = el > 0 ? (double)P.done / el : 0;
    char done[32], total[32], r[32], left[32] = "";
    human(done, sizeof done, (double)P.done);
    human(r, sizeof r, rate);
    if (!P.total) { /* a pipe: no size, no bar */
        fprintf(stderr, "\r%s %s read, %s/s, %.0f s ", P.label, done, r, el);
        fflush(stderr);
        return;
    }
    double f = (double)P.done / (double)P.total;
    if (f > 1) f = 1;
    human(total, sizeof total, (double)P.total);
    if (rate > 0 && P.done < P.total) {
        double s = (double)(P.total - P.done) / rate;
        if (s < 90) snprintf(left, sizeof left, ", %.0f s left", s);
        else snprintf(left, sizeof left, ", %.0f min left", s / 60);
    }
    int fill = (int)(f * BAR_WIDTH + 0.5);
    char bar[BAR_WIDTH + 1];
    memset(bar, '#', (size_t)fill);
    memset(bar + fill, '-', (size_t)(BAR_WIDTH - fill));
    bar[BAR_WIDTH] = 0;
    if (P.colour)
        fprintf(stderr, "\r%s \033[32m%.*s\033[2m%s\033[0m %5.1f%% %s of %s, %s/s%s ", P.label, fill, bar, bar + fill,
                100 * f, done, total, r, left);
    else
        fprintf(stderr, "\r%s [%s] %5.1f%% %s of %s, %s/s%s ", P.label, bar, 100 * f, done, total, r, left);
    fflush(stderr);
}

static void draw(void)
{
    if (P.bytes) {
        draw_bytes();
        return;
    }
    double f = P.total ? (double)P.done / (double)P.total : 1.0;
    if (f > 1) f = 1;
    int fill = (int)(f * BAR_WIDTH + 0.5);
    char bar[BAR_WIDTH + 1];
    memset(bar, '#', (size_t)fill);
    memset(bar + fill, '-', (size_t)(BAR_WIDTH - fill));
    bar[BAR_WIDTH] = 0;
    double el = now_s() - P.t0;
    if (P.colour)
        fprintf(stderr, "\r%s \033[32m%.*s\033[2m%s\033[0m %5.1f%% %zu/%zu %.1fs ", P.label, fill, bar, bar + fill,
                100 * f, P.done, P.total, el);
    else
        fprintf(stderr, "\r%s [%s] %5.1f%% %zu/%zu %.1fs ", P.label, bar, 100 * f, P.done, P.total, el);
    fflush(stderr);
}

static void start(size_t total, const char *label, int bytes)
{
    P.on = 0;
    P.bytes = bytes;
    if ((total == 0 && !bytes) || cli_quiet || !isatty(STDERR_FILENO)) return;
    const char *nc = getenv("NO_COLOR");
    P.colour = !(nc && *nc);
    P.total = total;
    P.done = 0;
    snprintf(P.label, sizeof P.label, "%s", label ? label : "");
    /* a long label (a path) keeps its end */
    size_t n = label ? strlen(label) : 0;
    if (n >= sizeof P.label) snprintf(P.label, sizeof P.label, "...%s", label + n - (sizeof P.label - 4));
    P.t0 = P.last = now_s();
    P.on = 1;
    draw();
}

void cli_progress_start_bytes(unsigned long long total, const char *label) { start((size_t)total, label, 1); }

void cli_progress_start(size_t total, const char *label) { start(total, label, 0); }


void cli_progress_update(size_t done)
{
    if (!P.on) return;
    P.done = done;
    double t = now_s();
    if (t - P.last < REDRAW_S) return;
    P.last = t;
    draw();
}

void cli_progress_end(void)
{
    if (!P.on) return;
    if (!P.bytes) P.done = P.total;
    draw();
    /* erase the line with spaces (no escape codes, so NO_COLOR output stays plain) */
    size_t n = strlen(P.label) + BAR_WIDTH + (P.bytes ? 80 : 48);
    fputc('\r', stderr);
    for (size_t i = 0; i < n; i++) fputc(' ', stderr);
    fputc('\r', stderr);
    fflush(stderr);
    P.on = 0;
}

int cli_progress_active(void) { return P.on; }
