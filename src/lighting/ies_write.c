/* ies_write.c - writes a luminaire as IES LM-63-2002 text (type C, the stored planes and their
 * symmetry kept), numbers in the shortest form that reads back exactly. */
#include "lighting/lighting_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct sbuf {
    char *p;
    size_t n, cap;
    int err;
} sbuf;

static void put(sbuf *b, const char *s, size_t n)
{
    if (b->err) return;
    if (b->n + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        while (b->n + n + 1 > cap) cap *= 2;
        char *np = realloc(b->p, cap);
        if (!np) {
            b->err = 1;
            return;
        }
        b->p = np;
        b->cap = cap;
    }
    memcpy(b->p + b->n, s, n);
    b->n += n;
    b->p[b->n] = 0;
}

static void puts_(sbuf *b, const char *s) { put(b, s, strlen(s)); }

static void num(sbuf *b, double v)
{
    char t[40];
    for (int prec = 1; prec <= 17; prec++) {
        snprintf(t, sizeof t, "%.*g", prec, v);
        if (strtod(t, NULL) == v) break;
    }
    puts_(b, t);
}

/* Header text on one line: no line breaks, at most 200 characters. */
static void kw(sbuf *b, const char *key, const char *val)
{
    char line[240];
    snprintf(line, sizeof line, "[%s] %.200s", key, val && *val ? val : "");
    for (char *q = line; *q; q++)
        if (*q == '\n' || *q == '\r') *q = ' ';
    puts_(b, line);
    puts_(b, "\r\n");
}

/* Values ten to a line (LM-63-2002 keeps lines under 256 characters). */
static void list(sbuf *b, const double *v, size_t n, size_t stride)
{
    for (size_t i = 0; i < n; i++) {
        num(b, v[i * stride]);
        puts_(b, (i + 1) % 10 == 0 || i + 1 == n ? "\r\n" : " ");
    }
}

lx_status lx_luminaire_write_ies(lx_ctx *ctx, const lx_luminaire *l, char **text, size_t *len)
{
    LX__NEED_CTX(ctx);
    if (text) *text = NULL;
    if (!l || !text || !len || !l->cd) return lx__error(ctx, LX_EINVAL, NULL, 0, "lx_luminaire_write_ies: NULL argument");
    if (l->photometric_type != 1)
        return lx__error(ctx, LX_EUNSUPPORTED, l->file, 0, "only type C luminaires can be written");
    /* IES stores the planes 0, 0-90, 0-180, 90-270 or 0-360: EULUMDAT Isym 0 tables that stop
     * short of 360 get the C360 plane (a copy of C0) */
    int close = l->symmetry == LX_SYM_NONE && l->h_deg[l->n_h - 1] < 360;
    sbuf b = {0};
    puts_(&b, "IESNA:LM-63-2002\r\n");
    kw(&b, "TEST", "computed by luxcalc (not a measurement)");
    kw(&b, "TESTLAB", "luxcalc");
    kw(&b, "ISSUEDATE", "none");
    kw(&b, "MANUFAC", l->manufacturer);
    kw(&b, "LUMCAT", l->catalog);
    kw(&b, "LUMINAIRE", l->description);
    if (isfinite(l->stated_lumens)) {
        char t[64];
        snprintf(t, sizeof t, "%.17g", l->stated_lumens);
        for (int prec = 1; prec <= 17; prec++) {
            snprintf(t, sizeof t, "%.*g", prec, l->stated_lumens);
            if (strtod(t, NULL) == l->stated_lumens) break;
        }
        kw(&b, "_ABSOLUTELUMENS", t);
    }
    kw(&b, "OTHER", "candela values are absolute (multiplier and ballast factor 1)");
    if (l->tilt_include && l->n_tilt) {
        puts_(&b, "TILT=INCLUDE\r\n");
        char t[16];
        snprintf(t, sizeof t, "%d\r\n", l->tilt_geometry ? l->tilt_geometry : 1);
        puts_(&b, t);
        snprintf(t, sizeof t, "%zu\r\n", l->n_tilt);
        puts_(&b, t);
        list(&b, l->tilt_deg, l->n_tilt, 1);
        list(&b, l->tilt_factor, l->n_tilt, 1);
    } else {
        puts_(&b, "TILT=NONE\r\n");
    }
    size_t nh = l->n_h + (close ? 1 : 0);
    double lamps = l->n_lamps > 0 ? l->n_lamps : 1;
    double lm_per_lamp = l->absolute || !isfinite(l->lamp_lumens) ? -1 : l->lamp_lumens / lamps;
    num(&b, lamps);
    puts_(&b, " ");
    num(&b, lm_per_lamp);
    puts_(&b, " 1 ");
    char t[64];
    snprintf(t, sizeof t, "%zu %zu 1 2 ", l->n_v, nh);
    puts_(&b, t);
    num(&b, l->width_m);
    puts_(&b, " ");
    num(&b, l->length_m);
    puts_(&b, " ");
    num(&b, l->height_m);
    puts_(&b, "\r\n1 1 ");
    num(&b, isfinite(l->input_watts) ? l->input_watts : 0);
    puts_(&b, "\r\n");
    list(&b, l->v_deg, l->n_v, 1);
    for (size_t i = 0; i < nh; i++) {
        num(&b, i < l->n_h ? l->h_deg[i] : 360.0);
        puts_(&b, (i + 1) % 10 == 0 || i + 1 == nh ? "\r\n" : " ");
    }
    for (size_t i = 0; i < nh; i++) list(&b, l->cd + (i < l->n_h ? i : 0) * l->n_v, l->n_v, 1);
    if (b.err) {
        free(b.p);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    *text = b.p;
    *len = b.n;
    return LX_OK;
}
