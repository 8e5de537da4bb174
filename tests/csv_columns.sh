# Sourced by the tests: COLUMNS_AWK, an awk preamble that reads a results
# file's columns by name (columns.h; `servo-bc --columns`). Prepend it to a
# program: awk -F, "$COLUMNS_AWK"'NR > 1 { print $col("sigma11") }' FILE.
# col(NAME) is the field of that column in the current file's header (the
# first occurrence, so that on files pasted side by side it is the first
# file's); a name no header has stops awk with status 2 and no output, so a
# misspelt column can never pass for a number.
COLUMNS_AWK='
function col(name) {
  if (!(name in at)) { printf "no column %s in %s\n", name, FILENAME > "/dev/stderr"; missing = 1; exit 2 }
  return at[name]
}
FNR == 1 { for (i = NF; i >= 1; i--) at[$i] = i }
END { if (missing) exit 2 }
'
