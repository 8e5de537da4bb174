/* Test runner: run_tests [SERVO_BC_BINARY [TMPDIR]]; last line "N passed, N failed".
 * SBC_TEST_SUITE=NAME[,NAME...] runs those suites, SBC_TEST_SKIP=NAME[,NAME...]
 * all others (make check-valgrind runs the two halves side by side). */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "tests.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int check_passed = 0, check_failed = 0;
const char *test_tmpdir = "build/test-tmp";
const char *test_runner = "build/servo-bc";

int file_contains(const char *path, const char *needle)
{
    FILE *fp = fopen(path, "r");
    char buf[512];
    int found = 0;
    if (!fp)
        return 0;
    while (!found && fgets(buf, sizeof buf, fp))
        found = strstr(buf, needle) != NULL;
    fclose(fp);
    return found;
}

int same_bytes(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    int ca = 0, cb = 0, same = fa && fb;
    while (same && ca != EOF) {
        ca = fgetc(fa);
        cb = fgetc(fb);
        same = ca == cb;
    }
    if (fa)
        fclose(fa);
    if (fb)
        fclose(fb);
    return same;
}

/* name is one of the comma-separated names of list */
static int listed(const char *list, const char *name)
{
    const size_t n = strlen(name);
    const char *at = list;
    while ((at = strstr(at, name)) != NULL) {
        if ((at == list || at[-1] == ',') && (at[n] == '\0' || at[n] == ','))
            return 1;
        at += n;
    }
    return 0;
}

int main(int argc, char **argv)
{
    struct {
        const char *name;
        void (*fn)(void);
    } suites[] = {{"frame", test_frame}, {"frame3d", test_frame_3d}, {"frame3d-periodic", test_frame_3d_periodic}, {"irregular3d", test_irregular_3d}, {"spheres", test_spheres},     {"homogenize", test_homogenize}, {"contact", test_contact}, {"cohesive", test_cohesive},
                  {"bonds", test_bonds}, {"bonds-runner", test_bonds_runner},
                  {"rattler", test_rattler_energy},
                  {"relax", test_relax},     {"lattice", test_lattice},       {"input", test_input},
                  {"outputs", test_outputs}, {"servo", test_servo}, {"restart", test_restart}, {"generate", test_generate}, {"mixed", test_mixed},
                  {"host", test_host}, {"decks", test_decks}, {"bpm", test_bpm}, {"accuracy", test_accuracy}, {"seal", test_seal}, {"seal3d", test_seal_3d}, {"point", test_point}, {"condensed", test_condensed}, {"newton", test_newton}, {"interior", test_interior}, {"interior-spheres", test_interior_spheres}, {"interior-bonds", test_interior_bonds}, {"bpm-host", test_bpm_host}, {"cohesive-host", test_cohesive_host}, {"driver", test_driver}, {"remap", test_remap}};
    size_t k;
    if (argc > 1) test_runner = argv[1];
    if (argc > 2) test_tmpdir = argv[2];
    mkdir(test_tmpdir, 0777);
    for (k = 0; k < sizeof suites / sizeof suites[0]; ++k) {
        int f0 = check_failed, p0 = check_passed;
        const char *only = getenv("SBC_TEST_SUITE"), *skip = getenv("SBC_TEST_SKIP");
        if ((only && !listed(only, suites[k].name)) || (skip && listed(skip, suites[k].name)))
            continue;
        suites[k].fn();
        printf("%-12s %4d checks, %d failed\n", suites[k].name, check_passed - p0 + check_failed - f0,
               check_failed - f0);
        fflush(stdout);
    }
    printf("%d passed, %d failed\n", check_passed, check_failed);
    return check_failed ? 1 : 0;
}
