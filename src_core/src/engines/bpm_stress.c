/* servo_bc: particle and RVE stress (thesis eqs. 54-62). */
#include "sbc/embedded/bpm_stress.h"
#include "sbc/embedded/bpm_packing.h"

#include <stdlib.h>
#include <string.h>

/* adds (arm (x) f) / v to s[9] */
static void add_dyad(double *s, const double arm[3], const double f[3], double v)
{
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j)
            s[3 * i + j] += arm[i] * f[j] / v;
}

sbc_status sbc_bpm_particle_stress(const sbc_bpm *e, double *sigma, sbc_error *err)
{
    double ext[6], centre[3];
    size_t i, k;
    int q;
    (void)err;
    memset(sigma, 0, 9 * e->n * sizeof *sigma);
    sbc_bpm_extent(e, ext);
    for (q = 0; q < 3; ++q)
        centre[q] = 0.5 * (ext[q] + ext[3 + q]);
    for (k = 0; k < e->nb; ++k) { /* eq. 62 per bond end */
        const sbc_bpm_bond *bd = &e->bonds[k];
        size_t a = bd->a, b = bd->b;
        const double *xa = &e->x[3 * a], *xb = &e->x[3 * b];
        double n[3], xc[3], fa[3] = {0, 0, 0}, ma[3] = {0, 0, 0}, fb[3] = {0, 0, 0}, mb[3] = {0, 0, 0};
        double arm_a[3], arm_b[3];
        sbc_parallel_bond_geometry(xa, e->r[a], xb, e->r[b], n, xc);
        if (e->set.model == SBC_BOND_BEAM)
            sbc_beam_bond_apply(&e->beam[k], fa, ma, fb, mb);
        else
            sbc_parallel_bond_apply(&e->parallel[k], xa, xb, xc, fa, ma, fb, mb);
        for (q = 0; q < 3; ++q) {
            arm_a[q] = xc[q] - xa[q];
            arm_b[q] = xc[q] - xb[q];
        }
        add_dyad(&sigma[9 * a], arm_a, fa, 1.0);
        add_dyad(&sigma[9 * b], arm_b, fb, 1.0);
    }
    for (i = 0; i < e->n; ++i) { /* loads on the outer side */
        double vp = 4.0 / 3.0 * SBC_PI * e->r[i] * e->r[i] * e->r[i];
        for (q = 0; q < 3; ++q) {
            double f = e->fext[6 * i + (size_t)q] + e->reaction[6 * i + (size_t)q];
            double side = e->x[3 * i + (size_t)q] < centre[q] ? -1.0 : 1.0;
            sigma[9 * i + 4 * (size_t)q] += side * e->r[i] * f;
        }
        for (q = 0; q < 9; ++q)
            sigma[9 * i + (size_t)q] /= vp;
    }
    return SBC_OK;
}

sbc_status sbc_bpm_rve_stress(const sbc_bpm *e, const unsigned char *mask, double volume, double sigma[9],
                              sbc_error *err)
{
    double *sp;
    size_t i;
    int q;
    sbc_status st;
    memset(sigma, 0, 9 * sizeof *sigma);
    if (!(volume > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "RVE stress: volume %g (expected > 0)", volume);
    sp = malloc((9 * e->n + 1) * sizeof *sp);
    if (!sp)
        return sbc_fail(err, SBC_ERR_NOMEM, "RVE stress: out of memory");
    if ((st = sbc_bpm_particle_stress(e, sp, err)) == SBC_OK)
        for (i = 0; i < e->n; ++i) { /* eq. 54 */
            double vp = 4.0 / 3.0 * SBC_PI * e->r[i] * e->r[i] * e->r[i];
            if (mask && !mask[i])
                continue;
            for (q = 0; q < 9; ++q)
                sigma[q] += vp * sp[9 * i + (size_t)q] / volume;
        }
    free(sp);
    return st;
}
