/* servo_bc: when a relaxation is over (paper eqs. 11-12, and the force
 * balance that bounds the stress error).
 *
 * Two criteria; the settings choose one (keyword `balance` or `relax`).
 *
 * Force balance (the default). A step counts when
 *     U = max |net force| / mean |contact force| <= tol         (a)
 *     Ek <= tol^2 / 2 * Ep                                      (b)
 * and the relaxation is over after `window` consecutive counting steps. The
 * max is over the interior particles, the mean over the contacts (YADE's
 * unbalancedForce with useMaxForce). (a) is what the stress sees: the
 * homogenized stress of eq. 23 is the exact volume average when every
 * interior particle is in balance, and off by the order of U otherwise.
 * The max, not the mean: a servo correction unbalances the particles next
 * to the frame, and a mean over the interior dilutes that by the interior's
 * size (docs/servo_bc.md, "Accuracy", for both measured). (b) keeps a relaxation from ending while the packing swings
 * through its balanced position: for one vibration mode of force amplitude
 * u f_c per particle, Ek at the balanced position is about u^2/2 of Ep, so
 * (a) and (b) hold together only when the amplitude is below tol. Neither
 * depends on the time step. Absolute floor: a mean contact force below floor_force (N) counts as
 * floor_force, and an Ek below floor_energy (J, the energy of vibrations of
 * force amplitude floor_force on every particle) counts as rest: a
 * stress-free packing (touching discs, overlaps of round-off size) or one
 * that has come apart in tension relaxes once its forces fall to round-off
 * instead of chasing a ratio of two round-off numbers. A net force below
 * SBC_RELAX_NET_FLOOR floor_force counts as balanced whatever tol says:
 * tol floor_force would sit at the round-off of the forces themselves
 * (kn eps L, eps = 2.2e-16) for tol 1e-5, below it for 1e-8. floor_force
 * = kn 1e-10 (L + R) (controller.c), so this is 1e3 times the round-off and
 * 1e-11 of a contact force of kn L / 10: far below every preset's accuracy.
 *
 * Energy (the paper's eq. 11, kept as an alternative): Ek/Ep <= tol_E held
 * for `window` consecutive steps. Our reading, stated because the paper does
 * not: steps count only after the kinetic energy of this relaxation has passed
 * a maximum (risen, then stopped rising). Right after the frame moves, the
 * interior is nearly at rest and Ek/Ep is tiny for hundreds of steps although
 * the forces are unbalanced (docs/servo_bc.md, "The paper's relaxation
 * criterion", for the measurement). A step
 * with Ek exactly 0 always counts; with Ep = 0 only Ek = 0 counts. In a
 * relaxation that starts with the frame where it was, a step below the
 * round-off floor Ek/Ep <= SBC_RELAX_ROUNDOFF counts without a maximum (a
 * balanced lattice moves only by round-off forces, and its Ek may never pass
 * a maximum). Ek/Ep <= tol_E bounds the stress error only as ~sqrt(tol_E),
 * and the relaxation may end while forces are still swinging
 * (docs/servo_bc.md); it is what `accuracy paper` uses.
 *
 * Hosts sum Ek and the net forces over the interior particles that carry a
 * force or moment: a contact-free rattler keeps its spin for good (local
 * damping acts through the force). */
#ifndef SBC_RELAX_H
#define SBC_RELAX_H

