#!/usr/bin/env bash
# fix servo_bc in a 3d LIGGGHTS box: (D) on the prestressed 4 x 4 x 4 simple
# cubic lattice of tests/liggghts/cubic.in on 1 and 2 ranks against the
# closed form of docs/frame3d.md (host_checks.sh, cubic_form); refused 3d input.
# Prints "N passed, N failed".
# Usage: cubic_D.sh LIGGGHTS_SERVO
set -u
BIN=$(cd "$(dirname "${1:?usage: cubic_D.sh LIGGGHTS_SERVO}")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")" && pwd)
HOST=liggghts DECK=$here/cubic.in TMP=$(mktemp -d)
. "$here/../host_checks.sh"
# 64 spheres of diameter 2.04 mm at the nodes of a 2 mm cubic lattice; the
# density gives each the mass 1e-3 kg (4/3 pi R^3 rho)
awk 'BEGIN {
  r = 1.02e-3; rho = 1e-3 / (4.0 / 3.0 * 3.14159265358979323846 * r * r * r)
  print "LIGGGHTS data file: 4 x 4 x 4 simple cubic lattice, spacing 2 mm, diameter 2.04 mm, mass 1 g"
  print ""; print "64 atoms"; print "1 atom types"; print ""
  for (a = 0; a < 3; a++) printf "-0.003 0.009 %slo %shi\n", substr("xyz", a + 1, 1), substr("xyz", a + 1, 1)
  print ""; print "Atoms # sphere"; print ""
  for (k = 0; k < 4; k++) for (j = 0; j < 4; j++) for (i = 0; i < 4; i++)
    printf "%d 1 0.00204 %.17g %.17g %.17g %.17g\n", ++n, rho, 2e-3 * i, 2e-3 * j, 2e-3 * k
}' > "$TMP/cubic.data"
cubic_form 1
cubic_form 2
deck_with 's/servo_bc D F/servo_bc P F/' "$TMP/p.in"
refused_deck "(P) in a 3d box" p.in "this version imposes (D) alone in a 3d box (P is 2d"
rm -rf "$TMP"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
