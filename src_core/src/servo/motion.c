/* The frame's travel to new commands at a bounded speed (motion.h). */
#include "motion.h"
#include "sbc/tensor.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int sbc_motion_alloc(sbc_motion *m, int q, int rot)
{
    size_t n = (size_t)q;
    m->rot = rot;
    m->x_from = calloc(3 * n, sizeof(double));
    m->x_goal = calloc(3 * n, sizeof(double));
    m->th_from = calloc((size_t)rot * n, sizeof(double));
    m->th_goal = calloc((size_t)rot * n, sizeof(double));
    m->steps = m->done = 1;
    return m->x_from && m->x_goal && m->th_from && m->th_goal;
}

void sbc_motion_free(sbc_motion *m)
{
    free(m->x_from);
    free(m->x_goal);
    free(m->th_from);
    free(m->th_goal);
}

/* commands a fraction t of the way from x_from to x_goal */
static void place(const sbc_motion *m, int q, double t, double *x, double *th)
{
    int k;
    for (k = 0; k < 3 * q; ++k)
        x[k] = t >= 1.0 ? m->x_goal[k] : m->x_from[k] + t * (m->x_goal[k] - m->x_from[k]);
    for (k = 0; k < m->rot * q; ++k)
        th[k] = t >= 1.0 ? m->th_goal[k] : m->th_from[k] + t * (m->th_goal[k] - m->th_from[k]);
}

void sbc_motion_begin(sbc_motion *m, const sbc_frame *f, const double *mass, double kn, double dt, double speed,
                      const double *carry, const double *origin, double *x, double *th)
{
    double longest = 0.0; /* the most time steps one frame particle needs */
    int q;
    memcpy(m->x_goal, x, sizeof(double) * 3 * (size_t)f->n);
    memcpy(m->th_goal, th, sizeof(double) * (size_t)(m->rot * f->n));
    if (speed > 0.0 && kn > 0.0) {
        for (q = 0; q < f->n; ++q) {
            const double R = f->R[q];
            const double *a = &m->x_from[3 * q], *b = &m->x_goal[3 * q];
            const double *ta = &m->th_from[m->rot * q], *tb = &m->th_goal[m->rot * q];
            double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, u[3] = {0.0, 0.0, 0.0};
            int k;
            /* hypot(h, 0) = |h| exactly (C11 F.10.4.3): a 2D frame's length is hypot(d0, d1) */
            const double turn = m->rot == 1 ? fabs(tb[0] - ta[0])
                                            : hypot(hypot(tb[0] - ta[0], tb[1] - ta[1]), tb[2] - ta[2]);
            double path;
            if (carry)
                sbc_remap_displacement(f->dim, carry, origin, a, u);
            for (k = 0; k < 3; ++k)
                d[k] -= u[k];
            path = hypot(hypot(d[0], d[1]), d[2]) + R * turn;
            const double per_step = speed * R * dt / sqrt(2.0 * mass[q] / kn); /* m per time step */
            if (path / per_step > longest)
                longest = path / per_step;
        }
    }
    m->steps = longest > 1.0 ? (long)fmin(ceil(longest), 1e9) : 1;
    m->done = 1;
    place(m, f->n, 1.0 / (double)m->steps, x, th);
}

int sbc_motion_advance(sbc_motion *m, int q, double *x, double *th)
{
    if (m->done >= m->steps)
        return 0;
    m->done++;
    place(m, q, (double)m->done / (double)m->steps, x, th);
    return 1;
}
