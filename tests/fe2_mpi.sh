#!/usr/bin/env bash
# FE^2 with the material points spread over 2 MPI ranks (fe2/macro.py, comm):
# tests/fe2_mpi.py alone and under mpirun -np 2 must give the same displacements
# and nodal forces to the bit, step by step. Prints the wall times and
# "N passed, N failed". Usage: fe2_mpi.sh LIBSERVO_BC [PYTHON]
set -u
lib=${1:?usage: fe2_mpi.sh LIBSERVO_BC [PYTHON]}
py=${2:-/usr/bin/python3}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
SERVO_BC_LIB=$lib timeout 600 "$py" "$here/fe2_mpi.py" > "$tmp/one.txt" 2> "$tmp/one.log"
SERVO_BC_LIB=$lib timeout 600 mpirun --allow-run-as-root --oversubscribe -np 2 "$py" "$here/fe2_mpi.py" mpi \
  > "$tmp/two.txt" 2> "$tmp/two.log"
steps=$(grep -c '^step ' "$tmp/one.txt")
if [ "$steps" = 2 ] && cmp -s <(grep -v '^time' "$tmp/one.txt") <(grep -v '^time' "$tmp/two.txt"); then
  pass=$((pass + 1))
  echo "fe2 mpi: 16 (P) points on 1 and 2 ranks, 2 load steps: the same displacements and nodal forces bit for bit" \
    "($(grep '^time' "$tmp/one.txt" | awk '{ print $2 }') s on 1 rank, $(grep '^time' "$tmp/two.txt" | awk '{ print $2 }') s on 2)"
else
  fail=$((fail + 1))
  echo "FAIL fe2 mpi: $steps steps on 1 rank; $(grep -c '^step ' "$tmp/two.txt") on 2; $(tail -2 "$tmp/one.log" "$tmp/two.log")"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
