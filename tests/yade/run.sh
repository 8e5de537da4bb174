#!/usr/bin/env bash
# The YADE engine (yade_adapter/servo_bc.py over the core's shared library),
# against the Debian YADE package: the closed-form lattice (D) and (P) and the
# refusals (closed_form.py), (D), (P), (T) in 3D (cubic.py); bad words in batch mode end the process non-zero
# with the core's message. YADE beside the other engines on the same case is
# tests/cross_host.sh (make check-cross-host).
# Prints "N passed, N failed".
# Usage: run.sh LIBSERVO_BC.so SERVO_BC
set -u
lib=$(cd "$(dirname "${1:?usage: run.sh LIBSERVO_BC.so SERVO_BC}")" && pwd)/$(basename "$1")
emb=$(cd "$(dirname "${2:?usage: run.sh LIBSERVO_BC.so SERVO_BC}")" && pwd)/$(basename "$2")
export SERVO_BC_LIB=$lib
here=$(cd "$(dirname "$0")" && pwd)
run=$here/../../inputs/yade/run.py
tmp=$(mktemp -d)
pass=0 fail=0
lattice() {  # side file
  printf 'dimension 2\nlattice square %s %s spacing 2.0e-3 radius 1.02e-3\nwrite_packing yade %s\n' "$1" "$1" "$2" > "$tmp/w.sbc"
  "$emb" "$tmp/w.sbc" > /dev/null
}
lattice 5 "$tmp/l5.yade"
yade -n -x "$here/closed_form.py" "$tmp/l5.yade" > "$tmp/closed.log" 2>&1
grep -E '^(FAIL )?yade ' "$tmp/closed.log"
counts=$(awk '/ passed, .* failed$/ { print $1, $3 }' "$tmp/closed.log")
set -- ${counts:-0 1}
pass=$((pass + $1)) fail=$((fail + $2))
[ -n "$counts" ] || { echo "FAIL yade closed_form.py did not finish:"; tail -5 "$tmp/closed.log"; }

# 3D: (D), (P) and (T) on the 4^3 lattices against their closed forms, and the refusals
yade -n -x "$here/cubic.py" > "$tmp/cubic.log" 2>&1
grep -E '^(FAIL )?yade ' "$tmp/cubic.log"
counts=$(awk '/ passed, .* failed$/ { print $1, $3 }' "$tmp/cubic.log")
set -- ${counts:-0 1}
pass=$((pass + $1)) fail=$((fail + $2))
[ -n "$counts" ] || { echo "FAIL yade cubic.py did not finish:"; tail -5 "$tmp/cubic.log"; }

# batch mode: a Python exception with the core's message, and a non-zero exit
yade -n -x "$run" "$tmp/l5.yade" 2e3 1e4 2e3 0.4 1e-5 servo_bc D F 1 2 2 1 > "$tmp/bad.log" 2>&1
status=$?
if [ $status -ne 0 ] && grep -q "ServoBCError: servo_bc: keyword 'F': det F = -3 is not positive" "$tmp/bad.log"; then
  pass=$((pass + 1)); echo "yade batch mode: exit status $status, ServoBCError names the keyword and value"
else
  fail=$((fail + 1)); echo "FAIL yade batch mode with bad words (exit $status):"; tail -3 "$tmp/bad.log"
fi

