/* servo_bc: the keyword grammar shared by every host (docs/servo_bc.md).
 *
 *   servo_bc BC keyword value ...        BC = D | P | T | mixed
 *
 * Hosts pass the words after "servo_bc" (LAMMPS: after the fix style) to
 * sbc_settings_parse; the same words mean the same thing everywhere. */
#ifndef SBC_SETTINGS_H
#define SBC_SETTINGS_H

#include <stddef.h>

#include "sbc/relax.h"
#include "sbc/numbers.h"
#include "sbc/status.h"
#include "sbc/tensor.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sbc_bc { SBC_BC_D = 0, SBC_BC_P, SBC_BC_T, SBC_BC_MIXED } sbc_bc;

#define SBC_NAME_LEN 256

/* Mixed boundary conditions (Sect. 5): how one displacement component of one
 * edge is controlled. D: follows the prescribed F path (eq. 17 componentwise);
 * P: periodic with the opposite edge, both components and the rotation
 * (eq. 19); T: uniform traction a_q,c = P_cj A_q,j under servo control (eq. 48). */
/* How a servo iteration turns residuals into frame corrections: the paper's
 * fixed gains (eqs. 33, 34, 36, 48), those corrections scaled by a secant
 * (Barzilai-Borwein) factor learned from the last two iterations, or the
 * Newton correction of the host's linearized contact network (the
 * condensed stiffness; controller.h, sbc_newton_fn). */
typedef enum sbc_update { SBC_UPDATE_FIXED = 0, SBC_UPDATE_SECANT, SBC_UPDATE_NEWTON } sbc_update;

/* What dissipates the interior's kinetic energy during a relaxation: nothing,
 * the local non-viscous damping of eq. 10, or FIRE (fire_damping.h). */
typedef enum sbc_damping { SBC_DAMPING_NONE = 0, SBC_DAMPING_LOCAL, SBC_DAMPING_FIRE } sbc_damping;

typedef enum sbc_mode { SBC_MODE_D = 0, SBC_MODE_P, SBC_MODE_T } sbc_mode;

/* How the interior reaches each new position of the frame: dynamic
 * relaxation (the host's own dynamics with damping), or a static
 * equilibrium solved by Newton on the contact network (docs/servo_bc.md,
 * "Interior"; the embedded 2D runner). */
typedef enum sbc_interior { SBC_INTERIOR_DYNAMIC = 0, SBC_INTERIOR_NEWTON } sbc_interior;

/* The tangent C = dP/dF the runner writes per converged increment (keyword
 * tangent; material_point.h gives the three). */
typedef enum sbc_tangent {
    SBC_TANGENT_NONE = 0,
    SBC_TANGENT_AFFINE,
    SBC_TANGENT_CONDENSED,
    SBC_TANGENT_PERTURBATION
} sbc_tangent;

/* "affine", "condensed", "perturbation" ("none" for SBC_TANGENT_NONE) */
const char *sbc_tangent_name(sbc_tangent t);

/* The faces of the frame's box, indexed 2 axis + (1 on the high side), the
 * bit index of SBC_FACE_* (frame.h): xlo xhi ylo yhi zlo zhi. The 2D
 * edges are faces: left xlo, right xhi, bottom ylo, top yhi. */
enum { SBC_FACES_MAX = 6 };
enum { SBC_EDGE_LEFT = 0, SBC_EDGE_RIGHT = 1, SBC_EDGE_BOTTOM = 2, SBC_EDGE_TOP = 3 };

typedef struct sbc_stress_spec {
    int i, j;     /* component P_ij, 0-based */
    double value; /* final prescribed first Piola-Kirchhoff stress, N/m */
} sbc_stress_spec;

