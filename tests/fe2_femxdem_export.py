"""fe2/femxdem/rve_export.py without YADE: a periodic cell's discs as a geometrically periodic servo_bc packing.

A packing of the runner's `generate periodic` is taken back to its cell (each disc once, wrapped into the box),
moved by an arbitrary offset, and exported again: a different disc becomes the corner. Checked: the export's count
(the cell's discs, one more per disc on an edge, three more for the corner), every edge disc's copy at exactly +-L,
every cell disc in it, a (P) point of it certified at F = I with the stress of the original's point within 2e-2 of max |P|
(the window of the cell, and so the frame, differs: measured 1.0e-2 here, 8.4e-3 frictionless; docs/fe2.md), and a cell in which every disc
would cross an x and a y edge refused.
Usage: fe2_femxdem_export.py RUNNER OUT (SERVO_BC_LIB for the core's library). Prints 'N passed, N failed'."""
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(here, '..', 'fe2'), os.path.join(here, '..', 'fe2', 'femxdem')]
import macro        # noqa: E402
import rve_export   # noqa: E402

LAW = dict(kn=1e4, ks=2e3, mu=0.4, density=2e3, dt=1e-4)
passed = failed = 0


def check(ok, what):
    global passed, failed
    passed, failed = passed + bool(ok), failed + (not ok)
    print('%s: %s' % ('ok' if ok else 'FAILED', what))


def cell_discs(x, r, box):
    """Each disc of a geometrically periodic packing once: centres wrapped into the box, copies dropped."""
    Lx, Ly = box[1] - box[0], box[3] - box[2]
    seen = {}
    for k in range(len(r)):
        u, v = (x[2 * k] - box[0]) % Lx, (x[2 * k + 1] - box[2]) % Ly
        u, v = (0.0 if min(u, Lx - u) < 1e-12 * Lx else u), (0.0 if min(v, Ly - v) < 1e-12 * Ly else v)
        seen.setdefault((round(u / Lx, 9), round(v / Ly, 9), r[k]), (u, v, r[k]))
    return list(seen.values()), Lx, Ly


def main():
    runner, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, 'export_source.txt')
    script = os.path.join(out, 'export_source.sbc')
    with open(script, 'w') as f:
        f.write('dimension 2\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-4\n'
                'generate periodic n0 40 rmin 1e-3 polydispersity 2 seed 3 strain 0.01\nwrite_packing text %s\n'
                % path)
    subprocess.run([runner, script], check=True, capture_output=True)
    x, r, box = macro.read_packing(path)
    discs, Lx, Ly = cell_discs(x, r, box)
    ox, oy = 0.37 * Lx, 0.61 * Ly
    moved = [(u + ox, v + oy, s) for u, v, s in discs]
    out_discs, out_box, corner = rve_export.periodic_packing([d[0] for d in moved], [d[1] for d in moved],
                                                             [d[2] for d in moved], Lx, Ly)
    on_edge = 0
    for k, (u, v, s) in enumerate(moved):
        if k == corner:
            continue
        a, b = (u - moved[corner][0]) % Lx, (v - moved[corner][1]) % Ly
        on_edge += (a < s or a > Lx - s or b < s or b > Ly - s)
    check(len(out_discs) == len(discs) + on_edge + 3,
          'export of %d cell discs: %d discs (%d on an edge, 3 corner copies)' % (len(discs), len(out_discs), on_edge))
    generators = next(k for k, (u, v, s) in enumerate(discs) if u == 0.0 and v == 0.0)
    check(corner != generators, 'the export\'s corner is cell disc %d, the generator\'s %d' % (corner, generators))
    copies = {(u, v, s) for u, v, s in out_discs}
    unpaired = [(u, v, s) for u, v, s in out_discs if (u < s or u > Lx - s) and (u + Lx, v, s) not in copies
                and (u - Lx, v, s) not in copies] + \
        [(u, v, s) for u, v, s in out_discs if (v < s or v > Ly - s) and (u, v + Ly, s) not in copies
         and (u, v - Ly, s) not in copies]
    check(not unpaired, 'every disc on an edge has its copy at exactly +-L (%d without)' % len(unpaired))
    xs = [c for u, v, s in out_discs for c in (u, v)]
    rs = [s for u, v, s in out_discs]
    words = 'P accuracy tight'
    original = macro.core.MaterialPoint(x, r, words, box=box, **LAW)
    exported = macro.core.MaterialPoint(xs, rs, words, box=out_box, **LAW)
    identity = [1, 0, 0, 0, 1, 0, 0, 0, 1]
    _, P0, _ = original.integrate(identity)
    _, P1, _ = exported.integrate(identity)
    scale = max(abs(v) for v in P0)
    worst = max(abs(a - b) for a, b in zip(P0, P1)) / scale
    check(exported.certified() and worst <= 2e-2, 'the exported packing\'s P at F = I against the original\'s: '
          '%.2e of max |P| (%.6g N/m; at most 2e-2), certified' % (worst, scale))
    back, _, _ = cell_discs(xs, rs, out_box)
    origin = moved[corner]
    shifted = sorted((round((u + origin[0] - ox) % Lx / Lx, 9) % 1.0, round((v + origin[1] - oy) % Ly / Ly, 9) % 1.0,
                      s) for u, v, s in back)
    check(shifted == sorted((round(u / Lx, 9) % 1.0, round(v / Ly, 9) % 1.0, s) for u, v, s in discs),
          'the export holds every cell disc once, at its place (to 1e-9 of the cell)')
    try:
        rve_export.periodic_packing([0.0, 0.1], [0.0, 0.1], [0.15, 0.15], 1.0, 1.0)
        check(False, 'a cell whose every disc crosses two edges is refused')
    except ValueError as e:
        check('corner' in str(e), 'a cell whose every disc crosses two edges is refused: %s' % e)
    print('%d passed, %d failed' % (passed, failed))
    sys.exit(1 if failed else 0)


if __name__ == '__main__':
    main()
