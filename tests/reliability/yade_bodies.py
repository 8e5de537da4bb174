# yade -n -x tests/reliability/yade_bodies.py CASE (SERVO_BC_LIB set): one bad input for servo_bc.Bonds / servo_bc.Cohesive; prints RESULT lines
import sys, os, math, traceback
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', '..', 'yade_adapter'))
assert 'SERVO_BC_LIB' in os.environ, 'set SERVO_BC_LIB to build/libservo_bc.so'
import servo_bc
from yade import O, utils
from yade.wrapper import *
case = sys.argv[1]
nan = float('nan')
def row3d(n=5, r=0.1, gap=0.0):
    mat = O.materials.append(FrictMat(young=1e9, poisson=0.3, density=925, frictionAngle=0))
    return [O.bodies.append(utils.sphere((k * (2 * r + gap), 0, 0), r, material=mat)) for k in range(n)]
def lattice2d(n=3, r=1.02e-3, d=2e-3, z=None):
    mat = O.materials.append(FrictMat(young=1e9, poisson=0.3, density=2e3, frictionAngle=0))
    ids = []
    for b in range(n):
        for a in range(n):
            ids.append(O.bodies.append(utils.sphere((a * d, b * d, 0 if z is None else z(a, b)), r, material=mat)))
    for i in ids:
        O.bodies[i].state.blockedDOFs = 'zXY'
    return ids
LAW = 'kn 1e4 ks 2e3 kr 1e-3 fn 1 fs 1 mr 1e-3 mu 0.4'
def steps(obj, n=50):
    O.engines = [ForceResetter(), obj.engine, NewtonIntegrator(damping=0.2)]
    O.dt = 1e-7
    O.run(n, True)
