/* Private: the controller's tuning constants, a line each. Why each has its
 * value, with the measurements, is in docs/tuning.md. */
#ifndef SBC_TUNING_H
#define SBC_TUNING_H

/* a relaxation after a servo correction ends at INEXACT times the relative frame residual it corrected */
#define INEXACT 0.03
/* ... the first relaxation of an increment of (P), (T) or mixed at this unbalanced force ratio */
#define INEXACT_FIRST 1e-3
/* ... at INEXACT_LOOSE instead with FIRE when tol_relative >= LOOSE_FRAME_TOL (fast, balanced) */
#define INEXACT_LOOSE 0.3
#define LOOSE_FRAME_TOL 1e-5
/* update secant: no frame particle moves more than this many radii in one correction */
#define SECANT_MAX_STEP 0.002
/* update newton: the largest correction of a frame particle, of its radius
   (controller_update.c) */
#define NEWTON_MAX_STEP 0.05
/* update newton: the smallest factor on the Newton step (controller_update.c) */
#define NEWTON_LAMBDA_MIN 1e-2
/* update newton: corrections without a new smallest force residual before
   the increment goes on with the secant update (controller_update.c) */
#define NEWTON_PATIENCE 8
/* update secant with kn known: the factor on the scale-free corrections stays in [MIN, MAX] */
#define SECANT_LAMBDA_MIN 1e-2
#define SECANT_LAMBDA_MAX 1e2
/* stagnation on round-off: windows of this many servo iterations, checked when the force residual
 * is below STAGNATION_ROUNDOFF of the frame's forces */
#define STAGNATION_WINDOW 200
#define STAGNATION_ROUNDOFF 1e-9

#endif
