/* servo-bc: the checks every script command makes of its words
 * (script_state.h). */
#include "script_state.h"

#include <string.h>

sbc_status sbc_script_expect_count(int nw, char **w, int want, const char *usage, sbc_error *err)
{
    if (nw < want)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: missing values (expected '%s')", w[0], usage);
    if (nw > want)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: unexpected extra value '%s' (expected '%s')", w[0], w[want], usage);
    return SBC_OK;
}

sbc_status sbc_script_expect_key(const char *cmd, const char *word, const char *key, const char *usage, sbc_error *err)
{
    if (strcmp(word, key) != 0)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: expected keyword '%s' but found '%s' (usage '%s')", cmd, key, word,
                        usage);
    return SBC_OK;
}

sbc_status sbc_script_positive(const char *cmd, const char *what, const char *word, double *out, sbc_error *err)
{
    if (sbc_parse_real(word, what, out, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: %s '%s' is not a number (expected a real > 0)", cmd, what, word);
    if (!(*out > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: %s %s is not positive (expected a real > 0)", cmd, what, word);
    return SBC_OK;
}
