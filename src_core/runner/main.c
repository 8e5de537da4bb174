/* servo-bc: the embedded runner. Usage: servo-bc SCRIPT */
#include "sbc/script.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    sbc_error err;
    if (argc != 2 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0) {
        fprintf(stderr, "usage: servo-bc SCRIPT\n");
        return argc == 2 ? 0 : 2;
    }
    if (sbc_script_run_file(argv[1], stdout, &err) != SBC_OK) {
        fflush(stdout);
        fprintf(stderr, "ERROR: %s\n", err.message);
        return 1;
    }
    return 0;
}
