/* servo_bc: the embedded 3D bonded particle engine (thesis Chapter 3).
 *
 * Spheres with six degrees of freedom, bonds (parallel bond or Timoshenko
 * beam, bpm_bond.h) created between the spheres that touch at the start,
 * viscous bond dashpots (eqs. 35-37), position Verlet for translation and
 * rotation (eqs. 38-45), and the energy bookkeeping of eqs. 49-53.
 *
 * Time integration. Velocities live at half steps: v and w hold v(t - dt/2)
 * and omega(t - dt/2) when a step starts at time t. A step computes the bond
 * loads at t from the displacement increment dt v(t - dt/2) (incremental
 * laws), the dashpot forces from v(t - dt/2), then v(t + dt/2) (eqs. 40, 44)
 * and x(t + dt) (eqs. 41, 45).
 *
 * Prescribed degrees of freedom. Bit k of fix[i] (k = 0..2 translation x, y,
 * z; 3..5 rotation) prescribes that velocity component to vfix[6 i + k]; the
 * force the constraint exerts is kept in reaction[6 i + k] (N or N m).
 *
 * Energies (J). kinetic uses 1/2 m v(t - dt/2) . v(t + dt/2), the form the
 * position Verlet scheme conserves exactly; with it, strain energy by the
 * trapezoidal rule and the work of external, reaction and dashpot forces
 * paired with the same increments, eq. 53 holds to round-off for a linear
 * elastic bond network. With failure, the energy a bond held when it broke
 * and the work of friction in broken contacts count as dissipated, the
 * contacts' elastic energy as strain energy.
 *
 * Failure (optional, settings.strength): a bond whose criterion reaches 1
 * at a step breaks before its loads are applied; from then on the pair is a
 * frictional contact (bpm_bond.h) with kn the bond's axial stiffness and ks
 * = kn k^s/k^n (parallel bond) or kn / 2(1 + nu_b) (beam). Spheres that were
 * not bonded at the start never interact. */
#ifndef SBC_BPM_H
#define SBC_BPM_H

#include "sbc/bpm_bond.h"
#include "sbc/status.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sbc_bond_model { SBC_BOND_PARALLEL = 0, SBC_BOND_BEAM = 1 } sbc_bond_model;

typedef struct sbc_bpm_settings {
    sbc_bond_model model;
    sbc_parallel_bond_law parallel; /* k^n, k^s (Pa/m) when model is SBC_BOND_PARALLEL */
    sbc_beam_law beam;              /* E_b (Pa), nu_b when model is SBC_BOND_BEAM */
    double alpha;                   /* bond radius multiplier, eq. 9: r_b = alpha r_min (thesis: 1) */
    double xi;                      /* dashpot damping ratio of eq. 37, - */
    double touch;                   /* spheres bond when |xb - xa| <= (ra + rb)(1 + touch) */
    sbc_bond_strength strength;     /* optional failure (bpm_bond.h); tension <= 0: none (the default) */
    double mu;                      /* friction of a broken bond's contact, - */
} sbc_bpm_settings;

typedef struct sbc_bpm_bond {
    size_t a, b;
    double c; /* dashpot coefficient, N s/m (eq. 37) */
} sbc_bpm_bond;

typedef struct sbc_bpm_energy {
    double kinetic;   /* eq. 49 */
    double strain;    /* eq. 50 (parallel bond) or the beams' 1/2 u K u */
    double dissipated; /* eq. 51 */
    double external;  /* eq. 52: external loads and prescribed motion */
    double balance;   /* eq. 53: |W_kin + W_int + W_dis - W_ext| / max(components) (0 when all vanish) */
} sbc_bpm_energy;

typedef struct sbc_bpm {
    size_t n, cap;
    double *x, *v, *w;     /* position (m), velocity (m/s), angular velocity (rad/s); 3 per sphere */
    double *theta;         /* angular position, eq. 45 (rad); 3 per sphere */
    double *r, *m, *inertia; /* radius (m), mass (kg), 2/5 m r^2 (kg m^2) */
    double *fext;          /* external force and moment, 6 per sphere (N, N m) */
    unsigned char *fix;    /* prescribed degrees of freedom, bits 0..5 */
    double *vfix;          /* prescribed velocities, 6 per sphere */
    double *reaction;      /* constraint forces, 6 per sphere */
    double *load;          /* resultant force and moment at the last step, 6 per sphere */
    double *fwork_prev;    /* external + reaction loads of the last step, 6 per sphere */
    double *fdamp, *fdamp_prev; /* dashpot forces of this and the last step, 3 per sphere */
    unsigned *coordination; /* bonds per sphere */
    size_t nb, bcap;
    sbc_bpm_bond *bonds;
    sbc_parallel_bond *parallel; /* bond k's state, parallel bond model (else NULL) */
    sbc_beam_bond *beam;         /* bond k's state, beam model (else NULL) */
    unsigned char *broken;       /* bond k has failed (only with a strength) */
    sbc_broken_bond *contact;    /* bond k's contact once broken (only with a strength) */
    size_t nbroken;
    double w_fracture;           /* strain energy the broken bonds held, J (dissipated) */
    sbc_bpm_settings set;
    double dt;
    long step;
    double w_dis, w_ext, w_kin;
} sbc_bpm;

/* Thesis defaults (Table 3): Timoshenko beams, E_b = 4 GPa, nu_b = 0.3,
 * alpha = 1, k^n/k^s = 4.2 (k^n itself depends on r_p: sbc_bpm_parallel_law),
 * no damping, touch = 1e-9. */
