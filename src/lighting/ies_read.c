/* ies_read.c - the IES LM-63 reader: every version seen in practice (1986 without a version line,
 * IESNA91, LM-63-1995, 2002, 2019), keywords, TILT=NONE/INCLUDE/file, comma or blank separators,
 * lines of any length, Latin-1 header bytes. The table is checked and expanded by photometry.c. */
#include "lighting/lighting_private.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The numbers after the TILT= line: one token stream with the line of each token. */
typedef struct toks {
    double *v;
    long *line;
    size_t n, cap, pos;
} toks;

static int toks_push(toks *t, double v, long line)
{
    if (t->n == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 1024;
        double *nv = lx__realloc_n(t->v, cap, sizeof *nv);
        if (!nv) return -1;
        t->v = nv;
        long *nl = lx__realloc_n(t->line, cap, sizeof *nl);
        if (!nl) return -1;
        t->line = nl;
        t->cap = cap;
    }
    t->v[t->n] = v;
    t->line[t->n++] = line;
    return 0;
}

static int is_sep(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '\f' || c == '\v'; }

/* Tokenises lines from it to the end of the buffer. A trailing Ctrl-Z (DOS end of file) is ignored. */
static lx_status tokenize(lx_ctx *ctx, const char *file, lx__lines *it, toks *t)
{
    const char *s, *e;
    while (lx__next_line(it, &s, &e)) {
        const char *p = s;
        for (;;) {
            while (p < e && is_sep(*p)) p++;
            if (p >= e) break;
            if (*p == 0x1a) break;
            const char *q = p;
            while (q < e && !is_sep(*q)) q++;
            double v;
            const char *end = lx__parse_double(p, q, &v);
            if (end != q || !isfinite(v)) {
                int n = (int)(q - p) > 40 ? 40 : (int)(q - p);
                return lx__error(ctx, LX_EPARSE, file, it->line, "'%.*s' is not a number", n, p);
            }
            if (toks_push(t, v, it->line)) return lx__error(ctx, LX_ENOMEM, file, it->line, "out of memory");
            p = q;
        }
    }
    return LX_OK;
}

/* Takes the next number, or reports the table as truncated. */
static lx_status take(lx_ctx *ctx, const char *file, toks *t, long last_line, const char *what, double *out)
{
    if (t->pos >= t->n)
        return lx__error(ctx, LX_EPARSE, file, last_line, "the file ends before %s (truncated table)", what);
    *out = t->v[t->pos++];
    return LX_OK;
}

static long tok_line(const toks *t, long last_line)
{
    return t->pos == 0 ? last_line : t->line[t->pos - 1];
}

static lx_status take_count(lx_ctx *ctx, const char *file, toks *t, long last, const char *what, long max, long *out)
{
    double v = 0;
    lx_status st = take(ctx, file, t, last, what, &v);
    if (st) return st;
    if (v != floor(v) || v < 1 || v > max)
        return lx__error(ctx, LX_EPARSE, file, tok_line(t, last), "%s must be a whole number from 1 to %ld (got %g)",
                         what, max, v);
    *out = (long)v;
    return LX_OK;
}

static int prefix_ci(const char *s, const char *e, const char *p)
{
    for (; *p; p++, s++)
        if (s >= e || toupper((unsigned char)*s) != toupper((unsigned char)*p)) return 0;
    return 1;
}

