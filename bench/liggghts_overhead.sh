#!/usr/bin/env bash
# Overhead of fix servo_bc in LIGGGHTS per step against the same run with the
# frame atoms merely held, 1e4 and 1e5 particles, 1 and 2 ranks; and the time
# per particle-step of the held scene in LIGGGHTS beside LAMMPS (bench/
# lammps_overhead.in, held) and the embedded engine (build/bench_engine), one
# rank, measured in this run.
# Usage: bench/liggghts_overhead.sh LIGGGHTS_SERVO SERVO_BC [LMP_SERVO BENCH_ENGINE] [STEPS]; SIDES (default
# "100 316") sets the lattices, e.g. SIDES=1000 for 10^6 discs
set -euo pipefail
abs() { echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; }
lig=$(abs "${1:?usage: liggghts_overhead.sh LIGGGHTS_SERVO SERVO_BC [LMP_SERVO BENCH_ENGINE] [STEPS]}")
emb=$(abs "${2:?usage: liggghts_overhead.sh LIGGGHTS_SERVO SERVO_BC [LMP_SERVO BENCH_ENGINE] [STEPS]}")
lmp=${3:+$(abs "$3")} engine=${4:+$(abs "$4")}
steps=${5:-2000}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
loop() {  # np servo -> loop time (s)
  (cd "$tmp" && mpirun --allow-run-as-root --oversubscribe -np "$1" "$lig" -in "$here/liggghts_overhead.in" \
    -var top "$here/.." -var steps "$steps" -var servo "$2" -log none > out.txt 2>&1) || { tail -3 "$tmp/out.txt"; exit 1; }
  awk '/^Loop time of/ {print $4}' "$tmp/out.txt"
}
ns() { awk -v t="$1" -v n="$2" -v s="$steps" 'BEGIN {printf "%.1f", t / s / n * 1e9}'; }
declare -A held1
printf '%-10s %5s %12s %12s %9s\n' particles ranks "held (s)" "servo_bc (s)" overhead
for side in ${SIDES:-100 316}; do
  printf 'dimension 2\nlattice square %d %d spacing 2e-3 radius 1.02e-3\ndensity 2e3\nwrite_packing liggghts %s\n' \
    $side $side "$tmp/lattice.data" > "$tmp/w.sbc"
  "$emb" "$tmp/w.sbc" > /dev/null
  for np in 1 2; do
    held=$(loop $np 0)
    servo=$(loop $np 1)
    [ $np = 1 ] && held1[$side]=$held
    printf '%-10s %5s %12s %12s %8s%%\n' $((side * side)) $np "$held" "$servo" \
      "$(awk -v a="$held" -v b="$servo" 'BEGIN {printf "%.1f", 100 * (b - a) / a}')"
  done
done
echo "$steps steps; overhead = (servo_bc - held) / held"
echo
printf '%-10s %14s %14s %14s\n' particles "LIGGGHTS (ns)" "LAMMPS (ns)" "embedded (ns)"
for side in ${SIDES:-100 316}; do
  n=$((side * side)) l="-" e="-"
  if [ -n "$lmp" ]; then
    (cd "$tmp" && "$lmp" -in "$here/lammps_overhead.in" -var side $side -var steps "$steps" -var servo 0 -log none \
      > lmp.txt 2>&1) && l=$(ns "$(awk '/^Loop time of/ {print $4}' "$tmp/lmp.txt")" $n)
  fi
  [ -n "$engine" ] && e=$("$engine" $side "$steps" | awk '{print $4}')
  printf '%-10s %14s %14s %14s\n' $n "$(ns "${held1[$side]}" $n)" "$l" "$e"
done
echo "ns per particle-step of the held scene, one rank (frame atoms not integrated; the engine integrates all)"
rm -rf "$tmp"
