#include "sbc/contact.h"

sbc_frictional sbc_frictional_default(void)
{
    sbc_frictional law;
    law.kn = 1.0e4; /* N/m, Table 4 */
    law.ks = 2.0e3; /* N/m, Table 4 */
    law.mu = 0.4;   /* Table 4 */
    return law;
}
