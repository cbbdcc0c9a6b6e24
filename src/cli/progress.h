/* progress.h - a progress bar on stderr for long batches (progress.c): drawn only when stderr is
 * a terminal and -q was not given, at most ~10 times a second, without colour under NO_COLOR;
 * spectra done of a total, or bytes read of a file with the rate and the time left. */
#ifndef LX_CLI_PROGRESS_H
#define LX_CLI_PROGRESS_H

#include <stddef.h>

/* Starts a bar for `total` units of work labelled `label` (copied, may be NULL). Does nothing
 * when stderr is not a terminal, with -q, or when total is 0. One bar at a time. */
void cli_progress_start(size_t total, const char *label);
/* The same counting bytes read of `total` (0: unknown, a pipe: no bar, the bytes and the rate),
 * drawn with the rate and the time left; cli_progress_update then takes bytes. */
void cli_progress_start_bytes(unsigned long long total, const char *label);
/* Reports that `done` of the total units are finished (redraws at most every 100 ms). */
void cli_progress_update(size_t done);
/* Draws the final state and erases the bar (leaves the cursor at the start of a clean line). */
void cli_progress_end(void);
/* 1 while a bar is being drawn (after start on a terminal, before end). */
int cli_progress_active(void);

#endif
