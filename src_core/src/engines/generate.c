/* Irregular polydisperse periodic packings: jamming by box shrinking with FIRE
 * overlap minimization, then the periodic reconstruction of Sect. 4.2. */
#include "sbc/embedded/generate.h"
#include "fire.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

sbc_generate_def sbc_generate_def_default(void)
{
    sbc_generate_def d;
    d.n = 200;
    d.r_min = 0.67e-3;
    d.polydispersity = 2.0;
    d.seed = 1;
    d.strain = 0.0;
    d.log = NULL;
    return d;
}


static double quantize(double a) { return ldexp(nearbyint(ldexp(a, 50)), -50); }

/* floor(t) for |t| < 2^62 without a libm call (the inner loop's): the same value */
static double floor_small(double t)
{
    const double k = (double)(long long)t;
    return k > t ? k - 1.0 : k;
}

static double image(double d, double L) { return d - L * floor_small(d / L + 0.5); }

static double wrap(double a, double L) { return a - L * floor_small(a / L); }

typedef struct box {
    int dim, n;
    double L, rmax, *x, *r, *v, *f; /* x, v, f [dim n] */
    int *head, *next, cells; /* periodic cell list, cells^dim heads */
    /* the pairs that may touch (within r_i + r_j + skin when listed), in the
       order in which the cell list visits them; -1 in listed: not listed */
    int *pair, npair, cap, listed, *cell;
    double skin, *x0; /* x0 [dim n]: the centres when listed */
} box;

/* the neighbour list's skin, in largest radii: a list is made again when a
   particle has moved by half of it */
#define SKIN 0.3

static void box_free(box *b, box *keep)
{
    free(b->x); free(b->r); free(b->v); free(b->f); free(b->head); free(b->next); free(b->cell); free(b->x0);
    free(b->pair); free(keep->x);
}

static double pair_force(box *b, int i, int j)
{
    const int dim = b->dim;
    double dx[3], rs = b->r[i] + b->r[j], d2 = 0.0, d, ov;
    int k;
    for (k = 0; k < dim; ++k) {
        dx[k] = image(b->x[dim * j + k] - b->x[dim * i + k], b->L);
        d2 = k ? d2 + dx[k] * dx[k] : dx[k] * dx[k];
    }
    if (d2 >= rs * rs)
        return 0.0;
    d = sqrt(d2);
    ov = rs - d;
    if (d > 0.0)
        for (k = 0; k < dim; ++k) {
            b->f[dim * i + k] -= ov * dx[k] / d;
            b->f[dim * j + k] += ov * dx[k] / d;
        }
    return 0.5 * ov * ov;
}

/* the cell of particle i along each axis, in a box of nc cells per side */
static void cell_of(const box *b, int i, int nc, int c[3])
{
    int k;
    c[2] = 0;
    for (k = 0; k < b->dim; ++k) {
        c[k] = (int)(b->x[b->dim * i + k] / b->L * nc);
        if (c[k] >= nc) c[k] = nc - 1;
    }
}

/* The pairs (i, j > i) in the order the overlap sum visits them: every pair
 * when nc < 3 (or above the cells allocated), else i ascending and, for each,
 * the 3^dim cells around its own in a periodic cell list of nc cells a side
 * (each >= 2 rmax wide), each cell's particles newest first. visit(b, i, j)
 * for each; cell[i] (when not NULL) gets particle i's cell. */
static void visit_pairs(box *b, int nc, int *cell, void (*visit)(box *, int, int, void *), void *ctx)
{
    const int dim = b->dim;
    int i, j, k, ncell = 1, oz, oy, ox;
    if (nc < 3 || nc > b->cells) {
        for (i = 0; i < b->n; ++i)
            for (j = i + 1; j < b->n; ++j)
                visit(b, i, j, ctx);
        return;
    }
    for (k = 0; k < dim; ++k)
        ncell *= nc;
    for (i = 0; i < ncell; ++i)
        b->head[i] = -1;
    for (i = 0; i < b->n; ++i) {
        int c[3];
        cell_of(b, i, nc, c);
        k = (c[2] * nc + c[1]) * nc + c[0];
        b->next[i] = b->head[k];
        b->head[k] = i;
        if (cell)
            cell[i] = k;
    }
    for (i = 0; i < b->n; ++i) {
        int c[3];
        cell_of(b, i, nc, c);
        for (oz = dim == 3 ? -1 : 0; oz <= (dim == 3 ? 1 : 0); ++oz)
            for (oy = -1; oy <= 1; ++oy)
                for (ox = -1; ox <= 1; ++ox) {
                    const int z = dim == 3 ? (c[2] + oz + nc) % nc : 0;
                    for (j = b->head[(z * nc + (c[1] + oy + nc) % nc) * nc + (c[0] + ox + nc) % nc]; j >= 0;
                         j = b->next[j])
                        if (j > i)
                            visit(b, i, j, ctx);
                }
    }
}

