/* servo-bc --decks: one case written for every host. The embedded script
 * reproduces the case's own run bit for bit; the host decks carry the same
 * contact law, time step and servo words, the frame of a periodic packing,
 * and each its own results file; what no host can run is refused. */
#define _POSIX_C_SOURCE 200809L
#include "decks.h"
#include "check.h"
#include "csv_read.h"
#include "tests.h"

#include "sbc/embedded/script.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char *slurp(const char *path)
{
    FILE *fp = fopen(path, "rb");
    char *text;
    long n;
    if (!fp) return NULL;
    fseek(fp, 0, SEEK_END);
    n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    text = calloc((size_t)n + 1, 1);
    if (text && fread(text, 1, (size_t)n, fp) != (size_t)n) text[0] = '\0';
    fclose(fp);
    return text;
}

/* text of dir/name contains every needle (NULL-terminated) */
static int contains(const char *dir, const char *name, const char *const *needle)
{
    char path[512];
    char *text;
    int ok = 1;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    text = slurp(path);
    if (!text) return 0;
    for (; *needle; ++needle)
        if (!strstr(text, *needle)) {
            printf("  %s lacks '%s'\n", name, *needle);
            ok = 0;
        }
    free(text);
    return ok;
}

void test_decks(void)
{
    char dir[256], path[512], script[1024], cwd[1024], *direct, *decked;
    sbc_error err;
    int same;
    snprintf(dir, sizeof dir, "%s/decks", test_tmpdir);
    mkdir(dir, 0777);
    /* a lattice case: its own run, and its decks */
    snprintf(script, sizeof script,
             "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 2e3 mu 0.4\n"
             "density 2e3\ntimestep 1e-5\nservo_bc P F 0.999 -0.01 -0.01 0.999 increments 2 file %s/direct.csv "
             "gain_force 1e3 gain_moment 1e3\nrun\n",
             test_tmpdir);
    snprintf(path, sizeof path, "%s/case.sbc", test_tmpdir);
    CHECK(write_text(path, script) == 0);
    CHECK(sbc_script_run_file(path, NULL, &err) == SBC_OK);
    CHECK(sbc_script_decks_file(path, dir, sbc_runner_write_decks, NULL, &err) == SBC_OK);
    /* the embedded script, run in the folder, writes the very same CSV */
    CHECK(getcwd(cwd, sizeof cwd) != NULL);
    CHECK(chdir(dir) == 0);
    CHECK(sbc_script_run_file("embedded.sbc", NULL, &err) == SBC_OK);
    CHECK(chdir(cwd) == 0);
    snprintf(path, sizeof path, "%s/direct.csv", test_tmpdir);
    direct = slurp(path);
    snprintf(path, sizeof path, "%s/embedded.csv", dir);
    decked = slurp(path);
    same = direct && decked && strlen(direct) > 100 && strcmp(direct, decked) == 0;
    CHECK(same);
    free(direct);
    free(decked);
    {
        const char *lammps[] = {"read_data       packing.lammps.data",
                                "pair_style      gran/hooke/history 10000 2000 0 0 0.4 0", "timestep        1e-05",
                                "neighbor        0.000255 bin",
                                "servo_bc P F 0.999 -0.01 -0.01 0.999 increments 2 gain_force 1e3 gain_moment 1e3 "
                                "file lammps.csv",
                                "nve/sphere disc", NULL};
        const char *liggghts[] = {"read_data       packing.liggghts.data", "kn peratomtypepair 2 10000 10000 10000 10000",
                                  "kt peratomtypepair 2 2000 2000 2000 2000",
                                  "coefficientFriction peratomtypepair 2 0.4 0.4 0.4 0.4",
                                  "gamman_abs peratomtypepair 2 0 0 0 0", "file liggghts.csv", "jump SELF loop", NULL};
        const char *yade[] = {"'packing.yade'", "increments 2 gain_force 1e3 gain_moment 1e3 file yade.csv'",
                              "density=2000, kn=10000, ks=2000, mu=0.4, dt=1e-05", NULL};
        const char *packings[] = {"25 discs", NULL};
        CHECK(contains(dir, "lammps.in", lammps));
        CHECK(contains(dir, "liggghts.in", liggghts));
        CHECK(contains(dir, "yade.py", yade));
        CHECK(contains(dir, "packing.yade", packings) && contains(dir, "packing.lammps.data", packings) &&
              contains(dir, "packing.liggghts.data", packings));
    }
    /* a periodic packing: every host takes the flagged frame */
    snprintf(script, sizeof script,
             "dimension 2\ngenerate periodic n0 25 rmin 0.67e-3 polydispersity 2 seed 1\n"
             "contact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-6\nservo_bc P F 1 0.01 0 1\nrun\n");
    snprintf(path, sizeof path, "%s/case_periodic.sbc", test_tmpdir);
    CHECK(write_text(path, script) == 0);
    CHECK(sbc_script_decks_file(path, dir, sbc_runner_write_decks, NULL, &err) == SBC_OK);
    {
        const char *lammps[] = {"servo_bc P F 1 0.01 0 1 frame frame_atoms file lammps.csv", NULL};
        const char *liggghts[] = {"servo_bc P F 1 0.01 0 1 frame frame_atoms file liggghts.csv", NULL};
        const char *yade[] = {"P F 1 0.01 0 1 frame 2 file yade.csv", NULL};
        const char *box[] = {"box ", NULL};
        CHECK(contains(dir, "lammps.in", lammps) && contains(dir, "liggghts.in", liggghts));
        CHECK(contains(dir, "yade.py", yade));
        CHECK(contains(dir, "packing.txt", box));
    }
    /* a cohesive case: every host hands its contacts to the core, with the same law words */
    snprintf(script, sizeof script,
             "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\n"
             "contact cohesive kn 1e4 ks 2e3 kr 0.001 fn 1 fs 1 mr 0.001 mu 0.4\ndensity 2e3\ntimestep 1e-6\n"
             "servo_bc D F 1 0.01 0 1\nrun\n");
    snprintf(path, sizeof path, "%s/case_cohesive.sbc", test_tmpdir);
    CHECK(write_text(path, script) == 0);
    CHECK(sbc_script_decks_file(path, dir, sbc_runner_write_decks, NULL, &err) == SBC_OK);
    {
        const char *embedded[] = {"contact cohesive kn 10000 ks 2000 kr 0.001 fn 1 fs 1 mr 0.001 mu 0.4", NULL};
        const char *lammps[] = {"pair_style      zero", "fix             bonds all servo_bc/bonds cohesive kn 10000 "
                                "ks 2000 kr 0.001 fn 1 fs 1 mr 0.001 mu 0.4", NULL};
        const char *liggghts[] = {"pair_style      none", "atom_modify     sort 0 0.0",
                                  "fix             bonds all servo_bc/bonds cohesive kn 10000", NULL};
        const char *yade[] = {"cohesive='kn 10000 ks 2000 kr 0.001 fn 1 fs 1 mr 0.001 mu 0.4'", NULL};
        const char *frictional[] = {"gran", NULL};
        CHECK(contains(dir, "embedded.sbc", embedded) && contains(dir, "lammps.in", lammps));
        CHECK(contains(dir, "liggghts.in", liggghts) && contains(dir, "yade.py", yade));
        CHECK(!contains(dir, "lammps.in", frictional) && !contains(dir, "liggghts.in", frictional));
    }
    /* a folder that is not there */
    snprintf(path, sizeof path, "%s/case_periodic.sbc", test_tmpdir);
    CHECK(sbc_script_decks_file(path, "/dev/null/folder", sbc_runner_write_decks, NULL, &err) == SBC_ERR_IO &&
          strstr(err.message, "cannot write '/dev/null/folder/packing.txt'"));
}
