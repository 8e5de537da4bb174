/* servo_bc: the dynamic-relaxation criterion (paper eqs. 11-12).
 *
 * Relaxed when Ek/Ep <= tolE holds for `window` consecutive steps (the paper
 * uses 20). Our reading, stated because the paper does not: steps count only
 * after the kinetic energy of this relaxation has passed a maximum (risen,
 * then stopped rising). Right after the frame moves, the interior is nearly
 * at rest and Ek/Ep is tiny for hundreds of steps although the forces are
 * unbalanced; with the literal criterion the paper's 25-particle (D) case is
 * "relaxed" 21 steps after every frame move, i.e. not relaxed at all. A step
 * with Ek exactly 0 (no interior motion at all) always counts. With Ep = 0
 * (no loaded contact) only Ek = 0 counts. Hosts sum Ek over the interior
 * particles that carry a force or moment: a contact-free rattler keeps its
 * spin for good (local damping acts through the force), and counted it would
 * hold Ek above tolE Ep forever (measured: the 455-particle frictional layer of
 * Sect. 5.3 at F12 = 0.144, Ek = 4.5e-5 J).
 *
 * A packing that starts balanced (the affine lattice at F = I) moves only by
 * round-off forces; its Ek grows like t^2 and may never pass a maximum
 * (measured on the 100-particle lattice: 5979 steps in the embedded engine,
 * 2.5e6 in YADE, none within 1e7 steps in LIGGGHTS). In a relaxation that
 * starts with the frame where it was (increment 0 of (D), or after a servo
 * correction below the round-off of the frame positions), a step below the
 * round-off floor Ek/Ep <= SBC_RELAX_ROUNDOFF therefore counts without a
 * maximum (still only when Ek/Ep <= tolE). Not after a real frame move: a
 * servo correction near convergence moves the frame by picometres, and its
 * relaxation starts below the floor although the interior is not yet in
 * balance with the new frame. */
#ifndef SBC_RELAX_H
#define SBC_RELAX_H

#define SBC_RELAX_ROUNDOFF 1e-20

typedef struct sbc_relax {
    double tol_E;   /* tolerance on Ek/Ep */
    int window;     /* consecutive steps required */
    long steps;     /* steps since sbc_relax_start */
    int count;      /* current run of steps satisfying the criterion */
    int rising;     /* Ek has risen in this relaxation */
    int past_peak;  /* ... and then stopped rising */
    int at_rest;    /* the frame was not moved: the round-off floor applies */
    double ek_prev; /* Ek of the previous step, J */
    long known_step;  /* step of the last measured Ep in this relaxation, 0: none */
    double ep_known;  /* that Ep, J */
    double ek_known;  /* the Ek of that step, J */
} sbc_relax;

/* Ep passed to sbc_relax_update for a step on which it was not measured. */
#define SBC_RELAX_EP_UNMEASURED (-1.0)

/* at_rest: the frame was left where it was before this relaxation */
void sbc_relax_start(sbc_relax *r, double tol_E, int window, int at_rest);

/* Records one step with interior kinetic energy ek and potential energy ep
 * (J); returns 1 when the criterion has held for the whole window. */
int sbc_relax_update(sbc_relax *r, double ek, double ep);

/* Whether the next sbc_relax_update, with kinetic energy ek, needs Ep; when it
 * does not, the host may skip its contact sum and pass
 * SBC_RELAX_EP_UNMEASURED, and the criterion decides exactly as with the
 * measured Ep. Ep is not needed for Ek = 0, nor when an upper bound of Ep
 * already fails eq. 11 (before the kinetic-energy maximum, at rest: the floor): during a
 * relaxation the frame stands still, so the interior only loses energy
 * (local damping, sliding) and Ep <= Ep_m + Ek_m - Ek for a measured step m
 * of the same relaxation (Ep is measured on its first step). Ep is needed when
 * Ek <= 2 limit (Ep_m + Ek_m - Ek), limit: the ratio that may count;
 * the factor 2 covers the integrator's energy error and energy handed over
 * by freely spinning frame particles (T), and Ep is measured at least every
 * SBC_RELAX_EP_REFRESH steps in case something else works on the packing. */
#define SBC_RELAX_EP_REFRESH 100
int sbc_relax_needs_potential(const sbc_relax *r, double ek);

#endif
