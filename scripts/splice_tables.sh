#!/usr/bin/env bash
# Puts generated tables into the documentation pages (make figures), so that
# the pages never drift from what the scripts measure. In a page, a block
#   <!-- generated: out/paper/fig2.md -->
#   ... (replaced) ...
#   <!-- end generated -->
# gets the current content of the named file (a path relative to the
# repository's top folder). A block whose file does not exist is left as it
# is, with one line on stderr. Prints one line per page changed.
# Usage: scripts/splice_tables.sh PAGE.md...
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
status=0
for page in "$@"; do
  [ -f "$page" ] || { echo "splice_tables: $page: no such page" >&2; status=1; continue; }
  tmp=$(mktemp)
  if ! awk -v top="$top" -v page="$page" '
    function flush_old() { for (i = 1; i <= nold; i++) print old[i]; nold = 0 }
    /^<!-- generated: .* -->$/ {
      if (inside) { printf "splice_tables: %s:%d: a block opens inside the block of line %d\n", page, NR, start > "/dev/stderr"; bad = 1; exit 1 }
      print; inside = 1; start = NR; file = $3; nold = 0; next }
    /^<!-- end generated -->$/ {
      if (!inside) { printf "splice_tables: %s:%d: an end without a block\n", page, NR > "/dev/stderr"; bad = 1; exit 1 }
      path = file ~ /^\// ? file : top "/" file
      if ((getline line < path) > 0) {
        print line; while ((getline line < path) > 0) print line; close(path); nold = 0
      } else {
        printf "splice_tables: %s:%d: %s is not there (run its script); the block is kept\n", page, start, file > "/dev/stderr"
        flush_old()
      }
      print; inside = 0; next }
    inside { old[++nold] = $0; next }
    { print }
    END { if (inside && !bad) { printf "splice_tables: %s:%d: the block is never closed\n", page, start > "/dev/stderr"; exit 1 } }
  ' "$page" > "$tmp"; then
    rm -f "$tmp"; status=1; continue
  fi
  if cmp -s "$tmp" "$page"; then rm -f "$tmp"; else cat "$tmp" > "$page"; rm -f "$tmp"; echo "splice_tables: $page updated"; fi
done
exit $status
