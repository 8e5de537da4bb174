/* Irregular polydisperse periodic packings: jamming by box shrinking with FIRE
 * overlap minimization (or by one compression under pressure, the box free),
 * then the periodic reconstruction of Sect. 4.2. */
#include "sbc/embedded/generate.h"
#include "fire.h"
#include "jam_box.h"

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
    d.protocol = SBC_GENERATE_SHRINK;
    d.log = NULL;
    return d;
}

static double quantize(double a) { return ldexp(nearbyint(ldexp(a, 50)), -50); }

static void box_free(sbc_jam_box *b, sbc_jam_box *keep)
{
    free(b->x); free(b->r); free(b->v); free(b->f); free(b->head); free(b->next); free(b->cell); free(b->x0);
    free(b->pair); free(keep->x);
}

/* a progress line every SBC_GENERATE_PROGRESS seconds of a long generation:
   the stage, the box, the packing fraction, the stage's figure */
static void progress(const sbc_generate_def *def, const sbc_jam_box *b, double area, const struct timespec *t0,
                     struct timespec *shown, const char *stage, const char *figure, double value)
{
    struct timespec now;
    if (!def->log)
        return;
    timespec_get(&now, TIME_UTC);
    if ((double)(now.tv_sec - shown->tv_sec) + 1e-9 * (double)(now.tv_nsec - shown->tv_nsec) < SBC_GENERATE_PROGRESS)
        return;
    *shown = now;
    fprintf(def->log, "  generate: %s %d %s, box %.6g m, packing fraction %.4f, %s %.1e, elapsed %.0f s\n", stage, b->n,
            b->dim == 3 ? "spheres" : "discs", b->L, area / (b->dim == 3 ? b->L * b->L * b->L : b->L * b->L), figure,
            value, (double)(now.tv_sec - t0->tv_sec) + 1e-9 * (double)(now.tv_nsec - t0->tv_nsec));
    fflush(def->log);
}

static void widest_overlap(sbc_jam_box *b, int i, int j, void *widest)
{
    double d2 = 0.0, rs = b->r[i] + b->r[j], d;
    int k;
    for (k = 0; k < b->dim; ++k) {
        const double dx = sbc_jam_image(b->x[b->dim * j + k] - b->x[b->dim * i + k], b->L);
        d2 += dx * dx;
    }
    d = sqrt(d2);
    if (d < rs && d > 0.0 && (rs - d) / d > *(double *)widest)
        *(double *)widest = (rs - d) / d;
}

/* stages of the pressure protocol: overlaps of about omega R_min, omega from
   1e-2 down to 1e-4 by tenths, each stage at most this many FIRE iterations
   (each to 1e-3 omega R_min, which near jamming it does not reach: the packing
   creeps); then the strained box relaxed by at most the last figure */
#define PRESSURE_FIRST 1e-2
#define PRESSURE_LAST 1e-4
#define PRESSURE_ITERATIONS 2000
#define PRESSURE_FINAL_ITERATIONS 10000

/* The pressure protocol: the enthalpy E + P V (unit stiffness) minimized over
 * the centres and the box, each stage from the last at a tenth of its pressure
 * (P = omega R_min^(2 - dim)), so that the packing is compressed once and then
 * let expand towards the jamming point. Returns that point's box, extrapolated
 * from the last two stages (near jamming P grows linearly with L_J - L). keep
 * gets the last stage's packing with its box stretched affinely by the largest
 * overlap over its distance (and 1e-9): touching, free of force; that box lies
 * above L_J by what the stages left unrelaxed, and bounds it. b keeps the last
 * stage. */
static double jam_under_pressure(sbc_jam_box *b, sbc_jam_box *keep, const sbc_generate_def *def, double area)
{
    const size_t dn = (size_t)b->dim * (size_t)b->n;
    struct timespec t0, shown;
    double omega, rmean = 0.0, widest = 0.0, P = 0.0, P_before = 0.0, L_before = 0.0;
    int k;
    for (k = 0; k < b->n; ++k)
        rmean += b->r[k] / b->n;
    sbc_jam_sort_by_cell(b, keep->x);
    b->L_start = b->L;
    b->c = 2.0 * rmean * sqrt((double)b->n);
    timespec_get(&t0, TIME_UTC);
    shown = t0;
    for (omega = PRESSURE_FIRST; omega > 0.5 * PRESSURE_LAST; omega *= 0.1) {
        P_before = P;
        L_before = b->L;
        P = omega * pow(def->r_min, 2 - b->dim);
        sbc_jam_relax_under(b, P, 1e-3 * omega * def->r_min, PRESSURE_ITERATIONS);
        progress(def, b, area, &t0, &shown, "compressing", "overlap / R_min", omega);
    }
    sbc_jam_wrap_all(b);
    sbc_jam_visit_pairs(b, (int)(b->L / (2.0 * b->rmax + b->skin)), NULL, widest_overlap, &widest);
    memcpy(keep->x, b->x, sizeof(double) * dn);
    keep->L = b->L;
    sbc_jam_scale(keep, keep->L * (1.0 + widest) * (1.0 + 1e-9));
    /* between the last stage's box and the touching one (a few particles jam erratically) */
    return fmin(fmax(b->L + (b->L - L_before) * P / (P_before - P), b->L), keep->L);
}

