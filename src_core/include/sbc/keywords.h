/* servo_bc: the keyword registry of the servo_bc words, one table (names,
 * values, meaning, default) that the parser's "unknown keyword" message, the
 * keyword table of docs/servo_bc.md (`servo-bc --keywords`) and the
 * keyword lists of the LAMMPS and LIGGGHTS fix pages follow
 * (tests/tables.sh compares them). A new keyword is a row here, its branch
 * in settings.c, and a line in the fix pages. */
#ifndef SBC_KEYWORDS_H
#define SBC_KEYWORDS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_keyword {
    const char *names;    /* one keyword, or several that share the row, separated by spaces */
    const char *values;   /* what follows it (Markdown) */
    const char *meaning;  /* (Markdown) */
    const char *fallback; /* the default (Markdown) */
} sbc_keyword;

#define SBC_KEYWORDS 24
extern const sbc_keyword sbc_keywords[SBC_KEYWORDS];

/* Every keyword name, "F, increments, ... or file", into out [cap]; returns
 * its length (as snprintf). */
int sbc_keywords_list(char *out, size_t cap);

#ifdef __cplusplus
}
#endif

#endif
