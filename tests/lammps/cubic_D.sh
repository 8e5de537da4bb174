#!/usr/bin/env bash
# fix servo_bc in a 3d LAMMPS box: (D) on the prestressed 4 x 4 x 4 simple
# cubic lattice of tests/lammps/cubic.in on 1 and 2 ranks against the closed
# form of docs/frame3d.md (host_checks.sh, cubic_form); refused 3d input.
# Prints "N passed, N failed".
# Usage: cubic_D.sh LMP_SERVO
set -u
BIN=$(cd "$(dirname "${1:?usage: cubic_D.sh LMP_SERVO}")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")" && pwd)
HOST=lammps DECK=$here/cubic.in TMP=$(mktemp -d)
. "$here/../host_checks.sh"
cubic_form 1
cubic_form 2
# refused in a 3d box: (P) and keyword seal (2d in this version)
deck_with 's/servo_bc D F/servo_bc P F/' "$TMP/p.in"
refused_deck "(P) in a 3d box" p.in "this version imposes (D) alone in a 3d box (P is 2d"
deck_with 's/accuracy tight/accuracy tight seal yes/' "$TMP/seal.in"
refused_deck "keyword seal in a 3d box" seal.in "keyword 'seal' is 2d in this version; the box is 3d"
rm -rf "$TMP"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
