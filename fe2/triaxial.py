"""The 3D FE^2 demo (make fe2-demo3d, docs/fe2.md "The 3D macro model"): triaxial compression of a cube of
frictional spheres under a lateral pressure, once as FE^2 with (D), (P) and (T) aggregates at the Gauss points of
trilinear hexahedra and once as a direct DEM simulation (DNS) of the whole specimen, with the same particle
statistics.

The material: spheres of radii uniform in [1, 2] mm (kn 1e4 N/m, ks 2e3 N/m, mu 0.4, 2000 kg/m^3, dt 2e-6 s), a
periodic packing jammed by the runner's `generate periodic` and compressed by 1 % (`strain 0.01`), so that it
carries a prestress. Gauss point k gets its own packing of n0 spheres (seed k + 1); the DNS packing has n0 times
the number of Gauss points (seed 1000), and its box sets the specimen's side L; --specimen S adds 10000 S to every
seed. (T) points hold their frame's rotations (`rotation zero`: on irregular sphere packings the paper's free
rotations carry nothing, docs/frame3d.md) and solve statically (`interior newton`).

The test: the four side faces under the lateral pressure p (N/m^2) from the start (dead load), the platens smooth
(the bottom's vertical displacement 0, the top's -u; in FE the corner at the origin held in x and y and the corner
(L, 0, 0) in y, against the rigid motions), then u in `steps` equal steps to L * strain. The DNS is the runner's
mixed frame on the whole specimen: xlo and xhi `T D D`, ylo and yhi `D T D` under `stress P11 -p 0` and `stress
P22 -p 0` (held from increment 0), zlo and zhi `D D D` following F33 = 1 - u / L. Force on the top (N), compression
positive: FE^2 the reactions of the top's vertical dofs, DNS -P33 L^2.

Writes OUT/triaxial.csv (u,force_D,force_P,force_T,force_DNS, m and N), one CSV per curve for the figure, and
prints the cost of each. A path that stops keeps its rows, leaves its later cells empty, and makes the script exit 1
after writing everything. (T) points run on request (--only D,P,T,DNS): on these irregular sphere packings most of
them lose their stress at F = I (docs/fe2.md, "The 3D macro model"), and the path stops. Usage (defaults: the
smallest size, about 15 s on 2 cores; docs/fe2.md the full one):
  python3 fe2/triaxial.py [--n0 15] [--elements 1] [--steps 4] [--strain 0.01] [--pressure 2e4] [--out out/fe2]
                          [--runner build/servo-bc] [--plot build/servo-bc-plot] [--threads 2] [--only D,P,DNS]
                          [--specimen 0]"""
import os
import sys
import time

import numpy as np

import macro
import specimens

KN, KS, MU, DENSITY, DT = 1e4, 2e3, 0.4, 2e3, 2e-6  # N/m, N/m, -, kg/m^3, s (0.07 of sqrt(m/kn), r = 1 mm)
LAW = 'contact frictional kn %g ks %g mu %g\ndensity %g\ntimestep %g' % (KN, KS, MU, DENSITY, DT)
GENERATE = 'generate periodic n0 %d rmin 1e-3 polydispersity 2 seed %d strain 0.01'
WORDS = {'D': 'D accuracy tight', 'P': 'P accuracy tight', 'T': 'T accuracy tight rotation zero interior newton'}
TOLERANCE = 1e-3  # the macro Newton's, of the reaction


def packing(runner, out, n0, seed):
    return specimens.packing(runner, out, LAW, GENERATE, n0, seed, dim=3)


def fe2(bc, args, L, us):
    """The top force (N, compression positive) at each u of us, the time to create the points and the wall time."""
    t0 = time.time()

    def make_point(k, X):
        x, r, _ = packing(args.runner, args.out, args.n0, specimens.point_seed(args, k))
        return macro.core.MaterialPoint(x, r, WORDS[bc], kn=KN, ks=KS, mu=MU, density=DENSITY, dt=DT, dim=3)

    n = args.elements
    model = macro.Macro((L, L, L), (n, n, n), make_point, tangent='condensed', threads=args.threads)
    created = time.time() - t0
    x, y, z, c = model.X[0], model.X[1], model.X[2], model.comp
    bottom = np.flatnonzero(np.isclose(z, 0.0) & (c == 2))
    top = np.flatnonzero(np.isclose(z, L) & (c == 2))
    origin = np.isclose(x, 0.0) & np.isclose(y, 0.0) & np.isclose(z, 0.0)
    held = np.flatnonzero((origin & (c < 2)) | (np.isclose(x, L) & np.isclose(y, 0.0) & np.isclose(z, 0.0) & (c == 1)))
    lateral = model.traction_forces([-args.pressure, 0, 0, 0, -args.pressure, 0, 0, 0, 0])
    forces = specimens.platen_path(model, bottom, top, held, lateral, us, '3D (%s)' % bc, TOLERANCE)
    return forces, created, time.time() - t0


def dns(args, L, us):
    """The DNS's top force (N) at each u of us, its packing's description and the wall time."""
    t0 = time.time()
    csv = os.path.join(args.out, 'triaxial_dns_rows.csv')
    n0 = args.n0 * 8 * args.elements ** 3
    packing(args.runner, args.out, n0, specimens.dns_seed(args))
    p = -args.pressure
    specimens.run(args.runner, 'dimension 3\n%s\nread_packing %s\n'
                  'servo_bc mixed xlo T D D xhi T D D ylo D T D yhi D T D zlo D D D zhi D D D '
                  'stress P11 %.17g 0 stress P22 %.17g 0 F 1 0 0 0 1 0 0 0 %.17g increments %d accuracy tight file %s\n'
                  'run\n' % (LAW, specimens.packing_path(args.out, n0, specimens.dns_seed(args), 3), p, p,
                             1.0 - us[-1] / L, len(us) - 1, csv), os.path.join(args.out, 'triaxial_dns.sbc'))
    head, *rows = [line.strip().split(',') for line in open(csv)]
    P33, F33 = head.index('P33'), head.index('F33')
    forces = [-float(row[P33]) * L * L for row in rows]
    got = [(1.0 - float(row[F33])) * L for row in rows]
    if len(rows) != len(us) or max(abs(a - b) for a, b in zip(got, us)) > 1e-9 * L:
        sys.exit('fe2/triaxial.py: the DNS rows (%d) are not at the platen displacements of FE^2' % len(rows))
    with open(specimens.packing_path(args.out, n0, specimens.dns_seed(args), 3)) as f:
        spheres = f.readline().strip('# \n')
    return forces, spheres, time.time() - t0


def main():
    args = specimens.arguments(__doc__, 15, 2e4, 'D,P,DNS')
    points = 8 * args.elements ** 3
    _, _, box = packing(args.runner, args.out, args.n0 * points, specimens.dns_seed(args))
    L = box[1] - box[0]
    us = [L * args.strain * k / args.steps for k in range(args.steps + 1)]
    print('fe2 triaxial: specimen a cube of %.6g m, %d^3 elements, %d points of n0 %d spheres, p %g N/m^2, u to '
          '%.4g m' % (L, args.elements, points, args.n0, args.pressure, us[-1]), flush=True)
    specimens.compare('triaxial', args, L, us, fe2, dns, 'triaxial compression, p = %g N/m^2' % args.pressure)


if __name__ == '__main__':
    main()
