#!/usr/bin/env bash
# bench/yade_overhead.py at 10^3 and 10^4 particles (32 x 32 and 100 x 100 lattices).
# Usage: bench/yade_overhead.sh SERVO_BC LIBSERVO_BC.so [STEPS]
set -euo pipefail
emb=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
export SERVO_BC_LIB=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
steps=${3:-2000}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
for side in 32 100; do
  printf 'dimension 2\nlattice square %s %s spacing 2.0e-3 radius 1.02e-3\nwrite_packing yade %s/l.yade\n' \
    "$side" "$side" "$tmp" > "$tmp/w.sbc"
  "$emb" "$tmp/w.sbc" > /dev/null
  yade -n -x "$here/yade_overhead.py" "$side" "$steps" "$tmp/l.yade" 2>&1 | grep '^yade '
done
rm -rf "$tmp"
