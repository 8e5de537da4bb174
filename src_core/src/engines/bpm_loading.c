/* servo_bc: uniaxial test on a bonded specimen (thesis Sect. 4.3). */
#include "sbc/embedded/bpm_loading.h"
#include "sbc/embedded/bpm_packing.h"
#include "sbc/embedded/bpm_stress.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a row of the time series is written only when every value in it is
   finite: the run stops first, naming the step and the value */
static sbc_status series_finite(const char *test, long step, const double *v, int n, sbc_error *err)
{
    int k;
    for (k = 0; k < n; ++k)
        if (!isfinite(v[k]))
            return sbc_fail(err, SBC_ERR_NUMERIC, "%s: step %ld: a value of the time series is %g (column %d); the "
                            "run stops before writing it (check the time step against eq. 48)", test, step, v[k],
                            k + 2);
    return SBC_OK;
}

/* least-squares slope of y against x */
typedef struct fit {
    double n, sx, sy, sxx, sxy;
} fit;

static void fit_add(fit *f, double x, double y)
{
    f->n += 1.0;
    f->sx += x;
    f->sy += y;
    f->sxx += x * x;
    f->sxy += x * y;
}

static double fit_slope(const fit *f)
{
    double d = f->n * f->sxx - f->sx * f->sx;
    return d != 0.0 ? (f->n * f->sxy - f->sx * f->sy) / d : 0.0;
}

/* mean of coordinate axis over the spheres flagged in mask */
static double mean_coord(const sbc_bpm *e, const unsigned char *mask, unsigned char bit, int axis)
{
    double s = 0.0;
    size_t i, n = 0;
    for (i = 0; i < e->n; ++i)
        if (mask[i] & bit) {
            s += e->x[3 * i + (size_t)axis];
            ++n;
        }
    return n ? s / (double)n : 0.0;
}

enum { LOADED = 1, HELD = 2, YLO = 4, YHI = 8, ZLO = 16, ZHI = 32 };

