#define _POSIX_C_SOURCE 200809L
/* (P) and (T) servo control (Sect. 3.2): converged states checked against
 * eqs. 20, 21, 15 and 30 from the final snapshot, independently of the
 * controller's own norms; closed form; prediction; divergence. */
#include "check.h"
#include "csv_read.h"
#include "tests.h"

#include "sbc/controller.h"
#include "sbc/embedded/engine.h"
#include "sbc/embedded/generate.h"
#include "sbc/homogenize.h"
#include "sbc/packing.h"
#include "sbc/embedded/script.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct final_state {
    sbc_frame frame;
    double *x, *a, *m, *mass; /* frame-ordered copies of the last snapshot */
    double F[9];              /* imposed at the last increment */
    sbc_result result;
    sbc_status status;
    char message[SBC_ERROR_LEN];
} final_state;

/* Runs the packing p (kn 1e4, ks, mu 0.4, density 2e3, dt 1e-5) with the
 * given servo_bc words to the end; p is freed. A host that misreports: with
 * misreport > 0 the snapshot's frame positions are off those of the engine
 * by misreport radii, +/- alternately along the frame (a non-affine
 * pattern). */
static void run_packing(sbc_packing p, const char *words, double ks, double misreport, final_state *out)
{
    char buf[512], *w[64];
    int nw = 0, q;
    sbc_settings s;
    sbc_error err;
    sbc_engine_def def = sbc_engine_def_default();
    sbc_engine *e;
    sbc_controller *c;
    sbc_snapshot snap;
    memset(out, 0, sizeof *out);
    snprintf(buf, sizeof buf, "%s", words);
    for (w[nw] = strtok(buf, " "); w[nw]; w[++nw] = strtok(NULL, " "))
        ;
    out->status = sbc_settings_parse(&s, nw, (const char *const *)w, &err);
    CHECK(out->status == SBC_OK);
    sbc_frame_detect_packing(&out->frame, &p, &err);
    def.n = p.n;
    def.x = p.x;
    def.r = p.r;
    def.dt = 1e-5;
    def.law.ks = ks;
    e = sbc_engine_create(&def, &err);
    sbc_engine_set_frame(e, &out->frame);
    out->mass = malloc(sizeof(double) * (size_t)out->frame.n);
    sbc_engine_frame_masses(e, out->mass);
    c = sbc_controller_create(&out->frame, &s, out->mass, def.dt, def.law.kn, &err);
    out->status = SBC_ERR_INPUT;
    if (!c) { /* refused before the run: the status and message of the refusal */
        out->status = err.status;
        snprintf(out->message, sizeof out->message, "%s", err.message);
    }
    CHECK(c != NULL || (out->status == SBC_ERR_INPUT && out->message[0]));
    double *reported = malloc(sizeof(double) * 3 * (size_t)out->frame.n);
    for (; c;) {
        sbc_event ev;
        sbc_commands cmd;
        sbc_engine_step(e, &err);
        sbc_engine_snapshot(e, &snap);
        if (misreport > 0.0) {
            for (q = 0; q < out->frame.n; ++q) {
                const double d = (q % 2 ? misreport : -misreport) * out->frame.R[q];
                reported[3 * q] = snap.x[3 * q] + d;
                reported[3 * q + 1] = snap.x[3 * q + 1] - d;
                reported[3 * q + 2] = 0.0;
            }
            snap.x = reported;
        }
        ev = sbc_controller_step(c, &snap, &err);
        if (ev == SBC_EVENT_FAILED) {
            out->status = err.status;
            snprintf(out->message, sizeof out->message, "%s", err.message);
            break;
        }
        if (ev == SBC_EVENT_FINISHED) {
            int nq = out->frame.n;
            out->status = SBC_OK;
            out->result = *sbc_controller_result(c);
            sbc_controller_target_F(c, s.increments, out->F);
            out->x = malloc(sizeof(double) * 3 * (size_t)nq);
            out->a = malloc(sizeof(double) * 3 * (size_t)nq);
            out->m = malloc(sizeof(double) * (size_t)nq);
            for (q = 0; q < nq; ++q) {
                out->x[3 * q] = snap.x[3 * q];
                out->x[3 * q + 2] = out->a[3 * q + 2] = 0.0;
                out->x[3 * q + 1] = snap.x[3 * q + 1];
                out->a[3 * q] = -snap.force[3 * q]; /* eq. 5 */
                out->a[3 * q + 1] = -snap.force[3 * q + 1];
                out->m[q] = -snap.torque[q];
            }
            break;
        }
        cmd = sbc_controller_commands(c);
        sbc_engine_move_frame(e, &cmd);
    }
    free(reported);
    sbc_controller_free(c);
    sbc_engine_free(e);
    sbc_packing_free(&p);
}

