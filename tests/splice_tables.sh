#!/usr/bin/env bash
# scripts/splice_tables.sh (make figures): a marked block gets the file's
# content, text around it is kept byte for byte, a missing file keeps the
# block and says so, a block never closed is an error that leaves the page
# as it was. Prints "N passed, N failed".
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "splice_tables: $1"; }
bad() { fail=$((fail + 1)); echo "FAIL splice_tables: $1"; }
printf '| a | b |\n| --- | --- |\n| 1 | 2 |\n' > "$tmp/table.md"
printf '# page\ntext before\n<!-- generated: %s/table.md -->\n| old |\n<!-- end generated -->\ntext after\n<!-- generated: %s/missing.md -->\nkept\n<!-- end generated -->\n' "$tmp" "$tmp" > "$tmp/page.md"
printf '# page\ntext before\n<!-- generated: %s/table.md -->\n| a | b |\n| --- | --- |\n| 1 | 2 |\n<!-- end generated -->\ntext after\n<!-- generated: %s/missing.md -->\nkept\n<!-- end generated -->\n' "$tmp" "$tmp" > "$tmp/expected.md"
bash "$top/scripts/splice_tables.sh" "$tmp/page.md" > "$tmp/out" 2> "$tmp/err"
if cmp -s "$tmp/page.md" "$tmp/expected.md"; then ok "the block has the table, the rest is unchanged"; else bad "page differs:"; diff "$tmp/page.md" "$tmp/expected.md"; fi
if grep -q "missing.md is not there" "$tmp/err"; then ok "a missing file keeps its block and is named"; else bad "no notice for the missing file"; cat "$tmp/err"; fi
bash "$top/scripts/splice_tables.sh" "$tmp/page.md" > "$tmp/out2" 2> /dev/null
if [ ! -s "$tmp/out2" ] && cmp -s "$tmp/page.md" "$tmp/expected.md"; then ok "a second run changes nothing"; else bad "the second run changed the page"; fi
printf 'x\n<!-- generated: %s/table.md -->\nnever closed\n' "$tmp" > "$tmp/open.md"
cp "$tmp/open.md" "$tmp/open.orig"
if ! bash "$top/scripts/splice_tables.sh" "$tmp/open.md" 2> "$tmp/err3" && cmp -s "$tmp/open.md" "$tmp/open.orig" &&
  grep -q "never closed" "$tmp/err3"; then ok "an open block is an error and the page is kept"; else bad "open block: $(cat "$tmp/err3")"; fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
