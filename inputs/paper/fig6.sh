#!/usr/bin/env bash
# Fig. 6 / Sect. 4.2: the five irregular periodic packings (n0 = 25 ... 600,
# polydispersity 2, R_min = 0.67 mm, seed 1): particle counts, volume fraction,
# coordination, rose diagrams; writes each packing as text, LAMMPS and LIGGGHTS data and YADE
# files in out/paper/ for the other cases and hosts. About 1.5 min.
set -euo pipefail
. "$(dirname "$0")/common.sh"
out=$top/out/paper
echo "| n0 | particles (paper) | L (mm) | V (mm²) (paper) | volume fraction | coordination | generation (s) |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
paper_n=(37 120 228 444 650)
paper_v=(100 400 818 1462 2156)
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
  awk -v n0=$n0 -v pn=${paper_n[$k]} -v pv=${paper_v[$k]} -v t="$(echo "$t1 - $t0" | bc)" '/^generate:/ {
      for (i = 1; i <= NF; i++) { if ($i == "->") n = $(i + 1); if ($i == "L") L = $(i + 2);
        if ($i == "fraction") { f = $(i + 1); sub(",", "", f) } if ($i == "coordination") c = $(i + 1) }
      L += 0; printf "| %d | %d (%d) | %.2f | %.0f (%d) | %s | %s | %.1f |\n", n0, n, pn, L * 1e3, L * L * 1e6, pv, f, c, t }' \
      "$out/packing_$n0.log"
  k=$((k + 1))
done
echo "(paper: volume fraction 0.833-0.850, coordination 2.97-3.47)"
