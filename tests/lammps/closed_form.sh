#!/usr/bin/env bash
# fix servo_bc in LAMMPS (build/lmp_servo, Debian package) on the closed-form
# (D) lattice of tests/test_lattice.c, under (D) and (P): P11 = -N kn (2R - d F11)/((N-1) d),
# P22 likewise, P12 = P21 = 0, every increment, 1e-9 relative; serial and on
# 2 MPI ranks. Prints "N passed, N failed".
set -u
lmp=$(cd "$(dirname "${1:?usage: closed_form.sh LMP_SERVO}")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
pass=0 fail=0
check() {  # label csv
  local out
  out=$(awk -F, 'NR > 1 {
      t = $1 / 2; f11 = 1 + t * 0.002; f22 = 1 - t * 0.003;
      p11 = -5 * 1e4 * (2.04e-3 - 2e-3 * f11) / (4 * 2e-3);
      p22 = -5 * 1e4 * (2.04e-3 - 2e-3 * f22) / (4 * 2e-3);
      e = ($6 - p11) / p11; if (e < 0) e = -e; if (e > m) m = e;
      e = ($9 - p22) / p22; if (e < 0) e = -e; if (e > m) m = e;
      e = ($7 < 0 ? -$7 : $7) / -p11; if (e > m) m = e;
      e = ($8 < 0 ? -$8 : $8) / -p11; if (e > m) m = e;
      n++ }
    END { printf "%d %.3g", n, m }' "$2")
  set -- "$1" $out
  if [ "${2:-0}" = 3 ] && awk -v m="$3" 'BEGIN { exit !(m <= 1e-9) }'; then
    pass=$((pass + 1)); echo "lammps $1: 3 increments, max relative error $3"
  else
    fail=$((fail + 1)); echo "FAIL lammps $1: increments ${2:-0}, max relative error ${3:-?}"
  fi
}
(cd "$tmp" && "$lmp" -in "$here/lattice.in" -var csv "$tmp/serial.csv" -log none > serial.log 2>&1) \
  || { echo "lmp_servo failed:"; tail -5 "$tmp/serial.log"; }
check "serial (D) closed form" "$tmp/serial.csv"
(cd "$tmp" && mpirun --allow-run-as-root --oversubscribe -np 2 "$lmp" -in "$here/lattice.in" -var csv "$tmp/np2.csv" \
  -log none > np2.log 2>&1) || { echo "lmp_servo -np 2 failed:"; tail -5 "$tmp/np2.log"; }
check "2 ranks (D) closed form" "$tmp/np2.csv"
# (P): the affine state is periodic with anti-periodic forces: the same closed form
sed 's/servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20/servo_bc P F 1.002 0 0 0.997 increments 2 relax 1e-22 20 tol_force 1e-14 tol_moment 1e-14 gain_force 1e3 gain_moment 1e3/' \
  "$here/lattice.in" > "$tmp/periodic.in"
(cd "$tmp" && "$lmp" -in periodic.in -var csv "$tmp/periodic.csv" -log none > periodic.log 2>&1) \
  || { echo "lmp_servo (P) failed:"; tail -5 "$tmp/periodic.log"; }
check "serial (P) closed form" "$tmp/periodic.csv"
# bad input: the core's message, named by the fix
sed 's/servo_bc D F 1.002 0 0 0.997/servo_bc D F 1 2 2 1/' "$here/lattice.in" > "$tmp/bad.in"
(cd "$tmp" && "$lmp" -in bad.in -var csv "$tmp/bad.csv" -log none > bad.log 2>&1)
if [ $? -ne 0 ] && grep -q "ERROR: Fix servo_bc: keyword 'F': det F = -3 is not positive" "$tmp/bad.log"; then
  pass=$((pass + 1)); echo "lammps bad input: ERROR names the fix, keyword and value"
else
  fail=$((fail + 1)); echo "FAIL lammps bad input:"; tail -3 "$tmp/bad.log"
fi
rm -rf "$tmp"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
