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

/* A sealed block: [n, seal of n, checksum, payload ...], n values in all.
 * A host's restart buffer comes without its size (LAMMPS and LIGGGHTS pass
 * a bare pointer), so the length cannot be checked against the buffer: the
 * seal, a hash of n, refuses a changed length before any value past the head
 * is read, and the checksum, a hash of the payload's bytes, refuses a
 * changed value anywhere after it. Both are integers below 2^52, exact in a
 * double. SBC_SEALED_HEAD values precede the payload. */
#define SBC_SEALED_HEAD 3

/* A hash of bytes (FNV-1a folded to 52 bits, exact in a double), chained:
 * from is 0 or the hash of what came before. */
double sbc_saved_hash(const void *data, size_t bytes, double from);

/* Writes the head of block [n] (its payload already in place). */
void sbc_saved_seal(double *block, size_t n);

/* Checks the head and the checksum of the sealed block at in, which holds at
 * most `most` values (SIZE_MAX where the host does not say); *n: its length.
 * The message names what and the value that fails. */
sbc_status sbc_saved_open(const double *in, size_t most, size_t *n, const char *what, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