/* Whether a particle other than `corner`, its centre taken relative to the
   corner's, comes within its radius of every face of the box: it would cross
   the faces at the corner as the corner particle does. */
static int crosses_corner(const sbc_jam_box *keep, const double *r, int corner)
{
    int k, a;
    for (k = 0; k < keep->n; ++k) {
        int all = k != corner;
        for (a = 0; a < keep->dim && all; ++a) {
            const double x = sbc_jam_wrap(keep->x[keep->dim * k + a] - keep->x[keep->dim * corner + a], keep->L);
            all = x < r[k] || x > keep->L - r[k];
        }
        if (all)
            return 1;
    }
    return 0;
}

typedef struct touching {
    double gap;
    long pairs, overlapping;
    double overlap; /* the sum of the overlaps */
} touching;

static void count_touching(sbc_jam_box *b, int i, int j, void *ctx)
{
    touching *t = ctx;
    double d2 = 0.0;
    int k;
    for (k = 0; k < b->dim; ++k) {
        const double d = sbc_jam_image(b->x[b->dim * j + k] - b->x[b->dim * i + k], b->L);
        d2 = k ? d2 + d * d : d * d;
    }
    t->pairs += sqrt(d2) < b->r[i] + b->r[j] + t->gap;
    if (sqrt(d2) < b->r[i] + b->r[j]) {
        ++t->overlapping;
        t->overlap += b->r[i] + b->r[j] - sqrt(d2);
    }
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
    sbc_jam_box b, keep;
    double area = 0.0, shrink = 0.01, ftol = 1e-12 * def->r_min, jam = 1e-10 * def->r_min, ecut, L_jammed = 0.0;
    int k, n = def->n, corner, cap, m = 0, shifts = 1;
    const size_t dn = (size_t)dim * (size_t)n;
    struct timespec t0, shown;
    memset(p, 0, sizeof *p);
    if (n < 4 || n > SBC_GENERATE_MAX)
        return sbc_fail(err, SBC_ERR_INPUT, "generate: %d particles (expected 4 to %d)", n, SBC_GENERATE_MAX);
    /* positions are rounded to 2^-50 m (quantize): radii far below a micrometre lose
     * their digits, and the jamming never ends; far above a kilometre neither */
    if (!(def->r_min >= 1e-6 && def->r_min <= 1e3))
        return sbc_fail(err, SBC_ERR_INPUT, "generate: rmin %g m is out of range (expected 1e-6 to 1e3 m)", def->r_min);
    if (!(def->r_min > 0.0) || !(def->polydispersity >= 1.0))
        return sbc_fail(err, SBC_ERR_INPUT, "generate: R_min %g must be > 0 and polydispersity %g >= 1", def->r_min,
                        def->polydispersity);
    b.dim = keep.dim = dim;
    b.n = keep.n = n;
    b.x = malloc(sizeof(double) * (dn + 1)); /* x[dn], v[dn], f[dn]: the box's, in the pressure protocol */
    b.r = malloc(sizeof(double) * (size_t)n);
    b.v = malloc(sizeof(double) * (dn + 1));
    b.f = malloc(sizeof(double) * (dn + 1));
    b.cells = (int)(dim == 3 ? cbrt((double)n) : sqrt((double)n)) + 1;
    b.head = malloc(sizeof(int) * (size_t)(dim == 3 ? b.cells * b.cells * b.cells : b.cells * b.cells));
    b.next = malloc(sizeof(int) * (size_t)n);
    b.cell = malloc(sizeof(int) * (size_t)n);
    b.x0 = malloc(sizeof(double) * dn);
    b.pair = NULL;
    b.npair = b.cap = b.listed = 0;
    b.pressure = def->protocol == SBC_GENERATE_PRESSURE;
    b.box_free = 0;
    b.P = b.c = b.L_start = b.L_listed = b.virial = 0.0;
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
    b.skin = SBC_JAM_SKIN * b.rmax;
    /* start at a packing fraction of 0.5 (discs) or 0.3 (spheres) */
    b.L = dim == 3 ? cbrt(area / 0.3) : sqrt(area / 0.5);
    for (k = 0; k < dim * n; ++k)
        b.x[k] = b.L * sbc_uniform(&s);
    if (b.pressure) {
        L_jammed = jam_under_pressure(&b, &keep, def, area);
    } else {
        ecut = 0.5 * n * jam * jam;
        sbc_jam_relax(&b, ftol, 20000);
        memcpy(keep.x, b.x, sizeof(double) * dn);
        keep.L = b.L;
        /* shrink until jammed; halve the step at each jam */
        timespec_get(&t0, TIME_UTC);
        shown = t0;
        while (shrink > 1e-5) {
            progress(def, &b, area, &t0, &shown, "jamming", "step", shrink);
            sbc_jam_scale(&b, b.L * (1.0 - shrink));
            if (sbc_jam_relax(&b, ftol, 20000) > ecut) {
                memcpy(b.x, keep.x, sizeof(double) * dn);
                b.L = keep.L;
                shrink *= 0.5;
            } else {
                memcpy(keep.x, b.x, sizeof(double) * dn);
                keep.L = b.L;
            }
        }
    }
    /* the jammed state keeps overlaps up to ~1e-10 R_min; stretching the box by
       1e-8 opens them (gaps below 1e-7 R_min), so that the packing is free of
       force: touching, not loaded. A loaded start would leave rattlers ringing
       in an energy Ep ~ 1e-20 kn R^2 that no relaxation criterion can resolve. */
    if (def->strain > 0.0) {
        /* a load-bearing packing: the jammed box compressed by `strain` and its
           overlaps relaxed to force balance (FIRE on the unit-stiffness forces);
           the pressure protocol's from its last stage and extrapolated L_J */
        if (!b.pressure) {
            memcpy(b.x, keep.x, sizeof(double) * dn);
            b.L = keep.L;
        }
        sbc_jam_scale(&b, (b.pressure ? L_jammed : b.L) * (1.0 - def->strain));
        sbc_jam_relax(&b, ftol, b.pressure ? PRESSURE_FINAL_ITERATIONS : 20000);
        sbc_jam_wrap_all(&b);
        memcpy(keep.x, b.x, sizeof(double) * dn);
        keep.L = b.L;
    } else if (!b.pressure) {
        sbc_jam_scale(&keep, keep.L * (1.0 + 1e-8));
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
            x[a] = quantize(sbc_jam_wrap(keep.x[dim * k + a] - keep.x[dim * corner + a], keep.L));
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
        double inside = 0.0;
        touching t;
        /* the copies across the faces carry exactly the parts of the particles
           that stick out of the box, so the measure inside is that of the n0 */
        for (k = 0; k < n; ++k)
            inside += measure(dim, b.r[k]);
        /* the pairs within 1e-6 R_min of contact, each counted at both ends */
        memcpy(b.x, keep.x, sizeof(double) * dn);
        b.L = keep.L;
        t.gap = 1e-6 * def->r_min;
        t.pairs = t.overlapping = 0;
        t.overlap = 0.0;
        sbc_jam_visit_pairs(&b, (int)(b.L / (2.0 * b.rmax + b.skin)), NULL, count_touching, &t);
        /* the largest net force (unit stiffness: overlaps) over the mean */
        b.listed = 0;
        sbc_jam_forces(&b);
        info->residual = 0.0;
        for (k = 0; k < n && t.overlapping; ++k) {
            double f2 = 0.0;
            int a;
            for (a = 0; a < dim; ++a)
                f2 += b.f[dim * k + a] * b.f[dim * k + a];
            if (sqrt(f2) * (double)t.overlapping / t.overlap > info->residual)
                info->residual = sqrt(f2) * (double)t.overlapping / t.overlap;
        }
        info->n0 = n;
        info->n = m;
        info->L = keep.L;
        info->fraction = inside / (dim == 3 ? keep.L * keep.L * keep.L : keep.L * keep.L);
        info->coordination = 2.0 * (double)t.pairs / n;
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
