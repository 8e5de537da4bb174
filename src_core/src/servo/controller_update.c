/* The controller's update rules: the fixed gains of Table 4 (servo.c) and
 * the secant update's factor; eq. 15 restored under (T) (controller_private.h). */
#include "controller_private.h"
#include "sbc/homogenize.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* (T): after a force correction, the frame is put back on the imposed F
 * (eq. 15) exactly, by the smallest change of the commands in the metric of
 * the area vectors:
 *   x_q += M S^-1 A_q,  M = F G - sum_r x_r (x) A_r,  S = sum_r A_r (x) A_r,
 * G = sum_r X_r (x) A_r (eq. 15 normalized as sbc_homogenize_F does), since
 * sum_q (M S^-1 A_q) (x) A_q = M. The force correction then only moves the
 * frame within the set of positions that keep F, and the deformation
 * residual of eq. 35 stays at round-off instead of being won back at
 * g_F per iteration (the stall near F12 = 0.2 of the irregular packing). */
void sbc_ctl_restore_eq15(sbc_controller *c)
{
    const sbc_frame *f = c->frame;
    const int dim = f->dim;
    const double *F = c->F_now;
    double S[9] = {0.0}, G[9] = {0.0}, X[9] = {0.0}, M[9] = {0.0}, Si[9];
    int q, i, j, k;
    for (q = 0; q < f->n; ++q) {
        const double *A = &f->A[3 * q];
        for (i = 0; i < dim; ++i)
            for (j = 0; j < dim; ++j) {
                S[SBC_IJ(i, j)] += A[i] * A[j];
                G[SBC_IJ(i, j)] += f->X[3 * q + i] * A[j];
                X[SBC_IJ(i, j)] += c->x_cmd[3 * q + i] * A[j];
            }
    }
    if (!sbc_tensor_inverse(dim, S, Si))
        return;
    for (i = 0; i < dim; ++i)
        for (j = 0; j < dim; ++j) {
            double FG = 0.0;
            for (k = 0; k < dim; ++k)
                FG += F[SBC_IJ(i, k)] * G[SBC_IJ(k, j)];
            M[SBC_IJ(i, j)] = FG - X[SBC_IJ(i, j)];
        }
    for (q = 0; q < f->n; ++q) {
        double b[3], shift[3];
        sbc_tensor_apply(dim, Si, &f->A[3 * q], b);
        sbc_tensor_apply(dim, M, b, shift);
        for (k = 0; k < dim; ++k)
            c->x_cmd[3 * q + k] += shift[k];
    }
}

/* Scales the correction d_k (du, R dtheta of every frame particle, m) by
 * lambda_k. Within an increment, from the previous correction d_(k-1) and
 * its factor, the Barzilai-Borwein step of the preconditioned iteration
 * x <- x + lambda d(x):
 *   s = lambda_(k-1) d_(k-1),  y = d_(k-1) - d_k  (~ P J s),
 *   lambda_k = s.y / y.y = lambda_(k-1) d_(k-1).(d_(k-1) - d_k) / |d_(k-1) - d_k|^2,
 * when s.y > 0; when s.y <= 0 (the residual did not fall along s) lambda
 * halves. The first correction of an increment keeps the factor the rule's
 * start left. lambda stays in [lo, hi] when hi > 0, and no frame particle
 * moves more than max_step of its radius in one correction. */
static void barzilai_borwein(sbc_controller *c, sbc_servo_norms *n, double lo, double hi, double max_step)
{
    const sbc_frame *f = c->frame;
    double dd = 0.0, dy = 0.0, yy = 0.0, lam = c->secant.lambda, cap = DBL_MAX;
    const int nd = SBC_CTL_STEP_PARTS(f->dim);
    int q, k;
    for (q = 0; q < f->n; ++q) {
        double d[2 * SBC_DIM_MAX], len = 0.0, *prev = &c->secant.d_prev[nd * q];
        for (k = 0; k < f->dim; ++k)
            d[k] = c->du[3 * q + k];
        for (k = 0; k < c->rot; ++k)
            d[f->dim + k] = f->R[q] * c->dtheta[c->rot * q + k];
        for (k = 0; k < nd; ++k)
            len += d[k] * d[k];
        len = sqrt(len);
        for (k = 0; k < nd; ++k) {
            double y = prev[k] - d[k];
            dd += d[k] * d[k];
            dy += prev[k] * y;
            yy += y * y;
            prev[k] = d[k];
        }
        if (len > 0.0 && max_step * f->R[q] / len < cap)
            cap = max_step * f->R[q] / len;
    }
    if (c->secant.have_prev)
        lam = dy > 0.0 && yy > 0.0 ? c->secant.lambda * dy / yy : 0.5 * c->secant.lambda;
    if (hi > 0.0)
        lam = fmin(fmax(lam, lo), hi);
    if (dd > 0.0) {
        c->secant.lambda = lam = fmin(lam, cap);
    } else {
        lam = c->secant.lambda; /* no correction to scale; the factor stays */
    }
    c->secant.have_prev = 1;
    for (k = 0; k < 3 * f->n; ++k)
        c->du[k] *= lam;
    for (k = 0; k < c->rot * f->n; ++k)
        c->dtheta[k] *= lam;
    n->max_step *= lam;
}

