#!/usr/bin/env bash
# fix servo_bc in LAMMPS (build/lmp_servo, Debian package) on the closed-form
# (D) lattice of tests/test_lattice.c (tests/lammps/lattice.in): (D) and (P)
# against the closed form, serial and on 2 ranks, (P) on 1, 2 and 4 ranks,
# refused input, restart (tests/host_checks.sh); and the plugin route when
# given. Prints "N passed, N failed".
# Usage: closed_form.sh LMP_SERVO [PLUGIN_DRIVER PLUGIN.so]
set -u
BIN=$(cd "$(dirname "${1:?usage: closed_form.sh LMP_SERVO}")" && pwd)/$(basename "$1")
drv_arg=${2:-} so_arg=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
HOST=lammps DECK=$here/lattice.in TMP=$(mktemp -d)
. "$here/../host_checks.sh"
lattice_checks
refuses "units other than si" 's/^units  *si/units           lj/' "requires units si (its outputs are in m, N/m and s; this script has units lj)"
refuses "an interior that no fix integrates" '/^fix  *integrate servo_interior/d' "atoms of group servo_interior are integrated by no fix"
# a run that ends before the loading path does: exit 0 (a path may span runs), with a warning
deck_with 's/^run .*/run             300/' "$TMP/short.in"
run_deck 1 short.in "$TMP/short.csv" "$TMP/short.log"
if [ $? -eq 0 ] && grep -q "WARNING: Fix servo_bc: the run ended at increment 1 of 2: the loading path is unfinished" "$TMP/short.log"; then
  ok "warns when the run ends before the loading path"
else
  no "no warning on a short run:"; tail -3 "$TMP/short.log"
fi
refuses "a normal dashpot (gamman 50)" 's/^pair_style      gran\/hooke\/history 1e4 0 0 0 0.4 0/pair_style      gran\/hooke\/history 1e4 0 50 0 0.4 0/' \
  "has no dashpots); this script gives gamman 50.000000, gammat 0.000000, dampflag 0"
# (gammat without dampflag is no dashpot: LAMMPS sets it to 0 when dampflag is 0)
refuses "dampflag 1" 's/^pair_style      gran\/hooke\/history 1e4 0 0 0 0.4 0/pair_style      gran\/hooke\/history 1e4 0 0 0 0.4 1/' \
  "dampflag 1"
refuses "a time step beyond the critical step of the lightest atom" 's/^timestep .*/timestep 2e-3/' \
  "time step 0.002 s exceeds the critical step 0.00114342 s = 2 sqrt(M / (2 kn)) of particle"
frictional_checks 's/^pair_style      gran\/hooke\/history 1e4 0 0 0 0.4 0/pair_style      gran\/hooke\/history 1e4 2e3 0 0 0.4 0/'
outputs_checks
refuses "a 2D F in a 3d box" 's/^dimension       2/dimension 3/; s/lattice         sq/lattice sc/; /enforce2d/d; s/nve\/sphere disc/nve\/sphere/' \
  "keyword 'F': 4 values give a 2D F, but the packing is 3D (expected 9 values"
refuses "a 3d box of one layer (F with nine values)" 's/^dimension       2/dimension 3/; s/lattice         sq/lattice sc/; /enforce2d/d; s/nve\/sphere disc/nve\/sphere/; s/servo_bc D F 1.002 0 0 0.997/servo_bc D F 1.002 0 0 0 0.997 0 0 0 1/' \
  "frame: the packing is too thin (0.008 x 0.008 x 0 m) to have six faces"
cat > "$TMP/restart_head.in" <<LMP
comm_modify     vel yes
neighbor        0.000255 bin
neigh_modify    delay 0 every 1 check yes
LMP
restart_decks "$TMP/restart_head.in"
restart_check
restart_friction_check 's/^pair_style      gran\/hooke\/history 1e4 0 0 0 0.4 0/pair_style      gran\/hooke\/history 1e4 2e3 0 0 0.4 0/' \
  "$TMP/restart_head.in"
restart_remap_check 's/^pair_style      gran\/hooke\/history 1e4 0 0 0 0.4 0/pair_style      gran\/hooke\/history 1e4 2e3 0 0 0.4 0/' \
  "$TMP/restart_head.in"
# per-atom outputs for dumps: f_ID[1] frame flag, f_ID[2] accumulated rotation (rad)
printf 'write_dump all custom %s id f_servo[1] f_servo[2] modify sort id\n' "$TMP/atoms.txt" > "$TMP/dump_tail.in"
cat "$DECK" "$TMP/dump_tail.in" > "$TMP/dump.in"
run_deck 1 dump.in "$TMP/dump.csv" "$TMP/dump.log"
flags=$(awk 'NR > 9 { n++; f += $2; if ($3 != $3 + 0) bad++ } END { printf "%d %d %d", n, f, bad }' "$TMP/atoms.txt" 2>/dev/null)
if [ "$flags" = "25 16 0" ]; then
  ok "dump: f_servo[1] flags the 16 frame atoms of 25, f_servo[2] holds a number on every atom"
else
  no "dump of the per-atom outputs: atoms, frame flags, non-numbers = ${flags:-none}"; grep -m1 ERROR "$TMP/dump.log"
fi
# the plugin route: lammpsplugin_init called by a driver that registers like `plugin load`
if [ -n "$drv_arg" ] && [ -n "$so_arg" ]; then
  drv=$(cd "$(dirname "$drv_arg")" && pwd)/$(basename "$drv_arg")
  so=$(cd "$(dirname "$so_arg")" && pwd)/$(basename "$so_arg")
  (cd "$TMP" && "$drv" "$so" -in "$DECK" -var csv "$TMP/plugin.csv" -log none > plugin.log 2>&1)
  if grep -q "registered fix style servo_bc " "$TMP/plugin.log"; then
    closed_form "plugin route (D) closed form" "$TMP/plugin.csv"
  else
    no "plugin route:"; tail -3 "$TMP/plugin.log"
  fi
  # fix servo_bc/bonds through the plugin: the 5-sphere beam of Table B1 (eq. B1 to 1e-4)
  (cd "$TMP" && "$drv" "$so" -in "$here/../../inputs/lammps/bpm_beam.in" -var n 5 -var out "$TMP/plugin_beam.txt" \
    -log none > plugin_beam.log 2>&1)
  d=$(awk '$1 == "deflection" { print $2 }' "$TMP/plugin_beam.txt" 2>/dev/null)
  if grep -q "registered fix style servo_bc/bonds" "$TMP/plugin_beam.log" &&
    awk -v d="${d:-none}" 'BEGIN { R = 0.1; E = 4e9; G = E / 2.6; pi = atan2(0, -1); L = 0.8
      b = 1e3 * L^3 / (48 * E * pi * R^4 / 4) + 1e3 * L * (10 / 9) / (4 * G * pi * R * R); e = (d - b) / b
      exit !(d == d + 0 && e * e <= 1e-8) }'; then
    ok "plugin route: fix servo_bc/bonds, the 5-sphere beam deflects $d m (eq. B1 to 1e-4)"
  else
    no "plugin route, fix servo_bc/bonds: deflection ${d:-none}"; tail -3 "$TMP/plugin_beam.log"
  fi
fi
rm -rf "$TMP"
finish
