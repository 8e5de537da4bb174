#!/usr/bin/env bash
# Fig. 4: (D), (P), (T) on 25 particles: -sigma~11 and the mean overlap (eq. 39)
# against -F12; and the fraction of increments with -sigma~11 (D) >= (P) >= (T).
set -euo pipefail
source "$(dirname "$0")/common.sh"
table=$top/out/paper/fig4.md
table_header > "$table"
d=$(bash "$top/inputs/paper/regular_case.sh" D 5 table4 0)
summary_row "D 25" "$d" >> "$table"
for set in table4 active; do
  p=$(bash "$top/inputs/paper/regular_case.sh" P 5 $set 0)
  t=$(bash "$top/inputs/paper/regular_case.sh" T 5 $set 0)
  summary_row "P 25 $set" "$p" >> "$table"
  summary_row "T 25 $set" "$t" >> "$table"
  "$plot" "$fig/fig4a_$set.svg" "Fig. 4a: 25 particles, $set" "-F12" "-sigma~11 (m)" F12 -1 sigma11 $S \
    "$d" "(D)" "$p" "(P)" "$t" "(T)"
  "$plot" "$fig/fig4b_$set.svg" "Fig. 4b: 25 particles, $set" "-F12" "mean overlap (%)" F12 -1 overlap_mean 100 \
    "$d" "(D)" "$p" "(P)" "$t" "(T)"
  paste -d, <(cut -d, -f10 "$d") <(cut -d, -f10 "$p") <(cut -d, -f10 "$t") | awk -F, -v set=$set '
    NR > 1 { n++; if (-$1 >= -$2 && -$2 >= -$3) k++; if (-$1 >= -$2) dp++; if (-$2 >= -$3) pt++ }
    END { printf "%s: (D) >= (P) >= (T) for -sigma~11 in %d of %d increments (%.1f %%); (D) >= (P) %.1f %%, (P) >= (T) %.1f %%\n",
          set, k, n, 100 * k / n, 100 * dp / n, 100 * pt / n }' >> "$top/out/paper/fig4_order.txt.tmp"
done
mv "$top/out/paper/fig4_order.txt.tmp" "$top/out/paper/fig4_order.txt"
cat "$table" "$top/out/paper/fig4_order.txt"
