#!/usr/bin/env bash
# fix servo_bc in a 3d LIGGGHTS box on the 4 x 4 x 4 simple cubic lattice of
# tests/liggghts/cubic.in against the closed forms of docs/frame3d.md
# (host_checks.sh, cubic_form): (D) and (P) on the prestressed lattice with
# friction (kt = kn / 2, mu 0.5), 1 and 2 ranks; (T) on the touching
# frictionless lattice; the 3D layer (mixed) on the touching lattice with
# friction, 1 and 2 ranks; a (P) run split by restart. Prints "N passed, N
# failed".
# Usage: cubic.sh LIGGGHTS_SERVO
set -u
BIN=$(cd "$(dirname "${1:?usage: cubic.sh LIGGGHTS_SERVO}")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")" && pwd)
HOST=liggghts DECK=$here/cubic.in TMP=$(mktemp -d)
. "$here/../host_checks.sh"
# 64 spheres of diameter D at the nodes of a 2 mm cubic lattice; the density
# gives each the mass 1e-3 kg (4/3 pi R^3 rho)
lattice_data() {
  awk -v D="$1" 'BEGIN {
    r = D / 2; rho = 1e-3 / (4.0 / 3.0 * 3.14159265358979323846 * r * r * r)
    print "LIGGGHTS data file: 4 x 4 x 4 simple cubic lattice, spacing 2 mm, diameter " D " m, mass 1 g"
    print ""; print "64 atoms"; print "1 atom types"; print ""
    for (a = 0; a < 3; a++) printf "-0.003 0.009 %slo %shi\n", substr("xyz", a + 1, 1), substr("xyz", a + 1, 1)
    print ""; print "Atoms # sphere"; print ""
    for (k = 0; k < 4; k++) for (j = 0; j < 4; j++) for (i = 0; i < 4; i++)
      printf "%d 1 %s %.17g %.17g %.17g %.17g\n", ++n, D, rho, 2e-3 * i, 2e-3 * j, 2e-3 * k
  }'
}
lattice_data 0.00204 > "$TMP/cubic.data"
lattice_data 0.002 > "$TMP/touching.data"
for np in 1 2; do
  cubic_form $np "(D) frictional" prestressed bc D kt 5e3 mu 0.5
  cubic_form $np "(P) frictional" prestressed bc P kt 5e3 mu 0.5
done
cubic_form 1 "(T) frictionless touching" touching bc T data touching.data F11 0.999998 F22 0.999999 F33 1
for np in 1 2; do
  layer3d_form $np data touching.data kt 5e3 mu 0.5
done
# restart in 3d (host_checks.sh, cubic_restart_check): LIGGGHTS keeps neither
# its communication, neighbour and material settings nor the time step
{ printf 'newton off\ncommunicate single vel yes\nneighbor 0.000255 bin\nneigh_modify delay 0\n'
  sed -n '/^fix  *kn /,/^timestep/p' "$DECK"; } > "$TMP/cubic_head.in"
cubic_restart_check "$TMP/cubic_head.in"
restart_corruption_check
host_refusals_3d
screen_none_check
thermo3d_check
rm -rf "$TMP"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
