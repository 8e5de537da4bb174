/* The controller, mixed condition (Table 5, Sect. 5.1): which rows of F are
 * measured, the support's centre, the D components following F, the stress
 * targets and how far the frame lags (controller_private.h). */
#include "controller_private.h"
#include "sbc/homogenize.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Mixed: row i of F (F_i1, F_i2, ...) is a result of the (T) condition, eq. 45,
 * when some face controls component i by traction (the layer: the last row). */
int sbc_ctl_row_measured(const sbc_controller *c, int i)
{
    int f;
    for (f = 0; f < 2 * c->frame->dim; ++f)
        if (c->s.face_mode[f][i] == SBC_MODE_T)
            return 1;
    return 0;
}

/* Mixed: the point the D components deform about, x = c + F (X - c): the
 * centroid of the support's reference centres (the low face of the last
 * axis, its edges and corners included: the bottom edge in 2D, zlo in 3D),
 * so that the support keeps its place on average while it follows F, and a
 * translated packing gives the same results. */
void sbc_ctl_mixed_centre(const sbc_controller *c, double centre[3])
{
    const sbc_frame *f = c->frame;
    const int support = 2 * (f->dim - 1);
    int q, k, n = 0;
    centre[0] = centre[1] = centre[2] = 0.0;
    for (q = 0; q < f->n; ++q)
        if (sbc_frame_faces(f, q) >> support & 1) {
            for (k = 0; k < f->dim; ++k)
                centre[k] += f->X[3 * q + k];
            ++n;
        }
    for (k = 0; k < f->dim; ++k)
        centre[k] /= n;
}

/* F_k. v: row k of F applied to v (over j < dim) */
static double row_dot(int dim, const double F[9], int k, const double v[3])
{
    double s = 0.0;
    int j;
    for (j = 0; j < dim; ++j)
        s += F[SBC_IJ(k, j)] * v[j];
    return s;
}

/* One family of periodic images (sbc_frame_family) keeps x_m - x_n = F (X_m
 * - X_n) (eq. 19) about its servo-controlled mean: x_m = mean + (o_m - mean
 * of o), o_m = F (X_m - X_first), component by component (for a pair, the
 * midpoint plus and minus half of F (X+ - X-)) */
static void keep_offsets(sbc_controller *c, const int *member, int count)
{
    const sbc_frame *f = c->frame;
    const int dim = f->dim;
    double offset[8];
    int j, k, i;
    for (k = 0; k < dim; ++k) {
        double mid = 0.0, mean = 0.0;
        for (j = 0; j < count; ++j) {
            double D[3] = {0.0, 0.0, 0.0};
            for (i = 0; i < dim; ++i)
                D[i] = f->X[3 * member[j] + i] - f->X[3 * member[0] + i];
            offset[j] = row_dot(dim, c->F_now, k, D);
            mid = j ? mid + c->x_cmd[3 * member[j] + k] : c->x_cmd[3 * member[j] + k];
            mean = j ? mean + offset[j] : offset[j];
        }
        mid *= 1.0 / count;
        mean *= 1.0 / count;
        for (j = 0; j < count; ++j)
            c->x_cmd[3 * member[j] + k] = mid + (offset[j] - mean);
    }
}

/* Mixed, Sect. 5.1: the D components follow F, x_q = c + F (X_q - c) (eqs. 17,
 * 43_1), and the periodic families keep x_m - x_n = F (X_m - X_n) (eq. 19)
 * about their servo-controlled mean, with F the imposed components and, in the
 * rows of eq. 45, the measured ones (F_now holds both). With the measured F
 * every boundary term of eq. 46 vanishes: w_q = 0 on D components, periodic w
 * on the pairs (the proof of Sect. 5.1). */
void sbc_ctl_mixed_follow_F(sbc_controller *c)
{
    const sbc_frame *f = c->frame;
    const double *F = c->F_now;
    const int dim = f->dim;
    double centre[3];
    int q, k, j;
    sbc_ctl_mixed_centre(c, centre);
    for (q = 0; q < f->n; ++q) {
        double d[3] = {0.0, 0.0, 0.0};
        for (k = 0; k < dim; ++k)
            d[k] = f->X[3 * q + k] - centre[k];
        for (k = 0; k < dim; ++k)
            if (c->mode[3 * q + k] == SBC_MODE_D) {
                double x = centre[k];
                for (j = 0; j < dim; ++j)
                    x += F[SBC_IJ(k, j)] * d[j];
                c->x_cmd[3 * q + k] = x;
            }
        if (c->mode[3 * q] == SBC_MODE_P) {
            int member[8], count = sbc_frame_family(f, q, member);
            if (count > 1 && q != f->corner[0])
                keep_offsets(c, member, count);
        }
    }
}

