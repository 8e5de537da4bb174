/* The update rules' table (update_rules.h). Their functions are the
 * controller's (controller_update.c). */
#include "update_rules.h"

#include "controller_private.h"

#include <stdio.h>
#include <string.h>

static const sbc_update_rule rules[] = {
    /* the paper's: gains of Table 4 per time step (eqs. 33, 34, 36, 48) */
    {SBC_UPDATE_FIXED, "fixed", 0, 0, 0, NULL, NULL},
    /* those corrections scaled by a Barzilai-Borwein factor (controller_update.c) */
    {SBC_UPDATE_SECANT, "secant", 1, 1, 1, sbc_ctl_secant_scale, sbc_ctl_secant_start},
    /* the host's Newton correction from its linearized contact network (controller_update.c) */
    {SBC_UPDATE_NEWTON, "newton", 1, 1, 1, sbc_ctl_newton_scale, sbc_ctl_newton_start},
};

enum { RULES = (int)(sizeof rules / sizeof rules[0]) };

const sbc_update_rule *sbc_update_rule_of(sbc_update id)
{
    int k;
    for (k = 0; k < RULES; ++k)
        if (rules[k].id == id)
            return &rules[k];
    return NULL;
}

const sbc_update_rule *sbc_update_rule_named(const char *name)
{
    int k;
    for (k = 0; k < RULES; ++k)
        if (strcmp(rules[k].name, name) == 0)
            return &rules[k];
    return NULL;
}

void sbc_update_rule_names(char *out, size_t cap)
{
    size_t used = 0;
    int k;
    if (cap == 0)
        return;
    out[0] = '\0';
    for (k = 0; k < RULES && used < cap; ++k)
        used += (size_t)snprintf(out + used, cap - used, "%s%s", k == 0 ? "" : k == RULES - 1 ? " or " : ", ",
                                 rules[k].name);
}
