/* The core behind one handle, for hosts reaching C through an FFI (host.h). */
#include "sbc/host.h"
#include "sbc/fire_damping.h"

#include "sbc/columns.h"
#include "sbc/confine.h"
#include "sbc/packing.h"
#include "sbc/results.h"
#include "sbc/seal.h"
#include "sbc/time_step.h"
#include "base/words.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct sbc_host {
    sbc_settings settings;
    sbc_frame frame;
    sbc_controller *ctl;
    sbc_csv csv;
    sbc_error err;
    int pending; /* a converged increment's row, written once sbc_host_confined passes it */
    sbc_fire_state fire; /* damping fire */
    /* keyword seal (seal.h) */
    int sealed, n;    /* n: the creation's particles */
    sbc_seal seal;
    double *r, kn;    /* [n] radii (m), N/m */
    int *slot;        /* [n] frame position, -1 interior */
    double *reaction; /* [3Q] N */
    char step_note[SBC_ERROR_LEN]; /* time_step.h: sbc_time_step_note, or "" */
    char line[320];   /* sbc_host_result_line */
};

static int host_slot(const void *ctx, int k) { return ((const int *)ctx)[k]; }

/* the seal's state at creation; 0, or 1 with the message in err */
static int seal_start(sbc_host *h, int n, const double *r, double kn, sbc_error *err)
{
    int k;
    double rmin = r[0];
    h->kn = kn;
    h->r = malloc(sizeof(double) * (size_t)n);
    h->slot = malloc(sizeof(int) * (size_t)n);
    h->reaction = malloc(sizeof(double) * 3 * (size_t)h->frame.n);
    if (!h->r || !h->slot || !h->reaction) {
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return 1;
    }
    for (k = 0; k < n; ++k) {
        h->r[k] = r[k];
        h->slot[k] = -1;
        rmin = fmin(rmin, r[k]);
    }
    for (k = 0; k < h->frame.n; ++k)
        h->slot[h->frame.particle[k]] = k;
    if (sbc_seal_init(&h->seal, &h->frame, 0.25 * rmin, err) != SBC_OK)
        return 1;
    h->sealed = 1;
    return 0;
}

/* the pending row to the CSV; 0, or 1 with the message in h->err */
static int write_pending(sbc_host *h)
{
    if (!h->pending)
        return 0;
    h->pending = 0;
    return h->csv.fp && sbc_csv_write(&h->csv, sbc_controller_result(h->ctl), &h->err) != SBC_OK;
}

static sbc_host *fail_create(sbc_host *h, const sbc_error *err, char *msg, size_t cap)
{
    if (msg && cap > 0)
        snprintf(msg, cap, "%s", err->message);
    sbc_host_free(h);
    return NULL;
}