/* Table 5, 1.1 / 2.1: D components follow F (mixed_follow_F); P pairs and
 * T components carry on from the previous converged state, shifted by the
 * change of F; rotations are free on edges with a T component, held at zero
 * on D edges, servo-controlled on P. The measured rows of F carry on from the
 * previous converged increment. */
void sbc_ctl_start_mixed(sbc_controller *c)
{
    const sbc_frame *f = c->frame;
    double *F = c->F_now;
    const double *G = c->F_prev;
    const int dim = f->dim;
    double centre[3], dF[9];
    int q, k, j;
    for (k = 0; k < dim; ++k)
        if (sbc_ctl_row_measured(c, k))
            for (j = 0; j < dim; ++j)
                F[SBC_IJ(k, j)] = G[SBC_IJ(k, j)];
    for (k = 0; k < 9; ++k)
        dF[k] = F[k] - G[k];
    sbc_ctl_mixed_centre(c, centre);
    for (q = 0; q < f->n; ++q) {
        double d[3] = {0.0, 0.0, 0.0};
        int any_t = 0, all_d = 1;
        for (k = 0; k < dim; ++k)
            d[k] = f->X[3 * q + k] - centre[k];
        for (k = 0; k < dim; ++k) {
            const double shift = row_dot(dim, dF, k, d);
            if (c->mode[3 * q + k] != SBC_MODE_D && c->increment > 0)
                c->x_cmd[3 * q + k] = c->x_prev[3 * q + k] + shift;
            any_t |= c->mode[3 * q + k] == SBC_MODE_T;
            all_d &= c->mode[3 * q + k] == SBC_MODE_D;
        }
        c->free_rot[q] = (unsigned char)any_t;
        if (all_d)
            for (k = 0; k < c->rot; ++k)
                c->theta_cmd[c->rot * q + k] = 0.0;
    }
    sbc_ctl_mixed_follow_F(c);
}

/* The prescribed stresses of this increment: `stress` components ramp to
 * their values over the stress stage and hold after it; the others are
 * measured (eq. 23). Sect. 5.2 prescribes P21 = 0 during the stress stage,
 * "to avoid the initial development of a shear stress"; the proof of eqs.
 * 46-47 needs the measured P21 in the top's traction, and prescribing 0 does
 * not keep the measured P21 at 0 (the support's reactions make it): on a
 * 37-disc layer at accuracy tight, P21 = -3.5e4 N/m either way (P22* =
 * -1.05e6), Hill-Mandel 1.6e-5 with P21 = 0 prescribed and 1.2e-10 with P21
 * measured; 120 discs: 1.0e-7 against 5e-11 (docs/servo_bc.md). */
void sbc_ctl_mixed_stress_targets(sbc_controller *c)
{
    double t = c->s.stress_increments > 0 ? fmin(1.0, (double)c->increment / c->s.stress_increments) : 1.0;
    int k;
    for (k = 0; k < 9; ++k) {
        c->P_star[k] = 0.0;
        c->P_fixed[k] = 0;
    }
    for (k = 0; k < c->s.nstress; ++k) {
        int ij = SBC_IJ(c->s.stress[k].i, c->s.stress[k].j);
        c->P_star[ij] = t * c->s.stress[k].value;
        c->P_fixed[ij] = 1;
    }
}

/* Modes of each frame position from the face modes of the settings
 * (controller.h): a particle on several faces takes those of its face normal to the last axis
 * (the support's and the top's: the horizontal edges in 2D, zlo and zhi in
 * 3D), then the middle, then the first. Where that face is periodic the
 * particle is P with its family of images, unless it is a corner or one of
 * its other faces is not periodic: then it follows F (D), as the corners of
 * (P) do (eq. 17). The top corners of the layer stay T in y: made D (Sect.
 * 5.1's "followed by the four corner nodes"), their reactions put 8 % into
 * eq. 23's P22 on 120 discs (docs/servo_bc.md, "Mixed"). */
