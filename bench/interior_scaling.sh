#!/usr/bin/env bash
# interior newton against interior dynamic (docs/servo_bc.md, "Interior"): wall
# time and DEM steps of a run of two certified increments (increment 0 at F = I,
# then F12 = 1e-4) on irregular frictional packings (`generate periodic n0 N
# rmin 1e-3 polydispersity 2 seed 1 strain 0.01`, mu 0.4, dt 1e-6 s) under (D)
# and (P), both measured in the same run; prints the ratio of wall times and the
# growth exponent of newton's wall time with the particle count (least squares
# of log time on log particles).
# Usage: bench/interior_scaling.sh SERVO_BC [N0S] [PRESET]
#   defaults: "100 400 1600", balanced. DYNAMIC_P_MAX (default 400): the largest
#   n0 whose (P) case also runs dynamically (the 1 677-disc one takes tens of
#   minutes); generating n0 1600 takes about 2 minutes, 6400 about 20.
#   DIMENSION=3: sphere packings instead (`generate periodic n0 N rmin 1e-3
#   polydispersity 1.5 seed 1 strain 0.01`, ks 5e3 N/m, mu 0.5, density 2650,
#   dt 9e-6 s), F13 = 1e-4; defaults "100 300 600". PROTOCOL=pressure: the
#   packings by `generate ... protocol pressure` (10^4 discs in 9 s, 10^5 in
#   96 s; docs/benchmarks.md, "The packing generator").
set -euo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
export DIMENSION=${DIMENSION:-2}
if [ "$DIMENSION" = 3 ]; then n0s=${2:-100 300 600}; else n0s=${2:-100 400 1600}; fi
preset=${3:-balanced}
dyn_p_max=${DYNAMIC_P_MAX:-400}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
contact='contact frictional kn 1e4 ks 2e3 mu 0.4
density 2e3
timestep 1e-6'
generate="polydispersity 2 seed 1 strain 0.01 protocol ${PROTOCOL:-shrink}"
shear='F 1 0.0001 0 1'
if [ "$DIMENSION" = 3 ]; then
  contact='contact frictional kn 1e4 ks 5e3 mu 0.5
density 2650
timestep 9e-6'
  generate="polydispersity 1.5 seed 1 strain 0.01 protocol ${PROTOCOL:-shrink}"
  shear='F 1 0 0.0001 0 1 0 0 0 1'
fi
# shared: timed_run, particles, exponent
. "$(dirname "$0")/scaling_lib.sh"
# run NAME PACKING WORDS: "seconds steps newton_iterations" (the steps and iterations of increment 1)
run() { timed_run "$1" "read_packing $2" "$contact" "$3" relax_steps newton_iterations; }
printf '%-3s %9s %12s %10s %12s %10s %8s %9s\n' BC particles "dynamic (s)" steps "newton (s)" steps "Newton" ratio
for bc in D P; do
  : > "$tmp/growth"
  for n0 in $n0s; do
    pk="$tmp/irr$n0.txt"
    if [ ! -f "$pk" ]; then
      printf 'dimension %s\ngenerate periodic n0 %s rmin 1e-3 %s\n%s\nwrite_packing text %s\n' \
        "$DIMENSION" "$n0" "$generate" "$contact" "$pk" > "$tmp/gen$n0.sbc"
      "$bin" "$tmp/gen$n0.sbc" > "$tmp/gen$n0.log" 2>&1 || { tail -3 "$tmp/gen$n0.log"; exit 1; }
    fi
    p=$(particles "$pk")
    words="$bc $shear accuracy $preset"
    read -r tn sn kn <<< "$(run "n${bc}$n0" "$pk" "$words interior newton")"
    if [ "$bc" = D ] || [ "$n0" -le "$dyn_p_max" ]; then
      read -r td sd _ <<< "$(run "d${bc}$n0" "$pk" "$words interior dynamic")"
      ratio=$(awk -v a="$td" -v b="$tn" 'BEGIN { printf "%.1f", a / b }')
    else
      td=-; sd=-; ratio=-
    fi
    printf '%-3s %9d %12s %10s %12s %10s %8s %9s\n' "$bc" "$p" "$td" "$sd" "$tn" "$sn" "$kn" "$ratio"
    echo "$p $tn" >> "$tmp/growth"
  done
  echo "$bc: newton's wall time grows as N^$(exponent < "$tmp/growth") over these sizes (preset $preset)"
done
