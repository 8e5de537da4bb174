/* An aggregate's tangents C_ijkl = dP_ij / dF_kl (aggregate.h, docs/fe2.md):
 * affine, condensed and by perturbation. */
#include "aggregate.h"
#include "condensed.h"
#include "contact_blocks.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sbc/controller.h"
#include "sbc/tensor.h"

sbc_status sbc_aggregate_affine(const sbc_aggregate *a, const double F[9], double C[81], sbc_error *err)
{
    const int dim = a->frame->dim, npair = a->ops->pair_count(a->engine);
    const double *x = a->ops->centres(a->engine), *r = a->ops->radii(a->engine);
    const sbc_frictional *law = &a->law;
    double Finv[9];
    int c, i, j, k, l;
    if (a->bonds)
        return sbc_fail(err, SBC_ERR_INPUT, "affine tangent: it sums the contacts of eq. 6; this aggregate's "
                        "cohesive bonds (eqs. 7-8) are not in it (use the perturbation tangent)");
    memset(C, 0, sizeof(double) * 81);
    if (!sbc_tensor_inverse(dim, F, Finv))
        return sbc_fail(err, SBC_ERR_GEOMETRY, "affine tangent: the current F cannot be inverted");
    for (c = 0; c < npair; ++c) {
        double lv[3] = {0, 0, 0}, L[3], n[3] = {0, 0, 0}, K[9], len = 0.0, dn, fv[3], fs;
        int ij[2], stick;
        a->ops->pair(a->engine, c, ij, fv);
        fs = sqrt(fv[0] * fv[0] + fv[1] * fv[1] + fv[2] * fv[2]);
        for (k = 0; k < dim; ++k) {
            lv[k] = x[dim * ij[1] + k] - x[dim * ij[0] + k];
            len += lv[k] * lv[k];
        }
        len = sqrt(len);
        dn = r[ij[0]] + r[ij[1]] - len;
        if (!(dn > 0.0))
            continue; /* open */
        for (k = 0; k < dim; ++k)
            n[k] = lv[k] / len;
        sbc_tensor_apply(dim, Finv, lv, L);
        stick = law->ks > 0.0 && fs < law->mu * law->kn * dn * (1.0 - SBC_SLIDING_BAND);
        for (i = 0; i < dim; ++i)
            for (k = 0; k < dim; ++k) {
                const double t = (i == k ? 1.0 : 0.0) - n[i] * n[k]; /* I - n (x) n */
                K[SBC_IJ(i, k)] = -law->kn * n[i] * n[k] + law->kn * dn / len * t - (stick ? law->ks * t : 0.0);
            }
        for (i = 0; i < dim; ++i)
            for (j = 0; j < dim; ++j)
                for (k = 0; k < dim; ++k)
                    for (l = 0; l < dim; ++l)
                        C[9 * SBC_IJ(i, j) + SBC_IJ(k, l)] -= K[SBC_IJ(i, k)] * L[l] * L[j] / a->frame->V;
    }
    return SBC_OK;
}

/* the committed spring of each current pair of net (zero for a pair that was not committed), [3 npair] */
static void springs_at_start(const sbc_network *net, const sbc_increment_start *start, double *fs0)
{
    int k, q;
    for (k = 0; k < net->npair; ++k) {
        const int c = sbc_pair_index(start->npair, start->i, start->j, net->i[k], net->j[k]);
        for (q = 0; q < 3; ++q)
            fs0[3 * k + q] = c >= 0 ? start->fs[3 * c + q] : 0.0;
    }
}

sbc_status sbc_aggregate_condensed(const sbc_aggregate *a, const sbc_increment_start *start, double C[81],
                                   int *mechanisms, sbc_error *err)
{
    int *ij = NULL, ignored;
    double *fs = NULL, *fs0 = NULL;
    unsigned char *mode = NULL;
    sbc_network net;
    sbc_status st;
    if (!mechanisms)
        mechanisms = &ignored;
    memset(C, 0, sizeof(double) * 81);
    *mechanisms = 0;
    if (a->settings->bc == SBC_BC_MIXED) { /* each frame particle's D and P components */
        if (!(mode = malloc(3 * (size_t)a->frame->n)))
            return sbc_fail(err, SBC_ERR_NOMEM, "condensed tangent: out of memory");
        sbc_mixed_modes(a->frame, a->settings, mode);
    }
    if ((st = sbc_aggregate_network(a, &net, &ij, &fs, err)) == SBC_OK) {
        net.mode = mode;
        if (start && net.dim == 2)
            net.x0 = start->x;
        else if (start && start->theta) { /* 3D: the increment's springs from the committed ones */
            if (!(fs0 = malloc(sizeof *fs0 * 3 * (size_t)(net.npair > 0 ? net.npair : 1))))
                st = sbc_fail(err, SBC_ERR_NOMEM, "condensed tangent: out of memory for %d pairs", net.npair);
            else {
                springs_at_start(&net, start, fs0);
                net.x0 = start->x;
                net.theta0 = start->theta;
                net.theta = a->ops->rotations(a->engine);
                net.fs0 = fs0;
            }
        }
        if (st == SBC_OK)
            st = sbc_condensed_tangent(&net, a->frame, a->settings->bc, C, mechanisms, err);
    }
    free(ij);
    free(fs);
    free(fs0);
    free(mode);
    return st;
}

