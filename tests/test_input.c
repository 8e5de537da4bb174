/* Bad input: every error names the line, the command or keyword, the value
 * and what was expected; nothing crashes; the runner exits non-zero. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "csv_read.h"
#include "tests.h"

#include "sbc/embedded/script.h"
#include "sbc/settings.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HEAD "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 2e3 mu 0.4\n" \
             "density 2e3\ntimestep 1e-5\n"

typedef struct bad_case {
    const char *script;
    const char *expect[3]; /* substrings the message must contain */
} bad_case;

static const bad_case cases[] = {
    {"dimension 2\nfoo 1\n", {"bad:2:", "unknown command 'foo'", "expected dimension"}},
    {"dimension 5\n", {"bad:1:", "dimension", "'5'"}},
    {"lattice square 5 5 spacing 2e-3\n", {"bad:1:", "lattice: missing values", "radius R"}},
    {"density 2e3 5\n", {"bad:1:", "extra value '5'", "density RHO"}},
    {"timestep abc\n", {"bad:1:", "'abc' is not a number", "timestep"}},
    {"timestep -1e-6\n", {"bad:1:", "DT -1e-6 is not positive", "> 0"}},
    {"density 0\n", {"bad:1:", "RHO 0 is not positive", "density"}},
    {"lattice square 5 5 spacing 2e-3 radius -1\n", {"bad:1:", "radius -1 is not positive", "lattice"}},
    {"lattice square 2 5 spacing 2e-3 radius 1e-3\n", {"bad:1:", "NX '2'", "3 to 100000"}},
    {"lattice hex 5 5 spacing 2e-3 radius 1e-3\n", {"bad:1:", "style 'hex'", "'square'"}},
    {"contact frictional kn 0 ks 2e3 mu 0.4\n", {"bad:1:", "kn 0 is not positive", "contact"}},
    {"contact frictional kn 1e4 ks -2 mu 0.4\n", {"bad:1:", "ks '-2'", ">= 0"}},
    {"contact frictional kn 1e4 kt 2e3 mu 0.4\n", {"bad:1:", "expected keyword 'ks' but found 'kt'", "usage"}},
    {"contact glue kn 1e4\n", {"bad:1:", "law 'glue'", "'frictional' or 'cohesive'"}},
    {"contact cohesive kn 1e8 ks 4e7 kr 20 fn 0 fs 60 mr 0.2 mu 0.6\n", {"bad:1:", "contact cohesive: fn '0' is not valid", "> 0"}},
    {"contact cohesive kn 1e8 ks 4e7 kr -20 fn 300 fs 60 mr 0.2 mu 0.6\n", {"bad:1:", "kr '-20'", ">= 0"}},
    {"contact cohesive kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mu 0.6\n",
     {"bad:1:", "contact cohesive: missing values", "mr MR mu MU"}},
    {"contact cohesive kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mb 0.2 mu 0.6\n",
     {"bad:1:", "expected keyword 'mr' but found 'mb'", "usage"}},
    {"servo_bc Q\n", {"bad:1:", "unknown boundary condition 'Q'", "D, P, T or mixed"}},
    {"servo_bc mixed\n", {"bad:1:", "component y of the top edge is under T", "stress P22"}},
    {"servo_bc mixed stress P22 -1e6 6 top D D\n", {"bad:1:", "'stress P22' is prescribed", "both prescribed and free"}},
    {"servo_bc mixed stress P22 -1e6 6 left P T\n", {"bad:1:", "left P T", "'left P P'"}},
    {"servo_bc mixed stress P22 -1e6 6 left D D\n", {"bad:1:", "right is periodic", "opposite left edge is D D"}},
    {"servo_bc mixed stress P22 -1e6 6 F 1 0.1 0 0.9\n", {"bad:1:", "F22 = 0.9", "is a result"}},
    {"servo_bc mixed stress P22 -1e6 6 stress P11 -1e6 4 right T D left T D\n",
     {"bad:1:", "P11 is applied in 4 increments", "one stress stage"}},
    {"servo_bc mixed stress P33 -1e6 6\n", {"bad:1:", "component 'P33'", "P11, P12, P21 or P22"}},
    {"servo_bc mixed stress P22 -1e6 6 top D X\n", {"bad:1:", "mode of component y 'X'", "D, P or T"}},
    {"servo_bc P top D T\n", {"bad:1:", "keyword 'top' needs boundary condition mixed", "got P"}},
    {"servo_bc D bogus 1\n", {"bad:1:", "unknown keyword 'bogus'", "increments"}},
    {"servo_bc D F 1 2 2 1\n", {"bad:1:", "keyword 'F'", "det F = -3"}},
    {"servo_bc D F -1 0 0 -1\n", {"bad:1:", "det F reaches 0 at 0.5", "whole path"}},
    {"servo_bc D F 1 0 0\n", {"bad:1:", "keyword 'F'", "missing F22"}},
    {"servo_bc D F 1 0 x 1\n", {"bad:1:", "F21 'x'", "a real number"}},
    {"servo_bc D increments 0\n", {"bad:1:", "keyword 'increments'", "'0'"}},
    {"servo_bc D relax 1e-3\n", {"bad:1:", "keyword 'relax'", "missing window"}},
    {"servo_bc D relax -1 20\n", {"bad:1:", "tolE '-1'", "> 0"}},
    {"servo_bc D damping 1.5 0.7\n", {"bad:1:", "keyword 'damping'", "'1.5'"}},
    {"servo_bc D stress P22 -1e6 6\n", {"bad:1:", "keyword 'stress'", "mixed"}},
    {"servo_bc D gain_force 0\n", {"bad:1:", "keyword 'gain_force'", "'0'"}},
    {"servo_bc D predict 2\n", {"bad:1:", "keyword 'predict'", "[0, 1]"}},
    {"servo_bc P update newtonian\n", {"bad:1:", "keyword 'update': mode 'newtonian'", "fixed, secant or newton"}},
    {"servo_bc P update\n", {"bad:1:", "keyword 'update'", "missing mode"}},
    {"servo_bc P tol_relative -1e-3\n", {"bad:1:", "keyword 'tol_relative'", "a real >= 0"}},
    {"servo_bc P accuracy quick\n", {"bad:1:", "preset 'quick'", "fast, balanced, paper or tight"}},
    {"servo_bc P accuracy fast tol_force 1e-7 accuracy tight\n", {"bad:1:", "keyword 'accuracy' given twice", NULL}},
    {"servo_bc P increments 2 tol_force 1e-7 increments 3\n", {"bad:1:", "keyword 'increments' given twice", NULL}},
    {"servo_bc D F 1e300 0 0 1e300 increments 5\n", {"bad:1:", "keyword 'F': F11 1e+300", "|Fij| <= 100"}},
    {"servo_bc P accuracy\n", {"bad:1:", "keyword 'accuracy'", "missing preset"}},
    {HEAD "run\n", {"bad:6:", "run", "no boundary condition"}},
    {"dimension 2\nservo_bc D\nrun\n", {"bad:3:", "run", "no packing"}},
    {HEAD "servo_bc D frame boundary\nrun\n", {"bad:7:", "keyword 'frame'", "'boundary'"}},
    {"dimension 2\nlattice square 5 5 spacing 3e-3 radius 1e-3\ncontact frictional kn 1e4 ks 2e3 mu 0.4\n"
     "density 2e3\ntimestep 1e-5\nservo_bc D\nrun\n",
     {"bad:7:", "no contacts", "radius and spacing"}},
    {"dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 2e3 mu 0.4\n"
     "density 2e3\ntimestep 1e-2\nservo_bc D\nrun\n",
     {"bad:5:", "time step 0.01 s", "exceeds the critical step"}}, /* at its timestep line */
    {HEAD "servo_bc D F 0.99 0 0 0.99 damping none remap none max_relax_steps 500\nrun\n",
     {"bad:7:", "increment 1", "did not reach force balance 1e-05"}},
    {"read_packing /nonexistent/packing.txt\n", {"bad:1:", "read_packing", "cannot open"}},
    /* scripts that would compute nothing, or silently use one of two servo_bc lines */
    {"dimension 2\n", {"bad: the script computes nothing", "expected run, write_packing or rose", NULL}},
    {"", {"bad: the script computes nothing", "it is empty", NULL}},
    {HEAD "servo_bc D\nservo_bc P\nrun\n", {"bad:7:", "a second servo_bc line", "line 6"}},
    /* sizes and scales that used to loop for ever or overflow */
    {"dimension 2\ngenerate periodic n0 10 rmin 1e200 polydispersity 2 seed 1\n",
     {"bad:2:", "rmin 1e+200 m is out of range", "1e-6 to 1e3 m"}},
    {"dimension 2\nlattice square 100000 100000 spacing 2e-3 radius 1e-3\n",
     {"bad:2:", "100000 x 100000 particles exceed the limit", NULL}},
    {HEAD "timestep 1e-300\nservo_bc D\nrun\n", {"bad:6:", "time step 1e-300 s", "do not span one critical step"}},
    {"dimension 3\npacking random radius 1e-9 porosity 0.41 seed 1\nbond parallel E 4e9 ratio 4.2 touch 0.05\n"
     "density 925 scaled\ntimestep critical 0.6\ntest uniaxial velocity -1e-5 steps 10\nrun\n",
     {"bad:7:", "random packing: 3.5213e+23 spheres", "exceed the limit of 10000000"}},
    {"dimension 3\npacking hcp radius 1e-9\nbond parallel E 4e9 ratio 4.2 touch 0.05\n"
     "density 925 scaled\ntimestep critical 0.6\ntest uniaxial velocity -1e-5 steps 10\nrun\n",
     {"bad:7:", "packing: ", "exceed the limit of 10000000"}},
};

