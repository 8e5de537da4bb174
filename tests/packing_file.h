/* Test helper: a generated packing written once per run of the tests. */
#ifndef SBC_TEST_PACKING_FILE_H
#define SBC_TEST_PACKING_FILE_H

#include <stddef.h>

/* The packing of the script lines `generate` ("dimension ...\ngenerate ...\n") written as text to
 * test_tmpdir/name.txt, its path in path; generated only while *made is 0 (then set). 1 on success. */
int packing_file(const char *name, const char *generate, char *path, size_t cap, int *made);

#endif
