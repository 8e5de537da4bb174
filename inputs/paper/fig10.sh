#!/usr/bin/env bash
# Fig. 10 (Sect. 4.2.2): the stress norm of eq. 42 along simple shear
# F12 = 0.5 (100 increments) against the particle number, for the five packings
# of Fig. 6 (n0 = 25, 100, 200, 400, 600) under (D), (P) and (T), Table 4
# settings as in Figs. 7-9. Runs that already have a complete CSV in out/paper
# are reused (delete it to rerun). About 1 h on one core, mostly (P) and (T) of
# the two largest packings.
#   fig10.sh [SET]     SET = table4 (default) or active
set -euo pipefail
. "$(dirname "$0")/common.sh"
set=${1:-table4}
out=$top/out/paper
table=$out/fig10_$set.csv
echo "particles,D,P,T" > "$table"
for n0 in 25 100 200 400 600; do
  row=$(awk '$1 != "box" && $1 !~ /^#/ && NF >= 3 { n++ } END { print n }' "$out/packing_$n0.txt" 2>/dev/null || true)
  for bc in D P T; do
    csv=$out/irregular_${bc}_${n0}_${set}.csv
    if [ ! -f "$csv" ] || [ "$(wc -l < "$csv")" -lt 102 ]; then
      bash "$top/inputs/paper/irregular_case.sh" "$bc" "$n0" "$set" > /dev/null
    fi
    # sigma~ = sigma Rbar / kn, kn = 1e4 N/m (Sect. 4.2.1)
    scale=$(awk -v r="$(rbar "$out/packing_$n0.txt")" 'BEGIN { printf "%.10g", r / 1e4 }')
    row="$row,$(path_norm "$csv" "$scale")"
  done
  echo "$row" >> "$table"
done
cat "$table"
# one file per BC for the overlay: particles,norm
series=()
for c in 2 3 4; do
  bc=$(head -1 "$table" | cut -d, -f$c)
  awk -F, -v c=$c 'NR == 1 { print "particles,norm"; next } { print $1 "," $c }' "$table" > "$out/fig10_${set}_$bc.csv"
  series+=("$out/fig10_${set}_$bc.csv" "($bc)")
done
"$plot" "$fig/fig10_$set.svg" "Fig. 10: stress norm of eq. 42 vs particle number" "particles" "norm of sigma~ (eq. 42)" \
  particles 1 norm 1 "${series[@]}"
