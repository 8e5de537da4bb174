#define _POSIX_C_SOURCE 200809L
/* The runner's case as input for every host (`servo-bc --decks DIR CASE`),
 * part of the servo-bc program and not of the core library, which writes no
 * host's input syntax:
 * one packing written in each host's format, and the embedded script, the
 * LAMMPS deck, the LIGGGHTS script and the YADE script that run the same
 * contact law, time step and servo_bc words on it, each writing DIR/HOST.csv.
 * Written from the parsed case, so the four cannot drift apart by hand.
 * A frictional case uses each host's own contact law (eq. 6); a cohesive
 * one (eqs. 7-8) hands every contact to the core: fix servo_bc/bonds
 * cohesive in LAMMPS and LIGGGHTS, servo_bc.Cohesive in YADE. */
#include "decks.h"
#include "runner/script_state.h"
#include "sbc/columns.h"
#include "sbc/embedded/output_file.h"
#include "sbc/tensor.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The shortest of %.15g, %.17g that reads back as v (1e-06, not
 * 9.9999999999999995e-07); the temporary lives to the end of the full
 * expression that uses it (C11 6.2.4). */
typedef struct number_text {
    char s[32];
} number_text;

static number_text num(double v)
{
    number_text t;
    snprintf(t.s, sizeof t.s, "%.15g", v);
    if (strtod(t.s, NULL) != v)
        snprintf(t.s, sizeof t.s, "%.17g", v);
    return t;
}

/* The cohesive law's words after `cohesive` (contact.h, sbc_cohesive_parse). */
typedef struct law_text {
    char s[320];
} law_text;

static law_text cohesive_words(const sbc_cohesive *c)
{
    law_text t;
    snprintf(t.s, sizeof t.s, "kn %s ks %s kr %s fn %s fs %s mr %s mu %s", num(c->kn).s, num(c->ks).s, num(c->kr).s,
             num(c->fn_u).s, num(c->fs_u).s, num(c->m_u).s, num(c->mu).s);
    return t;
}

/* DIR/name opened for writing */
static sbc_status open_in(FILE **fp, const char *dir, const char *name, char *path, size_t size, sbc_error *err)
{
    if ((size_t)snprintf(path, size, "%s/%s", dir, name) >= size)
        return sbc_fail(err, SBC_ERR_INPUT, "--decks: directory name '%s' is too long", dir);
    if (!(*fp = sbc_output_open(path, SBC_OUTPUT_DECK, "--decks", err)))
        return err->status;
    return SBC_OK;
}

/* DIR is a folder name, not a file, and none of the files --decks writes in
   it is the script or a file the script read or wrote, or a file servo_bc
   did not write: checked before anything is written */
static sbc_status decks_folder(script *s, const char *dir, sbc_error *err)
{
    static const char *const decks[8][2] = {
        {"packing.txt", "p"}, {"packing.lammps.data", "p"}, {"packing.liggghts.data", "p"}, {"packing.yade", "p"},
        {"embedded.sbc", "d"}, {"lammps.in", "d"}, {"liggghts.in", "d"}, {"yade.py", "d"}};
    char path[2 * SBC_NAME_LEN];
    struct stat st;
    sbc_status status;
    int k;
    if (!dir[0])
        return sbc_fail(err, SBC_ERR_INPUT, "--decks: the folder name is empty (expected a folder to write the "
                        "hosts' inputs into)");
    if (strlen(dir) >= SBC_NAME_LEN)
        return sbc_fail(err, SBC_ERR_INPUT, "--decks: folder name '%.40s...' is too long (at most %d characters)", dir,
                        SBC_NAME_LEN - 1);
    if (stat(dir, &st) == 0 && !S_ISDIR(st.st_mode))
        return sbc_fail(err, SBC_ERR_INPUT, "--decks: '%s' exists and is not a folder", dir);
    for (k = 0; k < 8; ++k) {
        snprintf(path, sizeof path, "%s/%s", dir, decks[k][0]);
        if ((status = sbc_script_files_check(s, path, "--decks:", err)) != SBC_OK ||
            (status = sbc_output_owned(path, decks[k][1][0] == 'p' ? SBC_OUTPUT_PACKING : SBC_OUTPUT_DECK, "--decks",
                                       err)) != SBC_OK)
            return status;
    }
    return SBC_OK;
}

static sbc_status close_file(FILE *fp, const char *path, sbc_error *err)
{
    return sbc_output_close(fp, path, "--decks", err);
}

/* The frame words of a host: a periodic packing's frame is the flagged one
 * (its corner copies are recognized only in a given list), a lattice ring's
 * is detected from the positions by every host alike. */
static const char *frame_words(const script *s, const char *host)
{
    if (!s->packing.has_box)
        return "";
    return strcmp(host, "yade") == 0 ? " frame 2" : " frame frame_atoms";
}