/* Reads the tilt block of a TILT=<file> reference (relative to the IES file's folder). */
static lx_status tilt_file(lx_ctx *ctx, const char *file, long line, const char *name, toks *t)
{
    char path[1024];
    const char *slash = strrchr(file, '/');
    if (name[0] != '/' && slash)
        snprintf(path, sizeof path, "%.*s/%s", (int)(slash - file), file, name);
    else
        snprintf(path, sizeof path, "%s", name);
    struct stat sb; /* a TILT table is a file: not stdin, a device or a FIFO */
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode) && !S_ISDIR(sb.st_mode))
        return lx__error(ctx, LX_EIO, file, line, "TILT file '%s': not a regular file", path);
    if (!strcmp(path, "-")) return lx__error(ctx, LX_EIO, file, line, "TILT file '%s': not a file", path);
    char *buf = NULL;
    size_t len = 0;
    lx_status st = lx__read_all(ctx, path, LX_INPUT_LUMINAIRE, &buf, &len);
    if (st) return lx__error(ctx, st, file, line, "TILT file '%s': %s", path, lx_ctx_errmsg(ctx));
    lx__lines it = {buf, buf + len, 0};
    st = tokenize(ctx, path, &it, t);
    lx__free(buf);
    return st;
}

static lx_status read_tilt(lx_ctx *ctx, const char *file, toks *t, long last, lx_luminaire *lum)
{
    double g = 0;
    long n = 0;
    lx_status st = take(ctx, file, t, last, "the TILT lamp-to-luminaire geometry", &g);
    if (st) return st;
    if (g != 1 && g != 2 && g != 3)
        return lx__error(ctx, LX_EPARSE, file, tok_line(t, last), "TILT lamp-to-luminaire geometry must be 1, 2 or 3 (got %g)", g);
    if ((st = take_count(ctx, file, t, last, "the number of TILT angles", LX__IES_MAX_TILT_ANGLES, &n))) return st;
    if (t->n - t->pos < 2 * (size_t)n) /* the count against the numbers there, before allocating */
        return lx__error(ctx, LX_EPARSE, file, last, "the file ends before the end of the TILT table: %ld angles need "
                         "%ld numbers, the file has %zu (truncated table or a count that lies)", n, 2 * n, t->n - t->pos);
    lum->tilt_geometry = (int)g;
    lum->n_tilt = (size_t)n;
    lum->tilt_deg = lx__alloc_n((size_t)n, sizeof(double));
    lum->tilt_factor = lx__alloc_n((size_t)n, sizeof(double));
    if (!lum->tilt_deg || !lum->tilt_factor) return lx__error(ctx, LX_ENOMEM, file, last, "out of memory");
    for (long i = 0; i < n; i++) {
        if ((st = take(ctx, file, t, last, "the end of the TILT angles", &lum->tilt_deg[i]))) return st;
        if (i > 0 && !(lum->tilt_deg[i] > lum->tilt_deg[i - 1]))
            return lx__error(ctx, LX_EPARSE, file, tok_line(t, last), "TILT angles out of order (%g after %g)",
                             lum->tilt_deg[i], lum->tilt_deg[i - 1]);
    }
    for (long i = 0; i < n; i++) {
        if ((st = take(ctx, file, t, last, "the end of the TILT factors", &lum->tilt_factor[i]))) return st;
        if (lum->tilt_factor[i] < 0)
            return lx__error(ctx, LX_EPARSE, file, tok_line(t, last), "negative TILT multiplying factor %g", lum->tilt_factor[i]);
    }
    lum->tilt_include = 1;
    return LX_OK;
}

/* "[KEY] value" or "[KEY]value"; [MORE] continues the previous keyword. *last: the field the
 * previous keyword line filled (NULL when it was one we do not keep). Returns -1 on no memory. */
