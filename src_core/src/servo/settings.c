/* The servo_bc keyword parser shared by every host. */
#include "sbc/settings.h"
#include "update_rules.h"

#include "settings_mixed.h"
#include "../base/sparse.h"
#include "sbc/keywords.h"
#include "base/words.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

sbc_settings sbc_settings_default(void)
{
    sbc_settings s;
    memset(&s, 0, sizeof s);
    s.bc = SBC_BC_D;
    s.dim = 2;
    sbc_tensor_identity(s.dim, s.F);
    s.increments = 1;
    s.max_relax_steps = 10000000L;
    s.damping = SBC_DAMPING_LOCAL;
    s.alpha = s.beta = 0.7;
    s.gain_force = 1.0e2;
    s.gain_moment = 2.0e2;
    s.gain_deformation = 2.0e-5;
    s.tol_force = 1.0e-6;
    s.tol_moment = 1.0e-6;
    s.predict = 0.0;
    s.max_iterations = 100000;
    sbc_mixed_default(&s);
    sbc_settings_preset(&s, "balanced");
    return s;
}

/* The presets (docs/servo_bc.md, Accuracy). paper: Table 4 as printed, the
 * Ek/Ep criterion of eq. 11, fixed gains, the frame moved in one step. The
 * others: force balance (relax.h) to tol_balance, frame residuals relative
 * to the frame's own forces below tol_relative, the secant update, and the
 * frame moved at `speed` radii per critical step, FIRE on the interior
 * instead of eq. 10 (fire_damping.h; fewer DEM steps on every case of
 * docs/speed-accuracy.md), and remap x (the interior follows the affine
 * part of the frame's move: steps per increment that do not grow with a
 * lattice, docs/servo_bc.md "Remap"); each guarantees the
 * relative stress error `accuracy` at a converged increment, measured on
 * the closed-form lattices and the sweep cases (docs/servo_bc.md). */
typedef struct preset {
    const char *name;
    double accuracy;
    sbc_criterion criterion;
    double tol; /* tol_balance or tol_E */
    int window;
    double tol_relative, tol_deformation, speed;
    sbc_update update;
    sbc_damping damping;
    int remap;
} preset;

static const preset presets[] = {
    {"paper", 0.0, SBC_CRITERION_ENERGY, 1.0e-3, 20, 0.0, 1.0e-2, 0.0, SBC_UPDATE_FIXED, SBC_DAMPING_LOCAL, 0},
    {"fast", 1.0e-2, SBC_CRITERION_FORCE, 1.0e-3, 20, 1.0e-2, 1.0e-2, 0.1, SBC_UPDATE_SECANT, SBC_DAMPING_FIRE, 1},
    {"balanced", 1.0e-4, SBC_CRITERION_FORCE, 1.0e-5, 20, 1.0e-4, 1.0e-2, 0.01, SBC_UPDATE_SECANT, SBC_DAMPING_FIRE, 1},
    {"tight", 1.0e-6, SBC_CRITERION_FORCE, 1.0e-8, 20, 1.0e-7, 1.0e-2, 0.001, SBC_UPDATE_SECANT, SBC_DAMPING_FIRE, 1},
};

static const preset *find_preset(const char *name)
{
    size_t k;
    for (k = 0; k < sizeof presets / sizeof presets[0]; ++k)
        if (strcmp(name, presets[k].name) == 0)
            return &presets[k];
    return NULL;
}

double sbc_settings_preset_accuracy(const char *name)
{
    const preset *p = find_preset(name);
    return p ? p->accuracy : -1.0;
}

int sbc_settings_preset(sbc_settings *s, const char *name)
{
    const preset *p = find_preset(name);
    if (!p)
        return 0;
    s->criterion = p->criterion;
    if (p->criterion == SBC_CRITERION_FORCE) {
        s->tol_balance = p->tol;
        s->tol_E = 1.0e-3; /* Table 4; read only by the energy criterion */
    } else {
        s->tol_E = p->tol;
        s->tol_balance = 0.0;
    }
    s->window = p->window;
    s->gain_force = 1.0e2; /* Table 4 */
    s->gain_moment = 2.0e2;
    s->gain_deformation = 2.0e-5;
    s->tol_force = 1.0e-6;
    s->tol_moment = 1.0e-6;
    s->tol_deformation = p->tol_deformation;
    s->tol_relative = p->tol_relative;
    s->update = p->update;
    s->speed = p->speed;
    s->damping = p->damping;
    s->remap = p->remap;
    s->alpha = s->beta = 0.7; /* eq. 10: the interior under `paper`, free frame rotations under every preset */
    snprintf(s->accuracy, sizeof s->accuracy, "%s", p->name);
    return 1;
}

