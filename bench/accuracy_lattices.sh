#!/usr/bin/env bash
# The presets against the frictional lattice's closed form
# (docs/speed-accuracy.md, "The presets on the closed-form lattices"): N x N frictional square lattices (R =
# 1.02 mm, spacing 2 mm, kn 1e4, ks 2e3 N/m, mu 0.4, dt 1e-5 s), F =
# diag(0.99, 0.995) in 4 increments, (D) and (P), every preset, against the
# affine closed form of tests/test_lattice.c. Prints one markdown row per run:
# the largest relative error of P11, P22 over the rows, |P12|/|P11|, DEM
# steps, servo iterations and wall time. DAMPING="damping 0.7 0.7" runs every
# preset with eq. 10's local damping instead of the presets' FIRE.
#   bash bench/accuracy_lattices.sh [OUT]
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
B=${B:-$top/build}
out=${1:-$top/out/accuracy_lattices}
damping=${DAMPING:-}
mkdir -p "$out"
[ -x "$B/servo-bc" ] || { echo "accuracy_lattices: $B/servo-bc not built (make)"; exit 1; }
echo "| lattice | BC | preset | error P̄11, P̄22 | \|P̄12\|/\|P̄11\| | DEM steps | iterations | wall (s) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for n in 5 7 9; do
  for bc in D P; do
    for p in paper fast balanced tight; do
      name=$out/${n}_${bc}_$p
      printf 'dimension 2\nlattice square %d %d spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\ntimestep 1e-5\nservo_bc %s F 0.99 0 0 0.995 increments 4 accuracy %s %s file %s.csv\nrun\n' \
        "$n" "$n" "$bc" "$p" "$([ $p = paper ] || echo "$damping")" "$name" > "$name.sbc"
      t0=$(date +%s.%N)
      "$B/servo-bc" "$name.sbc" > "$name.log" 2>&1 || { echo "| ${n}×$n | $bc | $p | stopped: $(grep -m1 ERROR "$name.log") | | | | |"; continue; }
      t1=$(date +%s.%N)
      awk -F, -v n="$n" -v p="$p" -v bc="$bc" -v wall="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')" '
        function abs(x) { return x < 0 ? -x : x }
        NR > 1 { p11 = -n * 1e4 * (2.04e-3 - 2e-3 * $2) / ((n - 1) * 2e-3)
                 p22 = -n * 1e4 * (2.04e-3 - 2e-3 * $5) / ((n - 1) * 2e-3)
                 e = abs($6 - p11) / abs(p11); if (abs($9 - p22) / abs(p22) > e) e = abs($9 - p22) / abs(p22)
                 if (e > E) E = e
                 s = abs($7) / abs(p11); if (abs($8) / abs(p11) > s) s = abs($8) / abs(p11); if (s > S) S = s
                 st += $17; it += $16 }
        END { printf "| %d×%d | %s | %s | %.2g | %.2g | %d | %d | %s |\n", n, n, bc, p, E, S, st, it, wall }' "$name.csv"
    done
  done
done | tee "$out/table.md"
