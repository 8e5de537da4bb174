#!/usr/bin/env bash
# Figs. 7-9 (Sect. 4.2.1): simple shear F12 = 0.5 in 100 increments on the
# 232-particle packing (n0 = 200; the paper's has 228) under (D), (P), (T).
#   fig7_9.sh [SET]     SET = table4 (default), active or converged, see irregular_case.sh;
#   once table4 and converged have both run, Fig. 7 is also drawn with both (fig7{a,b}_both.svg)
# Fig. 7: -sigma~11, -sigma~22 (sigma~ = sigma Rbar / kn); Fig. 9: mean
# overlap (eq. 39) and mean rotation (eq. 41); Fig. 8: contact networks at
# F12 = 0.05, 0.1, 0.3, 0.5 as docs/figures/fig8_BC_{a,b,c,d}.svg (and VTK
# snapshots every 10 increments in out/paper/vtk/). About 15 min with table4.
set -euo pipefail
. "$(dirname "$0")/common.sh"
set=${1:-table4}
for bc in D P T; do
  csv=$top/out/paper/irregular_${bc}_200_$set.csv
  # REUSE=1: a run whose CSV has the whole path is not run again (make figures runs them all)
  if [ "${REUSE:-0}" = 1 ] && [ -f "$csv" ] && [ "$(tail -n 1 "$csv" | cut -d, -f1)" = 100 ]; then continue; fi
  bash "$top/inputs/paper/irregular_case.sh" "$bc" 200 "$set" > /dev/null || echo "($bc) stopped before the end (message above); plotting the increments it converged"
  for pair in a:10 b:20 c:60 d:100; do
    svg=$top/out/paper/net/irregular_${bc}_200_${set}_$(printf %06d "${pair#*:}").svg
    [ -f "$svg" ] && cp "$svg" "$fig/fig8_${bc}_${set}_${pair%%:*}.svg"
  done
done
out=$top/out/paper
# Rbar = mean radius of all P + Q particles (Sect. 4.2.1), kn = 1e4 N/m
scale=$(awk -v r="$(rbar "$out/packing_200.txt")" 'BEGIN { printf "%.10g", -r / 1e4 }')
runs=()
for bc in D P T; do runs+=("$out/irregular_${bc}_200_${set}.csv" "($bc)"); done
"$plot" "$fig/fig7a_$set.svg" "Fig. 7a: simple shear, 232 particles" "F12" "-sigma~11" F12 1 sigma11 "$scale" "${runs[@]}"
"$plot" "$fig/fig7b_$set.svg" "Fig. 7b: simple shear, 232 particles" "F12" "-sigma~22" F12 1 sigma22 "$scale" "${runs[@]}"
"$plot" "$fig/fig9a_$set.svg" "Fig. 9a: mean normalized overlap (eq. 39)" "F12" "overlap" F12 1 overlap_mean 1 "${runs[@]}"
"$plot" "$fig/fig9b_$set.svg" "Fig. 9b: mean rotation (eq. 41)" "F12" "rotation (rad)" F12 1 rotation_mean 1 "${runs[@]}"
# the cost table and the path norm of eq. 42 (trapezoid over F12), also in
# out/paper/fig7_9_SET.md for the page (make figures)
{
  table_header
  for bc in D P T; do summary_row "($bc) $set" "$out/irregular_${bc}_200_${set}.csv"; done
  echo
  echo "| BC | last F̄12 | path norm of eq. 42 |"
  echo "| --- | --- | --- |"
  for bc in D P T; do
    echo "| ($bc) | $(printf %.3f "$(last_F12 "$out/irregular_${bc}_200_${set}.csv")") | $(path_norm "$out/irregular_${bc}_200_${set}.csv" "$scale") |"
  done
} > "$out/fig7_9_$set.md"
cat "$out/fig7_9_$set.md"
# both sets side by side
if [ -f "$out/irregular_D_200_table4.csv" ] && [ -f "$out/irregular_D_200_converged.csv" ]; then
  both=()
  for s in converged table4; do
    for bc in D P T; do
      [ -f "$out/irregular_${bc}_200_$s.csv" ] && both+=("$out/irregular_${bc}_200_$s.csv" "($bc) $s")
    done
  done
  "$plot" "$fig/fig7a_both.svg" "Fig. 7a: converged presets and Table 4" "F12" "-sigma~11" F12 1 sigma11 "$scale" "${both[@]}"
  "$plot" "$fig/fig7b_both.svg" "Fig. 7b: converged presets and Table 4" "F12" "-sigma~22" F12 1 sigma22 "$scale" "${both[@]}"
fi
