/* spd_report.c - `luxcalc spd --report DIR`: one PNG report per spectrum (lx_spd_report_write_png)
 * and its TM-30 page (lx_tm30_report_write_png),
 * named DIR/<file-stem>_<spectrum>.png with the names reduced to portable characters. */
#include "spd_report.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

int cli_make_dir(const char *cmd, const char *opt, const char *dir)
{
    struct stat sb;
    if (stat(dir, &sb) == 0) {
        if (S_ISDIR(sb.st_mode)) return 0;
        cli_error(cmd, "%s: %s: not a directory", dir, opt);
        return -1;
    }
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        cli_error(cmd, "%s: %s: cannot create the directory: %s", dir, opt, strerror(errno));
        return -1;
    }
    return 0;
}

/* appends s to buf (cap bytes) with every character outside [A-Za-z0-9._-] as '_' */
static void put_clean(char *buf, size_t cap, const char *s, size_t n)
{
    size_t len = strlen(buf);
    for (size_t i = 0; i < n && len + 1 < cap; i++) {
        char ch = s[i];
        int ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '.' ||
                 ch == '_' || ch == '-';
        buf[len++] = ok ? ch : '_';
    }
    buf[len] = 0;
}

/* 1 when name was written before in this run, else records it (0) */
static int seen(cli_reports *rep, const char *name)
{
    for (size_t i = 0; i < rep->n_used; i++)
        if (!strcmp(rep->used[i], name)) return 1;
    if (rep->n_used == rep->cap_used) {
        size_t cap = rep->cap_used ? 2 * rep->cap_used : 64;
        char **nu = realloc(rep->used, cap * sizeof *nu);
        if (!nu) return 0; /* without memory to remember, a repeat may overwrite */
        rep->used = nu;
        rep->cap_used = cap;
    }
    char *c = strdup(name);
    if (c) rep->used[rep->n_used++] = c;
    return 0;
}

void cli_reports_free(cli_reports *rep)
{
    for (size_t i = 0; i < rep->n_used; i++) free(rep->used[i]);
    free(rep->used);
    rep->used = NULL;
    rep->n_used = rep->cap_used = 0;
}

int cli_spd_report(cli_reports *rep, lx_ctx *ctx, const char *file, size_t index, const lx_spd *spd)
{
    char name[256] = "", idx[32], unique[280];
    const char *base = strrchr(file, '/');
    base = base ? base + 1 : file;
    if (!strcmp(file, "-")) base = "stdin";
    const char *dot = strrchr(base, '.');
    size_t stem = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    put_clean(name, 120, base, stem);
    put_clean(name, sizeof name, "_", 1);
    const char *sp = spd->name && *spd->name ? spd->name : (snprintf(idx, sizeof idx, "%zu", index + 1), idx);
    put_clean(name, 240, sp, strlen(sp));
    if (name[0] == '.') name[0] = '_'; /* never a hidden file */
    snprintf(unique, sizeof unique, "%s", name);
    for (int k = 2; seen(rep, unique); k++) snprintf(unique, sizeof unique, "%s_%d", name, k);
    size_t n = strlen(rep->dir) + strlen(unique) + 8;
    char *path = malloc(n);
    if (!path) return cli_error(rep->cmd, "out of memory"), CLI_RUNTIME;
    snprintf(path, n, "%s/%s.png", rep->dir, unique);
    char title[200];
    snprintf(title, sizeof title, "%s: %s", base, sp);
    lx_report_opts o = rep->opts;
    o.title = title;
    lx_status st = lx_spd_report_write_png(ctx, spd, &o, path);
    int rc = CLI_OK;
    if (st != LX_OK) rc = cli_fail(rep->cmd, ctx, st);
    else if (cli_verbose) fprintf(stderr, "luxcalc: %s: wrote %s\n", rep->cmd, path);
    /* the TM-30 page beside it, where TM-30 is defined (the summary page says why where it is not) */
    char tm[300];
    snprintf(tm, sizeof tm, "%s_tm30", unique);
    if (rc == CLI_OK && !seen(rep, tm)) {
        char *tpath = malloc(strlen(rep->dir) + strlen(tm) + 8);
        if (!tpath) rc = (cli_error(rep->cmd, "out of memory"), CLI_RUNTIME);
        else {
            sprintf(tpath, "%s/%s.png", rep->dir, tm);
            st = lx_tm30_report_write_png(ctx, spd, &o, tpath);
            if (st == LX_OK && cli_verbose) fprintf(stderr, "luxcalc: %s: wrote %s\n", rep->cmd, tpath);
            else if (st != LX_OK && st != LX_ERANGE) rc = cli_fail(rep->cmd, ctx, st);
            free(tpath);
        }
    }
    free(path);
    return rc;
}
