/* ugr_text.c - the CIE 190:2010 UGR table as luminaire data sheets print it: a matrix of room sizes
 * (rows) by reflectance combinations (columns), crosswise then endwise, one decimal. */
#include "lighting/lighting_private.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct sbuf {
    char *s;
    size_t n, cap;
    int oom;
} sbuf;

static void put(sbuf *b, const char *fmt, ...)
{
    if (b->oom) return;
    va_list ap;
    va_start(ap, fmt);
    char line[256];
    int k = vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (k < 0) k = 0;
    size_t len = (size_t)k < sizeof line ? (size_t)k : sizeof line - 1;
    if (b->n + len + 1 > b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 4096;
        while (cap < b->n + len + 1) cap *= 2;
        char *ns = lx__realloc(b->s, cap);
        if (!ns) {
            b->oom = 1;
            return;
        }
        b->s = ns, b->cap = cap;
    }
    memcpy(b->s + b->n, line, len);
    b->n += len;
    b->s[b->n] = 0;
}

/* a multiple of H as "2H", "12H", "1.5H" */
static void h_text(char *buf, size_t cap, double h)
{
    if (fabs(h - round(h)) < 1e-9) snprintf(buf, cap, "%.0fH", h);
    else snprintf(buf, cap, "%gH", h);
}

lx_status lx_ugr_table_text(lx_ctx *ctx, const lx_ugr_table *tab, char **text)
{
    LX__NEED_CTX(ctx);
    if (!tab || !text) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_ugr_table_text: NULL argument");
    /* the reflectance combinations of CIE 190 Table 2, in lx_ugr_table's column order */
    static const int rho[3][5] = {{70, 70, 50, 50, 30}, {50, 30, 50, 30, 30}, {20, 20, 20, 20, 20}};
    static const char *const what[3] = {"ceiling", "walls", "floor cavity"};
    sbuf b = {0};
    put(&b, "reflectances\n");
    for (int k = 0; k < 3; k++) {
        put(&b, "  %-14s", what[k]);
        for (int c = 0; c < 10; c++) put(&b, "%s%6.2f", c == 5 ? "   " : "", rho[k][c % 5] / 100.0);
        put(&b, "\n");
    }
    put(&b, "\n%-18s%-33s%s\n", "room size  X   Y", "viewed crosswise", "viewed endwise");
    for (int r = 0; r < 19; r++) {
        char xs[16] = "", ys[16];
        if (r == 0 || tab->x_h[r] != tab->x_h[r - 1]) h_text(xs, sizeof xs, tab->x_h[r]);
        h_text(ys, sizeof ys, tab->y_h[r]);
        put(&b, "%12s%4s", xs, ys);
        for (int c = 0; c < 10; c++) {
            double v = tab->ugr[r][c];
            if (isfinite(v)) put(&b, "%s%6.1f", c == 5 ? "   " : "", round(v * 10) / 10 + 0.0);
            else put(&b, "%s%6s", c == 5 ? "   " : "", "-");
        }
        put(&b, "\n");
    }
    if (b.oom) {
        lx__free(b.s);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "UGR table text: out of memory");
    }
    *text = b.s;
    return LX_OK;
}
