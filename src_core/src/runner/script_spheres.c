/* The embedded runner's 3D servo_bc commands (after `dimension 3`):
 *
 *   lattice cubic NX NY NZ spacing D radius R | read_packing FILE (x y z r)
 *   generate periodic n0 N rmin R polydispersity PD seed S [strain E]
 *   contact frictional kn KN ks KS mu MU
 *   density RHO          (kg/m^3)
 *   timestep DT | timestep critical F
 *   servo_bc BC ... F (nine values) ... [file F.csv]
 *   run
 *
 *   vtk EVERY PREFIX     (spheres and the frame's surface, spheres_vtk.h)
 *   write_packing text|lammps|liggghts|yade FILE
 *
 * `run` runs the servo_bc line on the sphere engine (spheres.h) through the
 * host driver, as the hosts do: the results file with the 3D columns, a log
 * line per converged increment, a progress line every 10 s. */
#include "script_state.h"
#include "sbc/driver.h"
#include "sbc/embedded/spheres.h"
#include "sbc/embedded/spheres_vtk.h"
#include "sbc/embedded/output_file.h"
#include "sbc/numbers.h"
#include "sbc/packing.h"
#include "sbc/results.h"
#include "sbc/time_step.h"
#include "sbc/version.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void sbc_script_spheres_free(script *s)
{
    free(s->x3);
    free(s->r3);
    s->x3 = s->r3 = NULL;
    s->n3 = 0;
}

sbc_status sbc_script_lattice_cubic(script *s, int nw, char **w, sbc_error *err)
{
    static const char usage[] = "lattice cubic NX NY NZ spacing D radius R";
    long n[3];
    double d, r;
    int k, i, j, l, m = 0;
    sbc_status st;
    if (nw >= 2 && strcmp(w[1], "cubic") != 0)
        return sbc_fail(err, SBC_ERR_INPUT, "lattice: style '%s' is not known after 'dimension 3' (expected 'cubic')",
                        w[1]);
    if ((st = sbc_script_expect_count(nw, w, 9, usage, err)) != SBC_OK) return st;
    for (k = 0; k < 3; ++k)
        if (sbc_parse_int(w[2 + k], "N", 3, 1000, &n[k], NULL) != SBC_OK)
            return sbc_fail(err, SBC_ERR_INPUT, "lattice: N%c '%s' is not valid (expected an integer from 3 to 1000)",
                            "XYZ"[k], w[2 + k]);
    if (n[0] * n[1] * n[2] > SBC_PACKING_MAX)
        return sbc_fail(err, SBC_ERR_INPUT, "lattice: %ld x %ld x %ld spheres exceed the limit of %ld", n[0], n[1], n[2],
                        (long)SBC_PACKING_MAX);
    if ((st = sbc_script_expect_key("lattice", w[5], "spacing", usage, err)) != SBC_OK) return st;
    if ((st = sbc_script_positive("lattice", "spacing", w[6], &d, err)) != SBC_OK) return st;
    if ((st = sbc_script_expect_key("lattice", w[7], "radius", usage, err)) != SBC_OK) return st;
    if ((st = sbc_script_positive("lattice", "radius", w[8], &r, err)) != SBC_OK) return st;
    sbc_script_spheres_free(s);
    s->x3 = malloc(sizeof(double) * 3 * (size_t)(n[0] * n[1] * n[2]));
    s->r3 = malloc(sizeof(double) * (size_t)(n[0] * n[1] * n[2]));
    if (!s->x3 || !s->r3) {
        sbc_script_spheres_free(s);
        return sbc_fail(err, SBC_ERR_NOMEM, "lattice: out of memory");
    }
    for (l = 0; l < n[2]; ++l)
        for (j = 0; j < n[1]; ++j)
            for (i = 0; i < n[0]; ++i, ++m) {
                s->x3[3 * m] = i * d, s->x3[3 * m + 1] = j * d, s->x3[3 * m + 2] = l * d;
                s->r3[m] = r;
            }
    s->n3 = m;
    return SBC_OK;
}

sbc_status sbc_script_read_spheres(script *s, const char *path, sbc_error *err)
{
    sbc_status st;
    sbc_script_spheres_free(s);
    if ((st = sbc_spheres_read(path, &s->n3, &s->x3, &s->r3, err)) == SBC_OK)
        sbc_script_files_note(s, path, "packing read");
    return st;
}

