"""A FEMxDEM RVE (a YADE periodic cell of discs: spheres moving in a plane, 0.1 m thick) as a servo_bc packing: a
geometrically periodic packing (docs/runner.md, "Frame detection") in the box [0, Lx] x [0, Ly] with one disc's
centre on the four corners and every disc that crosses an edge written twice, at +-L; and the contact law's
figures for a servo_bc point.

servo_bc's frictional law has one kn for every contact; YADE's FrictPhys gives each contact its own,
kn = 2 E r1 r2 / (r1 + r2) (E r for equal discs), ks = poisson kn, tan(friction angle). The exported kn is the mean
of the RVE's contacts' kn; its spread is in the JSON. servo_bc's 2D stress is per unit thickness: a YADE stress
(Pa) times the thickness (m) is the servo_bc P (N/m); the areal density is YADE's mass over pi r^2."""
import json
import math


def periodic_packing(x, y, r, Lx, Ly):
    """(discs [(x, y, r)], box [0, Lx, 0, Ly], corner index): the cell's discs shifted so that the corner disc's
    centre is at the origin, its copies on the other three corners, every disc crossing an x (y) edge copied at
    +-Lx (+-Ly). The corner disc is the largest one for which no other disc crosses an x and a y edge at once (it
    would need copies on four corners); ValueError when there is none."""
    for c in sorted(range(len(r)), key=lambda k: (-r[k], k)):
        discs, clear = [(0.0, 0.0, r[c]), (Lx, 0.0, r[c]), (0.0, Ly, r[c]), (Lx, Ly, r[c])], True
        for k in range(len(r)):
            if k == c:
                continue
            u, v = (x[k] - x[c]) % Lx, (y[k] - y[c]) % Ly
            du = Lx if u < r[k] else -Lx if u > Lx - r[k] else 0.0
            dv = Ly if v < r[k] else -Ly if v > Ly - r[k] else 0.0
            if du and dv:
                clear = False
                break
            discs.append((u, v, r[k]))
            if du or dv:
                discs.append((u + du, v + dv, r[k]))
        if clear:
            return discs, [0.0, Lx, 0.0, Ly], c
    raise ValueError('rve_export: no disc can be the corner (for each, another crosses an x and a y edge at once)')


def write(omega, stress, txt, json_path):
    """Writes the RVE loaded in YADE's omega as the servo_bc text packing txt and its law, with its stress (Pa,
    YADE's utils.getStress()), as json_path."""
    bodies = list(omega.bodies)
    h = omega.cell.hSize
    Lx, Ly, thickness = h[0, 0], h[1, 1], h[2, 2]
    if abs(h[0, 1]) + abs(h[1, 0]) > 0.0:
        raise ValueError('rve_export: a sheared cell (hSize %s); expected the prepared RVE' % h)
    x = [b.state.pos[0] for b in bodies]
    y = [b.state.pos[1] for b in bodies]
    r = [b.shape.radius for b in bodies]
    discs, box, corner = periodic_packing(x, y, r, Lx, Ly)
    with open(txt, 'w') as f:
        f.write('# servo_bc packing: %d discs, exported from a FEMxDEM RVE (%d discs, YADE cell %.17g x %.17g m, '
                'corner disc %d)\n' % (len(discs), len(bodies), Lx, Ly, corner))
        f.write('box %.17g %.17g %.17g %.17g\n' % tuple(box))
        f.writelines('%.17g %.17g %.17g\n' % d for d in discs)
    contacts = [i for i in omega.interactions if i.isReal]
    kn = [i.phys.kn for i in contacts]
    law = {
        'kn': sum(kn) / len(kn), 'kn_min': min(kn), 'kn_max': max(kn),
        'ks_over_kn': contacts[0].phys.ks / contacts[0].phys.kn,
        'mu': contacts[0].phys.tangensOfFrictionAngle,
        'density': bodies[0].state.mass / (math.pi * r[0] ** 2),
        'dt': omega.dt, 'thickness': thickness, 'discs': len(bodies), 'contacts': len(contacts),
        'cell': [Lx, Ly], 'stress_Pa': [[stress[a, b] for b in range(2)] for a in range(2)],
    }
    with open(json_path, 'w') as f:
        json.dump(law, f, indent=1)
    return law
