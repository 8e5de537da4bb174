#!/usr/bin/env bash
# Cost of the 3D bonded particle model (issue 8, docs/reproduction-bpm.md):
# one uniaxial compression test at r_p = 5 mm (10000 steps, Table 4's
# loading) per packing and bond model, on one core. Prints, per run: spheres,
# bonds, wall time of the whole test (packing, bonding, run), ns per
# sphere-step and per bond-step of the run, and the beam-to-parallel-bond cost
# ratio per packing (the thesis: the Timoshenko beam about 2x slower).
#   bash bench/bpm.sh [OUT]      (default out/bench-bpm)
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
B=${B:-$top/build}
out=${1:-$top/out/bench-bpm}
mkdir -p "$out"
{
printf '| packing | bond | spheres | bonds | test wall time (s) | ns per sphere-step | ns per bond-step |\n'
printf '| --- | --- | ---: | ---: | ---: | ---: | ---: |\n'
for packing in cubic hcp random; do
  extra="" touch=""
  [ "$packing" = random ] && extra="porosity 0.41 seed 1" && touch="touch 0.05"
  for bond in parallel beam; do
    case $bond in parallel) law="bond parallel E 4e9 ratio 4.2 $touch" ;; beam) law="bond beam E 4e9 nu 0.3 $touch" ;; esac
    cat > "$out/${packing}_$bond.sbc" <<CASE
dimension 3
packing $packing radius 5e-3 $extra
$law
density 925 scaled
timestep critical 0.6
test uniaxial velocity -1e-5 steps 10000
run
CASE
    t0=$(date +%s.%N)
    "$B/servo-bc" "$out/${packing}_$bond.sbc" > "$out/${packing}_$bond.log" 2>&1 || { echo "bench/bpm: ${packing} $bond failed"; continue; }
    t1=$(date +%s.%N)
    awk -v p="$packing" -v b="$bond" -v t0="$t0" -v t1="$t1" '
      /packing,/ { for (i = 1; i <= NF; ++i) { if ($i == "spheres") n = $(i - 1); if ($i == "bonds") nb = $(i - 1) } }
      / ns per bond-step/ { split($0, a, ": "); split(a[3], c, " "); sph = c[1]; split($0, d, ", "); split(d[2], e, " "); bnd = e[1] }
      END { printf "| %s | %s | %s | %s | %.1f | %s | %s |\n", p, b, n, nb, t1 - t0, sph, bnd }' "$out/${packing}_$bond.log"
  done
done
} | tee "$out/table.md"
awk -F'|' '{ gsub(/ /, "", $2); gsub(/ /, "", $3); c[$2, $3] = $8 } END {
  n = split("cubic hcp random", p, " ")
  for (i = 1; i <= n; ++i) if (c[p[i], "parallel"] > 0) printf "beam / parallel bond cost per bond-step, %s: %.2f\n", p[i], c[p[i], "beam"] / c[p[i], "parallel"] }' "$out/table.md"