static void check_case(const bad_case *c)
{
    sbc_error err;
    sbc_status st = sbc_script_run_string(c->script, "bad", NULL, &err);
    int k, ok = st != SBC_OK;
    for (k = 0; k < 3 && ok; ++k)
        ok = c->expect[k] == NULL || strstr(err.message, c->expect[k]) != NULL;
    CHECK(ok);
    if (!ok)
        printf("  script:\n%s  message: %s\n", c->script, st != SBC_OK ? err.message : "(none: accepted)");
}

/* Packing-file errors name the file and line; a frame that cannot be found is reported. */
static void packing_files(void)
{
    char path[512], script[1024];
    sbc_error err;
    snprintf(path, sizeof path, "%s/bad_packing.txt", test_tmpdir);
    write_text(path, "# x y r\n0 0 1e-3\n1e-3 0 abc\n");
    snprintf(script, sizeof script, "read_packing %s\n", path);
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_INPUT);
    CHECK(strstr(err.message, "line 3") && strstr(err.message, "'abc'"));
    write_text(path, "0 0 1e-3\n1e-3 0 0\n");
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_INPUT);
    CHECK(strstr(err.message, "line 2") && strstr(err.message, "radius 0"));
    write_text(path, "0 0 1e-3 7\n");
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_INPUT);
    CHECK(strstr(err.message, "4 values") != NULL);
    /* a packing without a top-right corner particle */
    write_text(path, "0 0 1.02e-3\n2e-3 0 1.02e-3\n4e-3 0 1.02e-3\n0 2e-3 1.02e-3\n2e-3 2e-3 1.02e-3\n"
                     "4e-3 2e-3 1.02e-3\n0 4e-3 1.02e-3\n2e-3 4e-3 1.02e-3\n");
    snprintf(script, sizeof script,
             "read_packing %s\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\nservo_bc D\nrun\n",
             path);
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_FRAME);
    CHECK(strstr(err.message, "bad:6:") && strstr(err.message, "top-right corner"));
    /* (P) needs +/- partners: a 4 x 4 lattice without one top edge particle */
    write_text(path, "0 0 1.02e-3\n2e-3 0 1.02e-3\n4e-3 0 1.02e-3\n6e-3 0 1.02e-3\n"
                     "0 2e-3 1.02e-3\n2e-3 2e-3 1.02e-3\n4e-3 2e-3 1.02e-3\n6e-3 2e-3 1.02e-3\n"
                     "0 4e-3 1.02e-3\n2e-3 4e-3 1.02e-3\n4e-3 4e-3 1.02e-3\n6e-3 4e-3 1.02e-3\n"
                     "0 6e-3 1.02e-3\n4e-3 6e-3 1.02e-3\n6e-3 6e-3 1.02e-3\n");
    snprintf(script, sizeof script,
             "read_packing %s\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\nservo_bc P\nrun\n",
             path);
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_FRAME);
    CHECK(strstr(err.message, "bad:6:") && strstr(err.message, "servo_bc P") &&
          strstr(err.message, "no periodic partner"));
}

