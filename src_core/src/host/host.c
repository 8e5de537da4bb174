/* The core behind one handle, for hosts reaching C through an FFI (host.h). */
#include "sbc/host.h"

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
    sbc_driver *driver;    /* sbc_host_drive */
    sbc_host_callbacks cb;
    long *ids;             /* [N - Q] interior_state's */
    double *ix, *iv;       /* [3 (N - Q)] */
    /* keyword seal (seal.h) */
    int sealed, n;    /* n: the creation's particles */
    sbc_seal seal;
    double *r, kn;    /* [n] radii (m), N/m */
    int *slot;        /* [n] frame position, -1 interior */
    double *reaction; /* [3Q] N */
    char step_note[SBC_ERROR_LEN]; /* time_step.h: sbc_time_step_note, or "" */
};

/* the seal's state at creation; 0, or 1 with the message in err */
static int seal_start(sbc_host *h, int n, const double *r, double kn, sbc_error *err)
{
    int k;
    double rmin = r[0];
    h->kn = kn;
    h->r = malloc(sizeof(double) * (size_t)n);
    h->slot = sbc_seal_slots(&h->frame, n);
    h->reaction = malloc(sizeof(double) * 3 * (size_t)h->frame.n);
    if (!h->r || !h->slot || !h->reaction) {
        sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return 1;
    }
    for (k = 0; k < n; ++k) {
        h->r[k] = r[k];
        rmin = fmin(rmin, r[k]);
    }
    if (sbc_seal_init(&h->seal, &h->frame, 0.25 * rmin, err) != SBC_OK)
        return 1;
    h->sealed = 1;
    return 0;
}

static sbc_host *fail_create(sbc_host *h, const sbc_error *err, char *msg, size_t cap)
{
    if (msg && cap > 0)
        snprintf(msg, cap, "%s", err->message);
    sbc_host_free(h);
    return NULL;
}

