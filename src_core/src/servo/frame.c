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
    free(f->image);
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
    if (src->image) {
        if (!(dst->image = malloc(sizeof(int) * 3 * q))) {
            sbc_frame_free(dst);
            return sbc_fail(err, SBC_ERR_NOMEM, "frame: out of memory for the images of %d particles", src->n);
        }
        memcpy(dst->image, src->image, sizeof(int) * 3 * q);
    }
    return SBC_OK;
}

/* Layout (2D, as 0.2.0 wrote it): Q, then per frame position: particle,
 * side, partner, X (2), R, A (2); then the four corners and V. 3D: the
 * marker -3 first, then Q, per position particle, side, partner, X (3), R,
 * A (3); the eight corners, V, the cell count, the cells [4 ncell] and the
 * images [3Q]. */
#define FRAME_3D_MARKER -3.0

static size_t corners_of(int dim) { return dim == 3 ? 8 : 4; }

size_t sbc_frame_state_size(const sbc_frame *f)
{
    const size_t head = f->dim == 3 ? 2 : 1, tail = f->dim == 3 ? 1 + 4 * (size_t)f->ncell + 3 * (size_t)f->n : 0;
    return head + (4 + 2 * (size_t)f->dim) * (size_t)f->n + corners_of(f->dim) + 1 + tail;
}

void sbc_frame_save(const sbc_frame *f, double *out)
{
    int q, c, k;
    if (f->dim == 3)
        *out++ = FRAME_3D_MARKER;
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
    for (c = 0; c < (int)corners_of(f->dim); ++c)
        *out++ = f->corner[c];
    *out++ = f->V;
    if (f->dim == 3) {
        *out++ = f->ncell;
        for (c = 0; c < 4 * f->ncell; ++c)
            *out++ = f->cell[c];
        for (c = 0; c < 3 * f->n; ++c)
            *out++ = f->image[c];
    }
}

/* the invariants the servo indexes by: corners have no partner, a partner's
   partner is the particle itself, the corner list names corners (an edge
   particle may lack a partner: (D) needs none) */
static sbc_status check_loaded(const sbc_frame *f, sbc_error *err)
{
    int q, c;
    for (q = 0; q < f->n; ++q) {
        const int p = f->partner[q];
        const int corner = f->dim == 3 ? f->side[q] == (f->side[q] & 0x3f) && (f->side[q] & 3) && (f->side[q] & 12) &&
                                             (f->side[q] & 48)
                                       : f->side[q] == SBC_SIDE_CORNER;
        if ((corner && p >= 0) || (p >= 0 && f->partner[p] != q))
            return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: frame position %d (side %d) has partner %d, "
                            "which is not its periodic partner", q, f->side[q], p);
    }
    for (q = 0; f->image && q < 3 * f->n; ++q) {
        const int p = f->image[q];
        if (p >= 0 && f->image[3 * p + q % 3] != q / 3)
            return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: frame position %d has image %d across axis %d, "
                            "whose image is not it", q / 3, p, q % 3);
    }
    for (c = 0; c < (int)corners_of(f->dim); ++c) {
        const int side = f->side[f->corner[c]];
        const int corner = f->dim == 3 ? (side & 3) && (side & 12) && (side & 48) : side == SBC_SIDE_CORNER;
        if (!corner)
            return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: corner %d is frame position %d, not a corner", c,
                            f->corner[c]);
    }
    return SBC_OK;
}

sbc_status sbc_frame_load(sbc_frame *f, const double *in, size_t n, sbc_error *err)
{
    static const char *const xn[3] = {"X1", "X2", "X3"}, *const an[3] = {"A1", "A2", "A3"};
    sbc_saved rd;
    int q, c, k, nq, dim = 2, ncell = 0;
    size_t expect;
    sbc_status st;
    if (n > 0 && in[0] == FRAME_3D_MARKER) {
        dim = 3;
        ++in;
        --n;
    }
    sbc_saved_start(&rd, in, n, "frame restart data", err);
    nq = (int)sbc_saved_int(&rd, "frame particles Q", dim == 3 ? 8 : 4, 100000000L);
    if (rd.st != SBC_OK)
        return rd.st;
    expect = 1 + (4 + 2 * (size_t)dim) * (size_t)nq + corners_of(dim) + 1;
    if (dim == 3 && n > expect) /* the cells follow */
        ncell = (int)fmin(fmax(in[expect], -1.0), 1e9);
    if (dim == 3)
        expect += 1 + 4 * (size_t)(ncell > 0 ? ncell : 0) + 3 * (size_t)nq;
    if (n != expect || ncell < 0)
        return sbc_fail(err, SBC_ERR_INPUT, "frame restart data: %zu values do not describe a %dD frame of %d particles "
                        "(expected %zu)", n, dim, nq, expect);
    if ((st = sbc_frame_alloc(f, dim, nq, err)) != SBC_OK)
        return st;
    for (q = 0; q < nq; ++q) {
        f->particle[q] = (int)sbc_saved_int(&rd, "particle", 0, INT_MAX - 1);
        f->side[q] = (int)(dim == 3 ? sbc_saved_int(&rd, "side", 1, 63)
                                    : sbc_saved_int(&rd, "side", SBC_SIDE_CORNER, SBC_SIDE_LEFT));
        f->partner[q] = (int)sbc_saved_int(&rd, "partner", -1, nq - 1);
        for (k = 0; k < dim; ++k)
            f->X[3 * q + k] = sbc_saved_real(&rd, xn[k]);
        f->R[q] = sbc_saved_positive(&rd, "R");
        for (k = 0; k < dim; ++k)
            f->A[3 * q + k] = sbc_saved_real(&rd, an[k]);
    }
    for (c = 0; c < (int)corners_of(dim); ++c)
        f->corner[c] = (int)sbc_saved_int(&rd, "corner", 0, nq - 1);
    f->V = sbc_saved_positive(&rd, "V");
    if (dim == 3) {
        f->ncell = (int)sbc_saved_int(&rd, "cell count", 1, 1000000000L);
        if (rd.st == SBC_OK && !(f->cell = malloc(sizeof(int) * 4 * (size_t)f->ncell))) {
            sbc_frame_free(f);
            return sbc_fail(err, SBC_ERR_NOMEM, "frame restart data: out of memory for %d cells", ncell);
        }
        for (c = 0; c < 4 * f->ncell && rd.st == SBC_OK; ++c)
            f->cell[c] = (int)sbc_saved_int(&rd, "cell corner", 0, nq - 1);
        if (rd.st == SBC_OK && !(f->image = malloc(sizeof(int) * 3 * (size_t)nq))) {
            sbc_frame_free(f);
            return sbc_fail(err, SBC_ERR_NOMEM, "frame restart data: out of memory for %d images", nq);
        }
        for (c = 0; c < 3 * nq && rd.st == SBC_OK; ++c)
            f->image[c] = (int)sbc_saved_int(&rd, "image", -1, nq - 1);
    }
    if (rd.st == SBC_OK && (st = check_loaded(f, err)) == SBC_OK)
        return SBC_OK;
    sbc_frame_free(f);
    return rd.st != SBC_OK ? rd.st : st;
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
