# Any servo_bc case in YADE, on a packing the runner wrote (`write_packing yade FILE`):
#   yade -n -x inputs/yade/run.py PACKING DENSITY KN KS MU DT servo_bc WORDS...
# DENSITY kg/m^2 (disc mass rho pi R^2), KN KS N/m, MU, DT s; the words after
# `servo_bc` are those of every host (a `frame 2` word takes the flagged frame).
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: the script's folder
from common import args, servo_bc  # noqa: E402

packing, density, kn, ks, mu, dt, keyword, *words = args('PACKING DENSITY KN KS MU DT servo_bc WORDS...', 8)
if keyword != 'servo_bc':
    sys.exit("run.py: expected the word 'servo_bc' before the servo words, got '%s'" % keyword)
servo_bc.run_case(packing, ' '.join(words), density=float(density), kn=float(kn), ks=float(ks), mu=float(mu),
                  dt=float(dt))
