/* The per-step protocol of a host (driver.h): what the controller needs on
 * this step, measured through the host's callbacks and reduced over its
 * ranks; the controller's step; the confinement cadence; the row. */
#include "sbc/driver.h"
#include "sbc/confine.h"
#include "sbc/results.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct sbc_driver {
    sbc_controller *ctl;
    sbc_settings s;
    sbc_driver_callbacks cb;
    sbc_fire_state fire;
    int since_check; /* steps since the last confinement check */
    int dim, Q;
    size_t size;       /* SBC_DRIVER_FRAME_SIZE(dim, Q) */
    double *buf, *sum; /* [size] this rank's and all ranks' frame data */
};

sbc_driver *sbc_driver_create(sbc_controller *c, const sbc_settings *s, const sbc_driver_callbacks *cb,
                              sbc_error *err)
{
    sbc_driver *d;
    if (!c || !s || !cb || !cb->interior || !cb->contacts || !cb->frame ||
        (s->damping == SBC_DAMPING_FIRE && !cb->fire_sums)) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc: the host driver needs a controller, the settings and the callbacks "
                 "interior, contacts, frame (and fire_sums for damping fire)");
        return NULL;
    }
    if (s->remap && !cb->remap) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc %s: keyword 'remap': x needs a host that moves its interior "
                 "particles (the driver's remap callback); this one does not, and x is the default under "
                 "accuracy fast, balanced and tight (expected remap none)", sbc_bc_name(s->bc));
        return NULL;
    }
    if (s->update == SBC_UPDATE_NEWTON && s->bc != SBC_BC_D && !cb->newton) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc %s: keyword 'update': newton needs the host's linearized contact "
                 "network (the driver's newton callback), which the embedded runner and the material point give "
                 "and this host does not (expected fixed or secant)", sbc_bc_name(s->bc));
        return NULL;
    }
    if (s->interior == SBC_INTERIOR_NEWTON && !cb->solves_interior) {
        sbc_fail(err, SBC_ERR_INPUT, "servo_bc %s: keyword 'interior': newton solves the interior's static "
                 "equilibrium on the embedded engine's contact network (servo-bc and the material point, discs); "
                 "this host relaxes its interior with its own dynamics (expected dynamic)", sbc_bc_name(s->bc));
        return NULL;
    }
    if (!(d = calloc(1, sizeof *d))) {
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return NULL;
    }
    d->ctl = c;
    d->s = *s;
    d->cb = *cb;
    d->Q = sbc_controller_frame(c)->n;
    d->dim = sbc_controller_frame(c)->dim;
    d->size = SBC_DRIVER_FRAME_SIZE(d->dim, d->Q);
    d->buf = calloc(d->size, sizeof(double));
    d->sum = calloc(d->size, sizeof(double));
    if (!d->buf || !d->sum) {
        sbc_driver_free(d);
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory for a frame of %d particles", sbc_controller_frame(c)->n);
        return NULL;
    }
    sbc_fire_start(&d->fire);
    if (cb->newton)
        sbc_controller_set_newton(c, cb->newton, cb->newton_data ? cb->newton_data : cb->user_data);
    return d;
}

void sbc_driver_free(sbc_driver *d)
{
    if (!d)
        return;
    free(d->buf);
    free(d->sum);
    free(d);
}

sbc_fire_state *sbc_driver_fire(sbc_driver *d) { return &d->fire; }

void sbc_driver_remap(sbc_driver *d)
{
    double M[9], origin[3];
    if (d->cb.remap && sbc_controller_remap(d->ctl, M, origin))
        d->cb.remap(d->cb.user_data, M, origin, 1);
}

/* the velocity of the last remap, if any, taken back (driver.h, remap) */
static void stop_streaming(sbc_driver *d)
{
    static const double I[9] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}, origin[3] = {0.0, 0.0, 0.0};
    if (d->s.remap)
        d->cb.remap(d->cb.user_data, I, origin, -1);
}

static void reduce(const sbc_driver *d, const double *in, double *out, int n, sbc_reduce_op op)
{
    if (d->cb.reduce)
        d->cb.reduce(d->cb.user_data, in, out, n, op);
    else
        memcpy(out, in, sizeof(double) * (size_t)n);
}

/* the frame data of all ranks into d->sum; the first n values reduced */
static void gather_frame(sbc_driver *d, int n)
{
    memset(d->buf, 0, sizeof(double) * d->size);
    d->cb.frame(d->cb.user_data, d->buf);
    reduce(d, d->buf, d->sum, n, SBC_REDUCE_SUM);
}

