/* servo_bc: checked conversions of words to numbers (numbers.h). */
#include "sbc/numbers.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

sbc_status sbc_parse_real(const char *word, const char *what, double *out, sbc_error *err)
{
    char *end = NULL;
    double v;
    errno = 0;
    v = strtod(word, &end);
    if (end == word || *end != '\0')
        return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' is not a number", what, word);
    if (errno == ERANGE || !isfinite(v))
        return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' is out of the range of a double", what, word);
    *out = v;
    return SBC_OK;
}

sbc_status sbc_parse_int(const char *word, const char *what, long lo, long hi, long *out, sbc_error *err)
{
    char *end = NULL;
    long v;
    errno = 0;
    v = strtol(word, &end, 10);
    if (end == word || *end != '\0')
        return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' is not an integer", what, word);
    if (errno == ERANGE || v < lo || v > hi)
        return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' is out of range (expected %ld to %ld)", what, word, lo, hi);
    *out = v;
    return SBC_OK;
}
