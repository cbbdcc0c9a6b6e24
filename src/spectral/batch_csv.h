/* batch_csv.h - what the batch CSV reader (batch_csv.c) shares with its streamed form
 * (batch_stream.c): a part of the text parsed by one thread, the header, the parser. */
#ifndef LX_BATCH_CSV_H
#define LX_BATCH_CSV_H

#include "spectral/spectral_private.h"

typedef struct lx__csv_part {
    const char *s, *e;   /* whole lines */
    size_t rows, lines;  /* data rows and all lines in the part (pass 1) */
    size_t row0;         /* first row index (pass 2) */
    long line0;          /* line number of its first line */
    const char *lim;     /* end of the readable text (for 8-byte loads) */
    size_t rows_cap;     /* rows the part's destination and name_at can hold */
    void *values;        /* the destination of its first row (pass 2) */
    size_t rows_done;    /* rows parsed (pass 2) */
    long lines_done;     /* lines consumed before stopping (pass 2; the bad line on error) */
    /* pass 2 */
    const lx_batch_table *t;
    char sep;
    int named;           /* rows start with a name cell */
    char *names;         /* this part's names, NUL-separated */
    size_t names_len, names_cap, name_at_cap;
    size_t *name_at;     /* local offsets */
    long err_line;       /* 0: no error */
    char err[256];
} lx__csv_part;

/* The header: the first line that is not blank or a comment; its separator, whether rows start
 * with a name cell, and the uniform grid. body: the text after it, line: its line number. */
typedef struct lx__csv_header {
    const char *body;
    long line;
    char sep;
    int named;
    size_t n;
    double start, step;
} lx__csv_header;

/* The end of the line at s (its '\n', or end), or NULL when it is longer than LX__BATCH_LINE_MAX
 * bytes (without its '\n'): the search never looks further than that. */
const char *lx__csv_line_end(const char *s, const char *end);
/* The LX_EPARSE of a line longer than LX__BATCH_LINE_MAX, naming file and line. */
lx_status lx__csv_line_too_long(lx_ctx *ctx, const char *file, long line);
/* Reads the header from text[0, len) (errors name file and line). */
lx_status lx__csv_read_header(lx_ctx *ctx, const char *file, const char *text, size_t len, lx__csv_header *H);
/* Parses the rows of part p (pass 2): values, names, rows_done, lines_done, or err_line and err. */
void lx__csv_parse_part(lx__csv_part *p);

#endif /* LX_BATCH_CSV_H */