sbc_status sbc_script_write_spheres(script *s, const char *format, const char *path, sbc_error *err)
{
    double density, dt, fraction;
    sbc_frame frame;
    int *is_frame, k;
    sbc_status st = sbc_script_files_check(s, path, "write_packing:", err);
    if (st == SBC_OK && s->check)
        st = sbc_output_probe(path, SBC_OUTPUT_PACKING, "write_packing", err);
    if (st != SBC_OK)
        return st;
    if (!s->x3)
        return sbc_fail(err, SBC_ERR_INPUT, "write_packing: no sphere packing (use 'lattice cubic ...' or "
                        "'read_packing FILE' first)");
    if (strcmp(format, "text") == 0) {
        st = s->check ? SBC_OK : sbc_spheres_write_text(s->n3, s->x3, s->r3, path, err);
        if (st == SBC_OK)
            sbc_script_files_note(s, path, "packing written");
        return st;
    }
    if (strcmp(format, "lammps") != 0 && strcmp(format, "liggghts") != 0 && strcmp(format, "yade") != 0)
        return sbc_fail(err, SBC_ERR_INPUT, "write_packing: format '%s' is not known after 'dimension 3' (expected "
                        "text, lammps, liggghts or yade)", format);
    sbc_script_bpm_material(s, &density, &dt, &fraction);
    if (format[0] == 'l' && !(density > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "write_packing %s: no density (use 'density RHO', kg/m^3, first: the data "
                        "file carries the masses)", format);
    if ((st = sbc_frame_detect_3d(&frame, s->n3, s->x3, s->r3, 0.0, err)) != SBC_OK)
        return st;
    if (!(is_frame = calloc((size_t)s->n3, sizeof *is_frame))) {
        sbc_frame_free(&frame);
        return sbc_fail(err, SBC_ERR_NOMEM, "write_packing: out of memory");
    }
    for (k = 0; k < frame.n; ++k)
        is_frame[frame.particle[k]] = 1;
    if (!s->check)
        st = format[0] == 'y' ? sbc_spheres_write_yade(s->n3, s->x3, s->r3, is_frame, path, err)
                              : sbc_spheres_write_data(s->n3, s->x3, s->r3, is_frame, density, format, path, err);
    free(is_frame);
    sbc_frame_free(&frame);
    if (st == SBC_OK)
        sbc_script_files_note(s, path, "packing written");
    return st;
}

/* the run's side of the driver: the row (the driver's row_data); the
   particles' callbacks are the engine's (spheres.h) */
typedef struct sphere_run {
    const script *s;
    const sbc_spheres *spheres;
    const sbc_frame *frame;
    sbc_csv csv;
    int nrows;
    struct timespec start, reported;
    const sbc_controller *ctl;  /* for keyword tangent: the controller, */
    sbc_driver *driver;         /* the driver (its FIRE), */
    sbc_aggregate aggregate;    /* the engine as the tangents see it */
    sbc_script_tangent tangent; /* and the file */
    sbc_statics_tally tally;    /* interior newton: the static solves of the increment under way */
} sphere_run;

/* a converged increment: its row in the results file and the log line */
static int sphere_row(void *user_data, const sbc_result *row, const char *line, char *message, size_t cap)
{
    sphere_run *r = user_data;
    sbc_result filled = *row;
    sbc_error e;
    filled.newton_iterations = r->tally.iterations;
    filled.newton_held = r->tally.mechanisms;
    row = &filled;
    if (r->csv.fp && sbc_csv_write(&r->csv, row, &e) != SBC_OK) {
        snprintf(message, cap, "%s", e.message);
        return e.status;
    }
    r->nrows++;
    if (r->s->vtk_every && (row->increment % r->s->vtk_every == 0 ||
                            row->increment == sbc_settings_total_increments(&r->s->settings))) {
        const sbc_spheres_view view = sbc_spheres_get_view(r->spheres);
        if (sbc_spheres_vtk_write(r->s->vtk_prefix, row->increment, &view, r->frame, &e) != SBC_OK) {
            snprintf(message, cap, "%s", e.message);
            return e.status;
        }
    }
    if (r->s->log) {
        fprintf(r->s->log, "%s\n", line);
        if (r->aggregate.tally)
            sbc_script_tally_line(r->s, &r->tally);
        fflush(r->s->log);
    }
    if (sbc_script_tangent_row(r->s, &r->tangent, &r->aggregate, r->ctl, sbc_driver_fire(r->driver), row, &e) !=
        SBC_OK) {
        snprintf(message, cap, "%s", e.message);
        return e.status;
    }
    memset(&r->tally, 0, sizeof r->tally); /* the next increment's solves */
    timespec_get(&r->reported, TIME_UTC);
    return SBC_OK;
}

static double seconds(const struct timespec *a, const struct timespec *b)
{
    return (double)(b->tv_sec - a->tv_sec) + 1e-9 * (double)(b->tv_nsec - a->tv_nsec);
}

/* the run's parts, freed together */
typedef struct sphere_parts {
    sbc_frame frame;
    sbc_spheres *engine;
    sbc_controller *ctl;
    sbc_driver *driver;
    double *mass;
} sphere_parts;

static void parts_free(sphere_parts *p, sphere_run *r)
{
    sbc_driver_free(p->driver);
    sbc_controller_free(p->ctl);
    sbc_spheres_free(p->engine);
    sbc_frame_free(&p->frame);
    free(p->mass);
    sbc_csv_close(&r->csv);
    sbc_script_tangent_close(&r->tangent);
}

sbc_status sbc_script_run_spheres(script *s, sbc_error *err)
{
    sphere_parts p;
    sphere_run r;
    sbc_spheres_def def = sbc_spheres_def_default();
    sbc_driver_callbacks cb;
    double density, dt, fraction, dtc;
    sbc_status st = SBC_OK;
    long steps = 0;
    memset(&p, 0, sizeof p);
    memset(&r, 0, sizeof r);
    r.s = s;
    sbc_script_bpm_material(s, &density, &dt, &fraction);
    if (!s->x3)
        return sbc_fail(err, SBC_ERR_INPUT, "run: no sphere packing (use 'lattice cubic ...' or 'read_packing FILE' "
                        "first)");
    if (!s->have_contact) return sbc_fail(err, SBC_ERR_INPUT, "run: no contact law (use 'contact frictional ...' first)");
    if (!(density > 0.0)) return sbc_fail(err, SBC_ERR_INPUT, "run: no density (use 'density RHO', kg/m^3, first)");
    if (!(dt > 0.0) && !(fraction > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "run: no time step (use 'timestep DT' first)");
    if ((st = sbc_script_outputs_check(s, err)) != SBC_OK)
        return st;
    if (s->settings.frame_group[0])
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc (line %d): keyword 'frame' is 2D in this version; the packing is 3D",
                        s->servo_line);
    if ((st = sbc_frame_detect_3d(&p.frame, s->n3, s->x3, s->r3, 0.0, err)) != SBC_OK)
        return st;
    def.n = s->n3;
    def.x = s->x3;
    def.r = s->r3;
    def.density = density;
    def.law = s->law;
    def.dt = dt > 0.0 ? dt : 1.0;
    def.alpha = s->settings.damping ? s->settings.alpha : 0.0;
    def.beta = s->settings.damping ? s->settings.beta : 0.0;
    def.fire = s->settings.damping == SBC_DAMPING_FIRE;
    if (!(p.engine = sbc_spheres_create(&def, err))) {
        parts_free(&p, &r);
        return err->status;
    }
    dtc = sbc_spheres_critical_dt(p.engine);
    if (!(dt > 0.0)) { /* timestep critical F: made again with F times the critical step */
        def.dt = dt = fraction * dtc;
        sbc_spheres_free(p.engine);
        if (!(p.engine = sbc_spheres_create(&def, err))) {
            parts_free(&p, &r);
            return err->status;
        }
    }
    if ((st = sbc_time_step_bound(dt, dtc, "2 sqrt(M_min / (2 kn))", s->settings.max_relax_steps, err)) != SBC_OK) {
        if (s->dt_line > 0) /* the error belongs to the timestep command */
            s->line = s->dt_line;
        parts_free(&p, &r);
        return st;
    }
    sbc_spheres_set_frame(p.engine, &p.frame);
    if (s->settings.seal && (st = sbc_spheres_seal(p.engine, err)) != SBC_OK) {
        parts_free(&p, &r);
        return st;
    }
    if (!(p.mass = malloc(sizeof(double) * (size_t)p.frame.n))) {
        parts_free(&p, &r);
        return sbc_fail(err, SBC_ERR_NOMEM, "run: out of memory");
    }
    sbc_spheres_frame_masses(p.engine, p.mass);
    if (!(p.ctl = sbc_controller_create(&p.frame, &s->settings, p.mass, dt, s->law.kn, err))) {
        parts_free(&p, &r);
        return err->status;
    }
    if (s->settings.file[0] && !s->check && (st = sbc_csv_open(&r.csv, s->settings.file, 3, err)) != SBC_OK) {
        parts_free(&p, &r);
        return st;
    }
    sbc_script_files_note(s, s->settings.file, "results file");
    if ((st = sbc_script_tangent_open(s, 3, &r.tangent, err)) != SBC_OK) {
        parts_free(&p, &r);
        return st;
    }
    sbc_script_files_note(s, s->settings.tangent_file, "tangent file");
    r.aggregate.ops = &sbc_engine_ops_spheres;
    r.aggregate.engine = p.engine;
    r.aggregate.n = s->n3;
    r.aggregate.frame = &p.frame;
    r.aggregate.settings = &s->settings;
    r.aggregate.mass = p.mass;
    r.aggregate.dt = dt;
    r.aggregate.law = s->law;
    r.aggregate.tally = s->settings.interior == SBC_INTERIOR_NEWTON ? &r.tally : NULL;
    if (s->check) {
        if (s->log)
            fprintf(s->log, "check: run of line %d: servo_bc %s, %d spheres, frame of %d, %d increments, dt = %g s "
                    "(critical %g s)\n", s->line, sbc_bc_name(s->settings.bc), s->n3, p.frame.n,
                    sbc_settings_total_increments(&s->settings), dt, dtc);
        parts_free(&p, &r);
        return SBC_OK;
    }
    if (s->log)
        fprintf(s->log, "servo_bc %s (servo-bc %s): %d spheres, frame of %d, %d increments, dt = %g s (critical %g s)\n",
                sbc_bc_name(s->settings.bc), sbc_version(), s->n3, p.frame.n,
                sbc_settings_total_increments(&s->settings), dt, dtc);
    r.spheres = p.engine;
    r.frame = &p.frame;
    cb = sbc_aggregate_callbacks(&r.aggregate);
    cb.row = sphere_row;
    cb.row_data = &r;
    if (!(p.driver = sbc_driver_create(p.ctl, &s->settings, &cb, err))) {
        parts_free(&p, &r);
        return err->status;
    }
    r.ctl = p.ctl;
    r.driver = p.driver;
    timespec_get(&r.start, TIME_UTC);
    r.reported = r.start;
    if ((st = sbc_spheres_forces(p.engine, err)) == SBC_OK && r.aggregate.tally)
        st = sbc_aggregate_advance(&r.aggregate, p.ctl, 1, err); /* increment 0's interior solved first */
    while (st == SBC_OK) {
        sbc_event ev = sbc_driver_step(p.driver, 0, err);
        ++steps;
        if (ev == SBC_EVENT_FAILED) {
            st = err->status;
            break;
        }
        if (ev == SBC_EVENT_FINISHED)
            break;
        if ((st = sbc_aggregate_advance(&r.aggregate, p.ctl, 0, err)) != SBC_OK)
            break;
        if (s->log && steps % 1000 == 0) {
            struct timespec now;
            timespec_get(&now, TIME_UTC);
            if (seconds(&r.reported, &now) >= SBC_PROGRESS_EVERY) {
                char line[256];
                r.reported = now;
                sbc_controller_progress_line(p.ctl, steps, seconds(&r.start, &now), line, sizeof line);
                fprintf(s->log, "  %s\n", line);
                fflush(s->log);
            }
        }
    }
    if (st != SBC_OK && s->vtk_every) { /* the state the run stopped in, for a look in ParaView */
        const sbc_spheres_view view = sbc_spheres_get_view(p.engine);
        sbc_error verr;
        if (sbc_spheres_vtk_write(s->vtk_prefix, sbc_controller_increment(p.ctl), &view, &p.frame, &verr) == SBC_OK &&
            s->log)
            fprintf(s->log, "servo_bc: the state the run stopped in is %s_spheres_%06d.vtk\n", s->vtk_prefix,
                    sbc_controller_increment(p.ctl));
    }
    if (s->log && st == SBC_OK) {
        struct timespec t1;
        timespec_get(&t1, TIME_UTC);
        fprintf(s->log, "servo_bc: finished %d increments: %ld steps, wall %.2f s\n", r.nrows, steps,
                seconds(&r.start, &t1));
        if (s->settings.file[0])
            fprintf(s->log, "  results: %s\n", s->settings.file);
        if (s->vtk_every)
            fprintf(s->log, "  vtk:     %s_spheres_*.vtk, %s_frame_*.vtk\n", s->vtk_prefix, s->vtk_prefix);
    }
    parts_free(&p, &r);
    return st;
}