sbc_host *sbc_host_create(const char *words, int dim, int n, const double *x, const double *r, const double *m,
                          int nlist, const int *list, double dt, double kn, char *msg, size_t cap)
{
    sbc_host *h = calloc(1, sizeof *h);
    sbc_error err;
    int q;
    double *frame_mass;
    sbc_error_clear(&err);
    if (!h || !words) {
        sbc_fail(&err, SBC_ERR_NOMEM, "servo_bc: out of memory");
        return fail_create(h, &err, msg, cap);
    }
    if (sbc_settings_parse_words(&h->settings, words, &err) != SBC_OK ||
        sbc_settings_check_dimension(&h->settings, dim, &err) != SBC_OK)
        return fail_create(h, &err, msg, cap);
    if (sbc_settings_check_host(&h->settings, &err) != SBC_OK)
        return fail_create(h, &err, msg, cap);
    if (h->settings.update == SBC_UPDATE_NEWTON && h->settings.bc != SBC_BC_D) {
        sbc_fail(&err, SBC_ERR_INPUT, "servo_bc %s: keyword 'update': newton needs the host's linearized contact "
                 "network, which the embedded runner and the material point give and this host does not (expected "
                 "fixed or secant)", sbc_bc_name(h->settings.bc));
        return fail_create(h, &err, msg, cap);
    }
    if (n < 4) {
        sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: %d particles given; a frame needs at least 4", n);
        return fail_create(h, &err, msg, cap);
    }
    if (!x || !r || !m || (nlist > 0 && !list)) {
        sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: the centres, radii, masses or frame list are missing (NULL)");
        return fail_create(h, &err, msg, cap);
    }
    {
        int k, lightest = 0;
        for (k = 0; k < n; ++k) {
            const double *xk = &x[dim * k];
            if (!isfinite(xk[0]) || !isfinite(xk[1]) || !isfinite(xk[dim - 1]) || !(r[k] > 0.0) || !isfinite(r[k]) ||
                !(m[k] > 0.0) || !isfinite(m[k])) {
                char centre[96];
                if (dim == 3)
                    snprintf(centre, sizeof centre, "(%g, %g, %g)", xk[0], xk[1], xk[2]);
                else
                    snprintf(centre, sizeof centre, "(%g, %g)", xk[0], xk[1]);
                sbc_fail(&err, SBC_ERR_INPUT,
                         "servo_bc: particle %d: centre %s m, radius %g m, mass %g kg (expected a finite centre, "
                         "radius > 0 and mass > 0)",
                         k, centre, r[k], m[k]);
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
            (dim == 2 && sbc_packing_distinct(n, x, r, &err) != SBC_OK))
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
    if (dim == 3 && nlist > 0) {
        sbc_fail(&err, SBC_ERR_INPUT, "servo_bc: keyword 'frame' is 2D in this version; the packing is 3D (its frame "
                 "is detected)");
        return fail_create(h, &err, msg, cap);
    }
    if ((dim == 3 ? sbc_frame_detect_3d(&h->frame, n, x, r, 0.0, &err)
         : nlist > 0 ? sbc_frame_from_list(&h->frame, nlist, list, x, r, &err)
                     : sbc_frame_detect(&h->frame, n, x, r, 0.0, &err)) != SBC_OK)
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
    if (h->settings.file[0] && sbc_csv_open(&h->csv, h->settings.file, h->settings.dim, &err) != SBC_OK)
        return fail_create(h, &err, msg, cap);
    return h;
}

void sbc_host_free(sbc_host *h)
{
    if (!h)
        return;
    sbc_driver_free(h->driver);
    sbc_controller_free(h->ctl);
    sbc_csv_close(&h->csv);
    sbc_frame_free(&h->frame);
    sbc_seal_free(&h->seal);
    free(h->r);
    free(h->slot);
    free(h->reaction);
    free(h->ids);
    free(h->ix);
    free(h->iv);
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

int sbc_host_sealed(const sbc_host *h) { return h->sealed; }

int sbc_host_seal(sbc_host *h, const double *x, double *force, double *energy)
{
    const int d = h->frame.dim;
    const sbc_seal_particles p = sbc_seal_packed(h->n, x, force, d, h->r, h->slot);
    memset(force, 0, sizeof(double) * (size_t)d * (size_t)h->n);
    *energy = 0.0;
    if (!h->sealed)
        return 0;
    if (sbc_seal_forces_packed(&h->seal, &h->frame, sbc_controller_commands(h->ctl).x, &p, h->kn, h->reaction, energy,
                               &h->err) != SBC_OK)
        return -1;
    return h->seal.contacts;
}

int sbc_host_frame_size(const sbc_host *h) { return h->frame.n; }

const int *sbc_host_frame_particles(const sbc_host *h) { return h->frame.particle; }

/* driver.h's callbacks over the host's (sbc_host_callbacks) */
static void drive_fire_sums(void *u, double *sums)
{
    const sbc_host *h = u;
    h->cb.fire_sums(h->cb.user_data, sums);
}

static void drive_interior(void *u, const sbc_fire_mix *mix, int again, double out[2])
{
    const sbc_host *h = u;
    double m[4];
    (void)again; /* a handle's host never revisits a step */
    if (mix)
        m[0] = mix->keep, m[1] = mix->push, m[2] = mix->spin, m[3] = mix->stop;
    h->cb.interior(h->cb.user_data, mix ? m : NULL, out);
}

static void drive_contacts(void *u, double out[4])
{
    const sbc_host *h = u;
    h->cb.contacts(h->cb.user_data, out);
}

static double drive_net_force(void *u, const double *contacts)
{
    const sbc_host *h = u;
    return h->cb.net_force(h->cb.user_data, contacts);
}

static void drive_frame(void *u, double *buf)
{
    const sbc_host *h = u;
    h->cb.frame(h->cb.user_data, buf);
}

static int drive_confined(void *u, const double *fx, int increment, char *message, size_t cap)
{
    sbc_host *h = u;
    const int n = h->n - h->frame.n;
    sbc_confine c;
    sbc_error err;
    int k;
    h->cb.interior_state(h->cb.user_data, h->ids, h->ix, h->iv);
    sbc_confine_prepare(&c, &h->frame, fx);
    for (k = 0; k < n; ++k)
        if (sbc_confine_check(&c, increment, h->ids[k], &h->ix[3 * k], &h->iv[3 * k], &err) != SBC_OK) {
            snprintf(message, cap, "%s", err.message);
            return err.status;
        }
    return SBC_OK;
}

static void drive_remap(void *u, const double *M, const double *origin, int sign)
{
    const sbc_host *h = u;
    h->cb.remap(h->cb.user_data, M, origin, sign);
}

static int drive_row(void *u, const sbc_result *row, const char *line, char *message, size_t cap)
{
    sbc_host *h = u;
    double values[SBC_HOST_ROW];
    sbc_error err;
    if (h->csv.fp && sbc_csv_write(&h->csv, row, &err) != SBC_OK) {
        snprintf(message, cap, "%s", err.message);
        return err.status;
    }
    if (h->cb.row) {
        sbc_column_values(row, values);
        h->cb.row(h->cb.user_data, values, line);
    }
    return SBC_OK;
}

int sbc_host_drive(sbc_host *h, const sbc_host_callbacks *cb)
{
    sbc_driver_callbacks d = {0};
    const size_t interior = (size_t)(h->n - h->frame.n);
    if (!cb || !cb->interior || !cb->contacts || !cb->frame ||
        (h->settings.damping == SBC_DAMPING_FIRE && !cb->fire_sums)) {
        sbc_fail(&h->err, SBC_ERR_INPUT, "servo_bc: sbc_host_drive needs the callbacks interior, contacts, frame "
                 "(and fire_sums for damping fire)");
        return 1;
    }
    sbc_driver_free(h->driver);
    h->cb = *cb;
    d.user_data = h;
    d.fire_sums = cb->fire_sums ? drive_fire_sums : NULL;
    d.interior = drive_interior;
    d.contacts = drive_contacts;
    d.net_force = cb->net_force ? drive_net_force : NULL;
    d.frame = drive_frame;
    d.row = drive_row;
    d.remap = cb->remap ? drive_remap : NULL;
    if (cb->interior_state) {
        free(h->ids);
        free(h->ix);
        free(h->iv);
        h->ids = malloc(sizeof *h->ids * (interior > 0 ? interior : 1));
        h->ix = malloc(sizeof *h->ix * 3 * (interior > 0 ? interior : 1));
        h->iv = malloc(sizeof *h->iv * 3 * (interior > 0 ? interior : 1));
        if (!h->ids || !h->ix || !h->iv) {
            sbc_fail(&h->err, SBC_ERR_NOMEM, "servo_bc: out of memory for %zu interior particles", interior);
            return 1;
        }
        d.confined = drive_confined;
    }
    return !(h->driver = sbc_driver_create(h->ctl, &h->settings, &d, &h->err));
}

int sbc_host_step(sbc_host *h)
{
    if (!h->driver) {
        sbc_fail(&h->err, SBC_ERR_INPUT, "servo_bc: sbc_host_step before sbc_host_drive gave the host's callbacks");
        return SBC_EVENT_FAILED;
    }
    return (int)sbc_driver_step(h->driver, 0, &h->err);
}

const char *sbc_host_message(const sbc_host *h) { return h->err.message; }

void sbc_host_progress_line(const sbc_host *h, long step, double elapsed, char *out, size_t cap)
{
    sbc_controller_progress_line(h->ctl, step, elapsed, out, cap);
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