/* the case's dimension, density (kg/m^2 in 2D, kg/m^3 in 3D) and time step */
typedef struct case_material {
    int dim;
    double density, dt;
} case_material;

static sbc_status write_embedded(const script *s, const case_material *c, const char *dir, sbc_error *err)
{
    char path[2 * SBC_NAME_LEN];
    FILE *fp;
    sbc_status st = open_in(&fp, dir, "embedded.sbc", path, sizeof path, err);
    if (st != SBC_OK)
        return st;
    fprintf(fp, "# %s on the embedded engine (servo-bc --decks); run in this folder\n", s->name);
    fprintf(fp, "dimension %d\nread_packing packing.txt\n", c->dim);
    if (s->cohesive)
        fprintf(fp, "contact cohesive %s\n", cohesive_words(&s->bond_law).s);
    else
        fprintf(fp, "contact frictional kn %s ks %s mu %s\n", num(s->law.kn).s, num(s->law.ks).s, num(s->law.mu).s);
    fprintf(fp, "density %s\ntimestep %s\nservo_bc %s file embedded.csv\nrun\n", num(c->density).s, num(c->dt).s,
            s->servo_words);
    return close_file(fp, path, err);
}

/* The ghost cutoff of a cohesive case (m): a contact within the skin, an
 * intact bond up to eq. 8's stretch fn / kn, with 0.1 % to spare. */
static double cohesive_reach(const script *s, double skin, double rmax)
{
    const double stretch = s->bond_law.fn_u / s->bond_law.kn;
    return 1.001 * (2.0 * rmax + (stretch > skin ? stretch : skin));
}

/* the thermo columns of a host deck: the increment, the path's own components (those of F that leave the identity,
   else the stress components of a stress path; at most three) with their Cauchy stress, the servo iterations */
typedef struct thermo_text {
    char s[256];
} thermo_text;

static thermo_text thermo_columns(const script *s, int dim)
{
    thermo_text t;
    int n = snprintf(t.s, sizeof t.s, "f_servo[1]"), i, j, k, shown = 0;
    for (k = 0; k < dim * dim && shown < 3; ++k) {
        char F[32], sigma[40];
        i = k / dim, j = k % dim;
        snprintf(F, sizeof F, "F%d%d", i + 1, j + 1);
        snprintf(sigma, sizeof sigma, "sigma%d%d", i + 1, j + 1);
        if (s->settings.F[SBC_IJ(i, j)] != (i == j ? 1.0 : 0.0)) {
            n += snprintf(t.s + n, sizeof t.s - (size_t)n, " f_servo[%d] f_servo[%d]", sbc_thermo_index(F),
                          sbc_thermo_index(sigma));
            ++shown;
        }
    }
    for (k = 0; k < s->settings.nstress && shown < 3; ++k, ++shown) {
        char sigma[40];
        snprintf(sigma, sizeof sigma, "sigma%d%d", s->settings.stress[k].i + 1, s->settings.stress[k].j + 1);
        n += snprintf(t.s + n, sizeof t.s - (size_t)n, " f_servo[%d]", sbc_thermo_index(sigma));
    }
    if (!shown)
        n += snprintf(t.s + n, sizeof t.s - (size_t)n, " f_servo[10]");
    snprintf(t.s + n, sizeof t.s - (size_t)n, " f_servo[17]");
    return t;
}

static sbc_status write_lammps(const script *s, const case_material *c, const char *dir, double skin, double rmax,
                               sbc_error *err)
{
    char path[2 * SBC_NAME_LEN];
    FILE *fp;
    sbc_status st = open_in(&fp, dir, "lammps.in", path, sizeof path, err);
    if (st != SBC_OK)
        return st;
    fprintf(fp, "# %s in LAMMPS (servo-bc --decks): build/lmp_servo -in lammps.in, in this folder\n", s->name);
    fprintf(fp, "units           si\ndimension       %d\nboundary        m m %s\natom_style      sphere\n"
                "read_data       packing.lammps.data\ngroup           frame_atoms type 2\n",
            c->dim, c->dim == 3 ? "m" : "p");
    if (s->cohesive) /* the core owns every contact: the pair style adds nothing */
        fprintf(fp, "pair_style      zero %s\npair_coeff      * *\n", num(2.0 * rmax).s);
    else
        fprintf(fp, "pair_style      gran/hooke/history %s %s 0 0 %s 0\npair_coeff      * *\n", num(s->law.kn).s,
                num(s->law.ks).s, num(s->law.mu).s);
    if (s->cohesive) /* the pairs of a rank's discs with ghosts: fix servo_bc/bonds cohesive checks the reach */
        fprintf(fp, "comm_modify     vel yes cutoff %s\n", num(cohesive_reach(s, skin, rmax)).s);
    else
        fprintf(fp, "comm_modify     vel yes\n");
    fprintf(fp, "neighbor        %s bin\nneigh_modify    delay 0 every 1 check yes\ntimestep        %s\n", num(skin).s,
            num(c->dt).s);
    if (s->cohesive)
        fprintf(fp, "fix             bonds all servo_bc/bonds cohesive %s\n", cohesive_words(&s->bond_law).s);
    fprintf(fp, "fix             servo all servo_bc %s%s file lammps.csv\n", s->servo_words, frame_words(s, "lammps"));
    fprintf(fp, c->dim == 3 ? "fix             integrate servo_interior nve/sphere\n"
                            : "fix             integrate servo_interior nve/sphere disc\nfix             plane all "
                              "enforce2d\n");
    fprintf(fp, "thermo_style    custom step %s%s\n"
                "thermo          100000\nrun             2000000000    # the fix ends the run\n",
            thermo_columns(s, c->dim).s, s->cohesive ? " f_bonds[1]" : "");
    return close_file(fp, path, err);
}

