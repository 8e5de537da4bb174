/* servo_bc: reading saved state (restart data) with every value checked.
 * Restart files come from disk and may be truncated, corrupted or written by
 * another version: no value is cast, used as an index or trusted as a count
 * before it has been checked against what it may be. The first failure
 * sticks (st, and the message in err names the value and what was expected);
 * later reads return 0. Hosts read their own restart fields with it too. */
#ifndef SBC_SAVED_H
#define SBC_SAVED_H

#include <stddef.h>

#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_saved {
    const double *in;
    size_t at, n;
    const char *what; /* "frame restart data", "servo_bc restart state" */
    sbc_error *err;
    sbc_status st;
} sbc_saved;

void sbc_saved_start(sbc_saved *s, const double *in, size_t n, const char *what, sbc_error *err);

/* The next value as an integer in [lo, hi]. */
long sbc_saved_int(sbc_saved *s, const char *name, long lo, long hi);

/* The next value, finite. */
double sbc_saved_real(sbc_saved *s, const char *name);

/* The next value, finite and > 0. */
double sbc_saved_positive(sbc_saved *s, const char *name);

#ifdef __cplusplus
}
#endif

#endif
