/* The embedded runner: script commands -> packing, engine, controller. */
#include "sbc/embedded/script.h"

#include "sbc/confine.h"
#include "sbc/controller.h"
#include "sbc/driver.h"
#include "sbc/embedded/engine.h"
#include "sbc/frame.h"
#include "sbc/homogenize.h"
#include "sbc/embedded/network.h"
#include "sbc/packing.h"
#include "sbc/embedded/plot.h"
#include "sbc/results.h"
#include "sbc/settings.h"
#include "sbc/time_step.h"
#include "sbc/version.h"
#include "sbc/embedded/vtk.h"
#include "script_state.h"
#include "base/words.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>


/* Prefixes err's message with the script name and line. */
static sbc_status at_line(script *s, sbc_status st, sbc_error *err)
{
    char msg[SBC_ERROR_LEN];
    if (st == SBC_OK)
        return st;
    snprintf(msg, sizeof msg, "%s", err->message);
    return sbc_fail(err, st, "%s:%d: %s", s->name, s->line, msg);
}

static sbc_status cmd_lattice(script *s, int nw, char **w, sbc_error *err)
{
    static const char usage[] = "lattice square NX NY spacing D radius R";
    long nx, ny;
    double d, r;
    sbc_status st = sbc_script_expect_count(nw, w, 8, usage, err);
    if (st != SBC_OK) return st;
    if (strcmp(w[1], "square") != 0)
        return sbc_fail(err, SBC_ERR_INPUT, "lattice: style '%s' is not known (expected 'square')", w[1]);
    if (sbc_parse_int(w[2], "NX", 3, 100000, &nx, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "lattice: NX '%s' is not valid (expected an integer from 3 to 100000)", w[2]);
    if (sbc_parse_int(w[3], "NY", 3, 100000, &ny, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "lattice: NY '%s' is not valid (expected an integer from 3 to 100000)", w[3]);
    if (nx * ny > SBC_PACKING_MAX)
        return sbc_fail(err, SBC_ERR_INPUT, "lattice: %ld x %ld particles exceed the limit of %ld", nx, ny,
                        (long)SBC_PACKING_MAX);
    if ((st = sbc_script_expect_key("lattice", w[4], "spacing", usage, err)) != SBC_OK) return st;
    if ((st = sbc_script_positive("lattice", "spacing", w[5], &d, err)) != SBC_OK) return st;
    if ((st = sbc_script_expect_key("lattice", w[6], "radius", usage, err)) != SBC_OK) return st;
    if ((st = sbc_script_positive("lattice", "radius", w[7], &r, err)) != SBC_OK) return st;
    sbc_packing_free(&s->packing);
    st = sbc_packing_lattice_square(&s->packing, (int)nx, (int)ny, d, r, err);
    s->have_packing = st == SBC_OK;
    return st;
}

/* A keyword KEY followed by a real >= 0 (or > 0 when positive) at w[k], w[k + 1]. */
static sbc_status keyed_real(char **w, int k, const char *key, int positive, const char *usage, double *out,
                             sbc_error *err)
{
    sbc_status st = sbc_script_expect_key("contact", w[k], key, usage, err);
    if (st != SBC_OK) return st;
    if (positive) return sbc_script_positive("contact", key, w[k + 1], out, err);
    if (sbc_parse_real(w[k + 1], key, out, NULL) != SBC_OK || !(*out >= 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "contact: %s '%s' is not valid (expected a real >= 0)", key, w[k + 1]);
    return SBC_OK;
}

/* contact frictional kn KN ks KS mu MU                                  (eq. 6)
 * contact cohesive kn KN ks KS kr KR fn FN fs FS mr MR mu MU          (eqs. 7-8) */
static sbc_status cmd_contact(script *s, int nw, char **w, sbc_error *err)
{
    static const char usage_f[] = "contact frictional kn KN ks KS mu MU";
    sbc_cohesive c;
    sbc_status st;
    if (nw >= 2 && strcmp(w[1], "frictional") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 8, usage_f, err)) != SBC_OK) return st;
        if ((st = keyed_real(w, 2, "kn", 1, usage_f, &s->law.kn, err)) != SBC_OK) return st;
        if ((st = keyed_real(w, 4, "ks", 0, usage_f, &s->law.ks, err)) != SBC_OK) return st;
        if ((st = keyed_real(w, 6, "mu", 0, usage_f, &s->law.mu, err)) != SBC_OK) return st;
        s->cohesive = 0;
        s->have_contact = 1;
        return SBC_OK;
    }
    if (nw < 2 || strcmp(w[1], "cohesive") != 0)
        return sbc_fail(err, SBC_ERR_INPUT, "contact: law '%s' is not known (expected 'frictional' or 'cohesive')",
                        nw >= 2 ? w[1] : "");
    if ((st = sbc_cohesive_parse(nw - 2, w + 2, "contact cohesive", &c, err)) != SBC_OK) return st;
    s->bond_law = c;
    s->law.kn = c.kn; /* broken bonds and new contacts follow eq. 6 with these */
    s->law.ks = c.ks;
    s->law.mu = c.mu;
    s->cohesive = 1;
    s->have_contact = 1;
    return SBC_OK;
}

