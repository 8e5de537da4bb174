/* Cell-binned Verlet pair list (O(N) build), history carried by merge. */
#include "neighbor.h"
#include "sbc/saved.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

sbc_status sbc_pairs_init(sbc_pairs *p, int dim, int n, double skin, int history, int bonds, sbc_error *err)
{
    memset(p, 0, sizeof *p);
    if (dim != 2 && dim != 3)
        return sbc_fail(err, SBC_ERR_INPUT, "neighbour list: dimension %d (expected 2 or 3)", dim);
    p->dim = dim;
    p->n = n;
    p->skin = skin;
    p->capacity = 4 * n + 16;
    history = history || bonds;
    p->start = calloc((size_t)n + 1, sizeof(int));
    p->i = malloc(sizeof(int) * (size_t)p->capacity);
    p->j = malloc(sizeof(int) * (size_t)p->capacity);
    p->fs = history ? calloc((size_t)p->capacity, sizeof(double)) : NULL;
    p->m = bonds ? calloc((size_t)p->capacity, sizeof(double)) : NULL;
    p->bond = bonds ? calloc((size_t)p->capacity, 1) : NULL;
    p->cell_of = malloc(sizeof(int) * (size_t)n);
    p->cell_order = malloc(sizeof(int) * (size_t)n);
    p->x_build = malloc(sizeof(double) * (size_t)dim * (size_t)n);
    if (!p->start || !p->i || !p->j || (history && !p->fs) || (bonds && (!p->m || !p->bond)) || !p->cell_of ||
        !p->cell_order || !p->x_build) {
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
    free(p->m);
    free(p->bond);
    free(p->cell_of);
    free(p->cell_start);
    free(p->cell_cursor);
    free(p->cell_order);
    free(p->x_build);
    memset(p, 0, sizeof *p);
}

/* The new list under construction. */
typedef struct new_list {
    int *i, *j, *start;
    double *fs, *m;
    unsigned char *bond;
} new_list;

static int resize(void **a, size_t size)
{
    void *b;
    if (!*a)
        return 1;
    b = realloc(*a, size);
    if (!b)
        return 0;
    *a = b;
    return 1;
}

static int grow(sbc_pairs *p, int need, new_list *q)
{
    size_t cap = (size_t)p->capacity;
    while (cap < (size_t)need)
        cap *= 2;
    if (!resize((void **)&q->i, sizeof(int) * cap) || !resize((void **)&q->j, sizeof(int) * cap) ||
        !resize((void **)&q->fs, sizeof(double) * cap) || !resize((void **)&q->m, sizeof(double) * cap) ||
        !resize((void **)&q->bond, cap))
        return 0;
    p->capacity = (int)cap;
    return 1;
}

static void new_list_free(new_list *q)
{
    free(q->i);
    free(q->j);
    free(q->start);
    free(q->fs);
    free(q->m);
    free(q->bond);
}

sbc_status sbc_pairs_build(sbc_pairs *p, const double *x, const double *r, double rmax, sbc_error *err)
{
    const int dim = p->dim;
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, h, cut_extra = p->skin;
    long nc[3] = {1, 1, 1}, ncell;
    int n = p->n, k, c, count = 0;
    new_list q;

    for (c = 0; c < dim; ++c) {
        lo[c] = DBL_MAX;
        hi[c] = -DBL_MAX;
    }
    for (k = 0; k < n; ++k)
        for (c = 0; c < dim; ++c) {
            lo[c] = fmin(lo[c], x[dim * k + c]);
            hi[c] = fmax(hi[c], x[dim * k + c]);
        }
    h = 2.0 * rmax + p->skin;
    /* keep the grid O(N) even when particles are scattered far apart, or tiny
       against their spacing (counted in doubles: the cell counts of a tiny h
       overflow a long) */
    for (;;) {
        double cells = 1.0, along[3] = {1, 1, 1};
        for (c = 0; c < dim; ++c)
            cells *= along[c] = floor((hi[c] - lo[c]) / h) + 1.0;
        if (cells <= 4.0 * n + 64.0) {
            for (c = 0; c < dim; ++c)
                nc[c] = (long)along[c];
            break;
        }
        h *= 1.5;
    }
    ncell = nc[0] * nc[1] * nc[2];
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
        long cell = 0;
        for (c = dim - 1; c >= 0; --c) {
            long b = (long)((x[dim * k + c] - lo[c]) / h);
            cell = cell * nc[c] + (b >= nc[c] ? nc[c] - 1 : b);
        }
        p->cell_of[k] = (int)cell;
        p->cell_start[p->cell_of[k] + 1]++;
    }
    for (k = 0; k < ncell; ++k)
        p->cell_start[k + 1] += p->cell_start[k];
    memcpy(p->cell_cursor, p->cell_start, sizeof(int) * (size_t)ncell);
    for (k = 0; k < n; ++k)
        p->cell_order[p->cell_cursor[p->cell_of[k]]++] = k;

    memset(&q, 0, sizeof q);
    q.i = malloc(sizeof(int) * (size_t)p->capacity);
    q.j = malloc(sizeof(int) * (size_t)p->capacity);
    q.start = malloc(sizeof(int) * ((size_t)n + 1));
    q.fs = p->fs ? malloc(sizeof(double) * (size_t)p->capacity) : NULL;
    q.m = p->m ? malloc(sizeof(double) * (size_t)p->capacity) : NULL;
    q.bond = p->bond ? malloc((size_t)p->capacity) : NULL;
    if (!q.i || !q.j || !q.start || (p->fs && !q.fs) || (p->m && !q.m) || (p->bond && !q.bond))
        goto nomem;

    for (k = 0; k < n; ++k) {
        long b[3] = {p->cell_of[k] % nc[0], (p->cell_of[k] / nc[0]) % nc[1], p->cell_of[k] / (nc[0] * nc[1])};
        long d[3];
        int first = count, m;
        q.start[k] = count;
        for (d[2] = dim == 3 ? -1 : 0; d[2] <= (dim == 3 ? 1 : 0); ++d[2])
            for (d[1] = -1; d[1] <= 1; ++d[1])
                for (d[0] = -1; d[0] <= 1; ++d[0]) {
                    long cell = 0;
                    int s, inside = 1;
                    for (c = 2; c >= 0; --c) {
                        inside &= b[c] + d[c] >= 0 && b[c] + d[c] < nc[c];
                        cell = cell * nc[c] + b[c] + d[c];
                    }
                    if (!inside)
                        continue;
                    for (s = p->cell_start[cell]; s < p->cell_start[cell + 1]; ++s) {
                        const int j = p->cell_order[s];
                        double d2 = 0.0, cut;
                        if (j <= k)
                            continue;
                        for (c = 0; c < dim; ++c)
                            d2 += (x[dim * j + c] - x[dim * k + c]) * (x[dim * j + c] - x[dim * k + c]);
                        cut = r[k] + r[j] + cut_extra;
                        if (d2 >= cut * cut)
                            continue;
                        if (count >= p->capacity && !grow(p, count + 1, &q))
                            goto nomem;
                        q.i[count] = k;
                        q.j[count++] = j;
                    }
                }
        /* insertion sort of k's partners by j (few per particle) */
        for (m = first + 1; m < count; ++m) {
            int v = q.j[m], t = m;
            while (t > first && q.j[t - 1] > v) {
                q.j[t] = q.j[t - 1];
                --t;
            }
            q.j[t] = v;
        }
    }
    q.start[n] = count;

    if (q.fs) { /* carry history and bonds over by merging the old and new lists of each i */
        for (k = 0; k < n; ++k) {
            int a = p->start[k], ae = p->start[k + 1], b;
            for (b = q.start[k]; b < q.start[k + 1]; ++b) {
                for (; a < ae && p->j[a] < q.j[b]; ++a)
                    if (p->bond && p->bond[a])
                        goto dropped_bond;
                if (a < ae && p->j[a] == q.j[b]) {
                    q.fs[b] = p->fs[a];
                    if (q.m) {
                        q.m[b] = p->m[a];
                        q.bond[b] = p->bond[a];
                    }
                    ++a;
                } else {
                    q.fs[b] = 0.0;
                    if (q.m) {
                        q.m[b] = 0.0;
                        q.bond[b] = 0;
                    }
                }
            }
            for (; a < ae; ++a)
                if (p->bond && p->bond[a])
                    goto dropped_bond;
        }
    }
    /* the arrays may have grown: p->capacity is the new size */
    free(p->i);
    free(p->j);
    free(p->start);
    free(p->fs);
    free(p->m);
    free(p->bond);
    p->i = q.i;
    p->j = q.j;
    p->start = q.start;
    p->fs = q.fs;
    p->m = q.m;
    p->bond = q.bond;
    p->count = count;
    memcpy(p->x_build, x, sizeof(double) * (size_t)dim * (size_t)n);
    return SBC_OK;
dropped_bond:
    new_list_free(&q);
    return sbc_fail(err, SBC_ERR_GEOMETRY,
                    "neighbour list: an intact bond stretched beyond the skin of %g m (the engine's skin must exceed "
                    "the bond's failure stretch fn_u / kn)",
                    p->skin);
nomem:
    new_list_free(&q);
    return sbc_fail(err, SBC_ERR_NOMEM, "neighbour list: out of memory for %d pairs", count);
}

