/* servo_bc: the library's version (version.h). */
#include "sbc/version.h"

const char *sbc_version(void) { return SBC_VERSION; }
