"""FE^2 at the size of FEMxDEM's `biaxialSmooth` example (docs/fe2.md, "At FEMxDEM's size"): a plane-strain
specimen of 8 x 16 bilinear elements, 512 Gauss points, each a (P) point of a 400-disc irregular frictional packing
(the biaxial demo's material, fe2/biaxial.py), the sides under a lateral pressure, the platens smooth, u in steps
of 0.1 % of the height; as many steps as --steps asks. What it measures is the cost: CPU seconds per Gauss point
per step (the process's CPU time, every thread), wall time, macro iterations, and the resident memory per point
(the growth of the process's peak resident set while the points are created, over their count).

The points cycle through --packings distinct packings (point k has packing k mod --packings, seeds 1, 2, ...):
generating 512 packings of 400 discs would take longer than the run; every point still has its own state.
Usage: python3 fe2/at_scale.py [--steps 2] [--threads 2] [--packings 16] [--n0 400] [--words 'P accuracy tight']
                               [--out out/fe2/scale] [--runner build/servo-bc]"""
import argparse
import os
import resource
import time

import numpy as np

import biaxial
import macro
import specimens


def main():
    a = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    a.add_argument('--steps', type=int, default=2)
    a.add_argument('--threads', type=int, default=2)
    a.add_argument('--packings', type=int, default=16)
    a.add_argument('--n0', type=int, default=400)
    a.add_argument('--words', default='P accuracy tight')
    a.add_argument('--pressure', type=float, default=50.0)
    a.add_argument('--out', default='out/fe2/scale')
    a.add_argument('--runner', default='build/servo-bc')
    args = a.parse_args()
    os.makedirs(args.out, exist_ok=True)
    t0 = time.time()
    packings = [biaxial.packing(args.runner, args.out, args.n0, seed + 1) for seed in range(args.packings)]
    generated = time.time() - t0
    L = packings[0][2][1] - packings[0][2][0]   # the width of one packing sets the element's side
    W, H, nx, ny = 8 * L, 16 * L, 8, 16
    rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    t0, c0 = time.time(), time.process_time()

    def make_point(k, X):
        x, r, box = packings[k % args.packings]
        return macro.core.MaterialPoint(x, r, args.words, kn=biaxial.KN, ks=biaxial.KS, mu=biaxial.MU,
                                        density=biaxial.DENSITY, dt=biaxial.DT, box=box)

    model = macro.Macro((W, H), (nx, ny), make_point, tangent='condensed', threads=args.threads)
    created, created_cpu = time.time() - t0, time.process_time() - c0
    memory = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - rss0) * 1024.0 / model.count
    print('fe2 scale: %d x %d elements, %d points of %d discs (%d packings, generated in %.0f s), %s, %d threads; '
          'created in %.1f s (%.1f s CPU), %.0f bytes of resident memory per point'
          % (nx, ny, model.count, len(packings[0][1]), args.packings, generated, args.words, args.threads, created,
             created_cpu, memory), flush=True)
    x, y, c = model.X[0], model.X[1], model.comp
    bottom = np.flatnonzero(np.isclose(y, 0.0) & (c == 1))
    top = np.flatnonzero(np.isclose(y, H) & (c == 1))
    corner = np.flatnonzero(np.isclose(x, 0.0) & np.isclose(y, 0.0) & (c == 0))
    lateral = model.traction_forces([-args.pressure, 0, 0, 0, 0, 0, 0, 0, 0])
    with open(os.path.join(args.out, 'scale_%dthreads.csv' % args.threads), 'w') as f:
        f.write('step,u,force,wall,cpu,cpu_per_point\n')
        for step in range(args.steps + 1):
            u = H * 0.001 * step
            t0, c0 = time.time(), time.process_time()
            forces = specimens.platen_path(model, bottom, top, corner, lateral, [u], 'scale step %d' % step,
                                           biaxial.TOLERANCE)
            if not forces:
                break
            wall, cpu = time.time() - t0, time.process_time() - c0
            f.write('%d,%.17g,%.17g,%.3f,%.3f,%.5f\n' % (step, u, forces[0], wall, cpu, cpu / model.count))
            f.flush()
            print('fe2 scale: step %d: %.1f s wall, %.1f s CPU, %.4f s CPU per Gauss point' % (step, wall, cpu,
                                                                                              cpu / model.count),
                  flush=True)


if __name__ == '__main__':
    main()