/* Files: a NUL byte in a script, an output over the script or an earlier
 * output, a packing line too long to read whole, coincident centres. */
static void runner_files(void)
{
    char path[512], csv[512], packing[512], script[2048], line[1400];
    sbc_error err;
    FILE *fp;
    int k;
    snprintf(path, sizeof path, "%s/nul.sbc", test_tmpdir);
    fp = fopen(path, "wb");
    CHECK(fp != NULL);
    if (fp) {
        fwrite("dimension 2\n\nlattice square 4 4 spacing 2e-3 radius 1e-3\0run\n", 1, 57, fp);
        fclose(fp);
    }
    CHECK(sbc_script_run_file(path, NULL, &err) == SBC_ERR_INPUT && strstr(err.message, "nul.sbc:3: a NUL byte"));
    /* the results file over the script itself */
    snprintf(path, sizeof path, "%s/self.sbc", test_tmpdir);
    snprintf(script, sizeof script, HEAD "servo_bc D file %s\nrun\n", path);
    write_text(path, script);
    CHECK(sbc_script_run_file(path, NULL, &err) == SBC_ERR_INPUT && strstr(err.message, "is this script"));
    fp = fopen(path, "r");
    CHECK(fp && fgets(line, sizeof line, fp) && strcmp(line, "dimension 2\n") == 0); /* the script is intact */
    if (fp)
        fclose(fp);
    /* two runs into one results file: the second would truncate the first */
    snprintf(csv, sizeof csv, "%s/twice.csv", test_tmpdir);
    snprintf(script, sizeof script, HEAD "servo_bc D file %s\nrun\nservo_bc D F 0.99 0 0 1 file %s\nrun\n", csv, csv);
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "bad:9:") && strstr(err.message, "is the results file of line 7"));
    /* the results file over the packing read */
    snprintf(packing, sizeof packing, "%s/read.txt", test_tmpdir);
    write_text(packing, "0 0 1e-3\n2e-3 0 1e-3\n4e-3 0 1e-3\n0 2e-3 1e-3\n2e-3 2e-3 1e-3\n4e-3 2e-3 1e-3\n"
                        "0 4e-3 1e-3\n2e-3 4e-3 1e-3\n4e-3 4e-3 1e-3\n");
    snprintf(script, sizeof script,
             "read_packing %s\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\n"
             "servo_bc D file %s\nrun\n", packing, packing);
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "is the packing read of line 1"));
    /* a packing line longer than the reader's buffer is refused, not split in two */
    for (k = 0; k < 1300; ++k)
        line[k] = '0';
    memcpy(line, "0.", 2);
    memcpy(line + 1300, " 0 1e-3\n", 9);
    fp = fopen(packing, "w");
    CHECK(fp != NULL);
    if (fp) {
        fputs("0 0 1e-3\n", fp);
        fputs(line, fp);
        fclose(fp);
    }
    snprintf(script, sizeof script, "read_packing %s\n", packing);
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "line 2 is longer than 1023 characters"));
    snprintf(script, sizeof script, "read_packing /dev/zero\n");
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "/dev/zero line 1 holds a NUL byte"));
    /* two discs on one centre: named with their lines when read, not as a blown-up packing */
    write_text(packing, "0 0 1e-3\n2e-3 0 1e-3\n4e-3 0 1e-3\n0 2e-3 1e-3\n2e-3 2e-3 1e-3\n4e-3 2e-3 1e-3\n"
                        "0 4e-3 1e-3\n2e-3 4e-3 1e-3\n4e-3 4e-3 1e-3\n2e-3 2e-3 1e-3\n");
    snprintf(script, sizeof script,
             "read_packing %s\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\nservo_bc D\nrun\n",
             packing);
    CHECK(sbc_script_run_string(script, "bad", NULL, &err) == SBC_ERR_INPUT && strstr(err.message, "bad:1:") &&
          strstr(err.message, "lines 5 and 10: discs 4 and 9 have coincident centres"));
    if (!strstr(err.message, "discs 4 and 9"))
        printf("  coincident: %s\n", err.message);
}

