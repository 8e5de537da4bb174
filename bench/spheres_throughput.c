/* Embedded sphere engine throughput: ns per particle-step on a simple cubic
 * lattice of side^3 spheres (spacing 2 mm, R 1.02 mm: 2 % overlap), contact
 * law kn 1e4 N/m, ks 2e3 N/m, mu 0.4, density 2500 kg/m^3, dt 1e-6 s, no
 * damping, free faces: the scene of bench/lammps_cubic.in.
 *
 *   bench_spheres SIDE STEPS          prints "spheres N STEPS ns_per_particle_step"
 *   bench_spheres SIDE STEPS servo    the same, the outer layer a (D) frame
 *                                     driven through the host driver each step */
#define _POSIX_C_SOURCE 200809L
#include "sbc/driver.h"
#include "sbc/embedded/spheres.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    const int side = argc > 1 ? atoi(argv[1]) : 22;
    const long steps = argc > 2 ? atol(argv[2]) : 1000;
    const int servo = argc > 3 && strcmp(argv[3], "servo") == 0;
    sbc_spheres_def def = sbc_spheres_def_default();
    sbc_spheres *e;
    sbc_frame frame;
    sbc_error err;
    sbc_settings s = sbc_settings_default();
    sbc_controller *ctl = NULL;
    sbc_driver *drv = NULL;
    sbc_driver_callbacks cb;
    double *x, *r, *mass = NULL, t0, t1, out[2];
    long k;
    int i, j, l, n = 0;
    if (side < 3 || steps < 1) {
        fprintf(stderr, "usage: bench_spheres SIDE(>=3) STEPS [servo]\n");
        return 2;
    }
    x = malloc(sizeof(double) * 3 * (size_t)side * side * side);
    r = malloc(sizeof(double) * (size_t)side * side * side);
    for (l = 0; l < side; ++l)
        for (j = 0; j < side; ++j)
            for (i = 0; i < side; ++i, ++n) {
                x[3 * n] = 2e-3 * i, x[3 * n + 1] = 2e-3 * j, x[3 * n + 2] = 2e-3 * l;
                r[n] = 1.02e-3;
            }
    def.n = n, def.x = x, def.r = r;
    def.law.kn = 1e4, def.law.ks = 2e3, def.law.mu = 0.4;
    def.alpha = def.beta = 0.0;
    def.skin = 0.25 * 1.02e-3;
    if (!(e = sbc_spheres_create(&def, &err))) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    cb = sbc_spheres_callbacks(e);
    if (servo) {
        sbc_frame_detect_3d(&frame, n, x, r, 0.0, &err);
        sbc_spheres_set_frame(e, &frame);
        mass = malloc(sizeof(double) * (size_t)frame.n);
        sbc_spheres_frame_masses(e, mass);
        s.damping = SBC_DAMPING_NONE;
        sbc_settings_check_dimension(&s, 3, &err);
        s.F[SBC_IJ(0, 0)] = s.F[SBC_IJ(1, 1)] = s.F[SBC_IJ(2, 2)] = 0.999;
        s.increments = 1000000;
        ctl = sbc_controller_create(&frame, &s, mass, def.dt, def.law.kn, &err);
        drv = ctl ? sbc_driver_create(ctl, &s, &cb, &err) : NULL;
        if (!drv) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
    }
    t0 = now();
    for (k = 0; k < steps; ++k) {
        sbc_spheres_forces(e, &err);
        if (drv) {
            sbc_commands cmd;
            sbc_driver_step(drv, 0, &err);
            cmd = sbc_controller_commands(ctl);
            sbc_spheres_move_frame(e, &cmd);
        } else {
            cb.interior(cb.user_data, NULL, 0, out);
        }
    }
    t1 = now();
    printf("spheres%s %d %ld %.2f\n", servo ? "+servo" : "", n, steps, (t1 - t0) / ((double)n * steps) * 1e9);
    sbc_driver_free(drv);
    sbc_controller_free(ctl);
    if (servo)
        sbc_frame_free(&frame);
    free(mass);
    sbc_spheres_free(e);
    free(x);
    free(r);
    return 0;
}