static int keyword(lx_luminaire *lum, const char *s, const char *e, char ***last)
{
    const char *k = s + 1, *ke = k;
    while (ke < e && *ke != ']') ke++;
    if (ke >= e) return 0; /* not a keyword line: free text */
    const char *v = ke + 1;
    while (v < e && (*v == ' ' || *v == '\t')) v++;
    while (e > v && (e[-1] == ' ' || e[-1] == '\t')) e--;
    size_t kl = (size_t)(ke - k);
    char **dst = NULL;
    if (kl == 7 && prefix_ci(k, ke, "MANUFAC")) dst = &lum->manufacturer;
    else if (kl == 6 && prefix_ci(k, ke, "LUMCAT")) dst = &lum->catalog;
    else if (kl == 9 && prefix_ci(k, ke, "LUMINAIRE")) dst = &lum->description;
    else if (kl == 4 && prefix_ci(k, ke, "TEST")) dst = &lum->test;
    else if (kl == 7 && prefix_ci(k, ke, "TESTLAB")) dst = &lum->testlab;
    else if (kl == 9 && prefix_ci(k, ke, "ISSUEDATE")) dst = &lum->issuedate;
    else if (kl == 4 && prefix_ci(k, ke, "LAMP")) dst = &lum->lamp;
    else if (kl == 4 && prefix_ci(k, ke, "MORE")) dst = *last;
    else if (kl == 15 && prefix_ci(k, ke, "_ABSOLUTELUMENS")) {
        double x;
        if (lx__parse_double(v, e, &x) == e && x > 0) lum->stated_lumens = x;
    }
    *last = dst;
    if (!dst) return 0;
    if (!*dst) {
        *dst = lx__strndup(v, e);
        return *dst ? 0 : -1;
    }
    size_t a = strlen(*dst), b = (size_t)(e - v);
    char *n = lx__realloc(*dst, a + b + 2);
    if (!n) return -1;
    n[a] = ' ';
    memcpy(n + a + 1, v, b);
    n[a + 1 + b] = 0;
    *dst = n;
    return 0;
}

/* The version line, when it is one: sets lum->format and returns 1. */
static int version_line(lx_luminaire *lum, const char *p, const char *e)
{
    if (prefix_ci(p, e, "IESNA:LM-63-1995") || prefix_ci(p, e, "IESNA95"))
        lum->format = LX_LUM_LM63_1995;
    else if (prefix_ci(p, e, "IESNA:LM-63-2002"))
        lum->format = LX_LUM_LM63_2002;
    else if (prefix_ci(p, e, "IES:LM-63-2019") || prefix_ci(p, e, "IESNA:LM-63-2019"))
        lum->format = LX_LUM_LM63_2019;
    else if (prefix_ci(p, e, "IESNA91") || prefix_ci(p, e, "IESNA:LM-63-1991"))
        lum->format = LX_LUM_LM63_1991;
    else
        return 0;
    return 1;
}

/* A "TILT=" line (*is_tilt becomes 1; other lines are left alone): NONE, INCLUDE (the table follows
 * in the number stream) or a file, whose table is read now. */
static lx_status tilt_line(lx_ctx *ctx, const char *file, long line, const char *p, const char *e, lx_luminaire *lum,
                           int *is_tilt)
{
    *is_tilt = 0;
    if (!prefix_ci(p, e, "TILT")) return LX_OK;
    const char *q = p + 4;
    while (q < e && *q == ' ') q++;
    if (!(q < e && *q == '=')) return LX_OK;
    *is_tilt = 1;
    q++;
    while (q < e && (*q == ' ' || *q == '\t')) q++;
    const char *qe = e;
    while (qe > q && (qe[-1] == ' ' || qe[-1] == '\t')) qe--;
    if (prefix_ci(q, qe, "NONE") && qe - q == 4) return LX_OK; /* no tilt table */
    if (prefix_ci(q, qe, "INCLUDE") && qe - q == 7) {
        lum->tilt_include = 2; /* read from the stream below */
        return LX_OK;
    }
    if (!(qe > q)) return lx__error(ctx, LX_EPARSE, file, line, "TILT= names nothing (NONE, INCLUDE or a file)");
    char name[512];
    snprintf(name, sizeof name, "%.*s", (int)(qe - q), q);
    toks tt = {0};
    lx_status st = tilt_file(ctx, file, line, name, &tt);
    if (!st) st = read_tilt(ctx, name, &tt, line, lum);
    lx__free(tt.v);
    lx__free(tt.line);
    return st;
}

/* A header line before TILT= that is not the version: a [KEYWORD] line, or in 1986 files free
 * text, whose first line describes the luminaire. *last_kw: as keyword() keeps it. */
