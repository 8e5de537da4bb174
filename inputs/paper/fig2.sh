#!/usr/bin/env bash
# Fig. 2: 25 particles, (P) and (T), with (n_f = 0.5) and without prediction:
# -sigma~11 and -sigma~12 against -F12, for both parameter sets.
set -euo pipefail
source "$(dirname "$0")/common.sh"
table=$top/out/paper/fig2.md
table_header > "$table"
for set in table4 active; do
  for bc in P T; do
    a=$(bash "$top/inputs/paper/regular_case.sh" $bc 5 $set 0)
    b=$(bash "$top/inputs/paper/regular_case.sh" $bc 5 $set 0.5)
    summary_row "$bc 25 $set, without prediction" "$a" >> "$table"
    summary_row "$bc 25 $set, n_f = 0.5" "$b" >> "$table"
    "$plot" "$fig/fig2_${bc}_$set.svg" "Fig. 2 ($bc), 25 particles, $set" "-F12" "-sigma~ (m)" F12 -1 sigma11 $S \
      "$a" "-sigma~11 without prediction" "$b" "-sigma~11 with prediction (n_f = 0.5)"
    "$plot" "$fig/fig2_${bc}_${set}_s12.svg" "Fig. 2 ($bc), 25 particles, $set" "-F12" "-sigma~12 (m)" F12 -1 sigma12 $S \
      "$a" "-sigma~12 without prediction" "$b" "-sigma~12 with prediction (n_f = 0.5)"
  done
done
cat "$table"