static void sum_pair(box *b, int i, int j, void *e) { *(double *)e += pair_force(b, i, j); }

/* the pair (i, j) goes to the list when its gap is below the skin; a full list
   (out of memory) is marked by listed = 0 */
static void list_pair(box *b, int i, int j, void *unused)
{
    double d2 = 0.0, reach = b->r[i] + b->r[j] + b->skin;
    int k;
    (void)unused;
    for (k = 0; k < b->dim; ++k) {
        const double d = image(b->x[b->dim * j + k] - b->x[b->dim * i + k], b->L);
        d2 += d * d;
    }
    if (d2 >= reach * reach || !b->listed)
        return;
    if (b->npair == b->cap) {
        int cap = b->cap ? 2 * b->cap : 8 * b->n, *more = realloc(b->pair, sizeof(int) * 2 * (size_t)cap);
        if (!more) {
            b->listed = 0;
            return;
        }
        b->pair = more;
        b->cap = cap;
    }
    b->pair[2 * b->npair] = i;
    b->pair[2 * b->npair + 1] = j;
    ++b->npair;
}

/* Whether the list still holds every pair that can touch, in the order of
   visit_pairs: the same cell size, no particle in another cell, none moved by
   more than half the skin since it was made. */
static int list_holds(const box *b, int nc)
{
    const int dim = b->dim, direct = nc < 3 || nc > b->cells;
    int i, k;
    if (!b->listed || b->listed != (direct ? -1 : nc))
        return 0;
    for (i = 0; i < b->n; ++i) {
        double d2 = 0.0;
        for (k = 0; k < dim; ++k) {
            const double d = image(b->x[dim * i + k] - b->x0[dim * i + k], b->L);
            d2 += d * d;
        }
        if (4.0 * d2 >= b->skin * b->skin)
            return 0;
        if (!direct) {
            int c[3];
            cell_of(b, i, nc, c);
            if ((c[2] * nc + c[1]) * nc + c[0] != b->cell[i])
                return 0;
        }
    }
    return 1;
}

/* Overlap forces (unit stiffness) and energy sum(overlap^2)/2 in the periodic
 * box, the pairs summed in visit_pairs' order: from the list of the pairs that
 * may touch while it holds (the pairs left out add exactly nothing, so the
 * sums are the same to the bit), else over every visited pair. */
static double forces(box *b)
{
    const int nc = (int)(b->L / (2.0 * b->rmax)), direct = nc < 3 || nc > b->cells;
    double e = 0.0;
    int k;
    memset(b->f, 0, sizeof(double) * (size_t)b->dim * (size_t)b->n);
    if (!list_holds(b, nc)) {
        b->npair = 0;
        b->listed = direct ? -1 : nc;
        visit_pairs(b, nc, b->cell, list_pair, NULL);
        memcpy(b->x0, b->x, sizeof(double) * (size_t)b->dim * (size_t)b->n);
    }
    if (!b->listed) {
        visit_pairs(b, nc, NULL, sum_pair, &e);
        return e;
    }
    for (k = 0; k < b->npair; ++k)
        e += pair_force(b, b->pair[2 * k], b->pair[2 * k + 1]);
    return e;
}

static double forces_cb(void *ctx) { return forces(ctx); }

static void wrap_cb(void *ctx, size_t k)
{
    box *b = ctx;
    b->x[k] = wrap(b->x[k], b->L);
}

