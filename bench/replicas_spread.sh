#!/usr/bin/env bash
# The spread of a path, measured with `replicas` (docs/speed-accuracy.md,
# "The spread of a path"): K histories of the same case (replica 0 plain,
# the others with the interior's centres moved by up to 1e-6 R), J at a
# time, at the default preset (accuracy balanced: stated accuracy 1e-4),
# on generated packings of 34, 121, 232, 439 and 649 discs (n0 = 25 ... 600):
#  - the irregular (P) case of Sect. 4.2 (inputs/paper/irregular_case.sh,
#    converged set) to F12 = 0.05 in 10 increments;
#  - the frictional mixed layer of Sect. 5 (inputs/paper/fig11.sh, converged
#    set, its touching packing): P22* = -1.05e6 N/m in 6 increments, then
#    F12 = 0.02 in 10.
# Prints one markdown row per run: the largest spread (max - min over the
# replicas) of a sigma component over the path, absolute and relative to the
# path's stress scale (the largest |mean sigma|), the spread of sigma12 at the
# last increment, DEM steps of replica 0 and the wall time.
#   bash bench/replicas_spread.sh [OUT]     K=4 J=2 SIZES="25 100 200 400 600" CASES="P mixed"
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
# results files are read by column name (scripts/columns.awk)
COLUMNS_AWK=$(cat "$top/scripts/columns.awk")
B=${B:-$top/build}
out=${1:-$top/out/replicas_spread}
K=${K:-4} J=${J:-2}
mkdir -p "$out"
echo "| case | discs | replicas | largest spread (N/m) | of the stress scale | σ̄12 spread, last increment (N/m) | DEM steps (replica 0) | wall (s) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for c in ${CASES:-P mixed}; do
  for n0 in ${SIZES:-25 100 200 400 600}; do
    name=$out/${c}_$n0
    if [ "$c" = P ]; then
      printf 'dimension 2\ngenerate periodic n0 %s rmin 0.67e-3 polydispersity 2 seed 1 strain 0.01\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 7.5e-5\nreplicas %s jobs %s\nservo_bc P F 1 0.05 0 1 increments 10 seal yes max_iterations 200000 file %s.csv\nrun\n' \
        "$n0" "$K" "$J" "$name" > "$name.sbc"
    else
      printf 'dimension 2\ngenerate periodic n0 %s rmin 0.8e-3 polydispersity 1.5 seed 1\ncontact frictional kn 1e8 ks 4e7 mu 0.6\ndensity 1e4\ntimestep 5e-6\nreplicas %s jobs %s\nservo_bc mixed F 1 0.02 0 1 increments 10 stress P22 -1.05e6 6 seal yes max_iterations 200000 file %s.csv\nrun\n' \
        "$n0" "$K" "$J" "$name" > "$name.sbc"
    fi
    t0=$(date +%s.%N)
    "$B/servo-bc" "$name.sbc" > "$name.log" 2>&1
    rc=$?
    t1=$(date +%s.%N)
    discs=$(sed -n 's/.*-> \([0-9]*\) particles.*/\1/p' "$name.log" | head -1)
    steps=$(awk -F, "$COLUMNS_AWK"'NR > 1 { s += $col("relax_steps") } END { print s + 0 }' "$name.csv" 2>/dev/null)
    awk -F, -v c="$c" -v d="$discs" -v k="$K" -v st="$steps" -v rc="$rc" -v wall="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.0f", b - a }')" '
      NR > 1 { n++; for (j = 7; j <= 22; j += 4) { w = $(j + 3) - $(j + 2); if (w > W) W = w; a = $j < 0 ? -$j : $j; if (a > S) S = a }
               last12 = $14 - $13 }
      END { printf "| %s | %s | %d%s | %.3g | %.2g | %.3g | %d | %s |\n", c, d, k, (rc ? " (a replica stopped)" : ""), W, (S > 0 ? W / S : 0), last12, st, wall }' \
      "${name}_replicas.csv"
  done
done | tee "$out/table.md"
