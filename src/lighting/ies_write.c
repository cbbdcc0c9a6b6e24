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
        char *np = lx__realloc(b->p, cap);
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

/* the shortest text that reads back as v exactly, without an exponent where a plain number does
 * (800, not 8e+02) */
static void num(sbuf *b, double v)
{
    char t[64];
    for (int prec = 1; prec <= 17; prec++) {
        snprintf(t, sizeof t, "%.*g", prec, v);
        if (strtod(t, NULL) == v) break;
    }
    if (strchr(t, 'e') && fabs(v) >= 1e-4 && fabs(v) < 1e15)
        for (int dec = 0; dec <= 20; dec++) {
            snprintf(t, sizeof t, "%.*f", dec, v);
            if (strtod(t, NULL) == v) break;
        }
    puts_(b, t);
}

/* An angle in the shortest form within 1e-9 deg of it: computed angles (j x 0.1) print as
 * 0.3, not 0.30000000000000004. */
static void angle(sbuf *b, double v)
{
    char t[48];
    for (int dec = 0; dec <= 12; dec++) {
        snprintf(t, sizeof t, "%.*f", dec, v);
        if (fabs(strtod(t, NULL) - v) <= 1e-9) break;
    }
    if (!strcmp(t, "-0")) snprintf(t, sizeof t, "0");
    puts_(b, t);
}

/* A keyword line, its value on lines of at most 200 characters (LM-63-2002 keeps lines under 256):
 * a longer value goes on in [MORE] lines, cut between words; line breaks become spaces. */
static void kw(sbuf *b, const char *key, const char *val)
{
    const char *s = val ? val : "";
    int first = 1;
    do {
        size_t n = strlen(s), take = n > 200 ? 200 : n;
        if (take < n) {
            size_t k = take;
            while (k > 0 && s[k] != ' ') k--;
            if (k > 0) take = k;
        }
        char line[240];
        snprintf(line, sizeof line, "[%s] %.*s", first ? key : "MORE", (int)take, s);
        for (char *q = line; *q; q++)
            if (*q == '\n' || *q == '\r') *q = ' ';
        puts_(b, line);
        puts_(b, "\r\n");
        s += take;
        while (*s == ' ') s++;
        first = 0;
    } while (*s);
}

/* Values ten to a line (LM-63-2002 keeps lines under 256 characters); angles cleaned. */
static void list_(sbuf *b, const double *v, size_t n, size_t stride, int angles)
{
    for (size_t i = 0; i < n; i++) {
        (angles ? angle : num)(b, v[i * stride]);
        puts_(b, (i + 1) % 10 == 0 || i + 1 == n ? "\r\n" : " ");
    }
}

static void list(sbuf *b, const double *v, size_t n, size_t stride) { list_(b, v, n, stride, 0); }

/* The base name of a path (the file a converted luminaire came from). */
static const char *base(const char *path)
{
    const char *s = path ? strrchr(path, '/') : NULL;
    return s ? s + 1 : path ? path : "";
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
    /* the source's own test, laboratory, date, lamp and catalogue fields are kept; what a source
     * does not state is said so, and a file written today is issued today */
    char other[400], src[200];
    snprintf(src, sizeof src, "%s", base(l->file));
    char *today = l->issuedate && *l->issuedate ? NULL : lx__date_today();
    puts_(&b, "IESNA:LM-63-2002\r\n");
    snprintf(other, sizeof other, "not stated in %s", src);
    kw(&b, "TEST", l->test && *l->test ? l->test : other);
    kw(&b, "TESTLAB", l->testlab && *l->testlab ? l->testlab : other);
    kw(&b, "ISSUEDATE", l->issuedate && *l->issuedate ? l->issuedate : today ? today : "unknown");
    lx__free(today);
    kw(&b, "MANUFAC", l->manufacturer && *l->manufacturer ? l->manufacturer : other);
    kw(&b, "LUMCAT", l->catalog);
    kw(&b, "LUMINAIRE", l->description);
    if (l->lamp && *l->lamp) kw(&b, "LAMP", l->lamp);
    if (isfinite(l->stated_lumens)) {
        sbuf nb = {0};
        num(&nb, l->stated_lumens);
        kw(&b, "_ABSOLUTELUMENS", nb.p);
        lx__free(nb.p);
    }
    if (strcmp(src, "(model)")) {
        snprintf(other, sizeof other, "written by luxcalc %s from %s (%s); candela values are absolute (multiplier and "
                 "ballast factor 1)", LX_VERSION_STRING, src, lx_lum_format_name(l->format));
        kw(&b, "OTHER", other);
    } else {
        kw(&b, "OTHER", "candela values are absolute (multiplier and ballast factor 1)");
    }
    if (l->tilt_include && l->n_tilt) {
        puts_(&b, "TILT=INCLUDE\r\n");
        char t[16];
        snprintf(t, sizeof t, "%d\r\n", l->tilt_geometry ? l->tilt_geometry : 1);
        puts_(&b, t);
        snprintf(t, sizeof t, "%zu\r\n", l->n_tilt);
        puts_(&b, t);
        list_(&b, l->tilt_deg, l->n_tilt, 1, 1);
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
    /* the opening as LM-63 orders it: width (along the 90-270 plane), then length (along 0-180);
     * lx_luminaire keeps the same meaning, so the axes survive a write and a read */
    num(&b, l->width_m);
    puts_(&b, " ");
    num(&b, l->length_m);
    puts_(&b, " ");
    num(&b, l->height_m);
    puts_(&b, "\r\n1 1 ");
    num(&b, isfinite(l->input_watts) ? l->input_watts : 0);
    puts_(&b, "\r\n");
    list_(&b, l->v_deg, l->n_v, 1, 1);
    for (size_t i = 0; i < nh; i++) {
        angle(&b, i < l->n_h ? l->h_deg[i] : 360.0);
        puts_(&b, (i + 1) % 10 == 0 || i + 1 == nh ? "\r\n" : " ");
    }
    for (size_t i = 0; i < nh; i++) list(&b, l->cd + (i < l->n_h ? i : 0) * l->n_v, l->n_v, 1);
    if (b.err) {
        lx__free(b.p);
        return lx__error(ctx, LX_ENOMEM, NULL, 0, "out of memory");
    }
    *text = b.p;
    *len = b.n;
    return LX_OK;
}