/* FIRE minimization of the overlap energy; returns it. */
static double relax(box *b, double ftol)
{
    sbc_fire_problem p;
    p.n = (size_t)b->dim * (size_t)b->n;
    p.x = b->x;
    p.v = b->v;
    p.f = b->f;
    p.forces = forces_cb;
    p.place = wrap_cb;
    p.ctx = b;
    p.dt_max = 1.0;
    b->listed = 0; /* the box may have been put back (L and x) since */
    return sbc_fire_minimize(&p, ftol, 20000);
}

static void scale_box(box *b, double L)
{
    int k;
    for (k = 0; k < b->dim * b->n; ++k)
        b->x[k] *= L / b->L;
    b->L = L;
    b->listed = 0;
}

/* Whether a particle other than `corner`, its centre taken relative to the
   corner's, comes within its radius of every face of the box: it would cross
   the faces at the corner as the corner particle does. */
static int crosses_corner(const box *keep, const double *r, int corner)
{
    int k, a;
    for (k = 0; k < keep->n; ++k) {
        int all = k != corner;
        for (a = 0; a < keep->dim && all; ++a) {
            const double x = wrap(keep->x[keep->dim * k + a] - keep->x[keep->dim * corner + a], keep->L);
            all = x < r[k] || x > keep->L - r[k];
        }
        if (all)
            return 1;
    }
    return 0;
}

/* the generated packing: m particles, centres x [dim m], radii r [m], the
   periodic box [0, L]^dim */
typedef struct generated {
    int m;
    double *x, *r, L;
} generated;

/* free (the ball's) volume of a particle of radius r in dim dimensions: pi
   r^2 or 4/3 pi r^3 */
static double measure(int dim, double r) { return dim == 3 ? 4.0 / 3.0 * M_PI * r * r * r : M_PI * r * r; }