const char *sbc_bc_name(sbc_bc bc)
{
    static const char *names[] = {"D", "P", "T", "mixed"};
    return (bc >= SBC_BC_D && bc <= SBC_BC_MIXED) ? names[bc] : "?";
}

/* Smallest det(I + t A), A = F - I, for t in [0, 1]: the polynomial
 * 1 + t c1 + t^2 c2 + t^3 c3 with c1 = tr A, c2 the sum of A's principal
 * 2 x 2 minors and c3 = det A (0 in 2D, where c2 = det A), at t = 1 and
 * where its derivative c1 + 2 c2 t + 3 c3 t^2 vanishes. */
static double path_det_min(int dim, const double F[9], double *t_min)
{
    double A[9], c1 = 0.0, c2 = 0.0, c3 = 0.0, best = 1.0, tb = 0.0, cand[3] = {1.0, -1.0, -1.0};
    int k, i, j;
    for (k = 0; k < 9; ++k)
        A[k] = F[k] - (k % 4 == 0 ? 1.0 : 0.0);
    for (i = 0; i < dim; ++i)
        c1 += A[SBC_IJ(i, i)];
    for (i = 0; i < dim; ++i)
        for (j = i + 1; j < dim; ++j)
            c2 += A[SBC_IJ(i, i)] * A[SBC_IJ(j, j)] - A[SBC_IJ(i, j)] * A[SBC_IJ(j, i)];
    if (dim == 3) {
        double disc;
        c3 = sbc_tensor_det(3, A);
        disc = 4.0 * c2 * c2 - 12.0 * c3 * c1;
        if (c3 != 0.0 && disc >= 0.0) {
            cand[1] = (-2.0 * c2 + sqrt(disc)) / (6.0 * c3);
            cand[2] = (-2.0 * c2 - sqrt(disc)) / (6.0 * c3);
        } else if (c3 == 0.0 && c2 > 0.0) {
            cand[1] = -c1 / (2.0 * c2);
        }
    } else if (c2 > 0.0) {
        cand[1] = -c1 / (2.0 * c2);
    }
    for (k = 0; k < 3; ++k) {
        double t = cand[k], J;
        if (t < 0.0 || t > 1.0)
            continue;
        J = 1.0 + t * c1 + t * t * c2 + t * t * t * c3;
        if (J < best) {
            best = J;
            tb = t;
        }
    }
    *t_min = tb;
    return best;
}

typedef struct cursor {
    int n, i;
    const char *const *w;
    const char *key;
    sbc_error *err;
} cursor;

static const char *next_word(cursor *c, const char *what, sbc_status *st)
{
    if (c->i >= c->n) {
        *st = sbc_fail(c->err, SBC_ERR_INPUT, "keyword '%s': missing %s", c->key, what);
        return NULL;
    }
    return c->w[c->i++];
}

/* Reads a real for keyword c->key with lo < v (strict when lo_open) and v <= hi. */
/* 1 when strtod reads the whole word (a number, inf or nan) */
static int number_like(const char *w)
{
    char *end;
    (void)strtod(w, &end);
    return end != w && *end == '\0';
}

static sbc_status read_real(cursor *c, const char *what, double lo, int lo_open, double hi, const char *expect,
                            double *out)
{
    sbc_status st = SBC_OK;
    const char *w = next_word(c, what, &st);
    double v;
    if (!w)
        return st;
    if (sbc_parse_real(w, what, &v, NULL) != SBC_OK || (lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi))
        return sbc_fail(c->err, SBC_ERR_INPUT, "keyword '%s': %s '%s' is not valid (expected %s)", c->key, what, w,
                        expect);
    *out = v;
    return SBC_OK;
}