static sbc_status write_liggghts(const script *s, const case_material *c, const char *dir, double skin,
                                 double rmax, sbc_error *err)
{
    static const char *property[5] = {"kn", "kt", "gamman_abs", "gammat_abs", "coefficientFriction"};
    const double value[5] = {s->law.kn, s->law.ks, 0.0, 0.0, s->law.mu};
    char path[2 * SBC_NAME_LEN];
    FILE *fp;
    int k;
    sbc_status st = open_in(&fp, dir, "liggghts.in", path, sizeof path, err);
    if (st != SBC_OK)
        return st;
    fprintf(fp, "# %s in LIGGGHTS (servo-bc --decks): build/liggghts_servo -in liggghts.in, in this folder\n",
            s->name);
    fprintf(fp, "units           si\ndimension       %d\nboundary        m m %s\natom_style      sphere\n", c->dim,
            c->dim == 3 ? "m" : "p");
    if (s->cohesive) /* no pair style, so no neighbour bins to sort atoms by */
        fprintf(fp, "atom_modify     sort 0 0.0\n");
    fprintf(fp, "newton          off\n");
    if (s->cohesive)
        fprintf(fp, "communicate     single cutoff %s vel yes\n", num(cohesive_reach(s, skin, rmax)).s);
    else
        fprintf(fp, "communicate     single vel yes\n");
    fprintf(fp, "read_data       packing.liggghts.data\ngroup           frame_atoms type 2\n");
    if (s->cohesive) {
        fprintf(fp, "pair_style      none    # the core owns every contact\nneighbor        %s bin\n"
                    "neigh_modify    delay 0\ntimestep        %s\n"
                    "fix             bonds all servo_bc/bonds cohesive %s\n",
                num(skin).s, num(c->dt).s, cohesive_words(&s->bond_law).s);
    } else {
        for (k = 0; k < 5; ++k)
            fprintf(fp, "fix             m%d all property/global %s peratomtypepair 2 %s %s %s %s\n", k + 1,
                    property[k], num(value[k]).s, num(value[k]).s, num(value[k]).s, num(value[k]).s);
        fprintf(fp, "pair_style      gran model hooke/stiffness tangential history absolute_damping on\n"
                    "pair_coeff      * *\nneighbor        %s bin\nneigh_modify    delay 0\ntimestep        %s\n",
                num(skin).s, num(c->dt).s);
    }
    fprintf(fp, "fix             servo all servo_bc %s%s file liggghts.csv\n", s->servo_words,
            frame_words(s, "liggghts"));
    fprintf(fp, c->dim == 3 ? "fix             integrate servo_interior nve/sphere\n"
                            : "fix             integrate servo_interior nve/sphere\nfix             plane all "
                              "enforce2d\n");
    fprintf(fp, "thermo_style    custom step %s%s\n"
                "thermo          100000\n"
                "variable        done equal f_servo[18]    # LIGGGHTS cannot end a run from a fix\n"
                "run             0\n"
                "label           loop    # pieces without a setup between them: the uninterrupted run's results\n"
                "run             10000 pre no post no\n"
                "if              \"${done} == 0\" then \"jump SELF loop\"\n",
            thermo_columns(s, c->dim).s, s->cohesive ? " f_bonds[1]" : "");
    return close_file(fp, path, err);
}

