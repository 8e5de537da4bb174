// Every public header of the core in one C++ translation unit, with no
// extern "C" wrapper of its own: the headers carry their guards, and the
// library links from C++ (make check-core builds and runs this). Checks a few
// calls through the C ABI. Prints "N passed, N failed".
#include "sbc/bpm.h"
#include "sbc/bpm_bond.h"
#include "sbc/bpm_host.h"
#include "sbc/embedded/bpm_loading.h"
#include "sbc/embedded/bpm_packing.h"
#include "sbc/embedded/bpm_stress.h"
#include "sbc/embedded/bpm_vtk.h"
#include "sbc/cohesive_host.h"
#include "sbc/confine.h"
#include "sbc/contact.h"
#include "sbc/controller.h"
#include "sbc/embedded/engine.h"
#include "sbc/fire_damping.h"
#include "sbc/frame.h"
#include "sbc/embedded/generate.h"
#include "sbc/homogenize.h"
#include "sbc/host.h"
#include "sbc/embedded/network.h"
#include "sbc/embedded/output_file.h"
#include "sbc/packing.h"
#include "sbc/embedded/plot.h"
#include "sbc/relax.h"
#include "sbc/results.h"
#include "sbc/saved.h"
#include "sbc/embedded/script.h"
#include "sbc/seal.h"
#include "sbc/settings.h"
#include "sbc/status.h"
#include "sbc/time_step.h"
#include "sbc/version.h"
#include "sbc/embedded/vtk.h"

#include <cstdio>
#include <cstring>

int main()
{
    int pass = 0, fail = 0;
    auto check = [&](bool ok, const char *what) {
        if (ok) {
            ++pass;
            std::printf("c++ headers: %s\n", what);
        } else {
            ++fail;
            std::printf("FAIL c++ headers: %s\n", what);
        }
    };
    check(std::strcmp(sbc_version(), SBC_VERSION) == 0, "sbc_version() is SBC_VERSION");
    sbc_settings s;
    sbc_error err;
    const char *words[] = {"P", "F", "1", "0.01", "0", "1", "increments", "3"};
    check(sbc_settings_parse(&s, 8, words, &err) == SBC_OK && s.bc == SBC_BC_P &&
              sbc_settings_total_increments(&s) == 3,
          "sbc_settings_parse reads (P) in 3 increments");
    const char *bad[] = {"Q"};
    check(sbc_settings_parse(&s, 1, bad, &err) == SBC_ERR_INPUT && std::strstr(err.message, "'Q'") != nullptr,
          "sbc_settings_parse refuses 'Q' with the core's message");
    std::printf("%d passed, %d failed\n", pass, fail);
    return fail != 0;
}