int sbc_pairs_bond_touching(sbc_pairs *p, const double *x, const double *r, double gap)
{
    int k, bonds = 0;
    for (k = 0; p->bond && k < p->count; ++k) {
        int i = p->i[k], j = p->j[k];
        double dx = x[2 * j] - x[2 * i], dy = x[2 * j + 1] - x[2 * i + 1];
        double d = sqrt(dx * dx + dy * dy);
        p->bond[k] = d - r[i] - r[j] < gap;
        p->m[k] = 0.0;
        p->fs[k] = 0.0;
        bonds += p->bond[k];
    }
    return bonds;
}

size_t sbc_pairs_state_size(const sbc_pairs *p)
{
    const size_t per = 2 + (p->fs ? 1 : 0) + (p->bond ? 2 : 0);
    return 1 + (size_t)p->n + 1 + per * (size_t)p->count + (size_t)p->dim * (size_t)p->n;
}

double *sbc_pairs_save(const sbc_pairs *p, double *out)
{
    int k;
    *out++ = p->count;
    for (k = 0; k <= p->n; ++k)
        *out++ = p->start[k];
    for (k = 0; k < p->count; ++k) {
        *out++ = p->i[k];
        *out++ = p->j[k];
        if (p->fs)
            *out++ = p->fs[k];
        if (p->bond) {
            *out++ = p->m[k];
            *out++ = p->bond[k];
        }
    }
    for (k = 0; k < p->dim * p->n; ++k)
        *out++ = p->x_build[k];
    return out;
}