/* The executable: non-zero exit, "ERROR:" with the line on stderr, and the
 * CSV keeps every increment converged before a failure. */
static void runner_exit(void)
{
    char script[512], csv[512], cmd[1400], out[1024] = "";
    static double rows[8][CSV_COLS];
    FILE *pp;
    int status;
    snprintf(script, sizeof script, "%s/fail.sbc", test_tmpdir);
    snprintf(csv, sizeof csv, "%s/fail.csv", test_tmpdir);
    {
        char text[1024];
        snprintf(text, sizeof text,
                 HEAD "servo_bc D F 0.99 0 0 0.99 increments 3 damping none remap none max_relax_steps 3000 file %s\nrun\n", csv);
        write_text(script, text);
    }
    snprintf(cmd, sizeof cmd, "%s %s 2>&1 >/dev/null", test_runner, script);
    pp = popen(cmd, "r");
    CHECK(pp != NULL);
    if (!pp)
        return;
    if (!fgets(out, sizeof out, pp))
        out[0] = '\0';
    status = pclose(pp);
    CHECK(status != 0);
    CHECK(strstr(out, "ERROR: ") == out && strstr(out, "fail.sbc:7:") && strstr(out, "increment 1"));
    /* increment 0 (F = I, already in equilibrium) converged and was kept */
    CHECK(csv_read(csv, rows, 8) == 1);
    snprintf(cmd, sizeof cmd, "%s 2>/dev/null", test_runner);
    CHECK(system(cmd) != 0); /* usage error */
}

