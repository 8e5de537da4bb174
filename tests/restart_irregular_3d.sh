#!/usr/bin/env bash
# A 3D run split by write_restart/read_restart inside an increment, on an irregular frictional packing (round 4:
# 1.8e-3 of the stress scale was reported for LAMMPS): the runner's `generate periodic` (87 spheres, jammed and
# compressed by 1 %), (P) shear F12 0.002 with F33 0.999 in 3 increments at `balanced`, written for the hosts by
# `servo-bc --decks`; each host's full run against the same run split half way through increment 1 (the step
# read from the full run's relax_steps), LAMMPS on 1 and 2 ranks: the CSVs byte for byte; LIGGGHTS on 1: byte for
# byte a run with a setup at the split step and no restart (the setup itself moves the path; its difference from
# the full run is printed). Prints "N passed, N failed".
# Usage: restart_irregular_3d.sh SERVO_BC LMP_SERVO LIGGGHTS_SERVO
set -u
runner=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
lmp=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
lig=$(cd "$(dirname "$3")" && pwd)/$(basename "$3")
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
cat > "$T/case.sbc" <<'SBC'
dimension 3
generate periodic n0 40 rmin 1e-3 polydispersity 1.5 seed 3 strain 0.01
contact frictional kn 1e4 ks 5e3 mu 0.5
density 2650
timestep 1e-5
servo_bc P F 1 0.002 0 0 1 0 0 0 0.999 increments 3 accuracy balanced file embedded.csv
run
SBC
(cd "$T" && "$runner" --decks d case.sbc > decks.log 2>&1) || { echo "FAIL restart 3d: --decks"; cat "$T/decks.log"; exit 1; }
# differ FULL SPLIT: "byte for byte", or the largest |d sigma| over the stress scale
differ() {
  cmp -s "$1" "$2" && { echo "byte for byte"; return; }
  awk -F, 'FNR == 1 { for (i = 1; i <= NF; i++) if ($i ~ /^sigma/) s[i] = 1; next }
    FNR == NR { for (i in s) { a[FNR, i] = $i; v = $i < 0 ? -$i : $i; if (v > scale) scale = v }; next }
    { for (i in s) { d = $i - a[FNR, i]; d = d < 0 ? -d : d; if (d > m) m = d } }
    END { printf "differs by %.2g of the stress scale", m / scale }' "$1" "$2"
}
# split_step FULL: half way through increment 1
split_step() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "relax_steps") c = i; next }
           NR == 2 { s0 = $c } NR == 3 { printf "%d", s0 + $c / 2 }' "$1"
}
check() {  # LABEL FULL SPLIT
  local got
  got=$(differ "$2" "$3")
  if [ "$got" = "byte for byte" ] && [ "$(wc -l < "$2")" = 5 ]; then
    pass=$((pass + 1)); echo "restart 3d irregular, $1: the split run's CSV byte for byte the full run's"
  else
    fail=$((fail + 1)); echo "FAIL restart 3d irregular, $1: $got ($(wc -l < "$2") and $(wc -l < "$3") lines)"
  fi
}
cd "$T/d"
skin=$(sed -n 's/^neighbor  *\([^ ]*\) bin/\1/p' lammps.in)
for np in 1 2; do
  mpi=(); [ "$np" = 1 ] || mpi=(mpirun --allow-run-as-root --oversubscribe -np "$np")
  rm -f lammps.csv; timeout 300 "${mpi[@]}" "$lmp" -in lammps.in -log none > full.log 2>&1; mv lammps.csv full.csv
  at=$(split_step full.csv)
  sed "s|^run .*|run $at\nwrite_restart split.restart|" lammps.in > part1.in
  { echo "read_restart split.restart"; printf 'comm_modify vel yes\nneighbor %s bin\nneigh_modify delay 0 every 1 check yes\n' "$skin"
    sed -n '/^fix  *servo /,$p' lammps.in; } > part2.in
  timeout 300 "${mpi[@]}" "$lmp" -in part1.in -log none > part1.log 2>&1
  timeout 300 "${mpi[@]}" "$lmp" -in part2.in -log none > part2.log 2>&1
  check "LAMMPS on $np rank(s), split at step $at" full.csv lammps.csv
done
rm -f liggghts.csv; timeout 300 "$lig" -in liggghts.in -log none > full.log 2>&1; mv liggghts.csv full.csv
at=$(split_step full.csv)
sed "/^label/,\$d; s|^run  *0\$|run 0\nrun $at pre no post no\nwrite_restart split.restart|" liggghts.in > part1.in
{ echo "read_restart split.restart"
  sed -n '/^newton/p; /^communicate/p; /^fix  *m[0-9]/,/^timestep/p' liggghts.in; sed -n '/^fix  *servo /,$p' liggghts.in; } > part2.in
timeout 300 "$lig" -in part1.in -log none > part1.log 2>&1
timeout 300 "$lig" -in part2.in -log none > part2.log 2>&1
mv liggghts.csv split.csv
# LIGGGHTS: the run's setup at the split step (the first run after read_restart must have one) changes the path
# by itself; a run with `run 0` at that step and no restart is the split run byte for byte, so the restart file
# keeps the state whole (docs/liggghts/README.md, "Restart")
sed "s|^run  *0\$|run 0\nrun $at pre no post no\nrun 0|" liggghts.in > setup.in
timeout 300 "$lig" -in setup.in -log none > setup.log 2>&1
if cmp -s split.csv liggghts.csv && [ "$(wc -l < split.csv)" = 5 ]; then
  pass=$((pass + 1))
  echo "restart 3d irregular, LIGGGHTS, split at step $at: byte for byte a run with a setup at that step and no restart; the setup $(differ full.csv split.csv)"
else
  fail=$((fail + 1)); echo "FAIL restart 3d irregular, LIGGGHTS, split at step $at: the split run against a setup at that step $(differ liggghts.csv split.csv)"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