sbc_status sbc_pairs_load(sbc_pairs *p, sbc_saved *s)
{
    const long most = (long)p->n * (long)(p->n > 1 ? p->n - 1 : 1) / 2;
    const int count = (int)sbc_saved_int(s, "pair count", 0, most);
    int k;
    if (s->st != SBC_OK)
        return s->st;
    if (count > p->capacity) {
        new_list q = {p->i, p->j, p->start, p->fs, p->m, p->bond};
        if (!grow(p, count, &q))
            return sbc_fail(s->err, SBC_ERR_NOMEM, "neighbour list: out of memory for %d pairs", count);
        p->i = q.i;
        p->j = q.j;
        p->fs = q.fs;
        p->m = q.m;
        p->bond = q.bond;
    }
    for (k = 0; k <= p->n; ++k)
        p->start[k] = (int)sbc_saved_int(s, "pair list start", k ? p->start[k - 1] : 0, count);
    if (s->st == SBC_OK && p->start[p->n] != count)
        return sbc_fail(s->err, SBC_ERR_INPUT, "%s: the pair list's starts end at %d, not at its %d pairs", s->what,
                        p->start[p->n], count);
    for (k = 0; k < count && s->st == SBC_OK; ++k) {
        p->i[k] = (int)sbc_saved_int(s, "pair particle i", 0, p->n - 1);
        p->j[k] = (int)sbc_saved_int(s, "pair particle j", p->i[k] + 1, p->n - 1);
        if (p->fs)
            p->fs[k] = sbc_saved_real(s, "pair tangential force");
        if (p->bond) {
            p->m[k] = sbc_saved_real(s, "pair bond moment");
            p->bond[k] = (unsigned char)sbc_saved_int(s, "pair bond flag", 0, 1);
        }
    }
    for (k = 0; k < p->dim * p->n; ++k)
        p->x_build[k] = sbc_saved_real(s, "pair list build position");
    if (s->st == SBC_OK)
        p->count = count;
    return s->st;
}