/* the 5 x 5 lattice: spacing 2 mm, R 1.02 mm */
static void run_lattice(const char *words, double ks, final_state *out)
{
    sbc_packing p;
    sbc_error err;
    CHECK(sbc_packing_lattice_square(&p, 5, 5, 2e-3, 1.02e-3, &err) == SBC_OK);
    run_packing(p, words, ks, 0.0, out);
}

static void final_free(final_state *f)
{
    sbc_frame_free(&f->frame);
    free(f->x);
    free(f->a);
    free(f->m);
    free(f->mass);
}

/* The run converged and the servo had work to do; otherwise reports and frees. */
static int converged_with_work(final_state *f)
{
    CHECK(f->status == SBC_OK);
    if (f->status != SBC_OK) {
        printf("  %s\n", f->message);
        final_free(f);
        return 0;
    }
    CHECK(f->result.iterations > 1);
    return 1;
}

/* Hill-Mandel residual of eq. 30 from the final state, relative to the work scale */
static double hill_mandel(const final_state *f)
{
    double F[9], P[9];
    sbc_homogenize_F(&f->frame, f->x, F);
    sbc_homogenize_P(&f->frame, f->a, P);
    return fabs(sbc_homogenize_hill_mandel(&f->frame, f->a, f->x, F, P)) / sbc_homogenize_work_scale(2, P, F);
}

/* (P) on the frictionless lattice with a diagonal F: the affine state is
 * periodic with anti-periodic forces, so (P) gives the closed form of (D)
 * (see test_lattice.c) to 1e-9. */
static void periodic_closed_form(void)
{
    const double N = 5, kn = 1e4, d = 2e-3, R = 1.02e-3, F11 = 1.002, F22 = 0.997;
    final_state f;
    run_lattice("P F 1.002 0 0 0.997 increments 1 relax 1e-22 20 tol_force 1e-14 tol_moment 1e-14 gain_force 1e3 "
                "gain_moment 1e3", 0.0, &f);
    CHECK(f.status == SBC_OK);
    CHECK_REL(f.result.P[0], -N * kn * (2 * R - d * F11) / ((N - 1) * d), 1e-9);
    CHECK_REL(f.result.P[4], -N * kn * (2 * R - d * F22) / ((N - 1) * d), 1e-9);
    CHECK_ABS(f.result.P[1], 0.0, 1e-9 * fabs(f.result.P[0]));
    CHECK_ABS(f.result.P[3], 0.0, 1e-9 * fabs(f.result.P[0]));
    final_free(&f);
}

/* (P) converged: a+ + a- = 0 and m+ + m- = 0 on every pair within the
 * tolerance of eq. 37's normalization; eq. 19 exactly; Hill-Mandel. With
 * `update` fixed or secant; returns the iterations of the last increment. */
static int periodic_state(const char *update)
{
    const double tol = 1e-12, dt = 1e-5;
    final_state f;
    char words[512];
    int q, ok_f = 1, ok_m = 1, ok_x = 1, iterations;
    snprintf(words, sizeof words, "P F 0.995 -0.01 -0.01 0.995 increments 2 relax 1e-14 20 tol_force 1e-12 "
             "tol_moment 1e-12 gain_force 1e3 gain_moment 1e3 update %s", update);
    run_lattice(words, 2e3, &f);
    if (!converged_with_work(&f))
        return 0;
    iterations = f.result.iterations;
    for (q = 0; q < f.frame.n; ++q) {
        int p = f.frame.partner[q];
        double at, mt, dx[2], DX[2];
        if (f.frame.side[q] != SBC_SIDE_BOTTOM && f.frame.side[q] != SBC_SIDE_RIGHT)
            continue;
        at = f.mass[q] * f.frame.R[q] / (dt * dt);
        mt = at * f.frame.R[q];
        ok_f &= hypot(f.a[3 * q] + f.a[3 * p], f.a[3 * q + 1] + f.a[3 * p + 1]) <= tol * at;
        ok_m &= fabs(f.m[q] + f.m[p]) <= tol * mt;
        /* eq. 19: x+ - x- = F (X+ - X-) */
        dx[0] = f.x[3 * q] - f.x[3 * p];
        dx[1] = f.x[3 * q + 1] - f.x[3 * p + 1];
        DX[0] = f.frame.X[3 * q] - f.frame.X[3 * p];
        DX[1] = f.frame.X[3 * q + 1] - f.frame.X[3 * p + 1];
        ok_x &= fabs(dx[0] - (f.F[0] * DX[0] + f.F[1] * DX[1])) < 1e-15 &&
                fabs(dx[1] - (f.F[3] * DX[0] + f.F[4] * DX[1])) < 1e-15;
    }
    CHECK(ok_f);
    CHECK(ok_m);
    CHECK(ok_x);
    CHECK(hill_mandel(&f) <= 1e-8);
    final_free(&f);
    return iterations;
}