/* vtk EVERY PREFIX | network EVERY PREFIX: snapshots every EVERY increments and at the last. */
static sbc_status cmd_snapshots(int nw, char **w, int *every_out, char *prefix, sbc_error *err)
{
    char usage[32];
    long every;
    sbc_status st;
    snprintf(usage, sizeof usage, "%s EVERY PREFIX", w[0]);
    if ((st = sbc_script_expect_count(nw, w, 3, usage, err)) != SBC_OK) return st;
    if (sbc_parse_int(w[1], "EVERY", 1, 100000000L, &every, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: EVERY '%s' is not valid (expected an integer from 1 to 100000000)",
                        w[0], w[1]);
    if (strlen(w[2]) >= SBC_NAME_LEN)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: PREFIX is too long (at most %d characters)", w[0], SBC_NAME_LEN - 1);
    *every_out = (int)every;
    strcpy(prefix, w[2]);
    return SBC_OK;
}

/* the snapshots due at a converged increment */
static sbc_status write_snapshots(const script *s, const sbc_engine *engine, const sbc_frame *frame, int increment,
                                  int last, sbc_error *err)
{
    sbc_engine_view view = sbc_engine_get_view(engine);
    sbc_status st = SBC_OK;
    if (s->vtk_every && (increment % s->vtk_every == 0 || last))
        st = sbc_vtk_write(s->vtk_prefix, increment, &view, err);
    if (st == SBC_OK && s->network_every && (increment % s->network_every == 0 || last)) {
        char path[SBC_NAME_LEN + 32], title[96];
        snprintf(path, sizeof path, "%s_%06d.svg", s->network_prefix, increment);
        snprintf(title, sizeof title, "contact network, increment %d", increment);
        st = sbc_network_svg(path, title, &view, frame, err);
    }
    return st;
}

/* Everything `run` needs, freed in one place. */
typedef struct run_state {
    sbc_frame frame;
    sbc_engine *engine;
    sbc_controller *ctl;
    double *mass;
    sbc_csv csv;
    sbc_result *rows;
    int nrows, cap;
    int increment_now; /* the increment in progress */
    long since_check;  /* engine steps since the last progress check */
    struct timespec start, reported; /* the run's start, the last progress line */
    sbc_driver *driver; /* the per-step protocol (driver.h) over the engine */
    const script *s;
    sbc_aggregate aggregate;    /* the engine as the tangents see it (keyword tangent) */
    sbc_script_tangent tangent; /* ... and its file */
    sbc_statics_tally tally;    /* interior newton: the static solves of the increment under way */
} run_state;

static double seconds_between(const struct timespec *a, const struct timespec *b)
{
    return (double)(b->tv_sec - a->tv_sec) + 1e-9 * (double)(b->tv_nsec - a->tv_nsec);
}

/* A progress line when an increment has run SBC_PROGRESS_EVERY seconds
 * since the last line, so that a long increment is not silent. */
static void report_progress(const script *s, run_state *r)
{
    struct timespec now;
    char line[256];
    if (!s->log)
        return;
    timespec_get(&now, TIME_UTC);
    if (seconds_between(&r->reported, &now) < SBC_PROGRESS_EVERY)
        return;
    r->reported = now;
    sbc_controller_progress_line(r->ctl, sbc_engine_get_view(r->engine).step, seconds_between(&r->start, &now), line,
                                 sizeof line);
    fprintf(s->log, "  %s\n", line);
    fflush(s->log);
}

static void run_free(run_state *r)
{
    sbc_driver_free(r->driver);
    sbc_frame_free(&r->frame);
    sbc_engine_free(r->engine);
    sbc_controller_free(r->ctl);
    free(r->mass);
    free(r->rows);
    sbc_csv_close(&r->csv);
    sbc_script_tangent_close(&r->tangent);
}

static sbc_status keep_row(run_state *r, const sbc_result *row, sbc_error *err)
{
    if (r->nrows == r->cap) {
        int cap = r->cap ? 2 * r->cap : 64;
        sbc_result *p = realloc(r->rows, sizeof *p * (size_t)cap);
        if (!p)
            return sbc_fail(err, SBC_ERR_NOMEM, "run: out of memory for results");
        r->rows = p;
        r->cap = cap;
    }
    r->rows[r->nrows++] = *row;
    return SBC_OK;
}

/* sigma~ = sigma R / (kn t) against F12 (paper Sect. 4.1), with the 2D
 * stress (N/m) per unit thickness t = 1 m, so that sigma~ is dimensionless.
 * A path of negative F12 is drawn as the paper draws it, -sigma~ against
 * -F12, so that the loading runs left to right. */
static sbc_status write_plot(script *s, run_state *r, sbc_error *err)
{
    double *xs, *s11, *s12, rbar = 0.0, sign;
    sbc_series series[2];
    sbc_status st;
    int k;
    if (!s->plot[0] || r->nrows == 0)
        return SBC_OK;
    sign = s->settings.F[1] < 0.0 ? -1.0 : 1.0;
    for (k = 0; k < s->packing.n; ++k)
        rbar += s->packing.r[k] / s->packing.n;
    xs = malloc(sizeof(double) * (size_t)r->nrows);
    s11 = malloc(sizeof(double) * (size_t)r->nrows);
    s12 = malloc(sizeof(double) * (size_t)r->nrows);
    if (!xs || !s11 || !s12) {
        free(xs); free(s11); free(s12);
        return sbc_fail(err, SBC_ERR_NOMEM, "plot: out of memory");
    }
    for (k = 0; k < r->nrows; ++k) {
        xs[k] = sign * r->rows[k].F[1];
        s11[k] = sign * r->rows[k].sigma[0] * rbar / s->law.kn;
        s12[k] = sign * r->rows[k].sigma[1] * rbar / s->law.kn;
    }
    series[0].label = sign < 0.0 ? "-sigma~11 = -sigma11 R / (kn t)" : "sigma~11 = sigma11 R / (kn t)";
    series[0].y = s11;
    series[1].label = sign < 0.0 ? "-sigma~12 = -sigma12 R / (kn t)" : "sigma~12 = sigma12 R / (kn t)";
    series[1].y = s12;
    series[0].n = series[1].n = r->nrows;
    series[0].x = series[1].x = xs;
    st = sbc_plot_svg(s->plot, "servo_bc: normalized Cauchy stress (t = 1 m)", sign < 0.0 ? "-F12 (-)" : "F12 (-)",
                      sign < 0.0 ? "-sigma~ (-)" : "sigma~ (-)", 2, series, err);
    free(xs); free(s11); free(s12);
    return st;
}

/* A packing without a single pair touching within 1e-6 R_min cannot carry a load. */
static sbc_status expect_touching(const sbc_packing *p, sbc_error *err)
{
    double *angle, rmin = p->r[0];
    int n, k;
    sbc_status st;
    for (k = 1; k < p->n; ++k)
        if (p->r[k] < rmin) rmin = p->r[k];
    if ((st = sbc_packing_contact_angles(p, 1e-6 * rmin, &angle, &n, err)) != SBC_OK)
        return st;
    free(angle);
    if (n == 0)
        return sbc_fail(err, SBC_ERR_GEOMETRY,
                        "run: the packing has no contacts (no two particles touch; check radius and spacing)");
    return SBC_OK;
}

/* a converged increment: kept for the plot, the results file, the snapshots
   due, the log line */
static int engine_row(void *user_data, const sbc_result *row, const char *line, char *message, size_t cap)
{
    run_state *r = user_data;
    const script *s = r->s;
    const int last = row->increment == sbc_settings_total_increments(&s->settings);
    sbc_error err;
    sbc_status st;
    sbc_result filled = *row;
    r->increment_now = row->increment + 1;
    filled.newton_iterations = r->tally.iterations;
    filled.newton_held = r->tally.mechanisms;
    row = &filled;
    if ((st = keep_row(r, row, &err)) != SBC_OK || (r->csv.fp && (st = sbc_csv_write(&r->csv, row, &err)) != SBC_OK) ||
        (st = write_snapshots(s, r->engine, &r->frame, row->increment, last, &err)) != SBC_OK) {
        snprintf(message, cap, "%s", err.message);
        return st;
    }
    if (s->log) {
        fprintf(s->log, "%s\n", line);
        if (s->cohesive)
            fprintf(s->log, "  bonds intact %d\n", sbc_engine_get_view(r->engine).bond_count);
        if (r->aggregate.tally)
            sbc_script_tally_line(s, &r->tally);
        fflush(s->log);
    }
    if (sbc_script_tangent_row(s, &r->tangent, &r->aggregate, r->ctl, sbc_driver_fire(r->driver), row, &err) !=
        SBC_OK) {
        snprintf(message, cap, "%s", err.message);
        return err.status;
    }
    memset(&r->tally, 0, sizeof r->tally); /* the next increment's solves */
    timespec_get(&r->reported, TIME_UTC);
    return SBC_OK;
}

sbc_status sbc_script_run_once(script *s, sbc_error *err)
{
    run_state r;
    sbc_engine_def def = sbc_engine_def_default();
    sbc_status st = SBC_OK;
    sbc_snapshot snap;
    double dtc;
    memset(&r, 0, sizeof r);
    timespec_get(&r.start, TIME_UTC);
    r.reported = r.start;
    if (!s->have_packing) return sbc_fail(err, SBC_ERR_INPUT, "run: no packing (use 'lattice' or 'read_packing' first)");
    if (!s->have_contact) return sbc_fail(err, SBC_ERR_INPUT, "run: no contact law (use 'contact frictional ...' first)");
    if (!s->have_density) return sbc_fail(err, SBC_ERR_INPUT, "run: no density (use 'density RHO' first)");
    if (!s->have_dt) return sbc_fail(err, SBC_ERR_INPUT, "run: no time step (use 'timestep DT' first)");
    if (!s->have_servo) return sbc_fail(err, SBC_ERR_INPUT, "run: no boundary condition (use 'servo_bc BC ...' first)");
    if (s->settings.frame_group[0])
        return sbc_fail(err, SBC_ERR_INPUT,
                        "servo_bc (line %d): keyword 'frame' names a host group '%s'; the embedded runner detects "
                        "the frame from the packing",
                        s->servo_line, s->settings.frame_group);
    if ((st = sbc_script_outputs_check(s, err)) != SBC_OK)
        return st;

    if ((st = sbc_packing_distinct(s->packing.n, s->packing.x, s->packing.r, err)) != SBC_OK ||
        (st = sbc_frame_detect_packing(&r.frame, &s->packing, err)) != SBC_OK)
        return st;
    def.n = s->packing.n;
    def.x = s->packing.x;
    def.r = s->packing.r;
    def.density = s->density;
    def.law = s->law;
    def.bonds = s->cohesive ? &s->bond_law : NULL;
    def.dt = s->dt;
    def.alpha = s->settings.damping ? s->settings.alpha : 0.0;
    def.beta = s->settings.damping ? s->settings.beta : 0.0;
    def.fire = s->settings.damping == SBC_DAMPING_FIRE;
    if (!(r.engine = sbc_engine_create(&def, err))) {
        run_free(&r);
        return err->status;
    }
    dtc = sbc_engine_critical_dt(r.engine);
    if ((st = sbc_time_step_bound(s->dt, dtc, s->cohesive ? "2 sqrt(M_min / (2 kn)) or 2 sqrt(I_min / (2 kr))"
                                                          : "2 sqrt(M_min / (2 kn))",
                                  s->settings.max_relax_steps, err)) != SBC_OK) {
        if (s->dt_line > 0) /* the error belongs to the timestep command */
            s->line = s->dt_line;
        run_free(&r);
        return st;
    }
    sbc_engine_set_frame(r.engine, &r.frame);
    if (s->settings.seal && sbc_engine_seal(r.engine, err) != SBC_OK) {
        run_free(&r);
        return err->status;
    }
    r.mass = malloc(sizeof(double) * (size_t)r.frame.n);
    if (!r.mass) {
        run_free(&r);
        return sbc_fail(err, SBC_ERR_NOMEM, "run: out of memory");
    }
    sbc_engine_frame_masses(r.engine, r.mass);
    if (!(r.ctl = sbc_controller_create(&r.frame, &s->settings, r.mass, s->dt, s->law.kn, err))) {
        run_free(&r);
        return err->status;
    }
    if ((st = sbc_engine_forces(r.engine, err)) != SBC_OK) {
        run_free(&r);
        return st;
    }
    sbc_engine_snapshot(r.engine, &snap);
    if (snap.contact_count == 0 && (st = expect_touching(&s->packing, err)) != SBC_OK) {
        run_free(&r);
        return st;
    }
    if (s->settings.file[0] && !s->check && (st = sbc_csv_open(&r.csv, s->settings.file, 2, err)) != SBC_OK) {
        run_free(&r);
        return st;
    }
    sbc_script_files_note(s, s->settings.file, "results file");
    if ((st = sbc_script_tangent_open(s, 2, &r.tangent, err)) != SBC_OK) {
        run_free(&r);
        return st;
    }
    sbc_script_files_note(s, s->settings.tangent_file, "tangent file");
    r.aggregate.ops = &sbc_engine_ops_discs;
    r.aggregate.engine = r.engine;
    r.aggregate.n = s->packing.n;
    r.aggregate.frame = &r.frame;
    r.aggregate.settings = &s->settings;
    r.aggregate.mass = r.mass;
    r.aggregate.dt = s->dt;
    r.aggregate.law = s->law;
    r.aggregate.bonds = s->cohesive ? &s->bond_law : NULL;
    r.aggregate.tally = s->settings.interior == SBC_INTERIOR_NEWTON ? &r.tally : NULL;
    if (s->check) {
        if (s->log)
            fprintf(s->log, "check: run of line %d: servo_bc %s, %d particles, frame of %d, %d increments, dt = %g s "
                    "(critical %g s)\n", s->line, sbc_bc_name(s->settings.bc), s->packing.n, r.frame.n,
                    sbc_settings_total_increments(&s->settings), s->dt, dtc);
        run_free(&r);
        return SBC_OK;
    }
    if (s->log)
        fprintf(s->log, "servo_bc %s (servo-bc %s): %d particles, frame of %d, %d increments, dt = %g s (critical %g s)\n",
                sbc_bc_name(s->settings.bc), sbc_version(), s->packing.n, r.frame.n, sbc_settings_total_increments(&s->settings), s->dt, dtc);
    {
        char note[SBC_ERROR_LEN];
        if (s->log && sbc_settings_ignored_message(&s->settings, note, sizeof note))
            fprintf(s->log, "WARNING: %s\n", note);
        if (s->log && sbc_time_step_note(&s->settings, s->dt, dtc, note, sizeof note))
            fprintf(s->log, "WARNING: %s\n", note);
    }
    if (s->log && s->cohesive)
        fprintf(s->log, "servo_bc: %d cohesive bonds between the pairs touching at the start\n",
                sbc_engine_get_view(r.engine).bonds_initial);
    {
        sbc_driver_callbacks cb = sbc_aggregate_callbacks(&r.aggregate);
        cb.row = engine_row;
        cb.row_data = &r;
        r.s = s;
        if (!(r.driver = sbc_driver_create(r.ctl, &s->settings, &cb, err))) {
            run_free(&r);
            return err->status;
        }
    }
    /* the first step's forces were taken above; interior newton solves increment 0's interior first */
    if (r.aggregate.tally && (st = sbc_aggregate_advance(&r.aggregate, r.ctl, 1, err)) != SBC_OK) {
        run_free(&r);
        return st;
    }
    for (;;) {
        sbc_event ev = sbc_driver_step(r.driver, 0, err);
        if (ev == SBC_EVENT_FAILED || ++r.since_check == SBC_CONFINE_EVERY) {
            r.since_check = 0;
            report_progress(s, &r);
        }
        if (ev == SBC_EVENT_FAILED) {
            st = err->status;
            break;
        }
        if (ev == SBC_EVENT_FINISHED)
            break;
        if ((st = sbc_aggregate_advance(&r.aggregate, r.ctl, 0, err)) != SBC_OK) break;
    }
    if (st != SBC_OK) { /* the state the run stopped in, for a look in ParaView and a picture */
        sbc_error verr;
        sbc_engine_view view = sbc_engine_get_view(r.engine);
        if (s->vtk_every && sbc_vtk_write(s->vtk_prefix, r.increment_now, &view, &verr) == SBC_OK && s->log)
            fprintf(s->log, "servo_bc: the state the run stopped in is %s_particles_%06d.vtk\n", s->vtk_prefix,
                    r.increment_now);
        if (s->network_every) {
            char path[SBC_NAME_LEN + 32], title[96];
            snprintf(path, sizeof path, "%s_%06d.svg", s->network_prefix, r.increment_now);
            snprintf(title, sizeof title, "contact network where the run stopped, in increment %d", r.increment_now);
            if (sbc_network_svg(path, title, &view, &r.frame, &verr) == SBC_OK && s->log)
                fprintf(s->log, "servo_bc: its picture is %s\n", path);
        }
    }
    {
        sbc_error perr;
        sbc_error_clear(&perr);
        if (write_plot(s, &r, &perr) != SBC_OK && st == SBC_OK) {
            st = perr.status;
            *err = perr;
        }
    }
    if (s->log && st == SBC_OK) {
        struct timespec t1;
        long iters = 0, imax = 0;
        int k;
        timespec_get(&t1, TIME_UTC);
        for (k = 0; k < r.nrows; ++k) {
            iters += r.rows[k].iterations;
            if (r.rows[k].iterations > imax) imax = r.rows[k].iterations;
        }
        fprintf(s->log,
                "servo_bc: finished %d increments: %ld steps, servo iterations per increment mean %.2f max %ld, "
                "wall %.2f s\n",
                r.nrows, sbc_engine_get_view(r.engine).step, r.nrows ? (double)iters / r.nrows : 0.0, imax,
                seconds_between(&r.start, &t1));
        if (s->settings.file[0]) fprintf(s->log, "  results: %s\n", s->settings.file);
        if (s->vtk_every) fprintf(s->log, "  vtk:     %s_particles_*.vtk, %s_contacts_*.vtk\n", s->vtk_prefix, s->vtk_prefix);
        if (s->network_every) fprintf(s->log, "  network: %s_*.svg\n", s->network_prefix);
        if (s->plot[0]) fprintf(s->log, "  plot:    %s\n", s->plot);
    }
    run_free(&r);
    return st;
}

/* The servo_bc words without 'file NAME', for the decks of every host. */
static sbc_status keep_servo_words(script *s, int nw, char **w, sbc_error *err)
{
    size_t used = 0;
    int k;
    s->servo_words[0] = '\0';
    for (k = 1; k < nw; ++k) {
        if (strcmp(w[k], "file") == 0 && k + 1 < nw) {
            ++k;
            continue;
        }
        if (strcmp(w[k], "tangent") == 0 && k + 2 < nw) { /* the runner's (hosts refuse it) */
            k += 2;
            continue;
        }
        used += (size_t)snprintf(s->servo_words + used, used < sizeof s->servo_words ? sizeof s->servo_words - used : 0,
                                 "%s%s", used ? " " : "", w[k]);
        if (used >= sizeof s->servo_words)
            return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: the line is longer than %d characters",
                            (int)sizeof s->servo_words - 1);
    }
    return SBC_OK;
}

