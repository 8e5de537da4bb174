#!/usr/bin/env bash
# The servo's update rules side by side (docs/servo_bc.md, "Newton"): `update
# secant` (the presets') against `update newton` at the same preset, on the
# cases of docs/speed-accuracy.md with the default words, in the embedded
# runner. Prints per case and rule the DEM steps, the servo iterations per
# increment (mean, max), the wall time, and the largest difference of the two
# rules' P̄ over the path relative to its stress scale (the largest |P̄ij|).
#   regular_P, regular_T: the 100-disc regular packing (Sect. 4.1), eq. 38 to
#     F12 = -0.02 in 20 increments (the sweep's increment size)
#   irregular_P: the 232-disc periodic packing (Sect. 4.2) compressed by
#     `strain 0.01`, F12 to 0.05 in 10 increments, `seal yes` (the case of
#     bench/replicas_spread.sh, whose spread of the path the difference is
#     to be read against)
#   frictionless_P: the same packing with mu 0 and ks 0 (one equilibrium: the
#     rules' rows agree within the preset's accuracy), F12 to 0.002 in 2, before the
#     first rearrangement (further on, frictionless paths part too)
# Usage: bench/newton_servo.sh SERVO_BC [PRESET]     (default balanced)
set -euo pipefail
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
preset=${2:-balanced}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
regular='lattice square 10 10 spacing 2.0e-3 radius 1.02e-3'
frictional='contact frictional kn 1e4 ks 2e3 mu 0.4'
frictionless='contact frictional kn 1e4 ks 0 mu 0'
printf 'dimension 2\ngenerate periodic n0 200 rmin 0.67e-3 polydispersity 2 seed 1 strain 0.01\nwrite_packing text %s/irregular.txt\n' \
  "$tmp" > "$tmp/make.sbc"
(cd "$tmp" && "$bin" make.sbc > make.log 2>&1) || { tail -3 "$tmp/make.log"; exit 1; }
irregular="read_packing $tmp/irregular.txt"
# run NAME PACKING CONTACT DT WORDS: "steps mean max wall" of the run
run() {
  printf 'dimension 2\n%s\n%s\ndensity 2e3\ntimestep %s\nservo_bc %s accuracy %s file %s/%s.csv\nrun\n' \
    "$2" "$3" "$4" "$5" "$preset" "$tmp" "$1" > "$tmp/$1.sbc"
  local t0 t1
  t0=$(date +%s.%N)
  if ! (cd "$tmp" && "$bin" "$1.sbc" > "$1.log" 2>&1); then
    echo "stopped: $(tail -n 1 "$tmp/$1.log")"
    return 0
  fi
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" '/^servo_bc: finished/ { for (i = 1; i <= NF; i++) { if ($i == "steps,") s = $(i - 1);
    if ($i == "mean") m = $(i + 1); if ($i == "max") x = $(i + 1) } }
    END { sub(",", "", x); printf "%s %s %s %.1f", s, m, x, b - a }' "$tmp/$1.log"
}
# difference of two runs' P over their common rows, of the stress scale of the first
difference() {
  awk -F, 'FNR == 1 { for (c = 1; c <= NF; c++) col[$c] = c; next }
    NR == FNR { for (k = 0; k < 4; k++) { v = $col[name[k]]; a[FNR, k] = v; if (v < 0) v = -v; if (v > s) s = v }; next }
    { for (k = 0; k < 4; k++) if ((FNR, k) in a) { d = $col[name[k]] - a[FNR, k]; if (d < 0) d = -d; if (d > m) m = d } }
    BEGIN { name[0] = "P11"; name[1] = "P12"; name[2] = "P21"; name[3] = "P22" }
    END { if (s > 0) printf "%.2e", m / s; else print "-" }' "$1" "$2"
}
printf '%-15s %-7s %10s %10s %6s %8s %14s\n' case update steps "iter mean" max "wall s" "P difference"
for c in "regular_P|$regular|$frictional|3e-4|P F 0.998 -0.02 -0.02 0.998 increments 20" \
         "regular_T|$regular|$frictional|3e-4|T F 0.998 -0.02 -0.02 0.998 increments 20" \
         "irregular_P|$irregular|$frictional|7.5e-5|P F 1 0.05 0 1 increments 10 seal yes" \
         "frictionless_P|$irregular|$frictionless|7.5e-5|P F 1 0.002 0 1 increments 2 seal yes"; do
  IFS='|' read -r name packing contact dt words <<< "$c"
  for rule in secant newton; do
    set -- $(run "${name}_$rule" "$packing" "$contact" "$dt" "$words update $rule")
    diff=-
    [ "$rule" = newton ] && [ -f "$tmp/${name}_secant.csv" ] && [ -f "$tmp/${name}_newton.csv" ] &&
      diff=$(difference "$tmp/${name}_secant.csv" "$tmp/${name}_newton.csv")
    printf '%-15s %-7s %10s %10s %6s %8s %14s\n' "$name" "$rule" "$1" "${2:-}" "${3:-}" "${4:-}" "$diff"
  done
done