void sbc_mixed_modes(const sbc_frame *f, const sbc_settings *s, unsigned char *mode)
{
    const int dim = f->dim;
    int q, k, a;
    for (q = 0; q < f->n; ++q) {
        const int faces = sbc_frame_faces(f, q);
        int face = -1, nfaces = 0, all_p = 1, g;
        for (a = dim - 1; a >= 0 && face < 0; --a)
            if (faces >> (2 * a) & 3)
                face = faces >> (2 * a) & 1 ? 2 * a : 2 * a + 1;
        for (g = 0; g < 2 * dim; ++g)
            if (faces >> g & 1) {
                ++nfaces;
                all_p &= s->face_mode[g][0] == SBC_MODE_P;
            }
        for (k = 0; k < dim; ++k) {
            unsigned char m = s->face_mode[face][k];
            mode[3 * q + k] = m == SBC_MODE_P && (nfaces == dim || !all_p) ? SBC_MODE_D : m;
        }
    }
}

/* Mixed: how far (in radii) the frame's D components and pair offsets may
 * lag behind the measured rows of F (eq. 45) at a converged increment: the
 * relative tolerance of the preset, or 1e-6 with absolute tolerances. */
double sbc_ctl_mixed_lag_tol(const sbc_controller *c)
{
    return c->s.tol_relative > 0.0 ? c->s.tol_relative : 1e-6;
}

/* Mixed: measures F (eq. 15 on the positions x) and returns the largest
 * displacement, in radii, by which the D components and the pair offsets
 * lag behind it in the measured rows; Fm receives the measured F. */
double sbc_ctl_mixed_lag(const sbc_controller *c, const double *x, double Fm[9])
{
    const sbc_frame *f = c->frame;
    double centre[3], lag = 0.0;
    int q, k;
    sbc_homogenize_F(f, x, Fm);
    sbc_ctl_mixed_centre(c, centre);
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < f->dim; ++k)
            if (sbc_ctl_row_measured(c, k) && c->mode[3 * q + k] != SBC_MODE_T) {
                const double d = (Fm[SBC_IJ(k, k)] - c->F_now[SBC_IJ(k, k)]) * (f->X[3 * q + k] - centre[k]);
                if (fabs(d) / f->R[q] > lag)
                    lag = fabs(d) / f->R[q];
            }
    return lag;
}

/* Mixed: P of eq. 23 from the boundary forces (into P), and how far it misses
 * the prescribed components of the traction rows, relative to |P_star|
 * there. P_hat: eq. 23 with the traction components of the top at their
 * targets (P_star + P_shift, measured where not prescribed), which measures
 * what the support and the pairs add to P apart from the top's lag. */
double sbc_ctl_mixed_stress_miss(sbc_controller *c, double P[9], double P_hat[9])
{
    const sbc_frame *f = c->frame;
    double miss = 0.0, scale = 0.0, Pt[9], centre[3];
    int q, k;
    sbc_ctl_mixed_centre(c, centre);
    sbc_homogenize_P_about(f, c->a, centre, P);
    for (k = 0; k < 9; ++k)
        Pt[k] = c->P_fixed[k] ? c->P_star[k] + c->P_shift[k] : P[k];
    memcpy(c->a_hat, c->a, sizeof(double) * 3 * (size_t)f->n);
    for (q = 0; q < f->n; ++q)
        for (k = 0; k < f->dim; ++k)
            if (c->mode[3 * q + k] == SBC_MODE_T)
                c->a_hat[3 * q + k] = row_dot(f->dim, Pt, k, &f->A[3 * q]);
    sbc_homogenize_P_about(f, c->a_hat, centre, P_hat);
    for (k = 0; k < f->dim; ++k)
        if (c->P_fixed[SBC_IJ(k, k)] && sbc_ctl_row_measured(c, k)) {
            miss = fmax(miss, fabs(P[SBC_IJ(k, k)] - c->P_star[SBC_IJ(k, k)]));
            scale = fmax(scale, fabs(c->P_star[SBC_IJ(k, k)]));
        }
    return scale > 0.0 ? miss / scale : 0.0;
}

/* End of the stress stage of a mixed BC: the converged state becomes the
 * reference X of stage 2 (Sect. 5.1, after eq. 44), with its A_q and V. */
void sbc_ctl_new_reference(sbc_controller *c, const double *x)
{
    int q, k;
    for (q = 0; q < c->ref.n; ++q) /* the third slot of a 2D frame stays 0 */
        for (k = 0; k < c->ref.dim; ++k)
            c->ref.X[3 * q + k] = x[3 * q + k];
    sbc_frame_update_geometry(&c->ref);
}
