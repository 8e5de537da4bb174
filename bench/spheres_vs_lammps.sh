#!/usr/bin/env bash
# The embedded sphere engine against LAMMPS gran/hooke/history on the identical
# 3D lattice scene, in one run: ns per particle-step for both and the ratio
# embedded/LAMMPS, at 22^3 (10 648) and 46^3 (97 336) spheres.
# Usage: bench/spheres_vs_lammps.sh BENCH_SPHERES [STEPS]
set -euo pipefail
engine=${1:?usage: spheres_vs_lammps.sh BENCH_SPHERES [STEPS]}
steps=${2:-500}
here=$(cd "$(dirname "$0")" && pwd)
lmp=$(command -v lmp || command -v lmp_serial || command -v lmp_stable || true)

printf '%-10s %6s %7s %12s %12s %12s %8s\n' spheres side steps "embedded" "+servo(D)" "LAMMPS" ratio
for side in 22 46; do
  emb=$("$engine" "$side" "$steps" | awk '{print $4}')
  srv=$("$engine" "$side" "$steps" servo | awk '{print $4}')
  n=$((side * side * side))
  if [ -n "$lmp" ]; then
    tmp=$(mktemp -d)
    (cd "$tmp" && "$lmp" -in "$here/lammps_cubic.in" -var side "$side" -var steps "$steps" -log none > out.txt 2>&1) || {
      echo "LAMMPS failed:"; tail -5 "$tmp/out.txt"; exit 1; }
    loop=$(awk '/^Loop time of/ {print $4}' "$tmp/out.txt")
    atoms=$(awk '/^Loop time of/ {print $(NF-1)}' "$tmp/out.txt")
    rm -rf "$tmp"
    lns=$(awk -v t="$loop" -v s="$steps" -v n="$atoms" 'BEGIN {printf "%.2f", t / s / n * 1e9}')
    ratio=$(awk -v a="$emb" -v b="$lns" 'BEGIN {printf "%.2f", a / b}')
    printf '%-10s %6s %7s %12s %12s %12s %8s\n' "$n" "$side" "$steps" "$emb ns" "$srv ns" "$lns ns" "$ratio"
  else
    printf '%-10s %6s %7s %12s %12s %12s %8s\n' "$n" "$side" "$steps" "$emb ns" "$srv ns" "-" "-"
  fi
done
[ -n "$lmp" ] || echo "LAMMPS not installed: only the embedded engine was measured (apt-get install lammps)."