# the thesis' Appendix B beam through the core's bonds (servo_bc.Bonds, bpm_host.h):
# the midspan deflection of eq. B1 to 1e-4, and Table B1's delta_DEM (mm, 5 digits)
beam=$here/../../inputs/yade/bpm_beam.py
for pair in 3:0.0065436 5:0.038551 7:0.12148 11:0.54201; do
  n=${pair%%:*} thesis=${pair#*:}
  yade -n -x "$beam" "$n" "$tmp/beam_$n.txt" > "$tmp/beam_$n.log" 2>&1
  got=$(awk '$1 == "deflection" { print $2 }' "$tmp/beam_$n.txt" 2>/dev/null)
  verdict=$(awk -v n="$n" -v d="${got:-none}" -v t="$thesis" 'BEGIN {
      R = 0.1; E = 4e9; nu = 0.3; G = E / (2 * (1 + nu)); pi = atan2(0, -1); I = pi * R^4 / 4; A = pi * R * R
      Le = 2 * R * (n - 1); b1 = 1e3 * Le^3 / (48 * E * I) + 1e3 * Le * (10 / 9) / (4 * G * A)
      e1 = (d - b1) / b1; e2 = (1e3 * d - t) / t; if (e1 < 0) e1 = -e1; if (e2 < 0) e2 = -e2
      printf "%s %.3g %.3g %.9g", (d == d + 0 && e1 <= 1e-4 && e2 <= 1.5e-4) ? "ok" : "bad", e1, e2, b1 }')
  set -- $verdict
  if [ "$1" = ok ]; then
    pass=$((pass + 1)); echo "yade beam of $n spheres: deflection $got m, eq. B1 $4 m (relative $2), Table B1 $thesis mm (relative $3)"
  else
    fail=$((fail + 1)); echo "FAIL yade beam of $n spheres: deflection ${got:-none} m against eq. B1 $4 m:"; tail -3 "$tmp/beam_$n.log"
  fi
done
yade -n -x "$here/../../inputs/yade/bpm_uniaxial.py" 5 3 3 "$tmp/uni.txt" > "$tmp/uni.log" 2>&1
got=$(awk '$1 == "modulus" { print $2 }' "$tmp/uni.txt" 2>/dev/null)
if awk -v e="${got:-none}" 'BEGIN { t = atan2(0, -1) * 4e9 / 4; d = (e - t) / t; if (d < 0) d = -d; exit !(e == e + 0 && d <= 1e-6) }'; then
  pass=$((pass + 1)); echo "yade uniform packing 5 x 3 x 3 under uniaxial tension: E = $got Pa, pi E_b / 4 = 3141592653.6 Pa"
else
  fail=$((fail + 1)); echo "FAIL yade uniform packing: E = ${got:-none} Pa against pi E_b / 4:"; tail -3 "$tmp/uni.log"
fi
# the user's cohesive layer deck (servo_bc.Cohesive) on the 37-disc layer, 2 shear
# increments, 8 times Table 6's strengths: every row, some bonds broken, and
# a bad law word refused by keyword
(cd "$tmp" && yade -n -x "$here/../../inputs/yade/cohesive_layer.py" "$tmp/coh.csv" 25 2 8 > "$tmp/coh.log" 2>&1)
intact=$(grep -a -o 'bonds intact [0-9]* of 54' "$tmp/coh.log" | awk '{ print $3 }')
if [ "$(wc -l < "$tmp/coh.csv" 2>/dev/null)" = 10 ] && [ -n "$intact" ] && [ "$intact" -lt 54 ] && [ "$intact" -gt 0 ]; then
  pass=$((pass + 1)); echo "yade cohesive layer deck: 9 rows, bonds intact $intact of 54"
else
  fail=$((fail + 1)); echo "FAIL yade cohesive layer deck:"; tail -3 "$tmp/coh.log"
fi
cat > "$tmp/bad_cohesive.py" <<PY
import sys
sys.path.insert(0, '$here/../../yade_adapter')
import servo_bc
from yade import O, utils
O.bodies.append([utils.sphere((0, 0, 0), 1e-3), utils.sphere((2e-3, 0, 0), 1e-3)])
servo_bc.Cohesive([0, 1], 'kn 1e8 ks 4e7 kr 20 fn 300 fs sixty mr 0.2 mu 0.6')
PY
yade -n -x "$tmp/bad_cohesive.py" > "$tmp/bad_cohesive.log" 2>&1
status=$?
if [ $status -ne 0 ] && grep -q "cohesive: fs 'sixty' is not a number (expected a real > 0)" "$tmp/bad_cohesive.log"; then
  pass=$((pass + 1)); echo "yade Cohesive refuses a word for a strength (exit $status), by keyword"
else
  fail=$((fail + 1)); echo "FAIL yade Cohesive with fs 'sixty' (exit $status):"; tail -3 "$tmp/bad_cohesive.log"
fi
# a bond that fails (servo_bc.Bonds strength): a parallel bond between two
# spheres (r = 0.1 m, axial stiffness K = E pi r / 2) pulled apart at 1e-6 m per
# step breaks once K d >= 1e5 N (d = 1.6e-4 m; checked intact after 150 steps
# and broken after 170: O.forces after 10 steps shows 9 increments, and the
# bond is still intact after 160) and leaves K d^2 / 2 dissipated (eq. 51)
cat > "$tmp/break.py" <<PY
import math, sys
sys.path.insert(0, '$here/../../yade_adapter')
import servo_bc
from yade import O, utils
from yade.wrapper import ForceResetter, NewtonIntegrator
a = O.bodies.append(utils.sphere((0, 0, 0), 0.1))
b = O.bodies.append(utils.sphere((0.2, 0, 0), 0.1))
for i in (a, b):
    O.bodies[i].state.blockedDOFs = 'xyzXYZ'
O.bodies[b].state.vel = (0.01, 0, 0)
bonds = servo_bc.Bonds([a, b], 'parallel', E=4e9, nu=0.3, alpha=1.0, strength=(1e5, 0, 0, 0), friction=0.5)
O.engines = [ForceResetter(), bonds.engine, NewtonIntegrator(damping=0.0)]
O.dt = 1e-4
O.run(150, True)
before = bonds.intact()
O.run(20, True)
K = 4e9 * math.pi * 0.1 / 2
print('break %d %d %.17g %.17g' % (before, bonds.intact(), bonds.dissipated(), K * 1.6e-4 ** 2 / 2))
PY
yade -n -x "$tmp/break.py" > "$tmp/break.log" 2>&1
if awk '$1 == "break" { e = ($4 - $5) / $5; if (e < 0) e = -e; ok = $2 == 1 && $3 == 0 && e <= 1e-9 } END { exit !ok }' "$tmp/break.log"; then
  pass=$((pass + 1)); echo "yade Bonds with a strength: the bond breaks at d = 1.6e-4 m holding K d^2/2 = $(awk '$1 == "break" { print $5 }' "$tmp/break.log") J (eq. 51)"
else
  fail=$((fail + 1)); echo "FAIL yade Bonds with a strength:"; tail -3 "$tmp/break.log"
fi
yade -n -x "$beam" 4 "$tmp/beam_4.txt" > "$tmp/beam_4.log" 2>&1
status=$?
if [ $status -ne 0 ] && grep -q "N must be odd and at least 3, got 4" "$tmp/beam_4.log"; then
  pass=$((pass + 1)); echo "yade beam refuses an even N (exit $status)"
else
  fail=$((fail + 1)); echo "FAIL yade beam with N = 4 (exit $status):"; tail -3 "$tmp/beam_4.log"
fi

# Bonds and Cohesive refuse bodies by name (tests/reliability/yade_bodies.py: the
# round-3 reproducers), and the controls run
bodies=$here/../reliability/yade_bodies.py
for item in "b_ctrl:RESULT OK bonds 4 intact 4" "c_ctrl:RESULT OK bonds 12 now 12" \
            "b_idneg:body -1 does not exist" "c_idneg:body -1 does not exist" "b_dup:body 0 is listed twice" \
            "c_dup:body 4 is listed twice" "b_twice:which would bond it twice" "b_erase:body 2 was erased" \
            "c_erase:body 4 was erased" "c_z_offset:the cohesive law is 2D"; do
  case_name=${item%%:*} expect=${item#*:}
  result=$(cd "$tmp" && timeout 120 yade -n -x "$bodies" "$case_name" 2>&1 | grep -m1 '^RESULT')
  if [[ "$result" == *"$expect"* ]]; then
    pass=$((pass + 1)); echo "yade $case_name: $(echo "$result" | cut -c1-150)"
  else
    fail=$((fail + 1)); echo "FAIL yade $case_name: expected '$expect', got: ${result:-nothing}"
  fi
done

rm -rf "$tmp"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
