/* spd_batch.c - the batch paths of `luxcalc spd`: many spectra on one uniform grid go through
 * lx_batch_colorimetry (vectorised, threaded, OpenCL when asked or large), and raw float32 input
 * (--input-format f32 --grid START:END:STEP) for pipelines whose data is already numeric.
 * Rows-layout CSV files are streamed by spd_stream.c. */
#include "spd_batch.h"
#include "progress.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define CHUNK 65536 /* spectra per batch call: bounds memory, lets output stream */

void cli_spd_add_row(cli_spd_batch *B, const char *file, const char *name, const lx_colorimetry *r, const lx_par *par,
                     const lx_hazard *hz, const lx_binning *bin)
{
    cli_table *t = B->table;
    cli_table_str(t, file);
    cli_table_str(t, name);
    double v[] = {r->X, r->Y, r->Z, r->x, r->y, r->u_prime, r->v_prime, r->cct_K, r->duv, r->ler_lm_per_W,
                  r->scotopic_Y, r->sp_ratio, r->radiant};
    for (size_t j = 0; j < sizeof v / sizeof *v; j++) cli_table_num(t, v[j]);
    cli_table_str(t, "cie15");
    if (B->metrics && B->metrics->any)
        cli_metrics_row_batch(t, B->ctx, B->metrics, B->unit ? B->unit : "relative", par, hz, bin, B->vendor);
    cli_table_json(t, B->instrument);
}

typedef cli_spd_lab lab;

void cli_spd_lab_free(cli_spd_lab *L) { free(L->par), free(L->hz), free(L->bin); }

lx_status cli_spd_lab_compute(cli_spd_batch *B, const lx_batch *b, const lx_colorimetry *res, lx_batch_opts *opts,
                              cli_spd_lab *L)
{
    memset(L, 0, sizeof *L);
    const cli_metrics *m = B->metrics;
    if (!m || !m->any) return LX_OK;
    size_t n = b->n_spectra ? b->n_spectra : 1;
    int need_par = cli_metrics_need_par(m), need_hz = cli_metrics_need_hazard(m), need_bin = cli_metrics_need_binning(m);
    /* binning from the exact CCT of the colorimetry (2 deg); with --observer 10 the batch's own */
    int table_bin = need_bin && B->observer != LX_OBSERVER_2;
    if ((need_par && !(L->par = malloc(n * sizeof *L->par))) || (need_hz && !(L->hz = malloc(n * sizeof *L->hz))) ||
        (need_bin && !(L->bin = malloc(n * sizeof *L->bin))))
        return LX_ENOMEM;
    lx_status st = LX_OK;
    if (need_par || need_hz || table_bin)
        st = lx_lab_batch(B->ctx, b, opts, L->par, L->hz, table_bin ? L->bin : NULL);
    for (size_t i = 0; need_bin && !table_bin && i < b->n_spectra && st == LX_OK; i++)
        st = lx_binning_compute(B->ctx, res[i].x, res[i].y, res[i].cct_K, res[i].duv, &L->bin[i]);
    return st;
}

/* The largest |value| of spectrum i of b (for the overflow message). */
double cli_spd_row_max_abs(const lx_batch *b, size_t i)
{
    size_t stride = b->row_stride ? b->row_stride : b->n_lambda;
    double m = 0;
    for (size_t j = 0; j < b->n_lambda; j++) {
        double v = b->dtype == LX_F32 ? (double)((const float *)b->values)[i * stride + j]
                                      : ((const double *)b->values)[i * stride + j];
        if (fabs(v) > m) m = fabs(v);
    }
    return m;
}

/* Colorimetry of spectra [i0, i0+n) of b, one row each; names[i] or the 1-based index, lines[i]
 * (or none). A result lx_colorimetry_check refuses (an overflow, a NaN) is reported on stderr as
 * "FILE:LINE: spectrum 'NAME': why" instead of a row and counted in B->rejected; with stop_at_bad
 * the chunk ends there (LX_ERANGE, the rows before it added). */
static lx_status run_chunk(cli_spd_batch *B, const lx_batch *b, const char *file, const char *const *names,
                           const long *lines, size_t i0, int stop_at_bad)
{
    lx_colorimetry *res = malloc(sizeof *res * (b->n_spectra ? b->n_spectra : 1));
    if (!res) return LX_ENOMEM;
    lx_batch_opts opts;
    memset(&opts, 0, sizeof opts);
    opts.backend = B->backend;
    lab L = {0};
    lx_status st = lx_batch_colorimetry(B->ctx, b, B->observer, &opts, res);
    if (st == LX_OK) st = cli_spd_lab_compute(B, b, res, &opts, &L);
    if (st == LX_OK) {
        char idx[32];
        for (size_t i = 0; i < b->n_spectra; i++) {
            const char *name = names ? names[i] : (snprintf(idx, sizeof idx, "%zu", i0 + i + 1), idx);
            if (lx_colorimetry_check(B->ctx, &res[i], cli_spd_row_max_abs(b, i)) != LX_OK) {
                if (lines) cli_error(B->cmd, "%s:%ld: spectrum '%s': %s", file, lines[i], name, lx_ctx_errmsg(B->ctx));
                else cli_error(B->cmd, "%s: spectrum %s: %s", file, name, lx_ctx_errmsg(B->ctx));
                B->rejected++;
                if (stop_at_bad) {
                    st = LX_ERANGE;
                    break;
                }
                continue;
            }
            cli_spd_add_row(B, file, name, &res[i], L.par ? &L.par[i] : NULL, L.hz ? &L.hz[i] : NULL, L.bin ? &L.bin[i] : NULL);
        }
        if (B->flush) B->flush(B->flush_arg);
    }
    cli_spd_lab_free(&L);
    free(res);
    return st;
}