typedef struct sbc_settings {
    sbc_bc bc;
    int dim;                 /* the words' dimension: 3 when F has nine values, else 2 (the host holds
                                it to its packing's: sbc_settings_check_dimension); 2 */
    double F[9];             /* final macroscopic F, 3 x 3 slots (tensor.h); F ramps from I; default I */
    int increments;          /* loading increments i_tot; default 1 */
    sbc_criterion criterion; /* when a relaxation is over (relax.h): force balance (keyword balance) or
                                Ek/Ep (keyword relax); force */
    double tol_balance;      /* force balance: mean |net force| / mean |contact force| <= this; preset */
    double tol_E;            /* energy: Ek/Ep <= tol_E (eq. 11); 1e-3 */
    int window;              /* ... held for this many consecutive steps; 20 */
    double speed;            /* largest frame speed while the frame moves to new commands, in radii per
                                critical time step 2 sqrt(M_q / (2 kn)); 0: in one time step (the paper's
                                literal algorithm); preset */
    long max_relax_steps;    /* a relaxation longer than this stops the run; 1e7 */
    sbc_damping damping;     /* on interior particles; preset (fire; local for `paper`) */
    double alpha, beta;      /* translational, rotational damping of eq. 10; 0.7, 0.7 (with FIRE, beta
                                still damps the free frame rotations of (T)) */
    double gain_force;       /* dimensionless g_a M / dt^2 (Table 4); 1e2 */
    double gain_moment;      /* dimensionless g_m M R^2 / dt^2 (Table 4); 2e2 */
    double gain_deformation; /* dimensionless g_F R^2 (Table 4); 2e-5 */
    double tol_force;        /* eps_a (Table 4); 1e-6 */
    double tol_moment;       /* eps for the moment part of r_a; 1e-6 */
    double tol_deformation;  /* eps_F (Table 4); 1e-2 */
    double tol_relative;     /* > 0: force and moment residuals relative to the frame's own forces
                                (servo.h) must fall below this instead of tol_force, tol_moment; 0 */
    double predict;          /* inheritance factor n_f in [0, 1]; 0 = no prediction */
    int max_iterations;      /* servo iterations per increment; 100000 */
    int seal;                /* 1: the edges of the frame's polygon are walls for the interior (seal.h); 0 */
    int rotation_zero;       /* T only: 1 (rotation zero): the frame's rotations held at zero, as (D) holds them;
                                0 (rotation free): the paper's free rotation (docs/frame3d.md, "(T) and the
                                frame's rotations") */
    int remap;               /* 1 (remap x): while the frame travels to an increment's first commands, the
                                interior follows the affine part of the change of F (controller.h,
                                sbc_controller_remap), the default of the presets fast, balanced
                                and tight; 0 (remap none), accuracy paper's */
    sbc_update update;       /* fixed (the paper's) or secant; fixed */
    sbc_interior interior;   /* keyword interior: dynamic (every host) or newton (the embedded 2D runner; the
                                frame then jumps to its commands, speed 0 and remap none); dynamic */
    char accuracy[16];       /* preset in force (keyword accuracy; balanced by default) */
    /* mixed only: face_mode[face][component] (faces as above, components 0 = x,
       1 = y, 2 = z); the default is the paper's layer: 2D bottom D D, right P P,
       top D T, left P P; 3D zlo D D D, zhi D D T, the four side faces P P P */
    unsigned char face_mode[SBC_FACES_MAX][SBC_DIM_MAX];
    unsigned char face_given;      /* mixed: bit f set when the words name face f */
    unsigned char edge_given;      /* mixed: bit f set when a 2D edge keyword (bottom, right, top, left) named it */
    int nstress;                   /* prescribed stress components (keyword stress) */
    sbc_stress_spec stress[9];
    int stress_increments;         /* i_vs: increments of the stress stage (all stress keywords alike) */
    char frame_group[SBC_NAME_LEN]; /* host group of frame particles; "" = detect */
    char file[SBC_NAME_LEN];        /* CSV path; "" = none */
    sbc_tangent tangent;            /* keyword tangent: the runner's; none */
    char tangent_file[SBC_NAME_LEN]; /* its CSV path */
    char ignored[192];              /* the servo's keywords given to (D), which has no servo (hosts warn);
                                       "" = none */
} sbc_settings;

/* The defaults listed above: the `balanced` preset, and paper Table 4 for
 * what no preset sets. */
sbc_settings sbc_settings_default(void);

/* Presets of keyword `accuracy` (docs/servo_bc.md, Accuracy): each sets the
 * relaxation criterion and its tolerance, the tolerances, tol_relative,
 * update and speed; keywords given with it win, wherever they stand. Returns
 * 0 for an unknown name. */
int sbc_settings_preset(sbc_settings *s, const char *name);

/* The relative stress error a preset guarantees at a converged increment
 * (docs/servo_bc.md), 0 for `paper`, which guarantees none; -1 for an
 * unknown name. */
double sbc_settings_preset_accuracy(const char *name);

/* Parses words[0] = BC and the keyword/value pairs after it into *s, which
 * is first reset to the defaults. On error the message names the keyword,
 * the offending value and what was expected, e.g.
 *   keyword 'relax': tolE value 'abc' is not a number (expected a real > 0) */
sbc_status sbc_settings_parse(sbc_settings *s, int nwords, const char *const *words, sbc_error *err);

/* sbc_settings_parse on the words of one string ("P accuracy balanced F 1
 * 0.01 0 1"), split at blanks. */
sbc_status sbc_settings_parse_words(sbc_settings *s, const char *words, sbc_error *err);

/* Holds the words to the dimension dim of the host's packing: words
 * without a deformation (no F, or F 1 0 0 1) take dim; otherwise F's values
 * must be dim x dim (4 or 9), and mixed conditions and stresses are 2D. On
 * error the message says which F the words give and what the packing
 * expects. */
sbc_status sbc_settings_check_dimension(sbc_settings *s, int dim, sbc_error *err);

/* What a host's fix (LAMMPS, LIGGGHTS, YADE, the C API's host) cannot serve,
 * refused by name: the keyword tangent, which is the embedded runner's. */
sbc_status sbc_settings_check_host(const sbc_settings *s, sbc_error *err);

/* The warning a host prints when the words give (D) the servo's keywords
 * (settings.ignored): 1 with the message in out, 0 when there is none. */
int sbc_settings_ignored_message(const sbc_settings *s, char *out, size_t cap);

/* Total increments of the loading path: increments, plus the stress stage
 * of a mixed BC (i_vs + i_tot - i_vs in Table 5). */
int sbc_settings_total_increments(const sbc_settings *s);

/* The F imposed at increment i of the path, I + t (F - I): t = i / increments
 * (mixed: 0 during the stress stage, then (i - stress_increments) /
 * increments). */
void sbc_settings_target_F(const sbc_settings *s, int increment, double F[9]);

/* Name of a BC ("D", "P", "T", "mixed"). */
const char *sbc_bc_name(sbc_bc bc);


#ifdef __cplusplus
}
#endif

#endif
