/* Servo control of (P) and (T): residuals (eqs. 32, 35), normalizations
 * (eq. 37) and corrections (eqs. 33, 34, 36). */
#include "servo.h"
#include "update_rules.h"
#include "sbc/homogenize.h"

#include <math.h>
#include <string.h>

/* (P), eqs. 32-34. Residuals on each +/- edge pair:
 *   da_e = a+_e + a-_e,   dm_e = m+_e + m-_e,   dm_c = sum of the four corner moments.
 * The corrections are added to both partners alike, which keeps
 * x+ - x- = F (X+ - X-) (eq. 19) exactly:
 *   du_e = -g_a da_e,   dtheta_e = -g_m dm_e,   dtheta_c = -g_m dm_c.
 * Sign: a_q is minus the resultant contact force (eq. 5), so a frame particle
 * held off its equilibrium by u has a = +k u; the correction must be -g a. The
 * paper's eq. 33 writes +g da with da of eq. 32; we read its residual as
 * "required minus measured" (0 - (a+ + a-)), as eq. 35 writes it for (T).
 * Gains from the dimensionless values of Table 4: g_a = G_a dt^2 / M,
 * g_m = G_m dt^2 / (M R^2), with M and R the mean of the two partners. */
/* Squared residuals and scales of tol_relative: force residual (N^2), force
 * scale sum |a_q|^2 (plus the squared target forces P A_q of (T)
 * components, so that a frame not yet in contact has a scale), moment
 * residual ((N m)^2), moment scale sum (|a_q| R_q)^2. */
typedef struct raw_sums {
    double fr, fs, mr, ms;
    double kn;           /* the host's contact stiffness, N/m (0: unknown) */
    double floor;        /* force floor, N (the force criterion's, relax.h) */
    double fs_lo, ms_lo; /* the scales' floors: floor^2 and (floor R)^2 summed like fs, ms */
    double roundoff;     /* round-off force, N (relax.h) */
    double fr_lo, mr_lo; /* roundoff^2 and (roundoff R)^2 summed like fr, mr */
} raw_sums;

static raw_sums no_sums(double kn, const sbc_servo_floors *floors)
{
    raw_sums w = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    w.kn = kn;
    w.floor = floors->scale;
    w.roundoff = floors->roundoff;
    return w;
}

/* one force residual da (N) */
static void add_residual(raw_sums *w, double da2)
{
    w->fr += da2;
    w->fr_lo += w->roundoff * w->roundoff;
}

/* The gains. update fixed: the paper's, from the dimensionless values of
 * Table 4, g_a = G_a dt^2 / M and g_m = G_m dt^2 / (M R^2) (eq. 37), which
 * hold one time step only (Table 4's values act at 1/1143 of the critical
 * step and throw the frame at 1/10). update secant with kn known: scale-free
 * first steps that the secant factor then adapts, g_a = share / kn (m/N; a
 * frame particle held by about one contact of stiffness kn on each side of a
 * pair: share 1/4 for a +/- pair, whose two partners move together, 1/2 for
 * one particle) and g_m = 1 / (4 kn R^2) (rad/(N m)). */
static int physical(const sbc_settings *s, const raw_sums *w)
{
    return sbc_update_rule_of(s->update)->scale_free_gains && w->kn > 0.0;
}

static double gain_force(const sbc_settings *s, const raw_sums *w, double dt, double M, double share)
{
    return physical(s, w) ? share / w->kn : s->gain_force * dt * dt / M;
}

static double gain_moment(const sbc_settings *s, const raw_sums *w, double dt, double M, double R)
{
    return physical(s, w) ? 0.25 / (w->kn * R * R) : s->gain_moment * dt * dt / (M * R * R);
}

/* |v|^2 over the first dim components */
static double norm2(int dim, const double *v)
{
    double s = 0.0;
    int k;
    for (k = 0; k < dim; ++k)
        s += v[k] * v[k];
    return s;
}

/* row i of T dotted with v: sum_j T_ij v_j, j < dim */
static double row_dot(int dim, const double T[9], int i, const double *v)
{
    double s = 0.0;
    int j;
    for (j = 0; j < dim; ++j)
        s += T[SBC_IJ(i, j)] * v[j];
    return s;
}

static void add_scale(raw_sums *w, int dim, const double *a, double R)
{
    double a2 = norm2(dim, a);
    w->fs += a2;
    w->ms += a2 * R * R;
    w->fs_lo += w->floor * w->floor;
    w->ms_lo += w->floor * w->floor * R * R;
}

