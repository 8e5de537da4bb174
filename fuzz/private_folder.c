#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"

#include <unistd.h>

void fuzz_private_folder(void)
{
    static int done;
    char dir[] = "/tmp/servo_bc_fuzz_XXXXXX";
    if (done)
        return;
    done = 1;
    if (!mkdtemp(dir) || chdir(dir) != 0) {
        perror("fuzz: private folder");
        abort();
    }
}
