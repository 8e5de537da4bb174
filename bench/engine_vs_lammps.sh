#!/usr/bin/env bash
# An embedded engine against LAMMPS on the identical lattice scene, in one run.
# Prints ns per particle-step for both and the ratio embedded/LAMMPS (goal <= 0.5).
#   DIM 2: the disc engine (bench/engine_throughput.c) against bench/lammps_lattice.in,
#          100^2 and 316^2 discs;
#   DIM 3: the sphere engine (bench/spheres_throughput.c) against LAMMPS
#          gran/hooke/history in bench/lammps_cubic.in, 22^3 and 46^3 spheres.
# Usage: bench/engine_vs_lammps.sh BENCH_ENGINE [STEPS] [DIM]
set -euo pipefail
engine=${1:?usage: engine_vs_lammps.sh BENCH_ENGINE [STEPS] [DIM]}
steps=${2:-2000}
dim=${3:-2}
here=$(cd "$(dirname "$0")" && pwd)
lmp=$(command -v lmp || command -v lmp_serial || command -v lmp_stable || true)
if [ "$dim" = 3 ]; then sides="22 46" deck=$here/lammps_cubic.in; else sides="100 316" deck=$here/lammps_lattice.in; fi

printf '%-10s %8s %7s %12s %12s %12s %8s\n' particles side steps "embedded" "+servo(D)" "LAMMPS" ratio
for side in $sides; do
  emb=$("$engine" "$side" "$steps" | awk '{print $4}')
  srv=$("$engine" "$side" "$steps" servo | awk '{print $4}')
  n=$((dim == 3 ? side * side * side : side * side))
  if [ -n "$lmp" ]; then
    tmp=$(mktemp -d)
    (cd "$tmp" && "$lmp" -in "$deck" -var side "$side" -var steps "$steps" -log none > out.txt 2>&1) || {
      echo "LAMMPS failed:"; tail -5 "$tmp/out.txt"; exit 1; }
    loop=$(awk '/^Loop time of/ {print $4}' "$tmp/out.txt")
    atoms=$(awk '/^Loop time of/ {print $(NF-1)}' "$tmp/out.txt")
    rm -rf "$tmp"
    lns=$(awk -v t="$loop" -v s="$steps" -v n="$atoms" 'BEGIN {printf "%.2f", t / s / n * 1e9}')
    ratio=$(awk -v a="$emb" -v b="$lns" 'BEGIN {printf "%.2f", a / b}')
    printf '%-10s %8s %7s %12s %12s %12s %8s\n' "$n" "$side" "$steps" "$emb ns" "$srv ns" "$lns ns" "$ratio"
  else
    printf '%-10s %8s %7s %12s %12s %12s %8s\n' "$n" "$side" "$steps" "$emb ns" "$srv ns" "-" "-"
  fi
done
[ -n "$lmp" ] || echo "LAMMPS not installed: only the embedded engine was measured (apt-get install lammps)."