static lx_status header_text(lx_ctx *ctx, const char *file, long line, const char *p, const char *e,
                             lx_luminaire *lum, char ***last_kw)
{
    if (p < e && *p == '[') {
        if (keyword(lum, p, e, last_kw)) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    } else if (lum->format == LX_LUM_LM63_1986 && !lum->description && p < e) {
        const char *q = e;
        while (q > p && (q[-1] == ' ' || q[-1] == '\t')) q--;
        lum->description = lx__strndup(p, q);
        if (!lum->description) return lx__error(ctx, LX_ENOMEM, file, line, "out of memory");
    }
    return LX_OK;
}

/* The lines up to and including TILT=: the version (first line only), keywords and text, and the
 * tilt reference. *tilt: the TILT= line, 0 when the text has none (it is then read to the end). */
static lx_status read_header(lx_ctx *ctx, const char *file, lx__lines *it, lx_luminaire *lum, long *tilt)
{
    const char *s, *e;
    char **last_kw = NULL;
    int first = 1;
    lum->format = LX_LUM_LM63_1986;
    while (lx__next_line(it, &s, &e)) {
        const char *p = s;
        while (p < e && (*p == ' ' || *p == '\t')) p++;
        if (first) {
            first = 0;
            if (version_line(lum, p, e)) continue;
        }
        int is_tilt;
        lx_status st = tilt_line(ctx, file, it->line, p, e, lum, &is_tilt);
        if (st) return st;
        if (is_tilt) {
            *tilt = it->line;
            return LX_OK;
        }
        if ((st = header_text(ctx, file, it->line, p, e, lum, &last_kw))) return st;
    }
    return LX_OK;
}

static const char *const count_names[10] = {"the number of lamps", "lumens per lamp", "the candela multiplier",
                                            "the number of vertical angles", "the number of horizontal angles",
                                            "the photometric type", "the units type", "the width", "the length",
                                            "the height"};

/* The 13 numbers after the tilt block, all taken before any is checked: h (lamps, lumens per lamp,
 * multiplier, vertical and horizontal counts, photometric type, units type, width, length,
 * height) and b (ballast factor, ballast-lamp factor, input watts); *hline: the line of the first. */
static lx_status take_counts(lx_ctx *ctx, const char *file, toks *t, long last, double h[10], double b[3],
                             long *hline)
{
    static const char *names2[3] = {"the ballast factor", "the ballast-lamp factor", "the input watts"};
    lx_status st;
    for (int i = 0; i < 10; i++) {
        if ((st = take(ctx, file, t, last, count_names[i], &h[i]))) return st;
        if (i == 0) *hline = tok_line(t, last);
    }
    for (int i = 0; i < 3; i++)
        if ((st = take(ctx, file, t, last, names2[i], &b[i]))) return st;
    return LX_OK;
}

/* Checks the first line of numbers h (errors name hline) and stores it in lum: lamps and lumens,
 * multiplier, the angle counts, photometric type (type A refused), units and the opening's sizes. */