static sbc_status write_yade(const script *s, const case_material *c, const char *dir, sbc_error *err)
{
    char path[2 * SBC_NAME_LEN];
    FILE *fp;
    sbc_status st = open_in(&fp, dir, "yade.py", path, sizeof path, err);
    if (st != SBC_OK)
        return st;
    fprintf(fp, "# %s in YADE (servo-bc --decks): SERVO_BC_YADE=<servo_bc>/yade_adapter yade -n -x yade.py,\n"
                "# in this folder\nimport os\nimport sys\nsys.path.insert(0, os.environ['SERVO_BC_YADE'])\n"
                "import servo_bc  # noqa: E402\n\n",
            s->name);
    fprintf(fp, "words = '%s%s file yade.csv'\n", s->servo_words, frame_words(s, "yade"));
    fprintf(fp, "servo_bc.run_case('packing.yade', words, density=%s, kn=%s, ks=%s, mu=%s, dt=%s", num(c->density).s,
            num(s->law.kn).s, num(s->law.ks).s, num(s->law.mu).s, num(c->dt).s);
    if (c->dim == 3)
        fprintf(fp, ", dimension=3");
    if (s->cohesive)
        fprintf(fp, ",\n                  cohesive='%s'", cohesive_words(&s->bond_law).s);
    fprintf(fp, ")\n");
    return close_file(fp, path, err);
}

sbc_status sbc_runner_write_decks(sbc_script_case *s, const char *dir, sbc_error *err)
{
    static const char *format[4] = {"text", "lammps", "liggghts", "yade"};
    static const char *file[4] = {"packing.txt", "packing.lammps.data", "packing.liggghts.data", "packing.yade"};
    char path[2 * SBC_NAME_LEN];
    int k, n;
    double rmin = HUGE_VAL, rmax = 0.0, fraction = 0.0;
    const double *radius;
    case_material c = {2, s->density, s->dt};
    sbc_status st = SBC_OK;
    if (s->bpm) { /* after 'dimension 3': the sphere packing and the 3D material */
        c.dim = 3;
        sbc_script_bpm_material(s, &c.density, &c.dt, &fraction);
        if (!s->x3) return sbc_fail(err, SBC_ERR_INPUT, "--decks: no sphere packing (use 'lattice cubic ...' or "
                                    "'read_packing FILE')");
        if (!(c.density > 0.0)) return sbc_fail(err, SBC_ERR_INPUT, "--decks: no density (use 'density RHO')");
        if (!(c.dt > 0.0))
            return sbc_fail(err, SBC_ERR_INPUT, "--decks: no time step in seconds (use 'timestep DT'; the hosts take "
                            "no 'timestep critical')");
    } else {
        if (!s->have_packing) return sbc_fail(err, SBC_ERR_INPUT, "--decks: no packing (use 'lattice', 'read_packing' or 'generate')");
        if (!s->have_density) return sbc_fail(err, SBC_ERR_INPUT, "--decks: no density (use 'density RHO')");
        if (!s->have_dt) return sbc_fail(err, SBC_ERR_INPUT, "--decks: no time step (use 'timestep DT')");
    }
    if (!s->have_contact) return sbc_fail(err, SBC_ERR_INPUT, "--decks: no contact law (use 'contact frictional ...')");
    if (!s->have_servo) return sbc_fail(err, SBC_ERR_INPUT, "--decks: no boundary condition (use 'servo_bc BC ...')");
    if (s->settings.frame_group[0])
        return sbc_fail(err, SBC_ERR_INPUT, "--decks: servo_bc keyword 'frame' names a host group '%s'; the decks "
                                            "take the frame of the packing", s->settings.frame_group);
    if (s->decks_line)
        return sbc_fail(err, SBC_ERR_INPUT, "--decks: a second run (the first is on line %d); --decks writes the case "
                        "of one run into '%s': give each run a script of its own", s->decks_line, dir);
    if ((st = decks_folder(s, dir, err)) != SBC_OK)
        return st;
    s->decks_line = s->line;
    n = c.dim == 3 ? s->n3 : s->packing.n;
    radius = c.dim == 3 ? s->r3 : s->packing.r;
    for (k = 0; k < n; ++k)
        rmin = fmin(rmin, radius[k]), rmax = fmax(rmax, radius[k]);
    for (k = 0; k < 4 && st == SBC_OK; ++k) {
        snprintf(path, sizeof path, "%s/%s", dir, file[k]);
        st = c.dim == 3 ? sbc_script_write_spheres(s, format[k], path, err)
                        : sbc_script_write_packing_as(s, format[k], path, err);
    }
    /* neighbour skin R_min / 4, as the hand-written decks */
    if (st == SBC_OK) st = write_embedded(s, &c, dir, err);
    if (st == SBC_OK) st = write_lammps(s, &c, dir, 0.25 * rmin, rmax, err);
    if (st == SBC_OK) st = write_liggghts(s, &c, dir, 0.25 * rmin, rmax, err);
    if (st == SBC_OK) st = write_yade(s, &c, dir, err);
    return st;
}
