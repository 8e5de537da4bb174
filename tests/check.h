/* Minimal test harness: counts checks, prints failures with file and line. */
#ifndef SBC_TEST_CHECK_H
#define SBC_TEST_CHECK_H

#include <math.h>
#include <stdio.h>

extern int check_passed, check_failed;
extern const char *test_tmpdir;  /* scratch directory for files */
extern const char *test_runner;  /* path of the servo-bc executable */

/* 1 when a line of the file at path contains needle. */
int file_contains(const char *path, const char *needle);

/* 1 when the files at a and b hold the same bytes (both readable). */
int same_bytes(const char *a, const char *b);

#define CHECK(cond)                                                                          \
    do {                                                                                     \
        if (cond) {                                                                          \
            ++check_passed;                                                                  \
        } else {                                                                             \
            ++check_failed;                                                                  \
            printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond);                           \
        }                                                                                    \
    } while (0)

/* |a - b| <= rel * |b| (or <= rel when b == 0) */
#define CHECK_REL(a, b, rel)                                                                 \
    do {                                                                                     \
        double a_ = (a), b_ = (b), tol_ = (rel) * (fabs(b_) > 0.0 ? fabs(b_) : 1.0);          \
        if (fabs(a_ - b_) <= tol_) {                                                         \
            ++check_passed;                                                                  \
        } else {                                                                             \
            ++check_failed;                                                                  \
            printf("FAIL %s:%d: %s = %.17g, expected %s = %.17g (rel. tol %g)\n", __FILE__,  \
                   __LINE__, #a, a_, #b, b_, (double)(rel));                                 \
        }                                                                                    \
    } while (0)

#define CHECK_ABS(a, b, tol)                                                                 \
    do {                                                                                     \
        double a_ = (a), b_ = (b);                                                           \
        if (fabs(a_ - b_) <= (tol)) {                                                        \
            ++check_passed;                                                                  \
        } else {                                                                             \
            ++check_failed;                                                                  \
            printf("FAIL %s:%d: %s = %.17g, expected %s = %.17g (abs. tol %g)\n", __FILE__,  \
                   __LINE__, #a, a_, #b, b_, (double)(tol));                                 \
        }                                                                                    \
    } while (0)

/* a 2D tensor [a b; c d] in the core's 3 x 3 slots (sbc/tensor.h) */
#define TENSOR2(a, b, c, d) {(a), (b), 0.0, (c), (d), 0.0, 0.0, 0.0, 0.0}

#endif