/* The force residual relative to the frame's own forces, and with
 * tol_relative r_force and r_moment so: 0 when there is neither residual nor
 * force. Frame forces below the floor count as the floor: a packing that has
 * come apart (no stress to be relative to) is converged once its residual
 * forces are below the floor too. With tol_relative eps, the scale is never
 * below the force whose eps-th part is the round-off force: residuals whose
 * root mean square per frame particle is below it meet eps, as a net force
 * below it does in the relaxation (relax.h); eps times a floor can lie below
 * the round-off of the forces (tight: 1e-7 of the path floor). */
static void relative_norms(const sbc_settings *s, const raw_sums *w, sbc_servo_norms *o)
{
    const double eps2 = s->tol_relative * s->tol_relative;
    double fs = fmax(w->fs, w->fs_lo), ms = fmax(w->ms, w->ms_lo);
    if (eps2 > 0.0) {
        fs = fmax(fs, w->fr_lo / eps2);
        ms = fmax(ms, w->mr_lo / eps2);
    }
    o->relative_force = w->fr > 0.0 ? (fs > 0.0 ? sqrt(w->fr / fs) : 1.0) : 0.0;
    if (!(eps2 > 0.0))
        return;
    o->r_force = o->relative_force;
    o->r_moment = w->mr > 0.0 ? (ms > 0.0 ? sqrt(w->mr / ms) : 1.0) : 0.0;
}

/* |theta| of a rotation of r components: the angle in 2D, the length of the
   rotation vector in 3D */
static double rotation_length(int r, const double *v)
{
    return r == 1 ? fabs(v[0]) : hypot(hypot(v[0], v[1]), v[2]);
}

/* One family of (P) (sbc_frame_family: a +/- pair, in 3D also an edge
 * quadruple): the sums of its forces and moments are its residuals; the
 * corrections go to every member alike, which keeps x+ - x- = F (X+ - X-)
 * (eq. 19) exactly. Adds the family's normalized squared residuals to *sf
 * and *sm, the raw ones to *w. M, R: the members' means; the secant's first
 * step shares the force over the 2k contacts of the k members. */
static void periodic_family(const sbc_frame *f, const sbc_settings *s, const double *mass, double dt,
                            const int *member, int count, const double *a, const double *m, double *du,
                            double *dtheta, double *sf, double *sm, raw_sums *w, sbc_servo_norms *o)
{
    const int dim = f->dim, rot = SBC_ROTATIONS(dim);
    double M = 0.0, R = 0.0, at, mt, ga, gm, step;
    double da[3] = {0.0, 0.0, 0.0}, u[3] = {0.0, 0.0, 0.0}, dm[3] = {0.0, 0.0, 0.0}, t[3] = {0.0, 0.0, 0.0};
    int j, k;
    for (j = 0; j < count; ++j) { /* sums from the first member on: a sum of -0 stays -0 */
        M += mass[member[j]];
        R += f->R[member[j]];
        for (k = 0; k < dim; ++k)
            da[k] = j ? da[k] + a[3 * member[j] + k] : a[3 * member[j] + k];
        for (k = 0; k < rot; ++k)
            dm[k] = j ? dm[k] + m[rot * member[j] + k] : m[rot * member[j] + k];
    }
    M *= 1.0 / count;
    R *= 1.0 / count;
    at = M * R / (dt * dt);     /* a~ of eq. 37, N */
    mt = M * R * R / (dt * dt); /* m~ of eq. 37, N m */
    ga = gain_force(s, w, dt, M, 0.5 / count);
    gm = gain_moment(s, w, dt, M, R);
    for (k = 0; k < dim; ++k)
        u[k] = -ga * da[k];
    for (k = 0; k < rot; ++k)
        t[k] = -gm * dm[k];
    *sf += norm2(dim, da) / (at * at);
    *sm += norm2(rot, dm) / (mt * mt);
    add_residual(w, norm2(dim, da));
    w->mr += norm2(rot, dm);
    w->mr_lo += w->roundoff * w->roundoff * R * R;
    for (j = 0; j < count; ++j)
        add_scale(w, dim, &a[3 * member[j]], f->R[member[j]]);
    for (j = 0; j < count; ++j) {
        for (k = 0; k < SBC_DIM_MAX; ++k)
            du[3 * member[j] + k] = u[k];
        for (k = 0; k < rot; ++k)
            dtheta[rot * member[j] + k] = t[k];
    }
    step = sqrt(norm2(dim, u)) / R;
    if (step > o->max_step) o->max_step = step;
    step = gm * rotation_length(rot, dm); /* rotation step in rad = arc length / R */
    if (step > o->max_step) o->max_step = step;
}

/* (P): every family but the corners' (periodic_family); the corners follow F
 * (eq. 17) and share one rotation, servo-controlled on the sum of their
 * moments. */
