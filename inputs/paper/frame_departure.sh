#!/usr/bin/env bash
# How far the frame has left the homogeneous deformation between two
# snapshots of one run: for every frame disc q, |x_q(1) - dF x_q(0)| / R_q,
# where dF = I + DF12 e1 (x) e2 carries the first snapshot's centres to the
# second's under simple shear (eq. 40). (D) gives 0; a (T) whose servo barely
# acts stays near 0; a free (T) frame that gives way at a corner does not.
#   frame_departure.sh PARTICLES0.vtk PARTICLES1.vtk DF12
# prints: largest departure (radii), its particle index, mean departure (radii)
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: frame_departure.sh PARTICLES0.vtk PARTICLES1.vtk DF12" >&2; exit 2; }
awk -v df="$3" '
  FNR == 1 { file++ }
  $1 == "POINTS" { n = $2; row = FNR; block = "x"; next }
  block == "x" && FNR > row && FNR <= row + n { x[file, FNR - row - 1] = $1; y[file, FNR - row - 1] = $2; next }
  $1 == "SCALARS" { block = $2; row = FNR + 1; next }
  (block == "radius" || block == "frame") && FNR > row && FNR <= row + n { v[block, FNR - row - 1] = $1 }
  END {
    for (k = 0; k < n; k++) {
      if (!v["frame", k]) continue
      d = sqrt((x[2, k] - x[1, k] - df * y[1, k])^2 + (y[2, k] - y[1, k])^2) / v["radius", k]
      sum += d; q++
      if (d > max) { max = d; at = k }
    }
    printf "%.3g %d %.3g\n", max, at, sum / q
  }' "$1" "$2"
