/* The embedded runner's 3D commands (after `dimension 3`): the bonded
 * particle model of the thesis (docs/reproduction-bpm.md has the grammar).
 *
 *   packing cubic|hcp|random radius RP [box LX LY LZ] [porosity P] [seed N]
 *   bond parallel|beam [E EB] [nu NU] [ratio KN/KS] [alpha A] [damping XI] [touch T]
 *        [strength FT FS MB MT] [friction MU]
 *   density RHO [scaled]
 *   timestep DT | timestep critical F
 *   test uniaxial velocity V steps N [zone Z] [file F.csv]
 *   test bending force F ramp N steps N [nu NU] [zone Z] [file F.csv]
 *   vtk PREFIX
 *   run */
#define _POSIX_C_SOURCE 200809L
#include "script_state.h"
#include "sbc/embedded/output_file.h"
#include "base/words.h"

#include "sbc/bpm.h"
#include "sbc/embedded/bpm_loading.h"
#include "sbc/embedded/bpm_packing.h"
#include "sbc/embedded/bpm_stress.h"
#include "sbc/embedded/bpm_vtk.h"
#include "sbc/settings.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { TEST_NONE, TEST_UNIAXIAL, TEST_BENDING };

struct bpm_script {
    int lattice, have_packing, have_bond, have_density, have_dt, test, scaled;
    double rp, box[3], porosity;
    unsigned long seed;
    sbc_bpm_settings set;
    double ratio; /* k^n / k^s of the parallel bond */
    double density, dt, dt_fraction;
    sbc_bpm_uniaxial uniaxial;
    sbc_bpm_bending bending;
    char series[SBC_NAME_LEN], vtk[SBC_NAME_LEN];
};

void sbc_script_bpm_free(script *s)
{
    free(s->bpm);
    s->bpm = NULL;
}

sbc_status sbc_script_bpm_begin(script *s, sbc_error *err)
{
    struct bpm_script *b = calloc(1, sizeof *b);
    if (!b)
        return sbc_fail(err, SBC_ERR_NOMEM, "dimension: out of memory");
    b->box[0] = 0.25; /* the thesis' specimen, Sect. 4.1 */
    b->box[1] = b->box[2] = 0.1;
    b->porosity = 0.41;
    b->seed = 1;
    b->set = sbc_bpm_settings_default();
    b->ratio = 4.2;
    b->uniaxial.zone = b->bending.zone = 1.5;
    free(s->bpm);
    s->bpm = b;
    return SBC_OK;
}

/* a real from word w[k + 1] for keyword w[k] */
static sbc_status value(int nw, char **w, int k, double *out, sbc_error *err)
{
    if (k + 1 >= nw)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: keyword '%s' needs a value", w[0], w[k]);
    if (sbc_parse_real(w[k + 1], w[k], out, NULL) != SBC_OK || !isfinite(*out))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: %s '%s' is not a number", w[0], w[k], w[k + 1]);
    return SBC_OK;
}