static sbc_status read_int(cursor *c, const char *what, long lo, long hi, long *out)
{
    sbc_status st = SBC_OK;
    const char *w = next_word(c, what, &st);
    if (!w)
        return st;
    if (sbc_parse_int(w, what, lo, hi, out, NULL) != SBC_OK)
        return sbc_fail(c->err, SBC_ERR_INPUT, "keyword '%s': %s '%s' is not valid (expected an integer from %ld to %ld)",
                        c->key, what, w, lo, hi);
    return SBC_OK;
}

static sbc_status read_name(cursor *c, const char *what, char *dst)
{
    sbc_status st = SBC_OK;
    const char *w = next_word(c, what, &st);
    if (!w)
        return st;
    if (strlen(w) >= SBC_NAME_LEN)
        return sbc_fail(c->err, SBC_ERR_INPUT, "keyword '%s': %s is longer than %d characters", c->key, what,
                        SBC_NAME_LEN - 1);
    strcpy(dst, w);
    return SBC_OK;
}

const char *sbc_tangent_name(sbc_tangent t)
{
    static const char *const names[] = {"none", "affine", "condensed", "perturbation"};
    return t >= SBC_TANGENT_NONE && t <= SBC_TANGENT_PERTURBATION ? names[t] : "unknown";
}

static const char *const gain_keys[] = {"gain_force", "gain_moment", "gain_deformation"};
static const char *const tol_keys[] = {"tol_force", "tol_moment", "tol_deformation"};

/* The keywords one pass met (at keyword places, never a value that spells
 * a keyword), and the preset it read. */
typedef struct met {
    const char *keys[64];
    int n;
    char accuracy[16];
} met;

static int was_met(const met *m, const char *key)
{
    int k;
    for (k = 0; k < m->n; ++k)
        if (strcmp(m->keys[k], key) == 0)
            return 1;
    return 0;
}

/* One pass over the keywords into *s, which holds the defaults (and, in the
 * second pass, the preset). first: the pass that validates `accuracy` and
 * records it in *m instead of applying it. */
