/* servo_bc: many material points at once (material_point.h,
 * sbc_points_integrate): a queue of points taken one at a time by C11
 * threads */
#include "sbc/material_point.h"

#include <stdatomic.h>
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

sbc_status sbc_points_integrate(sbc_point *const *points, int count, const double *F, double *P, int *status,
                                double *ratio, int threads, sbc_error *err)
{
    batch b;
    thrd_t *pool = NULL;
    int k, started = 0;
    if (count < 0 || (count > 0 && (!points || !F || !P || !status || !ratio)))
        return sbc_fail(err, SBC_ERR_INPUT, "material points: %d points without their arrays", count);
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