static sbc_settings parse_words(const char *line)
{
    char buf[512], *w[64];
    int nw = 0;
    sbc_settings s;
    sbc_error err;
    snprintf(buf, sizeof buf, "%s", line);
    for (w[nw] = strtok(buf, " "); w[nw]; w[++nw] = strtok(NULL, " "))
        ;
    CHECK(sbc_settings_parse(&s, nw, (const char *const *)w, &err) == SBC_OK);
    return s;
}

/* accuracy presets: what each sets; keywords given with one win wherever they
 * stand; paper is Table 4, the defaults. */
static void presets(void)
{
    sbc_settings d = sbc_settings_default(), s = parse_words("P accuracy paper");
    CHECK(s.tol_E == d.tol_E && s.window == d.window && s.gain_force == d.gain_force && s.tol_force == d.tol_force &&
          s.tol_moment == d.tol_moment && s.tol_deformation == d.tol_deformation && s.tol_relative == 0.0 &&
          s.update == SBC_UPDATE_FIXED && strcmp(s.accuracy, "paper") == 0);
    s = parse_words("P accuracy fast");
    CHECK(s.update == SBC_UPDATE_SECANT && s.tol_relative > 0.0);
    {
        sbc_settings a = parse_words("T tol_relative 5e-3 relax 1e-2 7 accuracy tight update fixed");
        sbc_settings b = parse_words("T accuracy tight tol_relative 5e-3 relax 1e-2 7 update fixed");
        sbc_settings t = parse_words("T accuracy tight");
        CHECK(a.tol_relative == 5e-3 && a.tol_E == 1e-2 && a.window == 7 && a.update == SBC_UPDATE_FIXED);
        CHECK(b.tol_relative == 5e-3 && b.tol_E == 1e-2 && b.window == 7 && b.update == SBC_UPDATE_FIXED);
        CHECK(a.tol_deformation == t.tol_deformation && t.tol_relative < s.tol_relative);
    }
}

void test_input(void)
{
    size_t k;
    for (k = 0; k < sizeof cases / sizeof cases[0]; ++k)
        check_case(&cases[k]);
    packing_files();
    runner_files();
    runner_exit();
    presets();
}
