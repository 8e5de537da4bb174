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

static double wrap(double a, double L) { return a - L * floor(a / L); }

static double quantize(double a) { return ldexp(nearbyint(ldexp(a, 50)), -50); }

static double image(double d, double L) { return d - L * floor(d / L + 0.5); }

typedef struct box {
    int n;
    double L, rmax, *x, *r, *v, *f;
    int *head, *next, cells; /* periodic cell list, cells^2 heads */
} box;

static double pair_force(box *b, int i, int j)
{
    double dx = image(b->x[2 * j] - b->x[2 * i], b->L), dy = image(b->x[2 * j + 1] - b->x[2 * i + 1], b->L);
    double rs = b->r[i] + b->r[j], d2 = dx * dx + dy * dy, d, ov;
    if (d2 >= rs * rs)
        return 0.0;
    d = sqrt(d2);
    ov = rs - d;
    if (d > 0.0) {
        b->f[2 * i] -= ov * dx / d;
        b->f[2 * i + 1] -= ov * dy / d;
        b->f[2 * j] += ov * dx / d;
        b->f[2 * j + 1] += ov * dy / d;
    }
    return 0.5 * ov * ov;
}

/* Overlap forces (unit stiffness) and energy sum(overlap^2)/2 in the periodic
 * box: a periodic cell list (cells >= 2 rmax wide) when the box holds at least
 * 3 x 3 cells, all pairs otherwise. */
static double forces(box *b)
{
    double e = 0.0;
    int i, j, nc = (int)(b->L / (2.0 * b->rmax));
    memset(b->f, 0, sizeof(double) * 2 * (size_t)b->n);
    if (nc < 3 || nc > b->cells) {
        for (i = 0; i < b->n; ++i)
            for (j = i + 1; j < b->n; ++j)
                e += pair_force(b, i, j);
        return e;
    }
    for (i = 0; i < nc * nc; ++i)
        b->head[i] = -1;
    for (i = 0; i < b->n; ++i) {
        int cx = (int)(b->x[2 * i] / b->L * nc), cy = (int)(b->x[2 * i + 1] / b->L * nc), c;
        if (cx >= nc) cx = nc - 1;
        if (cy >= nc) cy = nc - 1;
        c = cy * nc + cx;
        b->next[i] = b->head[c];
        b->head[c] = i;
    }
    for (i = 0; i < b->n; ++i) {
        int cx = (int)(b->x[2 * i] / b->L * nc), cy = (int)(b->x[2 * i + 1] / b->L * nc), ox, oy;
        if (cx >= nc) cx = nc - 1;
        if (cy >= nc) cy = nc - 1;
        for (oy = -1; oy <= 1; ++oy)
            for (ox = -1; ox <= 1; ++ox)
                for (j = b->head[((cy + oy + nc) % nc) * nc + (cx + ox + nc) % nc]; j >= 0; j = b->next[j])
                    if (j > i)
                        e += pair_force(b, i, j);
    }
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
    p.n = 2 * (size_t)b->n;
    p.x = b->x;
    p.v = b->v;
    p.f = b->f;
    p.forces = forces_cb;
    p.place = wrap_cb;
    p.ctx = b;
    p.dt_max = 1.0;
    return sbc_fire_minimize(&p, ftol, 20000);
}

static void scale_box(box *b, double L)
{
    int k;
    for (k = 0; k < 2 * b->n; ++k)
        b->x[k] *= L / b->L;
    b->L = L;
}