/* servo_bc BC ...: the words, held to the script's dimension (3 after
   'dimension 3') */
static sbc_status cmd_servo_bc(script *s, int nw, char **w, sbc_error *err)
{
    char msg[SBC_ERROR_LEN];
    sbc_status st;
    if (s->servo_pending)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: a second servo_bc line before a run has used the one of line "
                        "%d (each run takes the servo_bc line before it)", s->servo_line);
    st = sbc_settings_parse(&s->settings, nw - 1, (const char *const *)(w + 1), err);
    if (st == SBC_OK)
        st = sbc_settings_check_dimension(&s->settings, s->bpm ? 3 : 2, err);
    if (st != SBC_OK) {
        snprintf(msg, sizeof msg, "%s", err->message);
        return sbc_fail(err, st, "servo_bc: %s", msg);
    }
    s->have_servo = 1;
    s->servo_pending = 1;
    s->servo_line = s->line;
    return keep_servo_words(s, nw, w, err);
}

/* after 'dimension 3': the servo_bc commands on spheres (script_spheres.c),
   the bonded particle model's otherwise (script_bpm.c) */
static sbc_status execute_3d(script *s, int nw, char **w, sbc_error *err)
{
    const char *c = w[0];
    sbc_status st;
    if (strcmp(c, "lattice") == 0) return sbc_script_lattice_cubic(s, nw, w, err);
    if (strcmp(c, "generate") == 0) return sbc_script_generate(s, nw, w, err);
    if (strcmp(c, "read_packing") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "read_packing FILE", err)) != SBC_OK) return st;
        return sbc_script_read_spheres(s, w[1], err);
    }
    if (strcmp(c, "contact") == 0) {
        if (nw >= 2 && strcmp(w[1], "frictional") != 0)
            return sbc_fail(err, SBC_ERR_INPUT, "contact: law '%s' is 2D in this version (expected 'frictional' after "
                            "'dimension 3')", w[1]);
        return cmd_contact(s, nw, w, err);
    }
    if (strcmp(c, "servo_bc") == 0) return cmd_servo_bc(s, nw, w, err);
    if (strcmp(c, "write_packing") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 3, "write_packing text|lammps|liggghts|yade FILE", err)) != SBC_OK)
            return st;
        return sbc_script_write_spheres(s, w[1], w[2], err);
    }
    if (strcmp(c, "vtk") == 0 && nw == 3) /* vtk EVERY PREFIX: the servo run's; vtk PREFIX: the bonded model's */
        return cmd_snapshots(nw, w, &s->vtk_every, s->vtk_prefix, err);
    if (strcmp(c, "run") == 0 && s->servo_pending) {
        if ((st = sbc_script_expect_count(nw, w, 1, "run", err)) != SBC_OK) return st;
        if (sbc_script_bpm_vtk(s)[0])
            return sbc_fail(err, SBC_ERR_INPUT, "run: 'vtk %s' (one word) is the bonded model's snapshot of a 'test' "
                            "run; a servo_bc run writes its snapshots with 'vtk EVERY PREFIX'", sbc_script_bpm_vtk(s));
        s->servo_pending = 0;
        if (s->decks_dir)
            return s->write_decks(s, s->decks_dir, err);
        return s->replicas > 0 ? sbc_script_replicas(s, sbc_script_run_spheres, err) : sbc_script_run_spheres(s, err);
    }
    if (strcmp(c, "replicas") == 0) return sbc_script_replicas_command(s, nw, w, err);
    return sbc_script_bpm(s, nw, w, err);
}