/* confine.h, before a converged increment's row, on failure and every
   SBC_CONFINE_EVERY steps; 1 with the message in err when a particle left */
static int escaped(sbc_driver *d, sbc_event ev, sbc_error *err)
{
    const int converged = ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED;
    char message[SBC_ERROR_LEN] = "";
    int status;
    if (!(converged || ev == SBC_EVENT_FAILED || ++d->since_check >= SBC_CONFINE_EVERY))
        return 0;
    d->since_check = 0;
    if (!d->cb.confined)
        return 0;
    gather_frame(d, 3 * d->Q);
    status = d->cb.confined(d->cb.user_data, d->sum,
                            converged ? sbc_controller_result(d->ctl)->increment : sbc_controller_increment(d->ctl),
                            message, sizeof message);
    if (status == SBC_OK)
        return 0;
    sbc_fail(err, (sbc_status)status, "%s", message);
    return 1;
}

sbc_event sbc_driver_step(sbc_driver *d, int again, sbc_error *err)
{
    const int fire = d->s.damping == SBC_DAMPING_FIRE && !again;
    const int Q = d->Q;
    double local[SBC_FIRE_SUMS] = {0.0, 0.0, 0.0, 0.0, 0.0}, interior[2], measured[4];
    sbc_fire_mix mix;
    sbc_snapshot snap;
    unsigned need;
    sbc_event ev;
    if (!again) /* a revisit (the setup of a later run) precedes the step that carries the move */
        stop_streaming(d);
    if (fire) {
        double sums[SBC_FIRE_SUMS] = {0.0, 0.0, 0.0, 0.0, 0.0};
        d->cb.fire_sums(d->cb.user_data, local);
        reduce(d, local, sums, SBC_FIRE_SUMS, SBC_REDUCE_SUM);
        mix = sbc_fire_step(&d->fire, sums);
    }
    d->cb.interior(d->cb.user_data, fire ? &mix : NULL, again, local);
    reduce(d, &local[0], &interior[0], 1, SBC_REDUCE_SUM);
    reduce(d, &local[1], &interior[1], 1, SBC_REDUCE_MAX);
    if (again)
        return SBC_EVENT_RELAXING;

    memset(&snap, 0, sizeof snap);
    snap.kinetic_energy = interior[0];
    snap.unbalanced_max = interior[1];
    snap.potential_energy = SBC_RELAX_EP_UNMEASURED;
    need = sbc_controller_needs(d->ctl, &snap);
    if (need) {
        d->cb.contacts(d->cb.user_data, local);
        reduce(d, local, measured, 4, SBC_REDUCE_SUM);
        snap.potential_energy = measured[0];
        snap.overlap_sum = measured[1];
        snap.contact_count = (long)measured[2];
        snap.contact_force_sum = measured[3];
        if (d->cb.net_force) {
            const double mine = d->cb.net_force(d->cb.user_data, measured);
            reduce(d, &mine, &snap.unbalanced_max, 1, SBC_REDUCE_MAX);
        }
        need = sbc_controller_needs(d->ctl, &snap);
    }
    if (need & SBC_NEED_FRAME) {
        gather_frame(d, (int)d->size);
        snap.x = &d->sum[0];
        snap.force = &d->sum[3 * Q];
        snap.torque = &d->sum[SBC_DRIVER_TORQUE(d->dim, Q)];
        snap.theta = &d->sum[SBC_DRIVER_THETA(d->dim, Q)];
        snap.rotation_sum = d->sum[SBC_DRIVER_SUMS(d->dim, Q)];
        snap.particle_count = (long)d->sum[SBC_DRIVER_SUMS(d->dim, Q) + 1];
    }
    ev = sbc_controller_step(d->ctl, &snap, err);
    if (escaped(d, ev, err))
        return SBC_EVENT_FAILED;
    if ((ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED) && d->cb.row) {
        const sbc_result *row = sbc_controller_result(d->ctl);
        char line[320], message[SBC_ERROR_LEN] = "";
        int status;
        sbc_result_line(row, d->s.bc, sbc_settings_total_increments(&d->s), line, sizeof line);
        if ((status = d->cb.row(d->cb.row_data ? d->cb.row_data : d->cb.user_data, row, line, message, sizeof message)) != SBC_OK) {
            sbc_fail(err, (sbc_status)status, "%s", message);
            return SBC_EVENT_FAILED;
        }
    }
    if (ev != SBC_EVENT_FAILED && ev != SBC_EVENT_FINISHED)
        sbc_driver_remap(d);
    return ev;
}
