/* servo_bc: opening an output file, creating the folders of its path that
 * do not exist yet (as `mkdir -p`), so that `file out/run1/P.csv` works in a
 * fresh folder. */
#ifndef SBC_OUTPUT_FILE_H
#define SBC_OUTPUT_FILE_H

#include <stdio.h>

/* fopen(path, "w") after creating the missing parent folders; NULL (errno
 * set) when a folder cannot be made or the file cannot be opened. */
FILE *sbc_output_open(const char *path);

/* Creates the folder path and its missing parents; 0 on success. */
int sbc_output_folder(const char *path);

#endif
