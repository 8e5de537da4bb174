/* servo_bc: checked conversions used by every parser of the project (the
 * servo_bc words, the runner's script, the hosts' contact words). `what`
 * names the value in the error message. */
#ifndef SBC_NUMBERS_H
#define SBC_NUMBERS_H

#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* a finite double, the whole word */
sbc_status sbc_parse_real(const char *word, const char *what, double *out, sbc_error *err);

/* an integer in [lo, hi], the whole word */
sbc_status sbc_parse_int(const char *word, const char *what, long lo, long hi, long *out, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
