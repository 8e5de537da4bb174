/* Embedded engine throughput: ns per particle-step on a square lattice of
 * side x side discs (spacing 2 mm, R 1.02 mm: 4 % overlap), paper contact law
 * (kn 1e4 N/m, ks 2e3 N/m, mu 0.4), dt 1e-6 s, no damping, free edges: the
 * same scene as bench/lammps_lattice.in.
 *
 *   bench_engine SIDE STEPS          prints "engine N STEPS ns_per_particle_step"
 *   bench_engine SIDE STEPS servo    the same, with the outer ring as a (D) frame
 *                                    driven through the controller each step
 *   bench_engine SIDE STEPS cohesive every touching pair bonded by Table 6's
 *                                    cohesive law (eqs. 7-8; bench/cohesive_million.sh) */
#define _POSIX_C_SOURCE 200809L
#include "sbc/controller.h"
#include "sbc/embedded/engine.h"
#include "sbc/packing.h"

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
    int side = argc > 1 ? atoi(argv[1]) : 100;
    long steps = argc > 2 ? atol(argv[2]) : 2000, k;
    int servo = argc > 3 && strcmp(argv[3], "servo") == 0, cohesive = argc > 3 && strcmp(argv[3], "cohesive") == 0;
    sbc_cohesive law = sbc_cohesive_default();
    sbc_packing p;
    sbc_frame frame;
    sbc_error err;
    sbc_engine_def def = sbc_engine_def_default();
    sbc_engine *e;
    sbc_controller *ctl = NULL;
    sbc_settings s = sbc_settings_default();
    double t0, t1, *mass = NULL;

    if (side < 3 || steps < 1) {
        fprintf(stderr, "usage: bench_engine SIDE(>=3) STEPS [servo | cohesive]\n");
        return 2;
    }
    if (sbc_packing_lattice_square(&p, side, side, 2e-3, 1.02e-3, &err) != SBC_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    def.n = p.n;
    def.x = p.x;
    def.r = p.r;
    def.alpha = def.beta = 0.0;
    def.skin = 0.25 * 1.02e-3;
    if (cohesive) {
        def.bonds = &law;
        def.law.kn = law.kn;
    }
    e = sbc_engine_create(&def, &err);
    if (!e) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    if (servo) {
        sbc_frame_detect(&frame, p.n, p.x, p.r, 0.0, &err);
        sbc_engine_set_frame(e, &frame);
        mass = malloc(sizeof(double) * (size_t)frame.n);
        sbc_engine_frame_masses(e, mass);
        s.F[SBC_IJ(0, 0)] = s.F[SBC_IJ(1, 1)] = 0.999;
        s.increments = 1000000;
        ctl = sbc_controller_create(&frame, &s, mass, def.dt, def.law.kn, &err);
    }
    t0 = now();
    for (k = 0; k < steps; ++k) {
        sbc_engine_step(e, &err);
        if (ctl) {
            sbc_snapshot snap;
            sbc_commands cmd;
            sbc_engine_snapshot(e, &snap);
            sbc_controller_step(ctl, &snap, &err);
            cmd = sbc_controller_commands(ctl);
            sbc_engine_move_frame(e, &cmd);
        }
    }
    t1 = now();
    if (cohesive) {
        sbc_snapshot snap;
        sbc_engine_snapshot(e, &snap);
        printf("engine+cohesive %d %ld %.2f Ep %.12g J\n", p.n, steps, (t1 - t0) / ((double)p.n * steps) * 1e9,
               snap.potential_energy);
    } else
        printf("engine%s %d %ld %.2f\n", servo ? "+servo" : "", p.n, steps, (t1 - t0) / ((double)p.n * steps) * 1e9);
    sbc_controller_free(ctl);
    if (servo)
        sbc_frame_free(&frame);
    free(mass);
    sbc_engine_free(e);
    sbc_packing_free(&p);
    return 0;
}
