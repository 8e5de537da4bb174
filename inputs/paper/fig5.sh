#!/usr/bin/env bash
# Fig. 5: sample sizes 25, 100, 225 for each BC: -sigma~11 against -F12.
# The Table 4 set runs every size. The servo-active set runs 25 and 100
# particles; set ACTIVE_SIDES="5 10 15" to add 225 (measured: (P) about 20 min,
# (T) longer; iterations per increment grow with the frame).
set -euo pipefail
source "$(dirname "$0")/common.sh"
table=$top/out/paper/fig5.md
table_header > "$table"
for bc in D P T; do
  for set in table4 active; do
    [ $bc = D ] && [ $set = active ] && continue
    files=()
    sides="5 10 15"
    [ $set = active ] && sides=${ACTIVE_SIDES:-5 10}
    for side in $sides; do
      f=$(bash "$top/inputs/paper/regular_case.sh" $bc $side $set 0)
      summary_row "$bc $((side * side)) $set" "$f" >> "$table"
      files+=("$f" "$((side * side)) particles")
    done
    "$plot" "$fig/fig5_${bc}_$set.svg" "Fig. 5 ($bc), $set" "-F12" "-sigma~11 (m)" F12 -1 sigma11 $S "${files[@]}"
  done
done
cat "$table"