static void servo_periodic(const sbc_frame *f, const sbc_settings *s, const double *mass, double dt, double kn, const sbc_servo_floors *floors,
                           const double *a, const double *m, double *du, double *dtheta, sbc_servo_norms *o)
{
    const int rot = SBC_ROTATIONS(f->dim);
    double sf = 0.0, sm = 0.0, dmc[3] = {0.0, 0.0, 0.0}, mc = 0.0, rc = 0.0;
    raw_sums w = no_sums(kn, floors);
    int q, c, k, corners = 0, corner[8], member[8];
    for (q = 0; q < f->n; ++q) {
        const int count = sbc_frame_family(f, q, member);
        if (count <= 0)
            continue;
        if (q == f->corner[0]) { /* the corners' family: after the others */
            corners = count;
            memcpy(corner, member, sizeof corner);
            continue;
        }
        periodic_family(f, s, mass, dt, member, count, a, m, du, dtheta, &sf, &sm, &w, o);
    }
    for (c = 0; c < corners; ++c) {
        int qc = corner[c];
        for (k = 0; k < rot; ++k)
            dmc[k] += m[rot * qc + k];
        mc += mass[qc] / corners;
        rc += f->R[qc] / corners;
        add_scale(&w, f->dim, &a[3 * qc], f->R[qc]);
    }
    w.mr += norm2(rot, dmc);
    w.mr_lo += w.roundoff * w.roundoff * rc * rc;
    {
        double mt = mc * rc * rc / (dt * dt);
        double gm = gain_moment(s, &w, dt, mc, rc);
        sm += norm2(rot, dmc) / (mt * mt);
        for (c = 0; c < corners; ++c) {
            int qc = corner[c];
            du[3 * qc] = du[3 * qc + 1] = du[3 * qc + 2] = 0.0; /* corners follow F (eq. 17) */
            for (k = 0; k < rot; ++k)
                dtheta[rot * qc + k] = -gm * dmc[k];
        }
        if (gm * rotation_length(rot, dmc) > o->max_step) o->max_step = gm * rotation_length(rot, dmc);
    }
    o->r_force = sqrt(sf);
    o->r_moment = sqrt(sm);
    o->r_deformation = 0.0;
    relative_norms(s, &w, o);
}

/* (T), eqs. 35-36, for every frame particle q:
 *   da_q = P A_q - a_q                                  (P from eq. 23)
 *   dF_q = V F A_q - sum_r (A_q . A_r) x_r              (m^3)
 *   du_q = g_a da_q + g_F dF_q
 * eq. 35 prints dF_q as sum_r [V F A_q - (A_q . A_r) x_r]; derived again from
 * eq. 15 dotted with A_q (V F A_q = sum_r x_r (A_r . A_q)), the V F A_q term
 * stands once, outside the sum; it vanishes exactly when eq. 15 holds for the
 * imposed F. Gains: g_a = G_a dt^2 / M_q, g_F = G_F / R_q^2; normalizations of
 * eq. 37: a~ = M R / dt^2, F~ = R^3. O(Q^2) for the sum over r; the frame
 * is O(sqrt N) particles, so this stays far below the cost of a DEM step. */
static void servo_traction(const sbc_frame *f, const sbc_settings *s, const double *mass, double dt, double kn, const sbc_servo_floors *floors,
                           const double F[9], const double *a, const double *x, double *du, double *dtheta,
                           sbc_servo_norms *o)
{
    const int dim = f->dim;
    double P[9], sf = 0.0, sd = 0.0;
    raw_sums w = no_sums(kn, floors);
    int q, r, i, j;
    /* eq. 23 */
    for (q = 0; q < 9; ++q)
        P[q] = 0.0;
    for (q = 0; q < f->n; ++q)
        for (i = 0; i < dim; ++i)
            for (j = 0; j < dim; ++j)
                P[SBC_IJ(i, j)] += a[3 * q + i] * f->X[3 * q + j];
    for (q = 0; q < 9; ++q)
        P[q] /= f->V;
    for (q = 0; q < f->n; ++q) {
        const double *A = &f->A[3 * q];
        double M = mass[q], R = f->R[q];
        double at = M * R / (dt * dt), Ft = R * R * R;
        double da[3] = {0.0, 0.0, 0.0}, dF[3] = {0.0, 0.0, 0.0}, t[3] = {0.0, 0.0, 0.0}, u[3] = {0.0, 0.0, 0.0};
        for (i = 0; i < dim; ++i) {
            t[i] = row_dot(dim, P, i, A);
            da[i] = t[i] - a[3 * q + i];
            dF[i] = f->V * row_dot(dim, F, i, A);
        }
        for (r = 0; r < f->n; ++r) {
            double w = 0.0;
            for (j = 0; j < dim; ++j)
                w += A[j] * f->A[3 * r + j];
            for (i = 0; i < dim; ++i)
                dF[i] -= w * x[3 * r + i];
        }
        sf += norm2(dim, da) / (at * at);
        sd += norm2(dim, dF) / (Ft * Ft);
        add_residual(&w, norm2(dim, da));
        add_scale(&w, dim, &a[3 * q], R);
        add_scale(&w, dim, t, R);
        {
            double ga = gain_force(s, &w, dt, M, 0.5), gF = s->gain_deformation / (R * R), step;
            for (i = 0; i < dim; ++i)
                u[i] = ga * da[i] + gF * dF[i];
            for (i = 0; i < SBC_DIM_MAX; ++i)
                du[3 * q + i] = u[i];
            for (i = 0; i < SBC_ROTATIONS(dim); ++i)
                dtheta[SBC_ROTATIONS(dim) * q + i] = 0.0; /* free rotation */
            step = sqrt(norm2(dim, u)) / R;
            if (step > o->max_step) o->max_step = step;
        }
    }
    o->r_force = sqrt(sf);
    o->r_moment = 0.0;
    o->r_deformation = sqrt(sd);
    relative_norms(s, &w, o);
}

