/* servo_bc: many material points at once (material_point.h,
 * sbc_points_integrate): a queue of points taken one at a time by C11
 * threads */
#include "sbc/material_point.h"

#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <threads.h>

typedef struct batch {
    sbc_point *const *points;
    int count;
    const double *F;
    double *P, *ratio;
    int *status;
    sbc_error *errs; /* [count] */
    atomic_int next;
} batch;

static int worker(void *arg)
{
    batch *b = arg;
    int k;
    while ((k = atomic_fetch_add(&b->next, 1)) < b->count)
        b->status[k] = (int)sbc_point_integrate(b->points[k], &b->F[9 * (size_t)k], &b->P[9 * (size_t)k],
                                                &b->ratio[k], &b->errs[k]);
    return 0;
}

static int by_address(const void *a, const void *b)
{
    const uintptr_t x = (uintptr_t) * (sbc_point *const *)a, y = (uintptr_t) * (sbc_point *const *)b;
    return (x > y) - (x < y);
}

/* every point given and none twice (two threads would integrate one point at once); SBC_OK or the refusal */
static sbc_status distinct(sbc_point *const *points, int count, sbc_error *err)
{
    sbc_point **sorted;
    int k, twice = -1;
    for (k = 0; k < count; ++k)
        if (!points[k])
            return sbc_fail(err, SBC_ERR_INPUT, "material points: point %d is NULL", k);
    if (!(sorted = malloc(sizeof *sorted * (size_t)(count > 0 ? count : 1))))
        return sbc_fail(err, SBC_ERR_NOMEM, "material points: out of memory for %d points", count);
    memcpy(sorted, points, sizeof *sorted * (size_t)count);
    qsort(sorted, (size_t)count, sizeof *sorted, by_address);
    for (k = 1; k < count && twice < 0; ++k)
        if (sorted[k] == sorted[k - 1])
            twice = k;
    if (twice >= 0) {
        int first = -1, second = -1;
        for (k = 0; k < count && second < 0; ++k)
            if (points[k] == sorted[twice])
                *(first < 0 ? &first : &second) = k;
        free(sorted);
        return sbc_fail(err, SBC_ERR_INPUT, "material points: points %d and %d are the same sbc_point (each "
                        "integration point needs its own)", first, second);
    }
    free(sorted);
    return SBC_OK;
}

sbc_status sbc_points_integrate(sbc_point *const *points, int count, const double *F, double *P, int *status,
                                double *ratio, int threads, sbc_error *err)
{
    batch b;
    thrd_t *pool = NULL;
    int k, started = 0;
    if (count < 0 || (count > 0 && (!points || !F || !P || !status || !ratio)))
        return sbc_fail(err, SBC_ERR_INPUT, "material points: %d points without their arrays", count);
    if (distinct(points, count, err) != SBC_OK) {
        for (k = 0; k < count; ++k)
            status[k] = SBC_POINT_FAILED, ratio[k] = 0.5;
        memset(P, 0, sizeof(double) * 9 * (size_t)count);
        return err->status;
    }
    b.points = points;
    b.count = count;
    b.F = F;
    b.P = P;
    b.ratio = ratio;
    b.status = status;
    atomic_init(&b.next, 0);
    if (!(b.errs = calloc((size_t)(count > 0 ? count : 1), sizeof *b.errs)))
        return sbc_fail(err, SBC_ERR_NOMEM, "material points: out of memory for %d points", count);
    if (threads > count)
        threads = count;
    if (threads > 1 && (pool = malloc(sizeof *pool * (size_t)(threads - 1))))
        for (; started < threads - 1 && thrd_create(&pool[started], worker, &b) == thrd_success; ++started)
            ;
    worker(&b); /* the calling thread takes its share (all of it without a pool) */
    for (k = 0; k < started; ++k)
        thrd_join(pool[k], NULL);
    free(pool);
    for (k = 0; k < count; ++k)
        if (status[k] != SBC_POINT_CONVERGED) {
            sbc_fail(err, b.errs[k].status != SBC_OK ? b.errs[k].status : SBC_ERR_DIVERGED, "point %d: %s", k,
                     b.errs[k].message);
            free(b.errs);
            return err->status;
        }
    free(b.errs);
    return SBC_OK;
}
