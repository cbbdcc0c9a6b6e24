/* spd_unc_stream.c - `luxcalc spd --uncertainty` on a large rows-layout CSV: a first pass reads the
 * whole file for its bad rows (cheap beside the uncertainty, and a file with one is then left to
 * the general reader, which reports it as for any file); the second streams it with
 * lx_batch_table_stream_ex, each part's spectra getting their uncertainty on the thread that parsed
 * it (one context a thread, Monte Carlo on one thread a spectrum: the cores share the spectra), and
 * the rows go out in file order as the parts come, in bounded memory. */
#include "spd_unc.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define MAX_THREADS 64
#define STREAM_MIN 1024 /* spectra: fewer go through the general reader, as every small file */

typedef struct ustream {
    const cli_unc *u;
    const lx_unc_model *m;
    lx_observer obs;
    lx_method method;
    const cli_unc_rows *rows;
    const char *path, *cmd;
    lx_ctx *tctx[MAX_THREADS];
    int rc;
} ustream;

/* One part's results, made on its parsing thread, written by emit. */
typedef struct part_res {
    size_t n, cap;
    lx_unc_result **r;
    lx_status *st;
    char **msg;
    double *lam;
    size_t nlam;
} part_res;

static lx_status count_rows(void *user, const lx_batch_table *chunk, size_t row0)
{
    size_t *n = user;
    *n = row0 + chunk->batch.n_spectra;
    return LX_OK;
}

/* spectrum i of a part as a view (lam: the part's grid, made by the caller) */
static lx_spd spectrum(const lx_batch_table *part, size_t i, const double *lam)
{
    const lx_batch *b = &part->batch;
    size_t stride = b->row_stride ? b->row_stride : b->n_lambda;
    lx_spd s = {part->names + part->name_at[i], b->n_lambda, lam, (const double *)b->values + i * stride};
    return s;
}

static int grid_of(part_res *p, const lx_batch *b)
{
    if (p->nlam != b->n_lambda) {
        double *l = realloc(p->lam, b->n_lambda * sizeof *l);
        if (!l) return -1;
        p->lam = l, p->nlam = b->n_lambda;
    }
    for (size_t j = 0; j < b->n_lambda; j++) p->lam[j] = b->start_nm + (double)j * b->step_nm;
    return 0;
}

static void part_free(void *user, void *state)
{
    (void)user;
    part_res *p = state;
    if (!p) return;
    for (size_t i = 0; i < p->n; i++) lx_unc_result_free(p->r[i]), free(p->msg[i]);
    free(p->r), free(p->st), free(p->msg), free(p->lam);
    free(p);
}

static lx_status work(void *user, int thread, const lx_batch_table *part, void **state)
{
    ustream *S = user;
    part_res *p = *state;
    if (!p && !(p = *state = calloc(1, sizeof *p))) return LX_ENOMEM;
    if (!S->tctx[thread] && lx_ctx_create(&S->tctx[thread]) != LX_OK) return LX_ENOMEM;
    size_t n = part->batch.n_spectra;
    if (n > p->cap) {
        lx_unc_result **r = realloc(p->r, n * sizeof *r);
        if (r) p->r = r;
        lx_status *st = realloc(p->st, n * sizeof *st);
        if (st) p->st = st;
        char **msg = realloc(p->msg, n * sizeof *msg);
        if (msg) p->msg = msg;
        if (!r || !st || !msg) return LX_ENOMEM;
        p->cap = n;
    }
    p->n = n;
    if (grid_of(p, &part->batch)) return LX_ENOMEM;
    for (size_t i = 0; i < n; i++) {
        lx_spd s = spectrum(part, i, p->lam);
        p->r[i] = cli_unc_compute(S->u, S->tctx[thread], &s, S->obs, S->method, S->m, 1, &p->st[i], &p->msg[i]);
    }
    return LX_OK;
}

static lx_status emit(void *user, const lx_batch_table *part, size_t row0, void *state)
{
    ustream *S = user;
    part_res *p = state;
    const cli_unc_rows *R = S->rows;
    for (size_t i = 0; i < p->n; i++) {
        lx_spd s = spectrum(part, i, p->lam);
        char where[1100];
        snprintf(where, sizeof where, "%s (data row %zu)", S->path, row0 + i + 1);
        int e = R->plain(R->arg, R->row, &s, where);
        if (e < 0) { /* no plain row (reported): no uncertainty row either */
            if (-e > S->rc) S->rc = -e;
            cli_table_discard(R->row);
            lx_unc_result_free(p->r[i]);
        } else {
            if (e > S->rc) S->rc = e;
            e = cli_unc_write(S->u, R->dst, R->row, p->r[i], p->st[i], p->msg[i], S->m, where, s.name, S->cmd);
            if (e > S->rc) S->rc = e;
        }
        p->r[i] = NULL;
        free(p->msg[i]);
        p->msg[i] = NULL;
    }
    p->n = 0;
    R->flush(R->flush_arg);
    return LX_OK;
}

int cli_unc_stream(const cli_unc *u, lx_ctx *ctx, const char *path, const lx_unc_model *m, lx_observer obs,
                   lx_method method, const cli_unc_rows *rows, const char *cmd, int *rc)
{
    struct stat sb;
    if (!strcmp(path, "-") || stat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) return 0; /* read once: the general reader */
    size_t n = 0;
    if (lx_batch_table_stream(ctx, path, LX_F64, 0, count_rows, &n) != LX_OK) return 0; /* not a (good) rows layout */
    if (n < STREAM_MIN && (size_t)sb.st_size <= lx_ctx_input_limit(ctx, LX_INPUT_SPECTRUM)) return 0;
    ustream S;
    memset(&S, 0, sizeof S);
    S.u = u, S.m = m, S.obs = obs, S.method = method, S.rows = rows, S.path = path, S.cmd = cmd;
    lx_batch_stream cb;
    memset(&cb, 0, sizeof cb);
    cb.user = &S, cb.work = work, cb.emit = emit, cb.release = part_free;
    lx_status st = lx_batch_table_stream_ex(ctx, path, LX_F64, 0, &cb);
    for (int t = 0; t < MAX_THREADS; t++) lx_ctx_destroy(S.tctx[t]);
    if (st != LX_OK) {
        cli_error(cmd, "%s: %s", path, st == LX_ENOMEM && !*lx_ctx_errmsg(ctx) ? "out of memory" : lx_ctx_errmsg(ctx));
        if (cli_exit_code(st) > S.rc) S.rc = cli_exit_code(st);
    }
    *rc = S.rc;
    return 1;
}
