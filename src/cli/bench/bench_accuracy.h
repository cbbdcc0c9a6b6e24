/* bench_accuracy.h - the parts of `luxcalc bench accuracy` shared between bench_accuracy.c (driver,
 * timing helpers, spectra) and bench_accuracy_fields.c (radiance fields and lighting). */
#ifndef LX_BENCH_ACCURACY_H
#define LX_BENCH_ACCURACY_H

#include <stdio.h>

#include "bench_common.h"
#include "luxcalc.h"

/* Seconds per call of fn(arg): median of 5 runs of enough calls (at most cap) to last 3 ms. */
double acc_time(void (*fn)(void *), void *arg, long cap);
void acc_fmt_time(char *buf, size_t n, double s);
void acc_fmt_err(char *buf, size_t n, double e); /* "-" for NaN, "0", else %.2e */

/* The four topics: markdown on o, the PNG at png (NULL: none). Return a CLI exit code. */
int acc_spectra(lx_ctx *ctx, FILE *o, const char *png);
int acc_radiance(lx_ctx *ctx, FILE *o, const char *png);
int acc_lighting(lx_ctx *ctx, FILE *o, const char *png);
int acc_nearfield(lx_ctx *ctx, FILE *o, const char *png); /* bench_accuracy_nearfield.c */

/* The topic (cmd_bench.c): outpath is bench's -o FILE (NULL: no PNG files). */
int cli_bench_accuracy(FILE *out, const char *outpath);

#endif