sbc_status sbc_generate_periodic(const sbc_generate_def *def, sbc_packing *p, sbc_generate_info *info,
                                 sbc_error *err)
{
    unsigned long long s = def->seed * 0x9E3779B97F4A7C15ULL + 1;
    box b, keep;
    double area = 0.0, shrink = 0.01, ftol = 1e-12 * def->r_min, jam = 1e-10 * def->r_min, ecut;
    int k, n = def->n, corner, cap, m = 0;
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
    b.n = keep.n = n;
    b.x = malloc(sizeof(double) * 2 * (size_t)n);
    b.r = malloc(sizeof(double) * (size_t)n);
    b.v = malloc(sizeof(double) * 2 * (size_t)n);
    b.f = malloc(sizeof(double) * 2 * (size_t)n);
    b.cells = (int)sqrt((double)n) + 1;
    b.head = malloc(sizeof(int) * (size_t)(b.cells * b.cells));
    b.next = malloc(sizeof(int) * (size_t)n);
    keep.x = malloc(sizeof(double) * 2 * (size_t)n);
    if (!b.x || !b.r || !b.v || !b.f || !b.head || !b.next || !keep.x) {
        free(b.x); free(b.r); free(b.v); free(b.f); free(b.head); free(b.next); free(keep.x);
        return sbc_fail(err, SBC_ERR_NOMEM, "generate: out of memory");
    }
    b.rmax = 0.0;
    for (k = 0; k < n; ++k) {
        b.r[k] = def->r_min * (1.0 + (def->polydispersity - 1.0) * sbc_uniform(&s));
        area += M_PI * b.r[k] * b.r[k];
        if (b.r[k] > b.rmax) b.rmax = b.r[k];
    }
    b.L = sqrt(area / 0.5); /* start at a packing fraction of 0.5 */
    for (k = 0; k < 2 * n; ++k)
        b.x[k] = b.L * sbc_uniform(&s);
    ecut = 0.5 * n * jam * jam;
    relax(&b, ftol);
    memcpy(keep.x, b.x, sizeof(double) * 2 * (size_t)n);
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
                fprintf(def->log, "  generate: jamming %d discs, box %.6g m, packing fraction %.4f, step %.1e, "
                        "elapsed %.0f s\n", n, b.L, area / (b.L * b.L), shrink,
                        (double)(now.tv_sec - t0.tv_sec) + 1e-9 * (double)(now.tv_nsec - t0.tv_nsec));
                fflush(def->log);
            }
        }
        scale_box(&b, b.L * (1.0 - shrink));
        if (relax(&b, ftol) > ecut) {
            memcpy(b.x, keep.x, sizeof(double) * 2 * (size_t)n);
            b.L = keep.L;
            shrink *= 0.5;
        } else {
            memcpy(keep.x, b.x, sizeof(double) * 2 * (size_t)n);
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
        memcpy(b.x, keep.x, sizeof(double) * 2 * (size_t)n);
        b.L = keep.L;
        scale_box(&b, b.L * (1.0 - def->strain));
        relax(&b, ftol);
        memcpy(keep.x, b.x, sizeof(double) * 2 * (size_t)n);
        keep.L = b.L;
    } else {
        scale_box(&keep, keep.L * (1.0 + 1e-8));
    }
    /* reconstruction: particle `corner` at the origin, copies across the edges */
    cap = 4 * n;
    p->x = malloc(sizeof(double) * 2 * (size_t)cap);
    p->r = malloc(sizeof(double) * (size_t)cap);
    if (!p->x || !p->r) {
        free(b.x); free(b.r); free(b.v); free(b.f); free(b.head); free(b.next); free(keep.x);
        sbc_packing_free(p);
        return sbc_fail(err, SBC_ERR_NOMEM, "generate: out of memory");
    }
    /* positions and L on a grid of 2^-50 m (~9e-16 m): then x + L and x - L are
       exact, and every copy sits at exactly +-L from its original both ways */
    keep.L = quantize(keep.L);
    /* the corner particle: a disc of radius r crossing both edges beside a
       corner disc of radius R_c at the origin would have its centre within
       r sqrt(2) of it, and overlap it unless r > (1 + sqrt(2)) R_c; that disc
       would be a second corner. Disc 0 when it is large enough (every packing
       of polydispersity up to 2), else the largest disc. */
    corner = 0;
    if (b.rmax > (1.0 + sqrt(2.0)) * b.r[0])
        for (k = 1; k < n; ++k)
            if (b.r[k] > b.r[corner])
                corner = k;
    for (k = 0; k < n; ++k) {
        double x = quantize(wrap(keep.x[2 * k] - keep.x[2 * corner], keep.L));
        double y = quantize(wrap(keep.x[2 * k + 1] - keep.x[2 * corner + 1], keep.L)), r = b.r[k];
        if (x >= keep.L) x = 0.0;
        if (y >= keep.L) y = 0.0;
        int sx, sy;
        if (k == corner)
            x = y = 0.0;
        for (sx = -1; sx <= 1; ++sx) {
            for (sy = -1; sy <= 1; ++sy) {
                double cx = x + sx * keep.L, cy = y + sy * keep.L;
                /* keep the image if its disc meets the closed square [0, L]^2 */
                if (cx + r < 0.0 || cx - r > keep.L || cy + r < 0.0 || cy - r > keep.L)
                    continue;
                if ((sx != 0 || sy != 0) && !(cx >= -r && cx <= keep.L + r && cy >= -r && cy <= keep.L + r))
                    continue;
                if (sx != 0 && !(x - r < 0.0 || x + r > keep.L))
                    continue;
                if (sy != 0 && !(y - r < 0.0 || y + r > keep.L))
                    continue;
                p->x[2 * m] = cx;
                p->x[2 * m + 1] = cy;
                p->r[m++] = r;
            }
        }
    }
    p->n = m;
    p->has_box = 1;
    p->box[0] = p->box[2] = 0.0;
    p->box[1] = p->box[3] = keep.L;
    if (info) {
        double inside = 0.0, contacts = 0.0;
        int i, j, counted = 0;
        /* the copies across the edges carry exactly the parts of the discs that
           stick out of the square, so the area inside is that of the n0 discs */
        for (k = 0; k < n; ++k)
            inside += M_PI * b.r[k] * b.r[k];
        for (i = 0; i < n; ++i) {
            int c = 0;
            for (j = 0; j < n; ++j) {
                double dx, dy;
                if (j == i) continue;
                dx = image(keep.x[2 * j] - keep.x[2 * i], keep.L);
                dy = image(keep.x[2 * j + 1] - keep.x[2 * i + 1], keep.L);
                if (sqrt(dx * dx + dy * dy) < b.r[i] + b.r[j] + 1e-6 * def->r_min) ++c;
            }
            contacts += c;
            ++counted;
        }
        info->n0 = n;
        info->n = m;
        info->L = keep.L;
        info->fraction = inside / (keep.L * keep.L);
        info->coordination = counted ? contacts / counted : 0.0;
    }
    free(b.x); free(b.r); free(b.v); free(b.f); free(b.head); free(b.next); free(keep.x);
    return SBC_OK;
}