sbc_bpm_settings sbc_bpm_settings_default(void);

/* Table 3: k^n = E_b / 2 r_p, k^s = k^n / ratio. */
sbc_parallel_bond_law sbc_bpm_parallel_law(double E, double rp, double kn_over_ks);

sbc_status sbc_bpm_create(const sbc_bpm_settings *set, sbc_bpm **out, sbc_error *err);
void sbc_bpm_free(sbc_bpm *e);

/* Adds a sphere at x with radius r (m) and density rho (kg/m^3); returns its
 * index in *index (may be NULL). */
sbc_status sbc_bpm_add(sbc_bpm *e, const double x[3], double r, double rho, size_t *index, sbc_error *err);

/* Bonds every pair of touching spheres (settings.touch), then sets the
 * dashpot coefficients from the coordination numbers (eq. 37). Call once,
 * after the last sbc_bpm_add. */
sbc_status sbc_bpm_bond_touching(sbc_bpm *e, sbc_error *err);

/* ---- One bond, wherever its state is kept --------------------------------
 * The embedded engine keeps its bonds' states in arrays; a host that keeps
 * them with its particles (per-atom slots that migrate between ranks,
 * bpm_host.h) calls the same functions one bond at a time. A view points at
 * one bond's state: beam for SBC_BOND_BEAM, parallel otherwise; broken and
 * contact only with a strength (else NULL). */
typedef struct sbc_bpm_bond_view {
    sbc_beam_bond *beam;
    sbc_parallel_bond *parallel;
    unsigned char *broken;
    sbc_broken_bond *contact;
} sbc_bpm_bond_view;

/* Spheres at xa and xb (radii ra, rb, m) bond: |xb - xa| <= (ra + rb)(1 + touch). */
int sbc_bpm_touch(const sbc_bpm_settings *set, const double xa[3], double ra, const double xb[3], double rb);

/* Calls found(i, j, user) for every touching pair i < j of the n spheres
 * (centres x [3n], radii r [n]) through a uniform grid of cells no smaller
 * than the largest bonding distance; stops at the first status found
 * returns other than SBC_OK, and returns it. */
typedef sbc_status (*sbc_bpm_pair_fn)(size_t i, size_t j, void *user, sbc_error *err);
sbc_status sbc_bpm_pairs(const sbc_bpm_settings *set, size_t n, const double *x, const double *r,
                         sbc_bpm_pair_fn found, void *user, sbc_error *err);

/* A new bond's state between A (xa, ra) and B (xb, rb): bond radius alpha
 * min(ra, rb) (eq. 9), no load; a beam's frame and stiffness from A -> B. */
void sbc_bpm_bond_start(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b, const double xa[3], double ra,
                        const double xb[3], double rb);

/* The bond's axial stiffness, N/m (eq. 36: k^n A, or E A / L for a beam). */
double sbc_bpm_bond_stiffness(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b);

/* One step of one bond at t (eqs. 10-34) from the motion dt v(t - dt/2),
 * dt w(t - dt/2) of its spheres A and B; adds its loads to fa, ma (on A) and
 * fb, mb (on B). With a strength, a bond whose criterion reaches 1 breaks
 * before its loads are applied: returns 1 with the strain energy it held in
 * *fracture (J), else 0. */
int sbc_bpm_bond_advance(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b, const double xa[3], double ra,
                         const double va[3], const double wa[3], const double xb[3], double rb, const double vb[3],
                         const double wb[3], double dt, double fa[3], double ma[3], double fb[3], double mb[3],
                         double *fracture);

/* The bond's energies at centres xa, xb (J): *strain its elastic energy
 * (eq. 50 or 1/2 u K u; a broken bond's contact: kn dn^2/2 + |fs|^2/2 ks),
 * *friction the work of friction in a broken bond's contact (0 intact). */
void sbc_bpm_bond_energies(const sbc_bpm_settings *set, const sbc_bpm_bond_view *b, const double xa[3], double ra,
                           const double xb[3], double rb, double *strain, double *friction);

/* Eq. 48: 0.22 sqrt(m / k) with the smallest mass and the largest bond axial
 * stiffness (k^n A for the parallel bond, E A / L for the beam), s; 0 when
 * there is no bond. */
double sbc_bpm_critical_dt(const sbc_bpm *e);

/* Eq. 48 from its two extremes: 0.22 sqrt(m_min / k_max) (kg, N/m), s; 0
 * when k_max is not positive. For a host that reduces them over ranks. */
double sbc_bpm_critical_dt_of(double mmin, double kmax);

/* The bonds' loads (force, moment: 6 per sphere, N and N m) at the centres
 * e->x, from the motion dt (v, w) of the step (eqs. 10-34), added to load;
 * the bonds' state advances by that step and failing bonds break. The step
 * of sbc_bpm_step, and the whole of a host's bond step (bpm_host.h). */
void sbc_bpm_bond_loads(sbc_bpm *e, double *load);

/* One time step of length e->dt. SBC_ERR_NUMERIC when a value stops being
 * finite (the step and the sphere are named). */
sbc_status sbc_bpm_step(sbc_bpm *e, sbc_error *err);

/* Energies after the last step. */
sbc_bpm_energy sbc_bpm_energies(const sbc_bpm *e);

/* Mean coordination number (bonds per sphere). */
double sbc_bpm_mean_coordination(const sbc_bpm *e);

#ifdef __cplusplus
}
#endif

#endif
