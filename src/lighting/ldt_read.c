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
        lx__free(*out);
        *out = lx__strndup(r->s, r->e);
        if (!*out) return lx__error(ctx, LX_ENOMEM, r->file, r->it.line, "out of memory");
    }
    return LX_OK;
}

/* The header fields the table and the model need. */
typedef struct ldt_head {
    long ityp, isym, mc, ng, nsets;
    long isym_line;
    double dc, dg, dim[9], dff, lorl, cfli, tilt;
    long lamps1; /* the first (standard) lamp set: lamps (negative: absolute photometry), flux, watts */
    double flux1, watts1;
} ldt_head;

static lx_status nomem(lx_ctx *ctx, const ldt *r)
{
    return lx__error(ctx, LX_ENOMEM, r->file, r->it.line, "out of memory");
}

/* Lines 1 to 26: identification, type and symmetry, the angle grid, the texts, the dimensions in
 * mm, DFF, LORL, the conversion factor, the tilt and the number of lamp sets. */
static lx_status read_head(lx_ctx *ctx, ldt *r, lx_luminaire *l, ldt_head *h)
{
    static const char *dn[9] = {"the luminaire length", "the luminaire width", "the luminaire height",
                                "the luminous area length", "the luminous area width", "the luminous height C0",
                                "the luminous height C90", "the luminous height C180", "the luminous height C270"};
    lx_status st;
    if ((st = text(ctx, r, "the company identification", &l->manufacturer))) return st;
    if ((st = whole(ctx, r, "Ityp (type indicator)", 0, 3, &h->ityp))) return st;
    if ((st = whole(ctx, r, "Isym (symmetry indicator)", 0, 4, &h->isym))) return st;
    h->isym_line = r->it.line;
    if ((st = whole(ctx, r, "Mc (number of C-planes)", 1, LX__LDT_MAX_C_PLANES, &h->mc))) return st;
    if ((st = num(ctx, r, "Dc (C-plane step)", &h->dc))) return st;
    if ((st = whole(ctx, r, "Ng (number of gamma angles)", 2, LX__LDT_MAX_GAMMA, &h->ng))) return st;
    if ((st = num(ctx, r, "Dg (gamma step)", &h->dg))) return st;
    if ((st = text(ctx, r, "the measurement report number", &l->test))) return st;
    if ((st = text(ctx, r, "the luminaire name", &l->description))) return st;
    if ((st = text(ctx, r, "the luminaire number", &l->catalog))) return st;
    if ((st = text(ctx, r, "the file name", NULL))) return st;
    if ((st = text(ctx, r, "the date/user", &l->issuedate))) return st;
    for (int i = 0; i < 9; i++)
        if ((st = num(ctx, r, dn[i], &h->dim[i]))) return st;
    if ((st = num(ctx, r, "DFF (downward flux fraction)", &h->dff))) return st;
    if ((st = num(ctx, r, "LORL (light output ratio)", &h->lorl))) return st;
    if ((st = num(ctx, r, "the intensity conversion factor", &h->cfli))) return st;
    if ((st = num(ctx, r, "the tilt during measurement", &h->tilt))) return st;
    return whole(ctx, r, "the number of lamp sets", 1, LX__LDT_MAX_LAMP_SETS, &h->nsets);
}

/* The lamp sets (six lines each; the first, the standard set, is kept) and the ten direct ratios. */
static lx_status read_lamp_sets(lx_ctx *ctx, ldt *r, lx_luminaire *l, ldt_head *h)
{
    lx_status st;
    for (long k = 0; k < h->nsets; k++) {
        double lamps, flux, w;
        if ((st = num(ctx, r, "the number of lamps", &lamps))) return st;
        if (lamps != floor(lamps) || lamps == 0 || fabs(lamps) > LX__LDT_MAX_LAMPS)
            return lx__error(ctx, LX_EPARSE, r->file, r->it.line, "the number of lamps must be a non-zero whole number "
                             "of at most %g (got %g)", LX__LDT_MAX_LAMPS, lamps);
        if ((st = text(ctx, r, "the lamp type", k == 0 ? &l->lamp : NULL))) return st;
        if ((st = num(ctx, r, "the lamps' luminous flux", &flux))) return st;
        if (!(flux > 0))
            return lx__error(ctx, LX_EPARSE, r->file, r->it.line, "the lamps' luminous flux must be positive (got %g lm)",
                             flux);
        if ((st = text(ctx, r, "the colour temperature", NULL))) return st;
        if ((st = text(ctx, r, "the colour rendering index", NULL))) return st;
        if ((st = num(ctx, r, "the wattage", &w))) return st;
        if (k == 0) {
            h->lamps1 = (long)lamps;
            h->flux1 = flux;
            h->watts1 = w;
        }
    }
    for (int k = 0; k < 10; k++) {
        double dr;
        if ((st = num(ctx, r, "the direct ratios", &dr))) return st;
    }
    return LX_OK;
}