static sbc_status parse_pass(sbc_settings *s, int nwords, const char *const *words, int first, met *m,
                             sbc_error *err)
{
    cursor c;
    sbc_status st = SBC_OK;
    long iv;
    int k;
    m->n = 0;
    c.n = nwords;
    c.i = 1;
    c.w = words;
    c.err = err;
    while (c.i < c.n && st == SBC_OK) {
        const char *key = c.w[c.i++];
        c.key = key;
        /* every keyword once, but stress (one per component; its parser refuses a repeated component) */
        if (strcmp(key, "stress") != 0 && was_met(m, key))
            return sbc_fail(err, SBC_ERR_INPUT, "keyword '%s' given twice (each keyword once per servo_bc line)", key);
        if (m->n < (int)(sizeof m->keys / sizeof m->keys[0]))
            m->keys[m->n++] = key;
        if (strcmp(key, "accuracy") == 0) {
            const char *name = next_word(&c, "preset", &st);
            if (name && sbc_settings_preset_accuracy(name) < 0.0)
                st = sbc_fail(err, SBC_ERR_INPUT,
                              "keyword 'accuracy': preset '%s' is not valid (expected fast, balanced, paper or tight)",
                              name);
            else if (name && first)
                snprintf(m->accuracy, sizeof m->accuracy, "%s", name);
        } else if (strcmp(key, "F") == 0) {
            /* nine numbers give a 3D F, row-major; otherwise the 2D one's four
               (sbc_settings_check_dimension holds them to the host's packing). A word strtod reads whole counts
               (inf and nan too: read_real then names the component that holds it) */
            int numbers = 0, d;
            while (numbers < 10 && c.i + numbers < c.n && number_like(c.w[c.i + numbers]))
                ++numbers;
            if (numbers > 4 && numbers != 9)
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'F': %d values (expected 4 for a 2D F or 9 for a 3D F, "
                              "row-major)", numbers);
            d = s->dim = numbers == 9 ? 3 : 2;
            sbc_tensor_identity(d, s->F);
            for (k = 0; k < d * d && st == SBC_OK; ++k) {
                char name[8];
                double *Fij = &s->F[SBC_IJ(k / d, k % d)];
                sbc_tensor_component_name("F", k / d, k % d, name);
                st = read_real(&c, name, -HUGE_VAL, 0, HUGE_VAL, "a real number", Fij);
                /* a frame stretched a hundredfold is no DEM sample; beyond, det F overflows */
                if (st == SBC_OK && !(fabs(*Fij) <= 100.0))
                    st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'F': %s %g is out of range (expected |Fij| <= 100)",
                                  name, *Fij);
            }
            if (st == SBC_OK && !(sbc_tensor_det(d, s->F) > 0.0))
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'F': det F = %g is not positive (expected det F > 0)",
                              sbc_tensor_det(d, s->F));
            if (st == SBC_OK) {
                double t = 0.0, J = path_det_min(d, s->F, &t);
                if (!(J > 0.0))
                    st = sbc_fail(err, SBC_ERR_INPUT,
                                  "keyword 'F': det F reaches %g at %.3g of the linear path from I (expected det F > 0 "
                                  "on the whole path; apply the deformation in stages)",
                                  J, t);
            }
        } else if (strcmp(key, "increments") == 0) {
            st = read_int(&c, "N", 1, 100000000L, &iv);
            s->increments = (int)iv;
        } else if (strcmp(key, "relax") == 0 || strcmp(key, "balance") == 0) {
            const int energy = key[0] == 'r';
            s->criterion = energy ? SBC_CRITERION_ENERGY : SBC_CRITERION_FORCE;
            st = read_real(&c, energy ? "tolE" : "tol", 0.0, 1, energy ? HUGE_VAL : 1.0,
                           energy ? "a real > 0" : "a real in (0, 1]", energy ? &s->tol_E : &s->tol_balance);
            if (st == SBC_OK)
                st = read_int(&c, "window", 1, 1000000000L, &iv);
            if (st == SBC_OK)
                s->window = (int)iv;
        } else if (strcmp(key, "speed") == 0) {
            st = read_real(&c, "v", 0.0, 0, 1.0e6, "a real >= 0, radii per critical time step (0: in one step)",
                           &s->speed);
        } else if (strcmp(key, "max_relax_steps") == 0) {
            st = read_int(&c, "steps", 1, 2000000000L, &s->max_relax_steps);
        } else if (strcmp(key, "damping") == 0) {
            if (c.i < c.n && strcmp(c.w[c.i], "none") == 0) {
                ++c.i;
                s->damping = SBC_DAMPING_NONE;
                s->alpha = s->beta = 0.0;
            } else if (c.i < c.n && strcmp(c.w[c.i], "fire") == 0) {
                ++c.i; /* the interior; free frame rotations (T) keep eq. 10 at alpha, beta */
                s->damping = SBC_DAMPING_FIRE;
            } else {
                s->damping = SBC_DAMPING_LOCAL;
                st = read_real(&c, "alpha", 0.0, 0, 1.0, "a real in [0, 1), 'none' or 'fire'", &s->alpha);
                if (st == SBC_OK)
                    st = read_real(&c, "beta", 0.0, 0, 1.0, "a real in [0, 1)", &s->beta);
                if (st == SBC_OK && (s->alpha >= 1.0 || s->beta >= 1.0))
                    st = sbc_fail(err, SBC_ERR_INPUT,
                                  "keyword 'damping': values %g %g must be below 1 (damping 1 cancels every force)",
                                  s->alpha, s->beta);
            }
        } else if (strcmp(key, "predict") == 0) {
            st = read_real(&c, "n_f", 0.0, 0, 1.0, "an inheritance factor in [0, 1]", &s->predict);
        } else if (strcmp(key, "tol_relative") == 0) {
            st = read_real(&c, "eps", 0.0, 0, HUGE_VAL, "a real >= 0 (0: the tolerances of eq. 37)", &s->tol_relative);
        } else if (strcmp(key, "update") == 0) {
            const char *w = next_word(&c, "mode", &st);
            const sbc_update_rule *rule = w ? sbc_update_rule_named(w) : NULL;
            if (rule && rule->id == SBC_UPDATE_NEWTON && s->bc == SBC_BC_MIXED) {
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'update': newton takes (P) and (T); mixed conditions "
                              "take fixed or secant");
            } else if (rule) {
                s->update = rule->id;
            } else if (w) {
                char names[64];
                sbc_update_rule_names(names, sizeof names);
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'update': mode '%s' is not valid (expected %s)", w, names);
            }
        } else if (strcmp(key, "seal") == 0) {
            const char *w = next_word(&c, "yes|no", &st);
            if (w && (strcmp(w, "yes") == 0 || strcmp(w, "no") == 0))
                s->seal = strcmp(w, "yes") == 0;
            else if (w)
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'seal': value '%s' is not valid (expected yes or no)", w);
        } else if (strcmp(key, "rotation") == 0) {
            const char *w = next_word(&c, "free|zero", &st);
            if (w && strcmp(w, "free") != 0 && strcmp(w, "zero") != 0)
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'rotation': value '%s' is not valid (expected free or zero)",
                              w);
            else if (w && s->bc != SBC_BC_T)
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'rotation': applies to T (D holds the frame's rotations "
                              "at zero, P shares them between images, mixed frames keep the paper's free rotation)");
            else if (w)
                s->rotation_zero = strcmp(w, "zero") == 0;
        } else if (strcmp(key, "remap") == 0) {
            const char *w = next_word(&c, "x|none", &st);
            if (w && (strcmp(w, "x") == 0 || strcmp(w, "none") == 0))
                s->remap = strcmp(w, "x") == 0;
            else if (w)
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'remap': value '%s' is not valid (expected x or none)", w);
        } else if (strcmp(key, "interior") == 0) {
            const char *w = next_word(&c, "dynamic|newton", &st);
            if (w && strcmp(w, "newton") == 0 && !sbc_sparse_available())
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'interior': newton needs the sparse direct solver (UMFPACK), "
                              "which this build of the core was made without (SPARSE=no, or libsuitesparse-dev "
                              "missing: scripts/install-deps.sh core, then make again); expected dynamic");
            else if (w && (strcmp(w, "dynamic") == 0 || strcmp(w, "newton") == 0))
                s->interior = strcmp(w, "newton") == 0 ? SBC_INTERIOR_NEWTON : SBC_INTERIOR_DYNAMIC;
            else if (w)
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'interior': value '%s' is not valid (expected dynamic or "
                              "newton)", w);
        } else if (strcmp(key, "max_iterations") == 0) {
            st = read_int(&c, "K", 1, 1000000000L, &iv);
            s->max_iterations = (int)iv;
        } else if (strcmp(key, "frame") == 0) {
            st = read_name(&c, "group-ID", s->frame_group);
        } else if (strcmp(key, "file") == 0) {
            st = read_name(&c, "path", s->file);
        } else if (strcmp(key, "tangent") == 0) {
            const char *w = next_word(&c, "affine|condensed|perturbation", &st);
            int t;
            for (t = SBC_TANGENT_AFFINE; w && t <= SBC_TANGENT_PERTURBATION; ++t)
                if (strcmp(w, sbc_tangent_name((sbc_tangent)t)) == 0)
                    break;
            if (w && t > SBC_TANGENT_PERTURBATION)
                st = sbc_fail(err, SBC_ERR_INPUT,
                              "keyword 'tangent': kind '%s' is not valid (expected affine, condensed or perturbation)", w);
            else if (w) {
                s->tangent = (sbc_tangent)t;
                st = read_name(&c, "path", s->tangent_file);
            }
        } else if (strcmp(key, "stress") == 0 || sbc_mixed_face_index(key) >= 0) {
            k = 0;
            if (s->bc != SBC_BC_MIXED)
                st = sbc_fail(err, SBC_ERR_INPUT, "keyword '%s' needs boundary condition mixed (got %s)", key,
                              sbc_bc_name(s->bc));
            else if (strcmp(key, "stress") == 0)
                st = sbc_mixed_parse_stress(s, c.n - c.i, c.w + c.i, &k, err);
            else
                st = sbc_mixed_parse_face(s, key, c.n - c.i, c.w + c.i, &k, err);
            c.i += k;
        } else {
            double *gain[3] = {&s->gain_force, &s->gain_moment, &s->gain_deformation};
            double *tol[3] = {&s->tol_force, &s->tol_moment, &s->tol_deformation};
            int found = 0;
            for (k = 0; k < 3 && !found; ++k) {
                if (strcmp(key, gain_keys[k]) == 0) {
                    st = read_real(&c, "g", 0.0, 1, HUGE_VAL, "a real > 0", gain[k]);
                    found = 1;
                } else if (strcmp(key, tol_keys[k]) == 0) {
                    st = read_real(&c, "eps", 0.0, 1, HUGE_VAL, "a real > 0", tol[k]);
                    found = 1;
                }
            }
            if (!found) {
                char list[512];
                sbc_keywords_list(list, sizeof list);
                st = sbc_fail(err, SBC_ERR_INPUT, "unknown keyword '%s' (expected %s)", key, list);
            }
        }
    }
    /* absolute tolerances given without tol_relative are meant absolute */
    if (st == SBC_OK && !was_met(m, "tol_relative") && (was_met(m, "tol_force") || was_met(m, "tol_moment")))
        s->tol_relative = 0.0;
    if (st == SBC_OK && was_met(m, "relax") && was_met(m, "balance"))
        st = sbc_fail(err, SBC_ERR_INPUT, "keywords 'relax' and 'balance' both choose when a relaxation is over "
                      "(Ek/Ep, or the force balance); give one");
    /* interior newton: the interior is solved at the frame's commands, so the frame jumps to them and the
       interior is not carried along by the frame's move */
    if (st == SBC_OK && s->interior == SBC_INTERIOR_NEWTON) {
        if (was_met(m, "remap") && s->remap)
            st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'remap': x moves the interior with the frame's travel, which "
                          "interior newton solves instead (expected remap none, or interior dynamic)");
        else if (was_met(m, "speed") && s->speed > 0.0)
            st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'speed': %g; under interior newton the frame jumps to its "
                          "commands and the interior is solved there (expected speed 0, or interior dynamic)",
                          s->speed);
        else if (s->seal)
            st = sbc_fail(err, SBC_ERR_INPUT, "keyword 'seal': yes puts walls between the frame's particles, which "
                          "interior newton's static solve does not hold (expected seal no, or interior dynamic)");
        s->remap = 0;
        s->speed = 0.0;
    }
    /* (D) puts the frame where F X says: the servo's words have nothing to act on */
    s->ignored[0] = '\0';
    if (st == SBC_OK && s->bc == SBC_BC_D) {
        static const char *const servo_keys[] = {"gain_force", "gain_moment", "gain_deformation", "tol_force",
                                                 "tol_moment", "tol_deformation", "tol_relative", "predict",
                                                 "update", "max_iterations"};
        size_t k2, used = 0;
        for (k2 = 0; k2 < sizeof servo_keys / sizeof servo_keys[0]; ++k2)
            if (was_met(m, servo_keys[k2]))
                used += (size_t)snprintf(s->ignored + used, used < sizeof s->ignored ? sizeof s->ignored - used : 0,
                                         "%s%s", used ? " " : "", servo_keys[k2]);
    }
    if (st == SBC_OK && s->bc == SBC_BC_MIXED)
        st = sbc_mixed_validate(s, err);
    return st;
}

