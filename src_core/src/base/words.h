/* Private: splitting a line into words. */
#ifndef SBC_WORDS_H
#define SBC_WORDS_H

/* Cuts line at the first '#', splits the rest in place on blanks and stores
 * up to max word pointers; returns the number of words found (which may
 * exceed max: the extra words are not stored). */
int sbc_split_words(char *line, char **words, int max);

#endif
