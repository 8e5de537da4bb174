#!/usr/bin/env bash
# The core's two tables and their copies: the result columns (columns.h) and
# the servo_bc keywords (keywords.h). docs/servo_bc.md's tables equal
# `servo-bc --columns` and `servo-bc --keywords`; the results file's header
# is the columns' names (YADE's COLUMNS: tests/yade); the parser knows every
# keyword of the registry and its message for an unknown one lists them all;
# the LAMMPS and LIGGGHTS fix pages name each keyword once in their syntax
# line and give each a line of its own. Prints "N passed, N failed".
# Usage: tables.sh BUILD
set -u
B=$(cd "${1:-build}" && pwd)
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "tables: $1"; }
no() { fail=$((fail + 1)); echo "FAIL tables: $1"; }

# docs_block WHAT: docs/servo_bc.md's block <!-- WHAT: servo-bc --WHAT --> equals
# servo-bc --WHAT, left in $tmp/WHAT.md
docs_block() {
  "$B/servo-bc" "--$1" > "$tmp/$1.md"
  awk -v first="<!-- $1: servo-bc --$1 -->" -v last="<!-- end $1 -->" '$0 == first { on = 1; next } $0 == last { on = 0 } on' \
    "$top/docs/servo_bc.md" > "$tmp/$1.docs"
  if [ -s "$tmp/$1.md" ] && cmp -s "$tmp/$1.md" "$tmp/$1.docs"; then
    ok "docs/servo_bc.md's $1 table is servo-bc --$1 ($(($(wc -l < "$tmp/$1.md") - 2)) rows)"
  else
    no "docs/servo_bc.md's $1 table differs from servo-bc --$1:"; diff "$tmp/$1.md" "$tmp/$1.docs" | head -4
  fi
}

docs_block columns
printf 'dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 0 mu 0.4\ndensity 2e3\ntimestep 1e-5\nservo_bc D F 0.999 0 0 0.999 increments 1 file %s\nrun\n' \
  "$tmp/run.csv" > "$tmp/run.sbc"
"$B/servo-bc" "$tmp/run.sbc" > /dev/null
# the 2D file's: the rows marked 2D
names=$(awk -F'|' 'NR > 2 && $3 ~ /2D/ { gsub(/[ `]/, "", $2); printf "%s%s", (n++ ? "," : ""), $2 }' "$tmp/columns.md")
if [ "$(head -n 1 "$tmp/run.csv")" = "$names" ] && awk -F, -v n="$(echo "$names" | tr ',' '\n' | wc -l)" \
     'NF != n { bad++ } END { exit bad > 0 || NR != 3 }' "$tmp/run.csv"; then
  ok "the results file's header is the table's names, every row has as many fields"
else
  no "the results file's header or rows do not follow the table:"; head -n 2 "$tmp/run.csv"
fi

docs_block keywords
# the names, in the registry's order
awk -F' [|] ' 'NR > 2 { sub(/^[|] /, "", $1); n = split($1, w, " "); for (i = 1; i <= n; i++) { gsub(/`/, "", w[i]); print w[i] } }' \
  "$tmp/keywords.md" > "$tmp/names"
head='dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 0 mu 0.4\ndensity 2e3\ntimestep 1e-5\n'
unknown=""
while read -r k; do
  printf "${head}servo_bc P %s\nrun\n" "$k" > "$tmp/k.sbc"
  "$B/servo-bc" --check "$tmp/k.sbc" > /dev/null 2> "$tmp/k.err"
  grep -q "unknown keyword" "$tmp/k.err" && unknown="$unknown $k"
done < "$tmp/names"
if [ -z "$unknown" ] && [ "$(wc -l < "$tmp/names")" -ge 19 ]; then
  ok "the parser knows all $(wc -l < "$tmp/names") names of the registry"
else
  no "names of the registry the parser calls unknown:${unknown:- (too few names)}"
fi
printf "${head}servo_bc P bogus 1\nrun\n" > "$tmp/k.sbc"
"$B/servo-bc" --check "$tmp/k.sbc" > /dev/null 2> "$tmp/k.err"
listed=$(sed -n "s/.*unknown keyword 'bogus' (expected \(.*\))$/\1/p" "$tmp/k.err" | sed 's/ or /, /' | tr -d ' ' | tr ',' '\n')
if [ "$listed" = "$(cat "$tmp/names")" ]; then
  ok "an unknown keyword's message lists the registry's names in its order"
else
  no "the unknown keyword's message does not list the registry:"; cat "$tmp/k.err"
fi
# the fix pages: LAMMPS (*name*) and LIGGGHTS ({name})
for page in lammps/fix_servo_bc.rst:'*' liggghts/fix_servo_bc.txt:'{'; do
  file=$top/docs/${page%%:*} mark=${page##*:}
  if [ "$mark" = '*' ]; then pat='\*[A-Za-z_0-9]+\*'; strip='s/\*//g'; else pat='\{[A-Za-z_0-9]+\}'; strip='s/[{}]//g'; fi
  syntax=$(grep -m1 '^\*\? *keyword = ' "$file" | grep -oE "$pat" | sed "$strip")
  lines=$(awk -v m="$mark" 'index($0, "  " m) && / values? = / { print }' "$file" | grep -oE "^ *($pat, )*$pat" | grep -oE "$pat" | sed "$strip")
  if [ "$(echo "$syntax" | sort)" = "$(sort "$tmp/names")" ] && [ "$(echo "$syntax" | sort | uniq -d)" = "" ] &&
     [ "$(echo "$lines" | sort)" = "$(sort "$tmp/names")" ]; then
    ok "docs/${page%%:*}: the syntax line names each of the $(wc -l < "$tmp/names") keywords once, each has its line"
  else
    no "docs/${page%%:*}: keywords differ from the registry:"
    diff <(sort "$tmp/names") <(echo "$syntax" | sort) | head -4; diff <(sort "$tmp/names") <(echo "$lines" | sort) | head -4
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
