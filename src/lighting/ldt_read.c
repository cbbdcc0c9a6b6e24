/* ldt_read.c - the EULUMDAT (.ldt) reader: one field per line, every Isym value (0-4), several
 * lamp sets (the first is the standard set the intensities refer to), cd/klm scaled to candela,
 * dimensions in mm. The table is checked and expanded by photometry.c. */
#include "lighting/lighting_private.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct ldt {
    lx__lines it;
    const char *file;
    const char *s, *e; /* the current line, trimmed */
} ldt;

static lx_status next(lx_ctx *ctx, ldt *r, const char *what)
{
    if (!lx__next_line(&r->it, &r->s, &r->e))
        return lx__error(ctx, LX_EPARSE, r->file, r->it.line, "the file ends before %s (truncated)", what);
    while (r->s < r->e && (*r->s == ' ' || *r->s == '\t')) r->s++;
    while (r->e > r->s && (r->e[-1] == ' ' || r->e[-1] == '\t' || r->e[-1] == '\r')) r->e--;
    return LX_OK;
}

/* A number on a line of its own; a decimal comma is accepted when the line has no point. */
static lx_status num(lx_ctx *ctx, ldt *r, const char *what, double *out)
{
    lx_status st = next(ctx, r, what);
    if (st) return st;
    char point = memchr(r->s, '.', (size_t)(r->e - r->s)) ? '.' : ',';
    if (r->s == r->e) {
        *out = 0; /* empty numeric fields (optional values) read as 0 */
        return LX_OK;
    }
    if (lx__parse_double_ex(r->s, r->e, point, out) != r->e || !isfinite(*out)) {
        int n = (int)(r->e - r->s) > 40 ? 40 : (int)(r->e - r->s);
        return lx__error(ctx, LX_EPARSE, r->file, r->it.line, "%s: '%.*s' is not a number", what, n, r->s);
    }
    return LX_OK;
}

static lx_status whole(lx_ctx *ctx, ldt *r, const char *what, long lo, long hi, long *out)
{
    double v;
    lx_status st = num(ctx, r, what, &v);
    if (st) return st;
    if (v != floor(v) || v < lo || v > hi)
        return lx__error(ctx, LX_EPARSE, r->file, r->it.line, "%s must be a whole number from %ld to %ld (got %g)", what, lo, hi, v);
    *out = (long)v;
    return LX_OK;
}

static lx_status text(lx_ctx *ctx, ldt *r, const char *what, char **out)
{
    lx_status st = next(ctx, r, what);
    if (st) return st;
    if (out) {
        free(*out);
        *out = lx__strndup(r->s, r->e);
        if (!*out) return lx__error(ctx, LX_ENOMEM, r->file, r->it.line, "out of memory");
    }
    return LX_OK;
}