#ifdef __cplusplus
extern "C" {
#endif

#define SBC_RELAX_NET_FLOOR 1e-3
#define SBC_RELAX_ROUNDOFF 1e-20

typedef enum sbc_criterion { SBC_CRITERION_FORCE = 0, SBC_CRITERION_ENERGY } sbc_criterion;

/* Ep (and the other contact sums) passed for a step on which they were not
 * measured. */
#define SBC_RELAX_EP_UNMEASURED (-1.0)

/* What a host measures on one step. */
typedef struct sbc_relax_sample {
    double ek;          /* Ek of the interior particles that carry a force, J */
    double ep;          /* Ep of all contacts (eq. 12), J; SBC_RELAX_EP_UNMEASURED if not measured */
    double net_max;     /* largest |net contact force| on an interior particle, N */
    double contact_sum; /* sum of |contact force| over the contacts, N (measured with ep) */
    long contact_count; /* contacts */
} sbc_relax_sample;

typedef struct sbc_relax {
    sbc_criterion criterion;
    double tol;          /* force: tol on U; energy: tol on Ek/Ep */
    int window;          /* consecutive steps required */
    double floor_force;  /* force: smallest mean contact force that scales U, N */
    double floor_energy; /* force: smallest Ep that scales Ek, J */
    long steps;          /* steps since sbc_relax_start */
    int count;           /* current run of steps satisfying the criterion */
    int rising;          /* energy: Ek has risen in this relaxation */
    int past_peak;       /* energy: ... and then stopped rising */
    int at_rest;         /* energy: the frame was not moved: the round-off floor applies */
    double ek_prev;      /* Ek of the previous step, J */
    long known_step;     /* step of the last measured contact sums in this relaxation, 0: none */
    double ep_known;     /* that Ep, J */
    double ek_known;     /* the Ek of that step, J */
    double fc_known;     /* force: the mean contact force of that step, N */
    double unbalanced;   /* U of the last step with measured contact sums, reported: against the mean
                            contact force, or below the floor against the path's (path_force) */
    double net_known;    /* the largest net force of that step, N */
    double path_force;   /* the largest mean contact force of the loading path's converged increments, N */
} sbc_relax;

/* The path floor: a state whose mean contact force has fallen below
 * SBC_RELAX_PATH_FLOOR of the path's (path_force) is judged against that
 * fraction of the path's forces, not its own: a stress-free state of a
 * mechanism (a frictionless lattice under (T) that slid out of contact) has
 * forces of round-off size whose ratios mean nothing, and its stress error
 * relative to the path's stress scale is what a preset can state. */
#define SBC_RELAX_PATH_FLOOR 1e-6

/* The force below which contact forces count as the floor (N): the larger of
 * floor_force and SBC_RELAX_PATH_FLOOR path_force. */
double sbc_relax_scale_floor(const sbc_relax *r);

/* A converged increment's mean contact force fc (N) joins the path's scale. */
void sbc_relax_path(sbc_relax *r, double fc);

/* Whether the last measured step meets the force criterion's (a): U <= tol,
 * or a net force below SBC_RELAX_NET_FLOOR floor_force (round-off). */
int sbc_relax_balanced(const sbc_relax *r);

/* at_rest: the frame was left where it was before this relaxation (energy
 * criterion only). The floors are kept from the previous start (set them
 * with sbc_relax_floor). */
void sbc_relax_start(sbc_relax *r, sbc_criterion criterion, double tol, int window, int at_rest);

/* Absolute floors of the force criterion: forces below floor_force (N) are
 * round-off; energies below floor_energy (J) too. Starts the path's scale
 * (path_force) at 0: call it once per loading path, before sbc_relax_start. */
void sbc_relax_floor(sbc_relax *r, double floor_force, double floor_energy);

/* Records one step; returns 1 when the criterion has held for the whole
 * window. */
int sbc_relax_update(sbc_relax *r, const sbc_relax_sample *s);

/* Whether the next sbc_relax_update needs the contact sums (Ep, contact
 * force sum), given the cheap part of the sample (ek, net_sum, net_count).
 * When it does not, the host may skip its contact pass and pass
 * SBC_RELAX_EP_UNMEASURED; the criterion decides exactly as with the
 * measured sums. Force: needed when (a) may hold, judged with twice the last
 * measured mean contact force, and at least every SBC_RELAX_EP_REFRESH steps.
 * Energy: not for Ek = 0, nor when an upper bound of Ep already fails eq. 11
 * (Ep <= Ep_m + Ek_m - Ek for a measured step m of the same relaxation, the
 * frame standing still; factor 2 for the integrator's energy error). */
#define SBC_RELAX_EP_REFRESH 100
int sbc_relax_needs_contacts(const sbc_relax *r, const sbc_relax_sample *s);

#ifdef __cplusplus
}
#endif

#endif
