/* Cell-binned Verlet pair list (O(N) build), history carried by merge. */
#include "neighbor.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

sbc_status sbc_pairs_init(sbc_pairs *p, int n, double skin, int history, sbc_error *err)
{
    memset(p, 0, sizeof *p);
    p->n = n;
    p->skin = skin;
    p->capacity = 4 * n + 16;
    p->start = calloc((size_t)n + 1, sizeof(int));
    p->i = malloc(sizeof(int) * (size_t)p->capacity);
    p->j = malloc(sizeof(int) * (size_t)p->capacity);
    p->fs = history ? calloc((size_t)p->capacity, sizeof(double)) : NULL;
    p->cell_of = malloc(sizeof(int) * (size_t)n);
    p->cell_order = malloc(sizeof(int) * (size_t)n);
    p->x_build = malloc(sizeof(double) * 2 * (size_t)n);
    if (!p->start || !p->i || !p->j || (history && !p->fs) || !p->cell_of || !p->cell_order || !p->x_build) {
        sbc_pairs_free(p);
        return sbc_fail(err, SBC_ERR_NOMEM, "neighbour list: out of memory for %d particles", n);
    }
    return SBC_OK;
}

void sbc_pairs_free(sbc_pairs *p)
{
    free(p->start);
    free(p->i);
    free(p->j);
    free(p->fs);
    free(p->cell_of);
    free(p->cell_start);
    free(p->cell_cursor);
    free(p->cell_order);
    free(p->x_build);
    memset(p, 0, sizeof *p);
}

static int grow(sbc_pairs *p, int need, int **ni, int **nj, double **nfs)
{
    int cap = p->capacity;
    while (cap < need)
        cap *= 2;
    if (cap == p->capacity)
        return 1;
    {
        int *a = realloc(*ni, sizeof(int) * (size_t)cap);
        int *b;
        double *c = NULL;
        if (!a)
            return 0;
        *ni = a;
        b = realloc(*nj, sizeof(int) * (size_t)cap);
        if (!b)
            return 0;
        *nj = b;
        if (nfs && *nfs) {
            c = realloc(*nfs, sizeof(double) * (size_t)cap);
            if (!c)
                return 0;
            *nfs = c;
        }
    }
    p->capacity = cap;
    return 1;
}

