/* servo_bc: lattice packings of equal spheres (thesis Sect. 4.1). */
#include "sbc/embedded/bpm_packing.h"
#include "sbc/packing.h"

#include <math.h>

/* how many points spaced s fit in [0, L] with a margin r on each side; more
 * than SBC_PACKING_MAX is reported as SBC_PACKING_MAX + 1 (never cast) */
static long fit(double L, double r, double s)
{
    double room = L - 2.0 * r, n;
    if (room < -1e-12 * L)
        return 0;
    n = floor(room / s + 1e-9) + 1.0;
    return n > (double)SBC_PACKING_MAX ? SBC_PACKING_MAX + 1 : (long)n;
}

sbc_status sbc_bpm_pack_lattice(sbc_bpm *e, sbc_bpm_lattice lattice, const double box[3], double rp, double rho,
                                double extent[6], sbc_error *err)
{
    double sx = 2.0 * rp, sy = lattice == SBC_PACK_HCP ? sqrt(3.0) * rp : 2.0 * rp;
    double sz = lattice == SBC_PACK_HCP ? 2.0 * sqrt(2.0 / 3.0) * rp : 2.0 * rp;
    double shift_y = lattice == SBC_PACK_HCP ? rp / sqrt(3.0) : 0.0; /* B layers over the hollows */
    long nx, ny, nz, i, j, k;
    if (!(rp > 0.0) || !(box[0] > 0.0) || !(box[1] > 0.0) || !(box[2] > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "packing: radius %g and box %g x %g x %g (expected positive values)", rp,
                        box[0], box[1], box[2]);
    nz = fit(box[2], rp, sz);
    ny = fit(box[1] - shift_y, rp, sy);
    /* as many spheres per row as the cubic lattice; the shifted hcp rows
     * stick out by r_p (Table 2: 25 per row, 0.255 m long, in a 0.25 m box) */
    nx = fit(box[0], rp, sx);
    if (nx < 1 || ny < 1 || nz < 1)
        return sbc_fail(err, SBC_ERR_INPUT, "packing: no sphere of radius %g fits in the box %g x %g x %g", rp,
                        box[0], box[1], box[2]);
    if ((double)nx * (double)ny * (double)nz > (double)SBC_PACKING_MAX)
        return sbc_fail(err, SBC_ERR_INPUT, "packing: %g spheres of radius %g in the box %g x %g x %g exceed the limit "
                        "of %ld", (double)nx * (double)ny * (double)nz, rp, box[0], box[1], box[2],
                        (long)SBC_PACKING_MAX);
    for (k = 0; k < nz; ++k)
        for (j = 0; j < ny; ++j)
            for (i = 0; i < nx; ++i) {
                double x[3];
                sbc_status st;
                x[0] = rp + sx * (double)i;
                x[1] = rp + sy * (double)j;
                x[2] = rp + sz * (double)k;
                if (lattice == SBC_PACK_HCP) {
                    /* A layers: odd rows shifted by r; B layers: the other rows, and r/sqrt 3 in y */
                    long odd = (j + k) % 2;
                    x[0] += odd ? rp : 0.0;
                    x[1] += (k % 2) ? shift_y : 0.0;
                }
                if ((st = sbc_bpm_add(e, x, rp, rho, NULL, err)) != SBC_OK)
                    return st;
            }
    if (extent)
        sbc_bpm_extent(e, extent);
    return SBC_OK;
}

void sbc_bpm_extent(const sbc_bpm *e, double extent[6])
{
    size_t i;
    int k;
    for (k = 0; k < 3; ++k) {
        extent[k] = e->n ? e->x[k] - e->r[0] : 0.0;
        extent[3 + k] = e->n ? e->x[k] + e->r[0] : 0.0;
    }
    for (i = 0; i < e->n; ++i)
        for (k = 0; k < 3; ++k) {
            extent[k] = fmin(extent[k], e->x[3 * i + (size_t)k] - e->r[i]);
            extent[3 + k] = fmax(extent[3 + k], e->x[3 * i + (size_t)k] + e->r[i]);
        }
}

double sbc_bpm_porosity(const sbc_bpm *e, const double extent[6])
{
    double vs = 0.0, vol = (extent[3] - extent[0]) * (extent[4] - extent[1]) * (extent[5] - extent[2]);
    size_t i;
    for (i = 0; i < e->n; ++i)
        vs += 4.0 / 3.0 * SBC_PI * e->r[i] * e->r[i] * e->r[i];
    return vol > 0.0 ? 1.0 - vs / vol : 0.0;
}