static sbc_status execute(script *s, int nw, char **w, sbc_error *err)
{
    const char *c = w[0];
    sbc_status st;
    if (strcmp(c, "dimension") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "dimension 2|3", err)) != SBC_OK) return st;
        if (strcmp(w[1], "3") == 0) return sbc_script_bpm_begin(s, err);
        if (strcmp(w[1], "2") != 0)
            return sbc_fail(err, SBC_ERR_INPUT, "dimension: value '%s' is not supported (expected 2, or 3 for spheres and "
                            "the bonded particle model)", w[1]);
        sbc_script_bpm_free(s);
        return SBC_OK;
    }
    if (s->bpm) return execute_3d(s, nw, w, err);
    if (strcmp(c, "lattice") == 0) return cmd_lattice(s, nw, w, err);
    if (strcmp(c, "read_packing") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "read_packing FILE", err)) != SBC_OK) return st;
        sbc_packing_free(&s->packing);
        st = sbc_packing_read(&s->packing, w[1], err);
        s->have_packing = st == SBC_OK;
        if (st == SBC_OK)
            sbc_script_files_note(s, w[1], "packing read");
        return st;
    }
    if (strcmp(c, "generate") == 0) return sbc_script_generate(s, nw, w, err);
    if (strcmp(c, "write_packing") == 0) return sbc_script_write_packing(s, nw, w, err);
    if (strcmp(c, "rose") == 0) return sbc_script_rose(s, nw, w, err);
    if (strcmp(c, "contact") == 0) return cmd_contact(s, nw, w, err);
    if (strcmp(c, "density") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "density RHO", err)) != SBC_OK) return st;
        st = sbc_script_positive("density", "RHO", w[1], &s->density, err);
        s->have_density = st == SBC_OK;
        return st;
    }
    if (strcmp(c, "timestep") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "timestep DT", err)) != SBC_OK) return st;
        st = sbc_script_positive("timestep", "DT", w[1], &s->dt, err);
        s->have_dt = st == SBC_OK;
        s->dt_line = s->line;
        return st;
    }
    if (strcmp(c, "servo_bc") == 0) return cmd_servo_bc(s, nw, w, err);
    if (strcmp(c, "vtk") == 0) return cmd_snapshots(nw, w, &s->vtk_every, s->vtk_prefix, err);
    if (strcmp(c, "network") == 0) return cmd_snapshots(nw, w, &s->network_every, s->network_prefix, err);
    if (strcmp(c, "replicas") == 0) return sbc_script_replicas_command(s, nw, w, err);
    if (strcmp(c, "plot") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "plot FILE.svg", err)) != SBC_OK) return st;
        if (strlen(w[1]) >= SBC_NAME_LEN) return sbc_fail(err, SBC_ERR_INPUT, "plot: file name is too long");
        strcpy(s->plot, w[1]);
        return SBC_OK;
    }
    if (strcmp(c, "run") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 1, "run", err)) != SBC_OK) return st;
        s->servo_pending = 0;
        if (s->decks_dir)
            return s->write_decks(s, s->decks_dir, err);
        return s->replicas > 0 ? sbc_script_replicas(s, sbc_script_run_once, err) : sbc_script_run_once(s, err);
    }
    return sbc_fail(err, SBC_ERR_INPUT,
                    "unknown command '%s' (expected dimension, lattice, read_packing, generate, write_packing, rose, "
                    "contact, density, timestep, servo_bc, vtk, network, plot, replicas or run)",
                    c);
}

