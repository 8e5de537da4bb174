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
# refused in a 3d box: keyword seal (2d in this version), mixed words of 2D
deck_with 's/accuracy tight/accuracy tight seal yes/' "$TMP/seal.in"
refused_deck "keyword seal in a 3d box" seal.in "keyword 'seal' is 2d in this version; the box is 3d"
deck_with 's/servo_bc ${bc} F .* increments/servo_bc mixed stress P22 -1 1 increments/' "$TMP/mixed.in"
refused_deck "mixed words of 2D in a 3d box" mixed.in "the packing is 3D but the words are 2D: give F with nine values"
rm -rf "$TMP"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
