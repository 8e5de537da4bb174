#!/usr/bin/env bash
# 10^6 discs under (P) with remap x in LAMMPS and LIGGGHTS, 1 and 2 ranks
# (inputs/lammps/million.in, inputs/liggghts/million.in): time per step and per
# particle-step, memory per rank as the host reports it, the 2-rank efficiency
# t1 / (2 t2), and the rows of 2 ranks against 1 rank and against the closed
# form P_ii = -N kn (2R - d F_ii) / ((N - 1) d) (largest difference of P11,
# P22 over the increments, relative to |P11|).
# Usage: bench/million.sh LMP_SERVO LIGGGHTS_SERVO SERVO_BC [SIDE]   (SIDE 1000: 10^6 discs)
set -euo pipefail
abs() { echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; }
lmp=$(abs "$1") lig=$(abs "$2") emb=$(abs "$3")
side=${4:-1000}
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf 'dimension 2\nlattice square %d %d spacing 2e-3 radius 1.02e-3\ndensity 2e3\nwrite_packing liggghts %s\n' \
  "$side" "$side" "$tmp/million.data" > "$tmp/w.sbc"
"$emb" "$tmp/w.sbc" > /dev/null
run() {  # host np -> "seconds steps megabytes" (the loop times and steps of every run piece summed)
  local bin deck extra
  if [ "$1" = lammps ]; then bin=$lmp deck=$top/inputs/lammps/million.in extra="-var side $side"
  else bin=$lig deck=$top/inputs/liggghts/million.in extra="-var top $top -var data $tmp/million.data"; fi
  # shellcheck disable=SC2086
  (cd "$tmp" && mpirun --allow-run-as-root --oversubscribe -np "$2" "$bin" -in "$deck" $extra \
    -var out "$tmp/$1_$2.csv" -log none > "$1_$2.log" 2>&1) || { tail -3 "$tmp/$1_$2.log"; exit 1; }
  awk '/^Loop time of/ { t += $4; s += $9 }
       /Per MPI rank memory allocation/ { split($0, a, "= "); split(a[2], b, " "); m = b[3] }
       /Memory usage per processor/ { m = $6 }
       END { printf "%.2f %d %s", t, s, m }' "$tmp/$1_$2.log"
}
# rows: largest |P_ii - closed form| / |P11| over increments 1..; and against another CSV
rows() {
  awk -F, -v N="$side" -v other="${2:-}" '
    NR == 1 { for (c = 1; c <= NF; c++) col[$c] = c; next }
    { for (k = 0; k < 2; k++) { F = $col[k ? "F22" : "F11"]; P = $col[k ? "P22" : "P11"]
        want = -N * 1e4 * (2.04e-3 - 2e-3 * F) / ((N - 1) * 2e-3); d = (P - want) / want; if (d < 0) d = -d; if (d > m) m = d } }
    END { printf "%.2g", m }' "$1"
}
diff_rows() {
  paste -d, "$1" "$2" | awk -F, 'NR == 1 { w = NF / 2; for (c = 1; c <= w; c++) col[$c] = c; next }
    { for (k = 0; k < 4; k++) { c = col[k == 0 ? "P11" : k == 1 ? "P12" : k == 2 ? "P21" : "P22"]
        d = $c - $(c + w); if (d < 0) d = -d; if (d > m) m = d; a = $c < 0 ? -$c : $c; if (a > S) S = a } }
    END { printf "%.2g", (S > 0 ? m / S : 1) }'
}
n=$((side * side))
printf '%-9s %5s %7s %10s %12s %9s %11s %14s %16s\n' host ranks steps "s/step" "ns/particle" "MB/rank" efficiency "P vs closed" "2 vs 1 rank"
for host in lammps liggghts; do
  read -r t1 s1 m1 <<< "$(run $host 1)"
  read -r t2 s2 m2 <<< "$(run $host 2)"
  for np in 1 2; do
    if [ $np = 1 ]; then t=$t1 s=$s1 m=$m1; else t=$t2 s=$s2 m=$m2; fi
    printf '%-9s %5s %7s %10.4f %12.1f %9s %11s %14s %16s\n' $host $np "$s" "$(awk -v t="$t" -v s="$s" 'BEGIN { print t / s }')" \
      "$(awk -v t="$t" -v s="$s" -v n=$n 'BEGIN { print 1e9 * t / s / n }')" "$m" \
      "$([ $np = 2 ] && awk -v a="$t1" -v b="$t2" -v x="$s1" -v y="$s2" 'BEGIN { printf "%.0f %%", 100 * (a / x) / (2 * b / y) }' || echo -)" \
      "$(rows "$tmp/${host}_$np.csv")" "$([ $np = 2 ] && diff_rows "$tmp/${host}_1.csv" "$tmp/${host}_2.csv" || echo -)"
  done
done
echo "$n discs; efficiency = (t1 / steps1) / (2 t2 / steps2); P vs closed: largest |P_ii - P_ii*| / |P_ii*|; 2 vs 1 rank: largest |P_2 - P_1| / max |P|"
