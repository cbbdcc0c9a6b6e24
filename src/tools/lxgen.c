/* lxgen.c - build-time generator: turns the CIE tables (the CSV files of src/data) and the OpenCL kernels
 * (the .cl files of kernels/) into C source, so the library needs no files at run time.
 * Usage: lxgen tables OUT.c FILE.csv...   |   lxgen kernels OUT.c FILE.cl... */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void die(const char *file, long line, const char *what)
{
    fprintf(stderr, "lxgen: %s:%ld: %s\n", file, line, what);
    exit(1);
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) die(path, 0, "cannot open");
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap + 1);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) buf = realloc(buf, (cap *= 2) + 1);
    }
    fclose(f);
    if (!buf) die(path, 0, "out of memory");
    buf[n] = 0;
    *len = n;
    return buf;
}

static void c_string(FILE *out, const char *s, size_t len)
{
    fputc('"', out);
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '\n') {
            fputs("\\n\"\n    \"", out);
        } else if (c == '\\' || c == '"') {
            fputc('\\', out);
            fputc(c, out);
        } else if (c < 32 || c >= 127) {
            fprintf(out, "\\%03o", c);
        } else {
            fputc(c, out);
        }
    }
    fputc('"', out);
}

static const char *stem(const char *path, char *buf, size_t cap)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    snprintf(buf, cap, "%s", b);
    char *dot = strrchr(buf, '.');
    if (dot) *dot = 0;
    for (char *p = buf; *p; p++)
        if (!isalnum((unsigned char)*p)) *p = '_';
    return buf;
}

static void gen_table(FILE *out, const char *path, int index)
{
    size_t len;
    char *text = slurp(path, &len);
    char name[256];
    stem(path, name, sizeof name);
    /* provenance: the '#' lines, verbatim */
    fprintf(out, "/* %s */\nstatic const char prov_%d[] = ", path, index);
    char *p = text;
    size_t provlen = 0;
    while (p[provlen] == '#') {
        char *nl = strchr(p + provlen, '\n');
        provlen = nl ? (size_t)(nl - p) + 1 : len;
    }
    c_string(out, p, provlen);
    fputs(";\n", out);
    p += provlen;
    /* header */
    char *nl = strchr(p, '\n');
    if (!nl) die(path, 0, "no header line");
    *nl = 0;
    int ncols = 0;
    fprintf(out, "static const char *const cols_%d[] = {", index);
    for (char *tok = p;; ncols++) {
        char *comma = strchr(tok, ',');
        if (comma) *comma = 0;
        char *cr = strchr(tok, '\r');
        if (cr) *cr = 0;
        fprintf(out, "\"%s\", ", tok);
        if (!comma) break;
        tok = comma + 1;
    }
    ncols++;
    fputs("};\n", out);
    /* rows, then transposed into column-major order */
    size_t cap = 1024, nrows = 0;
    char **cells = malloc(cap * ncols * sizeof *cells);
    long lineno = 1;
    for (char *q = text; q < p; q++) lineno += *q == '\n';
    for (p = nl + 1; *p; lineno++) {
        nl = strchr(p, '\n');
        if (nl) *nl = 0;
        char *cr = strchr(p, '\r');
        if (cr) *cr = 0;
        if (*p) {
            if (nrows == cap) cells = realloc(cells, (cap *= 2) * ncols * sizeof *cells);
            int c = 0;
            for (char *tok = p;; c++) {
                char *comma = strchr(tok, ',');
                if (comma) *comma = 0;
                if (c >= ncols) die(path, lineno, "too many fields");
                cells[nrows * ncols + c] = tok;
                if (!comma) break;
                tok = comma + 1;
            }
            if (c + 1 != ncols) die(path, lineno, "too few fields");
            nrows++;
        }
        if (!nl) break;
        p = nl + 1;
    }
    fprintf(out, "static const double data_%d[] = {\n", index);
    for (int c = 0; c < ncols; c++) {
        for (size_t r = 0; r < nrows; r++) {
            const char *cell = cells[r * ncols + c];
            char *end;
            strtod(cell, &end);
            if (!*cell)
                fputs("NAN,", out);
            else if (*end || end == cell)
                die(path, (long)r, "not a number");
            else
                fprintf(out, "%s,", cell);
            fputc((r % 8 == 7) ? '\n' : ' ', out);
        }
        fputc('\n', out);
    }
    fputs("};\n", out);
    fprintf(out, "#define TABLE_%d {\"%s\", prov_%d, %zu, %d, cols_%d, data_%d}\n\n", index, name, index,
            nrows, ncols, index, index);
    free(cells);
    free(text);
}

int main(int argc, char **argv)
{
    if (argc < 3 || (strcmp(argv[1], "tables") && strcmp(argv[1], "kernels"))) {
        fprintf(stderr, "usage: lxgen tables|kernels OUT.c FILE...\n");
        return 1;
    }
    int tables = !strcmp(argv[1], "tables");
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp", argv[2]);
    FILE *out = fopen(tmp, "w");
    if (!out) die(tmp, 0, "cannot create");
    fputs("/* Generated by src/tools/lxgen.c from", out);
    for (int i = 3; i < argc; i++) fprintf(out, " %s", argv[i]);
    fprintf(out, ". Do not edit. */\n#include \"%s\"\n#include <math.h>\n\n",
            tables ? "tables/tables_private.h" : "core/core_private.h");
    int n = argc - 3;
    if (tables) {
        for (int i = 0; i < n; i++) gen_table(out, argv[3 + i], i);
        fputs("const lx__table lx__tables[] = {\n", out);
        for (int i = 0; i < n; i++) fprintf(out, "    TABLE_%d,\n", i);
        fprintf(out, "};\nconst int lx__ntables = %d;\n", n);
    } else {
        fputs("const lx__kernel_source lx__kernel_sources[] = {\n", out);
        for (int i = 0; i < n; i++) {
            size_t len;
            char *text = slurp(argv[3 + i], &len);
            const char *base = strrchr(argv[3 + i], '/');
            fprintf(out, "    {\"%s\",\n    ", base ? base + 1 : argv[3 + i]);
            c_string(out, text, len);
            fputs("},\n", out);
            free(text);
        }
        if (n == 0) fputs("    {NULL, NULL},\n", out);
        fprintf(out, "};\nconst int lx__nkernel_sources = %d;\n", n);
    }
    if (fclose(out) != 0 || rename(tmp, argv[2]) != 0) die(argv[2], 0, "cannot write");
    return 0;
}
