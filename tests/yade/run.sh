#!/usr/bin/env bash
# The YADE engine (yade_adapter/servo_bc.py over the core's shared library),
# against the Debian YADE package: the closed-form lattice (D) and (P) and the
# refusals (closed_form.py); bad words in batch mode end the process non-zero
# with the core's message. YADE beside the other engines on the same case is
# tests/cross_host.sh (make check-cross-host).
# Prints "N passed, N failed".
# Usage: run.sh LIBSERVO_BC.so SERVO_BC
set -u
lib=$(cd "$(dirname "${1:?usage: run.sh LIBSERVO_BC.so SERVO_BC}")" && pwd)/$(basename "$1")
emb=$(cd "$(dirname "${2:?usage: run.sh LIBSERVO_BC.so SERVO_BC}")" && pwd)/$(basename "$2")
export SERVO_BC_LIB=$lib
here=$(cd "$(dirname "$0")" && pwd)
run=$here/../../inputs/yade/run.py
tmp=$(mktemp -d)
pass=0 fail=0
lattice() {  # side file
  printf 'dimension 2\nlattice square %s %s spacing 2.0e-3 radius 1.02e-3\nwrite_packing yade %s\n' "$1" "$1" "$2" > "$tmp/w.sbc"
  "$emb" "$tmp/w.sbc" > /dev/null
}
lattice 5 "$tmp/l5.yade"
yade -n -x "$here/closed_form.py" "$tmp/l5.yade" > "$tmp/closed.log" 2>&1
grep -E '^(FAIL )?yade ' "$tmp/closed.log"
counts=$(awk '/ passed, .* failed$/ { print $1, $3 }' "$tmp/closed.log")
set -- ${counts:-0 1}
pass=$((pass + $1)) fail=$((fail + $2))
[ -n "$counts" ] || { echo "FAIL yade closed_form.py did not finish:"; tail -5 "$tmp/closed.log"; }

# batch mode: a Python exception with the core's message, and a non-zero exit
yade -n -x "$run" "$tmp/l5.yade" 2e3 1e4 2e3 0.4 1e-5 servo_bc D F 1 2 2 1 > "$tmp/bad.log" 2>&1
status=$?
if [ $status -ne 0 ] && grep -q "ServoBCError: servo_bc: keyword 'F': det F = -3 is not positive" "$tmp/bad.log"; then
  pass=$((pass + 1)); echo "yade batch mode: exit status $status, ServoBCError names the keyword and value"
else
  fail=$((fail + 1)); echo "FAIL yade batch mode with bad words (exit $status):"; tail -3 "$tmp/bad.log"
fi

rm -rf "$tmp"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