static sbc_status generate(const sbc_generate_def *def, int dim, generated *p, sbc_generate_info *info,
                           sbc_error *err)
{
    unsigned long long s = def->seed * 0x9E3779B97F4A7C15ULL + 1;
    box b, keep;
    double area = 0.0, shrink = 0.01, ftol = 1e-12 * def->r_min, jam = 1e-10 * def->r_min, ecut;
    int k, n = def->n, corner, cap, m = 0, shifts = 1;
    const size_t dn = (size_t)dim * (size_t)n;
    struct timespec t0, shown;
    memset(p, 0, sizeof *p);
    if (n < 4 || n > 100000)
        return sbc_fail(err, SBC_ERR_INPUT, "generate: %d particles (expected 4 to 100000)", n);
    /* positions are rounded to 2^-50 m (quantize): radii far below a micrometre lose
     * their digits, and the jamming never ends; far above a kilometre neither */
    if (!(def->r_min >= 1e-6 && def->r_min <= 1e3))
        return sbc_fail(err, SBC_ERR_INPUT, "generate: rmin %g m is out of range (expected 1e-6 to 1e3 m)", def->r_min);
    if (!(def->r_min > 0.0) || !(def->polydispersity >= 1.0))
        return sbc_fail(err, SBC_ERR_INPUT, "generate: R_min %g must be > 0 and polydispersity %g >= 1", def->r_min,
                        def->polydispersity);
    b.dim = keep.dim = dim;
    b.n = keep.n = n;
    b.x = malloc(sizeof(double) * dn);
    b.r = malloc(sizeof(double) * (size_t)n);
    b.v = malloc(sizeof(double) * dn);
    b.f = malloc(sizeof(double) * dn);
    b.cells = (int)(dim == 3 ? cbrt((double)n) : sqrt((double)n)) + 1;
    b.head = malloc(sizeof(int) * (size_t)(dim == 3 ? b.cells * b.cells * b.cells : b.cells * b.cells));
    b.next = malloc(sizeof(int) * (size_t)n);
    b.cell = malloc(sizeof(int) * (size_t)n);
    b.x0 = malloc(sizeof(double) * dn);
    b.pair = NULL;
    b.npair = b.cap = b.listed = 0;
    keep.x = malloc(sizeof(double) * dn);
    if (!b.x || !b.r || !b.v || !b.f || !b.head || !b.next || !b.cell || !b.x0 || !keep.x) {
        box_free(&b, &keep);
        return sbc_fail(err, SBC_ERR_NOMEM, "generate: out of memory");
    }
    b.rmax = 0.0;
    b.skin = 0.0;
    for (k = 0; k < n; ++k) {
        b.r[k] = def->r_min * (1.0 + (def->polydispersity - 1.0) * sbc_uniform(&s));
        area += measure(dim, b.r[k]);
        if (b.r[k] > b.rmax) b.rmax = b.r[k];
    }
    b.skin = SKIN * b.rmax;
    /* start at a packing fraction of 0.5 (discs) or 0.3 (spheres) */
    b.L = dim == 3 ? cbrt(area / 0.3) : sqrt(area / 0.5);
    for (k = 0; k < dim * n; ++k)
        b.x[k] = b.L * sbc_uniform(&s);
    ecut = 0.5 * n * jam * jam;
    relax(&b, ftol);
    memcpy(keep.x, b.x, sizeof(double) * dn);
    keep.L = b.L;
    /* shrink until jammed; halve the step at each jam */
    timespec_get(&t0, TIME_UTC);
    shown = t0;
    while (shrink > 1e-5) {
        if (def->log) {
            struct timespec now;
            timespec_get(&now, TIME_UTC);
            if ((double)(now.tv_sec - shown.tv_sec) + 1e-9 * (double)(now.tv_nsec - shown.tv_nsec) >=
                SBC_GENERATE_PROGRESS) {
                shown = now;
                fprintf(def->log, "  generate: jamming %d %s, box %.6g m, packing fraction %.4f, step %.1e, "
                        "elapsed %.0f s\n", n, dim == 3 ? "spheres" : "discs", b.L,
                        area / (dim == 3 ? b.L * b.L * b.L : b.L * b.L), shrink,
                        (double)(now.tv_sec - t0.tv_sec) + 1e-9 * (double)(now.tv_nsec - t0.tv_nsec));
                fflush(def->log);
            }
        }
        scale_box(&b, b.L * (1.0 - shrink));
        if (relax(&b, ftol) > ecut) {
            memcpy(b.x, keep.x, sizeof(double) * dn);
            b.L = keep.L;
            shrink *= 0.5;
        } else {
            memcpy(keep.x, b.x, sizeof(double) * dn);
            keep.L = b.L;
        }
    }
    /* the jammed state keeps overlaps up to ~1e-10 R_min; stretching the box by
       1e-8 opens them (gaps below 1e-7 R_min), so that the packing is free of
       force: touching, not loaded. A loaded start would leave rattlers ringing
       in an energy Ep ~ 1e-20 kn R^2 that no relaxation criterion can resolve. */
    if (def->strain > 0.0) {
        /* a load-bearing packing: the jammed box compressed by `strain` and its
           overlaps relaxed to force balance (FIRE on the unit-stiffness forces) */
        memcpy(b.x, keep.x, sizeof(double) * dn);
        b.L = keep.L;
        scale_box(&b, b.L * (1.0 - def->strain));
        relax(&b, ftol);
        memcpy(keep.x, b.x, sizeof(double) * dn);
        keep.L = b.L;
    } else {
        scale_box(&keep, keep.L * (1.0 + 1e-8));
    }
    /* reconstruction: particle `corner` at the origin, copies across the faces */
    for (k = 0; k < dim; ++k)
        shifts *= 2;
    cap = shifts * n;
    p->x = malloc(sizeof(double) * (size_t)dim * (size_t)cap);
    p->r = malloc(sizeof(double) * (size_t)cap);
    if (!p->x || !p->r) {
        box_free(&b, &keep);
        free(p->x);
        free(p->r);
        memset(p, 0, sizeof *p);
        return sbc_fail(err, SBC_ERR_NOMEM, "generate: out of memory");
    }
    /* positions and L on a grid of 2^-50 m (~9e-16 m): then x + L and x - L are
       exact, and every copy sits at exactly +-L from its original both ways */
    keep.L = quantize(keep.L);
    /* the corner particle: a particle of radius r crossing the dim faces beside
       a corner particle of radius R_c at the origin has its centre within
       r sqrt(dim) of it, and overlaps it unless r >= R_c / (sqrt(dim) - 1)
       (2.41 R_c in 2D, 1.37 R_c in 3D); that one would be a second corner, which
       no frame takes. Particle 0 when it is large enough (every packing of
       polydispersity up to 2 in 2D) or no particle crosses its corner, else the
       largest, which no particle can cross. */
    corner = 0;
    if (b.rmax > (1.0 + sqrt((double)dim)) * b.r[0] || crosses_corner(&keep, b.r, 0))
        for (k = 1; k < n; ++k)
            if (b.r[k] > b.r[corner])
                corner = k;
    for (k = 0; k < n; ++k) {
        const double r = b.r[k];
        double x[3] = {0.0, 0.0, 0.0};
        int a, sh[3];
        for (a = 0; a < dim; ++a) {
            x[a] = quantize(wrap(keep.x[dim * k + a] - keep.x[dim * corner + a], keep.L));
            if (x[a] >= keep.L) x[a] = 0.0;
        }
        if (k == corner)
            x[0] = x[1] = x[2] = 0.0;
        for (sh[0] = -1; sh[0] <= 1; ++sh[0]) {
            for (sh[1] = -1; sh[1] <= 1; ++sh[1]) {
                for (sh[2] = dim == 3 ? -1 : 0; sh[2] <= (dim == 3 ? 1 : 0); ++sh[2]) {
                    double c[3];
                    int keep_it = 1, moved = 0;
                    for (a = 0; a < dim; ++a) {
                        c[a] = x[a] + sh[a] * keep.L;
                        moved |= sh[a] != 0;
                        /* keep the image if its particle meets the closed box [0, L]^dim */
                        keep_it &= !(c[a] + r < 0.0 || c[a] - r > keep.L);
                    }
                    for (a = 0; a < dim && keep_it; ++a) {
                        if (moved && !(c[a] >= -r && c[a] <= keep.L + r))
                            keep_it = 0;
                        if (sh[a] != 0 && !(x[a] - r < 0.0 || x[a] + r > keep.L))
                            keep_it = 0;
                    }
                    if (!keep_it)
                        continue;
                    for (a = 0; a < dim; ++a)
                        p->x[dim * m + a] = c[a];
                    p->r[m++] = r;
                }
            }
        }
    }
    p->m = m;
    p->L = keep.L;
    if (info) {
        double inside = 0.0, contacts = 0.0;
        int i, j, counted = 0;
        /* the copies across the faces carry exactly the parts of the particles
           that stick out of the box, so the measure inside is that of the n0 */
        for (k = 0; k < n; ++k)
            inside += measure(dim, b.r[k]);
        for (i = 0; i < n; ++i) {
            int c = 0;
            for (j = 0; j < n; ++j) {
                double d2 = 0.0;
                int a;
                if (j == i) continue;
                for (a = 0; a < dim; ++a) {
                    const double d = image(keep.x[dim * j + a] - keep.x[dim * i + a], keep.L);
                    d2 = a ? d2 + d * d : d * d;
                }
                if (sqrt(d2) < b.r[i] + b.r[j] + 1e-6 * def->r_min) ++c;
            }
            contacts += c;
            ++counted;
        }
        info->n0 = n;
        info->n = m;
        info->L = keep.L;
        info->fraction = inside / (dim == 3 ? keep.L * keep.L * keep.L : keep.L * keep.L);
        info->coordination = counted ? contacts / counted : 0.0;
    }
    box_free(&b, &keep);
    return SBC_OK;
}

sbc_status sbc_generate_periodic(const sbc_generate_def *def, sbc_packing *p, sbc_generate_info *info,
                                 sbc_error *err)
{
    generated g;
    sbc_status st;
    memset(p, 0, sizeof *p);
    if ((st = generate(def, 2, &g, info, err)) != SBC_OK)
        return st;
    p->n = g.m;
    p->x = g.x;
    p->r = g.r;
    p->has_box = 1;
    p->box[0] = p->box[2] = 0.0;
    p->box[1] = p->box[3] = g.L;
    return SBC_OK;
}

sbc_status sbc_generate_periodic_3d(const sbc_generate_def *def, sbc_sphere_packing *p, sbc_generate_info *info,
                                    sbc_error *err)
{
    generated g;
    sbc_status st;
    memset(p, 0, sizeof *p);
    if ((st = generate(def, 3, &g, info, err)) != SBC_OK)
        return st;
    p->n = g.m;
    p->x = g.x;
    p->r = g.r;
    p->L = g.L;
    return SBC_OK;
}

void sbc_sphere_packing_free(sbc_sphere_packing *p)
{
    free(p->x);
    free(p->r);
    memset(p, 0, sizeof *p);
}
