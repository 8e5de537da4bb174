#!/usr/bin/env bash
# Fig. 6 / Sect. 4.2: the five irregular periodic packings (n0 = 25 ... 600,
# polydispersity 2, R_min = 0.67 mm, seed 1): particle counts, volume fraction,
# coordination, rose diagrams; writes each packing as text, LAMMPS and LIGGGHTS data and YADE
# files in out/paper/ for the other cases and hosts. Then the same five jammed
# under pressure (`strain 0.01`, the packings of the converged runs of Figs.
# 7-10, out/paper/packing_N0_converged.txt). About 3 min.
# Tables for the page (make figures): out/paper/fig6.md, out/paper/fig6_coordination.md.
set -euo pipefail
. "$(dirname "$0")/common.sh"
out=$top/out/paper
paper_n=(37 120 228 444 650)
paper_v=(100 400 818 1462 2156)
# figures LOG: "n fraction coordination L" from the generator's line
figures() {
  awk '/^generate: n0/ { for (i = 1; i <= NF; i++) { if ($i == "->") n = $(i + 1); if ($i == "fraction") { f = $(i + 1); sub(",", "", f) }
      if ($i == "coordination") c = $(i + 1); if ($i == "L") L = $(i + 2) + 0 } }
    END { print n, f, c, L }' "$1"
}
# all_discs TEXT: 2 Nc / N over every disc of the reconstructed packing, frame
# copies included, contacts closer than 1e-6 R_min (the second reading of the
# paper's coordination)
all_discs() {
  awk '$1 == "box" || $1 ~ /^#/ || NF < 3 { next } { x[n] = $1; y[n] = $2; r[n] = $3; if (!n || $3 < rmin) rmin = $3; n++ }
    END { for (i = 0; i < n; i++) for (j = i + 1; j < n; j++)
            if (sqrt((x[i] - x[j])^2 + (y[i] - y[j])^2) < r[i] + r[j] + 1e-6 * rmin) c++
          printf "%.3f", 2 * c / n }' "$1"
}
{
  echo "| n0 | particles (paper) | L (mm) | V (mm²) (paper) | volume fraction | coordination | generation (s) |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
} > "$out/fig6.md"
{
  echo "| packing | discs | volume fraction | over the n0 original discs | 2 N_c / N, all discs |"
  echo "| --- | --- | --- | --- | --- |"
} > "$out/fig6_coordination.md"
rows=
k=0
for n0 in 25 100 200 400 600; do
  cat > "$out/packing_$n0.sbc" <<SBC
dimension 2
generate periodic n0 $n0 rmin 0.67e-3 polydispersity 2 seed 1
density 2e3
write_packing text $out/packing_$n0.txt
write_packing lammps $out/packing_$n0.data
write_packing liggghts $out/packing_$n0.liggghts.data
write_packing yade $out/packing_$n0.yade
rose $fig/fig6c_rose_$n0.svg
SBC
  t0=$(date +%s.%N)
  "$top/build/servo-bc" "$out/packing_$n0.sbc" > "$out/packing_$n0.log"
  t1=$(date +%s.%N)
  read -r n f c L <<< "$(figures "$out/packing_$n0.log")"
  awk -v n0=$n0 -v n=$n -v pn=${paper_n[$k]} -v pv=${paper_v[$k]} -v L=$L -v f=$f -v c=$c -v t="$(echo "$t1 - $t0" | bc)" \
    'BEGIN { printf "| %d | %d (%d) | %.2f | %.0f (%d) | %s | %s | %.1f |\n", n0, n, pn, L * 1e3, L * L * 1e6, pv, f, c, t }' >> "$out/fig6.md"
  echo "| touching, n0 = $n0 | $n | $f | $c | $(all_discs "$out/packing_$n0.txt") |" >> "$out/fig6_coordination.md"
  k=$((k + 1))
done
# the same packings jammed under pressure, as the converged runs read them
for n0 in 25 100 200 400 600; do
  printf 'dimension 2\ngenerate periodic n0 %s rmin 0.67e-3 polydispersity 2 seed 1 strain 0.01\nwrite_packing text %s\n' \
    "$n0" "$out/packing_${n0}_converged.txt" > "$out/packing_${n0}_converged.sbc"
  "$top/build/servo-bc" "$out/packing_${n0}_converged.sbc" > "$out/packing_${n0}_converged.log"
  read -r n f c L <<< "$(figures "$out/packing_${n0}_converged.log")"
  echo "| strain 0.01, n0 = $n0 | $n | $f | $c | $(all_discs "$out/packing_${n0}_converged.txt") |" >> "$out/fig6_coordination.md"
done
echo "| paper | 37–650 | 0.833–0.850 | 2.97–3.47 (over which discs: not said) | |" >> "$out/fig6_coordination.md"
cat "$out/fig6.md" "$out/fig6_coordination.md"
