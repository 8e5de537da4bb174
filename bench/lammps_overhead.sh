#!/usr/bin/env bash
# Overhead of fix servo_bc per step against the same run with the frame atoms
# merely held, 1e4 and 1e5 particles, 1 and 2 ranks (goal: <= 3 % at 1e5); 2d
# square lattices, then 3d simple cubic ones (22^3 and 46^3 spheres).
# Usage: bench/lammps_overhead.sh LMP_SERVO [STEPS]; SIDES (default "100 316") and SIDES3
# (default "22 46") set the lattices, e.g. SIDES=1000 for 10^6 discs
set -euo pipefail
lmp=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
steps=${2:-2000}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
loop() {  # np side servo [deck]
  (cd "$tmp" && mpirun --allow-run-as-root --oversubscribe -np "$1" "$lmp" -in "$here/${4:-lammps_overhead.in}" \
    -var side "$2" -var steps "$steps" -var servo "$3" -log none > out.txt 2>&1) || { tail -3 "$tmp/out.txt"; exit 1; }
  awk '/^Loop time of/ {print $4}' "$tmp/out.txt"
}
printf '%-10s %5s %12s %12s %9s\n' particles ranks "held (s)" "servo_bc (s)" overhead
for side in ${SIDES:-100 316}; do
  for np in 1 2; do
    held=$(loop $np $side 0)
    servo=$(loop $np $side 1)
    printf '%-10s %5s %12s %12s %8s%%\n' $((side * side)) $np "$held" "$servo" \
      "$(awk -v a="$held" -v b="$servo" 'BEGIN {printf "%.1f", 100 * (b - a) / a}')"
  done
done
for side in ${SIDES3:-22 46}; do
  for np in 1 2; do
    held=$(loop $np $side 0 lammps_overhead_3d.in)
    servo=$(loop $np $side 1 lammps_overhead_3d.in)
    printf '%-10s %5s %12s %12s %8s%%  3d\n' $((side * side * side)) $np "$held" "$servo" \
      "$(awk -v a="$held" -v b="$servo" 'BEGIN {printf "%.1f", 100 * (b - a) / a}')"
  done
done
rm -rf "$tmp"
echo "$steps steps; overhead = (servo_bc - held) / held; goal <= 3 % at 1e5 and 1e6 particles"