static sbc_status run_text(const char *text, const char *name, FILE *log, const char *decks_dir,
                           sbc_script_decks_fn write_decks, int check, sbc_error *err)
{
    script s;
    const char *p = text;
    sbc_status st = SBC_OK;
    sbc_error_clear(err);
    memset(&s, 0, sizeof s);
    s.name = name;
    s.log = log;
    s.decks_dir = decks_dir;
    s.write_decks = write_decks;
    s.check = check;
    s.settings = sbc_settings_default();
    while (*p && st == SBC_OK) {
        const char *e = strchr(p, '\n');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        char *line = malloc(len + 1), *w[MAX_WORDS];
        int nw;
        if (!line) {
            st = sbc_fail(err, SBC_ERR_NOMEM, "out of memory");
            break;
        }
        memcpy(line, p, len);
        line[len] = '\0';
        s.line++;
        nw = sbc_split_words(line, w, MAX_WORDS);
        if (nw > MAX_WORDS)
            st = at_line(&s, sbc_fail(err, SBC_ERR_INPUT, "%s: more than %d words on one line", w[0], MAX_WORDS), err);
        else if (nw > 0) {
            const int acts = strcmp(w[0], "run") == 0 || strcmp(w[0], "write_packing") == 0 || strcmp(w[0], "rose") == 0;
            st = at_line(&s, execute(&s, nw, w, err), err);
            s.actions += acts && st == SBC_OK;
        }
        free(line);
        p = e ? e + 1 : p + len;
    }
    if (st == SBC_OK && s.actions == 0)
        st = sbc_fail(err, SBC_ERR_INPUT, "%s: the script computes nothing (expected run, write_packing or rose)%s",
                      name, s.line == 0 ? "; it is empty" : "");
    sbc_packing_free(&s.packing);
    sbc_script_bpm_free(&s);
    sbc_script_spheres_free(&s);
    return st;
}