static lx_status apply_counts(lx_ctx *ctx, const char *file, long hline, const double h[10], lx_luminaire *lum)
{
    if (h[0] != floor(h[0]) || fabs(h[0]) < 1 || fabs(h[0]) > LX__IES_MAX_LAMPS)
        return lx__error(ctx, LX_EPARSE, file, hline, "the number of lamps must be a whole number (got %g)", h[0]);
    lum->n_lamps = (int)fabs(h[0]);
    if (h[1] == -1) {
        lum->absolute = 1;
        lum->lamp_lumens = NAN;
    } else if (h[1] > 0) {
        lum->lamp_lumens = h[1] * lum->n_lamps;
    } else {
        return lx__error(ctx, LX_EPARSE, file, hline,
                         "lumens per lamp must be positive or -1 (absolute photometry), got %g", h[1]);
    }
    if (!(h[2] > 0))
        return lx__error(ctx, LX_EPARSE, file, hline, "the candela multiplier must be positive (got %g)", h[2]);
    lum->multiplier = h[2];
    for (int i = 3; i <= 4; i++)
        if (h[i] != floor(h[i]) || h[i] < 1 || h[i] > LX__IES_MAX_ANGLES)
            return lx__error(ctx, LX_EPARSE, file, hline, "%s must be a whole number from 1 to %d (got %g)",
                             count_names[i], LX__IES_MAX_ANGLES, h[i]);
    lum->n_v = (size_t)h[3];
    lum->n_h = (size_t)h[4];
    if (h[5] == 3)
        return lx__error(ctx, LX_EUNSUPPORTED, file, hline, "type A photometry (photometric type 3) is not supported");
    if (h[5] != 1 && h[5] != 2)
        return lx__error(ctx, LX_EPARSE, file, hline, "the photometric type must be 1 (C), 2 (B) or 3 (A), got %g",
                         h[5]);
    lum->photometric_type = (int)h[5];
    if (h[6] != 1 && h[6] != 2)
        return lx__error(ctx, LX_EPARSE, file, hline, "the units type must be 1 (feet) or 2 (metres), got %g", h[6]);
    double unit = h[6] == 1 ? 0.3048 : 1.0;
    /* LM-63: the width is measured along the 90-270 degree photometric plane, the length along
     * 0-180 (negative values: round shapes) */
    lum->width_m = h[7] * unit;
    lum->length_m = h[8] * unit;
    lum->height_m = h[9] * unit;
    return LX_OK;
}

/* Checks the second line of numbers b (errors name line) and stores it in lum; *scale: the factor
 * every candela value is multiplied by (multiplier x ballast factor, x the ballast-lamp factor up
 * to LM-63-1995). */
static lx_status apply_ballast(lx_ctx *ctx, const char *file, long line, const double b[3], lx_luminaire *lum,
                               double *scale)
{
    if (!(b[0] > 0)) return lx__error(ctx, LX_EPARSE, file, line, "the ballast factor must be positive (got %g)", b[0]);
    lum->ballast_factor = b[0];
    lum->input_watts = b[2];
    *scale = lum->multiplier * lum->ballast_factor;
    if (lum->format == LX_LUM_LM63_2019) {
        /* the field is the file generation type (1.00001 ... 1.10100): it scales nothing */
        lum->file_generation_type = (int)lround(b[1] * 100000.0) - 100000;
        lum->ballast_lamp_factor = NAN;
    } else {
        lum->ballast_lamp_factor = b[1];
        if (lum->format <= LX_LUM_LM63_1995) {
            if (!(b[1] > 0))
                return lx__error(ctx, LX_EPARSE, file, line,
                                 "the ballast-lamp photometric factor must be positive (got %g)", b[1]);
            *scale *= b[1];
        }
    }
    return LX_OK;
}

/* The candela values, plane after plane, times scale; none negative. */
static lx_status read_candela(lx_ctx *ctx, const char *file, toks *t, long last, double scale, lx_luminaire *lum)
{
    size_t nv = lum->n_v, nh = lum->n_h;
    lx_status st;
    for (size_t i = 0; i < nh; i++)
        for (size_t j = 0; j < nv; j++) {
            double v = 0;
            char what[160];
            snprintf(what, sizeof what, "the end of the candela table (plane %zu of %zu, value %zu of %zu)", i + 1, nh,
                     j + 1, nv);
            if ((st = take(ctx, file, t, last, what, &v))) return st;
            if (v < 0)
                return lx__error(ctx, LX_EPARSE, file, tok_line(t, last),
                                 "negative candela value %g (plane %zu, angle %zu)", v, i + 1, j + 1);
            lum->cd[i * nv + j] = v * scale;
        }
    return LX_OK;
}

/* The vertical angles, the horizontal angles and the candela table, the counts checked against the
 * numbers there before anything is sized by them; line_v, line_h, line_cd: where each starts. */
