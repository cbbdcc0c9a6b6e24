/* bench_common.h - what every `luxcalc bench` topic shares: the clock, medians, the load average. */
#ifndef LX_BENCH_COMMON_H
#define LX_BENCH_COMMON_H

double cli_bench_now_s(void);              /* monotonic seconds */
double cli_bench_median(double *v, int n); /* sorts v */
double cli_bench_load1(void);              /* the 1-minute load average (NaN when unknown) */

#endif
