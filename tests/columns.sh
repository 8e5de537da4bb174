#!/usr/bin/env bash
# One table of result columns (src_core/include/sbc/columns.h): the results
# file's header is its names, the docs' copy (docs/servo_bc.md, "Output file")
# equals `servo-bc --columns`, and the YADE module's COLUMNS (read from the
# library) are checked in tests/yade. Prints "N passed, N failed".
# Usage: columns.sh BUILD
set -u
B=$(cd "${1:-build}" && pwd)
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "columns: $1"; }
no() { fail=$((fail + 1)); echo "FAIL columns: $1"; }
"$B/servo-bc" --columns > "$tmp/table.md"
awk '/^<!-- columns: servo-bc --columns -->$/ { on = 1; next } /^<!-- end columns -->$/ { on = 0 } on' \
  "$top/docs/servo_bc.md" > "$tmp/docs.md"
if [ -s "$tmp/table.md" ] && cmp -s "$tmp/table.md" "$tmp/docs.md"; then
  ok "docs/servo_bc.md lists the $(($(wc -l < "$tmp/table.md") - 2)) columns of columns.h"
else
  no "docs/servo_bc.md's column table differs from servo-bc --columns:"; diff "$tmp/table.md" "$tmp/docs.md" | head -5
fi
printf 'dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 0 mu 0.4\ndensity 2e3\ntimestep 1e-5\nservo_bc D F 0.999 0 0 0.999 increments 1 file %s\nrun\n' \
  "$tmp/run.csv" > "$tmp/run.sbc"
"$B/servo-bc" "$tmp/run.sbc" > /dev/null
names=$(awk -F'|' 'NR > 2 { gsub(/[ `]/, "", $2); printf "%s%s", (NR > 3 ? "," : ""), $2 }' "$tmp/table.md")
if [ "$(head -n 1 "$tmp/run.csv")" = "$names" ] && awk -F, -v n="$(echo "$names" | tr ',' '\n' | wc -l)" \
     'NF != n { bad++ } END { exit bad > 0 || NR != 3 }' "$tmp/run.csv"; then
  ok "the results file's header is the table's names, every row has as many fields"
else
  no "the results file's header or rows do not follow the table:"; head -n 2 "$tmp/run.csv"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