/* The Mc C angles (increasing, from 0 to below 360) into c and the Ng gamma angles into g, both
 * the caller's; *cline, *gline: the lines each list starts on. */
static lx_status read_angles(lx_ctx *ctx, ldt *r, const ldt_head *h, double *c, double *g, long *cline, long *gline)
{
    lx_status st;
    long mc = h->mc;
    *cline = r->it.line + 1;
    for (long i = 0; i < mc; i++) {
        if ((st = num(ctx, r, "the end of the C angles", &c[i]))) return st;
        if (i > 0 && !(c[i] > c[i - 1]))
            return lx__error(ctx, LX_EPARSE, r->file, r->it.line, "C angles out of order (%g after %g)", c[i], c[i - 1]);
    }
    if (c[0] != 0 || c[mc - 1] >= 360)
        return lx__error(ctx, LX_EPARSE, r->file, *cline, "the C angles must run from 0 to below 360 (got %g..%g)", c[0],
                         c[mc - 1]);
    *gline = r->it.line + 1;
    for (long j = 0; j < h->ng; j++)
        if ((st = num(ctx, r, "the end of the gamma angles", &g[j]))) return st;
    return LX_OK;
}

/* The C planes stored for each Isym: count planes from index *first (Isym 3: C270 through C0 to
 * C90); Mc must suit the symmetry. */
static lx_status stored_planes(lx_ctx *ctx, const ldt *r, const ldt_head *h, long *first, long *count)
{
    long mc = h->mc, isym = h->isym;
    *first = 0;
    *count = mc;
    switch (isym) {
    case 1: *count = 1; break;
    case 2: *count = mc / 2 + 1; break;
    case 3: *first = 3 * mc / 4; *count = mc / 2 + 1; break;
    case 4: *count = mc / 4 + 1; break;
    default: break;
    }
    if ((isym == 2 || isym == 3) && mc % 2)
        return lx__error(ctx, LX_EPARSE, r->file, h->isym_line, "Isym %ld needs an even number of C-planes (Mc = %ld)",
                         isym, mc);
    if ((isym == 3 || isym == 4) && mc % 4)
        return lx__error(ctx, LX_EPARSE, r->file, h->isym_line,
                         "Isym %ld needs a number of C-planes divisible by 4 (Mc = %ld)", isym, mc);
    return LX_OK;
}

/* One value per line: the counts against the lines left, before the table is sized by them. */
static lx_status check_lines_left(lx_ctx *ctx, const ldt *r, long count, long ng)
{
    long left = 0;
    for (const char *p = r->it.p; p < r->it.end; p++) left += *p == '\n';
    if (r->it.p < r->it.end && r->it.end[-1] != '\n') left++;
    if (left < count * ng)
        return lx__error(ctx, LX_EPARSE, r->file, r->it.line + left, "the file ends before the end of the intensities: "
                         "%ld planes x %ld angles need %ld lines, the file has %ld (truncated table or counts that lie)",
                         count, ng, count * ng, left);
    return LX_OK;
}

/* The model's fields from the header: lamps and flux (absolute when the lamp count is negative),
 * the cd/klm scale, watts, and the luminous area in metres. Returns the candela scale. */
static double apply_head(lx_luminaire *l, const ldt_head *h)
{
    l->absolute = h->lamps1 < 0;
    l->n_lamps = (int)labs(h->lamps1);
    double scale = (h->cfli > 0 ? h->cfli : 1) * h->flux1 / 1000.0;
    l->multiplier = scale;
    l->lamp_lumens = l->absolute ? NAN : h->flux1;
    l->stated_lumens = l->absolute ? h->flux1 : h->flux1 * h->lorl / 100.0;
    l->input_watts = h->watts1;
    /* the luminous area: its length (or diameter) lies along C0-C180, its width along C90-C270
     * (EULUMDAT, as LM-63 puts length along 0-180 and width along 90-270); width 0 means a
     * circle whose diameter is the length, stored as LM-63 does (both negative) */
    if (h->dim[4] == 0 && h->dim[3] > 0) {
        l->width_m = l->length_m = -h->dim[3] / 1000.0;
    } else {
        l->length_m = h->dim[3] / 1000.0;
        l->width_m = h->dim[4] / 1000.0;
    }
    l->height_m = h->dim[5] / 1000.0;
    return scale;
}