sbc_host *sbc_host_create(const char *words, int n, const double *xy, const double *r, const double *m, int nlist,
                          const int *list, double dt, double kn, char *msg, size_t cap)
{
    sbc_host *h = calloc(1, sizeof *h);
    if (h)
        sbc_fire_start(&h->fire);
    sbc_error err;
    char *line, **w;
    int nw, q;
    double *frame_mass;
    sbc_error_clear(&err);
    if (!h || !words) {
        sbc_fail(&err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return fail_create(h, &err, msg, cap);
    }
    if (!(line = malloc(strlen(words) + 1))) {
        sbc_fail(&err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return fail_create(h, &err, msg, cap);
    }
    strcpy(line, words);
    nw = sbc_split_words(line, NULL, 0);
    strcpy(line, words);
    w = malloc(sizeof *w * (size_t)(nw > 0 ? nw : 1));
    if (!w) {
        free(line);
        sbc_fail(&err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return fail_create(h, &err, msg, cap);
    }
    sbc_split_words(line, w, nw);
    if (sbc_settings_parse(&h->settings, nw, (const char *const *)w, &err) != SBC_OK) {
        free(w);
        free(line);
        return fail_create(h, &err, msg, cap);
    }
    free(w);
    free(line);
    if (n < 4) {
        sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: %d particles given; a frame needs at least 4", n);
        return fail_create(h, &err, msg, cap);
    }
    if (!xy || !r || !m || (nlist > 0 && !list)) {
        sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: the centres, radii, masses or frame list are missing (NULL)");
        return fail_create(h, &err, msg, cap);
    }
    {
        int k, lightest = 0;
        for (k = 0; k < n; ++k) {
            if (!isfinite(xy[2 * k]) || !isfinite(xy[2 * k + 1]) || !(r[k] > 0.0) || !isfinite(r[k]) ||
                !(m[k] > 0.0) || !isfinite(m[k])) {
                sbc_fail(&err, SBC_ERR_INPUT,
                         "servo_bc: particle %d: centre (%g, %g) m, radius %g m, mass %g kg (expected a finite centre, "
                         "radius > 0 and mass > 0)",
                         k, xy[2 * k], xy[2 * k + 1], r[k], m[k]);
                return fail_create(h, &err, msg, cap);
            }
            if (m[k] < m[lightest])
                lightest = k;
        }
        if (!(kn >= 0.0) || !isfinite(kn)) {
            sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: contact stiffness kn %g N/m (expected a finite kn >= 0)", kn);
            return fail_create(h, &err, msg, cap);
        }
        if (sbc_time_step_check(dt, kn, m[lightest], lightest, h->settings.max_relax_steps, &err) != SBC_OK ||
            sbc_packing_distinct(n, xy, r, &err) != SBC_OK)
            return fail_create(h, &err, msg, cap);
        if (!sbc_time_step_note_mass(&h->settings, dt, kn, m[lightest], h->step_note, sizeof h->step_note))
            h->step_note[0] = '\0';
    }
    if (h->settings.frame_group[0] && nlist < 1) {
        sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: keyword 'frame': '%s' names no particle", h->settings.frame_group);
        return fail_create(h, &err, msg, cap);
    }
    if (!h->settings.frame_group[0] && nlist > 0) {
        sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: %d frame particles given but no keyword 'frame'", nlist);
        return fail_create(h, &err, msg, cap);
    }
    for (q = 0; q < nlist; ++q)
        if (list[q] < 0 || list[q] >= n) {
            sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: keyword 'frame': particle index %d is not in [0, %d)", list[q], n);
            return fail_create(h, &err, msg, cap);
        }
    if ((nlist > 0 ? sbc_frame_from_list(&h->frame, nlist, list, xy, r, &err)
                   : sbc_frame_detect(&h->frame, n, xy, r, 0.0, &err)) != SBC_OK)
        return fail_create(h, &err, msg, cap);
    if (!(frame_mass = malloc(sizeof *frame_mass * (size_t)h->frame.n))) {
        sbc_fail(&err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return fail_create(h, &err, msg, cap);
    }
    for (q = 0; q < h->frame.n; ++q)
        frame_mass[q] = m[h->frame.particle[q]];
    h->ctl = sbc_controller_create(&h->frame, &h->settings, frame_mass, dt, kn, &err);
    free(frame_mass);
    if (!h->ctl)
        return fail_create(h, &err, msg, cap);
    h->n = n;
    if (h->settings.seal && seal_start(h, n, r, kn, &err))
        return fail_create(h, &err, msg, cap);
    if (h->settings.file[0] && sbc_csv_open(&h->csv, h->settings.file, &err) != SBC_OK)
        return fail_create(h, &err, msg, cap);
    return h;
}

void sbc_host_free(sbc_host *h)
{
    if (!h)
        return;
    if (h->ctl)
        write_pending(h);
    sbc_controller_free(h->ctl);
    sbc_csv_close(&h->csv);
    sbc_frame_free(&h->frame);
    sbc_seal_free(&h->seal);
    free(h->r);
    free(h->slot);
    free(h->reaction);
    free(h);
}

int sbc_host_warning(const sbc_host *h, char *msg, size_t cap)
{
    size_t used;
    if (!sbc_settings_ignored_message(&h->settings, msg, cap)) {
        if (!h->step_note[0] || cap == 0)
            return 0;
        snprintf(msg, cap, "%s", h->step_note);
        return 1;
    }
    used = strlen(msg);
    if (h->step_note[0] && used + 1 < cap)
        snprintf(msg + used, cap - used, "\n%s", h->step_note);
    return 1;
}

int sbc_host_damping(const sbc_host *h, double *alpha, double *beta)
{
    *alpha = h->settings.damping ? h->settings.alpha : 0.0;
    *beta = h->settings.damping ? h->settings.beta : 0.0;
    return (int)h->settings.damping;
}

void sbc_host_fire_mix(sbc_host *h, const double *sums, double *mix)
{
    const sbc_fire_mix m = sbc_fire_step(&h->fire, sums);
    mix[0] = m.keep;
    mix[1] = m.push;
    mix[2] = m.spin;
    mix[3] = m.stop;
}

int sbc_host_sealed(const sbc_host *h) { return h->sealed; }

int sbc_host_seal(sbc_host *h, const double *xy, double *force, double *energy)
{
    sbc_seal_particles p;
    int q;
    memset(force, 0, sizeof(double) * 2 * (size_t)h->n);
    *energy = 0.0;
    if (!h->sealed)
        return 0;
    memset(h->reaction, 0, sizeof(double) * 3 * (size_t)h->frame.n);
    p.n = h->n;
    p.x = xy;
    p.f = force;
    p.stride = 2;
    p.r = h->r;
    p.frame = host_slot;
    p.ctx = h->slot;
    if (sbc_seal_forces(&h->seal, &h->frame, sbc_controller_commands(h->ctl).x, &p, h->kn, 0, h->reaction, energy,
                        &h->err) != SBC_OK)
        return -1;
    for (q = 0; q < h->frame.n; ++q) {
        force[2 * h->frame.particle[q]] += h->reaction[3 * q];
        force[2 * h->frame.particle[q] + 1] += h->reaction[3 * q + 1];
    }
    return h->seal.contacts;
}

int sbc_host_frame_size(const sbc_host *h) { return h->frame.n; }

const int *sbc_host_frame_particles(const sbc_host *h) { return h->frame.particle; }

/* the snapshot of the measures (no frame arrays) */
static sbc_snapshot measures(const double *m)
{
    sbc_snapshot s;
    memset(&s, 0, sizeof s);
    s.kinetic_energy = m[SBC_HOST_EK];
    s.unbalanced_max = m[SBC_HOST_NET_MAX];
    s.potential_energy = m[SBC_HOST_EP];
    s.contact_force_sum = m[SBC_HOST_CONTACT_SUM];
    s.contact_count = (long)m[SBC_HOST_CONTACT_COUNT];
    s.overlap_sum = m[SBC_HOST_OVERLAP_SUM];
    s.rotation_sum = m[SBC_HOST_ROTATION_SUM];
    s.particle_count = (long)m[SBC_HOST_PARTICLE_COUNT];
    return s;
}

unsigned sbc_host_needs(const sbc_host *h, const double *m)
{
    const sbc_snapshot s = measures(m);
    return sbc_controller_needs(h->ctl, &s);
}

int sbc_host_step(sbc_host *h, const double *m, const double *x, const double *theta, const double *force,
                  const double *torque)
{
    sbc_snapshot s = measures(m);
    sbc_event ev;
    s.x = x;
    s.theta = theta;
    s.force = force;
    s.torque = torque;
    if (write_pending(h))
        return SBC_EVENT_FAILED;
    ev = sbc_controller_step(h->ctl, &s, &h->err);
    if (ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED)
        h->pending = 1;
    return (int)ev;
}

int sbc_host_confined(sbc_host *h, const double *frame_x, int n, const long *ids, const double *xy,
                      const double *vxy)
{
    const int increment = h->pending ? sbc_controller_result(h->ctl)->increment : sbc_controller_increment(h->ctl);
    int k;
    for (k = 0; k < n; ++k)
        if (sbc_confine_check(&h->frame, frame_x, increment, ids[k], &xy[2 * k], &vxy[2 * k], &h->err) != SBC_OK) {
            h->pending = 0; /* the increment's results are not kept */
            return 1;
        }
    return write_pending(h);
}

const char *sbc_host_message(const sbc_host *h) { return h->err.message; }

const char *sbc_host_result_line(sbc_host *h)
{
    sbc_result_line(sbc_controller_result(h->ctl), h->settings.bc, sbc_settings_total_increments(&h->settings), h->line,
                    sizeof h->line);
    return h->line;
}

void sbc_host_progress(const sbc_host *h, double *out)
{
    int iteration;
    sbc_controller_progress(h->ctl, &iteration, &out[1], &out[2], &out[3]);
    out[0] = iteration;
}

const double *sbc_host_command_x(const sbc_host *h) { return sbc_controller_commands(h->ctl).x; }

const double *sbc_host_command_theta(const sbc_host *h) { return sbc_controller_commands(h->ctl).theta; }

const unsigned char *sbc_host_command_free(const sbc_host *h)
{
    return sbc_controller_commands(h->ctl).free_rotation;
}

void sbc_host_result(const sbc_host *h, double *row)
{
    sbc_column_values(sbc_controller_result(h->ctl), row);
}
