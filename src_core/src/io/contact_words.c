/* The cohesive law's words (contact.h, sbc_cohesive_parse): one grammar for
 * the runner's `contact cohesive` and every host's `servo_bc/bonds cohesive`. */
#include "sbc/contact.h"
#include "sbc/settings.h"

#include <string.h>

static const char usage[] = "kn KN ks KS kr KR fn FN fs FS mr MR mu MU";

sbc_status sbc_cohesive_parse(int nw, char *const *w, const char *cmd, sbc_cohesive *law, sbc_error *err)
{
    static const char *key[7] = {"kn", "ks", "kr", "fn", "fs", "mr", "mu"};
    /* kn and the strengths > 0 (eq. 8 divides by them), ks, kr, mu >= 0 */
    static const int positive[7] = {1, 0, 0, 1, 1, 1, 0};
    double value[7];
    int k;
    if (nw < 14)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: missing values (expected '%s')", cmd, usage);
    if (nw > 14)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: unexpected extra value '%s' (expected '%s')", cmd, w[14], usage);
    for (k = 0; k < 7; ++k) {
        const char *word = w[2 * k + 1];
        if (strcmp(w[2 * k], key[k]) != 0)
            return sbc_fail(err, SBC_ERR_INPUT, "%s: expected keyword '%s' but found '%s' (usage '%s')", cmd, key[k],
                            w[2 * k], usage);
        if (sbc_parse_real(word, key[k], &value[k], NULL) != SBC_OK)
            return sbc_fail(err, SBC_ERR_INPUT, "%s: %s '%s' is not a number (expected a real %s)", cmd, key[k], word,
                            positive[k] ? "> 0" : ">= 0");
        if (positive[k] ? !(value[k] > 0.0) : !(value[k] >= 0.0))
            return sbc_fail(err, SBC_ERR_INPUT, "%s: %s '%s' is not valid (expected a real %s)", cmd, key[k], word,
                            positive[k] ? "> 0" : ">= 0");
    }
    law->kn = value[0];
    law->ks = value[1];
    law->kr = value[2];
    law->fn_u = value[3];
    law->fs_u = value[4];
    law->m_u = value[5];
    law->mu = value[6];
    return SBC_OK;
}
