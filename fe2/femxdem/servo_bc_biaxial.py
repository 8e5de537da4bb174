"""servo_bc's FE^2 on the macro problem of fe2/femxdem/femxdem_biaxial.py: the specimen 0.05 m x 0.1 m of
ELEMENTS x ELEMENTS bilinear elements (4 Gauss points each), every Gauss point a (P) point of the RVE FEMxDEM used
(OUT/rve.txt and OUT/rve.json, written by rve_export.py), the sides under 1e5 Pa, the platens smooth (the bottom-left
corner held sideways: a bilinear element has no bottom centre), the top moved down by STRAIN of the height per step;
the condensed tangent, the macro Newton to 1e-4 of the reaction. Forces per unit thickness: servo_bc's 2D stress of
a disc packing 0.1 m thick is the YADE stress (Pa) times 0.1 m.

Writes OUT/servo_bc.csv (the columns of OUT/femxdem.csv, and the first Gauss point's committed F). Usage: servo_bc_biaxial.py OUT; FEMXDEM_ELEMENTS (1),
FEMXDEM_STEPS (4), FEMXDEM_STRAIN (0.0025), FEMXDEM_WORDS ('P accuracy tight'), FEMXDEM_THREADS (2) by environment,
as the FEMxDEM side takes them."""
import json
import os
import sys
import time

import numpy as np

import macro
import specimens

ELEMENTS = int(os.environ.get('FEMXDEM_ELEMENTS', '1'))
STEPS = int(os.environ.get('FEMXDEM_STEPS', '4'))
STRAIN = float(os.environ.get('FEMXDEM_STRAIN', '0.0025'))
WORDS = os.environ.get('FEMXDEM_WORDS', 'P accuracy tight')
THREADS = int(os.environ.get('FEMXDEM_THREADS', '2'))
LX, LY, CONFINING = 0.05, 0.1, 1.e5   # m, m, Pa (FEMxDEM's example)
TOLERANCE = 1e-4                       # of the reaction


def main():
    out = sys.argv[1]
    law = json.load(open(os.path.join(out, 'rve.json')))
    x, r, box = macro.read_packing(os.path.join(out, 'rve.txt'))
    t = law['thickness']
    c0 = time.process_time()

    def make_point(k, X):
        return macro.core.MaterialPoint(x, r, WORDS, kn=law['kn'], ks=law['ks_over_kn'] * law['kn'], mu=law['mu'],
                                        density=law['density'], dt=law['dt'], box=box)

    model = macro.Macro((LX, LY), (ELEMENTS, ELEMENTS), make_point, tangent='condensed', threads=THREADS)
    created = time.process_time() - c0
    state = len(model.points[0].state())
    print('servo_bc: %d x %d elements, %d Gauss points of %d discs (%s), kn %.6g N/m, %d threads; created in %.2f '
          's CPU, %d bytes a stored point' % (ELEMENTS, ELEMENTS, model.count, len(r), WORDS, law['kn'], THREADS,
                                              created, state), flush=True)
    xs, ys, c = model.X[0], model.X[1], model.comp
    bottom = np.flatnonzero(np.isclose(ys, 0.0) & (c == 1))
    top = np.flatnonzero(np.isclose(ys, LY) & (c == 1))
    corner = np.flatnonzero(np.isclose(xs, 0.0) & np.isclose(ys, 0.0) & (c == 0))
    lateral = model.traction_forces([-CONFINING * t, 0, 0, 0, 0, 0, 0, 0, 0])
    with open(os.path.join(out, 'servo_bc.csv'), 'w') as f:
        f.write('step,u,force,iterations,cpu_per_point,uncertified,residual,wall,point_bytes,F11,F12,F21,F22\n')
        for step in range(STEPS + 1):
            u = STRAIN * LY * step
            c0, t0, seen = time.process_time(), time.time(), []
            forces = specimens.platen_path(model, bottom, top, corner, lateral, [u], 'servo_bc step %d' % step,
                                           TOLERANCE, seen)
            if not forces:
                sys.exit('servo_bc_biaxial.py: the path stopped at step %d (above)' % step)
            cpu, wall = time.process_time() - c0, time.time() - t0
            F = model.deformation(model.U)[0]
            f.write('%d,%.17g,%.17g,%d,%.6f,%d,%.3g,%.3f,%d,%.17g,%.17g,%.17g,%.17g\n'
                    % (step, u, forces[0] / t, sum(len(h) - 1 for h in seen), cpu / model.count, model.uncertified,
                       seen[-1][-1], wall, state, F[0], F[1], F[3], F[4]))
            f.flush()


if __name__ == '__main__':
    main()
