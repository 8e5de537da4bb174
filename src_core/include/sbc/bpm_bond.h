/* servo_bc: 3D bond laws of the bonded particle model (thesis Chapter 3.2) as
 * pure kernels on per-bond state, usable by the embedded 3D engine (bpm.h)
 * and by any host.
 *
 * Conventions. A bond joins particle A (centre xa) and particle B (centre xb).
 * Vectors are global unless named _l (local). Increments are the motion of one
 * time step: du = displacement increment (m), dth = rotation increment (rad),
 * both taken from the velocities of the step (du = v dt, dth = omega dt).
 * Forces and moments are those acting ON the particles (N, N m). */
#ifndef SBC_BPM_BOND_H
#define SBC_BPM_BOND_H

#include "sbc/tensor.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SBC_PI 3.14159265358979323846

/* Local frame of a bond, eqs. 4-8: rows T[0] = x^ (centre line A -> B,
 * eq. 5), T[1] = y^ = x^ x e_z / |.| (eq. 6), or e_y when x^ and e_z are
 * collinear (eq. 7), T[2] = z^ = x^ x y^ / |.| (eq. 8). A vector u goes to
 * local coordinates as T u and back as T^T u (T is orthonormal).
 * Returns the bond length L_b = |xb - xa| (m). */
double sbc_bond_frame(const double xa[3], const double xb[3], double T[3][3]);

/* Cross-section of a bond of radius rb (m), eqs. 9, 18, 19. */
static inline double sbc_bond_area(double rb) { return SBC_PI * rb * rb; }
static inline double sbc_bond_inertia(double rb) { return 0.25 * SBC_PI * rb * rb * rb * rb; }
static inline double sbc_bond_polar(double rb) { return 0.5 * SBC_PI * rb * rb * rb * rb; }

/* ---- Parallel bond, eqs. 9-22 ------------------------------------------- */

typedef struct sbc_parallel_bond_law {
    double kn; /* normal stiffness per unit area k^n, Pa/m (Table 3: E_b / 2 r_p) */
    double ks; /* shear stiffness per unit area k^s, Pa/m (Table 3: k^n / 4.2) */
} sbc_parallel_bond_law;

/* Per-bond state: the forces and moments the bond applies to particle A,
 * split on the contact plane (B carries the opposite force; its moment is
 * given by sbc_parallel_bond_apply). */
typedef struct sbc_parallel_bond {
    double rb;    /* bond radius alpha r_min, m (eq. 9) */
    double fn[3]; /* normal force on A, N (eq. 10) */
    double fs[3]; /* shear force on A, N (eq. 11) */
    double mn[3]; /* twisting moment on A, N m (eq. 16) */
    double ms[3]; /* bending moment on A, N m (eq. 17) */
} sbc_parallel_bond;

/* Geometry of the bond: unit normal n (A -> B) and the contact point on the
 * centre line, halfway across the gap (x_c = xa + (ra + (L - ra - rb)/2) n,
 * m). Returns the length L = |xb - xa| (m). */
double sbc_parallel_bond_geometry(const double xa[3], double ra, const double xb[3], double rb, double n[3],
                                  double xc[3]);

/* One increment, eqs. 10-11 and 15-17: the relative displacement of A
 * against B at the contact point (eq. 14 times dt),
 *   du = (dxa + dtha x (xc - xa)) - (dxb + dthb x (xc - xb)),
 * split on the normal n (unit, A -> B) into du_n = (du.n) n and du_s; the
 * relative rotation dth = dtha - dthb (eq. 15) into dth_n and dth_s. The
 * bond resists: fn -= k^n A du_n, fs -= k^s A du_s, mn -= k^s J dth_n,
 * ms -= k^n I dth_s (forces on A). */
void sbc_parallel_bond_increment(const sbc_parallel_bond_law *law, sbc_parallel_bond *bond, const double n[3],
                                 const double du[3], const double dth[3]);

/* Resultant on the particles, eqs. 20-22: force on A = fn + fs, on B the
 * opposite; moment on A = mn + ms + (xc - xa) x fs, on B = -(mn + ms) +
 * (xc - xb) x (-fs). Adds to fa, ma, fb, mb. */
void sbc_parallel_bond_apply(const sbc_parallel_bond *bond, const double xa[3], const double xb[3],
                             const double xc[3], double fa[3], double ma[3], double fb[3], double mb[3]);

/* Strain energy of eq. 50, J. */
double sbc_parallel_bond_energy(const sbc_parallel_bond_law *law, const sbc_parallel_bond *bond);

/* ---- Timoshenko beam, eqs. 23-34 ---------------------------------------- */

typedef struct sbc_beam_law {
    double E;  /* Young's modulus E_b, Pa */
    double nu; /* Poisson's ratio nu_b, - */
} sbc_beam_law;

/* Timoshenko shear coefficient, eq. 31: Phi = 12 f_s E I / (G A L^2) with
 * f_s = 10/9, G = E / 2(1 + nu), which for a circular section is
 * 20 rb^2 (1 + nu) / (3 L^2). */
double sbc_beam_phi(double nu, double rb, double L);

/* The 12 x 12 stiffness of eqs. 26-30 (Przemieniecki) for a beam of radius
 * rb and length L, in the local frame, for the local vector of eq. 25
 * (du_A, dth_A, du_B, dth_B). Row-major K[12][12]. */