sbc_status sbc_bpm_uniaxial_run(sbc_bpm *e, const sbc_bpm_uniaxial *test, sbc_bpm_uniaxial_result *res,
                                sbc_error *err)
{
    double ext[6], reach = test->zone * test->rp, xl, xh, w0, h0, outer_y, outer_z;
    unsigned char *zone;
    fit force = {0, 0, 0, 0, 0}, wide = {0, 0, 0, 0, 0}, high = {0, 0, 0, 0, 0};
    long t, every = test->every > 0 ? test->every : (test->steps >= 100 ? test->steps / 100 : 1);
    size_t i;
    sbc_status st = SBC_OK;
    memset(res, 0, sizeof *res);
    if (e->nb == 0)
        return sbc_fail(err, SBC_ERR_INPUT, "uniaxial: the specimen has no bonds (bond the packing first)");
    if (!(test->rp > 0.0) || !(test->zone > 0.0) || test->velocity == 0.0 || test->steps < 2)
        return sbc_fail(err, SBC_ERR_INPUT,
                        "uniaxial: r_p %g, zone %g, velocity %g, steps %ld (expected r_p > 0, zone > 0, a non-zero "
                        "velocity, at least 2 steps)", test->rp, test->zone, test->velocity, test->steps);
    zone = calloc(e->n, 1);
    if (!zone)
        return sbc_fail(err, SBC_ERR_NOMEM, "uniaxial: out of memory");
    sbc_bpm_extent(e, ext);
    for (i = 0; i < e->n; ++i) {
        const double *x = &e->x[3 * i];
        if (x[0] - ext[0] <= reach) zone[i] |= LOADED;
        else if (ext[3] - x[0] <= reach) zone[i] |= HELD;
        if (x[1] - ext[1] <= reach) zone[i] |= YLO;
        if (ext[4] - x[1] <= reach) zone[i] |= YHI;
        if (x[2] - ext[2] <= reach) zone[i] |= ZLO;
        if (ext[5] - x[2] <= reach) zone[i] |= ZHI;
        res->loaded += (zone[i] & LOADED) != 0;
        res->held += (zone[i] & HELD) != 0;
    }
    if (!res->loaded || !res->held) {
        free(zone);
        return sbc_fail(err, SBC_ERR_INPUT, "uniaxial: an end zone of %g r_p holds no sphere", test->zone);
    }
    xl = mean_coord(e, zone, LOADED, 0);
    xh = mean_coord(e, zone, HELD, 0);
    res->L0 = xh - xl;
    /* a specimen one sphere across: its lateral strain over the outer width (bpm_loading.h) */
    outer_y = mean_coord(e, zone, YHI, 1) - mean_coord(e, zone, YLO, 1) < test->rp ? 2.0 * test->rp : 0.0;
    outer_z = mean_coord(e, zone, ZHI, 2) - mean_coord(e, zone, ZLO, 2) < test->rp ? 2.0 * test->rp : 0.0;
    res->w0 = w0 = mean_coord(e, zone, YHI, 1) - mean_coord(e, zone, YLO, 1) + outer_y;
    res->h0 = h0 = mean_coord(e, zone, ZHI, 2) - mean_coord(e, zone, ZLO, 2) + outer_z;
    res->A = (ext[4] - ext[1]) * (ext[5] - ext[2]);
    for (i = 0; i < e->n; ++i) { /* the velocity ramp; the loaded end moves to -x in tension */
        double ramp = (xh - e->x[3 * i]) / res->L0, v0 = e->v[3 * i];
        e->v[3 * i] = -test->velocity * (ramp < 0.0 ? 0.0 : ramp > 1.0 ? 1.0 : ramp);
        /* the ramp's kinetic energy is given to the specimen: external work (eq. 52) */
        e->w_ext += 0.5 * e->m[i] * (e->v[3 * i] * e->v[3 * i] - v0 * v0);
        if (zone[i] & (LOADED | HELD)) {
            e->fix[i] |= 1u;
            e->vfix[6 * i] = zone[i] & LOADED ? -test->velocity : 0.0;
        }
    }
    for (t = 1; t <= test->steps; ++t) {
        if ((st = sbc_bpm_step(e, err)) != SBC_OK)
            break;
        if (t % every == 0 || t == test->steps) {
            double fx = 0.0, dl = xh - mean_coord(e, zone, LOADED, 0) - res->L0;
            double ey = (mean_coord(e, zone, YHI, 1) - mean_coord(e, zone, YLO, 1) + outer_y - w0) / w0;
            double ez = (mean_coord(e, zone, ZHI, 2) - mean_coord(e, zone, ZLO, 2) + outer_z - h0) / h0;
            sbc_bpm_energy en = sbc_bpm_energies(e);
            for (i = 0; i < e->n; ++i)
                if (zone[i] & LOADED)
                    fx -= e->reaction[6 * i];
            if (2 * t > test->steps) {
                fit_add(&force, dl, fx);
                fit_add(&wide, dl / res->L0, ey);
                fit_add(&high, dl / res->L0, ez);
                if (en.balance > res->balance)
                    res->balance = en.balance;
            }
            res->force = fx;
            res->dL = dl;
            if ((st = series_finite("uniaxial", t, (const double[]){dl, fx, ey, ez, en.kinetic, en.strain,
                                    en.dissipated, en.external}, 8, err)) != SBC_OK)
                break;
            if (test->series)
                fprintf(test->series, "%ld,%.10e,%.10e,%.10e,%.10e,%.6e,%.6e,%.6e,%.6e\n", t, dl, fx, ey, ez,
                        en.kinetic, en.strain, en.dissipated, en.external);
        }
    }
    free(zone);
    if (st != SBC_OK)
        return st;
    if ((st = sbc_bpm_rve_stress(e, NULL, (ext[3] - ext[0]) * res->A, res->sigma_rve, err)) != SBC_OK)
        return st;
    res->sigma_load = res->force / res->A;
    res->E = fit_slope(&force) * res->L0 / res->A; /* eq. 64 */
    res->nu_xy = -fit_slope(&wide);                /* eq. 65 */
    res->nu_xz = -fit_slope(&high);
    return SBC_OK;
}

/* ---- three-point flexural test (thesis Sect. 4.4) ------------------------- */

enum { PIN = 1, ROLLER = 2, TOP = 4, BOTTOM = 8 };

/* mean downward displacement of the spheres flagged TOP or BOTTOM */
static double mean_drop(const sbc_bpm *e, const unsigned char *zone, const double *z0)
{
    double s = 0.0;
    size_t i, n = 0;
    for (i = 0; i < e->n; ++i)
        if (zone[i] & (TOP | BOTTOM)) {
            s += z0[i] - e->x[3 * i + 2];
            ++n;
        }
    return n ? s / (double)n : 0.0;
}

