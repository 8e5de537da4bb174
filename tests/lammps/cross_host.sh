#!/usr/bin/env bash
# Same packing, same settings: fix servo_bc in LAMMPS (build/lmp_servo) against
# the embedded engine (build/servo-bc), the paper's regular packing of SIDE x SIDE
# particles under the first INCREMENTS of the 300 increments of eq. 38
# (F = I + (INCREMENTS/300)(F - I)), servo-active gains, for (D), (P) and (T).
# Every converged increment: every sigma component within 0.5 % of the stress
# scale (max |sigma| of the run). Prints "N passed, N failed".
# Usage: cross_host.sh LMP_SERVO SERVO_BC [SIDE [INCREMENTS]]   (defaults 10, 30:
# 100 particles up to -F12 = 0.1, before the first stress peak)
set -u
lmp=$(cd "$(dirname "${1:?usage: cross_host.sh LMP_SERVO SERVO_BC}")" && pwd)/$(basename "$1")
emb=$(cd "$(dirname "${2:?usage: cross_host.sh LMP_SERVO SERVO_BC}")" && pwd)/$(basename "$2")
side=${3:-10} inc=${4:-30}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
pass=0 fail=0
F=$(awk -v t="$inc" 'BEGIN { t /= 300; printf "%.17g %.17g %.17g %.17g", 1 - 0.03 * t, -0.3 * t, -0.3 * t, 1 - 0.03 * t }')
SERVO="F $F increments $inc relax 1e-3 20 gain_force 1e5 gain_moment 1e5 gain_deformation 1e-2 tol_force 1e-9 tol_moment 1e-9 tol_deformation 1e-3"
for bc in D P T; do
  cat > "$tmp/$bc.sbc" <<SBC
dimension 2
lattice square $side $side spacing 2.0e-3 radius 1.02e-3
contact frictional kn 1e4 ks 2e3 mu 0.4
density 2e3
timestep 1e-6
servo_bc $bc $SERVO file $tmp/emb_$bc.csv
run
SBC
  cat > "$tmp/$bc.in" <<LMP
units           si
dimension       2
boundary        f f p
atom_style      sphere
lattice         sq 0.002
region          box block -2 $((side + 2)) -2 $((side + 2)) -0.5 0.5
region          packing block -0.5 $((side - 1)).5 -0.5 $((side - 1)).5 -0.5 0.5
create_box      1 box
create_atoms    1 region packing
set             type 1 diameter 0.00204
set             type 1 mass 6.5370259935896430e-3   # rho pi R^2: "set density" would give the 3d mass
pair_style      gran/hooke/history 1e4 2e3 0 0 0.4 0
pair_coeff      * *
comm_modify     vel yes
neighbor        0.000255 bin
neigh_modify    delay 0 every 1 check yes
timestep        1e-6
fix             servo all servo_bc $bc $SERVO file $tmp/lmp_$bc.csv
fix             integrate servo_interior nve/sphere disc
fix             plane all enforce2d
thermo          1000000
run             10000000
LMP
  "$emb" "$tmp/$bc.sbc" > "$tmp/emb_$bc.log" 2>&1 || { echo "servo-bc $bc failed:"; tail -3 "$tmp/emb_$bc.log"; }
  (cd "$tmp" && "$lmp" -in "$bc.in" -log none > "lmp_$bc.log" 2>&1) || { echo "lmp_servo $bc failed:"; tail -3 "$tmp/lmp_$bc.log"; }
  res=$(paste -d, "$tmp/emb_$bc.csv" "$tmp/lmp_$bc.csv" | awk -F, -f "$here/../sigma_diff.awk")
  set -- $res
  if [ "${1:-0}" = $((inc + 1)) ] && awk -v e="${2:-100}" 'BEGIN { exit !(e <= 0.5) }'; then
    pass=$((pass + 1)); echo "cross-host ($bc), $((side * side)) particles: $((inc + 1)) increments, max |sigma_lammps - sigma_embedded| = $2 % of the stress scale"
  else
    fail=$((fail + 1)); echo "FAIL cross-host ($bc): increments ${1:-0}, max difference ${2:-?} % of the stress scale"
  fi
done
rm -rf "$tmp"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