/* (T) converged: a_q = P A_q on every frame particle within the force
 * tolerance (eq. 21), F of eq. 15 equals the imposed F within eps_F, and the
 * Hill-Mandel residual vanishes. */
static int traction_state(const char *update)
{
    const double tol = 1e-12, epsF = 1e-6, dt = 1e-5;
    final_state f;
    double P[9], F[9];
    char words[512];
    int q, ok = 1, k, iterations;
    snprintf(words, sizeof words, "T F 0.995 -0.01 -0.01 0.995 increments 2 relax 1e-14 20 tol_force 1e-12 "
             "tol_deformation 1e-6 gain_force 1e3 gain_deformation 1e-2 update %s", update);
    run_lattice(words, 2e3, &f);
    if (!converged_with_work(&f))
        return 0;
    iterations = f.result.iterations;
    sbc_homogenize_P(&f.frame, f.a, P);
    sbc_homogenize_F(&f.frame, f.x, F);
    for (q = 0; q < f.frame.n; ++q) {
        const double *A = &f.frame.A[3 * q];
        double at = f.mass[q] * f.frame.R[q] / (dt * dt);
        ok &= hypot(f.a[3 * q] - (P[0] * A[0] + P[1] * A[1]), f.a[3 * q + 1] - (P[3] * A[0] + P[4] * A[1])) <=
              tol * at;
    }
    CHECK(ok);
    for (k = 0; k < 9; ++k)
        CHECK_ABS(F[k], f.F[k], epsF);
    CHECK(hill_mandel(&f) <= 1e-8);
    /* and it is not the (D) state: the frame moved off F X */
    {
        double off = 0.0;
        for (q = 0; q < f.frame.n; ++q) {
            const double *X = &f.frame.X[3 * q];
            off = fmax(off, fabs(f.x[3 * q] - (f.F[0] * X[0] + f.F[1] * X[1])));
        }
        CHECK(off > 1e-8);
    }
    final_free(&f);
    return iterations;
}

/* update secant (issue 9) reaches the same converged states as the paper's
 * fixed gains, in fewer iterations. */
static void secant_update(void)
{
    int fixed = periodic_state("fixed"), secant = periodic_state("secant");
    printf("  (P) iterations of increment 2: fixed %d, secant %d\n", fixed, secant);
    CHECK(secant > 0 && 3 * secant <= fixed);
    fixed = traction_state("fixed");
    secant = traction_state("secant");
    printf("  (T) iterations of increment 2: fixed %d, secant %d\n", fixed, secant);
    CHECK(secant > 0 && 3 * secant <= fixed);
}

/* tol_relative: converged when |a+ + a-| summed over the pairs is below the
 * tolerance times the frame's own forces (pair members and corners), here
 * recomputed from the final snapshot. */
static void relative_tolerance(void)
{
    final_state f;
    double num = 0.0, den = 0.0;
    int q;
    run_lattice("P F 0.995 -0.01 -0.01 0.995 increments 2 relax 1e-14 20 tol_relative 1e-6 gain_force 1e3 "
                "gain_moment 1e3 update secant",
                2e3, &f);
    if (!converged_with_work(&f))
        return;
    for (q = 0; q < f.frame.n; ++q) {
        int p = f.frame.partner[q];
        den += f.a[3 * q] * f.a[3 * q] + f.a[3 * q + 1] * f.a[3 * q + 1];
        if (f.frame.side[q] == SBC_SIDE_BOTTOM || f.frame.side[q] == SBC_SIDE_RIGHT)
            num += pow(f.a[3 * q] + f.a[3 * p], 2) + pow(f.a[3 * q + 1] + f.a[3 * p + 1], 2);
    }
    CHECK(num > 0.0 && sqrt(num / den) <= 1e-6);
    CHECK_ABS(f.result.r_force, sqrt(num / den), 1e-12); /* the CSV's r_force is the relative norm */
    final_free(&f);
}

/* Tolerances below the floor of relaxation noise and round-off stop with
 * the stagnation message long before max_iterations. */