/* The intensities of the stored planes (count from first; C angles c) into l->h_deg and l->cd,
 * cd/klm times scale; Isym 3 planes are stored as their mirror image C90..C270. */
static lx_status read_intensities(lx_ctx *ctx, ldt *r, lx_luminaire *l, const ldt_head *h, const double *c,
                                  long first, long count, double scale)
{
    long mc = h->mc, ng = h->ng, isym = h->isym;
    lx_status st;
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
            if ((st = num(ctx, r, what, &v))) return st;
            if (v < 0)
                return lx__error(ctx, LX_EPARSE, r->file, r->it.line, "negative luminous intensity %g cd/klm", v);
            l->cd[dst * (size_t)ng + (size_t)j] = v * scale;
        }
    }
    return LX_OK;
}

/* Anything but blank lines after the table means the counts do not match the data. */
static lx_status check_trailing(lx_ctx *ctx, ldt *r, long count, long ng)
{
    const char *s, *e;
    while (lx__next_line(&r->it, &s, &e)) {
        while (s < e && (*s == ' ' || *s == '\t' || *s == '\r' || *s == 0x1a)) s++;
        if (s < e)
            return lx__error(ctx, LX_EPARSE, r->file, r->it.line,
                             "data after the intensity table (%ld planes x %ld angles expected)", count, ng);
    }
    return LX_OK;
}

/* After the header and the lamp sets: the angles, the stored planes, the intensity table and the
 * model (EULUMDAT full tables do not repeat C360: photometry.c closes the circle). */
static lx_status read_table(lx_ctx *ctx, ldt *r, lx_luminaire *l, const ldt_head *h)
{
    long first = 0, count = 0, cline = 0, gline = 0, ng = h->ng;
    double *c = lx__alloc_n((size_t)h->mc, sizeof *c);
    double *g = lx__alloc_n((size_t)ng, sizeof *g);
    lx_status st = !c || !g ? nomem(ctx, r) : read_angles(ctx, r, h, c, g, &cline, &gline);
    if (!st) st = stored_planes(ctx, r, h, &first, &count);
    if (!st) st = check_lines_left(ctx, r, count, ng);
    if (!st) {
        l->n_h = (size_t)count;
        l->n_v = (size_t)ng;
        l->h_deg = lx__alloc_n(l->n_h, sizeof(double));
        l->v_deg = lx__alloc_n(l->n_v, sizeof(double));
        l->cd = lx__alloc_n(l->n_h * l->n_v, sizeof(double));
        if (!l->h_deg || !l->v_deg || !l->cd) st = nomem(ctx, r);
    }
    if (!st) {
        memcpy(l->v_deg, g, (size_t)ng * sizeof *g);
        double scale = apply_head(l, h);
        long cdline = r->it.line + 1;
        st = read_intensities(ctx, r, l, h, c, first, count, scale);
        if (!st) st = check_trailing(ctx, r, count, ng);
        if (!st) st = lx__lum_finish(ctx, l, cline, gline, cdline);
    }
    lx__free(c);
    lx__free(g);
    return st;
}

lx_status lx__ldt_read(lx_ctx *ctx, const char *file, const char *buf, size_t len, lx_luminaire **out)
{
    *out = NULL;
    lx_luminaire *l = lx__lum_new(file);
    if (!l) return lx__error(ctx, LX_ENOMEM, file, 0, "out of memory");
    ldt r = {{buf, buf + len, 0}, file, NULL, NULL};
    if (len >= 3 && (unsigned char)buf[0] == 0xEF && (unsigned char)buf[1] == 0xBB && (unsigned char)buf[2] == 0xBF) r.it.p += 3;
    l->format = LX_LUM_EULUMDAT;
    ldt_head h = {0};
    lx_status st = read_head(ctx, &r, l, &h);
    if (!st) st = read_lamp_sets(ctx, &r, l, &h);
    if (!st) st = read_table(ctx, &r, l, &h);
    if (st) {
        lx_luminaire_free(l);
        return st;
    }
    *out = l;
    return LX_OK;
}