int cli_spd_batchable(const cli_spd_batch *B, const lx_spd_set *set)
{
    if (set->count == 0) return 0;
    if (!B->forced && set->count < CLI_SPD_BATCH_MIN) return 0;
    const lx_spd *s0 = &set->spd[0];
    if (lx_method_resolve(s0, B->method) != LX_METHOD_CIE15) return 0;
    for (size_t k = 1; k < set->count; k++) {
        const lx_spd *s = &set->spd[k];
        if (s->n != s0->n || memcmp(s->lambda_nm, s0->lambda_nm, s0->n * sizeof(double)) != 0) return 0;
    }
    for (size_t k = 0; k < set->count; k++)
        if (lx_spd_check(B->ctx, &set->spd[k]) != LX_OK) return 0; /* the scalar path reports it */
    return 1;
}

lx_status cli_spd_batch_set(cli_spd_batch *B, const lx_spd_set *set)
{
    const lx_spd *s0 = &set->spd[0];
    size_t n = s0->n;
    double step = (s0->lambda_nm[n - 1] - s0->lambda_nm[0]) / (double)(n - 1);
    lx_status st = LX_OK;
    cli_progress_start(set->count, set->file);
    for (size_t i0 = 0; i0 < set->count && st == LX_OK; i0 += CHUNK) {
        size_t m = set->count - i0 < CHUNK ? set->count - i0 : CHUNK;
        double *v = malloc(sizeof(double) * m * n);
        const char **names = malloc(sizeof *names * m);
        if (!v || !names) {
            free(v);
            free(names);
            cli_progress_end();
            return LX_ENOMEM;
        }
        for (size_t i = 0; i < m; i++) {
            memcpy(v + i * n, set->spd[i0 + i].value, n * sizeof(double));
            names[i] = set->spd[i0 + i].name ? set->spd[i0 + i].name : "";
        }
        lx_batch b = {m, n, 0, s0->lambda_nm[0], step, LX_F64, v};
        st = run_chunk(B, &b, set->file, names, set->line ? set->line + i0 : NULL, i0, 0);
        free(v);
        free(names);
        cli_progress_update(i0 + m);
    }
    cli_progress_end();
    return st;
}

int cli_spd_parse_grid(const char *s, double *start, double *step, size_t *n)
{
    char buf[128], *p1, *p2, *end;
    snprintf(buf, sizeof buf, "%s", s);
    if (!(p1 = strchr(buf, ':')) || !(p2 = strchr(p1 + 1, ':'))) return -1;
    *p1++ = 0;
    *p2++ = 0;
    double a = strtod(buf, &end);
    if (*end) return -1;
    double b = strtod(p1, &end);
    if (*end) return -1;
    double st = strtod(p2, &end);
    if (*end || !(a > 0) || !(b > a) || !(st > 0) || !isfinite(a + b + st)) return -1;
    double k = (b - a) / st;
    if (fabs(k - nearbyint(k)) > 1e-6 * (k > 1 ? k : 1) || k > 1e6) return -1;
    *start = a;
    *step = st;
    *n = (size_t)nearbyint(k) + 1;
    return 0;
}

lx_status cli_spd_f32_file(cli_spd_batch *B, const char *path, double start, double step, size_t n)
{
    FILE *f = !strcmp(path, "-") ? stdin : fopen(path, "rb");
    if (!f) {
        cli_error(B->cmd, "%s: cannot open: %s", path, strerror(errno));
        return LX_EIO;
    }
    size_t per = n * sizeof(float), total = 0;
    float *buf = malloc(per * CHUNK);
    if (!buf) {
        if (f != stdin) fclose(f);
        return LX_ENOMEM;
    }
    lx_status st = LX_OK;
    struct stat sb; /* a bar only where the size is known (a regular file) */
    if (f != stdin && fstat(fileno(f), &sb) == 0 && S_ISREG(sb.st_mode)) cli_progress_start((size_t)sb.st_size / per, path);
    for (;;) {
        size_t got = fread(buf, 1, per * CHUNK, f);
        if (got % per) {
            /* read to the end to report the real size */
            size_t rest = got;
            while (!feof(f) && !ferror(f)) rest += fread(buf, 1, per * CHUNK, f);
            cli_error(B->cmd, "%s: %zu bytes is not a whole number of spectra of %zu float32 samples (%zu bytes each)",
                      path, total + rest, n, per);
            st = LX_EPARSE;
            break;
        }
        size_t m = got / per;
        if (m) {
            /* little-endian on disk; this build's host order is checked at start-up of the command */
            for (size_t i = 0; i < m * n && st == LX_OK; i++)
                if (!isfinite(buf[i])) {
                    cli_error(B->cmd, "%s: spectrum %zu, sample %zu (%g nm): value is not finite", path,
                              total / per + i / n + 1, i % n + 1, start + (double)(i % n) * step);
                    st = LX_EPARSE;
                }
            if (st != LX_OK) break;
            lx_batch b = {m, n, 0, start, step, LX_F32, buf};
            st = run_chunk(B, &b, path, NULL, NULL, total / per, 1); /* the first bad spectrum ends the file */
            if (st != LX_OK) {
                if (st != LX_ERANGE) cli_error(B->cmd, "%s: %s", path, lx_ctx_errmsg(B->ctx));
                break;
            }
            total += got;
            cli_progress_update(total / per);
        }
        if (got < per * CHUNK) break;
    }
    cli_progress_end();
    if (ferror(f)) {
        cli_error(B->cmd, "%s: read error", path);
        st = LX_EIO;
    }
    free(buf);
    if (f != stdin) fclose(f);
    return st;
}
