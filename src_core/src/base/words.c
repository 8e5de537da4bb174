#include "words.h"

#include <string.h>

static int blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

int sbc_split_words(char *line, char **words, int max)
{
    char *hash = strchr(line, '#'), *p = line;
    int n = 0;
    if (hash)
        *hash = '\0';
    for (;;) {
        while (*p && blank(*p))
            ++p;
        if (!*p)
            break;
        if (n < max)
            words[n] = p;
        ++n;
        while (*p && !blank(*p))
            ++p;
        if (*p)
            *p++ = '\0';
    }
    return n;
}
