#!/usr/bin/env bash
# Overhead of fix servo_bc per step against the same run with the frame atoms
# merely held, 1e4 and 1e5 particles, 1 and 2 ranks (goal: <= 3 % at 1e5); 2d
# square lattices, then 3d simple cubic ones (22^3 and 46^3 spheres). Beside it,
# what one pass over the interior costs: the held run with LAMMPS' fix viscous on
# the interior (f -= gamma v, the cheapest damping LAMMPS has).
# Usage: bench/lammps_overhead.sh LMP_SERVO [STEPS]; SIDES (default "100 316") and SIDES3
# (default "22 46") set the lattices, e.g. SIDES=1000 for 10^6 discs. Prints the loop times and
# the fix's own time, the growth of the Modify section (the pair style's time may differ between
# the two runs on its own), and fix viscous's growth of it
set -euo pipefail
lmp=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
steps=${2:-2000}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
loop() {  # np side servo [deck]
  (cd "$tmp" && mpirun --allow-run-as-root --oversubscribe -np "$1" "$lmp" -in "$here/${4:-lammps_overhead.in}" \
    -var side "$2" -var steps "$steps" -var servo "$3" -log none > out.txt 2>&1) || { tail -3 "$tmp/out.txt"; exit 1; }
  # the loop time and the fixes' share of it (LAMMPS' Modify section, average over ranks)
  awk '/^Loop time of/ { t = $4 } /^Modify / { m = $5 } END { print t, m }' "$tmp/out.txt"
}
# row PARTICLES NP HELD_LOOP HELD_MODIFY SERVO_LOOP SERVO_MODIFY VISCOUS_LOOP VISCOUS_MODIFY [NOTE]
row() {
  printf '%-10s %5s %12s %12s %9s %12s %10s %14s %s\n' "$1" "$2" "$3" "$5" \
    "$(awk -v a="$3" -v b="$5" 'BEGIN {printf "%.1f%%", 100 * (b - a) / a}')" \
    "$(awk -v a="$4" -v b="$6" 'BEGIN {printf "%.2f", b - a}')" \
    "$(awk -v a="$4" -v b="$6" -v h="$3" 'BEGIN {printf "%.1f%%", 100 * (b - a) / h}')" \
    "$(awk -v a="$4" -v b="$8" -v h="$3" 'BEGIN {printf "%.1f%%", 100 * (b - a) / h}')" "${9:-}"
}
printf '%-10s %5s %12s %12s %9s %12s %10s %14s\n' particles ranks "held (s)" "servo_bc (s)" overhead "fix time (s)" \
  "fix/held" "viscous/held"
for side in ${SIDES:-100 316}; do
  for np in 1 2; do
    row $((side * side)) $np $(loop $np $side 0) $(loop $np $side 1) $(loop $np $side 2)
  done
done
for side in ${SIDES3:-22 46}; do
  for np in 1 2; do
    row $((side * side * side)) $np $(loop $np $side 0 lammps_overhead_3d.in) $(loop $np $side 1 lammps_overhead_3d.in) \
      $(loop $np $side 2 lammps_overhead_3d.in) 3d
  done
done
rm -rf "$tmp"
echo "$steps steps; overhead = (servo_bc - held) / held, loop times; fix time = the Modify section's growth"
echo "(fix servo_bc beside the held run's integrator), fix/held = that over the held loop time;"
echo "viscous/held = the Modify growth of the held run with fix viscous on the interior (one pass over it per"
echo "step) over the held loop time; goal <= 3 % at 1e5 and 1e6 particles"
