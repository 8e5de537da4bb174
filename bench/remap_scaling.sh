#!/usr/bin/env bash
# DEM steps of one (D) increment against the packing's size, without and with
# `remap x` (docs/servo_bc.md, "Remap"), at each preset (PRESETS, default
# "fast balanced tight"), in the embedded engine; prints the steps and the
# exponent of their growth with the particle count (a least-squares line
# through log steps against log particles).
#   lattices: prestressed frictional N x N squares, F = 0.9999 I
#   irregular: `generate periodic n0 N ... strain 0.01` (mu 0.4), F12 = 1e-4
# Usage: bench/remap_scaling.sh SERVO_BC [LATTICE_SIDES] [IRREGULAR_N0S] [LARGE_SIDES]
#   defaults: "10 20 40 80", "100 400 1600", "316 1000" (the large lattices with remap x only)
set -euo pipefail
presets=${PRESETS:-fast balanced tight}
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
sides=${2:-10 20 40 80}
n0s=${3:-100 400 1600}
large=${4:-316 1000}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
contact='contact frictional kn 1e4 ks 2e3 mu 0.4
density 2e3
timestep 1e-6'
# shared: timed_run, particles, exponent
. "$(dirname "$0")/scaling_lib.sh"
# run NAME PACKING_LINES WORDS: "steps seconds" of the last increment (seconds to one decimal)
run() { timed_run "$1" "$2" "$contact" "$3" relax_steps | awk '{ printf "%s %.1f", $2, $1 }'; }
for preset in $presets; do
printf '%-9s %-10s %10s %12s %8s %12s %8s\n' preset packing particles "steps none" "s" "steps x" "s"
: > "$tmp/lat_none"; : > "$tmp/lat_x"; : > "$tmp/irr_none"; : > "$tmp/irr_x"
for N in $sides; do
  p=$((N * N))
  lat="lattice square $N $N spacing 2e-3 radius 1.02e-3"
  read -r s0 t0 <<< "$(run "lat${N}_none" "$lat" "D F 0.9999 0 0 0.9999 accuracy $preset remap none")"
  read -r s1 t1 <<< "$(run "lat${N}_x" "$lat" "D F 0.9999 0 0 0.9999 accuracy $preset remap x")"
  printf '%-9s %-10s %10d %12s %8s %12s %8s\n' $preset lattice $p "$s0" "$t0" "$s1" "$t1"
  echo "$p $s0" >> "$tmp/lat_none"; echo "$p $s1" >> "$tmp/lat_x"
done
for N in $large; do
  p=$((N * N))
  read -r s1 t1 <<< "$(run "lat${N}_x" "lattice square $N $N spacing 2e-3 radius 1.02e-3" "D F 0.9999 0 0 0.9999 accuracy $preset remap x")"
  printf '%-9s %-10s %10d %12s %8s %12s %8s\n' $preset lattice $p - - "$s1" "$t1"
  echo "$p $s1" >> "$tmp/lat_x"
done
for n0 in $n0s; do
  if [ ! -f "$tmp/irr$n0.txt" ]; then
    printf 'dimension 2\ngenerate periodic n0 %s rmin 1e-3 polydispersity 2 seed 1 strain 0.01\n%s\nwrite_packing text %s/irr%s.txt\n' \
      "$n0" "$contact" "$tmp" "$n0" > "$tmp/gen$n0.sbc"
    "$bin" "$tmp/gen$n0.sbc" > "$tmp/gen$n0.log" 2>&1 || { tail -3 "$tmp/gen$n0.log"; exit 1; }
  fi
  read -r s0 t0 <<< "$(run "irr${n0}_none" "read_packing $tmp/irr$n0.txt" "D F 1 0.0001 0 1 accuracy $preset remap none")"
  read -r s1 t1 <<< "$(run "irr${n0}_x" "read_packing $tmp/irr$n0.txt" "D F 1 0.0001 0 1 accuracy $preset remap x")"
  p=$(particles "$tmp/irr$n0.txt")
  printf '%-9s %-10s %10d %12s %8s %12s %8s\n' $preset irregular "$p" "$s0" "$t0" "$s1" "$t1"
  echo "$p $s0" >> "$tmp/irr_none"; echo "$p $s1" >> "$tmp/irr_x"
done
echo "$preset: growth exponent of the steps per increment in the particle count:"
echo "  lattices: remap none $(exponent < "$tmp/lat_none"), remap x $(exponent < "$tmp/lat_x")"
echo "  irregular: remap none $(exponent < "$tmp/irr_none"), remap x $(exponent < "$tmp/irr_x")"
done
echo "(the seconds include creating a lattice; the irregular packings are generated once, beforehand)"