/* update secant: the fixed-gain correction of servo.c scaled by
 * barzilai_borwein, whose factor an increment takes over from the last; with
 * kn known (scale-free first steps, servo.c) it stays within two decades of
 * them; no frame particle moves more than SECANT_MAX_STEP of its radius,
 * which also bounds the first step whatever the gains. */
sbc_status sbc_ctl_secant_scale(sbc_controller *c, sbc_servo_norms *n, sbc_error *err)
{
    (void)err;
    barzilai_borwein(c, n, c->kn > 0.0 ? SECANT_LAMBDA_MIN : 0.0, c->kn > 0.0 ? SECANT_LAMBDA_MAX : 0.0,
                     SECANT_MAX_STEP);
    return SBC_OK;
}

/* update newton: the correction is the host's (sbc_newton_fn): the frame's
 * move that balances its reactions on the linearized contact network with
 * the interior condensed out, in place of servo.c's fixed-gain one, scaled
 * by barzilai_borwein from 1 at each increment's start (1 for a network
 * that stays linear; less where contacts open, close or slide on the way),
 * within [NEWTON_LAMBDA_MIN, 1], no frame particle moving more than
 * NEWTON_MAX_STEP of its radius. Where the linearization leads nowhere
 * (NEWTON_PATIENCE corrections without a new smallest force residual: contacts
 * sliding far within the increment), the increment goes on with the secant
 * update from its first step. */
sbc_status sbc_ctl_newton_scale(sbc_controller *c, sbc_servo_norms *n, sbc_error *err)
{
    const sbc_frame *f = c->frame;
    char message[SBC_ERROR_LEN] = "";
    double largest = 0.0;
    int q, k, status;
    if (c->norms.relative_force < c->newton_best) {
        c->newton_best = c->norms.relative_force;
        c->newton_stalled = 0;
    } else if (++c->newton_stalled == NEWTON_PATIENCE) { /* the secant update from its first step */
        c->secant.have_prev = 0;
        c->secant.lambda = 1.0;
    }
    if (c->newton_stalled >= NEWTON_PATIENCE)
        return sbc_ctl_secant_scale(c, n, err);
    if (!c->newton)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: keyword 'update': newton needs the host's contact network, "
                        "which this host does not give (the embedded runner and the material point do)");
    status = c->newton(c->newton_data, c->a, c->m, c->du, c->dtheta, message, sizeof message);
    if (status != SBC_OK)
        return sbc_fail(err, (sbc_status)status, "servo_bc: increment %d, iteration %d: update newton: %s",
                        c->increment, c->iteration, message);
    for (q = 0; q < f->n; ++q) {
        double len = 0.0;
        for (k = 0; k < f->dim; ++k)
            len += c->du[3 * q + k] * c->du[3 * q + k];
        for (k = 0; k < c->rot; ++k)
            len += f->R[q] * f->R[q] * c->dtheta[c->rot * q + k] * c->dtheta[c->rot * q + k];
        if (!isfinite(len))
            return sbc_fail(err, SBC_ERR_NUMERIC, "servo_bc: increment %d, iteration %d: update newton: a "
                            "non-finite correction of frame particle %d", c->increment, c->iteration, q);
        largest = fmax(largest, sqrt(len) / f->R[q]);
    }
    n->max_step = largest;
    barzilai_borwein(c, n, NEWTON_LAMBDA_MIN, 1.0, NEWTON_MAX_STEP);
    return SBC_OK;
}

/* update newton: each increment starts from the full Newton step */
void sbc_ctl_newton_start(sbc_controller *c)
{
    c->secant.have_prev = 0;
    c->secant.lambda = 1.0;
    c->newton_best = HUGE_VAL;
    c->newton_stalled = 0;
}

/* update secant: a new increment keeps the factor and forgets the last
   correction */
void sbc_ctl_secant_start(sbc_controller *c) { c->secant.have_prev = 0; }
