# Sourced by the shell tests after setting CHECKS_LABEL: top (the repository),
# B (the build directory: the test's first argument, or build), COLUMNS_AWK
# (csv_columns.sh), tmp (a temporary directory removed on exit), and the
# counters pass and fail with ok and no, which print "LABEL text" and
# "FAIL LABEL text". The test ends with: echo "$pass passed, $fail failed".
top=$(cd "$(dirname "${BASH_SOURCE[1]}")/.." && pwd)
B=$(cd "${1:-$top/build}" && pwd)
. "$top/tests/csv_columns.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "$CHECKS_LABEL $*"; }
no() { fail=$((fail + 1)); echo "FAIL $CHECKS_LABEL $*"; }