sbc_status sbc_script_run_string(const char *text, const char *name, FILE *log, sbc_error *err)
{
    return run_text(text, name, log, NULL, NULL, 0, err);
}

sbc_status sbc_script_check_string(const char *text, const char *name, FILE *log, sbc_error *err)
{
    return run_text(text, name, log, NULL, NULL, 1, err);
}

static sbc_status run_file(const char *path, FILE *log, const char *decks_dir, sbc_script_decks_fn write_decks,
                           int check, sbc_error *err)
{
    FILE *fp = fopen(path, "rb");
    char *text;
    long size;
    sbc_status st;
    if (!fp)
        return sbc_fail(err, SBC_ERR_IO, "cannot open script '%s'", path);
    if (fseek(fp, 0, SEEK_END) != 0 || (size = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET) != 0) {
        fclose(fp);
        return sbc_fail(err, SBC_ERR_IO, "cannot read script '%s'", path);
    }
    text = malloc((size_t)size + 1);
    if (!text) {
        fclose(fp);
        return sbc_fail(err, SBC_ERR_NOMEM, "out of memory for script '%s'", path);
    }
    if (fread(text, 1, (size_t)size, fp) != (size_t)size) {
        fclose(fp);
        free(text);
        return sbc_fail(err, SBC_ERR_IO, "cannot read script '%s'", path);
    }
    text[size] = '\0';
    fclose(fp);
    {
        /* a NUL byte would end the text early, and the rest unread */
        const char *nul = memchr(text, '\0', (size_t)size), *q;
        if (nul) {
            int line = 1;
            for (q = text; q < nul; ++q)
                line += *q == '\n';
            free(text);
            return sbc_fail(err, SBC_ERR_INPUT, "%s:%d: a NUL byte (expected a text script)", path, line);
        }
    }
    st = run_text(text, path, log, decks_dir, write_decks, check, err);
    free(text);
    return st;
}

sbc_status sbc_script_run_file(const char *path, FILE *log, sbc_error *err)
{
    return run_file(path, log, NULL, NULL, 0, err);
}

sbc_status sbc_script_check_file(const char *path, FILE *log, sbc_error *err)
{
    return run_file(path, log, NULL, NULL, 1, err);
}

sbc_status sbc_script_decks_file(const char *path, const char *dir, sbc_script_decks_fn write, FILE *log,
                                 sbc_error *err)
{
    if (!write)
        return sbc_fail(err, SBC_ERR_INPUT, "--decks: no deck writer");
    return run_file(path, log, dir, write, 0, err);
}