sbc_status sbc_settings_parse(sbc_settings *s, int nwords, const char *const *words, sbc_error *err)
{
    met m;
    sbc_status st;
    sbc_bc bc;
    *s = sbc_settings_default();
    if (nwords < 1)
        return sbc_fail(err, SBC_ERR_INPUT, "missing boundary condition (expected D, P, T or mixed)");
    if (strcmp(words[0], "D") == 0)
        bc = SBC_BC_D;
    else if (strcmp(words[0], "P") == 0)
        bc = SBC_BC_P;
    else if (strcmp(words[0], "T") == 0)
        bc = SBC_BC_T;
    else if (strcmp(words[0], "mixed") == 0)
        bc = SBC_BC_MIXED;
    else
        return sbc_fail(err, SBC_ERR_INPUT, "unknown boundary condition '%s' (expected D, P, T or mixed)", words[0]);
    s->bc = bc;
    m.accuracy[0] = '\0';
    /* the first pass finds every error in the order of the words, and the preset */
    if ((st = parse_pass(s, nwords, words, 1, &m, err)) != SBC_OK || !m.accuracy[0])
        return st;
    /* a preset: applied first, so that the keywords given with it win wherever they stand */
    *s = sbc_settings_default();
    s->bc = bc;
    sbc_settings_preset(s, m.accuracy);
    return parse_pass(s, nwords, words, 0, &m, err);
}

