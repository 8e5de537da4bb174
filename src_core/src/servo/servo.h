/* Private: residuals and corrections of the servo-controlled boundary
 * conditions (P) and (T) (paper Sect. 3.2, eqs. 32-37). */
#ifndef SBC_SERVO_H
#define SBC_SERVO_H

#include "sbc/frame.h"
#include "sbc/settings.h"

typedef struct sbc_servo_norms {
    /* with tol_relative > 0, r_force and r_moment are relative instead:
       sqrt(sum |da|^2 / sum |a_q|^2) and sqrt(sum dm^2 / sum (|a_q| R_q)^2)
       over the frame particles that enter the residuals */
    double r_force;       /* sqrt(sum |da|^2 / a~^2), eq. 37 normalization */
    double r_moment;      /* sqrt(sum (dm / m~)^2), (P) only */
    double r_deformation; /* sqrt(sum |dF_q|^2 / F~^2), (T) only */
    double relative_force; /* sqrt(sum |da|^2 / sum |a_q|^2) whatever the tolerances (round-off check) */
    double max_step;      /* largest correction, relative to the particle's radius */
} sbc_servo_norms;

/* Force floors of the relative norms, N (relax.h): frame forces below scale
 * count as scale; residuals whose root mean square per frame particle is
 * below roundoff count as none. */
typedef struct sbc_servo_floors {
    double scale;
    double roundoff;
} sbc_servo_floors;

/* Residual norms of the state (a [3Q] boundary forces, m [rQ] boundary
 * moments, r = SBC_ROTATIONS(dim), x [3Q] positions) and the corrections
 * (eqs. 33-34 for P, 36 for T) written to du [3Q] (m) and dtheta [rQ] (rad). F is the imposed
 * macroscopic deformation gradient, mass [Q] in kg, dt in s; kn (N/m) the
 * host's contact stiffness (0: unknown), for the secant update's gains; floors:
 * those of the relative norms. */
void sbc_servo_residuals(sbc_bc bc, const sbc_frame *f, const sbc_settings *s, const double *mass, double dt,
                         double kn, const sbc_servo_floors *floors, const double F[9], const double *a, const double *m, const double *x,
                         double *du, double *dtheta, sbc_servo_norms *out);

/* Mixed (D)-(P)-(T), Table 5 and eq. 48, with the modes per frame component
 * (mode [3Q], sbc_mode) and the stress targets P_star where P_fixed. */
void sbc_servo_mixed(const sbc_frame *f, const unsigned char *mode, const sbc_settings *s, const double *mass,
                     double dt, double kn, const sbc_servo_floors *floors, const double P_star[9], const unsigned char P_fixed[9],
                     const double *a, const double *m, double *du, double *dtheta, sbc_servo_norms *o);

#endif
