#!/usr/bin/env bash
# The restart layout: the frame and controller state that fuzz/restart_seed.c
# saves (a (P) run on a 4 x 4 lattice, three corrections into its first
# increment) byte for byte as tests/reference/restart/seed_P.bin, written by
# the core before vectors and tensors took 3 and 3 x 3 slots; a 2D restart
# file of an earlier version therefore loads. A commit that means to change
# the layout writes the file again (REFERENCE_UPDATE=1) and bumps
# STATE_VERSION. Prints "N passed, N failed".
# Usage: restart_layout.sh BUILD
set -u
B=${1:-build}
top=$(cd "$(dirname "$0")/.." && pwd)
ref=$top/tests/reference/restart/seed_P.bin
out=$(mktemp)
trap 'rm -f "$out"' EXIT
if ! "$B/fuzz/restart_seed" "$out"; then
  echo "FAIL restart layout: fuzz/restart_seed did not write a state"; echo "0 passed, 1 failed"; exit 1
fi
[ "${REFERENCE_UPDATE:-0}" = 1 ] && cp "$out" "$ref"
if cmp -s "$out" "$ref"; then
  echo "restart layout: $(wc -c < "$ref") bytes of (P) state byte for byte as tests/reference/restart/seed_P.bin"
  echo "1 passed, 0 failed"
else
  echo "FAIL restart layout: the saved state differs from tests/reference/restart/seed_P.bin ($(cmp "$out" "$ref" 2>&1 | head -n 1))"
  echo "0 passed, 1 failed"; exit 1
fi