sbc_status sbc_settings_check_dimension(sbc_settings *s, int dim, sbc_error *err)
{
    const double *F = s->F;
    if (dim != 2 && dim != 3)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: a packing of dimension %d (expected 2 or 3)", dim);
    if (s->dim == 2 && dim == 3 && F[0] == 1.0 && F[1] == 0.0 && F[3] == 0.0 && F[4] == 1.0 && s->nstress == 0 &&
        s->bc != SBC_BC_MIXED) { /* no deformation (no F, or the 2D identity) means none in 3D */
        s->dim = 3;
        sbc_tensor_identity(3, s->F);
    }
    if (s->dim == dim)
        return SBC_OK;
    if (dim == 3 && s->bc == SBC_BC_MIXED)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc mixed: the packing is 3D but the words are 2D: give F with nine "
                        "values (F11 F12 F13 F21 F22 F23 F31 F32 F33, row-major; the identity for a stress stage "
                        "alone)");
    if (s->dim == 3)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'F': 9 values give a 3D F, but the packing is 2D (expected 4 "
                        "values, F11 F12 F21 F22)");
    return sbc_fail(err, SBC_ERR_INPUT, "keyword 'F': 4 values give a 2D F, but the packing is 3D (expected 9 values, "
                    "F11 F12 F13 F21 F22 F23 F31 F32 F33, row-major)");
}

