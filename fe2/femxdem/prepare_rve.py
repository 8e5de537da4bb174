"""FEMxDEM's RVE, made as its example examples/FEMxDEM/prepareRVE.py makes it (run by `yade-double -n -x`), with the
disc count as a parameter: discs of radii 5 mm +- 40 % (makeCloud, periodic, seed 1) in a square cell of side
0.24 m * sqrt(n / 400) (the example's 400 discs in 0.24 m), 0.1 m thick, E 6e8 Pa, ks/kn 0.8, no friction while a
PeriTriaxController compresses the cell to 1e5 Pa on x and y, then the friction angle 0.5 rad; saved as 0.yade.gz
in the working folder (the file every FEMxDEM Gauss point loads). Parameters by environment (YADE rewrites
sys.argv): FEMXDEM_DISCS (121)."""
import math
import os

from yade import pack

n = int(os.environ.get('FEMXDEM_DISCS', '121'))
O.materials.append(FrictMat(young=6.e8, poisson=.8, frictionAngle=.0))
sp = pack.SpherePack()
size = .24 * math.sqrt(n / 400.0)
sp.makeCloud(minCorner=(0, 0, .05), maxCorner=(size, size, .05), rMean=.005, rRelFuzz=.4, num=n, periodic=True, seed=1)
sp.toSimulation()
O.cell.hSize = Matrix3(size, 0, 0, 0, size, 0, 0, 0, .1)
for p in O.bodies:
    p.state.blockedDOFs = 'zXY'
    p.state.mass = 2650 * 0.1 * math.pi * p.shape.radius ** 2  # a cylinder 0.1 m thick
    inertia = 0.5 * p.state.mass * p.shape.radius ** 2
    p.state.inertia = (.5 * inertia, .5 * inertia, inertia)
O.dt = utils.PWaveTimeStep()
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                    [Law2_ScGeom_FrictPhys_CundallStrack()]),
    PeriTriaxController(dynCell=True, goal=(-1.e5, -1.e5, 0), stressMask=3, relStressTol=.001, maxUnbalanced=.001,
                        maxStrainRate=(.5, .5, .0), doneHook='term()', label='biax'),
    NewtonIntegrator(damping=.1)
]


def term():
    O.engines = O.engines[:3] + O.engines[4:]
    setContactFriction(0.5)
    O.cell.trsf = Matrix3.Identity
    O.cell.velGrad = Matrix3.Zero
    for p in O.bodies:
        p.state.vel = Vector3.Zero
        p.state.angVel = Vector3.Zero
        p.state.refPos = p.state.pos
        p.state.refOri = p.state.ori
    O.save('0.yade.gz')
    print('prepare_rve: %d discs, cell %s, stress %s, %d steps' % (len(O.bodies), O.cell.hSize.diagonal(),
                                                                   getStress().diagonal(), O.iter))
    O.pause()


O.run()
O.wait()