static void stagnation(void)
{
    final_state f;
    run_lattice("P F 0.99 -0.02 -0.02 0.99 increments 2 tol_force 1e-24 tol_moment 1e-24 gain_force 1e3 "
                "gain_moment 1e3 max_iterations 100000",
                2e3, &f);
    CHECK(f.status == SBC_ERR_DIVERGED);
    CHECK(strstr(f.message, "servo_bc P: increment 1, iteration ") && strstr(f.message, "stagnated") &&
          strstr(f.message, "stagnated on round-off") && strstr(f.message, "in the last 200 iterations is not 1 % below that of the 200 before") && strstr(f.message, "loosen the tolerances"));
    {
        const char *it = strstr(f.message, "iteration ");
        CHECK(it && atoi(it + 10) < 5000);
    }
    final_free(&f);
}

static void dirichlet_hill_mandel(void)
{
    final_state f;
    run_lattice("D F 0.995 -0.01 -0.01 0.995 increments 2 relax 1e-14 20", 2e3, &f);
    CHECK(f.status == SBC_OK);
    CHECK(hill_mandel(&f) <= 1e-8);
    final_free(&f);
}

/* predict 0 is the algorithm without prediction, to the last digit; a
 * non-zero inheritance factor takes another path. */
static void prediction(void)
{
    const char *bcs[2] = {"P", "T"};
    int b;
    for (b = 0; b < 2; ++b) {
        char script[1024], csv[3][512], *text[3];
        const char *extra[3] = {"", "predict 0", "predict 0.5"};
        int k;
        for (k = 0; k < 3; ++k) {
            sbc_error err;
            FILE *fp;
            long n;
            snprintf(csv[k], sizeof csv[k], "%s/predict_%s_%d.csv", test_tmpdir, bcs[b], k);
            snprintf(script, sizeof script,
                     "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\n"
                     "contact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\n"
                     "servo_bc %s F 0.99 -0.03 -0.03 0.99 increments 3 relax 1e-8 20 tol_force 1e-10 tol_moment "
                     "1e-10 tol_deformation 1e-4 gain_force 1e3 gain_moment 1e3 gain_deformation 1e-2 %s file %s\n"
                     "run\n",
                     bcs[b], extra[k], csv[k]);
            CHECK(sbc_script_run_string(script, "predict", NULL, &err) == SBC_OK);
            text[k] = NULL;
            fp = fopen(csv[k], "rb");
            if (fp) {
                fseek(fp, 0, SEEK_END);
                n = ftell(fp);
                fseek(fp, 0, SEEK_SET);
                text[k] = calloc((size_t)n + 1, 1);
                if (fread(text[k], 1, (size_t)n, fp) != (size_t)n)
                    text[k][0] = '\0';
                fclose(fp);
            }
        }
        CHECK(text[0] && text[1] && strlen(text[0]) > 100 && strcmp(text[0], text[1]) == 0);
        CHECK(text[0] && text[2] && strcmp(text[0], text[2]) != 0);
        for (k = 0; k < 3; ++k)
            free(text[k]);
    }
}

/* A gain far too large stops with the divergence error: no NaN, no hang.
 * (Increment 0 of the prestressed lattice is in equilibrium and converges.) */
static void divergence(void)
{
    final_state f;
    char csv[512], script[1024];
    static double rows[8][CSV_COLS];
    sbc_error err;
    run_lattice("P F 0.99 -0.02 -0.02 0.99 increments 2 tol_force 1e-14 gain_force 1e9 update fixed", 2e3, &f);
    CHECK(f.status == SBC_ERR_DIVERGED);
    CHECK(strstr(f.message, "servo_bc P: increment 1, iteration 0") && strstr(f.message, "half its radius") &&
          strstr(f.message, "r_force =") && strstr(f.message, "lower gain_force"));
    final_free(&f);
    run_lattice("T F 0.99 -0.02 -0.02 0.99 increments 2 tol_force 1e-14 gain_force 1e3 max_iterations 3", 2e3, &f);
    CHECK(f.status == SBC_ERR_DIVERGED);
    CHECK(strstr(f.message, "servo_bc T: increment 0, iteration 3: max_iterations reached") != NULL);
    final_free(&f);
    /* the CSV keeps the increments converged before the failure */
    snprintf(csv, sizeof csv, "%s/diverge.csv", test_tmpdir);
    snprintf(script, sizeof script,
             "dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 2e3 mu 0.4\n"
             "density 2e3\ntimestep 1e-5\nservo_bc P F 0.99 -0.02 -0.02 0.99 increments 3 tol_force 1e-14 "
             "gain_force 1e3 gain_moment 1e3 max_iterations 4 file %s\nrun\n",
             csv);
    CHECK(sbc_script_run_string(script, "diverge", NULL, &err) == SBC_ERR_DIVERGED);
    CHECK(strstr(err.message, "diverge:7:") && strstr(err.message, "increment 1, iteration 4: max_iterations"));
    CHECK(csv_read(csv, rows, 8) >= 0); /* header at least, every field finite */
}

