/* lines.c - the line cursor every text reader walks its file with (LF or CRLF endings, lines
 * counted from 1) and copies of byte ranges as strings. */
#include "core/core_private.h"

#include <stdlib.h>
#include <string.h>

int lx__next_line(lx__lines *it, const char **s, const char **e)
{
    if (it->p >= it->end) return 0;
    const char *nl = memchr(it->p, '\n', (size_t)(it->end - it->p));
    const char *le = nl ? nl : it->end;
    *s = it->p;
    if (le > it->p && le[-1] == '\r') le--;
    *e = le;
    it->p = nl ? nl + 1 : it->end;
    it->line++;
    return 1;
}

char *lx__strndup(const char *s, const char *e)
{
    size_t n = (size_t)(e - s);
    char *r = lx__alloc(n + 1);
    if (!r) return NULL;
    memcpy(r, s, n);
    r[n] = '\0';
    return r;
}