sbc_status sbc_bpm_bending_run(sbc_bpm *e, const sbc_bpm_bending *test, sbc_bpm_bending_result *res,
                               sbc_error *err)
{
    double ext[6], reach = test->zone * test->rp, mid, w, h, xlo = 0.0, xhi = 0.0, xpin = 0.0, xrol = 0.0;
    double *z0, lo_swing = 0.0, hi_swing = 0.0, sum_tail = 0.0, fs = 10.0 / 9.0, F = test->force, Le, b, term;
    long tail = 0;
    unsigned char *zone;
    long t, every = test->every > 0 ? test->every : (test->steps >= 100 ? test->steps / 100 : 1);
    size_t i, npin = 0, nrol = 0, first = 1;
    sbc_status st = SBC_OK;
    memset(res, 0, sizeof *res);
    if (e->nb == 0)
        return sbc_fail(err, SBC_ERR_INPUT, "bending: the specimen has no bonds (bond the packing first)");
    if (!(test->rp > 0.0) || !(test->zone > 0.0) || test->ramp < 1 || test->steps < test->ramp ||
        !(test->nu > -1.0 && test->nu < 0.5))
        return sbc_fail(err, SBC_ERR_INPUT,
                        "bending: r_p %g, zone %g, ramp %ld, steps %ld, nu %g (expected r_p > 0, zone > 0, "
                        "1 <= ramp <= steps, -1 < nu < 0.5)", test->rp, test->zone, test->ramp, test->steps, test->nu);
    zone = calloc(e->n, 1);
    z0 = malloc(e->n * sizeof *z0);
    if (!zone || !z0) {
        free(zone);
        free(z0);
        return sbc_fail(err, SBC_ERR_NOMEM, "bending: out of memory");
    }
    sbc_bpm_extent(e, ext);
    mid = 0.5 * (ext[0] + ext[3]);
    for (i = 0; i < e->n; ++i) {
        const double *x = &e->x[3 * i];
        int near_mid = fabs(x[0] - mid) <= reach;
        z0[i] = x[2];
        if (x[2] - ext[2] <= reach) {
            if (x[0] - ext[0] <= reach) { zone[i] |= PIN; xpin += x[0]; ++npin; }
            else if (ext[3] - x[0] <= reach) { zone[i] |= ROLLER; xrol += x[0]; ++nrol; }
            else if (near_mid) zone[i] |= BOTTOM;
        }
        if (near_mid && ext[5] - x[2] <= reach) {
            zone[i] |= TOP;
            ++res->loaded;
            if (first || x[0] < xlo) xlo = x[0];
            if (first || x[0] > xhi) xhi = x[0];
            first = 0;
        }
    }
    res->supports = npin + nrol;
    if (!npin || !nrol || !res->loaded) {
        free(zone);
        free(z0);
        return sbc_fail(err, SBC_ERR_INPUT, "bending: a zone of %g r_p finds %zu pinned, %zu sliding and %zu loaded "
                        "spheres (expected at least one of each)", test->zone, npin, nrol, res->loaded);
    }
    for (i = 0; i < e->n; ++i) {
        if (zone[i] & PIN) e->fix[i] |= 1u | 2u | 4u | 8u | 32u;
        if (zone[i] & ROLLER) e->fix[i] |= 2u | 4u | 8u | 32u;
        e->vfix[6 * i] = e->vfix[6 * i + 1] = e->vfix[6 * i + 2] = 0.0;
        e->vfix[6 * i + 3] = e->vfix[6 * i + 5] = 0.0;
    }
    res->Le = Le = xrol / (double)nrol - xpin / (double)npin;
    res->b = b = xhi - xlo;
    w = ext[4] - ext[1];
    h = ext[5] - ext[2];
    res->I = w * h * h * h / 12.0;
    res->A = w * h;
    for (t = 1; t <= test->steps; ++t) {
        double ramp = t < test->ramp ? (double)t / (double)test->ramp : 1.0;
        for (i = 0; i < e->n; ++i)
            if (zone[i] & TOP)
                e->fext[6 * i + 2] = -F * ramp / (double)res->loaded;
        if ((st = sbc_bpm_step(e, err)) != SBC_OK)
            break;
        if (10 * t > 9 * test->steps) { /* the last tenth: mean and swing */
            double d = mean_drop(e, zone, z0);
            if (tail == 0 || d < lo_swing) lo_swing = d;
            if (tail == 0 || d > hi_swing) hi_swing = d;
            sum_tail += d;
            ++tail;
        }
        if (t % every == 0 || t == test->steps) {
            sbc_bpm_energy en = sbc_bpm_energies(e);
            double d = mean_drop(e, zone, z0);
            if (t >= test->ramp && en.balance > res->balance)
                res->balance = en.balance;
            if ((st = series_finite("bending", t, (const double[]){F * ramp, d, en.kinetic, en.strain, en.dissipated,
                                    en.external}, 6, err)) != SBC_OK)
                break;
            if (test->series)
                fprintf(test->series, "%ld,%.10e,%.10e,%.6e,%.6e,%.6e,%.6e\n", t, F * ramp, d, en.kinetic,
                        en.strain, en.dissipated, en.external);
        }
    }
    free(zone);
    free(z0);
    if (st != SBC_OK)
        return st;
    res->delta = sum_tail / (double)tail;
    res->swing = hi_swing - lo_swing;
    term = fs * (1.0 + test->nu) / res->A;
    res->Ef_point = F / (2.0 * res->delta) * (Le * Le * Le / (24.0 * res->I) + Le * term); /* eq. 67 */
    res->Ef_band = F / (2.0 * res->delta) *
                   ((8.0 * Le * Le * Le - 4.0 * b * b * Le + b * b * b) / (192.0 * res->I) + (Le - b) * term); /* eq. 69 */
    return SBC_OK;
}
