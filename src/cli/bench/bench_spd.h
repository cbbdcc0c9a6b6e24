/* bench_spd.h - what the parts of the `luxcalc bench spd` topic share (bench_spd.c,
 * bench_spd_cli.c): timing, the spectra, running commands. */
#ifndef LX_BENCH_SPD_H
#define LX_BENCH_SPD_H

#include <stddef.h>
#include <stdio.h>

#include "bench_common.h"
#include "luxcalc.h"

#define BENCH_NL 471 /* samples of a bench spectrum: 360-830 nm at 1 nm */

double cli_bench_cpu_s(void); /* this process's CPU time, every thread */
/* Writes ns spectra of v (ns x BENCH_NL floats) as a rows-layout CSV: header "id,360,...,830" when
 * named (rows "s0,...") else numpy's (wavelengths only), values %.6g. 0, or -1 on failure. */
int cli_bench_write_csv(const char *path, const float *v, size_t ns, int named);
/* Runs argv with LX_SIMD=simd (NULL: unchanged), stdout and stderr to /dev/null (or stdout to
 * out_path); wall and child CPU seconds (user + system). 0 when it exited 0. */
int cli_bench_run(char *const argv[], const char *simd, const char *out_path, double *wall_s, double *cpu_s);
/* Runs argv and returns its standard output (malloc'ed; NULL when it failed). */
char *cli_bench_capture(char *const argv[], const char *perf_data);
double cli_bench_json_num(const char *js, const char *key);
/* The SIMD paths this CPU runs, widest first (n of them); the bench sets LX_SIMD to each. */
int cli_bench_paths(lx_simd paths[3]);
/* The CLI end to end and the kernels it uses (bench_spd_cli.c): `luxcalc spd --format csv FILE -o
 * OUT` as a whole process on each SIMD path beside numpy loadtxt + matmul + savetxt and
 * colour-science with Ohno 2013 CCT; the fast CCT against the exact solve; lx_double_format
 * against printf. v: the spectra (at least the largest size). */
void cli_bench_spd_cli(FILE *o, const char *tmp, const size_t *sizes, int nsizes, const float *v);

#endif
