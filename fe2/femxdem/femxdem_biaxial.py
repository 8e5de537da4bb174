"""FEMxDEM's biaxial example (examples/FEMxDEM/biaxialSmooth.py, Guo & Zhao, in Debian's yade package) shrunk and
measured: a plane-strain specimen 0.05 m x 0.1 m of ELEMENTS x ELEMENTS finley elements (order 2, 4 Gauss points
each, as the example), every Gauss point the RVE 0.yade.gz of the working folder, the sides under 1e5 Pa, the platens
smooth (the bottom's centre held), the top moved down by STRAIN of the height per step for STEPS steps; FEMxDEM's
MultiScale with its own settings (rtol 1e-2 on the displacement correction, the tangent from
utils.getStressAndTangent, 2 worker processes). Run by fe2/femxdem/run.sh (escript and yadeimport importable,
the working folder out/femxdem); parameters by environment, as YADE rewrites sys.argv: FEMXDEM_ELEMENTS (1),
FEMXDEM_STEPS (4), FEMXDEM_STRAIN (0.0025), FEMXDEM_WORKERS (2), FEMXDEM_RTOL (1e-2, the example's).

Measures per step: the top force (N/m of thickness, compression positive), the macro iterations (FEMxDEM's own
count), the CPU seconds per Gauss point (this process and its workers), each RVE's equilibrium after the step
(YADE's unbalancedForce, the mean net force over the mean contact force, and the largest net force over the mean
contact force, servo_bc's `unbalanced`; both after one step of the stored RVE, as YADE keeps no forces in a
saved scene), and the bytes of a stored RVE. Writes femxdem.csv, and rve.txt + rve.json: the RVE for a servo_bc
point (fe2/femxdem/rve_export.py)."""
import contextlib
import io
import multiprocessing
import os
import re
import time

from esys.escript import FunctionOnBoundary, interpolate, integrate, matrix_mult, whereZero, sup
from esys.escript.pdetools import Projector
from esys.finley import Rectangle
from msFEM2D import MultiScale
from yadeimport import Omega, utils

import rve_export

ELEMENTS = int(os.environ.get('FEMXDEM_ELEMENTS', '1'))
STEPS = int(os.environ.get('FEMXDEM_STEPS', '4'))
STRAIN = float(os.environ.get('FEMXDEM_STRAIN', '0.0025'))
WORKERS = int(os.environ.get('FEMXDEM_WORKERS', '2'))
RTOL = float(os.environ.get('FEMXDEM_RTOL', '1e-2'))
LX, LY, CONFINING = 0.05, 0.1, -1.e5   # m, m, Pa (the example's)


def children_cpu():
    """CPU seconds of this process's live children (FEMxDEM's pool workers), from /proc."""
    total = 0.0
    for child in multiprocessing.active_children():
        with open('/proc/%d/stat' % child.pid) as f:
            fields = f.read().rsplit(')', 1)[1].split()
        total += (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')
    return total


def equilibrium(scene):
    """(YADE's unbalancedForce, largest net force / mean contact force) of a stored RVE, after one step of it."""
    Omega().stringToScene(scene)
    Omega().run(1, True)
    forces = [i.phys.normalForce.norm() for i in Omega().interactions if i.isReal]
    largest = max(Omega().forces.f(b.id).norm() for b in Omega().bodies)
    return utils.unbalancedForce(), largest / (sum(forces) / len(forces))


def top_force(prob, top):
    """The top platen's force (N/m of thickness, compression positive) from the projected Gauss-point stress."""
    dom = prob.getDomain()
    sig = interpolate(Projector(dom)(prob.getCurrentStress()), FunctionOnBoundary(dom))
    return -integrate(matrix_mult(sig, dom.getNormal()) * top, where=FunctionOnBoundary(dom))[1]


def main():
    Omega().load('0.yade.gz')
    rve_export.write(Omega(), utils.getStress(), 'rve.txt', 'rve.json')
    nx, ny = ELEMENTS, ELEMENTS
    domain = Rectangle(l0=LX, l1=LY, n0=nx, n1=ny, order=2, integrationOrder=2)
    ng = 4 * nx * ny
    c0, t0 = time.process_time() + children_cpu(), time.time()
    prob = MultiScale(domain=domain, ng=ng, np=WORKERS, random=False, rtol=RTOL, usePert=False, verbose=True)
    created = time.process_time() + children_cpu() - c0
    x, bx = domain.getX(), FunctionOnBoundary(domain).getX()
    top = whereZero(bx[1] - sup(bx[1]))
    Dbc = whereZero(x[1]) * [0, 1] + whereZero(x[1] - LY) * [0, 1] + \
        whereZero(x[1]) * whereZero(x[0] - .5 * LX) * [1, 1]
    vel = -STRAIN * LY
    Vbc = whereZero(x[1] - LY) * [0, vel]
    Nbc = whereZero(bx[0]) * [-CONFINING, 0] + whereZero(bx[0] - LX) * [CONFINING, 0]
    scenes = prob._MultiScale__scenes
    print('femxdem: %d x %d elements, %d Gauss points of %d discs, %d workers; created in %.2f s CPU, %d bytes a '
          'stored RVE' % (nx, ny, ng, len(Omega().bodies), WORKERS, created, len(scenes[0])), flush=True)
    with open('femxdem.csv', 'w') as out:
        out.write('step,u,force,iterations,cpu_per_point,unbalanced_mean_max,unbalanced_largest_max,wall,'
                  'rve_bytes\n')
        start = (0, 0.0, top_force(prob, top), 0, created / ng) + tuple(
            max(v) for v in zip(*[equilibrium(s) for s in scenes])) + (time.time() - t0, len(scenes[0]))
        out.write('%d,%.17g,%.17g,%d,%.6f,%.6g,%.6g,%.3f,%d\n' % start)
        for step in range(1, STEPS + 1):
            c0, t0 = time.process_time() + children_cpu(), time.time()
            prob.initialize(f=Nbc, specified_u_mask=Dbc, specified_u_val=Vbc)
            said = io.StringIO()
            with contextlib.redirect_stdout(said):
                prob.solve(iter_max=100)   # after 100 iterations FEMxDEM commits the step as it stands
            cpu, wall = time.process_time() + children_cpu() - c0, time.time() - t0
            done = re.findall(r'Convergence reached after (\d+) iteration\(s\)! Relative error: (\S+)', said.getvalue())
            iterations = int(done[-1][0]) if done else -1
            scenes = prob._MultiScale__scenes
            worst = [max(v) for v in zip(*[equilibrium(s) for s in scenes])]
            row = (step, -vel * step, top_force(prob, top), iterations, cpu / ng, worst[0], worst[1], wall,
                   len(scenes[0]))
            out.write('%d,%.17g,%.17g,%d,%.6f,%.6g,%.6g,%.3f,%d\n' % row)
            out.flush()
            print('femxdem: step %d: force %.6g N/m, %d macro iterations (relative correction %s), %.4f s CPU per '
                  'Gauss point, RVE unbalanced (mean / largest) up to %.3g / %.3g' % (step, row[2], iterations,
                                                                                     done[-1][1] if done else '?',
                                                                                     row[4], row[5], row[6]),
                  flush=True)
    prob.exitSimulation()


if __name__ == '__main__':
    main()