static sbc_status positive(int nw, char **w, int k, double *out, sbc_error *err)
{
    sbc_status st = value(nw, w, k, out, err);
    if (st == SBC_OK && !(*out > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: %s %s is not positive (expected a real > 0)", w[0], w[k], w[k + 1]);
    return st;
}

static sbc_status steps_value(int nw, char **w, int k, long *out, sbc_error *err)
{
    double d;
    sbc_status st = value(nw, w, k, &d, err);
    if (st != SBC_OK)
        return st;
    if (d < 1.0 || d > 1e12 || d != floor(d))
        return sbc_fail(err, SBC_ERR_INPUT, "%s: %s %s (expected a whole number from 1 to 1e12)", w[0], w[k], w[k + 1]);
    *out = (long)d;
    return SBC_OK;
}

static sbc_status name_value(int nw, char **w, int k, char *out, sbc_error *err)
{
    if (k + 1 >= nw)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: keyword '%s' needs a file name", w[0], w[k]);
    if (strlen(w[k + 1]) >= SBC_NAME_LEN)
        return sbc_fail(err, SBC_ERR_INPUT, "%s: file name '%s' is too long", w[0], w[k + 1]);
    strcpy(out, w[k + 1]);
    return SBC_OK;
}

static sbc_status unknown(char **w, int k, const char *expected, sbc_error *err)
{
    return sbc_fail(err, SBC_ERR_INPUT, "%s: unknown keyword '%s' (expected %s)", w[0], w[k], expected);
}

static sbc_status cmd_packing(struct bpm_script *b, int nw, char **w, sbc_error *err)
{
    sbc_status st = SBC_OK;
    int k, have_radius = 0;
    if (nw < 2)
        return sbc_fail(err, SBC_ERR_INPUT, "packing: missing values (expected 'packing cubic|hcp|random radius RP "
                        "[box LX LY LZ] [porosity P] [seed N]')");
    if (strcmp(w[1], "cubic") == 0) b->lattice = 0;
    else if (strcmp(w[1], "hcp") == 0) b->lattice = 1;
    else if (strcmp(w[1], "random") == 0) b->lattice = 2;
    else return sbc_fail(err, SBC_ERR_INPUT, "packing: kind '%s' is not known (expected cubic, hcp or random)", w[1]);
    for (k = 2; k < nw && st == SBC_OK; k += 2) {
        if (strcmp(w[k], "radius") == 0) {
            st = positive(nw, w, k, &b->rp, err);
            have_radius = 1;
        } else if (strcmp(w[k], "box") == 0) {
            int q;
            if (k + 3 >= nw)
                st = sbc_fail(err, SBC_ERR_INPUT, "packing: box needs three lengths (expected 'box LX LY LZ', m)");
            for (q = 0; q < 3 && st == SBC_OK; ++q)
                st = sbc_script_positive("packing", "box length", w[k + 1 + q], &b->box[q], err);
            k += 2;
        } else if (strcmp(w[k], "porosity") == 0) {
            st = value(nw, w, k, &b->porosity, err);
        } else if (strcmp(w[k], "seed") == 0) {
            long seed;
            st = steps_value(nw, w, k, &seed, err);
            b->seed = (unsigned long)seed;
        } else {
            st = unknown(w, k, "radius, box, porosity or seed", err);
        }
    }
    if (st == SBC_OK && !have_radius)
        st = sbc_fail(err, SBC_ERR_INPUT, "packing: keyword 'radius' is missing (expected 'radius RP', m)");
    b->have_packing = st == SBC_OK;
    return st;
}

static sbc_status cmd_bond(struct bpm_script *b, int nw, char **w, sbc_error *err)
{
    sbc_status st = SBC_OK;
    int k;
    if (nw < 2)
        return sbc_fail(err, SBC_ERR_INPUT, "bond: missing values (expected 'bond parallel|beam [E EB] [nu NU] "
                        "[ratio KN/KS] [alpha A] [damping XI] [touch T]')");
    if (strcmp(w[1], "parallel") == 0) b->set.model = SBC_BOND_PARALLEL;
    else if (strcmp(w[1], "beam") == 0) b->set.model = SBC_BOND_BEAM;
    else return sbc_fail(err, SBC_ERR_INPUT, "bond: model '%s' is not known (expected parallel or beam)", w[1]);
    for (k = 2; k < nw && st == SBC_OK; k += 2) {
        if (strcmp(w[k], "E") == 0) st = positive(nw, w, k, &b->set.beam.E, err);
        else if (strcmp(w[k], "nu") == 0) st = value(nw, w, k, &b->set.beam.nu, err);
        else if (strcmp(w[k], "ratio") == 0) st = positive(nw, w, k, &b->ratio, err);
        else if (strcmp(w[k], "alpha") == 0) st = positive(nw, w, k, &b->set.alpha, err);
        else if (strcmp(w[k], "damping") == 0) st = value(nw, w, k, &b->set.xi, err);
        else if (strcmp(w[k], "touch") == 0) st = value(nw, w, k, &b->set.touch, err);
        else if (strcmp(w[k], "friction") == 0) st = value(nw, w, k, &b->set.mu, err);
        else if (strcmp(w[k], "strength") == 0) {
            double *v[4] = {&b->set.strength.tension, &b->set.strength.shear, &b->set.strength.bending,
                            &b->set.strength.twisting};
            int q;
            if (k + 4 >= nw)
                st = sbc_fail(err, SBC_ERR_INPUT, "bond: strength needs four values (expected 'strength FT FS MB MT': "
                              "tension N, shear N, bending N m, twisting N m)");
            for (q = 0; q < 4 && st == SBC_OK; ++q) {
                st = sbc_parse_real(w[k + 1 + q], "strength", v[q], NULL);
                if (st != SBC_OK || !(*v[q] >= 0.0) || (q == 0 && !(*v[q] > 0.0)))
                    st = sbc_fail(err, SBC_ERR_INPUT, "bond: strength value '%s' (expected a tension > 0 and shear, "
                                  "bending, twisting >= 0; 0 leaves a term out)", w[k + 1 + q]);
            }
            k += 3;
        } else st = unknown(w, k, "E, nu, ratio, alpha, damping, touch, strength or friction", err);
    }
    if (st == SBC_OK && !(b->set.beam.nu > -1.0 && b->set.beam.nu < 0.5))
        st = sbc_fail(err, SBC_ERR_INPUT, "bond: nu %g (expected -1 < nu < 0.5)", b->set.beam.nu);
    if (st == SBC_OK && !(b->set.alpha <= 1.0))
        st = sbc_fail(err, SBC_ERR_INPUT, "bond: alpha %g (expected 0 < alpha <= 1, eq. 9)", b->set.alpha);
    if (st == SBC_OK && !(b->set.xi >= 0.0))
        st = sbc_fail(err, SBC_ERR_INPUT, "bond: damping %g (expected a damping ratio >= 0, eq. 37)", b->set.xi);
    if (st == SBC_OK && !(b->set.touch >= 0.0 && b->set.touch < 0.5))
        st = sbc_fail(err, SBC_ERR_INPUT, "bond: touch %g (expected 0 <= touch < 0.5, a fraction of ra + rb)",
                      b->set.touch);
    b->have_bond = st == SBC_OK;
    return st;
}

static sbc_status cmd_test(struct bpm_script *b, int nw, char **w, sbc_error *err)
{
    sbc_status st = SBC_OK;
    int k, have_steps = 0, have_load = 0, have_ramp = 0;
    if (nw < 2 || (strcmp(w[1], "uniaxial") != 0 && strcmp(w[1], "bending") != 0))
        return sbc_fail(err, SBC_ERR_INPUT, "test: kind '%s' is not known (expected uniaxial or bending)",
                        nw < 2 ? "" : w[1]);
    b->test = strcmp(w[1], "uniaxial") == 0 ? TEST_UNIAXIAL : TEST_BENDING;
    b->series[0] = '\0';
    for (k = 2; k < nw && st == SBC_OK; k += 2) {
        if (strcmp(w[k], "steps") == 0) {
            st = steps_value(nw, w, k, b->test == TEST_UNIAXIAL ? &b->uniaxial.steps : &b->bending.steps, err);
            have_steps = 1;
        } else if (strcmp(w[k], "zone") == 0) {
            st = positive(nw, w, k, b->test == TEST_UNIAXIAL ? &b->uniaxial.zone : &b->bending.zone, err);
        } else if (strcmp(w[k], "file") == 0) {
            st = name_value(nw, w, k, b->series, err);
        } else if (b->test == TEST_UNIAXIAL && strcmp(w[k], "velocity") == 0) {
            st = value(nw, w, k, &b->uniaxial.velocity, err);
            if (st == SBC_OK && b->uniaxial.velocity == 0.0)
                st = sbc_fail(err, SBC_ERR_INPUT, "test: velocity 0 (expected > 0 for tension, < 0 for compression)");
            have_load = 1;
        } else if (b->test == TEST_BENDING && strcmp(w[k], "force") == 0) {
            st = positive(nw, w, k, &b->bending.force, err);
            have_load = 1;
        } else if (b->test == TEST_BENDING && strcmp(w[k], "ramp") == 0) {
            st = steps_value(nw, w, k, &b->bending.ramp, err);
            have_ramp = 1;
        } else if (b->test == TEST_BENDING && strcmp(w[k], "nu") == 0) {
            st = value(nw, w, k, &b->bending.nu, err);
        } else {
            st = unknown(w, k, b->test == TEST_UNIAXIAL ? "velocity, steps, zone or file"
                                                        : "force, ramp, steps, nu, zone or file", err);
        }
    }
    if (st == SBC_OK && (!have_steps || !have_load || (b->test == TEST_BENDING && !have_ramp)))
        st = sbc_fail(err, SBC_ERR_INPUT, "test: %s needs %s", w[1],
                      b->test == TEST_UNIAXIAL ? "'velocity V' and 'steps N'" : "'force F', 'ramp N' and 'steps N'");
    if (st != SBC_OK)
        b->test = TEST_NONE;
    return st;
}

/* the packing into e, bonded; *porosity of the spheres' extent */
static sbc_status build(struct bpm_script *b, sbc_bpm *e, double *porosity, sbc_error *err)
{
    double ext[6], rho = b->density;
    sbc_status st;
    size_t i;
    if (b->lattice == 2)
        st = sbc_bpm_pack_random(e, b->box, b->rp, rho, b->porosity, b->seed, ext, err);
    else
        st = sbc_bpm_pack_lattice(e, b->lattice ? SBC_PACK_HCP : SBC_PACK_CUBIC, b->box, b->rp, rho, ext, err);
    if (st != SBC_OK)
        return st;
    *porosity = sbc_bpm_porosity(e, ext);
    if (b->scaled) /* eq. 63 */
        for (i = 0; i < e->n; ++i) {
            e->m[i] /= 1.0 - *porosity;
            e->inertia[i] /= 1.0 - *porosity;
        }
    return sbc_bpm_bond_touching(e, err);
}

static sbc_status cmd_run(script *s, struct bpm_script *b, sbc_error *err)
{
    sbc_bpm *e = NULL;
    sbc_bpm_settings set = b->set;
    double porosity = 0.0, dtc;
    FILE *series = NULL;
    clock_t c0;
    double seconds;
    long steps;
    sbc_status st;
    if (!b->have_packing) return sbc_fail(err, SBC_ERR_INPUT, "run: no packing (expected a 'packing' command before 'run')");
    if (!b->have_bond) return sbc_fail(err, SBC_ERR_INPUT, "run: no bond model (expected a 'bond' command before 'run')");
    if (!b->have_density) return sbc_fail(err, SBC_ERR_INPUT, "run: no density (expected 'density RHO' before 'run')");
    if (!b->have_dt) return sbc_fail(err, SBC_ERR_INPUT, "run: no time step (expected 'timestep DT' or 'timestep critical F')");
    if (b->test == TEST_NONE) return sbc_fail(err, SBC_ERR_INPUT, "run: no test (expected 'test uniaxial ...' or 'test bending ...')");
    set.parallel = sbc_bpm_parallel_law(set.beam.E, b->rp, b->ratio); /* Table 3 */
    if ((st = sbc_bpm_create(&set, &e, err)) != SBC_OK) {
        char msg[SBC_ERROR_LEN];
        snprintf(msg, sizeof msg, "%s", err->message);
        return sbc_fail(err, st, "bond: %s", msg);
    }
    if ((st = build(b, e, &porosity, err)) != SBC_OK)
        goto done;
    dtc = sbc_bpm_critical_dt(e);
    e->dt = b->dt_fraction > 0.0 ? b->dt_fraction * dtc : b->dt;
    if (s->log)
        fprintf(s->log, "bpm: %s packing, %zu spheres of r_p %g m, porosity %.4f, %zu bonds (C_n %.3f), %s bonds, "
                "time step %.4g s (%.3f of eq. 48's %.4g s)\n", b->lattice == 0 ? "cubic" : b->lattice == 1 ? "hcp" : "random",
                e->n, b->rp, porosity, e->nb, sbc_bpm_mean_coordination(e),
                set.model == SBC_BOND_BEAM ? "Timoshenko beam" : "parallel", e->dt, e->dt / dtc, dtc);
    if (e->dt > dtc && s->log)
        fprintf(s->log, "bpm: warning: the time step is above the estimate of eq. 48\n");
    if (s->check)
        goto done;
    if (b->series[0] && !(series = sbc_output_open(b->series, SBC_OUTPUT_SERIES, "test: keyword 'file'", err))) {
        st = err->status;
        goto done;
    }
    c0 = clock();
    if (b->test == TEST_UNIAXIAL) {
        sbc_bpm_uniaxial_result r;
        b->uniaxial.rp = b->rp;
        b->uniaxial.series = series;
        if (series) fprintf(series, "step,dL,Fx,eps_y,eps_z,W_kin,W_int,W_dis,W_ext\n");
        st = sbc_bpm_uniaxial_run(e, &b->uniaxial, &r, err);
        steps = b->uniaxial.steps;
        if (st == SBC_OK && s->log)
            fprintf(s->log, "uniaxial: E %.6g Pa (eq. 64), nu_xy %.4g nu_xz %.4g (eq. 65), F_x %.6g N at dL %.6g m, "
                    "L0 %.6g m, A %.6g m^2, %zu loaded and %zu held spheres\n"
                    "uniaxial: sigma_xx %.6g Pa (RVE, eq. 54) against F_x/A %.6g Pa: %.3f %%; energy balance (eq. 53) "
                    "%.2e\n", r.E, r.nu_xy, r.nu_xz, r.force, r.dL, r.L0, r.A, r.loaded, r.held, r.sigma_rve[0],
                    r.sigma_load, r.sigma_load != 0.0 ? 100.0 * (r.sigma_rve[0] - r.sigma_load) / r.sigma_load : 0.0,
                    r.balance);
    } else {
        sbc_bpm_bending_result r;
        b->bending.rp = b->rp;
        b->bending.series = series;
        if (series) fprintf(series, "step,F,delta,W_kin,W_int,W_dis,W_ext\n");
        st = sbc_bpm_bending_run(e, &b->bending, &r, err);
        steps = b->bending.steps;
        if (st == SBC_OK && s->log)
            fprintf(s->log, "bending: delta %.6g m (swing %.2g m over the last tenth), E_f %.6g Pa (point load, eq. 67), "
                    "%.6g Pa (over b = %.4g m, eq. 69), L_e %.6g m, %zu loaded spheres, %zu on the supports; energy "
                    "balance (eq. 53) %.2e\n", r.delta, r.swing, r.Ef_point, r.Ef_band, r.b, r.Le, r.loaded,
                    r.supports, r.balance);
    }
    seconds = (double)(clock() - c0) / CLOCKS_PER_SEC;
    if (st == SBC_OK && s->log)
        fprintf(s->log, "bpm: %ld steps in %.2f s: %.1f ns per sphere-step, %.1f ns per bond-step\n", steps, seconds,
                1e9 * seconds / ((double)steps * (double)e->n), 1e9 * seconds / ((double)steps * (double)e->nb));
    if (st == SBC_OK && set.strength.tension > 0.0 && s->log)
        fprintf(s->log, "bpm: %zu of %zu bonds broken\n", e->nbroken, e->nb);
    if (st == SBC_OK && b->vtk[0] && (st = sbc_bpm_vtk_write(b->vtk, e, err)) == SBC_OK && s->log)
        fprintf(s->log, "bpm: spheres with their stress (eq. 62) in %s_spheres.vtk\n", b->vtk);
done:
    if (series && st == SBC_OK)
        st = sbc_output_close(series, b->series, "test: keyword 'file'", err);
    else if (series)
        fclose(series);
    sbc_bpm_free(e);
    return st;
}

void sbc_script_bpm_material(const script *s, double *density, double *dt, double *dt_fraction)
{
    const struct bpm_script *b = s->bpm;
    *density = b && b->have_density && !b->scaled ? b->density : 0.0;
    *dt = b && b->have_dt ? b->dt : 0.0;
    *dt_fraction = b && b->have_dt ? b->dt_fraction : 0.0;
}

const char *sbc_script_bpm_vtk(const script *s) { return s->bpm ? s->bpm->vtk : ""; }

sbc_status sbc_script_bpm(script *s, int nw, char **w, sbc_error *err)
{
    struct bpm_script *b = s->bpm;
    const char *c = w[0];
    sbc_status st;
    if (strcmp(c, "packing") == 0) return cmd_packing(b, nw, w, err);
    if (strcmp(c, "bond") == 0) return cmd_bond(b, nw, w, err);
    if (strcmp(c, "density") == 0) {
        if (nw == 3 && strcmp(w[2], "scaled") != 0)
            return sbc_fail(err, SBC_ERR_INPUT, "density: unknown word '%s' (expected 'density RHO [scaled]')", w[2]);
        if (nw < 2 || nw > 3)
            return sbc_fail(err, SBC_ERR_INPUT, "density: expected 'density RHO [scaled]'");
        st = positive(nw, w, 0, &b->density, err);
        b->scaled = nw == 3;
        b->have_density = st == SBC_OK;
        return st;
    }
    if (strcmp(c, "timestep") == 0) {
        s->dt_line = s->line;
        if (nw == 3 && strcmp(w[1], "critical") == 0) {
            st = positive(nw, w, 1, &b->dt_fraction, err);
            b->have_dt = st == SBC_OK;
            return st;
        }
        if (nw != 2 || strcmp(w[1], "critical") == 0)
            return sbc_fail(err, SBC_ERR_INPUT, "timestep: expected 'timestep DT' (s) or 'timestep critical F' "
                            "(F times eq. 48)");
        b->dt_fraction = 0.0;
        st = positive(nw, w, 0, &b->dt, err);
        b->have_dt = st == SBC_OK;
        return st;
    }
    if (strcmp(c, "test") == 0) return cmd_test(b, nw, w, err);
    if (strcmp(c, "vtk") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 2, "vtk PREFIX", err)) != SBC_OK) return st;
        return name_value(nw, w, 0, b->vtk, err);
    }
    if (strcmp(c, "run") == 0) {
        if ((st = sbc_script_expect_count(nw, w, 1, "run", err)) != SBC_OK) return st;
        if (s->decks_dir)
            return sbc_fail(err, SBC_ERR_INPUT, "run: the 3D model runs on the embedded engine only (no host decks)");
        return cmd_run(s, b, err);
    }
    return sbc_fail(err, SBC_ERR_INPUT,
                    "unknown command '%s' after 'dimension 3' (expected packing, bond, density, timestep, test, vtk, "
                    "lattice, generate, read_packing, write_packing, contact, servo_bc, replicas or run; plot and network "
                    "are 2D in this version)", c);
}
