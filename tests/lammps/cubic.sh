#!/usr/bin/env bash
# fix servo_bc in a 3d LAMMPS box on the 4 x 4 x 4 simple cubic lattice of
# tests/lammps/cubic.in against the closed forms of docs/frame3d.md
# (host_checks.sh, cubic_form): (D) and (P) on the prestressed lattice with
# friction (kt = kn / 2, mu 0.5), 1 and 2 ranks; (T) on the touching
# frictionless lattice; the stress stage of the 3D layer (mixed) on the
# touching lattice with friction, 1 and 2 ranks; refused 3d input. Prints "N passed, N failed".
# Usage: cubic.sh LMP_SERVO
set -u
BIN=$(cd "$(dirname "${1:?usage: cubic.sh LMP_SERVO}")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")" && pwd)
HOST=lammps DECK=$here/cubic.in TMP=$(mktemp -d)
. "$here/../host_checks.sh"
for np in 1 2; do
  cubic_form $np "(D) frictional" prestressed bc D kt 5e3 mu 0.5
  cubic_form $np "(P) frictional" prestressed bc P kt 5e3 mu 0.5
done
cubic_form 1 "(T) frictionless touching" touching bc T diameter 0.002 F11 0.999998 F22 0.999999 F33 1
for np in 1 2; do
  layer3d_form $np diameter 0.002 kt 5e3 mu 0.5
done
# restart in 3d (host_checks.sh, cubic_restart_check); the per-atom array's
# 4 columns in a dump
printf 'comm_modify vel yes\nneighbor 0.000255 bin\nneigh_modify delay 0 every 1 check yes\n' > "$TMP/cubic_head.in"
cubic_restart_check "$TMP/cubic_head.in"
restart_corruption_check
host_refusals_3d
screen_none_check
thermo3d_check
{ cat "$DECK"; echo "write_dump all custom $TMP/cubic_atoms.txt id f_servo[1] f_servo[2] f_servo[3] f_servo[4] modify sort id"; } \
  > "$TMP/cubic_dump.in"
run_deck 1 cubic_dump.in "$TMP/cubic_dump.csv" "$TMP/cubic_dump.log" bc P kt 5e3 mu 0.5
dumped=$(awk 'f && NF == 5 { n++; flags += $2; if ($3 != $3 + 0 || $5 != $5 + 0) bad++ } /^ITEM: ATOMS/ { f = 1 }
  END { printf "%d %d %d", n, flags, bad }' "$TMP/cubic_atoms.txt" 2>/dev/null)
if [ "$dumped" = "64 56 0" ]; then
  ok "3d dump: f_servo[1] flags the 56 frame atoms of 64, f_servo[2..4] the rotation vector on every atom"
else
  no "3d dump: atoms, frame flags, bad values: ${dumped:-none} (expected 64 56 0)"
fi
# refused in a 3d box: keyword frame (2d in this version; the 3d frame is
# found from the centres), mixed words of 2D
deck_with 's/accuracy tight/accuracy tight frame all/' "$TMP/frame.in"
refused_deck "keyword frame in a 3d box" frame.in "keyword 'frame' is 2d in this version; the box is 3d"
deck_with 's/servo_bc ${bc} F .* increments/servo_bc mixed stress P22 -1 1 increments/' "$TMP/mixed.in"
refused_deck "mixed words of 2D in a 3d box" mixed.in "the packing is 3D but the words are 2D: give F with nine values"
rm -rf "$TMP"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