int sbc_settings_ignored_message(const sbc_settings *s, char *out, size_t cap)
{
    if (!s->ignored[0])
        return 0;
    snprintf(out, cap, "servo_bc D: the keywords %s have no effect: they set the servo-control of P, T and mixed, and "
             "D puts the frame at F X directly (docs/servo_bc.md)", s->ignored);
    return 1;
}

void sbc_settings_target_F(const sbc_settings *s, int increment, double F[9])
{
    /* mixed: F stays I during the stress stage, then ramps over `increments` */
    int stage = s->bc == SBC_BC_MIXED ? s->stress_increments : 0;
    double t = increment <= stage ? 0.0 : (double)(increment - stage) / (double)s->increments, I[9];
    int k;
    sbc_tensor_identity(s->dim, I);
    for (k = 0; k < 9; ++k)
        F[k] = I[k] + t * (s->F[k] - I[k]);
}

int sbc_settings_total_increments(const sbc_settings *s)
{
    return s->increments + (s->bc == SBC_BC_MIXED ? s->stress_increments : 0);
}

sbc_status sbc_settings_parse_words(sbc_settings *s, const char *words, sbc_error *err)
{
    const size_t len = words ? strlen(words) : 0;
    char *line = malloc(len + 1), **w;
    sbc_status st;
    int nw;
    if (!line)
        return sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory");
    memcpy(line, words ? words : "", len + 1);
    nw = sbc_split_words(line, NULL, 0);
    memcpy(line, words ? words : "", len + 1);
    if (!(w = malloc(sizeof *w * (size_t)(nw > 0 ? nw : 1)))) {
        free(line);
        return sbc_fail(err, SBC_ERR_NOMEM, "servo_bc: out of memory");
    }
    sbc_split_words(line, w, nw);
    st = sbc_settings_parse(s, nw, (const char *const *)w, err);
    free(w);
    free(line);
    return st;
}

sbc_status sbc_settings_check_host(const sbc_settings *s, sbc_error *err)
{
    if (s->tangent != SBC_TANGENT_NONE)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: keyword 'tangent' (%s %s) is the embedded runner's: its "
                        "perturbations rerun the aggregate from saved states and its condensed tangent reads the "
                        "engine's contacts; run the case with servo-bc, or take the tangent from the material point "
                        "(docs/fe2.md)", sbc_tangent_name(s->tangent), s->tangent_file);
    return SBC_OK;
}