try:
    if case == 'b_ctrl':
        ids = row3d(); b = servo_bc.Bonds(ids); steps(b); print('RESULT OK bonds', b.count, 'intact', b.intact())
    elif case == 'b_id99':
        ids = row3d(); b = servo_bc.Bonds(ids + [99]); print('RESULT OK accepted', b.count)
    elif case == 'b_idneg':
        ids = row3d(); b = servo_bc.Bonds([-1] + ids); print('RESULT OK accepted', b.count)
    elif case == 'b_dup':
        ids = row3d(); b = servo_bc.Bonds(ids + [ids[0]]); steps(b); print('RESULT OK accepted', b.count, 'intact', b.intact())
    elif case == 'b_empty':
        row3d(); b = servo_bc.Bonds([]); print('RESULT OK accepted', b.count)
    elif case == 'b_float_id':
        ids = row3d(); b = servo_bc.Bonds([0, 1.5, 2]); print('RESULT OK accepted', b.count)
    elif case == 'b_box':
        ids = row3d(); bx = O.bodies.append(utils.box((0.4, 0.3, 0), (0.1, 0.1, 0.1))); b = servo_bc.Bonds(ids + [bx]); print('RESULT OK accepted', b.count)
    elif case == 'b_model_upper':
        ids = row3d(); b = servo_bc.Bonds(ids, model='Beam'); print('RESULT OK accepted', b.count)
    elif case == 'b_model_cohesive':
        ids = row3d(); b = servo_bc.Bonds(ids, model='cohesive'); print('RESULT OK accepted', b.count)
    elif case == 'b_E_neg':
        ids = row3d(); b = servo_bc.Bonds(ids, E=-4e9); print('RESULT OK accepted', b.count)
    elif case == 'b_E_nan':
        ids = row3d(); b = servo_bc.Bonds(ids, E=nan); print('RESULT OK accepted', b.count)
    elif case == 'b_nu_half':
        ids = row3d(); b = servo_bc.Bonds(ids, nu=0.5); print('RESULT OK accepted', b.count)
    elif case == 'b_alpha0':
        ids = row3d(); b = servo_bc.Bonds(ids, alpha=0); print('RESULT OK accepted', b.count)
    elif case == 'b_strength3':
        ids = row3d(); b = servo_bc.Bonds(ids, strength=(1e5, 0, 0)); print('RESULT OK accepted', b.count)
    elif case == 'b_strength0':
        ids = row3d(); b = servo_bc.Bonds(ids, strength=(0, 0, 0, 0)); print('RESULT OK accepted', b.count)
    elif case == 'b_strength_word':
        ids = row3d(); b = servo_bc.Bonds(ids, strength=(1e5, 'x', 0, 0)); print('RESULT OK accepted', b.count)
    elif case == 'b_strength_nan':
        ids = row3d(); b = servo_bc.Bonds(ids, strength=(nan, 0, 0, 0)); print('RESULT OK accepted', b.count)
    elif case == 'b_friction_neg':
        ids = row3d(); b = servo_bc.Bonds(ids, strength=(1e5, 0, 0, 0), friction=-1); print('RESULT OK accepted', b.count)
    elif case == 'b_apart':
        ids = row3d(gap=0.05); b = servo_bc.Bonds(ids); print('RESULT OK accepted', b.count)
    elif case == 'b_mass0':
        ids = row3d(); O.bodies[2].state.mass = 0; b = servo_bc.Bonds(ids); steps(b); print('RESULT OK accepted', b.count, 'dt', b.critical_dt())
    elif case == 'b_twice':
        ids = row3d(); b = servo_bc.Bonds(ids); b2 = servo_bc.Bonds(ids)
        O.engines = [ForceResetter(), b.engine, b2.engine, NewtonIntegrator(damping=0.2)]; O.dt = 1e-7; O.run(10, True)
        print('RESULT OK two Bonds on the same bodies accepted', b.count, b2.count)
    elif case == 'b_erase':
        ids = row3d(); b = servo_bc.Bonds(ids); O.bodies.erase(ids[2]); steps(b, 10); print('RESULT OK body erased after Bonds(): ran on', b.intact())
    elif case == 'b_dt_big':
        ids = row3d(); b = servo_bc.Bonds(ids); O.engines = [ForceResetter(), b.engine, NewtonIntegrator(damping=0)]
        O.dt = 100 * b.critical_dt(); O.bodies[2].state.vel = (0, 0, 1); O.run(2000, True); print('RESULT OK ran at 100x critical dt', b.intact())
    # ---- Cohesive
    elif case == 'c_ctrl':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, LAW); steps(c); print('RESULT OK bonds', c.bonds_initial, 'now', c.bond_count())
    elif case == 'c_words_empty':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, ''); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_words_none':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, None); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_words_short':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, 'kn 1e4'); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_words_nan':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, LAW.replace('fn 1', 'fn nan')); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_words_order':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, 'ks 2e3 kn 1e4 kr 1e-3 fn 1 fs 1 mr 1e-3 mu 0.4'); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_words_extra':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, LAW + ' extra'); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_words_list':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, LAW.split()); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_words_prefixed':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, 'contact cohesive ' + LAW); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_id99':
        ids = lattice2d(); c = servo_bc.Cohesive(ids + [99], LAW); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_idneg':
        ids = lattice2d(); c = servo_bc.Cohesive([-1] + ids, LAW); steps(c); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_dup':
        ids = lattice2d(); c = servo_bc.Cohesive(ids + [ids[4]], LAW); steps(c); print('RESULT OK accepted', c.bonds_initial, c.bond_count())
    elif case == 'c_empty':
        lattice2d(); c = servo_bc.Cohesive([], LAW); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_one':
        ids = lattice2d(); c = servo_bc.Cohesive(ids[:1], LAW); steps(c); print('RESULT OK accepted one disc', c.bonds_initial)
    elif case == 'c_z_offset':
        ids = lattice2d(z=lambda a, b: 0.05 * a); c = servo_bc.Cohesive(ids, LAW); print('RESULT OK discs 5 cm apart in z bonded:', c.bonds_initial)
    elif case == 'c_box':
        ids = lattice2d(); bx = O.bodies.append(utils.box((0.01, 0.01, 0), (1e-3, 1e-3, 1e-3))); c = servo_bc.Cohesive(ids + [bx], LAW); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_erase':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, LAW); O.bodies.erase(ids[4]); steps(c, 10); print('RESULT OK body erased after Cohesive(): ran on', c.bond_count())
    elif case == 'c_nan_pos':
        ids = lattice2d(); O.bodies[ids[4]].state.pos = (nan, 0, 0); c = servo_bc.Cohesive(ids, LAW); print('RESULT OK accepted', c.bonds_initial)
    elif case == 'c_nan_later':
        ids = lattice2d(); c = servo_bc.Cohesive(ids, LAW); O.bodies[ids[4]].state.vel = (nan, 0, 0); steps(c, 10); print('RESULT OK ran with a NaN velocity', c.bond_count())
    else:
        print('RESULT unknown case')
except servo_bc.ServoBCError as e:
    print('RESULT ServoBCError:', e)
except Exception as e:
    print('RESULT %s: %s' % (type(e).__name__, str(e).replace('\n', ' ')[:300]))
