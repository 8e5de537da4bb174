/* The frame of boundary particles, whatever its dimension: storage, restart
 * layout, gathering centres. Its geometry: frame_2d.c, frame_3d.c. */
#include "frame_private.h"

#include "sbc/saved.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

sbc_status sbc_frame_alloc(sbc_frame *f, int dim, int q, sbc_error *err)
{
    memset(f, 0, sizeof *f);
    f->dim = dim;
    f->n = q;
    f->particle = malloc(sizeof(int) * (size_t)q);
    f->side = malloc(sizeof(int) * (size_t)q);
    f->partner = malloc(sizeof(int) * (size_t)q);
    f->X = calloc(SBC_DIM_MAX * (size_t)q, sizeof(double));
    f->R = malloc(sizeof(double) * (size_t)q);
    f->A = calloc(SBC_DIM_MAX * (size_t)q, sizeof(double));
    if (!f->particle || !f->side || !f->partner || !f->X || !f->R || !f->A) {
        sbc_frame_free(f);
        return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory for %d particles", q);
    }
    return SBC_OK;
}

void sbc_frame_free(sbc_frame *f)
{
    if (!f)
        return;
    free(f->particle);
    free(f->side);
    free(f->partner);
    free(f->X);
    free(f->R);
    free(f->A);
    free(f->cell);
    memset(f, 0, sizeof *f);
}

sbc_status sbc_frame_copy(sbc_frame *dst, const sbc_frame *src, sbc_error *err)
{
    const size_t q = (size_t)src->n;
    sbc_status st = sbc_frame_alloc(dst, src->dim, src->n, err);
    if (st != SBC_OK)
        return st;
    memcpy(dst->particle, src->particle, sizeof(int) * q);
    memcpy(dst->side, src->side, sizeof(int) * q);
    memcpy(dst->partner, src->partner, sizeof(int) * q);
    memcpy(dst->X, src->X, sizeof(double) * SBC_DIM_MAX * q);
    memcpy(dst->R, src->R, sizeof(double) * q);
    memcpy(dst->A, src->A, sizeof(double) * SBC_DIM_MAX * q);
    memcpy(dst->corner, src->corner, sizeof dst->corner);
    dst->V = src->V;
    if (src->ncell > 0) {
        if (!(dst->cell = malloc(sizeof(int) * 4 * (size_t)src->ncell))) {
            sbc_frame_free(dst);
            return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory for %d surface cells", src->ncell);
        }
        memcpy(dst->cell, src->cell, sizeof(int) * 4 * (size_t)src->ncell);
        dst->ncell = src->ncell;
    }
    return SBC_OK;
}

/* Layout: Q, then per frame position: particle, side, partner, X (dim), R,
 * A (dim); then the four corners and V. A saved frame is read as a 2D one
 * (the layout names no dimension yet). */
size_t sbc_frame_state_size(const sbc_frame *f) { return 1 + (4 + 2 * (size_t)f->dim) * (size_t)f->n + 5; }

void sbc_frame_save(const sbc_frame *f, double *out)
{
    int q, c, k;
    *out++ = f->n;
    for (q = 0; q < f->n; ++q) {
        *out++ = f->particle[q];
        *out++ = f->side[q];
        *out++ = f->partner[q];
        for (k = 0; k < f->dim; ++k)
            *out++ = f->X[3 * q + k];
        *out++ = f->R[q];
        for (k = 0; k < f->dim; ++k)
            *out++ = f->A[3 * q + k];
    }
    for (c = 0; c < 4; ++c)
        *out++ = f->corner[c];
    *out = f->V;
}

sbc_status sbc_frame_load(sbc_frame *f, const double *in, size_t n, sbc_error *err)
{
    sbc_saved rd;
    int q, c, nq;
    sbc_status st;
    sbc_saved_start(&rd, in, n, "frame restart data", err);
    nq = (int)sbc_saved_int(&rd, "frame particles Q", 4, 100000000L);
    if (rd.st != SBC_OK)
        return rd.st;
    if (n != 1 + 8 * (size_t)nq + 5)
        return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: %zu values do not describe a frame of %d particles "
                        "(expected %zu)", n, nq, 1 + 8 * (size_t)nq + 5);
    if ((st = sbc_frame_alloc(f, 2, nq, err)) != SBC_OK)
        return st;
    for (q = 0; q < nq; ++q) {
        f->particle[q] = (int)sbc_saved_int(&rd, "particle", 0, INT_MAX - 1);
        f->side[q] = (int)sbc_saved_int(&rd, "side", SBC_SIDE_CORNER, SBC_SIDE_LEFT);
        f->partner[q] = (int)sbc_saved_int(&rd, "partner", -1, nq - 1);
        f->X[3 * q] = sbc_saved_real(&rd, "X1");
        f->X[3 * q + 1] = sbc_saved_real(&rd, "X2");
        f->R[q] = sbc_saved_positive(&rd, "R");
        f->A[3 * q] = sbc_saved_real(&rd, "A1");
        f->A[3 * q + 1] = sbc_saved_real(&rd, "A2");
    }
    for (c = 0; c < 4; ++c)
        f->corner[c] = (int)sbc_saved_int(&rd, "corner", 0, nq - 1);
    f->V = sbc_saved_positive(&rd, "V");
    if (rd.st != SBC_OK)
        return rd.st;
    /* the invariants the servo indexes by: corners have no partner, a
       partner's partner is the particle itself, the corner list names corners
       (an edge particle may lack a partner: (D) needs none) */
    for (q = 0; q < nq; ++q) {
        const int p = f->partner[q];
        if ((f->side[q] == SBC_SIDE_CORNER && p >= 0) || (p >= 0 && f->partner[p] != q))
            return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: frame position %d (side %d) has partner %d, "
                            "which is not its periodic partner", q, f->side[q], p);
    }
    for (c = 0; c < 4; ++c)
        if (f->side[f->corner[c]] != SBC_SIDE_CORNER)
            return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: corner %d is frame position %d, not a corner", c,
                            f->corner[c]);
    return SBC_OK;
}

void sbc_frame_centres(const sbc_frame *frame, const double *x, double *fx)
{
    int q;
    for (q = 0; q < frame->n; ++q) {
        const int p = frame->particle[q], dim = frame->dim;
        int k;
        for (k = 0; k < SBC_DIM_MAX; ++k)
            fx[3 * q + k] = k < dim ? x[dim * p + k] : 0.0;
    }
}
