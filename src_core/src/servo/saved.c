/* servo_bc: checked reads of saved state (saved.h). */
#include "sbc/saved.h"

#include <math.h>

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
