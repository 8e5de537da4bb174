#!/usr/bin/env bash
# Overhead of fix servo_bc per step against the same run with the frame atoms
# merely held, 1e4 and 1e5 particles, 1 and 2 ranks (goal: <= 3 % at 1e5).
# Usage: bench/lammps_overhead.sh LMP_SERVO [STEPS]
set -euo pipefail
lmp=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
steps=${2:-2000}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
loop() {  # np side servo
  (cd "$tmp" && mpirun --allow-run-as-root --oversubscribe -np "$1" "$lmp" -in "$here/lammps_overhead.in" \
    -var side "$2" -var steps "$steps" -var servo "$3" -log none > out.txt 2>&1) || { tail -3 "$tmp/out.txt"; exit 1; }
  awk '/^Loop time of/ {print $4}' "$tmp/out.txt"
}
printf '%-10s %5s %12s %12s %9s\n' particles ranks "held (s)" "servo_bc (s)" overhead
for side in 100 316; do
  for np in 1 2; do
    held=$(loop $np $side 0)
    servo=$(loop $np $side 1)
    printf '%-10s %5s %12s %12s %8s%%\n' $((side * side)) $np "$held" "$servo" \
      "$(awk -v a="$held" -v b="$servo" 'BEGIN {printf "%.1f", 100 * (b - a) / a}')"
  done
done
rm -rf "$tmp"
echo "$steps steps; overhead = (servo_bc - held) / held; goal <= 3 % at 1e5 particles"