/* one increment from the accepted state (engine E0, controller C0) to F: P */
static sbc_status branch(const sbc_aggregate *a, const double *E0, size_t ne, const double *C0, size_t nc,
                         const sbc_fire_state *fire, const double F[9], double P[9], sbc_error *err)
{
    sbc_driver_callbacks cb = sbc_aggregate_callbacks(a);
    sbc_controller *ctl = NULL;
    sbc_driver *driver = NULL;
    sbc_event ev = SBC_EVENT_FAILED;
    if (a->ops->load(a->engine, E0, ne, err) == SBC_OK &&
        (ctl = sbc_controller_create(a->frame, a->settings, a->mass, a->dt, a->law.kn, err)) &&
        sbc_controller_load(ctl, C0, nc, err) == SBC_OK && sbc_controller_branch(ctl, F, err) == SBC_OK &&
        (driver = sbc_driver_create(ctl, a->settings, &cb, err))) {
        *sbc_driver_fire(driver) = *fire;
        sbc_driver_remap(driver);
        ev = sbc_aggregate_run_increment(a, ctl, driver, 0, err);
        if (ev != SBC_EVENT_FAILED)
            memcpy(P, sbc_controller_result(ctl)->P, sizeof(double) * 9);
    }
    sbc_driver_free(driver);
    sbc_controller_free(ctl);
    return ev == SBC_EVENT_FAILED ? err->status : SBC_OK;
}

sbc_status sbc_aggregate_perturbation(const sbc_aggregate *a, const sbc_controller *accepted,
                                      const sbc_fire_state *fire, double h, double C[81], sbc_error *err)
{
    const int dim = a->frame->dim;
    const size_t ne = a->ops->state_size(a->engine), nc = sbc_controller_state_size(accepted);
    double *E0 = malloc(sizeof(double) * ne), *C0 = malloc(sizeof(double) * nc), F0[9], F[9], P[2][9];
    sbc_status st = SBC_OK;
    int k, l, side, ij;
    memset(C, 0, sizeof(double) * 81);
    if (!(h > 0.0) || !isfinite(h))
        st = sbc_fail(err, SBC_ERR_INPUT, "perturbation tangent: step %g is not positive", h);
    else if (!E0 || !C0)
        st = sbc_fail(err, SBC_ERR_NOMEM, "perturbation tangent: out of memory");
    if (st != SBC_OK) {
        free(E0);
        free(C0);
        return st;
    }
    a->ops->save(a->engine, E0);
    sbc_controller_save(accepted, C0);
    memcpy(F0, sbc_controller_result(accepted)->F, sizeof F0);
    for (k = 0; k < dim && st == SBC_OK; ++k)
        for (l = 0; l < dim && st == SBC_OK; ++l) {
            for (side = 0; side < 2 && st == SBC_OK; ++side) {
                memcpy(F, F0, sizeof F);
                F[SBC_IJ(k, l)] += side ? -h : h;
                st = branch(a, E0, ne, C0, nc, fire, F, P[side], err);
            }
            for (ij = 0; ij < 9 && st == SBC_OK; ++ij) /* eq. 23's P at F + h e_kl and F - h e_kl */
                C[9 * ij + SBC_IJ(k, l)] = (P[0][ij] - P[1][ij]) / (2.0 * h);
        }
    {
        sbc_error ignored; /* a state this engine saved itself: it loads */
        a->ops->load(a->engine, E0, ne, &ignored);
    }
    free(E0);
    free(C0);
    if (st != SBC_OK)
        memset(C, 0, sizeof(double) * 81);
    return st;
}