/* Certified rows (docs/servo_bc.md): on an irregular packing under load
 * (n0 30, strain 0.01), a host whose reported frame positions are 0.01 radii
 * off the engine's, alternately, breaks eq. 30 (its residual is
 * sum (a_q - P A_q) . dx_q / V, and a_q != P A_q off a lattice); under (D) at
 * tight the Hill-Mandel residual of the first row exceeds the stated 1e-6 and
 * the run stops naming it, the increment and the frame particle farthest from
 * F X (0.01 radii: sqrt(2) 0.01 = 0.0141), instead of writing the row. The
 * same host reporting truly passes. */
static void irregular(sbc_packing *p)
{
    sbc_generate_def g = sbc_generate_def_default();
    sbc_error err;
    g.n = 30;
    g.strain = 0.01;
    CHECK(sbc_generate_periodic(&g, p, NULL, &err) == SBC_OK);
}

static void certification_failure(void)
{
    final_state f;
    sbc_packing p;
    const char *hm;
    irregular(&p);
    run_packing(p, "D F 0.99 0 0 0.99 increments 2 accuracy tight", 2e3, 0.01, &f);
    CHECK(f.status == SBC_ERR_DIVERGED);
    hm = strstr(f.message, "|hill_mandel| ");
    CHECK(strstr(f.message, "servo_bc D: increment 0, iteration 0: the state reached cannot be certified at accuracy "
                            "tight") != NULL);
    CHECK(hm && strtod(hm + 14, NULL) > 1e-6 && strstr(hm, "> the stated accuracy 1e-06"));
    CHECK(strstr(f.message, "is 0.0141 radii from F X") && strstr(f.message, "the row is not written"));
    final_free(&f);
    irregular(&p);
    run_packing(p, "D F 0.99 0 0 0.99 increments 2 accuracy tight", 2e3, 0.0, &f);
    CHECK(f.status == SBC_OK && fabs(f.result.hill_mandel) <= 1e-6);
    final_free(&f);
}

/* With the frame moved in one step (speed 0, accuracy paper), an increment
 * whose first step would move a frame particle by more than half a radius is
 * refused, with the jump in radii and how many more
 * increments it takes. F12 = 0.3 in one increment moves the top frame
 * particles of the 5 x 5 lattice (X2 = 8 mm) by 0.3 * 8 / 1.02 = 2.353 radii:
 * five times as many increments (0.471 radii each) pass. */
static void first_step_jump(void)
{
    final_state f;
    run_lattice("D F 1 0.3 0 1 increments 1 speed 0", 2e3, &f);
    CHECK(f.status == SBC_ERR_INPUT);
    CHECK(strstr(f.message, "servo_bc D: increment 1: its first step moves frame particle") &&
          strstr(f.message, "by 2.35 radii") && strstr(f.message, "take at least 5 times as many increments"));
    final_free(&f);
    run_lattice("P F 1 0.3 0 1 increments 4 accuracy paper", 2e3, &f); /* 0.588 radii */
    CHECK(f.status == SBC_ERR_INPUT && strstr(f.message, "by 0.588 radii") && strstr(f.message, "at least 2 times"));
    final_free(&f);
    run_lattice("D F 1 0.3 0 1 increments 5 speed 0", 2e3, &f);
    CHECK(f.status == SBC_OK && fabs(f.F[1] - 0.3) < 1e-15);
    final_free(&f);
    /* a frame that travels (speed > 0, the presets) does not jump: the same
       2.35 radii in one increment converge */
    run_lattice("D F 1 0.3 0 1 increments 1", 2e3, &f);
    CHECK(f.status == SBC_OK && fabs(f.F[1] - 0.3) < 1e-15);
    final_free(&f);
}

void test_servo(void)
{
    periodic_closed_form();
    periodic_state("fixed");
    traction_state("fixed");
    secant_update();
    relative_tolerance();
    stagnation();
    dirichlet_hill_mandel();
    prediction();
    divergence();
    certification_failure();
    first_step_jump();
}