void sbc_servo_residuals(sbc_bc bc, const sbc_frame *f, const sbc_settings *s, const double *mass, double dt,
                         double kn, const sbc_servo_floors *floors, const double F[9], const double *a, const double *m, const double *x,
                         double *du, double *dtheta, sbc_servo_norms *out)
{
    out->max_step = 0.0;
    if (bc == SBC_BC_P)
        servo_periodic(f, s, mass, dt, kn, floors, a, m, du, dtheta, out);
    else
        servo_traction(f, s, mass, dt, kn, floors, F, a, x, du, dtheta, out);
}

/* Mixed, Table 5 with the modes as data (mode[3q + c] = sbc_mode):
 *  - P pairs: eqs. 32-34 as in (P), each pair once;
 *  - T components: da_q,c = P_cj A_q,j - a_q,c and du_q,c = g_a da_q,c (eq. 48),
 *    P_cj prescribed where P_fixed, otherwise measured by eq. 23;
 *  - D components: no correction. Rotations: P pairs servo-controlled, all
 *    other rotations free or held by the commands (dtheta = 0).
 * r_force gathers the force residuals of P pairs and T components (r_a^p and
 * r_a^t of Table 5, one tolerance); r_moment those of the P pairs. */
void sbc_servo_mixed(const sbc_frame *f, const unsigned char *mode, const sbc_settings *s, const double *mass,
                     double dt, double kn, const sbc_servo_floors *floors, const double P_star[9], const unsigned char P_fixed[9],
                     const double *a, const double *m, double *du, double *dtheta, sbc_servo_norms *o)
{
    double P[9] = {0.0}, sf = 0.0, sm = 0.0;
    raw_sums w = no_sums(kn, floors);
    int q, k;
    o->max_step = 0.0;
    sbc_homogenize_P(f, a, P); /* eq. 23 */
    for (k = 0; k < 9; ++k)
        if (P_fixed[k])
            P[k] = P_star[k];
    for (q = 0; q < 3 * f->n; ++q)
        du[q] = 0.0;
    for (q = 0; q < SBC_ROTATIONS(f->dim) * f->n; ++q)
        dtheta[q] = 0.0;
    for (q = 0; q < f->n; ++q) {
        const double *A = &f->A[3 * q];
        double R = f->R[q], at = mass[q] * R / (dt * dt), ga = gain_force(s, &w, dt, mass[q], 0.5);
        int c;
        if (mode[3 * q] == SBC_MODE_P) { /* the families but the corners' */
            int member[8], count = sbc_frame_family(f, q, member);
            if (count > 0 && q != f->corner[0])
                periodic_family(f, s, mass, dt, member, count, a, m, du, dtheta, &sf, &sm, &w, o);
            continue;
        }
        for (c = 0; c < f->dim; ++c) {
            double da, step;
            if (mode[3 * q + c] != SBC_MODE_T)
                continue;
            da = row_dot(f->dim, P, c, A) - a[3 * q + c];
            sf += da * da / (at * at);
            add_residual(&w, da * da);
            w.fs += a[3 * q + c] * a[3 * q + c] + (da + a[3 * q + c]) * (da + a[3 * q + c]); /* measured and target */
            w.fs_lo += 2.0 * w.floor * w.floor;
            du[3 * q + c] = ga * da;
            step = fabs(ga * da) / R;
            if (step > o->max_step) o->max_step = step;
        }
    }
    o->r_force = sqrt(sf);
    o->r_moment = sqrt(sm);
    o->r_deformation = 0.0;
    relative_norms(s, &w, o);
}
