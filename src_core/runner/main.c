/* servo-bc: the embedded runner.
 *   servo-bc SCRIPT              runs the script
 *   servo-bc --decks DIR SCRIPT  writes the script's case for every host into DIR */
#include "sbc/script.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    sbc_error err;
    const int decks = argc == 4 && strcmp(argv[1], "--decks") == 0;
    if ((argc != 2 && !decks) || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0) {
        fprintf(stderr, "usage: servo-bc SCRIPT\n       servo-bc --decks DIR SCRIPT\n");
        return argc == 2 ? 0 : 2;
    }
    if ((decks ? sbc_script_decks_file(argv[3], argv[2], stdout, &err) : sbc_script_run_file(argv[1], stdout, &err)) !=
        SBC_OK) {
        fflush(stdout);
        fprintf(stderr, "ERROR: %s\n", err.message);
        return 1;
    }
    return 0;
}
