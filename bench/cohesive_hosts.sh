#!/usr/bin/env bash
# Cost of the paper's cohesive layer in the hosts (fix servo_bc/bonds cohesive:
# every contact computed by the core) against the embedded engine, measured in
# the same run: the compare case inputs/compare/cohesive_layer_10.sbc (455
# discs, the stress stage and 4 shear increments) on the embedded engine,
# LAMMPS and LIGGGHTS, serial (YADE: ENGINES="embedded lammps liggghts yade",
# some minutes). Prints each engine's DEM steps, wall time, ns per
# particle-step and the ratio to the embedded engine's ns per particle-step.
#   bash bench/cohesive_hosts.sh [OUT]
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
B=${B:-$top/build}
out=${1:-$top/out/bench-cohesive-hosts}
mkdir -p "$out"
ENGINES=${ENGINES:-embedded lammps liggghts} RANKS=1 B=$B \
  bash "$top/scripts/compare.sh" "$top/inputs/compare/cohesive_layer_10.sbc" "$out" > "$out.log" 2>&1 ||
  echo "cohesive_hosts: not every engine finished (see $out.log)"
awk -F'|' '$2 ~ /^ (embedded|lammps|liggghts|yade) $/ && $3 + 0 > 0 {
    gsub(/ /, "", $2); ns[$2] = $6 + 0; line[$2] = sprintf("%-9s %7d steps %8.2f s %9.0f ns per particle-step", $2, $5, $4, $6) }
  END { for (e in line) printf "%s  %.2fx the embedded engine\n", line[e], (ns["embedded"] > 0 ? ns[e] / ns["embedded"] : 0) }' \
  "$out/report.md" | sort
