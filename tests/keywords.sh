#!/usr/bin/env bash
# One keyword registry (src_core/include/sbc/keywords.h): docs/servo_bc.md's
# keyword table equals `servo-bc --keywords`; the parser knows every name
# of the table (none is an "unknown keyword"), and its message for an
# unknown one lists them all; the LAMMPS and LIGGGHTS fix pages name each
# keyword once in their syntax line and give each a line of its own.
# Prints "N passed, N failed".
# Usage: keywords.sh BUILD
set -u
B=$(cd "${1:-build}" && pwd)
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "keywords: $1"; }
no() { fail=$((fail + 1)); echo "FAIL keywords: $1"; }
"$B/servo-bc" --keywords > "$tmp/table.md"
awk '/^<!-- keywords: servo-bc --keywords -->$/ { on = 1; next } /^<!-- end keywords -->$/ { on = 0 } on' \
  "$top/docs/servo_bc.md" > "$tmp/docs.md"
if [ -s "$tmp/table.md" ] && cmp -s "$tmp/table.md" "$tmp/docs.md"; then
  ok "docs/servo_bc.md's keyword table is servo-bc --keywords ($(($(wc -l < "$tmp/table.md") - 2)) rows)"
else
  no "docs/servo_bc.md's keyword table differs from servo-bc --keywords:"; diff "$tmp/table.md" "$tmp/docs.md" | head -4
fi
# the names, in the registry's order
awk -F' [|] ' 'NR > 2 { sub(/^[|] /, "", $1); n = split($1, w, " "); for (i = 1; i <= n; i++) { gsub(/`/, "", w[i]); print w[i] } }' \
  "$tmp/table.md" > "$tmp/names"
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
