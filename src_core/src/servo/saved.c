/* servo_bc: checked reads of saved state (saved.h). */
#include "sbc/saved.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

void sbc_saved_start(sbc_saved *s, const double *in, size_t n, const char *what, sbc_error *err)
{
    s->in = in;
    s->at = 0;
    s->n = n;
    s->what = what;
    s->err = err;
    s->st = SBC_OK;
}

/* the next value, or 0 with the failure recorded when there is none */
static int next(sbc_saved *s, const char *name, double *v)
{
    if (s->st != SBC_OK)
        return 0;
    if (s->at >= s->n) {
        s->st = sbc_fail(s->err, SBC_ERR_INPUT, "%s: ends before '%s' (value %zu of %zu)", s->what, name, s->at + 1,
                         s->n);
        return 0;
    }
    *v = s->in[s->at++];
    return 1;
}

long sbc_saved_int(sbc_saved *s, const char *name, long lo, long hi)
{
    double v;
    if (!next(s, name, &v))
        return 0;
    if (!(v >= (double)lo && v <= (double)hi) || v != floor(v)) {
        s->st = sbc_fail(s->err, SBC_ERR_INPUT, "%s: '%s' (value %zu) is %.17g (expected an integer from %ld to %ld)",
                         s->what, name, s->at, v, lo, hi);
        return 0;
    }
    return (long)v;
}

double sbc_saved_real(sbc_saved *s, const char *name)
{
    double v;
    if (!next(s, name, &v))
        return 0.0;
    if (!isfinite(v)) {
        s->st = sbc_fail(s->err, SBC_ERR_INPUT, "%s: '%s' (value %zu) is %g (expected a finite number)", s->what, name,
                         s->at, v);
        return 0.0;
    }
    return v;
}

double sbc_saved_positive(sbc_saved *s, const char *name)
{
    const double v = sbc_saved_real(s, name);
    if (s->st == SBC_OK && !(v > 0.0)) {
        s->st = sbc_fail(s->err, SBC_ERR_INPUT, "%s: '%s' (value %zu) is %.17g (expected a number > 0)", s->what, name,
                         s->at, v);
        return 0.0;
    }
    return v;
}

/* FNV-1a over size bytes from the basis h, folded to 52 bits */
static double hash_bytes(const unsigned char *b, size_t size, uint64_t h)
{
    size_t i;
    for (i = 0; i < size; ++i)
        h = (h ^ b[i]) * 1099511628211ULL;
    return (double)((h ^ (h >> 52)) & ((1ULL << 52) - 1));
}

static double hash_of(const double *v, size_t n, uint64_t h) { return hash_bytes((const unsigned char *)v, sizeof(double) * n, h); }

#define SEAL_BASIS 0x6a09e667f3bcc908ULL     /* of the length */
#define CHECKSUM_BASIS 0xcbf29ce484222325ULL /* of the payload (FNV's own) */

void sbc_saved_seal(double *block, size_t n)
{
    block[0] = (double)n;
    block[1] = hash_of(block, 1, SEAL_BASIS);
    block[2] = hash_of(block + SBC_SEALED_HEAD, n - SBC_SEALED_HEAD, CHECKSUM_BASIS);
}

sbc_status sbc_saved_open(const double *in, size_t most, size_t *n, const char *what, sbc_error *err)
{
    const double hi = most < 1e15 ? (double)most : 1e15;
    if (!(in[0] >= SBC_SEALED_HEAD && in[0] <= hi) || in[0] != floor(in[0]))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: its length is %.17g (expected an integer from %d to %.0f): the "
                        "block is corrupted or not this version's", what, in[0], SBC_SEALED_HEAD, hi);
    if (in[1] != hash_of(in, 1, SEAL_BASIS))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: its length %.17g does not match its seal %.17g: the block is "
                        "corrupted", what, in[0], in[1]);
    *n = (size_t)in[0];
    if (in[2] != hash_of(in + SBC_SEALED_HEAD, *n - SBC_SEALED_HEAD, CHECKSUM_BASIS))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: its %zu values do not match their checksum %.17g: a value was "
                        "changed after it was written", what, *n - SBC_SEALED_HEAD, in[2]);
    return SBC_OK;
}

double sbc_saved_hash(const void *data, size_t bytes, double from)
{
    return hash_bytes(data, bytes, CHECKSUM_BASIS ^ (uint64_t)from);
}
