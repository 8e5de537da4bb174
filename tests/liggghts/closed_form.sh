#!/usr/bin/env bash
# fix servo_bc in LIGGGHTS (build/liggghts_servo, Debian package) on the
# closed-form (D) lattice of tests/test_lattice.c (tests/liggghts/lattice.in):
# (D) and (P) against the closed form, serial and on 2 ranks, (P) on 1, 2 and
# 4 ranks, refused input, restart (tests/host_checks.sh). Prints "N passed, N failed".
# Usage: closed_form.sh LIGGGHTS_SERVO SERVO_BC
set -u
BIN=$(cd "$(dirname "${1:?usage: closed_form.sh LIGGGHTS_SERVO SERVO_BC}")" && pwd)/$(basename "$1")
emb=$(cd "$(dirname "${2:?usage: closed_form.sh LIGGGHTS_SERVO SERVO_BC}")" && pwd)/$(basename "$2")
here=$(cd "$(dirname "$0")" && pwd)
HOST=liggghts DECK=$here/lattice.in TMP=$(mktemp -d)
. "$here/../host_checks.sh"
printf 'dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ndensity 2e3\nwrite_packing liggghts %s\n' \
  "$TMP/lattice5.data" > "$TMP/packing.sbc"
"$emb" "$TMP/packing.sbc" > /dev/null || echo "servo-bc could not write the packing"
lattice_checks
frictional_checks 's/^fix             kt all property\/global kt peratomtypepair 2 0 0 0 0/fix             kt all property\/global kt peratomtypepair 2 2e3 2e3 2e3 2e3/'
outputs_checks
refuses "a 2D F in a 3d box" 's/^dimension       2/dimension 3/; /enforce2d/d' "keyword 'F': 4 values give a 2D F, but the packing is 3D"
refuses "a 3d box of one layer (F with nine values)" 's/^dimension       2/dimension 3/; /enforce2d/d; s/servo_bc D F 1.002 0 0 0.997/servo_bc D F 1.002 0 0 0 0.997 0 0 0 1/' "frame: the packing is too thin"
refuses "mixed words of 2D in a 3d box" 's/^dimension       2/dimension 3/; /enforce2d/d; s/servo_bc D F 1.002 0 0 0.997/servo_bc mixed F 1.002 0 0 1 stress P22 -1 1/' "the packing is 3D but the words are 2D: give F with nine values"
refuses "a pair style without tangential history" 's/tangential history/tangential no_history/' \
  "keeps no tangential history"
# the documented run in pieces (no setup between them) writes the CSV of one
# uninterrupted run byte for byte, whatever the piece length: frictional (P)
pieces=""
for n in 6000 10000 200000; do
  deck_with "s/^run             10000 pre no post no/run             $n pre no post no/; s/servo_bc D F 1.002 0 0 0.997 increments 2 relax 1e-22 20/servo_bc P F 1 0.02 0 1 increments 4/; s/kt peratomtypepair 2 0 0 0 0/kt peratomtypepair 2 2e3 2e3 2e3 2e3/" \
    "$TMP/pieces_$n.in"
  run_deck 1 "pieces_$n.in" "$TMP/pieces_$n.csv" "$TMP/pieces_$n.log" || tail -3 "$TMP/pieces_$n.log"
  pieces="$pieces $TMP/pieces_$n.csv"
done
if [ "$(wc -l < "$TMP/pieces_200000.csv")" = 6 ] && cmp -s "$TMP/pieces_6000.csv" "$TMP/pieces_200000.csv" &&
   cmp -s "$TMP/pieces_10000.csv" "$TMP/pieces_200000.csv"; then
  ok "pieces of 6000 and 10000 steps write the uninterrupted run's CSV byte for byte"
else
  no "pieces of 6000, 10000 steps and one run differ:$(for f in $pieces; do tail -n 1 "$f" | cut -d, -f11; done | tr '\n' ' ')"
fi
refuses "a normal dashpot (gamman_abs 0.5)" 's/gamman_abs peratomtypepair 2 0 0 0 0/gamman_abs peratomtypepair 2 0.5 0.5 0.5 0.5/' \
  "gamman_abs is 0.5"
refuses "a tangential dashpot (gammat_abs 0.5)" 's/gammat_abs peratomtypepair 2 0 0 0 0/gammat_abs peratomtypepair 2 0.5 0.5 0.5 0.5/' \
  "gammat_abs is 0.5"
refuses "units other than si" 's/^units  *si/units           lj/' "requires units si (its outputs are in m, N/m and s; this script has units lj)"
refuses "an interior that no fix integrates" '/^fix  *integrate servo_interior/d' "atoms of group servo_interior are integrated by no fix"
refuses "a time step beyond the critical step of the lightest atom" 's/^timestep .*/timestep 2e-3/' \
  "time step 0.002 s exceeds the critical step 0.00114342 s = 2 sqrt(M / (2 kn)) of particle"
refuses "kn that differs between types" 's/kn peratomtypepair 2 1e4 1e4 1e4 1e4/kn peratomtypepair 2 1e4 2e4 2e4 1e4/' \
  "fix property/global kn differs between atom type pairs"
# an error on one rank (the results file cannot be opened) aborts the job: the
# message must still reach a pipe (liggghts_servo line-buffers stdout)
deck_with 's|file ${csv}|file /dev/null/dir/out.csv|' "$TMP/bad_file.in"
run_deck 2 bad_file.in "$TMP/unused.csv" "$TMP/bad_file.log"
rc=$?
if [ $rc -ne 0 ] && grep -aq "ERROR on proc 0: Fix servo_bc: keyword 'file': cannot write '/dev/null/dir/out.csv'" \
     "$TMP/bad_file.log"; then
  ok "refuses an unwritable results file on 2 ranks, message on the pipe"
else
  no "unwritable results file (exit $rc):"; tail -3 "$TMP/bad_file.log"
fi
cat > "$TMP/restart_head.in" <<LIG
newton          off
communicate     single vel yes
neighbor        0.000255 bin
neigh_modify    delay 0
LIG
sed -n '/^fix  *kn /,/^timestep/p' "$DECK" >> "$TMP/restart_head.in"
restart_decks "$TMP/restart_head.in"
restart_check
restart_friction_check 's/kt peratomtypepair 2 0 0 0 0/kt peratomtypepair 2 2e3 2e3 2e3 2e3/' "$TMP/restart_head.in"
restart_remap_check 's/kt peratomtypepair 2 0 0 0 0/kt peratomtypepair 2 2e3 2e3 2e3 2e3/' "$TMP/restart_head.in"
# LIGGGHTS 3.8 does not keep the time step in its restart files: without it the
# fix would servo with other gains (eq. 37); the core refuses
sed '/^timestep/d' "$TMP/part2.in" > "$TMP/part2_nodt.in"
run_deck 1 part2_nodt.in "$TMP/nodt.csv" "$TMP/nodt.log"
if [ $? -ne 0 ] && grep -q "ERROR: Fix servo_bc: restart: time step .* contradicts the saved 1.0000000000000001e-05 s" "$TMP/nodt.log"; then
  ok "restart refuses a time step other than the saved one"
else
  no "restart without the time step:"; grep -m1 ERROR "$TMP/nodt.log" || tail -2 "$TMP/nodt.log"
fi
rm -rf "$TMP"
finish
