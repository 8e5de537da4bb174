# Sourced by the tests: COLUMNS_AWK, scripts/columns.awk as a preamble that
# reads a results file's columns by name (columns.h; `servo-bc --columns`).
# Prepend it to a program: awk -F, "$COLUMNS_AWK"'NR > 1 { print $col("sigma11") }' FILE.
COLUMNS_AWK=$(cat "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/scripts/columns.awk")