void sbc_beam_stiffness(const sbc_beam_law *law, double rb, double L, double K[12][12]);

/* Per-bond state: the frame T and the stiffness fixed at creation (small
 * deformations, Sect. 3.2.3), and the accumulated local end loads f_l = K u_l
 * (eq. 24; the loads the particles apply to the beam ends). K of eq. 26 has
 * six distinct entries, kept as k[]: E A / L, 12 E I / L^3 (1 + Phi),
 * 6 E I / L^2 (1 + Phi), G J / L, E I (4 + Phi) / L (1 + Phi),
 * E I (2 - Phi) / L (1 + Phi); the increment multiplies by them directly
 * (the same product as the full matrix, 24 terms instead of 144). */
typedef struct sbc_beam_bond {
    double T[3][3];
    double k[6];
    double f[12];
    double w; /* strain energy, J: the trapezoidal sum of the increments */
} sbc_beam_bond;

/* Creates the bond state between centres xa and xb with radius rb. */
void sbc_beam_bond_init(const sbc_beam_law *law, double rb, const double xa[3], const double xb[3],
                        sbc_beam_bond *bond);

/* K du_l for the local vector of eq. 25 (dl[12]), into df[12]. */
void sbc_beam_bond_product(const sbc_beam_bond *bond, const double ul[12], double df[12]);

/* One increment, eqs. 32 and 23: du_l = diag(T, T, T, T) (dxa, dtha, dxb,
 * dthb), f_l += K du_l. Adds the strain-energy increment (f_old + f_new)/2 .
 * du_l (exact for the linear law) to bond->w and returns it (J). */
double sbc_beam_bond_increment(sbc_beam_bond *bond, const double dxa[3], const double dtha[3], const double dxb[3],
                               const double dthb[3]);

/* Resultant on the particles, eqs. 33-34: the beam ends push back, so
 * particle A gets -T^T f_l[0..2] and -T^T f_l[3..5], B the rest. Adds to fa, ma,
 * fb, mb. */
void sbc_beam_bond_apply(const sbc_beam_bond *bond, double fa[3], double ma[3], double fb[3], double mb[3]);

/* ---- Optional failure ------------------------------------------------------ */

/* Bond strength: the paper's eq. 8 (contact.h) in 3D with twisting. A bond
 * breaks for good when
 *   F_t / F_t,u + |F_s| / F_s,u + |M_b| / M_b,u + |M_t| / M_t,u >= 1
 * with F_t its normal force, tension positive (compression lowers the
 * criterion, as in our reading of the 2D eq. 8), F_s its shear force, M_b its
 * bending and M_t its twisting moment (for a beam the larger end moment). A
 * strength of 0 leaves its term out; tension <= 0 means no failure (the
 * default). */
typedef struct sbc_bond_strength {
    double tension;  /* F_t,u, N */
    double shear;    /* F_s,u, N */
    double bending;  /* M_b,u, N m */
    double twisting; /* M_t,u, N m */
} sbc_bond_strength;

/* The criterion's left-hand side for the loads (ft, fs, mb, mt). */
double sbc_bond_criterion(const sbc_bond_strength *s, double ft, double fs, double mb, double mt);

/* A bond's loads in the criterion's terms (n: unit A -> B). */
void sbc_parallel_bond_loads(const sbc_parallel_bond *bond, const double n[3], double out[4]);
void sbc_beam_bond_loads(const sbc_beam_bond *bond, double out[4]);

/* A broken bond becomes a frictional contact (the thesis' contact springs,
 * eqs. 12-13, with Coulomb's cap): while the spheres overlap by dn > 0 the
 * normal force on A is -kn dn n, the tangential spring force fs (on A) is
 * advanced by -ks du_s and capped at mu kn dn; apart, both vanish. No
 * moment but that of fs about the centres (eq. 20). w accumulates the work
 * done on the contact (trapezoidal), so that friction's share is
 * w - the elastic energy. */
typedef struct sbc_friction_law {
    double kn; /* N/m */
    double ks; /* N/m */
    double mu; /* - */
} sbc_friction_law;

typedef struct sbc_broken_bond {
    double fs[3]; /* tangential spring force on A, N */
    double f[3];  /* total force on A at the last step, N */
    double w;     /* work done on the contact, J */
} sbc_broken_bond;

/* One increment at overlap dn (m) with the relative displacement du of A
 * against B at the contact point (as sbc_parallel_bond_increment); writes
 * the force on A into f. */
void sbc_broken_bond_increment(const sbc_friction_law *law, sbc_broken_bond *c, double dn, const double n[3],
                               const double du[3], double f[3]);

/* Elastic energy of the contact: kn dn^2 / 2 + |fs|^2 / 2 ks, J. */
double sbc_broken_bond_energy(const sbc_friction_law *law, const sbc_broken_bond *c, double dn);

/* ---- Viscous bond damping, eqs. 35-37 ------------------------------------ */

/* Damping coefficient of one bond (N s/m), eqs. 36-37:
 * c = xi 2 sqrt(k m_red) / sqrt(C_n / 3), with m_red = ma mb / (ma + mb), k
 * the bond's axial stiffness (k^n A for the parallel bond, E A / L for the
 * beam) and C_n the coordination number (the mean over the two particles). */
double sbc_bond_damping(double xi, double k, double ma, double mb, double cn);

#ifdef __cplusplus
}
#endif

#endif
