/* The embedded runner: script commands -> packing, engine, controller. */
#include "sbc/script.h"

#include "sbc/controller.h"
#include "sbc/engine.h"
#include "sbc/frame.h"
#include "sbc/homogenize.h"
#include "sbc/packing.h"
#include "sbc/plot.h"
#include "sbc/results.h"
#include "sbc/settings.h"
#include "sbc/vtk.h"
#include "script_state.h"
#include "words.h"

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

sbc_status sbc_script_expect_count(int nw, char **w, int want, const char *usage, sbc_error *err)
{
    if (nw < want)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: missing values (expected '%s')", w[0], usage);
    if (nw > want)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: unexpected extra value '%s' (expected '%s')", w[0], w[want], usage);
    return SBC_OK;
}

sbc_status sbc_script_expect_key(const char *cmd, const char *word, const char *key, const char *usage, sbc_error *err)
{
    if (strcmp(word, key) != 0)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: expected keyword '%s' but found '%s' (usage '%s')", cmd, key, word,
                        usage);
    return SBC_OK;
}

sbc_status sbc_script_positive(const char *cmd, const char *what, const char *word, double *out, sbc_error *err)
{
    if (sbc_parse_real(word, what, out, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: %s '%s' is not a number (expected a real > 0)", cmd, what, word);
    if (!(*out > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: %s %s is not positive (expected a real > 0)", cmd, what, word);
    return SBC_OK;
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
    if ((st = sbc_script_expect_key("lattice", w[4], "spacing", usage, err)) != SBC_OK) return st;
    if ((st = sbc_script_positive("lattice", "spacing", w[5], &d, err)) != SBC_OK) return st;
    if ((st = sbc_script_expect_key("lattice", w[6], "radius", usage, err)) != SBC_OK) return st;
    if ((st = sbc_script_positive("lattice", "radius", w[7], &r, err)) != SBC_OK) return st;
    sbc_packing_free(&s->packing);
    st = sbc_packing_lattice_square(&s->packing, (int)nx, (int)ny, d, r, err);
    s->have_packing = st == SBC_OK;
    return st;
}

static sbc_status cmd_contact(script *s, int nw, char **w, sbc_error *err)
{
    static const char usage[] = "contact frictional kn KN ks KS mu MU";
    sbc_status st = sbc_script_expect_count(nw, w, 8, usage, err);
    if (st != SBC_OK) return st;
    if (strcmp(w[1], "frictional") != 0)
        return sbc_fail(err, SBC_ERR_INPUT, "contact: law '%s' is not known (expected 'frictional')", w[1]);
    if ((st = sbc_script_expect_key("contact", w[2], "kn", usage, err)) != SBC_OK) return st;
    if ((st = sbc_script_positive("contact", "kn", w[3], &s->law.kn, err)) != SBC_OK) return st;
    if ((st = sbc_script_expect_key("contact", w[4], "ks", usage, err)) != SBC_OK) return st;
    if (sbc_parse_real(w[5], "ks", &s->law.ks, NULL) != SBC_OK || s->law.ks < 0.0)
        return sbc_fail(err, SBC_ERR_INPUT, "contact: ks '%s' is not valid (expected a real >= 0)", w[5]);
    if ((st = sbc_script_expect_key("contact", w[6], "mu", usage, err)) != SBC_OK) return st;
    if (sbc_parse_real(w[7], "mu", &s->law.mu, NULL) != SBC_OK || s->law.mu < 0.0)
        return sbc_fail(err, SBC_ERR_INPUT, "contact: mu '%s' is not valid (expected a real >= 0)", w[7]);
    s->have_contact = 1;
    return SBC_OK;
}

static sbc_status cmd_vtk(script *s, int nw, char **w, sbc_error *err)
{
    long every;
    sbc_status st = sbc_script_expect_count(nw, w, 3, "vtk EVERY PREFIX", err);
    if (st != SBC_OK) return st;
    if (sbc_parse_int(w[1], "EVERY", 1, 100000000L, &every, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "vtk: EVERY '%s' is not valid (expected an integer >= 1)", w[1]);
    if (strlen(w[2]) >= SBC_NAME_LEN)
        return sbc_fail(err, SBC_ERR_INPUT, "vtk: PREFIX is too long");
    s->vtk_every = (int)every;
    strcpy(s->vtk_prefix, w[2]);
    return SBC_OK;
}

/* Everything `run` needs, freed in one place. */
typedef struct run_state {
    sbc_frame frame;
    sbc_engine *engine;
    sbc_controller *ctl;
    double *mass;
    FILE *csv;
    sbc_result *rows;
    int nrows, cap;
} run_state;

static void run_free(run_state *r)
{
    sbc_frame_free(&r->frame);
    sbc_engine_free(r->engine);
    sbc_controller_free(r->ctl);
    free(r->mass);
    free(r->rows);
    if (r->csv)
        fclose(r->csv);
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

/* sigma~ = sigma R / kn against F12 (paper Sect. 4.1). */
static sbc_status write_plot(script *s, run_state *r, sbc_error *err)
{
    double *xs, *s11, *s12, rbar = 0.0;
    sbc_series series[2];
    sbc_status st;
    int k;
    if (!s->plot[0] || r->nrows == 0)
        return SBC_OK;
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
        xs[k] = r->rows[k].F[1];
        s11[k] = r->rows[k].sigma[0] * rbar / s->law.kn;
        s12[k] = r->rows[k].sigma[1] * rbar / s->law.kn;
    }
    series[0].label = "sigma~11 = sigma11 R / kn";
    series[0].y = s11;
    series[1].label = "sigma~12 = sigma12 R / kn";
    series[1].y = s12;
    series[0].n = series[1].n = r->nrows;
    series[0].x = series[1].x = xs;
    st = sbc_plot_svg(s->plot, "servo_bc: normalized Cauchy stress", "F12", "sigma~ (m)", 2, series, err);
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

static sbc_status cmd_run(script *s, sbc_error *err)
{
    run_state r;
    sbc_engine_def def = sbc_engine_def_default();
    sbc_status st = SBC_OK;
    sbc_snapshot snap;
    double dtc;
    struct timespec t0;
    timespec_get(&t0, TIME_UTC);
    memset(&r, 0, sizeof r);
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

    if ((st = sbc_frame_detect_packing(&r.frame, &s->packing, err)) != SBC_OK)
        return st;
    def.n = s->packing.n;
    def.x = s->packing.x;
    def.r = s->packing.r;
    def.density = s->density;
    def.law = s->law;
    def.dt = s->dt;
    def.alpha = s->settings.damping ? s->settings.alpha : 0.0;
    def.beta = s->settings.damping ? s->settings.beta : 0.0;
    if (!(r.engine = sbc_engine_create(&def, err))) {
        run_free(&r);
        return err->status;
    }
    dtc = sbc_engine_critical_dt(r.engine);
    if (s->dt > dtc) {
        run_free(&r);
        return sbc_fail(err, SBC_ERR_INPUT, "timestep %g s exceeds the critical step %g s = 2 sqrt(M_min / (2 kn))",
                        s->dt, dtc);
    }
    sbc_engine_set_frame(r.engine, &r.frame);
    r.mass = malloc(sizeof(double) * (size_t)r.frame.n);
    if (!r.mass) {
        run_free(&r);
        return sbc_fail(err, SBC_ERR_NOMEM, "run: out of memory");
    }
    sbc_engine_frame_masses(r.engine, r.mass);
    if (!(r.ctl = sbc_controller_create(&r.frame, &s->settings, r.mass, s->dt, err))) {
        run_free(&r);
        return err->status;
    }
    if ((st = sbc_engine_step(r.engine, err)) != SBC_OK) {
        run_free(&r);
        return st;
    }
    sbc_engine_snapshot(r.engine, &snap);
    if (snap.contact_count == 0 && (st = expect_touching(&s->packing, err)) != SBC_OK) {
        run_free(&r);
        return st;
    }
    if (s->settings.file[0] && (st = sbc_csv_open(&r.csv, s->settings.file, err)) != SBC_OK) {
        run_free(&r);
        return st;
    }
    if (s->log)
        fprintf(s->log, "servo_bc %s: %d particles, frame of %d, %d increments, dt = %g s (critical %g s)\n",
                sbc_bc_name(s->settings.bc), s->packing.n, r.frame.n, sbc_settings_total_increments(&s->settings), s->dt, dtc);
    for (;;) {
        sbc_commands cmd;
        sbc_event ev = sbc_controller_step(r.ctl, &snap, err);
        if (ev == SBC_EVENT_FAILED) {
            st = err->status;
            break;
        }
        if (ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED) {
            const sbc_result *row = sbc_controller_result(r.ctl);
            if ((st = keep_row(&r, row, err)) != SBC_OK) break;
            if (r.csv && (st = sbc_csv_write(r.csv, row, err)) != SBC_OK) break;
            if (s->vtk_every && (row->increment % s->vtk_every == 0 || ev == SBC_EVENT_FINISHED)) {
                sbc_engine_view view = sbc_engine_get_view(r.engine);
                if ((st = sbc_vtk_write(s->vtk_prefix, row->increment, &view, err)) != SBC_OK) break;
            }
            if (s->log)
                fprintf(s->log, "increment %d/%d  F12 %+.5f  sigma11 %+.6e  sigma12 %+.6e N/m  steps %ld  HM %.1e\n",
                        row->increment, sbc_settings_total_increments(&s->settings), row->F[1], row->sigma[0], row->sigma[1],
                        row->relax_steps, row->hill_mandel);
            if (ev == SBC_EVENT_FINISHED) break;
        }
        cmd = sbc_controller_commands(r.ctl);
        sbc_engine_move_frame(r.engine, &cmd);
        if ((st = sbc_engine_step(r.engine, err)) != SBC_OK) break;
        sbc_engine_snapshot(r.engine, &snap);
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
                (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
        if (s->settings.file[0]) fprintf(s->log, "  results: %s\n", s->settings.file);
        if (s->vtk_every) fprintf(s->log, "  vtk:     %s_particles_*.vtk, %s_contacts_*.vtk\n", s->vtk_prefix, s->vtk_prefix);
        if (s->plot[0]) fprintf(s->log, "  plot:    %s\n", s->plot);
    }
    run_free(&r);
    return st;
}

static sbc_status execute(script *s, int nw, char **w, sbc_error *err)
{
    const char *c = w[0];
    sbc_status st;
    if (strcmp(c, "dimension") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "dimension 2", err)) != SBC_OK) return st;
        if (strcmp(w[1], "2") != 0)
            return sbc_fail(err, SBC_ERR_INPUT, "dimension: value '%s' is not supported (expected 2)", w[1]);
        return SBC_OK;
    }
    if (strcmp(c, "lattice") == 0) return cmd_lattice(s, nw, w, err);
    if (strcmp(c, "read_packing") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "read_packing FILE", err)) != SBC_OK) return st;
        sbc_packing_free(&s->packing);
        st = sbc_packing_read(&s->packing, w[1], err);
        s->have_packing = st == SBC_OK;
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
        return st;
    }
    if (strcmp(c, "servo_bc") == 0) {
        char msg[SBC_ERROR_LEN];
        st = sbc_settings_parse(&s->settings, nw - 1, (const char *const *)(w + 1), err);
        if (st != SBC_OK) {
            snprintf(msg, sizeof msg, "%s", err->message);
            return sbc_fail(err, st, "servo_bc: %s", msg);
        }
        s->have_servo = 1;
        s->servo_line = s->line;
        return SBC_OK;
    }
    if (strcmp(c, "vtk") == 0) return cmd_vtk(s, nw, w, err);
    if (strcmp(c, "plot") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "plot FILE.svg", err)) != SBC_OK) return st;
        if (strlen(w[1]) >= SBC_NAME_LEN) return sbc_fail(err, SBC_ERR_INPUT, "plot: file name is too long");
        strcpy(s->plot, w[1]);
        return SBC_OK;
    }
    if (strcmp(c, "run") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 1, "run", err)) != SBC_OK) return st;
        return cmd_run(s, err);
    }
    return sbc_fail(err, SBC_ERR_INPUT,
                    "unknown command '%s' (expected dimension, lattice, read_packing, generate, write_packing, rose, "
                    "contact, density, timestep, servo_bc, vtk, plot or run)",
                    c);
}

sbc_status sbc_script_run_string(const char *text, const char *name, FILE *log, sbc_error *err)
{
    script s;
    const char *p = text;
    sbc_status st = SBC_OK;
    sbc_error_clear(err);
    memset(&s, 0, sizeof s);
    s.name = name;
    s.log = log;
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
        else if (nw > 0)
            st = at_line(&s, execute(&s, nw, w, err), err);
        free(line);
        p = e ? e + 1 : p + len;
    }
    sbc_packing_free(&s.packing);
    return st;
}

sbc_status sbc_script_run_file(const char *path, FILE *log, sbc_error *err)
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
    st = sbc_script_run_string(text, path, log, err);
    free(text);
    return st;
}
