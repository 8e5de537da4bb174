/* Private: the embedded runner's state and argument helpers, shared by the
 * files that implement its commands (script.c, script_packing.c). */
#ifndef SBC_SCRIPT_STATE_H
#define SBC_SCRIPT_STATE_H

#include "sbc/embedded/script.h"
#include "sbc/contact.h"
#include "sbc/packing.h"
#include "sbc/settings.h"

#include <stdio.h>

#include "../host/aggregate.h"

#define MAX_WORDS 64

/* a file the script read or wrote (script_files.c) */
typedef struct sbc_file_id {
    unsigned long long dev, ino;
    int line;
    char role[24];
    char path[SBC_NAME_LEN];
} sbc_file_id;

#define SBC_SCRIPT_FILES 64

typedef struct sbc_script_case {
    const char *name;
    int line;
    FILE *log;
    sbc_packing packing;
    int have_packing, have_contact, have_density, have_dt, have_servo;
    sbc_frictional law;
    int cohesive;          /* 'contact cohesive': bonds between the pairs touching at the start */
    sbc_cohesive bond_law; /* eqs. 7-8 */
    double density, dt;
    sbc_settings settings;
    int servo_line;
    int dt_line;           /* the line of the last 'timestep': a time step refused at the run is reported there */
    int vtk_every;
    char vtk_prefix[SBC_NAME_LEN];
    int network_every;
    char network_prefix[SBC_NAME_LEN];
    char plot[SBC_NAME_LEN];
    char servo_words[2048]; /* the servo_bc words without 'file NAME', 'tangent KIND NAME' */
    const char *decks_dir;  /* --decks: 'run' writes the hosts' inputs here instead */
    sbc_script_decks_fn write_decks; /* ... with this writer (script.h) */
    int decks_line;         /* the line of the run whose decks were written (one run per --decks) */
    int check;              /* --check: every command is checked, nothing is run or written */
    struct bpm_script *bpm; /* after 'dimension 3': the 3D bonded particle model (script_bpm.c) */
    int n3;                 /* after 'dimension 3', 'lattice cubic': the sphere packing (script_spheres.c) */
    double *x3, *r3;        /* ... its centres [3 n3] and radii [n3], m */
    int actions;            /* commands that computed or wrote something (run, write_packing, rose) */
    int servo_pending;      /* a servo_bc line no run has used yet */
    int replicas;           /* replicas K: the runs that follow are K histories (script_replicas.c); 0: one */
    double perturb;         /* ... the interior's centres moved by up to this many radii in replicas 1 .. K-1 */
    int jobs;               /* ... replicas run at once */
    int replica;            /* the replica this process runs (0: the unperturbed one) */
    sbc_file_id files[SBC_SCRIPT_FILES], script_id;
    int nfiles;
} script;

/* script_files.c: remember PATH (read or written at this line, as ROLE:
 * "packing read", "results file", ...), and refuse to write WHAT 'PATH'
 * over the script or a remembered file. */
void sbc_script_files_note(script *s, const char *path, const char *role);
sbc_status sbc_script_files_check(script *s, const char *path, const char *what, sbc_error *err);
/* Before a run: its outputs (results file, plot, the vtk and network
 * snapshots) name neither the script, nor a file read or written before,
 * nor one another; with --check, each is probed (output_file.h). */
sbc_status sbc_script_outputs_check(script *s, sbc_error *err);

/* The log line of an increment's static solves (interior newton; script_log.c). */
void sbc_script_tally_line(const script *s, const sbc_statics_tally *t);

/* Keyword tangent (script_tangent.c): its file, opened by a run of
 * dimension dim after the refusals (mixed, cohesive contacts); a row per
 * converged increment from the driver's row callback, where `ctl` has just
 * accepted `row` and *fire is the driver's FIRE; closed with the run. */
typedef struct sbc_script_tangent {
    FILE *fp; /* NULL: no tangent */
    int dim;
} sbc_script_tangent;
sbc_status sbc_script_tangent_open(const script *s, int dim, sbc_script_tangent *t, sbc_error *err);
sbc_status sbc_script_tangent_row(const script *s, sbc_script_tangent *t, const sbc_aggregate *a,
                                  const sbc_controller *ctl, const sbc_fire_state *fire, const sbc_result *row,
                                  sbc_error *err);
void sbc_script_tangent_close(sbc_script_tangent *t);

/* The checks of a command's words (script_words.c).
 * "cmd: missing values / unexpected extra value" unless nw == want. */
sbc_status sbc_script_expect_count(int nw, char **w, int want, const char *usage, sbc_error *err);
/* word must equal key. */
sbc_status sbc_script_expect_key(const char *cmd, const char *word, const char *key, const char *usage,
                                 sbc_error *err);
/* A real > 0, named `what` in the message. */
sbc_status sbc_script_positive(const char *cmd, const char *what, const char *word, double *out, sbc_error *err);

/* Packing commands (script_packing.c). */
sbc_status sbc_script_generate(script *s, int nw, char **w, sbc_error *err);
sbc_status sbc_script_write_packing(script *s, int nw, char **w, sbc_error *err);
/* The packing in format text, lammps, liggghts or yade, the frame flagged. */
sbc_status sbc_script_write_packing_as(script *s, const char *format, const char *path, sbc_error *err);
sbc_status sbc_script_rose(script *s, int nw, char **w, sbc_error *err);

/* The 3D commands (script_bpm.c): 'dimension 3' begins them, every later
 * command goes to sbc_script_bpm. */
sbc_status sbc_script_bpm_begin(script *s, sbc_error *err);
sbc_status sbc_script_bpm(script *s, int nw, char **w, sbc_error *err);
void sbc_script_bpm_free(script *s);

/* The material of the 3D commands (script_bpm.c): density (kg/m^3) and time
 * step (s; or a fraction of the critical one), each 0 when not given. */
void sbc_script_bpm_material(const script *s, double *density, double *dt, double *dt_fraction);

/* The bonded model's one-word 'vtk PREFIX' (script_bpm.c), "" when not given. */
const char *sbc_script_bpm_vtk(const script *s);

/* The 3D servo_bc commands (script_spheres.c): 'lattice cubic NX NY NZ
 * spacing D radius R', and the run of a servo_bc line on the sphere engine
 * (spheres.h) through the host driver. */
sbc_status sbc_script_lattice_cubic(script *s, int nw, char **w, sbc_error *err);
/* read_packing FILE after 'dimension 3': x y z r per line */
sbc_status sbc_script_read_spheres(script *s, const char *path, sbc_error *err);
sbc_status sbc_script_run_spheres(script *s, sbc_error *err);
/* write_packing lammps|liggghts|yade FILE of the sphere packing, the frame flagged */
sbc_status sbc_script_write_spheres(script *s, const char *format, const char *path, sbc_error *err);
void sbc_script_spheres_free(script *s);

/* One run of the servo_bc line (script.c). */
sbc_status sbc_script_run_once(script *s, sbc_error *err);

/* One run of the case, as sbc_script_run_once. */
typedef sbc_status (*sbc_script_run_fn)(script *s, sbc_error *err);

/* replicas K [perturb EPS] [jobs J], and the runs it makes (script_replicas.c),
 * each by run_once. */
sbc_status sbc_script_replicas_command(script *s, int nw, char **w, sbc_error *err);
sbc_status sbc_script_replicas(script *s, sbc_script_run_fn run_once, sbc_error *err);

#endif