static lx_status read_table(lx_ctx *ctx, const char *file, toks *t, long last, double scale, lx_luminaire *lum,
                            long *line_v, long *line_h, long *line_cd)
{
    size_t nv = lum->n_v, nh = lum->n_h;
    if (t->n - t->pos < nv + nh + nv * nh)
        return lx__error(ctx, LX_EPARSE, file, last,
                         "the file ends before the end of the candela table: %zu vertical x %zu horizontal angles "
                         "need %zu numbers, the file has %zu (truncated table or counts that lie)",
                         nv, nh, nv + nh + nv * nh, t->n - t->pos);
    lum->v_deg = lx__alloc_n(nv, sizeof(double));
    lum->h_deg = lx__alloc_n(nh, sizeof(double));
    lum->cd = lx__alloc_n(nv * nh, sizeof(double));
    if (!lum->v_deg || !lum->h_deg || !lum->cd) return lx__error(ctx, LX_ENOMEM, file, last, "out of memory");
    lx_status st;
    *line_v = t->pos < t->n ? t->line[t->pos] : last;
    for (size_t i = 0; i < nv; i++)
        if ((st = take(ctx, file, t, last, "the end of the vertical angles", &lum->v_deg[i]))) return st;
    *line_h = t->pos < t->n ? t->line[t->pos] : last;
    for (size_t i = 0; i < nh; i++)
        if ((st = take(ctx, file, t, last, "the end of the horizontal angles", &lum->h_deg[i]))) return st;
    *line_cd = t->pos < t->n ? t->line[t->pos] : last;
    if ((st = read_candela(ctx, file, t, last, scale, lum))) return st;
    if (t->pos < t->n)
        return lx__error(ctx, LX_EPARSE, file, t->line[t->pos],
                         "%zu numbers more than the counts (%zu vertical x %zu horizontal) ask for", t->n - t->pos,
                         nv, nh);
    return LX_OK;
}

/* After the TILT= line: the numbers to the end of the text (an INCLUDE tilt block, the two lines
 * of counts and factors, the table), checked and expanded. */
static lx_status read_numbers(lx_ctx *ctx, const char *file, lx__lines *it, lx_luminaire *lum, toks *t)
{
    lx_status st = tokenize(ctx, file, it, t);
    if (st) return st;
    long last = it->line;
    if (lum->tilt_include == 2 && (st = read_tilt(ctx, file, t, last, lum))) return st;
    double h[10], b[3], scale = 1;
    long hline = 0, line_v = 0, line_h = 0, line_cd = 0;
    if ((st = take_counts(ctx, file, t, last, h, b, &hline))) return st;
    if ((st = apply_counts(ctx, file, hline, h, lum))) return st;
    if ((st = apply_ballast(ctx, file, tok_line(t, last), b, lum, &scale))) return st;
    if ((st = read_table(ctx, file, t, last, scale, lum, &line_v, &line_h, &line_cd))) return st;
    return lx__lum_finish(ctx, lum, line_h, line_v, line_cd);
}

lx_status lx__ies_read(lx_ctx *ctx, const char *file, const char *text, size_t len, lx_luminaire **out)
{
    *out = NULL;
    lx_luminaire *lum = lx__lum_new(file);
    if (!lum) return lx__error(ctx, LX_ENOMEM, file, 0, "out of memory");
    toks t = {0};
    lx__lines it = {text, text + len, 0};
    if (len >= 3 && (unsigned char)text[0] == 0xEF && (unsigned char)text[1] == 0xBB && (unsigned char)text[2] == 0xBF)
        it.p += 3;
    long tilt = 0;
    lx_status st = read_header(ctx, file, &it, lum, &tilt);
    if (!st && !tilt) st = lx__error(ctx, LX_EPARSE, file, it.line, "no TILT= line: not an IES LM-63 file");
    if (!st) st = read_numbers(ctx, file, &it, lum, &t);
    lx__free(t.v);
    lx__free(t.line);
    if (st) {
        lx_luminaire_free(lum);
        return st;
    }
    *out = lum;
    return LX_OK;
}