sbc_status sbc_pairs_build(sbc_pairs *p, const double *x, const double *r, double rmax, sbc_error *err)
{
    double lo[2] = {DBL_MAX, DBL_MAX}, hi[2] = {-DBL_MAX, -DBL_MAX}, h, cut_extra = p->skin;
    long ncx, ncy, ncell;
    int n = p->n, k, count = 0;
    int *ni = NULL, *nj = NULL, *nstart = NULL;
    double *nfs = NULL;

    for (k = 0; k < n; ++k) {
        if (x[2 * k] < lo[0]) lo[0] = x[2 * k];
        if (x[2 * k] > hi[0]) hi[0] = x[2 * k];
        if (x[2 * k + 1] < lo[1]) lo[1] = x[2 * k + 1];
        if (x[2 * k + 1] > hi[1]) hi[1] = x[2 * k + 1];
    }
    h = 2.0 * rmax + p->skin;
    /* keep the grid O(N) even when particles are scattered far apart */
    for (;;) {
        ncx = (long)((hi[0] - lo[0]) / h) + 1;
        ncy = (long)((hi[1] - lo[1]) / h) + 1;
        if (ncx * ncy <= 4L * n + 64)
            break;
        h *= 1.5;
    }
    ncell = ncx * ncy;
    if (ncell + 1 > p->cell_capacity) {
        free(p->cell_start);
        free(p->cell_cursor);
        p->cell_start = malloc(sizeof(int) * (size_t)(ncell + 1));
        p->cell_cursor = malloc(sizeof(int) * (size_t)(ncell + 1));
        if (!p->cell_start || !p->cell_cursor) {
            p->cell_capacity = 0;
            return sbc_fail(err, SBC_ERR_NOMEM, "neighbour list: out of memory for %ld cells", ncell);
        }
        p->cell_capacity = (int)(ncell + 1);
    }
    memset(p->cell_start, 0, sizeof(int) * (size_t)(ncell + 1));
    for (k = 0; k < n; ++k) {
        long cx = (long)((x[2 * k] - lo[0]) / h), cy = (long)((x[2 * k + 1] - lo[1]) / h);
        if (cx >= ncx) cx = ncx - 1;
        if (cy >= ncy) cy = ncy - 1;
        p->cell_of[k] = (int)(cy * ncx + cx);
        p->cell_start[p->cell_of[k] + 1]++;
    }
    for (k = 0; k < ncell; ++k)
        p->cell_start[k + 1] += p->cell_start[k];
    memcpy(p->cell_cursor, p->cell_start, sizeof(int) * (size_t)ncell);
    for (k = 0; k < n; ++k)
        p->cell_order[p->cell_cursor[p->cell_of[k]]++] = k;

    ni = malloc(sizeof(int) * (size_t)p->capacity);
    nj = malloc(sizeof(int) * (size_t)p->capacity);
    nstart = malloc(sizeof(int) * ((size_t)n + 1));
    if (p->fs)
        nfs = malloc(sizeof(double) * (size_t)p->capacity);
    if (!ni || !nj || !nstart || (p->fs && !nfs))
        goto nomem;

    for (k = 0; k < n; ++k) {
        long cx = p->cell_of[k] % ncx, cy = p->cell_of[k] / ncx, ax, ay;
        int first = count, m;
        nstart[k] = count;
        for (ay = cy - 1; ay <= cy + 1; ++ay) {
            if (ay < 0 || ay >= ncy) continue;
            for (ax = cx - 1; ax <= cx + 1; ++ax) {
                long c;
                int s;
                if (ax < 0 || ax >= ncx) continue;
                c = ay * ncx + ax;
                for (s = p->cell_start[c]; s < p->cell_start[c + 1]; ++s) {
                    int j = p->cell_order[s];
                    double dx, dy, cut;
                    if (j <= k) continue;
                    dx = x[2 * j] - x[2 * k];
                    dy = x[2 * j + 1] - x[2 * k + 1];
                    cut = r[k] + r[j] + cut_extra;
                    if (dx * dx + dy * dy >= cut * cut) continue;
                    if (count >= p->capacity && !grow(p, count + 1, &ni, &nj, &nfs))
                        goto nomem;
                    ni[count] = k;
                    nj[count++] = j;
                }
            }
        }
        /* insertion sort of k's partners by j (few per particle) */
        for (m = first + 1; m < count; ++m) {
            int v = nj[m], t = m;
            while (t > first && nj[t - 1] > v) {
                nj[t] = nj[t - 1];
                --t;
            }
            nj[t] = v;
        }
    }
    nstart[n] = count;

    if (nfs) { /* carry the tangential history over by merging old and new lists of each i */
        for (k = 0; k < n; ++k) {
            int a = p->start[k], ae = p->start[k + 1], b;
            for (b = nstart[k]; b < nstart[k + 1]; ++b) {
                while (a < ae && p->j[a] < nj[b]) ++a;
                nfs[b] = (a < ae && p->j[a] == nj[b]) ? p->fs[a] : 0.0;
            }
        }
    }
    /* the arrays may have grown: p->capacity is the new size */
    free(p->i);
    free(p->j);
    free(p->start);
    free(p->fs);
    p->i = ni;
    p->j = nj;
    p->start = nstart;
    p->fs = nfs;
    p->count = count;
    memcpy(p->x_build, x, sizeof(double) * 2 * (size_t)n);
    return SBC_OK;
nomem:
    free(ni);
    free(nj);
    free(nstart);
    free(nfs);
    return sbc_fail(err, SBC_ERR_NOMEM, "neighbour list: out of memory for %d pairs", count);
}
