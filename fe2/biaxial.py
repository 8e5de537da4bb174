"""The FE^2 biaxial demo (make fe2-demo, docs/fe2.md "The biaxial demo"): plane-strain biaxial compression of a
square specimen of frictional discs, once as FE^2 with (D), (P) and (T) aggregates at the Gauss points and once
as a direct DEM simulation (DNS) of the whole specimen, with the same particle statistics.

The material: discs of radii uniform in [1, 2] mm (kn 1e4 N/m, ks 2e3 N/m, mu 0.4, 2000 kg/m^2), a periodic
packing jammed by the runner's `generate periodic` and compressed by 1 % (`strain 0.01`), so that it carries a
prestress. Every Gauss point gets its own packing of n0 discs (seed 1, 2, ...: a heterogeneous specimen); the
DNS packing has n0 times the number of Gauss points (seed 1000), and its box sets the specimen's side L; --specimen
S adds 10000 S to every seed (another specimen of the same statistics).

The test: the sides under the lateral pressure p (N/m) from the start, the platens smooth (the bottom's vertical
displacement 0, the top's -u, the bottom-left corner's horizontal one 0 in FE), then u in `steps` equal steps to
L * strain. The DNS is the runner's mixed frame on the whole specimen: `left T D`, `right T D` under `stress P11
-p 0` (held from increment 0), `bottom D D`, `top D D` following F22 = 1 - u / L (its platens move sideways with
the specimen's mean lateral stretch, F11 measured). Force per unit thickness on the top (N), compression
positive: FE^2 the reactions of the top's vertical dofs, DNS -P22 L.

Writes OUT/biaxial.csv (u,force_D,force_P,force_T,force_DNS, m and N), one CSV per curve for the figure, and
prints the cost of each. A path that stops (a point that fails below the smallest step cut) keeps its rows, leaves
its later cells empty, and makes the script exit 1 after writing everything. Usage (defaults: the demo's size, a few minutes on 2 cores):
  python3 fe2/biaxial.py [--n0 100] [--elements 1] [--steps 4] [--strain 0.01] [--pressure 50] [--out out/fe2]
                         [--runner build/servo-bc] [--plot build/servo-bc-plot] [--threads 2] [--only D,P,T,DNS]
                         [--specimen 0]"""
import os
import sys
import time

import numpy as np

import macro
import specimens

KN, KS, MU, DENSITY, DT = 1e4, 2e3, 0.4, 2e3, 1e-4  # N/m, N/m, -, kg/m^2, s (0.09 of the critical step)
LAW = 'contact frictional kn %g ks %g mu %g\ndensity %g\ntimestep %g' % (KN, KS, MU, DENSITY, DT)
GENERATE = 'generate periodic n0 %d rmin 1e-3 polydispersity 2 seed %d strain 0.01'
# (T) sealed: without the walls an interior disc of one 2 x 2 point escapes between frame discs (docs/fe2.md)
WORDS = {'D': 'D accuracy tight', 'P': 'P accuracy tight', 'T': 'T accuracy tight seal yes'}
TOLERANCE = 1e-3  # the macro Newton's, of the reaction: the points' frictional equilibria are not smoother


def packing(runner, out, n0, seed):
    return specimens.packing(runner, out, LAW, GENERATE, n0, seed)


def fe2(bc, args, L, us):
    """The top force (N, compression positive) at each u of us, and the wall time."""
    t0 = time.time()

    def make_point(k, X):
        x, r, box = packing(args.runner, args.out, args.n0, specimens.point_seed(args, k))
        return macro.core.MaterialPoint(x, r, WORDS[bc], kn=KN, ks=KS, mu=MU, density=DENSITY, dt=DT, box=box)

    n = args.elements
    model = macro.Macro((L, L), (n, n), make_point, tangent='condensed', threads=args.threads)
    created = time.time() - t0
    x, y, c = model.X[0], model.X[1], model.comp
    bottom = np.flatnonzero(np.isclose(y, 0.0) & (c == 1))
    top = np.flatnonzero(np.isclose(y, L) & (c == 1))
    corner = np.flatnonzero(np.isclose(x, 0.0) & np.isclose(y, 0.0) & (c == 0))
    lateral = model.traction_forces([-args.pressure, 0, 0, 0, 0, 0, 0, 0, 0])
    forces = specimens.platen_path(model, bottom, top, corner, lateral, us, '(%s)' % bc, TOLERANCE)
    return forces, created, time.time() - t0


def dns(args, L, us):
    """The DNS's top force (N) at each u of us, its packing's disc count and the wall time."""
    t0 = time.time()
    csv = os.path.join(args.out, 'biaxial_dns_rows.csv')
    n0 = args.n0 * 4 * args.elements ** 2
    steps = len(us) - 1
    packing(args.runner, args.out, n0, specimens.dns_seed(args))
    specimens.run(args.runner, 'dimension 2\n%s\nread_packing %s\n'
        'servo_bc mixed bottom D D top D D left T D right T D stress P11 %.17g 0 F 1 0 0 %.17g increments %d '
        'accuracy tight file %s\nrun\n' % (LAW, specimens.packing_path(args.out, n0, specimens.dns_seed(args)),
                                           -args.pressure, 1.0 - us[-1] / L,
                                           steps, csv), os.path.join(args.out, 'biaxial_dns.sbc'))
    head, *rows = [line.strip().split(',') for line in open(csv)]
    P22, F22 = head.index('P22'), head.index('F22')
    forces = [-float(row[P22]) * L for row in rows]
    got = [(1.0 - float(row[F22])) * L for row in rows]
    if len(rows) != len(us) or max(abs(a - b) for a, b in zip(got, us)) > 1e-9 * L:
        sys.exit('fe2/biaxial.py: the DNS rows (%d) are not at the platen displacements of FE^2' % len(rows))
    with open(specimens.packing_path(args.out, n0, specimens.dns_seed(args))) as f:
        discs = f.readline().strip('# \n')
    return forces, discs, time.time() - t0


def main():
    args = specimens.arguments(__doc__, 100, 50.0, 'D,P,T,DNS')
    _, _, box = packing(args.runner, args.out, args.n0 * 4 * args.elements ** 2, specimens.dns_seed(args))
    L = box[1] - box[0]
    us = [L * args.strain * k / args.steps for k in range(args.steps + 1)]
    print('fe2 biaxial: specimen %.6g m square, %d x %d elements, %d points of n0 %d discs, p %g N/m, u to %.4g m'
          % (L, args.elements, args.elements, 4 * args.elements ** 2, args.n0, args.pressure, us[-1]), flush=True)
    specimens.compare('biaxial', args, L, us, fe2, dns, 'biaxial compression, p = %g N/m' % args.pressure)


if __name__ == '__main__':
    main()
