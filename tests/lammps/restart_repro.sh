#!/usr/bin/env bash
# The round-3 reproducers of fix servo_bc/bonds' restart blocks
# (tests/lammps/restart_repro/: written by 0.2.0 from part1_*.in, then
# corrupted: counts of 1e9, sizes of 1e12, NaN and 1e300 values), each read
# back by part2_*.in: every one must end in a LAMMPS error from the fix (exit
# 1, "ERROR: Fix servo_bc/bonds: ..."), never a signal, an abort or a run
# with NaN outputs. The intact files are refused too (another version's
# block), which the message must say. Prints "N passed, N failed".
# Usage: restart_repro.sh LMP_SERVO
set -u
bin=$(cd "$(dirname "${1:?usage: restart_repro.sh LMP_SERVO}")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")" && pwd)/restart_repro
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$here"/* "$tmp"/
chmod u+w "$tmp"/*
pass=0 fail=0
beam_fix='fix             bonds all servo_bc/bonds beam 4e9 0.3 1.0 strength 1e5 0 0 0'
coh_fix='fix             bonds all servo_bc/bonds cohesive kn 10000 ks 2000 kr 0.001 fn 1 fs 1 mr 0.001 mu 0.4'
for f in "$tmp"/*.restart; do
  name=$(basename "$f")
  case $name in coh_* | half_coh*) deck=part2_coh.in fix=$coh_fix ;; *) deck=part2_beam.in fix=$beam_fix ;; esac
  sed "s#RESTART#$name#; s#FIXLINE#$fix#" "$tmp/$deck" > "$tmp/bad.in"
  (cd "$tmp" && timeout 60 "$bin" -in bad.in -log none > "$name.log" 2>&1)
  rc=$?
  message=$(grep -m1 -o "ERROR: Fix servo_bc/bonds: .*" "$tmp/$name.log" | cut -c1-150)
  if [ $rc -ge 1 ] && [ $rc -le 125 ] && [ -n "$message" ]; then
    pass=$((pass + 1)); echo "lammps restart reproducer $name: exit $rc, $message"
  else
    fail=$((fail + 1)); echo "FAIL lammps restart reproducer $name: exit $rc"; tail -n 3 "$tmp/$name.log"
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