lx_status lx__ldt_read(lx_ctx *ctx, const char *file, const char *buf, size_t len, lx_luminaire **out)
{
    *out = NULL;
    lx_luminaire *l = lx__lum_new(file);
    if (!l) return lx__error(ctx, LX_ENOMEM, file, 0, "out of memory");
    ldt r = {{buf, buf + len, 0}, file, NULL, NULL};
    if (len >= 3 && (unsigned char)buf[0] == 0xEF && (unsigned char)buf[1] == 0xBB && (unsigned char)buf[2] == 0xBF) r.it.p += 3;
    l->format = LX_LUM_EULUMDAT;
    lx_status st;
    long ityp, isym, mc, ng, nsets;
    double dc, dg, dim[9], dff, lorl, cfli, tilt;
    double *c = NULL, *g = NULL;
    if ((st = text(ctx, &r, "the company identification", &l->manufacturer))) goto fail;
    if ((st = whole(ctx, &r, "Ityp (type indicator)", 0, 3, &ityp))) goto fail;
    if ((st = whole(ctx, &r, "Isym (symmetry indicator)", 0, 4, &isym))) goto fail;
    long isym_line = r.it.line;
    if ((st = whole(ctx, &r, "Mc (number of C-planes)", 1, LX__LDT_MAX_C_PLANES, &mc))) goto fail;
    if ((st = num(ctx, &r, "Dc (C-plane step)", &dc))) goto fail;
    if ((st = whole(ctx, &r, "Ng (number of gamma angles)", 2, LX__LDT_MAX_GAMMA, &ng))) goto fail;
    if ((st = num(ctx, &r, "Dg (gamma step)", &dg))) goto fail;
    if ((st = text(ctx, &r, "the measurement report number", &l->test))) goto fail;
    if ((st = text(ctx, &r, "the luminaire name", &l->description))) goto fail;
    if ((st = text(ctx, &r, "the luminaire number", &l->catalog))) goto fail;
    if ((st = text(ctx, &r, "the file name", NULL))) goto fail;
    if ((st = text(ctx, &r, "the date/user", &l->issuedate))) goto fail;
    static const char *dn[9] = {"the luminaire length", "the luminaire width", "the luminaire height",
                                "the luminous area length", "the luminous area width", "the luminous height C0",
                                "the luminous height C90", "the luminous height C180", "the luminous height C270"};
    for (int i = 0; i < 9; i++)
        if ((st = num(ctx, &r, dn[i], &dim[i]))) goto fail;
    if ((st = num(ctx, &r, "DFF (downward flux fraction)", &dff))) goto fail;
    if ((st = num(ctx, &r, "LORL (light output ratio)", &lorl))) goto fail;
    if ((st = num(ctx, &r, "the intensity conversion factor", &cfli))) goto fail;
    if ((st = num(ctx, &r, "the tilt during measurement", &tilt))) goto fail;
    if ((st = whole(ctx, &r, "the number of lamp sets", 1, LX__LDT_MAX_LAMP_SETS, &nsets))) goto fail;
    double flux1 = 0, watts1 = 0;
    long lamps1 = 0;
    for (long k = 0; k < nsets; k++) {
        double lamps, flux, w;
        if ((st = num(ctx, &r, "the number of lamps", &lamps))) goto fail;
        if (lamps != floor(lamps) || lamps == 0 || fabs(lamps) > LX__LDT_MAX_LAMPS) {
            st = lx__error(ctx, LX_EPARSE, file, r.it.line, "the number of lamps must be a non-zero whole number of at most "
                           "%g (got %g)", LX__LDT_MAX_LAMPS, lamps);
            goto fail;
        }
        if ((st = text(ctx, &r, "the lamp type", k == 0 ? &l->lamp : NULL))) goto fail;
        if ((st = num(ctx, &r, "the lamps' luminous flux", &flux))) goto fail;
        if (!(flux > 0)) {
            st = lx__error(ctx, LX_EPARSE, file, r.it.line, "the lamps' luminous flux must be positive (got %g lm)", flux);
            goto fail;
        }
        if ((st = text(ctx, &r, "the colour temperature", NULL))) goto fail;
        if ((st = text(ctx, &r, "the colour rendering index", NULL))) goto fail;
        if ((st = num(ctx, &r, "the wattage", &w))) goto fail;
        if (k == 0) {
            lamps1 = (long)lamps;
            flux1 = flux;
            watts1 = w;
        }
    }
    for (int k = 0; k < 10; k++) {
        double dr;
        if ((st = num(ctx, &r, "the direct ratios", &dr))) goto fail;
    }
    c = malloc((size_t)mc * sizeof *c);
    g = malloc((size_t)ng * sizeof *g);
    if (!c || !g) goto nomem;
    long cline = r.it.line + 1;
    for (long i = 0; i < mc; i++) {
        if ((st = num(ctx, &r, "the end of the C angles", &c[i]))) goto fail;
        if (i > 0 && !(c[i] > c[i - 1])) {
            st = lx__error(ctx, LX_EPARSE, file, r.it.line, "C angles out of order (%g after %g)", c[i], c[i - 1]);
            goto fail;
        }
    }
    if (c[0] != 0 || c[mc - 1] >= 360) {
        st = lx__error(ctx, LX_EPARSE, file, cline, "the C angles must run from 0 to below 360 (got %g..%g)", c[0], c[mc - 1]);
        goto fail;
    }
    long gline = r.it.line + 1;
    for (long j = 0; j < ng; j++)
        if ((st = num(ctx, &r, "the end of the gamma angles", &g[j]))) goto fail;
    /* the planes stored for each Isym (Isym 3: C270 through C0 to C90) */
    long first = 0, count = mc;
    switch (isym) {
    case 1: count = 1; break;
    case 2: count = mc / 2 + 1; break;
    case 3: first = 3 * mc / 4; count = mc / 2 + 1; break;
    case 4: count = mc / 4 + 1; break;
    default: break;
    }
    if ((isym == 2 || isym == 3) && mc % 2) {
        st = lx__error(ctx, LX_EPARSE, file, isym_line, "Isym %ld needs an even number of C-planes (Mc = %ld)", isym, mc);
        goto fail;
    }
    if ((isym == 3 || isym == 4) && mc % 4) {
        st = lx__error(ctx, LX_EPARSE, file, isym_line, "Isym %ld needs a number of C-planes divisible by 4 (Mc = %ld)", isym, mc);
        goto fail;
    }
    {
        /* one value per line: check the counts against the lines left before sizing the table */
        long left = 0;
        for (const char *p = r.it.p; p < r.it.end; p++) left += *p == '\n';
        if (r.it.p < r.it.end && r.it.end[-1] != '\n') left++;
        if (left < count * ng) {
            st = lx__error(ctx, LX_EPARSE, file, r.it.line + left, "the file ends before the end of the intensities: %ld "
                           "planes x %ld angles need %ld lines, the file has %ld (truncated table or counts that lie)",
                           count, ng, count * ng, left);
            goto fail;
        }
    }
    l->n_h = (size_t)count;
    l->n_v = (size_t)ng;
    l->h_deg = malloc(l->n_h * sizeof(double));
    l->v_deg = malloc(l->n_v * sizeof(double));
    l->cd = malloc(l->n_h * l->n_v * sizeof(double));
    if (!l->h_deg || !l->v_deg || !l->cd) goto nomem;
    memcpy(l->v_deg, g, (size_t)ng * sizeof *g);
    l->absolute = lamps1 < 0;
    l->n_lamps = (int)labs(lamps1);
    double scale = (cfli > 0 ? cfli : 1) * flux1 / 1000.0;
    l->multiplier = scale;
    l->lamp_lumens = l->absolute ? NAN : flux1;
    l->stated_lumens = l->absolute ? flux1 : flux1 * lorl / 100.0;
    l->input_watts = watts1;
    /* the luminous area: its length (or diameter) lies along C0-C180, its width along C90-C270
     * (EULUMDAT, as LM-63 puts length along 0-180 and width along 90-270); width 0 means a
     * circle whose diameter is the length, stored as LM-63 does (both negative) */
    if (dim[4] == 0 && dim[3] > 0) {
        l->width_m = l->length_m = -dim[3] / 1000.0;
    } else {
        l->length_m = dim[3] / 1000.0;
        l->width_m = dim[4] / 1000.0;
    }
    l->height_m = dim[5] / 1000.0;
    long cdline = r.it.line + 1;
    for (long k = 0; k < count; k++) {
        long src = (first + k) % mc;
        double cang = c[src];
        size_t dst = (size_t)k;
        if (isym == 3) {
            /* store as the mirror image C90..C270 (C -> 180 - C), increasing */
            cang = 180 - (cang >= 270 ? cang - 360 : cang);
            dst = (size_t)(count - 1 - k);
        }
        if (isym == 1) cang = 0;
        l->h_deg[dst] = cang;
        for (long j = 0; j < ng; j++) {
            double v;
            char what[80];
            snprintf(what, sizeof what, "the end of the intensities (plane %ld of %ld)", k + 1, count);
            if ((st = num(ctx, &r, what, &v))) goto fail;
            if (v < 0) {
                st = lx__error(ctx, LX_EPARSE, file, r.it.line, "negative luminous intensity %g cd/klm", v);
                goto fail;
            }
            l->cd[dst * (size_t)ng + (size_t)j] = v * scale;
        }
    }
    /* anything but blank lines after the table means the counts do not match the data */
    {
        const char *s, *e;
        while (lx__next_line(&r.it, &s, &e)) {
            while (s < e && (*s == ' ' || *s == '\t' || *s == '\r' || *s == 0x1a)) s++;
            if (s < e) {
                st = lx__error(ctx, LX_EPARSE, file, r.it.line, "data after the intensity table (%ld planes x %ld angles expected)", count, ng);
                goto fail;
            }
        }
    }
    if (isym == 0 && mc >= 2) {
        /* EULUMDAT full tables do not repeat C360: photometry.c closes the circle */
    }
    if ((st = lx__lum_finish(ctx, l, cline, gline, cdline))) goto fail;
    free(c);
    free(g);
    *out = l;
    return LX_OK;
nomem:
    st = lx__error(ctx, LX_ENOMEM, file, r.it.line, "out of memory");
fail:
    free(c);
    free(g);
    lx_luminaire_free(l);
    return st;
}
